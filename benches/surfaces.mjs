// Curve-network surfaces benchmark (issue 5): while a point of an N×N network is dragged, recompute every
// surface through it (S, T, G, GB — those this build has) and tessellate each at 64×64 (also 256×256), with
// the three norms on the paper's 57×57 grid: the `networkSurfaces` call the "Curve networks" demo makes per
// drag event. Reports the API time per drag (median, p95) for networks 10×10 → 40×40.
// Usage: node benches/surfaces.mjs   (after scripts/build-wasm.sh)   REPS=60 to change the drag count.
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const require = createRequire(import.meta.url);
const sl = require(join(root, 'pkg-node/splinelab.js'));
const REPS = Number(process.env.REPS || 40);

// A compatible network: the isocurves of a biquadratic tensor surface Σ C_ij B_i B_j (Schoenberg net of a
// dome). networkFromFunction / networkFromControlNet build it when the module has them; otherwise the
// isocurve formula P_j^(r) = σ_{r+1} C_rj + σ'_{r+1} C_{r+1,j} (surfaces.md §9) is applied here.
function isocurves(u, v, C) {
  const m = u.length - 1, n = v.length - 1;
  const h = (x, r) => (r >= 1 && r < x.length ? x[r] - x[r - 1] : 0);
  const w = (x, r) => { const a = h(x, r), b = h(x, r + 1); return [b / (a + b), a / (a + b)]; }; // σ_{r+1}, σ'_{r+1}
  const mix = (p, q, [s, t]) => [s * p[0] + t * q[0], s * p[1] + t * q[1], s * p[2] + t * q[2]];
  const P = u.map((_, r) => Array.from({ length: n + 2 }, (_, j) => mix(C[r][j], C[r + 1][j], w(u, r))));
  const Q = v.map((_, s) => Array.from({ length: m + 2 }, (_, i) => mix(C[i][s], C[i][s + 1], w(v, s))));
  return { u, v, P, Q };
}
function domeNet(N, bump = 0) {
  const u = Array.from({ length: N + 1 }, (_, i) => i / N);
  const xi = [u[0], ...u.slice(1).map((x, i) => (u[i] + x) / 2), u[N]]; // Greville
  const C = xi.map((x, i) => xi.map((y, j) => [x, y, 1 - (x - 0.5) ** 2 - (y - 0.5) ** 2 + 0.2 * Math.sin(5 * x + 3 * y)]));
  const mid = (N + 2) >> 1;
  C[mid][mid][2] += bump; // the dragged point
  return isocurves(u, u, C);
}

const pct = (xs, p) => { const s = [...xs].sort((a, b) => a - b); return s[Math.min(s.length - 1, Math.floor(p * s.length))]; };
function bench(N, samples) {
  const nets = Array.from({ length: REPS }, (_, k) => domeNet(N, 0.3 * Math.sin(k / 3)));
  const opts = (network) => ({ network, samplesU: samples, samplesV: samples });
  sl.networkSurfaces(opts(nets[0])); // warm-up
  const ts = [];
  let names = [];
  for (const net of nets) {
    const t0 = process.hrtime.bigint();
    const r = sl.networkSurfaces(opts(net));
    ts.push(Number(process.hrtime.bigint() - t0) / 1e6);
    names = r.names;
  }
  // the tessellation alone (no norms)
  const ts2 = [];
  for (const net of nets.slice(0, 10)) {
    const t0 = process.hrtime.bigint();
    sl.networkSurfaces({ ...opts(net), normSamples: 0 });
    ts2.push(Number(process.hrtime.bigint() - t0) / 1e6);
  }
  return { N, samples, names: names.join('+'), median: pct(ts, 0.5), p95: pct(ts, 0.95), noNorms: pct(ts2, 0.5) };
}

console.log(`networkSurfaces per drag (Node ${process.version}, ${REPS} drags; times in ms)`);
console.log('network  grid     surfaces        median    p95   (without the 57×57 norms: median)');
for (const [N, s] of [[10, 64], [10, 256], [20, 64], [40, 64], [40, 256]]) {
  const r = bench(N, s);
  console.log(`${String(N).padStart(2)}×${String(N).padEnd(4)} ${String(s).padStart(3)}×${String(s).padEnd(4)} ${r.names.padEnd(14)} ${r.median.toFixed(2).padStart(7)} ${r.p95.toFixed(2).padStart(7)}   ${r.noNorms.toFixed(2).padStart(7)}`);
}
