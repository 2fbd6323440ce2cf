// <spline-lab>: a SplineLab demo as a custom element, for course pages that allow scripts.
//
//   <script type="module" src="https://example.org/splinelab/spline-lab.js"></script>
//   <spline-lab demo="bspline-basics"></spline-lab>
//   <spline-lab demo="bspline-basics" state="v1.…" height="560" controls="false" explain="false" locked="true"></spline-lab>
//
// Attributes (all optional except `demo`):
//   demo      a demo id (www/demos/index.js), e.g. "bspline-basics"
//   state     the state part of a SplineLab link (the text after "#<demo>/"), or a whole link / hash
//             "…#<demo>/<state>?controls=0" (then `demo` may be left out and the link's options apply)
//   height    the element's height (CSS: "560", "560px", "70vh"); content scrolls inside. Default: natural height.
//   controls  "false" hides the controls column;  explain "false" hides the explanation text;
//   locked    "true" stops the points from being dragged.
//   lang      the language: en, sk, ro, hu or it (default: the course page's <html lang> or a lang on a container,
//             else the reader's choice or browser). One language per page: the figures of a page share it.
//
// Several elements per page are independent (each has its own state and its own shadow root, so the course
// page's CSS and SplineLab's do not mix); they share one wasm instance. The element never touches the page's
// URL. Events: `ready` when the demo is mounted, `change` (detail: { state }) after the user changed it.
// Methods: `getState()` (a copy), `async getLink()` (a link to the full SplineLab page with this state),
// `async getPayload()` (the value for the `state` attribute).

import { DEMO_IDS } from './demos/index.js';
import { encodeState, parseHash, buildHash } from './lib/state.js';
import { createHistory, undoKey } from './lib/history.js';
import { createPresenter } from './lib/present.js';
import { BASE, loadWasm, loadDemo, readState, mountDemo } from './lib/host.js';
import { t, setLocale, chooseLocale } from './lib/i18n.js';
import { errorText } from './lib/error-text.js';

// (the wasm module: www/lib/host.js loads the module of each demo's group once per page, shared by the elements
// of that group; loadWasm(demoId) stays exported here for course pages that call the API themselves)
export { loadWasm };

// Styles: the site's style.css, plus its :root variables re-declared on :host (a shadow root has no :root).
let hostSheetPromise = null;
function hostSheet() {
  if (!hostSheetPromise) {
    hostSheetPromise = (async () => {
      let vars = '';
      try {
        const css = await (await fetch(new URL('style.css', BASE).href)).text();
        const m = /:root\s*\{([^}]*)\}/.exec(css);
        if (m) vars = m[1];
      } catch { /* the link still styles most things */ }
      const text = `:host { display: block; position: relative; min-height: 10rem; ${vars} font-family: var(--font, system-ui, sans-serif);`
        + ' font-size: var(--fs, 1rem); line-height: 1.5; color: var(--c-text, #1a1a1a); background: #fff;'
        + ' border: 1px solid var(--c-border, #c9c9c4); border-radius: var(--radius, 8px); }'
        + ' :host([hidden]) { display: none; }'
        + ' .sl-el-body { padding: 0.5rem; box-sizing: border-box; }'
        + ' .sl-el-body.sl-el-fixed { overflow: auto; }'
        + ' .sl-el-message { padding: 1rem; margin: 0; }'
        + ' .sl-el-message.error { color: #6e1a09; background: #fdf0ed; border: 2px solid #a1260d; border-radius: 6px; font-weight: 600; }'
        + ' .sl-el-fallback { display: block; padding: 0 1rem 1rem; }'
        + ' .sl-el-fallback a, .sl-el-open { font-weight: 600; }'
        + ' .sl-el-notices { position: sticky; top: 0; z-index: 5; display: flex; flex-direction: column; gap: 0.25rem; }'
        + ' .sl-el-notice { padding: 0.4rem 0.6rem; border-radius: 6px; background: #eef4fb; border: 1px solid #7aa7d6; }'
        + ' .sl-el-notice.error { background: #fdf0ed; border-color: #a1260d; color: #6e1a09; }'
        + ' .sl-el-footer { margin: 0.5rem 0 0; text-align: right; font-size: 0.9rem; }';
      try {
        const sheet = new CSSStyleSheet();
        sheet.replaceSync(text);
        return sheet;
      } catch { return text; }
    })();
  }
  return hostSheetPromise;
}

