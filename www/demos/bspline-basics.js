// Demo "B-spline basics": drag the control points of a clamped B-spline, change the degree, drag the interior
// knots, and scrub a parameter u to see which p + 1 basis functions are non-zero there. All spline values come
// from the wasm API (bsplineCurve, bsplineBasis); two algorithm steppers walk through de Boor's algorithm at u and
// Boehm's insertion of the knot u, every intermediate point from the wasm API too (bsplineDeBoor,
// bsplineInsertKnot). The modules in bspline-basics/ compute and draw:
//   state-rules.js  limits, domain, what a link may hold   compute.js  every wasm call   draw.js  both plots (pure)
//   steps.js  the steppers (text and drawing)   explain.js  the explanation.
// This entry holds the demo contract (www/demos/README.md): meta, the declared state, mount (plots, controls,
// point and knot editing), snippet.

import { mathText } from '../lib/mathml.js';
import { t, tn } from '../lib/i18n.js';
import { h, demoLayout, explanation, legend } from '../lib/dom.js';
import { createPlot, PALETTE, restoreView, curveSection, basisSection, evenParams, paramRange } from '../lib/plot2d.js';
import { slider, toggle, buttonGroup, button, table, group, row } from '../lib/controls.js';
import { uPlayer } from '../lib/player.js';
import { pointEditing } from '../lib/point-edit.js';
import { stepper } from '../lib/stepper.js';
import { code, snippetCode } from '../lib/snippet.js';
import { dataImport } from '../lib/data-import.js';
import { MAX_POINTS, KNOT_ROW, MIN_GAP, sanitize as sanitizeRules, domain as domainOf, sub } from './bspline-basics/state-rules.js';
import { emptyComputed, clampedKnots, computeBasis, computeCurve, computeAtU as computeAtUInto } from './bspline-basics/compute.js';
import { series, describeCurve, describeBasis, drawCurve, drawCurveOver, drawBasis, drawBasisOver } from './bspline-basics/draw.js';
import { ALGOS, buildSteps } from './bspline-basics/steps.js';
import { explanationContent } from './bspline-basics/explain.js';
import { curveTrace, basisTrace } from './bspline-basics/sound.js';

export const meta = {
  id: 'bspline-basics',
  title: 'B-spline basics',
  summary: 'Drag control points and knots of a clamped B-spline; see its basis functions and which ones act at u.',
  paper: 'Cox–de Boor recursion (de Boor 1972); the kernel every SplineLab construction builds on',
};

export function defaults() {
  return {
    degree: 3,
    points: [[0, 0], [1, 2.2], [2.4, 2.6], [3.4, 0.6], [4.6, 0.2], [5.4, 2.4], [6.6, 1.8]],
    knots: [0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1],
    u: 0.4,
    showPolygon: true,
    showSum: true,
    stepAlgo: 'deboor', // the stepper: 'deboor' (de Boor at u) or 'insert' (Boehm: insert the knot u)
    step: -1,           // its step (-1 = off)
    view: [],
  };
}

