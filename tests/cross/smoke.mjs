// The cross-engine smoke suite: every demo (index.html#<id>) and embed.html in one engine, one browser for the
// whole run and one page load per demo. Per page: the shell starts with no error, every visible canvas draws
// (pixels read back), a mouse drag of a control point changes the state and the URL, the keyboard moves a focused
// point, a 3D view draws with WebGL2 (its fallback message fails the run: the suite runs headful, where every
// engine has WebGL2), and an export produces a file (the download is caught in the
// page, so no engine opens a save dialog). The offline single file dist/splinelab.html is opened from file://
// with each demo and a link state when it has been built (scripts/build-offline.sh).
//
// Run under Xvfb: `xvfb-run -a node --test --test-concurrency=1 tests/cross/` (scripts/test.sh does).
// CROSS_DEMOS=b2-surfaces,curve-networks runs only these demos (and skips the file:// pass).

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { access, readFile, mkdtemp, mkdir, writeFile, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { LAUNCH } from './engines.mjs';
import { startServer, ensureWasm, demoIds, ROOT } from '../e2e/harness.mjs';
import { manifest, launchPage } from '../../www/lib/scorm-package.js';
import { zip } from '../../www/lib/zip.js';
import { unzip } from '../fixtures/unzip.mjs';

export const DIST = join(ROOT, 'dist/splinelab.html');

// ---------- functions evaluated in the page (plain, self-contained) ----------

/** Shell status: ready flag, mounted demo, error notices, fatal box. */
function pageStatus() {
  return {
    ready: document.documentElement.dataset.ready || '',
    mounted: !!document.querySelector('#demo-root[data-mounted="true"]'),
    errorNotices: [...document.querySelectorAll('.notice-error, .fatal')].map((n) => n.textContent.trim().slice(0, 200)),
    demo: document.body.dataset.demo || '',
  };
}

/**
 * Pixels of every visible canvas: distinct colours and the share of pixels off the most common colour (ink) in a
 * 64 × 64 sample; 3D views: WebGL2 context or not, fallback shown or not. Also the visible fallback messages of
 * the 3D views (class sl-view3d-fallback, www/lib/view3d/index.js) wherever they are, and whether this engine
 * gives a page a WebGL2 context at all.
 */
function canvasReport() {
  const canvases = [];
  for (const c of document.querySelectorAll('canvas')) {
    if (!c.getClientRects().length || c.width < 8 || c.height < 8) continue;
    const is3D = !!c.view3d;
    const fallbackShown = is3D && !!c.view3d.fallback && c.view3d.fallback.isConnected && !!c.view3d.fallback.getClientRects().length;
    const webgl2 = is3D && !!c.view3d.supported;
    const s = document.createElement('canvas');
    s.width = 64; s.height = 64;
    const g = s.getContext('2d');
    let colours = 0, ink = 0;
    try {
      // (the views keep their drawing buffer, preserveDrawingBuffer: this reads what is on screen)
      g.drawImage(c, 0, 0, 64, 64);
      const d = g.getImageData(0, 0, 64, 64).data;
      const counts = new Map();
      for (let i = 0; i < d.length; i += 4) { const k = (d[i] << 16) | (d[i + 1] << 8) | d[i + 2]; counts.set(k, (counts.get(k) || 0) + 1); }
      colours = counts.size;
      ink = 1 - Math.max(...counts.values()) / (64 * 64);
    } catch (e) { colours = -1; }
    canvases.push({ is3D, webgl2, fallbackShown, colours, ink: Math.round(ink * 1000) / 1000, w: c.width, h: c.height });
  }
  const fallbacks = [...document.querySelectorAll('.sl-view3d-fallback')].filter((m) => m.getClientRects().length).length;
  let engineWebgl2 = false;
  try { engineWebgl2 = !!document.createElement('canvas').getContext('webgl2'); } catch { engineWebgl2 = false; }
  return { canvases, fallbacks, engineWebgl2 };
}

/** A visible 2D plot with draggable points: viewport position of handle k (after scrolling it to the centre). */
function handleAt(k) {
  const cs = [...document.querySelectorAll('canvas')].filter((c) => c.splinePlot && c.getClientRects().length && c.splinePlot.handles().length);
  if (!cs.length) return null;
  const c = cs[0];
  const hs = c.splinePlot.handles();
  const hnd = hs[Math.min(k, hs.length - 1)];
  c.scrollIntoView({ block: 'center', inline: 'center' });
  const r = c.getBoundingClientRect();
  const [sx, sy] = c.splinePlot.toScreen(hnd.point[0], hnd.point[1]);
  return { x: r.left + sx, y: r.top + sy, count: hs.length, canvasIndex: [...document.querySelectorAll('canvas')].indexOf(c),
    inside: sx > 4 && sy > 4 && sx < r.width - 4 && sy < r.height - 4 };
}

/** A visible 3D view: viewport position of its first draggable point, else of its centre. */
function view3dTarget() {
  const c = [...document.querySelectorAll('canvas')].find((x) => x.view3d && x.getClientRects().length);
  if (!c) return null;
  c.scrollIntoView({ block: 'center', inline: 'center' });
  const r = c.getBoundingClientRect();
  const v = c.view3d;
  for (const [id, o] of v.objects) {
    if (o.kind === 'points' && o.draggable && o.positions.length) {
      const p = v.screenPosition(id, 0);
      if (p && p[0] > 4 && p[1] > 4 && p[0] < r.width - 4 && p[1] < r.height - 4) return { x: r.left + p[0], y: r.top + p[1], point: true };
    }
  }
  return { x: r.left + r.width / 2, y: r.top + r.height / 2, point: false };
}

/** A visible range slider (demos without draggable points): viewport points at 15 % and 85 % of its track. */
function sliderTarget() {
  const el = [...document.querySelectorAll('input[type="range"]')].find((x) => x.getClientRects().length && !x.disabled);
  if (!el) return null;
  el.scrollIntoView({ block: 'center' });
  const r = el.getBoundingClientRect();
  return { x0: r.left + r.width * 0.15, x1: r.left + r.width * 0.85, y: r.top + r.height / 2 };
}

/** Focuses the first visible 2D plot with draggable points (a keyboard focus selects its first point). */
function focusPlot() {
  const c = [...document.querySelectorAll('canvas')].find((x) => x.splinePlot && x.getClientRects().length && x.splinePlot.handles().length);
  if (!c) return false;
  c.scrollIntoView({ block: 'center' });
  c.focus();
  return document.activeElement === c;
}

async function snapshot() {
  await window.splinelab.flush();
  const cur = window.splinelab.current();
  return { state: JSON.stringify(cur && cur.state), hash: location.hash };
}

/** Catches downloads (anchor clicks with `download`) and clicks the JSON and PNG export buttons. */
async function exportFiles() {
  const got = [];
  const blobs = new Map();
  const orig = HTMLAnchorElement.prototype.click;
  const origURL = URL.createObjectURL;
  // the page's CSP (connect-src 'self') forbids fetching blob: URLs in some engines: keep the Blob itself
  URL.createObjectURL = function createObjectURL(b) { const u = origURL.call(URL, b); blobs.set(u, b); return u; };
  HTMLAnchorElement.prototype.click = function click() {
    if (this.download) got.push({ name: this.download, href: this.href });
    else orig.call(this);
  };
  try {
    const row = document.querySelector('.export-bar-buttons');
    if (!row) return { error: 'no export row' };
    row.dispatchEvent(new PointerEvent('pointerenter'));
    const out = [];
    for (const fmt of ['json', 'png']) {
      const btn = row.querySelector(`button[data-format="${fmt}"]`);
      if (!btn) { out.push({ fmt, error: 'no button' }); continue; }
      const n = got.length;
      btn.click();
      for (let i = 0; i < 250 && got.length === n; i++) await new Promise((ok) => setTimeout(ok, 20));   // (up to 5 s: the writers load lazily)
      const f = got[n];
      if (!f) { out.push({ fmt, error: 'no file' }); continue; }
      const blob = blobs.get(f.href);
      if (!blob) { out.push({ fmt, error: 'no blob' }); continue; }
      const head = new Uint8Array(await blob.slice(0, 8).arrayBuffer());
      let parsed = null;
      if (fmt === 'json') { try { parsed = JSON.parse(await blob.text()); } catch { parsed = null; } }
      out.push({ fmt, name: f.name, size: blob.size, png: head[1] === 0x50 && head[2] === 0x4e && head[3] === 0x47, demo: parsed && parsed.demo, hasState: !!(parsed && parsed.state) });
    }
    return { files: out };
  } finally {
    HTMLAnchorElement.prototype.click = orig;
    URL.createObjectURL = origURL;
  }
}

/** Records uncaught errors, rejections and console.error calls from now on in window.__crossErrors. */
function collectErrors() {
  if (window.__crossErrors) return;
  const list = window.__crossErrors = [];
  addEventListener('error', (e) => list.push(`error: ${e.message}`));
  addEventListener('unhandledrejection', (e) => list.push(`rejection: ${e.reason && e.reason.message || e.reason}`));
  const ce = console.error;
  console.error = function error(...a) { list.push(`console: ${a.map(String).join(' ')}`); return ce.apply(console, a); };
}

/** The sandbox (sandbox.html): puts `code` in the code area and runs it (in the sandbox's worker, off the page). */
function sandboxRun(code) {
  const ta = document.getElementById('sb-code');
  ta.value = code;
  ta.dispatchEvent(new Event('input'));
  window.splinelabSandbox.run();
}

/** The sandbox's last run: outcome, output, message box, coloured pixels of the curves' plot. */
function sandboxResult() {
  const c = document.querySelector('#sb-plot canvas');
  let ink = 0;
  if (c && c.width && !document.getElementById('sb-plot-panel').hidden) {
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - d[i + 1]) + Math.abs(d[i + 1] - d[i + 2]) > 60) ink++;
  }
  const box = document.getElementById('sb-error');
  return { run: document.body.dataset.run, output: document.getElementById('sb-output').textContent, note: box.hidden ? '' : box.textContent, ink };
}

