// What "Curve networks" computes (every wasm call: networkFromFunction / networkExample through the presets,
// networkCompatibility, networkRepair, networkSurfaces, surfaceDifferences, crissCrossSurface, crissCrossBasis,
// crissCrossCells) into one object c = { net, result, c2, numbers, apiTime }:
//   net      the network on screen (a preset's or the edited one, repaired to compatibility C2 when needed)
//   result   the last networkSurfaces result: the meshes of S, T, G, GB (Dagnino–Lamberti–Remogna §3–4, Kuklišová
//            eq. (4)) and of the Gordon components L1, L2, Tg (eq. (39)), the network curves, the colour map, the
//            norms ‖S − G‖∞, ‖S − T‖∞, ‖T − G‖∞, ‖S − GB‖∞ on the paper's 57² grid (null while they follow a drag)
//   c2       the C2 residual max |φᵣ(vₛ) − ψₛ(uᵣ)|;  numbers  { c11 }: S with the two free points C₁₁ of §4.1
//            (Theorem 3.2: the same surface);  apiTime  the text of the "API time" readout
// and, on demand, the terms Cᵢⱼ Bᵢⱼ of S = Σ Cᵢⱼ Bᵢⱼ (Lemma 3.1), the triangulation lifted onto S and the BB
// ordinates of the cells. The surfaces and the numbers go to the compute worker when slow (issue 26;
// www/lib/compute-client.js); the presets' small networks stay synchronous.
import { fmt } from '../../lib/dom.js';
import { computeClient } from '../../lib/compute-client.js';
import { PRESETS, overLimit, clone } from './presets.js';
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

// While a point is dragged the numbers follow in a task after the frame, at most every NUMBERS_MS.
const NUMBERS_MS = 200;

/** max |S(C₁₁ = a) − S(C₁₁ = b)| over a 17 × 17 grid: `a`, `b` are both evaluated as Σ Cᵢⱼ Bᵢⱼ (crissCrossSurface,
 * evaluate: 'sum'; numberCalls). */
function c11Difference(a, b) {
  let d = 0, size = 1;
  for (let i = 0; i < a.length; i++) { d = Math.max(d, Math.abs(a[i] - b[i])); size = Math.max(size, Math.abs(a[i])); }
  return { d, same: d <= 1e-10 * size };
}

/**
 * The computations of one mounted demo. `busyLine` shows "Computing…" with Cancel; `onNumbers` shows the numbers
 * when they are in.
 * @param {{ wasm: SplineLab, state: any, notify: (m: any, k?: string) => void, demoId: string, busyLine: HTMLElement, onNumbers: () => void }} o
 */
