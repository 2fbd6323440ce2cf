// How www/lib/host.js gets a wasm module's glue (wasm-bindgen's splinelab.js) and, where the page carries it, the
// binary. On the site: the glue of the routed demo's group is imported by URL at run time and fetches or is handed
// its binary. scripts/build-offline.mjs builds dist/splinelab.html with its own version of this module (the complete
// module's glue bundled, the binary inline in the page), because a file:// page can neither import nor fetch.

/** The glue module at `url` (a Promise). */
export const importGlue = (url) => import(url);

/** The wasm binary the page carries inline (the offline file), or null: the glue's init fetches it. */
export const inlineBinary = () => null;
