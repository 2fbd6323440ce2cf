// End-to-end tests of embedding: the <spline-lab> custom element (www/spline-lab.js) and the iframe
// (embed.html), on one test page; the course-author guide (www/guide.html) and its live examples.
// Headless Chromium with --disable-gpu; every request must stay on 127.0.0.1.
// Run: node --test tests/e2e/embed.test.mjs   (needs www/pkg: scripts/build-wasm.sh)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, mkdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { serve } from '../../scripts/static-server.mjs';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const WWW = join(ROOT, 'www');
const SHOTS = join(ROOT, 'tests', 'e2e', 'screenshots');
mkdirSync(SHOTS, { recursive: true });
const DEMO = 'bspline-basics';
// The element and the iframe need the shell (www/app.js, www/lib/state.js) and the first demo.
const SHELL = ['app.js', 'embed.html', 'lib/state.js', `demos/${DEMO}.js`].every((f) => existsSync(join(WWW, f)));
const opts = SHELL ? {} : { skip: 'the shell (www/app.js, lib/state.js, demos/bspline-basics.js) is not on this branch yet' };
const CSP = "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; style-src 'self'; img-src 'self' data: blob:; connect-src 'self'; frame-src 'self'; object-src 'none'; base-uri 'none'";

let server, browser, base, missingDemos;

before(async () => {
  if (!SHELL) return;
  const { DEMO_IDS } = await import(join(WWW, 'demos', 'index.js'));
  missingDemos = DEMO_IDS.filter((id) => !existsSync(join(WWW, 'demos', `${id}.js`)));
  server = await serve(WWW, 0);
  base = `http://127.0.0.1:${server.address().port}/`;
  browser = await chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--disable-quic'],
  });
});

after(async () => {
  await browser?.close();
  server?.close();
});

/** The embed test page: two independent elements and one iframe (served on the same origin). */
const TEST_PAGE = `<!doctype html>
<html lang="en"><head><meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="${CSP}">
<link rel="icon" href="data:,">
<title>Embed test</title>
<script type="module" src="spline-lab.js"></script>
</head><body>
<h1>A course page</h1>
<p>Some text before the figures.</p>
<spline-lab id="a" demo="${DEMO}"></spline-lab>
<spline-lab id="b" demo="${DEMO}" controls="false" explain="false" locked="true" height="480"></spline-lab>
<iframe id="f" src="embed.html#${DEMO}?explain=0" title="embedded demo" width="900" height="640"></iframe>
<p>Some text after the figures.</p>
</body></html>`;

/**
 * Opens a page and records problems: console errors, page errors, failed responses (404s of demo modules that
 * are not written yet excepted), requests that leave 127.0.0.1 (blocked).
 */
async function open(path, { testPage = false, html = null } = {}) {
  const page = await browser.newPage({ viewport: { width: 1100, height: 900 } });
  const problems = [];
  const expected404 = (url) => missingDemos.some((id) => url.endsWith(`/demos/${id}.js`));
  page.on('console', (m) => {
    if (m.type() !== 'error') return;
    if (/^Failed to load resource/.test(m.text())) return; // judged by the response handler below
    problems.push(`console: ${m.text()}`);
  });
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  page.on('response', (r) => { if (r.status() >= 400 && !expected404(r.url())) problems.push(`HTTP ${r.status()}: ${r.url()}`); });
  await page.route('**/*', (route) => {
    const u = new URL(route.request().url());
    if (u.protocol === 'data:' || u.protocol === 'blob:' || u.hostname === '127.0.0.1') return route.continue();
    problems.push(`external request: ${u.href}`);
    return route.abort();
  });
  if (testPage || html) {
    await page.route(`${base}${path}`, (route) => route.fulfill({ status: 200, contentType: 'text/html; charset=utf-8', body: html || TEST_PAGE }));
  }
  await page.goto(base + path);
  return { page, problems };
}

const allReady = (page) => page.waitForFunction(
  () => [...document.querySelectorAll('spline-lab')].every((e) => e.dataset.ready), null, { timeout: 30000 });

