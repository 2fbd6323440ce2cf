// Accessibility of the gallery and of every demo, in index.html#<id> and embed.html#<id>: axe-core reports no
// serious or critical violation; every canvas has an accessible name; keyboard only (one Tab stop per plot,
// PageDown chooses a point, said by its subscripted name, arrow keys) moves a point in every demo that has
// draggable 2D points; focus is visible; prefers-reduced-motion turns the CSS transitions off. Headless
// Chromium, every request on 127.0.0.1.
// Run: node --test tests/e2e/a11y.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness, demoIds, demoExists } from './harness.mjs';
import { asciiIndexIn } from './raw-notation.mjs';

let H;
let ids;
before(async () => { H = await startHarness(); ids = await demoIds(); });
after(async () => { await H?.close(); });

const fmtViolations = (v) => v.map((x) => `${x.id} (${x.impact}): ${x.help} — ${x.nodes.join(', ')}`).join('\n');

test('the gallery: no serious axe violation, a link to the guide', async () => {
  const t = await H.open('');
  const v = await t.axe();
  assert.deepEqual(v, [], fmtViolations(v));
  assert.ok(await t.page.$('footer a[href="guide.html"]'), 'footer links the guide');
  t.assertClean();
  await t.close();
});

test('every demo in index.html and embed.html: no serious axe violation, named canvases', async (tt) => {
  for (const id of ids) {
    await tt.test(id, async () => {
      assert.ok(await demoExists(id), `${id}: listed in www/demos/index.js but www/demos/${id}.js is missing (a renamed demo fails, it is not skipped)`);
      for (const route of [`#${id}`, `embed.html#${id}`]) {
        const t = await H.open(route);
        await t.page.hover('.export-bar').catch(() => {});
        if (!route.startsWith('embed')) await t.page.click('.share-toggle'); // the Share panel open too
        await t.frames(2);
        const v = await t.axe();
        assert.deepEqual(v, [], `${route}\n${fmtViolations(v)}`);
        const unnamed = await t.page.$$eval('canvas', (cs) => cs.filter((c) => !c.closest('[aria-hidden="true"]') && !(c.getAttribute('aria-label') || c.getAttribute('aria-labelledby'))).length);
        assert.equal(unnamed, 0, `${route}: every canvas has an accessible name`);
        t.assertClean();
        await t.close();
      }
    });
  }
});

/** Presses Tab until a 2D plot canvas with draggable points has focus. Returns its index among the canvases or -1. */
async function tabToHandles(t, max = 80) {
  for (let i = 0; i < max; i++) {
    const k = await t.page.evaluate(() => {
      const a = document.activeElement;
      if (!a || a.tagName !== 'CANVAS' || !a.splinePlot) return -1;
      if (!a.splinePlot.handles().length) return -1;
      return [...document.querySelectorAll('canvas')].indexOf(a);
    });
    if (k >= 0) return k;
    await t.page.keyboard.press('Tab');
  }
  return -1;
}

