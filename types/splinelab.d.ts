// The declarations of the wasm module's exports that the type check of www/ (www/jsconfig.json) uses for `ctx.wasm`.
// For now a re-export of the hand-written npm/splinelab.d.ts; issue 29 replaces this file with the declarations
// generated from the Rust API types (the one file to change).
export * from '../npm/splinelab.js';
