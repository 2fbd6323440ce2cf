// The gallery page and every demo route: loads with no console error and no request leaving 127.0.0.1.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { join } from 'node:path';
import { startHarness, demoIds, demoExists, WWW } from './harness.mjs';

let H;
let ids;
before(async () => { H = await startHarness(); ids = await demoIds(); });
after(async () => { await H?.close(); });

test('both pages carry the Content-Security-Policy meta and no inline script or style', async () => {
  for (const f of ['index.html', 'embed.html']) {
    const html = await readFile(join(WWW, f), 'utf8');
    const m = html.match(/<meta http-equiv="Content-Security-Policy" content="([^"]+)">/);
    assert.ok(m, `${f}: CSP meta`);
    for (const d of ["default-src 'self'", "script-src 'self' 'wasm-unsafe-eval'", "style-src 'self'", "object-src 'none'", "base-uri 'none'"]) {
      assert.ok(m[1].includes(d), `${f}: ${d}`);
    }
    assert.doesNotMatch(html, /<script(?![^>]*\bsrc=)[^>]*>/, `${f}: inline script`);
    assert.doesNotMatch(html, /<style|\sstyle="/, `${f}: inline style`);
  }
});

test('the gallery loads cleanly and shows one card per demo', async () => {
  const t = await H.open('');
  assert.equal(await t.page.evaluate(() => document.body.dataset.view), 'gallery');
  for (const id of ids) {
    const card = await t.page.$(`.card[data-demo="${id}"]`);
    assert.ok(card, `card for ${id}`);
    const available = await demoExists(id);
    const tag = await card.evaluate((e) => e.tagName);
    if (available) {
      assert.equal(tag, 'A', `${id} is a link`);
      assert.equal(await card.getAttribute('href'), `#${id}`);
      assert.ok((await card.textContent()).trim().length > 10, `${id} card has a title and summary`);
    } else {
      assert.match(await card.getAttribute('class'), /unavailable/, `${id} marked unavailable`);
    }
  }
  await t.screenshot('gallery');
  assert.deepEqual(await t.axe(), [], 'axe: no serious or critical violation');
  t.assertClean();
  await t.close();
});

test('clicking a card opens the demo on the same page; the back link returns', async () => {
  const t = await H.open('');
  await t.page.click('a.card[data-demo="bspline-basics"]');
  await t.page.waitForSelector('#demo-root[data-mounted="true"]');
  assert.equal(await t.text('.demo-title'), 'B-spline basics');
  assert.match(await t.page.title(), /B-spline basics/);
  // change the state, go back to the gallery, then forward: the same state comes back
  await t.press('Tab'); // (focus is on the title)
  await t.setInput('input[type=range]', 0.75);
  const hash = await t.flushState();
  await t.page.click('.back-link');
  await t.page.waitForSelector('.cards');
  assert.equal(await t.page.evaluate(() => document.body.dataset.view), 'gallery');
  await t.page.goBack();
  await t.page.waitForSelector('#demo-root[data-mounted="true"]');
  assert.equal(await t.page.$eval('input[type=range]', (e) => e.value), '0.75');
  assert.ok(hash.startsWith('#bspline-basics/'));
  await t.page.goBack();
  await t.page.waitForSelector('.cards');
  t.assertClean();
  await t.close();
});

test('every demo route mounts without console error', async (tt) => {
  for (const id of ids) {
    await tt.test(id, { skip: !(await demoExists(id)) && 'module not written yet' }, async () => {
      const t = await H.open(`#${id}`);
      assert.equal(await t.page.evaluate(() => document.body.dataset.demo), id);
      assert.ok(await t.page.$('#demo-root[data-mounted="true"]'), 'mounted');
      const embed = await H.open(`embed.html#${id}`);
      assert.ok(await embed.page.$('#demo-root[data-mounted="true"]'), 'mounted in embed.html');
      assert.equal(await embed.page.$('.site-header'), null, 'no chrome in embed.html');
      t.assertClean();
      embed.assertClean();
      await t.close();
      await embed.close();
    });
  }
});

test('embed options hide the controls and the explanation', async () => {
  const t = await H.open('embed.html?explain=0#bspline-basics?controls=0');
  assert.equal(await t.page.$eval('.demo-controls', (e) => e.hidden), true);
  assert.equal(await t.page.$eval('.demo-explain', (e) => e.hidden), true);
  assert.ok(await t.page.$('canvas'), 'plots still drawn');
  t.assertClean();
  await t.close();
});

test('an unknown demo or a hostile id shows a notice and the gallery', async () => {
  for (const route of ['#no-such-demo', '#%3Cimg%20src%3Dx%20onerror%3Dalert(1)%3E/v1.AAAA']) {
    const t = await H.open(route);
    assert.equal(await t.page.evaluate(() => document.body.dataset.view), 'gallery');
    assert.ok(await t.page.$('.notice'), `notice for ${route}`);
    assert.equal(await t.page.$('img'), null, 'nothing injected');
    t.assertClean();
    await t.close();
  }
});

test('the harness itself blocks and records a request that leaves 127.0.0.1', async () => {
  // (so that "no outside request" above is a check that can fail) — a page without the CSP tries two fetches
  const t = await H.open('', { ready: false });
  await t.page.goto('about:blank');
  const r = await t.page.evaluate(async () => {
    const out = [];
    for (const u of ['http://example.invalid/x.js', 'https://10.255.255.1/beacon']) {
      try { await fetch(u, { mode: 'no-cors' }); out.push('loaded'); } catch { out.push('blocked'); }
    }
    return out;
  });
  assert.deepEqual(r, ['blocked', 'blocked']);
  assert.deepEqual(t.outside, ['http://example.invalid/x.js', 'https://10.255.255.1/beacon']);
  await t.close();
});
