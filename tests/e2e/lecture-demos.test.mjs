// Issue 19 (lecture-ready demos): legends equal the drawn colours, the Parabola preset, the noisy-data defaults,
// the Export row's slide PNG (2×/4×, legend, caption), adding/removing points by click, and "Play u".
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';
import { PALETTE } from '../../www/lib/plot2d/palette.js';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

const CURVE = 'canvas[data-plot="curve"]';

// ---------------------------------------------------------------- legends

/**
 * In the page: records the colour/dash/alpha of every polyline the plot draws in one repaint, reads the legend's
 * swatches (their computed colour and the colour given to legend()), and counts canvas pixels close to each
 * opaque legend colour.
 */
async function legendVsDrawing(t, canvasSel, legendSel) {
  return t.page.evaluate(([cs, ls]) => {
    const parse = (c) => {
      const m = String(c).match(/rgba?\(([^)]+)\)/);
      if (m) { const v = m[1].split(/[ ,/]+/).filter(Boolean).map(Number); return [v[0], v[1], v[2], v.length > 3 ? v[3] : 1]; }
      const x = String(c).trim().replace('#', '');
      if (/^[0-9a-f]{6}$/i.test(x)) return [parseInt(x.slice(0, 2), 16), parseInt(x.slice(2, 4), 16), parseInt(x.slice(4, 6), 16), 1];
      return null;
    };
    const canvas = document.querySelector(cs);
    const plot = canvas.splinePlot;
    const drawn = [];
    const orig = plot.polyline;
    plot.polyline = (d, st = {}) => { drawn.push({ color: parse(st.color || '#111111'), dash: !!st.dash, alpha: st.alpha ?? 1 }); return orig(d, st); };
    try { plot.paintNow(); } finally { plot.polyline = orig; }
    const swatches = Array.from(document.querySelectorAll(`${ls} .swatch`)).map((sw) => {
      const cs2 = getComputedStyle(sw);
      const img = cs2.backgroundImage;
      const shown = img && img !== 'none' ? parse(img) : parse(cs2.backgroundColor);
      return { label: sw.parentElement.textContent.trim(), kind: sw.dataset.kind, given: parse(sw.dataset.color), shown, opacity: Number(cs2.opacity) };
    });
    // pixels close to a colour (the canvas at device resolution)
    const g = canvas.getContext('2d');
    const px = g.getImageData(0, 0, canvas.width, canvas.height).data;
    const count = (c) => { let n = 0; for (let i = 0; i < px.length; i += 4) if (Math.abs(px[i] - c[0]) + Math.abs(px[i + 1] - c[1]) + Math.abs(px[i + 2] - c[2]) < 24) n++; return n; };
    for (const s of swatches) s.pixels = s.given ? count(s.given) : 0;
    return { drawn, swatches };
  }, [canvasSel, legendSel]);
}

const same = (a, b) => a && b && a.slice(0, 3).every((v, i) => Math.abs(v - b[i]) <= 1);

function assertLegendMatches({ drawn, swatches }, { pixels = [] } = {}) {
  assert.ok(swatches.length >= 3, 'a legend with entries');
  for (const s of swatches) {
    assert.ok(s.given, `${s.label}: the swatch records the colour it was given`);
    assert.ok(same(s.shown, s.given), `${s.label}: the swatch shows ${s.shown} but the legend was given ${s.given}`);
  }
  // every line the plot draws has an entry of its colour (and a dashed one for dashed lines)
  for (const d of drawn) {
    const hit = swatches.filter((s) => same(s.given, d.color) && s.kind !== 'dot');
    assert.ok(hit.length, `a drawn ${d.dash ? 'dashed ' : ''}line of colour ${d.color} has no legend entry: ${swatches.map((s) => `${s.label} ${s.given}`).join('; ')}`);
    if (d.dash) assert.ok(hit.some((s) => s.kind === 'dashed' || s.kind === 'dotted'), `the dashed line ${d.color} has a dashed swatch`);
    if (d.alpha < 1) assert.ok(hit.some((s) => Math.abs(s.opacity - d.alpha) < 0.02), `the translucent line ${d.color} (alpha ${d.alpha}) has a swatch of the same opacity`);
  }
  // every line/dashed entry names something drawn
  for (const s of swatches.filter((x) => x.kind === 'line' || x.kind === 'dashed' || x.kind === 'dotted')) {
    assert.ok(drawn.some((d) => same(d.color, s.given)), `legend entry "${s.label}" (${s.given}) is not drawn`);
  }
  // and the canvas really holds those colours (pixel sampling), for the entries named
  for (const re of pixels) {
    const s = swatches.find((x) => re.test(x.label));
    assert.ok(s, `legend entry ${re}`);
    assert.ok(s.pixels > 20, `${s.label}: ${s.pixels} pixels of ${s.given} on the canvas`);
  }
}

