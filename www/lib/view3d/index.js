// A small hand-written WebGL2 surface viewer for SplineLab's 3D demos (no three.js, no build step).
//
//   const view = new View3D(parentElement, { height: 420, ariaLabel: 'Gordon surface' });
//   view.setMesh('S', wasmResult.mesh, { color: '#3f7fd6', isolines: true, wireframe: false,
//                                        colors: 'height' | Float32Array, colormap: 'viridis', legend: 'z' });
//   view.setLines('net', [flatXYZ, flatXYZ, …], { color: '#111', width: 3 });
//   view.setPoints('ctrl', flatXYZ, { color: '#d62728', size: 12, labels: ['P0', …], draggable: true,
//                                     names: (i) => `P${sub(i)}`,      // the paper's names, for words
//                                     onDrag: (index, [x, y, z], phase) => { … } });   // phase: start|move|end
//   view.onPick(({ id, index, position }) => …);  view.onDrag(({ id, index, position, phase }) => …);
//   view.fit(); view.remove('S'); view.destroy();
//
// Touch (course pages must keep scrolling): until the view is activated by a tap ("Tap to rotate" shows), one
// finger scrolls the page (touch-action: pan-y); after the tap one finger orbits, and a tap outside the view
// deactivates it. Two fingers zoom and pan always; a draggable point is dragged by the finger that starts on it.
// Axes: the three front/bottom edges of the scene's bounding box with tick values (option `axes`, default true;
// `showAxes(false)`), drawn on a 2D overlay; `view.axesInfo` holds what was drawn (for tests).
// Narrow screens (< 640 px): the height follows the width and, after fit(), the content's aspect.
// Camera: orbit around a target, z up. Mouse: drag = orbit, wheel (once the view has focus, or with
// Ctrl) / pinch = zoom, right-drag / shift-drag / two fingers = pan, drag a draggable point = move it in the plane parallel to the screen (hold
// Shift, or give the set `axis: 'x'|'y'|'z'`, to move it along that axis; Shift alone means z). Keyboard (the
// canvas is focusable, one Tab stop: Tab enters the view and the next Tab leaves it): arrows orbit, Shift+arrows
// pan, +/- zoom, F or Home frames everything (a change of view is said in words in the live region once the keys
// pause), N / Shift+N (or ] / [) select the draggable points one by one (said with their `names`), then arrows move the
// selected point (Shift: 5× step, PageUp/PageDown: along z), Escape deselects; the selected point's x, y, z fields
// under the canvas (./fields.js) move it without dragging. Rendering is coalesced with requestAnimationFrame.
// Without WebGL2 the element shows a clear message and every method still works (as a no-op).
//
// Shading: Blinn-Phong with a light mounted on the camera, two-sided (back faces slightly darker), optional
// wireframe and isoparametric lines (for a u-major nu × nv grid mesh such as the wasm `mesh` results), and a
// colour-map mode for any per-vertex scalar (height, the distance between two surfaces, Gaussian curvature…)
// with a legend.
//
// The viewer is split by concept in this folder: constants, shaders, math, geometry, camera, gl (WebGL2),
// overlay (axes, labels, legend), input; ./index.js holds the scene API and puts the parts together.

import { legendElement, scalarRange } from '../colormap.js';
import { DEFAULT_VIEW, PALETTE, POINT_COLOR } from './constants.js';
import { bboxOf, computeNormals, isolineSegments, parseColor, segmentsOf, toXYZ, wireframeSegments } from './geometry.js';
import { HELP } from './input.js';
import { add, scale } from './math.js';
import { CameraPart } from './camera.js';
import { GlPart } from './gl.js';
import { OverlayPart } from './overlay.js';
import { InputPart } from './input.js';
import { FieldsPart } from './fields.js';
import { fmt } from '../dom.js';
import { createTableView } from '../plot2d/table.js';
import { viewTools } from './tools.js';

/** A coordinate in the description: 3 decimals like the readouts ("0.364", not "0.363658"). */
const fmtWords = (v) => fmt(Number(v), 3);

export { parseColor, computeNormals };

let uid = 0;

