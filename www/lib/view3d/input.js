// View3D's input: mouse, touch (tap to activate, pinch), wheel and keyboard, picking and point dragging.

import { DEG } from './constants.js';
import { bboxOf } from './geometry.js';
import { add, dot, scale, sub } from './math.js';

export const HELP = 'Drag or arrow keys: rotate (on a touch screen, tap the view first; a tap outside releases it). '
  + 'Wheel, pinch or + and −: zoom. Right-drag, Shift+drag, two fingers or '
  + 'Shift+arrows: pan. F: frame everything; R: reset the view. The buttons at the top right turn, tilt, zoom and '
  + 'frame the view with single clicks or taps; after ✥ (Arrow buttons pan) the arrow buttons pan it. The view is said in words after a change '
  + '(compass directions: x is east, y is north). Tab moves on past the view. '
  + 'N or ]: select the next draggable point, Shift+N or [: the previous one; arrows then move the selected point '
  + '(Shift: bigger steps, Page Up/Down: along z), Tab reaches its x, y, z fields, Escape deselects. '
  + 'Without dragging: click or tap a point to pick it, then click or tap where it should go (it moves in the plane '
  + 'facing you, or along its axis); a click on it again or Escape cancels.';

/** The unit vector of axis 'x', 'y' or 'z'. */
const axisVector = (name) => (name === 'x' ? [1, 0, 0] : name === 'y' ? [0, 1, 0] : [0, 0, 1]);

/** @typedef {import('./index.js').Viewer} Viewer */
/** Input methods of View3D. Installed on View3D.prototype by ./index.js. */
export class InputPart {
  /**
   * The nearest point of a pickable mesh under a canvas position (CSS px): { id, kind: 'surface', position,
   * triangle (index), vertex (the triangle's vertex nearest the hit), iu, iv (that vertex's grid indices for a
   * u-major nu × nv mesh, else undefined) }, or null.
   * @this {Viewer}
   */
  pickSurface(x, y) {
    const ray = this._ray(x, y);
    const O = ray.origin, D = ray.dir;
    let best = null, bestT = Infinity;
    for (const [id, o] of this.objects) {
      if (o.kind !== 'mesh' || !o.visible || !o.pickable) continue;
      const P = o.positions, I = o.indices;
      for (let t = 0; t + 2 < I.length; t += 3) {
        const a = 3 * I[t], b = 3 * I[t + 1], c = 3 * I[t + 2];
        // Möller–Trumbore
        const e1x = P[b] - P[a], e1y = P[b + 1] - P[a + 1], e1z = P[b + 2] - P[a + 2];
        const e2x = P[c] - P[a], e2y = P[c + 1] - P[a + 1], e2z = P[c + 2] - P[a + 2];
        const px = D[1] * e2z - D[2] * e2y, py = D[2] * e2x - D[0] * e2z, pz = D[0] * e2y - D[1] * e2x;
        const det = e1x * px + e1y * py + e1z * pz;
        if (Math.abs(det) < 1e-14) continue;
        const inv = 1 / det;
        const sx = O[0] - P[a], sy = O[1] - P[a + 1], sz = O[2] - P[a + 2];
        const u = (sx * px + sy * py + sz * pz) * inv;
        if (u < 0 || u > 1) continue;
        const qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
        const v = (D[0] * qx + D[1] * qy + D[2] * qz) * inv;
        if (v < 0 || u + v > 1) continue;
        const dist = (e2x * qx + e2y * qy + e2z * qz) * inv;
        if (dist > 0 && dist < bestT) {
          bestT = dist;
          const w = 1 - u - v;
          const vertex = w >= u && w >= v ? I[t] : u >= v ? I[t + 1] : I[t + 2];
          best = { id, kind: 'surface', triangle: t / 3, vertex, position: add(O, scale(D, dist)), iu: undefined, iv: undefined };
          if (o.grid) { best.iu = Math.floor(vertex / o.grid[1]); best.iv = vertex % o.grid[1]; }
        }
      }
    }
    return best;
  }

  /** The nearest pickable point under a canvas position, within its radius plus `slack` px. @this {Viewer} */
  pickAt(x, y, slack = 6) {
    const cam = this._camera();
    let best = null, bestD = Infinity;
    for (const [id, o] of this.objects) {
      if (o.kind !== 'points' || !o.visible || !(o.pickable || o.draggable)) continue;
      const p = o.positions;
      for (let i = 0; i < p.length / 3; i++) {
        const s = this._project([p[3 * i], p[3 * i + 1], p[3 * i + 2]], cam);
        if (!s) continue;
        const d = Math.hypot(s[0] - x, s[1] - y);
        if (d <= o.size / 2 + slack && d < bestD) { bestD = d; best = { id, index: i, position: [p[3 * i], p[3 * i + 1], p[3 * i + 2]] }; }
      }
    }
    return best;
  }

