// Safe DOM building for SplineLab. Text always goes through textContent / text nodes; nothing here ever
// assigns innerHTML, so data (state from a URL, labels, numbers) cannot inject markup.
//
//   h('button', { class: 'btn', onclick: fn, 'aria-label': 'Add' }, 'Add point')
//   h('div', { style: { width: '3px' }, dataset: { id: 'x' } }, child, [more, children], null)
//
// attrs: `class` (string or array), `style` (object: assigned through CSSOM, which the CSP allows),
// `dataset` (object), `on<event>` (function → addEventListener), `text` (textContent), boolean `true`
// → empty attribute, `false`/`null`/`undefined` → omitted, anything else → setAttribute(String(v)).
// children: strings/numbers (text nodes), Nodes, arrays (flattened), null/undefined/false (skipped).

import { formulaBlock } from './mathml.js';
import { num, decimalSeparator, t, tLabel } from './i18n.js';

export function h(tag, attrs, ...children) {
  const el = document.createElement(tag);
  if (attrs) setAttrs(el, attrs);
  append(el, children);
  return el;
}

export function setAttrs(el, attrs) {
  for (const [k, v] of Object.entries(attrs)) {
    if (v === undefined || v === null || v === false) continue;
    if (k === 'class') el.className = Array.isArray(v) ? v.filter(Boolean).join(' ') : String(v);
    else if (k === 'style' && typeof v === 'object') Object.assign(el.style, v);
    else if (k === 'dataset' && typeof v === 'object') Object.assign(el.dataset, v);
    else if (k === 'text') el.textContent = String(v);
    else if (k.startsWith('on') && typeof v === 'function') el.addEventListener(k.slice(2).toLowerCase(), v);
    else if (k === 'value' && 'value' in el) el.value = v;
    else if (k === 'checked' || k === 'selected' || k === 'disabled' || k === 'hidden') { el[k] = !!v; if (v === true && k !== 'checked' && k !== 'selected') el.setAttribute(k, ''); }
    else el.setAttribute(k, v === true ? '' : String(v));
  }
  return el;
}

/** Appends children (strings, numbers, nodes, nested arrays; null/false skipped). Returns `el`. */
export function append(el, ...children) {
  for (const c of children.flat(Infinity)) {
    if (c === null || c === undefined || c === false) continue;
    el.appendChild(c instanceof Node ? c : document.createTextNode(String(c)));
  }
  return el;
}

/** Removes every child of `el`. */
export function clear(el) {
  while (el.firstChild) el.removeChild(el.firstChild);
  return el;
}

/** Sets the text of `el` (textContent). */
export function text(el, s) {
  el.textContent = s === undefined || s === null ? '' : String(s);
  return el;
}

export const $ = (sel, root = document) => root.querySelector(sel);
export const $$ = (sel, root = document) => Array.from(root.querySelectorAll(sel));

/** A function that calls `fn` at most once per `ms` after the last call (trailing). `.flush()`, `.cancel()`. */
export function debounce(fn, ms) {
  let t = null, lastArgs = null;
  const d = (...args) => { lastArgs = args; clearTimeout(t); t = setTimeout(() => { t = null; fn(...lastArgs); }, ms); };
  d.flush = () => { if (t !== null) { clearTimeout(t); t = null; fn(...lastArgs); } };
  d.cancel = () => { clearTimeout(t); t = null; };
  return d;
}

/**
 * Formats a number compactly for reading: fixed `digits` decimals, trailing zeros trimmed, −0 → 0, with the page
 * language's decimal separator (0,25 in sk, ro, hu, it: www/lib/i18n.js). Never for links, JSON, CSV or code.
 */
export const fmt = num;

/** The separator of a coordinate pair's numbers: "(0.25, 1.5)", and "(0,25; 1,5)" where the decimal is a comma. */
export const pairSep = () => (decimalSeparator() === ',' ? '; ' : ', ');

