// Exercises that check themselves: a demo state + a task + a check with a tolerance, all in the link.
//
// An exercise is stored in the demo's own link state under the key `exercise` (versioned with `v`, like the
// state itself), so `#<demo-id>/<state>` opens it in index.html, embed.html and <spline-lab state="…">:
//
//   state.exercise = { v: 1, id: 'b2-interpolate', title, task, check: 'data-distance', tol: 1e-9, hint, target? }
//
// The student sees the task, a Check button, feedback (how far off, the hint) and the number of attempts.
// Each check is computed by the wasm core (checks per demo: ./exercise-checks.js). Every result goes to
// the host page:
//   * in an iframe:           parent.postMessage({ type: 'splinelab:result', exercise, passed, score, attempts, state }, '*')
//   * in <spline-lab>:        a bubbling, composed CustomEvent('splinelab-result', { detail: same }) from the element
//   * in the page itself:     the same CustomEvent on the panel (it bubbles to document)
//
// Teachers make an exercise from any view with "Make exercise" (makeExerciseButton): choose a check the
// demo offers, a tolerance and the text; they get the link and the embed code.

import { h } from './dom.js';
import { encodeState, buildHash } from './state.js';
import { checksFor, findCheck, runCheck } from './exercise-checks.js';
import { t, tn, translateIfKnown, localDigits } from './i18n.js';
import { errorText } from './error-text.js'; // a module error in the page's language (its .field, .kind)

export const EXERCISE_VERSION = 1;
const MAX_TEXT = 2000;
const ID_RE = /^[a-z0-9][a-z0-9-]{0,63}$/;

/**
 * The exercise carried by a decoded link state (`raw.exercise`), validated, or null when there is none.
 * Throws an Error with a readable reason when it is there but unusable (unknown version, bad fields).
 */
export function readExercise(raw, demoId) {
  const e = raw && typeof raw === 'object' ? raw.exercise : null;
  if (e === undefined || e === null) return null;
  if (typeof e !== 'object' || Array.isArray(e)) throw new Error(t('the exercise in this link is not an object'));
  if (e.v !== EXERCISE_VERSION) throw new Error(t('this link\'s exercise has version {v}; this SplineLab reads version {mine}', { v: JSON.stringify(e.v), mine: String(EXERCISE_VERSION) }));
  const str = (k, req) => {
    const x = e[k];
    if (x === undefined || x === null) { if (req) throw new Error(t('the exercise has no {field}', { field: k })); return ''; }
    if (typeof x !== 'string' || x.length > MAX_TEXT) throw new Error(t('the exercise\'s {field} is not a text of at most {max} characters', { field: k, max: String(MAX_TEXT) }));
    return x;
  };
  const out = {
    v: EXERCISE_VERSION,
    id: str('id', false) || `${demoId}-${str('check', true)}`,
    title: str('title', false),
    task: str('task', true),
    check: str('check', true),
    hint: str('hint', false),
    tol: e.tol,
  };
  if (!ID_RE.test(out.id)) throw new Error(t('the exercise id may only hold a–z, 0–9 and -'));
  if (!(typeof out.tol === 'number' && Number.isFinite(out.tol) && out.tol >= 0)) throw new Error(t('the exercise tolerance is not a number ≥ 0'));
  if (!findCheck(demoId, out.check)) throw new Error(t('the demo "{demo}" offers no check "{check}"', { demo: demoId, check: out.check }));
  if (e.target !== undefined) {
    if (!(Array.isArray(e.target) && e.target.length === 2 && e.target.every((x) => typeof x === 'number' && Number.isFinite(x)))) throw new Error(t('the exercise target is not a point [x, y]'));
    out.target = [e.target[0], e.target[1]];
  }
  return out;
}

/** For the shell: keeps a valid exercise of `raw` on the validated `state` (a bad one is dropped, reported). */
export function withExercise(raw, state, demoId, notify) {
  try {
    const ex = readExercise(raw, demoId);
    if (ex) state.exercise = ex;
  } catch (e) {
    notify?.(t('The exercise in this link could not be read ({reason}); showing the demo without it.', { reason: e.message }), 'warning');
  }
  return state;
}

