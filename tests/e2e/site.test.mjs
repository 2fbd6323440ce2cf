// The deployment build dist/site/ (scripts/build-site.mjs, issue 13 start-up): built here (0.5 s), served as a host
// would serve it, and checked in Chromium: the gallery and every demo mount and draw (the canvas has ink), embed.html
// and the <spline-lab> element work, a link with state restores it, there is no CSP violation, no request outside
// the site and no missing file (the build copies no source module: a chunk that is not there is a 404 here), and
// a demo page makes at most MAX_REQUESTS requests before its first drawing (49 from www/ as it is).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { createHash } from 'node:crypto';
import { startHarness, ensureWasm, ROOT, demoIds } from './harness.mjs';
import { ink } from './png-ink.mjs';
import { groupOf } from '../../www/lib/wasm-groups.js';

const SITE = join(ROOT, 'dist/site');
/** Requests of a demo page up to its first drawing: the HTML, style.css, app.js, its 3 chunks, the demo's chunk (+1
 * for the 3D view's, +1 for the worker client's), the wasm glue and the wasm = 9–11. */
const MAX_REQUESTS = 12;

let H;
before(async () => {
  await ensureWasm();
  if (process.env.SITE_PREBUILT !== '1') execFileSync(process.execPath, [join(ROOT, 'scripts/build-site.mjs')], { cwd: ROOT, stdio: 'pipe' });
  H = await startHarness({ dir: SITE, fresh: true /* counts requests: nothing cached */ });
});
after(() => H?.close());

/** Opens a route of the built site in a fresh context, recording requests, failed responses and CSP violations. */
async function openSite(route, o = {}) {
  // (the service worker registers on load and caches the shell: its requests are not the page's start-up)
  const context = await H.browser.newContext({ viewport: o.viewport || { width: 1280, height: 900 }, serviceWorkers: o.serviceWorkers || 'block' });
  await context.addInitScript(() => {
    window.__csp = [];
    document.addEventListener('securitypolicyviolation', (e) => window.__csp.push(`${e.violatedDirective} ${e.blockedURI}`));
    // what the page had fetched when the demo mounted (the shell's background load of the other demos starts
    // 1.5 s after the first drawing, which a loaded machine can reach before the test reads the count)
    new MutationObserver((_, o) => {
      if (document.getElementById('demo-root')?.dataset.mounted !== 'true') return;
      o.disconnect();
      window.__atMount = [location.href, ...performance.getEntriesByType('resource').map((e) => e.name)];
    }).observe(document, { subtree: true, attributes: true, attributeFilter: ['data-mounted'] });
  });
  const requests = [], failed = [];
  context.on('request', (r) => requests.push(r.url()));
  context.on('response', (r) => { if (r.status() >= 400) failed.push(`${r.status()} ${r.url()}`); });
  context.on('requestfailed', (r) => failed.push(`failed ${r.url()} ${r.failure()?.errorText}`));
  const t = await H.open(route, { context, ready: o.ready });
  t.requests = requests;
  t.failed = failed;
  t.done = async () => {
    t.assertClean();
    assert.deepEqual(failed, [], 'missing files or failed requests');
    assert.deepEqual(await t.page.evaluate(() => window.__csp), [], 'CSP violations');
    for (const u of requests) assert.ok(u.startsWith(H.base) || u.startsWith('data:') || u.startsWith('blob:'), `a request outside the site: ${u}`);
    await context.close();
  };
  return t;
}

/** Ink of the demo's main view (its first visible canvas), from a screenshot (works for WebGL canvases too). */
async function canvasInk(t, scope = '#demo-root') {
  const c = await t.page.$(`${scope} canvas`);
  assert.ok(c, 'the demo has a canvas');
  await c.scrollIntoViewIfNeeded();
  await t.frames(3);
  return ink(await c.screenshot());
}

