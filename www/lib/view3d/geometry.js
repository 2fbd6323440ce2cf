// Geometry preparation for View3D: colours, flat xyz arrays, polylines to segments, bounding boxes,
// vertex normals, wireframe and isoparametric line segments of a u-major grid mesh.

import { cross } from './math.js';

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
export function toXYZ(data, what) {
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

export function isPointList(a) {
  return Array.isArray(a) && a.length > 0 && a.every((p) => Array.isArray(p) && p.length >= 2 && p.length <= 3 && typeof p[0] === 'number');
}

/** Polylines → flat segment list [ax, ay, az, bx, by, bz, …]; NaN points break a polyline. */
export function segmentsOf(polylines) {
  let list;
  if (ArrayBuffer.isView(polylines) || (Array.isArray(polylines) && typeof polylines[0] === 'number')) list = [polylines];
  else if (isPointList(polylines)) list = [polylines];
  else if (Array.isArray(polylines)) list = polylines;
  else throw new Error('polylines: expected an array of flat xyz arrays');
  // flat arrays are read in place (no Float32 copy first); two passes: count, then fill one Float32Array
  const flat = list.map((p, k) => (ArrayBuffer.isView(p) || (Array.isArray(p) && (p.length === 0 || typeof p[0] === 'number')) ? checkXYZ(p, `polylines[${k}]`) : toXYZ(p, `polylines[${k}]`)));
  const finite = (p, i) => Number.isFinite(p[i]) && Number.isFinite(p[i + 1]) && Number.isFinite(p[i + 2]);
  let count = 0;
  for (const p of flat) for (let i = 0; i + 5 < p.length; i += 3) if (finite(p, i) && finite(p, i + 3)) count++;
  const segs = new Float32Array(6 * count);
  let o = 0;
  for (const p of flat) {
    for (let i = 0; i + 5 < p.length; i += 3) {
      if (!(finite(p, i) && finite(p, i + 3))) continue;
      for (let j = 0; j < 6; j++) segs[o + j] = p[i + j];
      o += 6;
    }
  }
  return segs;
}

function checkXYZ(data, what) {
  if (data.length % 3 !== 0) throw new Error(`${what}: a flat xyz array needs a length divisible by 3, got ${data.length}`);
  return data;
}

export function bboxOf(xyz) {
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

export function wireframeSegments(pos, idx) {
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
export function isolineSegments(pos, nu, nv, ku, kv) {
  const keep = (i, n, k) => i % k === 0 || i === n - 1;
  let lines = 0;
  for (let iu = 0; iu < nu; iu++) if (keep(iu, nu, ku)) lines += nv - 1;
  for (let iv = 0; iv < nv; iv++) if (keep(iv, nv, kv)) lines += nu - 1;
  const segs = new Float32Array(6 * lines);
  let o = 0;
  const put = (a, b) => {
    segs[o] = pos[a]; segs[o + 1] = pos[a + 1]; segs[o + 2] = pos[a + 2];
    segs[o + 3] = pos[b]; segs[o + 4] = pos[b + 1]; segs[o + 5] = pos[b + 2];
    o += 6;
  };
  for (let iu = 0; iu < nu; iu++) {
    if (!keep(iu, nu, ku)) continue;
    for (let iv = 0; iv + 1 < nv; iv++) put(3 * (iu * nv + iv), 3 * (iu * nv + iv + 1));
  }
  for (let iv = 0; iv < nv; iv++) {
    if (!keep(iv, nv, kv)) continue;
    for (let iu = 0; iu + 1 < nu; iu++) put(3 * (iu * nv + iv), 3 * ((iu + 1) * nv + iv));
  }
  return segs;
}
