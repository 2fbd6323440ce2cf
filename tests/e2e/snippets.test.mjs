// "Copy as code" round trip for every demo: open the demo in the real page, record what the page computed (the
// Export row's JSON "computed" data, or its CSV where the JSON holds no samples), take the code the "Copy as
// code" button produces, run it in Node against pkg-node exactly as its header says
// (`new Function('sl', code)(require(…))`) and compare the numbers to 1e-12. Also: the "Open in sandbox" link
// holds the same code (base64url, no padding), the clipboard path shows a confirmation and a blocked clipboard
// falls back to a selected text area.
//
//   node --test --test-concurrency=1 tests/e2e/snippets.test.mjs

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { startHarness, demoIds, ROOT } from './harness.mjs';

const require = createRequire(import.meta.url);
const sl = require(join(ROOT, 'pkg-node/splinelab.js'));

let H;
before(async () => { H = await startHarness(); });
after(() => H?.close());

// For each demo: pairs [path in the page's computed JSON, path in the snippet's result]. Every pair must hold
// numbers on both sides (a missing path fails), equal to 1e-12.
const PAIRS = {
  'bspline-basics': [['samples.params', 'curve.params'], ['samples.points', 'curve.points'], ['pointAtU', 'atU.points'], ['basisAtU', 'basisAtU.values']],
  'interp-approx': [['domain', 'curve.domain'], ['knots', 'curve.knots'], ['controlPoints', 'curve.controlPoints'], ['joints', 'curve.joints'],
    ['evenVertices', 'curve.evenVertices'], ['tension', 'curve.tension'], ['samples.params', 'curve.params'], ['samples.points', 'curve.points']],
  'quasi-cubic-curves': [['samples.params', 'curve.params'], ['samples.points', 'curve.points']],
  'blended-interpolation': [['beta', 'curve.beta'], ['curvatureMatchingBeta', 'curvatureMatchingBeta'], ['samples.params', 'curve.params'], ['samples.points', 'curve.points']],
  'b2-surfaces': [['surface.uv', 'surface.uv'], ['surface.points', 'surface.points']],
  'quasi-cubic-surfaces': [['samples.uv', 'surface.uv'], ['samples.points', 'surface.points']],
  'bezier-remodel': [['curve.controlPoints', 'curve.controlPoints'], ['curve.alphas', 'curve.alphas'], ['curve.curvature', 'curve.curvature'],
    ['curve.curvatureOriginal', 'curve.curvatureOriginal'], ['samples.params', 'curve.params'], ['samples.points', 'curve.points']],
  'bezier-remodel/surface': [['surface.controlPoints', 'surface.controlPoints'], ['surface.alphas', 'surface.alphas'], ['surface.uv', 'surface.uv'], ['surface.points', 'surface.points']],
  'knot-modification': [['affectedRange', 'modified.affectedRange'], ['affectedSpans', 'modified.affectedSpans'], ['limits.minus', 'limits.minus'],
    ['limits.plus', 'limits.plus'], ['samples.params', 'modified.params'], ['samples.points', 'modified.points']],
  'knot-modification/surface': [['surface.controlPoints', 'surface.controlPoints'], ['samples.uv', 'modified.uv'], ['samples.points', 'modified.points']],
  'criss-cross-basis': [['cells.ordinates', 'cells.ordinates'], ['cells.domainPoints', 'cells.domainPoints'], ['cells.support', 'cells.support'],
    ['csv.u', 'basis.uv:0/2'], ['csv.v', 'basis.uv:1/2'], ['csv.B', 'basis.values']],
  'curve-networks': [['network.u', 'network.u'], ['network.v', 'network.v'], ['network.P', 'network.P'], ['network.Q', 'network.Q'],
    ['norms.SG', 'norms.SG'], ['norms.ST', 'norms.ST'], ['norms.TG', 'norms.TG'], ['c2', 'c2']],
  'noisy-data': [['data.points', 'points'], ['fitInterpolating.points', 'fitInterpolating.points'], ['fitA.points', 'fitA.points'],
    ['fitA.controlPoints', 'fitA.controlPoints'], ['fitA.rms', 'fitA.rms'], ['sweep.a', 'sweep.a'], ['sweep.rms', 'sweep.rms'], ['sweep.cv', 'sweep.cv'], ['sweep.bestA', 'sweep.bestA']],
  'noisy-data/dataset': [['data.points', 'points'], ['fitInterpolating.points', 'fitInterpolating.points'], ['fitA.points', 'fitA.points'],
    ['fitA.residuals', 'fitA.residuals'], ['sweep.a', 'sweep.a'], ['sweep.cv', 'sweep.cv'], ['sweep.bestCvA', 'sweep.bestCvA']],
};
// views other than the default one: [name, demo id, state overrides]
const VARIANTS = [
  ['b2-surfaces', 'b2-surfaces', { mode: 'blended', shape: 'ripple', a: 0.1 }],
  ['quasi-cubic-surfaces', 'quasi-cubic-surfaces', { shape: 'blended', beta: 2.2 }],
  ['bezier-remodel/surface', 'bezier-remodel', { tab: 'surface' }],
  ['knot-modification/surface', 'knot-modification', { tab: 'surface', smove: 'u' }],
  ['noisy-data/dataset', 'noisy-data', { source: 'dataset', dataset: 'rpn14', a: 0.1 }],
  ['interp-approx', 'interp-approx', { autoEnds: true, autoTension: 'paper', knots: 'chord' }],
  ['curve-networks', 'curve-networks', { preset: 'dome', show: { S: true, T: true, G: true, GB: true }, colorBy: 'SG' }],
];

