// The explanation of "Noisy data" (static text): what it shows, the key formulas — the §5 blend, the residuals
// and the leave-one-out cross-validation (not in the paper) —, what to try, the paper reference.
import { math } from '../../lib/mathml.js';
import { t, withNodes } from '../../lib/i18n.js';

/** The content for `explanation(L.explain, …)` (www/lib/dom.js); `paper` is meta.paper. */
export function explanationContent(paper) {
  return {
    what: [
      'The paper\'s Figs. 1–3: an interpolating curve passes through every data point, so it reproduces the noise; an approximating curve (a > 0) smooths it. Left: a = 0; right: the a of the slider. Grey dashes: the true curve (when known); red segments: the residuals from each data point to the curve point that belongs to it.',
      'The bottom plot sweeps a from −0.1 to 0.5 (beyond a = 1/6 the blend extrapolates past the cubic B-spline and smooths more): the distance to the true curve (only for generated data), the residuals at the data (zero at a = 0, growing with a), and the leave-one-out cross-validation error, which needs no true curve and is minimal where smoothing predicts unseen points best. Cross-validation is not in the paper.',
      withNodes(t('The data {d} get their auxiliary end points by point reflection ({w}, and likewise at the end), so the curve covers all the data. Noise is reproducible: the same draw number gives the same points (SplitMix64 + Box–Muller).'), {
        d: math('D_1, \\ldots, D_N'), w: math('W_0 = 2D_1 - D_2, \\; W_{-1} = 2D_1 - D_3'),
      }),
    ],
    math: [
      'L^a = 6a\\,L^B + (1 - 6a)\\,L',
      'r_i = |L^a(u_i) - D_i|, \\quad \\mathrm{RMS} = \\sqrt{\\frac{1}{N}\\sum_i r_i^2}',
      `\\mathrm{CV}(a) = \\frac{1}{N-2}\\sum_{i=2}^{N-1} |L^a_{-i}(\\tilde{u}_i) - D_i|^2 \\quad (L^a_{-i}: \\;\\text{${t('fit without')}}\\; D_i)`,
    ],
    mathLabel: 'The §5 blend, the residuals with their RMS, and the leave-one-out cross-validation error',
    tryThis: [
      'Raise σ: the interpolating curve starts to wiggle; press "Use the cross-validated a".',
      'Set σ = 0: the best a moves to (about) 0 — with clean data, interpolation wins.',
      'Load the Titanium heat data: its sharp peak is exactly where smoothing costs accuracy.',
      'Paste your own points as "x, y" lines.',
    ],
    paper,
  };
}
