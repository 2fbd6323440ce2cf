// The SplineLab sandbox (sandbox.html): the visitor's JavaScript runs against the wasm module as the body of
//   async function (sl, plot, surface, print) { … }
// only when they press Run (or Ctrl/Cmd+Enter) — never on load, not even from a link `sandbox.html#code=<base64url>`.
// It runs OFF the page: in a Web Worker started by an opaque-origin sandboxed iframe (www/lib/sandbox-runner.js,
// www/sandbox-frame.js, www/sandbox-worker.js), so it cannot read the site's saved states or cookies, touch this
// page or navigate it, and an endless loop freezes only the worker: Stop, or the time limit, ends it and a fresh
// worker takes its place. plot / surface / print in the worker post their data here; this page draws it (items in
// order on the 2D plot, meshes in the 3D view) and prints. An error's line (and an API error's `.field`, `.kind`)
// is shown under that line of the code. A returned value is printed and drawn (by the worker, as plot/surface).

import { h } from './lib/dom.js';
import { createPlot, PALETTE, SERIES } from './lib/plot2d.js';
import { View3D } from './lib/view3d.js';
import { EXAMPLES, exampleLabel } from './lib/sandbox-examples.js';
import { createEditor } from './lib/sandbox-editor.js';
import { encodeCode, codeFromHash } from './lib/sandbox-format.js';
import { createRunner } from './lib/sandbox-runner.js';

/** The page's element `id` (inputs, buttons, …: typed loosely). @returns {any} */
const $ = (id) => document.getElementById(id);
/** A run that has not finished after this many seconds is stopped (the page says so, next to Run). */
const LIMIT_S = 10;
let limitMs = LIMIT_S * 1000; // tests shorten it (window.splinelabSandbox.limitMs) to see the same mechanism act

const editor = createEditor($('sb-editor'));
const output = $('sb-output');
const status = $('sb-status');
const runButton = $('sb-run');
const stopButton = $('sb-stop');
let ready = false;
let running = false;
let runCount = 0;

// ---------------------------------------------------------------- 2D plot: items drawn in order

const items = []; // { kind: 'line' | 'points', data, stride, color, width, dash, close, label, radius }
let colour = 0;
const nextColour = () => SERIES[colour++ % SERIES.length];
const plot2d = createPlot($('sb-plot'), {
  ariaLabel: 'Sandbox plot: what plot() drew',
  height: 380,
  equal: true, // geometry: a circle looks round (plot.equal(false) for graphs of functions)
  describe: () => (items.length ? `${items.length} drawn: ${items.map((i) => i.label || i.kind).join(', ')}` : 'Nothing drawn yet'),
  draw(g, p) {
    for (const it of items) {
      if (it.kind === 'line') p.polyline(it.data, { stride: it.stride, color: it.color, width: it.width ?? 2.5, dash: it.dash, close: it.close });
      else p.points(it.data, { stride: it.stride, color: it.color, radius: it.radius ?? 4.5 });
    }
  },
  fit: () => p2bounds(),
});

// Basis functions (parameter u across, value up) get axes of their own: drawn into the x–y plot of the
// curves they would share one box with points of another space.
const basisItems = []; // { data, stride, color, width, label }
const basisPlot = createPlot($('sb-basis'), {
  ariaLabel: 'Sandbox basis plot: the basis functions plot() drew, over their parameter',
  height: 240,
  equal: false,
  describe: () => (basisItems.length ? `${basisItems.length} basis functions over the parameter u` : 'No basis functions drawn'),
  draw(g, p) { for (const it of basisItems) p.polyline(it.data, { stride: 2, color: it.color, width: it.width ?? 2 }); },
  fit: () => p2bounds(basisItems),
});
basisPlot.canvas.dataset.plot = 'basis';
plot2d.canvas.dataset.plot = 'curves';