/** The numbers at `path` ("a.b.c"; "x:k/d" takes every d-th number from offset k), flattened. */
function numbersAt(obj, path) {
  const [p, slice] = path.split(':');
  let v = obj;
  for (const k of p.split('.')) {
    if (v === null || v === undefined) return null;
    v = v[k];
  }
  if (v === null || v === undefined) return null;
  const out = [];
  const walk = (x) => {
    if (typeof x === 'number') out.push(x);
    else if (x === null) out.push(NaN);
    else if (Array.isArray(x) || ArrayBuffer.isView(x)) for (const y of x) walk(y);
    else if (typeof x === 'object') for (const k of Object.keys(x).sort()) walk(x[k]);
    else throw new Error(`${path}: not a number (${typeof x})`);
  };
  walk(v);
  if (!slice) return out;
  const [k, d] = slice.split('/').map(Number);
  return out.filter((_, i) => i % d === k);
}

function assertClose(page, mine, what) {
  assert.ok(page && page.length > 0, `${what}: the page's value is missing or empty`);
  assert.ok(mine, `${what}: the snippet's result lacks it`);
  assert.equal(mine.length, page.length, `${what}: ${mine.length} numbers from the snippet, ${page.length} from the page`);
  let worst = 0, at = -1;
  for (let i = 0; i < page.length; i++) {
    const a = page[i], b = mine[i];
    if (Number.isNaN(a) && !Number.isFinite(b)) continue; // JSON writes NaN/±∞ as null
    const d = Math.abs(a - b) / Math.max(1, Math.abs(a));
    if (!(d <= worst)) { worst = d; at = i; }
  }
  assert.ok(worst <= 1e-12, `${what}: differs by ${worst} at [${at}] (page ${page[at]}, snippet ${mine[at]})`);
  return page.length;
}

/** Clicks an Export-row button and waits until the row has recorded the file (the writers load lazily). */
async function clickExport(page, format) {
  const before = await page.$eval('.export-bar', (r) => Number(r.dataset.exported || 0));
  await page.click(`.export-bar button[data-format="${format}"]`);
  await page.waitForFunction((n) => Number(document.querySelector('.export-bar').dataset.exported || 0) > n, before, { timeout: 15000 });
}

const b64url = (s) => Buffer.from(s, 'utf8').toString('base64url');

/** Opens a demo (with state overrides), returns { computed, state, code, href, t }. */
async function capture(id, overrides) {
  const route = overrides ? `#${id}/v0.${b64url(JSON.stringify(overrides))}` : `#${id}`;
  const t = await H.open(route, { waitFor: '.export-bar .snippet-bar[data-ready="true"]' });
  const page = t.page;
  await clickExport(page, 'json');
  const doc = JSON.parse(await page.$eval('.export-bar', (row) => row.lastExport.text));
  const computed = doc.computed || {};
  if (await page.$('.export-bar button[data-format="csv"]')) {
    await clickExport(page, 'csv');
    const csv = await page.$eval('.export-bar', (row) => row.lastExport.text);
    const [head, ...rows] = csv.trim().split('\n');
    const cols = head.split(',');
    computed.csv = Object.fromEntries(cols.map((c, k) => [c, rows.map((r) => Number(r.split(',')[k]))]));
  }
  await page.click('.export-bar button[data-format="code"]');
  const code = await page.$eval('.export-bar .snippet-bar', (el) => el.lastSnippet);
  await page.hover('.export-bar .snippet-open');
  const href = await page.$eval('.export-bar .snippet-open', (a) => a.href);
  return { computed, state: doc.state, code, href, t };
}

