// Reader-facing notation of the "Bézier remodelling" demo: sub- and superscript digits, the parameter names
// αₖ⁽ᴵ⁾, the API's constraint strings in that notation, and numbers that may be tiny (jumps at rounding level).
import { fmt } from '../../lib/dom.js';

import { subscript as sub } from '../../lib/indices.js';
export { sub };
export const sup = (i) => String(i).replace(/\d/g, (d) => '⁰¹²³⁴⁵⁶⁷⁸⁹'[d]);
/** "⁽ᴵ⁾": a segment index as a superscript in parentheses. */
export const supParen = (i) => sup(`(${i})`).replace('(', '⁽').replace(')', '⁾');
export const alphaName = (k, I) => `α${sub(k)}${supParen(I)}`;
// "α_1^(2) = 1 − 2·α_4^(1)  (eq. 9)" (from the API) → "α₁⁽²⁾ = 1 − 2·α₄⁽¹⁾  (eq. 9)"
export const prettyConstraint = (t) => String(t).replace(/α_(\d+)\^\((\d+)\)/g, (_, k, i) => alphaName(k, i));
export const sci = (x) => (!Number.isFinite(x) ? String(x) : x === 0 ? '0' : Math.abs(x) >= 1e-3 && Math.abs(x) < 1e4 ? fmt(x, 4) : x.toExponential(1).replace('-', '−'));
