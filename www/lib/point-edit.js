// Adding and removing a demo's points with the pointer and the keyboard, on top of a plot2d plot (plot2d.js is
// not changed: this listens on its canvas and uses its public API).
//
//   const edit = pointEditing(curvePlot, {
//     group: handles,                        // the addHandles() group whose points can be removed
//     points: () => state.points,            // the polygon a new point is inserted into (nearest edge)
//     insert(index, [x, y]) { state.points.splice(index, 0, [x, y]); … },   // index in points()
//     remove(i) { state.points.splice(i, 1); … },                            // i = the group's handle index
//     canAdd: () => n < MAX, canRemove: () => n > MIN,
//     minText: () => 'A cubic needs at least 4 control points.', maxText: () => '…',
//     notify: ctx.notify, locked: options.locked,
//   });
//   edit.destroy() in the demo's destroy().
//
// Gestures: double-click (or Alt+click) on empty plot space inserts a point at the nearest place of the polygon
// (between the two ends of its nearest edge; beyond an end, a new end point); double-click on a handle of the
// group, or Delete/Backspace while a handle of the group is selected (Tab into the plot), removes it. At the
// minimum/maximum count nothing changes and a notice says why.

import { t } from './i18n.js';

/**
 * Where a point q goes into the polygon `pts` ([[x, y], …]): the index it gets (0 … pts.length). The nearest edge
 * decides; when q lies beyond the first or last point (its projection falls outside the end edges), it becomes
 * the new first or last point. `closed` polygons also consider the closing edge (and never add ends).
 */
export function insertionIndex(pts, q, { closed = false } = {}) {
  const n = pts.length;
  if (n === 0) return 0;
  if (n === 1) return 1;
  let best = Infinity, at = n, tBest = 0.5, seg = 0;
  const m = closed ? n : n - 1;
  for (let i = 0; i < m; i++) {
    const a = pts[i], b = pts[(i + 1) % n];
    const dx = b[0] - a[0], dy = b[1] - a[1], L = dx * dx + dy * dy;
    let t = L > 0 ? ((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / L : 0;
    const tc = Math.min(1, Math.max(0, t));
    const px = a[0] + tc * dx - q[0], py = a[1] + tc * dy - q[1];
    const d = px * px + py * py;
    if (d < best - 1e-15) { best = d; at = i + 1; tBest = t; seg = i; }
  }
  if (!closed) {
    if (seg === 0 && tBest < 0) return 0;
    if (seg === n - 2 && tBest > 1) return n;
  }
  return at;
}

export function pointEditing(plot, spec) {
  const canvas = plot.canvas;
  let down = null;
  const say = (msg) => {
    plot.announce?.(msg);
    if (typeof spec.notify === 'function') spec.notify(msg, 'info');
  };
  const locked = () => !!(spec.locked || plot.options?.locked || spec.group?.locked);
  const xy = (e) => { const r = canvas.getBoundingClientRect(); return [e.clientX - r.left, e.clientY - r.top]; };

  /** The handle under a page event: { own: boolean, index } or null (any group of the plot counts as a hit). */
  function hit(e) {
    const [px, py] = xy(e);
    const slop = e.pointerType === 'touch' ? 14 : 6;
    let best = null, bestD = Infinity;
    for (const h of plot.handles()) {
      if (!h.point) continue;
      const [X, Y] = plot.toScreen(h.point[0], h.point[1]);
      const d = Math.hypot(X - px, Y - py);
      if (d < 7 + slop && d < bestD) { bestD = d; best = h; }
    }
    if (!best) return null;
    const own = spec.group && best.name === spec.group.name;
    return { own, index: best.index };
  }

  function addAt(q) {
    if (locked()) return false;
    if (spec.canAdd && !spec.canAdd()) { say(spec.maxText ? spec.maxText() : t('No more points can be added here.')); return false; }
    const pts = spec.points();
    const idx = insertionIndex(pts, q, { closed: !!(spec.closed && spec.closed()) });
    spec.insert(idx, [q[0], q[1]]);
    plot.redraw();
    return true;
  }

  function removeAt(i) {
    if (locked()) return false;
    if (spec.canRemove && !spec.canRemove(i)) { say(spec.minText ? spec.minText(i) : t('This point cannot be removed: the construction needs it.')); return false; }
    spec.remove(i);
    plot.select(null);
    plot.redraw();
    return true;
  }

  function onDblClick(e) {
    const hh = hit(e);
    if (hh) { if (hh.own) { e.preventDefault(); removeAt(hh.index); } return; }
    e.preventDefault();
    const [px, py] = xy(e);
    addAt(plot.toWorld(px, py));
  }
  function onDown(e) { down = { x: e.clientX, y: e.clientY }; }
  function onClick(e) {
    if (!e.altKey || !down || Math.hypot(e.clientX - down.x, e.clientY - down.y) > 4) return;
    if (hit(e)) return;
    const [px, py] = xy(e);
    addAt(plot.toWorld(px, py));
  }
  function onKey(e) {
    if (e.key !== 'Delete' && e.key !== 'Backspace') return;
    const sel = plot.selected;
    if (!sel || sel.group !== spec.group) return;
    e.preventDefault();
    removeAt(sel.index);
  }
  canvas.addEventListener('dblclick', onDblClick);
  canvas.addEventListener('pointerdown', onDown);
  canvas.addEventListener('click', onClick);
  canvas.addEventListener('keydown', onKey);
  return {
    addAt, removeAt,
    destroy() {
      canvas.removeEventListener('dblclick', onDblClick);
      canvas.removeEventListener('pointerdown', onDown);
      canvas.removeEventListener('click', onClick);
      canvas.removeEventListener('keydown', onKey);
    },
  };
}
