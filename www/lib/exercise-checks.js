// Which checks each demo offers to exercises, and how each is computed from the demo's state.
//
// One central table (rather than an `exercises` export in every demo module): a check reads the demo's
// state, asks the wasm API for the construction the demo draws (the same calls the demo makes), and hands
// it to `exerciseCheck` — the measure itself is computed by the wasm core (src/exercise/), never here.
//
//   CHECKS[demoId] = [{ id, label, measure, tol, task, hint, run(wasm, state, tol) → { value, passed, score, … } }]
//
// `label` names the check for the teacher's "Make exercise" panel; `tol`, `task` and `hint` are the
// suggestions it starts from. `measure` (a text, or a function of the state) says what the number is, for the
// student's feedback: “RMS distance to the true sine: 0.206”.

import { t } from './i18n.js';

const rows = (flat) => { const o = []; for (let i = 0; i + 1 < flat.length; i += 2) o.push([flat[i], flat[i + 1]]); return o; };

// ---------- Interpolating vs approximating (B2-splines) ----------
function b2Options(s) {
  const o = { a: s.a, tension: s.p, knots: s.knots, c2: s.c2, construction: s.construction };
  if (s.useK) o.K = s.K;
  if (s.autoTension !== 'off' && s.construction !== 'section3') { o.autoTension = s.autoTension; o.autoTensionScale = s.autoScale; }
  return o;
}
/** @param {import('./host.js').SplineLab} wasm @param {any} s */
function b2AsBspline(wasm, s) {
  // the B2 curve Lᵃ is a cubic B-spline: b2Curve returns its knots and control points C_0..C_2n
  const r = s.autoEnds
    ? wasm.b2Fit({ points: s.points.slice(2, -2), ...b2Options(s), samples: 2 })
    : wasm.b2Curve({ points: s.points, ...b2Options(s), samples: 2 });
  return { degree: 3, knots: Array.from(r.knots), controlPoints: r.controlPoints };
}

// ---------- Knot modification ----------
function clampedKnots(k, count) {
  const t = [];
  for (let i = 0; i < k; i++) t.push(0);
  for (let i = 1; i <= count - k; i++) t.push(i);
  for (let i = 0; i < k; i++) t.push(count - k + 1);
  return t;
}
const knotCurve = (s) => ({ order: s.order, knots: clampedKnots(s.order, s.points.length), controlPoints: s.points });

// ---------- Curve networks ----------
const U3 = [0, 1 / 3, 2 / 3, 1];
const U6 = [0, 0.2, 0.4, 0.6, 0.8, 1];
const NETWORKS = { // the demo's presets (www/demos/curve-networks.js)
  paper: (w) => w.networkFromFunction({ u: U3, v: U3, f: (u, v) => [u, v, 0.45 * Math.sin(Math.PI * u) * Math.sin(Math.PI * v) + 0.35 * u * v * v] }),
  'three-sided': (w) => w.networkExample({ name: 'three-sided' }),
  separable: (w) => w.networkExample({ name: 'separable' }),
  dome: (w) => w.networkFromFunction({ u: U6, v: U6, f: (u, v) => [u, v, 0.6 - 0.9 * ((u - 0.5) ** 2 + (v - 0.5) ** 2) + 0.25 * u * (1 - v) * Math.cos(3 * v)] }),
  dome10: (w) => w.networkExample({ name: 'dome10' }),
};
function network(wasm, s) {
  if (s.network && Array.isArray(s.network.u)) {
    const net = JSON.parse(JSON.stringify(s.network));
    return wasm.networkCompatibility({ network: net }).compatible ? net : wasm.networkRepair({ network: net }).network;
  }
  return (NETWORKS[s.preset] || NETWORKS.paper)(wasm);
}
const networkNorm = (pair) => (/** @type {import('./host.js').SplineLab} */ wasm, /** @type {any} */ s, /** @type {number} */ tol) => wasm.exerciseCheck({ check: 'networkNorm', tol, network: network(wasm, s), pair });

/** The noisy-data check's measure per true curve (one sentence each: a language declines the curve's name). */
const RMS_TRUE = {
  sine: 'RMS distance to the true sine', arc: 'RMS distance to the true arc', lemniscate: 'RMS distance to the true lemniscate',
  spiral: 'RMS distance to the true spiral', step: 'RMS distance to the true step',
};

