// One-call sweeps (issue 13), side by side in one Node process, medians of several runs, same work:
//  1. the Fig. 3 curvature plot of the Bézier remodelling demo: 61 bezierRemodel calls (before) vs one call
//     with `alphaSweep` (after), outputs compared;
//  2. b2FitSweep (36 values of a, distances of 400 fitted points to the 2001-point true curve, no CV) in this
//     build (spatial grid) vs an older build given as OLD=path/to/pkg-node (brute force over every segment).
//   scripts/build-wasm.sh && OLD=/work/main/pkg-node node benches/sweeps.mjs
import { createRequire } from 'node:module';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { cpus } from 'node:os';

const require = createRequire(import.meta.url);
const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const sl = require(join(root, 'pkg-node/splinelab.js'));
const old = process.env.OLD ? require(join(process.env.OLD, 'splinelab.js')) : null;
const RUNS = Number(process.env.RUNS || 9);

const median = (xs) => { const s = [...xs].sort((a, b) => a - b); return s[s.length >> 1]; };
function time(fn, reps) {
  fn();
  const ms = [];
  for (let r = 0; r < RUNS; r++) { const t0 = performance.now(); for (let i = 0; i < reps; i++) fn(); ms.push((performance.now() - t0) / reps); }
  return median(ms);
}

console.log(`machine: ${cpus().length} × ${cpus()[0].model}; node ${process.version}; ${new Date().toISOString()}; medians of ${RUNS}`);

// 1. Fig. 3 sweep
const ex = [[10, 16], [7, 21], [3, 9], [0, 0], [-4, 0], [-8, 0], [-6, 3], [-4, 6], [2, 2], [8, -2], [10, 3]];
const base = { points: ex, degree: 2, breaks: [0, 1, 7 / 4, 5 / 2, 13 / 4, 4], alphas: [[2 / 3, 1 / 20], [19 / 20, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 10]], r: 1, enforce: true, at: [] };
const I = 2, xs = Array.from({ length: 61 }, (_, j) => 0.004 + (0.5 - 0.004) * j / 60);
const perValue = () => xs.map((a) => { const al = base.alphas.map((r) => [...r]); al[I - 1][1] = a; return sl.bezierRemodel({ ...base, alphas: al }).curvature[I]; });
const oneCall = () => sl.bezierRemodel({ ...base, alphaSweep: xs, alphaSweepJoint: I }).sweepCurvature;
const a1 = perValue(), a2 = oneCall();
const diff = Math.max(...a1.map((x, j) => Math.abs(x - a2[j])));
const t1 = time(perValue, 20), t2 = time(oneCall, 20);
console.log(`Fig. 3 sweep (61 α): 61 calls ${t1.toFixed(3)} ms, 1 call ${t2.toFixed(3)} ms → ${(t1 / t2).toFixed(1)}× (max |Δ| = ${diff})`);

// 2. b2FitSweep distances
const data = sl.noisyData({ curve: 'lemniscate', count: 100, sigma: 0.2, seed: 1 });
const pts = Array.from({ length: data.points.length / 2 }, (_, i) => [data.points[2 * i], data.points[2 * i + 1]]);
const fo = { points: pts, truthCurve: 'lemniscate', aMin: -0.1, aMax: 0.25, steps: 36, cv: false };
const tn = time(() => sl.b2FitSweep(fo), 3);
const rn = sl.b2FitSweep(fo);
if (old) {
  const to = time(() => old.b2FitSweep(fo), 3);
  const ro = old.b2FitSweep(fo);
  const d = Math.max(...['rms', 'max', 'residualRms'].flatMap((k) => Array.from(ro[k], (x, j) => Math.abs(x - rn[k][j]))));
  console.log(`b2FitSweep 36 a × 400 points vs 2000 segments, cv off: old (brute force) ${to.toFixed(2)} ms, new (grid) ${tn.toFixed(2)} ms → ${(to / tn).toFixed(1)}× (max |Δ| = ${d.toExponential(2)})`);
} else {
  console.log(`b2FitSweep 36 a × 400 points vs 2000 segments, cv off: ${tn.toFixed(2)} ms (OLD=… for the brute-force build)`);
}
const fc = { ...fo, cv: true };
console.log(`b2FitSweep with cv (the demo's default): ${time(() => sl.b2FitSweep(fc), 1).toFixed(2)} ms${old ? `; old ${time(() => old.b2FitSweep(fc), 1).toFixed(2)} ms` : ''}`);

// 3. quasi-cubic uniform samples with two derivatives (rotation recurrence vs sin_cos per point)
const poly = Array.from({ length: 40 }, (_, i) => [i, Math.sin(i * 0.7) * 3]);
const qo = { points: poly, alpha: 0.5, samples: 1_000_000, derivatives: 2 };
const qn = time(() => sl.quasiCubicCurve(qo), 1);
if (old) {
  const qd = old.quasiCubicCurve(qo), qm = sl.quasiCubicCurve(qo);
  const d = Math.max(...['points', 'd1', 'd2'].map((k) => { let m = 0; for (let i = 0; i < qd[k].length; i++) m = Math.max(m, Math.abs(qd[k][i] - qm[k][i])); return m; }));
  const qt = time(() => old.quasiCubicCurve(qo), 1);
  console.log(`quasiCubicCurve 1M samples + d1 + d2: old ${qt.toFixed(1)} ms, new ${qn.toFixed(1)} ms → ${(qt / qn).toFixed(2)}× (max |Δ| = ${d.toExponential(2)})`);
} else console.log(`quasiCubicCurve 1M samples + d1 + d2: ${qn.toFixed(1)} ms`);