  // ---------------------------------------------------------------- drawing

  /** @this {Viewer} */
  _bind() {
    const c = this.canvas;
    this._listeners = [];
    const on = (target, type, fn, opt) => { target.addEventListener(type, fn, opt); this._listeners.push([target, type, fn, opt]); };
    on(c, 'pointerdown', (e) => this._down(e));
    on(c, 'pointermove', (e) => this._move(e));
    on(c, 'pointerup', (e) => this._up(e));
    on(c, 'pointercancel', (e) => this._up(e));
    on(c, 'lostpointercapture', (e) => { if (this.pointers.has(e.pointerId)) this._up(e); });
    on(c, 'pointerleave', () => { if (this.hover && !this.pointers.size) { this.hover = null; this.render(); } });
    on(c, 'contextmenu', (e) => e.preventDefault());
    // touch: stop the page from scrolling while the view owns the gesture (active, dragging, two fingers)
    const touch = (e) => {
      if (e.cancelable && (this.touchActive || this.mode === 'drag' || this.mode === 'pinch' || e.touches.length >= 2)) e.preventDefault();
    };
    on(c, 'touchstart', touch, { passive: false });
    on(c, 'touchmove', touch, { passive: false });
    // a tap (or click) outside the view gives one-finger swipes back to the page
    on(document, 'pointerdown', (e) => {
      if (!this.touchActive) return;
      const path = typeof e.composedPath === 'function' ? e.composedPath() : [];
      if (!path.includes(this.element)) this.setTouchActive(false);
    }, true);
    on(c, 'wheel', (e) => this._wheel(e), { passive: false });
    on(c, 'keydown', (e) => this._key(e));
    on(c, 'focus', () => {
      let visible = true;
      try { visible = c.matches(':focus-visible'); } catch { /* old browser */ }
      if (visible) { c.style.outline = '3px solid #111'; c.style.outlineOffset = '2px'; }
    });
    on(c, 'blur', () => { c.style.outline = 'none'; });
    // the selection lasts while focus stays in the view (its canvas or the selected point's fields)
    on(this.element, 'focusout', (e) => {
      const to = /** @type {Node | null} */ (e.relatedTarget);
      if (this.selected && !(to && this.element.contains(to))) this.select(null, { quiet: true });
    });
    on(c, 'webglcontextlost', (e) => { e.preventDefault(); });
    on(c, 'webglcontextrestored', () => {
      try { this._initGL(); this.render(); } catch (err) { console.error(err); }
    });
  }

  /** @this {Viewer} */
  _pos(e) {
    const r = this.canvas.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  }

  /** @this {Viewer} */
  _down(e) {
    if (this.destroyed) return;
    const [x, y] = this._pos(e);
    if (e.pointerType === 'touch' && !this.touchActive) {
      this.tapHint.hidden = false;   // a touch device after all: say how to rotate
      // an inactive view: one finger scrolls the page; a finger on a draggable point drags it; a second finger
      // zooms/pans; a tap (no movement) activates one-finger orbiting
      const hit = this.pointers.size === 0 ? this.pickAt(x, y, 14) : null;
      const dragHit = hit && this.objects.get(hit.id)?.draggable && !this.locked;
      if (this.pointers.size === 0 && !dragHit) {
        this.pointers.set(e.pointerId, { x, y });
        this._tap = { id: e.pointerId, x, y, t: performance.now(), moved: false };
        this.mode = null; this._last = null; this._press = null;
        return;
      }
      this._tap = null;
    }
    if ((/** @type {Document | ShadowRoot} */ (this.canvas.getRootNode?.())?.activeElement ?? document.activeElement) !== this.canvas) this.canvas.focus({ preventScroll: true });
    try { this.canvas.setPointerCapture(e.pointerId); } catch { /* synthetic events */ }
    this.pointers.set(e.pointerId, { x, y });
    if (this.pointers.size === 2 && this.mode !== 'drag') {
      this._tap = null;
      this._press = null;
      this.mode = 'pinch';
      this._pinch = this._pinchState();
      return;
    }
    if (this.pointers.size > 1) return;
    if (e.pointerType === 'mouse' && e.button !== 0 && e.button !== 2) return;
    const hit = e.button === 0 ? this.pickAt(x, y, e.pointerType === 'touch' ? 14 : 6) : null;
    if (hit) this._emitPick(hit);
    const obj = hit && this.objects.get(hit.id);
    if (hit && obj.draggable && !this.locked) {
      e.preventDefault();
      this.mode = 'drag';
      const cam = this._camera();
      const p0 = hit.position;
      const ray = this._ray(x, y, cam);
      const n = cam.forward;
      const t = dot(sub(p0, ray.origin), n) / dot(ray.dir, n);
      const grab = add(ray.origin, scale(ray.dir, t));
      this.dragging = { id: hit.id, index: hit.index, p0, n, offset: sub(grab, p0), s0: null, moved: false };
      this.canvas.style.cursor = 'grabbing';
      // 'start' waits for the first movement (_dragTo): a press that does not move the point is a click, and a
      // click must not look like an edit to the demo (which saves its state at 'end')
      this.render();
      return;
    }
    this.mode = e.button === 2 || e.shiftKey ? 'pan' : 'orbit';
    this._last = { x, y };
    this._press = hit || e.button !== 0 ? null : { x, y, moved: false };
  }

