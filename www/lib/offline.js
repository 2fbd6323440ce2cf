// Registers the service worker (www/sw.js) of the hosted playground, so that after one visit it also works
// offline, and hands it the list of files this page loaded (they were fetched before the worker existed).
// Does nothing where a service worker cannot or should not run: the single-file dist/splinelab.html (file://, or
// served by an LMS in a SCORM package),
// browsers without it, or a blocked registration (some third-party iframes) — the page works the same.
// app.js calls startOffline() once; importing the module does nothing by itself.

import { WASM_GROUPS } from './wasm-groups.js';

const SW_URL = new URL('../sw.js', import.meta.url);

/**
 * Every group's wasm module (glue and binary, www/lib/wasm-groups.js): a page loads only its demo's, the worker
 * fetches the others in the background so that every demo opens offline.
 */
export function wasmModuleFiles() {
  return Object.keys(WASM_GROUPS).flatMap((g) => ['splinelab.js', 'splinelab_bg.wasm'].map((f) => new URL(`../pkg/${g}/${f}`, import.meta.url).href));
}

/** Same-origin files this page has loaded so far (modules, wasm, CSS), as absolute URLs. */
export function loadedFiles() {
  const own = new URL('../', import.meta.url).href;
  const list = [location.href.split('#')[0]];
  for (const e of performance.getEntriesByType('resource')) if (e.name.startsWith(own)) list.push(e.name);
  return list;
}

/** Registers the worker; resolves to the registration or null. Posts the loaded files once it is active. */
export async function registerOffline() {
  // (the one-file build carries every file inside the page, and has no sw.js beside it where it is served over
  // http, e.g. by an LMS from a SCORM package: Firefox reported the blocked registration as an error)
  if (!('serviceWorker' in navigator) || location.protocol === 'file:' || !window.isSecureContext
    || document.body?.dataset.offlineFile === 'true') return null;
  try {
    const reg = await navigator.serviceWorker.register(SW_URL.href, { scope: new URL('../', import.meta.url).href });
    const ready = await navigator.serviceWorker.ready;
    // wait until the shell has started so that every demo module and the wasm are in the list
    await new Promise((ok) => {
      if (document.documentElement.dataset.ready) { ok(); return; }
      new MutationObserver((_, o) => { if (document.documentElement.dataset.ready) { o.disconnect(); ok(); } })
        .observe(document.documentElement, { attributes: true, attributeFilter: ['data-ready'] });
    });
    ready.active?.postMessage({ type: 'splinelab:cache', urls: [...loadedFiles(), ...wasmModuleFiles()] });
    return reg;
  } catch {
    return null; // registration refused (storage blocked, insecure origin): the page works online as before
  }
}

/** Resolves when the worker has cached the files posted by registerOffline (for tests): { count, total }. */
export function whenCached() {
  return new Promise((ok) => {
    if (!('serviceWorker' in navigator)) { ok(null); return; }
    navigator.serviceWorker.startMessages?.();
    navigator.serviceWorker.addEventListener('message', function on(e) {
      if (e.data?.type === 'splinelab:cached') { navigator.serviceWorker.removeEventListener('message', on); ok(e.data); }
    });
  });
}

/**
 * Starts offline support for the hosted playground (app.js calls it once): registers the worker after the page
 * has loaded. Only the playground's own pages call this. The module has no effect on import, so a bundle that
 * puts it in a shared chunk (scripts/build-site.mjs's kit) does not register SplineLab's worker on a course page
 * that only uses <spline-lab> (there it would control the course page's own URLs).
 */
export function startOffline() {
  if (window.splinelabOffline) return window.splinelabOffline;
  const started = (window.splinelabOffline = { cached: whenCached(), registration: null });
  const register = () => registerOffline().then((r) => { started.registration = r; });
  if (document.readyState === 'complete') register();
  else addEventListener('load', register, { once: true });
  return started;
}
