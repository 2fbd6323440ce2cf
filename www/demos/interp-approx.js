// Demo "Interpolating vs approximating" (Kuklišová): one slider a moves the B2-spline curve from
// interpolation (a = 0) to the cubic B-spline (a = 1/6), with tension p, modified knots K, automatic tension
// and the paper's figures as presets. All spline values come from the wasm API (b2Curve, b2Fit, b2Basis);
// the modules in interp-approx/ draw and react:
//   presets.js  the data and the paper's figures   state-rules.js  what a link may hold   compute.js  every wasm call
//   curve-draw.js  the curve plot (pure)   side-plots.js  basis and curvature (pure)   steps.js  the stepper
//   explain.js  the explanation. This entry holds the demo contract (www/demos/README.md): meta, the declared
// state, mount (plots, controls, point editing), snippet.
// A stepper walks through the construction (data → auxiliary points →
// joints → even vertices → cubic control polygon → curve) with the weights of each stage from b2Curve, and a
// toggle draws the curve with eq. (5)'s last weight as printed next to the corrected one.

import { mathText } from '../lib/mathml.js';
import { t, tn } from '../lib/i18n.js';
import { h, demoLayout, explanation, legend, setLegendItems } from '../lib/dom.js';
import { cite, correctionLink } from '../lib/papers-ref.js';
import { createPlot, PALETTE, restoreView, curveSection, evenParams, paramRange } from '../lib/plot2d.js';
import { slider, toggle, buttonGroup, button, group, row, readout } from '../lib/controls.js';
import { uPlayer } from '../lib/player.js';
import { pointEditing } from '../lib/point-edit.js';
import { stepper } from '../lib/stepper.js';
import { code, raw, snippetCode } from '../lib/snippet.js';
import { dataImport } from '../lib/data-import.js';
import { MAX_POINTS, SHAPE, PRESETS } from './interp-approx/presets.js';
import { sub, sanitize } from './interp-approx/state-rules.js';
import { compute, computeAtU, curveAt } from './interp-approx/compute.js';
import { describeCurve, drawCurve, drawCurveOver, curveLegendItems } from './interp-approx/curve-draw.js';
import { describeBasis, drawBasis, drawKappa, basisView, kappaView } from './interp-approx/side-plots.js';
import { curveTrace } from './interp-approx/sound.js';
import { buildSteps } from './interp-approx/steps.js';
import { readoutTexts } from './interp-approx/readouts.js';
import { explanationContent } from './interp-approx/explain.js';

export const meta = {
  id: 'interp-approx',
  title: 'Interpolating vs approximating',
  summary: 'One slider from interpolation (a = 0) to the cubic B-spline (a = 1/6), with tension and modified knots.',
  paper: cite('000', '§3–5'),
};

export function defaults() {
  return {
    points: SHAPE.map((q) => [...q]),
    autoEnds: false,
    a: 0,
    p: 1 / 6,
    K: 20,
    useK: false,
    knots: 'chord',
    construction: 'nonuniform',
    autoTension: 'off',
    autoScale: 0.2,
    c2: 1,
    showB: true,
    showInterp: true,
    showBuild: false,
    showComb: false,
    family: null,
    preset: '',
    u: 0,
    step: -1,          // the construction stepper (-1 = off)
    eq5Printed: false, // also draw the curve with eq. (5)'s last weight as printed
    view: [],
  };
}

