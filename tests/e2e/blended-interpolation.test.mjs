// The "Blended interpolation" demo: draws; a β* change changes the curve and the curvature plot; "fair by
// curvature" puts κ(b_j) on K_j; the Titanium preset loads; no console error.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

const CURVE = 'canvas[data-plot="curve"]';
const KAPPA = 'canvas[data-plot="curvature"]';

let H;
before(async () => { H = await startHarness({ warm: true /* the idle warm-up on, as a visitor has it */, fresh: true /* a first visit: nothing cached */ }); });
after(async () => { await H?.close(); });

const sliderFor = (label) => `xpath=//label[contains(., "${label}")]/ancestor::div[contains(@class,"ctl-slider")]//input[@type="range"]`;

/** Waits until the curve of the current state is shown: a large curve (or any, on a loaded machine: the compute
 * client decides by measured time) is computed in the worker and its readouts are written when it is in. */
async function shown(t) {
  await t.settled();
  await t.frames(2);
}
/** What the page shows and does, for a failure message. */
const diagnosis = (t) => t.page.evaluate(() => `warm ${document.documentElement.dataset.warm}/${document.documentElement.dataset.warmCalls}; ` +
  `computing ${[...document.querySelectorAll('.compute-status')].map((e) => e.dataset.computing)}; ` +
  `readouts ${[...document.querySelectorAll('.ctl-readout')].map((e) => e.textContent.trim()).join(' | ')}`);

test('a β* change changes the curve and the curvature plot', async () => {
  const t = await H.open('#blended-interpolation');
  const c0 = await t.canvasHash(CURVE), k0 = await t.canvasHash(KAPPA);
  await t.setInput(sliderFor('β*'), 2.2);
  assert.notEqual(await t.canvasHash(CURVE), c0, 'curve redrawn');
  assert.notEqual(await t.canvasHash(KAPPA), k0, 'curvature plot redrawn');
  // dragging the tangent-length handle also changes β* (at β* = 2.2 the tip lies below the initial view: fit the
  // view to the handles first, so that the drag really starts on the tip)
  await t.plotEval(CURVE, (p) => p.fitContent());
  await t.frames(2);
  const tip = (await t.handles(CURVE)).find((x) => x.name === 'tangent length').point;
  const k1 = await t.canvasHash(KAPPA);
  const b1 = (await t.state()).beta.slice();
  await t.dragWorld(CURVE, tip, [tip[0] - 0.3, tip[1]]);
  assert.notDeepEqual((await t.state()).beta, b1, 'the drag changed β*');
  assert.notEqual(await t.canvasHash(KAPPA), k1, 'curvature plot redrawn after the handle drag');
  await t.screenshot('blended-interpolation');
  t.assertClean();
  await t.close();
});

test('fair by curvature: κ(b_j) equals K_j at the selected point', async () => {
  const t = await H.open('#blended-interpolation');
  await t.page.click('button:text-is("Fair by curvature")');
  await shown(t);
  const [k, K] = (await t.text('[data-readout="kappa"] .ctl-readout-value')).replace(/−/g, '-').split('/').map(Number);
  assert.ok(Number.isFinite(k) && Math.abs(k - K) < 1e-3, `κ ${k} vs K ${K} (${await diagnosis(t)})`);
  t.assertClean();
  await t.close();
});

test('Titanium and RPN 14 presets load and fair', async () => {
  const t = await H.open('#blended-interpolation');
  const backText = () => t.text('[data-readout="backwards"] .ctl-readout-value');
  const before = await backText();
  await t.page.click('.ctl-group label:text-is("Titanium")');
  await shown(t);
  assert.equal((await t.handles(CURVE)).filter((x) => x.name === 'data point').length, 51);
  assert.notEqual((await backText()).split(' of ')[1], before.split(' of ')[1], 'the readout counts the Titanium curve\'s samples');
  const backwards = async () => Number((await backText()).split(' ')[0]);
  assert.equal(await backwards(), 0, 'the plain spline (β* = 1) moves right all the time');
  const plain = (await t.state()).beta.slice();
  await t.page.click('button:text-is("Fair by curvature")');
  await shown(t);
  // the finding the demo teaches: exact curvature matching makes small loops on the flat runs
  const faired = (await t.state()).beta;
  assert.notDeepEqual(faired, plain, 'the click faired β*');
  assert.ok((await backwards()) > 0, `faired Titanium curve runs backwards somewhere (${await diagnosis(t)})`);
  await t.screenshot('blended-interpolation-titanium');
  await t.page.click('.ctl-group label:text-is("RPN 14")');
  await t.frames(3);
  assert.equal((await t.handles(CURVE)).filter((x) => x.name === 'data point').length, 11);
  t.assertClean();
  await t.close();
});
