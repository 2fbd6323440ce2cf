// Algorithm steppers of B-spline basics (de Boor at u, Boehm's knot insertion), interpolating vs approximating
// (the B2 construction, and eq. (5) as printed) and Bézier remodelling (remodelling one segment, de Casteljau),
// plus the two shared modules they use (www/lib/stepper.js, www/lib/mathml.js) and the MathML explanations.
// For each stepper: Step forward and Back change the drawing (canvas pixel hash) and the typeset formula (MathML
// text with numbers), Back returns to the same drawing, the step index is in the link and restores from it, Play
// advances, and a control whose accessible name contains "Step" exists. Numbers in the formulas are checked
// against values computed by hand.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

const CURVE = 'canvas[data-plot="curve"]';
const FWD = 'button[aria-label="Step forward"]';
const BACK = 'button[aria-label="Step back"]';
const PLAY = 'button[aria-label="Play steps"]';

/** The stepper's state: index, count, status text, formula text and MathML element count. */
const panel = (t) => t.page.$eval('section.stepper', (s) => ({
  step: Number(s.dataset.step), steps: Number(s.dataset.steps),
  status: s.querySelector('.stepper-status').textContent,
  formula: s.querySelector('.stepper-formula').textContent.replace(/\s+/g, ''),
  maths: s.querySelectorAll('.stepper-formula math').length,
}));

async function click(t, sel) { await t.page.click(sel); await t.frames(2); }

/**
 * Walks a stepper: off → step 0 → step 1 → back to 0. Returns what it saw. `choose` clicks an algorithm first.
 */
async function walk(route, choose) {
  const t = await H.open(route);
  if (choose) { await t.page.click(`label:has-text("${choose}")`); await t.frames(2); }
  // a control whose accessible name contains "Step"
  assert.ok(await t.page.getByRole('button', { name: /Step/ }).count() >= 2, 'buttons named "Step …"');
  const off = { hash: await t.canvasHash(CURVE), panel: await panel(t) };
  assert.equal(off.panel.step, -1);
  assert.ok(off.panel.steps >= 3, `${off.panel.steps} steps`);
  assert.equal(off.panel.maths, 0);
  await click(t, FWD);
  const s0 = { hash: await t.canvasHash(CURVE), panel: await panel(t) };
  await click(t, FWD);
  const s1 = { hash: await t.canvasHash(CURVE), panel: await panel(t) };
  assert.equal(s0.panel.step, 0); assert.equal(s1.panel.step, 1);
  assert.notEqual(s0.hash, off.hash, 'step 0 changes the drawing');
  assert.notEqual(s1.hash, s0.hash, 'step 1 changes the drawing');
  assert.ok(s0.panel.maths > 0 && s1.panel.maths > 0, 'formulas are MathML');
  assert.notEqual(s1.panel.formula, s0.panel.formula, 'the formula changes');
  assert.match(s1.panel.formula, /\d\.\d/, 'numbers in the formula');
  assert.match(s1.panel.status, /^Step 2 of \d+: /);
  // accessible with a step shown (MathML, the live status, the buttons): no serious axe violation
  const v = await t.axe();
  assert.deepEqual(v, [], JSON.stringify(v));
  await click(t, BACK);
  const b0 = { hash: await t.canvasHash(CURVE), panel: await panel(t) };
  assert.equal(b0.panel.step, 0);
  assert.equal(b0.hash, s0.hash, 'Back gives the drawing of step 0 again');
  assert.equal(b0.panel.formula, s0.panel.formula);
  return { t, off, s0, s1 };
}

