// The bi-degree remodelling (Gânscă–Coman–Ţămbulea §4.2) in the Bézier remodelling demo's surface tab:
// the tab draws G*, the per-column α_{k,l} (eq. 17) change the drawing and the link, the link restores it,
// and every readout (jumps across the break lines, corners kept) is a finite number equal to what the API
// (pkg-node's bezierRemodelSurfaceBi, called here with the state read from the page) returns, within 1e-12.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';
import { startHarness } from './harness.mjs';

const require = createRequire(import.meta.url);
const sl = require(join(dirname(fileURLToPath(import.meta.url)), '..', '..', 'pkg-node/splinelab.js'));

const SURFACE = 'canvas[data-plot="surface"]';
// the demo's net: the §4 table with its v-patch split at v = 1 (written out here, not imported from the demo)
const NET = [
  [[0, 0, 3], [0, 1, 2], [0, 2, 1.5], [0, 3, 1], [0, 4, 3]],
  [[1, 0, 1], [1, 1, 4], [1, 2, 3], [1, 3, 2], [1, 4, 4]],
  [[2, 0, 2.5], [2, 1, 3], [2, 2, 2], [2, 3, 1], [2, 4, 3]],
  [[3, 0, 4], [3, 1, 2], [3, 2, 1], [3, 3, 0], [3, 4, 2]],
  [[4, 0, 2.5], [4, 1, 3], [4, 2, 2], [4, 3, 1], [4, 4, 2.5]],
  [[5, 0, 1], [5, 1, 4], [5, 2, 3], [5, 3, 2], [5, 4, 3]],
  [[6, 0, 3], [6, 1, 0], [6, 2, 0.5], [6, 3, 1], [6, 4, 2]],
];

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

async function openBi(route = '#bezier-remodel') {
  const t = await H.open(route);
  if (!(await t.state()).bi.on || (await t.state()).tab !== 'surface') {
    await t.page.click('.ctl-segments label:text-is("Surface (§4)")');
    await t.page.click('.ctl-segments label:text-is("Bi-degree, u and v (§4.2)")');
  }
  await t.frames(3);
  return t;
}
const api = (b) => sl.bezierRemodelSurfaceBi({ points: NET, breaksU: [0, 1, 2, 3], breaksV: [0, 1, 2], degreeU: 2, degreeV: 2, alphas: b.alphas, betas: b.betas, r: b.r, s: b.s, enforce: b.enforce, samplesU: 3, samplesV: 3 });
const cells = (t, role) => t.page.$$eval(`[data-role="${role}"] tbody tr`, (rows) => rows.map((r) => Array.from(r.querySelectorAll('td'), (c) => Number(c.dataset.value))));
const close = (a, b, what) => assert.ok(Number.isFinite(a) && Math.abs(a - b) <= 1e-12, `${what}: page ${a}, API ${b}`);

/** Every readout on the page equals the API's result for the page's state; returns that result. */
async function readoutsMatchApi(t) {
  const st = await t.state();
  const r = api(st.bi);
  for (const [role, want] of [['bi-continuity-u', r.continuityU], ['bi-continuity-v', r.continuityV]]) {
    const got = await cells(t, role);
    assert.equal(got.length, want.length, `${role}: one row per interior break line`);
    got.forEach((row, j) => {
      assert.equal(row.length, want[j].length, `${role} row ${j}`);
      row.forEach((x, i) => close(x, want[j][i], `${role}[${j}][${i}]`));
    });
  }
  // corners kept: b*_{3I,3J} = b_{2I,2J}, measured from the API's control net
  let gap = 0;
  for (let I = 0; I <= 3; I++) for (let J = 0; J <= 2; J++) {
    const q = 3 * (3 * I * r.cols + 3 * J), p = NET[2 * I][2 * J];
    gap = Math.max(gap, Math.hypot(r.controlPoints[q] - p[0], r.controlPoints[q + 1] - p[1], r.controlPoints[q + 2] - p[2]));
  }
  close(Number(await t.page.$eval('[data-readout="bi-corners"]', (e) => e.dataset.value)), gap, 'corner gap');
  assert.ok(gap <= 1e-12, `corners kept (gap ${gap})`);
  return r;
}

