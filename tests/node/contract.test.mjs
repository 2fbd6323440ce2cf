// Independent audit of the public JS API against /work/shared/spec/api.md, curves.md and surfaces.md.
// Every expectation below is written from the contract text and the specs, with small plain-JS reference
// implementations (Cox–de Boor, de Casteljau, the quasi-cubic basis of curves.md §1, …); nothing is taken from
// the implementation's own docs.
//   scripts/build-wasm.sh && node --test tests/node/contract.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';

const require = createRequire(import.meta.url);
const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const sl = require(join(root, 'pkg-node/splinelab.js'));

// ---------------------------------------------------------------------------------------------------------
// helpers
let checks = 0;
const ok = (cond, msg) => { checks++; assert.ok(cond, msg); };
const eq = (a, b, msg) => { checks++; assert.deepEqual(a, b, msg); };
const close = (a, b, tol, msg) => {
  checks++;
  const A = typeof a === 'number' ? [a] : Array.from(a);
  const B = typeof b === 'number' ? [b] : Array.from(b);
  assert.equal(A.length, B.length, `${msg}: length ${A.length} vs ${B.length}`);
  let worst = 0, at = -1;
  for (let i = 0; i < A.length; i++) {
    const e = Math.abs(A[i] - B[i]) / Math.max(1, Math.abs(B[i]));
    if (!(e <= worst)) { worst = e; at = i; }
  }
  assert.ok(worst <= tol, `${msg}: max rel err ${worst} at ${at} (${A[at]} vs ${B[at]})`);
};
const isF64 = (x, msg) => { checks++; assert.ok(x instanceof Float64Array, `${msg} is a Float64Array`); };
const throwsField = (fn, field, msg) => {
  checks++;
  assert.throws(fn, (e) => e instanceof Error && !(e instanceof WebAssembly.RuntimeError)
    && (Array.isArray(field) ? field.some((f) => e.message.startsWith(f)) : e.message.startsWith(field)),
  `${msg ?? ''} an Error whose message starts with ${field}`);
  // the next valid call works
  const r = sl.bsplineCurve({ degree: 1, knots: [0, 0, 1, 1], points: [[0, 0], [1, 1]], samples: 3 });
  checks++; assert.equal(r.points.length, 6);
};
const flat = (pts) => pts.flat();
const linspace = (a, b, n) => Array.from({ length: n }, (_, i) => (n === 1 ? a : a + (b - a) * i / (n - 1)));
const lerp = (p, q, t) => p.map((x, i) => (1 - t) * x + t * q[i]);
const add = (p, q) => p.map((x, i) => x + q[i]);
const sub = (p, q) => p.map((x, i) => x - q[i]);
const scale = (p, s) => p.map((x) => x * s);
const norm = (p) => Math.hypot(...p);
const dist = (p, q) => norm(sub(p, q));
const row = (arr, i, dim) => Array.from(arr.slice(i * dim, i * dim + dim));

// Curve result: keys, types, lengths.
function curveShape(r, dim, nParams, derivs, name) {
  eq(r.dim, dim, `${name}.dim`);
  isF64(r.params, `${name}.params`);
  isF64(r.points, `${name}.points`);
  eq(r.params.length, nParams, `${name}.params.length`);
  eq(r.points.length, r.params.length * dim, `${name}.points.length`);
  if (derivs >= 1) { isF64(r.d1, `${name}.d1`); eq(r.d1.length, r.points.length, `${name}.d1.length`); } else ok(r.d1 === undefined, `${name}: no d1 by default`);
  if (derivs >= 2) { isF64(r.d2, `${name}.d2`); eq(r.d2.length, r.points.length, `${name}.d2.length`); } else ok(r.d2 === undefined, `${name}: no d2 unless asked`);
}
// Surface result.
function surfaceShape(r, dim, nPts, derivs, name) {
  eq(r.dim, dim, `${name}.dim`);
  isF64(r.uv, `${name}.uv`);
  isF64(r.points, `${name}.points`);
  eq(r.uv.length, 2 * nPts, `${name}.uv.length`);
  eq(r.points.length, nPts * dim, `${name}.points.length`);
  if (derivs >= 1) {
    isF64(r.du, `${name}.du`); isF64(r.dv, `${name}.dv`);
    eq(r.du.length, r.points.length, `${name}.du.length`); eq(r.dv.length, r.points.length, `${name}.dv.length`);
  } else ok(r.du === undefined && r.dv === undefined, `${name}: no du/dv by default`);
}
// Default sampling: `samples` 200 uniform over [a, b], ends included.
function defaultSamples(fn, opts, a, b, name) {
  const r = fn(opts);
  eq(r.params.length, 200, `${name}: default samples 200`);
  close(r.params, linspace(a, b, 200), 1e-12, `${name}: uniform params over the domain [${a}, ${b}]`);
  const r2 = fn({ ...opts, samples: 7 });
  close(r2.params, linspace(a, b, 7), 1e-12, `${name}: samples 7`);
  return r;
}
// Default surface sampling: 40 × 40, u-major.
function defaultGrid(fn, opts, [u0, u1], [v0, v1], name) {
  const r = fn(opts);
  eq(r.uv.length, 2 * 1600, `${name}: default samplesU = samplesV = 40`);
  const r2 = fn({ ...opts, samplesU: 3, samplesV: 4 });
  const us = linspace(u0, u1, 3), vs = linspace(v0, v1, 4);
  const want = [];
  for (let iu = 0; iu < 3; iu++) for (let iv = 0; iv < 4; iv++) want.push(us[iu], vs[iv]);
  close(r2.uv, want, 1e-12, `${name}: u-major grid iu*samplesV+iv over [${u0},${u1}]×[${v0},${v1}]`);
  // the grid points equal atUV evaluation at those pairs
  const atUV = []; for (let i = 0; i < want.length; i += 2) atUV.push([want[i], want[i + 1]]);
  const r3 = fn({ ...opts, samplesU: undefined, samplesV: undefined, atUV });
  close(r3.points, r2.points, 1e-12, `${name}: grid = atUV at the same pairs`);
  return r;
}
// Derivatives against central finite differences through the API (curve, at params away from knots).
function fdCurve(fn, opts, us, h, tol, name) {
  const r = fn({ ...opts, at: us, derivatives: 2 });
  const rp = fn({ ...opts, at: us.map((u) => u + h), derivatives: 1 });
  const rm = fn({ ...opts, at: us.map((u) => u - h), derivatives: 1 });
  const fd1 = r.points.map((_, i) => (rp.points[i] - rm.points[i]) / (2 * h));
  const fd2 = r.points.map((_, i) => (rp.d1[i] - rm.d1[i]) / (2 * h));
  close(r.d1, fd1, tol, `${name}: d1 = finite difference w.r.t. the global parameter`);
  close(r.d2, fd2, tol, `${name}: d2 = finite difference of d1`);
}
function fdSurface(fn, opts, uvs, h, tol, name) {
  const r = fn({ ...opts, atUV: uvs, derivatives: 1 });
  const f = (du, dv) => fn({ ...opts, atUV: uvs.map(([u, v]) => [u + du, v + dv]) }).points;
  const up = f(h, 0), um = f(-h, 0), vp = f(0, h), vm = f(0, -h);
  close(r.du, up.map((x, i) => (x - um[i]) / (2 * h)), tol, `${name}: du = finite difference`);
  close(r.dv, vp.map((x, i) => (x - vm[i]) / (2 * h)), tol, `${name}: dv = finite difference`);
}

// Reference B-spline (Cox–de Boor, right-hand piece at knots, last piece at the end).
function findSpan(knots, p, u) {
  const hi = knots.length - p - 2;
  if (u >= knots[hi + 1]) { let s = hi; while (s > p && knots[s] === knots[s + 1]) s--; return s; }
  let s = p; while (s < hi && u >= knots[s + 1]) s++;
  return s;
}
function basisAll(knots, p, u) {
  const count = knots.length - p - 1;
  const s = findSpan(knots, p, u);
  const N = new Array(count).fill(0);
  const loc = [1], left = [], right = [];
  for (let j = 1; j <= p; j++) {
    left[j] = u - knots[s + 1 - j]; right[j] = knots[s + j] - u;
    let saved = 0;
    for (let r = 0; r < j; r++) {
      const tmp = loc[r] / (right[r + 1] + left[j - r]);
      loc[r] = saved + right[r + 1] * tmp; saved = left[j - r] * tmp;
    }
    loc[j] = saved;
  }
  for (let r = 0; r <= p; r++) N[s - p + r] = loc[r];
  return N;
}
function bspline(knots, p, ctrl, u) {
  const N = basisAll(knots, p, u);
  let out = ctrl[0].map(() => 0);
  N.forEach((w, i) => { if (w) out = add(out, scale(ctrl[i], w)); });
  return out;
}
function tensorBspline(ku, p, kv, q, ctrl, u, v) {
  const Nu = basisAll(ku, p, u), Nv = basisAll(kv, q, v);
  let out = [0, 0, 0];
  Nu.forEach((a, i) => { if (a) Nv.forEach((b, j) => { if (b) out = add(out, scale(ctrl[i][j], a * b)); }); });
  return out;
}
const clamped2 = (br) => [br[0], br[0], ...br, br[br.length - 1], br[br.length - 1]];

