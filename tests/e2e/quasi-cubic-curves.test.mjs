// The "Quasi-cubic curves" demo: draws; the ellipse preset reads a deviation below 1e-12 (measured by wasm)
// that grows when a vertex is dragged; the α slider changes the drawing; no console error.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

const CURVE = 'canvas[data-plot="curve"]';
const BASIS = 'canvas[data-plot="basis"]';
const ALPHA = '.ctl-slider input[type="range"]';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

const deviation = async (t) => {
  const s = await t.text('[data-readout="deviation"] .ctl-readout-value');
  return Number(s);
};
const choosePreset = async (t, label) => {
  await t.page.click(`.ctl-group label:text-is("${label}")`);
  await t.frames(3);
};

test('draws the curve and the basis; the α slider changes both', async () => {
  const t = await H.open('#quasi-cubic-curves');
  const c0 = await t.canvasHash(CURVE), b0 = await t.canvasHash(BASIS);
  await t.setInput(ALPHA, 2.5);
  assert.notEqual(await t.canvasHash(CURVE), c0, 'curve redrawn');
  assert.notEqual(await t.canvasHash(BASIS), b0, 'basis redrawn');
  await t.waitHash((hh) => hh.startsWith('#quasi-cubic-curves/'));
  await t.screenshot('quasi-cubic-curves');
  t.assertClean();
  await t.close();
});

test('ellipse preset: deviation below 1e-12, grows when a vertex is dragged', async () => {
  const t = await H.open('#quasi-cubic-curves');
  await choosePreset(t, 'Ellipse');
  const d = await deviation(t);
  assert.ok(Number.isFinite(d) && d < 1e-12, `ellipse deviation ${d}`);
  assert.match(await t.text('[data-readout="condition"] .ctl-readout-value'), /holds/);
  await t.screenshot('quasi-cubic-curves-ellipse');
  const pts = (await t.handles(CURVE)).map((x) => x.point);
  await t.dragWorld(CURVE, pts[0], [pts[0][0] + 0.6, pts[0][1] + 0.5]);
  const d2 = await deviation(t);
  assert.ok(d2 > 1e-3, `broken ellipse deviation ${d2}`);
  assert.match(await t.text('[data-readout="condition"] .ctl-readout-value'), /broken/);
  await t.screenshot('quasi-cubic-curves-broken');
  t.assertClean();
  await t.close();
});

test('circle, parabola and sine presets are exact too', async () => {
  const t = await H.open('#quasi-cubic-curves');
  for (const name of ['Circle', 'Parabola', 'Sine']) {
    await choosePreset(t, name);
    const d = await deviation(t);
    assert.ok(d < 1e-12, `${name} deviation ${d}`);
  }
  // moving α off 0 breaks the sine
  await t.setInput(ALPHA, 0.4);
  assert.ok((await deviation(t)) > 1e-4);
  t.assertClean();
  await t.close();
});

test('sine: dragging one point names the broken segments', async () => {
  const t = await H.open('#quasi-cubic-curves');
  await choosePreset(t, 'Sine');
  const pts = (await t.handles(CURVE)).map((x) => x.point);
  await t.dragWorld(CURVE, pts[3], [pts[3][0], pts[3][1] + 0.7]);
  assert.ok((await deviation(t)) > 1e-3);
  const text = await t.page.$eval('.ctl-section p.ctl-hint[aria-live]', (e) => e.textContent);
  assert.match(text, /segment 0 \(y\), segment 1 \(y\), segment 2 \(y\), segment 3 \(y\)\./);
  await t.screenshot('quasi-cubic-curves-sine-broken');
  t.assertClean();
  await t.close();
});
