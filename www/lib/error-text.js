// An error of the SplineLab module, as the page shows it in the reader's language. The module's errors carry
// `.field` (which input: "points[3][1]", "a", "curve.order") and `.kind` (one of the stable kinds of docs/API.md:
// missing, wrong-type, not-finite, too-few, too-many, out-of-range, not-increasing, incompatible, degenerate,
// invalid), and for counts `.expected` and `.got`. In English the module's own message is shown (it says the
// most); in another language a message built from those facts, never the English text:
//
//   errorText(e)   → 'points: príliš málo (potrebných aspoň 4, zadaných 3)'   (sk)
//
// An error without a kind (a page's own, already in the language) is shown as it is.

import { t, locale, num } from './i18n.js';

/** The sentence for each kind; {field}, {expected}, {got} filled from the error. */
const KIND = {
  missing: '{field}: a value is missing',
  'wrong-type': '{field}: a value of the wrong type',
  'not-finite': '{field}: not a finite number',
  'too-few': '{field}: too few (at least {expected} needed, {got} given)',
  'too-many': '{field}: too many (at most {expected} allowed, {got} given)',
  'out-of-range': '{field}: out of its range',
  'not-increasing': '{field}: the values must increase',
  incompatible: '{field}: does not agree with the other inputs',
  degenerate: '{field}: degenerate (coincident points or a singular system)',
  invalid: '{field}: not a valid value',
};

/** The text of `e` for the page (an Error, a string or anything else). @param {unknown} e */
export function errorText(e) {
  if (!(e instanceof Error)) return String(e);
  const x = /** @type {Error & { kind?: string, field?: string, expected?: number, got?: number }} */ (e);
  if (locale() === 'en' || !x.kind || !Object.hasOwn(KIND, x.kind)) return x.message;
  // a counting error whose bound is not known says only "too few" / "too many"
  const key = (x.kind === 'too-few' || x.kind === 'too-many') && !(Number.isFinite(x.expected) && Number.isFinite(x.got))
    ? (x.kind === 'too-few' ? '{field}: too few' : '{field}: too many') : KIND[x.kind];
  return t(key, { field: x.field || '?', expected: Number.isFinite(x.expected) ? num(/** @type {number} */ (x.expected), 6) : '', got: Number.isFinite(x.got) ? num(/** @type {number} */ (x.got), 6) : '' });
}

/** Every sentence errorText can ask for (a translator's list; the node test checks each catalogue has them). */
export const ERROR_TEXTS = [...Object.values(KIND), '{field}: too few', '{field}: too many'];
