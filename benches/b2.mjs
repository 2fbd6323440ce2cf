// Benchmark (not a test): the API time of b2Curve for 200 data points and 2,000 samples, the work the
// "Interpolating vs approximating" demo does on every drag event. Median of many runs, Node against pkg-node/.
//
//   scripts/build-wasm.sh && node benches/b2.mjs
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';

const require = createRequire(import.meta.url);
const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const sl = require(join(root, 'pkg-node/splinelab.js'));

const N = 200;
const points = Array.from({ length: N }, (_, i) => {
  const t = (i / (N - 1)) * 6 * Math.PI;
  return [t + 0.3 * Math.sin(3 * t), 2 * Math.sin(t) + 0.2 * Math.cos(7 * t)];
});

function bench(name, opts, runs = 400) {
  for (let i = 0; i < 50; i++) sl.b2Curve(opts); // warm-up (JIT, allocator)
  const times = [];
  for (let i = 0; i < runs; i++) {
    const t0 = process.hrtime.bigint();
    const r = sl.b2Curve(opts);
    const t1 = process.hrtime.bigint();
    if (r.points.length !== 2 * (opts.samples ?? 200)) throw new Error('bad result');
    times.push(Number(t1 - t0) / 1e6);
  }
  times.sort((a, b) => a - b);
  const q = (f) => times[Math.min(times.length - 1, Math.floor(f * times.length))];
  console.log(`${name.padEnd(58)} median ${q(0.5).toFixed(3)} ms   p10 ${q(0.1).toFixed(3)}   p90 ${q(0.9).toFixed(3)}`);
  return q(0.5);
}

console.log(`b2Curve, ${N} data points, 2,000 samples (${process.version}, ${runs()} runs each)`);
function runs() { return 400; }
bench('a = 0, chord knots', { points, samples: 2000 });
bench('a = 0.1, K = 20, tension 0.13', { points, a: 0.1, K: 20, tension: 0.13, samples: 2000 });
bench('a = 0.05, autoTension "paper", derivatives: 2', { points, a: 0.05, autoTension: 'paper', samples: 2000, derivatives: 2 });
bench('a = 1/6 (the B-spline), uniform knots', { points, a: 1 / 6, knots: 'uniform', samples: 2000 });

// The same call inside headless Chromium (`node benches/b2.mjs --browser`): loads www/pkg in a blank page of
// the static server and times b2Curve there with performance.now().
if (process.argv.includes('--browser')) {
  const { chromium } = await import('playwright-core');
  const { serve } = await import(join(root, 'scripts/static-server.mjs'));
  const server = await serve(join(root, 'www'), 0, '127.0.0.1');
  const base = `http://127.0.0.1:${server.address().port}/`;
  const browser = await chromium.launch({ executablePath: process.env.CHROMIUM || '/usr/bin/chromium', args: ['--no-sandbox', '--headless'] });
  const page = await browser.newPage();
  await page.goto(base + 'pkg/splinelab.js');
  const res = await page.evaluate(async ({ pts, base }) => {
    const m = await import(base + 'pkg/splinelab.js');
    await m.default();
    const run = (o) => {
      for (let i = 0; i < 50; i++) m.b2Curve(o);
      const t = [];
      for (let i = 0; i < 400; i++) { const t0 = performance.now(); m.b2Curve(o); t.push(performance.now() - t0); }
      t.sort((a, b) => a - b);
      return [t[200], t[40], t[360]];
    };
    return {
      plain: run({ points: pts, samples: 2000 }),
      k: run({ points: pts, a: 0.1, K: 20, tension: 0.13, samples: 2000 }),
      auto: run({ points: pts, a: 0.05, autoTension: 'paper', samples: 2000, derivatives: 2 }),
    };
  }, { pts: points, base });
  console.log(`Chromium ${browser.version()} (performance.now() resolution may be coarse):`);
  for (const [k, [med, p10, p90]] of Object.entries(res)) console.log(`  ${k.padEnd(6)} median ${med.toFixed(3)} ms   p10 ${p10.toFixed(3)}   p90 ${p90.toFixed(3)}`);
  await browser.close();
  server.close();
}
