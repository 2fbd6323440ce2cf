// Forced colours (Windows High Contrast; WCAG 2.2, issue 25) in Chromium, emulated with a dark system palette
// (forcedColors 'active' + colorScheme 'dark', as a "Night sky"-like theme). The browser recolours the page but
// never a canvas's pixels, so what a person must still see is: the figures on a white ground with their curves
// drawn, legend swatches in the figure's colours, the chosen option and the keyboard focus marked in system
// colours, and the page's text readable. One open each of a 2D demo, a 3D demo and the gallery; screenshots in
// tests/e2e/out/forced-*.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { startHarness, OUT } from './harness.mjs';
import { decodePng } from './png-ink.mjs';
import { PALETTE } from '../../www/lib/plot2d/palette.js';

let H;
before(async () => { mkdirSync(OUT, { recursive: true }); H = await startHarness(); });
after(() => H?.close());

/** Opens `route` in a fresh context with forced colours on (dark system palette). */
async function openForced(route, viewport = { width: 1366, height: 900 }) {
  const context = await H.browser.newContext({ viewport, forcedColors: 'active', colorScheme: 'dark', serviceWorkers: 'block' });
  await context.addInitScript(() => { /** @type {any} */ (window).splinelabWarm = 0; });
  const t = await H.open(route, { context });
  assert.equal(await t.page.evaluate(() => matchMedia('(forced-colors: active)').matches), true, 'forced colours are on');
  return { t, context };
}

