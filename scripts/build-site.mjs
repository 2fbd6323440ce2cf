// Writes dist/site/: the deployment build of the playground (issue 13, start-up). The source in www/ stays plain
// ES modules and works served as it is (scripts/serve.sh with DEV=1, every e2e test); this build is what a host
// serves (scripts/serve.sh), because a demo page of the source makes ~49 module requests and each round of six
// (HTTP/1.1) costs a round trip on a real link.
//
// What it does (esbuild from npm, a devDependency; ESM output, code splitting, minified):
//   - every page entry (app.js for index.html and embed.html, spline-lab.js for the <spline-lab> element,
//     exercises.js, papers.js, sandbox.js) becomes one module at the same path, with what it needs before its
//     first drawing; what it imports dynamically (each demo, the features loaded after the first frame) becomes a
//     lazily loaded chunk in chunks/. Shared code sits in chunks too; the HTML preloads exactly the chunks the
//     page's entry imports statically (<link rel="modulepreload">), nothing else.
//   - lib/wasm-preload.js (async, first in the page) is rebuilt as one file that, besides starting the routed
//     demo's wasm group (www/lib/wasm-groups.js), preloads that demo's chunks; index.html and embed.html carry the
//     same code inline (a classic script, allowed by its sha256 in the page's CSP), so the demo's code, the wasm
//     glue and the wasm are requested as soon as the HTML is parsed: on a demo route (a state link too) the HTML
//     and then everything else, 2 sequential round trips before the first drawing (3 with the script file).
//   - `import.meta.url` in the source means "this source file's URL" (wasm-load.js, offline.js, snippet.js resolve
//     pkg/, sw.js, sandbox.html against it); in a bundle it would be the chunk's URL, so each use is rewritten to
//     the URL the source file would have in dist/site/ (computed from the output file's own import.meta.url).
//   - everything else (HTML, CSS, pkg/ with the wasm glue and modules, data, static images, sw.js) is copied;
//     the source modules are not (a request for one would be a bug: tests/e2e/site.test.mjs fails on a 404).
// Nothing is fetched from outside the site folder; the pages' CSP (script-src 'self' 'wasm-unsafe-eval') holds.
//
// Usage: node scripts/build-site.mjs [out=dist/site]   (after scripts/build-wasm.sh; scripts/serve.sh runs both)
//   prints each page's critical path (files and KB gzip) and writes <out>/build-manifest.json.
import { build } from 'esbuild';
import { readFile, writeFile, mkdir, rm, cp, readdir, stat } from 'node:fs/promises';
import { existsSync } from 'node:fs';
import { dirname, join, relative, resolve, posix, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';
import { createHash } from 'node:crypto';
import { syncPreloadLists } from './preload-list.mjs';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const WWW = join(ROOT, 'www');
const OUT = resolve(ROOT, process.argv[2] || 'dist/site');
const fail = (msg) => { console.error(`build-site: ${msg}`); process.exit(1); };
const toPosix = (p) => p.split(sep).join('/');

/** page → its entry module (relative to www/). */
const PAGES = {
  'index.html': 'app.js',
  'embed.html': 'app.js',
  'exercises.html': 'exercises.js',
  'papers.html': 'papers.js',
  'sandbox.html': 'sandbox.js',
};
/** The playground's entries (index.html, embed.html; the element script, referenced by course pages under this
 * exact name) are built together with the kit (below); the other pages' entries on their own. */
const SHELL_ENTRIES = ['app.js', 'spline-lab.js'];
const OTHER_ENTRIES = ['exercises.js', 'papers.js', 'sandbox.js'];
/** Worker entries: each one self-contained module (no chunks), because the page hands its text to a worker that
 * cannot import from the site (the sandbox's worker lives in an opaque-origin frame). */
const WORKER_ENTRIES = ['sandbox-worker.js'];
/** Classic scripts copied as they are (the sandbox's frame loads its script without modules or CORS). */
const CLASSIC_SCRIPTS = ['sandbox-frame.js'];
/** What most demos import besides the shell's static graph (with what these import): part of the kit. */
const DEMO_COMMON = ['lib/plot2d.js', 'lib/controls.js', 'lib/mathml.js', 'lib/stepper.js', 'lib/papers-ref.js', 'lib/player.js',
  'lib/point-edit.js', 'lib/data-import.js', 'lib/snippet.js', 'lib/dom.js'];

/** Static imports of a source module (relative specifiers), as paths relative to www/. */
async function staticImports(file) {
  const src = await readFile(join(WWW, file), 'utf8');
  return [...src.matchAll(/^\s*(?:import|export)\s+(?:[^'"]*?\sfrom\s+)?['"](\.[^'"]+)['"]/gm)]
    .map((m) => toPosix(relative(WWW, join(WWW, dirname(file), m[1]))));
}
async function closure(roots) {
  const seen = new Set();
  const walk = async (f) => { if (seen.has(f)) return; seen.add(f); for (const g of await staticImports(f)) await walk(g); };
  for (const r of roots) await walk(r);
  return seen;
}

// The kit: the modules the shell imports statically and those most demos share. esbuild's code splitting gives
// every distinct set of importers its own chunk (a demo page was ~20 requests: 8 small shared chunks for app.js,
// 7 for the demo); routing every import of a kit module from outside the kit through one virtual module puts the
// whole kit in ONE chunk, which app.js and spline-lab.js import and the demo chunks find already loaded.
// Each kit module is seen from outside through a proxy: `export const { a, b } = <its namespace in the kit>`
// (the exported names come from esbuild's metafile; the source has no `export let`, so nothing is lost).
async function kitPlugin() {
  const entries = new Set(SHELL_ENTRIES);
  const kit = [...await closure([...SHELL_ENTRIES, ...DEMO_COMMON])].filter((f) => !entries.has(f) && !f.startsWith('pkg/'));
  const names = new Map();
  const probe = await build({ entryPoints: kit.map((f) => join(WWW, f)), bundle: false, format: 'esm', write: false,
    metafile: true, outdir: join(OUT, '.probe'), outbase: WWW, logLevel: 'error' });
  for (const o of Object.values(probe.metafile.outputs)) names.set(toPosix(relative(WWW, resolve(ROOT, o.entryPoint))), o.exports);
  const index = new Map(kit.map((f, i) => [f, i]));
  return {
    kit,
    plugin: {
      name: 'kit',
      setup(b) {
        b.onResolve({ filter: /^kit:all$/ }, () => ({ path: 'all', namespace: 'kit' }));
        b.onResolve({ filter: /^\.\.?\// }, (args) => {
          if (args.namespace !== 'file') return undefined;
          const target = toPosix(relative(WWW, resolve(args.resolveDir, args.path)));
          const from = toPosix(relative(WWW, args.importer));
          if (!index.has(target) || index.has(from)) return undefined; // inside the kit: the module itself
          // one proxy per importer, so that it lands in the importer's own chunk (a shared proxy would be a chunk)
          return { path: `${target}?from=${from}`, namespace: 'kit-proxy' };
        });
        b.onLoad({ filter: /^all$/, namespace: 'kit' }, () => ({
          contents: kit.map((f, i) => `export * as m${i} from ${JSON.stringify(`./${f}`)};`).join('\n'), resolveDir: WWW, loader: 'js',
        }));
        b.onLoad({ filter: /.*/, namespace: 'kit-proxy' }, (args) => {
          const target = args.path.split('?')[0];
          const ex = names.get(target) || [];
          const plain = ex.filter((n) => n !== 'default');
          return {
            contents: `import { m${index.get(target)} as M } from 'kit:all';\n`
              + (plain.length ? `export const { ${plain.join(', ')} } = M;\n` : '')
              + (ex.includes('default') ? 'export default M.default;\n' : ''),
            resolveDir: WWW, loader: 'js',
          };
        });
      },
    },
  };
}

// `import.meta.url` → a placeholder naming the source file; replaced after the build (see the header)
const URL_MARK = '__SL_SOURCE_URL__';
const sourceUrlPlugin = {
  name: 'source-url',
  setup(b) {
    b.onLoad({ filter: /\.js$/ }, async (args) => {
      const src = await readFile(args.path, 'utf8');
      if (!src.includes('import.meta.url')) return { contents: src, loader: 'js' };
      const rel = toPosix(relative(WWW, args.path));
      if (rel.startsWith('..')) fail(`${args.path} is outside www/`);
      return { contents: src.replace(/\bimport\.meta\.url\b/g, `${URL_MARK}(${JSON.stringify(rel)})`), loader: 'js' };
    });
  },
};

/** Replaces the placeholders in one output file, `file` relative to the site root. */
function fixUrls(code, file) {
  const up = '../'.repeat(file.split('/').length - 1) || './';
  const out = code.replace(new RegExp(`${URL_MARK}\\((["'\`])([^"'\`]+)\\1\\)`, 'g'),
    (m, q, rel) => `new URL(${JSON.stringify(up + rel)},import.meta.url).href`);
  if (out.includes(URL_MARK)) fail(`${file}: an import.meta.url placeholder was left (minifier changed its form?)`);
  return out;
}

async function copySite() {
  await rm(OUT, { recursive: true, force: true });
  // everything but the source modules (bundled) and the developers' pages; pkg/ (wasm glue) and sw.js stay
  await cp(WWW, OUT, {
    recursive: true,
    filter: (src) => {
      const rel = toPosix(relative(WWW, src));
      if (rel === 'dev' || rel.startsWith('dev/')) return false;
      if (rel.endsWith('.md')) return false;
      if (/^jsconfig.*\.json$/.test(rel)) return false; // (the type check's settings)
      if (!rel.endsWith('.js')) return true;
      // (lib/compute-worker.js: a worker script, loaded by URL from lib/compute-client.js; no imports of its own)
      // (lib/scorm.js: its text is inlined into a relay SCORM package's page, www/lib/scorm-package.js)
      return rel.startsWith('pkg/') || rel === 'sw.js' || rel === 'lib/compute-worker.js' || rel === 'lib/scorm.js' || CLASSIC_SCRIPTS.includes(rel);
    },
  });
}

async function main() {
  for (const f of ['pkg/splinelab.js', 'pkg/splinelab_bg.wasm']) if (!existsSync(join(WWW, f))) fail(`www/${f} is missing: run scripts/build-wasm.sh first`);
  // the source pages' module-preload lists follow the module graph (scripts/preload-list.mjs; scripts/test.sh checks)
  for (const { page } of (await syncPreloadLists({ write: true })).stale) console.log(`build-site: www/${page}: module-preload list updated`);
  await copySite();
  // the one-file build (scripts/build-offline.sh) goes beside the pages: "Download for LMS (SCORM)" makes each
  // package's launch page from it (www/lib/scorm-package.js); without it that button says how to get it
  const oneFile = join(ROOT, 'dist/splinelab.html');
  if (existsSync(oneFile)) await cp(oneFile, join(OUT, 'splinelab.html'));
  else console.log('build-site: dist/splinelab.html is not built (scripts/build-offline.sh): the site\'s SCORM downloads will say so');

  // 1. the page entries, split
  const common = {
    bundle: true, format: 'esm', splitting: true, minify: true, target: 'es2022', platform: 'browser',
    preserveSymlinks: true, // (a worktree may link www/pkg to another checkout's build: keep its www/ paths)
    outbase: WWW, outdir: OUT, chunkNames: 'chunks/[name]-[hash]', metafile: true, write: false,
    plugins: [sourceUrlPlugin], logLevel: 'warning', legalComments: 'none',
    // the wasm glue is loaded at run time by URL (lib/wasm-load.js: the routed demo's group); only sandbox.js imports the
    // complete module's glue statically, and bundles it (its wasm URL is fixed like any import.meta.url)
  };
  const { kit, plugin } = await kitPlugin();
  const main = await build({ ...common, entryPoints: SHELL_ENTRIES.map((e) => join(WWW, e)), plugins: [plugin, sourceUrlPlugin] });
  const others = await build({ ...common, entryPoints: OTHER_ENTRIES.map((e) => join(WWW, e)) });
  const workers = await build({ ...common, splitting: false, chunkNames: undefined, entryPoints: WORKER_ENTRIES.map((e) => join(WWW, e)) });
  const outputs = { ...others.metafile.outputs, ...main.metafile.outputs }; // path (relative to cwd) → { imports, entryPoint, bytes }
  const key = (abs) => toPosix(relative(OUT, resolve(ROOT, abs)));
  const byKey = new Map(Object.entries(outputs).map(([p, o]) => [key(p), o]));
  const staticClosure = (k, seen = new Set()) => {
    for (const imp of byKey.get(k)?.imports || []) {
      if (imp.kind !== 'import-statement' || imp.external) continue;
      const d = key(imp.path);
      if (!seen.has(d)) { seen.add(d); staticClosure(d, seen); }
    }
    return seen;
  };
  // (a demo has a chunk in each build; the shell's is the one lib/wasm-preload.js names)
  const entryOut = (src) => [...Object.entries(main.metafile.outputs)].find(([, o]) => o.entryPoint && toPosix(relative(WWW, resolve(ROOT, o.entryPoint))) === src)?.[0];

  // each demo's chunk and what it imports statically (preloaded by lib/wasm-preload.js on a demo route)
  const { DEMO_IDS } = await import(join(WWW, 'demos/index.js'));
  // a figure file (www/demos/<id>/*.js) belongs in its demo's chunk: as an entry of its own (a pattern import such as
  // import(`./demos/${id}.js`) matches them too) each would be one more request before the demo draws
  const stray = Object.values(main.metafile.outputs).map((o) => o.entryPoint && toPosix(relative(WWW, resolve(ROOT, o.entryPoint)))).filter((e) => e && /^demos\/[^/]+\//.test(e));
  if (stray.length) fail(`figure files bundled as chunks of their own: ${stray.join(', ')} (import demos only through DEMO_MODULES of www/demos/index.js)`);
  const demoChunks = {};
  for (const id of DEMO_IDS) {
    const k = entryOut(`demos/${id}.js`);
    if (!k) fail(`no chunk for demos/${id}.js (is it in DEMO_MODULES of www/demos/index.js?)`);
    demoChunks[id] = [key(k), ...staticClosure(key(k))];
  }
  const appStatic = staticClosure(key(entryOut('app.js')));
  for (const id of DEMO_IDS) demoChunks[id] = demoChunks[id].filter((k) => !appStatic.has(k)); // preloaded by the HTML

  // 2. lib/wasm-preload.js: the wasm group (as in the source) plus the routed demo's chunks, one file
  const preloadSrc = `import './wasm-preload.js';
const chunks = ${JSON.stringify(demoChunks)};
const id = /^#([a-z0-9-]+)/.exec(location.hash)?.[1];
if (id && Object.hasOwn(chunks, id)) {
  for (const f of chunks[id]) {
    const l = document.createElement('link');
    l.rel = 'modulepreload';
    l.href = new URL('../' + f, import.meta.url).href;
    document.head.append(l);
  }
}
`;
  const pre = await build({
    ...common, splitting: false, outdir: undefined, outbase: undefined, chunkNames: undefined,
    stdin: { contents: preloadSrc, resolveDir: join(WWW, 'lib'), sourcefile: 'lib/wasm-preload.build.js', loader: 'js' },
    outfile: join(OUT, 'lib/wasm-preload.js'),
  });
  // 2b. the same start-up hint inline in index.html and embed.html (a classic script, allowed by its hash in the
  // page's CSP): the wasm, its glue and the demo's chunks are requested as soon as the HTML is parsed, not one round
  // trip later when lib/wasm-preload.js has arrived (4G: HTML → wasm-preload.js → wasm was 2 sequential round trips
  // before the wasm's first byte, now 1). URLs resolve against the page (both pages are at the site's root).
  const boot = await build({
    ...common, splitting: false, outdir: undefined, outbase: undefined, chunkNames: undefined, format: 'iife', write: false,
    stdin: { contents: preloadSrc.replace("new URL('../' + f, import.meta.url)", 'new URL(f, document.baseURI)'), resolveDir: join(WWW, 'lib'), sourcefile: 'lib/wasm-preload.inline.js', loader: 'js' },
    outfile: join(OUT, 'lib/wasm-preload.inline.js'),
  });
  const bootCode = boot.outputFiles[0].text.trim()
    .replace(new RegExp(`${URL_MARK}\\((["'\`])([^"'\`]+)\\1\\)`, 'g'), (m, q, rel) => `new URL(${JSON.stringify(rel)},document.baseURI).href`);
  if (bootCode.includes(URL_MARK) || bootCode.includes('import.meta') || /<\/script/i.test(bootCode)) fail('the inline start-up script has an import.meta.url or a </script>');
  const bootHash = `'sha256-${createHash('sha256').update(bootCode).digest('base64')}'`;

  // write the JS
  const written = new Map(); // site-relative path → bytes
  for (const f of [...main.outputFiles, ...others.outputFiles, ...workers.outputFiles, ...pre.outputFiles]) {
    const rel = toPosix(relative(OUT, f.path));
    const code = fixUrls(f.text, rel);
    await mkdir(dirname(f.path), { recursive: true });
    await writeFile(f.path, code);
    written.set(rel, Buffer.byteLength(code));
  }

  // 3. the pages: their entry plus the chunks it imports statically; no hints for source modules
  const report = {};
  for (const [page, entry] of Object.entries(PAGES)) {
    const file = join(OUT, page);
    let html = await readFile(file, 'utf8');
    if (!html.includes(`<script type="module" src="${entry}"></script>`)) fail(`${page}: no <script type="module" src="${entry}">`);
    const critical = [...staticClosure(entry)];
    if (entry === 'app.js') {
      const tag = '<script type="module" async src="lib/wasm-preload.js"></script>';
      if (!html.includes(tag) || !html.includes("script-src 'self' 'wasm-unsafe-eval'")) fail(`${page}: no ${tag} or no CSP script-src to extend`);
      html = html.replace(tag, () => `<script>${bootCode}</script>`)
        .replace("script-src 'self' 'wasm-unsafe-eval'", () => `script-src 'self' 'wasm-unsafe-eval' ${bootHash}`);
    }
    html = html
      .replace(/[ \t]*<!--[^]*?-->\n/g, (c) => (/modulepreload|preload|start-up/.test(c) ? '' : c))
      .replace(/[ \t]*<link rel="modulepreload" href="[^"]*">\n/g, '')
      .replace(/[ \t]*<link rel="modulepreload" href="[^"]*">/g, '');
    const hints = critical.map((k) => `  <link rel="modulepreload" href="${k}">\n`).join('');
    html = html.replace(`  <script type="module" src="${entry}"></script>`,
      `${hints}  <script type="module" src="${entry}"></script>`);
    if (/<link rel="modulepreload" href="(?:lib|demos|data)\//.test(html)) fail(`${page}: a hint for a source module is left`);
    await writeFile(file, html);
    report[page] = [entry, ...critical];
  }
  // the element script: every chunk it imports statically (course pages have no hints; listed for the record)
  report['spline-lab.js'] = ['spline-lab.js', ...staticClosure('spline-lab.js')];

  const gz = async (rel) => gzipSync(await readFile(join(OUT, rel)), { level: 6 }).length;
  const kb = (n) => (n / 1024).toFixed(1);
  console.log(`build-site: ${toPosix(relative(ROOT, OUT))}/ — ${written.size} JS files (esbuild, split, minified; the kit: ${kit.length} modules)`);
  for (const [page, files] of Object.entries(report)) {
    let sum = 0;
    for (const f of files) sum += await gz(f);
    console.log(`  ${page.padEnd(15)} critical JS: ${files.length} file(s), ${kb(sum)} KB gzip`);
  }
  for (const id of DEMO_IDS) {
    let sum = 0;
    for (const f of demoChunks[id]) sum += await gz(f);
    console.log(`  #${id.padEnd(22)} + ${demoChunks[id].length} chunk(s), ${kb(sum)} KB gzip (preloaded from the hash)`);
  }
  await writeFile(join(OUT, 'build-manifest.json'), JSON.stringify({ pages: report, demos: demoChunks, files: Object.fromEntries(written) }, null, 1));
}

main().catch((e) => fail(e.stack || String(e)));
