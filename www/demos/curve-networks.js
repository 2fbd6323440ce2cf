// Demo "Curve networks" (Dagnino–Lamberti–Remogna §3–4, Kuklišová §7): one compatible network of C¹ quadratic curves and the four
// surfaces through it — the criss-cross surface S, the thin-plate tensor surface T, the Gordon boolean sum G and
// the spline-blended GB — side by side or overlaid, with the paper's norms ‖S−G‖, ‖S−T‖, ‖T−G‖ live while a
// network control point is dragged (the dependent control points follow so the network stays compatible).
// All values come from the wasm API (networkExample, networkFromFunction, networkRepair, networkSurfaces,
// crissCrossSurface, crissCrossCells); the modules in curve-networks/ compute, draw and explain:
//   presets.js  surfaces, colours, preset networks (and their code), the size limit, what a link may hold
//   compute.js  every wasm call (surfaces and numbers through the compute worker when slow)   draw.js  the 3D view
//   (surfaces, network, probe, triangulation, BB net)   steps.js  the stepper with its probe   explain.js  the text.
// This entry holds the demo contract (www/demos/README.md): meta, the declared state, mount (view, controls,
// dragging, wiring), snippet.

import { h, demoLayout, explanation } from '../lib/dom.js';
import { math, mathText } from '../lib/mathml.js';
import { stepper } from '../lib/stepper.js';
import { cite, correctionLink } from '../lib/papers-ref.js';
import { toggle, select, buttonGroup, button, table, group, row, slider, readout } from '../lib/controls.js';
import { View3D } from '../lib/view3d.js';
import { code, raw, snippetCode } from '../lib/snippet.js';
import { dataImport } from '../lib/data-import.js';
import { SURFACES, NAMES, PRESETS, PRESET_CODE, MAX_CELLS, overLimit, sub, clone, sanitize } from './curve-networks/presets.js';
import { networkModel } from './curve-networks/compute.js';
import { layoutOffsets, drawSurfaces, drawPartial, drawNetwork, drawProbe, drawTriangulation, drawCellNet } from './curve-networks/draw.js';
import { STEP_SEQ, probeVal, probeTex, booleanSteps } from './curve-networks/steps.js';
import { explanationContent, whySGContent } from './curve-networks/explain.js';

export { MAX_CELLS };

export const meta = {
  id: 'curve-networks',
  title: 'Curve networks',
  summary: 'Drag a curve of a network: the criss-cross, thin-plate, Gordon and spline-blended surfaces through it, and how far apart they are.',
  paper: `${cite('004', '§3–4.3, eqs. (13), (35)–(40)')}; ${cite('000', '§7 eq. (4)')}`,
};

export function defaults() {
  return {
    preset: 'paper',
    network: null,          // the edited network { u, v, P, Q } (null: the preset's)
    show: { S: true, T: false, G: true, GB: false },
    layout: 'side',         // 'side' | 'overlay'
    colorBy: 'none',        // 'none' | 'SG' | 'ST' | 'TG' | 'SGB'
    components: false,      // the Gordon components L1, L2, Tg
    triangulation: false,   // the criss-cross triangulation on S
    cell: null,             // [a, b]: the BB net of that cell of S
    density: 40,
    step: -1,               // the stepper: −1 off, 0 L1, 1 L2, 2 L12 (= Tg), 3 G = L1 + L2 − L12, 4 + i: S summed up to row i
    view: null,
  };
}

