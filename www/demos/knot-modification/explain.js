// The explanation of "Knot modification" (static text with the paper's formulas; www/lib/dom.js explanation()).
import { math } from '../../lib/mathml.js';
import { correctionLink } from '../../lib/papers-ref.js';

/** What it shows, the key formulas (5), (6), (9), (10), Theorems 3, 7 and de Boor's recursion, what to try. */
export function explanationContent(meta) {
  return {
    what: [
      ['A B-spline curve ', math('a(u) = \\sum_r N_r^k(u)\\, d_r'), ' of order k is fixed by its control points and its knots. Replace one interior knot ', math('u_p'), ' by a new value: the curve changes only on the ', math('2(k-1)'), ' spans whose pieces use ', math('u_p'), ' (highlighted), and every curve point moves along a path — a rational curve in ', math('u_p'), ' (Theorem 1). The stepper “Moving uₚ, step by step” shows why: in the de Boor recursion at one parameter only the weights α whose interval ends at the moved knot contain it.'],
      ['While ', math('u_p'), ' stays between its neighbours the members of this one-parameter family all touch one curve, the envelope ', math('e(w)'), ': a B-spline of order ', math('k-1'), ' on the knots with ', math('u_p'), ' removed, using only the control points ', math('d_{p-k+1}, \\ldots, d_{p-1}'), ' (eq. (6)). The curve with knot value ', math('u_p'), ' touches the envelope at its own point ', math('u = u_p'), '.'],
      ['With "extend" the knot may pass its neighbours: the paths continue (extended paths) and, for the points with ', math('u \\in [u_{p-1}, u_{p+1})'), ', end in control points: ', math('d_p'), ' as ', math('u_p \\to -\\infty'), ' and ', math('d_{p-k}'), ' as ', math('u_p \\to +\\infty'), ' (Theorem 3). On a surface two knots move at once; points move on path-surfaces, and the corners of the ', math('(u_p, v_q)'), ' plane give the control points ', math('d_{p,q}, d_{p,q-l}, d_{p-k,q}, d_{p-k,q-l}'), ' (Theorem 4, with the paper\'s garbled list corrected).'],
      ['Outside its neighbours the knot vector is no longer ordered, so the whole "curve" is only the pieces of the de Boor recursion continued algebraically: far from ', math('[u_{p-1}, u_{p+1}]'), ' it may break apart or shoot off (the paths there have poles where ', math('u_p'), ' meets another knot). The paper\'s statements, and the tracked points here, are about ', math('u \\in [u_{p-1}, u_{p+1})'), '.'],
    ],
    math: [
      '\\text{family:}\\quad s(u,v;u_p) = \\sum_r \\sum_s N_r^k(u;u_p)\\, N_s^l(v)\\, d_{rs} \\qquad (5)',
      '\\text{envelope:}\\quad e(w,v) = \\sum_{r=p-k+1}^{p-1} \\sum_s N_r^{k-1}(w)\\, N_s^l(v)\\, d_{rs}, \\quad w \\in [u_{p-1}, u_{p+1}] \\qquad (6)',
      '\\text{contact:}\\quad \\frac{\\partial^i e}{\\partial w^i}(u_p, v) = \\frac{k-1-i}{k-1} \\cdot \\frac{\\partial^i s}{\\partial u^i}(u_p, v; u_p) \\qquad (9)',
      'e(u_p, v) = s(u_p, v; u_p), \\quad \\frac{\\partial e}{\\partial w} = (2-k)\\, \\frac{\\partial s}{\\partial u_p} \\qquad (10), \\;\\text{Thm 7}',
      '\\text{limits:}\\quad u_p \\to -\\infty: \\sum_s N_s^l(v)\\, d_{p,s}; \\quad u_p \\to +\\infty: \\sum_s N_s^l(v)\\, d_{p-k,s} \\qquad \\text{Thm 3}',
      '\\text{de Boor:}\\quad d_j^r = (1-\\alpha_j^r)\\, d_{j-1}^{r-1} + \\alpha_j^r\\, d_j^{r-1}, \\quad \\alpha_j^r = \\frac{u - u_j}{u_{j+k-r} - u_j}',
    ],
    tryThis: [
      'Drag the triangle on the knot line (or move the slider): the diamonds run along their paths, and only the highlighted part of the curve moves.',
      'Press Step in “Moving uₚ, step by step”: the de Boor points that contain the moved knot are drawn in red; move the knot and watch only those change.',
      ['Watch the green envelope: every light-blue family member touches it once, at ', math('u = u_p'), '.'],
      ['Switch on "extend" and push ', math('u_p'), ' far to the left or right: the paths of all tracked points end at the ringed control point ', math('d_p'), ' or ', math('d_{p-k}'), '.'],
      ['Choose order 2: the envelope degenerates to the control point ', math('d_{p-1}'), ' and the paths are straight segments.'],
      'Open the Surface tab and move both knots: the tracked points move on path-surfaces, and with "extend" their corners approach the four labelled control points.',
    ],
    formulaNote: ['Corrections (', correctionLink('correction-002-thm4', 'Theorem 4'), ', ', correctionLink('correction-002-envelope', 'the envelope’s knots'), '): two of the printed corner limits of Theorem 4 are wrong (shown here corrected), and the envelope uses the knot vector without the moving knot, which the paper does not define.'],
    paper: meta.paper,
  };
}