test('interp-approx: the legend equals the drawn colours (dashed a = 1/6 orange, a = 0 green, the data polygon)', async () => {
  const t = await H.open('#interp-approx');
  await t.setInput('input[name="a"]', 0.1); // a ≠ 0: the a = 0 overlay is not hidden under the current curve
  const r = await legendVsDrawing(t, CURVE, '[data-legend-for="curve"]');
  assertLegendMatches(r, { pixels: [/a = 1\/6/, /a = 0/, /data polygon/, /current a/] });
  const labels = r.swatches.map((s) => s.label).join(' | ');
  assert.match(labels, /data polygon/);
  const orange = r.swatches.find((s) => /a = 1\/6/.test(s.label));
  const hex = (c) => [1, 3, 5].map((k) => parseInt(c.slice(k, k + 2), 16));
  assert.deepEqual(orange.shown.slice(0, 3), hex(PALETTE.accent), 'the B-spline swatch is the palette\'s orange');
  assert.equal(orange.kind, 'dashed');
  // with the "how it is built" overlay the legend follows
  await t.page.getByLabel('How it is built').check();
  await t.frames(2);
  assertLegendMatches(await legendVsDrawing(t, CURVE, '[data-legend-for="curve"]'));
  t.assertClean();
  await t.close();
});

test('bezier-remodel: the legend colours equal the osculating circles and the other lines', async () => {
  const t = await H.open('#bezier-remodel');
  const r = await legendVsDrawing(t, CURVE, '[data-legend-for="curve"]');
  assertLegendMatches(r, { pixels: [/remodelled/] });
  const circles = r.swatches.filter((s) => /osculating/.test(s.label));
  const drawnCircles = r.drawn.filter((d) => d.alpha === 0.75);
  assert.equal(circles.length, 1, `one circle (at the joint of Fig. 3), one entry: ${circles.length}`);
  assert.equal(circles.length, new Set(drawnCircles.map((d) => d.color.join())).size, 'as many circle entries as circle colours drawn');
  t.assertClean();
  await t.close();
});

// ---------------------------------------------------------------- noisy data

// the error sweep (and its "best a" readouts) follows the first drawing (start-up, issue 13)
const cvShown = (t) => t.page.waitForFunction(() => [...document.querySelectorAll('.ctl-readout-value')].some((e) => /cross-validation picks a =/.test(e.textContent)), null, { timeout: 20000 });
test('noisy-data: with the default noise the fits differ clearly and both best a sit strictly inside the sweep', async () => {
  const t = await H.open('#noisy-data');
  await cvShown(t);
  const nums = await t.page.$$eval('.plot-numbers', (ps) => ps.map((p) => p.textContent));
  const rms = (s) => Number((s.match(/RMS ([0-9.]+)/) || [])[1]);
  const cv = await t.page.$$eval('.ctl-readout-value', (e) => e.map((x) => x.textContent).join(' '));
  const cvA = Number((cv.match(/cross-validation picks a = (−?\d+(?:\.\d+)?)/) || [])[1]?.replace('−', '-'));
  const bestA = Number((cv.match(/true curve is at a = (−?\d+(?:\.\d+)?)/) || [])[1]?.replace('−', '-'));
  const [lo, hi] = await t.page.$eval('input[name="a"]', (e) => [Number(e.min), Number(e.max)]);
  // the sweep's ends are the slider's ends; the optima are strictly inside (not within one sweep step of an end)
  const step = (hi - lo) / 35;
  for (const [what, a] of [['cross-validation', cvA], ['truth', bestA]]) {
    assert.ok(Number.isFinite(a), `${what}: a readout (${cv})`);
    assert.ok(a > lo + step / 2 && a < hi - step / 2, `${what}: best a = ${a} strictly inside [${lo}, ${hi}]`);
  }
  // the approximating fit (default a) is clearly closer to the truth than the interpolating one. The B2 family is
  // local (L^a blends 3-point averages), so with 60 points a factor of about 1.5 is what it reaches here.
  const [r0, rA] = [rms(nums[0]), rms(nums[1])];
  assert.ok(r0 >= 1.4 * rA, `RMS to the truth: interpolation ${r0} vs approximation ${rA}`);
  // the default a is close to the cross-validated one (the demo opens on a sensible smoothing)
  const a = await t.page.$eval('input[name="a"]', (e) => Number(e.value));
  assert.ok(Math.abs(a - cvA) < 0.08, `default a = ${a} near the CV choice ${cvA}`);
  t.assertClean();
  await t.close();
});

