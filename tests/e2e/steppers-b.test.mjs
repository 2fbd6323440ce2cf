// Algorithm steppers of knot modification, curve networks / criss-cross basis and quasi-cubic curves, and the
// typeset (MathML) formulas of the demos noisy-data, b2-surfaces, quasi-cubic-curves, blended-interpolation,
// quasi-cubic-surfaces, curve-networks, criss-cross-basis and knot-modification.
//
// For each stepper: a control named with "Step" exists; Step forward and Back change the drawing (pixel hash of
// the canvas, or of the WebGL view's screenshot) and the formula (its MathML text changes and contains numbers
// of the current view, checked against values computed here from the wasm API or from the paper's formulas);
// the step is in the link and a link restores it.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { startHarness, WWW } from './harness.mjs';

let H, encodeState;
before(async () => {
  H = await startHarness();
  ({ encodeState } = await import(join(WWW, 'lib/state.js')));
});
/** A link to demo `id` with the state `partial` (missing keys take their defaults). */
const link = async (id, partial) => `#${id}/${await encodeState(partial)}`;
after(async () => { await H?.close(); });

const FWD = 'button[aria-label="Step forward"]';
const BACK = 'button[aria-label="Step back"]';

/** The stepper panel's state: its step, the status line and the text of its MathML formulas. */
async function panel(t, root = '.stepper') {
  return t.page.$eval(root, (el) => ({
    step: Number(el.dataset.step),
    steps: Number(el.dataset.steps),
    status: el.querySelector('.stepper-status').textContent,
    math: Array.from(el.querySelectorAll('.stepper-formula math'), (m) => m.textContent).join(' | '),
    tex: Array.from(el.querySelectorAll('.stepper-formula math'), (m) => m.dataset.tex).join(' | '),
    mathCount: el.querySelectorAll('.stepper-formula math').length,
  }));
}

/** Hash of a 2D canvas, or of a screenshot of the element (WebGL views). */
async function drawingHash(t, selector, webgl = false) {
  if (!webgl) return t.canvasHash(selector);
  await t.frames(3);
  // the 3D view's public API: its pixels as a data URL
  const url = await t.page.$eval(selector, (c) => c.splineView.toDataURL());
  const { createHash } = await import('node:crypto');
  return createHash('sha1').update(url).digest('hex');
}

const numbersIn = (s) => (s.replace(/−/g, '-').match(/-?\d+(\.\d+)?(e[-+]?\d+)?/g) || []).map(Number);
const hasNumber = (s, x, tol) => numbersIn(s).some((y) => Math.abs(y - x) <= tol);

/**
 * The common stepper checks: a "Step" control exists; forward changes drawing + formula and puts the step into
 * the link; back undoes; the link restores the step. Returns the page (left at step `upTo`).
 */
async function checkStepper(route, { drawing, webgl = false, upTo = 2, root = '.stepper' }) {
  const t = await H.open(route);
  const names = await t.page.$$eval('button', (bs) => bs.map((b) => b.getAttribute('aria-label') || b.textContent));
  assert.ok(names.some((n) => /Step/.test(n)), 'a control named with "Step"');
  const p0 = await panel(t, root);
  assert.equal(p0.step, -1, 'starts off');
  assert.ok(p0.steps > upTo, `enough steps (${p0.steps})`);
  const d0 = await drawingHash(t, drawing, webgl);
  let prevMath = p0.math, prevDraw = d0;
  for (let i = 0; i <= upTo; i++) {
    await t.page.click(`${root} ${FWD}`);
    await t.frames(3);
    const p = await panel(t, root);
    assert.equal(p.step, i, 'forward moves one step');
    assert.ok(p.mathCount > 0, 'the step shows MathML');
    assert.notEqual(p.math, prevMath, `formula changes at step ${i}`);
    const d = await drawingHash(t, drawing, webgl);
    assert.notEqual(d, prevDraw, `drawing changes at step ${i}`);
    prevMath = p.math; prevDraw = d;
  }
  const st = await t.state();
  assert.equal(st.step, upTo, 'the step is in the demo state');
  const hash = await t.flushState();
  // back
  await t.page.click(`${root} ${BACK}`);
  await t.frames(3);
  const pb = await panel(t, root);
  assert.equal(pb.step, upTo - 1);
  assert.notEqual(pb.math, prevMath, 'back changes the formula');
  assert.notEqual(await drawingHash(t, drawing, webgl), prevDraw, 'back changes the drawing');
  t.assertClean();
  await t.close();
  // the link restores the step
  const t2 = await H.open(hash);
  await t2.frames(3);
  const pr = await panel(t2, root);
  assert.equal(pr.step, upTo, 'restored from the link');
  assert.equal(pr.math, prevMath, 'same formula after restoring');
  return t2;
}

