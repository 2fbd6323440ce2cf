// Nothing heavy on the main thread (issue 26): every demo, driven at the largest sizes its UI accepts (its own data
// at the demo's maximum count, the largest curve network at the finest tessellation, dragging a point), must not
// block the page's main thread for more than 50 ms with its own work. Long tasks are counted with a
// PerformanceObserver ({ type: 'longtask' }) installed before the page loads, and attributed with the long animation
// frames ({ type: 'long-animation-frame' }: each frame's scripts — event handlers, animation-frame callbacks,
// timers, worker messages, with the wasm they call — and its rendering). Each action clears the lists first, so
// page start-up is not counted. The check: no frame spends over 50 ms in the page's scripts, except the named,
// measured entries of KNOWN (what still blocks, with why). Frames that went to rendering only (in this headless
// setup Chromium rasterises WebGL in software and the commit waits for it: 0.2–3 s per frame of a large 3D scene)
// are printed in the table (MAIN_THREAD_TABLE=1), not checked: that is the GPU's work on a real machine.
// Durations depend on the machine's load: the numbers in KNOWN are from a shared 2-core machine at load 11–15.
// The machine's own load adds time to a frame, never takes it away, so an action whose frames went over the budget
// is measured again on a fresh page, up to ATTEMPTS times, and its best attempt is the one checked: work that
// really blocks goes over in every attempt (seen: with a budget of 10 ms the check fails after three attempts),
// while a frame that only a busy moment stretched does not repeat. The table says which attempt was kept.
// Except the actions of FIRST_ATTEMPT: they are checked on their first attempt. They used to pass only by retrying
// (in CI, at load 5 from the suite's own browsers, bezier-remodel's import and noisy-data's paste took 81 and 74 ms
// in one frame; on a quiet machine under 50 and 28 ms); now each does its work over several frames.
//
//   node --test --test-concurrency=1 tests/e2e/main-thread.test.mjs
//   MAIN_THREAD_TABLE=1 …   prints the table of every action (demo, action, longest task, count over 50 ms)
//   MAIN_THREAD_THROTTLE=4 …   the same with the page's CPU throttled 4× (Chromium's emulation of a slower machine)

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { startHarness, ROOT } from './harness.mjs';

const require = createRequire(import.meta.url);
const sl = require(join(ROOT, 'pkg-node/splinelab.js'));

const BUDGET_MS = Number(process.env.MAIN_THREAD_BUDGET || 50);
const ATTEMPTS = 3;
// Checked on their first attempt, no retries (issue 26): the click does a part, each next part comes in a frame of
// its own (www/lib/frame-steps.js). Measured 2026-11-27 on the shared 2-core machine, most page script in one frame
// (the shell's timers left out) at 4× CPU throttling, load 2.5–3.3, alternating with the code before the split: the
// paste 39–65 ms (before: 53–104; its largest frame now is one plot of 2000 points painted), the import 0–31 ms
// (before: 67–162); unthrottled about a quarter of that. Before the split this check failed unthrottled at load 2–4
// (the paste: 75 ms in one frame) and with MAIN_THREAD_THROTTLE=3 for both (80 and 116 ms).
const FIRST_ATTEMPT = [
  { demo: 'noisy-data', action: /^paste 2000 CSV points$/ },
  { demo: 'bezier-remodel', action: /^import 25 control points/ },
];
const firstAttemptOnly = (r) => FIRST_ATTEMPT.some((k) => k.demo === r.demo && k.action.test(r.action));
let H;
before(async () => { H = await startHarness({ warm: true /* the idle warm-up on, as a visitor has it */, fresh: true /* a first visit: nothing cached */ }); });
after(() => H?.close());

