// Benchmark (not a test): the rows of the engine issue's table, each side by side with its peer in this one
// Node process, same work (same curve or surface, same parameters, same output: a flat Float64Array of all
// points), same repetitions, interleaved. Prints median and minimum (labelled) and the ratios on both.
// Outputs are compared first (max |difference| relative to the data's size must be ≤ 1e-10).
//
//   scripts/build-wasm.sh && (cd benches && npm ci --ignore-scripts) && node benches/engine.mjs
//   REPS=7 N=1000000 G=500 node benches/engine.mjs [row-name-substring]
//   PKG=/path/to/other/pkg-node node benches/engine.mjs at   (the same rows on another build)
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';
import { cpus, loadavg } from 'node:os';

const require = createRequire(import.meta.url);
const here = dirname(fileURLToPath(import.meta.url));
const root = join(here, '..');
// PKG=<dir with splinelab.js> runs another build (e.g. a copy of main's pkg-node) for before/after runs
const sl = require(process.env.PKG ? join(process.env.PKG, 'splinelab.js') : join(root, 'pkg-node/splinelab.js'));
// verb's optional worker addon is not installed (--ignore-scripts); stub it, and silence its load message
const Module = require('node:module');
const load = Module._load;
Module._load = function (req, ...rest) { return req === 'webworker-threads' ? { Worker: class {} } : load.call(this, req, ...rest); };
const log = console.log; console.log = () => {};
const verb = require(join(here, 'node_modules/verb-nurbs'));
console.log = log;
Module._load = load;

const REPS = Number(process.env.REPS || 7);
const N = Number(process.env.N || 1_000_000);
const G = Number(process.env.G || 500);
const only = process.argv[2];

console.log(`engine benchmark — ${new Date().toISOString()}, ${process.version}, ${cpus()[0]?.model} ×${cpus().length}, load ${loadavg().map((x) => x.toFixed(1)).join(' ')}`);
console.log(`N = ${N} curve points, G = ${G}² surface points, ${REPS} interleaved repetitions; median (min) in ms\n`);

const median = (xs) => { const s = [...xs].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };
const now = () => Number(process.hrtime.bigint()) / 1e6;

/** Times `fns` (name → () => result) interleaved, REPS times each after one warm-up; returns stats. */
function race(fns, { warm = 1, reps = REPS } = {}) {
  const names = Object.keys(fns);
  const t = Object.fromEntries(names.map((k) => [k, []]));
  for (let w = 0; w < warm; w++) for (const k of names) fns[k]();
  for (let r = 0; r < reps; r++) {
    for (const k of names) {
      globalThis.gc?.();
      const t0 = now();
      fns[k]();
      t[k].push(now() - t0);
    }
  }
  return Object.fromEntries(names.map((k) => [k, { med: median(t[k]), min: Math.min(...t[k]) }]));
}

function agree(name, a, b) {
  if (a.length !== b.length) throw new Error(`${name}: lengths ${a.length} vs ${b.length}`);
  let worst = 0, scale = 1;
  for (let i = 0; i < a.length; i++) { worst = Math.max(worst, Math.abs(a[i] - b[i])); scale = Math.max(scale, Math.abs(b[i])); }
  if (!(worst <= 1e-10 * scale)) throw new Error(`${name}: outputs differ by ${worst} (scale ${scale})`);
  return worst / scale;
}

const rows = [];
function report(name, goal, ours, peer, diff) {
  const rMed = peer.med / ours.med, rMin = peer.min / ours.min;
  const line = `${name.padEnd(62)} ours ${ours.med.toFixed(1)} (${ours.min.toFixed(1)})  peer ${peer.med.toFixed(1)} (${peer.min.toFixed(1)})  ratio ${rMed.toFixed(2)}× median, ${rMin.toFixed(2)}× min  [goal ${goal}]${diff !== undefined ? `  agree ${diff.toExponential(1)}` : ''}`;
  console.log(line);
  rows.push({ name, goal, ours, peer, rMed, rMin });
}

