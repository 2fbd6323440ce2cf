// Pointer, touch, wheel and keyboard input of a 2D plot: dragging handles, panning, pinch and wheel zoom,
// keyboard selection and moves, focus handling and the screen-reader announcements; and moving without dragging
// (WCAG 2.2 SC 2.5.7): a click or tap on a handle picks it, the next single click or tap on the plot moves it there.
//
// Click-then-click and the other gestures: a press that moves less than CLICK_SLOP px is a click (a drag starts
// only past it, so a hand that trembles still clicks). The destination click waits DOUBLE_MS before it moves the
// point: a second press in that time makes it a double-click (point-edit.js inserts or removes a point) and nothing
// moves. A click that picked or moved a point is not passed on to the demo's own click listeners (criss-cross-basis
// picks a cell with a click: with a point picked, the click moves the point instead). Alt+click stays point-edit's.

/** Pointer travel (CSS px) below which a press is a click, not a drag: by pointer type. */
const CLICK_SLOP = { mouse: 4, pen: 6, touch: 10 };
/** How long a destination click waits for a second click (a double-click moves nothing), ms. */
import { t } from '../i18n.js';

export const DOUBLE_MS = 300;

/**
 * Attaches the plot's input handlers to `canvas`. `st` is the shared interaction state, `handles` the handle
 * functions (createHandles), `transform()` → the current transform, `size()` → [W, H]; the view functions
 * move the plot. Returns { select(sel), announce(msg, now), dispose() }.
 */