/** A point for reading: "(0.25, 1.5)" or "(0,25; 1,5)". */
export const pair = (x, y, digits = 3) => `(${num(x, digits)}${pairSep()}${num(y, digits)})`;

let uid = 0;
/** A unique id for label/aria wiring: uniqueId('slider') → 'slider-7'. */
export function uniqueId(prefix = 'sl') { uid += 1; return `${prefix}-${uid}`; }

/**
 * The standard demo layout inside `root`: returns `{ plots, controls, explain }` elements.
 * Plots go left (top on phones), controls right (under the plots on phones), the explanation below.
 * `options` are ctx.options: `controls: false` hides the controls column, `explain: false` the text.
 *
 * The drawing stays next to its controls (issue 19): on wide screens the plots column is sticky (CSS); a column
 * taller than the window sticks by its bottom edge (the `--plots-top` computed here), so the part under the
 * last control change stays in view. On phones the controls are a bottom drawer (CSS) with a handle that folds
 * it. After a click on a button or choice in the controls, the main view is scrolled into sight if it is out of it.
 */
/** Text in the page's language (www/lib/i18n.js). */
const tw = tLabel;

export function demoLayout(root, options = {}) {
  const plots = h('div', { class: 'demo-plots' });
  const controls = h('div', { class: 'demo-controls', role: 'group', 'aria-label': t('Controls') });
  const explain = h('section', { class: 'demo-explain', 'aria-label': t('Explanation') });
  if (options.controls === false) controls.hidden = true;
  if (options.explain === false) explain.hidden = true;
  const handle = h('button', { type: 'button', class: 'drawer-handle', 'aria-expanded': 'true', onclick: () => {
    const folded = controls.classList.toggle('drawer-collapsed');
    handle.setAttribute('aria-expanded', String(!folded));
    handle.lastChild.textContent = folded ? t('Show controls') : t('Hide controls');
  } }, h('span', null, t('Hide controls')));
  controls.append(handle);
  const grid = h('div', { class: ['demo-layout', options.controls === false && 'no-controls'] }, plots, controls);
  append(root, grid, explain);
  keepInView(plots, controls);
  keepFocusAboveSheet(plots, controls);
  return { plots, controls, explain };
}

/**
 * On phones the controls are a sheet fixed to the bottom of the window: an element of the figure that takes the
 * focus there (a point's x / y fields, the table, a tool) may sit under it, in the window but hidden. Scrolls the
 * page so that one entirely hidden shows above the sheet (WCAG 2.2 SC 2.4.11, Focus Not Obscured (Minimum)).
 */
function keepFocusAboveSheet(plots, controls) {
  plots.addEventListener('focusin', (e) => {
    const el = /** @type {HTMLElement} */ (e.target);
    if (controls.hidden || getComputedStyle(controls).position !== 'fixed') return;
    const sheetTop = controls.getBoundingClientRect().top, r = el.getBoundingClientRect();
    // only what the sheet hides entirely (SC 2.4.11): a plot tapped or focused half under the sheet stays where it
    // is (scrolling it would move the place a tap-then-tap move aims at)
    if (r.top >= sheetTop - 2) window.scrollBy(0, r.bottom + 8 - sheetTop);
  });
}

/** The demo's main view inside the plots column: the wrapper of its first visible canvas. */
export function mainView(plots) {
  const c = Array.from(plots.querySelectorAll('canvas')).find((e) => e.getClientRects().length && !e.closest('[hidden]'));
  return c ? (c.closest('.plot, .sl-view3d') || c) : null;
}

