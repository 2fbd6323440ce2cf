// knotDeBoorCurve: the de Boor triangle with a moved knot ends at the family's point (knotModifiedCurve) for
// ordinary and extended knot values; α_j^r is (u − u_lo)/(u_hi − u_lo) on the substituted knots; `usesUp` marks
// exactly the α that contain the moved knot; bad input names the field.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';

const sl = createRequire(import.meta.url)('../../pkg-node/splinelab.js');
const P = [[0, 0], [1, 2.4], [2.2, 2.8], [3.2, 0.6], [4.4, 0.2], [5.4, 2.6], [6.6, 2.4], [7.4, 0.4]];

test('the last point of the triangle is the modified curve point (orders 2–5, inside and outside the neighbours)', () => {
  for (const k of [2, 3, 4, 5]) {
    const knots = [...Array(k).fill(0), ...Array.from({ length: P.length - k }, (_, i) => i + 1), ...Array(k).fill(P.length - k + 1)];
    const curve = { order: k, knots, controlPoints: P };
    const p = k + 1;
    for (const up of [knots[p] - 0.4, knots[p] + 0.3, knots[p] - 3.7, knots[p] + 5.2]) {
      for (const u of [0.2, 1.1, knots[p] - 0.5, knots[p] + 0.45, P.length - k + 0.9]) {
        const t = sl.knotDeBoorCurve({ curve, p, up, u });
        assert.equal(t.levels.length, k * (k - 1) / 2);
        const e = sl.knotModifiedCurve({ curve, p, up, at: [u] }).points;
        const n = t.points.length;
        assert.ok(Math.hypot(t.points[n - 2] - e[0], t.points[n - 1] - e[1]) < 1e-11, `k ${k} up ${up} u ${u}`);
        for (let s = 0; s < t.levels.length; s++) {
          const lo = t.knotLo[s], hi = t.knotHi[s];
          const den = t.knots[hi] - t.knots[lo];
          const a = den === 0 ? 0 : (u - t.knots[lo]) / den;
          assert.ok(Math.abs(a - t.alphas[s]) < 1e-14, 'α from the substituted knots');
          assert.equal(t.usesUp[s], lo === p || hi === p ? 1 : 0);
          assert.equal(hi - lo, k - t.levels[s], 'α_j^r spans u_j … u_{j+k−r}');
        }
      }
    }
  }
});

test('bad input names the field', () => {
  const curve = { order: 4, knots: [0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5], controlPoints: P };
  assert.throws(() => sl.knotDeBoorCurve({ curve, p: 5, up: 2.4 }), /^Error: u/);
  assert.throws(() => sl.knotDeBoorCurve({ curve, p: 5, up: 2.4, u: 9 }), /u: must lie in the curve's domain/);
  assert.throws(() => sl.knotDeBoorCurve({ curve, up: 2.4, u: 1 }), /up|p/);
  assert.throws(() => sl.knotDeBoorCurve({ curve, p: 1, up: 2.4, u: 1 }), /p/);
  assert.equal(sl.knotDeBoorCurve({ curve, p: 5, up: 2.4, u: 1 }).levels.length, 6, 'still works after errors');
});
