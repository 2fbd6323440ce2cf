// Export = screen: the figure a reader downloads shows what the page shows. For every demo with a 2D plot, the
// Export row's PNG at 1×, 2× and 4× is decoded and compared with the on-screen canvas (1366×900, device pixel
// ratio 1, so the screen canvas is in CSS px): the axis lines, the grid lines, the dark ink of tick numbers and
// labels, and the colour at every handle must sit at k × their screen position (within 1 CSS px). The SVG of
// every visible plot is parsed: its axis and grid lines lie on the screen's, its tick numbers at the world
// positions they name (plot.sx / plot.sy of the number), and a marker is centred on every handle.
// Run: node --test --test-concurrency=1 tests/e2e/export-screen.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { writeFile, mkdir } from 'node:fs/promises';
import { join } from 'node:path';
import { startHarness, demoIds, demoExists, OUT, WWW } from './harness.mjs';
import { PALETTE } from '../../www/lib/plot2d/palette.js';

const VIEWPORT = { width: 1366, height: 900 };
const BAR = '.export-bar';
let H;
before(async () => { H = await startHarness({ viewport: VIEWPORT }); await mkdir(OUT, { recursive: true }); });
after(async () => { await H?.close(); });

// ---------------------------------------------------------------- in the page: image features

/**
 * Installs window.__exportProbe: feature detectors on RGBA images, shared by the screen canvas and the decoded
 * export. Positions are returned in CSS px (image px / k).
 */
