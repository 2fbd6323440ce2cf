// Says so when the browser will not save: with localStorage blocked (third-party iframes with storage blocked,
// some private modes) or full, the playground works on and the state lives in the link, but "restore my last
// state" cannot work. www/lib/state.js reports failures through the `splinelab:storage` event; this shows one
// notice (the shell's notify, kind 'warning', for 20 s or until dismissed — it floats over the figure, so it
// does not stay for good) and marks <html data-storage="off">.
// Inside an iframe (an embedded exercise: cross-origin storage is blocked in private windows, Safari and
// Firefox's strict mode, so this is the usual case there) nothing floats over the task, and there is no
// address to copy: one quiet line under the view says that the work lasts while the page is open.
// app.js calls startStorageNotice() once; importing the module does nothing by itself.

import { probeStorage, storageStatus } from './state.js';
import { h } from './dom.js';

const TEXT = {
  blocked: 'Saving is off: this browser does not let SplineLab store anything here. Everything still works, and your work lives in the link — copy the address to keep it.',
  full: 'Saving is off: this browser’s storage for this site is full. Everything still works, and your work lives in the link — copy the address to keep it.',
};

const EMBEDDED = 'Saving is off in this embedded view (the browser blocks it here): your changes last while this page stays open.';

/** Is this page inside a frame of another page? (a cross-origin parent makes window.top unreadable, not unequal) */
function inFrame() {
  try { return window.self !== window.top; } catch { return true; }
}

let shown = null;
function show(reason) {
  document.documentElement.dataset.storage = reason ? 'off' : 'on';
  if (!reason || shown === reason) return;
  if (inFrame()) {
    shown = reason;
    if (!document.querySelector('.storage-embedded')) document.body.append(h('p', { class: 'storage-embedded', role: 'note' }, EMBEDDED));
    return;
  }
  const notify = window.splinelab?.notify;
  if (typeof notify !== 'function') { setTimeout(() => show(reason), 50); return; }
  shown = reason;
  notify(TEXT[reason] || TEXT.blocked, 'warning', { id: 'storage-off', timeout: 20000 });
}

let started = false;
/**
 * Starts the notice for the playground's own pages (app.js calls it once). Importing the module does nothing by
 * itself, so a bundle that puts it in a shared chunk (scripts/build-site.mjs's kit) does not touch a course page
 * that only uses <spline-lab> (no attribute on its <html>, no note in its body, no polling for a notifier).
 */
export function startStorageNotice() {
  if (started) return;
  started = true;
  window.addEventListener('splinelab:storage', (e) => show(/** @type {CustomEvent} */ (e).detail?.reason ?? null));
  setTimeout(() => { probeStorage(); show(storageStatus()); }, 0);
}
