// Says so when the browser will not save: with localStorage blocked (third-party iframes with storage blocked,
// some private modes) or full, the playground works on and the state lives in the link, but "restore my last
// state" cannot work. www/lib/state.js reports failures through the `splinelab:storage` event; this shows one
// notice (the shell's notify, kind 'warning', for 20 s or until dismissed — it floats over the figure, so it
// does not stay for good) and marks <html data-storage="off">.
// Imported for its effect by app.js: `import './lib/storage-notice.js';`.

import { probeStorage, storageStatus } from './state.js';

const TEXT = {
  blocked: 'Saving is off: this browser does not let SplineLab store anything here. Everything still works, and your work lives in the link — copy the address to keep it.',
  full: 'Saving is off: this browser’s storage for this site is full. Everything still works, and your work lives in the link — copy the address to keep it.',
};

let shown = null;
function show(reason) {
  document.documentElement.dataset.storage = reason ? 'off' : 'on';
  if (!reason || shown === reason) return;
  const notify = window.splinelab?.notify;
  if (typeof notify !== 'function') { setTimeout(() => show(reason), 50); return; }
  shown = reason;
  notify(TEXT[reason] || TEXT.blocked, 'warning', { id: 'storage-off', timeout: 20000 });
}

window.addEventListener('splinelab:storage', (e) => show(e.detail?.reason ?? null));
setTimeout(() => { probeStorage(); show(storageStatus()); }, 0);
