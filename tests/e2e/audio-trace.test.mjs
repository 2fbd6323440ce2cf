// "Figures in sound" (www/lib/audio-trace.js, issue 25): the ♪ button and the keys S , . of a plot play its curve
// or basis function. The page's AudioContext is a recording stub (no sound in CI): every node created, its type,
// every scheduled parameter call and every start / stop. One page goes through bspline-basics (curve and basis
// plots, a link with a double knot), knot-modification, quasi-cubic-curves, blended-interpolation and interp-approx.
//
// Ticks: one click per distinct knot strictly inside the parameter domain; the two end knots are not clicked
// (the sound starts and stops there, and a clamped vector's ends are not joints between pieces).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

let H;
before(async () => { H = await startHarness(); });
after(() => H.close());

function stubAudio() {
  const A = { contexts: 0, nodes: [] };
  /** @type {any} */ (window).__audio = A;
  class Param {
    constructor() { this.calls = []; this.value = 0; }
    setValueAtTime(v, t) { this.calls.push(['set', v, t]); return this; }
    linearRampToValueAtTime(v, t) { this.calls.push(['ramp', v, t]); return this; }
    setValueCurveAtTime(c, t, d) { this.calls.push(['curve', Array.from(c), t, d]); return this; }
    cancelScheduledValues() { return this; }
  }
  class Node {
    constructor(kind) { this.kind = kind; this.start_ = null; this.stops = 0; A.nodes.push(this); }
    connect(n) { return n; }
    disconnect() {}
    start(t = 0) { this.start_ = t; }
    stop(t) { if (t === undefined) this.stops++; else this.stopAt = t; } // stops: stop() now (not a scheduled end)
  }
  class Ctx {
    constructor() { A.contexts++; this.currentTime = 0; this.sampleRate = 44100; this.destination = new Node('destination'); }
    createOscillator() { const n = new Node('oscillator'); n.type = 'sine'; n.frequency = new Param(); return n; }
    createGain() { const n = new Node('gain'); n.gain = new Param(); return n; }
    createStereoPanner() { const n = new Node('panner'); n.pan = new Param(); return n; }
    createBuffer(_c, len) { const d = new Float32Array(len); return { length: len, getChannelData: () => d }; }
    createBufferSource() { return new Node('click'); }
    resume() { return Promise.resolve(); }
    close() { return Promise.resolve(); }
  }
  /** @type {any} */ (window).AudioContext = Ctx;
}

/** What the stub recorded since node `from`: the voices (oscillators), clicks, panners, as plain data. */
const recorded = (page, from = 0) => page.evaluate((k) => {
  const A = /** @type {any} */ (window).__audio;
  const ns = A.nodes.slice(k);
  return {
    contexts: A.contexts, count: A.nodes.length,
    voices: ns.filter((n) => n.kind === 'oscillator').map((n) => ({ type: n.type, start: n.start_, stops: n.stops, freq: n.frequency.calls })),
    clicks: ns.filter((n) => n.kind === 'click').map((n) => ({ start: n.start_, stops: n.stops })),
    pans: ns.filter((n) => n.kind === 'panner').map((n) => n.pan.calls),
  };
}, from);

/** C(u) of a clamped B-spline by de Boor's algorithm (independent of the page's wasm). */
function deBoor(p, U, P, u) {
  const n = P.length;
  let k = p;
  while (k < n - 1 && u >= U[k + 1]) k++;
  const d = P.slice(k - p, k + 1).map((q) => q.slice());
  for (let r = 1; r <= p; r++) {
    for (let j = p; j >= r; j--) {
      const i = k - p + j, den = U[i + p - r + 1] - U[i];
      const a = den > 0 ? (u - U[i]) / den : 0;
      d[j] = [(1 - a) * d[j - 1][0] + a * d[j][0], (1 - a) * d[j - 1][1] + a * d[j][1]];
    }
  }
  return d[p];
}

