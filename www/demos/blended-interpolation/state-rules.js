// The state rules of "Blended interpolation": what a link may hold (a known data set, 4…MAX_POINTS + 2 points,
// one β* ≥ 0 per data point, k ∈ {2, 3, 4}, a selected point among b₀ … bₙ).
import { MAX_POINTS, BETA_MAX, CUSTOM } from './data.js';

/** Brings a state (from a link or an import) within the rules. */
export function sanitize(state) {
  const n = () => state.points.length - 3; // segments; data points b₀ … bₙ
  if (!['custom', 'titanium', 'rpn14'].includes(state.dataset)) state.dataset = 'custom';
  if (!Array.isArray(state.points) || state.points.length < 4 || state.points.length > MAX_POINTS + 2) state.points = CUSTOM.map((p) => p.slice());
  if (!Array.isArray(state.beta) || state.beta.length !== n() + 1) state.beta = new Array(n() + 1).fill(1);
  state.beta = state.beta.map((b) => (Number.isFinite(b) ? Math.min(BETA_MAX * 4, Math.max(0, b)) : 1));
  if (![2, 3, 4].includes(state.k)) state.k = 3;
  if (!Number.isInteger(state.selected) || state.selected < 0 || state.selected > n()) state.selected = Math.min(n(), 1);
}
