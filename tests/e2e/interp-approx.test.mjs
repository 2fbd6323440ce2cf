// The "Interpolating vs approximating" demo: draws, the a slider and a dragged data point change the drawing,
// presets and toggles work, the state survives a reload, and nothing logs a console error.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

const CURVE = 'canvas[data-plot="curve"]';
const BASIS = 'canvas[data-plot="basis"]';
const KAPPA = 'canvas[data-plot="curvature"]';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

const dataPts = async (t) => (await t.handles(CURVE)).filter((x) => x.name === 'data point').map((x) => x.point);
const aux = async (t) => (await t.handles(CURVE)).filter((x) => x.name === 'auxiliary point').map((x) => x.point);
const readouts = (t) => t.page.$$eval('.ctl-readout-value', (els) => els.map((e) => e.textContent));

test('draws the curve, the basis functions and the curvature', async () => {
  const t = await H.open('#interp-approx');
  for (const sel of [CURVE, BASIS, KAPPA]) {
    const blank = await t.page.$eval(sel, (c) => { const e = document.createElement('canvas'); e.width = c.width; e.height = c.height; return e.toDataURL(); });
    assert.notEqual(await t.page.$eval(sel, (c) => c.toDataURL()), blank, `${sel} is drawn`);
  }
  assert.equal((await dataPts(t)).length, 7);
  assert.equal((await aux(t)).length, 4);
  const [tension, domain] = await readouts(t);
  assert.match(tension, /^0\.167(, 0\.167){7}$/);
  assert.match(domain, /n = 7/);
  await t.screenshot('interp-approx');
  t.assertClean();
  await t.close();
});

test('moving the a slider changes the curve (and the basis functions) but not the data', async () => {
  const t = await H.open('#interp-approx');
  const c0 = await t.canvasHash(CURVE), b0 = await t.canvasHash(BASIS);
  const pts = await dataPts(t);
  await t.setInput('input[name="a"]', 0.12);
  assert.notEqual(await t.canvasHash(CURVE), c0, 'curve redrawn');
  assert.notEqual(await t.canvasHash(BASIS), b0, 'basis redrawn');
  assert.deepEqual(await dataPts(t), pts);
  const out = await t.page.$eval('input[name="a"]', (e) => e.closest('.ctl').querySelector('input.ctl-number, output').value);
  assert.equal(Number(out), 0.12);
  // the curve at a = 1/6 is the B-spline overlay: switching the overlay off then changes nothing at a = 1/6…
  await t.setInput('input[name="a"]', 1 / 6);
  const h6 = await t.canvasHash(CURVE);
  await t.setInput('input[name="a"]', 0);
  assert.notEqual(await t.canvasHash(CURVE), h6);
  await t.waitHash((h) => h.startsWith('#interp-approx/'));
  t.assertClean();
  await t.close();
});

test('dragging a data point moves it and redraws; the URL restores it', async () => {
  const t = await H.open('#interp-approx');
  const pts = await dataPts(t);
  const c0 = await t.canvasHash(CURVE), k0 = await t.canvasHash(KAPPA);
  await t.dragWorld(CURVE, pts[2], [pts[2][0] + 0.3, pts[2][1] - 0.8]);
  const moved = await dataPts(t);
  assert.ok(Math.abs(moved[2][0] - (pts[2][0] + 0.3)) < 0.05 && Math.abs(moved[2][1] - (pts[2][1] - 0.8)) < 0.05, `W3 moved: ${moved[2]}`);
  assert.deepEqual(moved[4], pts[4]);
  assert.notEqual(await t.canvasHash(CURVE), c0);
  assert.notEqual(await t.canvasHash(KAPPA), k0);
  await t.waitHash((h) => h.startsWith('#interp-approx/'));
  await new Promise((ok) => setTimeout(ok, 400));
  const url = t.page.url();
  await t.close();
  const t2 = await H.open(url.slice(url.indexOf('#')));
  assert.deepEqual(await dataPts(t2), moved);
  t2.assertClean();
  await t2.close();
});

test('presets, automatic ends and toggles work without errors', async () => {
  const t = await H.open('#interp-approx');
  const click = (text) => t.page.getByRole('button', { name: text }).click();
  const c0 = await t.canvasHash(CURVE);
  await click('Fig. 6: a = −0.1 … 0.2');
  await t.frames(3);
  assert.notEqual(await t.canvasHash(CURVE), c0);
  assert.match(await t.text('.preset-row + .ctl-hint'), /Fig\. 6/);
  await click('Fig. 14: K = 20');
  await t.frames(3);
  assert.equal(await t.page.$eval('input[name="K"]', (e) => Number(e.value)), 20);
  const [, domain] = await readouts(t);
  assert.match(domain, /n = 6/);
  assert.match(await t.text('.preset-row + .ctl-hint'), /K = 20/);
  // automatic ends: the auxiliary points are recomputed from the data when a data point moves
  await t.page.getByLabel('Automatic ends').check();
  await t.frames(3);
  const before = await aux(t);
  const pts = await dataPts(t);
  await t.dragWorld(CURVE, pts[0], [pts[0][0] + 0.5, pts[0][1] + 0.5]);
  const after2 = await aux(t);
  assert.notDeepEqual(after2[0], before[0], 'W₋₁ follows the reflection');
  await t.page.getByLabel('How it is built').check();
  await t.page.getByLabel('Curvature comb').check();
  await t.page.getByRole('radio', { name: 'paper', exact: true }).evaluate((el) => el.click());
  await t.frames(3);
  const [tension] = await readouts(t);
  assert.doesNotMatch(tension, /^0\.167(, 0\.167)+$/, 'automatic tension changes the tensions');
  t.assertClean();
  await t.close();
});

test('the printed claim "a = 1/6, p = 0 gives the B-spline" is measured live: 0 on uniform knots, not on chord-length knots', async () => {
  const t = await H.open('#interp-approx');
  const claim = () => t.page.$eval('[data-readout="claim-bspline"] .ctl-readout-value', (e) => e.textContent);
  const m = /^off by ([\d.]+): fails$/.exec(await claim());
  assert.ok(m, await claim());
  assert.ok(Number(m[1]) > 0.01, `chord-length knots: the p = 0 even vertices are not the B-spline's (${m[1]})`);
  assert.ok(await t.page.$('[data-readout="claim-bspline"] + .ctl-hint a[href="papers.html#correction-000-bspline"]'), 'links the correction');
  // Knots: uniform (the radio of the "Knots" button group)
  await t.page.evaluate(() => {
    const fs = [...document.querySelectorAll('fieldset.ctl-group')].find((f) => f.querySelector('legend')?.textContent === 'Knots');
    const lab = [...fs.querySelectorAll('label')].find((l) => l.textContent.trim() === 'uniform');
    lab.click();
  });
  await t.page.waitForFunction(() => /^off by 0: holds$/.test(document.querySelector('[data-readout="claim-bspline"] .ctl-readout-value').textContent), null, { timeout: 5000 });
  t.assertClean();
  await t.close();
});
