// Algorithm stepper: Back / Step / Play controls that walk through the steps of a construction, with the
// formula of the current step typeset (MathML) and filled in with the current numbers.
//
//   const st = stepper({
//     title: 'de Boor at u',
//     steps: () => [                                // recomputed on every refresh (numbers follow the view)
//       { label: 'Level 1: P¹ᵢ from P⁰', tex: `P^1_i = (1-\\alpha)P_{i-1} + \\alpha P_i, \\; \\alpha = ${fmt(a)}` },
//       …
//     ],
//     get: () => state.step,                        // -1 = off (the plain drawing), 0…n−1 = the step shown
//     set(i) { state.step = i; redraw(); ctx.save(); },   // the step lives in the demo's state, so in the link
//   });
//   controls.append(st.el);   …   st.refresh() after a recompute;   st.destroy() in the demo's destroy()
//
// Accessible names: "Step back", "Step forward", "Play steps" (a toggle), "Leave the steps". The panel is an
// aria-live region saying "Step k of n: label". Play advances one step every `interval` ms and stops at the
// last step; with prefers-reduced-motion it still steps (each step is a discrete change, not an animation).
//
// A step is `{ label, tex, note }`: `tex` one TeX line or an array of them (www/lib/mathml.js subset), `note`
// plain text under the formula. `data-step` / `data-steps` on `st.el` hold the index and the count (tests).
// An empty step list (nothing computed yet) shows no step but leaves the demo's index alone (a step restored
// from a link is kept until the steps exist); a list shorter than the index clamps it (through `set`).
// Additions (steppers-a): `st.setTitle(text)` renames the panel (a demo that switches between algorithms keeps
// one stepper); the live status is rewritten only when its text changes (no screen-reader chatter while a
// point is dragged and the numbers follow).

import { h, clear, append } from './dom.js';
import { math } from './mathml.js';
import { t, tn } from './i18n.js';

/** The smallest size (of the panel's font size) a formula row is shrunk to before it scrolls instead. */
const MIN_FORMULA_SCALE = 0.75;

/**
 * Splits one TeX line into two rows at a top-level (outside braces and brackets) `=`, `+`, `-` or `\quad` as near its middle
 * as possible; the second row starts with the operator, indented. null when there is no such place.
 */
export function splitTex(tex) {
  let depth = 0, best = -1, bestCost = Infinity;
  const mid = tex.length / 2;
  for (let i = 1; i < tex.length - 1; i++) {
    const c = tex[i];
    if (c === '{' || c === '(' || c === '[') depth++;
    else if (c === '}' || c === ')' || c === ']') depth--;
    if (depth !== 0) continue;
    const atOp = ((c === '=' || c === '+' || c === '-') && tex[i - 1] === ' ') || tex.startsWith('\\quad', i);
    if (!atOp || i < tex.length * 0.25) continue;
    const cost = Math.abs(i - mid);
    if (cost < bestCost) { best = i; bestCost = cost; }
  }
  if (best < 0) return null;
  const rest = tex.slice(best).replace(/^\\quad\s*/, '');
  return [tex.slice(0, best).trimEnd(), `\\qquad ${rest}`];
}

/**
 * @param {{ title?: string, steps?: () => any[], get?: () => number, set?: (i: number) => void, interval?: number,
 *   hint?: string }} options
 */
