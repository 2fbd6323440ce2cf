// Start-up contract (issue 13): the page starts the whole static module graph with the HTML (preload hints) and the
// fetch of the routed demo's wasm module early (lib/wasm-preload.js); a demo route loads only its group's wasm
// module (www/lib/wasm-groups.js), never the complete one, fetches it once, and draws without waiting for the other
// demos' modules; every demo's group module has every export the demo calls.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, existsSync, readdirSync } from 'node:fs';
import { join, dirname, relative } from 'node:path';
import { startHarness, WWW, demoIds } from './harness.mjs';
import { WASM_GROUPS, groupOf } from '../../www/lib/wasm-groups.js';

let H;
before(async () => { H = await startHarness({ warm: true /* the idle warm-up on, as a visitor has it */, fresh: true /* a first visit: nothing cached */ }); });
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

test('index.html and embed.html preload every module of the static graph (app.js, wasm-preload.js and what the demos import), and no wasm', async () => {
  const ids = (await demoIds()).filter((id) => existsSync(join(WWW, 'demos', `${id}.js`)));
  // the shell's graph, plus what the demos import (not the demo modules themselves: only the routed one loads)
  const want = new Set([...graph(['app.js', 'lib/wasm-preload.js']), ...[...graph(ids.map((id) => `demos/${id}.js`))].filter((f) => !/^demos\/(?!index\.js)/.test(f))]);
  for (const html of ['index.html', 'embed.html']) {
    const { modules, fetches } = hints(html);
    // the wasm depends on the routed demo (its group): lib/wasm-preload.js adds that hint, the HTML has none
    assert.deepEqual(fetches, [], `${html}: no static wasm preload (the complete module is not what a demo loads)`);
    assert.match(readFileSync(join(WWW, html), 'utf8'), /<script type="module" async src="lib\/wasm-preload\.js"><\/script>/, `${html}: the wasm preload script`);
    for (const f of want) assert.ok(modules.includes(f), `${html}: no <link rel="modulepreload" href="${f}">`);
    for (const f of modules) {
      assert.ok(existsSync(join(WWW, f)), `${html}: preloads ${f}, which does not exist`);
      assert.ok(want.has(f), `${html}: preloads ${f}, which nothing imports statically`);
    }
  }
});