function p2bounds(list = items) {
  const b = { xmin: Infinity, xmax: -Infinity, ymin: Infinity, ymax: -Infinity };
  for (const it of list) {
    const d = it.data;
    const add = (x, y) => { if (Number.isFinite(x) && Number.isFinite(y)) { b.xmin = Math.min(b.xmin, x); b.xmax = Math.max(b.xmax, x); b.ymin = Math.min(b.ymin, y); b.ymax = Math.max(b.ymax, y); } };
    if (d.length && Array.isArray(d[0])) for (const q of d) add(q[0], q[1]);
    else for (let i = 0; i + 1 < d.length; i += it.stride) add(d[i], d[i + 1]);
  }
  return Number.isFinite(b.xmin) ? b : null;
}

/** Writes the legend `ul` of a plot's labelled items (a swatch per item: dot for points, dashed for dashes). */
function writeLegend(ul, list) {
  ul.replaceChildren(...list.filter((i) => i.label).map((i) => {
    const sw = h('span', { class: `swatch${i.kind === 'points' ? ' dot' : ''}${i.dash ? ' dashed' : ''}` });
    if (!i.dash) sw.style.background = i.color; // CSSOM, which the page's style-src allows (a style attribute is not)
    return h('li', {}, sw, i.label);
  }));
}

/** Refits and redraws a plot, and writes its legend, on the next frame: once however many items were added in
 * this frame (a program may draw thousands). */
const fitting = new Set();
function scheduleFit(p, legend, list) {
  if (fitting.has(p)) return;
  fitting.add(p);
  requestAnimationFrame(() => { fitting.delete(p); writeLegend(legend, list); p.resize(); p.fitContent(); p.redraw(); });
}

const str = (x) => (x == null ? '' : String(x));
const num = (x) => (Number.isFinite(x) ? x : undefined);
const dashOf = (d) => (Array.isArray(d) ? d.map(Number) : !!d); // true or [on, off] (plot2d)

/** Adds a polyline item: `o` is the worker's op { data, stride, opts } (data: flat numbers or [[x, y], …]). */
function addLine(o, defaults = {}) {
  const opts = { ...defaults, ...o.opts };
  items.push({ kind: 'line', data: o.data, stride: o.stride || 2, color: str(opts.color) || nextColour(), width: num(opts.width), dash: dashOf(opts.dash), close: !!opts.close, label: str(opts.label) });
}

/** The rows of a basis result (values, params, count) as one curve per function over u, in the basis plot. */
function addBasis(o) {
  const opts = o.opts || {};
  const n = o.params.length;
  const count = o.count || (n ? o.values.length / n : 0);
  const y0 = num(opts.y0) ?? 0, k = num(opts.scale) ?? 1;
  for (let i = 0; i < count; i++) {
    const data = new Float64Array(2 * n);
    for (let r = 0; r < n; r++) { data[2 * r] = o.params[r]; data[2 * r + 1] = y0 + k * o.values[r * count + i]; }
    basisItems.push({ data, stride: 2, color: SERIES[i % SERIES.length], width: 2, label: opts.label && i === 0 ? str(opts.label) : '' });
  }
}

function redrawBasis() {
  $('sb-basis-panel').hidden = basisItems.length === 0;
  scheduleFit(basisPlot, $('sb-basis-legend'), basisItems);
}

function redraw() {
  $('sb-plot-panel').hidden = false;
  scheduleFit(plot2d, $('sb-plot-legend'), items);
}

// ---------------------------------------------------------------- 3D view

let view = null;
let meshCount = 0;
function view3d() {
  $('sb-view-panel').hidden = false;
  if (!view) view = new View3D($('sb-view'), { height: 380, ariaLabel: 'Sandbox 3D view: what surface() drew' });
  return view;
}
let fit3d = false;
function refit() {
  if (fit3d) return;
  fit3d = true;
  requestAnimationFrame(() => { fit3d = false; view?.fit(); view?.render(); });
}

// ---------------------------------------------------------------- what the worker's plot / surface / print post

