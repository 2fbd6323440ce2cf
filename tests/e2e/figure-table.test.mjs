// Figures in words (issue 25): every 2D figure with movable points has a "Table of the figure" under it that lists
// every point by its paper name with its coordinates (the numbers the plot holds, rounded as shown), and the
// demo's sampled values where it gives them; after a point is moved the table follows and the figure's
// description names the moved point. bspline-basics' C(u) rows are checked against the API computed here in Node
// (pkg-node), not against the page. The demos are found from the page (canvases with movable plot2d handles).
// Run: node --test tests/e2e/figure-table.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { startHarness, demoIds } from './harness.mjs';

const require = createRequire(import.meta.url);
let H, ids;
before(async () => { H = await startHarness(); ids = await demoIds(); });
after(async () => { await H?.close(); });

/** The number a table cell shows, as a JS number (Unicode minus → '-'), or NaN. */
const num = (s) => Number(String(s).replace('−', '-'));

/** Opens the table under the k-th movable-handle plot and reads it: [{ caption, head, rows }] and the handles. */
async function readTable(t, k) {
  return t.page.evaluate(async (kk) => {
    const c = [...document.querySelectorAll('canvas')].filter((e) => e.splinePlot && e.getClientRects().length && e.splinePlot.handles().some((x) => x.movable))[kk];
    const d = c.closest('.plot').querySelector('details.plot-table');
    if (!d) return null;
    if (!d.open) { d.querySelector('summary').click(); }
    await new Promise((ok) => setTimeout(ok, 50));
    const tables = [...d.querySelectorAll('table')].map((tb) => ({
      caption: tb.caption?.textContent ?? '',
      head: [...tb.tHead.rows[0].cells].map((x) => x.textContent),
      rows: [...tb.tBodies[0].rows].map((r) => [...r.cells].map((x) => x.textContent)),
    }));
    return { tables, handles: c.splinePlot.handles(), desc: document.getElementById(c.getAttribute('aria-describedby').split(' ')[0]).textContent };
  }, k);
}

test('every 2D figure with movable points: its table lists every point by name with its coordinates', async (tt) => {
  let seen = 0;
  for (const id of ids) {
    await tt.test(id, async () => {
      const t = await H.open(`#${id}`);
      const n = await t.page.evaluate(() => [...document.querySelectorAll('canvas')].filter((e) => e.splinePlot && e.getClientRects().length && e.splinePlot.handles().some((x) => x.movable)).length);
      for (let k = 0; k < n; k++) {
        const r = await readTable(t, k);
        assert.ok(r, `${id}: plot ${k} has a table`);
        const pts = r.tables.find((x) => x.caption.startsWith('Points'));
        const movable = r.handles.filter((x) => x.movable);
        assert.ok(pts, `${id}: plot ${k}'s table has a Points section (${r.tables.map((x) => x.caption)})`);
        assert.equal(pts.rows.length, movable.length, `${id}: one row per movable point`);
        movable.forEach((hd, i) => {
          const [name, x, y] = pts.rows[i];
          assert.doesNotMatch(name, /^(point|knot) \d/, `${id}: row ${i} names the point by its paper name (${name})`);
          assert.ok(Math.abs(num(x) - hd.point[0]) <= 5.1e-5, `${id}: ${name} x ${x} vs ${hd.point[0]}`);
          if (hd.axis !== 'x') assert.ok(Math.abs(num(y) - hd.point[1]) <= 5.1e-5, `${id}: ${name} y ${y} vs ${hd.point[1]}`);
        });
        seen++;
      }
      t.assertClean();
      await t.close();
    });
  }
  assert.ok(seen >= 8, `tables read on ${seen} plots`);
});

test('bspline-basics: C(u) rows are the curve at those u (checked with pkg-node); a moved point: the table and the description follow', async () => {
  const t = await H.open('#bspline-basics');
  const sl = require('../../pkg-node/splinelab.js');
  const st = await t.state();
  const r = await readTable(t, 0);
  const cu = r.tables.find((x) => x.caption.startsWith('C(u)'));
  assert.ok(cu, `a C(u) section (${r.tables.map((x) => x.caption)})`);
  assert.deepEqual(cu.head, ['u', 'x', 'y']);
  assert.equal(cu.rows.length, 11);
  const at = cu.rows.map((row) => num(row[0]));
  const ref = sl.bsplineCurve({ degree: st.degree, knots: st.knots, points: st.points, at });
  cu.rows.forEach((row, i) => {
    assert.ok(Math.abs(num(row[1]) - ref.points[2 * i]) <= 5.1e-5 * 2 && Math.abs(num(row[2]) - ref.points[2 * i + 1]) <= 5.1e-5 * 2, `C(${row[0]}) = (${row[1]}, ${row[2]}) vs (${ref.points[2 * i]}, ${ref.points[2 * i + 1]})`);
  });
  // move P₂ with the keyboard (focus selects P₀, PageDown twice P₂, an arrow moves it): the table follows, the
  // description names it
  const before = (await readTable(t, 0)).tables[0].rows[2];
  await t.page.focus('canvas[data-plot="curve"]');
  await t.page.keyboard.press('PageDown');
  await t.page.keyboard.press('PageDown');
  await t.page.keyboard.press('ArrowUp');
  await t.settled();
  // the description and the open table follow 300–600 ms after the change
  await t.page.waitForFunction((y0) => {
    const c = document.querySelector('canvas[data-plot="curve"]');
    const row = c.closest('.plot').querySelector('details.plot-table table')?.tBodies[0].rows[2];
    return / moved to /.test(document.getElementById(c.getAttribute('aria-describedby').split(' ')[0]).textContent) && row && row.cells[2].textContent !== y0;
  }, before[2]);
  const after = await readTable(t, 0);
  const st2 = await t.state();
  const moved = st2.points.findIndex((p, i) => p[1] !== st.points[i][1]);
  assert.equal(moved, 2, 'P₂ moved');
  const row = after.tables[0].rows[moved];
  assert.ok(Math.abs(num(row[2]) - st2.points[moved][1]) <= 5.1e-5, `the table shows the new y of row ${moved}: ${row} vs ${st2.points[moved]}`);
  assert.notDeepEqual(row, before, 'the row changed');
  assert.match(after.desc, new RegExp(`P${String.fromCharCode(0x2080 + moved)} moved`), `the description names the moved point: ${after.desc.slice(0, 120)}`);
  t.assertClean();
  await t.close();
});