export function stepper({ title: title0 = 'Step by step', steps, get, set, interval = 1400, hint: hint0 } = {}) {
  const title = t(title0), hint = hint0 && t(hint0);
  let timer = 0, destroyed = false;
  const list = () => { try { return steps() || []; } catch { return []; } };
  const index = () => { const i = Number(get()); return Number.isInteger(i) ? i : -1; };

  const back = h('button', { type: 'button', class: 'btn btn-secondary step-back', 'aria-label': t('Step back'), title: t('Previous step') }, `◀ ${t('Back')}`);
  const fwd = h('button', { type: 'button', class: 'btn btn-primary step-forward', 'aria-label': t('Step forward'), title: t('Next step') }, `${t('Step')} ▶`);
  const play = h('button', { type: 'button', class: 'btn btn-secondary step-play', 'aria-label': t('Play steps'), 'aria-pressed': 'false', title: t('Play the steps one after another') }, `▶▶ ${t('Play')}`);
  const leave = h('button', { type: 'button', class: 'btn btn-secondary step-leave', 'aria-label': t('Leave the steps'), title: t('Back to the plain drawing') }, '✕');
  const status = h('p', { class: 'stepper-status', 'aria-live': 'polite' });
  const formula = h('div', { class: 'stepper-formula' });
  const note = h('p', { class: 'stepper-note' });
  const heading = h('h3', { class: 'stepper-title' }, title);
  const el = h('section', { class: 'stepper', 'aria-label': t('{title} (stepper)', { title }) },
    heading,
    hint ? h('p', { class: 'ctl-hint' }, hint) : null,
    h('div', { class: 'stepper-buttons btn-row' }, back, fwd, play, leave),
    status, formula, note);

  function go(i) {
    const n = list().length;
    const j = Math.max(-1, Math.min(n - 1, i));
    if (j !== index()) set(j);
    refresh();
  }

  function stop() {
    if (timer) clearInterval(timer);
    timer = 0;
    play.setAttribute('aria-pressed', 'false');
    play.textContent = `▶▶ ${t('Play')}`;
  }

  function start() {
    if (destroyed) return;
    const n = list().length;
    if (!n) return;
    if (index() >= n - 1) go(-1);
    play.setAttribute('aria-pressed', 'true');
    play.textContent = `❚❚ ${t('Pause')}`;
    const tick = () => {
      const m = list().length;
      if (index() >= m - 1 || document.hidden) { stop(); return; }
      go(index() + 1);
      if (index() >= m - 1) stop();
    };
    tick();
    timer = setInterval(tick, interval);
  }

  back.addEventListener('click', () => { stop(); go(index() - 1); });
  fwd.addEventListener('click', () => { stop(); go(index() + 1); });
  leave.addEventListener('click', () => { stop(); go(-1); });
  play.addEventListener('click', () => (timer ? stop() : start()));

  /** Re-reads the steps (numbers of the current view) and redraws the panel. */
  function refresh() {
    const all = list();
    let i = index();
    // an empty list means "nothing computed yet" (a demo builds its stepper before its first computation):
    // show nothing but keep the index, so a step restored from a link survives until the steps exist
    if (!all.length) i = -1;
    else if (i >= all.length) { i = all.length - 1; set(i); }
    // demos refresh the stepper in every drag frame: write only what changed (an unchanged attribute written
    // again is still a DOM mutation: style work, and noise for assistive technology)
    const put = (obj, key, v) => { if (obj[key] !== v) obj[key] = v; };
    put(back, 'disabled', i < 0);
    put(fwd, 'disabled', i >= all.length - 1);
    put(leave, 'disabled', i < 0);
    put(el.dataset, 'step', String(i));
    put(el.dataset, 'steps', String(all.length));
    if (formula.firstChild) clear(formula);
    if (note.textContent) note.textContent = '';
    const say = (x) => { if (status.textContent !== x) status.textContent = x; };
    if (i < 0) {
      say(all.length ? tn(all.length, '{n} step. Press Step to start.', '{n} steps. Press Step to start.') : t('No steps for this view.'));
      return;
    }
    const s = all[i];
    say(t('Step {i} of {n}: {label}', { i: i + 1, n: all.length, label: t(s.label) }));
    renderFormulas(s);
    if (s.note) note.textContent = t(s.note);
  }

  const texOf = new WeakMap();   // formula row → its TeX (to split it)
  const row = (t) => { const m = math(t, { display: true }); texOf.set(m, t); return m; };
  /** Typesets the step's formula rows once, then fits them to the panel's width. */
  function renderFormulas(s) {
    clear(formula);
    for (const t of [].concat(s.tex || [])) append(formula, row(t));
    fitFormulas();
  }

  /**
   * A formula wider than the panel is first broken at a top-level operator (=, +, −, \quad) near its middle
   * into two rows, the second indented (splitTex), then typeset smaller if a row is still too wide (down to
   * MIN_FORMULA_SCALE of the panel's size; past that the row scrolls, with a visible shadow at its edge),
   * instead of being cut at the edge. Runs again when the panel's width changes (shown, resized).
   */
  function fitFormulas() {
    const avail = formula.clientWidth;
    if (!avail) return;   // not laid out (a hidden tab or panel): the observer fits it when it is shown
    const width = (m) => m.scrollWidth || m.getBoundingClientRect().width;
    const shrink = (m) => {
      const w = width(m);
      if (w <= avail) return false;
      m.style.fontSize = `${Math.max(MIN_FORMULA_SCALE, Math.floor((avail / w) * 100) / 100)}em`;
      return width(m) > avail + 0.5;
    };
    let scrolls = false;
    for (const m of [...formula.children]) {
      if (width(m) <= avail) continue;
      const parts = texOf.has(m) ? splitTex(texOf.get(m)) : null;
      if (!parts) { scrolls = shrink(m) || scrolls; continue; }
      const rows = parts.map(row);
      m.replaceWith(...rows);
      for (const r of rows) scrolls = shrink(r) || scrolls;
    }
    formula.classList.toggle('stepper-formula-scrolls', scrolls);
  }
  let lastFitWidth = 0;
  // a new width (the panel shown, the window resized): typeset the rows afresh for it
  const fitObserver = typeof ResizeObserver === 'function' ? new ResizeObserver(() => {
    if (formula.clientWidth === lastFitWidth) return;
    lastFitWidth = formula.clientWidth;
    const s = list()[index()];
    if (s) renderFormulas(s);
  }) : null;
  fitObserver?.observe(formula);

  refresh();
  return {
    el, refresh, go, stop,
    /** The current step (-1 when off) — demos read it in draw() to highlight. */
    get index() { return index(); },
    destroy() { destroyed = true; stop(); fitObserver?.disconnect(); },
    /** Renames the panel (its heading and its accessible name). */
    setTitle(name) { const x = t(name); heading.textContent = x; el.setAttribute('aria-label', t('{title} (stepper)', { title: x })); },
  };
}
