// Batch evaluation benchmark (issue 8): 1,000,000 points of one cubic B-spline curve, three ways in one run:
// SplineLab's wasm from Node, the same Rust natively, and the pure-JS library verb-nurbs.
// Usage: node benches/batch.mjs   (after scripts/build-wasm.sh; installs verb-nurbs into benches/ if missing)
import { createRequire } from 'node:module';
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';

const here = dirname(fileURLToPath(import.meta.url));
const root = join(here, '..');
const require = createRequire(import.meta.url);
const N = 1_000_000;
const REPS = Number(process.env.REPS || 7);

// the test curve: 100 control points on a spiral, clamped uniform cubic knots
const ctrl = Array.from({ length: 100 }, (_, i) => [Math.cos(i * 0.3) * (1 + i * 0.05), Math.sin(i * 0.3) * (1 + i * 0.05)]);
const degree = 3;
const inner = ctrl.length - degree - 1;
const knots = [0, 0, 0, 0, ...Array.from({ length: inner }, (_, i) => (i + 1) / (inner + 1)), 1, 1, 1, 1];

function median(xs) { const s = [...xs].sort((a, b) => a - b); return s[s.length >> 1]; }
function time(fn) {
  fn(); // warm-up
  const ts = [];
  for (let r = 0; r < REPS; r++) { const t0 = process.hrtime.bigint(); fn(); ts.push(Number(process.hrtime.bigint() - t0) / 1e6); }
  return median(ts);
}

const results = [];
// 1. wasm from Node
const sl = require(join(root, 'pkg-node/splinelab.js'));
let check;
const tWasm = time(() => { const r = sl.bsplineCurve({ degree, knots, points: ctrl, samples: N }); check = r.points; });
results.push(['SplineLab wasm (Node), bsplineCurve', tWasm]);
if (sl.bsplineSample) {
  const tFast = time(() => { check = sl.bsplineSample({ degree, knots, points: ctrl, samples: N }); });
  results.push(['SplineLab wasm (Node), bsplineSample (points only)', tFast]);
}
// 2. native Rust (the same core, release build)
try {
  execFileSync('cargo', ['build', '--release', '--example', 'batch'], { cwd: root, stdio: 'ignore' });
  const out = execFileSync(join(root, 'target/release/examples/batch'), [String(N), String(REPS)], { encoding: 'utf8' });
  for (const line of out.trim().split('\n')) { const [name, ms] = line.split('\t'); results.push([name, Number(ms)]); }
} catch (e) { results.push(['native: failed: ' + e.message, NaN]); }
// 3. verb-nurbs (pure JS)
try {
  if (!existsSync(join(here, 'node_modules/verb-nurbs'))) execFileSync('npm', ['install', '--ignore-scripts', '--no-audit', '--no-fund'], { cwd: here, stdio: 'ignore' });
  const Module = require('node:module');
  const load = Module._load;
  Module._load = function (req, ...rest) { return req === 'webworker-threads' ? { Worker: class {} } : load.call(this, req, ...rest); };
  const log = console.log; console.log = () => {};
  const verb = require(join(here, 'node_modules/verb-nurbs'));
  console.log = log;
  const c = verb.geom.NurbsCurve.byKnotsControlPointsWeights(degree, knots, ctrl.map(([x, y]) => [x, y, 0]));
  const M = N / 10; // verb is slow: time 100,000 points and scale
  const tVerb = time(() => { const out = new Float64Array(2 * M); for (let i = 0; i < M; i++) { const p = c.point(i / (M - 1)); out[2 * i] = p[0]; out[2 * i + 1] = p[1]; } }) * 10;
  results.push(['verb-nurbs 2.0.2 (pure JS), NurbsCurve.point ×1e6 (timed on 1e5, ×10)', tVerb]);
} catch (e) { results.push(['verb-nurbs: failed: ' + e.message, NaN]); }

// memory-bandwidth floor: writing 16 bytes per point
const tFloor = time(() => { const a = new Float64Array(2 * N); for (let i = 0; i < 2 * N; i++) a[i] = i; check = a; });
results.push(['floor: fill a Float64Array of 2e6 (16 bytes/point) in JS', tFloor]);

console.log(`batch evaluation of ${N.toLocaleString('en')} points, cubic B-spline with ${ctrl.length} control points; median of ${REPS}`);
for (const [name, ms] of results) console.log(`${ms.toFixed(1).padStart(9)} ms  ${name}`);