/** Counts the inked pixels of the first canvas inside element `sel` (shadow roots are pierced). */
function inkOf(frameOrPage, sel) {
  return frameOrPage.locator(`${sel} canvas`).first().evaluate((c) => {
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let ink = 0, colour = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (d[i] < 235 || d[i + 1] < 235 || d[i + 2] < 235) ink++;
      if (Math.max(d[i], d[i + 1], d[i + 2]) - Math.min(d[i], d[i + 1], d[i + 2]) > 80) colour++;
    }
    return { ink, colour, total: d.length / 4 };
  });
}

test('two <spline-lab> elements and an iframe on one page: each draws, no error, nothing leaves 127.0.0.1', opts, async () => {
  const { page, problems } = await open('embed-test.html', { testPage: true });
  await allReady(page);
  assert.equal(await page.locator('#a').getAttribute('data-ready'), 'true');
  assert.equal(await page.locator('#b').getAttribute('data-ready'), 'true');
  const frame = page.frameLocator('#f');
  await frame.locator('[data-mounted="true"]').waitFor({ timeout: 30000 });
  await page.waitForTimeout(300);
  for (const [where, sel] of [[page, '#a'], [page, '#b'], [frame, 'body']]) {
    const s = await inkOf(where, sel);
    assert.ok(s.ink > s.total * 0.02 && s.colour > 200, `${sel} draws (${s.ink} inked, ${s.colour} coloured of ${s.total})`);
  }
  // options: #b has no controls and no explanation, #a has both
  assert.equal(await page.locator('#a .demo-controls').isVisible(), true);
  assert.equal(await page.locator('#a .demo-explain').isVisible(), true);
  assert.equal(await page.locator('#b .demo-controls').isVisible(), false);
  assert.equal(await page.locator('#b .demo-explain').isVisible(), false);
  // the page's own styles are untouched and the page's URL is not changed by the elements
  assert.equal(await page.evaluate(() => location.hash), '');
  assert.equal(await page.evaluate(() => getComputedStyle(document.body).backgroundColor), 'rgba(0, 0, 0, 0)', 'SplineLab CSS did not leak into the page');
  assert.equal(await page.evaluate(() => document.querySelectorAll('link[rel=stylesheet], style').length), 0);
  await page.screenshot({ path: join(SHOTS, 'embed-page.png'), fullPage: true });
  assert.deepEqual(problems, []);
  await page.close();
});

test('elements are independent, and a state round-trips through the state attribute', opts, async () => {
  const { page, problems } = await open('embed-test.html', { testPage: true });
  await allReady(page);
  const a0 = await page.evaluate(() => document.getElementById('a').getState());
  const b0 = await page.evaluate(() => document.getElementById('b').getState());
  assert.deepEqual(a0, b0, 'both start from the defaults');

  // drag the first control point of #a with the mouse
  const canvas = page.locator('#a canvas').first();
  const box = await canvas.boundingBox();
  const [px, py] = await canvas.evaluate((c) => c.splinePlot.toScreen(...c.splinePlot.handles()[0].point));
  const changed = page.evaluate(() => new Promise((ok) => document.getElementById('a').addEventListener('change', (e) => ok(e.detail.state), { once: true })));
  await page.mouse.move(box.x + px, box.y + py);
  await page.mouse.down();
  await page.mouse.move(box.x + px + 60, box.y + py - 40, { steps: 6 });
  await page.mouse.up();
  const detail = await changed;
  const a1 = await page.evaluate(() => document.getElementById('a').getState());
  assert.notDeepEqual(a1.points[0], a0.points[0], 'the point of #a moved');
  assert.deepEqual(detail, a1, 'change event carries the state');
  assert.deepEqual(await page.evaluate(() => document.getElementById('b').getState()), b0, '#b did not change');

  // #b is locked: dragging does not move its point
  const cb = page.locator('#b canvas').first();
  const bb = await cb.boundingBox();
  const [qx, qy] = await cb.evaluate((c) => c.splinePlot.toScreen(...c.splinePlot.handles()[1].point));
  await page.mouse.move(bb.x + qx, bb.y + qy);
  await page.mouse.down();
  await page.mouse.move(bb.x + qx + 50, bb.y + qy + 30, { steps: 5 });
  await page.mouse.up();
  assert.deepEqual(await page.evaluate(() => document.getElementById('b').getState()), b0, 'locked #b did not change');

  // changing an option re-mounts #a but keeps what the reader did
  const kept = await page.evaluate(async () => {
    const a = document.getElementById('a');
    await new Promise((ok) => { a.addEventListener('ready', ok, { once: true }); a.setAttribute('controls', 'false'); });
    return a.getState();
  });
  assert.deepEqual(kept, a1, 'state kept across an option change');
  assert.equal(await page.locator('#a .demo-controls').isVisible(), false, 'controls now hidden');

  // round trip: a new element with #a's payload has #a's state
  const payload = await page.evaluate(() => document.getElementById('a').getPayload());
  assert.match(payload, /^v[01]\./);
  const c = await page.evaluate(async (p) => {
    const el = document.createElement('spline-lab');
    el.id = 'c';
    el.setAttribute('demo', 'bspline-basics');
    el.setAttribute('state', p);
    await new Promise((ok) => { el.addEventListener('ready', ok, { once: true }); document.body.appendChild(el); });
    return el.getState();
  }, payload);
  assert.deepEqual(c, a1, 'same state in the new element');
  // …and the element's link opens the full page with the same state
  const link = await page.evaluate(() => document.getElementById('a').getLink());
  assert.ok(link.startsWith(`${base}index.html#bspline-basics/v`), link);
  assert.deepEqual(problems, []);
  await page.close();
});

