// The sandbox page (www/sandbox.html, issue 18) in headless Chromium:
//   - EVERY ```js example of docs/API.md, pasted into the code area and run with the Run button: no error, output
//     present. The examples are extracted as docs/examples.mjs does (same fence rule). Adapted, because there they
//     run in Node with `sl` and `assert` given: (1) the line `const sl = require('./pkg-node/splinelab.js');` is
//     dropped (the sandbox passes the module as `sl`; the page's own `init()` loaded it); (2) one line is put in
//     front that defines a small `assert` (ok, equal, deepEqual, throws — Node's strict semantics for what the
//     examples use) counting the assertions; (3) one line is put at the end that prints that count. The example's
//     own lines are unchanged, so every assertion of the docs runs against the page's module.
//   - a deliberate bad call shows the field-named error (.field, .kind) next to the line where it happened;
//   - a link with code (`#code=<base64url>`) shows the code and does not run it until Run is pressed;
//   - Ctrl+Enter runs; plot() changes the 2D canvas' pixels; surface() draws in the 3D view (or its fallback);
//   - every ready example of the menu runs cleanly; screenshots at desktop and phone size.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { startHarness, ROOT, OUT } from './harness.mjs';
import { EXAMPLES } from '../../www/lib/sandbox-examples.js';

let H;
before(async () => { H = await startHarness(); mkdirSync(OUT, { recursive: true }); });
after(async () => { await H?.close(); });

/** The ```js blocks of docs/API.md, as docs/examples.mjs extracts them: { code, line }. */
function apiExamples() {
  const text = readFileSync(join(ROOT, 'docs/API.md'), 'utf8');
  const out = [];
  for (const m of text.matchAll(/^```([^\n]*)\n([\s\S]*?)^```$/gm)) {
    if (m[1].trim() === 'js') out.push({ code: m[2], line: text.slice(0, m.index).split('\n').length });
  }
  return out;
}

// one line, so the example's own lines keep their numbers + 1
const ASSERT_SHIM = 'let __n = 0; const __eq = (a, b) => { if (Object.is(a, b)) return true; if (a == null || b == null || typeof a !== \'object\' || typeof b !== \'object\') return false; const arr = (x) => Array.isArray(x) || ArrayBuffer.isView(x); if (arr(a) !== arr(b)) return false; if (arr(a)) return a.length === b.length && Array.from(a).every((x, i) => __eq(x, b[i])); const ka = Object.keys(a), kb = Object.keys(b); return ka.length === kb.length && ka.every((k) => __eq(a[k], b[k])); }; const assert = { ok(v, m) { __n++; if (!v) throw new Error(m || \'assert.ok failed\'); }, equal(a, b, m) { __n++; if (!Object.is(a, b)) throw new Error(m || `assert.equal: ${a} !== ${b}`); }, deepEqual(a, b, m) { __n++; if (!__eq(a, b)) throw new Error(m || `assert.deepEqual: ${JSON.stringify(Array.isArray(a) ? a : a)} vs ${JSON.stringify(b)}`); }, throws(f, want) { __n++; let e = null; try { f(); } catch (x) { e = x; } if (!e) throw new Error(\'assert.throws: nothing was thrown\'); if (want instanceof RegExp) { if (!want.test(String(e))) throw new Error(`assert.throws: ${e} does not match ${want}`); } else if (want) { for (const [k, v] of Object.entries(want)) { if (v instanceof RegExp ? !v.test(e[k]) : !Object.is(e[k], v)) throw new Error(`assert.throws: ${k} = ${e[k]}, expected ${v}`); } } } };';

