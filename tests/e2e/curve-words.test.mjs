// Figures in words (issue 25): the main curve plot's description (the element named first by the canvas'
// aria-describedby, visually hidden) states what the drawn curve does, from the core's curveFacts of the demo's own
// samples: its extremes, its inflections, how close it passes to the data, and its continuity at the joints. Each
// check compares the numbers with an independent computation (a symmetric configuration's highest point or centre,
// an interpolant's distance 0 to its data). One page open per demo, no sleeps.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { deflateRawSync } from 'node:zlib';
import { startHarness } from './harness.mjs';

let H;
before(async () => { H = await startHarness({ viewport: { width: 1280, height: 720 } }); });
after(async () => { await H?.close(); });

const link = (demo, state) => `#${demo}/v1.${deflateRawSync(Buffer.from(JSON.stringify(state))).toString('base64url')}`;
const num = (s) => Number(s.replace('−', '-'));

/** The description of the plot `sel` once it contains `until` (a regular expression). */
async function described(t, sel, until) {
  const handle = await t.page.waitForFunction(([s, src]) => {
    const c = document.querySelector(s);
    const id = c?.getAttribute('aria-describedby')?.split(' ')[0];
    const text = id ? document.getElementById(id)?.textContent ?? '' : '';
    return new RegExp(src).test(text) ? text : null;
  }, [sel, until.source], { timeout: 10_000 });
  return /** @type {string} */ (await handle.jsonValue());
}
/** "(x, y) at u = v" after `label` in the text → [x, y, u]. */
function pointAfter(text, label) {
  const m = text.match(new RegExp(`${label} \\((\\S+), (\\S+)\\) at u = (\\S+?)[,;.]? `));
  assert.ok(m, `"${label} (x, y) at u = …" in: ${text}`);
  return m.slice(1, 4).map(num);
}
const near = (a, b, tol, what) => assert.ok(Math.abs(a - b) <= tol, `${what}: ${a} vs ${b}`);

