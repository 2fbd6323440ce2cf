// The papers page: one section per paper, every figure (or theorem) with our caption, a link to the demo
// state that reproduces it (or an honest note), the corrections, and the references. Built from the tables
// below with h() (no innerHTML); the demo links are encoded with the same code the app uses for its URLs.

import { h } from './lib/dom.js';
import { math } from './lib/mathml.js';
import { encodeState, buildHash } from './lib/state.js';
import { PAPERS } from './lib/papers-ref.js';
import { importDemo } from './demos/index.js';

// ---------------------------------------------------------------------------------------------------------
// The papers (cited by authors and title; the publication details that the papers' texts print)
// ---------------------------------------------------------------------------------------------------------
// PAPERS lives in lib/papers-ref.js (shared with the demos' references); re-exported here.
export { PAPERS };

// ---------------------------------------------------------------------------------------------------------
// Figures. demo + state: the live view (a partial state: the demo fills what is missing from its defaults).
// chosen: the paper prints no data for it (the data here are ours). nr: why it cannot be reproduced.
// ---------------------------------------------------------------------------------------------------------
const FIG8_POINTS = [[-0.3, -0.3], [0, 0], [0.25, 0.3], [0.5, 0.35], [4, 0.6], [4.3, 1], [4.4, 3.6], [4.7, 4], [5.2, 4.1], [5.6, 4.2]];
const UNIFORM_POINTS = [[-1, 0], [0, 0], [1, 2], [2, 2.2], [3, 0.2], [4, 0], [5, 2], [6, 2.2], [7, 0.4], [8, 0.2]];
const STAIRS = [[-1, 0], [0, 0], [3, 0], [3, 0.5], [6, 0.5], [6, 1], [9, 1], [9, 1.5], [12, 1.5], [13, 1.5]];
// many points on a rounded object (Figs. 11–12)
const DENSE = Array.from({ length: 24 }, (_, i) => {
  const t = (i - 1) / 21 * 2 * Math.PI;
  return [Math.round(400 * (Math.cos(t) + 0.15 * Math.cos(3 * t))) / 100, Math.round(250 * Math.sin(t)) / 100];
});
const SMALL_TURNS = [[-1, 0], [0, 0], [1, 0.09], [2, 0.26], [3, 0.52], [4, 0.86], [5, 1.28], [6, 1.78]];
const QUICK_TURNS = [[-1, 0], [0, 0], [1, 0], [1.5, 0.87], [1, 1.73], [0, 1.73], [-0.5, 0.87], [-1.5, 0.87]];
const REVERSAL = [[-1, 0], [0, 0], [2, 0], [4, 0], [1, 0.2], [3, 0.4], [5, 0.4], [6, 0.4]];
const TURN_RETURN = [[-1, 0], [0, 0], [1, 0], [1.87, 0.5], [2.87, 0.5], [3.73, 1], [4.73, 1], [5.73, 1]];
const CURVE_SHAPE = [[-0.6, -0.4], [0, 0], [0.6, 1.6], [1.8, 2.4], [2.4, 2.2], [3.6, 0.2], [4.4, 0.1], [5.6, 1.8], [6.4, 2.2], [7.6, 1.2], [8.2, 0.6]];
// Fig. 9 of Kuklišová §4: the data W₁ = (0, 0), W₂ = (0, C), W₃ = (B, C), W₄ = (B, 0) with B = C = 1, between the
// end points the demo's automatic ends reflect through W₁ and W₄ (W₋₁, W₀ and W₅, W₆)
const FIG9_POINTS = [[-1, -1], [0, -1], [0, 0], [0, 1], [1, 1], [1, 0], [1, -1], [2, -1]];
const FIG9_STATE = { points: FIG9_POINTS, autoEnds: true, construction: 'nonuniform', knots: 'chord', a: 0, p: 1 / 6, c2: 1, autoTension: 'off', showBuild: true, useK: false, family: null, preset: '' };
// the quasi-cubic demo's sine preset (quasiCubicPreset({ name: 'sine' }): 4 segments, α = 0), carried by the link
const SINE_POINTS = [[-3, -1.5], [-2, 1], [-1, -0.5], [0, 0], [1, 0.5], [2, -1], [3, 1.5]];
const ones = (n, at, v) => Array.from({ length: n }, (_, i) => (i === at ? v : 1));

// The labels of the demos' readouts of printed claims (a figure whose view shows one failing lists it in
// expect.fails; CLAIM_READOUTS below says why on the card).
const CLAIM_B = 'Printed: “a = 1/6, p = 0 gives the B-spline”';
const CLAIM_SG = 'Printed: ‖S − G‖∞ = 4.4·10⁻¹⁵ (S = G)';

