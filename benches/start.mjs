// Start-up (issue 8): time from navigation to the first interactive drawing in headless Chromium, for the gallery
// and one demo, cold (fresh browser context: empty HTTP cache, module compiled from scratch) and warm (the
// same context navigating again: HTTP cache, and V8's code cache for the wasm module).
// Usage: node benches/start.mjs [demo-id]   (default bspline-basics; after scripts/build-wasm.sh)   RUNS=7
//
// Marks (ms from navigationStart; performance.timing / PerformanceObserver and the shell's readiness markers,
// recorded by benches/common.mjs' init script):
//   FCP        first contentful paint (PerformanceObserver 'paint')
//   wasm       the module instantiated (WebAssembly.instantiateStreaming resolved; includes fetch + compile)
//   ready      <html data-ready="true"> (the shell has loaded the module and rendered its view)
//   interactive the gallery: the second frame after `ready` (its first drawing done); a demo: the second frame after #demo-root[data-mounted],
//              i.e. its first drawing is on screen and its handles accept input
import { startServer, launch, initScript, machine, median } from './common.mjs';

const RUNS = Number(process.env.RUNS || 7);
const demo = process.argv[2] || 'bspline-basics';
const m = machine();
const srv = await startServer();
const browser = await launch();

async function measure(context, route, isDemo) {
  const page = await context.newPage();
  await page.goto(srv.base + route);
  await page.waitForFunction((d) => {
    const P = window.__perf;
    return P && (d ? P.marks.mountedFrame : P.marks.readyFrame);
  }, isDemo, { timeout: 30000 });
  const r = await page.evaluate(() => {
    const P = window.__perf;
    const fcp = performance.getEntriesByName('first-contentful-paint')[0]?.startTime ?? NaN;
    const nav = performance.getEntriesByType('navigation')[0];
    return {
      fcp, wasm: P.instantiatedAt, instantiate: P.instantiateMs, wasmStart: P.instantiateStart,
      jsFiles: performance.getEntriesByType('resource').filter((e) => /\.m?js$/.test(e.name)).length, ready: P.marks.ready,
      interactive: P.marks.mountedFrame || P.marks.readyFrame, domContentLoaded: nav?.domContentLoadedEventEnd ?? NaN,
      bytes: performance.getEntriesByType('resource').reduce((s, e) => s + (e.transferSize || 0), nav?.transferSize || 0),
    };
  });
  await page.close();
  return r;
}

const rows = [];
for (const [name, route, isDemo] of [['gallery', '', false], [`demo #${demo}`, `#${demo}`, true]]) {
  const cold = [], warm = [];
  for (let i = 0; i < RUNS; i++) {
    const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
    await context.addInitScript(initScript);
    cold.push(await measure(context, route, isDemo));
    warm.push(await measure(context, route, isDemo));
    await context.close();
  }
  rows.push([name, cold, warm]);
}
await browser.close();
await srv.close();

console.log(`start-up: navigation → first interactive drawing, headless Chromium (--disable-gpu), 1280×900, local server; median of ${RUNS} — ${m.date}`);
console.log(`machine: ${m.cpus} CPUs, load ${m.load}; ${m.lscpu}; ${m.chromium}`);
console.log('ms from navigation start      FCP    DOMContentLoaded   wasm requested → instantiated   ready   interactive   (min interactive)   JS modules');
const f = (x) => x.toFixed(0).padStart(6);
for (const [name, cold, warm] of rows) {
  for (const [kind, xs] of [['cold', cold], ['warm', warm]]) {
    const med = (k) => median(xs.map((x) => x[k]));
    console.log(`${(name + ', ' + kind).padEnd(28)} ${f(med('fcp'))}   ${f(med('domContentLoaded'))}            ${f(med('wasmStart'))} → ${f(med('wasm'))}         ${f(med('ready'))}   ${f(med('interactive'))}        (${f(Math.min(...xs.map((x) => x.interactive)))})          ${med('jsFiles')}`);
  }
}
const worst = Math.max(...rows.map(([, cold]) => median(cold.map((x) => x.interactive))));
console.log(`target (< 500 ms to the first interactive drawing, cold): ${worst < 500 ? 'met' : 'NOT met'} (worst median ${worst.toFixed(0)} ms)`);
