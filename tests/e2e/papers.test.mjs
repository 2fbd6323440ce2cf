// The papers page (www/papers.html): every figure / theorem id of the five papers, every correction entry,
// no internal names on the page (its live-view links are opened in tests/e2e/papers-facts.test.mjs).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { join } from 'node:path';
import { startHarness, WWW } from './harness.mjs';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

const range = (a, b) => Array.from({ length: b - a + 1 }, (_, i) => a + i);
const EXPECTED_IDS = [
  ...range(1, 23).map((n) => `paper-000-fig-${n}`),
  ...range(1, 5).map((n) => `paper-001-fig-${n}`),
  ...range(1, 17).map((n) => `paper-003-fig-${n}`),
  ...range(1, 9).map((n) => `paper-004-fig-${n}`),
  ...range(1, 8).map((n) => `paper-002-thm-${n}`),
];
const CORRECTIONS = [
  'correction-000-eq5', 'correction-000-tension-half', 'correction-000-eq8', 'correction-000-autotension',
  'correction-000-bspline', 'correction-001-eq14', 'correction-001-eq15', 'correction-001-breaks',
  'correction-001-alpha', 'correction-001-eq20', 'correction-002-thm4', 'correction-002-envelope',
  'correction-003-basis', 'correction-003-bspline', 'correction-003-eq36', 'correction-004-sg',
];

test('the page has no inline script or style and carries the CSP', async () => {
  const html = await readFile(join(WWW, 'papers.html'), 'utf8');
  assert.match(html, /<meta http-equiv="Content-Security-Policy" content="[^"]*script-src 'self'/);
  assert.doesNotMatch(html, /<script(?![^>]*\bsrc=)[^>]*>/);
  assert.doesNotMatch(html, /<style|\sstyle="/);
  for (const f of ['index.html', 'guide.html']) {
    assert.match(await readFile(join(WWW, f), 'utf8'), /href="papers\.html"/, `${f} links to the papers page`);
  }
});

test('every figure and theorem id exists with a live view or a note; corrections and references are there', async () => {
  const t = await H.open('papers.html');
  const info = await t.page.evaluate((ids) => ids.map((id) => {
    const el = document.getElementById(id);
    return {
      id,
      tag: el?.tagName,
      caption: el?.querySelector('figcaption')?.textContent.trim().length ?? 0,
      link: !!el?.querySelector('a.paper-demo-link'),
      note: !!el?.querySelector('.not-reproducible'),
    };
  }), EXPECTED_IDS);
  for (const f of info) {
    assert.equal(f.tag, 'FIGURE', `${f.id} exists as a <figure>`);
    assert.ok(f.caption > 20, `${f.id} has a caption`);
    assert.ok(f.link !== f.note, `${f.id}: a live link or a .not-reproducible note (exactly one)`);
  }
  for (const id of CORRECTIONS) {
    const parts = await t.page.evaluate((i) => [...(document.getElementById(i)?.querySelectorAll('dd') ?? [])].map((d) => d.textContent.trim().length), id);
    assert.equal(parts.length, 3, `${id}: printed, correct, why`);
    assert.ok(parts.every((n) => n > 15), `${id}: each part is written out`);
  }
  assert.equal(await t.page.$$eval('#references li', (l) => l.length), 5);
  const text = await t.page.evaluate(() => document.body.innerText);
  assert.doesNotMatch(text, /seed/i, 'no internal paper numbers on the page');
  assert.doesNotMatch(text, /curves\.md|surfaces\.md|api\.md|spec\//i, 'no spec file names on the page');
  assert.deepEqual(await t.axe(), [], 'axe: no serious or critical violation');
  await t.screenshot('papers-desktop', { fullPage: false });
  await t.page.evaluate(() => document.getElementById('paper-000-fig-6').scrollIntoView());
  await t.screenshot('papers-desktop-figures', { fullPage: false });
  await t.page.evaluate(() => document.getElementById('correction-001-alpha').scrollIntoView());
  await t.screenshot('papers-desktop-corrections', { fullPage: false });
  t.assertClean();
  await t.close();
  const p = await H.open('papers.html#paper-001-fig-5', { viewport: { width: 390, height: 844 } });
  assert.ok(await p.page.evaluate(() => document.documentElement.scrollWidth <= window.innerWidth + 1), 'no horizontal scroll on a phone');
  const top = await p.page.$eval('#paper-001-fig-5', (e) => e.getBoundingClientRect().top);
  assert.ok(top >= -1 && top < 844, `a linked figure is scrolled into view (top ${top})`);
  await p.screenshot('papers-phone', { fullPage: false });
  p.assertClean();
  await p.close();
});

// Every live link (figures, theorems, corrections) is opened and checked — the demo mounts without a notice, draws,
// holds the promised state, and every figure shows the facts it states — in tests/e2e/papers-facts.test.mjs.
