// A 2D canvas plot for SplineLab demos: world ↔ screen transform (optionally equal aspect), pan and zoom,
// grid and axes with tick labels, HiDPI, drawing helpers in world coordinates, and draggable handles that
// work with mouse, pen, touch and keyboard. Touch: one finger on a handle drags it; one finger elsewhere scrolls
// the page (touch-action: pan-y); two fingers pan and zoom the plot. Mouse and pen: drag the background to pan.
//
//   const plot = createPlot(parent, { ariaLabel: 'Curve', equal: true, view: { xmin: 0, xmax: 6, ymin: 0, ymax: 4 },
//                                     draw(g, plot) { plot.polyline(result.points, { color: PALETTE.curve }); } });
//   plot.addHandles({ name: 'control point', points: () => state.points,
//                     move(i, [x, y]) { state.points[i] = [x, y]; recompute(); plot.redraw(); }, end() { ctx.save(); } });
//   plot.redraw();   // coalesced to one animation frame; call it after any change
//   plot.destroy();  // in the demo's destroy()
//
// Drawing helpers (world coordinates; call them inside draw/drawOver): polyline(flat | [[x,y]], { stride: 2|3,
// color, width, dash: true|[on,off], alpha, close, fill }), fill(poly, { color, alpha }), fillUnder(flat,
// { base, color, alpha }), points(flat | [[x,y]], { radius, color, shape, hollow, stroke }), label(x, y, text,
// { color, offset, align, baseline, font }), segment(x0, y0, x1, y1, st), vline(x, st), hline(y, st),
// arrow(x0, y0, x1, y1, { head }), comb(points, vectors, { scale, every, envelope }).
// View: toScreen(x, y), toWorld(px, py), setView(rect), getView(), fitBounds(rect, padPx), boundsOf(...sets),
// fitContent(), zoomBy(f). Keyboard: Tab into the canvas selects the first handle, Tab/Shift+Tab or [ ] move
// the selection (Tab past the last handle leaves the plot), arrows move it (Shift ×10), Esc deselects,
// + − 0 zoom/fit. Tests reach the API as canvas.splinePlot.

import { h, fmt } from './dom.js';
import { PALETTE, SERIES } from './plot2d/palette.js';
import { DEFAULT_VIEW, layoutTransform, boundsOf } from './plot2d/view.js';
import { drawGrid } from './plot2d/grid.js';
import { drawLabels } from './plot2d/labels.js';
import { createPrimitives } from './plot2d/primitives.js';

// the parts of a plot live in ./plot2d/ (palette, view, grid, primitives, labels); this module assembles them
export { PALETTE, SERIES };

const reducedMotion = () => typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;

/**
 * Applies a view saved in a demo's state as `[xmin, xmax, ymin, ymax]` (what `onView` stores). Returns false,
 * leaving the plot as it is, when `saved` is not a finite, non-empty view (e.g. `[]`: "fit to content").
 */
export function restoreView(plot, saved) {
  const v = saved;
  if (!(Array.isArray(v) && v.length === 4 && v.every(Number.isFinite) && v[1] > v[0] && v[3] > v[2])) return false;
  plot.setView({ xmin: v[0], xmax: v[1], ymin: v[2], ymax: v[3] });
  return true;
}

/**
 * Creates a plot inside `parent` (appends a `.plot` wrapper with the canvas). Options:
 *   ariaLabel     string: what the plot shows (canvas aria-label)
 *   describe()    → string: a text description for screen readers (refreshed after redraws, throttled)
 *   view          { xmin, xmax, ymin, ymax } initial world rectangle (default −1..1)
 *   equal         true → same scale on both axes (default false)
 *   height        CSS height in px (default 360; at most maxHeightRatio·width, default 0.85, for phones)
 *                 or 'aspect' with `aspect` (width/height ratio)
 *   pan, zoom     allow panning by dragging the background / zooming (wheel, pinch, +/− keys) (default true)
 *   zoomX, zoomY  restrict zoom/pan to one axis (default both true)
 *   grid, axes, ticks   draw grid lines / axis lines / tick labels (default true)
 *   xLabel, yLabel      axis names drawn at the ends of the axes
 *   padding       px around the world rectangle when fitting (default 12)
 *   locked        true → handles cannot be moved (still drawn)
 *   tools         true → overlay buttons zoom in / zoom out / fit (default = zoom)
 *   draw(g, plot) the user drawing callback (world helpers are on `plot`; g is the 2D context in CSS px)
 *   drawOver(g, plot) drawn after the handles
 *   onView(view)  called after the user pans/zooms
 *   fit()         → bounds {xmin,xmax,ymin,ymax} used by the "fit" button / 0 key (default: all handles)
 */
