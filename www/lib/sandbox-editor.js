// The sandbox's code area: a plain <textarea> (accessible name "Code"; what the visitor types, pastes, undoes)
// over a highlighted copy of its text (aria-hidden), with line numbers, and an error marker shown under the line
// where the code failed. The highlighter is a small tokenizer (comments, strings, numbers, keywords, `sl.` calls);
// it only colours text, so a tokenizing mistake can never change the code.

import { h } from './dom.js';

const KEYWORDS = new Set(('await async break case catch class const continue default do else export for function if in '
  + 'instanceof let new of return switch throw try typeof var void while yield true false null undefined this').split(' '));
const HELPERS = new Set(['sl', 'plot', 'surface', 'print', 'Math']);

/** Tokens [{ t: kind | '', s: text }] of JavaScript source (best effort; every character lands in one token). */
export function tokenize(src) {
  const out = [];
  const re = /(\/\/[^\n]*|\/\*[\s\S]*?(?:\*\/|$))|('(?:[^'\\\n]|\\.)*'?|"(?:[^"\\\n]|\\.)*"?|`(?:[^`\\]|\\[\s\S])*`?)|(\b\d[\d_]*(?:\.\d*)?(?:[eE][+-]?\d+)?\b|\.\d+(?:[eE][+-]?\d+)?)|([A-Za-z_$][\w$]*)|(\s+)|([\s\S])/g;
  for (let m; (m = re.exec(src));) {
    if (m[1]) out.push({ t: 'comment', s: m[1] });
    else if (m[2]) out.push({ t: 'string', s: m[2] });
    else if (m[3]) out.push({ t: 'number', s: m[3] });
    else if (m[4]) out.push({ t: KEYWORDS.has(m[4]) ? 'keyword' : HELPERS.has(m[4]) ? 'helper' : '', s: m[4] });
    else out.push({ t: '', s: m[0] });
  }
  return out;
}

/**
 * Creates the editor inside `parent`. Returns { textarea, value, setValue(text), showError(line, message),
 * clearError(), onInput(fn), onRun(fn) } — onRun fires on Ctrl/Cmd+Enter.
 */
export function createEditor(parent) {
  const gutter = h('div', { class: 'sb-gutter', 'aria-hidden': 'true' });
  const highlight = h('pre', { class: 'sb-highlight', 'aria-hidden': 'true' });
  const textarea = h('textarea', {
    id: 'sb-code', class: 'sb-textarea', 'aria-label': 'Code', spellcheck: 'false', autocapitalize: 'off',
    autocomplete: 'off', autocorrect: 'off', wrap: 'off', 'aria-describedby': 'sb-code-help',
  });
  const help = h('p', { id: 'sb-code-help', class: 'visually-hidden' },
    'JavaScript, run as the body of an async function with sl, plot, surface and print. Ctrl+Enter or Command+Enter runs it. Tab inserts two spaces; Escape then Tab leaves the code area.');
  const marker = h('div', { class: 'sb-line-error', hidden: true, 'aria-hidden': 'true' });
  const inline = h('div', { class: 'sb-inline-error', hidden: true, id: 'sb-inline-error' });
  const scroller = h('div', { class: 'sb-scroller' }, marker, highlight, textarea, inline);
  const root = h('div', { class: 'sb-editor-box' }, gutter, scroller, help);
  parent.appendChild(root);
  const inputFns = [];
  const runFns = [];
  let errorLine = 0;
  let escaped = false;

  function render() {
    const text = textarea.value;
    const frag = document.createDocumentFragment();
    for (const tok of tokenize(text)) frag.append(tok.t ? h('span', { class: `tk-${tok.t}` }, tok.s) : document.createTextNode(tok.s));
    frag.append('\n'); // the textarea shows an empty last line after a final newline
    highlight.replaceChildren(frag);
    const lines = text.split('\n').length;
    if (gutter.childElementCount !== lines) {
      gutter.replaceChildren(...Array.from({ length: lines }, (_, i) => h('div', { class: 'sb-ln' }, String(i + 1))));
    }
    for (const el of gutter.querySelectorAll('.sb-ln-error')) el.classList.remove('sb-ln-error');
    if (errorLine) gutter.children[errorLine - 1]?.classList.add('sb-ln-error');
    size();
  }

  /** The textarea grows with its text (the page scrolls, not the box), so the overlay and gutter line up. */
  function size() {
    textarea.style.height = '0px';
    textarea.style.height = `${Math.max(textarea.scrollHeight, 160)}px`;
    highlight.style.width = `${textarea.scrollWidth}px`;
    placeError();
  }

  function lineHeight() { return parseFloat(getComputedStyle(textarea).lineHeight) || 20; }
  function padTop() { return parseFloat(getComputedStyle(textarea).paddingTop) || 0; }

  function placeError() {
    if (!errorLine) return;
    const top = padTop() + (errorLine - 1) * lineHeight();
    marker.style.top = `${top}px`;
    marker.style.height = `${lineHeight()}px`;
    inline.style.top = `${top + lineHeight()}px`;
  }

  textarea.addEventListener('input', () => {
    if (errorLine) clearError();
    render();
    for (const f of inputFns) f(textarea.value);
  });
  textarea.addEventListener('scroll', () => { highlight.style.transform = `translateX(${-textarea.scrollLeft}px)`; });
  textarea.addEventListener('keydown', (e) => {
    if (e.key === 'Enter' && (e.ctrlKey || e.metaKey)) {
      e.preventDefault();
      for (const f of runFns) f();
      return;
    }
    if (e.key === 'Escape') { escaped = true; return; }
    if (e.key === 'Tab' && !e.shiftKey && !e.ctrlKey && !e.metaKey && !e.altKey && !escaped) {
      e.preventDefault();
      // insertText keeps the browser's undo history
      if (!document.execCommand?.('insertText', false, '  ')) textarea.setRangeText('  ', textarea.selectionStart, textarea.selectionEnd, 'end');
      textarea.dispatchEvent(new Event('input'));
      return;
    }
    escaped = false;
  });
  new ResizeObserver(() => size()).observe(scroller);

  function showError(line, message) {
    const n = textarea.value.split('\n').length;
    errorLine = Number.isInteger(line) && line >= 1 ? Math.min(line, n) : 0;
    inline.textContent = message;
    inline.dataset.line = String(errorLine || '');
    marker.hidden = !errorLine;
    inline.hidden = !errorLine;
    render();
  }

  function clearError() {
    errorLine = 0;
    marker.hidden = true;
    inline.hidden = true;
    inline.dataset.line = '';
    for (const el of gutter.querySelectorAll('.sb-ln-error')) el.classList.remove('sb-ln-error');
  }

  render();
  return {
    textarea, root,
    get value() { return textarea.value; },
    setValue(text) { textarea.value = text; clearError(); render(); for (const f of inputFns) f(text); },
    showError, clearError,
    onInput(fn) { inputFns.push(fn); },
    onRun(fn) { runFns.push(fn); },
    get errorLine() { return errorLine; },
  };
}
