// The "B2 surfaces" demo: draws the surface in the 3D view; a, the tensions, the grid size and the knots
// redraw it; dragging a grid point edits the grid; the state survives a reload; no console error.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

const SURF = 'canvas[data-plot="surface"]';
const IGNORE = [/GPU stall due to ReadPixels/];

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

const readouts = (t) => t.page.$$eval('.ctl-readout-value', (els) => els.map((e) => e.textContent));

test('draws the surface and the grid', async () => {
  const t = await H.open('#b2-surfaces');
  const ink = await t.page.$eval(SURF, (c) => {
    c.view3d.renderNow();
    const d = document.createElement('canvas'); d.width = c.width; d.height = c.height;
    const g = d.getContext('2d'); g.drawImage(c, 0, 0);
    const px = g.getImageData(0, 0, d.width, d.height).data;
    let n = 0;
    for (let i = 0; i < px.length; i += 4) if (px[i] < 200 || px[i + 1] < 200 || px[i + 2] < 200) n++;
    return n / (px.length / 4);
  });
  assert.ok(ink > 0.05, `the view shows a surface (${(100 * ink).toFixed(1)} % of the pixels)`);
  const [domain, edits] = await readouts(t);
  assert.match(domain, /u ∈ \[0, 3\], v ∈ \[0, 3\]/);
  assert.equal(edits, 'none');
  await t.screenshot('b2-surfaces');
  t.assertClean(IGNORE);
  await t.close();
});

/** Sets a, the tension in u and the grid size in turn; each must change the surface's pixels. Returns the last hash. */
async function eachInputRedraws(t) {
  let h = await t.canvasHash(SURF);
  for (const [sel, v] of [['input[name="a"]', 1 / 6], ['input[name="tu"]', 0.35], ['input[name="size"]', 10]]) {
    await t.setInput(sel, v);
    const h2 = await t.canvasHash(SURF);
    assert.notEqual(h2, h, `${sel} redraws`);
    h = h2;
  }
  return h;
}

test('on a slow machine (every worker answer 250 ms late) a, tension and grid size still redraw the surface', async () => {
  // CI under load sent the tension change to the worker and read the picture two frames later, before the answer:
  // the harness's setInput and canvasHash now wait until no request is unanswered (seen failing without)
  const context = await H.browser.newContext({ viewport: { width: 1280, height: 900 } });
  await context.addInitScript(() => {
    /** @type {any} */ (window).splinelabCompute = 'worker';
    const W = window.Worker;
    window.Worker = class extends W {
      set onmessage(fn) { super.onmessage = (e) => setTimeout(() => fn.call(this, e), 250); }
      get onmessage() { return super.onmessage; }
      addEventListener(type, fn, o) { return super.addEventListener(type, type === 'message' ? (e) => setTimeout(() => fn.call(this, e), 250) : fn, o); }
    };
  });
  const t = await H.open('#b2-surfaces', { context });
  let h = await eachInputRedraws(t);
  t.assertClean(IGNORE);
  await t.page.close();
  await context.close();
});

test('a, tension, grid size and knots redraw the surface', async () => {
  const t = await H.open('#b2-surfaces');
  let h = await eachInputRedraws(t);
  assert.match((await readouts(t))[0], /u ∈ \[0, 5\]/);
  await t.page.getByRole('radio', { name: 'chord' }).evaluate((el) => el.click());
  assert.notEqual(await t.canvasHash(SURF), h);
  // the spline-blended surface of §7 (when the module exports it)
  const blended = t.page.getByRole('radio', { name: 'spline-blended (§7)' });
  if (await blended.count()) {
    const hb = await t.canvasHash(SURF);
    await blended.evaluate((el) => el.click());
    assert.notEqual(await t.canvasHash(SURF), hb, 'the blended surface is drawn');
    await t.setInput('input[name="a"]', 0.1);
    assert.equal(await t.page.$('.notice'), null, 'no error notice');
  }
  t.assertClean(IGNORE);
  await t.close();
});

test('dragging a grid point edits the grid, and the link restores it', async () => {
  const t = await H.open('#b2-surfaces');
  const h0 = await t.canvasHash(SURF);
  // the inner grid point W_1,1 = index (2, 2) of the 8 × 8 grid
  const [x, y] = await t.page.$eval(SURF, (c) => {
    c.view3d.renderNow();
    const r = c.getBoundingClientRect();
    const p = c.view3d.screenPosition('W', 2 * 8 + 2);
    return [r.left + p[0], r.top + p[1]];
  });
  await t.dragScreen([x, y], [x, y - 60], 10);
  await t.frames(3);
  const [, edits] = await readouts(t);
  assert.match(edits, /^W₁,₁ \+\d/, `edited: ${edits}`);
  assert.notEqual(await t.canvasHash(SURF), h0);
  await t.waitHash((s) => s.startsWith('#b2-surfaces/'));
  await new Promise((ok) => setTimeout(ok, 400));
  const url = t.page.url();
  t.assertClean(IGNORE);
  await t.close();
  const t2 = await H.open(url.slice(url.indexOf('#')));
  assert.equal((await readouts(t2))[1], edits, 'the edit is restored from the link');
  await t2.page.getByRole('button', { name: 'Reset the grid' }).click();
  assert.equal((await readouts(t2))[1], 'none');
  t2.assertClean(IGNORE);
  await t2.close();
});