/** @typedef {import('./host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */
/**
 * @typedef {{ id: string, label: string, measure: string | ((s: any) => string), tol: number, task: string, hint?: string,
 *   needsTarget?: boolean, run: (wasm: SplineLab, s: any, tol: number, ex?: any) => any }} Check
 */
/** @type {Record<string, Check[]>} */
export const CHECKS = {
  'interp-approx': [
    { id: 'data-distance', label: 'The curve passes within ε of the data points W₁ … Wₙ', tol: 1e-9,
      measure: 'Largest distance from a data point to the curve',
      task: 'Make the curve pass through every data point W₁ … Wₙ.',
      hint: 'Which value of the approximation parameter a makes Lᵃ interpolate?',
      run: (wasm, s, tol) => wasm.exerciseCheck({ check: 'dataDistance', tol, curve: b2AsBspline(wasm, s), data: s.points.slice(2, -2) }) },
  ],
  'noisy-data': [
    { id: 'fit-error', label: 'RMS distance of the fit to the true curve below ε', tol: 0.05,
      measure: (s) => RMS_TRUE[s.curve] || 'RMS distance to the true curve',
      task: 'Choose a so that the fitted curve is within the bound of the true curve (RMS distance).',
      hint: 'Noise wants smoothing: move a from 0 towards the cubic B-spline (1/6) and beyond, and watch the error plot.',
      run: (wasm, s, tol) => {
        if (s.source !== 'curve') throw new Error(t('this check needs data drawn from a known curve (source: curve)'));
        const d = wasm.noisyData({ curve: s.curve, count: s.count, sigma: s.sigma, seed: s.seed });
        return wasm.exerciseCheck({ check: 'fitError', tol, points: rows(d.points), a: s.a, tension: s.p, knots: s.knots, truthCurve: s.curve });
      } },
  ],
  'bezier-remodel': [
    { id: 'c1-joint', label: 'The remodelled curve g* is C¹ at the selected joint', tol: 1e-9,
      measure: 'Relative jump of g* and of its first derivative at the joint',
      task: 'Make the remodelled curve g* C¹ at the selected joint again.',
      hint: 'Equation (9) of the paper ties some α to others; the app can enforce it for you.',
      run: (wasm, s, tol) => bezierJoint(wasm, s, tol, 1) },
    { id: 'c2-joint', label: 'The remodelled curve g* is C² at the selected joint', tol: 1e-9,
      measure: 'Relative jump of g* and of its first two derivatives at the joint',
      task: 'Make the remodelled curve g* C² at the selected joint.',
      hint: 'How much continuity the elevation keeps is the r of eq. (9): r ≤ ⌊m/2⌋.',
      run: (wasm, s, tol) => bezierJoint(wasm, s, tol, 2) },
  ],
  'bspline-basics': [
    { id: 'c2-middle', label: 'The curve is C² at its knot u = 0.5', tol: 1e-9,
      measure: 'Relative jump of the curve and of its first two derivatives at u = 0.5',
      task: 'Make the cubic curve C² at u = 0.5.',
      hint: 'A knot of multiplicity μ leaves p − μ continuous derivatives there: how many knots may sit at 0.5?',
      run: (wasm, s, tol) => wasm.exerciseCheck({ check: 'continuity', tol, order: 2, at: 0.5,
        curve: { degree: s.degree, knots: s.knots, controlPoints: s.points } }) },
  ],
  'knot-modification': [
    { id: 'envelope-point', label: 'The moved curve touches the envelope at a given point Q', tol: 1e-3, needsTarget: true,
      measure: 'Distance from the touching point e(uₚ) to Q',
      task: 'Move the knot uₚ so that the curve touches its envelope at the point Q.',
      hint: 'The curve with the knot at uₚ touches the envelope at e(uₚ): slide uₚ and watch the touching point.',
      run: (wasm, s, tol, ex) => wasm.exerciseCheck({ check: 'envelopePoint', tol, curve: knotCurve(s), p: s.p, up: s.up, target: ex?.target ?? [0, 0] }) },
  ],
  'quasi-cubic-curves': [
    { id: 'ellipse', label: 'The closed quasi-cubic curve is an exact ellipse', tol: 1e-9,
      measure: 'Largest distance from the curve to the ellipse of its control points',
      task: 'Make the curve an exact ellipse (to 10⁻⁹).',
      hint: 'Conics need a particular shape parameter α, and the diagonals of the control polygon must bisect each other.',
      run: (wasm, s, tol) => wasm.exerciseCheck({ check: 'ellipse', tol, points: s.points, alpha: s.alpha }) },
    { id: 'inner-points', label: 'The curve passes within ε of the inner control points', tol: 1e-9,
      measure: 'Largest distance from an inner control point to the curve',
      task: 'Make the curve pass through the inner control points b₁ … bₙ₊₁.',
      hint: 'One value of α turns the approximating basis into an interpolating one.',
      run: (wasm, s, tol) => wasm.exerciseCheck({ check: 'dataDistance', tol, curve: { alpha: s.alpha, controlPoints: s.points, closed: !!s.closed },
        data: s.closed ? s.points : s.points.slice(1, -1) }) },
  ],
  'curve-networks': [
    { id: 'norm-SG', label: '‖S − G‖∞ below ε (criss-cross vs Gordon)', tol: 1e-9, measure: '‖S − G‖∞', task: 'Find a network for which S and G coincide.',
      hint: 'S and G agree when the Gordon surface is already a criss-cross spline: think of networks that separate u and v.', run: networkNorm('SG') },
    { id: 'norm-GGB', label: '‖G − GB‖∞ below ε (Gordon vs spline-blended)', tol: 1e-9, measure: '‖G − GB‖∞', task: 'Find a network for which G and GB coincide.',
      hint: 'Look at the colour map “G vs GB” for each network.', run: networkNorm('GGB') },
    { id: 'norm-ST', label: '‖S − T‖∞ below ε (criss-cross vs thin-plate)', tol: 1e-4, measure: '‖S − T‖∞', task: 'Find a network for which S and T differ by less than the bound.',
      hint: 'Finer networks leave the surfaces less freedom.', run: networkNorm('ST') },
  ],
};

