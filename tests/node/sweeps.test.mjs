// One-call sweeps (issue 13): each equals the per-value calls it replaces.
//   scripts/build-wasm.sh && node --test tests/node/sweeps.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';

const require = createRequire(import.meta.url);
const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const sl = require(join(root, 'pkg-node/splinelab.js'));
const throwsField = (fn, field) => assert.throws(fn, (e) => e instanceof Error && e.message.startsWith(`${field}:`), `an Error naming ${field}`);

const ex = [[10, 16], [7, 21], [3, 9], [0, 0], [-4, 0], [-8, 0], [-6, 3], [-4, 6], [2, 2], [8, -2], [10, 3]];
const exBreaks = [0, 1, 7 / 4, 5 / 2, 13 / 4, 4];
const fig1 = [[2 / 3, 1 / 20], [19 / 20, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 10]];

test('bezierRemodel alphaSweep = one bezierRemodel call per α (Fig. 3), enforced and not', () => {
  const xs = Array.from({ length: 61 }, (_, j) => 0.004 + (0.5 - 0.004) * j / 60);
  for (const enforce of [true, false]) {
    for (const I of [1, 2, 4, 5]) {
      const base = { points: ex, degree: 2, breaks: exBreaks, alphas: fig1, r: 1, enforce, at: [] };
      const s = sl.bezierRemodel({ ...base, alphaSweep: new Float64Array(xs), alphaSweepJoint: I });
      assert.ok(s.sweepCurvature instanceof Float64Array && s.sweepCurvature.length === xs.length);
      xs.forEach((a, j) => {
        const al = fig1.map((row) => [...row]);
        al[I - 1][1] = a;
        const one = sl.bezierRemodel({ ...base, alphas: al });
        assert.equal(s.sweepCurvature[j], one.curvature[I], `K* I=${I} α=${a} enforce=${enforce}`);
        assert.equal(s.sweepCurvaturePrinted[j], one.curvaturePrinted[I], `printed I=${I} α=${a}`);
      });
    }
  }
  // without the option nothing is added; errors name the field
  assert.equal(sl.bezierRemodel({ points: ex, degree: 2, breaks: exBreaks, at: [] }).sweepCurvature, undefined);
  throwsField(() => sl.bezierRemodel({ points: ex, degree: 2, breaks: exBreaks, at: [], alphaSweep: [0.2], alphaSweepJoint: 0 }), 'alphaSweepJoint');
  throwsField(() => sl.bezierRemodel({ points: ex, degree: 2, breaks: exBreaks, at: [], alphaSweep: [0.2], alphaSweepJoint: 9 }), 'alphaSweepJoint');
  throwsField(() => sl.bezierRemodel({ points: ex, degree: 2, breaks: exBreaks, at: [], alphaSweep: [0.2, 1.2] }), 'alphaSweep[1]');
  throwsField(() => sl.bezierRemodel({ points: ex, degree: 2, breaks: exBreaks, at: [], alphaSweep: [0.2, NaN] }), 'alphaSweep[1]');
});
