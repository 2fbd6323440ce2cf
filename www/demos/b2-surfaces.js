// Demo "B2 surfaces" (Kuklišová §6–7): the tensor-product B2-spline surface of a grid W_ij with the a slider
// (a = 0 interpolates the grid, a = 1/6 is the bicubic B-spline), tensions in u and v, draggable grid points,
// and — when the module exports it — the spline-blended surface of a network formula. Surface values and
// render buffers come from the wasm API (b2Surface, splineBlendedSurface); View3D draws them.

import { subscript as sub } from '../lib/indices.js';
import { h, demoLayout, explanation, fmt } from '../lib/dom.js';
import { math, mathText } from '../lib/mathml.js';
import { cite } from '../lib/papers-ref.js';
import { View3D } from '../lib/view3d.js';
import { slider, buttonGroup, select, button, group, row, readout, toggle } from '../lib/controls.js';
import { computeClient } from '../lib/compute-client.js';

export const meta = {
  id: 'b2-surfaces',
  title: 'B2 surfaces',
  summary: 'Tensor-product B2-spline surfaces: from interpolating the grid (a = 0) to the bicubic B-spline (a = 1/6).',
  paper: cite('000', '§6 tensor-product surfaces, §7 spline-blended surfaces'),
};

// Height functions for the grid W_ij = (x_i, y_j, f(x_i, y_j)) and for the network of the blended surface
// (data only; no spline maths).
const SHAPES = {
  hill: { label: 'hill', f: (x, y) => 2.2 * Math.exp(-((x - 2.5) ** 2 + (y - 2.5) ** 2) / 2.5) },
  saddle: { label: 'saddle', f: (x, y) => 0.18 * ((x - 2.5) ** 2 - (y - 2.5) ** 2) },
  ripple: { label: 'ripple', f: (x, y) => 0.8 * Math.sin(1.3 * x) * Math.cos(1.1 * y) },
  step: { label: 'step (overshoot test)', f: (x, y) => (x + 0.3 * y > 3 ? 1.5 : 0) },
};
const SAMPLES = 41;

export function defaults() {
  return { mode: 'tensor', shape: 'hill', size: 8, a: 0, tu: 1 / 6, tv: 1 / 6, knots: 'uniform', showNet: true, colors: true, edits: [], view: null, grid: null };
}

