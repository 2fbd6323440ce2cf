// The shared parser of "Use my data" (www/lib/data-import.js): points, grids and networks from CSV and JSON,
// good rows and bad rows (errors name the row and what was wrong).
//
//   node --test tests/node/data-import.test.mjs

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { parsePoints, parseGrid, parseNetwork, parseData, DataError } from '../../www/lib/data-import.js';

const throwsWith = (fn, re, extra = {}) => assert.throws(fn, (e) => {
  assert.ok(e instanceof DataError, `a DataError, got ${e}`);
  assert.equal(e.field, 'data');
  assert.match(e.message, re);
  for (const [k, v] of Object.entries(extra)) assert.equal(e[k], v, k);
  return true;
});

test('points: CSV with commas, a header line, blank and comment lines', () => {
  assert.deepEqual(parsePoints('x,y\n0,0\n\n# a comment\n1.5, -2\n3e-1,4E2\n'), [[0, 0], [1.5, -2], [0.3, 400]]);
});

test('points: tabs, spaces, semicolons (with decimal commas), CRLF', () => {
  assert.deepEqual(parsePoints('1\t2\r\n3   4\r\n'), [[1, 2], [3, 4]]);
  assert.deepEqual(parsePoints('x;y\n1,5; 2,25\n-0,5;3\n'), [[1.5, 2.25], [-0.5, 3]]);
  assert.deepEqual(parsePoints('1;2\n3;4'), [[1, 2], [3, 4]]);
});

test('points: numbers read back exactly', () => {
  const xs = [0.1 + 0.2, Math.PI, -1e-300, 123456789.123456789, 5e-324];
  const pts = parsePoints(xs.map((x) => `${x}, ${-x}`).join('\n'));
  assert.deepEqual(pts, xs.map((x) => [x, -x]));
});

test('points: JSON [[x, y]], [{x, y}], { points }', () => {
  assert.deepEqual(parsePoints('[[0, 1], [2, 3]]'), [[0, 1], [2, 3]]);
  assert.deepEqual(parsePoints('[{"x": 0, "y": 1}, {"x": 2, "y": 3}]'), [[0, 1], [2, 3]]);
  assert.deepEqual(parsePoints('{"points": [[0, 1], [2, 3]]}'), [[0, 1], [2, 3]]);
  assert.deepEqual(parsePoints('[[0, 1, 2]]', { dims: [3] }), [[0, 1, 2]]);
});

test('points: a bad row names the row and the text', () => {
  throwsWith(() => parsePoints('x,y\n1,2\nabc\n'), /^row 3: expected 2 numbers, got 'abc'$/, { row: 3, kind: 'wrong-type' });
  throwsWith(() => parsePoints('1,2\n3,oops\n'), /^row 2: expected 2 numbers, got 'oops' in '3 oops'$/, { row: 2 });
  throwsWith(() => parsePoints('1,2\n3,4,5\n'), /^row 2: expected 2 numbers, got 3 \('3 4 5'\)$/, { row: 2, kind: 'incompatible' });
  throwsWith(() => parsePoints('1,2\n3\n'), /^row 2: expected 2 numbers, got 1/, { row: 2 });
  throwsWith(() => parsePoints('1,2\n0x10,4\n'), /row 2: .*got '0x10'/);
  throwsWith(() => parsePoints('1,2\nInfinity,4\n'), /row 2: .*got 'Infinity'/);
  throwsWith(() => parsePoints('1,2\nNaN,4\n'), /row 2: .*got 'NaN'/);
  // the first row fixes the dimension when 2 or 3 are allowed
  assert.deepEqual(parsePoints('1 2 3\n4 5 6', { dims: [2, 3] }), [[1, 2, 3], [4, 5, 6]]);
  throwsWith(() => parsePoints('1 2 3\n4 5', { dims: [2, 3] }), /^row 2: expected 3 numbers, got 2/);
});

test('points: bad JSON, bad items, counts', () => {
  throwsWith(() => parsePoints('[[0, 1], [2, 3]'), /^JSON/, { kind: 'invalid' });
  throwsWith(() => parsePoints('[[0, 1], [2, "a"]]'), /^item 2: expected a finite number at \[1\], got "a"$/);
  throwsWith(() => parsePoints('[[0, 1], [2]]'), /^item 2: expected \[x, y\], got 1 numbers$/);
  throwsWith(() => parsePoints('[{"x": 0}]'), /^item 1: expected \{x, y\}/);
  throwsWith(() => parsePoints('{"a": 1}'), /^JSON: expected an array of points/);
  throwsWith(() => parsePoints('1,2\n3,4', { min: 4 }), /^need at least 4 points, got 2$/, { kind: 'too-few' });
  throwsWith(() => parsePoints('1,2\n3,4\n5,6', { max: 2 }), /^at most 2 points, got 3$/, { kind: 'too-many' });
  throwsWith(() => parsePoints('   \n'), /^no data/, { kind: 'missing' });
  throwsWith(() => parsePoints(42), /expected text/);
});

