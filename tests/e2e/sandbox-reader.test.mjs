// Issue 24, item 12: what a sandbox user reads and sees. The "API" link opens a reference that lists every
// function of the module (www/api.html, generated from docs/API.md and kept in step with it); the B2 example
// draws its auxiliary end points as such; basis functions (over u) are drawn in axes of their own, never in the
// x–y box of the curves — for the ready examples and for a demo's "Copy as code" snippet opened in the sandbox.
// Run: node --test tests/e2e/sandbox-reader.test.mjs   (needs www/pkg: scripts/build-wasm.sh)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { join } from 'node:path';
import { startHarness, ROOT, WWW } from './harness.mjs';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

async function run(t) {
  const before = await t.page.evaluate(() => Number(document.body.dataset.runs || 0));
  await t.page.click('#sb-run');
  await t.page.waitForFunction((n) => Number(document.body.dataset.runs || 0) > n && document.body.dataset.run !== 'running', before, { timeout: 20000 });
  await t.frames(3);
  return t.page.evaluate(() => document.body.dataset.run);
}
const viewOf = (t, which) => t.page.$eval(`canvas[data-plot="${which}"]`, (c) => c.splinePlot.getView());
const legendOf = (t, id) => t.page.$$eval(`#${id} li`, (ls) => ls.map((l) => l.textContent.trim()));

test('www/api.html is what docs/API.md gives now, and has a section for every export of the module', async () => {
  execFileSync(process.execPath, [join(ROOT, 'scripts/build-api-page.mjs'), '--check'], { stdio: 'pipe' });
  const mod = await import(join(WWW, 'pkg/splinelab.js'));
  const exported = Object.keys(mod).filter((k) => k !== 'default' && !k.startsWith('init') && !k.startsWith('__') && typeof mod[k] === 'function' && /^[a-z]/.test(k));
  const t = await H.open('sandbox.html', { ready: false });
  await t.page.waitForLoadState('load');
  await t.page.getByRole('link', { name: 'API reference' }).click();
  await t.page.waitForLoadState('load');
  assert.match(t.page.url(), /api\.html$/);
  const ids = await t.page.$$eval('h3[id]', (hs) => hs.map((x) => x.id));
  const missing = exported.filter((k) => !ids.includes(k));
  assert.deepEqual(missing, [], `functions of the module without a section on the API page: ${missing.join(', ')}`);
  // the reader's page: index notation typeset (no W_{i} or L^a in prose; code keeps its own text), papers by name
  const prose = await t.page.evaluate(() => {
    const c = document.querySelector('main').cloneNode(true);
    c.querySelectorAll('code, pre').forEach((e) => e.remove());
    return c.textContent;
  });
  const raw = prose.match(/.{0,30}(?:[_^]\{|\b[A-Za-z]_[A-Za-z0-9]|[A-Za-z)]\^[A-Za-z0-9(]).{0,30}/);
  assert.equal(raw, null, `raw index notation in the API page's prose: "${raw?.[0]}"`);
  assert.doesNotMatch(prose, /\bseed \d{3}\b/i, 'the papers are named, not numbered');
  const links = await t.page.$$eval('a[href^="#"]', (as) => as.map((a) => a.getAttribute('href').slice(1)).filter((h) => !document.getElementById(h)));
  assert.deepEqual(links, [], 'every in-page link has its target');
  t.assertClean();
  await t.close();
});

test('B2 example: the auxiliary end points are drawn and named apart from the data', async () => {
  const t = await H.open('sandbox.html', { ready: false });
  await t.page.waitForFunction(() => !document.getElementById('sb-run').disabled);
  await t.page.selectOption('#sb-examples', 'b2-splines');
  assert.equal(await run(t), 'ok');
  const legend = await legendOf(t, 'sb-plot-legend');
  assert.ok(legend.includes('data W₁ … Wₙ'), `legend: ${legend.join(' | ')}`);
  assert.ok(legend.some((l) => /^auxiliary W₋₁, W₀, Wₙ₊₁, Wₙ₊₂/.test(l)), `legend: ${legend.join(' | ')}`);
  assert.ok(!legend.some((l) => /[_^]/.test(l)), `no raw notation in the legend: ${legend.join(' | ')}`);
  t.assertClean();
  await t.close();
});

test('basis functions are drawn in their own axes: the B-spline example and a demo\'s "Copy as code" snippet', async () => {
  const t = await H.open('sandbox.html', { ready: false });
  await t.page.waitForFunction(() => !document.getElementById('sb-run').disabled);
  await t.page.selectOption('#sb-examples', 'bspline-basics');
  assert.equal(await run(t), 'ok');
  const curves = await viewOf(t, 'curves');
  const basis = await viewOf(t, 'basis');
  // the curves' plot holds the curve, its points and polygon (3 items), not the six basis rows; the basis plot
  // the six rows over u 0…3 with values 0…1
  const describedOf = (page) => page.waitForFunction(() => {
    const c = document.querySelector('canvas[data-plot="curves"]');
    // aria-describedby lists the plot's description, then (a plot with movable points) its gestures' help
    const d = document.getElementById(c.getAttribute('aria-describedby').split(/\s+/)[0]).textContent;
    return /drawn:/.test(d) && d;
  }).then((h) => h.jsonValue());
  // (the items arrive one after the other: under load the first read saw "1 drawn: C(u)"; wait up to 10 s for three)
  let described = await describedOf(t.page);
  for (let i = 0; i < 100 && !/^3 drawn: /.test(described); i++) { await t.page.waitForTimeout(100); described = await describedOf(t.page); }
  assert.match(described, /^3 drawn: /, `the curves' plot: ${described}`);
  assert.ok(curves.ymax > 2, `curves plot ${JSON.stringify(curves)}`);
  assert.ok(basis.xmin > -0.5 && basis.xmax < 3.5 && basis.ymin > -0.3 && basis.ymax < 1.4, `basis axes: u and N ranges only (${JSON.stringify(basis)})`);
  assert.ok(await t.page.isVisible('#sb-basis-panel'));
  await t.page.screenshot({ path: 'tests/e2e/out/sandbox-basis-axes.png', fullPage: true });
  await t.close();

  // B-spline basics → "Open in sandbox": the snippet returns { curve, basis, … }; both are drawn, apart
  const d = await H.open('#bspline-basics');
  const href = await d.page.getByRole('link', { name: 'Open in sandbox' }).getAttribute('href');
  await d.close();
  const s = await H.open(new URL(href, H.base).pathname.replace(/^\//, '') + new URL(href, H.base).hash, { ready: false });
  await s.page.waitForFunction(() => !document.getElementById('sb-run').disabled);
  assert.equal(await run(s), 'ok');
  const basisItems = await s.page.$eval('canvas[data-plot="basis"]', (c) => c.splinePlot.getView());
  const curveView = await viewOf(s, 'curves');
  assert.ok(await s.page.isVisible('#sb-basis-panel'), 'the snippet\'s basis is in the basis plot');
  assert.ok(basisItems.ymax < 1.5, `basis plot: values of the basis functions (${JSON.stringify(basisItems)})`);
  const snippetDescribed = await describedOf(s.page);
  assert.doesNotMatch(snippetDescribed, /basis/, `the curves' plot holds no basis row: ${snippetDescribed}`);
  assert.ok(curveView.ymax > 1.5, `curves plot: the curve's own range (${JSON.stringify(curveView)})`);
  s.assertClean();
  await s.close();
});
