// The "Criss-cross basis" demo: draws B_ij with its support, dragging a knot line or changing i changes the
// drawing and the numbers, picking a cell shows its BB ordinates, no console error.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const require = createRequire(import.meta.url);
const sl = require(join(dirname(fileURLToPath(import.meta.url)), '..', '..', 'pkg-node/splinelab.js'));

const DOMAIN = 'canvas[data-plot="domain"]';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

const knots = async (t, name) => (await t.handles(DOMAIN)).filter((x) => x.name === name).map((x) => x.point);
const table = (t) => t.page.$$eval('.ctl-table tbody tr', (rows) => rows.map((r) => [r.querySelector('th').textContent, Number(r.querySelector('td').textContent)]));
const centre = (t) => t.page.$eval('.ctl-readout-value', (e) => e.textContent);

test('draws B_ij, its support and the BB ordinates of the picked cell', async () => {
  const t = await H.open('#criss-cross-basis');
  const blank = await t.page.$eval(DOMAIN, (c) => { const e = document.createElement('canvas'); e.width = c.width; e.height = c.height; return e.toDataURL(); });
  assert.notEqual(await t.page.$eval(DOMAIN, (c) => c.toDataURL()), blank);
  assert.ok(await t.page.$('.cc-view3d canvas'), 'the 3D view is there');
  assert.equal((await knots(t, 'u knot')).length, 4);
  assert.equal((await knots(t, 'v knot')).length, 3);
  const rows = await table(t);
  assert.equal(rows.length, 13);
  // B_32 on the default knots: the centre value (σ′_3 + σ_4 + τ′_2 + τ_3)/4
  const u = [0, 0.12, 0.4, 0.62, 0.8, 1], v = [0, 0.3, 0.45, 0.75, 1];
  const h = (x, r) => x[r] - x[r - 1];
  const want = (h(u, 2) / (h(u, 2) + h(u, 3)) + h(u, 4) / (h(u, 3) + h(u, 4)) + h(v, 1) / (h(v, 1) + h(v, 2)) + h(v, 3) / (h(v, 2) + h(v, 3))) / 4;
  assert.ok(Math.abs(Number(await centre(t)) - want) < 1e-4, `centre ${await centre(t)} vs ${want}`);
  // the last row is the centre ordinate o of cell (3, 2) = the centre value
  assert.equal(rows[12][0], 'o');
  assert.ok(Math.abs(rows[12][1] - want) < 1e-4, `o = ${rows[12][1]}`);
  await t.screenshot('criss-cross-basis');
  t.assertClean();
  await t.close();
});

test('dragging a knot line changes the drawing, the numbers and the URL', async () => {
  const t = await H.open('#criss-cross-basis');
  const before = await t.canvasHash(DOMAIN);
  const c0 = await centre(t);
  const [, k2] = await knots(t, 'u knot'); // u_2 = 0.4 next to the centre of B_32
  await t.dragWorld(DOMAIN, k2, [0.5, k2[1]]);
  const after = await knots(t, 'u knot');
  assert.ok(Math.abs(after[1][0] - 0.5) < 0.02, `u_2 moved: ${after[1]}`);
  assert.notEqual(await t.canvasHash(DOMAIN), before);
  assert.notEqual(await centre(t), c0);
  await t.waitHash((x) => x.startsWith('#criss-cross-basis/'));
  t.assertClean();
  await t.close();
});

test('changing i moves the support; picking a cell shows its ordinates', async () => {
  const t = await H.open('#criss-cross-basis');
  const before = await t.canvasHash(DOMAIN);
  const rows0 = await table(t);
  // set i = 1 through the slider
  await t.page.$eval('input[type="range"]', (el) => { el.value = '1'; el.dispatchEvent(new Event('input', { bubbles: true })); el.dispatchEvent(new Event('change', { bubbles: true })); });
  assert.notEqual(await t.canvasHash(DOMAIN), before);
  assert.notDeepEqual(await table(t), rows0);
  // click into cell (1, 1): the corner cell of B_12 has only a few non-zero ordinates
  await t.page.$eval(DOMAIN, (c) => c.scrollIntoView({ block: 'center' }));
  const [x, y] = await t.page.$eval(DOMAIN, (c) => c.splinePlot.toScreen(0.05, 0.1));
  const box = await (await t.page.$(DOMAIN)).boundingBox();
  await t.page.mouse.click(box.x + x, box.y + y);
  const rows = await table(t);
  assert.equal(rows.length, 13);
  const nonzero = rows.filter((r) => r[1] !== 0).map((r) => r[0]);
  assert.ok(nonzero.length > 0 && nonzero.length < 13, rows.join('|'));
  t.assertClean();
  await t.close();
});

