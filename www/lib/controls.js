// Shared, labelled, keyboard-operable controls. Each returns an object `{ el, get(), set(v) }` (set never
// fires the callback) plus extras; put `el` into the page (e.g. the `controls` element of demoLayout).

import { t as translate, tLabel } from './i18n.js';
import { h, fmt, uniqueId, clear, append, balanceWrap } from './dom.js';
import { numberInput } from './number-input.js';

export { balanceWrap };

/** A label or hint in the page's language (www/lib/i18n.js). */
const tl = tLabel;

/** A control's label: text, an element (e.g. a formula), or a list of them. @typedef {string | Node | ReadonlyArray<string | Node | null>} Label */
/** A choice of select() and buttonGroup(): a value (shown as text) or { value, label }. @typedef {unknown | { value: unknown, label?: Label }} Choice */

/**
 * Slider with its value visible (and an optional number field).
 *   slider({ label, min, max, step, value, onInput(v), onChange(v), format(v), ticks, number, hint, name })
 *   ticks:  [{ value, label }] — marks under the track (e.g. a = 0 and a = 1/6)
 *   number: true → an editable number field next to the value (Enter/blur applies; fractions such as 1/6
 *           and π/4 are read, out-of-range input is set to the bound with a note: www/lib/number-input.js)
 * onInput fires continuously while dragging, onChange once on release / Enter.
 */
/**
 * @param {{ label?: Label, min?: number, max?: number, step?: number, value?: number, onInput?: (v: number) => void,
 *   onChange?: (v: number) => void, format?: (v: number) => string, ticks?: ReadonlyArray<{ value: number, label: string }>,
 *   number?: boolean, hint?: Label, name?: string }} [options]
 */
export function slider({ label: label0, min = 0, max = 1, step = 0.01, value = min, onInput, onChange, format, ticks, number = false, hint: hint0, name } = {}) {
  const label = tl(label0), hint = tl(hint0);
  const id = uniqueId('slider');
  const show = format || ((v) => fmt(v, Math.max(0, Math.min(6, -Math.floor(Math.log10(step || 1))))));
  const input = h('input', { type: 'range', id, min, max, step, value, name: name || id, 'aria-valuetext': show(value) });
  const out = h('output', { class: 'ctl-value', for: id }, show(value));
  // the exact-value box (www/lib/number-input.js): takes 0.75, 3/4, 1 − 1/4, π/4; says when it clamps or refuses
  const num = number ? numberInput({
    label: plainLabel(label), min, max, value,
    attrs: { class: 'ctl-number', id: uniqueId('num'), 'aria-label': translate('{label} (exact value)', { label: plainLabel(label) }) },
    onCommit(c) {
      input.value = String(c);
      reflect(c);
      onInput && onInput(c);
      onChange && onChange(c);
    },
  }) : null;
  // the value itself: a range input rounds to its step (1/6 → 0.167), the state and the number box must not
  let cur = Number(value);
  let shown = null; // the text on screen: the same text again writes nothing (demos set sliders in drag frames)
  const reflect = (v) => {
    cur = v;
    const s = show(v);
    if (s !== shown) {
      shown = s;
      out.textContent = s;
      input.setAttribute('aria-valuetext', s);
    }
    num?.set(v);
  };
  reflect(Number(input.value));
  input.addEventListener('input', () => { const v = Number(input.value); reflect(v); onInput && onInput(v); });
  input.addEventListener('change', () => { const v = Number(input.value); onChange && onChange(v); });
  let tickRow = null;
  if (ticks && ticks.length) {
    tickRow = h('div', { class: 'ctl-ticks', 'aria-hidden': 'true' });
    const place = () => {
      clear(tickRow);
      const lo = Number(input.min), hi = Number(input.max);
      for (const t of ticks) {
        const f = (t.value - lo) / (hi - lo);
        if (!(f >= 0 && f <= 1)) continue;
        // the thumb centre travels from half a thumb width to (100% − half a thumb width)
        append(tickRow, h('span', { class: 'ctl-tick', style: { left: `calc(${f * 100}% + ${(0.5 - f) * 20}px)` } }, h('span', { class: 'ctl-tick-label' }, t.label != null ? tl(t.label) : show(t.value))));
      }
    };
    place();
    tickRow.place = place;
  }
  const el = h('div', { class: 'ctl ctl-slider' },
    h('div', { class: 'ctl-head' }, h('label', { for: id }, label), num ? num.input : out),
    num ? num.note : null,
    h('div', { class: 'ctl-track' }, input, tickRow),
    hint ? h('div', { class: 'ctl-hint' }, hint) : null);
  return {
    el, input,
    get: () => cur,
    set(v) { input.value = String(v); reflect(Number(v)); },
    /** @param {{ min?: number, max?: number, step?: number }} range */
    setRange({ min: lo, max: hi, step: st }) {
      const was = `${input.min} ${input.max}`;
      if (lo !== undefined && input.min !== String(lo)) input.min = String(lo);
      if (hi !== undefined && input.max !== String(hi)) input.max = String(hi);
      if (st !== undefined && input.step !== String(st)) input.step = String(st);
      num?.setRange({ min: Number(input.min), max: Number(input.max) });
      if (`${input.min} ${input.max}` !== was) tickRow?.place();
      reflect(Math.min(Number(input.max), Math.max(Number(input.min), cur)));
    },
    setDisabled(d) { input.disabled = !!d; num?.setDisabled(d); },
  };
}

