// Issue 29: files stay readable in one sitting. No Rust file in src/ over 700 lines, no demo file in www/demos/
// over 400 (a demo is a small figure file: state, draw, controls; shared parts live in www/lib). Counted as `wc -l`
// counts: newline characters.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, dirname, relative } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');

/** Every file under `dir` whose name ends with `ext`. */
function filesIn(dir, ext) {
  return readdirSync(dir).flatMap((name) => {
    const p = join(dir, name);
    if (statSync(p).isDirectory()) return filesIn(p, ext);
    return name.endsWith(ext) ? [p] : [];
  });
}

const lines = (p) => (readFileSync(p, 'utf8').match(/\n/g) || []).length;

/** The files of `dir` (ending in `ext`) over `limit` lines, as "path: n lines". */
function over(dir, ext, limit) {
  return filesIn(join(root, dir), ext)
    .map((p) => [relative(root, p), lines(p)])
    .filter(([, n]) => n > limit)
    .map(([p, n]) => `${p}: ${n} lines`);
}

test('no Rust file in src/ over 700 lines', () => {
  assert.deepEqual(over('src', '.rs', 700), []);
});

test('no demo file in www/demos/ over 400 lines', () => {
  assert.deepEqual(over('www/demos', '.js', 400), []);
});
