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

// A paste spreads its work over frames (issue 26, www/lib/frame-steps.js): a newer paste, or a change of the data
// source, that comes in the middle of it wins, and the page ends exactly as with the newer action alone (the same
// pixels, views and numbers; no later frame of the older paste draws over it).
const rows = (k, f) => Array.from({ length: k }, (_, i) => `${i / 100}, ${Math.round(f(i) * 1000) / 1000}`).join('\n');
const BIG = rows(2000, (i) => Math.sin(i / 150) + 0.1 * Math.sin(i * 7.1));
const SMALL = rows(40, (i) => 3 + Math.cos(i / 5));
/** What the person sees once everything is in (the fits from the worker too, and a moment more for any late frame). */
async function seen(t) {
  await t.page.waitForFunction(() => !document.querySelector('[data-computing="true"]'), null, { timeout: 30000 });
  await t.page.waitForTimeout(800);
  await t.frames(3);
  return t.page.evaluate(() => ({
    views: [...document.querySelectorAll('canvas[data-plot]')].map((c) => JSON.stringify(c.splinePlot.getView())),
    pixels: [...document.querySelectorAll('canvas[data-plot]')].map((c) => c.toDataURL()),
    texts: [...document.querySelectorAll('.plot-numbers, .ctl-readout-value, .plot-title')].map((e) => e.textContent),
  }));
}
/** Pastes `first`, then does `then` (in the page) as soon as the paste has shown its left plot (its third frame). */
const pasteThen = (t, first, then) => t.page.evaluate(([text, what]) => new Promise((done) => {
  const area = document.querySelector('textarea.csv-input');
  const apply = () => area.closest('.ctl').querySelector('button').click();
  const left = document.querySelector('canvas[data-plot="interp"]').splinePlot, before = JSON.stringify(left.getView());
  area.value = text;
  apply();
  const poll = () => {
    if (JSON.stringify(left.getView()) === before) { requestAnimationFrame(poll); return; }
    if (what.paste) { area.value = what.paste; apply(); } else [...document.querySelectorAll('.ctl-segments label')].find((l) => l.textContent === 'known curve + noise').click();
    done();
  };
  requestAnimationFrame(poll);
}), [first, then]);

test('a second paste or a change of data in the middle of a paste wins', async () => {
  const ref = await H.open('#noisy-data');
  const paste = (text) => ref.page.$eval('textarea.csv-input', (e, v) => { e.value = v; e.closest('.ctl').querySelector('button').click(); }, text);
  await paste(SMALL);
  const small = await seen(ref);
  await paste(BIG);
  await seen(ref);
  await ref.page.getByRole('radio', { name: 'known curve + noise' }).evaluate((el) => el.click());
  const curve = await seen(ref);
  await ref.close();

  const t = await H.open('#noisy-data');
  await pasteThen(t, BIG, { paste: SMALL });
  const afterPaste = await seen(t);
  assert.match(afterPaste.texts.join(' '), /your 40 points/);
  assert.deepEqual(afterPaste.views, small.views, 'the views are those of the newer paste');
  assert.deepEqual(afterPaste.texts, small.texts, 'the numbers are those of the newer paste');
  assert.ok(afterPaste.pixels.every((p, i) => p === small.pixels[i]), 'the pixels are those of the newer paste');
  // a change of the data source in the middle of a paste: the paste's remaining frames are dropped
  await pasteThen(t, BIG, { source: 'curve' });
  const afterSwitch = await seen(t);
  assert.deepEqual(afterSwitch.views, curve.views, 'the views are those of the generated data');
  assert.deepEqual(afterSwitch.texts, curve.texts);
  assert.ok(afterSwitch.pixels.every((p, i) => p === curve.pixels[i]), 'the pixels are those of the generated data');
  t.assertClean();
  await t.close();
});
