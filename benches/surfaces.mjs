// Curve-network surfaces benchmark (issue 5): while a point of an N×N network is dragged, recompute every
// surface through it (S, T, G, GB) and tessellate each at 64×64 (also 256×256), with the paper's norms on the
// 57×57 grid: the `networkRepair` + `networkSurfaces` calls the "Curve networks" demo makes per drag event.
// Reports the API time per drag (median, p95) for networks 10×10 → 40×40, in Node and in headless Chromium.
// Usage: node benches/surfaces.mjs   (after scripts/build-wasm.sh)   REPS=60 for more drags; NO_CHROMIUM=1 to skip.
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const require = createRequire(import.meta.url);
const REPS = Number(process.env.REPS || 40);
const CASES = [[10, 64], [10, 256], [20, 64], [40, 64], [40, 256]];

// The benchmark body, run in Node and (as source text) in the browser: `sl` is the wasm module.
function runBench(sl, REPS, CASES) {
  const now = () => (typeof performance !== 'undefined' ? performance.now() : Date.now());
  const pct = (xs, p) => { const s = [...xs].sort((a, b) => a - b); return s[Math.min(s.length - 1, Math.floor(p * s.length))]; };
  // a dome's biquadratic control net on an N×N grid (networkFromControlNet builds the compatible network)
  function domeNet(N) {
    const u = Array.from({ length: N + 1 }, (_, i) => i / N);
    const xi = [u[0], ...u.slice(1).map((x, i) => (u[i] + x) / 2), u[N]];
    const C = xi.map((x) => xi.map((y) => [x, y, 1 - (x - 0.5) ** 2 - (y - 0.5) ** 2 + 0.2 * Math.sin(5 * x + 3 * y)]));
    return sl.networkFromControlNet({ u, v: u, C });
  }
  const out = [];
  for (const [N, samples] of CASES) {
    let net = domeNet(N);
    const r = Math.floor(N / 2), j = Math.floor(N / 2) + 1;
    const p0 = net.P[r][j].slice();
    const opts = (network) => ({ network, samplesU: samples, samplesV: samples });
    sl.networkSurfaces(opts(net)); // warm-up
    const all = [], surf = [], noNorms = [];
    let names = [];
    for (let k = 0; k < REPS; k++) {
      // the drag: move P_j^{(r)} up, repair the network, recompute all four surfaces
      const t0 = now();
      const edited = { ...net, P: net.P.map((row) => row.slice()) };
      edited.P[r][j] = [p0[0], p0[1], p0[2] + 0.3 * Math.sin(k / 3)];
      net = sl.networkRepair({ network: edited, edited: { kind: 'P', r, j } }).network;
      const t1 = now();
      const res = sl.networkSurfaces(opts(net));
      const t2 = now();
      all.push(t2 - t0); surf.push(t2 - t1);
      names = res.names;
      if (k < 10) { const t3 = now(); sl.networkSurfaces({ ...opts(net), normSamples: 0 }); noNorms.push(now() - t3); }
    }
    out.push({ N, samples, names: names.join('+'), median: pct(all, 0.5), p95: pct(all, 0.95), surfMedian: pct(surf, 0.5), surfP95: pct(surf, 0.95), noNorms: pct(noNorms, 0.5) });
  }
  return out;
}

function print(title, rows) {
  console.log(`\n${title} (${REPS} drags; ms)`);
  console.log('network  grid      surfaces     repair+surfaces median/p95   networkSurfaces median/p95   (no norms: median)');
  for (const r of rows) {
    console.log(`${String(r.N).padStart(2)}×${String(r.N).padEnd(4)} ${String(r.samples).padStart(3)}×${String(r.samples).padEnd(4)} ${r.names.padEnd(12)} ${r.median.toFixed(2).padStart(10)} / ${r.p95.toFixed(2).padEnd(12)} ${r.surfMedian.toFixed(2).padStart(12)} / ${r.surfP95.toFixed(2).padEnd(12)} ${r.noNorms.toFixed(2).padStart(8)}`);
  }
}

const sl = require(join(root, 'pkg-node/splinelab.js'));
print(`Node ${process.version}`, runBench(sl, REPS, CASES));

if (!process.env.NO_CHROMIUM) {
  const { chromium } = await import(join(root, 'node_modules/playwright-core/index.mjs'));
  const { serve } = await import(join(root, 'scripts/static-server.mjs'));
  const server = await serve(join(root, 'www'), 0, '127.0.0.1');
  const base = `http://127.0.0.1:${server.address().port}/`;
  const browser = await chromium.launch({ executablePath: process.env.CHROMIUM || '/usr/bin/chromium', args: ['--no-sandbox', '--disable-gpu'] });
  try {
    const page = await browser.newPage();
    await page.goto(`${base}pkg/splinelab.js`); // a same-origin document without the pages' CSP
    const rows = await page.evaluate(async ([src, reps, cases]) => {
      const m = await import('/pkg/splinelab.js');
      await m.default();
      return (0, eval)(`(${src})`)(m, reps, cases);
    }, [runBench.toString(), REPS, CASES]);
    print(`Chromium ${browser.version()} (headless)`, rows);
  } finally {
    await browser.close();
    server.close();
  }
}
