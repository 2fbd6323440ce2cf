// Drawing primitives of a 2D plot in world coordinates: polylines, fills, points and markers, segments, lines
// across the plot, arrows and combs. Created per plot by createPlot with its context and transform.

import { PALETTE } from './palette.js';

/**
 * The primitives drawing on `g` through the transform `sx`, `sy` (world → CSS px); `size()` → [W, H];
 * `addMarker({ x, y, r })` records a point marker of the frame (labels keep clear of it).
 */
export function createPrimitives({ g, sx, sy, size, addMarker }) {
  function strokeStyle(st = {}) {
    g.strokeStyle = st.color || PALETTE.curve;
    g.lineWidth = st.width ?? 2.5;
    g.globalAlpha = st.alpha ?? 1;
    g.setLineDash(st.dash === true ? [7, 6] : st.dash || []);
    g.lineJoin = 'round'; g.lineCap = 'round';
  }
  function done() { g.globalAlpha = 1; g.setLineDash([]); }

  /** Polyline through a flat array (Float64Array or number[]) with `stride` 2 or 3 (z ignored), or [[x,y],…]. */
  function polyline(data, st = {}) {
    const stride = st.stride || 2;
    strokeStyle(st);
    g.beginPath();
    let pen = false;
    const pt = (x, y) => {
      if (!Number.isFinite(x) || !Number.isFinite(y)) { pen = false; return; }
      const X = sx(x), Y = sy(y);
      if (pen) g.lineTo(X, Y); else { g.moveTo(X, Y); pen = true; }
    };
    if (data && data.length && Array.isArray(data[0])) for (const p of data) pt(p[0], p[1]);
    else if (data) for (let i = 0; i + 1 < data.length; i += stride) pt(data[i], data[i + 1]);
    if (st.close) g.closePath();
    if (st.fill) { g.fillStyle = st.fill; g.globalAlpha = st.fillAlpha ?? 0.2; g.fill(); g.globalAlpha = st.alpha ?? 1; }
    if (st.width !== 0) g.stroke();
    done();
  }

  /** Filled polygon (flat or [[x,y]]). `st.color`, `st.alpha` (default 0.2), `st.stride`. */
  function fill(data, st = {}) {
    polyline(data, { ...st, width: 0, close: true, fill: st.color || PALETTE.curve, fillAlpha: st.alpha ?? 0.2 });
  }

  /** Fills between a function graph (flat x,y pairs) and the line y = base. */
  function fillUnder(data, st = {}) {
    const stride = st.stride || 2, n = Math.floor(data.length / stride);
    if (n < 2) return;
    const poly = [[data[0], st.base ?? 0]];
    for (let i = 0; i < n; i++) poly.push([data[i * stride], data[i * stride + 1]]);
    poly.push([data[(n - 1) * stride], st.base ?? 0]);
    fill(poly, st);
  }

  function marker(X, Y, r, shape) {
    g.beginPath();
    markerPath(X, Y, r, shape);
  }
  /** Adds the marker's outline to the current path as a subpath of its own. */
  function markerPath(X, Y, r, shape) {
    if (shape === 'square') g.rect(X - r, Y - r, 2 * r, 2 * r);
    else if (shape === 'diamond') { g.moveTo(X, Y - r * 1.3); g.lineTo(X + r * 1.3, Y); g.lineTo(X, Y + r * 1.3); g.lineTo(X - r * 1.3, Y); g.closePath(); }
    else if (shape === 'triangle') { g.moveTo(X, Y - r * 1.3); g.lineTo(X + r * 1.2, Y + r * 0.9); g.lineTo(X - r * 1.2, Y + r * 0.9); g.closePath(); }
    else { g.moveTo(X + r, Y); g.arc(X, Y, r, 0, 2 * Math.PI); }
  }

  /** Points (flat with stride, or [[x,y]]): `radius`, `color`, `shape` ('circle'|'square'|'diamond'|'triangle'), `stroke`. */
  function points(data, st = {}) {
    const r = st.radius ?? 4, stride = st.stride || 2;
    g.fillStyle = st.color || PALETTE.ink;
    g.globalAlpha = st.alpha ?? 1;
    let one = (x, y) => {
      if (!Number.isFinite(x) || !Number.isFinite(y)) return;
      marker(sx(x), sy(y), r, st.shape);
      addMarker({ x: sx(x), y: sy(y), r: r + 1 });
      if (st.hollow) { g.fillStyle = '#fff'; g.fill(); g.strokeStyle = st.color || PALETTE.ink; g.lineWidth = 2; g.stroke(); g.fillStyle = st.color || PALETTE.ink; }
      else { g.fill(); if (st.stroke) { g.strokeStyle = st.stroke; g.lineWidth = 1.5; g.stroke(); } }
    };
    // opaque filled markers without an outline: one path and one fill for all (the same pixels as one fill per
    // marker, apart from anti-aliasing where markers overlap; 2000 data points painted in ~1/10 of the time)
    const batch = !st.hollow && !st.stroke && g.globalAlpha === 1;
    if (batch) {
      g.beginPath();
      one = (x, y) => {
        if (!Number.isFinite(x) || !Number.isFinite(y)) return;
        const X = sx(x), Y = sy(y);
        markerPath(X, Y, r, st.shape);
        addMarker({ x: X, y: Y, r: r + 1 });
      };
    }
    if (data && data.length && Array.isArray(data[0])) for (const p of data) one(p[0], p[1]);
    else if (data) for (let i = 0; i + 1 < data.length; i += stride) one(data[i], data[i + 1]);
    if (batch) g.fill();
    g.globalAlpha = 1;
  }

  /** Straight segment in world coordinates. */
  function segment(x0, y0, x1, y1, st = {}) {
    strokeStyle({ width: 1.5, ...st });
    g.beginPath(); g.moveTo(sx(x0), sy(y0)); g.lineTo(sx(x1), sy(y1)); g.stroke();
    done();
  }
  /** Vertical line across the plot at world x. */
  function vline(x, st = {}) { strokeStyle({ width: 1.5, ...st }); g.beginPath(); g.moveTo(Math.round(sx(x)) + 0.5, 0); g.lineTo(Math.round(sx(x)) + 0.5, size()[1]); g.stroke(); done(); }
  /** Horizontal line across the plot at world y. */
  function hline(y, st = {}) { strokeStyle({ width: 1.5, ...st }); g.beginPath(); g.moveTo(0, Math.round(sy(y)) + 0.5); g.lineTo(size()[0], Math.round(sy(y)) + 0.5); g.stroke(); done(); }

  /** Arrow from (x0,y0) to (x1,y1) world; `head` px (default 10). */
  function arrow(x0, y0, x1, y1, st = {}) {
    const X0 = sx(x0), Y0 = sy(y0), X1 = sx(x1), Y1 = sy(y1);
    const len = Math.hypot(X1 - X0, Y1 - Y0);
    if (!(len > 0.5)) return;
    strokeStyle({ width: 2, ...st });
    g.beginPath(); g.moveTo(X0, Y0); g.lineTo(X1, Y1); g.stroke();
    const hd = Math.min(st.head ?? 10, len * 0.6), a = Math.atan2(Y1 - Y0, X1 - X0);
    g.setLineDash([]);
    g.fillStyle = st.color || PALETTE.curve;
    g.beginPath(); g.moveTo(X1, Y1);
    g.lineTo(X1 - hd * Math.cos(a - 0.4), Y1 - hd * Math.sin(a - 0.4));
    g.lineTo(X1 - hd * Math.cos(a + 0.4), Y1 - hd * Math.sin(a + 0.4));
    g.closePath(); g.fill();
    done();
  }

  /**
   * A comb (e.g. curvature comb): for each point p_i (flat, stride) a tooth to p_i + scale·v_i (flat vectors,
   * same stride), and the envelope through the tooth tips. `color`, `scale` (default 1), `envelope` (default true).
   */
  function comb(pts, vecs, st = {}) {
    const stride = st.stride || 2, scale = st.scale ?? 1;
    const n = Math.min(Math.floor(pts.length / stride), Math.floor(vecs.length / stride));
    const every = Math.max(1, st.every || 1);
    strokeStyle({ width: 1, color: PALETTE.second, alpha: 0.8, ...st });
    g.beginPath();
    for (let i = 0; i < n; i += every) {
      const x = pts[i * stride], y = pts[i * stride + 1];
      const tx = x + scale * vecs[i * stride], ty = y + scale * vecs[i * stride + 1];
      if (!Number.isFinite(tx + ty + x + y)) continue;
      g.moveTo(sx(x), sy(y)); g.lineTo(sx(tx), sy(ty));
    }
    g.stroke();
    if (st.envelope !== false) {
      g.lineWidth = 1.5;
      g.beginPath();
      let pen = false;
      for (let i = 0; i < n; i++) {
        const tx = pts[i * stride] + scale * vecs[i * stride], ty = pts[i * stride + 1] + scale * vecs[i * stride + 1];
        if (!Number.isFinite(tx + ty)) { pen = false; continue; }
        if (pen) g.lineTo(sx(tx), sy(ty)); else { g.moveTo(sx(tx), sy(ty)); pen = true; }
      }
      g.stroke();
    }
    done();
  }

  return { strokeStyle, done, polyline, fill, fillUnder, marker, points, segment, vline, hline, arrow, comb };
}
