// Phones: touch that lets the page scroll. At 390×844 with a touch screen (hasTouch, isMobile), real touch
// input through the DevTools protocol (Input.dispatchTouchEvent, which runs the browser's own gesture and
// scrolling pipeline, so touch-action and preventDefault decide as on a phone):
//   - a vertical swipe over a 2D plot that does not start on a handle scrolls the page, and leaves the plot alone;
//   - a finger on a handle drags it (the state point moves, the page does not scroll);
//   - two fingers zoom the plot (the page does not scroll);
//   - a swipe over an inactive 3D view scrolls the page; a tap activates it ("Tap to rotate"), then a swipe
//     orbits the camera; a tap outside gives swipes back to the page;
//   - no demo scrolls sideways at 390 px.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness, demoIds } from './harness.mjs';

const PHONE = { viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true, deviceScaleFactor: 2 };
let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

async function openPhone(route) {
  const t = await H.open(route, PHONE); // (the harness's shared context for these options)
  t.cdp = await t.context.newCDPSession(t.page);
  t.done = async () => { await t.cdp.detach(); await t.close(); };
  return t;
}

const sleep = (ms) => new Promise((ok) => setTimeout(ok, ms));
const scrollY = (t) => t.page.evaluate(() => window.scrollY);

/** One finger from a to b (viewport CSS px) in `steps` moves, then lifted; waits for scrolling to settle. */
async function swipe(t, [x0, y0], [x1, y1], steps = 12) {
  await t.cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x: x0, y: y0, id: 1 }] });
  for (let i = 1; i <= steps; i++) {
    await t.cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [{ x: x0 + (x1 - x0) * i / steps, y: y0 + (y1 - y0) * i / steps, id: 1 }] });
  }
  await t.cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await sleep(400);
  await t.frames(2);
}

async function tap(t, [x, y]) {
  await t.cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x, y, id: 1 }] });
  await t.cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await sleep(150);
  await t.frames(2);
}

/** Two fingers spread horizontally around c (zoom in). */
async function pinch(t, [cx, cy], from = 30, to = 90, steps = 10) {
  const pts = (d) => [{ x: cx - d, y: cy, id: 1 }, { x: cx + d, y: cy, id: 2 }];
  await t.cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: pts(from) });
  for (let i = 1; i <= steps; i++) await t.cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: pts(from + (to - from) * i / steps) });
  await t.cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await sleep(300);
  await t.frames(2);
}

/** Centres `selector` in the viewport and returns its bounding box (viewport px). */
async function centre(t, selector) {
  await t.page.$eval(selector, (e) => e.scrollIntoView({ block: 'center', behavior: 'instant' }));
  await sleep(100);
  return t.page.$eval(selector, (e) => { const r = e.getBoundingClientRect(); return { x: r.left, y: r.top, width: r.width, height: r.height }; });
}

/** A point of a plot2d canvas (viewport px) at least `clear` px from every marker drawn in the last frame. */
async function emptySpot(t, selector, clear = 40) {
  return t.page.$eval(selector, (c, clr) => {
    const r = c.getBoundingClientRect(), p = c.splinePlot;
    let best = null;
    for (let y = r.height * 0.25; y <= r.height * 0.75; y += 8) {
      for (let x = 30; x <= r.width - 30; x += 8) {
        const d = Math.min(...p.lastMarkers.map((m) => Math.hypot(m.x - x, m.y - y)), Infinity);
        if (!best || d > best.d) best = { x, y, d };
      }
    }
    return best && best.d >= clr ? [r.left + best.x, r.top + best.y] : null;
  }, clear);
}

const CURVE = 'canvas[aria-label^="B-spline curve"]';

test('2D plot: a vertical swipe off the handles scrolls the page; a finger on a handle drags it; two fingers zoom', async () => {
  const t = await openPhone('#bspline-basics');
  const sel = (await t.page.$(CURVE)) ? CURVE : '.plot-canvas';
  await centre(t, sel);
  const spot = await emptySpot(t, sel);
  assert.ok(spot, 'the plot has a spot away from the handles');
  const view0 = await t.plotEval(sel, (p) => p.getView());
  const y0 = await scrollY(t);
  await swipe(t, spot, [spot[0], spot[1] - 220]);
  const y1 = await scrollY(t);
  assert.ok(y1 - y0 > 80, `the page scrolled: ${y0} → ${y1}`);
  assert.deepEqual(await t.plotEval(sel, (p) => p.getView()), view0, 'the swipe did not pan the plot');

  // a finger on a handle drags it, and the page stays
  await centre(t, sel);
  const hs = await t.handles(sel);
  const k = Math.floor(hs.length / 2);
  const from = hs[k].point;
  const [px, py] = await t.worldToPage(sel, from);
  const ys = await scrollY(t);
  await swipe(t, [px, py], [px + 30, py - 60]);
  const to = (await t.handles(sel))[k].point;
  assert.equal(await scrollY(t), ys, 'dragging a handle does not scroll the page');
  assert.ok(to[1] > from[1] + 0.1 && to[0] > from[0], `the handle moved up and right: ${from} → ${to}`);
  await t.flushState();
  const st = await t.state();
  assert.deepEqual(st.points[k].map((v) => Number(v.toFixed(6))), to.map((v) => Number(v.toFixed(6))), 'the state point moved with it');

  // two fingers: pinch zooms the plot, the page stays
  await centre(t, sel);
  const spot2 = await emptySpot(t, sel, 20);
  const yp = await scrollY(t);
  const v0 = await t.plotEval(sel, (p) => p.getView());
  await pinch(t, spot2);
  const v1 = await t.plotEval(sel, (p) => p.getView());
  assert.equal(await scrollY(t), yp, 'a pinch does not scroll the page');
  assert.ok((v1.xmax - v1.xmin) < 0.7 * (v0.xmax - v0.xmin), `the pinch zoomed in: ${v0.xmax - v0.xmin} → ${v1.xmax - v1.xmin}`);
  t.assertClean();
  await t.done();
});

