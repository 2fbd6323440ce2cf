// The "Noisy data" demo: draws both fits and the error curve; noise, a, the CV button, the classic data sets and
// pasted CSV all work; no console error.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

const INTERP = 'canvas[data-plot="interp"]';
const APPROX = 'canvas[data-plot="approx"]';
const ERR = 'canvas[data-plot="error"]';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

const numbers = (t) => t.page.$$eval('.plot-numbers', (ps) => ps.map((p) => p.textContent));
const num = (s, label) => Number((s.match(new RegExp(`${label} ([0-9.]+)`)) || [])[1]);

test('draws both fits with their error numbers and the error curve', async () => {
  const t = await H.open('#noisy-data');
  const [n0, n1] = await numbers(t);
  assert.equal(num(n0, 'residual RMS'), 0, 'interpolation has zero residual');
  assert.ok(num(n1, 'residual RMS') > 0);
  assert.ok(num(n1, 'RMS') < num(n0, 'RMS'), `smoothing is closer to the true curve: ${n1} vs ${n0}`);
  assert.match(await t.text('.ctl-readout-value'), /sine \+ noise σ = 0\.2, draw 1/);
  // the error sweep and its readouts follow the first drawing (start-up, issue 13)
  await t.page.waitForFunction(() => [...document.querySelectorAll('.ctl-readout-value')].some((e) => /cross-validation picks a =/.test(e.textContent)), null, { timeout: 20000 });
  const cv = await t.page.$$eval('.ctl-readout-value', (e) => e.map((x) => x.textContent).join(' '));
  assert.match(cv, /cross-validation picks a = 0\.\d+/);
  await t.screenshot('noisy-data');
  t.assertClean();
  await t.close();
});

test('noise, a and the cross-validated choice change the drawing and the numbers', async () => {
  const t = await H.open('#noisy-data');
  const i0 = await t.canvasHash(INTERP), a0 = await t.canvasHash(APPROX), e0 = await t.canvasHash(ERR);
  const before = await numbers(t);
  await t.setInput('input[name="sigma"]', 0.4);
  assert.notEqual(await t.canvasHash(INTERP), i0);
  assert.notEqual(await t.canvasHash(ERR), e0);
  const noisy = await numbers(t);
  assert.ok(num(noisy[0], 'RMS') > num(before[0], 'RMS'), 'more noise, larger error of the interpolant');
  const a1 = await t.canvasHash(APPROX), i1 = await t.canvasHash(INTERP);
  await t.setInput('input[name="a"]', 0.2);
  assert.notEqual(await t.canvasHash(APPROX), a1, 'the approximation follows a');
  assert.equal(await t.canvasHash(INTERP), i1, 'the interpolation does not');
  await t.page.getByRole('button', { name: 'Use the cross-validated a' }).click();
  await t.frames(3);
  const a = await t.page.$eval('input[name="a"]', (e) => Number(e.value));
  const txt = await t.page.$$eval('.ctl-readout-value', (e) => e.map((x) => x.textContent).join(' '));
  assert.match(txt, new RegExp(`picks a = ${String(a).replace('.', '\\.')}`));
  assert.ok(a > 0, `CV chooses smoothing on noisy data: ${a}`);
  await t.waitHash((h) => h.startsWith('#noisy-data/'));
  t.assertClean();
  await t.close();
});

test('classic data sets and pasted CSV', async () => {
  const t = await H.open('#noisy-data');
  await t.page.getByRole('radio', { name: 'classic data' }).evaluate((el) => el.click());
  await t.frames(3);
  assert.match(await t.page.$$eval('.ctl-readout-value', (e) => e.map((x) => x.textContent).join(' ')), /Titanium/);
  const [n0] = await numbers(t);
  assert.doesNotMatch(n0, /true curve/, 'no true curve for measured data');
  await t.page.getByLabel('Data set').selectOption({ label: 'RPN 14 (Fritsch–Carlson, 9 points)' });
  await t.frames(3);
  assert.match(await t.page.$$eval('.ctl-readout-value', (e) => e.map((x) => x.textContent).join(' ')), /RPN 14/);
  await t.page.getByRole('radio', { name: 'your CSV' }).evaluate((el) => el.click());
  await t.page.fill('textarea.csv-input', 'x,y\n0,0\n1,1.2\n2,-0.1\n3,0.9\n4,0.2\n5,1.1\n6,0\n');
  const h0 = await t.canvasHash(APPROX);
  await t.page.getByRole('button', { name: 'Use these points' }).click();
  await t.frames(3);
  assert.match(await t.page.$$eval('.ctl-readout-value', (e) => e.map((x) => x.textContent).join(' ')), /your 7 points/);
  assert.notEqual(await t.canvasHash(APPROX), h0);
  // too few points: a notice, no crash; the page keeps working
  await t.page.fill('textarea.csv-input', '1,2\n');
  await t.page.getByRole('button', { name: 'Use these points' }).click();
  await t.frames(3);
  assert.ok(await t.page.$('.notice'), 'a notice explains the problem');
  await t.page.getByRole('radio', { name: 'known curve + noise' }).evaluate((el) => el.click());
  await t.frames(3);
  assert.match(await t.text('.plot-numbers'), /residual RMS 0/);
  t.assertClean();
  await t.close();
});
