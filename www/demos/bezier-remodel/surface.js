// The surface tab of "Bézier remodelling" (§4): a WebGL2 view (www/lib/view3d.js: drag to orbit, wheel/pinch to
// zoom, F to frame) that shows either the §4.1 remodelling in u (bezierRemodelSurface: the curve remodelling of
// eq. (6) applied to every column l with the same αₖ⁽ᴵ⁾, eq. (17); eq. (19) keeps C¹ across u = 1, 2) or the
// §4.2 bi-degree remodelling (bi-surface.js), in the same view with the same object names.
import { h, fmt } from '../../lib/dom.js';
import { PALETTE } from '../../lib/plot2d.js';
import { slider, toggle, buttonGroup, button, table, group } from '../../lib/controls.js';
import { View3D } from '../../lib/view3d.js';
import { SURFACE_POINTS, SURFACE_PRESETS } from './data.js';
import { alphaName, prettyConstraint, sci } from './notation.js';
import { clampAlpha } from './curve-state.js';
import { mountBiSurface } from './bi-surface.js';
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

const NU = 61, NV = 17;   // samples: u = 1, 2 at iu = 20, 40
const SURFACE = { points: SURFACE_POINTS, degreeU: 2, degreeV: 3, breaksU: [0, 1, 2, 3], samplesU: NU, samplesV: NV };

/** Validates the §4.1 state in place (a link may hold anything that passed the type check). */
export function sanitizeSurface(s, fresh) {
  if (!(s.alphas.length === 3 && s.alphas.every((r) => Array.isArray(r) && r.length === 2))) s.alphas = fresh.alphas;
  for (const row of s.alphas) for (let k = 0; k < 2; k++) row[k] = clampAlpha(row[k]);
  s.r = s.r === 0 ? 0 : 1;
  s.yaw = Math.max(-360, Math.min(360, s.yaw));
  s.pitch = Math.max(-89, Math.min(89, s.pitch));
}

// polylines of a u-major NU × NV grid (flat xyz): along u at every `kv`-th v, or along v at the given iu
const alongU = (pts, kv) => {
  const out = [];
  for (let iv = 0; iv < NV; iv += kv) { const l = []; for (let iu = 0; iu < NU; iu++) { const k = 3 * (iu * NV + iv); l.push([pts[k], pts[k + 1], pts[k + 2]]); } out.push(l); }
  return out;
};
const alongV = (pts, iu) => { const l = []; for (let iv = 0; iv < NV; iv++) { const k = 3 * (iu * NV + iv); l.push([pts[k], pts[k + 1], pts[k + 2]]); } return l; };

/** Draws G* (mesh, isolines), the joint lines u = 1, 2, the control net of G* and the given G into `view`. */
function drawSurface(view, s, sres, sorig) {
  view.setMesh('G*', sres.mesh, { color: PALETTE.sky, isolines: { every: [5, 2], width: 1 } });
  view.setLines('joints', [alongV(sres.points, 20), alongV(sres.points, 40)], { color: PALETTE.control, width: 4 }); // u = 1, 2
  const cp = sres.controlPoints, rows = sres.rows, cols = sres.cols, net = [];
  const P = (k, l) => [cp[3 * (k * cols + l)], cp[3 * (k * cols + l) + 1], cp[3 * (k * cols + l) + 2]];
  for (let k = 0; k < rows; k++) net.push(Array.from({ length: cols }, (_, l) => P(k, l)));
  for (let l = 0; l < cols; l++) net.push(Array.from({ length: rows }, (_, k) => P(k, l)));
  view.setLines('net', net, { color: PALETTE.second, width: 1.5, opacity: 0.85, visible: s.showNet });
  view.setPoints('b*', cp, { color: PALETTE.second, size: 7, pickable: false, visible: s.showNet });
  if (sorig) view.setLines('G', alongU(sorig.points, 4), { color: PALETTE.ink, width: 1.5, opacity: 0.7, visible: s.showOriginal });
}

/**
 * Builds the surface tab into `panel` (the view, the legends) and `ctl` (controls).
 * Returns { update, showConstruction, frame, result, biResult, destroy }.
 * @param {{ wasm: SplineLab, state: Record<string, any>, ctx: import('../../lib/host.js').DemoContext, notify: (e: any, kind?: 'info' | 'error') => void, locked: boolean, panel: HTMLElement, ctl: HTMLElement }} figure
 */