// ---------------------------------------------------------------- the viewer

class View3D {
  /**
   * @param {HTMLElement} parent  the element to draw into (the viewer appends its own container)
   * @param {object} [options]  { height = 420 (CSS px), ariaLabel, background = '#ffffff', onViewChange(view),
   *                              locked = false (points cannot be dragged), disableWebGL (tests the fallback) }
   */
  constructor(parent, options = {}) {
    this.options = options;
    this.height = Number.isFinite(options.height) && options.height > 40 ? options.height : 420;
    this.background = parseColor(options.background, [1, 1, 1]);
    this.locked = !!options.locked;
    this.objects = new Map();
    this.pickListeners = [];
    this.dragListeners = [];
    this.viewListeners = typeof options.onViewChange === 'function' ? [options.onViewChange] : [];
    this.yaw = DEFAULT_VIEW.yaw; this.pitch = DEFAULT_VIEW.pitch;
    this.target = [0, 0, 0]; this.distance = 4; this.sceneRadius = 1; this.sceneCenter = [0, 0, 0];
    this._needsFit = true;
    this._raf = 0;
    this.pointers = new Map();
    this.mode = null;       // 'orbit' | 'pan' | 'drag' | 'pinch'
    this.hover = null;      // { id, index }
    this.selected = null;   // { id, index } — the selected point (keyboard, fields, or a click)
    this._picked = false;   // the selection was picked by a click or tap: the next click elsewhere moves it there
    this.destroyed = false;
    this.id = ++uid;
    this.touchActive = false;  // one-finger touch orbits only after a tap has activated the view
    this.axes = options.axes !== false;
    this.axesInfo = null;
    this._contentAspect = 0;
    // set by the parts (declared here for the type checker)
    this._drawnSize = null;  // [w, h, dpr] of the last drawing
    this._links = null;      // the Set of linked views (linkViews)
    this._syncing = false;
    this._hintTimer = 0;
    this._wheelTimer = 0;
    this._viewWordsTimer = 0;
    this._fitDistance = 0;   // the camera distance of the last fit() (zoom 1× in words)
    this._listeners = [];
    this.fieldsPanel = null; // the selected point's x, y, z fields (./fields.js)
    this._fieldsName = null;
    this._fields = null;
    /** this view with its parts' methods (installed on the prototype below) */
    const view = /** @type {Viewer} */ (/** @type {unknown} */ (this));

    const wrap = this.element = document.createElement('div');
    wrap.className = 'sl-view3d';
    wrap.style.cssText = 'position:relative;width:100%;';
    const canvas = this.canvas = document.createElement('canvas');
    canvas.className = 'sl-view3d-canvas';
    canvas.view3d = this; // for the shell's exporters and tests (like canvas.splinePlot)
    canvas.tabIndex = 0;
    canvas.setAttribute('role', 'application');
    canvas.setAttribute('aria-roledescription', '3D view');
    canvas.setAttribute('aria-label', options.ariaLabel || '3D view');
    canvas.style.cssText = `display:block;width:100%;height:${this.height}px;touch-action:pan-y;outline:none;`
      + `background:rgb(${this.background.map((v) => Math.round(v * 255)).join(',')});border-radius:4px;`;
    const help = document.createElement('p');
    help.id = `sl-view3d-help-${this.id}`;
    help.textContent = HELP;
    help.style.cssText = 'position:absolute;width:1px;height:1px;overflow:hidden;clip:rect(0 0 0 0);white-space:nowrap;margin:0;';
    // what the figure shows, in words (the demo's `describe()`, after the last moved point), read before the help
    const desc = this.desc = document.createElement('p');
    desc.id = `sl-view3d-desc-${this.id}`;
    desc.style.cssText = help.style.cssText;
    canvas.setAttribute('aria-describedby', `${desc.id} ${help.id}`);
    const live = this.live = document.createElement('p');
    live.setAttribute('aria-live', 'polite');
    live.style.cssText = help.style.cssText;
    const labels = this.labelLayer = document.createElement('div');
    labels.style.cssText = 'position:absolute;left:0;top:0;right:0;bottom:0;pointer-events:none;overflow:hidden;'
      + 'font:600 13px/1 system-ui,sans-serif;color:#111;';
    labels.setAttribute('aria-hidden', 'true');
    const overlay = this.overlay = document.createElement('canvas');
    overlay.className = 'sl-view3d-axes';
    overlay.setAttribute('aria-hidden', 'true');
    overlay.style.cssText = 'position:absolute;left:0;top:0;pointer-events:none;';
    const tapHint = this.tapHint = document.createElement('div');
    tapHint.className = 'sl-view3d-tap';
    tapHint.setAttribute('aria-hidden', 'true');
    tapHint.textContent = 'Tap to rotate';
    tapHint.style.cssText = 'position:absolute;left:8px;top:8px;padding:3px 9px;border-radius:12px;pointer-events:none;'
      + 'background:rgba(17,17,17,0.78);color:#fff;font:600 13px/1.3 system-ui,sans-serif;';
    tapHint.hidden = !View3D.touchDevice();
    this.tools = viewTools(view);
    this.legend = legendElement({});
    this.legend.style.position = 'absolute';
    this.legend.style.right = '8px';
    this.legend.style.top = '52px';   // under the tools
    this.legend.style.pointerEvents = 'none';
    this.legend.hidden = true;
    // "Table of the figure" (../plot2d/table.js): its named points with x, y, z, and what the demo samples
    this.table = createTableView({
      label: options.ariaLabel || '3D view',
      points: () => view._tablePoints(),
      samples: () => (typeof options.table === 'function' ? options.table() : null),
    });
    this.table.el.hidden = true;
    this._describeTimer = 0;
    this._moved = null;     // { id, index } of the point the last move changed (said first in the description)
    wrap.append(canvas, overlay, labels, this.tools, this.legend, tapHint, desc, help, live, view._buildFields());
    // the table after the view, not in it: the view stays one Tab stop (with its point's fields), the table the next
    parent.append(wrap, this.table.el);

    this.gl = null;
    if (!options.disableWebGL) {
      try {
        this.gl = canvas.getContext('webgl2', { antialias: true, premultipliedAlpha: true, preserveDrawingBuffer: true, alpha: false });
      } catch { this.gl = null; }
    }
    if (this.gl) {
      try { view._initGL(); } catch (e) { this.gl = null; this._glError = e; }
    }
    if (!this.gl) view._showFallback();

    view._bind();
    this._resizeObserver = typeof ResizeObserver === 'function' ? new ResizeObserver((entries) => {
      for (const e of entries) if (e.target === canvas) this._cssSize = [e.contentRect.width, e.contentRect.height];
      view._sizeCanvas();
      // (the first report comes after the first layout: a view already drawn at this size is not drawn again)
      const [w, h] = view._canvasSize(), d = this._drawnSize;
      if (!d || d[0] !== w || d[1] !== h || d[2] !== Math.min(window.devicePixelRatio || 1, 2)) view.render();
    }) : null;
    view._sizeCanvas();
    this._resizeObserver?.observe(wrap);
    this._resizeObserver?.observe(canvas);
    view.render();
  }

