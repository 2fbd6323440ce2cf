// API fuzzer (issue 9): calls every exported function of the wasm module with valid, mutated and garbage
// options. Required: zero traps (WebAssembly.RuntimeError), every failure a JS Error whose message names the
// field ("<field>: …"), no call over 2 s, and a valid call right after any error still works.
//
//   node --test tests/node/fuzz-api.test.mjs            short mode (CI): FUZZ_CALLS=100000, seed 1
//   FUZZ_CALLS=1000000 FUZZ_SEED=7 node --test tests/node/fuzz-api.test.mjs   long mode
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';

const require = createRequire(import.meta.url);
const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const sl = require(join(root, 'pkg-node/splinelab.js'));

const CALLS = Number(process.env.FUZZ_CALLS || 100_000);
const SEED = Number(process.env.FUZZ_SEED || 1);

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

// ---------- valid example calls (shapes of ../shared/spec/api.md) ----------
const grid = (rows, cols, f) => Array.from({ length: rows }, (_, i) => Array.from({ length: cols }, (_, j) => f(i, j)));
const pts2 = (n) => Array.from({ length: n }, (_, i) => [i, Math.sin(i * 1.3) * 2]);
const surf = {
  orderU: 3, orderV: 3, knotsU: [0, 0, 0, 1, 2, 2, 2], knotsV: [0, 0, 0, 1, 2, 2, 2],
  controlPoints: grid(4, 4, (i, j) => [i, j, Math.sin(i + j)]),
};
function network() {
  try { return sl.networkFromFunction({ u: [0, 0.4, 1], v: [0, 0.5, 1], f: (u, v) => [u, v, u * v + u * u] }); } catch { return undefined; }
}
const NET = typeof sl.networkFromFunction === 'function' ? network() : undefined;
const EXAMPLES = {
  bsplineCurve: () => ({ degree: 3, knots: [0, 0, 0, 0, 0.5, 1, 1, 1, 1], points: pts2(5), samples: 20, derivatives: 2 }),
  bsplineBasis: () => ({ degree: 2, knots: [0, 0, 0, 0.5, 1, 1, 1], at: [0, 0.3, 1], derivatives: 1 }),
  quasiCubicBasis: () => ({ alpha: 0.5, at: [0, 0.5, 1], derivatives: 2 }),
  quasiCubicCurve: () => ({ points: pts2(6), alpha: 1, samples: 20, derivatives: 1 }),
  quasiCubicInterpolation: () => ({ points: pts2(6), beta: 'curvature', samples: 20 }),
  quasiCubicSurface: () => ({ grid: grid(4, 5, (i, j) => [i, j, i * j]), alpha: 1, samplesU: 5, samplesV: 5 }),
  b2Curve: () => ({ points: pts2(7), a: 0.1, samples: 20, derivatives: 2 }),
  b2Surface: () => ({ grid: grid(6, 6, (i, j) => [i, j, Math.cos(i - j)]), a: 0, samplesU: 5, samplesV: 5 }),
  splineBlendedSurface: () => ({ network: (u, v) => [u, v, u * v], uKnots: [0, 0.5, 1], vKnots: [0, 0.3, 1], blend: 'cubic-natural', samplesU: 5, samplesV: 5 }),
  bezierRemodel: () => ({
    points: [[10, 16], [7, 21], [3, 9], [0, 0], [-4, 0], [-8, 0], [-6, 3], [-4, 6], [2, 2], [8, -2], [10, 3]],
    degree: 2, breaks: [0, 1, 1.75, 2.5, 3.25, 4],
    alphas: [[2 / 3, 1 / 20], [19 / 20, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 10]], r: 1, samples: 20,
  }),
  bezierRemodelSurface: () => ({
    points: grid(3, 2, (k, l) => [k, l, k * l]), degreeU: 2, degreeV: 1, breaksU: [0, 1], alphas: [[2 / 3, 1 / 3]], r: 1, samplesU: 4, samplesV: 4,
  }),
  crissCrossSurface: () => ({ network: NET, samplesU: 5, samplesV: 5, derivatives: 1 }),
  crissCrossBasis: () => ({ u: [0, 0.5, 1], v: [0, 0.5, 1], i: 1, j: 1, atUV: [[0.25, 0.25], [0.5, 0.7]], derivatives: 1 }),
  thinPlateSurface: () => ({ network: NET, samplesU: 5, samplesV: 5 }),
  gordonSurface: () => ({ network: NET, samplesU: 5, samplesV: 5 }),
  networkFromFunction: () => ({ u: [0, 0.4, 1], v: [0, 0.5, 1], f: (u, v) => [u, v, u * v] }),
  knotModifiedSurface: () => ({ surface: surf, p: 3, up: 1.5, atUV: [[0.5, 0.5], [1.2, 1]] }),
  knotEnvelope: () => ({ surface: surf, p: 3, atUV: [[1, 0.5]] }),
  knotPaths: () => ({ surface: surf, p: 3, points: [[0.5, 0.5]], from: 0.5, to: 1.5, samples: 10 }),
};
const SKIP = new Set(['initSync', 'default', 'version', '__wbg_init']);
const exported = Object.keys(sl).filter((k) => typeof sl[k] === 'function' && !SKIP.has(k) && !/^[A-Z]/.test(k));

