// A small hand-written WebGL2 surface viewer for SplineLab's 3D demos (no three.js, no build step).
//
//   const view = new View3D(parentElement, { height: 420, ariaLabel: 'Gordon surface' });
//   view.setMesh('S', wasmResult.mesh, { color: '#3f7fd6', isolines: true, wireframe: false,
//                                        colors: 'height' | Float32Array, colormap: 'viridis', legend: 'z' });
//   view.setLines('net', [flatXYZ, flatXYZ, …], { color: '#111', width: 3 });
//   view.setPoints('ctrl', flatXYZ, { color: '#d62728', size: 12, labels: ['P0', …], draggable: true,
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
// canvas is focusable): arrows orbit, Shift+arrows pan, +/- zoom, F or Home frames everything, Tab/Shift+Tab
// select the draggable points one by one, then arrows move the selected point (Shift: 5× step, PageUp/PageDown:
// along z), Escape deselects. Rendering is coalesced with requestAnimationFrame. Without WebGL2 the element
// shows a clear message and every method still works (as a no-op).
//
// Shading: Blinn-Phong with a light mounted on the camera, two-sided (back faces slightly darker), optional
// wireframe and isoparametric lines (for a u-major nu × nv grid mesh such as the wasm `mesh` results), and a
// colour-map mode for any per-vertex scalar (height, the distance between two surfaces, Gaussian curvature…)
// with a legend.

import { colormapLUT, scalarRange, legendElement, updateLegend } from './colormap.js';

const DEG = Math.PI / 180;
const FOV = 35 * DEG;
const POINT_COLOR = [0xd5 / 255, 0x5e / 255, 0];   // vermillion, the playground's control-point colour
const DEFAULT_VIEW = { yaw: -60 * DEG, pitch: 28 * DEG };
// Okabe–Ito colour-blind-safe palette (as style.css / plot2d.js): default surface colours, in order
const PALETTE = ['#0072B2', '#E69F00', '#009E73', '#CC79A7', '#56B4E9', '#D55E00'];

// ---------------------------------------------------------------- shaders

const MESH_VS = `#version 300 es
layout(location=0) in vec3 aPos;
layout(location=1) in vec3 aNormal;
layout(location=2) in float aScalar;
uniform mat4 uView, uProj;
uniform vec2 uRange;
out vec3 vEye; out vec3 vNormal; out float vT;
void main() {
  vec4 e = uView * vec4(aPos, 1.0);
  vEye = e.xyz;
  vNormal = mat3(uView) * aNormal;
  vT = (aScalar - uRange.x) / (uRange.y - uRange.x);
  gl_Position = uProj * e;
}`;

const MESH_FS = `#version 300 es
precision highp float;
in vec3 vEye; in vec3 vNormal; in float vT;
uniform vec3 uColor;
uniform float uOpacity;
uniform bool uUseMap;
uniform sampler2D uMap;
out vec4 outColor;
void main() {
  vec3 v = normalize(-vEye);
  vec3 n = vNormal;
  if (dot(n, n) < 1e-20) n = cross(dFdx(vEye), dFdy(vEye));
  n = normalize(n);
  bool back = dot(n, v) < 0.0;
  if (back) n = -n;
  vec3 base = uUseMap ? texture(uMap, vec2(clamp(vT, 0.0, 1.0), 0.5)).rgb : uColor;
  if (back && !uUseMap) base *= 0.78;
  vec3 l = normalize(vec3(-0.35, 0.45, 1.0));          // headlight, slightly above-left of the eye
  vec3 h = normalize(l + v);
  float diff = max(dot(n, l), 0.0);
  float spec = pow(max(dot(n, h), 0.0), 60.0);
  vec3 c = base * (0.30 + 0.70 * diff) + vec3(0.22 * spec);
  outColor = vec4(c * uOpacity, uOpacity);
}`;

// Thick lines: one instance per segment (endpoints aA, aB), expanded to a screen-space quad.
const LINE_VS = `#version 300 es
layout(location=0) in vec2 aCorner;
layout(location=1) in vec3 aA;
layout(location=2) in vec3 aB;
uniform mat4 uView, uProj;
uniform vec2 uViewport;
uniform float uWidth;
uniform float uBias;
void main() {
  vec4 ca = uProj * uView * vec4(aA, 1.0);
  vec4 cb = uProj * uView * vec4(aB, 1.0);
  vec2 sa = ca.xy / max(ca.w, 1e-6) * uViewport * 0.5;
  vec2 sb = cb.xy / max(cb.w, 1e-6) * uViewport * 0.5;
  vec2 d = sb - sa;
  float len = length(d);
  vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
  vec2 nrm = vec2(-dir.y, dir.x);
  vec4 c = aCorner.x < 0.5 ? ca : cb;
  vec2 off = (nrm * aCorner.y + dir * (aCorner.x < 0.5 ? -1.0 : 1.0)) * uWidth * 0.5;
  c.xy += off / (uViewport * 0.5) * c.w;
  c.z -= uBias * c.w;
  gl_Position = c;
}`;

const FLAT_FS = `#version 300 es
precision highp float;
uniform vec4 uColor;
out vec4 outColor;
void main() { outColor = vec4(uColor.rgb * uColor.a, uColor.a); }`;

const POINT_VS = `#version 300 es
layout(location=0) in vec3 aPos;
layout(location=1) in vec3 aColor;
uniform mat4 uView, uProj;
uniform float uSize;
out vec3 vColor;
void main() {
  gl_Position = uProj * uView * vec4(aPos, 1.0);
  gl_Position.z -= 0.002 * gl_Position.w;
  gl_PointSize = uSize;
  vColor = aColor;
}`;

const POINT_FS = `#version 300 es
precision highp float;
in vec3 vColor;
uniform float uSize;
uniform float uHighlight;
out vec4 outColor;
void main() {
  vec2 p = gl_PointCoord * 2.0 - 1.0;
  float r = length(p);
  if (r > 1.0) discard;
  float px = 2.0 / uSize;                       // one pixel in point-coordinate units
  float ring = uHighlight > 0.5 ? 1.0 - 5.0 * px : 1.0 - 2.5 * px;
  vec3 c = vColor;
  if (r > ring) c = vec3(0.07);
  else if (uHighlight > 0.5 && r > ring - 3.0 * px) c = vec3(1.0);
  float a = 1.0 - smoothstep(1.0 - px, 1.0, r);
  outColor = vec4(c * a, a);
}`;

// ---------------------------------------------------------------- small vector / matrix helpers

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => { const l = Math.hypot(a[0], a[1], a[2]) || 1; return [a[0] / l, a[1] / l, a[2] / l]; };

function perspective(fovy, aspect, near, far) {
  const f = 1 / Math.tan(fovy / 2), nf = 1 / (near - far);
  return new Float32Array([f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) * nf, -1, 0, 0, 2 * far * near * nf, 0]);
}

function lookAt(eye, x, y, z) {
  return new Float32Array([x[0], y[0], z[0], 0, x[1], y[1], z[1], 0, x[2], y[2], z[2], 0,
    -dot(x, eye), -dot(y, eye), -dot(z, eye), 1]);
}

