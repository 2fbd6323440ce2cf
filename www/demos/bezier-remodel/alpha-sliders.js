// The α sliders of the curve tab: one per parameter αₖ⁽ᴵ⁾ of eq. (6), grouped by segment I; the ones eq. (9)
// fixes are greyed with their constraint (from the API's `free` and `constraints`).
import { h, fmt, clear } from '../../lib/dom.js';
import { slider } from '../../lib/controls.js';
import { sub, alphaName, prettyConstraint } from './notation.js';
import { alphaMax } from './curve-state.js';

/**
 * alphaSliders({ state, locked, onInput(I, k, v), onChange() }) → { el, build(most), refresh(res) }: build() makes
 * the sliders again when the degree or the number of segments changed (`most`: at most that many segments' rows
 * per call, the rest on the next calls; true when all are there); refresh(res) shows the α used and greys the fixed
 * ones (of the rows there are).
 */
export function alphaSliders({ state, locked, onInput, onChange }) {
  const el = h('div', { class: 'alpha-sliders' });
  let sliders = [];   // [I][k] → slider
  let shape = '';

  /** @param {number} [most] */
  function build(most = Infinity) {
    const m = state.degree, segs = state.breaks.length - 1;
    if (`${m}x${segs}` !== shape) {
      shape = `${m}x${segs}`;
      clear(el);
      sliders = [];
    }
    // an import of 12 segments builds its 24 sliders over three frames (issue 26)
    for (let added = 0; sliders.length < segs && added < most; added++) {
      const I = sliders.length;
      const row = [];
      const box = h('div', { class: 'alpha-segment', style: { borderTop: '1px solid #ddd', paddingTop: '0.25rem', marginTop: '0.25rem' } },
        h('div', { style: { fontWeight: '600' } }, `Segment I = ${I}  [u${sub(I)}, u${sub(I + 1)}]`));
      for (let k = 1; k <= m; k++) {
        const s = slider({
          label: alphaName(k, I), min: 0.001, max: 0.999, step: 0.001, value: state.alphas[I][k - 1], number: true,
          format: (v) => fmt(v, 4),
          onInput(v) { onInput(I, k, v); },
          onChange,
        });
        s.el.dataset.alpha = `${I},${k}`;
        const hint = h('div', { class: 'ctl-hint alpha-constraint' });
        s.el.appendChild(hint);
        s.hint = hint;
        row.push(s);
        box.appendChild(s.el);
      }
      sliders.push(row);
      el.appendChild(box);
    }
    return sliders.length === segs;
  }

  function refresh(res) {
    if (!res) return;
    const m = state.degree;
    const free = res.free, cons = res.constraints;
    for (let I = 0; I < sliders.length; I++) {
      for (let k = 1; k <= m; k++) {
        const s = sliders[I][k - 1];
        const isFree = free[I][k - 1];
        const max = k === m ? alphaMax(state) : 0.999, value = state.alphas[I][k - 1];
        const hint = isFree ? '' : `fixed: ${prettyConstraint(cons[I][k - 1])}`;
        // a drag of a control point refreshes every slider in every frame: touch the DOM only where it changes
        const key = `${max}|${value}|${isFree}|${hint}`;
        if (s.shown === key) continue;
        s.shown = key;
        s.setRange({ max });
        s.set(value);
        s.setDisabled(locked || !isFree);
        s.el.querySelector('.ctl-track').style.opacity = isFree ? '1' : '0.45';
        s.el.querySelector('label').style.color = isFree ? '' : '#595959';
        s.el.dataset.free = String(isFree);
        s.hint.textContent = hint;
      }
    }
  }

  return { el, build, refresh };
}