// Quasi-cubic basis, curves.md §1 (values, first and second derivatives in t).
function qcBasis(alpha, t, d = 0) {
  const P = Math.PI, s = Math.sin(P * t), c = Math.cos(P * t), S = Math.sin(P * t / 2), C = Math.cos(P * t / 2);
  let B0, B1;
  if (d === 0) {
    B0 = [(1 - t) / 4 - s / (4 * P), 0.5 - t / 4 + s / (4 * P), 0.25 + t / 4 + s / (4 * P), t / 4 - s / (4 * P)];
    B1 = [(1 - S) ** 2 / 6, (1 + C) ** 2 / 6, (1 + S) ** 2 / 6, (1 - C) ** 2 / 6];
  } else if (d === 1) {
    B0 = [-0.25 - c / 4, -0.25 + c / 4, 0.25 + c / 4, 0.25 - c / 4];
    B1 = [-P * (1 - S) * C / 6, -P * (1 + C) * S / 6, P * (1 + S) * C / 6, P * (1 - C) * S / 6];
  } else {
    B0 = [P * s / 4, -P * s / 4, -P * s / 4, P * s / 4];
    const k = P * P / 12;
    B1 = [k * (C * C + S - S * S), k * (S * S - C - C * C), k * (C * C - S - S * S), k * (S * S + C - C * C)];
  }
  return B0.map((x, i) => (1 - alpha) * x + alpha * B1[i]);
}
function qcCurve(pts, alpha, u, d = 0) {
  const n = pts.length - 3;
  const i = Math.min(Math.floor(u), n - 1), t = u - i;
  const B = qcBasis(alpha, t, d);
  let out = pts[0].map(() => 0);
  for (let j = 0; j < 4; j++) out = add(out, scale(pts[i + j], B[j]));
  return out;
}

// ---------------------------------------------------------------------------------------------------------
// B-spline basics
test('bsplineCurve: shape, defaults, domain, de Boor, right-hand piece, derivatives, errors', () => {
  const knots = [-1, 0, 0.5, 1, 2, 2.5, 3.5, 4, 5, 6];
  const pts = [[0, 0], [1, 2], [2, -1], [3, 3], [5, 0], [6, 1]];
  const opts = { degree: 3, knots, points: pts };
  const r = defaultSamples(sl.bsplineCurve, opts, knots[3], knots[knots.length - 4], 'bsplineCurve');
  curveShape(r, 2, 200, 0, 'bsplineCurve');
  const at = [1, 1.3, 2, 2.2, 2.5, 3.0, 3.5, 3.9, 4];
  const ra = sl.bsplineCurve({ ...opts, at });
  curveShape(ra, 2, at.length, 0, 'bsplineCurve at');
  close(ra.params, at, 0, 'bsplineCurve: params are `at` in the given order');
  close(ra.points, flat(at.map((u) => bspline(knots, 3, pts, u))), 1e-12, 'bsplineCurve vs JS de Boor');
  fdCurve(sl.bsplineCurve, opts, [1.2, 2.3, 3.1, 3.8], 1e-5, 1e-5, 'bsplineCurve');
  // 3D
  const p3 = pts.map(([x, y], i) => [x, y, i * i]);
  const r3 = sl.bsplineCurve({ degree: 3, knots, points: p3, at, derivatives: 2 });
  curveShape(r3, 3, at.length, 2, 'bsplineCurve 3D');
  close(r3.points, flat(at.map((u) => bspline(knots, 3, p3, u))), 1e-12, 'bsplineCurve 3D vs de Boor');
  // right-hand piece at an interior knot: degree 1 with a kink; d1 at the knot is the right slope
  const k1 = sl.bsplineCurve({ degree: 1, knots: [0, 0, 1, 3, 3], points: [[0, 0], [1, 1], [2, 5]], at: [1, 3], derivatives: 1 });
  close(k1.d1, [0.5, 2, 0.5, 2], 1e-12, 'bsplineCurve: right-hand piece at a knot, last piece at the end');
  // degree 2, double interior knot (C0 kink): the derivative at the knot is the right one
  const k2 = sl.bsplineCurve({ degree: 2, knots: [0, 0, 0, 1, 1, 2, 2, 2], points: [[0, 0], [1, 0], [1, 1], [1, 3], [2, 3]], at: [1], derivatives: 1 });
  close(k2.d1, [0, 4], 1e-12, 'bsplineCurve: right derivative at a double knot');
  // errors
  throwsField(() => sl.bsplineCurve({ degree: 3, knots: [0, 0, 0, 0, 1, 1, 1, 1], points: [[0, 0], [1, 1], [2, 0]], samples: 5 }), ['points', 'knots'], 'mismatch');
  throwsField(() => sl.bsplineCurve({ ...opts, samples: 1_000_001 }), 'samples');
  throwsField(() => sl.bsplineCurve({ ...opts, at: [1, NaN] }), 'at');
  throwsField(() => sl.bsplineCurve({ ...opts, at: [1, Infinity] }), 'at');
  throwsField(() => sl.bsplineCurve({ ...opts, points: [[0, 0], [1, NaN], [2, -1], [3, 3], [5, 0], [6, 1]] }), 'points');
  throwsField(() => sl.bsplineCurve({ ...opts, knots: [-1, 0, 0.5, 1, 2, Infinity, 3.5, 4, 5, 6] }), 'knots');
  throwsField(() => sl.bsplineCurve({ ...opts, knots: [-1, 0, 0.5, 1, 2, 1.5, 3.5, 4, 5, 6] }), 'knots');
  throwsField(() => sl.bsplineCurve({ ...opts, derivatives: 3 }), 'derivatives');
  throwsField(() => sl.bsplineCurve({ ...opts, points: [[0, 0], [1, 2, 3], [2, -1], [3, 3], [5, 0], [6, 1]] }), 'points');
  const big = 100_001;
  const bigKnots = Array.from({ length: big + 2 }, (_, i) => i);
  throwsField(() => sl.bsplineCurve({ degree: 1, knots: bigKnots, points: Array.from({ length: big }, (_, i) => [i, 0]), samples: 3 }), ['points', 'knots'], '> 100,000 input points');
  // exactly at the limits is fine
  const rl = sl.bsplineCurve({ degree: 1, knots: [0, 0, 1, 1], points: [[0, 0], [1, 1]], samples: 1_000_000 });
  eq(rl.params.length, 1_000_000, '1,000,000 samples accepted');
});

test('bsplineBasis: count × params, partition of unity, reference, derivatives', () => {
  const knots = [0, 0, 0, 1, 2, 2, 3, 4, 4, 4];
  const at = [0, 0.5, 1, 1.7, 2, 2.5, 3, 3.9, 4];
  const count = knots.length - 3;
  const r = sl.bsplineBasis({ degree: 2, knots, at });
  isF64(r.values, 'bsplineBasis.values');
  eq(r.values.length, count * at.length, 'bsplineBasis: count × at.length');
  ok(r.d1 === undefined && r.d2 === undefined, 'bsplineBasis: no derivatives by default');
  close(r.values, at.flatMap((u) => basisAll(knots, 2, u)), 1e-13, 'bsplineBasis vs Cox–de Boor (right-hand piece)');
  for (let k = 0; k < at.length; k++) close(r.values.slice(k * count, k * count + count).reduce((a, b) => a + b, 0), 1, 1e-14, 'partition of unity');
  const inner = [0.3, 1.4, 2.6, 3.3], h = 1e-6;
  const rd = sl.bsplineBasis({ degree: 2, knots, at: inner, derivatives: 2 });
  isF64(rd.d1, 'd1'); isF64(rd.d2, 'd2');
  const rp = sl.bsplineBasis({ degree: 2, knots, at: inner.map((u) => u + h), derivatives: 1 });
  const rm = sl.bsplineBasis({ degree: 2, knots, at: inner.map((u) => u - h), derivatives: 1 });
  close(rd.d1, rp.values.map((x, i) => (x - rm.values[i]) / (2 * h)), 1e-6, 'bsplineBasis d1 = FD');
  close(rd.d2, rp.d1.map((x, i) => (x - rm.d1[i]) / (2 * h)), 1e-6, 'bsplineBasis d2 = FD');
  throwsField(() => sl.bsplineBasis({ degree: 2, knots: [0, 0, 1], at: [0] }), 'knots');
  throwsField(() => sl.bsplineBasis({ degree: 2, knots, at: [NaN] }), 'at');
});

// ---------------------------------------------------------------------------------------------------------
// Quasi-cubic (curves.md §1)
test('quasiCubicBasis: 4 values per t, formula of §1, derivatives, end values l1..l4', () => {
  const ts = [0, 0.1, 0.25, 0.5, 0.8, 1];
  for (const alpha of [-3, 0, 0.5, 1, 3]) {
    const r = sl.quasiCubicBasis({ alpha, at: ts, derivatives: 2 });
    isF64(r.values, 'values'); isF64(r.d1, 'd1'); isF64(r.d2, 'd2');
    eq(r.values.length, 4 * ts.length, 'values.length = 4 × at.length');
    close(r.values, ts.flatMap((t) => qcBasis(alpha, t, 0)), 1e-13, `quasiCubicBasis α=${alpha} values`);
    close(r.d1, ts.flatMap((t) => qcBasis(alpha, t, 1)), 1e-13, `quasiCubicBasis α=${alpha} d1`);
    close(r.d2, ts.flatMap((t) => qcBasis(alpha, t, 2)), 1e-13, `quasiCubicBasis α=${alpha} d2`);
    const l1 = (3 - alpha) / 12, l2 = (3 + alpha) / 6, l3 = alpha * Math.PI / 6 + (1 - alpha) / 2, l4 = alpha * Math.PI ** 2 / 12;
    close(r.values.slice(0, 4), [l1, l2, l1, 0], 1e-13, 'B(0)');
    close(r.d1.slice(20, 24), [0, -l3, 0, l3], 1e-13, "B'(1)");
    close(r.d2.slice(0, 4), [l4, -2 * l4, l4, 0], 1e-13, "B''(0)");
  }
  const r0 = sl.quasiCubicBasis({ alpha: 1, at: [0.3] });
  ok(r0.d1 === undefined, 'quasiCubicBasis: derivatives default 0');
  throwsField(() => sl.quasiCubicBasis({ alpha: NaN, at: [0.3] }), 'alpha');
  throwsField(() => sl.quasiCubicBasis({ alpha: 1, at: [0.3, Infinity] }), 'at');
});

