// The sound of "Blended interpolation" (www/lib/audio-trace.js, issue 25): the blended spline BIS(u) as a trace,
// built from the samples the demo computed for drawing (c.bis) when the user asks. It passes through bⱼ at u = j
// (j = 0 … n); the joints are C² for k ≥ 3 and only C¹ for k = 2 (curves.md §1: the k = 2 second-derivative jump
// is 15.0 on the test data), so with k = 2 the tone turns to a triangle after the first joint.
import { traceOf } from '../../lib/audio-trace.js';
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

/** The blended spline as a trace (null before the first computation). @param {SplineLab} wasm */
export function splineTrace(wasm, state, c) {
  if (!c.bis) return null;
  const n = state.points.length - 3, o = { points: state.points, beta: state.beta, k: state.k };
  return traceOf({
    name: 'the blended spline', params: c.bis.params, points: c.bis.points,
    knots: Array.from({ length: n + 1 }, (_, j) => ({ t: j, continuity: state.k >= 3 ? 2 : 1 })),
    at: (u) => { const r = wasm.quasiCubicInterpolation({ ...o, at: [u] }).points; return [r[0], r[1]]; },
  });
}
