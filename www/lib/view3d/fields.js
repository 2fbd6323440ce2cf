// View3D's keyboard selection of draggable points and the number fields of the selected point (issue 25):
// N / Shift+N (or ] / [) choose a point, the live region names it by its paper name, and x / y / z fields under
// the view move it without dragging, through the same path as a drag (onDrag 'start', 'move', 'end'), so a demo saves it.

import { parseNumber } from '../number-input.js';
import { localDigits } from '../i18n.js';

/** @typedef {import('./index.js').Viewer} Viewer */

/** A coordinate for a field or an announcement: 6 significant digits and 6 decimals at most, no float32 noise
 * ("0.163", not "0.163000002"; "0.001345", not "0.00134476"), no "−0". */
export function fmtCoord(v) {
  const r = Number(Number(Number(v).toFixed(6)).toPrecision(6));
  return localDigits(String(r === 0 ? 0 : r).replace('-', '−'));
}

/** Selection and coordinate-field methods of View3D. Installed on View3D.prototype by ./index.js. */
export class FieldsPart {
  /** The panel under the canvas with the x, y, z fields of the selected point (hidden while none is selected). @this {Viewer} */
  _buildFields() {
    const panel = this.fieldsPanel = document.createElement('div');
    panel.className = 'sl-view3d-fields';
    panel.setAttribute('role', 'group');
    panel.hidden = true;
    const name = this._fieldsName = document.createElement('span');
    name.className = 'sl-view3d-fields-name';
    panel.appendChild(name);
    this._fields = ['x', 'y', 'z'].map((axis, k) => {
      const label = document.createElement('label');
      label.className = 'sl-view3d-field';
      const input = document.createElement('input');
      input.type = 'text';
      input.inputMode = 'decimal';
      input.autocomplete = 'off';
      input.spellcheck = false;
      input.size = 8;
      const msg = document.createElement('span');
      msg.className = 'sl-view3d-field-msg';
      msg.id = `sl-view3d-${this.id}-msg-${axis}`;
      msg.setAttribute('role', 'status');
      input.setAttribute('aria-describedby', msg.id);
      label.append(`${axis} `, input);
      panel.append(label, msg);
      input.addEventListener('change', () => this._applyField(k));
      input.addEventListener('keydown', (e) => {
        if (e.key === 'Enter') { e.preventDefault(); this._applyField(k); }
        // Escape: back to the point's coordinate (the typed text was not applied) and to the view
        else if (e.key === 'Escape') { e.preventDefault(); this._fieldError(k, ''); this._syncFields(true); this.canvas.focus(); }
      });
      return { axis, input, msg, shown: '' };
    });
    return panel;
  }

  /** The paper name of point `index` of set `id` (the set's `names`, else its label, else "point n"). @this {Viewer} */
  pointName(id, index) {
    const o = this.objects.get(id);
    let name = '';
    try { name = typeof o?.names === 'function' ? String(o.names(index) ?? '') : o?.names ? String(o.names[index] ?? '') : ''; } catch { name = ''; }
    return name || o?.labels?.[index] || `point ${index + 1}`;
  }

  /** The selected point's position [x, y, z], or null. @this {Viewer} */
  _selectedPosition() {
    const sel = this.selected, o = sel && this.objects.get(sel.id);
    if (!o || o.kind !== 'points' || sel.index >= o.positions.length / 3) return null;
    return Array.from(o.positions.subarray(3 * sel.index, 3 * sel.index + 3));
  }

  /** "W₁,₂ (0, 2, 0.163)"; `f` formats a coordinate (the description's words: 3 decimals like the readouts). @this {Viewer} */
  _describe(sel, f = fmtCoord) {
    const o = this.objects.get(sel.id), p = o.positions, i = 3 * sel.index;
    return `${this.pointName(sel.id, sel.index)} (${f(p[i])}, ${f(p[i + 1])}, ${f(p[i + 2])})`;
  }

