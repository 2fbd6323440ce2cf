// Demo "B-spline basics": drag the control points of a clamped B-spline, change the degree, drag the interior
// knots, and scrub a parameter u to see which p + 1 basis functions are non-zero there. All spline values come
// from the wasm API (bsplineCurve, bsplineBasis); this module only draws and handles input. Two algorithm
// steppers walk through de Boor's algorithm at u and Boehm's insertion of the knot u, every intermediate point
// from the wasm API too (bsplineDeBoor, bsplineInsertKnot).

import { h, demoLayout, explanation, fmt, legend } from '../lib/dom.js';
import { createPlot, PALETTE, SERIES, restoreView } from '../lib/plot2d.js';
import { slider, toggle, buttonGroup, button, table, group, row } from '../lib/controls.js';
import { uPlayer } from '../lib/player.js';
import { pointEditing } from '../lib/point-edit.js';
import { stepper } from '../lib/stepper.js';
import { mathText } from '../lib/mathml.js';

export const meta = {
  id: 'bspline-basics',
  title: 'B-spline basics',
  summary: 'Drag control points and knots of a clamped B-spline; see its basis functions and which ones act at u.',
  paper: 'Cox–de Boor recursion (de Boor 1972); the kernel every SplineLab construction builds on',
};

const MAX_POINTS = 16;
const KNOT_ROW = -0.13; // y of the knot strip under the basis functions
const MIN_GAP = 0.004;  // interior knots stay this far apart (ordered, no coincident handles)

export function defaults() {
  return {
    degree: 3,
    points: [[0, 0], [1, 2.2], [2.4, 2.6], [3.4, 0.6], [4.6, 0.2], [5.4, 2.4], [6.6, 1.8]],
    knots: [0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1],
    u: 0.4,
    showPolygon: true,
    showSum: true,
    stepAlgo: 'deboor', // the stepper: 'deboor' (de Boor at u) or 'insert' (Boehm: insert the knot u)
    step: -1,           // its step (-1 = off)
    view: [],
  };
}

