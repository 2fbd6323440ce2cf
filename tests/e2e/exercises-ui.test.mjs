// Every catalogue exercise (www/lib/exercise-catalogue.js) solved as a student on a phone does it: 390×844,
// a touch screen, the controls a student uses — typing into the number boxes (fractions such as 3/4 too),
// tapping toggles and choices, dragging handles with a finger (pointer events of type 'touch' at whole CSS
// pixels, as a finger lands), the keyboard on a slider — then tapping Check and reading the feedback on screen.
// Untouched, no exercise passes. Nothing here writes the state directly (tests/e2e/exercises.test.mjs does that).
// Also: the figure is on screen, not under the controls sheet, while a control is used; a typed 1/6 shows its
// exact value and clamped or refused input says so; an embedded exercise with storage blocked keeps its task
// uncovered. Screenshots: tests/e2e/out/exercise-ui-*.png.
// Run: node --test --test-concurrency=1 tests/e2e/exercises-ui.test.mjs   (EXERCISE=<id> for one exercise)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

const PHONE = { viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true, deviceScaleFactor: 1 };

let H, phone, catalogue;
before(async () => {
  H = await startHarness();
  phone = await H.browser.newContext(PHONE);
  const t = await H.open('exercises.html', { context: phone });
  catalogue = await t.page.$$eval('.exercise-card', (cs) => cs.map((c) => ({
    id: c.dataset.exercise, task: c.querySelector('p').textContent, href: c.querySelector('.exercise-open').getAttribute('href'),
  })));
  await t.close();
});
after(async () => { await phone?.close(); await H?.close(); });