// verb's fastest evaluator (non-rational), writing into one Float64Array like our result
function verbCurve(degree, knots, ctrl, params) {
  const data = new verb.core.NurbsCurveData(degree, knots, ctrl);
  const dim = ctrl[0].length;
  return () => {
    const out = new Float64Array(params.length * dim);
    for (let i = 0; i < params.length; i++) { const p = verb.eval.Eval.curvePoint(data, params[i]); for (let d = 0; d < dim; d++) out[dim * i + d] = p[d]; }
    return out;
  };
}
function verbSurface(p, q, ku, kv, net, us, vs) {
  const data = new verb.core.NurbsSurfaceData(p, q, ku, kv, net);
  return () => {
    const out = new Float64Array(us.length * vs.length * 3);
    let k = 0;
    for (const u of us) for (const v of vs) { const s = verb.eval.Eval.surfacePoint(data, u, v); out[k++] = s[0]; out[k++] = s[1]; out[k++] = s[2]; }
    return out;
  };
}
const uniform = (a, b, n) => { const s = (b - a) / (n - 1); const x = new Float64Array(n); for (let i = 0; i < n; i++) x[i] = a + s * i; x[n - 1] = b; return x; };
const pts2 = (r) => Array.from(r.points.length ? { length: r.points.length / r.dim } : [], (_, i) => Array.from(r.points.subarray(i * r.dim, i * r.dim + r.dim)));
const want = (name) => !only || name.includes(only);

// data: 100 points on a wobbly spiral
const W = Array.from({ length: 100 }, (_, i) => { const t = i * 0.15; return [(1 + t) * Math.cos(t) + 0.1 * Math.sin(7 * t), (1 + t) * Math.sin(t)]; });

// 1. b2Curve vs verb on the same cubic, 2. vs bsplineCurve on its own cubic
if (want('b2Curve')) {
  const opts = { points: W, a: 0.05, samples: N };
  const r = sl.b2Curve(opts);
  const ctrl = pts2({ points: r.controlPoints, dim: 2 });
  const knots = Array.from(r.knots);
  const peer = verbCurve(3, knots, ctrl, r.params);
  const d = agree('b2Curve vs verb', sl.b2Curve(opts).points, peer());
  const t = race({ ours: () => sl.b2Curve(opts).points, peer });
  report('b2Curve 1M vs verb-nurbs on the same cubic', '≥ 10×', t.ours, t.peer, d);
  const bs = { degree: 3, knots, points: ctrl, samples: N };
  const d2 = agree('b2Curve vs bsplineCurve', sl.b2Curve(opts).points, sl.bsplineCurve(bs).points);
  const t2 = race({ b2: () => sl.b2Curve(opts).points, bs: () => sl.bsplineCurve(bs).points });
  const slow = t2.b2.med / t2.bs.med, slowMin = t2.b2.min / t2.bs.min;
  console.log(`${'b2Curve vs bsplineCurve on its own cubic (cost ratio)'.padEnd(62)} b2 ${t2.b2.med.toFixed(1)} (${t2.b2.min.toFixed(1)})  bspline ${t2.bs.med.toFixed(1)} (${t2.bs.min.toFixed(1)})  b2 costs ${slow.toFixed(2)}× median, ${slowMin.toFixed(2)}× min  [goal ≤ 1.5×]  agree ${d2.toExponential(1)}`);
}

// 3. quasiCubicCurve vs verb's cubic on the same polygon (clamped uniform cubic B-spline)
if (want('quasiCubic')) {
  const opts = { points: W, alpha: 1, samples: N };
  const r = sl.quasiCubicCurve(opts);
  const n = W.length; // clamped uniform cubic on the same control polygon
  const knots = [0, 0, 0, ...Array.from({ length: n - 2 }, (_, i) => i), n - 3, n - 3, n - 3];
  const peer = verbCurve(3, knots, W, uniform(0, n - 3, N));
  const t = race({ ours: () => sl.quasiCubicCurve(opts).points, peer });
  report('quasiCubicCurve 1M vs verb\'s cubic on the same polygon', '≥ 10×', t.ours, t.peer);
  void r;
  // a general α (0.5: both trigonometric and polynomial parts of the basis) against the B-spline sampler on
  // the same polygon and against verb, after ≥ 10 warm-up calls each (V8's optimizing tier), median of ≥ 15
  const half = { points: W, alpha: 0.5, samples: N };
  const bs = { degree: 3, points: W, samples: N };
  const reps = Math.max(REPS, 15);
  const tb = race({ qc: () => sl.quasiCubicCurve(half).points, bs: () => sl.bsplineCurve(bs).points }, { warm: 10, reps });
  console.log(`${'quasiCubicCurve α = 0.5 1M vs bsplineCurve 1M (cost ratio)'.padEnd(62)} qc ${tb.qc.med.toFixed(1)} (${tb.qc.min.toFixed(1)})  bspline ${tb.bs.med.toFixed(1)} (${tb.bs.min.toFixed(1)})  qc costs ${(tb.qc.med / tb.bs.med).toFixed(2)}× median, ${(tb.qc.min / tb.bs.min).toFixed(2)}× min  [goal ≤ 1×]`);
  const th = race({ ours: () => sl.quasiCubicCurve(half).points, peer }, { warm: 10, reps });
  report('quasiCubicCurve α = 0.5 1M vs verb\'s cubic on the same polygon', '≥ 10×', th.ours, th.peer);
}