  /**
   * The points the table lists: every visible point set that can be dragged or has the paper's names (a locked
   * view's control net too), in the keyboard's order; by name with x, y, z.
   * @this {Viewer}
   */
  _tablePoints() {
    const rows = [];
    for (const [id, o] of [...this.objects].sort((a, b) => a[1].order - b[1].order)) {
      if (o.kind !== 'points' || !o.visible || !(o.draggable || o.names)) continue;
      const p = o.positions;
      for (let i = 0; i < p.length / 3; i++) rows.push({ name: this.pointName(id, i), x: p[3 * i], y: p[3 * i + 1], z: p[3 * i + 2] });
    }
    return rows;
  }

  /**
   * After a change of the scene or a move: the table (when open) and the description follow, 300–600 ms later
   * (not in the frame; a drag does not rewrite them 60 times a second).
   * @this {Viewer}
   */
  _wordsChanged() {
    if (this.destroyed) return;
    // (a look at the point sets, not the rows: this runs on every scene change, each frame of a drag)
    const listed = [...this.objects.values()].some((o) => o.kind === 'points' && o.visible && (o.draggable || o.names) && o.positions.length);
    this.table.el.hidden = !(listed || typeof this.options.table === 'function');
    this.table.refresh();
    clearTimeout(this._describeTimer);
    this._describeTimer = setTimeout(() => {
      let text = '';
      const m = this._moved, o = m && this.objects.get(m.id);
      if (o && m.index < o.positions.length / 3) text = `${this._describe(m, fmtWords)}: moved there last. `;
      try { text += typeof this.options.describe === 'function' ? String(this.options.describe() ?? '') : this._meshWords(); } catch { /* keep the rest */ }
      if (this.desc.textContent !== text) this.desc.textContent = text;
    }, 400);
  }