/** 'rgb(r, g, b)' → [r, g, b]. */
const rgbOf = (css) => (css.match(/\d+(\.\d+)?/g) || []).slice(0, 3).map(Number);
const hexRgb = (hex) => [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
const lum = ([r, g, b]) => {
  const l = (c) => { const s = c / 255; return s <= 0.04045 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4; };
  return 0.2126 * l(r) + 0.7152 * l(g) + 0.0722 * l(b);
};
const contrast = (a, b) => { const [x, y] = [lum(a), lum(b)].sort((p, q) => q - p); return (x + 0.05) / (y + 0.05); };

/** Pixels of an element's screenshot: share of white ones, count near `rgb` (per channel ≤ tol), corner colours. */
async function pixels(locator, path, rgb, tol = 40) {
  const img = decodePng(await locator.screenshot({ path }));
  const { width, height, bpp, pixels: px } = img;
  let white = 0, near = 0;
  for (let i = 0; i < width * height; i++) {
    const r = px[i * bpp], g = px[i * bpp + 1], b = px[i * bpp + 2];
    if (r > 245 && g > 245 && b > 245) white++;
    if (rgb && Math.abs(r - rgb[0]) <= tol && Math.abs(g - rgb[1]) <= tol && Math.abs(b - rgb[2]) <= tol) near++;
  }
  const at = (x, y) => [...px.subarray((y * width + x) * bpp, (y * width + x) * bpp + 3)];
  // corners a few pixels in (the plot's rounded border is drawn by the page, outside the canvas)
  const corners = [at(8, 8), at(width - 9, 8), at(8, height - 9), at(width - 9, height - 9)];
  return { white: white / (width * height), near, corners };
}

test('2D demo (bspline-basics): white plot with the curve, swatches in colour, chosen degree and focus in system colours', async () => {
  const { t, context } = await openForced('#bspline-basics');
  const { page } = t;
  const canvas = page.locator('.plot-canvas').first();
  const style = await canvas.evaluate((el) => { const s = getComputedStyle(el); return { adjust: s.forcedColorAdjust, bg: s.backgroundColor }; });
  assert.equal(style.adjust, 'none', 'the canvas is not recoloured');
  assert.deepEqual(rgbOf(style.bg), [255, 255, 255], 'the canvas keeps its white ground');
  const p = await pixels(canvas, join(OUT, 'forced-bspline-basics-plot.png'), hexRgb(PALETTE.curve));
  // (a corner may fall on a light grey grid line, #e3e3e3; a forced dark ground would be near 0)
  for (const c of p.corners) assert.ok(c.every((v) => v > 200), `plot corner is white, got rgb(${c})`);
  assert.ok(p.white > 0.6, `most of the plot is white (${(p.white * 100).toFixed(1)} %)`);
  assert.ok(p.near > 500, `the curve is drawn in its blue (${p.near} px near ${PALETTE.curve})`);

  // the legend's curve swatch keeps the curve's colour (the forced palette would make it the page's background)
  const sw = await page.locator('.legend .swatch').first().evaluate((el) => { const s = getComputedStyle(el); return { adjust: s.forcedColorAdjust, bg: s.backgroundColor }; });
  assert.equal(sw.adjust, 'none');
  assert.deepEqual(rgbOf(sw.bg), hexRgb(PALETTE.curve), 'the curve swatch is the curve blue');

  // the chosen degree stands out from the others, and the page text is readable on the forced background
  const seg = await page.evaluate(() => {
    const labels = [...document.querySelectorAll('.ctl-segments input + label')];
    const on = labels.find((l) => /** @type {HTMLInputElement} */ (l.previousElementSibling).checked);
    const off = labels.find((l) => !(/** @type {HTMLInputElement} */ (l.previousElementSibling).checked));
    const bg = (el) => getComputedStyle(el).backgroundColor, fg = (el) => getComputedStyle(el).color;
    return { on: bg(on), onText: fg(on), off: bg(off), body: bg(document.body), text: fg(document.body) };
  });
  assert.notDeepEqual(rgbOf(seg.on), rgbOf(seg.off), 'the checked segment has its own background');
  assert.ok(contrast(rgbOf(seg.on), rgbOf(seg.onText)) >= 4.5, `checked segment text ${seg.onText} on ${seg.on}`);
  assert.ok(contrast(rgbOf(seg.body), rgbOf(seg.text)) >= 4.5, `page text ${seg.text} on ${seg.body}`);

  // keyboard focus: a visible ring in a system colour that stands out from the forced background
  await page.keyboard.press('Tab');
  const ring = await page.evaluate(() => {
    const el = /** @type {HTMLElement} */ (document.activeElement); const s = getComputedStyle(el);
    return { tag: el.tagName, style: s.outlineStyle, width: parseFloat(s.outlineWidth), color: s.outlineColor };
  });
  assert.notEqual(ring.style, 'none', `focus ring on ${ring.tag}`);
  assert.ok(ring.width >= 2, `focus ring ${ring.width}px`);
  assert.ok(contrast(rgbOf(ring.color), rgbOf(seg.body)) >= 3, `focus ring ${ring.color} on ${seg.body}`);
  await page.screenshot({ path: join(OUT, 'forced-bspline-basics.png') });
  t.assertClean();
  await context.close();
});

test('3D demo (b2-surfaces): the view keeps its white ground with the surface drawn; swatches keep colour', async () => {
  const { t, context } = await openForced('#b2-surfaces');
  const { page } = t;
  const canvas = page.locator('canvas.sl-view3d-canvas').first();
  // the surface is drawn once the WebGL canvas has more than its clear colour
  await page.waitForFunction(() => {
    const c = /** @type {HTMLCanvasElement} */ (document.querySelector('canvas.sl-view3d-canvas'));
    return c && c.width > 100 && /** @type {any} */ (c).view3d?.objects?.has('S');
  }, null, { timeout: 20000 });
  const p = await pixels(canvas, join(OUT, 'forced-b2-surfaces-view.png'));
  for (const c of p.corners) assert.ok(c.every((v) => v > 235), `3D view corner is white, got rgb(${c})`);
  assert.ok(p.white > 0.4 && p.white < 0.98, `a white ground with a surface on it (${(p.white * 100).toFixed(1)} % white)`);
  const dot = await page.locator('.legend .swatch.dot').first().evaluate((el) => getComputedStyle(el).backgroundColor);
  assert.deepEqual(rgbOf(dot), hexRgb(PALETTE.control), 'grid points swatch is the control colour');
  await page.screenshot({ path: join(OUT, 'forced-b2-surfaces.png') });
  await context.close();
});

test('gallery (index.html): text, links and the focus ring readable in forced colours', async () => {
  const { t, context } = await openForced('');
  const { page } = t;
  const c = await page.evaluate(() => {
    const s = (sel) => { const el = document.querySelector(sel); return el && { fg: getComputedStyle(el).color, bg: getComputedStyle(document.body).backgroundColor }; };
    return { body: s('body'), link: s('a') };
  });
  assert.ok(contrast(rgbOf(c.body.fg), rgbOf(c.body.bg)) >= 4.5, `text ${c.body.fg} on ${c.body.bg}`);
  assert.ok(contrast(rgbOf(c.link.fg), rgbOf(c.link.bg)) >= 4.5, `links ${c.link.fg} on ${c.link.bg}`);
  await page.keyboard.press('Tab');
  const ring = await page.evaluate(() => { const s = getComputedStyle(/** @type {Element} */ (document.activeElement)); return { style: s.outlineStyle, color: s.outlineColor }; });
  assert.notEqual(ring.style, 'none');
  assert.ok(contrast(rgbOf(ring.color), rgbOf(c.body.bg)) >= 3, `focus ring ${ring.color} on ${c.body.bg}`);
  await page.screenshot({ path: join(OUT, 'forced-index.png') });
  await context.close();
});
