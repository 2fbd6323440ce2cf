// Draggable handles of a 2D plot: groups of points the demo owns (read live through points()), their markers,
// hit testing with a pointer-type slop, constrained moves and the names spoken for them.

import { pair } from '../dom.js';
import { PALETTE } from './palette.js';
import { t } from '../i18n.js';

/**
 * The handle groups of one plot. `st` is the plot's shared interaction state ({ groups, hover, selected, drag,
 * pointers }); `o` its options; `g`, `sx`, `sy` its context and transform; `marker`, `label` its primitives;
 * `addMarker` records a marker disc of the frame; `isFocused()`; `redraw()`.
 */
export function createHandles({ st, o, g, sx, sy, marker, label, addMarker, isFocused, redraw }) {
  /**
   * Draggable handles. `spec`:
   *   name        'control point' (used in the keyboard/screen-reader text)
   *   points()    → the live array of [x, y] (read at every frame and hit test)
   *   move(i, [x, y], how)  apply a move (after `constrain`); `how` is 'drag' | 'key'
   *   constrain(i, [x, y]) → [x, y]  optional (keep knots ordered, move only in x, …)
   *   end(i)      optional, after a drag or key move ends (e.g. ctx.save())
   *   start(i)    optional, when a drag starts
   *   color, radius (px, default 7), shape, label(i) → string (drawn next to the handle), labelOf(i) (spoken; both
   *               with Unicode subscripts, P₃ not P3: the paper's name)
   *   step        world step for arrow keys (default: 1/100 of the view width); Shift × 10
   *   axis        'x' | 'y' to restrict arrow keys (and drags) to one axis
   *   locked      true → not movable (overrides nothing if the plot is locked anyway)
   *   hidden      true → not drawn / not hit
   * Returns the group (with .remove()). Groups added later are drawn on top.
   */
  function addHandles(spec) {
    const gr = { radius: 7, color: PALETTE.control, name: 'point', ...spec };
    gr.remove = () => { const k = st.groups.indexOf(gr); if (k >= 0) st.groups.splice(k, 1); if (st.selected?.group === gr) st.selected = null; redraw(); };
    st.groups.push(gr);
    redraw();
    return gr;
  }

  const movable = (gr) => !o.locked && !gr.locked && !gr.hidden;

  function flatHandles() {
    const out = [];
    for (const gr of st.groups) {
      if (gr.hidden) continue;
      const ps = gr.points() || [];
      for (let i = 0; i < ps.length; i++) out.push({ group: gr, index: i });
    }
    return out;
  }

  // the handles' discs are known before the demo draws, so that every label of the frame avoids them
  function registerHandles() {
    for (const gr of st.groups) {
      if (gr.hidden) continue;
      const ps = gr.points() || [];
      for (let i = 0; i < ps.length; i++) {
        const [x, y] = ps[i];
        if (Number.isFinite(x) && Number.isFinite(y)) addMarker({ x: sx(x), y: sy(y), r: (gr.radius || 7) * (gr.shape && gr.shape !== 'circle' ? 1.3 : 1) + 2 });
      }
    }
  }

  function drawHandles() {
    const focused = isFocused();
    for (const gr of st.groups) {
      if (gr.hidden) continue;
      const ps = gr.points() || [];
      for (let i = 0; i < ps.length; i++) {
        const [x, y] = ps[i];
        if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
        const X = sx(x), Y = sy(y);
        const isHover = st.hover && st.hover.group === gr && st.hover.index === i;
        const isSel = st.selected && st.selected.group === gr && st.selected.index === i;
        const isDrag = st.drag && st.drag.kind === 'handle' && st.drag.group === gr && st.drag.index === i;
        const r = gr.radius + (isHover || isDrag ? 2 : 0);
        marker(X, Y, r, gr.shape);
        g.fillStyle = gr.colorOf ? gr.colorOf(i) : gr.color;
        g.fill();
        g.lineWidth = 2; g.strokeStyle = '#fff'; g.stroke();
        if (isSel && focused) {
          g.beginPath(); g.arc(X, Y, r + 6, 0, 2 * Math.PI);
          g.lineWidth = 3; g.strokeStyle = PALETTE.focus; g.setLineDash([4, 3]); g.stroke(); g.setLineDash([]);
        }
        if (gr.label) {
          const s = gr.label(i);
          if (s) label(x, y, s, { color: gr.labelColor || PALETTE.ink, offset: gr.labelOffset || [r + 3, -r - 1] });
        }
      }
    }
  }

  function hitTest(px, py, pointerType) {
    const slop = pointerType === 'touch' ? 14 : pointerType === 'pen' ? 8 : 5;
    let best = null, bestD = Infinity;
    for (let k = st.groups.length - 1; k >= 0; k--) {
      const gr = st.groups[k];
      if (gr.hidden) continue;
      const ps = gr.points() || [];
      for (let i = 0; i < ps.length; i++) {
        const d = Math.hypot(sx(ps[i][0]) - px, sy(ps[i][1]) - py);
        if (d <= gr.radius + slop && d < bestD) { best = { group: gr, index: i }; bestD = d; }
      }
    }
    return best;
  }

  function applyMove(gr, i, x, y, how) {
    const ps = gr.points();
    if (!ps || !ps[i]) return;
    if (gr.axis === 'x') y = ps[i][1];
    if (gr.axis === 'y') x = ps[i][0];
    let p = [x, y];
    if (gr.constrain) p = gr.constrain(i, p) || p;
    if (!Number.isFinite(p[0]) || !Number.isFinite(p[1])) return;
    gr.move(i, p, how);
    st.moved = { group: gr, index: i };   // the figure's description says it first (plot2d.js scheduleDescribe)
    redraw();
  }

  /** The paper's name of handle `sel` alone ("Control point P₃", "knot u₃"; see nameOf). */
  function nameOnly(sel) {
    const gr = sel.group, drawn = gr.label ? gr.label(sel.index) : '';
    return gr.labelOf ? t(gr.labelOf(sel.index)) : drawn ? `${t(gr.name)} ${drawn}` : `${t(gr.name)} ${sel.index + 1}`;
  }

  /**
   * The spoken name of handle `sel`: the demo's labelOf(i) (the paper's name, e.g. "Control point P₃"), else the
   * group's name with the drawn label ("knot u₃"), else with a count ("point 4": only where the paper has no
   * name). With `position`, its place in the keyboard order ("3 of 7", see flatHandles). Then where it is.
   */
  function nameOf(sel, { position = false } = {}) {
    if (!sel) return '';
    const gr = sel.group;
    const p = (gr.points() || [])[sel.index];
    const nm = nameOnly(sel);
    let where = '';
    if (position) {
      const list = flatHandles();
      const k = list.findIndex((s) => s.group === gr && s.index === sel.index);
      if (k >= 0) where = ` (${t('{i} of {n}', { i: k + 1, n: list.length })})`;
    }
    return p ? t('{name} at {where}', { name: `${nm}${where}`, where: pair(p[0], p[1]) }) : `${nm}${where}`;
  }

  return { addHandles, movable, flatHandles, registerHandles, drawHandles, hitTest, applyMove, nameOf, nameOnly };
}