test('the build: one module per page entry, chunks, no source module; the pages hint only built files', () => {
  for (const f of ['app.js', 'spline-lab.js', 'lib/wasm-preload.js', 'index.html', 'embed.html', 'style.css', 'pkg/splinelab_bg.wasm', 'sw.js', 'build-manifest.json']) {
    assert.ok(existsSync(join(SITE, f)), `dist/site/${f}`);
  }
  for (const f of ['lib/host.js', 'lib/dom.js', 'demos/bspline-basics.js', 'lib/wasm-groups.js']) assert.ok(!existsSync(join(SITE, f)), `dist/site/${f} is a source module, bundled`);
  const manifest = JSON.parse(readFileSync(join(SITE, 'build-manifest.json'), 'utf8'));
  for (const page of ['index.html', 'embed.html']) {
    const html = readFileSync(join(SITE, page), 'utf8');
    const hints = [...html.matchAll(/<link rel="modulepreload" href="([^"]+)">/g)].map((m) => m[1]);
    assert.deepEqual(hints.sort(), manifest.pages[page].slice(1).sort(), `${page}: preloads the chunks app.js imports`);
    for (const h of hints) assert.ok(existsSync(join(SITE, h)), `${page}: ${h} exists`);
    // the start-up hint is inline (no round trip for lib/wasm-preload.js before the wasm), allowed by its hash alone
    const inline = /<script>([^<]+)<\/script>/.exec(html);
    assert.ok(inline, `${page}: the inline start-up script`);
    const hash = createHash('sha256').update(inline[1]).digest('base64');
    assert.match(html, new RegExp(`script-src 'self' 'wasm-unsafe-eval' 'sha256-${hash.replace(/[+/]/g, '\\$&')}';`), `${page}: the CSP allows that script by its hash`);
    assert.doesNotMatch(html, /unsafe-inline/, `${page}: no 'unsafe-inline'`);
  }
});

test('gallery of the built site: every card available, clean', async () => {
  const t = await openSite('', { serviceWorkers: 'allow' });
  const ids = await demoIds();
  await t.page.waitForFunction((n) => document.querySelectorAll('.cards .card').length === n, ids.length);
  assert.equal(await t.page.$$eval('.cards .card.unavailable', (c) => c.length), 0, 'every demo card is available');
  await t.done();
});

for (const id of await demoIds()) {
  test(`built site #${id}: mounts and draws; ≤ ${MAX_REQUESTS} requests; its group's wasm only`, async () => {
    const t = await openSite(`#${id}`);
    const atMount = (await t.page.evaluate(() => window.__atMount)).map((u) => new URL(u).pathname);
    assert.ok(atMount.length <= MAX_REQUESTS, `${atMount.length} requests before the demo mounted: ${atMount.join(' ')}`);
    const paths = t.requests.map((u) => new URL(u).pathname);
    assert.deepEqual(paths.filter((u) => u.endsWith('.wasm')), [`/pkg/${groupOf(id)}/splinelab_bg.wasm`], 'one wasm request, its group');
    // the wasm, its glue and the demo's chunk are requested by the page's inline script, not after a script file
    assert.ok(!atMount.includes('/lib/wasm-preload.js'), `no wasm-preload.js round trip before the first drawing: ${atMount.join(' ')}`);
    const { inked, colours, total } = await canvasInk(t);
    assert.ok(inked > total * 0.005 && colours >= 4, `${id}: the canvas is drawn (${inked} of ${total} pixels inked, ${colours} colours)`);
    assert.equal(await t.page.evaluate(() => document.querySelectorAll('.notice-error, .fatal').length), 0, 'no error shown');
    await t.done();
  });
}

test('built embed.html: a demo with options mounts and draws, no page chrome', async () => {
  const t = await openSite('embed.html#quasi-cubic-curves?controls=0');
  assert.equal(await t.page.evaluate(() => document.body.dataset.mode), 'embed');
  const { inked } = await canvasInk(t);
  assert.ok(inked > 100, 'drawn');
  const atMount = await t.page.evaluate(() => window.__atMount);
  assert.ok(atMount.length <= MAX_REQUESTS, `${atMount.length} requests before the demo mounted: ${atMount.join(' ')}`);
  await t.done();
});

