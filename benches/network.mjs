// Curve-network surfaces while dragging (issue 5 speed target): a 10 × 10 network (m = n = 9), one control point
// moved, then networkRepair + crissCrossSurface + thinPlateSurface (+ gordonSurface when exported), each tessellated
// at 64 × 64 (mesh: true). Median over REPS runs, from Node against pkg-node (release build).
// Usage: node benches/network.mjs   (after scripts/build-wasm.sh)
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const sl = createRequire(import.meta.url)(join(root, 'pkg-node/splinelab.js'));
const REPS = Number(process.env.REPS || 41);

const base = sl.networkExample({ name: 'dome10' });
const grid = { samplesU: 64, samplesV: 64, mesh: true };
const median = (xs) => [...xs].sort((a, b) => a - b)[xs.length >> 1];

function step(k) {
  const net = structuredClone(base);
  net.P[4][5][2] += 0.01 * Math.sin(k); // drag P_5^{(4)} in z
  const t0 = performance.now();
  const fixed = sl.networkRepair({ network: net, edited: { kind: 'P', r: 4, j: 5 } }).network;
  const t1 = performance.now();
  sl.crissCrossSurface({ network: fixed, ...grid });
  const t2 = performance.now();
  sl.thinPlateSurface({ network: fixed, ...grid });
  const t3 = performance.now();
  if (typeof sl.gordonSurface === 'function') sl.gordonSurface({ network: fixed, ...grid });
  const t4 = performance.now();
  return [t1 - t0, t2 - t1, t3 - t2, t4 - t3, t4 - t0];
}

for (let k = 0; k < 5; k++) step(k); // warm-up
const runs = Array.from({ length: REPS }, (_, k) => step(k));
const col = (c) => median(runs.map((r) => r[c])).toFixed(3);
console.log(`10 × 10 network, 64 × 64 tessellation, median of ${REPS} (ms):`);
const totals = runs.map((r) => r[4]).sort((a, b) => a - b);
console.log(`  total per drag step: min ${totals[0].toFixed(3)}, median ${col(4)}, 90th percentile ${totals[Math.floor(0.9 * totals.length)].toFixed(3)} (GC pauses land in one part or another)`);
console.log(`  networkRepair ${col(0)}  crissCrossSurface ${col(1)}  thinPlateSurface ${col(2)}  gordonSurface ${typeof sl.gordonSurface === 'function' ? col(3) : 'n/a'}  total ${col(4)}`);

// Input crossing (issue 13, "the boundary costs O(1) crossings"): a 40 × 40 network (m = n = 39: 40 curves each way,
// 41 control points each, 3280 points) read by networkCompatibility (a light computation: the C2 residuals), nested
// [[x, y, z], …] curves vs one Float64Array per curve vs P and Q as two whole flat Float64Arrays. Same results bit for
// bit (tests/node/network-flat.test.mjs); interleaved in one run, median of REPS_IO.
{
  const REPS_IO = Number(process.env.REPS_IO || 201);
  const breaks = Array.from({ length: 40 }, (_, i) => i / 39);
  const big = sl.networkFromFunction({ u: breaks, v: breaks, f: (u, v) => [u, v, Math.sin(3 * u) * Math.cos(2 * v)] });
  const forms = {
    nested: big,
    'Float64Array curves': { ...big, P: big.P.map((r) => Float64Array.from(r.flat())), Q: big.Q.map((r) => Float64Array.from(r.flat())) },
    'whole flat tables': { u: Float64Array.from(big.u), v: Float64Array.from(big.v), P: Float64Array.from(big.P.flat(2)), Q: Float64Array.from(big.Q.flat(2)) },
  };
  const names = Object.keys(forms);
  const times = Object.fromEntries(names.map((k) => [k, []]));
  const ref = sl.networkCompatibility({ network: big }).residuals;
  for (let k = 0; k < REPS_IO + 10; k++) {
    for (const name of names) {
      const t0 = performance.now();
      const r = sl.networkCompatibility({ network: forms[name] });
      const t = performance.now() - t0;
      if (r.residuals[7] !== ref[7]) throw new Error(`${name}: a different result`);
      if (k >= 10) times[name].push(t);
    }
  }
  const med = Object.fromEntries(names.map((k) => [k, median(times[k])]));
  console.log(`40 × 40 network (3280 control points), networkCompatibility, median of ${REPS_IO} interleaved (ms):`);
  console.log('  ' + names.map((k) => `${k} ${med[k].toFixed(3)}${k === 'nested' ? '' : ` (${(med.nested / med[k]).toFixed(1)}× faster)`}`).join('  '));
}
