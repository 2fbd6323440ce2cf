// The exports behind the algorithm steppers, checked against independent JavaScript implementations written
// here from the textbook formulas (not against the module itself): bsplineDeBoor (de Boor's triangle),
// bsplineInsertKnot (Boehm), bezierDeCasteljau, and b2Curve's construction weights and eq. (5) as printed.
//   scripts/build-wasm.sh && node --test tests/node/steppers.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';

const require = createRequire(import.meta.url);
const sl = require(join(dirname(fileURLToPath(import.meta.url)), '..', '..', 'pkg-node/splinelab.js'));

const lerp = (a, b, t) => a.map((x, i) => (1 - t) * x + t * b[i]);
const near = (a, b, tol, what) => {
  assert.equal(a.length, b.length, `${what}: length`);
  for (let i = 0; i < a.length; i++) assert.ok(Math.abs(a[i] - b[i]) <= tol, `${what}[${i}]: ${a[i]} vs ${b[i]}`);
};
const span = (t, p, n, u) => { let k = p; for (let i = p; i < n; i++) if (t[i] <= u && u < t[i + 1]) k = i; if (u >= t[n]) { for (let i = n - 1; i >= p; i--) if (t[i] < t[i + 1]) { k = i; break; } } return k; };

/** De Boor's triangle, straight from the recurrence (Piegl–Tiller eq. 5.11). */
function deBoorJS(p, t, P, u) {
  const k = span(t, p, P.length, u);
  const levels = [P.slice(k - p, k + 1)], alphas = [[]];
  for (let r = 1; r <= p; r++) {
    const prev = levels[r - 1], L = [], A = [];
    for (let i = k - p + r; i <= k; i++) {
      const d = t[i + p + 1 - r] - t[i], a = d ? (u - t[i]) / d : 0;
      const j = i - (k - p + r);
      L.push(lerp(prev[j], prev[j + 1], a)); A.push(a);
    }
    levels.push(L); alphas.push(A);
  }
  return { k, levels, alphas };
}

const P7 = [[0, 0], [1, 2.2], [2.4, 2.6], [3.4, 0.6], [4.6, 0.2], [5.4, 2.4], [6.6, 1.8]];
const CASES = [
  { degree: 3, knots: [0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1], points: P7 },
  { degree: 2, knots: [0, 0, 0, 0.1, 0.15, 0.6, 0.9, 1, 1, 1], points: P7 },
  { degree: 4, knots: [0, 0, 0, 0, 0, 0.3, 0.7, 1, 1, 1, 1, 1], points: P7.map(([x, y], i) => [x, y, i % 3]) },
];

test('bsplineDeBoor: every level and α equal the textbook recurrence, the last level the curve', () => {
  for (const c of CASES) {
    const dim = c.points[0].length;
    for (const u of [0, 0.05, 0.25, 0.4, 0.62, 0.75, 0.999, 1]) {
      const r = sl.bsplineDeBoor({ ...c, u });
      const js = deBoorJS(c.degree, c.knots, c.points, u);
      assert.equal(r.span, js.k, `span at ${u}`);
      assert.equal(r.dim, dim);
      assert.equal(r.levels.length, c.degree + 1);
      js.levels.forEach((L, lv) => {
        near(Array.from(r.levels[lv]), L.flat(), 1e-13, `level ${lv} at ${u}`);
        near(Array.from(r.alphas[lv]), js.alphas[lv], 1e-15, `alphas ${lv} at ${u}`);
        assert.equal(r.firstIndex[lv], js.k - c.degree + lv);
      });
      const on = sl.bsplineCurve({ degree: c.degree, knots: c.knots, points: c.points, at: [u] }).points;
      near(Array.from(r.point), Array.from(on), 1e-12, `C(${u})`);
    }
  }
});

test('bsplineInsertKnot: Boehm’s points, the kept points, and the same curve', () => {
  for (const c of CASES) {
    const p = c.degree, n = c.points.length;
    for (const u of [0.05, 0.3, 0.5, 0.75, 0.95]) {
      const r = sl.bsplineInsertKnot({ ...c, u });
      const k = span(c.knots, p, n, u);
      assert.equal(r.span, k); assert.equal(r.first, k - p + 1);
      const Q = [];
      for (let i = 0; i <= n; i++) {
        if (i <= k - p) Q.push(c.points[i]);
        else if (i > k) Q.push(c.points[i - 1]);
        else { const a = (u - c.knots[i]) / (c.knots[i + p] - c.knots[i]); Q.push(lerp(c.points[i - 1], c.points[i], a)); assert.ok(Math.abs(r.alphas[i - r.first] - a) < 1e-15); }
      }
      near(Array.from(r.points), Q.flat(), 1e-13, `Q at ${u}`);
      near(Array.from(r.knots), [...c.knots.slice(0, k + 1), u, ...c.knots.slice(k + 1)], 0, 'knots');
      const at = Array.from({ length: 101 }, (_, j) => j / 100);
      const before = sl.bsplineCurve({ degree: p, knots: c.knots, points: c.points, at }).points;
      const dim = c.points[0].length;
      const newPts = Array.from({ length: n + 1 }, (_, i) => Array.from(r.points.slice(dim * i, dim * i + dim)));
      const after = sl.bsplineCurve({ degree: p, knots: Array.from(r.knots), points: newPts, at }).points;
      near(Array.from(after), Array.from(before), 1e-12, `same curve after inserting ${u}`);
    }
  }
});

