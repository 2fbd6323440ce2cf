import { PALETTE } from '../../lib/plot2d.js';
// The networks of "Curve networks": the surfaces and their colours, the preset networks (wasm examples or networks
// from a formula on the paper's grids) with the same calls as code for "Copy as code", the largest network taken,
// and what a link may hold (sanitize).

export const SURFACES = ['S', 'T', 'G', 'GB'];
export const NAMES = { S: 'S (criss-cross)', T: 'T (thin-plate)', G: 'G (Gordon)', GB: 'GB (spline-blended)' };
// Okabe–Ito colours, readable on a projector
export const COLOURS = { S: PALETTE.curve, T: PALETTE.accent, G: PALETTE.second, GB: PALETTE.highlight, L1: PALETTE.sky, L2: PALETTE.control, Tg: PALETTE.muted };
const U3 = [0, 1 / 3, 2 / 3, 1];
const U6 = [0, 0.2, 0.4, 0.6, 0.8, 1];
const upTo = (k) => Array.from({ length: k + 1 }, (_, i) => i);   // the breakpoints 0, 1, …, k

// The paper's grids (m, n, the breakpoints uᵢ = i, vⱼ = j) with curves of our own: the paper prints no control
// points of its networks (its Figs. 4, 6, 9), so the shapes are ours; the labels say so.
const F18 = (u, v) => [u, v, 1.5 * Math.sin(Math.PI * u / 6) * Math.cos(Math.PI * (v - 2) / 6) + 0.25 * v];
const F54 = (u, v) => [u, v, 3.5 - 0.22 * (u - 2.5) ** 2 - 0.3 * (v - 2) ** 2 + 0.15 * u * Math.sin(v)];

/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

/**
 * Preset networks: wasm examples or networks from a formula (networkFromFunction).
 * @type {Record<string, { label: string, build: (w: SplineLab) => import('../../../types/splinelab.js').Network }>}
 */
export const PRESETS = {
  paper: { label: 'm = n = 3 on [0,1]², §4.2 grid', build: (w) => w.networkFromFunction({ u: U3, v: U3, f: (u, v) => [u, v, 0.45 * Math.sin(Math.PI * u) * Math.sin(Math.PI * v) + 0.35 * u * v * v] }) },
  'paper-18x4': { label: 'm = 18, n = 4, §4.1 grid', build: (w) => w.networkFromFunction({ u: upTo(18), v: upTo(4), f: F18 }) },
  'three-sided': { label: '3-sided facets (§4.3, m = 5, n = 3)', build: (w) => w.networkExample({ name: 'three-sided' }) },
  'paper-5x4': { label: 'm = 5, n = 4, §4.3 grid', build: (w) => w.networkFromFunction({ u: upTo(5), v: upTo(4), f: F54 }) },
  separable: { label: 'Separable (S = G exactly)', build: (w) => w.networkExample({ name: 'separable' }) },
  dome: { label: 'Dome, m = n = 5', build: (w) => w.networkFromFunction({ u: U6, v: U6, f: (u, v) => [u, v, 0.6 - 0.9 * ((u - 0.5) ** 2 + (v - 0.5) ** 2) + 0.25 * u * (1 - v) * Math.cos(3 * v)] }) },
  dome10: { label: 'Dome 10 × 10 (speed)', build: (w) => w.networkExample({ name: 'dome10' }) },
};

// The presets as code (the same calls as PRESETS[…].build).
export const PRESET_CODE = {
  paper: "sl.networkFromFunction({ u: [0, 1 / 3, 2 / 3, 1], v: [0, 1 / 3, 2 / 3, 1], f: (u, v) => [u, v, 0.45 * Math.sin(Math.PI * u) * Math.sin(Math.PI * v) + 0.35 * u * v * v] })",
  'paper-18x4': "sl.networkFromFunction({ u: [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18], v: [0, 1, 2, 3, 4], f: (u, v) => [u, v, 1.5 * Math.sin(Math.PI * u / 6) * Math.cos(Math.PI * (v - 2) / 6) + 0.25 * v] })",
  'three-sided': "sl.networkExample({ name: 'three-sided' })",
  'paper-5x4': "sl.networkFromFunction({ u: [0, 1, 2, 3, 4, 5], v: [0, 1, 2, 3, 4], f: (u, v) => [u, v, 3.5 - 0.22 * (u - 2.5) ** 2 - 0.3 * (v - 2) ** 2 + 0.15 * u * Math.sin(v)] })",
  separable: "sl.networkExample({ name: 'separable' })",
  dome: "sl.networkFromFunction({ u: [0, 0.2, 0.4, 0.6, 0.8, 1], v: [0, 0.2, 0.4, 0.6, 0.8, 1], f: (u, v) => [u, v, 0.6 - 0.9 * ((u - 0.5) ** 2 + (v - 0.5) ** 2) + 0.25 * u * (1 - v) * Math.cos(3 * v)] })",
  dome10: "sl.networkExample({ name: 'dome10' })",
};

// The largest network the demo takes (issue 26, limits that say so): 30 × 30 cells, i.e. 31 curves φᵣ and 31 curves
// ψₛ. Chosen from measurements: its state (the network, ~57 KB of JSON) still fits in a link (www/lib/state.js
// decodes at most 64 KB; 40 × 40 is ~100 KB), and on the main thread its drag stays small (networkRepair, the
// control points: ~10 ms) while the surfaces and numbers go to the worker (30 × 30 at 96², four surfaces:
// 25–50 ms per frame on a loaded 2-core machine, which would drop frames here). Larger networks are refused with
// a message naming the field; nothing is cut down silently.
export const MAX_CELLS = 30;
/** null, or why the network `nw` is over the limit (a sentence naming the field). */
export function overLimit(nw) {
  const m = nw.u.length - 1, n = nw.v.length - 1;
  if (m <= MAX_CELLS && n <= MAX_CELLS) return null;
  return `network: at most ${MAX_CELLS} × ${MAX_CELLS} cells (${MAX_CELLS + 1} values in u and in v); this one has ${m} × ${n} cells (u has ${m + 1} values, v ${n + 1}). Larger networks would not fit in a link, and a drag would fall behind.`;
}

export { subscript as sub } from '../../lib/indices.js';
const isNet = (n) => n && Array.isArray(n.u) && Array.isArray(n.v) && Array.isArray(n.P) && Array.isArray(n.Q);
export const clone = (n) => JSON.parse(JSON.stringify(n));

/** Validates the state in place (a link may hold anything that passed the type check); `d` is defaults(). */
export function sanitize(state, d) {
  if (!PRESETS[state.preset]) state.preset = d.preset;
  if (state.network !== null && !isNet(state.network)) state.network = null;
  if (!state.show || typeof state.show !== 'object') state.show = { ...d.show };
  for (const k of SURFACES) state.show[k] = !!state.show[k];
  if (!['side', 'overlay'].includes(state.layout)) state.layout = d.layout;
  if (!['none', 'SG', 'ST', 'TG', 'SGB'].includes(state.colorBy)) state.colorBy = 'none';
  state.components = !!state.components;
  state.triangulation = !!state.triangulation;
  if (!(Array.isArray(state.cell) && state.cell.length === 2 && state.cell.every(Number.isInteger))) state.cell = null;
  if (!Number.isInteger(state.density) || state.density < 8 || state.density > 96) state.density = d.density;
  if (!Number.isInteger(state.step) || state.step < -1 || state.step > 40) state.step = -1;
}