test('3D view: swipes scroll the page until a tap activates it; then a swipe orbits; a tap outside releases it', async () => {
  const t = await openPhone('#quasi-cubic-surfaces');
  const sel = 'canvas[data-plot="surface3d"]';
  const cam = () => t.page.$eval(sel, (c) => c.view3d.getView());
  const state = () => t.page.$eval(sel, (c) => ({ active: c.view3d.touchActive, touchAction: getComputedStyle(c).touchAction,
    hint: !c.closest('.sl-view3d').querySelector('.sl-view3d-tap').hidden }));
  let box = await centre(t, sel);
  assert.ok(box.width >= 300, `the 3D view uses the width: ${box.width}`);
  assert.ok(box.height <= box.width * 1.1 + 1, `its height follows the width: ${box.width} × ${box.height}`);
  const c0 = await cam();
  let s = await state();
  assert.deepEqual([s.active, s.touchAction], [false, 'pan-y'], 'inactive at first');
  const mid = [box.x + box.width / 2, box.y + box.height / 2];
  const y0 = await scrollY(t);
  await swipe(t, mid, [mid[0], mid[1] - 200]);
  const y1 = await scrollY(t);
  assert.ok(y1 - y0 > 80, `a swipe over the inactive view scrolls the page: ${y0} → ${y1}`);
  assert.deepEqual(await cam(), c0, 'and leaves the camera alone');
  assert.ok((await state()).hint, '"Tap to rotate" is shown');

  box = await centre(t, sel);
  const m2 = [box.x + box.width / 2, box.y + box.height / 2];
  await tap(t, m2);
  s = await state();
  assert.deepEqual([s.active, s.touchAction, s.hint], [true, 'none', false], 'a tap activates the view');
  const ya = await scrollY(t);
  await swipe(t, [m2[0] - 80, m2[1]], [m2[0] + 40, m2[1] - 60]);
  const c1 = await cam();
  assert.ok(Math.abs(c1.yaw - c0.yaw) > 5, `the swipe orbits: yaw ${c0.yaw} → ${c1.yaw}`);
  assert.equal(await scrollY(t), ya, 'the page stays while the view is active');

  // a tap outside (above the view) gives swipes back to the page
  await tap(t, [box.x + 20, Math.max(5, box.y - 20)]);
  s = await state();
  assert.deepEqual([s.active, s.touchAction], [false, 'pan-y'], 'a tap outside deactivates the view');
  t.assertClean();
  await t.done();
});

/** The page's width at 390 px (its scroll width, three frames after it is ready), checked clean, page closed. */
async function phoneWidth(t) {
  await t.frames(3);
  const w = await t.page.evaluate(() => document.documentElement.scrollWidth);
  t.assertClean();
  await (t.done ? t.done() : t.close());
  return w;
}

test('no demo scrolls sideways at 390 px', async () => {
  const wide = [];
  for (const id of await demoIds()) {
    const w = await phoneWidth(await openPhone(`#${id}`));
    if (w > 390) wide.push(`${id}: ${w}px`);
  }
  assert.deepEqual(wide, [], 'pages wider than the phone');
});

// The other pages too: a teacher reads the guide on a phone (it was 1241 px wide, the API page 866: long code lines
// and table cells widened them)
test('no page scrolls sideways at 390 px: gallery, guide, exercises, papers, sandbox, API', async () => {
  const wide = [];
  // (the guide and the API page are static: no script of theirs says it is ready; the others mark html[data-ready])
  for (const page of ['index.html', 'guide.html', 'exercises.html', 'papers.html', 'sandbox.html', 'api.html']) {
    const still = page === 'guide.html' || page === 'api.html';
    const t = await H.open(page, { ...PHONE, ready: !still });
    if (still) await t.page.waitForLoadState('load');
    const w = await phoneWidth(t);
    if (w > 390) wide.push(`${page}: ${w}px`);
  }
  assert.deepEqual(wide, [], 'pages wider than the phone');
});

// The same on the two laptop sizes, after the demo's worker answers (noisy-data's "Choosing a" sentence arrived with
// the cross-validation sweep and, kept on one line by the readout style, made the page 2104 px wide at 1366).
test('no demo scrolls sideways at 1366×900 or 1280×720', async () => {
  const wide = [];
  for (const viewport of [{ width: 1366, height: 900 }, { width: 1280, height: 720 }]) {
    for (const id of await demoIds()) {
      const t = await H.open(`#${id}`, { viewport });
      await t.settled();
      await t.frames(3);
      const w = await t.page.evaluate(() => document.documentElement.scrollWidth);
      if (w > viewport.width) {
        const what = await t.page.evaluate(() => [...document.querySelectorAll('body *')]
          .find((e) => e.getBoundingClientRect().right > document.documentElement.clientWidth + 1)?.className);
        wide.push(`${id} at ${viewport.width}: ${w}px (.${what})`);
      }
      t.assertClean();
      await t.close();
    }
  }
  assert.deepEqual(wide, [], 'pages wider than the window');
});
