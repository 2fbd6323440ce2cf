// Size budget (issue 8): fails when the optimised wasm grows past its gzip budget; prints the page weight.
// Usage: node scripts/check-size.mjs   (after scripts/build-wasm.sh)
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { join } from 'node:path';

// The target of issue 8 is 150 KB gzip. It is not met without removing features: the complete module (every
// construction of the five papers, all exports on main at 2026-11-22 03:29 UTC) measures 263.0 KB gzip at
// opt-level 3 + wasm-opt -Os, and still 215+ KB at opt-level "s" and ~200 KB at "z" (which is 10× slower);
// see benches/README.md for what was measured and tried. The budget is that measurement + 10 %, so the check
// fails when the module grows; lower it when the module shrinks.
const WASM_TARGET_GZIP = 150 * 1024;
const WASM_BUDGET_GZIP = 290 * 1024; // bytes
const wasm = readFileSync('www/pkg/splinelab_bg.wasm');
const gz = gzipSync(wasm, { level: 9 }).length;

function walk(dir) {
  return readdirSync(dir).flatMap((f) => {
    const p = join(dir, f);
    return statSync(p).isDirectory() ? (f === 'dev' ? [] : walk(p)) : [p];
  });
}
const page = walk('www').filter((p) => /\.(js|mjs|css|html|wasm)$/.test(p));
const pageGz = page.reduce((s, p) => s + gzipSync(readFileSync(p), { level: 9 }).length, 0);
const kb = (b) => `${(b / 1024).toFixed(1)} KB`;
console.log(`wasm: ${kb(wasm.length)} raw, ${kb(gz)} gzip (budget ${kb(WASM_BUDGET_GZIP)}, target ${kb(WASM_TARGET_GZIP)}); whole page (${page.length} files: JS + wasm + CSS + HTML): ${kb(pageGz)} gzip`);
if (gz > WASM_BUDGET_GZIP) {
  console.error(`size budget exceeded: the wasm is ${kb(gz)} gzip, the budget is ${kb(WASM_BUDGET_GZIP)}`);
  process.exit(1);
}
