// What the curve tab computes (every number from the wasm API): the remodelled spline g* (bezierRemodel, eq. (6)
// with the constraints (9)), the given spline g (bezierSpline), the live Fig. 3 (K* at a joint against αₘ of the
// segment before), the stepper's de Casteljau levels on g* (bezierDeCasteljau) and the point g*(u) of "Play u".
// Results go into one object `c` = { res, orig, fig3, dc, atU } that the drawing reads.
import { alphaMax } from './curve-state.js';
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

export const uRange = (state) => [state.breaks[0], state.breaks[state.breaks.length - 1]];

/** bezierRemodel with the state's spline and α, plus `extra` options (samples, at, a sweep). @param {SplineLab} wasm */
export function callRemodel(wasm, state, extra) {
  return wasm.bezierRemodel({
    points: state.points, degree: state.degree, breaks: state.breaks, alphas: state.alphas,
    r: state.r, enforce: state.enforce, ...extra,
  });
}

/** g* and g (a failed call keeps the previous result and is reported), then Fig. 3 and the stepper's data. @param {SplineLab} wasm */
export function computeCurve(wasm, state, notify, c) {
  try {
    c.res = callRemodel(wasm, state, { samples: 600 });
    // keep the α that were used (eq. 9 overwrote the fixed ones)
    state.alphas = c.res.alphas.map((row) => Array.from(row));
  } catch (e) { notify(e, 'error'); }
  try {
    c.orig = wasm.bezierSpline({ points: state.points, degree: state.degree, breaks: state.breaks, samples: 600 });
  } catch (e) { notify(e, 'error'); }
  computeFig3(wasm, state, notify, c);
  computeSteps(wasm, state, c);
}

/** The stepper's data: bezierDeCasteljau on g* at stepU → c.dc = { segment, t, levels[r] (flat), point }. @param {SplineLab} wasm */
export function computeSteps(wasm, state, c) {
  c.dc = null;
  if (!c.res) return;
  try { c.dc = wasm.bezierDeCasteljau({ points: c.res.controlPoints, degree: state.degree + 1, breaks: state.breaks, u: state.stepU }); } catch (e) { c.dc = null; }
}

/** Fig. 3: K*(u_I) as αₘ⁽ᴵ⁻¹⁾ runs over (0, ½] (everything else as it is now), measured by the API in one sweep.
 * c.fig3 = { xs, ks, printed (eq. 15 as printed), k0 = K(u_I) of g, joint I, hi (end of the sweep) }. @param {SplineLab} wasm */
export function computeFig3(wasm, state, notify, c) {
  c.fig3 = null;
  const m = state.degree, I = state.joint, segs = state.breaks.length - 1;
  if (I < 1 || I >= segs) return;
  const hi = Math.min(alphaMax(state), Math.max(0.5, state.alphas[I - 1][m - 1] + 0.05));
  const xs = Array.from({ length: 61 }, (_, j) => 0.004 + (hi - 0.004) * j / 60);
  try {
    // one call for the whole sweep (was one bezierRemodel call per α)
    const r = wasm.bezierRemodel({ points: state.points, degree: m, breaks: state.breaks, alphas: state.alphas, r: state.r, enforce: state.enforce, at: [], alphaSweep: xs, alphaSweepJoint: I });
    const ks = Array.from(r.sweepCurvature), printed = Array.from(r.sweepCurvaturePrinted);
    c.fig3 = { xs, ks, printed, k0: c.res ? c.res.curvatureOriginal[I] : NaN, joint: I, hi };
  } catch (e) { notify(e, 'error'); }
}

/** "Play u": c.atU = g*(u) (u is moved into [u₀, u_L] first), by de Casteljau on the control points of g* already
 * computed (c.res): not a second remodelling of the whole spline for one point (issue 26; it ran in every drag
 * frame; the point agrees with bezierRemodel's `at` to 1e-14). @param {SplineLab} wasm */
export function computeAtU(wasm, state, c) {
  const [a, b] = uRange(state);
  if (!(state.u >= a && state.u <= b)) state.u = a;
  c.atU = null;
  if (!c.res) return;
  try { const r = wasm.bezierDeCasteljau({ points: c.res.controlPoints, degree: state.degree + 1, breaks: state.breaks, u: state.u }); c.atU = [r.point[0], r.point[1]]; } catch (e) { c.atU = null; }
}
