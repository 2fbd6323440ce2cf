// Issue 24, item 10: no raw TeX or ASCII notation reaches a reader. Every page (the gallery, each demo with each
// of its tabs and every step of its steppers, the papers page, the exercises and their hints, the guide, the
// sandbox with an example run, the API reference) is scanned where a person reads or hears: visible and hidden
// text (not code), aria-labels, titles, placeholders, aria-valuetext, live regions after a keyboard move, and
// every string drawn on a canvas (labels, ticks, legends, the exported captions, which are drawn the same way).
// Fails on `L^a`, `10^8`, `_{`, `u_p`-style subscripts and `\commands`; and, in what each 2D plot says (its
// description, canvas labels and live region after PageDown chooses a point), on ASCII indices `P0`, `N1`, `W-1`.
// Run: node --test tests/e2e/notation.test.mjs   (needs www/pkg: scripts/build-wasm.sh)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness, demoIds } from './harness.mjs';

let H, IDS;
before(async () => { H = await startHarness(); IDS = await demoIds(); });
after(async () => { await H?.close(); });

import { rawIn, asciiIndexIn } from './raw-notation.mjs';

// every string a canvas draws, recorded before the page's scripts run
const RECORD_CANVAS = () => {
  window.__drawnText = new Set();
  const wrap = (proto) => {
    for (const f of ['fillText', 'strokeText']) {
      const orig = proto[f];
      proto[f] = function (text, ...rest) { try { window.__drawnText.add(String(text)); } catch { /* */ } return orig.call(this, text, ...rest); };
    }
  };
  wrap(CanvasRenderingContext2D.prototype);
  if (typeof OffscreenCanvasRenderingContext2D !== 'undefined') wrap(OffscreenCanvasRenderingContext2D.prototype);
};

/** What a reader meets on the page now: text outside code and formulas, attributes read aloud, canvas strings. */
async function readerStrings(t) {
  return t.page.evaluate(() => {
    const out = [];
    const skip = 'code, pre, textarea, kbd, samp, script, style, math, .sb-editor, .snippet-code';
    const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
    for (let n = walker.nextNode(); n; n = walker.nextNode()) {
      if (n.parentElement?.closest(skip)) continue;
      const s = n.textContent.trim();
      if (s) out.push(s);
    }
    for (const el of document.querySelectorAll('[aria-label], [title], [placeholder], [alt], [aria-valuetext], [aria-roledescription]')) {
      if (el.closest('code, pre, .sb-editor')) continue;
      for (const a of ['aria-label', 'title', 'placeholder', 'alt', 'aria-valuetext', 'aria-roledescription']) if (el.hasAttribute(a)) out.push(el.getAttribute(a));
    }
    out.push(document.title);
    for (const s of window.__drawnText || []) out.push(s);
    return out;
  });
}

async function openRecorded(route, o = {}) {
  // (the harness's shared context for these options, with the canvas recorder as its init script)
  const t = await H.open(route, { viewport: { width: 1366, height: 900 }, ...o, init: RECORD_CANVAS });
  t.closeAll = () => t.close();
  return t;
}

function collect(found, where, strings) {
  for (const s of strings) for (const r of rawIn(s)) found.add(`${where}: ${r}`);
}

/** Every step of every stepper, every tab (button groups named Show/View/tab), each collected. */
async function walkDemo(t, id, found) {
  collect(found, id, await readerStrings(t));
  await walk2DPlots(t, id, found); // the first tab's plots (the last tab's are read at the end)
  // tabs: the first segmented control of the demo whose options switch views
  const tabs = await t.page.$$('#demo-root [role="tab"], #demo-root .demo-tabs button');
  for (const tab of tabs) { if (await tab.isVisible()) { await tab.click(); await t.frames(3); collect(found, id, await readerStrings(t)); } }
  for (const panel of await t.page.$$('#demo-root .stepper')) {
    if (!(await panel.isVisible())) continue;
    const n = Number(await panel.getAttribute('data-steps'));
    for (let k = 0; k < n; k++) {
      const fwd = await panel.$('.step-forward');
      if (await fwd.isDisabled()) break;   // a stepper waiting for its data (the steps are not computed yet)
      await fwd.click();
      await t.frames(2);
      collect(found, id, await readerStrings(t));
    }
    const leave = await panel.$('.step-leave');
    if (!(await leave.isDisabled())) await leave.click();
  }
  // a keyboard move of the first handle: what the live region announces
  const canvas = await t.page.$('#demo-root canvas[tabindex="0"]');
  if (canvas) {
    await canvas.focus();
    await t.page.keyboard.press('PageDown').catch(() => {});
    for (const k of ['ArrowRight', 'ArrowUp', 'ArrowLeft', 'ArrowDown']) await t.page.keyboard.press(k);
    await t.frames(3);
    const live = await t.page.$$eval('[aria-live]', (ls) => ls.map((l) => l.textContent));
    collect(found, `${id} live region`, live);
  }
  await walk2DPlots(t, id, found);
}

/**
 * What each shown 2D plot says and draws: its description and help (the elements its aria-describedby names),
 * its canvas labels (plot.lastLabels) and its live region after PageDown chooses a point — checked for raw
 * notation and for ASCII indices ("P0", "N1", "W-1": ASCII_INDEX in raw-notation.mjs).
 */
