// The module-preload lists of www/index.html and www/embed.html, generated from the module graph (one source: the
// imports themselves). Both pages start the whole static graph with the HTML, so a real network pays one round trip
// for it instead of one per import level (benches/start.mjs): lib/wasm-preload.js (async, first: it starts the fetch
// of the routed demo's wasm module) with what it imports, app.js with what it imports statically, and what the demos
// import (not the demo modules themselves: only the routed one loads). tests/e2e/startup.test.mjs checks the same rule.
//
// The list sits between two markers in each page, written by this script:
//   <!-- modulepreload: … -->  …links…  <!-- /modulepreload -->
// The graph is read by esbuild (its metafile: every static import of every module), not by a regex.
//
// Usage: node scripts/preload-list.mjs [--write | --check]
//   --write  rewrites the lists that are stale (scripts/build-site.mjs runs this first)
//   --check  exits 1 naming each page whose list is stale, with the lines to add and remove (scripts/test.sh)
//   (none)   prints the list

import { build } from 'esbuild';
import { readFile, writeFile, readdir } from 'node:fs/promises';
import { dirname, join, relative, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const WWW = join(ROOT, 'www');
export const PAGES = ['index.html', 'embed.html'];
const START = '  <!-- modulepreload: the static module graph of lib/wasm-preload.js and app.js, then what the demos import;\n'
  + '       generated from the imports by scripts/preload-list.mjs (node scripts/preload-list.mjs --write), do not edit -->\n';
const END = '  <!-- /modulepreload -->\n';
const PRELOAD_SCRIPT = '  <script type="module" async src="lib/wasm-preload.js"></script>\n';
const toPosix = (p) => p.split(sep).join('/');

/** Every www/ module's static imports (paths relative to www/), from esbuild's metafile. */
async function staticImports(entries) {
  const result = await build({
    entryPoints: entries.map((e) => join(WWW, e)), bundle: true, splitting: true, format: 'esm', write: false,
    metafile: true, outdir: join(ROOT, 'dist/.preload'), platform: 'browser', logLevel: 'error',
    preserveSymlinks: true, // (a worktree may link www/pkg to another checkout's build)
  });
  const rel = (p) => toPosix(relative(WWW, resolve(ROOT, p)));
  const imports = new Map();
  for (const [path, input] of Object.entries(result.metafile.inputs)) {
    imports.set(rel(path), input.imports.filter((i) => i.kind === 'import-statement' && !i.external).map((i) => rel(i.path)));
  }
  return imports;
}

/** The preload list, breadth first (a module before what it imports: the order the browser needs them). */
export async function preloadList() {
  const demos = (await readdir(join(WWW, 'demos'))).filter((f) => f.endsWith('.js') && f !== 'index.js').map((f) => `demos/${f}`);
  const imports = await staticImports(['lib/wasm-preload.js', 'app.js', ...demos]);
  const seen = new Set();
  const order = [];
  const walk = (roots) => {
    const queue = [...roots];
    while (queue.length) {
      const f = queue.shift();
      if (seen.has(f)) continue;
      seen.add(f);
      // a demo module itself is not preloaded (only the routed one loads); demos/index.js (the list of ids) is
      if (!/^demos\/(?!index\.js$)/.test(f)) order.push(f);
      queue.push(...(imports.get(f) || []));
    }
  };
  walk(['lib/wasm-preload.js']);
  const early = order.length; // lib/wasm-preload.js and its imports: hinted before the script that runs it
  walk(['app.js']);
  walk(demos);
  return { early: order.slice(0, early), rest: order.slice(early) };
}

/** The generated block of a page. */
export function block({ early, rest }) {
  const link = (f) => `  <link rel="modulepreload" href="${f}">\n`;
  return START + early.map(link).join('') + PRELOAD_SCRIPT + rest.map(link).join('') + END;
}

/** A page's current block (between the markers), or null when it has none. */
function currentBlock(html) {
  const a = html.indexOf('  <!-- modulepreload');
  const b = html.indexOf(END);
  return a < 0 || b < a ? null : { a, b: b + END.length, text: html.slice(a, b + END.length) };
}

/**
 * Compares (and with `write`, rewrites) the lists of index.html and embed.html with the graph. Returns the pages
 * that were stale, each with the lines missing from it and the lines that are not in the graph.
 */
export async function syncPreloadLists({ write = false } = {}) {
  const list = await preloadList();
  const want = block(list);
  const stale = [];
  for (const page of PAGES) {
    const file = join(WWW, page);
    const html = await readFile(file, 'utf8');
    const cur = currentBlock(html);
    if (!cur) throw new Error(`www/${page} has no "<!-- modulepreload…" … "<!-- /modulepreload -->" block`);
    if (cur.text === want) continue;
    const lines = (t) => t.split('\n').filter((l) => l.includes('rel="modulepreload"') || l.includes('<script'));
    const have = lines(cur.text), need = lines(want);
    stale.push({ page, missing: need.filter((l) => !have.includes(l)), extra: have.filter((l) => !need.includes(l)) });
    if (write) await writeFile(file, html.slice(0, cur.a) + want + html.slice(cur.b));
  }
  return { stale, count: list.early.length + list.rest.length };
}

async function main() {
  const mode = process.argv[2] || '';
  if (!['', '--write', '--check'].includes(mode)) { console.error('usage: node scripts/preload-list.mjs [--write | --check]'); process.exit(2); }
  if (!mode) { process.stdout.write(block(await preloadList())); return; }
  const { stale, count } = await syncPreloadLists({ write: mode === '--write' });
  for (const { page, missing, extra } of stale) {
    if (mode === '--write') { console.log(`preload-list: www/${page} updated`); continue; }
    console.error(`preload-list: www/${page} is stale (node scripts/preload-list.mjs --write fixes it)`
      + `${missing.length ? `\n  missing:\n${missing.join('\n')}` : ''}${extra.length ? `\n  not in the graph:\n${extra.join('\n')}` : ''}`
      + `${!missing.length && !extra.length ? '\n  (the same lines in another order)' : ''}`);
  }
  if (mode === '--check' && stale.length) process.exit(1);
  if (mode === '--check') console.log(`preload-list: ${PAGES.join(', ')} preload the ${count} modules of the graph`);
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  main().catch((e) => { console.error(`preload-list: ${e.stack || e}`); process.exit(1); });
}