/** @param {HTMLElement} root @param {import('../lib/host.js').DemoContext} ctx @returns {import('../lib/host.js').MountedDemo} */
export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);
  const hasBlended = typeof wasm.splineBlendedSurface === 'function';

  function sanitize() {
    const d = defaults();
    for (const k of Object.keys(d)) if (state[k] === undefined) state[k] = d[k];
    if (!['tensor', 'blended'].includes(state.mode) || (state.mode === 'blended' && !hasBlended)) state.mode = 'tensor';
    if (!SHAPES[state.shape]) state.shape = 'hill';
    const num = (k, lo, hi) => { if (!(Number.isFinite(state[k]) && state[k] >= lo && state[k] <= hi)) state[k] = d[k]; };
    num('size', 6, 14); state.size = Math.round(state.size);
    num('a', -0.1, 0.25); num('tu', 0, 0.5); num('tv', 0, 0.5);
    if (!['uniform', 'chord'].includes(state.knots)) state.knots = 'uniform';
    // edits: [[i, j, dz], …] — heights added to the formula's grid points
    if (!Array.isArray(state.edits)) state.edits = [];
    state.edits = state.edits.filter((e) => Array.isArray(e) && e.length === 3 && Number.isInteger(e[0]) && Number.isInteger(e[1]) &&
      e[0] >= 0 && e[0] < rowsOf() && e[1] >= 0 && e[1] < colsOf() && Number.isFinite(e[2]) && Math.abs(e[2]) <= 10).slice(0, 200);
    state.showNet = !!state.showNet; state.colors = !!state.colors;
    // grid: your own grid W_ij ("Use my data"; null = the formula's), rectangular, points [x, y, z]
    if (state.grid !== null && !validGrid(state.grid)) state.grid = null;
  }

  // ---------- the grid W_-1..W_m+2 × W_-1..W_n+2 ----------
  const coord = (k) => (k - 1) * 5 / (state.size - 3);
  const rowsOf = () => (state.grid ? state.grid.length : state.size);
  const colsOf = () => (state.grid ? state.grid[0].length : state.size);
  // the height a grid point has before its edit: your grid's, else the formula's
  const baseZ = (i, j) => (state.grid ? state.grid[i][j][2] : SHAPES[state.shape].f(coord(i), coord(j)));
  function grid() {
    if (state.grid && state.mode === 'tensor') {
      const dz = new Map(state.edits.map(([i, j, z]) => [`${i},${j}`, z]));
      return state.grid.map((r, i) => r.map((p, j) => [p[0], p[1], p[2] + (dz.get(`${i},${j}`) || 0)]));
    }
    const f = SHAPES[state.shape].f, s = state.size, out = [];
    // the spline-blended surface interpolates the formula's network itself: edits apply to the tensor grid only
    const dz = new Map(state.mode === 'tensor' ? state.edits.map(([i, j, z]) => [`${i},${j}`, z]) : []);
    for (let i = 0; i < s; i++) {
      const r = [];
      for (let j = 0; j < s; j++) r.push([coord(i), coord(j), f(coord(i), coord(j)) + (dz.get(`${i},${j}`) || 0)]);
      out.push(r);
    }
    return out;
  }

  // The tensor-product surface (b2Surface of the grid, 41² samples with its mesh) runs in a worker when it is slow
  // (issue 26; www/lib/compute-client.js): up to ~200 ms for your 32 × 32 grid on a loaded 2-core machine. Small
  // grids (measured under SYNC_MS) stay synchronous, as before; while a grid point is dragged the newest request
  // wins. The spline-blended surface (a network formula: a function, which cannot go to a worker; at most 14
  // curves each way) is computed here.
  // the compute client's name for the size of the work, and its estimate for a size it has not measured yet:
  // ~0.02 ms per grid point (measured: 32 × 32 ≈ 4 ms in Node, 20–200 ms in the page under load)
  const workKey = (mode, g) => `${mode} ${g.length} × ${g[0].length}`;
  const guessMs = (g) => g.length * g[0].length * 0.02;
  let W = null, surf = null, surfKey = '';
  let computeToken = 0;
  const tensorArgs = (g) => ({ grid: g, a: state.a, tensionU: state.tu, tensionV: state.tv, knotsU: state.knots, knotsV: state.knots, samplesU: SAMPLES, samplesV: SAMPLES, mesh: true });
  /** Computes the surface; `ready()` runs once it is in. Returns true when that was now (synchronously). */
  function compute(ready = () => {}) {
    const mine = ++computeToken;
    W = grid();
    const key = workKey(state.mode, W);
    if (state.mode !== 'tensor' || surfaceCC.runsHere(key, guessMs(W))) {
      surf = null;
      const t0 = performance.now();
      try {
        if (state.mode === 'tensor') surf = wasm.b2Surface(tensorArgs(W));
        else {
          const f = SHAPES[state.shape].f, s = state.size;
          const knots = Array.from({ length: s }, (_, k) => coord(k));
          surf = wasm.splineBlendedSurface({ network: (u, v) => [u, v, f(u, v)], uKnots: knots, vKnots: knots, blend: 'b2', a: state.a, tensionU: state.tu, tensionV: state.tv, samplesU: SAMPLES, samplesV: SAMPLES, mesh: true });
        }
      } catch (e) { notify(e, 'error'); }
      surfaceCC.record(key, performance.now() - t0);
      surfKey = key;
      ready();
      return true;
    }
    // in the worker: a surface of another grid is not shown meanwhile (a drag keeps the previous one)
    if (surfKey !== key) surf = null;
    surfaceCC.run([{ fn: 'b2Surface', args: tensorArgs(W) }], { key }).then((r) => {
      if (!r || mine !== computeToken) return;
      surf = r[0]; surfKey = key;
      ready();
    }, (e) => {
      if (mine !== computeToken) return;
      surf = null; surfKey = key;
      notify(e, 'error');
      ready();
    });
    return false;
  }

  // ---------- the 3D view ----------
  const view = new View3D(L.plots, {
    height: 480, locked: options.locked,
    ariaLabel: 'B2 surface with its grid; the grid points can be dragged up and down',
    onViewChange(v) { state.view = v; ctx.save(); },
  });
  view.canvas.dataset.plot = 'surface';
  view.canvas.view3d = view; // for tests and devtools

  function drawSurface() {
    if (surf && surf.mesh) view.setMesh('S', surf.mesh, { isolines: true, colors: state.colors ? 'height' : undefined, color: PALETTE.sky, legend: 'height z' });
    // computing in the worker: the previous surface is hidden meanwhile (not removed: the view keeps its place
    // in the drawing order, so the new one is drawn exactly as when computed here)
    else if (surfaceCC.busy) view.setVisible('S', false);
    else view.remove('S');
    showSurfaceSwatch();
    if (W) {
      const lines = [];
      for (const r of W) lines.push(r.flat());
      for (let j = 0; j < W[0].length; j++) lines.push(W.flatMap((r) => r[j]));
      view.setLines('grid', lines, { color: PALETTE.polygon, width: 1.5, visible: state.showNet });
    }
  }
  function drawPoints() {
    if (!W) return;
    const s = W.length, sv = W[0].length, pos = [], colors = [], labels = [];
    for (let i = 0; i < s; i++) {
      for (let j = 0; j < sv; j++) {
        pos.push(...W[i][j]);
        const inner = i >= 2 && i < s - 2 && j >= 2 && j < sv - 2;
        colors.push(inner ? PALETTE.control : PALETTE.muted);
        labels.push('');
      }
    }
    // the paper's W_{i,j}, i = −1 … m + 2 (grid row 0 is W₋₁,…, as in the edits readout)
    view.setPoints('W', pos, {
      colors, size: 10, draggable: !options.locked && state.mode === 'tensor', axis: 'z', visible: state.showNet,
      names: (index) => `W${sub(Math.floor(index / sv) - 1)},${sub((index % sv) - 1)}`,
      onDrag(index, p, phase) {
        const i = Math.floor(index / sv), j = index % sv;
        const base = baseZ(i, j);
        const k = state.edits.findIndex((e) => e[0] === i && e[1] === j);
        const dz = Math.max(-10, Math.min(10, p[2] - base));
        if (k >= 0) state.edits[k][2] = dz; else state.edits.push([i, j, dz]);
        // the grid follows the pointer now, the surface when it is computed
        if (!compute(() => { drawSurface(); refresh(); })) { drawSurface(); refresh(); }
        if (phase === 'end') { drawPoints(); ctx.save(); }
      },
    });
  }
  /** Computes and draws everything; `then()` runs once the surface is drawn. */
  function all(then) {
    // the view's drawing order is surface, grid, points (as computed here): at the very start with the surface
    // computing in the worker, nothing is drawn before it
    const first = !view.objects.has('S');
    const ready = () => { drawSurface(); refresh(); if (first) drawPoints(); then?.(); };
    const now = compute(ready);
    // computing in the worker: the grid is drawn now, the surface when it is in
    if (!now && !first) { drawSurface(); refresh(); }
    if (!first) drawPoints();
  }

  // "Computing the surface… 1.2 s [Cancel]" while a slow surface computes in the worker (under the view)
  const surfaceStatus = h('p', { class: 'compute-line' });
  const surfaceCC = computeClient({ demoId: meta.id, wasm, status: surfaceStatus, label: 'Computing the surface' });

  // the surface's swatch shows what the surface shows: the viridis ramp of its height colouring (low → high, as
  // the bar in the view), or its plain blue when "Colour by height" is off
  const surfaceSwatch = h('span', { class: 'swatch', 'aria-hidden': 'true' });
  const surfaceHow = h('span');
  function showSurfaceSwatch() {
    const ramp = Array.from({ length: 9 }, (_, i) => cssColor('viridis', i / 8)).join(', ');
    surfaceSwatch.style.backgroundColor = state.colors ? 'transparent' : PALETTE.sky;
    surfaceSwatch.style.backgroundImage = state.colors ? `linear-gradient(90deg, ${ramp})` : 'none';
    surfaceSwatch.dataset.kind = state.colors ? 'ramp' : 'line';
    surfaceSwatch.dataset.color = state.colors ? cssColor('viridis', 0.5) : PALETTE.sky;
    surfaceHow.textContent = state.colors ? ' (coloured by height z, low → high; with isolines)' : ' (with isolines)';
  }
  L.plots.appendChild(h('ul', { class: 'legend', 'aria-label': 'Legend' },
    h('li', null, surfaceSwatch, 'surface ', math('S(u,v)'), surfaceHow),
    h('li', null, h('span', { class: 'swatch dot', style: { background: PALETTE.control } }), 'grid points ', math('W_{ij}, \\; i = 1, \\ldots, m, \\; j = 1, \\ldots, n'), ' (drag up/down)'),
    h('li', null, h('span', { class: 'swatch dot', style: { background: PALETTE.muted } }), 'auxiliary border rows and columns')));
  L.plots.appendChild(surfaceStatus);

  // ---------- controls ----------
  const modeOpts = [{ value: 'tensor', label: 'tensor product (§6)' }];
  if (hasBlended) modeOpts.push({ value: 'blended', label: 'spline-blended (§7)' });
  const modeCtl = buttonGroup({ label: 'Surface', options: modeOpts, value: state.mode, onChange(v) { state.mode = v; refreshControls(); all(); ctx.save(); } });
  const shapeCtl = select({ label: 'Data', options: Object.entries(SHAPES).map(([value, s]) => ({ value, label: s.label })), value: state.shape, onChange(v) { state.shape = v; state.edits = []; state.grid = null; all(); view.fit(); ctx.save(); } });
  const sizeCtl = slider({ label: 'Grid size (m + 4 = n + 4)', name: 'size', min: 6, max: 14, step: 1, value: state.size, onInput(v) { state.size = v; state.grid = null; sanitize(); all(); }, onChange() { ctx.save(); } });
  const aCtl = slider({
    label: 'Approximation a', name: 'a', min: -0.1, max: 0.25, step: 0.001, value: state.a, number: true,
    ticks: [{ value: 0, label: '0 interpolates' }, { value: 1 / 6, label: '1/6 B-spline' }],
    onInput(v) { state.a = v; all(); }, onChange() { ctx.save(); },
  });
  const tuCtl = slider({ label: 'Tension in u', name: 'tu', min: 0, max: 0.5, step: 0.001, value: state.tu, onInput(v) { state.tu = v; all(); }, onChange() { ctx.save(); } });
  const tvCtl = slider({ label: 'Tension in v', name: 'tv', min: 0, max: 0.5, step: 0.001, value: state.tv, onInput(v) { state.tv = v; all(); }, onChange() { ctx.save(); } });
  const knotCtl = buttonGroup({ label: 'Knots (tensor product)', options: ['uniform', 'chord'], value: state.knots, onChange(v) { state.knots = v; all(); ctx.save(); } });
  const netCtl = toggle({ label: 'Show the grid', value: state.showNet, onChange(v) { state.showNet = v; all(); ctx.save(); } });
  const colCtl = toggle({ label: 'Colour by height', value: state.colors, onChange(v) { state.colors = v; drawSurface(); ctx.save(); } });
  const info = readout({ label: 'Domain' });
  const editsOut = readout({ label: 'Edited points' });
  const interpBtn = button({ label: 'a = 0', onClick: () => { state.a = 0; aCtl.set(0); all(); ctx.save(); } });
  const bsplBtn = button({ label: 'a = 1/6', onClick: () => { state.a = 1 / 6; aCtl.set(state.a); all(); ctx.save(); } });
  const resetBtn = button({ label: 'Reset the grid', onClick: () => { state.edits = []; all(); ctx.save(); } });
  const fitBtn = button({ label: 'Frame the view', onClick: () => view.fit() });

  L.controls.append(
    group('Surface', modeCtl.el, shapeCtl.el, sizeCtl.el, knotCtl.el, info.el),
    group('Approximation', aCtl.el, row(interpBtn.el, bsplBtn.el), tuCtl.el, tvCtl.el),
    group('Grid', editsOut.el, row(resetBtn.el, fitBtn.el), netCtl.el, colCtl.el,
      h('p', { class: 'ctl-hint' }, 'Drag a grid point up or down; or, in the view, choose it with N (Shift+N goes back) and move it with Page Up/Page Down. Drag the background to orbit, wheel or pinch to zoom.')),
  );
  // "Use my data" (www/lib/data-import.js): your grid W_ij for the tensor-product surface (border rows included)
  if (!options.locked) L.controls.append(group('Your data', dataImport({ kind: 'grid', label: 'Use my grid', apply: 'Use this grid', min: [6, 6], max: 32 * 32, onData(g) {
    const use = () => { Object.assign(state, { grid: g, mode: 'tensor', edits: [] }); refreshControls(); };
    const key = workKey('tensor', g);
    if (surfaceCC.runsHere(key, guessMs(g))) {
      // the API judges the grid first (its Error names what is wrong; the view keeps the previous data)
      wasm.b2Surface({ ...tensorArgs(g), samplesU: 2, samplesV: 2, mesh: false });
      use();
      // the view frames the grid with its surface once that is in (one framing: each costs a layout pass)
      all(() => view.fit());
      ctx.save();
      return;
    }
    // a large grid: judged and computed at once in the worker (the click only parses it, issue 26); its Error
    // shows under the box and the view keeps the previous data. Drawn in two frames: the surface and the grid
    // lines, then the grid points and the framing.
    const mine = ++computeToken;
    return surfaceCC.run([{ fn: 'b2Surface', args: tensorArgs(g) }], { key }).then((r) => {
      if (!r || mine !== computeToken) return false;
      use();
      W = grid(); surf = r[0]; surfKey = key;
      drawSurface(); refresh();
      // (an animation frame requested here runs in this frame: the second one is the next frame)
      requestAnimationFrame(() => requestAnimationFrame(() => { drawPoints(); view.fit(); }));
      ctx.save();
      return true;
    });
  } }).el));

  function refreshControls() {
    knotCtl.setDisabled(state.mode !== 'tensor');
    modeCtl.set(state.mode); shapeCtl.set(state.shape); sizeCtl.set(state.size); aCtl.set(state.a);
    tuCtl.set(state.tu); tvCtl.set(state.tv); knotCtl.set(state.knots); netCtl.set(state.showNet); colCtl.set(state.colors);
  }
  function refresh() {
    if (surf && surf.domain) info.set(`u ∈ [${fmt(surf.domain[0], 2)}, ${fmt(surf.domain[1], 2)}], v ∈ [${fmt(surf.domain[2], 2)}, ${fmt(surf.domain[3], 2)}]`);
    else info.set(`${rowsOf()} × ${colsOf()} grid`);
    editsOut.set(state.edits.length ? state.edits.map(([i, j, z]) => `${mathText(`W_{${i - 1},${j - 1}}`)} ${z >= 0 ? '+' : '−'}${fmt(Math.abs(z), 2)}`).join(', ') : 'none');
  }

  explanation(L.explain, {
    what: [
      ['Section 6 of the paper: with the B2 blending functions ', math('L_i(u), L_j(v)'), ' of the curve construction, the tensor-product surface is ', math('S(u,v) = \\sum_i \\sum_j W_{ij} L_i(u) L_j(v)'), '. The grid has a border of two extra rows and columns on each side (', math('i = -1, \\ldots, m+2, \\; j = -1, \\ldots, n+2'), '), shown grey; at ', math('a = 0'), ' the surface passes through the inner points ', math('W_{ij}'), ' (', math('i = 1, \\ldots, m, \\; j = 1, \\ldots, n'), '), at ', math('a = \\frac{1}{6}'), ' it is the bicubic B-spline of the grid.'],
      'The paper gives no rule for a single knot sequence and tension that suits every row, so both are chosen per direction here (uniform, or chord lengths averaged over the grid lines). The surface is computed as a bicubic B-spline whose control net is the B2 construction applied along u and then along v.',
      hasBlended ? ['Section 7: the spline-blended surface ', math('G = G_1 + G_2 - G_{12}'), ' interpolates a whole network of curves, here the lines ', math('u = u_i'), ' and ', math('v = v_j'), ' of the chosen formula (its grid is not editable).'] : '',
    ].filter(Boolean),
    math: [
      'S(u,v) = \\sum_{i=-1}^{m+2} \\sum_{j=-1}^{n+2} W_{ij}\\, L_i(u)\\, L_j(v)',
      'L_j = \\;\\text{the B2 curve of the data}\\; e_j \\;\\text{(1 at}\\; j \\text{, 0 elsewhere)}',
      'G = G_1 + G_2 - G_{12}, \\quad G_1 = \\sum_i G(u_i, v)\\, L_i(u), \\quad G_2 = \\sum_j G(u, v_j)\\, L_j(v) \\qquad (4)',
    ],
    tryThis: [
      'Drag an inner grid point at a = 0: the surface follows it exactly; at a = 1/6 it only pulls the surface towards it.',
      'Choose the "step" data: the interpolating surface overshoots at the step, the B-spline does not.',
      'Raise the tension in one direction only and orbit the view.',
    ],
    paper: meta.paper,
  });

  sanitize();
  refreshControls();
  all();
  if (state.view && typeof state.view === 'object') { try { view.setView(state.view); } catch { state.view = null; } }
  return {
    destroy() { surfaceCC.destroy(); view.destroy(); },
    // idle warm-up (www/lib/warm.js): a grid-point drag's frame with the current grid (same pixels; no save); not
    // while the worker computes (a large grid of your own)
    warm() { if (!surfaceCC.busy) compute(() => { drawSurface(); refresh(); }); },
    // for the shell's Export row: the control grid, the sampled surface (CSV) and its mesh (OBJ)
    exports() {
      return {
        json: { mode: state.mode, grid: W, samplesU: SAMPLES, samplesV: SAMPLES, surface: surf ? { uv: surf.uv, points: surf.points } : null },
        obj: surf?.mesh ? [{ name: state.mode === 'tensor' ? 'b2_surface' : 'spline_blended_surface', mesh: surf.mesh }] : [],
        csv: surf ? { points: surf.points, dim: surf.dim || 3 } : undefined,
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------
// (imports are hoisted: this block stays self-contained at the end of the file)
import { code, snippetCode } from '../lib/snippet.js';
import { dataImport } from '../lib/data-import.js';
import { cssColor } from '../lib/colormap.js';
import { PALETTE } from '../lib/plot2d.js';

/** A rectangular grid of [x, y, z] (at least 6 × 6) — the shape "Use my data" produces. */
function validGrid(g) {
  return Array.isArray(g) && g.length >= 6 && g.length <= 32 && Array.isArray(g[0]) && g[0].length >= 6 && g[0].length <= 32 &&
    g.every((r) => Array.isArray(r) && r.length === g[0].length && r.every((p) => Array.isArray(p) && p.length === 3 && p.every(Number.isFinite)));
}

/** The grid W_ij of the state (the same bookkeeping as grid() in mount). */
function snippetGrid(state) {
  if (state.grid) {
    const dz = new Map(state.edits.map(([i, j, z]) => [`${i},${j}`, z]));
    return state.grid.map((r, i) => r.map((p, j) => [p[0], p[1], p[2] + (dz.get(`${i},${j}`) || 0)]));
  }
  const coord = (k) => (k - 1) * 5 / (state.size - 3);
  const f = SHAPES[state.shape].f, dz = new Map(state.mode === 'tensor' ? state.edits.map(([i, j, z]) => [`${i},${j}`, z]) : []);
  return Array.from({ length: state.size }, (_, i) => Array.from({ length: state.size }, (_, j) => [coord(i), coord(j), f(coord(i), coord(j)) + (dz.get(`${i},${j}`) || 0)]));
}

export function snippet(state) {
  if (state.mode === 'tensor') {
    return snippetCode(meta.title, code`
      // the grid W_ij (rows i along u, columns j along v), points [x, y, z]
      const grid = ${snippetGrid(state)};
      const surface = sl.b2Surface({ grid, a: ${state.a}, tensionU: ${state.tu}, tensionV: ${state.tv}, knotsU: ${state.knots}, knotsV: ${state.knots}, samplesU: ${SAMPLES}, samplesV: ${SAMPLES}, mesh: true });
      return { surface };
    `);
  }
  const knots = Array.from({ length: state.size }, (_, k) => (k - 1) * 5 / (state.size - 3));
  return snippetCode(meta.title, code`
    // the height function whose network of curves (u = const and v = const at the knots) is blended
    const f = ${SHAPES[state.shape].f};
    const knots = ${knots};
    const surface = sl.splineBlendedSurface({ network: (u, v) => [u, v, f(u, v)], uKnots: knots, vKnots: knots, blend: 'b2', a: ${state.a}, tensionU: ${state.tu}, tensionV: ${state.tv}, samplesU: ${SAMPLES}, samplesV: ${SAMPLES}, mesh: true });
    return { surface };
  `);
}
