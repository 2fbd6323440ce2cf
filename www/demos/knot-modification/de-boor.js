// The stepper of the curve tab: the de Boor recursion at the first tracked point with the moved knot u_p,
// d_j^r = (1 − α_j^r) d_{j−1}^{r−1} + α_j^r d_j^{r−1}, α_j^r = (u − u_j)/(u_{j+k−r} − u_j), and which of its points
// depend on u_p (their α uses the moved knot, or a point they blend does). The triangle comes from the wasm core
// (knotDeBoorCurve, in C.db); the functions here read the state and C and change nothing.
import { fmt } from '../../lib/dom.js';
import { mathText } from '../../lib/mathml.js';
import { PALETTE } from '../../lib/plot2d.js';
import { sub } from './knots.js';

/** The triangle while the stepper is on (curve tab), else null. */
export const stepInfo = (state, C) => (state.step >= 0 && state.tab === 'curve' ? deBoorInfo(state, C) : null);

/**
 * The de Boor triangle at u = the first tracked point: which intermediate points d_j^r depend on u_p (their α
 * uses the moved knot, or one of the two points they blend depends on it), from the wasm core's triangle.
 */
export function deBoorInfo(state, C) {
  const db = C.db;
  if (!db) return null;
  const k = state.order, n = db.levels.length;
  const at = (arr, i) => [arr[2 * i], arr[2 * i + 1]];
  const pos = new Map();   // `${r},${j}` → { pt, dep }
  for (let a = 0; a < k; a++) pos.set(`0,${db.startIndices[a]}`, { pt: at(db.start, a), dep: false });
  const items = [];
  for (let s = 0; s < n; s++) {
    const r = db.levels[s], j = db.indices[s];
    const left = pos.get(`${r - 1},${j - 1}`), right = pos.get(`${r - 1},${j}`);
    const dep = db.usesUp[s] === 1 || left.dep || right.dep;
    const it = { r, j, lo: db.knotLo[s], hi: db.knotHi[s], alpha: db.alphas[s], uses: db.usesUp[s] === 1, dep, pt: at(db.points, s), left, right };
    pos.set(`${r},${j}`, { pt: it.pt, dep });
    items.push(it);
  }
  return { items, u: db.u, span: db.span, start: Array.from(db.startIndices, (j, a) => ({ j, pt: at(db.start, a) })) };
}
const knotTex = (i) => `u_{${i}}`;
/** The stepper's steps: one per point d_j^r of the triangle, its formula with the current numbers. */
export function deBoorSteps(state, C) {
  const info = deBoorInfo(state, C);
  if (!info) return [];
  const t = C.db.knots, p = state.p, u = info.u;
  const val = (i) => (i === p ? `\\mathbf{${fmt(t[i], 3)}}` : fmt(t[i], 3));
  return info.items.map((it) => {
    const { r, j, lo, hi } = it;
    const up = lo === p || hi === p;
    return {
      label: `level ${r}, the point ${mathText(`d_${j}^${r}`)}${it.dep ? ' moves with u' + sub(p) : ' does not depend on u' + sub(p)}`,
      tex: [
        `d_{${j}}^{${r}} = (1-\\alpha_{${j}}^{${r}})\\, d_{${j - 1}}^{${r - 1}} + \\alpha_{${j}}^{${r}}\\, d_{${j}}^{${r - 1}}`,
        `\\alpha_{${j}}^{${r}} = \\frac{u - ${knotTex(lo)}}{${knotTex(hi)} - ${knotTex(lo)}} = \\frac{${fmt(u, 3)} - ${val(lo)}}{${val(hi)} - ${val(lo)}} = ${fmt(it.alpha, 4)}`,
        `d_{${j}}^{${r}} = (${fmt(it.pt[0], 3)}, ${fmt(it.pt[1], 3)})`,
      ],
      note: up
        ? `α uses the moved knot u${sub(p)} = ${fmt(state.up, 3)}: this point changes when the knot moves.`
        : it.dep ? `α does not use u${sub(p)}, but a point it blends does: this point changes too.`
        : `Neither α nor the points it blends use u${sub(p)}: this point stays put when the knot moves.`,
    };
  });
}
/** Draws the triangle up to the current step: the span's control points ringed, each point with its two parents. */
export function drawDeBoor(g, plot, state, C) {
  const st = state.step, info = stepInfo(state, C);
  if (!info) return;
  const colorOf = (dep) => (dep ? PALETTE.control : PALETTE.muted);
  // the control points the span uses, then every point computed so far with its two parents
  for (const s of info.start) {
    const [X, Y] = plot.toScreen(s.pt[0], s.pt[1]);
    g.beginPath(); g.arc(X, Y, 12, 0, 2 * Math.PI); g.lineWidth = 2; g.strokeStyle = PALETTE.ink; g.stroke();
  }
  info.items.slice(0, st + 1).forEach((it, s) => {
    const now = s === st;
    const w = now ? 3.5 : 1.5;
    plot.segment(it.left.pt[0], it.left.pt[1], it.right.pt[0], it.right.pt[1], { color: colorOf(it.dep), width: w, alpha: now ? 1 : 0.6 });
    plot.points([it.pt], { color: colorOf(it.dep), radius: now ? 8 : 5, stroke: '#fff', shape: it.dep ? 'diamond' : 'circle' });
    if (now) plot.label(it.pt[0], it.pt[1], mathText(`d_${it.j}^${it.r}`), { offset: [10, -10], font: '700 14px system-ui, sans-serif', color: it.dep ? '#8a2f6a' : '#333' });
  });
}
