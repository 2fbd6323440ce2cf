// The explanation of "Interpolating vs approximating" (static text with the paper's formulas; www/lib/dom.js
// explanation()): what it shows, the construction's eqs. (8), (9), (5) (corrected) and the §5 blend, what to try.
import { correctionLink } from '../../lib/papers-ref.js';
import { t, withNodes } from '../../lib/i18n.js';

export function explanationContent(meta) {
  return {
    what: [
      'Kuklišová\'s B2-splines are cubic B-splines whose control polygon C₀ … C₂ₙ is built from the data W₋₁ … Wₙ₊₂. The odd vertices are replaced by joints Rᵢ — points the curve passes through — and the even vertices C₂ᵢ come from four neighbouring data points with a tension pᵢ. With Rᵢ = Wᵢ the curve interpolates the data (a = 0); blending the joints and even vertices with those of the cubic B-spline on W₀ … Wₙ₊₁ gives a whole family Lᵃ that reaches the B-spline at a = 1/6 and is C² for every a.',
      'The knots are Farin\'s split knots: each chord-length span [uᵢ, uᵢ₊₁] is halved, so the cubic has 2n − 2 pieces on [u₁, uₙ]. The basis plot shows the blending functions Lⱼ(u) with Σⱼ Lⱼ = 1 (at a = 0, Lⱼ(uᵢ) = δᵢⱼ); the curvature plot shows κ(u) — continuous, because the curve is C².',
      withNodes(t('Corrections used here ({eq5}, {claim}, {eq8}, {auto}): the last weight of eq. (5) is Δ²₂ᵢ₋₁/((Δ₂ᵢ₋₁+Δ₂ᵢ)(Δ₂ᵢ₋₁+Δ₂ᵢ+Δ₂ᵢ₊₁)) (the printed one does not sum to 1); the paper\'s "a = 1/6, p = 0 gives the B-spline" holds only through the section-5 blend on non-uniform knots.'), {
        eq5: correctionLink('correction-000-eq5', t('eq. (5)')), claim: correctionLink('correction-000-bspline', t('“a = 1/6, p = 0 gives the B-spline”')),
        eq8: correctionLink('correction-000-eq8', t('eq. (8)')), auto: correctionLink('correction-000-autotension', t('automatic tension')),
      }),
    ],
    math: [
      'R_{i} = W_{i} \\;(a = 0), \\quad C_{2i} = -p^{-}_{i}W_{i-1} + (\\frac{1}{2} + p^{-}_{i})W_{i} + (\\frac{1}{2} + p^{+}_{i})W_{i+1} - p^{+}_{i}W_{i+2} \\quad (8)',
      `p^{-}_{i} = \\frac{6p_{i}\\Delta_{i}^{2}}{\\Delta_{i}^{2} + 5\\Delta_{i}\\Delta_{i-1} + c_{2}\\Delta_{i-1}^{2}}, \\quad p^{+}_{i} \\;\\text{${t('likewise with')}}\\; \\Delta_{i+1} \\quad (9)`,
      `R_{i} = w_{0}C_{2i-2} + w_{1}C_{2i-1} + w_{2}C_{2i}, \\quad w_{2} = \\frac{b^{2}}{(b+c)(b+c+d)} \\quad (5, \\text{${t('corrected')}})`,
      `L^{a} = 6a\\,L^{B} + (1 - 6a)\\,L \\quad (\\text{${t('section 5')}})`,
    ],
    mathLabel: 'The B2-spline construction: eqs. (8), (9), (5) and the section-5 blend',
    tryThis: [
      'Move a from 0 to 1/6: the blue curve leaves the data and lands on the orange dashed B-spline.',
      'Drag a data point: only a few pieces of the curve move (local control).',
      'Try the presets: Fig. 8 shows why uniform knots fail on uneven data and Fig. 10 the chord-length cure; Fig. 13/14 the modified knots.',
      'Switch on "how it is built" to see the joints (squares), even vertices (diamonds) and the full cubic control polygon.',
      'Set a < 0: the curve overshoots the data — the opposite of smoothing.',
      'Step by step: press Step to build the curve stage by stage; the formulas show the weights of the joint nearest u.',
      'Switch on “Also draw eq. (5) as printed” on the Fig. 8 data: the dashed curve misses the data points where long and short spans meet.',
    ],
    paper: meta.paper,
  };
}
