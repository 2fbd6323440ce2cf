// Issue 28: SplineLab in Slovak, Romanian, Hungarian and Italian beside English.
//
// The check that looks where a reader looks: each page of TRANSLATED is opened in English and in each language;
// every visible text, aria-label, title, placeholder and alt (tests/e2e/i18n-texts.mjs) that the language's page
// shows exactly as the English page does is a failure (an English string in a Slovak page), unless it is on the
// reviewed list of words that are the same in that language (tests/fixtures/i18n-same.mjs); so is a text the catalogue lacks (the page's
// missingKeys()). The pages not translated yet are not opened here: `node scripts/i18n-keys.mjs` says how many
// texts each catalogue still lacks.
//
// Also: <html lang> follows the language; the decimal comma in readouts and number boxes (typing 0,25 works; 0.25
// too); a link made in Slovak opens the same state in English; the language menu switches and is remembered.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';
import { pageTexts } from './i18n-texts.mjs';
import { sameAllowed } from '../fixtures/i18n-same.mjs';

const LANGS = ['sk', 'ro', 'hu', 'it'];
/** The pages whose every text is translated (issue 28's first slice): the gallery and three demos. */
const TRANSLATED = ['', '#bspline-basics', '#interp-approx', '#noisy-data'];
let H;
before(async () => { H = await startHarness(); });
after(() => H?.close());

/** The texts of `route` in `lang` ('' = the browser's, English here), with the page's missing keys. */
async function textsOf(route, lang, o = {}) {
  const t = await H.open(`${lang ? `?lang=${lang}` : ''}${route}`, { viewport: { width: 1366, height: 900 }, ...o });
  const texts = await t.page.evaluate(pageTexts);
  const info = await t.page.evaluate(() => ({ lang: document.documentElement.lang, missing: window.splinelab.i18n.missingKeys() }));
  await t.close();
  return { texts, ...info };
}

/** The texts of `there` that are exactly a text of `english` and not on the language's list of same words. */
function stillEnglish(english, there, lang) {
  const en = new Set(english.map((x) => x.text));
  return there.filter((x) => en.has(x.text) && !sameAllowed(lang, x.text));
}

for (const route of TRANSLATED) {
  test(`${route || 'the gallery'}: in sk, ro, hu and it no text a person reads or hears is the English one; no key is missing; <html lang> follows`, async () => {
    const en = await textsOf(route, 'en');
    assert.equal(en.lang, 'en');
    assert.ok(en.texts.length > 20, `the English page has texts: ${en.texts.length}`);
    const problems = [];
    for (const lang of LANGS) {
      const x = await textsOf(route, lang);
      if (x.lang !== lang) problems.push(`${lang}: <html lang="${x.lang}">`);
      for (const k of x.missing) problems.push(`${lang}: the catalogue lacks “${k}”`);
      for (const s of stillEnglish(en.texts, x.texts, lang)) problems.push(`${lang}: English on the page: “${s.text}” (${s.where})`);
    }
    assert.deepEqual(problems, []);
  });
}

/** Every visible number with a decimal point between digits (2.2, 0.25): none may show in a comma language. */
const pointDecimals = (texts) => texts.filter((x) => /\d\.\d/.test(x.text)).map((x) => `“${x.text.slice(0, 80)}” (${x.where})`);

