// The "Criss-cross basis" demo: draws B_ij with its support, dragging a knot line or changing i changes the
// drawing and the numbers, picking a cell shows its BB ordinates, no console error.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

const DOMAIN = 'canvas[data-plot="domain"]';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

const knots = async (t, name) => (await t.handles(DOMAIN)).filter((x) => x.name === name).map((x) => x.point);
const table = (t) => t.page.$$eval('.ctl-table tbody tr', (rows) => rows.map((r) => [r.querySelector('th').textContent, Number(r.querySelector('td').textContent)]));
const centre = (t) => t.page.$eval('.ctl-readout-value', (e) => e.textContent);

test('draws B_ij, its support and the BB ordinates of the picked cell', async () => {
  const t = await H.open('#criss-cross-basis');
  const blank = await t.page.$eval(DOMAIN, (c) => { const e = document.createElement('canvas'); e.width = c.width; e.height = c.height; return e.toDataURL(); });
  assert.notEqual(await t.page.$eval(DOMAIN, (c) => c.toDataURL()), blank);
  assert.ok(await t.page.$('.cc-view3d canvas'), 'the 3D view is there');
  assert.equal((await knots(t, 'u knot')).length, 4);
  assert.equal((await knots(t, 'v knot')).length, 3);
  const rows = await table(t);
  assert.equal(rows.length, 13);
  // B_32 on the default knots: the centre value (σ′_3 + σ_4 + τ′_2 + τ_3)/4
  const u = [0, 0.12, 0.4, 0.62, 0.8, 1], v = [0, 0.3, 0.45, 0.75, 1];
  const h = (x, r) => x[r] - x[r - 1];
  const want = (h(u, 2) / (h(u, 2) + h(u, 3)) + h(u, 4) / (h(u, 3) + h(u, 4)) + h(v, 1) / (h(v, 1) + h(v, 2)) + h(v, 3) / (h(v, 2) + h(v, 3))) / 4;
  assert.ok(Math.abs(Number(await centre(t)) - want) < 1e-4, `centre ${await centre(t)} vs ${want}`);
  // the last row is the centre ordinate o of cell (3, 2) = the centre value
  assert.equal(rows[12][0], 'o');
  assert.ok(Math.abs(rows[12][1] - want) < 1e-4, `o = ${rows[12][1]}`);
  await t.screenshot('criss-cross-basis');
  t.assertClean();
  await t.close();
});

test('dragging a knot line changes the drawing, the numbers and the URL', async () => {
  const t = await H.open('#criss-cross-basis');
  const before = await t.canvasHash(DOMAIN);
  const c0 = await centre(t);
  const [, k2] = await knots(t, 'u knot'); // u_2 = 0.4 next to the centre of B_32
  await t.dragWorld(DOMAIN, k2, [0.5, k2[1]]);
  const after = await knots(t, 'u knot');
  assert.ok(Math.abs(after[1][0] - 0.5) < 0.02, `u_2 moved: ${after[1]}`);
  assert.notEqual(await t.canvasHash(DOMAIN), before);
  assert.notEqual(await centre(t), c0);
  await t.waitHash((x) => x.startsWith('#criss-cross-basis/'));
  t.assertClean();
  await t.close();
});

test('changing i moves the support; picking a cell shows its ordinates', async () => {
  const t = await H.open('#criss-cross-basis');
  const before = await t.canvasHash(DOMAIN);
  const rows0 = await table(t);
  // set i = 1 through the slider
  await t.page.$eval('input[type="range"]', (el) => { el.value = '1'; el.dispatchEvent(new Event('input', { bubbles: true })); el.dispatchEvent(new Event('change', { bubbles: true })); });
  assert.notEqual(await t.canvasHash(DOMAIN), before);
  assert.notDeepEqual(await table(t), rows0);
  // click into cell (1, 1): the corner cell of B_12 has only a few non-zero ordinates
  await t.page.$eval(DOMAIN, (c) => c.scrollIntoView({ block: 'center' }));
  const [x, y] = await t.page.$eval(DOMAIN, (c) => c.splinePlot.toScreen(0.05, 0.1));
  const box = await (await t.page.$(DOMAIN)).boundingBox();
  await t.page.mouse.click(box.x + x, box.y + y);
  const rows = await table(t);
  assert.equal(rows.length, 13);
  const nonzero = rows.filter((r) => r[1] !== 0).map((r) => r[0]);
  assert.ok(nonzero.length > 0 && nonzero.length < 13, rows.join('|'));
  t.assertClean();
  await t.close();
});