  /**
   * The surfaces in words, from their vertices (a demo without its own `describe`): "The surface spans x from 0
   * to 4 and y from 0 to 4; its lowest point is (0, 0, 0.364), its highest (2, 2, 2.22)." (3 decimals, like the
   * readouts: the fields and the announcements of a move keep 6 digits)
   * @this {Viewer}
   */
  _meshWords() {
    const meshes = [...this.objects.values()].filter((o) => o.kind === 'mesh' && o.visible);
    return meshes.map((o, k) => {
      const p = o.positions, b = o.bbox;
      let lo = 0, hi = 0;
      for (let i = 0; i < p.length / 3; i++) { if (p[3 * i + 2] < p[3 * lo + 2]) lo = i; if (p[3 * i + 2] > p[3 * hi + 2]) hi = i; }
      const at = (i) => `(${fmtWords(p[3 * i])}, ${fmtWords(p[3 * i + 1])}, ${fmtWords(p[3 * i + 2])})`;
      const name = meshes.length > 1 ? `Surface ${k + 1}` : 'The surface';
      return `${name} spans x from ${fmtWords(b.lo[0])} to ${fmtWords(b.hi[0])} and y from ${fmtWords(b.lo[1])} to ${fmtWords(b.hi[1])}; `
        + `its lowest point is ${at(lo)}, its highest ${at(hi)}.`;
    }).join(' ');
  }

  /** Is this a touch-first device (coarse pointer, no hover)? Decides whether "Tap to rotate" shows up front. */
  static touchDevice() {
    try { return typeof matchMedia === 'function' && matchMedia('(hover: none) and (pointer: coarse)').matches; } catch { return false; }
  }

  /**
   * The canvas height: the `height` option on wide screens; on narrow ones (< 640 px) it follows the width (the
   * content's aspect after fit(), between 0.55 and 1.1 times the width, never above `height`).
   * @this {Viewer}
   */
  _sizeCanvas() {
    if (this.destroyed) return;
    const w = this.element.clientWidth;
    let h = this.height;
    if (w > 0 && w < 640) {
      const k = this._contentAspect > 0 ? 1.3 / this._contentAspect : 0.85;
      h = Math.round(Math.min(this.height, w * Math.min(1.1, Math.max(0.72, k))));
    }
    if (this.canvas.style.height !== `${h}px`) { this.canvas.style.height = `${h}px`; this._cssSize = null; }
  }

  /**
   * The canvas's CSS size [width, height] in px: as the ResizeObserver last reported it, so that a frame does not
   * force a layout to read it (0 × 0 until the first report, then read from the element).
   * @this {Viewer}
   */
  _canvasSize() {
    const s = this._cssSize;
    if (s && s[0] > 0 && s[1] > 0) return s;
    return [this.canvas.clientWidth, this.canvas.clientHeight];
  }

  /** Touch: activates one-finger orbiting (after a tap) or gives one-finger swipes back to the page. @this {Viewer} */
  setTouchActive(on) {
    on = !!on;
    if (this.destroyed || on === this.touchActive) return;
    this.touchActive = on;
    this.canvas.style.touchAction = on ? 'none' : 'pan-y';
    this.tapHint.hidden = on;
    this.element.classList.toggle('touch-active', on);
    if (on) this._hint('One finger rotates; tap outside the view to scroll');
  }