// ---------------------------------------------------------------------------------------------------
test('quasi-cubic curves: the basis assembled piece by piece, then the sum = 1', async () => {
  const t = await checkStepper('#quasi-cubic-curves', { drawing: 'canvas[data-plot="basis"]', upTo: 3 });
  await t.close();
  // α = 0.5, u = 0.3 (segment 0, t = 0.3): values from the paper's formulas (spec: reconstructed eq. (1))
  const a = 0.5, tt = 0.3, th = Math.PI * tt / 2, sg = Math.sin(Math.PI * tt) / (4 * Math.PI);
  const B0 = [(1 - tt) / 4 - sg, 0.5 - tt / 4 + sg, 0.25 + tt / 4 + sg, tt / 4 - sg];
  const B1 = [(1 - Math.sin(th)) ** 2 / 6, (1 + Math.cos(th)) ** 2 / 6, (1 + Math.sin(th)) ** 2 / 6, (1 - Math.cos(th)) ** 2 / 6];
  const B = B0.map((x, j) => (1 - a) * x + a * B1[j]);
  const t3 = await H.open(await link('quasi-cubic-curves', { u: 0.3, step: 1 }));
  await t3.frames(3);
  let p = await panel(t3);
  assert.equal(p.step, 1);
  assert.ok(hasNumber(p.math, B[1], 1e-4), `B_1(0.5; 0.3) = ${B[1]} in "${p.math}"`);
  assert.ok(hasNumber(p.math, B0[1], 1e-4) && hasNumber(p.math, B1[1], 1e-4), 'B⁰_1 and B¹_1 filled in');
  // the last step: the sum, its four terms and the measured max |ΣB − 1|
  for (let i = 0; i < 3; i++) await t3.page.click(FWD);
  await t3.frames(2);
  p = await panel(t3);
  assert.equal(p.step, 4);
  for (const x of B) assert.ok(hasNumber(p.math, x, 1e-4), `term ${x} in the sum`);
  assert.ok(hasNumber(p.math, 1, 1e-12), 'sum = 1');
  const worst = numbersIn(p.math.split('|').pop()).pop();
  assert.ok(worst < 1e-14, `max |ΣB − 1| = ${worst}`);
  await t3.screenshot('steppers-b-quasi-cubic-sum');
  t3.assertClean();
  await t3.close();
});

