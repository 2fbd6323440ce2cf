// What "Quasi-cubic curves" computes (every value from the wasm API: quasiCubicCurve, quasiCubicBasis,
// quasiCubicPreset, quasiCubicShapeCheck, bsplineCurve, bsplineBasis) into
// c = { curve, ghost, basis, ghostBasis, check, atU, stepData }: the curve p_i(t) = Σ_j B_j(α;t) b_{i+j}, the uniform
// cubic B-spline of the same polygon (the ghost), the four basis functions B_j(α; t) and the cubic B-spline's
// pieces on one span (paper Fig. 2), a preset's shape check (analytic curve, deviation, condition residual), the
// point p(u) of "Play u", and the stepper's values at u: B_j = (1 − α) B⁰_j + α B¹_j with B⁰, B¹ at t.
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

/** An empty result object (what the plots draw before the first computation). */
export const emptyComputed = () => ({ curve: null, ghost: null, basis: null, ghostBasis: null, check: null, atU: null, stepData: null });

/** The number of segments: u runs over [0, segs]. */
export const segs = (state) => (state.closed ? state.points.length : state.points.length - 3);

/** The uniform cubic B-spline's polygon for the same curve (closed: the polygon wrapped by three points). */
function ghostPolygon(state) {
  const P = state.points;
  return state.closed ? [...P, P[0], P[1], P[2]] : P;
}

/** A preset's polygon, closedness and α. @param {SplineLab} wasm */
export function presetData(wasm, name) {
  const p = wasm.quasiCubicPreset({ name });
  return { points: p.points.map((q) => [q[0], q[1]]), closed: p.closed, alpha: p.alpha };
}

/** The evaluation point p(u) (u kept in [0, segs]). @param {SplineLab} wasm */
export function computeAtU(wasm, state, c) {
  state.u = Math.min(segs(state), Math.max(0, Number.isFinite(state.u) ? state.u : 0));
  try {
    const r = wasm.quasiCubicCurve({ points: state.points, alpha: state.alpha, closed: state.closed, at: [state.u] });
    c.atU = [r.points[0], r.points[1]];
  } catch { c.atU = null; }
}

/** The curve, the ghost B-spline and a preset's shape check (with p(u)). @param {SplineLab} wasm */
export function compute(wasm, state, notify, c) {
  computeAtU(wasm, state, c);
  try {
    c.curve = wasm.quasiCubicCurve({ points: state.points, alpha: state.alpha, closed: state.closed, samples: 60 * state.points.length });
  } catch (e) { c.curve = null; notify(e, 'error'); }
  try {
    const gp = ghostPolygon(state);
    const knots = Array.from({ length: gp.length + 4 }, (_, i) => i);
    c.ghost = state.showGhost ? wasm.bsplineCurve({ degree: 3, knots, points: gp, samples: 60 * gp.length }) : null;
  } catch (e) { c.ghost = null; notify(e, 'error'); }
  try {
    c.check = state.preset === 'free' ? null
      : wasm.quasiCubicShapeCheck({ shape: state.preset, points: state.points, alpha: state.alpha, samples: 200 });
  } catch (e) { c.check = null; notify(e, 'error'); }
}

/** The four basis functions for α and the cubic B-spline's four pieces on one span. @param {SplineLab} wasm */
export function computeBasis(wasm, state, notify, c) {
  try {
    c.basis = wasm.quasiCubicBasis({ alpha: state.alpha, samples: 201 });
    // the uniform cubic B-spline's four pieces on one span, for comparison (paper Fig. 2)
    const at = Array.from({ length: 101 }, (_, j) => 3 + j / 100);
    c.ghostBasis = wasm.bsplineBasis({ degree: 3, knots: [0, 1, 2, 3, 4, 5, 6, 7], at });
  } catch (e) { notify(e, 'error'); }
}

// ---------- the basis assembled on one segment (stepper) ----------
// At the evaluation point u (segment i = ⌊u⌋, t = u − i) the four pieces B_j(α; t) and the two bases they
// blend, B⁰ (α = 0) and B¹ (α = 1), all from the wasm core; the sum is checked over the sampled basis.
/** @param {SplineLab} wasm */
export function computeSteps(wasm, state, c) {
  const { basis } = c;
  try {
    const n = segs(state), seg = Math.min(Math.floor(state.u), n - 1), t = state.u - seg;
    const v = wasm.quasiCubicBasis({ alpha: state.alpha, at: [t] }).values;
    const v0 = wasm.quasiCubicBasis({ alpha: 0, at: [t] }).values;
    const v1 = wasm.quasiCubicBasis({ alpha: 1, at: [t] }).values;
    let worst = 0;
    if (basis) for (let j = 0; j < basis.params.length; j++) {
      const sum = basis.values[4 * j] + basis.values[4 * j + 1] + basis.values[4 * j + 2] + basis.values[4 * j + 3];
      worst = Math.max(worst, Math.abs(sum - 1));
    }
    c.stepData = { seg, t, v: Array.from(v), v0: Array.from(v0), v1: Array.from(v1), worst };
  } catch { c.stepData = null; }
}
