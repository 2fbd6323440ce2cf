// The colour map of "Criss-cross basis": a viridis-like ramp, and the map of Bᵢⱼ / max Bᵢⱼ as a GRID × GRID image
// (one texel per grid sample) that the domain plot draws scaled onto [0, 1]², clipped to the support.
import { GRID } from './data.js';

// viridis-like ramp for the colour map (5 stops), t in [0, 1]
const RAMP = [[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]];
function rampRGB(t) {
  const x = Math.min(1, Math.max(0, t)) * (RAMP.length - 1);
  const k = Math.min(RAMP.length - 2, Math.floor(x)), f = x - k;
  return RAMP[k].map((a, q) => Math.round(a + (RAMP[k + 1][q] - a) * f));
}
/** The ramp's CSS colour at t in [0, 1]. */
export function ramp(t) { const c = rampRGB(t); return `rgb(${c[0]},${c[1]},${c[2]})`; }
// the ramp at 1024 levels as opaque RGBA pixels (one 32-bit word each, in the platform's byte order), for
// writing the colour map straight into an image
const LEVELS = 1024;
const RAMP_PX = (() => {
  const px = new Uint32Array(LEVELS), bytes = new Uint8ClampedArray(px.buffer);
  for (let q = 0; q < LEVELS; q++) { bytes.set(rampRGB(q / (LEVELS - 1)), 4 * q); bytes[4 * q + 3] = 255; }
  return px;
})();
export const MAP_ALPHA = 0.85;    // the colour map over the white domain

/**
 * Writes the colour map of `values` (B_ij on the u-major n × n grid: sample iu·n + iv at (iu, iv) / (n − 1))
 * into the n × n pixels `px` (row 0 at the top, so v points up): the ramp at values / vmax (≤ 0 → 0).
 */
function rampImage(px, values, vmax, n) {
  const k = (LEVELS - 1) / vmax;
  for (let iu = 0; iu < n; iu++) {
    for (let iv = 0; iv < n; iv++) {
      const t = values[iu * n + iv] * k;
      px[(n - 1 - iv) * n + iu] = RAMP_PX[t > 0 ? (t < LEVELS - 1 ? (t + 0.5) | 0 : LEVELS - 1) : 0];
    }
  }
}

/**
 * The colour map as an image: one texel per grid sample (column iu, row GRID − 1 − iv, since v points up),
 * coloured by B_ij / max B_ij through the ramp. The plot draws it scaled onto the domain with bilinear
 * smoothing (the texel centres sit on the sample points (u, v) = (iu, iv) / (GRID − 1)), clipped to the
 * support triangles: outside them B_ij = 0 and nothing is drawn; inside, the colour runs down to the value 0
 * at the support's edge. `ok` is false where the browser gives no 2D context (then there is no map).
 */
export function colourMap() {
  const canvas = document.createElement('canvas');
  canvas.width = GRID; canvas.height = GRID;
  const g = canvas.getContext('2d');
  const image = g ? g.createImageData(GRID, GRID) : null;
  const pixels = image ? new Uint32Array(image.data.buffer) : null;
  return {
    canvas, ok: !!image,
    /** Paints the values of the basis on its GRID² grid with the maximum vmax. */
    paint(basis, vmax) {
      if (!image || basis.values.length !== GRID * GRID) return;
      rampImage(pixels, basis.values, vmax, GRID);
      g.putImageData(image, 0, 0);
    },
  };
}
