// The host of a demo: what the playground shell (www/app.js: index.html, embed.html) and the <spline-lab> element
// (www/spline-lab.js) share. Both are thin callers of this module: they build their own chrome (gallery, header,
// share panel, notices; the element's shadow root and tools) and leave the rest here:
//   - loadWasm(demoId)       the wasm module of the demo's group (www/lib/wasm-groups.js), fetched and compiled as
//                            it streams, once per page and group; the complete module where no group applies
//   - loadDemo(id)           imports www/demos/<id>.js and checks the demo contract (www/demos/README.md)
//   - readState(mod, p)      a link's state payload → a validated state, or the defaults and why
//   - mountDemo({ … })       mounts a demo with its ctx, the Export row, the undo history and the presenter, runs the
//                            extensions, and returns the mounted demo (one object to destroy)
//   - addExtension(fn)       the one place where other features (exercises, "copy as code", …) get each mounted
//                            demo: fn(mounted) runs after every mount and may return a clean-up function
// Paths resolve against this file, so the element works from another origin (the host sends CORS headers).

import { decodeState, validateState, StateError } from './state.js';
import { demoExportRow, placeRow } from './demo-export.js';
import { withExercise, mountExercise } from './exercise.js';
import { importDemo } from '../demos/index.js';
import { loadWasm } from './wasm-load.js';
import { t } from './i18n.js';

/**
 * The wasm module's exports as a demo sees them (`ctx.wasm`; types/splinelab.d.ts: the declarations of every export,
 * its options and results). A group's module has only the exports of that group (www/lib/wasm-groups.js).
 * @typedef {typeof import('../../types/splinelab.js')} SplineLab
 */
/**
 * What a demo's `mount(root, ctx)` gets (the demo contract, www/demos/README.md).
 * @typedef {object} DemoContext
 * @property {SplineLab} wasm  the initialised wasm module of the demo's group
 * @property {Record<string, any>} state  the current state (mutate it in place, then call save())
 * @property {(() => void) & { flush?: () => void, cancel?: () => void, now?: () => Promise<void> }} save  writes the
 *   state to the URL hash (debounced)
 * @property {{ controls?: boolean, explain?: boolean, locked?: boolean }} options  the embed options
 * @property {(msg: string, kind?: 'info' | 'error') => void} notify  a transient message
 */
/**
 * What a demo's mount() returns.
 * @typedef {object} MountedDemo
 * @property {() => void} destroy
 * @property {() => void} [warm]
 * @property {() => { json?: object, obj?: object[], csv?: object }} [exports]
 */

export { BASE, wasmFiles, compiledWasm, loadWasm } from './wasm-load.js';

/** Throws unless `mod` follows the demo contract (www/demos/README.md) for the demo `id`. */
export function checkDemoModule(id, mod) {
  if (!mod || typeof mod.mount !== 'function' || typeof mod.defaults !== 'function' || !mod.meta || typeof mod.meta.title !== 'string') {
    throw new Error('the module does not follow the demo contract (meta, defaults, mount)');
  }
  if (mod.meta.id !== id) throw new Error(`meta.id is "${mod.meta.id}", expected "${id}"`);
  const d = mod.defaults();
  if (!d || typeof d !== 'object' || Array.isArray(d)) throw new Error('defaults() must return an object');
  JSON.stringify(d);
}

const demoLoads = new Map(); // id → Promise<module>
/**
 * Imports www/demos/<id>.js (once per page) and checks the contract; rejects with the reason. Demo modules load
 * on demand: a demo route imports only its own module (and what it imports) before the first drawing.
 */
export function loadDemo(id) {
  if (!demoLoads.has(id)) {
    const p = importDemo(id).then((mod) => { checkDemoModule(id, mod); return mod; });
    p.catch(() => demoLoads.delete(id));
    demoLoads.set(id, p);
  }
  return demoLoads.get(id);
}

