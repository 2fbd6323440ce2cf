// The worker draws what the page draws (issue 26): the five demos whose heavy wasm work moved to the compute worker
// (www/lib/compute-client.js) — B2 surfaces, quasi-cubic surfaces, blended interpolation, the criss-cross basis and
// noisy data — each do their largest action twice, once with every call forced onto the page
// (`globalThis.splinelabCompute = 'here'`) and once forced into the worker ('worker'); the pixels of every canvas
// and the numbers on screen must be the same. And small work stays on the page: at the demos' default sizes a
// drag or a slider sends no request to a worker and never shows a "Computing…" line.
//
//   node --test --test-concurrency=1 tests/e2e/compute-parity.test.mjs

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { writeFileSync, mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { startHarness, OUT } from './harness.mjs';

mkdirSync(OUT, { recursive: true });

const IGNORE = [/GPU stall due to ReadPixels/];
let H;
before(async () => { H = await startHarness(); });
after(() => H?.close());

// ---------- the data at each demo's maximum ----------
const rowsCSV = (pts) => pts.map((p) => p.join(', ')).join('\n');
const wave = (k) => Array.from({ length: k }, (_, i) => [Math.round(i * 1000 / (k - 1)) / 100, Math.round(Math.sin(i / 3) * 1000) / 1000]);
const gridJSON = (r, c) => JSON.stringify(Array.from({ length: r }, (_, i) => Array.from({ length: c }, (_, j) => [i, j, Math.round(Math.sin(i / 4) * Math.cos(j / 5) * 1000) / 1000])));
const noisy2000 = () => rowsCSV(Array.from({ length: 2000 }, (_, i) => [i / 100, Math.round((Math.sin(i / 150) + 0.1 * Math.sin(i * 7.1)) * 1000) / 1000]));

async function applyData(t, text) {
  if (!(await t.page.$eval('.data-import', (d) => d.open))) await t.page.click('.data-import > summary');
  await t.page.fill('.data-import textarea', text);
  await t.page.click('.data-import [data-action="apply-data"]');
}
const sliderOf = async (t, label) => '#' + await t.page.getByLabel(label, { exact: true }).first().getAttribute('id');

/** Each demo's largest action (what main-thread.test measures), done the same way in both modes. */
const ACTIONS = {
  'b2-surfaces': async (t) => {
    await applyData(t, gridJSON(32, 32));
    await settle(t);
    // and a drag of an inner grid point of the 32 × 32 grid (the newest request wins in the worker)
    await t.page.$eval('canvas[data-plot="surface"]', (c) => c.view3d.fit());
    const p = await t.page.$eval('canvas[data-plot="surface"]', (c) => c.view3d.screenPosition('W', 16 * 32 + 16));
    const box = await t.page.locator('canvas[data-plot="surface"]').boundingBox();
    await t.page.mouse.move(box.x + p[0], box.y + p[1]);
    await t.page.mouse.down();
    for (let i = 1; i <= 8; i++) { await t.page.mouse.move(box.x + p[0], box.y + p[1] - 5 * i); await t.page.waitForTimeout(16); }
    await t.page.mouse.up();
  },
  'quasi-cubic-surfaces': async (t) => {
    await applyData(t, gridJSON(32, 32));
    await settle(t);
    await t.setInput(await sliderOf(t, 'Shape parameter α'), 0.6);
  },
  'blended-interpolation': async (t) => {
    await applyData(t, rowsCSV(wave(80)));
    await settle(t);
    const hs = await t.page.$eval('canvas[data-plot="curve"]', (c) => c.splinePlot.handles());
    const p = hs[40].point;
    await t.dragWorld('canvas[data-plot="curve"]', p, [p[0] + 0.3, p[1] + 0.3], 12);
  },
  'criss-cross-basis': async (t) => {
    await t.setInput(await sliderOf(t, 'cells in u (m)'), 10);
    await t.setInput(await sliderOf(t, 'cells in v (n)'), 10);
  },
  'noisy-data': async (t) => {
    await t.page.$eval('textarea.csv-input', (e, v) => { e.value = v; }, noisy2000());
    await t.page.$eval('textarea.csv-input', (e) => e.closest('.ctl').querySelector('button').click());
    await settle(t);
    await t.setInput('input[name="a"]', 0.1);
  },
};

/** Waits until no request is unanswered (the compute line's data-computing) and the frames are drawn. */
async function settle(t) {
  await t.page.waitForFunction(() => !document.querySelector('[data-computing="true"]'), null, { timeout: 60000 });
  await t.frames(3);
}

/** Every canvas of the demo as PNG data (3D views drawn synchronously first) and the numbers it shows. */
const capture = (t) => t.page.evaluate(() => ({
  canvases: [...document.querySelectorAll('#demo canvas, main canvas')].filter((c) => c.width > 0 && c.height > 0).map((c) => (c.view3d ? c.view3d.toDataURL() : c.toDataURL('image/png'))),
  numbers: [...document.querySelectorAll('.ctl-readout, .plot-numbers, .ctl-table, .data-import-ok, .data-import-error:not([hidden])')].map((e) => e.textContent.trim()).join(' | '),
  // each 3D view's camera, size and objects (drawing order, visibility, a checksum of each array)
  scene: JSON.stringify([...document.querySelectorAll('canvas')].filter((c) => c.view3d).map((c) => [c.view3d.getView(), c.width, c.height,
    [...c.view3d.objects].map(([id, o]) => [id, o.order, o.visible, ...['positions', 'normals', 'scalars', 'segs', 'indices'].map((k) => (o[k] ? [o[k].constructor.name, o[k].length, Array.from(o[k]).reduce((a, x, i) => a + x * ((i % 7) + 1), 0)] : null)), (o.overlays || []).map((v) => v.segs.length)])])),
  workers: performance.getEntriesByType('resource').filter((e) => e.name.endsWith('/compute-worker.js')).length,
}));

async function run(id, mode) {
  const context = await H.browser.newContext({ viewport: { width: 1366, height: 900 } });
  await context.addInitScript((m) => { window.splinelabCompute = m; }, mode);
  const t = await H.open(`#${id}`, { context });
  await ACTIONS[id](t);
  await settle(t);
  const shot = await capture(t);
  t.assertClean(IGNORE);
  await t.close(); await context.close();
  return shot;
}

for (const id of Object.keys(ACTIONS)) {
  test(`${id}: computed in the worker, the drawing and the numbers are those computed on the page`, async () => {
    const here = await run(id, 'here');
    const worker = await run(id, 'worker');
    assert.ok(here.canvases.length > 0, 'canvases to compare');
    assert.equal(worker.numbers, here.numbers, 'the same numbers on screen');
    assert.equal(worker.scene, here.scene, 'the same 3D scenes: camera, objects in the same drawing order, the same data');
    assert.equal(worker.canvases.length, here.canvases.length);
    const differ = here.canvases.map((png, k) => (png === worker.canvases[k] ? null : k)).filter((k) => k !== null);
    // the differing canvases of both modes, to look at
    for (const k of differ) {
      for (const [mode, s] of [['here', here], ['worker', worker]]) writeFileSync(join(OUT, `parity-${id}-${k}-${mode}.png`), Buffer.from(s.canvases[k].split(',')[1], 'base64'));
    }
    assert.deepEqual(differ, [], `the same pixels in every canvas (differing canvases: ${differ.join(', ')})`);
    assert.equal(here.workers, 0, 'forced here: no worker started');
    assert.ok(worker.workers > 0, 'forced into the worker: the worker computed');
  });
}

// Small work stays synchronous (measured under SYNC_MS): at the default sizes no worker starts and no
// "Computing…" line ever shows, while dragging or moving a slider.
test('small work stays on the page: no worker request, no "Computing…" line', async () => {
  const SMALL = {
    'blended-interpolation': async (t) => {
      const hs = await t.page.$eval('canvas[data-plot="curve"]', (c) => c.splinePlot.handles());
      const p = hs[3].point;
      await t.dragWorld('canvas[data-plot="curve"]', p, [p[0] + 0.3, p[1] + 0.3], 12);
    },
    'criss-cross-basis': async (t) => { await t.setInput(await sliderOf(t, 'cells in u (m)'), 6); },
    'b2-surfaces': (t) => t.setInput('input[name="a"]', 0.1),
    'quasi-cubic-surfaces': async (t) => { await t.setInput(await sliderOf(t, 'Shape parameter α'), 0.8); },
    'noisy-data': (t) => t.setInput('input[name="a"]', 0.1),
  };
  for (const [id, act] of Object.entries(SMALL)) {
    const context = await H.browser.newContext({ viewport: { width: 1366, height: 900 } });
    // every time a compute line is shown, it is counted
    await context.addInitScript(() => {
      // every request to a compute worker is counted
      window.__posts = 0;
      window.__posted = [];   // the wasm functions of each request, for the failure message
      const post = Worker.prototype.postMessage;
      Worker.prototype.postMessage = function (...a) { window.__posts++; window.__posted.push((a[0]?.calls || []).map((c) => c.fn).join('+')); return post.apply(this, a); };
      window.__shown = 0;
      new MutationObserver((ms) => { for (const m of ms) if (m.target.classList?.contains('compute-status') && !m.target.hidden) window.__shown++; })
        .observe(document, { subtree: true, attributes: true, attributeFilter: ['hidden'] });
      // every reason a request went to the worker, in order (the status line keeps only the latest: during a drag,
      // a frame measured slow goes there, and the frames after it follow while it computes, "the worker is busy")
      window.__whys = [];
      new MutationObserver((ms) => {
        for (const m of ms) {
          const e = /** @type {HTMLElement} */ (m.target);
          if (e.classList?.contains('compute-status') && e.dataset.why) window.__whys.push({ why: e.dataset.why, ms: e.dataset.whyMs });
        }
      }).observe(document, { subtree: true, attributes: true, attributeFilter: ['data-why'] });
    });
    const t = await H.open(`#${id}`, { context });
    await settle(t);
    // noisy-data's start-up sweep (60 points with cross-validation, estimated 90 ms: the worker) starts two frames
    // after the first drawing and is shown when it returns: wait for its readout before counting requests
    if (id === 'noisy-data') {
      await t.page.waitForFunction(() => [...document.querySelectorAll('.ctl-readout')].some((r) => r.querySelector('.ctl-readout-label')?.textContent === 'Choosing a' && !/^\s*—?\s*$/.test(r.querySelector('output').textContent)), null, { timeout: 60000 });
      await settle(t);
    }
    await t.page.evaluate(() => {
      window.__shown = 0; window.__posts = 0; window.__posted = []; window.__whys = [];
      for (const e of document.querySelectorAll('.compute-status')) { delete e.dataset.why; delete e.dataset.whyMs; }
    });
    const before = await capture(t);
    await act(t);
    await settle(t);
    const after = await capture(t);
    // Small is measured, not assumed: a request to the worker is right only when the page measured this work at
    // SYNC_MS (16 ms) or more (a loaded or cold machine: CI sent noisy-data's two 60-point fits there once);
    // then the status line says so (data-why-ms), and the requests sent while it computes say the worker is busy.
    // Anything else sent there fails.
    const posts = await t.page.evaluate(() => window.__posts);
    // The first request must have been measured slow; the ones after it may go there because it still computes.
    const why = await t.page.evaluate(() => window.__whys);
    const measuredLarge = why.length > 0 && Number(why[0].ms) >= 16 && why.every((w) => Number(w.ms) >= 16 || /: the worker is busy$/.test(w.why));
    if (posts > 0) console.log(`# ${id}: ${posts} request(s) to the worker: ${why.map((w) => w.why).join('; ')}`);
    assert.ok(posts === 0 || measuredLarge, `${id}: small work sent no request to a worker (sent: ${await t.page.evaluate(() => window.__posted.join(', '))}; why: ${why.map((w) => w.why).join('; ') || 'not said'})`);
    assert.ok(await t.page.evaluate(() => window.__shown) === 0 || measuredLarge, `${id}: no "Computing…" line showed`);
    assert.notDeepEqual(after.canvases, before.canvases, `${id}: the action changed the drawing`);
    t.assertClean(IGNORE);
    await t.close(); await context.close();
  }
});

// An API error from the worker reaches the page as before: the same message (naming the field) in the same notice.
test('noisy-data: an API error computed in the worker is shown as when computed on the page', async () => {
  const shown = {};
  for (const mode of ['here', 'worker']) {
    const context = await H.browser.newContext({ viewport: { width: 1366, height: 900 } });
    await context.addInitScript((m) => { window.splinelabCompute = m; }, mode);
    const t = await H.open('#noisy-data', { context });
    await settle(t);
    // four equal points: chord-length knots need distinct neighbours (b2Fit's error names points[0])
    await t.page.$eval('textarea.csv-input', (e) => { e.value = '1, 2\n1, 2\n1, 2\n1, 2'; });
    await t.page.$eval('textarea.csv-input', (e) => e.closest('.ctl').querySelector('button').click());
    await settle(t);
    shown[mode] = {
      notices: await t.page.$$eval('.notice-error .notice-text', (e) => e.map((x) => x.textContent)),
      numbers: await t.page.$$eval('.plot-numbers', (e) => e.map((x) => x.textContent)),
    };
    await t.close(); await context.close();
  }
  // on the page each of the two fits and the sweep report it (3 notices); in the worker the two fits are one
  // request (one notice) and the sweep another: the same message, from both requests
  const coincide = (m) => /^points\[0\]: coincides with points\[0\]/.test(m);
  assert.equal(shown.here.notices.filter(coincide).length, 3, `the page's errors: ${JSON.stringify(shown.here)}`);
  assert.equal(shown.worker.notices.filter(coincide).length, 2, `the worker's errors: ${JSON.stringify(shown.worker)}`);
  assert.deepEqual(new Set(shown.worker.notices), new Set(shown.here.notices), 'the same messages');
  assert.deepEqual(shown.worker.numbers, shown.here.numbers, 'the same (empty) numbers');
});
