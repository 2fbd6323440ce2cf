// The explanation of "Quasi-cubic curves" (static text): what it shows, the basis B(α; t) = (1 − α) B⁰ + α B¹
// (reconstructed from the paper's stated properties), what to try, the corrections.
import { math } from '../../lib/mathml.js';
import { correctionLink } from '../../lib/papers-ref.js';

/** The content for explanation() (www/lib/dom.js). */
export function explanationContent(meta) {
  return {
    what: [
      ['Each segment of a quasi-cubic curve blends four consecutive control points with trigonometric basis functions: ', math('p_i(t) = \\sum_j B_j(\\alpha;t)\\, b_{i+j}, \\; t \\in [0,1]'), '. Like the cubic B-spline (dotted grey), the segments join with continuous first and second derivatives for every α — but the basis contains ', math('\\sin\\frac{\\pi t}{2}, \\cos\\frac{\\pi t}{2}, \\sin \\pi t, \\cos \\pi t'), ', so some curves that no polynomial spline can draw come out exactly.'],
      'The presets show them: at α = 1 a rhombus (any parallelogram) gives an ellipse and a square a circle; an isosceles triangle used as b₀, b₁, b₀, b₃ gives a parabola; at α = 0 a zig-zag with the right symmetry gives a sine wave. The orange band is the analytic curve, and the deviation printed on the right is measured by the wasm core over the whole curve: about 1e-16 when the condition holds. Drag a point or move α and watch it grow.',
    ],
    math: [
      'B(\\alpha;t) = (1-\\alpha)\\,B^0(t) + \\alpha\\,B^1(t), \\quad \\theta = \\frac{\\pi t}{2}',
      'B^1 = \\frac{1}{6}\\left[ (1-\\sin\\theta)^2, (1+\\cos\\theta)^2, (1+\\sin\\theta)^2, (1-\\cos\\theta)^2 \\right]',
      'B^0 = \\left[ \\frac{1-t}{4} - \\sigma, \\frac{1}{2} - \\frac{t}{4} + \\sigma, \\frac{1}{4} + \\frac{t}{4} + \\sigma, \\frac{t}{4} - \\sigma \\right], \\quad \\sigma = \\frac{\\sin \\pi t}{4\\pi}',
      '\\sum_i B_i = 1; \\quad B_i \\ge 0 \\;\\text{exactly for}\\; \\alpha \\in [-3, 1]; \\quad C^2 \\;\\text{joins for every}\\; \\alpha, \\quad C^3 \\;\\text{only at}\\; \\alpha = 1',
      '\\alpha = 1, \\;\\text{square with half-diagonal}\\; d: \\quad |p(t) - c| = \\frac{2d}{3}',
    ],
    tryThis: [
      'Choose Ellipse: the deviation reads about 1e-16. Drag one vertex: the red segment shows the diagonals no longer bisect each other, and the deviation jumps.',
      'Choose Circle and move α away from 1: the curve stays closed and smooth but is no longer round.',
      'Choose Sine and drag one point up: the y-relation of every segment that uses it breaks.',
      'In Free mode, move α from −3 to 3: for α ≤ 1 the curve stays inside the convex hull; at α = 3 it passes through b₁ … bₙ₊₁.',
    ],
    formulaNote: ['Corrections (', correctionLink('correction-003-basis', 'the basis'), ', ', correctionLink('correction-003-bspline', '“includes the B-spline”'), '): the explicit basis formulas are lost from the text and are reconstructed here from the stated properties; no α gives the cubic B-spline, contrary to the abstract.'],
    paper: meta.paper,
  };
}
