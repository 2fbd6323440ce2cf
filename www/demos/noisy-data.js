// Demo "Noisy data" (Kuklišová, Figs. 1–3): interpolation (a = 0) reproduces the noise, approximation (a > 0)
// smooths it. A known curve plus seeded Gaussian noise, a classic data set or pasted CSV; the two fits side by
// side with their error numbers and residuals; the error-vs-a curve and a leave-one-out cross-validated a
// (not in the paper). All numbers come from the wasm API (noisyData, dataset, b2Fit, b2FitSweep); the modules in
// noisy-data/ compute, draw and explain:
//   data.js  the curves, data sets, a range, CSV parser and what a link may hold   compute.js  every wasm call
//   (the slow ones through the compute worker)   draw.js  the plots (pure) and their texts   explain.js  the text.
// This entry holds the demo contract (www/demos/README.md): meta, the declared state, mount (plots, controls,
// wiring), snippet.

import { h, demoLayout, explanation, fmt } from '../lib/dom.js';
import { math, mathText } from '../lib/mathml.js';
import { t, withNodes } from '../lib/i18n.js';
import { cite } from '../lib/papers-ref.js';
import { createPlot, PALETTE, curveSection } from '../lib/plot2d.js';
import { slider, buttonGroup, select, button, group, row, readout, numberField } from '../lib/controls.js';
import { computeClient } from '../lib/compute-client.js';
import { frameSteps } from '../lib/frame-steps.js';
import { CURVES, DATASETS, A_MIN, A_MAX, parseCsv, sanitize } from './noisy-data/data.js';
import { computations } from './noisy-data/compute.js';
import { drawFit, drawErrors, errorsView, errText, numText, describeFit } from './noisy-data/draw.js';
import { explanationContent } from './noisy-data/explain.js';

export { A_MIN, A_MAX, parseCsv };

export const meta = {
  id: 'noisy-data',
  title: 'Noisy data',
  summary: 'Interpolation reproduces the noise, approximation smooths it: error numbers, residuals and a cross-validated a.',
  paper: cite('000', 'Figs. 1–3 and §5; the cross-validation is an addition, not in the paper'),
};

export function defaults() {
  return {
    source: 'curve', curve: 'sine', dataset: 'titanium_heat', count: 60, sigma: 0.2, seed: 1,
    a: 0.25, p: 1 / 6, knots: 'chord', csv: '', view: [],
  };
}

