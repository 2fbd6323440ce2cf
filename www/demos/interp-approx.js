// Demo "Interpolating vs approximating" (Kuklišová): one slider a moves the B2-spline curve from
// interpolation (a = 0) to the cubic B-spline (a = 1/6), with tension p, modified knots K, automatic tension
// and the paper's figures as presets. All spline values come from the wasm API (b2Curve, b2Fit, b2Basis);
// this module only draws and handles input. A stepper walks through the construction (data → auxiliary points →
// joints → even vertices → cubic control polygon → curve) with the weights of each stage from b2Curve, and a
// toggle draws the curve with eq. (5)'s last weight as printed next to the corrected one.

import { h, demoLayout, explanation, fmt, legend, setLegendItems } from '../lib/dom.js';
import { cite, correctionLink } from '../lib/papers-ref.js';
import { createPlot, PALETTE, SERIES, restoreView } from '../lib/plot2d.js';
import { slider, toggle, buttonGroup, button, group, row, readout } from '../lib/controls.js';
import { uPlayer } from '../lib/player.js';
import { pointEditing } from '../lib/point-edit.js';
import { stepper } from '../lib/stepper.js';
import { mathText } from '../lib/mathml.js';

export const meta = {
  id: 'interp-approx',
  title: 'Interpolating vs approximating',
  summary: 'One slider from interpolation (a = 0) to the cubic B-spline (a = 1/6), with tension and modified knots.',
  paper: cite('000', '§3–5'),
};

const MAX_POINTS = 30;
const SAMPLES = 600;

const SHAPE = [[-0.6, -0.4], [0, 0], [0.6, 1.6], [1.8, 2.4], [2.4, 2.2], [3.6, 0.2], [4.4, 0.1], [5.6, 1.8], [6.4, 2.2], [7.6, 1.2], [8.2, 0.6]];