function installProbe() {
  const grey = (d, i, lo, hi) => {
    const r = d[i], g = d[i + 1], b = d[i + 2];
    const mx = Math.max(r, g, b), mn = Math.min(r, g, b);
    return mx - mn <= 14 && mx >= lo && mx <= hi;
  };
  // the plot's colours (www/lib/plot2d/palette.js): axis #7a7a7a, grid #e3e3e3, tick numbers #444 and ink #111
  const isAxis = (d, i) => grey(d, i, 95, 175);
  const isGrid = (d, i) => grey(d, i, 214, 238);
  const isInk = (d, i) => { const r = d[i], g = d[i + 1], b = d[i + 2]; return Math.max(r, g, b) <= 105 && Math.max(r, g, b) - Math.min(r, g, b) <= 30; };

  /** Centres (CSS px) of the runs of rows (or columns) in which more than `frac` of the pixels match `pred`. */
  function lines(img, k, pred, dir, frac = 0.5) {
    const { data: d, width: w, height: h } = img;
    const n = dir === 'row' ? h : w, len = dir === 'row' ? w : h;
    const count = new Float64Array(n);
    for (let y = 0; y < h; y++) {
      for (let x = 0; x < w; x++) {
        if (pred(d, 4 * (y * w + x))) count[dir === 'row' ? y : x]++;
      }
    }
    const out = [];
    let s = 0, m = 0;
    for (let i = 0; i <= n; i++) {
      if (i < n && count[i] > frac * len) { s += count[i] * (i + 0.5); m += count[i]; continue; }
      if (m) { out.push(s / m / k); s = 0; m = 0; }
    }
    return out;
  }

  /** Integral image of a mask, for "is there a set pixel in this rectangle?" in O(1). */
  function integral(img, pred) {
    const { data: d, width: w, height: h } = img;
    const S = new Uint32Array((w + 1) * (h + 1));
    let total = 0;
    for (let y = 0; y < h; y++) {
      let row = 0;
      for (let x = 0; x < w; x++) {
        const v = pred(d, 4 * (y * w + x)) ? 1 : 0;
        row += v; total += v;
        S[(y + 1) * (w + 1) + x + 1] = S[y * (w + 1) + x + 1] + row;
      }
    }
    const any = (x0, y0, x1, y1) => { // [x0, x1) × [y0, y1), clamped
      x0 = Math.max(0, x0); y0 = Math.max(0, y0); x1 = Math.min(w, x1); y1 = Math.min(h, y1);
      if (x1 <= x0 || y1 <= y0) return false;
      return S[y1 * (w + 1) + x1] - S[y0 * (w + 1) + x1] - S[y1 * (w + 1) + x0] + S[y0 * (w + 1) + x0] > 0;
    };
    return { any, total, w, h };
  }

  /**
   * The dark ink (tick numbers, labels, dark strokes) of the screen image `a` (1×) found in the export `b` (k×) at
   * k × its place, within 1 CSS px, and the other way round: the fractions of ink pixels matched.
   */
  function inkMatch(a, b, k) {
    const A = integral(a, isInk), B = integral(b, isInk);
    let hitA = 0, hitB = 0;
    for (let y = 0; y < a.height; y++) {
      for (let x = 0; x < a.width; x++) {
        if (!isInk(a.data, 4 * (y * a.width + x))) continue;
        if (B.any(k * (x - 1), k * (y - 1), k * (x + 2), k * (y + 2))) hitA++;
      }
    }
    for (let y = 0; y < b.height; y++) {
      for (let x = 0; x < b.width; x++) {
        if (!isInk(b.data, 4 * (y * b.width + x))) continue;
        const X = Math.floor(x / k), Y = Math.floor(y / k);
        if (A.any(X - 1, Y - 1, X + 2, Y + 2)) hitB++;
      }
    }
    return { screenInk: A.total, exportInk: B.total, screenFound: A.total ? hitA / A.total : 1, exportFound: B.total ? hitB / B.total : 1 };
  }

  /** Mean colour of the (2r+1)² pixels around (x, y) of an image (image px). */
  function colourAt(img, x, y, r) {
    const c = [0, 0, 0]; let n = 0;
    for (let j = Math.round(y) - r; j <= Math.round(y) + r; j++) {
      for (let i = Math.round(x) - r; i <= Math.round(x) + r; i++) {
        if (i < 0 || j < 0 || i >= img.width || j >= img.height) continue;
        const o = 4 * (j * img.width + i);
        c[0] += img.data[o]; c[1] += img.data[o + 1]; c[2] += img.data[o + 2]; n++;
      }
    }
    return c.map((v) => Math.round(v / Math.max(1, n)));
  }

  const features = (img, k) => ({
    axisRows: lines(img, k, isAxis, 'row'), axisCols: lines(img, k, isAxis, 'col'),
    gridRows: lines(img, k, isGrid, 'row'), gridCols: lines(img, k, isGrid, 'col'),
  });

  /** A round step (1, 2 or 5 × 10ⁿ) for about `target` ticks over `range` (as www/lib/plot2d/view.js niceStep). */
  function niceStep(range, target) {
    const raw = range / Math.max(1, target);
    const p = Math.pow(10, Math.floor(Math.log10(raw)));
    const m = raw / p;
    return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
  }

  /**
   * Where the plot's world → screen transform puts its axis lines and grid lines (CSS px, line centres), from the
   * plot's view and size only: { axisRows, axisCols, gridRows, gridCols }.
   */
  function expected(plot) {
    const v = plot.getView(), W = plot.width, H = plot.height, o = plot.options;
    const sx = Math.round(plot.sx(0)) + 0.5, sy = Math.round(plot.sy(0)) + 0.5;
    const out = { axisRows: [], axisCols: [], gridRows: [], gridCols: [] };
    if (o.axes && v.ymin <= 0 && v.ymax >= 0) out.axisRows.push(sy);
    if (o.axes && v.xmin <= 0 && v.xmax >= 0) out.axisCols.push(sx);
    if (o.grid) {
      const stepX = niceStep(v.xmax - v.xmin, W / 90), stepY = niceStep(v.ymax - v.ymin, H / 60);
      for (let x = Math.ceil(v.xmin / stepX) * stepX; x <= v.xmax; x += stepX) out.gridCols.push(Math.round(plot.sx(x)) + 0.5);
      for (let y = Math.ceil(v.ymin / stepY) * stepY; y <= v.ymax; y += stepY) out.gridRows.push(Math.round(plot.sy(y)) + 0.5);
    }
    return out;
  }

  /** The plot's screen pixels (repainted now) and what the plot knows: size, ratio, handles on screen. */
  function screen(canvas) {
    const plot = canvas.splinePlot;
    plot.paintNow();
    const img = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height);
    const handles = plot.handles().map((hd) => ({ name: hd.name, index: hd.index, at: plot.toScreen(hd.point[0], hd.point[1]) }))
      .filter((hd) => hd.at.every(Number.isFinite) && hd.at[0] > 6 && hd.at[1] > 6 && hd.at[0] < plot.width - 6 && hd.at[1] < plot.height - 6);
    return { img, W: plot.width, H: plot.height, ratio: plot.pixelRatio || canvas.width / plot.width, handles, expect: expected(plot) };
  }

  async function decode(blob) {
    const bmp = await createImageBitmap(blob);
    const c = document.createElement('canvas');
    c.width = bmp.width; c.height = bmp.height;
    const g = c.getContext('2d', { willReadFrequently: true });
    g.drawImage(bmp, 0, 0);
    return g.getImageData(0, 0, c.width, c.height);
  }

  /**
   * The tick numbers of the plot as drawn (the SVG recorder of www/lib/export.js, CSS px): boxes around each.
   */
  async function tickBoxes(plot) {
    const { plotToSVG } = await import(new URL('lib/export.js', document.baseURI).href);
    const doc = new DOMParser().parseFromString(plotToSVG(plot), 'image/svg+xml');
    const m = document.createElement('canvas').getContext('2d');
    m.font = '12px system-ui, sans-serif';
    return Array.from(doc.querySelectorAll('text')).filter((t) => t.getAttribute('fill') === '#444' && t.getAttribute('font-size') === '12').map((t) => {
      const x = Number(t.getAttribute('x')), y = Number(t.getAttribute('y')), w = m.measureText(t.textContent).width;
      const anchor = t.getAttribute('text-anchor');
      const x0 = anchor === 'middle' ? x - w / 2 : anchor === 'end' ? x - w : x;
      const middle = t.getAttribute('dominant-baseline') === 'central';
      return { text: t.textContent, x0: x0 - 1, x1: x0 + w + 1, y0: middle ? y - 8 : y - 11, y1: middle ? y + 8 : y + 3 };
    });
  }
  const isText = (d, i) => { const r = d[i], g = d[i + 1], b = d[i + 2]; return Math.max(r, g, b) <= 150 && Math.max(r, g, b) - Math.min(r, g, b) <= 30; };
  /** Dark pixels of `img` (scale k) in the CSS-px box. */
  function inkIn(img, k, b) {
    let n = 0;
    for (let y = Math.max(0, Math.floor(b.y0 * k)); y < Math.min(img.height, Math.ceil(b.y1 * k)); y++) {
      for (let x = Math.max(0, Math.floor(b.x0 * k)); x < Math.min(img.width, Math.ceil(b.x1 * k)); x++) if (isText(img.data, 4 * (y * img.width + x))) n++;
    }
    return n / (k * k); // in CSS px²
  }

  /** Compares an exported PNG (Blob, `k`×) of `canvas`'s plot with the plot on screen. */
  async function comparePNG(canvas, blob, k) {
    const ticks = await tickBoxes(canvas.splinePlot);
    const s = screen(canvas);
    const e = await decode(blob);
    const tickInk = ticks.map((b) => ({ text: b.text, box: [b.x0, b.y0].map((v) => Math.round(v)), screen: inkIn(s.img, s.ratio, b), export: inkIn(e, k, b) }));
    const fs = features(s.img, s.ratio), fe = features(e, k);
    const handles = s.handles.map((hd) => ({ ...hd, screen: colourAt(s.img, hd.at[0] * s.ratio - 0.5, hd.at[1] * s.ratio - 0.5, 1), export: colourAt(e, hd.at[0] * k - 0.5, hd.at[1] * k - 0.5, k) }));
    return { size: [e.width, e.height], css: [s.W, s.H], expect: s.expect, tickInk, screen: fs, export: fe, ink: s.ratio === 1 ? inkMatch(s.img, e, k) : null, handles };
  }

  /** The SVG's axis lines, grid lines, tick numbers and filled markers (CSS px), and the screen's features. */
  function compareSVG(canvas, text) {
    const plot = canvas.splinePlot;
    const s = screen(canvas);
    const doc = new DOMParser().parseFromString(text, 'image/svg+xml');
    if (doc.querySelector('parsererror')) return { error: doc.querySelector('parsererror').textContent };
    const root = doc.documentElement;
    const segs = (p) => {
      const out = [];
      const re = /M([-\d.e]+) ([-\d.e]+)L([-\d.e]+) ([-\d.e]+)/g;
      let m;
      while ((m = re.exec(p.getAttribute('d')))) out.push(m.slice(1, 5).map(Number));
      return out;
    };
    const byStroke = (c) => Array.from(doc.querySelectorAll('path')).filter((p) => (p.getAttribute('stroke') || '').toLowerCase() === c);
    const axis = byStroke('#7a7a7a').filter((p) => p.getAttribute('stroke-width') === '1.5').flatMap(segs);
    const grid = byStroke('#e3e3e3').flatMap(segs);
    const vert = (ls) => ls.filter(([x0, , x1]) => x0 === x1).map(([x0]) => x0);
    const horiz = (ls) => ls.filter(([, y0, , y1]) => y0 === y1).map(([, y0]) => y0);
    // tick numbers: 12 px text in #444 (www/lib/plot2d/grid.js); y ticks are left-aligned beside the y axis
    const ticks = Array.from(doc.querySelectorAll('text')).filter((t) => t.getAttribute('fill') === '#444' && t.getAttribute('font-size') === '12')
      .map((t) => {
        const v = Number(t.textContent.replace('−', '-'));
        const x = Number(t.getAttribute('x')), y = Number(t.getAttribute('y'));
        const isY = t.getAttribute('text-anchor') === 'start';
        // where that number is on screen: y ticks at sy(v), x ticks at sx(v) ("0" is right-aligned 4 px left of it)
        const want = isY ? plot.sy(v) : plot.sx(v) - (t.getAttribute('text-anchor') === 'end' ? 4 : 0);
        return { text: t.textContent, axis: isY ? 'y' : 'x', at: isY ? y : x, want };
      }).filter((tk) => Number.isFinite(tk.want)); // a demo's own 12 px grey text is not a number
    // filled closed paths (markers): their bounding boxes
    const markers = Array.from(doc.querySelectorAll('path')).filter((p) => p.getAttribute('fill') !== 'none' && /Z\s*$/.test(p.getAttribute('d') || '')).map((p) => {
      const n = (p.getAttribute('d').match(/[-\d.e]+/g) || []).map(Number);
      let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
      for (let i = 0; i + 1 < n.length; i += 2) { x0 = Math.min(x0, n[i]); x1 = Math.max(x1, n[i]); y0 = Math.min(y0, n[i + 1]); y1 = Math.max(y1, n[i + 1]); }
      return { c: [(x0 + x1) / 2, (y0 + y1) / 2], size: Math.max(x1 - x0, y1 - y0), fill: p.getAttribute('fill') };
    }).filter((m) => m.size >= 5 && m.size <= 40);
    const handles = s.handles.map((hd) => {
      let best = null, bd = Infinity;
      for (const m of markers) { const d = Math.hypot(m.c[0] - hd.at[0], m.c[1] - hd.at[1]); if (d < bd) { bd = d; best = m; } }
      return { ...hd, dist: bd, size: best?.size ?? 0, fill: best?.fill };
    });
    return {
      width: Number(root.getAttribute('width')), height: Number(root.getAttribute('height')), css: [s.W, s.H],
      axisX: vert(axis), axisY: horiz(axis), gridX: vert(grid), gridY: horiz(grid), ticks, handles,
      screen: features(s.img, s.ratio),
      zero: [plot.sx(0), plot.sy(0)], grid: !!plot.options.grid,
      expectAxes: (() => { const v = plot.getView(), a = plot.options.axes; return [a && v.xmin <= 0 && v.xmax >= 0, a && v.ymin <= 0 && v.ymax >= 0]; })(),
    };
  }

  /** The PNG the Export row would make of the plot on `canvas` at k× (for plots that are not the main view). */
  async function sidePNG(canvas, k) {
    const { slideCanvas } = await import(new URL('lib/export.js', document.baseURI).href);
    const fig = slideCanvas(canvas.splinePlot, { scale: k });
    const blob = await new Promise((ok) => fig.toBlob(ok, 'image/png'));
    return comparePNG(canvas, blob, Number(fig.dataset.scale));
  }

  window.__exportProbe = { comparePNG, compareSVG, sidePNG };
}