// expect: what each figure's live view must show, read on the opened page by tests/e2e/papers-facts.test.mjs —
//   pressed: labels of checked buttons · selected: { select label: option shown } · readouts: { label (start):
//   { below | above | near: [x, tol] | match: regex source } } · handles: { group: count } · points: { group:
//   [[x, y], …] } · labels: texts drawn in the main plot · inView: every point and label of the main plot inside
//   it · points3d: { 3D point set: count } · text: strings the demo shows · polygonDistance: [d, tol], the largest
//   distance of the curve from its data polygon (measured with the view's own wasm call) · fails: readouts of
//   printed claims that read "fails" here (the card explains each).
export const FIGURES = {
  '000': [
    { n: 1, caption: 'An interpolating curve through a set of points: the curve passes through every one of them.', demo: 'interp-approx', state: { a: 0 }, tryit: 'Drag a point: only the nearby part of the curve moves (local control).', chosen: true,
      expect: { pressed: ['chord length', 'non-uniform (§4–5)'], handles: { 'data point': 7 }, readouts: { Domain: { match: 'n = 7$' } }, fails: [CLAIM_B] } },
    { n: 2, caption: 'The interpolating curve on noisy data: it follows every wiggle of the noise.', demo: 'noisy-data', state: { a: 0, source: 'curve', curve: 'sine', sigma: 0.15 }, tryit: 'Raise the noise σ and watch the a = 0 curve copy it.', chosen: true,
      expect: { pressed: ['known curve + noise'], selected: { 'True curve': 'sine' }, readouts: { Data: { match: 'sine \\+ noise σ = 0\\.15' } } } },
    { n: 3, caption: 'An approximating curve of the same family on the same noisy data: it smooths the noise away.', demo: 'noisy-data', state: { a: 0.12, source: 'curve', curve: 'sine', sigma: 0.15 }, tryit: 'Move a towards 1/6 and compare the error numbers with a = 0.', chosen: true,
      expect: { pressed: ['known curve + noise'], selected: { 'True curve': 'sine' }, readouts: { Data: { match: 'σ = 0\\.15' } } } },
    { n: 4, caption: 'A network of curves in u and v, the input of a spline-blended surface $G = G_1 + G_2 - G_{12}$ (eq. (4)).', demo: 'b2-surfaces', state: { mode: 'blended', shape: 'hill' }, tryit: 'Switch between the tensor-product and the spline-blended surface over the same data.', chosen: true,
      expect: { pressed: ['spline-blended (§7)'], selected: { Data: 'hill' } } },
    { n: 5, caption: 'A B2-spline curve: it passes through its joints, and its even control vertices pull it like those of a cubic B-spline.', demo: 'interp-approx', state: { showBuild: true, a: 0 }, tryit: 'With “How it is built” on, compare the joints (squares) with the even vertices (diamonds).', chosen: true,
      expect: { pressed: ['chord length', 'non-uniform (§4–5)'], handles: { 'data point': 7 }, fails: [CLAIM_B] } },
    { n: 6, caption: 'The uniform curve of §3 for the approximation parameter a = −0.1, 0, 0.1, 0.2: below 0 it overshoots, at 0 it interpolates, above 0 it approximates.', demo: 'interp-approx', state: { preset: 'fig6', points: UNIFORM_POINTS, construction: 'section3', knots: 'uniform', a: 0, p: 0.05, autoTension: 'off', useK: false, family: { key: 'a', values: [-0.1, 0, 0.1, 0.2] } }, tryit: 'Move a slowly from 0 to 1/6.', chosen: true,
      expect: { pressed: ['uniform (§3)'], labels: ['a = −0.1', 'a = 0', 'a = 0.1', 'a = 0.2'], readouts: { [CLAIM_B]: { match: 'holds' } } } },
    { n: 7, caption: 'The same curve for the tension p = 0, 0.1, 0.2, 0.3: a larger p makes the curve fuller between the points.', demo: 'interp-approx', state: { preset: 'fig7', points: UNIFORM_POINTS, construction: 'section3', knots: 'uniform', a: 0, p: 0.1, autoTension: 'off', useK: false, family: { key: 'p', values: [0, 0.1, 0.2, 0.3] } }, tryit: 'Try p = 1/12: then the uniform curve reproduces cubic polynomials.', chosen: true,
      expect: { pressed: ['uniform (§3)'], labels: ['p = 0', 'p = 0.1', 'p = 0.2', 'p = 0.3'], readouts: { [CLAIM_B]: { match: 'holds' } } } },
    { n: 8, caption: 'The problem of the uniform curve: on unevenly spaced points it overshoots and loops along the long edges.', demo: 'interp-approx', state: { preset: 'fig8', points: FIG8_POINTS, construction: 'section3', knots: 'uniform', a: 0, p: 1 / 12, autoTension: 'off', useK: false, family: null }, tryit: 'Switch the construction to non-uniform (Fig. 10).', chosen: true,
      expect: { pressed: ['uniform (§3)'], handles: { 'data point': 6 }, readouts: { 'Tensions': { match: '^0.083, ' }, [CLAIM_B]: { match: 'holds' } } } },
    { n: 9, caption: 'The three-segment curve through W₁ = (0, 0), W₂ = (0, C), W₃ = (B, C), W₄ = (B, 0) from which §4 derives the tension of the non-uniform curve (here B = C = 1).', demo: 'interp-approx', state: FIG9_STATE,
      ours: 'The points are the paper’s, with B = C = 1 (the paper’s own choice B = C); the end points W₋₁, W₀, W₅, W₆ are reflected through W₁ and W₄.',
      tryit: 'With “How it is built” on, the diamond above the top edge W₂W₃ is the even vertex C₄ = −p·W₁ + (½ + p)·(W₂ + W₃) − p·W₄: its height y = (1 + 2p)·C is what §4 solves for the tension (here p⁻ = p⁺ = 1/7 by eq. (8) with equal spans, so y = 9/7 ≈ 1.29). See the correction on the factor ½ below.',
      expect: { pressed: ['chord length', 'non-uniform (§4–5)'], points: { 'data point': [[0, 0], [0, 1], [1, 1], [1, 0]] }, labels: ['W₁', 'W₂', 'W₃', 'W₄'], inView: true, readouts: { Domain: { match: '^\\[0, 3\\], n = 4$' } } } },
    { n: 10, caption: 'The problem of Fig. 8 solved: the non-uniform curve with chord-length knots and the tension of eq. (8) has no loops.', demo: 'interp-approx', state: { preset: 'fig10', points: FIG8_POINTS, construction: 'nonuniform', knots: 'chord', a: 0, p: 1 / 6, autoTension: 'off', useK: false, family: null }, tryit: 'Switch the knots between uniform and chord length.', chosen: true,
      expect: { pressed: ['chord length', 'non-uniform (§4–5)'], handles: { 'data point': 6 }, fails: [CLAIM_B] } },
    { n: 11, caption: 'Many points on a simple rounded object: with the default tension the interpolating curve is too full between them.', demo: 'interp-approx', state: { points: DENSE, construction: 'nonuniform', knots: 'chord', a: 0, p: 1 / 6, autoTension: 'off', useK: false, family: null }, tryit: 'Lower the tension p to 0.13 (Fig. 12).', chosen: true,
      expect: { handles: { 'data point': 20 }, readouts: { Tensions: { match: '^0.167, 0.167' } }, fails: [CLAIM_B] } },
    { n: 12, caption: 'The same points with the tension p = 0.13: a good result.', demo: 'interp-approx', state: { points: DENSE, construction: 'nonuniform', knots: 'chord', a: 0, p: 0.13, autoTension: 'off', useK: false, family: null }, tryit: 'Turn on the curvature comb and compare p = 0.13 with p = 1/6.', chosen: true,
      expect: { handles: { 'data point': 20 }, readouts: { Tensions: { match: '^0.13, 0.13' } }, fails: [CLAIM_B] } },
    { n: 13, caption: 'A staircase of long and short edges: the curve swings away from the long edges of its control polygon.', demo: 'interp-approx', state: { preset: 'fig13', points: STAIRS, construction: 'nonuniform', knots: 'chord', a: 0, p: 1 / 6, autoTension: 'off', useK: false, K: 20, family: null }, tryit: 'Here the curve swings up to 0.25 away from the edges it spans. Turn on the modified knots with K = 20 (Fig. 14), then try K = 5.', chosen: true,
      expect: { handles: { 'data point': 6 }, polygonDistance: [0.247, 0.005], fails: [CLAIM_B] } },
    { n: 14, caption: 'The paper’s cure for Fig. 13: the modified knots u′₂ᵢ = (uᵢ₋₁ + K·uᵢ + uᵢ₊₁)/(K + 2) with K = 20.', demo: 'interp-approx', state: { preset: 'fig14', points: STAIRS, construction: 'nonuniform', knots: 'chord', a: 0, p: 1 / 6, autoTension: 'off', useK: true, K: 20, family: null }, tryit: 'Lower K from 20 to 5: the curve hugs the long edges; raise it to 100 and it swings out again, towards Fig. 13.', chosen: true,
      differs: 'the paper says K = 20 (“K big enough”) solves the problem of Fig. 13. Measured in this view, the largest distance of the curve from the edges it spans is 0.25 with the standard knots (Fig. 13) and still 0.15 with K = 20: better, not solved. As K grows, u′₂ᵢ tends to uᵢ, the standard knots (0.22 at K = 100, 0.24 at K = 1000); it is a small K that helps: 0.10 at K = 10, 0.06 at K = 5. Below that the curve leaves the short edges instead (0.15 at K = 2).',
      expect: { handles: { 'data point': 6 }, polygonDistance: [0.145, 0.005], text: ['max. distance 0.15'], fails: [CLAIM_B] } },
    { n: 15, caption: 'Design condition of the automatic tension: where the polygon turns only a little, the tension should be close to zero.', demo: 'interp-approx', state: { points: SMALL_TURNS, construction: 'nonuniform', knots: 'chord', a: 0, autoTension: 'paper', autoScale: 0.2, useK: false, family: null }, tryit: 'Compare the printed rule with the turning-angle rule: the printed one gives nearly the full p here (see the corrections).', chosen: true,
      expect: { pressed: ['paper'], readouts: { Tensions: { match: '^0.199, 0.199' } }, fails: [CLAIM_B] } },
    { n: 16, caption: 'Design condition: where the polygon turns quickly, the tension should rise.', demo: 'interp-approx', state: { points: QUICK_TURNS, construction: 'nonuniform', knots: 'chord', a: 0, autoTension: 'paper', autoScale: 0.2, useK: false, family: null }, tryit: 'Switch the automatic tension between the printed and the turning-angle rule.', chosen: true,
      expect: { pressed: ['paper'], readouts: { Tensions: { match: '^0.15, 0.1, 0.1' } }, fails: [CLAIM_B] } },
    { n: 17, caption: 'Design condition: where the polygon almost reverses its direction, the tension should be close to zero again.', demo: 'interp-approx', state: { points: REVERSAL, construction: 'nonuniform', knots: 'chord', a: 0, autoTension: 'paper', autoScale: 0.2, useK: false, family: null }, tryit: 'Drag the reversing point and watch the tension of its segments.', chosen: true,
      expect: { pressed: ['paper'], readouts: { Tensions: { match: '^0.2, 0, 0.198' } }, fails: [CLAIM_B] } },
    { n: 18, caption: 'Design condition: where an edge turns and the next one returns to the first direction, the tension should be close to zero.', demo: 'interp-approx', state: { points: TURN_RETURN, construction: 'nonuniform', knots: 'chord', a: 0, autoTension: 'paper', autoScale: 0.2, useK: false, family: null }, tryit: 'Compare the printed rule (it does not give zero here) with the turning-angle rule.', chosen: true,
      expect: { pressed: ['paper'], readouts: { Tensions: { match: '^0.187, 0.173' } }, fails: [CLAIM_B] } },
    { n: 19, caption: 'The interpolating curve with the automatic tension pᵢ = p·|cos αᵢ + cos αᵢ₊₁|/2, p = 0.2: better in detail than Fig. 1.', demo: 'interp-approx', state: { preset: 'fig19', points: CURVE_SHAPE, construction: 'nonuniform', knots: 'chord', a: 0, p: 1 / 6, autoTension: 'paper', autoScale: 0.2, useK: false, family: null }, tryit: 'Toggle the automatic tension off and on and compare the details.', chosen: true,
      expect: { pressed: ['paper'], handles: { 'data point': 7 }, fails: [CLAIM_B] } },
    { n: 20, caption: 'The text numbers two figures 20: a detail of Fig. 1 (§4) and an interpolating tensor-product surface (§6). The link shows the surface; for the detail, open Fig. 1 and zoom in.', demo: 'b2-surfaces', state: { mode: 'tensor', a: 0, shape: 'hill' }, tryit: 'Move a from 0 (the surface interpolates the grid) to 1/6 (the bicubic B-spline).', chosen: true,
      expect: { pressed: ['tensor product (§6)'], selected: { Data: 'hill' } } },
    { n: 21, caption: 'A detail of Fig. 19: with the automatic tension the curve follows the points more closely than in Fig. 1.', demo: 'interp-approx', state: { points: CURVE_SHAPE, construction: 'nonuniform', knots: 'chord', a: 0, autoTension: 'paper', autoScale: 0.2, useK: false, family: null }, tryit: 'Zoom into one turn with the mouse wheel or two fingers, then switch the automatic tension off.', chosen: true,
      expect: { pressed: ['paper'], handles: { 'data point': 7 }, fails: [CLAIM_B] } },
    { n: 22, caption: 'Another detail of Fig. 1 (constant tension).', demo: 'interp-approx', state: { points: CURVE_SHAPE, construction: 'nonuniform', knots: 'chord', a: 0, p: 1 / 6, autoTension: 'off', useK: false, family: null }, tryit: 'Zoom in where the points turn sharply.', chosen: true,
      expect: { pressed: ['off'], handles: { 'data point': 7 }, readouts: { Tensions: { match: '^0.167, 0.167' } }, fails: [CLAIM_B] } },
    { n: 23, caption: 'The same detail of Fig. 19 (automatic tension).', demo: 'interp-approx', state: { points: CURVE_SHAPE, construction: 'nonuniform', knots: 'chord', a: 0, autoTension: 'paper', autoScale: 0.2, useK: false, family: null }, tryit: 'Compare with Fig. 22 at the same place.', chosen: true,
      expect: { pressed: ['paper'], handles: { 'data point': 7 }, fails: [CLAIM_B] } },
  ],
  '001': [
    { n: 1, caption: 'The paper’s quadratic Bézier spline (11 points, 5 segments) and its remodelled cubic for the parameters of Fig. 1; the new curve stays C¹.', demo: 'bezier-remodel', state: { tab: 'curve', preset: 'fig1' }, tryit: 'Drag an α slider: the curve changes shape, the C¹ jumps stay at zero.',
      expect: { pressed: ['Curve (§2–3)', 'Fig. 1'], handles: { 'control point': 11 } } },
    { n: 2, caption: 'The same spline remodelled with the parameters of Fig. 2: a stronger change of shape, still C¹.', demo: 'bezier-remodel', state: { tab: 'curve', preset: 'fig2', alphas: [[1 / 10, 1 / 10], [9 / 10, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 100], [99 / 100, 1 / 5]] }, tryit: 'Turn off “Enforce eq. (9)” to see the first-derivative jumps appear.',
      expect: { pressed: ['Curve (§2–3)', 'Fig. 2'], handles: { 'control point': 11 } } },
    { n: 3, caption: 'The curvature $K^*(u_I)$ of the remodelled curve at an interior joint as a function of $\\alpha_m^{(I-1)}$, $0 < \\alpha_m^{(I-1)} < \\frac{1}{2}$ (eq. (15)): the plot “Fig. 3 (live)” under the curve, here for the parameters of Fig. 1.', demo: 'bezier-remodel', state: { tab: 'curve', preset: 'fig1', showCircles: true, joint: 1 }, tryit: 'Change αₘ of the segment before the joint: the dot runs along the curve; the osculating circles on the curve show the same K* at the joint.',
      differs: 'the paper’s graph is eq. (15), by which K* falls to 0 as αₘ⁽ᴵ⁻¹⁾ grows to ½. That form needs r ≥ 2 (see the correction on eq. (15)); Fig. 1 is remodelled with r = 1, and there the measured K* rises instead. The live plot draws both: the measured K* (solid) and (15) as printed (dashed), which cross only at αₘ = 1/(m + 1) = 1/3. At Fig. 1’s α₂⁽⁰⁾ = 1/20 the table reads K*(u₁) = 0.01038 measured, 0.02803 by (15) as printed.',
      expect: { pressed: ['Curve (§2–3)', 'Fig. 1'], text: ['Fig. 3 (live): K*(u₁) against α₂⁽⁰⁾', '0.01038', '0.02803'] } },
    { n: 4, caption: 'The paper’s surface (one patch row in v, three segments in u) after the usual degree elevation in u: the surface is unchanged.', demo: 'bezier-remodel', state: { tab: 'surface', surface: { preset: 'fig4', alphas: [[2 / 3, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 3]], r: 1, enforce: true } }, tryit: 'Choose the literal “all α = 1/3” example to see why the printed caption is wrong (corrections).',
      expect: { pressed: ['Surface (§4)', 'Fig. 4'] } },
    { n: 5, caption: 'The same surface remodelled in u with the parameters of Fig. 5; it stays C¹ across the lines u = 1 and u = 2.', demo: 'bezier-remodel', state: { tab: 'surface', surface: { preset: 'fig5', alphas: [[1 / 2, 1 / 500], [499 / 500, 1 / 1000], [999 / 1000, 4 / 5]], r: 1, enforce: true } }, tryit: 'Turn the view and follow the break lines; then turn off eq. (19).',
      expect: { pressed: ['Surface (§4)', 'Fig. 5'] } },
  ],
  '003': [
    { n: 1, caption: 'The quasi-cubic basis functions on a uniform knot vector for several values of the shape parameter α.', demo: 'quasi-cubic-curves', state: { preset: 'free', alpha: 0.5 }, tryit: 'Move α and watch the basis plot: at α = 1 it is C³, for α < 0 some functions are no longer monotone.', chosen: true,
      expect: { pressed: ['Free'], handles: { 'control point': 7 } } },
    { n: 2, caption: 'The four pieces B₀ … B₃ of the basis on one segment t ∈ [0, 1]; they sum to one.', demo: 'quasi-cubic-curves', state: { preset: 'free', alpha: 1 }, tryit: 'Try α = −3 and α = 1, the ends of the interval where the functions stay non-negative.', chosen: true,
      expect: { pressed: ['Free'], handles: { 'control point': 7 } } },
    { n: 3, caption: 'A family of quasi-cubic curves with fixed control points and varied α, next to the cubic B-spline.', demo: 'quasi-cubic-curves', state: { preset: 'free', alpha: 0.5, showGhost: true }, tryit: 'Move α across 0 … 1: the curve passes near the cubic B-spline but never equals it (corrections).', chosen: true,
      expect: { pressed: ['Free'], handles: { 'control point': 7 } } },
    { n: 4, caption: 'As α changes the curve moves between its control polygon and the chord bᵢbᵢ₊₃.', demo: 'quasi-cubic-curves', state: { preset: 'free', alpha: -2, showPolygon: true }, tryit: 'Sweep α from −3 to 3 and watch where the curve goes.', chosen: true,
      expect: { pressed: ['Free'], handles: { 'control point': 7 } } },
    { n: 5, caption: 'A parabola arc represented exactly (α = 1, the apex used twice).', demo: 'quasi-cubic-curves', state: { preset: 'parabola', alpha: 1 }, tryit: 'Drag a point: the residual shows when the parabola condition breaks.', chosen: true,
      expect: { pressed: ['Parabola'], handles: { 'control point': 4 }, readouts: { 'Max deviation': { below: 1e-12 }, 'Condition residual': { match: 'holds' }, 'α for this shape': { match: 'α = 1 ✓' } } } },
    { n: 6, caption: 'An elliptic arc represented exactly (α = 1, control points on a rhombus).', demo: 'quasi-cubic-curves', state: { preset: 'ellipse', alpha: 1 }, tryit: 'Choose the circle preset: a square gives a circle of 2/3 the half-diagonal.', chosen: true,
      expect: { pressed: ['Ellipse'], handles: { 'control point': 4 }, readouts: { 'Max deviation': { below: 1e-12 }, 'Condition residual': { match: 'holds' }, 'α for this shape': { match: 'α = 1 ✓' } } } },
    { n: 7, caption: 'A sine arc represented exactly (α = 0).', demo: 'quasi-cubic-curves', state: { preset: 'sine', alpha: 0, points: SINE_POINTS, closed: false }, tryit: 'Change α away from 0 and watch the deviation from the sine.', chosen: true,
      expect: { pressed: ['Sine'], handles: { 'control point': 7 }, readouts: { 'Max deviation': { below: 1e-12 }, 'Condition residual': { match: 'holds' }, 'α for this shape': { match: 'α = 0 ✓' } } } },
    { n: 8, caption: 'A bowl made of four C² quasi-bicubic patches, and the bowl with its profile projected on the xy-plane.', demo: 'quasi-cubic-surfaces', state: { shape: 'bowl', alpha: 1 }, tryit: 'Change α and turn the view.', chosen: true,
      expect: { pressed: ['Bowl (Fig. 8)'] } },
    { n: 9, caption: 'A three-way pipe junction; every pipe is a cylinder of four C² patches. The demo shows one such cylinder, represented exactly; the junction itself is not built.', demo: 'quasi-cubic-surfaces', state: { shape: 'cylinder', alpha: 1 }, tryit: 'Read the distance from the exact cylinder, then move α away from 1.', chosen: true,
      expect: { pressed: ['Cylinder'], readouts: { 'Max distance from the quadric': { below: 1e-12 } } } },
    { n: 10, caption: 'A tread surface made of four C² patches.', nr: 'The paper prints neither the data nor the shape of the tread surface, so it cannot be rebuilt. The torus and the bowl in the quasi-cubic surfaces demo show the same kind of exact trigonometric surface.' },
    { n: 11, caption: 'The blended interpolation spline with all local parameters β* equal to one except at one point, where it grows: the curve gets fuller there.', demo: 'blended-interpolation', state: { dataset: 'custom', selected: 3, beta: ones(7, 3, 1.8) }, tryit: 'Move β* at the selected point from 0 to 2.', chosen: true,
      expect: { pressed: ['Own points'], labels: ['β*₃ = 1.8'] } },
    { n: 12, caption: 'The same with a small β* at that point: the curve flattens there, and for larger changes it gets two inflexions.', demo: 'blended-interpolation', state: { dataset: 'custom', selected: 3, beta: ones(7, 3, 0.2) }, tryit: 'Set β* = 0: the tangent at the point vanishes.', chosen: true,
      expect: { pressed: ['Own points'], labels: ['β*₃ = 0.2'] } },
    { n: 13, caption: 'The blended interpolation surface with all local parameters one except at one point.', demo: 'quasi-cubic-surfaces', state: { shape: 'blended', beta: 1.8, betaOthers: 1, bisAlpha: 3 }, tryit: 'Move the local β* at the marked point.', chosen: true,
      expect: { pressed: ['Blended (Fig. 13)'] } },
    { n: 14, caption: 'Two segments of a blended interpolation curve, the first without and the second with an inflexion (how the local parameters are chosen).', demo: 'blended-interpolation', state: { dataset: 'custom', selected: 2 }, tryit: 'Press “Fair by curvature” and compare the tangent lengths.', chosen: true,
      expect: { pressed: ['Own points'], labels: ['β*₂ = 1'] } },
    { n: 15, caption: 'Shape-preserving interpolation of data with flat parts and a steep rise, with suitable local parameters.', demo: 'blended-interpolation', state: { dataset: 'rpn14' }, tryit: 'Press “Fair by curvature”, then compare with all β* = 1.', chosen: true,
      expect: { pressed: ['RPN 14'] } },
    { n: 16, caption: 'Blended surfaces with the global α = 0.6 and one growing local parameter.', demo: 'quasi-cubic-surfaces', state: { shape: 'blended', bisAlpha: 0.6, beta: 2.2, betaOthers: 1 }, tryit: 'Move the local β* from 0 to 3.', chosen: true,
      expect: { pressed: ['Blended (Fig. 13)'] } },
    { n: 17, caption: 'Blended surfaces with all local parameters 0.8 and the global α = 0, 0.3, 0.7, 1.', demo: 'quasi-cubic-surfaces', state: { shape: 'blended', bisAlpha: 0.3, beta: 0.8, betaOthers: 0.8 }, tryit: 'Move the α of the blended spline through 0, 0.3, 0.7 and 1.', chosen: true,
      expect: { pressed: ['Blended (Fig. 13)'] } },
  ],
  '004': [
    { n: 1, caption: 'The parameter domain: the pre-images of the network curves (the lines u = uᵣ, v = vₛ) and of their control points.', demo: 'criss-cross-basis', state: { map: true, ordinates: false }, tryit: 'Drag a breakpoint of u or v: the grid and the pre-images follow.', chosen: true,
      expect: { handles: { 'u knot': 4, 'v knot': 3 } } },
    { n: 2, caption: 'The criss-cross triangulation of the domain (every cell cut by both diagonals) and the pre-images of the surface’s control points.', demo: 'criss-cross-basis', state: { map: true, ordinates: true }, tryit: 'Pick another B-spline Bᵢⱼ and see its octagonal support on the triangulation.', chosen: true,
      expect: { handles: { 'u knot': 4, 'v knot': 3 } } },
    { n: 3, caption: 'The order in which the control points Cᵢⱼ are computed from C₁₁ by eq. (26), a path through the control net.', nr: 'A diagram of a computation order, not a surface. Its result is live in the curve networks demo (the control points of S for any C₁₁).' },
    { n: 4, caption: 'The paper’s test network of §4.1: m = 18, n = 4, the knots uᵢ = i, vⱼ = j — 19 quadratic B-spline curves φᵣ across and 5 curves ψₛ along.', demo: 'curve-networks', state: { preset: 'paper-18x4', show: { S: true, T: false, G: false, GB: false }, colorBy: 'none', layout: 'side' },
      ours: 'The paper’s: m = 18, n = 4 and the knots. Ours: the curves — the paper prints none of their control points (only a picture), so the live network has the paper’s grid with a shape of our own.',
      tryit: 'Drag a curve of the network: the other curves keep meeting it.',
      expect: { selected: { Network: 'm = 18, n = 4, §4.1 grid' }, points3d: { 'net-P': 19 * 6, 'net-Q': 5 * 20 }, readouts: { 'C2 residual': { below: 1e-12 } }, fails: [CLAIM_SG] } },
    { n: 5, caption: 'The surface S through that network, computed with two very different free points C₁₁ = (1.5, 1.5, 32) and (1, 0, 30): the same surface (Theorem 3.2).', demo: 'curve-networks', state: { preset: 'paper-18x4', show: { S: true, T: false, G: false, GB: false }, colorBy: 'none', layout: 'side', triangulation: true },
      ours: 'The paper’s: m = 18, n = 4, the knots and the two C₁₁. Ours: the curves (the paper prints none), so the two C₁₁ are the paper’s values for its own network, used here on ours.',
      tryit: 'Read “S with C₁₁ = (1.5, 1.5, 32) against S with C₁₁ = (1, 0, 30)” under Criss-cross: the two sums Σ Cᵢⱼ Bᵢⱼ agree to rounding, though their control points differ. Drag a curve: they still agree.',
      expect: { selected: { Network: 'm = 18, n = 4, §4.1 grid' }, points3d: { 'net-P': 19 * 6, 'net-Q': 5 * 20 }, readouts: { 'C2 residual': { below: 1e-12 }, 'S with C₁₁ = (1.5, 1.5, 32) against S with C₁₁ = (1, 0, 30)': { below: 1e-10, match: 'the same surface$' } }, fails: [CLAIM_SG] } },
    { n: 6, caption: 'A curve network (m = n = 3) and the C¹ quadratic surface S on the criss-cross triangulation through it.', demo: 'curve-networks', state: { preset: 'paper', show: { S: true, T: false, G: false, GB: false } }, tryit: 'Click a cell to see its Bernstein–Bézier net.',
      ours: 'The paper’s: m = n = 3 on [0, 1]², U = V = {0, 0, 0, ⅓, ⅔, 1, 1, 1}. Ours: the curves (the paper prints none of their control points).',
      expect: { selected: { Network: 'm = n = 3 on [0,1]², §4.2 grid' }, points3d: { 'net-P': 4 * 5, 'net-Q': 4 * 5 }, fails: [CLAIM_SG] } },
    { n: 7, caption: 'The same network: the biquadratic surface T of minimal thin-plate energy and the Gordon surface G.', demo: 'curve-networks', state: { preset: 'paper', show: { S: false, T: true, G: true, GB: false }, colorBy: 'TG' }, tryit: 'Colour by |T − G| and drag a curve.',
      ours: 'The paper’s: m = n = 3 on [0, 1]² and the knots. Ours: the curves (the paper prints none).',
      differs: 'for its network the paper reports ‖S − T‖∞ = 3.79·10⁻², ‖S − G‖∞ = 4.44·10⁻¹⁵, ‖T − G‖∞ = 3.79·10⁻² (57 × 57 grid) and C₁₁* = (1.11, −0.15, 3). It prints no control points, so these cannot be reproduced; on our network the table reads ‖S − G‖∞ = 8.7521·10⁻³, ‖S − T‖∞ = 8.3351·10⁻³, ‖T − G‖∞ = 5.3152·10⁻⁴. S and G differ here: S = G holds only for the special class of networks the paper’s must belong to (see the ‖S − G‖ correction).',
      expect: { selected: { Network: 'm = n = 3 on [0,1]², §4.2 grid', 'Colour map': '|T − G| on T' }, points3d: { 'net-P': 4 * 5, 'net-Q': 4 * 5 }, text: ['8.7521e-3', '8.3351e-3', '5.3152e-4'], fails: [CLAIM_SG] } },
    { n: 8, caption: 'A network with three-sided and four-sided facets (m = 5, n = 3) and the surface S through it.', demo: 'curve-networks', state: { preset: 'three-sided', show: { S: true, T: false, G: false, GB: false } }, tryit: 'Turn on the triangulation to see where the facets degenerate.',
      ours: 'The paper’s: m = 5, n = 3 on [0, 5] × [0, 3], and every curve φᵣ running from one point Q⁽⁰⁾ to one point Q⁽³⁾. Ours: the rest of the curves (the paper prints no control points).',
      expect: { selected: { Network: '3-sided facets (§4.3, m = 5, n = 3)' }, points3d: { 'net-P': 6 * 5, 'net-Q': 4 * 7 }, fails: [CLAIM_SG] } },
    { n: 9, caption: 'Another network, m = 5, n = 4 on [0, 5] × [0, 4] with uᵢ = i, vⱼ = j (the paper takes C₁₁ = (0.5, 0.5, 3.5)), and the surface S through it.', demo: 'curve-networks', state: { preset: 'paper-5x4', show: { S: true, T: false, G: false, GB: false }, colorBy: 'none', layout: 'side' },
      ours: 'The paper’s: m = 5, n = 4, the domain and the knots. Ours: the curves (the paper prints none; the shape is ours).',
      tryit: 'Show G as well and colour S by |S − G|: on this network the two surfaces differ (see the ‖S − G‖ correction).',
      expect: { selected: { Network: 'm = 5, n = 4, §4.3 grid' }, points3d: { 'net-P': 6 * 6, 'net-Q': 5 * 7 }, readouts: { 'C2 residual': { below: 1e-12 } }, fails: [CLAIM_SG] } },
  ],
};

