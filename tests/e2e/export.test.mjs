// The shell's Export row under every demo: each button downloads a file that parses back (PNG signature and
// size, SVG through DOMParser, JSON with the demo's state and computed data, OBJ v/vn/f counts and face indices,
// CSV rows of numbers). Real downloads (playwright's download event), in headless Chromium, 127.0.0.1 only.
// Run: node --test tests/e2e/export.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { join } from 'node:path';
import { startHarness, demoIds, demoExists, WWW } from './harness.mjs';

let H;
let ids;
let encodeState;
before(async () => {
  H = await startHarness();
  ids = await demoIds();
  ({ encodeState } = await import(join(WWW, 'lib/state.js')));
});
after(async () => { await H?.close(); });

/** Clicks an export button and returns the downloaded file { name, buf }. */
async function grab(t, button) {
  const [dl] = await Promise.all([t.page.waitForEvent('download', { timeout: 15000 }), button.click()]);
  const path = await dl.path();
  return { name: dl.suggestedFilename(), buf: await readFile(path) };
}

/** Validates an SVG text in the page (DOMParser): returns { root, paths, circles, texts } or throws. */
async function parseSVG(t, text) {
  return t.page.evaluate((s) => {
    const doc = new DOMParser().parseFromString(s, 'image/svg+xml');
    if (doc.querySelector('parsererror')) return { error: doc.querySelector('parsererror').textContent };
    const r = doc.documentElement;
    return { root: r.localName, ns: r.namespaceURI, width: Number(r.getAttribute('width')), paths: doc.querySelectorAll('path').length, texts: doc.querySelectorAll('text').length };
  }, text);
}

function checkOBJ(text) {
  const lines = text.split('\n');
  const v = lines.filter((l) => l.startsWith('v ')), vn = lines.filter((l) => l.startsWith('vn ')), f = lines.filter((l) => l.startsWith('f '));
  assert.ok(v.length >= 4, `OBJ: ${v.length} vertices`);
  assert.ok(f.length >= 2, `OBJ: ${f.length} faces`);
  assert.ok(vn.length === 0 || vn.length === v.length, `OBJ: ${vn.length} normals for ${v.length} vertices`);
  for (const l of v) { const c = l.split(' ').slice(1).map(Number); assert.equal(c.length, 3); assert.ok(c.every(Number.isFinite), l); }
  for (const l of f) {
    const idx = l.split(' ').slice(1).map((x) => Number(x.split('/')[0]));
    assert.equal(idx.length, 3, l);
    assert.ok(idx.every((i) => Number.isInteger(i) && i >= 1 && i <= v.length), `face index out of range: ${l}`);
  }
  return { v: v.length, vn: vn.length, f: f.length };
}

function checkCSV(text) {
  const rows = text.trim().split('\n');
  const head = rows[0].split(',');
  assert.ok(head.length >= 2 && head.every((c) => /^[A-Za-z_][\w]*$/.test(c)), `CSV header: ${rows[0]}`);
  assert.ok(rows.length >= 3, 'CSV has data rows');
  for (const r of rows.slice(1)) {
    const c = r.split(',').map(Number);
    assert.equal(c.length, head.length, `CSV row: ${r}`);
    assert.ok(c.every(Number.isFinite), `CSV row: ${r}`);
  }
  return { rows: rows.length - 1, cols: head.length };
}

/** Every button of the Export row: downloads and checks the file. Returns the formats seen. */
async function exportAll(t, id) {
  await t.page.waitForSelector('.export-bar button[data-format="json"]');
  await t.page.hover('.export-bar');
  await t.frames(2);
  const state = await t.state();
  const buttons = await t.page.$$('.export-bar .export-bar-buttons button'); // the downloads (not Copy as code)
  const seen = [];
  for (const b of buttons) {
    const fmt = await b.getAttribute('data-format');
    const { name, buf } = await grab(t, b);
    seen.push(fmt);
    if (fmt === 'png') {
      assert.match(name, new RegExp(`^${id}\\.png$`));
      assert.deepEqual([...buf.subarray(0, 8)], [137, 80, 78, 71, 13, 10, 26, 10], 'PNG signature');
      assert.ok(buf.length > 2000, `PNG of ${buf.length} bytes`);
      const w = buf.readUInt32BE(16), h = buf.readUInt32BE(20);
      assert.ok(w >= 200 && h >= 150, `PNG ${w}×${h}`);
    } else if (fmt === 'svg') {
      assert.match(name, /\.svg$/);
      const s = await parseSVG(t, buf.toString('utf8'));
      assert.equal(s.error, undefined, `SVG parses: ${s.error}`);
      assert.equal(s.root, 'svg');
      assert.equal(s.ns, 'http://www.w3.org/2000/svg');
      assert.ok(s.paths > 3, `SVG has paths (${s.paths})`);
      assert.ok(s.width > 100, 'SVG width');
    } else if (fmt === 'json') {
      const j = JSON.parse(buf.toString('utf8'));
      assert.equal(j.demo, id);
      assert.deepEqual(j.state, state, 'JSON carries the demo state');
      // every demo provides computed data through exports()
      assert.ok(j.computed && typeof j.computed === 'object', `${id}: JSON carries computed data`);
    } else if (fmt === 'obj') {
      checkOBJ(buf.toString('utf8'));
    } else if (fmt === 'csv') {
      checkCSV(buf.toString('utf8'));
    } else assert.fail(`unknown format ${fmt}`);
  }
  return seen;
}

/** The URL of a demo with `patch` merged into its current (default) state. */
async function withState(t, id, patch) {
  const st = { ...(await t.state()), ...patch };
  return `#${id}/${await encodeState(st)}`;
}

test('every demo: the Export row downloads PNG, SVG, JSON (and OBJ/CSV) that parse back', async (tt) => {
  const SURFACES = new Set(['b2-surfaces', 'quasi-cubic-surfaces', 'criss-cross-basis']);
  for (const id of ids) {
    await tt.test(id, async () => {
      assert.ok(await demoExists(id), `${id}: listed in www/demos/index.js but www/demos/${id}.js is missing (a renamed demo fails, it is not skipped)`);
      const t = await H.open(`#${id}`);
      const seen = await exportAll(t, id);
      assert.ok(seen.includes('png'), 'PNG offered');
      assert.ok(seen.includes('json'), 'JSON offered');
      if (SURFACES.has(id)) assert.ok(seen.includes('obj'), 'OBJ offered for a surface demo');
      assert.ok(seen.includes('csv'), 'CSV offered');
      t.assertClean();
      await t.close();
    });
  }
});

test('demos with a surface tab export OBJ there (knot modification, Bézier remodelling)', async () => {
  for (const id of ['knot-modification', 'bezier-remodel']) {
    assert.ok(await demoExists(id), `${id}: listed but its module is missing`);
    const t0 = await H.open(`#${id}`);
    const url = await withState(t0, id, { tab: 'surface' });
    await t0.close();
    const t = await H.open(url);
    assert.equal((await t.state()).tab, 'surface');
    const seen = await exportAll(t, id);
    assert.ok(seen.includes('obj'), `${id}: OBJ offered on the surface tab (${seen})`);
    t.assertClean();
    await t.close();
  }
});

test('the element and the iframe show the Export row; controls=0 hides it', async () => {
  const t = await H.open('embed.html#bspline-basics');
  assert.ok(await t.page.$('.export-bar:not([hidden]) button[data-format="svg"]'));
  await t.close();
  const t2 = await H.open('embed.html#bspline-basics?controls=0');
  assert.equal(await t2.page.$eval('.export-bar', (e) => e.hidden), true);
  t2.assertClean();
  await t2.close();
});
