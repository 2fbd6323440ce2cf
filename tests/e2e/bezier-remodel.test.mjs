// The "Bézier remodelling" demo (Gânscă–Coman–Ţămbulea): α sliders change the curvature numbers, eq. (9) greys the fixed α,
// presets, the continuity table, dragging a control point, the surface tab, state round-trip through the URL.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

const CURVE = 'canvas[data-plot="curve"]';
const FIG3 = 'canvas[data-plot="fig3"]';
const SURFACE = 'canvas[data-plot="surface"]';
const ROUTE = '#bezier-remodel';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

const curvatureRows = (t) => t.page.$$eval('[data-role="curvature"] tbody tr', (rows) => rows.map((r) => Array.from(r.children, (c) => c.textContent.trim())));
const tableRows = (t, caption) => t.page.$$eval('table', (ts, cap) => {
  const tb = ts.find((x) => x.caption && x.caption.textContent.includes(cap));
  return tb ? Array.from(tb.tBodies[0].rows, (r) => Array.from(r.cells, (c) => c.textContent.trim())) : null;
}, caption);
const num = (s) => Number(String(s).replace('−', '-'));
const alphaInput = (I, k) => `[data-alpha="${I},${k}"] input[type=range]`;
const alphaNumber = (I, k) => `[data-alpha="${I},${k}"] input.ctl-number`;

test('draws the paper example with Fig. 1 parameters; fixed α greyed with their constraint', async () => {
  const t = await H.open(ROUTE);
  const rows = await curvatureRows(t);
  assert.equal(rows.length, 6, 'one row per breakvalue u_0..u_5');
  // K* by (14) equals the measured K* and the right-sided (15), at every breakpoint
  for (const r of rows) {
    assert.ok(Math.abs(num(r[2]) - num(r[3])) < 1e-5 && Math.abs(num(r[2]) - num(r[4])) < 1e-5, r.join(' | '));
  }
  // m = 2, r = 1: α₁⁽ᴵ⁾ for I ≥ 1 is fixed by eq. (9), everything else free
  const free = await t.page.$$eval('[data-alpha]', (els) => els.map((e) => [e.dataset.alpha, e.dataset.free]));
  assert.equal(free.length, 10);
  for (const [key, f] of free) assert.equal(f, String(key === '0,1' || key.endsWith(',2')), key);
  assert.equal(await t.page.$eval(alphaInput(1, 1), (e) => e.disabled), true);
  assert.match(await t.text('[data-alpha="1,1"] .alpha-constraint'), /= 1 − α₂⁽⁰⁾ {2}\(eq\. 9\)/);
  // b*_1 is not shown, but the fixed value is: α₁⁽¹⁾ = 1 − 1/20
  assert.equal(Number(await t.page.$eval(alphaNumber(1, 1), (e) => e.value)), 0.95);
  // g* is C¹: d0, d1 jumps are 0 in the continuity table, d2 is not
  const jumps = await tableRows(t, 'Jumps of g*');
  assert.equal(jumps.length, 4);
  for (const j of jumps) { assert.ok(Math.abs(num(j[2])) < 1e-9, j.join(' ')); assert.ok(num(j[3]) > 1, j.join(' ')); }
  await t.screenshot('bezier-remodel');
  assert.deepEqual(await t.axe(), [], 'no serious accessibility violation');
  t.assertClean();
  await t.close();
});

test('moving one α slider changes the curvature numbers, the fixed α and the drawing', async () => {
  const t = await H.open(ROUTE);
  const rows0 = await curvatureRows(t);
  const curve0 = await t.canvasHash(CURVE);
  const fig30 = await t.canvasHash(FIG3);
  await t.setInput(alphaInput(0, 2), 0.25); // α₂⁽⁰⁾: 1/20 → 1/4
  const rows1 = await curvatureRows(t);
  assert.notDeepEqual(rows1, rows0, 'curvature numbers changed');
  // K*(u_1) = 4/3 · α₂⁽¹⁾/(α₁⁽¹⁾)² · K(u_1) with α₁⁽¹⁾ = 1 − α₂⁽⁰⁾ = 0.75 now: formula and measurement agree
  const [, k, ks, km] = rows1[1];
  assert.ok(Math.abs(num(ks) - num(km)) < 1e-5);
  assert.ok(Math.abs(num(ks) - (4 / 3) * (1 / 3) / 0.75 ** 2 * num(k)) < 2e-5, `${ks} vs formula`);
  assert.equal(Number(await t.page.$eval(alphaNumber(1, 1), (e) => e.value)), 0.75, 'eq. (9) updated α₁⁽¹⁾');
  assert.notEqual(await t.canvasHash(CURVE), curve0);
  assert.notEqual(await t.canvasHash(FIG3), fig30, 'the Fig. 3 dot moved');
  // still C¹
  for (const j of await tableRows(t, 'Jumps of g*')) assert.ok(Math.abs(num(j[2])) < 1e-9);
  await t.waitHash((h) => h.startsWith('#bezier-remodel/'));
  t.assertClean();
  await t.close();
});

