// The data of "Noisy data": the true curves of the generator, the classic data sets, the range of the a sweep,
// the pasted-points parser and what a link may hold (sanitize).
import { parsePoints } from '../../lib/data-import.js';

export const CURVES = ['sine', 'arc', 'lemniscate', 'spiral', 'step'];
export const DATASETS = [{ value: 'titanium_heat', label: 'Titanium heat (de Boor, 49 points)' }, { value: 'rpn14', label: 'RPN 14 (Fritsch–Carlson, 9 points)' }];
const MAX_CSV = 2000;
// The sweep of a (error plot, slider): wide enough that the best a — by the truth and by cross-validation — lies
// inside it for the default data (sine, 60 points, σ = 0.2: truth optimum a ≈ 0.29, CV optimum a ≈ 0.24), not
// at its end. a > 1/6 extrapolates the blend L^a = 6a·L^B + (1 − 6a)·L beyond the B-spline: it smooths more.
export const A_MIN = -0.1, A_MAX = 0.5;

/** Parses pasted text into [[x, y], …] with the shared parser of "Use my data" (www/lib/data-import.js): CSV
 *  rows (commas, semicolons, tabs or spaces; an optional header line; # comments) or JSON. A malformed row
 *  throws an Error naming it ("row 3: expected 2 numbers, got 'abc'"). */
export function parseCsv(text, min = 1) {
  return parsePoints(String(text), { dims: [2], min, max: MAX_CSV });
}

/** Validates the state in place (a link may hold anything that passed the type check); `d` is defaults(). */
export function sanitize(state, d) {
  for (const k of Object.keys(d)) if (state[k] === undefined) state[k] = d[k];
  if (!['curve', 'dataset', 'csv'].includes(state.source)) state.source = 'curve';
  if (!CURVES.includes(state.curve)) state.curve = 'sine';
  if (!DATASETS.some((o) => o.value === state.dataset)) state.dataset = 'titanium_heat';
  const num = (k, lo, hi, int = false) => { if (!(Number.isFinite(state[k]) && state[k] >= lo && state[k] <= hi) || (int && !Number.isInteger(state[k]))) state[k] = d[k]; };
  num('count', 6, 400, true); num('sigma', 0, 2); num('seed', 0, 1e9, true); num('a', A_MIN, A_MAX); num('p', 0, 0.5);
  if (!['chord', 'uniform'].includes(state.knots)) state.knots = 'chord';
  if (typeof state.csv !== 'string') state.csv = '';
  if (state.csv.length > 100000) state.csv = state.csv.slice(0, 100000);
}
