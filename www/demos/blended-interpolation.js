// Demo "Blended interpolation" (quasi-cubic paper §4): the blended interpolation spline (BIS) through b₀ … bₙ with one
// local parameter β*ⱼ per point (the tangent-length ratio), the "fair by curvature" β* (exact curvature matching), and a
// curvature plot with the circle curvatures Kⱼ as dots; Titanium and RPN 14 presets as in the paper's Fig. 15.
// All spline values come from the wasm API (quasiCubicInterpolation, quasiCubicCurve; slow ones in the compute
// worker, www/lib/compute-client.js); the modules in blended-interpolation/ compute and draw:
//   data.js  limits, data sets, their note   state-rules.js  what a link may hold   compute.js  every wasm call
//   draw.js  both plots (pure)   explain.js  the explanation.
// This entry holds the demo contract (www/demos/README.md): meta, the declared state, mount (plots, controls,
// point and β* editing), snippet.

import { h, demoLayout, explanation, fmt, legend } from '../lib/dom.js';
import { math, mathText } from '../lib/mathml.js';
import { cite } from '../lib/papers-ref.js';
import { createPlot, PALETTE, restoreView, curveSection, evenParams, paramRange } from '../lib/plot2d.js';
import { slider, toggle, buttonGroup, button, group, row, readout } from '../lib/controls.js';
import { uPlayer } from '../lib/player.js';
import { pointEditing } from '../lib/point-edit.js';
import { computeClient } from '../lib/compute-client.js';
import { code, snippetCode } from '../lib/snippet.js';
import { dataImport } from '../lib/data-import.js';
import { MAX_POINTS, BETA_MAX, CUSTOM, MIN_POINTS, sub, datasetPoints, dataNote } from './blended-interpolation/data.js';
import { sanitize as sanitizeRules } from './blended-interpolation/state-rules.js';
import { createComputation, curvatureMatchingBeta } from './blended-interpolation/compute.js';
import { describeCurve, describeCurvature, drawCurve, drawCurveOver, drawCurvature, curvatureView } from './blended-interpolation/draw.js';
import { explanationContent } from './blended-interpolation/explain.js';
import { splineTrace } from './blended-interpolation/sound.js';

export const meta = {
  id: 'blended-interpolation',
  title: 'Blended interpolation',
  summary: 'A C² interpolating spline with one tangent-length parameter β* per point; fair it by curvature.',
  paper: cite('003', '§4 (Eqs. 11–19, Fig. 15); the exact curvature matching corrects Eqs. (36)–(37)'),
};

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
  const n = () => state.points.length - 3; // segments; data points b₀ … bₙ

  const sanitize = () => sanitizeRules(state);

  // ---------- computed data (all from wasm: blended-interpolation/compute.js) ----------
  // "Computing the curve… 1.2 s [Cancel]" while a slow curve computes in the worker (under the plots)
  const curveStatus = h('p', { class: 'compute-line' });
  const curveCC = computeClient({ demoId: meta.id, wasm, status: curveStatus, label: 'Computing the curve' });
  const { c, compute, computeAtU } = createComputation({ wasm, state, notify, curveCC });

  function recompute() {
    const shown = () => { computeAtU(); refresh(); curvePlot.redraw(); curvPlot.redraw(); fitCurvature(); };
    let now = false;
    compute(() => { now = true; shown(); });
    // computing in the worker: the points are drawn at once, the curve and its handle when they are in
    if (!now) { refresh(); curvePlot.redraw(); }
  }

  // ---------- curve plot ----------
  const curvePlot = createPlot(L.plots, {
    ariaLabel: 'Blended interpolation spline with draggable data points and a tangent-length handle',
    equal: true, height: 400, locked: options.locked,
    view: { xmin: -1.5, xmax: 10, ymin: -0.5, ymax: 3.6 },
    describe: () => describeCurve(state, c, wasm),
    sound: () => splineTrace(wasm, state, c), // ♪ (blended-interpolation/sound.js)
    table: () => { const r = paramRange(c.bis); return r ? [curveSection('The blended spline at 11 values of u', wasm.quasiCubicInterpolation({ points: state.points, beta: state.beta, k: state.k, at: evenParams(...r) }))] : []; },
    onView(v) { state.view = [v.xmin, v.xmax, v.ymin, v.ymax]; ctx.save(); },
    draw(g, plot) { drawCurve(plot, state, c); },
    drawOver(g, plot) { drawCurveOver(plot, state, c, player.playing); },
  });
  curvePlot.canvas.dataset.plot = 'curve';
  const small = () => state.points.length > 24;
  const dataHandles = curvePlot.addHandles({
    name: 'data point',
    points: () => state.points,
    colorOf: (i) => (i === 0 || i === state.points.length - 1 ? PALETTE.muted : i - 1 === state.selected ? PALETTE.highlight : PALETTE.control),
    label: (i) => (small() && i - 1 !== state.selected ? '' : `b${sub(i - 1)}`),
    labelOf: (i) => `${i === 0 || i === state.points.length - 1 ? 'Auxiliary end point' : 'Data point'} ${mathText(`b_{${i - 1}}`)}`,
    radius: 6,
    start(i) { if (i >= 1 && i <= n() + 1) { state.selected = i - 1; refresh(); } },
    move(i, q) { state.points[i] = [q[0], q[1]]; state.dataset = 'custom'; recompute(); },
    end() { ctx.save(); },
  });
  // the β* handle: the tip of the tangent arrow β*ⱼ·p′(j), constrained to the tangent line
  curvePlot.addHandles({
    name: 'tangent length',
    points: () => (c.tangent ? [[c.tangent.at[0] + (state.beta[state.selected] ?? 1) * c.tangent.d[0], c.tangent.at[1] + (state.beta[state.selected] ?? 1) * c.tangent.d[1]]] : []),
    color: PALETTE.highlight, shape: 'diamond', radius: 7,
    labelOf: () => `Tangent length β* of ${mathText(`b_{${state.selected}}`)}`,
    move(_i, q) {
      const { tangent } = c;
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
    describe: () => describeCurvature(state, c),
    draw(g, plot) { drawCurvature(plot, state, c); },
  });
  curvPlot.canvas.dataset.plot = 'curvature';

  function fitCurvature() {
    const v = curvatureView(state, c);
    if (v) curvPlot.setView(v);
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
  function refreshU() { const { atU } = c; uOut.set(atU ? `u = ${fmt(state.u, 3)}: p(u) = (${fmt(atU[0], 3)}, ${fmt(atU[1], 3)})` : '—'); }
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
    const { bis, fairBeta } = c;
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
    note.textContent = dataNote(state);
  }

  // adding and removing data points (double-click / Alt+click, Delete, the buttons); β* follows the points
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
      state.beta = Array.from(curvatureMatchingBeta(wasm, state));
      recompute();
      ctx.save();
    } catch (e) { notify(e, 'error'); }
  }

  function loadDataset(v) {
    state.dataset = v;
    state.points = datasetPoints(v);
    state.beta = new Array(n() + 1).fill(1);
    state.selected = Math.min(state.selected, n());
    curvePlot.select(null);
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 40);
    recompute();
    ctx.save();
  }

  // ---------- explanation (blended-interpolation/explain.js) ----------
  explanation(L.explain, explanationContent(meta));

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
      const { bis, fairBeta } = c;
      return {
        json: bis ? { beta: bis.beta, curvatureMatchingBeta: fairBeta, samples: { params: bis.params, points: bis.points } } : undefined,
        csv: bis ? { points: bis.points, dim: bis.dim || 2 } : undefined,
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------

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