test('quasiCubicCurve: domain [0, n], segments, derivatives w.r.t. u', () => {
  const pts = [[0, 0], [1, 2], [3, 3], [4, 1], [6, 0], [7, 2], [9, 3]]; // b_0..b_6, n = 4
  const n = pts.length - 3;
  for (const alpha of [0, 0.7, 3]) {
    const opts = { points: pts, alpha };
    const r = defaultSamples(sl.quasiCubicCurve, opts, 0, n, `quasiCubicCurve α=${alpha}`);
    curveShape(r, 2, 200, 0, 'quasiCubicCurve');
    const at = [0, 0.4, 1, 1.5, 2, 3.25, 3.999, 4];
    const ra = sl.quasiCubicCurve({ ...opts, at, derivatives: 2 });
    curveShape(ra, 2, at.length, 2, 'quasiCubicCurve');
    close(ra.points, flat(at.map((u) => qcCurve(pts, alpha, u))), 1e-13, 'quasiCubicCurve vs §1 reference');
    close(ra.d1, flat(at.map((u) => qcCurve(pts, alpha, u, 1))), 1e-12, 'quasiCubicCurve d1 vs reference');
    close(ra.d2, flat(at.map((u) => qcCurve(pts, alpha, u, 2))), 1e-12, 'quasiCubicCurve d2 vs reference');
    fdCurve(sl.quasiCubicCurve, opts, [0.3, 1.6, 3.7], 1e-5, 1e-5, 'quasiCubicCurve');
  }
  throwsField(() => sl.quasiCubicCurve({ points: [[0, 0], [1, 1], [2, 0]], alpha: 1 }), 'points');
  throwsField(() => sl.quasiCubicCurve({ points: [[0, 0], [1, 1], [2, 0], [3, NaN]], alpha: 1 }), 'points');
});

function bisRef(P, beta, k, u) {
  // P = b_{-1}..b_{n+1}; global segment g = i+1 of the paper's p_i; BIS_i uses b_{i+1}, b_{i+2} and β*_{i+1}, β*_{i+2}
  const n = P.length - 3;
  const g = Math.min(Math.floor(u), n - 1), t = u - g;
  const b = (j) => P[j + 1];
  const p = qcCurve(P, 3, u);
  let s = 0;
  const binom = (a, c) => { let r = 1; for (let i = 1; i <= c; i++) r = r * (a - c + i) / i; return r; };
  for (let j = k; j <= 2 * k - 1; j++) s += binom(2 * k - 1, j) * t ** j * (1 - t) ** (2 * k - 1 - j);
  const L = lerp(b(g), b(g + 1), s);
  const bt = (1 - s) * beta[g] + s * beta[g + 1];
  return add(L, scale(sub(p, L), bt));
}

test('quasiCubicInterpolation: passes through b_j at u = j, BIS, β*, k', () => {
  const P = [[-1, 0.5], [0, 0], [1, 2], [2.5, 2.2], [4, 0.5], [5, 1], [6.5, 3], [7, 2]]; // b_-1..b_6, n = 5
  const n = P.length - 3;
  const js = Array.from({ length: n + 1 }, (_, j) => j);
  const r0 = defaultSamples(sl.quasiCubicInterpolation, { points: P }, 0, n, 'quasiCubicInterpolation');
  curveShape(r0, 2, 200, 0, 'quasiCubicInterpolation');
  const ri = sl.quasiCubicInterpolation({ points: P, at: js });
  close(ri.points, flat(P.slice(1, n + 2)), 1e-13, 'interpolates b_j at u = j');
  isF64(ri.beta, 'beta'); close(ri.beta, new Array(n + 1).fill(1), 0, 'beta omitted = all 1');
  const at = linspace(0, n, 23);
  close(sl.quasiCubicInterpolation({ points: P, at }).points, sl.quasiCubicCurve({ points: P, alpha: 3, at }).points, 1e-13, 'β ≡ 1 gives the α = 3 spline');
  const beta = [1, 0.3, 1.7, 0, 2, 0.8];
  for (const k of [3, 4]) {
    const r = sl.quasiCubicInterpolation({ points: P, beta, k, at, derivatives: 2 });
    close(r.points, flat(at.map((u) => bisRef(P, beta, k, u))), 1e-12, `BIS vs reference, k = ${k}`);
    close(r.beta, beta, 0, 'beta used = beta given');
    fdCurve(sl.quasiCubicInterpolation, { points: P, beta, k }, [0.3, 2.6, 4.4], 1e-5, 1e-5, `BIS k=${k}`);
    close(sl.quasiCubicInterpolation({ points: P, beta, k, at: js }).points, flat(P.slice(1, n + 2)), 1e-13, 'BIS interpolates');
  }
  // k defaults to 3
  close(sl.quasiCubicInterpolation({ points: P, beta, at }).points, flat(at.map((u) => bisRef(P, beta, 3, u))), 1e-12, 'k default 3');
  // BIS'(j) = β*_j (π/2 − 1)(b_{j+1} − b_{j−1})
  const rt = sl.quasiCubicInterpolation({ points: P, beta, at: js, derivatives: 1 });
  const c0 = Math.PI / 2 - 1;
  close(rt.d1, flat(js.map((j) => scale(sub(P[j + 2], P[j]), beta[j] * c0))), 1e-12, "BIS'(j) = β*_j p'(j)");
  // curvature matching
  const c1 = Math.PI ** 2 / 4;
  const bstar = js.map((j) => (c1 / c0 ** 2) * dist(P[j + 1], P[j]) * dist(P[j + 2], P[j + 1]) / dist(P[j + 2], P[j]) ** 2);
  const rc = sl.quasiCubicInterpolation({ points: P, beta: 'curvature', at: js, derivatives: 2 });
  close(rc.beta, bstar, 1e-12, 'β* curvature formula');
  for (const j of js) {
    const d1 = row(rc.d1, j, 2), d2 = row(rc.d2, j, 2);
    const kappa = (d1[0] * d2[1] - d1[1] * d2[0]) / norm(d1) ** 3;
    const [A, B, C] = [P[j], P[j + 1], P[j + 2]];
    const area2 = (B[0] - A[0]) * (C[1] - A[1]) - (B[1] - A[1]) * (C[0] - A[0]);
    const K = 2 * area2 / (dist(A, B) * dist(B, C) * dist(A, C));
    close(kappa, K, 1e-10, `curvature at b_${j} = circle curvature`);
  }
  throwsField(() => sl.quasiCubicInterpolation({ points: P, beta: [1, 1] }), 'beta');
  throwsField(() => sl.quasiCubicInterpolation({ points: P, beta: 'nope' }), 'beta');
  throwsField(() => sl.quasiCubicInterpolation({ points: P, beta: [1, 1, NaN, 1, 1, 1] }), 'beta');
  throwsField(() => sl.quasiCubicInterpolation({ points: P, k: 0 }), 'k');
});

test('quasiCubicSurface: tensor product, (m+3)×(n+3) grid, domain [0,m]×[0,n], u-major', () => {
  const m = 2, n = 3;
  const grid = Array.from({ length: m + 3 }, (_, i) => Array.from({ length: n + 3 }, (_, j) => [i, j, Math.sin(i + 2 * j)]));
  const opts = { grid, alpha: 0.5 };
  const r = defaultGrid(sl.quasiCubicSurface, opts, [0, m], [0, n], 'quasiCubicSurface');
  surfaceShape(r, 3, 1600, 0, 'quasiCubicSurface');
  const uvs = [[0, 0], [0.3, 2.1], [1, 1], [1.7, 3], [2, 3], [2, 0.5]];
  const ref = ([u, v]) => {
    const iu = Math.min(Math.floor(u), m - 1), iv = Math.min(Math.floor(v), n - 1);
    const Bu = qcBasis(0.5, u - iu), Bv = qcBasis(0.5, v - iv);
    let out = [0, 0, 0];
    for (let a = 0; a < 4; a++) for (let b = 0; b < 4; b++) out = add(out, scale(grid[iu + a][iv + b], Bu[a] * Bv[b]));
    return out;
  };
  const ra = sl.quasiCubicSurface({ ...opts, atUV: uvs, derivatives: 1 });
  surfaceShape(ra, 3, uvs.length, 1, 'quasiCubicSurface atUV');
  close(ra.points, flat(uvs.map(ref)), 1e-13, 'quasiCubicSurface vs tensor reference');
  fdSurface(sl.quasiCubicSurface, opts, [[0.3, 0.4], [1.5, 2.5]], 1e-5, 1e-5, 'quasiCubicSurface');
  throwsField(() => sl.quasiCubicSurface({ grid: grid.slice(0, 3), alpha: 1 }), 'grid');
  throwsField(() => sl.quasiCubicSurface({ ...opts, samplesU: 1001, samplesV: 1000 }), ['samplesU', 'samplesV', 'samples']);
  throwsField(() => sl.quasiCubicSurface({ ...opts, atUV: [[0.5, NaN]] }), 'atUV');
});

// ---------------------------------------------------------------------------------------------------------
// B2-splines (curves.md §2)
const W = [[-1, -0.5], [0, 0], [1, 1.5], [2.5, 1.8], [3.2, 0.4], [4.5, -0.3], [5.2, 1.2], [6.5, 2], [7, 3.4]]; // W_-1..W_7, n = 5
function chordKnots(W) { // u_-1..u_{n+2}, u_1 = 0
  const u = [0];
  for (let j = 1; j < W.length; j++) u.push(u[j - 1] + dist(W[j], W[j - 1]));
  return u.map((x) => x - u[2]);
}
function farin(u) { // u'_0..u'_{2n+2} from u (array index k ↔ u_{k-1}); u'_{2i} = u_i, i = 0..n+1
  const up = [];
  for (let i = 0; i <= u.length - 3; i++) { up.push(u[i + 1]); if (i < u.length - 3) up.push((u[i + 1] + u[i + 2]) / 2); }
  return up;
}
function evenRef(W, u, p, c2) { // C_{2i}, i = 0..n
  const n = W.length - 4, w = (j) => W[j + 1], D = (j) => u[j + 2] - u[j + 1];
  const out = [];
  for (let i = 0; i <= n; i++) {
    const pi = Array.isArray(p) ? p[i] : p;
    const pm = 6 * pi * D(i) ** 2 / (D(i) ** 2 + 5 * D(i) * D(i - 1) + c2 * D(i - 1) ** 2);
    const pp = 6 * pi * D(i) ** 2 / (D(i) ** 2 + 5 * D(i) * D(i + 1) + c2 * D(i + 1) ** 2);
    out.push(add(add(scale(w(i - 1), -pm), scale(w(i), 0.5 + pm)), add(scale(w(i + 1), 0.5 + pp), scale(w(i + 2), -pp))));
  }
  return out;
}

