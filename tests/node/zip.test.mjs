// www/lib/zip.js read back by a reader written here from the format (PKWARE APPNOTE §4.3: the end record, the
// central directory, each local header), with Node's zlib for the CRC-32 and the inflating — not by zip.js itself.
// Where `unzip` is installed, it also tests the archive (`unzip -t`).

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { crc32 as zlibCrc32, deflateRawSync } from 'node:zlib';
import { writeFileSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { spawnSync } from 'node:child_process';
import { zip, crc32 } from '../../www/lib/zip.js';
import { unzip } from '../fixtures/unzip.mjs';

const FILES = [
  { name: 'imsmanifest.xml', data: '<?xml version="1.0"?>\n<manifest identifier="ü-ő-ț">' + 'x'.repeat(3000) + '</manifest>' },
  { name: 'sco/index.html', data: '<!doctype html><title>Š</title>' },
  { name: 'data.bin', data: new Uint8Array([0, 255, 1, 254, 2, 253]) },
  { name: 'empty.txt', data: '' },
];

function same(files) {
  assert.deepEqual(files.map((f) => f.name), FILES.map((f) => f.name));
  files.forEach((f, i) => assert.deepEqual(new Uint8Array(f.data), typeof FILES[i].data === 'string' ? new TextEncoder().encode(FILES[i].data) : FILES[i].data, f.name));
}

test('crc32 equals zlib\'s on text, bytes and the empty input', () => {
  for (const s of ['', 'a', 'The quick brown fox jumps over the lazy dog', 'Slovenčina, română, magyar, italiano']) {
    const u = new TextEncoder().encode(s);
    assert.equal(crc32(u), zlibCrc32(Buffer.from(u)), JSON.stringify(s));
  }
  assert.equal(crc32(new TextEncoder().encode('123456789')), 0xcbf43926, 'the check value of CRC-32/ISO-HDLC');
});

test('stored: every file reads back with its name, bytes and CRC', async () => {
  const z = await zip(FILES, { compress: false });
  const files = unzip(z);
  same(files);
  assert.ok(files.every((f) => f.method === 0));
});

test('deflated where CompressionStream has deflate-raw (here through zlib), stored where that is not smaller', async () => {
  const Real = globalThis.CompressionStream;
  // Node 20 has no 'deflate-raw' format: a stand-in with the same interface, so the method-8 path runs
  globalThis.CompressionStream = class {
    constructor(fmt) {
      if (fmt !== 'deflate-raw') throw new TypeError(fmt);
      const chunks = [];
      const ts = new TransformStream({ transform(c) { chunks.push(Buffer.from(c)); }, flush(ctl) { ctl.enqueue(new Uint8Array(deflateRawSync(Buffer.concat(chunks)))); } });
      this.readable = ts.readable; this.writable = ts.writable;
    }
  };
  try {
    const z = await zip(FILES);
    const files = unzip(z);
    same(files);
    assert.equal(files[0].method, 8, 'the long manifest is deflated');
    assert.equal(files[2].method, 0, 'six random bytes are stored');
    assert.ok(z.length < (await zip(FILES, { compress: false })).length);
  } finally {
    globalThis.CompressionStream = Real;
  }
});

test('without deflate-raw every file is stored; the same input gives the same bytes', async () => {
  const Real = globalThis.CompressionStream;
  globalThis.CompressionStream = class { constructor() { throw new TypeError('unsupported'); } };
  try {
    const a = await zip(FILES), b = await zip(FILES);
    assert.ok(unzip(a).every((f) => f.method === 0));
    assert.deepEqual(a, b);
  } finally {
    globalThis.CompressionStream = Real;
  }
});

test('names that are not relative paths are refused', async () => {
  await assert.rejects(zip([{ name: '/etc/x', data: '' }]), /relative path/);
  await assert.rejects(zip([{ name: 'a\\b', data: '' }]), /relative path/);
});

test('unzip -t accepts the archive (where unzip is installed)', async (t) => {
  if (spawnSync('unzip', ['-v']).status !== 0) { t.skip('no unzip here'); return; }
  const dir = mkdtempSync(join(tmpdir(), 'zip-'));
  try {
    const f = join(dir, 'a.zip');
    writeFileSync(f, await zip(FILES, { compress: false }));
    const r = spawnSync('unzip', ['-t', f], { encoding: 'utf8' });
    assert.equal(r.status, 0, r.stdout + r.stderr);
    assert.match(r.stdout, /No errors detected/);
  } finally { rmSync(dir, { recursive: true }); }
});