// Readouts of printed claims that a live view may show as failing, with why (the card of a figure that lists
// one in expect.fails says so; tests/e2e/papers-facts.test.mjs fails for a failing readout a card leaves unexplained).
export const CLAIM_READOUTS = {
  [CLAIM_B]: {
    why: 'that printed claim holds on uniform knots only. This view has chord-length knots, where a = 1/6 and p = 0 put into the construction are not the B-spline (SplineLab reaches the B-spline through the §5 blend); the figure is about something else.',
    correction: 'correction-000-bspline',
  },
  [CLAIM_SG]: {
    why: 'the paper’s S = G holds only for networks of the special class a(u) + b(v) + c·uv. This network (ours: the paper prints none) is not of that class, so S and G differ, by the ‖S − G‖∞ of the table.',
    correction: 'correction-004-sg',
  },
};

// The knot-modification paper has no numbered figures: its theorems get one live view each.
export const THEOREMS = [
  { n: 1, caption: 'Moving the knot $u_p$, points of the affected patches travel on paths.', demo: 'knot-modification', state: { tab: 'curve', extend: false, showFamily: true, trackAll: true }, tryit: 'Move the knot slider and follow the tracked points.',
      expect: { pressed: ['Curve'], handles: { 'control point': 8 } } },
  { n: 2, caption: 'Moving $u_p$ and $v_q$ together, points of the affected patches travel on path-surfaces.', demo: 'knot-modification', state: { tab: 'surface', smove: 'both' }, tryit: 'Move both surface knots.',
      expect: { pressed: ['Surface'] } },
  { n: 3, caption: 'Extended paths (the knot leaves its interval): as the knot tends to ±∞ the points tend to combinations of the control points (a limit curve of the control net).', demo: 'knot-modification', state: { tab: 'curve', extend: true, showLimits: true }, tryit: 'Turn on “Extend” and push the knot far out: the points approach the marked limits.',
      expect: { pressed: ['Curve'], labels: ['u₅ → −∞', 'u₅ → +∞'] } },
  { n: 4, caption: 'If $u_p$ and $v_q$ tend to infinity together, the points converge to single control points of the surface (corrected list of limits, see below).', demo: 'knot-modification', state: { tab: 'surface', smove: 'both', extend: true }, tryit: 'Push both knots towards the ends and watch the points gather at control points.',
      expect: { pressed: ['Surface'] } },
  { n: 5, caption: 'The one-parameter family of surfaces obtained by moving $u_p$ has an envelope, a B-spline surface of order $k - 1$ in u.', demo: 'knot-modification', state: { tab: 'curve', showFamily: true, showEnvelope: true }, tryit: 'Show the family and the envelope, then change the order k.',
      expect: { pressed: ['Curve'], labels: ['e(uₚ) = s(uₚ; uₚ)'] } },
  { n: 6, caption: 'The two-parameter family obtained by moving $u_p$ and $v_q$ has an envelope of orders $k - 1$ and $l - 1$.', demo: 'knot-modification', state: { tab: 'surface', smove: 'both' }, tryit: 'Move both knots and compare with the envelope.',
      expect: { pressed: ['Surface'] } },
  { n: 7, caption: 'Each path and the envelope have G¹ contact: a common point and a common tangent where $u_p$ equals the path’s parameter.', demo: 'knot-modification', state: { tab: 'curve', showEnvelope: true, trackAll: true }, tryit: 'Track every point and watch each path touch the envelope.',
      expect: { pressed: ['Curve'], handles: { 'control point': 8 } } },
  { n: 8, caption: 'The same G¹ contact for path-surfaces and the envelope of the two-parameter family.', demo: 'knot-modification', state: { tab: 'surface', smove: 'both' }, tryit: 'Move $u_p$ and $v_q$ to the same place as the tracked point.',
      expect: { pressed: ['Surface'] } },
];

