// Static PNG fallbacks for print/PDF notes: renders every demo at its default state (embed.html#<id>, no
// explanation text: the figures and the controls with their values) to docs/static/<id>.png with headless
// Chromium (playwright-core + Debian chromium, like tests/e2e/harness.mjs). Nothing leaves 127.0.0.1.
//
//   node scripts/snapshots.mjs [id …]        (needs www/pkg: scripts/build-wasm.sh)
//
// Each image is at most 1280×900 CSS px and kept under ~200 KB (re-shot narrower if larger).

import { chromium } from 'playwright-core';
import { mkdir, stat, access } from 'node:fs/promises';
import { join, dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { serve } from './static-server.mjs';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const WWW = join(ROOT, 'www');
const OUT = join(ROOT, 'docs/static');
const MAX_BYTES = 200 * 1024;

const exists = (p) => access(p).then(() => true, () => false);

async function main() {
  if (!(await exists(join(WWW, 'pkg/splinelab_bg.wasm')))) {
    console.error('www/pkg is missing: run scripts/build-wasm.sh first');
    process.exit(1);
  }
  const { DEMO_IDS } = await import(join(WWW, 'demos/index.js'));
  const wanted = process.argv.slice(2);
  const ids = (wanted.length ? DEMO_IDS.filter((id) => wanted.includes(id)) : DEMO_IDS);
  await mkdir(OUT, { recursive: true });
  const server = await serve(WWW, 0, '127.0.0.1');
  const base = `http://127.0.0.1:${server.address().port}/`;
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--disable-quic'],
  });
  let failed = 0;
  try {
    for (const id of ids) {
      if (!(await exists(join(WWW, 'demos', `${id}.js`)))) { console.log(`${id}: module not written yet, skipped`); continue; }
      let done = false;
      for (const width of [1280, 1100, 960, 820]) {
        const context = await browser.newContext({ viewport: { width, height: 900 }, deviceScaleFactor: 1, reducedMotion: 'reduce' });
        await context.route('**/*', (r) => (new URL(r.request().url()).hostname === '127.0.0.1' || /^(data|blob):/.test(r.request().url()) ? r.continue() : r.abort()));
        const page = await context.newPage();
        const errors = [];
        page.on('pageerror', (e) => errors.push(String(e)));
        await page.goto(`${base}embed.html#${id}?explain=0`);
        await page.waitForFunction(() => document.documentElement.dataset.ready, null, { timeout: 30000 });
        await page.waitForSelector('#demo-root[data-mounted="true"]', { timeout: 30000 });
        // no focus ring, no hover state; two frames for the plots and the WebGL views to draw
        await page.evaluate(() => { document.activeElement?.blur(); document.querySelectorAll('.export-bar, .plot-tools').forEach((e) => { e.style.display = 'none'; }); });
        await page.evaluate(() => new Promise((ok) => requestAnimationFrame(() => requestAnimationFrame(ok))));
        await page.waitForTimeout(150);
        const box = await page.$eval('#demo-root', (e) => { const r = e.getBoundingClientRect(); return { x: r.left, y: r.top, width: r.width, height: r.height }; });
        const clip = { x: Math.max(0, box.x - 4), y: Math.max(0, box.y - 4), width: Math.min(width, box.width + 8), height: Math.min(900, box.height + 8) };
        const path = join(OUT, `${id}.png`);
        await page.screenshot({ path, clip, fullPage: true });
        await context.close();
        if (errors.length) console.warn(`${id}: page errors: ${errors.join('; ')}`);
        const { size } = await stat(path);
        if (size <= MAX_BYTES) {
          console.log(`${id}: docs/static/${id}.png ${Math.round(clip.width)}×${Math.round(clip.height)} ${Math.round(size / 1024)} KB`);
          done = true;
          break;
        }
        console.log(`${id}: ${Math.round(size / 1024)} KB at width ${width}, trying narrower`);
      }
      if (!done) { failed++; console.warn(`${id}: could not get under ${MAX_BYTES / 1024} KB (kept the last image)`); }
    }
  } finally {
    await browser.close();
    server.close();
  }
  if (failed) process.exitCode = 1;
}

main().catch((e) => { console.error(e); process.exit(1); });