export function attachInput({ st, o, canvas, live, status, handles, transform, size, toWorld, getView, setView, zoomBy, fitContent, redraw, isFocused, focusFields, fieldsEl }) {
  const { hitTest, movable, applyMove, nameOf, flatHandles } = handles;
  const slopOf = (e) => CLICK_SLOP[e.pointerType] ?? CLICK_SLOP.mouse;
  let pending = null;        // a destination click waiting for DOUBLE_MS: { timer, at: [wx, wy] }
  let skipUp = false;        // the press is the second of a double-click: its release moves nothing
  let eatClick = false;      // the coming click event was a pick or a move: the demo's click listeners skip it
  let tap = null;            // a touch press off the handles (the page may scroll it): { id, x, y }

  let announceTimer = 0;
  function announce(msg, now = false) {
    clearTimeout(announceTimer);
    const go = () => { live.textContent = msg; };
    if (now) go(); else announceTimer = setTimeout(go, 250);
  }

  function localXY(e) {
    const r = canvas.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  }

  function onPointerDown(e) {
    if (e.button !== undefined && e.button > 0 && e.pointerType === 'mouse') return;
    const [px, py] = localXY(e);
    st.pointers.set(e.pointerId, { x: px, y: py });
    if (st.pointers.size === 2 && o.zoom) {
      // second finger: switch to pinch (cancel any handle drag)
      if (st.drag && st.drag.kind === 'handle' && st.drag.group.end) st.drag.group.end(st.drag.index);
      const [a, b] = [...st.pointers.values()];
      st.drag = { kind: 'pinch', dist: Math.hypot(a.x - b.x, a.y - b.y), mid: [(a.x + b.x) / 2, (a.y + b.y) / 2], view: getView() };
      try { canvas.setPointerCapture(e.pointerId); } catch { /* ignore */ }
      e.preventDefault();
      return;
    }
    if (st.pointers.size > 2) return;
    eatClick = false;
    tap = null;
    // a press while a destination click waits is the second click of a double-click: nothing moves
    if (pending) { clearTimeout(pending.timer); pending = null; skipUp = true; } else skipUp = false;
    const hit = hitTest(px, py, e.pointerType);
    if (!(hit && movable(hit.group)) && e.pointerType === 'touch') {
      // one finger that does not start on a handle belongs to the page (it scrolls, touch-action: pan-y);
      // a second finger turns the gesture into a pinch (above). Lifted where it went down, it is a tap.
      tap = { id: e.pointerId, x: px, y: py };
      return;
    }
    if (hit && movable(hit.group)) {
      const p = hit.group.points()[hit.index];
      const again = !!st.picked && st.selected?.group === hit.group && st.selected?.index === hit.index;
      st.drag = { kind: 'handle', group: hit.group, index: hit.index, off: [p[0] - toWorld(px, py)[0], p[1] - toWorld(px, py)[1]], moved: false, start: [px, py], slop: slopOf(e), again };
      st.selected = { group: hit.group, index: hit.index };
      st.by = 'pointer';
      if (hit.group.start) hit.group.start(hit.index);
      canvas.classList.add('dragging');
    } else if (o.pan) {
      st.drag = { kind: 'pan', start: [px, py], view: getView(), slop: slopOf(e) };
      canvas.classList.add('panning');
    } else {
      // no panning here (criss-cross-basis): a press that stays put is still a click
      st.drag = { kind: 'click', start: [px, py], slop: slopOf(e) };
    }
    try { canvas.setPointerCapture(e.pointerId); } catch { /* ignore */ }
    if (!isFocused()) { pointerFocus = true; canvas.focus({ preventScroll: true }); pointerFocus = false; }
    e.preventDefault();
    redraw();
  }

  function onPointerMove(e) {
    const [px, py] = localXY(e);
    if (st.pointers.has(e.pointerId)) st.pointers.set(e.pointerId, { x: px, y: py });
    if (!st.drag) {
      const hit = hitTest(px, py, e.pointerType);
      const changed = (hit?.group !== st.hover?.group) || (hit?.index !== st.hover?.index);
      st.hover = hit;
      canvas.style.cursor = hit && movable(hit.group) ? 'grab' : st.picked ? 'crosshair' : o.pan ? 'move' : 'default';
      if (changed) redraw();
      return;
    }
    const far = st.drag.start && Math.hypot(px - st.drag.start[0], py - st.drag.start[1]) > st.drag.slop;
    if (st.drag.start && !st.drag.moved && !far) return; // still a click
    if (st.drag.start) st.drag.moved = true;
    if (st.drag.kind === 'handle') {
      const [wx, wy] = toWorld(px, py);
      st.picked = false;
      applyMove(st.drag.group, st.drag.index, wx + st.drag.off[0], wy + st.drag.off[1], 'drag');
      announce(nameOf(st.drag));
    } else if (st.drag.kind === 'pan') {
      const v = st.drag.view;
      const dx = o.zoomX ? (px - st.drag.start[0]) / transform().kx : 0, dy = o.zoomY ? (py - st.drag.start[1]) / transform().ky : 0;
      setView({ xmin: v.xmin - dx, xmax: v.xmax - dx, ymin: v.ymin + dy, ymax: v.ymax + dy });
    } else if (st.drag.kind === 'pinch' && st.pointers.size >= 2) {
      const [a, b] = [...st.pointers.values()];
      const dist = Math.hypot(a.x - b.x, a.y - b.y);
      if (dist < 4) return;
      const f = st.drag.dist / dist;
      const v = st.drag.view;
      const kx = size()[0] / (v.xmax - v.xmin), ky = size()[1] / (v.ymax - v.ymin);
      const wx = v.xmin + st.drag.mid[0] / kx, wy = v.ymax - st.drag.mid[1] / ky;
      const mid = [(a.x + b.x) / 2, (a.y + b.y) / 2];
      const fx = o.zoomX ? f : 1, fy = o.zoomY ? f : 1;
      const nkx = kx / fx, nky = ky / fy;
      const xmin = wx - mid[0] / nkx, ymax = wy + mid[1] / nky;
      setView({ xmin, xmax: xmin + size()[0] / nkx, ymin: ymax - size()[1] / nky, ymax });
    }
  }

  function onPointerUp(e) {
    st.pointers.delete(e.pointerId);
    try { canvas.releasePointerCapture(e.pointerId); } catch { /* ignore */ }
    const cancelled = e.type === 'pointercancel';
    if (!st.drag) {
      // a touch tap off the handles (a scroll of the page cancels the pointer: no tap)
      const tp = tap;
      tap = null;
      if (tp && !cancelled && tp.id === e.pointerId && st.pointers.size === 0) {
        const [px, py] = localXY(e);
        if (Math.hypot(px - tp.x, py - tp.y) <= CLICK_SLOP.touch) clickAt(px, py, e);
      }
      return;
    }
    const d = st.drag;
    if (d.kind === 'pinch') { if (st.pointers.size === 0) { st.drag = null; if (o.onView) o.onView(getView()); } return; }
    if (st.pointers.size > 0) return;
    st.drag = null;
    canvas.classList.remove('dragging', 'panning');
    if (d.kind === 'handle') {
      if (d.moved) { if (d.group.end) d.group.end(d.index); announce(nameOf(d), true); }
      else if (!cancelled && !skipUp) pickClick(d);
    }
    if (d.kind === 'pan' && o.onView && d.moved) o.onView(getView());
    if ((d.kind === 'pan' || d.kind === 'click') && !d.moved && !cancelled) {
      const [px, py] = localXY(e);
      clickAt(px, py, e);
    }
    redraw();
  }

  /** A click or tap on a handle: picks it for a click-then-click move, or (on the picked one) cancels. */
  function pickClick(d) {
    eatClick = true;
    if (d.again) { cancelPick(); return; }
    st.selected = { group: d.group, index: d.index };
    st.picked = true;
    st.by = 'pointer';
    canvas.style.cursor = 'crosshair';
    announce(t('{name} selected. Click or tap where it should go; Escape cancels. Its x and y fields are under the plot.', { name: nameOf(d) }), true);
    flashStatus(t('Click or tap where the point should go (Esc cancels)'));
  }

  /** Drops the picked point (Escape, or a click on it again). */
  function cancelPick() {
    const had = st.selected;
    st.picked = false;
    st.selected = null;
    if (pending) { clearTimeout(pending.timer); pending = null; }
    if (had) announce(t('{name}: selection cancelled.', { name: nameOf(had) }), true);
    redraw();
  }

  /** A click or tap on the plot off the handles: with a picked point, moves it there after DOUBLE_MS. */
  function clickAt(px, py, e) {
    if (skipUp || e.altKey || !st.picked || !st.selected) return;
    eatClick = true;
    const sel = st.selected;
    const at = toWorld(px, py);
    pending = {
      at,
      timer: setTimeout(() => {
        pending = null;
        if (st.selected !== sel || !st.picked) return;
        st.picked = false;
        canvas.style.cursor = '';
        applyMove(sel.group, sel.index, at[0], at[1], 'key');
        if (sel.group.end) sel.group.end(sel.index);
        announce(t('{name}: moved.', { name: nameOf(sel) }), true);
        redraw();
      }, DOUBLE_MS),
    };
  }

  // the demo's own click listeners (added after the plot's) do not see a click that picked or moved a point
  function onClick(e) { if (eatClick) { eatClick = false; e.stopImmediatePropagation(); } }
  // a double-click never moves a point: a destination click still waiting is dropped
  // (and a point picked before it is dropped: point-edit.js may insert a point, which renumbers the handles)
  function onDblClick() {
    if (pending) { clearTimeout(pending.timer); pending = null; }
    if (st.picked) { st.picked = false; canvas.style.cursor = ''; redraw(); }
  }

  function onPointerLeave() { if (st.hover && !st.drag) { st.hover = null; redraw(); } }

  function onWheel(e) {
    if (!o.zoom) return;
    // Zoom only when the plot has focus or with Ctrl/⌘ (trackpad pinch): plain wheel keeps scrolling the page.
    if (!(e.ctrlKey || e.metaKey || isFocused())) {
      flashStatus(t('Click the plot (or hold Ctrl) to zoom with the wheel'));
      return;
    }
    e.preventDefault();
    const [px, py] = localXY(e);
    const dy = e.deltaMode === 1 ? e.deltaY * 16 : e.deltaMode === 2 ? e.deltaY * size()[1] : e.deltaY;
    zoomBy(Math.exp(Math.max(-2, Math.min(2, dy * 0.0015))), px, py);
  }

  let statusTimer = 0;
  function flashStatus(msg) {
    status.textContent = msg;
    status.classList.add('show');
    clearTimeout(statusTimer);
    statusTimer = setTimeout(() => status.classList.remove('show'), 1500);
  }

  function select(sel) {
    st.selected = sel;
    st.picked = false;
    st.by = 'key';
    redraw();
    if (sel) announce(t('{name}. Arrow keys move it, Shift for larger steps.', { name: nameOf(sel, { position: true }) }), true);
  }

  // One Tab stop per plot (WCAG 2.2 SC 2.4.3, 2.1.1): Tab and Shift+Tab are the browser's — they leave the canvas
  // (Tab first reaches the selected point's x / y fields, right after it). Inside, the keys of the 3D views choose
  // a point: PageDown / ] / N the next, PageUp / [ / Shift+N the previous (both wrap), Home / End the first / last.
  // (Not P , . — the audio trace's keys.)
  const STEP_KEYS = { PageDown: 1, ']': 1, n: 1, PageUp: -1, '[': -1 };
  function onKeyDown(e) {
    if (e.altKey || e.ctrlKey || e.metaKey) return;
    const list = flatHandles();
    const idx = st.selected ? list.findIndex((s) => s.group === st.selected.group && s.index === st.selected.index) : -1;
    const k = e.key;
    if (k === 'Tab') return; // one tab stop: never cycles the points
    if (k === 'Enter' && st.selected) { focusFields(); e.preventDefault(); return; }
    // while presenting, Page Down / Page Up are the clicker's: they step the construction (present.js), not the points
    if ((k === 'PageDown' || k === 'PageUp') && canvas.closest('.presenting')) return;
    const lower = k.length === 1 ? k.toLowerCase() : k;
    const step = lower === 'n' ? (e.shiftKey ? -1 : 1) : STEP_KEYS[k] || 0;
    if (step || k === 'Home' || k === 'End') {
      if (!list.length) return;
      let next;
      if (k === 'Home') next = 0;
      else if (k === 'End') next = list.length - 1;
      else next = idx < 0 ? (step < 0 ? list.length - 1 : 0) : (idx + step + list.length) % list.length;
      select(list[next]);
      e.preventDefault();
      return;
    }
    if (k.startsWith('Arrow')) {
      if (!st.selected) { if (list.length) select(list[0]); e.preventDefault(); return; }
      const gr = st.selected.group;
      if (!movable(gr)) { e.preventDefault(); return; }
      const p = gr.points()[st.selected.index];
      if (!p) return;
      const base = gr.step || (transform().xmax - transform().xmin) / 100;
      const stepX = base * (e.shiftKey ? 10 : 1), stepY = (gr.step || (transform().ymax - transform().ymin) / 100) * (e.shiftKey ? 10 : 1);
      let [x, y] = p;
      if (k === 'ArrowLeft') x -= stepX; else if (k === 'ArrowRight') x += stepX;
      else if (k === 'ArrowUp') y += stepY; else if (k === 'ArrowDown') y -= stepY;
      applyMove(gr, st.selected.index, x, y, 'key');
      if (gr.end) gr.end(st.selected.index);
      announce(nameOf(st.selected));
      e.preventDefault();
      return;
    }
    if (k === 'Escape' && st.selected) { remembered = null; cancelPick(); e.preventDefault(); return; }
    if (o.zoom && (k === '+' || k === '=')) { zoomBy(1 / 1.25); e.preventDefault(); return; }
    if (o.zoom && (k === '-' || k === '_')) { zoomBy(1.25); e.preventDefault(); return; }
    if (o.zoom && k === '0') { fitContent(); e.preventDefault(); }
  }

  function onBlur() { redraw(); }

  // Shift+Tab into the canvas should select the last handle: track the direction of the last Tab press.
  let lastTabBack = false;
  const trackTab = (e) => { if (e.key === 'Tab') lastTabBack = e.shiftKey; };
  let pointerFocus = false;
  // a point chosen with the keyboard is let go when the focus leaves the plot (its fields row hides) and chosen
  // again when the keyboard comes back
  let remembered = null;
  const stillThere = (sel) => sel && flatHandles().some((s) => s.group === sel.group && s.index === sel.index);
  function onFocusIn() {
    if (pointerFocus) { redraw(); return; } // focused by a click/tap: no automatic selection
    const list = flatHandles();
    if (!list.length) { announce(o.ariaLabel, true); redraw(); return; }
    const back = st.selected || (stillThere(remembered) ? remembered : null);
    remembered = null;
    if (back) { st.selected = back; select(back); return; }
    select(lastTabBack ? list[list.length - 1] : list[0]);
  }
  /** Focus gone from the canvas and from its fields row: a keyboard selection is remembered and let go. */
  function onFocusOut(e) {
    const to = e.relatedTarget;
    if (to && (to === canvas || fieldsEl()?.contains(to))) return;
    if (st.selected && st.by === 'key' && !st.picked) { remembered = st.selected; st.selected = null; redraw(); }
  }

  // Touch: the canvas lets the page scroll vertically (touch-action: pan-y) unless the gesture starts on a handle
  // or uses two fingers; then the plot takes it (preventDefault on the touch events stops the page's scrolling).
  // Pointer events come first, so `st.drag` (the shared state) already says what the touch does.
  canvas.style.touchAction = 'pan-y';
  function onTouch(e) {
    if (!e.cancelable) return;
    if ((st.drag && (st.drag.kind === 'handle' || st.drag.kind === 'pinch')) || (o.zoom && e.touches.length >= 2)) e.preventDefault();
  }
  canvas.addEventListener('touchstart', onTouch, { passive: false });
  canvas.addEventListener('touchmove', onTouch, { passive: false });
  canvas.addEventListener('pointerdown', onPointerDown);
  canvas.addEventListener('pointermove', onPointerMove);
  canvas.addEventListener('pointerup', onPointerUp);
  canvas.addEventListener('pointercancel', onPointerUp);
  canvas.addEventListener('pointerleave', onPointerLeave);
  canvas.addEventListener('wheel', onWheel, { passive: false });
  canvas.addEventListener('click', onClick);
  canvas.addEventListener('dblclick', onDblClick);
  canvas.addEventListener('keydown', onKeyDown);
  canvas.addEventListener('focus', onFocusIn);
  canvas.addEventListener('blur', onBlur);
  canvas.parentElement?.addEventListener('focusout', onFocusOut); // the canvas, its fields row, its tools
  document.addEventListener('keydown', trackTab, true);

  /** Stops the timers and the document listener (the canvas listeners go with the canvas). */
  function dispose() {
    clearTimeout(announceTimer); clearTimeout(statusTimer);
    if (pending) clearTimeout(pending.timer);
    document.removeEventListener('keydown', trackTab, true);
  }

  /** Escape in a point field: deselects and gives the canvas the focus back (without selecting a point again). */
  function escapeFromFields() {
    cancelPick();
    pointerFocus = true; canvas.focus({ preventScroll: true }); pointerFocus = false;
  }

  return { select, announce, dispose, escapeFromFields };
}
