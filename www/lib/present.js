// Presentation mode for a mounted demo (index.html, embed.html and the <spline-lab> element).
//
//   const p = createPresenter({ root, title, fullscreenTarget: document.documentElement, keyTarget: document });
//   header.append(p.button);        // "Present" (aria-pressed); Alt+P toggles, Esc leaves
//   … p.destroy()                   // on unmount
//
// In presentation mode the demo's main view (its first visible 2D plot or 3D view) fills the viewport: the demo
// layout becomes a fixed full-viewport layer (works in iframes without allowfullscreen), and the Fullscreen API
// is asked for where it is allowed. The controls float in a collapsible panel over the right side, readouts
// in large type; a small bar (top left) holds the title, the panel toggle and "Exit presentation".
// Plots are resized through their own API (plot2d: setOptions({ height }) + resize(); View3D: the CSS height
// of its canvas, which it observes), and restored on leaving.
//
// The drawing is fitted into the area that the title bar and an open controls panel leave free (freeArea():
// the plots' box is inset by the bar's height and by the panel's width, or its height where the panel is a
// bottom sheet), so nothing the demo draws lies under them and the plot's Fit uses what is visible.
// A presenter's clicker steps the construction: in presentation mode PageDown, →, ↓ and Space press the visible
// stepper's "Step", PageUp, ← and ↑ its "Back" (not while a plot or a control has the focus: there the arrows
// move a point or a slider as usual). The live region of the stepper says which step is shown.

import { h } from './dom.js';
import { mainCanvas } from './demo-export.js';
import { isTyping } from './history.js';
import { t } from './i18n.js';

/**
 * @param {{ root?: HTMLElement, title?: string, fullscreenTarget?: HTMLElement | null, keyTarget?: EventTarget | null,
 *   onChange?: (presenting: boolean) => void }} options
 */
