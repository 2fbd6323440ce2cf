// Size budget (issue 8): fails when the optimised wasm grows past its gzip budget; prints the page weight.
// Usage: node scripts/check-size.mjs   (after scripts/build-wasm.sh)
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { join } from 'node:path';

const WASM_BUDGET_GZIP = 150 * 1024; // bytes, the target of issue 8
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
console.log(`wasm: ${kb(wasm.length)} raw, ${kb(gz)} gzip (budget ${kb(WASM_BUDGET_GZIP)}); whole page (${page.length} files: JS + wasm + CSS + HTML): ${kb(pageGz)} gzip`);
if (gz > WASM_BUDGET_GZIP) {
  console.error(`size budget exceeded: the wasm is ${kb(gz)} gzip, the budget is ${kb(WASM_BUDGET_GZIP)}`);
  process.exit(1);
}
