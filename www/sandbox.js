// The SplineLab sandbox (sandbox.html): the visitor's JavaScript runs against the wasm module as the body of
//   async function (sl, plot, surface, print) { … }
// only when they press Run (or Ctrl/Cmd+Enter) — never on load, not even from a link `sandbox.html#code=<base64url>`.
// The code runs as a module script made from a Blob, so an error's stack names the exact line; errors of the API
// (`.field`, `.kind`) are shown under that line. A returned value is printed and drawn: results with `points` (or
// `paths`, or basis `values`) on the 2D plot, meshes (`mesh`, or `positions` + `indices`) in the 3D view; for a
// returned plain object (a "Copy as code" snippet's `return { … }`), each drawable entry is drawn.

import init, * as sl from './pkg/splinelab.js';
import { h } from './lib/dom.js';
import { createPlot, PALETTE, SERIES } from './lib/plot2d.js';
import { View3D } from './lib/view3d.js';
import { EXAMPLES, exampleLabel } from './lib/sandbox-examples.js';
import { createEditor } from './lib/sandbox-editor.js';
import { encodeCode, codeFromHash, formatValue, meshOf, drawKind, codeLocation } from './lib/sandbox-format.js';

const $ = (id) => document.getElementById(id);
const WRAPPER_LINES = 1; // the line before the visitor's code in the module (see run())
Error.stackTraceLimit = Math.max(Error.stackTraceLimit || 10, 100); // wasm frames must not push the code's frame out

const editor = createEditor($('sb-editor'));
const output = $('sb-output');
const status = $('sb-status');
const runButton = $('sb-run');
let ready = false;
let running = false;
let runCount = 0;

// ---------------------------------------------------------------- 2D plot: items drawn in order

const drawn = new WeakSet(); // values plot()/surface() drew (a returned one is not drawn twice)
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

/** Refits and redraws a plot on the next frame, once however many items were added in this frame. */
const fitting = new Set();
function scheduleFit(p) {
  if (fitting.has(p)) return;
  fitting.add(p);
  requestAnimationFrame(() => { fitting.delete(p); p.resize(); p.fitContent(); p.redraw(); });
}

/** Points of a value: a result with `points` (flat, `dim`), a flat array, or [[x, y], …]. */
function pointsOf(v, what) {
  if (v == null) throw fieldError(what, 'expected points: a result with points, a flat array or [[x, y], …]');
  if (Array.isArray(v) || ArrayBuffer.isView(v)) {
    return { data: v, stride: ArrayBuffer.isView(v) && v.dim ? v.dim : 2 };
  }
  if (v.points != null) return { data: v.points, stride: v.dim || (Array.isArray(v.points[0]) ? 2 : 2) };
  if (v.positions != null) return { data: v.positions, stride: 3 };
  throw fieldError(what, 'expected points: a result with points, a flat array or [[x, y], …]');
}

function fieldError(field, msg) {
  const e = new Error(`${field}: ${msg}`);
  e.field = field;
  e.kind = 'wrong-type';
  return e;
}

function addLine(v, opts = {}) {
  const { data, stride } = pointsOf(v, 'plot');
  items.push({ kind: 'line', data, stride, color: opts.color || nextColour(), width: opts.width, dash: opts.dash, close: opts.close, label: opts.label });
}

/** plot(value, { label, color, width, dash, close }): curves (any result with points), knot paths; basis rows
 * (a result with `values` and `params`) go to the basis plot (plot.basis). */
function plot(v, opts = {}) {
  if (v && typeof v === 'object') drawn.add(v);
  if (v && typeof v === 'object' && !Array.isArray(v) && !ArrayBuffer.isView(v)) {
    if (meshOf(v)) throw fieldError('plot', 'this is a surface: draw it with surface(…) (a result computed with mesh: true)');
    if (Array.isArray(v.paths)) {
      const c = opts.color || nextColour();
      v.paths.forEach((p, i) => items.push({ kind: 'line', data: p, stride: p.dim || v.dim || 2, color: c, width: opts.width ?? 1.75, dash: opts.dash, label: i === 0 ? opts.label : '' }));
      return redraw();
    }
    if (v.points == null && v.values != null && v.params != null) return plot.basis(v, opts);
  }
  addLine(v, opts);
  redraw();
}
/** plot.points(points, { label, color, radius }) */
plot.points = (v, opts = {}) => {
  const { data, stride } = pointsOf(v, 'plot.points');
  items.push({ kind: 'points', data, stride, color: opts.color || PALETTE.control, radius: opts.radius, label: opts.label });
  redraw();
};
/** plot.polygon(points): a dashed grey control polygon. */
plot.polygon = (v, opts = {}) => { addLine(v, { color: PALETTE.polygon, width: 1.5, dash: true, ...opts }); redraw(); };
/**
 * plot.basis(result, { y0 = 0, scale = 1, label }): the rows of a basis result ({ values, params, count? }, e.g.
 * bsplineBasis, b2Basis, quasiCubicBasis) as one curve per function over its parameters, in the basis plot (its
 * own axes: u across, the function's value up; y0 and scale shift and stretch a set of rows there).
 */
