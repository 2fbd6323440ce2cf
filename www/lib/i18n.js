// The page's language: which one (en, sk, ro, hu, it), its catalogue, and the words and numbers in it.
//
//   await startLocale({ param, attr })   → 'sk'   (chooses, loads www/lang/sk.js, sets <html lang>)
//   t('Reset')                          → 'Obnoviť'
//   t('Degree p = {p}', { p: 3 })       → 'Stupeň p = 3'
//   tn(5, '{n} point', '{n} points')    → '5 bodov'      (Intl.PluralRules: one / few / many / other)
//   num(0.25)                           → '0,25'         (the decimal separator of the language)
//   list(['a', 'b', 'c'])               → 'a, b a c'     (Intl.ListFormat)
//
// The English text is the key (as gettext's msgid): a string that a catalogue does not have is shown in English,
// never as a key, and is counted in `missingKeys()`; `node scripts/i18n-keys.mjs --check` lists every t()/tn()
// string of www/ and fails on one that a catalogue lacks. A catalogue is a plain object, English → translation; a
// plural entry is keyed by the English plural form and holds the language's forms { one, few, many, other }.
// Numbers in links, JSON, CSV and code are never formatted here: they keep the decimal point in every language.
//
// The choice, first that applies: an explicit `lang=` (link, embed.html parameter) or the `lang` attribute of
// <spline-lab>; the reader's earlier choice (localStorage, where storage works); the browser's languages; English.

/** The languages, each named in itself (the menu shows these). */
export const LOCALES = /** @type {const} */ ({ en: 'English', sk: 'Slovenčina', ro: 'Română', hu: 'Magyar', it: 'Italiano' });

/** One explicit import() per language, so the bundlers make one chunk each: a page loads its own language only. */
/** @type {Record<string, () => Promise<{ default: Record<string, string | Record<string, string>> }>>} */
const CATALOGUES = {
  sk: () => import('../lang/sk.js'),
  ro: () => import('../lang/ro.js'),
  hu: () => import('../lang/hu.js'),
  it: () => import('../lang/it.js'),
};

const STORE_KEY = 'splinelab:lang';
/** Words: two letters in a row, not counting modifier letters (Nᵢ,ₚ, P₀ are notation). */
const WORDS = /(?:(?!\p{Lm})\p{L}){2}/u;

let code = 'en';
/** @type {Record<string, string | Record<string, string>>} */
let catalogue = {};
let decimal = '.';
/** @type {Intl.PluralRules} */
let plurals = new Intl.PluralRules('en');
const missing = new Set();
/** The catalogue's translations (t() of one of them is that text: translating twice changes nothing). */
let translated = new Set();

/** The language code if `s` names one of LOCALES ('sk', 'sk-SK', 'SK'), else null. */
export function localeOf(s) {
  const c = String(s || '').trim().toLowerCase().split(/[-_]/)[0];
  return Object.hasOwn(LOCALES, c) ? c : null;
}

/** The stored choice, or null (storage blocked or empty). */
function stored() {
  try { return localeOf(localStorage.getItem(STORE_KEY)); } catch { return null; }
}

/** The reader's remembered choice, or null (none, or storage blocked). */
export const storedLocale = () => stored();

/** A label in the page's language: a string through t(); an element or a list of nodes (a formula, a link) as it is. */
export const tLabel = (x) => (typeof x === 'string' ? t(x) : x);

/** Remembers the reader's choice where storage works (a blocked storage keeps the choice for this page only). */
export function rememberLocale(c) {
  try { localStorage.setItem(STORE_KEY, c); } catch { /* storage blocked: the link's lang= still carries it */ }
}

/**
 * The language to show: `param` (lang= of the link or of embed.html), then `attr` (<spline-lab lang>), then the
 * stored choice, then the first of the browser's languages that SplineLab has, then English.
 * @param {{ param?: string | null, attr?: string | null }} [given]
 */
export function chooseLocale({ param = null, attr = null } = {}) {
  const nav = typeof navigator === 'undefined' ? [] : (navigator.languages?.length ? navigator.languages : [navigator.language]);
  return localeOf(param) || localeOf(attr) || stored() || nav.map(localeOf).find(Boolean) || 'en';
}

/** The `lang=` of the page's address (query or hash options), or null. */
export function linkLocale() {
  const q = new URLSearchParams(location.search).get('lang');
  const hash = location.hash, i = hash.indexOf('?');
  const h = i >= 0 ? new URLSearchParams(hash.slice(i + 1)).get('lang') : null;
  return h || q;
}

/**
 * Loads the catalogue of `c` and makes it the language of t(), tn(), num() and list(). A catalogue that does not
 * load (offline, a broken chunk) leaves English, and says so in the console.
 * @param {string} c @param {{ documentLang?: boolean }} [opts] documentLang: set <html lang> (pages; not an element)
 */
export async function setLocale(c, { documentLang = true } = {}) {
  const next = localeOf(c) || 'en';
  /** @type {Record<string, string | Record<string, string>>} */
  let cat = {};
  if (next !== 'en') {
    try { cat = (await CATALOGUES[next]()).default; } catch (e) { console.warn(`SplineLab: the ${LOCALES[next]} texts did not load (${e}); showing English`); return setLocale('en', { documentLang }); }
  }
  code = next;
  catalogue = cat;
  translated = new Set(Object.values(cat).flatMap((v) => (typeof v === 'string' ? [v] : Object.values(v))));
  missing.clear();
  plurals = new Intl.PluralRules(code);
  decimal = new Intl.NumberFormat(code).formatToParts(0.5).find((p) => p.type === 'decimal')?.value || '.';
  if (documentLang && typeof document !== 'undefined') document.documentElement.lang = code;
  return code;
}

