// Issue 24, items 9 and 11: a presenter's clicker steps the construction in presentation mode; stepper formulas
// are never cut at the panel's edge; stepping does not fill the undo history; the curve is not drawn finished
// while the stepper builds it.
// Run: node --test tests/e2e/present-steps.test.mjs   (needs www/pkg: scripts/build-wasm.sh)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

const stepOf = (t) => t.page.$eval('#demo-root .stepper', (s) => Number(s.dataset.step));
const isPresenting = (t) => t.page.evaluate(() => document.querySelector('#demo-root').classList.contains('presenting'));

test('present mode at 1280×720: PageDown/PageUp, arrows and Space step the construction, with the panel open or hidden; every data point stays in the free area', async () => {
  const t = await H.open('#interp-approx', { viewport: { width: 1280, height: 720 } });
  await t.page.getByRole('button', { name: 'Present', exact: true }).click();
  await t.frames(4);
  assert.ok(await isPresenting(t));
  assert.equal(await stepOf(t), -1);
  for (const [key, want] of [['PageDown', 0], ['PageDown', 1], ['ArrowRight', 2], ['Space', 3], ['PageUp', 2], ['ArrowLeft', 1], ['ArrowDown', 2], ['ArrowUp', 1]]) {
    await t.page.keyboard.press(key);
    assert.equal(await stepOf(t), want, `${key} → step ${want}`);
  }
  await t.page.keyboard.press('PageDown'); await t.page.keyboard.press('PageDown');
  assert.equal(await stepOf(t), 3, 'Step ×4 (as in the issue)');
  await t.frames(3);
  // every data point W₁…Wₙ and the ends of the curve are visible: inside the canvas, not under the bar or panel
  const where = await t.page.evaluate(() => {
    const c = document.querySelector('#demo-root .present-main canvas');
    const p = c.splinePlot, r = c.getBoundingClientRect();
    const bar = document.querySelector('.present-bar').getBoundingClientRect();
    const panel = document.querySelector('#demo-root .demo-controls').getBoundingClientRect();
    return { canvas: r.toJSON(), bar: bar.toJSON(), panel: panel.toJSON(), view: p.getView() };
  });
  const state = await t.state();
  for (const [k, q] of state.points.entries()) {
    const [x, y] = await t.worldToPage('#demo-root .present-main canvas', q);
    const name = `W${k - 1}`;
    assert.ok(x >= where.canvas.left && x <= where.canvas.right && y >= where.canvas.top && y <= where.canvas.bottom, `${name} (${x.toFixed(0)}, ${y.toFixed(0)}) inside the drawing ${JSON.stringify(where.canvas)}`);
    assert.ok(!(x >= where.panel.left && y >= where.panel.top && y <= where.panel.bottom), `${name} at (${x.toFixed(0)}, ${y.toFixed(0)}) lies under the controls panel (left ${where.panel.left})`);
    assert.ok(!(x <= where.bar.right && y <= where.bar.bottom), `${name} at (${x.toFixed(0)}, ${y.toFixed(0)}) lies under the title bar (bottom ${where.bar.bottom})`);
  }
  await t.page.screenshot({ path: 'tests/e2e/out/present-1280x720-step4.png' });
  // the panel hidden: the clicker still steps, and the drawing takes the whole width
  await t.page.getByRole('button', { name: 'Hide controls' }).click();
  await t.frames(3);
  const wide = await t.page.$eval('#demo-root .present-main canvas', (c) => c.getBoundingClientRect().width);
  assert.ok(wide >= 1270, `panel hidden: the drawing is ${wide} px wide`);
  await t.page.keyboard.press('PageDown');
  assert.equal(await stepOf(t), 4, 'PageDown with the controls hidden');
  await t.page.keyboard.press('PageDown');
  assert.equal(await stepOf(t), 5);
  await t.page.keyboard.press('PageDown');
  assert.equal(await stepOf(t), 5, 'stays at the last step');
  // out of presentation mode the keys do their usual work (PageDown scrolls the page)
  await t.press('Escape');
  assert.equal(await isPresenting(t), false);
  await t.page.keyboard.press('PageUp');
  assert.equal(await stepOf(t), 5, 'outside presentation mode PageUp does not step');
  t.assertClean();
  await t.close();
});

