// Demo "B2 surfaces" (seed 000 §6–7): the tensor-product B2-spline surface of a grid W_ij with the a slider
// (a = 0 interpolates the grid, a = 1/6 is the bicubic B-spline), tensions in u and v, and — when the module
// exports it — the spline-blended surface of a network formula. The surface values come from the wasm API
// (b2Surface, splineBlendedSurface); this module only projects and draws a wireframe on a 2D canvas.

import { h, demoLayout, explanation, fmt } from '../lib/dom.js';
import { createPlot, PALETTE } from '../lib/plot2d.js';
import { slider, buttonGroup, select, button, group, row, readout, toggle } from '../lib/controls.js';

export const meta = {
  id: 'b2-surfaces',
  title: 'B2 surfaces',
  summary: 'Tensor-product B2-spline surfaces: from interpolating the grid (a = 0) to the bicubic B-spline (a = 1/6).',
  paper: 'M. Kuklišová (seed 000) §6 tensor-product surfaces, §7 spline-blended surfaces',
};

// Height functions for the grid W_ij = (i − 1, j − 1, f(i − 1, j − 1)) and for the network of the blended
// surface (data only; no spline maths).
const SHAPES = {
  hill: { label: 'hill', f: (x, y) => 2.2 * Math.exp(-((x - 2.5) ** 2 + (y - 2.5) ** 2) / 2.5) },
  saddle: { label: 'saddle', f: (x, y) => 0.18 * ((x - 2.5) ** 2 - (y - 2.5) ** 2) },
  ripple: { label: 'ripple', f: (x, y) => 0.8 * Math.sin(1.3 * x) * Math.cos(1.1 * y) },
  step: { label: 'step (overshoot test)', f: (x, y) => (x + 0.3 * y > 3 ? 1.5 : 0) },
};

