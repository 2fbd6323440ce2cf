// Issue 28 for the exercises: the catalogue page (www/exercises.html), the student's panel and the teacher's
// "Make exercise" panel (www/lib/exercise.js) in Slovak, Romanian, Hungarian and Italian.
//
// As tests/e2e/i18n.test.mjs does for the gallery: each page is opened in English and in each language, and every
// visible text, aria-label, title and placeholder (tests/e2e/i18n-texts.mjs) that the language's page shows exactly
// as the English page does is a failure, unless it is on the reviewed list SAME; so is a text the catalogue lacks
// (the page's missingKeys()), and <html lang> must be the language. Two checks per page:
//   * the exercises' own texts: the catalogue page without its language menu, and on an exercise link the panels
//     .exercise-panel and .exercise-make (www/lang/<code>/exercises.js);
//   * the whole page: also the shell's and the demo's texts (core.js, demos.js), and every missing key.
// And a student solves one exercise in Slovak with the controls (a value typed with a decimal comma): the feedback
// is the Slovak text, its numbers with a decimal comma.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';
import { pageTexts } from './i18n-texts.mjs';
import { PAPERS } from '../../www/lib/papers-ref.js';

const LANGS = ['sk', 'ro', 'hu', 'it'];

/**
 * Texts that are the same in a language as in English (reviewed): names, and the papers' titles as printed (a
 * citation is not translated). A text is allowed when the whole text is on the list.
 */
const SAME_EVERYWHERE = ['SplineLab', 'Spline', 'Lab', 'SCORM', 'LMS', 'English', 'Slovenčina', 'Română', 'Magyar', 'Italiano', 'B-spline', 'Bézier',
  'PNG', 'SVG', 'SVG 1', 'SVG 2', 'SVG 3', 'JSON', 'CSV',
  ...PAPERS.map((p) => `${p.authors}: ${p.title}`), ...PAPERS.map((p) => p.title)];
const SAME = { sk: [], ro: [], hu: [], it: ['Link', 'Sandbox'] };

/** The exercise the link checks open: the catalogue's card on the B-spline basics (a demo translated in full). */
const CARD = 'bspline-c2';
/** The exercise a student solves in Slovak: a value typed into the box of "Approximation a". */
const SOLVE = 'noisy-sine';

let H;
before(async () => { H = await startHarness(); });
after(() => H?.close());