test('built site: a link with state restores that state', async () => {
  const a = await openSite('#bspline-basics');
  const s0 = await a.state();
  const range = await a.page.$('#demo-root input[type="range"]');
  assert.ok(range, 'a slider');
  await a.page.$eval('#demo-root input[type="range"]', (el) => {
    el.value = String(Number(el.min) + (Number(el.max) - Number(el.min)) * 0.83);
    el.dispatchEvent(new Event('input', { bubbles: true }));
    el.dispatchEvent(new Event('change', { bubbles: true }));
  });
  const hash = await a.flushState();
  const s1 = await a.state();
  assert.notDeepEqual(s1, s0, 'the slider changed the state');
  assert.match(hash, /^#bspline-basics\/.+/);
  await a.done();
  const b = await openSite(hash);
  assert.deepEqual(await b.state(), s1, 'the link restored the state');
  await b.done();
});

test('built spline-lab.js: <spline-lab> elements on a course page mount and draw', async () => {
  const context = await H.browser.newContext({ viewport: { width: 1000, height: 900 } });
  await context.route(`${H.base}course-page.html`, (route) => route.fulfill({ contentType: 'text/html', body: `<!doctype html><meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; style-src 'self' 'unsafe-inline'; img-src 'self' data: blob:; connect-src 'self'">
<script type="module" src="spline-lab.js"></script>
<spline-lab demo="knot-modification"></spline-lab><spline-lab demo="b2-surfaces" height="500"></spline-lab>` }));
  const p = await context.newPage();
  const errors = [], failed = [];
  p.on('pageerror', (e) => errors.push(String(e)));
  p.on('console', (m) => { if (m.type() === 'error') errors.push(`${m.text()} @ ${m.location().url}`); });
  p.on('response', (r) => { if (r.status() >= 400) failed.push(`${r.status()} ${r.url()}`); });
  await p.goto(`${H.base}course-page.html`);
  await p.waitForFunction(() => [...document.querySelectorAll('spline-lab')].every((e) => e.dataset.ready), null, { timeout: 30000 });
  assert.deepEqual(await p.$$eval('spline-lab', (els) => els.map((e) => e.dataset.ready)), ['true', 'true']);
  for (const i of [0, 1]) {
    const el = (await p.$$('spline-lab'))[i];
    const canvas = await el.evaluateHandle((e) => e.shadowRoot.querySelector('canvas'));
    await canvas.asElement().scrollIntoViewIfNeeded();
    await p.evaluate(() => new Promise((ok) => requestAnimationFrame(() => requestAnimationFrame(ok))));
    const { inked } = ink(await canvas.asElement().screenshot());
    assert.ok(inked > 100, `element ${i} drew (${inked} pixels inked)`);
  }
  // The course page is the teacher's: the element registers no service worker there (SplineLab's worker would
  // control the course page's own URLs and precache the playground; esbuild's shared kit chunk once carried
  // offline.js's import-time registration onto course pages), and leaves the page's <html> alone.
  await p.waitForLoadState('load');
  await p.waitForTimeout(500);
  assert.deepEqual(await p.evaluate(async () => (await navigator.serviceWorker.getRegistrations()).map((r) => r.scope)), [],
    'no service worker registered by the course page');
  assert.equal(await p.evaluate(() => document.documentElement.dataset.storage ?? null), null, 'no storage flag on the course page');
  assert.deepEqual(errors, []);
  assert.deepEqual(failed, []);
  await context.close();
});

test('the other pages of the built site: sandbox (its wasm starts, an example runs), exercises, papers, guide load clean', async () => {
  for (const page of ['sandbox.html', 'exercises.html', 'papers.html', 'guide.html']) {
    const t = await openSite(page, { ready: page !== 'guide.html' });
    if (page === 'guide.html') await t.page.waitForLoadState('load');
    if (page === 'sandbox.html') {
      await t.page.evaluate(() => window.splinelabSandbox.run());
      await t.page.waitForFunction(() => window.splinelabSandbox.items?.length > 0 || document.querySelector('#sb-plot-panel:not([hidden]), #sb-view-panel:not([hidden])'), null, { timeout: 20000 });
    }
    await t.done();
  }
});