const FALSE = new Set(['false', '0', 'no', 'off']);
const flag = (v, dflt) => (v === null ? dflt : !FALSE.has(String(v).trim().toLowerCase()));

function cssHeight(v) {
  if (v == null) return null;
  const s = String(v).trim();
  const m = /^(\d{1,5}(?:\.\d+)?)(px|vh|em|rem)?$/.exec(s);
  if (!m) return null;
  const n = Number(m[1]);
  if (!(n > 0)) return null;
  return `${n}${m[2] || 'px'}`;
}

function el(tag, cls, text) {
  const e = document.createElement(tag);
  if (cls) e.className = cls;
  if (text != null) e.textContent = text;
  return e;
}

export class SplineLabElement extends HTMLElement {
  static get observedAttributes() { return ['demo', 'state', 'height', 'controls', 'explain', 'locked', 'lang']; }

  constructor() {
    super();
    this._root = this.attachShadow({ mode: 'open' });
    this._instance = null;
    this._state = null;
    this._token = 0;
    this._scheduled = false;
    // undo / redo of the reader's edits (Ctrl+Z, Ctrl+Shift+Z / Ctrl+Y while the focus is inside the element)
    this._history = createHistory({ getState: () => this._state ?? {}, onChange: () => this._updateHistory() });
    this._stepping = null;
    this.addEventListener('keydown', (e) => {
      const which = this._instance && !e.defaultPrevented ? undoKey(e) : null;
      if (!which) return;
      e.preventDefault();
      this._step(which);
    });
  }

  _updateHistory() {
    if (this._undoBtn) this._undoBtn.disabled = !this._history.canUndo;
    if (this._redoBtn) this._redoBtn.disabled = !this._history.canRedo;
  }

  /** Undo / redo one step: re-mounts the demo with that state (staying in presentation mode). */
  _step(which) {
    const s = which === 'undo' ? this._history.undo() : this._history.redo();
    if (!s) return;
    const focus = this._root.activeElement === this._undoBtn ? 'undo' : this._root.activeElement === this._redoBtn ? 'redo' : null;
    this._stepping = { present: !!this._mounted?.presenter?.active, focus };
    this._state = s;
    this._render();
  }

  connectedCallback() { this._schedule(); }

  disconnectedCallback() {
    this._token++;
    this._unmount();
  }

  attributeChangedCallback(name, oldValue, newValue) {
    if (oldValue === newValue || !this.isConnected) return;
    this._schedule();
  }

  /** The current state of the demo (a deep copy), or null before it is mounted. */
  getState() { return this._state ? structuredClone(this._state) : null; }

  /** The value for the `state` attribute that reproduces the current view. */
  async getPayload() { return this._state ? encodeState(this._state) : ''; }

  /** A link to the full SplineLab page (index.html) showing the current state. */
  async getLink() {
    if (!this._demoId) return '';
    const payload = await this.getPayload();
    return new URL(`index.html${buildHash(this._demoId, payload)}`, BASE).href;
  }

  _schedule() {
    if (this._scheduled) return;
    this._scheduled = true;
    queueMicrotask(() => { this._scheduled = false; if (this.isConnected) this._render(); });
  }

  _unmount() {
    const m = this._mounted;
    this._mounted = null;
    this._instance = null;
    m?.destroy({ keepFullscreen: !!this._stepping?.present });
  }

  _message(text, kind = 'info') {
    const p = el('p', `sl-el-message ${kind}`, text);
    p.setAttribute('role', kind === 'error' ? 'alert' : 'status');
    return p;
  }

