// The "B-spline basics" demo: draws, drags, keyboard, u slider, state round-trip through the URL, bad links.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { deflateRawSync } from 'node:zlib';
import { startHarness } from './harness.mjs';

const CURVE = 'canvas[data-plot="curve"]';
const BASIS = 'canvas[data-plot="basis"]';
const DEFAULT_POINTS = [[0, 0], [1, 2.2], [2.4, 2.6], [3.4, 0.6], [4.6, 0.2], [5.4, 2.4], [6.6, 1.8]];

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

const ctrl = async (t) => (await t.handles(CURVE)).filter((x) => x.name === 'control point').map((x) => x.point);
const knots = async (t) => (await t.handles(BASIS)).filter((x) => x.name === 'knot').map((x) => x.point[0]);
const readout = (t) => t.page.$$eval('.ctl-table tbody tr', (rows) => rows.map((r) => r.textContent));

test('draws the curve and the basis functions', async () => {
  const t = await H.open('#bspline-basics');
  assert.deepEqual(await ctrl(t), DEFAULT_POINTS);
  // a drawn canvas is not blank: compare with an empty canvas of the same size
  const blank = await t.page.$eval(CURVE, (c) => { const e = document.createElement('canvas'); e.width = c.width; e.height = c.height; return e.toDataURL(); });
  assert.notEqual(await t.page.$eval(CURVE, (c) => c.toDataURL()), blank);
  // p + 1 = 4 non-zero basis functions at u plus the sum row
  const rows = await readout(t);
  assert.equal(rows.length, 5);
  assert.match(rows[4], /sum\s*1$/);
  await t.screenshot('bspline-basics');
  t.assertClean();
  await t.close();
});

test('dragging a control point changes the drawing, the state and the URL', async () => {
  const t = await H.open('#bspline-basics');
  const before = await t.canvasHash(CURVE);
  // a drag frame refreshes the sliders, the stepper and the "Non-zero at u" table with what they already show:
  // nothing of theirs is written (www/lib/controls.js, stepper.js write only what changed)
  await t.page.evaluate(() => {
    const w = /** @type {any} */ (window);
    w.__writes = [];
    const mo = new MutationObserver((rs) => { for (const r of rs) w.__writes.push(`${r.type} in ${r.target.closest?.('[class]')?.className ?? r.target.parentElement?.closest('[class]')?.className}`); });
    for (const el of document.querySelectorAll('#demo-root .ctl-slider, #demo-root section.stepper, #demo-root .ctl-tablewrap')) mo.observe(el, { subtree: true, attributes: true, childList: true, characterData: true });
  });
  await t.dragWorld(CURVE, DEFAULT_POINTS[2], [2.8, 1.2]);
  const pts = await ctrl(t);
  assert.ok(Math.abs(pts[2][0] - 2.8) < 0.05 && Math.abs(pts[2][1] - 1.2) < 0.05, `P2 moved: ${pts[2]}`);
  assert.deepEqual(pts[3], DEFAULT_POINTS[3], 'other points stay');
  assert.notEqual(await t.canvasHash(CURVE), before);
  assert.deepEqual(await t.page.evaluate(() => /** @type {any} */ (window).__writes), [], 'a point drag wrote to controls that did not change');
  const hash = await t.waitHash((h) => h.startsWith('#bspline-basics/v1.'));
  assert.ok(hash.length < 400, `compact link (${hash.length} chars)`);
  t.assertClean();
  await t.close();
});

test('reloading the URL after a drag restores the same state', async () => {
  const t = await H.open('#bspline-basics');
  await t.dragWorld(CURVE, DEFAULT_POINTS[5], [5, 3]);
  await t.dragWorld(BASIS, [0.5, -0.13], [0.6, -0.13]);
  const hash = await t.flushState();
  const url = t.page.url();
  const state = await t.state();
  const pts = await ctrl(t), ks = await knots(t);
  assert.ok(Math.abs(ks[1] - 0.6) < 0.01, `knot moved: ${ks}`);
  await t.close();
  const t2 = await H.open(url.slice(url.indexOf('#')));
  assert.deepEqual(await ctrl(t2), pts);
  assert.deepEqual(await knots(t2), ks);
  assert.deepEqual(await t2.state(), state, 'the whole state round-trips');
  assert.equal(await t2.page.$('.notice'), null, 'no notice for a good link');
  assert.ok(hash);
  t2.assertClean();
  await t2.close();
});

