// The table view of a figure (issue 25, "figures in words"; 2D plots and 3D views): under the figure, a disclosure "Table of the
// figure" that lists every movable point by its paper name with its coordinates, and, where the demo gives them,
// sampled values of what is drawn (C(u) at 11 values of u, N₀,₃(u)…). A screen reader reads it as a table (caption,
// column headers); a person can select it, or copy it as CSV (tab-free, one header row per section) for a
// spreadsheet. Its numbers are the figure's, rounded as the readouts are; it is filled only while open and
// refreshed after a change (not in the frame: a drag does not rebuild it 60 times a second).

import { fmt, h } from '../dom.js';
import { t } from '../i18n.js';

/**
 * One section of the table: a caption, the column names and the rows (numbers or text).
 * @typedef {{ title: string, columns: string[], rows: (number | string)[][] }} TableSection
 */

/** Digits after the point in the table (the readouts use 3; a table is for reading values off). */
const DIGITS = 4;
/** How long after the last change the open table is rebuilt, ms. */
const REFRESH_MS = 300;

const cell = (v) => (typeof v === 'number' ? fmt(v, DIGITS) : String(v));

/** A CSV field: quoted when it holds a comma, a quote or a line break; numbers plain (ASCII minus, full stop). */
function csvField(v) {
  if (typeof v === 'number') return Number.isFinite(v) ? String(Number(v.toFixed(DIGITS + 2))) : '';
  const s = String(v);
  return /[",\n]/.test(s) ? `"${s.replace(/"/g, '""')}"` : s;
}

/** The sections as CSV: each section's title on its own line, its header row, its rows; a blank line between. */
export function tableCsv(sections) {
  return sections.map((s) => [csvField(s.title), s.columns.map(csvField).join(','), ...s.rows.map((r) => r.map(csvField).join(','))].join('\n')).join('\n\n');
}

/** `count` indices spread evenly over 0 … n − 1 (first and last included). */
export function evenIndices(n, count = 11) {
  if (n < 1) return [];
  if (n <= count) return Array.from({ length: n }, (_, i) => i);
  return Array.from({ length: count }, (_, k) => Math.round((k * (n - 1)) / (count - 1)));
}

/** `count` parameters evenly spaced over [lo, hi] (the rows of a table: u = 0, 0.1, …, 1 on [0, 1]). */
export function evenParams(lo, hi, count = 11) {
  return Array.from({ length: count }, (_, k) => (k === count - 1 ? hi : lo + ((hi - lo) * k) / (count - 1)));
}

/** [first, last] parameter of a sampled result of the API ({ params }), or null. */
export const paramRange = (result) => (result?.params?.length ? [result.params[0], result.params[result.params.length - 1]] : null);

/**
 * A section of `[u, x, y]` rows from a 2D curve result of the API ({ params, points }, points flat x, y): every
 * row of a result computed at the table's parameters (`at: evenParams(…)`), or `count` evenly spread rows of a
 * longer one.
 */
export function curveSection(title, result, { count = 11, param = 'u' } = {}) {
  const P = result?.params;
  if (!P || !result.points) return null;
  return { title, columns: [param, 'x', 'y'], rows: evenIndices(P.length, count).map((i) => [P[i], result.points[2 * i], result.points[2 * i + 1]]) };
}

/**
 * A section of basis values at `params`: `values[j · m + i]` = Bᵢ(params[j]) with m = names.length (the layout of
 * the API's basis results), `names[i]` the column of function i.
 */
export function basisSection(title, params, values, names, { param = 'u' } = {}) {
  const m = names.length;
  if (!params || !values || !m || values.length < params.length * m) return null;
  return { title, columns: [param, ...names], rows: Array.from(params, (u, j) => [u, ...Array.from({ length: m }, (_, i) => values[j * m + i])]) };
}

/**
 * The table view. `points()` → [{ name, x, y, z? }] (the points, in the order the keyboard visits them; with z in 3D);
 * `samples()` → TableSection[] or null (what the demo samples); `label` names the figure.
 * Returns { el (append under the figure), refresh() (after a change), sections() (tests), dispose() }.
 */
export function createTableView({ label, points, samples }) {
  const body = h('div', { class: 'plot-table-body', role: 'group', 'aria-label': t('Table: {plot}', { plot: label }) });
  const note = h('span', { class: 'plot-table-note', role: 'status' });
  const copy = h('button', { type: 'button', class: 'plot-table-copy' }, t('Copy as CSV'));
  const summary = h('summary', null, t('Table of the figure'));
  const el = h('details', { class: 'plot-table' }, summary, h('div', { class: 'plot-table-tools' }, copy, note), body);

  /** @returns {TableSection[]} */
  function sections() {
    const out = [];
    const ps = points();
    const z = ps.some((p) => p.z !== undefined);   // a 3D view's points
    if (ps.length) out.push({ title: t('Points ({n})', { n: ps.length }), columns: z ? [t('point'), 'x', 'y', 'z'] : [t('point'), 'x', 'y'], rows: ps.map((p) => (z ? [p.name, p.x, p.y, p.z ?? ''] : [p.name, p.x, p.y])) });
    let more = [];
    try { more = samples?.() || []; } catch (e) {
      more = [{ title: t('Values'), columns: [t('note')], rows: [[t('They could not be computed: {why}', { why: e?.message ?? e })]] }];
    }
    for (const s of more) if (s && s.rows.length) out.push(s);
    return out;
  }

  let timer = 0;
  function build() {
    timer = 0;
    if (!el.open) return;
    const list = sections();
    body.replaceChildren(...(list.length ? list.map((s) => h('table', null,
      h('caption', null, t(s.title)),
      h('thead', null, h('tr', null, ...s.columns.map((c) => h('th', { scope: 'col' }, t(c))))),
      h('tbody', null, ...s.rows.map((r) => h('tr', null, ...r.map((v, j) => (j === 0 && typeof v === 'string' ? h('th', { scope: 'row' }, v) : h('td', null, cell(v)))))))))
      : [h('p', null, t('This figure has no points or values to list.'))]));
    // a table wider than the figure scrolls sideways (a phone, many basis functions): then it is a Tab stop, so a
    // keyboard can scroll it (SC 2.1.1); otherwise not (an empty stop would be noise)
    if (body.scrollWidth > body.clientWidth + 1) body.tabIndex = 0; else body.removeAttribute('tabindex');
  }
  /** Rebuilds the open table after a change (debounced); a closed table waits until it is opened. */
  function refresh() { if (el.open && !timer) timer = setTimeout(build, REFRESH_MS); }
  el.addEventListener('toggle', () => { if (el.open) build(); });

  copy.addEventListener('click', async () => {
    const text = tableCsv(sections());
    try {
      await navigator.clipboard.writeText(text);
      note.textContent = t('Copied.');
    } catch {
      // no clipboard here (an iframe without the permission, an old browser): select the table instead
      const range = document.createRange();
      range.selectNodeContents(body);
      const sel = getSelection();
      sel?.removeAllRanges();
      sel?.addRange(range);
      note.textContent = t('The clipboard is not available here: the table is selected, copy it with Ctrl+C (⌘C).');
    }
  });

  return { el, refresh, sections, dispose: () => clearTimeout(timer) };
}