/** Opens a demo with the long-task observer installed before any script of the page runs. */
async function openDemo(id, viewport = { width: 1366, height: 900 }) {
  const context = await H.browser.newContext({ viewport });
  await context.addInitScript(() => {
    window.__longTasks = [];
    window.__frames = [];
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) window.__longTasks.push({ start: e.startTime, duration: e.duration });
    }).observe({ type: 'longtask', buffered: true });
    // the same blocking, attributed: each long animation frame's scripts (event handlers, animation-frame
    // callbacks, timers: the page's JavaScript and the wasm it calls) and its rendering (style, layout, paint,
    // and the commit that waits for the WebGL frame)
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) {
        const script = e.scripts.reduce((s, x) => s + x.duration, 0);
        const render = e.renderStart ? e.startTime + e.duration - e.renderStart : 0;
        window.__frames.push({ duration: e.duration, script, render, scripts: e.scripts.map((x) => ({ invoker: x.invoker || x.name, duration: Math.round(x.duration) })) });
      }
    }).observe({ type: 'long-animation-frame', buffered: true });
  });
  const t = await H.open(`#${id}`, { context });
  // MAIN_THREAD_THROTTLE=4: the page's main thread 4× slower (Chromium's CPU throttling), a slower machine's view
  if (Number(process.env.MAIN_THREAD_THROTTLE) > 1) {
    const cdp = await context.newCDPSession(t.page);
    await cdp.send('Emulation.setCPUThrottlingRate', { rate: Number(process.env.MAIN_THREAD_THROTTLE) });
  }
  // what the page loads after its first drawing (the Export row's code, the exercise module…) is not an action's
  await t.page.waitForLoadState('networkidle');
  await t.page.waitForTimeout(500);
  const close = t.close;
  t.close = async () => { await close(); await context.close(); };
  return t;
}

/** Runs `action`, lets the page settle (work it finishes in later tasks or in a worker counts too), and returns
 * the long tasks of that time. */
async function measure(t, action, settle = 'settled') {
  await t.frames(2);
  await t.page.evaluate(() => { window.__longTasks.length = 0; window.__frames.length = 0; });
  await action();
  // the page's own "working" indication (www/lib/compute-client.js) must have gone: all results are in
  await t.page.waitForFunction(() => !document.querySelector('[data-computing="true"]'), null, { timeout: 30000 });
  await t.page.waitForTimeout(300);
  await t.frames(3);
  void settle;
  return t.page.evaluate(() => ({ tasks: window.__longTasks.map((e) => Math.round(e.duration)), frames: window.__frames }));
}

// ---------- the data at each demo's maximum ----------
const rowsCSV = (pts) => pts.map((p) => p.join(', ')).join('\n');
const wave = (k, f = 1) => Array.from({ length: k }, (_, i) => [Math.round(i * 1000 / (k - 1)) / 100 * f, Math.round(Math.sin(i / 3) * 1000) / 1000]);
const gridJSON = (r, c) => JSON.stringify(Array.from({ length: r }, (_, i) => Array.from({ length: c }, (_, j) => [i, j, Math.round(Math.sin(i / 4) * Math.cos(j / 5) * 1000) / 1000])));
/** A compatible curve network with `m + 1` × `n + 1` curves (the API builds it from a function). */
function networkJSON(m, n) {
  const upTo = (k) => Array.from({ length: k + 1 }, (_, i) => i);
  return JSON.stringify(sl.networkFromFunction({ u: upTo(m), v: upTo(n), f: (u, v) => [u, v, Math.sin(u / 3) * Math.cos(v / 4) + 0.02 * u * v] }));
}

async function pasteData(t, text) {
  if (!(await t.page.$eval('.data-import', (d) => d.open))) await t.page.click('.data-import > summary');
  await t.page.fill('.data-import textarea', text);
  return () => t.page.click('.data-import [data-action="apply-data"]');
}
const okText = (t) => t.page.$eval('.data-import', (b) => ({ ok: b.querySelector('.data-import-ok').textContent, err: b.querySelector('.data-import-error').hidden ? '' : b.querySelector('.data-import-error').textContent }));

/** Drags the first handle of the first 2D plot a little (plot2d handles). */
async function dragFirstHandle(t) {
  const sel = 'canvas[data-plot]';
  const hs = await t.page.$eval(sel, (c) => c.splinePlot?.handles?.() || []).catch(() => []);
  if (!hs.length) return false;
  const p = hs[Math.floor(hs.length / 2)].point;
  await t.dragWorld(sel, p, [p[0] + 0.3, p[1] + 0.3], 12);
  return true;
}

