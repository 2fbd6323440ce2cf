// The npm package from its tarball, as a user gets it (issue 18): scripts/pack.sh builds dist/splinelab-<version>.tgz,
// which is installed into an empty folder (`npm install --offline <tgz>`: the package has no dependencies), then
//   - required from Node as CommonJS and imported as an ES module (named and default), calling exports;
//   - the web build (`splinelab/web`) instantiated with initSync in Node, giving the same numbers;
//   - a small TypeScript program calling three exports type-checks with `tsc --noEmit` (the repository's
//     dev dependency typescript), and programs with a wrong option type or an unknown option FAIL to compile.
// Needs the wasm build (scripts/build-wasm.sh) and node_modules (npm ci).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import { mkdtempSync, writeFileSync, rmSync, existsSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
const TSC = join(ROOT, 'node_modules/typescript/bin/tsc');
let dir, tgz;

before(() => {
  const out = mkdtempSync(join(tmpdir(), 'splinelab-pack-'));
  tgz = execFileSync(join(ROOT, 'scripts/pack.sh'), [], { cwd: ROOT, env: { ...process.env, PACK_OUT: out }, encoding: 'utf8' })
    .trim().split('\n').pop();
  assert.match(tgz, /splinelab-\d+\.\d+\.\d+[^/]*\.tgz$/);
  dir = mkdtempSync(join(tmpdir(), 'splinelab-user-'));
  writeFileSync(join(dir, 'package.json'), '{ "name": "user", "private": true }\n');
  execFileSync('npm', ['install', '--offline', '--no-audit', '--no-fund', '--ignore-scripts', tgz], { cwd: dir, stdio: 'pipe' });
});
after(() => {
  if (dir) rmSync(dir, { recursive: true, force: true });
  if (tgz) rmSync(dirname(tgz), { recursive: true, force: true });
});

const node = (file, src) => {
  writeFileSync(join(dir, file), src);
  return execFileSync(process.execPath, [file], { cwd: dir, encoding: 'utf8' }).trim();
};

test('the tarball holds both builds, the types, a README and the licence; version from Cargo.toml', () => {
  const pkg = JSON.parse(readFileSync(join(dir, 'node_modules/splinelab/package.json'), 'utf8'));
  const cargo = /^version\s*=\s*"([^"]+)"/m.exec(readFileSync(join(ROOT, 'Cargo.toml'), 'utf8'))[1];
  assert.equal(pkg.version, cargo);
  assert.ok(tgz.endsWith(`splinelab-${cargo}.tgz`));
  for (const f of ['web/splinelab.js', 'web/splinelab_bg.wasm', 'node/splinelab.js', 'node/index.mjs', 'splinelab.d.ts',
    'web/splinelab.d.ts', 'README.md', 'LICENSE']) assert.ok(existsSync(join(dir, 'node_modules/splinelab', f)), f);
  assert.equal(pkg.exports['.'].node.require, './node/splinelab.js');
  assert.equal(pkg.exports['.'].node.import, './node/index.mjs');
  assert.equal(pkg.exports['.'].browser.default, './web/splinelab.js');
  assert.equal(pkg.exports['./web'].default, './web/splinelab.js');
  assert.equal(pkg.types, './splinelab.d.ts');
  assert.equal(pkg.dependencies, undefined, 'no dependencies');
});

test('CommonJS: require("splinelab") computes and throws field-named errors', () => {
  const out = node('cjs.cjs', `
    const sl = require('splinelab');
    const r = sl.bsplineCurve({ degree: 2, knots: [0, 0, 0, 1, 2, 2, 2], points: [[0, 0], [1, 2], [3, 2], [4, 0]], at: [0, 1, 2] });
    let e; try { sl.bsplineCurve({ points: [[0, 0], [1, 1]] }); } catch (x) { e = x; }
    console.log(JSON.stringify({ v: sl.version(), p: Array.from(r.points), field: e.field, kind: e.kind }));
  `);
  const r = JSON.parse(out);
  assert.deepEqual(r.p, [0, 0, 2, 2, 4, 0]);
  assert.equal(r.field, 'points');
  assert.equal(r.kind, 'too-few');
  assert.match(r.v, /^\d+\.\d+\.\d+/);
});

test('ES module: named and default imports of "splinelab" are the Node build', () => {
  const out = node('esm.mjs', `
    import sl, { quasiCubicPreset, quasiCubicCurve, version } from 'splinelab';
    const c = quasiCubicPreset({ name: 'circle', radius: 2 });
    const r = quasiCubicCurve({ points: c.points, alpha: c.alpha, closed: c.closed, samples: 17 });
    let worst = 0;
    for (let i = 0; i < r.points.length; i += 2) worst = Math.max(worst, Math.abs(Math.hypot(r.points[i], r.points[i + 1]) - 2));
    console.log(JSON.stringify({ worst, same: sl.version === version, n: Object.keys(sl).length }));
  `);
  const r = JSON.parse(out);
  assert.ok(r.worst < 1e-12, `circle radius error ${r.worst}`);
  assert.equal(r.same, true);
  assert.ok(r.n > 40);
});

