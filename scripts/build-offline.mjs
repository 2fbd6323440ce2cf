// Writes dist/splinelab.html: the whole playground (gallery + every demo) as ONE self-contained file that opens
// from file:// (double-click) in Chromium, Firefox and WebKit, and can be uploaded to an LMS as a single file.
//
// file:// refuses ES module imports and fetch(), so this is a tiny home-made bundler:
//   - it walks the ES module graph from www/app.js (static imports, plus the dynamic imports of the demos and of
//     the wasm glue, which it lists itself), and rewrites each module into a function of a small registry:
//       import { a, b as c } from './x.js'   →  const { a, b: c } = __sl_require('lib/x.js');
//       export function f / const / class     →  the declaration, plus a live getter on the module's exports
//       export { a, b as c }; export default x →  getters
//       import(spec)                           →  __sl_import(<this module's path>, spec)  (a Promise)
//   - modules evaluate lazily on first require, like ES modules (the graph has no cycles: checked);
//   - the wasm binary is inlined as base64 and handed to the glue's init when it is called without arguments;
//   - style.css is inlined in a <style>; the page's CSP keeps everything inside the file (no network at all).
// Only the forms of import/export the project uses are supported; anything else stops the build with the
// module and line, so a new form cannot slip through unnoticed.
//
// Usage: node scripts/build-offline.mjs [out=dist/splinelab.html]   (scripts/build-offline.sh builds wasm first)

import { readFile, writeFile, mkdir, readdir } from 'node:fs/promises';
import { dirname, join, resolve, posix } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const WWW = join(ROOT, 'www');
const OUT = resolve(ROOT, process.argv[2] || 'dist/splinelab.html');

const fail = (msg) => { console.error(`build-offline: ${msg}`); process.exit(1); };

/** Entry modules: the shell, every demo (imported dynamically by app.js), the wasm glue. */
async function entries() {
  const demos = (await readdir(join(WWW, 'demos'))).filter((f) => f.endsWith('.js')).map((f) => `demos/${f}`);
  return ['app.js', 'pkg/splinelab.js', ...demos];
}

const lineOf = (src, idx) => src.slice(0, idx).split('\n').length;

/** Parses `{ a, b as c }` (import or export clause) into [[imported, local], …]. */
function clause(text, where) {
  return text.replace(/^\{|\}$/g, '').split(',').map((s) => s.trim()).filter(Boolean).map((s) => {
    const m = /^([A-Za-z_$][\w$]*)(?:\s+as\s+([A-Za-z_$][\w$]*))?$/.exec(s);
    if (!m) fail(`${where}: unsupported import/export clause "${s}"`);
    return [m[1], m[2] || m[1]];
  });
}

