// The stepper "The basis, step by step" of "Quasi-cubic curves": on the segment of the evaluation point u
// (i = ⌊u⌋, t = u − i) each piece B_j(α; t) = (1 − α) B⁰_j(t) + α B¹_j(t) with the numbers from the wasm core
// (compute.js, c.stepData), then their sum, a partition of unity (the reconstructed basis of the quasi-cubic
// paper §2, see the correction on the papers page).
import { fmt } from '../../lib/dom.js';
import { mathText } from '../../lib/mathml.js';
import { sub } from './data.js';

const B0TEX = ['\\frac{1-t}{4} - \\sigma', '\\frac{1}{2} - \\frac{t}{4} + \\sigma', '\\frac{1}{4} + \\frac{t}{4} + \\sigma', '\\frac{t}{4} - \\sigma'];
const B1TEX = ['\\frac{(1-\\sin\\theta)^2}{6}', '\\frac{(1+\\cos\\theta)^2}{6}', '\\frac{(1+\\sin\\theta)^2}{6}', '\\frac{(1-\\cos\\theta)^2}{6}'];
const num = (x, d = 4) => (x < 0 ? `(${fmt(x, d)})` : fmt(x, d));
export function basisSteps(state, { stepData, basis }) {
  if (!stepData) return [];
  const { seg, t, v, v0, v1, worst } = stepData, a = state.alpha;
  const at = `${num(a, 2)};${fmt(t, 3)}`;
  const steps = [0, 1, 2, 3].map((j) => ({
    label: `the piece B${sub(j)}, weight of b${sub(seg + j)} on segment ${seg}`,
    tex: [
      `B_${j}(\\alpha;t) = (1-\\alpha)\\,B^0_${j}(t) + \\alpha\\,B^1_${j}(t)`,
      `B^0_${j} = ${B0TEX[j]}, \\quad B^1_${j} = ${B1TEX[j]}`,
      `\\theta = \\frac{\\pi t}{2}, \\quad \\sigma = \\frac{\\sin \\pi t}{4\\pi}`,
      `B_${j}(${at}) = (1-${num(a, 2)})\\cdot ${num(v0[j])}`,
      `+ ${num(a, 2)}\\cdot ${num(v1[j])} = ${num(v[j])}`,
    ],
    note: `At the evaluation point u = ${fmt(state.u, 3)} (segment ${seg}, t = ${fmt(t, 3)}); move it with Play u.`,
  }));
  const sum = v[0] + v[1] + v[2] + v[3];
  steps.push({
    label: 'their sum: a partition of unity',
    tex: [
      `\\sum_{j=0}^{3} B_j(${at}) = ${fmt(sum, 12)}`,
      `= ${v.map((x, i) => (i ? (x < 0 ? `- ${fmt(-x, 4)}` : `+ ${fmt(x, 4)}`) : fmt(x, 4))).join(' ')}`,
      `\\max_{t} \\left| \\sum_j B_j(${num(a, 2)};t) - 1 \\right| = ${worst === 0 ? '0' : worst.toExponential(1)}`,
    ],
    note: `The curve point is ${mathText(`p(u) = \\sum_j B_j b_{${seg}+j}`)}: an affine combination, so the curve moves with its polygon. Measured over ${basis ? basis.params.length : 0} values of t.`,
  });
  return steps;
}
