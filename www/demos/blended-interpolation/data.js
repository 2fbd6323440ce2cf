// The data of "Blended interpolation": the limits, the own points, and the paper's data sets (Titanium, RPN 14;
// www/data/datasets.js) scaled into the plot box with auxiliary end points b₋₁, bₙ₊₁ continuing the end chords.
import { TITANIUM, RPN14 } from '../../data/datasets.js';

export const MAX_POINTS = 80;
export const BETA_MAX = 4;
// b₋₁ … b₇ (the first and last are the auxiliary end points)
export const CUSTOM = [[-1, 0.2], [0, 0], [1, 2.1], [2.7, 2.6], [3.4, 0.9], [5.2, 0.4], [6.1, 2.8], [8, 3.3], [9.5, 1.2]];

/** A data set scaled into a box [0, W] × [0, Hh], with auxiliary points continuing the first/last chord. */
function scaled(ds, W, Hh) {
  const xs = ds.x, ys = ds.y;
  const x0 = Math.min(...xs), x1 = Math.max(...xs), y0 = Math.min(...ys), y1 = Math.max(...ys);
  const pts = xs.map((x, i) => [(x - x0) / (x1 - x0) * W, (ys[i] - y0) / (y1 - y0) * Hh]);
  const a = pts[0], b = pts[1], c = pts[pts.length - 2], d = pts[pts.length - 1];
  return [[2 * a[0] - b[0], 2 * a[1] - b[1]], ...pts, [2 * d[0] - c[0], 2 * d[1] - c[1]]];
}

export const MIN_POINTS = 5; // b₋₁, three data points, bₙ₊₁

/** Subscript digits and minus (b₋₁). */
import { subscript as sub } from '../../lib/indices.js';
export { sub };

/** The points b₋₁ … bₙ₊₁ of a data set: Titanium in [0, 12] × [0, 4], RPN 14 in [0, 10] × [0, 4], or the own points. */
export function datasetPoints(v) {
  return v === 'titanium' ? scaled(TITANIUM, 12, 4) : v === 'rpn14' ? scaled(RPN14, 10, 4) : CUSTOM.map((p) => p.slice());
}

/** The hint under the data choice: which data, how many points, what k = 2 does. */
export function dataNote(state) {
  const n = state.points.length - 3;
  return (state.dataset === 'titanium' ? `Titanium heat data (49 points), scaled to [0, 12] × [0, 4]. ` : state.dataset === 'rpn14' ? 'RPN 14 radiochemical data (9 points, monotone), scaled to [0, 10] × [0, 4]. ' : '')
    + `${n + 1} data points b₀ … b${sub(n)}; the grey end points b₋₁, b${sub(n + 1)} only shape the ends.`
    + (state.k === 2 ? ' k = 2: the second derivative jumps at the data points (the curve is only C¹).' : '');
}
