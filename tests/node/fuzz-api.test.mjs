// API fuzzer (issue 9): calls every exported function of the wasm module with valid, mutated and garbage
// options. Required: zero traps (WebAssembly.RuntimeError), every failure a JS Error whose message names the
// field ("<field>: …"), no call over 2 s, a valid call right after any error still works, and — for accepted
// calls whose input is finite and moderate (|x| ≤ 1e6) — only finite numbers in the result.
//
//   scripts/build-wasm.sh && node --test tests/node/fuzz-api.test.mjs      short mode (CI): 100,000 calls, seed 1
//   FUZZ_CALLS=1000000 FUZZ_SEED=7 node --test tests/node/fuzz-api.test.mjs   long mode
//   FUZZ_ONLY=b2Curve,knotPaths …                                            fuzz only these exports
//
// Figures (details, the bug list and the regression tests: tests/ROBUSTNESS.md):
//   short mode: 100,000 calls, seed 1, 42 exports (all the module had then: it fuzzes every export, 49 on 2026-11-27), 59–150 s here (2 cores, load 5–12): 0 traps, 0 bad messages,
//     0 failures after an error. No finding is excused: the slow curve-network calls (bug 5) have API limits
//     instead, checked at and beyond the limits by the second test below.
//   long mode: 1,000,000 calls, seed 7, 42 exports (then), 495 s: 0 traps, 0 bad messages, 0 failures after an
//     error; non-finite/slow findings all belong to the open bugs 4, 6, 8–11 of tests/ROBUSTNESS.md.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';
import { openSync, writeSync } from 'node:fs';

const require = createRequire(import.meta.url);
const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const sl = require(join(root, 'pkg-node/splinelab.js'));

const CALLS = Number(process.env.FUZZ_CALLS || 100_000);
const SEED = Number(process.env.FUZZ_SEED || 1);
const ONLY = process.env.FUZZ_ONLY ? new Set(process.env.FUZZ_ONLY.split(',')) : null;
const SLOW_MS = 2000;
const DEBUG = !!process.env.FUZZ_DEBUG;
const DEBUG_FD = DEBUG ? openSync(process.env.FUZZ_DEBUG, 'w') : null;