test('bad input: a damaged state shows a notice and the defaults; an unknown demo shows a message', opts, async () => {
  const { page, problems } = await open('embed-test.html', { testPage: true });
  await allReady(page);
  const defaults = await page.evaluate(() => document.getElementById('b').getState());
  const r = await page.evaluate(async () => {
    const make = (attrs) => new Promise((ok) => {
      const el = document.createElement('spline-lab');
      for (const [k, v] of Object.entries(attrs)) el.setAttribute(k, v);
      el.addEventListener('ready', () => ok(el), { once: true });
      document.body.appendChild(el);
    });
    const bad = await make({ demo: 'bspline-basics', state: 'v1.<img src=x onerror=alert(1)>' });
    const bad2 = await make({ demo: 'bspline-basics', state: 'v0.' + btoa(JSON.stringify({ points: 'nope' })).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '') });
    const none = await make({ demo: 'no-such-demo' });
    const text = (el) => el.shadowRoot.textContent;
    return {
      bad: { ready: bad.dataset.ready, state: bad.getState(), notice: bad.shadowRoot.querySelector('[role=alert]')?.textContent || '', imgs: bad.shadowRoot.querySelectorAll('img').length },
      bad2: { ready: bad2.dataset.ready, state: bad2.getState(), notice: bad2.shadowRoot.querySelector('[role=alert]')?.textContent || '' },
      none: { ready: none.dataset.ready, text: text(none) },
    };
  });
  assert.equal(r.bad.ready, 'true');
  assert.deepEqual(r.bad.state, defaults);
  assert.match(r.bad.notice, /could not be read/);
  assert.equal(r.bad.imgs, 0, 'nothing from the attribute became markup');
  assert.deepEqual(r.bad2.state, defaults);
  assert.match(r.bad2.notice, /points/);
  assert.equal(r.none.ready, 'error');
  assert.match(r.none.text, /no demo called "no-such-demo"/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('the course-author guide loads and its live examples draw', opts, async () => {
  const { page, problems } = await open('guide.html');
  await allReady(page);
  assert.equal(await page.locator('spline-lab').count(), 2);
  for (const sel of ['#example-full', '#example-bare']) {
    assert.equal(await page.locator(sel).getAttribute('data-ready'), 'true');
    const s = await inkOf(page, sel);
    assert.ok(s.ink > s.total * 0.02, `${sel} draws`);
  }
  const frame = page.frameLocator('#example-iframe');
  await frame.locator('[data-mounted="true"]').waitFor({ timeout: 30000 });
  for (const h of ['iframe', 'element', 'Host the folder', 'Offline', 'link']) {
    assert.match(await page.locator('main').textContent(), new RegExp(h, 'i'));
  }
  assert.deepEqual(problems, []);
  await page.close();
});

test('axe-core: no serious or critical violation on a page with elements and an iframe', opts, async () => {
  const context = await browser.newContext({ bypassCSP: true }); // to inject axe
  const page = await context.newPage();
  await page.route(`${base}embed-test.html`, (route) => route.fulfill({ status: 200, contentType: 'text/html; charset=utf-8', body: TEST_PAGE }));
  await page.goto(`${base}embed-test.html`);
  await allReady(page);
  await page.addScriptTag({ path: join(ROOT, 'node_modules', 'axe-core', 'axe.min.js') });
  const violations = await page.evaluate(async () => (await window.axe.run(document, { resultTypes: ['violations'] })).violations
    .filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`));
  assert.deepEqual(violations, []);
  await context.close();
});

test('every available demo embeds via the element and via an iframe on one page', opts, async () => {
  const { DEMO_IDS } = await import(join(WWW, 'demos', 'index.js'));
  const ids = DEMO_IDS.filter((id) => existsSync(join(WWW, 'demos', `${id}.js`)));
  const body = ids.map((id) => `<h2>${id}</h2>\n<spline-lab data-test="${id}" demo="${id}" explain="false"></spline-lab>\n`
    + `<iframe data-test="${id}" src="embed.html#${id}?explain=0" title="${id}" width="1000" height="700"></iframe>`).join('\n');
  const html = TEST_PAGE.replace(/<body>[\s\S]*<\/body>/, `<body><h1>Every demo</h1>\n${body}\n</body>`);
  const { page, problems } = await open('every-demo.html', { html });
  await allReady(page);
  for (const id of ids) {
    assert.equal(await page.locator(`spline-lab[data-test="${id}"]`).getAttribute('data-ready'), 'true', `${id}: element mounted`);
    const frame = page.frameLocator(`iframe[data-test="${id}"]`);
    await frame.locator('[data-mounted="true"]').waitFor({ timeout: 30000 });
    // something is drawn: a 2D canvas with ink, or a WebGL canvas
    for (const [where, sel] of [[page, `spline-lab[data-test="${id}"]`], [frame, 'body']]) {
      const drawn = await where.locator(`${sel} canvas`).first().evaluate((c) => {
        const g = c.getContext('2d');
        if (!g) return true; // a WebGL canvas (checked by the demo's own tests)
        const d = g.getImageData(0, 0, c.width, c.height).data;
        let ink = 0;
        for (let i = 0; i < d.length; i += 4) if (d[i] < 235 || d[i + 1] < 235 || d[i + 2] < 235) ink++;
        return ink > 100;
      });
      assert.ok(drawn, `${id}: ${where === page ? 'element' : 'iframe'} draws`);
    }
  }
  assert.deepEqual(problems, []);
  await page.close();
});

test('the element: an Export row in its shadow root (JSON carries its state); focus works inside the shadow root', opts, async () => {
  const { page, problems } = await open('embed-test.html', { testPage: true });
  await allReady(page);
  await page.locator('#a .export-bar button[data-format="json"]').waitFor({ timeout: 10000 });
  assert.equal(await page.locator('#b .export-bar').isVisible(), false, 'controls="false" hides the Export row');
  const [dl] = await Promise.all([page.waitForEvent('download'), page.locator('#a .export-bar button[data-format="json"]').click()]);
  const { readFile } = await import('node:fs/promises');
  const j = JSON.parse(await readFile(await dl.path(), 'utf8'));
  assert.equal(j.demo, DEMO);
  assert.deepEqual(j.state, await page.evaluate(() => document.getElementById('a').getState()));
  assert.ok(Array.isArray(j.computed.samples.points) && j.computed.samples.points.length > 100, 'computed samples');
  // plot2d inside a shadow root knows it has focus (getRootNode().activeElement): a plain wheel zooms it
  const canvas = page.locator('#a canvas').first();
  await canvas.focus();
  assert.equal(await canvas.evaluate((c) => c.getRootNode().activeElement === c), true);
  const v0 = await canvas.evaluate((c) => c.splinePlot.getView());
  const box = await canvas.boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.wheel(0, -300);
  await page.waitForTimeout(150);
  const v1 = await canvas.evaluate((c) => c.splinePlot.getView());
  assert.ok(v1.xmax - v1.xmin < v0.xmax - v0.xmin, `the wheel zoomed the focused plot (${JSON.stringify(v0)} → ${JSON.stringify(v1)})`);
  assert.deepEqual(problems, []);
  await page.close();
});