// ---------------------------------------------------------------------------------------------------------
// Corrections: printed claim, corrected claim, why, and where to see it.
// ---------------------------------------------------------------------------------------------------------
export const CORRECTIONS = [
  { id: 'correction-000-eq5', paper: '000', where: 'eq. (5), the joints of a cubic B-spline',
    printed: 'The last weight of $P_i$ is $\\frac{\\Delta_{2i}}{\\Delta_{2i-1} + \\Delta_{2i}} \\cdot \\frac{\\Delta_{2i-1}}{\\Delta_{2i-1} + \\Delta_{2i} + \\Delta_{2i+1}}$ (in the notation $a, b, c, d = \\Delta_{2i-2}, \\ldots, \\Delta_{2i+1}$: $\\frac{b}{b + c} \\cdot \\frac{c}{b + c + d}$).',
    corrected: 'The last weight is $\\frac{b^2}{(b + c)(b + c + d)}$; with it the three weights sum to one and equal de Boor’s algorithm exactly.',
    why: 'The printed weights sum to $1 - \\frac{b(b - c)}{(b + c)(b + c + d)}$, e.g. 1.0444 for $\\Delta = (1, 2, 3, 4)$: the joint would leave the curve on uneven knots.',
    demo: 'interp-approx', state: { showBuild: true, points: FIG8_POINTS, construction: 'nonuniform', knots: 'chord' } },
  { id: 'correction-000-tension-half', paper: '000', where: '§4, the tension of the three-segment example',
    printed: '$p = \\frac{B^2}{A(B + C) + 2BC + C^2}$.',
    corrected: '$p = \\frac{B^2}{2\\,(A(B + C) + 2BC + C^2)}$: the factor $\\frac{1}{2}$ from $p = \\frac{1}{2}(\\frac{y}{C} - 1)$ is lost. With $A = \\frac{B}{2}$ the paper’s final symmetric formula $p = \\frac{B^2}{B^2 + 5BC + 2C^2}$ is nevertheless right, because the slip cancels.',
    why: 'Redoing the construction (split knots, $y = (1 + 2p)\\,C$) symbolically gives the factor $\\frac{1}{2}$; at $B = C$ the corrected value is $\\frac{1}{8}$.',
    demo: 'interp-approx', state: FIG9_STATE },
  { id: 'correction-000-eq8', paper: '000', where: 'eqs. (8) and (9), the tension denominators',
    printed: '$p^{\\pm}_i = \\frac{\\Delta_i^2}{\\Delta_i^2 + 5\\Delta_i \\Delta_{i\\pm 1} + \\Delta_{i\\pm 1}^2}$.',
    corrected: 'The derivation generalises to $\\frac{\\Delta_i^2}{\\Delta_i^2 + 5\\Delta_i \\Delta_{i\\pm 1} + 2\\Delta_{i\\pm 1}^2}$ ($\\frac{1}{8}$ for equal spans; the printed one gives $\\frac{1}{7}$). SplineLab keeps the printed form by default and offers the derived one as an option (c2 = 2).',
    why: 'The printed symmetric formula has $2C^2$, the general one $1 \\cdot \\Delta^2$; the step from B = C to B ≠ C is heuristic in the paper. On uneven data the two differ by up to 0.046 in position.',
    demo: 'interp-approx', state: { points: FIG8_POINTS, construction: 'nonuniform', knots: 'chord', c2: 2 } },
  { id: 'correction-000-autotension', paper: '000', where: '§4, automatic tension',
    printed: '$p_i = \\frac{p}{2}\\,|\\cos \\alpha_i + \\cos \\alpha_{i+1}|$ with $\\alpha_i = ∠W_{i-1} W_i W_{i+1}$ meets the four design conditions of Figs. 15–18.',
    corrected: 'It meets only the reversal condition (Fig. 17): for small turns it gives nearly the full p (0.199 for 5°), for quick turns it falls (0 at 90°), and for turn-and-return it does not vanish. The rule $\\frac{p}{2}\\,|\\sin \\theta_i + \\sin \\theta_{i+1}|$ with the signed turning angles $\\theta$ meets all four; it is not in the paper and is offered as an option.',
    why: 'Measured on polygons with constant turns (p = 0.2): straight 0.2, 5° turns 0.199, 60°/90° turns 0.1/0.0, ±30° turn and return 0.173.',
    demo: 'interp-approx', state: { points: SMALL_TURNS, construction: 'nonuniform', knots: 'chord', autoTension: 'turning', autoScale: 0.2 } },
  { id: 'correction-000-bspline', paper: '000', where: '§3 and §5, “a = 1/6 and p = 0 gives the B-spline”',
    printed: 'For $a = \\frac{1}{6}$ and $p = 0$ the curve is the cubic B-spline.',
    corrected: 'True for the uniform curve of §3 only. On non-uniform knots, putting $a = \\frac{1}{6}$ and $p = 0$ into the joints and even vertices is not the B-spline (the even vertices are off by 0.2 and the curve by 0.13 on our test data); the B-spline is reached through §5’s blend $L^a = 6a\\,L^B + (1 - 6a)\\,L$, which SplineLab uses.',
    why: 'The non-uniform even vertices with p = 0 are midpoints, not the B-spline’s vertices.',
    demo: 'interp-approx', state: { a: 1 / 6, p: 0, points: FIG8_POINTS, construction: 'nonuniform', knots: 'chord' } },
  { id: 'correction-001-eq14', paper: '001', where: 'eq. (14), curvature at the last breakpoint',
    printed: '$K^*(u_L)$ uses $\\Delta b^*_{Im-1} ∧ \\Delta b^*_{Im}$.',
    corrected: '$K^*(u_L) = \\frac{m}{m + 1} \\cdot \\frac{\\| \\Delta b^*_{(m+1)L-2} ∧ \\Delta b^*_{(m+1)L-1} \\|}{\\| \\Delta b^*_{(m+1)L-1} \\|^3}$ (the last two differences of the new polygon).',
    why: 'The printed indices belong to the old polygon; with the corrected ones the formula agrees with the measured curvature to 4.5·10⁻¹³.',
    demo: 'bezier-remodel', state: { tab: 'curve', preset: 'fig1', showCircles: true } },
  { id: 'correction-001-eq15', paper: '001', where: 'eq. (15), the curvature ratio at interior joints',
    printed: '$K^*(u_I) = \\frac{m^2}{m^2 - 1} \\cdot \\frac{1 - 2\\alpha_m^{(I-1)}}{(1 - \\alpha_m^{(I-1)})^2} \\cdot K(u_I)$, for every $C^r$ remodelling.',
    corrected: 'This needs $r \\ge 2$ (it uses $\\alpha_2 = 1 - 2\\alpha_m$ from eq. (9)). For every r the right-sided form $K^*(u_I) = \\frac{m^2}{m^2 - 1} \\cdot \\frac{\\alpha_2^{(I)}}{(\\alpha_1^{(I)})^2} \\cdot K(u_I^+)$ holds.',
    why: 'For r = 1 the printed ratio is wrong by a factor of 7 (m = 3) to 12 (m = 2); the general form agrees to 1.7·10⁻¹³.',
    demo: 'bezier-remodel', state: { tab: 'curve', preset: 'fig1', r: 1, showCircles: true, joint: 2 } },
  { id: 'correction-001-breaks', paper: '001', where: '§3, the example’s breakvalues 0, 1, 7/4, 5/2, 13/4, 4',
    printed: 'The breakvalues are presented as chosen for the example (as if from the chord lengths).',
    corrected: 'They are exactly the values forced by C¹ of the given curve; chord-length values (0, 0.965, 2.077, …) would make it not C¹.',
    why: '$C^1$ fixes the ratios $\\frac{\\Delta_{I-1}}{\\Delta_I} = \\frac{|b_{2I} - b_{2I-1}|}{|b_{2I+1} - b_{2I}|} = \\frac{4}{3}, 1, 1, 1$.',
    demo: 'bezier-remodel', state: { tab: 'curve', preset: 'fig1' } },
  { id: 'correction-001-alpha', paper: '001', where: '§4.1, the surface of Fig. 4',
    printed: 'αₖ,ₗ⁽ᴵ⁾ = 1/3 for k = 0…2 gives the usual degree elevation.',
    corrected: 'The usual elevation is α₁ = 2/3, α₂ = 1/3 (there is no α₀). Taken literally, all α = 1/3 changes the surface by up to 0.29 and breaks C¹ (a jump of 1.5 in ∂G*/∂u), since eq. (19) needs α₁⁽ᴵ⁾ = 1 − α₂⁽ᴵ⁻¹⁾ = 2/3.',
    why: 'With (2/3, 1/3) the elevated surface equals the given one to 2.7·10⁻¹⁵.',
    demo: 'bezier-remodel', state: { tab: 'surface', surface: { preset: 'literal', alphas: [[1 / 3, 1 / 3], [1 / 3, 1 / 3], [1 / 3, 1 / 3]], r: 1, enforce: false } } },
  { id: 'correction-001-eq20', paper: '001', where: '§4.2, eqs. (20)–(22), remodelling in both directions',
    printed: 'A closed formula for the bi-degree control points; its corner case writes n(I + l/(n + 1)) with I where J is meant, and the edge rows k ∈ {0, m + 1}, 1 ≤ l ≤ n are never defined.',
    corrected: 'SplineLab builds it as the curve remodelling in u (one parameter table per column, eq. (17)) followed by the same in v (one per row). It keeps Cʳ˒ˢ when eq. (9) holds on every line and the lines around each break share one table, and it keeps every patch corner.',
    why: 'The garbled formula cannot be implemented as printed; the two-step form is what it describes, and its continuity and interpolation are tested.',
    demo: 'bezier-remodel', state: { tab: 'surface', bi: { on: true } }, api: 'Programs can call it as bezierRemodelSurfaceBi in the SplineLab JavaScript API.' },
  { id: 'correction-002-thm4', paper: '002', where: 'Theorem 4, limits of path-surfaces',
    printed: 'The list of limits gives $(u_p, v_q) \\to (-\\infty, +\\infty) \\mapsto d_{p-k,q}$ and repeats the $(+\\infty, +\\infty)$ case.',
    corrected: '$(-\\infty, -\\infty) \\mapsto d_{p,q}$; $(-\\infty, +\\infty) \\mapsto d_{p,q-l}$; $(+\\infty, -\\infty) \\mapsto d_{p-k,q}$; $(+\\infty, +\\infty) \\mapsto d_{p-k,q-l}$.',
    why: 'At $u_p, v_q = \\pm 10^8$ the printed second limit is off by 2.18, the corrected one by 5.4·10⁻⁸.',
    demo: 'knot-modification', state: { tab: 'surface', smove: 'both', extend: true } },
  { id: 'correction-002-envelope', paper: '002', where: 'eqs. (6) and (8), the envelope',
    printed: 'The envelope is a B-spline surface of order k − 1 on a knot vector w that the paper does not define.',
    corrected: 'w is the knot vector u with the moving knot $u_p$ removed (likewise z in v), as in the authors’ earlier curve paper; with it eqs. (9), (10) and Theorems 5–8 hold.',
    why: 'Checked for orders (3, 3) … (5, 4) and several positions of the knot to 10⁻¹⁵.',
    demo: 'knot-modification', state: { tab: 'curve', showEnvelope: true } },
  { id: 'correction-003-basis', paper: '003', where: '§2, the basis functions',
    printed: 'The explicit formulas of the basis functions (and of several later equations) are lost from the text we work from.',
    corrected: 'SplineLab uses a reconstruction $B(\\alpha;t) = (1 - \\alpha)\\,B^0(t) + \\alpha\\,B^1(t)$ that meets every stated property: partition of unity, symmetry, the end values, derivatives and second derivatives of Props. 1–4, C² joins, positivity exactly for $\\alpha \\in [-3, 1]$, and the exact parabola, ellipse and sine arcs.',
    why: 'Each property was checked symbolically; the decreasing/increasing “Note” after Prop. 1 holds only for α ∈ [0, 1].',
    demo: 'quasi-cubic-curves', state: { preset: 'free', alpha: -1 } },
  { id: 'correction-003-bspline', paper: '003', where: 'abstract and §2, “the curves include the B-spline curves”',
    printed: 'The quasi-cubic curves include the cubic B-spline curves and approximate them from both sides.',
    corrected: 'No α gives the cubic B-spline: the basis space $\\{1, t, \\sin \\pi t, \\cos \\pi t, \\sin \\frac{\\pi t}{2}, \\cos \\frac{\\pi t}{2}\\}$ contains no $t^2$ or $t^3$. The closest, α ≈ 0.964, still differs by 6·10⁻³; and the cubic basis lies between α = 0 and α = 1 for only 78 % of the samples.',
    why: 'A trigonometric space cannot contain the cubic polynomials.',
    demo: 'quasi-cubic-curves', state: { preset: 'free', alpha: 0.964, showGhost: true } },
  { id: 'correction-003-eq36', paper: '003', where: 'eqs. (36)–(37), local parameters from the curvature',
    printed: '$\\beta^*_j$ from a formula that matches the curvature only up to $O(\\varphi^2)$.',
    corrected: 'The exact rule is $\\beta^*_j = \\frac{c_1}{c_0^2} \\cdot \\frac{a_j a_{j+1}}{|b_{j+1} - b_{j-1}|^2}$, with $a_j = |b_j - b_{j-1}|$, $c_0 = \\frac{\\pi}{2} - 1$, $c_1 = \\frac{\\pi^2}{4}$; then the curvature at $b_j$ equals that of the circle through $b_{j-1}, b_j, b_{j+1}$ to $4 \\cdot 10^{-16}$.',
    why: 'The printed formula replaces $|b_{j+1} - b_{j-1}|$ by $a_j + a_{j+1}$; besides, the allocated function needs order k ≥ 3 for C² (k = 2 gives a jump of 15 in the second derivative).',
    demo: 'blended-interpolation', state: { dataset: 'custom', k: 2 } },
  { id: 'correction-004-sg', paper: '004', where: '§4.2, ‖S − G‖∞ = 4.4·10⁻¹⁵',
    printed: 'The criss-cross surface S and the Gordon surface G agree to rounding error (the example suggests in general).',
    corrected: '$S = G$ holds only for networks of a special class (per coordinate $a(u) + b(v) + c\\,uv$); for generic networks $\\|S - G\\|_\\infty$ is about a quarter of the data’s size.',
    why: 'On random compatible networks the relative difference has a median of 0.22–0.29; for a separable network it is 10⁻¹⁵.',
    demo: 'curve-networks', state: { preset: 'dome', show: { S: true, T: false, G: true, GB: false }, colorBy: 'SG' },
    alt: { label: 'a separable network (S = G)', demo: 'curve-networks', state: { preset: 'separable', show: { S: true, T: false, G: true, GB: false }, colorBy: 'SG' } } },
];

