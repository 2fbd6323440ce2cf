// The site speaks the reader's language (issue 17): no page says "seed" (our internal paper numbers) or names a
// spec file (curves.md / surfaces.md); every "Corrections" note of a demo links to the papers page, and every such
// link points at an entry that exists there.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness, demoIds } from './harness.mjs';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

const FORBIDDEN = [/seed/i, /curves\.md|surfaces\.md/i];

/** All the text a reader can meet on the page: text (hidden tabs too), and titles, labels and placeholders. */
async function readerText(t) {
  return t.page.evaluate(() => {
    const parts = [document.title, document.body.textContent];
    for (const el of document.querySelectorAll('[title], [aria-label], [placeholder], [alt]')) {
      for (const a of ['title', 'aria-label', 'placeholder', 'alt']) if (el.hasAttribute(a)) parts.push(el.getAttribute(a));
    }
    return parts.join('\n');
  });
}

function assertWording(text, where) {
  for (const re of FORBIDDEN) {
    const m = text.match(re);
    assert.equal(m, null, `${where}: says "${m && text.slice(Math.max(0, m.index - 60), m.index + 40).replace(/\s+/g, ' ')}"`);
  }
}

test('index, guide, papers and embed pages never say "seed" or name a spec file', async () => {
  const ids = await demoIds();
  for (const route of ['index.html', 'guide.html', 'papers.html', `embed.html#${ids[0]}`]) {
    const t = await H.open(route, { ready: route !== 'guide.html' });
    if (route === 'guide.html') await t.page.waitForLoadState('load');
    assertWording(await readerText(t), route);
    t.assertClean();
    await t.close();
  }
});

test('every demo: no "seed", no spec file; each Corrections note links to an existing papers-page entry', async () => {
  const ids = await demoIds();
  const targets = new Map(); // correction id → demo that links it
  for (const id of ids) {
    const t = await H.open(`index.html#${id}`);
    assertWording(await readerText(t), id);
    const notes = await t.page.$$eval('#demo-root .formula-note, #demo-root .demo-explain p, #demo-root p', (ps) => ps
      .filter((p) => /^\s*Corrections?\b/.test(p.textContent))
      .map((p) => ({ text: p.textContent.slice(0, 60), links: [...p.querySelectorAll('a')].map((a) => a.getAttribute('href')) })));
    for (const n of notes) {
      assert.ok(n.links.length > 0, `${id}: the note "${n.text}…" links to the papers page`);
      for (const href of n.links) {
        const m = /^papers\.html#(correction-[\w-]+)$/.exec(href);
        assert.ok(m, `${id}: correction link ${href} goes to papers.html#correction-…`);
        targets.set(m[1], id);
      }
    }
    t.assertClean();
    await t.close();
  }
  // the demos whose paper is corrected in a way they show carry the link
  const linked = new Set(targets.values());
  for (const id of ['interp-approx', 'bezier-remodel', 'curve-networks', 'knot-modification', 'quasi-cubic-curves', 'blended-interpolation']) {
    if (ids.includes(id)) assert.ok(linked.has(id), `${id} links its corrections`);
  }
  for (const must of ['correction-000-eq5', 'correction-000-bspline', 'correction-004-sg']) assert.ok(targets.has(must), `some demo links ${must}`);
  const p = await H.open('papers.html');
  const missing = await p.page.evaluate((list) => list.filter((i) => !document.getElementById(i)?.classList.contains('correction')), [...targets.keys()]);
  assert.deepEqual(missing, [], 'every linked correction exists on papers.html');
  await p.close();
});

test('data-set notes shown in a demo are cited by paper, not by internal number', async () => {
  for (const dataset of ['titanium_heat', 'rpn14']) {
    const t0 = await H.open('index.html#noisy-data');
    const href = await t0.page.evaluate(async (ds) => {
      const { encodeState, buildHash } = await import('./lib/state.js');
      return 'index.html' + buildHash('noisy-data', await encodeState({ source: 'dataset', dataset: ds }));
    }, dataset);
    await t0.close();
    const t = await H.open(href);
    const text = await readerText(t);
    assert.match(text, /Fig\. 15/, `${dataset}: the source note is shown`);
    assertWording(text, `noisy-data ${dataset}`);
    t.assertClean();
    await t.close();
  }
});