// ---------------------------------------------------------------- add and remove points

const notices = (t) => t.page.$$eval('#notices .notice-text', (e) => e.map((x) => x.textContent).join(' | '));

/** Page coordinates of a world point after scrolling the canvas into view. */
async function at(t, sel, w) {
  await t.page.$eval(sel, (c) => c.scrollIntoView({ block: 'center' }));
  return t.worldToPage(sel, w);
}

test('bspline-basics: double-click adds a control point on the nearest edge, double-click / Delete remove, the minimum holds', async () => {
  const t = await H.open('#bspline-basics');
  const s0 = await t.state();
  const n0 = s0.points.length;
  // a little off the middle of the edge P1–P2, away from the curve and the handles
  const [p1, p2] = [s0.points[1], s0.points[2]];
  const q = [(p1[0] + p2[0]) / 2, (p1[1] + p2[1]) / 2];
  const [x, y] = await at(t, CURVE, q);
  await t.page.mouse.dblclick(x, y);
  await t.frames(2);
  const s1 = await t.state();
  assert.equal(s1.points.length, n0 + 1, 'one point more');
  assert.ok(Math.hypot(s1.points[2][0] - q[0], s1.points[2][1] - q[1]) < 0.05, `inserted between P1 and P2 where clicked: ${JSON.stringify(s1.points[2])}`);
  assert.equal(s1.knots.length, n0 + 1 + s1.degree + 1, 'the clamped knot vector follows (n + p + 1 knots)');
  // double-click on the new point removes it
  const [hx, hy] = await at(t, CURVE, s1.points[2]);
  await t.page.mouse.dblclick(hx, hy);
  await t.frames(2);
  assert.equal((await t.state()).points.length, n0, 'double-click on a point removes it');
  // keyboard: the plot has the focus; ] selects P0 (the first handle), Delete removes it
  await t.page.focus(CURVE);
  await t.page.keyboard.press(']');
  await t.frames(1);
  const sel = await t.plotEval(CURVE, (p) => p.selected && p.selected.index);
  assert.equal(sel, 0, 'focus selects the first point');
  await t.page.keyboard.press('Delete');
  await t.frames(2);
  const s2 = await t.state();
  assert.equal(s2.points.length, n0 - 1, 'Delete removes the selected point');
  assert.deepEqual(s2.points[0], s0.points[1], 'it was P0');
  // down to the minimum p + 1, then a notice and no change
  while ((await t.state()).points.length > s2.degree + 1) await t.page.getByRole('button', { name: 'Remove point' }).click();
  const nMin = (await t.state()).points.length;
  assert.equal(nMin, s2.degree + 1);
  const last = (await t.state()).points[nMin - 1];
  const [lx, ly] = await at(t, CURVE, last);
  await t.page.mouse.dblclick(lx, ly);
  await t.frames(2);
  assert.equal((await t.state()).points.length, nMin, 'not below p + 1 points');
  assert.match(await notices(t), /at least 4 control points/);
  t.assertClean();
  await t.close();
});