  /** Shows or hides the axes with tick values (the bounding box's front and bottom edges). @this {Viewer} */
  showAxes(on = true) { this.axes = !!on; this.render(); }

  /** true when WebGL2 works here. @this {Viewer} */
  get supported() { return !!this.gl; }

  /** @this {Viewer} */
  _showFallback() {
    const msg = this.fallback = document.createElement('div');
    msg.setAttribute('role', 'alert');
    msg.className = 'sl-view3d-fallback';
    msg.style.cssText = 'position:absolute;left:0;top:0;right:0;bottom:0;display:flex;align-items:center;justify-content:center;'
      + 'padding:1em;text-align:center;font:15px/1.4 system-ui,sans-serif;color:#222;background:#f3f3f3;border:1px dashed #888;border-radius:4px;';
    msg.textContent = 'This 3D view needs WebGL2, which this browser does not provide (or it is turned off). '
      + 'Try a current Firefox, Chrome, Edge or Safari, or enable hardware acceleration / WebGL in the browser settings.';
    this.element.appendChild(msg);
  }

  // ---------------------------------------------------------------- GL setup

  /** @this {Viewer} */
  _put(id, obj) {
    if (this.destroyed) return;
    const old = this.objects.get(id);
    // same kind: the new object takes over the old one's GPU buffers (rewritten at the next upload)
    if (old && old.kind === obj.kind && this.gl) { obj._reuse = old.gpu || old._reuse || null; old.gpu = null; old._reuse = null; }
    else if (old) this._free(old);
    obj.order = old ? old.order : this.objects.size;
    this.objects.set(id, obj);
    this._updateLegend();
    this._wordsChanged();
    this.render();
  }

  // ---------------------------------------------------------------- public scene API

  /**
   * A triangle mesh. `mesh`: { positions (xyz), normals? (xyz; computed when missing), indices (triangles),
   * nu?, nv? (u-major grid size: enables isolines: true) } — e.g. the `mesh` of a wasm surface result.
   * `opts`: { color, opacity = 1, wireframe = false, wireframeColor, isolines: true | { nu, nv, every | [ku, kv],
   * color, width }, colors: 'height' | 'x' | 'y' | 'z' | Float32Array (one scalar per vertex), colormap:
   * 'viridis' | 'diverging', range: [min, max], legend: 'caption', visible = true, pickable = false (clicks on
   * the surface are reported to `onPick` as { id, kind: 'surface', position, triangle, vertex, iu, iv }) }.
   * @this {Viewer}
   */
  setMesh(id, mesh, opts = {}) {
    if (!mesh || mesh.positions == null || mesh.indices == null) throw new Error('mesh: expected { positions, indices, normals? }');
    const positions = toXYZ(mesh.positions, 'mesh.positions');
    const nvert = positions.length / 3;
    const indices = mesh.indices instanceof Uint32Array ? mesh.indices : Uint32Array.from(mesh.indices);
    if (indices.length % 3 !== 0) throw new Error(`mesh.indices: need a multiple of 3 (triangles), got ${indices.length}`);
    for (let i = 0; i < indices.length; i++) {
      if (indices[i] >= nvert) throw new Error(`mesh.indices: index ${indices[i]} out of range (${nvert} vertices)`);
    }
    let normals = mesh.normals ? toXYZ(mesh.normals, 'mesh.normals') : null;
    if (!normals || normals.length !== positions.length) normals = computeNormals(positions, indices);
    let scalars = null, colormap = opts.colormap === 'diverging' ? 'diverging' : 'viridis';
    const c = opts.colors;
    if (typeof c === 'string' && ['height', 'x', 'y', 'z'].includes(c)) {
      const k = c === 'x' ? 0 : c === 'y' ? 1 : 2;
      scalars = new Float32Array(nvert);
      for (let i = 0; i < nvert; i++) scalars[i] = positions[3 * i + k];
    } else if (c != null && typeof c.length === 'number') {
      if (c.length !== nvert) throw new Error(`colors: need one value per vertex (${nvert}), got ${c.length}`);
      scalars = c instanceof Float32Array ? c : Float32Array.from(c);
    }
    let range = null;
    if (scalars) {
      const r = opts.range;
      range = Array.isArray(r) && r.length === 2 && r.every(Number.isFinite) && r[1] > r[0]
        ? r.slice() : scalarRange(scalars, { symmetric: colormap === 'diverging' });
    }
    const overlays = [];
    if (opts.wireframe) {
      overlays.push({ segs: wireframeSegments(positions, indices), color: parseColor(opts.wireframeColor, [0.1, 0.1, 0.12]), alpha: 0.55, width: 1 });
    }
    const iso = opts.isolines;
    if (iso) {
      const nu = (iso.nu ?? mesh.nu) | 0, nv = (iso.nv ?? mesh.nv) | 0;
      if (nu >= 2 && nv >= 2 && nu * nv === nvert) {
        const ev = iso.every;
        const ku = Math.max(1, (Array.isArray(ev) ? ev[0] : ev) | 0 || Math.max(1, Math.round((nu - 1) / 10)));
        const kv = Math.max(1, (Array.isArray(ev) ? ev[1] : ev) | 0 || Math.max(1, Math.round((nv - 1) / 10)));
        overlays.push({ segs: isolineSegments(positions, nu, nv, ku, kv), color: parseColor(iso.color, [0.08, 0.08, 0.1]),
          alpha: 0.8, width: Number.isFinite(iso.width) ? iso.width : 1.25 });
      }
    }
    const order = this.objects.has(id) ? this.objects.get(id).order : this.objects.size;
    this._put(id, {
      kind: 'mesh', positions, normals, indices, scalars, range, colormap, overlays,
      color: parseColor(opts.color, parseColor(PALETTE[order % PALETTE.length])),
      opacity: Number.isFinite(opts.opacity) ? Math.min(1, Math.max(0.05, opts.opacity)) : 1,
      legend: scalars ? (opts.legend ?? (typeof c === 'string' ? (c === 'height' ? 'height z' : c) : '')) : null,
      visible: opts.visible !== false, bbox: bboxOf(positions), pickable: !!opts.pickable,
      grid: (mesh.nu | 0) >= 2 && (mesh.nv | 0) >= 2 && (mesh.nu | 0) * (mesh.nv | 0) === nvert ? [mesh.nu | 0, mesh.nv | 0] : null,
    });
  }

