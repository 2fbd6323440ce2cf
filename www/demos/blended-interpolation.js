// Demo "Blended interpolation" (quasi-cubic paper §4): the blended interpolation spline (BIS) through b₀ … bₙ with one
// local parameter β*ⱼ per point (the tangent-length ratio), the "fair by curvature" β* (exact curvature matching), and a
// curvature plot with the circle curvatures Kⱼ as dots; Titanium and RPN 14 presets as in the paper's Fig. 15.
// All spline values come from the wasm API (quasiCubicInterpolation, quasiCubicCurve); this module only draws,
// scales the data sets into the plot box and handles input.

import { h, demoLayout, explanation, fmt, legend } from '../lib/dom.js';
import { math } from '../lib/mathml.js';
import { cite, correctionLink } from '../lib/papers-ref.js';
import { createPlot, PALETTE, restoreView } from '../lib/plot2d.js';
import { slider, toggle, buttonGroup, button, group, row, readout } from '../lib/controls.js';
import { uPlayer } from '../lib/player.js';
import { pointEditing } from '../lib/point-edit.js';
import { TITANIUM, RPN14 } from '../data/datasets.js';
import { computeClient } from '../lib/compute-client.js';

export const meta = {
  id: 'blended-interpolation',
  title: 'Blended interpolation',
  summary: 'A C² interpolating spline with one tangent-length parameter β* per point; fair it by curvature.',
  paper: cite('003', '§4 (Eqs. 11–19, Fig. 15); the exact curvature matching corrects Eqs. (36)–(37)'),
};

const MAX_POINTS = 80;
const BETA_MAX = 4;
// b₋₁ … b₇ (the first and last are the auxiliary end points)
const CUSTOM = [[-1, 0.2], [0, 0], [1, 2.1], [2.7, 2.6], [3.4, 0.9], [5.2, 0.4], [6.1, 2.8], [8, 3.3], [9.5, 1.2]];

/** A data set scaled into a box [0, W] × [0, Hh], with auxiliary points continuing the first/last chord. */
function scaled(ds, W, Hh) {
  const xs = ds.x, ys = ds.y;
  const x0 = Math.min(...xs), x1 = Math.max(...xs), y0 = Math.min(...ys), y1 = Math.max(...ys);
  const pts = xs.map((x, i) => [(x - x0) / (x1 - x0) * W, (ys[i] - y0) / (y1 - y0) * Hh]);
  const a = pts[0], b = pts[1], c = pts[pts.length - 2], d = pts[pts.length - 1];
  return [[2 * a[0] - b[0], 2 * a[1] - b[1]], ...pts, [2 * d[0] - c[0], 2 * d[1] - c[1]]];
}

export function defaults() {
  return {
    dataset: 'custom',
    points: CUSTOM.map((p) => p.slice()),
    beta: [1, 1, 1, 1, 1, 1, 1],
    k: 3,
    selected: 3,
    showSpline: true,
    u: 0,
    view: [],
  };
}