/** @param {HTMLElement} root @param {import('../lib/host.js').DemoContext} ctx @returns {import('../lib/host.js').MountedDemo} */
export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);
  sanitize(state, defaults());

  const put = (ro, t) => { if (ro.get() !== t) ro.set(t); };   // readouts: the DOM only when the text changes

  // ---------- the viewer ----------
  const viewWrap = h('div', { class: 'cn-view' });
  L.plots.appendChild(viewWrap);
  const view = new View3D(viewWrap, { height: 460, ariaLabel: 'Surfaces through the curve network', locked: !!options.locked,
    onViewChange(v) { state.view = v; ctx.save(); } });
  view.canvas.splineView = view; // for tests and course authors' scripts
  view.canvas.dataset.plot = 'networks';
  const legend = h('p', { class: 'cn-legend', 'aria-live': 'polite' });
  // "Computing the surfaces… 1.2 s [Cancel]" while the worker takes over SHOW_MS (www/lib/compute-client.js)
  const busyLine = h('p', { class: 'cn-busy compute-line' });
  L.plots.append(busyLine, legend);

  // every wasm call and its results c = { net, result, c2, numbers, apiTime } (curve-networks/compute.js)
  const model = networkModel({ wasm, state, notify, demoId: meta.id, busyLine, onNumbers: () => showNumbers() });
  const { c, m, n, loadNetwork, compatibility } = model;
  const scale = () => Math.max(1, ...c.net.P.flat().concat(c.net.Q.flat()).map((p) => Math.max(...p.map(Math.abs))));

  // ---------- controls ----------
  const presetSel = select({ label: 'Network', value: state.preset, options: Object.entries(PRESETS).map(([value, p]) => ({ value, label: p.label })),
    onChange(v) { state.preset = v; state.network = null; state.cell = null; ctx.save(); loadNetwork(); refresh(true); } });
  const shows = SURFACES.map((k) => toggle({ label: NAMES[k], value: state.show[k], onChange(v) { state.show[k] = v; ctx.save(); refresh(state.layout === 'side'); } }));
  const layoutCtl = buttonGroup({ label: 'Layout', value: state.layout, options: [{ value: 'side', label: 'Side by side' }, { value: 'overlay', label: 'Overlaid' }],
    onChange(v) { state.layout = v; ctx.save(); refresh(true); } });
  const colorCtl = select({ label: 'Colour map', value: state.colorBy,
    options: [{ value: 'none', label: 'none' }, { value: 'SG', label: '|S − G| on S' }, { value: 'ST', label: '|S − T| on S' }, { value: 'TG', label: '|T − G| on T' }, { value: 'SGB', label: '|S − GB| on S' }],
    onChange(v) { state.colorBy = v; ctx.save(); refresh(); } });
  const compCtl = toggle({ label: 'Gordon components L1, L2, Tg', value: state.components, onChange(v) { state.components = v; ctx.save(); refresh(true); },
    hint: 'G = L1 + L2 − Tg (eq. (39)): two skinned surfaces and a tensor interpolant, drawn next to G.' });
  const triCtl = toggle({ label: 'Criss-cross triangulation on S', value: state.triangulation, onChange(v) { state.triangulation = v; ctx.save(); refresh(); } });
  const densityCtl = slider({ label: 'Tessellation', min: 8, max: 96, step: 8, value: state.density, format: (v) => `${v} × ${v}`,
    hint: 'Up to 96 × 96 samples per surface; fine tessellations of large networks are computed in the background (“Computing…”, with Cancel).',
    onChange(v) { state.density = v; ctx.save(); refresh(); } });
  const cellInfo = readout({ label: 'BB net of cell', value: '—' });
  // Theorem 3.2 with the paper's two free points of §4.1 (its Fig. 5): S = Σ Cᵢⱼ Bᵢⱼ from either set of control points
  const c11Out = readout({ label: 'S with C₁₁ = (1.5, 1.5, 32) against S with C₁₁ = (1, 0, 30), max difference' });
  c11Out.el.dataset.readout = 'c11';
  const clearCell = button({ label: 'Hide BB net', onClick() { state.cell = null; ctx.save(); refresh(); } });
  const resetBtn = button({ label: 'Reset network', onClick() { state.network = null; state.cell = null; ctx.save(); loadNetwork(); refresh(true); } });
  const c2Out = readout({ label: ['C2 residual ', math('\\max |\\varphi_r(v_s) - \\psi_s(u_r)|')], value: '' });
  // prose: the text ("400.9 ms (S, G at 40², norms on 57²)" on a slow machine) wraps between words; as one
  // unbreakable line it pushed the page 1 px wider than a 1280 px window
  const timeOut = readout({ label: 'API time (networkSurfaces)', value: '', prose: true });
  const norms = table({ caption: 'Distances on the paper\'s 57 × 57 grid (max over x, y, z)', columns: ['norm', 'value'], rows: [], digits: 6 });
  const why = h('div', { class: 'cn-why', role: 'note', hidden: true });
  // the paper's ‖S − G‖∞ claim against this network (correction-004-sg): the live norm from the wasm API
  const claimOut = readout({ label: 'Printed: ‖S − G‖∞ = 4.4·10⁻¹⁵ (S = G)' });
  claimOut.el.dataset.readout = 'claim-sg';
  const claimNote = h('p', { class: 'ctl-hint' }, '‖S − G‖∞ of the network on screen. The claim holds for the special class a(u) + b(v) + c·uv only (try “Separable”); drag a point to leave it. ', correctionLink('correction-004-sg', 'The correction'));
  L.controls.append(
    group('Network', presetSel.el, row(resetBtn.el), c2Out.el),
    group('Surfaces', ...shows.map((s) => s.el), layoutCtl.el, colorCtl.el, compCtl.el, densityCtl.el),
    group('Numbers', norms.el, claimOut.el, claimNote, why, timeOut.el),
    group('Criss-cross', triCtl.el, cellInfo.el, row(clearCell.el), c11Out.el,
      h('p', { class: 'ctl-hint' }, 'The control points Cᵢⱼ of S depend on the free point C₁₁ (eq. (26)); S does not (Theorem 3.2). Both sums are evaluated by the wasm core on a 17 × 17 grid.')),
  );
  // "Use my data" (www/lib/data-import.js): your network { u, v, P, Q } (JSON; repaired when not compatible)
  if (!options.locked) L.controls.append(group('Your data', dataImport({ kind: 'network', label: 'Use my network', apply: 'Use this network',
    hint: `Paste JSON { u, v, P, Q } (or this demo’s JSON export), or drop a .json file here. Up to ${MAX_CELLS} × ${MAX_CELLS} cells (${MAX_CELLS + 1} curves each way); large networks are computed in the background.`, onData(nw) {
    const why = overLimit(nw);
    if (why) throw Object.assign(new Error(why), { field: 'network', kind: 'too-many' });
    compatibility(nw); // the API judges the shapes first (its Error names the field); loadNetwork repairs
    state.network = nw; state.cell = null; loadNetwork(); refresh(true); ctx.save();
  } }).el));

  // ---------- drawing ----------
  // where each surface is drawn: [dx, dy] (draw.js layoutOffsets)
  let offsets = {};
  function drawn() {
    const names = SURFACES.filter((k) => state.show[k]);
    return names.length ? names : ['S'];
  }

  // While a point is dragged, a frame builds only the surfaces on screen (networkSurfaces with norms: false) and
  // touches no text: the numbers (the four norms on the 57² grid from surfaceDifferences, the C2 residual, the
  // claim, the API time) follow in a task after the frame (compute.js laterNorms). On release and on every other
  // change they are computed with the surfaces and shown at once. In the worker the control points follow the
  // pointer at once, the surfaces as soon as they are computed.
  function refresh(refit = false, { dragging = false } = {}) {
    const stepping = state.step >= 0, sMode = state.step >= 4;
    // stepping through the Boolean sum: L1, then L2, then L12 (Tg), then G, side by side, the current one opaque;
    // then S = Σ C_ij B_ij summed row by row (the partial sum 'P' next to the core's S)
    const names = sMode ? ['S'] : stepping ? STEP_SEQ.slice(0, state.step + 1) : drawn();
    const comps = !stepping && state.components ? ['L1', 'L2', 'Tg'] : [];
    const colorBy = !stepping && state.colorBy !== 'none' ? state.colorBy : undefined;
    const surfaces = /** @type {import('../../types/splinelab.js').NetworkSurfaceName[]} */ (names.concat(comps));
    const where = model.computeSurfaces({ surfaces, colorBy, norms: !dragging }, () => draw(refit, { dragging, stepping, sMode, names, comps, colorBy }));
    // the control points follow the pointer now (the surfaces when they are computed)
    if (where === 'worker' && c.result && dragging) showNetwork(lastNames);
  }
  let lastNames = [];
  function draw(refit, { dragging, stepping, sMode, names, comps, colorBy }) {
    offsets = layoutOffsets(c.net, state, sMode ? ['P', 'S'] : names, comps, stepping);
    // surfaces no longer drawn go; the others are replaced in place (the viewer reuses their GPU buffers)
    const keep = new Set(names.concat(comps));
    if (sMode) keep.add('P');
    for (const id of [...SURFACES, 'L1', 'L2', 'Tg', 'P']) if (!keep.has(id)) view.remove(`surf-${id}`);
    if (sMode) drawPartial(view, state, c, offsets, model.partialSum(state.step - 4));
    drawSurfaces(view, state, c, offsets, { stepping, sMode, names, comps, colorBy, stepName: STEP_SEQ[state.step] });
    lastNames = sMode ? ['P', 'S'] : names.concat(comps);
    showNetwork(lastNames);
    drawProbe(view, sMode ? ['P', 'S'] : stepping ? names : [], offsets, (k) => probeVal(k, state, c, model));
    if (!dragging || stepping) steps.refresh();   // off, the panel only counts the steps: a drag does not change that
    showTriangulation();
    showCell();
    const tex = () => probeTex(state, c.net);
    if (sMode) {
      const i = state.step - 4;
      legend.replaceChildren('Left: the partial sum ', math(`\\sum_{i \\le ${i}} \\sum_j C_{ij} B_{ij}`), '; right (faded): the core’s S. The black point is the probe ', math(tex()), '.');
    } else if (stepping) {
      legend.replaceChildren('Boolean sum, left to right: ', ...names.flatMap((k, i) => [i ? ', ' : '', math(k === 'Tg' ? 'L_{12}' : k.replace(/^L(\d)$/, 'L_$1')), k === STEP_SEQ[state.step] ? ' (this step)' : '']),
        '. The black point is the probe ', math(tex()), ' whose values the formula uses.');
    } else setText(legend, names.concat(comps).map((k) => `${k}: ${k === 'L1' ? 'L1 (skin of φᵣ)' : k === 'L2' ? 'L2 (skin of ψₛ)' : k === 'Tg' ? 'Tg (interpolates Iᵣₛ)' : NAMES[k]}`).join(' · ')
      + (state.layout === 'side' ? '  (left to right)' : ''));
    if (refit || !fitted) { fitted = true; if (state.view && !refit) view.setView(state.view); else view.fit(); }
  }
  let fitted = false;
  const setText = (el, t) => { if (el.childNodes.length !== 1 || el.textContent !== t) el.textContent = t; };

  // ---------- the Boolean sum, step by step (curve-networks/steps.js) ----------
  let ready = false;   // the stepper must not clamp the step from the link before the network is loaded
  const steps = stepper({
    title: 'The Boolean sum and S, step by step',
    // (plain text: mathText would turn the hyphen of “criss-cross” into a minus)
    hint: `${mathText('L_1')}, then ${mathText('L_2')}, then ${mathText('L_{12}')}, then ${mathText('G = L_1 + L_2 - L_{12}')}; then the criss-cross surface ${mathText('S = \\sum C_{ij} B_{ij}')} summed row by row. Values at one probe point.`,
    steps: () => booleanSteps(state, c, model),
    get: () => state.step,
    set(i) { if (!ready) return; state.step = i; ctx.save(); refresh(true); },
  });

  function showNetwork(names) {
    drawNetwork(view, c, offsets, names, { locked: options.locked, onDrag });
  }

  // dragging: move the point, let networkRepair recompute the dependent control points, recompute everything
  let pending = null, raf = 0;
  function onDrag(kind, index, pos, phase) {
    const cols = kind === 'P' ? n() + 2 : m() + 2;
    const a = Math.floor(index / cols), b = index % cols;
    pending = { kind, a, b, pos, phase };
    if (!raf) raf = requestAnimationFrame(applyDrag);
    if (phase === 'end') { cancelAnimationFrame(raf); applyDrag(); }
  }
  function applyDrag() {
    raf = 0;
    if (!pending) return;
    const { kind, a, b, pos, phase } = pending;
    pending = null;
    if (!model.moveControlPoint(kind, a, b, pos)) return;
    refresh(false, { dragging: phase !== 'end' });
    if (phase === 'end') { state.network = clone(c.net); ctx.save(); }
  }

  function showTriangulation() {
    if (!state.triangulation || !c.result.surfaces.S) { view.remove('tri'); return; }
    // grid lines and both diagonals of every cell, lifted onto S (sampled with crissCrossSurface)
    const pieces = model.triangulation();
    if (pieces) drawTriangulation(view, pieces, offsets);
  }

  // BB net of one cell of S: 13 ordinates (crissCrossCells), four quadratic triangles
  function showCell() {
    const none = () => { view.remove('bb-net'); view.remove('bb-pts'); put(cellInfo, '— (click S)'); };
    if (!state.cell) { none(); return; }
    const [a, b] = state.cell;
    if (a < 1 || a > m() || b < 1 || b > n()) { state.cell = null; none(); return; }
    try {
      drawCellNet(view, model.cellOrdinates(), a, b, n(), offsets);
      put(cellInfo, `[u${sub(a - 1)}, u${sub(a)}] × [v${sub(b - 1)}, v${sub(b)}] — 13 ordinates`);
    } catch (e) { notify(e, 'error'); }
  }
  view.onPick((e) => {
    if (e.kind !== 'surface' || e.id !== 'surf-S') return;
    // grid indices → (u, v) → the cell (bookkeeping on the breakpoints)
    const net = c.net, N = state.density - 1;
    const u = net.u[0] + (net.u[m()] - net.u[0]) * e.iu / N, v = net.v[0] + (net.v[n()] - net.v[0]) * e.iv / N;
    const a = Math.min(m(), Math.max(1, net.u.findIndex((x) => x > u) === -1 ? m() : net.u.findIndex((x) => x > u)));
    const b = Math.min(n(), Math.max(1, net.v.findIndex((x) => x > v) === -1 ? n() : net.v.findIndex((x) => x > v)));
    state.cell = [a, b]; ctx.save(); showCell();
  });

  let whyBuilt = false;
  function showNumbers() {
    put(c2Out, c.c2.toExponential(2));
    if (c.numbers) { const { d, same } = c.numbers.c11; put(c11Out, `${d.toExponential(1)}: ${same ? 'the same surface' : 'different surfaces'}`); }
    put(timeOut, c.apiTime);
    const N = c.result.norms;
    if (!N) return;   // coming after the frame (compute.js laterNorms)
    const rows = [['‖S − G‖∞', N.SG], ['‖S − T‖∞', N.ST], ['‖T − G‖∞', N.TG], ['‖S − GB‖∞', N.SGB]].map(([k, v]) => [k, v.toExponential(4)]);
    // the table's numbers in place (same rows, same order)
    const tds = norms.el.querySelectorAll('tbody td');
    if (tds.length !== rows.length) norms.set(rows);
    else rows.forEach((r, k) => { if (tds[k].textContent !== r[1]) tds[k].textContent = r[1]; });
    const special = N.SG <= 1e-12 * scale();
    put(claimOut, `here ${N.SG.toExponential(2)}: ${special ? 'holds' : 'fails'}`);
    if (why.hidden !== !special) why.hidden = !special;
    if (whyBuilt) return;
    whyBuilt = true;
    why.replaceChildren(...whySGContent());
  }

  explanation(L.explain, explanationContent(meta.paper));

  L.controls.append(group('Gordon surface, step by step', steps.el));
  loadNetwork();
  ready = true;
  refresh(false);
  return {
    destroy() { steps.destroy(); cancelAnimationFrame(raf); model.destroy(); view.destroy(); },
    // idle warm-up (www/lib/warm.js): a point drag's networkRepair with the current network (result dropped) and
    // its last frame, the release: the surfaces on screen with their norms, the drawing (same pixels and numbers;
    // no save). A drag's frames in between skip the norms only.
    warm() { if (pending || raf || !c.net) return; model.warmRepair(); refresh(false); },
    // Export row (www/demos/README.md): the network, the norms and every computed surface as OBJ / CSV
    exports() {
      const { result } = c;
      if (!result) return {};
      const keys = Object.keys(result.surfaces || {});
      return {
        // (the norms come with every surfaces result at rest; during a drag they follow, and exports() — called by the
        // Export row after every save — computes nothing: null until they are in)
        json: { network: c.net, norms: result.norms ?? null, c2: c.c2 },
        obj: keys.filter((k) => result.surfaces[k].mesh).map((k) => ({ name: `surface_${k}`, mesh: result.surfaces[k].mesh })),
        csv: keys.length && result.surfaces[keys[0]].mesh ? { points: result.surfaces[keys[0]].mesh.positions, dim: 3 } : undefined,
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------
export function snippet(state) {
  const names = SURFACES.filter((k) => state.show[k]);
  const surfaces = (names.length ? names : ['S']).concat(state.components ? ['L1', 'L2', 'Tg'] : []);
  const net = state.network ? code`
    // your network: u_r, v_s, the curves P[r][j] (u = u_r) and Q[s][i] (v = v_s), points [x, y, z]
    let network = ${state.network};
    // an edited network is repaired to satisfy the compatibility conditions (C2) when needed
    if (!sl.networkCompatibility({ network }).compatible) network = sl.networkRepair({ network }).network;`
    : code`
    // the curve network ${raw(JSON.stringify(state.preset))}: u_r, v_s and the curves P[r][j] (u = u_r), Q[s][i] (v = v_s)
    const network = ${raw(PRESET_CODE[state.preset] || PRESET_CODE.paper)};`;
  return snippetCode(meta.title, net + '\n' + code`
    // S (criss-cross), T (thin-plate), G (Gordon), GB (spline-blended): meshes, and their distances on a 57² grid
    const result = sl.networkSurfaces({ network, samplesU: ${state.density}, samplesV: ${state.density}, surfaces: ${surfaces}${raw(state.colorBy !== 'none' ? `, colorBy: '${state.colorBy}'` : '')}, curveSamples: 48 });
    const compatibility = sl.networkCompatibility({ network });
    return { network, surfaces: result.surfaces, norms: result.norms, c2: compatibility.c2 };
  `);
}
