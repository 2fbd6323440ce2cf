// The curve tab's drawing: the curve plot (g*, g, the control polygons, the osculating circle at joint I, the
// breakpoints, g*(u), the stepper's marks), its legend as data, and the paper's Fig. 3 (K* at joint I against
// αₘ⁽ᴵ⁻¹⁾). Every function reads the state and the computed results `c` = { res, orig, fig3, dc, atU }
// (curve-compute.js) and changes nothing.
import { fmt } from '../../lib/dom.js';
import { PALETTE } from '../../lib/plot2d.js';
import { sub, alphaName } from './notation.js';
import { drawStepLines, drawStepMarks } from './steps.js';

const CIRCLE_ALPHA = 0.75;
// circle colours distinct from the curve (blue), g (black), the control points (vermillion) and b* (green)
const CIRCLE_COLORS = [PALETTE.highlight, PALETTE.accent, PALETTE.sky, PALETTE.wine, PALETTE.yellow, '#332288'];
const circleColor = (i) => CIRCLE_COLORS[i % CIRCLE_COLORS.length];
// one circle, at the joint chosen for Fig. 3 (all of them at once cover the curve they explain)
const circleDrawn = (state, res, i) => i === state.joint && res && res.osculatingRadii[i] > 0 && res.osculatingRadii[i] <= 200;

/** The curve plot's text for screen readers. */
export const describeCurve = (state, { res }) => (res ? `Degree ${state.degree} spline with ${state.breaks.length - 1} segments remodelled to degree ${state.degree + 1}. Curvature at the breakpoints: ${Array.from(res.curvature).map((k, i) => `u${sub(i)}: ${fmt(k, 4)}`).join(', ')}.` : '');

/** Under the handles: the osculating circle, the polygons of g and g*, g (dotted), g* (solid), the stepper's lines. */
export function drawCurve(plot, state, c) {
  const { res, orig } = c;
  if (state.showCircles && res) {
    const ctr = res.osculatingCentres, rad = res.osculatingRadii;
    for (let i = 0; i < rad.length; i++) {
      if (!circleDrawn(state, res, i)) continue;
      const n = 120, ring = new Float64Array(2 * (n + 1));
      for (let j = 0; j <= n; j++) { const t = 2 * Math.PI * j / n; ring[2 * j] = ctr[2 * i] + rad[i] * Math.cos(t); ring[2 * j + 1] = ctr[2 * i + 1] + rad[i] * Math.sin(t); }
      plot.polyline(ring, { color: circleColor(i), width: 1.5, alpha: CIRCLE_ALPHA });
    }
  }
  if (state.showPolygon) {
    plot.polyline(state.points, { color: PALETTE.polygon, width: 1.5, dash: [8, 6] });
    if (res) plot.polyline(res.controlPoints, { color: PALETTE.second, width: 1.25, alpha: 0.8 });
  }
  if (state.showOriginal && orig) plot.polyline(orig.points, { color: PALETTE.ink, width: 2.5, dash: [2, 6] });
  if (res) plot.polyline(res.points, { color: PALETTE.curve, width: 3.5 });
  drawStepLines(plot, state, c);
}

/** Over the handles: the stepper's points, b*ᵢ, g*(u) while playing or after u₀, the breakpoints b_{mI} = b*_{(m+1)I}. */
export function drawCurveOver(plot, state, c, playing) {
  const { res, atU } = c;
  if (!res) return;
  drawStepMarks(plot, state, c);
  if (state.showPolygon) plot.points(res.controlPoints, { color: PALETTE.second, radius: 3.5, shape: 'square' });
  if (atU && (playing || state.u > state.breaks[0])) {
    plot.points([atU], { color: PALETTE.ink, radius: 6, shape: 'diamond', stroke: '#fff' });
    plot.label(atU[0], atU[1], `g*(${fmt(state.u, 2)})`, { offset: [10, -12] });
  }
  const m1 = state.degree + 1, cp = res.controlPoints;
  for (let i = 0; i < res.curvature.length; i++) {
    const x = cp[2 * m1 * i], y = cp[2 * m1 * i + 1];
    plot.points([[x, y]], { color: PALETTE.ink, radius: 5, shape: 'diamond', stroke: '#fff' });
    plot.label(x, y, `u${sub(i)}`, { offset: [8, 16], baseline: 'top', font: '600 14px system-ui, sans-serif' });
  }
}