test('keyboard: Tab reaches the plot, arrow keys move the selected point', async () => {
  const t = await H.open('#bspline-basics');
  assert.ok(await t.tabTo(CURVE), 'the curve plot is reachable with Tab');
  const before = await t.canvasHash(CURVE);
  await t.press('ArrowRight', 'ArrowRight', 'Shift+ArrowUp');
  let pts = await ctrl(t);
  assert.ok(pts[0][0] > 0 && pts[0][1] > 0, `P0 moved right and up: ${pts[0]}`);
  const up = pts[0][1];
  await t.press('PageDown', 'ArrowDown'); // select P₁ (the next point: the plot is one Tab stop) and move it down
  pts = await ctrl(t);
  assert.ok(pts[1][1] < DEFAULT_POINTS[1][1], 'P1 moved down');
  assert.equal(pts[0][1], up);
  assert.notEqual(await t.canvasHash(CURVE), before);
  const live = await t.page.$eval('.plot [aria-live]', (e) => e.textContent);
  assert.match(live, /Control point P₁ (\(2 of 7\) )?at \(/, 'the selection is announced with the paper name P₁ (not P1)');
  // the other keys that choose a point (the plot is one Tab stop): End / Home, ] and Shift+N wrap; each is said with
  // its place in the list; Tab leaves to P₁'s fields and Shift+Tab comes back to the point chosen before
  const said = async () => { await t.frames(2); return t.page.$eval('.plot [aria-live]', (e) => e.textContent); };
  await t.press('End');
  assert.match(await said(), /^Control point P₆ \(7 of 7\) at \(/, 'End: the last point');
  await t.press(']');
  assert.match(await said(), /^Control point P₀ \(1 of 7\) at \(/, '] after the last wraps to the first');
  await t.press('Shift+N');
  assert.match(await said(), /^Control point P₆ \(7 of 7\) at \(/, 'Shift+N before the first wraps to the last');
  await t.press('Home', 'n');
  assert.match(await said(), /^Control point P₁ \(2 of 7\) at \(/, 'Home, then N: the second point');
  await t.press('Tab');
  assert.equal(await t.page.evaluate(() => document.activeElement.getAttribute('aria-label')), 'x of P₁', 'Tab from the plot reaches the chosen point’s x field');
  await t.press('Shift+Tab');
  assert.match(await said(), /^Control point P₁ \(2 of 7\) at \(/, 'Shift+Tab back into the plot: the point chosen before, said again');
  // on past the fields to the zoom tools: the keyboard's point is let go (its fields hide); Shift+Tab chooses it again
  await t.press('Tab', 'Tab', 'Tab');
  const on = await t.page.evaluate(() => ({ tool: !!document.activeElement.closest('.plot-tools'), rowHidden: document.querySelector('.plot-fields').hidden }));
  assert.deepEqual(on, { tool: true, rowHidden: true }, 'three Tabs: x, y, then the zoom tools; the fields hide');
  await t.press('Shift+Tab');
  assert.match(await said(), /^Control point P₁ \(2 of 7\) at \(/, 'Shift+Tab from the tools: the point chosen before');
  t.assertClean();
  await t.close();
});

test('moving the u slider changes the highlighted basis functions', async () => {
  const t = await H.open('#bspline-basics');
  const rows0 = await readout(t);
  const before = await t.canvasHash(BASIS);
  await t.setInput('input[type=range]', 0.9);
  const rows1 = await readout(t);
  assert.notDeepEqual(rows1, rows0);
  assert.match(rows1.join(' '), /N₆/, 'N6 is non-zero near the end');
  assert.doesNotMatch(rows1.join(' '), /N₁,/, 'N1 is zero near the end');
  assert.notEqual(await t.canvasHash(BASIS), before);
  t.assertClean();
  await t.close();
});

test('changing the degree rebuilds a valid clamped knot vector', async () => {
  const t = await H.open('#bspline-basics');
  await t.page.click('.ctl-segments label:text-is("5")');
  await t.frames(3);
  assert.equal((await knots(t)).length, 7 - 5 - 1, 'n − p − 1 interior knots');
  assert.equal((await readout(t)).length, 5 + 1 + 1);
  await t.page.click('button:text-is("Add point")');
  await t.frames(3);
  assert.equal((await ctrl(t)).length, 8);
  assert.equal((await knots(t)).length, 8 - 5 - 1);
  await t.page.click('.ctl-segments label:text-is("1")');
  await t.frames(3);
  assert.equal((await readout(t)).length, 2 + 1);
  t.assertClean();
  await t.close();
});

test('a malformed or hostile hash shows the notice and the default state', async () => {
  for (const payload of ['v1.%%%garbage', 'v1.AAAA', 'v0.eyJkZWdyZWUiOiJ4In0', 'v9.abc',
    // valid encoding, wrong types / non-finite numbers: {"points":[[0,"x"]]} and {"degree":1e999}
    'v0.eyJwb2ludHMiOltbMCwieCJdXX0', 'v0.eyJkZWdyZWUiOjFlOTk5fQ',
    // a deflate bomb: 2 MB of spaces compress to ~2 KB; the decoder must stop at 64 KB
    'v1.' + deflateRawSync(Buffer.from(`{"u":0.5${' '.repeat(2 << 20)}}`)).toString('base64url'),
    // points of the wrong arity
    'v0.' + Buffer.from(JSON.stringify({ points: [[0, 0, 0], [1, 1, 1], [2, 0, 0]] })).toString('base64url')]) {
    const t = await H.open(`#bspline-basics/${payload}`);
    const notice = await t.text('.notice');
    assert.ok(notice && /could not be read/.test(notice), `notice for ${payload}: ${notice}`);
    assert.deepEqual(await ctrl(t), DEFAULT_POINTS, `default state for ${payload}`);
    t.assertClean();
    await t.close();
  }
});

test('after a bad link the last good state can be restored', async () => {
  const t = await H.open('#bspline-basics');
  await t.dragWorld(CURVE, DEFAULT_POINTS[1], [1.5, 1.5]);
  await t.flushState();
  const moved = await ctrl(t);
  // same browser context (same localStorage), a broken link
  const t2 = await H.open('#bspline-basics/v1.broken', { context: t.context });
  assert.deepEqual(await ctrl(t2), DEFAULT_POINTS);
  await t2.page.click('.notice button:text-is("Restore my last state")');
  await t2.frames(3);
  assert.deepEqual(await ctrl(t2), moved);
  t2.assertClean();
  await t2.close();
  await t.close();
});

test('touch and pen drag points; the canvas lets vertical swipes scroll the page (touch-action pan-y)', async () => {
  const t = await H.open('#bspline-basics');
  assert.equal(await t.page.$eval(CURVE, (c) => getComputedStyle(c).touchAction), 'pan-y');
  assert.equal(await t.page.evaluate(() => getComputedStyle(document.body).touchAction), 'auto', 'the page still scrolls');
  await t.pointerDrag(CURVE, DEFAULT_POINTS[4], [4.2, 1.0], { pointerType: 'touch' });
  let pts = await ctrl(t);
  assert.ok(Math.abs(pts[4][0] - 4.2) < 0.05 && Math.abs(pts[4][1] - 1.0) < 0.05, `touch moved P4: ${pts[4]}`);
  await t.pointerDrag(CURVE, DEFAULT_POINTS[6], [6, 1], { pointerType: 'pen' });
  pts = await ctrl(t);
  assert.ok(Math.abs(pts[6][0] - 6) < 0.05, `pen moved P6: ${pts[6]}`);
  // knots stay ordered: try to drag the first interior knot past the second
  await t.pointerDrag(BASIS, [0.25, -0.13], [0.9, -0.13], { pointerType: 'touch' });
  const ks = await knots(t);
  assert.ok(ks[0] < ks[1] && ks[1] < ks[2], `ordered: ${ks}`);
  t.assertClean();
  await t.close();
});

test('pan, wheel zoom and pinch change the view, and the view round-trips through the URL', async () => {
  const t = await H.open('#bspline-basics');
  const v0 = await t.plotEval(CURVE, (p) => p.getView());
  // plain wheel over an unfocused plot scrolls the page, it does not zoom
  await t.wheel(CURVE, [3, 1], -300);
  assert.deepEqual(await t.plotEval(CURVE, (p) => p.getView()), v0);
  await t.wheel(CURVE, [3, 1], -300, { ctrl: true });
  const v1 = await t.plotEval(CURVE, (p) => p.getView());
  assert.ok(v1.xmax - v1.xmin < v0.xmax - v0.xmin, 'ctrl+wheel zooms in');
  await t.pinch(CURVE, [3, 1], 2);
  const v2 = await t.plotEval(CURVE, (p) => p.getView());
  assert.ok(v2.xmax - v2.xmin < (v1.xmax - v1.xmin) * 0.7, 'pinch zooms in');
  // background drag (bottom-left corner of the plot, away from the curve) pans
  const box = await (await t.page.$(CURVE)).boundingBox();
  await t.dragScreen([box.x + 30, box.y + box.height - 30], [box.x + 130, box.y + box.height - 30]);
  const v3 = await t.plotEval(CURVE, (p) => p.getView());
  assert.ok(v3.xmin < v2.xmin, 'panned');
  assert.deepEqual(await ctrl(t), DEFAULT_POINTS, 'panning moved no point');
  await t.flushState();
  const url = t.page.url();
  await t.close();
  const t2 = await H.open(url.slice(url.indexOf('#')));
  const v4 = await t2.plotEval(CURVE, (p) => p.getView());
  for (const k of ['xmin', 'xmax', 'ymin', 'ymax']) assert.ok(Math.abs(v4[k] - v3[k]) < 1e-6, `${k} restored`);
  t.assertClean();
  t2.assertClean();
  await t2.close();
});

test('locked embed: points cannot be moved; axe finds no serious issue', async () => {
  const t = await H.open('embed.html#bspline-basics?locked=1');
  await t.dragWorld(CURVE, DEFAULT_POINTS[2], [3, 1]);
  await t.press('Tab');
  assert.deepEqual(await ctrl(t), DEFAULT_POINTS);
  assert.equal(await t.page.$eval('button:text-is("Add point")', (b) => b.disabled), true);
  assert.deepEqual(await t.axe(), []);
  t.assertClean();
  await t.close();
  const t2 = await H.open('#bspline-basics');
  assert.deepEqual(await t2.axe(), []);
  await t2.close();
});

test('old or partial links: unknown keys are dropped, missing keys take their defaults', async () => {
  const payload = 'v0.' + Buffer.from('{"degree":2,"knots":[0,0,0,0.3,0.5,0.7,0.9,1,1,1],"evil":"<img src=x>","__proto__":{"polluted":true}}').toString('base64url');
  const t = await H.open(`#bspline-basics/${payload}`);
  assert.equal(await t.page.$('.notice'), null);
  assert.deepEqual(await ctrl(t), DEFAULT_POINTS);
  assert.deepEqual(await knots(t), [0.3, 0.5, 0.7, 0.9]);
  assert.equal((await readout(t)).length, 3 + 1, 'degree 2: three non-zero functions');
  assert.equal(await t.page.evaluate(() => ({}).polluted), undefined);
  t.assertClean();
  await t.close();
});