const SUP = { '0': '⁰', '1': '¹', '2': '²', '3': '³', '4': '⁴', '5': '⁵', '6': '⁶', '7': '⁷', '8': '⁸', '9': '⁹', '-': '⁻' };
/** 10 to an integer power, written as it is read: 10⁵. */
const pow10 = (k) => `10${String(k).replace(/./g, (c) => SUP[c] ?? c)}`;

/** A measured value for reading: three significant digits, 2.3 × 10⁻¹⁶ when tiny, the language's decimal separator. */
const num = (x) => {
  if (!Number.isFinite(x)) return String(x);
  if (x === 0) return '0';
  const a = Math.abs(x);
  if (a >= 1e-3 && a < 1e4) return localDigits(String(+x.toPrecision(3)).replace('-', '−'));
  const [m, e] = x.toExponential(1).split('e');   // 2.3e-16 is written 2.3 × 10⁻¹⁶
  return `${localDigits(m.replace('-', '−'))} × ${pow10(Number(e))}`;
};

/** A point Q as the task writes it: three decimals at most (2.945333 → 2.945, 2.5 → 2.5). */
export const targetText = (q) => {
  const parts = q.map((x) => localDigits(String(+x.toFixed(3))));
  // with a decimal comma the coordinates are parted by ';' (as the plot writes them)
  return `(${parts.join(localDigits('.') === ',' ? '; ' : ', ')})`;
};

/**
 * The feedback sentence for a result (exported for tests and the catalogue): what was measured and its
 * value (“RMS distance to the true sine: 0.206”), the tolerance, how far off, and the hint.
 */
export function feedbackText(res, ex) {
  if (res.error) return t('The check could not be computed: {error}', { error: res.error });
  const what = `${res.measure || t('Measured')}: ${num(res.value)}`;
  if (res.passed) return t('Correct! {what}, within the tolerance {tol}.', { what, tol: num(res.tol) });
  const factor = res.tol > 0 ? res.value / res.tol : Infinity;
  const far = Number.isFinite(factor)
    ? ` ${factor >= 10 ? t('(about {power} times too large)', { power: pow10(Math.floor(Math.log10(factor))) }) : t('({factor} times too large)', { factor: num(factor) })}` : '';
  // the hint: SplineLab's own (a catalogue exercise's, a check's default) is translated; a teacher's own is shown as typed
  const hint = ex.hint ? ` ${t('Hint: {hint}', { hint: translateIfKnown(ex.hint) })}` : '';
  return `${t('Not yet. {what}; the tolerance is {tol}', { what, tol: num(res.tol) })}${far}.${hint}`;
}

// attempts survive a re-mount of the same exercise (undo/redo re-mount the demo): per page, or per element
const pageAttempts = new Map();
const elementAttempts = new WeakMap();
function attemptsStore(host) {
  if (!host) return pageAttempts;
  if (!elementAttempts.has(host)) elementAttempts.set(host, new Map());
  return elementAttempts.get(host);
}

/**
 * The student's panel: task, Check button, feedback, attempts. Returns `{ element, check(), destroy() }`.
 * opts: { demoId, wasm, getState: () => state (with .exercise), host: the <spline-lab> element or null }
 */
/**
 * `wasm` may be the module itself, a promise of it, or a function returning either: the shell passes
 * `() => loadWasm()` (www/lib/host.js), the complete module, loaded on first use, because a check may call exports
 * of several demo groups (a demo page itself loads only its group's smaller module).
 */
function moduleOf(wasm) {
  let p = null;
  return () => (p ??= Promise.resolve(typeof wasm === 'function' ? wasm() : wasm));
}

