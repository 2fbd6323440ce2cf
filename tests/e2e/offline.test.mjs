// Offline: (1) after one visit the hosted playground works offline (service worker www/sw.js, registered by
// www/lib/offline.js): the test visits the gallery, goes offline with playwright's context.setOffline(true) and
// reloads a demo link; a new build is picked up on the next online visit. (2) dist/splinelab.html (built by
// scripts/build-offline.sh) opens from file:// in Chromium with every demo and a link state; Firefox and WebKit
// open it in tests/cross/.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtemp, cp, readFile, writeFile, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { execFileSync } from 'node:child_process';
import { chromium } from 'playwright-core';
import { ensureWasm, startServer, demoIds, CHROMIUM_ARGS, WWW, ROOT } from './harness.mjs';

let browser, copy, srv;
before(async () => {
  await ensureWasm();
  // a private copy of www/ so the test can publish a "new build"
  copy = await mkdtemp(join(tmpdir(), 'splinelab-offline-'));
  await cp(WWW, copy, { recursive: true, dereference: true });
  srv = await startServer(copy);
  browser = await chromium.launch({ executablePath: process.env.CHROMIUM || '/usr/bin/chromium', headless: true, args: CHROMIUM_ARGS });
});
after(async () => {
  await browser?.close();
  await srv?.close();
  if (copy) await rm(copy, { recursive: true, force: true });
});

const ready = (page) => page.waitForFunction(() => document.documentElement.dataset.ready === 'true'
  && (document.body.dataset.view !== 'demo' || !!document.querySelector('#demo-root[data-mounted="true"]')), null, { timeout: 20000 });

