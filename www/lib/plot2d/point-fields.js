// The x / y number fields of a 2D plot's selected handle (WCAG 2.2 SC 2.5.7: a way to move a point without
// dragging). A row under the canvas, shown while a handle is selected (keyboard, click or tap), with the point's
// name and two fields; Enter or a change applies the typed value through the same path as a drag (the group's
// constrain → move → end, so the demo saves and records an undo step). A value the constraint changes is shown
// as applied and announced; text that is not a number is refused with a note next to the field.

import { h, fmt, pair, uniqueId } from '../dom.js';
import { parseNumber } from '../number-input.js';
import { t } from '../i18n.js';

/** The name shown for handle `i` of group `gr`: its drawn label (P3), else its spoken one, else "point 4". */
export function shortName(gr, i) {
  const drawn = gr.label ? gr.label(i) : '';
  if (drawn) return drawn;
  return gr.labelOf ? t(gr.labelOf(i)) : `${t(gr.name)} ${i + 1}`;
}

/**
 * Builds the row (not yet in the page: the caller places it under the canvas). `st` is the plot's interaction
 * state, `handles` its handle functions (createHandles), `announce(msg)` speaks in the plot's live region,
 * `onEscape()` is called for Escape in a field (the plot deselects and takes the focus back).
 * Returns { el, sync() (call after every paint), focus() }.
 */
export function createPointFields({ st, handles, announce, onEscape }) {
  const { applyMove, movable } = handles;
  const id = uniqueId('pf');
  const nameEl = h('span', { class: 'plot-fields-name' });
  const make = (axis) => {
    const input = h('input', {
      type: 'text', inputmode: 'decimal', autocomplete: 'off', spellcheck: 'false', class: 'plot-field',
      id: `${id}-${axis}`, 'aria-describedby': `${id}-note`,
    });
    const lab = h('label', { class: 'plot-field-label', for: `${id}-${axis}` }, axis);
    return { axis, input, lab };
  };
  const fx = make('x'), fy = make('y');
  const note = h('span', { class: 'plot-fields-note', id: `${id}-note`, role: 'status' });
  const el = h('div', { class: 'plot-fields', hidden: true },
    nameEl, h('span', { class: 'plot-field-pair' }, fx.lab, fx.input), h('span', { class: 'plot-field-pair' }, fy.lab, fy.input), note);

  let shownFor = null;   // the { group, index } the row shows
  let noteFor = null;    // the selection the note was written for (a new selection clears it)
  const fieldOf = (axis) => (axis === 'x' ? fx : fy);

  /** Writes the selected point's coordinates into the fields (not into a field being typed in). */
  function sync() {
    const sel = st.selected;
    const p = sel ? (sel.group.points() || [])[sel.index] : null;
    if (!sel || !p || sel.group.hidden) {
      if (!el.hidden) el.hidden = true;
      shownFor = null;
      return;
    }
    const same = shownFor && shownFor.group === sel.group && shownFor.index === sel.index;
    if (!same) {
      shownFor = { group: sel.group, index: sel.index };
      const nm = shortName(sel.group, sel.index);
      nameEl.textContent = `${nm}:`;
      for (const f of [fx, fy]) {
        f.input.setAttribute('aria-label', t('{axis} of {name}', { axis: f.axis, name: nm }));
        f.input.classList.remove('invalid');
        f.input.removeAttribute('aria-invalid');
        // an axis-constrained handle keeps its other coordinate: that field is shown, read-only
        const fixed = !movable(sel.group) || (sel.group.axis && sel.group.axis !== f.axis);
        f.input.readOnly = !!fixed;
        f.input.classList.toggle('fixed', !!fixed);
      }
      if (noteFor !== sel) { note.textContent = ''; noteFor = null; }
    }
    const active = el.getRootNode().activeElement;
    for (const [f, v] of [[fx, p[0]], [fy, p[1]]]) {
      if (active === f.input && !f.input.readOnly) continue; // the person is typing here
      if (f.input.classList.contains('invalid')) continue;    // their refused text stays until they change it
      const s = fmt(v, 4);
      if (f.input.value !== s) f.input.value = s;
    }
    if (el.hidden) el.hidden = false;
  }

  /** Applies the text of field `f` to the selected point. */
  function apply(f) {
    const sel = st.selected;
    if (!sel || f.input.readOnly) return;
    const gr = sel.group, i = sel.index;
    const p = (gr.points() || [])[i];
    if (!p) return;
    const nm = shortName(gr, i);
    const r = parseNumber(f.input.value);
    if (!r.ok) {
      f.input.classList.add('invalid');
      f.input.setAttribute('aria-invalid', 'true');
      note.textContent = t('{axis} of {name}: “{text}” is not a number ({why}); the point did not move.', { axis: f.axis, name: nm, text: f.input.value, why: r.error });
      noteFor = sel;
      announce(note.textContent);
      return;
    }
    f.input.classList.remove('invalid');
    f.input.removeAttribute('aria-invalid');
    const want = f.axis === 'x' ? [r.value, p[1]] : [p[0], r.value];
    applyMove(gr, i, want[0], want[1], 'key');
    if (gr.end) gr.end(i);
    const q = (gr.points() || [])[i] || p;
    const got = f.axis === 'x' ? q[0] : q[1];
    const tol = 1e-9 * Math.max(1, Math.abs(r.value));
    if (Math.abs(got - r.value) > tol) {
      const why = t(gr.constraintNote ? (typeof gr.constraintNote === 'function' ? gr.constraintNote(i) : gr.constraintNote) : 'the construction does not let this point go there');
      note.textContent = t('{axis} of {name} kept at {got} (asked {asked}): {why}.', { axis: f.axis, name: nm, got: fmt(got, 4), asked: fmt(r.value, 4), why });
    } else {
      note.textContent = t('{name} moved to {where}.', { name: nm, where: pair(q[0], q[1], 4) });
    }
    noteFor = sel;
    f.input.value = fmt(got, 4);
    announce(note.textContent);
  }

  for (const f of [fx, fy]) {
    f.input.addEventListener('keydown', (e) => {
      if (e.key === 'Enter') { e.preventDefault(); apply(f); }
      else if (e.key === 'Escape') { e.preventDefault(); onEscape(); }
    });
    f.input.addEventListener('change', () => apply(f));
    f.input.addEventListener('input', () => { if (f.input.classList.contains('invalid')) { f.input.classList.remove('invalid'); f.input.removeAttribute('aria-invalid'); } });
  }

  return { el, sync, focus: () => { if (!el.hidden) (fx.input.readOnly && !fy.input.readOnly ? fy : fx).input.focus(); }, fieldOf };
}
