// Number fields that take what a person types: numbers (0.75, 1e-9, 0,75), fractions (1/6), π and simple
// expressions (2/3, π/4, 1 − 1/4, 2π, (1+2)/3) — parsed here, never with eval. Used by every number field
// of www/lib/controls.js (the slider's exact-value box and numberField):
//
//   parseNumber('1/6')              → { ok: true, value: 0.16666666666666666 }
//   parseNumber('1//6')             → { ok: false, error: '…' }
//   numberInput({ label, min, max, value, integer, onCommit(v) }) → { input, note, set(v), setRange(), setDisabled() }
//
// numberInput keeps the typed text (1/6 stays 1/6) and shows the exact value under it (“= 0.1666666667”);
// input out of range is set to the nearest bound and the note says so, naming the field
// (“K: 200 is above the maximum 100; set to 100”); input that is not a number is refused with a note and the
// value stays as it was. A text field (not type=number, which drops “/” and “π” and clamps without a word).

import { h, uniqueId } from './dom.js';
import { t, localDigits } from './i18n.js';

const MAX_LEN = 100;

/** Splits `text` into tokens: { t: 'num', v } | { t: 'op', v: one of + − × ÷ ( ) } | { t: 'pi' }, each with its text `s`.
 * Throws on anything else. */
function tokens(text) {
  const out = [];
  const s = text.replace(/\s+/g, '');
  let i = 0;
  while (i < s.length) {
    const rest = s.slice(i);
    // a decimal number; a comma is read as the decimal point (0,75) since lists are never typed here
    const m = /^(\d+(?:[.,]\d*)?|[.,]\d+)(?:[eE][+\-−]?\d+)?/.exec(rest);
    if (m) { out.push({ t: 'num', v: Number(m[0].replace(',', '.').replace('−', '-')), s: m[0] }); i += m[0].length; continue; }
    const c = s[i];
    if (c === 'π') { out.push({ t: 'pi', s: c }); i += 1; continue; }
    if (/^pi/i.test(rest)) { out.push({ t: 'pi', s: rest.slice(0, 2) }); i += 2; continue; }
    const op = { '+': '+', '-': '-', '−': '-', '–': '-', '*': '*', '×': '*', '·': '*', '/': '/', '÷': '/', ':': '/', '(': '(', ')': ')' }[c];
    if (!op) throw new Error(t('“{c}” cannot be read', { c }));
    out.push({ t: 'op', v: op, s: c });
    i += 1;
  }
  return out;
}

/**
 * Recursive descent over the tokens: expr = term (± term)*, term = factor ((×|÷) factor | factor)*,
 * factor = ± factor | number | π | ( expr ). π or a bracket right after a factor multiplies (2π, 3(1+1)).
 */
function evaluate(toks) {
  let k = 0;
  const peek = () => toks[k];
  const isOp = (v) => peek()?.t === 'op' && peek().v === v;
  const startsFactor = () => { const p = peek(); return p && (p.t === 'pi' || (p.t === 'op' && p.v === '(')); };
  function factor() {
    const p = peek();
    if (!p) throw new Error(t('something is missing at the end'));
    if (p.t === 'op' && (p.v === '-' || p.v === '+')) { k++; const v = factor(); return p.v === '-' ? -v : v; }
    if (p.t === 'num') { k++; return p.v; }
    if (p.t === 'pi') { k++; return Math.PI; }
    if (p.t === 'op' && p.v === '(') {
      k++;
      const v = expr();
      if (!isOp(')')) throw new Error(t('a “)” is missing'));
      k++;
      return v;
    }
    throw new Error(t('“{c}” is not expected there', { c: p.s }));
  }
  function term() {
    let v = factor();
    for (;;) {
      if (isOp('*')) { k++; v *= factor(); } else if (isOp('/')) { k++; v /= factor(); } else if (startsFactor()) v *= factor(); else return v;
    }
  }
  function expr() {
    let v = term();
    for (;;) {
      if (isOp('+')) { k++; v += term(); } else if (isOp('-')) { k++; v -= term(); } else return v;
    }
  }
  const v = expr();
  if (k < toks.length) throw new Error(t('“{c}” is not expected there', { c: toks[k].s }));
  return v;
}

/**
 * Reads a typed number or simple expression. Returns { ok: true, value } or { ok: false, error } (error: why,
 * in words). Division by zero and other non-finite results are refused.
 */
export function parseNumber(text) {
  const s = String(text ?? '').trim();
  if (s === '') return { ok: false, error: t('nothing was typed') };
  if (s.length > MAX_LEN) return { ok: false, error: t('more than {n} characters', { n: MAX_LEN }) };
  try {
    const toks = tokens(s);
    if (!toks.length) return { ok: false, error: t('nothing was typed') };
    const v = evaluate(toks);
    if (!Number.isFinite(v)) return { ok: false, error: t('the result is not a finite number (a division by zero?)') };
    return { ok: true, value: v === 0 ? 0 : v };
  } catch (e) {
    return { ok: false, error: e.message };
  }
}