/** @param {HTMLElement} root @param {import('../lib/host.js').DemoContext} ctx @returns {import('../lib/host.js').MountedDemo} */
export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);
  const series = (i) => SERIES[i % SERIES.length];

  // ---------- state helpers (bookkeeping only; knot vectors come from the wasm API) ----------
  const n = () => state.points.length;
  const p = () => state.degree;

  function clampedKnots() {
    // bsplineCurve without `knots` uses the clamped uniform knot vector on [0, 1] and returns it
    const r = wasm.bsplineCurve({ degree: p(), points: state.points, samples: 2 });
    return Array.from(r.knots);
  }

  function knotsLookValid() {
    const k = state.knots, m = n() + p() + 1;
    if (!Array.isArray(k) || k.length !== m) return false;
    for (let i = 1; i < m; i++) if (!(k[i] >= k[i - 1])) return false;
    for (let i = 0; i <= p(); i++) if (k[i] !== k[0] || k[m - 1 - i] !== k[m - 1]) return false;
    return k[m - 1] > k[0];
  }

  function sanitize() {
    if (!Number.isInteger(state.degree)) state.degree = Math.round(state.degree) || 3;
    state.degree = Math.max(1, Math.min(5, state.degree));
    if (state.points.length > MAX_POINTS) state.points.length = MAX_POINTS;
    if (state.points.length < 2) state.points = defaults().points;
    if (state.degree > n() - 1) state.degree = n() - 1;
    if (!knotsLookValid()) {
      try { state.knots = clampedKnots(); } catch (e) { notify(e, 'error'); Object.assign(state, defaults()); }
    }
    const [a, b] = domain();
    if (!(state.u >= a && state.u <= b)) state.u = Math.min(b, Math.max(a, state.u || 0));
    if (!['deboor', 'insert'].includes(state.stepAlgo)) state.stepAlgo = 'deboor';
    if (!Number.isInteger(state.step) || state.step < -1 || state.step > 8) state.step = -1;
  }

  const domain = () => [state.knots[p()], state.knots[n()]];

  let steps = null;      // the stepper (built with the controls below)

  // ---------- computed data (from wasm) ----------
  let curve = null;      // { points: Float64Array }
  let basis = null;      // { params, values, count }
  let atU = null;        // { values (count), point [x, y], active: [i…] }
  let spanPiece = null;  // the curve piece of the knot span that contains u

  function computeBasis() {
    try {
      basis = wasm.bsplineBasis({ degree: p(), knots: state.knots, samples: 301 });
    } catch (e) { notify(e, 'error'); }
  }

  function computeCurve() {
    try {
      curve = wasm.bsplineCurve({ degree: p(), knots: state.knots, points: state.points, samples: 400 });
    } catch (e) { notify(e, 'error'); }
  }

  function computeAtU() {
    try {
      const b = wasm.bsplineBasis({ degree: p(), knots: state.knots, at: [state.u] });
      const c = wasm.bsplineCurve({ degree: p(), knots: state.knots, points: state.points, at: [state.u] });
      const active = [];
      for (let i = 0; i < b.values.length; i++) if (b.values[i] > 1e-12) active.push(i);
      atU = { values: b.values, point: [c.points[0], c.points[1]], active };
      // the knot span [u_k, u_{k+1}) containing u (right-hand piece; the last span at the end)
      const k = state.knots;
      let lo = k[p()], hi = k[n()];
      for (let i = p(); i < n(); i++) if (k[i] <= state.u && state.u < k[i + 1]) { lo = k[i]; hi = k[i + 1]; }
      if (state.u >= k[n()]) { for (let i = n() - 1; i >= p(); i--) if (k[i] < k[i + 1]) { lo = k[i]; hi = k[i + 1]; break; } }
      const at = [];
      for (let j = 0; j <= 60; j++) at.push(lo + (hi - lo) * j / 60);
      spanPiece = hi > lo ? wasm.bsplineCurve({ degree: p(), knots: state.knots, points: state.points, at }).points : null;
      spanLabel = [lo, hi];
    } catch (e) { notify(e, 'error'); }
    computeSteps();
  }

  // ---------- the steppers' data (from wasm: every intermediate point) ----------
  let tri = null;  // bsplineDeBoor: { span, levels[r] (flat), alphas[r], firstIndex[r], point }
  let ins = null;  // bsplineInsertKnot: { span, first, alphas, knots, points (flat) }
  function computeSteps() {
    const o = { degree: p(), knots: state.knots, points: state.points, u: state.u };
    try { tri = wasm.bsplineDeBoor(o); } catch (e) { tri = null; }
    try { ins = wasm.bsplineInsertKnot(o); } catch (e) { ins = null; }
  }
  let spanLabel = [0, 1];

  function recompute({ knots = true } = {}) {
    if (knots) computeBasis();
    computeCurve();
    computeAtU();
    refreshControls();
    steps?.refresh();
    curvePlot.redraw();
    basisPlot.redraw();
  }

  // ---------- curve plot ----------
  const curvePlot = createPlot(L.plots, {
    ariaLabel: 'B-spline curve with draggable control points',
    equal: true, height: 420, maxHeightRatio: 0.62, locked: options.locked,
    view: { xmin: -0.5, xmax: 7, ymin: -0.5, ymax: 3 },
    describe: () => `Clamped B-spline of degree ${p()} with ${n()} control points: ${state.points.map((q, i) => `P${i} (${fmt(q[0], 2)}, ${fmt(q[1], 2)})`).join(', ')}. Curve point at u = ${fmt(state.u, 3)}: (${atU ? fmt(atU.point[0], 2) : '?'}, ${atU ? fmt(atU.point[1], 2) : '?'}).`,
    onView(v) { state.view = [v.xmin, v.xmax, v.ymin, v.ymax]; ctx.save(); },
    draw(g, plot) {
      if (state.showPolygon) plot.polyline(state.points, { color: PALETTE.polygon, width: 1.75, dash: [8, 6] });
      if (curve) plot.polyline(curve.points, { color: PALETTE.curve, width: 3.5 });
      if (spanPiece) plot.polyline(spanPiece, { color: PALETTE.ink, width: 7, alpha: 0.22 });
      if (atU) {
        // rings around the p + 1 control points that act at u
        for (const i of atU.active) {
          const q = state.points[i];
          if (!q) continue;
          const [X, Y] = plot.toScreen(q[0], q[1]);
          g.beginPath(); g.arc(X, Y, 14, 0, 2 * Math.PI);
          g.lineWidth = 3; g.strokeStyle = series(i); g.stroke();
        }
      }
      drawStepLines(plot);
    },
    drawOver(g, plot) {
      drawStepMarks(g, plot);
      if (!atU) return;
      plot.points([atU.point], { color: PALETTE.ink, radius: 7, shape: 'diamond', stroke: '#fff' });
      plot.label(atU.point[0], atU.point[1], `C(${fmt(state.u, 2)})`, { offset: [10, 22], baseline: 'top' });
    },
  });
  curvePlot.canvas.dataset.plot = 'curve';
  const ctrlHandles = curvePlot.addHandles({
    name: 'control point',
    points: () => state.points,
    colorOf: (i) => series(i),
    label: (i) => `P${i}`,
    labelOf: (i) => `Control point P${i}`,
    radius: 8,
    move(i, q) { state.points[i] = [q[0], q[1]]; recompute({ knots: false }); },
    end() { ctx.save(); },
  });

  const key = legend([
    { label: 'curve C(u) = Σ Nᵢ,ₚ(u) Pᵢ', color: PALETTE.curve },
    { label: 'control polygon', color: PALETTE.polygon, kind: 'dashed' },
    { label: 'control points Pᵢ (drag; colour = its Nᵢ,ₚ)', color: PALETTE.control, kind: 'dot' },
    { label: 'piece over the knot span of u', color: 'rgba(0,0,0,0.25)', kind: 'band' },
  ]);
  L.plots.appendChild(key);

  // ---------- basis plot with the knot strip ----------
  const basisPlot = createPlot(L.plots, {
    ariaLabel: 'Basis functions Nᵢ,ₚ over the domain, with draggable interior knots under the axis',
    height: 280, pan: false, zoom: false, locked: options.locked, xLabel: 'u',
    view: { xmin: -0.03, xmax: 1.03, ymin: -0.22, ymax: 1.2 },
    describe: () => `Knots: ${state.knots.map((k) => fmt(k, 3)).join(', ')}. At u = ${fmt(state.u, 3)} the non-zero basis functions are ${atU ? atU.active.map((i) => `N${i} = ${fmt(atU.values[i], 3)}`).join(', ') : 'unknown'}.`,
    draw(g, plot) {
      const [a, b] = domain();
      const k = state.knots;
      // knot strip: a line and the (fixed) end knots
      plot.segment(a, KNOT_ROW, b, KNOT_ROW, { color: PALETTE.axis, width: 2 });
      for (let i = 0; i < k.length; i++) {
        plot.segment(k[i], KNOT_ROW, k[i], 1.05, { color: '#bdbdbd', width: 1, dash: [3, 4] });
      }
      plot.points([[k[0], KNOT_ROW], [k[k.length - 1], KNOT_ROW]], { color: PALETTE.axis, radius: 6, shape: 'square' });
      plot.label(k[0], KNOT_ROW, `u₀…u${sub(p())}`, { offset: [4, 18], baseline: 'top', font: '12px system-ui, sans-serif', color: '#444' });
      // the span of u
      if (spanLabel) plot.fill([[spanLabel[0], 0], [spanLabel[1], 0], [spanLabel[1], 1.05], [spanLabel[0], 1.05]], { color: PALETTE.ink, alpha: 0.06 });
      if (!basis) return;
      const cnt = basis.count, P = basis.params, V = basis.values, m = P.length;
      const active = new Set(atU ? atU.active : []);
      const line = new Float64Array(2 * m);
      for (let i = 0; i < cnt; i++) {
        for (let j = 0; j < m; j++) { line[2 * j] = P[j]; line[2 * j + 1] = V[j * cnt + i]; }
        if (active.has(i)) plot.fillUnder(line, { color: series(i), alpha: 0.16 });
        plot.polyline(line, { color: series(i), width: active.has(i) ? 3.5 : 1.75, alpha: active.has(i) ? 1 : 0.55 });
      }
      if (state.showSum) {
        for (let j = 0; j < m; j++) { let s = 0; for (let i = 0; i < cnt; i++) s += V[j * cnt + i]; line[2 * j + 1] = s; }
        plot.polyline(line, { color: PALETTE.ink, width: 2, dash: [10, 6] });
        const [a0, b0] = domain();
        const jx = Math.round((m - 1) * ((state.u - a0) / (b0 - a0 || 1) < 0.5 ? 0.78 : 0.12));
        plot.label(P[jx], line[2 * jx + 1], 'Σ Nᵢ,ₚ(u) = 1', { offset: [0, -4], align: 'center', font: '600 13px system-ui, sans-serif' });
      }
      // labels at each function's maximum
      for (let i = 0; i < cnt; i++) {
        let best = 0, bj = 0;
        for (let j = 0; j < m; j++) if (V[j * cnt + i] > best) { best = V[j * cnt + i]; bj = j; }
        if (best > 0.05) plot.label(P[bj], best, `N${sub(i)}`, { color: series(i), offset: [0, -3], align: 'center', font: '600 13px system-ui, sans-serif' });
      }
    },
    drawOver(g, plot) {
      plot.vline(state.u, { color: PALETTE.ink, width: 2 });
      if (atU) for (const i of atU.active) plot.points([[state.u, atU.values[i]]], { color: series(i), radius: 5, stroke: '#fff' });
      plot.label(state.u, 1.19, `u = ${fmt(state.u, 3)}`, { align: 'center', offset: [0, 0], baseline: 'top', font: '600 13px system-ui, sans-serif' });
    },
  });
  basisPlot.canvas.dataset.plot = 'basis';
  const interior = () => state.knots.slice(p() + 1, n()); // u_{p+1} … u_{n-1}
  basisPlot.addHandles({
    name: 'knot',
    points: () => interior().map((k) => [k, KNOT_ROW]),
    label: () => '',
    labelOf: (j) => `Interior knot u${p() + 1 + j}`,
    color: PALETTE.ink, shape: 'triangle', radius: 7, axis: 'x', step: 0.01,
    constrain(j, q) {
      const i = p() + 1 + j, k = state.knots;
      const lo = k[i - 1] + MIN_GAP, hi = k[i + 1] - MIN_GAP;
      return [Math.min(hi, Math.max(lo, q[0])), KNOT_ROW];
    },
    move(j, q) { state.knots[p() + 1 + j] = q[0]; recompute(); },
    end() { ctx.save(); },
  });
  const sub = (i) => String(i).replace(/\d/g, (d) => '₀₁₂₃₄₅₆₇₈₉'[d]);

  // ---------- controls ----------
  const degreeCtl = buttonGroup({
    label: 'Degree p', options: [1, 2, 3, 4, 5].map((d) => ({ value: d, label: String(d) })), value: state.degree,
    onChange(d) { setDegree(d); },
  });
  const uCtl = slider({
    label: 'Parameter u', min: 0, max: 1, step: 0.001, value: state.u, number: true,
    hint: 'The p + 1 basis functions that are non-zero at u are highlighted, with their control points.',
    onInput(v) { player.pause(); setU(v); },
    onChange() { ctx.save(); },
  });
  function setU(v) { state.u = v; computeAtU(); refreshReadout(); steps?.refresh(); curvePlot.redraw(); basisPlot.redraw(); }
  // "Play u": runs u along the domain (the slider follows)
  const player = uPlayer({ range: domain, get: () => state.u, set(v) { setU(v); uCtl.set(v); }, onPause() { ctx.save(); } });
  const addBtn = button({ label: 'Add point', onClick: addPoint });
  const removeBtn = button({ label: 'Remove point', onClick: removePoint, title: 'Removes the selected control point (or the last one)' });
  const uniformBtn = button({ label: 'Uniform knots', onClick: () => { rebuildKnots(); recompute(); ctx.save(); }, title: 'Reset the interior knots to equal spacing' });
  const polyCtl = toggle({ label: 'Show control polygon', value: state.showPolygon, onChange(v) { state.showPolygon = v; curvePlot.redraw(); ctx.save(); } });
  const sumCtl = toggle({ label: 'Show the sum Σ Nᵢ,ₚ(u)', value: state.showSum, onChange(v) { state.showSum = v; basisPlot.redraw(); ctx.save(); } });
  const readout = table({ caption: 'Non-zero at u', columns: ['i', 'Nᵢ,ₚ(u)'], digits: 4 });
  const info = h('p', { class: 'ctl-hint', 'aria-live': 'polite' });
  if (options.locked) { addBtn.setDisabled(true); removeBtn.setDisabled(true); uniformBtn.setDisabled(true); }

  // ---------- step by step: de Boor at u, Boehm's insertion of u ----------
  const ALGOS = { deboor: 'de Boor’s algorithm at u', insert: 'Insert the knot u (Boehm)' };
  const algoCtl = buttonGroup({
    label: 'Algorithm', options: [{ value: 'deboor', label: 'de Boor at u' }, { value: 'insert', label: 'Insert knot u' }], value: state.stepAlgo,
    onChange(v) { state.stepAlgo = v; if (state.step >= 0) state.step = 0; steps.setTitle(ALGOS[v]); steps.refresh(); curvePlot.redraw(); ctx.save(); },
  });
  steps = stepper({
    title: ALGOS[state.stepAlgo],
    hint: 'Both use the parameter u of the slider above; the numbers follow the curve when you drag.',
    steps: () => (state.stepAlgo === 'insert' ? insertSteps() : deBoorSteps()),
    get: () => state.step,
    set(i) { state.step = i; curvePlot.redraw(); ctx.save(); },
  });

  L.controls.append(
    group('Curve', degreeCtl.el, row(addBtn.el, removeBtn.el), info, polyCtl.el),
    group('Basis functions', uCtl.el, h('div', { class: 'ctl-added' }, row(player.el)), readout.el, sumCtl.el, row(uniformBtn.el)),
    group('Step by step', algoCtl.el, steps.el),
  );
  // "Use my data" (www/lib/data-import.js): your control points; the knots become clamped uniform
  if (!options.locked) L.controls.append(group('Your data', dataImport({ label: 'Use my control points', apply: 'Use these points', min: 2, max: MAX_POINTS, onData(pts) {
    state.points = pts; state.knots = []; sanitize(); refreshControls(); recompute(); state.view = [];
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 56); ctx.save();
  } }).el));

  const num = (x, d = 3) => fmt(x, d);
  const at = (flat, j) => [flat[2 * j], flat[2 * j + 1]];
  const pt = (q) => `(${num(q[0])}, ${num(q[1])})`;
  /** `X_a, …, X_b` in TeX (just `X_a` or `X_a, X_b` when the range is that short). */
  const range = (x, a, b) => (a === b ? `${x}_{${a}}` : b === a + 1 ? `${x}_{${a}}, ${x}_{${b}}` : `${x}_{${a}}, \\ldots, ${x}_{${b}}`);
  const LEVEL = ['#D55E00', '#E69F00', '#009E73', '#CC79A7', '#0072B2', '#882255'];

  function deBoorSteps() {
    if (!tri) return [];
    const P = tri.levels.length - 1, k = tri.span, K = state.knots, u = num(state.u);
    const out = [{
      label: `the ${P + 1} control points that act at u`,
      tex: [
        `u = ${u} \\in [u_{${k}}, u_{${k + 1}}) = [${num(K[k])}, ${num(K[k + 1])}) \\;\\Rightarrow\\; k = ${k}`,
        `P^{0}_{i} = P_{i}, \\quad i = k - p, \\ldots, k = ${k - P}, \\ldots, ${k}`,
      ],
      note: `Level 0 of the triangle: only these p + 1 = ${P + 1} control points pull on C(u).`,
    }];
    for (let r = 1; r <= P; r++) {
      const L0 = tri.levels[r], A = tri.alphas[r], f = tri.firstIndex[r];
      const lines = [
        `P^{${r}}_{i} = (1 - \\alpha_{i,${r}})\\,P^{${r - 1}}_{i-1} + \\alpha_{i,${r}}\\,P^{${r - 1}}_{i}`,
        `\\alpha_{i,${r}} = \\frac{u - u_{i}}{u_{i+${P + 1 - r}} - u_{i}}, \\quad i = ${f === k ? f : k === f + 1 ? `${f}, ${k}` : `${f}, \\ldots, ${k}`}`,
      ];
      for (let j = 0; j < A.length; j++) {
        const i = f + j;
        lines.push(`\\alpha_{${i},${r}} = \\frac{${u} - ${num(K[i])}}{${num(K[i + P + 1 - r])} - ${num(K[i])}} = ${num(A[j], 4)}`);
        lines.push(`P^{${r}}_{${i}} = ${num(1 - A[j], 3)}\\,P^{${r - 1}}_{${i - 1}} + ${num(A[j], 3)}\\,P^{${r - 1}}_{${i}} = ${pt(at(L0, j))}`);
      }
      out.push({
        label: r === P ? `level ${r} of ${P}: the curve point` : `level ${r} of ${P}`,
        tex: r === P ? [...lines, `C(${u}) = P^{${P}}_{${k}} = ${pt(at(tri.point, 0))}`] : lines,
        note: r === P ? 'The last level is the curve point C(u), the diamond.' : `Each new point cuts a leg of level ${r - 1} in the ratio α : (1 − α).`,
      });
    }
    return out;
  }

  function insertSteps() {
    if (!ins) return [];
    const P = p(), k = ins.span, f = ins.first, K = state.knots, u = num(state.u);
    /** @type {{ label: string, tex: string[], note?: string }[]} */
    const out = [{
      label: 'the span of ū and the points it replaces',
      tex: [
        `\\bar u = ${u} \\in [u_{${k}}, u_{${k + 1}}) = [${num(K[k])}, ${num(K[k + 1])}) \\;\\Rightarrow\\; k = ${k}`,
        P > 1 ? `${range('P', f, k - 1)} \\;\\to\\; ${range('Q', f, k)}` : `Q_{${k}} \\;\\text{between}\\; P_{${k - 1}} \\;\\text{and}\\; P_{${k}}`,
      ],
      note: `${P - 1} control point${P - 1 === 1 ? '' : 's'} (crossed) ${P - 1 === 1 ? 'is' : 'are'} replaced by ${P} new ones on the highlighted legs; all others stay.`,
    }];
    for (let j = 0; j < P; j++) {
      const i = f + j, a = ins.alphas[j];
      out.push({
        label: `new point Q${mathText(`_{${i}}`)} (${j + 1} of ${P})`,
        tex: [
          `Q_{i} = (1 - \\alpha_{i})\\,P_{i-1} + \\alpha_{i}\\,P_{i}`,
          `\\alpha_{i} = \\frac{\\bar u - u_{i}}{u_{i+${P}} - u_{i}}`,
          `\\alpha_{${i}} = \\frac{${u} - ${num(K[i])}}{${num(K[i + P])} - ${num(K[i])}} = ${num(a, 4)}`,
          `Q_{${i}} = ${num(1 - a, 3)}\\,P_{${i - 1}} + ${num(a, 3)}\\,P_{${i}} = ${pt(at(ins.points, i))}`,
        ],
      });
    }
    out.push({
      label: 'the new control polygon: the same curve',
      tex: [
        `\\bar P = (${range('P', 0, f - 1)}, ${range('Q', f, k)}, ${range('P', k, n() - 1)})`,
        `${n() + 1} \\;\\text{points}, \\; ${K.length + 1} \\;\\text{knots (}\\bar u = ${u}\\;\\text{added)}`,
        '\\sum_{i} N_{i,p}(u)\\,P_{i} = \\sum_{i} \\bar N_{i,p}(u)\\,\\bar P_{i}',
      ],
      note: 'The new polygon (green) is closer to the curve; inserting the same knot p times splits the curve there.',
    });
    return out;
  }

  // the current step, drawn on the curve plot: lines under the handles, markers and labels over them
  function drawStepLines(plot) {
    const s = state.step;
    if (s < 0) return;
    if (state.stepAlgo === 'deboor' && tri) {
      for (let r = 0; r <= Math.min(s, tri.levels.length - 1); r++) {
        const cur = r === s;
        if (tri.levels[r].length >= 4) plot.polyline(tri.levels[r], { color: LEVEL[r % LEVEL.length], width: cur ? 3.5 : 2, alpha: cur ? 1 : 0.6 });
      }
    } else if (state.stepAlgo === 'insert' && ins) {
      const P = p(), f = ins.first;
      plot.polyline(state.points.slice(f - 1, f + P), { color: PALETTE.accent, width: 5, alpha: 0.55 });
      if (s === P + 1) plot.polyline(ins.points, { color: PALETTE.second, width: 3 });
    }
  }

  function drawStepMarks(g, plot) {
    const s = state.step;
    if (s < 0) return;
    const font = '600 13px system-ui, sans-serif';
    if (state.stepAlgo === 'deboor' && tri) {
      for (let r = 0; r <= Math.min(s, tri.levels.length - 1); r++) {
        const cur = r === s, Lr = tri.levels[r], f = tri.firstIndex[r];
        for (let j = 0; j < Lr.length / 2; j++) {
          const q = at(Lr, j);
          plot.points([q], { color: LEVEL[r % LEVEL.length], radius: cur ? 6 : 4, shape: r === tri.levels.length - 1 ? 'diamond' : 'circle', stroke: '#fff' });
          if (cur && r > 0) plot.label(q[0], q[1], mathText(`P^{${r}}_{${f + j}}`), { color: '#222', offset: [8, -8], font });
        }
      }
    } else if (state.stepAlgo === 'insert' && ins) {
      const P = p(), f = ins.first;
      if (s <= P) {
        // the points that will be replaced: crossed
        for (let i = f; i < f + P - 1; i++) {
          const q = state.points[i];
          const [X, Y] = plot.toScreen(q[0], q[1]);
          g.beginPath(); g.moveTo(X - 12, Y - 12); g.lineTo(X + 12, Y + 12); g.moveTo(X + 12, Y - 12); g.lineTo(X - 12, Y + 12);
          g.lineWidth = 3; g.strokeStyle = PALETTE.control; g.stroke();
        }
      }
      const upto = s === P + 1 ? P : s;
      for (let j = 0; j < upto; j++) {
        const q = at(ins.points, f + j);
        plot.points([q], { color: PALETTE.second, radius: j === s - 1 ? 7 : 5, shape: 'square', stroke: '#fff' });
        plot.label(q[0], q[1], mathText(`Q_{${f + j}}`), { color: '#0b5e45', offset: [8, 16], baseline: 'top', font });
      }
    }
  }

  function refreshReadout() {
    if (!atU) return;
    let s = 0;
    const rows = atU.active.map((i) => { s += atU.values[i]; return [`N${sub(i)},${sub(p())}`, atU.values[i]]; });
    rows.push(['sum', s]);
    readout.set(rows);
  }

  function refreshControls() {
    degreeCtl.set(state.degree);
    degreeCtl.inputs.forEach((inp, k) => { inp.disabled = options.locked || k + 1 > n() - 1; });
    const [a, b] = domain();
    uCtl.setRange({ min: a, max: b });
    uCtl.set(state.u);
    polyCtl.set(state.showPolygon);
    sumCtl.set(state.showSum);
    addBtn.setDisabled(options.locked || n() >= MAX_POINTS);
    removeBtn.setDisabled(options.locked || n() <= Math.max(2, p() + 1));
    info.textContent = `${n()} control points, ${state.knots.length} knots (n + p + 1 = ${n()} + ${p()} + 1).`;
    refreshReadout();
  }

  function rebuildKnots() {
    try { state.knots = clampedKnots(); } catch (e) { notify(e, 'error'); }
  }

  function setDegree(d) {
    if (d > n() - 1) { notify(`Degree ${d} needs at least ${d + 1} control points.`, 'info'); degreeCtl.set(state.degree); return; }
    state.degree = d;
    rebuildKnots();
    recompute();
    ctx.save();
  }

  function addPoint() {
    if (n() >= MAX_POINTS) return;
    const a = state.points[n() - 2], b = state.points[n() - 1];
    state.points.push([b[0] + (b[0] - a[0]) * 0.8 || b[0] + 1, b[1] + (b[1] - a[1]) * 0.8]);
    rebuildKnots();
    recompute();
    curvePlot.fitContent();
    ctx.save();
  }

  // double-click / Alt+click on the plot adds a control point on the nearest edge of the polygon; double-click on a
  // point or Delete removes it (not below p + 1 points)
  const editing = pointEditing(curvePlot, {
    group: ctrlHandles, points: () => state.points, locked: options.locked, notify,
    canAdd: () => n() < MAX_POINTS, canRemove: () => n() > Math.max(2, p() + 1),
    maxText: () => `At most ${MAX_POINTS} control points.`,
    minText: () => `A degree ${p()} B-spline needs at least ${p() + 1} control points: lower the degree to remove more.`,
    insert(i, q) { state.points.splice(i, 0, q); rebuildKnots(); recompute(); ctx.save(); },
    remove(i) { state.points.splice(i, 1); rebuildKnots(); recompute(); ctx.save(); },
  });

  function removePoint() {
    if (n() <= Math.max(2, p() + 1)) { notify(`A degree ${p()} B-spline needs at least ${p() + 1} control points: lower the degree to remove more.`, 'info'); return; }
    const sel = curvePlot.selected;
    const i = sel && sel.group === ctrlHandles ? sel.index : n() - 1;
    state.points.splice(i, 1);
    curvePlot.select(null);
    rebuildKnots();
    recompute();
    ctx.save();
  }

  // ---------- explanation ----------
  explanation(L.explain, {
    what: [
      'A B-spline curve of degree p blends its control points P₀ … Pₙ₋₁ with the basis functions Nᵢ,ₚ(u): C(u) = Σᵢ Nᵢ,ₚ(u) Pᵢ. ' +
      'Each Nᵢ,ₚ is a piecewise polynomial of degree p that is non-zero only on the knot interval [uᵢ, uᵢ₊ₚ₊₁), so at any parameter u exactly p + 1 of them are non-zero (local control), they are never negative, and they sum to 1 — so the curve stays inside the convex hull of those p + 1 control points.',
      'The knot vector is clamped: the first and last knots are repeated p + 1 times, so the curve starts at P₀ and ends at Pₙ₋₁. The top plot shows the curve; the bottom plot shows every basis function over the domain, their sum, and the knots (the triangles under the axis can be dragged).',
    ],
    math: [
      'N_{i,0}(u) = 1 \\;\\text{if}\\; u_{i} \\le u < u_{i+1}, \\;\\text{else}\\; 0',
      'N_{i,p}(u) = \\frac{u - u_{i}}{u_{i+p} - u_{i}}\\,N_{i,p-1}(u) + \\frac{u_{i+p+1} - u}{u_{i+p+1} - u_{i+1}}\\,N_{i+1,p-1}(u)',
      'C(u) = \\sum_{i} N_{i,p}(u)\\,P_{i}, \\quad \\sum_{i} N_{i,p}(u) = 1, \\quad N_{i,p}(u) \\ge 0',
      'P^{r}_{i} = (1 - \\alpha_{i,r})\\,P^{r-1}_{i-1} + \\alpha_{i,r}\\,P^{r-1}_{i}, \\quad \\alpha_{i,r} = \\frac{u - u_{i}}{u_{i+p+1-r} - u_{i}} \\quad (\\text{de Boor})',
      'Q_{i} = (1 - \\alpha_{i})\\,P_{i-1} + \\alpha_{i}\\,P_{i}, \\quad \\alpha_{i} = \\frac{\\bar u - u_{i}}{u_{i+p} - u_{i}} \\quad (\\text{Boehm})',
    ],
    mathLabel: 'Cox–de Boor recursion, the curve, de Boor’s algorithm and knot insertion',
    formulaNote: 'A term whose denominator is 0 is taken as 0. The step-by-step panel fills these formulas in with the numbers of the current curve.',
    tryThis: [
      'Drag one control point: only the part of the curve over p + 1 knot spans moves (local control).',
      'Scrub u: the highlighted basis functions are the ones whose control points (ringed) pull on C(u).',
      'Set the degree to 1: the curve becomes the control polygon. Raise it: the curve gets smoother and pulls away from the polygon.',
      'Drag two interior knots close together: the curve bends more sharply there (continuity drops as knots merge).',
      'Step by step: press Step to walk through de Boor’s triangle at u, level by level, then switch to “Insert knot u” to see which control points Boehm’s algorithm replaces.',
      'Use Tab to reach a plot, Tab/Shift+Tab to choose a point, and the arrow keys (Shift for larger steps) to move it.',
    ],
    paper: meta.paper,
  });

  // ---------- start ----------
  sanitize();
  if (!restoreView(curvePlot, state.view)) {
    state.view = [];
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 56);
  }
  recompute();

  return {
    destroy() { steps.destroy(); player.destroy(); editing.destroy(); curvePlot.destroy(); basisPlot.destroy(); },
    // idle warm-up (www/lib/warm.js): a point drag's computation and drawing with the current state (same pixels;
    // no save, and no text rewritten in the live regions)
    warm() { computeCurve(); computeAtU(); curvePlot.redraw(); basisPlot.redraw(); },
    // for the shell's Export row: the curve's samples, the basis at u and the curve point there
    exports() {
      return {
        json: curve ? { degree: p(), knots: state.knots, controlPoints: state.points, u: state.u, pointAtU: atU?.point, basisAtU: atU?.values, samples: { params: curve.params, points: curve.points } } : undefined,
        csv: curve ? { points: curve.points, dim: curve.dim || 2 } : undefined,
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------
// (imports are hoisted: this block stays self-contained at the end of the file)
import { code, snippetCode } from '../lib/snippet.js';
import { dataImport } from '../lib/data-import.js';

export function snippet(state) {
  return snippetCode(meta.title, code`
    const degree = ${state.degree};
    const knots = ${state.knots};
    const points = ${state.points};
    // the curve and all basis functions N_i,p over the knot vector (Cox–de Boor)
    const curve = sl.bsplineCurve({ degree, knots, points, samples: 400 });
    const basis = sl.bsplineBasis({ degree, knots, samples: 301 });
    // the point C(u) and the basis values N_i,p(u) at the scrubbed parameter u
    const u = ${state.u};
    const atU = sl.bsplineCurve({ degree, knots, points, at: [u] });
    const basisAtU = sl.bsplineBasis({ degree, knots, at: [u] });
    return { curve, basis, atU, basisAtU };
  `);
}
