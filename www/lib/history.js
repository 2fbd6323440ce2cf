// Undo / redo of a demo's state, for the shell (app.js) and the <spline-lab> element.
//
//   const hist = createHistory({ getState: () => current.state, onChange: () => updateButtons() });
//   hist.reset(state)            after mounting a new demo / view: no steps
//   hist.attach(root)            listens to the user's input in the demo (pointer, keys, inputs, wheel)
//   hist.touch()                 from every ctx.save(): the first save of a burst records the state before it
//   const prev = hist.undo()     → the state to re-mount (a copy), or null;  hist.redo() likewise
//   hist.rebase(state)           after re-mounting with a state: the committed state, without a step
//   hist.record()                before a whole-state replacement by the shell (Reset): one step
//
// Coalescing: a burst of saves is one step. A burst ends when no save came for `idleMs` while no pointer is
// held down (so a drag, however slow, is one step) or when undo/redo is asked for. Saves that no user input
// preceded (a demo saving its fitted view after mounting) record nothing. A burst that ends where it began
// (a slider moved and moved back) records nothing either, and neither does one that only moved the stepper
// (NAVIGATION_KEYS).

const same = (a, b) => JSON.stringify(a) === JSON.stringify(b);

/** State keys that only say where the reader is in a walk-through (the stepper's step), not what they made: a
 * burst that changes nothing else records no undo step (stepping through a construction four times and then
 * dragging a point is one undo of the drag, not five). */
export const NAVIGATION_KEYS = ['step'];
const withoutNavigation = (s) => {
  if (!s || typeof s !== 'object') return s;
  const o = { ...s };
  for (const k of NAVIGATION_KEYS) delete o[k];
  return o;
};
const sameWork = (a, b) => same(withoutNavigation(a), withoutNavigation(b));
const copy = (s) => structuredClone(s);

/** @param {{ getState?: () => any, onChange?: () => void, idleMs?: number, limit?: number }} options */
export function createHistory({ getState, onChange = () => {}, idleMs = 500, limit = 200 } = {}) {
  let undo = [], redo = [];
  let committed = null;   // the state after the last finished step (what an undo step returns to)
  let open = false;       // a burst is in progress (its "before" is on top of `undo`)
  let armed = false;      // the user has touched the demo since the last (re)mount
  let held = 0;           // pointers down inside the demo
  let timer = 0;

  const changed = () => { try { onChange(); } catch (e) { console.error(e); } };

  function close() {
    clearTimeout(timer);
    timer = 0;
    if (!open) return;
    open = false;
    const cur = copy(getState());
    if (undo.length && sameWork(undo[undo.length - 1], cur)) undo.pop();
    committed = cur;
    changed();
  }
  const schedule = () => { clearTimeout(timer); timer = setTimeout(() => { if (!held) close(); else schedule(); }, idleMs); };

  const api = {
    reset(state) {
      clearTimeout(timer); timer = 0;
      undo = []; redo = []; open = false; armed = false; held = 0;
      committed = copy(state);
      changed();
    },
    rebase(state) {
      clearTimeout(timer); timer = 0;
      open = false; armed = false; held = 0;
      committed = copy(state);
      changed();
    },
    /** Called on every save of the demo. */
    touch() {
      if (!armed || committed === null) return;
      if (!open) {
        undo.push(committed);
        if (undo.length > limit) undo.shift();
        redo = [];
        open = true;
        changed();
      }
      schedule();
    },
    /** Records the current state as one step before the shell replaces it wholesale (e.g. Reset). */
    record() {
      close();
      if (committed === null) return;
      undo.push(copy(getState()));
      if (undo.length > limit) undo.shift();
      redo = [];
      changed();
    },
    undo() {
      close();
      if (!undo.length) return null;
      redo.push(copy(getState()));
      committed = undo.pop();
      changed();
      return copy(committed);
    },
    redo() {
      close();
      if (!redo.length) return null;
      undo.push(copy(getState()));
      committed = redo.pop();
      changed();
      return copy(committed);
    },
    get canUndo() { return undo.length > 0; },
    get canRedo() { return redo.length > 0; },
    get size() { return { undo: undo.length, redo: redo.length, open }; },
    /** Marks user input inside `root` (capture phase); returns a function that removes the listeners. */
    attach(root) {
      const arm = () => { armed = true; };
      const down = () => { armed = true; held++; };
      const up = () => { if (held) { held = Math.max(0, held - 1); if (open) schedule(); } };
      const evs = ['keydown', 'input', 'change', 'wheel', 'click'];
      evs.forEach((e) => root.addEventListener(e, arm, { capture: true, passive: true }));
      root.addEventListener('pointerdown', down, { capture: true, passive: true });
      window.addEventListener('pointerup', up, true);
      window.addEventListener('pointercancel', up, true);
      return () => {
        evs.forEach((e) => root.removeEventListener(e, arm, { capture: true }));
        root.removeEventListener('pointerdown', down, { capture: true });
        window.removeEventListener('pointerup', up, true);
        window.removeEventListener('pointercancel', up, true);
      };
    },
  };
  return api;
}

/** Is this key event typing into a text field (where Ctrl+Z, P and Esc belong to the field)? */
export function isTyping(e) {
  const t = e.composedPath ? e.composedPath()[0] : e.target;
  if (!t || !t.tagName) return false;
  if (t.isContentEditable) return true;
  if (t.tagName === 'TEXTAREA' || t.tagName === 'SELECT') return true;
  if (t.tagName !== 'INPUT') return false;
  return !['range', 'checkbox', 'radio', 'button', 'submit', 'reset', 'color', 'file', 'image'].includes((t.type || 'text').toLowerCase());
}

/** 'undo' | 'redo' | null for a keydown event (Ctrl/Cmd+Z, Ctrl/Cmd+Shift+Z, Ctrl+Y), not while typing. */
export function undoKey(e) {
  if (!(e.ctrlKey || e.metaKey) || e.altKey || isTyping(e)) return null;
  const k = e.key.length === 1 ? e.key.toLowerCase() : e.key;
  if (k === 'z') return e.shiftKey ? 'redo' : 'undo';
  if (k === 'y' && !e.shiftKey) return 'redo';
  return null;
}
