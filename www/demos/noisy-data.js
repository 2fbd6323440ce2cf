// Demo "Noisy data" (Kuklišová, Figs. 1–3): interpolation (a = 0) reproduces the noise, approximation (a > 0)
// smooths it. A known curve plus seeded Gaussian noise, a classic data set or pasted CSV; the two fits side by
// side with their error numbers and residuals; the error-vs-a curve and a leave-one-out cross-validated a
// (not in the paper). All numbers come from the wasm API (noisyData, dataset, b2Fit, b2FitSweep).

import { h, demoLayout, explanation, fmt } from '../lib/dom.js';
import { math } from '../lib/mathml.js';
import { cite, readerText } from '../lib/papers-ref.js';
import { createPlot, PALETTE } from '../lib/plot2d.js';
import { slider, buttonGroup, select, button, group, row, readout, numberField } from '../lib/controls.js';
import { computeClient } from '../lib/compute-client.js';

export const meta = {
  id: 'noisy-data',
  title: 'Noisy data',
  summary: 'Interpolation reproduces the noise, approximation smooths it: error numbers, residuals and a cross-validated a.',
  paper: cite('000', 'Figs. 1–3 and §5; the cross-validation is an addition, not in the paper'),
};

const CURVES = ['sine', 'arc', 'lemniscate', 'spiral', 'step'];
const DATASETS = [{ value: 'titanium_heat', label: 'Titanium heat (de Boor, 49 points)' }, { value: 'rpn14', label: 'RPN 14 (Fritsch–Carlson, 9 points)' }];
const MAX_CSV = 2000;
// The sweep of a (error plot, slider): wide enough that the best a — by the truth and by cross-validation — lies
// inside it for the default data (sine, 60 points, σ = 0.2: truth optimum a ≈ 0.29, CV optimum a ≈ 0.24), not
// at its end. a > 1/6 extrapolates the blend L^a = 6a·L^B + (1 − 6a)·L beyond the B-spline: it smooths more.
export const A_MIN = -0.1, A_MAX = 0.5;

export function defaults() {
  return {
    source: 'curve', curve: 'sine', dataset: 'titanium_heat', count: 60, sigma: 0.2, seed: 1,
    a: 0.25, p: 1 / 6, knots: 'chord', csv: '', view: [],
  };
}

/** Parses pasted text into [[x, y], …] with the shared parser of "Use my data" (www/lib/data-import.js): CSV
 *  rows (commas, semicolons, tabs or spaces; an optional header line; # comments) or JSON. A malformed row
 *  throws an Error naming it ("row 3: expected 2 numbers, got 'abc'"). */
export function parseCsv(text, min = 1) {
  return parsePoints(String(text), { dims: [2], min, max: MAX_CSV });
}

