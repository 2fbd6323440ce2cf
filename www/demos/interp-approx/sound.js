// The sound of "Interpolating vs approximating" (www/lib/audio-trace.js, issue 25): the curve Lᵃ as a trace, built
// from the samples the demo computed for drawing (c.main) when the user asks. Lᵃ = 6a·Lᴮ + (1 − 6a)·L: L is a cubic
// B-spline on the Farin knots u′ (the data knots uᵢ and the midpoints between them, curves.md §2) and Lᴮ one on the
// data knots, a subset of them; so Lᵃ is a cubic on u′ with continuity 3 − multiplicity at each knot: C² at every
// simple knot (curves.md §2.5: the d0, d1, d2 jumps measured 0 at all knots), less where equal data knots coincide.
// The tension, K and c2 change the control points only, not the knots.
import { traceOf, knotsWithContinuity } from '../../lib/audio-trace.js';
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

/** The curve Lᵃ as a trace (null before the first computation). @param {SplineLab} wasm */
export function curveTrace(wasm, state, c, curveAt) {
  if (!c.main) return null;
  return traceOf({
    name: 'the curve Lᵃ', params: c.main.params, points: c.main.points,
    knots: knotsWithContinuity(c.main.knots, 3),
    at: (u) => { const r = curveAt(wasm, state, [u]).points; return [r[0], r[1]]; },
  });
}
