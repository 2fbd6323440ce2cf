// The §4.2 part of the surface tab of "Bézier remodelling": the bi-degree remodelling (degrees (m, n) → (m + 1, n + 1),
// class C^{r,s}). The construction (bezierRemodelSurfaceBi) is the curve remodelling of eq. (6) applied in u, column by
// column with the parameters α_{k,l}^(I) of eq. (17), then in v, row by row with β_l^(J); the printed eqs. (20)–(22)
// are garbled. The net (data.js) is the §4 table with its v-patch split at v = 1 (a biquadratic net, 3 × 2 patches,
// C¹ in u and v).
import { h, fmt, clear, append, legend } from '../../lib/dom.js';
import { PALETTE } from '../../lib/plot2d.js';
import { slider, toggle, buttonGroup, table, group, readout } from '../../lib/controls.js';
import { BI_POINTS, BI_BREAKS_U, BI_BREAKS_V, BI_M, BI_N, BI_COLS, BI_SEGS_U, BI_SEGS_V, BI_NU, BI_NV } from './data.js';
import { sub, sup, supParen, alphaName, sci } from './notation.js';
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

/** The state of the bi-degree view (its own key, so the §4.1 state and links stay as they were). */
export function biDefaults() {
  const c2 = [[0.6, 0.15], [0.85, 0.4], [0.6, 0.5]];   // columns 1..3 share column 2's table (C¹ across v = 1)
  return {
    on: false,
    col: 0,
    alphas: [[[0.5, 0.2], [0.8, 0.3], [0.7, 0.6]], c2, c2, c2, [[0.4, 0.3], [0.7, 0.2], [0.8, 0.7]]].map((t) => t.map((r) => [...r])),
    betas: [[0.55, 0.3], [0.7, 0.35]],
    r: 1,
    s: 1,
    enforce: true,
  };
}

/** Validates the bi-degree state in place (a link may hold anything that passed the type check). */
export function sanitizeBi(b) {
  const d = biDefaults();
  const table = (t, segs) => Array.isArray(t) && t.length === segs && t.every((r) => Array.isArray(r) && r.length === 2 && r.every(Number.isFinite));
  if (!(Array.isArray(b.alphas) && b.alphas.length === BI_COLS && b.alphas.every((t) => table(t, BI_SEGS_U)))) b.alphas = d.alphas;
  if (!table(b.betas, BI_SEGS_V)) b.betas = d.betas;
  const clamp = (a) => Math.min(0.999, Math.max(0.001, a));
  for (const t of [...b.alphas, b.betas]) for (const r of t) for (let k = 0; k < 2; k++) r[k] = clamp(r[k]);
  b.r = b.r === 0 ? 0 : 1;
  b.s = b.s === 0 ? 0 : 1;
  b.col = Math.max(0, Math.min(BI_COLS - 1, Math.round(b.col) || 0));
}

/**
 * Mounts the §4.2 part of the surface tab: controls (r, s, eq. (9) on/off, the column l whose α_{k,l} are edited,
 * the shared β), readouts (jumps across u = u_I and v = v_J, corner points kept) and the drawing in `view`.
 * Returns { controls, legend, update, draw, result }.
 * @param {{ wasm: SplineLab, state: Record<string, any>, ctx: import('../../lib/host.js').DemoContext, notify: (e: any, kind?: 'info' | 'error') => void, view: any, locked: boolean }} figure
 */
