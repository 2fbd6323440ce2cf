// The "Knot modification" demo (Juhász–Hoffmann): moving the knot moves the tracked points along their paths, the
// extend switch lets the knot pass its neighbours, the surface tab moves two knots; no console error.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

const CURVE = 'canvas[data-plot="curve"]';
const KNOTS = 'canvas[data-plot="knots"]';
const SURFACE = 'canvas[data-plot="surface"]';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

const readout = (t) => t.page.$$eval('.ctl-table tbody tr', (rows) => rows.map((r) => r.textContent));
/** The tracked-point table as numbers [u, x, y]. */
const cells = (t) => t.page.$$eval('.ctl-table tbody tr', (rows) => rows.map((r) => [...r.children].map((c) => Number(c.textContent.replace('−', '-')))));
const knotHandle = async (t) => (await t.handles(KNOTS)).find((x) => x.name === 'moving knot').point;
/** The range input of the slider whose label starts with `label`. */
const sliderOf = (label) => `xpath=//label[starts-with(normalize-space(.), "${label}")]/ancestor::div[contains(@class,"ctl-slider")]//input[@type="range"]`;

test('draws the curve, the knot line and the tracked points', async () => {
  const t = await H.open('#knot-modification');
  const rows = await readout(t);
  assert.equal(rows.length, 3, 'three tracked points by default');
  const blank = await t.page.$eval(CURVE, (c) => { const e = document.createElement('canvas'); e.width = c.width; e.height = c.height; return e.toDataURL(); });
  assert.notEqual(await t.page.$eval(CURVE, (c) => c.toDataURL()), blank);
  assert.deepEqual(await knotHandle(t), [2.4, 0]);
  const info = await t.text('.km-info');
  assert.match(info, /spans 3…7/);
  assert.match(info, /uₚ → −∞ gives d₅|u₅ → −∞ gives d₅/);   // plain text with Unicode indices (a live region)
  assert.match(info, /u₅ → \+∞ gives d₁/);
  await t.screenshot('knot-modification');
  t.assertClean();
  await t.close();
});

test('dragging the knot moves the points along their paths and changes the drawing', async () => {
  const t = await H.open('#knot-modification');
  const rows0 = await readout(t);
  const before = await t.canvasHash(CURVE);
  await t.dragWorld(KNOTS, [2.4, 0], [1.3, 0]);
  const [x] = await knotHandle(t);
  assert.ok(Math.abs(x - 1.3) < 0.05, `knot moved to ${x}`);
  const rows1 = await readout(t);
  assert.notDeepEqual(rows1, rows0, 'tracked points moved');
  assert.notEqual(await t.canvasHash(CURVE), before);
  // without "extend" the knot stops at its neighbour u_4 = 1
  await t.dragWorld(KNOTS, [1.3, 0], [-1.5, 0]);
  assert.equal((await knotHandle(t))[0], 1);
  await t.waitHash((h) => h.startsWith('#knot-modification/'));
  t.assertClean();
  await t.close();
});

test('the slider and the extend switch: the knot passes its neighbours, the paths change', async () => {
  const t = await H.open('#knot-modification');
  const before = await t.canvasHash(CURVE);
  await t.setInput(sliderOf('Moving knot'), 2.9);
  assert.deepEqual(await knotHandle(t), [2.9, 0]);
  const near = await cells(t);
  const mid = await t.canvasHash(CURVE);
  assert.notEqual(mid, before);
  await t.page.click('label:text-is("Extend: let the knot pass its neighbours")');
  await t.frames(3);
  const extended = await t.canvasHash(CURVE);
  assert.notEqual(extended, mid, 'extended paths are drawn');
  const max = await t.page.$eval(sliderOf('Moving knot'), (e) => Number(e.max));
  assert.ok(max > 3 + 10, `the slider reaches past u_{p+1}: ${max}`);
  await t.setInput(sliderOf('Moving knot'), 14);
  assert.deepEqual(await knotHandle(t), [14, 0]);
  assert.match(await t.text('.km-info'), /extended path/);
  // far to the right the tracked points approach d_{p−k} = d_1 = (1, 2.4)
  const far = await cells(t);
  assert.equal(far.length, 3);
  far.forEach(([, x, y], j) => {
    const [, x0, y0] = near[j];
    const d = Math.hypot(x - 1, y - 2.4), d0 = Math.hypot(x0 - 1, y0 - 2.4);
    assert.ok(d < 0.4 * d0, `point ${j} approaches d1 = (1, 2.4): ${d0} → ${d}`);
  });
  t.assertClean();
  await t.close();
});

test('tracking a point in every affected span', async () => {
  const t = await H.open('#knot-modification');
  const before = await t.canvasHash(CURVE);
  await t.page.click('label:text-is("Track one point in every affected span")');
  await t.frames(3);
  const rows = await cells(t);
  assert.equal(rows.length, 5, 'spans 3…7 of the order-4 curve with p = 5');
  assert.deepEqual(rows.map((r) => r[0]), [0.5, 1.5, 2.5, 3.5, 4.5]);
  assert.notEqual(await t.canvasHash(CURVE), before);
  t.assertClean();
  await t.close();
});

test('surface tab: moving v_q changes the path-surface drawing', async () => {
  const t = await H.open('#knot-modification');
  await t.page.click('.ctl-segments label:text-is("Surface")');
  await t.frames(3);
  assert.equal(await t.page.$eval(SURFACE, (c) => c.offsetParent !== null), true, 'surface plot shown');
  const before = await t.canvasHash(SURFACE);
  await t.setInput(sliderOf('Knot v'), 1.2);
  assert.notEqual(await t.canvasHash(SURFACE), before);
  assert.match(await t.text('.km-surface ~ * .ctl-hint, .demo-controls'), /path-surface/);
  await t.screenshot('knot-modification-surface');
  // one knot only: paths and the limit curves of Theorem 3
  const two = await t.canvasHash(SURFACE);
  await t.page.click('.ctl-segments label:text-is("only uₚ")');
  await t.frames(3);
  assert.notEqual(await t.canvasHash(SURFACE), two);
  assert.match(await t.text('.demo-controls'), /Theorem 3/);
  assert.equal(await t.page.$eval(sliderOf('Knot v'), (e) => e.disabled), true);
  t.assertClean();
  await t.close();
});

test('axe finds no serious accessibility issue; a locked embed cannot move the knot', async () => {
  const t = await H.open('#knot-modification');
  assert.deepEqual(await t.axe(), []);
  await t.close();
  const t2 = await H.open('embed.html#knot-modification?locked=1');
  await t2.dragWorld(KNOTS, [2.4, 0], [1.5, 0]);
  assert.deepEqual(await knotHandle(t2), [2.4, 0]);
  t2.assertClean();
  await t2.close();
});
