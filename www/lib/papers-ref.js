// The five papers as readers know them: authors, title, and where the text says it appeared. One table for
// the papers page (www/papers.js) and the demos' references, so a paper is cited the same way everywhere.
// cite(key, where) gives the one-line reference of a demo; correctionLink(id, text) links a demo's
// "Corrections" note to the entry on the papers page that states the printed claim, the correct one and why.

import { h } from './dom.js';

// `key` is an internal table key (never shown); `cite` is the short reference used in the demos.
export const PAPERS = [
  {
    key: '000', ref: 'K', short: 'Kuklišová',
    title: 'Construction of non-uniform basis functions for spline curves and surfaces',
    authors: 'Mária Kuklišová',
    where: 'Department of Computer Graphics and Image Processing, Faculty of Mathematics and Physics, Comenius University, Bratislava. The text names no journal or year; its own references date from 1999.',
    contribution: [
      'Builds C² B2-spline basis functions from the cubic B-spline so that one parameter a moves a curve continuously from interpolating its points (a = 0) to the approximating cubic B-spline (a = 1/6), with a tension p and chord-length (non-uniform) knots.',
      'Extends the construction to tensor-product surfaces and to spline-blended surfaces through a network of curves, and proposes modified knots and an automatic tension rule.',
    ],
  },
  {
    key: '001', ref: 'GCT', short: 'Gânscă, Coman, Ţămbulea',
    title: 'Remodelling given Bézier spline curves and surfaces',
    authors: 'Ioan Gânscă, Gheorghe Coman, Leon Ţămbulea',
    where: 'Technical University and “Babeş-Bolyai” University, Cluj-Napoca. Dedicated to Professor Ioan Purdea at his 60th anniversary; the text names no journal or year.',
    contribution: [
      'Raises the degree of a polynomial Bézier spline by one with free parameters α instead of the fixed weights of the usual degree elevation, so the curve can be reshaped while its control polygon’s breakpoints stay and a chosen class Cʳ is kept (eq. (9)).',
      'Gives the curvature at the joints of the remodelled curve and carries the construction to tensor-product Bézier spline surfaces, in one direction (§4.1) and in both (§4.2).',
    ],
  },
  {
    key: '002', ref: 'JH', short: 'Juhász, Hoffmann',
    title: 'On the family of B-spline surfaces obtained by knot modification',
    authors: 'Imre Juhász, Miklós Hoffmann',
    where: 'University of Miskolc and Károly Eszterházy College, Eger. Received 2 November 2005, accepted 8 February 2006.',
    contribution: [
      'Moving one knot of a B-spline surface makes its points travel on paths (path-surfaces when a knot moves in each direction); the paper proves where these paths go when the knot leaves its interval and where they end.',
      'Shows that the family of surfaces obtained this way has an envelope, a B-spline surface of lower order, which touches every member along a curve (G¹ contact).',
    ],
  },
  {
    key: '003', ref: 'QC', short: 'Quasi-cubic trigonometric splines',
    title: 'Quasi-cubic trigonometric B-spline curves and surfaces, and a C² blended interpolation spline',
    authors: 'The authors’ names are not preserved in the text we work from',
    where: 'The title above describes the paper; its printed title, authors and venue are not preserved in that text, which begins with the abstract “A class of quasi-cubic B-spline base functions by trigonometric polynomials are established…”.',
    contribution: [
      'Defines B-spline-like basis functions from trigonometric polynomials with a shape parameter α; the curves represent straight lines, parabolas, ellipses, circles and sine arcs exactly, and the tensor-product surfaces spheres and cylinders.',
      'Gives up positivity to build a C² interpolating spline with one local parameter per data point (the length of the tangent there), for curves and surfaces, and uses it for shape-preserving interpolation.',
    ],
  },
  {
    key: '004', ref: 'DLR', short: 'Dagnino, Lamberti, Remogna',
    title: 'Curve network interpolation by C¹ quadratic B-spline surfaces',
    authors: 'Catterina Dagnino, Paola Lamberti, Sara Remogna',
    where: 'The text names no journal or year.',
    contribution: [
      'Builds the unique C¹ piecewise quadratic surface on a criss-cross triangulation that interpolates a network of quadratic B-spline curves, with its control points in closed form from the curves and one free point C₁₁ that does not change the surface.',
      'Compares it with two biquadratic tensor-product alternatives through the same network: the surface of minimal thin-plate energy and the Gordon (boolean sum) surface.',
    ],
  },
];

const SHORT = {
  '000': 'M. Kuklišová, “Construction of non-uniform basis functions for spline curves and surfaces”',
  '001': 'I. Gânscă, Gh. Coman, L. Ţămbulea, “Remodelling given Bézier spline curves and surfaces”',
  '002': 'I. Juhász, M. Hoffmann, “On the family of B-spline surfaces obtained by knot modification” (2006)',
  '003': '“Quasi-cubic trigonometric B-spline curves and surfaces, and a C² blended interpolation spline”',
  '004': 'C. Dagnino, P. Lamberti, S. Remogna, “Curve network interpolation by C¹ quadratic B-spline surfaces”',
};

/** The short reference of a paper, e.g. cite('000', '§3–5') → 'M. Kuklišová, “Construction …”, §3–5'. */
export function cite(key, where = '') {
  const s = SHORT[key];
  if (!s) throw new Error(`unknown paper: ${key}`);
  return where ? `${s}, ${where}` : s;
}

/** The papers page's entry for a correction id (e.g. 'correction-000-eq5'). */
export function correctionHref(id) {
  return `papers.html#${id}`;
}

/** A link to a correction entry on the papers page. */
export function correctionLink(id, text) {
  return h('a', { href: correctionHref(id), class: 'correction-link' }, text);
}

/**
 * Replaces internal paper numbers ("seed 003") in a text that comes from data (e.g. the data sets' source
 * notes) by the paper's short reference.
 */
export function readerText(s) {
  return String(s).replace(/\bseed (00[0-4])\b/g, (_, k) => SHORT[k]);
}
