// Colour maps for scalar fields (heights, distances, curvature) and their legends.
//
//   viridis(t) / diverging(t)        t ∈ [0, 1] → [r, g, b] in [0, 1]
//   colormap(name)                    the function for 'viridis' | 'diverging'
//   colormapLUT(name, n = 256)        Uint8Array of n RGBA texels (for a WebGL texture)
//   cssColor(name, t)                 'rgb(r, g, b)'
//   scalarRange(values, { symmetric }) → [min, max] of the finite values (symmetric around 0 if asked)
//   drawLegendBar(ctx2d, name, x, y, w, h, { vertical })   paints the gradient
//   legendElement({ colormap, min, max, label, ticks })     a small DOM legend (canvas bar + text labels)
//
// viridis is perceptually uniform and readable in greyscale and by most colour-blind viewers; the diverging map
// (blue – light grey – red, after Moreland's "cool to warm") is for signed quantities centred on 0 such as the
// difference of two surfaces or Gaussian curvature. Both are piecewise linear through a small table of sRGB
// samples of the published maps.

import { localDigits } from './i18n.js';

const VIRIDIS = [
  '#440154', '#482475', '#414487', '#355f8d', '#2a788e', '#21918c',
  '#22a884', '#44bf70', '#7ad151', '#bddf26', '#fde725',
];
const DIVERGING = [
  '#3b4cc0', '#5977e3', '#7b9ff9', '#9ebeff', '#c0d4f5', '#dddcdc',
  '#f2cbb7', '#f7ac8e', '#ee8468', '#d65244', '#b40426',
];

function parseHex(h) {
  const n = parseInt(h.slice(1), 16);
  return [((n >> 16) & 255) / 255, ((n >> 8) & 255) / 255, (n & 255) / 255];
}
const TABLES = { viridis: VIRIDIS.map(parseHex), diverging: DIVERGING.map(parseHex) };

function sample(table, t) {
  if (!Number.isFinite(t)) t = 0;
  t = Math.min(1, Math.max(0, t));
  const s = t * (table.length - 1);
  const i = Math.min(table.length - 2, Math.floor(s));
  const f = s - i;
  const a = table[i], b = table[i + 1];
  return [a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f, a[2] + (b[2] - a[2]) * f];
}

export const COLORMAPS = Object.freeze(Object.keys(TABLES));
export const viridis = (t) => sample(TABLES.viridis, t);
export const diverging = (t) => sample(TABLES.diverging, t);

/** The colour function of a map by name ('viridis' | 'diverging'); unknown names give viridis. */
export function colormap(name) {
  const table = TABLES[name] || TABLES.viridis;
  return (t) => sample(table, t);
}

/** n RGBA texels of the map, 0..255 (for a 256×1 WebGL texture). */
export function colormapLUT(name, n = 256) {
  const f = colormap(name);
  const out = new Uint8Array(n * 4);
  for (let i = 0; i < n; i++) {
    const c = f(n === 1 ? 0 : i / (n - 1));
    out[4 * i] = Math.round(c[0] * 255);
    out[4 * i + 1] = Math.round(c[1] * 255);
    out[4 * i + 2] = Math.round(c[2] * 255);
    out[4 * i + 3] = 255;
  }
  return out;
}

/** The colour at t as a CSS `rgb()` string. */
export function cssColor(name, t) {
  const c = colormap(name)(t);
  return `rgb(${Math.round(c[0] * 255)}, ${Math.round(c[1] * 255)}, ${Math.round(c[2] * 255)})`;
}

/**
 * [min, max] of the finite values (NaN/±∞ skipped); [0, 1] when there are none. With `symmetric: true` the range
 * is [−m, m] with m = max |value| (for the diverging map). A zero-width range is widened so t stays defined.
 */