test('b2Curve: shape, extras, domain, chord knots, a = 0 interpolation, even vertices, c2', () => {
  const n = W.length - 4, u = chordKnots(W);
  const r = defaultSamples(sl.b2Curve, { points: W }, 0, u[n + 1], 'b2Curve');
  curveShape(r, 2, 200, 0, 'b2Curve');
  for (const k of ['domain', 'knots', 'controlPoints', 'joints', 'evenVertices', 'tension']) isF64(r[k], `b2Curve.${k}`);
  close(r.domain, [u[2], u[n + 1]], 1e-13, 'b2Curve.domain = [u_1, u_n], u_1 = 0 for chord knots');
  const up = farin(u);
  close(r.knots, [up[0], ...up, up[up.length - 1]], 1e-13, 'b2Curve.knots = [u\'_0] + u\' + [u\'_{2n+2}] (Farin)');
  eq(r.controlPoints.length, (2 * n + 1) * 2, 'controlPoints = C_0..C_{2n}');
  eq(r.evenVertices.length, (n + 1) * 2, 'evenVertices = C_0, C_2, …, C_2n');
  close(r.tension, new Array(n + 1).fill(1 / 6), 1e-15, 'tension default 1/6, p_0..p_n');
  close(r.evenVertices, flat(evenRef(W, u, 1 / 6, 1)), 1e-12, 'even vertices (Eq. 8/9, c2 = 1 default)');
  close(r.evenVertices, Array.from({ length: n + 1 }, (_, i) => row(r.controlPoints, 2 * i, 2)).flat(), 0, 'evenVertices = even controlPoints');
  const ri = sl.b2Curve({ points: W, at: u.slice(2, n + 2) });
  close(ri.points, flat(W.slice(2, n + 2)), 1e-12, 'a = 0 interpolates W_1..W_n at u_1..u_n');
  close(r.joints, flat(W.slice(2, n + 2)), 1e-12, 'a = 0: joints are W_1..W_n');
  const r2 = sl.b2Curve({ points: W, c2: 2, samples: 3 });
  close(r2.evenVertices, flat(evenRef(W, u, 1 / 6, 2)), 1e-12, 'even vertices with c2 = 2');
  const tens = [0.1, 0.2, 0, 0.15, 0.3, 0.05];
  const r3 = sl.b2Curve({ points: W, tension: tens, samples: 3 });
  close(r3.evenVertices, flat(evenRef(W, u, tens, 1)), 1e-12, 'even vertices with a tension array');
  close(r3.tension, tens, 0, 'tension used = given');
  const at = linspace(0, u[n + 1], 31);
  for (const a of [0, 0.1, 1 / 6, -0.1]) {
    const ra = sl.b2Curve({ points: W, a, tension: 0.13, at });
    const bs = sl.bsplineCurve({ degree: 3, knots: Array.from(ra.knots), points: Array.from({ length: 2 * n + 1 }, (_, i) => row(ra.controlPoints, i, 2)), at });
    close(ra.points, bs.points, 1e-12, `a = ${a}: the curve is the cubic B-spline on (knots, controlPoints)`);
    close(ra.joints, flat(u.slice(2, n + 2).map((x) => row(sl.b2Curve({ points: W, a, tension: 0.13, at: [x] }).points, 0, 2))), 1e-12, `a = ${a}: joints = L^a(u_i)`);
  }
  // a = 1/6: the cubic B-spline with control W_0..W_{n+1} on [u_-1, u_-1, …, u_{n+2}, u_{n+2}]
  const LB = sl.bsplineCurve({ degree: 3, knots: [u[0], ...u, u[u.length - 1]], points: W.slice(1, n + 3), at });
  for (const p of [0, 0.13, 1 / 6]) close(sl.b2Curve({ points: W, a: 1 / 6, tension: p, at }).points, LB.points, 1e-12, `a = 1/6 equals L^B (p = ${p})`);
  const L = sl.b2Curve({ points: W, a: 0, at }).points;
  const La = sl.b2Curve({ points: W, a: 0.05, at }).points;
  close(La, L.map((x, i) => 6 * 0.05 * LB.points[i] + (1 - 0.3) * x), 1e-12, 'L^a = 6a L^B + (1 − 6a) L');
  fdCurve(sl.b2Curve, { points: W, a: 0.05 }, [0.3, 2.2, 5.1], 1e-5, 1e-5, 'b2Curve');
  // 3D
  const W3 = W.map(([x, y], i) => [x, y, 0.3 * i]);
  const r3d = sl.b2Curve({ points: W3, at: chordKnots(W3).slice(2, n + 2) });
  curveShape(r3d, 3, n, 0, 'b2Curve 3D');
  close(r3d.points, flat(W3.slice(2, n + 2)), 1e-12, '3D a = 0 interpolates');
});

test('b2Curve: uniform / explicit knots, K, section3, auto tension', () => {
  const n = W.length - 4;
  const ru = sl.b2Curve({ points: W, knots: 'uniform', at: linspace(0, n - 1, n) });
  close(ru.domain, [0, n - 1], 0, 'uniform knots: u_j = j − 1, domain [0, n − 1]');
  close(ru.points, flat(W.slice(2, n + 2)), 1e-12, 'uniform: interpolates W_i at i − 1');
  const ue = [-3, -1.5, 0, 1, 3, 3.5, 5, 7, 8];
  const re = sl.b2Curve({ points: W, knots: ue, at: ue.slice(2, n + 2) });
  close(re.domain, [ue[2], ue[n + 1]], 0, 'explicit knots domain');
  close(re.points, flat(W.slice(2, n + 2)), 1e-12, 'explicit knots: interpolation');
  close(re.evenVertices, flat(evenRef(W, ue, 1 / 6, 1)), 1e-12, 'explicit knots: even vertices');
  // K
  const K = 20, u = chordKnots(W);
  const um = (i) => (u[i] + K * u[i + 1] + u[i + 2]) / (K + 2); // u'_{2i}
  const rk = sl.b2Curve({ points: W, K, samples: 5 });
  close(rk.domain, [um(1), um(n)], 1e-13, 'K: domain [u\'_2, u\'_2n]');
  const upk = farin(u).map((x, j) => (j % 2 === 0 ? um(j / 2) : x));
  close(rk.knots, [upk[0], ...upk, upk[upk.length - 1]], 1e-13, 'K: modified even knots, odd knots stay');
  close(sl.b2Curve({ points: W, K, at: Array.from({ length: n }, (_, i) => um(i + 1)) }).points, flat(W.slice(2, n + 2)), 1e-12, 'K: interpolates W_i at u\'_2i');
  close(rk.evenVertices, flat(evenRef(W, u, 1 / 6, 1)), 1e-12, 'K: p± use the original Δ');
  // section3
  const at = linspace(0, n - 1, 17);
  const uniformB = sl.bsplineCurve({ degree: 3, knots: [-2, -2, -1, 0, 1, 2, 3, 4, 5, 6, 6], points: W.slice(1, n + 3), at });
  close(sl.b2Curve({ points: W, knots: 'uniform', construction: 'section3', a: 1 / 6, tension: 0, at }).points, uniformB.points, 1e-12, 'section3: a = 1/6, p = 0 is the uniform B-spline');
  const s3 = sl.b2Curve({ points: W, knots: 'uniform', construction: 'section3', a: 0, tension: 0.1, at: linspace(0, n - 1, n) });
  close(s3.points, flat(W.slice(2, n + 2)), 1e-12, 'section3: a = 0 interpolates');
  const w = (j) => W[j + 1];
  close(s3.evenVertices, flat(Array.from({ length: n + 1 }, (_, i) => add(add(scale(w(i - 1), -0.1), scale(add(w(i), w(i + 1)), 0.6)), scale(w(i + 2), -0.1)))), 1e-12, 'section3 C_2i');
  for (const [a, p] of [[0, 1 / 6], [0.1, 0.13], [-0.05, 0.2]]) {
    close(sl.b2Curve({ points: W, knots: 'uniform', a, tension: p, at }).points,
      sl.b2Curve({ points: W, knots: 'uniform', construction: 'section3', a, tension: (1 - 6 * a) * 6 * p / 7, at }).points, 1e-12, `equal spacing: nonuniform(${a}, ${p}) = section3(a, (1−6a)6p/7)`);
  }
  throwsField(() => sl.b2Curve({ points: W, construction: 'section3', samples: 3 }), ['construction', 'knots'], 'section3 needs uniform knots');
  // auto tension (curves.md §2.6)
  const ang = (j) => { const a = sub(w(j - 1), w(j)), b = sub(w(j + 1), w(j)); return Math.acos((a[0] * b[0] + a[1] * b[1]) / (norm(a) * norm(b))); };
  const turn = (j) => { const a = sub(w(j), w(j - 1)), b = sub(w(j + 1), w(j)); return Math.atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]); };
  const paper = (p) => Array.from({ length: n + 1 }, (_, i) => p * Math.abs(Math.cos(ang(i)) + Math.cos(ang(i + 1))) / 2);
  const turning = (p) => Array.from({ length: n + 1 }, (_, i) => p * Math.abs(Math.sin(turn(i)) + Math.sin(turn(i + 1))) / 2);
  close(sl.b2Curve({ points: W, autoTension: 'paper', samples: 3 }).tension, paper(0.2), 1e-14, 'autoTension "paper", scale default 0.2');
  close(sl.b2Curve({ points: W, autoTension: 'paper', autoTensionScale: 0.5, samples: 3 }).tension, paper(0.5), 1e-14, 'autoTensionScale');
  close(sl.b2Curve({ points: W, autoTension: 'turning', samples: 3 }).tension, turning(0.2), 1e-14, 'autoTension "turning"');
  close(sl.b2Curve({ points: W, autoTension: false, samples: 3 }).tension, new Array(n + 1).fill(1 / 6), 0, 'autoTension false');
  // paper's table: straight 0.2, 5° turns 0.199, 60° 0.1, 90° 0
  const poly = (deg) => { const P = [[0, 0]]; let th = 0; for (let i = 1; i < 8; i++) { P.push(add(P[i - 1], [Math.cos(th), Math.sin(th)])); th += deg * Math.PI / 180; } return P; };
  close(sl.b2Curve({ points: poly(60), autoTension: 'paper', knots: 'uniform', samples: 3 }).tension, new Array(5).fill(0.1), 1e-14, 'table: 60° turns → 0.1');
  close(sl.b2Curve({ points: poly(0), autoTension: 'turning', knots: 'uniform', samples: 3 }).tension, new Array(5).fill(0), 1e-14, 'table: straight, turning → 0');
  throwsField(() => sl.b2Curve({ points: W.map(([x, y]) => [x, y, 1]), autoTension: 'turning', samples: 3 }), 'autoTension', '"turning" is 2D only');
  // errors
  throwsField(() => sl.b2Curve({ points: W.slice(0, 5) }), 'points', 'n ≥ 2');
  throwsField(() => sl.b2Curve({ points: W, a: NaN }), 'a');
  throwsField(() => sl.b2Curve({ points: W, tension: [0.1, 0.2] }), 'tension');
  throwsField(() => sl.b2Curve({ points: W, knots: [0, 1, 2] }), 'knots');
  throwsField(() => sl.b2Curve({ points: W, knots: [0, 1, 2, 3, 2, 5, 6, 7, 8] }), 'knots');
  throwsField(() => sl.b2Curve({ points: W, c2: Infinity }), 'c2');
  throwsField(() => sl.b2Curve({ points: W, K: NaN }), 'K');
  throwsField(() => sl.b2Curve({ points: W, samples: 2_000_000 }), 'samples');
});