/** The focused plot's keyboard state: its selected handle's place in handles() (-1: none) and its live region. */
const plotKeys = (t, k) => t.page.evaluate((k) => {
  const c = document.querySelectorAll('canvas')[k], p = c.splinePlot, sel = p.selected;
  const at = sel ? p.handles().findIndex((h) => h.name === sel.group.name && h.index === sel.index) : -1;
  return { at, n: p.handles().length, point: at >= 0 ? p.handles()[at].point.slice() : null, live: c.closest('.plot').querySelector('[aria-live]').textContent, focused: document.activeElement === c };
}, k);
/** A spoken handle name with its paper subscript and place: "Control point P₁ (2 of 7) at (…)". */
const NAMED = /[₀-₉] \((\d+) of (\d+)\) at \(/u;

// Issue 25 (WCAG 2.2 SC 2.4.3 / 2.1.1): one Tab stop per 2D plot. Tab from the element before enters the plot (the
// first point is selected and said), PageDown chooses the next (said with its subscripted name), an arrow moves
// it, and Tab leaves the canvas at once (to the point's fields or on), never to another point of the plot.
test('keyboard only: one Tab stop per plot; PageDown chooses the next point, said by name; an arrow moves it (every 2D demo)', async (tt) => {
  for (const id of ids) {
    await tt.test(id, async () => {
      assert.ok(await demoExists(id), `${id}: listed in www/demos/index.js but www/demos/${id}.js is missing (a renamed demo fails, it is not skipped)`);
      const t = await H.open(`#${id}`);
      const has2D = await t.page.$$eval('canvas', (cs) => cs.some((c) => c.splinePlot && c.splinePlot.handles().length && c.getClientRects().length));
      if (!has2D) { await t.close(); return; } // 3D-only demo (its View3D has its own keyboard test)
      const before = JSON.stringify(await t.state());
      const k = await tabToHandles(t);
      assert.ok(k >= 0, `${id}: Tab reaches a plot with draggable points`);
      // the focus is visible: the canvas draws an outline (CSS :focus-visible)
      const outline = await t.page.evaluate(() => { const s = getComputedStyle(document.activeElement); return [s.outlineStyle, parseFloat(s.outlineWidth)]; });
      assert.equal(outline[0], 'solid', `${id}: focus outline`);
      assert.ok(outline[1] >= 2, `${id}: focus outline width`);
      await t.frames(2);
      const entered = await plotKeys(t, k);
      assert.equal(entered.at, 0, `${id}: entering with Tab selects the first point`);
      assert.match(entered.live, NAMED, `${id}: the entered point is said by name and place (live region: ${entered.live})`);
      await t.press('PageDown');
      const next = await plotKeys(t, k);
      assert.equal(next.at, 1 % next.n, `${id}: PageDown selects the next point`);
      const m = next.live.match(NAMED);
      assert.ok(m && Number(m[1]) === next.at + 1 && Number(m[2]) === next.n, `${id}: PageDown says the point's subscripted name and place (live region: ${next.live})`);
      assert.deepEqual(asciiIndexIn(next.live), [], `${id}: no ASCII index in what is said`);
      await t.press('ArrowRight', 'ArrowUp', 'Shift+ArrowRight');
      const moved = await plotKeys(t, k);
      assert.notDeepEqual(moved.point, next.point, `${id}: the arrow keys moved the chosen point (${next.point} → ${moved.point})`);
      await t.flushState();
      const after = JSON.stringify(await t.state());
      assert.notEqual(after, before, `${id}: the arrow keys changed the state`);
      // one Tab leaves the canvas (to the point's fields, or on), the point stays chosen; a second Tab is not back on it
      await t.press('Tab');
      const out1 = await plotKeys(t, k);
      assert.equal(out1.focused, false, `${id}: the first Tab leaves the canvas`);
      await t.press('Tab');
      const out2 = await plotKeys(t, k);
      assert.equal(out2.focused, false, `${id}: the second Tab is not on the canvas`);
      assert.ok(out2.at === -1 || out2.at === next.at, `${id}: Tab never chose another point (${out2.at})`);
      t.assertClean();
      await t.close();
    });
  }
});

test('visible focus on buttons, links and controls', async () => {
  const t = await H.open('#bspline-basics');
  const seen = new Set();
  // 80 presses: the page's first link came after about 40 stops while the curve plot took one per control point
  // (each plot is one stop since issue 25; the scrollable table one more); kept at 80, a margin
  for (let i = 0; i < 80; i++) {
    await t.page.keyboard.press('Tab');
    const r = await t.page.evaluate(() => {
      const a = document.activeElement;
      if (!a || a === document.body) return null;
      const s = getComputedStyle(a);
      const own = s.outlineStyle !== 'none' && parseFloat(s.outlineWidth) >= 2;
      // segmented radio groups draw the outline on the label that follows the input
      const lab = a.matches('input[type=radio]') && a.nextElementSibling ? getComputedStyle(a.nextElementSibling) : null;
      const viaLabel = !!lab && lab.outlineStyle !== 'none' && parseFloat(lab.outlineWidth) >= 2;
      return { tag: a.tagName, type: a.type || '', ok: own || viaLabel, what: a.outerHTML.slice(0, 80) };
    });
    if (!r) continue;
    seen.add(r.tag);
    assert.ok(r.ok, `no visible focus on ${r.what}`);
  }
  assert.ok(seen.has('BUTTON') && seen.has('A'), `tabbed through buttons and links (${[...seen]})`);
  await t.close();
});

test('prefers-reduced-motion: no CSS transitions or animations', async () => {
  const durations = async (t) => t.page.evaluate(() => {
    let moving = 0;
    for (const e of document.querySelectorAll('*')) {
      const s = getComputedStyle(e);
      const tr = s.transitionDuration.split(',').some((d) => parseFloat(d) > 0);
      const an = s.animationName !== 'none' && s.animationDuration.split(',').some((d) => parseFloat(d) > 0);
      if (tr || an) moving++;
    }
    return moving;
  });
  const normal = await H.open('#bspline-basics');
  assert.ok(await durations(normal) > 0, 'some transitions exist without the preference (the check can fail)');
  await normal.close();
  const t = await H.open('#bspline-basics', { reducedMotion: 'reduce' });
  assert.equal(await t.page.evaluate(() => matchMedia('(prefers-reduced-motion: reduce)').matches), true);
  assert.equal(await durations(t), 0, 'no element transitions or animates');
  t.assertClean();
  await t.close();
});

// Panning and zooming a 2D plot with single clicks (WCAG 2.2 SC 2.5.1, 2.5.7; www/lib/plot2d/tools.js): every plot
// that pans or zooms has a tool row under its drawing (not over it), one Tab stop, targets ≥ 24 px; Pan right moves
// the view by a fifth of its width, Zoom in shrinks it by 1.25, Fit gives the view of the 0 key back; each click is
// said, keeps the focus on the plot, and goes where a key's zoom goes (state.view, the link; Ctrl+Z undoes it).
// A representative set: curves and κ (both axes), knot-modification's knot line (x only), bspline-basics (one
// plot that does not pan: no row).
test('2D view tools: one click pans, zooms, fits; said; the link changes; under the drawing; ≥ 24 px', async (tt) => {
  const inPlot = (t, k, fn, arg) => t.page.evaluate(([kk, src, a]) => (0, eval)(`(${src})`)([...document.querySelectorAll('canvas')].filter((c) => c.splinePlot && c.getClientRects().length)[kk], a), [k, fn.toString(), arg]);
  for (const id of ['blended-interpolation', 'knot-modification', 'bspline-basics']) {
    await tt.test(id, async () => {
      const t = await H.open(`#${id}`);
      const plots = await t.page.$$eval('canvas', (cs) => cs.filter((c) => c.splinePlot && c.getClientRects().length).map((c) => {
        const o = c.splinePlot.options, row = c.closest('.plot').querySelector(':scope > .plot-toolbar');
        const cr = c.getBoundingClientRect(), rr = row?.getBoundingClientRect();
        return {
          moves: !!(o.pan || o.zoom), zoomY: o.zoomY !== false, row: !!row, role: row?.getAttribute('role'), under: rr ? rr.top >= cr.bottom - 0.5 : null,
          stops: row ? [...row.querySelectorAll('button')].filter((b) => b.tabIndex === 0).length : 0,
          labels: row ? [...row.querySelectorAll('button')].map((b) => b.getAttribute('aria-label')) : [],
          small: row ? [...row.querySelectorAll('button')].map((b) => b.getBoundingClientRect()).filter((r) => r.width < 24 || r.height < 24).length : 0,
        };
      }));
      for (const [k, p] of plots.entries()) {
        assert.equal(p.row, p.moves, `${id} plot ${k}: a tool row exactly when it pans or zooms`);
        if (!p.row) continue;
        assert.deepEqual([p.role, p.under, p.stops, p.small], ['toolbar', true, 1, 0], `${id} plot ${k}: a toolbar under the drawing, one Tab stop, no target under 24 px`);
        assert.deepEqual(p.labels.filter((l) => l !== 'Play as sound'), [...['Pan left', 'Pan right'], ...(p.zoomY ? ['Pan up', 'Pan down'] : []), 'Zoom in', 'Zoom out', 'Fit to content'], `${id} plot ${k}: its buttons`);
      }
      const k = plots.findIndex((p) => p.row);
      if (id === 'bspline-basics') assert.ok(plots.some((p) => !p.row), `${id}: its basis plot does not pan and has no row`);
      if (k < 0) { await t.close(); return; }
      await inPlot(t, k, (c) => { c.scrollIntoView({ block: 'center', behavior: 'instant' }); c.focus(); });
      await t.press('0');   // the keyboard's fit: the view Fit must give back
      const fitted = await inPlot(t, k, (c) => c.splinePlot.getView());
      const click = async (label) => {
        const box = await inPlot(t, k, (c, l) => { const r = c.closest('.plot').querySelector(`.plot-toolbar [aria-label="${l}"]`).getBoundingClientRect(); return [r.x + r.width / 2, r.y + r.height / 2]; }, label);
        await t.page.mouse.click(box[0], box[1]);
        await t.frames(2);
        return inPlot(t, k, (c) => ({ v: c.splinePlot.getView(), focused: document.activeElement === c }));
      };
      const before = await t.flushState();
      const right = await click('Pan right');
      const w = fitted.xmax - fitted.xmin;
      assert.ok(Math.abs(right.v.xmin - fitted.xmin - 0.2 * w) < 1e-9 * w && Math.abs(right.v.ymin - fitted.ymin) < 1e-12 + 1e-9 * Math.abs(fitted.ymin), `${id}: Pan right moves the view a fifth of its width to the right (${fitted.xmin} → ${right.v.xmin}, width ${w})`);
      assert.equal(right.focused, true, `${id}: the click leaves the focus on the plot`);
      const hash = await t.flushState();
      assert.notEqual(hash, before, `${id}: the click changed the link`);
      const saved = (await t.state()).view;
      assert.ok(Array.isArray(saved) && Math.abs(saved[0] - right.v.xmin) < 1e-6 * w, `${id}: the state holds the panned view (${saved})`);
      await t.page.waitForFunction((kk) => /^Pan right\. x from .+ to /.test([...document.querySelectorAll('canvas')].filter((c) => c.splinePlot && c.getClientRects().length)[kk].closest('.plot').querySelector('[aria-live]').textContent), k, { timeout: 3000 })
        .catch(() => {});
      const said = await inPlot(t, k, (c) => c.closest('.plot').querySelector('[aria-live]').textContent);
      assert.match(said, /^Pan right\. x from -?[\d.]+ to -?[\d.]+/, `${id}: the pan is said in the plot's live region`);
      const zoomed = await click('Zoom in');
      const zw = zoomed.v.xmax - zoomed.v.xmin;
      assert.ok(Math.abs(zw - w / 1.25) < 1e-9 * w, `${id}: Zoom in shrinks the width by 1.25 (${w} → ${zw})`);
      // the key's zoom takes the same path: the link changes alike
      const h1 = await t.flushState();
      await t.press('+');
      assert.notEqual(await t.flushState(), h1, `${id}: the + key changes the link too`);
      const back = await click('Fit to content');
      for (const key of ['xmin', 'xmax', 'ymin', 'ymax']) assert.ok(Math.abs(back.v[key] - fitted[key]) < 1e-9 * w + 1e-12, `${id}: Fit gives the fitted view back (${key} ${fitted[key]} → ${back.v[key]})`);
      await click('Pan left');
      const h2 = await t.flushState();
      await undo(t);
      assert.notEqual(await t.flushState(), h2, `${id}: Ctrl+Z undoes the pan's link`);
      t.assertClean();
      await t.close();
    });
  }
});

async function undo(t) {
  await t.page.keyboard.press('Control+z');
  await t.page.waitForSelector('#demo-root[data-mounted="true"]');
  await t.settled();
  await t.frames(3);
}
