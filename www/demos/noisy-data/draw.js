// What "Noisy data" draws (pure: reads the state and the computed c, changes nothing): the two fits with the data,
// the true curve and the residuals rᵢ = |Lᵃ(uᵢ) − Dᵢ|, and the error-against-a plot with the cross-validated and
// the best-vs-truth a; the texts the plots' screen readers and the readouts show.
import { curveFactsOf, curveWords } from '../../lib/curve-words.js';
import { subscript } from '../../lib/indices.js';
import { fmt } from '../../lib/dom.js';
import { t } from '../../lib/i18n.js';
import { PALETTE } from '../../lib/plot2d.js';
import { A_MIN, A_MAX } from './data.js';

/** One fit: the true curve (dashed, when known), the residual segments data point → its joint, the curve, the data. */
export function drawFit(plot, data, res, color) {
  if (!data) return;
  if (data.truth) plot.polyline(data.truth, { color: PALETTE.muted, width: 2, dash: [6, 5] });
  if (res) {
    // residuals: data point → the curve's joint, one path (a NaN point breaks it: up to 2000 segments in one stroke)
    const n = data.points.length, segs = new Float64Array(6 * n);
    for (let i = 0, o = 0; i < n; i++, o += 6) {
      segs[o] = data.points[i][0]; segs[o + 1] = data.points[i][1];
      segs[o + 2] = res.joints[2 * i]; segs[o + 3] = res.joints[2 * i + 1];
      segs[o + 4] = Number.NaN; segs[o + 5] = Number.NaN;
    }
    plot.polyline(segs, { color: PALETTE.control, width: 1.5 });
    plot.polyline(res.points, { color, width: 3 });
  }
  plot.points(data.points, { color: PALETTE.ink, radius: 3.5 });
}

/** The error plot: a = 0 and a = 1/6 marked; RMS and max distance to the truth, residual RMS, √CV(a), the two best a. */
export function drawErrors(plot, sweep) {
  if (!sweep) return;
  const A = sweep.a, line = (ys) => { const f = new Float64Array(2 * A.length); for (let i = 0; i < A.length; i++) { f[2 * i] = A[i]; f[2 * i + 1] = ys[i]; } return f; };
  plot.vline(0, { color: '#bdbdbd', width: 1 });
  plot.vline(1 / 6, { color: '#bdbdbd', width: 1, dash: [4, 4] });
  if (sweep.rms) {
    plot.polyline(line(sweep.rms), { color: PALETTE.curve, width: 2.5 });
    plot.polyline(line(sweep.max), { color: PALETTE.curve, width: 1.5, dash: [6, 4] });
  }
  plot.polyline(line(sweep.residualRms), { color: PALETTE.control, width: 2 });
  if (sweep.cv) plot.polyline(line(Array.from(sweep.cv, Math.sqrt)), { color: PALETTE.highlight, width: 2.5 });
  if (sweep.bestCvA !== undefined) {
    plot.vline(sweep.bestCvA, { color: PALETTE.highlight, width: 2, dash: [2, 3] });
    const right = sweep.bestCvA > A_MIN + 0.6 * (A_MAX - A_MIN);
    plot.label(sweep.bestCvA, plot.getView().ymax, `CV: a = ${fmt(sweep.bestCvA, 2)}`, { color: PALETTE.highlight, offset: [right ? -4 : 4, 18], align: right ? 'right' : 'left', baseline: 'top', font: '600 12px system-ui, sans-serif' });
  }
  if (sweep.bestA !== undefined) {
    const right = sweep.bestA > A_MIN + 0.45 * (A_MAX - A_MIN);
    plot.vline(sweep.bestA, { color: PALETTE.curve, width: 1.5, dash: [2, 3] });
    plot.label(sweep.bestA, plot.getView().ymax, t('best vs truth: a = {a}', { a: fmt(sweep.bestA, 2) }), { color: PALETTE.curve, offset: [right ? -4 : 4, 36], align: right ? 'right' : 'left', baseline: 'top', font: '600 12px system-ui, sans-serif' });
  }
}

/** The error plot's view: the sweep's a range and the largest finite error (null: no sweep). */
export function errorsView(sweep) {
  if (!sweep) return null;
  let hi = 0;
  const take = (v) => { if (v) for (const x of v) if (Number.isFinite(x)) hi = Math.max(hi, x); };
  if (sweep.rms) { take(sweep.rms); take(sweep.max); }
  take(sweep.residualRms);
  if (sweep.cv) take(Array.from(sweep.cv, Math.sqrt));
  const pad = 0.01 * (A_MAX - A_MIN);
  return { xmin: A_MIN - pad, xmax: A_MAX + pad, ymin: -0.05 * (hi || 1), ymax: 1.25 * (hi || 1) };
}

/** The two best a in words (the error plot's description and the "Choosing a" readout). */
export function errText(sweep) {
  if (!sweep) return t('no sweep');
  let s = '';
  if (sweep.bestCvA !== undefined) s += `${t('Leave-one-out cross-validation picks a = {a}.', { a: fmt(sweep.bestCvA, 3) })} `;
  if (sweep.bestA !== undefined) s += t('The smallest RMS distance to the true curve is at a = {a}.', { a: fmt(sweep.bestA, 3) });
  return s;
}

/** A fit's numbers under its plot: the distance to the true curve (when known) and the residual RMS. */
export function numText(r) {
  if (!r) return '—';
  const s = t('residual RMS {v}', { v: fmt(r.residualRms, 4) });
  return r.rms === undefined ? s : t('distance to the true curve: RMS {rms}, max {max} · {residual}', { rms: fmt(r.rms, 4), max: fmt(r.max, 4), residual: s });
}

/** A fit's plot in words: what the drawn fit does and how close it passes to the data Dᵢ (curveFacts of its own
 * samples), then its numbers. */
export function describeFit(wasm, data, fit, numbers) {
  const words = data && fit ? curveWords(curveFactsOf(wasm, fit, data.points), { name: 'The fit', dataName: (i) => `D${subscript(i)}` }) : '';
  return words ? `${words} ${numbers}` : numbers;
}