const results = [];   // { demo, action, longest, over }
function record(demo, action, { tasks, frames }) {
  const longest = tasks.length ? Math.max(...tasks) : 0;
  const over = tasks.filter((d) => d > BUDGET_MS).length;
  const script = Math.round(Math.max(0, ...frames.map((f) => f.script)));
  const render = Math.round(Math.max(0, ...frames.map((f) => f.render)));
  const worst = frames.reduce((a, f) => (f.script > (a?.script ?? -1) ? f : a), null);
  results.push({ demo, action, longest, over, tasks, script, render, frames, worst: worst?.scripts.slice(0, 3).map((x) => `${x.invoker} ${x.duration}`).join('; ') || '' });
  return { longest, over };
}

/**
 * Runs `unit` (opens a page, acts, records its measurements) until none of its frames is over the budget, at most
 * ATTEMPTS times, and keeps the rows of its best attempt (fewest blocking frames): the machine's load only adds
 * time, so a frame over the budget in every attempt is the page's own work. The rows of FIRST_ATTEMPT actions are
 * those of the first attempt, whatever the later ones measured.
 */
async function attempts(unit) {
  let best = null, first = [];
  for (let k = 1; k <= ATTEMPTS; k++) {
    const start = results.length;
    await unit();
    const rows = results.splice(start);
    if (k === 1) first = rows.filter(firstAttemptOnly).map((r) => ({ ...r, attempt: 1 }));
    const over = rows.reduce((n, r) => n + blockedFrames(r).length, 0);
    if (!best || over < best.over) best = { rows, over, attempt: k };
    if (over === 0) break;
  }
  for (const r of best.rows) r.attempt = best.attempt;
  results.push(...best.rows.map((r) => (firstAttemptOnly(r) ? first.find((f) => f.demo === r.demo && f.action === r.action) : r)));
}

/** Import `text` into the demo's "Use my data", then drag a point; each is one measured action. */
async function importAndDrag(...args) { await attempts(() => importAndDragOnce(...args)); }
async function importAndDragOnce(id, what, text, { drag = true } = {}) {
  const t = await openDemo(id);
  const apply = await pasteData(t, text);
  record(id, `import ${what}`, await measure(t, apply));
  const { ok, err } = await okText(t);
  assert.equal(err, '', `${id}: the import was refused: ${err}`);
  assert.ok(ok, `${id}: the import was applied`);
  if (drag) {
    let dragged = false;
    const tasks = await measure(t, async () => { dragged = await dragFirstHandle(t); });
    if (dragged) record(id, `drag a point (${what})`, tasks);
  }
  t.assertClean();
  await t.close();
}

// The largest sizes each demo accepts (the demos' own limits: MAX_POINTS, the data-import max, slider max).
test('curve demos with their maximum own data', async () => {
  await importAndDrag('bspline-basics', '16 control points', rowsCSV(wave(16)));
  await importAndDrag('interp-approx', '26 data points', rowsCSV(wave(26)));
  await importAndDrag('quasi-cubic-curves', '14 control points', rowsCSV(wave(14)));
  await importAndDrag('blended-interpolation', '80 data points', rowsCSV(wave(80)));
  await importAndDrag('bezier-remodel', '25 control points (degree 2, L = 12)', rowsCSV(wave(25)));
  await importAndDrag('knot-modification', '16 control points', rowsCSV(wave(16)));
});

test('noisy-data: 2000 pasted CSV points, 200 generated points', () => attempts(async () => {
  const t = await openDemo('noisy-data');
  const pts = Array.from({ length: 2000 }, (_, i) => [i / 100, Math.round((Math.sin(i / 150) + 0.1 * Math.sin(i * 7.1)) * 1000) / 1000]);
  await t.page.$eval('textarea.csv-input', (e, v) => { e.value = v; }, rowsCSV(pts));
  record('noisy-data', 'paste 2000 CSV points', await measure(t, () => t.page.$eval('textarea.csv-input', (e) => e.closest('.ctl').querySelector('button').click())));
  assert.equal(await t.page.$eval('.data-import-error', (e) => e.hidden), true, 'the CSV was accepted');
  await t.page.$$eval('.ctl-segments label', (ls) => ls.find((l) => l.textContent === 'known curve + noise').click());
  record('noisy-data', 'points slider to 200', await measure(t, () => t.setInput('input[name="count"]', 200)));
  t.assertClean();
  await t.close();
}));

