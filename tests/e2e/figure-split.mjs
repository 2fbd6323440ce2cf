// Before/after check for refactors of the demos that must not change what a reader sees (issue 29, "demos as
// figure files"): opens each tab and preset of bezier-remodel, knot-modification and interp-approx (gallery
// page, embed page, state links, a few clicks) at 1366×900 and 390×844, and records a full-page screenshot, the
// page's visible text and the demo's state after the clicks (what the URL holds).
//
//   node tests/e2e/figure-split.mjs capture <name> [demo…]   → tests/e2e/out/figure-split/<name>/
//   node tests/e2e/figure-split.mjs compare <a> <b>          → differing pixels and texts per view (exit 1 if any)
//   VIEWS=<regex> limits a capture to the views whose name matches.
//
// Not a *.test.mjs: its reference is the code before the refactor, captured on the spot (nothing committed).
import { writeFile, readFile, mkdir, readdir } from 'node:fs/promises';
import { join } from 'node:path';
import { startHarness, OUT } from './harness.mjs';
import { decodePng } from './png-ink.mjs';

const link = (id, state) => `#${id}/v0.${Buffer.from(JSON.stringify(state)).toString('base64url')}`;
const clickLabel = (text) => async (t) => { await t.page.click(`label:text-is("${text}")`); await t.frames(3); };
// a choice of a buttonGroup: the fieldset whose legend starts with `legend`, then its label `text`
const choose = (legend, text) => async (t) => {
  await t.page.locator('fieldset.ctl-group:visible').filter({ has: t.page.locator(`legend:has-text("${legend}")`) }).first().locator(`label:text-is("${text}")`).click();
  await t.frames(3);
};
const clickButton = (text) => async (t) => { await t.page.click(`button:text-is("${text}")`); await t.frames(3); };

