// Explicit parameters through the streamed output (api/out.rs curve_result: 8192 parameters per block):
// results across block boundaries equal the uniform-samples path at the same parameters, values and both
// derivatives, for a B-spline (kernel run walk), a B2 curve and a quasi-cubic curve (trig polynomials).
import test from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';

const require = createRequire(import.meta.url);
const sl = require('../../pkg-node/splinelab.js');

const W = Array.from({ length: 60 }, (_, i) => { const t = i * 0.15; return [(1 + t) * Math.cos(t), (1 + t) * Math.sin(t)]; });
const N = 3 * 8192 + 5; // three full blocks and a partial one

function close(name, a, b, tol) {
  assert.equal(a.length, b.length, `${name}: lengths`);
  let worst = 0, scale = 1;
  for (let i = 0; i < a.length; i++) { worst = Math.max(worst, Math.abs(a[i] - b[i])); scale = Math.max(scale, Math.abs(b[i])); }
  assert.ok(worst <= tol * scale, `${name}: differs by ${worst} (scale ${scale})`);
}

for (const [name, fn, opts, tol] of [
  ['bsplineCurve', sl.bsplineCurve, { degree: 3, points: W }, 1e-12],
  ['b2Curve', sl.b2Curve, { points: W, a: 0.05 }, 1e-12],
  ['quasiCubicCurve', sl.quasiCubicCurve, { points: W, alpha: 1 }, 1e-12],
]) {
  test(`${name}: at (Float64Array, ${N} parameters, 4 blocks) equals samples at the same parameters`, () => {
    for (const derivatives of [0, 1, 2]) {
      const u = fn({ ...opts, samples: N, derivatives });
      const at = new Float64Array(u.params);
      const r = fn({ ...opts, at, derivatives });
      assert.notEqual(r.params, at, 'params is a copy, never the caller\'s array');
      assert.deepEqual(Array.from(r.params), Array.from(at));
      close(`${name} points (derivatives ${derivatives})`, r.points, u.points, tol);
      if (derivatives >= 1) close(`${name} d1`, r.d1, u.d1, tol);
      if (derivatives >= 2) close(`${name} d2`, r.d2, u.d2, tol);
      assert.equal(r.d1 === undefined, derivatives < 1);
      assert.equal(r.d2 === undefined, derivatives < 2);
    }
    // reversed order: the same points, reversed
    const u = fn({ ...opts, samples: 20001 });
    const rev = new Float64Array(u.params).reverse();
    const r = fn({ ...opts, at: rev });
    const back = new Float64Array(r.points.length);
    for (let i = 0; i < 20001; i++) { back[2 * i] = r.points[2 * (20000 - i)]; back[2 * i + 1] = r.points[2 * (20000 - i) + 1]; }
    close(`${name} reversed`, back, u.points, tol);
  });
}

test('a non-finite at entry is named by its index, wherever it sits', () => {
  for (const i of [0, 1023, 1024, 50_000]) {
    const at = new Float64Array(60_000).fill(0.5);
    at[i] = NaN;
    at[59_999] = Infinity;
    assert.throws(() => sl.bsplineCurve({ degree: 3, points: W, at }), (e) => e.field === `at[${i}]` && e.kind === 'not-finite');
  }
});