/** Checkbox toggle: toggle({ label, value, onChange(bool), hint }). */
/** @param {{ label?: Label, value?: boolean, onChange?: (v: boolean) => void, hint?: Label }} [options] */
export function toggle({ label: label0, value = false, onChange, hint: hint0 } = {}) {
  const label = tl(label0), hint = tl(hint0);
  const id = uniqueId('toggle');
  const input = h('input', { type: 'checkbox', id, class: 'ctl-switch', role: 'switch', checked: !!value });
  input.addEventListener('change', () => onChange && onChange(input.checked));
  const el = h('div', { class: 'ctl ctl-toggle' }, input, h('label', { for: id }, label), hint ? h('div', { class: 'ctl-hint' }, hint) : null);
  return { el, input, get: () => input.checked, set(v) { input.checked = !!v; }, setDisabled(d) { input.disabled = !!d; } };
}

const normOptions = (options) => options.map((o) => (typeof o === 'object' ? { value: o.value, label: tl(o.label ?? String(o.value)) } : { value: o, label: tl(String(o)) }));

/** Drop-down: select({ label, options: [value | { value, label }], value, onChange(value) }). Values keep their type. */
/** @param {{ label?: Label, options?: ReadonlyArray<Choice>, value?: unknown, onChange?: (v: any) => void }} [options] */
export function select({ label, options = [], value, onChange } = {}) {
  const id = uniqueId('select');
  const opts = normOptions(options);
  const sel = h('select', { id }, opts.map((o, i) => h('option', { value: String(i) }, o.label)));
  const idxOf = (v) => Math.max(0, opts.findIndex((o) => o.value === v));
  sel.value = String(idxOf(value));
  sel.addEventListener('change', () => onChange && onChange(opts[Number(sel.value)].value));
  const el = h('div', { class: 'ctl ctl-select' }, h('label', { for: id }, tl(label)), sel);
  return { el, input: sel, get: () => opts[Number(sel.value)].value, set(v) { sel.value = String(idxOf(v)); }, setDisabled(d) { sel.disabled = !!d; } };
}

/** Button: button({ label, onClick, title, kind: 'primary'|'secondary'|'danger', icon }). */
/** @param {{ label?: Label, onClick?: (e: MouseEvent) => void, title?: string, kind?: 'primary' | 'secondary' | 'danger', ariaLabel?: string }} [options] */
export function button({ label, onClick, title, kind = 'secondary', ariaLabel } = {}) {
  const b = h('button', { type: 'button', class: `btn btn-${kind}`, title: tl(title), 'aria-label': tl(ariaLabel), onclick: (e) => onClick && onClick(e) }, tl(label));
  return { el: b, input: b, get: () => undefined, set() {}, setDisabled(d) { b.disabled = !!d; } };
}

/**
 * Segmented choice (radio group styled as buttons; arrow keys move between options):
 *   buttonGroup({ label, options: [value | { value, label }], value, onChange(value) })
 */
/** @param {{ label?: Label, options?: ReadonlyArray<Choice>, value?: unknown, onChange?: (v: any) => void }} [options] */
export function buttonGroup({ label, options = [], value, onChange } = {}) {
  const name = uniqueId('group');
  const opts = normOptions(options);
  const inputs = opts.map((o, i) => h('input', { type: 'radio', name, id: `${name}-${i}`, value: String(i), checked: o.value === value }));
  inputs.forEach((inp) => inp.addEventListener('change', () => { if (inp.checked) onChange && onChange(opts[Number(inp.value)].value); }));
  const segments = h('div', { class: 'ctl-segments' }, opts.map((o, i) => [inputs[i], h('label', { for: `${name}-${i}` }, o.label)]));
  balanceWrap(segments, 'label');
  const el = h('fieldset', { class: 'ctl ctl-group' }, h('legend', null, tl(label)), segments);
  return {
    el, inputs,
    get: () => { const k = inputs.findIndex((i) => i.checked); return k >= 0 ? opts[k].value : undefined; },
    set(v) { inputs.forEach((inp, i) => { inp.checked = opts[i].value === v; }); },
    setDisabled(d) { inputs.forEach((i) => { i.disabled = !!d; }); },
  };
}

