// Writes dist/splinelab.html: the whole playground (gallery + every demo) as ONE self-contained file that opens
// from file:// (double-click) in Chromium, Firefox and WebKit, and can be uploaded to an LMS as a single file.
//
// file:// refuses ES module imports and fetch(), so everything is inside the page:
//   - the JS: esbuild bundles www/app.js into one ES module (no code splitting), inlined in a
//     <script type="module">. Dynamic imports of local files become bundled code: the demos
//     (the `import()` of each demo in www/demos/index.js, DEMO_MODULES),
//     the writers of the Export row, the warm start. Modules still evaluate when first imported, as in the browser.
//   - the wasm: www/lib/wasm-glue.js (how lib/wasm-load.js gets the glue and the binary) is replaced by a version that
//     imports the complete module's glue (www/pkg/splinelab.js, bundled) and decodes the binary, which the page
//     carries as base64 in a <script type="application/octet-stream">;
//   - `import.meta.url` in a source file means "this source file's URL" (wasm-load.js, offline.js, snippet.js resolve
//     paths against it); in one inline bundle it would be the page's, so each use becomes the URL the file would
//     have next to the page (as scripts/build-site.mjs does for its chunks);
//   - style.css is inlined in a <style>; the page's CSP keeps everything inside the file (no network at all).
//
// Usage: node scripts/build-offline.mjs [out=dist/splinelab.html]   (scripts/build-offline.sh builds wasm first)

import { build } from 'esbuild';
import { readFile, writeFile, mkdir } from 'node:fs/promises';
import { existsSync } from 'node:fs';
import { dirname, join, relative, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const WWW = join(ROOT, 'www');
const OUT = resolve(ROOT, process.argv[2] || 'dist/splinelab.html');
const WASM_ID = 'splinelab-wasm';

const fail = (msg) => { console.error(`build-offline: ${msg}`); process.exit(1); };
const toPosix = (p) => p.split(sep).join('/');

/** The offline file's www/lib/wasm-glue.js: the complete module's glue, bundled; the binary from the page. */
const OFFLINE_WASM_GLUE = `
import * as glue from '../pkg/splinelab.js';
export const importGlue = async () => glue;
let bytes = null;
export function inlineBinary() {
  if (!bytes) {
    const b = atob(document.getElementById(${JSON.stringify(WASM_ID)}).textContent.trim());
    bytes = new Uint8Array(b.length);
    for (let i = 0; i < b.length; i++) bytes[i] = b.charCodeAt(i);
  }
  return bytes;
}
`;

/** esbuild plugin: the offline wasm-glue module, and `import.meta.url` → the source file's URL next to the page. */
const offlinePlugin = {
  name: 'offline',
  setup(b) {
    b.onLoad({ filter: /\.js$/ }, async (args) => {
      const rel = toPosix(relative(WWW, args.path));
      if (rel.startsWith('..')) fail(`${args.path} is outside www/`);
      if (rel === 'lib/wasm-glue.js') return { contents: OFFLINE_WASM_GLUE, resolveDir: dirname(args.path), loader: 'js' };
      const src = await readFile(args.path, 'utf8');
      if (!src.includes('import.meta.url')) return { contents: src, loader: 'js' };
      return { contents: src.replace(/\bimport\.meta\.url\b/g, `new URL(${JSON.stringify(rel)}, location.href).href`), loader: 'js' };
    });
  },
};

/** The playground as one ES module (code, and the number of source modules in it). */
async function bundle() {
  const result = await build({
    entryPoints: [join(WWW, 'app.js')],
    bundle: true, splitting: false, format: 'esm', minify: true, target: 'es2022', platform: 'browser',
    preserveSymlinks: true, // (a worktree may link www/pkg to another checkout's build: keep its www/ paths)
    write: false, metafile: true, outfile: join(ROOT, 'dist/.offline/app.js'), plugins: [offlinePlugin],
    logLevel: 'warning', legalComments: 'none',
  });
  const code = result.outputFiles[0].text;
  const inputs = Object.keys(result.metafile.inputs);
  // every import left in the code would be a request the file cannot make
  const imports = Object.values(result.metafile.outputs)[0].imports.filter((i) => i.external || i.kind === 'dynamic-import');
  if (imports.length) fail(`imports left in the bundle: ${imports.map((i) => i.path).join(', ')}`);
  for (const [need, what] of [['demos/bspline-basics.js', 'the demos (dynamic imports)'], ['pkg/splinelab.js', 'the wasm glue'], ['lib/export.js', 'the Export writers']]) {
    if (!inputs.some((p) => toPosix(p).endsWith(`www/${need}`))) fail(`${what} (www/${need}) not in the bundle`);
  }
  // an inline script ends at "</script" and changes parsing state at "<!--" (esbuild escapes these in strings;
  // the minifier drops comments): stop rather than write a page that breaks
  if (/<\/script|<!--/i.test(code)) fail('the bundle contains "</script" or "<!--"');
  return { code, modules: inputs.length };
}

async function main() {
  for (const f of ['pkg/splinelab.js', 'pkg/splinelab_bg.wasm']) if (!existsSync(join(WWW, f))) fail(`www/${f} is missing: run scripts/build-wasm.sh first`);
  const { code, modules } = await bundle();
  const wasm = await readFile(join(WWW, 'pkg/splinelab_bg.wasm'));
  const css = await readFile(join(WWW, 'style.css'), 'utf8');
  let html = await readFile(join(WWW, 'index.html'), 'utf8');

  // everything inline, nothing from outside the file
  const csp = "default-src 'none'; script-src 'unsafe-inline' 'wasm-unsafe-eval'; style-src 'unsafe-inline'; img-src data: blob:; connect-src data: blob:; object-src 'none'; base-uri 'none'";
  html = html
    .replace(/<meta http-equiv="Content-Security-Policy"[^>]*>/, `<meta http-equiv="Content-Security-Policy" content="${csp}">`)
    .replace(/<link rel="stylesheet" href="style\.css">/, () => `<style>\n${css.replace(/<\/(style)/gi, '<\\/$1')}\n</style>`)
    .replace(/\s*<script type="module" src="app\.js"><\/script>/, '')
    .replace(/\s*<script type="module" async src="lib\/wasm-preload\.js"><\/script>/, '') // (the wasm is inline)
    // the start-up hints (modulepreload / preload of the wasm) point at files the single file does not have
    .replace(/\s*<link rel="(?:modulepreload|preload)"[^>]*>/g, '')
    .replace(/[ \t]*<!--[^]*?-->\n/g, (c) => (/modulepreload|preload|start-up/.test(c) ? '' : c))
    .replace(/<body data-mode="gallery">/, '<body data-mode="gallery" data-offline-file="true">');
  if (/<script[^>]+src=|<link[^>]+stylesheet/.test(html)) fail('an external script or stylesheet is left in the page');
  html = html.replace(/<\/body>/, () => `<script type="application/octet-stream" id="${WASM_ID}">${wasm.toString('base64')}</script>\n<script type="module">${code}</script>\n</body>`);
  for (const must of ['<style>', `id="${WASM_ID}"`, 'data-offline-file', '<script type="module">']) if (!html.includes(must)) fail(`index.html changed: could not insert ${must}`);

  await mkdir(dirname(OUT), { recursive: true });
  await writeFile(OUT, html);
  const gz = gzipSync(html).length;
  console.log(`build-offline: ${OUT} — ${modules} modules (esbuild), ${(html.length / 1024).toFixed(1)} KB (${(gz / 1024).toFixed(1)} KB gzip)`);
}

main().catch((e) => fail(e.stack || String(e)));
