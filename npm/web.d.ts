// Types of the web build (`splinelab/web`, wasm-bindgen --target web): the same API as the Node build, plus the
// loader. Call `await init()` once (it fetches splinelab_bg.wasm next to splinelab.js), or `initSync({ module })`
// with the bytes or a compiled WebAssembly.Module, before any other function.
export * from '../splinelab.js';

/**
 * Loads the WebAssembly module. `module_or_path`: `{ module_or_path }` with a URL, a Response, the bytes or a
 * WebAssembly.Module (default: the splinelab_bg.wasm next to this file). Resolves to the module's exports.
 */
export default function init(module_or_path?: unknown): Promise<unknown>;

/** Instantiates the module synchronously from `{ module }`: its bytes or a compiled WebAssembly.Module. */
export function initSync(module: unknown): unknown;