test('in sk, ro, hu and it every number a person reads has a decimal comma: readouts, descriptions, tables, the axes (read from the SVG export); typing 0,25 and 0.25 both work', async () => {
  const problems = [];
  for (const lang of LANGS) {
    const t = await H.open(`?lang=${lang}#bspline-basics`, { viewport: { width: 1366, height: 900 } });
    const p = t.page;
    // the exact-value box of u: a decimal comma, then a point; each moves the state; the box and the slider's
    // value show the comma
    const box = p.locator('input.ctl-number').first();
    for (const [typed, want] of [['0,25', 0.25], ['0.6', 0.6]]) {
      await box.fill(typed);
      await box.press('Enter');
      await p.waitForFunction((w) => window.splinelab.current().state.u === w, want);
    }
    await box.fill('1/6');
    await box.press('Enter');
    await p.waitForFunction(() => Math.abs(window.splinelab.current().state.u - 1 / 6) < 1e-15);
    const note = await p.textContent('.num-note');
    if (note !== '= 0,1666666667') problems.push(`${lang}: the exact value of 1/6 reads “${note}”`);
    // the axes: the SVG export draws the plot's tick labels as text (before the tables open below: a table that
    // appears moves the Export row, and a click aimed at it then missed on CI's loaded machine)
    // (the button's own click, not a mouse at its coordinates: what is checked here is the axes, and the Export
    // row's mouse path is export.test's. A failed export says why in a notice, which leaves after 12 s: every notice
    // is kept for the failure message, with the page's errors)
    const before = await p.$eval('.export-bar', (r) => Number(r.dataset.exported || 0));
    await p.evaluate(() => {
      const seen = (/** @type {any} */ (window).__notices = []);
      new MutationObserver(() => { for (const n of document.querySelectorAll('.notice')) if (!seen.includes(n.textContent)) seen.push(n.textContent); })
        .observe(document.getElementById('notices'), { childList: true, subtree: true });
    });
    await p.$eval('.export-bar button[data-format="svg"]', (b) => /** @type {HTMLElement} */ (b).click());
    await p.waitForFunction((n) => Number(document.querySelector('.export-bar').dataset.exported || 0) > n, before, { timeout: 60000 }).catch(async (e) => {
      throw new Error(`${lang}: the SVG export did not finish: ${e.message}; notices: ${JSON.stringify(await p.evaluate(() => /** @type {any} */ (window).__notices))}; errors: ${t.pageErrors}`);
    });
    const ticks = await p.$eval('.export-bar', (r) => [...new DOMParser().parseFromString(r.lastExport.text, 'image/svg+xml').querySelectorAll('text')].map((x) => x.textContent));
    if (!ticks.some((s) => /^−?\d+,\d+$/.test(s))) problems.push(`${lang}: no axis number with a decimal comma in the SVG: ${ticks.slice(0, 12).join(' | ')}`);
    for (const s of ticks.filter((x) => /\d\.\d/.test(x))) problems.push(`${lang}: SVG text “${s}”`);
    // the figure's table opened, a point chosen with the keyboard (its fields show its coordinates)
    for (const d of await p.$$('details.plot-table')) await d.evaluate((e) => { e.open = true; });
    await p.focus('canvas.plot-canvas');
    await p.keyboard.press('PageDown');
    await p.waitForTimeout(400);
    const texts = await p.evaluate(pageTexts);
    const fields = await p.$$eval('.plot-fields input, input.ctl-number', (xs) => xs.filter((x) => x.getClientRects().length).map((x) => ({ text: x.value, where: 'input' })));
    for (const s of pointDecimals([...texts, ...fields])) problems.push(`${lang}: ${s}`);
    if (!texts.some((x) => /\d,\d/.test(x.text))) problems.push(`${lang}: no number with a decimal comma on the page at all`);
    t.assertClean();
    await t.close();
  }
  assert.deepEqual(problems, []);
});

test('a link made in Slovak opens the same view in English: the same state, the same numbers (with a point)', async () => {
  const sk = await H.open('?lang=sk#bspline-basics', { viewport: { width: 1366, height: 900 } });
  const box = sk.page.locator('input.ctl-number').first();
  await box.fill('0,35');
  await box.press('Enter');
  // a control point moved with the keyboard too
  await sk.page.focus('canvas.plot-canvas');
  await sk.page.keyboard.press('PageDown');
  await sk.page.keyboard.press('Shift+ArrowUp');
  await sk.page.evaluate(() => window.splinelab.flush());
  const made = await sk.page.evaluate(() => window.splinelab.current());
  assert.equal(made.state.u, 0.35);
  const readSk = await sk.page.$$eval('table.ctl-table td', (xs) => xs.map((x) => x.textContent));
  const hash = await sk.page.evaluate(() => location.hash);
  await sk.close();
  const en = await H.open(`?lang=en${hash}`, { viewport: { width: 1366, height: 900 } });
  const opened = await en.page.evaluate(() => window.splinelab.current());
  assert.deepEqual(opened.state, made.state);
  const readEn = await en.page.$$eval('table.ctl-table td', (xs) => xs.map((x) => x.textContent));
  assert.ok(readSk.length > 2 && readSk.some((s) => s.includes(',')), `Slovak readouts: ${readSk}`);
  assert.deepEqual(readSk.map((s) => s.replace(',', '.')), readEn);
  assert.equal(await en.page.evaluate(() => document.documentElement.lang), 'en');
  await en.close();
});

