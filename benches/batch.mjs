// Batch evaluation benchmark (issue 8): 1,000,000 points of one cubic B-spline curve, three ways in one run:
// SplineLab's wasm from Node, the same Rust natively, and the pure-JS library verb-nurbs.
// Usage: node benches/batch.mjs   (after scripts/build-wasm.sh; installs verb-nurbs into benches/ if missing)
//   REPS=15 node benches/batch.mjs   (more repetitions; the median and the minimum are printed)
//   NATIVE=0 to skip the native build.
//
// The wasm call `bsplineCurve({ samples: 1e6 })` returns `{ params, points, knots }` as JS-owned Float64Arrays
// (8 MB + 16 MB). Its time is split with an instrumented copy of the module's imports (every JS function the
// wasm calls is timed): "inside wasm" = the export's time minus the time spent in JS imports; the boundary
// part is the imports (reading the options object, creating the Float64Arrays and copying out of wasm memory).
import { createRequire } from 'node:module';
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';
import { setFlagsFromString } from 'node:v8';
import { runInNewContext } from 'node:vm';

const here = dirname(fileURLToPath(import.meta.url));
const root = join(here, '..');
const require = createRequire(import.meta.url);
const N = 1_000_000;
const REPS = Number(process.env.REPS || 9);

// the test curve: 100 control points on a spiral, clamped uniform cubic knots
const ctrl = Array.from({ length: 100 }, (_, i) => [Math.cos(i * 0.3) * (1 + i * 0.05), Math.sin(i * 0.3) * (1 + i * 0.05)]);
const degree = 3;
const inner = ctrl.length - degree - 1;
const knots = [0, 0, 0, 0, ...Array.from({ length: inner }, (_, i) => (i + 1) / (inner + 1)), 1, 1, 1, 1];

const sorted = (xs) => [...xs].sort((a, b) => a - b);
const median = (xs) => sorted(xs)[xs.length >> 1];
function time(fn, reps = REPS) {
  fn(); // warm-up
  const ts = [];
  for (let r = 0; r < reps; r++) { const t0 = process.hrtime.bigint(); fn(); ts.push(Number(process.hrtime.bigint() - t0) / 1e6); }
  return { med: median(ts), min: Math.min(...ts) };
}