// ---------------------------------------------------------------- driving the Export row

/** Clicks an Export-row button and waits until the row has recorded the file (row.lastExport). */
async function clickExport(t, selector) {
  const before = await t.page.$eval(BAR, (r) => Number(r.dataset.exported || 0));
  await t.page.click(`${BAR} ${selector}`);
  await t.page.waitForFunction(([s, n]) => Number(document.querySelector(s).dataset.exported || 0) > n, [BAR, before], { timeout: 15000 });
}

/** The visible 2D plots of the open demo: their index among the canvases and whether the PNG exports them. */
async function plotsOf(t) {
  return t.page.evaluate(() => {
    const vis = (c) => c.isConnected && c.getClientRects().length && !c.closest('[hidden]');
    const all = Array.from(document.querySelectorAll('#demo-root canvas')).filter(vis);
    const main = all.find((c) => c.splinePlot || c.view3d) || all[0] || null;
    return all.map((c, i) => ({ i, plot: !!c.splinePlot, main: c === main, label: c.getAttribute('aria-label') || '' }))
      .filter((c) => c.plot);
  });
}

const near = (a, b, tol) => Math.abs(a - b) <= tol;

/** Every line of `want` has one in `got` within `tol` (CSS px); returns the misses. */
function missing(want, got, tol = 1) { return want.filter((w) => !got.some((g) => near(g, w, tol))); }