/** @param {HTMLElement} root @param {import('../lib/host.js').DemoContext} ctx @returns {import('../lib/host.js').MountedDemo} */
export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);
  const sub = (i) => String(i).replace(/-/g, '₋').replace(/\d/g, (d) => '₀₁₂₃₄₅₆₇₈₉'[d]);
  const n = () => state.points.length - 3; // segments; data points b₀ … bₙ

  function sanitize() {
    if (!['custom', 'titanium', 'rpn14'].includes(state.dataset)) state.dataset = 'custom';
    if (!Array.isArray(state.points) || state.points.length < 4 || state.points.length > MAX_POINTS + 2) state.points = CUSTOM.map((p) => p.slice());
    if (!Array.isArray(state.beta) || state.beta.length !== n() + 1) state.beta = new Array(n() + 1).fill(1);
    state.beta = state.beta.map((b) => (Number.isFinite(b) ? Math.min(BETA_MAX * 4, Math.max(0, b)) : 1));
    if (![2, 3, 4].includes(state.k)) state.k = 3;
    if (!Number.isInteger(state.selected) || state.selected < 0 || state.selected > n()) state.selected = Math.min(n(), 1);
  }

  // ---------- computed data (from wasm) ----------
  let bis = null, spline = null, tangent = null, fairBeta = null;

  // The curve (quasiCubicInterpolation with curvature, ~4000 samples), the α = 3 spline, the tangent at bⱼ and the
  // fair β* run in a worker when they are slow (issue 26; www/lib/compute-client.js): ~40–200 ms for 80 points on
  // a loaded 2-core machine, in every pointer move of a drag. Small data (measured under SYNC_MS) stays
  // synchronous, as before. While dragging, the newest request wins; the points follow the pointer now, the
  // curve and its handle when they are computed.
  let computeToken = 0;
  /** Computes the curve data; `done()` runs once they are all in (now, or when the worker answers). With
   * `hereOnly` (the idle warm-up) work that would go to the worker is not started; returns whether it ran here. */
  function compute(done, { hereOnly = false } = {}) {
    const per = Math.max(8, Math.min(60, Math.floor(4000 / Math.max(1, n()))));
    const samples = n() * per + 1;
    const key = `${n()} segments, ${samples} samples${state.showSpline ? ' + spline' : ''}`;
    // a new size: ~0.6 ms per segment (measured: 79 segments ≈ 45 ms in Node, 40–200 ms in the page under load)
    if (curveCC.runsHere(key, n() * 0.6)) {
      ++computeToken;   // a pending worker answer is older than this
      const t0 = performance.now();
      try {
        bis = wasm.quasiCubicInterpolation({ points: state.points, beta: state.beta, k: state.k, samples, derivatives: 1, curvature: true });
      } catch (e) { bis = null; notify(e, 'error'); }
      try {
        spline = state.showSpline ? wasm.quasiCubicCurve({ points: state.points, alpha: 3, samples }) : null;
        // p′(j) of the α = 3 spline at the selected point: the β* handle moves along it
        const j = state.selected;
        const r = wasm.quasiCubicCurve({ points: state.points, alpha: 3, at: [j], derivatives: 1 });
        tangent = { at: [r.points[0], r.points[1]], d: [r.d1[0], r.d1[1]] };
      } catch (e) { spline = null; tangent = null; notify(e, 'error'); }
      try {
        fairBeta = wasm.quasiCubicInterpolation({ points: state.points, beta: 'curvature', k: state.k, at: [0] }).beta;
      } catch (e) { fairBeta = null; }
      curveCC.record(key, performance.now() - t0);
      done();
      return true;
    }
    if (hereOnly) return false;
    const mine = ++computeToken;
    // in the worker: a curve of another number of points is not shown meanwhile (a drag keeps the previous one)
    if (bis && bis.circleCurvature.length !== n() + 1) { bis = null; spline = null; tangent = null; fairBeta = null; }
    const points = state.points.map((p) => [p[0], p[1]]);
    /** @type {import('../lib/compute-client.js').WasmCall[]} */ 
    const calls = [
      { fn: 'quasiCubicInterpolation', args: { points, beta: state.beta.slice(), k: state.k, samples, derivatives: 1, curvature: true } },
      { fn: 'quasiCubicCurve', args: { points, alpha: 3, at: [state.selected], derivatives: 1 } },
      { fn: 'quasiCubicInterpolation', args: { points, beta: 'curvature', k: state.k, at: [0] }, optional: true },
    ];
    if (state.showSpline) calls.push({ fn: 'quasiCubicCurve', args: { points, alpha: 3, samples } });
    curveCC.run(calls, { key }).then((r) => {
      if (!r || mine !== computeToken) return;
      const [b, t, f, sp = null] = r;
      bis = b; spline = sp;
      tangent = { at: [t.points[0], t.points[1]], d: [t.d1[0], t.d1[1]] };
      fairBeta = f ? f.beta : null;
      done();
    }, (e) => {
      if (mine !== computeToken) return;
      bis = null; spline = null; tangent = null;
      notify(e, 'error');
      done();
    });
  }

  // the evaluation point p(u) of "Play u", u ∈ [0, n]
  let atU = null;
  function computeAtU() {
    if (!(state.u >= 0 && state.u <= n())) state.u = 0;
    try {
      const r = wasm.quasiCubicInterpolation({ points: state.points, beta: state.beta, k: state.k, at: [state.u] });
      atU = [r.points[0], r.points[1]];
    } catch (e) { atU = null; }
  }

  function recompute() {
    const shown = () => { computeAtU(); refresh(); curvePlot.redraw(); curvPlot.redraw(); fitCurvature(); };
    let now = false;
    compute(() => { now = true; shown(); });
    // computing in the worker: the points are drawn at once, the curve and its handle when they are in
    if (!now) { refresh(); curvePlot.redraw(); }
  }

  // "Computing the curve… 1.2 s [Cancel]" while a slow curve computes in the worker (under the plots)
  const curveStatus = h('p', { class: 'compute-line' });
  const curveCC = computeClient({ demoId: meta.id, wasm, status: curveStatus, label: 'Computing the curve' });

  // ---------- curve plot ----------
  const curvePlot = createPlot(L.plots, {
    ariaLabel: 'Blended interpolation spline with draggable data points and a tangent-length handle',
    equal: true, height: 400, locked: options.locked,
    view: { xmin: -1.5, xmax: 10, ymin: -0.5, ymax: 3.6 },
    describe: () => `Blended interpolation spline through ${n() + 1} points (k = ${state.k}). β* = ${state.beta.map((b) => fmt(b, 2)).join(', ')}. Selected point b${state.selected}.`,
    onView(v) { state.view = [v.xmin, v.xmax, v.ymin, v.ymax]; ctx.save(); },
    draw(g, plot) {
      const P = state.points;
      plot.polyline(P, { color: PALETTE.polygon, width: 1.25, dash: [6, 6], alpha: 0.7 });
      if (spline) plot.polyline(spline.points, { color: PALETTE.muted, width: 2, dash: [3, 5] });
      if (bis) plot.polyline(bis.points, { color: PALETTE.curve, width: 3 });
      if (tangent) {
        const j = state.selected, b = state.beta[j] ?? 1;
        const [x, y] = tangent.at;
        plot.segment(x - tangent.d[0] * 1.5, y - tangent.d[1] * 1.5, x + tangent.d[0] * BETA_MAX, y + tangent.d[1] * BETA_MAX, { color: PALETTE.highlight, width: 1, dash: [2, 4] });
        plot.arrow(x, y, x + b * tangent.d[0], y + b * tangent.d[1], { color: PALETTE.highlight, width: 3 });
        plot.label(x + b * tangent.d[0], y + b * tangent.d[1], `β*${sub(j)} = ${fmt(b, 2)}`, { color: PALETTE.highlight, offset: [10, -10] });
      }
    },
    drawOver(g, plot) {
      if (!atU || !(state.u > 0 || player.playing)) return;
      plot.points([atU], { color: PALETTE.ink, radius: 6, shape: 'diamond', stroke: '#fff' });
      plot.label(atU[0], atU[1], `p(${fmt(state.u, 2)})`, { offset: [10, 20], baseline: 'top' });
    },
  });
  curvePlot.canvas.dataset.plot = 'curve';
  const small = () => state.points.length > 24;
  const dataHandles = curvePlot.addHandles({
    name: 'data point',
    points: () => state.points,
    colorOf: (i) => (i === 0 || i === state.points.length - 1 ? PALETTE.muted : i - 1 === state.selected ? PALETTE.highlight : PALETTE.control),
    label: (i) => (small() && i - 1 !== state.selected ? '' : `b${sub(i - 1)}`),
    labelOf: (i) => (i === 0 || i === state.points.length - 1 ? `Auxiliary end point b${i - 1}` : `Data point b${i - 1}`),
    radius: 6,
    start(i) { if (i >= 1 && i <= n() + 1) { state.selected = i - 1; refresh(); } },
    move(i, q) { state.points[i] = [q[0], q[1]]; state.dataset = 'custom'; recompute(); },
    end() { ctx.save(); },
  });
  // the β* handle: the tip of the tangent arrow β*ⱼ·p′(j), constrained to the tangent line
  curvePlot.addHandles({
    name: 'tangent length',
    points: () => (tangent ? [[tangent.at[0] + (state.beta[state.selected] ?? 1) * tangent.d[0], tangent.at[1] + (state.beta[state.selected] ?? 1) * tangent.d[1]]] : []),
    color: PALETTE.highlight, shape: 'diamond', radius: 7,
    labelOf: () => `Tangent length β* of b${state.selected}`,
    move(_i, q) {
      if (!tangent) return;
      const d = tangent.d, dd = d[0] * d[0] + d[1] * d[1];
      if (!(dd > 0)) return;
      const b = ((q[0] - tangent.at[0]) * d[0] + (q[1] - tangent.at[1]) * d[1]) / dd;
      setBeta(state.selected, Math.min(BETA_MAX, Math.max(0, b)));
    },
    end() { ctx.save(); },
  });

  const key = legend([
    { label: 'BIS (β*)', color: PALETTE.curve },
    { label: 'α = 3 spline (all β* = 1)', color: PALETTE.muted, kind: 'dashed', dash: [3, 5] },
    { label: 'data polygon', color: PALETTE.polygon, kind: 'dashed', dash: [6, 6], alpha: 0.7 },
    { label: 'tangent β*ⱼ·p′(j): drag its tip', color: PALETTE.highlight },
    { label: 'data bⱼ (drag)', color: PALETTE.control, kind: 'dot' },
    { label: 'auxiliary b₋₁, bₙ₊₁', color: PALETTE.muted, kind: 'dot' },
  ]);
  key.dataset.legendFor = 'curve';
  L.plots.appendChild(key);
  L.plots.appendChild(curveStatus);

  // ---------- curvature plot ----------
  const curvPlot = createPlot(L.plots, {
    ariaLabel: 'Signed curvature of the spline against u, with the circle curvatures Kⱼ as dots',
    height: 230, xLabel: 'u', yLabel: 'κ',
    view: { xmin: 0, xmax: 6, ymin: -2, ymax: 2 },
    describe: () => (bis ? `Curvature at the data points: ${Array.from({ length: n() + 1 }, (_, j) => fmt(bis.curvature[j * Math.round((bis.params.length - 1) / n())], 3)).join(', ')}.` : 'Curvature plot'),
    draw(g, plot) {
      plot.hline(0, { color: PALETTE.axis, width: 1 });
      if (!bis) return;
      const m = bis.params.length, line = new Float64Array(2 * m);
      for (let j = 0; j < m; j++) { line[2 * j] = bis.params[j]; line[2 * j + 1] = bis.curvature[j]; }
      plot.polyline(line, { color: PALETTE.curve, width: 2.5 });
      const K = bis.circleCurvature;
      plot.points(Array.from(K, (k, j) => [j, k]), { color: PALETTE.control, radius: 4.5, stroke: '#fff' });
      plot.vline(state.selected, { color: PALETTE.highlight, width: 1.5, dash: [3, 4] });
    },
  });
  curvPlot.canvas.dataset.plot = 'curvature';

  function fitCurvature() {
    if (!bis) return;
    const K = Array.from(bis.circleCurvature).filter(Number.isFinite);
    const kmax = Math.max(0.2, ...K.map(Math.abs));
    const lim = 2.5 * kmax;
    let lo = Math.min(0, ...K), hi = Math.max(0, ...K);
    for (const c of bis.curvature) if (Number.isFinite(c)) { lo = Math.min(lo, Math.max(-lim, c)); hi = Math.max(hi, Math.min(lim, c)); }
    const pad = 0.08 * (hi - lo || 1);
    curvPlot.setView({ xmin: -0.02 * n(), xmax: n() * 1.02, ymin: lo - pad, ymax: hi + pad });
  }

  // ---------- controls ----------
  const datasetCtl = buttonGroup({
    label: 'Data', value: state.dataset,
    options: [{ value: 'custom', label: 'Own points' }, { value: 'titanium', label: 'Titanium' }, { value: 'rpn14', label: 'RPN 14' }],
    onChange(v) { loadDataset(v); },
  });
  const pointCtl = slider({
    label: 'Point j', min: 0, max: n(), step: 1, value: state.selected,
    onInput(v) { state.selected = v; recompute(); }, onChange() { ctx.save(); },
  });
  const betaCtl = slider({
    label: 'β*ⱼ (tangent length)', min: 0, max: BETA_MAX, step: 0.01, value: state.beta[state.selected] ?? 1, number: true,
    ticks: [{ value: 0, label: '0' }, { value: 1, label: '1' }, { value: 2, label: '2' }],
    hint: '0: a corner at bⱼ; 1: the α = 3 spline’s tangent; larger: a longer, flatter passage.',
    onInput(v) { setBeta(state.selected, v); }, onChange() { ctx.save(); },
  });
  const fairBtn = button({ label: 'Fair by curvature', kind: 'primary', onClick: fair, title: 'β*ⱼ from the exact curvature-matching rule: κ(bⱼ) = Kⱼ' });
  const onesBtn = button({ label: 'All β* = 1', onClick: () => { state.beta = state.beta.map(() => 1); recompute(); ctx.save(); } });
  const kCtl = buttonGroup({
    label: 'Allocated function order k', value: state.k,
    options: [{ value: 2, label: 'k = 2 (C¹ only)' }, { value: 3, label: 'k = 3' }, { value: 4, label: 'k = 4' }],
    onChange(v) { state.k = v; recompute(); ctx.save(); },
  });
  const splineCtl = toggle({ label: 'Show the α = 3 spline', value: state.showSpline, onChange(v) { state.showSpline = v; recompute(); ctx.save(); } });
  const addBtn = button({ label: 'Add point', onClick: () => addAfter(state.selected), title: 'Adds a data point after the selected point bⱼ' });
  const removeBtn = button({ label: 'Remove point', onClick: () => removeData(state.selected), title: 'Removes the selected data point bⱼ' });
  const uOut = readout({ label: 'Evaluation point', value: '—' });
  uOut.el.dataset.readout = 'u';
  const player = uPlayer({
    range: () => [0, n()], get: () => state.u,
    set(v) { state.u = v; computeAtU(); refreshU(); curvePlot.redraw(); },
    onPause() { ctx.save(); },
  });
  function refreshU() { uOut.set(atU ? `u = ${fmt(state.u, 3)}: p(u) = (${fmt(atU[0], 3)}, ${fmt(atU[1], 3)})` : '—'); }
  if (options.locked) { addBtn.setDisabled(true); removeBtn.setDisabled(true); }
  const kappaOut = readout({ label: 'κ(bⱼ) / Kⱼ', value: '—' });
  kappaOut.el.dataset.readout = 'kappa';
  const fairOut = readout({ label: 'fair β*ⱼ', value: '—' });
  const backOut = readout({ label: 'x runs backwards', value: '—' });
  backOut.el.dataset.readout = 'backwards';
  const note = h('p', { class: 'ctl-hint', 'aria-live': 'polite' });

  L.controls.append(
    group('Data', datasetCtl.el, note, h('div', { class: 'ctl-added' }, row(addBtn.el, removeBtn.el)), splineCtl.el, h('div', { class: 'ctl-added' }, row(player.el), uOut.el)),
    group('Local parameters β*', pointCtl.el, betaCtl.el, kappaOut.el, fairOut.el, backOut.el, row(fairBtn.el, onesBtn.el)),
    group('Blending', kCtl.el),
  );
  // "Use my data" (www/lib/data-import.js): your data points b₀…bₙ; the auxiliary b₋₁, bₙ₊₁ continue the end chords
  if (!options.locked) L.controls.append(group('Your data', dataImport({ label: 'Use my data points', apply: 'Interpolate these points', min: 2, max: MAX_POINTS, onData(d) {
    const a = d[0], b = d[1], c = d[d.length - 2], e = d[d.length - 1];
    state.points = [[2 * a[0] - b[0], 2 * a[1] - b[1]], ...d, [2 * e[0] - c[0], 2 * e[1] - c[1]]];
    state.dataset = 'custom'; state.beta = []; state.u = 0; sanitize();
    curvePlot.select(null); curvePlot.fitBounds(curvePlot.boundsOf(state.points), 40); recompute(); state.view = []; ctx.save();
  } }).el));
  if (options.locked) { fairBtn.setDisabled(true); onesBtn.setDisabled(true); }

  let labelsOf = -1;   // the point the readout labels name (typeset again only when it changes)
  function refresh() {
    refreshU();
    addBtn.setDisabled(options.locked || state.points.length >= MAX_POINTS + 2);
    removeBtn.setDisabled(options.locked || state.points.length <= MIN_POINTS);
    datasetCtl.set(state.dataset);
    pointCtl.setRange({ min: 0, max: n() });
    pointCtl.set(state.selected);
    betaCtl.set(state.beta[state.selected] ?? 1);
    kCtl.set(state.k);
    splineCtl.set(state.showSpline);
    const j = state.selected;
    if (bis) {
      const idx = Math.round(j * (bis.params.length - 1) / n());
      kappaOut.set(`${fmt(bis.curvature[idx], 4)} / ${fmt(bis.circleCurvature[j], 4)}`);
    }
    fairOut.set(fairBeta ? fmt(fairBeta[j], 4) : 'undefined here');
    // the readout labels name the selected point (typeset)
    if (labelsOf !== j) {
      labelsOf = j;
      kappaOut.el.querySelector('.ctl-readout-label').replaceChildren(math(`\\kappa(b_{${j}}) / K_{${j}}`));
      fairOut.el.querySelector('.ctl-readout-label').replaceChildren('fair ', math(`\\beta^*_{${j}}`));
    }
    if (bis) {
      // a function graph should move right all the time: count the samples where the curve moves left
      let back = 0;
      for (let i = 1; i < bis.params.length; i++) if (bis.d1[2 * i] < 0) back++;
      backOut.set(`${back} of ${bis.params.length} samples`);
    }
    note.textContent = (state.dataset === 'titanium' ? `Titanium heat data (49 points), scaled to [0, 12] × [0, 4]. ` : state.dataset === 'rpn14' ? 'RPN 14 radiochemical data (9 points, monotone), scaled to [0, 10] × [0, 4]. ' : '')
      + `${n() + 1} data points b₀ … b${sub(n())}; the grey end points b₋₁, b${sub(n() + 1)} only shape the ends.`
      + (state.k === 2 ? ' k = 2: the second derivative jumps at the data points (the curve is only C¹).' : '');
  }

  // adding and removing data points (double-click / Alt+click, Delete, the buttons); β* follows the points
  const MIN_POINTS = 5; // b₋₁, three data points, bₙ₊₁
  const minText = () => `The spline needs at least ${MIN_POINTS - 2} data points: this is the minimum.`;
  function insertAt(i, q) {
    if (state.points.length >= MAX_POINTS + 2) { notify(`At most ${MAX_POINTS} data points.`, 'info'); return; }
    i = Math.min(state.points.length - 1, Math.max(1, i)); // between b₋₁ and bₙ₊₁: a data point
    state.points.splice(i, 0, q);
    state.beta.splice(i - 1, 0, 1);
    state.selected = i - 1;
    state.dataset = 'custom';
    recompute(); ctx.save();
  }
  function removeData(j) {
    if (state.points.length <= MIN_POINTS) { notify(minText(), 'info'); return; }
    if (!(j >= 0 && j <= n())) return;
    state.points.splice(j + 1, 1);
    state.beta.splice(j, 1);
    state.selected = Math.min(state.selected, n());
    state.dataset = 'custom';
    curvePlot.select(null);
    recompute(); ctx.save();
  }
  function addAfter(j) {
    const P = state.points, i = Math.min(P.length - 2, j + 1);
    const a = P[i], b = P[i + 1] || P[i];
    insertAt(i + 1, [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2]);
  }
  const editing = pointEditing(curvePlot, {
    group: dataHandles, points: () => state.points, locked: options.locked, notify,
    canAdd: () => state.points.length < MAX_POINTS + 2,
    canRemove: (i) => i > 0 && i < state.points.length - 1 && state.points.length > MIN_POINTS,
    maxText: () => `At most ${MAX_POINTS} data points.`,
    minText: (i) => (i === 0 || i === state.points.length - 1 ? 'The auxiliary end points b₋₁ and bₙ₊₁ shape the ends: move them instead.' : minText()),
    insert(i, q) { insertAt(i, q); },
    remove(i) { removeData(i - 1); },
  });

  function setBeta(j, v) {
    if (!(j >= 0 && j < state.beta.length)) return;
    state.beta[j] = v;
    recompute();
  }

  function fair() {
    try {
      const r = wasm.quasiCubicInterpolation({ points: state.points, beta: 'curvature', k: state.k, at: [0] });
      state.beta = Array.from(r.beta);
      recompute();
      ctx.save();
    } catch (e) { notify(e, 'error'); }
  }

  function loadDataset(v) {
    state.dataset = v;
    state.points = v === 'titanium' ? scaled(TITANIUM, 12, 4) : v === 'rpn14' ? scaled(RPN14, 10, 4) : CUSTOM.map((p) => p.slice());
    state.beta = new Array(n() + 1).fill(1);
    state.selected = Math.min(state.selected, n());
    curvePlot.select(null);
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 40);
    recompute();
    ctx.save();
  }

  // ---------- explanation ----------
  explanation(L.explain, {
    what: [
      ['At ', math('\\alpha = 3'), ' the quasi-cubic spline interpolates: the curve passes through ', math('b_0, \\ldots, b_n'), ' at ', math('u = 0, \\ldots, n'), ', with tangent ', math("p'(j) = (\\frac{\\pi}{2} - 1)(b_{j+1} - b_{j-1})"), ' — but it has no free parameter. The blended interpolation spline (BIS) blends it with the chord ', math('L_i'), ' between neighbouring points through an allocated function ', math('s(t) = 10t^3 - 15t^4 + 6t^5'), ' (', math('k = 3'), '), and with a local parameter ', math('\\beta^*_j'), ' per point: at ', math('b_j'), ' the tangent becomes ', math("\\beta^*_j\\, p'(j)"), ' and the second derivative ', math("\\beta^*_j\\, p''(j)"), ', so the curve stays ', math('C^2'), '.'],
      '“Fair by curvature” chooses every β*ⱼ so that the curve’s curvature at bⱼ equals the curvature Kⱼ of the circle through bⱼ₋₁, bⱼ, bⱼ₊₁ (the dots in the lower plot). The paper’s Eq. (36) is garbled and only approximates this; SplineLab uses the exact rule below. The paper (Fig. 15) presents this as shape-preserving on the Titanium and RPN 14 data. Measured here it is not: on long, nearly straight runs the rule gives β* ≈ c₁/(4c₀²) ≈ 1.89, the tangents at the data points become about twice the chord, the curve nearly stops in the middle of each segment, and tiny loops appear (the “x runs backwards” readout counts them; the curvature plot spikes). The curvature at the data points is matched exactly all the same.',
    ],
    math: [
      '\\mathrm{BIS}_i(t) = L_i(t) + \\beta_i(t)\\,(p_i(t) - L_i(t)), \\quad L_i = (1 - s)\\,b_i + s\\,b_{i+1}, \\quad \\beta_i = (1 - s)\\,\\beta^*_i + s\\,\\beta^*_{i+1}',
      's(t) = \\sum_{j=k}^{2k-1} \\mathrm{C}(2k-1, j)\\, t^j (1 - t)^{2k-1-j} \\qquad (k = 3: \\; 10t^3 - 15t^4 + 6t^5)',
      '\\text{fair:}\\quad \\beta^*_j = \\frac{c_1}{c_0^2} \\cdot \\frac{|b_j - b_{j-1}| \\, |b_{j+1} - b_j|}{|b_{j+1} - b_{j-1}|^2}, \\quad c_0 = \\frac{\\pi}{2} - 1, \\quad c_1 = \\frac{\\pi^2}{4}',
    ],
    tryThis: [
      'Drag the pink diamond along the tangent: β* = 0 makes a corner, β* = 2 a long flat passage; the curvature plot changes only near that point.',
      'Press “Fair by curvature”: the curvature at every data point lands on its dot.',
      'Load Titanium and press “Fair by curvature”: the dots are hit exactly, but zoom into the flat part — the curve makes small loops, and “x runs backwards” is no longer 0. Set β* back to 1 and compare.',
      'Choose k = 2: the curvature plot jumps at the data points — the curve is only C¹.',
    ],
    formulaNote: ['Correction (', correctionLink('correction-003-eq36', 'eqs. (36)–(37)'), '): the printed local parameters match the curvature only approximately; “fair by curvature” uses the exact rule, and the allocated function needs k ≥ 3 for C².'],
    paper: meta.paper,
  });

  // ---------- start ----------
  sanitize();
  if (!restoreView(curvePlot, state.view)) {
    state.view = [];
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 40);
  }
  recompute();

  return {
    destroy() { curveCC.destroy(); player.destroy(); editing.destroy(); curvePlot.destroy(); curvPlot.destroy(); },
    // idle warm-up (www/lib/warm.js): a point drag's computation and drawing with the current state (same pixels;
    // no save, and no text rewritten in the live regions)
    // (only work that runs on the page: what goes to the worker needs no warming here)
    warm() { if (compute(() => {}, { hereOnly: true })) { computeAtU(); curvePlot.redraw(); curvPlot.redraw(); } },
    // for the shell's Export row: the interpolating curve's samples and the β used
    exports() {
      return {
        json: bis ? { beta: bis.beta, curvatureMatchingBeta: fairBeta, samples: { params: bis.params, points: bis.points } } : undefined,
        csv: bis ? { points: bis.points, dim: bis.dim || 2 } : undefined,
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------
// (imports are hoisted: this block stays self-contained at the end of the file)
import { code, snippetCode } from '../lib/snippet.js';
import { dataImport } from '../lib/data-import.js';

export function snippet(state) {
  const n = state.points.length - 3;
  const samples = n * Math.max(8, Math.min(60, Math.floor(4000 / Math.max(1, n)))) + 1;
  return snippetCode(meta.title, code`
    // b₋₁ … bₙ₊₁: the data points and the two auxiliary end points
    const points = ${state.points};
    const beta = ${state.beta};
    const k = ${state.k};
    const curve = sl.quasiCubicInterpolation({ points, beta, k, samples: ${samples}, derivatives: 1, curvature: true });
    // the β* that match the curvature of the α = 3 spline at the data points
    const curvatureMatching = sl.quasiCubicInterpolation({ points, beta: 'curvature', k, at: [0] });
    const spline = ${state.showSpline} ? sl.quasiCubicCurve({ points, alpha: 3, samples: ${samples} }) : null;
    const atU = sl.quasiCubicInterpolation({ points, beta, k, at: [${state.u}] });
    return { curve, curvatureMatchingBeta: curvatureMatching.beta, spline, atU };
  `);
}
