// Static PNG fallbacks for print/PDF notes: renders every demo at its default state (embed.html#<id>, no
// explanation text: the figures and the controls with their values) to docs/static/<id>.png with headless
// Chromium (playwright-core + Debian chromium, like tests/e2e/harness.mjs). Nothing leaves 127.0.0.1.
//
//   node scripts/snapshots.mjs [id …]        (needs www/pkg: scripts/build-wasm.sh)
//   node scripts/snapshots.mjs --cards [id …]  the gallery card pictures docs/static/cards/<id>.png instead
//
// Each image is at most 1280×900 CSS px and kept under ~200 KB (re-shot narrower if larger).
// A card picture is the demo's main view at its default state (embed.html#<id>?explain=0&controls=0: the first
// figure, its first canvas-holding element), scaled to cover CARD_W × CARD_H and kept under CARD_MAX_BYTES.

import { chromium } from 'playwright-core';
import { mkdir, stat, access, writeFile } from 'node:fs/promises';
import { join, dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { serve } from './static-server.mjs';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const WWW = join(ROOT, 'www');
const OUT = join(ROOT, 'docs/static');
const MAX_BYTES = 200 * 1024;
const CARD_W = 320;
const CARD_H = 200;
const CARD_MAX_BYTES = 40 * 1024;

const exists = (p) => access(p).then(() => true, () => false);

async function main() {
  if (!(await exists(join(WWW, 'pkg/splinelab_bg.wasm')))) {
    console.error('www/pkg is missing: run scripts/build-wasm.sh first');
    process.exit(1);
  }
  const { DEMO_IDS } = await import(join(WWW, 'demos/index.js'));
  const cardsMode = process.argv.includes('--cards');
  const wanted = process.argv.slice(2).filter((a) => a !== '--cards');
  const ids = (wanted.length ? DEMO_IDS.filter((id) => wanted.includes(id)) : DEMO_IDS);
  await mkdir(OUT, { recursive: true });
  if (cardsMode) return cards(ids);
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

// ---------- gallery card pictures ----------
async function cards(ids) {
  const dir = join(OUT, 'cards');
  await mkdir(dir, { recursive: true });
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
      // a desktop-sized view, so every demo shows its usual layout; the picture is scaled down afterwards
      const context = await browser.newContext({ viewport: { width: 1100, height: 760 }, deviceScaleFactor: 1, reducedMotion: 'reduce' });
      await context.route('**/*', (r) => (new URL(r.request().url()).hostname === '127.0.0.1' || /^(data|blob):/.test(r.request().url()) ? r.continue() : r.abort()));
      const page = await context.newPage();
      const errors = [];
      page.on('pageerror', (e) => errors.push(String(e)));
      await page.goto(`${base}embed.html#${id}?explain=0&controls=0`);
      await page.waitForFunction(() => document.documentElement.dataset.ready, null, { timeout: 30000 });
      await page.waitForSelector('#demo-root[data-mounted="true"]', { timeout: 30000 });
      await page.evaluate(() => { document.activeElement?.blur(); document.querySelectorAll('.export-bar, .plot-tools').forEach((e) => { e.style.display = 'none'; }); });
      await page.evaluate(() => new Promise((ok) => requestAnimationFrame(() => requestAnimationFrame(ok))));
      await page.waitForTimeout(200);
      // the main view: the first visible canvas of a reasonable size
      const box = await page.$eval('#demo-root', (root) => {
        const c = [...root.querySelectorAll('canvas')].find((x) => { const r = x.getBoundingClientRect(); return r.width >= 160 && r.height >= 100; });
        const r = (c || root).getBoundingClientRect();
        return { x: r.left + scrollX, y: r.top + scrollY, width: r.width, height: r.height };
      });
      const shot = await page.screenshot({ clip: box, fullPage: true });
      // scale to cover CARD_W × CARD_H (centred crop) in a blank page's canvas; PNG from the browser's encoder
      const blank = await context.newPage();
      // too large (smooth 3D shading compresses badly): posterise the colours a little, then more
      let png = null;
      for (const levels of [256, 64, 32, 16]) {
        const dataUrl = await blank.evaluate(async ({ b64, W, H, levels }) => {
          const img = new Image();
          img.src = `data:image/png;base64,${b64}`;
          await img.decode();
          const s = Math.max(W / img.naturalWidth, H / img.naturalHeight);
          const w = img.naturalWidth * s, hh = img.naturalHeight * s;
          const c = document.createElement('canvas');
          c.width = W; c.height = H;
          const g = c.getContext('2d');
          g.fillStyle = '#fff'; g.fillRect(0, 0, W, H);
          g.imageSmoothingQuality = 'high';
          g.drawImage(img, (W - w) / 2, (H - hh) / 2, w, hh);
          if (levels < 256) {
            const d = g.getImageData(0, 0, W, H);
            const q = 255 / (levels - 1);
            for (let i = 0; i < d.data.length; i++) if ((i & 3) !== 3) d.data[i] = Math.round(Math.round(d.data[i] / q) * q);
            g.putImageData(d, 0, 0);
          }
          return c.toDataURL('image/png');
        }, { b64: shot.toString('base64'), W: CARD_W, H: CARD_H, levels });
        png = Buffer.from(dataUrl.split(',')[1], 'base64');
        if (png.length <= CARD_MAX_BYTES) break;
      }
      await context.close();
      const path = join(dir, `${id}.png`);
      await writeFile(path, png);
      if (errors.length) { failed++; console.warn(`${id}: page errors: ${errors.join('; ')}`); }
      const ok = png.length <= CARD_MAX_BYTES;
      if (!ok) failed++;
      console.log(`${id}: docs/static/cards/${id}.png ${CARD_W}×${CARD_H} ${(png.length / 1024).toFixed(1)} KB${ok ? '' : ` — over ${CARD_MAX_BYTES / 1024} KB`}`);
    }
  } finally {
    await browser.close();
    server.close();
  }
  if (failed) process.exitCode = 1;
}

main().catch((e) => { console.error(e); process.exit(1); });
