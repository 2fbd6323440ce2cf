// The stepper of the curve tab: the remodelling of one segment (g → the points b* of eq. (6) one by one → g*)
// and de Casteljau's algorithm on that segment of g* at u (every intermediate point from bezierDeCasteljau).
// Steps are data ({ label, tex, note }, www/lib/stepper.js); the two draw functions read the state and the
// computed results `c` = { res, dc } and change nothing.
import { fmt } from '../../lib/dom.js';
import { PALETTE } from '../../lib/plot2d.js';
import { mathText } from '../../lib/mathml.js';
import { prettyConstraint } from './notation.js';

/** The stepper's titles by algorithm (state.stepAlgo). */
export const ALGOS = { remodel: 'Remodelling one segment (eq. 6)', casteljau: 'de Casteljau on g* at u' };

const num = (x, d = 3) => fmt(x, d);
const at = (flat, j) => [flat[2 * j], flat[2 * j + 1]];
const pt = (q) => `(${num(q[0])}, ${num(q[1])})`;
const LEVEL = [PALETTE.polygon, PALETTE.accent, PALETTE.second, PALETTE.highlight, PALETTE.curve, PALETTE.wine, PALETTE.sky, PALETTE.black];

/** The steps of the remodelling of segment I (the one holding stepU): eq. (6), b*₍ₘ₊₁₎ᵢ₊ₖ = (1 − αₖ⁽ᴵ⁾) bₘᵢ₊ₖ₋₁ + αₖ⁽ᴵ⁾ bₘᵢ₊ₖ. */
export function remodelSteps(state, c) {
  const { res, dc } = c;
  if (!res || !dc) return [];
  const m = state.degree, I = dc.segment, B = state.breaks, cp = res.controlPoints;
  const al = Array.from(res.alphas[I]);
  const out = [{
    label: `segment I = ${I} of g (degree ${m})`,
    tex: [
      `g(u) = \\sum_{k=0}^{${m}} B_{${m},k}(t)\\,b_{${m * I}+k}, \\quad t = \\frac{u - u_{${I}}}{u_{${I + 1}} - u_{${I}}}`,
      `u \\in [u_{${I}}, u_{${I + 1}}] = [${num(B[I])}, ${num(B[I + 1])}]: \\; b_{${m * I}}, \\ldots, b_{${m * I + m}}`,
    ],
    note: `The ${m + 1} control points of this segment (ringed). g* gets ${m + 2}: the ends stay, the ${m} inner ones slide along the legs.`,
  }];
  for (let k = 1; k <= m; k++) {
    const a = al[k - 1], j = (m + 1) * I + k, fixed = res.free && !res.free[I][k - 1];
    out.push({
      label: `the new point b*${mathText(`_{${j}}`)} (k = ${k} of ${m})`,
      tex: [
        `b^{*}_{(m+1)I+k} = (1 - \\alpha^{(I)}_{k})\\,b_{mI+k-1}`,
        `\\qquad + \\alpha^{(I)}_{k}\\,b_{mI+k}`,
        `\\alpha^{(${I})}_{${k}} = ${num(a, 4)} \\quad (\\text{classical}\\; \\frac{m+1-k}{m+1} = \\frac{${m + 1 - k}}{${m + 1}})`,
        `b^{*}_{${j}} = ${num(1 - a, 4)}\\,b_{${m * I + k - 1}} + ${num(a, 4)}\\,b_{${m * I + k}} = ${pt(at(cp, j))}`,
      ],
      note: fixed ? `This α is fixed by eq. (9) to keep the class: ${prettyConstraint(res.constraints[I][k - 1])}.` : 'This α is free: its slider moves the point along the leg.',
    });
  }
  out.push({
    label: `the remodelled segment of g* (degree ${m + 1})`,
    tex: [
      `b^{*}_{${(m + 1) * I}} = b_{${m * I}}, \\quad b^{*}_{${(m + 1) * (I + 1)}} = b_{${m * (I + 1)}}`,
      `g^{*}(u) = \\sum_{k=0}^{${m + 1}} B_{${m + 1},k}(t)\\,b^{*}_{${(m + 1) * I}+k}`,
    ],
    note: 'Same breakpoints, one degree more; with the classical α it is the same curve as g.',
  });
  return out;
}