/** `index.html#<demo>/<payload>` for a partial state. */
export async function demoHref(demo, state) {
  const payload = state ? await encodeState(state) : '';
  return 'index.html' + buildHash(demo, payload);
}

// ---------------------------------------------------------------------------------------------------------
// Building the page
// ---------------------------------------------------------------------------------------------------------
function citation(p) {
  return [h('span', { class: 'cite-authors' }, p.authors), '. ', h('cite', null, p.title), '. ', p.where];
}

/** The title a demo shows (its meta.title), read from the demo module itself so the link names it the same way. */
const titles = new Map();
export function demoTitle(id) {
  if (!titles.has(id)) titles.set(id, importDemo(id).then((m) => m.meta.title, () => id));
  return titles.get(id);
}

async function figure(key, f, kind = 'fig') {
  const id = `paper-${key}-${kind}-${f.n}`;
  const label = kind === 'thm' ? `Theorem ${f.n}` : `Fig. ${f.n}`;
  const body = [h('figcaption', null, h('strong', null, `${label}. `), rich(f.caption))];
  if (f.nr) {
    body.push(h('p', { class: 'not-reproducible' }, h('strong', null, 'Not reproducible: '), f.nr));
  } else {
    const href = await demoHref(f.demo, f.state);
    body.push(h('p', { class: 'paper-live' }, h('a', { href, class: 'paper-demo-link', dataset: { demo: f.demo } }, `Open the live view: ${await demoTitle(f.demo)}`)));
    if (f.ours) body.push(h('p', { class: 'paper-data-note' }, rich(f.ours)));
    else if (f.chosen) body.push(h('p', { class: 'paper-data-note' }, 'The paper prints no data for this figure: the data here are chosen to show the same effect.'));
    if (f.differs) body.push(h('p', { class: 'paper-differs' }, h('strong', null, 'The live view and the paper differ: '), rich(f.differs)));
    for (const r of f.expect?.fails ?? []) body.push(claimNote(r));
    if (f.tryit) body.push(h('p', { class: 'paper-try' }, h('strong', null, 'Try: '), rich(f.tryit)));
  }
  return h('figure', { id, class: 'paper-figure' }, body);
}

