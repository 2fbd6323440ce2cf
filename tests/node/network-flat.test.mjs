// Typed and flat input for curve networks (issue 13): every export that reads a network `{ u, v, P, Q }` gives
// bit-for-bit the same result when each curve P[r] / Q[s] is flat coordinates (a Float64Array or a plain array of
// numbers), when P and Q are whole flat tables (r-major), and when u, v are Float64Arrays; bad flat input names its
// field and kind.
//   scripts/build-wasm.sh && node --test tests/node/network-flat.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';

const require = createRequire(import.meta.url);
const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const sl = require(join(root, 'pkg-node/splinelab.js'));

/** The forms of one network: nested (as networkExample returns it) and its flat variants. */
function forms(net) {
  const rowsTyped = (t) => t.map((r) => Float64Array.from(r.flat()));
  const rowsPlain = (t) => t.map((r) => r.flat());
  return {
    'Float64Array curves': { ...net, P: rowsTyped(net.P), Q: rowsTyped(net.Q) },
    'plain flat curves': { ...net, P: rowsPlain(net.P), Q: rowsPlain(net.Q) },
    'whole flat tables (Float64Array)': {
      u: Float64Array.from(net.u), v: Float64Array.from(net.v),
      P: Float64Array.from(net.P.flat(2)), Q: Float64Array.from(net.Q.flat(2)),
    },
    'whole flat tables (plain)': { ...net, P: net.P.flat(2), Q: net.Q.flat(2) },
    'mixed rows': { ...net, P: net.P.map((r, i) => (i % 2 ? Float64Array.from(r.flat()) : r)), Q: net.Q },
  };
}

/** Deep equality with numbers compared bit for bit (Object.is), typed arrays element by element. */
function sameBits(a, b, path) {
  if (typeof a === 'number') {
    assert.ok(Object.is(a, b), `${path}: ${a} vs ${b}`);
    return;
  }
  if (a === null || typeof a !== 'object') {
    assert.equal(a, b, path);
    return;
  }
  if (ArrayBuffer.isView(a) || Array.isArray(a)) {
    assert.equal(a.length, b.length, `${path}.length`);
    for (let i = 0; i < a.length; i++) sameBits(a[i], b[i], `${path}[${i}]`);
    return;
  }
  assert.deepEqual(Object.keys(a).sort(), Object.keys(b).sort(), `${path} keys`);
  for (const k of Object.keys(a)) sameBits(a[k], b[k], `${path}.${k}`);
}

const grid = { samplesU: 9, samplesV: 7 };
// every export that reads a network, with the options that exercise it
const CALLS = {
  networkCompatibility: (network) => sl.networkCompatibility({ network }),
  networkRepair: (network) => sl.networkRepair({ network, edited: { kind: 'P', r: 1, j: 2 } }),
  crissCrossSurface: (network) => sl.crissCrossSurface({ network, ...grid, derivatives: 1, mesh: true }),
  crissCrossCells: (network) => sl.crissCrossCells({ network }),
  thinPlateSurface: (network) => sl.thinPlateSurface({ network, ...grid, derivatives: 1 }),
  gordonSurface: (network) => sl.gordonSurface({ network, ...grid, derivatives: 1, components: true }),
  splineBlendedSurface: (network) => sl.splineBlendedSurface({ network, blend: 'cubic-natural', ...grid, derivatives: 1 }),
  networkSurfaces: (network) => sl.networkSurfaces({ network, ...grid, colorBy: 'SG', components: true, curveSamples: 9, normSamples: 9 }),
  surfaceDifferences: (network) => sl.surfaceDifferences({ network, samples: 9 }),
  exerciseCheck: (network) => sl.exerciseCheck({ check: 'networkNorm', tol: 1, network, pair: 'SG', normSamples: 9, answer: 0 }),
};