// ---------------------------------------------------------------------------------------------------
test('knot modification: the de Boor triangle with the moved knot, point by point', async () => {
  const t = await checkStepper('#knot-modification', { drawing: 'canvas[data-plot="curve"]', upTo: 2 });
  await t.close();
  // defaults: order 4, u_5 = 2.4, first tracked point u = 1 + 2·0.5/3; the span is 4 (u < u_5): d_2^1 has
  // α = (u − u_2)/(u_5 − u_2) = u/2.4 (the moved knot), d_3^1 α = (u − u_3)/(u_6 − u_3) = u/3 (not moved)
  const u = 1 + 2 * 0.5 / 3;
  const P = [[0, 0], [1, 2.4], [2.2, 2.8], [3.2, 0.6], [4.4, 0.2], [5.4, 2.6], [6.6, 2.4], [7.4, 0.4]];
  const t2 = await H.open(await link('knot-modification', { step: 0 }));
  await t2.frames(3);
  let p = await panel(t2);
  assert.equal(p.step, 0);
  const a21 = u / 2.4;
  assert.ok(hasNumber(p.math, a21, 1e-4), `α = ${a21} in "${p.math}"`);
  assert.ok(/\\mathbf\{2\.4\}/.test(p.tex), `the moved knot value is filled in (bold): "${p.tex}"`);
  const d21 = [(1 - a21) * P[1][0] + a21 * P[2][0], (1 - a21) * P[1][1] + a21 * P[2][1]];
  assert.ok(hasNumber(p.math, d21[0], 1e-3) && hasNumber(p.math, d21[1], 1e-3), `d_2^1 = ${d21}`);
  assert.match(p.status, /moves with u/);
  await t2.page.click(FWD);
  await t2.frames(2);
  p = await panel(t2);
  assert.ok(hasNumber(p.math, u / 3, 1e-4), `α_3^1 = u/3 in "${p.math}"`);
  assert.match(p.status, /does not depend on u/);
  // the last step is the curve point itself: equal to the tracked point of the readout table
  for (let i = 0; i < 4; i++) await t2.page.click(FWD);
  await t2.frames(2);
  p = await panel(t2);
  assert.equal(p.step, 5, 'order 4: 3 + 2 + 1 points');
  const row = await t2.page.$$eval('table tbody tr', (rs) => Array.from(rs[0].cells, (c) => Number(c.textContent.replace('−', '-'))));
  assert.ok(hasNumber(p.math, row[1], 2e-3) && hasNumber(p.math, row[2], 2e-3), `the last point = the tracked point ${row}`);
  await t2.screenshot('steppers-b-knot-modification');
  t2.assertClean();
  await t2.close();
});

// ---------------------------------------------------------------------------------------------------
test('curve networks: the Boolean sum L1, L2, L12, then G = L1 + L2 − L12', async () => {
  const t = await checkStepper('#curve-networks', { drawing: 'canvas[data-plot="networks"]', webgl: true, upTo: 2 });
  await t.page.click(FWD);
  await t.frames(3);
  const p = await panel(t);
  assert.equal(p.step, 3);
  // the z-values at the probe, read from the formula: L1 + L2 − L12 = G (the core's G, to rounding)
  const zLine = p.tex.split(' | ').find((l) => l.startsWith('G_z'));
  assert.ok(zLine, `a line with G_z in "${p.tex}"`);
  const nums = numbersIn(zLine.replace(/\([^)]*\)/, '').replace(/\((-?[\d.]+)\)/g, '$1'));
  const [a, b, c, g] = nums.slice(-4);
  assert.ok(Math.abs(a + b - c - g) < 2e-4, `${a} + ${b} − ${c} = ${g}`);
  await t.screenshot('steppers-b-curve-networks');
  t.assertClean();
  await t.close();
});

