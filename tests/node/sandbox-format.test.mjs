// The sandbox's pure helpers (www/lib/sandbox-format.js): the link format `#code=<base64url, no padding>` round-trips
// any UTF-8 code, and the line of the visitor's code is found in Chromium's, Firefox's and WebKit's stack formats.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { encodeCode, decodeCode, codeFromHash, codeLocation, formatValue, drawKind } from '../../www/lib/sandbox-format.js';

test('code ↔ base64url round-trips UTF-8 and matches Node\'s base64url (no padding)', () => {
  const samples = ['', 'a', 'ab', 'abc', 'print(1)', 'const α = 1; // ∞ → é 😀\nreturn α;', 'x'.repeat(70000)];
  let seed = 7;
  const rnd = () => (seed = (seed * 1103515245 + 12345) % 2 ** 31) / 2 ** 31;
  for (let k = 0; k < 50; k++) samples.push(Array.from({ length: Math.floor(rnd() * 40) }, () => String.fromCodePoint(Math.floor(rnd() * 0x2FFF))).join(''));
  for (const s of samples) {
    const e = encodeCode(s);
    assert.equal(e, Buffer.from(s, 'utf8').toString('base64url'));
    assert.doesNotMatch(e, /[=+/]/);
    assert.equal(decodeCode(e), s);
    assert.equal(codeFromHash(`#code=${e}`), s);
    assert.equal(codeFromHash(`#other=1&code=${e}`), s);
  }
  assert.equal(decodeCode('cHJpbnQoMSk='), 'print(1)', 'padding is accepted');
  assert.equal(codeFromHash('#bspline-basics'), null);
  assert.throws(() => decodeCode('a*b'), /base64url/);
  assert.throws(() => decodeCode('_w'), TypeError, 'not UTF-8 (0xff)');
});

test('the line of the code in a stack trace (Chromium, Firefox, WebKit), minus the wrapper line', () => {
  const url = 'blob:http://127.0.0.1:8080/1b2c3d4e-aaaa-bbbb-cccc-0123456789ab';
  const chromium = `Error: points: need at least 4 points, got 3\n    at __wbg_new_1 (http://127.0.0.1:8080/pkg/splinelab.js:1000:17)\n    at splinelab.wasm.func (wasm://wasm/00a:wasm-function[12]:0x1)\n    at bsplineCurve (http://127.0.0.1:8080/pkg/splinelab.js:160:18)\n    at ${url}:6:12\n    at run (http://127.0.0.1:8080/sandbox.js:300:5)`;
  const firefox = `__wbg_new_1@http://127.0.0.1:8080/pkg/splinelab.js:1000:17\nbsplineCurve@http://127.0.0.1:8080/pkg/splinelab.js:160:18\n@${url}:6:12\nrun@http://127.0.0.1:8080/sandbox.js:300:5`;
  const webkit = `bsplineCurve@http://127.0.0.1:8080/pkg/splinelab.js:160:18\n${url}:6:12\nrun@http://127.0.0.1:8080/sandbox.js:300:5`;
  for (const s of [chromium, firefox, webkit]) assert.deepEqual(codeLocation(s, url, 1), { line: 5, column: 12 });
  assert.equal(codeLocation(chromium, 'blob:http://127.0.0.1:8080/other', 1), null);
  assert.equal(codeLocation('', url, 1), null);
});

test('values print briefly; drawable results are recognised', () => {
  assert.equal(formatValue(new Float64Array([1, 2.5, 1 / 3])), 'Float64Array(3) [1, 2.5, 0.3333333333]');
  assert.equal(formatValue([[1, 2], [3, 4]]), '[[1, 2], [3, 4]]');
  assert.match(formatValue(Object.assign(new Float64Array(10), { dim: 2 })), /^Float64Array\(10\) \[0, 0, 0, 0, 0, 0, 0, 0, …\] \{ dim \}$/);
  assert.equal(drawKind({ dim: 2, params: [], points: new Float64Array(4) }), 'plot');
  assert.equal(drawKind({ points: new Float64Array(3), mesh: { positions: new Float32Array(3), indices: new Uint32Array(3) } }), 'surface');
  assert.equal(drawKind({ surfaces: { S: { points: [], mesh: { positions: [], indices: [] } } } }), 'surface');
  assert.equal(drawKind({ values: [], params: [] }), 'plot');
  assert.equal(drawKind({ u: [0, 1], v: [0, 1], P: [], Q: [] }), null);
  assert.equal(drawKind(new Float64Array(2)), null);
});
