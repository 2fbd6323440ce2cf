// The view tools of a 2D plot: pan left / right / up / down, zoom in / out and fit, each one click or tap
// (WCAG 2.2 SC 2.5.1 Pointer Gestures and 2.5.7 Dragging Movements: panning is otherwise a drag of the background,
// zooming the wheel or a pinch). A row under the drawing, not over it (the figure's content stays visible at
// every width), one Tab stop (role=toolbar: the arrow keys, Home and End go from button to button; a keyboard
// user pans here, the plot's own arrows move its points). A click keeps the focus where it was (on the plot: its
// keys keep working). Every button changes the view through the plot's own setView({ user: true }) / zoomBy /
// fitContent, the path of the + − 0 keys: the demo's onView (state, link, undo) hears it alike.

import { fmt, h } from '../dom.js';
import { t } from '../i18n.js';

/** What one pan click moves: this fraction of the visible width (or height). */
export const PAN_STEP = 0.2;
/** What one zoom click scales the visible range by (the + − keys' step). */
export const ZOOM_STEP = 1.25;

/**
 * Builds the tool row. `o` the plot's options (pan, zoom, zoomX, zoomY), `getView()` the visible world rectangle,
 * `setView(v, { user })`, `zoomBy(f)`, `fitContent()` the plot's, `say(msg)` its live region. Returns the row.
 */
export function createViewTools({ o, getView, setView, zoomBy, fitContent, say }) {
  const sayView = (what) => {
    const v = getView();
    const xs = t('x from {a} to {b}', { a: fmt(v.xmin, 3), b: fmt(v.xmax, 3) }), ys = t('y from {a} to {b}', { a: fmt(v.ymin, 3), b: fmt(v.ymax, 3) });
    say(`${what}. ${o.zoomY === false ? xs : o.zoomX === false ? ys : `${xs}, ${ys}`}.`);
  };
  /** Moves the view by a fraction of its size (dx, dy in [−1, 1], y up), like a drag of the background. */
  const pan = (dx, dy) => {
    const v = getView(), w = v.xmax - v.xmin, hgt = v.ymax - v.ymin;
    setView({ xmin: v.xmin + dx * w, xmax: v.xmax + dx * w, ymin: v.ymin + dy * hgt, ymax: v.ymax + dy * hgt }, { user: true });
  };
  const tool = (en, text, run) => { const label = t(en); return h('button', {
    type: 'button', class: 'plot-tool', title: label, 'aria-label': label, tabindex: '-1',
    onclick: () => { run(); sayView(label); },
    // a click leaves the focus where it was (on the plot: its keys keep working after a click on a tool)
    onmousedown: (/** @type {MouseEvent} */ e) => e.preventDefault(),
  }, text); };
  const buttons = [];
  // the view "moves" the way the arrow points: Pan left shows what lies to the left
  if (o.pan && o.zoomX !== false) buttons.push(tool('Pan left', '←', () => pan(-PAN_STEP, 0)), tool('Pan right', '→', () => pan(PAN_STEP, 0)));
  if (o.pan && o.zoomY !== false) buttons.push(tool('Pan up', '↑', () => pan(0, PAN_STEP)), tool('Pan down', '↓', () => pan(0, -PAN_STEP)));
  if (o.zoom) {
    buttons.push(
      tool('Zoom in', '+', () => zoomBy(1 / ZOOM_STEP)), tool('Zoom out', '−', () => zoomBy(ZOOM_STEP)),
      tool('Fit to content', '⤢', () => fitContent()),
    );
  }
  const row = h('div', { class: 'plot-tools plot-toolbar', role: 'toolbar', 'aria-label': t('View of {plot}', { plot: o.ariaLabel }) }, ...buttons);
  rove(row);
  return row;
}

/**
 * One Tab stop for the row (the ARIA toolbar pattern): the button last used keeps tabindex 0, the others −1;
 * ← → Home End move the focus between them. Counts the buttons at each key, so one added later (the ♪ of
 * ../audio-trace.js) joins the row; call `rove(row)` again after adding it.
 */
export function rove(row) {
  const all = () => /** @type {HTMLElement[]} */ (Array.from(row.querySelectorAll('button')));
  const list = all();
  const current = list.find((b) => b.tabIndex === 0 && b.getAttribute('tabindex') === '0') || list[0];
  for (const b of list) b.tabIndex = b === current ? 0 : -1;
  if (row.dataset.roving) return;
  row.dataset.roving = '1';
  row.addEventListener('keydown', (e) => {
    const bs = all(), i = bs.indexOf(/** @type {HTMLElement} */ (e.target));
    if (i < 0) return;
    const to = { ArrowRight: i + 1, ArrowDown: i + 1, ArrowLeft: i - 1, ArrowUp: i - 1, Home: 0, End: bs.length - 1 }[e.key];
    if (to === undefined) return;
    const next = bs[(to + bs.length) % bs.length];
    for (const b of bs) b.tabIndex = b === next ? 0 : -1;
    next.focus();
    e.preventDefault();
  });
}
