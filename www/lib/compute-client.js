// Heavy wasm calls off the main thread (issue 26): a demo hands a list of wasm calls to computeClient(), which runs
// them either right here (small work: faster than a round trip) or in a Web Worker (www/lib/compute-worker.js)
// that instantiates the same wasm module (the demo's group). The page stays responsive while the worker computes.
//
//   const cc = computeClient({ demoId, wasm: ctx.wasm, status: someElement });
//   const calls = [{ fn: 'networkSurfaces', args: { network, samplesU: 96, … } }];   // { …, optional: true }: null on error
//   if (cc.runsHere(key)) draw(cc.runHere(calls, key));              // measured small: synchronously, as before
//   else cc.run(calls, { key }).then((r) => r && draw(r), onError);   // in the worker; null = superseded/cancelled
//
// - Per call, measured: `key` names the size of the work (e.g. "20×20 network, 96², S+G"). A key's calls run where
//   their latest measurement says: measured here, they stay here while under SYNC_MS; measured in the worker (which
//   reports its time), they come back here when that time is under SYNC_MS / WORKER_FACTOR: the worker runs the
//   calls alone, the page runs them in a frame with its drawing and DOM work (measured: blended interpolation's
//   80-point curve took 6 ms in the worker and its pointer handler 57 ms on a loaded 2-core machine). One slow time
//   here after a time under SYNC_MS / 2 is taken as a hiccup (a loaded machine, a garbage collection), not as the
//   key's cost: the key moves to the worker on its second slow time in a row. A key that came back from the worker
//   and was slow again stays in the worker after its second return (no back and forth). A new key is decided by
//   the demo's estimate (`guessMs`, from its measured cost model) and measured.
// - Latest request wins: at most one request computes in the worker and one waits; a newer request replaces the
//   waiting one (which resolves to null), so dragging never builds a queue. The computing one still delivers its
//   result (the newest the page can have), then the waiting one starts.
// - Progress and cancel: while a request takes longer than SHOW_MS the `status` element shows "Working… n s" and a
//   Cancel button; Cancel terminates the worker (the wasm call cannot be interrupted otherwise) and starts a fresh
//   one on the next request; both requests resolve to null. The line's `data-computing` is "true" while a
//   request is unanswered (tests wait for it).
// - Results come back with their typed arrays transferred (no copy); API errors keep `field` and `kind`.
// - Where a worker cannot start (the single-file offline build opened from file://: no module workers there; a
//   browser without module workers), every call runs here, synchronously, exactly as before.

import { h } from './dom.js';
import { wasmFiles, compiledWasm } from './wasm-load.js';
import { t, num } from './i18n.js';

/** @typedef {import('./host.js').SplineLab} SplineLab */
/**
 * One wasm call for computeClient: the export's name and its options (checked against the export's declared
 * options, types/splinelab.d.ts; an option's value may be `{ $ref: [k, key] }`, the result k's `key`, which the type
 * check does not follow). `optional`: an error gives null instead of failing the request.
 * @typedef {{ [K in keyof SplineLab]: { fn: K, args: Parameters<SplineLab[K]>[0], optional?: boolean } }[keyof SplineLab]} WasmCall
 */

/** Work measured under this runs on the main thread: a worker round trip costs ~2–6 ms (structured clone of the
 * input, transfer back, two message tasks; measured with curve-networks on a loaded 2-core machine), and a call
 * under 16 ms keeps a 60 Hz drag within one frame. Over it the main thread would lose frames: the worker. */
export const SYNC_MS = 16;
/** The page's cost of a call over the worker's, assumed when only the worker has measured it (see above). */
export const WORKER_FACTOR = 4;
/** Work running longer than this shows "Working…" with a Cancel button (the 200 ms). */
export const SHOW_MS = 200;

const offlineFile = () => globalThis.document?.body?.dataset.offlineFile === 'true';
/** `globalThis.splinelabCompute = 'here' | 'worker'` forces every call to one side (tests compare the drawings of
 * both; a course page can force 'here'). Unset: decided per call, as above. */
const forced = () => globalThis.splinelabCompute;
/** Can this page start a module worker? (Not in the offline single file: file:// refuses worker scripts.) */
export const workersAvailable = () => typeof Worker === 'function' && !offlineFile();

/** An Error like the API's (message, field, kind) from the worker's plain data. */
function apiError(e) { return Object.assign(new Error(e.message), { name: e.name, field: e.field, kind: e.kind }); }

