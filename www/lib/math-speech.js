// A formula in words (issue 25, "formulas read aloud"): the reading of a typeset <math> element that a screen
// reader speaks when it has no MathML support (it then reads the element's aria-label, set by www/lib/mathml.js).
//
//   N_{i,p}(u)            → "N sub i comma p end sub (u)"
//   L^a = 6a\,L^B + …     → "L superscript a equals 6 a L superscript B plus …"
//   \frac{m^2}{m^2 - 1}   → "fraction m squared over m squared minus 1 end fraction"
//
// The reading follows the MathML tree (not the TeX text), in the words of MathSpeak's brief style: a script of one
// symbol is "x sub i", of several "x sub i comma p end sub"; squares and cubes are "squared" / "cubed", a star
// superscript "star"; Greek letters are spoken by name. The words are in WORDS, OPERATORS and GREEK below, in English;
// each is spoken in the page's language through t() (www/lib/i18n.js; the catalogues' part www/lang/<code>/math.js).

import { t } from './i18n.js';

const WORDS = {
  sub: 'sub', endSub: 'end sub', sup: 'superscript', endSup: 'end superscript', squared: 'squared', cubed: 'cubed',
  star: 'star', prime: 'prime', frac: 'fraction', over: 'over', endFrac: 'end fraction', sqrt: 'square root of',
  endSqrt: 'end root', capital: 'capital',
};
/** A word of WORDS in the page's language. @param {keyof typeof WORDS} k */
const w = (k) => t(WORDS[k]);

/** Accents over a letter, by name. */
const ACCENTS = { '¯': 'bar', '^': 'hat', '~': 'tilde', '˙': 'dot', '→': 'vector' };

/** Operators and symbols in words (those not listed are spoken as they are: ( ) [ ] , ;). */
const OPERATORS = {
  '=': 'equals', '+': 'plus', '−': 'minus', '-': 'minus', '<': 'less than', '>': 'greater than', '≤': 'less than or equal to',
  '≥': 'greater than or equal to', '≠': 'not equal to', '≈': 'approximately equals', '≡': 'is identical to',
  '·': 'times', '×': 'times', '±': 'plus or minus', '∓': 'minus or plus', '→': 'to', '←': 'from', '↦': 'maps to',
  '⇒': 'implies', '⇔': 'if and only if', '∈': 'in', '∉': 'not in', '⊂': 'subset of', '∪': 'union', '∩': 'intersection',
  '∑': 'sum', '∏': 'product', '∫': 'integral', '∂': 'partial', '∇': 'nabla', '∞': 'infinity', '…': 'dots',
  '⋯': 'dots', '∀': 'for all', '∃': 'there exists', '∘': 'composed with', '‖': 'norm', '|': 'absolute value',
  '⟨': 'open angle', '⟩': 'close angle', '⌊': 'floor', '⌋': 'end floor', '⌈': 'ceiling', '⌉': 'end ceiling',
  '/': 'over', '′': 'prime', '∗': 'star', '*': 'star', ':': 'colon', '{': 'the set', '}': 'end set',
};

const GREEK = {
  α: 'alpha', β: 'beta', γ: 'gamma', δ: 'delta', ε: 'epsilon', ζ: 'zeta', η: 'eta', θ: 'theta', ϑ: 'theta',
  ι: 'iota', κ: 'kappa', λ: 'lambda', μ: 'mu', ν: 'nu', ξ: 'xi', π: 'pi', ρ: 'rho', σ: 'sigma', τ: 'tau',
  υ: 'upsilon', φ: 'phi', χ: 'chi', ψ: 'psi', ω: 'omega',
  Γ: 'gamma', Δ: 'delta', Θ: 'theta', Λ: 'lambda', Ξ: 'xi', Π: 'pi', Σ: 'sigma', Φ: 'phi', Ψ: 'psi', Ω: 'omega',
};

/** A symbol in words: a Greek letter by name ("capital Sigma"), an operator by its word, anything else as is. */
function symbol(s) {
  if (/^[A-Za-z]{2,}$/.test(s)) return s;   // an upright name (max, sin, CV)
  return [...s].map((c) => {
    // a capital letter: "capital" and the letter's name (one name per letter: Σ is "capital sigma")
    if (GREEK[c]) return /\p{Lu}/u.test(c) ? `${w('capital')} ${t(GREEK[c.toLowerCase()] ?? GREEK[c])}` : t(GREEK[c]);
    return OPERATORS[c] ? t(OPERATORS[c]) : c;
  }).join(' ');
}

/** Is the node one spoken symbol (so its script needs no "end")? */
const simple = (n) => n.localName === 'mn' || (['mi', 'mo', 'mtext'].includes(n.localName) && [...(n.textContent || '')].length <= 1);

/** A script in words: "sub i" for one symbol, "sub i comma p end sub" for more; squares, cubes and stars short. */
function script(kind, n) {
  const s = (n.textContent || '').trim();
  if (kind === 'sup') {
    if (s === '2') return w('squared');
    if (s === '3') return w('cubed');
    if (s === '∗' || s === '*') return w('star');
    if (s === '′') return w('prime');
  }
  const body = speak(n);
  const [open, close] = kind === 'sub' ? [w('sub'), w('endSub')] : [w('sup'), w('endSup')];
  return simple(n) ? `${open} ${body}` : `${open} ${body} ${close}`;
}

/** The words of one MathML node (and its children). @param {Element} n @returns {string} */
function speak(n) {
  const kids = [...n.children];
  switch (n.localName) {
    case 'mn': return (n.textContent || '').trim();
    case 'mi': return symbol((n.textContent || '').trim());
    case 'mo': {
      const s = (n.textContent || '').trim();
      return s === ',' ? t('comma') : symbol(s);
    }
    case 'mtext': return (n.textContent || '').trim();
    case 'mspace': return '';
    case 'msub': return `${speak(kids[0])} ${script('sub', kids[1])}`;
    case 'msup': return `${speak(kids[0])} ${script('sup', kids[1])}`;
    case 'msubsup': return `${speak(kids[0])} ${script('sub', kids[1])} ${script('sup', kids[2])}`;
    case 'mfrac': return simple(kids[0]) && simple(kids[1])
      ? `${speak(kids[0])} ${w('over')} ${speak(kids[1])}`
      : `${w('frac')} ${speak(kids[0])} ${w('over')} ${speak(kids[1])} ${w('endFrac')}`;
    case 'msqrt': return `${w('sqrt')} ${kids.map(speak).join(' ')} ${w('endSqrt')}`;
    // an accent (x̄, x̂): the letter, then the accent's name
    case 'mover': { const a = ACCENTS[(kids[1]?.textContent || '').trim()]; return `${speak(kids[0])} ${a ? t(a) : ''}`; }
    default: return kids.map(speak).join(' ');
  }
}

/** The reading of a typeset formula (a <math> element from www/lib/mathml.js) in words. @param {Element} mathEl */
export function mathSpeech(mathEl) {
  // (a lone dot in parentheses, s(·), is a placeholder for the argument: "dot", not "times")
  return speak(mathEl).replace(/\s+/g, ' ').replace(new RegExp(`\\( ${t('times')} \\)`, 'g'), `(${t('dot')})`).replace(/([([]) /g, '$1').replace(/ ([)\]])/g, '$1').trim();
}