/** Draws or prints one operation of the worker (its helpers' documentation is in sandbox-worker.js). */
function apply(o) {
  const opts = o.opts && typeof o.opts === 'object' ? o.opts : {};
  switch (o.op) {
    case 'print':
      output.append(h('span', { class: 'sb-line' }, `${str(o.text)}\n`));
      return;
    case 'result':
      output.append(h('span', { class: 'sb-result-label' }, 'Returned:\n'), h('span', { class: 'sb-result' }, `${str(o.text)}\n`));
      return;
    case 'line': addLine(o); return redraw();
    case 'polygon': addLine(o, { color: PALETTE.polygon, width: 1.5, dash: true }); return redraw();
    case 'paths': {
      const color = str(opts.color) || nextColour();
      o.paths.forEach((p, i) => items.push({ kind: 'line', data: p.data, stride: p.stride || 2, color, width: num(opts.width) ?? 1.75, dash: dashOf(opts.dash), label: i === 0 ? str(opts.label) : '' }));
      return redraw();
    }
    case 'points':
      items.push({ kind: 'points', data: o.data, stride: o.stride || 2, color: str(opts.color) || PALETTE.control, radius: num(opts.radius), label: str(opts.label) });
      return redraw();
    case 'basis': addBasis(o); return redrawBasis();
    case 'clear': items.length = 0; basisItems.length = 0; colour = 0; redraw(); return redrawBasis();
    case 'equal': plot2d.setOptions({ equal: !!o.on }); return redraw();
    case 'mesh':
      view3d().setMesh(`mesh-${++meshCount}`, o.mesh, { isolines: !!o.mesh.nu, ...opts });
      return refit();
    case 'lines': view3d().setLines(`lines-${++meshCount}`, o.lines, opts); return refit();
    case 'points3d': view3d().setPoints(`points-${++meshCount}`, o.points, { ...opts, pickable: false, draggable: false }); return refit();
    case 'clear3d': view?.clear(); return undefined;
    case 'cut': {
      const l = o.limits || {};
      output.append(h('span', { class: 'sb-result-label' }, `… The code printed or drew more than this page shows (${l.prints} lines, ${l.drawings} drawings, ${l.bytes} MB of data): the rest is left out; the code went on running.\n`));
      return undefined;
    }
    default: throw new Error(`unknown drawing operation ${str(o.op)}`);
  }
}

// ---------------------------------------------------------------- running the code (in the worker)

const runner = createRunner($('sb-runner'), { onMessage });
let current = null; // the run in progress: { id, t0, timer, resolve, failed }

// The worker's messages are handled in slices of at most 8 ms, each its own task, so that the page keeps drawing
// frames and answering input (Stop) however fast a program posts.
const queue = [];
let queueAt = 0;
let flushing = false;
let lastOutcome = '';

/** A message of the worker: queued (a breakdown of the worker is handled at once). */
function onMessage(d) {
  if (d.type === 'failed') {
    // the worker itself broke down (e.g. out of memory): end the run, and start a fresh worker
    if (current) { finish('error', { name: 'Error', message: `the sandbox's worker stopped: ${str(d.message)}` }); restartWorker(); }
    return;
  }
  queue.push(d);
  if (!flushing) { flushing = true; setTimeout(flush, 0); }
}

function flush() {
  const t0 = performance.now();
  while (queueAt < queue.length && performance.now() - t0 < 8) handle(queue[queueAt++]);
  if (queueAt < queue.length) { setTimeout(flush, 0); return; }
  queue.length = 0;
  queueAt = 0;
  flushing = false;
}

/** One message: an operation, the end of a run, or an error thrown after its end. */
function handle(d) {
  if (!current || d.id !== current.id) {
    // after the run ended (a timer of the code): its prints and drawings still show, its errors below the output
    if (d.id !== runCount || current || (lastOutcome !== 'ok' && lastOutcome !== 'error')) return;
    if (d.type === 'op') { try { apply(d); } catch { /* nothing to attach it to */ } }
    if (d.type === 'stray') output.append(h('span', { class: 'sb-line' }, `Error after the run ended: ${str(d.error?.message)}\n`));
    return;
  }
  if (d.type === 'op') {
    try { apply(d); } catch (e) {
      // the page could not draw what the code passed (e.g. a mesh index out of range): an error of that line
      current.failed ??= { name: 'Error', message: e.message, line: d.line | 0 };
    }
  } else if (d.type === 'done') finish(current.failed ? 'error' : 'ok', current.failed);
  else if (d.type === 'error' || d.type === 'stray') finish('error', d.error || {});
}

