// The ready-made exercises of www/exercises.html: each is a demo, the state it starts from (changes to the
// demo's defaults()), and the exercise (task, check, tolerance, hint) that travels in its link.
// The checks are those of ./exercise-checks.js; tests/e2e/exercises.test.mjs solves every one of them by
// setting the state, tests/e2e/exercises-ui.test.mjs with the controls a student uses (touch, 390×844).
// The titles, tasks and hints are written here in English, the key of their translations (www/lang/<code>/
// exercises.js): www/exercises.js shows them with t(), and the link keeps the English text, which the student's
// panel shows with translateIfKnown() (www/lib/exercise.js), so that a teacher's own text in a link stays as typed.

const THIRD = [1 / 3, 1 / 3];
const ELLIPSE = [[3, 0], [0, 1.5], [-3, 0], [0, -1.5]];

/** Paper keys of www/lib/papers-ref.js ('bg': B-spline background used by every paper). */
export const CATALOGUE = [
  // ---- Kuklišová: interpolating ↔ approximating B2-splines, noisy data
  { id: 'b2-through-data', paper: '000', demo: 'interp-approx', title: 'Through the data',
    start: { a: 1 / 6 },
    exercise: { check: 'data-distance', tol: 1e-9, task: 'The curve is the cubic B-spline of the points (a = 1/6) and misses them. Make it pass through every data point W₁ … Wₙ (to within 10⁻⁹). An exact value is typed into the box beside its slider.',
      hint: 'One slider moves the curve from approximating to interpolating: which value of a interpolates? Type it into the box beside “Approximation a”.' } },
  { id: 'noisy-sine', paper: '000', demo: 'noisy-data', title: 'Smooth a noisy sine',
    start: { source: 'curve', curve: 'sine', count: 60, sigma: 0.2, seed: 1, a: 0 },
    exercise: { check: 'fit-error', tol: 0.17, task: 'Sixty samples of a sine curve carry noise σ = 0.2. Choose a so that the fitted curve stays close to the true sine: RMS distance below 0.17.',
      hint: 'a = 0 follows every noisy point. Larger a smooths; watch the error plot below the figure.' } },
  { id: 'noisy-spiral', paper: '000', demo: 'noisy-data', title: 'The sweet spot on a spiral',
    start: { source: 'curve', curve: 'spiral', count: 80, sigma: 0.05, seed: 2, a: 0 },
    exercise: { check: 'fit-error', tol: 0.04, task: 'Fit the noisy spiral so that the RMS distance to the true spiral is below 0.040. Too little smoothing fails, and so does too much.',
      hint: 'The error plot has a minimum between a = 0 and a = 1/4: find it.' } },
  { id: 'noisy-arc', paper: '000', demo: 'noisy-data', title: 'An arc through noise',
    start: { source: 'curve', curve: 'arc', count: 40, sigma: 0.1, seed: 3, a: 0 },
    exercise: { check: 'fit-error', tol: 0.06, task: 'Forty noisy samples of an arc (σ = 0.1). Choose a so that the fit is within 0.06 of the true arc (RMS distance).',
      hint: 'Smooth more than the cubic B-spline (a = 1/6) does.' } },
  // ---- Gânscă, Coman, Ţămbulea: remodelling Bézier splines
  { id: 'remodel-c1', paper: '001', demo: 'bezier-remodel', title: 'Repair the joint',
    start: { preset: 'fig1', alphas: [THIRD, THIRD, THIRD, THIRD, THIRD], enforce: false, r: 1, joint: 1 },
    exercise: { check: 'c1-joint', tol: 1e-9, task: 'Every α was set to 1/3 and eq. (9) is off, so the remodelled curve g* has a corner at the joint u₁ = 1. Make g* C¹ at u₁ again.',
      hint: 'Eq. (9) fixes α₁ of one segment from αₘ of the previous one. You can type the α by hand (fractions such as 2/3 work) or let the app enforce eq. (9).' } },
  { id: 'remodel-alpha', paper: '001', demo: 'bezier-remodel', title: 'Set α by hand',
    start: { preset: 'fig2', alphas: [[0.1, 0.1], [0.9, 1 / 3], [2 / 3, 0.25], [0.5, 0.01], [0.99, 0.2]], enforce: false, r: 1, joint: 3 },
    exercise: { check: 'c1-joint', tol: 1e-9, task: 'Eq. (9) is switched off and g* has a corner at the joint u₃ = 5/2. Keep it off, and set the α of the segment after the joint so that g* is C¹ at u₃ again (to 10⁻⁹: type the exact value into the box beside the slider; a slider alone cannot reach it).',
      hint: 'For quadratic pieces, eq. (9) with r = 1 reads α₁ of the next segment = 1 − α₂ of the previous one: type α₁⁽³⁾ as a number or as 1 − α₂⁽²⁾ written out.' } },
  // ---- B-spline background (the knot vector decides continuity)
  { id: 'bspline-c2', paper: 'bg', demo: 'bspline-basics', title: 'A double knot',
    start: { knots: [0, 0, 0, 0, 0.25, 0.5, 0.5, 1, 1, 1, 1] },
    exercise: { check: 'c2-middle', tol: 1e-9, task: 'The knot 0.5 is double, so this cubic is only C¹ there. Make the curve C² at u = 0.5 (a knot must stay at 0.5).',
      hint: 'A cubic with a knot of multiplicity μ has 3 − μ continuous derivatives there. Drag the other 0.5 away.' } },
  // ---- Juhász, Hoffmann: knot modification
  { id: 'envelope-q1', paper: '002', demo: 'knot-modification', title: 'Touch the envelope at Q',
    start: { tab: 'curve', p: 5, up: 2.4 },
    exercise: { check: 'envelope-point', tol: 1e-3, target: [2.945333, 1.294667], task: 'Move the knot u₅ so that the curve touches its envelope at the point Q = (2.945, 1.295), marked Q in the figure. Drag the triangle on the knot line (it moves in steps of 0.01 or 0.02), use the slider or type the value.',
      hint: 'The curve touches the envelope where the envelope’s own parameter equals uₚ; the touching point (green dot) slides as you move uₚ.' } },
  { id: 'envelope-q2', paper: '002', demo: 'knot-modification', title: 'Another knot, another envelope',
    start: { tab: 'curve', p: 6, up: 3 },
    exercise: { check: 'envelope-point', tol: 1e-3, target: [4.725, 1.116667], task: 'Now the knot u₆ moves. Place it so that the curve touches its envelope at Q = (4.725, 1.117), marked Q in the figure.',
      hint: 'Every member of the family touches the envelope once; Q lies to the right of the knot’s starting value.' } },
  { id: 'envelope-q3', paper: '002', demo: 'knot-modification', title: 'Envelope near the start',
    start: { tab: 'curve', p: 4, up: 1 },
    exercise: { check: 'envelope-point', tol: 1e-3, target: [2.5, 1.95], task: 'The knot u₄ moves. Make the curve touch its envelope at Q = (2.5, 1.95), marked Q in the figure.',
      hint: 'Try the middle of the knot’s range.' } },
  // ---- Quasi-cubic trigonometric B-splines
  { id: 'qc-ellipse-alpha', paper: '003', demo: 'quasi-cubic-curves', title: 'An exact ellipse',
    start: { preset: 'ellipse', closed: true, points: ELLIPSE, alpha: 0.5 },
    exercise: { check: 'ellipse', tol: 1e-9, task: 'The control polygon is a rhombus, but the closed curve is not yet an ellipse. Change the shape parameter α so that the curve is an exact ellipse (to 10⁻⁹: type the value into the box beside the slider).',
      hint: 'Trigonometric splines reproduce conics at one value of α.' } },
  { id: 'qc-ellipse-drag', paper: '003', demo: 'quasi-cubic-curves', title: 'Mend the parallelogram',
    start: { preset: 'ellipse', closed: true, points: [[3.6, 0.5], ELLIPSE[1], ELLIPSE[2], ELLIPSE[3]], alpha: 1 },
    exercise: { check: 'ellipse', tol: 0.01, task: 'One control point was pushed away, and the curve is no longer an ellipse. Drag b₀ so that the curve is an ellipse again (within 0.01).',
      hint: 'The curve is an ellipse when the diagonals of the control polygon bisect each other: b₀ + b₂ = b₁ + b₃.' } },
  { id: 'qc-interpolate', paper: '003', demo: 'quasi-cubic-curves', title: 'From approximating to interpolating',
    start: { preset: 'free', alpha: 0.5 },
    exercise: { check: 'inner-points', tol: 1e-9, task: 'Make the quasi-cubic curve pass through its inner control points b₁ … bₙ₊₁, without moving them.',
      hint: 'The shape parameter α runs from −3 to 3; at one end the basis interpolates.' } },
  // ---- Curve networks: criss-cross S, thin-plate T, Gordon G
  { id: 'network-s-equals-g', paper: '004', demo: 'curve-networks', title: 'When S equals G',
    start: { preset: 'paper' },
    exercise: { check: 'norm-SG', tol: 1e-9, task: 'The criss-cross surface S and the Gordon surface G interpolate the same network but differ in between. Choose a network for which they coincide: ‖S − G‖∞ below 10⁻⁹.',
      hint: 'Colour the surface by “S vs G” and try each network.' } },
  { id: 'network-g-equals-gb', paper: '004', demo: 'curve-networks', title: 'Two boolean sums',
    start: { preset: 'paper' },
    exercise: { check: 'norm-GGB', tol: 1e-9, task: 'Find a network on which the Gordon surface G and the spline-blended surface GB are the same surface (‖G − GB‖∞ below 10⁻⁹).',
      hint: 'Both are boolean sums L₁ + L₂ − L₁₂ with different blending functions: compare the networks one by one with the colour map “G vs GB”.' } },
  { id: 'network-s-near-t', paper: '004', demo: 'curve-networks', title: 'S close to the thin plate',
    start: { preset: 'paper' },
    exercise: { check: 'norm-ST', tol: 1e-4, task: 'Find a network for which the criss-cross surface S and the thin-plate surface T differ by less than 10⁻⁴ everywhere.',
      hint: 'More curves leave less room between them.' } },
];

/** The exercise object stored in the link (www/lib/exercise.js) for a catalogue entry. */
export function catalogueExercise(entry) {
  return { v: 1, id: entry.id, title: entry.title, ...entry.exercise };
}
