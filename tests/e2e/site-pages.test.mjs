// The built site's reading pages as a person sees them (issue 30, item 4): tests/e2e/site.test.mjs loads
// exercises.html, papers.html and guide.html only for console errors; here their content is checked on the
// deployment build (scripts/build-site.mjs, into dist/site-pages/ so that this file and site.test never write
// the same folder):
//   - exercises.html lists every exercise of www/lib/exercise-catalogue.js (count, titles, tasks, grouped by
//     paper), and an exercise's link opens its demo with its task;
//   - papers.html shows the five papers with every figure (theorem) card of www/papers.js, and a figure's link
//     opens that demo (its title) in the figure's state;
//   - guide.html shows its sections (table of contents and headings) and its live examples draw: two
//     <spline-lab> elements (one with controls, one bare) and an embed.html iframe.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { startHarness, ensureWasm, ROOT, OUT } from './harness.mjs';
import { ink } from './png-ink.mjs';
import { CATALOGUE } from '../../www/lib/exercise-catalogue.js';
import { PAPERS } from '../../www/lib/papers-ref.js';

// SITE_PREBUILT=1 (as for site.test): check the dist/site already built instead of building one
const SITE = join(ROOT, process.env.SITE_PREBUILT === '1' ? 'dist/site' : 'dist/site-pages');

// www/papers.js builds the page when it finds #papers; in Node there is no document, so it only exports its tables
globalThis.document ??= { getElementById: () => null };
const { FIGURES, THEOREMS } = await import('../../www/papers.js');

/** The guide's numbered sections and the exercises section, in page order (ids of their h2). */
const GUIDE_SECTIONS = ['link', 'iframe', 'element', 'options', 'host', 'offline', 'export', 'lecture', 'access', 'demos', 'live', 'api', 'browsers', 'exercises'];

let H;
before(async () => {
  mkdirSync(OUT, { recursive: true });
  await ensureWasm();
  if (process.env.SITE_PREBUILT !== '1') execFileSync(process.execPath, [join(ROOT, 'scripts/build-site.mjs'), SITE], { cwd: ROOT, stdio: 'pipe' });
  H = await startHarness({ dir: SITE, fresh: true /* counts requests: nothing cached */ });
});
after(() => H?.close());

/** Ink of an element's screenshot (scrolled into view first; works for WebGL canvases too). */
async function inkOf(t, handle) {
  await handle.scrollIntoViewIfNeeded();
  await t.frames(3);
  return ink(await handle.screenshot());
}

test('exercises.html lists every catalogue exercise under its paper, with its title and task', async () => {
  const t = await H.open('exercises.html');
  const cards = await t.page.$$eval('.exercise-card', (cs) => cs.map((c) => ({
    id: c.dataset.exercise, paper: c.closest('.exercise-group')?.dataset.paper, visible: c.offsetHeight > 0,
    title: c.querySelector('h3').textContent, task: c.querySelector('h3 + p').textContent,
    open: c.querySelector('.exercise-open')?.textContent,
  })));
  assert.equal(cards.length, CATALOGUE.length, `${cards.length} exercise cards for ${CATALOGUE.length} catalogue entries`);
  const order = [...PAPERS.map((p) => p.key), 'bg'];
  const expected = order.flatMap((key) => CATALOGUE.filter((e) => e.paper === key))
    .map((e) => ({ id: e.id, paper: e.paper, visible: true, title: e.title, task: e.exercise.task, open: `Open “${e.title}”` }));
  assert.deepEqual(cards, expected, 'every exercise, in paper order, with its title, task and open link');
  t.assertClean();
  await t.context.close();
});

test('an exercise link of exercises.html opens its demo with the task', async () => {
  const t = await H.open('exercises.html');
  const e = CATALOGUE.find((x) => x.id === 'qc-ellipse-alpha');
  await t.page.click(`.exercise-card[data-exercise="${e.id}"] .exercise-open`);
  await t.page.waitForSelector('#demo-root[data-mounted="true"]', { timeout: 30000 });
  await t.page.waitForSelector('.exercise-panel .exercise-task', { timeout: 30000 });
  assert.equal(await t.page.evaluate(() => window.splinelab.current()?.id), e.demo, 'the exercise\'s demo is mounted');
  assert.equal(await t.page.textContent('.exercise-task'), e.exercise.task, 'the task is shown');
  const title = await t.page.textContent('h1.demo-title');
  assert.equal(title, await t.page.evaluate(() => document.title.replace(/ — SplineLab$/, '')), 'the demo title is shown');
  assert.equal((await t.state()).alpha, e.start.alpha, 'the demo starts from the exercise\'s state');
  await t.page.screenshot({ path: join(OUT, 'site-pages-exercise.png') });
  const { inked, total } = await inkOf(t, await t.page.$('#demo-root canvas'));
  assert.ok(inked > total * 0.005, `the figure is drawn (${inked} of ${total} pixels inked)`);
  t.assertClean();
  await t.context.close();
});

