// Errors keep their kind in JavaScript (issue 15): every export, given a bad input, throws a plain `Error`
// whose `.field` is the option path of the bad input and whose `.kind` is one of the stable strings of
// docs/API.md ("Errors"); the message keeps its "<field>: …" form. One or more bad inputs per export; the
// list of exports is taken from the module, so a new export without a case here fails the test.
//   scripts/build-wasm.sh && node --test tests/node/errors.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';
import { rawIn } from '../e2e/raw-notation.mjs';

const require = createRequire(import.meta.url);
const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const sl = require(join(root, 'pkg-node/splinelab.js'));

const KINDS = new Set(['too-few', 'too-many', 'not-finite', 'not-increasing', 'incompatible', 'out-of-range',
  'degenerate', 'invalid', 'wrong-type', 'missing']);

const grid = (rows, cols, f) => Array.from({ length: rows }, (_, i) => Array.from({ length: cols }, (_, j) => f(i, j)));
const pts2 = (n) => Array.from({ length: n }, (_, i) => [i, Math.sin(i * 1.3) * 2]);
const surf = (patch = {}) => ({
  orderU: 3, orderV: 3, knotsU: [0, 0, 0, 1, 2, 2, 2], knotsV: [0, 0, 0, 1, 2, 2, 2],
  controlPoints: grid(4, 4, (i, j) => [i, j, Math.sin(i + j)]), ...patch,
});
const curveK = (patch = {}) => ({ order: 4, knots: [0, 0, 0, 0, 1, 2, 3, 3, 3, 3], controlPoints: pts2(6), ...patch });
const net = () => sl.networkExample({ name: 'uniform-dome' });
const withNet = (f) => { const n = net(); f(n); return n; };
// the network with every curve as flat coordinates (a Float64Array per curve), edited by f
const flatNet = (f) => withNet((n) => { n.P = n.P.map((r) => Float64Array.from(r.flat())); n.Q = n.Q.map((r) => Float64Array.from(r.flat())); f(n); });

