// The texts of the readouts of "Interpolating vs approximating", from the computed c (compute.js): eq. (5) as
// printed (how far its curve misses the data where the spans around a joint differ), Lᵃ(u), the tensions used,
// the printed claim "a = 1/6, p = 0 gives the B-spline" and the domain. null: the readout keeps its text.
import { fmt, pair, pairSep } from '../../lib/dom.js';
import { t } from '../../lib/i18n.js';
import { sub } from './state-rules.js';

/** eq. (5) as printed: the worst joint residual and its weights' sum, against the corrected curve's. */
function eq5Text({ printed, build }) {
  if (!(printed && build)) return '—';
  const r = Array.from(printed.jointResiduals), w = printed.eq5Weights;
  let worst = 0, at = 0, sum = 1;
  r.forEach((x, k) => { if (x > worst) { worst = x; at = k; } });
  if (w.length >= 3 * (at + 1)) sum = w[3 * at] + w[3 * at + 1] + w[3 * at + 2];
  return worst < 1e-12 ? t('weights sum to 1 here (equal spans): same curve')
    : t('misses {name} by {d} (its weights sum to {sum}); corrected: {corrected}', {
      name: `W${sub(at + 1)}`, d: fmt(worst, 4), sum: fmt(sum, 4), corrected: fmt(Math.max(...Array.from(build.jointResiduals)), 4),
    });
}

/** { eq5, u, tension, claim, domain }: the readouts' texts (the last three null without a curve). */
export function readoutTexts(state, c) {
  const { atU, main, claim } = c;
  return {
    eq5: eq5Text(c),
    u: atU ? `u = ${fmt(state.u, 3)}: L(u) = ${pair(atU[0], atU[1], 3)}` : '—',
    tension: main ? Array.from(main.tension, (x) => fmt(x, 3)).join(pairSep()) : null,
    claim: main ? (claim === null ? '—' : claim < 1e-12 ? t('off by 0: holds') : t('off by {d}: fails', { d: fmt(claim, 4) })) : null,
    domain: main ? `[${fmt(main.domain[0], 3)}${pairSep()}${fmt(main.domain[1], 3)}], n = ${main.joints.length / 2}` : null,
  };
}