// The colour map is an image now (issue 13: one drawImage instead of a rectangle per sample); what it shows is
// checked in numbers: at points of the domain clear of every drawn line, marker and label, the pixel must be the
// ramp colour of B_ij(u, v) / max B_ij (the core's values, here from pkg-node; the max over the demo's 61 × 61
// grid), laid over the white domain with opacity 0.85. Outside the support (B_ij = 0) the domain stays white.
test('the colour map shows the core\'s B_ij through the ramp, pixel by pixel', async () => {
  const t = await H.open('#criss-cross-basis');
  await t.page.$eval(DOMAIN, (c) => c.scrollIntoView({ block: 'center' }));
  await t.frames(3);
  const q = { u: [0, 0.12, 0.4, 0.62, 0.8, 1], v: [0, 0.3, 0.45, 0.75, 1], i: 3, j: 2 };
  const vmax = Math.max(...sl.crissCrossBasis({ ...q, samplesU: 61, samplesV: 61 }).values);
  const RAMP = [[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]];
  const ramp = (t) => {
    const x = Math.min(1, Math.max(0, t)) * 4, k = Math.min(3, Math.floor(x)), f = x - k;
    return RAMP[k].map((a, c) => a + (RAMP[k + 1][c] - a) * f);
  };
  // candidate points: clear of the grid lines and diagonals (≥ 7 px), markers and labels, inside [0, 1]² and
  // right of the v axis's tick labels (u > 0.07)
  const cands = [];
  for (let a = 3; a < 40; a++) for (let b = 1; b < 40; b++) cands.push([a / 40, b / 40]);
  const clear = await t.page.$eval(DOMAIN, (c, [cands, U, V]) => {
    const p = c.splinePlot, [sx, sy] = [(x) => p.toScreen(x, 0)[0], (y) => p.toScreen(0, y)[1]];
    const segs = [];
    for (const x of U) segs.push([x, 0, x, 1]);
    for (const y of V) segs.push([0, y, 1, y]);
    for (let a = 1; a < U.length; a++) for (let b = 1; b < V.length; b++) segs.push([U[a - 1], V[b - 1], U[a], V[b]], [U[a], V[b - 1], U[a - 1], V[b]]);
    const dist = (X, Y, [x0, y0, x1, y1]) => {
      const [ax, ay, bx, by] = [sx(x0), sy(y0), sx(x1), sy(y1)];
      const L = (bx - ax) ** 2 + (by - ay) ** 2, s = Math.max(0, Math.min(1, ((X - ax) * (bx - ax) + (Y - ay) * (by - ay)) / L));
      return Math.hypot(X - ax - s * (bx - ax), Y - ay - s * (by - ay));
    };
    const dpr = c.width / p.width, g = c.getContext('2d');
    return cands.map(([u, v]) => {
      const X = sx(u), Y = sy(v);
      if (segs.some((sg) => dist(X, Y, sg) < 7)) return null;
      if (p.lastMarkers.some((m) => Math.hypot(X - m.x, Y - m.y) < m.r + 6)) return null;
      if (p.lastLabels.some((l) => X > l.x - 6 && X < l.x + l.w + 6 && Y > l.y - 6 && Y < l.y + l.h + 6)) return null;
      return [u, v, [...g.getImageData(Math.round(X * dpr), Math.round(Y * dpr), 1, 1).data]];
    }).filter(Boolean);
  }, [cands, q.u, q.v]);
  const vals = sl.crissCrossBasis({ ...q, atUV: clear.map(([u, v]) => [u, v]) }).values;
  let inside = 0, outside = 0, worst = 0, at = null;
  clear.forEach(([u, v, px], k) => {
    const val = vals[k];
    if (val > 0.02 * vmax) {
      inside++;
      const want = ramp(val / vmax).map((c) => 0.85 * c + 0.15 * 255);
      const d = Math.max(...want.map((c, i) => Math.abs(c - px[i])));
      if (d > worst) { worst = d; at = { u, v, val, want: want.map(Math.round), got: px.slice(0, 3) }; }
    } else if (val === 0) {
      outside++;
      const d = Math.max(...px.slice(0, 3).map((c) => 255 - c));
      if (d > worst) { worst = d; at = { u, v, val, want: [255, 255, 255], got: px.slice(0, 3) }; }
    }
  });
  assert.ok(inside >= 100 && outside >= 100, `points checked: ${inside} in the support, ${outside} outside`);
  assert.ok(worst <= 8, `largest colour difference ${worst.toFixed(1)} / 255 at ${JSON.stringify(at)}`);
  t.assertClean();
  await t.close();
});
