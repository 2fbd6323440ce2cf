// Shared helpers of the browser benchmarks (interaction.mjs, start.mjs): a static server for www/, headless
// Chromium, and an init script that times the wasm module's exports and the page's animation-frame callbacks
// without touching www/.
import { chromium } from 'playwright-core';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { cpus, loadavg } from 'node:os';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { serve } from '../scripts/static-server.mjs';

export const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..');
export const WWW = join(ROOT, 'www');
export const CHROMIUM_ARGS = [
  '--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking',
  '--disable-component-update', '--disable-sync', '--disable-quic',
];

/** Serves www/ (WWW_DIR=dist/site: another folder, e.g. the built site) on 127.0.0.1 (PORT=8109 to pick the port;
 * a free one by default). */
export async function startServer(port = Number(process.env.PORT || 0)) {
  const server = await serve(process.env.WWW_DIR || WWW, port, '127.0.0.1');
  const base = `http://127.0.0.1:${server.address().port}/`;
  return { base, close: () => new Promise((ok) => { server.closeAllConnections?.(); server.close(() => ok()); }) };
}

export async function launch() {
  return chromium.launch({ executablePath: process.env.CHROMIUM || '/usr/bin/chromium', headless: true, args: CHROMIUM_ARGS });
}

/**
 * Init script (runs before the page's scripts): wraps WebAssembly.instantiate / instantiateStreaming so that
 * every exported function of the instance is timed (outermost calls only; wasm-bindgen's glue calls them),
 * wraps requestAnimationFrame so the time inside frame callbacks is summed, and patches View3D (www/lib/view3d.js)
 * so that the benchmark can find the 3D views of a page. Totals live in `window.__perf`.
 */
export function initScript() {
  const P = (window.__perf = { byName: {}, wasmMs: 0, wasmCalls: 0, rafMs: 0, instantiateMs: 0, instantiatedAt: 0, views: [], marks: {} });
  let depth = 0;
  const wrapExports = (exports) => {
    const out = {};
    for (const [k, v] of Object.entries(exports)) {
      out[k] = typeof v !== 'function' ? v : function (...args) {
        if (depth++ > 0) { try { return v.apply(this, args); } finally { depth--; } }
        const t0 = performance.now();
        try { return v.apply(this, args); } finally { depth--; const dt = performance.now() - t0; P.wasmMs += dt; P.wasmCalls++; P.byName[k] = (P.byName[k] || 0) + dt; }
      };
    }
    return out;
  };
  const wrapResult = (r) => {
    P.instantiatedAt = performance.now();
    // an Instance (instantiate(module, imports): the shell compiles the module while it streams in) stays an Instance
    if (r instanceof WebAssembly.Instance) return Object.defineProperty(Object.create(WebAssembly.Instance.prototype), 'exports', { value: wrapExports(r.exports) });
    return { module: r.module, instance: { exports: wrapExports(r.instance.exports) } };
  };
  const inst = WebAssembly.instantiate, stream = WebAssembly.instantiateStreaming;
  WebAssembly.instantiate = async function (...a) { const t0 = performance.now(); P.instantiateStart = P.instantiateStart || t0; const r = await inst.apply(this, a); P.instantiateMs += performance.now() - t0; return wrapResult(r); };
  if (stream) WebAssembly.instantiateStreaming = async function (...a) { const t0 = performance.now(); P.instantiateStart = P.instantiateStart || t0; const r = await stream.apply(this, a); P.instantiateMs += performance.now() - t0; return wrapResult(r); };
  const raf = window.requestAnimationFrame.bind(window);
  window.requestAnimationFrame = (cb) => raf((ts) => {
    if (cb.__bench) return cb(ts);
    const t0 = performance.now();
    try { return cb(ts); } finally { P.rafMs += performance.now() - t0; }
  });
  // readiness marks (start.mjs): when the shell says ready, when the demo is mounted, then the next frame
  const mark = (name) => { if (!P.marks[name]) P.marks[name] = performance.now(); };
  const check = () => {
    const html = document.documentElement;
    if (html.dataset.ready === 'true') mark('ready');
    const root = document.getElementById('demo-root');
    if (root && root.dataset.mounted === 'true' && !P.marks.mounted) {
      mark('mounted');
      const f = () => { mark('mountedFrame'); }; f.__bench = true;
      // two frames: the demo's first paint runs in the first frame after mounting
      const g = () => raf(f); g.__bench = true; raf(g);
    }
    if (P.marks.ready && !P.readyFrameAsked) { P.readyFrameAsked = true; const f = () => mark('readyFrame'); f.__bench = true; const g = () => raf(f); g.__bench = true; raf(g); }
  };
  new MutationObserver(check).observe(document, { subtree: true, attributes: true, attributeFilter: ['data-ready', 'data-mounted'] });
  document.addEventListener('DOMContentLoaded', check);
  // find the 3D views: patch the class once the module is loaded by the app
  const patch = () => import('/lib/view3d.js').then((m) => {
    const C = m.View3D || m.default;
    if (!C || C.prototype.__benchPatched) return;
    C.prototype.__benchPatched = true;
    const render = C.prototype.renderNow;
    C.prototype.renderNow = function (...a) { if (!P.views.includes(this)) P.views.push(this); return render.apply(this, a); };
  }).catch(() => {});
  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', patch); else patch();
}

export function machine() {
  let lscpu = '';
  try { lscpu = execFileSync('lscpu', { encoding: 'utf8' }).split('\n').filter((l) => /Model name|^CPU\(s\)|Thread|MHz/.test(l)).map((l) => l.replace(/\s+/g, ' ')).join('; '); } catch { /* */ }
  let chromium = '';
  try { chromium = execFileSync(process.env.CHROMIUM || '/usr/bin/chromium', ['--version'], { encoding: 'utf8' }).trim(); } catch { /* */ }
  return { date: new Date().toISOString(), cpus: cpus().length, load: loadavg().map((x) => x.toFixed(2)).join(' '), lscpu, chromium, node: process.version };
}

export const pct = (xs, q) => { const s = [...xs].sort((a, b) => a - b); return s.length ? s[Math.min(s.length - 1, Math.floor(q * s.length))] : NaN; };
export const median = (xs) => pct(xs, 0.5);
export const demoIds = async () => (await import(join(WWW, 'demos/index.js'))).DEMO_IDS;
export const demoExists = (id) => { try { readFileSync(join(WWW, 'demos', `${id}.js`)); return true; } catch { return false; } };
