// View3D's 2D overlays: axes with tick values, point labels and the colour-map legend.

import { updateLegend } from '../colormap.js';
import { add, scale } from './math.js';
import { localDigits } from '../i18n.js';

/** A round tick step (1, 2 or 5 × 10ⁿ) giving about `target` ticks over `range`. */
export function niceStep(range, target) {
  const raw = range / Math.max(1, target);
  const p = Math.pow(10, Math.floor(Math.log10(raw)));
  const m = raw / p;
  return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
}

/** A tick value with `digits` decimals, without a minus sign on zero. */
export function fmtTick(v, digits) {
  const s = v.toFixed(digits);
  return localDigits(/^-0(\.0*)?$/.test(s) ? s.slice(1) : s);
}

/** @typedef {import('./index.js').Viewer} Viewer */
/** Overlay methods of View3D. Installed on View3D.prototype by ./index.js. */
export class OverlayPart {
  /** What the axes measure: the box of the visible surfaces (control nets may reach far out), else of everything. @this {Viewer} */
  _axesBox() {
    let lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity], any = false;
    for (const o of this.objects.values()) {
      if (o.kind !== 'mesh' || !o.visible || !o.bbox) continue;
      any = true;
      for (let k = 0; k < 3; k++) { lo[k] = Math.min(lo[k], o.bbox.lo[k]); hi[k] = Math.max(hi[k], o.bbox.hi[k]); }
    }
    return any ? { lo, hi } : this._sceneBox();
  }

  /** The scene box's front/bottom edges with tick values, on the 2D overlay canvas. @this {Viewer} */
  _drawAxes(cam, cw, ch, dpr) {
    const ov = this.overlay;
    const W = Math.max(1, Math.round(cw * dpr)), H = Math.max(1, Math.round(ch * dpr));
    if (ov.width !== W || ov.height !== H) { ov.width = W; ov.height = H; }
    if (ov.style.width !== `${cw}px`) ov.style.width = `${cw}px`;
    if (ov.style.height !== `${ch}px`) ov.style.height = `${ch}px`;
    const g = ov.getContext('2d');
    if (!g) return;
    // the same camera, box and size draw the same axes: keep the overlay (a dragged point rarely moves the box)
    const box = this.axes ? this._axesBox() : null;
    // (screen positions need the view matrix and the projection's two scale entries; near and far do not matter)
    const key = box ? [...cam.view, cam.proj[0], cam.proj[5], ...box.lo, ...box.hi, cw, ch, dpr].join(' ') : '';
    if (key && key === this._axesKey && this.axesInfo) return;
    this._axesKey = key;
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.clearRect(0, 0, cw, ch);
    this.axesInfo = null;
    const b = box;
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

  /** @this {Viewer} */
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
      const span = /** @type {HTMLElement} */ (layer.childNodes[k]);
      if (span.textContent !== text) span.textContent = text;
      const s = this._project([o.positions[3 * i], o.positions[3 * i + 1], o.positions[3 * i + 2]], cam);
      if (span.hidden !== !s) span.hidden = !s;
      const tr = s ? `translate(${Math.round(s[0] + o.size / 2 + 2)}px, ${Math.round(s[1] - o.size / 2 - 16)}px)` : '';
      if (s && span.style.transform !== tr) span.style.transform = tr;
    });
  }

  /** @this {Viewer} */
  _updateLegend() {
    let m = null;
    for (const o of this.objects.values()) if (o.kind === 'mesh' && o.visible && o.scalars && o.legend !== false) m = o;
    if (this.legend.hidden !== !m) this.legend.hidden = !m;
    // redrawn only when what it shows changed (objects are replaced on every frame of a drag)
    const key = m ? `${m.colormap} ${m.range[0]} ${m.range[1]} ${m.legend || ''}` : '';
    if (m && key !== this._legendKey) updateLegend(this.legend, { colormap: m.colormap, min: m.range[0], max: m.range[1], label: m.legend || '' });
    this._legendKey = key;
  }

  // ---------------------------------------------------------------- interaction
}
