// Start-up contract (issue 13): the page starts the wasm fetch and the whole static module graph with the HTML
// (preload hints), fetches the wasm once, and a demo route draws without waiting for the other demos' modules.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, existsSync } from 'node:fs';
import { join, dirname, relative } from 'node:path';
import { startHarness, WWW, demoIds } from './harness.mjs';

let H;
before(async () => { H = await startHarness(); });
after(() => H?.close());

/** Static imports of a module (relative specifiers), as paths relative to www/. */
function staticImports(file) {
  const src = readFileSync(join(WWW, file), 'utf8');
  return [...src.matchAll(/^\s*import\s+(?:[^'"]*?\sfrom\s+)?['"](\.[^'"]+)['"]/gm)]
    .map((m) => relative(WWW, join(WWW, dirname(file), m[1])));
}
function graph(roots) {
  const seen = new Set();
  const walk = (f) => { if (seen.has(f)) return; seen.add(f); for (const g of staticImports(f)) walk(g); };
  roots.forEach(walk);
  return seen;
}
const hints = (html) => {
  const src = readFileSync(join(WWW, html), 'utf8');
  return {
    modules: [...src.matchAll(/<link rel="modulepreload" href="([^"]+)">/g)].map((m) => m[1]),
    fetches: [...src.matchAll(/<link rel="preload" href="([^"]+)" as="fetch" crossorigin>/g)].map((m) => m[1]),
  };
};

test('index.html and embed.html preload the wasm and every module of the static graph (app.js and what the demos import)', async () => {
  const ids = (await demoIds()).filter((id) => existsSync(join(WWW, 'demos', `${id}.js`)));
  // the shell's graph, plus what the demos import (not the demo modules themselves: only the routed one loads)
  const want = new Set([...graph(['app.js']), ...[...graph(ids.map((id) => `demos/${id}.js`))].filter((f) => !/^demos\/(?!index\.js)/.test(f)), 'pkg/splinelab.js']);
  for (const html of ['index.html', 'embed.html']) {
    const { modules, fetches } = hints(html);
    assert.deepEqual(fetches, ['pkg/splinelab_bg.wasm'], `${html}: the wasm is preloaded as a CORS fetch (what app.js's fetch() asks for)`);
    for (const f of want) assert.ok(modules.includes(f), `${html}: no <link rel="modulepreload" href="${f}">`);
    for (const f of modules) {
      assert.ok(f === 'pkg/splinelab.js' || existsSync(join(WWW, f)), `${html}: preloads ${f}, which does not exist`);
      assert.ok(want.has(f), `${html}: preloads ${f}, which nothing imports statically`);
    }
  }
});

for (const page of ['index.html', 'embed.html']) {
  test(`${page}: a demo route draws while the other demos' modules are still loading; the wasm is fetched once, first`, async () => {
    const ids = (await demoIds()).filter((id) => existsSync(join(WWW, 'demos', `${id}.js`)));
    const first = ids.includes('interp-approx') ? 'interp-approx' : ids[0];
    const context = await H.browser.newContext({ viewport: { width: 1280, height: 900 } });
    const held = [];
    // hold every other demo module until the end of the test (a shell that waits for them never gets ready)
    await context.route(/\/demos\/[a-z0-9-]+\.js$/, (route) => {
      const url = route.request().url();
      if (url.endsWith('/demos/index.js') || url.endsWith(`/demos/${first}.js`)) return route.continue();
      held.push(route);
    });
    const requests = [];
    const errors = [];
    const p = await context.newPage();
    p.on('request', (r) => requests.push(new URL(r.url()).pathname));
    p.on('pageerror', (e) => errors.push(String(e)));
    p.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
    await p.goto(`${H.base}${page === 'index.html' ? '' : page}#${first}`);
    await p.waitForFunction(() => document.documentElement.dataset.ready === 'true', null, { timeout: 20000 });
    await p.waitForSelector('#demo-root[data-mounted="true"]', { timeout: 20000 });
    assert.ok(await p.$eval('#demo-root canvas', (c) => c.width > 0), 'the demo drew a canvas');
    const wasm = requests.filter((u) => u.endsWith('/pkg/splinelab_bg.wasm'));
    assert.equal(wasm.length, 1, `the wasm is fetched once (the preload is what the shell's fetch uses): ${requests.join(' ')}`);
    assert.ok(requests.indexOf('/pkg/splinelab_bg.wasm') < requests.indexOf('/demos/index.js'),
      `the wasm request starts with the page, before the modules app.js imports: ${requests.join(' ')}`);
    for (const r of held) await r.continue().catch(() => {});
    await context.unroute(/\/demos\/[a-z0-9-]+\.js$/);
    if (page === 'index.html') {
      // the gallery still lists every demo once they have loaded
      await p.evaluate(() => { location.hash = ''; });
      await p.waitForFunction((n) => document.querySelectorAll('.cards .card').length === n, ids.length, { timeout: 20000 });
      assert.equal(await p.$$eval('.cards .card.unavailable', (c) => c.length), 0, 'every demo card is available');
    }
    assert.deepEqual(errors, []);
    await context.close();
  });
}
