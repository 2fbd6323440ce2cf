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
    assert.ok(available, `${id}: listed in www/demos/index.js but its module is missing (a renamed demo fails, it is not skipped)`);
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
    await tt.test(id, async () => {
      assert.ok(await demoExists(id), `${id}: listed in www/demos/index.js but www/demos/${id}.js is missing (a renamed demo fails, it is not skipped)`);
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
    // the notice is seen when it appears: it closes itself after 5 s, and under CI load an open (ready, worker
    // settled) takes longer than that (this check failed so at a load of 25-29 while the page was right)
    const t = await H.open(route, { ready: false });
    const notice = await t.page.waitForSelector('.notice', { state: 'attached', timeout: 20000 }).then(() => true, () => false);
    await t.ready();
    assert.equal(await t.page.evaluate(() => document.body.dataset.view), 'gallery');
    assert.ok(notice, `notice for ${route}`);
    // the only images are the cards' own pictures
    assert.deepEqual(await t.page.$$eval('img', (l) => l.filter((i) => !/^static\/cards\/[a-z0-9-]+\.png$/.test(i.getAttribute('src'))).map((i) => i.outerHTML)), [], 'nothing injected');
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

/** Changes the demo through the UI: the first slider of its controls, and (2D demos) a point moved with the keyboard. */
async function changeSomething(t) {
  const moved = await t.page.evaluate(() => {
    const r = [...document.querySelectorAll('.demo-controls input[type=range]')].find((e) => e.getClientRects().length && !e.disabled);
    if (!r) return null;
    const min = Number(r.min || 0), max = Number(r.max || 100), step = r.step === 'any' || !r.step ? 0 : Number(r.step);
    const snap = (v) => (step ? min + Math.round((v - min) / step) * step : v);
    let v = snap(min + 0.3 * (max - min));
    if (String(v) === r.value || Math.abs(v - Number(r.value)) < 1e-12) v = snap(min + 0.7 * (max - min));
    r.value = String(v);
    r.dispatchEvent(new Event('input', { bubbles: true }));
    r.dispatchEvent(new Event('change', { bubbles: true }));
    return r.getAttribute('aria-label') || r.id || 'slider';
  });
  await t.frames(2);
  const has2D = await t.page.$$eval('canvas', (cs) => cs.some((c) => c.splinePlot && c.splinePlot.handles().length && c.getClientRects().length));
  if (has2D) {
    await t.page.focus('.back-link');
    for (let i = 0; i < 80; i++) {
      const ok = await t.page.evaluate(() => { const a = document.activeElement; return !!(a && a.splinePlot && a.splinePlot.handles().length); });
      if (ok) break;
      await t.page.keyboard.press('Tab');
    }
    await t.press('ArrowRight', 'Shift+ArrowUp');
  }
  return { slider: moved, keyboard: has2D };
}

test('every demo: a state link from the Share panel round-trips in a fresh page; both embed snippets carry it', async (tt) => {
  for (const id of ids) {
    await tt.test(id, async () => {
      assert.ok(await demoExists(id), `${id}: listed in www/demos/index.js but www/demos/${id}.js is missing (a renamed demo fails, it is not skipped)`);
      const t = await H.open(`#${id}`);
      const s0 = await t.state();
      const how = await changeSomething(t);
      await t.flushState();
      const s1 = await t.state();
      assert.notDeepEqual(s1, s0, `${id}: the UI changed the state (${JSON.stringify(how)})`);
      await t.page.click('.share-toggle');
      await t.page.waitForSelector('.share-panel:not([hidden])');
      const link = await t.page.$eval('.share-link input', (e) => e.value);
      const iframe = await t.page.$eval('.share-iframe textarea', (e) => e.value);
      const element = await t.page.$eval('.share-element textarea', (e) => e.value);
      const payload = link.split('#')[1].split('/')[1].split('?')[0];
      assert.ok(link.startsWith(`${t.base}#${id}/v`), `link: ${link}`);
      assert.ok(iframe.includes(`embed.html#${id}/${payload}`), 'iframe snippet carries the state');
      assert.match(element, /<script type="module" src="http:\/\/127\.0\.0\.1:\d+\/spline-lab\.js"><\/script>/);
      assert.ok(element.includes(`<spline-lab demo="${id}" state="${payload}">`), `element snippet: ${element}`);
      // fallback content inside the element: a link to this view on the SplineLab host (shown until it starts)
      assert.ok(element.includes(`<a href="${t.base}index.html#${id}/${payload}">`) && element.trimEnd().endsWith('</spline-lab>'), `element fallback: ${element}`);
      assert.ok(await t.page.$('.share-panel a[href="guide.html"]'), 'the Share panel links the guide');
      t.assertClean();
      await t.close();
      // a fresh page (new browser context: no localStorage) shows the same state, in index.html and in embed.html
      const fresh = await H.open(link.slice(t.base.length));
      assert.deepEqual(await fresh.state(), s1, `${id}: same state from the link`);
      assert.equal(await fresh.page.$('.notice-warning'), null, 'no bad-link notice');
      fresh.assertClean();
      await fresh.close();
      const src = iframe.match(/src="([^"]+)"/)[1];
      const emb = await H.open(src.slice(t.base.length));
      assert.deepEqual(await emb.state(), s1, `${id}: same state in embed.html`);
      emb.assertClean();
      await emb.close();
    });
  }
});

test('every demo: a malformed or hostile state shows the notice and the default demo', async (tt) => {
  for (const id of ids) {
    await tt.test(id, async () => {
      assert.ok(await demoExists(id), `${id}: listed in www/demos/index.js but www/demos/${id}.js is missing (a renamed demo fails, it is not skipped)`);
      const clean = await H.open(`#${id}`);
      const s0 = await clean.state();
      await clean.close();
      const cases = [
        { bad: 'v1.@@not-base64@@', malformed: true },
        { bad: 'v1.AAAA', malformed: true },            // not deflate data
        { bad: 'v9.abc', malformed: true },             // unknown version
        { bad: `v0.${Buffer.from('{"points":').toString('base64url')}`, malformed: true }, // truncated JSON
        // valid JSON with wrong or unknown fields: validation keeps the defaults for them (a notice is optional)
        { bad: `v0.${Buffer.from('{"points":"x","degree":"<img src=x onerror=alert(1)>"}').toString('base64url')}`, malformed: false },
        { bad: `v0.${Buffer.from('{"__proto__":{"x":1},"constructor":1}').toString('base64url')}`, malformed: false },
      ];
      // The first link opens a fresh page (the start-up path); the others are pasted into its address bar, a
      // hash change (the same route(): parse, read the state, mount, notice), without ~2 s of a fresh page each.
      let t = null;
      for (const { bad, malformed } of cases) {
        if (!t) t = await H.open(`#${id}/${bad}`);
        else {
          await t.page.evaluate((hash) => new Promise((ok) => {
            document.getElementById('demo-root').dataset.before = 'true';   // the demo mounted for the previous link
            addEventListener('hashchange', () => ok(), { once: true });
            location.hash = hash;
          }), `#${id}/${bad}`);
          await t.page.waitForSelector('#demo-root[data-mounted="true"]:not([data-before])', { timeout: 20000 });
          await t.settled();
          await t.frames(2);
        }
        assert.equal(await t.page.evaluate(() => document.body.dataset.demo), id, `${bad}: the demo is shown`);
        if (malformed) {
          assert.ok(await t.page.$('.notice'), `${id} ${bad}: a notice`);
          assert.equal(await t.page.evaluate(() => document.body.dataset.badLink), 'true');
        }
        assert.deepEqual(await t.state(), s0, `${id} ${bad}: default state`);
        assert.equal(await t.page.$('#demo-root img'), null, 'nothing injected');
        assert.equal(await t.page.evaluate(() => ({}).x), undefined, 'no prototype pollution');
        t.assertClean();
      }
      await t.close();
    });
  }
});

test('static PNG fallbacks: one per demo in docs/static, served as static/<id>.png and linked from the guide', async () => {
  const t = await H.open('guide.html', { ready: false });
  await t.page.waitForLoadState('load');
  for (const id of ids) {
    assert.ok(await demoExists(id), `${id}: listed but its module is missing`);
    const r = await t.page.evaluate(async (u) => { const x = await fetch(u); const b = new Uint8Array(await x.arrayBuffer()); return { status: x.status, type: x.headers.get('content-type'), size: b.length, sig: Array.from(b.subarray(0, 4)) }; }, `static/${id}.png`);
    assert.equal(r.status, 200, `static/${id}.png`);
    assert.match(r.type, /image\/png/);
    assert.deepEqual(r.sig, [137, 80, 78, 71]);
    assert.ok(r.size > 10000 && r.size < 230 * 1024, `${id}.png is ${r.size} bytes`);
    assert.ok(await t.page.$(`a[href="static/${id}.png"]`), `the guide links ${id}.png`);
  }
  assert.match(await t.page.textContent('#static ~ p, #static + p'), /PDF notes/);
  await t.close();
});

test('every gallery card shows its generated picture (static/cards/<id>.png, 320×200, < 40 KB), and it loads', async () => {
  const t = await H.open('');
  // the pictures are lazy: scroll each card into view so the browser fetches it, then wait for it to decode
  const cards = await t.page.evaluate(async () => {
    const out = [];
    for (const a of document.querySelectorAll('a.card')) {
      const img = a.querySelector('img.card-thumb');
      if (img) {
        img.scrollIntoView();
        if (!img.complete || !img.naturalWidth) await new Promise((ok) => { img.addEventListener('load', ok, { once: true }); img.addEventListener('error', ok, { once: true }); setTimeout(ok, 8000); });
      }
      out.push({ id: a.dataset.demo, src: img?.getAttribute('src'), alt: img?.getAttribute('alt'), lazy: img?.loading, w: img?.naturalWidth ?? 0, h: img?.naturalHeight ?? 0, shownW: img?.getBoundingClientRect().width ?? 0 });
    }
    return out;
  });
  assert.equal(cards.length, ids.length, 'one card per demo');
  for (const c of cards) {
    assert.equal(c.src, `static/cards/${c.id}.png`, `${c.id}: card picture`);
    assert.equal(c.alt, '', `${c.id}: decorative picture (alt="")`);
    assert.equal(c.lazy, 'lazy', `${c.id}: loading=lazy`);
    assert.ok(c.w > 0, `${c.id}: the picture loads (naturalWidth ${c.w})`);
    assert.equal(`${c.w}×${c.h}`, '320×200', `${c.id}: picture size`);
    assert.ok(c.shownW > 100, `${c.id}: the picture is shown (${c.shownW} px wide)`);
    const { size } = await import('node:fs/promises').then((fs) => fs.stat(join(WWW, 'static/cards', `${c.id}.png`)));
    assert.ok(size < 40 * 1024, `${c.id}: ${size} bytes`);
  }
  await t.page.evaluate(() => window.scrollTo(0, 0));
  await t.screenshot('gallery-cards-desktop', { fullPage: false });
  t.assertClean();
  await t.close();
  const p = await H.open('', { viewport: { width: 390, height: 844 } });
  assert.ok(await p.page.evaluate(() => document.documentElement.scrollWidth <= window.innerWidth + 1), 'no horizontal scroll on a phone');
  await p.screenshot('gallery-cards-phone', { fullPage: false });
  p.assertClean();
  await p.close();
});