test('390×844: what takes the focus under a figure (its x field, its table) shows above the controls sheet (SC 2.4.11)', async () => {
  const t = await H.open('#bspline-basics', { viewport: { width: 390, height: 844 } });
  const clear = () => t.page.evaluate(() => {
    const a = document.activeElement, sheet = document.querySelector('.demo-controls');
    const r = a.getBoundingClientRect(), top = sheet.getBoundingClientRect().top;
    const hit = document.elementFromPoint(r.left + Math.min(r.width / 2, 20), r.top + r.height / 2);
    return { what: a.getAttribute('aria-label') || a.textContent.slice(0, 30), bottom: r.bottom, sheetTop: top, onTop: !!hit && (hit === a || a.contains(hit)) };
  });
  await t.page.focus('canvas[data-plot="curve"]');
  // the selected point's fields show at the plot's next frame (a person is slower than that; a loaded CI is not)
  await t.page.waitForFunction(() => !document.querySelector('canvas[data-plot="curve"]').splinePlot.fieldsRow.hidden);
  await t.page.keyboard.press('Tab');
  let c = await clear();
  assert.match(c.what, /^x of /, `Tab from the plot reaches its x field (${c.what})`);
  assert.ok(c.bottom <= c.sheetTop && c.onTop, `the x field shows above the sheet: ${JSON.stringify(c)}`);
  // on to the table's summary (past the y field and the zoom tools)
  for (let k = 0; k < 8 && !(await t.page.evaluate(() => document.activeElement.tagName === 'SUMMARY')); k++) await t.page.keyboard.press('Tab');
  c = await clear();
  assert.match(c.what, /Table of the figure/);
  assert.ok(c.bottom <= c.sheetTop && c.onTop, `the table's summary shows above the sheet: ${JSON.stringify(c)}`);
  t.assertClean();
  await t.close();
});

// noisy-data's fits have no movable points: their tables list the data points and both fits at 11 values of u
test('noisy-data: each fit has a table of the data points and both fits at 11 values of u', async () => {
  const t = await H.open('#noisy-data');
  const read = (which) => t.page.evaluate(async (w) => {
    const c = document.querySelector(`canvas[data-plot="${w}"]`);
    const d = c.closest('.plot').querySelector('details.plot-table');
    if (!d || d.hidden) return null;
    if (!d.open) d.querySelector('summary').click();
    for (let i = 0; i < 50 && !d.querySelector('table'); i++) await new Promise((ok) => setTimeout(ok, 20));
    return [...d.querySelectorAll('table')].map((tb) => ({ caption: tb.caption?.textContent ?? '', head: [...tb.tHead.rows[0].cells].map((x) => x.textContent), rows: [...tb.tBodies[0].rows].map((r) => [...r.cells].map((x) => x.textContent)) }));
  }, which);
  const count = (await t.state()).count;
  for (const which of ['interp', 'approx']) {
    const tb = await read(which);
    assert.ok(tb, `${which}: the plot has a table`);
    assert.deepEqual(tb.map((s) => s.head.join(' ')), ['point x y', 'u x y', 'u x y'], `${which}: data points, then two fits (${tb.map((s) => s.caption)})`);
    assert.equal(tb[0].rows.length, count, `${which}: every data point is listed`);
    assert.deepEqual([tb[0].rows[0][0], tb[0].rows.at(-1)[0]], ['D₁', `D${String(count).replace(/\d/g, (d) => '₀₁₂₃₄₅₆₇₈₉'[d])}`], `${which}: named D₁ … D_N`);
    assert.deepEqual(tb.slice(1).map((s) => s.rows.length), [11, 11], `${which}: both fits at 11 values`);
    assert.match(tb[1].caption, which === 'interp' ? /^The interpolating fit \(a = 0\)/ : /^The approximating fit \(a = 0\.25\)/, `${which}: its own fit first`);
    // the interpolating fit passes through the data: its first row is the first data point
    const f0 = (which === 'interp' ? tb[1] : tb[2]).rows[0];
    assert.ok(Math.abs(num(f0[1]) - num(tb[0].rows[0][1])) < 1e-3 && Math.abs(num(f0[2]) - num(tb[0].rows[0][2])) < 1e-3, `${which}: the interpolating fit starts at D₁ (${f0} vs ${tb[0].rows[0]})`);
  }
  t.assertClean();
  await t.close();
});
