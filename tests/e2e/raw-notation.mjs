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