function keepInView(plots, controls) {
  // sticky offset: 8 px from the top, or (for a column taller than the window) its bottom 8 px above the window's
  const place = () => {
    const vh = window.innerHeight || 800;
    const top = Math.min(8, vh - plots.offsetHeight - 8);
    plots.style.setProperty('--plots-top', `${Math.round(top)}px`);
  };
  if (typeof ResizeObserver === 'function') new ResizeObserver(place).observe(plots);
  const onResize = () => { if (plots.isConnected) place(); else window.removeEventListener('resize', onResize); };
  window.addEventListener('resize', onResize);
  // presets and buttons bring the main view into sight
  controls.addEventListener('click', (e) => {
    const t = e.target instanceof Element ? e.target : null;
    if (!t || !t.closest('button:not(.drawer-handle), input[type=radio], input[type=checkbox], label')) return;
    requestAnimationFrame(() => requestAnimationFrame(() => bringIntoView(mainView(plots))));
  });
  // rows of buttons and segmented choices wrap in balanced lines (also those a demo builds later)
  const balanceAll = () => controls.querySelectorAll('.ctl-row, .ctl-segments').forEach((b) => balanceWrap(b, b.classList.contains('ctl-segments') ? 'label' : ':scope > *'));
  if (typeof MutationObserver === 'function') new MutationObserver(balanceAll).observe(controls, { childList: true, subtree: true });
  controls.addEventListener('change', (e) => {
    if (e.target instanceof Element && e.target.matches('select')) requestAnimationFrame(() => bringIntoView(mainView(plots)));
  });
}

/**
 * Balanced wrapping of a flex row of buttons/labels: when the items do not fit on one line, every line gets the
 * same number of items (±1, the last line never a lone orphan): sets `--per-row` and the class `balanced`
 * (style.css sizes the items from it). Re-measured when the row's width changes. Returns `box`.
 */
export function balanceWrap(box, itemSelector = ':scope > *') {
  if (typeof ResizeObserver !== 'function' || box.dataset.balance) return box;
  box.dataset.balance = 'on';
  let lastWidth = -1;
  const measure = () => {
    const w = Math.round(box.clientWidth);
    if (!box.isConnected || w === lastWidth || w === 0) return;
    lastWidth = w;
    box.classList.remove('balanced');
    box.style.removeProperty('--per-row');
    const items = Array.from(box.querySelectorAll(itemSelector)).filter((i) => i.getClientRects().length);
    if (items.length < 3) return;
    const rows = new Set(items.map((i) => Math.round(i.getBoundingClientRect().top))).size;
    if (rows < 2) return;
    const n = items.length;
    let per = Math.ceil(n / rows);
    // no orphan: a last line of one item under fuller lines → one item less per line
    while (per > 1 && n % per === 1) per -= 1;
    box.style.setProperty('--per-row', String(per));
    box.classList.add('balanced');
  };
  new ResizeObserver(() => measure()).observe(box);
  return box;
}

/** Scrolls `el` into sight when less than a quarter of it (or 120 px) is visible in the window. */
export function bringIntoView(el) {
  if (!el || !el.isConnected || el.closest('.presenting')) return false;
  const r = el.getBoundingClientRect();
  const vh = window.innerHeight || document.documentElement.clientHeight;
  const seen = Math.min(r.bottom, vh) - Math.max(r.top, 0);
  if (seen >= Math.min(120, r.height / 4)) return false;
  const reduce = typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;
  el.scrollIntoView({ block: r.height > vh ? 'start' : 'nearest', behavior: reduce ? 'auto' : 'smooth' });
  return true;
}

/**
 * Fills an explanation element from static text: `{ what, math, formula, tryThis: [...], paper, extra }`.
 * `math` is a TeX line or an array of TeX lines (the subset of www/lib/mathml.js), typeset as native MathML in a
 * `formulaBlock` (one display formula per line); `mathLabel` names the block for screen readers (default
 * 'Formula'). `formula` is the older plain-text path (a string or an array of lines, shown in a monospace block),
 * kept for demos not converted yet; when both are given, `math` is shown and `formula` is ignored.
 */
/**
 * @param {HTMLElement} el
 * @param {{ title?: string, what?: any, math?: string | string[], mathLabel?: string, formula?: string | string[],
 *   formulaNote?: any, tryThis?: any, paper?: any, extra?: any }} [parts]
 */
