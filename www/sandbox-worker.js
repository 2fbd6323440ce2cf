// The sandbox's worker runtime: the visitor's code runs HERE, in a Web Worker started by the opaque-origin frame
// sandbox-frame.html, never in the page (sandbox.html). It has the complete wasm module (`sl`) and the helpers
// plot / surface / print, which turn their arguments into plain data (typed arrays copied and transferred) and
// post them over a MessagePort to the page, which draws with its plot2d / View3D code. The worker sees neither the
// page's DOM nor its storage: localStorage, document and cookies do not exist in a worker, and its origin is
// opaque (indexedDB and caches refuse it); it cannot navigate the page, and the frame's CSP lets it fetch nothing.
//
// Protocol (port): page → worker { type: 'run', id, code };
//   worker → page { type: 'ready', version } | { type: 'op', id, line, op, … } (one per drawing or printed line)
//   | { type: 'done', id, ms } | { type: 'error', id, error: { name, message, field, kind, line } }
//   | { type: 'stray', id, error } (an error thrown after the run, e.g. in a timer) | { type: 'failed', message }.
// The code runs as the body of `async function (sl, plot, surface, print)` in strict mode, loaded with
// importScripts from a blob: URL, so that a stack (and a syntax error's event) names the line of the code.

import init, * as sl from './pkg/splinelab.js';
import { formatValue, meshOf, drawKind, codeLocation } from './lib/sandbox-format.js';

const WRAPPER_LINES = 1; // the line before the visitor's code in the script (see run())
/** @type {any} */ (Error).stackTraceLimit = Math.max(/** @type {any} */ (Error).stackTraceLimit || 10, 100); // wasm frames must not push the code's frame out

/** What one run may post to the page: beyond it the code keeps running, but the page is sent nothing more than one
 * note (a `while (true) print(…)` must not flood the page with messages it has to draw). */
export const LIMITS = { prints: 5000, drawings: 2000, bytes: 64 * 1024 * 1024 };

let port = null;
let lastRun = null; // { id, url } of the latest run (stray errors are reported against it)

/** Called by the frame's bootstrap: instantiates the wasm module and answers runs on `port`. */
export async function start({ module, port: p }) {
  port = p;
  await init({ module_or_path: module });
  port.onmessage = (e) => {
    const d = e.data;
    if (d && d.type === 'run' && Number.isInteger(d.id)) run(d.id, String(d.code ?? ''));
  };
  self.addEventListener('error', (ev) => {
    if (loading) return; // a syntax error while loading the code: load() reports it
    ev.preventDefault();
    if (lastRun) port.postMessage({ type: 'stray', id: lastRun.id, error: describe(ev.error ?? new Error(ev.message), lastRun.url) });
  });
  self.addEventListener('unhandledrejection', (ev) => {
    ev.preventDefault();
    if (lastRun) port.postMessage({ type: 'stray', id: lastRun.id, error: describe(ev.reason, lastRun.url) });
  });
  port.postMessage({ type: 'ready', version: sl.version() });
}

// ---------------------------------------------------------------- loading and running the code

const pending = new Map();
self.__splinelabSandbox = (id, fn) => { const f = pending.get(id); if (f) f(fn); };
let loading = false;

/**
 * Loads the code's script from `url`: resolves to its async function, or rejects with the syntax error, its
 * line taken from the error event (importScripts' own exception does not say where the parse failed).
 */
function load(url, id) {
  return new Promise((resolve, reject) => {
    let fn = null, event = null;
    pending.set(id, (f) => { fn = f; });
    const onError = (ev) => { ev.preventDefault(); event = ev; };
    self.addEventListener('error', onError);
    // uncaught on purpose: a syntax error then fires the error event that names its line
    setTimeout(() => { loading = true; importScripts(url); }, 0);
    setTimeout(() => {
      loading = false;
      self.removeEventListener('error', onError);
      pending.delete(id);
      if (fn) { resolve(fn); return; }
      const e = event && event.error instanceof Error ? event.error : new SyntaxError(event ? event.message : 'the code did not compile');
      e.message = String(e.message).replace(/^(?:Uncaught \w*Error: )?Failed to execute 'importScripts' on 'WorkerGlobalScope': /, '');
      if (event && event.filename === url && event.lineno) e.sandboxLine = event.lineno - WRAPPER_LINES;
      else if (e.fileName === url && e.lineNumber) e.sandboxLine = e.lineNumber - WRAPPER_LINES; // Firefox
      reject(e);
    }, 0);
  });
}

