// Demo "Quasi-cubic surfaces" (quasi-cubic paper §3 Figs. 8–10, §4 Figs. 13, 16, 17): tensor-product quasi-cubic
// surfaces that are exact quadrics (sphere, cylinder, torus from circle × meridian control nets at α = 1), the
// bowl of Fig. 8, and a blended interpolation surface with a local β* at one grid point. Surfaces, meshes and
// control nets come from the wasm API (quasiCubicPreset, quasiCubicSurface, quasiCubicBlendedSurface); the
// demo only draws them (in the WebGL view of www/lib/view3d.js) and prints how far the surface points are from
// the quadric the preset names.

import { h, demoLayout, explanation, fmt } from '../lib/dom.js';
import { math } from '../lib/mathml.js';
import { cite, correctionLink } from '../lib/papers-ref.js';
import { PALETTE } from '../lib/plot2d.js';
import { View3D } from '../lib/view3d.js';
import { slider, toggle, buttonGroup, group, readout } from '../lib/controls.js';
import { computeClient } from '../lib/compute-client.js';

export const meta = {
  id: 'quasi-cubic-surfaces',
  title: 'Quasi-cubic surfaces',
  summary: 'Exact spheres, cylinders and tori from quasi-cubic control nets; a blended surface with local β*.',
  paper: cite('003', '§3 (Fig. 8) and §4 (Figs. 13, 16, 17)'),
};

const SHAPES = ['sphere', 'cylinder', 'torus', 'bowl', 'blended'];
const BIS_M = 4; // the blended surface interpolates a 5 × 5 grid of points
const CENTRE = { i: 2, j: 2 }; // the point whose β* the slider sets (Fig. 13: b_{i+2, j+2})

export function defaults() {
  return { shape: 'sphere', alpha: 1, bisAlpha: 3, beta: 1.8, betaOthers: 1, k: 3, showNet: true, view: [], grid: null };
}

