// Presentation mode for a mounted demo (index.html, embed.html and the <spline-lab> element).
//
//   const p = createPresenter({ root, title, fullscreenTarget: document.documentElement, keyTarget: document });
//   header.append(p.button);        // "Present" (aria-pressed); the P key toggles, Esc leaves
//   … p.destroy()                   // on unmount
//
// In presentation mode the demo's main view (its first visible 2D plot or 3D view) fills the viewport: the demo
// layout becomes a fixed full-viewport layer (works in iframes without allowfullscreen), and the Fullscreen API
// is asked for where it is allowed. The controls float in a collapsible panel over the right side, readouts
// in large type; a small bar (top left) holds the title, the panel toggle and "Exit presentation".
// Plots are resized through their own API (plot2d: setOptions({ height }) + resize(); View3D: the CSS height
// of its canvas, which it observes), and restored on leaving.

import { h } from './dom.js';
import { mainCanvas } from './demo-export.js';
import { isTyping } from './history.js';

export function createPresenter({ root, title = '', fullscreenTarget = null, keyTarget = null, onChange = () => {} } = {}) {
  let active = false;
  let saved = null;       // { canvas, plot options to restore }
  let bar = null;
  let ownFullscreen = false;
  let docOverflow = '';
  const doc = root.ownerDocument || document;

  const button = h('button', {
    type: 'button', class: 'btn present-toggle', 'aria-pressed': 'false', title: 'Presentation mode: the view fills the screen (P; Esc leaves)',
    onclick: () => toggle(),
  }, 'Present');

  const layer = () => root.querySelector('.demo-layout');
  const plots = () => root.querySelector('.demo-plots');

  function size() {
    if (!active || !saved) return;
    const box = plots();
    // the legends shown under the drawing keep their rows; the drawing takes the rest of the height
    const kept = box ? Array.from(box.querySelectorAll('.present-keep')).filter((l) => l.getClientRects().length) : [];
    const used = kept.reduce((a, l) => a + l.getBoundingClientRect().height, 0);
    const H = Math.max(120, Math.floor((box?.clientHeight || window.innerHeight) - used - 2));
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
    const controls = root.querySelector('.demo-controls');
    const hasControls = controls && !controls.hidden;
    const setPanel = (open) => {
      root.classList.toggle('present-collapsed', !open);
      panelBtn?.setAttribute('aria-expanded', String(open));
      if (panelBtn) panelBtn.textContent = open ? 'Hide controls' : 'Show controls';
    };
    const panelBtn = hasControls ? h('button', {
      type: 'button', class: 'btn btn-small present-panel-toggle', 'aria-expanded': 'true',
      onclick: () => setPanel(root.classList.contains('present-collapsed')),
    }, 'Hide controls') : null;
    // on a narrow screen the panel would hide half the drawing: it starts folded there
    setPanel(hasControls && window.innerWidth >= 1000);
    bar = h('div', { class: 'present-bar', role: 'toolbar', 'aria-label': 'Presentation', tabindex: '-1' },
      title ? h('span', { class: 'present-title' }, title) : null,
      panelBtn,
      h('button', { type: 'button', class: 'btn btn-small present-exit', onclick: () => leave() }, 'Exit presentation'));
    grid.append(bar);
    docOverflow = doc.documentElement.style.overflow;
    doc.documentElement.style.overflow = 'hidden';
    button.setAttribute('aria-pressed', 'true');
    window.addEventListener('resize', onResize);
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
    root.classList.remove('presenting', 'present-collapsed');
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

  function onKey(e) {
    if (e.defaultPrevented || isTyping(e) || e.ctrlKey || e.metaKey || e.altKey) return;
    if ((e.key === 'p' || e.key === 'P') && !e.repeat) { e.preventDefault(); toggle(); }
    else if (e.key === 'Escape' && active) { e.preventDefault(); leave(); }
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
