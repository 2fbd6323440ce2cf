// The stepper of "Interpolating vs approximating": the B2-spline construction stage by stage — the data and their
// knots, the auxiliary end points, the joints Rᵢ, the even vertices C₂ᵢ (eqs. (8), (9)), the odd vertices by eq. (5)
// (corrected; the printed weight beside it), the cubic B-spline on the split knots — with the weights of the joint
// nearest u, every number from b2Curve (c.build, c.printed). The draw functions read the state and c only.
import { fmt, pairSep } from '../../lib/dom.js';
import { t, tn } from '../../lib/i18n.js';
import { PALETTE } from '../../lib/plot2d.js';
import { mathText } from '../../lib/mathml.js';
import { sub } from './state-rules.js';

const num = (x, d = 3) => fmt(x, d);
const at = (flat, j) => [flat[2 * j], flat[2 * j + 1]];
const pt = (q) => `(${num(q[0])}${pairSep()}${num(q[1])})`;
/** The joint i (1…n) nearest the evaluation point u: its numbers fill the formulas. */
function focus(state, build) {
  if (!build) return 1;
  const jp = build.jointParams;
  let best = 0;
  for (let k = 1; k < jp.length; k++) if (Math.abs(jp[k] - state.u) < Math.abs(jp[best] - state.u)) best = k;
  return best + 1;
}
const ix = (j) => String(j);           // index text (negative indices are fine in TeX)
const comb = (ws, names) => ws.map((w, k) => `${k && w >= 0 ? '+ ' : k ? '- ' : ''}${num(k ? Math.abs(w) : w, 4)}\\,${names[k]}`).join(' ');

/** The six stages of the construction with the numbers of the joint nearest u (www/lib/stepper.js steps). */
export function buildSteps(state, c) {
  const { build, printed } = c;
  if (!build) return [];
  const W = (j) => state.points[j + 1];   // W_j, j = −1…n+2
  const n = build.joints.length / 2, i = focus(state, build), dk = build.dataKnots, sec3 = state.construction === 'section3';
  const out = [];
  // 1. data and knots
  out.push({
    label: 'the data W₁ … Wₙ and their knots',
    tex: [
      sec3 || state.knots === 'uniform' ? `u_{j} = j - 1 \\quad (\\text{${t('uniform knots')}})` : '\\Delta_{j} = u_{j+1} - u_{j} = \\lVert W_{j+1} - W_{j} \\rVert, \\quad u_{1} = 0',
      `u_{${i - 1}}, u_{${i}}, u_{${i + 1}}, u_{${i + 2}} = ${[i - 1, i, i + 1, i + 2].map((j) => num(dk[j + 1])).join(pairSep())}`,
      `W_{${i}} = ${pt(W(i))}, \\quad n = ${n}`,
    ],
    note: tn(n, '{n} data point W₁ … {last} (circled); the curve will run over [u₁, {end}].', '{n} data points W₁ … {last} (circled); the curve will run over [u₁, {end}].', { last: `W${sub(n)}`, end: `u${sub(n)}` }),
  });
  // 2. auxiliary points
  out.push({
    label: 'the auxiliary end points',
    tex: state.autoEnds
      ? ['W_{0} = 2W_{1} - W_{2}, \\quad W_{-1} = 2W_{1} - W_{3}', `W_{0} = ${pt(W(0))}, \\quad W_{-1} = ${pt(W(-1))}`]
      : [`W_{-1} = ${pt(W(-1))}, \\quad W_{0} = ${pt(W(0))}`, `W_{${n + 1}} = ${pt(W(n + 1))}, \\quad W_{${n + 2}} = ${pt(W(n + 2))}`],
    note: state.autoEnds ? 'Automatic ends: the data reflected through W₁ and Wₙ.' : 'Free (drag the grey squares): they steer the curve’s ends, which it does not pass through.',
  });
  // 3. joints
  const jw = Array.from(build.jointWeights.slice(3 * (i - 1), 3 * i));
  out.push({
    label: 'the joints Rᵢ',
    tex: [
      sec3 ? 'R_{i} = a\\,W_{i-1} + (1 - 2a)\\,W_{i} + a\\,W_{i+1}' : 'R_{i} = 6a\\,W^{B}_{i} + (1 - 6a)\\,W_{i}, \\quad W^{B}_{i} = L^{B}(u_{i})',
      `a = ${num(state.a, 4)}: \\quad R_{${i}} = ${comb(jw, [`W_{${ix(i - 1)}}`, `W_{${i}}`, `W_{${i + 1}}`])}`,
      `R_{${i}} = ${pt(at(build.joints, i - 1))}`,
    ],
    note: state.a === 0 ? 'a = 0: the joints are the data — the curve will interpolate.' : 'a ≠ 0: the joints move off the data towards the B-spline’s points.',
  });
  // 4. even vertices
  const ew = Array.from(build.evenWeights.slice(4 * i, 4 * i + 4));
  out.push({
    label: 'the even vertices C₂ᵢ (tension)',
    tex: [
      sec3 ? 'C_{2i} = -p\\,W_{i-1} + (\\frac{1}{2} + p)(W_{i} + W_{i+1}) - p\\,W_{i+2}'
        : 'C_{2i} = -p^{-}_{i}W_{i-1} + (\\frac{1}{2} + p^{-}_{i})W_{i} + (\\frac{1}{2} + p^{+}_{i})W_{i+1} - p^{+}_{i}W_{i+2}',
      sec3 ? `p = ${num(state.p, 4)}` : `p^{\\pm}_{i} = \\frac{6p_{i}\\Delta_{i}^{2}}{\\Delta_{i}^{2} + 5\\Delta_{i}\\Delta_{i\\pm1} + ${state.c2}\\,\\Delta_{i\\pm1}^{2}}, \\quad p_{${i}} = ${num(build.tension[i], 4)}`,
      `C_{${2 * i}} = ${comb(ew, [`W_{${ix(i - 1)}}`, `W_{${i}}`, `W_{${i + 1}}`, `W_{${i + 2}}`])}`,
      `C_{${2 * i}} = ${pt(at(build.controlPoints, 2 * i))}`,
    ],
    note: state.a === 0 ? 'The weights on the outer points are −p⁻ᵢ and −p⁺ᵢ (eqs. (8), (9)).' : 'With a ≠ 0 these weights are blended with those of the B-spline (section 5).',
  });
  // 5. odd vertices by eq. (5): the cubic control polygon
  const w5 = Array.from(build.eq5Weights.slice(3 * (i - 1), 3 * i));
  const wp = printed ? printed.eq5Weights[3 * (i - 1) + 2] : NaN;
  out.push({
    label: 'the odd vertices: the cubic control polygon',
    tex: [
      'R_{i} = w_{0}\\,C_{2i-2} + w_{1}\\,C_{2i-1} + w_{2}\\,C_{2i} \\quad (5)',
      `w_{0}, w_{1}, w_{2} = ${w5.map((w) => num(w, 4)).join(pairSep())}`,
      `C_{${2 * i - 1}} = \\frac{R_{${i}} - ${num(w5[0], 4)}\\,C_{${2 * i - 2}} - ${num(w5[2], 4)}\\,C_{${2 * i}}}{${num(w5[1], 4)}}`,
      `C_{${2 * i - 1}} = ${pt(at(build.controlPoints, 2 * i - 1))}`,
      `w_{2} = \\frac{b^{2}}{(b+c)(b+c+d)} = ${num(w5[2], 4)}`,
      `\\text{${t('printed:')}}\\; w_{2} = \\frac{bc}{(b+c)(b+c+d)} = ${num(wp, 4)}`,
    ],
    note: t('(a, b, c, d) are the four knot spans around the joint. {more}', {
      more: Math.abs(wp - w5[2]) < 1e-12 ? t('Here b = c, so the printed weight happens to agree.') : t('The printed weight differs here: switch on “Also draw eq. (5) as printed” to see the curve miss the data.'),
    }),
  });
  // 6. the curve
  const ju = build.jointParams[i - 1];
  out.push({
    label: 'the curve: a cubic B-spline on the split knots',
    tex: [
      `L^{a}(u) = \\sum_{j=0}^{${2 * n}} N_{j,3}(u)\\,C_{j}, \\quad u \\in [${num(build.domain[0])}${pairSep()}${num(build.domain[1])}]`,
      `L^{a}(${num(ju)}) = R_{${i}} = ${pt(at(build.joints, i - 1))}`,
    ],
    note: 'C² everywhere: the split knots u′ halve every data span, so the 2n + 1 control points make 2n − 2 cubic pieces.',
  });
  return out;
}

