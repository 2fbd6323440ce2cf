// The first drawing of a demo is made once (issue 26, start-up): each 2D plot is painted once and each 3D view
// drawn once until the page has nothing left to do, for a demo opened by its name and from a state link (what
// course pages embed). Before, every plot was painted twice in its first frame (its ResizeObserver's first report,
// at the size it already had, repainted it) and every 3D view drew twice (the camera fit of the mount asked for a
// second frame). Counted, not timed: a 2D paint clears the whole canvas (clearRect(0, 0, W, H), www/lib/plot2d.js),
// a 3D drawing clears its WebGL canvas (www/lib/view3d/gl.js renderNow).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { startHarness, WWW } from './harness.mjs';

let H, encodeState;
before(async () => {
  H = await startHarness({ fresh: true /* times a first visit: nothing cached */ });
  ({ encodeState } = await import(join(WWW, 'lib/state.js')));
});
after(() => H?.close());

/** Counts, per canvas, the full clears (2D) and the clears (WebGL2) from the page's start. */
function countDraws() {
  const n = (window.__draws = new Map());
  const bump = (c, k) => { const e = n.get(c) || { d2: 0, gl: 0 }; e[k]++; n.set(c, e); };
  const clearRect = CanvasRenderingContext2D.prototype.clearRect;
  CanvasRenderingContext2D.prototype.clearRect = function (x, y, w, h) {
    const c = this.canvas, t = this.getTransform();
    // (plot2d paints at the device-pixel ratio: the whole canvas is W × H CSS px times that scale)
    if (x === 0 && y === 0 && Math.abs(w * t.a - c.width) < 1 && Math.abs(h * t.d - c.height) < 1) bump(c, 'd2');
    return clearRect.call(this, x, y, w, h);
  };
  const getContext = HTMLCanvasElement.prototype.getContext;
  HTMLCanvasElement.prototype.getContext = function (type, opts) {
    const g = getContext.call(this, type, opts);
    if (type === 'webgl2' && g && !g.__counted) {
      g.__counted = true;
      const clear = g.clear.bind(g);
      g.clear = (mask) => { bump(this, 'gl'); return clear(mask); };
    }
    return g;
  };
}

/** The draws of the demo's visible plots and 3D views, after the page has been idle for a second. */
async function drawsOf(route) {
  const context = await H.browser.newContext({ viewport: { width: 1280, height: 900 } });
  await context.addInitScript(countDraws);
  const t = await H.open(route, { context });
  await t.page.waitForTimeout(1000);
  await t.frames(2);
  const r = await t.page.evaluate(() => {
    const out = [];
    for (const [c, e] of window.__draws) {
      if (!c.isConnected || !c.getClientRects().length || c.closest('[hidden]') || c.width < 2) continue;
      if (c.splinePlot) out.push({ kind: '2d', label: c.getAttribute('aria-label')?.slice(0, 40), draws: e.d2 });
      else if (e.gl) out.push({ kind: '3d', label: c.getAttribute('aria-label')?.slice(0, 40), draws: e.gl });
    }
    return out;
  });
  t.assertClean();
  await context.close();
  return r;
}

const LINKS = {
  'bspline-basics': { u: 0.7 },
  'curve-networks': { show: { S: true, T: false, G: false, GB: true } },
};

for (const [id, over] of Object.entries(LINKS)) {
  test(`${id}: each plot and 3D view is drawn once, opened by name and from a state link`, async () => {
    const mod = await import(join(WWW, 'demos', `${id}.js`));
    // ?warm=0: no idle warm-up (www/lib/warm.js redraws the views on purpose after the first drawing, with the same
    // pixels: tests/e2e/warm-start.test.mjs)
    for (const route of [`?warm=0#${id}`, `embed.html?warm=0#${id}/${await encodeState({ ...mod.defaults(), ...over })}`]) {
      const views = await drawsOf(route);
      console.log(`# ${route.slice(0, 40)}: ${views.map((v) => `${v.kind} ${v.draws}×`).join(', ')}`);
      assert.ok(views.length >= 1, `${route}: a drawn view`);
      for (const v of views) assert.equal(v.draws, 1, `${route}: the ${v.kind} view “${v.label}” was drawn ${v.draws} times`);
    }
  });
}
