// The demos of the gallery, in gallery order: id → its module www/demos/<id>.js (see README.md). One explicit
// `import()` per demo, so that the bundlers (scripts/build-site.mjs, scripts/build-offline.mjs) make one chunk per
// demo with its figure files (www/demos/<id>/) inside: a pattern such as import(`./${id}.js`) would also match
// every figure file and make each one a chunk of its own.
/** @type {Record<string, () => Promise<any>>} */
export const DEMO_MODULES = {
  'bspline-basics': () => import('./bspline-basics.js'),
  'interp-approx': () => import('./interp-approx.js'),
  'noisy-data': () => import('./noisy-data.js'),
  'b2-surfaces': () => import('./b2-surfaces.js'),
  'quasi-cubic-curves': () => import('./quasi-cubic-curves.js'),
  'blended-interpolation': () => import('./blended-interpolation.js'),
  'quasi-cubic-surfaces': () => import('./quasi-cubic-surfaces.js'),
  'curve-networks': () => import('./curve-networks.js'),
  'criss-cross-basis': () => import('./criss-cross-basis.js'),
  'bezier-remodel': () => import('./bezier-remodel.js'),
  'knot-modification': () => import('./knot-modification.js'),
};

/** The demo ids in gallery order. */
export const DEMO_IDS = Object.keys(DEMO_MODULES);

/** Imports the module of demo `id` (a Promise; rejects for an id that is not a demo). */
export function importDemo(id) {
  return Object.hasOwn(DEMO_MODULES, id) ? DEMO_MODULES[id]() : Promise.reject(new Error(`there is no demo "${id}"`));
}