function clearAll() {
  items.length = 0;
  colour = 0;
  output.replaceChildren();
  view?.clear();
  meshCount = 0;
  editor.clearError();
  const box = $('sb-error');
  box.hidden = true;
  delete box.dataset.kind;
  $('sb-plot-legend').replaceChildren();
  $('sb-plot-panel').hidden = true;
  $('sb-view-panel').hidden = true;
  basisItems.length = 0;
  $('sb-basis-legend').replaceChildren();
  $('sb-basis-panel').hidden = true;
  plot2d.redraw();
}

/** Run ↔ Stop: while code runs, Run is disabled and says so, and Stop is shown (focus follows the button). */
function showRunning(on) {
  const focused = document.activeElement;
  runButton.disabled = on || !ready;
  runButton.textContent = on ? 'Running…' : 'Run';
  stopButton.hidden = !on;
  stopButton.disabled = !on;
  if (on && focused === runButton) stopButton.focus();
  if (!on && focused === stopButton) runButton.focus();
}

/** Runs the code in the worker; resolves when it has finished, failed, been stopped or hit the time limit. */
async function run() {
  if (!ready || running) return;
  running = true;
  const id = ++runCount;
  clearAll();
  plot2d.setOptions({ equal: true });
  document.body.dataset.run = 'running';
  showRunning(true);
  status.textContent = 'Starting…';
  try {
    await runner.ready; // a fresh worker after a Stop may still be starting
  } catch (e) {
    running = false;
    showRunning(false);
    status.textContent = `The sandbox's worker did not start: ${e.message}`;
    document.body.dataset.run = 'error';
    document.body.dataset.runs = String(id);
    return;
  }
  await new Promise((resolve) => {
    current = { id, t0: performance.now(), resolve, failed: null, timer: setTimeout(() => finish('limit'), limitMs) };
    status.textContent = `Running… (Stop ends it; it stops by itself after ${limitMs / 1000} s)`;
    runner.run(id, editor.value);
  });
}

/** Ends the current run: 'ok' | 'error' (with the worker's error) | 'stopped' (Stop) | 'limit' (time limit). */
function finish(outcome, error) {
  const c = current;
  if (!c) return;
  current = null;
  clearTimeout(c.timer);
  const secs = ((performance.now() - c.t0) / 1000).toFixed(1);
  if (outcome === 'ok') status.textContent = `Ran in ${Math.max(1, Math.round(performance.now() - c.t0))} ms.`;
  else if (outcome === 'error') { showError(error); status.textContent = 'The code stopped with an error.'; }
  else {
    // the worker may be in an endless loop: end it, and start a fresh one for the next Run; what it posted and the
    // page has not drawn yet is dropped
    restartWorker();
    queue.length = 0;
    queueAt = 0;
    showNote(outcome === 'limit'
      ? `Stopped: the code was still running after ${limitMs / 1000} s, the time limit. A loop that never ends (while (true) …) is the usual cause. What it drew and printed before is kept.`
      : `Stopped after ${secs} s: you pressed Stop. What the code drew and printed before is kept.`, outcome);
    status.textContent = outcome === 'limit' ? `Stopped at the time limit (${limitMs / 1000} s).` : 'Stopped.';
  }
  running = false;
  lastOutcome = outcome;
  showRunning(false);
  document.body.dataset.run = outcome;
  document.body.dataset.runs = String(c.id);
  c.resolve();
}

function stop() { if (current) finish('stopped'); }
stopButton.addEventListener('click', stop);

/** A fresh worker (a Run meanwhile waits for it; values the code kept in globalThis are gone with the old one). */
function restartWorker() {
  runner.restart().catch((e) => { status.textContent = `The sandbox's worker did not start again: ${e.message}`; });
}

/** A message about the end of a run that is not an error of the code (Stop, time limit): in the alert box. */
function showNote(text, kind) {
  const box = $('sb-error');
  box.hidden = false;
  box.dataset.kind = kind;
  box.dataset.line = '';
  delete box.dataset.field;
  box.textContent = text;
}

