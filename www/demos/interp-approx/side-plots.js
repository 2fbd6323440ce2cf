// The two plots under the curve of "Interpolating vs approximating": the blending functions Lⱼ(u) of the current
// options (b2Basis; Σⱼ Lⱼ = 1, and at a = 0 Lⱼ(uᵢ) = δᵢⱼ) with the joints' parameters, and the signed curvature κ(u)
// of the curve (continuous: the curve is C²). Draw functions read the computed c only; the views fit its ranges.
import { fmt, pairSep } from '../../lib/dom.js';
import { t, tn } from '../../lib/i18n.js';
import { PALETTE, SERIES } from '../../lib/plot2d.js';

export const describeBasis = ({ basis }) => (basis
  ? tn(basis.count, '{n} blending function over u in {range}; they sum to 1.', '{n} blending functions over u in {range}; they sum to 1.', { range: `[${fmt(basis.domain[0], 2)}${pairSep()}${fmt(basis.domain[1], 2)}]` })
  : t('no basis'));

export function drawBasis(plot, { basis }) {
  if (!basis) return;
  const cnt = basis.count, P = basis.params, V = basis.values, np = P.length;
  const line = new Float64Array(2 * np);
  for (let j = 0; j < cnt; j++) {
    for (let r = 0; r < np; r++) { line[2 * r] = P[r]; line[2 * r + 1] = V[r * cnt + j]; }
    // neighbours overlap: every other one is dashed, so they differ by more than colour (WCAG 1.4.1)
    plot.polyline(line, { color: SERIES[j % SERIES.length], width: 2, dash: j % 2 ? [7, 4] : undefined });
  }
  for (const u of basis.jointParams) plot.vline(u, { color: '#bdbdbd', width: 1, dash: [3, 4] });
  plot.hline(0, { color: PALETTE.axis, width: 1 });
  plot.hline(1, { color: '#bdbdbd', width: 1, dash: [3, 4] });
}

export function drawKappa(plot, { main }) {
  if (!main || !main.curvature) return;
  const P = main.params, K = main.curvature, line = new Float64Array(2 * P.length);
  for (let i = 0; i < P.length; i++) { line[2 * i] = P[i]; line[2 * i + 1] = K[i]; }
  plot.polyline(line, { color: PALETTE.curve, width: 2 });
  for (const u of main.jointParams) plot.vline(u, { color: '#bdbdbd', width: 1, dash: [3, 4] });
}

/** The basis plot's view: the domain, and the values' range (at least [0, 1]) with a margin (null: no basis). */
export function basisView({ basis }) {
  if (!basis) return null;
  let lo = 0, hi = 1;
  for (const v of basis.values) { if (v < lo) lo = v; if (v > hi) hi = v; }
  return { xmin: basis.domain[0], xmax: basis.domain[1], ymin: lo - 0.08, ymax: hi + 0.08 };
}

/** The curvature plot's view: the domain, and κ's range (with 0) with a margin (null: no curvature). */
export function kappaView({ main }) {
  if (!(main && main.curvature)) return null;
  let lo = 0, hi = 0;
  for (const k of main.curvature) { lo = Math.min(lo, k); hi = Math.max(hi, k); }
  const pad = 0.1 * (hi - lo || 1);
  return { xmin: main.domain[0], xmax: main.domain[1], ymin: lo - pad, ymax: hi + pad };
}