test('flat and typed networks give the same results as nested ones, bit for bit', () => {
  let compared = 0;
  for (const name of ['uniform-dome', 'nonuniform-dome', 'three-sided', 'strongly-nonuniform']) {
    const nested = sl.networkExample({ name });
    for (const [exp, call] of Object.entries(CALLS)) {
      const ref = call(nested);
      for (const [form, net] of Object.entries(forms(nested))) {
        sameBits(call(net), ref, `${name} ${exp} ${form}`);
        compared++;
      }
    }
  }
  assert.equal(compared, 4 * Object.keys(CALLS).length * 5);
});

test('networkFromControlNet and networkFromFreeData read flat tables and rows', () => {
  const u = [0, 0.4, 1], v = [0, 0.3, 0.7, 1];
  const C = Array.from({ length: u.length + 1 }, (_, i) => Array.from({ length: v.length + 1 }, (_, j) => [i, j, Math.sin(i * j)]));
  const ref = sl.networkFromControlNet({ u, v, C });
  sameBits(sl.networkFromControlNet({ u, v, C: Float64Array.from(C.flat(2)) }), ref, 'C whole flat');
  sameBits(sl.networkFromControlNet({ u: Float64Array.from(u), v, C: C.map((r) => Float64Array.from(r.flat())) }), ref, 'C rows');
  const P = ref.P, Q1 = ref.Q.map((row) => row[1]);
  const free = sl.networkFromFreeData({ u, v, P, Q1 });
  sameBits(sl.networkFromFreeData({ u, v, P: Float64Array.from(P.flat(2)), Q1: Float64Array.from(Q1.flat()) }), free, 'free data flat');
  sameBits(sl.networkFromFreeData({ u, v, P: P.map((r) => r.flat()), Q1: Q1.flat() }), free, 'free data plain flat');
});

test('bad flat networks name the field and kind', () => {
  const net = sl.networkExample({ name: 'uniform-dome' });
  const rows = (t) => t.map((r) => Float64Array.from(r.flat()));
  const flat = () => ({ ...net, P: rows(net.P), Q: rows(net.Q) });
  const cases = [
    // a curve one number short: not whole points
    [(n) => { n.P[2] = n.P[2].subarray(1); }, 'network.P[2]', 'incompatible'],
    // a curve one point short
    [(n) => { n.Q[1] = n.Q[1].subarray(3); }, 'network.Q[1]', 'incompatible'],
    // NaN in the second point's y: named like the nested form
    [(n) => { n.P[2][4] = NaN; }, 'network.P[2][1][1]', 'not-finite'],
    [(n) => { n.Q[0][0] = Infinity; }, 'network.Q[0][0][0]', 'not-finite'],
    // wrong types: a string, a Float32Array, a whole table of the wrong length
    [(n) => { n.P[0] = 'abc'; }, 'network.P[0]', 'wrong-type'],
    [(n) => { n.P[3] = Float32Array.from(n.P[3]); }, 'network.P[3]', 'wrong-type'],
    [(n) => { n.P = Float64Array.from(net.P.flat(2)).subarray(3); }, 'network.P', 'incompatible'],
    [(n) => { n.Q = 7; }, 'network.Q', 'wrong-type'],
    [(n) => { n.u = Float64Array.of(0, NaN, 1, 2, 3, 4); }, 'network.u[1]', 'not-finite'],
    [(n) => { n.v = 'x'; }, 'network.v', 'wrong-type'],
  ];
  for (const [edit, field, kind] of cases) {
    const n = flat();
    edit(n);
    for (const call of [CALLS.networkCompatibility, CALLS.crissCrossSurface, CALLS.gordonSurface]) {
      assert.throws(() => call(n), (e) => {
        assert.ok(e instanceof Error, 'an Error');
        assert.equal(e.field, field, e.message);
        assert.equal(e.kind, kind, `${field}: ${e.message}`);
        assert.ok(e.message.startsWith(e.field), e.message);
        return true;
      }, `${field} ${kind}`);
    }
  }
});
