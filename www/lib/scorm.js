// The content side of SCORM 1.2 (issue 27): an exercise in a package that an LMS launches (Moodle's SCORM
// activity, Canvas, Blackboard, D2L) reports its checks to the LMS's gradebook, with no plugin and no server.
//
// The LMS gives the launched page a JavaScript object `API` in a window above it (SCORM 1.2 Run-Time Environment,
// §3.3: LMSInitialize, LMSGetValue, LMSSetValue, LMSCommit, LMSFinish, LMSGetLastError, LMSGetErrorString,
// LMSGetDiagnostic; every argument and result is a string, "true" / "false" for success). It is found as ADL's
// sample code finds it: up the `parent` chain (at most 7 steps), then from `opener`. Frames of another origin throw
// on access; they are skipped.
//
// What is written (cmi.core.* of the RTE data model, §3.4):
//   at launch     LMSInitialize(""); lesson_status "incomplete" on a first launch (it was "not attempted")
//   each Check    score.raw (0–100, the best of this attempt: the core's score × 100), score.min 0, score.max 100;
//                 lesson_status "passed" / "failed" against the pass mark (the manifest's adlcp:masteryscore);
//                 suspend_data (the view's link, so a relaunch continues there); exit "suspend" until passed
//                 (then ""); LMSCommit("")
//   on leaving    (pagehide) suspend_data again, session_time (HHHH:MM:SS.SS), LMSCommit, LMSFinish("")
// suspend_data holds at most 4096 characters in SCORM 1.2: the link (compressed already) is saved only when it
// fits; otherwise the page says that this view cannot be kept and the score is still recorded.
// Errors of the LMS (a call returning "false") are shown in the page with LMSGetLastError's code and text, never
// thrown. Without an LMS (the launch page opened by itself) the exercise works as anywhere, and the page says that
// the result is not recorded.

/** SCORM 1.2 limit of cmi.suspend_data (RTE §3.4.2, CMIString4096). */
export const SUSPEND_LIMIT = 4096;

/** `text` with its `{name}` places filled from `params` (the messages in English, where no translator is given). */
const fillIn = (text, params) => text.replace(/\{(\w+)\}/g, (m, k) => (params && k in params ? String(params[k]) : m));

/** The LMS's API object above `win` (ADL's algorithm), or null. */
export function findAPI(win) {
  const look = (w) => {
    let tries = 0;
    for (let cur = w; cur; tries++) {
      try { if (cur.API && typeof cur.API.LMSInitialize === 'function') return cur.API; } catch { /* another origin */ }
      let up = null;
      try { up = cur.parent; } catch { up = null; }
      if (!up || up === cur || tries >= 7) return null;
      cur = up;
    }
    return null;
  };
  const found = look(win);
  if (found) return found;
  let op = null;
  try { op = win.opener; } catch { op = null; }
  return op ? look(op) : null;
}

/** Seconds as SCORM 1.2's CMITimespan: HHHH:MM:SS.SS. */
export function timespan(seconds) {
  const s = Math.max(0, seconds);
  const hh = Math.min(9999, Math.floor(s / 3600)), mm = Math.floor((s % 3600) / 60), ss = s % 60;
  return `${String(hh).padStart(4, '0')}:${String(mm).padStart(2, '0')}:${ss.toFixed(2).padStart(5, '0')}`;
}

/**
 * The record kept in cmi.suspend_data: `{ v: 1, i, b, a, h, l }` — the exercise shown (index), and per exercise of
 * the package its best score (0–100, or -1: not checked yet), the Checks used, whether its hint was shown (0/1),
 * and the view's link. Returns null for anything else.
 */
