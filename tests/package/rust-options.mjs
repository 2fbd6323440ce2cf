// The option keys each export of the wasm bindings reads, from the Rust source of src/api/*.rs (for
// tests/package/types.test.mjs, which checks them against the TypeScript declarations).
//
// How options are read: an export makes `let o = Opts::new(options)?` and reads keys with methods of `Opts`
// (`o.points("points", …)`, `o.f64_or("a", …)`, `o.opt::<T>("blend")`, …) or passes `o` to helpers with the key as
// a literal argument (`read_tension(o, "tensionU", …)`, `read_moved(&o, "p", "up", …)`). Helpers and the `Opts`
// methods read further keys themselves (`curve_params` reads `at` and `samples`; `points` reads `dim`).
// So, per function (free functions and the methods of `impl Opts`): the receivers are its parameters of type
// `&Opts` / `Opts`, `self` inside `impl Opts`, and locals made by `Opts::new(`. A key is read where
//   receiver.method("key", …)        a method call on a receiver with a string literal as an argument, or
//   helper(…, receiver, …, "key", …) a call that passes a receiver and string literals,
// and the function reads the keys of every function it calls that way (transitively). Keys held in variables
// (a loop over an array of names) are not seen; nested objects (`curve.order`, `network.P`) are not keys here.
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';

/** The end index of the brace block that starts at `open` (an index of '{'), skipping strings and comments. */
function blockEnd(src, open) {
  let depth = 0;
  for (let i = open; i < src.length; i++) {
    const c = src[i];
    if (c === '/' && src[i + 1] === '/') { i = src.indexOf('\n', i); if (i < 0) return src.length; continue; }
    if (c === '/' && src[i + 1] === '*') { i = src.indexOf('*/', i + 2) + 1; continue; }
    if (c === '"') { for (i++; i < src.length && src[i] !== '"'; i++) if (src[i] === '\\') i++; continue; }
    if (c === "'" && /^'(\\.|[^\\'])'/.test(src.slice(i, i + 4))) { i = src.indexOf("'", i + 2); continue; }
    if (c === '{') depth++;
    else if (c === '}' && --depth === 0) return i;
  }
  return src.length;
}

/** Top-level comma-separated arguments of the call whose '(' is at `open`; and the index after ')'. */
function callArgs(src, open) {
  const args = [];
  let depth = 0, start = open + 1;
  for (let i = open; i < src.length; i++) {
    const c = src[i];
    if (c === '"') { for (i++; i < src.length && src[i] !== '"'; i++) if (src[i] === '\\') i++; continue; }
    if (c === '(' || c === '[' || c === '{') depth++;
    else if (c === ')' || c === ']' || c === '}') {
      if (--depth === 0) { args.push(src.slice(start, i).trim()); return { args: args.filter(Boolean), end: i + 1 }; }
    } else if (c === ',' && depth === 1) { args.push(src.slice(start, i).trim()); start = i + 1; }
  }
  return { args, end: src.length };
}

/** Functions of one file: [{ name, params, body, file, exportName? }]. */
function functions(file, src) {
  const out = [];
  // impl Opts { … }: its methods read with `self`
  const implOpts = [];
  for (const m of src.matchAll(/\bimpl\s+Opts\s*\{/g)) {
    const open = m.index + m[0].length - 1;
    implOpts.push([open, blockEnd(src, open)]);
  }
  const re = /((?:#\[wasm_bindgen[^\]]*\]\s*)?)(?:pub(?:\([^)]*\))?\s+)?fn\s+(\w+)\s*(?:<[^(]*>)?\s*\(/g;
  for (let m; (m = re.exec(src));) {
    const { args, end } = callArgs(src, m.index + m[0].length - 1);
    const open = src.indexOf('{', end);
    if (open < 0) continue;
    // a declaration without a body (trait method) ends with ';' before the next '{'
    const semi = src.indexOf(';', end);
    if (semi >= 0 && semi < open) continue;
    const close = blockEnd(src, open);
    const attr = m[1];
    let exportName = null;
    if (attr) exportName = /js_name\s*=\s*(\w+)/.exec(attr)?.[1] || m[2];
    const inImpl = implOpts.some(([a, b]) => m.index > a && m.index < b);
    const receivers = new Set(args.filter((a) => /:\s*&?\s*(mut\s+)?Opts\b/.test(a)).map((a) => a.split(':')[0].trim()));
    if (inImpl && args.some((a) => /^&?\s*(mut\s+)?self$/.test(a))) receivers.add('self');
    const body = src.slice(open, close + 1);
    for (const l of body.matchAll(/\blet\s+(?:mut\s+)?(\w+)\s*=\s*Opts::new\(/g)) receivers.add(l[1]);
    out.push({ name: m[2], file, exportName, receivers, body, method: inImpl });
  }
  return out;
}

/** Direct key reads and calls (that pass a receiver) of one function. */
function reads(fn) {
  const keys = new Set();
  const calls = new Set();
  const body = fn.body;
  const lit = (a) => /^"([A-Za-z][A-Za-z0-9]*)"$/.exec(a)?.[1];
  const re = /(?:\b(\w+)\s*\.\s*)?\b(\w+)\s*(?:::<[^(]*?>)?\s*\(/g;
  for (let m; (m = re.exec(body));) {
    const recv = m[1], name = m[2];
    if (['if', 'while', 'for', 'match', 'return', 'Some', 'Ok', 'Err'].includes(name)) continue;
    const { args } = callArgs(body, m.index + m[0].length - 1);
    const onReceiver = recv && fn.receivers.has(recv);
    const passesReceiver = args.some((a) => fn.receivers.has(a.replace(/^&\s*/, '')));
    if (onReceiver || passesReceiver) {
      for (const a of args) { const k = lit(a); if (k) keys.add(k); }
      calls.add(onReceiver ? `Opts::${name}` : name);
    }
  }
  return { keys, calls };
}

/** Map export name → sorted list of the option keys its binding reads. */
export function rustOptionKeys(apiDir) {
  const fns = [];
  for (const f of readdirSync(apiDir).filter((f) => f.endsWith('.rs'))) fns.push(...functions(f, readFileSync(join(apiDir, f), 'utf8')));
  const byName = new Map();
  for (const fn of fns) {
    const key = fn.method ? `Opts::${fn.name}` : fn.name;
    if (!byName.has(key)) byName.set(key, []);
    byName.get(key).push(fn);
  }
  const info = new Map(fns.map((fn) => [fn, reads(fn)]));
  const memo = new Map();
  function closure(fn, seen = new Set()) {
    if (memo.has(fn)) return memo.get(fn);
    if (seen.has(fn)) return new Set();
    seen.add(fn);
    const { keys, calls } = info.get(fn);
    const all = new Set(keys);
    for (const c of calls) {
      // a helper of the same file first (names repeat across files), else any file's
      const cands = byName.get(c) || [];
      const same = cands.filter((x) => x.file === fn.file);
      for (const g of (same.length ? same : cands)) for (const k of closure(g, seen)) all.add(k);
    }
    memo.set(fn, all);
    return all;
  }
  const out = {};
  for (const fn of fns.filter((f) => f.exportName)) out[fn.exportName] = [...closure(fn)].sort();
  return out;
}

if (import.meta.url === `file://${process.argv[1]}`) {
  console.log(JSON.stringify(rustOptionKeys(process.argv[2] || 'src/api'), null, 1));
}
