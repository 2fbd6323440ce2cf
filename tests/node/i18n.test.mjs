// Issue 28: the language layer (www/lib/i18n.js) and the catalogues (www/lang/<code>.js), in Node.
// The pages in each language are checked end to end by tests/e2e/i18n.test.mjs; this file checks what a
// catalogue must be (every translation keeps the English text's placeholders; plural entries have exactly the
// language's CLDR categories; no translation is left as the English text unless reviewed) and the helpers'
// numbers, plurals, lists and error texts in Slovak.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { setLocale, t, tn, num, list, localeOf, chooseLocale, decimalSeparator, missingKeys, translateIfKnown } from '../../www/lib/i18n.js';
import { fmt, pair } from '../../www/lib/dom.js';
import { parseNumber, formatNumber } from '../../www/lib/number-input.js';
import { errorText, ERROR_TEXTS } from '../../www/lib/error-text.js';
import { sameAllowed } from '../fixtures/i18n-same.mjs';

const LANGS = ['sk', 'ro', 'hu', 'it'];
const catalogue = async (c) => (await import(`../../www/lang/${c}.js`)).default;
const placeholders = (s) => [...s.matchAll(/\{(\w+)\}/g)].map((m) => m[1]).sort();
test('each catalogue: a translation keeps the placeholders of its English text; a plural entry has exactly the language\'s CLDR forms', async () => {
  const problems = [];
  for (const c of LANGS) {
    const cat = await catalogue(c);
    const forms = new Intl.PluralRules(c).resolvedOptions().pluralCategories.slice().sort();
    for (const [en, v] of Object.entries(cat)) {
      const want = placeholders(en);
      if (typeof v === 'string') {
        if (JSON.stringify(placeholders(v)) !== JSON.stringify(want)) problems.push(`${c}: “${en}” → “${v}”: placeholders ${placeholders(v)} ≠ ${want}`);
        if (v === en && !sameAllowed(c, en) && /(?:(?!\p{Lm})\p{L}){2}/u.test(en)) problems.push(`${c}: “${en}” is left in English`);
        if (v.trim() === '') problems.push(`${c}: “${en}” is empty`);
      } else if (v && typeof v === 'object') {
        if (JSON.stringify(Object.keys(v).sort()) !== JSON.stringify(forms)) problems.push(`${c}: plural “${en}” has forms ${Object.keys(v)}, the language has ${forms}`);
        // (a form may leave out the count, as English "one inflection" does; it may not bring another placeholder)
        for (const [f, s] of Object.entries(v)) if (placeholders(s).some((p) => !want.includes(p))) problems.push(`${c}: plural “${en}” (${f}) → “${s}”: placeholders differ`);
      } else problems.push(`${c}: “${en}” is neither a text nor plural forms`);
    }
  }
  assert.deepEqual(problems, []);
});

test('the four catalogues have the same keys, and every error text of the module\'s error kinds', async () => {
  const sk = Object.keys(await catalogue('sk')).sort();
  for (const c of ['ro', 'hu', 'it']) {
    const keys = Object.keys(await catalogue(c)).sort();
    assert.deepEqual(keys.filter((k) => !sk.includes(k)), [], `${c} has keys sk lacks`);
    assert.deepEqual(sk.filter((k) => !keys.includes(k)), [], `${c} lacks keys sk has`);
  }
  for (const c of LANGS) {
    const cat = await catalogue(c);
    assert.deepEqual(ERROR_TEXTS.filter((k) => typeof cat[k] !== 'string'), [], `${c}: error texts`);
  }
});

test('a text is in one part of a catalogue only (core, exercises, demos, math): the same key twice would let the later part win silently', async () => {
  const dup = [];
  for (const c of LANGS) {
    const seen = new Map();
    for (const part of ['core', 'exercises', 'demos', 'math']) {
      for (const k of Object.keys((await import(`../../www/lang/${c}/${part}.js`)).default)) {
        if (seen.has(k)) dup.push(`${c}: “${k}” in ${seen.get(k)} and ${part}`);
        else seen.set(k, part);
      }
    }
  }
  assert.deepEqual(dup, []);
});