/** The legend follows the drawing (same colours and dashes as the polylines; one entry per circle drawn). */
export function curveLegendItems(state, { res }) {
  const circles = [];
  if (state.showCircles && res) {
    for (let i = 0; i < res.osculatingRadii.length; i++) {
      if (circleDrawn(state, res, i)) circles.push({ label: `osculating circle at u${sub(i)}`, color: circleColor(i), alpha: CIRCLE_ALPHA });
    }
  }
  return [
    { label: 'remodelled g* (degree m + 1)', color: PALETTE.curve },
    state.showOriginal && { label: 'given g (witness)', color: PALETTE.ink, kind: 'dotted', dash: [2, 6] },
    { label: 'control points bᵢ of g (drag)', color: PALETTE.control, kind: 'dot' },
    state.showPolygon && { label: 'control polygon of g', color: PALETTE.polygon, kind: 'dashed', dash: [8, 6] },
    state.showPolygon && { label: 'control polygon b*ᵢ of g*', color: PALETTE.second, alpha: 0.8 },
    ...circles,
  ];
}

// ---------- Fig. 3 ----------
export const fig3Title = (state, { fig3 }) => (fig3 ? `Fig. 3 (live): K*(u${sub(fig3.joint)}) against ${alphaName(state.degree, fig3.joint - 1)}, the other α as set` : 'Fig. 3: needs an interior joint');

export const describeFig3 = ({ fig3 }) => (fig3 ? `K* at u${sub(fig3.joint)} falls from ${fmt(fig3.ks[0], 3)} to ${fmt(fig3.ks[fig3.ks.length - 1], 3)} as αₘ grows; K = ${fmt(fig3.k0, 3)}.` : 'No interior joint.');

/** Fig. 3's view: α from 0 to the sweep's end, K from 0 to above the largest value drawn (null: no joint). */
export function fig3View(state, { fig3 }) {
  if (!fig3) return null;
  const ymax = Math.max(fig3.k0, ...fig3.ks.filter(Number.isFinite), ...(state.r < 2 ? fig3.printed.filter(Number.isFinite) : [])) * 1.15 || 1;
  return { xmin: 0, xmax: fig3.hi * 1.04, ymin: -0.06 * ymax, ymax };
}

/** K = K(u_I) of g (dotted), α = 1/(m + 1) (remark c), eq. (15) as printed (only for r < 2, where it is wrong), K*. */
export function drawFig3(plot, state, { fig3 }) {
  if (!fig3) return;
  const m = state.degree, line = new Float64Array(2 * fig3.xs.length), pr = new Float64Array(2 * fig3.xs.length);
  for (let j = 0; j < fig3.xs.length; j++) { line[2 * j] = fig3.xs[j]; line[2 * j + 1] = fig3.ks[j]; pr[2 * j] = fig3.xs[j]; pr[2 * j + 1] = fig3.printed[j]; }
  plot.hline(fig3.k0, { color: PALETTE.ink, dash: [2, 5], width: 2 });
  plot.label(fig3.hi, fig3.k0, `K(u${sub(fig3.joint)}) = ${fmt(fig3.k0, 3)}`, { align: 'right', offset: [-4, -4] });
  plot.vline(1 / (m + 1), { color: PALETTE.muted, dash: [5, 5], width: 1.5 });
  plot.label(1 / (m + 1), 0, `1/(m+1)`, { offset: [4, -6], color: '#555', font: '12px system-ui, sans-serif' });
  if (state.r < 2) {
    plot.polyline(pr, { color: PALETTE.accent, width: 2.5, dash: [8, 5] });
    const j = Math.round(fig3.xs.length * 0.15);
    plot.label(pr[2 * j], pr[2 * j + 1], '(15) as printed', { color: '#9a5b00', offset: [6, -6], font: '600 12px system-ui, sans-serif' });
  }
  plot.polyline(line, { color: PALETTE.curve, width: 3 });
}

/** The current αₘ⁽ᴵ⁻¹⁾ and K*(u_I) as a dot on the Fig. 3 curve. */
export function drawFig3Over(plot, state, { fig3, res }) {
  if (!fig3 || !res) return;
  const a = state.alphas[fig3.joint - 1][state.degree - 1];
  plot.points([[a, res.curvature[fig3.joint]]], { color: PALETTE.control, radius: 6, stroke: '#fff' });
}
