// The curve tab's state rules: what a link may hold (sanitizeCurve), the α range that eq. (9) allows, and the
// examples (applyCurvePreset). Plain functions of the state; the only wasm call is bsplineToBezier for the
// quartic example (no spline maths here).
import { EXAMPLE_POINTS, EXAMPLE_BREAKS, FIG1, FIG2, QUARTIC } from './data.js';

export const clampAlpha = (a) => (Number.isFinite(a) ? Math.min(0.999, Math.max(0.001, a)) : 0.5);

/** With r ≥ 2, eq. (9) fixes entries p·αₘ and 1 − p·αₘ: they stay in (0, 1) only for αₘ < 1/r. */
export const alphaMax = (state) => (state.enforce && state.r >= 2 ? 1 / state.r - 0.001 : 0.999);

/** Keeps every segment's last α (αₘ) below alphaMax. */
export function limitLast(state) {
  const m = state.degree;
  for (const row of state.alphas) row[m - 1] = Math.min(row[m - 1], alphaMax(state));
}

/** Validates the curve part of the state in place (a link may hold anything that passed the type check);
 * `fresh` is defaults(), whose example replaces data of the wrong shape. */
export function sanitizeCurve(state, fresh) {
  const m = state.degree;
  const segs = state.breaks.length - 1;
  const ok = Number.isInteger(m) && m >= 1 && m <= 8 && segs >= 1 && segs <= 12 && state.points.length === m * segs + 1 &&
    state.alphas.length === segs && state.alphas.every((r) => Array.isArray(r) && r.length === m);
  if (!ok) {
    const d = fresh;
    Object.assign(state, { preset: d.preset, degree: d.degree, points: d.points, breaks: d.breaks, alphas: d.alphas, r: d.r });
  }
  state.r = Math.max(0, Math.min(Math.floor(state.degree / 2), Math.round(state.r) || 0));
  state.joint = Math.max(1, Math.min(state.breaks.length - 2, Math.round(state.joint) || 1));
  for (const row of state.alphas) for (let k = 0; k < row.length; k++) row[k] = clampAlpha(row[k]);
  limitLast(state);
  if (!['remodel', 'casteljau'].includes(state.stepAlgo)) state.stepAlgo = 'remodel';
  if (!Number.isInteger(state.step) || state.step < -1 || state.step > 12) state.step = -1;
  const [a, b] = [state.breaks[0], state.breaks[state.breaks.length - 1]];
  if (!(Number.isFinite(state.stepU) && state.stepU >= a && state.stepU <= b)) state.stepU = (state.breaks[0] + state.breaks[1]) / 2;
}

/** The classical degree elevation's α: αₖ = (m + 1 − k)/(m + 1), k = 1..m, for each of `segs` segments (g* = g). */
export const classicalAlphas = (m, segs) => Array.from({ length: segs }, () => Array.from({ length: m }, (_, k) => (m - k) / (m + 1)));

/** Sets the curve example `p` ('fig1', 'fig2', 'classical', 'quartic'); throws what bsplineToBezier throws. */
export function applyCurvePreset(state, p, wasm) {
  state.preset = p;
  if (p === 'quartic') {
    const b = wasm.bsplineToBezier(QUARTIC);
    state.degree = b.degree;
    state.points = b.points.map((q) => [q[0], q[1]]);
    state.breaks = Array.from(b.breaks);
    state.alphas = classicalAlphas(state.degree, state.breaks.length - 1);
    state.r = 2;
    state.enforce = true;
    state.joint = 1;
  } else {
    state.degree = 2;
    state.points = EXAMPLE_POINTS.map((q) => [...q]);
    state.breaks = [...EXAMPLE_BREAKS];
    state.alphas = (p === 'fig2' ? FIG2 : p === 'fig1' ? FIG1 : FIG1.map(() => [2 / 3, 1 / 3])).map((r) => [...r]);
    state.r = 1;
    state.enforce = true;
    state.joint = Math.min(state.joint, 4);
  }
}