/** Column-major 4×4 times (x, y, z, 1). */
function xform(m, x, y, z) {
  return [m[0] * x + m[4] * y + m[8] * z + m[12], m[1] * x + m[5] * y + m[9] * z + m[13],
    m[2] * x + m[6] * y + m[10] * z + m[14], m[3] * x + m[7] * y + m[11] * z + m[15]];
}

/** A CSS hex colour ('#abc', '#aabbcc') or [r, g, b] in 0..1 → [r, g, b]; anything else → fallback. */
export function parseColor(c, fallback = [0.25, 0.5, 0.84]) {
  if (Array.isArray(c) && c.length >= 3 && c.every((v) => Number.isFinite(v))) return c.slice(0, 3).map((v) => Math.min(1, Math.max(0, v)));
  if (typeof c === 'string') {
    let h = c.trim();
    if (/^#[0-9a-f]{3}$/i.test(h)) h = '#' + h[1] + h[1] + h[2] + h[2] + h[3] + h[3];
    if (/^#[0-9a-f]{6}$/i.test(h)) {
      const n = parseInt(h.slice(1), 16);
      return [((n >> 16) & 255) / 255, ((n >> 8) & 255) / 255, (n & 255) / 255];
    }
  }
  return fallback;
}

/** Flat xyz Float32Array from a flat numeric array / typed array, or from an array of [x, y, z] (or [x, y]) points. */
function toXYZ(data, what) {
  if (data == null) return new Float32Array(0);
  if (ArrayBuffer.isView(data) || (Array.isArray(data) && (data.length === 0 || typeof data[0] === 'number'))) {
    if (data.length % 3 !== 0) throw new Error(`${what}: a flat xyz array needs a length divisible by 3, got ${data.length}`);
    return data instanceof Float32Array ? data : Float32Array.from(data);
  }
  if (Array.isArray(data)) {
    const out = new Float32Array(data.length * 3);
    data.forEach((p, i) => {
      if (!p || typeof p.length !== 'number' || p.length < 2) throw new Error(`${what}: point ${i} is not [x, y, z]`);
      out[3 * i] = p[0]; out[3 * i + 1] = p[1]; out[3 * i + 2] = p.length > 2 ? p[2] : 0;
    });
    return out;
  }
  throw new Error(`${what}: expected a flat xyz array or an array of [x, y, z] points`);
}

function isPointList(a) {
  return Array.isArray(a) && a.length > 0 && a.every((p) => Array.isArray(p) && p.length >= 2 && p.length <= 3 && typeof p[0] === 'number');
}

/** Polylines → flat segment list [ax, ay, az, bx, by, bz, …]; NaN points break a polyline. */
function segmentsOf(polylines) {
  let list;
  if (ArrayBuffer.isView(polylines) || (Array.isArray(polylines) && typeof polylines[0] === 'number')) list = [polylines];
  else if (isPointList(polylines)) list = [polylines];
  else if (Array.isArray(polylines)) list = polylines;
  else throw new Error('polylines: expected an array of flat xyz arrays');
  const segs = [];
  for (let k = 0; k < list.length; k++) {
    const p = toXYZ(list[k], `polylines[${k}]`);
    for (let i = 0; i + 5 < p.length; i += 3) {
      let ok = true;
      for (let j = 0; j < 6; j++) if (!Number.isFinite(p[i + j])) { ok = false; break; }
      if (ok) segs.push(p[i], p[i + 1], p[i + 2], p[i + 3], p[i + 4], p[i + 5]);
    }
  }
  return new Float32Array(segs);
}

function bboxOf(xyz) {
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i + 2 < xyz.length; i += 3) {
    const x = xyz[i], y = xyz[i + 1], z = xyz[i + 2];
    if (!Number.isFinite(x) || !Number.isFinite(y) || !Number.isFinite(z)) continue;
    if (x < lo[0]) lo[0] = x; if (y < lo[1]) lo[1] = y; if (z < lo[2]) lo[2] = z;
    if (x > hi[0]) hi[0] = x; if (y > hi[1]) hi[1] = y; if (z > hi[2]) hi[2] = z;
  }
  return lo[0] <= hi[0] ? { lo, hi } : null;
}

/** Area-weighted vertex normals of a triangle mesh. */
export function computeNormals(pos, idx) {
  const n = new Float32Array(pos.length);
  for (let t = 0; t + 2 < idx.length; t += 3) {
    const a = 3 * idx[t], b = 3 * idx[t + 1], c = 3 * idx[t + 2];
    const e1 = [pos[b] - pos[a], pos[b + 1] - pos[a + 1], pos[b + 2] - pos[a + 2]];
    const e2 = [pos[c] - pos[a], pos[c + 1] - pos[a + 1], pos[c + 2] - pos[a + 2]];
    const f = cross(e1, e2);
    if (!f.every(Number.isFinite)) continue;
    for (const v of [a, b, c]) { n[v] += f[0]; n[v + 1] += f[1]; n[v + 2] += f[2]; }
  }
  for (let i = 0; i < n.length; i += 3) {
    const l = Math.hypot(n[i], n[i + 1], n[i + 2]);
    if (l > 0) { n[i] /= l; n[i + 1] /= l; n[i + 2] /= l; }
  }
  return n;
}

function wireframeSegments(pos, idx) {
  const seen = new Set(), segs = [];
  const nv = pos.length / 3;
  const edge = (a, b) => {
    const key = a < b ? a * nv + b : b * nv + a;
    if (seen.has(key)) return;
    seen.add(key);
    segs.push(pos[3 * a], pos[3 * a + 1], pos[3 * a + 2], pos[3 * b], pos[3 * b + 1], pos[3 * b + 2]);
  };
  for (let t = 0; t + 2 < idx.length; t += 3) { edge(idx[t], idx[t + 1]); edge(idx[t + 1], idx[t + 2]); edge(idx[t + 2], idx[t]); }
  return new Float32Array(segs);
}

/** Isoparametric lines of a u-major nu × nv grid mesh (vertex iu * nv + iv), every `ku`-th / `kv`-th line plus the borders. */
function isolineSegments(pos, nu, nv, ku, kv) {
  const segs = [];
  const P = (iu, iv) => 3 * (iu * nv + iv);
  const keep = (i, n, k) => i % k === 0 || i === n - 1;
  for (let iu = 0; iu < nu; iu++) {
    if (!keep(iu, nu, ku)) continue;
    for (let iv = 0; iv + 1 < nv; iv++) { const a = P(iu, iv), b = P(iu, iv + 1); segs.push(pos[a], pos[a + 1], pos[a + 2], pos[b], pos[b + 1], pos[b + 2]); }
  }
  for (let iv = 0; iv < nv; iv++) {
    if (!keep(iv, nv, kv)) continue;
    for (let iu = 0; iu + 1 < nu; iu++) { const a = P(iu, iv), b = P(iu + 1, iv); segs.push(pos[a], pos[a + 1], pos[a + 2], pos[b], pos[b + 1], pos[b + 2]); }
  }
  return new Float32Array(segs);
}

const HELP = 'Drag or arrow keys: rotate (on a touch screen, tap the view first; a tap outside releases it). '
  + 'Wheel, pinch or + and −: zoom. Right-drag, Shift+drag, two fingers or '
  + 'Shift+arrows: pan. F: frame everything. Tab selects draggable points; arrows then move the selected point '
  + '(Shift: bigger steps, Page Up/Down: along z); Escape deselects.';

