// Start-up hint for index.html and embed.html (issue 13): starts the fetch of the routed demo's wasm module (its
// group's, www/lib/wasm-groups.js) and of its glue while the rest of the module graph is still loading. The pages
// load this as `<script type="module" async>`, so it runs as soon as it and wasm-groups.js arrive, before app.js's
// graph has finished; www/lib/host.js then takes the response of the fetch started here. The gallery
// (no demo in the hash) needs no wasm.
import { groupOf, wasmDir } from './wasm-groups.js';

const id = /^#([a-z0-9-]+)/.exec(location.hash)?.[1];
if (id && groupOf(id) && document.body?.dataset.offlineFile !== 'true') {
  const base = new URL('../', import.meta.url);
  const link = (rel, href, as) => {
    const l = document.createElement('link');
    l.rel = rel;
    l.href = new URL(href, base).href;
    if (as) { l.as = as; l.crossOrigin = 'anonymous'; }
    document.head.append(l);
  };
  const dir = wasmDir(id);
  // the wasm: a fetch() that www/lib/host.js takes over (a <link rel=preload> raced with host.js's own fetch when
  // this script ran second, and the module was then downloaded twice); whichever runs first starts the request
  const url = new URL(`${dir}splinelab_bg.wasm`, base).href;
  const started = (globalThis.__splinelabWasmFetch ??= new Map());
  if (!started.has(url)) started.set(url, fetch(url));
  link('modulepreload', `${dir}splinelab.js`);
}