export function readSuspend(text, count) {
  try {
    const d = JSON.parse(text);
    if (!d || d.v !== 1 || !Array.isArray(d.b) || d.b.length !== count || !Array.isArray(d.l)) return null;
    const b = d.b.map((x) => (Number.isInteger(x) && x >= -1 && x <= 100 ? x : -1));
    const per = (arr, ok) => Array.from({ length: count }, (_, k) => (Array.isArray(arr) && ok(arr[k]) ? arr[k] : 0));
    const a = per(d.a, (x) => Number.isInteger(x) && x >= 0);
    const h = per(d.h, (x) => x === 0 || x === 1);
    const l = Array.from({ length: count }, (_, k) => (typeof d.l[k] === 'string' ? d.l[k] : ''));
    const i = Number.isInteger(d.i) && d.i >= 0 && d.i < count ? d.i : 0;
    return { i, b, a, h, l };
  } catch { return null; }
}

/**
 * A session with the LMS for a package of `count` exercises (1, or a set with one total score). `api` from
 * findAPI (null: no LMS). `passMark` 0–100 (the lowest passing score.raw). `say(text, kind)` shows a message in
 * the page ('info' | 'warning' | 'error').
 * The score of the package (cmi.core.score.raw) is the mean over its exercises of each one's best score this
 * attempt (an exercise not checked yet counts 0), rounded to a whole number; each best score is round(100 · the
 * core's score of a Check). An attempt spans launches until the LMS starts a new one: the best scores, the views
 * and the exercise shown come back from cmi.suspend_data.
 * The teacher's rules: `attempts` Checks per exercise (0: no limit; a Check past them is not recorded, and
 * `left(index)` says how many remain), `hintCost` points: once an exercise's hint has been shown (with a wrong
 * answer: the result's `hinted`), its later scores count at most 100 − hintCost.
 * Returns { connected, entry, resumed ({ i, b, a, h, l } or null), total(), best, left(index),
 * report(index, result), setView(index, link), finish(), log (the calls made, for tests) }.
 * `tr(text, params)` writes a message in the page's language (www/lib/i18n.js t; the relay page has none: English,
 * its {name} places filled).
 * @param {{ api: any, count?: number, passMark?: number, attempts?: number, hintCost?: number, say?: (text: string, kind: string) => void, now?: () => number,
 *   tr?: (text: string, params?: Record<string, string | number>) => string }} opts
 */
