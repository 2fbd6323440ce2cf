// API-level regression tests for the bugs the fuzzers found (issue 9; the list is in tests/ROBUSTNESS.md).
// Each test is the smallest input that broke the module, and what it must do now.
//   scripts/build-wasm.sh && node --test tests/node/regressions.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';

const require = createRequire(import.meta.url);
const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const sl = require(join(root, 'pkg-node/splinelab.js'));

const pts5 = [[0, 0], [1, 1.9], [2, 1.0], [3, -1.4], [4, -1.8]];
const finite = (a) => Array.from(a).every(Number.isFinite);
const throwsField = (fn, field) => assert.throws(fn, (e) => e instanceof Error && !(e instanceof WebAssembly.RuntimeError) && e.message.startsWith(`${field}:`), `an Error naming ${field}`);
const stillWorks = () => {
  const r = sl.bsplineCurve({ degree: 2, knots: [0, 0, 0, 1, 1, 1], points: [[0, 0], [1, 1], [2, 0]], samples: 3 });
  assert.equal(r.points.length, 6);
};

// Bug 1: bsplineCurve with two distinct knots 1e-300 apart returned NaN in d2 (1/gap² overflows).
test('bug 1: bsplineCurve/bsplineBasis reject distinct knots closer than 1e-12 × range', () => {
  throwsField(() => sl.bsplineCurve({ degree: 3, knots: [0, 0, 0, 0, 1e-300, 1, 1, 1, 1], points: pts5, samples: 20, derivatives: 2 }), 'knots[4]');
  throwsField(() => sl.bsplineBasis({ degree: 3, knots: [0, 0, 0, 0, 1e-300, 1, 1, 1, 1], at: [0, 0.5], derivatives: 2 }), 'knots[4]');
  stillWorks();
  // gap ratio 1e-6 (the nearly equal knots) is accepted and finite, at coordinates 1e8
  const r = sl.bsplineCurve({ degree: 3, knots: [0, 0, 0, 0, 0.5, 0.5 + 1e-6, 1, 1, 1, 1], points: [...pts5, [5, 1]].map(([x, y]) => [x * 1e8, y * 1e8]), samples: 200, derivatives: 2 });
  assert.ok(finite(r.points) && finite(r.d1) && finite(r.d2));
});

// Bug 2: knotModifiedCurve with p = 5 moved to 1e-300 (outside its neighbours, next to the triple knot 0: a
// pole of the extended family) returned NaN points.
test('bug 2: knot modification at a pole of the extended family is an Error on up/to', () => {
  const curve = { order: 4, knots: [0, 0, 0, 0, 1, 2, 3, 3, 3, 3], controlPoints: [[0, 0], [0, 1.9], [2, 1], [3, -1.4], [4, -1.8], [5, 0.4]] };
  throwsField(() => sl.knotModifiedCurve({ curve, p: 5, up: 1e-300, samples: 20, derivatives: 2 }), 'up');
  stillWorks();
  const surface = { orderU: 4, orderV: 3, knotsU: curve.knots, knotsV: [0, 0, 0, 1, 2, 2, 2], controlPoints: curve.controlPoints.map(([x, y]) => [[x, y, 0], [x, y, 1], [x, y, 2], [x, y, 1]]) };
  throwsField(() => sl.knotModifiedSurface({ surface, p: 5, up: -1e-250, samplesU: 9, samplesV: 3 }), 'up');
  stillWorks();
  // away from the pole (and at ±1e8, towards the limits) the extended family is finite
  for (const up of [1e-5, -0.5, 5, 1e8, -1e8]) {
    const r = sl.knotModifiedCurve({ curve, p: 5, up, samples: 50, derivatives: 2 });
    assert.ok(finite(r.points) && finite(r.d1) && finite(r.d2), `up ${up}`);
  }
  const s = sl.knotModifiedSurface({ surface, p: 5, up: 1e8, samplesU: 9, samplesV: 3, mesh: true });
  assert.ok(finite(s.points));
});

