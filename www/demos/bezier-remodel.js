// Demo "Bézier remodelling" (Gânscă–Coman–Ţămbulea): a parametric degree elevation of a Bézier
// spline that keeps its class C^r. Sliders for the parameters α_k^(I) (the ones eq. (9) fixes are greyed with
// the constraint), curvature at every breakpoint (formula vs measured) with osculating circles, the paper's
// Fig. 3 (K* against α_m) as a live plot, and a surface tab (§4.1, Figs. 4–5). All spline values come from the
// wasm API (bezierRemodel, bezierSpline, bezierRemodelSurface, bsplineToBezier); this module draws and reacts.
// A stepper walks through the remodelling of one segment (g → the points b* of eq. (6) one by one → g*) and
// de Casteljau's algorithm on that segment of g* (every intermediate point from bezierDeCasteljau).

import { h, demoLayout, explanation, fmt, clear, append, legend, setLegendItems } from '../lib/dom.js';
import { cite, correctionLink } from '../lib/papers-ref.js';
import { createPlot, PALETTE, restoreView } from '../lib/plot2d.js';
import { slider, toggle, buttonGroup, button, table, group, readout, row } from '../lib/controls.js';
import { View3D } from '../lib/view3d.js';
import { uPlayer } from '../lib/player.js';
import { stepper } from '../lib/stepper.js';
import { mathText } from '../lib/mathml.js';

export const meta = {
  id: 'bezier-remodel',
  title: 'Bézier remodelling',
  summary: 'Raise the degree of a Bézier spline with free parameters α: reshape it while it stays Cʳ; watch the curvature at the joints.',
  paper: cite('001', '§2–4'),
};

// ---------- the paper's data ----------
const EXAMPLE_POINTS = [[10, 16], [7, 21], [3, 9], [0, 0], [-4, 0], [-8, 0], [-6, 3], [-4, 6], [2, 2], [8, -2], [10, 3]];
const EXAMPLE_BREAKS = [0, 1, 7 / 4, 5 / 2, 13 / 4, 4];
const FIG1 = [[2 / 3, 1 / 20], [19 / 20, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 10]];
const FIG2 = [[1 / 10, 1 / 10], [9 / 10, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 100], [99 / 100, 1 / 5]];
// a quartic B-spline (C³) turned into Bézier form with bsplineToBezier: here C² can be kept (r = 2 ≤ ⌊4/2⌋)
const QUARTIC = { degree: 4, knots: [0, 0, 0, 0, 0, 1, 2, 3, 3, 3, 3, 3], points: [[0, 0], [1.5, 4], [4, 5.5], [6.5, 2], [8, -1.5], [11, -1], [12.5, 2.5]] };
// the surface table of §4 (rows k = 0..6 along u, columns l = 0..3 along v; repeated rows merged)
const SURFACE_POINTS = [
  [[0, 0, 3], [0, 1, 2], [0, 3, 1], [0, 4, 3]],
  [[1, 0, 1], [1, 1, 4], [1, 3, 2], [1, 4, 4]],
  [[2, 0, 2.5], [2, 1, 3], [2, 3, 1], [2, 4, 3]],
  [[3, 0, 4], [3, 1, 2], [3, 3, 0], [3, 4, 2]],
  [[4, 0, 2.5], [4, 1, 3], [4, 3, 1], [4, 4, 2.5]],
  [[5, 0, 1], [5, 1, 4], [5, 3, 2], [5, 4, 3]],
  [[6, 0, 3], [6, 1, 0], [6, 3, 1], [6, 4, 2]],
];
const SURFACE_PRESETS = {
  fig4: { label: 'Fig. 4: usual elevation (2/3, 1/3)', alphas: [[2 / 3, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 3]], enforce: true },
  literal: { label: 'Fig. 4 text taken literally: all α = 1/3 (not C¹)', alphas: [[1 / 3, 1 / 3], [1 / 3, 1 / 3], [1 / 3, 1 / 3]], enforce: false },
  fig5: { label: 'Fig. 5: (1/2, 1/500), (·, 1/1000), (·, 4/5)', alphas: [[1 / 2, 1 / 500], [499 / 500, 1 / 1000], [999 / 1000, 4 / 5]], enforce: true },
};
const CURVE_PRESETS = [
  { value: 'fig1', label: 'Fig. 1' },
  { value: 'fig2', label: 'Fig. 2' },
  { value: 'classical', label: 'Classical (g* = g)' },
  { value: 'quartic', label: 'Quartic from a B-spline' },
];

export function defaults() {
  return {
    tab: 'curve',
    preset: 'fig1',
    degree: 2,
    points: EXAMPLE_POINTS.map((p) => [...p]),
    breaks: [...EXAMPLE_BREAKS],
    alphas: FIG1.map((r) => [...r]),
    r: 1,
    enforce: true,
    joint: 1,
    showCircles: true,
    showOriginal: true,
    showPolygon: true,
    u: 0,
    stepAlgo: 'remodel', // the stepper: 'remodel' (g → b* → g* on one segment) or 'casteljau' (g* at stepU)
    step: -1,            // its step (-1 = off)
    stepU: 1.375,        // the parameter of the steps (segment I = the one holding it)
    view: [],
    surface: { preset: 'fig5', alphas: SURFACE_PRESETS.fig5.alphas.map((r) => [...r]), r: 1, enforce: true, yaw: -60, pitch: 28, showOriginal: true, showNet: true, camera: [] },
    bi: biDefaults(), // surface tab, §4.2 (bi-degree): see mountBiSurface below
  };
}

const sub = (i) => String(i).replace(/\d/g, (d) => '₀₁₂₃₄₅₆₇₈₉'[d]);
const sup = (i) => String(i).replace(/\d/g, (d) => '⁰¹²³⁴⁵⁶⁷⁸⁹'[d]);
const alphaName = (k, I) => `α${sub(k)}${sup(`(${I})`).replace('(', '⁽').replace(')', '⁾')}`;
// "α_1^(2) = 1 − 2·α_4^(1)  (eq. 9)" (from the API) → "α₁⁽²⁾ = 1 − 2·α₄⁽¹⁾  (eq. 9)"
const prettyConstraint = (t) => String(t).replace(/α_(\d+)\^\((\d+)\)/g, (_, k, i) => alphaName(k, i));
const sci = (x) => (!Number.isFinite(x) ? String(x) : x === 0 ? '0' : Math.abs(x) >= 1e-3 && Math.abs(x) < 1e4 ? fmt(x, 4) : x.toExponential(1).replace('-', '−'));