// (w29-figures2) curve-networks' "API time" readout without its measured number (see VIEWS)
const apiTimeFixed = async (t) => {
  await t.page.evaluate(() => {
    for (const el of document.querySelectorAll('.ctl-readout')) {
      const v = el.querySelector('.ctl-readout-value');
      if (v && el.querySelector('.ctl-readout-label')?.textContent === 'API time (networkSurfaces)') v.textContent = v.textContent.replace(/^[\d.]+ ms/, '— ms');
    }
  });
  await t.frames(3);
};
/** [name, route, actions?] per demo. */
export const VIEWS = {
  'bezier-remodel': [
    ['default', '#bezier-remodel'],
    ['embed', 'embed.html#bezier-remodel'],
    ['fig2', '#bezier-remodel', [choose('Example', 'Fig. 2')]],
    ['quartic', '#bezier-remodel', [choose('Example', 'Quartic from a B-spline')]],
    ['no-eq9-r0', '#bezier-remodel', [clickLabel('Enforce eq. (9)'), choose('Keep Cʳ: r', '0')]],
    ['steps-remodel', link('bezier-remodel', { step: 2 })],
    ['steps-casteljau', link('bezier-remodel', { stepAlgo: 'casteljau', step: 3, stepU: 2.2 })],
    ['joint3-u', link('bezier-remodel', { joint: 3, u: 2.5, showPolygon: false })],
    ['surface', link('bezier-remodel', { tab: 'surface' })],
    ['surface-fig4', link('bezier-remodel', { tab: 'surface' }), [choose('Example (§4)', 'Fig. 4')]],
    ['surface-bi', link('bezier-remodel', { tab: 'surface' }), [choose('Construction', 'Bi-degree, u and v (§4.2)')]],
    ['surface-bi-col3', link('bezier-remodel', { tab: 'surface' }), [clickLabel('Bi-degree, u and v (§4.2)'), choose('Column l', '3')]],
    ['embed-surface', `embed.html${link('bezier-remodel', { tab: 'surface' })}`],
  ],
  'knot-modification': [
    ['default', '#knot-modification'],
    ['embed', 'embed.html#knot-modification'],
    ['order3', '#knot-modification', [choose('Order k', '3')]],
    ['steps', link('knot-modification', { step: 2 })],
    ['track-all-extend', link('knot-modification', { trackAll: true, extend: true, up: 3.1 })],
    ['no-family', link('knot-modification', { showFamily: false, showEnvelope: false, showLimits: false })],
    ['surface', link('knot-modification', { tab: 'surface' })],
    ['surface-u', link('knot-modification', { tab: 'surface', smove: 'u', sup: 3.2 })],
    ['embed-surface', `embed.html${link('knot-modification', { tab: 'surface' })}`],
  ],
  'interp-approx': [
    ['default', '#interp-approx'],
    ['embed', 'embed.html#interp-approx'],
    ...['Fig. 6: a = −0.1 … 0.2', 'Fig. 7: p = 0 … 0.3', 'Fig. 8: uneven spacing (uniform)', 'Fig. 10: the chord-length cure', 'Fig. 13: stairs, K off', 'Fig. 14: K = 20', 'Fig. 19: automatic tension']
      .map((label) => [`preset-${label.split(':')[0].replace(/\W+/g, '')}`, '#interp-approx', [clickButton(label)]]),
    ['a-sixth-build-comb', link('interp-approx', { a: 1 / 6, showBuild: true, showComb: true, u: 2.5 })],
    ['steps', link('interp-approx', { step: 3 })],
    ['eq5-printed', link('interp-approx', { eq5Printed: true, construction: 'section3', knots: 'uniform' })],
    ['embed-a', `embed.html${link('interp-approx', { a: 0.1 })}`],
  ],
  // ---- w29-figures3: bspline-basics, quasi-cubic-curves, blended-interpolation ----
  'bspline-basics': [
    ['default', '#bspline-basics'],
    ['embed', 'embed.html#bspline-basics'],
    ['degree2', '#bspline-basics', [choose('Degree p', '2')]],
    ['degree5', '#bspline-basics', [choose('Degree p', '5')]],
    ['steps-deboor', link('bspline-basics', { step: 2 })],
    ['steps-insert', link('bspline-basics', { stepAlgo: 'insert', step: 3, u: 0.62 })],
    ['knots-no-poly-sum', link('bspline-basics', { knots: [0, 0, 0, 0, 0.1, 0.5, 0.9, 1, 1, 1, 1], showPolygon: false, showSum: false, u: 0.8 })],
    ['knots-uniform-btn', link('bspline-basics', { knots: [0, 0, 0, 0, 0.1, 0.5, 0.9, 1, 1, 1, 1] }), [clickButton('Uniform knots')]],
    ['add-point', '#bspline-basics', [clickButton('Add point')]],
    ['embed-steps', `embed.html${link('bspline-basics', { step: 4 })}`],
  ],
  'quasi-cubic-curves': [
    ['default', '#quasi-cubic-curves'],
    ['embed', 'embed.html#quasi-cubic-curves'],
    ...['Ellipse', 'Circle', 'Parabola', 'Sine'].map((p) => [`preset-${p}`, '#quasi-cubic-curves', [choose('Preset', p)]]),
    ['closed', '#quasi-cubic-curves', [clickLabel('Closed (periodic) curve')]],
    ['alpha3-u', link('quasi-cubic-curves', { alpha: 3, u: 2.3 })],
    ['steps-piece', link('quasi-cubic-curves', { step: 1, u: 1.4 })],
    ['steps-sum', link('quasi-cubic-curves', { step: 4 })],
    ['no-ghost-poly', link('quasi-cubic-curves', { showGhost: false, showPolygon: false, alpha: -2 })],
    ['embed-sine', `embed.html${link('quasi-cubic-curves', { preset: 'sine' })}`],
  ],
  'blended-interpolation': [
    ['default', '#blended-interpolation'],
    ['embed', 'embed.html#blended-interpolation'],
    ['titanium', '#blended-interpolation', [choose('Data', 'Titanium')]],
    ['rpn14', '#blended-interpolation', [choose('Data', 'RPN 14')]],
    ['k2', '#blended-interpolation', [choose('Allocated function order k', 'k = 2 (C¹ only)')]],
    ['fair', '#blended-interpolation', [clickButton('Fair by curvature')]],
    ['titanium-fair', '#blended-interpolation', [choose('Data', 'Titanium'), clickButton('Fair by curvature')]],
    ['beta-u', link('blended-interpolation', { selected: 2, beta: [1, 1, 0.3, 1.8, 1, 1, 1], u: 2.5, showSpline: false, k: 4 })],
    ['add-point', '#blended-interpolation', [clickButton('Add point')]],
    ['embed-titanium', `embed.html${link('blended-interpolation', { dataset: 'titanium' })}`],
  ],
  // ---- end w29-figures3 ----
  // ---- w29-figures2: curve-networks, criss-cross-basis, noisy-data (added by the figures2 helper) ----
  // curve-networks shows a measurement, "API time (networkSurfaces): 21.6 ms (…)", which differs between two runs
  // of the same code: every view of it ends with `apiTimeFixed`, which writes "— ms" in place of the number.
  'curve-networks': [
    ['default', '#curve-networks', [apiTimeFixed]],
    ['embed', 'embed.html#curve-networks', [apiTimeFixed]],
    ...['paper-18x4', 'three-sided', 'paper-5x4', 'separable', 'dome'].map((preset) => [`preset-${preset}`, link('curve-networks', { preset }), [apiTimeFixed]]),
    ['overlay-SG', link('curve-networks', { layout: 'overlay', colorBy: 'SG', show: { S: true, T: true, G: true, GB: true } }), [apiTimeFixed]],
    ['components-tri-cell', link('curve-networks', { components: true, triangulation: true, cell: [2, 2], density: 24 }), [apiTimeFixed]],
    ['step0', link('curve-networks', { step: 0 }), [apiTimeFixed]],
    ['step3', link('curve-networks', { step: 3 }), [apiTimeFixed]],
    ['step5', link('curve-networks', { step: 5 }), [apiTimeFixed]],
    ['embed-separable', `embed.html${link('curve-networks', { preset: 'separable', colorBy: 'ST' })}`, [apiTimeFixed]],
  ],
  'criss-cross-basis': [
    ['default', '#criss-cross-basis'],
    ['embed', 'embed.html#criss-cross-basis'],
    ['corner', link('criss-cross-basis', { i: 0, j: 0, cell: [1, 1] })],
    ['no-map-no-ord', link('criss-cross-basis', { map: false, ordinates: false })],
    ['grid-4x2', link('criss-cross-basis', { u: [0, 0.25, 0.5, 0.75, 1], v: [0, 0.5, 1], i: 5, j: 3, cell: [4, 2] })],
    ['uniform', '#criss-cross-basis', [clickButton('Uniform knots')]],
  ],
  'noisy-data': [
    ['default', '#noisy-data'],
    ['embed', 'embed.html#noisy-data'],
    ['titanium', link('noisy-data', { source: 'dataset', dataset: 'titanium_heat' })],
    ['rpn14-uniform', link('noisy-data', { source: 'dataset', dataset: 'rpn14', knots: 'uniform', a: 0.1 })],
    ['csv', link('noisy-data', { source: 'csv', csv: 'x, y\n0, 0.1\n1, 0.9\n2, 0.2\n3, 1.1\n4, 0.4\n5, 1.3' })],
    ['csv-bad', link('noisy-data', { source: 'csv', csv: '0, 1\n1, abc' })],
    ['arc-clean', link('noisy-data', { curve: 'arc', sigma: 0, count: 30, a: 0, p: 0.3 })],
    ['step-seed', link('noisy-data', { curve: 'step', seed: 7, sigma: 0.5 })],
    ['embed-a', `embed.html${link('noisy-data', { a: -0.05 })}`],
  ],
  // ---- end w29-figures2 block ----
};
const VIEWPORTS = { w1366: { width: 1366, height: 900 }, w390: { width: 390, height: 844 } };