test('without eq. (9) a free α₁⁽¹⁾ breaks C¹; r = 0 frees every α', async () => {
  const t = await H.open(ROUTE);
  await t.page.click('label:text-is("Enforce eq. (9)")');
  await t.frames(2);
  assert.equal(await t.page.$eval(alphaInput(1, 1), (e) => e.disabled), false, 'α₁⁽¹⁾ is free now');
  await t.setInput(alphaInput(1, 1), 0.5);
  const jumps = await tableRows(t, 'Jumps of g*');
  assert.ok(num(jumps[0][2]) > 0.1, `d1 jump at u_1: ${jumps[0][2]}`);
  assert.ok(Math.abs(num(jumps[0][1])) < 1e-12, 'still C⁰');
  assert.match(await t.text('[aria-live="polite"].ctl-hint'), /not C¹/);
  await t.page.click('label:text-is("Enforce eq. (9)")');
  await t.page.click('.ctl-segments label:text-is("0")');
  await t.frames(2);
  const disabled = await t.page.$$eval('[data-alpha] input[type=range]', (els) => els.filter((e) => e.disabled).length);
  assert.equal(disabled, 0);
  t.assertClean();
  await t.close();
});

test('presets: Fig. 2, the classical elevation (K* = K) and the quartic with r = 2', async () => {
  const t = await H.open(ROUTE);
  await t.page.click('.ctl-segments label:text-is("Fig. 2")');
  await t.frames(2);
  assert.equal(Number(await t.page.$eval(alphaNumber(3, 2), (e) => e.value)), 0.01);
  await t.page.click('.ctl-segments label:text-is("Classical (g* = g)")');
  await t.frames(2);
  for (const r of await curvatureRows(t)) assert.ok(Math.abs(num(r[1]) - num(r[2])) < 1e-5, `K* = K: ${r.join(' | ')}`);
  await t.page.click('.ctl-segments label:text-is("Quartic from a B-spline")');
  await t.frames(2);
  assert.equal((await curvatureRows(t)).length, 4, 'L = 3 segments');
  // it starts from the classical elevation (g* = g, C³ like the quartic B-spline); move the free α₄⁽⁰⁾
  assert.ok(num((await tableRows(t, 'Jumps of g*'))[0][4]) < 1e-9);
  await t.setInput(alphaInput(0, 4), 0.3);
  const jumps = await tableRows(t, 'Jumps of g*');
  for (const j of jumps) {
    assert.equal(j.length, 5, 'I, d0..d3');
    assert.ok(num(j[3]) < 1e-9, `C² kept: ${j.join(' ')}`);
    assert.ok(num(j[4]) > 1e-6, `C³ lost: ${j.join(' ')}`);
  }
  // with r = 2 the printed interior (15) is right; with r = 1 it is not
  let rows = await curvatureRows(t);
  assert.ok(Math.abs(num(rows[1][4]) - num(rows[1][5])) < 1e-5);
  await t.page.click('.ctl-segments label:text-is("1")');
  await t.setInput(alphaInput(1, 2), 0.2);
  rows = await curvatureRows(t);
  assert.ok(Math.abs(num(rows[1][4]) - num(rows[1][5])) > 1e-3, `printed (15) differs for r = 1: ${rows[1].join(' | ')}`);
  t.assertClean();
  await t.close();
});

test('dragging a control point changes the curve; the link restores the state', async () => {
  const t = await H.open(ROUTE);
  const rows0 = await curvatureRows(t);
  // every drag frame refreshes the tables, the legend and the α sliders: new numbers go into the same elements
  // (www/lib/controls.js table(), dom.js setLegendItems(), alpha-sliders.js), not into a rebuilt DOM
  const kept = () => t.page.evaluate(() => {
    const w = /** @type {any} */ (window);
    const now = {
      cell: document.querySelector('[data-role="curvature"] tbody td'),
      legend: document.querySelector('[data-legend-for="curve"] li'),
    };
    if (!w.__kept) {
      w.__kept = now;
      // a point drag moves no α: their sliders are not written at all
      w.__alphaWrites = 0;
      new MutationObserver((rs) => { w.__alphaWrites += rs.length; }).observe(document.querySelector('.alpha-sliders'), { subtree: true, attributes: true, childList: true, characterData: true });
      return null;
    }
    const same = Object.fromEntries(Object.entries(now).map(([k, el]) => [k, !!el && el === w.__kept[k] && el.isConnected]));
    return { ...same, alphaWrites: w.__alphaWrites };
  });
  await kept();
  await t.dragWorld(CURVE, [-4, 6], [-2, 8]); // b7
  const h = (await t.handles(CURVE)).filter((x) => x.name === 'control point');
  assert.ok(Math.abs(h[7].point[0] + 2) < 0.3 && Math.abs(h[7].point[1] - 8) < 0.3, `b7 moved: ${h[7].point}`);
  assert.notDeepEqual(await curvatureRows(t), rows0);
  assert.deepEqual(await kept(), { cell: true, legend: true, alphaWrites: 0 }, 'a drag rebuilt a table or the legend, or wrote to the α sliders');
  await t.waitHash((x) => x.startsWith('#bezier-remodel/'));
  await new Promise((ok) => setTimeout(ok, 500));
  const url = t.page.url();
  const rows1 = await curvatureRows(t);
  await t.close();
  const t2 = await H.open(url.slice(url.indexOf('#')));
  assert.deepEqual(await curvatureRows(t2), rows1);
  t2.assertClean();
  await t2.close();
});

