// The page's side of the sandbox's isolation (sandbox.html): the visitor's code never runs in the page. It runs in a
// Web Worker (www/sandbox-worker.js) started by an opaque-origin iframe (www/sandbox-frame.html, sandbox=
// "allow-scripts"), so it cannot read the site's storage or cookies, touch the page, or navigate it, and an endless
// loop freezes only that worker, which Stop (or the time limit) ends and replaces.
//
// The page fetches what the opaque-origin frame could not (no CORS for it): the wasm bytes and the worker's module
// sources (sandbox-worker.js and the modules it imports, found by following its relative static imports; in the
// deployment build, one self-contained file). It hands them to the frame once; for each worker it creates a
// MessageChannel whose other end the frame gives the worker, so page and worker talk directly.
//
//   const runner = createRunner(iframe, { onMessage(msg) {…} });   // <iframe sandbox="allow-scripts" src="sandbox-frame.html">
//   await runner.started;          // the first worker answered 'ready' (rejects if the module did not load)
//   runner.run(id, code);          // results arrive at onMessage as { type: 'op' | 'done' | 'error' | 'stray', id, … }
//   runner.restart();              // ends the worker (even in an endless loop) and starts a fresh one
//   await runner.ready;            // the current worker is ready: { version }

const WORKER_ENTRY = 'sandbox-worker.js';
const WASM = 'pkg/splinelab_bg.wasm';
const START_TIMEOUT_MS = 30000;

/** The relative static imports of a module's source (as build-site.mjs reads them). */
function staticImports(src) {
  return [...src.matchAll(/^\s*(?:import|export)\s+(?:[^'"]*?\sfrom\s+)?['"](\.[^'"]+)['"]/gm)].map((m) => m[1]);
}

async function fetchOk(url, as) {
  const r = await fetch(url);
  if (!r.ok) throw new Error(`${url.pathname ?? url}: HTTP ${r.status}`);
  return as === 'bytes' ? r.arrayBuffer() : r.text();
}

/** The worker's module sources: { entry, files: { 'sandbox-worker.js': text, 'lib/…': text, 'pkg/…': text } }. */
async function workerFiles(base) {
  const files = {};
  const visit = async (path) => {
    if (path in files) return;
    files[path] = '';
    const src = await fetchOk(new URL(path, base), 'text');
    files[path] = src;
    await Promise.all(staticImports(src).map((spec) => visit(new URL(spec, new URL(path, base)).href.slice(base.length))));
  };
  await visit(WORKER_ENTRY);
  return { entry: WORKER_ENTRY, files };
}

/** Starts the first worker in the runner frame `frame` (in sandbox.html, so that it loads with the page). */
export function createRunner(frame, { onMessage }) {
  // the site's root (sandbox.html sits there, and so does the built page)
  const base = new URL('./', location.href).href;
  // the frame announces itself when it has loaded, and answers a ping if it loaded before this listener
  const frameReady = new Promise((resolve) => {
    const onReady = (e) => {
      if (e.source !== frame.contentWindow || e.data?.type !== 'sandbox:frame-ready') return;
      window.removeEventListener('message', onReady);
      resolve();
    };
    window.addEventListener('message', onReady);
    frame.contentWindow.postMessage({ type: 'sandbox:ping' }, '*');
  });

  let port = null;
  let ready = null;
  const runner = { frame, ready: null, started: null, run, restart };

  /** A new MessageChannel; the frame ends the current worker and gives a fresh one the other end. */
  function restart() {
    if (port) port.close();
    const channel = new MessageChannel();
    port = channel.port1;
    let settle;
    ready = new Promise((resolve, reject) => { settle = { resolve, reject }; });
    const timer = setTimeout(() => settle.reject(new Error('the sandbox\'s worker did not start')), START_TIMEOUT_MS);
    port.onmessage = (e) => {
      const d = e.data;
      if (!d || typeof d !== 'object') return;
      if (d.type === 'ready') { clearTimeout(timer); settle.resolve({ version: String(d.version) }); return; }
      if (d.type === 'failed') { clearTimeout(timer); settle.reject(new Error(String(d.message))); }
      onMessage(d);
    };
    frame.contentWindow.postMessage({ type: 'sandbox:worker' }, '*', [channel.port2]);
    runner.ready = ready;
    ready.catch(() => {}); // reported where it is awaited
    return ready;
  }

  function run(id, code) { port.postMessage({ type: 'run', id, code }); }

  // '*': the frame's origin is opaque, so it cannot be named; the frame is the page's own element. The wasm goes
  // first (it compiles there while the worker's sources still load).
  const post = (msg, transfer) => frame.contentWindow.postMessage(msg, '*', transfer);
  const wasmSent = Promise.all([fetchOk(new URL(WASM, base), 'bytes'), frameReady]).then(([wasm]) => post({ type: 'sandbox:wasm', wasm }, [wasm]));
  const sourcesSent = Promise.all([workerFiles(base), frameReady]).then(([{ entry, files }]) => post({ type: 'sandbox:sources', entry, files }));
  runner.started = Promise.all([wasmSent, sourcesSent]).then(() => restart());
  return runner;
}
