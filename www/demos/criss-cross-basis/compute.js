// What "Criss-cross basis" computes (every value from the wasm API: crissCrossCells, crissCrossBasis) into one
// object c = { cells, basis, lines, vmax }: the 13 BB ordinates of every cell, their domain points and the support
// triangles of Bᵢⱼ (§3; the ordinates follow from eq. (23)'s tensor-product traces on the grid lines), Bᵢⱼ on the
// GRID² grid with its mesh, the grid lines and diagonals of the support lifted onto the surface, and max Bᵢⱼ.
import { GRID, cellsU, cellsV, cellIndex } from './data.js';
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

/** Is Bᵢⱼ non-zero on some triangle of cell (a, b)? */
export function inSupport(state, cells, a, b) {
  if (!cells) return false;
  const k = 4 * cellIndex(state, a, b);
  return cells.support[k] + cells.support[k + 1] + cells.support[k + 2] + cells.support[k + 3] > 0;
}

/**
 * The computations of one mounted demo; `basisCC` is its compute client, `onBasis(c)` runs when a basis is in
 * (it paints the colour map).
 * @param {{ wasm: SplineLab, state: any, notify: (m: any, k?: string) => void,
 *   basisCC: ReturnType<typeof import('../../lib/compute-client.js').computeClient>, onBasis: (c: any) => void }} o
 */
export function computations({ wasm, state, notify, basisCC, onBasis }) {
  const c = {
    basis: null,   // { uv, values, mesh }
    cells: null,   // { ordinates, domainPoints, support }
    lines: null,   // triangulation lines lifted onto the surface (flat xyz arrays)
    vmax: 1,
  };

  // The basis on its 61² grid with the mesh and the lifted triangulation lines (crissCrossBasis) run in a worker
  // when they are slow (issue 26; www/lib/compute-client.js): the first calls at a new grid size run in V8's
  // baseline tier (6–40 ms measured in the page for 61², then 1–7 ms) and a loaded machine multiplies that
  // (119 ms measured for the 10 × 10 slider at load 11–15). A size measured under SYNC_MS stays synchronous, as
  // before; while a knot line is dragged the newest request wins. The BB ordinates and the support
  // (crissCrossCells, ~0.2 ms) are computed here at once: the table and the 2D support follow the state now, the
  // surface and the colour map when they are in.
  let computeToken = 0;
  /** Computes the basis; `ready()` runs once it is in. Returns true when that was now (synchronously). */
  function compute(ready) {
    const mine = ++computeToken;
    const m = cellsU(state), n = cellsV(state);
    let /** @type {import('../../lib/compute-client.js').WasmCall[]} */ calls, pieces, at;
    try {
      /** @type {import('../../../types/splinelab.js').CrissCrossCellsOptions} */
      const q = { u: state.u, v: state.v, i: state.i, j: state.j };
      c.cells = wasm.crissCrossCells(q);
      // grid lines and diagonals of the cells where B_ij lives, evaluated on the surface (one flat (u, v) list)
      at = []; pieces = [];
      const S = 12;
      const seg = (u0, v0, u1, v1) => {
        const start = at.length / 2;
        for (let k = 0; k <= S; k++) at.push(u0 + (u1 - u0) * k / S, v0 + (v1 - v0) * k / S);
        pieces.push([start, at.length / 2]);
      };
      for (let a = 1; a <= m; a++) {
        for (let b = 1; b <= n; b++) {
          if (!inSupport(state, c.cells, a, b)) continue;
          const [u0, u1, v0, v1] = [state.u[a - 1], state.u[a], state.v[b - 1], state.v[b]];
          seg(u0, v0, u1, v0); seg(u1, v0, u1, v1); seg(u1, v1, u0, v1); seg(u0, v1, u0, v0);
          seg(u0, v0, u1, v1); seg(u1, v0, u0, v1);
        }
      }
      const uv = { u: state.u.slice(), v: state.v.slice(), i: state.i, j: state.j };
      calls = [{ fn: 'crissCrossBasis', args: { ...uv, samplesU: GRID, samplesV: GRID, mesh: true } }];
      if (at.length) calls.push({ fn: 'crissCrossBasis', args: { ...uv, atUV: Float64Array.from(at) } });
    } catch (e) { notify(e, 'error'); ready(); return true; }
    /** @param {any[]} results the basis on the grid and (when asked) at the points */
    function apply([b, r]) {
      c.basis = b;
      c.vmax = 1e-9;
      const vals = c.basis.values;
      for (let k = 0; k < vals.length; k++) if (vals[k] > c.vmax) c.vmax = vals[k];
      onBasis(c);
      c.lines = r ? pieces.map(([s0, e]) => {
        const out = new Float64Array(3 * (e - s0));
        for (let k = s0; k < e; k++) { out[3 * (k - s0)] = at[2 * k]; out[3 * (k - s0) + 1] = at[2 * k + 1]; out[3 * (k - s0) + 2] = r.values[k] + 0.002; }
        return out;
      }) : [];
    }
    const key = `${m} × ${n} cells`;
    // a new size: ~0.4 ms per cell (the first calls at 10 × 10 measured up to 40 ms in the page unloaded, the
    // slider's handler 119 ms at load 11–15): the default 5 × 4 cells stay here, from 40 cells on the worker first
    if (basisCC.runsHere(key, m * n * 0.4)) {
      try { apply(basisCC.runHere(calls, key)); } catch (e) { notify(e, 'error'); }
      ready();
      return true;
    }
    basisCC.run(calls, { key }).then((r) => {
      if (!r || mine !== computeToken) return;
      apply(r);
      ready();
    }, (e) => {
      if (mine !== computeToken) return;
      notify(e, 'error');
      ready();
    });
    return false;
  }

  /** Bᵢⱼ at its pre-image (ξᵢ, ηⱼ) (the centre readout; throws what the wasm throws). */
  const centreValue = (xi, eta) => wasm.crissCrossBasis({ u: state.u, v: state.v, i: state.i, j: state.j, atUV: [[xi, eta]] }).values[0];

  return { c, compute, centreValue };
}
