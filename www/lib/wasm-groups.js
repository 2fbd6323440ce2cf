// Which wasm module each demo loads (issue 13, size): the one place that maps demo → group. Every group with a 2D
// curve demo also carries api-facts (curveFacts: the facts its figure description states in words, issue 25).
//
// scripts/build-wasm.sh builds, besides the complete module (pkg/splinelab.js: every export, the public API), one
// smaller module per group into pkg/<group>/ with only the cargo features (src/api binding modules) listed here;
// www/lib/host.js loads the group module of the demo it mounts; scripts/check-size.mjs enforces a budget per
// module. A demo may only call exports of its group's features (tests/e2e/gallery.test.mjs opens every demo on
// its group module). Plain data: Node reads this file too.

/** group → { features: cargo features of src/api, demos: the demo ids that load it }. */
export const WASM_GROUPS = {
  bspline: { features: ['api-bspline', 'api-facts'], demos: ['bspline-basics'] },
  b2: { features: ['api-b2', 'api-fit', 'api-facts'], demos: ['interp-approx', 'noisy-data'] },
  // the two demos call b2Surface, splineBlendedSurface, networkSurfaces and the criss-cross/network exports of
  // api-network-core; api-gordon-core leaves out b2Curve, b2Basis, thinPlateSurface, gordonSurface, surfaceDifferences,
  // networkFromControlNet, networkFromFreeData (161.7 → 138.4 KB gzip, 2026-11-25)
  surfaces: { features: ['api-gordon-core'], demos: ['b2-surfaces', 'curve-networks'] },
  'criss-cross': { features: ['api-network-core'], demos: ['criss-cross-basis'] },
  'quasi-cubic': { features: ['api-quasi-cubic', 'api-bspline', 'api-facts'], demos: ['quasi-cubic-curves', 'blended-interpolation', 'quasi-cubic-surfaces'] },
  bezier: { features: ['api-bezier'], demos: ['bezier-remodel'] },
  knots: { features: ['api-knot-paths'], demos: ['knot-modification'] },
};

/** The group of a demo id, or null (then the complete module serves it). */
export function groupOf(demoId) {
  for (const [g, { demos }] of Object.entries(WASM_GROUPS)) if (demos.includes(demoId)) return g;
  return null;
}

/** The folder, relative to www/, of the wasm module (splinelab.js + splinelab_bg.wasm) that serves a demo. */
export function wasmDir(demoId) {
  const g = groupOf(demoId);
  return g ? `pkg/${g}/` : 'pkg/';
}
