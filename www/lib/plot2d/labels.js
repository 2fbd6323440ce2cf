// Label placement for 2D plots: each label goes to the asked-for place, or to the first free one of 32 candidate
// places around its anchor (8 directions × 4 distances) when that overlaps a point marker or an earlier label.

import { PALETTE } from './palette.js';

// a canvas only for measuring text (the plot's own context may be recording an SVG export)
let measureCtx = null;
// widths already measured (labels are redrawn on every frame of a drag, mostly with the same text); setting a
// context's font and measuring costs more than the lookup. Bounded: cleared when it grows large.
const measured = new Map();
export function measure(text, font) {
  const key = font + '\n' + text;
  let r = measured.get(key);
  if (r) return r;
  if (!measureCtx) measureCtx = document.createElement('canvas').getContext('2d');
  measureCtx.font = font;
  const w = measureCtx.measureText(text).width;
  const m = /(\d+(?:\.\d+)?)px/.exec(font);
  const size = m ? Number(m[1]) : 14;
  r = Object.freeze({ w, h: Math.round(size * 1.2) });
  if (measured.size > 4000) measured.clear();
  measured.set(key, r);
  return r;
}

export const overlaps = (a, b) => a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
export function hitsDisc(r, c) {
  const qx = Math.max(r.x, Math.min(c.x, r.x + r.w)), qy = Math.max(r.y, Math.min(c.y, r.y + r.h));
  return Math.hypot(qx - c.x, qy - c.y) < c.r;
}

/**
 * Places and draws `labels` ({ X, Y, text, st } in CSS px, queued by plot.label) on `g`, clear of the marker
 * discs `markers` ({ x, y, r }) and of each other, inside W × H when possible. Returns the boxes drawn
 * ({ text, x, y, w, h }).
 */
export function drawLabels(g, labels, markers, W, H) {
  const placed = [], boxes = [];
  const discs = markers.filter((c) => c.x > -20 && c.x < W + 20 && c.y > -20 && c.y < H + 20);
  for (const L of labels) {
    const st = L.st;
    const font = st.font || '600 14px system-ui, sans-serif';
    const { w, h } = measure(L.text, font);
    const pad = st.halo !== false ? 2 : 0;
    const [dx, dy] = st.offset || [8, -8];
    const align = st.align || 'left', base = st.baseline || 'bottom';
    // the asked-for box
    const ax = L.X + dx, ay = L.Y + dy;
    const bx = align === 'center' ? ax - w / 2 : align === 'right' || align === 'end' ? ax - w : ax;
    const by = base === 'top' || base === 'hanging' ? ay : base === 'middle' ? ay - h / 2 : ay - h;
    /** @type {{ x: number, y: number, asked?: boolean }[]} */
    const cands = [{ x: bx, y: by, asked: true }];
    if (st.avoid !== false) {
      const d0 = Math.max(6, Math.min(24, Math.hypot(dx, dy) * 0.75 || 8));
      for (const k of [1, 1.9, 3, 4.5]) {
        const d = d0 * k;
        cands.push(
          { x: L.X + d, y: L.Y - d - h }, { x: L.X - d - w, y: L.Y - d - h },   // NE, NW
          { x: L.X + d, y: L.Y + d }, { x: L.X - d - w, y: L.Y + d },           // SE, SW
          { x: L.X - w / 2, y: L.Y - d - h }, { x: L.X - w / 2, y: L.Y + d },   // N, S
          { x: L.X + d + 2, y: L.Y - h / 2 }, { x: L.X - d - 2 - w, y: L.Y - h / 2 }); // E, W
      }
    }
    let best = null, bestScore = Infinity;
    for (const c of cands) {
      const box = { x: c.x - pad, y: c.y - pad, w: w + 2 * pad, h: h + 2 * pad };
      let score = 0;
      for (const q of discs) if (hitsDisc(box, q)) score += 10;
      for (const p of placed) if (overlaps(box, p)) score += 10;
      if (box.x < 0 || box.y < 0 || box.x + box.w > W || box.y + box.h > H) score += c.asked ? 1 : 5;
      if (score < bestScore) { best = { c, box }; bestScore = score; }
      if (score === 0) break;
    }
    const { c, box } = best;
    placed.push(box);
    g.font = font;
    let tx, ty;
    if (c.asked) { g.textAlign = align; g.textBaseline = base; tx = ax; ty = ay; }
    else { g.textAlign = 'left'; g.textBaseline = 'middle'; tx = c.x; ty = c.y + h / 2; }
    if (st.halo !== false) { g.lineWidth = 4; g.strokeStyle = 'rgba(255,255,255,0.9)'; g.lineJoin = 'round'; g.strokeText(L.text, tx, ty); }
    g.fillStyle = st.color || PALETTE.ink;
    g.fillText(L.text, tx, ty);
    boxes.push({ text: L.text, x: box.x, y: box.y, w: box.w, h: box.h });
  }
  return boxes;
}