test('surface demos with their maximum grids', async () => {
  await importAndDrag('b2-surfaces', '32 × 32 grid', gridJSON(32, 32), { drag: false });
  await importAndDrag('quasi-cubic-surfaces', '32 × 32 control net', gridJSON(32, 32), { drag: false });
  await attempts(async () => {
  const t = await openDemo('criss-cross-basis');
  record('criss-cross-basis', 'm = n = 10', await measure(t, async () => { await t.setInput('#' + await t.page.getByLabel('cells in u (m)').getAttribute('id'), 10); await t.setInput('#' + await t.page.getByLabel('cells in v (n)').getAttribute('id'), 10); }));
  t.assertClean();
  await t.close();
  });
});

/** Drags a network control point with the mouse in `steps` moves (the 3D view's own drag). */
async function dragNetworkPoint(t, set, index, dx, dy, steps = 10) {
  const VIEW = 'canvas[data-plot="networks"]';
  const box = await t.page.locator(VIEW).boundingBox();
  const p = await t.page.$eval(VIEW, (c, [s, i]) => c.splineView.screenPosition(s, i), [set, index]);
  assert.ok(p, `point ${set}[${index}] on screen`);
  await t.page.mouse.move(box.x + p[0], box.y + p[1]);
  await t.page.mouse.down();
  for (let i = 1; i <= steps; i++) {
    await t.page.mouse.move(box.x + p[0] + dx * i / steps, box.y + p[1] + dy * i / steps);
    await t.page.waitForTimeout(16);
  }
  await t.page.mouse.up();
}

const NETWORK = Number(process.env.MAIN_THREAD_NETWORK || 30);   // MAX_CELLS of www/demos/curve-networks.js
test(`curve-networks: the largest network (${NETWORK} × ${NETWORK} cells) at the finest tessellation, all surfaces, dragging`, () => attempts(async () => {
  const t = await openDemo('curve-networks');
  for (const k of ['S (criss-cross)', 'T (thin-plate)', 'G (Gordon)', 'GB (spline-blended)']) {
    const box = t.page.getByLabel(k, { exact: true });
    if (!(await box.isChecked())) await box.check();
  }
  const apply = await pasteData(t, networkJSON(NETWORK, NETWORK));
  record('curve-networks', `import a ${NETWORK} × ${NETWORK} network`, await measure(t, apply));
  assert.equal((await okText(t)).err, '');
  const slider = '#' + await t.page.getByLabel('Tessellation').getAttribute('id');
  const max = await t.page.$eval(slider, (e) => e.max);
  record('curve-networks', `tessellation to ${max} × ${max}`, await measure(t, () => t.setInput(slider, max)));
  record('curve-networks', `drag a point (${NETWORK}², ${max}²)`, await measure(t, () => dragNetworkPoint(t, 'net-P', 7, 20, -40)));
  // the limits are stated next to the controls, and a larger network is refused with a message naming the field
  const hints = await t.page.$$eval('.ctl-hint', (e) => e.map((x) => x.textContent).join('\n'));
  assert.match(hints, new RegExp(`Up to ${NETWORK} × ${NETWORK} cells \\(${NETWORK + 1} curves each way\\)`));
  assert.match(hints, /Up to 96 × 96 samples per surface/);
  const before = await t.page.$eval('.ctl-table', (e) => e.textContent);
  const apply2 = await pasteData(t, networkJSON(NETWORK + 1, 4));
  await apply2();
  const { err } = await okText(t);
  assert.match(err, new RegExp(`^network: at most ${NETWORK} × ${NETWORK} cells .* this one has ${NETWORK + 1} × 4 cells`));
  assert.equal(await t.page.$eval('.ctl-table', (e) => e.textContent), before, 'the refused network changed nothing');
  t.assertClean();
  await t.close();
}));