export function mountSurfaceTab({ wasm, state, ctx, notify, locked, panel, ctl }) {
  const view = new View3D(panel, {
    height: 460, locked: true,
    ariaLabel: 'Remodelled Bézier spline surface G* (shaded, with isolines), the joint lines u = 1, 2, its control net and the given surface G',
    onViewChange(v) { state.surface.yaw = v.yaw; state.surface.pitch = v.pitch; state.surface.camera = [v.distance, ...v.target]; ctx.save(); },
  });
  view.canvas.dataset.plot = 'surface';
  const swatch = (color, text) => h('li', null, h('span', { class: 'swatch', style: { background: color } }), text);
  const surfLegend = h('ul', { class: 'legend', 'aria-label': 'Legend' },
    swatch(PALETTE.sky, 'G* (degree 3 in u, 3 in v) with isolines'),
    swatch(PALETTE.control, 'joint lines u = 1, 2'),
    swatch(PALETTE.second, 'control net b*ₖ,ₗ of G*'),
    swatch(PALETTE.ink, 'given G (lines v = const)'));
  panel.appendChild(surfLegend);
  // §4.2, the bi-degree remodelling: its own controls, readouts and legend, drawn in the same view
  const bi = mountBiSurface({ wasm, state, ctx, notify, view, locked });
  panel.appendChild(bi.legend);

  let sres = null, sorig = null;
  function computeSurface() {
    const s = state.surface;
    try {
      sres = wasm.bezierRemodelSurface({ ...SURFACE, alphas: s.alphas, r: s.r, enforce: s.enforce, mesh: true });
      s.alphas = sres.alphas.map((row) => Array.from(row));
    } catch (e) { notify(e, 'error'); }
    if (!sorig) {
      try { sorig = wasm.bezierRemodelSurface(SURFACE); } catch (e) { notify(e, 'error'); }
    }
  }
  function draw() {
    if (!sres) return;
    try { drawSurface(view, state.surface, sres, sorig); } catch (e) { notify(e, 'error'); }
  }
  let cameraSet = false;
  function frame() {
    view.fit();
    const c = state.surface.camera;   // zoom and target [d, x, y, z] kept in the link ([] = frame the surface)
    if (!cameraSet) {
      cameraSet = true; view.setView({ yaw: state.surface.yaw, pitch: state.surface.pitch }); view.fit();
      if (Array.isArray(c) && c.length === 4 && c.every(Number.isFinite) && c[0] > 0) view.setView({ distance: c[0], target: c.slice(1) });
    } else state.surface.camera = [];
    view.render();
  }

  // ---------- controls ----------
  const presetCtl = buttonGroup({
    label: 'Example (§4)', options: Object.entries(SURFACE_PRESETS).map(([value, p]) => ({ value, label: p.label.split(':')[0] })), value: state.surface.preset,
    onChange(p) {
      const s = state.surface, pr = SURFACE_PRESETS[p];
      s.preset = p; s.alphas = pr.alphas.map((r) => [...r]); s.enforce = pr.enforce; s.r = 1;
      update(); ctx.save();
    },
  });
  const presetNote = h('p', { class: 'ctl-hint' });
  const rCtl = buttonGroup({ label: 'Keep Cʳ in u: r', options: [0, 1].map((v) => ({ value: v, label: String(v) })), value: state.surface.r, onChange(v) { state.surface.r = v; update(); ctx.save(); } });
  const enforceCtl = toggle({ label: 'Enforce eq. (19)', value: state.surface.enforce, onChange(v) { state.surface.enforce = v; update(); ctx.save(); } });
  const origCtl = toggle({ label: 'Given surface G (black lines)', value: state.surface.showOriginal, onChange(v) { state.surface.showOriginal = v; view.setVisible('G', v); ctx.save(); } });
  const netCtl = toggle({ label: 'Control net of G*', value: state.surface.showNet, onChange(v) { state.surface.showNet = v; view.setVisible('net', v); view.setVisible('b*', v); ctx.save(); } });
  const resetViewBtn = button({ label: 'Reset view', onClick() { view.resetView(); } });
  const alphaBox = h('div');
  const sliders = [];   // [I][k]: αₖ⁽ᴵ⁾, the same for every column l (eq. 17)
  for (let I = 0; I < 3; I++) {
    const row = [];
    for (let k = 1; k <= 2; k++) {
      const s = slider({
        label: `${alphaName(k, I)} (every l)`, min: 0.001, max: 0.999, step: 0.001, value: state.surface.alphas[I][k - 1], number: true, format: (v) => fmt(v, 4),
        onInput(v) { state.surface.alphas[I][k - 1] = v; state.surface.preset = 'custom'; update(); },
        onChange() { ctx.save(); },
      });
      const hint = h('div', { class: 'ctl-hint' });
      s.el.appendChild(hint); s.hint = hint;
      row.push(s);
      alphaBox.appendChild(s.el);
    }
    sliders.push(row);
  }
  const contTable = table({ caption: 'Jumps of ∂ⁱG*/∂uⁱ across the joint lines', columns: ['I', 'd₀', 'd₁', 'd₂'], digits: 3 });
  const dataTable = table({ caption: 'Control points bₖ,ₗ of G (§4 table): z values', columns: ['k \\ l', '0', '1', '2', '3'], digits: 2, rows: SURFACE_POINTS.map((row, k) => [String(k), ...row.map((p) => p[2])]) });
  const constructionCtl = buttonGroup({
    label: 'Construction', value: state.bi.on ? 'bi' : 'u',
    options: [{ value: 'u', label: 'Degree in u (§4.1)' }, { value: 'bi', label: 'Bi-degree, u and v (§4.2)' }],
    onChange(v) { state.bi.on = v === 'bi'; showConstruction(); frame(); ctx.save(); },
  });
  const uOnlyBox = h('div', null,
    group('Surface', presetCtl.el, presetNote, rCtl.el, enforceCtl.el),
    group('Parameters α (eq. 17)', alphaBox),
    group('Continuity in u', contTable.el));
  const uDataBox = h('div', null,
    group('Data', dataTable.el, h('p', { class: 'ctl-hint' }, 'x = k, y ∈ {0, 1, 3, 4}; breakvalues u = 0, 1, 2, 3 and v = 0, 1; degrees m = 2, n = 3.')));
  ctl.append(
    constructionCtl.el,
    uOnlyBox,
    bi.controls,
    group('View', origCtl.el, netCtl.el, resetViewBtn.el, h('p', { class: 'ctl-hint' }, 'Drag to turn the surface, wheel or pinch to zoom (click the view first), F to frame it.')),
    uDataBox,
  );

  /** Shows the §4.1 or the §4.2 construction (same view, same object names, so the View toggles serve both). */
  function showConstruction() {
    const on = !!state.bi.on;
    constructionCtl.set(on ? 'bi' : 'u');
    for (const el of [uOnlyBox, uDataBox, surfLegend]) el.style.display = on ? 'none' : '';
    for (const el of [bi.controls, bi.legend]) el.style.display = on ? '' : 'none';
    if (on) bi.update(); else draw();
    view.render();
  }

  /** Recomputes §4.1 and refreshes its controls (and the drawing, when §4.1 is shown). */
  function update() {
    computeSurface();
    const s = state.surface;
    presetCtl.set(s.preset);
    rCtl.set(s.r);
    enforceCtl.set(s.enforce);
    origCtl.set(s.showOriginal);
    netCtl.set(s.showNet);
    presetNote.textContent = SURFACE_PRESETS[s.preset]?.label || 'Custom parameters';
    if (sres) {
      for (let I = 0; I < 3; I++) for (let k = 1; k <= 2; k++) {
        const sl = sliders[I][k - 1], free = sres.free[I][k - 1];
        sl.set(s.alphas[I][k - 1]);
        sl.setDisabled(locked || !free);
        sl.el.querySelector('.ctl-track').style.opacity = free ? '1' : '0.45';
        sl.el.querySelector('label').style.color = free ? '' : '#595959';
        sl.hint.textContent = free ? '' : `fixed: ${prettyConstraint(sres.constraints[I][k - 1]).replace('eq. 9', 'eq. 19')}`;
      }
      contTable.set(Array.from(sres.continuity, (row, j) => [String(j + 1), ...Array.from(row, sci)]));
    }
    if (!state.bi.on) draw();
  }

  return {
    update, showConstruction, frame,
    result: () => sres,
    biResult: () => bi.result(),
    destroy() { view.destroy(); },
  };
}
