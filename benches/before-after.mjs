// Benchmark (not a test): the same calls on two builds of the module, side by side in one Node process,
// interleaved, after a warm-up: for changes that must not cost speed (e.g. how options are read). The workloads
// are the engine benchmark's large calls (1M curve points, 500² surface points) and bursts of small calls, where
// reading the options object is a larger share of the time. Outputs of the two builds are compared first.
//
//   cp -r pkg-node /tmp/pkg-before   # before the change; then rebuild (scripts/build-wasm.sh)
//   BEFORE=/tmp/pkg-before node benches/before-after.mjs            (AFTER defaults to pkg-node)
//   REPS=15 N=1000000 G=500 SMALL=2000 BEFORE=… AFTER=… node benches/before-after.mjs [row-name-substring]
// Prints median (min) in ms per build and the ratio after / before on both.
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join, resolve } from 'node:path';
import { cpus, loadavg } from 'node:os';

const require = createRequire(import.meta.url);
const root = join(dirname(fileURLToPath(import.meta.url)), '..');
if (!process.env.BEFORE) throw new Error('set BEFORE=<dir with splinelab.js> (a copy of pkg-node from before the change)');
const builds = {
  before: require(join(resolve(process.env.BEFORE), 'splinelab.js')),
  after: require(join(resolve(process.env.AFTER || join(root, 'pkg-node')), 'splinelab.js')),
};
const REPS = Number(process.env.REPS || 15);
const N = Number(process.env.N || 1_000_000);
const G = Number(process.env.G || 500);
const SMALL = Number(process.env.SMALL || 2000);
const only = process.argv[2];

const median = (xs) => { const s = [...xs].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };
const now = () => Number(process.hrtime.bigint()) / 1e6;

/** The spiral data of benches/engine.mjs: 100 points. */
const W = Array.from({ length: 100 }, (_, i) => { const t = i * 0.15; return [(1 + t) * Math.cos(t) + 0.1 * Math.sin(7 * t), (1 + t) * Math.sin(t)]; });
const P8 = W.slice(0, 8);
const kn = (n) => [0, 0, 0, 0, ...Array.from({ length: n - 4 }, (_, i) => i + 1), n - 3, n - 3, n - 3, n - 3];

/** name → (sl) => a Float64Array to compare (one call), and how many calls a repetition makes. */
const rows = [
  ['bsplineCurve 1M samples', (sl) => sl.bsplineCurve({ degree: 3, points: W, samples: N }).points],
  ['b2Curve 1M samples', (sl) => sl.b2Curve({ points: W, a: 0.05, samples: N }).points],
  ['quasiCubicCurve α = 0.5, 1M samples', (sl) => sl.quasiCubicCurve({ points: W, alpha: 0.5, samples: N }).points],
  ['knotModifiedCurve 1M samples', (sl) => sl.knotModifiedCurve({ curve: { order: 4, knots: kn(100), controlPoints: W }, p: 50, up: 47.8, samples: N }).points],
  ['bezierRemodel 1M samples', (sl) => sl.bezierRemodel({ points: W.slice(0, 100), degree: 3, breaks: Array.from({ length: 34 }, (_, i) => i), samples: N }).points],
  ['knotModifiedSurface 500² samples', (sl) => {
    const controlPoints = Array.from({ length: 20 }, (_, r) => Array.from({ length: 20 }, (_, s) => [r, s, Math.sin(0.5 * r) * Math.cos(0.4 * s)]));
    return sl.knotModifiedSurface({ surface: { orderU: 4, orderV: 4, knotsU: kn(20), knotsV: kn(20), controlPoints }, p: 8, up: 5.3, q: 10, vq: 7.6, samplesU: G, samplesV: G }).points;
  }],
  [`${SMALL} × bsplineCurve (8 points, 50 samples)`, (sl) => { let r; for (let i = 0; i < SMALL; i++) r = sl.bsplineCurve({ degree: 3, points: P8, samples: 50 }).points; return r; }],
  [`${SMALL} × b2Curve (8 points, 50 samples)`, (sl) => { let r; for (let i = 0; i < SMALL; i++) r = sl.b2Curve({ points: P8, a: 0.1, samples: 50 }).points; return r; }],
  [`${SMALL} × quasiCubicCurve (8 points, 50 samples)`, (sl) => { let r; for (let i = 0; i < SMALL; i++) r = sl.quasiCubicCurve({ points: P8, alpha: 0.5, samples: 50 }).points; return r; }],
  [`${SMALL / 10} × networkSurfaces (uniform dome, 20² samples)`, (sl) => {
    const network = sl.networkExample({ name: 'uniform-dome' });
    let r; for (let i = 0; i < SMALL / 10; i++) r = sl.networkSurfaces({ network, samplesU: 20, samplesV: 20 }); return r.surfaces.G.points;
  }],
];

console.log(`before/after benchmark — ${new Date().toISOString()}, ${process.version}, ${cpus()[0]?.model} ×${cpus().length}, load ${loadavg().map((x) => x.toFixed(1)).join(' ')}`);
console.log(`before = ${process.env.BEFORE}, after = ${process.env.AFTER || 'pkg-node'}; ${REPS} interleaved repetitions after 5 warm-up calls each; median (min) in ms\n`);
for (const [name, run] of rows) {
  if (only && !name.includes(only)) continue;
  const out = Object.fromEntries(Object.entries(builds).map(([k, sl]) => [k, run(sl)]));
  if (out.before?.length !== out.after?.length || out.before.some((x, i) => x !== out.after[i])) {
    console.log(`${name.padEnd(48)} OUTPUTS DIFFER (lengths ${out.before?.length}, ${out.after?.length})`);
    continue;
  }
  const t = { before: [], after: [] };
  for (let w = 0; w < 5; w++) for (const sl of Object.values(builds)) run(sl);
  for (let r = 0; r < REPS; r++) {
    for (const [k, sl] of Object.entries(builds)) { globalThis.gc?.(); const t0 = now(); run(sl); t[k].push(now() - t0); }
  }
  const [mb, ma, nb, na] = [median(t.before), median(t.after), Math.min(...t.before), Math.min(...t.after)];
  console.log(`${name.padEnd(48)} before ${mb.toFixed(2)} (${nb.toFixed(2)})  after ${ma.toFixed(2)} (${na.toFixed(2)})  after/before ${(ma / mb).toFixed(3)} median, ${(na / nb).toFixed(3)} min`);
}
