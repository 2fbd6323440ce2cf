// Formulas read aloud (issue 25): every typeset formula (<math>) carries its reading in words as aria-label, which a
// screen reader without MathML support speaks (www/lib/math-speech.js); the words follow the formula's structure
// (checked on known formulas), and no formula on any page or in any demo is left without one or with TeX/ASCII
// notation in it ("N_i,p", "L^a", "\alpha").
// Run: node --test tests/e2e/math-speech.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness, demoIds } from './harness.mjs';

let H;
let ids;
before(async () => { H = await startHarness(); ids = await demoIds(); });
after(async () => { await H?.close(); });

test('known formulas are read in words that follow their structure', async () => {
  const t = await H.open('guide.html', { ready: false });
  await t.page.waitForLoadState('load');
  const cases = [
    ['N_{i,p}(u)', 'N sub i comma p end sub (u)'],
    ['L^a = 6a\\,L^B + (1 - 6a)\\,L', 'L superscript a equals 6 a L superscript B plus (1 minus 6 a) L'],
    ['\\frac{m^{2}}{m^{2} - 1}', 'fraction m squared over m squared minus 1 end fraction'],
    ['\\frac{1}{6}', '1 over 6'],
    ['b^{*}_{(m+1)I}', 'b sub (m plus 1) I end sub star'],
    ['\\alpha_k^{(I)} \\in (0, 1)', 'alpha sub k superscript (I) end superscript in (0 comma 1)'],
    ['\\sum_{i \\le 3} C_{ij} B_{ij}', 'sum sub i less than or equal to 3 end sub C sub i j end sub B sub i j end sub'],
    ['\\sqrt{\\mathrm{CV}(a)}', 'square root of CV (a) end root'],
    ['\\|S - G\\|_\\infty', 'norm S minus G norm sub infinity'],
    ['L_{12}', 'L sub 12'],
    ['\\bar{x}', 'x bar'],
  ];
  const got = await t.page.evaluate(async (tex) => {
    const { math } = await import('./lib/mathml.js');
    return tex.map((x) => math(x).getAttribute('aria-label'));
  }, cases.map((c) => c[0]));
  assert.deepEqual(got, cases.map((c) => c[1]));
  // a label given by the caller wins
  assert.equal(await t.page.evaluate(async () => (await import('./lib/mathml.js')).math('x', { label: 'the x' }).getAttribute('aria-label')), 'the x');
  await t.close();
});

/** Every <math> of the page (light DOM and open shadow roots): its TeX (when typeset by mathml.js) and aria-label. */
const formulas = (t) => t.page.evaluate(() => {
  const out = [];
  const walk = (root) => {
    for (const m of root.querySelectorAll('math')) out.push({ tex: m.getAttribute('data-tex') || m.outerHTML.slice(0, 120), label: m.getAttribute('aria-label') });
    for (const e of root.querySelectorAll('*')) if (e.shadowRoot) walk(e.shadowRoot);
  };
  walk(document);
  return out;
});
/** The formulas without a reading in words, or with notation in it. */
const unread = (list) => list.filter((f) => !f.label || !f.label.trim() || /[_^\\{}]/.test(f.label));

test('every formula of every page and every demo has a reading in words', async () => {
  // the pages, each with its formulas as shipped (the guide's are written in the HTML, so their labels are too)
  let count = 0;
  for (const page of ['guide.html', 'papers.html', 'exercises.html']) {
    const t = await H.open(page, { ready: false });
    await t.page.waitForLoadState('load');
    await t.frames(2);
    const list = await formulas(t);
    count += list.length;
    assert.deepEqual(unread(list), [], `${page}: formulas without a reading`);
    if (page === 'guide.html') {
      // the hand-written labels say what mathSpeech says of the same MathML
      const wrong = await t.page.evaluate(async () => {
        const { mathSpeech } = await import('./lib/math-speech.js');
        return [...document.querySelectorAll('math')].filter((m) => m.getAttribute('aria-label') !== mathSpeech(m)).map((m) => `${m.getAttribute('aria-label')} ≠ ${mathSpeech(m)}`);
      });
      assert.deepEqual(wrong, []);
    }
    await t.close();
  }
  // the demos, one page: each route mounted in turn (explanation, legends, readouts, stepper)
  const t = await H.open(`#${ids[0]}`);
  for (const id of ids) {
    if (id !== ids[0]) {
      await t.page.evaluate((x) => { location.hash = `#${x}`; }, id);
      await t.page.waitForFunction((x) => document.body.dataset.demo === x && document.querySelector('#demo-root[data-mounted="true"]'), id, { timeout: 20000 });
    }
    const list = await formulas(t);
    assert.ok(list.length > 0, `${id}: shows formulas`);
    count += list.length;
    assert.deepEqual(unread(list), [], `${id}: formulas without a reading`);
  }
  t.assertClean();
  await t.close();
  assert.ok(count > 100, `${count} formulas checked`);
});