plot.basis = (b, opts = {}) => {
  if (!b || b.values == null || b.params == null) throw fieldError('plot.basis', 'expected a basis result { values, params, count }');
  const n = b.params.length;
  const count = b.count || (n ? b.values.length / n : 0);
  const y0 = opts.y0 ?? 0, k = opts.scale ?? 1;
  for (let i = 0; i < count; i++) {
    const data = new Float64Array(2 * n);
    for (let r = 0; r < n; r++) { data[2 * r] = b.params[r]; data[2 * r + 1] = y0 + k * b.values[r * count + i]; }
    basisItems.push({ data, stride: 2, color: SERIES[i % SERIES.length], width: 2, label: opts.label && i === 0 ? opts.label : '' });
  }
  redrawBasis();
};
plot.clear = () => { items.length = 0; basisItems.length = 0; colour = 0; redraw(); redrawBasis(); };

function redrawBasis() {
  $('sb-basis-panel').hidden = basisItems.length === 0;
  writeLegend($('sb-basis-legend'), basisItems);
  scheduleFit(basisPlot);
}
/** plot.equal(false): independent x and y scales (graphs of functions); true (the default): same scale. */
plot.equal = (on = true) => { plot2d.setOptions({ equal: !!on }); redraw(); };

function redraw() {
  $('sb-plot-panel').hidden = false;
  writeLegend($('sb-plot-legend'), items);
  scheduleFit(plot2d);
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

/**
 * surface(value, { color, opacity, wireframe, colors, label }): a surface result computed with `mesh: true`, a
 * mesh { positions, indices, normals? }, or a networkSurfaces result (each of its surfaces).
 */
function surface(v, opts = {}) {
  if (v && v.surfaces && typeof v.surfaces === 'object' && !meshOf(v)) {
    Object.entries(v.surfaces).forEach(([name, s], i) => surface(s, { opacity: i ? 0.6 : 1, ...opts, label: opts.label ? `${opts.label} ${name}` : name }));
    return;
  }
  const m = meshOf(v);
  if (v && typeof v === 'object') drawn.add(v);
  if (!m) throw fieldError('surface', 'expected a surface result computed with mesh: true (or a mesh { positions, indices })');
  const id = `mesh-${++meshCount}`;
  view3d().setMesh(id, m, { isolines: m.nu ? true : false, ...opts });
  refit();
}
/** surface.lines(polylines, { color, width }): flat xyz arrays or [[x, y, z], …] per polyline. */
surface.lines = (lines, opts = {}) => { view3d().setLines(`lines-${++meshCount}`, lines, opts); refit(); };
/** surface.points(points, { color, size }): flat xyz or [[x, y, z], …]. */
surface.points = (pts, opts = {}) => { view3d().setPoints(`points-${++meshCount}`, pts, { pickable: false, ...opts }); refit(); };
/** surface.network(network, { samples = 40 }): the curves of a curve network (sampled by the module). */
surface.network = (network, opts = {}) => {
  const { curves } = sl.networkSurfaces({ network, surfaces: ['G'], samplesU: 2, samplesV: 2, normSamples: 0, curveSamples: opts.samples || 40 });
  surface.lines([...curves.phi, ...curves.psi], { color: opts.color || '#222222', width: opts.width || 2.5 });
};
surface.clear = () => { view?.clear(); };

// ---------------------------------------------------------------- print

function print(...args) {
  const text = args.map((a) => formatValue(a)).join(' ');
  output.append(h('span', { class: 'sb-line' }, `${text}\n`));
}

// ---------------------------------------------------------------- running the code

const pending = new Map();
globalThis.__splinelabSandbox = (id, fn) => { const p = pending.get(id); if (p) p.resolve(fn); };

/** Loads the code as a module from a Blob: resolves to the async function, or rejects with a syntax error. */
function load(code, id) {
  // the code sits in a block of its own inside the function, so it may declare its own `surface`, `plot`, … (the
  // docs' examples name a knot-modification surface `surface`), shadowing the helpers as a nested scope does
  const src = `globalThis.__splinelabSandbox(${id}, async function (sl, plot, surface, print) {{\n${code}\n}});\n`;
  const url = URL.createObjectURL(new Blob([src], { type: 'text/javascript' }));
  return {
    url,
    fn: new Promise((resolve, reject) => {
      let settled = false;
      const done = (f) => (x) => { if (!settled) { settled = true; cleanup(); f(x); } };
      const ok = done(resolve), fail = done(reject);
      pending.set(id, { resolve: ok });
      const onError = (ev) => {
        if (ev.filename !== url) return;
        ev.preventDefault();
        const e = ev.error instanceof Error ? ev.error : new SyntaxError(ev.message);
        e.sandboxLine = ev.lineno - WRAPPER_LINES;
        fail(e);
      };
      const script = document.createElement('script');
      function cleanup() { pending.delete(id); window.removeEventListener('error', onError); script.remove(); }
      window.addEventListener('error', onError);
      script.type = 'module';
      script.src = url;
      script.onload = () => setTimeout(() => fail(new SyntaxError('the code did not compile')), 0);
      script.onerror = () => fail(new Error('the code could not be loaded'));
      document.head.append(script);
    }),
  };
}

function clearAll() {
  items.length = 0;
  colour = 0;
  output.replaceChildren();
  view?.clear();
  meshCount = 0;
  editor.clearError();
  $('sb-error').hidden = true;
  $('sb-plot-legend').replaceChildren();
  $('sb-plot-panel').hidden = true;
  $('sb-view-panel').hidden = true;
  basisItems.length = 0;
  $('sb-basis-legend').replaceChildren();
  $('sb-basis-panel').hidden = true;
  plot2d.redraw();
}

/** Draws a returned value: the value itself if drawable, else each drawable entry of a plain object. */
function drawReturned(v) {
  const one = (x, label) => {
    if (x && typeof x === 'object' && drawn.has(x)) return true;
    const k = drawKind(x);
    if (k === 'surface') surface(x, label ? { label } : {});
    else if (k === 'plot') plot(x, label ? { label } : {});
    return !!k;
  };
  if (one(v)) return;
  if (v && typeof v === 'object' && !Array.isArray(v) && !ArrayBuffer.isView(v)) {
    for (const [k, x] of Object.entries(v)) one(x, k);
  }
}

async function run() {
  if (!ready || running) return;
  running = true;
  runButton.disabled = true;
  const id = ++runCount;
  clearAll();
  plot2d.setOptions({ equal: true });
  status.textContent = 'Running…';
  document.body.dataset.run = 'running';
  const code = editor.value;
  const t0 = performance.now();
  const { url, fn } = load(code, id);
  let outcome = 'ok';
  try {
    const f = await fn;
    const value = await f(sl, plot, surface, print);
    if (value !== undefined) {
      output.append(h('span', { class: 'sb-result-label' }, 'Returned:\n'), h('span', { class: 'sb-result' }, `${formatValue(value, 3)}\n`));
      drawReturned(value);
    }
    status.textContent = `Ran in ${Math.max(1, Math.round(performance.now() - t0))} ms.`;
  } catch (e) {
    outcome = 'error';
    showError(e, url);
    status.textContent = 'The code stopped with an error.';
  } finally {
    URL.revokeObjectURL(url);
    running = false;
    runButton.disabled = false;
    document.body.dataset.run = outcome;
    document.body.dataset.runs = String(id);
  }
}

function showError(e, url) {
  const err = e instanceof Error ? e : new Error(String(e));
  const loc = Number.isInteger(err.sandboxLine) ? { line: err.sandboxLine } : codeLocation(err.stack, url, WRAPPER_LINES);
  const lines = editor.value.split('\n').length;
  const line = loc && loc.line >= 1 && loc.line <= lines ? loc.line : 0;
  const facts = err.field ? ` (field ${err.field}, ${err.kind || 'error'})` : '';
  const message = `${err.name === 'Error' ? '' : `${err.name}: `}${err.message}${facts}`;
  editor.showError(line, line ? `Line ${line}: ${message}` : message);
  const box = $('sb-error');
  box.hidden = false;
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
  await init();
  ready = true;
  runButton.disabled = false;
  status.textContent = `SplineLab ${sl.version()} loaded. Press Run (or Ctrl+Enter).`;
  document.documentElement.dataset.ready = 'true';
} catch (e) {
  status.textContent = `The module did not load: ${e.message}`;
  document.documentElement.dataset.ready = 'error';
}
// tests and devtools
window.splinelabSandbox = { run, editor, plot: plot2d, get view() { return view; }, items };