async function walk2DPlots(t, id, found) {
  const read = (c) => {
    const ids = (c.getAttribute('aria-describedby') || '').split(/\s+/).filter(Boolean);
    return {
      desc: ids.map((i) => document.getElementById(i)?.textContent || ''),
      labels: (c.splinePlot.lastLabels || []).map((b) => b.text),
      live: c.closest('.plot')?.querySelector('[aria-live]')?.textContent || '',
    };
  };
  for (const c of await t.page.$$('#demo-root canvas')) {
    if (!(await c.evaluate((c) => !!c.splinePlot && c.getClientRects().length > 0))) continue;
    if (await c.evaluate((c) => c.splinePlot.handles().length > 0)) {
      await c.focus();
      await t.page.keyboard.press('PageDown');
      await t.frames(3);
    }
    const r = await c.evaluate(read);
    const where = `${id} 2D plot “${(await c.getAttribute('aria-label') || '').slice(0, 40)}”`;
    for (const s of [...r.desc, ...r.labels, r.live]) {
      for (const bad of [...rawIn(s), ...asciiIndexIn(s)]) found.add(`${where}: ${bad}`);
    }
  }
}

test('no raw notation in any demo: text, labels, canvas strings, steppers, live regions', async () => {
  const found = new Set();
  for (const id of IDS) {
    const t = await openRecorded(`#${id}`);
    await walkDemo(t, id, found);
    t.assertClean();
    await t.closeAll();
  }
  assert.deepEqual([...found], [], `${found.size} raw notation(s):\n${[...found].join('\n')}`);
});

test('no raw notation on the gallery, papers, exercises (tasks and hints), guide, sandbox and API pages', async () => {
  const found = new Set();
  for (const route of ['index.html', 'papers.html', 'exercises.html', 'guide.html', 'api.html']) {
    const t = await openRecorded(route, { ready: route === 'index.html' });
    await t.page.waitForLoadState('load');
    await t.frames(3);
    collect(found, route, await readerStrings(t));
    await t.closeAll();
  }
  // each exercise opened: its panel with task and hint (the hint shown)
  const ex = await openRecorded('exercises.html', { ready: false });
  await ex.page.waitForLoadState('load');
  const hrefs = await ex.page.$$eval('.exercise-card .exercise-open', (as) => as.map((a) => a.getAttribute('href')));
  await ex.closeAll();
  for (const href of hrefs) {
    const t = await openRecorded(href);
    const hint = t.page.locator('.exercise-panel .exercise-hint-toggle, .exercise-panel button:has-text("Hint")').first();
    if (await hint.count()) await hint.click().catch(() => {});
    await t.page.locator('.exercise-panel .exercise-check').click();
    await t.frames(3);
    collect(found, `exercise ${href.slice(0, 40)}`, await readerStrings(t));
    await t.closeAll();
  }
  // the sandbox, every ready example run (legends and labels come from the examples)
  const s = await openRecorded('sandbox.html', { ready: false });
  await s.page.waitForFunction(() => !document.getElementById('sb-run').disabled);
  const ids = await s.page.$$eval('#sb-examples option', (os) => os.map((o) => o.value).filter(Boolean));
  for (const v of ids) {
    const before = await s.page.evaluate(() => Number(document.body.dataset.runs || 0));
    await s.page.selectOption('#sb-examples', v);
    await s.page.click('#sb-run');
    await s.page.waitForFunction((n) => Number(document.body.dataset.runs || 0) > n && document.body.dataset.run !== 'running', before);
    await s.frames(3);
    collect(found, `sandbox ${v}`, await readerStrings(s));
  }
  await s.closeAll();
  assert.deepEqual([...found], [], `${found.size} raw notation(s):\n${[...found].join('\n')}`);
});

test('the scanner itself: it flags each kind of raw notation and passes typeset text', () => {
  for (const bad of ['L^a, the curve', '10^8 times too large', 'W_{i-1}', 'move u_p', 'N_i,p', 'B_ij', 'uses \\alpha', 'C^r joints', 'K*(u_I)', 'knots u_-1..u_n+2']) {
    assert.ok(rawIn(bad).length > 0, `not flagged: ${bad}`);
  }
  for (const ok of ['Lᵃ, the curve', '10⁸ times too large', 'Wᵢ₋₁', 'move uₚ', 'Nᵢ,ₚ', 'splinelab_bg.wasm', 'api-knot_paths', 'snake_case_name', 'a = 1/6', 'x² + y²']) {
    assert.deepEqual(rawIn(ok), [], `flagged: ${ok}`);
  }
  // ASCII indices, looked for in what a 2D plot says and draws (see ASCII_INDEX for what is allowed and why)
  for (const bad of ['P0 (0, 0), P1 (1, 2.2)', 'N1 = 0.016', 'u0', 'data W-1 (−0.6, −0.4)', 'B1,2 on u', 'Selected point b3.', 'C2 continuity', 'u12 = 3']) {
    assert.ok(asciiIndexIn(bad).length > 0, `ASCII index not flagged: ${bad}`);
  }
  for (const ok of ['P₀ (0, 0)', 'N₁ = 0.016', 'W₋₁', 'B₁,₂', 'C²', 'B-spline', 'B2-spline with a = 0', '2D plot', '3D view', 'x1.5', '×2', '1e-5', 'Fig3', '#a1b2c3', 'x-axis', 'u = 0.5']) {
    assert.deepEqual(asciiIndexIn(ok), [], `flagged as an ASCII index: ${ok}`);
  }
});
