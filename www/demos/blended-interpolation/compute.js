// What "Blended interpolation" computes (every value from the wasm API: quasiCubicInterpolation, quasiCubicCurve)
// into c = { bis, spline, tangent, fairBeta, atU }: the blended interpolation spline BIS_i = L_i + β_i (p_i − L_i)
// through b₀ … bₙ with its curvature (quasi-cubic paper §4, Eqs. 11–19), the α = 3 spline (all β* = 1), its tangent
// p′(j) at the selected point (the β* handle moves along it), the β* of exact curvature matching ("fair by
// curvature", correcting Eqs. (36)–(37)), and the point p(u) of "Play u".
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

/** The β* that match the curvature Kⱼ of the circle through bⱼ₋₁, bⱼ, bⱼ₊₁ at every data point. @param {SplineLab} wasm */
export function curvatureMatchingBeta(wasm, state) {
  return wasm.quasiCubicInterpolation({ points: state.points, beta: 'curvature', k: state.k, at: [0] }).beta;
}

/**
 * The demo's computation bound to its state: `compute(done, { hereOnly })` and `computeAtU()` fill `c`.
 * @param {{ wasm: SplineLab, state: any, notify: Function, curveCC: ReturnType<typeof import('../../lib/compute-client.js').computeClient> }} o
 */
export function createComputation({ wasm, state, notify, curveCC }) {
  const c = { bis: null, spline: null, tangent: null, fairBeta: null, atU: null };
  const n = () => state.points.length - 3; // segments; data points b₀ … bₙ

  // The curve (quasiCubicInterpolation with curvature, ~4000 samples), the α = 3 spline, the tangent at bⱼ and the
  // fair β* run in a worker when they are slow (issue 26; www/lib/compute-client.js): ~40–200 ms for 80 points on
  // a loaded 2-core machine, in every pointer move of a drag. Small data (measured under SYNC_MS) stays
  // synchronous, as before. While dragging, the newest request wins; the points follow the pointer now, the
  // curve and its handle when they are computed.
  let computeToken = 0;
  /** Computes the curve data; `done()` runs once they are all in (now, or when the worker answers). With
   * `hereOnly` (the idle warm-up) work that would go to the worker is not started; returns whether it ran here. */
  function compute(done, { hereOnly = false } = {}) {
    const per = Math.max(8, Math.min(60, Math.floor(4000 / Math.max(1, n()))));
    const samples = n() * per + 1;
    const key = `${n()} segments, ${samples} samples${state.showSpline ? ' + spline' : ''}`;
    // a new size: ~0.6 ms per segment (measured: 79 segments ≈ 45 ms in Node, 40–200 ms in the page under load)
    if (curveCC.runsHere(key, n() * 0.6)) {
      ++computeToken;   // a pending worker answer is older than this
      const t0 = performance.now();
      try {
        c.bis = wasm.quasiCubicInterpolation({ points: state.points, beta: state.beta, k: state.k, samples, derivatives: 1, curvature: true });
      } catch (e) { c.bis = null; notify(e, 'error'); }
      try {
        c.spline = state.showSpline ? wasm.quasiCubicCurve({ points: state.points, alpha: 3, samples }) : null;
        // p′(j) of the α = 3 spline at the selected point: the β* handle moves along it
        const j = state.selected;
        const r = wasm.quasiCubicCurve({ points: state.points, alpha: 3, at: [j], derivatives: 1 });
        c.tangent = { at: [r.points[0], r.points[1]], d: [r.d1[0], r.d1[1]] };
      } catch (e) { c.spline = null; c.tangent = null; notify(e, 'error'); }
      try {
        c.fairBeta = wasm.quasiCubicInterpolation({ points: state.points, beta: 'curvature', k: state.k, at: [0] }).beta;
      } catch { c.fairBeta = null; }
      curveCC.record(key, performance.now() - t0);
      done();
      return true;
    }
    if (hereOnly) return false;
    const mine = ++computeToken;
    // in the worker: a curve of another number of points is not shown meanwhile (a drag keeps the previous one)
    if (c.bis && c.bis.circleCurvature.length !== n() + 1) { c.bis = null; c.spline = null; c.tangent = null; c.fairBeta = null; }
    const points = state.points.map((p) => [p[0], p[1]]);
    /** @type {import('../../lib/compute-client.js').WasmCall[]} */
    const calls = [
      { fn: 'quasiCubicInterpolation', args: { points, beta: state.beta.slice(), k: state.k, samples, derivatives: 1, curvature: true } },
      { fn: 'quasiCubicCurve', args: { points, alpha: 3, at: [state.selected], derivatives: 1 } },
      { fn: 'quasiCubicInterpolation', args: { points, beta: 'curvature', k: state.k, at: [0] }, optional: true },
    ];
    if (state.showSpline) calls.push({ fn: 'quasiCubicCurve', args: { points, alpha: 3, samples } });
    curveCC.run(calls, { key }).then((r) => {
      if (!r || mine !== computeToken) return;
      const [b, t, f, sp = null] = r;
      c.bis = b; c.spline = sp;
      c.tangent = { at: [t.points[0], t.points[1]], d: [t.d1[0], t.d1[1]] };
      c.fairBeta = f ? f.beta : null;
      done();
    }, (e) => {
      if (mine !== computeToken) return;
      c.bis = null; c.spline = null; c.tangent = null;
      notify(e, 'error');
      done();
    });
  }

  // the evaluation point p(u) of "Play u", u ∈ [0, n]
  function computeAtU() {
    if (!(state.u >= 0 && state.u <= n())) state.u = 0;
    try {
      const r = wasm.quasiCubicInterpolation({ points: state.points, beta: state.beta, k: state.k, at: [state.u] });
      c.atU = [r.points[0], r.points[1]];
    } catch { c.atU = null; }
  }

  return { c, compute, computeAtU };
}