  /** @this {Viewer} */
  _pinchState() {
    const [a, b] = [...this.pointers.values()];
    return { d: Math.hypot(a.x - b.x, a.y - b.y) || 1, mx: (a.x + b.x) / 2, my: (a.y + b.y) / 2 };
  }

  /** @this {Viewer} */
  _move(e) {
    if (this.destroyed) return;
    const [x, y] = this._pos(e);
    if (!this.pointers.has(e.pointerId)) {
      // hover feedback (mouse / pen without buttons)
      const hit = this.pickAt(x, y);
      const dragHit = hit && this.objects.get(hit.id).draggable && !this.locked ? hit : null;
      const changed = (dragHit?.id !== this.hover?.id) || (dragHit?.index !== this.hover?.index);
      this.hover = dragHit ? { id: dragHit.id, index: dragHit.index } : null;
      this.canvas.style.cursor = dragHit ? 'pointer' : this._picked ? 'crosshair' : 'grab';
      if (changed) this.render();
      return;
    }
    this.pointers.set(e.pointerId, { x, y });
    if (this._tap && this._tap.id === e.pointerId) {
      if (Math.hypot(x - this._tap.x, y - this._tap.y) > 10) this._tap.moved = true;
      return;
    }
    if (this.mode === 'pinch' && this.pointers.size >= 2) {
      const s = this._pinchState(), p = this._pinch;
      this._zoom(p.d / s.d);
      this._pan(s.mx - p.mx, s.my - p.my);
      this._pinch = s;
      return;
    }
    if (this.mode === 'drag') { this._dragTo(x, y, e.shiftKey); return; }
    if (!this._last) return;
    const dx = x - this._last.x, dy = y - this._last.y;
    this._last = { x, y };
    if (this._press && Math.hypot(x - this._press.x, y - this._press.y) > 4) this._press.moved = true;
    if (this.mode === 'orbit') this._orbit(-dx * 0.45 * DEG, dy * 0.45 * DEG);
    else if (this.mode === 'pan') this._pan(dx, dy);
  }

  /** @this {Viewer} */
  _dragTo(x, y, constrain) {
    const d = this.dragging;
    const o = this.objects.get(d.id);
    if (!o || d.index >= o.positions.length / 3) { this.dragging = null; this.mode = null; return; }
    const cam = this._camera();
    const ray = this._ray(x, y, cam);
    let p;
    const axisName = o.axis || (constrain ? 'z' : null);
    if (axisName) {
      const A = axisVector(axisName);
      const s = this._axisParam(d.p0, A, ray);
      if (s === null) return;
      if (d.axisName !== axisName || d.s0 === null) {
        // re-anchor so switching modes does not jump
        const cur = [o.positions[3 * d.index], o.positions[3 * d.index + 1], o.positions[3 * d.index + 2]];
        d.s0 = s - dot(sub(cur, d.p0), A);
        d.axisName = axisName;
      }
      p = add(d.p0, scale(A, s - d.s0));
    } else {
      if (d.axisName) {
        const cur = [o.positions[3 * d.index], o.positions[3 * d.index + 1], o.positions[3 * d.index + 2]];
        d.p0 = cur; d.n = cam.forward;
        const t0 = dot(sub(cur, ray.origin), d.n) / dot(ray.dir, d.n);
        d.offset = sub(add(ray.origin, scale(ray.dir, t0)), cur);
        d.axisName = null; d.s0 = null;
      }
      const den = dot(ray.dir, d.n);
      if (Math.abs(den) < 1e-9) return;
      const t = dot(sub(d.p0, ray.origin), d.n) / den;
      if (!(t > 0)) return;
      p = sub(add(ray.origin, scale(ray.dir, t)), d.offset);
    }
    if (!p.every(Number.isFinite)) return;
    if (!d.moved) this._emitDrag('start', [o.positions[3 * d.index], o.positions[3 * d.index + 1], o.positions[3 * d.index + 2]]);
    d.moved = true;
    this._movePoint(d.id, d.index, p, 'move');
  }