/** The PNG check for one scale; returns a one-line summary. */
function checkPNG(id, k, r) {
  const where = `${id} PNG ${k}×`;
  assert.deepEqual(r.size, [k * r.css[0], k * r.css[1]], `${where}: size ${r.size} = ${k} × ${r.css}`);
  const s = r.screen, e = r.export, x = r.expect;
  // the axes and the grid lines: where the plot's transform puts them (x), the screen shows them, and the export
  // must show each one the screen shows at k × its place (tolerance 1 CSS px = k image px). Lines a demo draws
  // over them (a fill, a black edge) hide them in both.
  const at = (ls, v) => ls.some((g) => near(g, v, 1));
  const check = (what, want, scr, exp) => {
    const seen = want.filter((v) => at(scr, v));
    const lost = seen.filter((v) => !at(exp, v));
    assert.deepEqual(lost, [], `${where}: ${what} on screen at ${fmtL(seen)} CSS px (the transform puts them at ${fmtL(want)}); the export has them at ${fmtL(exp)} (÷${k})`);
    return seen.length;
  };
  const nAxes = check('x axis (rows)', x.axisRows, s.axisRows, e.axisRows) + check('y axis (columns)', x.axisCols, s.axisCols, e.axisCols);
  // (a grid line next to an axis is under its anti-aliased edge)
  const free = (ls, axes) => ls.filter((v) => !axes.some((a) => near(a, v, 2.5)));
  const nGrid = check('grid rows', free(x.gridRows, x.axisRows), s.gridRows, e.gridRows) + check('grid columns', free(x.gridCols, x.axisCols), s.gridCols, e.gridCols);
  // the tick numbers: each one's ink on screen is in the export's box at k × the place (half of it at least:
  // glyphs at k× are finer than k × the screen's anti-aliased ones)
  const seenTicks = r.tickInk.filter((tk) => tk.screen >= 4);
  const lostTicks = seenTicks.filter((tk) => tk.export < 0.5 * tk.screen);
  assert.deepEqual(lostTicks.map((tk) => `“${tk.text}” at (${tk.box}): ${tk.screen.toFixed(0)} px² of ink on screen, ${tk.export.toFixed(0)} in the export`), [],
    `${where}: tick numbers missing at ${k}× their screen place`);
  // labels and other dark ink: mostly found at k × their screen place (thick black curves differ at the edges)
  if (r.ink && r.ink.screenInk > 20) {
    assert.ok(r.ink.screenFound >= 0.85, `${where}: only ${(100 * r.ink.screenFound).toFixed(1)} % of the screen's dark ink (tick numbers, labels; ${r.ink.screenInk} px) is at ${k}× its place in the export`);
    assert.ok(r.ink.exportFound >= 0.85, `${where}: ${(100 * (1 - r.ink.exportFound)).toFixed(1)} % of the export's dark ink is where the screen has none`);
  }
  // every handle: the export has the handle's colour at k × its screen position
  for (const hd of r.handles) {
    const d = Math.max(...hd.screen.map((v, c) => Math.abs(v - hd.export[c])));
    assert.ok(d <= 48, `${where}: ${hd.name} ${hd.index + 1} at (${hd.at.map((v) => v.toFixed(1))}) is rgb(${hd.screen}) on screen, rgb(${hd.export}) in the export`);
  }
  return `${k}×: axes ${nAxes} grid ${nGrid} ticks ${seenTicks.length} ink ${r.ink ? (100 * r.ink.screenFound).toFixed(1) + '%' : '-'} handles ${r.handles.length}`;
}
const fmtL = (ls) => `[${ls.map((v) => v.toFixed(1)).join(', ')}]`;

