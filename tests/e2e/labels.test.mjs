// Labels in the 2D plots do not sit on points: after every frame, the label boxes plot2d drew (plot.lastLabels)
// contain no marker centre of that frame (plot.lastMarkers: handles, points(), marker()) and do not overlap each
// other. Checked over every demo (desktop and phone), over a sweep of u in B-spline basics (the label C(u) used
// to cover P3) and over every figure preset of interpolating vs approximating (W₂ / W₆).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness, demoIds } from './harness.mjs';

let H;
before(async () => { H = await startHarness({ viewport: { width: 1366, height: 800 } }); });
after(async () => { await H?.close(); });

/** Problems of the label layout of every visible plot2d canvas (repainted now). */
function labelProblems(t) {
  return t.page.evaluate(() => {
    const out = [];
    for (const c of document.querySelectorAll('canvas')) {
      if (!c.splinePlot || !c.getClientRects().length) continue;
      const p = c.splinePlot;
      p.paintNow();
      const L = p.lastLabels, M = p.lastMarkers, name = (c.getAttribute('aria-label') || '').slice(0, 40);
      for (const l of L) {
        for (const m of M) {
          if (m.x > l.x && m.x < l.x + l.w && m.y > l.y && m.y < l.y + l.h) out.push(`${name}: "${l.text}" covers a point at (${m.x.toFixed(0)}, ${m.y.toFixed(0)})`);
        }
      }
      for (let i = 0; i < L.length; i++) {
        for (let j = i + 1; j < L.length; j++) {
          const a = L[i], b = L[j];
          if (a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h) out.push(`${name}: "${a.text}" overlaps "${b.text}"`);
        }
      }
    }
    return out;
  });
}

test('every demo, desktop and phone: no label covers a point or another label', async () => {
  const bad = [];
  for (const viewport of [{ width: 1366, height: 800 }, { width: 390, height: 844 }]) {
    for (const id of await demoIds()) {
      const t = await H.open(`#${id}`, { viewport });
      await t.frames(3);
      for (const p of await labelProblems(t)) bad.push(`${viewport.width}px ${id}: ${p}`);
      t.assertClean();
      await t.close();
    }
  }
  assert.deepEqual(bad, []);
});

test('B-spline basics: the label C(u) stays off the control points for every u', async () => {
  const t = await H.open('#bspline-basics');
  const bad = [];
  let labels = 0;
  for (let k = 0; k <= 40; k++) {
    const u = k / 40;
    await t.setInput('xpath=//label[contains(., "Parameter u")]/ancestor::div[contains(@class,"ctl-slider")]//input[@type="range"]', u);
    for (const p of await labelProblems(t)) bad.push(`u = ${u}: ${p}`);
    labels += await t.page.evaluate(() => [...document.querySelectorAll('canvas')].filter((c) => c.splinePlot).reduce((s, c) => s + c.splinePlot.lastLabels.filter((l) => l.text.startsWith('C(')).length, 0));
  }
  assert.ok(labels >= 30, `the C(u) label was drawn (${labels} times)`);
  assert.deepEqual(bad, []);
  t.assertClean();
  await t.close();
});

test('interpolating vs approximating: no label on a point in any figure preset, at a = 0, 1/6 and 0.25', async () => {
  const t = await H.open('#interp-approx');
  const presets = await t.page.$$eval('.preset-row button', (bs) => bs.map((b) => b.textContent));
  assert.ok(presets.length >= 3, `presets: ${presets}`);
  const bad = [];
  for (const name of presets) {
    await t.page.click(`.preset-row button:text-is("${name}")`);
    for (const a of [0, 1 / 6, 0.25]) {
      await t.setInput('xpath=//label[contains(., "Approximation a")]/ancestor::div[contains(@class,"ctl-slider")]//input[@type="range"]', a);
      for (const p of await labelProblems(t)) bad.push(`${name}, a = ${a.toFixed(3)}: ${p}`);
    }
  }
  assert.deepEqual(bad, []);
  t.assertClean();
  await t.close();
});