  /** Parameter s of the point P0 + s·A closest to the ray. @this {Viewer} */
  _axisParam(p0, A, ray) {
    const w0 = sub(p0, ray.origin);
    const a = dot(A, A), b = dot(A, ray.dir), c = dot(ray.dir, ray.dir), d = dot(A, w0), e = dot(ray.dir, w0);
    const den = a * c - b * b;
    if (Math.abs(den) < 1e-9) return null;
    return (b * e - c * d) / den;
  }

  /** @this {Viewer} */
  _movePoint(id, index, p, phase) {
    const o = this.objects.get(id);
    if (!o) return;
    o.positions = Float32Array.from(o.positions);
    o.positions.set(p, 3 * index);
    o.bbox = bboxOf(o.positions);
    if (o.gpu && this.gl) {
      this.gl.bindBuffer(this.gl.ARRAY_BUFFER, o.gpu.buffers[0]);
      this.gl.bufferSubData(this.gl.ARRAY_BUFFER, 12 * index, new Float32Array(p));
    }
    // the listeners first: a demo that recomputes in its own animation frame registers it before ours, so the
    // frame draws the new scene (not the old one, with the new scene a frame later)
    this._emitDrag(phase, p, id, index);
    this.render();
  }

  /** @this {Viewer} */
  _emitDrag(phase, position, id = this.dragging?.id, index = this.dragging?.index) {
    const o = this.objects.get(id);
    if (phase === 'end') { this._moved = { id, index }; this._wordsChanged(); }
    const pos = [position[0], position[1], position[2]];
    try { o?.onDrag?.(index, pos, phase); } catch (e) { console.error(e); }
    for (const f of this.dragListeners) { try { f({ id, index, position: pos, phase }); } catch (e) { console.error(e); } }
  }

  /** @this {Viewer} */
  _emitPick(hit) {
    for (const f of this.pickListeners) { try { f(hit); } catch (e) { console.error(e); } }
  }

  /** @this {Viewer} */
  _up(e) {
    if (!this.pointers.has(e.pointerId)) return;
    this.pointers.delete(e.pointerId);
    if (this._tap && this._tap.id === e.pointerId) {
      const tap = this._tap;
      this._tap = null;
      if (e.type === 'pointerup' && !tap.moved && performance.now() - tap.t < 800 && this._picked && this.selected) {
        // the destination tap of a tap-then-tap move (the view stays inactive: the page keeps scrolling)
        this._moveSelectedTo(tap.x, tap.y);
      } else if (e.type === 'pointerup' && !tap.moved && performance.now() - tap.t < 800) {
        this.setTouchActive(true);
        this.canvas.focus({ preventScroll: true });
      } else if (e.type === 'pointercancel') this._hint('Tap the view first to rotate it');
      if (this.pointers.size === 0) { this.mode = null; this._last = null; }
      return;
    }
    try { this.canvas.releasePointerCapture(e.pointerId); } catch { /* not captured */ }
    if (this.mode === 'drag' && this.dragging) {
      const d = this.dragging, o = this.objects.get(d.id);
      if (d.moved && o && d.index < o.positions.length / 3) {
        this._emitDrag('end', [o.positions[3 * d.index], o.positions[3 * d.index + 1], o.positions[3 * d.index + 2]]);
      }
      this.dragging = null;
      // a click on a point (no drag) picks it: the next click elsewhere moves it there, and its fields move it
      // by number (WCAG 2.5.7, moving without dragging)
      if (!d.moved) this._pickClick(d);
      else if (this.selected?.id === d.id && this.selected.index === d.index) this._syncFields(true);
      this.canvas.style.cursor = 'grab';
      this.render();
    } else if (this.mode === 'orbit' && this._press && !this._press.moved && this.pointers.size === 0) {
      // a click (no drag) on the background or a surface: the destination of a picked point, else a pick
      if (this._picked && this.selected) this._moveSelectedTo(this._press.x, this._press.y);
      else {
        const hit = this.pickSurface(this._press.x, this._press.y);
        if (hit) this._emitPick(hit);
      }
      this._press = null;
    } else if (this.mode === 'orbit' || this.mode === 'pan' || this.mode === 'pinch') {
      this._viewChanged();
    }
    if (this.mode === 'pinch') this._press = null;
    if (this.pointers.size === 0) { this.mode = null; this._last = null; }
    else if (this.mode === 'pinch' && e.pointerType === 'touch' && !this.touchActive) { this.mode = null; this._last = null; }
    else if (this.mode === 'pinch') { this.mode = 'orbit'; const [p] = [...this.pointers.values()]; this._last = { ...p }; }
  }

