// "Copy as code" and "Open in sandbox" for every demo.
//
// A demo module exports `snippet(state)`: a pure function of its state returning JavaScript source — the body of
// a function of one parameter `sl` (the SplineLab module) that repeats the API calls of the demo's main drawing
// with the current data, parameters and options, and ends with `return { … }` of the results. It runs unchanged
// in Node (`new Function('sl', code)(require('splinelab'))`) and in the sandbox page (www/sandbox.html).
//
// This module holds what the demos share:
//   code`const points = ${state.points};`  — a tagged template: every interpolated value becomes a JavaScript
//                                            literal (numbers through JSON.stringify: they read back exactly)
//   raw(text)                              — an interpolation inserted as code, not as a literal
//   snippetCode(title, body)               — the header comment + body
//   sandboxHref(code)                      — `sandbox.html#code=<base64url of the UTF-8 code, no padding>`
//   snippetBar({ snippet, getState })      — the "Copy as code" button and the "Open in sandbox" link (the shell's
//                                            Export row adds it under every demo: www/lib/demo-export.js)

import { t, tn } from './i18n.js';

const WIDTH = 100;

/** Marks text to be inserted as code by the `code` tag (not turned into a literal). */
export function raw(text) { return { [RAW]: String(text) }; }
const RAW = Symbol('raw');

/** One number as JavaScript source that reads back as the same double (JSON.stringify is shortest round-trip). */
export function num(x) {
  if (Object.is(x, -0)) return '-0';
  if (Number.isFinite(x)) return JSON.stringify(x);
  return Number.isNaN(x) ? 'NaN' : x > 0 ? 'Infinity' : '-Infinity';
}

