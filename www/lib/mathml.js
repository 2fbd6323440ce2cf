// Native MathML from a small TeX subset, with no library and no innerHTML: formulas in explanations, legends,
// readouts and stepper panels are typeset by the browser (every current engine renders MathML Core).
//
//   math('L^a = 6a\\,L^B + (1 - 6a)\\,L')            → <math> element (inline)
//   math(`\\kappa = ${fmt(k)}`, { display: true })    → display-style block; live numbers are just interpolated
//   mathText('u_{p-1} \\le u_p')                      → the plain-text fallback 'uₚ₋₁ ≤ uₚ' (canvas labels, CSV)
//
// Supported: identifiers (one letter each, italic), numbers (1, 0.25, 1e-12), operators (+ - = < > ( ) [ ] , ; |),
// sub/superscripts `x_i`, `x^{2}`, `x_i^2`, braces `{…}` as groups, `\frac{a}{b}`, `\sqrt{x}`, `\text{…}`,
// `\mathrm{…}` / `\operatorname{…}` (upright names), `\bar{x}` / `\hat{x}` / `\tilde{x}` / `\dot{x}` (accents), `\left( … \right)`,
// greek letters (`\alpha` … `\Omega`), and the symbols listed in SYMBOLS below. Unknown commands show as text.
// Spaces are ignored except in \text; `\,` `\;` `\quad` give space.
// `*` is a multiplication dot (·) except as a script (`b^*`, `b^{*}`: the star ∗). Letters outside ASCII typed
// directly (α, ᵢ) are identifiers like Latin letters.

import { mathSpeech } from './math-speech.js';
import { decimalSeparator } from './i18n.js';

const NS = 'http://www.w3.org/1998/Math/MathML';

const GREEK = {
  alpha: 'α', beta: 'β', gamma: 'γ', delta: 'δ', epsilon: 'ε', varepsilon: 'ε', zeta: 'ζ', eta: 'η', theta: 'θ',
  vartheta: 'ϑ', iota: 'ι', kappa: 'κ', lambda: 'λ', mu: 'μ', nu: 'ν', xi: 'ξ', pi: 'π', rho: 'ρ', sigma: 'σ',
  tau: 'τ', upsilon: 'υ', phi: 'φ', varphi: 'φ', chi: 'χ', psi: 'ψ', omega: 'ω',
  Gamma: 'Γ', Delta: 'Δ', Theta: 'Θ', Lambda: 'Λ', Xi: 'Ξ', Pi: 'Π', Sigma: 'Σ', Phi: 'Φ', Psi: 'Ψ', Omega: 'Ω',
};

/** Operators (rendered as <mo>). */
const SYMBOLS = {
  cdot: '·', times: '×', pm: '±', mp: '∓', le: '≤', leq: '≤', ge: '≥', geq: '≥', ne: '≠', neq: '≠',
  approx: '≈', equiv: '≡', to: '→', rightarrow: '→', leftarrow: '←', mapsto: '↦', Rightarrow: '⇒', iff: '⇔',
  in: '∈', notin: '∉', subset: '⊂', cup: '∪', cap: '∩', sum: '∑', prod: '∏', int: '∫', partial: '∂',
  nabla: '∇', infty: '∞', ldots: '…', cdots: '⋯', dots: '…', forall: '∀', exists: '∃', circ: '∘',
  lVert: '‖', rVert: '‖', Vert: '‖', '|': '‖', langle: '⟨', rangle: '⟩', lfloor: '⌊', rfloor: '⌋',
  lceil: '⌈', rceil: '⌉', max: 'max', min: 'min', sin: 'sin', cos: 'cos', tan: 'tan', arctan: 'arctan',
  ln: 'ln', log: 'log', exp: 'exp', lim: 'lim', sup: 'sup', inf: 'inf', deg: 'deg', det: 'det',
};
const NAMED_FUNCS = new Set(['max', 'min', 'sin', 'cos', 'tan', 'arctan', 'ln', 'log', 'exp', 'lim', 'sup', 'inf', 'deg', 'det']);
const ACCENTS = { bar: '¯', hat: '^', tilde: '~', dot: '˙', vec: '→' };
const SPACES = { ',': '0.17em', ';': '0.28em', ':': '0.22em', quad: '1em', qquad: '2em', ' ': '0.25em', '!': '0' };