  /**
   * Polylines (network curves, control polygons): an array of flat xyz arrays (Float32Array / Float64Array /
   * number[]), one flat array with NaN breaks, or an array of [x, y, z] points. `opts`: { color = '#222',
   * width = 2.5 (CSS px), opacity = 1, visible = true }.
   * @this {Viewer}
   */
  setLines(id, polylines, opts = {}) {
    const segs = segmentsOf(polylines);
    this._put(id, {
      kind: 'lines', segs, bbox: bboxOf(segs), visible: opts.visible !== false,
      style: { color: parseColor(opts.color, [0.13, 0.13, 0.13]), alpha: Number.isFinite(opts.opacity) ? opts.opacity : 1,
        width: Number.isFinite(opts.width) && opts.width > 0 ? opts.width : 2.5 },
    });
  }

  /**
   * Points (control points): flat xyz or [x, y, z][]. `opts`: { color = '#D55E00', colors (one CSS colour per
   * point), size = 12 (CSS px), labels (strings), draggable = false, axis ('x' | 'y' | 'z': constrain dragging
   * to that axis), onDrag(index, [x, y, z], phase), names ((index) => string, or an array: the paper's names of
   * the points, said when one is selected and on its fields; else the label, else "point n"), pickable
   * (default: true), onTop = true (visible through surfaces), visible = true }.
   * @this {Viewer}
   */
  setPoints(id, positions, opts = {}) {
    const pos = toXYZ(positions, 'positions');
    const n = pos.length / 3;
    let colors = null;
    if (Array.isArray(opts.colors) && opts.colors.length === n) {
      colors = new Float32Array(3 * n);
      opts.colors.forEach((c, i) => colors.set(parseColor(c, parseColor(opts.color, POINT_COLOR)), 3 * i));
    }
    const labels = Array.isArray(opts.labels) ? opts.labels.slice(0, n).map((s) => String(s ?? '')) : null;
    this._put(id, {
      kind: 'points', positions: pos, colors, labels, bbox: bboxOf(pos), visible: opts.visible !== false,
      color: parseColor(opts.color, POINT_COLOR),
      size: Number.isFinite(opts.size) && opts.size > 1 ? opts.size : 12,
      draggable: !!opts.draggable, axis: ['x', 'y', 'z'].includes(opts.axis) ? opts.axis : null,
      onDrag: typeof opts.onDrag === 'function' ? opts.onDrag : null,
      names: typeof opts.names === 'function' || Array.isArray(opts.names) ? opts.names : null,
      pickable: opts.pickable !== false, onTop: opts.onTop !== false,
    });
    if (this.selected?.id === id) {
      const o = this.objects.get(id);
      if (this.selected.index >= n || !o.draggable || !o.visible) this.select(null, { quiet: true });
      else this._syncFields();
    }
  }