  /**
   * A click or tap on a draggable point that did not drag it: picks it for a click-then-click move, or (a click on
   * the picked point again) cancels.
   * @this {Viewer}
   */
  _pickClick(d) {
    if (this._picked && this.selected?.id === d.id && this.selected.index === d.index) { this.select(null); return; }
    this.select({ id: d.id, index: d.index }, { quiet: true });
    this._picked = true;
    this.canvas.style.cursor = 'crosshair';
    this._announce(`${this._describe(this.selected)} selected. Click or tap where it should go; Escape cancels. `
      + 'Its coordinate fields are under the view.');
  }

  /**
   * The destination click of a click-then-click move, at canvas position (x, y) (CSS px): the picked point goes to
   * where the click's ray meets the plane through the point facing the camera (so it lands under the click, as a
   * drag would take it there), or to the nearest place on its axis for a point that moves along one axis. One
   * start / move / end like a drag, so the demo records one undo step.
   * @this {Viewer}
   */
  _moveSelectedTo(x, y) {
    const sel = this.selected, o = sel && this.objects.get(sel.id);
    this._picked = false;
    this.canvas.style.cursor = 'grab';
    if (!o || this.locked || sel.index >= o.positions.length / 3) return;
    const cur = Array.from(o.positions.subarray(3 * sel.index, 3 * sel.index + 3));
    const cam = this._camera();
    const ray = this._ray(x, y, cam);
    let p = null;
    if (o.axis) {
      const A = axisVector(o.axis);
      const s = this._axisParam(cur, A, ray);
      if (s !== null) p = add(cur, scale(A, s));
    } else {
      const den = dot(ray.dir, cam.forward);
      const t = Math.abs(den) < 1e-9 ? NaN : dot(sub(cur, ray.origin), cam.forward) / den;
      if (t > 0) p = add(ray.origin, scale(ray.dir, t));
    }
    if (!p || !p.every(Number.isFinite)) { this._announce('That place cannot be reached from this view; the point did not move.'); return; }
    this._moveInOneStep(sel, cur, p, ': moved.');
    this.render();
  }

  /**
   * Moves the selected point `sel` from `cur` to `p` as one drag (start, move, end: the demo records one undo
   * step), then shows the new place in its fields and says it (its name and coordinates, then `after`).
   * @this {Viewer}
   */
  _moveInOneStep(sel, cur, p, after = '') {
    this._emitDrag('start', cur, sel.id, sel.index);
    this._movePoint(sel.id, sel.index, p, 'move');
    const now = this.objects.get(sel.id);
    if (now && sel.index < now.positions.length / 3) {
      this._emitDrag('end', Array.from(now.positions.subarray(3 * sel.index, 3 * sel.index + 3)), sel.id, sel.index);
      this._syncFields(true);
      if (this.objects.has(sel.id)) this._announce(`${this._describe(sel)}${after}`);
    }
  }

  /** @this {Viewer} */
  _wheel(e) {
    // Like the 2D plots: zoom only when the view has focus or with Ctrl/⌘ (trackpad pinch); otherwise the wheel
    // keeps scrolling the page, and a hint says how to zoom.
    const root = /** @type {Document | ShadowRoot} */ (this.canvas.getRootNode ? this.canvas.getRootNode() : document);
    const focused = (root.activeElement ?? document.activeElement) === this.canvas;
    if (!(focused || e.ctrlKey || e.metaKey)) { this._hint('Click the view (or hold Ctrl) to zoom with the wheel'); return; }
    e.preventDefault();
    const unit = e.deltaMode === 1 ? 33 : e.deltaMode === 2 ? 400 : 1;
    const dy = Math.max(-200, Math.min(200, e.deltaY * unit));
    this._zoom(Math.exp(dy * 0.0015));
    clearTimeout(this._wheelTimer);
    this._wheelTimer = setTimeout(() => this._viewChanged(), 250);
  }