/**
 * Number field: numberField({ label, value, min, max, step, onChange(v) }) — a text field of
 * www/lib/number-input.js: fractions and simple expressions are read; input out of range is set to the bound
 * and input that is not a number is refused, each with a note naming the field. step 1 = whole numbers.
 */
/** @param {{ label?: Label, value?: number, min?: number, max?: number, step?: number | 'any', onChange?: (v: number) => void }} [options] */
export function numberField({ label: label0, value = 0, min, max, step = 'any', onChange } = {}) {
  const label = tl(label0);
  const id = uniqueId('number');
  const field = numberInput({ label: plainLabel(label), min, max, value, integer: step === 1, attrs: { id, class: 'ctl-number' }, onCommit: (v) => onChange && onChange(v) });
  const el = h('div', { class: 'ctl ctl-numberfield' }, h('label', { for: id }, label), field.input, field.note);
  return { el, input: field.input, get: () => field.get(), set(v) { field.set(v); }, setDisabled(d) { field.setDisabled(d); } };
}

/** A label as plain text for messages (a label may be an element or a list of nodes). */
function plainLabel(label) {
  if (typeof label === 'string') return label;
  const box = h('span', null, label);
  return box.textContent.trim() || translate('This field');
}

/**
 * A labelled read-only value: readout({ label, value }) → set(text). A value stays on one line ("5.55e-17" never
 * splits); `prose: true` is for a sentence, which wraps under its label in the panel's width between words, never
 * inside one (each word is a nowrap span, class ctl-readout-list: tests/e2e/lecture-shell.test.mjs checks it).
 */
/** @param {{ label?: Label, value?: string | number, prose?: boolean }} [options] */
export function readout({ label, value = '', prose = false } = {}) {
  const v = h('output', { class: prose ? 'ctl-readout-value ctl-readout-list ctl-readout-prose' : 'ctl-readout-value' });
  const el = h('div', { class: 'ctl ctl-readout' }, h('span', { class: 'ctl-readout-label' }, tl(label)), v);
  // the same text as shown leaves the DOM alone (demos set their readouts in every drag frame)
  let shown = null;
  const set = (s) => {
    const t = String(s);
    if (t === shown) return;
    shown = t;
    if (prose) v.replaceChildren(...t.split(' ').flatMap((w, i) => [i ? ' ' : '', h('span', { style: { whiteSpace: 'nowrap' } }, w)]));
    else v.textContent = t;
  };
  set(value);
  return { el, get: () => v.textContent, set };
}

/**
 * Small numeric table: table({ caption, columns: ['i', 'x', 'y'], rows: [[…], …], digits }) → set(rows).
 * Numbers are formatted with `digits` decimals; strings shown as they are.
 */
/** @param {{ caption?: Label, columns?: ReadonlyArray<Label>, rows?: ReadonlyArray<ReadonlyArray<string | number>>, digits?: number }} [options] */
export function table({ caption, columns = [], rows = [], digits = 3 } = {}) {
  const tbody = h('tbody');
  const t = h('table', { class: 'ctl-table' },
    caption ? h('caption', null, tl(caption)) : null,
    h('thead', null, h('tr', null, columns.map((c) => h('th', { scope: 'col' }, tl(c))))), tbody);
  const text = (c) => (typeof c === 'number' ? fmt(c, digits) : String(c));
  let current = rows;
  const set = (rs) => {
    current = rs;
    // the same shape as shown (a drag frame's new numbers): rewrite only the cells whose text changed, so a
    // drag does not rebuild the table's DOM (style and layout work) in every frame, nor a screen reader's view
    const trs = tbody.rows;
    if (trs.length === rs.length && rs.every((r, i) => trs[i].cells.length === r.length)) {
      rs.forEach((r, i) => r.forEach((c, j) => {
        const cell = trs[i].cells[j], s = text(c);
        if (cell.textContent !== s) cell.textContent = s;
      }));
      return;
    }
    clear(tbody);
    for (const r of rs) append(tbody, h('tr', null, r.map((c, j) => h(j === 0 ? 'th' : 'td', j === 0 ? { scope: 'row' } : null, text(c)))));
  };
  set(rows);
  // it scrolls sideways on a narrow screen: focusable, so that the keyboard can scroll it (WCAG 2.1.1; axe's
  // scrollable-region-focusable), and named by its caption
  const el = h('div', { class: 'ctl ctl-tablewrap', tabindex: '0', role: 'region', 'aria-label': tl(caption) || translate('Table') }, t);
  return { el, get: () => current, set };
}

/** A titled group of controls: group('Curve', slider.el, toggle.el, …) → element. */
export function group(title, ...children) {
  return h('section', { class: 'ctl-section' }, title ? h('h2', { class: 'ctl-section-title' }, tl(title)) : null, ...children);
}

/** A row of buttons (or other small controls) side by side. */
export function row(...children) {
  return balanceWrap(h('div', { class: 'ctl-row' }, ...children), ':scope > *');
}