  /**
   * Coordinate axes as three labelled arrows-free lines from `origin` (default: the corner of the scene's bounding
   * box, or [0, 0, 0]) with length `length` (default: the box's largest side): x red-orange, y green, z blue
   * (Okabe–Ito). `setAxes(false)` removes them.
   * @this {Viewer}
   */
  setAxes(show = true, { origin = undefined, length = undefined } = {}) {
    if (!show) { for (const k of ['x', 'y', 'z']) this.remove(`__axis-${k}`); this.remove('__axis-labels'); return; }
    for (const k of ['x', 'y', 'z']) this.remove(`__axis-${k}`);
    this.remove('__axis-labels');
    const b = this._sceneBox();
    const o = Array.isArray(origin) && origin.length === 3 && origin.every(Number.isFinite) ? origin : b ? b.lo : [0, 0, 0];
    const L = Number.isFinite(length) && length > 0 ? length : b ? Math.max(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]) * 0.35 || 1 : 1;
    const colours = { x: '#D55E00', y: '#009E73', z: '#0072B2' };
    const ends = { x: [o[0] + L, o[1], o[2]], y: [o[0], o[1] + L, o[2]], z: [o[0], o[1], o[2] + L] };
    for (const k of ['x', 'y', 'z']) this.setLines(`__axis-${k}`, [[o, ends[k]]], { color: colours[k], width: 2 });
    this.setPoints('__axis-labels', [ends.x, ends.y, ends.z], { size: 4, color: '#333333', labels: ['x', 'y', 'z'], pickable: false });
  }

  /** Shows or hides an object without re-uploading it. @this {Viewer} */
  setVisible(id, visible) {
    const o = this.objects.get(id);
    if (o) { o.visible = !!visible; this._updateLegend(); this.render(); }
  }

  /** Removes an object (no error when it does not exist). @this {Viewer} */
  remove(id) {
    const o = this.objects.get(id);
    if (!o) return;
    this._free(o);
    this.objects.delete(id);
    if (this.selected?.id === id) this.select(null, { quiet: true });
    if (this.hover?.id === id) this.hover = null;
    this._updateLegend();
    this.render();
  }

  /** Removes everything. @this {Viewer} */
  clear() { for (const id of [...this.objects.keys()]) this.remove(id); }

  /** Positions of a point set (a copy, flat xyz), e.g. after dragging. @this {Viewer} */
  getPoints(id) { const o = this.objects.get(id); return o?.kind === 'points' ? Float64Array.from(o.positions) : null; }

  /** Canvas position [x, y] (CSS px from the canvas's top-left corner) of point `index` of set `id`, or null. @this {Viewer} */
  screenPosition(id, index) {
    const o = this.objects.get(id);
    if (!o || o.kind !== 'points' || !(index >= 0 && index < o.positions.length / 3)) return null;
    const p = o.positions;
    return this._project([p[3 * index], p[3 * index + 1], p[3 * index + 2]], this._camera());
  }

  /**
   * `callback({ id, index, position })` when a point is clicked / tapped or selected with the keyboard, and
   * `callback({ id, kind: 'surface', position, triangle, vertex, iu, iv })` when a `pickable` mesh is clicked.
   * Returns an unsubscribe function.
   * @this {Viewer}
   */
  onPick(callback) { this.pickListeners.push(callback); return () => { this.pickListeners = this.pickListeners.filter((f) => f !== callback); }; }

  /** `callback({ id, index, position, phase })` while a draggable point moves (phase 'start' | 'move' | 'end'). @this {Viewer} */
  onDrag(callback) { this.dragListeners.push(callback); return () => { this.dragListeners = this.dragListeners.filter((f) => f !== callback); }; }

  /** `callback(view)` after the user changed the camera (for saving it in the state). @this {Viewer} */
  onViewChange(callback) { this.viewListeners.push(callback); return () => { this.viewListeners = this.viewListeners.filter((f) => f !== callback); }; }

  /** Locks (no point dragging) or unlocks the view. @this {Viewer} */
  setLocked(locked) { this.locked = !!locked; if (this.locked && this.selected) this.select(null, { quiet: true }); }

  /** Schedules one redraw on the next animation frame (calls coalesce). @this {Viewer} */
  render() {
    if (this.destroyed || this._raf) return;
    this._raf = requestAnimationFrame(() => { this._raf = 0; this.renderNow(); });
  }

  /** A PNG data URL of the current view (drawn synchronously first). @this {Viewer} */
  toDataURL() { this.renderNow(); return this.canvas.toDataURL('image/png'); }

  /** Removes the element, listeners, animation frame and GPU resources. @this {Viewer} */
  destroy() {
    if (this.destroyed) return;
    for (const o of this.objects.values()) this._free(o);
    this.destroyed = true;
    if (this._links) { this._links.delete(this); this._links = null; }
    if (this._raf) cancelAnimationFrame(this._raf);
    this._raf = 0;
    clearTimeout(this._hintTimer);
    clearTimeout(this._wheelTimer);
    clearTimeout(this._viewWordsTimer);
    clearTimeout(this._describeTimer);
    this.table.dispose();
    this._resizeObserver?.disconnect();
    for (const [target, type, fn, opt] of this._listeners) target.removeEventListener(type, fn, opt);
    this.gl?.getExtension('WEBGL_lose_context')?.loseContext();
    this.gl = null;
    this.objects.clear();
    this.element.remove();
    this.table.el.remove();
  }

  // ---------------------------------------------------------------- camera

  /** @this {Viewer} */
  _updateScene() {
    const b = this._sceneBox();
    if (!b) return;
    this.sceneCenter = scale(add(b.lo, b.hi), 0.5);
    const r = Math.hypot(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]) / 2;
    this.sceneRadius = r > 1e-12 ? r : 1;
  }
}