export function exercisePanel({ demoId, wasm, getState, host = null }) {
  const module = moduleOf(wasm);
  const ex = getState().exercise;
  const store = attemptsStore(host);
  const key = `${demoId}:${ex.id}`;
  const attemptsOut = h('span', { class: 'exercise-attempts' });
  const feedback = h('p', { class: 'exercise-feedback', role: 'status', 'aria-live': 'polite' });
  const showAttempts = () => { const n = store.get(key) || 0; attemptsOut.textContent = tn(n, '{n} attempt', '{n} attempts'); };
  const check = async () => {
    const state = getState();
    let res;
    try { res = runCheck(await module(), demoId, ex, state); } catch (e) { res = { error: errorText(e), value: NaN, tol: ex.tol, passed: false, score: 0 }; }
    const attempts = (store.get(key) || 0) + 1;
    store.set(key, attempts);
    showAttempts();
    feedback.textContent = feedbackText(res, ex);
    feedback.dataset.passed = String(!!res.passed);
    panel.dataset.passed = String(!!res.passed);
    const { exercise: _omit, ...plain } = state;
    const detail = { type: 'splinelab:result', exercise: ex.id, passed: !!res.passed, score: res.score ?? 0, attempts, state: JSON.parse(JSON.stringify(plain)), value: res.value, tol: ex.tol, hinted: !res.passed && !res.error && !!ex.hint };
    report(detail, panel, host);
    return detail;
  };
  // the title and task in the link: SplineLab's own (a catalogue exercise) translated, a teacher's own as typed
  const panel = h('section', { class: 'exercise-panel', 'aria-label': t('Exercise'), dataset: { exercise: ex.id } },
    h('h2', { class: 'exercise-title' }, ex.title ? t('Exercise: {title}', { title: translateIfKnown(ex.title) }) : t('Exercise')),
    h('p', { class: 'exercise-task' }, translateIfKnown(ex.task)),
    ex.target ? h('p', { class: 'exercise-target' }, t('Q = {point}, marked Q in the figure', { point: targetText(ex.target) })) : null,
    h('div', { class: 'exercise-actions' },
      h('button', { type: 'button', class: 'btn btn-primary exercise-check', onclick: () => check() }, t('Check')),
      attemptsOut),
    feedback);
  showAttempts();
  return { element: panel, check, destroy() { panel.remove(); } };
}

/** Sends a result to whoever hosts this page or element (see the module doc). */
function report(detail, panel, host) {
  try {
    if (!host && window.parent && window.parent !== window) window.parent.postMessage(detail, '*');
  } catch { /* a detached frame: nothing to tell */ }
  panel.dispatchEvent(new CustomEvent('splinelab-result', { detail, bubbles: true, composed: true }));
}

/** A labelled form field of the exercise panels: its label above `el`. */
export const exerciseField = (label, el) => h('label', { class: 'exercise-field' }, h('span', null, label), el);

/**
 * Makes a SCORM package (./scorm-package.js, loaded on the first use) and saves it as `file`: the whole of
 * SplineLab inside, or with `relay` the small page that shows the exercises from the site at `base`. `status`
 * says how it went (with a link to the guide's steps); resolves to true when it was saved.
 * @param {{ id: string, title: string, passMark?: number, attempts?: number, hintCost?: number, items: { id: string, title: string, hash: string }[] }} pkg
 * @param {string} file
 * @param {HTMLElement} status
 * @param {{ relay?: boolean, base?: URL }} [opts]
 */
export async function savePackage(pkg, file, status, { relay = false, base = new URL('./', location.href) } = {}) {
  status.textContent = t('Making the package…');
  try {
    const { scormPackage, relayPackage, download } = await import('./scorm-package.js');
    download(await (relay ? relayPackage(pkg, { base }) : scormPackage(pkg, { base })), file);
    // the sentence around its link ({link}: the guide's steps), so that a language may place the link where it reads well
    const [before, after = ''] = t('Saved {file}: upload it to your course as a SCORM package ({link}).', { file }).split('{link}');
    status.replaceChildren(before,
      h('a', { href: new URL('guide.html#grades', base).href, target: '_blank', rel: 'noopener' }, t('how, in Moodle, Canvas and others')), after);
    return true;
  } catch (e) {
    status.textContent = t('The package could not be made: {error}', { error: e.message });
    return false;
  }
}

/**
 * The grading rules of a SCORM package (issue 27; applied in the launch page by ./scorm.js): pass mark, Checks
 * allowed per exercise, points a shown hint costs. `fields` go into a form; `read()` → the rules, or `{ error }`
 * naming the field (which it focuses). `passMark`: its starting value.
 */
