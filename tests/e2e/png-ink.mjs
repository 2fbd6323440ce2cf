// Ink of a PNG screenshot: how many pixels differ from its most common colour (the background), decoded here
// with zlib (8-bit RGB/RGBA, not interlaced: what Chromium's screenshots are), so a test needs no image library.
// Shared by site.test, site-pages.test and the tests that came after them.
import assert from 'node:assert/strict';
import { inflateSync } from 'node:zlib';

/** Decodes a PNG into { width, height, bpp, pixels } (rows of RGB or RGBA bytes, filters undone). */
export function decodePng(png) {
  let p = 8, width = 0, height = 0, type = 0;
  const idat = [];
  while (p < png.length) {
    const len = png.readUInt32BE(p), kind = png.toString('ascii', p + 4, p + 8), data = png.subarray(p + 8, p + 8 + len);
    if (kind === 'IHDR') { width = data.readUInt32BE(0); height = data.readUInt32BE(4); type = data[9]; assert.equal(data[8], 8); assert.equal(data[12], 0); }
    if (kind === 'IDAT') idat.push(data);
    p += 12 + len;
  }
  const bpp = type === 6 ? 4 : type === 2 ? 3 : assert.fail(`PNG colour type ${type}`);
  const raw = inflateSync(Buffer.concat(idat)), stride = width * bpp, pixels = Buffer.alloc(stride * height);
  for (let y = 0; y < height; y++) {
    const f = raw[y * (stride + 1)], src = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let x = 0; x < stride; x++) {
      const a = x >= bpp ? pixels[y * stride + x - bpp] : 0, b = y ? pixels[(y - 1) * stride + x] : 0, c = x >= bpp && y ? pixels[(y - 1) * stride + x - bpp] : 0;
      const pr = f === 1 ? a : f === 2 ? b : f === 3 ? (a + b) >> 1 : f === 4 ? ((pa, pb, pc) => (pa <= pb && pa <= pc ? a : pb <= pc ? b : c))(Math.abs(b - c), Math.abs(a - c), Math.abs(a + b - 2 * c)) : 0;
      pixels[y * stride + x] = (src[x] + pr) & 255;
    }
  }
  return { width, height, bpp, pixels };
}

/** { inked, colours, total }: pixels off the most common colour, distinct colours, all pixels. */
export function ink(png) {
  const { width, height, bpp, pixels } = decodePng(png);
  const counts = new Map();
  for (let i = 0; i < pixels.length; i += bpp) { const k = pixels.readUIntBE(i, 3); counts.set(k, (counts.get(k) || 0) + 1); }
  const most = Math.max(...counts.values());
  return { inked: width * height - most, colours: counts.size, total: width * height };
}
