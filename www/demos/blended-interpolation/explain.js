// The explanation of "Blended interpolation" (static text): the BIS of quasi-cubic paper §4 (Eqs. 11–19), the exact
// curvature-matching β* that corrects Eqs. (36)–(37), what the paper's Fig. 15 claims and what is measured here.
import { math } from '../../lib/mathml.js';
import { correctionLink } from '../../lib/papers-ref.js';

/** The content for explanation() (www/lib/dom.js). */
export function explanationContent(meta) {
  return {
    what: [
      ['At ', math('\\alpha = 3'), ' the quasi-cubic spline interpolates: the curve passes through ', math('b_0, \\ldots, b_n'), ' at ', math('u = 0, \\ldots, n'), ', with tangent ', math("p'(j) = (\\frac{\\pi}{2} - 1)(b_{j+1} - b_{j-1})"), ' — but it has no free parameter. The blended interpolation spline (BIS) blends it with the chord ', math('L_i'), ' between neighbouring points through an allocated function ', math('s(t) = 10t^3 - 15t^4 + 6t^5'), ' (', math('k = 3'), '), and with a local parameter ', math('\\beta^*_j'), ' per point: at ', math('b_j'), ' the tangent becomes ', math("\\beta^*_j\\, p'(j)"), ' and the second derivative ', math("\\beta^*_j\\, p''(j)"), ', so the curve stays ', math('C^2'), '.'],
      '“Fair by curvature” chooses every β*ⱼ so that the curve’s curvature at bⱼ equals the curvature Kⱼ of the circle through bⱼ₋₁, bⱼ, bⱼ₊₁ (the dots in the lower plot). The paper’s Eq. (36) is garbled and only approximates this; SplineLab uses the exact rule below. The paper (Fig. 15) presents this as shape-preserving on the Titanium and RPN 14 data. Measured here it is not: on long, nearly straight runs the rule gives β* ≈ c₁/(4c₀²) ≈ 1.89, the tangents at the data points become about twice the chord, the curve nearly stops in the middle of each segment, and tiny loops appear (the “x runs backwards” readout counts them; the curvature plot spikes). The curvature at the data points is matched exactly all the same.',
    ],
    math: [
      '\\mathrm{BIS}_i(t) = L_i(t) + \\beta_i(t)\\,(p_i(t) - L_i(t)), \\quad L_i = (1 - s)\\,b_i + s\\,b_{i+1}, \\quad \\beta_i = (1 - s)\\,\\beta^*_i + s\\,\\beta^*_{i+1}',
      's(t) = \\sum_{j=k}^{2k-1} \\mathrm{C}(2k-1, j)\\, t^j (1 - t)^{2k-1-j} \\qquad (k = 3: \\; 10t^3 - 15t^4 + 6t^5)',
      '\\text{fair:}\\quad \\beta^*_j = \\frac{c_1}{c_0^2} \\cdot \\frac{|b_j - b_{j-1}| \\, |b_{j+1} - b_j|}{|b_{j+1} - b_{j-1}|^2}, \\quad c_0 = \\frac{\\pi}{2} - 1, \\quad c_1 = \\frac{\\pi^2}{4}',
    ],
    tryThis: [
      'Drag the pink diamond along the tangent: β* = 0 makes a corner, β* = 2 a long flat passage; the curvature plot changes only near that point.',
      'Press “Fair by curvature”: the curvature at every data point lands on its dot.',
      'Load Titanium and press “Fair by curvature”: the dots are hit exactly, but zoom into the flat part — the curve makes small loops, and “x runs backwards” is no longer 0. Set β* back to 1 and compare.',
      'Choose k = 2: the curvature plot jumps at the data points — the curve is only C¹.',
    ],
    formulaNote: ['Correction (', correctionLink('correction-003-eq36', 'eqs. (36)–(37)'), '): the printed local parameters match the curvature only approximately; “fair by curvature” uses the exact rule, and the allocated function needs k ≥ 3 for C².'],
    paper: meta.paper,
  };
}
