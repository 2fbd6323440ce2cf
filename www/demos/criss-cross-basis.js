// Demo "Criss-cross basis": one C¹ quadratic B-spline B_ij on a non-uniform criss-cross triangulation (Dagnino–
// Lamberti–Remogna §3). A 3D height view of B_ij with the triangulation lifted onto it, and a
// 2D view of the parameter domain: grid, diagonals, the octagonal support, a colour map of the values, draggable
// knot lines and the 13 BB ordinates of a picked cell. All values come from the wasm API (crissCrossBasis,
// crissCrossCells); the modules in criss-cross-basis/ compute, draw and explain:
//   data.js  constants, cell indexing, camera and what a link may hold   compute.js  every wasm call (the basis
//   through the compute worker when slow)   colour-map.js  the ramp and the map image   draw.js  the domain plot, the
//   ordinates and the 3D view (pure)   explain.js  the text. This entry holds the demo contract
// (www/demos/README.md): meta, the declared state, mount (views, handles, controls, wiring), snippet.

import { h, demoLayout, explanation, fmt } from '../lib/dom.js';
import { math } from '../lib/mathml.js';
import { cite } from '../lib/papers-ref.js';
import { createPlot, PALETTE } from '../lib/plot2d.js';
import { slider, toggle, button, table, group, row, readout } from '../lib/controls.js';
import { View3D } from '../lib/view3d.js';
import { computeClient } from '../lib/compute-client.js';
import { MIN_GAP, STRIP, GRID, ORD_NAMES, uniform, sub, cellsU, cellsV, cellIndex, preImage, cameraOf, cameraFrom, sanitize } from './criss-cross-basis/data.js';
import { ramp, colourMap } from './criss-cross-basis/colour-map.js';
import { computations } from './criss-cross-basis/compute.js';
import { drawDomain, drawOrdinates, drawSurface } from './criss-cross-basis/draw.js';
import { explanationContent } from './criss-cross-basis/explain.js';

export const meta = {
  id: 'criss-cross-basis',
  title: 'Criss-cross basis',
  summary: 'One C¹ quadratic B-spline Bᵢⱼ on a criss-cross triangulation: its octagonal support, BB net and knots.',
  paper: cite('004', '§3 and eq. (23)'),
};

export function defaults() {
  return { u: [0, 0.12, 0.4, 0.62, 0.8, 1], v: [0, 0.3, 0.45, 0.75, 1], i: 3, j: 2, cell: [3, 2], map: true, ordinates: true, view: [] };
}