// export → [[options, field, kind, (expected, got)?], …]
const CASES = {
  bsplineCurve: [
    [{ degree: 3, knots: [0, 0, 0, 0, 0.5, 1, 1, 1, 1], points: [[0, 0], [1, NaN], [2, 0], [3, 1], [4, 0]] }, 'points[1][1]', 'not-finite'],
    [{ degree: 3, knots: [0, 1], points: pts2(5) }, 'knots', 'incompatible'],
    [{ degree: 3, knots: [0, 0, 0, 0, 0.5, 1, 1, 1, 1], points: [[0, 0]] }, 'points', 'too-few', 4, 1],
    [{ degree: 3, knots: [0, 0, 0, 0, 0.5, 1, 1, 1, 1], points: 'abc' }, 'points', 'wrong-type'],
    [{ degree: 3, knots: [0, 0, 0, 0, 0.5, 1, 1, 1, 1], points: pts2(100_001) }, 'points', 'too-many', 100_000, 100_001],
  ],
  bsplineBasis: [[{ degree: 2, knots: [0, 0, 0, 1, 0.5, 1, 1], at: [0.3] }, /^knots/, 'not-increasing']],
  bsplineDeBoor: [
    [{ degree: 2, knots: [0, 0, 0, 1, 2, 2, 2], points: pts2(4), u: 5 }, 'u', 'out-of-range'],
    [{ degree: 2, knots: [0, 0, 0, 1, 2, 2, 2], points: pts2(4) }, 'u', 'missing'],
    [{ degree: 2, knots: [0, 0, 0, 1, 2, 2, 2], points: pts2(4), u: NaN }, 'u', 'not-finite'],
  ],
  bsplineInsertKnot: [
    [{ degree: 2, knots: [0, 0, 0, 1, 2, 2, 2], points: pts2(4), u: -0.5 }, 'u', 'out-of-range'],
    [{ degree: 2, knots: [0, 0, 0, 1, 2, 2, 2], points: pts2(4), u: 'x' }, 'u', 'wrong-type'],
  ],
  bezierDeCasteljau: [
    [{ points: pts2(4), u: 1.5 }, 'u', 'out-of-range'],
    [{ points: pts2(5), degree: 2, breaks: [0, 1, 3], u: 4 }, 'u', 'out-of-range'],
  ],
  quasiCubicBasis: [[{ alpha: 'x', at: [0.5] }, 'alpha', 'wrong-type']],
  quasiCubicCurve: [[{ points: pts2(6), alpha: 1, samples: -1 }, 'samples', 'out-of-range']],
  quasiCubicInterpolation: [[{ points: pts2(6), beta: [1, 2] }, /^beta/, 'incompatible']],
  quasiCubicSurface: [
    [{ grid: [[[0, 0, 0]]], alpha: 1 }, 'grid', 'too-few'],
    // a grid's bad point is named by row and column (it was once named by its place in the flattened grid)
    [{ grid: grid(5, 6, (i, j) => [i, j, i === 2 && j === 1 ? Infinity : 0]), alpha: 1 }, 'grid[2][1][2]', 'not-finite'],
    [{ grid: grid(5, 6, (i, j) => (i === 3 && j === 4 ? [i, j] : [i, j, 0])), alpha: 1 }, 'grid[3][4]', 'incompatible'],
  ],
  quasiCubicBlendedSurface: [[{ grid: grid(5, 5, (i, j) => [i, j, 0]), beta: grid(2, 3, () => 1) }, 'beta', 'incompatible']],
  quasiCubicPreset: [[{ name: 'teapot' }, 'name', 'invalid']],
  quasiCubicShapeCheck: [[{ shape: 'circle', points: [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], alpha: 1 }, 'points', 'incompatible']],
  b2Curve: [
    [{ points: pts2(7), a: Infinity }, 'a', 'not-finite'],
    [{ points: pts2(7), a: 'x' }, 'a', 'wrong-type'],
    [{ points: pts2(7), eq5: 'typo' }, 'eq5', 'invalid'],
    // a choice given as something other than a string is the wrong type (as for every export's named choices)
    [{ points: pts2(7), eq5: 5 }, 'eq5', 'wrong-type'],
    [{ points: pts2(7), construction: 3 }, 'construction', 'wrong-type'],
    [{ points: pts2(7), autoTension: 1 }, 'autoTension', 'wrong-type'],
    [{ points: pts2(7), tension: 'x' }, 'tension', 'wrong-type'],
    [{ points: [[0, 0], [1, 1]] }, 'points', 'too-few'],
    [{ points: [[0, 0], [1, 0], [1, 0], [2, 0], [3, 1], [4, 0]] }, 'points[2]', 'degenerate'],
    [{ points: [[0, 0], [1, 0], [2, 0], [1, 0], [3, 1], [4, 0]], knots: [0, 1, 2, 2, 4, 5, 6, 7] }, /^knots/, 'incompatible'],
    [{ points: pts2(7), autoTension: 'always' }, 'autoTension', 'invalid'],
    [{ points: pts2(7), tension: Array(10).fill(0.1) }, 'tension', 'incompatible'],
  ],
  b2Surface: [[{ grid: grid(6, 6, (i, j) => [i, j, 0]), autoTension: 'paper' }, 'autoTension', 'invalid']],
  b2Basis: [
    [{ knots: 'uniform', count: 3 }, 'count', 'out-of-range'],
    [{ knots: [0, 1, 2] }, 'knots', 'too-few'],
  ],
  noisyData: [
    [{ curve: 'sine', count: 30, seed: -3 }, 'seed', 'out-of-range'],
    [{ curve: 'sine', count: 2 }, 'count', 'too-few', 3, 2],
    [{ curve: 'sine', count: 30, sigma: -1 }, 'sigma', 'out-of-range'],
  ],
  dataset: [[{ name: 'nope' }, 'name', 'invalid']],
  b2Fit: [[{ points: [[0, 0, 0], [1, 1, 1], [2, 0, 0], [3, 1, 1]] }, 'points', 'incompatible']],
  b2FitSweep: [[{ points: pts2(15), aMin: 0.2, aMax: 0.1 }, 'aMax', 'out-of-range']],
  splineBlendedSurface: [
    [{ network: (u, v) => [u, v, u * v], uKnots: [0, 0.5, 1], vKnots: [0, 0.3, 1], blend: 'cubic' }, 'blend', 'invalid'],
    [{ network: (u, v) => [u, v, u * v], uKnots: [0, 0.5, 1], vKnots: [0, 0.3, 1], blend: 3 }, 'blend', 'wrong-type'],
    [{ network: (u, v) => [u, v, u * v], vKnots: [0, 0.3, 1] }, 'uKnots', 'missing'],
    [{ network: (u, v) => [u, v, u * v], uKnots: [0, 0.5, 1], vKnots: [0, 0.3, 1] }, 'uKnots', 'too-few'],
  ],
  bezierRemodel: [[{ points: pts2(5), degree: 2, breaks: [0, 1, 2], alphas: [[0.5, 0.5]], r: 1 }, 'alphas', 'incompatible']],
  bezierSpline: [
    [{ points: pts2(7), degree: 0, breaks: [0, 1, 2] }, 'degree', 'out-of-range'],
    [{ points: pts2(7), degree: 3, breaks: [0, 2, 1] }, 'breaks[2]', 'not-increasing'],
  ],
  bsplineToBezier: [[{ degree: 3, knots: [0, 0, 0, 0, 0.5, 1, 1, 1, 1], points: 'abc' }, 'points', 'wrong-type']],
  bezierRemodelSurface: [[{ points: grid(3, 2, (k, l) => [k, l, k * l]), degreeU: 2, degreeV: 1, breaksU: [0, 1], alphas: [[2, 1 / 3]], r: 1 }, /^alphas/, 'out-of-range']],
  bezierRemodelSurfaceBi: [[{ points: grid(3, 3, (k, l) => [k, l, k * l]), r: 7 }, 'r', 'out-of-range']],
  crissCrossSurface: [
    [{ network: withNet((n) => { n.P[1][1][2] = NaN; }) }, /^network\.P\[1\]\[1\]/, 'not-finite'],
    [{ network: withNet((n) => { n.P[1][1][2] += 0.5; }) }, 'network', 'incompatible'],
    [{ network: withNet((n) => { n.u = [0]; }) }, 'network.u', 'too-few', 2, 1],
    // the order of the checks (the options are read in their declared order, C11 and evaluate once the network
    // is known compatible, the sampling last)
    [{ network: withNet((n) => { n.P[1][1][2] += 0.5; }), C11: 'x', evaluate: 'x', samplesU: -1 }, 'network', 'incompatible'],
    [{ network: net(), tolerance: -1, C11: 'x' }, 'tolerance', 'out-of-range'],
    [{ network: net(), C11: 'x', evaluate: 'x', samplesU: -1 }, 'C11', 'wrong-type'],
    [{ network: net(), C11: [1, 2], evaluate: 'x' }, 'C11', 'wrong-type'],
    [{ network: net(), evaluate: 'x', samplesU: -1 }, 'evaluate', 'invalid'],
  ],
  crissCrossBasis: [
    [{ u: [0, 0.5, 1], v: [0, 0.5, 1], j: 1 }, 'i', 'missing'],
    [{ u: [0, 0.5, 1], v: [0, 0.5, 1], i: 4, j: 'x' }, 'i', 'too-many', 3, 4],
    [{ u: [0, 0.5, 1], v: 'x', i: 'x' }, 'v', 'wrong-type'],
  ],
  crissCrossCells: [
    [{ u: [0, 2, 1], v: [0, 1, 2], i: 1, j: 1 }, /^u/, 'not-increasing'],
    // with a network, u, v, i and j are not read; without, tolerance is not
    [{ network: net(), tolerance: -1, u: 'x', i: 'x' }, 'tolerance', 'out-of-range'],
    [{ u: [0, 1], v: [0, 1], i: 'x', tolerance: -1 }, 'i', 'wrong-type'],
  ],
  thinPlateSurface: [[{}, 'network', 'missing']],
  gordonSurface: [
    [{ network: net(), samplesU: 1e9 }, 'samplesU', 'too-many'],
    [{ network: net(), samplesU: 2.5 }, 'samplesU', 'out-of-range'],
  ],
  surfaceDifferences: [[{ network: net(), samples: 1 }, 'samples', 'too-few']],
  networkSurfaces: [[{ network: net(), surfaces: ['S', 'X'] }, 'surfaces[1]', 'invalid']],
  exerciseCheck: [
    [{ check: 'teleport', tol: 1 }, 'check', 'invalid'],
    [{ check: 'dataDistance', data: [[0, 0]], curve: { degree: 2, breaks: [0, 1], controlPoints: pts2(3) } }, 'tol', 'missing'],
    [{ check: 'dataDistance', tol: -1, data: [[0, 0]], curve: { degree: 2, breaks: [0, 1], controlPoints: pts2(3) } }, 'tol', 'out-of-range'],
    [{ check: 'dataDistance', tol: 1, data: [[0, 0]], curve: { degree: 2, breaks: [0, 1], controlPoints: pts2(4) } }, 'curve.controlPoints', 'incompatible'],
    [{ check: 'dataDistance', tol: 1, data: [[0, 0]], curve: { degree: 2, breaks: [0, 2, 1], controlPoints: pts2(5) } }, 'curve.breaks[2]', 'not-increasing'],
    [{ check: 'continuity', tol: 1, at: 0.3, curve: { degree: 2, breaks: [0, 1, 2], controlPoints: pts2(5) } }, 'at', 'out-of-range'],
    [{ check: 'dataDistance', tol: 1, data: [[0, 0]] }, 'curve', 'missing'],
    [{ check: 'networkNorm', tol: 1, network: net(), pair: 'SX' }, 'pair', 'invalid'],
    [{ check: 'envelopePoint', tol: 1, curve: curveK(), p: 5, up: 2, target: [0, NaN] }, /^target/, 'not-finite'],
  ],
  networkFromFunction: [
    [{ u: [0, 0.4, 1], v: [0, 0.5, 1], f: (u, v) => [u, v] }, 'f', 'wrong-type'],
    [{ u: [0, 0.4, 1], v: [0, 0.5, 1], f: (u, v) => [u, v, NaN] }, 'f', 'not-finite'],
    [{ u: [0, 0.4, 1], v: [0, 0.5, 1], f: () => { throw new Error('boom'); } }, 'f', 'invalid'],
    [{ u: [0, 0.4, 1], v: [0, 0.5, 1], f: 3 }, 'f', 'wrong-type'],
  ],
  networkFromControlNet: [[{ u: [0, 1, 2], v: [0, 1], C: grid(3, 3, (i, j) => [i, j, 0]) }, /^C/, 'incompatible']],
  networkFromFreeData: [[{ u: [0, 1, 2], v: [0, 1] }, 'P', 'missing']],
  networkRepair: [
    [{ network: net(), edited: { kind: 'Z' } }, 'edited', 'invalid'],
    // flat curves (issue 13): a curve one number short, NaN in a flat curve, a curve of the wrong type
    [{ network: flatNet((n) => { n.P[2] = n.P[2].subarray(1); }) }, 'network.P[2]', 'incompatible'],
    [{ network: flatNet((n) => { n.Q[1][5] = NaN; }) }, 'network.Q[1][1][2]', 'not-finite'],
    [{ network: flatNet((n) => { n.P[0] = new Float32Array(12); }) }, 'network.P[0]', 'wrong-type'],
  ],
  networkCompatibility: [
    [{ network: net(), tolerance: -1 }, 'tolerance', 'out-of-range'],
    // a whole flat table of the wrong length, a plain flat curve with a string in it
    [{ network: withNet((n) => { n.Q = Float64Array.from(n.Q.flat(2)).subarray(0, 10); }) }, 'network.Q', 'incompatible'],
    [{ network: withNet((n) => { n.P[1] = [...n.P[1].flat().slice(0, 5), 'x']; }) }, 'network.P[1]', 'wrong-type'],
  ],
  networkExample: [[{ name: 'teapot' }, 'name', 'invalid']],
  knotModifiedSurface: [[{ surface: surf({ knotsU: [0, 0, 0, 1, 2, 2] }), p: 3, up: 1.5 }, /^surface\./, 'incompatible']],
  knotEnvelope: [[{ surface: surf(), p: 3, q: 3, samplesU: -2 }, 'samplesU', 'out-of-range']],
  knotPaths: [
    [{ surface: surf(), p: 3, points: [[0.5]] }, 'points[0]', 'wrong-type'],
    [{ surface: surf(), p: 3, points: [[0.5, 0.5]], from: 0.5, to: 1.5, samples: 0 }, 'samples', 'too-few'],
  ],
  knotModifiedCurve: [[{ curve: curveK({ order: 1 }), p: 5, up: 1.7 }, 'curve.order', 'out-of-range']],
  knotEnvelopeCurve: [[{ curve: curveK() }, 'p', 'missing']],
  knotPathsCurve: [[{ curve: curveK(), p: 5 }, 'params', 'missing']],
  knotLimits: [[{ curve: curveK() }, 'p', 'missing']],
  curveFacts: [
    [{ points: [[0, 0]] }, 'points', 'too-few'],
    [{ points: [[0, 0], [1, 1], [2, 0]], params: [0, 1] }, 'params', 'incompatible'],
    [{ points: [[0, 0], [1, 1], [2, 0]], params: [0, 2, 1] }, 'params[2]', 'not-increasing'],
    [{ points: [[0, 0, 0], [1, 1, 1]] }, 'points', 'invalid'],
    [{ points: [[0, 0], [1, 1]], data: [[0, NaN]] }, 'data[0][1]', 'not-finite'],
  ],
  knotDeBoorCurve: [[{ curve: curveK(), p: 5, up: 2.5 }, 'u', 'missing'], [{ curve: curveK(), p: 5, up: 2.5, u: 7 }, 'u', 'out-of-range']],
};

