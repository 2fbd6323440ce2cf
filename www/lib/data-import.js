// "Use my data": one parser for the points, grids and curve networks people paste or drop into a demo, and the
// control every demo uses for it (a text area that also takes a dropped or chosen file).
//
//   parsePoints(text, { dims: [2], min, max })  → [[x, y], …]            CSV/TSV/whitespace/semicolon rows (an
//                                                                         optional header line), or JSON
//                                                                         [[x, y], …] / [{ x, y }, …] / { points }
//   parseGrid(text, { min: [m, n], max })       → [[[x, y, z], …], …]    JSON [i][j] → [x, y, z] (or a matrix
//                                                                         of heights z_ij → [i, j, z]); CSV rows
//                                                                         "x y z" with a blank line between grid
//                                                                         rows, or a matrix of heights
//   parseNetwork(text)                          → { u, v, P, Q }         JSON (also a SplineLab JSON export)
//
// Bad input throws a DataError (an Error with .field = 'data', .kind, and .row for the line or item at fault)
// whose message says where and what: "row 3: expected 2 numbers, got 'abc'". Pure functions (no DOM): the Node
// tests call them directly; the DOM control is dataImport() at the end.

import { t, tn } from './i18n.js';

export const MAX_TEXT = 2_000_000;   // characters (a pasted or dropped file)
export const MAX_POINTS = 100_000;   // the API's own limit on input points

export class DataError extends Error {
  /** @param {string} message @param {{ kind?: string, row?: number }} [where] */
  constructor(message, { kind = 'invalid', row = undefined } = {}) {
    super(message);
    this.name = 'DataError';
    this.field = 'data';
    this.kind = kind;
    if (row !== undefined) this.row = row;
  }
}

const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;
const show = (s, n = 40) => { const t = String(s); return t.length > n ? `${t.slice(0, n - 1)}…` : t; };
const plural = (k, one, many = `${one}s`) => `${k} ${k === 1 ? one : many}`;

/** A field of a CSV row as a number, or null when it is not a plain decimal number. */
function toNumber(s, decimalComma) {
  const t = decimalComma ? s.replace(',', '.') : s;
  if (!NUMBER.test(t)) return null;
  const x = Number(t);
  return Number.isFinite(x) ? x : null;
}

/**
 * The rows of a delimited text: [{ line, fields }] with `line` 1-based; blank lines kept as { line, blank: true }
 * (grids use them), comment lines (# or //) dropped. Separators: comma, semicolon, tab or spaces; with
 * semicolons a comma inside a field is a decimal comma ("1,5; 2,5").
 */
function rows(text) {
  const out = [];
  lines(text).forEach((raw, k) => {
    const r = row(raw, k + 1);
    if (r) out.push(r);
  });
  return out;
}
const lines = (text) => String(text).split(/\r\n|\r|\n/);
/** One line of a delimited text as rows() reads it: { line, fields, semi }, { line, blank: true }, or null (a comment). */
function row(raw, line) {
  const s = raw.trim();
  if (!s) return { line, blank: true };
  if (s.startsWith('#') || s.startsWith('//')) return null;
  const semi = s.includes(';');
  const fields = (semi ? s.split(/\s*;\s*/) : s.split(/\s*[,\t]\s*|\s+/)).filter((f) => f !== '');
  return { line, fields, semi };
}

