// The sound of "Knot modification" (www/lib/audio-trace.js, issue 25): the modified curve s(u; uₚ) as a trace,
// built from the samples the demo computed for drawing (C.cur) when the user asks. Its knots are the clamped
// vector with uₚ moved (in order); a knot's continuity is k − 1 − its multiplicity, so uₚ dragged onto a
// neighbour makes a double knot and the tone changes there. The exact point of a step comes from the wasm API.
import { traceOf, knotsWithContinuity } from '../../lib/audio-trace.js';
import { knots, curveDesc } from './knots.js';
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

/** The knot vector with the moving knot at uₚ, in order. */
export function movedKnots(state) {
  const t = knots(state).slice();
  t[state.p] = state.up;
  return t.sort((a, b) => a - b);
}

/** The modified curve as a trace (null before the first computation). @param {SplineLab} wasm */
export function modifiedCurveTrace(wasm, state, C) {
  if (!C.cur) return null;
  const curve = curveDesc(state);
  return traceOf({
    name: 'the curve s(u; uₚ)', params: C.cur.params, points: C.cur.points, knots: knotsWithContinuity(movedKnots(state), state.order - 1),
    at: (u) => { const r = wasm.knotModifiedCurve({ curve, p: state.p, up: state.up, at: [u] }).points; return [r[0], r[1]]; },
  });
}
