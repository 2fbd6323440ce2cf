// What "Blended interpolation" draws: the curve plot (data polygon, the α = 3 spline, the BIS, the tangent
// β*ⱼ·p′(j) at the selected point, p(u)) and the curvature plot (κ(u) with the circle curvatures Kⱼ as dots).
// Every function reads the state and the computed c (compute.js) and changes nothing.
import { fmt } from '../../lib/dom.js';
import { curveFactsOf, curveWords } from '../../lib/curve-words.js';
import { PALETTE } from '../../lib/plot2d.js';
import { BETA_MAX, sub } from './data.js';

const segments = (state) => state.points.length - 3;

/** The curve figure in words: the settings, what the drawn BIS does and how close it passes to the data b₀ … bₙ
 * (curveFacts of its samples) and its continuity (C² for k ≥ 3, C¹ for k = 2: ../shared/spec/curves.md). */
export const describeCurve = (state, { bis }, wasm) => `Blended interpolation spline through ${segments(state) + 1} points (k = ${state.k}). β* = ${state.beta.map((b) => fmt(b, 2)).join(', ')}. Selected point b${sub(state.selected)}. ` +
  `${curveWords(curveFactsOf(wasm, bis, state.points.slice(1, -1)), { dataName: (i) => `b${sub(i)}` })} ` +
  (state.k >= 3 ? `At its joints it is C² (k = ${state.k}).` : 'At its joints it is only C¹ (k = 2: the second derivative jumps).');

export const describeCurvature = (state, { bis }) => (bis ? `Curvature at the data points: ${Array.from({ length: segments(state) + 1 }, (_, j) => fmt(bis.curvature[j * Math.round((bis.params.length - 1) / segments(state))], 3)).join(', ')}.` : 'Curvature plot');

/** The curve plot, under the handles. */
export function drawCurve(plot, state, c) {
  const { spline, bis, tangent } = c;
  const P = state.points;
  plot.polyline(P, { color: PALETTE.polygon, width: 1.25, dash: [6, 6], alpha: 0.7 });
  if (spline) plot.polyline(spline.points, { color: PALETTE.muted, width: 2, dash: [3, 5] });
  if (bis) plot.polyline(bis.points, { color: PALETTE.curve, width: 3 });
  if (tangent) {
    const j = state.selected, b = state.beta[j] ?? 1;
    const [x, y] = tangent.at;
    plot.segment(x - tangent.d[0] * 1.5, y - tangent.d[1] * 1.5, x + tangent.d[0] * BETA_MAX, y + tangent.d[1] * BETA_MAX, { color: PALETTE.highlight, width: 1, dash: [2, 4] });
    plot.arrow(x, y, x + b * tangent.d[0], y + b * tangent.d[1], { color: PALETTE.highlight, width: 3 });
    plot.label(x + b * tangent.d[0], y + b * tangent.d[1], `β*${sub(j)} = ${fmt(b, 2)}`, { color: PALETTE.highlight, offset: [10, -10] });
  }
}

/** The curve plot, over the handles: p(u) once u > 0 or playing. */
export function drawCurveOver(plot, state, { atU }, playing) {
  if (!atU || !(state.u > 0 || playing)) return;
  plot.points([atU], { color: PALETTE.ink, radius: 6, shape: 'diamond', stroke: '#fff' });
  plot.label(atU[0], atU[1], `p(${fmt(state.u, 2)})`, { offset: [10, 20], baseline: 'top' });
}

/** The curvature plot: κ(u), the circle curvatures Kⱼ at u = j, the selected point. */
export function drawCurvature(plot, state, { bis }) {
  plot.hline(0, { color: PALETTE.axis, width: 1 });
  if (!bis) return;
  const m = bis.params.length, line = new Float64Array(2 * m);
  for (let j = 0; j < m; j++) { line[2 * j] = bis.params[j]; line[2 * j + 1] = bis.curvature[j]; }
  plot.polyline(line, { color: PALETTE.curve, width: 2.5 });
  const K = bis.circleCurvature;
  plot.points(Array.from(K, (k, j) => [j, k]), { color: PALETTE.control, radius: 4.5, stroke: '#fff' });
  plot.vline(state.selected, { color: PALETTE.highlight, width: 1.5, dash: [3, 4] });
}

/** The curvature plot's view: all of u ∈ [0, n], and κ from 0 and every Kⱼ to the curve's curvature clipped at
 * 2.5·max|Kⱼ| (loops spike far beyond it); null before the first curve. */
export function curvatureView(state, { bis }) {
  if (!bis) return null;
  const n = segments(state);
  const K = Array.from(bis.circleCurvature).filter(Number.isFinite);
  const kmax = Math.max(0.2, ...K.map(Math.abs));
  const lim = 2.5 * kmax;
  let lo = Math.min(0, ...K), hi = Math.max(0, ...K);
  for (const c of bis.curvature) if (Number.isFinite(c)) { lo = Math.min(lo, Math.max(-lim, c)); hi = Math.max(hi, Math.min(lim, c)); }
  const pad = 0.08 * (hi - lo || 1);
  return { xmin: -0.02 * n, xmax: n * 1.02, ymin: lo - pad, ymax: hi + pad };
}
