// A zip file written in the browser (issue 27: the SCORM package a teacher uploads to an LMS), with no library:
// the container is a few fixed headers (PKWARE APPNOTE 6.3.x, §4.3: local file header + data per file, then the
// central directory and its end record), and the compression is the browser's own `CompressionStream('deflate-raw')`
// (method 8) where there is one (Chromium 103+, Firefox 113+, Safari 16.4+), else the files are stored (method 0).
// Why not a zip library: the format needs ~100 lines for what we write (a handful of files, no zip64, no
// encryption), and CompressionStream is the browser's zlib, faster than any JS deflate; zero runtime dependencies.
//
// Every file carries its CRC-32 (the IEEE polynomial 0xEDB88320, reflected, as APPNOTE §4.4.7 asks), its sizes, a
// fixed DOS time (1 Jan 2026 00:00, so the same input gives the same bytes) and the UTF-8 flag (bit 11) for names.

const CRC_TABLE = (() => {
  const t = new Uint32Array(256);
  for (let n = 0; n < 256; n++) {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    t[n] = c >>> 0;
  }
  return t;
})();

/** CRC-32 of `bytes` (as zip, gzip and PNG use it). */
export function crc32(bytes) {
  let c = 0xffffffff;
  for (let i = 0; i < bytes.length; i++) c = CRC_TABLE[(c ^ bytes[i]) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

/** Raw DEFLATE of `bytes` by the browser (or Node ≥ 21.2's CompressionStream), or null where there is none. */
async function deflateRaw(bytes) {
  if (typeof CompressionStream !== 'function') return null;
  let cs;
  try { cs = new CompressionStream(/** @type {any} */ ('deflate-raw')); } catch { return null; } // an engine without the raw format
  const out = new Response(new Blob([bytes]).stream().pipeThrough(cs));
  return new Uint8Array(await out.arrayBuffer());
}

const DOS_TIME = 0;                                     // 00:00:00
const DOS_DATE = ((2026 - 1980) << 9) | (1 << 5) | 1;   // 2026-01-01

/**
 * The bytes of a zip archive of `files`: [{ name, data }] with `data` a string (written as UTF-8) or bytes.
 * `compress: false` stores every file; otherwise each is deflated when that makes it smaller.
 * @param {{ name: string, data: string | Uint8Array }[]} files
 * @param {{ compress?: boolean }} [opts]
 * @returns {Promise<Uint8Array>}
 */
export async function zip(files, { compress = true } = {}) {
  const enc = new TextEncoder();
  const parts = [];
  const central = [];
  let offset = 0;
  for (const f of files) {
    if (!f.name || f.name.startsWith('/') || f.name.includes('\\')) throw new Error(`zip: a file name must be a relative path with "/": ${JSON.stringify(f.name)}`);
    const name = enc.encode(f.name);
    const raw = typeof f.data === 'string' ? enc.encode(f.data) : f.data;
    const crc = crc32(raw);
    const packed = compress ? await deflateRaw(raw) : null;
    const useDeflate = !!packed && packed.length < raw.length;
    const body = useDeflate ? packed : raw;
    if (body.length > 0xfffffffe || offset > 0xfffffffe) throw new Error('zip: the archive is too large (no zip64 here)');
    const method = useDeflate ? 8 : 0;
    const local = new DataView(new ArrayBuffer(30));
    local.setUint32(0, 0x04034b50, true);   // local file header signature
    local.setUint16(4, 20, true);           // version needed: 2.0
    local.setUint16(6, 0x0800, true);       // flags: UTF-8 names
    local.setUint16(8, method, true);
    local.setUint16(10, DOS_TIME, true);
    local.setUint16(12, DOS_DATE, true);
    local.setUint32(14, crc, true);
    local.setUint32(18, body.length, true);
    local.setUint32(22, raw.length, true);
    local.setUint16(26, name.length, true);
    local.setUint16(28, 0, true);           // extra field length
    parts.push(new Uint8Array(local.buffer), name, body);
    const cen = new DataView(new ArrayBuffer(46));
    cen.setUint32(0, 0x02014b50, true);     // central directory header signature
    cen.setUint16(4, 20, true);             // version made by: 2.0, MS-DOS attributes
    cen.setUint16(6, 20, true);
    cen.setUint16(8, 0x0800, true);
    cen.setUint16(10, method, true);
    cen.setUint16(12, DOS_TIME, true);
    cen.setUint16(14, DOS_DATE, true);
    cen.setUint32(16, crc, true);
    cen.setUint32(20, body.length, true);
    cen.setUint32(24, raw.length, true);
    cen.setUint16(28, name.length, true);
    // extra, comment, disk number, internal and external attributes: 0
    cen.setUint32(42, offset, true);        // where its local header is
    central.push(new Uint8Array(cen.buffer), name);
    offset += 30 + name.length + body.length;
  }
  const cenSize = central.reduce((a, p) => a + p.length, 0);
  const end = new DataView(new ArrayBuffer(22));
  end.setUint32(0, 0x06054b50, true);       // end of central directory signature
  end.setUint16(8, files.length, true);     // entries on this disk
  end.setUint16(10, files.length, true);    // entries in all
  end.setUint32(12, cenSize, true);
  end.setUint32(16, offset, true);
  const all = [...parts, ...central, new Uint8Array(end.buffer)];
  const out = new Uint8Array(all.reduce((a, p) => a + p.length, 0));
  let at = 0;
  for (const p of all) { out.set(p, at); at += p.length; }
  return out;
}