/** Shows the worker's error { name, message, field, kind, line } under its line of the code. */
function showError(err) {
  const lines = editor.value.split('\n').length;
  const line = Number.isInteger(err.line) && err.line >= 1 && err.line <= lines ? err.line : 0;
  const facts = err.field ? ` (field ${err.field}, ${err.kind || 'error'})` : '';
  const name = str(err.name) || 'Error';
  const message = `${name === 'Error' ? '' : `${name}: `}${str(err.message)}${facts}`;
  editor.showError(line, line ? `Line ${line}: ${message}` : message);
  const box = $('sb-error');
  box.hidden = false;
  box.dataset.kind = 'error';
  box.dataset.line = String(line || '');
  if (err.field) box.dataset.field = err.field; else delete box.dataset.field;
  box.textContent = line ? `Error on line ${line}: ${message}` : `Error: ${message}`;
}

// ---------------------------------------------------------------- examples, link, share

const select = $('sb-examples');
select.append(h('option', { value: '' }, 'Choose an example…'), ...EXAMPLES.map((ex) => h('option', { value: ex.id }, exampleLabel(ex))));
select.addEventListener('change', () => {
  const ex = EXAMPLES.find((x) => x.id === select.value);
  if (!ex) return;
  editor.setValue(ex.code);
  $('sb-link-note').hidden = true;
  status.textContent = ready ? 'Example loaded: press Run.' : status.textContent;
});

function linkOf(code) {
  const u = new URL(location.href);
  u.hash = `code=${encodeCode(code)}`;
  return u.href;
}
let hashTimer = 0;
editor.onInput((code) => {
  if (select.value && EXAMPLES.find((x) => x.id === select.value)?.code !== code) select.value = '';
  clearTimeout(hashTimer);
  hashTimer = setTimeout(() => { history.replaceState(null, '', `#code=${encodeCode(code)}`); }, 300);
  $('sb-share-row').hidden = true;
});
editor.onRun(run);
runButton.addEventListener('click', run);

$('sb-share').addEventListener('click', async () => {
  const link = linkOf(editor.value);
  history.replaceState(null, '', new URL(link).hash);
  const field = $('sb-link');
  field.value = link;
  $('sb-share-row').hidden = false;
  let copied = false;
  try { await navigator.clipboard.writeText(link); copied = true; } catch { /* not allowed here: select the field */ }
  if (!copied) { field.focus(); field.select(); }
  status.textContent = copied ? 'Link copied.' : 'Link ready: copy it from the field.';
});

/** The code of the link, shown (never run); false when the link has none or it cannot be read. */
function fromLink() {
  try {
    const code = codeFromHash(location.hash);
    if (code == null) return false;
    editor.setValue(code);
    select.value = '';
    $('sb-link-note').hidden = false;
    return true;
  } catch (e) {
    editor.setValue(EXAMPLES[0].code);
    $('sb-error').hidden = false;
    $('sb-error').textContent = `The link's code could not be read (${e.message}); here is an example instead.`;
    return true;
  }
}
window.addEventListener('hashchange', () => {
  // a link pasted into this tab: show its code, do not run it
  const code = (() => { try { return codeFromHash(location.hash); } catch { return null; } })();
  if (code != null && code !== editor.value) fromLink();
});
if (!fromLink()) {
  editor.setValue(EXAMPLES[0].code);
  select.value = EXAMPLES[0].id;
  history.replaceState(null, '', location.pathname + location.search);
}
$('sb-plot-panel').hidden = true;
$('sb-view-panel').hidden = true;

// ---------------------------------------------------------------- start

try {
  const { version } = await runner.started;
  ready = true;
  runButton.disabled = false;
  status.textContent = `SplineLab ${version} loaded. Press Run (or Ctrl+Enter).`;
  document.documentElement.dataset.ready = 'true';
} catch (e) {
  status.textContent = `The module did not load: ${e.message}`;
  document.documentElement.dataset.ready = 'error';
}
// tests and devtools
window.splinelabSandbox = {
  run, stop, editor, plot: plot2d, get view() { return view; }, items, runner,
  get limitMs() { return limitMs; }, set limitMs(ms) { limitMs = ms; },
};
