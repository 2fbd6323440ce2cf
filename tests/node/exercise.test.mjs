// exerciseCheck (src/api/exercise.rs → src/exercise/) from Node, against values known in closed form and
// against the other exports that draw the same constructions.
//   scripts/build-wasm.sh && node --test tests/node/exercise.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';

const require = createRequire(import.meta.url);
const sl = require(join(dirname(fileURLToPath(import.meta.url)), '..', '..', 'pkg-node/splinelab.js'));
const rows = (f) => { const o = []; for (let i = 0; i < f.length; i += 2) o.push([f[i], f[i + 1]]); return o; };
const PARABOLA = { degree: 2, breaks: [0, 1], controlPoints: [[-1, 1], [0, -1], [1, 1]] }; // y = x² on [−1, 1]

test('dataDistance: foot points on y = x² (closed form), verdict and score', () => {
  const r = sl.exerciseCheck({ check: 'dataDistance', tol: 0.5, curve: PARABOLA, data: [[0.5, 0.25], [0, 1]] });
  // (0, 1): x² = 1/2 minimises x² + (x² − 1)², distance √3/2
  assert.ok(Math.abs(r.value - Math.sqrt(3) / 2) < 1e-12, r.value);
  assert.equal(r.worst, 1);
  assert.ok(r.distances[0] < 1e-12);
  assert.equal(r.passed, false);
  // 1.73 times the tolerance: 1 − log10(1.732)/4 = 0.94, capped at 0.9 (a failed check never scores more)
  assert.equal(r.score, 0.9);
  // 100 times the tolerance: 1 − 2/4
  const far = sl.exerciseCheck({ check: 'dataDistance', tol: 0.005, curve: PARABOLA, data: [[0, -0.5]] });
  assert.ok(Math.abs(far.value - 0.5) < 1e-12 && Math.abs(far.score - 0.5) < 1e-12, far.score);
  const ok = sl.exerciseCheck({ check: 'dataDistance', tol: 1, curve: PARABOLA, data: [[0, 1]] });
  assert.equal(ok.passed, true);
  assert.equal(ok.score, 1);
  assert.equal(ok.check, 'dataDistance');
  assert.equal(ok.tol, 1);
});

test('dataDistance on the B2 curve through its B-spline form: 0 at a = 0, as far as b2Curve says at a = 1/6', () => {
  const W = [[-1, -0.5], [0, 0], [1, 2], [2.5, 2.4], [3.5, 0.5], [5, 1], [6, 2.5], [7, 3]];
  for (const a of [0, 1 / 6]) {
    const c = sl.b2Curve({ points: W, a, samples: 4001 });
    const r = sl.exerciseCheck({ check: 'dataDistance', tol: 1e-9, curve: { degree: 3, knots: Array.from(c.knots), controlPoints: c.controlPoints }, data: W.slice(2, -2) });
    // brute force on 4001 samples of b2Curve (a polyline: an upper bound, within the sampling error)
    const pts = rows(c.points);
    const brute = Math.max(...W.slice(2, -2).map(([x, y]) => Math.min(...pts.map(([u, v]) => Math.hypot(u - x, v - y)))));
    assert.ok(r.value <= brute + 1e-12 && brute - r.value < 1e-3, `${a}: ${r.value} vs ${brute}`);
    assert.equal(r.passed, a === 0);
  }
});

test('continuity: a double knot leaves C¹, the jump of the second derivative is measured', () => {
  const pts = [[0, 0], [1, 2], [2, 2.5], [3, 0.5], [4, 0], [5, 2], [6, 1.5]];
  const curve = { degree: 3, knots: [0, 0, 0, 0, 0.25, 0.5, 0.5, 1, 1, 1, 1], controlPoints: pts };
  const r = sl.exerciseCheck({ check: 'continuity', tol: 1e-9, curve, at: 0.5, order: 2 });
  assert.ok(r.relative[0] < 1e-13 && r.relative[1] < 1e-12, String(r.relative));
  assert.equal(r.passed, false);
  // the one-sided second derivatives from bsplineCurve just left and right of 0.5 (extrapolated pieces agree)
  const h = 1e-6;
  const d = sl.bsplineCurve({ ...curve, points: pts, at: [0.5 - h, 0.5], derivatives: 2 }).d2;
  const jump = Math.hypot(d[0] - d[2], d[1] - d[3]);
  assert.ok(Math.abs(r.jumps[2] - jump) < 1e-3 * jump, `${r.jumps[2]} vs ${jump}`);
  const c1 = sl.exerciseCheck({ check: 'continuity', tol: 1e-9, curve, at: 0.5, order: 1 });
  assert.equal(c1.passed, true);
});

test('ellipse: agrees with quasiCubicShapeCheck; 0 only at α = 1', () => {
  const e = sl.quasiCubicPreset({ name: 'ellipse' });
  for (const alpha of [0.5, 1]) {
    const r = sl.exerciseCheck({ check: 'ellipse', tol: 1e-9, points: e.points, alpha });
    const s = sl.quasiCubicShapeCheck({ shape: 'ellipse', points: e.points, alpha });
    assert.ok(Math.abs(r.value - s.deviation) < 1e-15);
    assert.equal(r.passed, alpha === 1);
  }
});

test('networkNorm: the same ‖S − G‖ as networkSurfaces; S = G on the separable network', () => {
  for (const name of ['uniform-dome', 'separable']) {
    const network = sl.networkExample({ name });
    const r = sl.exerciseCheck({ check: 'networkNorm', tol: 1e-9, network, pair: 'SG' });
    const n = sl.networkSurfaces({ network, samplesU: 4, samplesV: 4, surfaces: ['S'] }).norms.SG;
    assert.ok(Math.abs(r.value - n) < 1e-15, `${r.value} ${n}`);
    assert.equal(r.passed, name === 'separable');
  }
});

test('envelopePoint: 0 at the parameter of the target on knotEnvelopeCurve, the distance elsewhere', () => {
  const curve = { order: 4, knots: [0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5], controlPoints: [[0, 0], [1, 2.4], [2.2, 2.8], [3.2, 0.6], [4.4, 0.2], [5.4, 2.6], [6.6, 2.4], [7.4, 0.4]] };
  const e = sl.knotEnvelopeCurve({ curve, p: 5, at: [1.6, 2.2] }).points;
  const target = [e[0], e[1]];
  const hit = sl.exerciseCheck({ check: 'envelopePoint', tol: 1e-9, curve, p: 5, up: 1.6, target });
  assert.ok(hit.value < 1e-12 && hit.passed);
  assert.ok(hit.curveDistance < 1e-9, 'the moved curve passes through its touching point');
  const miss = sl.exerciseCheck({ check: 'envelopePoint', tol: 1e-9, curve, p: 5, up: 2.2, target });
  assert.ok(Math.abs(miss.value - Math.hypot(e[2] - e[0], e[3] - e[1])) < 1e-12);
});

test('fitError: the rms of b2Fit with the same data and known curve', () => {
  const d = sl.noisyData({ curve: 'sine', count: 40, sigma: 0.1, seed: 4 });
  const points = rows(d.points);
  for (const a of [0, 0.2]) {
    const r = sl.exerciseCheck({ check: 'fitError', tol: 0.05, points, a, truthCurve: 'sine' });
    const f = sl.b2Fit({ points, a, truthCurve: 'sine', samples: 2 });
    assert.ok(Math.abs(r.value - f.rms) < 1e-15 && Math.abs(r.max - f.max) < 1e-15);
  }
});