// the parts: their methods become View3D methods (same names, same `this`)
for (const Part of [CameraPart, GlPart, OverlayPart, InputPart, FieldsPart]) {
  for (const name of Object.getOwnPropertyNames(Part.prototype)) {
    if (name !== 'constructor') Object.defineProperty(View3D.prototype, name, Object.getOwnPropertyDescriptor(Part.prototype, name));
  }
}

/** A View3D as its users see it: its own members and the methods of its parts. @typedef {View3D & CameraPart & GlPart & OverlayPart & InputPart & FieldsPart} Viewer */
/** View3D for the type checker: `new View3D(…)` gives a Viewer (the parts' methods are installed above). */
const View3DWithParts = /** @type {(new (parent: HTMLElement, options?: object) => Viewer) & typeof View3D} */ (View3D);
export { View3DWithParts as View3D };

/**
 * Links the cameras of several views (side-by-side surfaces): orbiting, zooming or panning one moves the others
 * the same way. The first view's camera is copied to the others now. Returns a function that unlinks them.
 */
export function linkViews(...views) {
  const list = /** @type {Viewer[]} */ (views.flat().filter((v) => v instanceof View3D));
  const group = new Set(list);
  for (const v of list) { if (v._links) v._links.delete(v); v._links = group; }
  if (list.length) list[0]._cameraMoved();
  return () => { for (const v of list) { if (v._links === group) v._links = null; } group.clear(); };
}

export default View3D;
