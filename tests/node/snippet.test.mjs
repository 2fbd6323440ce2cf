// www/lib/snippet.js: literals read back as the same numbers, the code tag, the header, the sandbox link; and
// every demo's snippet(defaults()) is a function body that runs against pkg-node and returns results.
//
//   node --test tests/node/snippet.test.mjs

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { literal, code, raw, num, snippetCode, base64url, sandboxHref } from '../../www/lib/snippet.js';
import { DEMO_IDS } from '../../www/demos/index.js';

const require = createRequire(import.meta.url);
const sl = require('../../pkg-node/splinelab.js');

test('numbers round-trip exactly (shortest form), -0 and non-finite are spelled out', () => {
  const xs = [0.1 + 0.2, 1 / 3, 2 / 3, Math.PI, -1e-300, 5e-324, 1.7976931348623157e308, 123456789.12345679, 1e21, -0];
  for (const x of xs) assert.ok(Object.is(eval(num(x)), x), `${x} → ${num(x)}`);
  assert.equal(num(NaN), 'NaN');
  assert.equal(num(-Infinity), '-Infinity');
  const v = { a: xs, b: Float64Array.from(xs.slice(0, 5)), 'c-d': [[1, 2], [3, 4]], s: "it's", t: 'plain', n: null, f: true };
  const back = eval(`(${literal(v)})`);
  assert.deepEqual(back.a.map((x) => Object.is(x, -0) ? 'neg0' : x), xs.map((x) => Object.is(x, -0) ? 'neg0' : x));
  assert.deepEqual(back.b, xs.slice(0, 5));
  assert.deepEqual(back['c-d'], [[1, 2], [3, 4]]);
  assert.equal(back.s, "it's");
  assert.equal(literal('plain'), "'plain'");
});

test('long arrays wrap at about 100 characters and still read back', () => {
  const big = Array.from({ length: 300 }, (_, i) => [i / 7, Math.sin(i)]);
  const s = literal(big);
  assert.ok(s.split('\n').every((l) => l.length <= 110), 'lines ≤ 110 characters');
  assert.deepEqual(eval(`(${s})`), big);
  const grid = [[[0, 0, 1 / 3], [0, 1, 2 / 3]], [[1, 0, 0.1], [1, 1, 0.7]]];
  const c = code`
    const g = ${Array(20).fill(grid)};
    return { g };
  `;
  assert.deepEqual(new Function(c)().g, Array(20).fill(grid));
  assert.equal(code`const x = ${raw('sl.f()')};`, 'const x = sl.f();');
});

test('header and sandbox link', () => {
  const s = snippetCode('Demo', 'return { a: 1 };');
  assert.match(s, /^\/\/ SplineLab — Demo: /);
  assert.ok(s.includes("// Node: new Function('sl', code)(require('splinelab'))"));
  assert.ok(s.trimEnd().endsWith('return { a: 1 };'));
  const text = 'const é = "∑"; // ünïcode\nreturn { é };';
  const enc = base64url(text);
  assert.match(enc, /^[A-Za-z0-9_-]+$/, 'base64url, no padding');
  assert.equal(Buffer.from(enc, 'base64url').toString('utf8'), text);
  assert.equal(sandboxHref(text, 'https://example.org/sl/sandbox.html#old'), `https://example.org/sl/sandbox.html#code=${enc}`);
  assert.match(sandboxHref(text), /\/www\/sandbox\.html#code=/);
});

test('every demo: snippet(defaults()) runs against pkg-node and returns plain results', async () => {
  for (const id of DEMO_IDS) {
    const mod = await import(`../../www/demos/${id}.js`);
    assert.equal(typeof mod.snippet, 'function', `${id} exports snippet(state)`);
    const st = mod.defaults();
    const c = mod.snippet(st);
    assert.deepEqual(st, mod.defaults(), `${id}: snippet() does not change the state`);
    assert.equal(mod.snippet(st), c, `${id}: pure (same state, same code)`);
    const r = new Function('sl', c)(sl);
    assert.ok(r && typeof r === 'object' && Object.keys(r).length, `${id}: returns results`);
  }
});