test('interp-approx, quasi-cubic-curves, blended-interpolation: add and remove by click, presets that fix the count refuse', async () => {
  // interp-approx: a data point between W3 and W4 (state index 4, 5)
  let t = await H.open('#interp-approx');
  let s = await t.state();
  let n0 = s.points.length;
  let q = [(s.points[4][0] + s.points[5][0]) / 2, (s.points[4][1] + s.points[5][1]) / 2 - 0.2];
  let [x, y] = await at(t, CURVE, q);
  await t.page.mouse.dblclick(x, y);
  await t.frames(2);
  s = await t.state();
  assert.equal(s.points.length, n0 + 1, 'interp-approx: one data point more');
  assert.ok(Math.hypot(s.points[5][0] - q[0], s.points[5][1] - q[1]) < 0.05, 'inserted where clicked, between its neighbours');
  [x, y] = await at(t, CURVE, s.points[5]);
  await t.page.mouse.dblclick(x, y);
  await t.frames(2);
  assert.equal((await t.state()).points.length, n0, 'interp-approx: double-click on the data point removes it');
  // the auxiliary end points are not removed by a double-click
  [x, y] = await at(t, CURVE, s.points[0]);
  await t.page.mouse.dblclick(x, y);
  await t.frames(2);
  assert.equal((await t.state()).points.length, n0, 'an auxiliary point stays');
  t.assertClean();
  await t.close();

  // quasi-cubic-curves: free polygon grows; the parabola preset keeps its 4 points and says why
  t = await H.open('#quasi-cubic-curves');
  s = await t.state();
  n0 = s.points.length;
  q = [(s.points[3][0] + s.points[4][0]) / 2, (s.points[3][1] + s.points[4][1]) / 2];
  [x, y] = await at(t, CURVE, q);
  await t.page.mouse.dblclick(x, y);
  await t.frames(2);
  assert.equal((await t.state()).points.length, n0 + 1, 'quasi-cubic: one point more');
  await t.page.getByRole('radio', { name: 'Parabola' }).evaluate((el) => el.click());
  await t.frames(2);
  s = await t.state();
  assert.equal(s.points.length, 4);
  [x, y] = await at(t, CURVE, s.points[1]);
  await t.page.mouse.dblclick(x, y);
  await t.frames(2);
  assert.equal((await t.state()).points.length, 4, 'the parabola keeps 4 points');
  assert.match(await notices(t), /exactly 4 control points/);
  t.assertClean();
  await t.close();

  // blended-interpolation: β* follows the points
  t = await H.open('#blended-interpolation');
  s = await t.state();
  n0 = s.points.length;
  q = [(s.points[2][0] + s.points[3][0]) / 2, (s.points[2][1] + s.points[3][1]) / 2];
  [x, y] = await at(t, CURVE, q);
  await t.page.mouse.dblclick(x, y);
  await t.frames(2);
  s = await t.state();
  assert.equal(s.points.length, n0 + 1, 'blended: one point more');
  assert.equal(s.beta.length, s.points.length - 2, 'one β* per data point');
  await t.page.getByRole('button', { name: 'Remove point' }).click();
  await t.frames(2);
  s = await t.state();
  assert.equal(s.points.length, n0, 'the Remove button removes the selected point');
  assert.equal(s.beta.length, s.points.length - 2);
  t.assertClean();
  await t.close();
});

// ---------------------------------------------------------------- Play u

test('Play u runs the evaluation point along the domain, Pause stops it; reduced motion steps', async () => {
  for (const id of ['bspline-basics', 'quasi-cubic-curves', 'interp-approx', 'blended-interpolation', 'bezier-remodel']) {
    const t = await H.open(`#${id}`);
    const play = t.page.getByRole('button', { name: /^Play u/ });
    assert.equal(await play.getAttribute('aria-pressed'), 'false', `${id}: a Play u toggle`);
    const u0 = (await t.state()).u;
    const h0 = await t.canvasHash(CURVE);
    await play.click();
    await t.page.waitForTimeout(700);
    assert.equal(await play.getAttribute('aria-pressed'), 'true');
    const u1 = (await t.state()).u;
    assert.ok(u1 !== u0 && Number.isFinite(u1), `${id}: u moved (${u0} → ${u1})`);
    assert.notEqual(await t.canvasHash(CURVE), h0, `${id}: the drawing changed (the marker moved)`);
    if (id !== 'bspline-basics') assert.match(await t.text('[data-readout="u"] .ctl-readout-value'), /u = \d/);
    await play.click();
    assert.equal(await play.getAttribute('aria-pressed'), 'false', 'paused');
    const u2 = (await t.state()).u;
    await t.page.waitForTimeout(400);
    assert.equal((await t.state()).u, u2, `${id}: Pause stops u`);
    t.assertClean();
    await t.close();
  }
  // prefers-reduced-motion: one step per press and about one a second, no animation in between
  const t = await H.open('#bspline-basics', { reducedMotion: 'reduce' });
  const play = t.page.getByRole('button', { name: /^Play u/ });
  await play.click();
  const a = (await t.state()).u;
  assert.ok(Math.abs(a - 0.05) < 1e-9 || a > 0, `one step of 1/20 of the domain at once: ${a}`);
  await t.page.waitForTimeout(300);
  assert.equal((await t.state()).u, a, 'no animation between steps');
  await play.click();
  t.assertClean();
  await t.close();
});

