// The "B2 surfaces" demo: draws the wireframe; a, the tensions, lifting a grid point and turning the view all
// redraw; the state survives a reload; no console error.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

const SURF = 'canvas[data-plot="surface"]';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

test('draws the surface and the grid', async () => {
  const t = await H.open('#b2-surfaces');
  const blank = await t.page.$eval(SURF, (c) => { const e = document.createElement('canvas'); e.width = c.width; e.height = c.height; return e.toDataURL(); });
  assert.notEqual(await t.page.$eval(SURF, (c) => c.toDataURL()), blank);
  assert.match(await t.text('.ctl-readout-value'), /u ∈ \[0, 3\], v ∈ \[0, 3\]/);
  await t.screenshot('b2-surfaces');
  t.assertClean();
  await t.close();
});

test('a, tension, lifting a point and turning redraw the surface', async () => {
  const t = await H.open('#b2-surfaces');
  let h = await t.canvasHash(SURF);
  for (const [sel, v] of [['input[name="a"]', 1 / 6], ['input[name="tu"]', 0.35], ['input[name="lift"]', 1.5], ['input[name="yaw"]', 20], ['input[name="size"]', 10]]) {
    await t.setInput(sel, v);
    const h2 = await t.canvasHash(SURF);
    assert.notEqual(h2, h, `${sel} redraws`);
    h = h2;
  }
  assert.match(await t.text('.ctl-readout-value'), /u ∈ \[0, 5\]/);
  await t.page.getByRole('radio', { name: 'chord' }).evaluate((el) => el.click());
  await t.frames(3);
  assert.notEqual(await t.canvasHash(SURF), h);
  await t.page.getByLabel('Data', { exact: true }).selectOption({ label: 'step (overshoot test)' });
  await t.frames(3);
  await t.waitHash((x) => x.startsWith('#b2-surfaces/'));
  await new Promise((ok) => setTimeout(ok, 400));
  const url = t.page.url();
  const final = await t.canvasHash(SURF);
  t.assertClean();
  await t.close();
  const t2 = await H.open(url.slice(url.indexOf('#')));
  assert.equal(await t2.canvasHash(SURF), final, 'the link restores the same picture');
  t2.assertClean();
  await t2.close();
});
