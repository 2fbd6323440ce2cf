// The launch page of a SCORM package (issue 27; the package is made by ./scorm-package.js): the one-file build of
// SplineLab with a `<script id="splinelab-scorm" type="application/json">` config in its head. Before the shell
// routes, this opens the exercise (or, on a relaunch, the exercise and view the student left, from
// cmi.suspend_data); then each Check, each change of the view and the page's leaving go to the LMS through
// ./scorm.js. A bar above the figure says what was recorded (a line, not a notice over the page: notices are for
// the LMS's errors); a set (several exercises, one total score) also lists its exercises there to move between them.
//
// Config: { v: 1, title, passMark (0–100), attempts (Checks per exercise, 0: no limit), hintCost (0–100),
//          items: [{ id, title, hash: '#<demo>/<state with the exercise>' }] }.

import { findAPI, scormSession } from './scorm.js';
import { t, tn, translateIfKnown, startLocale, linkLocale } from './i18n.js';

const ID_RE = /^[a-z0-9][a-z0-9-]{0,63}$/;

/** The package's config in this page, or null (an ordinary page); `{ error }` when it is there but unusable. */
export function scormConfig(doc = document) {
  const el = doc.getElementById('splinelab-scorm');
  if (!el) return null;
  try {
    const c = JSON.parse(el.textContent || '');
    const ok = c && c.v === 1 && Array.isArray(c.items) && c.items.length >= 1 && c.items.length <= 50
      && c.items.every((x) => x && ID_RE.test(x.id) && typeof x.hash === 'string' && /^#[a-z0-9-]+\//.test(x.hash));
    if (ok) return c;
  } catch { /* below */ }
  // (read before the language is loaded: launchScorm translates it)
  return { error: 'the package\'s settings could not be read' };
}

const demoOf = (hash) => hash.slice(1).split('/')[0];

/**
 * Runs the launch: `start()` is the shell's own start (it routes from location.hash), `notify(text, kind, opts)`
 * its notices, `flush()` writes a pending state to the link now, `watchLink(f)` calls f with each link written.
 */
export async function launchScorm(config, { start, notify, flush, watchLink }) {
  // the language first (the shell's start() chooses it again, the same way): the bar's texts are written before it
  await startLocale({ param: linkLocale() });
  let bar = null;
  const early = [];
  const say = (text, kind) => {
    if (kind === 'error' || kind === 'warning') notify(text, kind, { id: `scorm-${kind}`, timeout: 0 });
    else if (bar) bar.status(text); else early.push(text);
  };
  if (!config || config.error) { notify(t('This package is damaged: {error}.', { error: config?.error ? t(config.error) : t('no settings') }), 'error', { timeout: 0 }); start(); return null; }
  const items = config.items;
  const whole = (x, lo, hi, d) => (Number.isInteger(x) && x >= lo && x <= hi ? x : d);
  const passMark = whole(config.passMark, 0, 100, 100);
  const attempts = whole(config.attempts, 0, 1000, 0);
  const hintCost = whole(config.hintCost, 0, 100, 0);
  const session = scormSession({ api: findAPI(window), count: items.length, passMark, attempts, hintCost, say, tr: t });
  // the numbers here are whole (0–100): String, not a decimal separator
  const rules = [t('pass mark {mark} of 100', { mark: String(passMark) }), attempts ? tn(attempts, '{n} Check per exercise', '{n} Checks per exercise') : '',
    hintCost ? tn(hintCost, 'a hint costs {n} point', 'a hint costs {n} points') : ''].filter(Boolean).join('; ');
  const viewOf = (k) => {
    const saved = session.resumed?.l[k] || '';
    return saved && demoOf(saved) === demoOf(items[k].hash) ? saved : items[k].hash;
  };
  let current = session.resumed?.i ?? 0;
  history.replaceState(history.state, '', viewOf(current));
  document.documentElement.dataset.scorm = session.connected ? 'connected' : 'none';
  bar = packageBar(items, session, rules, (k) => go(k));
  for (const t of early) bar.status(t);
  start();
  // every state the shell writes to the link is handed to the LMS (cmi.suspend_data; committed with the next Check
  // or on leaving): the shell writes it asynchronously (compressed), so pagehide alone may read the one before
  watchLink?.((hash) => { if (demoOf(hash) === demoOf(items[current].hash)) session.setView(current, hash); });
  function go(k) {
    if (k === current || !(k >= 0 && k < items.length)) return;
    current = k;
    location.hash = viewOf(k); // the shell routes to it (hashchange)
    session.setView(k, viewOf(k));
    bar.show(k);
  }
  // no Check left: the button does nothing but say so (a capturing listener: the panel is rebuilt on undo)
  document.addEventListener('click', (e) => {
    const b = /** @type {Element} */ (e.target)?.closest?.('.exercise-check');
    if (!b || !session.connected || session.left(current) > 0) return;
    e.preventDefault();
    e.stopImmediatePropagation();
    say(t('No Check left: this exercise allowed {allowed}. Your best score, {best} of 100, is recorded.', { allowed: String(attempts), best: String(Math.max(0, session.best[current])) }), 'info');
  }, true);
  document.addEventListener('splinelab-result', async (e) => {
    const d = /** @type {CustomEvent} */ (e).detail || {};
    await flush(); // the state checked is in the link before it is saved
    const k = items.findIndex((x) => x.id === d.exercise);
    const r = session.report(k >= 0 ? k : current, d);
    if (!r) return;
    document.documentElement.dataset.scormStatus = r.status;
    document.documentElement.dataset.scormScore = String(r.raw);
    bar.show(current);
    const of = items.length > 1 ? t('this exercise {best} of 100 (its best), the set {raw} of 100', { best: String(r.best), raw: String(r.raw) })
      : t('score {raw} of 100 (the best of this attempt)', { raw: String(r.raw) });
    const more = Number.isFinite(r.left) ? ` ${tn(r.left, '{n} Check left.', '{n} Checks left.')}` : '';
    const status = r.status === 'passed' ? t('passed') : t('not passed yet');
    say(`${t('Recorded in the course: {status}, {of}; {rules}.', { status, of, rules })}${more}`, 'info');
  });
  window.addEventListener('pagehide', () => session.finish());
  if (session.connected && session.resumed) say(t('Welcome back: this is where you left off.'), 'info');
  bar.show(current);
  return session;
}

/**
 * The bar above the figure: a status line (what was recorded); for a set also "Exercise k of n: title", the
 * exercises as buttons with their best scores, and the total.
 */
function packageBar(items, session, rules, go) {
  const set = items.length > 1;
  const el = document.createElement(set ? 'nav' : 'div');
  el.className = 'scorm-bar';
  if (set) el.setAttribute('aria-label', t('Exercises of this set'));
  const line = document.createElement('p');
  line.className = 'scorm-status';
  line.setAttribute('role', 'status');
  const head = document.createElement('p');
  head.className = 'scorm-set-head';
  const list = document.createElement('ol');
  list.className = 'scorm-set-list';
  const buttons = items.map((x, k) => {
    const li = document.createElement('li');
    const b = document.createElement('button');
    b.type = 'button';
    b.className = 'btn btn-small scorm-set-item';
    b.addEventListener('click', () => go(k));
    li.append(b);
    list.append(li);
    return b;
  });
  el.append(...(set ? [head, list] : []), line);
  document.body.prepend(el);
  return {
    status(text) { line.textContent = text; },
    show(k) {
      if (!set) return;
      // an item's title: the teacher's (as typed) or a catalogue exercise's (translated when the language has it)
      const name = (x) => (x.title ? translateIfKnown(x.title) : x.id);
      head.textContent = t('Exercise {k} of {count}: {title}. The set\'s score is the mean of the exercises\' best scores: {total} of 100 so far ({rules}).',
        { k: String(k + 1), count: String(items.length), title: name(items[k]), total: String(session.total()), rules });
      buttons.forEach((b, j) => {
        const s = session.best[j];
        b.textContent = `${j + 1}. ${name(items[j])}${s >= 0 ? ` — ${s}` : ''}`;
        if (j === k) b.setAttribute('aria-current', 'step'); else b.removeAttribute('aria-current');
      });
    },
  };
}