// ---------- the suite ----------

/** Loads `url` in a fresh document and waits for the shell and the mounted demo. */
async function load(E, url) {
  await E.goto(url);
  await E.waitFor(() => document.documentElement.dataset.ready && (document.documentElement.dataset.ready !== 'true'
    || document.body.dataset.view !== 'demo' || !!document.querySelector('#demo-root[data-mounted="true"]')), null, 30000);
  // errors after the start (classic WebDriver has no console events; the start is checked by its ready flag)
  await E.eval(collectErrors);
  // two frames: plots draw on the next animation frame
  await E.eval(() => new Promise((ok) => requestAnimationFrame(() => requestAnimationFrame(() => ok()))));
}

/** Every check on one mounted demo page. `full`: also keyboard and export. */
/** The WCAG 2.0–2.2 A and AA rules of axe-core (issue 25); the Chromium suite (tests/e2e/a11y.test) runs axe's defaults with WCAG 2.2's target-size added. */
const AXE_TAGS = ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22a', 'wcag22aa'];
let axeSrc = null;
/** axe-core's serious and critical violations of the WCAG A/AA rules in the engine's current page: [] when none. */
async function axeViolations(E) {
  axeSrc ??= await readFile(join(ROOT, 'node_modules/axe-core/axe.min.js'), 'utf8');
  if (!(await E.eval(() => typeof (/** @type {any} */ (window)).axe === 'object'))) await E.run(axeSrc);
  return E.eval(async (tags) => {
    const r = await (/** @type {any} */ (window)).axe.run(document, { runOnly: { type: 'tag', values: tags }, resultTypes: ['violations'] });
    return r.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => `${v.id} (${v.impact}): ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(' | ')}`);
  }, AXE_TAGS);
}