test('grid: JSON nested points, JSON heights, CSV blocks, CSV heights', () => {
  const g = [[[0, 0, 1], [0, 1, 2]], [[1, 0, 3], [1, 1, 4]]];
  assert.deepEqual(parseGrid(JSON.stringify(g)), g);
  assert.deepEqual(parseGrid(JSON.stringify({ grid: g })), g);
  assert.deepEqual(parseGrid('[[1, 2], [3, 4]]'), g);
  assert.deepEqual(parseGrid('x y z\n0 0 1\n0 1 2\n\n1 0 3\n1 1 4\n'), g);
  assert.deepEqual(parseGrid('1, 2\n3, 4\n'), g);
  assert.deepEqual(parseData('1, 2\n3, 4\n', 'grid'), g);
});

test('grid: bad rows, ragged rows, too small', () => {
  throwsWith(() => parseGrid('0 0 1\n0 1 2\n\n1 0 x\n1 1 4\n'), /^row 4: expected 3 numbers, got 'x'/, { row: 4 });
  throwsWith(() => parseGrid('0 0 1\n0 1 2\n\n1 0 3\n'), /^grid row 2 has 1 point, row 1 has 2/, { kind: 'incompatible' });
  throwsWith(() => parseGrid('0 0 1\n0 1 2\n1 0 3\n1 1 4\n'), /blank line between grid rows/);
  throwsWith(() => parseGrid('[[[0, 0, 1], [0, 1]]]'), /^grid\[0\]\[1\]: expected \[x, y, z\], got 2 numbers$/);
  throwsWith(() => parseGrid('[[1, 2], [3]]'), /^grid row 2 has 1 point, row 1 has 2/);
  throwsWith(() => parseGrid('[[1, 2], [3, 4]]', { min: [4, 4] }), /^need a grid of at least 4 × 4 points, got 2 × 2$/, { kind: 'too-few' });
  throwsWith(() => parseGrid('1 2 3 4\n5 6 x 8'), /^row 2: expected 4 numbers, got 'x'/);
});

test('network: a network from the API reads back; shapes are checked with names', () => {
  const require = createRequire(import.meta.url);
  const sl = require('../../pkg-node/splinelab.js');
  const net = sl.networkFromFunction({ u: [0, 0.5, 1], v: [0, 0.25, 0.75, 1], f: (u, v) => [u, v, u * v] });
  const plain = JSON.parse(JSON.stringify(net));
  assert.deepEqual(parseNetwork(JSON.stringify(plain)), plain);
  assert.deepEqual(parseNetwork(JSON.stringify({ network: plain })), plain);
  assert.deepEqual(parseNetwork(JSON.stringify({ splinelab: 1, demo: 'curve-networks', computed: { network: plain } })), plain);
  // the parsed network is accepted by the API
  assert.equal(sl.networkCompatibility({ network: parseNetwork(JSON.stringify(plain)) }).compatible, true);
  const bad = (f) => { const n = JSON.parse(JSON.stringify(plain)); f(n); return JSON.stringify(n); };
  throwsWith(() => parseNetwork(bad((n) => { delete n.Q; })), /^Q is required/, { kind: 'missing' });
  throwsWith(() => parseNetwork(bad((n) => { n.u[1] = 2; })), /^u: must increase, but u\[2\] = 1 ≤ u\[1\] = 2$/);
  throwsWith(() => parseNetwork(bad((n) => { n.P.pop(); })), /^P: expected 3 curves \(one per u_r\), got 2$/);
  throwsWith(() => parseNetwork(bad((n) => { n.P[1].pop(); })), /^P\[1\]: expected 5 points/);
  throwsWith(() => parseNetwork(bad((n) => { n.Q[2][1] = [0, 'a', 0]; })), /^Q\[2\]\[1\]: expected a finite number at \[1\], got "a"$/);
  throwsWith(() => parseNetwork('1, 2\n3, 4'), /is JSON/);
});