// --- instrument the wasm module's imports (before loading the glue) ---
const importTime = { copy: 0, alloc: 0, other: 0, calls: 0 };
let instrument = false;
const Instance = WebAssembly.Instance;
WebAssembly.Instance = function (module, imports) {
  const wrapped = {};
  for (const [ns, fns] of Object.entries(imports)) {
    wrapped[ns] = {};
    for (const [name, f] of Object.entries(fns)) {
      if (typeof f !== 'function') { wrapped[ns][name] = f; continue; }
      const src = f.toString();
      const kind = /getArray(F64|F32|U32)FromWasm0/.test(src) ? 'copy' : /new (Float64|Float32|Uint32)Array\(arg0/.test(src) ? 'alloc' : 'other';
      wrapped[ns][name] = function (...args) {
        if (!instrument) return f.apply(this, args);
        const t0 = performance.now();
        try { return f.apply(this, args); } finally { importTime[kind] += performance.now() - t0; importTime.calls++; }
      };
    }
  }
  return new Instance(module, wrapped);
};
const sl = require(join(process.env.PKG || join(root, 'pkg-node'), 'splinelab.js')); // PKG=dir: another build
WebAssembly.Instance = Instance;

const rows = []; // [name, {med, min}, note]
const opts = { degree, knots, points: ctrl, samples: N };
let check;

// 1. wasm from Node: the whole call, as a caller sees it
const tWasm = time(() => { check = sl.bsplineCurve(opts).points; });
rows.push(['wasm (Node): bsplineCurve({ samples: 1e6 }) → params + points + knots as Float64Arrays', tWasm]);
// the same, with a full GC before each call (outside the timing): the call without collecting the previous
// call's 24 MB of results (back-to-back calls above pay for that inside the next call)
{
  setFlagsFromString('--expose-gc');
  const gc = runInNewContext('gc');
  const ts = [];
  for (let r = 0; r <= REPS; r++) { check = null; gc(); const t0 = process.hrtime.bigint(); check = sl.bsplineCurve(opts).points; ts.push(Number(process.hrtime.bigint() - t0) / 1e6); }
  ts.shift();
  rows.push(['  the same call after a GC (previous results collected outside the timing)', { med: median(ts), min: Math.min(...ts) }]);
}
// the same call, split: time inside wasm vs in the JS imports (boundary)
{
  const inside = [], copy = [], alloc = [], other = [];
  sl.bsplineCurve(opts);
  for (let r = 0; r < REPS; r++) {
    Object.assign(importTime, { copy: 0, alloc: 0, other: 0, calls: 0 });
    instrument = true;
    const t0 = performance.now();
    sl.bsplineCurve(opts);
    const total = performance.now() - t0;
    instrument = false;
    inside.push(total - importTime.copy - importTime.alloc - importTime.other);
    copy.push(importTime.copy); alloc.push(importTime.alloc); other.push(importTime.other);
  }
  const s = (xs) => ({ med: median(xs), min: Math.min(...xs) });
  rows.push(['  of which inside wasm (options → Vec, params, power basis + forward differences, result object)', s(inside)]);
  rows.push(['  of which JS: new Float64Array(1e6) + (2e6) (zeroed)', s(alloc)]);
  rows.push(['  of which JS: copy out of wasm memory (Float64Array.set, 24 MB)', s(copy)]);
  rows.push([`  of which JS: reading the options object, building the result (${importTime.calls} import calls)`, s(other)]);
}
// the JS-boundary copy on its own: 16 MB (the points) into a fresh Float64Array
{
  const src = new Float64Array(2 * N).fill(1.5);
  rows.push(['JS: copy 16 MB into a fresh Float64Array (new + set)', time(() => { check = new Float64Array(2 * N); check.set(src); })]);
  const dst = new Float64Array(2 * N);
  rows.push(['JS: copy 16 MB into an existing Float64Array (set)', time(() => { dst.set(src); })]);
}

// 2. native Rust (the same core, release build)
if (process.env.NATIVE !== '0') {
  try {
    execFileSync('cargo', ['build', '--release', '--example', 'batch'], { cwd: root, stdio: 'ignore' });
    const out = execFileSync(join(root, 'target/release/examples/batch'), [String(N), String(REPS)], { encoding: 'utf8' });
    for (const line of out.trim().split('\n')) { const [name, med, min] = line.split('\t'); rows.push([name, { med: Number(med), min: Number(min) }]); }
  } catch (e) { rows.push(['native: failed: ' + e.message, { med: NaN, min: NaN }]); }
}

// 3. verb-nurbs (pure JS)
try {
  if (!existsSync(join(here, 'node_modules/verb-nurbs'))) execFileSync('npm', ['install', '--ignore-scripts', '--no-audit', '--no-fund'], { cwd: here, stdio: 'ignore' });
  const Module = require('node:module');
  const load = Module._load;
  Module._load = function (req, ...rest) { return req === 'webworker-threads' ? { Worker: class {} } : load.call(this, req, ...rest); };
  const log = console.log; console.log = () => {};
  const verb = require(join(here, 'node_modules/verb-nurbs'));
  console.log = log;
  Module._load = load;
  const c = verb.geom.NurbsCurve.byKnotsControlPointsWeights(degree, knots, ctrl.map(([x, y]) => [x, y, 0]));
  const M = N / 10; // verb is slow: time 100,000 points and scale ×10
  const scale = (t) => ({ med: t.med * 10, min: t.min * 10 });
  rows.push(['verb-nurbs 2.0.2: NurbsCurve.point(u) into a Float64Array (timed on 1e5, ×10)', scale(time(() => {
    const out = new Float64Array(2 * M);
    for (let i = 0; i < M; i++) { const p = c.point(i / (M - 1)); out[2 * i] = p[0]; out[2 * i + 1] = p[1]; }
    check = out;
  }, 5))]);
  // verb's fastest path: the non-rational evaluator on the raw curve data (no weights, no dehomogenising)
  const data = new verb.core.NurbsCurveData(degree, knots, ctrl.map(([x, y]) => [x, y]));
  rows.push(['verb-nurbs 2.0.2: eval.Eval.curvePoint (non-rational, fastest) (timed on 1e5, ×10)', scale(time(() => {
    const out = new Float64Array(2 * M);
    for (let i = 0; i < M; i++) { const p = verb.eval.Eval.curvePoint(data, i / (M - 1)); out[2 * i] = p[0]; out[2 * i + 1] = p[1]; }
    check = out;
  }, 5))]);
} catch (e) { rows.push(['verb-nurbs: failed: ' + e.message, { med: NaN, min: NaN }]); }

// floors: writing 16 bytes per point
rows.push(['floor (JS): new Float64Array(2e6).fill(x) (fresh 16 MB)', time(() => { check = new Float64Array(2 * N).fill(0.5); })]);
{
  const a = new Float64Array(2 * N);
  rows.push(['floor (JS): fill an existing Float64Array(2e6) (16 MB)', time(() => { a.fill(0.25); })]);
}

console.log(`batch evaluation of ${N.toLocaleString('en')} points, cubic B-spline with ${ctrl.length} control points; ${REPS} runs (median, min) — ${new Date().toISOString()}`);
for (const [name, t] of rows) console.log(`${t.med.toFixed(2).padStart(8)} ${t.min.toFixed(2).padStart(8)} ms  ${name}`);
const get = (re) => rows.find(([n]) => re.test(n))?.[1];
const wasm = tWasm, inside = get(/inside wasm/), native = get(/^native.*like for like/), verbFast = get(/curvePoint/), verbPt = get(/NurbsCurve\.point/);
if (native && verbFast) {
  console.log(`\nratios (medians; minima in brackets):`);
  console.log(`  wasm whole call vs verb-nurbs fastest path: ${(verbFast.med / wasm.med).toFixed(1)}× faster (${(verbFast.min / wasm.min).toFixed(1)}×); vs NurbsCurve.point: ${(verbPt.med / wasm.med).toFixed(1)}×`);
  console.log(`  wasm compute (inside wasm) / native like for like: ${(native.med / inside.med).toFixed(2)}× native speed (${(native.min / inside.min).toFixed(2)}×)`);
  console.log(`  wasm whole call / native like for like: ${(native.med / wasm.med).toFixed(2)}× native speed (${(native.min / wasm.min).toFixed(2)}×)`);
}