/** @param {HTMLElement} root @param {import('../lib/host.js').DemoContext} ctx @returns {import('../lib/host.js').MountedDemo} */
export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);

  const sanitizeState = () => sanitize(state, defaults());

  let steps = null; // the construction stepper (built with the controls below)

  // ---------- computed data (all from wasm: interp-approx/compute.js) ----------
  const c = { main: null, bspl: null, interp: null, basis: null, family: [], claim: null, build: null, printed: null, atU: null };

  function recompute() {
    compute(wasm, state, notify, c);
    computeAtU(wasm, state, c);
    refreshReadouts();
    refreshLegend();
    steps?.refresh();
    curvePlot.redraw();
    basisPlot.redraw();
    kappaPlot.redraw();
  }

  // ---------- the curve plot ----------
  const curvePlot = createPlot(L.plots, {
    ariaLabel: 'B2-spline curve with draggable data points',
    equal: true, height: 440, locked: options.locked,
    view: { xmin: -1, xmax: 9, ymin: -1, ymax: 3.5 },
    describe: () => describeCurve(state, c, wasm),
    table: () => { const r = paramRange(c.main); return r ? [curveSection('The B2-spline at 11 values of u', curveAt(wasm, state, evenParams(...r)))] : []; },
    onView(v) { state.view = [v.xmin, v.xmax, v.ymin, v.ymax]; ctx.save(); },
    sound: () => curveTrace(wasm, state, c, curveAt), // ♪ (interp-approx/sound.js)
    draw(g, plot) { drawCurve(plot, state, c); },
    drawOver(g, plot) { drawCurveOver(plot, state, c, player.playing); },
  });
  curvePlot.canvas.dataset.plot = 'curve';
  const m = () => state.points.length;
  const dataHandles = curvePlot.addHandles({
    name: 'data point',
    points: () => state.points.slice(2, -2),
    label: (i) => `W${sub(i + 1)}`,
    labelOf: (i) => t('Data point {name}', { name: mathText(`W_{${i + 1}}`) }),
    radius: 7,
    move(i, q) { state.points[i + 2] = [q[0], q[1]]; state.preset = ''; recompute(); },
    end() { ctx.save(); },
  });
  const auxIdx = () => [0, 1, m() - 2, m() - 1];
  const auxHandles = curvePlot.addHandles({
    name: 'auxiliary point',
    points: () => auxIdx().map((i) => state.points[i]),
    label: (k) => `W${sub(auxIdx()[k] - 1)}`,
    labelOf: (k) => t('Auxiliary end point {name}', { name: mathText(`W_{${auxIdx()[k] - 1}}`) }),
    color: PALETTE.muted, shape: 'square', radius: 6,
    move(k, q) { state.points[auxIdx()[k]] = [q[0], q[1]]; state.preset = ''; recompute(); },
    end() { ctx.save(); },
  });

  // the legend follows the drawing: the same colours and dash patterns as the polylines above
  const legendEl = legend([]);
  legendEl.dataset.legendFor = 'curve';
  const refreshLegend = () => setLegendItems(legendEl, curveLegendItems(state, c));
  L.plots.appendChild(legendEl);

  // ---------- basis functions ----------
  const basisPlot = createPlot(L.plots, {
    ariaLabel: 'The B2-spline blending functions Lⱼ(u) for the current options',
    height: 220, pan: false, zoom: false, xLabel: 'u',
    view: { xmin: 0, xmax: 1, ymin: -0.3, ymax: 1.15 },
    describe: () => describeBasis(c),
    draw(g, plot) { drawBasis(plot, c); },
  });
  basisPlot.canvas.dataset.plot = 'basis';

  // ---------- curvature ----------
  const kappaPlot = createPlot(L.plots, {
    ariaLabel: 'Signed curvature of the curve along its parameter',
    height: 170, pan: false, zoom: false, xLabel: 'u', yLabel: 'κ',
    view: { xmin: 0, xmax: 1, ymin: -1, ymax: 1 },
    describe: () => t('Signed curvature κ(u) of the current curve.'),
    draw(g, plot) { drawKappa(plot, c); },
  });
  kappaPlot.canvas.dataset.plot = 'curvature';

  function fitSidePlots() {
    const b = basisView(c), k = kappaView(c);
    if (b) basisPlot.setView(b);
    if (k) kappaPlot.setView(k);
  }

  // ---------- controls ----------
  const aCtl = slider({
    label: 'Approximation a', name: 'a', min: -0.1, max: 0.25, step: 0.001, value: state.a, number: true,
    ticks: [{ value: 0, label: t('0 interpolates') }, { value: 1 / 6, label: t('1/6 B-spline') }],
    hint: 'Lᵃ = 6a·Lᴮ + (1 − 6a)·L: a = 0 passes through the data, a = 1/6 is the cubic B-spline.',
    onInput(v) { state.a = v; recompute(); fitSidePlots(); },
    onChange() { ctx.save(); },
  });
  const pCtl = slider({
    label: 'Tension p', name: 'p', min: 0, max: 0.5, step: 0.001, value: state.p, number: true,
    ticks: [{ value: 1 / 12, label: '1/12' }, { value: 1 / 6, label: '1/6' }],
    hint: 'p = 1/6 is eq. (8); p = 0 puts the even vertices at the midpoints.',
    onInput(v) { state.p = v; recompute(); fitSidePlots(); },
    onChange() { ctx.save(); },
  });
  const kToggle = toggle({ label: 'Modified knots (K)', value: state.useK, onChange(v) { state.useK = v; kCtl.setDisabled(!v); recompute(); fitSidePlots(); ctx.save(); } });
  const kCtl = slider({
    label: 'K', name: 'K', min: 0, max: 100, step: 0.5, value: state.K, number: true,
    hint: 'u′₂ᵢ = (uᵢ₋₁ + K·uᵢ + uᵢ₊₁)/(K + 2); the paper suggests K = 20.',
    onInput(v) { state.K = v; if (state.useK) { recompute(); fitSidePlots(); } },
    onChange() { ctx.save(); },
  });
  const knotCtl = buttonGroup({
    label: 'Knots', options: [{ value: 'chord', label: 'chord length' }, { value: 'uniform', label: 'uniform' }], value: state.knots,
    onChange(v) { state.knots = v; if (v === 'chord' && state.construction === 'section3') state.construction = 'nonuniform'; refreshControls(); recompute(); fitSidePlots(); ctx.save(); },
  });
  const consCtl = buttonGroup({
    label: 'Construction', options: [{ value: 'nonuniform', label: 'non-uniform (§4–5)' }, { value: 'section3', label: 'uniform (§3)' }], value: state.construction,
    onChange(v) { state.construction = v; if (v === 'section3') { state.knots = 'uniform'; state.autoTension = 'off'; } refreshControls(); recompute(); fitSidePlots(); ctx.save(); },
  });
  const autoCtl = buttonGroup({
    label: 'Automatic tension', options: [{ value: 'off', label: 'off' }, { value: 'paper', label: 'paper' }, { value: 'turning', label: 'turning*' }], value: state.autoTension,
    onChange(v) { state.autoTension = v; if (v !== 'off' && state.construction === 'section3') { state.construction = 'nonuniform'; } refreshControls(); recompute(); fitSidePlots(); ctx.save(); },
  });
  const autoScaleCtl = slider({
    label: 'Automatic tension scale p', name: 'autoScale', min: 0, max: 0.5, step: 0.005, value: state.autoScale,
    hint: '"paper": pᵢ = p·|cos αᵢ + cos αᵢ₊₁|/2 (αᵢ interior angle). *"turning" (not in the paper): p·|sin θᵢ + sin θᵢ₊₁|/2 with signed turning angles θ — it meets the paper\'s four stated wishes, which the printed formula does not.',
    onInput(v) { state.autoScale = v; recompute(); },
    onChange() { ctx.save(); },
  });
  const c2Ctl = toggle({
    label: 'c2 = 2 (derived denominator)', value: state.c2 === 2,
    hint: 'p±ᵢ = 6pᵢΔᵢ²/(Δᵢ² + 5ΔᵢΔᵢ±₁ + c2·Δᵢ±₁²). c2 = 1 is eq. (8)/(9) as printed (default); c2 = 2 is what the paper\'s own derivation gives.',
    onChange(v) { state.c2 = v ? 2 : 1; recompute(); ctx.save(); },
  });
  const endsCtl = toggle({
    label: 'Automatic ends', value: state.autoEnds, hint: 'W₋₁, W₀, Wₙ₊₁, Wₙ₊₂ by point reflection of the data (e.g. W₀ = 2W₁ − W₂).',
    onChange(v) { state.autoEnds = v; auxHandles.locked = v; recompute(); ctx.save(); },
  });
  const bCtl = toggle({ label: 'Overlay a = 1/6 (B-spline)', value: state.showB, onChange(v) { state.showB = v; recompute(); ctx.save(); } });
  const iCtl = toggle({ label: 'Overlay a = 0 (interpolating)', value: state.showInterp, onChange(v) { state.showInterp = v; recompute(); ctx.save(); } });
  const buildCtl = toggle({ label: 'How it is built', hint: 'Joints Rᵢ (squares), even vertices C₂ᵢ (diamonds), the cubic control polygon C₀…C₂ₙ.', value: state.showBuild, onChange(v) { state.showBuild = v; refreshLegend(); curvePlot.redraw(); ctx.save(); } });
  const combCtl = toggle({ label: 'Curvature comb', value: state.showComb, onChange(v) { state.showComb = v; refreshLegend(); curvePlot.redraw(); ctx.save(); } });
  const addBtn = button({ label: 'Add point', onClick: addPoint, title: 'Adds a data point after the selected one (or at the end)' });
  const removeBtn = button({ label: 'Remove point', onClick: removePoint, title: 'Removes the selected data point (or the last one)' });
  const presetNote = h('p', { class: 'ctl-hint', 'aria-live': 'polite' });
  const presetBtns = Object.entries(PRESETS).map(([id, pr]) => button({ label: pr.label, onClick: () => applyPreset(id) }).el);
  const clearFamily = button({ label: 'Clear the family', onClick: () => { state.family = null; state.preset = ''; recompute(); refreshControls(); ctx.save(); } });
  const uOut = readout({ label: 'Evaluation point' });
  uOut.el.dataset.readout = 'u';
  const player = uPlayer({
    range: () => (c.main ? [c.main.domain[0], c.main.domain[1]] : [0, 1]), get: () => state.u,
    set(v) { state.u = v; computeAtU(wasm, state, c); refreshReadouts(); steps?.refresh(); curvePlot.redraw(); },
    onPause() { ctx.save(); },
  });
  const tensionOut = readout({ label: 'Tensions p₀…pₙ used' });
  const domainOut = readout({ label: 'Domain' });
  const claimOut = readout({ label: 'Printed: “a = 1/6, p = 0 gives the B-spline”' });
  claimOut.el.dataset.readout = 'claim-bspline';
  const claimNote = h('p', { class: 'ctl-hint' }, t('How far the even vertices C₂ᵢ with p = 0 (what the printed claim uses) are from those of the B-spline, on the current knots: 0 only on uniform knots. SplineLab reaches the B-spline through the §5 blend.'), ' ', correctionLink('correction-000-bspline', t('The correction')));
  if (options.locked) { addBtn.setDisabled(true); removeBtn.setDisabled(true); }

  // ---------- step by step: the construction ----------
  steps = stepper({
    title: 'How the curve is built',
    hint: 'For the current a and tension. The numbers are shown for the joint nearest the evaluation point u (Play u to move it).',
    steps: () => buildSteps(state, c),
    get: () => state.step,
    set(i) { state.step = i; curvePlot.redraw(); ctx.save(); },
  });
  // ---------- the printed eq. (5), live ----------
  const eq5Ctl = toggle({
    label: 'Also draw eq. (5) as printed', value: state.eq5Printed,
    hint: 'The odd vertices from the joints with the last weight of eq. (5) as printed, b·c/((b+c)(b+c+d)), instead of the corrected b²/((b+c)(b+c+d)).',
    onChange(v) { state.eq5Printed = v; recompute(); ctx.save(); },
  });
  const eq5Out = readout({ label: 'Eq. (5) as printed' });
  eq5Out.el.dataset.readout = 'eq5';
  // long readouts (a list of tensions, a sentence) wrap between words, never inside a number: each word is a
  // nowrap span (class ctl-readout-list; tests/e2e/lecture-shell.test.mjs checks that no word splits)
  for (const r of [eq5Out, tensionOut]) {
    const out = r.el.querySelector('output');
    out.classList.add('ctl-readout-list');
    out.style.whiteSpace = 'normal';
    r.set = (text) => out.replaceChildren(...String(text).split(' ').flatMap((w, i) => [i ? ' ' : '', h('span', { style: { whiteSpace: 'nowrap' } }, w)]));
  }

  L.controls.append(
    group('Step by step', steps.el),
    group('Approximation', aCtl.el, row(bCtl.el), row(iCtl.el)),
    group('Tension', pCtl.el, autoCtl.el, autoScaleCtl.el, c2Ctl.el, tensionOut.el),
    group('Knots', knotCtl.el, consCtl.el, kToggle.el, kCtl.el, domainOut.el, claimOut.el, claimNote),
    group('Data', endsCtl.el, row(addBtn.el, removeBtn.el), buildCtl.el, combCtl.el),
    group('Evaluation point', h('div', { class: 'ctl-added' }, row(player.el), uOut.el)),
    group('The paper\'s figures', h('div', { class: 'ctl-row preset-row' }, presetBtns), presetNote, row(clearFamily.el)),
    group('Correction: eq. (5)', eq5Ctl.el, eq5Out.el, h('p', { class: 'ctl-hint' }, t('The printed weights do not sum to 1 where the spans around a joint differ, so the curve misses the data there (0 on uniform knots).'), ' ', correctionLink('correction-000-eq5', t('The correction')))),
  );
  // "Use my data" (www/lib/data-import.js): your data W₁…Wₙ; the end points W₋₁, W₀, Wₙ₊₁, Wₙ₊₂ are reflected
  if (!options.locked) L.controls.append(group('Your data', dataImport({ label: 'Use my data points', apply: 'Fit these points', min: 2, max: MAX_POINTS - 4, onData(d) {
    const e0 = d[0], e1 = d[d.length - 1];
    state.points = [e0, e0, ...d, e1, e1].map((q) => q.slice());
    Object.assign(state, { autoEnds: true, family: null, preset: '' });
    sanitizeState(); refreshControls(); recompute(); fitSidePlots(); state.view = [];
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 40); ctx.save();
  } }).el));

  function refreshReadouts() {
    const r = readoutTexts(state, c);
    eq5Out.set(r.eq5); uOut.set(r.u);
    if (c.main) { tensionOut.set(r.tension); claimOut.set(r.claim); domainOut.set(r.domain); }
  }

  function refreshControls() {
    aCtl.set(state.a); pCtl.set(state.p); kCtl.set(state.K); kToggle.set(state.useK);
    kCtl.setDisabled(!state.useK);
    knotCtl.set(state.knots); consCtl.set(state.construction); autoCtl.set(state.autoTension);
    autoScaleCtl.set(state.autoScale); autoScaleCtl.setDisabled(state.autoTension === 'off');
    pCtl.setDisabled(state.autoTension !== 'off');
    c2Ctl.set(state.c2 === 2); endsCtl.set(state.autoEnds);
    bCtl.set(state.showB); iCtl.set(state.showInterp); buildCtl.set(state.showBuild); combCtl.set(state.showComb);
    auxHandles.locked = state.autoEnds;
    clearFamily.setDisabled(!state.family);
    addBtn.setDisabled(options.locked || m() >= MAX_POINTS);
    removeBtn.setDisabled(options.locked || m() <= (state.autoEnds ? 7 : 6));
    presetNote.textContent = state.preset && PRESETS[state.preset] ? t(PRESETS[state.preset].note) : '';
  }

  function applyPreset(id) {
    const pr = PRESETS[id];
    Object.assign(state, defaults(), { showB: state.showB, showInterp: state.showInterp, showBuild: state.showBuild }, JSON.parse(JSON.stringify(pr.state)), { preset: id });
    if (pr.state.family) { state.showB = false; state.showInterp = false; }
    sanitizeState();
    refreshControls();
    recompute();
    fitSidePlots();
    curvePlot.fitBounds(drawnBounds(), 40);
    state.view = [];
    ctx.save();
  }

  // the view fits what is drawn: the data, the curve (it may overshoot the data, e.g. above W₂W₃ of Fig. 9) and,
  // with "How it is built" on, the cubic control polygon
  function drawnBounds() {
    return curvePlot.boundsOf(state.points, c.main ? c.main.points : null, state.showBuild && c.main ? c.main.controlPoints : null);
  }

  function addPoint() {
    if (m() >= MAX_POINTS) return;
    const sel = curvePlot.selected;
    const i = sel && sel.group === dataHandles ? sel.index + 2 : m() - 3;
    const a = state.points[i], b = state.points[i + 1];
    state.points.splice(i + 1, 0, [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2 + 0.3]);
    state.preset = '';
    refreshControls(); recompute(); fitSidePlots(); ctx.save();
  }

  // double-click / Alt+click adds a data point on the nearest edge (between W₁ and Wₙ); double-click on a data
  // point or Delete removes it (the auxiliary end points stay)
  const minPts = () => (state.autoEnds ? 7 : 6);
  const needText = () => tn(minPts() - 4, 'The curve needs at least {n} data point: this is the minimum.', 'The curve needs at least {n} data points: this is the minimum.');
  const editing = pointEditing(curvePlot, {
    group: dataHandles, points: () => state.points, locked: options.locked, notify,
    canAdd: () => m() < MAX_POINTS, canRemove: () => m() > minPts(),
    maxText: () => tn(MAX_POINTS - 4, 'At most {n} data point.', 'At most {n} data points.'),
    minText: needText,
    insert(i, q) {
      state.points.splice(Math.min(m() - 2, Math.max(2, i)), 0, q);
      state.preset = ''; refreshControls(); recompute(); fitSidePlots(); ctx.save();
    },
    remove(i) { state.points.splice(i + 2, 1); state.preset = ''; refreshControls(); recompute(); fitSidePlots(); ctx.save(); },
  });

  function removePoint() {
    if (m() <= minPts()) { notify(needText(), 'info'); return; }
    const sel = curvePlot.selected;
    const i = sel && sel.group === dataHandles ? sel.index + 2 : m() - 3;
    state.points.splice(i, 1);
    curvePlot.select(null);
    state.preset = '';
    refreshControls(); recompute(); fitSidePlots(); ctx.save();
  }

  // ---------- explanation (interp-approx/explain.js) ----------
  explanation(L.explain, explanationContent(meta));

  // ---------- start ----------
  sanitizeState();
  refreshControls();
  compute(wasm, state, notify, c);
  computeAtU(wasm, state, c);
  refreshReadouts();
  refreshLegend();
  steps.refresh();
  fitSidePlots();
  if (!restoreView(curvePlot, state.view)) {
    state.view = [];
    curvePlot.fitBounds(drawnBounds(), 40);
  }
  curvePlot.redraw(); basisPlot.redraw(); kappaPlot.redraw();

  return {
    destroy() { steps.destroy(); player.destroy(); editing.destroy(); curvePlot.destroy(); basisPlot.destroy(); kappaPlot.destroy(); },
    // idle warm-up (www/lib/warm.js): a point drag's computation and drawing with the current state (same pixels;
    // no save, and no text rewritten in the live regions)
    warm() { compute(wasm, state, notify, c); computeAtU(wasm, state, c); curvePlot.redraw(); basisPlot.redraw(); kappaPlot.redraw(); },
    // for the shell's Export row: the B2-spline's control data (knots, C_0..C_2n, joints, tensions) and samples
    exports() {
      const { main } = c;
      if (!main) return {};
      return {
        json: { domain: main.domain, knots: main.knots, controlPoints: main.controlPoints, joints: main.joints, evenVertices: main.evenVertices, tension: main.tension, samples: { params: main.params, points: main.points } },
        csv: { points: main.points, dim: main.dim || 2 },
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------

export function snippet(state) {
  const o = { a: state.a, tension: state.p, knots: state.knots, c2: state.c2, construction: state.construction };
  if (state.useK) o.K = state.K;
  if (state.autoTension !== 'off' && state.construction !== 'section3') { o.autoTension = state.autoTension; o.autoTensionScale = state.autoScale; }
  const fit = state.autoEnds;
  return snippetCode(meta.title, code`
    // ${raw(fit ? 'the data W₁…Wₙ (b2Fit adds the end points W₋₁, W₀, Wₙ₊₁, Wₙ₊₂ by reflection)' : 'the points W₋₁…Wₙ₊₂')}
    const points = ${fit ? state.points.slice(2, -2) : state.points};
    const options = ${o};
    // L^a: a = 0 interpolates, a = 1/6 is the cubic B-spline
    const curve = sl.${raw(fit ? 'b2Fit' : 'b2Curve')}({ points, ...options, samples: 600, curvature: true });
    const basis = sl.b2Basis({ points: ${state.points}, ...options, samples: 301 });
    const atU = sl.${raw(fit ? 'b2Fit' : 'b2Curve')}({ points, ...options, at: [${state.u}] });
    return { curve, basis, atU };
  `);
}
