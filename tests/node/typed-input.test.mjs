// Typed and flat input for grids (issue 13): rows of flat coordinates (Float64Array or plain numbers) give
// the same surfaces as nested [x, y, z] rows, read in one copy per row; bad rows name their field and kind.
//   scripts/build-wasm.sh && node --test tests/node/typed-input.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';

const require = createRequire(import.meta.url);
const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const sl = require(join(root, 'pkg-node/splinelab.js'));

const rows = 7, cols = 6;
const nested = Array.from({ length: rows }, (_, i) =>
  Array.from({ length: cols }, (_, j) => [i, j, Math.sin(i + 2 * j) + 0.1 * i * j]));
const flatRows = nested.map((r) => Float64Array.from(r.flat()));
const plainRows = nested.map((r) => r.flat());

const same = (a, b, what) => {
  assert.equal(a.length, b.length, what);
  for (let i = 0; i < a.length; i++) assert.equal(a[i], b[i], `${what}[${i}]`);
};

test('grids as rows of flat coordinates equal nested grids', () => {
  for (const [name, call] of [
    ['quasiCubicSurface', (grid, extra) => sl.quasiCubicSurface({ grid, samplesU: 9, samplesV: 8, derivatives: 1, ...extra })],
    ['quasiCubicBlendedSurface', (grid, extra) => sl.quasiCubicBlendedSurface({ grid, samplesU: 9, samplesV: 8, derivatives: 1, ...extra })],
    ['b2Surface', (grid, extra) => sl.b2Surface({ grid, samplesU: 9, samplesV: 8, derivatives: 1, ...extra })],
  ]) {
    const ref = call(nested, {});
    for (const [kind, grid] of [['Float64Array rows', flatRows], ['plain number rows', plainRows]]) {
      const r = call(grid, { dim: 3 });
      for (const key of ['points', 'du', 'dv']) same(r[key], ref[key], `${name} ${kind} ${key}`);
      // dim defaults to 3 for a flat grid
      same(call(grid, {}).points, ref.points, `${name} ${kind} default dim`);
    }
  }
  // 2D grids with dim: 2
  const g2 = nested.map((r) => r.map(([x, , z]) => [x, z]));
  same(sl.quasiCubicSurface({ grid: g2.map((r) => Float64Array.from(r.flat())), dim: 2 }).points,
    sl.quasiCubicSurface({ grid: g2 }).points, '2D');
});

test('bad flat rows name the row and the kind', () => {
  const ragged = flatRows.slice();
  ragged[3] = ragged[3].subarray(0, 15);
  assert.throws(() => sl.quasiCubicSurface({ grid: ragged }), (e) => e.field === 'grid[3]' && e.kind === 'incompatible');
  const notMultiple = flatRows.slice();
  notMultiple[2] = notMultiple[2].subarray(0, 17);
  assert.throws(() => sl.quasiCubicSurface({ grid: notMultiple }), (e) => e.field === 'grid[2]' && e.kind === 'incompatible');
  const nan = flatRows.map((r) => r.slice());
  nan[1][4] = NaN;
  assert.throws(() => sl.quasiCubicSurface({ grid: nan }), (e) => e.field === 'grid[1][4]' && e.kind === 'not-finite');
  const mixed = flatRows.slice();
  mixed[5] = nested[5];
  assert.throws(() => sl.quasiCubicSurface({ grid: mixed }), (e) => e.field === 'grid[5]' && e.kind === 'wrong-type');
  assert.throws(() => sl.b2Surface({ grid: flatRows.slice(0, 3) }), (e) => e.field === 'grid' && e.kind === 'too-few');
  assert.throws(() => sl.quasiCubicSurface({ grid: flatRows, dim: 1 }), (e) => e.field === 'dim' && e.kind === 'out-of-range');
});