export function createPlot(parent, opts = {}) {
  const o = {
    ariaLabel: 'Plot', equal: false, height: 360, aspect: 1.6, pan: true, zoom: true, zoomX: true, zoomY: true,
    grid: true, axes: true, ticks: true, padding: 12, locked: false, ...opts,
  };
  if (o.tools === undefined) o.tools = o.zoom;
  const descId = `plot-desc-${Math.random().toString(36).slice(2, 9)}`;
  const canvas = h('canvas', {
    class: 'plot-canvas', tabindex: '0', role: 'application', 'aria-roledescription': 'interactive plot',
    'aria-label': o.ariaLabel, 'aria-describedby': descId,
  });
  const desc = h('div', { class: 'visually-hidden', id: descId });
  const live = h('div', { class: 'visually-hidden', 'aria-live': 'polite', 'aria-atomic': 'true' });
  const status = h('div', { class: 'plot-status', 'aria-hidden': 'true' });
  const tools = o.tools ? h('div', { class: 'plot-tools' },
    h('button', { type: 'button', class: 'plot-tool', title: 'Zoom in', 'aria-label': 'Zoom in', onclick: () => zoomBy(1 / 1.25) }, '+'),
    h('button', { type: 'button', class: 'plot-tool', title: 'Zoom out', 'aria-label': 'Zoom out', onclick: () => zoomBy(1.25) }, '−'),
    h('button', { type: 'button', class: 'plot-tool', title: 'Fit to content', 'aria-label': 'Fit to content', onclick: () => fitContent() }, '⤢'),
  ) : null;
  const wrap = h('div', { class: 'plot' }, canvas, tools, status, desc, live);
  parent.appendChild(wrap);
  const g = canvas.getContext('2d');
  // focus check that also works inside a shadow root (the <spline-lab> element)
  const isFocused = () => { const r = canvas.getRootNode(); return (r && r.activeElement !== undefined ? r.activeElement : document.activeElement) === canvas; };

  let W = 300, H = 150, dpr = 1;
  let view = { ...DEFAULT_VIEW, ...(o.view || {}) };
  let tf = { x0: 0, y0: 0, kx: 1, ky: 1, xmin: 0, xmax: 1, ymin: 0, ymax: 1 }; // screen = (x − xmin)·kx, (ymax − y)·ky
  const groups = [];
  let hover = null;          // { group, index }
  let selected = null;       // { group, index } keyboard selection
  let drag = null;           // { kind: 'handle'|'pan'|'pinch', … }
  const pointers = new Map();
  let frame = 0, destroyed = false, lastDesc = 0, descTimer = 0;
  let frameLabels = [], frameMarkers = [], lastLabels = [], lastMarkers = [];

  function setSize() {
    const rect = wrap.getBoundingClientRect();
    W = Math.max(50, Math.round(rect.width || parent.clientWidth || 300));
    H = o.height === 'aspect' ? Math.round(W / o.aspect) : Math.round(Math.min(o.height, W * (o.maxHeightRatio ?? 0.85)));
    dpr = Math.min(3, window.devicePixelRatio || 1);
    canvas.style.height = `${H}px`;
    canvas.width = Math.round(W * dpr);
    canvas.height = Math.round(H * dpr);
    layout();
  }

  function layout() { tf = layoutTransform(view, W, H, o.equal); }

  const sx = (x) => (x - tf.xmin) * tf.kx;
  const sy = (y) => (tf.ymax - y) * tf.ky;
  const toScreen = (x, y) => [sx(x), sy(y)];
  const toWorld = (px, py) => [tf.xmin + px / tf.kx, tf.ymax - py / tf.ky];

  function setView(v, { user = false } = {}) {
    view = { ...view, ...v };
    layout();
    redraw();
    if (user && o.onView) o.onView(getView());
  }
  const getView = () => ({ xmin: tf.xmin, xmax: tf.xmax, ymin: tf.ymin, ymax: tf.ymax });

  function fitBounds(b, pad = o.padding) {
    if (!b || !Number.isFinite(b.xmin + b.xmax + b.ymin + b.ymax)) return;
    let { xmin, xmax, ymin, ymax } = b;
    if (xmax - xmin < 1e-9) { xmin -= 0.5; xmax += 0.5; }
    if (ymax - ymin < 1e-9) { ymin -= 0.5; ymax += 0.5; }
    const fx = pad / Math.max(1, W - 2 * pad), fy = pad / Math.max(1, H - 2 * pad);
    const dx = (xmax - xmin) * fx, dy = (ymax - ymin) * fy;
    setView({ xmin: xmin - dx, xmax: xmax + dx, ymin: ymin - dy, ymax: ymax + dy });
  }

  function fitContent() {
    const b = o.fit ? o.fit() : boundsOf(...groups.map((gr) => gr.points()));
    if (b) { fitBounds(b, Math.max(o.padding, 28)); if (o.onView) o.onView(getView()); }
  }

  function zoomBy(f, cx = W / 2, cy = H / 2) {
    const [wx, wy] = toWorld(cx, cy);
    const fx = o.zoomX ? f : 1, fy = o.zoomY ? f : 1;
    setView({
      xmin: wx - (wx - tf.xmin) * fx, xmax: wx + (tf.xmax - wx) * fx,
      ymin: wy - (wy - tf.ymin) * fy, ymax: wy + (tf.ymax - wy) * fy,
    }, { user: true });
  }

  // ---------- drawing ----------
  function redraw() {
    if (frame || destroyed) return;
    frame = requestAnimationFrame(paint);
  }

  function paint() {
    frame = 0;
    if (destroyed) return;
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.clearRect(0, 0, W, H);
    g.fillStyle = PALETTE.background;
    g.fillRect(0, 0, W, H);
    frameLabels = []; frameMarkers = []; lastLabels = [];
    registerHandles();
    drawGrid(g, { tf, W, H, o, sx, sy });
    g.save();
    try { o.draw && o.draw(g, api); } catch (e) { console.error(e); }
    g.restore();
    drawHandles();
    if (o.drawOver) { g.save(); try { o.drawOver(g, api); } catch (e) { console.error(e); } g.restore(); }
    g.save();
    try { flushLabels(); } catch (e) { console.error(e); }
    g.restore();
    lastMarkers = frameMarkers;
    scheduleDescribe();
  }

  /** Places and draws the labels queued in this frame (see `label`). */
  function flushLabels() {
    for (const b of drawLabels(g, frameLabels, frameMarkers, W, H)) lastLabels.push(b);
    frameLabels = [];
  }

  const { strokeStyle, done, polyline, fill, fillUnder, marker, points, segment, vline, hline, arrow, comb } = createPrimitives({ g, sx, sy, size: () => [W, H], addMarker: (m) => frameMarkers.push(m) });

  /**
   * Text at a world position: `color`, `offset` [dx, dy] px, `align`, `baseline`, `font`, `halo` (default true).
   * Labels are drawn at the end of the frame, on top, and kept clear of each other and of the point markers of
   * the frame (handles, points(), marker()): when the asked-for place overlaps one, the first free place of a
   * few around the anchor is used instead (`avoid: false` keeps the asked-for place). The boxes drawn are in
   * `plot.lastLabels` ({ text, x, y, w, h }, CSS px) and the marker discs in `plot.lastMarkers` ({ x, y, r }).
   */
  function label(x, y, str, st = {}) {
    if (str == null || str === '') return;
    const X = sx(x), Y = sy(y);
    if (!Number.isFinite(X) || !Number.isFinite(Y)) return;
    frameLabels.push({ X, Y, text: String(str), st });
  }

  // ---------- handles ----------
  /**
   * Draggable handles. `spec`:
   *   name        'control point' (used in the keyboard/screen-reader text)
   *   points()    → the live array of [x, y] (read at every frame and hit test)
   *   move(i, [x, y], how)  apply a move (after `constrain`); `how` is 'drag' | 'key'
   *   constrain(i, [x, y]) → [x, y]  optional (keep knots ordered, move only in x, …)
   *   end(i)      optional, after a drag or key move ends (e.g. ctx.save())
   *   start(i)    optional, when a drag starts
   *   color, radius (px, default 7), shape, label(i) → string (drawn next to the handle), labelOf(i) (spoken)
   *   step        world step for arrow keys (default: 1/100 of the view width); Shift × 10
   *   axis        'x' | 'y' to restrict arrow keys (and drags) to one axis
   *   locked      true → not movable (overrides nothing if the plot is locked anyway)
   *   hidden      true → not drawn / not hit
   * Returns the group (with .remove()). Groups added later are drawn on top.
   */
  function addHandles(spec) {
    const gr = { radius: 7, color: PALETTE.control, name: 'point', ...spec };
    gr.remove = () => { const k = groups.indexOf(gr); if (k >= 0) groups.splice(k, 1); if (selected?.group === gr) selected = null; redraw(); };
    groups.push(gr);
    redraw();
    return gr;
  }

  const movable = (gr) => !o.locked && !gr.locked && !gr.hidden;

  function flatHandles() {
    const out = [];
    for (const gr of groups) {
      if (gr.hidden) continue;
      const ps = gr.points() || [];
      for (let i = 0; i < ps.length; i++) out.push({ group: gr, index: i });
    }
    return out;
  }

  // the handles' discs are known before the demo draws, so that every label of the frame avoids them
  function registerHandles() {
    for (const gr of groups) {
      if (gr.hidden) continue;
      const ps = gr.points() || [];
      for (let i = 0; i < ps.length; i++) {
        const [x, y] = ps[i];
        if (Number.isFinite(x) && Number.isFinite(y)) frameMarkers.push({ x: sx(x), y: sy(y), r: (gr.radius || 7) * (gr.shape && gr.shape !== 'circle' ? 1.3 : 1) + 2 });
      }
    }
  }

  function drawHandles() {
    const focused = isFocused();
    for (const gr of groups) {
      if (gr.hidden) continue;
      const ps = gr.points() || [];
      for (let i = 0; i < ps.length; i++) {
        const [x, y] = ps[i];
        if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
        const X = sx(x), Y = sy(y);
        const isHover = hover && hover.group === gr && hover.index === i;
        const isSel = selected && selected.group === gr && selected.index === i;
        const isDrag = drag && drag.kind === 'handle' && drag.group === gr && drag.index === i;
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
    for (let k = groups.length - 1; k >= 0; k--) {
      const gr = groups[k];
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
    redraw();
  }

  function nameOf(sel) {
    if (!sel) return '';
    const gr = sel.group;
    const p = (gr.points() || [])[sel.index];
    const nm = gr.labelOf ? gr.labelOf(sel.index) : `${gr.name} ${sel.index + 1}`;
    return p ? `${nm} at (${fmt(p[0], 3)}, ${fmt(p[1], 3)})` : nm;
  }

  let announceTimer = 0;
  function announce(msg, now = false) {
    clearTimeout(announceTimer);
    const go = () => { live.textContent = msg; };
    if (now) go(); else announceTimer = setTimeout(go, 250);
  }

  function localXY(e) {
    const r = canvas.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  }

  function onPointerDown(e) {
    if (e.button !== undefined && e.button > 0 && e.pointerType === 'mouse') return;
    const [px, py] = localXY(e);
    pointers.set(e.pointerId, { x: px, y: py });
    if (pointers.size === 2 && o.zoom) {
      // second finger: switch to pinch (cancel any handle drag)
      if (drag && drag.kind === 'handle' && drag.group.end) drag.group.end(drag.index);
      const [a, b] = [...pointers.values()];
      drag = { kind: 'pinch', dist: Math.hypot(a.x - b.x, a.y - b.y), mid: [(a.x + b.x) / 2, (a.y + b.y) / 2], view: getView() };
      try { canvas.setPointerCapture(e.pointerId); } catch { /* ignore */ }
      e.preventDefault();
      return;
    }
    if (pointers.size > 2) return;
    const hit = hitTest(px, py, e.pointerType);
    if (!(hit && movable(hit.group)) && e.pointerType === 'touch') {
      // one finger that does not start on a handle belongs to the page (it scrolls, touch-action: pan-y);
      // a second finger turns the gesture into a pinch (above)
      return;
    }
    if (hit && movable(hit.group)) {
      const p = hit.group.points()[hit.index];
      drag = { kind: 'handle', group: hit.group, index: hit.index, off: [p[0] - toWorld(px, py)[0], p[1] - toWorld(px, py)[1]], moved: false };
      selected = { group: hit.group, index: hit.index };
      if (hit.group.start) hit.group.start(hit.index);
      canvas.classList.add('dragging');
    } else if (o.pan) {
      drag = { kind: 'pan', start: [px, py], view: getView() };
      canvas.classList.add('panning');
    } else {
      return;
    }
    try { canvas.setPointerCapture(e.pointerId); } catch { /* ignore */ }
    if (!isFocused()) { pointerFocus = true; canvas.focus({ preventScroll: true }); pointerFocus = false; }
    e.preventDefault();
    redraw();
  }

  function onPointerMove(e) {
    const [px, py] = localXY(e);
    if (pointers.has(e.pointerId)) pointers.set(e.pointerId, { x: px, y: py });
    if (!drag) {
      const hit = hitTest(px, py, e.pointerType);
      const changed = (hit?.group !== hover?.group) || (hit?.index !== hover?.index);
      hover = hit;
      canvas.style.cursor = hit && movable(hit.group) ? 'grab' : o.pan ? 'move' : 'default';
      if (changed) redraw();
      return;
    }
    if (drag.kind === 'handle') {
      const [wx, wy] = toWorld(px, py);
      drag.moved = true;
      applyMove(drag.group, drag.index, wx + drag.off[0], wy + drag.off[1], 'drag');
      announce(nameOf(drag));
    } else if (drag.kind === 'pan') {
      const v = drag.view;
      const dx = o.zoomX ? (px - drag.start[0]) / tf.kx : 0, dy = o.zoomY ? (py - drag.start[1]) / tf.ky : 0;
      setView({ xmin: v.xmin - dx, xmax: v.xmax - dx, ymin: v.ymin + dy, ymax: v.ymax + dy });
    } else if (drag.kind === 'pinch' && pointers.size >= 2) {
      const [a, b] = [...pointers.values()];
      const dist = Math.hypot(a.x - b.x, a.y - b.y);
      if (dist < 4) return;
      const f = drag.dist / dist;
      const v = drag.view;
      const kx = W / (v.xmax - v.xmin), ky = H / (v.ymax - v.ymin);
      const wx = v.xmin + drag.mid[0] / kx, wy = v.ymax - drag.mid[1] / ky;
      const mid = [(a.x + b.x) / 2, (a.y + b.y) / 2];
      const fx = o.zoomX ? f : 1, fy = o.zoomY ? f : 1;
      const nkx = kx / fx, nky = ky / fy;
      const xmin = wx - mid[0] / nkx, ymax = wy + mid[1] / nky;
      setView({ xmin, xmax: xmin + W / nkx, ymin: ymax - H / nky, ymax });
    }
  }

  function onPointerUp(e) {
    pointers.delete(e.pointerId);
    try { canvas.releasePointerCapture(e.pointerId); } catch { /* ignore */ }
    if (!drag) return;
    const d = drag;
    if (d.kind === 'pinch') { if (pointers.size === 0) { drag = null; if (o.onView) o.onView(getView()); } return; }
    if (pointers.size > 0) return;
    drag = null;
    canvas.classList.remove('dragging', 'panning');
    if (d.kind === 'handle') { if (d.moved && d.group.end) d.group.end(d.index); announce(nameOf(d), true); }
    if (d.kind === 'pan' && o.onView) o.onView(getView());
    redraw();
  }

  function onPointerLeave() { if (hover && !drag) { hover = null; redraw(); } }

  function onWheel(e) {
    if (!o.zoom) return;
    // Zoom only when the plot has focus or with Ctrl/⌘ (trackpad pinch): plain wheel keeps scrolling the page.
    if (!(e.ctrlKey || e.metaKey || isFocused())) {
      flashStatus('Click the plot (or hold Ctrl) to zoom with the wheel');
      return;
    }
    e.preventDefault();
    const [px, py] = localXY(e);
    const dy = e.deltaMode === 1 ? e.deltaY * 16 : e.deltaMode === 2 ? e.deltaY * H : e.deltaY;
    zoomBy(Math.exp(Math.max(-2, Math.min(2, dy * 0.0015))), px, py);
  }

  let statusTimer = 0;
  function flashStatus(msg) {
    status.textContent = msg;
    status.classList.add('show');
    clearTimeout(statusTimer);
    statusTimer = setTimeout(() => status.classList.remove('show'), 1500);
  }

  function select(sel) {
    selected = sel;
    redraw();
    if (sel) announce(`${nameOf(sel)}. Arrow keys move it, Shift for larger steps.`, true);
  }

  function onKeyDown(e) {
    if (e.altKey || e.ctrlKey || e.metaKey) return;
    const list = flatHandles();
    const idx = selected ? list.findIndex((s) => s.group === selected.group && s.index === selected.index) : -1;
    const k = e.key;
    if (k === 'Tab' || k === '[' || k === ']') {
      if (!list.length) return;
      const back = k === '[' || (k === 'Tab' && e.shiftKey);
      const next = idx < 0 ? (back ? list.length - 1 : 0) : idx + (back ? -1 : 1);
      if (next < 0 || next >= list.length) {
        if (k === 'Tab') { selected = null; redraw(); return; } // let focus leave the plot: no keyboard trap
        select(list[(next + list.length) % list.length]);
      } else select(list[next]);
      e.preventDefault();
      return;
    }
    if (k.startsWith('Arrow')) {
      if (!selected) { if (list.length) select(list[0]); e.preventDefault(); return; }
      const gr = selected.group;
      if (!movable(gr)) { e.preventDefault(); return; }
      const p = gr.points()[selected.index];
      if (!p) return;
      const base = gr.step || (tf.xmax - tf.xmin) / 100;
      const stepX = base * (e.shiftKey ? 10 : 1), stepY = (gr.step || (tf.ymax - tf.ymin) / 100) * (e.shiftKey ? 10 : 1);
      let [x, y] = p;
      if (k === 'ArrowLeft') x -= stepX; else if (k === 'ArrowRight') x += stepX;
      else if (k === 'ArrowUp') y += stepY; else if (k === 'ArrowDown') y -= stepY;
      applyMove(gr, selected.index, x, y, 'key');
      if (gr.end) gr.end(selected.index);
      announce(nameOf(selected));
      e.preventDefault();
      return;
    }
    if (k === 'Escape' && selected) { selected = null; redraw(); e.preventDefault(); return; }
    if (o.zoom && (k === '+' || k === '=')) { zoomBy(1 / 1.25); e.preventDefault(); return; }
    if (o.zoom && (k === '-' || k === '_')) { zoomBy(1.25); e.preventDefault(); return; }
    if (o.zoom && k === '0') { fitContent(); e.preventDefault(); }
  }

  function onFocus() {
    if (!selected) {
      const list = flatHandles();
      if (list.length) select(list[0]); else announce(o.ariaLabel, true);
    }
    redraw();
  }
  function onBlur() { redraw(); }

  // Shift+Tab into the canvas should select the last handle: track the direction of the last Tab press.
  let lastTabBack = false;
  const trackTab = (e) => { if (e.key === 'Tab') lastTabBack = e.shiftKey; };
  let pointerFocus = false;
  function onFocusIn() {
    if (pointerFocus) { redraw(); return; } // focused by a click/tap: no automatic selection
    if (!selected) {
      const list = flatHandles();
      if (list.length) { select(lastTabBack ? list[list.length - 1] : list[0]); return; }
    }
    onFocus();
  }

  function scheduleDescribe() {
    if (!o.describe) return;
    const now = performance.now();
    clearTimeout(descTimer);
    const run = () => { lastDesc = performance.now(); try { desc.textContent = o.describe(); } catch { /* ignore */ } };
    if (now - lastDesc > 600) run(); else descTimer = setTimeout(run, 600);
  }

  // Touch: the canvas lets the page scroll vertically (touch-action: pan-y) unless the gesture starts on a handle
  // or uses two fingers; then the plot takes it (preventDefault on the touch events stops the page's scrolling).
  // Pointer events come first, so `drag` already says what the touch does.
  canvas.style.touchAction = 'pan-y';
  function onTouch(e) {
    if (!e.cancelable) return;
    if ((drag && (drag.kind === 'handle' || drag.kind === 'pinch')) || (o.zoom && e.touches.length >= 2)) e.preventDefault();
  }
  canvas.addEventListener('touchstart', onTouch, { passive: false });
  canvas.addEventListener('touchmove', onTouch, { passive: false });
  canvas.addEventListener('pointerdown', onPointerDown);
  canvas.addEventListener('pointermove', onPointerMove);
  canvas.addEventListener('pointerup', onPointerUp);
  canvas.addEventListener('pointercancel', onPointerUp);
  canvas.addEventListener('pointerleave', onPointerLeave);
  canvas.addEventListener('wheel', onWheel, { passive: false });
  canvas.addEventListener('keydown', onKeyDown);
  canvas.addEventListener('focus', onFocusIn);
  canvas.addEventListener('blur', onBlur);
  document.addEventListener('keydown', trackTab, true);
  const ro = new ResizeObserver(() => { setSize(); paint(); });
  ro.observe(wrap);
  const mq = typeof matchMedia === 'function' ? matchMedia(`(resolution: ${window.devicePixelRatio || 1}dppx)`) : null;
  const onDpr = () => { setSize(); redraw(); };
  mq?.addEventListener?.('change', onDpr);
  setSize();

  function destroy() {
    destroyed = true;
    cancelAnimationFrame(frame);
    clearTimeout(descTimer); clearTimeout(announceTimer); clearTimeout(statusTimer);
    ro.disconnect();
    mq?.removeEventListener?.('change', onDpr);
    document.removeEventListener('keydown', trackTab, true);
    wrap.remove();
  }

  const api = {
    canvas, element: wrap, get g() { return g; },
    get width() { return W; }, get height() { return H; },
    toScreen, toWorld, sx, sy,
    setView, getView, fitBounds, boundsOf, fitContent, zoomBy,
    redraw, paintNow: paint, destroy,
    polyline, fill, fillUnder, points, label, segment, vline, hline, arrow, comb, marker: (x, y, r, shape, color) => { marker(sx(x), sy(y), r, shape); frameMarkers.push({ x: sx(x), y: sy(y), r: r + 1 }); g.fillStyle = color || PALETTE.ink; g.fill(); },
    addHandles, select: (group, index) => select(group ? { group, index } : null),
    get selected() { return selected; },
    /** Label boxes ({ text, x, y, w, h }) and marker discs ({ x, y, r }) of the last frame, CSS px (tests). */
    get lastLabels() { return lastLabels.slice(); },
    get lastMarkers() { return lastMarkers.slice(); },
    handles: () => flatHandles().map(({ group, index }) => ({ name: group.name, index, point: group.points()[index] })),
    setOptions(p) { Object.assign(o, p); layout(); redraw(); },
    /** Re-reads the size (after setOptions({ height }) or a container change the observer cannot see). */
    resize() { setSize(); paint(); },
    get options() { return o; },
    announce: (msg) => announce(msg, true),
    reducedMotion,
  };
  canvas.splinePlot = api; // for tests and devtools: document.querySelector('canvas').splinePlot
  return api;
}