/** The student's hands on one open exercise page `t`. */
function student(t) {
  const { page } = t;
  /** A control in the folded controls sheet (exercises open with it folded): first tap its handle, “Show controls”. */
  async function openSheet(loc) {
    if (!(await loc.evaluate((el) => !!el.closest('.demo-controls.drawer-collapsed') && !el.closest('.drawer-handle')))) return;
    const b = await page.locator('.demo-controls .drawer-handle').boundingBox();
    await page.touchscreen.tap(b.x + b.width / 2, b.y + b.height / 2);
    await t.frames(2);
  }
  /** Is `loc` what a finger at the centre of its box touches (not covered by the controls sheet)? */
  const onTop = (loc) => loc.evaluate((el) => {
    const r = el.getBoundingClientRect();
    const e = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);
    return !!e && el.contains(e);
  });
  /**
   * Scrolls `loc` into view and taps its centre with a finger. Something in the page that the controls sheet
   * covers is scrolled up first, as a student would (the page, not the sheet, scrolls).
   */
  async function tap(loc) {
    await openSheet(loc);
    await loc.scrollIntoViewIfNeeded();
    if (!(await onTop(loc))) {
      await loc.evaluate((el) => { const r = el.getBoundingClientRect(); window.scrollBy(0, r.top + r.height / 2 - window.innerHeight * 0.3); });
      await t.frames(2);
    }
    assert.equal(await onTop(loc), true, 'nothing covers the element the finger taps');
    const b = await loc.boundingBox();
    await page.touchscreen.tap(b.x + b.width / 2, b.y + b.height / 2);
    await t.frames(2);
  }
  /** The bottom edge of what the controls sheet leaves free (the window's height when it covers nothing). */
  const freeBottom = () => page.evaluate(() => {
    const c = document.querySelector('.demo-controls');
    const r = c?.getBoundingClientRect();
    const fixed = c && getComputedStyle(c).position === 'fixed';
    return fixed && r.height > 0 ? r.top : window.innerHeight;
  });
  return {
    tap,
    /** Taps the number box whose accessible name starts with `name`, types `text`, presses Enter; returns the note. */
    async type(name, text) {
      const box = page.locator(`input.ctl-number[aria-label^="${name}"]`).first();
      await tap(box);
      assert.equal(await box.evaluate((el) => el === document.activeElement), true, `${name}: the tap focuses the box`);
      await page.keyboard.press('Control+A');
      await page.keyboard.type(text);
      await page.keyboard.press('Enter');
      await t.frames(2);
      return { value: await box.inputValue(), note: (await box.evaluate((el) => document.getElementById(el.getAttribute('aria-describedby'))?.textContent)) || '' };
    },
    /** Taps the label of the toggle or choice whose text is `text`. */
    tapLabel: (text) => tap(page.locator('.demo-controls label', { hasText: text }).first()),
    /** Chooses `label` in the drop-down named `name` (the phone's own picker). */
    async choose(name, label) {
      const sel = page.locator('.ctl-select', { hasText: name }).locator('select');
      await tap(sel);
      await sel.selectOption({ label });
      await t.frames(3);
    },
    /** Focuses the range slider named `name` and presses `key` (Home/End/arrows). */
    async sliderKey(name, key) {
      const r = page.locator('.ctl-slider', { has: page.locator('label', { hasText: name }) }).locator('input[type=range]').first();
      await openSheet(r);
      await r.scrollIntoViewIfNeeded();
      await r.focus();
      await page.keyboard.press(key);
      await t.frames(2);
    },
    /**
     * Drags with one finger on the plot canvas `sel` from world point `from` to `to`: pointer events of type
     * 'touch' at whole CSS pixels. Asserts that both points are on screen and not under the controls sheet.
     */
    async drag(sel, from, to, steps = 10) {
      const canvas = page.locator(`canvas[data-plot="${sel}"]`).first();
      await canvas.evaluate((c, w) => {
        const r = c.getBoundingClientRect();
        const [, y] = c.splinePlot.toScreen(w[0], w[1]);
        window.scrollBy(0, r.top + y - window.innerHeight * 0.3);
      }, from);
      await t.frames(2);
      const free = await freeBottom();
      const px = await canvas.evaluate((c, [a, b]) => {
        const r = c.getBoundingClientRect();
        return [a, b].map((w) => { const [x, y] = c.splinePlot.toScreen(w[0], w[1]); return [Math.round(r.left + x), Math.round(r.top + y)]; });
      }, [from, to]);
      for (const [x, y] of px) {
        assert.ok(y >= 0 && y < free, `the finger's point (${x}, ${y}) is on screen above the controls sheet (top ${free})`);
        assert.equal(await page.evaluate(([X, Y]) => document.elementFromPoint(X, Y)?.dataset.plot, [x, y]), sel, 'nothing covers the figure where the finger goes');
      }
      await canvas.evaluate((c, [a, b, n]) => {
        const ev = (name, [x, y]) => c.dispatchEvent(new PointerEvent(name, { bubbles: true, cancelable: true, pointerId: 21, pointerType: 'touch', isPrimary: true, button: 0, buttons: name === 'pointerup' ? 0 : 1, clientX: x, clientY: y, width: 20, height: 20 }));
        ev('pointerdown', a);
        for (let i = 1; i <= n; i++) ev('pointermove', [Math.round(a[0] + (b[0] - a[0]) * i / n), Math.round(a[1] + (b[1] - a[1]) * i / n)]);
        ev('pointerup', b);
      }, [...px, steps]);
      await t.frames(3);
    },
    /** How much of the main figure (first canvas) is on screen and not under the controls sheet (0…1). */
    async figureVisible() {
      const free = await freeBottom();
      return page.evaluate((fb) => {
        const c = [...document.querySelectorAll('.demo-plots canvas')].find((e) => e.getClientRects().length);
        const r = c.getBoundingClientRect();
        return Math.max(0, Math.min(r.bottom, fb) - Math.max(r.top, 0)) / r.height;
      }, free);
    },
    /** Taps Check and returns the feedback text once the attempt is counted. */
    async check() {
      const before = await page.textContent('.exercise-attempts');
      await tap(page.locator('.exercise-panel .exercise-check'));
      await page.waitForFunction((b) => document.querySelector('.exercise-attempts').textContent !== b, before, { timeout: 20000 });
      return (await page.textContent('.exercise-feedback')).trim();
    },
  };
}

