// Demo "Quasi-cubic curves" (quasi-cubic paper §2–3): a quasi-cubic trigonometric B-spline with shape parameter α,
// the cubic B-spline of the same polygon as a ghost, the four basis functions for the current α, and presets
// for the exact shapes (parabola, ellipse, circle, sine) with the analytic curve overlaid and the measured
// maximum deviation. All numbers come from the wasm API (quasiCubicCurve, quasiCubicBasis, quasiCubicPreset,
// quasiCubicShapeCheck, bsplineCurve, bsplineBasis); the modules in quasi-cubic-curves/ compute and draw:
//   data.js  limits, presets, condition texts   state-rules.js  what a link may hold   compute.js  every wasm call
//   draw.js  both plots (pure)   steps.js  the basis stepper   explain.js  the explanation.
// This entry holds the demo contract (www/demos/README.md): meta, the declared state, mount (plots, controls,
// point editing), snippet.

import { mathText } from '../lib/mathml.js';
import { h, demoLayout, explanation, fmt, legend } from '../lib/dom.js';
import { stepper } from '../lib/stepper.js';
import { cite } from '../lib/papers-ref.js';
import { createPlot, PALETTE, restoreView, curveSection, evenParams, paramRange } from '../lib/plot2d.js';
import { slider, toggle, buttonGroup, button, group, row, readout } from '../lib/controls.js';
import { uPlayer } from '../lib/player.js';
import { pointEditing } from '../lib/point-edit.js';
import { code, snippetCode } from '../lib/snippet.js';
import { dataImport } from '../lib/data-import.js';
import { MAX_POINTS, FREE_POINTS, CONDITION_TEXT, sub, brokenSegments } from './quasi-cubic-curves/data.js';
import { sanitize as sanitizeRules, takePreset } from './quasi-cubic-curves/state-rules.js';
import { emptyComputed, segs as segsOf, compute as computeAll, computeAtU as computeAtUInto, computeBasis as computeBasisInto, computeSteps as computeStepsInto } from './quasi-cubic-curves/compute.js';
import { series, describeCurve, describeBasis, drawCurve, drawCurveOver, drawBasis } from './quasi-cubic-curves/draw.js';
import { basisSteps } from './quasi-cubic-curves/steps.js';
import { curveTrace } from './quasi-cubic-curves/sound.js';
import { explanationContent } from './quasi-cubic-curves/explain.js';

export const meta = {
  id: 'quasi-cubic-curves',
  title: 'Quasi-cubic curves',
  summary: 'Trigonometric B-splines with a shape parameter α: exact ellipses, circles, parabolas and sines.',
  paper: cite('003', '§2–3 (Props. 3–8); the basis functions are reconstructed'),
};

export function defaults() {
  return {
    preset: 'free',
    alpha: 0.5,
    closed: false,
    points: FREE_POINTS.map((p) => p.slice()),
    showGhost: true,
    showPolygon: true,
    u: 0,
    step: -1,     // the basis stepper: −1 = off, 0…3 = the piece B_j, 4 = their sum (partition of unity)
    view: [],
  };
}