test('curve networks: S assembled from C_ij B_ij row by row equals the core\'s S', async () => {
  // the paper's network (m = n = 3): G at step 3, then rows i = 0 … 4 of S = Σ C_ij B_ij
  const t = await H.open(await link('curve-networks', { step: 4 }));
  await t.frames(3);
  let p = await panel(t);
  assert.equal(p.step, 4);
  assert.equal(p.steps, 4 + 5, 'four Boolean-sum steps and m + 2 = 5 rows');
  const d0 = await drawingHash(t, 'canvas[data-plot="networks"]', true);
  const m0 = p.math;
  await t.page.click(FWD);
  await t.frames(3);
  p = await panel(t);
  assert.notEqual(p.math, m0);
  assert.notEqual(await drawingHash(t, 'canvas[data-plot="networks"]', true), d0, 'the partial sum grows');
  for (let i = 0; i < 3; i++) await t.page.click(FWD);
  await t.frames(3);
  p = await panel(t);
  assert.equal(p.step, 8, 'the last row');
  const lines = p.tex.split(' | ');
  const dev = numbersIn(lines.at(-1)).at(-1);
  assert.ok(/\\max/.test(lines.at(-1)) && dev < 1e-12, `‖Σ C_ij B_ij − S‖ = ${dev}`);
  const unity = lines.find((l) => /B_\{i'j\}/.test(l));
  assert.ok(hasNumber(unity.split('=').at(-1), 1, 1e-9), `Σ B_ij = 1 at the probe: ${unity}`);
  await t.screenshot('steppers-b-curve-networks-S');
  t.assertClean();
  await t.close();
});

// ---------------------------------------------------------------------------------------------------
const MATH_DEMOS = ['noisy-data', 'b2-surfaces', 'quasi-cubic-curves', 'blended-interpolation', 'quasi-cubic-surfaces', 'curve-networks', 'criss-cross-basis', 'knot-modification'];

test('explanations typeset their formulas as MathML: no plain-text formula block, no unknown TeX command', async () => {
  for (const id of MATH_DEMOS) {
    const t = await H.open(`#${id}`);
    const r = await t.page.$eval('.demo-explain', (el) => {
      const maths = Array.from(el.querySelectorAll('math'));
      const outside = (s) => s.replace(/\s+/g, ' ');
      // text of the explanation outside the <math> elements
      const walker = document.createTreeWalker(el, NodeFilter.SHOW_TEXT);
      let plain = '';
      for (let n = walker.nextNode(); n; n = walker.nextNode()) if (!n.parentElement.closest('math')) plain += n.textContent + ' ';
      return {
        math: maths.length,
        block: el.querySelectorAll('.formula math[display="block"]').length,
        pre: el.querySelectorAll('pre.formula').length,
        unknown: maths.flatMap((m) => Array.from(m.querySelectorAll('mtext'), (x) => x.textContent)).filter((s) => s.startsWith('\\')),
        rawTex: (outside(plain).match(/\\[a-zA-Z]+|[A-Za-z]_\{[^}]*\}|\^\{[^}]*\}/g) || []),
      };
    });
    assert.equal(r.pre, 0, `${id}: no pre.formula`);
    assert.ok(r.block >= 3, `${id}: a typeset formula block (${r.block} display formulas)`);
    assert.ok(r.math >= r.block, `${id}: <math> elements`);
    assert.deepEqual(r.unknown, [], `${id}: every TeX command is known to mathml.js`);
    assert.deepEqual(r.rawTex, [], `${id}: no TeX left in the plain text`);
    t.assertClean();
    await t.close();
  }
});

test('papers page and guide: formulas are MathML (no unknown TeX command, no $ left over)', async () => {
  const t = await H.open('papers.html');
  const r = await t.page.evaluate(() => {
    const all = Array.from(document.querySelectorAll('#corrections math, figure math'));
    const text = document.body.innerText;
    return {
      corrections: Array.from(document.querySelectorAll('article.correction')).filter((a) => a.querySelector('math')).length,
      unknown: all.flatMap((m) => Array.from(m.querySelectorAll('mtext'), (x) => x.textContent)).filter((s) => s.startsWith('\\')),
      dollars: (text.match(/\$/g) || []).length,
      lmix: Array.from(document.querySelectorAll('#correction-000-bspline math'), (m) => m.textContent).join(' '),
    };
  });
  assert.ok(r.corrections >= 12, `corrections with typeset formulas: ${r.corrections}`);
  assert.deepEqual(r.unknown, []);
  assert.equal(r.dollars, 0, 'no TeX delimiters left in the text');
  assert.match(r.lmix, /La=6aLB\+\(1−6a\)L/, 'L^a = 6a·L^B + (1 − 6a)·L typeset');
  t.assertClean();
  await t.close();
  const g = await H.open('guide.html', { ready: false });
  await g.page.waitForLoadState('load');
  assert.ok(await g.page.$$eval('#steps-formulas ~ p math, #steps-formulas + p math', (m) => m.length) >= 5, 'the guide typesets its formulas');
  await g.close();
});

test('a stepper mid-way passes axe (serious/critical) in each demo', async () => {
  for (const [id, step] of [['knot-modification', 3], ['curve-networks', 5], ['quasi-cubic-curves', 4]]) {
    const t = await H.open(await link(id, { step }));
    await t.frames(3);
    assert.equal((await panel(t)).step, step);
    assert.deepEqual(await t.axe(), [], `${id}: no serious/critical axe violation`);
    t.assertClean();
    await t.close();
  }
});