test('curve-networks: the drawing from the worker is the drawing computed here, pixel for pixel', async () => {
  const shots = {};
  for (const mode of ['here', 'worker']) {
    const context = await H.browser.newContext({ viewport: { width: 1366, height: 900 } });
    await context.addInitScript((m) => { window.splinelabCompute = m; }, mode);
    const t = await H.open('#curve-networks', { context });
    const apply = await pasteData(t, networkJSON(12, 9));
    await apply();
    await t.page.waitForFunction(() => !document.querySelector('[data-computing="true"]'), null, { timeout: 30000 });
    await t.frames(3);
    const workers = await t.page.evaluate(() => performance.getEntriesByType('resource').filter((e) => e.name.endsWith('/compute-worker.js')).length);
    assert.equal(workers > 0, mode === 'worker', `${mode}: the worker ${mode === 'worker' ? 'computed' : 'was not used'}`);
    shots[mode] = { png: await t.page.$eval('canvas[data-plot="networks"]', (c) => c.splineView.toDataURL()), numbers: await t.page.$eval('.ctl-table', (e) => e.textContent) };
    t.assertClean();
    await t.close(); await context.close();
  }
  assert.equal(shots.worker.numbers, shots.here.numbers, 'the same norms');
  assert.ok(shots.worker.png === shots.here.png, 'the same pixels');
});

test('the compute kit: results from the worker, the latest request wins, Cancel ends the work, API errors keep their field', async () => {
  const t = await openDemo('curve-networks');
  const out = await t.page.evaluate(async () => {
    const { computeClient } = await import('./lib/compute-client.js');
    const { loadWasm } = await import('./lib/host.js');
    const wasm = await loadWasm('curve-networks');
    const status = document.createElement('p');
    document.body.append(status);
    const cc = computeClient({ demoId: 'curve-networks', wasm, status });
    const network = wasm.networkExample({ name: 'dome10' });
    const call = (density) => [{ fn: 'networkSurfaces', args: { network, samplesU: density, samplesV: density, surfaces: ['S'], norms: false } }];
    // three requests at once: the first computes, the second is superseded by the third
    const [a, b, c] = await Promise.all([cc.run(call(16)), cc.run(call(24)), cc.run(call(32))]);
    const here = cc.runHere(call(32))[0].surfaces.S.points;
    const same = c[0].surfaces.S.points.length === here.length && c[0].surfaces.S.points.every((x, i) => x === here[i]);
    // a request cancelled while it computes resolves to null, the line says nothing, and the next one still works
    const p = cc.run(call(96));
    const busyWhile = status.querySelector('[data-computing]').dataset.computing;
    cc.cancel();
    const cancelled = await p;
    const busyAfter = status.querySelector('[data-computing]').dataset.computing;
    const again = await cc.run(call(16));
    let error = null;
    try { await cc.run([{ fn: 'networkSurfaces', args: { network, samplesU: -3 } }]); } catch (e) { error = { field: e.field, kind: e.kind, message: e.message }; }
    const transferred = c[0].surfaces.S.points instanceof Float64Array || c[0].surfaces.S.points instanceof Float32Array;
    cc.destroy();
    return { a: a && a[0].surfaces.S.points.length, b, c: c && c[0].surfaces.S.points.length, same, busyWhile, cancelled, busyAfter, again: again && again[0].surfaces.S.points.length, error, transferred };
  });
  assert.equal(out.a, 3 * 16 * 16, 'the first request was computed');
  assert.equal(out.b, null, 'the waiting request was superseded by a newer one');
  assert.equal(out.c, 3 * 32 * 32, 'the newest request was computed');
  assert.ok(out.same, 'the worker computed exactly what the page computes');
  assert.ok(out.transferred, 'typed arrays came back');
  assert.equal(out.busyWhile, 'true');
  assert.equal(out.cancelled, null, 'a cancelled request resolves to null');
  assert.equal(out.busyAfter, 'false');
  assert.equal(out.again, 3 * 16 * 16, 'a fresh worker after Cancel');
  assert.ok(out.error && out.error.field && out.error.kind, `the API error keeps field and kind: ${JSON.stringify(out.error)}`);
  t.assertClean();
  await t.close();
});