// ---------- mutations ----------
const WEIRD_NUMBERS = [NaN, Infinity, -Infinity, -1, 0, -0, 1e300, -1e300, 1e-300, 1e9, 2 ** 31, 4294967296, 0.5, 1e6 + 1, 100001];
const WEIRD_VALUES = [undefined, null, true, 'x', '', [], {}, [[]], [[NaN, NaN]], [1, 2, 3], [[1, 2], [3]], [[1, 2, 3, 4]],
  () => { throw new Error('boom'); }, () => [NaN, 0, 0], () => 'garbage', () => [1, 2], Symbol('s'), 10n];
function randomValue(depth = 0) {
  const r = R();
  if (r < 0.35) return pick(WEIRD_NUMBERS);
  if (r < 0.7 || depth > 2) return pick(WEIRD_VALUES);
  const n = Math.floor(R() * 6);
  return Array.from({ length: n }, () => randomValue(depth + 1));
}
function clone(v) {
  if (Array.isArray(v)) return v.map(clone);
  if (v && typeof v === 'object' && !(v instanceof Function)) { const o = {}; for (const k of Object.keys(v)) o[k] = clone(v[k]); return o; }
  return v;
}
// paths to every number inside a value
function numberPaths(v, path = [], out = []) {
  if (typeof v === 'number') out.push(path);
  else if (Array.isArray(v)) v.forEach((x, i) => numberPaths(x, [...path, i], out));
  else if (v && typeof v === 'object' && typeof v !== 'function') for (const k of Object.keys(v)) numberPaths(v[k], [...path, k], out);
  return out;
}
function setAt(obj, path, val) { let o = obj; for (let i = 0; i < path.length - 1; i++) o = o[path[i]]; o[path[path.length - 1]] = val; }
function getAt(obj, path) { let o = obj; for (const p of path) o = o[p]; return o; }
function arrayPaths(v, path = [], out = []) {
  if (Array.isArray(v)) { out.push(path); v.forEach((x, i) => arrayPaths(x, [...path, i], out)); }
  else if (v && typeof v === 'object' && typeof v !== 'function') for (const k of Object.keys(v)) arrayPaths(v[k], [...path, k], out);
  return out;
}
function mutate(opts) {
  const o = clone(opts);
  const kinds = Math.floor(R() * 3) + 1;
  for (let m = 0; m < kinds; m++) {
    const r = R();
    const keys = Object.keys(o);
    if (r < 0.3) { // a number somewhere becomes weird
      const ps = numberPaths(o);
      if (ps.length) setAt(o, pick(ps), pick(WEIRD_NUMBERS));
    } else if (r < 0.45 && keys.length) { // a field is removed
      delete o[pick(keys)];
    } else if (r < 0.65 && keys.length) { // a field becomes garbage
      o[pick(keys)] = randomValue();
    } else if (r < 0.85) { // an array is truncated, duplicated, reversed or made ragged
      const ps = arrayPaths(o).filter((p) => p.length);
      if (ps.length) {
        const p = pick(ps);
        const a = getAt(o, p);
        const k = R();
        if (k < 0.3) setAt(o, p, a.slice(0, Math.floor(R() * a.length)));
        else if (k < 0.5) setAt(o, p, a.map((x, i) => (i === 1 ? clone(a[0]) : x)));
        else if (k < 0.7) setAt(o, p, [...a].reverse());
        else if (k < 0.9 && a.length) setAt(o, p, a.map((x, i) => (i === a.length - 1 && Array.isArray(x) ? x.slice(0, 1) : x)));
        else setAt(o, p, []);
      }
    } else if (r < 0.86) { // a huge input (rare: costly to build)
      const key = pick(['points', 'at', 'grid', 'atUV', 'knots']);
      o[key] = Array.from({ length: 100_001 }, (_, i) => (key === 'at' || key === 'knots' ? i : [i, i]));
    } else if (r < 0.95) { // absurd sample counts
      o[pick(['samples', 'samplesU', 'samplesV', 'derivatives', 'degree', 'k'])] = pick([1e7, 5000, -5, 1.5, NaN, 2e9]);
    } else { // an unknown extra field
      o.__proto_junk__ = randomValue();
    }
  }
  return o;
}
const GARBAGE_ARGS = [undefined, null, 0, NaN, 'points', [], [[0, 0]], () => 1, true, Symbol('x')];