export function explanation(el, { title = 'What this shows', what, math, mathLabel, formula, formulaNote, tryThis, paper, extra } = {}) {
  const hasMath = Array.isArray(math) ? math.length > 0 : typeof math === 'string' && math !== '';
  append(el,
    h('h2', null, tw(title)),
    what ? (Array.isArray(what) ? what.map((p) => h('p', null, tw(p))) : h('p', null, tw(what))) : null,
    hasMath ? formulaBlock(math, { label: tw(mathLabel || 'Formula') }) : null,
    !hasMath && formula ? h('pre', { class: 'formula', 'aria-label': t('Formula'), tabindex: '0' }, Array.isArray(formula) ? formula.join('\n') : formula) : null,
    formulaNote ? h('p', { class: 'formula-note' }, tw(formulaNote)) : null,
    extra || null,
    tryThis && tryThis.length ? [h('h3', null, t('Try this')), h('ul', null, tryThis.map((x) => h('li', null, tw(x))))] : null,
    paper ? h('p', { class: 'paper' }, t('Reference: '), tw(paper)) : null,
  );
  return el;
}

/**
 * A plot legend: legend([{ label, color, kind, dash, alpha }]) → <ul class="legend">. kinds: 'line' (default),
 * 'dashed' (dash pattern `dash` = [on, off] px, default [6, 4]), 'dotted' (short dashes), 'dot' (a point), 'band'
 * (a wide translucent bar), 'thin' (a hairline). Pass the same colour (and dash) the demo draws with: the swatch's
 * colour is set inline (it wins over the stylesheet) and recorded as `data-color` / `data-kind` so tests can
 * compare the legend with the drawing. Items that are falsy are skipped (conditional entries).
 */
export function legend(items, ariaLabel = 'Legend') {
  const ul = h('ul', { class: 'legend', 'aria-label': tw(ariaLabel) });
  setLegendItems(ul, items);
  return ul;
}

/** The entries each legend shows now (see setLegendItems). */
const legendKeys = new WeakMap();

/** What a legend entry's label shows (a string, nodes or a list of both), to tell a changed legend from the same. */
const labelKey = (x) => (x == null || x === false ? '' : typeof x === 'string' ? x : Array.isArray(x) ? x.map(labelKey).join('') : x.outerHTML ?? String(x));

/**
 * Replaces the entries of a legend made by legend() (for legends that follow the drawing). The same entries as
 * shown leave the DOM alone: demos call this in every drag frame, and rebuilding an unchanged legend there costs
 * style and layout work (and a screen reader's view of it).
 */
export function setLegendItems(ul, items) {
  const key = JSON.stringify(items.map((it) => it && [labelKey(it.label), it.color, it.kind, it.dash, it.alpha]));
  if (legendKeys.get(ul) === key) return ul;
  legendKeys.set(ul, key);
  clear(ul);
  for (const it of items) {
    if (!it) continue;
    const { label, color, kind = 'line', dash, alpha } = it;
    const sw = h('span', {
      class: ['swatch', kind === 'dot' && 'dot', (kind === 'dashed' || kind === 'dotted') && 'dashed', kind === 'band' && 'band', kind === 'thin' && 'thin'],
      'aria-hidden': 'true', dataset: { kind },
    });
    if (color) {
      sw.dataset.color = color;
      if (kind === 'dashed' || kind === 'dotted') {
        const [on, off] = Array.isArray(dash) && dash.length >= 2 ? dash : kind === 'dotted' ? [3, 4] : [6, 4];
        const a = Math.max(1, Math.min(8, on)), b = a + Math.max(2, Math.min(6, off));
        // background-image only: a `background` shorthand would also reset the colour to the stylesheet's
        sw.style.backgroundColor = 'transparent';
        sw.style.backgroundImage = `repeating-linear-gradient(90deg, ${color} 0 ${a}px, transparent ${a}px ${b}px)`;
      } else {
        sw.style.backgroundImage = 'none';
        sw.style.backgroundColor = color;
      }
      if (alpha !== undefined && kind !== 'band') sw.style.opacity = String(alpha);
    }
    ul.appendChild(h('li', null, sw, tw(label)));
  }
  return ul;
}