export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);
  const locked = !!options.locked;

  // ---------- state sanity (a link may hold anything that passed the type check) ----------
  function sanitizeCurve() {
    const m = state.degree;
    const segs = state.breaks.length - 1;
    const ok = Number.isInteger(m) && m >= 1 && m <= 8 && segs >= 1 && segs <= 12 && state.points.length === m * segs + 1 &&
      state.alphas.length === segs && state.alphas.every((r) => Array.isArray(r) && r.length === m);
    if (!ok) {
      const d = defaults();
      Object.assign(state, { preset: d.preset, degree: d.degree, points: d.points, breaks: d.breaks, alphas: d.alphas, r: d.r });
    }
    state.r = Math.max(0, Math.min(Math.floor(state.degree / 2), Math.round(state.r) || 0));
    state.joint = Math.max(1, Math.min(state.breaks.length - 2, Math.round(state.joint) || 1));
    for (const row of state.alphas) for (let k = 0; k < row.length; k++) row[k] = clampAlpha(row[k]);
    limitLast();
    if (!['remodel', 'casteljau'].includes(state.stepAlgo)) state.stepAlgo = 'remodel';
    if (!Number.isInteger(state.step) || state.step < -1 || state.step > 12) state.step = -1;
    const [a, b] = [state.breaks[0], state.breaks[state.breaks.length - 1]];
    if (!(Number.isFinite(state.stepU) && state.stepU >= a && state.stepU <= b)) state.stepU = (state.breaks[0] + state.breaks[1]) / 2;
  }
  const clampAlpha = (a) => (Number.isFinite(a) ? Math.min(0.999, Math.max(0.001, a)) : 0.5);
  // with r ≥ 2, eq. (9) fixes entries p·α_m and 1 − p·α_m: they stay in (0, 1) only for α_m < 1/r
  const alphaMax = () => (state.enforce && state.r >= 2 ? 1 / state.r - 0.001 : 0.999);
  function limitLast() {
    const m = state.degree;
    for (const row of state.alphas) row[m - 1] = Math.min(row[m - 1], alphaMax());
  }
  function sanitizeSurface() {
    const s = state.surface;
    if (!(s.alphas.length === 3 && s.alphas.every((r) => Array.isArray(r) && r.length === 2))) s.alphas = defaults().surface.alphas;
    for (const row of s.alphas) for (let k = 0; k < 2; k++) row[k] = clampAlpha(row[k]);
    s.r = s.r === 0 ? 0 : 1;
    s.yaw = Math.max(-360, Math.min(360, s.yaw));
    s.pitch = Math.max(-89, Math.min(89, s.pitch));
  }

  let steps = null; // the stepper (built with the curve controls)

  // ---------- computed data (from wasm) ----------
  let res = null;       // bezierRemodel result
  let orig = null;      // bezierSpline result (the witness g)
  let fig3 = null;      // { xs, ks, printed, k0, joint, current }

  // "Play u": the evaluation point g*(u) runs along [u₀, u_L]
  let atU = null;
  const uRange = () => [state.breaks[0], state.breaks[state.breaks.length - 1]];
  function computeAtU() {
    const [a, b] = uRange();
    if (!(state.u >= a && state.u <= b)) state.u = a;
    try { const r = callRemodel({ at: [state.u] }); atU = [r.points[0], r.points[1]]; } catch (e) { atU = null; }
  }
  const uOut = readout({ label: 'Evaluation point', value: '—' });
  uOut.el.dataset.readout = 'u';
  const refreshU = () => uOut.set(atU ? `u = ${fmt(state.u, 3)}: g*(u) = (${fmt(atU[0], 3)}, ${fmt(atU[1], 3)})` : '—');
  const player = uPlayer({
    range: uRange, get: () => state.u,
    set(v) { state.u = v; computeAtU(); refreshU(); curvePlot.redraw(); },
    onPause() { ctx.save(); },
  });

  function callRemodel(extra) {
    return wasm.bezierRemodel({
      points: state.points, degree: state.degree, breaks: state.breaks, alphas: state.alphas,
      r: state.r, enforce: state.enforce, ...extra,
    });
  }

  function computeCurve() {
    try {
      res = callRemodel({ samples: 600 });
      // keep the α that were used (eq. 9 overwrote the fixed ones)
      state.alphas = res.alphas.map((row) => Array.from(row));
    } catch (e) { notify(e, 'error'); }
    try {
      orig = wasm.bezierSpline({ points: state.points, degree: state.degree, breaks: state.breaks, samples: 600 });
    } catch (e) { notify(e, 'error'); }
    computeFig3();
    computeSteps();
  }

  // ---------- the stepper's data (from wasm) ----------
  let dc = null; // bezierDeCasteljau on g* at stepU: { segment, t, levels[r] (flat), point }
  function computeSteps() {
    dc = null;
    if (!res) return;
    try { dc = wasm.bezierDeCasteljau({ points: res.controlPoints, degree: state.degree + 1, breaks: state.breaks, u: state.stepU }); } catch (e) { dc = null; }
  }

  // Fig. 3: K*(u_I) as α_m^(I−1) runs over (0, ½] (everything else as it is now), measured by the API
  function computeFig3() {
    fig3 = null;
    const m = state.degree, I = state.joint, segs = state.breaks.length - 1;
    if (I < 1 || I >= segs) return;
    const hi = Math.min(alphaMax(), Math.max(0.5, state.alphas[I - 1][m - 1] + 0.05));
    const xs = Array.from({ length: 61 }, (_, j) => 0.004 + (hi - 0.004) * j / 60);
    try {
      // one call for the whole sweep (was one bezierRemodel call per α)
      const r = wasm.bezierRemodel({ points: state.points, degree: m, breaks: state.breaks, alphas: state.alphas, r: state.r, enforce: state.enforce, at: [], alphaSweep: xs, alphaSweepJoint: I });
      const ks = Array.from(r.sweepCurvature), printed = Array.from(r.sweepCurvaturePrinted);
      fig3 = { xs, ks, printed, k0: res ? res.curvatureOriginal[I] : NaN, joint: I, hi };
    } catch (e) { notify(e, 'error'); }
  }

  // ---------- layout: tabs ----------
  const curvePanel = h('div', { class: 'bezier-curve-panel' });
  const surfacePanel = h('div', { class: 'bezier-surface-panel' });
  const curveCtl = h('div');
  const surfaceCtl = h('div');
  L.plots.append(curvePanel, surfacePanel);

  // ---------- curve plot ----------
  const curvePlot = createPlot(curvePanel, {
    ariaLabel: 'Remodelled Bézier spline g* (solid), the given spline g (dotted), draggable control points of g, osculating circles at the breakpoints',
    equal: true, height: 540, locked,
    view: { xmin: -10, xmax: 13, ymin: -4, ymax: 23 },
    describe: () => res ? `Degree ${state.degree} spline with ${state.breaks.length - 1} segments remodelled to degree ${state.degree + 1}. Curvature at the breakpoints: ${Array.from(res.curvature).map((k, i) => `u${sub(i)}: ${fmt(k, 4)}`).join(', ')}.` : '',
    onView(v) { state.view = [v.xmin, v.xmax, v.ymin, v.ymax]; ctx.save(); },
    draw(g, plot) {
      if (state.showCircles && res) {
        const c = res.osculatingCentres, rad = res.osculatingRadii;
        for (let i = 0; i < rad.length; i++) {
          if (!circleDrawn(i)) continue;
          const n = 120, ring = new Float64Array(2 * (n + 1));
          for (let j = 0; j <= n; j++) { const t = 2 * Math.PI * j / n; ring[2 * j] = c[2 * i] + rad[i] * Math.cos(t); ring[2 * j + 1] = c[2 * i + 1] + rad[i] * Math.sin(t); }
          plot.polyline(ring, { color: circleColor(i), width: 1.5, alpha: CIRCLE_ALPHA });
        }
      }
      if (state.showPolygon) {
        plot.polyline(state.points, { color: PALETTE.polygon, width: 1.5, dash: [8, 6] });
        if (res) plot.polyline(res.controlPoints, { color: PALETTE.second, width: 1.25, alpha: 0.8 });
      }
      if (state.showOriginal && orig) plot.polyline(orig.points, { color: PALETTE.ink, width: 2.5, dash: [2, 6] });
      if (res) plot.polyline(res.points, { color: PALETTE.curve, width: 3.5 });
      drawStepLines(plot);
    },
    drawOver(g, plot) {
      if (!res) return;
      drawStepMarks(plot);
      if (state.showPolygon) plot.points(res.controlPoints, { color: PALETTE.second, radius: 3.5, shape: 'square' });
      if (atU && (player.playing || state.u > state.breaks[0])) {
        plot.points([atU], { color: PALETTE.ink, radius: 6, shape: 'diamond', stroke: '#fff' });
        plot.label(atU[0], atU[1], `g*(${fmt(state.u, 2)})`, { offset: [10, -12] });
      }
      // breakpoints b_{mI} = b*_{(m+1)I} with their curvature
      const m1 = state.degree + 1, cp = res.controlPoints;
      for (let i = 0; i < res.curvature.length; i++) {
        const x = cp[2 * m1 * i], y = cp[2 * m1 * i + 1];
        plot.points([[x, y]], { color: PALETTE.ink, radius: 5, shape: 'diamond', stroke: '#fff' });
        plot.label(x, y, `u${sub(i)}`, { offset: [8, 16], baseline: 'top', font: '600 14px system-ui, sans-serif' });
      }
    },
  });
  curvePlot.canvas.dataset.plot = 'curve';
  curvePlot.addHandles({
    name: 'control point',
    points: () => state.points,
    label: (i) => (i % state.degree === 0 ? '' : `b${sub(i)}`),
    labelOf: (i) => `Control point b${i}`,
    radius: 7,
    move(i, q) { state.points[i] = [q[0], q[1]]; state.preset = 'custom'; update(); },
    end() { ctx.save(); },
  });
  // the legend follows the drawing (same colours and dashes as the polylines above; one entry per circle drawn)
  const CIRCLE_ALPHA = 0.75;
  // circle colours distinct from the curve (blue), g (black), the control points (vermillion) and b* (green)
  const CIRCLE_COLORS = ['#CC79A7', '#E69F00', '#56B4E9', '#882255', '#999933', '#332288'];
  const circleColor = (i) => CIRCLE_COLORS[i % CIRCLE_COLORS.length];
  // one circle, at the joint chosen for Fig. 3 (all of them at once cover the curve they explain)
  const circleDrawn = (i) => i === state.joint && res && res.osculatingRadii[i] > 0 && res.osculatingRadii[i] <= 200;
  const legendEl = legend([]);
  legendEl.dataset.legendFor = 'curve';
  function refreshLegend() {
    const circles = [];
    if (state.showCircles && res) {
      for (let i = 0; i < res.osculatingRadii.length; i++) {
        if (circleDrawn(i)) circles.push({ label: `osculating circle at u${sub(i)}`, color: circleColor(i), alpha: CIRCLE_ALPHA });
      }
    }
    setLegendItems(legendEl, [
      { label: 'remodelled g* (degree m + 1)', color: PALETTE.curve },
      state.showOriginal && { label: 'given g (witness)', color: PALETTE.ink, kind: 'dotted', dash: [2, 6] },
      { label: 'control points bᵢ of g (drag)', color: PALETTE.control, kind: 'dot' },
      state.showPolygon && { label: 'control polygon of g', color: PALETTE.polygon, kind: 'dashed', dash: [8, 6] },
      state.showPolygon && { label: 'control polygon b*ᵢ of g*', color: PALETTE.second, alpha: 0.8 },
      ...circles,
    ]);
  }
  curvePanel.appendChild(legendEl);

  // ---------- Fig. 3 plot ----------
  const fig3Title = h('h3', { class: 'plot-title', style: { margin: '0.5rem 0 0', fontSize: '1.05rem' } });
  curvePanel.appendChild(fig3Title);
  const fig3Plot = createPlot(curvePanel, {
    ariaLabel: 'Fig. 3: curvature K* at a joint against the parameter αₘ of the previous segment',
    height: 250, pan: false, zoom: false, xLabel: 'αₘ⁽ᴵ⁻¹⁾', yLabel: 'K* at joint I',
    view: { xmin: 0, xmax: 0.55, ymin: 0, ymax: 1 },
    describe: () => fig3 ? `K* at u${sub(fig3.joint)} falls from ${fmt(fig3.ks[0], 3)} to ${fmt(fig3.ks[fig3.ks.length - 1], 3)} as αₘ grows; K = ${fmt(fig3.k0, 3)}.` : 'No interior joint.',
    draw(g, plot) {
      if (!fig3) return;
      const m = state.degree, line = new Float64Array(2 * fig3.xs.length), pr = new Float64Array(2 * fig3.xs.length);
      for (let j = 0; j < fig3.xs.length; j++) { line[2 * j] = fig3.xs[j]; line[2 * j + 1] = fig3.ks[j]; pr[2 * j] = fig3.xs[j]; pr[2 * j + 1] = fig3.printed[j]; }
      plot.hline(fig3.k0, { color: PALETTE.ink, dash: [2, 5], width: 2 });
      plot.label(fig3.hi, fig3.k0, `K(u${sub(fig3.joint)}) = ${fmt(fig3.k0, 3)}`, { align: 'right', offset: [-4, -4] });
      plot.vline(1 / (m + 1), { color: PALETTE.muted, dash: [5, 5], width: 1.5 });
      plot.label(1 / (m + 1), 0, `1/(m+1)`, { offset: [4, -6], color: '#555', font: '12px system-ui, sans-serif' });
      if (state.r < 2) {
        plot.polyline(pr, { color: PALETTE.accent, width: 2.5, dash: [8, 5] });
        const j = Math.round(fig3.xs.length * 0.15);
        plot.label(pr[2 * j], pr[2 * j + 1], '(15) as printed', { color: '#9a5b00', offset: [6, -6], font: '600 12px system-ui, sans-serif' });
      }
      plot.polyline(line, { color: PALETTE.curve, width: 3 });
    },
    drawOver(g, plot) {
      if (!fig3 || !res) return;
      const a = state.alphas[fig3.joint - 1][state.degree - 1];
      plot.points([[a, res.curvature[fig3.joint]]], { color: PALETTE.control, radius: 6, stroke: '#fff' });
    },
  });
  fig3Plot.canvas.dataset.plot = 'fig3';
  function fitFig3() {
    if (!fig3) return;
    const ymax = Math.max(fig3.k0, ...fig3.ks.filter(Number.isFinite), ...(state.r < 2 ? fig3.printed.filter(Number.isFinite) : [])) * 1.15 || 1;
    fig3Plot.setView({ xmin: 0, xmax: fig3.hi * 1.04, ymin: -0.06 * ymax, ymax });
  }

  // ---------- curve controls ----------
  const presetCtl = buttonGroup({ label: 'Example', options: CURVE_PRESETS, value: state.preset, onChange: applyPreset });
  const rCtl = buttonGroup({ label: 'Keep Cʳ: r', options: [0, 1, 2, 3, 4].map((v) => ({ value: v, label: String(v) })), value: state.r, onChange(v) { state.r = v; limitLast(); update(); ctx.save(); } });
  const enforceCtl = toggle({ label: 'Enforce eq. (9)', value: state.enforce, hint: 'Off: every α is free and g* generally loses C¹ (see the jumps).', onChange(v) { state.enforce = v; limitLast(); update(); ctx.save(); } });
  const jointCtl = buttonGroup({ label: 'Fig. 3 at joint I', options: [1], value: state.joint, onChange(v) { state.joint = v; computeFig3(); fitFig3(); fig3Plot.redraw(); refreshTitles(); refreshLegend(); curvePlot.redraw(); ctx.save(); } });
  const circlesCtl = toggle({ label: 'Osculating circle at joint I', value: state.showCircles, onChange(v) { state.showCircles = v; refreshLegend(); curvePlot.redraw(); ctx.save(); } });
  const origCtl = toggle({ label: 'Given curve g (dotted)', value: state.showOriginal, onChange(v) { state.showOriginal = v; refreshLegend(); curvePlot.redraw(); ctx.save(); } });
  const polyCtl = toggle({ label: 'Control polygons', value: state.showPolygon, onChange(v) { state.showPolygon = v; refreshLegend(); curvePlot.redraw(); ctx.save(); } });
  const alphaBox = h('div', { class: 'alpha-sliders' });
  const curvTable = table({ caption: 'Curvature at the breakpoints', columns: ['I', 'K (13)', 'K* (14)', 'K* measured', 'K* (15) right-sided', '(15) printed'], digits: 5 });
  curvTable.el.dataset.role = 'curvature';
  const contTable = table({ caption: 'Jumps of g*⁽ⁱ⁾ at the joints', columns: ['I'], digits: 3 });
  const status = h('p', { class: 'ctl-hint', 'aria-live': 'polite' });
  // ---------- step by step ----------
  const ALGOS = { remodel: 'Remodelling one segment (eq. 6)', casteljau: 'de Casteljau on g* at u' };
  const algoCtl = buttonGroup({
    label: 'Algorithm', options: [{ value: 'remodel', label: 'Remodel g → g*' }, { value: 'casteljau', label: 'de Casteljau' }], value: state.stepAlgo,
    onChange(v) { state.stepAlgo = v; if (state.step >= 0) state.step = 0; steps.setTitle(ALGOS[v]); steps.refresh(); curvePlot.redraw(); ctx.save(); },
  });
  const stepUCtl = slider({
    label: 'Parameter u of the steps', min: state.breaks[0], max: state.breaks[state.breaks.length - 1], step: 0.001, value: state.stepU, number: true,
    hint: 'The segment I that holds u is the one remodelled and evaluated.',
    onInput(v) { state.stepU = v; computeSteps(); steps.refresh(); curvePlot.redraw(); },
    onChange() { ctx.save(); },
  });
  steps = stepper({
    title: ALGOS[state.stepAlgo],
    steps: () => (state.stepAlgo === 'casteljau' ? casteljauSteps() : remodelSteps()),
    get: () => state.step,
    set(i) { state.step = i; curvePlot.redraw(); ctx.save(); },
  });

  curveCtl.append(
    group('Curve', presetCtl.el, rCtl.el, enforceCtl.el, status),
    group('Show', jointCtl.el, circlesCtl.el, origCtl.el, polyCtl.el, h('div', { class: 'ctl-added' }, row(player.el), uOut.el)),
    group('Step by step', algoCtl.el, stepUCtl.el, steps.el),
    group('Parameters α (eq. 6)', alphaBox),
  );
  // "Use my data" (www/lib/data-import.js): your Bézier control points (degree m: m·L + 1 points, breaks 0..L,
  // the classical α, so g* = g until you move them)
  if (!locked) curveCtl.append(group('Your data', dataImport({ label: 'Use my control points', apply: 'Use these points', min: 3, max: 12 * 8 + 1, onData(pts) {
    const m = state.degree, L = (pts.length - 1) / m;
    if (!Number.isInteger(L) || L < 1 || L > 12) throw new Error(`a Bézier spline of degree ${m} has m·L + 1 control points (${[1, 2, 3, 4].map((k) => k * m + 1).join(', ')}, …, L ≤ 12), got ${pts.length}`);
    Object.assign(state, { preset: 'custom', points: pts, breaks: Array.from({ length: L + 1 }, (_, i) => i), r: 1, enforce: true, joint: 1,
      alphas: Array.from({ length: L }, () => Array.from({ length: m }, (_, k) => (m - k) / (m + 1))) });
    sanitizeCurve(); refreshCurveControls(); update();
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 40); ctx.save();
  } }).el));
  // the number tables are wide: they go under the plots
  curvePanel.insertBefore(h('div', { class: 'bezier-tables', style: { display: 'flex', flexWrap: 'wrap', gap: '0.5rem 1.5rem', alignItems: 'flex-start' } }, curvTable.el, contTable.el), fig3Title);

  let sliders = [];   // [I][k] → slider
  let sliderShape = '';
  function buildSliders() {
    const m = state.degree, segs = state.breaks.length - 1;
    const shape = `${m}x${segs}`;
    if (shape === sliderShape) return;
    sliderShape = shape;
    clear(alphaBox);
    sliders = [];
    for (let I = 0; I < segs; I++) {
      const row = [];
      const box = h('div', { class: 'alpha-segment', style: { borderTop: '1px solid #ddd', paddingTop: '0.25rem', marginTop: '0.25rem' } },
        h('div', { style: { fontWeight: '600' } }, `Segment I = ${I}  [u${sub(I)}, u${sub(I + 1)}]`));
      for (let k = 1; k <= m; k++) {
        const s = slider({
          label: alphaName(k, I), min: 0.001, max: 0.999, step: 0.001, value: state.alphas[I][k - 1], number: true,
          format: (v) => fmt(v, 4),
          onInput(v) { state.alphas[I][k - 1] = v; state.preset = 'custom'; update({ quick: true }); },
          onChange() { update(); ctx.save(); },
        });
        s.el.dataset.alpha = `${I},${k}`;
        const hint = h('div', { class: 'ctl-hint alpha-constraint' });
        s.el.appendChild(hint);
        s.hint = hint;
        row.push(s);
        box.appendChild(s.el);
      }
      sliders.push(row);
      alphaBox.appendChild(box);
    }
  }

  function refreshSliders() {
    if (!res) return;
    const m = state.degree;
    const free = res.free, cons = res.constraints;
    for (let I = 0; I < sliders.length; I++) {
      for (let k = 1; k <= m; k++) {
        const s = sliders[I][k - 1];
        const isFree = free[I][k - 1];
        s.setRange({ max: k === m ? alphaMax() : 0.999 });
        s.set(state.alphas[I][k - 1]);
        s.setDisabled(locked || !isFree);
        s.el.querySelector('.ctl-track').style.opacity = isFree ? '1' : '0.45';
        s.el.querySelector('label').style.color = isFree ? '' : '#595959';
        s.el.dataset.free = String(isFree);
        s.hint.textContent = isFree ? '' : `fixed: ${prettyConstraint(cons[I][k - 1])}`;
      }
    }
  }

  function refreshTables() {
    if (!res) return;
    const rows = [];
    for (let i = 0; i < res.curvature.length; i++) {
      rows.push([`u${sub(i)} = ${fmt(state.breaks[i], 3)}`, res.curvatureOriginal[i], res.curvature[i], res.curvatureMeasured[i], res.curvaturePredicted[i], res.curvaturePrinted[i]]);
    }
    curvTable.set(rows);
    const r = state.r;
    const cols = ['I'];
    for (let i = 0; i <= r + 1; i++) cols.push(`d${sub(i)}${i <= r ? '' : ' (r+1)'}`);
    const head = contTable.el.querySelector('thead tr');
    clear(head);
    append(head, cols.map((c) => h('th', { scope: 'col' }, c)));
    contTable.set(Array.from(res.continuity, (row, j) => [String(j + 1), ...Array.from(row, sci)]));
    const scale = res.continuityScale;
    let worst = 0;
    for (const row of res.continuity) for (let i = 0; i <= r; i++) worst = Math.max(worst, row[i] / scale[i]);
    const origRes = res.crResidualOriginal;
    status.textContent = `g is degree ${state.degree} on ${state.breaks.length - 1} segments; g* has degree ${state.degree + 1}. ` +
      `C${sup(r)} conditions (8): residual ${sci(res.crResidual)} (g: ${sci(origRes)}); largest relative jump of orders ≤ r: ${sci(worst)} — ` +
      (worst < 1e-9 ? `g* is C${sup(r)} ✓` : `g* is not C${sup(r)}`) + '.';
  }

  const num = (x, d = 3) => fmt(x, d);
  const at = (flat, j) => [flat[2 * j], flat[2 * j + 1]];
  const pt = (q) => `(${num(q[0])}, ${num(q[1])})`;
  const LEVEL = ['#6b6b6b', '#E69F00', '#009E73', '#CC79A7', '#0072B2', '#882255', '#56B4E9', '#000000'];

  function remodelSteps() {
    if (!res || !dc) return [];
    const m = state.degree, I = dc.segment, B = state.breaks, cp = res.controlPoints;
    const al = Array.from(res.alphas[I]);
    const out = [{
      label: `segment I = ${I} of g (degree ${m})`,
      tex: [
        `g(u) = \\sum_{k=0}^{${m}} B_{${m},k}(t)\\,b_{${m * I}+k}, \\quad t = \\frac{u - u_{${I}}}{u_{${I + 1}} - u_{${I}}}`,
        `u \\in [u_{${I}}, u_{${I + 1}}] = [${num(B[I])}, ${num(B[I + 1])}]: \\; b_{${m * I}}, \\ldots, b_{${m * I + m}}`,
      ],
      note: `The ${m + 1} control points of this segment (ringed). g* gets ${m + 2}: the ends stay, the ${m} inner ones slide along the legs.`,
    }];
    for (let k = 1; k <= m; k++) {
      const a = al[k - 1], j = (m + 1) * I + k, fixed = res.free && !res.free[I][k - 1];
      out.push({
        label: `the new point b*${mathText(`_{${j}}`)} (k = ${k} of ${m})`,
        tex: [
          `b^{*}_{(m+1)I+k} = (1 - \\alpha^{(I)}_{k})\\,b_{mI+k-1}`,
          `\\qquad + \\alpha^{(I)}_{k}\\,b_{mI+k}`,
          `\\alpha^{(${I})}_{${k}} = ${num(a, 4)} \\quad (\\text{classical}\\; \\frac{m+1-k}{m+1} = \\frac{${m + 1 - k}}{${m + 1}})`,
          `b^{*}_{${j}} = ${num(1 - a, 4)}\\,b_{${m * I + k - 1}} + ${num(a, 4)}\\,b_{${m * I + k}} = ${pt(at(cp, j))}`,
        ],
        note: fixed ? `This α is fixed by eq. (9) to keep the class: ${prettyConstraint(res.constraints[I][k - 1])}.` : 'This α is free: its slider moves the point along the leg.',
      });
    }
    out.push({
      label: `the remodelled segment of g* (degree ${m + 1})`,
      tex: [
        `b^{*}_{${(m + 1) * I}} = b_{${m * I}}, \\quad b^{*}_{${(m + 1) * (I + 1)}} = b_{${m * (I + 1)}}`,
        `g^{*}(u) = \\sum_{k=0}^{${m + 1}} B_{${m + 1},k}(t)\\,b^{*}_{${(m + 1) * I}+k}`,
      ],
      note: 'Same breakpoints, one degree more; with the classical α it is the same curve as g.',
    });
    return out;
  }

  function casteljauSteps() {
    if (!dc) return [];
    const M = dc.levels.length - 1, I = dc.segment, B = state.breaks, u = num(state.stepU);
    const out = [{
      label: `segment I = ${I} of g* at u = ${u}`,
      tex: [
        `t = \\frac{u - u_{${I}}}{u_{${I + 1}} - u_{${I}}} = \\frac{${u} - ${num(B[I])}}{${num(B[I + 1])} - ${num(B[I])}} = ${num(dc.t, 4)}`,
        `b^{0}_{k} = b^{*}_{${(M) * I}+k}, \\quad k = 0, \\ldots, ${M}`,
      ],
      note: `The ${M + 1} control points of the segment of g* are level 0.`,
    }];
    for (let r = 1; r <= M; r++) {
      const L0 = dc.levels[r];
      const lines = [`b^{${r}}_{k} = (1 - t)\\,b^{${r - 1}}_{k} + t\\,b^{${r - 1}}_{k+1}`, `\\qquad = ${num(1 - dc.t, 4)}\\,b^{${r - 1}}_{k} + ${num(dc.t, 4)}\\,b^{${r - 1}}_{k+1}`];
      for (let k = 0; k < L0.length / 2; k++) lines.push(`b^{${r}}_{${k}} = ${pt(at(L0, k))}`);
      if (r === M) lines.push(`g^{*}(${u}) = b^{${M}}_{0} = ${pt(at(dc.point, 0))}`);
      out.push({ label: r === M ? `level ${r} of ${M}: the curve point` : `level ${r} of ${M}`, tex: lines,
        note: r === M ? 'The last level is the point g*(u) (the diamond); the two points of the level before span the tangent there.' : 'Every leg of the level before is cut in the ratio t : (1 − t).' });
    }
    return out;
  }

  function drawStepLines(plot) {
    const s = state.step;
    if (s < 0 || !res || !dc) return;
    const m = state.degree, I = dc.segment, cp = res.controlPoints;
    if (state.stepAlgo === 'remodel') {
      plot.polyline(state.points.slice(m * I, m * I + m + 1), { color: PALETTE.accent, width: 5, alpha: s === 0 ? 0.7 : 0.35 });
      if (s >= 1 && s <= m) plot.polyline([state.points[m * I + s - 1], state.points[m * I + s]], { color: PALETTE.control, width: 4 });
      if (s === m + 1) {
        const seg = [];
        for (let k = 0; k <= m + 1; k++) seg.push(at(cp, (m + 1) * I + k));
        plot.polyline(seg, { color: PALETTE.second, width: 3 });
        const P = res.params, X = res.points, part = [];
        for (let j = 0; j < P.length; j++) if (P[j] >= state.breaks[I] && P[j] <= state.breaks[I + 1]) part.push([X[2 * j], X[2 * j + 1]]);
        plot.polyline(part, { color: PALETTE.curve, width: 7, alpha: 0.45 });
      }
    } else {
      for (let r = 0; r <= Math.min(s, dc.levels.length - 1); r++) {
        if (dc.levels[r].length >= 4) plot.polyline(dc.levels[r], { color: LEVEL[r % LEVEL.length], width: r === s ? 3.5 : 2, alpha: r === s ? 1 : 0.6 });
      }
    }
  }

  function drawStepMarks(plot) {
    const s = state.step;
    if (s < 0 || !res || !dc) return;
    const m = state.degree, I = dc.segment, cp = res.controlPoints, font = '600 13px system-ui, sans-serif';
    if (state.stepAlgo === 'remodel') {
      if (s === 0) plot.points(state.points.slice(m * I, m * I + m + 1), { color: PALETTE.accent, radius: 11, hollow: true });
      const ks = s === m + 1 ? Array.from({ length: m + 2 }, (_, k) => k) : Array.from({ length: Math.min(s, m) }, (_, j) => j + 1);
      for (const k of ks) {
        const q = at(cp, (m + 1) * I + k);
        plot.points([q], { color: PALETTE.second, radius: k === s ? 7 : 5, shape: 'square', stroke: '#fff' });
        if (k >= 1 && k <= m) plot.label(q[0], q[1], mathText(`b^{*}_{${(m + 1) * I + k}}`), { color: '#0b5e45', offset: [10, -10], font });
      }
    } else {
      for (let r = 0; r <= Math.min(s, dc.levels.length - 1); r++) {
        const Lr = dc.levels[r], last = r === dc.levels.length - 1;
        for (let k = 0; k < Lr.length / 2; k++) {
          const q = at(Lr, k);
          plot.points([q], { color: LEVEL[r % LEVEL.length], radius: r === s ? 6 : 4, shape: last ? 'diamond' : 'circle', stroke: '#fff' });
          if (r === s && r > 0) plot.label(q[0], q[1], mathText(`b^{${r}}_{${k}}`), { color: '#222', offset: [8, -8], font });
        }
      }
    }
  }

  function refreshTitles() {
    fig3Title.textContent = fig3 ? `Fig. 3 (live): K*(u${sub(fig3.joint)}) against ${alphaName(state.degree, fig3.joint - 1)}, the other α as set` : 'Fig. 3: needs an interior joint';
  }

  function refreshCurveControls() {
    presetCtl.set(state.preset);
    rCtl.set(state.r);
    rCtl.inputs.forEach((inp, k) => { inp.disabled = locked || k > Math.floor(state.degree / 2); });
    enforceCtl.set(state.enforce);
    const segs = state.breaks.length - 1;
    const jl = [];
    for (let i = 1; i < segs; i++) jl.push(i);
    // rebuild the joint choice when the number of joints changes
    if (jointCtl.inputs.length !== jl.length) {
      const fresh = buttonGroup({ label: 'Fig. 3 at joint I', options: jl.map((v) => ({ value: v, label: String(v) })), value: state.joint, onChange(v) { state.joint = v; computeFig3(); fitFig3(); fig3Plot.redraw(); refreshTitles(); refreshLegend(); curvePlot.redraw(); ctx.save(); } });
      jointCtl.el.replaceWith(fresh.el);
      Object.assign(jointCtl, fresh);
    }
    jointCtl.set(state.joint);
    circlesCtl.set(state.showCircles); origCtl.set(state.showOriginal); polyCtl.set(state.showPolygon);
  }

  function update({ quick = false } = {}) {
    computeCurve();
    buildSliders();
    refreshSliders();
    refreshTables();
    refreshTitles();
    refreshLegend();
    computeAtU(); refreshU();
    steps?.refresh();
    if (!quick) fitFig3();
    curvePlot.redraw();
    fig3Plot.redraw();
  }

  function applyPreset(p) {
    state.preset = p;
    if (p === 'quartic') {
      try {
        const b = wasm.bsplineToBezier(QUARTIC);
        state.degree = b.degree;
        state.points = b.points.map((q) => [q[0], q[1]]);
        state.breaks = Array.from(b.breaks);
        const m = state.degree;
        state.alphas = state.breaks.slice(1).map(() => Array.from({ length: m }, (_, k) => (m - k) / (m + 1)));
        state.r = 2;
        state.enforce = true;
        state.joint = 1;
      } catch (e) { notify(e, 'error'); return; }
    } else {
      state.degree = 2;
      state.points = EXAMPLE_POINTS.map((q) => [...q]);
      state.breaks = [...EXAMPLE_BREAKS];
      state.alphas = (p === 'fig2' ? FIG2 : p === 'fig1' ? FIG1 : FIG1.map(() => [2 / 3, 1 / 3])).map((r) => [...r]);
      state.r = 1;
      state.enforce = true;
      state.joint = Math.min(state.joint, 4);
    }
    sanitizeCurve();
    stepUCtl.setRange({ min: state.breaks[0], max: state.breaks[state.breaks.length - 1] });
    stepUCtl.set(state.stepU);
    refreshCurveControls();
    update();
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 40);
    ctx.save();
  }

  // ---------- surface tab ----------
  // a WebGL2 view (www/lib/view3d.js): drag to orbit, wheel/pinch to zoom, F to frame
  const view = new View3D(surfacePanel, {
    height: 460, locked: true,
    ariaLabel: 'Remodelled Bézier spline surface G* (shaded, with isolines), the joint lines u = 1, 2, its control net and the given surface G',
    onViewChange(v) { state.surface.yaw = v.yaw; state.surface.pitch = v.pitch; state.surface.camera = [v.distance, ...v.target]; ctx.save(); },
  });
  view.canvas.dataset.plot = 'surface';
  const surfLegend = h('ul', { class: 'legend', 'aria-label': 'Legend' },
    h('li', null, h('span', { class: 'swatch', style: { background: '#56B4E9' } }), 'G* (degree 3 in u, 3 in v) with isolines'),
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.control } }), 'joint lines u = 1, 2'),
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.second } }), 'control net b*ₖ,ₗ of G*'),
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.ink } }), 'given G (lines v = const)'));
  surfacePanel.appendChild(surfLegend);
  // §4.2, the bi-degree remodelling: its own controls, readouts and legend, drawn in the same view
  const bi = mountBiSurface({ wasm, state, ctx, notify, view, locked });
  surfacePanel.appendChild(bi.legend);

  let sres = null, sorig = null;
  const NU = 61, NV = 17;
  function computeSurface() {
    const s = state.surface;
    try {
      sres = wasm.bezierRemodelSurface({ points: SURFACE_POINTS, degreeU: 2, degreeV: 3, breaksU: [0, 1, 2, 3], alphas: s.alphas, r: s.r, enforce: s.enforce, samplesU: NU, samplesV: NV, mesh: true });
      s.alphas = sres.alphas.map((row) => Array.from(row));
    } catch (e) { notify(e, 'error'); }
    if (!sorig) {
      try {
        sorig = wasm.bezierRemodelSurface({ points: SURFACE_POINTS, degreeU: 2, degreeV: 3, breaksU: [0, 1, 2, 3], samplesU: NU, samplesV: NV });
      } catch (e) { notify(e, 'error'); }
    }
  }
  // polylines of a u-major NU × NV grid (flat xyz): along u at every `kv`-th v, or along v at the given iu
  const alongU = (pts, kv) => {
    const out = [];
    for (let iv = 0; iv < NV; iv += kv) { const l = []; for (let iu = 0; iu < NU; iu++) { const k = 3 * (iu * NV + iv); l.push([pts[k], pts[k + 1], pts[k + 2]]); } out.push(l); }
    return out;
  };
  const alongV = (pts, iu) => { const l = []; for (let iv = 0; iv < NV; iv++) { const k = 3 * (iu * NV + iv); l.push([pts[k], pts[k + 1], pts[k + 2]]); } return l; };
  function drawSurface() {
    const s = state.surface;
    if (!sres) return;
    try {
      view.setMesh('G*', sres.mesh, { color: '#56B4E9', isolines: { every: [5, 2], width: 1 } });
      view.setLines('joints', [alongV(sres.points, 20), alongV(sres.points, 40)], { color: PALETTE.control, width: 4 }); // u = 1, 2
      const cp = sres.controlPoints, rows = sres.rows, cols = sres.cols, net = [];
      const P = (k, l) => [cp[3 * (k * cols + l)], cp[3 * (k * cols + l) + 1], cp[3 * (k * cols + l) + 2]];
      for (let k = 0; k < rows; k++) net.push(Array.from({ length: cols }, (_, l) => P(k, l)));
      for (let l = 0; l < cols; l++) net.push(Array.from({ length: rows }, (_, k) => P(k, l)));
      view.setLines('net', net, { color: PALETTE.second, width: 1.5, opacity: 0.85, visible: s.showNet });
      view.setPoints('b*', cp, { color: PALETTE.second, size: 7, pickable: false, visible: s.showNet });
      if (sorig) view.setLines('G', alongU(sorig.points, 4), { color: PALETTE.ink, width: 1.5, opacity: 0.7, visible: s.showOriginal });
    } catch (e) { notify(e, 'error'); }
  }
  let cameraSet = false;
  function frameSurface() {
    view.fit();
    const c = state.surface.camera;   // zoom and target [d, x, y, z] kept in the link ([] = frame the surface)
    if (!cameraSet) {
      cameraSet = true; view.setView({ yaw: state.surface.yaw, pitch: state.surface.pitch }); view.fit();
      if (Array.isArray(c) && c.length === 4 && c.every(Number.isFinite) && c[0] > 0) view.setView({ distance: c[0], target: c.slice(1) });
    } else state.surface.camera = [];
    view.render();
  }

  const surfPresetCtl = buttonGroup({
    label: 'Example (§4)', options: Object.entries(SURFACE_PRESETS).map(([value, p]) => ({ value, label: p.label.split(':')[0] })), value: state.surface.preset,
    onChange(p) {
      const s = state.surface, pr = SURFACE_PRESETS[p];
      s.preset = p; s.alphas = pr.alphas.map((r) => [...r]); s.enforce = pr.enforce; s.r = 1;
      surfUpdate(); ctx.save();
    },
  });
  const surfPresetNote = h('p', { class: 'ctl-hint' });
  const surfRCtl = buttonGroup({ label: 'Keep Cʳ in u: r', options: [0, 1].map((v) => ({ value: v, label: String(v) })), value: state.surface.r, onChange(v) { state.surface.r = v; surfUpdate(); ctx.save(); } });
  const surfEnforceCtl = toggle({ label: 'Enforce eq. (19)', value: state.surface.enforce, onChange(v) { state.surface.enforce = v; surfUpdate(); ctx.save(); } });
  const surfOrigCtl = toggle({ label: 'Given surface G (black lines)', value: state.surface.showOriginal, onChange(v) { state.surface.showOriginal = v; view.setVisible('G', v); ctx.save(); } });
  const surfNetCtl = toggle({ label: 'Control net of G*', value: state.surface.showNet, onChange(v) { state.surface.showNet = v; view.setVisible('net', v); view.setVisible('b*', v); ctx.save(); } });
  const resetViewBtn = button({ label: 'Reset view', onClick() { view.resetView(); } });
  const surfAlphaBox = h('div');
  const surfSliders = [];
  for (let I = 0; I < 3; I++) {
    const row = [];
    for (let k = 1; k <= 2; k++) {
      const s = slider({
        label: `${alphaName(k, I)} (every l)`, min: 0.001, max: 0.999, step: 0.001, value: state.surface.alphas[I][k - 1], number: true, format: (v) => fmt(v, 4),
        onInput(v) { state.surface.alphas[I][k - 1] = v; state.surface.preset = 'custom'; surfUpdate(); },
        onChange() { ctx.save(); },
      });
      const hint = h('div', { class: 'ctl-hint' });
      s.el.appendChild(hint); s.hint = hint;
      row.push(s);
      surfAlphaBox.appendChild(s.el);
    }
    surfSliders.push(row);
  }
  const surfCont = table({ caption: 'Jumps of ∂ⁱG*/∂uⁱ across the joint lines', columns: ['I', 'd₀', 'd₁', 'd₂'], digits: 3 });
  const surfTable = table({ caption: 'Control points bₖ,ₗ of G (§4 table): z values', columns: ['k \\ l', '0', '1', '2', '3'], digits: 2, rows: SURFACE_POINTS.map((row, k) => [String(k), ...row.map((p) => p[2])]) });
  const constructionCtl = buttonGroup({
    label: 'Construction', value: state.bi.on ? 'bi' : 'u',
    options: [{ value: 'u', label: 'Degree in u (§4.1)' }, { value: 'bi', label: 'Bi-degree, u and v (§4.2)' }],
    onChange(v) { state.bi.on = v === 'bi'; showConstruction(); frameSurface(); ctx.save(); },
  });
  const uOnlyBox = h('div', null,
    group('Surface', surfPresetCtl.el, surfPresetNote, surfRCtl.el, surfEnforceCtl.el),
    group('Parameters α (eq. 17)', surfAlphaBox),
    group('Continuity in u', surfCont.el));
  const uDataBox = h('div', null,
    group('Data', surfTable.el, h('p', { class: 'ctl-hint' }, 'x = k, y ∈ {0, 1, 3, 4}; breakvalues u = 0, 1, 2, 3 and v = 0, 1; degrees m = 2, n = 3.')));
  surfaceCtl.append(
    constructionCtl.el,
    uOnlyBox,
    bi.controls,
    group('View', surfOrigCtl.el, surfNetCtl.el, resetViewBtn.el, h('p', { class: 'ctl-hint' }, 'Drag to turn the surface, wheel or pinch to zoom (click the view first), F to frame it.')),
    uDataBox,
  );
  // shows the §4.1 or the §4.2 construction (same view, same object names, so the View toggles serve both)
  function showConstruction() {
    const on = !!state.bi.on;
    constructionCtl.set(on ? 'bi' : 'u');
    for (const el of [uOnlyBox, uDataBox, surfLegend]) el.style.display = on ? 'none' : '';
    for (const el of [bi.controls, bi.legend]) el.style.display = on ? '' : 'none';
    if (on) bi.update(); else drawSurface();
    view.render();
  }

  function surfUpdate() {
    computeSurface();
    const s = state.surface;
    surfPresetCtl.set(s.preset);
    surfRCtl.set(s.r);
    surfEnforceCtl.set(s.enforce);
    surfOrigCtl.set(s.showOriginal);
    surfNetCtl.set(s.showNet);
    surfPresetNote.textContent = SURFACE_PRESETS[s.preset]?.label || 'Custom parameters';
    if (sres) {
      for (let I = 0; I < 3; I++) for (let k = 1; k <= 2; k++) {
        const sl = surfSliders[I][k - 1], free = sres.free[I][k - 1];
        sl.set(s.alphas[I][k - 1]);
        sl.setDisabled(locked || !free);
        sl.el.querySelector('.ctl-track').style.opacity = free ? '1' : '0.45';
        sl.el.querySelector('label').style.color = free ? '' : '#595959';
        sl.hint.textContent = free ? '' : `fixed: ${prettyConstraint(sres.constraints[I][k - 1]).replace('eq. 9', 'eq. 19')}`;
      }
      surfCont.set(Array.from(sres.continuity, (row, j) => [String(j + 1), ...Array.from(row, sci)]));
    }
    if (!state.bi.on) drawSurface();
  }

  // ---------- tabs ----------
  const tabCtl = buttonGroup({ label: 'Show', options: [{ value: 'curve', label: 'Curve (§2–3)' }, { value: 'surface', label: 'Surface (§4)' }], value: state.tab, onChange(v) { state.tab = v; showTab(); ctx.save(); } });
  L.controls.append(tabCtl.el, curveCtl, surfaceCtl);
  function showTab() {
    const c = state.tab !== 'surface';
    curvePanel.hidden = !c; curveCtl.hidden = !c;
    surfacePanel.hidden = c; surfaceCtl.hidden = c;
    tabCtl.set(state.tab);
    if (c) { curvePlot.redraw(); fig3Plot.redraw(); } else frameSurface();
  }

  // ---------- explanation ----------
  explanation(L.explain, {
    what: [
      'A Bézier spline g of degree m (here the paper’s quadratic example, 11 control points, breakvalues 0, 1, 7/4, 5/2, 13/4, 4) is rewritten with degree m + 1. The classical degree elevation puts each new control point at a fixed place on the old control polygon and gives the same curve; here each new point b*₍ₘ₊₁₎ᵢ₊ₖ slides along its polygon leg with a free parameter αₖ⁽ᴵ⁾ ∈ (0, 1), which changes the shape while the breakpoints stay put.',
      'To keep the curve Cʳ at the joints, eq. (9) ties some parameters to the last parameter αₘ of a segment: those sliders are greyed and say which constraint fixes them. The others are free. The curvature at each breakpoint follows from the α (eq. 15): the table compares the formulas (13), the corrected (14) and the right-sided (15) with the curvature measured from the derivatives; the circles are the osculating circles there. The lower plot is the paper’s Fig. 3, computed live: K* at one joint as αₘ of the previous segment moves (the dot is the current value).',
    ],
    math: [
      'b^{*}_{(m+1)I} = b_{mI}, \\quad b^{*}_{(m+1)I+k} = (1 - \\alpha^{(I)}_{k})\\,b_{mI+k-1} + \\alpha^{(I)}_{k}\\,b_{mI+k} \\;(k = 1, \\ldots, m) \\quad (6)',
      '\\alpha_{k} = \\frac{m + 1 - k}{m + 1} \\;\\Rightarrow\\; g^{*} = g \\quad (\\text{classical elevation})',
      '\\alpha^{(I)}_{p} = 1 - p\\,\\alpha^{(I-1)}_{m} \\;(p = 1, \\ldots, r), \\quad \\alpha^{(I)}_{m-p+1} = p\\,\\alpha^{(I)}_{m} \\;(p = 2, \\ldots, r), \\quad r \\le \\lfloor m/2 \\rfloor \\quad (9)',
      'K^{*}(u_{I}) = \\frac{m^{2}}{m^{2} - 1} \\cdot \\frac{\\alpha^{(I)}_{2}}{(\\alpha^{(I)}_{1})^{2}} \\cdot K(u^{+}_{I}) \\quad (\\text{right-sided form of (15), any}\\; r)',
      'b^{r}_{k} = (1 - t)\\,b^{r-1}_{k} + t\\,b^{r-1}_{k+1}, \\quad t = \\frac{u - u_{I}}{u_{I+1} - u_{I}} \\quad (\\text{de Casteljau})',
    ],
    mathLabel: 'Remodelling eqs. (6), (9), (15) and de Casteljau’s algorithm',
    formulaNote: ['Corrections (', correctionLink('correction-001-eq14', 'eq. (14)'), ', ', correctionLink('correction-001-eq15', 'eq. (15)'), ', ', correctionLink('correction-001-alpha', '§4.1 surface'), ', ', correctionLink('correction-001-breaks', 'breakvalues'), ', ', correctionLink('correction-001-eq20', 'eqs. (20)–(22)'), '): the printed (14) has wrong indices at I = L; the printed interior (15) uses α₂⁽ᴵ⁾ = 1 − 2αₘ⁽ᴵ⁻¹⁾, which holds only for r ≥ 2 (compare the last two columns with r = 1 on the quartic example). On the surface, “all α = 1/3” is not the usual elevation: it breaks C¹ (jump 1.5); the usual one is (2/3, 1/3).'],
    tryThis: [
      'Fig. 1 → move α₂⁽¹⁾ towards 0: near the joint u₂ the curve flattens and K*(u₂) falls (pick joint 2 for Fig. 3: the dot runs down the solid curve). With r = 1 the printed (15), dashed orange, predicts the opposite trend: it is only valid for r ≥ 2.',
      'Turn “Enforce eq. (9)” off and move any α₁: the d₁ jump at that joint is no longer 0 — g* has a kink.',
      'Choose “Quartic from a B-spline” and r = 2: C² is kept (d₂ ≈ 1e−15) and the d₃ jump is not; switch to r = 1 and compare the printed (15) column.',
      'Quartic example with r = 2: set αₘ of a segment to 1/(m + 1) = 0.2 (the dashed vertical line in Fig. 3): K* equals K at the next joint (remark c); below it K* > K, above it K* < K.',
      'Step by step: walk through the remodelling of the segment that holds u (the points b* appear one by one), then switch to de Casteljau to evaluate g* there.',
      'Surface tab: “Fig. 4 literally” shows the kink across u = 1 and u = 2 that the all-1/3 reading produces; Fig. 5 stays C¹.',
      'Surface tab, “Bi-degree (§4.2)”: pick column l = 0 and move α₂,₀⁽¹⁾: only the edge v = 0 region bends, the jumps d₀, d₁ across u = 1, 2 and v = 1 stay at rounding level and the corner points do not move; turn “Enforce eq. (9)” off and move β₁⁽¹⁾ to see the kink across v = 1.',
    ],
    paper: meta.paper,
  });

  // ---------- start ----------
  sanitizeCurve();
  sanitizeSurface();
  refreshCurveControls();
  update();
  surfUpdate();
  showConstruction();
  showTab();
  if (!restoreView(curvePlot, state.view)) {
    state.view = [];
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 40);
  }

  return {
    destroy() { steps.destroy(); player.destroy(); curvePlot.destroy(); fig3Plot.destroy(); view.destroy(); },
    // for the shell's Export row: the remodelled control data (curve tab) or the surface (surface tab)
    exports() {
      if (state.tab === 'surface' && state.bi.on) {
        const b = bi.result();
        return {
          json: b ? { surfaceBi: { controlPoints: b.controlPoints, alphas: b.alphas, betas: b.betas, continuityU: b.continuityU, continuityV: b.continuityV, uv: b.uv, points: b.points } } : undefined,
          obj: b?.mesh ? [{ name: 'bidegree_remodelled_surface', mesh: b.mesh }] : [],
          csv: b ? { points: b.points, dim: b.dim || 3 } : undefined,
        };
      }
      if (state.tab === 'surface') {
        return {
          json: sres ? { surface: { controlPoints: sres.controlPoints, alphas: sres.alphas, uv: sres.uv, points: sres.points } } : undefined,
          obj: sres?.mesh ? [{ name: 'remodelled_surface', mesh: sres.mesh }] : [],
          csv: sres ? { points: sres.points, dim: sres.dim || 3 } : undefined,
        };
      }
      return {
        json: res ? {
          curve: { controlPoints: res.controlPoints, alphas: res.alphas, curvature: res.curvature, curvatureOriginal: res.curvatureOriginal, continuity: res.continuity },
          samples: { params: res.params, points: res.points },
        } : undefined,
        csv: res ? { points: res.points, dim: res.dim || 2 } : undefined,
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------
// (imports are hoisted: this block stays self-contained at the end of the file)
import { code, snippetCode } from '../lib/snippet.js';
import { dataImport } from '../lib/data-import.js';

export function snippet(state) {
  if (state.tab === 'surface') {
    const s = state.surface;
    return snippetCode(meta.title, code`
      // the bi-quadratic/cubic Bézier patches of §4: control points [k][l] (k along u, l along v)
      const points = ${SURFACE_POINTS};
      // degree elevation 2 → 3 along u with the α of each segment (eq. 9 fixes some when C^r is enforced)
      const options = { degreeU: 2, degreeV: 3, breaksU: [0, 1, 2, 3], alphas: ${s.alphas}, r: ${s.r}, enforce: ${s.enforce} };
      const surface = sl.bezierRemodelSurface({ points, ...options, samplesU: 61, samplesV: 17, mesh: true });
      const original = sl.bezierRemodelSurface({ points, degreeU: 2, degreeV: 3, breaksU: [0, 1, 2, 3], samplesU: 61, samplesV: 17 });
      return { surface, original };
    `);
  }
  return snippetCode(meta.title, code`
    const points = ${state.points};
    const degree = ${state.degree};
    const breaks = ${state.breaks};
    // the parametric degree elevation g → g* with one α vector per segment (eq. 9 fixes some when C^r is enforced)
    const alphas = ${state.alphas};
    const curve = sl.bezierRemodel({ points, degree, breaks, alphas, r: ${state.r}, enforce: ${state.enforce}, samples: 600 });
    const original = sl.bezierSpline({ points, degree, breaks, samples: 600 });
    return { curve, original };
  `);
}

// ---------- surface tab, §4.2: the bi-degree remodelling (degrees (m, n) → (m + 1, n + 1), class C^{r,s}) ----------
// The construction (bezierRemodelSurfaceBi) is the curve remodelling applied in u, column by column with the
// parameters α_{k,l}^(I) of eq. (17), then in v, row by row with β_l^(J); the printed eqs. (20)–(22) are garbled.
// The net is the §4 table with its v-patch split at v = 1 (a biquadratic net, 3 × 2 patches, C¹ in u and v):
// columns y = 0, 1, 2, 3, 4 where the y = 2 column is the midpoint of its neighbours (the C¹ joint in v).
const BI_POINTS = [
  [[0, 0, 3], [0, 1, 2], [0, 2, 1.5], [0, 3, 1], [0, 4, 3]],
  [[1, 0, 1], [1, 1, 4], [1, 2, 3], [1, 3, 2], [1, 4, 4]],
  [[2, 0, 2.5], [2, 1, 3], [2, 2, 2], [2, 3, 1], [2, 4, 3]],
  [[3, 0, 4], [3, 1, 2], [3, 2, 1], [3, 3, 0], [3, 4, 2]],
  [[4, 0, 2.5], [4, 1, 3], [4, 2, 2], [4, 3, 1], [4, 4, 2.5]],
  [[5, 0, 1], [5, 1, 4], [5, 2, 3], [5, 3, 2], [5, 4, 3]],
  [[6, 0, 3], [6, 1, 0], [6, 2, 0.5], [6, 3, 1], [6, 4, 2]],
];
const BI_BREAKS_U = [0, 1, 2, 3];
const BI_BREAKS_V = [0, 1, 2];
const BI_M = 2, BI_N = 2, BI_COLS = 5, BI_SEGS_U = 3, BI_SEGS_V = 2;
const BI_NU = 61, BI_NV = 41;   // samples: u = 1, 2 at iu = 20, 40; v = 1 at iv = 20

/** The state of the bi-degree view (its own key, so the §4.1 state and links stay as they were). */
function biDefaults() {
  const c2 = [[0.6, 0.15], [0.85, 0.4], [0.6, 0.5]];   // columns 1..3 share column 2's table (C¹ across v = 1)
  return {
    on: false,
    col: 0,
    alphas: [[[0.5, 0.2], [0.8, 0.3], [0.7, 0.6]], c2, c2, c2, [[0.4, 0.3], [0.7, 0.2], [0.8, 0.7]]].map((t) => t.map((r) => [...r])),
    betas: [[0.55, 0.3], [0.7, 0.35]],
    r: 1,
    s: 1,
    enforce: true,
  };
}

/** Validates the bi-degree state in place (a link may hold anything that passed the type check). */
function sanitizeBi(b) {
  const d = biDefaults();
  const table = (t, segs) => Array.isArray(t) && t.length === segs && t.every((r) => Array.isArray(r) && r.length === 2 && r.every(Number.isFinite));
  if (!(Array.isArray(b.alphas) && b.alphas.length === BI_COLS && b.alphas.every((t) => table(t, BI_SEGS_U)))) b.alphas = d.alphas;
  if (!table(b.betas, BI_SEGS_V)) b.betas = d.betas;
  const clamp = (a) => Math.min(0.999, Math.max(0.001, a));
  for (const t of [...b.alphas, b.betas]) for (const r of t) for (let k = 0; k < 2; k++) r[k] = clamp(r[k]);
  b.r = b.r === 0 ? 0 : 1;
  b.s = b.s === 0 ? 0 : 1;
  b.col = Math.max(0, Math.min(BI_COLS - 1, Math.round(b.col) || 0));
}

/**
 * Mounts the §4.2 part of the surface tab: controls (r, s, eq. (9) on/off, the column l whose α_{k,l} are edited,
 * the shared β), readouts (jumps across u = u_I and v = v_J, corner points kept) and the drawing in `view`.
 * Returns { controls, legend, update, draw, result }.
 */
function mountBiSurface({ wasm, state, ctx, notify, view, locked }) {
  const b = state.bi;
  sanitizeBi(b);
  let res = null, orig = null;

  function compute() {
    try {
      res = wasm.bezierRemodelSurfaceBi({
        points: BI_POINTS, degreeU: BI_M, degreeV: BI_N, breaksU: BI_BREAKS_U, breaksV: BI_BREAKS_V,
        alphas: b.alphas, betas: b.betas, r: b.r, s: b.s, enforce: b.enforce, samplesU: BI_NU, samplesV: BI_NV, mesh: true,
      });
      // keep the tables that were used (eq. (9) and the break-line windows overwrite some entries)
      b.alphas = Array.from(res.alphas, (t) => Array.from(t, (r) => Array.from(r)));
      // betas come back per row; the demo edits one shared table (every row's is the same)
      b.betas = Array.from(res.betas[0], (r) => Array.from(r));
    } catch (e) { res = null; notify(e, 'error'); }
    if (!orig) {
      try {
        orig = wasm.bezierRemodelSurfaceBi({ points: BI_POINTS, degreeU: BI_M, degreeV: BI_N, breaksU: BI_BREAKS_U, breaksV: BI_BREAKS_V, samplesU: BI_NU, samplesV: BI_NV });
      } catch (e) { notify(e, 'error'); }
    }
  }

  // which entries the API fixes (for greying the sliders): eq. (9) with r = 1 fixes α₁⁽ᴵ⁾ (I ≥ 1) to 1 − α₂⁽ᴵ⁻¹⁾,
  // and with s = 1 the columns n·J ± 1 around the break line v_J take the table of column n·J
  const windowOf = (l) => {
    if (!b.enforce) return -1;
    for (let J = 1; J < BI_SEGS_V; J++) if (l !== BI_N * J && Math.abs(l - BI_N * J) <= b.s) return BI_N * J;
    return -1;
  };
  const fixedByNine = (I, k, r) => b.enforce && r >= 1 && I >= 1 && k === 1;

  // ---------- controls ----------
  const rCtl = buttonGroup({ label: 'Keep Cʳ in u: r', options: [0, 1].map((v) => ({ value: v, label: String(v) })), value: b.r, onChange(v) { b.r = v; update(); ctx.save(); } });
  const sCtl = buttonGroup({ label: 'Keep Cˢ in v: s', options: [0, 1].map((v) => ({ value: v, label: String(v) })), value: b.s, onChange(v) { b.s = v; update(); ctx.save(); } });
  const enforceCtl = toggle({ label: 'Enforce eq. (9) in u and v', value: b.enforce, hint: 'Off: every α and β is free and G* generally loses C¹ across the break lines (see the jumps).', onChange(v) { b.enforce = v; update(); ctx.save(); } });
  const colCtl = buttonGroup({ label: 'Column l (αₖ,ₗ, eq. 17)', options: Array.from({ length: BI_COLS }, (_, l) => ({ value: l, label: String(l) })), value: b.col, onChange(v) { b.col = v; refresh(); ctx.save(); } });
  const mkSlider = (label, key, onInput) => {
    const s = slider({ label, min: 0.001, max: 0.999, step: 0.001, value: 0.5, number: true, format: (v) => fmt(v, 4), onInput, onChange() { ctx.save(); } });
    const hint = h('div', { class: 'ctl-hint bi-constraint' });
    s.el.appendChild(hint); s.hint = hint;
    Object.assign(s.el.dataset, key);
    return s;
  };
  const colHint = h('p', { class: 'ctl-hint', dataset: { role: 'bi-column-hint' }, 'aria-live': 'polite' });
  const alphaBox = h('div');
  const alphaSliders = [];
  for (let I = 0; I < BI_SEGS_U; I++) {
    for (let k = 1; k <= BI_M; k++) {
      const s = mkSlider(alphaName(k, I), { biAlpha: `${I},${k}` }, (v) => { b.alphas[b.col][I][k - 1] = v; update(); });
      s.I = I; s.k = k;
      alphaSliders.push(s);
      alphaBox.appendChild(s.el);
    }
  }
  const betaBox = h('div');
  const betaSliders = [];
  for (let J = 0; J < BI_SEGS_V; J++) {
    for (let k = 1; k <= BI_N; k++) {
      const s = mkSlider(`β${sub(k)}${sup(`(${J})`).replace('(', '⁽').replace(')', '⁾')} (every row)`, { biBeta: `${J},${k}` }, (v) => { b.betas[J][k - 1] = v; update(); });
      s.J = J; s.k = k;
      betaSliders.push(s);
      betaBox.appendChild(s.el);
    }
  }
  const contU = table({ caption: 'Jumps of ∂ⁱG*/∂uⁱ across the break lines in u (I: which line)', columns: ['I', 'd₀', 'd₁', 'd₂'], digits: 3 });
  const contV = table({ caption: 'Jumps of ∂ʲG*/∂vʲ across the break lines in v (J: which line)', columns: ['J', 'd₀', 'd₁', 'd₂'], digits: 3 });
  contU.el.dataset.role = 'bi-continuity-u';
  contV.el.dataset.role = 'bi-continuity-v';
  const cornerOut = readout({ label: 'Corners kept (max distance)', value: '—' });
  cornerOut.el.dataset.readout = 'bi-corners';
  const classOut = readout({ label: 'Degrees and class', value: '—' });
  classOut.el.dataset.readout = 'bi-class';
  const controls = h('div', { class: 'bi-surface-controls' },
    group('Bi-degree remodelling (§4.2)', rCtl.el, sCtl.el, enforceCtl.el, classOut.el,
      h('p', { class: 'ctl-hint' }, 'Built as the curve remodelling in u, column by column (αₖ,ₗ), then in v, row by row (β). The paper’s eqs. (20)–(22) are garbled; this is the reconstruction.')),
    group('Per-column parameters (eq. 17)', colCtl.el, colHint, alphaBox),
    group('Parameters in v, every row', betaBox),
    group('Continuity and corners', contU.el, contV.el, cornerOut.el),
    group('Data', h('p', { class: 'ctl-hint' }, 'The §4 table with its v-patch split at v = 1: columns y = 0, 1, 2, 3, 4 (the y = 2 column is the midpoint of its neighbours, so G is C¹ in v); degrees m = n = 2, breakvalues u = 0, 1, 2, 3 and v = 0, 1, 2. These data are ours: the paper prints none for §4.2.')),
  );
  const legendEl = legend([
    { label: 'G* (degree 3 in u, 3 in v) with isolines', color: '#56B4E9', kind: 'band' },
    { label: 'break lines u = 1, 2 and v = 1', color: PALETTE.control },
    { label: 'control net b*ₖ,ₗ of G*', color: PALETTE.second },
    { label: 'given G (lines v = const)', color: PALETTE.ink },
  ]);
  legendEl.dataset.legendFor = 'surface-bi';

  // the exact numbers stay on the cells (data-value) for tests and copy; the text is rounded
  const setJumps = (tbl, rows, lead) => {
    const n = Math.max(0, ...Array.from(rows, (r) => r.length));
    const cols = [lead, ...Array.from({ length: n }, (_, i) => `d${sub(i)}`)];
    const head = tbl.el.querySelector('thead tr');
    clear(head);
    for (const c of cols) append(head, h('th', { scope: 'col' }, c));
    tbl.set(Array.from(rows, (r, j) => [String(j + 1), ...Array.from(r, sci)]));
    tbl.el.querySelectorAll('tbody tr').forEach((tr, j) => tr.querySelectorAll('td').forEach((td, i) => { td.dataset.value = String(rows[j][i]); }));
  };
  // max distance between the kept corners b*_{(m+1)I,(n+1)J} and b_{mI,nJ} (read from the API's control net)
  function cornerGap() {
    let worst = 0;
    for (let I = 0; I <= BI_SEGS_U; I++) {
      for (let J = 0; J <= BI_SEGS_V; J++) {
        const q = 3 * ((BI_M + 1) * I * res.cols + (BI_N + 1) * J), p = BI_POINTS[BI_M * I][BI_N * J];
        worst = Math.max(worst, Math.hypot(res.controlPoints[q] - p[0], res.controlPoints[q + 1] - p[1], res.controlPoints[q + 2] - p[2]));
      }
    }
    return worst;
  }

  function refresh() {
    rCtl.set(b.r); sCtl.set(b.s); enforceCtl.set(b.enforce); colCtl.set(b.col);
    rCtl.setDisabled(locked); sCtl.setDisabled(locked); enforceCtl.setDisabled(locked);
    const w = windowOf(b.col);
    colHint.textContent = w >= 0
      ? `Column ${b.col} follows column ${w}, the break line v = v${sub(w / BI_N)}: Cˢ across it needs the same weights on the columns next to it. Edit column ${w}.`
      : `Column ${b.col}: its own parameters αₖ,${sub(b.col)}⁽ᴵ⁾.`;
    for (const s of alphaSliders) {
      const v = b.alphas[b.col][s.I][s.k - 1];
      const free = w < 0 && !fixedByNine(s.I, s.k, b.r);
      s.set(v);
      s.setDisabled(locked || !free);
      s.el.dataset.free = String(free);
      s.el.querySelector('.ctl-track').style.opacity = free ? '1' : '0.45';
      s.hint.textContent = free || w >= 0 ? '' : `fixed: ${alphaName(1, s.I)} = 1 − ${alphaName(2, s.I - 1)}  (eq. 9)`;
    }
    for (const s of betaSliders) {
      const free = !fixedByNine(s.J, s.k, b.s);
      s.set(b.betas[s.J][s.k - 1]);
      s.setDisabled(locked || !free);
      s.el.dataset.free = String(free);
      s.el.querySelector('.ctl-track').style.opacity = free ? '1' : '0.45';
      s.hint.textContent = free ? '' : `fixed: β${sub(1)}${sup(`(${s.J})`).replace('(', '⁽').replace(')', '⁾')} = 1 − β${sub(2)}${sup(`(${s.J - 1})`).replace('(', '⁽').replace(')', '⁾')}  (eq. 9)`;
    }
    if (res) {
      setJumps(contU, res.continuityU, 'I');
      setJumps(contV, res.continuityV, 'J');
      const gap = cornerGap();
      cornerOut.set(`${sci(gap)} over ${(BI_SEGS_U + 1) * (BI_SEGS_V + 1)} corners`);
      cornerOut.el.dataset.value = String(gap);
      classOut.set(`(${BI_M}, ${BI_N}) → (${res.degreeU}, ${res.degreeV}), kept C${sup(b.r)}˒${sup(b.s)}${b.enforce ? '' : ' (not enforced)'}`);
    } else {
      cornerOut.set('—'); classOut.set('—');
    }
  }

  function draw() {
    if (!res) return;
    const s = state.surface;
    const at = (pts, iu, iv) => { const q = 3 * (iu * BI_NV + iv); return [pts[q], pts[q + 1], pts[q + 2]]; };
    const alongV = (pts, iu) => Array.from({ length: BI_NV }, (_, iv) => at(pts, iu, iv));
    const alongU = (pts, iv) => Array.from({ length: BI_NU }, (_, iu) => at(pts, iu, iv));
    try {
      view.setMesh('G*', res.mesh, { color: '#56B4E9', isolines: { every: [5, 5], width: 1 } });
      view.setLines('joints', [alongV(res.points, 20), alongV(res.points, 40), alongU(res.points, 20)], { color: PALETTE.control, width: 4 });
      const cp = res.controlPoints, rows = res.rows, cols = res.cols, net = [];
      const P = (k, l) => [cp[3 * (k * cols + l)], cp[3 * (k * cols + l) + 1], cp[3 * (k * cols + l) + 2]];
      for (let k = 0; k < rows; k++) net.push(Array.from({ length: cols }, (_, l) => P(k, l)));
      for (let l = 0; l < cols; l++) net.push(Array.from({ length: rows }, (_, k) => P(k, l)));
      view.setLines('net', net, { color: PALETTE.second, width: 1.5, opacity: 0.85, visible: s.showNet });
      view.setPoints('b*', cp, { color: PALETTE.second, size: 7, pickable: false, visible: s.showNet });
      if (orig) view.setLines('G', Array.from({ length: 11 }, (_, j) => alongU(orig.points, 4 * j)), { color: PALETTE.ink, width: 1.5, opacity: 0.7, visible: s.showOriginal });
    } catch (e) { notify(e, 'error'); }
  }

  function update() {
    compute();
    refresh();
    draw();
  }

  return { controls, legend: legendEl, update, draw, result: () => res };
}
