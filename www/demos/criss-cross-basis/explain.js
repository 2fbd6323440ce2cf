// The explanation of "Criss-cross basis" (static text): what it shows (Dagnino–Lamberti–Remogna §3: the C¹
// quadratic B-spline Bᵢⱼ, its octagonal support, its BB net from eq. (23)'s traces), the key formulas, what to try.
import { math } from '../../lib/mathml.js';

/** The content for `explanation(L.explain, …)` (www/lib/dom.js); `paper` is meta.paper. */
export function explanationContent(paper) {
  return {
    what: [
      ['Each cell ', math('[u_{a-1}, u_a] \\times [v_{b-1}, v_b]'), ' of the grid is cut by its two diagonals into four triangles (the criss-cross triangulation). ',
        'On it, the B-spline ', math('B_{ij}'), ' is a piecewise quadratic that is ', math('C^1'), ' everywhere — across the grid lines and across the diagonals. ',
        'It is non-negative, the ', math('B_{ij}'), ' sum to 1, and ', math('B_{ij}'), ' is zero outside an octagon: 28 triangles for an interior one, including only two triangles of each corner cell (outlined in orange).'],
      ['On every grid line ', math('B_{ij}'), ' has the same trace as the tensor product ', math('B_i(u)\\, B_j(v)'), ' of univariate quadratic B-splines (eq. (23) and its v-analogue). ',
        'That fixes its BB net cell by cell: corners and edge midpoints are products of the univariate Bézier ordinates, each half-diagonal ordinate is the mean of the two neighbouring edge midpoints, and the centre is the mean of all four. ',
        'A surface is the sum ', math('S = \\sum_{ij} C_{ij} B_{ij}'), ': the stepper of the Curve networks demo adds these terms up row by row.'],
    ],
    math: [
      '\\sigma_r = \\frac{h_r}{h_{r-1} + h_r}, \\quad \\sigma\'_r = \\frac{h_{r-1}}{h_{r-1} + h_r}, \\quad h_r = u_r - u_{r-1} \\quad (\\tau, \\tau\' \\;\\text{likewise in}\\; v)',
      '\\text{central cell of}\\; B_{ij}: \\quad c_{00} = \\sigma\'_i \\tau\'_j, \\; e_b = \\tau\'_j, \\; e_r = \\sigma_{i+1}, \\; e_t = \\tau_{j+1}, \\; e_l = \\sigma\'_i',
      'd_{00} = \\frac{e_b + e_l}{2}, \\ldots \\quad o = B_{ij}(\\xi_i, \\eta_j) = \\frac{\\sigma\'_i + \\sigma_{i+1} + \\tau\'_j + \\tau_{j+1}}{4} \\quad (\\frac{1}{2} \\;\\text{on a uniform grid})',
      '\\text{dependence:}\\quad \\sum_{i=1}^{m} \\sum_{j=1}^{n} (-1)^{i+j} h_i k_j B_{ij} = 0',
    ],
    tryThis: [
      'Drag a knot line next to Bᵢⱼ: its support stretches and the centre value Bᵢⱼ(ξᵢ, ηⱼ) moves away from 1/2.',
      'Set i = 0 or j = 0: boundary B-splines have fewer triangles; B₀₀ is non-zero only near one corner.',
      'Click a cell of the support (or use the sliders) to read its 13 BB ordinates; in a corner cell only one is non-zero.',
      'Make two knot lines almost meet: the triangles get thin, yet Bᵢⱼ stays C¹ and non-negative.',
    ],
    paper,
  };
}