/** The SVG check of one plot. */
function checkSVG(id, label, r) {
  const where = `${id} SVG “${label.slice(0, 40)}”`;
  assert.equal(r.error, undefined, `${where}: parses (${r.error})`);
  assert.deepEqual([r.width, r.height], r.css, `${where}: the SVG is the plot's CSS size`);
  const s = r.screen;
  // axis lines: one per axis in view, where the plot's world → screen transform puts x = 0 and y = 0 (what paints
  // the screen; a demo's own grey lines make the screen's pixels ambiguous here, the PNG check compares them)
  assert.equal(r.axisX.length, r.expectAxes[0] ? 1 : 0, `${where}: y axis lines in the SVG at x = ${fmtL(r.axisX)}`);
  assert.equal(r.axisY.length, r.expectAxes[1] ? 1 : 0, `${where}: x axis lines in the SVG at y = ${fmtL(r.axisY)}`);
  for (const x of r.axisX) assert.ok(near(x, r.zero[0], 1), `${where}: SVG y axis at x = ${x}, world x = 0 is at ${r.zero[0].toFixed(2)} on screen`);
  for (const y of r.axisY) assert.ok(near(y, r.zero[1], 1), `${where}: SVG x axis at y = ${y}, world y = 0 is at ${r.zero[1].toFixed(2)} on screen`);
  // grid lines: every one seen on screen is in the SVG (a plot without a grid has none to compare)
  const free = (ls, axes) => ls.filter((v) => !axes.some((a) => near(a, v, 2.5)));
  if (r.grid) assert.deepEqual(missing(free(s.gridCols, s.axisCols), r.gridX), [], `${where}: grid columns on screen ${fmtL(s.gridCols)}, in the SVG ${fmtL(r.gridX)}`);
  if (r.grid) assert.deepEqual(missing(free(s.gridRows, s.axisRows), r.gridY), [], `${where}: grid rows on screen ${fmtL(s.gridRows)}, in the SVG ${fmtL(r.gridY)}`);
  // tick numbers sit where the number is in the plot's world → screen transform
  for (const tk of r.ticks) assert.ok(near(tk.at, tk.want, 0.6), `${where}: tick “${tk.text}” on the ${tk.axis} axis at ${tk.at}, the value is at ${tk.want.toFixed(2)}`);
  // a marker centred on every handle (a triangle's box centre is a quarter of its size off its anchor)
  for (const hd of r.handles) assert.ok(hd.dist <= Math.max(1, 0.25 * hd.size), `${where}: ${hd.name} ${hd.index + 1} at (${hd.at.map((v) => v.toFixed(1))}): nearest SVG marker (${hd.size.toFixed(1)} px) ${hd.dist.toFixed(1)} px away`);
  return `SVG: axes ${fmtL(r.axisX)}|${fmtL(r.axisY)} grid ${r.gridX.length}+${r.gridY.length} ticks ${r.ticks.length} handles ${r.handles.length}`;
}