function el(tag, attrs, ...kids) {
  const e = document.createElementNS(NS, tag);
  if (attrs) for (const [k, v] of Object.entries(attrs)) if (v !== undefined && v !== null) e.setAttribute(k, String(v));
  for (const k of kids) if (k) e.appendChild(typeof k === 'string' ? document.createTextNode(k) : k);
  return e;
}

/** Tokens: { t: 'cmd'|'num'|'id'|'op'|'open'|'close'|'sub'|'sup', v }. */
function tokenize(src) {
  const out = [];
  const groups = [];   // the open braces: true for a script's group (_{…}, ^{…})
  let i = 0;
  while (i < src.length) {
    const c = src[i];
    if (c === '\\') {
      const m = /^\\([A-Za-z]+|.)/.exec(src.slice(i));
      if (!m) { i += 1; continue; }
      out.push({ t: 'cmd', v: m[1] });
      i += m[0].length;
      if (m[1] === 'text' || m[1] === 'mathrm' || m[1] === 'operatorname') {
        // read the braced argument raw (spaces kept)
        const j = src.indexOf('{', i);
        if (j >= 0 && /^\s*$/.test(src.slice(i, j))) {
          let depth = 0, k = j;
          for (; k < src.length; k++) { if (src[k] === '{') depth++; else if (src[k] === '}' && --depth === 0) break; }
          /** @type {any} */ (out[out.length - 1]).arg = src.slice(j + 1, k);
          i = k + 1;
        }
      }
      continue;
    }
    if (/\s/.test(c)) { i += 1; continue; }
    // a number; where the page's language writes a decimal comma (www/lib/i18n.js: 0,25) that is part of the number
    // too, except in a sub- or superscript, where a comma separates indices (N_{2,3})
    const inScript = groups.includes(true);
    const num = (decimalSeparator() === ',' && !inScript ? /^(\d+([.,]\d+)?([eE][-+]?\d+)?|\.\d+)/ : /^(\d+(\.\d+)?([eE][-+]?\d+)?|\.\d+)/).exec(src.slice(i));
    if (num) { out.push({ t: 'num', v: num[0] }); i += num[0].length; continue; }
    if (c === '{') { const a = out[out.length - 1]; groups.push(!!a && (a.t === 'sub' || a.t === 'sup')); out.push({ t: 'open' }); }
    else if (c === '}') { groups.pop(); out.push({ t: 'close' }); }
    else if (c === '_') out.push({ t: 'sub' });
    else if (c === '^') out.push({ t: 'sup' });
    else if (/[A-Za-z]/.test(c) || /\p{L}/u.test(c)) out.push({ t: 'id', v: c });
    else if (c === "'") out.push({ t: 'op', v: '′' });
    else if (c === '-') out.push({ t: 'op', v: '−' });
    else if (c === '*') {
      // `b^*`, `b^{*}`, `x_*`: the star of a name (∗); elsewhere `*` is multiplication (·)
      const a = out[out.length - 1], b = out[out.length - 2];
      const script = a && (a.t === 'sup' || a.t === 'sub' || (a.t === 'open' && b && (b.t === 'sup' || b.t === 'sub')));
      out.push({ t: 'op', v: script ? '∗' : '·' });
    }
    else out.push({ t: 'op', v: c });
    i += 1;
  }
  return out;
}