async function checkDemo(E, id, { full = true } = {}) {
  const st = await E.eval(pageStatus);
  assert.equal(st.ready, 'true', `${E.name} ${id}: shell ready`);
  assert.ok(st.mounted, `${E.name} ${id}: demo mounted`);
  assert.deepEqual(st.errorNotices, [], `${E.name} ${id}: no error notice`);

  // draws: every visible canvas has a drawing; a 3D view draws with WebGL2 — its fallback message is a failure
  // (the suite runs headful under Xvfb, where Firefox and WebKit give pages WebGL2), not a pass
  const { canvases: cv, fallbacks, engineWebgl2 } = await E.eval(canvasReport);
  assert.ok(cv.length > 0, `${E.name} ${id}: a visible canvas`);
  assert.equal(fallbacks, 0, `${E.name} ${id}: a 3D view shows its "needs WebGL2" fallback instead of a drawing`
    + ` (this engine ${engineWebgl2 ? 'has' : 'has no'} WebGL2${engineWebgl2 ? '' : ': run headful, under xvfb-run -a'})`);
  for (const [i, c] of cv.entries()) {
    const what = `${E.name} ${id}: canvas ${i}${c.is3D ? ' (3D)' : ''}`;
    if (c.is3D) assert.ok(c.webgl2 && !c.fallbackShown, `${what} has a WebGL2 context (${JSON.stringify(c)})`);
    assert.ok(c.colours >= 4, `${what} draws (${c.colours} colours in a 64×64 sample)`);
    if (c.is3D) assert.ok(c.ink >= 0.02, `${what}: the WebGL drawing has ink (${(c.ink * 100).toFixed(1)} % of a 64×64 sample off the background)`);
  }

  // a pointer drag changes the state and the URL
  const s0 = await E.eval(snapshot);
  let h = await E.eval(handleAt, 0);
  let how;
  if (h) {
    // the first point may be fixed or outside the view: try up to three points
    for (let k = 0; k < Math.min(3, h.count); k++) {
      h = await E.eval(handleAt, k);
      if (!h.inside) continue;
      await E.mouseDrag([h.x, h.y], [h.x + 23, h.y - 17]);
      if ((await E.eval(snapshot)).state !== s0.state) break;
    }
    how = '2D point';
  } else if (await E.eval(() => [...document.querySelectorAll('canvas')].some((c) => c.view3d && c.getClientRects().length))) {
    const v = await E.eval(view3dTarget);
    await E.mouseDrag([v.x, v.y], [v.x + 40, v.y - 25]);
    how = v.point ? '3D point' : '3D view (orbit)';
    if (!v.point && (await E.eval(snapshot)).state === s0.state) {
      // this demo does not keep the camera in its state (quasi-cubic-surfaces): drag a slider instead
      const r = await E.eval(sliderTarget);
      if (r) { await E.mouseDrag([r.x0, r.y], [r.x1, r.y]); how = 'slider'; }
    }
  } else {
    // no draggable point in this demo (noisy-data): drag a slider with the pointer instead
    const r = await E.eval(sliderTarget);
    assert.ok(r, `${E.name} ${id}: a 2D plot with points, a 3D view or a slider`);
    await E.mouseDrag([r.x0, r.y], [r.x1, r.y]);
    how = 'slider';
  }
  const s1 = await E.eval(snapshot);
  assert.notEqual(s1.state, s0.state, `${E.name} ${id}: dragging a ${how} changes the state`);
  assert.notEqual(s1.hash, s0.hash, `${E.name} ${id}: … and the URL`);
  assert.ok(s1.hash.startsWith(`#${id}/v`), `${E.name} ${id}: the URL holds the state (${s1.hash.slice(0, 40)})`);

  if (!full) return;
  // the keyboard moves a focused point (2D demos)
  if (await E.eval(focusPlot)) {
    await E.press('ArrowRight', 'ArrowUp', 'ArrowRight');
    const s2 = await E.eval(snapshot);
    assert.notEqual(s2.state, s1.state, `${E.name} ${id}: arrow keys on the focused plot change the state`);
  }

  // export produces files
  const ex = await E.eval(exportFiles);
  assert.ok(ex.files, `${E.name} ${id}: export row (${ex.error})`);
  const [json, png] = ex.files;
  assert.ok(json.size > 20 && json.demo === id && json.hasState, `${E.name} ${id}: JSON export ${JSON.stringify(json)}`);
  assert.ok(png.size > 500 && png.png, `${E.name} ${id}: PNG export ${JSON.stringify(png)}`);
}