test('papers.html shows the five papers, each with its figure (theorem) cards', async () => {
  const t = await H.open('papers.html');
  const sections = await t.page.$$eval('section.paper-section[id^="paper-"]', (ss) => ss.map((s) => ({
    id: s.id, title: s.querySelector('h2').textContent, visible: s.offsetHeight > 0,
    cards: [...s.querySelectorAll('figure.paper-figure')].map((f) => f.id),
  })));
  const expected = PAPERS.map((p) => {
    const kind = p.key === '002' ? 'thm' : 'fig';
    const figs = p.key === '002' ? THEOREMS : FIGURES[p.key];
    return { id: `paper-${p.key}`, title: p.title, visible: true, cards: figs.map((f) => `paper-${p.key}-${kind}-${f.n}`) };
  });
  assert.equal(sections.length, 5, 'five papers');
  assert.deepEqual(sections, expected, 'each paper with its title and every figure card');
  // every card reads as a figure: a caption, and a live link or the note why there is none
  const bare = await t.page.$$eval('figure.paper-figure', (fs) => fs.filter((f) => !f.querySelector('figcaption')?.textContent.trim()
    || !(f.querySelector('.paper-demo-link') || f.querySelector('.not-reproducible'))).map((f) => f.id));
  assert.deepEqual(bare, [], 'cards without a caption or without a live link / note');
  t.assertClean();
  await t.context.close();
});

test('a figure link of papers.html opens that demo, in the figure\'s state', async () => {
  const t = await H.open('papers.html');
  const f = FIGURES['004'].find((x) => x.n === 1);
  const link = await t.page.$('#paper-004-fig-1 .paper-demo-link');
  const text = await link.textContent();
  const demoTitle = text.replace(/^Open the live view: /, '');
  assert.notEqual(demoTitle, text, `the link says what it opens: ${text}`);
  await link.scrollIntoViewIfNeeded();
  await link.click();
  await t.page.waitForSelector('#demo-root[data-mounted="true"]', { timeout: 30000 });
  await t.frames(3);
  assert.equal(await t.page.evaluate(() => window.splinelab.current()?.id), f.demo);
  assert.equal(await t.page.textContent('h1.demo-title'), demoTitle, 'the demo the link named');
  const state = await t.state();
  for (const [k, v] of Object.entries(f.state)) assert.deepEqual(state[k], v, `the figure's ${k}`);
  await t.page.screenshot({ path: join(OUT, 'site-pages-figure.png') });
  const { inked, total } = await inkOf(t, await t.page.$('#demo-root canvas'));
  assert.ok(inked > total * 0.005, `the figure is drawn (${inked} of ${total} pixels inked)`);
  t.assertClean();
  await t.context.close();
});

test('guide.html: its sections are listed and shown; its live examples (two elements, an iframe) draw', async () => {
  const t = await H.open('guide.html', { ready: false });
  await t.page.waitForLoadState('load');
  const toc = await t.page.$$eval('nav a[href^="#"], .toc a[href^="#"], main ol a[href^="#"]', (as) => [...new Set(as.map((a) => a.getAttribute('href').slice(1)))]);
  const headings = await t.page.$$eval('main h2[id]', (hs) => hs.filter((x) => x.offsetHeight > 0).map((x) => x.id));
  for (const id of GUIDE_SECTIONS) {
    assert.ok(headings.includes(id), `section #${id} is shown (${headings.join(', ')})`);
  }
  assert.deepEqual(headings.filter((id) => GUIDE_SECTIONS.includes(id)), GUIDE_SECTIONS, 'in this order');
  for (const id of GUIDE_SECTIONS.slice(0, 13)) assert.ok(toc.includes(id), `the contents link to #${id}`);
  // the two <spline-lab> elements: mounted, drawn; the full one has controls, the bare one none
  for (const id of ['example-full', 'example-bare', 'example-iframe']) assert.ok(await t.page.$(`#${id}`), `the live example #${id} is on the page`);
  await t.page.waitForFunction(() => ['example-full', 'example-bare'].every((id) => document.getElementById(id)?.dataset.ready === 'true'), null, { timeout: 30000 });
  for (const [id, controls] of [['example-full', true], ['example-bare', false]]) {
    const el = await t.page.$(`#${id}`);
    const canvas = (await el.evaluateHandle((e) => e.shadowRoot.querySelector('canvas'))).asElement();
    assert.ok(canvas, `#${id} has a canvas`);
    const { inked, total, colours } = await inkOf(t, canvas);
    assert.ok(inked > total * 0.005 && colours >= 4, `#${id} draws (${inked} of ${total} pixels inked, ${colours} colours)`);
    const sliders = await el.evaluate((e) => [...e.shadowRoot.querySelectorAll('input[type="range"]')].filter((s) => s.offsetParent).length);
    assert.equal(sliders > 0, controls, `#${id}: ${sliders} visible sliders`);
  }
  // the iframe: embed.html with the demo mounted and drawn
  const frame = await (await t.page.$('#example-iframe')).contentFrame();
  await frame.waitForSelector('#demo-root[data-mounted="true"]', { timeout: 30000 });
  const { inked, total } = await inkOf(t, await frame.$('#demo-root canvas'));
  assert.ok(inked > total * 0.005, `the iframe's demo draws (${inked} of ${total} pixels inked)`);
  await (await t.page.$('#example-bare')).screenshot({ path: join(OUT, 'site-pages-guide-bare.png') });
  t.assertClean();
  await t.context.close();
});
