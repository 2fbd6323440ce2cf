// Phones: every demo in index.html and embed.html at 390×844 (CSS px, DPR 3) with touch: no horizontal scroll,
// every control reachable (inside the page's width, not covered, big enough to hit), and a real touch drag
// (CDP Input.dispatchTouchEvent, so the browser's own touch → pointer path runs) moves a point in every demo
// that has draggable points (2D plots and 3D views). Swipe-to-scroll outside the drawing is tests/e2e/touch.test.mjs.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness, demoIds } from './harness.mjs';

const PHONE = { viewport: { width: 390, height: 844 }, deviceScaleFactor: 3, isMobile: true, hasTouch: true };

let H, ids;
before(async () => { H = await startHarness(); ids = await demoIds(); });
after(() => H?.close());

const openPhone = (route) => H.open(route, PHONE); // (the harness's shared context for these options)

/** Layout facts of the page at phone size. */
function layout() {
  const W = document.documentElement.clientWidth;
  const bad = [];
  const small = [];
  const sel = 'button, input, select, textarea, a[href], canvas, [tabindex="0"]';
  for (const el of document.querySelectorAll(sel)) {
    if (!el.getClientRects().length || el.closest('[hidden], .visually-hidden, .notices')) continue;
    const cs = getComputedStyle(el);
    if (cs.visibility === 'hidden' || cs.display === 'none' || el.type === 'hidden') continue;
    // custom switches / segment inputs hide the native input (1 px) behind a visible label
    if ((el.type === 'radio' || el.type === 'checkbox') && parseFloat(cs.opacity) === 0) continue;
    const r = el.getBoundingClientRect();
    const name = `${el.tagName.toLowerCase()}${el.className ? '.' + String(el.className).split(' ')[0] : ''}${el.getAttribute('aria-label') ? `[${el.getAttribute('aria-label')}]` : ''}`;
    // inside a horizontally scrolling box (code samples, tab strips) an element may sit beyond the edge
    let scroller = el.parentElement;
    while (scroller && scroller !== document.body && !(/(auto|scroll)/.test(getComputedStyle(scroller).overflowX) && scroller.scrollWidth > scroller.clientWidth)) scroller = scroller.parentElement;
    const inScroller = scroller && scroller !== document.body;
    if (!inScroller && (r.left < -1 || r.right > W + 1)) bad.push(`${name} ${Math.round(r.left)}..${Math.round(r.right)}`);
    if (el.tagName !== 'A' && el.tagName !== 'CANVAS' && (r.width < 20 || r.height < 20)) small.push(`${name} ${Math.round(r.width)}×${Math.round(r.height)}`);
  }
  return {
    W, scrollW: document.documentElement.scrollWidth, bodyScrollW: document.body.scrollWidth,
    bad, small,
  };
}

/** Viewport coordinates of a draggable point: a 2D plot handle or a 3D view point (scrolled to the centre). */
function dragTarget(k) {
  for (const c of document.querySelectorAll('canvas')) {
    if (!c.getClientRects().length) continue;
    if (c.splinePlot && c.splinePlot.handles().length) {
      const hs = c.splinePlot.handles();
      c.scrollIntoView({ block: 'center' });
      const r = c.getBoundingClientRect();
      // the k-th handle that a finger can reach: inside the canvas and not under the controls drawer
      for (let j = Math.min(k, hs.length - 1); j < hs.length; j++) {
        const [x, y] = c.splinePlot.toScreen(hs[j].point[0], hs[j].point[1]);
        if (x < 6 || y < 6 || x > r.width - 6 || y > r.height - 6) continue;
        const hit = document.elementFromPoint(r.left + x, r.top + y);
        if (hit && hit !== c && !c.parentElement.contains(hit)) continue;
        return { x: r.left + x, y: r.top + y, kind: '2D', count: hs.length };
      }
      continue;
    }
    if (c.view3d) {
      const v = c.view3d;
      for (const [id, o] of v.objects) {
        if (o.kind !== 'points' || !o.draggable || !o.positions.length) continue;
        c.scrollIntoView({ block: 'center' });
        const r = c.getBoundingClientRect();
        const n = o.positions.length / 3;
        const p = v.screenPosition(id, Math.min(k + Math.floor(n / 2), n - 1));
        if (p && p[0] > 6 && p[1] > 6 && p[0] < r.width - 6 && p[1] < r.height - 6) return { x: r.left + p[0], y: r.top + p[1], kind: '3D', count: n };
      }
    }
  }
  return null;
}

/** A real touch drag through the browser's input pipeline. */
async function touchDrag(t, [x0, y0], [x1, y1], steps = 8) {
  const cdp = await t.context.newCDPSession(t.page);
  const pt = (x, y) => [{ x: Math.round(x), y: Math.round(y), id: 1, radiusX: 4, radiusY: 4, force: 1 }];
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: pt(x0, y0) });
  for (let i = 1; i <= steps; i++) {
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: pt(x0 + (x1 - x0) * i / steps, y0 + (y1 - y0) * i / steps) });
  }
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await cdp.detach();
  await t.frames(3);
}

for (const page of ['index.html', 'embed.html']) {
  test(`phone 390×844, touch: every demo in ${page} fits the width, its controls are reachable, a touch drag moves a point`, async (tt) => {
    for (const id of ids) {
      await tt.test(id, async () => {
        const t = await openPhone(`${page}#${id}`);
        const L = await t.page.evaluate(layout);
        assert.ok(L.scrollW <= L.W + 1, `${id}: no horizontal scroll (document ${L.scrollW} px > ${L.W} px)`);
        assert.deepEqual(L.bad, [], `${id}: controls outside the screen's width`);
        assert.deepEqual(L.small, [], `${id}: controls too small to hit with a finger`);
        // the page scrolls to every control: the last one can be brought into view
        const lastVisible = await t.page.evaluate(() => {
          const els = [...document.querySelectorAll('#main button, #main input:not([type=hidden]), #main select')].filter((e) => e.getClientRects().length);
          const el = els[els.length - 1];
          if (!el) return true;
          el.scrollIntoView({ block: 'center' });
          const r = el.getBoundingClientRect();
          const hit = document.elementFromPoint(Math.min(r.left + r.width / 2, innerWidth - 1), r.top + r.height / 2);
          return r.top >= 0 && r.bottom <= innerHeight && (hit === el || el.contains(hit) || hit?.contains(el) || hit?.closest('label')?.contains(el) || el.labels?.[0]?.contains(hit));
        });
        assert.ok(lastVisible, `${id}: the last control can be scrolled to and is not covered`);

        const target = await t.page.evaluate(dragTarget, 0);
        if (target) {
          const before = JSON.stringify(await t.state());
          let changed = false;
          for (let k = 0; k < Math.min(3, target.count) && !changed; k++) {
            const p = await t.page.evaluate(dragTarget, k);
            if (!p) continue;
            await touchDrag(t, [p.x, p.y], [p.x + 24, p.y - 18]);
            await t.flushState();
            changed = JSON.stringify(await t.state()) !== before;
          }
          assert.ok(changed, `${id}: a touch drag of a ${target.kind} point changed the state`);
          assert.match(await t.hash(), new RegExp(`^#${id}/v`), `${id}: … and the link`);
        }
        t.assertClean();
        await t.close();
      });
    }
  });
}

test('phone screenshots (tests/e2e/out/phone-*.png)', async () => {
  for (const id of ['bspline-basics', 'b2-surfaces']) {
    const t = await openPhone(`index.html#${id}`);
    await t.screenshot(`phone-${id}`, { fullPage: false });
    await t.close();
  }
});