// ---------- a seeded PRNG (mulberry32) ----------
function rng(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
const R = rng(SEED);
const pick = (xs) => xs[Math.floor(R() * xs.length)];
const chance = (p) => R() < p;

// ---------- valid example calls (shapes of ../shared/spec/api.md and the src/api/*.rs headers) ----------
const grid = (rows, cols, f) => Array.from({ length: rows }, (_, i) => Array.from({ length: cols }, (_, j) => f(i, j)));
const pts2 = (n) => Array.from({ length: n }, (_, i) => [i, Math.sin(i * 1.3) * 2]);
const pts3 = (n) => Array.from({ length: n }, (_, i) => [i, Math.sin(i * 1.3) * 2, Math.cos(i)]);
const ptsD = (n) => (chance(0.7) ? pts2(n) : pts3(n));
const surf = () => ({
  orderU: 3, orderV: 3, knotsU: [0, 0, 0, 1, 2, 2, 2], knotsV: [0, 0, 0, 1, 2, 2, 2],
  controlPoints: grid(4, 4, (i, j) => [i, j, Math.sin(i + j)]),
});
const curveK = () => ({ order: 4, knots: [0, 0, 0, 0, 1, 2, 3, 3, 3, 3], controlPoints: ptsD(6) });
const safe = (f) => { try { return f(); } catch { return undefined; } };
const has = (name) => typeof sl[name] === 'function';
const NETS = [];
if (has('networkFromFunction')) {
  NETS.push(safe(() => sl.networkFromFunction({ u: [0, 0.4, 1], v: [0, 0.5, 1], f: (u, v) => [u, v, u * v + u * u] })));
}
if (has('networkExample')) for (const name of ['uniform-dome', 'three-sided', 'nonuniform-dome']) NETS.push(safe(() => sl.networkExample({ name })));
const NET_LIST = NETS.filter(Boolean);
const net = () => (NET_LIST.length ? pick(NET_LIST) : undefined);
const NET_NAMES = ['uniform-dome', 'uniform-random', 'nonuniform-dome', 'three-sided', 'strongly-nonuniform', 'separable', 'free-data', 'dome10'];
const QC_PRESETS = ['ellipse', 'circle', 'parabola', 'sine', 'sphere', 'cylinder', 'torus', 'bowl', 'wavy'];
const QC_SHAPES = has('quasiCubicPreset')
  ? ['ellipse', 'circle', 'parabola', 'sine'].map((name) => safe(() => ({ name, ...sl.quasiCubicPreset({ name }) }))).filter(Boolean)
  : [];
const noisy = () => (has('noisyData') ? safe(() => sl.noisyData({ curve: 'sine', count: 15, sigma: 0.05, seed: 3, truthSamples: 20 })) : undefined);
const NOISY = noisy();
const noisyPts = () => {
  if (!NOISY) return pts2(15);
  const p = NOISY.points;
  return Array.from({ length: p.length / 2 }, (_, i) => [p[2 * i], p[2 * i + 1]]);
};
const b2Variant = () => pick([
  {},
  { tension: 0.2 },
  { tension: [0.1, 0.15, 0.2, 0.25] },
  { autoTension: 'paper' },
  { autoTension: 'turning', autoTensionScale: 0.3 },
  { knots: 'uniform' },
  { knots: [-1, 0, 1.5, 2, 3, 4, 5] },
  { K: 20 },
  { c2: 2 },
  { construction: 'section3', knots: 'uniform', a: 0.05 },
]);

const EXAMPLES = {
  bsplineCurve: () => ({ degree: 3, knots: [0, 0, 0, 0, 0.5, 1, 1, 1, 1], points: ptsD(5), samples: 20, derivatives: 2 }),
  bsplineBasis: () => ({ degree: 2, knots: [0, 0, 0, 0.5, 1, 1, 1], at: [0, 0.3, 1], derivatives: 1 }),
  bsplineDeBoor: () => ({ degree: 3, knots: [0, 0, 0, 0, 0.5, 1, 1, 1, 1], points: ptsD(5), u: pick([0, 0.25, 0.5, 0.9, 1]) }),
  bsplineInsertKnot: () => ({ degree: pick([1, 2, 3]), points: ptsD(5), u: pick([0, 0.25, 0.5, 0.9, 1]) }),
  quasiCubicBasis: () => ({ alpha: 0.5, at: [0, 0.5, 1], derivatives: pick([0, 1, 2, 3]) }),
  quasiCubicCurve: () => (chance(0.8) ? { points: ptsD(6), alpha: 1, samples: 20, derivatives: 1 } : { points: ptsD(5), alpha: -1, closed: true, samples: 20, derivatives: 2 }),
  quasiCubicInterpolation: () => ({ points: ptsD(6), beta: pick(['curvature', undefined, [1, 0.5, 0, 2]]), k: pick([2, 3, 5]), curvature: chance(0.5), samples: 20, derivatives: 2 }),
  quasiCubicSurface: () => ({ grid: grid(4, 5, (i, j) => [i, j, i * j]), alpha: 1, samplesU: 5, samplesV: 5, derivatives: 1, mesh: chance(0.5) }),
  quasiCubicBlendedSurface: () => ({ grid: grid(5, 5, (i, j) => [i, j, Math.sin(i * j)]), beta: grid(3, 3, () => 1), k: 3, samplesU: 5, samplesV: 5, derivatives: 1 }),
  quasiCubicPreset: () => ({ name: pick(QC_PRESETS), segments: 4, m: 4, n: 4 }),
  quasiCubicShapeCheck: () => {
    const s = QC_SHAPES.length ? pick(QC_SHAPES) : { name: 'circle', points: pts2(8), alpha: 1 };
    return { shape: s.name, points: s.points, alpha: s.alpha, samples: 20 };
  },
  b2Curve: () => { const v = b2Variant(); return { points: v.autoTension === 'turning' ? pts2(7) : ptsD(7), a: 0.1, samples: 20, derivatives: 2, eq5: pick([undefined, 'corrected', 'printed']), ...v }; },
  b2Surface: () => ({
    grid: grid(6, 6, (i, j) => [i, j, Math.cos(i - j)]), a: 0, samplesU: 5, samplesV: 5, derivatives: 1,
    ...pick([{}, { knotsU: 'uniform', tensionV: [0.1, 0.2, 0.1] }, { knotsV: [-1, 0, 1, 2, 3, 4], c2: 2 }]),
  }),
  b2Basis: () => (chance(0.5)
    ? { knots: 'uniform', count: 8, a: 0.1, samples: 10, derivatives: 2 }
    : { points: pts2(7), samples: 10, derivatives: 1, ...b2Variant() }),
  fitNames: () => ({}),
  noisyData: () => ({ curve: pick(['sine', 'arc', 'lemniscate', 'spiral', 'step']), count: 30, sigma: 0.05, seed: 3, truthSamples: 50 }),
  dataset: () => ({ name: pick(['titanium_heat', 'rpn14']) }),
  b2Fit: () => ({ points: noisyPts(), a: 0.05, truthCurve: 'sine', errorSamples: 50, samples: 20, derivatives: 1 }),
  b2FitSweep: () => ({ points: noisyPts(), aMin: -0.1, aMax: 0.2, steps: 4, cv: chance(0.5), truthCurve: 'sine', errorSamples: 20 }),
  splineBlendedSurface: () => pick([
    { network: (u, v) => [u, v, u * v], uKnots: [0, 0.5, 1], vKnots: [0, 0.3, 1], blend: 'cubic-natural', samplesU: 5, samplesV: 5 },
    { network: (u, v) => [u, v, Math.sin(u + v)], uKnots: [-1, 0, 1, 2, 3, 4], vKnots: [-1, 0, 1, 2, 3, 4], blend: 'b2', a: 0.1, samplesU: 5, samplesV: 5, derivatives: 1 },
    { network: net(), samplesU: 5, samplesV: 5, blend: 'cubic-natural' },
    { network: (u, v) => [u, v, u * u - v], uKnots: [0, 0.2, 0.5, 1], vKnots: [0, 0.3, 0.6, 1], blend: 'cubic-notaknot', samplesU: 5, samplesV: 5 },
  ]),
  bezierRemodel: () => ({
    points: [[10, 16], [7, 21], [3, 9], [0, 0], [-4, 0], [-8, 0], [-6, 3], [-4, 6], [2, 2], [8, -2], [10, 3]],
    degree: 2, breaks: [0, 1, 1.75, 2.5, 3.25, 4],
    alphas: [[2 / 3, 1 / 20], [19 / 20, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 10]], r: 1, samples: 20, derivatives: 2,
  }),
  bezierSpline: () => ({ points: ptsD(7), degree: 3, breaks: [0, 1, 2], samples: 20, derivatives: 2 }),
  bezierDeCasteljau: () => ({ points: ptsD(7), degree: 3, breaks: [0, 1, 2], u: pick([0, 0.4, 1, 1.7, 2]) }),
  curveFacts: () => ({ points: Float64Array.from(pts2(40).flat()), ...(chance(0.5) ? { data: pts2(5) } : {}) }),
  bsplineToBezier: () => ({ degree: 3, knots: [0, 0, 0, 0, 0.5, 1, 1, 1, 1], points: ptsD(5) }),
  bezierRemodelSurface: () => ({
    points: grid(3, 2, (k, l) => [k, l, k * l]), degreeU: 2, degreeV: 1, breaksU: [0, 1], alphas: [[2 / 3, 1 / 3]], r: 1, samplesU: 4, samplesV: 4,
  }),
  bezierRemodelSurfaceBi: () => ({
    points: grid(5, 5, (k, l) => [k, l, (k * l) % 3]), breaksU: [0, 1, 2], breaksV: [0, 1, 2],
    alphas: chance(0.5) ? [[0.6, 0.3], [null, 0.3]] : [0, 1, 2, 3, 4].map(() => [[0.6, 0.3], [0.7, 0.2]]),
    betas: [[0.5, 0.25], [null, 0.4]], r: 1, s: 1, samplesU: 4, samplesV: 4, mesh: chance(0.3),
  }),
  crissCrossSurface: () => ({ network: net(), samplesU: 5, samplesV: 5, derivatives: 1, mesh: chance(0.3), evaluate: pick(['local', 'sum']) }),
  crissCrossBasis: () => ({ u: [0, 0.5, 1], v: [0, 0.5, 1], i: 1, j: 1, atUV: [[0.25, 0.25], [0.5, 0.7]], derivatives: 1 }),
  crissCrossCells: () => (chance(0.5) ? { u: [0, 1, 2, 3], v: [0, 1, 2], i: 2, j: 1 } : { network: net() }),
  thinPlateSurface: () => ({ network: net(), samplesU: 5, samplesV: 5, derivatives: 1 }),
  gordonSurface: () => ({ network: net(), samplesU: 5, samplesV: 5, derivatives: 1, components: chance(0.3) }),
  surfaceDifferences: () => ({ network: net(), samples: 5 }),
  networkSurfaces: () => ({ network: net(), samplesU: 6, samplesV: 6, normSamples: 5 }),
  exerciseCheck: () => ({ check: 'dataDistance', tol: 1e-6, data: [[0, -0.5]], curve: { degree: 2, breaks: [0, 1], controlPoints: [[-1, 1], [0, -1], [1, 1]] } }),
  networkFromFunction: () => ({ u: [0, 0.4, 1], v: [0, 0.5, 1], f: (u, v) => [u, v, u * v] }),
  networkFromControlNet: () => ({ u: [0, 1, 2], v: [0, 1], C: grid(4, 3, (i, j) => [i, j, (i * j) % 2]) }),
  networkFromFreeData: () => ({
    u: [0, 1, 2], v: [0, 1],
    P: [[[0, 0, 0], [0, 0.5, 0], [0, 1, 0]], [[1, 0, 1], [1, 0.5, 2], [1, 1, 1]], [[2, 0, 0], [2, 0.5, 0], [2, 1, 0]]],
    Q1: [[0.5, 0, 0.3], [0.5, 1, 0.2]],
  }),
  networkRepair: () => ({ network: net(), edited: pick([undefined, { kind: 'P', r: 1, j: 1 }, { kind: 'Q', s: 0, i: 1 }]) }),
  networkCompatibility: () => ({ network: net(), tolerance: 1e-9 }),
  networkExample: () => ({ name: pick(NET_NAMES) }),
  knotModifiedSurface: () => ({ surface: surf(), p: 3, up: 1.5, ...pick([{ atUV: [[0.5, 0.5], [1.2, 1]] }, { q: 3, vq: 0.5, samplesU: 4, samplesV: 4, derivatives: 1, mesh: true }]) }),
  knotEnvelope: () => ({ surface: surf(), p: 3, ...pick([{ atUV: [[1, 0.5]] }, { q: 3, samplesU: 4, samplesV: 4, derivatives: 1 }]) }),
  knotPaths: () => ({ surface: surf(), p: 3, points: [[0.5, 0.5], [1.5, 1]], from: 0.5, to: 1.5, samples: 10, ...pick([{}, { q: 3, from: [0.5, 0.5], to: [1.5, 1.5], samples: [4, 3] }]) }),
  knotModifiedCurve: () => ({ curve: curveK(), p: 5, up: 1.7, samples: 20, derivatives: 2 }),
  knotEnvelopeCurve: () => ({ curve: curveK(), p: 5, samples: 20, derivatives: 1 }),
  knotPathsCurve: () => ({ curve: curveK(), p: 5, params: [0.5, 1.5, 2.5], samples: 10 }),
  knotLimits: () => (chance(0.5) ? { curve: curveK(), p: 5 } : { surface: surf(), p: 3, q: 3, samples: 10 }),
};
const SKIP = new Set(['initSync', 'default', 'version', '__wbg_init']);
const exported = Object.keys(sl).filter((k) => typeof sl[k] === 'function' && !SKIP.has(k) && !/^[A-Z]/.test(k));

// ---------- mutations ----------
const WEIRD_NUMBERS = [NaN, Infinity, -Infinity, -1, 0, -0, 1e300, -1e300, 1e-300, 1e9, 2 ** 31, 4294967296, 0.5, 1e6 + 1, 100001, 1e6, -1e6, 1e-7, 3];
const GARBAGE_FNS = [
  () => { throw new Error('boom'); }, () => { throw 'a string'; }, () => [NaN, 0, 0], () => 'garbage', () => [1, 2],
  () => [1e308, -1e308, 1e308], () => ({ 0: 1, 1: 2, 2: 3 }), () => undefined, () => [1, 2, 3, 4], () => [Infinity, 0, 0],
  () => [[1, 2, 3]], () => { throw null; },
];
const GARBAGE_FN_SET = new Set(GARBAGE_FNS);
const WEIRD_VALUES = [undefined, null, true, false, 'x', '', 'uniform', 'chord', 'curvature', [], {}, [[]], [[NaN, NaN]], [1, 2, 3], [[1, 2], [3]],
  [[1, 2, 3, 4]], [[[1, 2, 3]]], ...GARBAGE_FNS, Symbol('s'), 10n, new Float64Array(3), { length: 5 }, Object.create(null), new Date(0)];
function randomValue(depth = 0) {
  const r = R();
  if (r < 0.35) return pick(WEIRD_NUMBERS);
  if (r < 0.7 || depth > 2) return clone(pick(WEIRD_VALUES)); // a fresh copy: later mutations write into it
  const n = Math.floor(R() * 6);
  return Array.from({ length: n }, () => randomValue(depth + 1));
}
function clone(v) {
  if (Array.isArray(v)) return v.map(clone);
  if (v && typeof v === 'object' && Object.getPrototypeOf(v) === Object.prototype) { const o = {}; for (const k of Object.keys(v)) o[k] = clone(v[k]); return o; }
  return v;
}
const isPlain = (v) => v && typeof v === 'object' && !Array.isArray(v) && Object.getPrototypeOf(v) === Object.prototype;
// paths to every number (or function, or plain object, or array) inside a value
function paths(v, test, path = [], out = []) {
  if (test(v) && path.length) out.push(path);
  if (Array.isArray(v)) v.forEach((x, i) => paths(x, test, [...path, i], out));
  else if (isPlain(v)) for (const k of Object.keys(v)) paths(v[k], test, [...path, k], out);
  return out;
}
function setAt(obj, path, val) { let o = obj; for (let i = 0; i < path.length - 1; i++) o = o[path[i]]; o[path[path.length - 1]] = val; }
function getAt(obj, path) { let o = obj; for (const p of path) o = o[p]; return o; }
function delAt(obj, path) {
  let o = obj; for (let i = 0; i < path.length - 1; i++) o = o[path[i]];
  const k = path[path.length - 1];
  if (Array.isArray(o)) o.splice(k, 1); else delete o[k];
}
// a copy of `a` grown to n entries (by repeating its entries, nudged so points stay distinct)
function grow(a, n) {
  if (!a.length) return Array.from({ length: n }, (_, i) => i);
  return Array.from({ length: n }, (_, i) => {
    const x = a[i % a.length];
    if (typeof x === 'number') return x + Math.floor(i / a.length);
    if (Array.isArray(x) && x.every((y) => typeof y === 'number')) return x.map((y, k) => (k === 0 ? y + Math.floor(i / a.length) : y));
    return x;
  });
}
const HUGE = [100_000, 100_001, 100_001, 200_000];
function mutate(opts) {
  const o = clone(opts);
  const kinds = Math.floor(R() * 3) + 1;
  let getterKey = null;
  for (let m = 0; m < kinds; m++) {
    const r = R();
    const keys = Object.keys(o);
    if (r < 0.25) { // a number somewhere becomes weird
      const ps = paths(o, (x) => typeof x === 'number');
      if (ps.length) setAt(o, pick(ps), pick(WEIRD_NUMBERS));
    } else if (r < 0.30) { // a number nudged (near-coincident points, nearly equal knots)
      const ps = paths(o, (x) => typeof x === 'number');
      if (ps.length) { const p = pick(ps); setAt(o, p, getAt(o, p) * (1 + pick([1e-12, -1e-9, 1e-6, -1e-3]))); }
    } else if (r < 0.40) { // something is removed (a field or an entry deep inside)
      const ps = paths(o, () => true);
      if (ps.length) delAt(o, pick(ps));
    } else if (r < 0.55) { // something becomes garbage (a field or an entry deep inside)
      const ps = chance(0.5) ? keys.map((k) => [k]) : paths(o, () => true);
      if (ps.length) setAt(o, pick(ps), randomValue());
    } else if (r < 0.60) { // a callback throws or returns garbage
      const ps = paths(o, (x) => typeof x === 'function');
      if (ps.length) setAt(o, pick(ps), pick(GARBAGE_FNS));
      else if (keys.length) o[pick(keys)] = pick(GARBAGE_FNS);
    } else if (r < 0.78) { // an array is truncated, duplicated, reversed, made ragged or emptied
      const ps = paths(o, Array.isArray);
      if (ps.length) {
        const p = pick(ps);
        const a = getAt(o, p);
        const k = R();
        if (k < 0.25) setAt(o, p, a.slice(0, Math.floor(R() * a.length)));
        else if (k < 0.4) setAt(o, p, a.map((x, i) => (i === 1 ? clone(a[0]) : x)));
        else if (k < 0.5) setAt(o, p, [...a].reverse());
        else if (k < 0.65 && a.length) setAt(o, p, a.map((x, i) => (i === a.length - 1 && Array.isArray(x) ? x.slice(0, 1) : x)));
        else if (k < 0.8) setAt(o, p, [...a, ...a.slice(0, 1 + Math.floor(R() * 3)).map(clone)]);
        else if (k < 0.9) setAt(o, p, a.map((x) => (Array.isArray(x) ? [...x, 1] : x)));
        else setAt(o, p, []);
      }
    } else if (r < 0.7805) { // a huge input (rare: costly to build and to read)
      const ps = paths(o, Array.isArray).filter((p) => p.length <= 2);
      if (ps.length) { const p = pick(ps); setAt(o, p, grow(getAt(o, p), pick(HUGE))); }
    } else if (r < 0.80) { // a large but allowed input
      const ps = paths(o, Array.isArray).filter((p) => p.length <= 2);
      if (ps.length) { const p = pick(ps); setAt(o, p, grow(getAt(o, p), pick([50, 300, 2000]))); }
    } else if (r < 0.90) { // absurd counts (the largest allowed one, 1e6, rarely: it costs a full evaluation)
      o[pick(['samples', 'samplesU', 'samplesV', 'derivatives', 'degree', 'k', 'count', 'steps', 'errorSamples', 'truthSamples', 'p', 'q', 'i', 'j', 'r', 'segments', 'm', 'n', 'normSamples'])] =
        chance(0.02) ? 1e6 : pick([1e7, 5000, 1000, -5, 1.5, NaN, 2e9, 0, 1, 2, 4, 1e6 + 1]);
    } else if (r < 0.95) { // a field of the wrong type
      if (keys.length) o[pick(keys)] = pick(['7', [7], { x: 1 }, true, () => 1, new Float64Array([1, 2])]);
    } else { // an unknown extra field or a prototype trick
      if (chance(0.5)) o.__proto_junk__ = randomValue();
      else getterKey = pick(keys.length ? keys : ['samples']);
    }
  }
  // a field whose getter throws (applied last, so later mutations do not write to it)
  if (getterKey) Object.defineProperty(o, getterKey, { get() { throw new Error('getter'); }, enumerable: false, configurable: true });
  return o;
}
const GARBAGE_ARGS = [undefined, null, 0, NaN, 'points', [], [[0, 0]], () => 1, true, Symbol('x'), 10n, new Float64Array(2), Object.create(null)];

// ---------- checks on the result ----------
// Whether every number in `v` is finite with |x| ≤ 1e6 and every function in it is a well-behaved example
// callback (then the output must be finite).
function moderate(v, depth = 0) {
  if (typeof v === 'number') return Number.isFinite(v) && Math.abs(v) <= 1e6;
  if (typeof v === 'function') return !GARBAGE_FN_SET.has(v);
  if (depth > 6) return true;
  if (Array.isArray(v)) return v.every((x) => moderate(x, depth + 1));
  if (isPlain(v)) return Object.keys(v).every((k) => moderate(v[k], depth + 1));
  return true;
}
// The first non-finite number in a result (typed arrays, arrays, plain objects), as a path, or null.
function nonFinite(v, path = '', depth = 0) {
  if (typeof v === 'number') return Number.isFinite(v) ? null : `${path} = ${v}`;
  if (depth > 6 || v == null) return null;
  if (ArrayBuffer.isView(v) && !(v instanceof DataView)) {
    if (v instanceof Float64Array || v instanceof Float32Array) {
      for (let i = 0; i < v.length; i++) if (!Number.isFinite(v[i])) return `${path}[${i}] = ${v[i]}`;
    }
    return null;
  }
  if (Array.isArray(v)) {
    for (let i = 0; i < v.length; i++) { const r = nonFinite(v[i], `${path}[${i}]`, depth + 1); if (r) return r; }
    return null;
  }
  if (typeof v === 'object') {
    for (const k of Object.keys(v)) { const r = nonFinite(v[k], `${path}.${k}`, depth + 1); if (r) return r; }
  }
  return null;
}
// Documented exceptions to "finite output for moderate finite input": keys whose value may legitimately be
// non-finite. (None so far: the module reports what cannot be computed with an Error.)
const NONFINITE_OK = [];

const msgRe = /^(options|[A-Za-z][\w]*(\.[A-Za-z]\w*)*(\[\d+\])*(\.[A-Za-z]\w*)*(\[\d+\])*(\.[A-Za-z]\w*)*)\s*:\s*\S/;

// ---------- the run ----------
test(`API fuzz: ${CALLS} calls, seed ${SEED}`, { timeout: 60 * 60 * 1000 }, () => {
  assert.ok(exported.length >= 2, 'the module exports functions');
  const missing = exported.filter((k) => !EXAMPLES[k]);
  if (missing.length) console.log(`fuzz: exports without a valid example (garbage only): ${missing.join(', ')}`);
  // every example is valid as written (a broken example would only test error paths)
  const invalid = [];
  for (const name of exported.filter((k) => EXAMPLES[k])) {
    for (let t = 0; t < 30; t++) {
      const ex = EXAMPLES[name]();
      if (ex === undefined || (isPlain(ex) && Object.keys(ex).some((k) => ex[k] === undefined && k === 'network'))) continue;
      try { sl[name](ex); } catch (e) { invalid.push(`${name}: ${e.message} ${safeJson(ex)}`); break; }
    }
  }
  assert.deepEqual(invalid, [], 'every example call is valid');
  const fns = exported.filter((k) => !ONLY || ONLY.has(k));
  const stats = { calls: 0, ok: 0, errors: 0, slow: [], badMessages: [], traps: [], nonFinite: [], deadAfterError: [], perFn: {}, retimed: [] };
  const sanity = () => sl.bsplineCurve({ degree: 2, knots: [0, 0, 0, 1, 1, 1], points: [[0, 0], [1, 1], [2, 0]], samples: 3 });
  const t0run = performance.now();
  for (let c = 0; c < CALLS; c++) {
    const name = pick(fns);
    const ex = EXAMPLES[name];
    let arg;
    const r = R();
    if (!ex || r < 0.05) arg = pick(GARBAGE_ARGS);
    else if (r < 0.15) arg = ex();
    else arg = mutate(ex());
    if (DEBUG) writeSync(DEBUG_FD, `${c} ${name} ${safeJson(arg)}\n`);
    const t0 = performance.now();
    let failed = false;
    let result;
    try {
      result = sl[name](arg);
      stats.ok++;
    } catch (e) {
      failed = true;
      stats.errors++;
      if (e instanceof WebAssembly.RuntimeError || /unreachable|RuntimeError|memory access out of bounds/.test(String(e))) {
        stats.traps.push({ name, arg: safeJson(arg), error: String(e) });
        break; // the module is dead after a trap
      }
      if (!(e instanceof Error) || !msgRe.test(e.message)) {
        if (stats.badMessages.length < 20) stats.badMessages.push({ name, arg: safeJson(arg), message: String((e && e.message) || e) });
      }
    }
    const dt = performance.now() - t0;
    const pf = (stats.perFn[name] ||= { calls: 0, ok: 0, ms: 0 });
    pf.calls++; pf.ms += dt; if (!failed) pf.ok++;
    if (dt > SLOW_MS) { // time it again: on a loaded machine a pause of the process is not the call's cost
      const t1 = performance.now();
      try { sl[name](arg); } catch { /* same outcome as above */ }
      const dt2 = performance.now() - t1;
      stats.retimed.push(`${name} ${Math.round(dt)}→${Math.round(dt2)} ms`);
      if (dt2 > SLOW_MS) stats.slow.push({ name, ms: Math.round(Math.min(dt, dt2)), arg: safeJson(arg) });
    }
    if (!failed && stats.nonFinite.length < 20 && moderate(arg)) {
      const bad = nonFinite(result);
      if (bad && !NONFINITE_OK.some((k) => bad.startsWith(k))) stats.nonFinite.push({ name, where: bad, arg: safeJson(arg) });
    }
    stats.calls++;
    if (c > 0 && c % 100_000 === 0) { // progress (a long run cut short still gives its figures)
      console.log(`fuzz: progress ${c} calls, ${((performance.now() - t0run) / 1000).toFixed(0)} s, ${stats.ok} accepted, ` +
        `${stats.traps.length} traps, ${stats.badMessages.length} bad messages, ${stats.slow.length} slow, ${stats.nonFinite.length} non-finite, ` +
        `${stats.deadAfterError.length} dead after error`);
    }
    if (DEBUG && c % 500 === 0) {
      const mb = process.memoryUsage().heapUsed / 1e6;
      if (mb > 1000) console.log(`fuzz: heap ${mb.toFixed(0)} MB after call ${c} (${name}) ${safeJson(arg)}`);
    }
    if (failed) { // the module still works right after an error
      try { sanity(); if (ex && chance(0.1)) sl[name](ex()); } catch (e) {
        stats.deadAfterError.push({ name, arg: safeJson(arg), error: String(e) });
        if (e instanceof WebAssembly.RuntimeError) break;
      }
    }
  }
  sanity();
  const secs = ((performance.now() - t0run) / 1000).toFixed(1);
  const top = Object.entries(stats.perFn).sort((a, b) => b[1].ms - a[1].ms).slice(0, 5)
    .map(([k, v]) => `${k} ${(v.ms / 1000).toFixed(1)} s/${v.calls} (${v.ok} ok)`).join(', ');
  console.log(`fuzz: ${stats.calls} calls in ${secs} s over ${fns.length} exports (${stats.ok} accepted, ${stats.errors} rejected), ` +
    `${stats.traps.length} traps, ${stats.badMessages.length} messages not naming a field, ${stats.slow.length} calls over 2 s, ` +
    `${stats.nonFinite.length} non-finite results, ${stats.deadAfterError.length} failures after an error; slowest: ${top}`);
  if (stats.retimed.length) console.log(`fuzz: calls over 2 s timed again: ${stats.retimed.join(', ')}`);
  for (const k of ['traps', 'deadAfterError', 'slow', 'badMessages', 'nonFinite']) {
    for (const x of stats[k]) console.log(`fuzz: ${k}: ${JSON.stringify(x)}`);
  }
  const never = fns.filter((k) => EXAMPLES[k] && !(stats.perFn[k] && stats.perFn[k].ok));
  if (never.length && CALLS >= 10_000) console.log(`fuzz: exports never accepted: ${never.join(', ')}`);
  assert.deepEqual(stats.traps, [], 'no input may trap the module');
  assert.deepEqual(stats.deadAfterError, [], 'a valid call right after an error works');
  assert.deepEqual(stats.slow, [], 'no call may take over 2 s');
  assert.deepEqual(stats.badMessages, [], 'every error is an Error whose message starts with the field name');
  assert.deepEqual(stats.nonFinite, [], 'moderate finite input gives finite output');
});

// ---------- the curve-network limits (bug 5: these calls had no bound and were excused as "known") ----------
// docs/API.md states them; a call at every limit at once stays under LIMIT_MS (the best of 3 runs: a pause of
// a loaded machine is not the call's cost), one over any limit throws a `too-many` Error naming the field.
const FAMILY = { lines: 65, normSamples: 200, gridPoints: 200_000, curveSamples: 1024 };
const LIMIT_MS = 1000;
const lineNodes = (k) => Array.from({ length: k }, (_, i) => i / (k - 1));
const netOfSize = (m, n) => sl.networkFromFunction({ u: lineNodes(m), v: lineNodes(n), f: (u, v) => [u, v, Math.sin(3 * u) * Math.cos(2 * v)] });
function bestOf3(f) {
  let best = Infinity;
  for (let r = 0; r < 3; r++) { const t = performance.now(); f(); best = Math.min(best, performance.now() - t); }
  return best;
}

test('curve-network calls at every limit stay bounded; one over a limit is refused naming the field', () => {
  if (!has('networkSurfaces') || !has('surfaceDifferences')) return;
  const big = netOfSize(FAMILY.lines, FAMILY.lines);
  const all7 = ['S', 'T', 'G', 'GB', 'L1', 'L2', 'Tg'];
  const side = Math.floor(Math.sqrt(FAMILY.gridPoints / all7.length)); // 169: 169² × 7 = 199,927
  const worst = { network: big, samplesU: side, samplesV: side, surfaces: all7, normSamples: FAMILY.normSamples, colorBy: 'SG', curveSamples: FAMILY.curveSamples };
  const timed = {
    networkSurfaces: bestOf3(() => sl.networkSurfaces(worst)),
    surfaceDifferences: bestOf3(() => sl.surfaceDifferences({ network: big, samples: FAMILY.normSamples })),
    exerciseCheck: bestOf3(() => sl.exerciseCheck({ check: 'networkNorm', network: big, pair: 'SG', normSamples: FAMILY.normSamples, tol: 1 })),
  };
  console.log(`fuzz: calls at every curve-network limit (best of 3): ${Object.entries(timed).map(([k, ms]) => `${k} ${ms.toFixed(0)} ms`).join(', ')}`);
  for (const [name, ms] of Object.entries(timed)) assert.ok(ms < LIMIT_MS, `${name} at its limits took ${ms.toFixed(0)} ms (bound ${LIMIT_MS} ms)`);
  const small = netOfSize(4, 4);
  const over = [
    ['networkSurfaces', { network: netOfSize(FAMILY.lines + 1, 4) }, 'network.u', FAMILY.lines, FAMILY.lines + 1],
    ['networkSurfaces', { network: netOfSize(4, FAMILY.lines + 1) }, 'network.v', FAMILY.lines, FAMILY.lines + 1],
    ['networkSurfaces', { network: small, samplesU: 2 * side, samplesV: side, surfaces: all7 }, 'samplesU', FAMILY.gridPoints, 2 * side * side * 7],
    ['networkSurfaces', { network: small, normSamples: FAMILY.normSamples + 1 }, 'normSamples', FAMILY.normSamples, FAMILY.normSamples + 1],
    ['networkSurfaces', { network: small, curveSamples: FAMILY.curveSamples + 1 }, 'curveSamples', FAMILY.curveSamples, FAMILY.curveSamples + 1],
    ['surfaceDifferences', { network: netOfSize(FAMILY.lines + 1, 4) }, 'network.u', FAMILY.lines, FAMILY.lines + 1],
    ['surfaceDifferences', { network: small, samples: FAMILY.normSamples + 1 }, 'samples', FAMILY.normSamples, FAMILY.normSamples + 1],
    ['exerciseCheck', { check: 'networkNorm', network: small, pair: 'SG', tol: 1, normSamples: FAMILY.normSamples + 1 }, 'normSamples', FAMILY.normSamples, FAMILY.normSamples + 1],
  ];
  for (const [name, arg, field, expected, got] of over) {
    assert.throws(() => sl[name](arg), (e) => {
      assert.ok(e instanceof Error, `${name} ${field}: an Error`);
      assert.deepEqual({ field: e.field, kind: e.kind, expected: e.expected, got: e.got }, { field, kind: 'too-many', expected, got }, `${name}: ${e.message}`);
      assert.match(e.message, new RegExp(`^${field.replace('.', '\\.')}: at most`));
      return true;
    }, `${name} over its ${field} limit`);
  }
});

function safeJson(v) {
  try {
    return JSON.stringify(v, (k, x) => (typeof x === 'function' ? `[fn ${x.toString().slice(0, 40)}]` : typeof x === 'number' && !Number.isFinite(x) ? String(x) : typeof x === 'bigint' ? `${x}n` : typeof x === 'symbol' ? 'Symbol' : Array.isArray(x) && x.length > 50 ? `[array of ${x.length}]` : x)).slice(0, 600);
  } catch { return String(v); }
}
