// The 3D camera round-trips through the link in every 3D demo: orbit (mouse drag) and zoom (wheel) the view,
// flush the state to the URL, open the same URL in a fresh page, and the camera (view3d.getView(): yaw, pitch,
// distance, target) is the one that was saved.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

let H;
before(async () => { H = await startHarness({ viewport: { width: 1280, height: 900 } }); });
after(async () => { await H?.close(); });

// demo id → the tab to show first (label of its segmented control), and how the demo keeps the camera
const DEMOS = [
  { id: 'quasi-cubic-surfaces' },
  { id: 'criss-cross-basis' },
  { id: 'b2-surfaces' },
  { id: 'curve-networks' },
  // knot modification keeps the direction in whole degrees (its Turn/Tilt sliders), so 0.5° is the tolerance
  { id: 'knot-modification', tab: 'Surface', angleTol: 0.5 },
  { id: 'bezier-remodel', tab: 'Surface (§4)' },
];

/** getView() of the first visible 3D view. */
const camera = (t) => t.page.evaluate(() => {
  const c = [...document.querySelectorAll('canvas.sl-view3d-canvas')].find((e) => e.getClientRects().length);
  return c ? c.view3d.getView() : null;
});

const near = (a, b, tol) => Math.abs(a - b) <= tol;

function assertSameCamera(got, want, { angleTol = 1e-3 } = {}, what = '') {
  assert.ok(got && want, `${what}: a camera`);
  assert.ok(near(got.yaw, want.yaw, angleTol), `${what}: yaw ${got.yaw} vs ${want.yaw}`);
  assert.ok(near(got.pitch, want.pitch, angleTol), `${what}: pitch ${got.pitch} vs ${want.pitch}`);
  assert.ok(near(got.distance, want.distance, 1e-4 * want.distance), `${what}: distance ${got.distance} vs ${want.distance}`);
  for (let k = 0; k < 3; k++) {
    assert.ok(near(got.target[k], want.target[k], 1e-4 * Math.max(1, want.distance)), `${what}: target ${got.target} vs ${want.target}`);
  }
}

for (const d of DEMOS) {
  test(`${d.id}: the camera (orbit and zoom) round-trips through the link`, async () => {
    const t = await H.open(`#${d.id}`);
    if (d.tab) { await t.page.click(`.ctl-segments label:text-is("${d.tab}")`); await t.frames(3); }
    const start = await camera(t);
    assert.ok(start, 'the demo shows a 3D view');
    const sel = 'canvas.sl-view3d-canvas >> visible=true';
    await t.page.locator(sel).first().scrollIntoViewIfNeeded();
    const box = await t.page.locator(sel).first().boundingBox();
    // orbit: a mouse drag that starts on the background near the top-left corner
    const x0 = box.x + 40, y0 = box.y + 40;
    await t.dragScreen([x0, y0], [x0 + 120, y0 + 50], 10);
    // zoom: the wheel (the view has focus after the drag); the view reports it 250 ms after the last tick
    await t.page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await t.page.mouse.wheel(0, -240);
    await t.page.waitForTimeout(450);
    const moved = await camera(t);
    assert.ok(Math.abs(moved.yaw - start.yaw) > 5, `the drag orbited: yaw ${start.yaw} → ${moved.yaw}`);
    assert.ok(moved.distance < start.distance * 0.95, `the wheel zoomed in: ${start.distance} → ${moved.distance}`);
    const hash = await t.flushState();
    assert.match(hash, new RegExp(`^#${d.id}/`), 'the state is in the link');
    const t2 = await H.open(hash);
    await t2.frames(3);
    assertSameCamera(await camera(t2), moved, d, `${d.id} after reload`);
    t.assertClean();
    t2.assertClean();
    await t2.close();
    await t.close();
  });
}

test('criss-cross basis: the 3D view has axes with tick values that measure the surface; they can be turned off', async () => {
  const t = await H.open('#criss-cross-basis');
  const info = await t.page.$eval('canvas[data-plot="basis3d"]', (c) => { c.view3d.renderNow(); return c.view3d.axesInfo; });
  assert.ok(info && info.x && info.y && info.z, `three axes: ${JSON.stringify(info && Object.keys(info))}`);
  const values = (a) => a.ticks.map((k) => k.value);
  // B_ij lives over the unit square: the u and v axes run from 0 to 1
  for (const k of ['x', 'y']) {
    assert.ok(values(info[k]).includes(0) && values(info[k]).includes(1), `${k} ticks ${values(info[k])}`);
    assert.ok(info[k].ticks.length >= 3, `${k}: at least three ticks`);
  }
  // the height axis spans [0, max B_ij] (max < 1: a partition of unity), with 0 among its ticks
  const z = values(info.z);
  assert.ok(z.includes(0) && Math.max(...z) <= 1 && z.length >= 2, `z ticks ${z}`);
  // ticks are increasing along each axis and sit on the canvas
  const box = await t.page.$eval('canvas[data-plot="basis3d"]', (c) => [c.clientWidth, c.clientHeight]);
  for (const a of Object.values(info)) {
    for (let i = 1; i < a.ticks.length; i++) assert.ok(a.ticks[i].value > a.ticks[i - 1].value);
    for (const k of a.ticks) assert.ok(k.at[0] >= 0 && k.at[0] <= box[0] && k.at[1] >= 0 && k.at[1] <= box[1], `tick on the canvas: ${k.at}`);
  }
  const off = await t.page.$eval('canvas[data-plot="basis3d"]', (c) => { c.view3d.showAxes(false); c.view3d.renderNow(); return c.view3d.axesInfo; });
  assert.equal(off, null, 'showAxes(false) removes them');
  t.assertClean();
  await t.close();
});
