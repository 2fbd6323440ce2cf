// What "Noisy data" computes (every value from the wasm API: noisyData, dataset, b2Fit, b2FitSweep) into one
// object c = { data, fit0, fitA, fitsOf, sweep }: the data points (a known curve plus seeded Gaussian noise, a
// classic data set, or the pasted points) with the true curve when known, the two fits Lᵃ = 6a·Lᴮ + (1 − 6a)·L at
// a = 0 (interpolation) and at the slider's a (the paper's Figs. 1–3), and the sweep of a with the errors and the
// leave-one-out cross-validation (not in the paper). Slow fits and sweeps go to the compute worker through
// www/lib/compute-client.js (issue 26); small data stays synchronous.
import { fmt } from '../../lib/dom.js';
import { t, tn } from '../../lib/i18n.js';
import { readerText } from '../../lib/papers-ref.js';
import { A_MIN, A_MAX, parseCsv } from './data.js';
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

/** Flat [x0, y0, x1, y1, …] → [[x, y], …]. */
function pairs(flat) {
  const pts = [];
  for (let i = 0; i < flat.length; i += 2) pts.push([flat[i], flat[i + 1]]);
  return pts;
}

/**
 * The computations of one mounted demo. `fitsCC` and `sweepCC` are its two compute clients (a fits request never
 * supersedes the sweep); `csvError` is the parser's message element under the text area; `onFits` / `onSweep`
 * redraw when a worker's answer lands.
 * @param {{ wasm: SplineLab, state: any, notify: (m: any, k?: string) => void, csvError: HTMLElement,
 *   fitsCC: ReturnType<typeof import('../../lib/compute-client.js').computeClient>,
 *   sweepCC: ReturnType<typeof import('../../lib/compute-client.js').computeClient>,
 *   onFits: () => void, onSweep: () => void }} o
 */
export function computations({ wasm, state, notify, csvError, fitsCC, sweepCC, onFits, onSweep }) {
  /** @type {{ data: { points: number[][], truth: Float64Array | null, title: string } | null, fit0: any, fitA: any, fitsOf: any, sweep: any }} */
  const c = { data: null, fit0: null, fitA: null, fitsOf: null, sweep: null };

  function loadData() {
    try {
      if (state.source === 'curve') {
        const r = wasm.noisyData({ curve: state.curve, count: state.count, sigma: state.sigma, seed: state.seed });
        c.data = { points: pairs(r.points), truth: r.truth, title: t('{curve} + noise σ = {sigma}, draw {seed}', { curve: t(state.curve), sigma: fmt(state.sigma, 3), seed: String(state.seed) }) };
      } else if (state.source === 'dataset') {
        const r = wasm.dataset({ name: state.dataset });
        c.data = { points: pairs(r.points), truth: null, title: t(readerText(r.source)) };
      } else {
        let pts;
        try { pts = parseCsv(state.csv, 4); csvError.textContent = ''; csvError.hidden = true; } catch (e) {
          csvError.textContent = e.message; csvError.hidden = false;
          notify(t('Your points: {message}.', { message: e.message }), 'info');
          c.data = null;
          return;
        }
        c.data = { points: pts, truth: null, title: tn(pts.length, 'your {n} point', 'your {n} points') };
      }
    } catch (e) { notify(e, 'error'); c.data = null; }
  }

  function fitOpts(a) {
    const o = { points: c.data.points, a, tension: state.p, knots: state.knots, samples: 600 };
    if (state.source === 'curve') o.truthCurve = state.curve;
    return o;
  }

  // The two fits (b2Fit at a = 0 and at the slider's a) run in a worker when they are slow (issue 26;
  // www/lib/compute-client.js): ~70–110 ms for 2000 pasted points on a loaded 2-core machine. Small data (measured
  // under SYNC_MS) stays synchronous, as before. While the a slider moves over large data the newest request wins;
  // the fits on screen stay until the new ones are in, and are drawn only with the data they belong to (`shown`).
  let fitToken = 0;
  function computeFits() {
    const mine = ++fitToken, of = c.data;
    if (!c.data) { c.fit0 = c.fitA = null; c.fitsOf = null; return; }
    const key = `fits ${c.data.points.length}`;
    // a new size: ~0.05 ms per point for the two fits (measured: 2000 points ≈ 70 ms in Node, 100 ms in the page)
    if (fitsCC.runsHere(key, c.data.points.length * 0.05)) {
      c.fit0 = c.fitA = null; c.fitsOf = of;
      const t0 = performance.now();
      try { c.fit0 = wasm.b2Fit(fitOpts(0)); } catch (e) { notify(e, 'error'); }
      try { c.fitA = wasm.b2Fit(fitOpts(state.a)); } catch (e) { notify(e, 'error'); }
      fitsCC.record(key, performance.now() - t0);
      return;
    }
    /** @type {import('../../lib/compute-client.js').WasmCall[]} */
    const calls = [{ fn: 'b2Fit', args: fitOpts(0) }, { fn: 'b2Fit', args: fitOpts(state.a) }];
    fitsCC.run(calls, { key }).then((r) => {
      if (!r || mine !== fitToken) return;
      [c.fit0, c.fitA] = r; c.fitsOf = of;
      onFits();
    }, (e) => {
      if (mine !== fitToken) return;
      c.fit0 = c.fitA = null; c.fitsOf = of;
      notify(e, 'error');
      onFits();
    });
  }

  // The sweep (b2FitSweep: 36 fits, each with its leave-one-out cross-validation) runs in a worker when it is
  // slow (issue 26; www/lib/compute-client.js): ~300 ms for 200 points on a loaded 2-core machine. Small data
  // (measured under SYNC_MS) stays synchronous, as before. A sweep answered after a newer one was asked for is
  // dropped (`sweepToken`); the error plot, its readouts and "best a" follow when the sweep is in.
  let sweepToken = 0;
  function computeSweep() {
    c.sweep = null;
    const mine = ++sweepToken;
    if (!c.data) return;
    const o = { points: c.data.points, tension: state.p, knots: state.knots, aMin: A_MIN, aMax: A_MAX, steps: 36, cv: c.data.points.length <= 400 };
    if (state.source === 'curve') o.truthCurve = state.curve;
    /** @type {import('../../lib/compute-client.js').WasmCall[]} */
    const calls = [{ fn: 'b2FitSweep', args: o }], key = `sweep ${c.data.points.length}${o.cv ? ' cv' : ''}`;
    // a new size: ~1.5 ms per point with cross-validation (measured: 200 points ≈ 300 ms at load 12), 0.1 without
    if (sweepCC.runsHere(key, c.data.points.length * (o.cv ? 1.5 : 0.1))) {
      try { c.sweep = sweepCC.runHere(calls, key)[0]; } catch (e) { notify(e, 'error'); }
      return;
    }
    sweepCC.run(calls, { key }).then((r) => {
      if (!r || mine !== sweepToken) return;
      c.sweep = r[0];
      onSweep();
    }, (e) => notify(e, 'error'));
  }

  /** Do the fits of the current data run here, synchronously (measured small, no worker request pending)? */
  const fitsRunHere = () => !!c.data && fitsCC.runsHere(`fits ${c.data.points.length}`, c.data.points.length * 0.05);

  /** The fit shown for the current data (null while the data's fits are computed in the worker). */
  const shown = (fit) => (c.fitsOf === c.data ? fit : null);

  return { c, loadData, computeFits, computeSweep, shown, fitsRunHere };
}
