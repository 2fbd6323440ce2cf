// View3D's camera: orbit around a target (z up), framing, zoom, pan, rays and projection.

import { DEFAULT_VIEW, DEG, FOV } from './constants.js';
import { add, cross, dot, lookAt, norm, perspective, scale, sub, xform } from './math.js';
import { viewWords } from './words.js';

/** @typedef {import('./index.js').Viewer} Viewer */
/** Camera methods of View3D. Installed on View3D.prototype by ./index.js. */
export class CameraPart {
  /** Frames everything visible: the camera target moves to the centre, the distance fits the bounding sphere. @this {Viewer} */
  fit() {
    const b = this._sceneBox();
    this._needsFit = !b;
    if (!b) { this._fitPending = false; this.render(); return; }
    // before the view's first drawing the frame is made in that drawing (renderNow, _flushFit): measuring the
    // canvas here would force a layout of the page being built, which the first frame lays out again anyway;
    // whatever reads the camera before then (getView, setView, _camera, a linked view) makes the frame first
    if (!this._drawnSize && !this._links && !this._fitNow) { this._fitPending = true; this.render(); return; }
    this._fitPending = false;
    // sample the visible geometry (at most ~20k points), centre it on screen, then back off until it fits
    const pts = [];
    for (const o of this.objects.values()) {
      if (!o.visible) continue;
      const arr = o.kind === 'lines' ? o.segs : o.positions;
      const n = arr.length / 3, step = Math.max(1, Math.ceil(n / 20000));
      for (let i = 0; i < n; i += step) {
        const p = [arr[3 * i], arr[3 * i + 1], arr[3 * i + 2]];
        if (p.every(Number.isFinite)) pts.push(p);
      }
    }
    this.target = scale(add(b.lo, b.hi), 0.5);
    const cam = this._camera();
    const back = scale(cam.forward, -1);
    let a0 = Infinity, a1 = -Infinity, u0 = Infinity, u1 = -Infinity;
    for (const p of pts) {
      const rel = sub(p, this.target);
      const a = dot(rel, cam.right), u = dot(rel, cam.up);
      a0 = Math.min(a0, a); a1 = Math.max(a1, a); u0 = Math.min(u0, u); u1 = Math.max(u1, u);
    }
    if (pts.length) this.target = add(this.target, add(scale(cam.right, (a0 + a1) / 2), scale(cam.up, (u0 + u1) / 2)));
    if (pts.length && u1 - u0 > 1e-12) { this._contentAspect = (a1 - a0) / (u1 - u0); this._sizeCanvas(); }
    const t = Math.tan(FOV / 2), aspect = this._aspect();
    let D = 1e-9;
    for (const p of pts) {
      const rel = sub(p, this.target);
      const a = Math.abs(dot(rel, cam.right)), u = Math.abs(dot(rel, cam.up)), d = dot(rel, back);
      D = Math.max(D, d + a / (t * aspect), d + u / t);
    }
    const r = Math.hypot(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]) / 2;
    // a scene of one point (or coincident ones) gets a unit-sized frame
    this.distance = r > 1e-12 ? Math.max(D * 1.1, r * 0.05) : 1 / Math.sin(FOV / 2);
    this._fitDistance = this.distance;   // zoom 1× in the spoken view
    this._cameraMoved();
  }

  /** Makes the frame fit() left for the first drawing, now. @this {Viewer} */
  _flushFit() {
    if (!this._fitPending) return;
    this._fitNow = true;
    try { this.fit(); } finally { this._fitNow = false; }
  }

  /** Back to the default direction, framing everything. @this {Viewer} */
  resetView() { this.yaw = DEFAULT_VIEW.yaw; this.pitch = DEFAULT_VIEW.pitch; this.fit(); this._viewChanged(); }

  /** The camera as plain JSON: { yaw, pitch (degrees), distance, target: [x, y, z] }. @this {Viewer} */
  getView() {
    this._flushFit();
    const r = (v) => Number(v.toPrecision(6));
    return { yaw: r(this.yaw / DEG), pitch: r(this.pitch / DEG), distance: r(this.distance), target: this.target.map(r) };
  }

  /** Restores a camera from `getView()` output; invalid fields are ignored (returns false when nothing was usable). @this {Viewer} */
  setView(v) {
    if (!v || typeof v !== 'object') return false;
    this._flushFit();
    let ok = false;
    if (Number.isFinite(v.yaw)) { this.yaw = v.yaw * DEG; ok = true; }
    if (Number.isFinite(v.pitch)) { this.pitch = Math.max(-89, Math.min(89, v.pitch)) * DEG; ok = true; }
    if (Number.isFinite(v.distance) && v.distance > 0 && v.distance < 1e12) { this.distance = v.distance; ok = true; }
    if (Array.isArray(v.target) && v.target.length === 3 && v.target.every(Number.isFinite)) { this.target = v.target.slice(); ok = true; }
    if (ok) { this._needsFit = false; this._cameraMoved(); }
    return ok;
  }

  /** @this {Viewer} */
  _aspect() {
    const [cw, ch] = this._canvasSize();
    return (cw || 1) / (ch || 1);
  }

  /** @this {Viewer} */
  _camera() {
    if (this._fitPending && !this._fitNow) this._flushFit();
    const cp = Math.cos(this.pitch), sp = Math.sin(this.pitch);
    const back = [cp * Math.cos(this.yaw), cp * Math.sin(this.yaw), sp];      // from target towards the eye
    const eye = add(this.target, scale(back, this.distance));
    const z = back;
    const x = norm(cross([0, 0, 1], z));
    const y = cross(z, x);
    const dc = Math.hypot(...sub(eye, this.sceneCenter));
    const R = this.sceneRadius;
    const near = Math.max(dc - 2 * R, this.distance * 0.01, 1e-9);
    const far = Math.max(dc + 2 * R, near * 10);
    const view = lookAt(eye, x, y, z);
    const proj = perspective(FOV, this._aspect(), near, far);
    return { eye, right: x, up: y, forward: scale(z, -1), view, proj };
  }

  /** @this {Viewer} */
  _sceneBox() {
    let lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity], any = false;
    for (const o of this.objects.values()) {
      if (!o.visible || !o.bbox) continue;
      any = true;
      for (let k = 0; k < 3; k++) { lo[k] = Math.min(lo[k], o.bbox.lo[k]); hi[k] = Math.max(hi[k], o.bbox.hi[k]); }
    }
    return any ? { lo, hi } : null;
  }

  /** @this {Viewer} */
  _orbit(dyaw, dpitch) {
    this.yaw += dyaw;
    this.pitch = Math.max(-89 * DEG, Math.min(89 * DEG, this.pitch + dpitch));
    this._cameraMoved();
  }

  /** @this {Viewer} */
  _zoom(factor) {
    this.distance = Math.min(Math.max(this.distance * factor, this.sceneRadius * 0.02), this.sceneRadius * 200);
    this._cameraMoved();
  }

  /** Redraws, and copies the camera to the linked views (see `linkViews`). @this {Viewer} */
  _cameraMoved() {
    this._flushFit();
    this.render();
    if (!this._links || this._syncing) return;
    for (const v of this._links) {
      if (v === this || v.destroyed) continue;
      v._flushFit();
      v._syncing = true;
      v.yaw = this.yaw; v.pitch = this.pitch; v.distance = this.distance; v.target = this.target.slice();
      v._needsFit = false;
      v.render();
      v._syncing = false;
    }
  }

  /** Pans by a screen offset in CSS pixels. @this {Viewer} */
  _pan(dx, dy) {
    const cam = this._camera();
    const h = this._canvasSize()[1] || 1;
    const perPx = (2 * this.distance * Math.tan(FOV / 2)) / h;
    this.target = add(this.target, add(scale(cam.right, -dx * perPx), scale(cam.up, dy * perPx)));
    this._cameraMoved();
  }

  /** @this {Viewer} */
  _viewChanged() {
    const v = this.getView();
    for (const f of this.viewListeners) { try { f(v); } catch (e) { console.error(e); } }
    // said once the keys or the gesture pause (a held arrow key must not flood the live region)
    clearTimeout(this._viewWordsTimer);
    this._viewWordsTimer = setTimeout(() => { if (!this.destroyed) this._announce(this.viewWords()); }, 400);
  }

  /** The camera in words: "view from the south-west, 30° above; zoom 1.5×" (x is east, y north). @this {Viewer} */
  viewWords() {
    this._flushFit();
    return viewWords(this.yaw, this.pitch, this._fitDistance > 0 ? this._fitDistance / this.distance : 1);
  }

  /** World ray through a canvas position (CSS px). @this {Viewer} */
  _ray(x, y, cam = /** @type {Viewer} */ (/** @type {unknown} */ (this))._camera()) {
    const [cw, ch] = this._canvasSize(), w = cw || 1, h = ch || 1;
    const nx = (2 * x) / w - 1, ny = 1 - (2 * y) / h;
    const t = Math.tan(FOV / 2);
    const dir = norm(add(cam.forward, add(scale(cam.right, nx * t * (w / h)), scale(cam.up, ny * t))));
    return { origin: cam.eye, dir };
  }

  /** Canvas position (CSS px) of a world point, or null behind the camera. @this {Viewer} */
  _project(p, cam) {
    const e = xform(cam.view, p[0], p[1], p[2]);
    const c = xform(cam.proj, e[0], e[1], e[2]);
    if (c[3] <= 1e-9) return null;
    const [cw, ch] = this._canvasSize(), w = cw || 1, h = ch || 1;
    return [((c[0] / c[3]) * 0.5 + 0.5) * w, (1 - ((c[1] / c[3]) * 0.5 + 0.5)) * h];
  }
}
