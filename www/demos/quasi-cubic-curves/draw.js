// What "Quasi-cubic curves" draws: the curve plot (control polygon, the cubic B-spline of the same polygon, a
// preset's analytic shape and what breaks its condition, the quasi-cubic curve, the stepper's control point and
// p(u)) and the basis plot (the four B_j(α; t), the cubic B-spline's pieces dashed, the stepper's piece or sum).
// Every function reads the state and the computed c (compute.js) and changes nothing.
import { fmt } from '../../lib/dom.js';
import { curveFactsOf, curveWords } from '../../lib/curve-words.js';
import { mathText } from '../../lib/mathml.js';
import { PALETTE, SERIES } from '../../lib/plot2d.js';
import { sub, brokenSegments } from './data.js';

/** The colour of B_j and of its control point. */
export const series = (i) => SERIES[i % SERIES.length];

/** The curve figure in words: the settings, what the drawn curve does (curveFacts of its samples), its continuity
 * (C² at every joint for every α: ../shared/spec/curves.md §1) and a preset's deviation. */
export const describeCurve = (state, { check, curve }, wasm) => `Quasi-cubic curve, α = ${fmt(state.alpha, 2)}, ${state.closed ? 'closed' : 'open'}, ${state.points.length} control points. ` +
  `${curveWords(curveFactsOf(wasm, curve))} At its joints it is C² (for every α). ` +
  (check ? `Preset ${state.preset}: maximum deviation from the analytic curve ${check.deviation.toExponential(2)}.` : '');

export const describeBasis = (state, { basis }) => (basis ? `Basis at α = ${fmt(state.alpha, 2)}: at t = 0 the values are ${Array.from(basis.values.slice(0, 4), (v) => fmt(v, 3)).join(', ')}.` : 'Basis functions');

/** The curve plot, under the handles. */
export function drawCurve(g, plot, state, c) {
  const { ghost, check, curve } = c;
  const P = state.points;
  if (state.showPolygon) plot.polyline(P, { color: PALETTE.polygon, width: 1.75, dash: [8, 6], close: state.closed });
  if (ghost) plot.polyline(ghost.points, { color: PALETTE.muted, width: 2.5, dash: [3, 5] });
  if (check) {
    plot.polyline(check.analytic, { color: PALETTE.accent, width: 7, alpha: 0.45 });
    drawCondition(plot, state, check);
  }
  if (curve) plot.polyline(curve.points, { color: PALETTE.curve, width: 3 });
}

/** The curve plot, over the handles: the control point of the stepper's piece B_j and p(u) (shown once u > 0 or playing). */
export function drawCurveOver(g, plot, state, c, playing) {
  const { atU } = c;
  const sd = c.stepData, st = state.step;
  if (sd && st >= 0 && st < 4) {
    const P = state.points, q = P[(sd.seg + st) % P.length];
    const [X, Y] = plot.toScreen(q[0], q[1]);
    g.beginPath(); g.arc(X, Y, 16, 0, 2 * Math.PI); g.lineWidth = 3.5; g.strokeStyle = series((sd.seg + st) % P.length); g.stroke();
    plot.label(q[0], q[1], mathText(`B_${st} = ${fmt(sd.v[st], 3)}`), { offset: [18, -14], font: '700 13px system-ui, sans-serif' });
  }
  if (!atU || !(state.u > 0 || playing)) return;
  plot.points([atU], { color: PALETTE.ink, radius: 6, shape: 'diamond', stroke: '#fff' });
  plot.label(atU[0], atU[1], `p(${fmt(state.u, 2)})`, { offset: [10, 20], baseline: 'top' });
}

/** A preset's condition on the polygon: the diagonals' midpoints (ellipse, circle), b₀ = b₂ (parabola), the broken segments (sine). */
function drawCondition(plot, state, check) {
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

/** The basis plot: the cubic B-spline's pieces dashed, the four B_j(α; t), the stepper's piece or their sum. */
export function drawBasis(plot, state, c) {
  const { ghostBasis, basis } = c;
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
  const st = state.step, sd = c.stepData;
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
}
