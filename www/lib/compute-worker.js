// The compute worker (issue 26, "off the main thread"): a module Worker that instantiates one wasm module (a demo's
// group, www/lib/wasm-groups.js, or the complete module) and runs lists of its exports for the page, so heavy calls
// never block the page's main thread. www/lib/compute-client.js starts it and talks to it; nothing else does.
//
// Message in:  { id, glue, wasm, calls: [{ fn, args, optional? }] }   (optional: its error gives null)   glue: the absolute URL of the module's glue; wasm: the
//   page's compiled WebAssembly.Module (so the wasm is fetched and compiled once per page) or its URL
//   The calls run in order; an argument value { $ref: [k, 'key'] } (at any depth) is replaced by
//   results[k].key, so one message can repair a network and then build surfaces through the repaired one.
// Message out: { id, ok: true, results, ms }   (ms: the time the calls took here, for the client's threshold)
//              { id, ok: false, error: { name, message, field, kind } }   (the API's Error, as plain data)
// The typed arrays of the results are transferred (their buffers move, no copy). This file has no imports of its
// own (the deployment build copies it as it is: scripts/build-site.mjs).

let loading = null;   // Promise<{ api, memory }>: the wasm module, instantiated once per worker

async function load(glue, wasm) {
  const api = await import(glue);
  const exports = await api.default({ module_or_path: wasm });
  return { api, memory: exports.memory };
}

/** `args` with every { $ref: [k, key] } replaced by results[k][key]. */
function resolveRefs(v, results) {
  if (Array.isArray(v)) return v.map((x) => resolveRefs(x, results));
  if (v && typeof v === 'object' && !ArrayBuffer.isView(v)) {
    if (Array.isArray(v.$ref)) { const [k, key] = v.$ref; return results[k][key]; }
    return Object.fromEntries(Object.entries(v).map(([k, x]) => [k, resolveRefs(x, results)]));
  }
  return v;
}

/** The buffers of every typed array in `v` (each once; never the wasm memory itself). */
function buffers(v, memory, out = new Set()) {
  if (ArrayBuffer.isView(v)) { if (v.buffer !== memory?.buffer) out.add(v.buffer); } else if (Array.isArray(v)) {
    for (const x of v) buffers(x, memory, out);
  } else if (v && typeof v === 'object') for (const x of Object.values(v)) buffers(x, memory, out);
  return out;
}

self.onmessage = async ({ data }) => {
  const { id, glue, wasm, calls } = data;
  try {
    const { api, memory } = await (loading ??= load(glue, wasm));
    const t0 = performance.now();
    const results = [];
    for (const { fn, args, optional } of calls) {
      if (typeof api[fn] !== 'function') throw Object.assign(new Error(`${fn} is not an export of this module`), { kind: 'invalid' });
      // an optional call's error gives null (the page shows "undefined here"), the others' fail the request
      try { results.push(api[fn](resolveRefs(args, results))); } catch (e) { if (!optional) throw e; results.push(null); }
    }
    const ms = performance.now() - t0;
    self.postMessage({ id, ok: true, results, ms }, [...buffers(results, memory)]);
  } catch (e) {
    self.postMessage({ id, ok: false, error: { name: e?.name || 'Error', message: String(e?.message || e), field: e?.field, kind: e?.kind } });
  }
};
