// SplineLab playground shell: starts the wasm module, builds the gallery from the demo modules, routes by the
// URL hash (`#<demo-id>/<state>?<options>`), mounts one demo at a time and keeps its state in the hash.
// Used by index.html (gallery, data-mode="gallery") and embed.html (one demo, no chrome, data-mode="embed").
// The demo contract is www/demos/README.md. Loading the wasm and the demos, reading a link's state and mounting a
// demo (ctx, Export row, history, extensions) are www/lib/host.js, shared with the <spline-lab> element.

import { h, clear, append, debounce } from './lib/dom.js';
import { encodeState, parseHash, buildHash, saveLast, loadLast } from './lib/state.js';
import { DEMO_IDS } from './demos/index.js';
import { loadWasm, loadDemo as hostLoadDemo, readState, mountDemo as hostMount } from './lib/host.js';
import { startOffline } from './lib/offline.js'; // service worker: the hosted playground works offline after one visit
import { startStorageNotice } from './lib/storage-notice.js'; // storage blocked or full: a notice says saving is off
import './lib/resize.js'; // embed.html in an iframe tells the parent its height (H5P resizer + splinelab:resize)
import { createHistory, undoKey } from './lib/history.js';
import { createPresenter } from './lib/present.js';
import { demoSummary } from './lib/summary.js'; // the summary under the title: clamped on short screens, with More
import { makeExerciseButton } from './lib/exercise.js';
import { t, startLocale, linkLocale, translateStatic, locale, missingKeys, askedKeys } from './lib/i18n.js'; // the page's language (issue 28)
import { languageMenu } from './lib/language-menu.js';
import { errorText } from './lib/error-text.js'; // a module error in the page's language, from its .field and .kind // exercises: the teacher's "Make exercise" (the student's panel: www/lib/host.js)

const MODE = document.body.dataset.mode === 'embed' ? 'embed' : 'gallery';
startOffline();
startStorageNotice();
const main = document.getElementById('main');
const noticeBox = document.getElementById('notices');

// ---------- notices ----------
/**
 * Shows a message. kind: 'info' | 'error'. extra: { actions: [{ label, onClick }], timeout (ms; 0 = stays),
 * id (replaces an earlier notice with the same id) }. Returns a function that dismisses it.
 */
function notify(msg, kind = 'info', extra = {}) {
  const k = kind === 'error' ? 'error' : kind === 'warning' ? 'warning' : 'info';
  if (extra.id) noticeBox.querySelectorAll(`[data-notice-id="${CSS.escape(extra.id)}"]`).forEach((n) => n.remove());
  const close = () => { clearTimeout(timer); el.remove(); };
  const el = h('div', { class: `notice notice-${k}`, role: k === 'error' ? 'alert' : 'status', dataset: extra.id ? { noticeId: extra.id } : undefined },
    h('span', { class: 'notice-text' }, errorText(msg)),
    (extra.actions || []).map((a) => h('button', { type: 'button', class: 'btn btn-small', onclick: () => { close(); a.onClick(); } }, a.label)),
    h('button', { type: 'button', class: 'notice-close', 'aria-label': t('Dismiss'), onclick: close }, '×'));
  noticeBox.appendChild(el);
  while (noticeBox.children.length > 4) noticeBox.firstElementChild.remove();
  const timeout = extra.timeout ?? (extra.actions?.length ? 0 : k === 'error' ? 12000 : 5000);
  const timer = timeout ? setTimeout(close, timeout) : 0;
  return close;
}

/** Removes the notices shown with `id` (e.g. 'bad-link' when the reader moves on). */
function dismiss(...ids) {
  for (const id of ids) noticeBox.querySelectorAll(`[data-notice-id="${CSS.escape(id)}"]`).forEach((n) => n.remove());
}

// ---------- options (embed) ----------
function readOptions(hashParams) {
  const q = new URLSearchParams(location.search);
  const get = (k) => (hashParams.has(k) ? hashParams.get(k) : q.get(k));
  const flag = (k, dflt) => {
    const v = get(k);
    if (v === null) return dflt;
    return !(v === '0' || v === 'false' || v === 'no' || v === 'off');
  };
  return { controls: flag('controls', true), explain: flag('explain', true), locked: flag('locked', false) };
}