export function gradingFields({ passMark = 100 } = {}) {
  const input = (cls, value, label, more) => {
    const el = /** @type {HTMLInputElement} */ (h('input', { type: 'text', inputmode: 'numeric', class: cls, value: String(value), spellcheck: 'false' }));
    return { el, label, field: exerciseField(`${label} ${more}`, el) };
  };
  // each label's name (for the error below) and its explanation in brackets, translated apart
  const pass = input('grading-pass', passMark, t('Pass mark for the LMS'), t('(score 0–100; a correct answer scores 100)'));
  const tries = input('grading-attempts', 0, t('Checks allowed per exercise'), t('(0: no limit)'));
  const hint = input('grading-hint', 0, t('Points a hint costs'), t('(0–100; the hint shows after a wrong answer)'));
  const read = () => {
    const out = {};
    /** @type {[string, { el: HTMLInputElement, label: string }, number][]} */
    const all = [['passMark', pass, 100], ['attempts', tries, 1000], ['hintCost', hint, 100]];
    for (const [key, f, max] of all) {
      const v = f.el.value.trim();
      if (!/^\d{1,4}$/.test(v) || Number(v) > max) {
        f.el.setAttribute('aria-invalid', 'true');
        f.el.focus();
        return { error: t('{field} must be a whole number from 0 to {max} (it is “{value}”).', { field: f.label, max: String(max), value: v }) };
      }
      f.el.removeAttribute('aria-invalid');
      out[key] = Number(v);
    }
    return out;
  };
  return { fields: [pass.field, tries.field, hint.field], inputs: [pass.el, tries.el, hint.el], read };
}

/** The hash of an exercise link for `demoId` with `state` and `exercise` (async: the state is compressed). */
export async function exerciseHash(demoId, state, exercise) {
  const { exercise: _old, ...plain } = state;
  return buildHash(demoId, await encodeState({ ...plain, exercise }));
}

/**
 * The teacher's "Make exercise" button and panel for the mounted demo. Returns { button, panel } (panel is
 * hidden until the button opens it), or null when the demo offers no checks.
 * opts: { demoId, title, wasm, getState, base (URL of the site's folder), notify }
 */
