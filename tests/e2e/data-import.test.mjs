// "Use my data" in the real page: pasted points in a curve demo, a pasted grid in a surface demo, a pasted network
// in the curve-network demo, a chosen file, and bad rows that show the parser's error (the view keeps its data).
// What the page then computes is checked against the API in Node (through the demo's "Copy as code").
//
//   node --test --test-concurrency=1 tests/e2e/data-import.test.mjs

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { startHarness, ROOT } from './harness.mjs';

const require = createRequire(import.meta.url);
const sl = require(join(ROOT, 'pkg-node/splinelab.js'));

let H;
before(async () => { H = await startHarness(); });
after(() => H?.close());

async function openDemo(id) {
  const t = await H.open(`#${id}`, { waitFor: '.export-bar .snippet-bar[data-ready="true"]' });
  await t.page.click('.data-import > summary');
  return t;
}
async function paste(t, text) {
  await t.page.fill('.data-import textarea', text);
  await t.page.click('.data-import [data-action="apply-data"]');
  await t.frames(3);
}
async function exported(t) {
  // (the Export row's writers load lazily: wait until the row has recorded the file)
  const before = await t.page.$eval('.export-bar', (r) => Number(r.dataset.exported || 0));
  await t.page.click('.export-bar button[data-format="json"]');
  await t.page.waitForFunction((n) => Number(document.querySelector('.export-bar').dataset.exported || 0) > n, before, { timeout: 15000 });
  return JSON.parse(await t.page.$eval('.export-bar', (row) => row.lastExport.text));
}
async function snippetResult(t) {
  await t.page.click('.export-bar button[data-format="code"]');
  const code = await t.page.$eval('.export-bar .snippet-bar', (el) => el.lastSnippet);
  return { code, result: new Function('sl', code)(sl) };
}
const errorText = (t) => t.page.$eval('.data-import .data-import-error', (e) => (e.hidden ? '' : e.textContent));
function close(a, b, what) {
  const x = Array.from(a).flat(3), y = Array.from(b).flat(3);
  assert.equal(x.length, y.length, `${what}: lengths`);
  for (let i = 0; i < x.length; i++) assert.ok(Math.abs(x[i] - y[i]) <= 1e-12 * Math.max(1, Math.abs(x[i])), `${what}[${i}]: ${x[i]} vs ${y[i]}`);
}

test('curve: pasted control points (CSV with a header) drive bspline-basics; a bad row shows its error', async () => {
  const t = await openDemo('bspline-basics');
  const h0 = await t.canvasHash();
  await paste(t, 'x;y\n0;0\n1,5;3\n3;3,5\n4;0\n6;1\n');
  let doc = await exported(t);
  assert.deepEqual(doc.state.points, [[0, 0], [1.5, 3], [3, 3.5], [4, 0], [6, 1]]);
  assert.equal(doc.state.knots.length, 5 + doc.state.degree + 1, 'clamped knots for 5 points');
  assert.match(await t.page.textContent('.data-import .data-import-ok'), /Using your 5 points/);
  assert.notEqual(await t.canvasHash(), h0, 'the drawing changed');
  // the page computed the curve of these points: its samples agree with the API in Node
  const { code, result } = await snippetResult(t);
  assert.ok(code.includes('[[0, 0], [1.5, 3], [3, 3.5], [4, 0], [6, 1]]'), 'the snippet holds the pasted points');
  close(doc.computed.samples.points, result.curve.points, 'samples');
  assert.deepEqual(doc.computed.samples.points.slice(0, 2), [0, 0], 'clamped: the curve starts at the first point');
  // a bad row: the error names it, nothing changes
  const h1 = await t.canvasHash();
  await paste(t, 'x,y\n0,0\nabc\n2,2\n');
  assert.equal(await errorText(t), "row 3: expected 2 numbers, got 'abc'");
  assert.equal(await t.page.$eval('.data-import textarea', (a) => a.getAttribute('aria-invalid')), 'true');
  doc = await exported(t);
  assert.equal(doc.state.points.length, 5, 'the previous data stay');
  assert.equal(await t.canvasHash(), h1);
  await paste(t, '[[0, 0], [1, 2], [2, "x"]]');
  assert.equal(await errorText(t), 'item 3: expected a finite number at [1], got "x"');
  t.assertClean();
  await t.close();
});

