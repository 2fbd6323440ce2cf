// Runs every example of docs/API.md and README.md against the built module, so the docs stay true.
//
//   scripts/build-wasm.sh && node docs/examples.mjs            Node examples (pkg-node/)
//   node docs/examples.mjs --browser                           also the page example (www/pkg/) in headless Chromium
//
// Each ```js block is run on its own with `sl` (the module from pkg-node/) and `assert` (node:assert/strict)
// in scope; a block may also `require('./pkg-node/splinelab.js')` itself. Blocks fenced ```js page are page
// code (ES module + init()); they run only with --browser. The script also fails when an export of the module
// has no `### \`name\`` section in docs/API.md, or is missing from the README's API list. Exit code 1 on any
// failure.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import assert from 'node:assert/strict';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const require = createRequire(import.meta.url);
const PKG = join(ROOT, 'pkg-node/splinelab.js');
const sl = require(PKG);
const AsyncFunction = (async () => {}).constructor;

/** The fenced code blocks of a markdown file: { info, code, line }. */
function blocks(file) {
  const text = readFileSync(join(ROOT, file), 'utf8');
  const out = [];
  const re = /^```([^\n]*)\n([\s\S]*?)^```$/gm;
  for (let m; (m = re.exec(text));) {
    out.push({ file, info: m[1].trim(), code: m[2], line: text.slice(0, m.index).split('\n').length });
  }
  return out;
}

/** `require` for the examples: './pkg-node/splinelab.js' resolves from the repository root. */
const exampleRequire = (id) => (id.startsWith('./') ? require(join(ROOT, id)) : require(id));

let failures = 0;
let ran = 0;
const fail = (what, e) => {
  failures++;
  console.error(`FAIL ${what}\n  ${String(e && e.stack || e).split('\n').slice(0, 4).join('\n  ')}`);
};

const all = [...blocks('docs/API.md'), ...blocks('README.md')];
for (const b of all.filter((b) => b.info === 'js')) {
  const where = `${b.file}:${b.line}`;
  try {
    // a block of its own, so that an example may declare `const sl = require(…)` itself
    await new AsyncFunction('sl', 'assert', 'require', `{\n${b.code}\n}`)(sl, assert, exampleRequire);
    ran++;
  } catch (e) {
    fail(where, e);
  }
}

// every export documented
const api = readFileSync(join(ROOT, 'docs/API.md'), 'utf8');
const readme = readFileSync(join(ROOT, 'README.md'), 'utf8');
const exports = Object.keys(sl).filter((k) => typeof sl[k] === 'function').sort();
for (const name of exports) {
  if (!api.includes(`### \`${name}\``)) fail(`docs/API.md has no section for the export ${name}`, 'missing');
  if (!readme.includes(`\`${name}\``) && !readme.includes(`\`${name}(`)) fail(`README.md does not list the export ${name}`, 'missing');
}
// and no section for a function that does not exist
for (const m of api.matchAll(/^### `([A-Za-z0-9]+)`/gm)) {
  if (typeof sl[m[1]] !== 'function') fail(`docs/API.md documents ${m[1]}, which the module does not export`, 'stale');
}

if (process.argv.includes('--browser')) {
  const page = all.filter((b) => b.info === 'js page');
  try {
    ran += await runInBrowser(page);
  } catch (e) {
    fail('page examples in headless Chromium', e);
  }
}

console.log(`${ran} examples ran, ${exports.length} exports checked, ${failures} failure(s)`);
process.exit(failures ? 1 : 0);

/** Serves www/ and runs each page block as the module script of a blank page at the root of www/. */
async function runInBrowser(page) {
  const { serve } = await import(join(ROOT, 'scripts/static-server.mjs'));
  const pw = await import('playwright-core');
  const chromium = pw.chromium ?? pw.default.chromium;
  const server = await serve(join(ROOT, 'www'), 0, '127.0.0.1');
  const base = `http://127.0.0.1:${server.address().port}/`;
  const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: ['--headless', '--no-sandbox'] });
  let n = 0;
  try {
    for (const b of page) {
      const where = `${b.file}:${b.line}`;
      const tab = await browser.newPage();
      const errors = [];
      tab.on('pageerror', (e) => errors.push(String(e)));
      tab.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
      // './pkg/splinelab.js' resolves as in a course page that sits next to pkg/
      await tab.route(`${base}__example.html`, (r) => r.fulfill({
        contentType: 'text/html', body: '<!doctype html><title>example</title><script type="module" src="__example.mjs"></script>',
      }));
      await tab.route(`${base}__example.mjs`, (r) => r.fulfill({
        contentType: 'text/javascript', body: `${b.code}\nwindow.__example = { version: sl.version() };\n`,
      }));
      await tab.goto(`${base}__example.html`);
      await tab.waitForFunction(() => window.__example, null, { timeout: 20000 }).catch(() => {});
      const result = await tab.evaluate(() => window.__example);
      if (errors.length || !result) throw new Error(`${where}: ${errors.join('; ') || 'did not finish'}`);
      assert.equal(typeof result.version, 'string', where);
      await tab.close();
      n++;
    }
  } finally {
    await browser.close();
    server.closeAllConnections?.();
    server.close();
  }
  return n;
}