/** @param {HTMLElement} root @param {import('../lib/host.js').DemoContext} ctx @returns {import('../lib/host.js').MountedDemo} */
export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);
  let view = null;       // the View3D
  let result = null, net = null, preset = null, error = '—';

  function sanitize() {
    // shape 'grid': your own control net (state.grid, from "Use my data")
    if (state.grid !== null && !validNet(state.grid)) state.grid = null;
    if (state.shape === 'grid' && !state.grid) state.shape = 'sphere';
    if (state.shape !== 'grid') state.grid = null;
    if (!SHAPES.includes(state.shape) && state.shape !== 'grid') state.shape = 'sphere';
    if (!(state.alpha >= -3 && state.alpha <= 3)) state.alpha = 1;
    if (!(state.bisAlpha >= -3 && state.bisAlpha <= 3)) state.bisAlpha = 3;
    if (!(state.beta >= 0 && state.beta <= 3)) state.beta = 1.8;
    if (!(state.betaOthers >= 0 && state.betaOthers <= 3)) state.betaOthers = 1;
    if (![2, 3, 4].includes(state.k)) state.k = 3;
    if (!validCamera(state.view)) state.view = [];
  }

  // ---------- computed data (from wasm) ----------
  // The tensor-product surface (quasiCubicSurface, 65 × 33 samples with its mesh) runs in a worker when it is slow
  // (issue 26; www/lib/compute-client.js): ~60–110 ms for your 32 × 32 control net on a loaded 2-core machine. The
  // presets (measured under SYNC_MS) stay synchronous, as before; while the α slider moves over a large net the
  // newest request wins and the previous surface stays on screen until the new one is in. The blended surface (a
  // fixed 5 × 5 grid) is computed here.
  let computeToken = 0, resultKey = '', pending = false;
  /** Computes the surface; `ready()` runs once it is in. Returns true when that was now (synchronously). */
  function compute(ready = () => {}) {
    const mine = ++computeToken;
    const prev = { result, key: resultKey };
    result = null; net = null; error = '—'; pending = false;
    try {
      if (state.shape === 'blended') {
        preset = wasm.quasiCubicPreset({ name: 'wavy', m: BIS_M, n: BIS_M });
        const beta = Array.from({ length: BIS_M + 1 }, (_, i) => Array.from({ length: BIS_M + 1 }, (_, j) => (i === CENTRE.i && j === CENTRE.j ? state.beta : state.betaOthers)));
        result = wasm.quasiCubicBlendedSurface({ grid: preset.grid, beta, k: state.k, alpha: state.bisAlpha, samplesU: 49, samplesV: 49, mesh: true });
        net = preset.grid; resultKey = 'blended';
        ready();
        return true;
      }
      const p = preset = state.shape === 'grid' ? { name: 'grid', grid: state.grid, periodicU: false, periodicV: false } : /** @type {import('../../types/splinelab.js').QuasiCubicSurfacePreset} */ (/** @type {unknown} */ (wasm.quasiCubicPreset({ name: state.shape })));
      const calls = surfaceCalls(p);
      const key = surfaceKey(state.shape, p.grid);
      // a new size: ~0.02 ms per control point (measured: 32 × 32 ≈ 10 ms in Node, 60–110 ms in the page under load)
      if (surfaceCC.runsHere(key, p.grid.length * p.grid[0].length * 0.02)) {
        result = surfaceCC.runHere(calls, key)[0];
        error = measure(p, result.points);
        net = p.grid; resultKey = key;
        ready();
        return true;
      }
      // in the worker: the net is drawn now; the previous surface stays while it is of the same net
      net = p.grid; pending = true;
      if (prev.key === key) result = prev.result;
      surfaceCC.run(calls, { key }).then((r) => {
        if (!r || mine !== computeToken) return;
        pending = false; result = r[0]; resultKey = key;
        error = measure(p, result.points);
        ready();
      }, (e) => {
        if (mine !== computeToken) return;
        pending = false; result = null;
        notify(e, 'error');
        ready();
      });
      return false;
    } catch (e) { net = null; notify(e, 'error'); ready(); return true; }
  }

  /** The worker/page call for the tensor-product surface of preset (or your net) `p`. @returns {import('../lib/compute-client.js').WasmCall[]} */
  function surfaceCalls(p) {
    return [{ fn: 'quasiCubicSurface', args: { grid: p.grid, alpha: state.alpha, periodicU: p.periodicU, periodicV: p.periodicV, samplesU: 65, samplesV: 33, mesh: true } }];
  }
  /** The compute client's key of a surface: its shape and net size (the time depends on those). */
  const surfaceKey = (shape, grid) => `${shape} ${grid.length} × ${grid[0].length}`;

  // Largest distance of the evaluated points from the quadric the preset names (a check of the output).
  function measure(p, pts) {
    const ex = p.exact || {};
    let worst = 0;
    for (let i = 0; i + 2 < pts.length; i += 3) {
      const [x, y, z] = [pts[i], pts[i + 1], pts[i + 2]];
      let d;
      if (p.name === 'sphere') d = Math.abs(Math.hypot(x, y, z) - ex.radius);
      else if (p.name === 'cylinder') d = Math.abs(Math.hypot(x, y) - ex.radius);
      else if (p.name === 'torus') d = Math.abs(Math.hypot(Math.hypot(x, y) - ex.major, z) - ex.minor);
      else return '— (no quadric)';
      worst = Math.max(worst, d);
    }
    return worst.toExponential(2);
  }

  // ---------- drawing ----------
  function netLines() {
    if (!net) return [];
    const rows = net.length, cols = net[0].length, lines = [];
    const closeU = preset?.periodicU && state.shape !== 'blended', closeV = preset?.periodicV && state.shape !== 'blended';
    for (let i = 0; i < rows; i++) lines.push((closeV ? [...net[i], net[i][0]] : net[i]).flat());
    for (let j = 0; j < cols; j++) {
      const col = net.map((r) => r[j]);
      lines.push((closeU ? [...col, col[0]] : col).flat());
    }
    return lines;
  }

  /** Draws the surface, the net's lines and (unless `points` is false) its points. */
  function draw3d({ points = true } = {}) {
    // computing in the worker: the net is drawn now, but not before the first surface (the view's drawing order
    // is surface, net, points, as when computed here)
    if (!view || !(result || (pending && net && view.objects.has('surface')))) return;
    const blended = state.shape === 'blended';
    // computing in the worker: the net now, the surface when it is in (the previous one hidden meanwhile, not
    // removed: it keeps its place in the view's drawing order, so the new one is drawn exactly as when computed here)
    if (!result) view.setVisible('surface', false);
    else {
      view.setMesh('surface', result.mesh, blended
        ? { colors: 'height', colormap: 'viridis', legend: 'height z', isolines: { every: [4, 4] } }
        : { color: PALETTE.curve, isolines: { every: [4, 4] } });
    }
    view.setLines('net', netLines(), { color: PALETTE.polygon, width: 1.5, opacity: 0.8, visible: state.showNet });
    if (points) drawPoints();
  }

  function drawPoints() {
    const blended = state.shape === 'blended';
    const pts = net ? net.flat() : [];
    if (blended) {
      const p = net[CENTRE.i + 1][CENTRE.j + 1];
      view.setPoints('data', pts.flat(), { color: PALETTE.control, size: 7, visible: state.showNet });
      view.setPoints('beta', p, { color: PALETTE.highlight, size: 16, labels: [`β* = ${fmt(state.beta, 2)}`] });
    } else {
      view.setPoints('data', pts.flat(), { color: PALETTE.control, size: 8, visible: state.showNet });
      view.remove('beta');
    }
  }

  function redraw() { draw3d(); }

  const holder = h('div', { class: 'surface-view', dataset: { plot: 'surface' } });
  L.plots.appendChild(holder);
  // "Computing the surface… 1.2 s [Cancel]" while a slow surface computes in the worker (under the view)
  const surfaceStatus = h('p', { class: 'compute-line' });
  const surfaceCC = computeClient({ demoId: meta.id, wasm, status: surfaceStatus, label: 'Computing the surface' });
  L.plots.appendChild(h('ul', { class: 'legend', 'aria-label': 'Legend' },
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.curve } }), 'quasi-cubic surface'),
    h('li', null, h('span', { class: 'swatch dashed' }), 'control net'),
    h('li', null, h('span', { class: 'swatch dot', style: { background: PALETTE.control } }), 'control / data points'),
    h('li', null, h('span', { class: 'swatch dot', style: { background: PALETTE.highlight } }), 'the point with the local β* (blended surface)')));
  L.plots.appendChild(surfaceStatus);

  // ---------- controls ----------
  const shapeCtl = buttonGroup({
    label: 'Surface', value: state.shape,
    options: [{ value: 'sphere', label: 'Sphere' }, { value: 'cylinder', label: 'Cylinder' }, { value: 'torus', label: 'Torus' }, { value: 'bowl', label: 'Bowl (Fig. 8)' }, { value: 'blended', label: 'Blended (Fig. 13)' }],
    onChange(v) { state.shape = v; state.grid = null; update(); view?.fit(); if (view) state.view = cameraOf(view.getView()); ctx.save(); },
  });
  const alphaCtl = slider({
    label: 'Shape parameter α', min: -3, max: 3, step: 0.01, value: state.alpha, number: true,
    ticks: [{ value: 0, label: '0' }, { value: 1, label: '1' }, { value: 3, label: '3' }],
    hint: 'The quadrics are exact at α = 1 only.',
    onInput(v) { state.alpha = v; update(); }, onChange() { ctx.save(); },
  });
  const betaCtl = slider({
    label: 'Local β* at the marked point', min: 0, max: 3, step: 0.01, value: state.beta, number: true,
    ticks: [{ value: 0, label: '0' }, { value: 1, label: '1' }],
    hint: 'β* scales both tangent lengths at that grid point; 1 everywhere gives the α = 3 interpolation surface.',
    onInput(v) { state.beta = v; update(); }, onChange() { ctx.save(); },
  });
  const othersCtl = slider({
    label: 'β* at all other points', min: 0, max: 3, step: 0.01, value: state.betaOthers, number: true,
    ticks: [{ value: 0.8, label: '0.8' }, { value: 1, label: '1' }],
    hint: 'Fig. 17 sets every β* to 0.8 and varies α.',
    onInput(v) { state.betaOthers = v; update(); }, onChange() { ctx.save(); },
  });
  const bisAlphaCtl = slider({
    label: 'α of the blended spline', min: -3, max: 3, step: 0.01, value: state.bisAlpha, number: true,
    ticks: [{ value: 0.6, label: '0.6' }, { value: 3, label: '3' }],
    hint: 'α = 3 interpolates the grid. Other α: the paper’s Remark 2 surfaces (Figs. 16, 17, α = 0.6), which pass through a point only where its β* = 0.',
    onInput(v) { state.bisAlpha = v; update(); }, onChange() { ctx.save(); },
  });
  const netCtl = toggle({ label: 'Show the control net', value: state.showNet, onChange(v) { state.showNet = v; update(); ctx.save(); } });
  const errOut = readout({ label: 'Max distance from the quadric', value: '—' });
  errOut.el.dataset.readout = 'exactness';
  const note = h('p', { class: 'ctl-hint', 'aria-live': 'polite' });
  const quadricGroup = group('Quasi-cubic surface', alphaCtl.el, errOut.el);
  const bisGroup = group('Blended interpolation surface', betaCtl.el, othersCtl.el, bisAlphaCtl.el);
  L.controls.append(group('Shape', shapeCtl.el, note, netCtl.el), quadricGroup, bisGroup);
  // "Use my data" (www/lib/data-import.js): your control net b_kl for the tensor-product surface (not periodic)
  if (!options.locked) L.controls.append(group('Your data', dataImport({ kind: 'grid', label: 'Use my control net', apply: 'Use this net', min: [4, 4], max: 32 * 32, onData(g) {
    const use = () => Object.assign(state, { shape: 'grid', grid: g });
    // the view frames the net with its surface once that is in (one framing: each costs a layout pass)
    const frame = () => { view?.fit(); if (view) state.view = cameraOf(view.getView()); };
    const p = { name: 'grid', grid: g, periodicU: false, periodicV: false };
    const key = surfaceKey('grid', g);
    if (surfaceCC.runsHere(key, g.length * g[0].length * 0.02)) {
      wasm.quasiCubicSurface({ grid: g, alpha: state.alpha, samplesU: 2, samplesV: 2 }); // the API judges the net first
      use();
      update(() => { frame(); ctx.save(); });
      ctx.save();
      return;
    }
    // a large net: judged and computed at once in the worker (the click only parses it, issue 26); its Error shows
    // under the box and the view keeps the previous data. Drawn in two frames: the surface and the net's lines,
    // then the net's points and the framing.
    const mine = ++computeToken;
    return surfaceCC.run(surfaceCalls(p), { key }).then((r) => {
      if (!r || mine !== computeToken) return false;
      use();
      preset = p; net = g; pending = false; result = r[0]; resultKey = key;
      error = measure(p, result.points);
      refresh(); draw3d({ points: false });
      // (an animation frame requested here runs in this frame: the second one is the next frame)
      requestAnimationFrame(() => requestAnimationFrame(() => { drawPoints(); frame(); ctx.save(); }));
      ctx.save();
      return true;
    }, (e) => {
      // refused: a surface of the current data that was computing meanwhile was superseded, so compute it again
      if (mine === computeToken && pending) update();
      throw e;
    });
  } }).el));

  const NOTES = {
    sphere: 'Circle × meridian: the square control polygon (periodic in u) times a half square (R, z) from pole to pole, bₖₗ = (Rₗ·cₖ, zₗ). At α = 1 every point is exactly at distance 1 from the centre.',
    cylinder: 'Circle × a straight meridian: exact distance 1 from the z axis at α = 1.',
    torus: 'Circle × a square meridian shifted away from the axis (periodic in both directions): an exact torus at α = 1.',
    bowl: 'Fig. 8: four patches around; the meridian starts on the axis with a horizontal tangent (b₀ and b₂ are mirror images).',
    grid: 'Your control net bₖₗ (rows along u, columns along v), not periodic: the tensor-product quasi-cubic surface with the α slider. Choose a surface above to leave it.',
    blended: 'A 5 × 5 grid of points is interpolated (α = 3). The marked point has its own β* (the paper’s Fig. 13 varies it from 0 to 1.8); the others share one value (1 by default).',
  };

  function refresh() {
    shapeCtl.set(state.shape);
    alphaCtl.set(state.alpha);
    betaCtl.set(state.beta);
    bisAlphaCtl.set(state.bisAlpha);
    othersCtl.set(state.betaOthers);
    netCtl.set(state.showNet);
    const blended = state.shape === 'blended';
    quadricGroup.hidden = blended;
    bisGroup.hidden = !blended;
    quadricGroup.style.display = blended ? 'none' : '';
    bisGroup.style.display = blended ? '' : 'none';
    errOut.set(error);
    note.textContent = NOTES[state.shape];
  }

  /** Computes and draws; `then()` runs once the surface is drawn. */
  function update(then) {
    const ready = () => { refresh(); redraw(); then?.(); };
    if (!compute(ready)) { refresh(); redraw(); }
  }

  // ---------- explanation ----------
  explanation(L.explain, {
    what: [
      ['The tensor-product surface ', math('S(u,v) = \\sum_k \\sum_l B_k(\\alpha;s)\\, B_l(\\alpha;t)\\, b_{kl}'), ' uses the quasi-cubic basis in both directions. Because the circle comes out exactly at ', math('\\alpha = 1'), ', so do surfaces of revolution: with a circle polygon ', math('c_k'), ' and a meridian polygon ', math('(R_l, z_l)'), ', the net ', math('b_{kl} = (R_l c_k, z_l)'), ' gives ', math('S = (R(v)\\, C(u), z(v))'), ' by the partition of unity — a sphere, a cylinder or a torus, to rounding error (the readout measures it on every mesh vertex).'],
      ['The blended interpolation surface interpolates a grid of points and gives every point its own ', math('\\beta^*'), ': ', math('\\mathrm{BIS} = L + \\beta\\,(p - L)'), ', where p is the α = 3 interpolation surface, L the bilinear blend of the patch corners through the allocated function s(t), and β the same blend of the four corner β*. The paper’s formulas (21)–(27) are lost; SplineLab reads them as this tensor analogue of the curve BIS (documented in src/quasi_cubic/surface.rs), which interpolates, scales the tangent plane by β*, and is C² for k ≥ 3.'],
    ],
    math: [
      'S(u,v) = \\sum_k \\sum_l B_k(\\alpha;s)\\, B_l(\\alpha;t)\\, b_{i+k, j+l}',
      '\\text{sphere of radius}\\; \\rho, \\; d = \\frac{3\\rho}{2}: \\quad c_k = \\;\\text{square of half-diagonal}\\; \\frac{3}{2},',
      '(R_l, z_l) = (-d, 0), (0, d), (d, 0), (0, -d), (-d, 0)',
      '\\mathrm{BIS}_{ij} = L_{ij} + \\beta_{ij}\\,(p_{ij} - L_{ij})',
      'L_{ij} = \\sum_{m, n \\in \\{0,1\\}} w_m(s)\\, w_n(t)\\, b_{i+1+m, j+1+n}, \\quad w_0 = 1 - s(\\cdot), \\; w_1 = s(\\cdot)',
    ],
    tryThis: [
      'Sphere: the distance readout shows about 1e-16. Move α to 0.8: the surface is still smooth and closed, but no longer a sphere.',
      'Torus: periodic in both directions — the control net is a closed square tube.',
      'Blended: slide β* from 0 (a sharp point) to 1.8 (a wide bulge), as in the paper’s Fig. 13.',
      'Blended, α = 0.6: the paper’s Fig. 16 surfaces — smoother, and only the point with β* = 0 stays on its control point.',
      'Blended, all other β* = 0.8, then move α from 0 to 1: the paper’s Fig. 17.',
    ],
    formulaNote: ['Correction (', correctionLink('correction-003-basis', 'the basis'), '): the basis formulas are reconstructed from the stated properties.'],
    paper: meta.paper,
  });

  // ---------- start ----------
  sanitize();
  // a link with a large net computes it in the worker: the view frames the surface once it is in
  let started = false;
  update(() => { if (started && !state.view.length) view?.fit(); });
  view = new View3D(holder, { height: 460, ariaLabel: 'Quasi-cubic surface (3D view: drag to orbit, wheel to zoom)', locked: true,
    onViewChange(v) { state.view = cameraOf(v); ctx.save(); } });
  view.canvas.dataset.plot = 'surface3d';
  draw3d();
  view.fit();
  if (state.view.length) view.setView(cameraFrom(state.view)); // the camera kept in the link
  started = true;

  return {
    destroy() { surfaceCC.destroy(); view?.destroy(); },
    // idle warm-up (www/lib/warm.js): an α-slider frame with the current state (same pixels; no save); not while
    // the worker computes (a large net of your own)
    warm() { if (!surfaceCC.busy) update(); },
    // for the shell's Export row: the control net, the sampled surface (CSV) and its mesh (OBJ)
    exports() {
      if (!result) return {};
      return {
        json: { shape: state.shape, grid: net, samples: { uv: result.uv, points: result.points } },
        obj: result.mesh ? [{ name: `quasi_cubic_${state.shape}`, mesh: result.mesh }] : [],
        csv: { points: result.points, dim: result.dim || 3 },
      };
    },
  };
}