test('bspline-basics: a symmetric arch has its highest point in the middle; a point-symmetric S one inflection at its centre; C¹ at a double knot', async () => {
  // the Bézier arch P = (0,0), (1,2), (2,2), (3,0): C(½) = (1.5, 1.5), no inflection, no inner knot
  const arch = { degree: 3, points: [[0, 0], [1, 2], [2, 2], [3, 0]], knots: [0, 0, 0, 0, 1, 1, 1, 1] };
  const t = await H.open(`/${link('bspline-basics', arch)}`);
  const sel = 'canvas[data-plot="curve"]';
  let text = await described(t, sel, /highest point/);
  const [x, y, u] = pointAfter(text, 'highest point is');
  near(x, 1.5, 5e-3, 'x'); near(y, 1.5, 5e-3, 'y'); near(u, 0.5, 5e-3, 'u');
  assert.match(text, /it has no inflections/);
  assert.match(text, /runs from x = 0 to 3;/);
  assert.match(text, /one polynomial piece/);
  // six points symmetric about (2.5, 0) with the double knot ½: the curve is symmetric about C(½) = (2.5, 0), which
  // is its one inflection; C^(3−2) = C¹ there
  const s = { degree: 3, points: [[0, 0], [1, 2], [2, 1], [3, -1], [4, -2], [5, 0]], knots: [0, 0, 0, 0, 0.5, 0.5, 1, 1, 1, 1] };
  await t.page.evaluate((h) => { location.hash = h; }, link('bspline-basics', s));
  text = await described(t, sel, /one inflection/);
  const m = text.match(/one inflection, at \((\S+), (\S+)\), u = (\S+?);/);
  assert.ok(m, text);
  near(num(m[1]), 2.5, 5e-3, 'inflection x'); near(num(m[2]), 0, 5e-3, 'inflection y'); near(num(m[3]), 0.5, 5e-3, 'inflection u');
  assert.match(text, /At its joints it is C¹ at the knot u = 0\.5 \(degree 3/);
  assert.doesNotMatch(text, /[A-Za-z]_\d|W\d/);
  t.assertClean();
  await t.close();
});

test('interp-approx: the interpolating B2-spline (a = 0) passes through its data W₁ … W₇', async () => {
  const t = await H.open('#interp-approx');
  const text = await described(t, 'canvas[data-plot="curve"]', /data point/);
  // a = 0 interpolates: every joint is its data point (measured on the drawn polyline: ≤ 0.0005 → "through")
  assert.match(text, /It passes through every data point \(farthest: W[₁-₇], 0\)/);
  // the curve runs from its joint at W₁ = (0.6, 1.6) to the one at W₇ = (6.4, 2.2) (the default data, presets.js)
  assert.match(text, /runs from x = 0\.6 to 6\.4;/);
  t.assertClean();
  await t.close();
});

test('noisy-data: the interpolating fit passes through every data point; the approximating one within its largest residual', async () => {
  const t = await H.open('#noisy-data');
  const interp = await described(t, 'canvas[data-plot="interp"]', /data point/);
  // a = 0 interpolates: the data lie on the curve; measured on the drawn polyline (600 samples of a wiggly fit) a
  // chord cuts inside the curve by its sagitta, a few thousandths here
  const i = interp.match(/The fit runs .* It passes within (\S+) of every data point \(farthest: D[₀-₉]+, \S+; RMS \S+\)/);
  assert.ok(i && num(i[1]) < 0.005, interp);
  const approx = await described(t, 'canvas[data-plot="approx"]', /data point/);
  const m = approx.match(/It passes within (\S+) of every data point \(farthest: D([₀-₉]+), (\S+); RMS (\S+)\)/);
  assert.ok(m, approx);
  // the distance to the curve is at most the residual |Lᵃ(uᵢ) − Dᵢ| (one point of the curve); the default data
  // (sine, 60 points, σ = 0.2, draw 1) at a = 0.25 have the largest residual 0.339
  const far = num(m[1]);
  assert.ok(far > 0.05 && far <= 0.34, `farthest distance ${far}`);
  assert.ok(num(m[4]) > 0 && num(m[4]) < far, `RMS ${m[4]} below the largest ${far}`);
  t.assertClean();
  await t.close();
});

test('quasi-cubic-curves: the closed curve of a square is convex and symmetric; C² at the joints', async () => {
  const sq = { preset: 'free', closed: true, alpha: 1, points: [[0, 0], [2, 0], [2, 2], [0, 2]] };
  const t = await H.open(`/${link('quasi-cubic-curves', sq)}`);
  const text = await described(t, 'canvas[data-plot="curve"]', /highest point/);
  // symmetric about x = 1 and y = 1: highest and lowest points on x = 1, the leftmost and rightmost at equal distance
  const [hx, hy] = pointAfter(text, 'highest point is');
  const [lx, ly] = pointAfter(text, 'its lowest');
  near(hx, 1, 5e-3, 'highest x'); near(lx, 1, 5e-3, 'lowest x'); near(hy + ly, 2, 5e-3, 'highest y + lowest y');
  const m = text.match(/runs from x = (\S+) to (\S+);/);
  near(num(m[1]) + num(m[2]), 2, 5e-3, 'left + right');
  assert.match(text, /it has no inflections/);
  assert.match(text, /At its joints it is C² \(for every α\)\./);
  t.assertClean();
  await t.close();
});

test('blended-interpolation: the BIS passes through b₀ … bₙ; C² for k = 3', async () => {
  const t = await H.open('#blended-interpolation');
  const text = await described(t, 'canvas[data-plot="curve"]', /data point/);
  assert.match(text, /It passes through every data point \(farthest: b[₀-₉]+, 0\)/);
  assert.match(text, /At its joints it is C² \(k = 3\)\./);
  await t.screenshot('curve-words-blended');
  t.assertClean();
  await t.close();
});