async function run(id, code) {
  // the code sits in a block of its own inside the function, so it may declare its own `surface`, `plot`, … (the
  // docs' examples name a knot-modification surface `surface`), shadowing the helpers as a nested scope does
  const src = `self.__splinelabSandbox(${id}, async function (sl, plot, surface, print) {'use strict'; {\n${code}\n}});\n`;
  const url = URL.createObjectURL(new Blob([src], { type: 'text/javascript' }));
  lastRun = { id, url };
  const api = helpers(id, url);
  const t0 = performance.now();
  try {
    const f = await load(url, id);
    const value = await f(sl, api.plot, api.surface, api.print);
    if (value !== undefined) {
      api.send({ op: 'result', text: formatValue(value, 3) });
      api.drawReturned(value);
    }
    port.postMessage({ type: 'done', id, ms: performance.now() - t0 });
  } catch (e) {
    port.postMessage({ type: 'error', id, error: describe(e, url) });
  } finally {
    URL.revokeObjectURL(url);
  }
}

/** What the page shows of an error: name, message, the API's field and kind, the line in the visitor's code. */
function describe(e, url) {
  /** @type {Error & { sandboxLine?: number, field?: string, kind?: string }} */
  const err = e instanceof Error ? e : new Error(String(e));
  const loc = Number.isInteger(err.sandboxLine) ? { line: err.sandboxLine } : codeLocation(err.stack, url, WRAPPER_LINES);
  return {
    name: String(err.name || 'Error'),
    message: String(err.message),
    field: err.field != null ? String(err.field) : '',
    kind: err.kind != null ? String(err.kind) : '',
    line: loc ? loc.line : 0,
  };
}

// ---------------------------------------------------------------- plain data for the page

/**
 * A structured-clone-safe copy of a value: numbers, strings, booleans, arrays and plain objects as they are
 * (functions dropped), typed arrays copied (the visitor's own arrays stay usable) with their buffers listed in
 * `acc.transfer`; `acc.bytes` counts what is sent (about 8 bytes per array entry); nesting is bounded.
 */
/** @param {any} v */
function pack(v, acc, depth = 0) {
  if (v === null || v === undefined) return v;
  if (typeof v === 'function' || typeof v === 'symbol') return undefined;
  if (typeof v === 'string') { acc.bytes += 2 * v.length; return v; }
  if (typeof v !== 'object') return v;
  if (ArrayBuffer.isView(v)) {
    if (v instanceof DataView) return undefined;
    const copy = /** @type {Float64Array} */ (v).slice();
    acc.transfer.push(copy.buffer);
    acc.bytes += copy.byteLength;
    return copy;
  }
  if (depth > 8) return undefined;
  if (Array.isArray(v)) { acc.bytes += 8 * v.length; return v.map((x) => pack(x, acc, depth + 1)); }
  const out = {};
  for (const [k, x] of Object.entries(v)) {
    const p = pack(x, acc, depth + 1);
    if (p !== undefined) out[k] = p;
  }
  return out;
}

function fieldError(field, msg) {
  const e = /** @type {Error & { field?: string, kind?: string }} */ (new Error(`${field}: ${msg}`));
  e.field = field;
  e.kind = 'wrong-type';
  return e;
}

/** Points of a value: a result with `points` (flat, `dim`), a flat array, or [[x, y], …]. @param {any} v */
function pointsOf(v, what) {
  if (v == null) throw fieldError(what, 'expected points: a result with points, a flat array or [[x, y], …]');
  if (Array.isArray(v) || ArrayBuffer.isView(v)) return { data: v, stride: ArrayBuffer.isView(v) && /** @type {any} */ (v).dim ? /** @type {any} */ (v).dim : 2 };
  if (v.points != null) return { data: v.points, stride: v.dim || 2 };
  if (v.positions != null) return { data: v.positions, stride: 3 };
  throw fieldError(what, 'expected points: a result with points, a flat array or [[x, y], …]');
}

// ---------------------------------------------------------------- plot, surface, print (one set per run)

