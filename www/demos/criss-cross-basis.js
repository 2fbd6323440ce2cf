// Demo "Criss-cross basis": one C¹ quadratic B-spline B_ij on a non-uniform criss-cross triangulation (Dagnino–
// Lamberti–Remogna §3). A 3D height view of B_ij with the triangulation lifted onto it, and a
// 2D view of the parameter domain: grid, diagonals, the octagonal support, a colour map of the values, draggable
// knot lines and the 13 BB ordinates of a picked cell. All values come from the wasm API (crissCrossBasis,
// crissCrossCells); this module only draws and handles input.

import { h, demoLayout, explanation, fmt } from '../lib/dom.js';
import { math, mathText } from '../lib/mathml.js';
import { cite } from '../lib/papers-ref.js';
import { createPlot, PALETTE } from '../lib/plot2d.js';
import { slider, toggle, button, table, group, row, readout } from '../lib/controls.js';
import { View3D } from '../lib/view3d.js';
import { computeClient } from '../lib/compute-client.js';

export const meta = {
  id: 'criss-cross-basis',
  title: 'Criss-cross basis',
  summary: 'One C¹ quadratic B-spline Bᵢⱼ on a criss-cross triangulation: its octagonal support, BB net and knots.',
  paper: cite('004', '§3 and eq. (23)'),
};

const MIN_GAP = 0.02;      // knot lines stay this far apart
const STRIP = 0.09;        // the knot handles sit this far outside the unit square
const GRID = 61;           // samples per direction for the surface and the colour map
// the four triangles of a cell as ordinate indices (b200, b020, b002, b110, b011, b101)
const TRIANGLES = [[0, 1, 12, 4, 9, 8], [1, 2, 12, 5, 10, 9], [2, 3, 12, 6, 11, 10], [3, 0, 12, 7, 8, 11]];
const ORD_NAMES = ['c00', 'c10', 'c11', 'c01', 'eb', 'er', 'et', 'el', 'd00', 'd10', 'd11', 'd01', 'o'];

const uniform = (k) => Array.from({ length: k + 1 }, (_, r) => r / k);

export function defaults() {
  return { u: [0, 0.12, 0.4, 0.62, 0.8, 1], v: [0, 0.3, 0.45, 0.75, 1], i: 3, j: 2, cell: [3, 2], map: true, ordinates: true, view: [] };
}

// viridis-like ramp for the colour map (5 stops), t in [0, 1]
const RAMP = [[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]];
function rampRGB(t) {
  const x = Math.min(1, Math.max(0, t)) * (RAMP.length - 1);
  const k = Math.min(RAMP.length - 2, Math.floor(x)), f = x - k;
  return RAMP[k].map((a, q) => Math.round(a + (RAMP[k + 1][q] - a) * f));
}
function ramp(t) { const c = rampRGB(t); return `rgb(${c[0]},${c[1]},${c[2]})`; }
// the ramp at 1024 levels as opaque RGBA pixels (one 32-bit word each, in the platform's byte order), for
// writing the colour map straight into an image
const LEVELS = 1024;
const RAMP_PX = (() => {
  const px = new Uint32Array(LEVELS), bytes = new Uint8ClampedArray(px.buffer);
  for (let q = 0; q < LEVELS; q++) { bytes.set(rampRGB(q / (LEVELS - 1)), 4 * q); bytes[4 * q + 3] = 255; }
  return px;
})();
const MAP_ALPHA = 0.85;    // the colour map over the white domain

/**
 * Writes the colour map of `values` (B_ij on the u-major n × n grid: sample iu·n + iv at (iu, iv) / (n − 1))
 * into the n × n pixels `px` (row 0 at the top, so v points up): the ramp at values / vmax (≤ 0 → 0).
 */
function rampImage(px, values, vmax, n) {
  const k = (LEVELS - 1) / vmax;
  for (let iu = 0; iu < n; iu++) {
    for (let iv = 0; iv < n; iv++) {
      const t = values[iu * n + iv] * k;
      px[(n - 1 - iv) * n + iu] = RAMP_PX[t > 0 ? (t < LEVELS - 1 ? (t + 0.5) | 0 : LEVELS - 1) : 0];
    }
  }
}

