// The TypeScript declarations are generated from the Rust bindings (src/api: api_options! structs, the
// typescript_custom_sections, unchecked_param_type / unchecked_return_type) into pkg-node/splinelab.d.ts by
// scripts/build-wasm.sh, which copies them to types/splinelab.d.ts. They cannot drift from the module:
//   1. every function exported by pkg-node is declared, and every declared function is exported;
//   2. every option key an export READS (its options object is a Proxy that records each key the binding gets
//      through Opts::raw's Reflect.get, over every call of check 3) is in that export's options type, and every
//      declared key is read by some call (a few documented exceptions below);
//   3. the results of real calls (every docs/API.md example, plus calls for the exports it does not show) have
//      only declared keys, and every key the declaration says is always there;
//   4. every ```js example of docs/API.md type-checks against the declarations (option types and shapes), and a
//      wrong option name in a call fails the type check (excess property check).
// Needs pkg-node (scripts/build-wasm.sh) and typescript (npm ci).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { readFileSync, mkdtempSync, writeFileSync, rmSync, mkdirSync, copyFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import ts from 'typescript';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
const require = createRequire(import.meta.url);
const sl = require(join(ROOT, 'pkg-node/splinelab.js'));
const DTS = join(ROOT, 'pkg-node/splinelab.d.ts');
const exported = Object.keys(sl).filter((k) => typeof sl[k] === 'function').sort();

/**
 * Keys the bindings read that are deliberately not in the options type, and declared keys no call reads.
 */
const READ_NOT_DECLARED = {
  // read only to refuse them, pointing to tensionU / tensionV (a surface has no automatic tension)
  b2Surface: ['tension', 'autoTension'],
};
const DECLARED_NOT_SEEN = {};

// ---------------------------------------------------------------- the declarations, through the compiler API

const program = ts.createProgram([DTS], { strict: true, noEmit: true, types: [], lib: ['lib.es2022.d.ts'] });
const checker = program.getTypeChecker();
const source = program.getSourceFile(DTS);
const moduleSymbol = checker.getSymbolAtLocation(source);
const declared = new Map(); // name → signatures
for (const sym of checker.getExportsOfModule(moduleSymbol)) {
  if (!(sym.flags & ts.SymbolFlags.Function)) continue;
  const type = checker.getTypeOfSymbolAtLocation(sym, source);
  declared.set(sym.name, type.getCallSignatures());
}

/** Property names of a type, through unions and intersections. */
function props(type) {
  const out = new Set();
  const types = type.isUnion() ? type.types : [type];
  for (const t of types) for (const p of checker.getPropertiesOfType(t)) out.add(p.name);
  return out;
}
/** The constituents of a (result) type: [{ all: Set, required: Set }] per union member. */
function shapes(type) {
  const types = type.isUnion() ? type.types : [type];
  return types.map((t) => {
    const all = new Set(), required = new Set();
    for (const p of checker.getPropertiesOfType(t)) {
      all.add(p.name);
      if (!(p.flags & ts.SymbolFlags.Optional)) required.add(p.name);
    }
    return { all, required, text: checker.typeToString(t) };
  });
}
function optionKeys(name) {
  const keys = new Set();
  for (const sig of declared.get(name) || []) {
    const p = sig.getParameters()[0];
    if (p) for (const k of props(checker.getTypeOfSymbolAtLocation(p, source))) keys.add(k);
  }
  return keys;
}
function resultShapes(name) {
  return (declared.get(name) || []).flatMap((sig) => shapes(checker.getReturnTypeOfSignature(sig)));
}

test('every export of the module is declared, and every declared function is exported', () => {
  const names = [...declared.keys()].sort();
  assert.deepEqual(exported.filter((n) => !declared.has(n)), [], 'exports without a declaration');
  assert.deepEqual(names.filter((n) => !exported.includes(n)), [], 'declarations of functions the module does not export');
  assert.ok(exported.length >= 40);
});

// ---------------------------------------------------------------- results of real calls