let uid = 0;

function niceStep(range, target) {
  const raw = range / Math.max(1, target);
  const p = Math.pow(10, Math.floor(Math.log10(raw)));
  const m = raw / p;
  return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
}

function fmtTick(v, digits) {
  const s = v.toFixed(digits);
  return /^-0(\.0*)?$/.test(s) ? s.slice(1) : s;
}

// ---------------------------------------------------------------- the viewer

export class View3D {
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
    this.selected = null;   // { id, index } — keyboard selection
    this.destroyed = false;
    this.id = ++uid;
    this.touchActive = false;  // one-finger touch orbits only after a tap has activated the view
    this.axes = options.axes !== false;
    this.axesInfo = null;
    this._contentAspect = 0;

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
    canvas.setAttribute('aria-describedby', help.id);
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
    this.legend = legendElement({});
    this.legend.style.position = 'absolute';
    this.legend.style.right = '8px';
    this.legend.style.top = '8px';
    this.legend.style.pointerEvents = 'none';
    this.legend.hidden = true;
    wrap.append(canvas, overlay, labels, this.legend, tapHint, help, live);
    parent.appendChild(wrap);

    this.gl = null;
    if (!options.disableWebGL) {
      try {
        this.gl = canvas.getContext('webgl2', { antialias: true, premultipliedAlpha: true, preserveDrawingBuffer: true, alpha: false });
      } catch { this.gl = null; }
    }
    if (this.gl) {
      try { this._initGL(); } catch (e) { this.gl = null; this._glError = e; }
    }
    if (!this.gl) this._showFallback();

