// The sandbox runs the visitor's code off the page (issue 26 "sandbox", issue 30 item 2): in a Web Worker of an
// opaque-origin sandboxed iframe (www/lib/sandbox-runner.js, www/sandbox-frame.js, www/sandbox-worker.js).
//   - an endless loop leaves the page responsive (its animation frames keep coming, the code area takes typing);
//     Stop ends it with a message, and the next Run (a fresh worker) draws and prints the right numbers;
//   - a program that prints or draws without end (thousands of messages a second) leaves the page responsive too:
//     the page handles them in slices, and a run posts at most 5000 lines / 2000 drawings / 64 MB, then one note;
//   - the time limit ends a long loop with its message (the limit shortened through the test hook, same mechanism);
//   - a program cannot read what the site stored (localStorage, indexedDB, cookies, the page through parent/top),
//     cannot fetch the site, cannot navigate the page (top.location, parent.location, location.href, open()),
//     and still draws and prints.
// Every page call is bounded in time, so that the old in-page execution (a frozen tab) fails instead of hanging.
// Run: node --test tests/e2e/sandbox-isolation.test.mjs   (needs www/pkg and pkg-node: scripts/build-wasm.sh)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { startHarness, ROOT, OUT } from './harness.mjs';
import { formatValue } from '../../www/lib/sandbox-format.js';

const sl = createRequire(import.meta.url)(join(ROOT, 'pkg-node/splinelab.js'));

let H;
before(async () => { H = await startHarness(); mkdirSync(OUT, { recursive: true }); });
after(async () => { await H?.close(); });

/** `p`, or a rejection naming `what` after `ms` (a frozen page never answers). */
function within(ms, what, p) {
  let timer;
  return Promise.race([p, new Promise((_, no) => { timer = setTimeout(() => no(new Error(`${what}: no answer within ${ms} ms (is the page frozen?)`)), ms); })])
    .finally(() => clearTimeout(timer));
}
const evaluate = (t, fn, arg, ms = 4000) => within(ms, 'page.evaluate', t.page.evaluate(fn, arg));

/** Presses Run (the code already in the code area) and waits until that run has ended; its outcome and output. */
async function runNow(t, { ms = 20000 } = {}) {
  const n = await evaluate(t, () => Number(document.body.dataset.runs || 0));
  await t.page.click('#sb-run', { timeout: 4000 });
  await t.page.waitForFunction((k) => Number(document.body.dataset.runs || 0) > k && document.body.dataset.run !== 'running', n, { timeout: ms });
  return evaluate(t, () => ({
    run: document.body.dataset.run,
    output: document.getElementById('sb-output').textContent,
    note: document.getElementById('sb-error').hidden ? '' : document.getElementById('sb-error').textContent,
    status: document.getElementById('sb-status').textContent,
  }));
}

/** Coloured (curve) pixels of the curves' plot: grey axes and the white ground do not count. */
const inked = (t) => evaluate(t, () => {
  const c = document.querySelector('#sb-plot canvas');
  const px = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let n = 0;
  for (let i = 0; i < px.length; i += 4) if (Math.abs(px[i] - px[i + 1]) + Math.abs(px[i + 1] - px[i + 2]) > 60) n++;
  return n;
});

const ui = (t) => evaluate(t, () => {
  const run = document.getElementById('sb-run'), stop = document.getElementById('sb-stop');
  const r = stop.getBoundingClientRect();
  return { runDisabled: run.disabled, runText: run.textContent, stopVisible: !stop.hidden && r.width > 0, stopInView: r.bottom <= innerHeight && r.right <= innerWidth };
});