/** Calls of the exports that docs/API.md does not show (or shows without some optional result keys). */
function extraCalls(s) {
  const network = s.networkExample({ name: 'uniform-dome' });
  const surface = { orderU: 3, orderV: 3, knotsU: [0, 0, 0, 1, 2, 2, 2], knotsV: [0, 0, 0, 1, 2, 2, 2],
    controlPoints: [0, 1, 2, 3].map((r) => [0, 1, 2, 3].map((c) => [r, c, r * c])) };
  const curve = { order: 4, knots: [0, 0, 0, 0, 1, 2, 3, 3, 3, 3], controlPoints: [[0, 0], [1, 2], [2, 0], [3, 2], [4, 0], [5, 2]] };
  const W = [[0, 0], [1, 1], [2, 0], [3, 1], [4, 0], [5, 1]];
  s.version();
  s.fitNames();
  s.dataset({ name: 'rpn14' });
  s.bsplineCurve({ points: W, derivatives: 2, samples: 5 });
  s.bsplineBasis({ knots: [0, 0, 0, 1, 2, 2, 2], degree: 2, derivatives: 2, samples: 3 });
  s.quasiCubicBasis({ derivatives: 3, samples: 3 });
  s.b2Curve({ points: W, curvature: true, derivatives: 2, samples: 4 });
  s.b2Fit({ points: W.slice(0, 5), truthCurve: 'sine', curvature: true, samples: 4 });
  s.b2FitSweep({ points: W.slice(0, 5), truthCurve: 'sine', steps: 3 });
  s.bezierSpline({ points: [[0, 0], [1, 2], [2, 2], [3, 2], [4, 0]], degree: 2, samples: 4 });
  s.b2Surface({ grid: Array.from({ length: 6 }, (_, i) => Array.from({ length: 6 }, (_, j) => [i, j, i * j])), samplesU: 3, samplesV: 3, mesh: true, derivatives: 1 });
  s.quasiCubicPreset({ name: 'sphere' });
  s.quasiCubicPreset({ name: 'sine', segments: 3 });
  s.quasiCubicPreset({ name: 'wavy', m: 3, n: 3 });
  s.b2Basis({ points: W, samples: 3 });
  s.knotPathsCurve({ curve, p: 5, points: [1.5], samples: 4 });
  s.b2Basis({ knots: 'uniform', count: 6, samples: 3 });
  s.quasiCubicInterpolation({ points: W, samples: 5 });
  s.splineBlendedSurface({ network, blend: 'cubic-natural', tolerance: 1e-9, samplesU: 3, samplesV: 3 });
  s.quasiCubicPreset({ name: 'cylinder' });
  s.crissCrossCells({ network });
  s.crissCrossCells({ u: [0, 1, 2], v: [0, 1, 2], i: 1, j: 1 });
  s.crissCrossBasis({ u: [0, 1, 2], v: [0, 1, 2], i: 1, j: 1, samplesU: 3, samplesV: 3, mesh: true, derivatives: 1 });
  s.thinPlateSurface({ network, samplesU: 3, samplesV: 3, mesh: true });
  s.gordonSurface({ network, samplesU: 3, samplesV: 3, mesh: true, derivatives: 1, components: true });
  s.networkSurfaces({ network, samplesU: 3, samplesV: 3, colorBy: 'SG', curveSamples: 3, components: true });
  s.networkFromControlNet({ u: [0, 1, 2], v: [0, 1, 2], C: [0, 1, 2, 3].map((i) => [0, 1, 2, 3].map((j) => [i, j, i * j])) });
  s.networkFromFreeData({ u: network.u, v: network.v, P: network.P, Q1: network.Q.map((q) => q[1]) });
  s.knotEnvelope({ surface, p: 3, samplesU: 3, samplesV: 3 });
  s.knotModifiedSurface({ surface, p: 3, up: 1.5, q: 3, vq: 0.5, samplesU: 3, samplesV: 3, mesh: true });
  s.knotModifiedCurve({ curve, p: 5, up: 1.5, samples: 3, derivatives: 2 });
  s.knotLimits({ surface, p: 3, samples: 3 });
  s.quasiCubicBlendedSurface({ grid: Array.from({ length: 5 }, (_, i) => Array.from({ length: 5 }, (_, j) => [i, j, i * j])), samplesU: 3, samplesV: 3, mesh: true });
  // grids of flat rows (Float64Array, dim), in an option and in a knotModifiedSurface net
  const flatRows = Array.from({ length: 6 }, (_, i) => new Float64Array(Array.from({ length: 6 }, (_, j) => [i, j, i * j]).flat()));
  s.b2Surface({ grid: flatRows, dim: 3, samplesU: 3, samplesV: 3 });
  s.knotModifiedSurface({ surface: { ...surface, controlPoints: flatRows.slice(0, 4).map((r) => r.slice(0, 12)) }, p: 3, up: 1.5, samplesU: 3, samplesV: 3 });
  // the exercise checks the docs do not show (each adds its own result keys)
  s.exerciseCheck({ check: 'fitError', tol: 1, points: W.slice(0, 5), truthCurve: 'sine', a: 0.1 });
  s.exerciseCheck({ check: 'ellipse', tol: 1, points: [[1, 0], [0, 1], [-1, 0], [0, -1]] });
  s.exerciseCheck({ check: 'networkNorm', tol: 1, network, pair: 'SG', normSamples: 5 });
  s.exerciseCheck({ check: 'envelopePoint', tol: 1, curve, p: 5, up: 1.5, target: [2, 1] });
}

