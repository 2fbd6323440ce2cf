// The constants and state rules of "Criss-cross basis": the knot lines' spacing and handles, the sampling grid,
// the 13 BB ordinates of a cell (Dagnino–Lamberti–Remogna §3: the four triangles of a cell and their names),
// the camera kept in the link, and what a link may hold (sanitize).

export const MIN_GAP = 0.02;      // knot lines stay this far apart
export const STRIP = 0.09;        // the knot handles sit this far outside the unit square
export const GRID = 61;           // samples per direction for the surface and the colour map
// the four triangles of a cell as ordinate indices (b200, b020, b002, b110, b011, b101)
export const TRIANGLES = [[0, 1, 12, 4, 9, 8], [1, 2, 12, 5, 10, 9], [2, 3, 12, 6, 11, 10], [3, 0, 12, 7, 8, 11]];
export const ORD_NAMES = ['c00', 'c10', 'c11', 'c01', 'eb', 'er', 'et', 'el', 'd00', 'd10', 'd11', 'd01', 'o'];

/** k uniform cells on [0, 1]: the break lines 0, 1/k, …, 1. */
export const uniform = (k) => Array.from({ length: k + 1 }, (_, r) => r / k);
/** Subscript digits (B₃₂, u₁). */
export { subscript as sub } from '../../lib/indices.js';
/** The cells in u (m) and in v (n). */
export const cellsU = (state) => state.u.length - 1;
export const cellsV = (state) => state.v.length - 1;
/** The index of cell (a, b), 1-based, in the wasm's cell lists (u-major). */
export const cellIndex = (state, a, b) => (a - 1) * cellsV(state) + (b - 1);
/** The pre-image (ξᵢ, ηⱼ) of Bᵢⱼ: the centre of cell (i, j), or the domain's edge for i = 0, m + 1 (j likewise). */
export function preImage(state) {
  const U = state.u, V = state.v, m = cellsU(state), n = cellsV(state);
  const xi = state.i === 0 ? U[0] : state.i > m ? U[m] : (U[state.i - 1] + U[state.i]) / 2;
  const eta = state.j === 0 ? V[0] : state.j > n ? V[n] : (V[state.j - 1] + V[state.j]) / 2;
  return [xi, eta];
}

// The camera in the state: [yaw°, pitch°, distance, target x, y, z] ([] = frame the surface).
export const validCamera = (a) => Array.isArray(a) && (a.length === 0 || (a.length === 6 && a.every(Number.isFinite) && a[2] > 0));
export const cameraOf = (v) => [v.yaw, v.pitch, v.distance, ...v.target];
export const cameraFrom = (a) => ({ yaw: a[0], pitch: a[1], distance: a[2], target: a.slice(3, 6) });

/** Break lines 0 = x₀ < … < x_k = 1, at most 12, at least MIN_GAP apart. */
function validBreaks(x) {
  if (!Array.isArray(x) || x.length < 2 || x.length > 12 || x[0] !== 0 || x[x.length - 1] !== 1) return false;
  for (let k = 1; k < x.length; k++) if (!(Number.isFinite(x[k]) && x[k] - x[k - 1] >= MIN_GAP * 0.999)) return false;
  return true;
}

/** Validates the state in place (a link may hold anything that passed the type check); `d` is defaults(). */
export function sanitize(state, d) {
  if (!validBreaks(state.u)) state.u = d.u.slice();
  if (!validBreaks(state.v)) state.v = d.v.slice();
  const m = cellsU(state), n = cellsV(state);
  const clampInt = (x, lo, hi, def) => (Number.isInteger(x) ? Math.min(hi, Math.max(lo, x)) : def);
  state.i = clampInt(state.i, 0, m + 1, Math.min(d.i, m + 1));
  state.j = clampInt(state.j, 0, n + 1, Math.min(d.j, n + 1));
  if (!Array.isArray(state.cell) || state.cell.length !== 2) state.cell = [1, 1];
  state.cell = [clampInt(state.cell[0], 1, m, 1), clampInt(state.cell[1], 1, n, 1)];
  state.map = state.map !== false;
  state.ordinates = state.ordinates !== false;
  if (!validCamera(state.view)) state.view = [];
}