export function mountBiSurface({ wasm, state, ctx, notify, view, locked }) {
  const b = state.bi;
  sanitizeBi(b);
  let res = null, orig = null;

  function compute() {
    try {
      res = wasm.bezierRemodelSurfaceBi({
        points: BI_POINTS, degreeU: BI_M, degreeV: BI_N, breaksU: BI_BREAKS_U, breaksV: BI_BREAKS_V,
        alphas: b.alphas, betas: b.betas, r: b.r, s: b.s, enforce: b.enforce, samplesU: BI_NU, samplesV: BI_NV, mesh: true,
      });
      // keep the tables that were used (eq. (9) and the break-line windows overwrite some entries)
      b.alphas = Array.from(res.alphas, (t) => Array.from(t, (r) => Array.from(r)));
      // betas come back per row; the demo edits one shared table (every row's is the same)
      b.betas = Array.from(res.betas[0], (r) => Array.from(r));
    } catch (e) { res = null; notify(e, 'error'); }
    if (!orig) {
      try {
        orig = wasm.bezierRemodelSurfaceBi({ points: BI_POINTS, degreeU: BI_M, degreeV: BI_N, breaksU: BI_BREAKS_U, breaksV: BI_BREAKS_V, samplesU: BI_NU, samplesV: BI_NV });
      } catch (e) { notify(e, 'error'); }
    }
  }

  // which entries the API fixes (for greying the sliders): eq. (9) with r = 1 fixes α₁⁽ᴵ⁾ (I ≥ 1) to 1 − α₂⁽ᴵ⁻¹⁾,
  // and with s = 1 the columns n·J ± 1 around the break line v_J take the table of column n·J
  const windowOf = (l) => {
    if (!b.enforce) return -1;
    for (let J = 1; J < BI_SEGS_V; J++) if (l !== BI_N * J && Math.abs(l - BI_N * J) <= b.s) return BI_N * J;
    return -1;
  };
  const fixedByNine = (I, k, r) => b.enforce && r >= 1 && I >= 1 && k === 1;

  // ---------- controls ----------
  const rCtl = buttonGroup({ label: 'Keep Cʳ in u: r', options: [0, 1].map((v) => ({ value: v, label: String(v) })), value: b.r, onChange(v) { b.r = v; update(); ctx.save(); } });
  const sCtl = buttonGroup({ label: 'Keep Cˢ in v: s', options: [0, 1].map((v) => ({ value: v, label: String(v) })), value: b.s, onChange(v) { b.s = v; update(); ctx.save(); } });
  const enforceCtl = toggle({ label: 'Enforce eq. (9) in u and v', value: b.enforce, hint: 'Off: every α and β is free and G* generally loses C¹ across the break lines (see the jumps).', onChange(v) { b.enforce = v; update(); ctx.save(); } });
  const colCtl = buttonGroup({ label: 'Column l (αₖ,ₗ, eq. 17)', options: Array.from({ length: BI_COLS }, (_, l) => ({ value: l, label: String(l) })), value: b.col, onChange(v) { b.col = v; refresh(); ctx.save(); } });
  const mkSlider = (label, key, onInput) => {
    const s = slider({ label, min: 0.001, max: 0.999, step: 0.001, value: 0.5, number: true, format: (v) => fmt(v, 4), onInput, onChange() { ctx.save(); } });
    const hint = h('div', { class: 'ctl-hint bi-constraint' });
    s.el.appendChild(hint); s.hint = hint;
    Object.assign(s.el.dataset, key);
    return s;
  };
  const colHint = h('p', { class: 'ctl-hint', dataset: { role: 'bi-column-hint' }, 'aria-live': 'polite' });
  const alphaBox = h('div');
  const alphaSliders = [];
  for (let I = 0; I < BI_SEGS_U; I++) {
    for (let k = 1; k <= BI_M; k++) {
      const s = mkSlider(alphaName(k, I), { biAlpha: `${I},${k}` }, (v) => { b.alphas[b.col][I][k - 1] = v; update(); });
      s.I = I; s.k = k;
      alphaSliders.push(s);
      alphaBox.appendChild(s.el);
    }
  }
  const betaBox = h('div');
  const betaSliders = [];
  for (let J = 0; J < BI_SEGS_V; J++) {
    for (let k = 1; k <= BI_N; k++) {
      const s = mkSlider(`β${sub(k)}${supParen(J)} (every row)`, { biBeta: `${J},${k}` }, (v) => { b.betas[J][k - 1] = v; update(); });
      s.J = J; s.k = k;
      betaSliders.push(s);
      betaBox.appendChild(s.el);
    }
  }
  const contU = table({ caption: 'Jumps of ∂ⁱG*/∂uⁱ across the break lines in u (I: which line)', columns: ['I', 'd₀', 'd₁', 'd₂'], digits: 3 });
  const contV = table({ caption: 'Jumps of ∂ʲG*/∂vʲ across the break lines in v (J: which line)', columns: ['J', 'd₀', 'd₁', 'd₂'], digits: 3 });
  contU.el.dataset.role = 'bi-continuity-u';
  contV.el.dataset.role = 'bi-continuity-v';
  const cornerOut = readout({ label: 'Corners kept (max distance)', value: '—' });
  cornerOut.el.dataset.readout = 'bi-corners';
  const classOut = readout({ label: 'Degrees and class', value: '—' });
  classOut.el.dataset.readout = 'bi-class';
  const controls = h('div', { class: 'bi-surface-controls' },
    group('Bi-degree remodelling (§4.2)', rCtl.el, sCtl.el, enforceCtl.el, classOut.el,
      h('p', { class: 'ctl-hint' }, 'Built as the curve remodelling in u, column by column (αₖ,ₗ), then in v, row by row (β). The paper’s eqs. (20)–(22) are garbled; this is the reconstruction.')),
    group('Per-column parameters (eq. 17)', colCtl.el, colHint, alphaBox),
    group('Parameters in v, every row', betaBox),
    group('Continuity and corners', contU.el, contV.el, cornerOut.el),
    group('Data', h('p', { class: 'ctl-hint' }, 'The §4 table with its v-patch split at v = 1: columns y = 0, 1, 2, 3, 4 (the y = 2 column is the midpoint of its neighbours, so G is C¹ in v); degrees m = n = 2, breakvalues u = 0, 1, 2, 3 and v = 0, 1, 2. These data are ours: the paper prints none for §4.2.')),
  );
  const legendEl = legend([
    { label: 'G* (degree 3 in u, 3 in v) with isolines', color: PALETTE.sky, kind: 'band' },
    { label: 'break lines u = 1, 2 and v = 1', color: PALETTE.control },
    { label: 'control net b*ₖ,ₗ of G*', color: PALETTE.second },
    { label: 'given G (lines v = const)', color: PALETTE.ink },
  ]);
  legendEl.dataset.legendFor = 'surface-bi';

  // the exact numbers stay on the cells (data-value) for tests and copy; the text is rounded
  const setJumps = (tbl, rows, lead) => {
    const n = Math.max(0, ...Array.from(rows, (r) => r.length));
    const cols = [lead, ...Array.from({ length: n }, (_, i) => `d${sub(i)}`)];
    const head = tbl.el.querySelector('thead tr');
    clear(head);
    for (const c of cols) append(head, h('th', { scope: 'col' }, c));
    tbl.set(Array.from(rows, (r, j) => [String(j + 1), ...Array.from(r, sci)]));
    tbl.el.querySelectorAll('tbody tr').forEach((tr, j) => tr.querySelectorAll('td').forEach((td, i) => { td.dataset.value = String(rows[j][i]); }));
  };
  // max distance between the kept corners b*_{(m+1)I,(n+1)J} and b_{mI,nJ} (read from the API's control net)
  function cornerGap() {
    let worst = 0;
    for (let I = 0; I <= BI_SEGS_U; I++) {
      for (let J = 0; J <= BI_SEGS_V; J++) {
        const q = 3 * ((BI_M + 1) * I * res.cols + (BI_N + 1) * J), p = BI_POINTS[BI_M * I][BI_N * J];
        worst = Math.max(worst, Math.hypot(res.controlPoints[q] - p[0], res.controlPoints[q + 1] - p[1], res.controlPoints[q + 2] - p[2]));
      }
    }
    return worst;
  }

  function refresh() {
    rCtl.set(b.r); sCtl.set(b.s); enforceCtl.set(b.enforce); colCtl.set(b.col);
    rCtl.setDisabled(locked); sCtl.setDisabled(locked); enforceCtl.setDisabled(locked);
    const w = windowOf(b.col);
    colHint.textContent = w >= 0
      ? `Column ${b.col} follows column ${w}, the break line v = v${sub(w / BI_N)}: Cˢ across it needs the same weights on the columns next to it. Edit column ${w}.`
      : `Column ${b.col}: its own parameters αₖ,${sub(b.col)}⁽ᴵ⁾.`;
    for (const s of alphaSliders) {
      const v = b.alphas[b.col][s.I][s.k - 1];
      const free = w < 0 && !fixedByNine(s.I, s.k, b.r);
      s.set(v);
      s.setDisabled(locked || !free);
      s.el.dataset.free = String(free);
      s.el.querySelector('.ctl-track').style.opacity = free ? '1' : '0.45';
      s.hint.textContent = free || w >= 0 ? '' : `fixed: ${alphaName(1, s.I)} = 1 − ${alphaName(2, s.I - 1)}  (eq. 9)`;
    }
    for (const s of betaSliders) {
      const free = !fixedByNine(s.J, s.k, b.s);
      s.set(b.betas[s.J][s.k - 1]);
      s.setDisabled(locked || !free);
      s.el.dataset.free = String(free);
      s.el.querySelector('.ctl-track').style.opacity = free ? '1' : '0.45';
      s.hint.textContent = free ? '' : `fixed: β${sub(1)}${supParen(s.J)} = 1 − β${sub(2)}${supParen(s.J - 1)}  (eq. 9)`;
    }
    if (res) {
      setJumps(contU, res.continuityU, 'I');
      setJumps(contV, res.continuityV, 'J');
      const gap = cornerGap();
      cornerOut.set(`${sci(gap)} over ${(BI_SEGS_U + 1) * (BI_SEGS_V + 1)} corners`);
      cornerOut.el.dataset.value = String(gap);
      classOut.set(`(${BI_M}, ${BI_N}) → (${res.degreeU}, ${res.degreeV}), kept C${sup(b.r)}˒${sup(b.s)}${b.enforce ? '' : ' (not enforced)'}`);
    } else {
      cornerOut.set('—'); classOut.set('—');
    }
  }

  function draw() {
    if (!res) return;
    const s = state.surface;
    const at = (pts, iu, iv) => { const q = 3 * (iu * BI_NV + iv); return [pts[q], pts[q + 1], pts[q + 2]]; };
    const alongV = (pts, iu) => Array.from({ length: BI_NV }, (_, iv) => at(pts, iu, iv));
    const alongU = (pts, iv) => Array.from({ length: BI_NU }, (_, iu) => at(pts, iu, iv));
    try {
      view.setMesh('G*', res.mesh, { color: PALETTE.sky, isolines: { every: [5, 5], width: 1 } });
      view.setLines('joints', [alongV(res.points, 20), alongV(res.points, 40), alongU(res.points, 20)], { color: PALETTE.control, width: 4 });
      const cp = res.controlPoints, rows = res.rows, cols = res.cols, net = [];
      const P = (k, l) => [cp[3 * (k * cols + l)], cp[3 * (k * cols + l) + 1], cp[3 * (k * cols + l) + 2]];
      for (let k = 0; k < rows; k++) net.push(Array.from({ length: cols }, (_, l) => P(k, l)));
      for (let l = 0; l < cols; l++) net.push(Array.from({ length: rows }, (_, k) => P(k, l)));
      view.setLines('net', net, { color: PALETTE.second, width: 1.5, opacity: 0.85, visible: s.showNet });
      view.setPoints('b*', cp, { color: PALETTE.second, size: 7, pickable: false, visible: s.showNet });
      if (orig) view.setLines('G', Array.from({ length: 11 }, (_, j) => alongU(orig.points, 4 * j)), { color: PALETTE.ink, width: 1.5, opacity: 0.7, visible: s.showOriginal });
    } catch (e) { notify(e, 'error'); }
  }

  function update() {
    compute();
    refresh();
    draw();
  }

  return { controls, legend: legendEl, update, draw, result: () => res };
}
