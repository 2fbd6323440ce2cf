// The sandbox's runner host (sandbox-frame.html, a classic script): it lives in an opaque-origin iframe
// (sandbox="allow-scripts", no allow-same-origin) of sandbox.html and starts the Web Worker in which the visitor's
// code runs. It touches no code itself: the page hands it (postMessage) the wasm bytes and the worker's module
// sources, which it could not fetch (an opaque origin has no CORS access to the site); it compiles the wasm once,
// as soon as the bytes arrive, and gives each worker the compiled module and a MessagePort to the page, over which
// the page and the worker talk directly. A new `sandbox:worker` message ends the current worker (Stop, time limit) and starts a fresh one.
'use strict';

(() => {
  // Run only as the sandbox's opaque-origin frame: opened on its own or framed without the sandbox attribute this
  // document would have the site's origin, and a worker of it could reach the site's storage.
  const SITE = new URL(location.href).origin;
  if (self.origin !== 'null' || window.parent === window) return;

  /**
   * The worker's bootstrap (stringified into a blob: it runs in the worker, not here). It links the module
   * sources it is given (each relative import specifier rewritten to the blob: URL of that module), imports the
   * entry and calls its start({ module, port }).
   */
  function boot() {
    self.onmessage = async (e) => {
      self.onmessage = null;
      const { module, files, entry, port } = e.data;
      try {
        const urls = new Map();
        const link = (path) => {
          if (urls.has(path)) return urls.get(path);
          if (typeof files[path] !== 'string') throw new Error(`the sandbox's module ${path} was not handed over`);
          const src = files[path].replace(/^(\s*(?:import|export)\s+(?:[^'"]*?\sfrom\s+)?)(['"])(\.[^'"]+)\2/gm,
            (m, head, q, spec) => head + q + link(new URL(spec, `https://x/${path}`).pathname.slice(1)) + q);
          const url = URL.createObjectURL(new Blob([src], { type: 'text/javascript' }));
          urls.set(path, url);
          return url;
        };
        const runtime = await import(link(entry));
        await runtime.start({ module, port });
      } catch (err) {
        port.postMessage({ type: 'failed', message: String((err && err.message) || err) });
      }
    };
  }
  const BOOT_URL = URL.createObjectURL(new Blob([`(${boot})();\n`], { type: 'text/javascript' }));

  // what the page hands over, each as soon as it has it (the wasm compiles while the sources still load)
  let compiled = null; // Promise of the WebAssembly.Module
  let giveSources = null;
  const sources = new Promise((resolve) => { giveSources = resolve; }); // Promise of { files, entry }
  let worker = null;
  let starts = 0; // the latest start wins (a Stop while a worker is still being set up)

  /** Ends the current worker (if any) and starts a fresh one talking to the page over `port`. */
  async function startWorker(port) {
    if (worker) worker.terminate();
    worker = null;
    const start = ++starts;
    let s;
    try {
      if (!compiled) throw new Error('no wasm was handed over');
      const [module, { files, entry }] = await Promise.all([compiled, sources]);
      s = { module, files, entry };
    } catch (err) {
      port.postMessage({ type: 'failed', message: `the module did not compile: ${err.message}` });
      return;
    }
    if (start !== starts) return;
    const w = new Worker(BOOT_URL);
    worker = w;
    // an error the worker did not handle itself (its runtime reports the visitor's errors over the port)
    w.onerror = (ev) => { ev.preventDefault(); port.postMessage({ type: 'failed', message: ev.message || 'the worker stopped' }); };
    w.postMessage({ module: s.module, files: s.files, entry: s.entry, port }, [port]);
  }

  window.addEventListener('message', (e) => {
    if (e.source !== window.parent || e.origin !== SITE) return;
    const d = e.data || {};
    if (d.type === 'sandbox:ping') {
      window.parent.postMessage({ type: 'sandbox:frame-ready' }, SITE);
    } else if (d.type === 'sandbox:wasm' && d.wasm instanceof ArrayBuffer) {
      compiled = WebAssembly.compile(d.wasm);
      compiled.catch(() => {}); // reported to the worker's port
    } else if (d.type === 'sandbox:sources' && d.files && typeof d.entry === 'string') {
      giveSources({ files: d.files, entry: d.entry });
    } else if (d.type === 'sandbox:worker' && e.ports[0]) {
      startWorker(e.ports[0]);
    }
  });
  // the page may have started listening before or after this document loaded: it also asks (sandbox:ping)
  window.parent.postMessage({ type: 'sandbox:frame-ready' }, SITE);
})();
