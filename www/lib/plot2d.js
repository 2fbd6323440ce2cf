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
// fitContent(), zoomBy(f). Keyboard: one Tab stop; Tab into the canvas selects the first handle (the last with
// Shift+Tab, or the one chosen before), PageDown/PageUp, ] [ or N/Shift+N choose the next/previous, Home/End the
// first/last, the next Tab leaves (to the point's fields first), arrows move it (Shift ×10), Esc deselects,
// Enter goes to the selected point's x / y fields, + − 0 zoom/fit. Without dragging (WCAG 2.2 SC 2.5.7): a
// click or tap on a handle picks it, the next click or tap on the plot moves it there (./plot2d/input.js); the
// selected point's x / y fields under the canvas (./plot2d/point-fields.js) move it by number; Tab from a
// clicked point reaches them. Both go through the group's constrain → move → end like a drag.
// Tests reach the API as canvas.splinePlot.

import { fmt, h, pair } from './dom.js';
import { PALETTE, SERIES } from './plot2d/palette.js';
import { DEFAULT_VIEW, layoutTransform, boundsOf } from './plot2d/view.js';
import { createGridLayer } from './plot2d/grid.js';
import { drawLabels } from './plot2d/labels.js';
import { createPrimitives } from './plot2d/primitives.js';
import { createHandles } from './plot2d/handles.js';
import { attachInput } from './plot2d/input.js';
import { createPointFields } from './plot2d/point-fields.js';
import { createTableView } from './plot2d/table.js';
import { createViewTools, rove } from './plot2d/tools.js';
import { attachAudioTrace, SOUND_HELP } from './audio-trace.js';
import { t } from './i18n.js';

/** The gestures of a plot with movable points, read by screen readers with the plot (aria-describedby). */
export const HANDLE_HELP = 'To move a point: drag it; or click or tap it, then click or tap where it should go '
  + '(Escape, or a click on the point again, cancels); or type its x and y in the fields under the plot '
  + '(Tab or Enter from a selected point reaches them). Keyboard: the plot is one Tab stop; Page Down and Page Up '
  + '(or ] and [, or N and Shift+N) choose the next or previous point, Home and End the first and last, the arrow '
  + 'keys move it (Shift for larger steps), Escape deselects.';

// the parts of a plot live in ./plot2d/ (palette, view, grid, primitives, labels, handles, input); this module
// assembles them
export { PALETTE, SERIES };
export { curveSection, basisSection, evenParams, paramRange } from './plot2d/table.js';

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
 *   tools         true → a row of buttons under the drawing: pan ← → ↑ ↓, zoom in / out, fit (default = pan || zoom)
 *   draw(g, plot) the user drawing callback (world helpers are on `plot`; g is the 2D context in CSS px)
 *   drawOver(g, plot) drawn after the handles
 *   onView(view)  called after the user pans/zooms
 *   fit()         → bounds {xmin,xmax,ymin,ymax} used by the "fit" button / 0 key (default: all handles)
 *   table()       → TableSection[] (./plot2d/table.js): sampled values listed in the figure's table, after its points
 *   sound()       → a trace (./audio-trace.js): a ♪ "Play as sound" button in the tool row, keys S , .
 */
