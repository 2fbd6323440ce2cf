// Visual regression (issue 30, item 4): the figure of every demo's default view in Chromium, at an 800 × 600
// viewport, compared with its reference image in tests/e2e/visual-ref/<demo>.png (pixelmatch, per-pixel colour
// threshold THRESHOLD, anti-aliased pixels ignored; at most MAX_DIFF of the pixels may differ). A change a reader
// would see — a colour, a line moved, a curve missing — fails; the next frame's sub-pixel noise does not.
//
//   node --test tests/e2e/visual.test.mjs                     compare
//   UPDATE_VISUAL=1 node --test tests/e2e/visual.test.mjs     (re)write the references (after a wanted change: look
//                                                             at the new PNGs before committing them)
// A failing demo writes tests/e2e/out/visual-<demo>-{actual,diff}.png (the diff: changed pixels in red).
// The references come from Debian's Chromium (software WebGL, SwiftShader) at device scale 1: on this machine three
// runs in a row differ by 0 pixels. Another Chromium build or font set may shift anti-aliasing: rewrite them there.
// Seen failing: the 2D curve colour (www/lib/plot2d/palette.js) changed from blue to orange → bspline-basics 1,636 of
// 315,750 pixels (0.52 %) and 5 other 2D demos fail. Needs the devDependency pixelmatch (7.2.0).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { deflateSync, crc32 } from 'node:zlib';
import { join } from 'node:path';
import pixelmatch from 'pixelmatch';
import { startHarness, demoIds, ROOT, OUT } from './harness.mjs';
import { decodePng } from './png-ink.mjs';

const REF = join(ROOT, 'tests/e2e/visual-ref');
const UPDATE = process.env.UPDATE_VISUAL === '1';
/** pixelmatch's colour distance threshold (0..1; its default 0.1). */
const THRESHOLD = 0.1;
/** The share of pixels that may differ (beyond the threshold, anti-aliasing excluded). */
const MAX_DIFF = 0.001;

let H;
before(async () => {
  mkdirSync(OUT, { recursive: true });
  if (UPDATE) mkdirSync(REF, { recursive: true });
  H = await startHarness({ viewport: { width: 800, height: 600 }, reducedMotion: 'reduce' });
});
after(() => H?.close());

/** RGBA bytes of a decoded PNG (Chromium writes RGB or RGBA). */
function rgba({ width, height, bpp, pixels }) {
  if (bpp === 4) return pixels;
  const out = Buffer.alloc(width * height * 4);
  for (let i = 0, j = 0; i < pixels.length; i += 3, j += 4) { out[j] = pixels[i]; out[j + 1] = pixels[i + 1]; out[j + 2] = pixels[i + 2]; out[j + 3] = 255; }
  return out;
}

/** A PNG (8-bit RGBA, no filter) of `data`: for the diff image. */
function encodePng(width, height, data) {
  const chunk = (type, body) => {
    const len = Buffer.alloc(4); len.writeUInt32BE(body.length);
    const tb = Buffer.concat([Buffer.from(type, 'ascii'), body]);
    const crc = Buffer.alloc(4); crc.writeUInt32BE(crc32(tb) >>> 0);
    return Buffer.concat([len, tb, crc]);
  };
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(width, 0); ihdr.writeUInt32BE(height, 4); ihdr[8] = 8; ihdr[9] = 6;
  const raw = Buffer.alloc((width * 4 + 1) * height);
  for (let y = 0; y < height; y++) data.copy(raw, y * (width * 4 + 1) + 1, y * width * 4, (y + 1) * width * 4);
  return Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk('IHDR', ihdr), chunk('IDAT', deflateSync(raw)), chunk('IEND', Buffer.alloc(0))]);
}

/** The demo's figure: the first visible canvas of the mounted demo, as a PNG. */
async function figure(id) {
  const t = await H.open(`#${id}`);
  await t.page.evaluate(() => document.fonts.ready);
  const canvas = await t.page.evaluateHandle(() => [...document.querySelectorAll('#demo-root canvas')].find((c) => c.getClientRects().length && c.width >= 8));
  assert.ok(canvas.asElement(), `${id}: a visible figure canvas`);
  await canvas.asElement().scrollIntoViewIfNeeded();
  await t.frames(4);
  const png = await canvas.asElement().screenshot({ animations: 'disabled', caret: 'hide' });
  t.assertClean();
  await t.context.close();
  return png;
}

for (const id of await demoIds()) {
  test(`visual: ${id} default view`, async () => {
    const png = await figure(id);
    const ref = join(REF, `${id}.png`);
    if (UPDATE) { writeFileSync(ref, png); return; }
    assert.ok(existsSync(ref), `${id}: no reference image ${ref} (write one with UPDATE_VISUAL=1 and look at it)`);
    const a = decodePng(png), b = decodePng(readFileSync(ref));
    assert.deepEqual([a.width, a.height], [b.width, b.height], `${id}: the figure's size changed`);
    const diff = Buffer.alloc(a.width * a.height * 4);
    const changed = pixelmatch(rgba(a), rgba(b), diff, a.width, a.height, { threshold: THRESHOLD, diffColor: [255, 0, 0] });
    const share = changed / (a.width * a.height);
    console.log(`# visual ${id}: ${changed} of ${a.width * a.height} pixels differ`);
    if (share > MAX_DIFF) {
      writeFileSync(join(OUT, `visual-${id}-actual.png`), png);
      writeFileSync(join(OUT, `visual-${id}-diff.png`), encodePng(a.width, a.height, diff));
    }
    assert.ok(share <= MAX_DIFF, `${id}: ${changed} of ${a.width * a.height} pixels (${(share * 100).toFixed(2)} %) differ from the reference `
      + `(at most ${(MAX_DIFF * 100).toFixed(2)} %); see tests/e2e/out/visual-${id}-{actual,diff}.png`);
  });
}