export function scormSession({ api, count = 1, passMark = 100, attempts = 0, hintCost = 0, say = (_text, _kind) => {}, now = () => Date.now(), tr = fillIn }) {
  const log = [];
  const started = now();
  const best = Array(count).fill(-1);
  const used = Array(count).fill(0);
  const hinted = Array(count).fill(0);
  const links = Array(count).fill('');
  let current = 0, passed = false, finished = false, lastError = '';
  const call = (name, ...args) => {
    let r = 'false';
    try { r = String(api[name](...args)); } catch (e) { r = 'false'; lastError = `${name} threw: ${e?.message || e}`; }
    log.push([name, ...args, r]);
    return r;
  };
  /** A call that must succeed: on "false", the LMS's error is shown (once per code and call). */
  const shown = new Set();
  const must = (name, ...args) => {
    const r = call(name, ...args);
    if (r === 'false' || (name === 'LMSSetValue' && r !== 'true')) {
      let code = '', text = '';
      try { code = String(api.LMSGetLastError()); text = String(api.LMSGetErrorString(code)); } catch { /* */ }
      const what = name === 'LMSSetValue' || name === 'LMSGetValue' ? ` (${args[0]})` : '';
      const msg = tr('The LMS refused {call}: error {error}. The result may not be recorded.', { call: `${name}${what}`, error: `${code || '?'}${text ? ` — ${text}` : ''}${lastError ? ` (${lastError})` : ''}` });
      if (!shown.has(code + name + what)) { shown.add(code + name + what); say(msg, 'error'); }
      return false;
    }
    return true;
  };
  const get = (key) => { const r = call('LMSGetValue', key); return typeof r === 'string' && r !== 'false' ? r : ''; };
  const total = () => Math.round(best.reduce((a, x) => a + Math.max(0, x), 0) / count);
  const left = (k) => (attempts > 0 ? Math.max(0, attempts - used[k]) : Infinity);

  if (!api) {
    say(tr('No LMS found: this exercise works, but its result is not recorded anywhere. (Opened by itself, not launched from a course.)'), 'info');
    return { connected: false, entry: '', resumed: null, total, best, left: () => Infinity, report() { return null; }, setView() {}, finish() {}, log };
  }
  const connected = must('LMSInitialize', '');
  const entry = connected ? get('cmi.core.entry') : '';
  const status = connected ? get('cmi.core.lesson_status') : '';
  const resumed = connected ? readSuspend(get('cmi.suspend_data'), count) : null;
  if (resumed) {
    for (let k = 0; k < count; k++) { best[k] = resumed.b[k]; used[k] = resumed.a[k]; hinted[k] = resumed.h[k]; links[k] = resumed.l[k]; }
    current = resumed.i;
  }
  if (connected && (status === '' || status === 'not attempted')) must('LMSSetValue', 'cmi.core.lesson_status', 'incomplete');
  if (connected) {
    must('LMSSetValue', 'cmi.core.exit', 'suspend');
    must('LMSCommit', '');
  }
  passed = status === 'passed' || (best.some((x) => x >= 0) && total() >= passMark); // a relaunch after a pass keeps it

  let cut = false;
  /** cmi.suspend_data from the record; past SCORM 1.2's 4096 characters the views are left out (said once). */
  function writeSuspend() {
    const rec = (l) => JSON.stringify({ v: 1, i: current, b: best, a: used, h: hinted, l });
    let text = rec(links);
    if (text.length > SUSPEND_LIMIT) {
      // keep the view shown, then none: the scores always fit (a few characters per exercise)
      text = rec(links.map((x, k) => (k === current ? x : '')));
      if (text.length > SUSPEND_LIMIT) text = rec([]);
      if (!cut) say(tr(text.includes('#') ? 'This view\'s link is too long for the {n} characters that SCORM 1.2 lets an LMS keep: the score is recorded, but a relaunch keeps only the exercise shown now.' : 'This view\'s link is too long for the {n} characters that SCORM 1.2 lets an LMS keep: the score is recorded, but a relaunch starts from the exercise\'s first view.', { n: String(SUSPEND_LIMIT) }), 'warning');
      cut = true;
    }
    must('LMSSetValue', 'cmi.suspend_data', text);
  }

  /** The view of exercise `index` is now `link` (the page shows it): written (committed with the next Check or on leaving). */
  function setView(index, link) {
    if (!connected || finished || typeof link !== 'string' || !(index >= 0 && index < count)) return;
    current = index;
    links[index] = link;
    writeSuspend();
  }

  /** A Check's result (`{ score, hinted }`, score in [0, 1]) for exercise `index`: written and committed (null
   * when there is no LMS, or no Check left). */
  function report(index, result) {
    if (!connected || finished || !(index >= 0 && index < count) || left(index) <= 0) return null;
    used[index]++;
    let raw = Math.round(Math.max(0, Math.min(1, Number(result.score) || 0)) * 100);
    if (hinted[index]) raw = Math.min(raw, 100 - hintCost); // the hint was shown by an earlier Check
    if (result.hinted) hinted[index] = 1;
    best[index] = Math.max(best[index], raw);
    passed = passed || total() >= passMark;
    must('LMSSetValue', 'cmi.core.score.min', '0');
    must('LMSSetValue', 'cmi.core.score.max', '100');
    must('LMSSetValue', 'cmi.core.score.raw', String(total()));
    must('LMSSetValue', 'cmi.core.lesson_status', passed ? 'passed' : 'failed');
    writeSuspend();
    must('LMSSetValue', 'cmi.core.exit', passed ? '' : 'suspend');
    const ok = must('LMSCommit', '');
    return { raw: total(), best: best[index], left: left(index), status: passed ? 'passed' : 'failed', committed: ok };
  }

  function finish() {
    if (!connected || finished) return;
    writeSuspend();
    must('LMSSetValue', 'cmi.core.session_time', timespan((now() - started) / 1000));
    must('LMSCommit', '');
    finished = true;
    must('LMSFinish', '');
  }

  return { connected, entry, resumed, total, best, left, report, setView, finish, log };
}
