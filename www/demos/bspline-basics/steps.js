// The two steppers of "B-spline basics", filled in with the numbers of the current curve (every point from the
// wasm API, compute.js: c.tri from bsplineDeBoor, c.ins from bsplineInsertKnot): de Boor's triangle at u, level by
// level, P^r_i = (1 − α_{i,r}) P^{r−1}_{i−1} + α_{i,r} P^{r−1}_i with α_{i,r} = (u − u_i)/(u_{i+p+1−r} − u_i), and
// Boehm's insertion of the knot ū, Q_i = (1 − α_i) P_{i−1} + α_i P_i with α_i = (ū − u_i)/(u_{i+p} − u_i). The draw
// functions put the current step on the curve plot; they read the state and c and change nothing.
import { fmt, pairSep } from '../../lib/dom.js';
import { t, tn } from '../../lib/i18n.js';
import { PALETTE } from '../../lib/plot2d.js';
import { mathText } from '../../lib/mathml.js';

/** The stepper's title per algorithm. */
export const ALGOS = { deboor: 'de Boor’s algorithm at u', insert: 'Insert the knot u (Boehm)' };   // (the stepper shows them in the page's language)
const LEVEL = [PALETTE.control, PALETTE.accent, PALETTE.second, PALETTE.highlight, PALETTE.curve, PALETTE.wine];

const num = (x, d = 3) => fmt(x, d);
const at = (flat, j) => [flat[2 * j], flat[2 * j + 1]];
const pt = (q) => `(${num(q[0])}${pairSep()}${num(q[1])})`;
/** `X_a, …, X_b` in TeX (just `X_a` or `X_a, X_b` when the range is that short). */
const range = (x, a, b) => (a === b ? `${x}_{${a}}` : b === a + 1 ? `${x}_{${a}}, ${x}_{${b}}` : `${x}_{${a}}, \\ldots, ${x}_{${b}}`);

/** The steps of the algorithm chosen in the state. */
export const buildSteps = (state, c) => (state.stepAlgo === 'insert' ? insertSteps(state, c) : deBoorSteps(state, c));

function deBoorSteps(state, { tri }) {
  if (!tri) return [];
  const P = tri.levels.length - 1, k = tri.span, K = state.knots, u = num(state.u);
  const out = [{
    label: t('the {n} control points that act at u', { n: P + 1 }),
    tex: [
      `u = ${u} \\in [u_{${k}}, u_{${k + 1}}) = [${num(K[k])}${pairSep()}${num(K[k + 1])}) \\;\\Rightarrow\\; k = ${k}`,
      `P^{0}_{i} = P_{i}, \\quad i = k - p, \\ldots, k = ${k - P}, \\ldots, ${k}`,
    ],
    note: t('Level 0 of the triangle: only these p + 1 = {n} control points pull on C(u).', { n: P + 1 }),
  }];
  for (let r = 1; r <= P; r++) {
    const L0 = tri.levels[r], A = tri.alphas[r], f = tri.firstIndex[r];
    const lines = [
      `P^{${r}}_{i} = (1 - \\alpha_{i,${r}})\\,P^{${r - 1}}_{i-1} + \\alpha_{i,${r}}\\,P^{${r - 1}}_{i}`,
      `\\alpha_{i,${r}} = \\frac{u - u_{i}}{u_{i+${P + 1 - r}} - u_{i}}, \\quad i = ${f === k ? f : k === f + 1 ? `${f}, ${k}` : `${f}, \\ldots, ${k}`}`,
    ];
    for (let j = 0; j < A.length; j++) {
      const i = f + j;
      lines.push(`\\alpha_{${i},${r}} = \\frac{${u} - ${num(K[i])}}{${num(K[i + P + 1 - r])} - ${num(K[i])}} = ${num(A[j], 4)}`);
      lines.push(`P^{${r}}_{${i}} = ${num(1 - A[j], 3)}\\,P^{${r - 1}}_{${i - 1}} + ${num(A[j], 3)}\\,P^{${r - 1}}_{${i}} = ${pt(at(L0, j))}`);
    }
    out.push({
      label: r === P ? t('level {r} of {n}: the curve point', { r, n: P }) : t('level {r} of {n}', { r, n: P }),
      tex: r === P ? [...lines, `C(${u}) = P^{${P}}_{${k}} = ${pt(at(tri.point, 0))}`] : lines,
      note: r === P ? t('The last level is the curve point C(u), the diamond.') : t('Each new point cuts a leg of level {r} in the ratio α : (1 − α).', { r: r - 1 }),
    });
  }
  return out;
}

