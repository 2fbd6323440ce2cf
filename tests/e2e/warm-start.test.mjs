// Warm start (issue 26, www/lib/warm.js): after the first frame the shell runs the demo's own drag path (its
// `instance.warm()`) in idle slices so that the first drag runs in optimized code. What a person must not notice:
// the picture, the link and the undo history stay as they were; the warm-up stops at the first key or pointer
// input; `?warm=0` turns it off. (Its effect on the first drag frames is measured, not asserted, by
// `FIRST=1 node benches/interaction.mjs <demo>`: a timing on this shared machine would be noise.)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createHash } from 'node:crypto';
import { startHarness } from './harness.mjs';

let H;
before(async () => { H = await startHarness(); });
after(() => H.close());

/** Waits until the warm-up has finished one way or the other ('done' | 'stopped' | 'off'). */
const warmEnd = (t) => t.page.waitForFunction(() => ['done', 'stopped', 'off'].includes(document.documentElement.dataset.warm), null, { timeout: 20000 });
/** One hash of the pixels of every canvas of the page (every plot the warm path redraws). */
async function canvasesHash(t) {
  await t.frames(3);
  const urls = await t.page.$$eval('canvas', (cs) => cs.map((c) => c.toDataURL('image/png')));
  return createHash('sha256').update(urls.join('|')).digest('hex');
}
const warmState = (t) => t.page.evaluate(() => ({ status: document.documentElement.dataset.warm, calls: Number(document.documentElement.dataset.warmCalls || 0) }));

// the demos that give a warm path (instance.warm)
const WARMED = ['bspline-basics', 'quasi-cubic-curves', 'interp-approx', 'blended-interpolation', 'knot-modification'];

for (const id of WARMED) {
  test(`${id}: the warm-up runs its rounds and changes nothing a person sees (picture, link, undo)`, async () => {
    const t = await H.open(`#${id}`);
    const hash = await t.page.evaluate(() => location.hash);
    await warmEnd(t);
    const w = await warmState(t);
    assert.deepEqual(w, { status: 'done', calls: 24 }, 'the default 24 warm calls ran');
    const warmed = await canvasesHash(t);
    assert.equal(await t.page.evaluate(() => location.hash), hash, 'the link is unchanged');
    assert.equal(await t.page.$eval('.btn-undo', (b) => b.disabled), true, 'no undo step');
    t.assertClean();
    await t.close();
    // the same view without the warm-up: the same pixels
    const cold = await H.open(`?warm=0#${id}`);
    await warmEnd(cold);
    assert.equal((await warmState(cold)).status, 'off');
    assert.equal(await canvasesHash(cold), warmed, 'the warmed page draws the same pictures (every canvas) as the cold one');
    await cold.close();
  });
}

test('the warm-up stops at the first input and does not start again', async () => {
  const t = await H.open('?warm=1000#bspline-basics');
  await t.page.waitForFunction(() => Number(document.documentElement.dataset.warmCalls || 0) >= 2 || document.documentElement.dataset.warm === 'off', null, { timeout: 20000 });
  assert.equal((await warmState(t)).status, 'running');
  await t.page.keyboard.press('Shift');
  const at = await warmState(t);
  assert.equal(at.status, 'stopped');
  await t.page.waitForTimeout(800);
  const later = await warmState(t);
  assert.equal(later.calls, at.calls, `no warm call after the key press (${at.calls} → ${later.calls})`);
  assert.ok(later.calls < 1000);
  t.assertClean();
  await t.close();
});

test('a demo that gives no warm path is left alone', async () => {
  const t = await H.open('#noisy-data');
  await warmEnd(t);
  assert.equal((await warmState(t)).status, 'off');
  await t.close();
});