// How a student solves each exercise with the controls.
const SOLVE = {
  async 'b2-through-data'(s) { await s.type('Approximation a', '0'); },
  async 'noisy-sine'(s) { await s.type('Approximation a', '0.2'); },
  async 'noisy-spiral'(s) { await s.type('Approximation a', '0.12'); },
  async 'noisy-arc'(s) { await s.type('Approximation a', '1/5'); },
  async 'remodel-c1'(s) { await s.tapLabel('Enforce eq. (9)'); },
  async 'remodel-alpha'(s) {
    // α₁ of segment 3 = 1 − α₂ of segment 2 = 1 − 1/4, typed as the student works it out
    const r = await s.type('α₁⁽³⁾', '1 − 1/4');
    assert.equal(r.value, '1 − 1/4', 'the typed expression stays in the box');
    assert.equal(r.note, '= 0.75', 'its exact value is shown');
  },
  async 'bspline-c2'(s, t) {
    // the knot triangles sit on a row under the basis functions: drag the (upper) knot at 0.5 to 0.75
    const [x, y] = (await t.handles('canvas[data-plot="basis"]')).filter((k) => k.point[0] === 0.5).pop().point;
    await s.drag('basis', [x, y], [0.75, y]);
  },
  async 'envelope-q1'(s) { await s.drag('knots', [2.4, 0], [1.6, 0]); },
  async 'envelope-q2'(s) { await s.drag('knots', [3, 0], [3.5, 0]); },
  async 'envelope-q3'(s) { await s.drag('knots', [1, 0], [1.5, 0]); },
  async 'qc-ellipse-alpha'(s) { await s.type('Shape parameter α', '1'); },
  async 'qc-ellipse-drag'(s) { await s.drag('curve', [3.6, 0.5], [3, 0]); },
  async 'qc-interpolate'(s) { await s.sliderKey('Shape parameter α', 'End'); },
  async 'network-s-equals-g'(s) { await s.choose('Network', 'Separable (S = G exactly)'); },
  async 'network-g-equals-gb'(s) { await s.choose('Network', 'Dome, m = n = 5'); },
  async 'network-s-near-t'(s) { await s.choose('Network', 'Dome 10 × 10 (speed)'); },
};

// Where the finger leaves the knot of the envelope exercises (the box must show exactly this, and the state be it).
const KNOT_AT = { 'envelope-q1': '1.6', 'envelope-q2': '3.5', 'envelope-q3': '1.5' };

/** After a drag of the knot, the number box shows the value the state has (not 1.6 for 1.604). */
async function knotShown(t, want) {
  const box = t.page.locator('input.ctl-number[aria-label^="Moving knot value"]');
  assert.equal(await box.inputValue(), want, 'the knot box shows the dragged value');
  assert.equal(String(await t.page.evaluate(() => window.splinelab.current().state.up)), want, 'and the knot is exactly there');
}

test('every catalogue exercise is solved with touch and keyboard at 390×844; untouched none passes', async (tt) => {
  assert.deepEqual(catalogue.map((e) => e.id).sort(), Object.keys(SOLVE).sort(), 'a way to solve every catalogue exercise');
  for (const e of catalogue.filter((x) => !process.env.EXERCISE || x.id === process.env.EXERCISE)) {
    await tt.test(e.id, async () => {
      const t = await H.open(e.href, { context: phone, waitFor: '.exercise-panel' });
      t.page.setDefaultTimeout(10000);
      const s = student(t);
      assert.equal(await t.page.textContent('.exercise-task'), e.task);
      const untouched = await s.check();
      assert.match(untouched, /^Not yet\. [^:]+: /, `untouched must not pass: ${untouched}`);
      await SOLVE[e.id](s, t);
      const fb = await s.check();
      assert.match(fb, /^Correct! /, `${e.id} solved by the UI: ${fb}`);
      if (KNOT_AT[e.id]) await knotShown(t, KNOT_AT[e.id]);
      if (e.id === 'envelope-q1') {
        // Q is drawn where the task says, with the task's digits, and the panel repeats them
        assert.match(e.task, /Q = \(2\.945, 1\.295\)/);
        assert.match(await t.page.textContent('.exercise-target'), /^Q = \(2\.945, 1\.295\)/);
        const dark = await t.page.$eval('canvas[data-plot="curve"]', (c) => {
          const [x, y] = c.splinePlot.toScreen(2.945333, 1.294667);
          const d = c.getContext('2d').getImageData(Math.round((x + 11) * devicePixelRatio), Math.round(y * devicePixelRatio), 1, 1).data;
          return d[0] + d[1] + d[2];
        });
        assert.ok(dark < 200, `the ring around Q is drawn (pixel sum ${dark})`);
        await t.page.locator('canvas[data-plot="curve"]').evaluate((c) => c.scrollIntoView({ block: 'start' }));
        await t.screenshot('exercise-ui-envelope-q', { fullPage: false });
      }
      t.assertClean();
      await t.close();
    });
  }
});