/** Chooses the language (chooseLocale) and loads it (setLocale). */
export function startLocale(given = {}, opts = {}) {
  return setLocale(chooseLocale(given), opts);
}

/** The current language's code. */
export const locale = () => code;

/** The English strings asked for that the current catalogue does not have (a check reads these). */
export const missingKeys = () => [...missing];

/** Every text t() and tn() were asked for on this page: { texts: [...], plurals: { other: one } } (for translators). */
const asked = new Set();
const askedPlural = new Map();
export const askedKeys = () => ({ texts: [...asked].filter((k) => WORDS.test(k)), plurals: Object.fromEntries(askedPlural) });

/** `{name}` in `s` replaced by `params.name` (numbers with the language's decimal separator). */
function fill(s, params) {
  if (!params) return s;
  return s.replace(/\{(\w+)\}/g, (m, k) => (Object.hasOwn(params, k) ? (typeof params[k] === 'number' ? num(params[k]) : String(params[k])) : m));
}

/** The last texts t() made with their numbers filled in ("Stupeň p = 3"), so that t() of one is that text. */
const recent = new Set();
function made(s) {
  if (recent.size > 2000) recent.clear();
  recent.add(s);
  return s;
}

/**
 * The text `en` in the current language, with `{name}` placeholders filled from `params`. English when the
 * catalogue has no entry (counted in missingKeys()).
 * @param {string} en @param {Record<string, string | number>} [params]
 */
export function t(en, params) {
  // already in the language (a component translates the label a demo translated; a stepper the label its steps
  // filled in): as it is
  if (translated.has(en) || recent.has(en)) return en;
  asked.add(en);
  const v = code === 'en' ? en : catalogue[en];
  if (typeof v === 'string') return params ? made(fill(v, params)) : v;
  // no words (a number, a symbol, a name such as "u"): as it is
  if (WORDS.test(en)) missing.add(en);
  return params ? made(fill(en, params)) : en;
}

/**
 * A text that may be SplineLab's own (a built-in exercise's task) or a person's (a teacher's own task in a link):
 * the catalogue's translation when it has one, else the text as it is, not counted as missing.
 * @param {string} s
 */
export function translateIfKnown(s) {
  if (code === 'en') return s;
  const v = catalogue[s];
  return typeof v === 'string' ? v : s;
}

/**
 * A count with its noun: `tn(n, '{n} point', '{n} points')`. The catalogue's entry is keyed by the English plural
 * and holds the language's CLDR forms ({ one, few, many, other }); `{n}` is the count.
 * @param {number} n @param {string} one @param {string} other @param {Record<string, string | number>} [params]
 */
export function tn(n, one, other, params) {
  const p = { n, ...params };
  askedPlural.set(other, one);
  if (code === 'en') return made(fill(n === 1 ? one : other, p));
  const v = catalogue[other];
  if (v && typeof v === 'object') return made(fill(v[plurals.select(n)] ?? v.other, p));
  missing.add(other);
  return made(fill(n === 1 ? one : other, p));
}

/**
 * A translated text whose `{name}` places hold elements (a link, a formula): the pieces in order, for h() or
 * append(): `withNodes(t('See {eq5} and {claim}.'), { eq5: link, claim: link2 })` → ['See ', link, ' and ', link2, '.'].
 * @param {string} s @param {Record<string, any>} nodes
 */
export const withNodes = (s, nodes) => s.split(/\{(\w+)\}/).map((x, i) => (i % 2 ? nodes[x] ?? `{${x}}` : x)).filter((x) => x !== '');

/** The decimal separator of the current language ('.' or ','). */
export const decimalSeparator = () => decimal;

/**
 * A number's text (already rounded, e.g. from toFixed: '−0.25', '1e-9') with the language's decimal separator.
 * Only for what a person reads; links, JSON, CSV and code keep the point.
 */
export function localDigits(s) {
  return decimal === '.' ? s : s.replace('.', decimal);
}

/** `x` for reading: up to `digits` decimals, trailing zeros trimmed, the language's decimal separator, −0 → 0. */
export function num(x, digits = 3) {
  if (typeof x !== 'number' || !Number.isFinite(x)) return String(x);
  let s = x.toFixed(digits);
  if (s.includes('.')) s = s.replace(/0+$/, '').replace(/\.$/, '');
  if (s === '-0') s = '0';
  return localDigits(s.replace('-', '−'));
}

/** Items joined as the language joins a list ("a, b and c"). */
export function list(items, type = /** @type {'conjunction' | 'disjunction'} */ ('conjunction')) {
  return new Intl.ListFormat(code, { style: 'long', type }).format(items.map(String));
}

/**
 * Translates the static text of a page's HTML: each element with `data-i18n` gets t(its English text) (kept in
 * the attribute, so switching back works), and each attribute named in `data-i18n-attr` ("aria-label title")
 * gets t(its English value).
 * @param {ParentNode} root
 */
export function translateStatic(root = document) {
  for (const el of root.querySelectorAll('[data-i18n]')) {
    const e = /** @type {HTMLElement} */ (el);
    if (!e.dataset.i18n) e.dataset.i18n = e.textContent.trim();
    e.textContent = t(e.dataset.i18n);
  }
  for (const el of root.querySelectorAll('[data-i18n-attr]')) {
    const e = /** @type {HTMLElement} */ (el);
    for (const a of e.dataset.i18nAttr.split(/\s+/).filter(Boolean)) {
      const key = `i18nEn${a.replace(/(^|-)(\w)/g, (m, d, c) => c.toUpperCase())}`;
      if (!e.dataset[key]) e.dataset[key] = e.getAttribute(a) || '';
      e.setAttribute(a, t(e.dataset[key]));
    }
  }
}