// ---------------------------------------------------------------- export for slides

test('Export: the PNG is re-rendered at 2× and 4×, with the legend and a caption band of dark text', async () => {
  const t = await H.open('#interp-approx');
  const bar = '.export-bar';
  await t.page.hover(bar);
  // the plot's CSS size as it paints it (plot.width × plot.height; the canvas box is that minus the 1 px border
  // of the .plot frame in width) — within 2 px of the element's box
  const css = await t.page.$eval(CURVE, (c) => [c.splinePlot.width, c.splinePlot.height]);
  const box = await t.page.$eval(CURVE, (c) => { const b = c.getBoundingClientRect(); return [b.width, b.height]; });
  assert.ok(Math.abs(box[0] - css[0]) <= 2 && Math.abs(box[1] - css[1]) <= 2, `plot ${css} vs canvas box ${box}`);
  async function png() {
    const before = await t.page.$eval(bar, (r) => Number(r.dataset.exported || 0));
    await t.page.click(`${bar} button[data-format="png"]`);
    await t.page.waitForFunction(([s, n]) => Number(document.querySelector(s).dataset.exported || 0) > n, [bar, before]);
    // decode the downloaded PNG in the page: its size, and the darkest pixels of its bottom band
    return t.page.$eval(bar, async (r) => {
      const { blob, figure, name } = r.lastExport;
      const bmp = await createImageBitmap(blob);
      const c = document.createElement('canvas');
      c.width = bmp.width; c.height = bmp.height;
      const g = c.getContext('2d');
      g.drawImage(bmp, 0, 0);
      const band = Math.round(figure.plotHeight * figure.scale);
      const d = c.height > band ? g.getImageData(0, band, c.width, c.height - band).data : [];
      let dark = 0;
      for (let i = 0; i < d.length; i += 4) if (d[i] + d[i + 1] + d[i + 2] < 200) dark++;
      return { name, w: bmp.width, h: bmp.height, figure, dark };
    });
  }
  // 2× without extras: exactly twice the canvas' CSS size
  await t.page.selectOption(`${bar} select[name="export-scale"]`, '2');
  let r = await png();
  assert.equal(r.name, 'interp-approx.png');
  assert.equal(r.w, 2 * css[0], `2× width: ${r.w} vs ${css[0]}`);
  assert.equal(r.h, 2 * css[1], `2× height: ${r.h} vs ${css[1]}`);
  assert.equal(r.dark, 0, 'no band under the plot');
  // 2× with a caption: the caption band adds to the height and holds dark text
  await t.page.fill(`${bar} input[name="export-caption"]`, 'Fig. 1: interpolation (a = 0) against the cubic B-spline (a = 1/6)');
  r = await png();
  assert.equal(r.w, 2 * css[0]);
  assert.ok(r.h > 2 * css[1] + 30, `caption band: ${r.h} vs ${2 * css[1]}`);
  assert.equal(r.h, 2 * r.figure.cssHeight);
  assert.ok(r.dark > 200, `dark text pixels in the caption band: ${r.dark}`);
  // 4× with the legend and the caption
  await t.page.check(`${bar} input[name="export-legend"]`);
  await t.page.selectOption(`${bar} select[name="export-scale"]`, '4');
  const withCaption = r.h / 2;
  r = await png();
  assert.equal(r.w, 4 * css[0], '4× width');
  assert.ok(r.h / 4 > withCaption + 20, `the legend adds rows: ${r.h / 4} vs ${withCaption}`);
  // the screen canvas is back at its own resolution
  const dpr = await t.page.evaluate(() => window.devicePixelRatio);
  assert.equal(await t.page.$eval(CURVE, (c) => c.width), Math.round(css[0] * dpr), 'the screen canvas is back at its resolution');
  t.assertClean();
  await t.close();
});

// ---------------------------------------------------------------- the parabola preset

