// Warm start (issue 26, www/lib/warm.js): after the first frame the shell runs the demo's own drag path (its
// `instance.warm()`) in idle slices so that the first drag runs in optimized code. What a person must not notice:
// the picture, the link and the undo history stay as they were; the warm-up stops at the first key or pointer
// input; `?warm=0` turns it off. (Its effect on the first drag frames is measured, not asserted, by
// `FIRST=1 node benches/interaction.mjs <demo>`: a timing on this shared machine would be noise.)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createHash } from 'node:crypto';
import { startHarness, demoIds } from './harness.mjs';

let H;
let ids;
before(async () => { H = await startHarness({ warm: true /* the idle warm-up on, as a visitor has it */, fresh: true /* a first visit: nothing cached */ }); ids = await demoIds(); });
after(() => H.close());

/** Waits until the warm-up has finished one way or the other ('done' | 'stopped' | 'off'). */
const warmEnd = (t) => t.page.waitForFunction(() => ['done', 'stopped', 'failed', 'off'].includes(document.documentElement.dataset.warm), null, { timeout: 20000 });
/** One hash of the pixels of every canvas of the page (every plot the warm path redraws; the 3D views are read
 * after a fresh render of their own, as their buffers are not kept), and the demo's visible text (readouts). */
async function canvasesHash(t) {
  // what the page computes after its first frame (noisy-data's deferred sweep, a worker's answer) lands first: the
  // demo's text is read until it stays the same for 300 ms (on a loaded machine the cold page's sweep came after
  // the first read: 'no sweep')
  let last = null;
  for (let i = 0; i < 40; i++) {
    await t.settled();
    await t.frames(3);
    const now = await t.page.$eval('#demo-root', (r) => /** @type {HTMLElement} */ (r).innerText);
    if (now === last && !/no sweep/.test(now)) break;
    last = now;
    await t.page.waitForTimeout(300);
  }
  const urls = await t.page.$$eval('canvas', (cs) => cs.map((c) => {
    /** @type {any} */ (c).view3d?.render?.();
    return c.toDataURL('image/png');
  }));
  // (a readout of the time a call took differs between any two page loads: its number is not compared)
  const text = (await t.page.$eval('#demo-root', (r) => /** @type {HTMLElement} */ (r).innerText)).replace(/\d+(\.\d+)? ms\b/g, '… ms');
  return { pixels: createHash('sha256').update(urls.join('|')).digest('hex'), text };
}
const warmState = (t) => t.page.evaluate(() => ({ status: document.documentElement.dataset.warm, calls: Number(document.documentElement.dataset.warmCalls || 0) }));

// Every demo gives a warm path (instance.warm). The 3D demos' calls (surfaces, GPU uploads) may take over the
// warm-up's 25 ms limit twice in a row on a loaded machine: it then stops, after at least two calls ('stopped'),
// which is its design; a warm call that throws ends it as 'failed', which fails here.
test('every demo: the warm-up runs its rounds and changes nothing a person sees (picture, readouts, link, undo)', async (tt) => {
  for (const id of ids) await tt.test(id, async () => {
    const t = await H.open(`#${id}`);
    const hash = await t.page.evaluate(() => location.hash);
    await warmEnd(t);
    const w = await warmState(t);
    assert.notEqual(w.status, 'off', 'the demo gives a warm path');
    assert.ok(w.status === 'done' ? w.calls === 24 : w.status === 'stopped' && w.calls >= 2, `the default 24 warm calls ran, or at least 2 before two slow ones stopped it: ${JSON.stringify(w)}`);
    const warmed = await canvasesHash(t);
    assert.equal(await t.page.evaluate(() => location.hash), hash, 'the link is unchanged');
    assert.equal(await t.page.$eval('.btn-undo', (b) => b.disabled), true, 'no undo step');
    t.assertClean();
    await t.close();
    // the same view without the warm-up: the same pixels
    const cold = await H.open(`?warm=0#${id}`);
    await warmEnd(cold);
    assert.equal((await warmState(cold)).status, 'off');
    assert.deepEqual(await canvasesHash(cold), warmed, 'the warmed page draws the same pictures (every canvas) and numbers as the cold one');
    await cold.close();
  });
});

test('the warm-up stops at the first input and does not start again', async () => {
  // it must be running when the key comes: on a loaded machine two slow calls in a row may have stopped it
  // before (its design), so up to three fresh pages are tried
  let t;
  for (let attempt = 0; attempt < 3; attempt++) {
    t = await H.open('?warm=1000#bspline-basics');
    await t.page.waitForFunction(() => Number(document.documentElement.dataset.warmCalls || 0) >= 2 || ['off', 'stopped', 'failed'].includes(document.documentElement.dataset.warm), null, { timeout: 20000 });
    if ((await warmState(t)).status === 'running' || attempt === 2) break;
    await t.close();
  }
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

test('a warm path that throws ends the warm-up as failed', async () => {
  const t = await H.open('?warm=0#bspline-basics');
  await warmEnd(t);
  const status = await t.page.evaluate(async () => {
    const { warmStart } = await import('./lib/warm.js');
    const root = document.createElement('div');
    document.body.append(root);
    warmStart({ root, instance: { warm() { throw new Error('broken'); } } }, 3);
    return new Promise((ok) => { const poll = () => (document.documentElement.dataset.warm === 'running' || document.documentElement.dataset.warm === 'waiting' ? setTimeout(poll, 20) : ok(document.documentElement.dataset.warm)); poll(); });
  });
  assert.equal(status, 'failed');
  await t.close();
});