// The paper's figures as presets (the paper prints no coordinates: the data are chosen to show the same effect).
const PRESETS = {
  fig6: {
    label: 'Fig. 6: a = −0.1 … 0.2',
    state: {
      points: [[-1, 0], [0, 0], [1, 2], [2, 2.2], [3, 0.2], [4, 0], [5, 2], [6, 2.2], [7, 0.4], [8, 0.2]],
      construction: 'section3', knots: 'uniform', a: 0, p: 0.05, autoTension: 'off', useK: false,
      family: { key: 'a', values: [-0.1, 0, 0.1, 0.2] },
    },
    note: 'Fig. 6 (section 3, uniform): the approximation parameter a = −0.1, 0, 0.1, 0.2. a < 0 overshoots the data, a = 0 interpolates, a > 0 approximates.',
  },
  fig7: {
    label: 'Fig. 7: p = 0 … 0.3',
    state: {
      points: [[-1, 0], [0, 0], [1, 2], [2, 2.2], [3, 0.2], [4, 0], [5, 2], [6, 2.2], [7, 0.4], [8, 0.2]],
      construction: 'section3', knots: 'uniform', a: 0, p: 0.1, autoTension: 'off', useK: false,
      family: { key: 'p', values: [0, 0.1, 0.2, 0.3] },
    },
    note: 'Fig. 7 (section 3, a = 0): the tension p = 0, 0.1, 0.2, 0.3. Larger p pulls the even control vertices outwards: rounder, fuller curves.',
  },
  fig8: {
    label: 'Fig. 8: uneven spacing (uniform)',
    state: {
      points: [[-0.3, -0.3], [0, 0], [0.25, 0.3], [0.5, 0.35], [4, 0.6], [4.3, 1], [4.4, 3.6], [4.7, 4], [5.2, 4.1], [5.6, 4.2]],
      construction: 'section3', knots: 'uniform', a: 0, p: 1 / 12, autoTension: 'off', useK: false, family: null,
    },
    note: 'Fig. 8: the uniform construction of section 3 on unevenly spaced data overshoots and loops on the long edges.',
  },
  fig10: {
    label: 'Fig. 10: the chord-length cure',
    state: {
      points: [[-0.3, -0.3], [0, 0], [0.25, 0.3], [0.5, 0.35], [4, 0.6], [4.3, 1], [4.4, 3.6], [4.7, 4], [5.2, 4.1], [5.6, 4.2]],
      construction: 'nonuniform', knots: 'chord', a: 0, p: 1 / 6, autoTension: 'off', useK: false, family: null,
    },
    note: 'Fig. 10: the non-uniform curve (chord-length knots, eq. (8)) on the same data: no loops.',
  },
  fig13: {
    label: 'Fig. 13: stairs, K off',
    state: {
      points: [[-1, 0], [0, 0], [3, 0], [3, 0.5], [6, 0.5], [6, 1], [9, 1], [9, 1.5], [12, 1.5], [13, 1.5]],
      construction: 'nonuniform', knots: 'chord', a: 0, p: 1 / 6, autoTension: 'off', useK: false, K: 20, family: null,
    },
    note: 'Fig. 13: a staircase of long and short edges: with the standard split knots the curve swings away from the long edges (max. distance to the polygon 0.25).',
  },
  fig14: {
    label: 'Fig. 14: K = 20',
    state: {
      points: [[-1, 0], [0, 0], [3, 0], [3, 0.5], [6, 0.5], [6, 1], [9, 1], [9, 1.5], [12, 1.5], [13, 1.5]],
      construction: 'nonuniform', knots: 'chord', a: 0, p: 1 / 6, autoTension: 'off', useK: true, K: 20, family: null,
    },
    note: 'Fig. 14: the modified knots u′₂ᵢ = (uᵢ₋₁ + K·uᵢ + uᵢ₊₁)/(K + 2) with K = 20 follow the polygon better (max. distance 0.15).',
  },
  fig19: {
    label: 'Fig. 19: automatic tension',
    state: {
      points: SHAPE.map((q) => [...q]), construction: 'nonuniform', knots: 'chord', a: 0, p: 1 / 6,
      autoTension: 'paper', autoScale: 0.2, useK: false, family: null,
    },
    note: 'Automatic tension pᵢ = p·|cos αᵢ + cos αᵢ₊₁|/2 with p = 0.2 (the printed formula).',
  },
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

export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);
  const sub = (i) => String(i).replace(/-/g, '₋').replace(/\d/g, (d) => '₀₁₂₃₄₅₆₇₈₉'[d]);

  // ---------- state hygiene (bookkeeping only) ----------
  function sanitize() {
    const d = defaults();
    for (const k of Object.keys(d)) if (state[k] === undefined) state[k] = d[k];
    const okPts = Array.isArray(state.points) && state.points.length >= 6 && state.points.length <= MAX_POINTS &&
      state.points.every((q) => Array.isArray(q) && q.length === 2 && q.every(Number.isFinite));
    if (!okPts) state.points = d.points;
    const num = (k, lo, hi) => { if (!(Number.isFinite(state[k]) && state[k] >= lo && state[k] <= hi)) state[k] = d[k]; };
    num('a', -0.1, 0.25); num('p', 0, 0.5); num('K', 0, 100); num('autoScale', 0, 0.5);
    if (![1, 2].includes(state.c2)) state.c2 = 1;
    if (!['chord', 'uniform'].includes(state.knots)) state.knots = 'chord';
    if (!['nonuniform', 'section3'].includes(state.construction)) state.construction = 'nonuniform';
    if (!['off', 'paper', 'turning'].includes(state.autoTension)) state.autoTension = 'off';
    if (state.construction === 'section3') { state.knots = 'uniform'; state.autoTension = 'off'; }
    const f = state.family;
    if (f && !(['a', 'p'].includes(f.key) && Array.isArray(f.values) && f.values.length <= 6 && f.values.every(Number.isFinite))) state.family = null;
    for (const k of ['autoEnds', 'useK', 'showB', 'showInterp', 'showBuild', 'showComb', 'eq5Printed']) state[k] = !!state[k];
    if (!Number.isInteger(state.step) || state.step < -1 || state.step > 5) state.step = -1;
  }

  let steps = null; // the construction stepper (built with the controls below)

  // ---------- computed data (from wasm) ----------
  let main = null, bspl = null, interp = null, basis = null, family = [], claim = null;

  function opts(over = {}) {
    const o = { a: state.a, tension: state.p, knots: state.knots, c2: state.c2, construction: state.construction };
    if (state.useK) o.K = state.K;
    if (state.autoTension !== 'off' && state.construction !== 'section3') {
      o.autoTension = state.autoTension;
      o.autoTensionScale = state.autoScale;
    }
    return { ...o, ...over };
  }
  // the curve for the current points: b2Curve on W₋₁…Wₙ₊₂, or b2Fit (reflected ends) on W₁…Wₙ
  function call(over) {
    if (state.autoEnds) return wasm.b2Fit({ points: state.points.slice(2, -2), ...opts(over) });
    return wasm.b2Curve({ points: state.points, ...opts(over) });
  }

  function compute() {
    try {
      main = call({ samples: SAMPLES, curvature: true });
      if (state.autoEnds && main.dataPoints) {
        const d = main.dataPoints, m = state.points.length;
        for (const i of [0, 1, m - 2, m - 1]) state.points[i] = [d[2 * i], d[2 * i + 1]];
      }
    } catch (e) { notify(e, 'error'); main = null; }
    try { bspl = state.showB ? call({ a: 1 / 6, samples: SAMPLES }) : null; } catch (e) { bspl = null; }
    try { interp = state.showInterp ? call({ a: 0, samples: SAMPLES }) : null; } catch (e) { interp = null; }
    family = [];
    if (state.family) {
      for (const v of state.family.values) {
        try { family.push({ v, r: call({ [state.family.key === 'a' ? 'a' : 'tension']: v, samples: SAMPLES }) }); } catch (e) { /* skip */ }
      }
    }
    // the printed claim "a = 1/6 and p = 0 gives the B-spline" (correction-000-bspline), live: with p = 0 the
    // even vertices C₂ᵢ of the construction (a = 0, no automatic tension) against those of the B-spline (a = 1/6,
    // the §5 blend). Both from the wasm API; equal on uniform knots, apart on non-uniform ones.
    claim = null;
    try {
      const mid = call({ a: 0, tension: 0, autoTension: false, samples: 2 }).evenVertices;
      // the claim is about a = 1/6 *and* p = 0 (with the current p, the §3 curve at a = 1/6 is not the B-spline)
      const bs = call({ a: 1 / 6, tension: 0, autoTension: false, samples: 2 }).evenVertices;
      let d = 0;
      for (let i = 0; i + 1 < Math.min(mid.length, bs.length); i += 2) d = Math.max(d, Math.hypot(mid[i] - bs[i], mid[i + 1] - bs[i + 1]));
      claim = d;
    } catch (e) { claim = null; }
    try {
      basis = wasm.b2Basis({ points: state.points, ...opts({ samples: 301 }) });
    } catch (e) { basis = null; }
    // the construction's stages and weights (the stepper), and the curve with eq. (5) as printed. b2Curve on
    // the current W₋₁…Wₙ₊₂ (with automatic ends these are the reflected points written back above).
    try { build = wasm.b2Curve({ points: state.points, ...opts({ samples: 2 }) }); } catch (e) { build = null; }
    try { printed = wasm.b2Curve({ points: state.points, ...opts({ samples: state.eq5Printed ? SAMPLES : 2 }), eq5: 'printed' }); } catch (e) { printed = null; }
  }
  let build = null, printed = null;

  // the evaluation point L^a(u) of "Play u" (u in the curve's domain)
  let atU = null;
  function computeAtU() {
    atU = null;
    if (!main) return;
    const [a, b] = main.domain;
    if (!(state.u >= a && state.u <= b)) state.u = a;
    try { const r = call({ at: [state.u] }); atU = [r.points[0], r.points[1]]; } catch (e) { atU = null; }
  }

  function recompute() {
    compute();
    computeAtU();
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
    describe: () => `B2-spline with a = ${fmt(state.a, 3)}, tension ${fmt(state.p, 3)}, ${state.knots} knots${state.useK ? `, K = ${state.K}` : ''}; data ${state.points.map((q, i) => `W${i - 1} (${fmt(q[0], 2)}, ${fmt(q[1], 2)})`).join(', ')}.`,
    onView(v) { state.view = [v.xmin, v.xmax, v.ymin, v.ymax]; ctx.save(); },
    draw(g, plot) {
      plot.polyline(state.points, { color: PALETTE.polygon, width: 1.5, dash: [8, 6] });
      if (state.showBuild && main) {
        plot.polyline(main.controlPoints, { color: PALETTE.highlight, width: 1.5, alpha: 0.9 });
        plot.points(main.controlPoints.filter((_, k) => (k >> 1) % 2 === 1), { color: PALETTE.highlight, radius: 3.5, hollow: true });
        plot.points(main.evenVertices, { color: PALETTE.highlight, radius: 6, shape: 'diamond' });
        plot.points(main.joints, { color: PALETTE.second, radius: 5, shape: 'square' });
      }
      // the family: one colour per value; the member at the current value is the blue curve itself (drawn
      // below, on top), so it is labelled in blue and not drawn twice under it
      family.forEach(({ v, r }, k) => {
        const current = isCurrent(v);
        if (!current) plot.polyline(r.points, { color: familyColor(v, k), width: 2.5 });
        const at = labelPoint(r.points, 0.15 + 0.2 * k, plot.getView());
        if (at) plot.label(at[0], at[1], `${state.family.key} = ${fmt(v, 2)}`, { color: familyColor(v, k), font: '600 13px system-ui, sans-serif' });
      });
      if (bspl) plot.polyline(bspl.points, { color: PALETTE.accent, width: 2.5, dash: [10, 6] });
      if (interp) plot.polyline(interp.points, { color: PALETTE.second, width: 2.5, dash: [3, 5] });
      if (main && state.showComb && main.curvature) {
        const kap = main.curvature, nr = main.normals;
        const vec = new Float64Array(nr.length);
        let kmax = 0;
        for (let i = 0; i < kap.length; i++) kmax = Math.max(kmax, Math.abs(kap[i]));
        const v = plot.getView();
        const scale = kmax > 0 ? 0.12 * (v.xmax - v.xmin) / kmax : 0;
        for (let i = 0; i < kap.length; i++) { vec[2 * i] = -kap[i] * nr[2 * i]; vec[2 * i + 1] = -kap[i] * nr[2 * i + 1]; }
        plot.comb(main.points, vec, { scale, every: 4, color: PALETTE.sky });
      }
      // while the stepper builds the curve stage by stage, the finished curve is only a faint trace until its
      // own step (6 of 6) draws it
      const building = state.step >= 0 && state.step < 5;
      if (main) plot.polyline(main.points, { color: PALETTE.curve, width: state.step === 5 ? 6 : building ? 2 : 3.5, alpha: building ? 0.22 : 1 });
      if (state.eq5Printed && printed) plot.polyline(printed.points, { color: PALETTE.control, width: 2.5, dash: [6, 4] });
      drawStepLines(plot);
    },
    drawOver(g, plot) {
      drawStepMarks(plot);
      if (!atU || !(player.playing || (main && state.u > main.domain[0]))) return;
      plot.points([atU], { color: PALETTE.ink, radius: 6, shape: 'diamond', stroke: '#fff' });
      plot.label(atU[0], atU[1], `L(${fmt(state.u, 2)})`, { offset: [10, 20], baseline: 'top' });
    },
  });
  curvePlot.canvas.dataset.plot = 'curve';
  const m = () => state.points.length;
  const dataHandles = curvePlot.addHandles({
    name: 'data point',
    points: () => state.points.slice(2, -2),
    label: (i) => `W${sub(i + 1)}`,
    labelOf: (i) => `Data point W${i + 1}`,
    radius: 7,
    move(i, q) { state.points[i + 2] = [q[0], q[1]]; state.preset = ''; recompute(); },
    end() { ctx.save(); },
  });
  const auxIdx = () => [0, 1, m() - 2, m() - 1];
  const auxHandles = curvePlot.addHandles({
    name: 'auxiliary point',
    points: () => auxIdx().map((i) => state.points[i]),
    label: (k) => `W${sub(auxIdx()[k] - 1)}`,
    labelOf: (k) => `Auxiliary end point W${auxIdx()[k] - 1}`,
    color: PALETTE.muted, shape: 'square', radius: 6,
    move(k, q) { state.points[auxIdx()[k]] = [q[0], q[1]]; state.preset = ''; recompute(); },
    end() { ctx.save(); },
  });

  // family colours: none of them is a colour of the other curves of this plot (the current curve blue, a = 1/6
  // orange, a = 0 green, the data vermillion, the build purple, the comb sky blue), so each value has its own; the
  // member at the current a (or p) is the current curve and takes its blue
  const FAMILY_COLORS = ['#882255', '#332288', '#999933', '#000000', '#661100', '#44AA99'];
  const isCurrent = (v) => Math.abs(v - (state.family?.key === 'p' ? state.p : state.a)) < 1e-9;
  const familyColor = (v, k) => (isCurrent(v) ? PALETTE.curve : FAMILY_COLORS[k % FAMILY_COLORS.length]);
  /** A point of the curve in view for a label, the first from fraction `f` of its samples on (null: none in view). */
  function labelPoint(pts, f, v) {
    const m = pts.length / 2;
    for (let s = 0; s < m; s++) {
      const j = (Math.floor(m * f) + s) % m, x = pts[2 * j], y = pts[2 * j + 1];
      const mx = 0.04 * (v.xmax - v.xmin), my = 0.04 * (v.ymax - v.ymin);
      if (x > v.xmin + mx && x < v.xmax - mx && y > v.ymin + my && y < v.ymax - my) return [x, y];
    }
    return null;
  }

  // the legend follows the drawing: the same colours and dash patterns as the polylines above
  const legendEl = legend([]);
  legendEl.dataset.legendFor = 'curve';
  function refreshLegend() {
    setLegendItems(legendEl, [
      { label: 'Lᵃ, the curve for the current a', color: PALETTE.curve },
      state.showB && { label: 'a = 1/6: the cubic B-spline', color: PALETTE.accent, kind: 'dashed', dash: [10, 6] },
      state.showInterp && { label: 'a = 0: the interpolating curve', color: PALETTE.second, kind: 'dashed', dash: [3, 5] },
      ...family.map(({ v }, k) => ({ label: `${state.family.key} = ${fmt(v, 2)}${isCurrent(v) ? ' (the current curve)' : ''}`, color: familyColor(v, k) })),
      { label: 'data polygon W₋₁ … Wₙ₊₂', color: PALETTE.polygon, kind: 'dashed', dash: [8, 6] },
      { label: 'data W₁…Wₙ (drag)', color: PALETTE.control, kind: 'dot' },
      { label: 'auxiliary W₋₁, W₀, Wₙ₊₁, Wₙ₊₂', color: PALETTE.muted, kind: 'dot' },
      state.showBuild && { label: 'how it is built: cubic polygon C₀…C₂ₙ, even vertices ◆', color: PALETTE.highlight, alpha: 0.9 },
      state.showBuild && { label: 'joints Rᵢ ■', color: PALETTE.second, kind: 'dot' },
      state.showComb && main && { label: 'curvature comb', color: PALETTE.sky, kind: 'thin' },
      state.eq5Printed && printed && { label: 'eq. (5) as printed (misses the data)', color: PALETTE.control, kind: 'dashed', dash: [6, 4] },
    ]);
  }
  L.plots.appendChild(legendEl);

  // ---------- basis functions ----------
  const basisPlot = createPlot(L.plots, {
    ariaLabel: 'The B2 blending functions Lⱼ(u) for the current options',
    height: 220, pan: false, zoom: false, xLabel: 'u',
    view: { xmin: 0, xmax: 1, ymin: -0.3, ymax: 1.15 },
    describe: () => (basis ? `${basis.count} blending functions over u in [${fmt(basis.domain[0], 2)}, ${fmt(basis.domain[1], 2)}]; they sum to 1.` : 'no basis'),
    draw(g, plot) {
      if (!basis) return;
      const cnt = basis.count, P = basis.params, V = basis.values, np = P.length;
      const line = new Float64Array(2 * np);
      for (let j = 0; j < cnt; j++) {
        for (let r = 0; r < np; r++) { line[2 * r] = P[r]; line[2 * r + 1] = V[r * cnt + j]; }
        plot.polyline(line, { color: SERIES[j % SERIES.length], width: 2 });
      }
      for (const u of basis.jointParams) plot.vline(u, { color: '#bdbdbd', width: 1, dash: [3, 4] });
      plot.hline(0, { color: PALETTE.axis, width: 1 });
      plot.hline(1, { color: '#bdbdbd', width: 1, dash: [3, 4] });
    },
  });
  basisPlot.canvas.dataset.plot = 'basis';

  // ---------- curvature ----------
  const kappaPlot = createPlot(L.plots, {
    ariaLabel: 'Signed curvature of the curve along its parameter',
    height: 170, pan: false, zoom: false, xLabel: 'u', yLabel: 'κ',
    view: { xmin: 0, xmax: 1, ymin: -1, ymax: 1 },
    describe: () => 'Signed curvature κ(u) of the current curve.',
    draw(g, plot) {
      if (!main || !main.curvature) return;
      const P = main.params, K = main.curvature, line = new Float64Array(2 * P.length);
      for (let i = 0; i < P.length; i++) { line[2 * i] = P[i]; line[2 * i + 1] = K[i]; }
      plot.polyline(line, { color: PALETTE.curve, width: 2 });
      for (const u of main.jointParams) plot.vline(u, { color: '#bdbdbd', width: 1, dash: [3, 4] });
    },
  });
  kappaPlot.canvas.dataset.plot = 'curvature';

  function fitSidePlots() {
    if (basis) {
      let lo = 0, hi = 1;
      for (const v of basis.values) { if (v < lo) lo = v; if (v > hi) hi = v; }
      basisPlot.setView({ xmin: basis.domain[0], xmax: basis.domain[1], ymin: lo - 0.08, ymax: hi + 0.08 });
    }
    if (main && main.curvature) {
      let lo = 0, hi = 0;
      for (const k of main.curvature) { lo = Math.min(lo, k); hi = Math.max(hi, k); }
      const pad = 0.1 * (hi - lo || 1);
      kappaPlot.setView({ xmin: main.domain[0], xmax: main.domain[1], ymin: lo - pad, ymax: hi + pad });
    }
  }

  // ---------- controls ----------
  const aCtl = slider({
    label: 'Approximation a', name: 'a', min: -0.1, max: 0.25, step: 0.001, value: state.a, number: true,
    ticks: [{ value: 0, label: '0 interpolates' }, { value: 1 / 6, label: '1/6 B-spline' }],
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
    range: () => (main ? [main.domain[0], main.domain[1]] : [0, 1]), get: () => state.u,
    set(v) { state.u = v; computeAtU(); refreshReadouts(); steps?.refresh(); curvePlot.redraw(); },
    onPause() { ctx.save(); },
  });
  const tensionOut = readout({ label: 'Tensions p₀…pₙ used' });
  const domainOut = readout({ label: 'Domain' });
  const claimOut = readout({ label: 'Printed: “a = 1/6, p = 0 gives the B-spline”' });
  claimOut.el.dataset.readout = 'claim-bspline';
  const claimNote = h('p', { class: 'ctl-hint' }, 'How far the even vertices C₂ᵢ with p = 0 (what the printed claim uses) are from those of the B-spline, on the current knots: 0 only on uniform knots. SplineLab reaches the B-spline through the §5 blend. ', correctionLink('correction-000-bspline', 'The correction'));
  if (options.locked) { addBtn.setDisabled(true); removeBtn.setDisabled(true); }

  // ---------- step by step: the construction ----------
  steps = stepper({
    title: 'How the curve is built',
    hint: 'For the current a and tension. The numbers are shown for the joint nearest the evaluation point u (Play u to move it).',
    steps: buildSteps,
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
    group('Correction: eq. (5)', eq5Ctl.el, eq5Out.el, h('p', { class: 'ctl-hint' }, 'The printed weights do not sum to 1 where the spans around a joint differ, so the curve misses the data there (0 on uniform knots). ', correctionLink('correction-000-eq5', 'The correction'))),
  );
  // "Use my data" (www/lib/data-import.js): your data W₁…Wₙ; the end points W₋₁, W₀, Wₙ₊₁, Wₙ₊₂ are reflected
  if (!options.locked) L.controls.append(group('Your data', dataImport({ label: 'Use my data points', apply: 'Fit these points', min: 2, max: MAX_POINTS - 4, onData(d) {
    const e0 = d[0], e1 = d[d.length - 1];
    state.points = [e0, e0, ...d, e1, e1].map((q) => q.slice());
    Object.assign(state, { autoEnds: true, family: null, preset: '' });
    sanitize(); refreshControls(); recompute(); fitSidePlots(); state.view = [];
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 40); ctx.save();
  } }).el));

  function refreshReadouts() {
    if (printed && build) {
      const r = Array.from(printed.jointResiduals), w = printed.eq5Weights;
      let worst = 0, at = 0, sum = 1;
      r.forEach((x, k) => { if (x > worst) { worst = x; at = k; } });
      if (w.length >= 3 * (at + 1)) sum = w[3 * at] + w[3 * at + 1] + w[3 * at + 2];
      eq5Out.set(worst < 1e-12 ? 'weights sum to 1 here (equal spans): same curve'
        : `misses W${sub(at + 1)} by ${fmt(worst, 4)} (its weights sum to ${fmt(sum, 4)}); corrected: ${fmt(Math.max(...Array.from(build.jointResiduals)), 4)}`);
    } else eq5Out.set('—');
    uOut.set(atU ? `u = ${fmt(state.u, 3)}: L(u) = (${fmt(atU[0], 3)}, ${fmt(atU[1], 3)})` : '—');
    if (main) {
      tensionOut.set(Array.from(main.tension, (t) => fmt(t, 3)).join(', '));
      claimOut.set(claim === null ? '—' : claim < 1e-12 ? 'off by 0: holds' : `off by ${fmt(claim, 4)}: fails`);
      domainOut.set(`[${fmt(main.domain[0], 3)}, ${fmt(main.domain[1], 3)}], n = ${main.joints.length / 2}`);
    }
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
    presetNote.textContent = state.preset && PRESETS[state.preset] ? PRESETS[state.preset].note : '';
  }

  function applyPreset(id) {
    const pr = PRESETS[id];
    Object.assign(state, defaults(), { showB: state.showB, showInterp: state.showInterp, showBuild: state.showBuild }, JSON.parse(JSON.stringify(pr.state)), { preset: id });
    if (pr.state.family) { state.showB = false; state.showInterp = false; }
    sanitize();
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
    return curvePlot.boundsOf(state.points, main ? main.points : null, state.showBuild && main ? main.controlPoints : null);
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
  const editing = pointEditing(curvePlot, {
    group: dataHandles, points: () => state.points, locked: options.locked, notify,
    canAdd: () => m() < MAX_POINTS, canRemove: () => m() > minPts(),
    maxText: () => `At most ${MAX_POINTS - 4} data points.`,
    minText: () => `The curve needs at least ${minPts() - 4} data points: this is the minimum.`,
    insert(i, q) {
      state.points.splice(Math.min(m() - 2, Math.max(2, i)), 0, q);
      state.preset = ''; refreshControls(); recompute(); fitSidePlots(); ctx.save();
    },
    remove(i) { state.points.splice(i + 2, 1); state.preset = ''; refreshControls(); recompute(); fitSidePlots(); ctx.save(); },
  });

  function removePoint() {
    if (m() <= minPts()) { notify(`The curve needs at least ${minPts() - 4} data points: this is the minimum.`, 'info'); return; }
    const sel = curvePlot.selected;
    const i = sel && sel.group === dataHandles ? sel.index + 2 : m() - 3;
    state.points.splice(i, 1);
    curvePlot.select(null);
    state.preset = '';
    refreshControls(); recompute(); fitSidePlots(); ctx.save();
  }

  // ---------- the construction, step by step (every number from b2Curve) ----------
  const num = (x, d = 3) => fmt(x, d);
  const at = (flat, j) => [flat[2 * j], flat[2 * j + 1]];
  const pt = (q) => `(${num(q[0])}, ${num(q[1])})`;
  /** The joint i (1…n) nearest the evaluation point u: its numbers fill the formulas. */
  function focus() {
    if (!build) return 1;
    const jp = build.jointParams;
    let best = 0;
    for (let k = 1; k < jp.length; k++) if (Math.abs(jp[k] - state.u) < Math.abs(jp[best] - state.u)) best = k;
    return best + 1;
  }
  const W = (j) => state.points[j + 1];   // W_j, j = −1…n+2
  const ix = (j) => String(j);           // index text (negative indices are fine in TeX)
  const comb = (ws, names) => ws.map((w, k) => `${k && w >= 0 ? '+ ' : k ? '- ' : ''}${num(k ? Math.abs(w) : w, 4)}\\,${names[k]}`).join(' ');

  function buildSteps() {
    if (!build) return [];
    const n = build.joints.length / 2, i = focus(), dk = build.dataKnots, sec3 = state.construction === 'section3';
    const out = [];
    // 1. data and knots
    out.push({
      label: 'the data W₁ … Wₙ and their knots',
      tex: [
        sec3 || state.knots === 'uniform' ? 'u_{j} = j - 1 \\quad (\\text{uniform knots})' : '\\Delta_{j} = u_{j+1} - u_{j} = \\lVert W_{j+1} - W_{j} \\rVert, \\quad u_{1} = 0',
        `u_{${i - 1}}, u_{${i}}, u_{${i + 1}}, u_{${i + 2}} = ${[i - 1, i, i + 1, i + 2].map((j) => num(dk[j + 1])).join(', ')}`,
        `W_{${i}} = ${pt(W(i))}, \\quad n = ${n}`,
      ],
      note: `${n} data points W₁ … W${sub(n)} (circled); the curve will run over [u₁, u${sub(n)}].`,
    });
    // 2. auxiliary points
    out.push({
      label: 'the auxiliary end points',
      tex: state.autoEnds
        ? ['W_{0} = 2W_{1} - W_{2}, \\quad W_{-1} = 2W_{1} - W_{3}', `W_{0} = ${pt(W(0))}, \\quad W_{-1} = ${pt(W(-1))}`]
        : [`W_{-1} = ${pt(W(-1))}, \\quad W_{0} = ${pt(W(0))}`, `W_{${n + 1}} = ${pt(W(n + 1))}, \\quad W_{${n + 2}} = ${pt(W(n + 2))}`],
      note: state.autoEnds ? 'Automatic ends: the data reflected through W₁ and Wₙ.' : 'Free (drag the grey squares): they steer the curve’s ends, which it does not pass through.',
    });
    // 3. joints
    const jw = Array.from(build.jointWeights.slice(3 * (i - 1), 3 * i));
    out.push({
      label: 'the joints Rᵢ',
      tex: [
        sec3 ? 'R_{i} = a\\,W_{i-1} + (1 - 2a)\\,W_{i} + a\\,W_{i+1}' : 'R_{i} = 6a\\,W^{B}_{i} + (1 - 6a)\\,W_{i}, \\quad W^{B}_{i} = L^{B}(u_{i})',
        `a = ${num(state.a, 4)}: \\quad R_{${i}} = ${comb(jw, [`W_{${ix(i - 1)}}`, `W_{${i}}`, `W_{${i + 1}}`])}`,
        `R_{${i}} = ${pt(at(build.joints, i - 1))}`,
      ],
      note: state.a === 0 ? 'a = 0: the joints are the data — the curve will interpolate.' : 'a ≠ 0: the joints move off the data towards the B-spline’s points.',
    });
    // 4. even vertices
    const ew = Array.from(build.evenWeights.slice(4 * i, 4 * i + 4));
    out.push({
      label: 'the even vertices C₂ᵢ (tension)',
      tex: [
        sec3 ? 'C_{2i} = -p\\,W_{i-1} + (\\frac{1}{2} + p)(W_{i} + W_{i+1}) - p\\,W_{i+2}'
          : 'C_{2i} = -p^{-}_{i}W_{i-1} + (\\frac{1}{2} + p^{-}_{i})W_{i} + (\\frac{1}{2} + p^{+}_{i})W_{i+1} - p^{+}_{i}W_{i+2}',
        sec3 ? `p = ${num(state.p, 4)}` : `p^{\\pm}_{i} = \\frac{6p_{i}\\Delta_{i}^{2}}{\\Delta_{i}^{2} + 5\\Delta_{i}\\Delta_{i\\pm1} + ${state.c2}\\,\\Delta_{i\\pm1}^{2}}, \\quad p_{${i}} = ${num(build.tension[i], 4)}`,
        `C_{${2 * i}} = ${comb(ew, [`W_{${ix(i - 1)}}`, `W_{${i}}`, `W_{${i + 1}}`, `W_{${i + 2}}`])}`,
        `C_{${2 * i}} = ${pt(at(build.controlPoints, 2 * i))}`,
      ],
      note: state.a === 0 ? 'The weights on the outer points are −p⁻ᵢ and −p⁺ᵢ (eqs. (8), (9)).' : 'With a ≠ 0 these weights are blended with those of the B-spline (section 5).',
    });
    // 5. odd vertices by eq. (5): the cubic control polygon
    const w5 = Array.from(build.eq5Weights.slice(3 * (i - 1), 3 * i));
    const wp = printed ? printed.eq5Weights[3 * (i - 1) + 2] : NaN;
    out.push({
      label: 'the odd vertices: the cubic control polygon',
      tex: [
        'R_{i} = w_{0}\\,C_{2i-2} + w_{1}\\,C_{2i-1} + w_{2}\\,C_{2i} \\quad (5)',
        `w_{0}, w_{1}, w_{2} = ${w5.map((w) => num(w, 4)).join(', ')}`,
        `C_{${2 * i - 1}} = \\frac{R_{${i}} - ${num(w5[0], 4)}\\,C_{${2 * i - 2}} - ${num(w5[2], 4)}\\,C_{${2 * i}}}{${num(w5[1], 4)}}`,
        `C_{${2 * i - 1}} = ${pt(at(build.controlPoints, 2 * i - 1))}`,
        `w_{2} = \\frac{b^{2}}{(b+c)(b+c+d)} = ${num(w5[2], 4)}`,
        `\\text{printed:}\\; w_{2} = \\frac{bc}{(b+c)(b+c+d)} = ${num(wp, 4)}`,
      ],
      note: `(a, b, c, d) are the four knot spans around the joint. ${Math.abs(wp - w5[2]) < 1e-12 ? 'Here b = c, so the printed weight happens to agree.' : 'The printed weight differs here: switch on “Also draw eq. (5) as printed” to see the curve miss the data.'}`,
    });
    // 6. the curve
    const ju = build.jointParams[i - 1];
    out.push({
      label: 'the curve: a cubic B-spline on the split knots',
      tex: [
        `L^{a}(u) = \\sum_{j=0}^{${2 * n}} N_{j,3}(u)\\,C_{j}, \\quad u \\in [${num(build.domain[0])}, ${num(build.domain[1])}]`,
        `L^{a}(${num(ju)}) = R_{${i}} = ${pt(at(build.joints, i - 1))}`,
      ],
      note: 'C² everywhere: the split knots u′ halve every data span, so the 2n + 1 control points make 2n − 2 cubic pieces.',
    });
    return out;
  }

  function drawStepLines(plot) {
    const s = state.step;
    if (s < 0 || !build) return;
    const i = focus();
    if (s === 3) for (const j of [i - 1, i, i + 1, i + 2]) plot.polyline([at(build.controlPoints, 2 * i), W(j)], { color: PALETTE.highlight, width: 1.5, dash: [4, 4] });
    if (s >= 4) plot.polyline(build.controlPoints, { color: PALETTE.highlight, width: s === 4 ? 2.5 : 1.5, alpha: 0.9 });
    if (s === 4) plot.polyline([at(build.controlPoints, 2 * i - 2), at(build.controlPoints, 2 * i - 1), at(build.controlPoints, 2 * i)], { color: PALETTE.accent, width: 5, alpha: 0.6 });
  }

  function drawStepMarks(plot) {
    const s = state.step;
    if (s < 0 || !build) return;
    const n = build.joints.length / 2, i = focus(), font = '600 13px system-ui, sans-serif';
    if (s === 0) plot.points(state.points.slice(2, -2), { color: PALETTE.accent, radius: 11, hollow: true });
    if (s === 1) plot.points([W(-1), W(0), W(n + 1), W(n + 2)], { color: PALETTE.accent, radius: 11, hollow: true });
    if (s >= 2) {
      plot.points(build.joints, { color: PALETTE.second, radius: s === 2 ? 6 : 4.5, shape: 'square', stroke: '#fff' });
      const r = at(build.joints, i - 1);
      if (s === 2 || s === 5) plot.label(r[0], r[1], mathText(`R_{${i}}`), { color: '#0b5e45', offset: [10, 18], baseline: 'top', font });
    }
    if (s >= 3) {
      plot.points(build.evenVertices, { color: PALETTE.highlight, radius: s === 3 ? 7 : 5, shape: 'diamond' });
      const c = at(build.controlPoints, 2 * i);
      if (s === 3 || s === 4) plot.label(c[0], c[1], mathText(`C_{${2 * i}}`), { color: '#7a3a63', offset: [10, -10], font });
    }
    if (s >= 4) {
      const odd = [];
      for (let j = 1; j < build.controlPoints.length / 2; j += 2) odd.push(at(build.controlPoints, j));
      plot.points(odd, { color: PALETTE.highlight, radius: s === 4 ? 5 : 3.5, hollow: true });
      const c = at(build.controlPoints, 2 * i - 1);
      if (s === 4) plot.label(c[0], c[1], mathText(`C_{${2 * i - 1}}`), { color: '#7a3a63', offset: [10, -10], font });
    }
  }

  // ---------- explanation ----------
  explanation(L.explain, {
    what: [
      'Kuklišová\'s B2-splines are cubic B-splines whose control polygon C₀ … C₂ₙ is built from the data W₋₁ … Wₙ₊₂. The odd vertices are replaced by joints Rᵢ — points the curve passes through — and the even vertices C₂ᵢ come from four neighbouring data points with a tension pᵢ. With Rᵢ = Wᵢ the curve interpolates the data (a = 0); blending the joints and even vertices with those of the cubic B-spline on W₀ … Wₙ₊₁ gives a whole family Lᵃ that reaches the B-spline at a = 1/6 and is C² for every a.',
      'The knots are Farin\'s split knots: each chord-length span [uᵢ, uᵢ₊₁] is halved, so the cubic has 2n − 2 pieces on [u₁, uₙ]. The basis plot shows the blending functions Lⱼ(u) with Σⱼ Lⱼ = 1 (at a = 0, Lⱼ(uᵢ) = δᵢⱼ); the curvature plot shows κ(u) — continuous, because the curve is C².',
      ['Corrections used here (', correctionLink('correction-000-eq5', 'eq. (5)'), ', ', correctionLink('correction-000-bspline', '“a = 1/6, p = 0 gives the B-spline”'), ', ', correctionLink('correction-000-eq8', 'eq. (8)'), ', ', correctionLink('correction-000-autotension', 'automatic tension'), '): the last weight of eq. (5) is Δ²₂ᵢ₋₁/((Δ₂ᵢ₋₁+Δ₂ᵢ)(Δ₂ᵢ₋₁+Δ₂ᵢ+Δ₂ᵢ₊₁)) (the printed one does not sum to 1); the paper\'s "a = 1/6, p = 0 gives the B-spline" holds only through the section-5 blend on non-uniform knots.'],
    ],
    math: [
      'R_{i} = W_{i} \\;(a = 0), \\quad C_{2i} = -p^{-}_{i}W_{i-1} + (\\frac{1}{2} + p^{-}_{i})W_{i} + (\\frac{1}{2} + p^{+}_{i})W_{i+1} - p^{+}_{i}W_{i+2} \\quad (8)',
      'p^{-}_{i} = \\frac{6p_{i}\\Delta_{i}^{2}}{\\Delta_{i}^{2} + 5\\Delta_{i}\\Delta_{i-1} + c_{2}\\Delta_{i-1}^{2}}, \\quad p^{+}_{i} \\;\\text{likewise with}\\; \\Delta_{i+1} \\quad (9)',
      'R_{i} = w_{0}C_{2i-2} + w_{1}C_{2i-1} + w_{2}C_{2i}, \\quad w_{2} = \\frac{b^{2}}{(b+c)(b+c+d)} \\quad (5, \\text{corrected})',
      'L^{a} = 6a\\,L^{B} + (1 - 6a)\\,L \\quad (\\text{section 5})',
    ],
    mathLabel: 'The B2-spline construction: eqs. (8), (9), (5) and the section-5 blend',
    tryThis: [
      'Move a from 0 to 1/6: the blue curve leaves the data and lands on the orange dashed B-spline.',
      'Drag a data point: only a few pieces of the curve move (local control).',
      'Try the presets: Fig. 8 shows why uniform knots fail on uneven data and Fig. 10 the chord-length cure; Fig. 13/14 the modified knots.',
      'Switch on "how it is built" to see the joints (squares), even vertices (diamonds) and the full cubic control polygon.',
      'Set a < 0: the curve overshoots the data — the opposite of smoothing.',
      'Step by step: press Step to build the curve stage by stage; the formulas show the weights of the joint nearest u.',
      'Switch on “Also draw eq. (5) as printed” on the Fig. 8 data: the dashed curve misses the data points where long and short spans meet.',
    ],
    paper: meta.paper,
  });

  // ---------- start ----------
  sanitize();
  refreshControls();
  compute();
  computeAtU();
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
    warm() { compute(); computeAtU(); curvePlot.redraw(); basisPlot.redraw(); kappaPlot.redraw(); },
    // for the shell's Export row: the B2-spline's control data (knots, C_0..C_2n, joints, tensions) and samples
    exports() {
      if (!main) return {};
      return {
        json: { domain: main.domain, knots: main.knots, controlPoints: main.controlPoints, joints: main.joints, evenVertices: main.evenVertices, tension: main.tension, samples: { params: main.params, points: main.points } },
        csv: { points: main.points, dim: main.dim || 2 },
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------
// (imports are hoisted: this block stays self-contained at the end of the file)
import { code, raw, snippetCode } from '../lib/snippet.js';
import { dataImport } from '../lib/data-import.js';

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
