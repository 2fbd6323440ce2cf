// The curve plot of "Interpolating vs approximating": the data polygon, "how it is built" (the cubic control
// polygon C₀…C₂ₙ, even vertices C₂ᵢ, joints Rᵢ), the family of a preset, the overlays a = 1/6 (B-spline) and a = 0
// (interpolating), the curvature comb, the curve Lᵃ, eq. (5) as printed, the stepper and Lᵃ(u). Every function
// reads the state and the computed c (compute.js) and changes nothing.
import { fmt, pair, pairSep } from '../../lib/dom.js';
import { t } from '../../lib/i18n.js';
import { PALETTE } from '../../lib/plot2d.js';
import { drawStepLines, drawStepMarks } from './steps.js';
import { sub } from './state-rules.js';
import { curveFactsOf, curveWords } from '../../lib/curve-words.js';

// family colours: none of them is a colour of the other curves of this plot (the current curve blue, a = 1/6
// orange, a = 0 green, the data vermillion, the build purple, the comb sky blue), so each value has its own; the
// member at the current a (or p) is the current curve and takes its blue
// (the last is Tol's teal darkened to 4.1:1 on white: #44AA99 was 2.8:1)
const FAMILY_COLORS = [PALETTE.wine, '#332288', PALETTE.yellow, PALETTE.black, '#661100', '#2E8B7D'];
const isCurrent = (state, v) => Math.abs(v - (state.family?.key === 'p' ? state.p : state.a)) < 1e-9;
const familyColor = (state, v, k) => (isCurrent(state, v) ? PALETTE.curve : FAMILY_COLORS[k % FAMILY_COLORS.length]);
/** A point of the curve in view for a label, the first from fraction `f` of its samples on (null: none in view). */
function labelPoint(pts, f, v) {
  const m = pts.length / 2;
  for (let s = 0; s < m; s++) {
    const j = (Math.floor(m * f) + s) % m, x = pts[2 * j], y = pts[2 * j + 1];
    const mx = 0.04 * (v.xmax - v.xmin), my = 0.04 * (v.ymax - v.ymin);
    if (x > v.xmin + mx && x < v.xmax - mx && y > v.ymin + my && y < v.ymax - my) return [x, y];
  }
  return null;
}

/** The curve figure in words: the parameters, the data W, and what the drawn curve does and how close it passes to
 * the data its joints stand for, W₁ … Wₙ₋₁ (curveFacts of the drawn samples; W₋₁, W₀, Wₙ, Wₙ₊₁ only shape the
 * ends: the curve runs from its joint at W₁ to the one at Wₙ₋₁). */
export const describeCurve = (state, { main }, wasm) => `${t('B2-spline with a = {a}, tension {p}, {knots}{K}; data {list}.', {
  a: fmt(state.a, 3), p: fmt(state.p, 3), knots: state.knots === 'chord' ? t('chord knots') : t('uniform knots'), K: state.useK ? `, K = ${fmt(state.K, 3)}` : '',
  list: state.points.map((q, i) => `W${sub(i - 1)} ${pair(q[0], q[1], 2)}`).join(pairSep()),
})} ${curveWords(curveFactsOf(wasm, main, state.points.slice(2, -2)), { dataName: (i) => `W${sub(i + 1)}` })}`;

