// The knot line of "Knot modification": the knots of the curve (ranges for repeated ones), the moving knot u_p
// with the interval of its neighbours and the affected spans, and the stepper's α interval. The drawing reads
// the state and the computed C; snapKnot rounds a dragged value to what the labels show.
import { fmt } from '../../lib/dom.js';
import { mathText } from '../../lib/mathml.js';
import { PALETTE } from '../../lib/plot2d.js';
import { KNOT_ROW, KNOT_SNAPS, knotText, sub, knots, nb, upRange } from './knots.js';
import { stepInfo } from './de-boor.js';

export const describeKnots = (state) => `Knots ${knots(state).map((x, i) => (i === state.p ? `u${sub(i)} = ${fmt(state.up, 3)} (moving)` : fmt(x, 2))).join(', ')}.`;

/** The view that shows every knot and the whole range of u_p. */
export function knotLineView(state) {
  const [kl, kh] = upRange(state), t = knots(state);
  return { xmin: Math.min(kl, t[0]) - 0.6, xmax: Math.max(kh, t[t.length - 1]) + 0.6, ymin: -1, ymax: 1 };
}

export function drawKnotLine(g, plot, state, C) {
  const t = knots(state);
  const [a, b] = nb(state);
  if (C.cur) {
    const [ra, rb] = C.cur.affectedRange;
    plot.fill([[ra, -0.55], [rb, -0.55], [rb, 0.55], [ra, 0.55]], { color: PALETTE.highlight, alpha: 0.16 });
    plot.label((ra + rb) / 2, -0.55, 'affected spans', { align: 'center', baseline: 'top', offset: [0, 2], color: '#8a2f6a', font: '600 12px system-ui, sans-serif' });
  }
  plot.fill([[a, -0.3], [b, -0.3], [b, 0.3], [a, 0.3]], { color: PALETTE.second, alpha: 0.18 });
  const [lo, hi] = upRange(state);
  plot.segment(Math.min(lo, t[0]), KNOT_ROW, Math.max(hi, t[t.length - 1]), KNOT_ROW, { color: PALETTE.axis, width: 2 });
  t.forEach((x, i) => {
    if (i === state.p) {
      plot.points([[x, KNOT_ROW]], { color: PALETTE.muted, radius: 5, hollow: true });
      return;
    }
    plot.segment(x, -0.2, x, 0.2, { color: PALETTE.ink, width: 2 });
  });
  // labels of the distinct knots (index ranges for repeated ones)
  let i = 0;
  while (i < t.length) {
    let j = i;
    while (j + 1 < t.length && t[j + 1] === t[i]) j++;
    const idx = [];
    for (let m = i; m <= j; m++) if (m !== state.p) idx.push(m);
    if (idx.length) plot.label(t[i], 0.2, idx.length > 1 ? `u${sub(idx[0])}…${sub(idx[idx.length - 1])}` : `u${sub(idx[0])}`, { align: 'center', offset: [0, -2], font: '12px system-ui, sans-serif', color: '#333' });
    i = j + 1;
  }
}

/** Over the handle: the stepper's α interval and parameter u, and the label of u_p. */
export function drawKnotLineOver(g, plot, state, C) {
  const info = stepInfo(state, C);
  const it = info && info.items[Math.min(state.step, info.items.length - 1)];
  if (it && C.db) {
    const t = C.db.knots, a = t[it.lo], b = t[it.hi];
    plot.segment(a, 0.55, b, 0.55, { color: it.uses ? PALETTE.control : PALETTE.ink, width: 5 });
    plot.label((a + b) / 2, 0.55, mathText(`\\alpha_${it.j}^${it.r}: [u_${it.lo}, u_${it.hi}]`), { align: 'center', baseline: 'bottom', offset: [0, -4], font: '600 12px system-ui, sans-serif' });
    plot.segment(info.u, -0.6, info.u, 0.6, { color: PALETTE.accent, width: 2, dash: [4, 3] });
  }
  plot.label(state.up, -0.25, `u${sub(state.p)} = ${knotText(state.up)}`, { align: 'center', baseline: 'top', offset: [0, 8], font: '700 13px system-ui, sans-serif' });
}

/** `x` rounded to the knot snap (KNOT_SNAPS): the first step at least one pixel of the knot line wide. */
export function snapKnot(plot, x) {
  const v = plot.getView();
  const px = (v.xmax - v.xmin) / Math.max(1, plot.canvas.clientWidth);
  const step = KNOT_SNAPS.find((st) => st >= px) ?? 1;
  return +(Math.round(x / step) * step).toFixed(6);
}