/** `args` with { $ref: [k, key] } replaced by results[k][key] (as the worker does). */
function resolveRefs(v, results) {
  if (Array.isArray(v)) return v.map((x) => resolveRefs(x, results));
  if (v && typeof v === 'object' && !ArrayBuffer.isView(v) && typeof v !== 'function') {
    if (Array.isArray(v.$ref)) { const [k, key] = v.$ref; return results[k][key]; }
    return Object.fromEntries(Object.entries(v).map(([k, x]) => [k, resolveRefs(x, results)]));
  }
  return v;
}

/**
 * A compute client for one mounted demo.
 * @param {{ demoId: string, wasm: SplineLab, status?: HTMLElement, label?: string }} o  wasm: the page's module of the
 *   demo (ctx.wasm) for the synchronous path; status: where "Working…" and Cancel appear
 */
export function computeClient({ demoId, wasm, status = null, label = 'Computing' }) {
  const files = wasmFiles(demoId);
  const urls = { glue: new URL(files.glue, import.meta.url).href, wasm: new URL(files.wasm, import.meta.url).href };
  const measured = new Map();   // key → ms the calls took here (the last two times, newest last)
  const measuredThere = new Map();   // key → ms the calls took in the worker (last time)
  const latest = new Map();     // key → where it was measured last: 'here' | 'there'
  const returns = new Map();    // key → how often it came back here from the worker
  let worker = null, nextId = 1;
  let running = null;           // { id, resolve, reject, t0 }
  let waiting = null;           // { calls, resolve, reject, key }
  let showTimer = 0, tickTimer = 0;
  let failed = false;           // the worker could not start: everything runs here
  const seen = new Set();        // keys that ran here at least once
  /** Records the time of work `key` done here. A key's first time here is cold code (V8 runs the first calls of a
   * wasm function in its baseline tier: blended interpolation's 80-point curve measured 87 ms on its first call
   * in the page, then 5–7 ms), so a first time over SYNC_MS is not taken as the key's cost: its second time is. */
  function record(key, ms) {
    if (key === undefined) return;
    const first = !seen.has(key);
    seen.add(key);
    if (first && ms >= SYNC_MS && !measured.has(key)) return;
    if (latest.get(key) === 'there') returns.set(key, (returns.get(key) || 0) + 1);
    measured.set(key, [...(measured.get(key) || []), ms].slice(-2));
    latest.set(key, 'here');
  }
  /** Does the latest evidence say that work `key` is small enough for the page? undefined: not measured yet. */
  function small(key) {
    if (latest.get(key) === 'there') return measuredThere.get(key) < SYNC_MS / WORKER_FACTOR && (returns.get(key) || 0) < 2;
    const here = measured.get(key);
    if (!here) return undefined;
    const [before, last] = here.length === 2 ? here : [undefined, here[0]];
    // one slow time after a clearly small one: a hiccup, not the key's cost
    return last < SYNC_MS || (before !== undefined && before < SYNC_MS / 2);
  }
  /** @param {WasmCall[]} calls @param {string} [key] @returns {any[]} */
  function runHere(calls, key) {
    const t0 = performance.now(), results = [];
    for (const { fn, args, optional } of calls) {
      try { results.push(/** @type {(o: unknown) => unknown} */ (wasm[fn])(resolveRefs(args, results))); } catch (e) { if (!optional) throw e; results.push(null); }
    }
    record(key, performance.now() - t0);
    return results;
  }

  // ---------- the status line ----------
  const text = h('span', { class: 'compute-text' });
  const cancelBtn = h('button', { type: 'button', class: 'btn btn-small', onclick: () => cancel() }, t('Cancel'));
  const line = h('span', { class: 'compute-status', role: 'status', hidden: true, dataset: { computing: 'false' } }, text, ' ', cancelBtn);
  if (status) { status.append(line); status.hidden = ![...status.children].some((c) => !(/** @type {HTMLElement} */ (c)).hidden); }
  function busy(on) {
    line.dataset.computing = on ? 'true' : 'false';
    clearTimeout(showTimer); clearInterval(tickTimer);
    // the status element takes room only while one of its lines shows
    const shown = (v) => { line.hidden = !v; if (status) status.hidden = ![...status.children].some((c) => !(/** @type {HTMLElement} */ (c)).hidden); };
    if (!on) { shown(false); return; }
    const t0 = performance.now();
    showTimer = setTimeout(() => {
      const tick = () => { text.textContent = `${t(label)}… ${num((performance.now() - t0) / 1000, 1)} s`; };
      tick(); shown(true);
      tickTimer = setInterval(tick, 250);
    }, SHOW_MS);
  }

  /** Why work `key` goes to the worker, as runsHere() decided it: { key, text, ms (the time measured here that
   * decided it) }. run() writes it on the status line (`data-why`, `data-why-ms`) when it sends that work: read by
   * tests and devtools, nothing depends on it. (Not written by runsHere(): a demo also asks it without sending
   * anything, e.g. the warm-up while a request runs, and that must not overwrite why the request went.) */
  let reason = null;
  function whyThere(key, isSmall, guessMs) {
    const here = measured.get(key);
    if (running || waiting) return { key, text: `${key}: the worker is busy` };
    if (isSmall === undefined) return { key, text: `${key}: new, estimated ${guessMs} ms` };
    if (latest.get(key) === 'there') return { key, text: `${key}: measured ${Number(measuredThere.get(key)).toFixed(1)} ms in the worker` };
    return { key, text: `${key}: measured ${here.map((ms) => ms.toFixed(1)).join(', ')} ms here`, ms: here[here.length - 1] };
  }

  // ---------- the worker ----------
  function start() {
    worker = new Worker(new URL('./compute-worker.js', import.meta.url), { type: 'module', name: `splinelab-${demoId}` });
    worker.onmessage = ({ data }) => {
      if (!running || data.id !== running.id) return;   // a cancelled request's late answer
      const r = running;
      running = null;
      if (data.ok) { if (r.key !== undefined) { measuredThere.set(r.key, data.ms); latest.set(r.key, 'there'); } r.resolve(data.results); } else r.reject(apiError(data.error));
      next();
    };
    // a worker that cannot start (its script not reachable: e.g. a cached site offline that never loaded it) or
    // breaks: this request and every later one run here, synchronously, as without workers
    worker.onerror = (e) => {
      e.preventDefault?.();
      const r = running;
      running = null;
      stop();
      failed = true;
      console.warn(`SplineLab: the compute worker failed (${e.message || 'could not start'}); computing on the page`);
      if (r) { try { r.resolve(runHere(r.calls, r.key)); } catch (err) { r.reject(err); } }
      next();
    };
  }
  function stop() { worker?.terminate(); worker = null; }
  function next() {
    if (running || !waiting) { if (!running && !waiting) busy(false); return; }
    const w = waiting;
    waiting = null;
    if (!worker) start();
    running = { ...w, id: nextId++ };
    // the page's compiled module (structured-cloned, not fetched or compiled again), or its URL
    worker.postMessage({ id: running.id, glue: urls.glue, wasm: compiledWasm(demoId) || urls.wasm, calls: w.calls });
  }

  /** Terminates the computing request (and drops the waiting one): both resolve to null. */
  function cancel() {
    const dropped = [running, waiting];
    running = null; waiting = null;
    stop();
    busy(false);
    for (const r of dropped) r?.resolve(null);
  }

  return {
    /** Does work of size `key` run here? When its time was measured under SYNC_MS (or `guessMs`, the demo's
     * estimate from its measured cost model, when the key is new), unless the worker is still busy (then the
     * order of the results would change), or when no worker is possible. */
    runsHere(key, guessMs = Infinity) {
      if (!workersAvailable() || failed || forced() === 'here') return true;
      if (forced() === 'worker') return false;
      const isSmall = small(key);
      const here = (isSmall ?? guessMs < SYNC_MS) && !running && !waiting;
      if (!here) reason = whyThere(key, isSmall, guessMs);
      return here;
    },
    /** Runs the calls here, now, on the page's module (throws the API's Error); records their time under `key`. */
    runHere,
    /** Records the time (ms) of work `key` that the demo ran here itself (e.g. calls with their own error handling). */
    record,
    /** Runs the calls in the worker: a Promise of their results, or of null when superseded or cancelled. */
    /** @param {WasmCall[]} calls @param {{ key?: string }} [options] @returns {Promise<any[] | null>} */
    run(calls, { key = undefined } = {}) {
      if (!workersAvailable() || failed) {
        try { return Promise.resolve(runHere(calls, key)); } catch (e) { return Promise.reject(e); }
      }
      const why = reason && reason.key === key ? reason : { key, text: `${key ?? 'work'}: sent to the worker by the demo` };
      reason = null;
      line.dataset.why = why.text;
      if (why.ms !== undefined) line.dataset.whyMs = String(why.ms); else delete line.dataset.whyMs;
      return new Promise((resolve, reject) => {
        waiting?.resolve(null);   // superseded: latest request wins
        waiting = { calls, resolve, reject, key };
        if (!running) busy(true);
        next();
      });
    },
    cancel,
    /** Is a request unanswered? */
    get busy() { return !!(running || waiting); },
    /** The latest measured time (ms) of work `key`, if any (here or in the worker). */
    measured: (key) => (latest.get(key) === 'there' ? measuredThere.get(key) : measured.get(key)?.at(-1)),
    destroy() { cancel(); line.remove(); },
  };
}