function adapt(code) {
  const body = code.split('\n').filter((l) => !/^\s*const sl = require\(['"]\.\/pkg-node\/splinelab\.js['"]\);/.test(l)).join('\n');
  return `${ASSERT_SHIM}\n${body}\nprint(__n + ' assertions passed');\n`;
}

async function runCode(t, code, { key = false } = {}) {
  const before = await t.page.evaluate(() => Number(document.body.dataset.runs || 0));
  await t.page.fill('#sb-code', code);
  if (key) { await t.page.focus('#sb-code'); await t.page.keyboard.press('Control+Enter'); } else await t.page.click('#sb-run');
  await t.page.waitForFunction((n) => Number(document.body.dataset.runs || 0) > n && document.body.dataset.run !== 'running', before, { timeout: 20000 });
  return t.page.evaluate(() => ({
    run: document.body.dataset.run,
    output: document.getElementById('sb-output').textContent,
    error: document.getElementById('sb-error').hidden ? '' : document.getElementById('sb-error').textContent,
    errorLine: document.getElementById('sb-error').dataset.line || '',
    inline: (() => { const el = document.getElementById('sb-inline-error'); return el && !el.hidden ? { text: el.textContent, line: el.dataset.line } : null; })(),
  }));
}

test('every docs/API.md example, pasted into the sandbox and run, runs without error and prints its assertions', async () => {
  const t = await H.open('sandbox.html');
  const blocks = apiExamples();
  assert.ok(blocks.length >= 25, `docs/API.md has ${blocks.length} js examples`);
  const failures = [];
  let assertions = 0;
  for (const b of blocks) {
    const r = await runCode(t, adapt(b.code));
    const m = /(\d+) assertions passed/.exec(r.output);
    if (r.run !== 'ok' || !m) failures.push(`docs/API.md:${b.line}: ${r.run} ${r.error || r.output.slice(0, 200)}`);
    else assertions += Number(m[1]);
  }
  assert.deepEqual(failures, []);
  assert.ok(assertions > 60, `${assertions} assertions ran`);
  t.assertClean();
  await t.close();
});

test('a bad call shows the field-named error next to the line where it happened', async () => {
  const t = await H.open('sandbox.html');
  const code = [
    '// three points are too few for a cubic',
    'const points = [[0, 0], [1, 1], [2, 0]];',
    'const ok = sl.bsplineCurve({ degree: 2, points, samples: 5 });',
    'print(ok.points.length);',
    'const c = sl.bsplineCurve({ degree: 3, points });',
    'print("not reached");',
  ].join('\n');
  const r = await runCode(t, code);
  assert.equal(r.run, 'error');
  assert.equal(r.errorLine, '5');
  assert.deepEqual(r.inline && r.inline.line, '5');
  assert.match(r.inline.text, /^Line 5: points: need at least 4/);
  assert.match(r.inline.text, /\(field points, too-few\)/);
  assert.match(r.output, /^10\n$/, 'the lines before the error ran; the one after did not');
  // the marker sits under line 5 of the code area, and the gutter marks line 5
  const geo = await t.page.evaluate(() => {
    const ta = document.getElementById('sb-code');
    const lh = parseFloat(getComputedStyle(ta).lineHeight);
    const top = ta.getBoundingClientRect().top + parseFloat(getComputedStyle(ta).paddingTop);
    const box = document.getElementById('sb-inline-error').getBoundingClientRect();
    return { line: (box.top - top) / lh, gutter: document.querySelector('.sb-ln-error')?.textContent };
  });
  assert.ok(Math.abs(geo.line - 5) < 0.2, `the message starts right below line 5 (at line ${geo.line})`);
  assert.equal(geo.gutter, '5');
  // an error in a helper the code defined, called later: the line of the throw (in the helper)
  const r2 = await runCode(t, 'const curve = (pts) =>\n  sl.b2Curve({ points: pts });\nprint("before");\ncurve([[0, 0], [1, NaN], [2, 0], [3, 1], [4, 0], [5, 1]]);');
  assert.equal(r2.inline.line, '2');
  assert.match(r2.inline.text, /points\[1\]\[1\]: expected a finite number.*\(field points\[1\]\[1\], not-finite\)/);
  // a syntax error names its line too
  const r3 = await runCode(t, 'const a = 1;\nconst b = (a + ;\n');
  assert.equal(r3.run, 'error');
  assert.equal(r3.inline.line, '2');
  assert.match(r3.inline.text, /SyntaxError/);
  await t.page.screenshot({ path: join(OUT, 'sandbox-error.png') });
  // typing clears the marker
  await t.page.type('#sb-code', ' ');
  assert.equal(await t.page.evaluate(() => document.getElementById('sb-inline-error').hidden), true);
  t.assertClean();
  await t.close();
});

test('a link with code shows it and runs nothing until Run is pressed', async () => {
  // the code runs in the sandbox's worker (not the page): it counts its runs there and prints the count
  const code = 'globalThis.__sandboxRan = (globalThis.__sandboxRan || 0) + 1;\nprint("ran from the link: é ∞", __sandboxRan);\nreturn sl.bsplineCurve({ points: [[0, 0], [1, 2], [3, 2], [4, 0]], samples: 20 });';
  const b64 = Buffer.from(code, 'utf8').toString('base64url');
  const t = await H.open(`sandbox.html#code=${b64}`);
  await t.frames(5);
  await new Promise((r) => setTimeout(r, 500));
  const st = await t.page.evaluate(() => ({
    code: document.getElementById('sb-code').value, out: document.getElementById('sb-output').textContent,
    note: !document.getElementById('sb-link-note').hidden, runs: document.body.dataset.runs,
  }));
  assert.equal(st.code, code, 'the link\'s code is shown exactly (UTF-8)');
  assert.equal(st.out, '', 'nothing ran on load');
  assert.equal(st.runs, undefined);
  assert.equal(st.note, true, 'the page says the code came with the link');
  await t.page.click('#sb-run');
  await t.page.waitForFunction(() => document.body.dataset.run === 'ok');
  assert.match(await t.page.textContent('#sb-output'), /ran from the link: é ∞ 1\n/, 'it ran once: when Run was pressed');
  assert.equal(await t.page.evaluate(() => globalThis.__sandboxRan), undefined, 'it ran off the page');
  // Share puts the code in the link (base64url, no padding) that opens it again
  await t.page.fill('#sb-code', 'print(1)');
  await t.page.click('#sb-share');
  const link = await t.page.inputValue('#sb-link');
  assert.equal(link.split('#code=')[1], Buffer.from('print(1)').toString('base64url'));
  assert.ok(!link.includes('='.repeat(2)) && !/[+/]/.test(link.split('#code=')[1]));
  t.assertClean();
  await t.close();
});

test('Ctrl+Enter runs; plot() changes the 2D canvas; surface() draws in the 3D view', async () => {
  const t = await H.open('sandbox.html');
  const r0 = await runCode(t, 'print("hello")', { key: true });
  assert.equal(r0.run, 'ok');
  assert.equal(r0.output, 'hello\n');
  await runCode(t, 'plot([[0, 0], [1, 1]]);');
  const h1 = await t.canvasHash('#sb-plot canvas');
  const r1 = await runCode(t, 'const c = sl.bsplineCurve({ points: [[0, 0], [1, 2], [3, -1], [4, 0]], samples: 100 });\nplot(c, { label: "C" });\nplot.points([[0, 0], [1, 2], [3, -1], [4, 0]]);', { key: true });
  assert.equal(r1.run, 'ok');
  const h2 = await t.canvasHash('#sb-plot canvas');
  assert.notEqual(h1, h2, 'the plot changed');
  const items = await t.page.evaluate(() => window.splinelabSandbox.items.map((i) => [i.kind, i.data.length]));
  assert.deepEqual(items, [['line', 200], ['points', 4]]);
  const r2 = await runCode(t, 'const { grid, periodicU, periodicV } = sl.quasiCubicPreset({ name: "sphere" });\nsurface(sl.quasiCubicSurface({ grid, periodicU, periodicV, samplesU: 20, samplesV: 20, mesh: true }));');
  assert.equal(r2.run, 'ok');
  await t.frames(3);
  const v = await t.page.evaluate(() => {
    const view = window.splinelabSandbox.view;
    const c = document.querySelector('#sb-view canvas');
    const r = c.getBoundingClientRect();
    return { objects: [...view.objects.values()].map((o) => o.kind), gl: !!view.gl, fallback: !!document.querySelector('#sb-view .sl-view3d-fallback'), w: r.width, h: r.height, hidden: document.getElementById('sb-view-panel').hidden };
  });
  assert.deepEqual(v.objects, ['mesh']);
  assert.equal(v.hidden, false);
  assert.ok(v.gl || v.fallback, 'WebGL2 or the fallback message');
  if (v.gl) {
    // pixels: the sphere covers part of the canvas with non-background colours
    const painted = await t.page.evaluate(() => {
      const view = window.splinelabSandbox.view;
      view.renderNow();
      const gl = view.gl;
      const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
      const px = new Uint8Array(4 * w * h);
      gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
      let n = 0;
      for (let i = 0; i < px.length; i += 4) if (px[i] < 240 || px[i + 1] < 240 || px[i + 2] < 240) n++;
      return n / (w * h);
    });
    assert.ok(painted > 0.05, `the surface covers ${(painted * 100).toFixed(1)} % of the 3D view`);
  }
  // a returned result is drawn too: points on the plot, a mesh in the 3D view (a snippet's `return { … }`)
  const r3 = await runCode(t, 'const network = sl.networkExample({ name: "uniform-dome" });\nreturn { curve: sl.bsplineCurve({ points: [[0, 0], [1, 1], [2, 0], [3, 1]], samples: 10 }), S: sl.crissCrossSurface({ network, samplesU: 6, samplesV: 6, mesh: true }) };');
  assert.equal(r3.run, 'ok');
  assert.match(r3.output, /^Returned:\n\{\n {2}curve: \{/);
  assert.equal(await t.page.evaluate(() => window.splinelabSandbox.items.length), 1);
  assert.equal(await t.page.evaluate(() => window.splinelabSandbox.view.objects.size), 1);
  t.assertClean();
  await t.close();
});

test('every ready example runs cleanly and draws; screenshots at desktop and phone size', async () => {
  for (const [name, viewport] of [['desktop', { width: 1366, height: 900 }], ['phone', { width: 390, height: 844 }]]) {
    const t = await H.open('sandbox.html', { viewport });
    const options = await t.page.$$eval('#sb-examples option', (os) => os.map((o) => o.value).filter(Boolean));
    assert.deepEqual(options, EXAMPLES.map((e) => e.id));
    assert.equal(EXAMPLES.filter((e) => e.paper).length, 5, 'one example per paper');
    assert.deepEqual(new Set(EXAMPLES.map((e) => e.paper).filter(Boolean)).size, 5);
    for (const id of options) {
      const before = await t.page.evaluate(() => Number(document.body.dataset.runs || 0));
      await t.page.selectOption('#sb-examples', id);
      await t.page.click('#sb-run');
      await t.page.waitForFunction((n) => Number(document.body.dataset.runs || 0) > n && document.body.dataset.run !== 'running', before);
      const st = await t.page.evaluate(() => ({ run: document.body.dataset.run, err: document.getElementById('sb-error').textContent, drawn: window.splinelabSandbox.items.length + (window.splinelabSandbox.view?.objects.size || 0) }));
      assert.equal(st.run, 'ok', `${id}: ${st.err}`);
      assert.ok(st.drawn > 0, `${id} draws something`);
      if (id === 'bspline-basics' || id === 'quasi-cubic') {
        await t.frames(3);
        await t.page.screenshot({ path: join(OUT, `sandbox-${name}-${id}.png`), fullPage: true });
      }
    }
    // nothing wider than the screen (the code area scrolls inside itself)
    const overflow = await t.page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth);
    assert.ok(overflow <= 0, `${name}: page overflows by ${overflow}px`);
    t.assertClean();
    await t.close();
  }
});

test('the gallery links to the sandbox; the sandbox speaks the reader\'s language and passes axe', async () => {
  const t = await H.open('index.html');
  assert.equal(await t.page.$$eval('a[href="sandbox.html"]', (as) => as.length > 0), true);
  await t.page.click('a[href="sandbox.html"]');
  await t.page.waitForFunction(() => document.documentElement.dataset.ready === 'true');
  const text = await t.page.evaluate(() => [document.body.textContent, ...[...document.querySelectorAll('option, [aria-label], [title]')].map((e) => e.textContent + (e.getAttribute('aria-label') || '') + (e.title || ''))].join('\n'));
  assert.doesNotMatch(text, /seed|curves\.md|surfaces\.md/i);
  const code = await t.page.getByRole('textbox', { name: 'Code' });
  assert.equal(await code.count(), 1, 'the code area\'s accessible name is "Code"');
  if (typeof t.axe === 'function') assert.deepEqual((await t.axe()).map((v) => `${v.id}: ${v.help}`), []);
  t.assertClean();
  await t.close();
});