/** The card's note on a readout of a printed claim that reads "fails" in the opened view, and why. */
function claimNote(label) {
  const c = CLAIM_READOUTS[label];
  if (!c) throw new Error(`no note for the readout “${label}”`);
  return h('p', { class: 'paper-claim-note' }, h('strong', null, `The readout ${label} says “fails” in this view: `), c.why, ' ',
    h('a', { href: `#${c.correction}` }, 'The correction'), '.');
}

/**
 * Text with inline formulas: the parts between `$…$` are TeX (the subset of lib/mathml.js), typeset as MathML;
 * the rest stays text. `rich('moving $u_p$')` → ['moving ', <math>].
 */
export function rich(s) {
  if (typeof s !== 'string' || !s.includes('$')) return s;
  return s.split('$').map((part, i) => (i % 2 ? math(part) : part)).filter((x) => x !== '');
}

async function correction(c) {
  const paper = PAPERS.find((p) => p.key === c.paper);
  const links = [];
  if (c.demo) links.push(h('a', { href: await demoHref(c.demo, c.state), class: 'paper-demo-link', dataset: { demo: c.demo } }, 'See it live'));
  if (c.alt) links.push(' · ', h('a', { href: await demoHref(c.alt.demo, c.alt.state), class: 'paper-demo-link', dataset: { demo: c.alt.demo } }, `compare: ${c.alt.label}`));
  if (!c.demo && c.api) links.push(c.api);
  return h('article', { id: c.id, class: 'correction' },
    h('h3', null, `${paper.short}: ${c.where}`),
    h('dl', null,
      h('dt', null, 'Printed'), h('dd', null, rich(c.printed)),
      h('dt', null, 'Correct'), h('dd', null, rich(c.corrected)),
      h('dt', null, 'Why'), h('dd', null, rich(c.why))),
    links.length ? h('p', { class: 'paper-live' }, links) : null);
}