test('curve: a chosen file feeds interp-approx (data W₁…Wₙ, ends reflected)', async () => {
  const t = await openDemo('interp-approx');
  const pts = [[0, 0], [1, 1.5], [2.2, 1.8], [3, 0.2], [4.1, 0.4], [5, 2]];
  await t.page.setInputFiles('.data-import input[type="file"]', { name: 'mine.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(pts.map(([x, y]) => ({ x, y })))) });
  await t.page.waitForFunction(() => document.querySelector('.data-import').dataset.applied === '1');
  await t.frames(3);
  const doc = await exported(t);
  assert.deepEqual(doc.state.points.slice(2, -2), pts, 'W₁…Wₙ are the file\'s points');
  assert.equal(doc.state.autoEnds, true);
  const { result } = await snippetResult(t);
  close(doc.computed.samples.points, result.curve.points, 'samples');
  // at a = 0 the curve interpolates your data: its joints are exactly the file's points
  assert.equal(doc.state.a, 0);
  close(doc.computed.joints, pts, 'joints = data');
  t.assertClean();
  await t.close();
});

test('surface: a pasted grid (blank line between rows) drives b2-surfaces; ragged and small grids are refused', async () => {
  const t = await openDemo('b2-surfaces');
  const grid = Array.from({ length: 7 }, (_, i) => Array.from({ length: 6 }, (_, j) => [i, j, Math.round(10 * Math.sin(i + 2 * j)) / 10]));
  const csv = 'x y z\n' + grid.map((r) => r.map((p) => p.join(' ')).join('\n')).join('\n\n') + '\n';
  await paste(t, csv);
  assert.equal(await errorText(t), '');
  const doc = await exported(t);
  assert.deepEqual(doc.state.grid, grid);
  assert.deepEqual(doc.computed.grid, grid, 'the surface was built on your grid');
  const { result } = await snippetResult(t);
  close(doc.computed.surface.points, result.surface.points, 'surface points');
  await paste(t, '0 0 0\n0 1 0\n\n1 0 0\n');
  assert.match(await errorText(t), /^grid row 2 has 1 point, row 1 has 2/);
  await paste(t, '[[1, 2, 3, 4], [1, 2, 3, 4], [1, 2, 3, 4], [1, 2, 3, 4]]');
  assert.equal(await errorText(t), 'need a grid of at least 6 × 6 points, got 4 × 4');
  await paste(t, '1 2 3 4 5 6\n1 2 3 4 5 6\n1 2 3 x 5 6\n');
  assert.match(await errorText(t), /^row 3: expected 6 numbers, got 'x'/);
  assert.deepEqual((await exported(t)).state.grid, grid, 'the previous grid stays');
  t.assertClean();
  await t.close();
});

test('surface: a large grid is judged in the worker: the API\'s error names the field, the view keeps its data; a good one is drawn', async () => {
  const t = await openDemo('b2-surfaces');
  await t.page.getByText('chord', { exact: true }).click();
  await t.frames(3);
  const shown = () => t.page.$eval('.data-import', (b) => ({ checking: b.dataset.checking, ok: b.querySelector('.data-import-ok').textContent }));
  const settled = () => t.page.waitForFunction(() => document.querySelector('.data-import').dataset.checking === 'false', null, { timeout: 30000 });
  const before = await exported(t);
  // 30 × 30 coinciding points: parsed fine, refused by the API (chord-length knots need distinct grid lines); a
  // grid this large goes to the compute worker (www/lib/compute-client.js), so the answer comes later
  await paste(t, JSON.stringify(Array.from({ length: 30 }, () => Array.from({ length: 30 }, () => [0, 0, 0]))));
  await settled();
  assert.match(await errorText(t), /^knotsU: grid lines 0 and 1 coincide/);
  assert.equal((await shown()).ok, '', 'nothing says the grid is used');
  const kept = await exported(t);
  assert.deepEqual(kept.state.grid, before.state.grid, 'the previous grid stays');
  assert.deepEqual(kept.computed.surface.points, before.computed.surface.points, 'and its surface');
  const grid = Array.from({ length: 30 }, (_, i) => Array.from({ length: 30 }, (_, j) => [i, j, Math.round(10 * Math.sin(i / 4 + j / 5)) / 10 || 0]));
  await paste(t, JSON.stringify(grid));
  await settled();
  assert.equal(await errorText(t), '');
  assert.equal((await shown()).ok, 'Using your 30 × 30 grid.');
  await t.frames(3);
  const doc = await exported(t);
  assert.deepEqual(doc.state.grid, grid);
  const { result } = await snippetResult(t);
  close(doc.computed.surface.points, result.surface.points, 'surface points');
  t.assertClean();
  await t.close();
});

test('quasi-cubic-surfaces: a 32 × 32 net is computed in the worker and drawn as when computed on the page', async () => {
  const net = Array.from({ length: 32 }, (_, i) => Array.from({ length: 32 }, (_, j) => [i, j, Math.round(10 * Math.sin(i / 4) * Math.cos(j / 5)) / 10 || 0]));
  const C = 'canvas[data-plot="surface3d"]';
  /** Imports the net with the calls computed where `mode` says (www/lib/compute-client.js); the view's pixels, its
   * scene and the exported document. */
  async function imported(mode) {
    const context = await H.browser.newContext({ viewport: { width: 1280, height: 900 } });
    await context.addInitScript((m) => { window.splinelabCompute = m; }, mode);
    const t = await H.open('#quasi-cubic-surfaces', { context, waitFor: '.export-bar .snippet-bar[data-ready="true"]' });
    await t.page.click('.data-import > summary');
    await paste(t, JSON.stringify(net));
    await t.page.waitForFunction(() => document.querySelector('.data-import').dataset.checking !== 'true', null, { timeout: 30000 });
    assert.equal(await errorText(t), '');
    assert.match(await t.page.textContent('.data-import .data-import-ok'), /32 × 32/);
    await t.settled();
    await t.frames(4);
    const shown = await t.page.$eval(C, (c) => ({ png: c.view3d.toDataURL(), camera: JSON.stringify(c.view3d.getView()),
      objects: JSON.stringify([...c.view3d.objects].map(([id, o]) => [id, o.order, o.visible, o.positions?.length])) }));
    const doc = await exported(t);
    const { result } = await snippetResult(t);
    t.assertClean();
    await t.close(); await context.close();
    return { shown, doc, result };
  }
  const worker = await imported('worker');
  assert.equal(worker.doc.state.shape, 'grid');
  assert.deepEqual(worker.doc.state.grid, net);
  assert.deepEqual(worker.doc.computed.grid, net, 'the surface was built on your net');
  close(worker.doc.computed.samples.points, worker.result.surface.points, 'surface points');
  // drawn over two frames from the worker's result: the picture of the same import computed on the page at once
  const here = await imported('here');
  assert.equal(worker.shown.objects, here.shown.objects, 'the same objects, in the same drawing order');
  assert.equal(worker.shown.camera, here.shown.camera, 'framed the same');
  assert.ok(worker.shown.png === here.shown.png, 'the same pixels');
});

test('surface: a pasted height matrix is the control net of quasi-cubic-surfaces', async () => {
  const t = await openDemo('quasi-cubic-surfaces');
  await paste(t, '0 0 0 0 0\n0 1 2 1 0\n0 2 3 2 0\n0 1 2 1 0\n0 0 0 0 0\n');
  assert.equal(await errorText(t), '');
  const doc = await exported(t);
  assert.equal(doc.state.shape, 'grid');
  assert.deepEqual(doc.computed.grid[2][2], [2, 2, 3]);
  const { result } = await snippetResult(t);
  close(doc.computed.samples.points, result.surface.points, 'surface points');
  t.assertClean();
  await t.close();
});

test('network: a pasted network (JSON) drives curve-networks; a wrong shape names the field', async () => {
  const t = await openDemo('curve-networks');
  const net = JSON.parse(JSON.stringify(sl.networkFromFunction({ u: [0, 0.3, 0.7, 1], v: [0, 0.25, 0.5, 0.75, 1], f: (u, v) => [u, v, Math.sin(2 * u) * Math.cos(v) + 0.2 * u * v] })));
  await paste(t, JSON.stringify(net));
  assert.equal(await errorText(t), '');
  assert.match(await t.page.textContent('.data-import .data-import-ok'), /network of 4 × 5 curves/);
  const doc = await exported(t);
  close(doc.computed.network.P, net.P, 'P');
  assert.deepEqual(doc.computed.network.u, net.u);
  const { result } = await snippetResult(t);
  close(doc.computed.norms.SG, result.norms.SG, 'norm S−G');
  close(doc.computed.network.Q, result.network.Q, 'Q');
  // one curve short
  const bad = JSON.parse(JSON.stringify(net));
  bad.P.pop();
  await paste(t, JSON.stringify(bad));
  assert.equal(await errorText(t), 'P: expected 4 curves (one per u_r), got 3');
  await paste(t, '{ "u": [0, 1], "v": [0, 1], "P": [[[0, 0, 0], [0, 1, 0], [0, 2, 0]], [[1, 0, 0], [1, 1, 0], [1, 2, "z"]]], "Q": [] }');
  assert.equal(await errorText(t), 'P[1][2]: expected a finite number at [2], got "z"');
  await paste(t, '{ "u": [0, 1], ');
  assert.match(await errorText(t), /^JSON/);
  close((await exported(t)).computed.network.P, net.P, 'the previous network stays');
  t.assertClean();
  await t.close();
});

test('noisy-data: pasted points go through the same parser (a bad row is named)', async () => {
  const t = await H.open('#noisy-data');
  await t.page.getByRole('radio', { name: 'your CSV' }).evaluate((el) => el.click());
  await t.page.fill('textarea.csv-input', 'x,y\n0,0\n1,1.2\n2,-0.1\n3,oops\n4,0.2\n');
  await t.page.getByRole('button', { name: 'Use these points' }).click();
  await t.frames(3);
  assert.match(await t.page.$eval('.csv-input ~ .data-import-error, .ctl .data-import-error', (e) => e.textContent), /^row 5: expected 2 numbers, got 'oops'/);
  await t.page.fill('textarea.csv-input', '0 0\n1 1.2\n2 -0.1\n3 0.9\n4 0.2\n');
  await t.page.getByRole('button', { name: 'Use these points' }).click();
  await t.frames(3);
  assert.ok(await t.page.$eval('.ctl .data-import-error', (e) => e.hidden));
  assert.match(await t.page.$$eval('.ctl-readout-value', (e) => e.map((x) => x.textContent).join(' ')), /your 5 points/);
  t.assertClean();
  await t.close();
});

test('curve: bezier-remodel takes m·L + 1 control points (breaks 0..L, classical α: g* = g) and names a wrong count', async () => {
  const t = await openDemo('bezier-remodel');
  const pts = [[0, 0], [1, 2], [2, 2], [3, 0], [4, -1], [5, 1], [6, 0]]; // degree 2, L = 3
  await paste(t, pts.map((p) => p.join('\t')).join('\n'));
  assert.equal(await errorText(t), '');
  const doc = await exported(t);
  assert.deepEqual(doc.state.points, pts);
  assert.deepEqual(doc.state.breaks, [0, 1, 2, 3]);
  const { result } = await snippetResult(t);
  close(doc.computed.samples.points, result.curve.points, 'samples');
  // classical elevation: the remodelled curve is the original one
  close(result.curve.points, result.original.points, 'g* = g');
  await paste(t, '0 0\n1 1\n2 0\n3 1\n');
  assert.match(await errorText(t), /^a Bézier spline of degree 2 has m·L \+ 1 control points \(3, 5, 7, 9, …, L ≤ 12\), got 4$/);
  t.assertClean();
  await t.close();
});

test('curve: knot-modification takes 6…16 control points (clamped knots); too few are refused', async () => {
  const t = await openDemo('knot-modification');
  const pts = [[0, 0], [1, 1], [2, 3], [3, 2], [4, 0], [5, 1], [6, 3], [7, 2], [8, 0], [9, 1]];
  await paste(t, JSON.stringify(pts));
  assert.equal(await errorText(t), '');
  const doc = await exported(t);
  assert.deepEqual(doc.state.points, pts);
  assert.equal(doc.computed.curve.knots.length, pts.length + doc.state.order);
  const { result } = await snippetResult(t);
  close(doc.computed.samples.points, result.modified.points, 'samples');
  await paste(t, '0 0\n1 1\n2 0\n3 1\n4 0\n');
  assert.equal(await errorText(t), 'need at least 6 points, got 5');
  t.assertClean();
  await t.close();
});