test('the web build ("splinelab/web") instantiates with initSync and gives the same numbers', () => {
  const out = node('web.mjs', `
    import { readFileSync } from 'node:fs';
    import { createRequire } from 'node:module';
    import { initSync, bsplineBasis } from 'splinelab/web';
    import * as nodeBuild from 'splinelab';
    const require = createRequire(import.meta.url);
    const wasm = readFileSync(require.resolve('splinelab/package.json').replace(/package\\.json$/, 'web/splinelab_bg.wasm'));
    initSync({ module: wasm });
    const opts = { degree: 2, knots: [0, 0, 0, 1, 2, 2, 2], at: [0.5, 1] };
    console.log(JSON.stringify([Array.from(bsplineBasis(opts).values), Array.from(nodeBuild.bsplineBasis(opts).values)]));
  `);
  const [web, nodeValues] = JSON.parse(out);
  assert.deepEqual(web, [0.25, 0.625, 0.125, 0, 0, 0.5, 0.5, 0]);
  assert.deepEqual(web, nodeValues);
});

/** Runs tsc --noEmit on `files` (name → source) with a strict nodenext config; returns { status, output }. */
function tsc(files, name, options = {}) {
  const proj = join(dir, name);
  execFileSync('mkdir', ['-p', proj]);
  for (const [f, src] of Object.entries(files)) writeFileSync(join(proj, f), src);
  writeFileSync(join(proj, 'tsconfig.json'), JSON.stringify({
    compilerOptions: { strict: true, noEmit: true, module: 'nodenext', moduleResolution: 'nodenext', target: 'es2022', lib: ['es2022'], types: [], skipLibCheck: false, ...options },
    include: Object.keys(files),
  }));
  const r = spawnSync(process.execPath, [TSC, '-p', proj], { cwd: dir, encoding: 'utf8' });
  return { status: r.status, output: `${r.stdout}${r.stderr}` };
}

test('TypeScript: a program calling three exports type-checks (tsc --noEmit)', () => {
  const r = tsc({
    'good.mts': `
import { bsplineCurve, quasiCubicPreset, crissCrossSurface, networkExample, type SplineLabError } from 'splinelab';
const c = bsplineCurve({ degree: 3, points: [[0, 0], [1, 2], [3, 2], [4, 0]], samples: 50, derivatives: 1 });
const n: number = c.points.length + c.dim;
const knots: Float64Array = c.knots;
const d1: Float64Array | undefined = c.d1;
const p = quasiCubicPreset({ name: 'torus', major: 2 });
if (p.kind === 'surface') { const rows: number = p.grid.length; void rows; }
const s = crissCrossSurface({ network: networkExample({ name: 'uniform-dome' }), samplesU: 8, samplesV: 8, mesh: true, C11: 'edges' });
const idx: Uint32Array | undefined = s.mesh?.indices;
try { bsplineCurve({ points: [] }); } catch (e) { const f: string = (e as SplineLabError).field; void f; }
void n; void knots; void d1; void idx;
`,
    'good.cts': `
import sl = require('splinelab');
const r = sl.b2Curve({ points: [[0, 0], [1, 1], [2, 0], [3, 1], [4, 0], [5, 1]], a: 1 / 12, knots: 'uniform', samples: 10 });
const j: Float64Array = r.joints;
void j;
`,
    'web.mts': `
import init, { b2Surface } from 'splinelab/web';
await init();
const grid = [[[0, 0, 0]]];
const s = b2Surface({ grid, samplesU: 4, samplesV: 4, mesh: true, knotsU: 'chord' });
const pts: Float64Array = s.points;
void pts;
`,
  }, 'ts-good');
  assert.equal(r.status, 0, r.output);
  // a bundler (moduleResolution "bundler") gets the web build for "splinelab": its types have the default init()
  const b = tsc({ 'app.ts': `
import init, { bsplineBasis } from 'splinelab';
await init();
const v: Float64Array = bsplineBasis({ knots: [0, 0, 1, 1], degree: 1, at: [0.5] }).values;
void v;
` }, 'ts-bundler', { module: 'esnext', moduleResolution: 'bundler' });
  assert.equal(b.status, 0, b.output);
});

test('TypeScript: a wrong option type, an unknown option and a wrong result type fail to compile', () => {
  // one tsc run over three files (tsc reports every file's errors); each file must have its own error
  const r = tsc({
    'bad-type.mts': `
import { bsplineCurve } from 'splinelab';
bsplineCurve({ degree: 'three', points: [[0, 0], [1, 1], [2, 0], [3, 1]] });
`,
    'bad-key.mts': `
import { b2Surface } from 'splinelab';
b2Surface({ grid: [[[0, 0, 0]]], tension: 0.2 });
`,
    'bad-result.mts': `
import { noisyData } from 'splinelab';
const s: string = noisyData({ count: 10 }).points;
void s;
`,
  }, 'ts-bad');
  assert.notEqual(r.status, 0, 'the bad programs must not compile');
  assert.match(r.output, /bad-type\.mts\(3,\d+\): error TS2322: Type 'string' is not assignable to type 'number'/, 'a string degree');
  assert.match(r.output, /bad-key\.mts\(3,\d+\): error TS2(353|561): Object literal may only specify known properties,? (and|but) 'tension' does not exist/, 'b2Surface takes tensionU/tensionV, not tension');
  assert.match(r.output, /bad-result\.mts\(3,\d+\): error TS2322: Type 'Float64Array[^']*' is not assignable to type 'string'/, 'points is a Float64Array');
  assert.equal(r.output.match(/error TS/g).length, 3, r.output);
});