const SKIP = new Set(['initSync', 'default', 'version', '__wbg_init']);
const exported = Object.keys(sl).filter((k) => typeof sl[k] === 'function' && !SKIP.has(k) && !/^[A-Z]/.test(k));

function thrown(fn) {
  try { fn(); } catch (e) { return e; }
  return undefined;
}

// exports that take no input and cannot fail
const CANNOT_FAIL = new Set(['fitNames']);

test('every export has at least one bad-input case here', () => {
  assert.ok(exported.length >= 40, `found ${exported.length} exports`);
  const missing = exported.filter((k) => !CASES[k] && !CANNOT_FAIL.has(k));
  assert.deepEqual(missing, [], 'exports without an error case');
});

for (const [name, cases] of Object.entries(CASES)) {
  test(`${name}: a bad input throws an Error with .field and .kind`, () => {
    assert.equal(typeof sl[name], 'function', `${name} is exported`);
    for (const [opts, field, kind, expected, got] of cases) {
      const e = thrown(() => sl[name](opts));
      const what = `${name}(${JSON.stringify(opts, (k, v) => (typeof v === 'function' ? String(v) : v))?.slice(0, 120)})`;
      assert.ok(e instanceof Error && !(e instanceof WebAssembly.RuntimeError), `${what} throws an Error (got ${e})`);
      assert.ok(KINDS.has(e.kind), `${what}: .kind ${JSON.stringify(e.kind)} is a documented kind (${e.message})`);
      assert.equal(typeof e.field, 'string', `${what}: .field is a string`);
      // the message keeps the "<field>: <detail>" form, with the same field
      assert.ok(e.message.startsWith(`${e.field}: `), `${what}: message ${JSON.stringify(e.message)} starts with .field ${e.field}`);
      if (field instanceof RegExp) assert.match(e.field, field, `${what}: .field (${e.message})`);
      else assert.equal(e.field, field, `${what}: .field (${e.message})`);
      assert.equal(e.kind, kind, `${what}: .kind (${e.message})`);
      // pages show the message as it is: indices typeset (W₋₁..Wₙ₊₂, α₁⁽²⁾), never raw (W_-1, α_1^(2))
      assert.deepEqual(rawIn(e.message.slice(e.field.length + 2)), [], `${what}: raw notation in ${JSON.stringify(e.message)}`);
      if (expected !== undefined) {
        assert.equal(e.expected, expected, `${what}: .expected`);
        assert.equal(e.got, got, `${what}: .got`);
      }
    }
  });
}

test('the error object is an ordinary Error (name, stack, message unchanged)', () => {
  const e = thrown(() => sl.bsplineCurve({ degree: 3, knots: [0, 0, 0, 0, 0.5, 1, 1, 1, 1], points: [[0, 0], [1, NaN], [2, 0], [3, 1], [4, 0]] }));
  assert.equal(e.name, 'Error');
  assert.equal(e.message, 'points[1][1]: expected a finite number, got NaN');
  assert.equal(typeof e.stack, 'string');
  // own, enumerable data properties: JSON.stringify(e) shows them
  assert.deepEqual(JSON.parse(JSON.stringify(e)), { field: 'points[1][1]', kind: 'not-finite' });
});
