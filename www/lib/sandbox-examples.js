// The ready examples of the sandbox (www/sandbox.html): one per paper and one on B-spline basics. Each is the body
// of `async function (sl, plot, surface, print)`: `sl` is the SplineLab module, `plot(…)` draws on the 2D plot,
// `surface(…)` in the 3D view, `print(…)` writes to the output. The sandbox end-to-end test runs every one.

import { cite } from './papers-ref.js';

/** { id, title, paper (short reference or ''), code } */
export const EXAMPLES = [
  {
    id: 'bspline-basics',
    title: 'B-spline basics: a cubic curve and its basis functions',
    paper: '',
    code: `// A clamped cubic B-spline through six control points, and its basis functions.
const points = [[0, 0], [1, 2], [2.5, 2.5], [4, 0.5], [5.5, 2], [6.5, 0]];
const knots = [0, 0, 0, 0, 1, 2, 3, 3, 3, 3];
const curve = sl.bsplineCurve({ degree: 3, knots, points, samples: 200 });
plot(curve, { label: 'C(u)' });
plot.points(points, { label: 'control points' });
plot.polygon(points);

// the basis functions N₀ … N₅ on [0, 3]: plot.basis draws them in their own axes (u across, Nᵢ(u) up)
const basis = sl.bsplineBasis({ degree: 3, knots, samples: 151 });
plot.basis(basis, { label: 'N₀ … N₅' });
print('partition of unity at u = 1.5:', basis.values.slice(75 * basis.count, 76 * basis.count).reduce((s, x) => s + x, 0));
return curve;
`,
  },
  {
    id: 'b2-splines',
    title: 'B2-splines: from interpolating (a = 0) to the cubic B-spline (a = 1/6)',
    paper: '000',
    code: `// One parameter a moves the curve from interpolating W₁ … Wₙ (a = 0) to approximating (a = 1/6).
// b2Curve reads its points as W₋₁, W₀, W₁ … Wₙ, Wₙ₊₁, Wₙ₊₂: the first two and the last two are AUXILIARY end
// points, which steer the ends and are not interpolated; the curve runs from W₁ to Wₙ.
const W = [[-1, 0], [0, 0], [1, 2], [2.5, 2.5], [4, 0.5], [5, 2], [6, 1], [7, 1]];
for (const a of [0, 1 / 12, 1 / 6]) {
  const c = sl.b2Curve({ points: W, a, samples: 200 });
  plot(c, { label: \`a = \${a.toFixed(3)}\` });
}
plot.points(W.slice(2, -2), { label: 'data W₁ … Wₙ' });
plot.points([...W.slice(0, 2), ...W.slice(-2)], { label: 'auxiliary W₋₁, W₀, Wₙ₊₁, Wₙ₊₂', color: '#888888', radius: 3.5 });
const L0 = sl.b2Curve({ points: W, a: 0, samples: 2 });
print('joints of a = 0 (they are W₁ … Wₙ):', L0.joints);
`,
  },
  {
    id: 'bezier-remodel',
    title: 'Bézier remodelling: raise the degree with free parameters α',
    paper: '001',
    code: `// A quadratic C¹ Bézier spline (m = 2, three segments) raised to degree 3 with chosen α.
const points = [[0, 0], [1, 2], [2, 2], [3, 2], [4, 0], [5, -2], [6, 0]];
const g = sl.bezierSpline({ points, degree: 2, breaks: [0, 1, 2, 3], samples: 150 });
const gStar = sl.bezierRemodel({
  points, degree: 2, breaks: [0, 1, 2, 3],
  alphas: [[0.7, 0.3], [null, 0.4], [null, 0.2]], // null: fixed by eq. (9) to keep C¹
  samples: 150,
});
plot(g, { label: 'g (given)', dash: true });
plot(gStar, { label: 'g* (remodelled)' });
plot.points(points, { label: 'bᵢ' });
print('curvature of g* at the breakvalues:', gStar.curvature);
print('C¹ jumps at the joints:', gStar.continuity);
`,
  },
  {
    id: 'knot-modification',
    title: 'Knot modification: move one knot and watch the curve follow',
    paper: '002',
    code: `// A cubic B-spline curve (order 4); the knot u₅ moves from 1.2 to 2.8.
const curve = { order: 4, knots: [0, 0, 0, 0, 1, 2, 3, 3, 3, 3], controlPoints: [[0, 0], [1, 2], [2, 0], [3, 2], [4, 0], [5, 2]] };
for (const up of [1.2, 1.6, 2, 2.4, 2.8]) plot(sl.knotModifiedCurve({ curve, p: 5, up, samples: 120 }), { label: \`u₅ = \${up}\` });
// the envelope of the family (order k − 1) and the paths of three curve points
plot(sl.knotEnvelopeCurve({ curve, p: 5, samples: 120 }), { label: 'envelope', width: 3 });
plot(sl.knotPathsCurve({ curve, p: 5, params: [1.5, 2, 2.5], samples: 60 }), { label: 'paths', dash: true });
plot.points(curve.controlPoints, { label: 'dᵣ' });
const lim = sl.knotLimits({ curve, p: 5 });
print('u₅ → −∞ tends to d' + lim.minusIndex, '; u₅ → +∞ to d' + lim.plusIndex);
`,
  },
  {
    id: 'quasi-cubic',
    title: 'Quasi-cubic trigonometric splines: an exact circle and a torus',
    paper: '003',
    code: `// α = 1 on a closed square of control points gives an exact circle.
const circle = sl.quasiCubicCurve({ points: [[1, 1], [-1, 1], [-1, -1], [1, -1]], alpha: 1, closed: true, samples: 121 });
plot(circle, { label: 'α = 1 (a circle)' });
plot(sl.quasiCubicCurve({ points: [[1, 1], [-1, 1], [-1, -1], [1, -1]], alpha: -1, closed: true, samples: 121 }), { label: 'α = −1' });
let r = [];
for (let i = 0; i < circle.points.length; i += 2) r.push(Math.hypot(circle.points[i], circle.points[i + 1]));
print('radius from', Math.min(...r), 'to', Math.max(...r));

// the torus preset: a periodic tensor-product surface, drawn in the 3D view
const { grid, periodicU, periodicV } = sl.quasiCubicPreset({ name: 'torus' });
const torus = sl.quasiCubicSurface({ grid, periodicU, periodicV, alpha: 1, samplesU: 48, samplesV: 24, mesh: true });
surface(torus, { label: 'torus' });
`,
  },
  {
    id: 'curve-networks',
    title: 'Curve networks: the criss-cross surface S and the Gordon surface G',
    paper: '004',
    code: `// A network of quadratic B-spline curves; S (criss-cross, C¹ quadratic) and G (biquadratic Gordon) interpolate it.
const network = sl.networkExample({ name: 'uniform-dome' });
const S = sl.crissCrossSurface({ network, samplesU: 30, samplesV: 30, mesh: true });
surface(S, { label: 'S' });
surface.network(network);
const d = sl.surfaceDifferences({ network });
print('‖S − G‖∞ =', d.SG, ' ‖S − T‖∞ =', d.ST);
// a network of the class a(u) + b(v) + c·uv: there S = G
print('separable network: ‖S − G‖∞ =', sl.surfaceDifferences({ network: sl.networkExample({ name: 'separable' }) }).SG);
return { S };
`,
  },
];

/** The label of an example in the menu: its title, and the paper it follows. */
export function exampleLabel(ex) {
  return ex.paper ? `${ex.title} (${cite(ex.paper)})` : ex.title;
}