/** The ```js blocks of docs/API.md (as docs/examples.mjs extracts them). */
function apiBlocks() {
  const text = readFileSync(join(ROOT, 'docs/API.md'), 'utf8');
  const out = [];
  for (const m of text.matchAll(/^```([^\n]*)\n([\s\S]*?)^```$/gm)) {
    if (m[1].trim() === 'js') out.push({ code: m[2], line: text.slice(0, m.index).split('\n').length });
  }
  return out;
}

/** The keys a binding reads of an options object: the Proxy's `get` trap sees every Reflect.get of Opts::raw. */
function recordingProxy(options, keys) {
  return new Proxy(options, {
    get(target, key, receiver) {
      if (typeof key === 'string') keys.add(key);
      return Reflect.get(target, key, receiver);
    },
  });
}

/**
 * The same options with nested `points` / `grid` as flat coordinates and `dim` (the form that reads `dim`), or null.
 */
function flatTwin(options) {
  if (!options || typeof options !== 'object' || 'dim' in options) return null;
  const isPoint = (p) => Array.isArray(p) && (p.length === 2 || p.length === 3) && p.every((x) => typeof x === 'number');
  const isGrid = (g) => Array.isArray(g) && g.length && g.every((row) => Array.isArray(row) && row.length && row.every(isPoint));
  for (const key of ['points', 'grid']) {
    const v = options[key];
    if (Array.isArray(v) && v.length && v.every(isPoint)) return { ...options, [key]: new Float64Array(v.flat()), dim: v[0].length };
    if (isGrid(v)) return { ...options, [key]: v.map((row) => new Float64Array(row.flat())), dim: v[0][0].length };
  }
  return null;
}

/**
 * Every docs/API.md example and extraCalls (each with its flat twin), once: name → { results: [result], read: Set of option keys read }.
 */
let callsMemo;
async function allCalls() {
  if (callsMemo) return callsMemo;
  const seen = new Map();
  const spy = {};
  for (const name of exported) {
    seen.set(name, { results: [], read: new Set(), twinErrors: [] });
    spy[name] = (...args) => {
      const mine = seen.get(name);
      const [options, ...rest] = args;
      const wrapped = options && typeof options === 'object' && !Array.isArray(options) ? recordingProxy(options, mine.read) : options;
      const r = args.length ? sl[name](wrapped, ...rest) : sl[name]();
      mine.results.push(r);
      const twin = flatTwin(options);
      if (twin) {
        // not every export takes flat points (a twin it refuses still shows what it read)
        try { mine.results.push(sl[name](recordingProxy(twin, mine.read), ...rest)); } catch (e) { mine.twinErrors.push(e.message); }
      }
      return r;
    };
  }
  const AsyncFunction = (async () => {}).constructor;
  const req = (id) => (id.startsWith('./pkg-node') ? spy : require(id));
  for (const b of apiBlocks()) await new AsyncFunction('sl', 'assert', 'require', `{\n${b.code}\n}`)(spy, assert, req);
  extraCalls(spy);
  callsMemo = seen;
  return seen;
}

test('every option key an export reads is declared for it, and every declared key is read (Proxy over real calls)', async () => {
  const calls = await allCalls();
  const problems = [];
  for (const name of exported) {
    const mine = optionKeys(name);
    const read = calls.get(name).read;
    for (const k of read) {
      if (!mine.has(k) && !(READ_NOT_DECLARED[name] || []).includes(k)) problems.push(`${name}: the binding reads "${k}", the declaration has no such option`);
    }
    for (const k of mine) {
      if (!read.has(k) && !(DECLARED_NOT_SEEN[name] || []).includes(k)) problems.push(`${name}: the declaration has "${k}", no call read it`);
    }
    if (read.size && !declared.get(name)[0]?.getParameters().length) problems.push(`${name}: reads options but is declared without any`);
    // the exceptions cannot go stale: each is read and not declared, or declared and not read
    for (const k of READ_NOT_DECLARED[name] || []) if (!read.has(k) || mine.has(k)) problems.push(`${name}: stale READ_NOT_DECLARED "${k}"`);
    for (const k of DECLARED_NOT_SEEN[name] || []) if (read.has(k) || !mine.has(k)) problems.push(`${name}: stale DECLARED_NOT_SEEN "${k}"`);
  }
  assert.deepEqual(problems, []);
});