test('bezierDeCasteljau: the levels of the textbook algorithm on the segment of u, and g(u)', () => {
  const b = [[10, 16], [7, 21], [3, 9], [0, 0], [-4, 0], [-8, 0], [-6, 3], [-4, 6], [2, 2], [8, -2], [10, 3]];
  const breaks = [0, 1, 7 / 4, 5 / 2, 13 / 4, 4];
  for (const u of [0, 0.3, 1, 1.375, 2.2, 3.9, 4]) {
    const r = sl.bezierDeCasteljau({ points: b, degree: 2, breaks, u });
    let I = 0;
    for (let i = 0; i < 5; i++) if (breaks[i] <= u) I = i;
    const t = (u - breaks[I]) / (breaks[I + 1] - breaks[I]);
    assert.equal(r.segment, I); assert.ok(Math.abs(r.t - t) < 1e-15);
    let L = b.slice(2 * I, 2 * I + 3);
    near(Array.from(r.levels[0]), L.flat(), 0, 'level 0');
    for (let lv = 1; lv <= 2; lv++) {
      L = L.slice(1).map((q, j) => lerp(L[j], q, t));
      near(Array.from(r.levels[lv]), L.flat(), 1e-13, `level ${lv} at ${u}`);
    }
    const on = sl.bezierSpline({ points: b, degree: 2, breaks, at: [u] }).points;
    near(Array.from(r.point), Array.from(on), 1e-12, `g(${u})`);
  }
});

test('b2Curve: the construction weights rebuild its vertices; eq. (5) as printed misses the data', () => {
  const W = [[-1, -0.5], [0, 0], [0.3, 1.1], [1.6, 1.9], [2, 1.7], [4.5, 2.2], [5, 0.4], [5.6, -0.3], [7.9, 0.1], [8.3, 1.2]];
  for (const a of [0, 0.1]) {
    const r = sl.b2Curve({ points: W, a, samples: 2 });
    const n = r.joints.length / 2;
    for (let i = 1; i <= n; i++) {
      const w = r.jointWeights.slice(3 * (i - 1), 3 * i);
      const R = [0, 1].map((d) => w[0] * W[i][d] + w[1] * W[i + 1][d] + w[2] * W[i + 2][d]);
      near(R, [r.joints[2 * i - 2], r.joints[2 * i - 1]], 1e-13, `R${i}`);
      // eq. (5): R_i = w0 C_{2i−2} + w1 C_{2i−1} + w2 C_{2i}, and the de Boor weights at the knot sum to 1
      const e = r.eq5Weights.slice(3 * (i - 1), 3 * i);
      const C = (j) => [r.controlPoints[2 * j], r.controlPoints[2 * j + 1]];
      near([0, 1].map((d) => e[0] * C(2 * i - 2)[d] + e[1] * C(2 * i - 1)[d] + e[2] * C(2 * i)[d]), R, 1e-12, `eq. (5) at ${i}`);
      assert.ok(Math.abs(e[0] + e[1] + e[2] - 1) < 1e-14);
    }
    for (let i = 0; i <= n; i++) {
      const w = r.evenWeights.slice(4 * i, 4 * i + 4);
      const C = [0, 1].map((d) => w[0] * W[i][d] + w[1] * W[i + 1][d] + w[2] * W[i + 2][d] + w[3] * W[i + 3][d]);
      near(C, [r.controlPoints[4 * i], r.controlPoints[4 * i + 1]], 1e-13, `C${2 * i}`);
    }
    assert.ok(Math.max(...r.jointResiduals) < 1e-12);
    // at a = 0 the outer even weights are −p⁻ and −p⁺ of eq. (9) with p = 1/6, c2 = 1 (the default)
    if (a === 0) {
      const u = Array.from(r.dataKnots), D = (j) => u[j + 2] - u[j + 1]; // Δ_j = u_{j+1} − u_j, u_j = u[j + 1]
      for (let i = 0; i <= n; i++) {
        const pm = (D(i) ** 2) / (D(i) ** 2 + 5 * D(i) * D(i - 1) + D(i - 1) ** 2);
        assert.ok(Math.abs(r.evenWeights[4 * i] + pm) < 1e-13, `−p⁻ at ${i}`);
      }
    }
  }
  // the printed last weight b·c/((b+c)(b+c+d)): the weights sum to 1 − b(b − c)/((b+c)(b+c+d)) ≠ 1
  const good = sl.b2Curve({ points: W, samples: 2 });
  const bad = sl.b2Curve({ points: W, samples: 2, eq5: 'printed' });
  const t = Array.from(good.knots), n = good.joints.length / 2;
  for (let i = 1; i <= n; i++) {
    const j = 2 * i + 1, a = t[j - 1] - t[j - 2], b = t[j] - t[j - 1], c = t[j + 1] - t[j], d = t[j + 2] - t[j + 1];
    assert.ok(Math.abs(good.eq5Weights[3 * i - 1] - b * b / ((b + c) * (b + c + d))) < 1e-15);
    assert.ok(Math.abs(bad.eq5Weights[3 * i - 1] - b * c / ((b + c) * (b + c + d))) < 1e-15);
    assert.ok(Math.abs(good.eq5Weights[3 * i - 3] - c * c / ((b + c) * (a + b + c))) < 1e-15);
  }
  assert.ok(Math.max(...bad.jointResiduals) > 0.05, `printed misses: ${bad.jointResiduals}`);
  near(Array.from(bad.joints), Array.from(good.joints), 0, 'same joints');
  // uniform knots: b = c everywhere, printed = corrected
  const u1 = sl.b2Curve({ points: W, knots: 'uniform', samples: 5 });
  const u2 = sl.b2Curve({ points: W, knots: 'uniform', samples: 5, eq5: 'printed' });
  near(Array.from(u2.points), Array.from(u1.points), 1e-12, 'uniform: same curve');
});