/** The steps of de Casteljau's algorithm on the segment of g* that holds stepU (levels from bezierDeCasteljau). */
export function casteljauSteps(state, c) {
  const { dc } = c;
  if (!dc) return [];
  const M = dc.levels.length - 1, I = dc.segment, B = state.breaks, u = num(state.stepU);
  const out = [{
    label: `segment I = ${I} of g* at u = ${u}`,
    tex: [
      `t = \\frac{u - u_{${I}}}{u_{${I + 1}} - u_{${I}}} = \\frac{${u} - ${num(B[I])}}{${num(B[I + 1])} - ${num(B[I])}} = ${num(dc.t, 4)}`,
      `b^{0}_{k} = b^{*}_{${(M) * I}+k}, \\quad k = 0, \\ldots, ${M}`,
    ],
    note: `The ${M + 1} control points of the segment of g* are level 0.`,
  }];
  for (let r = 1; r <= M; r++) {
    const L0 = dc.levels[r];
    const lines = [`b^{${r}}_{k} = (1 - t)\\,b^{${r - 1}}_{k} + t\\,b^{${r - 1}}_{k+1}`, `\\qquad = ${num(1 - dc.t, 4)}\\,b^{${r - 1}}_{k} + ${num(dc.t, 4)}\\,b^{${r - 1}}_{k+1}`];
    for (let k = 0; k < L0.length / 2; k++) lines.push(`b^{${r}}_{${k}} = ${pt(at(L0, k))}`);
    if (r === M) lines.push(`g^{*}(${u}) = b^{${M}}_{0} = ${pt(at(dc.point, 0))}`);
    out.push({ label: r === M ? `level ${r} of ${M}: the curve point` : `level ${r} of ${M}`, tex: lines,
      note: r === M ? 'The last level is the point g*(u) (the diamond); the two points of the level before span the tangent there.' : 'Every leg of the level before is cut in the ratio t : (1 − t).' });
  }
  return out;
}

/** Draws under the curve's points: the legs (remodel) or the levels' polygons (de Casteljau) up to the current step. */
export function drawStepLines(plot, state, c) {
  const { res, dc } = c;
  const s = state.step;
  if (s < 0 || !res || !dc) return;
  const m = state.degree, I = dc.segment, cp = res.controlPoints;
  if (state.stepAlgo === 'remodel') {
    plot.polyline(state.points.slice(m * I, m * I + m + 1), { color: PALETTE.accent, width: 5, alpha: s === 0 ? 0.7 : 0.35 });
    if (s >= 1 && s <= m) plot.polyline([state.points[m * I + s - 1], state.points[m * I + s]], { color: PALETTE.control, width: 4 });
    if (s === m + 1) {
      const seg = [];
      for (let k = 0; k <= m + 1; k++) seg.push(at(cp, (m + 1) * I + k));
      plot.polyline(seg, { color: PALETTE.second, width: 3 });
      const P = res.params, X = res.points, part = [];
      for (let j = 0; j < P.length; j++) if (P[j] >= state.breaks[I] && P[j] <= state.breaks[I + 1]) part.push([X[2 * j], X[2 * j + 1]]);
      plot.polyline(part, { color: PALETTE.curve, width: 7, alpha: 0.45 });
    }
  } else {
    for (let r = 0; r <= Math.min(s, dc.levels.length - 1); r++) {
      if (dc.levels[r].length >= 4) plot.polyline(dc.levels[r], { color: LEVEL[r % LEVEL.length], width: r === s ? 3.5 : 2, alpha: r === s ? 1 : 0.6 });
    }
  }
}

/** Draws over everything: the new points b* (remodel) or the levels' points with their names (de Casteljau). */
export function drawStepMarks(plot, state, c) {
  const { res, dc } = c;
  const s = state.step;
  if (s < 0 || !res || !dc) return;
  const m = state.degree, I = dc.segment, cp = res.controlPoints, font = '600 13px system-ui, sans-serif';
  if (state.stepAlgo === 'remodel') {
    if (s === 0) plot.points(state.points.slice(m * I, m * I + m + 1), { color: PALETTE.accent, radius: 11, hollow: true });
    const ks = s === m + 1 ? Array.from({ length: m + 2 }, (_, k) => k) : Array.from({ length: Math.min(s, m) }, (_, j) => j + 1);
    for (const k of ks) {
      const q = at(cp, (m + 1) * I + k);
      plot.points([q], { color: PALETTE.second, radius: k === s ? 7 : 5, shape: 'square', stroke: '#fff' });
      if (k >= 1 && k <= m) plot.label(q[0], q[1], mathText(`b^{*}_{${(m + 1) * I + k}}`), { color: '#0b5e45', offset: [10, -10], font });
    }
  } else {
    for (let r = 0; r <= Math.min(s, dc.levels.length - 1); r++) {
      const Lr = dc.levels[r], last = r === dc.levels.length - 1;
      for (let k = 0; k < Lr.length / 2; k++) {
        const q = at(Lr, k);
        plot.points([q], { color: LEVEL[r % LEVEL.length], radius: r === s ? 6 : 4, shape: last ? 'diamond' : 'circle', stroke: '#fff' });
        if (r === s && r > 0) plot.label(q[0], q[1], mathText(`b^{${r}}_{${k}}`), { color: '#222', offset: [8, -8], font });
      }
    }
  }
}