/** A number as it is written back into a field: at most 10 significant digits, no trailing zeros. */
export function formatNumber(v) {
  return localDigits(String(+Number(v).toPrecision(10)));
}

/** Is `text` just the plain decimal of `v` (then “= …” would only repeat it)? */
function isPlain(text, v) {
  const s = text.trim().replace(',', '.').replace('−', '-');
  return /^[+-]?(\d+\.?\d*|\.\d+)$/.test(s) && Number(s) === v && s.replace(/^[+-]/, '').replace(/^0+(?=\d)/, '').length <= 12;
}

/**
 * A labelled-by-its-control text field for one number. opts:
 *   label      the field's name in messages (“K”, “Approximation a”)
 *   min, max   bounds (input outside is set to the bound, with a note); may change with setRange
 *   integer    whole numbers only (a fraction is rounded, with a note)
 *   value      the start value
 *   onCommit(v)  called with the accepted value on Enter / leaving the field (not for refused input)
 *   attrs      extra attributes for the <input> (class, id, aria-label)
 * Returns { input, note, set(v) (shows v unless the field is being edited), setRange({min, max}), setDisabled(d) }.
 */
/**
 * @param {{ label?: string, min?: number, max?: number, integer?: boolean, value?: number,
 *   onCommit?: (v: number) => void, attrs?: Record<string, any> }} [options]
 */
export function numberInput({ label, min, max, integer = false, value = 0, onCommit, attrs = {} } = {}) {
  const noteId = uniqueId('numnote');
  const input = h('input', {
    type: 'text', inputmode: 'text', autocomplete: 'off', autocapitalize: 'off', spellcheck: 'false', enterkeyhint: 'done',
    value: formatNumber(value), 'aria-describedby': noteId, ...attrs,
  });
  const note = h('p', { class: 'num-note', id: noteId, 'aria-live': 'polite', hidden: true });
  let lo = min, hi = max, current = Number(value), committedText = input.value;

  const say = (text, kind) => {
    note.textContent = text || '';
    note.hidden = !text;
    note.dataset.kind = kind || '';
    if (kind === 'error') input.setAttribute('aria-invalid', 'true'); else input.removeAttribute('aria-invalid');
  };
  const exactNote = (text, v) => (isPlain(text, v) ? '' : `= ${formatNumber(v)}`);

  function commit() {
    const text = input.value;
    if (text === committedText) return;   // unchanged (blur after Enter): nothing to say again
    const r = parseNumber(text);
    if (!r.ok) {
      say(t('{label}: “{text}” is not a number ({why}); it stays {value}. Type e.g. {example}, 1/6 or 2π/3.', { label, text: text.trim().slice(0, 40), why: r.error, value: formatNumber(current), example: localDigits('0.25') }), 'error');
      return;
    }
    let v = r.value;
    const notes = [];
    if (integer && !Number.isInteger(v)) { const w = Math.round(v); notes.push(t('{v} is not a whole number; set to {w}', { v: formatNumber(v), w: String(w) })); v = w; }
    if (lo !== undefined && v < Number(lo)) { notes.push(t('{text} is below the minimum {min}; set to {min}', { text: text.trim(), min: formatNumber(lo) })); v = Number(lo); }
    else if (hi !== undefined && v > Number(hi)) { notes.push(t('{text} is above the maximum {max}; set to {max}', { text: text.trim(), max: formatNumber(hi) })); v = Number(hi); }
    if (notes.length) {
      input.value = formatNumber(v);
      say(`${label}: ${notes.join('; ')}.`, 'warning');
    } else {
      say(exactNote(text, v), 'exact');
    }
    committedText = input.value;
    current = v;
    onCommit && onCommit(v);
  }

  input.addEventListener('change', commit);
  input.addEventListener('keydown', (e) => { if (e.key === 'Enter') { e.preventDefault(); commit(); } });
  input.addEventListener('input', () => { if (note.dataset.kind === 'error') say('', ''); });

  return {
    input, note,
    get: () => current,
    /** Shows `v` (the state moved by another control); a field being edited keeps what is typed. */
    set(v) {
      v = Number(v);
      if (v === current) return;   // e.g. the slider echoing a committed 1/6: the typed text and its note stay
      say('', '');
      current = v;
      if (document.activeElement !== input) { input.value = formatNumber(v); committedText = input.value; }
    },
    /** @param {{ min?: number, max?: number }} [range] */
    setRange({ min: a, max: b } = {}) { if (a !== undefined) lo = a; if (b !== undefined) hi = b; },
    setDisabled(d) { input.disabled = !!d; },
  };
}