/** Rewrites one module. Returns { code, deps }. */
function transform(path, src) {
  const dir = posix.dirname(path);
  const rel = (spec, where) => {
    if (!spec.startsWith('./') && !spec.startsWith('../')) fail(`${where}: only relative imports are supported ("${spec}")`);
    return posix.normalize(posix.join(dir, spec));
  };
  const deps = new Set();
  const exported = []; // [exportName, localExpression]
  let out = src;

  // static imports (possibly over several lines)
  out = out.replace(/^import\s+(\{[^}]*\})\s+from\s+'([^']+)';?/gm, (m, cl, spec, idx) => {
    const where = `${path}:${lineOf(src, idx)}`;
    const p = rel(spec, where);
    deps.add(p);
    const parts = clause(cl.replace(/\s+/g, ' '), where).map(([a, b]) => (a === b ? a : `${a}: ${b}`));
    return `const { ${parts.join(', ')} } = __sl_require(${JSON.stringify(p)});`;
  });
  out = out.replace(/^import\s+([A-Za-z_$][\w$]*)\s+from\s+'([^']+)';?/gm, (m, name, spec, idx) => {
    const p = rel(spec, `${path}:${lineOf(src, idx)}`);
    deps.add(p);
    return `const ${name} = __sl_require(${JSON.stringify(p)}).default;`;
  });
  out = out.replace(/^import\s+'([^']+)';?/gm, (m, spec, idx) => {
    const p = rel(spec, `${path}:${lineOf(src, idx)}`);
    deps.add(p);
    return `__sl_require(${JSON.stringify(p)});`;
  });
  // export declarations
  out = out.replace(/^export\s+(async\s+function\*?|function\*?|const|let|var|class)\s+([A-Za-z_$][\w$]*)/gm, (m, kw, name) => {
    exported.push([name, name]);
    return `${kw} ${name}`;
  });
  out = out.replace(/^export\s+(\{[^}]*\})\s*;?/gm, (m, cl, idx) => {
    for (const [local, name] of clause(cl.replace(/\s+/g, ' '), `${path}:${lineOf(src, idx)}`)) exported.push([name, local]);
    return '';
  });
  out = out.replace(/^export\s+default\s+([A-Za-z_$][\w$]*)\s*;?/gm, (m, name) => { exported.push(['default', name]); return ''; });
  // dynamic imports → the registry (resolved relative to this module)
  out = out.replace(/\bimport\s*\(/g, `__sl_import(${JSON.stringify(path)}, `);
  out = out.replace(/\bimport\.meta\.url\b/g, `__sl_url(${JSON.stringify(path)})`);

  // anything left that looks like a module statement is a form this bundler does not know
  const left = /^\s*(import|export)\b[^(]/m.exec(out);
  if (left) fail(`${path}:${lineOf(out, left.index)}: unsupported module syntax: ${out.slice(left.index, left.index + 60)}`);

  const getters = exported.map(([name, local]) => `  __sl_export(exports, ${JSON.stringify(name)}, () => ${local});`).join('\n');
  return { code: `${getters}\n${out}`, deps: [...deps] };
}

async function main() {
  const modules = new Map(); // path → { code, deps }
  const queue = await entries();
  while (queue.length) {
    const p = queue.shift();
    if (modules.has(p)) continue;
    let src;
    try { src = await readFile(join(WWW, p), 'utf8'); } catch { fail(`cannot read www/${p} (run scripts/build-wasm.sh first?)`); }
    if (p === 'pkg/splinelab.js') {
      const before = src;
      src = src.replace(/module_or_path = new URL\('splinelab_bg\.wasm', import\.meta\.url\);/, 'module_or_path = __sl_wasm();');
      if (src === before) fail('pkg/splinelab.js: the wasm-bindgen glue changed (no default wasm URL to replace)');
    }
    const m = transform(p, src);
    modules.set(p, m);
    queue.push(...m.deps);
  }
  // no cycles (lazy evaluation with destructured imports needs a DAG)
  const state = new Map();
  const visit = (p, stack) => {
    if (state.get(p) === 2) return;
    if (state.get(p) === 1) fail(`import cycle: ${[...stack, p].join(' → ')}`);
    state.set(p, 1);
    for (const d of modules.get(p).deps) visit(d, [...stack, p]);
    state.set(p, 2);
  };
  for (const p of modules.keys()) visit(p, []);

  const wasm = await readFile(join(WWW, 'pkg/splinelab_bg.wasm'));
  const css = await readFile(join(WWW, 'style.css'), 'utf8');
  let html = await readFile(join(WWW, 'index.html'), 'utf8');

  const runtime = `
'use strict';
(() => {
const __sl_defs = Object.create(null), __sl_cache = Object.create(null);
function __sl_export(exports, name, get) { Object.defineProperty(exports, name, { get, enumerable: true }); }
function __sl_require(p) {
  if (__sl_cache[p]) return __sl_cache[p];
  const f = __sl_defs[p];
  if (!f) throw new Error('SplineLab offline file: no module ' + p);
  const exports = __sl_cache[p] = Object.create(null);
  f(exports);
  Object.freeze(exports);
  return exports;
}
function __sl_resolve(from, spec) {
  spec = String(spec);
  const base = from.includes('/') ? from.slice(0, from.lastIndexOf('/') + 1) : '';
  const out = [];
  for (const part of (spec.startsWith('.') ? base + spec : spec).split('/')) {
    if (part === '..') out.pop(); else if (part !== '.' && part !== '') out.push(part);
  }
  return out.join('/');
}
function __sl_import(from, spec) {
  try { return Promise.resolve(__sl_require(__sl_resolve(from, spec))); } catch (e) { return Promise.reject(e); }
}
function __sl_url(p) { return new URL(p, location.href).href; }
let __sl_bytes = null;
function __sl_wasm() {
  if (!__sl_bytes) {
    const b = atob(document.getElementById('splinelab-wasm').textContent.trim());
    __sl_bytes = new Uint8Array(b.length);
    for (let i = 0; i < b.length; i++) __sl_bytes[i] = b.charCodeAt(i);
  }
  return __sl_bytes;
}
${[...modules].map(([p, m]) => `__sl_defs[${JSON.stringify(p)}] = function (exports) {\n${m.code}\n};`).join('\n')}
__sl_require('app.js');
})();
`;
  const js = runtime.replace(/<\/(script)/gi, '<\\/$1').replace(/<!--/g, '<\\!--');
  // everything inline, nothing from outside the file
  const csp = "default-src 'none'; script-src 'unsafe-inline' 'wasm-unsafe-eval'; style-src 'unsafe-inline'; img-src data: blob:; connect-src data: blob:; object-src 'none'; base-uri 'none'";
  html = html
    .replace(/<meta http-equiv="Content-Security-Policy"[^>]*>/, `<meta http-equiv="Content-Security-Policy" content="${csp}">`)
    .replace(/<link rel="stylesheet" href="style\.css">/, () => `<style>\n${css.replace(/<\/(style)/gi, '<\\/$1')}\n</style>`)
    .replace(/\s*<script type="module" src="app\.js"><\/script>/, '')
    .replace(/\s*<script type="module" async src="lib\/wasm-preload\.js"><\/script>/, '') // (the wasm is inline)
    // the start-up hints (modulepreload / preload of the wasm) point at files the single file does not have
    .replace(/\s*<link rel="(?:modulepreload|preload)"[^>]*>/g, '')
    .replace(/<body data-mode="gallery">/, '<body data-mode="gallery" data-offline-file="true">');
  if (/<script[^>]+src=|<link[^>]+stylesheet/.test(html)) fail('an external script or stylesheet is left in the page');
  html = html.replace(/<\/body>/, () => `<script type="application/octet-stream" id="splinelab-wasm">${wasm.toString('base64')}</script>\n<script>${js}</script>\n</body>`);
  for (const must of ['<style>', 'id="splinelab-wasm"', 'data-offline-file']) if (!html.includes(must)) fail(`index.html changed: could not insert ${must}`);

  await mkdir(dirname(OUT), { recursive: true });
  await writeFile(OUT, html);
  const { gzipSync } = await import('node:zlib');
  const gz = gzipSync(html).length;
  console.log(`build-offline: ${OUT} — ${modules.size} modules, ${(html.length / 1024).toFixed(1)} KB (${(gz / 1024).toFixed(1)} KB gzip)`);
}

main();
