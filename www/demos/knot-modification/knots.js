// The knot bookkeeping of the "Knot modification" demo (Juhász–Hoffmann): the clamped knot vectors of the curve
// and the surface, the neighbours u_{p−1}, u_{p+1} of the moving knot and the range it may take, and what a link
// may hold (sanitize). Plain functions of the state: no spline maths (the curves come from the wasm API).

import { fmt } from '../../lib/dom.js';

export const KNOT_ROW = 0;          // y of the knot line in the knot plot
export const EXT = 12;              // how far beyond its neighbours the knot may go with "extend" (knot units)
export const FAR = 400;             // the extended paths are followed to u_p = u_{p−1} − FAR … u_{p+1} + FAR
export const SURF_N = 8;            // surface control net SURF_N × SURF_N
// Dragging the knot snaps it to the first of these steps that is at least one screen pixel of the knot line:
// 0.01 on a desktop, 0.02 on a phone (1 px ≈ 0.017 there). The value then is what the labels show (1.6, not
// 1.604), and every value of the grid (such as an exercise's answer 1.6) can be reached by a finger.
export const KNOT_SNAPS = [0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1];
/** A knot value as the labels show it: at most 4 decimals, no trailing zeros (1.6, 1.604). */
export const knotText = (x) => String(+x.toFixed(4));
import { subscript as sub } from '../../lib/indices.js';
export { sub };

/** Clamped knots with integer interior spacing for `count` control points of order `k` (bookkeeping). */
export function clampedKnots(k, count) {
  const t = [];
  for (let i = 0; i < k; i++) t.push(0);
  for (let i = 1; i <= count - k; i++) t.push(i);
  for (let i = 0; i < k; i++) t.push(count - k + 1);
  return t;
}

// ---------- the curve: order k, clamped knots, the moving knot u_p ----------
export const knots = (state) => clampedKnots(state.order, state.points.length);
/** [u_{p−1}, u_{p+1}]: the neighbours of the moving knot. */
export const nb = (state) => { const t = knots(state); return [t[state.p - 1], t[state.p + 1]]; };
/** Where u_p may go: between its neighbours, or EXT beyond them with "extend". */
export const upRange = (state) => { const [a, b] = nb(state); return state.extend ? [a - EXT, b + EXT] : [a, b]; };
/** The curve as the API takes it. */
export const curveDesc = (state) => ({ order: state.order, knots: knots(state), controlPoints: state.points });

// ---------- the surface: orders 3 × 3, SURF_N × SURF_N control points, knots u_p (index sp) and v_q (sq) ----------
export const surfKnots = () => clampedKnots(3, SURF_N);
export const surfNb = (i) => { const t = surfKnots(); return [t[i - 1], t[i + 1]]; };
export const surfRange = (state, i) => { const [a, b] = surfNb(i); return state.extend ? [a - EXT, b + EXT] : [a, b]; };

/** The surface's control net: a bump plus a wave over the integer grid; as the API takes it. */
export function surfaceDesc() {
  const cp = [];
  for (let r = 0; r < SURF_N; r++) {
    const rowPts = [];
    for (let s = 0; s < SURF_N; s++) {
      const c = (SURF_N - 1) / 2;
      const z = 2.2 * Math.exp(-((r - c) ** 2 + (s - c) ** 2) / 5) + 0.4 * Math.sin(r + 0.7 * s);
      rowPts.push([r, s, z]);
    }
    cp.push(rowPts);
  }
  return { orderU: 3, orderV: 3, knotsU: surfKnots(), knotsV: surfKnots(), controlPoints: cp };
}

/** Validates the state in place (a link may hold anything that passed the type check); `d` is defaults(). */
export function sanitize(state, d) {
  if (state.tab !== 'curve' && state.tab !== 'surface') state.tab = 'curve';
  if (!Number.isInteger(state.order) || state.order < 2 || state.order > 5) state.order = d.order;
  // 6…16 control points ("Use my data" may change their number; the default has 8)
  if (!Array.isArray(state.points) || state.points.length < 6 || state.points.length > 16
    || !state.points.every((q) => Array.isArray(q) && q.length === 2 && q.every(Number.isFinite))) state.points = d.points;
  const n = state.points.length - 1;
  if (!Number.isInteger(state.p) || state.p < state.order || state.p > n) state.p = Math.min(n, Math.max(state.order, d.p));
  const [lo, hi] = upRange(state);
  if (!Number.isFinite(state.up)) state.up = knots(state)[state.p];
  state.up = Math.min(hi, Math.max(lo, state.up));
  if (!Number.isInteger(state.tracked) || state.tracked < 1 || state.tracked > 7) state.tracked = d.tracked;
  if (typeof state.trackAll !== 'boolean') state.trackAll = false;
  if (!Number.isInteger(state.step) || state.step < -1 || state.step > 20) state.step = -1;
  for (const key of ['sp', 'sq']) if (!Number.isInteger(state[key]) || state[key] < 3 || state[key] > SURF_N - 1) state[key] = d[key];
  for (const [key, idx] of [['sup', 'sp'], ['svq', 'sq']]) {
    const [a, b] = surfRange(state, state[idx]);
    if (!Number.isFinite(state[key])) state[key] = d[key];
    state[key] = Math.min(b, Math.max(a, state[key]));
  }
  if (!['both', 'u', 'v'].includes(state.smove)) state.smove = 'both';
  if (!Number.isFinite(state.yaw)) state.yaw = d.yaw;
  if (!Number.isFinite(state.pitch)) state.pitch = d.pitch;
  state.yaw = Math.min(180, Math.max(-180, state.yaw));
  state.pitch = Math.min(89, Math.max(0, state.pitch));
}

/** The live text under the curve controls: the affected spans (at most 2(k − 1)) and the limits of Theorem 3. */
export function curveInfoText(state, C) {
  const [lo, hi] = C.cur.affectedSpans, [ra, rb] = C.cur.affectedRange;
  const [a, b] = nb(state);
  const outside = state.up < a || state.up > b;
  // plain text with Unicode indices, not MathML: this is a live region, and a screen reader announces the
  // text of MathML run together ("up→−∞" for uₚ → −∞)
  const up = `u${sub(state.p)}`;
  return `Moving ${up} changes the spans ${lo}…${hi} only, u ∈ [${fmt(ra, 2)}, ${fmt(rb, 2)}] (at most 2(k − 1) = ${2 * (state.order - 1)} spans). `
    + `Limits: ${up} → −∞ gives d${sub(state.p)}, ${up} → +∞ gives d${sub(state.p - state.order)}.`
    + (outside ? ` ${up} = ${fmt(state.up, 2)} is outside [${fmt(a, 2)}, ${fmt(b, 2)}]: an extended path.` : '');
}