export function scalarRange(values, { symmetric = false } = {}) {
  let lo = Infinity, hi = -Infinity;
  for (let i = 0; i < values.length; i++) {
    const v = values[i];
    if (Number.isFinite(v)) { if (v < lo) lo = v; if (v > hi) hi = v; }
  }
  if (lo > hi) return [0, 1];
  if (symmetric) { const m = Math.max(Math.abs(lo), Math.abs(hi)); lo = -m; hi = m; }
  if (hi - lo < 1e-300) { const d = Math.max(Math.abs(hi) * 1e-6, 1e-12); lo -= d; hi += d; }
  return [lo, hi];
}

/** Paints the gradient of map `name` into the rectangle; horizontal (low → high left to right) or vertical (low at the bottom). */
export function drawLegendBar(ctx, name, x, y, w, h, { vertical = false } = {}) {
  const g = vertical ? ctx.createLinearGradient(0, y + h, 0, y) : ctx.createLinearGradient(x, 0, x + w, 0);
  for (let i = 0; i <= 16; i++) g.addColorStop(i / 16, cssColor(name, i / 16));
  ctx.fillStyle = g;
  ctx.fillRect(x, y, w, h);
  ctx.strokeStyle = '#333';
  ctx.lineWidth = 1;
  ctx.strokeRect(x + 0.5, y + 0.5, w - 1, h - 1);
}

/** A short number for a tick label. */
export function formatTick(v) {
  if (v === 0) return '0';
  const a = Math.abs(v);
  if (a >= 1e4 || a < 1e-3) return localDigits(v.toExponential(2));
  return localDigits(String(Number(v.toPrecision(3))));
}

/**
 * A self-contained legend element: a horizontal gradient bar with min / mid / max tick labels and a caption.
 * All text is set with textContent. Returns the element (a <figure>); update it with `updateLegend`.
 */
export function legendElement(opts = {}) {
  const fig = document.createElement('figure');
  fig.className = 'sl-legend';
  fig.style.cssText = 'margin:0;padding:4px 6px;background:rgba(255,255,255,0.92);border:1px solid #888;'
    + 'border-radius:4px;font:12px/1.3 system-ui,sans-serif;color:#111;min-width:140px;';
  const cap = document.createElement('figcaption');
  cap.style.cssText = 'font-weight:600;margin-bottom:2px;';
  const bar = document.createElement('canvas');
  bar.width = 160; bar.height = 12;
  bar.style.cssText = 'display:block;width:100%;height:12px;';
  bar.setAttribute('aria-hidden', 'true');
  const ticks = document.createElement('div');
  ticks.style.cssText = 'display:flex;justify-content:space-between;gap:6px;font-variant-numeric:tabular-nums;';
  const spans = [0, 1, 2].map(() => ticks.appendChild(document.createElement('span')));
  fig.append(cap, bar, ticks);
  fig._parts = { cap, bar, spans };
  updateLegend(fig, opts);
  return fig;
}

/** Redraws a legend made by `legendElement` with new { colormap, min, max, label }. */
export function updateLegend(fig, { colormap: name = 'viridis', min = 0, max = 1, label = '' } = {}) {
  const { cap, bar, spans } = fig._parts;
  // only what changed is written (a legend may be updated on every frame of a drag)
  const text = (el, t) => { if (el.textContent !== t) el.textContent = t; };
  text(cap, label);
  if (cap.hidden !== !label) cap.hidden = !label;
  if (fig._map !== name) {
    const ctx = bar.getContext('2d');
    if (ctx) { ctx.clearRect(0, 0, bar.width, bar.height); drawLegendBar(ctx, name, 0, 0, bar.width, bar.height); fig._map = name; }
  }
  text(spans[0], formatTick(min));
  text(spans[1], formatTick((min + max) / 2));
  text(spans[2], formatTick(max));
  const aria = `${label ? label + ': ' : ''}colour scale ${name} from ${formatTick(min)} to ${formatTick(max)}`;
  if (fig.getAttribute('aria-label') !== aria) fig.setAttribute('aria-label', aria);
}