async function capture(name, demos) {
  const dir = join(OUT, 'figure-split', name);
  await mkdir(dir, { recursive: true });
  const H = await startHarness();
  const texts = {};
  try {
    for (const id of demos) {
      for (const [view, route, actions = []] of VIEWS[id].filter(([v]) => !process.env.VIEWS || new RegExp(process.env.VIEWS).test(v))) {
        for (const [vp, viewport] of Object.entries(VIEWPORTS)) {
          const key = `${id}--${view}--${vp}`;
          const t = await H.open(route, { viewport });
          try {
            for (const a of actions) await a(t);
            // the plots' screen-reader text is throttled (600 ms) and the state save debounced: let both land
            await t.page.waitForTimeout(900);
            // the same scroll and pointer for every run: a click leaves the page, the controls' sheet and the
            // hover state where the browser put them, which differs between two runs of the same code
            await t.page.mouse.move(1, 1);
            await t.page.evaluate(() => { for (const el of document.querySelectorAll('*')) if (el.scrollTop) el.scrollTop = 0; window.scrollTo(0, 0); });
            await t.frames(3);
            await t.page.screenshot({ path: join(dir, `${key}.png`), fullPage: true });
            const text = await t.page.evaluate(() => document.body.innerText);
            const state = await t.page.evaluate(() => JSON.stringify(window.splinelab.current()?.state ?? null));
            texts[key] = { text, state, errors: t.errors() };
          } catch (e) {
            texts[key] = { failed: String(e.message || e) };
          }
          await t.close();
          process.stdout.write(`${key}${texts[key].failed ? ` FAILED: ${texts[key].failed}` : ''}\n`);
        }
      }
    }
  } finally { await H.close(); }
  let old = {};
  try { old = JSON.parse(await readFile(join(dir, 'texts.json'), 'utf8')); } catch { /* first run */ }
  await writeFile(join(dir, 'texts.json'), JSON.stringify({ ...old, ...texts }, null, 1));
}

