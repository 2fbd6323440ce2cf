// The sound of "Quasi-cubic curves" (www/lib/audio-trace.js, issue 25): the curve as a trace, built from the samples
// the demo computed for drawing (c.curve) when the user asks. Its segments join at u = 1 … n − 1, with C² joins for
// every α (curves.md §1: Eq. 7–8, measured jumps ≤ 1.3e-15), so every inner joint clicks and the tone stays a sine.
import { traceOf } from '../../lib/audio-trace.js';
import { segs } from './compute.js';
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

/** The curve as a trace (null before the first computation). @param {SplineLab} wasm */
export function curveTrace(wasm, state, c) {
  if (!c.curve) return null;
  const o = { points: state.points, alpha: state.alpha, closed: state.closed };
  return traceOf({
    name: 'the curve', params: c.curve.params, points: c.curve.points,
    knots: Array.from({ length: segs(state) + 1 }, (_, i) => ({ t: i, continuity: 2 })),
    at: (u) => { const r = wasm.quasiCubicCurve({ ...o, at: [u] }).points; return [r[0], r[1]]; },
  });
}
