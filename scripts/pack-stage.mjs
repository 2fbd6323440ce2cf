// Stages the npm package in <dir> (called by scripts/pack.sh): copies the web and Node builds, writes the ES-module
// wrapper of the Node build (its named exports are the Node build's exports, so it cannot fall behind), the
// package.json with the exports map, the generated declarations pkg-node/splinelab.d.ts, and npm/{README.md, LICENSE, web.d.ts}. Fails when the two
// builds do not export the same functions or their version is not the one in Cargo.toml.
import { mkdirSync, copyFileSync, writeFileSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const dir = resolve(process.argv[2] || 'package');
const fail = (msg) => { console.error(`pack: ${msg}`); process.exit(1); };

const version = /^version\s*=\s*"([^"]+)"/m.exec(readFileSync(join(ROOT, 'Cargo.toml'), 'utf8'))?.[1] || fail('no version in Cargo.toml');
const nodeBuild = createRequire(import.meta.url)(join(ROOT, 'pkg-node/splinelab.js'));
const names = Object.keys(nodeBuild).filter((k) => typeof nodeBuild[k] === 'function').sort();
if (nodeBuild.version() !== version) fail(`pkg-node is version ${nodeBuild.version()}, Cargo.toml says ${version}: run scripts/pack.sh --build`);
const webSrc = readFileSync(join(ROOT, 'www/pkg/splinelab.js'), 'utf8');
const webNames = [...webSrc.matchAll(/^export function (\w+)\(/gm)].map((m) => m[1]).sort();
if (webNames.join() !== names.join()) fail(`www/pkg and pkg-node export different functions: run scripts/pack.sh --build\n  web:  ${webNames}\n  node: ${names}`);

mkdirSync(join(dir, 'web'), { recursive: true });
mkdirSync(join(dir, 'node'), { recursive: true });
for (const f of ['splinelab.js', 'splinelab_bg.wasm']) copyFileSync(join(ROOT, 'www/pkg', f), join(dir, 'web', f));
// one .wasm in the package when the two builds share it (they do: build-wasm.sh runs wasm-bindgen on one module and
// copies the optimised file to both): the Node glue then reads ../web/splinelab_bg.wasm
const nodeGlue = readFileSync(join(ROOT, 'pkg-node/splinelab.js'), 'utf8');
const WASM_PATH = '`${__dirname}/splinelab_bg.wasm`';
const same = readFileSync(join(ROOT, 'www/pkg/splinelab_bg.wasm')).equals(readFileSync(join(ROOT, 'pkg-node/splinelab_bg.wasm')));
if (same && nodeGlue.split(WASM_PATH).length === 2) {
  writeFileSync(join(dir, 'node/splinelab.js'), nodeGlue.replace(WASM_PATH, '`${__dirname}/../web/splinelab_bg.wasm`'));
} else {
  copyFileSync(join(ROOT, 'pkg-node/splinelab.js'), join(dir, 'node/splinelab.js'));
  copyFileSync(join(ROOT, 'pkg-node/splinelab_bg.wasm'), join(dir, 'node/splinelab_bg.wasm'));
}
writeFileSync(join(dir, 'web/package.json'), '{ "type": "module" }\n');
writeFileSync(join(dir, 'node/package.json'), '{ "type": "commonjs" }\n');
writeFileSync(join(dir, 'node/index.mjs'), `// ES-module entry of the Node build: the CommonJS module's exports, by name.
import sl from './splinelab.js';

export const {
${names.map((n) => `  ${n},`).join('\n')}
} = sl;
export default sl;
`);
// the declarations generated from the Rust bindings by wasm-bindgen (scripts/build-wasm.sh)
copyFileSync(join(ROOT, 'pkg-node/splinelab.d.ts'), join(dir, 'splinelab.d.ts'));
copyFileSync(join(ROOT, 'npm/web.d.ts'), join(dir, 'web/splinelab.d.ts'));
copyFileSync(join(ROOT, 'npm/README.md'), join(dir, 'README.md'));
copyFileSync(join(ROOT, 'npm/LICENSE'), join(dir, 'LICENSE'));

const web = { types: './web/splinelab.d.ts', default: './web/splinelab.js' };
const pkg = {
  name: 'splinelab',
  version,
  description: 'Spline constructions of five research papers (B2-splines, Bézier remodelling, knot modification, quasi-cubic trigonometric splines, curve-network surfaces) and B-splines, as one WebAssembly module with TypeScript types',
  license: 'MIT',
  keywords: ['spline', 'b-spline', 'bezier', 'surface', 'geometry', 'cagd', 'wasm', 'webassembly'],
  main: './node/splinelab.js',
  types: './splinelab.d.ts',
  exports: {
    // types per branch: TypeScript with moduleResolution node16/nodenext matches `node` (the Node build's types);
    // bundler resolution matches neither `browser` nor `node` and takes `default`, the web build with init()
    '.': {
      browser: web,
      node: { types: './splinelab.d.ts', import: './node/index.mjs', require: './node/splinelab.js' },
      default: web,
    },
    './web': web,
    './package.json': './package.json',
  },
  files: ['node/', 'web/', 'splinelab.d.ts', 'README.md', 'LICENSE'],
  sideEffects: false,
  engines: { node: '>=18' },
};
writeFileSync(join(dir, 'package.json'), `${JSON.stringify(pkg, null, 2)}\n`);