/** @param {HTMLElement} root @param {import('../lib/host.js').DemoContext} ctx @returns {import('../lib/host.js').MountedDemo} */
export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);

  const n = () => state.points.length;
  const p = () => state.degree;
  const domain = () => domainOf(state);
  const sanitize = () => sanitizeRules(wasm, state, defaults, notify);

  let steps = null;      // the stepper (built with the controls below)

  // ---------- computed data (all from wasm: bspline-basics/compute.js) ----------
  const c = emptyComputed();
  const computeAtU = () => computeAtUInto(wasm, state, notify, c);

  function recompute({ knots = true } = {}) {
    if (knots) computeBasis(wasm, state, notify, c);
    computeCurve(wasm, state, notify, c);
    computeAtU();
    refreshControls();
    steps?.refresh();
    curvePlot.redraw();
    basisPlot.redraw();
  }

  /** The figures' tables (www/lib/plot2d/table.js): C(u) and every Nᵢ,ₚ(u) at u = 11 even values of the domain. */
  function tableOf(which) {
    const range = paramRange(c.curve);
    if (!range) return [];
    const at = evenParams(...range);
    if (which === 'curve') return [curveSection('C(u) at 11 values of u', wasm.bsplineCurve({ degree: p(), knots: state.knots, points: state.points, at }))];
    const names = Array.from({ length: state.points.length }, (_, i) => `N${sub(i)},${sub(p())}(u)`);
    return [basisSection('Nᵢ,ₚ(u) at 11 values of u', at, wasm.bsplineBasis({ degree: p(), knots: state.knots, at }).values, names)];
  }

  // ---------- curve plot ----------
  const curvePlot = createPlot(L.plots, {
    ariaLabel: 'B-spline curve with draggable control points',
    equal: true, height: 420, maxHeightRatio: 0.62, locked: options.locked,
    view: { xmin: -0.5, xmax: 7, ymin: -0.5, ymax: 3 },
    describe: () => describeCurve(state, c, wasm),
    table: () => tableOf('curve'),
    onView(v) { state.view = [v.xmin, v.xmax, v.ymin, v.ymax]; ctx.save(); },
    draw(g, plot) { drawCurve(g, plot, state, c); },
    drawOver(g, plot) { drawCurveOver(g, plot, state, c); },
    sound: () => curveTrace(wasm, state, c), // ♪ (bspline-basics/sound.js)
  });
  curvePlot.canvas.dataset.plot = 'curve';
  const ctrlHandles = curvePlot.addHandles({
    name: 'control point',
    points: () => state.points,
    colorOf: (i) => series(i),
    label: (i) => `P${sub(i)}`,
    labelOf: (i) => t('Control point {name}', { name: mathText(`P_{${i}}`) }),
    radius: 8,
    move(i, q) { state.points[i] = [q[0], q[1]]; recompute({ knots: false }); },
    end() { ctx.save(); },
  });

  const key = legend([
    { label: 'curve C(u) = Σ Nᵢ,ₚ(u) Pᵢ', color: PALETTE.curve },
    { label: 'control polygon', color: PALETTE.polygon, kind: 'dashed' },
    { label: 'control points Pᵢ (drag; colour = its Nᵢ,ₚ)', color: PALETTE.control, kind: 'dot' },
    { label: 'piece over the knot span of u', color: 'rgba(0,0,0,0.25)', kind: 'band' },
  ]);
  L.plots.appendChild(key);

  // ---------- basis plot with the knot strip ----------
  const basisPlot = createPlot(L.plots, {
    ariaLabel: 'Basis functions Nᵢ,ₚ over the domain, with draggable interior knots under the axis',
    height: 280, pan: false, zoom: false, locked: options.locked, xLabel: 'u',
    view: { xmin: -0.03, xmax: 1.03, ymin: -0.22, ymax: 1.2 },
    describe: () => describeBasis(state, c),
    table: () => tableOf('basis'),
    draw(g, plot) { drawBasis(plot, state, c); },
    drawOver(g, plot) { drawBasisOver(plot, state, c); },
    sound: () => basisTrace(state, c), // ♪ the first Nᵢ,ₚ non-zero at u
  });
  basisPlot.canvas.dataset.plot = 'basis';
  const interior = () => state.knots.slice(p() + 1, n()); // u_{p+1} … u_{n-1}
  basisPlot.addHandles({
    name: 'knot',
    points: () => interior().map((k) => [k, KNOT_ROW]),
    label: () => '',
    labelOf: (j) => t('Interior knot {name}', { name: `u${sub(p() + 1 + j)}` }),
    color: PALETTE.ink, shape: 'triangle', radius: 7, axis: 'x', step: 0.01,
    constrain(j, q) {
      const i = p() + 1 + j, k = state.knots;
      const lo = k[i - 1] + MIN_GAP, hi = k[i + 1] - MIN_GAP;
      return [Math.min(hi, Math.max(lo, q[0])), KNOT_ROW];
    },
    constraintNote: 'the knots must stay in order, each between its neighbours',
    move(j, q) { state.knots[p() + 1 + j] = q[0]; recompute(); },
    end() { ctx.save(); },
  });

  // ---------- controls ----------
  const degreeCtl = buttonGroup({
    label: 'Degree p', options: [1, 2, 3, 4, 5].map((d) => ({ value: d, label: String(d) })), value: state.degree,
    onChange(d) { setDegree(d); },
  });
  const uCtl = slider({
    label: 'Parameter u', min: 0, max: 1, step: 0.001, value: state.u, number: true,
    hint: 'The p + 1 basis functions that are non-zero at u are highlighted, with their control points.',
    onInput(v) { player.pause(); setU(v); },
    onChange() { ctx.save(); },
  });
  function setU(v) { state.u = v; computeAtU(); refreshReadout(); steps?.refresh(); curvePlot.redraw(); basisPlot.redraw(); }
  // "Play u": runs u along the domain (the slider follows)
  const player = uPlayer({ range: domain, get: () => state.u, set(v) { setU(v); uCtl.set(v); }, onPause() { ctx.save(); } });
  const addBtn = button({ label: 'Add point', onClick: addPoint });
  const removeBtn = button({ label: 'Remove point', onClick: removePoint, title: 'Removes the selected control point (or the last one)' });
  const uniformBtn = button({ label: 'Uniform knots', onClick: () => { rebuildKnots(); recompute(); ctx.save(); }, title: 'Reset the interior knots to equal spacing' });
  const polyCtl = toggle({ label: 'Show control polygon', value: state.showPolygon, onChange(v) { state.showPolygon = v; curvePlot.redraw(); ctx.save(); } });
  const sumCtl = toggle({ label: 'Show the sum Σ Nᵢ,ₚ(u)', value: state.showSum, onChange(v) { state.showSum = v; basisPlot.redraw(); ctx.save(); } });
  const readout = table({ caption: 'Non-zero at u', columns: ['i', 'Nᵢ,ₚ(u)'], digits: 4 });
  const info = h('p', { class: 'ctl-hint', 'aria-live': 'polite' });
  if (options.locked) { addBtn.setDisabled(true); removeBtn.setDisabled(true); uniformBtn.setDisabled(true); }

  // ---------- step by step: de Boor at u, Boehm's insertion of u ----------
  const algoCtl = buttonGroup({
    label: 'Algorithm', options: [{ value: 'deboor', label: 'de Boor at u' }, { value: 'insert', label: 'Insert knot u' }], value: state.stepAlgo,
    onChange(v) { state.stepAlgo = v; if (state.step >= 0) state.step = 0; steps.setTitle(ALGOS[v]); steps.refresh(); curvePlot.redraw(); ctx.save(); },
  });
  steps = stepper({
    title: ALGOS[state.stepAlgo],
    hint: 'Both use the parameter u of the slider above; the numbers follow the curve when you drag.',
    steps: () => buildSteps(state, c),
    get: () => state.step,
    set(i) { state.step = i; curvePlot.redraw(); ctx.save(); },
  });

  L.controls.append(
    group('Curve', degreeCtl.el, row(addBtn.el, removeBtn.el), info, polyCtl.el),
    group('Basis functions', uCtl.el, h('div', { class: 'ctl-added' }, row(player.el)), readout.el, sumCtl.el, row(uniformBtn.el)),
    group('Step by step', algoCtl.el, steps.el),
  );
  // "Use my data" (www/lib/data-import.js): your control points; the knots become clamped uniform
  if (!options.locked) L.controls.append(group('Your data', dataImport({ label: 'Use my control points', apply: 'Use these points', min: 2, max: MAX_POINTS, onData(pts) {
    state.points = pts; state.knots = []; sanitize(); refreshControls(); recompute(); state.view = [];
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 56); ctx.save();
  } }).el));

  function refreshReadout() {
    const { atU } = c;
    if (!atU) return;
    let s = 0;
    const rows = atU.active.map((i) => { s += atU.values[i]; return [`N${sub(i)},${sub(p())}`, atU.values[i]]; });
    rows.push([t('sum'), s]);
    readout.set(rows);
  }

  function refreshControls() {
    degreeCtl.set(state.degree);
    degreeCtl.inputs.forEach((inp, k) => { inp.disabled = options.locked || k + 1 > n() - 1; });
    const [a, b] = domain();
    uCtl.setRange({ min: a, max: b });
    uCtl.set(state.u);
    polyCtl.set(state.showPolygon);
    sumCtl.set(state.showSum);
    addBtn.setDisabled(options.locked || n() >= MAX_POINTS);
    removeBtn.setDisabled(options.locked || n() <= Math.max(2, p() + 1));
    info.textContent = t('{points}, {knots} (n + p + 1 = {n} + {p} + 1).', { points: tn(n(), '{n} control point', '{n} control points'), knots: tn(state.knots.length, '{n} knot', '{n} knots'), n: n(), p: p() });
    refreshReadout();
  }

  function rebuildKnots() {
    try { state.knots = clampedKnots(wasm, state); } catch (e) { notify(e, 'error'); }
  }

  function setDegree(d) {
    if (d > n() - 1) { notify(t('Degree {d} needs at least {n} control points.', { d, n: d + 1 }), 'info'); degreeCtl.set(state.degree); return; }
    state.degree = d;
    rebuildKnots();
    recompute();
    ctx.save();
  }

  function addPoint() {
    if (n() >= MAX_POINTS) return;
    const a = state.points[n() - 2], b = state.points[n() - 1];
    state.points.push([b[0] + (b[0] - a[0]) * 0.8 || b[0] + 1, b[1] + (b[1] - a[1]) * 0.8]);
    rebuildKnots();
    recompute();
    curvePlot.fitContent();
    ctx.save();
  }

  // double-click / Alt+click on the plot adds a control point on the nearest edge of the polygon; double-click on a
  // point or Delete removes it (not below p + 1 points)
  const editing = pointEditing(curvePlot, {
    group: ctrlHandles, points: () => state.points, locked: options.locked, notify,
    canAdd: () => n() < MAX_POINTS, canRemove: () => n() > Math.max(2, p() + 1),
    maxText: () => t('At most {n} control points.', { n: MAX_POINTS }),
    minText: () => t('A degree {p} B-spline needs at least {n} control points: lower the degree to remove more.', { p: p(), n: p() + 1 }),
    insert(i, q) { state.points.splice(i, 0, q); rebuildKnots(); recompute(); ctx.save(); },
    remove(i) { state.points.splice(i, 1); rebuildKnots(); recompute(); ctx.save(); },
  });

  function removePoint() {
    if (n() <= Math.max(2, p() + 1)) { notify(t('A degree {p} B-spline needs at least {n} control points: lower the degree to remove more.', { p: p(), n: p() + 1 }), 'info'); return; }
    const sel = curvePlot.selected;
    const i = sel && sel.group === ctrlHandles ? sel.index : n() - 1;
    state.points.splice(i, 1);
    curvePlot.select(null);
    rebuildKnots();
    recompute();
    ctx.save();
  }

  // ---------- explanation (bspline-basics/explain.js) ----------
  explanation(L.explain, explanationContent(meta));

  // ---------- start ----------
  sanitize();
  if (!restoreView(curvePlot, state.view)) {
    state.view = [];
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 56);
  }
  recompute();

  return {
    destroy() { steps.destroy(); player.destroy(); editing.destroy(); curvePlot.destroy(); basisPlot.destroy(); },
    // idle warm-up (www/lib/warm.js): a point drag's computation and drawing with the current state (same pixels;
    // no save, and no text rewritten in the live regions)
    warm() { computeCurve(wasm, state, notify, c); computeAtU(); curvePlot.redraw(); basisPlot.redraw(); },
    // for the shell's Export row: the curve's samples, the basis at u and the curve point there
    exports() {
      const { curve, atU } = c;
      return {
        json: curve ? { degree: p(), knots: state.knots, controlPoints: state.points, u: state.u, pointAtU: atU?.point, basisAtU: atU?.values, samples: { params: curve.params, points: curve.points } } : undefined,
        csv: curve ? { points: curve.points, dim: curve.dim || 2 } : undefined,
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------

export function snippet(state) {
  return snippetCode(meta.title, code`
    const degree = ${state.degree};
    const knots = ${state.knots};
    const points = ${state.points};
    // the curve and all basis functions N_i,p over the knot vector (Cox–de Boor)
    const curve = sl.bsplineCurve({ degree, knots, points, samples: 400 });
    const basis = sl.bsplineBasis({ degree, knots, samples: 301 });
    // the point C(u) and the basis values N_i,p(u) at the scrubbed parameter u
    const u = ${state.u};
    const atU = sl.bsplineCurve({ degree, knots, points, at: [u] });
    const basisAtU = sl.bsplineBasis({ degree, knots, at: [u] });
    return { curve, basis, atU, basisAtU };
  `);
}