test('an endless loop leaves the page responsive; Stop ends it; then an example draws and prints the right numbers', async () => {
  for (const [name, viewport] of [['desktop', { width: 1366, height: 900 }], ['phone', { width: 390, height: 844 }]]) {
    const t = await H.open('sandbox.html', { viewport });
    assert.equal(await evaluate(t, () => window.splinelabSandbox.limitMs), 10000, 'the real limit is 10 s');
    assert.match((await t.page.textContent('#sb-isolation')).replace(/\s+/g, ' '), /cannot read the site's saved states or cookies.*navigate it.*stops after 10 s/s);
    await t.page.fill('#sb-code', 'print("into the loop");\nwhile (true) {}\n');
    await evaluate(t, () => { window.__frames = 0; const f = () => { window.__frames++; requestAnimationFrame(f); }; requestAnimationFrame(f); });
    await t.page.click('#sb-run');
    await t.page.waitForFunction(() => /into the loop/.test(document.getElementById('sb-output').textContent), null, { timeout: 10000 });
    // the page keeps drawing frames and takes typing while the loop runs
    const f0 = await evaluate(t, () => window.__frames);
    await new Promise((r) => setTimeout(r, 1000));
    const f1 = await evaluate(t, () => window.__frames);
    assert.ok(f1 - f0 >= 10, `${name}: the page drew ${f1 - f0} frames in 1 s of the endless loop`);
    await within(4000, 'typing', (async () => { await t.page.focus('#sb-code'); await t.page.keyboard.press('Control+End'); await t.page.keyboard.type('// typed'); })());
    assert.match(await t.page.inputValue('#sb-code', { timeout: 4000 }), /while \(true\) \{\}\n\/\/ typed$/, 'the code area took the typing');
    const running = await ui(t);
    assert.deepEqual(running, { runDisabled: true, runText: 'Running…', stopVisible: true, stopInView: true }, `${name}: while running`);
    assert.equal(await evaluate(t, () => document.body.dataset.run), 'running');
    await t.page.screenshot({ path: join(OUT, `sandbox-isolation-running-${name}.png`) });
    // Stop: a message, Run back
    await t.page.click('#sb-stop', { timeout: 4000 });
    const st = await evaluate(t, () => ({ run: document.body.dataset.run, note: document.getElementById('sb-error').textContent, hidden: document.getElementById('sb-error').hidden, status: document.getElementById('sb-status').textContent }));
    assert.equal(st.run, 'stopped');
    assert.equal(st.hidden, false);
    assert.match(st.note, /^Stopped after \d+\.\d s: you pressed Stop\./);
    assert.equal(st.status, 'Stopped.');
    assert.match(await t.page.textContent('#sb-output'), /^into the loop\n$/, 'what it printed before is kept');
    await t.page.waitForFunction(() => !document.getElementById('sb-run').disabled, null, { timeout: 10000 }); // the fresh worker
    const after = await ui(t);
    assert.deepEqual(after, { runDisabled: false, runText: 'Run', stopVisible: false, stopInView: true }, `${name}: after Stop`);
    await t.page.screenshot({ path: join(OUT, `sandbox-isolation-stopped-${name}.png`) });
    // the next Run: an example draws (pixels inked) and prints
    await t.page.selectOption('#sb-examples', 'bspline-basics');
    const ex = await runNow(t);
    assert.equal(ex.run, 'ok', ex.note);
    assert.match(ex.output, /^partition of unity at u = 1\.5: 1\n/);
    await t.frames(3);
    const ink = await inked(t);
    assert.ok(ink > 800, `${name}: the example's curve inked ${ink} pixels of the plot`);
    // the numbers printed are the module's (the same call in Node)
    const code = 'const c = sl.bsplineCurve({ points: [[0, 0], [1, 2], [3, -1], [4, 0]], samples: 5 });\nprint(c.points);\nprint(c.points[2] + c.points[3]);';
    await t.page.fill('#sb-code', code);
    const r = await runNow(t);
    const want = sl.bsplineCurve({ points: [[0, 0], [1, 2], [3, -1], [4, 0]], samples: 5 });
    assert.equal(r.output, `${formatValue(want.points)}\n${formatValue(want.points[2] + want.points[3])}\n`);
    assert.equal(r.output.split('\n')[1], '1.609375');
    t.assertClean();
    await t.close();
  }
});

test('a program that prints or draws without end leaves the page responsive; Stop ends it; the page says what it left out', async () => {
  const t = await H.open('sandbox.html');
  for (const [code, what] of [['let i = 0;\nwhile (true) print(i++);', 'prints'], ['while (true) plot([[0, 0], [1, 1]]);', 'drawings']]) {
    await t.page.fill('#sb-code', code);
    await evaluate(t, () => { window.__frames = 0; const f = () => { window.__frames++; requestAnimationFrame(f); }; requestAnimationFrame(f); });
    await t.page.click('#sb-run');
    await new Promise((r) => setTimeout(r, 1500));
    const frames = await evaluate(t, () => window.__frames);
    assert.ok(frames >= 5, `${what}: the page drew ${frames} frames in 1.5 s of the flood`); // (none when it froze; ~90 on an idle machine)
    // the cap is reached before Stop (on a loaded machine the worker may need more than 1.5 s for 5000 lines: CI printed 4404)
    await t.page.waitForFunction((w) => (w === 'prints'
      ? document.getElementById('sb-output').textContent.includes('… The code printed or drew more than this page shows')
      : window.splinelabSandbox.items.length >= 2000), what, { timeout: 20000 });
    const t0 = Date.now();
    await t.page.click('#sb-stop', { timeout: 4000 });
    assert.ok(Date.now() - t0 < 3000, `${what}: Stop answered after ${Date.now() - t0} ms`);
    const st = await evaluate(t, () => ({ run: document.body.dataset.run, lines: document.getElementById('sb-output').textContent.split('\n').length - 1, items: window.splinelabSandbox.items.length, out: document.getElementById('sb-output').textContent }));
    assert.equal(st.run, 'stopped');
    if (what === 'prints') {
      assert.equal(st.lines, 5001, 'the first 5000 lines and a note');
      assert.match(st.out, /^0\n1\n2\n/);
      assert.match(st.out, /\n4999\n… The code printed or drew more than this page shows \(5000 lines, 2000 drawings, 64 MB of data\): the rest is left out; the code went on running\.\n$/);
    } else assert.equal(st.items, 2000);
  }
  await t.page.fill('#sb-code', 'print(6 * 7);');
  const r = await runNow(t);
  assert.deepEqual([r.run, r.output], ['ok', '42\n']);
  t.assertClean();
  await t.close();
});

test('the time limit ends a long loop with its message; the next Run has a fresh worker', async () => {
  const t = await H.open('sandbox.html');
  await evaluate(t, () => { window.splinelabSandbox.limitMs = 1500; });
  await t.page.fill('#sb-code', 'globalThis.kept = 5;\nprint("looping");\nlet n = 0;\nwhile (true) n++;\n');
  const t0 = Date.now();
  const r = await runNow(t, { ms: 8000 });
  const secs = (Date.now() - t0) / 1000;
  assert.equal(r.run, 'limit');
  assert.match(r.note, /^Stopped: the code was still running after 1\.5 s, the time limit\./);
  assert.equal(r.status, 'Stopped at the time limit (1.5 s).');
  assert.equal(r.output, 'looping\n');
  assert.ok(secs >= 1.4 && secs < 6, `the run ended after ${secs.toFixed(1)} s`);
  await t.page.fill('#sb-code', 'print(typeof globalThis.kept, 6 * 7);');
  const r2 = await runNow(t);
  assert.equal(r2.run, 'ok');
  assert.equal(r2.output, 'undefined 42\n', 'a fresh worker: the stopped one\'s globals are gone');
  // a run that ends in time is not touched by the limit
  await t.page.fill('#sb-code', 'const t = Date.now(); while (Date.now() - t < 300) {}\nprint("done");');
  const r3 = await runNow(t);
  assert.deepEqual([r3.run, r3.output], ['ok', 'done\n']);
  t.assertClean();
  await t.close();
});

test('a program cannot read what the site stored, fetch the site or navigate the page, and still draws and prints', async () => {
  const t = await H.open('sandbox.html');
  // (the code area keeps its code in the hash, so the URL is compared without it)
  const doc = (u) => u.split('#')[0];
  const url0 = t.page.url();
  const navigations = [];
  t.page.on('framenavigated', (f) => { if (f === t.page.mainFrame() && doc(f.url()) !== doc(url0)) navigations.push(f.url()); });
  const popups = [];
  t.context.on('page', (p) => popups.push(p.url()));
  // what the site stored (a saved state), a cookie, an indexedDB database
  await evaluate(t, () => new Promise((ok, no) => {
    localStorage.setItem('splinelab-secret', 'S3CRET-LS');
    sessionStorage.setItem('splinelab-secret', 'S3CRET-SS');
    document.cookie = 'slsecret=S3CRET-COOKIE; path=/';
    window.__sameDocument = 'yes';
    const req = indexedDB.open('splinelab-secret', 1);
    req.onupgradeneeded = () => req.result.createObjectStore('S3CRET-IDB');
    req.onsuccess = () => { req.result.close(); ok(); };
    req.onerror = () => no(req.error);
  }));
  const origin = new URL(url0).origin;
  const code = `const got = {};
const tryIt = (name, f) => { try { got[name] = String(f()); } catch (e) { got[name] = 'error: ' + e.name; } };
tryIt('localStorage', () => localStorage.getItem('splinelab-secret'));
tryIt('sessionStorage', () => sessionStorage.getItem('splinelab-secret'));
tryIt('cookie', () => document.cookie);
tryIt('parent', () => parent.localStorage.getItem('splinelab-secret'));
tryIt('top', () => top.document.cookie);
got.indexedDB = await new Promise((ok) => { try { const r = indexedDB.open('splinelab-secret'); r.onsuccess = () => ok('opened: ' + [...r.result.objectStoreNames].join()); r.onerror = () => ok('error: ' + r.error.name); } catch (e) { ok('error: ' + e.name); } });
got.caches = await (async () => { try { return 'keys: ' + (await caches.keys()).join(); } catch (e) { return 'error: ' + e.name; } })();
got.fetch = await (async () => { try { const r = await fetch('${origin}/sandbox.html'); return 'status ' + r.status + ' ' + (await r.text()).length; } catch (e) { return 'error: ' + e.name; } })();
const leak = '${origin}/guide.html?leak=' + encodeURIComponent(JSON.stringify(got));
tryIt('top.location', () => { top.location.href = leak; });
tryIt('parent.location', () => { parent.location = leak; });
tryIt('location.href', () => { location.href = leak; });
tryIt('open', () => open(leak));
for (const [k, v] of Object.entries(got)) print(k + ' = ' + v);
plot([[0, 0], [1, 2], [2, 0]], { label: 'still drawn' });
print('still here', 2 + 2);`;
  await t.page.fill('#sb-code', code);
  const r = await runNow(t);
  await new Promise((ok) => setTimeout(ok, 500)); // a navigation would have started by now
  const got = Object.fromEntries(r.output.trim().split('\n').filter((l) => l.includes(' = ')).map((l) => l.split(' = ')));
  assert.equal(r.run, 'ok', r.note);
  assert.doesNotMatch(r.output, /S3CRET/, 'nothing the site stored reached the program');
  for (const k of ['localStorage', 'sessionStorage', 'cookie', 'parent', 'top', 'indexedDB', 'caches', 'fetch', 'top.location', 'parent.location', 'location.href', 'open']) {
    assert.match(got[k] ?? '', /^error: /, `${k}: ${got[k]}`);
  }
  assert.match(r.output, /still here 4\n$/);
  assert.equal(doc(t.page.url()), doc(url0), 'the page\'s URL is unchanged');
  assert.deepEqual(navigations, [], 'the page did not navigate');
  assert.deepEqual(popups, [], 'no window was opened');
  assert.equal(await evaluate(t, () => window.__sameDocument), 'yes', 'the same document');
  assert.equal(await evaluate(t, () => localStorage.getItem('splinelab-secret')), 'S3CRET-LS', 'the site\'s state is left as it was');
  await t.frames(3);
  assert.deepEqual(await evaluate(t, () => window.splinelabSandbox.items.map((i) => i.label)), ['still drawn']);
  assert.ok(await inked(t) > 200, 'the program\'s plot is drawn');
  // the refused fetch is reported by the browser (the frame's CSP): expected
  t.assertClean([/Refused to connect|violates the following Content Security Policy/]);
  await t.close();
});
