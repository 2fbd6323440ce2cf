// The world ↔ screen transform of a 2D plot and what it needs: the default view, tick steps, bounds of data.

export const DEFAULT_VIEW = { xmin: -1, xmax: 1, ymin: -1, ymax: 1 };

/** A round tick step (1, 2 or 5 × 10ⁿ) giving about `target` ticks over `range`. */
export function niceStep(range, target) {
  const raw = range / Math.max(1, target);
  const p = Math.pow(10, Math.floor(Math.log10(raw)));
  const m = raw / p;
  return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
}

/** The decimals a tick label needs for tick step `step`. */
export function tickDigits(step) { return Math.max(0, Math.min(8, -Math.floor(Math.log10(step) + 1e-9))); }

/**
 * The transform for a world rectangle `view` on a W × H px canvas: screen = ((x − xmin)·kx, (ymax − y)·ky).
 * With `equal`, one scale for both axes (the rectangle grows about its centre to fill the canvas).
 */
export function layoutTransform(view, W, H, equal) {
  let { xmin, xmax, ymin, ymax } = view;
  if (!(xmax > xmin)) { xmax = xmin + 1; }
  if (!(ymax > ymin)) { ymax = ymin + 1; }
  let kx = W / (xmax - xmin), ky = H / (ymax - ymin);
  if (equal) {
    const k = Math.min(kx, ky);
    const cx = (xmin + xmax) / 2, cy = (ymin + ymax) / 2;
    kx = ky = k;
    xmin = cx - W / k / 2; xmax = cx + W / k / 2;
    ymin = cy - H / k / 2; ymax = cy + H / k / 2;
  }
  return { kx, ky, xmin, xmax, ymin, ymax };
}

/** Bounds of flat arrays / point lists: boundsOf(flat, stride) or boundsOf([[x,y],…]). */
export function boundsOf(...sets) {
  const b = { xmin: Infinity, xmax: -Infinity, ymin: Infinity, ymax: -Infinity };
  const add = (x, y) => { if (Number.isFinite(x) && Number.isFinite(y)) { b.xmin = Math.min(b.xmin, x); b.xmax = Math.max(b.xmax, x); b.ymin = Math.min(b.ymin, y); b.ymax = Math.max(b.ymax, y); } };
  for (const s of sets) {
    if (!s) continue;
    if (Array.isArray(s.data)) { for (let i = 0; i + 1 < s.data.length; i += s.stride || 2) add(s.data[i], s.data[i + 1]); continue; }
    if (ArrayBuffer.isView(s)) { for (let i = 0; i + 1 < s.length; i += 2) add(s[i], s[i + 1]); continue; }
    if (s.flat && ArrayBuffer.isView(s.flat)) { for (let i = 0; i + 1 < s.flat.length; i += s.stride || 2) add(s.flat[i], s.flat[i + 1]); continue; }
    for (const p of s) add(p[0], p[1]);
  }
  return Number.isFinite(b.xmin) ? b : null;
}