/** Recursive-descent parse into MathML nodes. */
function parse(tokens) {
  let pos = 0;
  const peek = () => tokens[pos];

  function group() {
    // one argument: a braced group, or one atom
    const t = peek();
    if (t && t.t === 'open') {
      pos += 1;
      const kids = list('close');
      pos += 1; // the '}'
      return kids.length === 1 ? kids[0] : el('mrow', null, ...kids);
    }
    return atom() || el('mrow');
  }

  function atom() {
    const t = tokens[pos];
    if (!t) return null;
    pos += 1;
    switch (t.t) {
      case 'num': return el('mn', null, t.v);
      case 'id': return el('mi', null, t.v);
      case 'op': return el('mo', null, t.v);
      case 'open': {
        const kids = list('close');
        pos += 1;
        return el('mrow', null, ...kids);
      }
      case 'close': return null;
      case 'sub': case 'sup': return el('mo', null, t.t === 'sub' ? '_' : '^');
      case 'cmd': return command(t);
      default: return null;
    }
  }

  function command(t) {
    const v = t.v;
    if (GREEK[v]) return el('mi', /^[A-Z]/.test(v) ? { mathvariant: 'normal' } : null, GREEK[v]);
    if (v in SPACES) return el('mspace', { width: SPACES[v] });
    if (NAMED_FUNCS.has(v)) return el('mi', { mathvariant: 'normal' }, SYMBOLS[v]);
    if (v in SYMBOLS) return el('mo', v === 'sum' || v === 'prod' ? { largeop: 'true' } : null, SYMBOLS[v]);
    if (v === 'frac') { const a = group(); const b = group(); return el('mfrac', null, a, b); }
    if (v === 'sqrt') return el('msqrt', null, group());
    if (v === 'text') return el('mtext', null, t.arg ?? '');
    if (v === 'mathrm' || v === 'operatorname') return el('mi', { mathvariant: 'normal' }, t.arg ?? '');
    if (v === 'mathbf') { const g = group(); g.setAttribute?.('mathvariant', 'bold'); return g; }
    if (ACCENTS[v]) return el('mover', { accent: 'true' }, group(), el('mo', null, ACCENTS[v]));
    if (v === 'left' || v === 'right') {
      const d = tokens[pos]; pos += 1;
      const s = d ? (d.t === 'cmd' ? (SYMBOLS[d.v] ?? d.v) : d.v) : '';
      return s === '.' ? null : el('mo', { fence: 'true', stretchy: 'true' }, s);
    }
    if (v === '{' || v === '}' || v === '_' || v === '%' || v === '#' || v === '&') return el('mo', null, v);
    return el('mtext', null, `\\${v}`);
  }

  function scripted() {
    let base = atom();
    if (!base) return null;
    let sub = null, sup = null;
    for (;;) {
      const t = peek();
      if (t && t.t === 'sub' && !sub) { pos += 1; sub = group(); continue; }
      if (t && t.t === 'sup' && !sup) { pos += 1; sup = group(); continue; }
      break;
    }
    if (sub && sup) return el('msubsup', null, base, sub, sup);
    if (sub) return el('msub', null, base, sub);
    if (sup) return el('msup', null, base, sup);
    return base;
  }

  function list(until) {
    const kids = [];
    while (pos < tokens.length && !(until && peek().t === until)) {
      const n = scripted();
      if (n) kids.push(n);
    }
    return kids;
  }

  return list(null);
}

/**
 * A `<math>` element typesetting `tex` (the subset above). `display: true` gives a block formula.
 * Its aria-label is `label`, else the formula in words (www/lib/math-speech.js): what a screen reader without
 * MathML support speaks ("N sub i comma p end sub (u)"), instead of skipping the formula or spelling its letters.
 */