// ---------- the run ----------
test(`API fuzz: ${CALLS} calls, seed ${SEED}`, { timeout: 30 * 60 * 1000 }, () => {
  assert.ok(exported.length >= 2, 'the module exports functions');
  const fns = exported.filter((k) => EXAMPLES[k] ? EXAMPLES[k]() !== undefined : true);
  const stats = { calls: 0, ok: 0, errors: 0, slow: [], badMessages: [], traps: [] };
  const sanity = () => sl.bsplineCurve(EXAMPLES.bsplineCurve());
  const msgRe = /^(options|[A-Za-z][\w]*(\.[A-Za-z]\w*)*(\[\d+\])*(\.[A-Za-z]\w*)*(\[\d+\])*)\s*:\s*\S/;
  for (let c = 0; c < CALLS; c++) {
    const name = pick(fns);
    const ex = EXAMPLES[name];
    let arg;
    const r = R();
    if (!ex || r < 0.08) arg = pick(GARBAGE_ARGS);
    else if (r < 0.2) arg = ex();
    else arg = mutate(ex());
    const t0 = performance.now();
    let failed = false;
    try {
      sl[name](arg);
      stats.ok++;
    } catch (e) {
      failed = true;
      stats.errors++;
      if (e instanceof WebAssembly.RuntimeError || /unreachable|RuntimeError/.test(String(e))) {
        stats.traps.push({ name, arg: safeJson(arg), error: String(e) });
        break; // the module is dead after a trap
      }
      if (!(e instanceof Error) || !msgRe.test(e.message)) {
        if (stats.badMessages.length < 20) stats.badMessages.push({ name, arg: safeJson(arg), message: String(e && e.message || e) });
      }
    }
    const dt = performance.now() - t0;
    if (dt > 2000) stats.slow.push({ name, ms: Math.round(dt), arg: safeJson(arg) });
    stats.calls++;
    if (failed && c % 7 === 0) sanity(); // the module still works after an error
  }
  sanity();
  console.log(`fuzz: ${stats.calls} calls over ${fns.length} exports (${stats.ok} accepted, ${stats.errors} rejected), ` +
    `${stats.traps.length} traps, ${stats.badMessages.length} messages not naming a field, ${stats.slow.length} calls over 2 s`);
  assert.deepEqual(stats.traps, [], 'no input may trap the module');
  assert.deepEqual(stats.slow, [], 'no call may take over 2 s');
  assert.deepEqual(stats.badMessages, [], 'every error is an Error whose message starts with the field name');
});

function safeJson(v) {
  try {
    return JSON.stringify(v, (k, x) => (typeof x === 'function' ? `[fn ${x.toString().slice(0, 40)}]` : typeof x === 'number' && !Number.isFinite(x) ? String(x) : typeof x === 'bigint' ? `${x}n` : typeof x === 'symbol' ? 'Symbol' : x)).slice(0, 400);
  } catch { return String(v); }
}