test('b2Surface: a = 0 interpolates the grid, a = 1/6 is the tensor B-spline, shape', () => {
  const m = 3, n = 2;
  const ku = [-2, -1, 0, 1.5, 2, 3.5, 4], kv = [-1, -0.5, 0, 1, 1.5, 2.5];
  const grid = ku.map((x, i) => kv.map((y, j) => [x, y, Math.cos(i) * Math.sin(j + 1)]));
  const opts = { grid, knotsU: ku, knotsV: kv };
  const r = defaultGrid(sl.b2Surface, opts, [ku[2], ku[m + 1]], [kv[2], kv[n + 1]], 'b2Surface');
  surfaceShape(r, 3, 1600, 0, 'b2Surface');
  const nodes = []; for (let i = 1; i <= m; i++) for (let j = 1; j <= n; j++) nodes.push([i, j]);
  const ri = sl.b2Surface({ ...opts, atUV: nodes.map(([i, j]) => [ku[i + 1], kv[j + 1]]) });
  close(ri.points, flat(nodes.map(([i, j]) => grid[i + 1][j + 1])), 1e-12, 'b2Surface a = 0 interpolates W_ij at (u_i, v_j)');
  const uvs = [[0.2, 0.1], [1.7, 0.9], [3.5, 1.5], [2.6, 0.3]];
  const ctrl = grid.slice(1, m + 3).map((rw) => rw.slice(1, n + 3));
  const KU = [ku[0], ...ku, ku[ku.length - 1]], KV = [kv[0], ...kv, kv[kv.length - 1]];
  close(sl.b2Surface({ ...opts, a: 1 / 6, tensionU: 0.1, tensionV: 0.05, atUV: uvs }).points, flat(uvs.map(([u, v]) => tensorBspline(KU, 3, KV, 3, ctrl, u, v))), 1e-12, 'b2Surface a = 1/6 = tensor B-spline');
  fdSurface(sl.b2Surface, { ...opts, a: 0.05 }, [[0.3, 0.4], [2.7, 1.2]], 1e-5, 1e-5, 'b2Surface');
  const ru = sl.b2Surface({ grid, knotsU: 'uniform', knotsV: 'uniform', samplesU: 2, samplesV: 2 });
  close(ru.uv, [0, 0, 0, n - 1, m - 1, 0, m - 1, n - 1], 0, 'b2Surface uniform domain');
  throwsField(() => sl.b2Surface({ grid: grid.slice(0, 4) }), 'grid');
  throwsField(() => sl.b2Surface({ ...opts, tensionU: 'auto' }), 'tensionU');
  throwsField(() => sl.b2Surface({ ...opts, knotsV: [0, 1] }), 'knotsV');
});

test('splineBlendedSurface: interpolates the network function on its lines, for each blend', () => {
  const f = (u, v) => [u, v, Math.sin(2 * u) * Math.cos(v) + u * v * v];
  const uK = [-1, -0.4, 0, 0.5, 1.2, 2, 2.6, 3], vK = [-0.5, 0, 0.7, 1.5, 2, 2.5];
  const ts = linspace(0, 1, 7);
  // b2 blend (default): lines u_1..u_m (array entries 2..len-3) over the domain [u_1, u_m] × [v_1, v_n]
  for (const blend of [undefined, 'b2']) {
    const opts = { network: f, uKnots: uK, vKnots: vK, blend };
    const r = defaultGrid(sl.splineBlendedSurface, opts, [uK[2], uK[uK.length - 3]], [vK[2], vK[vK.length - 3]], `splineBlendedSurface ${blend}`);
    surfaceShape(r, 3, 1600, 0, 'splineBlendedSurface');
    const uvs = [];
    for (const ur of uK.slice(2, -2)) for (const t of ts) uvs.push([ur, vK[2] + t * (vK[vK.length - 3] - vK[2])]);
    for (const vs of vK.slice(2, -2)) for (const t of ts) uvs.push([uK[2] + t * (uK[uK.length - 3] - uK[2]), vs]);
    close(sl.splineBlendedSurface({ ...opts, atUV: uvs }).points, flat(uvs.map(([u, v]) => f(u, v))), 1e-12, `blend ${blend ?? 'default'}: interpolates the network`);
  }
  const uN = [0, 0.5, 1.2, 2, 2.6], vN = [0, 0.7, 1.5, 2];
  for (const blend of ['cubic-natural', 'cubic-notaknot']) {
    const opts = { network: f, uKnots: uN, vKnots: vN, blend };
    defaultGrid(sl.splineBlendedSurface, opts, [0, 2.6], [0, 2], `splineBlendedSurface ${blend}`);
    const uvs = [];
    for (const ur of uN) for (const t of ts) uvs.push([ur, 2 * t]);
    for (const vs of vN) for (const t of ts) uvs.push([2.6 * t, vs]);
    close(sl.splineBlendedSurface({ ...opts, atUV: uvs }).points, flat(uvs.map(([u, v]) => f(u, v))), 1e-12, `blend ${blend}: interpolates the network`);
    // P2 reproduction (cardinal C² cubic blending reproduces quadratics in each variable)
    const q = (u, v) => [u * u - u * v, 3 * v * v + u, 1 + 2 * u * v - v];
    const pts = [[0.3, 0.2], [1.9, 1.1], [2.4, 1.8]];
    close(sl.splineBlendedSurface({ network: q, uKnots: uN, vKnots: vN, blend, atUV: pts }).points, flat(pts.map(([u, v]) => q(u, v))), 1e-11, `blend ${blend}: reproduces P2`);
  }
  throwsField(() => sl.splineBlendedSurface({ network: f, uKnots: uN, vKnots: vN, blend: 'nope' }), 'blend');
  throwsField(() => sl.splineBlendedSurface({ network: 3, uKnots: uN, vKnots: vN, blend: 'cubic-natural' }), 'network');
  throwsField(() => sl.splineBlendedSurface({ network: () => [0, NaN, 0], uKnots: uN, vKnots: vN, blend: 'cubic-natural', samplesU: 3, samplesV: 3 }), 'network');
});

// ---------------------------------------------------------------------------------------------------------
// Bézier remodelling (curves.md §3)
const bern = (m, t) => Array.from({ length: m + 1 }, (_, k) => { let c = 1; for (let i = 1; i <= k; i++) c = c * (m - k + i) / i; return c * t ** k * (1 - t) ** (m - k); });
function bezSpline(b, m, breaks, u) {
  const L = breaks.length - 1;
  let I = 0; while (I < L - 1 && u >= breaks[I + 1]) I++;
  const t = (u - breaks[I]) / (breaks[I + 1] - breaks[I]);
  const B = bern(m, t);
  let out = b[0].map(() => 0);
  for (let k = 0; k <= m; k++) out = add(out, scale(b[m * I + k], B[k]));
  return out;
}
function bezDerivs(b, m, breaks, u) { // value, d1, d2 w.r.t. u
  const L = breaks.length - 1;
  let I = 0; while (I < L - 1 && u >= breaks[I + 1]) I++;
  const h = breaks[I + 1] - breaks[I], t = (u - breaks[I]) / h;
  const seg = b.slice(m * I, m * I + m + 1);
  const d = seg.slice(1).map((p, k) => scale(sub(p, seg[k]), m / h));
  const dd = d.slice(1).map((p, k) => scale(sub(p, d[k]), (m - 1) / h));
  const ev = (pts, deg) => { const B = bern(deg, t); return pts.reduce((acc, p, k) => add(acc, scale(p, B[k])), pts[0].map(() => 0)); };
  return [ev(seg, m), ev(d, m - 1), m >= 2 ? ev(dd, m - 2) : seg[0].map(() => 0)];
}
const curv2 = (d1, d2) => Math.abs(d1[0] * d2[1] - d1[1] * d2[0]) / norm(d1) ** 3;
function remodelRef(b, m, alphas) { // Eq. (6)
  const L = (b.length - 1) / m, out = [];
  for (let I = 0; I < L; I++) {
    out.push(b[m * I]);
    for (let k = 1; k <= m; k++) out.push(lerp(b[m * I + k - 1], b[m * I + k], alphas[I][k - 1]));
  }
  out.push(b[m * L]);
  return out;
}
const ex = [[10, 16], [7, 21], [3, 9], [0, 0], [-4, 0], [-8, 0], [-6, 3], [-4, 6], [2, 2], [8, -2], [10, 3]];
const exBreaks = [0, 1, 7 / 4, 5 / 2, 13 / 4, 4];
const fig1 = [[2 / 3, 1 / 20], [19 / 20, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 10]];