export function networkModel({ wasm, state, notify, demoId, busyLine, onNumbers }) {
  /** @type {{ net: any, result: any, c2: number, numbers: { c11: { d: number, same: boolean } } | null, apiTime: string }} */
  const c = { net: null, result: null, c2: 0, numbers: null, apiTime: '' };
  const m = () => c.net.u.length - 1;
  const n = () => c.net.v.length - 1;

  function loadNetwork() {
    try {
      const why = state.network && overLimit(state.network);
      if (why) throw Object.assign(new Error(why), { field: 'network', kind: 'too-many' });
      c.net = state.network ? clone(state.network) : PRESETS[state.preset].build(wasm);
      c.c2 = wasm.networkCompatibility({ network: c.net }).c2;
      if (state.network && !wasm.networkCompatibility({ network: c.net }).compatible) {
        c.net = wasm.networkRepair({ network: c.net }).network;
      }
    } catch (e) {
      notify(e, 'error');
      state.network = null;
      c.net = PRESETS[state.preset].build(wasm);
    }
  }
  /** The compatibility of a pasted network (the API judges its shapes first: its Error names the field). */
  const compatibility = (nw) => wasm.networkCompatibility({ network: nw });
  /** Moves control point [a][b] of P (φ-curves) or Q (ψ-curves) to `pos` and lets networkRepair recompute the
   * dependent control points so the curves still meet. False (and a message) when the API refuses. */
  function moveControlPoint(kind, a, b, pos) {
    const edited = clone(c.net);
    if (kind === 'P') edited.P[a][b] = pos; else edited.Q[a][b] = pos;
    try {
      const r = wasm.networkRepair({ network: edited, edited: kind === 'P' ? { kind, r: a, j: b } : { kind, s: a, i: b } });
      c.net = r.network;
    } catch (e) { notify(e, 'error'); return false; }
    return true;
  }

  /** A drag's networkRepair on the current network, its result dropped (the idle warm-up, www/lib/warm.js: the
   * wasm and glue of a drag run optimized before the first drag; nothing changes). */
  function warmRepair() {
    try { wasm.networkRepair({ network: c.net, edited: { kind: 'P', r: 0, j: 0 } }); } catch { /* the drag will say */ }
  }

  // Off the main thread (issue 26; www/lib/compute-client.js): the surfaces and the numbers are two lists of wasm
  // calls, each run here when the same size of work was measured under SYNC_MS (the small networks of the presets:
  // unchanged, synchronous) and in a worker otherwise (large networks, fine tessellations). In the worker the
  // latest request wins while dragging. Two clients (two workers), so that a numbers request never supersedes a
  // surfaces request.
  const surfacesCC = computeClient({ demoId, wasm, status: busyLine, label: 'Computing the surfaces' });
  const numbersCC = computeClient({ demoId, wasm, status: busyLine, label: 'Computing the numbers' });
  /** The estimated time (ms) of a request never measured (a new size): per sample of a surface and per cell of the
   * network, with the norms (57² samples of four surfaces) or without; the rates are from networkSurfaces and
   * surfaceDifferences measured in Node (2 cores, loaded: 96² × 4 surfaces ≈ 25 ms, norms of 50 × 50 cells ≈ 20 ms). */
  const costMs = ({ samples = 0, norms = false }) => 7e-4 * samples + (norms ? 5 + 8e-3 * m() * n() : 2e-3 * m() * n());

  /** The wasm calls of the numbers: the C2 residual, S with the two C₁₁ of Theorem 3.2 (and the norms, when the
   * surfaces came without them). @returns {import('../../lib/compute-client.js').WasmCall[]} */
  function numberCalls(withNorms) {
    /** @returns {import('../../lib/compute-client.js').WasmCall} */
    const sum = (C11) => ({ fn: 'crissCrossSurface', args: { network: c.net, C11, evaluate: 'sum', samplesU: 17, samplesV: 17 } });
    return [{ fn: 'networkCompatibility', args: { network: c.net } }, sum([1.5, 1.5, 32]), sum([1, 0, 30]),
      ...(withNorms ? [/** @type {const} */ ({ fn: 'surfaceDifferences', args: { network: c.net, samples: 57 } })] : [])];
  }
  /** Computes the numbers of the network on screen (here or in the worker), then shows them. */
  function computeNumbers(withNorms) {
    const forNet = c.net, forResult = c.result, calls = numberCalls(withNorms);
    const key = `numbers ${m()}×${n()}${withNorms ? ' norms' : ''}`;
    const apply = (r) => {
      if (!r || forNet !== c.net) return;   // superseded, cancelled, or the network moved on (a newer request follows)
      c.c2 = r[0].c2;
      c.numbers = { c11: c11Difference(r[1].points, r[2].points) };
      if (withNorms && forResult === c.result) c.result.norms = r[3];
      onNumbers();
    };
    if (numbersCC.runsHere(key, costMs({ norms: withNorms }))) {
      try { apply(numbersCC.runHere(calls, key)); } catch (e) { notify(e, 'error'); }
    } else numbersCC.run(calls, { key }).then(apply, (e) => notify(e, 'error'));
  }
  let normsTimer = 0, lastNumbers = 0;
  /** The numbers of a drag's frame, after the frame (at most every NUMBERS_MS). */
  function laterNorms() {
    if (normsTimer) return;
    normsTimer = setTimeout(() => {
      normsTimer = 0;
      if (!c.result || c.result.norms) return;
      lastNumbers = performance.now();
      computeNumbers(true);
    }, Math.max(0, NUMBERS_MS - (performance.now() - lastNumbers)));
  }

  /**
   * networkSurfaces for `surfaces` at the state's density (the norms too unless `norms` is false: then they follow
   * after the frame); `onDone()` runs when c.result holds them. Returns 'here' (done now), 'worker' (coming) or
   * 'failed' (a message was shown).
   * @param {{ surfaces: import('../../../types/splinelab.js').NetworkSurfaceName[], colorBy: string | undefined, norms: boolean }} o
   * @param {() => void} onDone
   */
  function computeSurfaces({ surfaces, colorBy, norms }, onDone) {
    /** @type {import('../../lib/compute-client.js').WasmCall[]} */
    const calls = [{ fn: 'networkSurfaces', args: { network: c.net, samplesU: state.density, samplesV: state.density, surfaces, colorBy, curveSamples: 48, norms } }];
    const key = `surfaces ${m()}×${n()} ${state.density}² ${surfaces.join('+')}${colorBy ? ` ${colorBy}` : ''}${norms ? ' norms' : ''}`;
    const done = (r, dt) => {
      if (!r) return;   // superseded by a newer request, or cancelled
      c.result = r[0];
      c.apiTime = `${fmt(dt, 1)} ms (${surfaces.join(', ')} at ${state.density}²${norms ? ', norms on 57²' : '; norms after the frame'})`;
      if (!norms) { c.result.norms = null; laterNorms(); }   // (the C2 residual too: it is only shown)
      onDone();
      if (norms) computeNumbers(false);
    };
    if (surfacesCC.runsHere(key, costMs({ samples: state.density ** 2 * surfaces.length, norms }))) {
      let r;
      const t0 = performance.now();
      try { r = surfacesCC.runHere(calls, key); } catch (e) { notify(e, 'error'); return 'failed'; }
      done(r, performance.now() - t0);
      return 'here';
    }
    surfacesCC.run(calls, { key }).then((r) => done(r, surfacesCC.measured(key) ?? NaN), (e) => notify(e, 'error'));
    return 'worker';
  }

  // S = Σ C_ij B_ij (Lemma 3.1): the control points C_ij from crissCrossSurface, each B_ij sampled by
  // crissCrossBasis on the same u-major grid as networkSurfaces; the demo only adds the terms up, row by row, and
  // compares the full sum with the core's S.
  let terms = null;
  function crissCrossTerms() {
    const net = c.net, N = state.density, key = JSON.stringify([net.u, net.v, net.P, net.Q, N]);
    if (terms && terms.key === key) return terms;
    try {
      const C = wasm.crissCrossSurface({ network: net, atUV: [[net.u[0], net.v[0]]] }).controlPoints;
      const rows = m() + 2, cols = n() + 2, B = [];
      for (let i = 0; i < rows; i++) for (let j = 0; j < cols; j++) B.push(wasm.crissCrossBasis({ u: net.u, v: net.v, i, j, samplesU: N, samplesV: N }).values);
      terms = { key, C, B, rows, cols, N, partial: [] };
    } catch (e) { notify(e, 'error'); terms = null; }
    return terms;
  }
  /** Σ_{i' ≤ i} Σ_j C_i'j B_i'j on the grid (flat xyz), cached per row. */
  function partialSum(i) {
    const T = crissCrossTerms();
    if (!T || i < 0) return null;
    i = Math.min(i, T.rows - 1);
    if (T.partial[i]) return T.partial[i];
    const K = T.N * T.N, out = new Float64Array(3 * K);
    if (i > 0) out.set(partialSum(i - 1));
    for (let j = 0; j < T.cols; j++) {
      const b = T.B[i * T.cols + j], q3 = 3 * (i * T.cols + j);
      for (let q = 0; q < K; q++) { const w = b[q]; out[3 * q] += w * T.C[q3]; out[3 * q + 1] += w * T.C[q3 + 1]; out[3 * q + 2] += w * T.C[q3 + 2]; }
    }
    T.partial[i] = out;
    return out;
  }

  /** The grid lines and both diagonals of every cell, lifted onto S (crissCrossSurface): k + 1 points per piece,
   * flat xyz (null and a message when the API refuses). */
  function triangulation(k = 12) {
    const net = c.net, segs = [];
    const seg = (u0, v0, u1, v1) => { const at = []; for (let i = 0; i <= k; i++) at.push([u0 + (u1 - u0) * i / k, v0 + (v1 - v0) * i / k]); return at; };
    const U = net.u, V = net.v;
    for (let a = 1; a <= m(); a++) for (let b = 1; b <= n(); b++) {
      segs.push(seg(U[a - 1], V[b - 1], U[a], V[b]), seg(U[a - 1], V[b], U[a], V[b - 1]));
    }
    for (const u of U) segs.push(seg(u, V[0], u, V[n()]));
    for (const v of V) segs.push(seg(U[0], v, U[m()], v));
    try {
      const pts = wasm.crissCrossSurface({ network: net, atUV: segs.flat() }).points;
      return Array.from(segs, (_, s) => pts.subarray(3 * s * (k + 1), 3 * (s + 1) * (k + 1)));
    } catch (e) { notify(e, 'error'); return null; }
  }

  /** The 13 BB ordinates (flat xyz) of every cell of S (crissCrossCells), cell (a, b) at ((a − 1)·n + b − 1)·39. */
  const cellOrdinates = () => wasm.crissCrossCells({ network: c.net }).ordinates;

  function destroy() { clearTimeout(normsTimer); surfacesCC.destroy(); numbersCC.destroy(); }

  return { c, m, n, loadNetwork, compatibility, moveControlPoint, warmRepair, computeSurfaces, crissCrossTerms, partialSum, triangulation, cellOrdinates, destroy };
}