test('the language menu, with the keyboard: it names each language in itself; arrows do not reload; Enter on Magyar switches the page, keeps the view, and is remembered', async () => {
  const t = await H.open('#bspline-basics', { viewport: { width: 1366, height: 900 } });
  const p = t.page;
  const box = p.locator('input.ctl-number').first();
  await box.fill('0.3');
  await box.press('Enter');
  await p.evaluate(() => window.splinelab.flush());
  const state = await p.evaluate(() => window.splinelab.current().state);
  // the keyboard: Tab to the menu's button (it is the first control after the brand), Enter opens the list
  await p.focus('.brand');
  await p.keyboard.press('Tab');
  assert.equal(await p.evaluate(() => document.activeElement.className), 'lang-toggle');
  assert.equal(await p.getAttribute('.lang-toggle', 'aria-expanded'), 'false');
  await p.keyboard.press('ArrowDown');   // a <select> would have changed the language (and reloaded) here
  await p.keyboard.press('Enter');
  assert.equal(await p.getAttribute('.lang-toggle', 'aria-expanded'), 'true');
  assert.deepEqual(await p.$$eval('.lang-choice', (bs) => bs.map((b) => [b.dataset.lang, b.textContent, b.lang, b.getAttribute('aria-current')])),
    [['en', 'English', 'en', 'true'], ['sk', 'Slovenčina', 'sk', null], ['ro', 'Română', 'ro', null], ['hu', 'Magyar', 'hu', null], ['it', 'Italiano', 'it', null]]);
  // Escape closes it and gives the focus back; Enter opens it again; Tab × 4 reaches Magyar
  await p.keyboard.press('Escape');
  assert.equal(await p.isVisible('.lang-list'), false);
  assert.equal(await p.evaluate(() => document.activeElement.className), 'lang-toggle');
  await p.keyboard.press('Enter');
  for (let i = 0; i < 4; i++) await p.keyboard.press('Tab');
  assert.equal(await p.evaluate(() => document.activeElement.textContent), 'Magyar');
  assert.equal(await p.evaluate(() => document.documentElement.lang), 'en', 'nothing switched before a language was pressed');
  await Promise.all([p.waitForNavigation(), p.keyboard.press('Enter')]);
  await t.ready();
  assert.equal(await p.evaluate(() => document.documentElement.lang), 'hu');
  assert.deepEqual(await p.evaluate(() => window.splinelab.current().state), state, 'the view is kept');
  assert.match(await p.textContent('.lang-toggle'), /Magyar/);
  assert.doesNotMatch(await p.textContent('.lang-toggle'), /Language/, 'the menu\'s own word is Hungarian');
  // remembered: a plain link (no lang=) opens in Hungarian
  await p.goto(`${H.base}#bspline-basics`);
  await t.ready();
  assert.equal(await p.evaluate(() => document.documentElement.lang), 'hu');
  await t.close();
});

test('the language menu on a phone, by touch: tap the button, tap Italiano', async () => {
  const t = await H.open('', { viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });
  const p = t.page;
  await p.tap('.lang-toggle');
  await Promise.all([p.waitForNavigation(), p.tap('.lang-choice[data-lang="it"]')]);
  await t.ready();
  assert.equal(await p.evaluate(() => document.documentElement.lang), 'it');
  // the list fits the phone's width
  await p.tap('.lang-toggle');
  const r = await p.$eval('.lang-list', (l) => { const b = l.getBoundingClientRect(); return [b.left, b.right]; });
  assert.ok(r[0] >= 0 && r[1] <= 390, `the list inside the screen: ${r}`);
  await t.close();
});

test('<spline-lab lang="it"> and embed.html?lang=ro: the figure in that language, the course page\'s own lang untouched', async () => {
  const t = await H.open('', { viewport: { width: 1280, height: 900 } });
  const p = t.page;
  // an English course page on the SplineLab host (a page of its own, served by the test) with an Italian figure
  await p.route(`${H.base}i18n-course-page.html`, (route) => route.fulfill({ contentType: 'text/html; charset=utf-8',
    body: '<!doctype html><html lang="en"><head><meta charset="utf-8"><title>A course page</title><script type="module" src="spline-lab.js"></script></head><body><h1>Splines, week 3</h1><spline-lab demo="bspline-basics" lang="it"></spline-lab></body></html>' }));
  await p.goto(`${H.base}i18n-course-page.html`);
  await p.waitForFunction(() => document.querySelector('spline-lab')?.dataset.ready === 'true', null, { timeout: 30000 });
  const it = await p.evaluate(() => {
    const r = document.querySelector('spline-lab').shadowRoot;
    return { lang: r.querySelector('.sl-el-body').lang, step: r.querySelector('.step-forward').textContent, page: document.documentElement.lang };
  });
  assert.equal(it.lang, 'it');
  assert.equal(it.page, 'en', 'the course page keeps its lang');
  assert.doesNotMatch(it.step, /^Step\b/);
  await t.close();
  const e = await H.open('embed.html?lang=ro#bspline-basics', { viewport: { width: 1280, height: 900 } });
  assert.equal(await e.page.evaluate(() => document.documentElement.lang), 'ro');
  assert.doesNotMatch(await e.page.textContent('.step-forward'), /^Step\b/);
  await e.close();
});