/** Differing pixels of two PNGs (a size change counts every pixel of the larger one). */
function pixelDiff(a, b) {
  const A = decodePng(a), B = decodePng(b);
  if (A.width !== B.width || A.height !== B.height) return { diff: Math.max(A.width * A.height, B.width * B.height), size: `${A.width}×${A.height} vs ${B.width}×${B.height}` };
  let diff = 0;
  for (let i = 0, n = A.width * A.height; i < n; i++) {
    for (let c = 0; c < 3; c++) if (A.pixels[i * A.bpp + c] !== B.pixels[i * B.bpp + c]) { diff++; break; }
  }
  return { diff, size: `${A.width}×${A.height}` };
}

async function compare(a, b) {
  const da = join(OUT, 'figure-split', a), db = join(OUT, 'figure-split', b);
  const ta = JSON.parse(await readFile(join(da, 'texts.json'), 'utf8')), tb = JSON.parse(await readFile(join(db, 'texts.json'), 'utf8'));
  let bad = 0;
  for (const f of (await readdir(db)).filter((x) => x.endsWith('.png')).sort()) {
    const key = f.replace(/\.png$/, '');
    let line;
    try {
      const { diff, size } = pixelDiff(await readFile(join(da, f)), await readFile(join(db, f)));
      const same = (k) => ta[key]?.[k] === tb[key]?.[k];
      const txt = same('text') ? 'text =' : 'TEXT DIFFERS', st = same('state') ? 'state =' : 'STATE DIFFERS';
      if (diff || !same('text') || !same('state')) bad++;
      line = `${key.padEnd(52)} ${size.padEnd(12)} ${String(diff).padStart(7)} px  ${txt}  ${st}`;
    } catch (e) { bad++; line = `${key}: ${e.message}`; }
    console.log(line);
  }
  for (const [k, v] of Object.entries(tb)) if (v.failed || v.errors?.length) console.log(`${k}: ${v.failed || v.errors.join('; ')}`);
  console.log(bad ? `${bad} view(s) differ` : 'all views identical');
  process.exitCode = bad ? 1 : 0;
}

const [cmd, ...args] = process.argv.slice(2);
if (cmd === 'capture') await capture(args[0], args.length > 1 ? args.slice(1) : Object.keys(VIEWS));
else if (cmd === 'compare') await compare(args[0], args[1]);
else console.log('usage: node tests/e2e/figure-split.mjs capture <name> [demo…] | compare <a> <b>');