// ---------------------------------------------------------------- the tests

/** Exports the PNG at k× through the Export row and compares it with the main plot on screen. */
async function pngAt(t, ci, k) {
  await t.page.selectOption(`${BAR} select[name="export-scale"]`, String(k));
  await clickExport(t, 'button[data-format="png"]');
  return t.page.evaluate(async (i) => {
    const c = Array.from(document.querySelectorAll('#demo-root canvas'))[i];
    const row = document.querySelector('.export-bar');
    return window.__exportProbe.comparePNG(c, row.lastExport.blob, Number(row.lastExport.figure.scale));
  }, ci);
}

/** Saves the k× PNG of the current export (for looking at it). */
async function savePNG(t, file) {
  const b64 = await t.page.$eval(BAR, async (row) => {
    const buf = new Uint8Array(await row.lastExport.blob.arrayBuffer());
    let s = ''; for (let i = 0; i < buf.length; i += 0x8000) s += String.fromCharCode(...buf.subarray(i, i + 0x8000));
    return btoa(s);
  });
  await writeFile(join(OUT, file), Buffer.from(b64, 'base64'));
}

test('Export = screen: every 2D demo’s PNG at 1×, 2×, 4× and the SVG of every plot show the axes, grid, ticks and handles where the screen does', async (tt) => {
  const ids = await demoIds();
  let covered = 0;
  for (const id of ids) {
    await tt.test(id, async () => {
      assert.ok(await demoExists(id), `${id}: listed in www/demos/index.js but www/demos/${id}.js is missing (a renamed demo fails, it is not skipped)`);
      const t = await H.open(`#${id}`);
      await t.page.evaluate(installProbe);
      await t.page.hover(BAR);
      await t.frames(2);
      const plots = await plotsOf(t);
      const lines = [];
      const main = plots.find((p) => p.main);
      if (main) {
        covered++;
        for (const k of [1, 2, 4]) {
          const r = await pngAt(t, main.i, k);
          lines.push(checkPNG(id, k, r));
          if (id === 'interp-approx' || id === 'bspline-basics') await savePNG(t, `export-screen-${id}-${k}x.png`);
        }
      }
      // the other plots (a curve demo's basis plot, a 3D demo's parameter plot) through the same figure code
      for (const p of plots.filter((q) => !q.main)) {
        for (const k of [2, 4]) {
          const r = await t.page.evaluate(([i, kk]) => window.__exportProbe.sidePNG(Array.from(document.querySelectorAll('#demo-root canvas'))[i], kk), [p.i, k]);
          lines.push(`plot ${p.i} ` + checkPNG(`${id} “${p.label.slice(0, 30)}”`, k, r));
        }
      }
      // the SVG of every visible plot (the Export row offers one per plot)
      const svgButtons = await t.page.$$eval(`${BAR} button[data-format="svg"]`, (bs) => bs.map((b) => b.dataset.key));
      for (const key of svgButtons) {
        await clickExport(t, `button[data-key="${key.replace(/"/g, '\\"')}"]`);
        const label = key.replace(/^svg\d+:/, '');
        const r = await t.page.evaluate(([lab]) => {
          const vis = (c) => c.isConnected && c.getClientRects().length && !c.closest('[hidden]');
          const cs = Array.from(document.querySelectorAll('#demo-root canvas')).filter((c) => c.splinePlot && vis(c));
          const c = cs.find((x) => (x.getAttribute('aria-label') || '').replace(/\s*\(.*$/, '').slice(0, 80) === lab) || cs[0];
          return window.__exportProbe.compareSVG(c, document.querySelector('.export-bar').lastExport.text);
        }, [label]);
        lines.push(checkSVG(id, label, r));
      }
      console.log(`${id}: ${main ? 'main plot' : 'no 2D main plot'}; ${lines.join(' · ')}`);
      t.assertClean();
      await t.close();
    });
  }
  assert.ok(covered >= 6, `2D demos checked: ${covered}`);
});

test('a HiDPI screen (device pixel ratio 2): the PNG at 1× and 4× of #interp-approx still equals the screen', async () => {
  const t = await H.open('#interp-approx', { deviceScaleFactor: 2 });
  await t.page.evaluate(installProbe);
  await t.page.hover(BAR);
  await t.frames(2);
  const main = (await plotsOf(t)).find((p) => p.main);
  assert.equal(await t.page.evaluate(() => window.devicePixelRatio), 2);
  const lines = [];
  for (const k of [1, 4]) lines.push(checkPNG('interp-approx (dpr 2)', k, await pngAt(t, main.i, k)));
  assert.equal(await t.page.$eval('canvas[data-plot="curve"]', (c) => c.width / c.splinePlot.width), 2, 'the screen canvas is back at 2 device px per CSS px');
  console.log(`interp-approx at dpr 2: ${lines.join(' · ')}`);
  t.assertClean();
  await t.close();
});

// ---------------------------------------------------------------- legends that tell the truth (issue #24, item 14)

/** Opens demo `id` with `patch` merged into its default state. */
async function openWith(id, patch) {
  const { encodeState } = await import(join(WWW, 'lib/state.js'));
  const t0 = await H.open(`#${id}`);
  const st = { ...(await t0.state()), ...patch };
  await t0.close();
  const t = await H.open(`#${id}/${await encodeState(st)}`);
  await t.frames(3);
  return t;
}

/** Paints the plot once and records its polylines ({ color, width, alpha, pts: screen px }) and labels, in order. */
function recordPlot(canvas) {
  const plot = canvas.splinePlot, lines = [], labels = [];
  const poly = plot.polyline, lab = plot.label;
  const flat = (d) => Array.from(Array.isArray(d) && Array.isArray(d[0]) ? d.flat() : d);
  plot.polyline = (d, st = {}) => {
    const f = flat(d), pts = [];
    for (let i = 0; i + 1 < f.length; i += 2) pts.push(plot.toScreen(f[i], f[i + 1]));
    lines.push({ color: st.color, width: st.width ?? 2, alpha: st.alpha ?? 1, dash: !!st.dash, pts });
    return poly(d, st);
  };
  plot.label = (x, y, s, st = {}) => { labels.push({ text: String(s), color: st.color, at: plot.toScreen(x, y), after: lines.length }); return lab(x, y, s, st); };
  try { plot.paintNow(); } finally { plot.polyline = poly; plot.label = lab; }
  return { lines, labels, W: plot.width, H: plot.height };
}

test('interp-approx, Fig. 6 family with both reference curves: one colour per value, every family label on a curve one can see', async () => {
  const t = await openWith('interp-approx', { family: { key: 'a', values: [-0.1, 0, 0.1, 0.2] }, a: 0, showB: true, showInterp: true, preset: '' });
  // the legend: value → colour (the current curve is a = 0, the overlays a = 1/6 and a = 0)
  const items = await t.page.$$eval('[data-legend-for="curve"] > li', (lis) => lis.map((li) => ({ label: li.textContent.trim(), color: li.querySelector('.swatch')?.dataset.color })));
  const valueOf = (label) => {
    if (/^a = 1\/6/.test(label)) return 1 / 6;
    if (/^a = 0: the interpolating/.test(label)) return 0;
    if (/current a/.test(label)) return 0;
    const m = /^a = (−?[\d.]+)/.exec(label);
    return m ? Number(m[1].replace('−', '-')) : null;
  };
  const curves = items.map((it) => ({ ...it, value: valueOf(it.label) })).filter((it) => it.value !== null);
  assert.ok(curves.length >= 7, `legend entries of curves with a value: ${curves.map((c) => c.label)}`);
  for (const a of curves) {
    for (const b of curves) {
      if (Math.abs(a.value - b.value) > 1e-9) assert.notEqual(a.color.toLowerCase(), b.color.toLowerCase(), `“${a.label}” (a = ${a.value}) and “${b.label}” (a = ${b.value}) share the colour ${a.color}`);
    }
  }
  // the drawing: each family label sits on a curve of its colour that is drawn and not covered by a later one
  const r = await t.page.$eval('canvas[data-plot="curve"]', recordPlot);
  const fam = r.labels.filter((l) => /^a = /.test(l.text));
  assert.equal(fam.length, 4, `four family labels: ${fam.map((l) => l.text)}`);
  const covers = (q, p) => q.width >= p.width && !q.dash && q.alpha >= 0.9 && q.pts.length === p.pts.length && p.pts.every((pt, i) => Math.hypot(pt[0] - q.pts[i][0], pt[1] - q.pts[i][1]) < 0.75);
  for (const l of fam) {
    const inView = l.at[0] >= 0 && l.at[0] <= r.W && l.at[1] >= 0 && l.at[1] <= r.H;
    assert.ok(inView, `label “${l.text}” anchored in view: (${l.at.map((v) => v.toFixed(0))})`);
    const own = r.lines.map((p, i) => ({ p, i })).filter(({ p }) => (p.color || '').toLowerCase() === (l.color || '').toLowerCase());
    const visible = own.filter(({ p, i }) => !r.lines.slice(i + 1).some((q) => covers(q, p)));
    assert.ok(visible.length, `label “${l.text}” (${l.color}): its curve is ${own.length ? 'drawn but covered by a later curve' : 'not drawn'}`);
    const d = Math.min(...visible.flatMap(({ p }) => p.pts.map((pt) => Math.hypot(pt[0] - l.at[0], pt[1] - l.at[1]))));
    assert.ok(d < 2, `label “${l.text}” anchored ${d.toFixed(1)} px from its visible curve`);
  }
  await t.page.locator('[data-legend-for="curve"]').screenshot({ path: join(OUT, 'legend-interp-approx-fig6.png') });
  await t.page.locator('canvas[data-plot="curve"]').screenshot({ path: join(OUT, 'plot-interp-approx-fig6.png') });
  t.assertClean();
  await t.close();
});

test('bezier-remodel: by default one osculating circle, at the joint chosen for Fig. 3; choosing joint 2 moves it', async () => {
  const t = await H.open('#bezier-remodel');
  const circles = async () => (await t.page.$eval('canvas[data-plot="curve"]', recordPlot)).lines.filter((l) => l.alpha === 0.75 && l.pts.length > 100);
  const legendCircles = () => t.page.$$eval('[data-legend-for="curve"] > li', (lis) => lis.map((li) => li.textContent.trim()).filter((s) => /osculating/.test(s)));
  const st = await t.state();
  assert.equal(st.joint, 1);
  assert.equal((await circles()).length, 1, 'one circle drawn');
  assert.deepEqual(await legendCircles(), ['osculating circle at u₁']);
  await t.page.locator('canvas[data-plot="curve"]').screenshot({ path: join(OUT, 'plot-bezier-remodel-circle.png') });
  await t.page.locator('fieldset.ctl', { hasText: 'Fig. 3 at joint I' }).locator('label', { hasText: /^2$/ }).click();
  await t.frames(3);
  assert.equal((await t.state()).joint, 2);
  assert.equal((await circles()).length, 1, 'still one circle');
  assert.deepEqual(await legendCircles(), ['osculating circle at u₂']);
  t.assertClean();
  await t.close();
});

test('b2-surfaces: the surface swatch shows the viridis ramp it is coloured with, plain blue without colours', async () => {
  const t = await H.open('#b2-surfaces');
  const swatch = t.page.locator('#demo-root ul.legend > li').first().locator('.swatch');
  const sample = async () => {
    const png = await swatch.screenshot();
    return t.page.evaluate(async (b64) => {
      const bmp = await createImageBitmap(new Blob([Uint8Array.from(atob(b64), (ch) => ch.charCodeAt(0))], { type: 'image/png' }));
      const c = document.createElement('canvas'); c.width = bmp.width; c.height = bmp.height;
      const g = c.getContext('2d'); g.drawImage(bmp, 0, 0);
      const y = Math.floor(bmp.height / 2);
      const px = (x) => Array.from(g.getImageData(x, y, 1, 1).data.slice(0, 3));
      return { left: px(2), mid: px(Math.floor(bmp.width / 2)), right: px(bmp.width - 3), w: bmp.width };
    }, png.toString('base64'));
  };
  await t.page.locator('#demo-root ul.legend').first().screenshot({ path: join(OUT, 'legend-b2-surfaces.png') });
  let s = await sample();
  const diff = (a, b) => Math.max(...a.map((v, i) => Math.abs(v - b[i])));
  // viridis runs from dark purple (#440154) to yellow (#fde725)
  assert.ok(diff(s.left, [0x44, 0x01, 0x54]) < 60, `left end of the swatch is viridis' low end: rgb(${s.left})`);
  assert.ok(diff(s.right, [0xfd, 0xe7, 0x25]) < 60, `right end of the swatch is viridis' high end: rgb(${s.right})`);
  assert.ok(diff(s.left, s.mid) > 60 && diff(s.mid, s.right) > 60, `a gradient: rgb(${s.left}) → rgb(${s.mid}) → rgb(${s.right})`);
  await t.page.getByRole('switch', { name: 'Colour by height' }).uncheck({ force: true });
  await t.frames(2);
  s = await sample();
  assert.ok(diff(s.left, [1, 3, 5].map((k) => parseInt(PALETTE.sky.slice(k, k + 2), 16))) < 20 && diff(s.right, s.left) < 10, `plain sky blue (the palette's) without colours: rgb(${s.left}) … rgb(${s.right})`);
  assert.match(await t.page.locator('#demo-root ul.legend > li').first().textContent(), /with isolines\)$/);
  t.assertClean();
  await t.close();
});