test('after one visit the playground works offline, and a new build is picked up on the next online visit', async () => {
  const context = await browser.newContext({ serviceWorkers: 'allow' });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(srv.base + 'index.html');
  await ready(page);
  const cached = await page.evaluate(() => window.splinelabOffline.cached);
  assert.ok(cached && cached.count > 20 && cached.count === cached.total, `the worker cached what the page loaded: ${JSON.stringify(cached)}`);
  assert.ok(await page.evaluate(() => !!navigator.serviceWorker.controller), 'the worker controls the page');

  // a link with state, made online
  await page.goto(srv.base + 'index.html#bspline-basics');
  // (a same-document hash change: the shell routes after goto returns, and loads the demo's wasm module first)
  await page.waitForFunction(() => window.splinelab.current()?.id === 'bspline-basics', null, { timeout: 20000 });
  await ready(page);
  await page.evaluate(() => document.querySelector('canvas').focus());
  await page.keyboard.press('ArrowRight'); await page.keyboard.press('ArrowUp');
  await page.evaluate(() => window.splinelab.flush());
  const link = await page.evaluate(() => location.href);
  const state = await page.evaluate(() => JSON.stringify(window.splinelab.current().state));
  assert.match(link, /#bspline-basics\/v/);

  // offline: every demo and the link state still load (the server is still up: only the browser is offline)
  await context.setOffline(true);
  assert.equal(await page.evaluate(() => fetch('never-cached.txt', { cache: 'no-store' }).then(() => 'online', () => 'offline')), 'offline', 'the network is off');
  await page.goto(link);
  await ready(page);
  assert.equal(await page.evaluate(() => JSON.stringify(window.splinelab.current().state)), state, 'offline: the link restores its state');
  for (const id of await demoIds()) {
    await page.goto(srv.base + `embed.html#${id}`);
    await ready(page);
    // from one embed.html#… to the next is a same-document hash change: the shell routes (and imports the demo
    // module, from the worker's cache) after goto returns, so wait for the mount, bounded
    await page.waitForFunction((want) => window.splinelab.current()?.id === want, id, { timeout: 15000 }).catch(() => {});
    assert.equal(await page.evaluate(() => window.splinelab.current()?.id), id, `offline: ${id} mounts`);
    assert.equal(await page.evaluate(() => document.querySelectorAll('.notice-error, .fatal').length), 0, `offline: ${id} has no error`);
  }

  // a new build is published; online again, the next visit shows it, and offline afterwards still shows it
  await context.setOffline(false);
  const idx = join(copy, 'index.html');
  await writeFile(idx, (await readFile(idx, 'utf8')).replace('<title>', '<meta name="splinelab-build" content="2">\n  <title>'));
  await page.goto(srv.base + 'index.html');
  await ready(page);
  assert.equal(await page.evaluate(() => document.querySelector('meta[name="splinelab-build"]')?.content), '2', 'online: the new build');
  await context.setOffline(true);
  await page.reload();
  await ready(page);
  assert.equal(await page.evaluate(() => document.querySelector('meta[name="splinelab-build"]')?.content), '2', 'offline after the update: the new build');
  assert.deepEqual(errors, []);
  await context.close();
});

test('dist/splinelab.html: one file, opens from file:// with every demo and a link state (Chromium)', async () => {
  // built from the current www/ (takes about a second; scripts/test.sh builds it again for tests/cross/)
  const dist = join(ROOT, 'dist/splinelab.html');
  execFileSync('node', [join(ROOT, 'scripts/build-offline.mjs')], { cwd: ROOT, stdio: 'inherit' });
  const html = await readFile(dist, 'utf8');
  // self-contained: no external script, stylesheet, module import or fetch target
  // (the code is one inline <script type="module">, bundled by esbuild: what it says is not markup)
  assert.doesNotMatch(html.replace(/<script(?: type="module")?>[\s\S]*?<\/script>/g, ''), /<script[^>]+src=|<link[^>]+rel="stylesheet"/);
  assert.equal((html.match(/<script type="module">/g) || []).length, 1, 'one inline module script');
  const context = await browser.newContext();
  const page = await context.newPage();
  const errors = [];
  const requests = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('request', (r) => { if (!r.url().startsWith('data:') && !r.url().startsWith('blob:')) requests.push(r.url()); });
  const file = pathToFileURL(dist).href;
  const t0 = Date.now();
  await page.goto(file);
  await ready(page);
  const cold = Date.now() - t0;
  assert.equal(await page.evaluate(() => document.querySelectorAll('a.card').length), (await demoIds()).length, 'gallery of every demo');
  for (const id of await demoIds()) {
    await page.evaluate((h) => { location.hash = h; }, id);
    await page.waitForFunction((d) => window.splinelab.current()?.id === d && document.querySelector('#demo-root[data-mounted="true"]'), id, { timeout: 20000 });
    assert.equal(await page.evaluate(() => document.querySelectorAll('.notice-error, .fatal').length), 0, `${id}: no error`);
    const colours = await page.evaluate(() => {
      const c = [...document.querySelectorAll('canvas')].find((x) => x.getClientRects().length);
      const s = document.createElement('canvas'); s.width = s.height = 48;
      const g = s.getContext('2d'); g.drawImage(c, 0, 0, 48, 48);
      const d = g.getImageData(0, 0, 48, 48).data; const set = new Set();
      for (let i = 0; i < d.length; i += 4) set.add((d[i] << 16) | (d[i + 1] << 8) | d[i + 2]);
      return set.size;
    });
    assert.ok(colours >= 4, `${id}: draws (${colours} colours)`);
  }
  // a link state from the hosted playground opens in the file
  const hp = await context.newPage();
  await hp.goto(srv.base + 'index.html#interp-approx');
  await ready(hp);
  await hp.evaluate(() => document.querySelector('canvas').focus());
  await hp.keyboard.press('ArrowRight'); await hp.keyboard.press('ArrowRight');
  await hp.evaluate(() => window.splinelab.flush());
  const [hash, state] = await hp.evaluate(() => [location.hash, JSON.stringify(window.splinelab.current().state)]);
  await page.goto(file + '?again' + hash);
  await ready(page);
  assert.equal(await page.evaluate(() => JSON.stringify(window.splinelab.current().state)), state, 'the file restores a hosted link state');
  assert.deepEqual(errors, [], 'no error');
  assert.deepEqual(requests.filter((u) => !u.startsWith('file:')), [], 'no request leaves the file');
  assert.equal(requests.filter((u) => u.startsWith('file:') && !u.startsWith(file.split('#')[0])).length, 0, 'no other file is read');
  if (process.env.CROSS_TIMING) console.log(`# chromium file:// cold start ${cold} ms`);
  await context.close();
});