function insertSteps(state, { ins }) {
  if (!ins) return [];
  const P = state.degree, n = state.points.length, k = ins.span, f = ins.first, K = state.knots, u = num(state.u);
  /** @type {{ label: string, tex: string[], note?: string }[]} */
  const out = [{
    label: t('the span of ū and the points it replaces'),
    tex: [
      `\\bar u = ${u} \\in [u_{${k}}, u_{${k + 1}}) = [${num(K[k])}${pairSep()}${num(K[k + 1])}) \\;\\Rightarrow\\; k = ${k}`,
      P > 1 ? `${range('P', f, k - 1)} \\;\\to\\; ${range('Q', f, k)}` : `Q_{${k}} \\;\\text{${t('between')}}\\; P_{${k - 1}} \\;\\text{${t('and')}}\\; P_{${k}}`,
    ],
    note: tn(P - 1, '{n} control point (crossed) is replaced by {m} new ones on the highlighted legs; all others stay.', '{n} control points (crossed) are replaced by {m} new ones on the highlighted legs; all others stay.', { m: P }),
  }];
  for (let j = 0; j < P; j++) {
    const i = f + j, a = ins.alphas[j];
    out.push({
      label: t('new point {name} ({i} of {n})', { name: `Q${mathText(`_{${i}}`)}`, i: j + 1, n: P }),
      tex: [
        `Q_{i} = (1 - \\alpha_{i})\\,P_{i-1} + \\alpha_{i}\\,P_{i}`,
        `\\alpha_{i} = \\frac{\\bar u - u_{i}}{u_{i+${P}} - u_{i}}`,
        `\\alpha_{${i}} = \\frac{${u} - ${num(K[i])}}{${num(K[i + P])} - ${num(K[i])}} = ${num(a, 4)}`,
        `Q_{${i}} = ${num(1 - a, 3)}\\,P_{${i - 1}} + ${num(a, 3)}\\,P_{${i}} = ${pt(at(ins.points, i))}`,
      ],
    });
  }
  out.push({
    label: t('the new control polygon: the same curve'),
    tex: [
      `\\bar P = (${range('P', 0, f - 1)}, ${range('Q', f, k)}, ${range('P', k, n - 1)})`,
      `${n + 1} \\;\\text{points}, \\; ${K.length + 1} \\;\\text{knots (}\\bar u = ${u}\\;\\text{added)}`,
      '\\sum_{i} N_{i,p}(u)\\,P_{i} = \\sum_{i} \\bar N_{i,p}(u)\\,\\bar P_{i}',
    ],
    note: t('The new polygon (green) is closer to the curve; inserting the same knot p times splits the curve there.'),
  });
  return out;
}

/** The current step on the curve plot, under the handles: de Boor's levels so far, or the legs Boehm cuts. */
export function drawStepLines(plot, state, { tri, ins }) {
  const s = state.step;
  if (s < 0) return;
  if (state.stepAlgo === 'deboor' && tri) {
    for (let r = 0; r <= Math.min(s, tri.levels.length - 1); r++) {
      const cur = r === s;
      if (tri.levels[r].length >= 4) plot.polyline(tri.levels[r], { color: LEVEL[r % LEVEL.length], width: cur ? 3.5 : 2, alpha: cur ? 1 : 0.6 });
    }
  } else if (state.stepAlgo === 'insert' && ins) {
    const P = state.degree, f = ins.first;
    plot.polyline(state.points.slice(f - 1, f + P), { color: PALETTE.accent, width: 5, alpha: 0.55 });
    if (s === P + 1) plot.polyline(ins.points, { color: PALETTE.second, width: 3 });
  }
}

/** The current step's markers and labels, over the handles (the replaced points crossed, the new Qᵢ). */
export function drawStepMarks(g, plot, state, { tri, ins }) {
  const s = state.step;
  if (s < 0) return;
  const font = '600 13px system-ui, sans-serif';
  if (state.stepAlgo === 'deboor' && tri) {
    for (let r = 0; r <= Math.min(s, tri.levels.length - 1); r++) {
      const cur = r === s, Lr = tri.levels[r], f = tri.firstIndex[r];
      for (let j = 0; j < Lr.length / 2; j++) {
        const q = at(Lr, j);
        plot.points([q], { color: LEVEL[r % LEVEL.length], radius: cur ? 6 : 4, shape: r === tri.levels.length - 1 ? 'diamond' : 'circle', stroke: '#fff' });
        if (cur && r > 0) plot.label(q[0], q[1], mathText(`P^{${r}}_{${f + j}}`), { color: '#222', offset: [8, -8], font });
      }
    }
  } else if (state.stepAlgo === 'insert' && ins) {
    const P = state.degree, f = ins.first;
    if (s <= P) {
      // the points that will be replaced: crossed
      for (let i = f; i < f + P - 1; i++) {
        const q = state.points[i];
        const [X, Y] = plot.toScreen(q[0], q[1]);
        g.beginPath(); g.moveTo(X - 12, Y - 12); g.lineTo(X + 12, Y + 12); g.moveTo(X + 12, Y - 12); g.lineTo(X - 12, Y + 12);
        g.lineWidth = 3; g.strokeStyle = PALETTE.control; g.stroke();
      }
    }
    const upto = s === P + 1 ? P : s;
    for (let j = 0; j < upto; j++) {
      const q = at(ins.points, f + j);
      plot.points([q], { color: PALETTE.second, radius: j === s - 1 ? 7 : 5, shape: 'square', stroke: '#fff' });
      plot.label(q[0], q[1], mathText(`Q_{${f + j}}`), { color: '#0b5e45', offset: [8, 16], baseline: 'top', font });
    }
  }
}