/** @param {{ demoId: string, title?: string, wasm: import('./host.js').SplineLab | Promise<import('./host.js').SplineLab> | (() => import('./host.js').SplineLab | Promise<import('./host.js').SplineLab>), getState: () => any, base?: URL, notify?: (msg: string, kind?: string) => void }} options */
export function makeExerciseButton({ demoId, title, wasm, getState, base = new URL('./', location.href), notify = () => {} }) {
  const checks = checksFor(demoId);
  if (!checks.length) return null;
  const module = moduleOf(wasm);
  const field = exerciseField;
  const checkSel = h('select', { class: 'exercise-make-check' }, checks.map((c) => h('option', { value: c.id }, t(c.label))));
  // text fields (decimal keyboard): a tolerance such as 1e-9 is typed as it is written
  const tolIn = h('input', { type: 'text', inputmode: 'decimal', class: 'exercise-make-tol', spellcheck: 'false' });
  const taskIn = h('textarea', { class: 'exercise-make-task', rows: 3 });
  const hintIn = h('textarea', { class: 'exercise-make-hint', rows: 2 });
  const titleIn = h('input', { type: 'text', class: 'exercise-make-title', maxlength: '200' });
  const tx = h('input', { type: 'text', inputmode: 'decimal', class: 'exercise-make-tx', 'aria-label': t('Point Q, x') });
  const ty = h('input', { type: 'text', inputmode: 'decimal', class: 'exercise-make-ty', 'aria-label': t('Point Q, y') });
  const targetRow = h('div', { class: 'exercise-field exercise-make-target', hidden: true }, h('span', null, t('Point Q (x, y)')), tx, ty);
  const now = h('p', { class: 'exercise-make-now', role: 'status' });
  const linkOut = h('input', { type: 'text', readonly: true, class: 'share-field exercise-make-link', 'aria-label': t('Exercise link') });
  const iframeOut = h('textarea', { readonly: true, class: 'share-field exercise-make-iframe', rows: 3, 'aria-label': t('Exercise embed code: iframe') });
  const elementOut = h('textarea', { readonly: true, class: 'share-field exercise-make-element', rows: 3, 'aria-label': t('Exercise embed code: spline-lab element') });
  // the exercise as a SCORM 1.2 package for an LMS's gradebook (./scorm-package.js, loaded on the first click)
  const grading = gradingFields();
  const scormStatus = h('p', { class: 'exercise-make-scorm-status', role: 'status', id: `scorm-status-${demoId}` });
  for (const el of grading.inputs) el.setAttribute('aria-describedby', scormStatus.id);
  const scormBtn = h('button', { type: 'button', class: 'btn exercise-make-scorm', onclick: () => scorm(false) }, t('Download for LMS (SCORM)'));
  const relayBtn = h('button', { type: 'button', class: 'btn exercise-make-relay', onclick: () => scorm(true) }, t('Small package that shows it from this site'));
  const out = h('div', { class: 'exercise-make-out', hidden: true },
    field(t('Link'), linkOut), field(t('Embed code (iframe)'), iframeOut), field(t('Embed code (<spline-lab> element)'), elementOut),
    ...grading.fields, h('div', { class: 'exercise-make-scorm-row' }, scormBtn, relayBtn), scormStatus);

  const current = () => findCheck(demoId, checkSel.value);
  const exercise = () => {
    const c = current();
    const ex = { v: EXERCISE_VERSION, id: `${demoId}-${c.id}`.slice(0, 64), title: titleIn.value.trim().slice(0, 200), task: taskIn.value.trim() || t(c.task),
      check: c.id, tol: tolIn.value.trim() === '' ? NaN : Number(tolIn.value), hint: hintIn.value.trim() };
    if (c.needsTarget) ex.target = [Number(tx.value), Number(ty.value)];
    return ex;
  };
  const preview = async () => {
    const ex = exercise();
    if (!(Number.isFinite(ex.tol) && ex.tol >= 0)) { now.textContent = t('The tolerance must be a number ≥ 0.'); return; }
    try {
      const r = runCheck(await module(), demoId, ex, getState());
      now.textContent = r.passed
        ? t('The view as it is now measures {value}: it passes — students would pass without doing anything; change the view first, or say so in the task.', { value: num(r.value) })
        : t('The view as it is now measures {value}: it does not pass (good: the student has something to do).', { value: num(r.value) });
    } catch (e) { now.textContent = t('The check cannot be computed on this view: {error}', { error: errorText(e) }); }
  };
  const pick = async () => {
    const c = current();
    tolIn.value = String(c.tol);
    taskIn.value = t(c.task);
    hintIn.value = c.hint ? t(c.hint) : '';
    targetRow.hidden = !c.needsTarget;
    if (c.needsTarget) {
      // suggest the point where the curve touches its envelope now (move the knot away afterwards)
      try {
        const s = getState();
        const k = s.order, n = s.points.length, t = [];
        for (let i = 0; i < k; i++) t.push(0);
        for (let i = 1; i <= n - k; i++) t.push(i);
        for (let i = 0; i < k; i++) t.push(n - k + 1);
        const e = (await module()).knotEnvelopeCurve({ curve: { order: k, knots: t, controlPoints: s.points }, p: s.p, at: [s.up] });
        tx.value = String(+e.points[0].toFixed(6)); ty.value = String(+e.points[1].toFixed(6));
      } catch { tx.value = '0'; ty.value = '0'; }
    }
    out.hidden = true;
    preview();
  };
  const make = async () => {
    const ex = exercise();
    if (!(Number.isFinite(ex.tol) && ex.tol >= 0)) { notify(t('The tolerance must be a number ≥ 0.'), 'error'); return; }
    if (ex.target && !ex.target.every(Number.isFinite)) { notify(t('The point Q needs two numbers.'), 'error'); return; }
    const hash = await exerciseHash(demoId, getState(), ex);
    lastHash = hash;
    const page = new URL(`index.html${hash}`, base).href;
    const embed = new URL(`embed.html${hash}`, base).href;
    linkOut.value = page;
    iframeOut.value = `<iframe src="${embed}" title="${t('{demo} — exercise (SplineLab)', { demo: t(String(title)) }).replace(/[<>&"]/g, '')}" width="100%" height="760" style="border:0" loading="lazy"></iframe>`;
    const payload = hash.slice(hash.indexOf('/') + 1);
    elementOut.value = `<script type="module" src="${new URL('spline-lab.js', base).href}"></script>\n<spline-lab demo="${demoId}" state="${payload}"></spline-lab>`;
    out.hidden = false;
    preview();
  };
  let lastHash = '';
  /** The package: the whole of SplineLab inside (`relay` false), or a small page that shows it from this site. */
  const scorm = async (relay) => {
    const rules = grading.read();
    if (rules.error) { scormStatus.textContent = rules.error; return; }
    const ex = exercise();
    scormBtn.disabled = relayBtn.disabled = true;
    const name = ex.title || t('{demo} — exercise', { demo: t(title) });
    const pkg = { id: ex.id, title: name, ...rules, items: [{ id: ex.id, title: name, hash: lastHash }] };
    await savePackage(pkg, `${ex.id}${relay ? '-relay' : ''}-scorm.zip`, scormStatus, { relay, base });
    scormBtn.disabled = relayBtn.disabled = false;
  };
  for (const el of [tolIn, tx, ty]) el.addEventListener('input', preview);
  checkSel.addEventListener('change', pick);
  const panel = h('div', { class: 'exercise-make', hidden: true, role: 'region', 'aria-label': t('Make an exercise') },
    h('p', { class: 'exercise-make-intro' }, t('The exercise starts from the view as it is now. Choose what the student must achieve; the link and the embed code carry everything.')),
    field(t('Check'), checkSel), field(t('Tolerance ε (passes when the measure ≤ ε)'), tolIn), targetRow,
    field(t('Title (optional)'), titleIn), field(t('Task for the student'), taskIn), field(t('Hint shown after a wrong answer'), hintIn),
    now,
    h('button', { type: 'button', class: 'btn btn-primary exercise-make-go', onclick: make }, t('Create exercise link')),
    out);
  const button = h('button', { type: 'button', class: 'btn exercise-make-toggle', 'aria-expanded': 'false', onclick: () => {
    const open = panel.hidden;
    if (open) pick();
    panel.hidden = !open;
    button.setAttribute('aria-expanded', String(open));
  } }, t('Make exercise'));
  return { button, panel };
}