/** @param {HTMLElement} root @param {import('../lib/host.js').DemoContext} ctx @returns {import('../lib/host.js').MountedDemo} */
export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);
  const m = () => state.u.length - 1;
  const n = () => state.v.length - 1;

  function validBreaks(x) {
    if (!Array.isArray(x) || x.length < 2 || x.length > 12 || x[0] !== 0 || x[x.length - 1] !== 1) return false;
    for (let k = 1; k < x.length; k++) if (!(Number.isFinite(x[k]) && x[k] - x[k - 1] >= MIN_GAP * 0.999)) return false;
    return true;
  }
  function sanitize() {
    const d = defaults();
    if (!validBreaks(state.u)) state.u = d.u.slice();
    if (!validBreaks(state.v)) state.v = d.v.slice();
    const clampInt = (x, lo, hi, def) => (Number.isInteger(x) ? Math.min(hi, Math.max(lo, x)) : def);
    state.i = clampInt(state.i, 0, m() + 1, Math.min(d.i, m() + 1));
    state.j = clampInt(state.j, 0, n() + 1, Math.min(d.j, n() + 1));
    if (!Array.isArray(state.cell) || state.cell.length !== 2) state.cell = [1, 1];
    state.cell = [clampInt(state.cell[0], 1, m(), 1), clampInt(state.cell[1], 1, n(), 1)];
    state.map = state.map !== false;
    state.ordinates = state.ordinates !== false;
    if (!validCamera(state.view)) state.view = [];
  }

  // ---------- computed data (from wasm) ----------
  let basis = null;   // { uv, values, mesh }
  let cells = null;   // { ordinates, domainPoints, support }
  let lines = null;   // triangulation lines lifted onto the surface (flat xyz arrays)
  let vmax = 1;

  function cellIndex(a, b) { return (a - 1) * n() + (b - 1); }
  function inSupport(a, b) {
    if (!cells) return false;
    const k = 4 * cellIndex(a, b);
    return cells.support[k] + cells.support[k + 1] + cells.support[k + 2] + cells.support[k + 3] > 0;
  }

  // The colour map as an image: one texel per grid sample (column iu, row GRID − 1 − iv, since v points up),
  // coloured by B_ij / max B_ij through the ramp. The plot draws it scaled onto the domain with bilinear
  // smoothing (the texel centres sit on the sample points (u, v) = (iu, iv) / (GRID − 1)), clipped to the
  // support triangles: outside them B_ij = 0 and nothing is drawn; inside, the colour runs down to the value 0
  // at the support's edge.
  const mapCanvas = document.createElement('canvas');
  mapCanvas.width = GRID; mapCanvas.height = GRID;
  const mapCtx = mapCanvas.getContext('2d');
  const mapImage = mapCtx ? mapCtx.createImageData(GRID, GRID) : null;
  const mapPixels = mapImage ? new Uint32Array(mapImage.data.buffer) : null;
  function paintMap() {
    if (!mapImage || basis.values.length !== GRID * GRID) return;
    rampImage(mapPixels, basis.values, vmax, GRID);
    mapCtx.putImageData(mapImage, 0, 0);
  }

  // The basis on its 61² grid with the mesh and the lifted triangulation lines (crissCrossBasis) run in a worker
  // when they are slow (issue 26; www/lib/compute-client.js): the first calls at a new grid size run in V8's
  // baseline tier (6–40 ms measured in the page for 61², then 1–7 ms) and a loaded machine multiplies that
  // (119 ms measured for the 10 × 10 slider at load 11–15). A size measured under SYNC_MS stays synchronous, as
  // before; while a knot line is dragged the newest request wins. The BB ordinates and the support
  // (crissCrossCells, ~0.2 ms) are computed here at once: the table and the 2D support follow the state now, the
  // surface and the colour map when they are in.
  let computeToken = 0;
  /** Computes the basis; `ready()` runs once it is in. Returns true when that was now (synchronously). */
  function compute(ready) {
    const mine = ++computeToken;
    let /** @type {import('../lib/compute-client.js').WasmCall[]} */ calls, pieces, at;
    try {
      const q = { u: state.u, v: state.v, i: state.i, j: state.j };
      cells = wasm.crissCrossCells(q);
      // grid lines and diagonals of the cells where B_ij lives, evaluated on the surface (one flat (u, v) list)
      at = []; pieces = [];
      const S = 12;
      const seg = (u0, v0, u1, v1) => {
        const start = at.length / 2;
        for (let k = 0; k <= S; k++) at.push(u0 + (u1 - u0) * k / S, v0 + (v1 - v0) * k / S);
        pieces.push([start, at.length / 2]);
      };
      for (let a = 1; a <= m(); a++) {
        for (let b = 1; b <= n(); b++) {
          if (!inSupport(a, b)) continue;
          const [u0, u1, v0, v1] = [state.u[a - 1], state.u[a], state.v[b - 1], state.v[b]];
          seg(u0, v0, u1, v0); seg(u1, v0, u1, v1); seg(u1, v1, u0, v1); seg(u0, v1, u0, v0);
          seg(u0, v0, u1, v1); seg(u1, v0, u0, v1);
        }
      }
      const uv = { u: state.u.slice(), v: state.v.slice(), i: state.i, j: state.j };
      calls = [{ fn: 'crissCrossBasis', args: { ...uv, samplesU: GRID, samplesV: GRID, mesh: true } }];
      if (at.length) calls.push({ fn: 'crissCrossBasis', args: { ...uv, atUV: Float64Array.from(at) } });
    } catch (e) { notify(e, 'error'); ready(); return true; }
    /** @param {any[]} results the basis on the grid and (when asked) at the points */
    function apply([b, r]) {
      basis = b;
      vmax = 1e-9;
      const vals = basis.values;
      for (let k = 0; k < vals.length; k++) if (vals[k] > vmax) vmax = vals[k];
      paintMap();
      lines = r ? pieces.map(([s0, e]) => {
        const out = new Float64Array(3 * (e - s0));
        for (let k = s0; k < e; k++) { out[3 * (k - s0)] = at[2 * k]; out[3 * (k - s0) + 1] = at[2 * k + 1]; out[3 * (k - s0) + 2] = r.values[k] + 0.002; }
        return out;
      }) : [];
    }
    const key = `${m()} × ${n()} cells`;
    // a new size: ~0.4 ms per cell (the first calls at 10 × 10 measured up to 40 ms in the page unloaded, the
    // slider's handler 119 ms at load 11–15): the default 5 × 4 cells stay here, from 40 cells on the worker first
    if (basisCC.runsHere(key, m() * n() * 0.4)) {
      try { apply(basisCC.runHere(calls, key)); } catch (e) { notify(e, 'error'); }
      ready();
      return true;
    }
    basisCC.run(calls, { key }).then((r) => {
      if (!r || mine !== computeToken) return;
      apply(r);
      ready();
    }, (e) => {
      if (mine !== computeToken) return;
      notify(e, 'error');
      ready();
    });
    return false;
  }

  // ---------- 3D view ----------
  const view3dBox = h('div', { class: 'cc-view3d' });
  L.plots.appendChild(view3dBox);
  // "Computing the basis… 1.2 s [Cancel]" while a slow basis computes in the worker (under the 3D view)
  const basisStatus = h('p', { class: 'compute-line' });
  const basisCC = computeClient({ demoId: meta.id, wasm, status: basisStatus, label: 'Computing the basis' });
  L.plots.appendChild(basisStatus);
  const view = new View3D(view3dBox, { height: 380, ariaLabel: 'The basis function Bᵢⱼ as a height surface over the parameter domain',
    onViewChange(v) { state.view = cameraOf(v); ctx.save(); } });
  view.canvas.dataset.plot = 'basis3d';

  function draw3d() {
    if (!basis) return;
    try {
      view.setMesh('B', basis.mesh, { colors: 'height', colormap: 'viridis', legend: `B${sub(state.i)}${sub(state.j)}(u, v)`, isolines: false });
      view.setLines('tri', lines || [], { color: '#222', width: 1.6, opacity: 0.8 });
      if (!view.objects.has('domain')) view.setLines('domain', [[0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 0]], { color: '#8a8a8a', width: 1.5 });
      // the BB net of the picked cell: its 13 ordinates over their domain points, joined triangle by triangle
      if (cells && state.ordinates) {
        const k0 = 13 * cellIndex(state.cell[0], state.cell[1]);
        const P = (k) => [cells.domainPoints[2 * (k0 + k)], cells.domainPoints[2 * (k0 + k) + 1], cells.ordinates[k0 + k]];
        const pts = [];
        for (let k = 0; k < 13; k++) pts.push(...P(k));
        const net = [];
        for (const [a, b, c, ab, bc, ca] of TRIANGLES) {
          net.push([...P(a), ...P(ab), ...P(b), ...P(bc), ...P(c), ...P(ca), ...P(a)]);
          net.push([...P(ab), ...P(bc), ...P(ca), ...P(ab)]);
        }
        view.setLines('bbnet', net, { color: '#CC79A7', width: 2 });
        view.setPoints('bb', pts, { color: '#CC79A7', size: 9, pickable: false });
      } else {
        view.setVisible('bbnet', false);
        view.setVisible('bb', false);
      }
    } catch (e) { notify(e, 'error'); }
  }

  // ---------- 2D domain plot ----------
  const plot = createPlot(L.plots, {
    ariaLabel: 'Parameter domain with the criss-cross triangulation, the support of Bᵢⱼ and draggable knot lines',
    equal: true, height: 'aspect', aspect: 1.12, pan: false, zoom: false, locked: options.locked,
    view: { xmin: -STRIP - 0.06, xmax: 1.04, ymin: -STRIP - 0.06, ymax: 1.04 },
    xLabel: 'u', yLabel: 'v', grid: false,
    describe: () => `B${state.i},${state.j} on u = ${state.u.map((x) => fmt(x, 3)).join(', ')} and v = ${state.v.map((x) => fmt(x, 3)).join(', ')}; ` +
      `picked cell (${state.cell[0]}, ${state.cell[1]}).`,
    draw(g, p) {
      const U = state.u, V = state.v;
      // colour map of the values. The SVG export (www/lib/export.js) records the drawing through the context's own
      // methods and draws no images: there, one small square per sample, as vector paths.
      const vector = Object.prototype.hasOwnProperty.call(g, 'drawImage');
      if (state.map && basis && vector) {
        const h = 0.5 / (GRID - 1);
        for (let s = 0; s < basis.values.length; s++) {
          const val = basis.values[s];
          if (!(val > 1e-12)) continue;
          const x = basis.uv[2 * s], y = basis.uv[2 * s + 1];
          p.fill([[x - h, y - h], [x + h, y - h], [x + h, y + h], [x - h, y + h]], { color: ramp(val / vmax), alpha: MAP_ALPHA });
        }
      }
      // on screen: one image (see paintMap), clipped to the support triangles
      if (state.map && basis && cells && mapImage && !vector) {
        const h = 0.5 / (GRID - 1);      // half a sample step: the texels' outer edges
        const x0 = p.sx(-h), x1 = p.sx(1 + h), y0 = p.sy(1 + h), y1 = p.sy(-h);
        g.save();
        g.beginPath();
        for (let a = 1; a <= m(); a++) {
          for (let b = 1; b <= n(); b++) {
            const [u0, u1, v0, v1] = [U[a - 1], U[a], V[b - 1], V[b]];
            const ox = p.sx((u0 + u1) / 2), oy = p.sy((v0 + v1) / 2);
            const corners = [[u0, v0], [u1, v0], [u1, v1], [u0, v1]];
            for (let k = 0; k < 4; k++) {
              if (!cells.support[4 * cellIndex(a, b) + k]) continue;
              const [pa, pb] = [corners[k], corners[(k + 1) % 4]];
              g.moveTo(p.sx(pa[0]), p.sy(pa[1])); g.lineTo(p.sx(pb[0]), p.sy(pb[1])); g.lineTo(ox, oy); g.closePath();
            }
          }
        }
        g.clip();
        g.globalAlpha = MAP_ALPHA;
        g.imageSmoothingEnabled = true;
        g.imageSmoothingQuality = 'low';
        g.drawImage(mapCanvas, x0, y0, x1 - x0, y1 - y0);
        g.restore();
      }
      // support triangles (outline), the triangulation, the picked cell; each kind of line is one path
      // (NaN breaks the pen between pieces)
      const BREAK = [NaN, NaN];
      if (cells) {
        const sup = [];
        for (let a = 1; a <= m(); a++) {
          for (let b = 1; b <= n(); b++) {
            const [u0, u1, v0, v1] = [U[a - 1], U[a], V[b - 1], V[b]];
            const o = [(u0 + u1) / 2, (v0 + v1) / 2];
            const tris = [[[u0, v0], [u1, v0], o], [[u1, v0], [u1, v1], o], [[u1, v1], [u0, v1], o], [[u0, v1], [u0, v0], o]];
            tris.forEach((t, k) => { if (cells.support[4 * cellIndex(a, b) + k]) sup.push(t[0], t[1], t[2], t[0], BREAK); });
          }
        }
        if (sup.length) p.polyline(sup, { color: PALETTE.control, width: 2.5, alpha: 0.9 });
      }
      const diag = [];
      for (let a = 1; a <= m(); a++) {
        for (let b = 1; b <= n(); b++) diag.push([U[a - 1], V[b - 1]], [U[a], V[b]], BREAK, [U[a], V[b - 1]], [U[a - 1], V[b]], BREAK);
      }
      p.polyline(diag, { color: '#555', width: 1 });
      const grid = [];
      for (const x of U) grid.push([x, 0], [x, 1], BREAK);
      for (const y of V) grid.push([0, y], [1, y], BREAK);
      p.polyline(grid, { color: PALETTE.ink, width: 1.75 });
      // knot strips
      p.segment(0, -STRIP, 1, -STRIP, { color: PALETTE.axis, width: 2 });
      p.segment(-STRIP, 0, -STRIP, 1, { color: PALETTE.axis, width: 2 });
      const [ca, cb] = state.cell;
      p.polyline([[U[ca - 1], V[cb - 1]], [U[ca], V[cb - 1]], [U[ca], V[cb]], [U[ca - 1], V[cb]]],
        { color: PALETTE.highlight, width: 4, close: true });
      // pre-image (ξ_i, η_j) of B_ij
      const xi = state.i === 0 ? U[0] : state.i > m() ? U[m()] : (U[state.i - 1] + U[state.i]) / 2;
      const eta = state.j === 0 ? V[0] : state.j > n() ? V[n()] : (V[state.j - 1] + V[state.j]) / 2;
      p.points([[xi, eta]], { color: PALETTE.ink, radius: 6, shape: 'diamond', stroke: '#fff' });
      p.label(xi, eta, `(ξ${sub(state.i)}, η${sub(state.j)})`, { offset: [8, -6], font: '600 13px system-ui, sans-serif' });
    },
    drawOver(g, p) {
      if (!state.ordinates || !cells) return;
      const k0 = 13 * cellIndex(state.cell[0], state.cell[1]);
      const [ca, cb] = state.cell;
      const wide = Math.min(p.sx(state.u[ca]) - p.sx(state.u[ca - 1]), p.sy(state.v[cb - 1]) - p.sy(state.v[cb])) > 150;
      for (let k = 0; k < 13; k++) {
        const x = cells.domainPoints[2 * (k0 + k)], y = cells.domainPoints[2 * (k0 + k) + 1];
        const val = cells.ordinates[k0 + k];
        p.points([[x, y]], { color: val !== 0 ? PALETTE.highlight : '#fff', radius: 4.5, stroke: PALETTE.ink });
        if (val !== 0 && wide) p.label(x, y, fmt(val, 2), { offset: [4, -3], font: '600 11px system-ui, sans-serif' });
      }
    },
  });
  plot.canvas.dataset.plot = 'domain';

  const clampKnot = (arr, k, x) => Math.min(arr[k + 1] - MIN_GAP, Math.max(arr[k - 1] + MIN_GAP, x));
  plot.addHandles({
    name: 'u knot',
    points: () => state.u.slice(1, -1).map((x) => [x, -STRIP]),
    label: (k) => `u${sub(k + 1)}`, labelOf: (k) => `Knot line u${k + 1}`,
    color: PALETTE.ink, shape: 'triangle', radius: 8, axis: 'x',
    constrain: (k, q) => [clampKnot(state.u, k + 1, q[0]), -STRIP],
    move(k, q) { state.u[k + 1] = q[0]; refresh({ dragging: true }); },
    end() { refresh({ compute: false }); ctx.save(); },
  });
  plot.addHandles({
    name: 'v knot',
    points: () => state.v.slice(1, -1).map((y) => [-STRIP, y]),
    label: (k) => `v${sub(k + 1)}`, labelOf: (k) => `Knot line v${k + 1}`,
    color: PALETTE.ink, shape: 'triangle', radius: 8, axis: 'y',
    constrain: (k, q) => [-STRIP, clampKnot(state.v, k + 1, q[1])],
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
    if (cells) {
      const k0 = 13 * cellIndex(state.cell[0], state.cell[1]);
      const rows = ORD_NAMES.map((nm, k) => [nm, cells.ordinates[k0 + k]]);
      const tds = ordTable.el.querySelectorAll('tbody td');
      if (tds.length !== rows.length) ordTable.set(rows);
      else rows.forEach((r, k) => { const t = fmt(r[1], 4); if (tds[k].textContent !== t) tds[k].textContent = t; });
    }
    try {
      const U = state.u, V = state.v;
      const xi = state.i === 0 ? U[0] : state.i > m() ? U[m()] : (U[state.i - 1] + U[state.i]) / 2;
      const eta = state.j === 0 ? V[0] : state.j > n() ? V[n()] : (V[state.j - 1] + V[state.j]) / 2;
      const r = wasm.crissCrossBasis({ u: U, v: V, i: state.i, j: state.j, atUV: [[xi, eta]] });
      const value = fmt(r.values[0], 4);
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
    sanitize();
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
  explanation(L.explain, {
    what: [
      ['Each cell ', math('[u_{a-1}, u_a] \\times [v_{b-1}, v_b]'), ' of the grid is cut by its two diagonals into four triangles (the criss-cross triangulation). ',
        'On it, the B-spline ', math('B_{ij}'), ' is a piecewise quadratic that is ', math('C^1'), ' everywhere — across the grid lines and across the diagonals. ',
        'It is non-negative, the ', math('B_{ij}'), ' sum to 1, and ', math('B_{ij}'), ' is zero outside an octagon: 28 triangles for an interior one, including only two triangles of each corner cell (outlined in orange).'],
      ['On every grid line ', math('B_{ij}'), ' has the same trace as the tensor product ', math('B_i(u)\\, B_j(v)'), ' of univariate quadratic B-splines (eq. (23) and its v-analogue). ',
        'That fixes its BB net cell by cell: corners and edge midpoints are products of the univariate Bézier ordinates, each half-diagonal ordinate is the mean of the two neighbouring edge midpoints, and the centre is the mean of all four. ',
        'A surface is the sum ', math('S = \\sum_{ij} C_{ij} B_{ij}'), ': the stepper of the Curve networks demo adds these terms up row by row.'],
    ],
    math: [
      '\\sigma_r = \\frac{h_r}{h_{r-1} + h_r}, \\quad \\sigma\'_r = \\frac{h_{r-1}}{h_{r-1} + h_r}, \\quad h_r = u_r - u_{r-1} \\quad (\\tau, \\tau\' \\;\\text{likewise in}\\; v)',
      '\\text{central cell of}\\; B_{ij}: \\quad c_{00} = \\sigma\'_i \\tau\'_j, \\; e_b = \\tau\'_j, \\; e_r = \\sigma_{i+1}, \\; e_t = \\tau_{j+1}, \\; e_l = \\sigma\'_i',
      'd_{00} = \\frac{e_b + e_l}{2}, \\ldots \\quad o = B_{ij}(\\xi_i, \\eta_j) = \\frac{\\sigma\'_i + \\sigma_{i+1} + \\tau\'_j + \\tau_{j+1}}{4} \\quad (\\frac{1}{2} \\;\\text{on a uniform grid})',
      '\\text{dependence:}\\quad \\sum_{i=1}^{m} \\sum_{j=1}^{n} (-1)^{i+j} h_i k_j B_{ij} = 0',
    ],
    tryThis: [
      'Drag a knot line next to Bᵢⱼ: its support stretches and the centre value Bᵢⱼ(ξᵢ, ηⱼ) moves away from 1/2.',
      'Set i = 0 or j = 0: boundary B-splines have fewer triangles; B₀₀ is non-zero only near one corner.',
      'Click a cell of the support (or use the sliders) to read its 13 BB ordinates; in a corner cell only one is non-zero.',
      'Make two knot lines almost meet: the triangles get thin, yet Bᵢⱼ stays C¹ and non-negative.',
    ],
    paper: meta.paper,
  });

  // ---------- start ----------
  sanitize();
  refresh();
  view.fit();
  if (state.view.length) view.setView(cameraFrom(state.view)); // the camera kept in the link

  return {
    destroy() { clearTimeout(ctlTimer); basisCC.destroy(); plot.destroy(); view.destroy(); },
    // for the shell's Export row: B_ij sampled on the grid (u, v, value), its mesh, the BB ordinates of the cells
    exports() {
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

function sub(i) { return String(i).replace(/\d/g, (d) => '₀₁₂₃₄₅₆₇₈₉'[d]); }

// The camera in the state: [yaw°, pitch°, distance, target x, y, z] ([] = frame the surface).
const validCamera = (a) => Array.isArray(a) && (a.length === 0 || (a.length === 6 && a.every(Number.isFinite) && a[2] > 0));
const cameraOf = (v) => [v.yaw, v.pitch, v.distance, ...v.target];
const cameraFrom = (a) => ({ yaw: a[0], pitch: a[1], distance: a[2], target: a.slice(3, 6) });

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
