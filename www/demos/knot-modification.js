// Demo "Knot modification" (Juhász–Hoffmann): drag one knot of a B-spline curve along the knot line
// (and, with "extend", beyond its neighbours); see the paths traced by a few curve points, the envelope of the
// family of curves, the limit control points as the knot goes to ±∞, and which segments the knot affects.
// A surface tab moves two knots of a B-spline surface (WebGL 3D view) and shows path-surfaces, the
// envelope (8) and the four corner limits of Theorem 4. All spline values come from the wasm API
// (knotModifiedCurve, knotPathsCurve, knotEnvelopeCurve, knotLimits, knotModifiedSurface, knotPaths,
// knotEnvelope); the modules in knot-modification/ draw and react:
//   knots.js          the knot bookkeeping, the state rules, the surface net   curve-compute.js  what the curve tab computes
//   curve-draw.js     the curve plot (pure)         knot-line.js  the knot line (pure)   de-boor.js  the stepper
//   surface.js        the surface tab (compute, draw, view)                          explain.js  the explanation
// This entry holds the demo contract (www/demos/README.md): meta, the declared state, mount (controls), snippet.

import { h, demoLayout, explanation, fmt } from '../lib/dom.js';
import { math, mathText } from '../lib/mathml.js';
import { stepper } from '../lib/stepper.js';
import { cite } from '../lib/papers-ref.js';
import { createPlot, restoreView, curveSection, evenParams, paramRange } from '../lib/plot2d.js';
import { slider, toggle, buttonGroup, button, table, group, row } from '../lib/controls.js';
import { uPlayer } from '../lib/player.js';
import { code, snippetCode } from '../lib/snippet.js';
import { dataImport } from '../lib/data-import.js';
import { PALETTE } from '../lib/plot2d.js';
import { KNOT_ROW, sub, clampedKnots, knots, upRange, surfKnots, surfRange, curveDesc, surfaceDesc, sanitize, curveInfoText } from './knot-modification/knots.js';
import { computeCurve } from './knot-modification/curve-compute.js';
import { describeCurve, drawCurve, drawCurveOver, curveLegend } from './knot-modification/curve-draw.js';
import { describeKnots, drawKnotLine, drawKnotLineOver, knotLineView, snapKnot } from './knot-modification/knot-line.js';
import { deBoorSteps } from './knot-modification/de-boor.js';
import { surfaceView, surfaceInfoText } from './knot-modification/surface.js';
import { explanationContent } from './knot-modification/explain.js';
import { modifiedCurveTrace } from './knot-modification/sound.js';

export const meta = {
  id: 'knot-modification',
  title: 'Knot modification',
  summary: 'Move one knot (even past its neighbours): curve points travel on paths, the family has an envelope, and the paths end at control points.',
  paper: cite('002', 'Thms 3–8, eqs. (6)–(10)'),
};

export function defaults() {
  return {
    tab: 'curve',
    order: 4,
    points: [[0, 0], [1, 2.4], [2.2, 2.8], [3.2, 0.6], [4.4, 0.2], [5.4, 2.6], [6.6, 2.4], [7.4, 0.4]],
    p: 5,
    up: 2.4,
    extend: false,
    tracked: 3,
    trackAll: false,
    showFamily: true,
    showEnvelope: true,
    showLimits: true,
    step: -1,     // the de Boor stepper at the first tracked point: −1 = off, else the index of d_j^r shown
    // surface tab
    sp: 4,
    sq: 4,
    sup: 2.5,
    svq: 2.5,
    smove: 'both',
    yaw: 35,
    pitch: 30,
    view: [],
    camera: [],   // 3D camera distance and target [d, x, y, z] ([] = frame the surface); the direction is yaw/pitch
  };
}