    this._bind();
    this._resizeObserver = typeof ResizeObserver === 'function' ? new ResizeObserver(() => { this._sizeCanvas(); this.render(); }) : null;
    this._sizeCanvas();
    this._resizeObserver?.observe(wrap);
    this.render();
  }

  /** Is this a touch-first device (coarse pointer, no hover)? Decides whether "Tap to rotate" shows up front. */
  static touchDevice() {
    try { return typeof matchMedia === 'function' && matchMedia('(hover: none) and (pointer: coarse)').matches; } catch { return false; }
  }

  /**
   * The canvas height: the `height` option on wide screens; on narrow ones (< 640 px) it follows the width (the
   * content's aspect after fit(), between 0.55 and 1.1 times the width, never above `height`).
   */
  _sizeCanvas() {
    if (this.destroyed) return;
    const w = this.element.clientWidth;
    let h = this.height;
    if (w > 0 && w < 640) {
      const k = this._contentAspect > 0 ? 1.3 / this._contentAspect : 0.85;
      h = Math.round(Math.min(this.height, w * Math.min(1.1, Math.max(0.72, k))));
    }
    if (this.canvas.style.height !== `${h}px`) this.canvas.style.height = `${h}px`;
  }

  /** Touch: activates one-finger orbiting (after a tap) or gives one-finger swipes back to the page. */
  setTouchActive(on) {
    on = !!on;
    if (this.destroyed || on === this.touchActive) return;
    this.touchActive = on;
    this.canvas.style.touchAction = on ? 'none' : 'pan-y';
    this.tapHint.hidden = on;
    this.element.classList.toggle('touch-active', on);
    if (on) this._hint('One finger rotates; tap outside the view to scroll');
  }

  /** Shows or hides the axes with tick values (the bounding box's front and bottom edges). */
  showAxes(on = true) { this.axes = !!on; this.render(); }

  /** true when WebGL2 works here. */
  get supported() { return !!this.gl; }

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

  _initGL() {
    const gl = this.gl;
    const compile = (type, src) => {
      const s = gl.createShader(type);
      gl.shaderSource(s, src);
      gl.compileShader(s);
      if (!gl.getShaderParameter(s, gl.COMPILE_STATUS) && !gl.isContextLost()) throw new Error('shader: ' + gl.getShaderInfoLog(s));
      return s;
    };
    const program = (vs, fs, uniforms) => {
      const p = gl.createProgram();
      gl.attachShader(p, compile(gl.VERTEX_SHADER, vs));
      gl.attachShader(p, compile(gl.FRAGMENT_SHADER, fs));
      gl.linkProgram(p);
      if (!gl.getProgramParameter(p, gl.LINK_STATUS) && !gl.isContextLost()) throw new Error('program: ' + gl.getProgramInfoLog(p));
      const u = {};
      for (const name of uniforms) u[name] = gl.getUniformLocation(p, name);
      return { p, u };
    };
    this.prog = {
      mesh: program(MESH_VS, MESH_FS, ['uView', 'uProj', 'uRange', 'uColor', 'uOpacity', 'uUseMap', 'uMap']),
      line: program(LINE_VS, FLAT_FS, ['uView', 'uProj', 'uViewport', 'uWidth', 'uBias', 'uColor']),
      point: program(POINT_VS, POINT_FS, ['uView', 'uProj', 'uSize', 'uHighlight']),
    };
    this.cornerBuf = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, this.cornerBuf);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([0, -1, 1, -1, 1, 1, 0, -1, 1, 1, 0, 1]), gl.STATIC_DRAW);
    this.maps = {};
    const pr = gl.getParameter(gl.ALIASED_POINT_SIZE_RANGE);
    this.maxPointSize = pr ? pr[1] : 64;
    for (const obj of this.objects.values()) obj.gpu = null;
  }

  _mapTexture(name) {
    const gl = this.gl;
    if (this.maps[name]) return this.maps[name];
    const tex = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, tex);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 256, 1, 0, gl.RGBA, gl.UNSIGNED_BYTE, colormapLUT(name, 256));
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    return (this.maps[name] = tex);
  }

  _segmentVAO(segs) {
    const gl = this.gl;
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.cornerBuf);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
    const buf = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, buf);
    gl.bufferData(gl.ARRAY_BUFFER, segs, gl.STATIC_DRAW);
    gl.enableVertexAttribArray(1);
    gl.vertexAttribPointer(1, 3, gl.FLOAT, false, 24, 0);
    gl.vertexAttribDivisor(1, 1);
    gl.enableVertexAttribArray(2);
    gl.vertexAttribPointer(2, 3, gl.FLOAT, false, 24, 12);
    gl.vertexAttribDivisor(2, 1);
    gl.bindVertexArray(null);
    return { vao, buffers: [buf], count: segs.length / 6 };
  }

  _upload(obj) {
    const gl = this.gl;
    const buffer = (data, target = gl.ARRAY_BUFFER) => {
      const b = gl.createBuffer();
      gl.bindBuffer(target, b);
      gl.bufferData(target, data, gl.STATIC_DRAW);
      return b;
    };
    const gpu = { parts: [] };
    if (obj.kind === 'mesh') {
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      const pb = buffer(obj.positions);
      gl.enableVertexAttribArray(0); gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 0, 0);
      const nb = buffer(obj.normals);
      gl.enableVertexAttribArray(1); gl.vertexAttribPointer(1, 3, gl.FLOAT, false, 0, 0);
      const bufs = [pb, nb];
      if (obj.scalars) {
        bufs.push(buffer(obj.scalars));
        gl.enableVertexAttribArray(2); gl.vertexAttribPointer(2, 1, gl.FLOAT, false, 0, 0);
      } else {
        gl.disableVertexAttribArray(2);
      }
      bufs.push(buffer(obj.indices, gl.ELEMENT_ARRAY_BUFFER));
      gl.bindVertexArray(null);
      gpu.vao = vao; gpu.buffers = bufs; gpu.count = obj.indices.length;
      for (const ov of obj.overlays) gpu.parts.push({ ...this._segmentVAO(ov.segs), style: ov });
    } else if (obj.kind === 'lines') {
      gpu.parts.push({ ...this._segmentVAO(obj.segs), style: obj.style });
    } else if (obj.kind === 'points') {
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      const pb = buffer(obj.positions);
      gl.enableVertexAttribArray(0); gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 0, 0);
      const bufs = [pb];
      if (obj.colors) {
        bufs.push(buffer(obj.colors));
        gl.enableVertexAttribArray(1); gl.vertexAttribPointer(1, 3, gl.FLOAT, false, 0, 0);
      } else gl.disableVertexAttribArray(1);
      gl.bindVertexArray(null);
      gpu.vao = vao; gpu.buffers = bufs; gpu.count = obj.positions.length / 3;
    }
    obj.gpu = gpu;
  }

  _free(obj) {
    const gl = this.gl, gpu = obj.gpu;
    obj.gpu = null;
    if (!gl || !gpu || gl.isContextLost()) return;
    if (gpu.vao) gl.deleteVertexArray(gpu.vao);
    for (const b of gpu.buffers || []) gl.deleteBuffer(b);
    for (const part of gpu.parts) { gl.deleteVertexArray(part.vao); part.buffers.forEach((b) => gl.deleteBuffer(b)); }
  }

  _put(id, obj) {
    if (this.destroyed) return;
    const old = this.objects.get(id);
    if (old) this._free(old);
    obj.order = old ? old.order : this.objects.size;
    this.objects.set(id, obj);
    this._updateLegend();
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
   * to that axis), onDrag(index, [x, y, z], phase), pickable (default: true), onTop = true (visible through
   * surfaces), visible = true }.
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
      pickable: opts.pickable !== false, onTop: opts.onTop !== false,
    });
    if (this.selected?.id === id && this.selected.index >= n) this.selected = null;
    this._syncLabels();
  }

  /**
   * Coordinate axes as three labelled arrows-free lines from `origin` (default: the corner of the scene's bounding
   * box, or [0, 0, 0]) with length `length` (default: the box's largest side): x red-orange, y green, z blue
   * (Okabe–Ito). `setAxes(false)` removes them.
   */
  setAxes(show = true, { origin, length } = {}) {
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

  /** Shows or hides an object without re-uploading it. */
  setVisible(id, visible) {
    const o = this.objects.get(id);
    if (o) { o.visible = !!visible; this._updateLegend(); this.render(); }
  }

  /** Removes an object (no error when it does not exist). */
  remove(id) {
    const o = this.objects.get(id);
    if (!o) return;
    this._free(o);
    this.objects.delete(id);
    if (this.selected?.id === id) this.selected = null;
    if (this.hover?.id === id) this.hover = null;
    this._updateLegend();
    this._syncLabels();
    this.render();
  }

  /** Removes everything. */
  clear() { for (const id of [...this.objects.keys()]) this.remove(id); }

  /** Positions of a point set (a copy, flat xyz), e.g. after dragging. */
  getPoints(id) { const o = this.objects.get(id); return o?.kind === 'points' ? Float64Array.from(o.positions) : null; }

  /** Canvas position [x, y] (CSS px from the canvas's top-left corner) of point `index` of set `id`, or null. */
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
   */
  onPick(callback) { this.pickListeners.push(callback); return () => { this.pickListeners = this.pickListeners.filter((f) => f !== callback); }; }

  /** `callback({ id, index, position, phase })` while a draggable point moves (phase 'start' | 'move' | 'end'). */
  onDrag(callback) { this.dragListeners.push(callback); return () => { this.dragListeners = this.dragListeners.filter((f) => f !== callback); }; }

  /** `callback(view)` after the user changed the camera (for saving it in the state). */
  onViewChange(callback) { this.viewListeners.push(callback); return () => { this.viewListeners = this.viewListeners.filter((f) => f !== callback); }; }

  /** Locks (no point dragging) or unlocks the view. */
  setLocked(locked) { this.locked = !!locked; }

  /** Frames everything visible: the camera target moves to the centre, the distance fits the bounding sphere. */
  fit() {
    const b = this._sceneBox();
    this._needsFit = !b;
    if (!b) { this.render(); return; }
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
    this._cameraMoved();
  }

  /** Back to the default direction, framing everything. */
  resetView() { this.yaw = DEFAULT_VIEW.yaw; this.pitch = DEFAULT_VIEW.pitch; this.fit(); this._viewChanged(); }

  /** The camera as plain JSON: { yaw, pitch (degrees), distance, target: [x, y, z] }. */
  getView() {
    const r = (v) => Number(v.toPrecision(6));
    return { yaw: r(this.yaw / DEG), pitch: r(this.pitch / DEG), distance: r(this.distance), target: this.target.map(r) };
  }

  /** Restores a camera from `getView()` output; invalid fields are ignored (returns false when nothing was usable). */
  setView(v) {
    if (!v || typeof v !== 'object') return false;
    let ok = false;
    if (Number.isFinite(v.yaw)) { this.yaw = v.yaw * DEG; ok = true; }
    if (Number.isFinite(v.pitch)) { this.pitch = Math.max(-89, Math.min(89, v.pitch)) * DEG; ok = true; }
    if (Number.isFinite(v.distance) && v.distance > 0 && v.distance < 1e12) { this.distance = v.distance; ok = true; }
    if (Array.isArray(v.target) && v.target.length === 3 && v.target.every(Number.isFinite)) { this.target = v.target.slice(); ok = true; }
    if (ok) { this._needsFit = false; this._cameraMoved(); }
    return ok;
  }

  /** Schedules one redraw on the next animation frame (calls coalesce). */
  render() {
    if (this.destroyed || this._raf) return;
    this._raf = requestAnimationFrame(() => { this._raf = 0; this.renderNow(); });
  }

  /** A PNG data URL of the current view (drawn synchronously first). */
  toDataURL() { this.renderNow(); return this.canvas.toDataURL('image/png'); }

  /** Removes the element, listeners, animation frame and GPU resources. */
  destroy() {
    if (this.destroyed) return;
    for (const o of this.objects.values()) this._free(o);
    this.destroyed = true;
    if (this._links) { this._links.delete(this); this._links = null; }
    if (this._raf) cancelAnimationFrame(this._raf);
    this._raf = 0;
    clearTimeout(this._hintTimer);
    clearTimeout(this._wheelTimer);
    this._resizeObserver?.disconnect();
    for (const [target, type, fn, opt] of this._listeners) target.removeEventListener(type, fn, opt);
    this.gl?.getExtension('WEBGL_lose_context')?.loseContext();
    this.gl = null;
    this.objects.clear();
    this.element.remove();
  }

  // ---------------------------------------------------------------- camera

  _aspect() {
    const w = this.canvas.clientWidth || 1, h = this.canvas.clientHeight || 1;
    return w / h;
  }

  _camera() {
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

  _sceneBox() {
    let lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity], any = false;
    for (const o of this.objects.values()) {
      if (!o.visible || !o.bbox) continue;
      any = true;
      for (let k = 0; k < 3; k++) { lo[k] = Math.min(lo[k], o.bbox.lo[k]); hi[k] = Math.max(hi[k], o.bbox.hi[k]); }
    }
    return any ? { lo, hi } : null;
  }

  /** What the axes measure: the box of the visible surfaces (control nets may reach far out), else of everything. */
  _axesBox() {
    let lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity], any = false;
    for (const o of this.objects.values()) {
      if (o.kind !== 'mesh' || !o.visible || !o.bbox) continue;
      any = true;
      for (let k = 0; k < 3; k++) { lo[k] = Math.min(lo[k], o.bbox.lo[k]); hi[k] = Math.max(hi[k], o.bbox.hi[k]); }
    }
    return any ? { lo, hi } : this._sceneBox();
  }

  _updateScene() {
    const b = this._sceneBox();
    if (!b) return;
    this.sceneCenter = scale(add(b.lo, b.hi), 0.5);
    const r = Math.hypot(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]) / 2;
    this.sceneRadius = r > 1e-12 ? r : 1;
  }

  _orbit(dyaw, dpitch) {
    this.yaw += dyaw;
    this.pitch = Math.max(-89 * DEG, Math.min(89 * DEG, this.pitch + dpitch));
    this._cameraMoved();
  }

  _zoom(factor) {
    this.distance = Math.min(Math.max(this.distance * factor, this.sceneRadius * 0.02), this.sceneRadius * 200);
    this._cameraMoved();
  }

  /** Redraws, and copies the camera to the linked views (see `linkViews`). */
  _cameraMoved() {
    this.render();
    if (!this._links || this._syncing) return;
    for (const v of this._links) {
      if (v === this || v.destroyed) continue;
      v._syncing = true;
      v.yaw = this.yaw; v.pitch = this.pitch; v.distance = this.distance; v.target = this.target.slice();
      v._needsFit = false;
      v.render();
      v._syncing = false;
    }
  }

  /** Pans by a screen offset in CSS pixels. */
  _pan(dx, dy) {
    const cam = this._camera();
    const h = this.canvas.clientHeight || 1;
    const perPx = (2 * this.distance * Math.tan(FOV / 2)) / h;
    this.target = add(this.target, add(scale(cam.right, -dx * perPx), scale(cam.up, dy * perPx)));
    this._cameraMoved();
  }

  _viewChanged() {
    const v = this.getView();
    for (const f of this.viewListeners) { try { f(v); } catch (e) { console.error(e); } }
  }

  /** World ray through a canvas position (CSS px). */
  _ray(x, y, cam = this._camera()) {
    const w = this.canvas.clientWidth || 1, h = this.canvas.clientHeight || 1;
    const nx = (2 * x) / w - 1, ny = 1 - (2 * y) / h;
    const t = Math.tan(FOV / 2);
    const dir = norm(add(cam.forward, add(scale(cam.right, nx * t * (w / h)), scale(cam.up, ny * t))));
    return { origin: cam.eye, dir };
  }

  /** Canvas position (CSS px) of a world point, or null behind the camera. */
  _project(p, cam) {
    const e = xform(cam.view, p[0], p[1], p[2]);
    const c = xform(cam.proj, e[0], e[1], e[2]);
    if (c[3] <= 1e-9) return null;
    const w = this.canvas.clientWidth || 1, h = this.canvas.clientHeight || 1;
    return [((c[0] / c[3]) * 0.5 + 0.5) * w, (1 - ((c[1] / c[3]) * 0.5 + 0.5)) * h];
  }

  /**
   * The nearest point of a pickable mesh under a canvas position (CSS px): { id, kind: 'surface', position,
   * triangle (index), vertex (the triangle's vertex nearest the hit), iu, iv (that vertex's grid indices for a
   * u-major nu × nv mesh, else undefined) }, or null.
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
          best = { id, kind: 'surface', triangle: t / 3, vertex, position: add(O, scale(D, dist)) };
          if (o.grid) { best.iu = Math.floor(vertex / o.grid[1]); best.iv = vertex % o.grid[1]; }
        }
      }
    }
    return best;
  }

  /** The nearest pickable point under a canvas position, within its radius plus `slack` px. */
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

  renderNow() {
    if (this.destroyed) return;
    if (this._raf) { cancelAnimationFrame(this._raf); this._raf = 0; }
    const canvas = this.canvas;
    const dpr = Math.min(window.devicePixelRatio || 1, 2);
    const cw = canvas.clientWidth, ch = canvas.clientHeight;
    const W = Math.max(1, Math.round(cw * dpr)), H = Math.max(1, Math.round(ch * dpr));
    if (canvas.width !== W || canvas.height !== H) { canvas.width = W; canvas.height = H; }
    this._updateScene();
    if (this._needsFit && this._sceneBox() && cw > 0) { this._needsFit = false; this.fit(); }
    const gl = this.gl;
    if (!gl || gl.isContextLost()) { this._syncLabels(); return; }
    const cam = this._camera();
    gl.viewport(0, 0, W, H);
    const bg = this.background;
    gl.clearColor(bg[0], bg[1], bg[2], 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LEQUAL);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
    gl.disable(gl.CULL_FACE);

    const objs = [...this.objects.values()].filter((o) => o.visible).sort((a, b) => a.order - b.order);
    for (const o of objs) if (!o.gpu) this._upload(o);
    const meshes = objs.filter((o) => o.kind === 'mesh');
    const opaque = meshes.filter((o) => o.opacity >= 1), clear = meshes.filter((o) => o.opacity < 1);

    // surfaces (pushed back a little so lines lying on them win the depth test)
    const mp = this.prog.mesh;
    gl.useProgram(mp.p);
    gl.uniformMatrix4fv(mp.u.uView, false, cam.view);
    gl.uniformMatrix4fv(mp.u.uProj, false, cam.proj);
    gl.uniform1i(mp.u.uMap, 0);
    gl.enable(gl.POLYGON_OFFSET_FILL);
    gl.polygonOffset(1, 1);
    const drawMesh = (o) => {
      gl.uniform3fv(mp.u.uColor, o.color);
      gl.uniform1f(mp.u.uOpacity, o.opacity);
      gl.uniform1i(mp.u.uUseMap, o.scalars ? 1 : 0);
      gl.uniform2f(mp.u.uRange, o.range ? o.range[0] : 0, o.range ? o.range[1] : 1);
      if (o.scalars) { gl.activeTexture(gl.TEXTURE0); gl.bindTexture(gl.TEXTURE_2D, this._mapTexture(o.colormap)); }
      gl.bindVertexArray(o.gpu.vao);
      if (!o.scalars) gl.vertexAttrib1f(2, 0);
      gl.drawElements(gl.TRIANGLES, o.gpu.count, gl.UNSIGNED_INT, 0);
    };
    gl.depthMask(true);
    opaque.forEach(drawMesh);
    gl.disable(gl.POLYGON_OFFSET_FILL);

    // lines: mesh overlays and line sets
    const lp = this.prog.line;
    gl.useProgram(lp.p);
    gl.uniformMatrix4fv(lp.u.uView, false, cam.view);
    gl.uniformMatrix4fv(lp.u.uProj, false, cam.proj);
    gl.uniform2f(lp.u.uViewport, W, H);
    const drawPart = (part, bias) => {
      if (!part.count) return;
      const s = part.style;
      gl.uniform1f(lp.u.uWidth, s.width * dpr);
      gl.uniform1f(lp.u.uBias, bias);
      gl.uniform4f(lp.u.uColor, s.color[0], s.color[1], s.color[2], s.alpha);
      gl.bindVertexArray(part.vao);
      gl.drawArraysInstanced(gl.TRIANGLES, 0, 6, part.count);
    };
    for (const o of objs) {
      if (o.kind === 'mesh' && o.opacity >= 1) o.gpu.parts.forEach((p) => drawPart(p, 0.0005));
      if (o.kind === 'lines') o.gpu.parts.forEach((p) => drawPart(p, 0.001));
    }

    // translucent surfaces: no depth writes, drawn after everything opaque
    if (clear.length) {
      gl.useProgram(mp.p);
      gl.depthMask(false);
      clear.forEach(drawMesh);
      gl.useProgram(lp.p);
      for (const o of clear) o.gpu.parts.forEach((p) => drawPart(p, 0.0005));
      gl.depthMask(true);
    }

    // points
    const pp = this.prog.point;
    gl.useProgram(pp.p);
    gl.uniformMatrix4fv(pp.u.uView, false, cam.view);
    gl.uniformMatrix4fv(pp.u.uProj, false, cam.proj);
    const hl = this.dragging || this.selected || this.hover;
    for (const [id, o] of this.objects) {
      if (o.kind !== 'points' || !o.visible || !o.gpu.count) continue;
      if (o.onTop) gl.disable(gl.DEPTH_TEST); else gl.enable(gl.DEPTH_TEST);
      gl.bindVertexArray(o.gpu.vao);
      if (!o.colors) gl.vertexAttrib3fv(1, o.color);
      const size = Math.min(o.size * dpr, this.maxPointSize);
      gl.uniform1f(pp.u.uSize, size);
      gl.uniform1f(pp.u.uHighlight, 0);
      gl.drawArrays(gl.POINTS, 0, o.gpu.count);
      if (hl && hl.id === id && hl.index < o.gpu.count) {
        gl.uniform1f(pp.u.uSize, Math.min(size * 1.45, this.maxPointSize));
        gl.uniform1f(pp.u.uHighlight, 1);
        gl.drawArrays(gl.POINTS, hl.index, 1);
      }
    }
    gl.enable(gl.DEPTH_TEST);
    gl.bindVertexArray(null);
    this._drawAxes(cam, cw, ch, dpr);
    this._syncLabels(cam);
  }

  /** The scene box's front/bottom edges with tick values, on the 2D overlay canvas. */
  _drawAxes(cam, cw, ch, dpr) {
    const ov = this.overlay;
    const W = Math.max(1, Math.round(cw * dpr)), H = Math.max(1, Math.round(ch * dpr));
    if (ov.width !== W || ov.height !== H) { ov.width = W; ov.height = H; }
    ov.style.width = `${cw}px`; ov.style.height = `${ch}px`;
    const g = ov.getContext('2d');
    if (!g) return;
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.clearRect(0, 0, cw, ch);
    this.axesInfo = null;
    const b = this.axes ? this._axesBox() : null;
    if (!b) return;
    const ext = [0, 1, 2].map((k) => b.hi[k] - b.lo[k]);
    const big = Math.max(...ext);
    if (!(big > 0)) return;
    const corner = (ix, iy, iz) => [ix ? b.hi[0] : b.lo[0], iy ? b.hi[1] : b.lo[1], iz ? b.hi[2] : b.lo[2]];
    const centre = this._project(scale(add(b.lo, b.hi), 0.5), cam);
    if (!centre) return;
    const info = {};
    g.lineWidth = 1;
    g.font = '12px system-ui, sans-serif';
    for (const k of [0, 1, 2]) {
      if (!(ext[k] > big * 1e-6)) continue;             // a flat direction has no axis
      // the four edges along axis k; x and y use the lowest one on screen, z the leftmost one
      let best = null;
      for (const a of [0, 1]) for (const c of [0, 1]) {
        const idx = (t) => { const q = [0, 0, 0]; q[k] = t; q[(k + 1) % 3] = a; q[(k + 2) % 3] = c; return q; };
        const p0 = corner(...idx(0)), p1 = corner(...idx(1));
        const s0 = this._project(p0, cam), s1 = this._project(p1, cam);
        if (!s0 || !s1) continue;
        const mid = [(s0[0] + s1[0]) / 2, (s0[1] + s1[1]) / 2];
        // prefer the edge that is most inside the canvas, then the lowest (x, y) or leftmost (z) one
        let inside = 0, qa = -1, qb = -1;
        for (let q = 0; q <= 10; q++) {
          const X = s0[0] + (s1[0] - s0[0]) * q / 10, Y = s0[1] + (s1[1] - s0[1]) * q / 10;
          if (X >= 4 && Y >= 4 && X <= cw - 4 && Y <= ch - 4) { inside++; if (qa < 0) qa = q; qb = q; }
        }
        const score = Math.min(inside, 7) * 1e5 + (k === 2 ? -mid[0] : mid[1]);
        // the axis name goes beside the middle of the part that is on screen
        const f = qa < 0 ? 0.5 : (qa + qb) / 20;
        const vis = [s0[0] + (s1[0] - s0[0]) * f, s0[1] + (s1[1] - s0[1]) * f];
        if (!best || score > best.score) best = { score, p0, p1, s0, s1, mid, vis };
      }
      if (!best) continue;
      const len = Math.hypot(best.s1[0] - best.s0[0], best.s1[1] - best.s0[1]);
      if (len < 24) continue;                            // seen end-on: no room for ticks
      let out = [best.mid[0] - centre[0], best.mid[1] - centre[1]];
      const ol = Math.hypot(out[0], out[1]);
      // ticks point away from the box, perpendicular to the edge on screen
      const dir = [(best.s1[0] - best.s0[0]) / len, (best.s1[1] - best.s0[1]) / len];
      let nrm = [-dir[1], dir[0]];
      if (ol > 1e-6 && nrm[0] * out[0] + nrm[1] * out[1] < 0) nrm = [-nrm[0], -nrm[1]];
      if (ol <= 1e-6) nrm = [0, 1];
      const step = niceStep(ext[k], Math.max(2, Math.min(6, len / 70)));
      const digits = Math.max(0, Math.min(8, -Math.floor(Math.log10(step) + 1e-9)));
      g.strokeStyle = '#8a8a8a';
      g.beginPath(); g.moveTo(best.s0[0], best.s0[1]); g.lineTo(best.s1[0], best.s1[1]); g.stroke();
      g.fillStyle = '#333';
      g.textAlign = Math.abs(nrm[0]) < 0.35 ? 'center' : nrm[0] > 0 ? 'left' : 'right';
      g.textBaseline = Math.abs(nrm[1]) < 0.35 ? 'middle' : nrm[1] > 0 ? 'top' : 'bottom';
      const ticks = [];
      const lo = b.lo[k], hi = b.hi[k];
      for (let v = Math.ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step) {
        const p = best.p0.slice(); p[k] = v;
        const s = this._project(p, cam);
        if (!s || s[0] < 0 || s[1] < 0 || s[0] > cw || s[1] > ch) continue;
        g.beginPath(); g.moveTo(s[0], s[1]); g.lineTo(s[0] + nrm[0] * 5, s[1] + nrm[1] * 5); g.stroke();
        const text = fmtTick(v, digits);
        g.lineWidth = 3; g.strokeStyle = 'rgba(255,255,255,0.85)'; g.strokeText(text, s[0] + nrm[0] * 8, s[1] + nrm[1] * 8);
        g.fillText(text, s[0] + nrm[0] * 8, s[1] + nrm[1] * 8);
        g.lineWidth = 1; g.strokeStyle = '#8a8a8a';
        ticks.push({ value: Number(text), at: [s[0], s[1]] });
      }
      const name = 'xyz'[k];
      g.font = 'italic 600 14px system-ui, sans-serif';
      g.fillStyle = '#111';
      g.fillText(name, best.vis[0] + nrm[0] * 30, best.vis[1] + nrm[1] * 30);
      g.font = '12px system-ui, sans-serif';
      info[name] = { from: best.p0, to: best.p1, step, ticks };
    }
    this.axesInfo = info;
  }

  _syncLabels(cam) {
    const layer = this.labelLayer;
    const wanted = [];
    for (const o of this.objects.values()) {
      if (o.kind !== 'points' || !o.visible || !o.labels) continue;
      o.labels.forEach((text, i) => { if (text) wanted.push({ o, i, text }); });
    }
    while (layer.childNodes.length > wanted.length) layer.lastChild.remove();
    while (layer.childNodes.length < wanted.length) {
      const s = document.createElement('span');
      s.style.cssText = 'position:absolute;left:0;top:0;white-space:nowrap;padding:1px 3px;border-radius:3px;'
        + 'background:rgba(255,255,255,0.8);';
      layer.appendChild(s);
    }
    if (!wanted.length) return;
    cam = cam || this._camera();
    wanted.forEach(({ o, i, text }, k) => {
      const span = layer.childNodes[k];
      if (span.textContent !== text) span.textContent = text;
      const s = this._project([o.positions[3 * i], o.positions[3 * i + 1], o.positions[3 * i + 2]], cam);
      span.hidden = !s;
      if (s) span.style.transform = `translate(${Math.round(s[0] + o.size / 2 + 2)}px, ${Math.round(s[1] - o.size / 2 - 16)}px)`;
    });
  }

  _updateLegend() {
    let m = null;
    for (const o of this.objects.values()) if (o.kind === 'mesh' && o.visible && o.scalars && o.legend !== false) m = o;
    this.legend.hidden = !m;
    if (m) updateLegend(this.legend, { colormap: m.colormap, min: m.range[0], max: m.range[1], label: m.legend || '' });
  }

  // ---------------------------------------------------------------- interaction

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
    on(c, 'blur', () => { c.style.outline = 'none'; if (this.selected) { this.selected = null; this.render(); } });
    on(c, 'webglcontextlost', (e) => { e.preventDefault(); });
    on(c, 'webglcontextrestored', () => {
      try { this._initGL(); this.render(); } catch (err) { console.error(err); }
    });
  }

  _pos(e) {
    const r = this.canvas.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  }

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
    if ((this.canvas.getRootNode?.().activeElement ?? document.activeElement) !== this.canvas) this.canvas.focus({ preventScroll: true });
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
      this.dragging = { id: hit.id, index: hit.index, p0, n, offset: sub(grab, p0), s0: null };
      this.selected = null;
      this.canvas.style.cursor = 'grabbing';
      this._emitDrag('start', hit.position);
      this.render();
      return;
    }
    this.mode = e.button === 2 || e.shiftKey ? 'pan' : 'orbit';
    this._last = { x, y };
    this._press = hit || e.button !== 0 ? null : { x, y, moved: false };
  }

  _pinchState() {
    const [a, b] = [...this.pointers.values()];
    return { d: Math.hypot(a.x - b.x, a.y - b.y) || 1, mx: (a.x + b.x) / 2, my: (a.y + b.y) / 2 };
  }

  _move(e) {
    if (this.destroyed) return;
    const [x, y] = this._pos(e);
    if (!this.pointers.has(e.pointerId)) {
      // hover feedback (mouse / pen without buttons)
      const hit = this.pickAt(x, y);
      const dragHit = hit && this.objects.get(hit.id).draggable && !this.locked ? hit : null;
      const changed = (dragHit?.id !== this.hover?.id) || (dragHit?.index !== this.hover?.index);
      this.hover = dragHit ? { id: dragHit.id, index: dragHit.index } : null;
      this.canvas.style.cursor = dragHit ? 'pointer' : 'grab';
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

  _dragTo(x, y, constrain) {
    const d = this.dragging;
    const o = this.objects.get(d.id);
    if (!o || d.index >= o.positions.length / 3) { this.dragging = null; this.mode = null; return; }
    const cam = this._camera();
    const ray = this._ray(x, y, cam);
    let p;
    const axisName = o.axis || (constrain ? 'z' : null);
    if (axisName) {
      const A = axisName === 'x' ? [1, 0, 0] : axisName === 'y' ? [0, 1, 0] : [0, 0, 1];
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
    this._movePoint(d.id, d.index, p, 'move');
  }

  /** Parameter s of the point P0 + s·A closest to the ray. */
  _axisParam(p0, A, ray) {
    const w0 = sub(p0, ray.origin);
    const a = dot(A, A), b = dot(A, ray.dir), c = dot(ray.dir, ray.dir), d = dot(A, w0), e = dot(ray.dir, w0);
    const den = a * c - b * b;
    if (Math.abs(den) < 1e-9) return null;
    return (b * e - c * d) / den;
  }

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
    this.render();
    this._emitDrag(phase, p, id, index);
  }

  _emitDrag(phase, position, id = this.dragging?.id, index = this.dragging?.index) {
    const o = this.objects.get(id);
    const pos = [position[0], position[1], position[2]];
    try { o?.onDrag?.(index, pos, phase); } catch (e) { console.error(e); }
    for (const f of this.dragListeners) { try { f({ id, index, position: pos, phase }); } catch (e) { console.error(e); } }
  }

  _emitPick(hit) {
    for (const f of this.pickListeners) { try { f(hit); } catch (e) { console.error(e); } }
  }

  _up(e) {
    if (!this.pointers.has(e.pointerId)) return;
    this.pointers.delete(e.pointerId);
    if (this._tap && this._tap.id === e.pointerId) {
      const tap = this._tap;
      this._tap = null;
      if (e.type === 'pointerup' && !tap.moved && performance.now() - tap.t < 800) {
        this.setTouchActive(true);
        this.canvas.focus({ preventScroll: true });
      } else if (e.type === 'pointercancel') this._hint('Tap the view first to rotate it');
      if (this.pointers.size === 0) { this.mode = null; this._last = null; }
      return;
    }
    try { this.canvas.releasePointerCapture(e.pointerId); } catch { /* not captured */ }
    if (this.mode === 'drag' && this.dragging) {
      const d = this.dragging, o = this.objects.get(d.id);
      if (o && d.index < o.positions.length / 3) {
        this._emitDrag('end', [o.positions[3 * d.index], o.positions[3 * d.index + 1], o.positions[3 * d.index + 2]]);
      }
      this.dragging = null;
      this.canvas.style.cursor = 'grab';
      this.render();
    } else if (this.mode === 'orbit' && this._press && !this._press.moved && this.pointers.size === 0) {
      // a click (no drag) on the background or a surface
      const hit = this.pickSurface(this._press.x, this._press.y);
      if (hit) this._emitPick(hit);
      this._press = null;
    } else if (this.mode === 'orbit' || this.mode === 'pan' || this.mode === 'pinch') {
      this._viewChanged();
    }
    if (this.mode === 'pinch') this._press = null;
    if (this.pointers.size === 0) { this.mode = null; this._last = null; }
    else if (this.mode === 'pinch' && e.pointerType === 'touch' && !this.touchActive) { this.mode = null; this._last = null; }
    else if (this.mode === 'pinch') { this.mode = 'orbit'; const [p] = [...this.pointers.values()]; this._last = { ...p }; }
  }

  _wheel(e) {
    // Like the 2D plots: zoom only when the view has focus or with Ctrl/⌘ (trackpad pinch); otherwise the wheel
    // keeps scrolling the page, and a hint says how to zoom.
    const root = this.canvas.getRootNode ? this.canvas.getRootNode() : document;
    const focused = (root.activeElement ?? document.activeElement) === this.canvas;
    if (!(focused || e.ctrlKey || e.metaKey)) { this._hint('Click the view (or hold Ctrl) to zoom with the wheel'); return; }
    e.preventDefault();
    const unit = e.deltaMode === 1 ? 33 : e.deltaMode === 2 ? 400 : 1;
    const dy = Math.max(-200, Math.min(200, e.deltaY * unit));
    this._zoom(Math.exp(dy * 0.0015));
    clearTimeout(this._wheelTimer);
    this._wheelTimer = setTimeout(() => this._viewChanged(), 250);
  }

  _hint(text) {
    if (!this._hintEl) {
      const el = this._hintEl = document.createElement('div');
      el.setAttribute('aria-hidden', 'true');
      el.style.cssText = 'position:absolute;left:50%;bottom:10px;transform:translateX(-50%);padding:4px 10px;border-radius:4px;'
        + 'background:rgba(17,17,17,0.85);color:#fff;font:14px/1.3 system-ui,sans-serif;pointer-events:none;';
      this.element.appendChild(el);
    }
    this._hintEl.textContent = text;
    this._hintEl.hidden = false;
    clearTimeout(this._hintTimer);
    this._hintTimer = setTimeout(() => { if (this._hintEl) this._hintEl.hidden = true; }, 1500);
  }

  _draggables() {
    const list = [];
    for (const [id, o] of [...this.objects].sort((a, b) => a[1].order - b[1].order)) {
      if (o.kind === 'points' && o.visible && o.draggable) for (let i = 0; i < o.positions.length / 3; i++) list.push({ id, index: i });
    }
    return list;
  }

  _announce(text) { this.live.textContent = text; }

  _describe(sel) {
    const o = this.objects.get(sel.id);
    const p = o.positions;
    const f = (v) => Number(v.toFixed(3));
    const name = o.labels?.[sel.index] || `point ${sel.index + 1}`;
    return `${name} (${f(p[3 * sel.index])}, ${f(p[3 * sel.index + 1])}, ${f(p[3 * sel.index + 2])})`;
  }

  _key(e) {
    if (this.destroyed || e.altKey || e.ctrlKey || e.metaKey) return;
    const big = e.shiftKey;
    if (e.key === 'Tab') {
      if (this.locked) return;
      const list = this._draggables();
      if (!list.length) return;
      let k = this.selected ? list.findIndex((s) => s.id === this.selected.id && s.index === this.selected.index) : -1;
      k += e.shiftKey ? -1 : 1;
      if (this.selected == null && e.shiftKey) return;        // leaving backwards
      if (k < 0 || k >= list.length) { this.selected = null; this.render(); return; }   // let focus move on
      e.preventDefault();
      this.selected = list[k];
      this._announce(`Selected ${this._describe(this.selected)}, ${k + 1} of ${list.length}. Arrow keys move it.`);
      const o = this.objects.get(this.selected.id);
      this._emitPick({ id: this.selected.id, index: this.selected.index, position: Array.from(o.positions.subarray(3 * this.selected.index, 3 * this.selected.index + 3)) });
      this.render();
      return;
    }
    if (e.key === 'Escape' && this.selected) { e.preventDefault(); this.selected = null; this._announce('Selection cleared'); this.render(); return; }
    const arrows = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] };
    if (this.selected && (arrows[e.key] || e.key === 'PageUp' || e.key === 'PageDown')) {
      e.preventDefault();
      const sel = this.selected, o = this.objects.get(sel.id);
      if (!o) { this.selected = null; return; }
      const cam = this._camera();
      const step = this.sceneRadius * 0.02 * (big ? 5 : 1);
      let dir;
      if (e.key === 'PageUp') dir = [0, 0, 1];
      else if (e.key === 'PageDown') dir = [0, 0, -1];
      else { const [a, b] = arrows[e.key]; dir = add(scale(cam.right, a), scale(cam.up, b)); }
      if (o.axis) { const A = o.axis === 'x' ? [1, 0, 0] : o.axis === 'y' ? [0, 1, 0] : [0, 0, 1]; const s = dot(dir, A); dir = scale(A, Math.abs(s) < 1e-6 ? 0 : Math.sign(s)); }
      const cur = Array.from(o.positions.subarray(3 * sel.index, 3 * sel.index + 3));
      const p = add(cur, scale(dir, step));
      this._emitDrag('start', cur, sel.id, sel.index);
      this._movePoint(sel.id, sel.index, p, 'move');
      const now = this.objects.get(sel.id);
      if (now && sel.index < now.positions.length / 3) {
        this._emitDrag('end', Array.from(now.positions.subarray(3 * sel.index, 3 * sel.index + 3)), sel.id, sel.index);
        this._announce(this._describe(sel));
      }
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

/**
 * Links the cameras of several views (side-by-side surfaces): orbiting, zooming or panning one moves the others
 * the same way. The first view's camera is copied to the others now. Returns a function that unlinks them.
 */
export function linkViews(...views) {
  const list = views.flat().filter((v) => v instanceof View3D);
  const group = new Set(list);
  for (const v of list) { if (v._links) v._links.delete(v); v._links = group; }
  if (list.length) list[0]._cameraMoved();
  return () => { for (const v of list) { if (v._links === group) v._links = null; } group.clear(); };
}

export default View3D;