test('the ♪ button and S, comma, period play and step; clicks at inner knots, timbre at a double knot', async () => {
  const context = await H.browser.newContext({ viewport: { width: 1280, height: 900 }, serviceWorkers: 'block' });
  await context.addInitScript(() => { /** @type {any} */ (window).splinelabWarm = 0; });
  await context.addInitScript(stubAudio);
  const t = await H.open('#bspline-basics', { context });
  const { page } = t;
  const curve = 'canvas[data-plot="curve"]', basis = 'canvas[data-plot="basis"]';
  const btn = (sel) => page.locator(`.plot:has(${sel}) .plot-sound`);

  assert.equal((await recorded(page)).contexts, 0, 'no AudioContext before the user asks');
  const box = await btn(curve).boundingBox();
  assert.ok(box && box.width >= 24 && box.height >= 24, `the ♪ button is at least 24×24 px (${JSON.stringify(box)})`);
  assert.equal(await btn(curve).getAttribute('aria-label'), 'Play as sound');
  const help = await page.$eval(curve, (c) => c.getAttribute('aria-describedby').split(' ').map((id) => document.getElementById(id)?.textContent).join(' '));
  assert.match(help, /plays the figure as sound/, 'the plot\'s help says the sound exists');

  // the button: one graph; the default cubic knots 0, 0, 0, 0, ¼, ½, ¾, 1, 1, 1, 1 → 3 inner knots, all C² → sine only
  await btn(curve).click();
  let r = await recorded(page);
  assert.equal(r.contexts, 1);
  assert.equal(r.clicks.length, 3, 'one click per distinct inner knot');
  assert.deepEqual(r.voices.map((v) => v.type), ['sine'], 'C² everywhere: one sine voice');
  assert.equal(await btn(curve).getAttribute('aria-pressed'), 'true');
  // the pitch follows y: every pair of scheduled points is ordered as the curve's heights there
  const st = await page.evaluate(() => window.splinelab.current().state);
  const f = r.voices[0].freq, t0 = f[0][2];
  const pts = f.map(([, hz, time]) => ({ hz, y: deBoor(st.degree, st.knots, st.points, Math.min(1, (time - t0) / 3))[1] }));
  const hi = pts.reduce((a, b) => (b.y > a.y ? b : a)), lo = pts.reduce((a, b) => (b.y < a.y ? b : a));
  assert.ok(hi.hz > lo.hz + 100, `higher y, higher pitch (y ${hi.y.toFixed(2)} → ${hi.hz.toFixed(0)} Hz, y ${lo.y.toFixed(2)} → ${lo.hz.toFixed(0)} Hz)`);
  for (let j = 1; j < pts.length; j++) {
    if (Math.abs(pts[j].y - pts[j - 1].y) > 1e-3) assert.equal(Math.sign(pts[j].hz - pts[j - 1].hz), Math.sign(pts[j].y - pts[j - 1].y), `pitch and y move together at point ${j}`);
  }
  assert.deepEqual(r.clicks.map((c) => +(c.start - t0).toFixed(6)), [0.75, 1.5, 2.25], 'clicks at u = ¼, ½, ¾ of 3 s');

  // S on the focused plot stops (every started node stopped), S again plays again in the same context
  await page.focus(curve);
  await page.keyboard.press('s');
  r = await recorded(page);
  assert.ok(r.voices.every((v) => v.stops > 0) && r.clicks.every((c) => c.stops > 0), 'S stops every voice and click');
  assert.equal(await btn(curve).getAttribute('aria-pressed'), 'false');
  let mark = r.count;
  await page.keyboard.press('s');
  r = await recorded(page, mark);
  assert.equal(r.contexts, 1, 'one AudioContext for the page');
  assert.equal(r.clicks.length, 3, 'S plays the trace');
  await page.keyboard.press('s');

  // period: steps of 1/20 of the domain, announced with the curve's numbers
  for (let k = 0; k < 8; k++) await page.keyboard.press('.');
  const live = await page.$eval(curve, (c) => c.parentElement.querySelector('[aria-live]').textContent);
  const m = live.match(/^u = (\d\.\d\d): \(([−\d.]+), ([−\d.]+)\)$/);
  assert.ok(m, `announced "${live}"`);
  assert.equal(m[1], '0.35', 'the eighth period press is at u = 7/20');
  const want = deBoor(st.degree, st.knots, st.points, 0.35);
  assert.equal(m[2], want[0].toFixed(2).replace('-', '−'));
  assert.equal(m[3], want[1].toFixed(2).replace('-', '−'));

  // the controls: one more point → one more inner knot; degree 2 → one more again
  await page.getByRole('button', { name: 'Add point' }).click();
  mark = (await recorded(page)).count;
  await btn(curve).click();
  assert.equal((await recorded(page, mark)).clicks.length, 4, '8 points, degree 3: 4 inner knots');
  await btn(curve).click();
  await page.getByRole('group', { name: 'Degree p' }).getByText('2', { exact: true }).click();
  await page.waitForFunction(() => window.splinelab.current().state.degree === 2);
  mark = (await recorded(page)).count;
  await btn(curve).click();
  assert.equal((await recorded(page, mark)).clicks.length, 5, '8 points, degree 2: 5 inner knots');

  // a link with a double knot at ½ (C¹ there): a triangle voice starts at ½, and playing stops when the plot goes
  await page.evaluate(async () => {
    const { encodeState } = await import('./lib/state.js');
    const s = window.splinelab.current().state;
    location.hash = `#bspline-basics/${await encodeState({ ...s, degree: 3, points: s.points.slice(0, 7), knots: [0, 0, 0, 0, 0.25, 0.5, 0.5, 1, 1, 1, 1] })}`;
  });
  await page.waitForFunction(() => window.splinelab.current()?.state.knots[6] === 0.5);
  await t.ready();
  r = await recorded(page, mark);
  assert.ok(r.voices.every((v) => v.stops > 0), 'the old plot\'s sound stopped when it was destroyed');
  mark = r.count;
  await btn(curve).click();
  r = await recorded(page, mark);
  assert.equal(r.clicks.length, 2, 'distinct inner knots ¼ and ½ (½ twice)');
  assert.deepEqual(r.voices.map((v) => v.type), ['sine', 'triangle'], 'the tone changes at the C¹ joint');
  assert.equal(+(r.voices[1].start - r.voices[0].start).toFixed(6), 1.5, 'at u = ½');
  await btn(curve).click();

  // the basis plot plays a basis function: pitch from its values 0 … 1
  mark = (await recorded(page)).count;
  await btn(basis).click();
  r = await recorded(page, mark);
  assert.equal(r.clicks.length, 2);
  const hz = r.voices.flatMap((v) => v.freq.map((c) => c[1]));
  assert.ok(Math.min(...hz) < 221 && Math.max(...hz) > 300, `a basis function from 0 (220 Hz) up (${Math.min(...hz).toFixed(0)}–${Math.max(...hz).toFixed(0)} Hz)`);
  await btn(basis).click();

  // knot-modification: order 4, 8 points, knots 0⁴ 1 2 3 4 5⁴, the moving knot u₅ = 2; u₅ on its neighbour 3 → double knot
  await page.evaluate(async () => {
    const { encodeState } = await import('./lib/state.js');
    const { defaults } = await import('./demos/knot-modification.js');
    location.hash = `#knot-modification/${await encodeState({ ...defaults(), up: 3 })}`;
  });
  await page.waitForFunction(() => window.splinelab.current()?.id === 'knot-modification');
  await t.ready();
  mark = (await recorded(page)).count;
  await btn(curve).click();
  r = await recorded(page, mark);
  assert.equal(r.clicks.length, 3, 'u₅ = 2 moved to 3: inner knots 1, 3 (twice), 4 → 3 clicks');
  assert.deepEqual(r.voices.map((v) => v.type), ['sine', 'triangle', 'sine'], 'C¹ at the double knot 3, C² again at 4');
  assert.deepEqual(r.voices.map((v) => +(v.start - r.voices[0].start).toFixed(6)), [0, 1.8, 2.4], 'at u = 3 and 4 of 0 … 5 (3 s)');
  await page.focus(curve);
  await page.keyboard.press(',');
  assert.match(await page.$eval(curve, (c) => c.parentElement.querySelector('[aria-live]').textContent), /^u = 5\.00: \(/, 'comma first goes to the end');

  // quasi-cubic-curves: C² joins at u = 1 … n − 1 for every α: one click each, one sine voice
  const go = async (id, over) => {
    await page.evaluate(async ([d, o]) => {
      const { encodeState } = await import('./lib/state.js');
      const { defaults } = await import(`./demos/${d}.js`);
      location.hash = `#${d}/${await encodeState({ ...defaults(), ...o })}`;
    }, [id, over]);
    await page.waitForFunction((d) => window.splinelab.current()?.id === d, id);
    await t.ready();
  };
  await go('quasi-cubic-curves', {});
  const segs = await page.evaluate(() => { const s = window.splinelab.current().state; return s.closed ? s.points.length : s.points.length - 3; });
  mark = (await recorded(page)).count;
  await btn(curve).click();
  r = await recorded(page, mark);
  assert.equal(r.clicks.length, segs - 1, `quasi-cubic-curves: ${segs} segments → ${segs - 1} clicks`);
  assert.deepEqual(r.voices.map((v) => v.type), ['sine'], 'quasi-cubic-curves: C² throughout');
  // blended-interpolation with k = 2: C¹ joints (the tone turns to a triangle at the first inner joint)
  await go('blended-interpolation', { k: 2 });
  const n = await page.evaluate(() => window.splinelab.current().state.points.length - 3);
  mark = (await recorded(page)).count;
  await btn(curve).click();
  r = await recorded(page, mark);
  assert.equal(r.clicks.length, n - 1, `blended-interpolation: ${n} segments → ${n - 1} clicks`);
  assert.equal(r.voices[0].type, 'sine');
  assert.ok(r.voices.slice(1).length >= 1 && r.voices.slice(1).every((v) => v.type === 'triangle'), `k = 2: triangle after the C¹ joints (${r.voices.map((v) => v.type)})`);
  // interp-approx: Lᵃ is a cubic on the Farin knots (the data knots u₁ … uₙ and the n − 1 midpoints between them),
  // C² at each (curves.md §2.5): with n data points W₁ … Wₙ, 2n − 3 inner knots click and the voice stays a sine
  await go('interp-approx', {});
  const nW = await page.evaluate(() => window.splinelab.current().state.points.length - 4);
  mark = (await recorded(page)).count;
  await btn(curve).click();
  r = await recorded(page, mark);
  assert.equal(r.clicks.length, 2 * nW - 3, `interp-approx: ${nW} data points → ${nW - 2} inner data knots and ${nW - 1} midpoints`);
  assert.deepEqual(r.voices.map((v) => v.type), ['sine'], 'interp-approx: C² throughout');
  t.assertClean();
  await t.close();
  await context.close();
});