/** @param {HTMLElement} root @param {import('../lib/host.js').DemoContext} ctx @returns {import('../lib/host.js').MountedDemo} */
export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);
  const sanitizeState = () => sanitize(state, defaults());

  // ---------- curve data (all from wasm: knot-modification/curve-compute.js) ----------
  const C = { cur: null, orig: null, affected: null, paths: [], env: null, family: [], limits: null, info: null, trackedU: [], trackedPts: null };

  // ---------- curve plot and knot line ----------
  const curveWrap = h('div', { class: 'km-curve' });
  L.plots.appendChild(curveWrap);
  const curvePlot = createPlot(curveWrap, {
    ariaLabel: 'B-spline curve with one moving knot: paths of curve points, envelope, limit control points',
    equal: true, height: 430, locked: options.locked,
    view: { xmin: -0.8, xmax: 8.2, ymin: -0.8, ymax: 3.4 },
    describe: () => describeCurve(state, C),
    table: () => { const r = paramRange(C.cur); return r ? [curveSection('The modified curve at 11 values of u', wasm.knotModifiedCurve({ curve: curveDesc(state), p: state.p, up: state.up, at: evenParams(...r) }))] : []; },
    onView(v) { state.view = [v.xmin, v.xmax, v.ymin, v.ymax]; ctx.save(); },
    draw(g, plot) { drawCurve(g, plot, state, C); },
    drawOver(g, plot) { drawCurveOver(g, plot, state, C); },
    sound: () => modifiedCurveTrace(wasm, state, C), // ♪ (knot-modification/sound.js)
  });
  curvePlot.canvas.dataset.plot = 'curve';
  curvePlot.addHandles({
    name: 'control point',
    points: () => state.points,
    label: (i) => `d${sub(i)}`,
    labelOf: (i) => `Control point ${mathText(`d_{${i}}`)}`,
    radius: 7,
    move(i, q) { state.points[i] = [q[0], q[1]]; recompute(); },
    end() { ctx.save(); },
  });
  curveWrap.appendChild(curveLegend());

  const knotPlot = createPlot(curveWrap, {
    ariaLabel: 'Knot line: drag the moving knot',
    height: 160, pan: true, zoom: true, zoomY: false, locked: options.locked, xLabel: 'u', ticks: true, grid: false,
    view: { xmin: -0.6, xmax: 5.6, ymin: -1, ymax: 1 },
    describe: () => describeKnots(state),
    draw(g, plot) { drawKnotLine(g, plot, state, C); },
    drawOver(g, plot) { drawKnotLineOver(g, plot, state, C); },
  });
  knotPlot.canvas.dataset.plot = 'knots';
  knotPlot.addHandles({
    name: 'moving knot',
    points: () => [[state.up, KNOT_ROW]],
    label: () => '',
    labelOf: () => `Knot ${mathText(`u_{${state.p}}`)}`,
    color: PALETTE.ink, shape: 'triangle', radius: 9, axis: 'x', step: 0.02,
    constrain(_, q) { const [lo, hi] = upRange(state); return [Math.min(hi, Math.max(lo, snapKnot(knotPlot, q[0]))), KNOT_ROW]; },
    constraintNote: () => (state.extend ? 'the knot stays within the extended range of its neighbours' : 'the knot stays between its neighbours (turn on “Extend” to let it pass them)'),
    move(_, q) { setUp(q[0]); },
    end() { ctx.save(); },
  });

  // ---------- surface tab (knot-modification/surface.js) ----------
  const surfWrap = h('div', { class: 'km-surface' });
  L.plots.appendChild(surfWrap);
  let controlsReady = false;
  const surf = surfaceView({ wrap: surfWrap, wasm, state, ctx, notify, onTurn(yaw, pitch) { if (controlsReady) { yawCtl.set(yaw); pitchCtl.set(pitch); } } });

  // ---------- controls ----------
  const tabCtl = buttonGroup({
    label: 'Show', options: [{ value: 'curve', label: 'Curve' }, { value: 'surface', label: 'Surface' }], value: state.tab,
    onChange(v) { state.tab = v; showTab(); ctx.save(); },
  });
  const extendCtl = toggle({
    label: 'Extend: let the knot pass its neighbours',
    value: state.extend,
    hint: mathText('\\text{Extended paths (paper §2): beyond } u_{p-1}, u_{p+1} \\text{ the pieces are continued algebraically; as } u_p \\to \\pm\\infty \\text{ the points of } [u_{p-1}, u_{p+1}) \\text{ run to a control point.}'),
    onChange(v) { state.extend = v; sanitizeState(); refreshControls(); recompute(); ctx.save(); },
  });
  const upCtl = slider({
    label: 'Moving knot value uₚ', min: 0, max: 1, step: 0.01, value: state.up, number: true,
    onInput(v) { knotPlayer.pause(); setUp(v); },
    onChange() { ctx.save(); },
  });
  // "Play u_p": the moving knot runs through its slider's range (the family and the path unfold)
  const knotPlayer = uPlayer({
    label: 'Play uₚ', duration: 8000,
    range: () => [Number(upCtl.input.min), Number(upCtl.input.max)], get: () => state.up,
    set(v) { setUp(v); upCtl.set(state.up); },
    onPause() { ctx.save(); },
  });
  const pCtl = buttonGroup({
    label: 'Which knot moves (index p)', options: [], value: state.p,
    onChange(v) { state.p = v; state.up = knots(state)[v]; sanitizeState(); refreshControls(); recompute(); ctx.save(); },
  });
  const pWrap = h('div', null, pCtl.el);
  const orderCtl = buttonGroup({
    label: 'Order k (degree k − 1)', options: [2, 3, 4, 5].map((v) => ({ value: v, label: String(v) })), value: state.order,
    onChange(v) { state.order = v; state.up = NaN; sanitizeState(); state.up = knots(state)[state.p]; rebuildP(); refreshControls(); recompute(); ctx.save(); },
  });
  const trackCtl = slider({
    label: 'Tracked points in [uₚ₋₁, uₚ₊₁)', min: 1, max: 7, step: 1, value: state.tracked,
    onInput(v) { state.tracked = v; recompute(); },
    onChange() { ctx.save(); },
  });
  const allCtl = toggle({
    label: 'Track one point in every affected span',
    value: state.trackAll,
    hint: 'Theorem 1: a point of the span p ± g moves on a rational curve of order k − g; in the outermost affected spans the paths are straight.',
    onChange(v) { state.trackAll = v; trackCtl.setDisabled(v); recompute(); ctx.save(); },
  });
  const famCtl = toggle({ label: 'Show the family (7 members)', value: state.showFamily, onChange(v) { state.showFamily = v; recompute(); ctx.save(); } });
  const envCtl = toggle({ label: 'Show the envelope', value: state.showEnvelope, onChange(v) { state.showEnvelope = v; redrawAll(); ctx.save(); } });
  const limCtl = toggle({ label: 'Show the limit control points', value: state.showLimits, onChange(v) { state.showLimits = v; redrawAll(); ctx.save(); } });
  const resetBtn = button({ label: 'Reset the knot', onClick() { state.up = knots(state)[state.p]; state.sup = surfKnots()[state.sp]; state.svq = surfKnots()[state.sq]; refreshControls(); recompute(); ctx.save(); } });
  const readoutTbl = table({ caption: ['Tracked points ', math('s(u; u_p)')], columns: ['u', 'x', 'y'], digits: 3 });
  const info = h('p', { class: 'ctl-hint km-info', 'aria-live': 'polite' });

  const supCtl = slider({
    label: 'Knot uₚ (surface)', min: 0, max: 1, step: 0.01, value: state.sup, number: true,
    onInput(v) { state.sup = v; surf.compute(); surf.plot.redraw(); refreshSurfaceInfo(); },
    onChange() { ctx.save(); },
  });
  const svqCtl = slider({
    label: ['Knot ', math('v_q'), ' (surface)'], min: 0, max: 1, step: 0.01, value: state.svq, number: true,
    onInput(v) { state.svq = v; surf.compute(); surf.plot.redraw(); refreshSurfaceInfo(); },
    onChange() { ctx.save(); },
  });
  const yawCtl = slider({ label: 'Turn', min: -180, max: 180, step: 1, value: state.yaw, onInput(v) { state.yaw = v; surf.view.setView({ yaw: v }); }, onChange() { ctx.save(); } });
  const pitchCtl = slider({ label: 'Tilt', min: 0, max: 89, step: 1, value: state.pitch, onInput(v) { state.pitch = v; surf.view.setView({ pitch: v }); }, onChange() { ctx.save(); } });
  const surfInfo = h('p', { class: 'ctl-hint', 'aria-live': 'polite' });

  if (options.locked) { resetBtn.setDisabled(true); }

  let stepsReady = false;   // the stepper must not clamp the step from the link before the data exists
  const steps = stepper({
    title: 'Moving uₚ, step by step',
    hint: 'The de Boor recursion at the first tracked point (the first diamond) with the moved knot: which intermediate points change when uₚ moves, each with its formula and the current numbers.',
    steps: () => deBoorSteps(state, C),
    get: () => state.step,
    set(i) { if (!stepsReady) return; state.step = i; redrawAll(); ctx.save(); },
  });
  steps.el.querySelector('.stepper-title').replaceChildren('Moving ', math('u_p'), ', step by step');
  const curveControls = group('Curve', orderCtl.el, pWrap, upCtl.el, h('div', { class: 'ctl-added' }, row(knotPlayer.el)), row(resetBtn.el), trackCtl.el, allCtl.el, readoutTbl.el, info, steps.el);
  const smoveCtl = buttonGroup({
    label: 'Knots that move', options: [{ value: 'both', label: ['uₚ and ', math('v_q')] }, { value: 'u', label: 'only uₚ' }, { value: 'v', label: ['only ', math('v_q')] }], value: state.smove,
    onChange(v) { state.smove = v; refreshControls(); surf.compute(); refreshSurfaceInfo(); surf.plot.redraw(); ctx.save(); },
  });
  const surfaceControls = group('Surface (orders 3 × 3, 8 × 8 control points)', smoveCtl.el, supCtl.el, svqCtl.el, yawCtl.el, pitchCtl.el, surfInfo);
  controlsReady = true;
  L.controls.append(group('Knot modification', tabCtl.el, extendCtl.el, famCtl.el, envCtl.el, limCtl.el), curveControls, surfaceControls);
  // "Use my data" (www/lib/data-import.js): your control points (6…16) for the curve tab; clamped knots 0, 1, 2, …
  if (!options.locked) curveControls.append(dataImport({ label: 'Use my control points', apply: 'Use these points', min: 6, max: 16, onData(pts) {
    state.points = pts; state.up = NaN; sanitizeState(); state.up = knots(state)[state.p]; rebuildP(); refreshControls(); recompute();
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 40); state.view = []; ctx.save();
  } }).el);

  function rebuildP() {
    const n = state.points.length - 1;
    const opts = [];
    for (let i = state.order; i <= n; i++) opts.push({ value: i, label: String(i) });
    const fresh = buttonGroup({
      label: 'Which knot moves (index p)', options: opts, value: state.p,
      onChange(v) { state.p = v; state.up = knots(state)[v]; sanitizeState(); refreshControls(); recompute(); ctx.save(); },
    });
    pWrap.replaceChildren(fresh.el);
    pCtlNow = fresh;
  }
  let pCtlNow = pCtl;

  function setUp(v) {
    const [lo, hi] = upRange(state);
    state.up = Math.min(hi, Math.max(lo, v));
    upCtl.set(state.up);
    computeCurve(wasm, state, notify, C);
    refreshInfo();
    redrawAll();
  }

  function refreshInfo() {
    if (C.trackedPts) readoutTbl.set(C.trackedU.map((u, j) => [fmt(u, 3), C.trackedPts[2 * j], C.trackedPts[2 * j + 1]]));
    if (C.cur) info.textContent = curveInfoText(state, C);
  }

  function refreshSurfaceInfo() { if (surf.S.surf) surfInfo.textContent = surfaceInfoText(state, surf.S); }

  function refreshControls() {
    tabCtl.set(state.tab);
    extendCtl.set(state.extend);
    orderCtl.set(state.order);
    pCtlNow.set(state.p);
    const [lo, hi] = upRange(state);
    upCtl.setRange({ min: lo, max: hi });
    upCtl.set(state.up);
    trackCtl.set(state.tracked);
    trackCtl.setDisabled(state.trackAll);
    allCtl.set(state.trackAll);
    famCtl.set(state.showFamily);
    envCtl.set(state.showEnvelope);
    limCtl.set(state.showLimits);
    const [a, b] = surfRange(state, state.sp), [c, d] = surfRange(state, state.sq);
    supCtl.setRange({ min: a, max: b }); supCtl.set(state.sup);
    svqCtl.setRange({ min: c, max: d }); svqCtl.set(state.svq);
    smoveCtl.set(state.smove);
    supCtl.setDisabled(state.smove === 'v');
    svqCtl.setDisabled(state.smove === 'u');
    yawCtl.set(state.yaw); pitchCtl.set(state.pitch);
    knotPlot.setView(knotLineView(state));
  }

  function showTab() {
    const curve = state.tab === 'curve';
    const show = (el, on) => { el.style.display = on ? '' : 'none'; };
    show(curveWrap, curve);
    show(curveControls, curve);
    show(famCtl.el, curve);
    show(surfWrap, !curve);
    show(surfaceControls, !curve);
    steps.refresh();
    if (curve) { curvePlot.redraw(); knotPlot.redraw(); } else { surf.compute(); refreshSurfaceInfo(); surf.plot.redraw(); }
  }

  function redrawAll() { steps.refresh(); curvePlot.redraw(); knotPlot.redraw(); surf.plot.redraw(); }

  function recompute() {
    computeCurve(wasm, state, notify, C);
    if (state.tab === 'surface') { surf.compute(); refreshSurfaceInfo(); }
    refreshInfo();
    redrawAll();
  }

  // ---------- explanation (knot-modification/explain.js) ----------
  explanation(L.explain, explanationContent(meta));

  // ---------- start ----------
  sanitizeState();
  stepsReady = true;
  rebuildP();
  if (!restoreView(curvePlot, state.view)) {
    state.view = [];
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 48);
  }
  refreshControls();
  computeCurve(wasm, state, notify, C);
  refreshInfo();
  showTab();

  return {
    destroy() { steps.destroy(); knotPlayer.destroy(); curvePlot.destroy(); knotPlot.destroy(); surf.plot.destroy(); },
    // idle warm-up (www/lib/warm.js): a point drag's computation and drawing with the current state (same pixels;
    // no save, and no text rewritten in the live regions)
    warm() { computeCurve(wasm, state, notify, C); curvePlot.redraw(); knotPlot.redraw(); },
    // for the shell's Export row: the modified curve (curve tab) or surface (surface tab) and its data
    exports() {
      const S = surf.S;
      if (state.tab === 'surface') {
        if (!S.surf) return {};
        return {
          json: { surface: S.desc, moved: { p: state.sp, up: state.sup, q: state.sq, vq: state.svq, which: state.smove }, samples: { uv: S.surf.uv, points: S.surf.points } },
          obj: S.surf.mesh ? [{ name: 'knot_modified_surface', mesh: S.surf.mesh }] : [],
          csv: { points: S.surf.points, dim: S.surf.dim || 3 },
        };
      }
      if (!C.cur) return {};
      return {
        json: { curve: curveDesc(state), p: state.p, up: state.up, affectedRange: C.cur.affectedRange, affectedSpans: C.cur.affectedSpans, limits: C.limits, samples: { params: C.cur.params, points: C.cur.points } },
        csv: { points: C.cur.points, dim: C.cur.dim || 2 },
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------

export function snippet(state) {
  if (state.tab === 'surface') {
    const mu = state.smove !== 'v', mv = state.smove !== 'u';
    const which = { ...(mu ? { p: state.sp } : {}), ...(mv ? { q: state.sq } : {}) };
    const vals = { ...(mu ? { up: state.sup } : {}), ...(mv ? { vq: state.svq } : {}) };
    return snippetCode(meta.title, code`
      // a bi-quadratic B-spline surface (orders 3, 3): knots and control points d_rs
      const surface = ${surfaceDesc()};
      // which knots move (index p in u, q in v) …
      const which = ${which};
      // … and where to: the knot u_p becomes up, v_q becomes vq
      const moveTo = ${vals};
      const modified = sl.knotModifiedSurface({ surface, ...which, ...moveTo, samplesU: 41, samplesV: 41, mesh: true });
      const envelope = sl.knotEnvelope({ surface, ...which, samplesU: 11, samplesV: 11 });
      const limits = sl.knotLimits({ surface, ...which, samples: 80 });
      return { surface, modified, envelope, limits };
    `);
  }
  return snippetCode(meta.title, code`
    // a clamped B-spline curve: order k, knots, control points
    const curve = ${{ order: state.order, knots: clampedKnots(state.order, state.points.length), controlPoints: state.points }};
    // move the knot u_p to up (even past its neighbours)
    const p = ${state.p};
    const modified = sl.knotModifiedCurve({ curve, p, up: ${state.up}, samples: 400 });
    // the envelope of the family of curves as u_p runs between its neighbours, and the limits of the paths
    const envelope = sl.knotEnvelopeCurve({ curve, p, samples: 200 });
    const limits = sl.knotLimits({ curve, p });
    return { modified, envelope, limits };
  `);
}