/** @param {import('./host.js').SplineLab} wasm @param {any} s @param {number} tol @param {number} order */
function bezierJoint(wasm, s, tol, order) {
  const r = wasm.bezierRemodel({ points: s.points, degree: s.degree, breaks: s.breaks, alphas: s.alphas, r: s.r, enforce: s.enforce, samples: 2 });
  const I = Math.min(Math.max(1, s.joint | 0), s.breaks.length - 2);
  return wasm.exerciseCheck({ check: 'continuity', tol, order, at: s.breaks[I], curve: { degree: s.degree + 1, breaks: s.breaks, controlPoints: r.controlPoints } });
}

/** The checks a demo offers ([] when none). */
export function checksFor(demoId) { return CHECKS[demoId] || []; }

/** The check `checkId` of `demoId`, or null. */
export function findCheck(demoId, checkId) { return checksFor(demoId).find((c) => c.id === checkId) || null; }

/**
 * What check `c` measures on `state`, in words (“RMS distance to the true sine”), in the page's language. The
 * table above keeps the English texts (it is read before the language is chosen); they are translated here, as the
 * labels, tasks and hints are where "Make exercise" shows them.
 */
export function measureOf(c, state) {
  const m = typeof c?.measure === 'function' ? c.measure(state) : c?.measure;
  // a norm (‖S − G‖∞) is notation: as it is in every language
  return !m ? t('Measured') : /‖/.test(m) ? m : t(m);
}

/**
 * Runs a check: `{ value, tol, passed, score, …, measure }` from the wasm core (`measure`: what the value is, in
 * words). Throws on a bad state or check.
 */
export function runCheck(wasm, demoId, exercise, state) {
  const c = findCheck(demoId, exercise.check);
  if (!c) throw new Error(t('the demo "{demo}" offers no check "{check}"', { demo: demoId, check: exercise.check }));
  const r = c.run(wasm, state, exercise.tol, exercise);
  return { ...r, measure: measureOf(c, state) };
}
