// What a link may hold in "Interpolating vs approximating": sanitize() repairs the state in place (bookkeeping
// only), and `sub` writes the subscripts of W₋₁ … Wₙ₊₂.
import { MAX_POINTS } from './presets.js';

export { subscript as sub } from '../../lib/indices.js';

/** Validates the state in place (a link may hold anything that passed the type check); `d` is defaults(). */
export function sanitize(state, d) {
  for (const k of Object.keys(d)) if (state[k] === undefined) state[k] = d[k];
  const okPts = Array.isArray(state.points) && state.points.length >= 6 && state.points.length <= MAX_POINTS &&
    state.points.every((q) => Array.isArray(q) && q.length === 2 && q.every(Number.isFinite));
  if (!okPts) state.points = d.points;
  const num = (k, lo, hi) => { if (!(Number.isFinite(state[k]) && state[k] >= lo && state[k] <= hi)) state[k] = d[k]; };
  num('a', -0.1, 0.25); num('p', 0, 0.5); num('K', 0, 100); num('autoScale', 0, 0.5);
  if (![1, 2].includes(state.c2)) state.c2 = 1;
  if (!['chord', 'uniform'].includes(state.knots)) state.knots = 'chord';
  if (!['nonuniform', 'section3'].includes(state.construction)) state.construction = 'nonuniform';
  if (!['off', 'paper', 'turning'].includes(state.autoTension)) state.autoTension = 'off';
  if (state.construction === 'section3') { state.knots = 'uniform'; state.autoTension = 'off'; }
  const f = state.family;
  if (f && !(['a', 'p'].includes(f.key) && Array.isArray(f.values) && f.values.length <= 6 && f.values.every(Number.isFinite))) state.family = null;
  for (const k of ['autoEnds', 'useK', 'showB', 'showInterp', 'showBuild', 'showComb', 'eq5Printed']) state[k] = !!state[k];
  if (!Number.isInteger(state.step) || state.step < -1 || state.step > 5) state.step = -1;
}