/** Under the handles. */
export function drawCurve(plot, state, c) {
  const { main, family, bspl, interp, printed } = c;
  plot.polyline(state.points, { color: PALETTE.polygon, width: 1.5, dash: [8, 6] });
  if (state.showBuild && main) {
    plot.polyline(main.controlPoints, { color: PALETTE.highlight, width: 1.5, alpha: 0.9 });
    plot.points(main.controlPoints.filter((_, k) => (k >> 1) % 2 === 1), { color: PALETTE.highlight, radius: 3.5, hollow: true });
    plot.points(main.evenVertices, { color: PALETTE.highlight, radius: 6, shape: 'diamond' });
    plot.points(main.joints, { color: PALETTE.second, radius: 5, shape: 'square' });
  }
  // the family: one colour per value; the member at the current value is the blue curve itself (drawn
  // below, on top), so it is labelled in blue and not drawn twice under it
  family.forEach(({ v, r }, k) => {
    const current = isCurrent(state, v);
    if (!current) plot.polyline(r.points, { color: familyColor(state, v, k), width: 2.5 });
    const at = labelPoint(r.points, 0.15 + 0.2 * k, plot.getView());
    if (at) plot.label(at[0], at[1], `${state.family.key} = ${fmt(v, 2)}`, { color: familyColor(state, v, k), font: '600 13px system-ui, sans-serif' });
  });
  if (bspl) plot.polyline(bspl.points, { color: PALETTE.accent, width: 2.5, dash: [10, 6] });
  if (interp) plot.polyline(interp.points, { color: PALETTE.second, width: 2.5, dash: [3, 5] });
  if (main && state.showComb && main.curvature) {
    const kap = main.curvature, nr = main.normals;
    const vec = new Float64Array(nr.length);
    let kmax = 0;
    for (let i = 0; i < kap.length; i++) kmax = Math.max(kmax, Math.abs(kap[i]));
    const v = plot.getView();
    const scale = kmax > 0 ? 0.12 * (v.xmax - v.xmin) / kmax : 0;
    for (let i = 0; i < kap.length; i++) { vec[2 * i] = -kap[i] * nr[2 * i]; vec[2 * i + 1] = -kap[i] * nr[2 * i + 1]; }
    plot.comb(main.points, vec, { scale, every: 4, color: PALETTE.sky });
  }
  // while the stepper builds the curve stage by stage, the finished curve is only a faint trace until its
  // own step (6 of 6) draws it
  const building = state.step >= 0 && state.step < 5;
  if (main) plot.polyline(main.points, { color: PALETTE.curve, width: state.step === 5 ? 6 : building ? 2 : 3.5, alpha: building ? 0.22 : 1 });
  if (state.eq5Printed && printed) plot.polyline(printed.points, { color: PALETTE.control, width: 2.5, dash: [6, 4] });
  drawStepLines(plot, state, c);
}

/** Over the handles: the stepper's points and Lᵃ(u) (while playing, or once u is past the start). */
export function drawCurveOver(plot, state, c, playing) {
  const { main, atU } = c;
  drawStepMarks(plot, state, c);
  if (!atU || !(playing || (main && state.u > main.domain[0]))) return;
  plot.points([atU], { color: PALETTE.ink, radius: 6, shape: 'diamond', stroke: '#fff' });
  plot.label(atU[0], atU[1], `L(${fmt(state.u, 2)})`, { offset: [10, 20], baseline: 'top' });
}

/** The legend follows the drawing: the same colours and dash patterns as the polylines. */
export function curveLegendItems(state, { family, main, printed }) {
  return [
    { label: 'Lᵃ, the curve for the current a', color: PALETTE.curve },
    state.showB && { label: 'a = 1/6: the cubic B-spline', color: PALETTE.accent, kind: 'dashed', dash: [10, 6] },
    state.showInterp && { label: 'a = 0: the interpolating curve', color: PALETTE.second, kind: 'dashed', dash: [3, 5] },
    ...family.map(({ v }, k) => {
      const name = `${state.family.key} = ${fmt(v, 2)}`;
      return { label: isCurrent(state, v) ? t('{name} (the current curve)', { name }) : name, color: familyColor(state, v, k) };
    }),
    { label: 'data polygon W₋₁ … Wₙ₊₂', color: PALETTE.polygon, kind: 'dashed', dash: [8, 6] },
    { label: 'data W₁…Wₙ (drag)', color: PALETTE.control, kind: 'dot' },
    { label: 'auxiliary W₋₁, W₀, Wₙ₊₁, Wₙ₊₂', color: PALETTE.muted, kind: 'dot' },
    state.showBuild && { label: 'how it is built: cubic polygon C₀…C₂ₙ, even vertices ◆', color: PALETTE.highlight, alpha: 0.9 },
    state.showBuild && { label: 'joints Rᵢ ■', color: PALETTE.second, kind: 'dot' },
    state.showComb && main && { label: 'curvature comb', color: PALETTE.sky, kind: 'thin' },
    state.eq5Printed && printed && { label: 'eq. (5) as printed (misses the data)', color: PALETTE.control, kind: 'dashed', dash: [6, 4] },
  ];
}