/** @param {HTMLElement} root @param {import('../lib/host.js').DemoContext} ctx @returns {import('../lib/host.js').MountedDemo} */
export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);
  const sanitize = () => sanitizeRules(wasm, state, notify);

  // ---------- computed data (all from wasm: quasi-cubic-curves/compute.js) ----------
  const c = emptyComputed();
  const segs = () => segsOf(state);
  const computeAtU = () => computeAtUInto(wasm, state, c);
  const compute = () => computeAll(wasm, state, notify, c);
  const computeBasis = () => computeBasisInto(wasm, state, notify, c);
  const computeSteps = () => computeStepsInto(wasm, state, c);

  // ---------- the basis assembled on one segment (stepper: quasi-cubic-curves/steps.js) ----------
  let ready = false;   // the stepper must not clamp the linked step before the data exists
  const steps = stepper({
    title: 'The basis, step by step',
    hint: 'The four trigonometric pieces on one segment, then their sum, with the current α and the evaluation point.',
    steps: () => basisSteps(state, c),
    get: () => state.step,
    set(i) { if (!ready) return; state.step = i; basisPlot.redraw(); curvePlot.redraw(); ctx.save(); },
  });

  function recompute({ alpha = false } = {}) {
    compute();
    if (alpha) computeBasis();
    computeSteps();
    steps.refresh();
    refresh();
    curvePlot.redraw();
    basisPlot.redraw();
  }

  // ---------- curve plot ----------
  const curvePlot = createPlot(L.plots, {
    ariaLabel: 'Quasi-cubic trigonometric B-spline with draggable control points',
    equal: true, height: 430, locked: options.locked,
    view: { xmin: -0.5, xmax: 7.5, ymin: -0.5, ymax: 3 },
    describe: () => describeCurve(state, c, wasm),
    sound: () => curveTrace(wasm, state, c), // ♪ (quasi-cubic-curves/sound.js)
    table: () => { const r = paramRange(c.curve); return r ? [curveSection('The curve at 11 values of its parameter', wasm.quasiCubicCurve({ points: state.points, alpha: state.alpha, closed: state.closed, at: evenParams(...r) }))] : []; },
    onView(v) { state.view = [v.xmin, v.xmax, v.ymin, v.ymax]; ctx.save(); },
    draw(g, plot) { drawCurve(g, plot, state, c); },
    drawOver(g, plot) { drawCurveOver(g, plot, state, c, player.playing); },
  });
  curvePlot.canvas.dataset.plot = 'curve';

  const handles = curvePlot.addHandles({
    name: 'control point',
    points: () => state.points,
    colorOf: (i) => series(i),
    label: (i) => `b${sub(i)}`,
    labelOf: (i) => `Control point ${mathText(`b_{${i}}`)}`,
    radius: 8,
    move(i, q) { state.points[i] = [q[0], q[1]]; recompute(); },
    end() { ctx.save(); },
  });

  const key = legend([
    { label: 'quasi-cubic curve (α)', color: PALETTE.curve },
    { label: 'cubic B-spline, same polygon', color: PALETTE.muted, kind: 'dashed', dash: [3, 5] },
    { label: 'analytic shape of the preset', color: PALETTE.accent, kind: 'band', alpha: 0.45 },
    { label: 'control polygon', color: PALETTE.polygon, kind: 'dashed', dash: [8, 6] },
  ]);
  key.dataset.legendFor = 'curve';
  L.plots.appendChild(key);

  // ---------- basis plot ----------
  const basisPlot = createPlot(L.plots, {
    ariaLabel: 'The four quasi-cubic basis functions for the current alpha, with the cubic B-spline pieces dashed',
    height: 240, pan: false, zoom: false, xLabel: 't',
    view: { xmin: -0.03, xmax: 1.03, ymin: -0.12, ymax: 1.08 },
    describe: () => describeBasis(state, c),
    draw(g, plot) { drawBasis(plot, state, c); },
  });
  basisPlot.canvas.dataset.plot = 'basis';

  // ---------- controls ----------
  const alphaCtl = slider({
    label: 'Shape parameter α', min: -3, max: 3, step: 0.01, value: state.alpha, number: true,
    ticks: [{ value: -3, label: '−3' }, { value: 0, label: '0' }, { value: 1, label: '1' }, { value: 3, label: '3' }],
    hint: 'α ∈ [−3, 1]: non-negative basis (convex hull). α = 1: conics. α = 3: interpolates the polygon’s inner points.',
    onInput(v) { state.alpha = v; recompute({ alpha: true }); },
    onChange() { ctx.save(); },
  });
  const presetCtl = buttonGroup({
    label: 'Preset', value: state.preset,
    options: [{ value: 'free', label: 'Free' }, { value: 'ellipse', label: 'Ellipse' }, { value: 'circle', label: 'Circle' }, { value: 'parabola', label: 'Parabola' }, { value: 'sine', label: 'Sine' }],
    onChange(v) { loadPreset(v, true); },
  });
  const closedCtl = toggle({ label: 'Closed (periodic) curve', value: state.closed, onChange(v) { setClosed(v); } });
  const ghostCtl = toggle({ label: 'Show the cubic B-spline', value: state.showGhost, onChange(v) { state.showGhost = v; recompute(); ctx.save(); } });
  const polyCtl = toggle({ label: 'Show control polygon', value: state.showPolygon, onChange(v) { state.showPolygon = v; curvePlot.redraw(); ctx.save(); } });
  const uOut = readout({ label: 'Evaluation point', value: '—' });
  uOut.el.dataset.readout = 'u';
  const player = uPlayer({
    range: () => [0, segs()], get: () => state.u,
    set(v) { state.u = v; computeAtU(); computeSteps(); steps.refresh(); refreshU(); curvePlot.redraw(); basisPlot.redraw(); },
    onPause() { ctx.save(); },
  });
  function refreshU() { const { atU } = c; uOut.set(atU ? `u = ${fmt(state.u, 3)}: p(u) = (${fmt(atU[0], 3)}, ${fmt(atU[1], 3)})` : '—'); }
  const addBtn = button({ label: 'Add point', onClick: addPoint });
  const removeBtn = button({ label: 'Remove point', onClick: removePoint });
  const devOut = readout({ label: 'Max deviation', value: '—' });
  devOut.el.dataset.readout = 'deviation';
  const condOut = readout({ label: 'Condition residual', value: '—' });
  condOut.el.dataset.readout = 'condition';
  const alphaOut = readout({ label: 'α for this shape', value: '—' });
  const condText = h('p', { class: 'ctl-hint', 'aria-live': 'polite' });
  const info = h('p', { class: 'ctl-hint' });
  if (options.locked) { addBtn.setDisabled(true); removeBtn.setDisabled(true); }

  L.controls.append(
    group('Curve', alphaCtl.el, closedCtl.el, row(addBtn.el, removeBtn.el), info, h('div', { class: 'ctl-added' }, row(player.el), uOut.el), ghostCtl.el, polyCtl.el),
    group('Exact shapes', presetCtl.el, devOut.el, condOut.el, alphaOut.el, condText),
    group('Basis on one segment', steps.el),
  );
  // "Use my data" (www/lib/data-import.js): your control points b₀…bₙ₊₂ (the shape presets' conditions no longer apply)
  if (!options.locked) L.controls.append(group('Your data', dataImport({ label: 'Use my control points', apply: 'Use these points', min: 4, max: MAX_POINTS, onData(pts) {
    Object.assign(state, { preset: 'free', points: pts, u: 0 }); sanitize();
    curvePlot.select(null); recompute({ alpha: true }); fitDrawing(); state.view = []; ctx.save();
  } }).el));

  function refresh() {
    const { check } = c;
    refreshU();
    alphaCtl.set(state.alpha);
    presetCtl.set(state.preset);
    closedCtl.set(state.closed);
    closedCtl.setDisabled(options.locked || state.preset !== 'free' || state.points.length < 4);
    ghostCtl.set(state.showGhost);
    polyCtl.set(state.showPolygon);
    const fixed = state.preset === 'ellipse' || state.preset === 'circle' || state.preset === 'parabola';
    addBtn.setDisabled(options.locked || fixed || state.points.length >= MAX_POINTS);
    removeBtn.setDisabled(options.locked || fixed || state.points.length <= 4);
    const n = state.closed ? state.points.length : state.points.length - 3;
    info.textContent = `${state.points.length} control points, ${n} segment${n === 1 ? '' : 's'}, u ∈ [0, ${n}].`;
    if (!check) {
      devOut.set('—'); condOut.set('—'); alphaOut.set('—');
      condText.textContent = 'Pick a preset to see a curve that is exactly a conic or a sine, and what breaks it.';
      return;
    }
    devOut.set(Number.isFinite(check.deviation) ? check.deviation.toExponential(2) : 'undefined');
    const holds = check.conditionResidual <= 1e-9;
    condOut.set(holds ? `${check.conditionResidual.toExponential(1)} (holds)` : `${fmt(check.conditionResidual, 4)} (broken)`);
    const need = state.preset === 'sine' ? 0 : 1;
    alphaOut.set(check.alphaOk ? `α = ${need} ✓` : `needs α = ${need} (now ${fmt(state.alpha, 2)})`);
    const why = !holds ? 'The condition is broken, so the curve leaves the analytic shape: ' : !check.alphaOk ? `The polygon is right but α ≠ ${need}, so the curve leaves the analytic shape. Condition: ` : 'The condition holds: ';
    let which = '';
    if (state.preset === 'sine' && !holds) {
      const r = check.segmentResiduals;
      which = ' Broken now (ringed): ' + brokenSegments(r).map((i) => `segment ${i} (${r[2 * i] > 1e-9 ? 'x' : ''}${r[2 * i] > 1e-9 && r[2 * i + 1] > 1e-9 ? ' and ' : ''}${r[2 * i + 1] > 1e-9 ? 'y' : ''})`).join(', ') + '.';
    }
    condText.textContent = why + CONDITION_TEXT[state.preset] + which;
  }

  function loadPreset(name, user) {
    if (name === 'free') {
      state.preset = 'free';
      if (user) { state.points = FREE_POINTS.map((p) => p.slice()); state.closed = false; state.alpha = 0.5; }
    } else {
      if (!takePreset(wasm, state, name, notify)) return;
    }
    if (!user) return;
    curvePlot.select(null);
    state.u = 0;
    recompute({ alpha: true });
    fitDrawing();
    ctx.save();
  }

  // the view fits what is drawn: the control points, the curve and the analytic overlay of a preset
  function fitDrawing() {
    curvePlot.fitBounds(curvePlot.boundsOf(state.points, c.curve ? c.curve.points : [], c.check ? c.check.analytic : []), 56);
    state.view = [];
  }

  function setClosed(v) {
    state.closed = v;
    recompute();
    ctx.save();
  }

  function addPoint() {
    const P = state.points, n = P.length;
    if (n >= MAX_POINTS) return;
    const a = P[n - 2], b = P[n - 1];
    P.push([b[0] + (b[0] - a[0]) * 0.8 || b[0] + 1, b[1] + (b[1] - a[1]) * 0.8]);
    recompute();
    curvePlot.fitContent();
    ctx.save();
  }

  const fixedShape = () => state.preset === 'ellipse' || state.preset === 'circle' || state.preset === 'parabola';
  const editing = pointEditing(curvePlot, {
    group: handles, points: () => state.points, closed: () => state.closed, locked: options.locked, notify,
    canAdd: () => !fixedShape() && state.points.length < MAX_POINTS,
    canRemove: () => !fixedShape() && state.points.length > 4,
    maxText: () => (fixedShape() ? `The ${state.preset} preset has exactly 4 control points: choose Free or Sine to add points.` : `At most ${MAX_POINTS} control points.`),
    minText: () => (fixedShape() ? `The ${state.preset} preset has exactly 4 control points: choose Free or Sine to remove points.` : 'A quasi-cubic segment needs 4 control points: this is the minimum.'),
    insert(i, q) { state.points.splice(i, 0, q); if (state.preset === 'sine') state.preset = 'free'; recompute(); ctx.save(); },
    remove(i) { state.points.splice(i, 1); if (state.preset === 'sine') state.preset = 'free'; recompute(); ctx.save(); },
  });

  function removePoint() {
    if (state.points.length <= 4) return;
    const sel = curvePlot.selected;
    const i = sel && sel.group === handles ? sel.index : state.points.length - 1;
    state.points.splice(i, 1);
    curvePlot.select(null);
    recompute();
    ctx.save();
  }

  // ---------- explanation (quasi-cubic-curves/explain.js) ----------
  explanation(L.explain, explanationContent(meta));

  // ---------- start ----------
  sanitize();
  ready = true;
  recompute({ alpha: true });
  if (!restoreView(curvePlot, state.view)) fitDrawing();

  return {
    destroy() { steps.destroy(); player.destroy(); editing.destroy(); curvePlot.destroy(); basisPlot.destroy(); },
    // idle warm-up (www/lib/warm.js): a point drag's computation and drawing with the current state (same pixels;
    // no save, and no text rewritten in the live regions)
    warm() { compute(); computeSteps(); curvePlot.redraw(); basisPlot.redraw(); },
    // for the shell's Export row: the quasi-cubic curve's samples (and the shape check of a preset)
    exports() {
      const { curve, check } = c;
      if (!curve) return {};
      return {
        json: { alpha: state.alpha, closed: state.closed, controlPoints: state.points, shapeCheck: check, samples: { params: curve.params, points: curve.points } },
        csv: { points: curve.points, dim: curve.dim || 2 },
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------

export function snippet(state) {
  const P = state.points;
  const gp = state.closed ? [...P, P[0], P[1], P[2]] : P;
  const ghost = state.showGhost ? code`
    // the uniform cubic B-spline of the same polygon, for comparison
    const ghost = sl.bsplineCurve({ degree: 3, knots: ${Array.from({ length: gp.length + 4 }, (_, i) => i)}, points: ${gp}, samples: ${60 * gp.length} });` : 'const ghost = null;';
  const check = state.preset !== 'free' ? code`
    const shapeCheck = sl.quasiCubicShapeCheck({ shape: ${state.preset}, points, alpha, samples: 200 });` : 'const shapeCheck = null;';
  return snippetCode(meta.title, code`
    const points = ${P};
    const alpha = ${state.alpha};
    const closed = ${state.closed};
    const curve = sl.quasiCubicCurve({ points, alpha, closed, samples: ${60 * P.length} });
    const atU = sl.quasiCubicCurve({ points, alpha, closed, at: [${state.u}] });
    // the four α-basis functions on one segment, t ∈ [0, 1]
    const basis = sl.quasiCubicBasis({ alpha, samples: 201 });
  ` + '\n' + ghost + '\n' + check + '\nreturn { curve, atU, basis, ghost, shapeCheck };');
}