test('quasi-cubic-curves: the Parabola preset overlays exactly the arc the spline draws, in view, error ~1e-16', async () => {
  const t = await H.open('#quasi-cubic-curves');
  await t.page.getByRole('radio', { name: 'Parabola' }).evaluate((el) => el.click());
  await t.frames(3);
  const r = await t.page.$eval(CURVE, (c, colors) => {
    const plot = c.splinePlot, lines = [];
    const orig = plot.polyline;
    plot.polyline = (d, st = {}) => { lines.push({ color: st.color, pts: Array.from(d.flat ? d.flat() : d) }); return orig(d, st); };
    try { plot.paintNow(); } finally { plot.polyline = orig; }
    const xr = (a) => { let lo = Infinity, hi = -Infinity; for (let i = 0; i < a.length; i += 2) { lo = Math.min(lo, a[i]); hi = Math.max(hi, a[i]); } return [lo, hi]; };
    const band = lines.find((l) => l.color === colors.accent), curve = lines.find((l) => l.color === colors.curve);
    const v = plot.getView();
    return { band: xr(band.pts), curve: xr(curve.pts), view: [v.xmin, v.xmax, v.ymin, v.ymax], curvePts: curve.pts };
  }, PALETTE);
  const span = r.curve[1] - r.curve[0];
  assert.ok(span > 0.5, 'an arc');
  assert.ok(Math.abs(r.band[0] - r.curve[0]) < 1e-3 * span && Math.abs(r.band[1] - r.curve[1]) < 1e-3 * span, `overlay x-range ${r.band} = the spline's ${r.curve}`);
  // the curve is inside the fitted view
  for (let i = 0; i < r.curvePts.length; i += 2) {
    assert.ok(r.curvePts[i] >= r.view[0] && r.curvePts[i] <= r.view[1] && r.curvePts[i + 1] >= r.view[2] && r.curvePts[i + 1] <= r.view[3], 'the arc is in view');
  }
  const dev = Number(await t.text('[data-readout="deviation"] .ctl-readout-value'));
  assert.ok(dev < 1e-14, `max deviation ${dev}`);
  t.assertClean();
  await t.close();
});

test('knot-modification: Play uₚ moves the knot (the family follows), Pause stops it', async () => {
  const t = await H.open('#knot-modification');
  const play = t.page.getByRole('button', { name: /^Play uₚ/ });
  const u0 = (await t.state()).up;
  const h0 = await t.canvasHash(CURVE);
  await play.click();
  await t.page.waitForTimeout(700);
  const u1 = (await t.state()).up;
  assert.ok(u1 !== u0, `u_p moved: ${u0} → ${u1}`);
  assert.notEqual(await t.canvasHash(CURVE), h0, 'the drawing follows');
  await play.click();
  const u2 = (await t.state()).up;
  await t.page.waitForTimeout(400);
  assert.equal((await t.state()).up, u2, 'paused');
  t.assertClean();
  await t.close();
});

test('Export of a 3D view: re-rendered at 2× (View3D caps its pixel ratio at 2), devicePixelRatio restored', async () => {
  const t = await H.open('#quasi-cubic-surfaces', { deviceScaleFactor: 1 });
  const bar = '.export-bar';
  await t.page.hover(bar);
  await t.page.selectOption(`${bar} select[name="export-scale"]`, '4');
  const css = await t.page.$eval('canvas', (c) => [c.clientWidth, c.clientHeight]);
  const before = await t.page.$eval(bar, (r) => Number(r.dataset.exported || 0));
  await t.page.click(`${bar} button[data-format="png"]`);
  await t.page.waitForFunction(([s, n]) => Number(document.querySelector(s).dataset.exported || 0) > n, [bar, before]);
  const r = await t.page.$eval(bar, async (row) => { const b = await createImageBitmap(row.lastExport.blob); return { w: b.width, h: b.height, fig: row.lastExport.figure }; });
  assert.equal(r.fig.scale, 2, 'a 3D view reaches 2×');
  assert.equal(r.w, 2 * css[0]);
  assert.equal(await t.page.evaluate(() => window.devicePixelRatio), 1, 'devicePixelRatio is the device\'s again');
  assert.equal(await t.page.evaluate(() => typeof Object.getOwnPropertyDescriptor(window, 'devicePixelRatio')?.get), 'function');
  t.assertClean();
  await t.close();
});