export function createPresenter({ root, title = '', fullscreenTarget = null, keyTarget = null, onChange = () => {} } = {}) {
  let active = false;
  let saved = null;       // { canvas, plot options to restore }
  let bar = null;
  let ownFullscreen = false;
  let docOverflow = '';
  let observer = null;
  const doc = root.ownerDocument || document;

  const button = h('button', {
    type: 'button', class: 'btn present-toggle', 'aria-pressed': 'false', title: t('Presentation mode: the view fills the screen (Alt+P; Esc leaves)'), 'aria-keyshortcuts': 'Alt+P',
    onclick: () => toggle(),
  }, t('Present'));

  /** @type {(sel: string) => HTMLElement | null} */
  const find = (sel) => root.querySelector(sel);
  const layer = () => find('.demo-layout');
  const plots = () => find('.demo-plots');

  /** Insets the plots' box so that the bar and an open panel do not cover the drawing. */
  function freeArea() {
    const box = plots();
    if (!active || !box) return;
    const grid = layer();
    const g = grid.getBoundingClientRect();
    const gap = 6;
    const barRect = bar?.getBoundingClientRect();
    const top = barRect ? Math.max(0, Math.ceil(barRect.bottom - g.top) + gap) : 0;
    let right = 0, bottom = 0;
    const panel = find('.demo-controls');
    const open = panel && !panel.hidden && !root.classList.contains('present-collapsed') && panel.getClientRects().length;
    if (open) {
      const r = panel.getBoundingClientRect();
      // a side panel (desktop) takes its width off the right; a bottom sheet (phone) its height off the bottom
      if (r.width < g.width * 0.8) right = Math.max(0, Math.ceil(g.right - r.left) + gap);
      else bottom = Math.max(0, Math.ceil(g.bottom - r.top) + gap);
    }
    box.style.top = `${top}px`;
    box.style.right = `${right}px`;
    box.style.bottom = `${bottom}px`;
  }

  function size() {
    if (!active || !saved) return;
    freeArea();
    const box = plots();
    // the legends shown under the drawing keep their rows; the drawing takes the rest of the height
    const boxH = box?.clientHeight || window.innerHeight;
    box?.querySelectorAll('.present-dropped').forEach((el) => el.classList.remove('present-dropped'));
    const kept = box ? Array.from(box.querySelectorAll('.present-keep'), (l) => /** @type {HTMLElement} */ (l)).filter((l) => l.getClientRects().length) : [];
    // legends get at most a quarter of the height together (they scroll past that: a phone's long legend
    // would otherwise leave the drawing a strip)
    const legends = kept.filter((l) => !l.querySelector('canvas'));
    const legendMax = Math.floor((boxH * 0.25) / Math.max(1, legends.length));
    for (const l of legends) { l.style.maxHeight = `${Math.max(40, legendMax)}px`; l.style.overflowY = 'auto'; }
    const height = (els) => els.reduce((a, l) => a + l.getBoundingClientRect().height, 0);
    // small figures kept under the drawing (a κ plot, a knot line) give way where the main view would get less
    // than half of the free height (a phone with its controls sheet open); they are back when there is room
    const small = kept.filter((l) => l.querySelector('canvas'));
    if (small.length && boxH - height(kept) < boxH * 0.5) small.forEach((l) => l.classList.add('present-dropped'));
    const used = height(kept.filter((l) => !l.classList.contains('present-dropped')));
    const H = Math.max(120, Math.floor(boxH - used - 2));
    const c = saved.canvas;
    if (c.splinePlot) {
      c.splinePlot.setOptions({ height: H, maxHeightRatio: 1000 });
      if (typeof c.splinePlot.resize === 'function') c.splinePlot.resize();
      else { saved.wrap.style.width = 'calc(100% - 1px)'; requestAnimationFrame(() => { saved && (saved.wrap.style.width = ''); }); }
    } else {
      saved.wrap.style.setProperty('--present-h', `${H}px`);
      c.view3d?.render?.();
    }
  }

  function onResize() { size(); }
  function onFullscreen() {
    const fsEl = doc.fullscreenElement;
    if (active && ownFullscreen && !fsEl) { ownFullscreen = false; leave({ fromFullscreen: true }); return; }
    requestAnimationFrame(size);
  }

  function enter({ fullscreen = true } = {}) {
    if (active) return;
    const main = mainCanvas(root);
    const grid = layer();
    if (!main || !grid) return;
    active = true;
    const wrap = main.closest('.plot, .sl-view3d') || main.parentElement;
    const p = main.splinePlot;
    saved = { canvas: main, wrap, options: p ? { height: p.options.height, maxHeightRatio: p.options.maxHeightRatio } : null, focus: doc.activeElement };
    const stop = plots();
    const path = [];
    for (let el = wrap; el && el !== stop && el !== root; el = el.parentElement) path.push(el);
    // what stays beside the main view: legends, and small figures (a knot line, a strip) that are part of the
    // interaction; measured before the layout changes
    const small = Math.min(200, window.innerHeight * 0.3);
    const keep = [];
    for (const parent of [stop, ...path.slice(1)]) {
      for (const c of parent?.children || []) {
        if (path.includes(c) || !c.getClientRects().length) continue;
        const isLegend = c.matches('.legend') || (c.querySelector('.legend') && !c.querySelector('canvas') && c.offsetHeight <= small);
        const isSmallPlot = !!c.querySelector('canvas') && c.offsetHeight <= small;
        if (isLegend || isSmallPlot) keep.push(c);
      }
    }
    path.forEach((el) => el.classList.add('present-path'));
    keep.forEach((el) => el.classList.add('present-keep'));
    wrap.classList.add('present-main');
    root.classList.add('presenting');
    const controls = find('.demo-controls');
    const hasControls = controls && !controls.hidden;
    const setPanel = (open) => {
      root.classList.toggle('present-collapsed', !open);
      panelBtn?.setAttribute('aria-expanded', String(open));
      if (panelBtn) panelBtn.textContent = open ? t('Hide controls') : t('Show controls');
      if (bar) { size(); requestAnimationFrame(size); }
    };
    const panelBtn = hasControls ? h('button', {
      type: 'button', class: 'btn btn-small present-panel-toggle', 'aria-expanded': 'true',
      onclick: () => setPanel(root.classList.contains('present-collapsed')),
    }, t('Hide controls')) : null;
    // on a narrow screen the panel would hide half the drawing: it starts folded there
    setPanel(hasControls && window.innerWidth >= 1000);
    bar = h('div', { class: 'present-bar', role: 'toolbar', 'aria-label': t('Presentation'), tabindex: '-1' },
      title ? h('span', { class: 'present-title' }, title) : null,
      panelBtn,
      h('button', { type: 'button', class: 'btn btn-small present-exit', onclick: () => leave() }, t('Exit presentation')));
    grid.append(bar);
    docOverflow = doc.documentElement.style.overflow;
    doc.documentElement.style.overflow = 'hidden';
    button.setAttribute('aria-pressed', 'true');
    window.addEventListener('resize', onResize);
    // the bar wraps and the bottom sheet grows with its content: the free area follows both
    observer = typeof ResizeObserver === 'function' ? new ResizeObserver(() => requestAnimationFrame(size)) : null;
    observer?.observe(bar);
    if (controls) observer?.observe(controls);
    size();
    requestAnimationFrame(size);
    bar.focus({ preventScroll: true });
    const target = fullscreenTarget;
    if (fullscreen && target && typeof target.requestFullscreen === 'function' && !doc.fullscreenElement && doc.fullscreenEnabled !== false) {
      try {
        target.requestFullscreen().then(() => { ownFullscreen = true; requestAnimationFrame(size); }, () => {});
      } catch { /* not allowed here (iframe without allowfullscreen): the fixed layer is the fallback */ }
    } else if (doc.fullscreenElement && doc.fullscreenElement === target) {
      ownFullscreen = true; // re-entered after a re-mount while the page stayed full screen
    }
    onChange(true);
  }

  function leave({ fromFullscreen = false, keepFullscreen = false } = {}) {
    if (!active) return;
    active = false;
    window.removeEventListener('resize', onResize);
    observer?.disconnect();
    observer = null;
    const box = plots();
    if (box) for (const side of ['top', 'right', 'bottom']) box.style.removeProperty(side);
    root.classList.remove('presenting', 'present-collapsed');
    root.querySelectorAll('.present-keep').forEach((/** @type {HTMLElement} */ el) => { el.style.removeProperty('max-height'); el.style.removeProperty('overflow-y'); el.classList.remove('present-dropped'); });
    root.querySelectorAll('.present-path, .present-main, .present-keep').forEach((el) => el.classList.remove('present-path', 'present-main', 'present-keep'));
    bar?.remove();
    bar = null;
    doc.documentElement.style.overflow = docOverflow;
    button.setAttribute('aria-pressed', 'false');
    if (saved) {
      const { canvas, wrap, options } = saved;
      wrap.style.removeProperty('--present-h');
      if (canvas.splinePlot && options) {
        canvas.splinePlot.setOptions(options);
        canvas.splinePlot.resize?.();
      } else canvas.view3d?.render?.();
    }
    const back = saved?.focus;
    saved = null;
    if (!fromFullscreen && !keepFullscreen && ownFullscreen && doc.fullscreenElement) doc.exitFullscreen?.().catch(() => {});
    if (!keepFullscreen) ownFullscreen = false;
    if (back && back.isConnected && back !== doc.body) back.focus?.({ preventScroll: true });
    onChange(false);
  }

  function toggle() { if (active) leave(); else enter(); }

  /** The stepper a presenter steps: the first one not inside a hidden part of the demo (a tab not shown). */
  function visibleStepper() {
    for (const st of root.querySelectorAll('.stepper')) {
      if (!st.closest('[hidden]')) return st;
    }
    return null;
  }

  /** Keys that a presenter's clicker sends: the step to take (+1, −1), or 0. */
  function stepKey(e) {
    const t = e.composedPath ? e.composedPath()[0] : e.target;
    const neutral = !t || t === doc.body || t === doc.documentElement || t === bar;
    const onControl = !neutral && !!(t.closest?.('.demo-controls') || t.matches?.('canvas, button, input, select, textarea, a, [tabindex]'));
    if (e.key === 'PageDown') return 1;
    if (e.key === 'PageUp') return -1;
    if (onControl) return 0;   // arrows and Space keep their meaning on a focused plot, slider or button
    if (e.key === 'ArrowRight' || e.key === 'ArrowDown' || e.key === ' ') return 1;
    if (e.key === 'ArrowLeft' || e.key === 'ArrowUp') return -1;
    return 0;
  }

  function onKey(e) {
    if (e.defaultPrevented || isTyping(e) || e.ctrlKey || e.metaKey) return;
    // Alt+P (the key's place, e.code: Option+P types "π" on a Mac), not P alone: a one-letter shortcut of the whole
    // page fires on the letters a speech-input user dictates (WCAG 2.2 SC 2.1.4, character key shortcuts)
    if (e.altKey && e.code === 'KeyP' && !e.repeat) { e.preventDefault(); toggle(); return; }
    if (e.altKey) return;
    if (e.key === 'Escape' && active) { e.preventDefault(); leave(); return; }
    if (!active) return;
    const dir = stepKey(e);
    const st = dir && visibleStepper();
    if (!st) return;
    const btn = /** @type {HTMLButtonElement | null} */ (st.querySelector(dir > 0 ? '.step-forward' : '.step-back'));
    e.preventDefault();
    if (btn && !btn.disabled) btn.click();
  }
  keyTarget?.addEventListener('keydown', onKey);
  doc.addEventListener('fullscreenchange', onFullscreen);

  return {
    button, enter, leave, toggle,
    get active() { return active; },
    get fullscreen() { return ownFullscreen; },
    /** keepFullscreen: the demo is re-mounted (undo/redo) and presents again at once. */
    destroy({ keepFullscreen = false } = {}) {
      leave({ keepFullscreen });
      keyTarget?.removeEventListener('keydown', onKey);
      doc.removeEventListener('fullscreenchange', onFullscreen);
    },
  };
}