test('bezierRemodel: paper example (Fig. 1), classical α reproduce g, extras, errors', () => {
  const opts = { points: ex, degree: 2, breaks: exBreaks, alphas: fig1 };
  const r = defaultSamples(sl.bezierRemodel, opts, 0, 4, 'bezierRemodel');
  curveShape(r, 2, 200, 0, 'bezierRemodel');
  for (const k of ['controlPoints', 'curvature', 'curvatureOriginal']) isF64(r[k], `bezierRemodel.${k}`);
  eq(r.controlPoints.length, (3 * 5 + 1) * 2, 'controlPoints = b*_0..b*_{(m+1)L}');
  close(r.controlPoints.slice(0, 8), [10, 16, 8, 19 + 1 / 3, 6.8, 20.4, 3, 9], 1e-13, 'Fig. 1: b* begins (10,16), (8,19.333), (6.8,20.4), (3,9)');
  close(r.controlPoints, flat(remodelRef(ex, 2, fig1)), 1e-13, 'controlPoints = Eq. (6) (Fig. 1 alphas satisfy Eq. 9)');
  ok(Array.isArray(r.alphas) && r.alphas.length === 5 && r.alphas.every((a) => a.length === 2), 'alphas[I][k−1] shape');
  close(r.alphas.map((a) => Array.from(a)).flat(), fig1.flat(), 1e-15, 'alphas used');
  eq(r.curvature.length, 6, 'curvature K*(u_I), I = 0..L');
  eq(r.curvatureOriginal.length, 6, 'curvatureOriginal K(u_I), I = 0..L');
  close(r.curvatureOriginal, exBreaks.map((u) => { const [, d1, d2] = bezDerivs(ex, 2, exBreaks, u); return curv2(d1, d2); }), 1e-12, 'curvatureOriginal = K(u_I) (right piece, last piece at u_L)');
  const bs = Array.from({ length: 16 }, (_, i) => row(r.controlPoints, i, 2));
  close(r.curvature, exBreaks.map((u) => { const [, d1, d2] = bezDerivs(bs, 3, exBreaks, u); return curv2(d1, d2); }), 1e-11, 'curvature = K*(u_I)');
  ok(Array.isArray(r.continuity) || r.continuity instanceof Float64Array, 'continuity present');
  // g* evaluation
  const at = linspace(0, 4, 41);
  close(sl.bezierRemodel({ ...opts, at }).points, flat(at.map((u) => bezSpline(bs, 3, exBreaks, u))), 1e-12, 'g* = Bézier spline of b* on the breaks');
  fdCurve(sl.bezierRemodel, opts, [0.5, 1.3, 3.6], 1e-5, 1e-5, 'bezierRemodel');
  // classical elevation reproduces g
  const cl = Array.from({ length: 5 }, () => [2 / 3, 1 / 3]);
  close(sl.bezierRemodel({ ...opts, alphas: cl, at }).points, flat(at.map((u) => bezSpline(ex, 2, exBreaks, u))), 1e-12, 'classical α reproduce g');
  // g*(u_I) = g(u_I)
  close(sl.bezierRemodel({ ...opts, at: exBreaks }).points, flat(exBreaks.map((u) => bezSpline(ex, 2, exBreaks, u))), 1e-12, 'g*(u_I) = g(u_I)');
  // enforce (default true) overwrites α_1^(I) = 1 − α_2^(I−1) (m = 2, r = 1); enforce false keeps them
  const bad = fig1.map((a, I) => (I > 0 ? [0.5, a[1]] : a));
  const re = sl.bezierRemodel({ ...opts, alphas: bad, samples: 3 });
  close(re.alphas.map((a) => Array.from(a)).flat(), fig1.flat(), 1e-15, 'enforce default true restores Eq. (9)');
  const rn = sl.bezierRemodel({ ...opts, alphas: bad, enforce: false, samples: 3 });
  close(rn.alphas.map((a) => Array.from(a)).flat(), bad.flat(), 0, 'enforce false keeps the alphas');
  close(rn.controlPoints, flat(remodelRef(ex, 2, bad)), 1e-13, 'enforce false: Eq. (6) with the given alphas');
  // errors
  throwsField(() => sl.bezierRemodel({ ...opts, points: ex.slice(0, 10) }), ['points', 'breaks']);
  throwsField(() => sl.bezierRemodel({ ...opts, breaks: [0, 1, 2] }), ['breaks', 'points']);
  throwsField(() => sl.bezierRemodel({ ...opts, breaks: [0, 1, 1, 2, 3, 4] }), 'breaks');
  throwsField(() => sl.bezierRemodel({ ...opts, alphas: fig1.slice(0, 3) }), 'alphas');
  throwsField(() => sl.bezierRemodel({ ...opts, alphas: [[NaN, 0.1], ...fig1.slice(1)] }), 'alphas');
  throwsField(() => sl.bezierRemodel({ ...opts, degree: 0 }), ['degree', 'points']);
});

test('bezierRemodelSurface: classical elevation reproduces G, controlPoints, breaksV default', () => {
  const cols = [[[0, 0, 3], [0, 1, 2], [0, 3, 1], [0, 4, 3]], [[1, 0, 1], [1, 1, 4], [1, 3, 2], [1, 4, 4]], [[2, 0, 2.5], [2, 1, 3], [2, 3, 1], [2, 4, 3]],
    [[3, 0, 4], [3, 1, 2], [3, 3, 0], [3, 4, 2]], [[4, 0, 2.5], [4, 1, 3], [4, 3, 1], [4, 4, 2.5]], [[5, 0, 1], [5, 1, 4], [5, 3, 2], [5, 4, 3]], [[6, 0, 3], [6, 1, 0], [6, 3, 1], [6, 4, 2]]];
  const opts = { points: cols, degreeU: 2, degreeV: 3, breaksU: [0, 1, 2, 3], alphas: [[2 / 3, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 3]] };
  const r = defaultGrid(sl.bezierRemodelSurface, opts, [0, 3], [0, 1], 'bezierRemodelSurface');
  surfaceShape(r, 3, 1600, 0, 'bezierRemodelSurface');
  isF64(r.controlPoints, 'controlPoints'); eq(r.controlPoints.length, (3 * 3 + 1) * 4 * 3, 'controlPoints (m+1)L+1 × (n+1)');
  const G = ([u, v]) => { const Bv = bern(3, v); const colPts = cols.map((c) => c.reduce((acc, p, l) => add(acc, scale(p, Bv[l])), [0, 0, 0])); return bezSpline(colPts, 2, [0, 1, 2, 3], u); };
  const uvs = [[0, 0], [0.4, 0.3], [1, 0.5], [1.5, 0.9], [2.7, 0.2], [3, 1]];
  close(sl.bezierRemodelSurface({ ...opts, atUV: uvs }).points, flat(uvs.map(G)), 1e-12, 'usual elevation reproduces G');
  const r2 = sl.bezierRemodelSurface({ ...opts, breaksV: [0, 2], samplesU: 2, samplesV: 2 });
  close(r2.uv, [0, 0, 0, 2, 3, 0, 3, 2], 0, 'breaksV sets the v domain');
  throwsField(() => sl.bezierRemodelSurface({ ...opts, alphas: [[2 / 3, 1 / 3]] }), 'alphas');
  throwsField(() => sl.bezierRemodelSurface({ ...opts, breaksU: [0, 1] }), ['breaksU', 'points']);
});

// ---------------------------------------------------------------------------------------------------------
// Criss-cross network surfaces (surfaces.md)
const uB = [0, 0.3, 0.45, 0.8, 1], vB = [0, 0.5, 0.6, 1]; // m = 4, n = 3 (non-uniform)
const xi = (b) => b.map((_, i) => i).concat([b.length]).map((i) => (i === 0 ? b[0] : i === b.length ? b[b.length - 1] : (b[i - 1] + b[i]) / 2));
function networkOf(C, ub, vb) { // isocurve network of the biquadratic Σ C_ij B_i(u) B_j(v)
  const U = clamped2(ub), V = clamped2(vb);
  const P = ub.map((ur) => { const N = basisAll(U, 2, ur); return C[0].map((_, j) => C.reduce((acc, rw, i) => add(acc, scale(rw[j], N[i])), [0, 0, 0])); });
  const Q = vb.map((vs) => { const N = basisAll(V, 2, vs); return C.map((rw) => rw.reduce((acc, p, j) => add(acc, scale(p, N[j])), [0, 0, 0])); });
  return { u: ub, v: vb, P, Q };
}
const Crand = xi(uB).map((x, i) => xi(vB).map((y, j) => [x, y, Math.sin(3 * i + j) + 0.3 * j]));
const netRand = networkOf(Crand, uB, vB);
const quad = (u, v) => [u * u - u * v, 3 * v * v + u, 1 + 2 * u * v - v];
const blossom2 = (b) => xi(b).map((_, i) => { const bl = (k) => b[Math.min(Math.max(k, 0), b.length - 1)]; return bl(i - 1) * bl(i); });
const Cquad = (() => { const xu = xi(uB), xv = xi(vB), uu = blossom2(uB), vv = blossom2(vB);
  return xu.map((x, i) => xv.map((y, j) => [uu[i] - x * y, 3 * vv[j] + x, 1 + 2 * x * y - y])); })();
const netQuad = networkOf(Cquad, uB, vB);
function checkInterpolates(fn, opts, net, tol, name) {
  const U = clamped2(net.u), V = clamped2(net.v), ts = linspace(0, 1, 9), uvs = [], want = [];
  net.u.forEach((ur, r) => ts.forEach((t) => { uvs.push([ur, t]); want.push(bspline(V, 2, net.P[r], t)); }));
  net.v.forEach((vs, s) => ts.forEach((t) => { uvs.push([t, vs]); want.push(bspline(U, 2, net.Q[s], t)); }));
  close(fn({ ...opts, atUV: uvs }).points, flat(want), tol, `${name}: interpolates the network curves φ_r, ψ_s`);
}

