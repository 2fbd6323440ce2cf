// The type check of the front end (issue 29): `tsc` over www/ with www/jsconfig.json (pages) and
// www/jsconfig.workers.json (workers) reports no error, and it does catch what it is for: a demo that calls the wasm
// module with a misspelt option name, directly (`ctx.wasm.bsplineCurve({ degre: 3 })`) or through the compute
// client (`{ fn: 'bsplineCurve', args: { degre: 3 } }`), fails the check; the same file spelt right passes.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, writeFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const TSC = join(root, 'node_modules', 'typescript', 'bin', 'tsc');

/** Runs tsc on a project file; returns { code, out } (tsc prints its errors on stdout). */
function tsc(project) {
  const r = spawnSync(process.execPath, [TSC, '-p', project, '--pretty', 'false'], { cwd: root, encoding: 'utf8' });
  return { code: r.status, out: `${r.stdout}${r.stderr}`.trim() };
}

test('www/ type-checks with no error (pages and workers)', () => {
  for (const project of ['www/jsconfig.json', 'www/jsconfig.workers.json']) {
    const { code, out } = tsc(project);
    assert.equal(out, '', `tsc -p ${project} reported:\n${out}`);
    assert.equal(code, 0);
  }
});

/** A demo-like module: mount(root, ctx) typed with the demo context of www/lib/host.js, as every demo is. */
function demoSource(option) {
  const host = JSON.stringify(join(root, 'www/lib/host.js'));
  const client = JSON.stringify(join(root, 'www/lib/compute-client.js'));
  return `
/** @param {HTMLElement} root @param {import(${host}).DemoContext} ctx */
export function mount(root, ctx) {
  const r = ctx.wasm.bsplineCurve({ points: [[0, 0], [1, 2], [2, 0], [3, 1]], ${option}: 3, samples: 50 });
  /** @type {import(${client}).WasmCall[]} */
  const calls = [{ fn: 'bsplineCurve', args: { points: [[0, 0], [1, 2], [2, 0], [3, 1]], ${option}: 3 } }];
  return { destroy() {}, exports: () => ({ json: { r, calls } }) };
}
`;
}

/** Type-checks one demo-like file with the front end's settings (www/jsconfig.json); returns tsc's result. */
function checkDemo(option) {
  const dir = mkdtempSync(join(tmpdir(), 'splinelab-typecheck-'));
  try {
    writeFileSync(join(dir, 'probe-demo.js'), demoSource(option));
    writeFileSync(join(dir, 'jsconfig.json'), JSON.stringify({
      extends: join(root, 'www/jsconfig.json'),
      // the whole union in messages (tsc shortens it to "… 40 more …", and its order follows the module graph)
      compilerOptions: { noErrorTruncation: true },
      include: [join(dir, 'probe-demo.js'), join(root, 'types/**/*.d.ts')],
      exclude: [],
    }));
    return tsc(join(dir, 'jsconfig.json'));
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

test('a misspelt wasm option in a demo fails the check, in a direct call and in a compute-client call', () => {
  const { code, out } = checkDemo('degre');
  assert.notEqual(code, 0, 'tsc passed a demo calling bsplineCurve with { degre: 3 }');
  const errors = out.split('\n').filter((l) => l.includes('probe-demo.js') && l.includes("'degre' does not exist"));
  assert.equal(errors.length, 2, `expected two errors naming 'degre' (the direct call and the WasmCall), got:\n${out}`);
  assert.match(errors[0], /probe-demo\.js\(4,\d+\): error TS(2353|2561)\b.*'degre' does not exist in type 'BsplineCurveOptions'/);
  // (the compute-client call names the union of every export's options when the key is in none of them)
  assert.match(errors[1], /probe-demo\.js\(6,\d+\): error TS(2353|2561)\b.*'degre' does not exist in type '.*BsplineCurveOptions/);
});

test('the same demo with the option spelt right passes', () => {
  const { code, out } = checkDemo('degree');
  assert.equal(out, '');
  assert.equal(code, 0);
});