  /**
   * Selects a draggable point ({ id, index }) or nothing (null): highlights it, shows its fields, tells the pick
   * listeners and says it in the live region (unless `quiet`).
   * @this {Viewer}
   */
  select(sel, { quiet = false } = {}) {
    const o = sel && this.objects.get(sel.id);
    if (sel && !(o && o.kind === 'points' && sel.index >= 0 && sel.index < o.positions.length / 3)) sel = null;
    const had = this.selected;
    this.selected = sel ? { id: sel.id, index: sel.index } : null;
    this._picked = false;   // a pointer pick (input.js _pickClick) sets it again after this
    for (const f of this._fields || []) this._fieldError(f.axis === 'x' ? 0 : f.axis === 'y' ? 1 : 2, '');
    this._syncFields(true);
    this.render();
    if (!sel) { if (had && !quiet) this._announce('Selection cleared'); return; }
    const list = this._draggables();
    const k = list.findIndex((s) => s.id === sel.id && s.index === sel.index);
    if (!quiet) {
      const axis = o.axis ? `; it moves along ${o.axis} only (Page Up/Down or its ${o.axis} field)` : '';
      this._announce(`Selected ${this._describe(this.selected)}${k >= 0 ? `, ${k + 1} of ${list.length}` : ''}. `
        + `Arrow keys move it${axis}; Tab goes to its coordinate fields; Escape deselects.`);
    }
    this._emitPick({ id: sel.id, index: sel.index, position: this._selectedPosition() });
  }

  /** N / Shift+N: the next (step 1) or previous (step −1) draggable point, wrapping around. @this {Viewer} */
  _selectStep(step) {
    const list = this._draggables();
    if (this.locked || !list.length) { this._announce(this.locked ? 'The points are locked' : 'This view has no points to move'); return; }
    let k = this.selected ? list.findIndex((s) => s.id === this.selected.id && s.index === this.selected.index) : -1;
    k = k < 0 ? (step > 0 ? 0 : list.length - 1) : (k + step + list.length) % list.length;
    this.select(list[k]);
  }

  /**
   * Shows the selected point's name and coordinates in the fields (the panel hides without a selection). A field
   * showing an error keeps the user's text; the field being edited keeps it unless `force`.
   * @this {Viewer}
   */
  _syncFields(force = false) {
    const panel = this.fieldsPanel;
    if (!panel) return;
    const p = this._selectedPosition();
    if (!p || this.locked) { panel.hidden = true; return; }
    const sel = this.selected, o = this.objects.get(sel.id), name = this.pointName(sel.id, sel.index);
    panel.hidden = false;
    panel.setAttribute('aria-label', `Coordinates of ${name}`);
    if (this._fieldsName.textContent !== name) this._fieldsName.textContent = name;
    const root = /** @type {Document | ShadowRoot} */ (this.canvas.getRootNode?.() ?? document);
    this._fields.forEach((f, k) => {
      const ro = !!o.axis && o.axis !== f.axis;
      f.input.readOnly = ro;
      f.input.setAttribute('aria-label', `${f.axis} of ${name}${ro ? ` (fixed: the point moves along ${o.axis} only)` : ''}`);
      const editing = (root.activeElement ?? document.activeElement) === f.input && !force;
      if (f.input.getAttribute('aria-invalid') === 'true' || editing) return;
      const text = fmtCoord(p[k]).replace('−', '-');
      if (f.input.value !== text) f.input.value = text;
      f.shown = text;
    });
  }

  /** A message next to field k ('' clears it). @this {Viewer} */
  _fieldError(k, text) {
    const f = this._fields?.[k];
    if (!f) return;
    f.msg.textContent = text;
    if (text) f.input.setAttribute('aria-invalid', 'true'); else f.input.removeAttribute('aria-invalid');
  }

  /** Applies field k to the selected point, as a drag would (start, move, end), or says why it cannot. @this {Viewer} */
  _applyField(k) {
    const f = this._fields[k], sel = this.selected, cur = this._selectedPosition();
    if (!sel || !cur || this.locked || f.input.readOnly) return;
    // the text this view wrote (after Enter, the browser still sends a change event when the field loses focus)
    if (f.input.value === f.shown) { this._fieldError(k, ''); return; }
    const name = this.pointName(sel.id, sel.index);
    // the project's reader of typed numbers (www/lib/number-input.js): 0,25, −1.5, 1e-3 and 1/6 as in every field
    const r = parseNumber(f.input.value), v = r.ok ? r.value : null;
    if (v === null) {
      this._fieldError(k, `${f.axis} of ${name}: “${f.input.value.trim()}” is not a number; the point stays at ${fmtCoord(cur[k])}.`);
      return;
    }
    this._fieldError(k, '');
    // (positions are float32: Enter and the change event that follows it must not apply the same value twice)
    if (Math.fround(v) === cur[k]) return;
    const p = cur.slice();
    p[k] = v;
    this._emitDrag('start', cur, sel.id, sel.index);
    this._movePoint(sel.id, sel.index, p, 'move');
    const now = this._selectedPosition();
    if (now) this._emitDrag('end', now, sel.id, sel.index);
    this._syncFields(true);
    if (this.selected) this._announce(`Moved ${this._describe(this.selected)}`);
  }
}
