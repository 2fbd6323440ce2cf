// The sound of "B-spline basics" (www/lib/audio-trace.js, issue 25): the traces its two plots play, built from
// what the demo already computed for drawing (c.curve, c.basis) when the user asks, never per frame. A knot's
// continuity is p − its multiplicity (C^{p−m}); the exact point of a step comes from the wasm API (bsplineCurve).
import { traceOf, knotsWithContinuity } from '../../lib/audio-trace.js';
import { sub } from './state-rules.js';
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

/** The curve C(u) as a trace (null before the first computation). @param {SplineLab} wasm */
export function curveTrace(wasm, state, c) {
  if (!c.curve) return null;
  const o = { degree: state.degree, knots: state.knots, points: state.points };
  return traceOf({
    name: 'the curve C(u)', params: c.curve.params, points: c.curve.points, knots: knotsWithContinuity(state.knots, state.degree),
    at: (u) => { const r = wasm.bsplineCurve({ ...o, at: [u] }).points; return [r[0], r[1]]; },
  });
}

/** The basis function that plays: the first one non-zero at u (highlighted in the plot), else N₀,ₚ. */
export const soundingBasis = (c) => (c.atU && c.atU.active.length ? c.atU.active[0] : 0);

/** The basis function Nᵢ,ₚ (i = soundingBasis) as y over u, its x the parameter u (null before the first computation). */
export function basisTrace(state, c) {
  if (!c.basis) return null;
  const { params: P, values: V, count: cnt } = c.basis, i = soundingBasis(c);
  const points = new Float64Array(2 * P.length);
  for (let j = 0; j < P.length; j++) { points[2 * j] = P[j]; points[2 * j + 1] = V[j * cnt + i]; }
  const tr = traceOf({ name: `N${sub(i)},${sub(state.degree)}`, params: P, points, knots: knotsWithContinuity(state.knots, state.degree) });
  tr.yRange = [0, 1]; // a basis function's values: 0 … 1, the same pitch for the same height in every function
  return tr;
}
