// What "B-spline basics" computes (every value from the wasm API: bsplineCurve, bsplineBasis, bsplineDeBoor,
// bsplineInsertKnot) into c = { curve, basis, atU, spanPiece, spanLabel, tri, ins }: the curve C(u) = Σ Nᵢ,ₚ(u) Pᵢ,
// all basis functions Nᵢ,ₚ over the domain (Cox–de Boor), the basis values and the curve point at the scrubbed u
// with the curve piece over u's knot span, and the two steppers' intermediate points (de Boor's triangle at u,
// Boehm's insertion of the knot u).
const p = (state) => state.degree;          // the degree
const n = (state) => state.points.length;   // the number of control points
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

/** An empty result object (what the plots draw before the first computation). */
export const emptyComputed = () => ({
  curve: null,      // { params, points: Float64Array }
  basis: null,      // { params, values, count }
  atU: null,        // { values (count), point [x, y], active: [i…] }
  spanPiece: null,  // the curve piece of the knot span that contains u
  spanLabel: [0, 1], // that span [lo, hi]
  tri: null,        // bsplineDeBoor: { span, levels[r] (flat), alphas[r], firstIndex[r], point }
  ins: null,        // bsplineInsertKnot: { span, first, alphas, knots, points (flat) }
});

/** The clamped uniform knot vector on [0, 1] for the current degree and points (bsplineCurve without `knots` returns it). @param {SplineLab} wasm */
export function clampedKnots(wasm, state) {
  const r = wasm.bsplineCurve({ degree: p(state), points: state.points, samples: 2 });
  return Array.from(r.knots);
}

/** Every basis function Nᵢ,ₚ over the domain (301 samples). @param {SplineLab} wasm */
export function computeBasis(wasm, state, notify, c) {
  try {
    c.basis = wasm.bsplineBasis({ degree: p(state), knots: state.knots, samples: 301 });
  } catch (e) { notify(e, 'error'); }
}

/** The curve C(u) (400 samples). @param {SplineLab} wasm */
export function computeCurve(wasm, state, notify, c) {
  try {
    c.curve = wasm.bsplineCurve({ degree: p(state), knots: state.knots, points: state.points, samples: 400 });
  } catch (e) { notify(e, 'error'); }
}

/** The basis values and the point C(u) at the scrubbed u, the piece over its knot span, then the steppers' data. @param {SplineLab} wasm */
export function computeAtU(wasm, state, notify, c) {
  try {
    const b = wasm.bsplineBasis({ degree: p(state), knots: state.knots, at: [state.u] });
    const cu = wasm.bsplineCurve({ degree: p(state), knots: state.knots, points: state.points, at: [state.u] });
    const active = [];
    for (let i = 0; i < b.values.length; i++) if (b.values[i] > 1e-12) active.push(i);
    c.atU = { values: b.values, point: [cu.points[0], cu.points[1]], active };
    // the knot span [u_k, u_{k+1}) containing u (right-hand piece; the last span at the end)
    const k = state.knots, P = p(state), N = n(state);
    let lo = k[P], hi = k[N];
    for (let i = P; i < N; i++) if (k[i] <= state.u && state.u < k[i + 1]) { lo = k[i]; hi = k[i + 1]; }
    if (state.u >= k[N]) { for (let i = N - 1; i >= P; i--) if (k[i] < k[i + 1]) { lo = k[i]; hi = k[i + 1]; break; } }
    const at = [];
    for (let j = 0; j <= 60; j++) at.push(lo + (hi - lo) * j / 60);
    c.spanPiece = hi > lo ? wasm.bsplineCurve({ degree: P, knots: state.knots, points: state.points, at }).points : null;
    c.spanLabel = [lo, hi];
  } catch (e) { notify(e, 'error'); }
  computeSteps(wasm, state, c);
}

/** The steppers' data: every intermediate point of de Boor at u and of Boehm's insertion of u (null when it fails). @param {SplineLab} wasm */
export function computeSteps(wasm, state, c) {
  const o = { degree: p(state), knots: state.knots, points: state.points, u: state.u };
  try { c.tri = wasm.bsplineDeBoor(o); } catch { c.tri = null; }
  try { c.ins = wasm.bsplineInsertKnot(o); } catch { c.ins = null; }
}
