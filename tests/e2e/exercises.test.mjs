// Exercises that check themselves (www/lib/exercise.js, exercise-checks.js, exercises.html), in the real pages:
// every catalogue exercise fails untouched and with a wrong answer, passes with the intended answer, counts
// attempts and says how far off; the result reaches the host page (postMessage from embed.html in an iframe,
// the `splinelab-result` event from <spline-lab>); "Make exercise" produces a working link.
// Run: node --test --test-concurrency=1 tests/e2e/exercises.test.mjs   (needs www/pkg: scripts/build-wasm.sh)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

const ELLIPSE = [[3, 0], [0, 1.5], [-3, 0], [0, -1.5]];
// For every catalogue exercise: a wrong answer and the intended one (changes to the exercise's start state).
const SOLUTIONS = {
  'b2-through-data': { wrong: { a: 0.05 }, answer: { a: 0 } },
  'noisy-sine': { wrong: { a: 0.1 }, answer: { a: 0.2 } },
  'noisy-spiral': { wrong: { a: 0.25 }, answer: { a: 0.12 } },
  'noisy-arc': { wrong: { a: 0.05 }, answer: { a: 0.2 } },
  'remodel-c1': { wrong: { alphas: [[1 / 3, 1 / 3], [0.5, 1 / 3], [1 / 3, 1 / 3], [1 / 3, 1 / 3], [1 / 3, 1 / 3]] }, answer: { enforce: true } },
  'remodel-alpha': { wrong: { alphas: [[0.1, 0.1], [0.9, 1 / 3], [2 / 3, 0.25], [0.7, 0.01], [0.99, 0.2]] },
    answer: { alphas: [[0.1, 0.1], [0.9, 1 / 3], [2 / 3, 0.25], [0.75, 0.01], [0.99, 0.2]] } },
  'bspline-c2': { wrong: { knots: [0, 0, 0, 0, 0.5, 0.5, 0.75, 1, 1, 1, 1] }, answer: { knots: [0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1] } },
  'envelope-q1': { wrong: { up: 1.8 }, answer: { up: 1.6 } },
  'envelope-q2': { wrong: { up: 3.7 }, answer: { up: 3.5 } },
  'envelope-q3': { wrong: { up: 1.2 }, answer: { up: 1.5 } },
  'qc-ellipse-alpha': { wrong: { alpha: 0.99 }, answer: { alpha: 1 } },
  'qc-ellipse-drag': { wrong: { points: [[3, 0.6], ELLIPSE[1], ELLIPSE[2], ELLIPSE[3]] }, answer: { points: ELLIPSE } },
  'qc-interpolate': { wrong: { alpha: 1 }, answer: { alpha: 3 } },
  'network-s-equals-g': { wrong: { preset: 'dome' }, answer: { preset: 'separable' } },
  'network-g-equals-gb': { wrong: { preset: 'three-sided' }, answer: { preset: 'dome' } },
  'network-s-near-t': { wrong: { preset: 'separable' }, answer: { preset: 'dome10' } },
};
const RESULT_KEYS = ['attempts', 'exercise', 'passed', 'score', 'state', 'type'];

let H, catalogue;
before(async () => {
  H = await startHarness();
  const t = await H.open('exercises.html');
  catalogue = await t.page.$$eval('.exercise-card', (cs) => cs.map((c) => ({
    id: c.dataset.exercise, demo: c.dataset.demo, paper: c.closest('[data-paper]').dataset.paper,
    task: c.querySelector('p').textContent,
    href: c.querySelector('.exercise-open').getAttribute('href'), embed: c.querySelector('.exercise-embed').getAttribute('href'),
  })));
  t.assertClean();
  await t.close?.();
});
after(() => H?.close());

/** Records every `splinelab-result` that reaches the document (the panel's event bubbles). */
async function listen(t) {
  await t.page.evaluate(() => { window.__results = []; document.addEventListener('splinelab-result', (e) => window.__results.push(e.detail)); });
}