/** The helpers of run `id` (code loaded from `url`): each call posts one drawing operation to the page. */
function helpers(id, url) {
  const drawn = new WeakSet(); // values plot()/surface() drew (a returned one is not drawn twice)
  const sent = { prints: 0, drawings: 0, bytes: 0, cut: false };
  /** Posts { op, … } with the line of the visitor's code that called (the page names it if drawing fails); past
   * LIMITS, one { op: 'cut' } and then nothing. */
  const send = (msg) => {
    if (sent.cut) return;
    const isPrint = msg.op === 'print' || msg.op === 'result';
    const acc = { transfer: [], bytes: 0 };
    const data = pack(msg, acc);
    if (isPrint) sent.prints++; else sent.drawings++;
    sent.bytes += acc.bytes;
    if (sent.prints > LIMITS.prints || sent.drawings > LIMITS.drawings || sent.bytes > LIMITS.bytes) {
      sent.cut = true;
      port.postMessage({ type: 'op', id, line: 0, op: 'cut', limits: { ...LIMITS, bytes: LIMITS.bytes / 1024 / 1024 } });
      return;
    }
    const loc = codeLocation(new Error().stack, url, WRAPPER_LINES);
    port.postMessage({ type: 'op', id, line: loc ? loc.line : 0, ...data }, acc.transfer);
  };

  /** plot(value, { label, color, width, dash, close }): curves (any result with points), knot paths; basis rows
   * (a result with `values` and `params`) go to the basis plot (plot.basis). */
  function plot(v, opts = {}) {
    if (v && typeof v === 'object') drawn.add(v);
    if (v && typeof v === 'object' && !Array.isArray(v) && !ArrayBuffer.isView(v)) {
      if (meshOf(v)) throw fieldError('plot', 'this is a surface: draw it with surface(…) (a result computed with mesh: true)');
      if (Array.isArray(v.paths)) {
        send({ op: 'paths', paths: v.paths.map((p) => ({ data: p, stride: p.dim || v.dim || 2 })), opts });
        return;
      }
      if (v.points == null && v.values != null && v.params != null) { plot.basis(v, opts); return; }
    }
    const { data, stride } = pointsOf(v, 'plot');
    send({ op: 'line', data, stride, opts });
  }
  /** plot.points(points, { label, color, radius }) */
  plot.points = (v, opts = {}) => { const { data, stride } = pointsOf(v, 'plot.points'); send({ op: 'points', data, stride, opts }); };
  /** plot.polygon(points): a dashed grey control polygon. */
  plot.polygon = (v, opts = {}) => { const { data, stride } = pointsOf(v, 'plot.polygon'); send({ op: 'polygon', data, stride, opts }); };
  /** plot.basis(result, { y0 = 0, scale = 1, label }): the rows of a basis result ({ values, params, count? }) in
   * the basis plot (its own axes: u across, the function's value up). */
  plot.basis = (b, opts = {}) => {
    if (!b || b.values == null || b.params == null) throw fieldError('plot.basis', 'expected a basis result { values, params, count }');
    send({ op: 'basis', values: b.values, params: b.params, count: b.count, opts });
  };
  plot.clear = () => send({ op: 'clear' });
  /** plot.equal(false): independent x and y scales (graphs of functions); true (the default): same scale. */
  plot.equal = (on = true) => send({ op: 'equal', on: !!on });

  /** surface(value, { color, opacity, wireframe, colors, label }): a surface result computed with `mesh: true`,
   * a mesh { positions, indices, normals? }, or a networkSurfaces result (each of its surfaces). */
  function surface(v, opts = {}) {
    if (v && v.surfaces && typeof v.surfaces === 'object' && !meshOf(v)) {
      Object.entries(v.surfaces).forEach(([name, s], i) => surface(s, { opacity: i ? 0.6 : 1, ...opts, label: opts.label ? `${opts.label} ${name}` : name }));
      return;
    }
    const m = meshOf(v);
    if (v && typeof v === 'object') drawn.add(v);
    if (!m) throw fieldError('surface', 'expected a surface result computed with mesh: true (or a mesh { positions, indices })');
    const mesh = { positions: m.positions, indices: m.indices, normals: m.normals, nu: m.nu, nv: m.nv };
    send({ op: 'mesh', mesh, opts });
  }
  /** surface.lines(polylines, { color, width }): flat xyz arrays or [[x, y, z], …] per polyline. */
  surface.lines = (lines, opts = {}) => send({ op: 'lines', lines, opts });
  /** surface.points(points, { color, size }): flat xyz or [[x, y, z], …]. */
  surface.points = (pts, opts = {}) => send({ op: 'points3d', points: pts, opts });
  /** surface.network(network, { samples = 40 }): the curves of a curve network (sampled by the module). */
  surface.network = (network, opts = {}) => {
    const { curves } = sl.networkSurfaces({ network, surfaces: ['G'], samplesU: 2, samplesV: 2, normSamples: 0, curveSamples: opts.samples || 40 });
    surface.lines([...curves.phi, ...curves.psi], { color: opts.color || '#222222', width: opts.width || 2.5 });
  };
  surface.clear = () => send({ op: 'clear3d' });

  function print(...args) {
    send({ op: 'print', text: args.map((a) => formatValue(a)).join(' ') });
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

  return { plot, surface, print, drawReturned, send };
}