export function createPlot(parent, opts = {}) {
  /** @type {Record<string, any>} the options with their defaults */
  const o = {
    ariaLabel: 'Plot', equal: false, height: 360, aspect: 1.6, pan: true, zoom: true, zoomX: true, zoomY: true,
    grid: true, axes: true, ticks: true, padding: 12, locked: false, ...opts,
  };
  if (o.tools === undefined) o.tools = o.pan || o.zoom;
  o.ariaLabel = t(o.ariaLabel);   // what the plot shows, in the page's language
  const descId = `plot-desc-${Math.random().toString(36).slice(2, 9)}`;
  const canvas = h('canvas', {
    class: 'plot-canvas', tabindex: '0', role: 'application', 'aria-roledescription': t('interactive plot'),
    'aria-label': o.ariaLabel, 'aria-describedby': `${descId} ${descId}-help`,
  });
  const desc = h('div', { class: 'visually-hidden', id: descId });
  // the help is written once the plot has a movable handle (see paint)
  const help = h('div', { class: 'visually-hidden', id: `${descId}-help` });
  const live = h('div', { class: 'visually-hidden', 'aria-live': 'polite', 'aria-atomic': 'true' });
  const status = h('div', { class: 'plot-status', 'aria-hidden': 'true' });
  // pan / zoom / fit by single clicks, in a row under the drawing (./plot2d/tools.js)
  const tools = o.tools ? createViewTools({ o, getView: () => getView(), setView: (v, how) => setView(v, how), zoomBy: (f) => zoomBy(f), fitContent: () => fitContent(), say: (msg) => announce(msg) }) : null;
  const toolRow = tools || (o.sound ? h('div', { class: 'plot-tools' }) : null); // the ♪ button needs a row
  const wrap = h('div', { class: 'plot' }, canvas, toolRow, status, desc, help, live);
  parent.appendChild(wrap);
  const g = canvas.getContext('2d');
  // focus check that also works inside a shadow root (the <spline-lab> element)
  const isFocused = () => { const r = canvas.getRootNode(); return (r && r.activeElement !== undefined ? r.activeElement : document.activeElement) === canvas; };

  let W = 300, H = 150, dpr = 1;
  let view = { ...DEFAULT_VIEW, ...(o.view || {}) };
  let tf = { kx: 1, ky: 1, xmin: 0, xmax: 1, ymin: 0, ymax: 1 }; // screen = (x − xmin)·kx, (ymax − y)·ky
  // interaction state shared by the handles (./plot2d/handles.js) and the input (./plot2d/input.js)
  const st = {
    groups: [],
    hover: null,      // { group, index }
    selected: null,   // { group, index } the selected handle (keyboard, click, tap or the last drag)
    picked: false,    // the selection was made by a click/tap: the next click/tap on the plot moves it there
    by: null,         // 'key' | 'pointer': how the selection was made (a keyboard one is let go when focus leaves the plot)
    drag: null,       // { kind: 'handle'|'pan'|'pinch', … }
    pointers: new Map(),
  };
  let frame = 0, destroyed = false, lastDesc = 0, descTimer = 0, sized = false, painted = false;
  let frameLabels = [], frameMarkers = [], lastLabels = [], lastMarkers = [];
  const drawGrid = createGridLayer(); // the grid, axes and ticks, cached while the view stays the same

  /** Sizes the canvas to its box (CSS px and device pixels). Returns false when nothing changed (then the bitmap,
   * and what is painted on it, is kept: resetting canvas.width would clear it). */
  function setSize() {
    const rect = wrap.getBoundingClientRect();
    const w = Math.max(50, Math.round(rect.width || parent.clientWidth || 300));
    const h = o.height === 'aspect' ? Math.round(w / o.aspect) : Math.round(Math.min(o.height, w * (o.maxHeightRatio ?? 0.85)));
    const r = Math.min(3, window.devicePixelRatio || 1);
    if (sized && w === W && h === H && r === dpr && canvas.width === Math.round(W * dpr) && canvas.height === Math.round(H * dpr)) return false;
    sized = true;
    W = w; H = h;
    canvas.style.height = `${H}px`;
    wrap.style.setProperty('--plot-h', `${H}px`); // the status line stays on the canvas above the point fields
    setPixelRatio(r);
    layout();
    return true;
  }

  /** Device pixels per CSS px: the canvas' bitmap size follows, and every layer paints with this ratio. */
  function setPixelRatio(r) {
    dpr = r;
    canvas.width = Math.round(W * dpr);
    canvas.height = Math.round(H * dpr);
  }

  /**
   * The plot painted at `scale` device pixels per CSS px (an export at 1×, 2×, 4×): the same paint as on screen,
   * only with that pixel ratio, copied into a new canvas of round(W·scale) × round(H·scale) px. The screen canvas
   * is back at its own resolution and repainted before this returns (no frame shows the export size).
   */
  function renderAt(scale) {
    const keep = dpr;
    const out = document.createElement('canvas');
    try {
      setPixelRatio(scale);
      out.width = canvas.width; out.height = canvas.height;
      paint();
      out.getContext('2d').drawImage(canvas, 0, 0);
    } finally {
      setPixelRatio(keep);
      paint();
    }
    return out;
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
    const b = o.fit ? o.fit() : boundsOf(...st.groups.map((gr) => gr.points()));
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

  /** Where the ♪ button of a tool row without zoom tools sits (a disc labels keep clear of), CSS px; per size. */
  let soundDisc = null;

  function paint() {
    frame = 0;
    if (destroyed) return;
    painted = true;
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.clearRect(0, 0, W, H);
    g.fillStyle = PALETTE.background;
    g.fillRect(0, 0, W, H);
    frameLabels = []; frameMarkers = []; lastLabels = [];
    registerHandles();
    drawGrid(g, { tf, W, H, o, sx, sy, ratio: dpr }, canvas);
    g.save();
    try { o.draw && o.draw(g, api); } catch (e) { console.error(e); }
    g.restore();
    drawHandles();
    if (o.drawOver) { g.save(); try { o.drawOver(g, api); } catch (e) { console.error(e); } g.restore(); }
    // a tool row of only the ♪ button sits over the drawing: the labels keep clear of it as of a point
    // (its place is measured once per size — in the ResizeObserver's paint, after layout — not in every frame of a
    // drag, where reading offsets after a readout changed would force a layout)
    if (sound && !tools) {
      const b = sound.button;
      soundDisc ??= { x: toolRow.offsetLeft + b.offsetLeft + b.offsetWidth / 2, y: toolRow.offsetTop + b.offsetTop + b.offsetHeight / 2, r: b.offsetWidth / 2 + 3 };
      frameMarkers.push(soundDisc);
    }
    g.save();
    try { flushLabels(); } catch (e) { console.error(e); }
    g.restore();
    lastMarkers = frameMarkers;
    fields.sync();
    let helpText = !o.locked && st.groups.some((gr) => !gr.locked && !gr.hidden) ? t(HANDLE_HELP) : '';
    if (o.sound) helpText = helpText ? `${helpText} ${t(SOUND_HELP)}` : t(SOUND_HELP);
    if (help.textContent !== helpText) help.textContent = helpText;
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
  function label(x, y, str, style = {}) {
    if (str == null || str === '') return;
    const X = sx(x), Y = sy(y);
    if (!Number.isFinite(X) || !Number.isFinite(Y)) return;
    frameLabels.push({ X, Y, text: String(str), st: style });
  }

  const handles = createHandles({ st, o, g, sx, sy, marker, label, addMarker: (m) => frameMarkers.push(m), isFocused, redraw });
  const { addHandles, flatHandles, registerHandles, drawHandles } = handles;

  /** "Control point P₃ moved to (1.2, 0.5). ": the point the last move changed, said first (empty before a move). */
  function movedWords() {
    const m = st.moved, p = m && (m.group.points() || [])[m.index];
    if (!p || !flatHandles().some((s) => s.group === m.group && s.index === m.index)) return '';
    const shown = m.group.axis === 'x' ? fmt(p[0], 3) : m.group.axis === 'y' ? fmt(p[1], 3) : pair(p[0], p[1]);
    return `${t('{name} moved to {where}.', { name: handles.nameOnly(m), where: shown })} `;
  }

  // "Table of the figure" under the plot (./plot2d/table.js): the movable points by name, and what the demo samples
  const table = createTableView({
    label: o.ariaLabel,
    points: () => flatHandles().filter((s) => handles.movable(s.group)).map((s) => {
      const p = s.group.points()[s.index];
      return { name: handles.nameOnly(s), x: p[0], y: s.group.axis === 'x' ? '' : p[1] };
    }),
    samples: () => o.table?.() ?? null,
  });

  wrap.append(table.el);

  function scheduleDescribe() {
    // the table shows where there is something to list: movable points, or values the demo samples
    // (per group, not per handle: this runs after every frame of a drag)
    table.el.hidden = !(o.table || st.groups.some((gr) => handles.movable(gr) && gr.points()?.length));
    table.refresh();
    if (!o.describe) return;
    const now = performance.now();
    clearTimeout(descTimer);
    const run = () => { lastDesc = performance.now(); try { const s = movedWords() + o.describe(); if (desc.textContent !== s) desc.textContent = s; } catch { /* ignore */ } };
    // right after the frame (not in it: the text is for screen readers, the frame is for the drawing)
    descTimer = setTimeout(run, now - lastDesc > 600 ? 0 : 600);
  }

  const { select, announce, dispose: disposeInput, escapeFromFields } = attachInput({
    st, o, canvas, live, status, handles, transform: () => tf, size: () => [W, H], toWorld, getView, setView, zoomBy, fitContent, redraw, isFocused,
    focusFields: () => fields.focus(), fieldsEl: () => fields.el,
  });
  // "Play as sound" (./audio-trace.js): built only for plots that give a trace; no AudioContext until asked
  const sound = o.sound ? attachAudioTrace({ canvas, row: toolRow, trace: () => o.sound(), announce: (msg) => announce(msg, true) }) : null;
  if (sound && tools) rove(tools); // the ♪ joins the row's one Tab stop
  const fields = createPointFields({ st, handles, announce: (msg) => announce(msg, true), onEscape: () => escapeFromFields() });
  // right after the canvas: Tab from a selected point reaches its fields before the zoom tools
  canvas.after(fields.el);
  // (the first report comes after the first layout: when the size is the one measured at creation and the frame's
  // paint is done, there is nothing to redo, so the first frame paints each plot once, not twice)
  const ro = new ResizeObserver(() => { soundDisc = null; if (setSize() || !painted) paint(); });
  ro.observe(wrap);
  const mq = typeof matchMedia === 'function' ? matchMedia(`(resolution: ${window.devicePixelRatio || 1}dppx)`) : null;
  const onDpr = () => { setSize(); redraw(); };
  mq?.addEventListener?.('change', onDpr);
  setSize();

  function destroy() {
    table.dispose();
    destroyed = true;
    cancelAnimationFrame(frame);
    clearTimeout(descTimer);
    disposeInput();
    sound?.dispose();
    ro.disconnect();
    mq?.removeEventListener?.('change', onDpr);
    wrap.remove();
  }

  const api = {
    canvas, element: wrap, get g() { return g; },
    get width() { return W; }, get height() { return H; },
    /** Device pixels per CSS px the plot paints with (its canvas is round(W·ratio) × round(H·ratio)). */
    get pixelRatio() { return dpr; },
    renderAt,
    toScreen, toWorld, sx, sy,
    setView, getView, fitBounds, boundsOf, fitContent, zoomBy,
    redraw, paintNow: paint, destroy,
    polyline, fill, fillUnder, points, label, segment, vline, hline, arrow, comb, marker: (x, y, r, shape, color) => { marker(sx(x), sy(y), r, shape); frameMarkers.push({ x: sx(x), y: sy(y), r: r + 1 }); g.fillStyle = color || PALETTE.ink; g.fill(); },
    addHandles, select: (group, index) => select(group ? { group, index } : null),
    get selected() { return st.selected; },
    /** The x / y fields row of the selected point (tests). */
    get fieldsRow() { return fields.el; },
    /** Label boxes ({ text, x, y, w, h }) and marker discs ({ x, y, r }) of the last frame, CSS px (tests). */
    get lastLabels() { return lastLabels.slice(); },
    get lastMarkers() { return lastMarkers.slice(); },
    /** [{ name, index, point, axis, movable }]: `axis` 'x' | 'y' for a handle that moves along one axis only. */
    handles: () => flatHandles().map(({ group, index }) => ({ name: group.name, index, point: group.points()[index], axis: group.axis || null, movable: handles.movable(group) })),
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
