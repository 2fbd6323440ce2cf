// Demo "Quasi-cubic curves" (quasi-cubic paper §2–3): a quasi-cubic trigonometric B-spline with shape parameter α,
// the cubic B-spline of the same polygon as a ghost, the four basis functions for the current α, and presets
// for the exact shapes (parabola, ellipse, circle, sine) with the analytic curve overlaid and the measured
// maximum deviation. All numbers come from the wasm API (quasiCubicCurve, quasiCubicBasis, quasiCubicPreset,
// quasiCubicShapeCheck, bsplineCurve, bsplineBasis); this module only draws and handles input.

import { h, demoLayout, explanation, fmt, legend } from '../lib/dom.js';
import { math, mathText } from '../lib/mathml.js';
import { stepper } from '../lib/stepper.js';
import { cite, correctionLink } from '../lib/papers-ref.js';
import { createPlot, PALETTE, SERIES, restoreView } from '../lib/plot2d.js';
import { slider, toggle, buttonGroup, button, group, row, readout } from '../lib/controls.js';
import { uPlayer } from '../lib/player.js';
import { pointEditing } from '../lib/point-edit.js';

export const meta = {
  id: 'quasi-cubic-curves',
  title: 'Quasi-cubic curves',
  summary: 'Trigonometric B-splines with a shape parameter α: exact ellipses, circles, parabolas and sines.',
  paper: cite('003', '§2–3 (Props. 3–8); the basis functions are reconstructed'),
};

const MAX_POINTS = 14;
const PRESETS = ['free', 'ellipse', 'circle', 'parabola', 'sine'];
const FREE_POINTS = [[0, 0], [0.8, 2.2], [2.4, 2.6], [3.4, 0.6], [4.8, 0.4], [5.6, 2.4], [7, 2]];

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

/** True when two point lists hold the same points (bookkeeping: which polygon a state carries). */
function samePoints(a, b) {
  return a.length === b.length && a.every((p, i) => p[0] === b[i][0] && p[1] === b[i][1]);
}

/** Segments whose sine relations (x, y residual pairs) are broken. */
function brokenSegments(r) {
  const out = [];
  for (let i = 0; 2 * i + 1 < (r?.length ?? 0); i++) if (r[2 * i] > 1e-9 || r[2 * i + 1] > 1e-9) out.push(i);
  return out;
}

// Which relation of the preset a control point takes part in (for the teaching text).
const CONDITION_TEXT = {
  ellipse: 'b₀ + b₂ = b₁ + b₃: the two diagonals must bisect each other (a parallelogram; the paper’s rhombus puts the axes on the diagonals). The red segment joins the two diagonal midpoints.',
  circle: 'a square: the diagonals bisect each other, have equal length and are perpendicular.',
  parabola: 'b₀ = b₂: the apex is used twice (the paper also asks for an isosceles triangle, which affine invariance makes unnecessary). The red segment joins b₀ and b₂.',
  sine: 'for every four consecutive points: xᵢ + xᵢ₊₃ = xᵢ₊₁ + xᵢ₊₂ (x linear in t) and yᵢ + yᵢ₊₁ = yᵢ₊₂ + yᵢ₊₃ (no linear drift in y).',
};