// ---------- start-up ----------
const demos = new Map(); // id → { id, mod?, meta?, error? }

// Demo modules load on demand (www/lib/host.js): a demo route imports only its own module (and what it imports)
// before the first drawing; the gallery (it shows every demo's meta) imports them all.
function loadDemo(id) {
  return hostLoadDemo(id).then((mod) => { demos.set(id, { id, mod, meta: mod.meta }); }, (e) => { demos.set(id, { id, error: e }); });
}
const loadDemos = () => Promise.all(DEMO_IDS.map(loadDemo));

// ---------- gallery ----------
function showGallery() {
  unmount();
  document.title = t('SplineLab — see and play with splines');
  document.body.dataset.view = 'gallery';
  delete document.body.dataset.demo;
  clear(main);
  if (MODE === 'embed') {
    append(main, h('div', { class: 'embed-empty' },
      h('p', null, t('No demo chosen. Add the demo id to the address, e.g. ')),
      h('code', null, 'embed.html#bspline-basics')));
    return;
  }
  const intro = h('section', { class: 'intro' },
    h('h1', null, 'SplineLab'),
    h('p', { class: 'lead' }, t('Interactive constructions from five research papers on splines — drag the points, move the sliders, and see the exact mathematics respond. Every view is a link you can share or embed.')));
  const cards = h('ul', { class: 'cards', 'aria-label': t('Demos') });
  for (const id of DEMO_IDS) {
    const d = demos.get(id);
    if (d && d.mod) {
      append(cards, h('li', null, h('a', { class: 'card', href: `#${id}`, dataset: { demo: id } },
        // the demo's default view, generated by `node scripts/snapshots.mjs --cards` (docs/static/cards/)
        // (not in the single-file offline build, which carries no image files)
        document.body.dataset.offlineFile === 'true' ? null
          : h('img', { class: 'card-thumb', src: `static/cards/${id}.png`, alt: '', loading: 'lazy', width: 320, height: 200 }),
        h('h2', { class: 'card-title' }, t(d.meta.title)),
        d.meta.summary ? h('p', { class: 'card-summary' }, t(d.meta.summary)) : null,
        d.meta.paper ? h('p', { class: 'card-paper' }, t(d.meta.paper)) : null)));
    } else {
      append(cards, h('li', null, h('div', { class: 'card unavailable', 'aria-disabled': 'true', dataset: { demo: id } },
        h('h2', { class: 'card-title' }, id.replace(/-/g, ' ')),
        h('p', { class: 'card-summary' }, t('Not available yet.')),
        h('p', { class: 'card-paper', title: String(d?.error?.message || '') }, t('This demo could not be loaded.')))));
    }
  }
  append(main, intro, cards);
}

// ---------- demo ----------
let current = null; // { id, entry, instance, state, payload, params, save }
let routeToken = 0;

// Undo / redo of the mounted demo's edits (one history per demo visit; undo re-mounts the demo with the earlier
// state and writes it to the hash).
const hist = createHistory({ getState: () => current?.state ?? {}, onChange: () => updateHistoryButtons() });
function updateHistoryButtons() {
  if (!current) return;
  if (current.undoBtn) current.undoBtn.disabled = !hist.canUndo;
  if (current.redoBtn) current.redoBtn.disabled = !hist.canRedo;
}

function unmount({ keepFullscreen = false } = {}) {
  if (!current) return;
  const c = current;
  current = null;
  c.save.cancel?.();
  saveLast(c.id, c.state);
  if (c.mounted) c.mounted.destroy({ keepFullscreen });
  else c.presenter?.destroy({ keepFullscreen });
}

/** Undo ('undo') or redo ('redo') one step: re-mounts the demo with that state, keeps presentation mode. */
async function step(which) {
  const c = current;
  if (!c) return;
  const s = which === 'undo' ? hist.undo() : hist.redo();
  if (!s) { notify(which === 'undo' ? t('Nothing to undo.') : t('Nothing to redo.'), 'info', { id: 'undo', timeout: 1500 }); return; }
  const active = document.activeElement;
  const focus = active === c.undoBtn ? 'undo' : active === c.redoBtn ? 'redo' : active?.tagName === 'CANVAS' ? 'canvas' : null;
  mountDemo(c.entry, s, c.params, '', { keep: true, present: c.presenter?.active, focus });
  await current?.save.now();
}