test('the surface tab shows the bi-degree surface; readouts equal the API; C¹ in u and v, corners kept', async () => {
  const t = await openBi();
  const st = await t.state();
  assert.equal(st.bi.on, true);
  assert.equal(await t.page.isVisible('.bi-surface-controls'), true);
  assert.equal(await t.page.isVisible('text=Jumps of ∂ⁱG*/∂uⁱ across the joint lines'), false, 'the §4.1 table is hidden');
  const r = await readoutsMatchApi(t);
  assert.equal(r.degreeU, 3); assert.equal(r.degreeV, 3);
  for (const row of [...r.continuityU, ...r.continuityV]) assert.ok(row[0] < 1e-12 && row[1] < 1e-12, `C¹: ${row}`);
  assert.ok(Math.max(...r.continuityU.map((x) => x[2])) > 1e-3, 'd₂ jumps across u (the class is C¹, not C²)');
  // fixed entries: α₁⁽ᴵ⁾ (I ≥ 1) by eq. (9); columns 1 and 3 follow column 2 (the break line v = 1)
  const free = await t.page.$$eval('[data-bi-alpha]', (els) => els.map((e) => [e.dataset.biAlpha, e.dataset.free]));
  for (const [key, f] of free) assert.equal(f, String(!(key.startsWith('1,1') || key.startsWith('2,1'))), key);
  await t.page.click('[data-bi-alpha] >> xpath=ancestor::section[1] >> label:text-is("1")');
  await t.frames(2);
  assert.deepEqual(await t.page.$$eval('[data-bi-alpha]', (els) => els.map((e) => e.dataset.free)), Array(6).fill('false'));
  assert.match(await t.text('[data-role="bi-column-hint"]'), /Column 1 follows column 2/);
  await t.screenshot('bezier-remodel-bi');
  assert.deepEqual(await t.axe(), [], 'no serious accessibility violation');
  t.assertClean();
  await t.close();
});

test('changing α_{k,l} of one column changes the drawing, the readouts and the link; the link restores it', async () => {
  const t = await openBi();
  const h0 = await t.canvasHash(SURFACE);
  const link0 = await t.flushState();
  await t.setInput('[data-bi-alpha="1,2"] input[type=range]', 0.12); // α₂⁽¹⁾ of column 0
  const st = await t.state();
  assert.equal(st.bi.col, 0);
  assert.equal(st.bi.alphas[0][1][1], 0.12);
  assert.ok(Math.abs(st.bi.alphas[0][2][0] - 0.88) < 1e-15, 'α₁⁽²⁾ = 1 − α₂⁽¹⁾ (eq. 9)');
  assert.deepEqual(st.bi.alphas[2], [[0.6, 0.15], [0.85, 0.4], [0.6, 0.5]], 'other columns unchanged');
  const h1 = await t.canvasHash(SURFACE);
  assert.notEqual(h1, h0, 'the drawing changed');
  const r1 = await readoutsMatchApi(t);
  const link1 = await t.flushState();
  assert.notEqual(link1, link0, 'the link changed');
  // the surface itself changed (not only the net): G* differs from the default at an interior sample
  const r0 = api((await (async () => { const d = structuredClone(st.bi); d.alphas[0][1][1] = 0.3; d.alphas[0][2][0] = 0.7; return d; })()));
  assert.ok(Math.max(...r1.controlPoints.map((x, i) => Math.abs(x - r0.controlPoints[i]))) > 1e-3);
  const u1 = await cells(t, 'bi-continuity-u');
  await t.close();

  const t2 = await openBi(link1);
  assert.deepEqual((await t2.state()).bi, st.bi, 'the link restores the bi-degree state');
  assert.deepEqual(await cells(t2, 'bi-continuity-u'), u1);
  assert.equal(await t2.page.$eval('[data-bi-alpha="1,2"] input[type=range]', (e) => Number(e.value)), 0.12);
  await readoutsMatchApi(t2);
  const h1r = await t2.canvasHash(SURFACE);
  t2.assertClean();
  await t2.close();
  // restored drawings (same path: from a link): the changed link draws differently from the default one
  const t3 = await openBi(link0);
  assert.notEqual(await t3.canvasHash(SURFACE), h1r, 'the link carries the changed surface');
  await t3.close();
});

test('without eq. (9) a β breaks C¹ across v = 1, and the jump shown is the API’s', async () => {
  const t = await openBi();
  await t.page.click('text=Enforce eq. (9) in u and v');
  await t.frames(2);
  await t.setInput('[data-bi-beta="1,1"] input[type=range]', 0.3); // β₁⁽¹⁾ free now: 0.7 → 0.3
  const r = await readoutsMatchApi(t);
  assert.ok(r.continuityV[0][1] > 0.1, `kink across v = 1: ${r.continuityV[0][1]}`);
  assert.equal((await t.state()).bi.enforce, false);
  t.assertClean();
  await t.close();
});

test('a damaged bi-degree state in the link falls back to valid values', async () => {
  const bad = { tab: 'surface', bi: { on: true, col: 99, alphas: [[[2, -1]]], betas: [[0.5, 2], [-1, 0.5]], r: 7, s: -3, enforce: true } };
  const payload = 'v0.' + Buffer.from(JSON.stringify(bad)).toString('base64url');
  const t = await openBi(`#bezier-remodel/${payload}`);
  const st = await t.state();
  assert.equal(st.bi.on, true);
  assert.equal(st.bi.col, 4);
  assert.equal(st.bi.alphas.length, 5);
  assert.equal(st.bi.r, 1); assert.equal(st.bi.s, 1);
  assert.deepEqual(st.bi.betas[0], [0.5, 0.999], 'β clamped into (0, 1)');
  await readoutsMatchApi(t);
  t.assertClean();
  await t.close();
});