/** Under the points: the weights of C₂ᵢ (stage 4), the cubic control polygon and its leg through R_i (stage 5). */
export function drawStepLines(plot, state, { build }) {
  const s = state.step;
  if (s < 0 || !build) return;
  const W = (j) => state.points[j + 1];
  const i = focus(state, build);
  if (s === 3) for (const j of [i - 1, i, i + 1, i + 2]) plot.polyline([at(build.controlPoints, 2 * i), W(j)], { color: PALETTE.highlight, width: 1.5, dash: [4, 4] });
  if (s >= 4) plot.polyline(build.controlPoints, { color: PALETTE.highlight, width: s === 4 ? 2.5 : 1.5, alpha: 0.9 });
  if (s === 4) plot.polyline([at(build.controlPoints, 2 * i - 2), at(build.controlPoints, 2 * i - 1), at(build.controlPoints, 2 * i)], { color: PALETTE.accent, width: 5, alpha: 0.6 });
}

/** Over everything: the points of the stages so far, the current one larger and named. */
export function drawStepMarks(plot, state, { build }) {
  const s = state.step;
  if (s < 0 || !build) return;
  const W = (j) => state.points[j + 1];
  const n = build.joints.length / 2, i = focus(state, build), font = '600 13px system-ui, sans-serif';
  if (s === 0) plot.points(state.points.slice(2, -2), { color: PALETTE.accent, radius: 11, hollow: true });
  if (s === 1) plot.points([W(-1), W(0), W(n + 1), W(n + 2)], { color: PALETTE.accent, radius: 11, hollow: true });
  if (s >= 2) {
    plot.points(build.joints, { color: PALETTE.second, radius: s === 2 ? 6 : 4.5, shape: 'square', stroke: '#fff' });
    const r = at(build.joints, i - 1);
    if (s === 2 || s === 5) plot.label(r[0], r[1], mathText(`R_{${i}}`), { color: '#0b5e45', offset: [10, 18], baseline: 'top', font });
  }
  if (s >= 3) {
    plot.points(build.evenVertices, { color: PALETTE.highlight, radius: s === 3 ? 7 : 5, shape: 'diamond' });
    const c = at(build.controlPoints, 2 * i);
    if (s === 3 || s === 4) plot.label(c[0], c[1], mathText(`C_{${2 * i}}`), { color: '#7a3a63', offset: [10, -10], font });
  }
  if (s >= 4) {
    const odd = [];
    for (let j = 1; j < build.controlPoints.length / 2; j += 2) odd.push(at(build.controlPoints, j));
    plot.points(odd, { color: PALETTE.highlight, radius: s === 4 ? 5 : 3.5, hollow: true });
    const c = at(build.controlPoints, 2 * i - 1);
    if (s === 4) plot.label(c[0], c[1], mathText(`C_{${2 * i - 1}}`), { color: '#7a3a63', offset: [10, -10], font });
  }
}
