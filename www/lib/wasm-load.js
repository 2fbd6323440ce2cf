// Loading the wasm module a demo needs: its group's module (www/lib/wasm-groups.js) or the complete one, fetched
// and compiled as it streams, once per page and group. The host (www/lib/host.js) re-exports it for the shell and
// the <spline-lab> element; the compute worker's client (www/lib/compute-client.js) hands the compiled module to its
// worker. Paths resolve against this file, so the element works from another origin (the host sends CORS headers).

import { groupOf, wasmDir } from './wasm-groups.js';
import { importGlue, inlineBinary } from './wasm-glue.js';

/** @typedef {typeof import('../../types/splinelab.js')} SplineLab */

/** The folder of index.html, app.js and spline-lab.js (www/). */
export const BASE = new URL('../', import.meta.url);

/** The single-file offline build (dist/splinelab.html) carries the complete module inside the page. */
const inlineWasm = () => globalThis.document?.body?.dataset.offlineFile === 'true';

/**
 * Where the wasm module that serves `demoId` lives: its group's module (pkg/<group>/, only the exports that
 * group's demos call) or, for an unknown id and in the offline file, the complete module (pkg/).
 * @returns {{ group: string|null, glue: string, wasm: string }} glue and wasm as URLs relative to this file
 */
export function wasmFiles(demoId) {
  const group = inlineWasm() ? null : groupOf(demoId);
  const dir = `../${group ? wasmDir(demoId) : 'pkg/'}`;
  return { group, glue: `${dir}splinelab.js`, wasm: `${dir}splinelab_bg.wasm` };
}

const wasmLoads = new Map(); // glue URL → Promise<module>
const compiled = new Map();  // glue URL → the compiled WebAssembly.Module (null: the glue loaded it its own way)
/** The compiled wasm module of a demo's group, once loadWasm(demoId) has finished (null before, or when it was not
 * compiled here): www/lib/compute-client.js hands it to its worker, so the wasm is fetched and compiled once. */
export const compiledWasm = (demoId) => compiled.get(wasmFiles(demoId).glue) ?? null;
/**
 * The initialised wasm module for a demo (every export its demos call; `loadWasm()` with no id: the complete
 * module). Loaded once per page and group and shared by every demo and element of that group. The wasm is
 * fetched (index.html/embed.html preload it, www/lib/wasm-preload.js) and compiled while it streams, in parallel
 * with loading the glue; if streaming compilation is not possible (e.g. a server without the application/wasm
 * type), the glue loads it its own way.
 */
export function loadWasm(demoId) {
  const { glue, wasm } = wasmFiles(demoId);
  if (!wasmLoads.has(glue)) {
    const p = (async () => {
      // (absolute: scripts/build-site.mjs moves this code into a chunk; the offline file resolves its own paths)
      const m = importGlue(inlineWasm() ? glue : new URL(glue, import.meta.url).href);
      // one request: www/lib/wasm-preload.js may have started this fetch already (then it is taken, once)
      const url = new URL(wasm, import.meta.url).href;
      const started = (globalThis.__splinelabWasmFetch ??= new Map());
      const response = inlineWasm() ? null : started.get(url) || fetch(url);
      started.set(url, null);
      const compiling = inlineWasm() ? null
        : WebAssembly.compileStreaming?.(response).catch(() => null);
      const mod = await m;
      const module = await compiling;
      const bytes = module ? null : inlineBinary();
      await mod.default(module ? { module_or_path: module } : bytes ? { module_or_path: bytes } : undefined);
      compiled.set(glue, module);
      return mod;
    })();
    p.catch(() => wasmLoads.delete(glue)); // a later call tries again
    wasmLoads.set(glue, p);
  }
  return wasmLoads.get(glue);
}