test('results of real calls have only declared keys, and every key declared as always present', async () => {
  const calls = await allCalls();
  const problems = [];
  for (const name of exported) {
    const results = calls.get(name).results;
    if (!results.length) { problems.push(`${name}: never called (add a call to extraCalls)`); continue; }
    const kinds = resultShapes(name).filter((s) => s.all.size || s.text !== 'string');
    for (const r of results) {
      if (typeof r !== 'object' || r === null) {
        if (!resultShapes(name).some((s) => s.text === typeof r)) problems.push(`${name}: returned a ${typeof r}, declared ${resultShapes(name).map((s) => s.text)}`);
        continue;
      }
      const keys = Object.keys(r);
      const fits = kinds.filter((s) => keys.every((k) => s.all.has(k) || s.all.has('__index')) && [...s.required].every((k) => k in r));
      if (!fits.length) {
        const best = kinds[0];
        problems.push(`${name}: result keys [${keys}] do not fit the declaration ${kinds.map((s) => s.text).join(' | ')}`
          + ` (undeclared: ${keys.filter((k) => !best.all.has(k))}; missing: ${[...best.required].filter((k) => !(k in r))})`);
      }
    }
  }
  assert.deepEqual(problems, []);
});

test('every docs/API.md example type-checks against the declarations', () => {
  const dir = mkdtempSync(join(tmpdir(), 'splinelab-types-'));
  try {
    mkdirSync(join(dir, 'node_modules/splinelab'), { recursive: true });
    copyFileSync(DTS, join(dir, 'node_modules/splinelab/splinelab.d.ts'));
    writeFileSync(join(dir, 'node_modules/splinelab/package.json'), JSON.stringify({ name: 'splinelab', types: './splinelab.d.ts' }));
    const files = [];
    for (const b of apiBlocks()) {
      const f = join(dir, `api-${b.line}.ts`);
      // each block in its own module, with `sl` the declared module and assert/require untyped (as docs/examples.mjs
      // runs them); a block that requires the module itself gets it untyped, like any require
      writeFileSync(f, `import * as sl from 'splinelab';\ndeclare const assert: any;\ndeclare const require: any;\nexport {};\n{\n${b.code}\n}\n`);
      files.push(f);
    }
    const p = ts.createProgram(files, {
      noEmit: true, strict: true, strictNullChecks: false, noImplicitAny: false, target: ts.ScriptTarget.ES2022,
      module: ts.ModuleKind.ESNext, moduleResolution: ts.ModuleResolutionKind.Bundler, types: [], lib: ['lib.es2022.d.ts'],
    });
    const deliberate = [];
    const diags = [];
    for (const d of ts.getPreEmitDiagnostics(p)) {
      const line = d.file ? d.file.getLineAndCharacterOfPosition(d.start).line : 0;
      const where = d.file ? `docs/API.md:${Number(/api-(\d+)\.ts$/.exec(d.file.fileName)?.[1]) + line - 4}` : '';
      const text = `${where} ${ts.flattenDiagnosticMessageText(d.messageText, ' ')}`;
      // a call inside assert.throws(() => …) is deliberately bad input: the types reject it too, as they should
      const src = d.file ? d.file.text.split('\n')[line] : '';
      (/assert\.throws\(\(\) =>/.test(src) ? deliberate : diags).push(text);
    }
    assert.deepEqual(diags, []);
    // the errors section's bad calls that a type can see: options as an array, an unknown network name
    assert.equal(deliberate.length, 2, deliberate.join('\n'));
    assert.ok(files.length > 20);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

/** Type-checks each { name: source } as a module importing the declarations as 'splinelab'; name → [message]. */
function typeCheck(sources) {
  const dir = mkdtempSync(join(tmpdir(), 'splinelab-types-'));
  try {
    mkdirSync(join(dir, 'node_modules/splinelab'), { recursive: true });
    copyFileSync(DTS, join(dir, 'node_modules/splinelab/splinelab.d.ts'));
    writeFileSync(join(dir, 'node_modules/splinelab/package.json'), JSON.stringify({ name: 'splinelab', types: './splinelab.d.ts' }));
    const files = Object.entries(sources).map(([name, code]) => {
      const f = join(dir, `${name}.ts`);
      writeFileSync(f, `import * as sl from 'splinelab';\nexport {};\n${code}\n`);
      return f;
    });
    const p = ts.createProgram(files, {
      noEmit: true, strict: true, target: ts.ScriptTarget.ES2022, module: ts.ModuleKind.ESNext,
      moduleResolution: ts.ModuleResolutionKind.Bundler, types: [], lib: ['lib.es2022.d.ts'],
    });
    const out = Object.fromEntries(Object.keys(sources).map((n) => [n, []]));
    for (const d of ts.getPreEmitDiagnostics(p)) {
      const name = d.file ? /([^/]+)\.ts$/.exec(d.file.fileName)[1] : 'global';
      (out[name] ||= []).push(ts.flattenDiagnosticMessageText(d.messageText, ' '));
    }
    return out;
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

test('a wrong option name in a call fails the type check (excess property check), the right one passes', () => {
  const W = '[[0, 0], [1, 2], [2, 0], [3, 2]]';
  const curve = '{ order: 4, knots: [0, 0, 0, 0, 1, 2, 2, 2, 2], controlPoints: [[0, 0], [1, 2], [2, 0], [3, 2], [4, 0]] }';
  const r = typeCheck({
    good: `sl.bsplineCurve({ points: ${W}, degree: 2, samples: 5 });\nsl.knotLimits({ curve: ${curve}, p: 4, samples: 3 });\nsl.b2Curve({ points: ${W}, tension: 0.2 });`,
    badCurve: `sl.bsplineCurve({ points: ${W}, degre: 2 });`,
    badOverload: `sl.knotLimits({ curve: ${curve}, p: 4, sample: 3 });`,
    badGenerated: `sl.b2Curve({ points: ${W}, tensoin: 0.2 });`,
  });
  assert.deepEqual(r.good, []);
  for (const [name, key] of [['badCurve', 'degre'], ['badOverload', 'sample'], ['badGenerated', 'tensoin']]) {
    assert.ok(r[name].some((m) => m.includes(`'${key}'`) && /Object literal may only specify known properties/.test(m)), `${name}: ${r[name].join('\n')}`);
  }
});

test('types/splinelab.d.ts (for the front end) is the generated declaration file', () => {
  assert.equal(readFileSync(join(ROOT, 'types/splinelab.d.ts'), 'utf8'), readFileSync(DTS, 'utf8'), 'run scripts/build-wasm.sh');
});

// docs/API.md states each export's signature in prose, `name({ a, b = 3, at | samples, samplesU/samplesV })`: every key
// it names must be an option the generated declarations give that export, so the reference cannot drift from the one
// source (47 of the 49 exports have such a signature; version and fitNames take no options). The converse is not
// asked: the prose leaves rarely used options (dim, mesh) to a sentence below the signature.
test('every option key a docs/API.md signature names is declared for that export', () => {
  const md = readFileSync(join(ROOT, 'docs/API.md'), 'utf8');
  const bad = [];
  let seen = 0;
  for (const m of md.matchAll(/^### `([A-Za-z0-9]+)`\n([\s\S]*?)(?=^### |(?![\s\S]))/gm)) {
    const [, name, body] = m;
    if (!declared.has(name)) continue;
    const sig = new RegExp('`' + name + '\\(\\{([^}]*)\\}\\)').exec(body.replace(/\n/g, ' '));
    if (!sig) continue;
    seen++;
    const keys = sig[1].split(/[,|/]/).map((k) => k.trim().replace(/\s*=.*$/, '').replace(/\?$/, '')).filter((k) => /^[A-Za-z][A-Za-z0-9]*$/.test(k));
    const mine = optionKeys(name);
    for (const k of keys) if (!mine.has(k)) bad.push(`${name}: docs/API.md names "${k}", the declarations of ${name} have ${[...mine].sort().join(', ')}`);
  }
  assert.ok(seen >= 30, `signatures found in docs/API.md: ${seen}`);
  assert.deepEqual(bad, []);
});
