// Exercises into the gradebook (issue 27): the built site (dist/site, with the one-file build beside it) makes a
// SCORM 1.2 package of an exercise in the browser; a test LMS page (tests/fixtures/scorm12-lms.js, the LMS side of
// the SCORM 1.2 RTE written from the specification) launches the unzipped package in an iframe of its own origin,
// as an LMS does; a student checks, solves with the page's controls, leaves, comes back.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { execFileSync } from 'node:child_process';
import { writeFileSync, mkdtempSync, rmSync, mkdirSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { spawnSync } from 'node:child_process';
import { startHarness, startServer, ROOT } from './harness.mjs';
import { unzip } from '../fixtures/unzip.mjs';

const SITE = join(ROOT, 'dist/site');
let H;
before(async () => {
  // the one-file build, then the site that carries it (CI builds both before the end-to-end step)
  if (!existsSync(join(ROOT, 'dist/splinelab.html'))) execFileSync('node', [join(ROOT, 'scripts/build-offline.mjs')], { cwd: ROOT, stdio: 'inherit' });
  if (!existsSync(join(SITE, 'splinelab.html'))) execFileSync('node', [join(ROOT, 'scripts/build-site.mjs')], { cwd: ROOT, stdio: 'inherit' });
  H = await startHarness({ dir: SITE });
});
after(() => H?.close());

/**
 * The SCORM 1.2 content-packaging rules a package must keep (IMS CP 1.1.2 + ADL SCORM 1.2 CAM §2), read with the
 * browser's XML parser: root <manifest> in the IMS CP namespace with an identifier; metadata schema "ADL SCORM" and
 * schemaversion "1.2"; a default <organization> that exists, with items whose identifierref names a <resource>;
 * each such resource a SCO with an href that is a file of the package. Returns the problems found.
 */
async function manifestProblems(page, xml, names) {
  return page.evaluate(([text, files]) => {
    const CP = 'http://www.imsproject.org/xsd/imscp_rootv1p1p2', ADL = 'http://www.adlnet.org/xsd/adlcp_rootv1p2';
    const doc = new DOMParser().parseFromString(text, 'application/xml');
    const bad = [];
    if (doc.querySelector('parsererror')) return ['not well-formed XML'];
    const root = doc.documentElement;
    if (root.localName !== 'manifest' || root.namespaceURI !== CP) bad.push(`root element ${root.localName} in ${root.namespaceURI}`);
    if (!root.getAttribute('identifier')) bad.push('manifest without identifier');
    const kid = (el, name) => [...el.children].filter((c) => c.localName === name && c.namespaceURI === CP);
    const meta = kid(root, 'metadata')[0];
    if (kid(meta || root, 'schema')[0]?.textContent !== 'ADL SCORM') bad.push('schema is not "ADL SCORM"');
    if (kid(meta || root, 'schemaversion')[0]?.textContent !== '1.2') bad.push('schemaversion is not 1.2');
    const orgs = kid(root, 'organizations')[0];
    const def = orgs?.getAttribute('default');
    const org = orgs && kid(orgs, 'organization').find((o) => o.getAttribute('identifier') === def);
    if (!org) bad.push(`no organization "${def}" (the default)`);
    const resources = kid(kid(root, 'resources')[0] || root, 'resource');
    const items = org ? [...org.getElementsByTagNameNS(CP, 'item')] : [];
    if (!items.length) bad.push('the organization has no item');
    for (const it of items) {
      const ref = it.getAttribute('identifierref');
      if (!ref) continue;
      const r = resources.find((x) => x.getAttribute('identifier') === ref);
      if (!r) { bad.push(`item ${it.getAttribute('identifier')} names no resource (${ref})`); continue; }
      if (r.getAttributeNS(ADL, 'scormtype') !== 'sco') bad.push(`resource ${ref} is not a sco`);
      const href = r.getAttribute('href');
      if (!href || !files.includes(href)) bad.push(`resource ${ref}: launch file ${href} is not in the package`);
      if (!kid(r, 'file').some((f) => f.getAttribute('href') === href)) bad.push(`resource ${ref} does not list its launch file`);
    }
    return bad;
  }, [xml, names]);
}

/** `unzip -t` on the bytes (where unzip is installed): the standard tool reads the archive. */
function unzipTest(bytes) {
  if (spawnSync('unzip', ['-v']).status !== 0) return 'no unzip here';
  const dir = mkdtempSync(join(tmpdir(), 'scorm-'));
  try {
    writeFileSync(join(dir, 'p.zip'), bytes);
    const r = spawnSync('unzip', ['-t', join(dir, 'p.zip')], { encoding: 'utf8' });
    assert.equal(r.status, 0, r.stdout + r.stderr);
    assert.match(r.stdout, /No errors detected/);
    return 'ok';
  } finally { rmSync(dir, { recursive: true }); }
}

/** Clicks `button` and returns the downloaded file's name and bytes. */
async function downloadOf(page, button) {
  const [dl] = await Promise.all([page.waitForEvent('download', { timeout: 30000 }), page.click(button)]);
  const path = await dl.path();
  return { name: dl.suggestedFilename(), bytes: readFileSync(path) };
}

const LMS_PAGE = `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Test LMS</title>
<script src="scorm12-lms.js"></script></head><body><h1>Test LMS</h1><div id="slot"></div>
<script>
  window.record = {};
  window.launch = () => {
    window.API = window.createScorm12LMS(window.record);
    const f = document.createElement('iframe');
    f.src = 'pkg/index.html'; f.width = 1200; f.height = 850; f.title = 'SCO';
    document.getElementById('slot').replaceChildren(f);
  };
  window.leave = () => { document.getElementById('slot').replaceChildren(); };
</script></body></html>`;

/** Serves the test LMS and the unzipped package under <site>/lms/ (the LMS's own origin, as the site's here). */
async function lmsContext(files) {
  const context = await H.browser.newContext({ viewport: { width: 1280, height: 1000 }, serviceWorkers: 'block' });
  await context.addInitScript(() => { /** @type {any} */ (window).splinelabWarm = 0; });
  const fixture = readFileSync(join(ROOT, 'tests/fixtures/scorm12-lms.js'));
  await context.route(`${H.base}lms/**`, (route) => {
    const path = new URL(route.request().url()).pathname.replace(/^\/lms\//, '');
    if (path === 'index.html') return route.fulfill({ contentType: 'text/html; charset=utf-8', body: LMS_PAGE });
    if (path === 'scorm12-lms.js') return route.fulfill({ contentType: 'text/javascript', body: fixture });
    const f = files.find((x) => `pkg/${x.name}` === path);
    if (!f) return route.fulfill({ status: 404, body: 'not in the package' });
    return route.fulfill({ contentType: f.name.endsWith('.html') ? 'text/html; charset=utf-8' : 'application/xml', body: f.data });
  });
  return context;
}

/** Types `text` into the number box of "Approximation a" in `where` (a page or a frame) and presses Enter. */
async function typeA(where, text) {
  const box = where.locator('input.ctl-number[aria-label^="Approximation a"]').first();
  await box.click();
  await box.press('Control+A');
  await box.type(text);
  await box.press('Enter');
}

/** interp-approx at a = 1/6 (the cubic B-spline, which misses the points), Make exercise opened, its link made. */
async function makeFromInterpApprox() {
  const t = await H.open('#interp-approx');
  await typeA(t.page, '1/6');
  await t.page.click('.exercise-make-toggle');
  await t.page.click('.exercise-make-go');
  await t.page.waitForSelector('.exercise-make-out:not([hidden])');
  // the measurement is written when the module answers (async): wait for it, then read it
  await t.page.waitForFunction(() => document.querySelector('.exercise-make-now').textContent !== '');
  assert.match(await t.page.textContent('.exercise-make-now'), /does not pass/);
  return t;
}

const sco = (page) => page.frames().find((f) => /\/lms\/pkg\/index\.html/.test(f.url()));

async function scoReady(page) {
  await page.waitForFunction(() => {
    const f = document.querySelector('#slot iframe');
    return f?.contentDocument?.querySelector('#demo-root[data-mounted="true"] , .exercise-panel') && f.contentDocument.querySelector('.exercise-panel');
  }, null, { timeout: 30000 });
  return sco(page);
}

test('exercises.html → SCORM package → a test LMS: untouched fails, solved with the controls passes 100, a relaunch resumes, leaving finishes', async () => {
  const t = await H.open('exercises.html', { waitFor: '.exercise-card' });
  const card = '.exercise-card[data-exercise="b2-through-data"]';
  const { name, bytes } = await downloadOf(t.page, `${card} .exercise-scorm`);
  assert.equal(name, 'b2-through-data-scorm.zip');
  const files = unzip(bytes);
  assert.deepEqual(files.map((f) => f.name), ['imsmanifest.xml', 'index.html']);
  const man = files[0].data.toString('utf8');
  assert.match(man, /<schemaversion>1\.2<\/schemaversion>/);
  assert.match(man, /adlcp:scormtype="sco" href="index\.html"/);
  assert.match(man, /<adlcp:masteryscore>100<\/adlcp:masteryscore>/);
  assert.match(man, /<title>Through the data<\/title>/);
  assert.deepEqual(await manifestProblems(t.page, man, files.map((x) => x.name)), []);
  unzipTest(bytes);
  const launch = files[1].data.toString('utf8');
  assert.ok(launch.length > 500000, `the launch page carries the one-file build (${launch.length} characters)`);
  // (script bodies cut off: the app's own text holds embed snippets with src=)
  const tags = launch.replace(/(<script\b[^>]*>)[\s\S]*?<\/script>/g, '$1</script>');
  assert.doesNotMatch(tags, /<script[^>]+src=|<link[^>]+rel="stylesheet"/, 'no script or style file of its own');
  t.assertClean();
  await t.close();

  const context = await lmsContext(files);
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  const requests = [];
  context.on('request', (r) => requests.push(r.url()));
  await page.goto(`${H.base}lms/index.html`);
  await page.evaluate(() => window.launch());
  let f = await scoReady(page);
  assert.equal(await f.evaluate(() => document.documentElement.dataset.scorm), 'connected');
  assert.match(await f.evaluate(() => location.hash), /^#interp-approx\//, 'the exercise\'s demo opened');
  let rec = await page.evaluate(() => window.record);
  assert.equal(rec.lesson_status, 'incomplete', 'launched: incomplete');

  // untouched: Check fails, the score is below 100
  await f.click('.exercise-panel .exercise-check');
  await f.waitForFunction(() => document.documentElement.dataset.scormStatus);
  rec = await page.evaluate(() => window.record);
  assert.equal(rec.lesson_status, 'failed');
  assert.ok(Number(rec.score_raw) < 100, `score ${rec.score_raw}`);
  assert.equal(rec.exit, 'suspend');
  assert.match(await f.textContent('.scorm-status'), /^Recorded in the course: not passed yet, score \d+ of 100/);

  // a change, then leave without passing: the view is kept in cmi.suspend_data, LMSFinish is called
  await typeA(f, '0.05');
  assert.equal(await f.evaluate(() => window.splinelab.current().state.a), 0.05);
  // the changed view reaches the LMS's suspend_data without a Check (the shell writes the link 200 ms later)
  await page.waitForFunction((before) => window.record.suspend_data !== before, rec.suspend_data, { timeout: 5000 });
  await page.evaluate(() => window.leave());
  await page.waitForFunction(() => window.API.finished(), null, { timeout: 10000 });
  rec = await page.evaluate(() => window.record);
  assert.match(JSON.parse(rec.suspend_data).l[0], /^#interp-approx\//);
  assert.equal(rec.session_times.length, 1);

  // relaunch: entry "resume", the view the student left (a = 0.05), then solve it: a = 0 interpolates
  await page.evaluate(() => window.launch());
  f = await scoReady(page);
  assert.equal(await page.evaluate(() => window.API.LMSGetValue('cmi.core.entry')), 'resume');
  assert.equal(await f.evaluate(() => window.splinelab.current().state.a), 0.05, 'the state the student left');
  await typeA(f, '0');
  await f.click('.exercise-panel .exercise-check');
  await f.waitForFunction(() => document.documentElement.dataset.scormStatus === 'passed');
  rec = await page.evaluate(() => window.record);
  assert.deepEqual([rec.lesson_status, rec.score_raw, rec.score_min, rec.score_max, rec.exit], ['passed', '100', '0', '100', '']);
  await page.evaluate(() => window.leave());
  await page.waitForFunction(() => window.API.finished(), null, { timeout: 10000 });
  const calls = await page.evaluate(() => window.API.calls);
  assert.ok(calls.every((c) => c.at(-1) !== 'false'), `no call refused: ${JSON.stringify(calls.filter((c) => c.at(-1) === 'false'))}`);
  assert.deepEqual(errors, []);
  // the launched package fetched nothing but its own files (and data:/blob: URLs it makes)
  const elsewhere = requests.filter((u) => !u.startsWith(`${H.base}lms/`) && !/^(data|blob):/.test(u));
  assert.deepEqual(elsewhere, [], 'requests outside the package');
  assert.ok(requests.filter((u) => u.startsWith(`${H.base}lms/pkg/`)).every((u) => /\/lms\/pkg\/index\.html(#.*)?$/.test(u)), JSON.stringify(requests));
  await context.close();
});

test('the launch page opened by itself (no LMS): the exercise works and the page says nothing is recorded', async () => {
  const t = await H.open('exercises.html', { waitFor: '.exercise-card' });
  const { bytes } = await downloadOf(t.page, '.exercise-card[data-exercise="noisy-sine"] .exercise-scorm');
  await t.close();
  const files = unzip(bytes);
  const context = await lmsContext(files);
  const page = await context.newPage();
  await page.goto(`${H.base}lms/pkg/index.html`);
  await page.waitForSelector('.exercise-panel', { timeout: 30000 });
  assert.equal(await page.evaluate(() => document.documentElement.dataset.scorm), 'none');
  assert.match(await page.textContent('.scorm-status'), /^No LMS found: .*not recorded/);
  await page.click('.exercise-panel .exercise-check');
  await page.waitForSelector('.exercise-feedback[data-passed]');
  assert.match(await page.textContent('.exercise-feedback'), /^Not yet\./);
  await context.close();
});

test('Make exercise: the teacher\'s pass mark goes into the package; a non-number is refused with a message', async () => {
  const t = await H.open('#interp-approx');
  await t.page.click('.exercise-make-toggle');
  await t.page.click('.exercise-make-go');
  await t.page.waitForSelector('.exercise-make-out:not([hidden])');
  await t.page.fill('.exercise-make .grading-pass', 'lots');
  await t.page.click('.exercise-make-scorm');
  await t.page.waitForFunction(() => /Pass mark/.test(document.querySelector('.exercise-make-scorm-status')?.textContent || ''));
  assert.match(await t.page.textContent('.exercise-make-scorm-status'), /^Pass mark for the LMS must be a whole number from 0 to 100 \(it is “lots”\)\.$/);
  await t.page.fill('.exercise-make .grading-pass', '75');
  const { name, bytes } = await downloadOf(t.page, '.exercise-make-scorm');
  assert.match(name, /^interp-approx-[a-z0-9-]+-scorm\.zip$/);
  const [man] = unzip(bytes);
  assert.match(man.data.toString('utf8'), /<adlcp:masteryscore>75<\/adlcp:masteryscore>/);
  assert.deepEqual(await t.axe(), [], 'axe: the Make exercise panel with its rules and packages');
  t.assertClean();
  await t.close();
});

test('a set of three from the catalogue: one package, one SCO; the total is the mean of the best scores; a relaunch keeps them', async () => {
  const t = await H.open('exercises.html', { waitFor: '.exercise-card' });
  for (const id of ['b2-through-data', 'noisy-sine', 'noisy-arc']) await t.page.check(`.exercise-card[data-exercise="${id}"] .exercise-pick-box`);
  assert.deepEqual(await t.page.$$eval('.scorm-set-picked li', (l) => l.map((x) => x.textContent)), ['Through the data', 'Smooth a noisy sine', 'An arc through noise']);
  assert.deepEqual(await t.axe(), [], 'axe: the catalogue with its set maker and ticked cards');
  await t.page.fill('.scorm-set-maker .grading-pass', '50');
  const { name, bytes } = await downloadOf(t.page, '.scorm-set-go');
  assert.equal(name, 'splinelab-set-3-scorm.zip');
  const files = unzip(bytes);
  const man = files[0].data.toString('utf8');
  assert.deepEqual(await manifestProblems(t.page, man, files.map((x) => x.name)), []);
  assert.match(man, /<adlcp:masteryscore>50<\/adlcp:masteryscore>/);
  assert.equal((man.match(/<item /g) || []).length, 1, 'one SCO with one score');
  unzipTest(bytes);
  // the manifest check can fail: a launch file that is not in the package
  assert.deepEqual(await manifestProblems(t.page, man.replace(/href="index\.html">/, 'href="start.html">'), files.map((x) => x.name)),
    ['resource sco-splinelab-set: launch file start.html is not in the package', 'resource sco-splinelab-set does not list its launch file']);
  t.assertClean();
  await t.close();

  const context = await lmsContext(files);
  const page = await context.newPage();
  await page.goto(`${H.base}lms/index.html`);
  await page.evaluate(() => window.launch());
  let f = await scoReady(page);
  await f.evaluate(() => { window.__results = []; document.addEventListener('splinelab-result', (e) => window.__results.push(e.detail)); });
  assert.match(await f.textContent('.scorm-set-head'), /^Exercise 1 of 3: Through the data\./);
  // 1: solved with its box (a = 0 interpolates)
  await typeA(f, '0');
  await f.click('.exercise-panel .exercise-check');
  await f.waitForFunction(() => window.__results.length === 1);
  // 2: the noisy sine, checked as it opens (a = 0 follows the noise: not passed)
  await f.click('.scorm-set-item >> nth=1');
  await f.waitForFunction(() => /^#noisy-data\//.test(location.hash) && document.querySelector('.exercise-panel[data-exercise="noisy-sine"]'));
  await f.click('.exercise-panel .exercise-check');
  await f.waitForFunction(() => window.__results.length === 2);
  const results = await f.evaluate(() => window.__results.map((r) => [r.exercise, r.passed, r.score]));
  assert.deepEqual(results.map((r) => r.slice(0, 2)), [['b2-through-data', true], ['noisy-sine', false]]);
  const s2 = Math.round(results[1][2] * 100);
  const want = Math.round((100 + s2 + 0) / 3); // the third is not checked: it counts 0
  let rec = await page.evaluate(() => window.record);
  assert.equal(rec.score_raw, String(want), `(100 + ${s2} + 0) / 3`);
  assert.equal(rec.lesson_status, want >= 50 ? 'passed' : 'failed');
  assert.match(await f.textContent('.scorm-set-head'), new RegExp(`^Exercise 2 of 3: Smooth a noisy sine\\. .* ${want} of 100 so far`));
  // leave and come back: the set's bar opens on exercise 2 with both best scores
  await page.evaluate(() => window.leave());
  await page.waitForFunction(() => window.API.finished(), null, { timeout: 10000 });
  await page.evaluate(() => window.launch());
  f = await scoReady(page);
  assert.match(await f.textContent('.scorm-set-head'), /^Exercise 2 of 3: Smooth a noisy sine\./);
  assert.deepEqual(await f.$$eval('.scorm-set-item', (b) => b.map((x) => x.textContent)), ['1. Through the data — 100', `2. Smooth a noisy sine — ${s2}`, '3. An arc through noise']);
  rec = await page.evaluate(() => window.record);
  assert.equal(rec.score_raw, String(want), 'unchanged by the relaunch');
  await context.close();
});

test('the teacher\'s rules from Make exercise: 2 Checks, a hint that costs 30 points, pass mark 60; a third Check is refused', async () => {
  const t = await makeFromInterpApprox();
  assert.notEqual(await t.page.inputValue('.exercise-make-hint'), '', 'the check comes with a hint');
  await t.page.fill('.exercise-make .grading-pass', '60');
  await t.page.fill('.exercise-make .grading-attempts', '2');
  await t.page.fill('.exercise-make .grading-hint', '30');
  const { bytes } = await downloadOf(t.page, '.exercise-make-scorm');
  await t.close();
  const files = unzip(bytes);
  const context = await lmsContext(files);
  const page = await context.newPage();
  await page.goto(`${H.base}lms/index.html`);
  await page.evaluate(() => window.launch());
  const f = await scoReady(page);
  // 1: as it opens (a = 1/6 misses the points): not passed; the feedback shows the hint
  await f.click('.exercise-panel .exercise-check');
  await f.waitForFunction(() => document.documentElement.dataset.scormScore !== undefined);
  assert.match(await f.textContent('.exercise-feedback'), /Hint: /);
  let rec = await page.evaluate(() => window.record);
  assert.equal(rec.lesson_status, 'failed');
  assert.match(await f.textContent('.scorm-status'), /pass mark 60 of 100; 2 Checks per exercise; a hint costs 30 points\. 1 Check left\.$/);
  // 2: solved: the hint was shown, so it counts 100 − 30 = 70 ≥ 60: passed
  await typeA(f, '0');
  await f.click('.exercise-panel .exercise-check');
  await f.waitForFunction(() => document.documentElement.dataset.scormScore === '70');
  rec = await page.evaluate(() => window.record);
  assert.deepEqual([rec.score_raw, rec.lesson_status], ['70', 'passed']);
  // 3: no Check left: nothing runs, nothing is sent, the page says so
  const calls = await page.evaluate(() => window.API.calls.length);
  await f.click('.exercise-panel .exercise-check');
  await f.waitForFunction(() => /^No Check left: this exercise allowed 2\. Your best score, 70 of 100, is recorded\.$/.test(document.querySelector('.scorm-status').textContent));
  assert.equal(await f.textContent('.exercise-attempts'), '2 attempts', 'the third Check did not run');
  assert.equal(await page.evaluate(() => window.API.calls.length), calls);
  await context.close();
});

test('the relay package: a few KB; the LMS (another origin) shows the hosted exercise; its results are recorded; a message from elsewhere is not', async (tt) => {
  const t = await makeFromInterpApprox();
  const { name, bytes } = await downloadOf(t.page, '.exercise-make-relay');
  assert.match(name, /^interp-approx-[a-z0-9-]+-relay-scorm\.zip$/);
  assert.ok(bytes.length < 20000, `the relay package is small: ${bytes.length} bytes`);
  tt.diagnostic(`relay package: ${bytes.length} bytes`);
  const files = unzip(bytes);
  assert.deepEqual(await manifestProblems(t.page, files[0].data.toString('utf8'), files.map((x) => x.name)), []);
  unzipTest(bytes);
  t.assertClean();
  await t.close();
  // the LMS on another origin (a second server, another port): the exercise frame is cross-origin, as a hosted site
  // is (a page fulfilled by the test itself would count as a public site, and Chromium blocks its frames of 127.0.0.1)
  const dir = mkdtempSync(join(tmpdir(), 'relay-lms-'));
  mkdirSync(join(dir, 'lms/pkg'), { recursive: true });
  writeFileSync(join(dir, 'lms/index.html'), LMS_PAGE);
  writeFileSync(join(dir, 'lms/scorm12-lms.js'), readFileSync(join(ROOT, 'tests/fixtures/scorm12-lms.js')));
  for (const f of files) writeFileSync(join(dir, 'lms/pkg', f.name), f.data);
  const lms = await startServer(dir);
  after(async () => { await lms.close(); rmSync(dir, { recursive: true, force: true }); });
  const lmsBase = lms.base;
  const context = await H.browser.newContext({ viewport: { width: 1280, height: 1000 }, serviceWorkers: 'block' });
  await context.addInitScript(() => { /** @type {any} */ (window).splinelabWarm = 0; });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(`${lmsBase}lms/index.html`);
  await page.evaluate(() => window.launch());
  await page.waitForFunction(() => window.record.lesson_status === 'incomplete');
  const relay = page.frames().find((f) => /\/lms\/pkg\/index\.html/.test(f.url()));
  assert.equal(await relay.evaluate(() => document.documentElement.dataset.scorm), 'connected');
  // a forged result from the LMS's own origin (not the exercise's frame, not its host) is not recorded
  await page.evaluate(() => document.querySelector('#slot iframe').contentWindow.postMessage({ type: 'splinelab:result', exercise: 'x', passed: true, score: 1 }, '*'));
  await page.waitForTimeout(300);
  assert.equal(await page.evaluate(() => window.record.score_raw), undefined, 'the forged message was ignored');
  // the hosted exercise, in the relay's frame: untouched fails, solved passes
  let ex = null;
  for (let i = 0; i < 100 && !ex; i++) { ex = page.frames().find((f) => f.url().startsWith(`${H.base}embed.html#interp-approx/`)); if (!ex) await page.waitForTimeout(100); }
  assert.ok(ex, `the hosted exercise is in the relay's frame: ${JSON.stringify(page.frames().map((f) => f.url()))} ${await relay.evaluate(() => document.body.innerText.slice(0, 300))} ${errors}`);
  await ex.waitForSelector('.exercise-panel .exercise-check', { timeout: 30000 });
  await ex.click('.exercise-panel .exercise-check');
  await page.waitForFunction(() => window.record.lesson_status === 'failed', null, { timeout: 10000 });
  await typeA(ex, '0');
  await ex.click('.exercise-panel .exercise-check');
  await page.waitForFunction(() => window.record.lesson_status === 'passed', null, { timeout: 10000 });
  assert.equal(await page.evaluate(() => window.record.score_raw), '100');
  assert.match(await relay.textContent('#status'), /^Recorded in the course: passed, score 100 of 100/);
  await page.evaluate(() => window.leave());
  await page.waitForFunction(() => window.API.finished(), null, { timeout: 10000 });
  assert.deepEqual(errors, []);
  await context.close();
});

test('Make exercise at 390×844: the panel, its rules and its package buttons fit the phone (no sideways scroll)', async () => {
  const t = await H.open('#interp-approx', { viewport: { width: 390, height: 844 } });
  await t.page.click('.exercise-make-toggle');
  await t.page.click('.exercise-make-go');
  await t.page.waitForSelector('.exercise-make-out:not([hidden])');
  const r = await t.page.evaluate(() => ({
    sw: document.documentElement.scrollWidth,
    out: [...document.querySelectorAll('.exercise-make *')].filter((e) => e.getClientRects().length && e.getBoundingClientRect().right > document.documentElement.clientWidth + 0.5).map((e) => e.className || e.tagName).slice(0, 5),
  }));
  assert.deepEqual(r, { sw: 390, out: [] });
  await t.close();
});
