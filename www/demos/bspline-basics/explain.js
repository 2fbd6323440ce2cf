// The explanation of "B-spline basics" (static text): what it shows, the Cox–de Boor recursion, the curve,
// de Boor's algorithm and Boehm's knot insertion, what to try.

import { t } from '../../lib/i18n.js';

/** The content for explanation() (www/lib/dom.js); its prose is translated there, the words inside formulas here. */
export function explanationContent(meta) {
  return {
    what: [
      'A B-spline curve of degree p blends its control points P₀ … Pₙ₋₁ with the basis functions Nᵢ,ₚ(u): C(u) = Σᵢ Nᵢ,ₚ(u) Pᵢ. ' +
      'Each Nᵢ,ₚ is a piecewise polynomial of degree p that is non-zero only on the knot interval [uᵢ, uᵢ₊ₚ₊₁), so at any parameter u exactly p + 1 of them are non-zero (local control), they are never negative, and they sum to 1 — so the curve stays inside the convex hull of those p + 1 control points.',
      'The knot vector is clamped: the first and last knots are repeated p + 1 times, so the curve starts at P₀ and ends at Pₙ₋₁. The top plot shows the curve; the bottom plot shows every basis function over the domain, their sum, and the knots (the triangles under the axis can be dragged).',
    ],
    math: [
      `N_{i,0}(u) = 1 \\;\\text{${t('if')}}\\; u_{i} \\le u < u_{i+1}, \\;\\text{${t('else')}}\\; 0`,
      'N_{i,p}(u) = \\frac{u - u_{i}}{u_{i+p} - u_{i}}\\,N_{i,p-1}(u) + \\frac{u_{i+p+1} - u}{u_{i+p+1} - u_{i+1}}\\,N_{i+1,p-1}(u)',
      'C(u) = \\sum_{i} N_{i,p}(u)\\,P_{i}, \\quad \\sum_{i} N_{i,p}(u) = 1, \\quad N_{i,p}(u) \\ge 0',
      'P^{r}_{i} = (1 - \\alpha_{i,r})\\,P^{r-1}_{i-1} + \\alpha_{i,r}\\,P^{r-1}_{i}, \\quad \\alpha_{i,r} = \\frac{u - u_{i}}{u_{i+p+1-r} - u_{i}} \\quad (\\text{de Boor})',
      'Q_{i} = (1 - \\alpha_{i})\\,P_{i-1} + \\alpha_{i}\\,P_{i}, \\quad \\alpha_{i} = \\frac{\\bar u - u_{i}}{u_{i+p} - u_{i}} \\quad (\\text{Boehm})',
    ],
    mathLabel: 'Cox–de Boor recursion, the curve, de Boor’s algorithm and knot insertion',
    formulaNote: 'A term whose denominator is 0 is taken as 0. The step-by-step panel fills these formulas in with the numbers of the current curve.',
    tryThis: [
      'Drag one control point: only the part of the curve over p + 1 knot spans moves (local control).',
      'Scrub u: the highlighted basis functions are the ones whose control points (ringed) pull on C(u).',
      'Set the degree to 1: the curve becomes the control polygon. Raise it: the curve gets smoother and pulls away from the polygon.',
      'Drag two interior knots close together: the curve bends more sharply there (continuity drops as knots merge).',
      'Step by step: press Step to walk through de Boor’s triangle at u, level by level, then switch to “Insert knot u” to see which control points Boehm’s algorithm replaces.',
      'Use Tab to reach a plot, Page Down/Page Up to choose a point, and the arrow keys (Shift for larger steps) to move it.',
    ],
    paper: meta.paper,
  };
}
