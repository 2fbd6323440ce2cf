// Surfaces (issue 8): S (crissCrossSurface), T (thinPlateSurface), G (gordonSurface), GB (splineBlendedSurface)
// and a quasi-cubic sphere (quasiCubicSurface) tessellated to render buffers (`mesh: true`) at 64×64 and 256×256,
// and how the time grows with the network size 10×10 → 40×40 (networks from networkFromFunction).
// Usage: node benches/surfaces-all.mjs   (after scripts/build-wasm.sh)   REPS=5
// Functions not on this branch yet are skipped with a note.
import { createRequire } from 'node:module';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { cpus, loadavg } from 'node:os';

const require = createRequire(import.meta.url);
const sl = require(join(dirname(fileURLToPath(import.meta.url)), '../pkg-node/splinelab.js'));
const REPS = Number(process.env.REPS || 5);
const median = (xs) => [...xs].sort((a, b) => a - b)[xs.length >> 1];
function time(fn) {
  fn();
  const ts = [];
  for (let r = 0; r < REPS; r++) { const t0 = performance.now(); fn(); ts.push(performance.now() - t0); }
  return Math.min(...ts); // the minimum: the machine is shared, contention only adds time
}

// the test surface: a smooth bump over the unit square
const f = (u, v) => [u, v, 0.3 * Math.sin(Math.PI * u) * Math.cos(Math.PI * v) + 0.1 * u * v];
const lin = (n) => Array.from({ length: n }, (_, i) => i / (n - 1));
const networks = new Map();
const network = (k) => {
  if (!networks.has(k)) networks.set(k, sl.networkFromFunction({ u: lin(k), v: lin(k), f }));
  return networks.get(k);
};
// uniform knots u_{−1}..u_{m+2} for the B2 blend of GB (m + 1 lines)
const b2Knots = (k) => Array.from({ length: k + 3 }, (_, j) => (j - 1) / (k - 1));

const surfaces = [
  ['S  crissCrossSurface', 'crissCrossSurface', (k) => ({ network: network(k) })],
  ['T  thinPlateSurface', 'thinPlateSurface', (k) => ({ network: network(k) })],
  ['G  gordonSurface', 'gordonSurface', (k) => ({ network: network(k) })],
  ['GB splineBlendedSurface', 'splineBlendedSurface', (k) => ({ network: f, uKnots: b2Knots(k), vKnots: b2Knots(k) })],
];

const rows = [];
const notes = [];
const sizes = [10, 20, 40];
for (const [label, fn, opts] of surfaces) {
  if (typeof sl[fn] !== 'function') { notes.push(`${label}: not on this branch yet (skipped)`); continue; }
  try {
    for (const k of sizes) {
      const o = opts(k);
      const setup = time(() => sl[fn]({ ...o, samplesU: 2, samplesV: 2 }));
      const t64 = time(() => sl[fn]({ ...o, samplesU: 64, samplesV: 64, mesh: true }));
      const t256 = time(() => sl[fn]({ ...o, samplesU: 256, samplesV: 256, mesh: true }));
      rows.push([label, `${k}×${k}`, setup, t64, t256]);
    }
  } catch (e) { notes.push(`${label}: failed: ${e.message}`); }
}
// the quasi-cubic sphere: quasiCubicPreset({ name: 'sphere' }) (the control grid of the quasi-cubic surfaces demo)
if (typeof sl.quasiCubicSurface !== 'function') notes.push('quasi-cubic sphere (quasiCubicSurface): not on this branch yet (skipped)');
else {
  try {
    const pr = sl.quasiCubicPreset({ name: 'sphere' });
    const o = { grid: pr.grid, alpha: pr.alpha, periodicU: pr.periodicU, periodicV: pr.periodicV };
    const setup = time(() => sl.quasiCubicSurface({ ...o, samplesU: 2, samplesV: 2 }));
    const t64 = time(() => sl.quasiCubicSurface({ ...o, samplesU: 64, samplesV: 64, mesh: true }));
    const t256 = time(() => sl.quasiCubicSurface({ ...o, samplesU: 256, samplesV: 256, mesh: true }));
    rows.push(['QC quasi-cubic sphere', `${pr.grid.length}×${pr.grid[0].length}`, setup, t64, t256]);
  } catch (e) { notes.push(`quasi-cubic sphere: failed: ${e.message}`); }
}

console.log(`surfaces tessellated with mesh: true (positions + normals + indices), wasm from Node ${process.version}; minimum of ${REPS} runs (after one warm-up) — ${new Date().toISOString()}`);
console.log(`machine: ${cpus().length} CPUs (${cpus()[0]?.model}), load ${loadavg().map((x) => x.toFixed(1)).join(' ')}`);
console.log('ms                         network   2×2 (≈ construction)   64×64 mesh   256×256 mesh   µs/vertex at 256²');
for (const [l, k, s, a, b] of rows) console.log(`${l.padEnd(26)} ${k.padStart(7)}   ${s.toFixed(2).padStart(10)}            ${a.toFixed(2).padStart(8)}     ${b.toFixed(2).padStart(9)}      ${(1000 * (b - s) / 65536).toFixed(3)}`);
for (const n of notes) console.log(n);