// The camera in the state: [yaw°, pitch°, distance, target x, y, z] ([] = frame the surface).
const validCamera = (a) => Array.isArray(a) && (a.length === 0 || (a.length === 6 && a.every(Number.isFinite) && a[2] > 0));
const cameraOf = (v) => [v.yaw, v.pitch, v.distance, ...v.target];
const cameraFrom = (a) => ({ yaw: a[0], pitch: a[1], distance: a[2], target: a.slice(3, 6) });

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------
// (imports are hoisted: this block stays self-contained at the end of the file)
import { code, raw, snippetCode } from '../lib/snippet.js';
import { dataImport } from '../lib/data-import.js';

/** A rectangular control net of [x, y, z] (4 × 4 to 32 × 32) — what "Use my data" produces. */
function validNet(g) {
  return Array.isArray(g) && g.length >= 4 && g.length <= 32 && Array.isArray(g[0]) && g[0].length >= 4 && g[0].length <= 32 &&
    g.every((r) => Array.isArray(r) && r.length === g[0].length && r.every((p) => Array.isArray(p) && p.length === 3 && p.every(Number.isFinite)));
}

export function snippet(state) {
  if (state.shape === 'blended') {
    const beta = Array.from({ length: BIS_M + 1 }, (_, i) => Array.from({ length: BIS_M + 1 }, (_, j) => (i === CENTRE.i && j === CENTRE.j ? state.beta : state.betaOthers)));
    return snippetCode(meta.title, code`
      // the grid of data points b_ij to interpolate (with its auxiliary border)
      const grid = sl.quasiCubicPreset({ name: 'wavy', m: ${BIS_M}, n: ${BIS_M} }).grid;
      // β* per data point: the slider's value at b_${CENTRE.i}${CENTRE.j}, the other slider elsewhere
      const beta = ${beta};
      const surface = sl.quasiCubicBlendedSurface({ grid, beta, k: ${state.k}, alpha: ${state.bisAlpha}, samplesU: 49, samplesV: 49, mesh: true });
      return { surface };
    `);
  }
  if (state.shape === 'grid') {
    return snippetCode(meta.title, code`
      // your control net b_kl (rows along u, columns along v), points [x, y, z]
      const grid = ${state.grid};
      const surface = sl.quasiCubicSurface({ grid, alpha: ${state.alpha}, periodicU: false, periodicV: false, samplesU: 65, samplesV: 33, mesh: true });
      return { surface };
    `);
  }
  return snippetCode(meta.title, code`
    // the control net of the ${raw(state.shape)} (and whether it wraps around in u and v)
    const preset = sl.quasiCubicPreset({ name: ${state.shape} });
    const surface = sl.quasiCubicSurface({ grid: preset.grid, alpha: ${state.alpha}, periodicU: preset.periodicU, periodicV: preset.periodicV, samplesU: 65, samplesV: 33, mesh: true });
    return { surface };
  `);
}