/**
 * The state a link's payload describes, validated against the demo's defaults. A payload that cannot be read
 * gives the defaults and the reason (`error`, a sentence for a notice); an empty payload gives the defaults.
 * An exercise in the link (task, check, tolerance: www/lib/exercise.js) is kept in `state.exercise`; a damaged one
 * is dropped with a `notify` message and the view still opens.
 * @returns {Promise<{ state: object, error: string|null }>}
 */
export async function readState(mod, payload, { notify = () => {} } = {}) {
  if (!payload) return { state: mod.defaults(), error: null };
  try {
    const raw = await decodeState(payload);
    return { state: withExercise(raw, validateState(raw, mod.defaults()), mod.meta.id, notify), error: null };
  } catch (e) {
    return { state: mod.defaults(), error: e instanceof StateError ? e.message : 'unexpected error' };
  }
}

const extensions = new Set();
/**
 * Registers a feature that works on every mounted demo, in both hosts. `fn(mounted)` runs after each mount
 * (mounted: { id, mod, meta, root, ctx, instance, exportRow, presenter, host: 'page' | 'element' }) and may return
 * a function, called when that demo is unmounted. Returns a function that unregisters it (mounted demos keep it
 * until they unmount).
 */
export function addExtension(fn) {
  extensions.add(fn);
  return () => extensions.delete(fn);
}

/**
 * Mounts demo `mod` into `root` (an empty element already in the document) with the ctx of the contract
 * ({ wasm, state, options, notify, save }), then the Export row, the undo history (`history`, from www/lib/history.js:
 * started with `historyStart` 'reset' or 'rebase', then attached to the demo's input) and the
 * extensions. `presenter` (www/lib/present.js) is owned by the mounted demo from now on. A demo whose mount()
 * throws is reported with notify() and the rest still mounts (the page keeps working).
 * @returns the mounted demo; `mounted.destroy({ keepFullscreen })` removes all of it.
 */
export function mountDemo({ id, mod, root, wasm, state, options, notify, save, history = null, historyStart = 'reset', presenter = null, host = 'page', hostElement = null }) {
  const ctx = { wasm, state, options, notify, save };
  const mounted = { id, mod, meta: mod.meta, root, ctx, instance: null, exportRow: null, presenter, host, error: null };
  // an exercise in the state: the student's task and Check button above the demo; results go to the parent page
  // (iframe) or bubble from `hostElement` (<spline-lab>). Checks run on the complete module, loaded on first use.
  const exercise = mountExercise({ demoId: id, wasm: () => loadWasm(), state, root, host: hostElement });
  try {
    mounted.instance = mod.mount(root, ctx) || null;
    root.dataset.mounted = 'true';
  } catch (e) {
    console.error(e);
    mounted.error = e;
    notify(t('The demo failed to start: {why}', { why: e.message }), 'error');
  }
  mounted.exportRow = demoExportRow({
    id, title: mod.meta.title, root, getInstance: () => mounted.instance, getState: () => structuredClone(ctx.state),
    snippet: mod.snippet,
    onError: (e) => notify(t('Export failed: {why}', { why: e.message }), 'error'), hidden: options.controls === false,
  });
  placeRow(root, mounted.exportRow.element);
  // the undo history starts from the state as mounted: no steps ('reset', a new view) or the same steps ('rebase',
  // after undo / redo re-mounted the demo)
  if (history) history[historyStart === 'rebase' ? 'rebase' : 'reset'](ctx.state);
  const detachHistory = history ? history.attach(root) : null;
  const cleanups = [];
  // extensions: every mounted demo's ctx and instance are available here, in both hosts
  for (const fn of extensions) {
    try { const c = fn(mounted); if (typeof c === 'function') cleanups.push(c); } catch (e) { console.error(e); }
  }
  let destroyed = false;
  mounted.destroy = ({ keepFullscreen = false } = {}) => {
    if (destroyed) return;
    destroyed = true;
    for (const c of cleanups) { try { c(); } catch (e) { console.error(e); } }
    exercise?.destroy();
    presenter?.destroy({ keepFullscreen });
    detachHistory?.();
    try { mounted.instance?.destroy?.(); } catch (e) { console.error(e); }
    mounted.exportRow?.destroy();
  };
  return mounted;
}