/** @param {HTMLElement} root @param {import('../lib/host.js').DemoContext} ctx @returns {import('../lib/host.js').MountedDemo} */
export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);
  const series = (i) => SERIES[i % SERIES.length];
  const sub = (i) => String(i).replace(/\d/g, (d) => '₀₁₂₃₄₅₆₇₈₉'[d]);

  // ---------- state sanitising ----------
  function sanitize() {
    if (!PRESETS.includes(state.preset)) state.preset = 'free';
    if (!(state.alpha >= -3 && state.alpha <= 3)) state.alpha = 0.5;
    if (!Array.isArray(state.points) || state.points.length < 4) state.points = FREE_POINTS.map((p) => p.slice());
    if (state.points.length > MAX_POINTS) state.points.length = MAX_POINTS;
    // A link that names a preset but no points gets the defaults' free polygon, which no preset's condition
    // holds for (a sine preset on it reads "broken"): such a state takes the preset's own points (and α).
    // Points a user dragged are never the free polygon exactly, so they stay.
    if (state.preset !== 'free' && samePoints(state.points, FREE_POINTS)) loadPreset(state.preset, false);
    if (state.preset === 'ellipse' || state.preset === 'circle') { state.closed = true; if (state.points.length !== 4) loadPreset(state.preset, false); }
    if (state.preset === 'parabola') { state.closed = false; if (state.points.length !== 4) loadPreset('parabola', false); }
    if (state.preset === 'sine') state.closed = false;
    if (!Number.isInteger(state.step) || state.step < -1 || state.step > 4) state.step = -1;
  }

  // ---------- computed data (from wasm) ----------
  let curve = null, ghost = null, basis = null, ghostBasis = null, check = null;

  function ghostPolygon() {
    // the uniform cubic B-spline of the same polygon (closed: the polygon wrapped by three points)
    const P = state.points;
    return state.closed ? [...P, P[0], P[1], P[2]] : P;
  }

  const segs = () => (state.closed ? state.points.length : state.points.length - 3);
  let atU = null; // the evaluation point C(u) ("Play u")
  function computeAtU() {
    state.u = Math.min(segs(), Math.max(0, Number.isFinite(state.u) ? state.u : 0));
    try {
      const r = wasm.quasiCubicCurve({ points: state.points, alpha: state.alpha, closed: state.closed, at: [state.u] });
      atU = [r.points[0], r.points[1]];
    } catch (e) { atU = null; }
  }
  function compute() {
    computeAtU();
    try {
      curve = wasm.quasiCubicCurve({ points: state.points, alpha: state.alpha, closed: state.closed, samples: 60 * state.points.length });
    } catch (e) { curve = null; notify(e, 'error'); }
    try {
      const gp = ghostPolygon();
      const knots = Array.from({ length: gp.length + 4 }, (_, i) => i);
      ghost = state.showGhost ? wasm.bsplineCurve({ degree: 3, knots, points: gp, samples: 60 * gp.length }) : null;
    } catch (e) { ghost = null; notify(e, 'error'); }
    try {
      check = state.preset === 'free' ? null
        : wasm.quasiCubicShapeCheck({ shape: state.preset, points: state.points, alpha: state.alpha, samples: 200 });
    } catch (e) { check = null; notify(e, 'error'); }
  }
  function computeBasis() {
    try {
      basis = wasm.quasiCubicBasis({ alpha: state.alpha, samples: 201 });
      // the uniform cubic B-spline's four pieces on one span, for comparison (paper Fig. 2)
      const at = Array.from({ length: 101 }, (_, j) => 3 + j / 100);
      ghostBasis = wasm.bsplineBasis({ degree: 3, knots: [0, 1, 2, 3, 4, 5, 6, 7], at });
    } catch (e) { notify(e, 'error'); }
  }

  // ---------- the basis assembled on one segment (stepper) ----------
  // At the evaluation point u (segment i = ⌊u⌋, t = u − i) the four pieces B_j(α; t) and the two bases they
  // blend, B⁰ (α = 0) and B¹ (α = 1), all from the wasm core; the sum is checked over the sampled basis.
  let stepData = null, ready = false;   // ready: the stepper must not clamp the linked step before the data exists
  function computeSteps() {
    try {
      const n = segs(), seg = Math.min(Math.floor(state.u), n - 1), t = state.u - seg;
      const v = wasm.quasiCubicBasis({ alpha: state.alpha, at: [t] }).values;
      const v0 = wasm.quasiCubicBasis({ alpha: 0, at: [t] }).values;
      const v1 = wasm.quasiCubicBasis({ alpha: 1, at: [t] }).values;
      let worst = 0;
      if (basis) for (let j = 0; j < basis.params.length; j++) {
        const sum = basis.values[4 * j] + basis.values[4 * j + 1] + basis.values[4 * j + 2] + basis.values[4 * j + 3];
        worst = Math.max(worst, Math.abs(sum - 1));
      }
      stepData = { seg, t, v: Array.from(v), v0: Array.from(v0), v1: Array.from(v1), worst };
    } catch (e) { stepData = null; }
  }
  const B0TEX = ['\\frac{1-t}{4} - \\sigma', '\\frac{1}{2} - \\frac{t}{4} + \\sigma', '\\frac{1}{4} + \\frac{t}{4} + \\sigma', '\\frac{t}{4} - \\sigma'];
  const B1TEX = ['\\frac{(1-\\sin\\theta)^2}{6}', '\\frac{(1+\\cos\\theta)^2}{6}', '\\frac{(1+\\sin\\theta)^2}{6}', '\\frac{(1-\\cos\\theta)^2}{6}'];
  const num = (x, d = 4) => (x < 0 ? `(${fmt(x, d)})` : fmt(x, d));
  function basisSteps() {
    if (!stepData) return [];
    const { seg, t, v, v0, v1, worst } = stepData, a = state.alpha;
    const at = `${num(a, 2)};${fmt(t, 3)}`;
    const steps = [0, 1, 2, 3].map((j) => ({
      label: `the piece B${sub(j)}, weight of b${sub(seg + j)} on segment ${seg}`,
      tex: [
        `B_${j}(\\alpha;t) = (1-\\alpha)\\,B^0_${j}(t) + \\alpha\\,B^1_${j}(t)`,
        `B^0_${j} = ${B0TEX[j]}, \\quad B^1_${j} = ${B1TEX[j]}`,
        `\\theta = \\frac{\\pi t}{2}, \\quad \\sigma = \\frac{\\sin \\pi t}{4\\pi}`,
        `B_${j}(${at}) = (1-${num(a, 2)})\\cdot ${num(v0[j])}`,
        `+ ${num(a, 2)}\\cdot ${num(v1[j])} = ${num(v[j])}`,
      ],
      note: `At the evaluation point u = ${fmt(state.u, 3)} (segment ${seg}, t = ${fmt(t, 3)}); move it with Play u.`,
    }));
    const sum = v[0] + v[1] + v[2] + v[3];
    steps.push({
      label: 'their sum: a partition of unity',
      tex: [
        `\\sum_{j=0}^{3} B_j(${at}) = ${fmt(sum, 12)}`,
        `= ${v.map((x, i) => (i ? (x < 0 ? `- ${fmt(-x, 4)}` : `+ ${fmt(x, 4)}`) : fmt(x, 4))).join(' ')}`,
        `\\max_{t} \\left| \\sum_j B_j(${num(a, 2)};t) - 1 \\right| = ${worst === 0 ? '0' : worst.toExponential(1)}`,
      ],
      note: `The curve point is ${mathText(`p(u) = \\sum_j B_j b_{${seg}+j}`)}: an affine combination, so the curve moves with its polygon. Measured over ${basis ? basis.params.length : 0} values of t.`,
    });
    return steps;
  }
  const steps = stepper({
    title: 'The basis, step by step',
    hint: 'The four trigonometric pieces on one segment, then their sum, with the current α and the evaluation point.',
    steps: basisSteps,
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
    describe: () => `Quasi-cubic curve, α = ${fmt(state.alpha, 2)}, ${state.closed ? 'closed' : 'open'}, ${state.points.length} control points. ` +
      (check ? `Preset ${state.preset}: maximum deviation from the analytic curve ${check.deviation.toExponential(2)}.` : ''),
    onView(v) { state.view = [v.xmin, v.xmax, v.ymin, v.ymax]; ctx.save(); },
    draw(g, plot) {
      const P = state.points;
      if (state.showPolygon) plot.polyline(P, { color: PALETTE.polygon, width: 1.75, dash: [8, 6], close: state.closed });
      if (ghost) plot.polyline(ghost.points, { color: PALETTE.muted, width: 2.5, dash: [3, 5] });
      if (check) {
        plot.polyline(check.analytic, { color: PALETTE.accent, width: 7, alpha: 0.45 });
        drawCondition(plot);
      }
      if (curve) plot.polyline(curve.points, { color: PALETTE.curve, width: 3 });
    },
    drawOver(g, plot) {
      const sd = stepData, st = state.step;
      if (sd && st >= 0 && st < 4) {
        const P = state.points, q = P[(sd.seg + st) % P.length];
        const [X, Y] = plot.toScreen(q[0], q[1]);
        g.beginPath(); g.arc(X, Y, 16, 0, 2 * Math.PI); g.lineWidth = 3.5; g.strokeStyle = series((sd.seg + st) % P.length); g.stroke();
        plot.label(q[0], q[1], mathText(`B_${st} = ${fmt(sd.v[st], 3)}`), { offset: [18, -14], font: '700 13px system-ui, sans-serif' });
      }
      if (!atU || !(state.u > 0 || player.playing)) return;
      plot.points([atU], { color: PALETTE.ink, radius: 6, shape: 'diamond', stroke: '#fff' });
      plot.label(atU[0], atU[1], `p(${fmt(state.u, 2)})`, { offset: [10, 20], baseline: 'top' });
    },
  });
  curvePlot.canvas.dataset.plot = 'curve';

  function drawCondition(plot) {
    const P = state.points, bad = PALETTE.control;
    if ((state.preset === 'ellipse' || state.preset === 'circle') && P.length === 4) {
      plot.segment(P[0][0], P[0][1], P[2][0], P[2][1], { color: PALETTE.muted, width: 1, dash: [2, 4] });
      plot.segment(P[1][0], P[1][1], P[3][0], P[3][1], { color: PALETTE.muted, width: 1, dash: [2, 4] });
      const m1 = [(P[0][0] + P[2][0]) / 2, (P[0][1] + P[2][1]) / 2], m2 = [(P[1][0] + P[3][0]) / 2, (P[1][1] + P[3][1]) / 2];
      if (check.conditionResidual > 1e-9) plot.segment(m1[0], m1[1], m2[0], m2[1], { color: bad, width: 3 });
      plot.points([m1, m2], { color: check.conditionResidual > 1e-9 ? bad : PALETTE.second, radius: 4 });
    } else if (state.preset === 'parabola' && P.length === 4 && check.conditionResidual > 1e-9) {
      plot.segment(P[0][0], P[0][1], P[2][0], P[2][1], { color: bad, width: 3 });
    } else if (state.preset === 'sine') {
      // ring the four points of every segment whose relation is broken
      const r = check.segmentResiduals, g = plot.g;
      for (const i of brokenSegments(r)) {
        for (let j = i; j < i + 4 && j < P.length; j++) {
          const [X, Y] = plot.toScreen(P[j][0], P[j][1]);
          g.beginPath(); g.arc(X, Y, 15, 0, 2 * Math.PI); g.lineWidth = 2.5; g.strokeStyle = bad; g.stroke();
        }
      }
    }
  }

  const handles = curvePlot.addHandles({
    name: 'control point',
    points: () => state.points,
    colorOf: (i) => series(i),
    label: (i) => `b${sub(i)}`,
    labelOf: (i) => `Control point b${i}`,
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
    describe: () => basis ? `Basis at α = ${fmt(state.alpha, 2)}: at t = 0 the values are ${Array.from(basis.values.slice(0, 4), (v) => fmt(v, 3)).join(', ')}.` : 'Basis functions',
    draw(g, plot) {
      plot.hline(0, { color: PALETTE.axis, width: 1 });
      if (ghostBasis) {
        const m = ghostBasis.params.length, cnt = ghostBasis.count;
        for (let i = 0; i < 4; i++) {
          const line = new Float64Array(2 * m);
          // on the span [3, 4] the non-zero functions are N₀..N₃; piece i of the curve weights b_{j+i} with N_i
          for (let j = 0; j < m; j++) { line[2 * j] = ghostBasis.params[j] - 3; line[2 * j + 1] = ghostBasis.values[j * cnt + i]; }
          plot.polyline(line, { color: series(i), width: 1.5, dash: [4, 5], alpha: 0.8 });
        }
      }
      if (!basis) return;
      const m = basis.params.length;
      const st = state.step, sd = stepData;
      if (st >= 0 && sd) plot.segment(sd.t, -0.1, sd.t, 1.05, { color: PALETTE.muted, width: 1.5, dash: [4, 4] });
      if (st === 4) {
        // the sum, sampled, and the four values at t stacked up to it
        const line = new Float64Array(2 * m);
        for (let j = 0; j < m; j++) { line[2 * j] = basis.params[j]; line[2 * j + 1] = basis.values[4 * j] + basis.values[4 * j + 1] + basis.values[4 * j + 2] + basis.values[4 * j + 3]; }
        plot.polyline(line, { color: PALETTE.ink, width: 4 });
        plot.label(0.5, 1, mathText('\\sum_j B_j = 1'), { offset: [0, -6], align: 'center', baseline: 'bottom', font: '700 13px system-ui, sans-serif' });
        if (sd) {
          let y = 0;
          for (let i = 0; i < 4; i++) {
            plot.segment(sd.t, y, sd.t, y + sd.v[i], { color: series(i), width: 10 });
            y += sd.v[i];
          }
        }
      }
      for (let i = 0; i < 4; i++) {
        const line = new Float64Array(2 * m);
        for (let j = 0; j < m; j++) { line[2 * j] = basis.params[j]; line[2 * j + 1] = basis.values[4 * j + i]; }
        const on = st === i, dim = st >= 0 && st < 4 && !on;
        if (on) plot.polyline(line, { color: series(i), width: 11, alpha: 0.25 });
        plot.polyline(line, { color: series(i), width: on ? 4.5 : 3, alpha: dim ? 0.25 : 1 });
        if (on && sd) {
          plot.points([[sd.t, sd.v[i]]], { color: series(i), radius: 7, stroke: '#fff' });
          plot.label(sd.t, sd.v[i], mathText(`B_${i} = ${fmt(sd.v[i], 4)}`), { color: series(i), offset: [10, -8], font: '700 13px system-ui, sans-serif' });
        }
        let best = -Infinity, bj = 0;
        for (let j = 0; j < m; j++) if (line[2 * j + 1] > best) { best = line[2 * j + 1]; bj = j; }
        plot.label(line[2 * bj], best, `B${sub(i)}`, { color: series(i), offset: [0, -4], align: 'center', font: '600 13px system-ui, sans-serif' });
      }
    },
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
  function refreshU() { uOut.set(atU ? `u = ${fmt(state.u, 3)}: p(u) = (${fmt(atU[0], 3)}, ${fmt(atU[1], 3)})` : '—'); }
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
      try {
        const p = wasm.quasiCubicPreset({ name });
        state.preset = name;
        state.points = p.points.map((q) => [q[0], q[1]]);
        state.closed = p.closed;
        state.alpha = p.alpha;
      } catch (e) { notify(e, 'error'); return; }
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
    curvePlot.fitBounds(curvePlot.boundsOf(state.points, curve ? curve.points : [], check ? check.analytic : []), 56);
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

  // ---------- explanation ----------
  explanation(L.explain, {
    what: [
      ['Each segment of a quasi-cubic curve blends four consecutive control points with trigonometric basis functions: ', math('p_i(t) = \\sum_j B_j(\\alpha;t)\\, b_{i+j}, \\; t \\in [0,1]'), '. Like the cubic B-spline (dotted grey), the segments join with continuous first and second derivatives for every α — but the basis contains ', math('\\sin\\frac{\\pi t}{2}, \\cos\\frac{\\pi t}{2}, \\sin \\pi t, \\cos \\pi t'), ', so some curves that no polynomial spline can draw come out exactly.'],
      'The presets show them: at α = 1 a rhombus (any parallelogram) gives an ellipse and a square a circle; an isosceles triangle used as b₀, b₁, b₀, b₃ gives a parabola; at α = 0 a zig-zag with the right symmetry gives a sine wave. The orange band is the analytic curve, and the deviation printed on the right is measured by the wasm core over the whole curve: about 1e-16 when the condition holds. Drag a point or move α and watch it grow.',
    ],
    math: [
      'B(\\alpha;t) = (1-\\alpha)\\,B^0(t) + \\alpha\\,B^1(t), \\quad \\theta = \\frac{\\pi t}{2}',
      'B^1 = \\frac{1}{6}\\left[ (1-\\sin\\theta)^2, (1+\\cos\\theta)^2, (1+\\sin\\theta)^2, (1-\\cos\\theta)^2 \\right]',
      'B^0 = \\left[ \\frac{1-t}{4} - \\sigma, \\frac{1}{2} - \\frac{t}{4} + \\sigma, \\frac{1}{4} + \\frac{t}{4} + \\sigma, \\frac{t}{4} - \\sigma \\right], \\quad \\sigma = \\frac{\\sin \\pi t}{4\\pi}',
      '\\sum_i B_i = 1; \\quad B_i \\ge 0 \\;\\text{exactly for}\\; \\alpha \\in [-3, 1]; \\quad C^2 \\;\\text{joins for every}\\; \\alpha, \\quad C^3 \\;\\text{only at}\\; \\alpha = 1',
      '\\alpha = 1, \\;\\text{square with half-diagonal}\\; d: \\quad |p(t) - c| = \\frac{2d}{3}',
    ],
    tryThis: [
      'Choose Ellipse: the deviation reads about 1e-16. Drag one vertex: the red segment shows the diagonals no longer bisect each other, and the deviation jumps.',
      'Choose Circle and move α away from 1: the curve stays closed and smooth but is no longer round.',
      'Choose Sine and drag one point up: the y-relation of every segment that uses it breaks.',
      'In Free mode, move α from −3 to 3: for α ≤ 1 the curve stays inside the convex hull; at α = 3 it passes through b₁ … bₙ₊₁.',
    ],
    formulaNote: ['Corrections (', correctionLink('correction-003-basis', 'the basis'), ', ', correctionLink('correction-003-bspline', '“includes the B-spline”'), '): the explicit basis formulas are lost from the text and are reconstructed here from the stated properties; no α gives the cubic B-spline, contrary to the abstract.'],
    paper: meta.paper,
  });

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
      if (!curve) return {};
      return {
        json: { alpha: state.alpha, closed: state.closed, controlPoints: state.points, shapeCheck: check, samples: { params: curve.params, points: curve.points } },
        csv: { points: curve.points, dim: curve.dim || 2 },
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------
// (imports are hoisted: this block stays self-contained at the end of the file)
import { code, snippetCode } from '../lib/snippet.js';
import { dataImport } from '../lib/data-import.js';

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