/** A string literal in single quotes (JSON escapes otherwise). */
const str = (s) => (/^[^'\\\n\r\u2028\u2029]*$/.test(s) ? `'${s}'` : JSON.stringify(s));

const IDENT = /^[A-Za-z_$][A-Za-z0-9_$]*$/;
const isSeq = (v) => Array.isArray(v) || ArrayBuffer.isView(v);

/**
 * A JavaScript literal of `v` (numbers, strings, booleans, null, arrays, typed arrays → arrays, plain objects;
 * functions as their source), wrapped to lines of about 100 characters; continuation lines start at `indent`.
 */
export function literal(v, indent = '') {
  if (v === null || v === undefined) return String(v);
  if (typeof v === 'number') return num(v);
  if (typeof v === 'string') return str(v);
  if (typeof v === 'boolean') return String(v);
  if (typeof v === 'function') return v.toString();
  if (v && v[RAW] !== undefined) return v[RAW];
  const inner = indent + '  ';
  if (isSeq(v)) {
    const items = Array.from(v, (x) => literal(x, inner));
    const flat = `[${items.join(', ')}]`;
    if (flat.length + indent.length <= WIDTH && !flat.includes('\n')) return flat;
    return `[\n${pack(items, inner)}\n${indent}]`;
  }
  if (typeof v === 'object') {
    const items = Object.entries(v).filter(([, x]) => x !== undefined)
      .map(([k, x]) => `${IDENT.test(k) ? k : JSON.stringify(k)}: ${literal(x, inner)}`);
    if (!items.length) return '{}';
    const flat = `{ ${items.join(', ')} }`;
    if (flat.length + indent.length <= WIDTH && !flat.includes('\n')) return flat;
    return `{\n${items.map((s) => inner + s).join(',\n')},\n${indent}}`;
  }
  throw new TypeError(`snippet: cannot write a ${typeof v} as a literal`);
}

/** Items packed greedily into lines of at most WIDTH characters (multi-line items get their own lines). */
function pack(items, indent) {
  const lines = [];
  let cur = '';
  for (const it of items) {
    if (it.includes('\n')) { if (cur) lines.push(cur); lines.push(`${indent}${it},`); cur = ''; continue; }
    const next = cur ? `${cur} ${it},` : `${indent}${it},`;
    if (cur && next.length > WIDTH) { lines.push(cur); cur = `${indent}${it},`; } else cur = next;
  }
  if (cur) lines.push(cur);
  return lines.join('\n');
}

/**
 * Tagged template for snippet bodies: interpolated values become literals (indented like the line they are on);
 * `raw(text)` inserts code. The common leading indentation of the template is removed.
 */
export function code(strings, ...values) {
  let out = '';
  strings.forEach((s, i) => {
    out += s;
    if (i < values.length) {
      const line = out.slice(out.lastIndexOf('\n') + 1);
      const indent = line.match(/^\s*/)[0];
      out += literal(values[i], indent);
    }
  });
  const lines = out.replace(/^\n/, '').replace(/\s+$/, '').split('\n');
  const pad = Math.min(...lines.filter((l) => l.trim()).map((l) => l.match(/^ */)[0].length));
  return lines.map((l) => l.slice(Number.isFinite(pad) ? pad : 0)).join('\n');
}

/** The full snippet: what it is, how to run it, then the body. */
export function snippetCode(title, body) {
  return [
    `// SplineLab — ${title}: the API calls behind this view, with its data and options.`,
    '// Runs as it is in the SplineLab sandbox (Open in sandbox) and in Node:',
    "// Node: new Function('sl', code)(require('splinelab'))",
    body.trim(),
    '',
  ].join('\n');
}

/** base64url (no padding) of the UTF-8 bytes of `text`. */
export function base64url(text) {
  const bytes = new TextEncoder().encode(String(text));
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
  return btoa(s).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

/** The sandbox link holding `code` (the sandbox shows it and runs it only when the visitor presses Run). */
export function sandboxHref(text, base = new URL('../sandbox.html', import.meta.url).href) {
  return `${base.replace(/#.*$/, '')}#code=${base64url(text)}`;
}

/**
 * "Copy as code" (to the clipboard, with a visible confirmation; where the clipboard is blocked the code is shown
 * in a read-only text area to copy by hand) and "Open in sandbox" (a link updated to the current state when it is
 * approached or used). For tests the last code is kept on `element.lastSnippet`.
 */
export function snippetBar({ snippet, getState, onError }) {
  const doc = document;
  const el = doc.createElement('span');
  el.className = 'snippet-bar';
  el.hidden = true;
  const copyBtn = doc.createElement('button');
  copyBtn.type = 'button';
  copyBtn.className = 'btn btn-small';
  copyBtn.dataset.format = 'code';
  copyBtn.textContent = t('Copy as code');
  copyBtn.title = t('Copy the JavaScript that computes this view (runs in the sandbox and in Node)');
  const link = doc.createElement('a');
  link.className = 'btn btn-small snippet-open';
  link.textContent = t('Open in sandbox');
  link.target = '_blank';
  link.rel = 'noopener';
  link.title = t('Open this view’s code in the sandbox (it runs when you press Run)');
  link.href = new URL('../sandbox.html', import.meta.url).href;
  const status = doc.createElement('span');
  status.className = 'snippet-status';
  status.setAttribute('role', 'status');
  status.setAttribute('aria-live', 'polite');
  const fallback = doc.createElement('div');
  fallback.className = 'snippet-fallback';
  fallback.hidden = true;
  const area = doc.createElement('textarea');
  area.readOnly = true;
  area.rows = 10;
  area.spellcheck = false;
  area.setAttribute('aria-label', t('Code of this view'));
  const close = doc.createElement('button');
  close.type = 'button';
  close.className = 'btn btn-small';
  close.textContent = t('Close');
  close.addEventListener('click', () => { fallback.hidden = true; copyBtn.focus(); });
  fallback.append(area, close);
  el.append(copyBtn, link, status, fallback);

  const fn = typeof snippet === 'function' ? snippet : null;
  let timer = 0;
  const current = () => {
    if (!fn) return null;
    try {
      const text = fn(getState());
      el.lastSnippet = text;
      return text;
    } catch (e) {
      if (typeof onError === 'function') onError(e); else console.error(e);
      return null;
    }
  };
  const say = (msg) => {
    status.textContent = msg;
    clearTimeout(timer);
    timer = setTimeout(() => { status.textContent = ''; }, 4000);
  };
  const updateLink = () => { const text = current(); if (text) link.href = sandboxHref(text); };
  link.addEventListener('pointerenter', updateLink);
  link.addEventListener('focus', updateLink);
  link.addEventListener('click', updateLink);
  copyBtn.addEventListener('click', async () => {
    const text = current();
    if (!text) return;
    const lines = text.split('\n').length;
    try {
      if (!navigator.clipboard?.writeText) throw new Error('no clipboard');
      await navigator.clipboard.writeText(text);
      fallback.hidden = true;
      el.dataset.copied = String((Number(el.dataset.copied) || 0) + 1);
      say(tn(lines, 'Copied {n} line of JavaScript', 'Copied {n} lines of JavaScript'));
    } catch {
      area.value = text;
      fallback.hidden = false;
      area.focus();
      area.select();
      say(t('The clipboard is blocked here: the code is selected below, copy it with Ctrl+C (⌘C)'));
    }
  });

  el.hidden = !fn;
  if (fn) el.dataset.ready = 'true';
  return { element: el, code: current, destroy() { clearTimeout(timer); el.remove(); } };
}