async function roundTrip(name, id, overrides) {
  const { computed, code, href, t } = await capture(id, overrides);
  try {
    assert.match(code, /^\/\/ .*\n/, 'starts with a comment');
    assert.ok(code.includes("// Node: new Function('sl', code)(require('splinelab'))"), 'says how to run it in Node');
    assert.match(code, /return \{[^]*\};?\s*$/, 'ends with return { … }');
    const body = code.split('\n').filter((l) => !l.trim().startsWith('//')).join('\n');
    assert.doesNotMatch(body, /\b(document|window|globalThis|self|fetch|require|import)\b/, 'uses only sl (no imports, globals or DOM)');
    // the sandbox link holds exactly this code
    const m = href.match(/\/sandbox\.html#code=([A-Za-z0-9_-]+)$/);
    assert.ok(m, `sandbox link format: ${href.slice(0, 80)}`);
    assert.equal(Buffer.from(m[1], 'base64url').toString('utf8'), code, 'the sandbox link decodes to the same code');
    const result = new Function('sl', code)(sl);
    assert.equal(typeof result, 'object');
    let n = 0;
    for (const [pagePath, mine] of PAIRS[name]) {
      n += assertClose(numbersAt(computed, pagePath), numbersAt(result, mine), `${name}: ${pagePath} ↔ ${mine}`);
    }
    t.assertClean();
    return n;
  } finally { await t.close(); }
}

test('every demo has a snippet test', async () => {
  for (const id of await demoIds()) assert.ok(PAIRS[id], `no round-trip pairs for ${id}`);
});

for (const id of Object.keys(PAIRS).filter((k) => !k.includes('/'))) {
  test(`round trip: ${id} (default view)`, async () => {
    const n = await roundTrip(id, id, null);
    assert.ok(n > 0);
  });
}

for (const [name, id, over] of VARIANTS) {
  test(`round trip: ${id} ${JSON.stringify(over)}`, async () => {
    const n = await roundTrip(name, id, over);
    assert.ok(n > 0);
  });
}

test('Copy as code: clipboard with a confirmation; blocked clipboard → selected text area', async () => {
  const ctx = await H.browser.newContext({ viewport: { width: 1280, height: 900 } });
  await ctx.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: H.base });
  const t = await H.open('#bspline-basics', { context: ctx, waitFor: '.export-bar .snippet-bar[data-ready="true"]' });
  try {
    await t.page.click('.export-bar button[data-format="code"]');
    await t.page.waitForFunction(() => document.querySelector('.snippet-bar').dataset.copied === '1');
    const clip = await t.page.evaluate(() => navigator.clipboard.readText());
    assert.equal(clip, await t.page.$eval('.snippet-bar', (el) => el.lastSnippet));
    assert.match(await t.page.textContent('.snippet-status'), /Copied \d+ lines/);
    assert.ok(await t.page.$eval('.snippet-fallback', (el) => el.hidden));
    // block the clipboard: the code appears selected in a read-only text area, with a note
    await t.page.evaluate(() => { navigator.clipboard.writeText = () => Promise.reject(new Error('denied')); });
    await t.page.click('.export-bar button[data-format="code"]');
    await t.page.waitForSelector('.snippet-fallback:not([hidden]) textarea');
    const sel = await t.page.$eval('.snippet-fallback textarea', (a) => ({ v: a.value, s: a.selectionStart, e: a.selectionEnd, focused: document.activeElement === a }));
    assert.ok(sel.v.includes('sl.bsplineCurve('));
    assert.equal(sel.e - sel.s, sel.v.length, 'all selected');
    assert.ok(sel.focused);
    assert.match(await t.page.textContent('.snippet-status'), /blocked/);
    t.assertClean();
  } finally { await t.close(); await ctx.close(); }
});
