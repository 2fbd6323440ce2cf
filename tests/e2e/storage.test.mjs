// Storage that fails: with localStorage throwing on access (storage blocked for a third-party iframe, private
// modes) or full (every write throws QuotaExceededError), every demo in index.html and embed.html still starts
// and works, the state lives in the link (a fresh page with the link shows the same state), and a notice says
// that saving is off (nothing is lost silently). With storage working there is no such notice.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness, demoIds } from './harness.mjs';

// init scripts, run before the page's own scripts
const BLOCKED = () => {
  Object.defineProperty(window, 'localStorage', { configurable: true, get() { throw new DOMException('The operation is insecure.', 'SecurityError'); } });
};
const FULL = () => {
  Storage.prototype.setItem = function setItem() { throw new DOMException('The quota has been exceeded.', 'QuotaExceededError'); };
};

let H, ids;
before(async () => { H = await startHarness(); ids = await demoIds(); });
after(() => H?.close());

// One browser context per kind of storage, shared by the opens of a file (www/ cached as for a visitor's second
// page; the harness clears the origin's storage before each open). Storage that throws keeps nothing between them.
const openWith = (route, init) => H.open(route, init ? { init } : {});

/** Changes the state like a user: arrow keys on a plot with points, else a slider. */
async function interact(t) {
  const viaKeys = await t.page.evaluate(() => {
    const c = [...document.querySelectorAll('canvas')].find((x) => x.splinePlot && x.getClientRects().length && x.splinePlot.handles().length);
    if (!c) return false;
    c.focus();
    return true;
  });
  if (viaKeys) await t.press('ArrowRight', 'ArrowUp', 'ArrowRight');
  else {
    const sel = await t.page.evaluate(() => {
      const r = [...document.querySelectorAll('input[type="range"]')].find((x) => x.getClientRects().length && !x.disabled);
      if (!r) return null;
      r.dataset.storageTest = '1';
      return r.max;
    });
    assert.ok(sel !== null, 'a plot with points or a slider');
    await t.setInput('input[data-storage-test]', sel);
  }
  return t.flushState();
}

const noticeText = (t) => t.page.evaluate(() => document.querySelector('[data-notice-id="storage-off"]')?.textContent || '');

for (const [mode, init, page] of [['blocked', BLOCKED, 'index.html'], ['full', FULL, 'embed.html']]) {
  test(`storage ${mode}: every demo in ${page} works, the state lives in the link, a notice says saving is off`, async (tt) => {
    for (const id of ids) {
      await tt.test(id, async () => {
        const t = await openWith(`${page}#${id}`, init);
        await t.page.waitForSelector('[data-notice-id="storage-off"]', { timeout: 10000 });
        assert.match(await noticeText(t), /Saving is off/, 'the notice');
        assert.match(await noticeText(t), mode === 'full' ? /full/ : /does not let/, 'the notice names the cause');
        assert.equal(await t.page.evaluate(() => document.documentElement.dataset.storage), 'off');
        const before = JSON.stringify(await t.state());
        const hash = await interact(t);
        const state = JSON.stringify(await t.state());
        assert.notEqual(state, before, 'the interaction changed the state');
        assert.match(hash, new RegExp(`^#${id}/v`), 'the state is in the link');
        // no second notice for the saves that failed (the first one goes away by itself after 20 s)
        assert.ok(await t.page.$$eval('[data-notice-id="storage-off"]', (n) => n.length) <= 1, 'one notice');
        t.assertClean();
        await t.close();
        // the link alone restores the state (a fresh page, storage still failing)
        const t2 = await openWith(`${page}${hash}`, init);
        assert.equal(JSON.stringify(await t2.state()), state, 'the link restores the state');
        t2.assertClean();
        await t2.close();
      });
    }
  });
}

test('storage working: no notice, and the last state is saved', async () => {
  const t = await openWith('index.html#bspline-basics');
  await interact(t);
  await t.frames(4);
  assert.equal(await noticeText(t), '');
  assert.equal(await t.page.evaluate(() => document.documentElement.dataset.storage), 'on');
  assert.ok(await t.page.evaluate(() => !!localStorage.getItem('splinelab:last:bspline-basics')), 'saved in localStorage');
  t.assertClean();
  await t.close();
});

test('storage that fills up while working: the notice comes with the first save that fails', async () => {
  const t = await openWith('index.html#interp-approx');
  assert.equal(await noticeText(t), '');
  await t.page.evaluate(() => { Storage.prototype.setItem = function setItem() { throw new DOMException('full', 'QuotaExceededError'); }; });
  const hash = await interact(t);
  await t.page.waitForSelector('[data-notice-id="storage-off"]', { timeout: 10000 });
  assert.match(await noticeText(t), /full/);
  assert.match(hash, /^#interp-approx\/v/);
  t.assertClean();
  await t.close();
});