export async function build(root) {
  const nav = h('nav', { 'aria-label': 'Papers', class: 'papers-nav' },
    h('ul', null, PAPERS.map((p) => h('li', null, h('a', { href: `#paper-${p.key}` }, `${p.short}: ${p.title}`))),
      h('li', null, h('a', { href: '#corrections' }, 'Corrections')),
      h('li', null, h('a', { href: '#references' }, 'References'))));
  root.append(nav);
  for (const p of PAPERS) {
    const figs = p.key === '002' ? THEOREMS : FIGURES[p.key];
    const kind = p.key === '002' ? 'thm' : 'fig';
    const items = [];
    for (const f of figs) items.push(await figure(p.key, f, kind));
    const ownCorrections = CORRECTIONS.filter((c) => c.paper === p.key);
    root.append(h('section', { id: `paper-${p.key}`, class: 'paper-section' },
      h('h2', null, p.title),
      h('p', { class: 'paper-authors' }, p.authors),
      p.contribution.map((s) => h('p', null, s)),
      h('p', { class: 'paper-citation' }, citation(p), ' ', h('a', { href: `#ref-${p.ref}` }, `[${p.ref}]`)),
      ownCorrections.length ? h('p', null, 'Corrections to this paper: ', ownCorrections.map((c, i) => [i ? ', ' : '', h('a', { href: `#${c.id}` }, c.where)])) : null,
      h('h3', null, p.key === '002' ? 'The theorems, live' : 'The figures, live'),
      p.key === '002' ? h('p', null, 'The paper has no numbered figures; each theorem gets a live view instead.') : null,
      h('div', { class: 'paper-figures' }, items)));
  }
  const corr = [];
  for (const c of CORRECTIONS) corr.push(await correction(c));
  root.append(h('section', { id: 'corrections', class: 'paper-section' },
    h('h2', null, 'Corrections'),
    h('p', null, 'Where a printed formula or claim is wrong or cannot be used as printed, SplineLab implements the corrected form. Each entry gives the printed claim, the correct one, why, and a live view where both can be seen.'),
    corr));
  root.append(h('section', { id: 'references', class: 'paper-section' },
    h('h2', null, 'References'),
    h('ol', { class: 'references' }, PAPERS.map((p) => h('li', { id: `ref-${p.ref}` }, `[${p.ref}] `, citation(p))))));
  // the page is built after load: bring a linked figure or correction into view now
  const target = location.hash.length > 1 && document.getElementById(decodeURIComponent(location.hash.slice(1)));
  if (target) target.scrollIntoView();
  document.documentElement.dataset.ready = 'true';
}

const main = document.getElementById('papers');
if (main) {
  build(main).catch((e) => {
    main.append(h('p', { class: 'fatal' }, `The page could not be built: ${e.message}`));
    document.documentElement.dataset.ready = 'error';
  });
}
