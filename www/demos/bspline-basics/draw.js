// What "B-spline basics" draws: the curve plot (control polygon, curve C(u), the piece over u's knot span, rings
// around the p + 1 control points that act at u, the stepper, C(u)) and the basis plot (knot strip, every Nᵢ,ₚ with
// the active ones filled, their sum Σ Nᵢ,ₚ(u) = 1, the line at u). Every function reads the state and the computed
// c (compute.js) and changes nothing.
import { fmt, pair, pairSep } from '../../lib/dom.js';
import { t, tn } from '../../lib/i18n.js';
import { curveFactsOf, curveWords, bsplineContinuityWords } from '../../lib/curve-words.js';
import { PALETTE, SERIES } from '../../lib/plot2d.js';
import { KNOT_ROW, domain, sub } from './state-rules.js';
import { drawStepLines, drawStepMarks } from './steps.js';

/** The colour of Nᵢ,ₚ and of its control point Pᵢ. */
export const series = (i) => SERIES[i % SERIES.length];

/** The curve figure in words: the control points, C(u), what the curve does (curveFacts of the drawn samples) and
 * its continuity at the knots (from the degree and the multiplicities: C^(p−m)). */
export const describeCurve = (state, { atU, curve }, wasm) => `${t('Clamped B-spline of degree {p} with {points}: {list}. Curve point at u = {u}: {at}.', {
  p: state.degree, points: tn(state.points.length, '{n} control point', '{n} control points'),
  list: state.points.map((q, i) => `P${sub(i)} ${pair(q[0], q[1], 2)}`).join(pairSep()), u: fmt(state.u, 3),
  at: atU ? pair(atU.point[0], atU.point[1], 2) : '(?)',
})} ${curveWords(curveFactsOf(wasm, curve))} ${bsplineContinuityWords(state.degree, state.knots)}`;

export const describeBasis = (state, { atU }) => t('Knots: {knots}. At u = {u} the non-zero basis functions are {list}.', {
  knots: state.knots.map((k) => fmt(k, 3)).join(pairSep()), u: fmt(state.u, 3),
  list: atU ? atU.active.map((i) => `N${sub(i)} = ${fmt(atU.values[i], 3)}`).join(pairSep()) : t('unknown'),
});

/** The curve plot, under the handles. */
export function drawCurve(g, plot, state, c) {
  const { curve, spanPiece, atU } = c;
  if (state.showPolygon) plot.polyline(state.points, { color: PALETTE.polygon, width: 1.75, dash: [8, 6] });
  if (curve) plot.polyline(curve.points, { color: PALETTE.curve, width: 3.5 });
  if (spanPiece) plot.polyline(spanPiece, { color: PALETTE.ink, width: 7, alpha: 0.22 });
  if (atU) {
    // rings around the p + 1 control points that act at u
    for (const i of atU.active) {
      const q = state.points[i];
      if (!q) continue;
      const [X, Y] = plot.toScreen(q[0], q[1]);
      g.beginPath(); g.arc(X, Y, 14, 0, 2 * Math.PI);
      g.lineWidth = 3; g.strokeStyle = series(i); g.stroke();
    }
  }
  drawStepLines(plot, state, c);
}

/** The curve plot, over the handles: the stepper's marks and the point C(u). */
export function drawCurveOver(g, plot, state, c) {
  drawStepMarks(g, plot, state, c);
  const { atU } = c;
  if (!atU) return;
  plot.points([atU.point], { color: PALETTE.ink, radius: 7, shape: 'diamond', stroke: '#fff' });
  plot.label(atU.point[0], atU.point[1], `C(${fmt(state.u, 2)})`, { offset: [10, 22], baseline: 'top' });
}

/** The basis plot, under the knot handles. */
export function drawBasis(plot, state, { basis, atU, spanLabel }) {
  const [a, b] = domain(state);
  const k = state.knots;
  // knot strip: a line and the (fixed) end knots
  plot.segment(a, KNOT_ROW, b, KNOT_ROW, { color: PALETTE.axis, width: 2 });
  for (let i = 0; i < k.length; i++) {
    plot.segment(k[i], KNOT_ROW, k[i], 1.05, { color: '#bdbdbd', width: 1, dash: [3, 4] });
  }
  plot.points([[k[0], KNOT_ROW], [k[k.length - 1], KNOT_ROW]], { color: PALETTE.axis, radius: 6, shape: 'square' });
  plot.label(k[0], KNOT_ROW, `u₀…u${sub(state.degree)}`, { offset: [4, 18], baseline: 'top', font: '12px system-ui, sans-serif', color: '#444' });
  // the span of u
  if (spanLabel) plot.fill([[spanLabel[0], 0], [spanLabel[1], 0], [spanLabel[1], 1.05], [spanLabel[0], 1.05]], { color: PALETTE.ink, alpha: 0.06 });
  if (!basis) return;
  const cnt = basis.count, P = basis.params, V = basis.values, m = P.length;
  const active = new Set(atU ? atU.active : []);
  const line = new Float64Array(2 * m);
  for (let i = 0; i < cnt; i++) {
    for (let j = 0; j < m; j++) { line[2 * j] = P[j]; line[2 * j + 1] = V[j * cnt + i]; }
    if (active.has(i)) plot.fillUnder(line, { color: series(i), alpha: 0.16 });
    // (not faded: a faded line falls under 3:1 against white, SC 1.4.11; the active ones stand out by width and fill)
    plot.polyline(line, { color: series(i), width: active.has(i) ? 3.5 : 1.75 });
  }
  if (state.showSum) {
    // partition of unity: the sum of all Nᵢ,ₚ, labelled away from u
    for (let j = 0; j < m; j++) { let s = 0; for (let i = 0; i < cnt; i++) s += V[j * cnt + i]; line[2 * j + 1] = s; }
    plot.polyline(line, { color: PALETTE.ink, width: 2, dash: [10, 6] });
    const jx = Math.round((m - 1) * ((state.u - a) / (b - a || 1) < 0.5 ? 0.78 : 0.12));
    plot.label(P[jx], line[2 * jx + 1], 'Σ Nᵢ,ₚ(u) = 1', { offset: [0, -4], align: 'center', font: '600 13px system-ui, sans-serif' });
  }
  // labels at each function's maximum
  for (let i = 0; i < cnt; i++) {
    let best = 0, bj = 0;
    for (let j = 0; j < m; j++) if (V[j * cnt + i] > best) { best = V[j * cnt + i]; bj = j; }
    if (best > 0.05) plot.label(P[bj], best, `N${sub(i)}`, { color: series(i), offset: [0, -3], align: 'center', font: '600 13px system-ui, sans-serif' });
  }
}

/** The basis plot, over the handles: the line at u and the values of the active Nᵢ,ₚ there. */
export function drawBasisOver(plot, state, { atU }) {
  plot.vline(state.u, { color: PALETTE.ink, width: 2 });
  if (atU) for (const i of atU.active) plot.points([[state.u, atU.values[i]]], { color: series(i), radius: 5, stroke: '#fff' });
  plot.label(state.u, 1.19, `u = ${fmt(state.u, 3)}`, { align: 'center', offset: [0, 0], baseline: 'top', font: '600 13px system-ui, sans-serif' });
}
