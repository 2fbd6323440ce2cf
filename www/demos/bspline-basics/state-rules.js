// The state rules of "B-spline basics": the limits, the domain [u_p, u_n] of a clamped knot vector, and what a
// link may hold (sanitize: degree 1…5 and below the number of points, a clamped non-decreasing knot vector of
// n + p + 1 knots, u in the domain, a known stepper).
import { clampedKnots } from './compute.js';
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

export const MAX_POINTS = 16;
export const KNOT_ROW = -0.13; // y of the knot strip under the basis functions
export const MIN_GAP = 0.004;  // interior knots stay this far apart (ordered, no coincident handles)

/** n: the number of control points. */
export const count = (state) => state.points.length;
/** p: the degree. */
export const degree = (state) => state.degree;
/** The domain [u_p, u_n] of the clamped knot vector. */
export const domain = (state) => [state.knots[degree(state)], state.knots[count(state)]];
/** Subscript digits (N₃). */
export { subscript as sub } from '../../lib/indices.js';

/** True when the knots are a clamped, non-decreasing vector of n + p + 1 knots with a non-empty domain. */
function knotsLookValid(state) {
  const k = state.knots, p = degree(state), m = count(state) + p + 1;
  if (!Array.isArray(k) || k.length !== m) return false;
  for (let i = 1; i < m; i++) if (!(k[i] >= k[i - 1])) return false;
  for (let i = 0; i <= p; i++) if (k[i] !== k[0] || k[m - 1 - i] !== k[m - 1]) return false;
  return k[m - 1] > k[0];
}

/** Brings a state (from a link or an import) within the rules; invalid knots become clamped uniform ones. @param {SplineLab} wasm */
export function sanitize(wasm, state, defaults, notify) {
  if (!Number.isInteger(state.degree)) state.degree = Math.round(state.degree) || 3;
  state.degree = Math.max(1, Math.min(5, state.degree));
  if (state.points.length > MAX_POINTS) state.points.length = MAX_POINTS;
  if (state.points.length < 2) state.points = defaults().points;
  if (state.degree > count(state) - 1) state.degree = count(state) - 1;
  if (!knotsLookValid(state)) {
    try { state.knots = clampedKnots(wasm, state); } catch (e) { notify(e, 'error'); Object.assign(state, defaults()); }
  }
  const [a, b] = domain(state);
  if (!(state.u >= a && state.u <= b)) state.u = Math.min(b, Math.max(a, state.u || 0));
  if (!['deboor', 'insert'].includes(state.stepAlgo)) state.stepAlgo = 'deboor';
  if (!Number.isInteger(state.step) || state.step < -1 || state.step > 8) state.step = -1;
}