  /**
   * What shows until the demo runs, and instead of it when it cannot: the page's own fallback content (the
   * element's children, e.g. a link written by the Share panel) through a <slot>, else a link to the demo on
   * the SplineLab host.
   */
  _fallback(id) {
    const box = el('div', 'sl-el-fallback');
    const slot = document.createElement('slot');
    const host = BASE.host || t('its host');
    const a = el('a', 'sl-el-open', id ? t('Open the SplineLab demo “{id}” on {host} ↗', { id, host }) : t('Open SplineLab on {host} ↗', { host }));
    a.href = new URL(id ? `index.html#${id}` : 'index.html', BASE).href;
    a.target = '_blank';
    a.rel = 'noopener';
    slot.append(a); // shown when the element has no children of its own
    box.append(slot);
    return box;
  }

  _fail(body, id, text) {
    body.replaceChildren(this._message(text, 'error'), this._fallback(id));
    this._done('error');
  }

  async _render() {
    const token = ++this._token;
    this._unmount();
    const shadow = this._root;
    while (shadow.firstChild) shadow.firstChild.remove();

    const link = document.createElement('link');
    link.rel = 'stylesheet';
    link.href = new URL('style.css', BASE).href;
    const notices = el('div', 'sl-el-notices');
    notices.setAttribute('aria-live', 'polite');
    const body = el('div', 'sl-el-body embed');
    // the language: the element's lang attribute, else the course page's (<html lang="sk">, or a lang on a
    // container), else the reader's choice or browser (www/lib/i18n.js); one language for the page's figures
    const lang = await setLocale(chooseLocale({ attr: this.closest('[lang]')?.getAttribute('lang') }), { documentLang: false });
    if (token !== this._token) return;
    body.lang = lang;
    const height = cssHeight(this.getAttribute('height'));
    if (height) { body.style.height = height; body.classList.add('sl-el-fixed'); }
    shadow.append(link, notices, body);
    // start-up: the demo's module and its wasm group start loading now, not after the stylesheet (a round trip)
    const early = (this.getAttribute('demo') || '').trim();
    if (DEMO_IDS.includes(early)) { loadWasm(early).catch(() => {}); loadDemo(early).catch(() => {}); }
    const sheet = await hostSheet();
    if (token !== this._token) return;
    if (typeof sheet === 'string') {
      const style = document.createElement('style');
      style.textContent = sheet;
      shadow.prepend(style);
    } else {
      shadow.adoptedStyleSheets = [sheet];
    }

    // which demo, which state, which options
    let id = (this.getAttribute('demo') || '').trim();
    let payload = (this.getAttribute('state') || '').trim();
    let params = new URLSearchParams();
    if (payload.includes('#')) {
      const parsed = parseHash(payload.slice(payload.indexOf('#')));
      if (!id && parsed.id) id = parsed.id;
      if (parsed.id && parsed.id !== id) payload = '';
      else payload = parsed.payload;
      params = parsed.params;
    }
    const opt = (k, dflt) => (this.hasAttribute(k) ? flag(this.getAttribute(k), dflt) : params.has(k) ? flag(params.get(k), dflt) : dflt);
    const options = { controls: opt('controls', true), explain: opt('explain', true), locked: opt('locked', false) };

    if (!DEMO_IDS.includes(id)) {
      this._fail(body, '', id ? t('SplineLab: there is no demo called "{id}".', { id }) : t('SplineLab: add a demo="…" attribute (for example demo="bspline-basics").'));
      return;
    }
    body.append(this._message(t('Loading SplineLab…')), this._fallback(id));
    let wasm, mod;
    try {
      [wasm, mod] = await Promise.all([loadWasm(id), loadDemo(id)]);
    } catch (e) {
      if (token !== this._token) return;
      console.error(e);
      const why = e && e.message ? e.message : String(e);
      this._fail(body, id, t('This interactive figure could not start ({why}). If the page is on another site than SplineLab, the SplineLab host must send Access-Control-Allow-Origin and serve .wasm as application/wasm.', { why }));
      return;
    }
    if (token !== this._token) return;

    let state = mod.defaults();
    let badState = null;
    const key = `${id}\n${payload}`;
    if (key === this._key && this._state) {
      state = this._state;      // re-connected or only the options changed: keep what the reader did
    } else if (payload) {
      ({ state, error: badState } = await readState(mod, payload, { notify: (m) => console.warn(m) }));
      if (token !== this._token) return;
    }
    this._demoId = id;
    this._state = state;
    this._key = key;

    const notify = (msg, kind = 'info') => {
      const n = el('div', `sl-el-notice ${kind === 'error' ? 'error' : 'info'}`, errorText(msg));
      n.setAttribute('role', kind === 'error' ? 'alert' : 'status');
      notices.append(n);
      while (notices.children.length > 3) notices.firstElementChild.remove();
      setTimeout(() => n.remove(), kind === 'error' ? 10000 : 5000);
    };
    if (badState) notify(t('The state given to this figure could not be read ({why}); showing the default.', { why: badState }), 'error');

    let changeTimer = 0;
    const save = () => {
      if (token === this._token) this._history.touch();
      clearTimeout(changeTimer);
      changeTimer = setTimeout(() => {
        if (token === this._token) this.dispatchEvent(new CustomEvent('change', { detail: { state: this.getState() } }));
      }, 150);
    };
    save.flush = () => {};
    save.cancel = () => clearTimeout(changeTimer);
    save.now = async () => { clearTimeout(changeTimer); };

    const root = el('div', 'demo-root');
    root.dataset.demo = id;
    const footer = el('p', 'sl-el-footer embed-footer');
    const open = el('a', 'embed-open', t('Open “{title}” in SplineLab ↗', { title: t(mod.meta.title) }));
    open.target = '_blank';
    open.rel = 'noopener';
    open.href = new URL(`index.html#${id}${payload && !badState ? '/' + payload : ''}`, BASE).href;
    open.addEventListener('click', async (e) => {
      // link to the state as it is now
      e.preventDefault();
      const href = await this.getLink();
      window.open(href, '_blank', 'noopener');
    });
    footer.append(open);
    const presenter = createPresenter({ root, title: t(mod.meta.title), fullscreenTarget: this, keyTarget: this });
    const tools = el('div', 'embed-tools');
    tools.setAttribute('role', 'toolbar');
    tools.setAttribute('aria-label', t('Figure tools'));
    const histBtn = (en, arrow, hintEn, which) => {
      const label = t(en), hint = t(hintEn);
      const b = el('button', 'btn btn-small');
      b.type = 'button';
      b.title = hint;
      b.setAttribute('aria-label', label);
      b.disabled = true;
      b.append(el('span', null, arrow), el('span', 'btn-word', ` ${label}`));
      b.firstChild.setAttribute('aria-hidden', 'true');
      b.addEventListener('click', () => this._step(which));
      return b;
    };
    this._undoBtn = histBtn('Undo', '↶', 'Undo (Ctrl+Z)', 'undo');
    this._redoBtn = histBtn('Redo', '↷', 'Redo (Ctrl+Shift+Z or Ctrl+Y)', 'redo');
    if (!(options.locked && options.controls === false)) tools.append(this._undoBtn, this._redoBtn);
    tools.append(presenter.button);
    body.replaceChildren(tools, root, footer);
    try {
      const stepping = this._stepping;
      this._stepping = null;
      // (the extensions of www/lib/host.js get this._mounted: ctx, instance, root)
      const mounted = mountDemo({
        id, mod, root, wasm, state, options, notify, save, presenter, host: 'element', hostElement: this,
        history: this._history, historyStart: !stepping && key !== this._historyKey ? 'reset' : 'rebase',
      });
      if (mounted.error) { mounted.destroy(); throw mounted.error; }
      this._mounted = mounted;
      this._instance = mounted.instance;
      this._historyKey = key;
      this._updateHistory();
      if (stepping?.present) presenter.enter();
      if (stepping?.focus) requestAnimationFrame(() => (stepping.focus === 'undo' ? this._undoBtn : this._redoBtn)?.focus());
      if (stepping) this.dispatchEvent(new CustomEvent('change', { detail: { state: this.getState() } }));
      this._done('true');
    } catch (e) {
      console.error(e);
      this._fail(body, id, t('The demo failed to start: {why}', { why: errorText(e) }));
    }
  }

  _done(status) {
    this.dataset.ready = status;
    this.dispatchEvent(new CustomEvent('ready', { detail: { status } }));
  }
}

if (!customElements.get('spline-lab')) customElements.define('spline-lab', SplineLabElement);
