// The pure parts of "figures in sound" (www/lib/audio-trace.js): height → pitch (exponential: equal steps in y
// are equal musical intervals), x → pan, continuity → timbre, a knot vector's distinct knots with their
// continuity, which knots click (inside the domain only) and where the voices change.
//   node --test tests/node/audio-trace.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pitchOf, panOf, timbreOf, knotsWithContinuity, innerKnots, planTrace, pointText, LOW_HZ, HIGH_HZ, TRACE_SECONDS, GAIN } from '../../www/lib/audio-trace.js';

test('y → Hz: the ends of yRange at LOW_HZ and HIGH_HZ, equal steps equal ratios, clamped outside', () => {
  assert.equal(pitchOf(0, [0, 1]), LOW_HZ);
  assert.equal(pitchOf(1, [0, 1]), HIGH_HZ);
  const a = pitchOf(0.25, [0, 1]), b = pitchOf(0.5, [0, 1]), c = pitchOf(0.75, [0, 1]);
  assert.ok(Math.abs(b / a - c / b) < 1e-12, 'exponential');
  assert.ok(Math.abs(b - Math.sqrt(LOW_HZ * HIGH_HZ)) < 1e-9, 'the middle of the range is the geometric mean');
  assert.equal(pitchOf(-5, [0, 1]), LOW_HZ);
  assert.equal(pitchOf(9, [0, 1]), HIGH_HZ);
  assert.ok(Number.isFinite(pitchOf(3, [3, 3])), 'a flat range still has a pitch');
  assert.ok(GAIN <= 0.2 && TRACE_SECONDS === 3);
});

test('x → pan and continuity → timbre', () => {
  assert.deepEqual([panOf(0, [0, 4]), panOf(2, [0, 4]), panOf(4, [0, 4])], [-1, 0, 1]);
  assert.deepEqual([3, 2, 1, 0, -1].map(timbreOf), ['sine', 'sine', 'triangle', 'square', 'sawtooth']);
});

test('knots: distinct values with continuity p − multiplicity; clicks strictly inside the domain', () => {
  const k = knotsWithContinuity([0, 0, 0, 0, 0.25, 0.5, 0.5, 1, 1, 1, 1], 3);
  assert.deepEqual(k, [{ t: 0, continuity: -1 }, { t: 0.25, continuity: 2 }, { t: 0.5, continuity: 1 }, { t: 1, continuity: -1 }]);
  const samples = Array.from({ length: 11 }, (_, j) => ({ t: j / 10, x: j / 10, y: (j / 10) ** 2 }));
  const trace = { name: 'C(u)', samples, knots: k, xRange: [0, 1], yRange: [0, 1] };
  assert.deepEqual(innerKnots(trace).map((q) => q.t), [0.25, 0.5], 'the end knots do not click');
  const plan = planTrace(trace);
  assert.deepEqual(plan.ticks, [{ time: 0.75, continuity: 2 }, { time: 1.5, continuity: 1 }]);
  assert.deepEqual(plan.voices.map((v) => [v.type, v.from, v.to]), [['sine', 0, 1.5], ['triangle', 1.5, 3]]);
  const hz = plan.voices.flatMap((v) => v.points.map((p) => p.hz));
  assert.ok(hz.every((f, i) => i === 0 || f >= hz[i - 1]), 'y rises, so does the pitch');
});

test('the step announcement: two decimals, Unicode minus', () => {
  assert.equal(pointText('u', { t: 0.35, x: 1.2, y: -0.5 }), 'u = 0.35: (1.20, −0.50)');
  assert.equal(pointText('u', { t: 0, x: -0.001, y: 0 }), 'u = 0.00: (0.00, 0.00)');
});