test('choosing the language: lang= first, then the element\'s attribute; region tags and case are read; unknown ones are not', () => {
  assert.equal(localeOf('sk-SK'), 'sk');
  assert.equal(localeOf('HU'), 'hu');
  assert.equal(localeOf('de'), null);
  assert.equal(localeOf(''), null);
  assert.equal(chooseLocale({ param: 'it', attr: 'ro' }), 'it');
  assert.equal(chooseLocale({ param: 'xx', attr: 'ro-RO' }), 'ro');
});

test('in Slovak: texts, plurals, the decimal comma, pairs with a semicolon, lists, typed numbers with a comma', async () => {
  try {
    assert.equal(await setLocale('sk'), 'sk');
    assert.equal(decimalSeparator(), ',');
    assert.equal(num(0.25), '0,25');
    assert.equal(num(-1.5, 2), '−1,5');
    assert.equal(num(-0.0001), '0');
    assert.equal(fmt(2.2), '2,2');
    assert.equal(pair(0.25, 1.5), '(0,25; 1,5)');
    assert.equal(list(['a', 'b', 'c']), 'a, b a c');
    // typed with a comma or a point, both read; the box shows the comma
    assert.deepEqual(parseNumber('0,25'), { ok: true, value: 0.25 });
    assert.deepEqual(parseNumber('0.25'), { ok: true, value: 0.25 });
    assert.deepEqual(parseNumber('1/6'), { ok: true, value: 1 / 6 });
    assert.equal(formatNumber(1 / 6), '0,1666666667');
    // a text of the catalogue, with a number filled in; a count with the Slovak plural forms
    const cat = await catalogue('sk');
    const plural = Object.entries(cat).find(([, v]) => typeof v === 'object');
    assert.ok(plural, 'the Slovak catalogue has a plural entry');
    const [other, forms] = plural;
    assert.equal(tn(1, 'one', other), forms.one.replace('{n}', '1'));
    assert.equal(tn(3, 'one', other), forms.few.replace('{n}', '3'));
    assert.equal(tn(7, 'one', other), forms.other.replace('{n}', '7'));
    assert.equal(t('Reset'), cat.Reset);
    // a text the catalogue lacks: English, and counted; a person's own text: as typed, not counted
    assert.equal(t('A text no catalogue has, {n}', { n: 0.5 }), 'A text no catalogue has, 0,5');
    assert.ok(missingKeys().includes('A text no catalogue has, {n}'));
    assert.equal(translateIfKnown('Moja vlastná úloha'), 'Moja vlastná úloha');
    assert.ok(!missingKeys().includes('Moja vlastná úloha'));
    // translating twice changes nothing (a control translates the label a demo translated)
    assert.equal(t(t('Reset')), cat.Reset);
    // an error of the module: built from .field and .kind, not its English message
    const e = Object.assign(new Error('points: need at least 4 control points (n ≥ 1 segment), got 3'), { field: 'points', kind: 'too-few', expected: 4, got: 3 });
    const sk = errorText(e);
    assert.notEqual(sk, e.message);
    assert.equal(sk, cat['{field}: too few (at least {expected} needed, {got} given)'].replace('{field}', 'points').replace('{expected}', '4').replace('{got}', '3'));
    assert.equal(errorText(new Error('Nejaká chyba stránky')), 'Nejaká chyba stránky', 'an error without a kind is shown as it is');
  } finally {
    await setLocale('en');
  }
  // English: the module's own message, the decimal point
  const e = Object.assign(new Error('a: not a finite number'), { field: 'a', kind: 'not-finite' });
  assert.equal(errorText(e), 'a: not a finite number');
  assert.equal(num(0.25), '0.25');
  assert.equal(pair(0.25, 1.5), '(0.25, 1.5)');
});