export function defaults() {
  return {
    mode: 'tensor', shape: 'hill', size: 8, a: 0, tu: 1 / 6, tv: 1 / 6, knots: 'uniform',
    yaw: -35, pitch: 30, showNet: true, lift: { i: 3, j: 3, dz: 0 },
  };
}

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
    num('a', -0.1, 0.25); num('tu', 0, 0.5); num('tv', 0, 0.5); num('yaw', -180, 180); num('pitch', -89, 89);
    if (!['uniform', 'chord'].includes(state.knots)) state.knots = 'uniform';
    const l = state.lift;
    if (!(l && Number.isInteger(l.i) && Number.isInteger(l.j) && Number.isFinite(l.dz) && Math.abs(l.dz) <= 5)) state.lift = { ...d.lift };
    state.lift.i = Math.max(0, Math.min(state.size - 1, state.lift.i));
    state.lift.j = Math.max(0, Math.min(state.size - 1, state.lift.j));
    state.showNet = !!state.showNet;
  }

  // ---------- data: the grid (W_-1..W_m+2 × W_-1..W_n+2) ----------
  function grid() {
    const f = SHAPES[state.shape].f, s = state.size, out = [];
    for (let i = 0; i < s; i++) {
      const r = [];
      for (let j = 0; j < s; j++) {
        const x = (i - 1) * 5 / (s - 3), y = (j - 1) * 5 / (s - 3);
        r.push([x, y, f(x, y) + (i === state.lift.i && j === state.lift.j ? state.lift.dz : 0)]);
      }
      out.push(r);
    }
    return out;
  }

  let W = null, surf = null, flatOf = null;
  const SU = 29, SV = 29;
  function compute() {
    W = grid();
    surf = null;
    try {
      if (state.mode === 'tensor') {
        surf = wasm.b2Surface({ grid: W, a: state.a, tensionU: state.tu, tensionV: state.tv, knotsU: state.knots, knotsV: state.knots, samplesU: SU, samplesV: SV });
      } else {
        const f = SHAPES[state.shape].f, s = state.size;
        const knots = Array.from({ length: s }, (_, k) => (k - 1) * 5 / (s - 3));
        surf = wasm.splineBlendedSurface({ network: (u, v) => [u, v, f(u, v)], uKnots: knots, vKnots: knots, blend: 'b2', a: state.a, tensionU: state.tu, tensionV: state.tv, samplesU: SU, samplesV: SV });
      }
    } catch (e) { notify(e, 'error'); }
  }

  // ---------- projection (display only) ----------
  function projector() {
    const cy = Math.cos(state.yaw * Math.PI / 180), sy = Math.sin(state.yaw * Math.PI / 180);
    const cp = Math.cos(state.pitch * Math.PI / 180), sp = Math.sin(state.pitch * Math.PI / 180);
    return (x, y, z) => {
      const X = cy * (x - 2.5) - sy * (y - 2.5);
      const Y = sy * (x - 2.5) + cy * (y - 2.5);
      return [X, z * cp + Y * sp];
    };
  }

  const plot = createPlot(L.plots, {
    ariaLabel: 'Wireframe of the B2 surface (drag the background to turn it)',
    equal: true, height: 480, pan: false, zoom: true, grid: false, axes: false, ticks: false,
    view: { xmin: -4.5, xmax: 4.5, ymin: -3.5, ymax: 4.5 },
    describe: () => `${state.mode === 'tensor' ? 'Tensor-product' : 'Spline-blended'} B2 surface, a = ${fmt(state.a, 3)}, ${state.size} × ${state.size} grid.`,
    draw(g, p) {
      const P = projector();
      if (surf) {
        const pts = surf.points, d = surf.dim;
        const line = new Float64Array(2 * Math.max(SU, SV));
        for (let iu = 0; iu < SU; iu++) {
          for (let iv = 0; iv < SV; iv++) { const k = (iu * SV + iv) * d; const q = P(pts[k], pts[k + 1], pts[k + 2]); line[2 * iv] = q[0]; line[2 * iv + 1] = q[1]; }
          p.polyline(line.subarray(0, 2 * SV), { color: PALETTE.curve, width: 1.5 });
        }
        for (let iv = 0; iv < SV; iv++) {
          for (let iu = 0; iu < SU; iu++) { const k = (iu * SV + iv) * d; const q = P(pts[k], pts[k + 1], pts[k + 2]); line[2 * iu] = q[0]; line[2 * iu + 1] = q[1]; }
          p.polyline(line.subarray(0, 2 * SU), { color: PALETTE.curve, width: 1.5 });
        }
      }
      if (state.showNet && W) {
        const s = W.length;
        for (let i = 0; i < s; i++) p.polyline(W[i].map((q) => P(...q)), { color: PALETTE.polygon, width: 1, dash: [4, 4] });
        for (let j = 0; j < s; j++) p.polyline(W.map((r) => P(...r[j])), { color: PALETTE.polygon, width: 1, dash: [4, 4] });
        const inner = [], outer = [];
        for (let i = 0; i < s; i++) for (let j = 0; j < s; j++) (i >= 2 && i < s - 2 && j >= 2 && j < s - 2 ? inner : outer).push(P(...W[i][j]));
        p.points(outer, { color: PALETTE.muted, radius: 3, shape: 'square' });
        p.points(inner, { color: PALETTE.control, radius: 3.5 });
        const l = state.lift, q = W[l.i][l.j];
        p.points([P(...q)], { color: PALETTE.highlight, radius: 7, shape: 'diamond', stroke: '#fff' });
      }
    },
  });
  plot.canvas.dataset.plot = 'surface';

  // turn by dragging with the pointer on the canvas background
  let turning = null;
  const onDown = (e) => { turning = { x: e.clientX, y: e.clientY, yaw: state.yaw, pitch: state.pitch }; };
  const onMove = (e) => {
    if (!turning || !(e.buttons & 1)) { turning = null; return; }
    state.yaw = ((turning.yaw - (e.clientX - turning.x) * 0.5 + 540) % 360) - 180;
    state.pitch = Math.max(-89, Math.min(89, turning.pitch + (e.clientY - turning.y) * 0.4));
    yawCtl.set(state.yaw); pitchCtl.set(state.pitch);
    plot.redraw();
  };
  const onUp = () => { if (turning) ctx.save(); turning = null; };
  plot.canvas.addEventListener('pointerdown', onDown);
  window.addEventListener('pointermove', onMove);
  window.addEventListener('pointerup', onUp);

  L.plots.appendChild(h('ul', { class: 'legend', 'aria-label': 'Legend' },
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.curve } }), 'surface S(u, v) (wireframe)'),
    h('li', null, h('span', { class: 'swatch dashed' }), 'grid W_ij'),
    h('li', null, h('span', { class: 'swatch dot', style: { background: PALETTE.control } }), 'interpolated points W_ij, i = 1..m, j = 1..n'),
    h('li', null, h('span', { class: 'swatch dot', style: { background: PALETTE.muted } }), 'auxiliary border rows and columns'),
    h('li', null, h('span', { class: 'swatch dot', style: { background: PALETTE.highlight } }), 'the lifted point')));

  // ---------- controls ----------
  const modeOpts = [{ value: 'tensor', label: 'tensor product (§6)' }];
  if (hasBlended) modeOpts.push({ value: 'blended', label: 'spline-blended (§7)' });
  const modeCtl = buttonGroup({ label: 'Surface', options: modeOpts, value: state.mode, onChange(v) { state.mode = v; all(); ctx.save(); } });
  const shapeCtl = select({ label: 'Data', options: Object.entries(SHAPES).map(([value, s]) => ({ value, label: s.label })), value: state.shape, onChange(v) { state.shape = v; all(); ctx.save(); } });
  const sizeCtl = slider({ label: 'Grid size (m + 4 = n + 4)', name: 'size', min: 6, max: 14, step: 1, value: state.size, onInput(v) { state.size = v; sanitize(); all(); }, onChange() { ctx.save(); } });
  const aCtl = slider({
    label: 'Approximation a', name: 'a', min: -0.1, max: 0.25, step: 0.001, value: state.a, number: true,
    ticks: [{ value: 0, label: '0 interpolates' }, { value: 1 / 6, label: '1/6 B-spline' }],
    onInput(v) { state.a = v; all(); }, onChange() { ctx.save(); },
  });
  const tuCtl = slider({ label: 'Tension in u', name: 'tu', min: 0, max: 0.5, step: 0.001, value: state.tu, onInput(v) { state.tu = v; all(); }, onChange() { ctx.save(); } });
  const tvCtl = slider({ label: 'Tension in v', name: 'tv', min: 0, max: 0.5, step: 0.001, value: state.tv, onInput(v) { state.tv = v; all(); }, onChange() { ctx.save(); } });
  const knotCtl = buttonGroup({ label: 'Knots (tensor product)', options: ['uniform', 'chord'], value: state.knots, onChange(v) { state.knots = v; all(); ctx.save(); } });
  const liftCtl = slider({ label: 'Lift the marked grid point', name: 'lift', min: -3, max: 3, step: 0.01, value: state.lift.dz, onInput(v) { state.lift.dz = v; all(); }, onChange() { ctx.save(); } });
  const liftI = slider({ label: 'marked point i', name: 'liftI', min: 0, max: state.size - 1, step: 1, value: state.lift.i, onInput(v) { state.lift.i = v; all(); }, onChange() { ctx.save(); } });
  const liftJ = slider({ label: 'marked point j', name: 'liftJ', min: 0, max: state.size - 1, step: 1, value: state.lift.j, onInput(v) { state.lift.j = v; all(); }, onChange() { ctx.save(); } });
  const yawCtl = slider({ label: 'Turn', name: 'yaw', min: -180, max: 180, step: 1, value: state.yaw, onInput(v) { state.yaw = v; plot.redraw(); }, onChange() { ctx.save(); } });
  const pitchCtl = slider({ label: 'Tilt', name: 'pitch', min: -89, max: 89, step: 1, value: state.pitch, onInput(v) { state.pitch = v; plot.redraw(); }, onChange() { ctx.save(); } });
  const netCtl = toggle({ label: 'Show the grid', value: state.showNet, onChange(v) { state.showNet = v; plot.redraw(); ctx.save(); } });
  const info = readout({ label: 'Domain' });
  const interpBtn = button({ label: 'a = 0', onClick: () => { state.a = 0; aCtl.set(0); all(); ctx.save(); } });
  const bsplBtn = button({ label: 'a = 1/6', onClick: () => { state.a = 1 / 6; aCtl.set(state.a); all(); ctx.save(); } });

  L.controls.append(
    group('Surface', modeCtl.el, shapeCtl.el, sizeCtl.el, knotCtl.el, info.el),
    group('Approximation', aCtl.el, row(interpBtn.el, bsplBtn.el), tuCtl.el, tvCtl.el),
    group('Edit', liftCtl.el, liftI.el, liftJ.el),
    group('View', yawCtl.el, pitchCtl.el, netCtl.el, h('p', { class: 'ctl-hint' }, 'Drag the picture to turn it. (A simple wireframe; the full 3D viewer is used by the surface demos.)')),
  );

  function refresh() {
    liftI.setRange({ max: state.size - 1 }); liftJ.setRange({ max: state.size - 1 });
    liftI.set(state.lift.i); liftJ.set(state.lift.j); liftCtl.set(state.lift.dz);
    knotCtl.setDisabled(state.mode !== 'tensor');
    if (surf && surf.domain) info.set(`u ∈ [${fmt(surf.domain[0], 2)}, ${fmt(surf.domain[1], 2)}], v ∈ [${fmt(surf.domain[2], 2)}, ${fmt(surf.domain[3], 2)}]`);
    else info.set(`${state.size} × ${state.size} grid`);
  }

  function all() { compute(); refresh(); plot.redraw(); }

  explanation(L.explain, {
    what: [
      'Section 6 of the paper: with the B2 blending functions Lᵢ(u), Lⱼ(v) of the curve construction, the tensor-product surface is S(u, v) = Σᵢ Σⱼ W_ij Lᵢ(u) Lⱼ(v). The grid has an extra border of two rows and columns on each side (i = −1..m+2, j = −1..n+2), shown grey; at a = 0 the surface passes through the inner points W_ij (i = 1..m, j = 1..n), at a = 1/6 it is the bicubic B-spline of the grid.',
      'Because the paper gives no rule for one knot sequence and one tension that suits every row, both are chosen per direction here (uniform or averaged chord lengths). The surface is computed as a bicubic B-spline whose control net is the B2 construction applied along u and then along v.',
      hasBlended ? 'Section 7: the spline-blended surface G = G₁ + G₂ − G₁₂ interpolates a whole network of curves, here the lines u = uᵢ and v = vⱼ of the chosen formula.' : '',
    ].filter(Boolean),
    formula: [
      'S(u, v) = Σᵢ Σⱼ W_ij · Lᵢ(u) · Lⱼ(v),    i = −1..m+2,  j = −1..n+2',
      'Lⱼ = the B2 curve of the data eⱼ (1 at j, 0 elsewhere)',
      'G = G₁ + G₂ − G₁₂,  G₁ = Σᵢ G(uᵢ, v) Lᵢ(u),  G₂ = Σⱼ G(u, vⱼ) Lⱼ(v)      (4)',
    ],
    tryThis: [
      'Lift the marked point at a = 0: the surface follows it exactly; at a = 1/6 it only pulls the surface towards it.',
      'Choose the "step" data: the interpolating surface overshoots at the step, the B-spline does not.',
      'Raise the tension in one direction only and turn the picture.',
    ],
    paper: meta.paper,
  });

  sanitize();
  all();
  return {
    destroy() {
      plot.destroy();
      window.removeEventListener('pointermove', onMove);
      window.removeEventListener('pointerup', onUp);
    },
  };
}