/** The step is in the link: reopen the URL and find the same step, formula and drawing. */
async function roundTrip(t, key = 'step') {
  await click(t, FWD);
  const seen = await panel(t);
  const drawn = await t.canvasHash(CURVE);
  await t.flushState();
  const st = await t.state();
  assert.equal(st[key], seen.step, 'the step index is in the state');
  const url = t.page.url();
  assert.match(url, /#[a-z-]+\/v\d\./);
  const t2 = await H.open(url.slice(url.indexOf('#')));
  const again = await panel(t2);
  assert.equal(again.step, seen.step, 'restored from the link');
  assert.equal(again.formula, seen.formula);
  assert.equal(await t2.canvasHash(CURVE), drawn, 'same drawing after reload');
  t2.assertClean();
  await t2.close();
}

/** Play advances (one step every 1.4 s) and ends paused at the last step or still running. */
async function plays(t) {
  await click(t, 'button[aria-label="Leave the steps"]');
  assert.equal((await panel(t)).step, -1);
  await t.page.click(PLAY);
  await t.page.waitForFunction(() => Number(document.querySelector('section.stepper').dataset.step) >= 1, null, { timeout: 8000 });
  assert.equal(await t.page.$eval(PLAY, (b) => b.getAttribute('aria-pressed')), 'true');
  await t.page.click(PLAY); // pause
  assert.equal(await t.page.$eval(PLAY, (b) => b.getAttribute('aria-pressed')), 'false');
}

test('B-spline basics: de Boor at u, level by level, with the numbers of the curve', async () => {
  const { t, s0, s1 } = await walk('#bspline-basics');
  // default curve, u = 0.4: span k = 4, level 0 = P1…P4; level 1: α₂,₁ = 0.4/0.5 = 0.8, P¹₂ = 0.2·P1 + 0.8·P2 = (2.12, 2.52)
  assert.match(s0.panel.formula, /k=4/);
  assert.match(s1.panel.formula, /=0\.8/);
  assert.match(s1.panel.formula, /\(2\.12,2\.52\)/);
  // α₄,₁ = (0.4 − 0.25)/(1 − 0.25) = 0.2, P¹₄ = 0.8·P3 + 0.2·P4 = (3.64, 0.52)
  assert.match(s1.panel.formula, /\(3\.64,0\.52\)/);
  await roundTrip(t);
  // the last level is the curve point (the readout under the slider shows the same C(u))
  while (!(await t.page.$eval(FWD, (b) => b.disabled))) await click(t, FWD);
  const last = await panel(t);
  assert.equal(last.step, last.steps - 1);
  assert.match(last.formula, /C\(0\.4\)=P43=\(2\.995,1\.43\)/);
  await plays(t);
  t.assertClean();
  await t.close();
});

test('B-spline basics: inserting the knot u (Boehm) replaces p − 1 points by p new ones', async () => {
  const { t, s1 } = await walk('#bspline-basics', 'Insert knot u');
  assert.equal((await t.state()).stepAlgo, 'insert');
  // Q₂ = 0.2·P1 + 0.8·P2 = (2.12, 2.52) with α₂ = 0.8: the same numbers as de Boor's first level
  assert.match(s1.panel.formula, /α2=0\.4−00\.5−0=0\.8/);
  assert.match(s1.panel.formula, /Q2=0\.2P1\+0\.8P2=\(2\.12,2\.52\)/);
  await roundTrip(t);
  while (!(await t.page.$eval(FWD, (b) => b.disabled))) await click(t, FWD);
  assert.match((await panel(t)).formula, /8points,12knots/);
  await plays(t);
  t.assertClean();
  await t.close();
});

test('Interpolating vs approximating: the B2 construction stage by stage', async () => {
  const { t, s0, s1 } = await walk('#interp-approx');
  assert.match(s0.panel.status, /data/);
  assert.match(s1.panel.status, /auxiliary/);
  // step 3 (joints, a = 0): R₁ = 0·W₀ + 1·W₁ + 0·W₂ = W₁ = (0.6, 1.6)   (Back left the stepper at step 1)
  await click(t, FWD); await click(t, FWD);
  const joints = await panel(t);
  assert.match(joints.status, /joints/);
  assert.match(joints.formula, /R1=0W0\+1W1\+0W2/);
  assert.match(joints.formula, /R1=\(0\.6,1\.6\)/);
  // step 4 (even vertices): the four weights sum to 1 (read from the formula)
  await click(t, FWD);
  const even = await panel(t);
  const m = /C2=(.*?)W0(.*?)W1(.*?)W2(.*?)W3/.exec(even.formula.replace(/−/g, '-'));
  assert.ok(m, even.formula);
  const ws = m.slice(1, 5).map((x) => Number(x.replace(/^\+/, '')));
  assert.ok(Math.abs(ws.reduce((a, b) => a + b, 0) - 1) < 2e-4, `weights ${ws}`);
  await roundTrip(t);
  await plays(t);
  t.assertClean();
  await t.close();
});

test('Interpolating vs approximating: eq. (5) as printed, live next to the corrected one', async () => {
  const t = await H.open('#interp-approx');
  const out = () => t.page.$eval('[data-readout="eq5"] output', (o) => o.textContent);
  // chord-length knots on uneven data: the printed weights miss the data, the corrected ones do not
  assert.match(await out(), /misses W\S+ by \d\.\d+ \(its weights sum to 0\.\d+\); corrected: 0$/);
  const before = await t.canvasHash(CURVE);
  await t.page.click('label:has-text("Also draw eq. (5) as printed")');
  await t.frames(2);
  assert.notEqual(await t.canvasHash(CURVE), before, 'the printed curve is drawn');
  assert.ok(await t.page.$('a[href*="correction-000-eq5"]'), 'links the correction entry');
  // uniform knots (section 3): b = c at every joint, the printed weight is right there
  await t.page.click('label:has-text("uniform (§3)")');
  await t.frames(2);
  assert.match(await out(), /weights sum to 1 here/);
  t.assertClean();
  await t.close();
});

test('Bézier remodelling: one segment remodelled, point by point (eq. 6)', async () => {
  const { t, s0, s1 } = await walk('#bezier-remodel');
  // stepU = 1.375 lies in segment I = 1 = [1, 7/4] of the paper's example (b2, b3, b4)
  assert.match(s0.panel.formula, /\[1,1\.75\]/);
  // Fig. 1: α₁⁽¹⁾ = 1 − α₂⁽⁰⁾ = 0.95, b*₄ = 0.05·b2 + 0.95·b3 = 0.05·(3, 9) + 0.95·(0, 0) = (0.15, 0.45)
  assert.match(s1.panel.formula, /b4∗=0\.05b2\+0\.95b3=\(0\.15,0\.45\)/);
  await roundTrip(t);
  await plays(t);
  t.assertClean();
  await t.close();
});

test('Bézier remodelling: de Casteljau on g* at u', async () => {
  const { t, s0, s1 } = await walk('#bezier-remodel', 'de Casteljau');
  // t = (1.375 − 1)/(1.75 − 1) = 0.5
  assert.match(s0.panel.formula, /t=u−u1u2−u1=1\.375−11\.75−1=0\.5/);
  assert.match(s1.panel.formula, /0\.5bk0\+0\.5bk\+10/);
  // level 1, b¹₀ = (b*₃ + b*₄)/2 = ((0, 0) + (0.15, 0.45))/2 = (0.075, 0.225): b*₃ = b₂·… no: b*₃ = b₂ = (3, 9)
  // (the breakpoint b*_{3I} = b_{2I} = b2 = (3, 9)), so b¹₀ = ((3, 9) + (0.15, 0.45))/2 = (1.575, 4.725)
  assert.match(s1.panel.formula, /b01=\(1\.575,4\.725\)/);
  await roundTrip(t);
  await plays(t);
  t.assertClean();
  await t.close();
});

test('the three explanations typeset their formulas as MathML (no plain-text block)', async () => {
  for (const id of ['bspline-basics', 'interp-approx', 'bezier-remodel']) {
    const t = await H.open(`#${id}`);
    const n = await t.page.$$eval('.demo-explain .formula-math math', (m) => m.length);
    assert.ok(n >= 4, `${id}: ${n} formulas`);
    assert.equal(await t.page.$$eval('.demo-explain pre.formula', (p) => p.length), 0, `${id}: no plain-text formula`);
    assert.ok(await t.page.$eval('.demo-explain .formula-math', (d) => d.querySelector('mfrac, msubsup, msub') !== null));
    t.assertClean();
    await t.close();
  }
});

test('mathml.js: the TeX subset becomes the right MathML, and its plain-text fallback', async () => {
  const t = await H.open('');
  const r = await t.page.evaluate(async () => {
    const m = await import('./lib/mathml.js');
    const tags = (tex) => { const e = m.math(tex); return Array.from(e.querySelectorAll('*'), (x) => x.localName + (x.childElementCount ? '' : `:${x.textContent}`)).join(' '); };
    return {
      sub: tags('x_i^2'), frac: tags('\\frac{a}{b}'), greek: tags('\\alpha'), uni: tags('α'), star: tags('b^*'), times: tags('a*b'),
      num: tags('1e-12 + 0.25'), minus: tags('-1'), text: tags('\\text{if } x'), nested: tags('P^{r-1}_{i}'),
      ns: m.math('x').namespaceURI, display: m.math('x', { display: true }).getAttribute('display'),
      block: (() => { const b = m.formulaBlock(['a', 'b']); return [b.className, b.getAttribute('role'), b.querySelectorAll('math').length]; })(),
      texts: ['u_{p-1} \\le u_p', 'a \\quad b', '\\|x\\|', '\\{a\\}', 'P^{1}_{2}', 'b^{*}_{4}', '\\alpha_{i,r}', '\\frac{1}{2}'].map(m.mathText),
    };
  });
  assert.equal(r.ns, 'http://www.w3.org/1998/Math/MathML');
  assert.equal(r.display, 'block');
  assert.equal(r.sub, 'msubsup mi:x mi:i mn:2');
  assert.equal(r.frac, 'mfrac mi:a mi:b');
  assert.equal(r.greek, 'mi:α');
  assert.equal(r.uni, 'mi:α', 'a Greek letter typed directly is an identifier, not an operator');
  assert.equal(r.star, 'msup mi:b mo:∗');
  assert.equal(r.times, 'mrow mi:a mo:· mi:b');
  assert.equal(r.num, 'mrow mn:1e-12 mo:+ mn:0.25');
  assert.equal(r.minus, 'mrow mo:− mn:1');
  assert.equal(r.text, 'mrow mtext:if  mi:x');
  assert.equal(r.nested, 'msubsup mi:P mi:i mrow mi:r mo:− mn:1', 'base, subscript, superscript');
  assert.deepEqual(r.block, ['formula formula-math', 'group', 2]);
  assert.deepEqual(r.texts, ['uₚ₋₁ ≤ uₚ', 'a b', '‖x‖', '{a}', 'P¹₂', 'b*₄', 'αᵢ,ᵣ', '(1)/(2)']);
  t.assertClean();
  await t.close();
});

test('stepper.js: Back/Step/Play/Leave drive the index through get/set, clamp, and Play stops at the end', async () => {
  const t = await H.open('');
  const r = await t.page.evaluate(async () => {
    const { stepper } = await import('./lib/stepper.js');
    let idx = -1, sets = 0, n = 3;
    const st = stepper({ title: 'Test', interval: 30, steps: () => Array.from({ length: n }, (_, k) => ({ label: `s${k}`, tex: `x_${k} = ${k}.5`, note: `n${k}` })), get: () => idx, set(i) { idx = i; sets++; } });
    document.body.append(st.el);
    const q = (s) => st.el.querySelector(s);
    const out = { start: [idx, q('.step-back').disabled, q('.step-forward').disabled, q('.stepper-status').textContent] };
    q('.step-forward').click(); q('.step-forward').click();
    out.two = [idx, st.el.dataset.step, q('.stepper-status').textContent, q('.stepper-formula').textContent, q('.stepper-note').textContent];
    q('.step-back').click();
    out.back = idx;
    q('.step-forward').click(); q('.step-forward').click(); q('.step-forward').click();
    out.end = [idx, q('.step-forward').disabled];
    q('.step-leave').click();
    out.leave = [idx, q('.stepper-formula').childElementCount];
    q('.step-play').click();
    await new Promise((ok) => setTimeout(ok, 300));
    out.play = [idx, q('.step-play').getAttribute('aria-pressed')];
    n = 2; st.refresh();                       // fewer steps: the index is clamped
    out.clamp = idx;
    st.setTitle('Renamed');
    out.title = [q('.stepper-title').textContent, st.el.getAttribute('aria-label')];
    n = 0; st.refresh();                       // nothing computed: the index is kept, nothing shown
    out.empty = [idx, st.el.dataset.step, q('.stepper-status').textContent];
    n = 2; st.refresh();
    const before = sets; st.refresh(); st.refresh();
    out.quiet = sets - before;                 // refresh does not call set when nothing changed
    st.destroy();
    return out;
  });
  assert.deepEqual(r.start, [-1, true, false, '3 steps. Press Step to start.']);
  assert.deepEqual(r.two, [1, '1', 'Step 2 of 3: s1', 'x1=1.5', 'n1']);
  assert.equal(r.back, 0);
  assert.deepEqual(r.end, [2, true]);
  assert.deepEqual(r.leave, [-1, 0]);
  assert.deepEqual(r.play, [2, 'false'], 'Play ran to the last step and stopped');
  assert.equal(r.clamp, 1);
  assert.deepEqual(r.empty, [1, '-1', 'No steps for this view.'], 'an empty list keeps the demo’s index (a restored link)');
  assert.deepEqual(r.title, ['Renamed', 'Renamed (stepper)']);
  assert.equal(r.quiet, 0);
  t.assertClean();
  await t.close();
});
