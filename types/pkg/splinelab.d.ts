// The wasm-bindgen glue www/pkg/splinelab.js (and www/pkg/<group>/splinelab.js, built with --no-typescript) as the
// type check of www/ sees it (www/jsconfig.json maps www/ and types/ into one folder with `rootDirs`): the module's
// exports (types/splinelab.d.ts) and the web build's loader.
export * from '../splinelab.js';
export { default, initSync } from '../../npm/web.js';