test('typing into a number box: 1/6 keeps its text and shows its exact value; clamped and refused input say so', async () => {
  const e = catalogue.find((x) => x.id === 'b2-through-data');
  const t = await H.open(e.href, { context: phone, waitFor: '.exercise-panel' });
  const s = student(t);
  const r = await s.type('Approximation a', '1/6');
  assert.equal(r.value, '1/6');
  assert.equal(r.note, '= 0.1666666667');
  assert.equal(await t.page.evaluate(() => window.splinelab.current().state.a), 1 / 6);
  await t.screenshot('exercise-ui-typed-fraction', { fullPage: false });
  const big = await s.type('Approximation a', '1/2');
  assert.equal(big.note, 'Approximation a: 1/2 is above the maximum 0.25; set to 0.25.');
  assert.equal(big.value, '0.25');
  const bad = await s.type('Approximation a', '1//6');
  assert.match(bad.note, /^Approximation a: “1\/\/6” is not a number .*it stays 0\.25/);
  assert.equal(await t.page.evaluate(() => window.splinelab.current().state.a), 0.25, 'refused input changes nothing');
  await s.tapLabel('Modified knots (K)');
  const k = await s.type('K', '200');
  assert.equal(k.note, 'K: 200 is above the maximum 100; set to 100.');
  await t.screenshot('exercise-ui-clamped-K', { fullPage: false });
  t.assertClean();
  await t.close();
});

test('on a phone the figure stays on screen while a control of the exercise is used', async () => {
  const e = catalogue.find((x) => x.id === 'remodel-alpha');
  const t = await H.open(e.href, { context: phone, waitFor: '.exercise-panel' });
  const s = student(t);
  await s.type('α₁⁽³⁾', '0.5');
  const box = t.page.locator('input.ctl-number[aria-label^="α₁⁽³⁾"]');
  const b = await box.boundingBox();
  assert.ok(b.y >= 0 && b.y + b.height <= 844, 'the box being typed into is on screen');
  const seen = await s.figureVisible();
  assert.ok(seen >= 0.6, `the figure is on screen with the control: ${(seen * 100).toFixed(0)} % of it visible`);
  await t.screenshot('exercise-ui-figure-and-control', { fullPage: false });
  await t.close();
});

test('an embedded exercise with storage blocked: no notice over the task, no "copy the address"', async () => {
  const ctx = await H.browser.newContext(PHONE);
  // a third-party frame without storage (private windows, Safari, Firefox strict): localStorage throws there
  await ctx.addInitScript(() => {
    if (window.self !== window.top) Object.defineProperty(window, 'localStorage', { get() { throw new DOMException('blocked', 'SecurityError'); } });
  });
  const e = catalogue.find((x) => x.id === 'noisy-sine');
  const t = await H.open('exercises.html', { context: ctx });
  await t.page.evaluate((src) => new Promise((ok) => {
    const f = document.createElement('iframe');
    f.src = src; f.style.cssText = 'width:380px;height:760px;border:0'; f.onload = () => ok();
    document.body.prepend(f);
  }), e.href.replace('index.html', 'embed.html'));
  const frame = t.page.frame({ url: /embed\.html/ });
  await frame.waitForSelector('.exercise-panel .exercise-check');
  await frame.waitForFunction(() => document.documentElement.dataset.storage === 'off');
  await t.frames(3);
  const seen = await frame.evaluate(() => {
    const notes = document.getElementById('notices')?.textContent || '';
    const task = document.querySelector('.exercise-task').getBoundingClientRect();
    const top = document.elementFromPoint(task.left + task.width / 2, task.top + task.height / 2);
    return { notes, covered: !top?.closest('.exercise-task'), line: document.querySelector('.storage-embedded')?.textContent || '' };
  });
  assert.doesNotMatch(seen.notes, /copy the address/i);
  assert.equal(seen.covered, false, 'the task is not covered');
  assert.match(seen.line, /Saving is off in this embedded view/);
  await t.screenshot('exercise-ui-embedded-storage-off', { fullPage: false });
  await frame.click('.exercise-check');
  await frame.waitForFunction(() => document.querySelector('.exercise-feedback').textContent !== '');
  assert.match(await frame.textContent('.exercise-feedback'), /^Not yet\. RMS distance to the true sine: 0\.\d+; the tolerance is 0\.17/);
  await t.close();
  await ctx.close();
});
