// Raw TeX or ASCII notation that a reader must never see (L^a, _{…}, u_p, u_-1, \alpha): the patterns that
// tests/e2e/notation.test.mjs looks for on every page, and tests/node/errors.test.mjs in every error message (the
// pages show messages as they are).

/** Raw notation: what a reader must never see. Each entry: [name, pattern]. */
export const RAW = [
  ['caret superscript (L^a, 10^8, C^r)', /[\p{L}\p{N})\]}*]\^[\p{L}\p{N}({*−-]/u],
  ['TeX braces (_{…}, ^{…})', /[_^]\{/u],
  ['underscore subscript (u_p, B_ij, N_i,p)', /(?<![\p{L}\p{N}_.\/-])\p{L}{1,2}_[\p{L}\p{N}\-−]/u],
  ['backslash command (\\alpha)', /\\[a-zA-Z]{2,}/u],
];

/** The offending snippets of a text: "name: …context…". */
export function rawIn(text) {
  const out = [];
  for (const [name, re] of RAW) {
    const g = new RegExp(re.source, `${re.flags}g`);
    for (const m of text.matchAll(g)) out.push(`${name}: “${text.slice(Math.max(0, m.index - 25), m.index + 20).replace(/\s+/g, ' ')}”`);
  }
  return out;
}


/**
 * An ASCII index after a letter: P0, N1 = …, u3, W-1, B1,2 (write P₀, N₁, u₃, W₋₁, B₁,₂). Only for what a 2D plot
 * says (its description, its live region, its canvas labels: tests/e2e/notation.test.mjs), not for whole pages,
 * where prose has "2D", "Figure 3" and file names. One letter standing alone (no letter, digit, _, #, ., /, \ or
 * hyphen before it), an optional minus, digits, and then no letter or digit. Allowed on purpose:
 *   - "2D", "3D", "1e-5": the letter comes after a digit (a dimension, a number's exponent);
 *   - "B-spline", "x-axis": no digit after the letter;
 *   - "x1.5", "×2": a factor — a decimal after the letter (a sentence's "P1." is still caught) or a × sign;
 *   - "Fig3", "mp4", "#a1b2c3", "api/v2": more than one letter before the digits, or a # / . / hyphen before it;
 *   - "B2-spline": Kuklišová's own name for her splines (interp-approx), written so in the paper.
 * Not allowed: "C2 continuity", "L2 norm", "G1" (write C², L², G¹).
 */
export const ASCII_INDEX = /(?<![\p{L}\p{N}_#.\/\\-])\p{L}-?\d+(?![\p{L}\p{N}]|\.\d|-spline)/u;

/** The ASCII indices of a text (see ASCII_INDEX): "…context…" for each. */
export function asciiIndexIn(text) {
  const g = new RegExp(ASCII_INDEX.source, `${ASCII_INDEX.flags}g`);
  return [...String(text).matchAll(g)].map((m) => `ASCII index “${m[0]}”: “${text.slice(Math.max(0, m.index - 25), m.index + 20).replace(/\s+/g, ' ')}”`);
}