/** Presses Check and returns { feedback, attempts, detail }. */
async function check(t) {
  const n = await t.page.evaluate(() => window.__results.length);
  await t.page.click('.exercise-panel .exercise-check');
  await t.page.waitForFunction((k) => window.__results.length > k, n);
  return t.page.evaluate(() => ({
    feedback: document.querySelector('.exercise-feedback').textContent,
    attempts: document.querySelector('.exercise-attempts').textContent,
    detail: window.__results[window.__results.length - 1],
  }));
}

/** Re-opens the mounted demo with `changes` applied to its state (the exercise stays): a hash with the answer. */
async function setState(t, changes) {
  await t.page.evaluate(async (ch) => {
    document.querySelector('.exercise-panel').dataset.old = 'true';
    await window.splinelab.flush(); // a pending (debounced) save of the demo must not overwrite the new hash
    const cur = window.splinelab.current();
    const { encodeState } = await import('./lib/state.js');
    location.hash = `#${cur.id}/${await encodeState({ ...cur.state, ...ch })}`;
  }, changes);
  await t.page.waitForSelector('.exercise-panel:not([data-old])', { timeout: 60000 }).catch(async (err) => {
    const info = await t.page.evaluate(() => ({ hash: location.hash.slice(0, 60), cur: window.splinelab.current()?.payload?.slice(0, 40), notices: document.getElementById('notices').textContent, panels: [...document.querySelectorAll('.exercise-panel')].map((p) => [p.dataset.old, p.offsetHeight, p.parentNode?.id]), r: window.splinelab.current()?.state.r, enf: window.splinelab.current()?.state.enforce }));
    throw new Error(`${err.message}\n${JSON.stringify(info)} ${t.errors().join('; ')}`);
  });
  await t.page.waitForSelector('#demo-root[data-mounted="true"]');
  await t.frames(2);
}

test('the catalogue lists at least 15 exercises covering the five papers, linked from the gallery', async () => {
  assert.ok(catalogue.length >= 15, `${catalogue.length} exercises`);
  for (const p of ['000', '001', '002', '003', '004']) assert.ok(catalogue.some((e) => e.paper === p), `paper ${p}`);
  assert.deepEqual(catalogue.map((e) => e.id).sort(), Object.keys(SOLUTIONS).sort(), 'every catalogue exercise has a tested solution');
  for (const e of catalogue) {
    assert.match(e.href, new RegExp(`^index\\.html#${e.demo}/v[01]\\.`));
    assert.equal(e.embed, e.href.replace('index.html', 'embed.html'));
  }
  const g = await H.open('');
  assert.ok(await g.page.$('a[href="exercises.html"]'), 'the gallery links to the catalogue');
  await g.close?.();
});