test('every demo has a group, and its group module exports every wasm function the demo calls', async () => {
  const ids = await demoIds();
  const listed = Object.values(WASM_GROUPS).flatMap((g) => g.demos);
  assert.deepEqual([...listed].sort(), [...ids].sort(), 'each demo is in exactly one group');
  for (const id of ids) {
    // the demo's entry and its own modules (www/demos/<id>/, where a demo is split into figure files)
    const own = existsSync(join(WWW, 'demos', id)) ? readdirSync(join(WWW, 'demos', id)).filter((f) => f.endsWith('.js')).map((f) => join(WWW, 'demos', id, f)) : [];
    const src = [join(WWW, 'demos', `${id}.js`), ...own].map((f) => readFileSync(f, 'utf8')).join('\n');
    // the exports the demo calls: wasm.name( and w.name( (preset builders get the module as `w`)
    const calls = [...new Set([...src.matchAll(/\b(?:wasm|w)\.([A-Za-z0-9_]+)\s*\(/g)].map((m) => m[1]))];
    const glue = readFileSync(join(WWW, 'pkg', groupOf(id), 'splinelab.js'), 'utf8');
    const full = readFileSync(join(WWW, 'pkg', 'splinelab.js'), 'utf8');
    const exported = new Set([...glue.matchAll(/^export function ([A-Za-z0-9_]+)\(/gm)].map((m) => m[1]));
    const api = new Set([...full.matchAll(/^export function ([A-Za-z0-9_]+)\(/gm)].map((m) => m[1]));
    assert.ok(calls.some((c) => api.has(c)), `${id}: found the exports it calls (${calls.join(' ')})`);
    for (const c of calls) if (api.has(c)) assert.ok(exported.has(c), `${id}: calls ${c}, which its group module pkg/${groupOf(id)}/ does not export`);
    assert.ok(exported.size < api.size, `${id}: the group module pkg/${groupOf(id)}/ is smaller than the complete module`);
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
    const own = `/pkg/${groupOf(first)}/splinelab_bg.wasm`;
    const wasm = requests.filter((u) => u.endsWith('.wasm'));
    assert.deepEqual(wasm, [own], `only the demo's group module is fetched, once (the preload is what the shell's fetch uses): ${requests.join(' ')}`);
    assert.ok(!requests.includes('/pkg/splinelab.js'), 'the complete module\'s glue is not loaded');
    assert.ok(requests.indexOf(own) < requests.indexOf(`/demos/${first}.js`),
      `the wasm request starts before app.js imports the demo: ${requests.join(' ')}`);
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

test('every demo on embed.html loads its group module only, and mounts with no error', async () => {
  const context = await H.browser.newContext({ viewport: { width: 1000, height: 800 } });
  const p = await context.newPage();
  const requests = [];
  const errors = [];
  p.on('request', (r) => requests.push(new URL(r.url()).pathname));
  p.on('pageerror', (e) => errors.push(String(e)));
  p.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  for (const id of await demoIds()) {
    await p.goto('about:blank');
    // (after the previous demo is gone: its compute worker may have fetched its glue while the page was left)
    requests.length = 0;
    await p.goto(`${H.base}embed.html#${id}`);
    await p.waitForFunction(() => document.documentElement.dataset.ready, null, { timeout: 30000 });
    await p.waitForSelector('#demo-root[data-mounted="true"]', { timeout: 30000 });
    // (a demo that computes in a worker, www/lib/compute-client.js, loads the same glue there; the wasm it is handed)
    const pkg = requests.filter((u) => /\/pkg\//.test(u));
    assert.deepEqual([...new Set(pkg)].sort(), [`/pkg/${groupOf(id)}/splinelab.js`, `/pkg/${groupOf(id)}/splinelab_bg.wasm`], `${id}: the requests for wasm modules`);
    assert.equal(pkg.filter((u) => u.endsWith('.wasm')).length, 1, `${id}: the wasm is fetched once`);
    assert.equal(await p.evaluate(() => document.querySelectorAll('.notice-error, .fatal').length), 0, `${id}: no error shown`);
  }
  assert.deepEqual(errors, []);
  await context.close();
});

test('<spline-lab> elements of demos of different groups on one page each load their group module', async () => {
  const context = await H.browser.newContext({ viewport: { width: 1000, height: 800 } });
  const a = 'bspline-basics', b = 'knot-modification', c = 'quasi-cubic-curves';
  assert.notEqual(groupOf(a), groupOf(b));
  await context.route(`${H.base}course-page.html`, (route) => route.fulfill({ contentType: 'text/html', body: `<!doctype html><meta charset="utf-8">
<script type="module" src="spline-lab.js"></script>
<spline-lab demo="${a}"></spline-lab><spline-lab demo="${b}"></spline-lab><spline-lab demo="${c}"></spline-lab><spline-lab demo="${a}"></spline-lab>` }));
  const p = await context.newPage();
  const requests = [];
  const errors = [];
  p.on('request', (r) => requests.push(new URL(r.url()).pathname));
  p.on('pageerror', (e) => errors.push(String(e)));
  await p.goto(`${H.base}course-page.html`);
  await p.waitForFunction(() => [...document.querySelectorAll('spline-lab')].every((e) => e.dataset.ready), null, { timeout: 30000 });
  assert.deepEqual(await p.$$eval('spline-lab', (els) => els.map((e) => e.dataset.ready)), ['true', 'true', 'true', 'true']);
  const wasm = requests.filter((u) => u.endsWith('.wasm')).sort();
  assert.deepEqual(wasm, [...new Set([a, b, c].map((d) => `/pkg/${groupOf(d)}/splinelab_bg.wasm`))].sort(), 'one module per group, each once, not the complete one');
  // each element drew
  for (const i of [0, 1, 2, 3]) {
    const inked = await p.evaluate((k) => {
      const cv = document.querySelectorAll('spline-lab')[k].shadowRoot.querySelector('canvas');
      return !!cv && cv.width > 0;
    }, i);
    assert.ok(inked, `element ${i} has a canvas`);
  }
  assert.deepEqual(errors, []);
  await context.close();
});
