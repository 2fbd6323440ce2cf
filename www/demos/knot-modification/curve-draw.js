// The curve plot of "Knot modification": the control polygon, the family, the original and the modified curve
// with its affected part, the envelope e(w) of eq. (6) and its contact point e(u_p) = s(u_p; u_p), the paths of
// the tracked points (Theorem 1), the limit control points d_p, d_{p−k} of Theorem 3, the de Boor stepper and an
// exercise's target Q. Every function reads the state and the computed C (curve-compute.js), changes nothing.
import { h, fmt } from '../../lib/dom.js';
import { math, mathText } from '../../lib/mathml.js';
import { PALETTE } from '../../lib/plot2d.js';
import { sub } from './knots.js';
import { drawDeBoor } from './de-boor.js';

/** The colour of tracked point j and its path (curve and surface tab). */
export const pathColor = (j) => [PALETTE.accent, PALETTE.control, PALETTE.wine, PALETTE.black, PALETTE.sky, PALETTE.second, PALETTE.curve][j % 7];

/** Splits a flat path where consecutive points jump by more than the view (poles of extended paths). */
function breakJumps(path, plot) {
  const v = plot.getView();
  const lim = 4 * Math.max(v.xmax - v.xmin, v.ymax - v.ymin);
  const out = [];
  for (let i = 0; i + 1 < path.length; i += 2) {
    const x = path[i], y = path[i + 1];
    if (i > 0 && Math.hypot(x - path[i - 2], y - path[i - 1]) > lim) out.push(NaN, NaN);
    out.push(x, y);
  }
  return out;
}

export function describeCurve(state, C) {
  const k = state.order;
  const pts = C.trackedPts ? C.trackedU.map((u, j) => `u = ${fmt(u, 2)} at (${fmt(C.trackedPts[2 * j], 2)}, ${fmt(C.trackedPts[2 * j + 1], 2)})`).join('; ') : '';
  return `B-spline of order ${k} with knot u${sub(state.p)} moved to ${fmt(state.up, 3)}. Tracked points: ${pts}. Limits: u${sub(state.p)} → −∞ gives d${sub(state.p)}, u${sub(state.p)} → +∞ gives d${sub(state.p - k)}.`;
}

/** Under the handles. */
export function drawCurve(g, plot, state, C) {
  plot.polyline(state.points, { color: PALETTE.polygon, width: 1.5, dash: [8, 6] });
  if (state.showFamily) for (const f of C.family) plot.polyline(f, { color: PALETTE.sky, width: 1.25, alpha: 0.7 });
  if (C.orig) plot.polyline(C.orig.points, { color: PALETTE.muted, width: 2, dash: [3, 5] });
  if (C.affected) plot.polyline(C.affected.points, { color: PALETTE.highlight, width: 11, alpha: 0.28 });
  if (C.cur) plot.polyline(C.cur.points, { color: PALETTE.curve, width: 3.5 });
  if (state.showEnvelope && C.env) plot.polyline(C.env.points, { color: PALETTE.second, width: 4, dash: [12, 5] });
  C.paths.forEach((segs, j) => {
    for (const path of segs) plot.polyline(breakJumps(path, plot), { color: pathColor(j), width: 2.25 });
  });
  if (state.showLimits && C.limits) {
    for (const [pt, , txt] of [[C.limits.minus, C.limits.minusIndex, '−∞'], [C.limits.plus, C.limits.plusIndex, '+∞']]) {
      const [X, Y] = plot.toScreen(pt[0], pt[1]);
      g.beginPath(); g.arc(X, Y, 16, 0, 2 * Math.PI); g.lineWidth = 3; g.strokeStyle = PALETTE.ink; g.setLineDash([4, 3]); g.stroke(); g.setLineDash([]);
      plot.label(pt[0], pt[1], `u${sub(state.p)} → ${txt}`, { offset: [0, -20], align: 'center', baseline: 'bottom', font: '700 13px system-ui, sans-serif' });
    }
  }
}

/** Over the handles: the stepper, the tracked points (diamonds), the contact point, the target Q. */
export function drawCurveOver(g, plot, state, C) {
  drawDeBoor(g, plot, state, C);
  if (C.trackedPts) {
    for (let j = 0; j < C.trackedU.length; j++) {
      plot.points([[C.trackedPts[2 * j], C.trackedPts[2 * j + 1]]], { color: pathColor(j), radius: 6, stroke: '#fff', shape: 'diamond' });
      // each path is named by its u at its diamond, so the paths differ by more than colour (WCAG 1.4.1)
      plot.label(C.trackedPts[2 * j], C.trackedPts[2 * j + 1], `u = ${fmt(C.trackedU[j], 2)}`, { color: pathColor(j), offset: [9, -7], font: '600 12px system-ui, sans-serif' });
    }
  }
  if (state.showEnvelope && C.touch) {
    plot.points([[C.touch[0], C.touch[1]]], { color: PALETTE.second, radius: 7, stroke: '#fff' });
    plot.label(C.touch[0], C.touch[1], mathText('e(u_p) = s(u_p; u_p)'), { color: '#00654a', offset: [10, 22], baseline: 'top', font: '600 13px system-ui, sans-serif' });
  }
  drawTarget(g, plot, state);
}

/** An exercise's point Q (state.exercise.target, www/lib/exercise.js): a ringed cross labelled “Q”. */
function drawTarget(g, plot, state) {
  const q = state.exercise?.target;
  if (!q || state.tab !== 'curve') return;
  const [X, Y] = plot.toScreen(q[0], q[1]);
  g.save();
  g.lineWidth = 2.5; g.strokeStyle = PALETTE.ink; g.fillStyle = 'rgba(255,255,255,0.6)';
  g.beginPath(); g.arc(X, Y, 11, 0, 2 * Math.PI); g.fill(); g.stroke();
  g.beginPath(); g.moveTo(X - 16, Y); g.lineTo(X + 16, Y); g.moveTo(X, Y - 16); g.lineTo(X, Y + 16); g.stroke();
  g.restore();
  plot.label(q[0], q[1], `Q (${q.map((x) => +x.toFixed(3)).join(', ')})`, { offset: [14, -14], baseline: 'bottom', font: '700 14px system-ui, sans-serif', color: PALETTE.ink });
}

/** The curve plot's legend (fixed: every item is drawn in every state). */
export function curveLegend() {
  const item = (swatch, ...text) => h('li', null, swatch, ...text);
  const swatch = (style, cls = 'swatch') => h('span', { class: cls, style });
  return h('ul', { class: 'legend', 'aria-label': 'Legend' },
    item(swatch({ background: PALETTE.curve }), 'curve with the moved knot'),
    item(h('span', { class: 'swatch dashed' }), 'original curve (dotted) and control polygon (dashed)'),
    item(swatch({ background: PALETTE.highlight, opacity: '0.5' }), 'segments the knot affects'),
    item(swatch({ background: PALETTE.accent }), 'paths of the tracked points (diamonds)'),
    item(swatch({ background: PALETTE.second }), 'envelope ', math('e(w)'), ' of the family'),
    item(swatch({ background: PALETTE.sky }), 'family members for ', math('u_p'), ' between its neighbours'));
}
