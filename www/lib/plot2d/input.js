// Pointer, touch, wheel and keyboard input of a 2D plot: dragging handles, panning, pinch and wheel zoom,
// keyboard selection and moves, focus handling and the screen-reader announcements.

/**
 * Attaches the plot's input handlers to `canvas`. `st` is the shared interaction state, `handles` the handle
 * functions (createHandles), `transform()` → the current transform, `size()` → [W, H]; the view functions
 * move the plot. Returns { select(sel), announce(msg, now), dispose() }.
 */
export function attachInput({ st, o, canvas, live, status, handles, transform, size, toWorld, getView, setView, zoomBy, fitContent, redraw, isFocused }) {
  const { hitTest, movable, applyMove, nameOf, flatHandles } = handles;

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
    const hit = hitTest(px, py, e.pointerType);
    if (!(hit && movable(hit.group)) && e.pointerType === 'touch') {
      // one finger that does not start on a handle belongs to the page (it scrolls, touch-action: pan-y);
      // a second finger turns the gesture into a pinch (above)
      return;
    }
    if (hit && movable(hit.group)) {
      const p = hit.group.points()[hit.index];
      st.drag = { kind: 'handle', group: hit.group, index: hit.index, off: [p[0] - toWorld(px, py)[0], p[1] - toWorld(px, py)[1]], moved: false };
      st.selected = { group: hit.group, index: hit.index };
      if (hit.group.start) hit.group.start(hit.index);
      canvas.classList.add('dragging');
    } else if (o.pan) {
      st.drag = { kind: 'pan', start: [px, py], view: getView() };
      canvas.classList.add('panning');
    } else {
      return;
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
      canvas.style.cursor = hit && movable(hit.group) ? 'grab' : o.pan ? 'move' : 'default';
      if (changed) redraw();
      return;
    }
    if (st.drag.kind === 'handle') {
      const [wx, wy] = toWorld(px, py);
      st.drag.moved = true;
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
    if (!st.drag) return;
    const d = st.drag;
    if (d.kind === 'pinch') { if (st.pointers.size === 0) { st.drag = null; if (o.onView) o.onView(getView()); } return; }
    if (st.pointers.size > 0) return;
    st.drag = null;
    canvas.classList.remove('dragging', 'panning');
    if (d.kind === 'handle') { if (d.moved && d.group.end) d.group.end(d.index); announce(nameOf(d), true); }
    if (d.kind === 'pan' && o.onView) o.onView(getView());
    redraw();
  }

  function onPointerLeave() { if (st.hover && !st.drag) { st.hover = null; redraw(); } }

  function onWheel(e) {
    if (!o.zoom) return;
    // Zoom only when the plot has focus or with Ctrl/⌘ (trackpad pinch): plain wheel keeps scrolling the page.
    if (!(e.ctrlKey || e.metaKey || isFocused())) {
      flashStatus('Click the plot (or hold Ctrl) to zoom with the wheel');
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
    redraw();
    if (sel) announce(`${nameOf(sel)}. Arrow keys move it, Shift for larger steps.`, true);
  }

  function onKeyDown(e) {
    if (e.altKey || e.ctrlKey || e.metaKey) return;
    const list = flatHandles();
    const idx = st.selected ? list.findIndex((s) => s.group === st.selected.group && s.index === st.selected.index) : -1;
    const k = e.key;
    if (k === 'Tab' || k === '[' || k === ']') {
      if (!list.length) return;
      const back = k === '[' || (k === 'Tab' && e.shiftKey);
      const next = idx < 0 ? (back ? list.length - 1 : 0) : idx + (back ? -1 : 1);
      if (next < 0 || next >= list.length) {
        if (k === 'Tab') { st.selected = null; redraw(); return; } // let focus leave the plot: no keyboard trap
        select(list[(next + list.length) % list.length]);
      } else select(list[next]);
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
    if (k === 'Escape' && st.selected) { st.selected = null; redraw(); e.preventDefault(); return; }
    if (o.zoom && (k === '+' || k === '=')) { zoomBy(1 / 1.25); e.preventDefault(); return; }
    if (o.zoom && (k === '-' || k === '_')) { zoomBy(1.25); e.preventDefault(); return; }
    if (o.zoom && k === '0') { fitContent(); e.preventDefault(); }
  }

  function onFocus() {
    if (!st.selected) {
      const list = flatHandles();
      if (list.length) select(list[0]); else announce(o.ariaLabel, true);
    }
    redraw();
  }
  function onBlur() { redraw(); }

  // Shift+Tab into the canvas should select the last handle: track the direction of the last Tab press.
  let lastTabBack = false;
  const trackTab = (e) => { if (e.key === 'Tab') lastTabBack = e.shiftKey; };
  let pointerFocus = false;
  function onFocusIn() {
    if (pointerFocus) { redraw(); return; } // focused by a click/tap: no automatic selection
    if (!st.selected) {
      const list = flatHandles();
      if (list.length) { select(lastTabBack ? list[list.length - 1] : list[0]); return; }
    }
    onFocus();
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
  canvas.addEventListener('keydown', onKeyDown);
  canvas.addEventListener('focus', onFocusIn);
  canvas.addEventListener('blur', onBlur);
  document.addEventListener('keydown', trackTab, true);

  /** Stops the timers and the document listener (the canvas listeners go with the canvas). */
  function dispose() {
    clearTimeout(announceTimer); clearTimeout(statusTimer);
    document.removeEventListener('keydown', trackTab, true);
  }

  return { select, announce, dispose };
}