  /** @this {Viewer} */
  _hint(text) {
    if (!this._hintEl) {
      const el = this._hintEl = document.createElement('div');
      el.setAttribute('aria-hidden', 'true');
      el.style.cssText = 'position:absolute;left:50%;bottom:10px;transform:translateX(-50%);padding:4px 10px;border-radius:4px;'
        + 'background:rgba(17,17,17,0.85);color:#fff;font:14px/1.3 system-ui,sans-serif;pointer-events:none;';
      this.element.appendChild(el);
    }
    this._hintEl.textContent = text;
    this._hintEl.style.bottom = `${10 + (this.fieldsPanel && !this.fieldsPanel.hidden ? this.fieldsPanel.offsetHeight : 0)}px`;
    this._hintEl.hidden = false;
    clearTimeout(this._hintTimer);
    this._hintTimer = setTimeout(() => { if (this._hintEl) this._hintEl.hidden = true; }, 1500);
  }

  /** @this {Viewer} */
  _draggables() {
    const list = [];
    for (const [id, o] of [...this.objects].sort((a, b) => a[1].order - b[1].order)) {
      if (o.kind === 'points' && o.visible && o.draggable) for (let i = 0; i < o.positions.length / 3; i++) list.push({ id, index: i });
    }
    return list;
  }

  /** Says `text` in the live region. A view change still waiting to be said (camera.js) is dropped: what was
   * done after it (a point chosen or moved) is the newer news and must not be overwritten 400 ms later. @this {Viewer} */
  _announce(text) { clearTimeout(this._viewWordsTimer); this.live.textContent = text; }

  /** @this {Viewer} */
  _key(e) {
    if (this.destroyed || e.altKey || e.ctrlKey || e.metaKey) return;
    const big = e.shiftKey;
    // one Tab stop: Tab is the browser's (it moves on, or to the selected point's fields); N / ] and Shift+N / [ choose a point
    const key = e.key.length === 1 ? e.key.toLowerCase() : e.key;
    // (the page's presentation key is Alt+P: P is free, but N is the 2D plots' key too)
    const pick = key === 'n' ? (e.shiftKey ? -1 : 1) : key === ']' ? 1 : key === '[' ? -1 : 0;
    if (pick) { e.preventDefault(); this._selectStep(pick); return; }
    if (e.key === 'Escape' && this.selected) { e.preventDefault(); this.select(null); return; }
    const arrows = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] };
    if (this.selected && (arrows[e.key] || e.key === 'PageUp' || e.key === 'PageDown')) {
      e.preventDefault();
      const sel = this.selected, o = this.objects.get(sel.id);
      if (!o) { this.select(null, { quiet: true }); return; }
      const cam = this._camera();
      const dist = this.sceneRadius * 0.02 * (big ? 5 : 1);
      let dir;
      if (e.key === 'PageUp') dir = [0, 0, 1];
      else if (e.key === 'PageDown') dir = [0, 0, -1];
      else { const [a, b] = arrows[e.key]; dir = add(scale(cam.right, a), scale(cam.up, b)); }
      if (o.axis) { const A = axisVector(o.axis); const s = dot(dir, A); dir = scale(A, Math.abs(s) < 1e-6 ? 0 : Math.sign(s)); }
      const cur = Array.from(o.positions.subarray(3 * sel.index, 3 * sel.index + 3));
      this._moveInOneStep(sel, cur, add(cur, scale(dir, dist)));
      return;
    }
    let handled = true;
    const a = (big ? 15 : 5) * DEG;
    switch (e.key) {
      case 'ArrowLeft': big ? this._pan(40, 0) : this._orbit(a, 0); break;
      case 'ArrowRight': big ? this._pan(-40, 0) : this._orbit(-a, 0); break;
      case 'ArrowUp': big ? this._pan(0, 40) : this._orbit(0, -a); break;
      case 'ArrowDown': big ? this._pan(0, -40) : this._orbit(0, a); break;
      case '+': case '=': this._zoom(1 / 1.15); break;
      case '-': case '_': this._zoom(1.15); break;
      case 'f': case 'F': case 'Home': this.fit(); break;
      case 'r': case 'R': this.resetView(); break;
      default: handled = false;
    }
    if (handled) { e.preventDefault(); this._viewChanged(); }
  }
}
