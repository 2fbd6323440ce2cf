// The "Quasi-cubic surfaces" demo: the sphere preset reads an exactness below 1e-12; presets, α and the local
// β* change the drawing (the WebGL view of www/lib/view3d.js); no console error.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

const canvasSel = async (t) => {
  await t.page.waitForSelector('canvas[data-plot="surface3d"]', { timeout: 20000 });
  return 'canvas[data-plot="surface3d"]';
};
const exactness = async (t) => Number(await t.text('[data-readout="exactness"] .ctl-readout-value'));
const slider = (label) => `xpath=//label[contains(., "${label}")]/ancestor::div[contains(@class,"ctl-slider")]//input[@type="range"]`;

test('sphere is exact; α breaks it; presets redraw', async () => {
  const t = await H.open('#quasi-cubic-surfaces');
  const C = await canvasSel(t);
  const e = await exactness(t);
  assert.ok(e < 1e-12, `sphere exactness ${e}`);
  await t.screenshot('quasi-cubic-surfaces');
  const h0 = await t.canvasHash(C);
  await t.setInput(slider('Shape parameter'), 0.6);
  assert.ok((await exactness(t)) > 1e-3, 'α = 0.6 is not a sphere');
  assert.notEqual(await t.canvasHash(C), h0);
  for (const name of ['Cylinder', 'Torus']) {
    await t.page.click(`.ctl-group label:text-is("${name}")`);
    await t.setInput(slider('Shape parameter'), 1);
    assert.ok((await exactness(t)) < 1e-12, `${name} exact at α = 1`);
  }
  await t.page.click('.ctl-group label:text-is("Bowl (Fig. 8)")');
  await t.frames(3);
  await t.screenshot('quasi-cubic-surfaces-bowl');
  t.assertClean();
  await t.close();
});

test('blended surface: the local β* changes the drawing', async () => {
  const t = await H.open('#quasi-cubic-surfaces');
  const C = await canvasSel(t);
  await t.page.click('.ctl-group label:text-is("Blended (Fig. 13)")');
  await t.frames(3);
  const h0 = await t.canvasHash(C);
  await t.setInput(slider('Local β*'), 0.1);
  assert.notEqual(await t.canvasHash(C), h0);
  await t.screenshot('quasi-cubic-surfaces-blended');
  t.assertClean();
  await t.close();
});
