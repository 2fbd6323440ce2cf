// The explanations of "Curve networks" (static text): what it shows (Dagnino–Lamberti–Remogna §3–4: the network,
// S, T, G; Kuklišová §7: GB), the key formulas (eqs. (35)–(40), Kuklišová eq. (4)), what to try, the correction of
// the printed ‖S − G‖∞, and the note "Why is S = G here?" shown when the network is of the special class.
import { h } from '../../lib/dom.js';
import { math } from '../../lib/mathml.js';
import { correctionLink } from '../../lib/papers-ref.js';

/** The content for `explanation(L.explain, …)` (www/lib/dom.js); `paper` is meta.paper. */
export function explanationContent(paper) {
  return {
    what: [
      ['A curve network: ', math('m + 1'), ' curves ', math('\\varphi_r(v)'), ' on the lines ', math('u = u_r'), ' and ', math('n + 1'), ' curves ', math('\\psi_s(u)'), ' on the lines ', math('v = v_s'), ', all ', math('C^1'), ' quadratic B-splines, meeting at the points ', math('I_{rs}'), ' (compatibility C2: ', math('\\varphi_r(v_s) = \\psi_s(u_r)'), '). Orange points are the control points P of the φᵣ, blue ones the Q of the ψₛ; drag any of them — the dependent control points are recomputed so the curves still meet (the C2 residual stays at rounding level).'],
      'Four surfaces pass through the same network: S, the unique C¹ piecewise quadratic on the criss-cross triangulation (the paper\'s construction, local, no parameter); T, a biquadratic tensor spline whose one free control point C11* minimises a thin-plate energy; G, the Gordon boolean sum of two skinned surfaces and a tensor interpolant on refined knots; and GB, the same boolean sum with cardinal cubic blending functions (Kuklišová’s eq. (4)).',
    ],
    math: [
      'S \\;\\text{on cell}\\; [u_{a-1}, u_a] \\times [v_{b-1}, v_b]: \\;\\text{BB net from the four edge curves (13 ordinates)}',
      'T = \\sum_{ij} C^*_{ij} B_i(u) B_j(v), \\quad C^*_{ij} = \\Gamma_{ij} + (-1)^{i+j} C^*_{11} \\frac{h_i k_j}{h_1 k_1}, \\quad C^*_{11} \\;\\text{from (38)}',
      'G = L_1 + L_2 - L_{12}, \\quad \\tilde{C} = \\tilde{C}^{L_1} + \\tilde{C}^{L_2} - \\tilde{C}^{L_{12}} \\;\\text{on}\\; \\tilde{U} = U \\cup \\bar{U}, \\; \\tilde{V} = V \\cup \\bar{V} \\qquad (39)\\text{–}(40)',
      'GB = \\sum_r \\varphi_r(v) L_r(u) + \\sum_s \\psi_s(u) M_s(v) - \\sum_{rs} I_{rs} L_r(u) M_s(v) \\qquad \\text{(Kuklišová eq. (4))}',
    ],
    tryThis: [
      'Pick "Separable": ‖S − G‖ is at rounding level (the paper\'s finding) while T differs. Drag one point: ‖S − G‖ jumps.',
      'Colour S by |S − G| to see where the two differ: along the cell diagonals, where G has no break lines.',
      'Turn on the Gordon components: G is L1 + L2 − Tg (Tg is the tensor surface L12 of the stepper); each of them interpolates only part of the data. Or press Step in “The Boolean sum and S, step by step”: L1, L2, L12, G, then S summed from its B-splines row by row.',
      'Show the triangulation and click a cell of S to see its Bernstein–Bézier net.',
    ],
    formulaNote: ['Correction (', correctionLink('correction-004-sg', '‖S − G‖ in §4.2'), '): the paper’s ‖S − G‖∞ = 4.4·10⁻¹⁵ holds only for networks of a special class (a(u) + b(v) + c·uv per coordinate); on other networks S and G differ — the table above shows by how much.'],
    paper,
  };
}

/** The children of the note "Why is S = G here?" (under the numbers, while ‖S − G‖∞ is at rounding level). */
export function whySGContent() {
  return [
    h('h3', null, 'Why is S = G here?'),
    h('p', null, 'Both surfaces interpolate every network curve, but they live in different spaces: G is a piecewise biquadratic on the refined grid Ũ × Ṽ, S a piecewise quadratic on the criss-cross triangles, and S is the only C¹ quadratic on those triangles through the network. So S = G exactly when G happens to be such a spline.'),
    h('p', null, 'That is the case when every coordinate of the network comes from f(u, v) = a(u) + b(v) + c·u·v with a, b C¹ quadratic splines on U and V (an (m + n + 4)-dimensional class): then L1, L2 and Tg reproduce f and G = f = S. The paper\'s ‖S − G‖ = 4.4·10⁻¹⁵ is of this kind; for a generic network ‖S − G‖ is about a quarter of the network\'s size. Drag a point to leave the class.'),
  ];
}