/** Numbers of a CSV row; `want` = allowed counts. Throws "row N: expected 2 numbers, got 'abc'". */
function rowNumbers(r, want) {
  const nums = r.fields.map((f) => toNumber(f, r.semi));
  const bad = nums.findIndex((x) => x === null);
  if (bad < 0 && want.includes(nums.length)) return nums;
  const what = want.length === 1 ? tn(want[0], '{n} number', '{n} numbers') : t('{some} or {last} numbers', { some: want.slice(0, -1).join(', '), last: want[want.length - 1] });
  if (bad >= 0) {
    throw new DataError(r.fields.length > 1 ? t('row {row}: expected {what}, got \'{got}\' in \'{line}\'', { row: r.line, what, got: show(r.fields[bad]), line: show(r.fields.join(' '), 60) })
      : t('row {row}: expected {what}, got \'{got}\'', { row: r.line, what, got: show(r.fields[bad]) }), { kind: 'wrong-type', row: r.line });
  }
  if (!want.includes(nums.length)) {
    throw new DataError(t('row {row}: expected {what}, got {got} (\'{line}\')', { row: r.line, what, got: nums.length, line: show(r.fields.join(' '), 60) }), { kind: 'incompatible', row: r.line });
  }
  return nums;
}

/** Is this the header line (every field a word, none a number)? */
const isHeader = (r) => r.fields.every((f) => toNumber(f, r.semi) === null && /^[\p{L}_"'][\p{L}\p{N}_ ."'()[\]-]*$/u.test(f));

function checkText(text) {
  if (typeof text !== 'string') throw new DataError(t('expected text (CSV or JSON)'), { kind: 'wrong-type' });
  if (text.length > MAX_TEXT) throw new DataError(t('the data is too long ({n} characters; at most {max})', { n: text.length, max: MAX_TEXT }), { kind: 'too-many' });
  if (!text.trim()) throw new DataError(t('no data: paste CSV rows or JSON, or drop a file'), { kind: 'missing' });
}

function parseJSON(text) {
  try { return JSON.parse(text); } catch (e) {
    const m = /position (\d+)/.exec(e.message);
    const line = m ? text.slice(0, Number(m[1])).split('\n').length : undefined;
    throw new DataError(`JSON${line ? ` (line ${line})` : ''}: ${e.message}`, { kind: 'invalid', row: line });
  }
}
const looksJSON = (text) => /^\s*[[{]/.test(text);

/** One JSON point: [x, y(, z)] or { x, y(, z) }; `where` names it in errors ("item 3", "P[1][2]"). */
function jsonPoint(p, dims, where) {
  let a = p;
  if (p && typeof p === 'object' && !Array.isArray(p)) {
    if (!('x' in p) || !('y' in p)) throw new DataError(`${where}: expected {x, y${dims.includes(3) ? ', z' : ''}}, got keys ${show(Object.keys(p).join(', '))}`, { kind: 'wrong-type' });
    a = 'z' in p ? [p.x, p.y, p.z] : [p.x, p.y];
  }
  const want = dims.length === 1 ? `[${['x', 'y', 'z'].slice(0, dims[0]).join(', ')}]` : '[x, y] or [x, y, z]';
  if (!Array.isArray(a)) throw new DataError(`${where}: expected ${want}, got ${show(JSON.stringify(p))}`, { kind: 'wrong-type' });
  if (!dims.includes(a.length)) throw new DataError(`${where}: expected ${want}, got ${a.length} numbers`, { kind: 'incompatible' });
  a.forEach((x, k) => {
    if (typeof x !== 'number' || !Number.isFinite(x)) throw new DataError(`${where}: expected a finite number at [${k}], got ${show(JSON.stringify(x))}`, { kind: typeof x === 'number' ? 'not-finite' : 'wrong-type' });
  });
  return a.slice();
}

function countCheck(k, { min = 1, max = MAX_POINTS } = {}, what = 'points') {
  if (k < min) throw new DataError(what === 'points' ? tn(min, 'need at least {n} point, got {k}', 'need at least {n} points, got {k}', { k }) : `need at least ${min} ${what}, got ${k}`, { kind: 'too-few' });
  if (k > max) throw new DataError(what === 'points' ? tn(max, 'at most {n} point, got {k}', 'at most {n} points, got {k}', { k }) : `at most ${max} ${what}, got ${k}`, { kind: 'too-many' });
}

// A row of two plain numbers ("0.25, 1.5", "1e-3\t2", "3 4"): exactly the rows that row() splits into two fields
// and toNumber() reads without a decimal comma (no semicolon in them)
const NUM = '[+-]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][+-]?\\d+)?';
const PAIR = new RegExp(`^\\s*(${NUM})(?:\\s*[,\\t]\\s*|\\s+)(${NUM})\\s*$`);

/**
 * The points of CSV rows (an optional header line first): what row() and rowNumbers() make of each line, with their
 * messages. A row of two plain numbers, the usual row, is read with one regular expression (PAIR) instead, which
 * gives the same two numbers: 2000 pasted rows took 5–10 ms on their own in a page's click (issue 26).
 */
function csvPoints(text, dims, max) {
  const pts = [];
  let first = true;   // the first row that is not blank or a comment may be a header
  const all = lines(text);
  for (let k = 0; k < all.length; k++) {
    const m = PAIR.exec(all[k]);
    if (m && (pts.length ? pts[0].length === 2 : dims.includes(2))) {
      const x = Number(m[1]), y = Number(m[2]);
      if (Number.isFinite(x) && Number.isFinite(y)) {
        first = false;
        pts.push([x, y]);
        if (pts.length > max) break;
        continue;
      }
    }
    const r = row(all[k], k + 1);
    if (!r || r.blank) continue;
    if (first) { first = false; if (isHeader(r)) continue; }
    pts.push(rowNumbers(r, pts.length ? [pts[0].length] : dims));
    if (pts.length > max) break;
  }
  return pts;
}

/**
 * Points from CSV (one point per row; an optional header line; `,` `;` tab or spaces between numbers) or JSON
 * ([[x, y], …], [{x, y}, …], { points: […] }). `dims`: the allowed numbers per point (all points alike).
 */
/** @param {string} text @param {{ dims?: number[], min?: number, max?: number }} [options] */
export function parsePoints(text, { dims = [2], min = 1, max = MAX_POINTS } = {}) {
  checkText(text);
  let pts;
  if (looksJSON(text)) {
    let v = parseJSON(text);
    if (v && !Array.isArray(v) && Array.isArray(v.points)) v = v.points;
    if (!Array.isArray(v)) throw new DataError(t('JSON: expected an array of points [[x, y], …] or [{ "x": …, "y": … }, …]'), { kind: 'wrong-type' });
    pts = v.map((p, i) => jsonPoint(p, dims, `item ${i + 1}`));
  } else {
    pts = csvPoints(text, dims, max);
  }
  if (pts.length && pts.some((p) => p.length !== pts[0].length)) {
    const i = pts.findIndex((p) => p.length !== pts[0].length);
    throw new DataError(t('item {i}: has {n} numbers, the first point {first}', { i: i + 1, n: pts[i].length, first: pts[0].length }), { kind: 'incompatible' });
  }
  countCheck(pts.length, { min, max });
  return pts;
}

/**
 * A grid of 3D points [i][j] = [x, y, z]: JSON nested arrays (or a matrix of heights z_ij, placed at x = i,
 * y = j), or CSV: "x y z" rows with a blank line between grid rows, or a matrix of heights (one grid row per line).
 * `min` = [rows, columns] at least; every row needs the same number of points.
 */
/** @param {string} text @param {{ min?: number[], max?: number }} [options] */
export function parseGrid(text, { min = [2, 2], max = 10_000 } = {}) {
  checkText(text);
  let grid;
  if (looksJSON(text)) {
    let v = parseJSON(text);
    if (v && !Array.isArray(v) && Array.isArray(v.grid)) v = v.grid;
    if (!Array.isArray(v) || !v.every(Array.isArray)) throw new DataError('JSON: expected a grid [[[x, y, z], …], …] (rows of points) or a matrix of heights [[z, …], …]', { kind: 'wrong-type' });
    const heights = v.every((r) => r.every((x) => typeof x === 'number'));
    grid = v.map((r, i) => r.map((p, j) => (heights ? height(p, i, j, `row ${i + 1}, column ${j + 1}`) : jsonPoint(p, [3], `grid[${i}][${j}]`))));
  } else {
    const rs = rows(text);
    const data = rs.filter((r) => !r.blank);
    if (data.length && isHeader(data[0])) rs.splice(rs.indexOf(data[0]), 1);
    // blocks of rows separated by blank lines
    const blocks = [];
    let cur = [];
    for (const r of rs) {
      if (r.blank) { if (cur.length) blocks.push(cur); cur = []; } else cur.push(r);
    }
    if (cur.length) blocks.push(cur);
    if (blocks.length === 1 && blocks[0][0].fields.length !== 3) {
      // a matrix of heights: row i = grid row i
      const width = blocks[0][0].fields.length;
      grid = blocks[0].map((r, i) => rowNumbers(r, [width]).map((z, j) => [i, j, z]));
    } else {
      if (blocks.length === 1 && blocks[0].length > 1) {
        throw new DataError(`rows of "x y z": put a blank line between grid rows (got one block of ${blocks[0].length} points), or give a matrix of heights`, { kind: 'incompatible' });
      }
      grid = blocks.map((b) => b.map((r) => rowNumbers(r, [3])));
    }
  }
  if (!grid.length) throw new DataError('no grid rows', { kind: 'missing' });
  const w = grid[0].length;
  const bad = grid.findIndex((r) => r.length !== w);
  if (bad >= 0) throw new DataError(`grid row ${bad + 1} has ${plural(grid[bad].length, 'point')}, row 1 has ${w}: every row needs the same number`, { kind: 'incompatible', row: bad + 1 });
  if (grid.length < min[0] || w < min[1]) throw new DataError(`need a grid of at least ${min[0]} × ${min[1]} points, got ${grid.length} × ${w}`, { kind: 'too-few' });
  countCheck(grid.length * w, { min: 1, max }, 'grid points');
  return grid;
}

function height(z, i, j, where) {
  if (!Number.isFinite(z)) throw new DataError(`${where}: expected a finite number, got ${show(JSON.stringify(z))}`, { kind: 'not-finite' });
  return [i, j, z];
}

/**
 * A curve network { u: [u_0..u_m], v: [v_0..v_n], P, Q } (JSON): P[r][j] = P_j^(r) (r = 0..m, j = 0..n+1) and
 * Q[s][i] = Q_i^(s) (s = 0..n, i = 0..m+1), points [x, y, z]. Also accepts { network } and SplineLab's JSON
 * export of the curve-networks demo. Shapes are checked here; compatibility is the API's to judge.
 */
export function parseNetwork(text) {
  checkText(text);
  if (!looksJSON(text)) throw new DataError('a curve network is JSON: { "u": […], "v": […], "P": [[[x, y, z], …], …], "Q": […] }', { kind: 'wrong-type' });
  let v = parseJSON(text);
  if (v && v.computed && v.computed.network) v = v.computed.network;
  else if (v && v.network && typeof v.network === 'object') v = v.network;
  if (!v || typeof v !== 'object' || Array.isArray(v)) throw new DataError('JSON: expected an object { u, v, P, Q }', { kind: 'wrong-type' });
  for (const k of ['u', 'v', 'P', 'Q']) if (!(k in v)) throw new DataError(`${k} is required (a network is { u, v, P, Q })`, { kind: 'missing' });
  const params = (k) => {
    const a = v[k];
    if (!Array.isArray(a) || a.length < 2) throw new DataError(`${k}: expected at least 2 parameter values, got ${show(JSON.stringify(a))}`, { kind: 'too-few' });
    a.forEach((x, i) => { if (typeof x !== 'number' || !Number.isFinite(x)) throw new DataError(`${k}[${i}]: expected a finite number, got ${show(JSON.stringify(x))}`, { kind: 'not-finite' }); });
    for (let i = 1; i < a.length; i++) if (!(a[i] > a[i - 1])) throw new DataError(`${k}: must increase, but ${k}[${i}] = ${a[i]} ≤ ${k}[${i - 1}] = ${a[i - 1]}`, { kind: 'out-of-range' });
    return a.slice();
  };
  const u = params('u'), V = params('v');
  const curves = (k, count, len, countName, lenName) => {
    const a = v[k];
    if (!Array.isArray(a) || a.length !== count) throw new DataError(`${k}: expected ${count} curves (${countName}), got ${Array.isArray(a) ? a.length : show(JSON.stringify(a))}`, { kind: 'incompatible' });
    return a.map((c, r) => {
      if (!Array.isArray(c) || c.length !== len) throw new DataError(`${k}[${r}]: expected ${len} points (${lenName}), got ${Array.isArray(c) ? c.length : show(JSON.stringify(c))}`, { kind: 'incompatible' });
      return c.map((p, j) => jsonPoint(p, [3], `${k}[${r}][${j}]`));
    });
  };
  const P = curves('P', u.length, V.length + 1, 'one per u_r', 'n + 2 = v.length + 1');
  const Q = curves('Q', V.length, u.length + 1, 'one per v_s', 'm + 2 = u.length + 1');
  return { u, v: V, P, Q };
}

/** parsePoints / parseGrid / parseNetwork by `kind` ('points' | 'grid' | 'network'). */
/** @param {string} text @param {string} [kind] @param {{ dims?: number[], min?: any, max?: any }} [opts] @returns {any} */
export function parseData(text, kind = 'points', opts = {}) {
  if (kind === 'grid') return parseGrid(text, opts);
  if (kind === 'network') return parseNetwork(text);
  return parsePoints(text, opts);
}

// ---------------------------------------------------------------- the control

const EXAMPLES = {
  points: 'x, y\n0, 0\n1, 2\n2.5, 2.4\n4, 0.5',
  grid: '0 0 0\n0 1 0.5\n…\n\n1 0 0.2\n1 1 0.9\n…',
  network: '{ "u": [0, 0.5, 1], "v": [0, 1], "P": [[[x, y, z], …], …], "Q": […] }',
};

/**
 * "Use my data": a disclosure with a text area (paste CSV or JSON, or drop a file on it), a file chooser, an Apply
 * button and the error of the last attempt (role="alert"). `onData(value, text)` receives the parsed data; it may
 * throw (e.g. an API Error about the data), and its message is shown the same way. It may also return a Promise
 * (data judged in a compute worker): its rejection is shown the same way, and a resolution to `false` (superseded
 * by a newer import) shows nothing; `data-checking` is "true" on the box meanwhile.
 *   dataImport({ kind: 'points', label: 'Use my points', hint, dims: [2], min: 4, onData })
 */
/**
 * @param {{ kind?: 'points' | 'grid' | 'network', label?: string, hint?: string, apply?: string, dims?: number[],
 *   min?: any, max?: any, onData?: (data: any, text: string) => void | Promise<boolean | void>, value?: string }} [options]
 */
export function dataImport({ kind = 'points', label = 'Use my data', hint, apply = 'Use these data', dims, min, max, onData, value = '' } = {}) {
  const uid = Math.random().toString(36).slice(2, 8);
  const mk = (tag, props = {}, ...kids) => { const el = document.createElement(tag); Object.assign(el, props); el.append(...kids); return el; };
  const box = mk('details', { className: 'data-import' });
  box.dataset.kind = kind;
  const summary = mk('summary', {}, t(label));
  const area = mk('textarea', { id: `data-import-${uid}`, name: 'data', rows: 6, spellcheck: false, value });
  area.placeholder = EXAMPLES[kind] || '';
  const areaLabel = mk('label', { htmlFor: area.id }, t(kind === 'network' ? 'Your network (JSON)' : kind === 'grid' ? 'Your grid (CSV or JSON)' : 'Your points (CSV or JSON)'));
  const help = mk('p', { className: 'ctl-hint' }, t(hint || (kind === 'network'
    ? 'Paste JSON { u, v, P, Q } (or this demo’s JSON export), or drop a .json file here.'
    : kind === 'grid' ? 'Rows “x y z” with a blank line between grid rows, a matrix of heights, or JSON [[[x, y, z], …], …]. Paste or drop a file.'
      : 'One point per row (“x, y”; commas, semicolons, tabs or spaces; a header line is fine) or JSON [[x, y], …]. Paste or drop a file.')));
  help.id = `data-import-help-${uid}`;
  area.setAttribute('aria-describedby', help.id);
  const file = mk('input', { type: 'file', id: `data-import-file-${uid}`, accept: '.csv,.txt,.tsv,.json,text/csv,text/plain,application/json' });
  const fileLabel = mk('label', { htmlFor: file.id, className: 'data-import-file' }, t('or choose a file'));
  const go = mk('button', { type: 'button', className: 'btn btn-small' }, t(apply));
  go.dataset.action = 'apply-data';
  const err = mk('p', { className: 'data-import-error' });
  err.setAttribute('role', 'alert');
  err.hidden = true;
  const ok = mk('p', { className: 'data-import-ok' });
  ok.setAttribute('role', 'status');
  box.append(summary, areaLabel, area, help, mk('div', { className: 'data-import-row' }, go, fileLabel, file), err, ok);

  const showError = (e) => {
    err.textContent = e ? String(e.message || e) : '';
    err.hidden = !e;
    if (e) { ok.textContent = ''; area.setAttribute('aria-invalid', 'true'); } else area.removeAttribute('aria-invalid');
    box.dataset.error = e ? 'true' : 'false';
  };
  function run() {
    const text = area.value;
    let v;
    try { v = parseData(text, kind, { ...(dims ? { dims } : {}), ...(min !== undefined ? { min } : {}), ...(max !== undefined ? { max } : {}) }); } catch (e) { showError(e); return false; }
    let pending;
    try { pending = onData?.(v, text); } catch (e) { showError(e); return false; }
    // a demo that judges the data in its compute worker answers later: shown when its answer is in
    if (pending && typeof pending.then === 'function') {
      box.dataset.checking = 'true';
      pending.then((applied) => { if (applied !== false) accepted(v); }, showError).finally(() => { box.dataset.checking = 'false'; });
      return true;
    }
    accepted(v);
    return true;
  }
  function accepted(v) {
    showError(null);
    ok.textContent = kind === 'grid' ? t('Using your {rows} × {cols} grid.', { rows: v.length, cols: v[0].length })
      : kind === 'network' ? t('Using your network of {a} × {b} curves.', { a: v.u.length, b: v.v.length })
        : tn(v.length, 'Using your {n} point.', 'Using your {n} points.');
    box.dataset.applied = String((Number(box.dataset.applied) || 0) + 1);
  }
  async function readFile(f) {
    if (!f) return;
    if (f.size > MAX_TEXT) { showError(new DataError(t('{file}: the file is too large ({kb} KB)', { file: f.name, kb: Math.round(f.size / 1024) }), { kind: 'too-many' })); return; }
    area.value = await f.text();
    run();
  }
  go.addEventListener('click', run);
  file.addEventListener('change', () => readFile(file.files?.[0]));
  area.addEventListener('keydown', (e) => { if (e.key === 'Enter' && (e.ctrlKey || e.metaKey)) { e.preventDefault(); run(); } });
  box.addEventListener('dragover', (e) => { if (e.dataTransfer?.types?.includes('Files')) { e.preventDefault(); box.classList.add('drop-target'); } });
  box.addEventListener('dragleave', () => box.classList.remove('drop-target'));
  box.addEventListener('drop', (e) => {
    const f = e.dataTransfer?.files?.[0];
    box.classList.remove('drop-target');
    if (!f) return;
    e.preventDefault();
    box.open = true;
    readFile(f);
  });
  return { el: box, textarea: area, apply: run, setText(t) { area.value = t; }, showError };
}