// What still blocks, named, with what it measured (ms of the page's scripts in one frame on 2026-11-26, a shared
// 2-core machine at load 11–13, so indicative) and a ceiling (about twice the worst measured): a blocking frame
// passes only when its scripts over the budget match an entry here (demo, action, the script's invoker) and stay
// under its ceiling; anything else fails. Before the worker, a curve-networks drag at 30 × 30 cells, 96², spent
// 300 ms in one animation-frame callback (networkSurfaces on the main thread): not tolerated below.
const KNOWN = [
  // curve-networks: the computing is in the worker; what remains on the page
  { demo: 'curve-networks', action: /./, invoker: /^Worker\.onmessage$/, measured: '23–208', ceiling: 400,
    why: 'drawing a result of the worker: View3D.setMesh of four 96² meshes with isolines, the side-by-side copies' },
  { demo: 'curve-networks', action: /^drag/, invoker: /^FrameRequestCallback$/, measured: '5–76', ceiling: 150,
    why: 'a drag frame: networkRepair of the 30 × 30 network and its 62 curves drawn on each of the four copies' },
  { demo: 'curve-networks', action: /^import/, invoker: /^BUTTON\.onclick$/, measured: '62–218', ceiling: 400,
    why: 'importing: JSON.parse of the network, networkCompatibility and networkRepair (the network is needed here)' },
  // every demo: the shell's debounced save 200 ms after a change (www/app.js writeHash: the state deflated into the
  // link, localStorage, the Export row asking the demo for its exports): not moved in this change
  { demo: /./, action: /./, invoker: /^(TimerHandler:setTimeout|Response\.arrayBuffer\.then)$/, measured: '51–243', ceiling: 400,
    why: 'timers: the shell saving the state after a change (app.js writeHash, the Export row refresh); in criss-cross-basis also its deferred refreshControls' },
];
const matches = (want, v) => (want instanceof RegExp ? want.test(v) : want === v);
/** The frames of measurement `r` whose scripts spent over the budget in work not listed in KNOWN. */
function blockedFrames(r) {
  return r.frames.filter((f) => f.script > BUDGET_MS && f.scripts.filter((x) => !known(r, x)).reduce((a, x) => a + x.duration, 0) > BUDGET_MS);
}
const known = (r, x) => KNOWN.some((k) => matches(k.demo, r.demo) && k.action.test(r.action) && k.invoker.test(x.invoker) && x.duration <= k.ceiling);

test('no main-thread task over 50 ms of the page\'s own work in any demo at its largest sizes', () => {
  if (process.env.MAIN_THREAD_TABLE) {
    console.log('| demo | action | longest task (ms) | tasks > 50 ms | most script in a frame (ms) | longest rendering (ms) | scripts | attempt |\n| --- | --- | --- | --- | --- | --- | --- | --- |');
    for (const r of results) console.log(`| ${r.demo} | ${r.action} | ${r.longest} | ${r.over} | ${r.script} | ${r.render} | ${r.worst} | ${r.attempt ?? 1} |`);
    console.log('Known (listed):\n' + KNOWN.map((k) => `- ${k.demo} ${k.action} ${k.invoker}: ${k.measured} ms (ceiling ${k.ceiling}): ${k.why}`).join('\n'));
  }
  // a long task is the page's own work when the long animation frame it belongs to spent over 50 ms in the page's
  // scripts (event handlers, animation-frame callbacks, timers, worker messages: JavaScript and the wasm it calls).
  // Frames whose time went to rendering only (style, layout, paint, the commit that waits for the WebGL frame,
  // which Chromium rasterises in software in this headless setup) are in the table, not in this check.
  const blocked = [];
  for (const r of results) {
    for (const f of blockedFrames(r)) blocked.push(`${r.demo}: ${r.action}: ${Math.round(f.script)} ms of scripts in one frame (${f.scripts.map((x) => `${x.invoker} ${x.duration}`).join('; ')}), ${firstAttemptOnly(r) ? 'first attempt' : `best of ${ATTEMPTS} attempts`}`);
  }
  assert.deepEqual(blocked, [], 'main-thread work over 50 ms in one frame');
});
