// curveFacts (issue 25, the facts behind the words of a 2D curve figure) on the built Node module: bad input names
// the field and the kind; good input gives numbers computed independently here (a parabola's vertex between
// samples, an S-curve's one inflection, the distances of known points to a polyline).
//   scripts/build-wasm.sh && node --test tests/node/curve-facts.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';
import { curveWords, bsplineContinuityWords, sig3 } from '../../www/lib/curve-words.js';

const require = createRequire(import.meta.url);
const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const sl = require(join(root, 'pkg-node/splinelab.js'));

/** n samples of f on [0, 1]: { params, points (flat) }. */
function sampled(n, f) {
  const params = Float64Array.from({ length: n }, (_, k) => k / (n - 1));
  return { params, points: Float64Array.from(Array.from(params, f).flat()) };
}
const close = (a, b, tol, what) => assert.ok(Math.abs(a - b) <= tol, `${what}: ${a} vs ${b}`);

test('bad input: the error names the field and the kind', () => {
  const cases = [
    [{ points: new Float64Array([0, 0]) }, 'points', 'too-few'],
    [{ points: new Float64Array([0, 0, 1, 1, 2]) }, 'points', 'invalid'],
    [{ points: new Float64Array([0, 0, 1, 1]), params: new Float64Array([0]) }, 'params', 'incompatible'],
    [{ points: new Float64Array([0, 0, 1, 1]), params: new Float64Array([1, 0]) }, 'params[1]', 'not-increasing'],
    [{ points: new Float64Array([0, 0, 1, Infinity]) }, /^points/, 'not-finite'],
    [{ points: new Float64Array([0, 0, 1, 1]), data: 'abc' }, 'data', 'wrong-type'],
  ];
  for (const [opts, field, kind] of cases) {
    assert.throws(() => sl.curveFacts(opts), (e) => {
      if (field instanceof RegExp) assert.match(e.field, field); else assert.equal(e.field, field, e.message);
      assert.equal(e.kind, kind, e.message);
      return true;
    });
  }
});

test('a parabola: its vertex between samples, its ends, no inflection, its length', () => {
  // y = (u − 0.33)² + 1, x = 2u, 11 samples: the vertex at u = 0.33 is not a sample; the parabola refinement is exact
  const c = sampled(11, (u) => [2 * u, (u - 0.33) ** 2 + 1]);
  const f = sl.curveFacts(c);
  close(f.lowest.u, 0.33, 1e-12, 'lowest u'); close(f.lowest.x, 0.66, 1e-12, 'lowest x'); close(f.lowest.y, 1, 1e-12, 'lowest y');
  assert.deepEqual([f.leftmost.x, f.rightmost.x, f.highest.u], [0, 2, 1]);
  assert.equal(f.inflectionParams.length, 0);
  let len = 0;
  for (let k = 1; k < 11; k++) len += Math.hypot(c.points[2 * k] - c.points[2 * k - 2], c.points[2 * k + 1] - c.points[2 * k - 1]);
  close(f.length, len, 1e-12, 'length');
});

test('an S-curve (one period of the sine) has one inflection, at u = 0.5', () => {
  const s = sl.curveFacts(sampled(301, (u) => [u, Math.sin(2 * Math.PI * u)]));
  assert.equal(s.inflectionParams.length, 1);
  close(s.inflectionParams[0], 0.5, 1e-3, 'inflection u');
  close(s.highest.u, 0.25, 1e-4, 'highest u'); close(s.highest.y, 1, 1e-5, 'highest y');
});

test('inflections: one for y = (u − 0.4)³, none for a circle arc', () => {
  const s = sl.curveFacts(sampled(201, (u) => [u, (u - 0.4) ** 3]));
  assert.equal(s.inflectionParams.length, 1);
  close(s.inflectionParams[0], 0.4, 1e-3, 'inflection u');
  close(s.inflectionPoints[0], 0.4, 1e-3, 'inflection x');
  const arc = sl.curveFacts(sampled(100, (u) => [Math.cos(3 * u), Math.sin(3 * u)]));
  assert.equal(arc.inflectionParams.length, 0);
});

test('distances of known points to a polyline: each, the largest with its index, the RMS', () => {
  const f = sl.curveFacts({ points: new Float64Array([0, 0, 4, 0, 4, 4]), data: [[2, 3], [-3, 4], [5, 2], [1, 0]] });
  // (2, 3): 2 from the vertical side x = 4 (nearer than 3 to the bottom); (−3, 4): 5 from (0, 0); (5, 2): 1; (1, 0): 0
  assert.deepEqual(Array.from(f.distances), [2, 5, 1, 0]);
  assert.equal(f.maxDistance, 5);
  assert.equal(f.maxDistanceIndex, 1);
  close(f.rmsDistance, Math.sqrt(30 / 4), 1e-12, 'RMS');
  assert.equal(sl.curveFacts({ points: new Float64Array([0, 0, 1, 0]) }).distances, undefined, 'no data: no distances');
});

test('the words: 3 significant digits, Unicode subscripts, continuity from the knots', () => {
  const f = sl.curveFacts({ points: new Float64Array([0, 0, 4, 0, 4, 4]), data: [[2, 3], [-3, 4]] });
  const w = curveWords(f);
  assert.match(w, /runs from x = 0 to 4/);
  assert.match(w, /within 5 of every data point \(farthest: W₁, 5; RMS 3\.81\)/);
  assert.doesNotMatch(w, /W_|W\d/);
  assert.deepEqual([sig3(0.018234), sig3(4.2), sig3(-123.4), sig3(1e-9)], ['0.0182', '4.2', '−123', '0']);
  assert.equal(bsplineContinuityWords(3, [0, 0, 0, 0, 0.25, 0.5, 0.5, 0.75, 1, 1, 1, 1]),
    'At its joints it is C² at the knots u = 0.25, 0.75 and is C¹ at the knot u = 0.5 (degree 3: C³⁻ᵐ at a knot of multiplicity m).');
});