/** @param {HTMLElement} root @param {import('../lib/host.js').DemoContext} ctx @returns {import('../lib/host.js').MountedDemo} */
export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);
  const m = () => cellsU(state);
  const n = () => cellsV(state);

  // the colour map image (criss-cross-basis/colour-map.js), painted when a basis is in
  const map = colourMap();

  // ---------- 3D view ----------
  const view3dBox = h('div', { class: 'cc-view3d' });
  L.plots.appendChild(view3dBox);
  // "Computing the basis… 1.2 s [Cancel]" while a slow basis computes in the worker (under the 3D view)
  const basisStatus = h('p', { class: 'compute-line' });
  const basisCC = computeClient({ demoId: meta.id, wasm, status: basisStatus, label: 'Computing the basis' });
  // every wasm call and its results c = { cells, basis, lines, vmax } (criss-cross-basis/compute.js)
  const { c, compute, centreValue } = computations({ wasm, state, notify, basisCC, onBasis: (r) => map.paint(r.basis, r.vmax) });
  L.plots.appendChild(basisStatus);
  const view = new View3D(view3dBox, { height: 380, ariaLabel: 'The basis function Bᵢⱼ as a height surface over the parameter domain',
    onViewChange(v) { state.view = cameraOf(v); ctx.save(); } });
  view.canvas.dataset.plot = 'basis3d';

  function draw3d() {
    if (!c.basis) return;
    try { drawSurface(view, state, c); } catch (e) { notify(e, 'error'); }
  }

  // ---------- 2D domain plot ----------
  const plot = createPlot(L.plots, {
    ariaLabel: 'Parameter domain with the criss-cross triangulation, the support of Bᵢⱼ and draggable knot lines',
    equal: true, height: 'aspect', aspect: 1.12, pan: false, zoom: false, locked: options.locked,
    view: { xmin: -STRIP - 0.06, xmax: 1.04, ymin: -STRIP - 0.06, ymax: 1.04 },
    xLabel: 'u', yLabel: 'v', grid: false,
    describe: () => `B${sub(state.i)},${sub(state.j)} on u = ${state.u.map((x) => fmt(x, 3)).join(', ')} and v = ${state.v.map((x) => fmt(x, 3)).join(', ')}; ` +
      `picked cell (${state.cell[0]}, ${state.cell[1]}).`,
    draw(g, p) { drawDomain(g, p, state, c, map); },
    drawOver(g, p) { drawOrdinates(p, state, c); },
  });
  plot.canvas.dataset.plot = 'domain';

  const clampKnot = (arr, k, x) => Math.min(arr[k + 1] - MIN_GAP, Math.max(arr[k - 1] + MIN_GAP, x));
  plot.addHandles({
    name: 'u knot',
    points: () => state.u.slice(1, -1).map((x) => [x, -STRIP]),
    label: (k) => `u${sub(k + 1)}`, labelOf: (k) => `Knot line u${sub(k + 1)}`,
    color: PALETTE.ink, shape: 'triangle', radius: 8, axis: 'x',
    constrain: (k, q) => [clampKnot(state.u, k + 1, q[0]), -STRIP],
    constraintNote: 'the knot lines must stay in order, each between its neighbours',
    move(k, q) { state.u[k + 1] = q[0]; refresh({ dragging: true }); },
    end() { refresh({ compute: false }); ctx.save(); },
  });
  plot.addHandles({
    name: 'v knot',
    points: () => state.v.slice(1, -1).map((y) => [-STRIP, y]),
    label: (k) => `v${sub(k + 1)}`, labelOf: (k) => `Knot line v${sub(k + 1)}`,
    color: PALETTE.ink, shape: 'triangle', radius: 8, axis: 'y',
    constrain: (k, q) => [-STRIP, clampKnot(state.v, k + 1, q[1])],
    constraintNote: 'the knot lines must stay in order, each between its neighbours',
    move(k, q) { state.v[k + 1] = q[1]; refresh({ dragging: true }); },
    end() { refresh({ compute: false }); ctx.save(); },
  });
  // clicking inside the domain picks the cell whose BB net is shown
  plot.canvas.addEventListener('click', (e) => {
    const r = plot.canvas.getBoundingClientRect();
    const [x, y] = plot.toWorld(e.clientX - r.left, e.clientY - r.top);
    if (!(x > 0 && x < 1 && y > 0 && y < 1)) return;
    const a = state.u.findIndex((t) => t > x), b = state.v.findIndex((t) => t > y);
    if (a < 1 || b < 1) return;
    state.cell = [a, b];
    refresh({ compute: false });
    ctx.save();
  });

  const legend = h('ul', { class: 'legend', 'aria-label': 'Legend' },
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.control } }), 'triangles where ', math('B_{ij}'), ' is not zero (its octagonal support)'),
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.highlight } }), 'picked cell and its 13 BB ordinates'),
    h('li', null, h('span', { class: 'swatch', style: { background: ramp(0.8) } }), 'colour: value of ', math('B_{ij}'), ' (yellow = maximum)'),
    h('li', null, '▲ drag the triangles under / left of the domain to move the knot lines'));
  L.plots.appendChild(legend);

  // ---------- controls ----------
  const iCtl = slider({ label: 'i', min: 0, max: m() + 1, step: 1, value: state.i, onInput(x) { state.i = x; refresh(); }, onChange() { ctx.save(); } });
  const jCtl = slider({ label: 'j', min: 0, max: n() + 1, step: 1, value: state.j, onInput(x) { state.j = x; refresh(); }, onChange() { ctx.save(); } });
  const mCtl = slider({ label: 'cells in u (m)', min: 1, max: 10, step: 1, value: m(), onChange(x) { state.u = uniform(x); refresh(); ctx.save(); } });
  const nCtl = slider({ label: 'cells in v (n)', min: 1, max: 10, step: 1, value: n(), onChange(x) { state.v = uniform(x); refresh(); ctx.save(); } });
  const aCtl = slider({ label: 'picked cell a', min: 1, max: m(), step: 1, value: state.cell[0], onInput(x) { state.cell[0] = x; refresh({ compute: false }); }, onChange() { ctx.save(); } });
  const bCtl = slider({ label: 'picked cell b', min: 1, max: n(), step: 1, value: state.cell[1], onInput(x) { state.cell[1] = x; refresh({ compute: false }); }, onChange() { ctx.save(); } });
  const uniformBtn = button({ label: 'Uniform knots', onClick() { state.u = uniform(m()); state.v = uniform(n()); refresh(); ctx.save(); } });
  const mapCtl = toggle({ label: 'Colour map of the values', value: state.map, onChange(x) { state.map = x; plot.redraw(); ctx.save(); } });
  const ordCtl = toggle({ label: 'BB ordinates of the picked cell', value: state.ordinates, onChange(x) { state.ordinates = x; plot.redraw(); draw3d(); ctx.save(); } });
  const centre = readout({ label: math('B_{ij}(\\xi_i, \\eta_j)') });
  const ordTable = table({ caption: 'BB ordinates of the picked cell', columns: ['ordinate', 'value'], digits: 4 });
  if (options.locked) [mCtl, nCtl, uniformBtn].forEach((c) => c.setDisabled(true));
  L.controls.append(
    group('Basis function Bᵢⱼ', iCtl.el, jCtl.el, centre.el),
    group('Knots', mCtl.el, nCtl.el, row(uniformBtn.el)),
    group('BB net', aCtl.el, bCtl.el, ordTable.el, ordCtl.el, mapCtl.el),
  );

  const shown = { controls: null, centre: null, label: null };   // what the readouts show now
  function refreshControls() {
    // the controls are written only when what they show changed (a knot drag changes none of them), the
    // table's numbers in place: every DOM write costs a style and layout pass in the frame
    const ctlKey = [m(), n(), state.i, state.j, state.cell[0], state.cell[1], state.map, state.ordinates].join(' ');
    if (ctlKey !== shown.controls) {
      shown.controls = ctlKey;
      iCtl.setRange({ max: m() + 1 }); iCtl.set(state.i);
      jCtl.setRange({ max: n() + 1 }); jCtl.set(state.j);
      mCtl.set(m()); nCtl.set(n());
      aCtl.setRange({ max: m() }); aCtl.set(state.cell[0]);
      bCtl.setRange({ max: n() }); bCtl.set(state.cell[1]);
      mapCtl.set(state.map); ordCtl.set(state.ordinates);
    }
    if (c.cells) {
      const k0 = 13 * cellIndex(state, state.cell[0], state.cell[1]);
      const rows = ORD_NAMES.map((nm, k) => [nm, c.cells.ordinates[k0 + k]]);
      const tds = ordTable.el.querySelectorAll('tbody td');
      if (tds.length !== rows.length) ordTable.set(rows);
      else rows.forEach((r, k) => { const t = fmt(r[1], 4); if (tds[k].textContent !== t) tds[k].textContent = t; });
    }
    try {
      const [xi, eta] = preImage(state);
      const value = fmt(centreValue(xi, eta), 4);
      if (value !== shown.centre) { shown.centre = value; centre.set(value); }
      // the label with the current indices and pre-image (typeset; rebuilt only when it reads differently)
      const ij = state.i > 9 || state.j > 9 ? `${state.i},${state.j}` : `${state.i}${state.j}`;
      const tex = `B_{${ij}}(\\xi_{${state.i}}, \\eta_{${state.j}}) = B_{${ij}}(${fmt(xi, 3)}, ${fmt(eta, 3)})`;
      if (tex !== shown.label) { shown.label = tex; centre.el.querySelector('.ctl-readout-label').replaceChildren(math(tex)); }
    } catch (e) { notify(e, 'error'); }
  }

  // While a knot line is dragged the frame draws and touches no text: the readouts (the centre value, the BB
  // table) follow in a task after the frame, at most every NUMBERS_MS (readable while they move; each text
  // change costs a style and layout pass); on release, and on every other change, at once.
  const NUMBERS_MS = 200;
  let ctlTimer = 0, lastControls = 0;
  function laterControls() {
    if (ctlTimer) return;
    ctlTimer = setTimeout(() => { ctlTimer = 0; lastControls = performance.now(); refreshControls(); },
      Math.max(0, NUMBERS_MS - (performance.now() - lastControls)));
  }
  function refresh({ compute: again = true, dragging = false } = {}) {
    sanitize(state, defaults());
    const show = () => {
      if (dragging) laterControls();
      else { clearTimeout(ctlTimer); ctlTimer = 0; refreshControls(); }
      plot.redraw();
      draw3d();
    };
    // computing in the worker: the knot lines, the support and the numbers now, the surface when it is in
    if (!again || !compute(show)) show();
  }

  // ---------- explanation ----------
  explanation(L.explain, explanationContent(meta.paper));

  // ---------- start ----------
  sanitize(state, defaults());
  refresh();
  view.fit();
  if (state.view.length) view.setView(cameraFrom(state.view)); // the camera kept in the link

  return {
    destroy() { clearTimeout(ctlTimer); basisCC.destroy(); plot.destroy(); view.destroy(); },
    // idle warm-up (www/lib/warm.js): a knot-line drag's frame with the current knots (same pixels; no save)
    warm() { refresh({ dragging: true }); },
    // for the shell's Export row: B_ij sampled on the grid (u, v, value), its mesh, the BB ordinates of the cells
    exports() {
      const { basis, cells } = c;
      if (!basis) return {};
      const k = basis.values.length, pts = new Float64Array(3 * k);
      for (let s = 0; s < k; s++) { pts[3 * s] = basis.uv[2 * s]; pts[3 * s + 1] = basis.uv[2 * s + 1]; pts[3 * s + 2] = basis.values[s]; }
      return {
        json: { i: state.i, j: state.j, u: state.u, v: state.v, cells: cells ? { ordinates: cells.ordinates, domainPoints: cells.domainPoints, support: cells.support } : null },
        obj: basis.mesh ? [{ name: `B_${state.i}_${state.j}`, mesh: basis.mesh }] : [],
        csv: { points: pts, dim: 3, header: ['u', 'v', 'B'] },
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------
// (imports are hoisted: this block stays self-contained at the end of the file)
import { code, snippetCode } from '../lib/snippet.js';

export function snippet(state) {
  return snippetCode(meta.title, code`
    // the criss-cross triangulation's break lines u_0..u_m and v_0..v_n, and which B_ij to show
    const options = ${{ u: state.u, v: state.v, i: state.i, j: state.j }};
    // the C¹ quadratic B-spline B_ij on a ${GRID} × ${GRID} grid over [0, 1]² (and a mesh for the 3D view)
    const basis = sl.crissCrossBasis({ ...options, samplesU: ${GRID}, samplesV: ${GRID}, mesh: true });
    // its Bézier ordinates per triangle, the domain points and the cells of its support
    const cells = sl.crissCrossCells(options);
    return { basis, cells };
  `);
}