/** @param {HTMLElement} root @param {import('../lib/host.js').DemoContext} ctx @returns {import('../lib/host.js').MountedDemo} */
export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);

  function sanitize() {
    const d = defaults();
    for (const k of Object.keys(d)) if (state[k] === undefined) state[k] = d[k];
    if (!['curve', 'dataset', 'csv'].includes(state.source)) state.source = 'curve';
    if (!CURVES.includes(state.curve)) state.curve = 'sine';
    if (!DATASETS.some((o) => o.value === state.dataset)) state.dataset = 'titanium_heat';
    const num = (k, lo, hi, int = false) => { if (!(Number.isFinite(state[k]) && state[k] >= lo && state[k] <= hi) || (int && !Number.isInteger(state[k]))) state[k] = d[k]; };
    num('count', 6, 400, true); num('sigma', 0, 2); num('seed', 0, 1e9, true); num('a', A_MIN, A_MAX); num('p', 0, 0.5);
    if (!['chord', 'uniform'].includes(state.knots)) state.knots = 'chord';
    if (typeof state.csv !== 'string') state.csv = '';
    if (state.csv.length > 100000) state.csv = state.csv.slice(0, 100000);
  }

  // ---------- data and fits (from wasm) ----------
  let data = null;      // { points: [[x,y]], truth: Float64Array|null, title }
  let fit0 = null, fitA = null, sweep = null;

  // the parser's message about the pasted points (shown under the text area)
  const csvError = h('p', { class: 'data-import-error', role: 'alert', hidden: true });
  function loadData() {
    try {
      if (state.source === 'curve') {
        const r = wasm.noisyData({ curve: state.curve, count: state.count, sigma: state.sigma, seed: state.seed });
        const pts = [];
        for (let i = 0; i < r.points.length; i += 2) pts.push([r.points[i], r.points[i + 1]]);
        data = { points: pts, truth: r.truth, title: `${state.curve} + noise σ = ${fmt(state.sigma, 3)}, draw ${state.seed}` };
      } else if (state.source === 'dataset') {
        const r = wasm.dataset({ name: state.dataset });
        const pts = [];
        for (let i = 0; i < r.points.length; i += 2) pts.push([r.points[i], r.points[i + 1]]);
        data = { points: pts, truth: null, title: readerText(r.source) };
      } else {
        let pts;
        try { pts = parseCsv(state.csv, 4); csvError.textContent = ''; csvError.hidden = true; } catch (e) {
          csvError.textContent = e.message; csvError.hidden = false;
          notify(`Your points: ${e.message}.`, 'info');
          data = null;
          return;
        }
        data = { points: pts, truth: null, title: `your ${pts.length} points` };
      }
    } catch (e) { notify(e, 'error'); data = null; }
  }

  function fitOpts(a) {
    const o = { points: data.points, a, tension: state.p, knots: state.knots, samples: 600 };
    if (state.source === 'curve') o.truthCurve = state.curve;
    return o;
  }

  // The two fits (b2Fit at a = 0 and at the slider's a) run in a worker when they are slow (issue 26;
  // www/lib/compute-client.js): ~70–110 ms for 2000 pasted points on a loaded 2-core machine. Small data (measured
  // under SYNC_MS) stays synchronous, as before. While the a slider moves over large data the newest request wins;
  // the fits on screen stay until the new ones are in, and are drawn only with the data they belong to (`fitsOf`).
  let fitToken = 0, fitsOf = null;
  function computeFits() {
    const mine = ++fitToken, of = data;
    if (!data) { fit0 = fitA = null; fitsOf = null; return; }
    const key = `fits ${data.points.length}`;
    // a new size: ~0.05 ms per point for the two fits (measured: 2000 points ≈ 70 ms in Node, 100 ms in the page)
    if (fitsCC.runsHere(key, data.points.length * 0.05)) {
      fit0 = fitA = null; fitsOf = of;
      const t0 = performance.now();
      try { fit0 = wasm.b2Fit(fitOpts(0)); } catch (e) { notify(e, 'error'); }
      try { fitA = wasm.b2Fit(fitOpts(state.a)); } catch (e) { notify(e, 'error'); }
      fitsCC.record(key, performance.now() - t0);
      return;
    }
    /** @type {import('../lib/compute-client.js').WasmCall[]} */ 
    const calls = [{ fn: 'b2Fit', args: fitOpts(0) }, { fn: 'b2Fit', args: fitOpts(state.a) }];
    fitsCC.run(calls, { key }).then((r) => {
      if (!r || mine !== fitToken) return;
      [fit0, fitA] = r; fitsOf = of;
      refreshNumbers();
      for (const p of plots) p.redraw();
    }, (e) => {
      if (mine !== fitToken) return;
      fit0 = fitA = null; fitsOf = of;
      notify(e, 'error');
      refreshNumbers();
      for (const p of plots) p.redraw();
    });
  }
  /** The fit shown for the current data (null while the data's fits are computed in the worker). */
  const shown = (fit) => (fitsOf === data ? fit : null);

  // The sweep (b2FitSweep: 36 fits, each with its leave-one-out cross-validation) runs in a worker when it is
  // slow (issue 26; www/lib/compute-client.js): ~300 ms for 200 points on a loaded 2-core machine. Small data
  // (measured under SYNC_MS) stays synchronous, as before. A sweep answered after a newer one was asked for is
  // dropped (`sweepToken`); the error plot, its readouts and "best a" follow when the sweep is in.
  let sweepToken = 0;
  function computeSweep() {
    sweep = null;
    const mine = ++sweepToken;
    if (!data) return;
    const o = { points: data.points, tension: state.p, knots: state.knots, aMin: A_MIN, aMax: A_MAX, steps: 36, cv: data.points.length <= 400 };
    if (state.source === 'curve') o.truthCurve = state.curve;
    /** @type {import('../lib/compute-client.js').WasmCall[]} */ 
    const calls = [{ fn: 'b2FitSweep', args: o }], key = `sweep ${data.points.length}${o.cv ? ' cv' : ''}`;
    // a new size: ~1.5 ms per point with cross-validation (measured: 200 points ≈ 300 ms at load 12), 0.1 without
    if (sweepCC.runsHere(key, data.points.length * (o.cv ? 1.5 : 0.1))) {
      try { sweep = sweepCC.runHere(calls, key)[0]; } catch (e) { notify(e, 'error'); }
      return;
    }
    sweepCC.run(calls, { key }).then((r) => {
      if (!r || mine !== sweepToken) return;
      sweep = r[0];
      refreshNumbers();
      fitErrPlot();
      errPlot.redraw();
    }, (e) => notify(e, 'error'));
  }

  /** @param {{ data?: boolean, sweep?: boolean | 'later' }} [what] reload the data; sweep now, later (on release) or not */
  function all({ data: reload = true, sweep: resweep = /** @type {boolean | 'later'} */ (true) } = {}) {
    if (reload) loadData();
    computeFits();
    // the cross-validation sweep costs ~100 ms: while a slider moves it is cleared, and recomputed on release
    if (resweep === 'later') sweep = null;
    else if (resweep) { computeSweep(); firstSweep = false; }
    refreshNumbers();
    for (const p of plots) p.redraw();
    errPlot.redraw();
  }

  // ---------- two plots side by side ----------
  const pair = h('div', { class: 'noisy-pair', style: { display: 'flex', gap: '0.75rem', flexWrap: 'wrap' } });
  L.plots.appendChild(pair);
  // "Fitting… 1.2 s [Cancel]" under the two fits while large data's fits compute in the worker
  const fitStatus = h('p', { class: 'compute-line' });
  L.plots.appendChild(fitStatus);
  const cols = [0, 1].map(() => {
    const col = h('div', { style: { flex: '1 1 300px', minWidth: '0' } });
    pair.appendChild(col);
    return col;
  });
  const heads = [h('h2', { class: 'plot-title', style: { fontSize: '1.05rem', margin: '0.4rem 0' } }, 'Interpolation, a = 0'), h('h2', { class: 'plot-title', style: { fontSize: '1.05rem', margin: '0.4rem 0' } }, 'Approximation')];
  const nums = [h('p', { class: 'plot-numbers', 'aria-live': 'polite' }), h('p', { class: 'plot-numbers', 'aria-live': 'polite' })];

  function drawFit(plot, res, color) {
    if (!data) return;
    if (data.truth) plot.polyline(data.truth, { color: PALETTE.muted, width: 2, dash: [6, 5] });
    if (res) {
      // residuals: data point → the curve's joint
      for (let i = 0; i < data.points.length; i++) {
        const [x, y] = data.points[i];
        plot.segment(x, y, res.joints[2 * i], res.joints[2 * i + 1], { color: PALETTE.control, width: 1.5 });
      }
      plot.polyline(res.points, { color, width: 3 });
    }
    plot.points(data.points, { color: PALETTE.ink, radius: 3.5 });
  }
  const plots = [0, 1].map((k) => {
    cols[k].append(heads[k]);
    const p = createPlot(cols[k], {
      ariaLabel: k === 0 ? 'Interpolating fit (a = 0) of the data' : 'Approximating fit of the data',
      height: 340, equal: false,
      describe: () => (k === 0 ? nums[0].textContent : nums[1].textContent),
      draw(g, plot) { drawFit(plot, shown(k === 0 ? fit0 : fitA), k === 0 ? PALETTE.second : PALETTE.curve); },
      fit: () => (data ? plot2bounds() : null),
    });
    p.canvas.dataset.plot = k === 0 ? 'interp' : 'approx';
    cols[k].append(nums[k]);
    return p;
  });
  function plot2bounds() { return plots[0].boundsOf(data.points, data.truth || []); }

  // ---------- error vs a ----------
  L.plots.appendChild(h('h2', { class: 'plot-title', style: { fontSize: '1.05rem', margin: '0.4rem 0' } }, 'Error against a'));
  const errPlot = createPlot(L.plots, {
    ariaLabel: 'Fit errors as functions of the approximation parameter a',
    height: 260, pan: false, zoom: false, xLabel: 'a',
    view: { xmin: A_MIN, xmax: A_MAX, ymin: 0, ymax: 1 },
    describe: () => errText(),
    draw(g, plot) {
      if (!sweep) return;
      const A = sweep.a, line = (ys) => { const f = new Float64Array(2 * A.length); for (let i = 0; i < A.length; i++) { f[2 * i] = A[i]; f[2 * i + 1] = ys[i]; } return f; };
      plot.vline(0, { color: '#bdbdbd', width: 1 });
      plot.vline(1 / 6, { color: '#bdbdbd', width: 1, dash: [4, 4] });
      if (sweep.rms) {
        plot.polyline(line(sweep.rms), { color: PALETTE.curve, width: 2.5 });
        plot.polyline(line(sweep.max), { color: PALETTE.curve, width: 1.5, dash: [6, 4] });
      }
      plot.polyline(line(sweep.residualRms), { color: PALETTE.control, width: 2 });
      if (sweep.cv) plot.polyline(line(Array.from(sweep.cv, Math.sqrt)), { color: PALETTE.highlight, width: 2.5 });
      if (sweep.bestCvA !== undefined) {
        plot.vline(sweep.bestCvA, { color: PALETTE.highlight, width: 2, dash: [2, 3] });
        const right = sweep.bestCvA > A_MIN + 0.6 * (A_MAX - A_MIN);
        plot.label(sweep.bestCvA, plot.getView().ymax, `CV: a = ${fmt(sweep.bestCvA, 2)}`, { color: PALETTE.highlight, offset: [right ? -4 : 4, 18], align: right ? 'right' : 'left', baseline: 'top', font: '600 12px system-ui, sans-serif' });
      }
      if (sweep.bestA !== undefined) {
        const right = sweep.bestA > A_MIN + 0.45 * (A_MAX - A_MIN);
        plot.vline(sweep.bestA, { color: PALETTE.curve, width: 1.5, dash: [2, 3] });
        plot.label(sweep.bestA, plot.getView().ymax, `best vs truth: a = ${fmt(sweep.bestA, 2)}`, { color: PALETTE.curve, offset: [right ? -4 : 4, 36], align: right ? 'right' : 'left', baseline: 'top', font: '600 12px system-ui, sans-serif' });
      }
    },
    drawOver(g, plot) { plot.vline(state.a, { color: PALETTE.ink, width: 2 }); },
  });
  errPlot.canvas.dataset.plot = 'error';
  const legend = h('ul', { class: 'legend', 'aria-label': 'Legend' },
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.curve } }), 'RMS distance to the true curve (dashed: max)'),
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.control } }), 'RMS residual at the data'),
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.highlight } }), math('\\sqrt{\\mathrm{CV}(a)}'), ' (leave-one-out): prediction error (not in the paper)'));
  L.plots.appendChild(legend);
  // "Cross-validating… 1.2 s [Cancel]" while a slow sweep computes in the worker
  const sweepStatus = h('p', { class: 'compute-line' });
  L.plots.appendChild(sweepStatus);
  const sweepCC = computeClient({ demoId: meta.id, wasm, status: sweepStatus, label: 'Cross-validating' });
  // "Fitting… 1.2 s [Cancel]" while the two fits of large data compute in their worker (a second client: a fits
  // request never supersedes the sweep)
  const fitsCC = computeClient({ demoId: meta.id, wasm, status: fitStatus, label: 'Fitting' });

  function fitErrPlot() {
    if (!sweep) return;
    let hi = 0;
    const take = (v) => { if (v) for (const x of v) if (Number.isFinite(x)) hi = Math.max(hi, x); };
    if (sweep.rms) { take(sweep.rms); take(sweep.max); }
    take(sweep.residualRms);
    if (sweep.cv) take(Array.from(sweep.cv, Math.sqrt));
    const pad = 0.01 * (A_MAX - A_MIN);
    errPlot.setView({ xmin: A_MIN - pad, xmax: A_MAX + pad, ymin: -0.05 * (hi || 1), ymax: 1.25 * (hi || 1) });
  }

  function errText() {
    if (!sweep) return 'no sweep';
    let s = '';
    if (sweep.bestCvA !== undefined) s += `Leave-one-out cross-validation picks a = ${fmt(sweep.bestCvA, 3)}. `;
    if (sweep.bestA !== undefined) s += `The smallest RMS distance to the true curve is at a = ${fmt(sweep.bestA, 3)}.`;
    return s;
  }

  const numText = (r) => {
    if (!r) return '—';
    let s = `residual RMS ${fmt(r.residualRms, 4)}`;
    if (r.rms !== undefined) s = `distance to the true curve: RMS ${fmt(r.rms, 4)}, max ${fmt(r.max, 4)} · ${s}`;
    return s;
  };
  function refreshNumbers() {
    heads[1].textContent = `Approximation, a = ${fmt(state.a, 3)}`;
    nums[0].textContent = numText(shown(fit0));
    nums[1].textContent = numText(shown(fitA));
    cvOut.set(errText() || '—');
    titleOut.set(data ? data.title : 'no data');
  }

  // ---------- controls ----------
  const srcCtl = buttonGroup({
    label: 'Data', options: [{ value: 'curve', label: 'known curve + noise' }, { value: 'dataset', label: 'classic data' }, { value: 'csv', label: 'your CSV' }], value: state.source,
    onChange(v) { state.source = v; refreshControls(); all(); fitView(); ctx.save(); },
  });
  const curveCtl = select({ label: 'True curve', options: CURVES, value: state.curve, onChange(v) { state.curve = v; all(); fitView(); ctx.save(); } });
  const dsCtl = select({ label: 'Data set', options: DATASETS, value: state.dataset, onChange(v) { state.dataset = v; all(); fitView(); ctx.save(); } });
  const countCtl = slider({ label: 'Points', name: 'count', min: 6, max: 200, step: 1, value: state.count, onInput(v) { state.count = v; all({ sweep: 'later' }); }, onChange() { all(); ctx.save(); } });
  const sigmaCtl = slider({ label: 'Noise σ', name: 'sigma', min: 0, max: 1, step: 0.005, value: state.sigma, onInput(v) { state.sigma = v; all({ sweep: 'later' }); }, onChange() { all(); ctx.save(); } });
  const seedCtl = numberField({ label: 'Noise draw', value: state.seed, min: 0, max: 1e9, step: 1, onChange(v) { state.seed = Math.round(v); all(); ctx.save(); } });
  const reseed = button({ label: 'New noise', onClick: () => { state.seed = (state.seed + 1) % 1e9; seedCtl.set(state.seed); all(); ctx.save(); } });
  const aCtl = slider({
    label: 'Approximation a', name: 'a', min: A_MIN, max: A_MAX, step: 0.001, value: state.a, number: true,
    ticks: [{ value: 0, label: '0' }, { value: 1 / 6, label: '1/6' }],
    onInput(v) { state.a = v; all({ data: false, sweep: false }); }, onChange() { ctx.save(); },
  });
  const useCv = button({ label: 'Use the cross-validated a', onClick: () => { if (sweep && sweep.bestCvA !== undefined) { state.a = sweep.bestCvA; aCtl.set(state.a); all({ data: false, sweep: false }); ctx.save(); } } });
  const pCtl = slider({ label: 'Tension p', name: 'p', min: 0, max: 0.5, step: 0.001, value: state.p, onInput(v) { state.p = v; all({ data: false, sweep: 'later' }); }, onChange() { all({ data: false }); ctx.save(); } });
  const knotCtl = buttonGroup({ label: 'Knots', options: [{ value: 'chord', label: 'chord length' }, { value: 'uniform', label: 'uniform' }], value: state.knots, onChange(v) { state.knots = v; all({ data: false }); ctx.save(); } });
  const csvArea = h('textarea', { class: 'csv-input', rows: 6, 'aria-label': 'CSV points, one "x, y" per line', placeholder: 'x, y\n0, 0.1\n1, 0.9\n2, 0.2\n3, 1.1\n…', style: { width: '100%', fontFamily: 'monospace' } });
  csvArea.value = state.csv;
  const csvBtn = button({ label: 'Use these points', kind: 'primary', onClick: () => { state.csv = csvArea.value.slice(0, 100000); state.source = 'csv'; srcCtl.set('csv'); refreshControls(); all(); fitView(); ctx.save(); } });
  const csvBox = h('div', { class: 'ctl' }, h('label', null, 'Paste points (x, y per line)'), csvArea, row(csvBtn.el), csvError);
  // a dropped .csv/.json file fills the text area (the same parser reads it)
  csvArea.addEventListener('dragover', (e) => { if (e.dataTransfer?.types?.includes('Files')) e.preventDefault(); });
  csvArea.addEventListener('drop', async (e) => { const f = e.dataTransfer?.files?.[0]; if (!f) return; e.preventDefault(); csvArea.value = (await f.text()).slice(0, 100000); });
  const cvOut = readout({ label: 'Choosing a' });
  const titleOut = readout({ label: 'Data' });

  L.controls.append(
    group('Data', srcCtl.el, curveCtl.el, countCtl.el, sigmaCtl.el, row(seedCtl.el, reseed.el), dsCtl.el, csvBox, titleOut.el),
    group('Fit', aCtl.el, pCtl.el, knotCtl.el),
    group('Choosing a', cvOut.el, row(useCv.el), h('p', { class: 'ctl-hint' }, 'Leave-one-out cross-validation is not in the paper: each interior point is predicted from a fit of the others, and the a with the smallest mean squared prediction error wins.')),
  );

  function refreshControls() {
    const c = state.source === 'curve';
    const show = (el, on) => { el.style.display = on ? '' : 'none'; };
    show(curveCtl.el, c); show(countCtl.el, c); show(sigmaCtl.el, c); show(seedCtl.el.parentElement, c);
    show(dsCtl.el, state.source === 'dataset');
    show(csvBox, state.source === 'csv');
    srcCtl.set(state.source); curveCtl.set(state.curve); dsCtl.set(state.dataset);
    countCtl.set(state.count); sigmaCtl.set(state.sigma); seedCtl.set(state.seed);
    aCtl.set(state.a); pCtl.set(state.p); knotCtl.set(state.knots);
  }

  function fitView() {
    if (!data) return;
    const b = plot2bounds();
    for (const p of plots) p.fitBounds(b, 24);
    fitErrPlot();
  }

  explanation(L.explain, {
    what: [
      'The paper\'s Figs. 1–3: an interpolating curve passes through every data point, so it reproduces the noise; an approximating curve (a > 0) smooths it. Left: a = 0; right: the a of the slider. Grey dashes: the true curve (when known); red segments: the residuals from each data point to the curve point that belongs to it.',
      'The bottom plot sweeps a from −0.1 to 0.5 (beyond a = 1/6 the blend extrapolates past the cubic B-spline and smooths more): the distance to the true curve (only for generated data), the residuals at the data (zero at a = 0, growing with a), and the leave-one-out cross-validation error, which needs no true curve and is minimal where smoothing predicts unseen points best. Cross-validation is not in the paper.',
      ['The data ', math('D_1, \\ldots, D_N'), ' get their auxiliary end points by point reflection (', math('W_0 = 2D_1 - D_2, \\; W_{-1} = 2D_1 - D_3'), ', and likewise at the end), so the curve covers all the data. Noise is reproducible: the same draw number gives the same points (SplitMix64 + Box–Muller).'],
    ],
    math: [
      'L^a = 6a\\,L^B + (1 - 6a)\\,L',
      'r_i = |L^a(u_i) - D_i|, \\quad \\mathrm{RMS} = \\sqrt{\\frac{1}{N}\\sum_i r_i^2}',
      '\\mathrm{CV}(a) = \\frac{1}{N-2}\\sum_{i=2}^{N-1} |L^a_{-i}(\\tilde{u}_i) - D_i|^2 \\quad (L^a_{-i}: \\;\\text{fit without}\\; D_i)',
    ],
    tryThis: [
      'Raise σ: the interpolating curve starts to wiggle; press "Use the cross-validated a".',
      'Set σ = 0: the best a moves to (about) 0 — with clean data, interpolation wins.',
      'Load the Titanium heat data: its sharp peak is exactly where smoothing costs accuracy.',
      'Paste your own points as "x, y" lines.',
    ],
    paper: meta.paper,
  });

  sanitize();
  refreshControls();
  // Start-up (issue 13): the first drawing (the two fits) does not wait for the error sweep with its 36
  // leave-one-out fits (the error plot and the "best a" readouts): it runs once the first frame is on screen.
  let firstSweep = true;
  let sweepFrame = 0;
  let sweepTimer = 0;
  all({ sweep: 'later' });
  fitView();
  sweepFrame = requestAnimationFrame(() => {
    sweepFrame = requestAnimationFrame(() => {
      sweepFrame = 0;
      sweepTimer = setTimeout(() => {
        if (!firstSweep) return; // a change since has computed it
        firstSweep = false;
        computeSweep();
        refreshNumbers();
        fitErrPlot();
        errPlot.redraw();
      }, 0);
    });
  });
  return {
    destroy() { cancelAnimationFrame(sweepFrame); clearTimeout(sweepTimer); sweepCC.destroy(); fitsCC.destroy(); for (const p of plots) p.destroy(); errPlot.destroy(); },
    // for the shell's Export row: the data, both fits (a = 0 and the chosen a) and the error sweep
    exports() {
      if (!data) return {};
      return {
        json: { data: { title: data.title, points: data.points }, a: state.a, fitInterpolating: fit0, fitA, sweep },
        csv: fitA ? { points: fitA.points, dim: fitA.dim || 2 } : undefined,
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------
// (imports are hoisted: this block stays self-contained at the end of the file)
import { code, raw, snippetCode } from '../lib/snippet.js';
import { parsePoints } from '../lib/data-import.js';

export function snippet(state) {
  const truth = state.source === 'curve' ? `, truthCurve: '${state.curve}'` : '';
  let data;
  if (state.source === 'curve') {
    data = code`
      // ${raw(state.count)} points of the curve '${raw(state.curve)}' plus Gaussian noise (σ = ${raw(state.sigma)}; the same draw for the same seed)
      const data = sl.noisyData({ curve: ${state.curve}, count: ${state.count}, sigma: ${state.sigma}, seed: ${state.seed} });
      const points = [];
      for (let i = 0; i < data.points.length; i += 2) points.push([data.points[i], data.points[i + 1]]);`;
  } else if (state.source === 'dataset') {
    data = code`
      const data = sl.dataset({ name: ${state.dataset} });
      const points = [];
      for (let i = 0; i < data.points.length; i += 2) points.push([data.points[i], data.points[i + 1]]);`;
  } else {
    let /** @type {any} */ pts = [];
    try { pts = parseCsv(state.csv, 4); } catch (e) { pts = raw(`[]; // your points could not be read: ${e.message.replace(/\n/g, ' ')}`); }
    data = code`
      // your data points
      const points = ${pts};`;
  }
  return snippetCode(meta.title, data + '\n' + code`
    const options = { tension: ${state.p}, knots: ${state.knots}${raw(truth)} };
    // the interpolating fit (a = 0) and the approximating fit at the chosen a
    const fitInterpolating = sl.b2Fit({ points, a: 0, ...options, samples: 600 });
    const fitA = sl.b2Fit({ points, a: ${state.a}, ...options, samples: 600 });
    // the error as a runs over [${raw(A_MIN)}, ${raw(A_MAX)}] (against the true curve, and by cross-validation)
    const sweep = sl.b2FitSweep({ points, ...options, aMin: ${A_MIN}, aMax: ${A_MAX}, steps: 36, cv: points.length <= 400 });
    return { points, fitInterpolating, fitA, sweep };
  `);
}
