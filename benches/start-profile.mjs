// Where a demo's first drawing goes (issue 13): for every demo, loopback, warm-ish (one navigation per demo in a
// fresh context), the time inside the wasm exports before the first drawing (by export), the time inside the
// animation-frame callbacks (the first paint's JS: plots, 3D views), and when the module was instantiated and the
// demo mounted. Uses benches/common.mjs' init script (it times every export).
// Usage: node benches/start-profile.mjs [demo-id …]   RUNS=3 (medians)
import { startServer, launch, initScript, median, demoIds, demoExists, machine } from './common.mjs';

const RUNS = Number(process.env.RUNS || 3);
const only = process.argv.slice(2);
const m = machine();
const srv = await startServer();
const browser = await launch();
console.log(`first drawing, loopback, median of ${RUNS} — ${m.date}; load ${m.load}`);
console.log(`${'demo'.padEnd(24)} instantiated  mounted  first drawing   wasm before it   paint JS   top exports (ms)`);
for (const id of only.length ? only : (await demoIds()).filter(demoExists)) {
  const rs = [];
  for (let i = 0; i < RUNS; i++) {
    const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
    await context.addInitScript(initScript);
    const page = await context.newPage();
    await page.goto(srv.base + '#' + id);
    await page.waitForFunction(() => window.__perf?.marks.mountedFrame, null, { timeout: 60000 });
    rs.push(await page.evaluate(() => { const P = window.__perf; return { inst: P.instantiatedAt, mounted: P.marks.mounted, first: P.marks.mountedFrame, wasm: P.wasmMs, raf: P.rafMs, by: { ...P.byName } }; }));
    await context.close();
  }
  const med = (k) => median(rs.map((r) => r[k])).toFixed(0).padStart(6);
  const names = [...new Set(rs.flatMap((r) => Object.keys(r.by)))];
  const top = names.map((n) => [n, median(rs.map((r) => r.by[n] || 0))]).sort((a, b) => b[1] - a[1]).slice(0, 4).map(([n, t]) => `${n} ${t.toFixed(0)}`).join(', ');
  console.log(`${id.padEnd(24)} ${med('inst')}      ${med('mounted')}   ${med('first')}          ${med('wasm')}         ${med('raf')}   ${top}`);
}
await browser.close();
await srv.close();