// 5. knotModifiedCurve vs verb on the modified knots
if (want('knotModifiedCurve')) {
  const n = W.length, k = 4;
  const knots = [0, 0, 0, 0, ...Array.from({ length: n - 4 }, (_, i) => i + 1), n - 3, n - 3, n - 3, n - 3];
  const p = 50, up = (knots[p - 1] + knots[p + 1]) / 2 + 0.3;
  const opts = { curve: { order: k, knots, controlPoints: W }, p, up, samples: N };
  const r = sl.knotModifiedCurve(opts);
  const mk = Array.from(r.knots);
  const peer = verbCurve(3, mk, W, r.params);
  const d = agree('knotModifiedCurve vs verb', r.points, peer());
  const t = race({ ours: () => sl.knotModifiedCurve(opts).points, peer });
  report('knotModifiedCurve 1M vs verb on the modified knots', '≥ 10×', t.ours, t.peer, d);
}

// 7. bezierRemodel vs verb on the same g* (a B-spline with (m+1)-fold interior knots)
if (want('bezierRemodel')) {
  const m = 3, L = 33;
  const pts = W.slice(0, m * L + 1);
  const breaks = Array.from({ length: L + 1 }, (_, i) => i);
  const opts = { points: pts, degree: m, breaks, samples: N };
  const r = sl.bezierRemodel(opts);
  const ctrl = pts2({ points: r.controlPoints, dim: 2 });
  const knots = [0]; for (let i = 0; i <= L; i++) for (let j = 0; j <= m; j++) knots.push(i); knots.push(L); // each break m+1 times, ends m+2
  const peer = verbCurve(m + 1, knots, ctrl, r.params);
  const d = agree('bezierRemodel vs verb', r.points, peer());
  const t = race({ ours: () => sl.bezierRemodel(opts).points, peer });
  report('bezierRemodel 1M vs verb on the same g*', '≥ 10×', t.ours, t.peer, d);
}

// 8. 1M explicit parameters (a Float64Array) vs 1M samples, same curve
if (want('at')) {
  const ctrl = W;
  const at = uniform(0, 1, N);
  const bs = { degree: 3, points: ctrl };
  const d = agree('at vs samples', sl.bsplineCurve({ ...bs, at }).points, sl.bsplineCurve({ ...bs, samples: N }).points);
  const t = race({ at: () => sl.bsplineCurve({ ...bs, at }).points, samples: () => sl.bsplineCurve({ ...bs, samples: N }).points });
  console.log(`${'bsplineCurve 1M at (Float64Array) vs 1M samples (cost ratio)'.padEnd(62)} at ${t.at.med.toFixed(1)} (${t.at.min.toFixed(1)})  samples ${t.samples.med.toFixed(1)} (${t.samples.min.toFixed(1)})  at costs ${(t.at.med / t.samples.med).toFixed(2)}× median, ${(t.at.min / t.samples.min).toFixed(2)}× min  [goal ≤ 2×]  agree ${d.toExponential(1)}`);
  const b2 = { points: W, a: 0.05 };
  const dom = sl.b2Curve({ ...b2, samples: 2 }).domain;
  const at2 = uniform(dom[0], dom[1], N);
  const t2 = race({ at: () => sl.b2Curve({ ...b2, at: at2 }).points, samples: () => sl.b2Curve({ ...b2, samples: N }).points });
  console.log(`${'b2Curve 1M at (Float64Array) vs 1M samples (cost ratio)'.padEnd(62)} at ${t2.at.med.toFixed(1)} (${t2.at.min.toFixed(1)})  samples ${t2.samples.med.toFixed(1)} (${t2.samples.min.toFixed(1)})  at costs ${(t2.at.med / t2.samples.med).toFixed(2)}× median, ${(t2.at.min / t2.samples.min).toFixed(2)}× min  [goal ≤ 2×]`);
  // the same with derivatives: 2 (values and both derivatives in one pass on both sides)
  const d3 = agree('at vs samples, derivatives 2', sl.bsplineCurve({ ...bs, at, derivatives: 2 }).d2, sl.bsplineCurve({ ...bs, samples: N, derivatives: 2 }).d2);
  const t3 = race({ at: () => sl.bsplineCurve({ ...bs, at, derivatives: 2 }).points, samples: () => sl.bsplineCurve({ ...bs, samples: N, derivatives: 2 }).points });
  console.log(`${'bsplineCurve 1M at vs samples, derivatives 2 (cost ratio)'.padEnd(62)} at ${t3.at.med.toFixed(1)} (${t3.at.min.toFixed(1)})  samples ${t3.samples.med.toFixed(1)} (${t3.samples.min.toFixed(1)})  at costs ${(t3.at.med / t3.samples.med).toFixed(2)}× median, ${(t3.at.min / t3.samples.min).toFixed(2)}× min  [goal ≤ 2×]  agree ${d3.toExponential(1)}`);
  // quasi-cubic: explicit parameters (runs sharing one Taylor expansion of a segment) vs uniform samples (blocks sharing one sin/cos table)
  const qdom = sl.quasiCubicCurve({ points: W, alpha: 1, samples: 2 }).domain;
  const qat = uniform(qdom[0], qdom[1], N);
  for (const derivatives of [0, 2]) {
    const q = { points: W, alpha: 1, derivatives };
    const key = derivatives ? 'd2' : 'points';
    const dq = agree('quasi-cubic at vs samples', sl.quasiCubicCurve({ ...q, at: qat })[key], sl.quasiCubicCurve({ ...q, samples: N })[key]);
    const tq = race({ at: () => sl.quasiCubicCurve({ ...q, at: qat }).points, samples: () => sl.quasiCubicCurve({ ...q, samples: N }).points });
    console.log(`${`quasiCubicCurve 1M at vs samples, derivatives ${derivatives} (cost ratio)`.padEnd(62)} at ${tq.at.med.toFixed(1)} (${tq.at.min.toFixed(1)})  samples ${tq.samples.med.toFixed(1)} (${tq.samples.min.toFixed(1)})  at costs ${(tq.at.med / tq.samples.med).toFixed(2)}× median, ${(tq.at.min / tq.samples.min).toFixed(2)}× min  [goal ≤ 2×]  agree ${dq.toExponential(1)}`);
  }
}

