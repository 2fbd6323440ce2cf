// Cross-origin embedding (issue 19, item 4): a course page served by ANOTHER server (another port = another
// origin) loads www/spline-lab.js from the playground server (scripts/static-server.mjs).
//   1. with the server's CORS headers the element starts and draws;
//   2. when the playground sends no CORS header the module is refused: the fallback content (a link to the demo)
//      stays readable, with a height;
//   3. when the module loads but the wasm cannot (blocked), the element shows a visible error and the link.
// Run: node --test tests/e2e/cross-origin.test.mjs   (needs www/pkg: scripts/build-wasm.sh)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createServer } from 'node:http';
import { join } from 'node:path';
import { chromium } from 'playwright-core';
import { serve } from '../../scripts/static-server.mjs';
import { WWW, CHROMIUM_ARGS, ensureWasm } from './harness.mjs';

const DEMO = 'bspline-basics';
let browser, withCors, noCors, course, courseBase;
const close = (s) => new Promise((ok) => { s.closeAllConnections?.(); s.close(() => ok()); });

/** The course page: loads the element from `lab` (another origin) with the fallback link the Share panel writes. */
const coursePage = (lab) => `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>Course page</title><link rel="icon" href="data:,">
<script type="module" src="${lab}spline-lab.js"></script></head>
<body><h1>Lecture 7: B-splines</h1>
<spline-lab id="fig" demo="${DEMO}"><a id="fallback" href="${lab}index.html#${DEMO}">Interactive figure: B-spline basics (SplineLab) ↗</a></spline-lab>
<p>Text after the figure.</p></body></html>`;

before(async () => {
  await ensureWasm();
  withCors = await serve(WWW, 0, '127.0.0.1');
  noCors = await serve(WWW, 0, '127.0.0.1', { cors: false });
  // the course site: any path → the course page; ?lab=<port> picks the playground server
  course = createServer((req, res) => {
    const port = new URL(req.url, 'http://x').searchParams.get('lab');
    res.writeHead(200, { 'content-type': 'text/html; charset=utf-8' }).end(coursePage(`http://127.0.0.1:${port}/`));
  });
  await new Promise((ok) => course.listen(0, '127.0.0.1', ok));
  courseBase = `http://127.0.0.1:${course.address().port}/`;
  browser = await chromium.launch({ executablePath: process.env.CHROMIUM || '/usr/bin/chromium', headless: true, args: CHROMIUM_ARGS });
});

after(async () => {
  await browser?.close();
  for (const s of [withCors, noCors, course]) if (s) await close(s);
});

async function openCourse(labServer, { blockWasm = false } = {}) {
  const page = await browser.newPage({ viewport: { width: 1100, height: 900 } });
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(`pageerror: ${e.message}`));
  await page.route('**/*', (route) => {
    const u = new URL(route.request().url());
    if (u.protocol === 'data:' || u.protocol === 'blob:') return route.continue();
    if (u.hostname !== '127.0.0.1') return route.abort();
    if (blockWasm && u.pathname.endsWith('.wasm')) return route.abort('failed');
    return route.continue();
  });
  await page.goto(`${courseBase}lecture7.html?lab=${labServer.address().port}`);
  return { page, errors };
}

test('the playground server sends CORS, CORP and the right MIME types', async () => {
  const base = `http://127.0.0.1:${withCors.address().port}/`;
  for (const [path, type] of [['spline-lab.js', 'text/javascript'], ['pkg/splinelab_bg.wasm', 'application/wasm'], ['style.css', 'text/css'], ['app.js', 'text/javascript']]) {
    const r = await fetch(base + path, { headers: { origin: 'http://example.org' } });
    assert.equal(r.status, 200, path);
    assert.equal(r.headers.get('access-control-allow-origin'), '*', `${path}: ACAO`);
    assert.equal(r.headers.get('cross-origin-resource-policy'), 'cross-origin', `${path}: CORP`);
    assert.ok(r.headers.get('content-type').startsWith(type), `${path}: ${r.headers.get('content-type')}`);
  }
  const r404 = await fetch(`${base}nope.js`);
  assert.equal(r404.status, 404);
  assert.equal(r404.headers.get('access-control-allow-origin'), '*', '404s carry CORS too (so the element can report them)');
  const plain = await fetch(`http://127.0.0.1:${noCors.address().port}/spline-lab.js`);
  assert.equal(plain.headers.get('access-control-allow-origin'), null, 'the cors:false variant sends none');
});

test('a course page on another origin renders a <spline-lab> (canvas drawn)', async () => {
  const { page, errors } = await openCourse(withCors);
  assert.notEqual(new URL(page.url()).origin, `http://127.0.0.1:${withCors.address().port}`, 'two origins');
  await page.waitForFunction(() => document.getElementById('fig').dataset.ready, null, { timeout: 30000 });
  assert.equal(await page.locator('#fig').getAttribute('data-ready'), 'true');
  await page.waitForTimeout(300);
  const ink = await page.locator('#fig canvas').first().evaluate((c) => {
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] < 235 || d[i + 1] < 235 || d[i + 2] < 235) n++;
    return { n, total: d.length / 4 };
  });
  assert.ok(ink.n > ink.total * 0.02, `the plot is drawn (${ink.n} of ${ink.total} pixels inked)`);
  // once started, the fallback link is no longer shown (the demo replaced it)
  assert.equal(await page.locator('#fallback').isVisible(), false);
  assert.deepEqual(errors, []);
  await page.close();
});

test('no CORS on the playground: the fallback link stays readable and the element has a height', async () => {
  const { page, errors } = await openCourse(noCors);
  await page.waitForLoadState('load');
  await page.waitForTimeout(500);
  assert.equal(await page.evaluate(() => !!customElements.get('spline-lab')), false, 'the module was refused (CORS)');
  assert.ok(errors.some((e) => /CORS|Access-Control-Allow-Origin/i.test(e)), `a CORS refusal: ${errors.join(' | ')}`);
  const link = page.locator('#fallback');
  assert.equal(await link.isVisible(), true, 'fallback link visible');
  assert.match(await link.textContent(), /B-spline basics/);
  const box = await page.locator('#fig').boundingBox();
  assert.ok(box && box.height > 10, `element height ${box?.height}`);
  await page.close();
});

test('module loads but the wasm does not: a visible error message and the fallback link', async () => {
  const { page } = await openCourse(withCors, { blockWasm: true });
  await page.waitForFunction(() => document.getElementById('fig').dataset.ready, null, { timeout: 30000 });
  assert.equal(await page.locator('#fig').getAttribute('data-ready'), 'error');
  const alert = page.locator('#fig [role=alert]');
  assert.equal(await alert.isVisible(), true, 'error message visible');
  assert.match(await alert.textContent(), /could not start/);
  const ab = await alert.boundingBox();
  assert.ok(ab.height >= 20 && ab.width >= 200, `readable message box ${JSON.stringify(ab)}`);
  assert.equal(await page.locator('#fallback').isVisible(), true, 'the page\'s fallback link is shown again');
  const box = await page.locator('#fig').boundingBox();
  assert.ok(box.height >= 100, `min-height (${box.height})`);
  await page.close();
});