test('crissCrossBasis: values, centre value, partition of unity, traces, derivatives', () => {
  const m = uB.length - 1, n = vB.length - 1;
  const h = (r) => (r >= 1 && r <= m ? uB[r] - uB[r - 1] : 0), k = (s) => (s >= 1 && s <= n ? vB[s] - vB[s - 1] : 0);
  const sig = (r) => h(r) / (h(r - 1) + h(r)), sigp = (r) => h(r - 1) / (h(r - 1) + h(r));
  const tau = (s) => k(s) / (k(s - 1) + k(s)), taup = (s) => k(s - 1) / (k(s - 1) + k(s));
  const pts = [[0, 0], [0.1, 0.7], [0.33, 0.2], [0.5, 0.55], [0.9, 0.95], [1, 1], [0.45, 0.6], [0.72, 0.05]];
  const sum = new Array(pts.length).fill(0);
  const U = clamped2(uB), V = clamped2(vB);
  for (let i = 0; i <= m + 1; i++) for (let j = 0; j <= n + 1; j++) {
    const r = sl.crissCrossBasis({ u: uB, v: vB, i, j, atUV: pts });
    isF64(r.values, 'crissCrossBasis.values'); eq(r.values.length, pts.length, 'one value per (u, v)');
    r.values.forEach((x, q) => { sum[q] += x; });
    if (i >= 1 && i <= m && j >= 1 && j <= n) {
      const c = sl.crissCrossBasis({ u: uB, v: vB, i, j, atUV: [[(uB[i - 1] + uB[i]) / 2, (vB[j - 1] + vB[j]) / 2]] });
      close(c.values, [(sigp(i) + sig(i + 1) + taup(j) + tau(j + 1)) / 4], 1e-15, `B_${i}${j} centre value`);
    }
    // traces on grid lines: B_ij(u_r, v) = B_i(u_r|U) B_j(v|V)
    const tr = [[uB[2], 0.37], [uB[1], 0.81], [0.2, vB[1]], [0.66, vB[2]]];
    close(sl.crissCrossBasis({ u: uB, v: vB, i, j, atUV: tr }).values, tr.map(([a, b]) => basisAll(U, 2, a)[i] * basisAll(V, 2, b)[j]), 1e-14, `B_${i}${j} traces`);
  }
  close(sum, new Array(pts.length).fill(1), 1e-14, 'Σ B_ij = 1');
  const r1 = sl.crissCrossBasis({ u: uB, v: vB, i: 2, j: 2, atUV: pts, derivatives: 1 });
  isF64(r1.du, 'du'); isF64(r1.dv, 'dv');
  const hh = 1e-6, q = [[0.37, 0.52], [0.6, 0.41]];
  const f = (du, dv) => sl.crissCrossBasis({ u: uB, v: vB, i: 2, j: 2, atUV: q.map(([a, b]) => [a + du, b + dv]) }).values;
  const rd = sl.crissCrossBasis({ u: uB, v: vB, i: 2, j: 2, atUV: q, derivatives: 1 });
  close(rd.du, f(hh, 0).map((x, t) => (x - f(-hh, 0)[t]) / (2 * hh)), 1e-6, 'crissCrossBasis du = FD');
  close(rd.dv, f(0, hh).map((x, t) => (x - f(0, -hh)[t]) / (2 * hh)), 1e-6, 'crissCrossBasis dv = FD');
  throwsField(() => sl.crissCrossBasis({ u: uB, v: vB, i: m + 2, j: 0, atUV: pts }), 'i');
  throwsField(() => sl.crissCrossBasis({ u: uB, v: vB, i: 0, j: -1, atUV: pts }), 'j');
  throwsField(() => sl.crissCrossBasis({ u: [0, 0.5, 0.5, 1], v: vB, i: 0, j: 0, atUV: pts }), 'u');
});

test('crissCrossSurface: shape, interpolation, independent of C11, P2, control points, incompatible network', () => {
  const m = uB.length - 1, n = vB.length - 1;
  const r = defaultGrid(sl.crissCrossSurface, { network: netRand }, [0, 1], [0, 1], 'crissCrossSurface');
  surfaceShape(r, 3, 1600, 0, 'crissCrossSurface');
  isF64(r.controlPoints, 'controlPoints');
  eq(r.controlPoints.length, (m + 2) * (n + 2) * 3, 'controlPoints: (m+2)(n+2) points');
  checkInterpolates(sl.crissCrossSurface, { network: netRand }, netRand, 1e-12, 'crissCrossSurface');
  const uvs = [[0.1, 0.2], [0.5, 0.55], [0.77, 0.9], [0.31, 0.05]];
  const a = sl.crissCrossSurface({ network: netRand, C11: [1, 0, 3], atUV: uvs });
  const b = sl.crissCrossSurface({ network: netRand, C11: [1.5, 1.5, 32], atUV: uvs });
  close(a.points, b.points, 1e-11, 'the surface does not depend on C11');
  close(row(a.controlPoints, 1 * (n + 2) + 1, 3), [1, 0, 3], 0, 'controlPoints i-major, C_11 = the given C11');
  ok(Math.abs(a.controlPoints[3 * (2 * (n + 2) + 2)] - b.controlPoints[3 * (2 * (n + 2) + 2)]) > 1e-3, 'control points depend on C11');
  // with C11 = the tensor net's own C_11 the control points are the tensor net (round trip, surfaces.md §3)
  const rt = sl.crissCrossSurface({ network: netRand, C11: Crand[1][1], samplesU: 2, samplesV: 2 });
  close(rt.controlPoints, flat(Crand.flat()), 1e-12, 'round trip: C11 = C_11 gives back the control net');
  close(sl.crissCrossSurface({ network: netQuad, atUV: uvs }).points, flat(uvs.map(([u, v]) => quad(u, v))), 1e-12, 'S reproduces P2');
  fdSurface(sl.crissCrossSurface, { network: netRand }, [[0.2, 0.3], [0.66, 0.8]], 1e-6, 1e-5, 'crissCrossSurface');
  const badNet = JSON.parse(JSON.stringify(netRand)); badNet.P[2][2][2] += 0.1;
  throwsField(() => sl.crissCrossSurface({ network: badNet }), 'network', 'incompatible network');
  throwsField(() => sl.crissCrossSurface({ network: { ...netRand, P: netRand.P.slice(0, 3) } }), 'network');
  throwsField(() => sl.crissCrossSurface({ network: netRand, C11: [1, NaN, 0] }), 'C11');
});

test('thinPlateSurface: C11, energy, controlPoints, interpolation', () => {
  const m = uB.length - 1, n = vB.length - 1;
  const r = defaultGrid(sl.thinPlateSurface, { network: netRand }, [0, 1], [0, 1], 'thinPlateSurface');
  surfaceShape(r, 3, 1600, 0, 'thinPlateSurface');
  isF64(r.C11, 'C11'); eq(r.C11.length, 3, 'C11 is a 3D point');
  ok(typeof r.energy === 'number' || r.energy instanceof Float64Array, 'energy present');
  isF64(r.controlPoints, 'controlPoints'); eq(r.controlPoints.length, (m + 2) * (n + 2) * 3, 'controlPoints (m+2)(n+2)');
  close(row(r.controlPoints, n + 3, 3), r.C11, 0, 'controlPoints[1][1] = C11');
  checkInterpolates(sl.thinPlateSurface, { network: netRand }, netRand, 1e-12, 'thinPlateSurface');
  // separable x = u, y = v network on a uniform grid: C11* = (ξ_1, η_1)
  const uu = [0, 1 / 3, 2 / 3, 1];
  const sep = sl.networkFromFunction({ u: uu, v: uu, f: (u, v) => [u, v, Math.sin(u) * v] });
  close(sl.thinPlateSurface({ network: sep, samplesU: 2, samplesV: 2 }).C11.slice(0, 2), [1 / 6, 1 / 6], 1e-12, 'separable: C11* = (ξ_1, η_1)');
  fdSurface(sl.thinPlateSurface, { network: netRand }, [[0.2, 0.3], [0.66, 0.8]], 1e-6, 1e-5, 'thinPlateSurface');
  throwsField(() => sl.thinPlateSurface({ network: 5 }), 'network');
});

test('gordonSurface: knotsU/knotsV (Ũ, Ṽ), controlPoints 2m × 2n, tensor form, interpolation, P2', () => {
  const uu = [0, 1 / 3, 2 / 3, 1];
  const net3 = sl.networkFromFunction({ u: uu, v: [0, 0.5, 1], f: (u, v) => [u, v, Math.sin(u + 2 * v)] });
  const g3 = sl.gordonSurface({ network: net3, samplesU: 2, samplesV: 2 });
  isF64(g3.knotsU, 'knotsU');
  close(g3.knotsU, [0, 0, 0, 1 / 3, 1 / 2, 2 / 3, 1, 1, 1], 1e-15, 'Ũ for U = {0,0,0,1/3,2/3,1,1,1}');
  const m = uB.length - 1, n = vB.length - 1;
  const r = defaultGrid(sl.gordonSurface, { network: netRand }, [0, 1], [0, 1], 'gordonSurface');
  surfaceShape(r, 3, 1600, 0, 'gordonSurface');
  const ubar = [0, 0, 0, ...uB.slice(1, m - 1).map((x, i) => (x + uB[i + 2]) / 2), 1, 1, 1];
  const Ut = [...new Set([...clamped2(uB), ...ubar])].sort((a, b) => a - b);
  const Ufull = [0, 0, ...Ut, 1, 1];
  eq(r.knotsU.length, 2 * m + 3, '|Ũ| = 2m + 3');
  close(r.knotsU, Ufull, 1e-15, 'Ũ = U ∪ Ū (averaged knots)');
  eq(r.knotsV.length, 2 * n + 3, '|Ṽ| = 2n + 3');
  eq(r.controlPoints.length, 2 * m * 2 * n * 3, 'C̃ has 2m × 2n points');
  const C = Array.from({ length: 2 * m }, (_, i) => Array.from({ length: 2 * n }, (_, j) => row(r.controlPoints, i * 2 * n + j, 3)));
  const uvs = [[0.1, 0.2], [0.5, 0.55], [0.77, 0.9], [1, 0.3]];
  close(sl.gordonSurface({ network: netRand, atUV: uvs }).points, flat(uvs.map(([u, v]) => tensorBspline(Array.from(r.knotsU), 2, Array.from(r.knotsV), 2, C, u, v))), 1e-12, 'G = tensor B-spline on Ũ×Ṽ with C̃ (i-major)');
  checkInterpolates(sl.gordonSurface, { network: netRand }, netRand, 1e-12, 'gordonSurface');
  close(sl.gordonSurface({ network: netQuad, atUV: uvs }).points, flat(uvs.map(([u, v]) => quad(u, v))), 1e-12, 'G reproduces P2');
  fdSurface(sl.gordonSurface, { network: netRand }, [[0.2, 0.3], [0.66, 0.8]], 1e-6, 1e-5, 'gordonSurface');
  throwsField(() => sl.gordonSurface({ network: sl.networkFromFunction({ u: [0, 1], v: [0, 0.5, 1], f: (u, v) => [u, v, 0] }) }), 'network', 'requires m ≥ 2');
});

