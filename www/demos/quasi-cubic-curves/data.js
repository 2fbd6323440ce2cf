// The data of "Quasi-cubic curves": the limits, the presets (their polygons come from the wasm API,
// quasiCubicPreset), the free polygon, and the teaching text of each preset's condition (quasi-cubic paper §3).

export const MAX_POINTS = 14;
export const PRESETS = ['free', 'ellipse', 'circle', 'parabola', 'sine'];
export const FREE_POINTS = [[0, 0], [0.8, 2.2], [2.4, 2.6], [3.4, 0.6], [4.8, 0.4], [5.6, 2.4], [7, 2]];

/** Subscript digits (b₃). */
export { subscript as sub } from '../../lib/indices.js';

/** True when two point lists hold the same points (bookkeeping: which polygon a state carries). */
export function samePoints(a, b) {
  return a.length === b.length && a.every((p, i) => p[0] === b[i][0] && p[1] === b[i][1]);
}

/** Segments whose sine relations (x, y residual pairs) are broken. */
export function brokenSegments(r) {
  const out = [];
  for (let i = 0; 2 * i + 1 < (r?.length ?? 0); i++) if (r[2 * i] > 1e-9 || r[2 * i + 1] > 1e-9) out.push(i);
  return out;
}

// Which relation of the preset a control point takes part in (for the teaching text).
export const CONDITION_TEXT = {
  ellipse: 'b₀ + b₂ = b₁ + b₃: the two diagonals must bisect each other (a parallelogram; the paper’s rhombus puts the axes on the diagonals). The red segment joins the two diagonal midpoints.',
  circle: 'a square: the diagonals bisect each other, have equal length and are perpendicular.',
  parabola: 'b₀ = b₂: the apex is used twice (the paper also asks for an isosceles triangle, which affine invariance makes unnecessary). The red segment joins b₀ and b₂.',
  sine: 'for every four consecutive points: xᵢ + xᵢ₊₃ = xᵢ₊₁ + xᵢ₊₂ (x linear in t) and yᵢ + yᵢ₊₁ = yᵢ₊₂ + yᵢ₊₃ (no linear drift in y).',
};