// Bug 3: a large array where a name or an object is expected (networkExample({ name: [200000 entries] }))
// took seconds: serde's "invalid type" message formatted the whole array. Fixed in src/api/mod.rs (Opts::opt
// probes large arrays with their first two entries); the message is now short.
test('bug 3: a huge array in place of a name fails fast with a short message', () => {
  const huge = Array.from({ length: 200_000 }, (_, i) => i);
  for (const [fn, key] of [['networkExample', 'name'], ['dataset', 'name'], ['noisyData', 'curve'], ['networkRepair', 'network']]) {
    if (typeof sl[fn] !== 'function') continue;
    assert.throws(() => sl[fn]({ [key]: huge }), (e) => e instanceof Error && e.message.startsWith(`${key}:`) && e.message.length < 300, fn);
  }
  stillWorks();
});

// Bugs found while their owners were still working, fixed after the merge (tests/ROBUSTNESS.md).
test('bug 4 (fixed in src/bezier: break gaps below 1e-12 × range are rejected): bezierSpline with a 1e-300 segment', () => {
  const r = (() => { try { return sl.bezierSpline({ points: [[0, 0], [1, 2], [2, 1], [3, -1], [4, -2], [5, 0], [6, 2]], degree: 3, breaks: [0, 1e-300, 2], samples: 20, derivatives: 2 }); } catch (e) { assert.ok(e.message.startsWith('breaks')); return null; } })();
  if (r) assert.ok(finite(r.d2));
});

test('bug 8 (fixed in src/bezier/alphas.rs: α kept 1e-9 from 0 and 1): bezierRemodel with α_1 = 1e-300', () => {
  const base = {
    points: [[10, 16], [7, 21], [3, 9], [0, 0], [-4, 0], [-8, 0], [-6, 3], [-4, 6], [2, 2], [8, -2], [10, 3]],
    degree: 2, breaks: [0, 1, 1.75, 2.5, 3.25, 4], r: 1, samples: 20, derivatives: 2,
  };
  const alphas = [[1e-300, 1 / 20], [19 / 20, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 10]];
  try {
    const r = sl.bezierRemodel({ ...base, alphas });
    for (const k of ['points', 'd1', 'd2', 'curvature', 'curvaturePredicted', 'curvaturePrinted', 'curvatureRatio']) if (r[k]) assert.ok(finite(r[k]), k);
  } catch (e) { assert.ok(e.message.startsWith('alphas'), e.message); }
});

test('bug 9 (fixed in src/quasi_cubic/presets.rs: an Error naming points): quasiCubicShapeCheck on coincident points', () => {
  try {
    const r = sl.quasiCubicShapeCheck({ shape: 'parabola', points: [[0, 2], [0, 2], [0, 2], [1.5, -0.5]], alpha: 1, samples: 20 });
    assert.ok(Number.isFinite(r.deviation));
  } catch (e) { assert.ok(e.message.startsWith('points'), e.message); }
});

test('bug 11 (fixed in src/network.rs: cells below 1e-12 × range rejected): crissCrossBasis with a 1e-300 cell', () => {
  try {
    const r = sl.crissCrossBasis({ u: [0, 0.5, 1], v: [0, 1e-300], i: 1, j: 1, atUV: [[0.25, 0.25], [0.5, 0.7]], derivatives: 1 });
    assert.ok(finite(r.values) && finite(r.du) && finite(r.dv));
  } catch (e) { assert.ok(e.message.startsWith('v'), e.message); }
});

test('bug 13 (fixed in src/api/opts.rs: a point row over 3 numbers is refused before the list is read): 300 rows of 200,000 numbers', () => {
  // the fuzzer's "duplicate an entry" mutation on points: the whole list (30 million numbers) was converted first (5 s)
  const long = Array.from({ length: 200_000 }, (_, i) => i >> 1);
  const points = Array.from({ length: 300 }, (_, i) => (i % 2 ? [i, 1] : long));
  assert.throws(() => sl.bsplineInsertKnot({ degree: 2, points, u: 0.5 }), { field: 'points[0]', kind: 'wrong-type', message: /got 200000 numbers/ });
  points[0] = [0, 0];
  assert.throws(() => sl.bsplineInsertKnot({ degree: 2, points, u: 0.5 }), { field: 'points[2]', kind: 'incompatible', message: /same dimension \(2\), got 200000 numbers/ });
});
