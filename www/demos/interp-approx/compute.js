// What "Interpolating vs approximating" computes (every value from the wasm API: b2Curve, b2Fit, b2Basis) into
// c = { main, bspl, interp, family, claim, basis, build, printed, atU }: the curve Lᵃ = 6a·Lᴮ + (1 − 6a)·L (the
// §5 blend) for the current options with its curvature, the overlays a = 1/6 and a = 0, the family of a preset,
// the printed claim "a = 1/6, p = 0 gives the B-spline", the blending functions, the stepper's stages and weights,
// the curve with eq. (5)'s last weight as printed, and the point Lᵃ(u) of "Play u".
import { SAMPLES } from './presets.js';
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

/** The options of every call: a, tension p (or the automatic tension), knots, c2, construction, K. */
function opts(state, over = {}) {
  const o = { a: state.a, tension: state.p, knots: state.knots, c2: state.c2, construction: state.construction };
  if (state.useK) o.K = state.K;
  if (state.autoTension !== 'off' && state.construction !== 'section3') {
    o.autoTension = state.autoTension;
    o.autoTensionScale = state.autoScale;
  }
  return { ...o, ...over };
}
/** The curve for the current points: b2Curve on W₋₁…Wₙ₊₂, or b2Fit (reflected ends) on W₁…Wₙ. @param {SplineLab} wasm */
function call(wasm, state, over) {
  if (state.autoEnds) return wasm.b2Fit({ points: state.points.slice(2, -2), ...opts(state, over) });
  return wasm.b2Curve({ points: state.points, ...opts(state, over) });
}

/** The curve at the parameters `at` (the figure's table). @param {SplineLab} wasm */
export const curveAt = (wasm, state, at) => call(wasm, state, { at });

/** Computes everything the demo shows into c (a failed call is reported or leaves its result null). @param {SplineLab} wasm */
export function compute(wasm, state, notify, c) {
  try {
    c.main = call(wasm, state, { samples: SAMPLES, curvature: true });
    if (state.autoEnds && c.main.dataPoints) {
      const d = c.main.dataPoints, m = state.points.length;
      for (const i of [0, 1, m - 2, m - 1]) state.points[i] = [d[2 * i], d[2 * i + 1]];
    }
  } catch (e) { notify(e, 'error'); c.main = null; }
  try { c.bspl = state.showB ? call(wasm, state, { a: 1 / 6, samples: SAMPLES }) : null; } catch (e) { c.bspl = null; }
  try { c.interp = state.showInterp ? call(wasm, state, { a: 0, samples: SAMPLES }) : null; } catch (e) { c.interp = null; }
  c.family = [];
  if (state.family) {
    for (const v of state.family.values) {
      try { c.family.push({ v, r: call(wasm, state, { [state.family.key === 'a' ? 'a' : 'tension']: v, samples: SAMPLES }) }); } catch (e) { /* skip */ }
    }
  }
  // the printed claim "a = 1/6 and p = 0 gives the B-spline" (correction-000-bspline), live: with p = 0 the
  // even vertices C₂ᵢ of the construction (a = 0, no automatic tension) against those of the B-spline (a = 1/6,
  // the §5 blend). Both from the wasm API; equal on uniform knots, apart on non-uniform ones.
  c.claim = null;
  try {
    const mid = call(wasm, state, { a: 0, tension: 0, autoTension: false, samples: 2 }).evenVertices;
    // the claim is about a = 1/6 *and* p = 0 (with the current p, the §3 curve at a = 1/6 is not the B-spline)
    const bs = call(wasm, state, { a: 1 / 6, tension: 0, autoTension: false, samples: 2 }).evenVertices;
    let d = 0;
    for (let i = 0; i + 1 < Math.min(mid.length, bs.length); i += 2) d = Math.max(d, Math.hypot(mid[i] - bs[i], mid[i + 1] - bs[i + 1]));
    c.claim = d;
  } catch (e) { c.claim = null; }
  try {
    c.basis = wasm.b2Basis({ points: state.points, ...opts(state, { samples: 301 }) });
  } catch (e) { c.basis = null; }
  // the construction's stages and weights (the stepper), and the curve with eq. (5) as printed. b2Curve on
  // the current W₋₁…Wₙ₊₂ (with automatic ends these are the reflected points written back above).
  try { c.build = wasm.b2Curve({ points: state.points, ...opts(state, { samples: 2 }) }); } catch (e) { c.build = null; }
  try { c.printed = wasm.b2Curve({ points: state.points, ...opts(state, { samples: state.eq5Printed ? SAMPLES : 2 }), eq5: 'printed' }); } catch (e) { c.printed = null; }
}

/** The evaluation point Lᵃ(u) of "Play u" (u is moved into the curve's domain first). @param {SplineLab} wasm */
export function computeAtU(wasm, state, c) {
  c.atU = null;
  if (!c.main) return;
  const [a, b] = c.main.domain;
  if (!(state.u >= a && state.u <= b)) state.u = a;
  try { const r = call(wasm, state, { at: [state.u] }); c.atU = [r.points[0], r.points[1]]; } catch (e) { c.atU = null; }
}