// 4. b2Surface (a = 1/6: the tensor cubic B-spline on the inner grid) vs verb's bicubic
if (want('b2Surface')) {
  const m = 20, n = 20;
  const ku = Array.from({ length: m + 4 }, (_, i) => i - 2 + 0.1 * Math.sin(i)), kv = Array.from({ length: n + 4 }, (_, j) => 0.5 * j);
  const grid = ku.map((x, i) => kv.map((y, j) => [x, y, Math.cos(0.4 * i) * Math.sin(0.3 * j + 1)]));
  const opts = { grid, knotsU: ku, knotsV: kv, a: 1 / 6, samplesU: G, samplesV: G };
  const r = sl.b2Surface(opts);
  const [u0, u1, v0, v1] = r.domain;
  const net = grid.slice(1, m + 3).map((rw) => rw.slice(1, n + 3));
  const KU = [ku[0], ...ku, ku[ku.length - 1]], KV = [kv[0], ...kv, kv[kv.length - 1]];
  const peer = verbSurface(3, 3, KU, KV, net, uniform(u0, u1, G), uniform(v0, v1, G));
  const d = agree('b2Surface vs verb', r.points, peer());
  const t = race({ ours: () => sl.b2Surface(opts).points, peer });
  report(`b2Surface ${G}² vs verb's bicubic`, '≥ 10×', t.ours, t.peer, d);
}

// 6. knotModifiedSurface vs verb on the modified knots
if (want('knotModifiedSurface')) {
  const nu = 20, nv = 20;
  const controlPoints = Array.from({ length: nu }, (_, r) => Array.from({ length: nv }, (_, s) => [r, s, Math.sin(0.5 * r) * Math.cos(0.4 * s)]));
  const kn = (n) => [0, 0, 0, 0, ...Array.from({ length: n - 4 }, (_, i) => i + 1), n - 3, n - 3, n - 3, n - 3];
  const surface = { orderU: 4, orderV: 4, knotsU: kn(nu), knotsV: kn(nv), controlPoints };
  const opts = { surface, p: 8, up: 5.3, q: 10, vq: 7.6, samplesU: G, samplesV: G };
  const r = sl.knotModifiedSurface(opts);
  const [u0, u1, v0, v1] = r.domain;
  const peer = verbSurface(3, 3, Array.from(r.knotsU), Array.from(r.knotsV), controlPoints, uniform(u0, u1, G), uniform(v0, v1, G));
  const d = agree('knotModifiedSurface vs verb', r.points, peer());
  const t = race({ ours: () => sl.knotModifiedSurface(opts).points, peer });
  report(`knotModifiedSurface ${G}² vs verb`, '≥ 10×', t.ours, t.peer, d);
}