/** Registers the suite for one engine ('firefox' | 'webkit' | 'chromium'). */
export function smokeSuite(engine) {
  let E, srv, ids, n = 0;
  const timing = {};
  before(async () => {
    await ensureWasm();
    ids = await demoIds();
    if (process.env.CROSS_DEMOS) ids = ids.filter((id) => process.env.CROSS_DEMOS.split(',').includes(id));
    srv = await startServer();
    const t0 = Date.now();
    E = await LAUNCH[engine]();
    timing.launch = Date.now() - t0;
  });
  after(async () => {
    await E?.close();
    await srv?.close();
    if (process.env.CROSS_TIMING) console.log(`# ${engine} timing`, JSON.stringify(timing));
  });
  const fresh = (route) => `${srv.base}${route.replace(/#/, `${route.includes('?') ? '&' : '?'}load=${++n}#`)}`;
  const noErrors = async (what) => {
    // the shell fetches the other demos' modules 1.5 s after the first drawing; leaving the page before they are in
    // makes Firefox log each cancelled one ("A ServiceWorker intercepted the request and encountered an unexpected
    // error"), which the next page's check would read: wait for them (not there: the file:// build has no modules)
    if (await E.eval(() => !!document.getElementById('demo-root') && location.protocol !== 'file:')) {
      await E.waitFor(() => document.documentElement.dataset.demos === 'loaded', null, 30000);
    }
    const errs = [...E.errors.splice(0), ...(await E.eval(() => (window.__crossErrors || []).splice(0)))];
    assert.deepEqual(errs, [], `${engine} ${what}: page/console errors`);
  };

  test(`${engine}: gallery`, async () => {
    await load(E, fresh('index.html#'));
    const st = await E.eval(() => ({ ready: document.documentElement.dataset.ready, cards: document.querySelectorAll('a.card').length }));
    assert.equal(st.ready, 'true');
    assert.equal(st.cards, (await demoIds()).length, 'one card per demo');
    assert.deepEqual(await axeViolations(E), [], `${engine} gallery: axe, WCAG 2.2 A/AA: no serious or critical violation`);
    await noErrors('gallery');
  });

  test(`${engine}: every demo`, async (tt) => {
    for (const id of ids) {
      await tt.test(id, async () => {
        const t0 = Date.now();
        await load(E, fresh(`index.html#${id}`));
        timing[id] = Date.now() - t0;
        await checkDemo(E, id);
        assert.deepEqual(await axeViolations(E), [], `${engine} ${id}: axe, WCAG 2.2 A/AA: no serious or critical violation`);
        await noErrors(id);
      });
    }
  });

  test(`${engine}: embed.html (a 2D and a 3D demo)`, async (tt) => {
    for (const id of ['bspline-basics', 'b2-surfaces']) {
      await tt.test(id, async () => {
        await load(E, fresh(`embed.html#${id}`));
        await checkDemo(E, id, { full: false });
        await noErrors(`embed ${id}`);
      });
    }
  });

  test(`${engine}: dist/splinelab.html from file:// (every demo, a link state)`, async (tt) => {
    if (!(await access(DIST).then(() => true, () => false))) { tt.skip('dist/splinelab.html not built (scripts/build-offline.sh)'); return; }
    if (process.env.CROSS_DEMOS) { tt.skip('CROSS_DEMOS: a partial run'); return; }
    const file = pathToFileURL(DIST).href;
    // a link state made by the hosted page
    await load(E, fresh('index.html#bspline-basics'));
    const h = await E.eval(handleAt, 1);
    await E.mouseDrag([h.x, h.y], [h.x + 30, h.y + 20]);
    const linked = await E.eval(snapshot);
    let cold = 0;
    for (const [i, id] of ids.entries()) {
      await tt.test(id, async () => {
        const t0 = Date.now();
        await E.goto(`${file}?load=${++n}#${id}`);
        await E.waitFor(() => document.documentElement.dataset.ready && !!document.querySelector('#demo-root[data-mounted="true"]'), null, 30000);
        if (i === 0) cold = Date.now() - t0;
        await E.eval(() => new Promise((ok) => requestAnimationFrame(() => requestAnimationFrame(() => ok()))));
        await checkDemo(E, id, { full: false });
        await noErrors(`file:// ${id}`);
      });
    }
    timing.fileColdStart = cold;
    await tt.test('link state', async () => {
      await E.goto(`${file}?load=${++n}${linked.hash}`);
      await E.waitFor(() => !!document.querySelector('#demo-root[data-mounted="true"]'), null, 30000);
      const s = await E.eval(snapshot);
      assert.equal(s.state, linked.state, 'the file restores the state of a hosted link');
      await noErrors('file:// link');
    });
  });

  // issue 27: the SCORM package of an exercise (the package made here with the site's own modules, unzipped, served
  // beside a test LMS page: tests/fixtures/scorm12-lms.js) in this engine; Chromium's end-to-end suite drives the real
  // buttons and the controls (tests/e2e/scorm.test.mjs)
  test(`${engine}: a SCORM package launched by a test LMS: untouched fails, solved passes 100, leaving finishes`, async (tt) => {
    if (!(await access(DIST).then(() => true, () => false))) { tt.skip('dist/splinelab.html not built (scripts/build-offline.sh)'); return; }
    await load(E, fresh('exercises.html'));
    await E.waitFor(() => !!document.querySelector('.exercise-card[data-exercise="b2-through-data"] a.exercise-open'), null, 30000);
    const href = await E.eval(() => document.querySelector('.exercise-card[data-exercise="b2-through-data"] a.exercise-open').getAttribute('href'));
    const hash = href.slice(href.indexOf('#'));
    const cfg = { title: 'Through the data', passMark: 100, items: [{ id: 'b2-through-data', title: 'Through the data', hash }] };
    const files = unzip(await zip([
      { name: 'imsmanifest.xml', data: manifest({ id: 'b2-through-data', title: cfg.title, passMark: 100 }) },
      { name: 'index.html', data: launchPage(await readFile(DIST, 'utf8'), cfg) },
    ]));
    const dir = await mkdtemp(join(tmpdir(), 'scorm-cross-'));
    await mkdir(join(dir, 'lms/pkg'), { recursive: true });
    for (const f of files) await writeFile(join(dir, 'lms/pkg', f.name), f.data);
    await writeFile(join(dir, 'lms/scorm12-lms.js'), await readFile(join(ROOT, 'tests/fixtures/scorm12-lms.js')));
    await writeFile(join(dir, 'lms/index.html'), '<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Test LMS</title><script src="scorm12-lms.js"></script></head>'
      + '<body><div id="slot"></div><script>window.record = {}; window.API = window.createScorm12LMS(window.record);'
      + 'const f = document.createElement("iframe"); f.src = "pkg/index.html"; f.width = 1100; f.height = 800; f.title = "SCO"; document.getElementById("slot").append(f);</script></body></html>');
    const lms = await startServer(dir);
    try {
      await E.goto(`${lms.base}lms/index.html`);
      await E.waitFor(() => !!document.querySelector('#slot iframe')?.contentDocument?.querySelector('#demo-root[data-mounted="true"]') && !!document.querySelector('#slot iframe').contentDocument.querySelector('.exercise-panel'), null, 30000);
      assert.equal(await E.eval(() => document.querySelector('#slot iframe').contentDocument.documentElement.dataset.scorm), 'connected', `${engine}: the package found the LMS's API`);
      await E.eval(() => document.querySelector('#slot iframe').contentDocument.querySelector('.exercise-check').click());
      await E.waitFor(() => window.record.lesson_status === 'failed', null, 10000);
      // a = 0 interpolates: typed into the slider's box (its change event commits it, as Enter does)
      await E.eval(() => {
        const box = document.querySelector('#slot iframe').contentDocument.querySelector('input.ctl-number[aria-label^="Approximation a"]');
        box.value = '0';
        box.dispatchEvent(new Event('change', { bubbles: true }));
      });
      await E.waitFor(() => document.querySelector('#slot iframe').contentWindow.splinelab.current().state.a === 0, null, 5000);
      await E.eval(() => document.querySelector('#slot iframe').contentDocument.querySelector('.exercise-check').click());
      await E.waitFor(() => window.record.lesson_status === 'passed', null, 10000);
      assert.deepEqual(await E.eval(() => [window.record.score_raw, window.record.exit]), ['100', ''], `${engine}: the score`);
      await E.eval(() => document.getElementById('slot').replaceChildren());
      await E.waitFor(() => window.API.finished(), null, 10000);
      const errs = [...E.errors.splice(0)];
      assert.deepEqual(errs, [], `${engine} SCORM: page/console errors`);
    } finally {
      await lms.close();
      await rm(dir, { recursive: true, force: true });
    }
  });

  test(`${engine}: sandbox (the code runs in a worker of an opaque-origin frame: draws, errors name their line, no storage, Stop ends an endless loop)`, async () => {
    await load(E, fresh('sandbox.html'));
    assert.equal(await E.eval(() => document.documentElement.dataset.ready), 'true', 'the sandbox\'s worker started');
    const ran = async (code) => {
      await E.eval(sandboxRun, code);
      await E.waitFor(() => document.body.dataset.run !== 'running', null, 20000);
      await E.eval(() => new Promise((ok) => requestAnimationFrame(() => requestAnimationFrame(() => ok()))));
      return E.eval(sandboxResult);
    };
    const a = await ran('const c = sl.bsplineCurve({ points: [[0, 0], [1, 2], [3, -1], [4, 0]], samples: 50 });\nplot(c);\nprint(c.points[0], c.points[99]);');
    assert.deepEqual([a.run, a.output], ['ok', '0 0\n']);
    assert.ok(a.ink > 200, `${engine}: the curve inked ${a.ink} pixels`);
    const b = await ran('print(1);\nconst a = (1 + ;\n');
    assert.equal(b.run, 'error');
    assert.match(b.note, /^Error on line 2: SyntaxError/);
    const c = await ran('print(1);\nsl.bsplineCurve({ degree: 3, points: [[0, 0], [1, 1]] });');
    assert.match(c.note, /^Error on line 2: points: .*\(field points, too-few\)/);
    const d = await ran('const got = [];\nfor (const f of [() => localStorage.length, () => document.cookie, () => top.location.href, () => indexedDB.open("x")]) { try { got.push("read " + typeof f()); } catch (e) { got.push(e.name); } }\nprint(got.join());');
    assert.equal(d.run, 'ok');
    assert.doesNotMatch(d.output, /read/, `${engine}: the code reached the site: ${d.output}`);
    await E.eval(sandboxRun, 'print("loop");\nwhile (true) {}');
    await E.waitFor(() => /loop/.test(document.getElementById('sb-output').textContent), null, 10000);
    const f0 = await E.eval(() => new Promise((ok) => { let n = 0; const t0 = performance.now(); const f = () => (performance.now() - t0 > 500 ? ok(n) : (n++, requestAnimationFrame(f))); requestAnimationFrame(f); }));
    assert.ok(f0 >= 5, `${engine}: the page drew ${f0} frames in 0.5 s of the endless loop`);
    await E.eval(() => window.splinelabSandbox.stop());
    const e = await E.eval(sandboxResult);
    assert.equal(e.run, 'stopped');
    assert.match(e.note, /you pressed Stop/);
    const g = await ran('print(6 * 7);');
    assert.deepEqual([g.run, g.output], ['ok', '42\n'], 'a fresh worker runs the next code');
    await noErrors('sandbox');
  });
}
