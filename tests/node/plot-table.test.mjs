// The table view's data (www/lib/plot2d/table.js, issue 25): the rows it takes from a curve or basis result, and
// the CSV a person copies. Numbers, not the page: tests/e2e/a11y.test.mjs opens the tables on the pages.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { evenIndices, evenParams, curveSection, basisSection, tableCsv } from '../../www/lib/plot2d/table.js';

test('evenIndices: first and last included, evenly spread, all of a short list', () => {
  assert.deepEqual(evenIndices(401, 11), [0, 40, 80, 120, 160, 200, 240, 280, 320, 360, 400]);
  assert.deepEqual(evenIndices(5, 11), [0, 1, 2, 3, 4]);
  assert.deepEqual(evenIndices(0, 11), []);
});

test('curveSection: [u, x, y] of the drawn samples, at the parameter values they were drawn at', () => {
  // the line C(u) = (2u, 1 − u), 401 samples on [0, 1]
  const params = Float64Array.from({ length: 401 }, (_, i) => i / 400);
  const points = new Float64Array(802);
  params.forEach((u, i) => { points[2 * i] = 2 * u; points[2 * i + 1] = 1 - u; });
  const s = curveSection('C(u)', { params, points });
  assert.deepEqual(s.columns, ['u', 'x', 'y']);
  assert.equal(s.rows.length, 11);
  for (const [u, x, y] of s.rows) { assert.ok(Math.abs(x - 2 * u) < 1e-15 && Math.abs(y - (1 - u)) < 1e-15, `C(${u}) = (${x}, ${y})`); }
  assert.deepEqual(s.rows[5], [0.5, 1, 0.5]);
});

test('basisSection: one column per function, values[j · count + i] = Bᵢ(params[j])', () => {
  // the linear Bernstein basis 1 − u, u at 3 parameters
  const s = basisSection('B', [0, 0.5, 1], [1, 0, 0.5, 0.5, 0, 1], ['B₀', 'B₁']);
  assert.deepEqual(s.columns, ['u', 'B₀', 'B₁']);
  assert.deepEqual(s.rows, [[0, 1, 0], [0.5, 0.5, 0.5], [1, 0, 1]]);
});

test('evenParams: the parameters of a table, the last one exactly the end', () => {
  assert.deepEqual(evenParams(0, 1, 5), [0, 0.25, 0.5, 0.75, 1]);
  const u = evenParams(0, 3, 7);
  assert.equal(u.length, 7);
  assert.equal(u[6], 3);
  assert.ok(Math.abs(u[3] - 1.5) < 1e-15);
});

test('tableCsv: a title line and a header per section, quoted text, plain numbers', () => {
  const csv = tableCsv([
    { title: 'Points (2)', columns: ['point', 'x', 'y'], rows: [['Control point P₀', -0.5, 1 / 3], ['a "b", c', 2, 0]] },
    { title: 'C(u)', columns: ['u', 'x', 'y'], rows: [[0, 1e-9, 2]] },
  ]);
  assert.equal(csv, 'Points (2)\npoint,x,y\nControl point P₀,-0.5,0.333333\n"a ""b"", c",2,0\n\nC(u)\nu,x,y\n0,0,2');
});