/** @param {HTMLElement} root @param {import('../lib/host.js').DemoContext} ctx @returns {import('../lib/host.js').MountedDemo} */
export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);
  const pasted = frameSteps();      // the frames of "Use these points" (useCsv)
  const fitsDrawn = frameSteps();   // the frames of the two fits from the worker (drawFits)

  // the parser's message about the pasted points (shown under the text area)
  const csvError = h('p', { class: 'data-import-error', role: 'alert', hidden: true });
  // "Fitting… 1.2 s [Cancel]" under the two fits while large data's fits compute in the worker
  const fitStatus = h('p', { class: 'compute-line' });
  // "Cross-validating… 1.2 s [Cancel]" while a slow sweep computes in the worker (under the error plot)
  const sweepStatus = h('p', { class: 'compute-line' });
  const sweepCC = computeClient({ demoId: meta.id, wasm, status: sweepStatus, label: 'Cross-validating' });
  // "Fitting… 1.2 s [Cancel]" while the two fits of large data compute in their worker (a second client: a fits
  // request never supersedes the sweep)
  const fitsCC = computeClient({ demoId: meta.id, wasm, status: fitStatus, label: 'Fitting' });
  // every wasm call and its results c = { data, fit0, fitA, fitsOf, sweep } (noisy-data/compute.js)
  const { c, loadData, computeFits, computeSweep, shown, fitsRunHere } = computations({
    wasm, state, notify, csvError, fitsCC, sweepCC,
    onFits() { refreshNumbers(); drawFits(); },
    onSweep() { refreshNumbers(); fitErrPlot(); errPlot.redraw(); },
  });

  /** @param {{ data?: boolean, sweep?: boolean | 'later' }} [what] reload the data; sweep now, later (on release) or not */
  function all({ data: reload = true, sweep: resweep = /** @type {boolean | 'later'} */ (true) } = {}) {
    // new data: what a paste still had to do for the data before is moot
    if (reload) { pasted.cancel(); loadData(); }
    computeFits();
    // the cross-validation sweep costs ~100 ms: while a slider moves it is cleared, and recomputed on release
    if (resweep === 'later') c.sweep = null;
    else if (resweep) { computeSweep(); firstSweep = false; }
    refreshNumbers();
    for (const p of plots) p.redraw();
    errPlot.redraw();
  }

  // ---------- two plots side by side ----------
  const pair = h('div', { class: 'noisy-pair', style: { display: 'flex', gap: '0.75rem', flexWrap: 'wrap' } });
  L.plots.appendChild(pair);
  L.plots.appendChild(fitStatus);
  const cols = [0, 1].map(() => {
    const col = h('div', { style: { flex: '1 1 300px', minWidth: '0' } });
    pair.appendChild(col);
    return col;
  });
  const heads = [h('h2', { class: 'plot-title', style: { fontSize: '1.05rem', margin: '0.4rem 0' } }, t('Interpolation, a = 0')), h('h2', { class: 'plot-title', style: { fontSize: '1.05rem', margin: '0.4rem 0' } }, t('Approximation'))];
  const nums = [h('p', { class: 'plot-numbers', 'aria-live': 'polite' }), h('p', { class: 'plot-numbers', 'aria-live': 'polite' })];

  const plots = [0, 1].map((k) => {
    cols[k].append(heads[k]);
    const p = createPlot(cols[k], {
      ariaLabel: k === 0 ? 'Interpolating fit (a = 0) of the data' : 'Approximating fit of the data',
      height: 340, equal: false,
      describe: () => describeFit(wasm, c.data, shown(k === 0 ? c.fit0 : c.fitA), nums[k].textContent ?? ''),
      draw(g, plot) { drawFit(plot, c.data, shown(k === 0 ? c.fit0 : c.fitA), k === 0 ? PALETTE.second : PALETTE.curve); },
      fit: () => (c.data ? plot2bounds() : null),
      // "Table of the figure": the data points, then both fits at 11 values of their parameter (this plot's first)
      table: () => {
        const fits = [['The interpolating fit (a = 0) at 11 values of u', shown(c.fit0)], [t('The approximating fit (a = {a}) at 11 values of u', { a: fmt(state.a, 3) }), shown(c.fitA)]];
        if (k === 1) fits.reverse();
        const pts = c.data?.points ?? [];
        return [
          { title: t('Data points ({n})', { n: pts.length }), columns: ['point', 'x', 'y'], rows: pts.map((q, i) => [mathText(`D_{${i + 1}}`), q[0], q[1]]) },
          ...fits.map(([title, r]) => curveSection(title, r)),
        ].filter(Boolean);
      },
    });
    p.canvas.dataset.plot = k === 0 ? 'interp' : 'approx';
    cols[k].append(nums[k]);
    return p;
  });
  function plot2bounds() { return plots[0].boundsOf(c.data.points, c.data.truth || []); }

  // ---------- error vs a ----------
  L.plots.appendChild(h('h2', { class: 'plot-title', style: { fontSize: '1.05rem', margin: '0.4rem 0' } }, t('Error against a')));
  const errPlot = createPlot(L.plots, {
    ariaLabel: 'Fit errors as functions of the approximation parameter a',
    height: 260, pan: false, zoom: false, xLabel: 'a',
    view: { xmin: A_MIN, xmax: A_MAX, ymin: 0, ymax: 1 },
    describe: () => errText(c.sweep),
    draw(g, plot) { drawErrors(plot, c.sweep); },
    drawOver(g, plot) { plot.vline(state.a, { color: PALETTE.ink, width: 2 }); },
  });
  errPlot.canvas.dataset.plot = 'error';
  const legend = h('ul', { class: 'legend', 'aria-label': t('Legend') },
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.curve } }), t('RMS distance to the true curve (dashed: max)')),
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.control } }), t('RMS residual at the data')),
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.highlight } }),
      withNodes(t('{cv} (leave-one-out): prediction error (not in the paper)'), { cv: math('\\sqrt{\\mathrm{CV}(a)}') })));
  L.plots.appendChild(legend);
  L.plots.appendChild(sweepStatus);

  function fitErrPlot() {
    const v = errorsView(c.sweep);
    if (v) errPlot.setView(v);
  }

  function refreshNumbers() {
    heads[1].textContent = t('Approximation, a = {a}', { a: fmt(state.a, 3) });
    nums[0].textContent = numText(shown(c.fit0));
    nums[1].textContent = numText(shown(c.fitA));
    cvOut.set(errText(c.sweep) || '—');
    titleOut.set(c.data ? c.data.title : t('no data'));
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
  const useCv = button({ label: 'Use the cross-validated a', onClick: () => { if (c.sweep && c.sweep.bestCvA !== undefined) { state.a = c.sweep.bestCvA; aCtl.set(state.a); all({ data: false, sweep: false }); ctx.save(); } } });
  const pCtl = slider({ label: 'Tension p', name: 'p', min: 0, max: 0.5, step: 0.001, value: state.p, onInput(v) { state.p = v; all({ data: false, sweep: 'later' }); }, onChange() { all({ data: false }); ctx.save(); } });
  const knotCtl = buttonGroup({ label: 'Knots', options: [{ value: 'chord', label: 'chord length' }, { value: 'uniform', label: 'uniform' }], value: state.knots, onChange(v) { state.knots = v; all({ data: false }); ctx.save(); } });
  const csvArea = h('textarea', { class: 'csv-input', rows: 6, 'aria-label': t('CSV points, one "x, y" per line'), placeholder: 'x, y\n0, 0.1\n1, 0.9\n2, 0.2\n3, 1.1\n…', style: { width: '100%', fontFamily: 'monospace' } });
  csvArea.value = state.csv;
  const csvBtn = button({ label: 'Use these points', kind: 'primary', onClick: useCsv });
  const csvBox = h('div', { class: 'ctl' }, h('label', null, t('Paste points (x, y per line)')), csvArea, row(csvBtn.el), csvError);
  // a dropped .csv/.json file fills the text area (the same parser reads it)
  csvArea.addEventListener('dragover', (e) => { if (e.dataTransfer?.types?.includes('Files')) e.preventDefault(); });
  csvArea.addEventListener('drop', async (e) => { const f = e.dataTransfer?.files?.[0]; if (!f) return; e.preventDefault(); csvArea.value = (await f.text()).slice(0, 100000); });
  const cvOut = readout({ label: 'Choosing a', prose: true });
  const titleOut = readout({ label: 'Data' });

  L.controls.append(
    group('Data', srcCtl.el, curveCtl.el, countCtl.el, sigmaCtl.el, row(seedCtl.el, reseed.el), dsCtl.el, csvBox, titleOut.el),
    group('Fit', aCtl.el, pCtl.el, knotCtl.el),
    group('Choosing a', cvOut.el, row(useCv.el), h('p', { class: 'ctl-hint' }, t('Leave-one-out cross-validation is not in the paper: each interior point is predicted from a fit of the others, and the a with the smallest mean squared prediction error wins.'))),
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

  /** The fits from the worker: each plot paints in a frame of its own (issue 26: up to 2000 points with their
   * residuals each). Fits of data replaced since are not drawn; during a paste's frames only the plots it has shown
   * already (its later frames draw the others). */
  function drawFits() {
    if (c.fitsOf !== c.data) return;
    if (pasted.pending) for (let k = 0; k < shownByPaste; k++) plots[k].redraw();
    else fitsDrawn.run([() => plots[0].redraw(), () => plots[1].redraw()]);
  }

  // "Use these points" (issue 26): 2000 pasted points took up to 74 ms in one frame on a busy machine (parsing, the
  // two workers starting, the data painted on both plots). The click parses and checks them (a bad row's message
  // at once, as before); the work for good data follows, one part per frame (www/lib/frame-steps.js): the fits
  // asked for, the left plot, the sweep asked for, the right plot and the error plot. A newer paste or data change
  // drops the rest.
  let shownByPaste = 0;   // how many of the two fit plots the pending paste has shown with its data's view
  function useCsv() {
    let bounds = null;   // of the data, for both plots' views
    const show = (k) => { plots[k].fitBounds(bounds, 24); shownByPaste = k + 1; };
    pasted.run([
      () => {
        state.csv = csvArea.value.slice(0, 100000); state.source = 'csv'; srcCtl.set('csv'); refreshControls();
        loadData();
        ctx.save();
        // the parser's message (loadData showed it): nothing to fit or draw, the plots are cleared now
        if (!c.data) { pasted.cancel(); all({ data: false }); return; }
        c.sweep = null; firstSweep = false; shownByPaste = 0;
        refreshNumbers();
      },
      () => { computeFits(); refreshNumbers(); },
      () => { bounds = plot2bounds(); show(0); },
      () => { computeSweep(); refreshNumbers(); },
      () => { show(1); fitErrPlot(); errPlot.redraw(); },
    ]);
  }

  function fitView() {
    if (!c.data) return;
    const b = plot2bounds();
    for (const p of plots) p.fitBounds(b, 24);
    fitErrPlot();
  }

  explanation(L.explain, explanationContent(meta.paper));

  sanitize(state, defaults());
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
    // idle warm-up (www/lib/warm.js): a slider frame's data, fits and drawing with the current state (same data,
    // same pixels; no save). Only while the fits run here: fits in the worker would blank the plots meanwhile.
    warm() { if (pasted.pending || !fitsRunHere()) return; loadData(); computeFits(); refreshNumbers(); for (const p of plots) p.redraw(); errPlot.redraw(); },
    // for the shell's Export row: the data, both fits (a = 0 and the chosen a) and the error sweep
    exports() {
      if (!c.data) return {};
      return {
        json: { data: { title: c.data.title, points: c.data.points }, a: state.a, fitInterpolating: c.fit0, fitA: c.fitA, sweep: c.sweep },
        csv: c.fitA ? { points: c.fitA.points, dim: c.fitA.dim || 2 } : undefined,
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------
// (imports are hoisted: this block stays self-contained at the end of the file)
import { code, raw, snippetCode } from '../lib/snippet.js';

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