test('surface tab: Fig. 5 is C¹ in u, the literal all-1/3 reading jumps by 1.5', async () => {
  const t = await H.open(ROUTE);
  await t.page.click('.ctl-segments label:text-is("Surface (§4)")');
  await t.frames(3);
  const s0 = await t.canvasHash(SURFACE);
  let jumps = await tableRows(t, 'across the joint lines');
  assert.equal(jumps.length, 2);
  for (const j of jumps) assert.ok(num(j[2]) < 1e-9, j.join(' '));
  await t.page.click('.ctl-segments label:text-is("Fig. 4 text taken literally")');
  await t.frames(3);
  jumps = await tableRows(t, 'across the joint lines');
  assert.ok(Math.abs(Math.max(num(jumps[0][2]), num(jumps[1][2])) - 1.5) < 1e-3, jumps.map((j) => j.join(' ')).join('; '));
  assert.notEqual(await t.canvasHash(SURFACE), s0);
  await t.screenshot('bezier-remodel-surface');
  assert.deepEqual(await t.axe(), [], 'no serious accessibility violation on the surface tab');
  t.assertClean();
  await t.close();
});

// An import spreads its work over frames (issue 26, www/lib/frame-steps.js; the α sliders four segments per
// frame): a second import that comes in the middle of it wins, and the page ends exactly as with the second import
// alone (the same pixels, views, tables and sliders).
const wavePoints = (k, f) => Array.from({ length: k }, (_, i) => `${i / 2}, ${Math.round(f(i) * 1000) / 1000}`).join('\n');
/** What the person sees once the import's frames are done. */
async function seenCurveTab(t) {
  await t.page.waitForTimeout(500);
  await t.frames(3);
  return t.page.evaluate((plots) => ({
    views: plots.map((s) => JSON.stringify(document.querySelector(s).splinePlot.getView())),
    pixels: plots.map((s) => document.querySelector(s).toDataURL()),
    texts: [...document.querySelectorAll('table, .plot-title, .legend, .ctl-hint, .ctl-readout-value, .data-import-ok')].map((e) => e.textContent),
    sliders: [...document.querySelectorAll('[data-alpha]')].map((e) => `${e.dataset.alpha} ${e.dataset.free} ${e.querySelector('input[type=range]').value} ${e.querySelector('input[type=range]').disabled}`),
  }), [CURVE, FIG3]);
}

test('a second import in the middle of an import wins', async () => {
  const A = wavePoints(25, (i) => Math.sin(i / 3)), B = wavePoints(25, (i) => 2 * Math.cos(i / 4));
  const open = async () => {
    const t = await H.open(ROUTE);
    if (!(await t.page.$eval('.data-import', (d) => d.open))) await t.page.click('.data-import > summary');
    return t;
  };
  const ref = await open();
  await ref.page.fill('.data-import textarea', B);
  await ref.page.click('.data-import [data-action="apply-data"]');
  const b = await seenCurveTab(ref);
  assert.equal(b.sliders.length, 24, 'the α sliders of 12 segments');
  // the stepper's parameter runs over all 12 segments of the import (it kept the example's [0, 4] once)
  const stepsRange = await ref.page.evaluate(() => {
    const label = [...document.querySelectorAll('label')].find((l) => l.textContent.trim().startsWith('Parameter u of the steps'));
    const input = label && /** @type {HTMLInputElement} */ (document.getElementById(label.htmlFor));
    return input && [input.type, input.min, input.max];
  });
  assert.deepEqual(stepsRange, ['range', '0', '12'], 'the steps slider spans u₀ = 0 … u₁₂ = 12');
  await ref.close();

  const t = await open();
  // A, then B as soon as A has built its first α sliders (4 of its 12 segments)
  await t.page.evaluate(([a, bText]) => new Promise((done) => {
    const area = document.querySelector('.data-import textarea');
    const go = document.querySelector('.data-import [data-action="apply-data"]');
    area.value = a; go.click();
    const poll = () => {
      if (document.querySelectorAll('[data-alpha]').length !== 8) { requestAnimationFrame(poll); return; }
      area.value = bText; go.click(); done();
    };
    requestAnimationFrame(poll);
  }), [A, B]);
  const seen = await seenCurveTab(t);
  assert.deepEqual(seen.sliders, b.sliders, 'the α sliders of the second import, all of them');
  assert.deepEqual(seen.texts, b.texts, 'the tables, titles and legend of the second import');
  assert.deepEqual(seen.views, b.views);
  assert.ok(seen.pixels.every((p, i) => p === b.pixels[i]), 'the pixels of the second import alone');
  t.assertClean();
  await t.close();
});