/** @param {string} tex @param {{ display?: boolean, label?: string, className?: string }} [options] */
export function math(tex, { display = false, label, className } = {}) {
  const root = el('math', { display: display ? 'block' : undefined, 'aria-label': label, class: className });
  const kids = parse(tokenize(String(tex)));
  root.appendChild(kids.length === 1 ? kids[0] : el('mrow', null, ...kids));
  root.dataset.tex = String(tex);
  if (label === undefined) root.setAttribute('aria-label', mathSpeech(root));
  return root;
}

/** Several display formulas, one per line, in a `<div class="formula">` (the explanation's formula block). */
export function formulaBlock(lines, { label = 'Formula' } = {}) {
  const div = document.createElement('div');
  div.className = 'formula formula-math';
  div.setAttribute('role', 'group');
  div.setAttribute('aria-label', label);
  div.tabIndex = 0;   // it scrolls sideways on a narrow screen: the keyboard can scroll it (WCAG 2.1.1)
  for (const line of [].concat(lines)) div.appendChild(math(line, { display: true }));
  return div;
}

const SUB = { ',': ',', 0: '₀', 1: '₁', 2: '₂', 3: '₃', 4: '₄', 5: '₅', 6: '₆', 7: '₇', 8: '₈', 9: '₉', '+': '₊', '−': '₋', '-': '₋', '(': '₍', ')': '₎', i: 'ᵢ', j: 'ⱼ', k: 'ₖ', l: 'ₗ', m: 'ₘ', n: 'ₙ', p: 'ₚ', r: 'ᵣ', s: 'ₛ', t: 'ₜ', u: 'ᵤ' };
const SUP = { '*': '*', '∗': '*', 0: '⁰', 1: '¹', 2: '²', 3: '³', 4: '⁴', 5: '⁵', 6: '⁶', 7: '⁷', 8: '⁸', 9: '⁹', '+': '⁺', '−': '⁻', '-': '⁻', '(': '⁽', ')': '⁾', a: 'ᵃ', i: 'ⁱ', k: 'ᵏ', n: 'ⁿ', r: 'ʳ', s: 'ˢ', T: 'ᵀ' };

/**
 * The plain-text fallback of a formula, for places MathML cannot go (canvas labels, CSV): Unicode letters,
 * sub/superscript digits where they exist, `_{…}` / `^{…}` otherwise.
 */
export function mathText(tex) {
  let s = String(tex)
    .replace(/\\(text|mathrm|operatorname|mathbf)\{([^}]*)\}/g, '$2')
    .replace(/\\frac\{([^}]*)\}\{([^}]*)\}/g, '($1)/($2)')
    .replace(/\\sqrt\{([^}]*)\}/g, '√($1)')
    .replace(/\\(left|right)\s*(\\?.)/g, (_, __, d) => (d === '.' ? '' : d.replace('\\', '')))
    .replace(/\\q?quad\b/g, '  ').replace(/\\[,;:! ]/g, ' ').replace(/\\\|/g, '‖').replace(/\\([{}])/g, '\u0000$1')
    .replace(/\\([A-Za-z]+)/g, (m, name) => GREEK[name] ?? SYMBOLS[name] ?? (ACCENTS[name] !== undefined ? '' : name));
  const script = (map, body) => {
    const chars = [...body];
    return chars.every((c) => map[c]) ? chars.map((c) => map[c]).join('') : null;
  };
  s = s.replace(/_\{([^}]*)\}|_(\S)/g, (m, a, b) => { const body = a ?? b; return script(SUB, body) ?? `_${a !== undefined ? `(${body})` : body}`; });
  s = s.replace(/\^\{([^}]*)\}|\^(\S)/g, (m, a, b) => { const body = a ?? b; return script(SUP, body) ?? `^${a !== undefined ? `(${body})` : body}`; });
  // biome-ignore lint/suspicious/noControlCharactersInRegex: \u0000 marks an escaped brace \{ (set above) so it stays; then the mark goes
  return s.replace(/(?<!\u0000)[{}]/g, '').replace(/\u0000/g, '').replace(/-/g, '−').replace(/\s+/g, ' ').trim();
}