test('every catalogue exercise: untouched and wrong answers fail, the intended answer passes, attempts count', async (tt) => {
  // EXERCISE=<id> runs one exercise only (when debugging one)
  for (const e of catalogue.filter((x) => !process.env.EXERCISE || x.id === process.env.EXERCISE)) {
    await tt.test(e.id, async () => {
      const t = await H.open(e.href, { waitFor: '.exercise-panel' });
      await listen(t);
      assert.equal(await t.page.textContent('.exercise-task'), e.task, 'the task is shown');
      assert.equal(await t.page.textContent('.exercise-attempts'), '0 attempts');
      const untouched = await check(t);
      assert.equal(untouched.detail.passed, false, `untouched must not pass: ${untouched.feedback}`);
      assert.match(untouched.feedback, /^Not yet\. [^:]+: [−0-9.]+( × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?; the tolerance is [0-9.]+( × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?/);
      assert.match(untouched.feedback, /Hint: /);
      assert.equal(untouched.attempts, '1 attempt');
      assert.ok(untouched.detail.score >= 0 && untouched.detail.score < 1);

      await setState(t, SOLUTIONS[e.id].wrong);
      const wrong = await check(t);
      assert.equal(wrong.detail.passed, false, `wrong answer must not pass: ${wrong.feedback}`);
      assert.equal(wrong.attempts, '2 attempts');

      await setState(t, SOLUTIONS[e.id].answer);
      const right = await check(t);
      assert.equal(right.detail.passed, true, `intended answer must pass: ${right.feedback}`);
      assert.match(right.feedback, /^Correct! [^:]+: /);
      assert.equal(right.attempts, '3 attempts');
      assert.equal(right.detail.attempts, 3);
      assert.equal(right.detail.score, 1);
      assert.deepEqual(Object.keys(right.detail).filter((k) => RESULT_KEYS.includes(k)).sort(), RESULT_KEYS);
      assert.equal(right.detail.type, 'splinelab:result');
      assert.equal(right.detail.exercise, e.id);
      assert.equal(right.detail.state.exercise, undefined, 'the state sent is the demo state');
      for (const [k, v] of Object.entries(SOLUTIONS[e.id].answer)) if (k !== 'alphas') assert.deepEqual(right.detail.state[k], v, k);
      t.assertClean();
      await t.close?.();
    });
  }
});

test('a real interaction: typing a = 0 in the slider’s number field solves "Through the data"', async () => {
  const e = catalogue.find((x) => x.id === 'b2-through-data');
  const t = await H.open(e.href, { waitFor: '.exercise-panel' });
  await listen(t);
  assert.equal((await check(t)).detail.passed, false);
  const field = t.page.locator('input.ctl-number[aria-label^="Approximation a"]');
  await field.fill('0');
  await field.press('Enter');
  await t.frames(2);
  const r = await check(t);
  assert.equal(r.detail.passed, true, r.feedback);
  assert.equal(r.detail.state.a, 0);
  t.assertClean();
  await t.close?.();
});

test('an exercise link opens in embed.html; in an iframe the result is posted to the parent', async () => {
  const e = catalogue.find((x) => x.id === 'qc-ellipse-alpha');
  const t = await H.open('exercises.html');
  await t.page.evaluate((src) => new Promise((ok) => {
    window.__msgs = [];
    window.addEventListener('message', (m) => { if (m.data && m.data.type === 'splinelab:result') window.__msgs.push({ data: m.data, fromFrame: m.source === document.getElementById('ex').contentWindow }); });
    const f = document.createElement('iframe');
    f.id = 'ex'; f.src = src; f.width = '1000'; f.height = '800'; f.onload = () => ok();
    document.body.append(f);
  }), e.embed);
  const frame = t.page.frame({ url: /embed\.html/ });
  await frame.waitForSelector('.exercise-panel .exercise-check');
  assert.equal(await frame.textContent('.exercise-task'), e.task);
  await frame.click('.exercise-check');
  await t.page.waitForFunction(() => window.__msgs.length === 1);
  const [{ data, fromFrame }] = await t.page.evaluate(() => window.__msgs);
  assert.equal(fromFrame, true);
  assert.deepEqual(Object.keys(data).filter((k) => RESULT_KEYS.includes(k)).sort(), RESULT_KEYS);
  assert.equal(data.type, 'splinelab:result');
  assert.equal(data.exercise, 'qc-ellipse-alpha');
  assert.equal(data.passed, false);
  assert.equal(data.attempts, 1);
  assert.ok(data.score >= 0 && data.score < 1);
  assert.equal(data.state.alpha, 0.5);
  t.assertClean();
  await t.close?.();
});

test('<spline-lab> with an exercise state: a bubbling, composed splinelab-result event', async () => {
  const e = catalogue.find((x) => x.id === 'network-s-equals-g');
  const t = await H.open('exercises.html');
  await t.page.evaluate(async (href) => {
    await import('./spline-lab.js');
    window.__el = []; window.__doc = [];
    const el = document.createElement('spline-lab');
    el.id = 'lab';
    el.setAttribute('state', href);
    el.addEventListener('splinelab-result', (ev) => window.__el.push({ detail: ev.detail, target: ev.target.id }));
    document.addEventListener('splinelab-result', (ev) => window.__doc.push(ev.detail));
    document.body.append(el);
  }, e.href);
  await t.page.waitForFunction(() => document.getElementById('lab').dataset.ready === 'true', null, { timeout: 20000 });
  await t.page.waitForFunction(() => document.getElementById('lab').shadowRoot.querySelector('.exercise-check'));
  const task = await t.page.evaluate(() => document.getElementById('lab').shadowRoot.querySelector('.exercise-task').textContent);
  assert.equal(task, e.task);
  await t.page.evaluate(() => document.getElementById('lab').shadowRoot.querySelector('.exercise-check').click());
  await t.page.waitForFunction(() => window.__el.length === 1 && window.__doc.length === 1);
  const [{ detail, target }] = await t.page.evaluate(() => window.__el);
  assert.equal(target, 'lab', 'retargeted to the element: the event left the shadow root');
  assert.deepEqual(Object.keys(detail).filter((k) => RESULT_KEYS.includes(k)).sort(), RESULT_KEYS);
  assert.equal(detail.type, 'splinelab:result');
  assert.equal(detail.exercise, 'network-s-equals-g');
  assert.equal(detail.passed, false);
  assert.equal(detail.attempts, 1);
  assert.equal(detail.state.preset, 'paper');
  t.assertClean();
  await t.close?.();
});

test('"Make exercise": a teacher turns a view into an exercise link that works in index.html and embed.html', async () => {
  const t = await H.open('#interp-approx');
  const field = t.page.locator('input.ctl-number[aria-label^="Approximation a"]');
  await field.fill('0.1');
  await field.press('Enter');
  assert.equal(await t.page.isVisible('.exercise-make'), false, 'the Make exercise panel is closed until asked for');
  await t.page.click('button.exercise-make-toggle');
  assert.equal(await t.page.isVisible('.exercise-make'), true);
  assert.equal(await t.page.getAttribute('button.exercise-make-toggle', 'aria-expanded'), 'true');
  await t.page.selectOption('.exercise-make-check', 'data-distance');
  await t.page.fill('.exercise-make-tol', '1e-6');
  await t.page.fill('.exercise-make-title', 'My first exercise');
  await t.page.fill('.exercise-make-task', 'Make the curve interpolate the data.');
  await t.page.fill('.exercise-make-hint', 'Look at a.');
  // the measurement is written when the module answers (async): wait for it, then read it
  await t.page.waitForFunction(() => document.querySelector('.exercise-make-now').textContent !== '');
  assert.match(await t.page.textContent('.exercise-make-now'), /does not pass/);
  await t.page.click('.exercise-make-go');
  await t.page.waitForFunction(() => document.querySelector('.exercise-make-link').value !== '');
  const link = await t.page.inputValue('.exercise-make-link');
  const iframe = await t.page.inputValue('.exercise-make-iframe');
  const element = await t.page.inputValue('.exercise-make-element');
  assert.match(link, /\/index\.html#interp-approx\/v[01]\./);
  const hash = link.slice(link.indexOf('#'));
  assert.ok(iframe.includes(`embed.html${hash}`), iframe);
  assert.ok(element.includes('<spline-lab demo="interp-approx" state="'), element);
  await t.close?.();

  for (const page of ['', 'embed.html']) {
    const s = await H.open(page + hash, { waitFor: '.exercise-panel' });
    await listen(s);
    assert.equal(await s.page.textContent('.exercise-title'), 'Exercise: My first exercise');
    assert.equal(await s.page.textContent('.exercise-task'), 'Make the curve interpolate the data.');
    const first = await check(s);
    assert.equal(first.detail.passed, false);
    assert.match(first.feedback, /Hint: Look at a\./);
    assert.equal(first.detail.exercise, 'interp-approx-data-distance');
    await setState(s, { a: 0 });
    const second = await check(s);
    assert.equal(second.detail.passed, true, second.feedback);
    assert.equal(second.detail.attempts, 2);
    s.assertClean();
    await s.close?.();
  }
});

test('a damaged exercise in a link is reported and the demo still opens', async () => {
  const t = await H.open('#interp-approx');
  await t.page.evaluate(async () => {
    const { encodeState } = await import('./lib/state.js');
    const st = window.splinelab.current().state;
    location.hash = `#interp-approx/${await encodeState({ ...st, a: 0.1, exercise: { v: 99, task: 'x', check: 'data-distance', tol: 1 } })}`;
  });
  await t.page.waitForFunction(() => window.splinelab.current()?.state.a === 0.1);
  await t.page.waitForSelector('.notice-warning');
  assert.match(await t.page.textContent('#notices'), /exercise in this link could not be read \(this link's exercise has version 99/);
  assert.equal(await t.page.$('.exercise-panel'), null);
  await t.close?.();
});