/** The view's options, with the page's language when it is not English: an embed made in Slovak stays Slovak. */
function withLang(params) {
  const p = new URLSearchParams(params || '');
  if (locale() !== 'en') p.set('lang', locale()); else p.delete('lang');
  return p;
}

function embedUrl(id, payload, params) {
  const u = new URL('embed.html', location.href);
  u.search = '';
  u.hash = buildHash(id, payload, withLang(params)).slice(1);
  return u.href;
}

function elementSnippet(id, payload, params) {
  const src = new URL('spline-lab.js', location.href);
  src.search = ''; src.hash = '';
  const attrs = [`demo="${id}"`];
  if (payload) attrs.push(`state="${payload}"`);
  if (locale() !== 'en') attrs.push(`lang="${locale()}"`);
  for (const k of ['controls', 'explain', 'locked']) if (params?.has(k)) attrs.push(`${k}="${String(params.get(k)).replace(/[^\w.-]/g, '')}"`);
  // fallback content: readable until the element starts, and if it cannot (no script, blocked by CORS/CSP)
  const page = new URL(`index.html${buildHash(id, payload, params)}`, location.href).href;
  const title = t(demos.get(id)?.meta?.title || id).replace(/[<>&"]/g, '');
  return `<script type="module" src="${src.href}"></script>\n<spline-lab ${attrs.join(' ')}>\n  <a href="${page.replace(/"/g, '%22')}">${t('Interactive figure: {title} (SplineLab) ↗', { title }).replace(/[<>&]/g, '')}</a>\n</spline-lab>`;
}

/** The Share panel: link, iframe snippet, element snippet, each with a copy button; a link to the guide. */
function shareBox(getLink, getIframe, getElement) {
  const field = (label, rows) => (rows ? h('textarea', { readonly: true, class: 'share-field', rows, 'aria-label': label, spellcheck: 'false' })
    : h('input', { type: 'text', readonly: true, class: 'share-field', 'aria-label': label }));
  const link = field(t('Link to this view'));
  const iframe = field(t('Embed code: iframe'), 4);
  const element = field(t('Embed code: spline-lab element'), 4);
  const copy = async (f, what) => {
    f.select();
    try { await navigator.clipboard.writeText(f.value); notify(t('{what} copied', { what }), 'info', { id: 'copy' }); }
    catch { notify(t('Press Ctrl+C to copy: {what}', { what }), 'info', { id: 'copy' }); }
  };
  const item = (title, hint, f, btnLabel, what, cls) => h('div', { class: ['share-item', cls] },
    h('span', { class: 'share-label' }, title),
    hint ? h('span', { class: 'share-hint' }, hint) : null,
    f,
    h('button', { type: 'button', class: 'btn btn-small', dataset: { copy: cls }, onclick: () => copy(f, what) }, btnLabel));
  const panel = h('div', { class: 'share-panel', hidden: true, role: 'region', 'aria-label': t('Share this view') },
    item(t('Link to this view'), t('Opens exactly what you see now.'), link, t('Copy link'), t('Link'), 'share-link'),
    item(t('Embed with an iframe'), t('Works in course platforms that strip scripts.'), iframe, t('Copy iframe code'), t('Iframe code'), 'share-iframe'),
    item(t('Embed with the <spline-lab> element'), t('One script line; several figures per page.'), element, t('Copy element code'), t('Element code'), 'share-element'),
    h('p', { class: 'share-guide' }, t('Options (hide controls, lock points, hide the text), hosting and offline use: '),
      h('a', { href: 'guide.html' }, t('the guide for course authors')), '.'));
  const toggleBtn = h('button', { type: 'button', class: 'btn share-toggle', 'aria-expanded': 'false', onclick: async () => {
    const open = panel.hidden;
    if (open) {
      await current?.save.now();
      link.value = getLink();
      iframe.value = getIframe();
      element.value = getElement();
    }
    panel.hidden = !open;
    toggleBtn.setAttribute('aria-expanded', String(open));
  } }, t('Share'));
  return { toggleBtn, panel };
}

function mountDemo(entry, state, params, payload, { keep = false, present = false, focus = null } = {}) {
  unmount({ keepFullscreen: present });
  const { id, mod, meta } = entry;
  const options = readOptions(params);
  document.title = `${t(meta.title)} — SplineLab`;
  document.body.dataset.view = 'demo';
  document.body.dataset.demo = id;
  clear(main);
  const root = h('div', { class: 'demo-root', id: 'demo-root', dataset: { demo: id } });
  const me = { id, entry, instance: null, state, payload, params };

  const writeHash = async () => {
    if (current !== me) return;
    let p;
    try { p = await encodeState(me.state); } catch (e) { notify(t('Could not save the state: {why}', { why: e.message }), 'error'); return; }
    if (current !== me) return;
    me.payload = p;
    const hash = buildHash(id, p, me.params);
    if (location.hash !== hash) history.replaceState(history.state, '', hash);
    me.updateOpenLink?.();
    saveLast(id, me.state);
    for (const f of linkWatchers) f(hash);
  };
  const deb = debounce(() => { writeHash(); me.exportRow?.refresh(); }, 200);
  me.save = Object.assign(() => { if (current === me) hist.touch(); deb(); }, { flush: () => deb.flush(), cancel: () => deb.cancel(), now: async () => { deb.cancel(); await writeHash(); } });

  me.presenter = createPresenter({
    root, title: t(meta.title), fullscreenTarget: document.documentElement, keyTarget: document,
    onChange: (on) => document.body.classList.toggle('is-presenting', on),
  });
  me.undoBtn = h('button', { type: 'button', class: 'btn btn-undo', title: t('Undo (Ctrl+Z)'), disabled: true, onclick: () => step('undo') }, h('span', { 'aria-hidden': 'true' }, '↶'), h('span', { class: 'btn-word' }, ` ${t('Undo')}`));
  me.redoBtn = h('button', { type: 'button', class: 'btn btn-redo', title: t('Redo (Ctrl+Shift+Z or Ctrl+Y)'), disabled: true, onclick: () => step('redo') }, h('span', { 'aria-hidden': 'true' }, '↷'), h('span', { class: 'btn-word' }, ` ${t('Redo')}`));
  // the accessible names are exactly "Undo" / "Redo" (the arrows are decoration)
  me.undoBtn.setAttribute('aria-label', t('Undo'));
  me.redoBtn.setAttribute('aria-label', t('Redo'));

  if (MODE === 'gallery') {
    const { toggleBtn, panel } = shareBox(() => location.href, () => {
      const src = embedUrl(id, me.payload, me.params);
      return `<iframe src="${src}" title="${t(meta.title)} (SplineLab)" width="100%" height="720" style="border:0" loading="lazy"></iframe>`;
    }, () => elementSnippet(id, me.payload, me.params));
    const title = h('h1', { class: 'demo-title', tabindex: '-1' }, t(meta.title));
    // exercise: the teacher's "Make exercise" button and panel (null when the demo offers no checks)
    const maker = makeExerciseButton({ demoId: id, title: t(meta.title), wasm: () => loadWasm(), getState: () => me.state, notify });
    append(main, h('header', { class: 'demo-header' },
      h('a', { class: 'back-link', href: '#' }, `← ${t('All demos')}`),
      title,
      meta.summary ? demoSummary(t(meta.summary)) : null,
      h('div', { class: 'demo-actions' },
        me.presenter.button,
        h('span', { class: 'btn-pair' }, me.undoBtn, me.redoBtn),
        toggleBtn,
        maker?.button,
        h('button', { type: 'button', class: 'btn', onclick: () => {
          hist.record();
          history.replaceState(history.state, '', `#${id}`);
          mountDemo(entry, mod.defaults(), params, '', { keep: true });
        } }, t('Reset'))),
      panel, maker?.panel));
    if (!keep) requestAnimationFrame(() => title.focus({ preventScroll: true }));
  }
  if (MODE === 'embed') {
    append(main, h('h1', { class: 'visually-hidden' }, t(meta.title)));
    const showUndo = !(options.locked && options.controls === false);
    append(main, h('div', { class: 'embed-tools', role: 'toolbar', 'aria-label': t('Figure tools') },
      showUndo ? [me.undoBtn, me.redoBtn] : null, me.presenter.button));
  }
  append(main, root);
  if (MODE === 'embed') {
    me.openLink = h('a', { class: 'embed-open', target: '_blank', rel: 'noopener' }, t('Open “{title}” in SplineLab ↗', { title: t(meta.title) }));
    me.updateOpenLink = () => { me.openLink.href = new URL(`index.html${buildHash(id, me.payload, me.params)}`, location.href).href; };
    me.updateOpenLink();
    append(main, h('p', { class: 'embed-footer' }, me.openLink));
  }
  current = me;

  // (the extensions of www/lib/host.js get me.mounted: ctx, instance, root)
  // A warm-up call (www/lib/warm.js) recomputes what is already shown: the notices it would raise (a state whose
  // fit fails) were given when it was first computed, so they are not given again (they were: noisy-data showed a
  // fourth copy of its error notice)
  let warming = false;
  me.mounted = hostMount({
    id, mod, root, wasm: entry.wasm, state, options, notify: (...a) => (warming ? () => {} : notify(...a)), save: me.save,
    history: hist, historyStart: keep ? 'rebase' : 'reset', presenter: me.presenter, host: 'page',
  });
  me.instance = me.mounted.instance;
  const warm = me.instance?.warm;
  const warmed = typeof warm === 'function' ? { ...me.mounted, instance: { warm() { warming = true; try { warm.call(me.instance); } finally { warming = false; } } } } : me.mounted;
  import('./lib/warm.js').then((w) => { if (current === me) w.warmStart(warmed); }, () => {}); // idle warm-up of the drag path (issue 26)
  updateHistoryButtons();
  if (present) me.presenter.enter();
  if (focus) {
    const el = focus === 'undo' ? me.undoBtn : focus === 'redo' ? me.redoBtn : me.presenter.active ? root.querySelector('.present-main canvas') : root.querySelector('canvas');
    requestAnimationFrame(() => { (el && !el.disabled ? el : root.querySelector('canvas'))?.focus({ preventScroll: true }); });
  }
}

function badLinkNotice(entry, reason) {
  const last = loadLast(entry.id, entry.mod.defaults());
  const actions = last ? [{ label: t('Restore my last state'), onClick: () => { mountDemo(entry, last, parseHash(location.hash).params, ''); current?.save(); } }] : [];
  notify(t('This link\'s state could not be read ({why}). Showing the default {title} demo.', { why: reason, title: t(entry.meta.title) }), 'warning', { actions, id: 'bad-link', timeout: 0 });
  document.body.dataset.badLink = 'true';
}

/** Called with the link each time the mounted view's state is written to it (a SCORM launch keeps it in the LMS). */
const linkWatchers = new Set();

async function route() {
  const token = ++routeToken;
  const { id, payload, params } = parseHash(location.hash);
  // a notice about the previous link's damaged state does not outlive that demo
  if (!current || current.id !== id || (payload && payload !== current.payload)) { dismiss('bad-link'); delete document.body.dataset.badLink; }
  if (id && demos.get(id)?.mod) dismiss('bad-route');
  if (id === '' || id === null) {
    if (id === null) notify(t('This link names a demo that does not exist.'), 'warning', { id: 'bad-route' });
    await loadDemos();
    if (token === routeToken) showGallery();
    return;
  }
  // the demo's module and its group's wasm module (www/lib/wasm-groups.js) load in parallel
  let wasm = null;
  let wasmError = null;
  if (DEMO_IDS.includes(id)) [, [wasm, wasmError]] = await Promise.all([loadDemo(id), loadWasm(id).then((m) => [m, null], (e) => [null, e])]);
  if (token !== routeToken) return;
  const entry = demos.get(id);
  if (!entry) { notify(t('There is no demo called "{id}".', { id }), 'warning', { id: 'bad-route' }); await loadDemos(); if (token === routeToken) showGallery(); return; }
  if (!entry.mod) {
    notify(t('The demo "{id}" is not available yet.', { id }), 'warning', { id: 'bad-route' });
    await loadDemos();
    if (token === routeToken) showGallery();
    return;
  }
  if (wasmError) { showFatal(wasmError); return; }
  entry.wasm = wasm;
  if (current && current.id === id && current.payload === payload) return; // our own replaceState / same view
  const { state, error: reason } = await readState(entry.mod, payload, { notify });
  if (token !== routeToken) return;
  delete document.body.dataset.badLink;
  mountDemo(entry, state, params, reason ? '' : payload);
  if (reason) {
    history.replaceState(history.state, '', buildHash(id, '', params));
    badLinkNotice(entry, reason);
  }
  if (MODE === 'gallery') window.scrollTo(0, 0);
}

// For tests and devtools (no behaviour depends on it): the mounted demo's state and a way to write it now.
window.splinelab = Object.freeze({
  /** The mounted demo's id and a deep copy of its state, or null. */
  current: () => (current ? { id: current.id, state: structuredClone(current.state), payload: current.payload } : null),
  /** Writes a pending (debounced) state save to the URL hash and localStorage now. */
  flush: async () => { if (current) await current.save.now(); },
  notify,
  /** The page's language, the texts its catalogue lacks, and every text asked for (issue 28's check reads these). */
  i18n: { locale, missingKeys, askedKeys },
});

function showFatal(wasmError) {
  unmount();
  clear(main);
  append(main, h('div', { class: 'fatal', role: 'alert' },
    h('h1', null, t('The SplineLab engine could not start')),
    h('p', null, t('The WebAssembly module (pkg/splinelab.js) did not load. Build it with scripts/build-wasm.sh, then reload.')),
    h('p', { class: 'fatal-detail' }, String(wasmError.message || wasmError))));
  document.documentElement.dataset.ready = 'error';
}

async function start() {
  // (the wasm module of the routed demo's group loads in route(); the gallery needs none)
  window.addEventListener('hashchange', () => { route(); });
  document.addEventListener('keydown', (e) => {
    const which = current && !e.defaultPrevented ? undoKey(e) : null;
    if (!which) return;
    e.preventDefault();
    step(which);
  });
  window.addEventListener('pagehide', () => current?.save.flush());
  // the language (lang= of the link, the reader's choice, the browser's): its catalogue loads before anything is
  // written (English loads nothing); the header's static words and its language menu follow it. The routed demo's
  // module and wasm start loading first, so a language's catalogue downloads beside them, not before them
  const routed = parseHash(location.hash).id;
  if (routed && DEMO_IDS.includes(routed)) { loadDemo(routed); loadWasm(routed).catch(() => {}); }
  await startLocale({ param: linkLocale() });
  translateStatic();
  if (MODE === 'gallery') languageMenu(document.querySelector('.site-header'));
  await route();
  if (document.documentElement.dataset.ready !== 'error') document.documentElement.dataset.ready = 'true';
  // after the first drawing (two animation frames: it is on screen; a 3D view's first frame can take seconds in
  // software WebGL) fetch the other demos while the page is idle, so the gallery opens at once
  // (html[data-demos="loaded"] once they are in, failed or not: a test leaves the page only then, as a page left
  // while modules load logs a failed load for each of them in Firefox)
  requestAnimationFrame(() => requestAnimationFrame(() => setTimeout(() => {
    loadDemos().finally(() => { document.documentElement.dataset.demos = 'loaded'; });
  }, 1500)));
}

// A SCORM package's launch page (issue 27: the one-file build with the package's config in its head) opens the
// exercise, or the view the student left, before the shell routes, and reports to the LMS (www/lib/scorm-launch.js)
if (document.getElementById('splinelab-scorm')) {
  import('./lib/scorm-launch.js').then(
    (m) => m.launchScorm(m.scormConfig(), { start, notify, flush: async () => { await current?.save.now(); }, watchLink: (f) => linkWatchers.add(f) }),
    () => start());
} else start();