/**
 * Shell hook (app.js, spline-lab.js): when the mounted demo's state carries an exercise, puts the student's
 * panel before `root` and returns it (else null).
 */
export function mountExercise({ demoId, wasm, state, root, host = null }) {
  if (!state || !state.exercise) return null;
  const p = exercisePanel({ demoId, wasm, getState: () => state, host });
  root.parentNode?.insertBefore(p.element, root);
  const stop = keepFigureOverSheet(root);
  return { ...p, destroy() { stop(); p.destroy(); } };
}

/**
 * Phones: the controls are a sheet over the lower part of the page (style.css), and the task sits above the
 * figure, so a student who opens the sheet and moves α would see neither the figure nor what it does. With an
 * exercise the sheet starts folded; while a
 * control in the sheet is used (focus, input, change), the page scrolls the figure — the demo's first visible
 * canvas — into the part of the window the sheet leaves free, unless most of it is there already. On wide
 * screens (no sheet) nothing happens: the plots column is sticky there. Returns a function that stops it.
 */
function keepFigureOverSheet(root) {
  const ac = new AbortController();
  let pending = false;
  const place = () => {
    pending = false;
    const sheet = root.querySelector('.demo-controls');
    if (!sheet || getComputedStyle(sheet).position !== 'fixed' || sheet.classList.contains('drawer-collapsed')) return;
    const fig = [...root.querySelectorAll('.demo-plots canvas')].find((c) => c.getClientRects().length && !c.closest('[hidden]'));
    if (!fig) return;
    const free = sheet.getBoundingClientRect().top;   // the window above the sheet
    const r = fig.getBoundingClientRect();
    const seen = Math.max(0, Math.min(r.bottom, free) - Math.max(r.top, 0));
    if (seen >= 0.9 * Math.min(r.height, free)) return;
    // the figure's top 8 px below the window's top, or (taller than the free part) its bottom at the sheet
    const dy = r.height + 16 <= free ? r.top - 8 : r.bottom - free + 8;
    const reduce = typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;
    window.scrollBy({ top: dy, behavior: reduce ? 'auto' : 'instant' });
  };
  const soon = (e) => {
    if (pending || !(e.target instanceof Element) || !e.target.closest('.demo-controls') || e.target.closest('.drawer-handle')) return;
    pending = true;
    requestAnimationFrame(place);
  };
  for (const type of ['focusin', 'input', 'change']) root.addEventListener(type, soon, { signal: ac.signal });
  // the sheet starts folded (its handle reads “Show controls”), so the task, Check and the figure are seen first
  requestAnimationFrame(() => {
    const sheet = root.querySelector('.demo-controls'), handle = sheet?.querySelector('.drawer-handle');
    if (!ac.signal.aborted && handle && getComputedStyle(sheet).position === 'fixed' && !sheet.classList.contains('drawer-collapsed')) handle.click();
  });
  return () => ac.abort();
}