/** `href` (index.html#…) with `?lang=xx` before its hash. */
const withLang = (href, lang) => href.replace(/^([^#]*)/, (m) => `${m}${m.includes('?') ? '&' : '?'}lang=${lang}`);

/** The English page's card links, by exercise id (opened once). */
let cards;
async function cardLinks() {
  if (cards) return cards;
  const t = await H.open('exercises.html');
  cards = Object.fromEntries(await t.page.$$eval('.exercise-card', (cs) => cs.map((c) => [c.dataset.exercise, c.querySelector('.exercise-open').getAttribute('href')])));
  await t.close();
  return cards;
}

/** Runs in the page: every text node and aria-label, title, placeholder of the elements of `sel` (normalised). */
function textsIn(sel) {
  const out = [];
  for (const r of document.querySelectorAll(sel)) {
    const walker = document.createTreeWalker(r, NodeFilter.SHOW_TEXT);
    for (let n = walker.nextNode(); n; n = walker.nextNode()) out.push(n.textContent.replace(/\s+/g, ' ').trim());
    for (const el of [r, ...r.querySelectorAll('*')]) {
      for (const a of ['aria-label', 'title', 'placeholder']) { const v = el.getAttribute(a); if (v) out.push(v.replace(/\s+/g, ' ').trim()); }
    }
  }
  return out;
}

/**
 * Opens `route` and reads { lang, missing, all (the page's texts), own (the texts of `region`) }. `prepare(t)` opens
 * what shows more text first (a panel, a Check).
 */
async function textsOf(route, { region, prepare, waitFor } = {}) {
  const t = await H.open(route, { viewport: { width: 1366, height: 900 }, waitFor });
  if (prepare) await prepare(t);
  const all = await t.page.evaluate(pageTexts);
  const info = await t.page.evaluate(() => {
    const i18n = window.splinelab?.i18n || window.splinelabExercises?.i18n;
    return { lang: document.documentElement.lang, missing: i18n ? i18n.missingKeys() : ['(the page does not expose its i18n)'] };
  });
  // the exercise texts: those of the page's texts that are in the elements of `region`
  const mine = new Set(await t.page.evaluate(textsIn, region));
  const own = all.filter((x) => x.where !== 'title' && mine.has(x.text));
  await t.close();
  return { all, own, ...info };
}

/** The texts of `there` that are exactly a text of `english` and not on the language's list of same words. */
function stillEnglish(english, there, lang) {
  const en = new Set(english.map((x) => x.text));
  const same = new Set([...SAME_EVERYWHERE, ...SAME[lang]]);
  return there.filter((x) => en.has(x.text) && !same.has(x.text));
}

/** Runs the two checks of one page: its exercise texts (`own`) and the whole page (`all`, missing keys). */
async function checkPage(tt, route, o) {
  const en = await textsOf(route('en'), o);
  assert.equal(en.lang, 'en');
  assert.ok(en.own.length > 10, `the English page has exercise texts: ${en.own.length}`);
  const own = [], whole = [];
  for (const lang of LANGS) {
    const x = await textsOf(route(lang), o);
    if (x.lang !== lang) own.push(`${lang}: <html lang="${x.lang}">`);
    for (const s of stillEnglish(en.own, x.own, lang)) own.push(`${lang}: English in the exercise texts: “${s.text}” (${s.where})`);
    for (const k of x.missing) whole.push(`${lang}: the catalogue lacks “${k}”`);
    for (const s of stillEnglish(en.all, x.all, lang)) if (!own.some((p) => p.includes(`“${s.text}”`))) whole.push(`${lang}: English on the page: “${s.text}” (${s.where})`);
  }
  await tt.test('the exercise texts are translated and <html lang> follows', () => assert.deepEqual(own, []));
  await tt.test('the whole page: no English text, no missing key (with the shell and demo texts of core.js, demos.js)', () => assert.deepEqual(whole, []));
}

test('exercises.html in sk, ro, hu and it', async (tt) => {
  await checkPage(tt, (lang) => (lang === 'en' ? 'exercises.html' : `exercises.html?lang=${lang}`), { region: 'header .brand, header .tagline, main, footer' });
});

test(`an exercise link (the catalogue's ${CARD}) in sk, ro, hu and it: the student's panel after a Check, and Make exercise`, async (tt) => {
  const href = (await cardLinks())[CARD];
  assert.ok(href, `the catalogue has ${CARD}`);
  const prepare = async (t) => {
    const p = t.page;
    await p.click('.exercise-panel .exercise-check');
    await p.waitForFunction(() => document.querySelector('.exercise-feedback').textContent !== '');
    await p.click('button.exercise-make-toggle');
    await p.waitForFunction(() => document.querySelector('.exercise-make-now').textContent !== '');
  };
  await checkPage(tt, (lang) => (lang === 'en' ? href : withLang(href, lang)), { region: '.exercise-panel, .exercise-make, .exercise-make-toggle', prepare, waitFor: '.exercise-panel' });
});

test(`in Slovak a student solves ${SOLVE} with a value typed with a decimal comma: Slovak feedback with decimal commas`, async () => {
  const href = (await cardLinks())[SOLVE];
  // the box of "Approximation a": found by its English name, then taken by its place (its name is Slovak in sk)
  const en = await H.open(href, { viewport: { width: 1366, height: 900 }, waitFor: '.exercise-panel' });
  const at = await en.page.$$eval('input.ctl-number', (els) => els.findIndex((el) => (el.getAttribute('aria-label') || '').startsWith('Approximation a')));
  await en.close();
  assert.ok(at >= 0, 'the demo has the number box of a');

  const t = await H.open(withLang(href, 'sk'), { viewport: { width: 1366, height: 900 }, waitFor: '.exercise-panel' });
  const p = t.page;
  assert.equal(await p.evaluate(() => document.documentElement.lang), 'sk');
  assert.equal((await p.textContent('.exercise-check')).trim(), 'Skontrolovať');
  assert.equal((await p.textContent('.exercise-attempts')).trim(), '0 pokusov');
  const press = async () => {
    const before = await p.textContent('.exercise-attempts');
    await p.click('.exercise-panel .exercise-check');
    await p.waitForFunction((b) => document.querySelector('.exercise-attempts').textContent !== b, before, { timeout: 20000 });
    return (await p.textContent('.exercise-feedback')).trim();
  };
  const wrong = await press();
  assert.match(wrong, /^Ešte nie\. Stredná kvadratická vzdialenosť od skutočnej sínusoidy: \d+,\d+; tolerancia je 0,17/, wrong);
  assert.match(wrong, / Nápoveda: /, 'the catalogue exercise\'s hint, in Slovak');
  assert.equal((await p.textContent('.exercise-attempts')).trim(), '1 pokus');
  const box = p.locator('input.ctl-number').nth(at);
  await box.fill('0,2');
  await box.press('Enter');
  await t.frames(3);
  const right = await press();
  assert.match(right, /^Správne! Stredná kvadratická vzdialenosť od skutočnej sínusoidy: 0,\d+, v rámci tolerancie 0,17\.$/, right);
  assert.doesNotMatch(right, /\d\.\d/, 'no decimal point in a Slovak number');
  assert.equal((await p.textContent('.exercise-attempts')).trim(), '2 pokusy');
  // the panel's own texts are none of the missing keys (the demo's own texts are demos.js's: tests/e2e/i18n.test.mjs)
  assert.deepEqual(await p.evaluate(() => window.splinelab.i18n.missingKeys().filter((k) => /^(Correct!|Not yet|Hint:|Exercise|Check$|\{n\} attempt|RMS distance to the true sine$|Q = )/.test(k))), []);
  // the state itself keeps the number (a = 0.2), not a text
  assert.equal(await p.evaluate(() => window.splinelab.current().state.a), 0.2);
  await t.close();
});