test('present mode on a phone (390×844, the panel a bottom sheet): the drawing ends above the sheet', async () => {
  const t = await H.open('#interp-approx', { viewport: { width: 390, height: 844 } });
  await t.page.getByRole('button', { name: 'Present', exact: true }).click();
  await t.frames(3);
  await t.page.getByRole('button', { name: 'Show controls' }).click();
  await t.frames(4);
  const { c, p } = await t.page.evaluate(() => ({
    c: document.querySelector('#demo-root .present-main canvas').getBoundingClientRect().toJSON(),
    p: document.querySelector('#demo-root .demo-controls').getBoundingClientRect().toJSON(),
  }));
  await t.page.screenshot({ path: 'tests/e2e/out/present-390x844-sheet.png' });
  assert.ok(c.bottom <= p.top + 1, `the drawing (bottom ${c.bottom}) ends above the sheet (top ${p.top})`);
  assert.ok(c.height >= 150, `and keeps a usable height (${c.height} px)`);
  t.assertClean();
  await t.close();
});

/** For every step of every stepper of a demo: no formula row is cut by the panel's edge. */
async function formulasFit(t, id) {
  const panels = await t.page.$$('#demo-root .stepper');
  const problems = [];
  for (const panel of panels) {
    if (!(await panel.isVisible())) continue;
    const n = Number(await panel.getAttribute('data-steps'));
    const fwd = await panel.$('.step-forward');
    for (let k = 0; k < n; k++) {
      await fwd.click();
      await t.frames(2);
      const rows = await panel.$$eval('.stepper-formula > math', (ms) => ms.map((m) => {
        const box = m.parentElement.getBoundingClientRect();
        const r = m.getBoundingClientRect();
        return { right: r.right, edge: box.right, scroll: m.parentElement.scrollWidth - m.parentElement.clientWidth, size: getComputedStyle(m).fontSize, text: m.textContent.slice(0, 60) };
      }));
      for (const r of rows) if (r.right > r.edge + 1 || r.scroll > 1) problems.push(`${id} step ${k + 1}: "${r.text}" ends at ${r.right.toFixed(0)} > ${r.edge.toFixed(0)} (at ${r.size})`);
    }
    await (await panel.$('.step-leave')).click();
  }
  return problems;
}

test('stepper formulas fit their 320 px panel at 1366×900 and 1280×720 (no row cut at the edge)', async () => {
  for (const vp of [{ width: 1366, height: 900 }, { width: 1280, height: 720 }]) {
    for (const id of ['interp-approx', 'bspline-basics', 'bezier-remodel', 'quasi-cubic-curves', 'knot-modification']) {
      const t = await H.open(`#${id}`, { viewport: vp });
      const problems = await formulasFit(t, id);
      assert.deepEqual(problems, [], `${vp.width}×${vp.height}: ${problems.join('; ')}`);
      t.assertClean();
      await t.close();
    }
  }
});

test('stepping is not undone step by step: drag, step ×4 (as a person, with pauses), one Undo restores the point', async () => {
  const t = await H.open('#interp-approx');
  const s0 = await t.state();
  const p = s0.points[4];
  await t.dragWorld('#demo-root canvas', p, [p[0] + 0.4, p[1] - 0.5], 10);
  await t.page.waitForTimeout(700);
  const s1 = await t.state();
  assert.notDeepEqual(s1.points[4], s0.points[4], 'the drag moved W₃');
  for (let i = 0; i < 4; i++) { await t.page.click('#demo-root .step-forward'); await t.page.waitForTimeout(650); }
  assert.equal((await t.state()).step, 3);
  await t.page.getByRole('button', { name: 'Undo', exact: true }).click();
  await t.frames(3);
  const s2 = await t.state();
  assert.deepEqual(s2.points[4], s0.points[4], 'one Undo undoes the drag');
  t.assertClean();
  await t.close();
});

test('while the stepper builds the curve, the finished curve is a faint trace; its own last step draws it', async () => {
  const t = await H.open('#interp-approx');
  // the curve's colour at a point of the curve far from the overlays: strong at the last step, faint before
  const sample = async () => t.page.evaluate(() => {
    const c = document.querySelector('#demo-root canvas[data-plot="curve"]');
    const g = c.getContext('2d');
    // count strongly blue pixels (the curve's colour) over the whole canvas
    const d = g.getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] < 40 && d[i + 1] > 90 && d[i + 1] < 140 && d[i + 2] > 150 && d[i + 3] > 200) n++;
    return n;
  });
  // overlays off, so only the main curve is blue
  await t.page.getByLabel('Overlay a = 1/6 (B-spline)').uncheck();
  await t.page.getByLabel('Overlay a = 0 (interpolating)').uncheck();
  const fwd = t.page.locator('#demo-root .step-forward');
  await fwd.click(); await t.frames(3);
  const early = await sample();
  for (let i = 0; i < 5; i++) await fwd.click();
  await t.frames(3);
  const last = await sample();
  assert.ok(last > 500, `the last step draws the curve (${last} curve-blue pixels)`);
  assert.ok(early < last * 0.1, `step 1 shows at most a faint trace (${early} vs ${last} curve-blue pixels)`);
  t.assertClean();
  await t.close();
});