test('networkFromFunction: Schoenberg QI isocurves, compatible, accepted everywhere', () => {
  const f = (u, v) => [Math.sin(u), Math.cos(v), u * v * v];
  const net = sl.networkFromFunction({ u: uB, v: vB, f });
  eq(Object.keys(net).sort(), ['P', 'Q', 'u', 'v'], 'network keys {u, v, P, Q}');
  const m = uB.length - 1, n = vB.length - 1;
  eq(net.P.length, m + 1, 'P: r = 0..m'); ok(net.P.every((rw) => rw.length === n + 2), 'P[r]: j = 0..n+1');
  eq(net.Q.length, n + 1, 'Q: s = 0..n'); ok(net.Q.every((rw) => rw.length === m + 2), 'Q[s]: i = 0..m+1');
  const C = xi(uB).map((x) => xi(vB).map((y) => f(x, y)));
  const ref = networkOf(C, uB, vB);
  close(net.P.flat(2), ref.P.flat(2), 1e-14, 'P = isocurves of the Schoenberg QI');
  close(net.Q.flat(2), ref.Q.flat(2), 1e-14, 'Q = isocurves of the Schoenberg QI');
  for (const fn of ['crissCrossSurface', 'thinPlateSurface', 'gordonSurface']) ok(sl[fn]({ network: net, samplesU: 3, samplesV: 3 }).points.length === 27, `${fn} accepts it`);
  throwsField(() => sl.networkFromFunction({ u: uB, v: vB, f: () => [0, 0] }), 'f');
  throwsField(() => sl.networkFromFunction({ u: [0, 1, 0.5], v: vB, f }), 'u');
});

// ---------------------------------------------------------------------------------------------------------
// Knot modification (surfaces.md §7)
const kmSurface = {
  orderU: 4, orderV: 3, knotsU: [0, 0, 0, 0, 1, 2, 3, 4, 4, 4, 4], knotsV: [0, 0, 0, 1, 2, 2, 2],
  controlPoints: Array.from({ length: 7 }, (_, r) => Array.from({ length: 4 }, (_, s) => [r, s, Math.sin(r + 2 * s)])),
};

test('knotModifiedSurface: equals the tensor B-spline with the modified knot vector', () => {
  const S = kmSurface, uvs = [[0.5, 0.5], [1.5, 1.2], [2.2, 0.3], [3.9, 1.9], [4, 2]];
  const opts = { surface: S, p: 5, up: 1.6, atUV: uvs };
  const r = sl.knotModifiedSurface(opts);
  surfaceShape(r, 3, uvs.length, 0, 'knotModifiedSurface');
  const ku = S.knotsU.slice(); ku[5] = 1.6;
  close(r.points, flat(uvs.map(([u, v]) => tensorBspline(ku, 3, S.knotsV, 2, S.controlPoints, u, v))), 1e-12, 'p moved inside its neighbours');
  const kv = S.knotsV.slice(); kv[3] = 1.3;
  close(sl.knotModifiedSurface({ surface: S, q: 3, vq: 1.3, atUV: uvs }).points, flat(uvs.map(([u, v]) => tensorBspline(S.knotsU, 3, kv, 2, S.controlPoints, u, v))), 1e-12, 'q moved');
  close(sl.knotModifiedSurface({ surface: S, p: 5, up: 1.6, q: 3, vq: 1.3, atUV: uvs }).points, flat(uvs.map(([u, v]) => tensorBspline(ku, 3, kv, 2, S.controlPoints, u, v))), 1e-12, 'both moved');
  close(sl.knotModifiedSurface({ surface: S, p: 5, up: 2, atUV: uvs }).points, flat(uvs.map(([u, v]) => tensorBspline(S.knotsU, 3, S.knotsV, 2, S.controlPoints, u, v))), 1e-12, 'unmoved knot = the original surface');
  const far = sl.knotModifiedSurface({ surface: S, p: 5, up: 1e8, atUV: uvs });
  ok(Array.from(far.points).every(Number.isFinite), 'extended path value finite at 1e8');
  throwsField(() => sl.knotModifiedSurface({ surface: S, p: 5, up: NaN, atUV: uvs }), 'up');
  throwsField(() => sl.knotModifiedSurface({ surface: S, p: 50, up: 1, atUV: uvs }), 'p');
  throwsField(() => sl.knotModifiedSurface({ surface: { ...S, knotsU: S.knotsU.slice(1) }, p: 5, up: 1.6, atUV: uvs }), ['surface', 'knotsU']);
});

test('knotEnvelope: surface result, e(u_p, v) = s(u_p, v), e_w = (k−2)/(k−1) s_u there', () => {
  const S = kmSurface, vs = [0.2, 0.9, 1.5], up = S.knotsU[5];
  const r = sl.knotEnvelope({ surface: S, p: 5, atUV: vs.map((v) => [up, v]), derivatives: 1 });
  surfaceShape(r, 3, vs.length, 1, 'knotEnvelope');
  close(r.points, flat(vs.map((v) => tensorBspline(S.knotsU, 3, S.knotsV, 2, S.controlPoints, up, v))), 1e-12, '(10): e(u_p, v) = s(u_p, v; u_p)');
  const h = 1e-6;
  const su = vs.map((v) => scale(sub(tensorBspline(S.knotsU, 3, S.knotsV, 2, S.controlPoints, up + h, v), tensorBspline(S.knotsU, 3, S.knotsV, 2, S.controlPoints, up - h, v)), 1 / (2 * h)));
  close(r.du, flat(su.map((x) => scale(x, 2 / 3))), 1e-6, '(9): e_w(u_p, v) = (k−2)/(k−1) s_u');
  const r2 = sl.knotEnvelope({ surface: S, p: 5, q: 3, atUV: [[up, S.knotsV[3]]] });
  close(r2.points, tensorBspline(S.knotsU, 3, S.knotsV, 2, S.controlPoints, up, S.knotsV[3]), 1e-12, 'eq. (8) at (u_p, v_q) = s(u_p, v_q)');
  throwsField(() => sl.knotEnvelope({ surface: S, p: -1, atUV: [[1, 1]] }), 'p');
});

test('knotPaths: one path per (u, v), from → to', () => {
  const S = kmSurface, pts = [[1.5, 0.5], [2.5, 1.2], [1.2, 1.9]];
  const r = sl.knotPaths({ surface: S, p: 5, points: pts, from: 1.2, to: 2.8, samples: 9 });
  ok(Array.isArray(r.paths) && r.paths.length === pts.length, 'paths: one per point');
  r.paths.forEach((path, i) => {
    const P = path.points ?? path;
    isF64(P, `paths[${i}]`);
    eq(P.length, 9 * 3, `paths[${i}]: samples points in 3D`);
    const [u, v] = pts[i];
    const at = (x) => { const ku = S.knotsU.slice(); ku[5] = x; return tensorBspline(ku, 3, S.knotsV, 2, S.controlPoints, u, v); };
    close(P.slice(0, 3), at(1.2), 1e-12, 'path starts at up = from');
    close(P.slice(24, 27), at(2.8), 1e-12, 'path ends at up = to');
    close(P.slice(12, 15), at(2.0), 1e-12, 'path midpoint');
  });
  throwsField(() => sl.knotPaths({ surface: S, p: 5, points: [[1, NaN]], from: 1.2, to: 2.8, samples: 9 }), 'points');
  throwsField(() => sl.knotPaths({ surface: S, p: 5, points: pts, from: 1.2, to: 2.8, samples: 2_000_000 }), 'samples');
});

test('limits and robustness across functions', () => {
  const many = Array.from({ length: 100_001 }, (_, i) => [i, Math.sin(i)]);
  throwsField(() => sl.quasiCubicCurve({ points: many, alpha: 1, samples: 3 }), 'points', '> 100,000 input points');
  throwsField(() => sl.b2Curve({ points: many, samples: 3 }), 'points', '> 100,000 input points');
  throwsField(() => sl.quasiCubicCurve({ points: [[0, 0], [1, 1], [2, 0], [3, 1]], alpha: 1, at: new Array(1_000_001).fill(0.5) }), 'at', '> 1,000,000 evaluation points');
  throwsField(() => sl.crissCrossSurface({ network: netRand, samplesU: 1001, samplesV: 1000 }), ['samplesU', 'samplesV', 'samples']);
  throwsField(() => sl.crissCrossSurface({ network: { ...netRand, u: [0, 0.3, NaN, 0.8, 1] } }), 'network');
  throwsField(() => sl.bsplineCurve({ degree: 1, knots: [0, 0, 1, 1], points: [[0, 0], [1, 1]], samples: 3, derivatives: Infinity }), 'derivatives');
});

test('check count', () => { console.log(`# contract checks: ${checks}`); });
