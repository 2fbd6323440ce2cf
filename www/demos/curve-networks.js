// Demo "Curve networks" (Dagnino–Lamberti–Remogna §3–4, Kuklišová §7): one compatible network of C¹ quadratic curves and the four
// surfaces through it — the criss-cross surface S, the thin-plate tensor surface T, the Gordon boolean sum G and
// the spline-blended GB — side by side or overlaid, with the paper's norms ‖S−G‖, ‖S−T‖, ‖T−G‖ live while a
// network control point is dragged (the dependent control points follow so the network stays compatible).
// All values come from the wasm API (networkExample, networkFromFunction, networkRepair, networkSurfaces,
// crissCrossSurface, crissCrossCells); this module only draws and handles input.

import { h, demoLayout, explanation, fmt } from '../lib/dom.js';
import { math, mathText } from '../lib/mathml.js';
import { stepper } from '../lib/stepper.js';
import { cite, correctionLink } from '../lib/papers-ref.js';
import { toggle, select, buttonGroup, button, table, group, row, slider, readout } from '../lib/controls.js';
import { View3D } from '../lib/view3d.js';
import { computeClient } from '../lib/compute-client.js';

export const meta = {
  id: 'curve-networks',
  title: 'Curve networks',
  summary: 'Drag a curve of a network: the criss-cross, thin-plate, Gordon and spline-blended surfaces through it, and how far apart they are.',
  paper: `${cite('004', '§3–4.3, eqs. (13), (35)–(40)')}; ${cite('000', '§7 eq. (4)')}`,
};

const SURFACES = ['S', 'T', 'G', 'GB'];
const NAMES = { S: 'S (criss-cross)', T: 'T (thin-plate)', G: 'G (Gordon)', GB: 'GB (spline-blended)' };
// Okabe–Ito colours, readable on a projector
const COLOURS = { S: '#0072B2', T: '#E69F00', G: '#009E73', GB: '#CC79A7', L1: '#56B4E9', L2: '#D55E00', Tg: '#999999' };
const U3 = [0, 1 / 3, 2 / 3, 1];
const U6 = [0, 0.2, 0.4, 0.6, 0.8, 1];
const upTo = (k) => Array.from({ length: k + 1 }, (_, i) => i);   // the breakpoints 0, 1, …, k

// The paper's grids (m, n, the breakpoints uᵢ = i, vⱼ = j) with curves of our own: the paper prints no control
// points of its networks (its Figs. 4, 6, 9), so the shapes are ours; the labels say so.
const F18 = (u, v) => [u, v, 1.5 * Math.sin(Math.PI * u / 6) * Math.cos(Math.PI * (v - 2) / 6) + 0.25 * v];
const F54 = (u, v) => [u, v, 3.5 - 0.22 * (u - 2.5) ** 2 - 0.3 * (v - 2) ** 2 + 0.15 * u * Math.sin(v)];

/** Preset networks: wasm examples or networks from a formula (networkFromFunction). */
const PRESETS = {
  paper: { label: 'm = n = 3 on [0,1]², §4.2 grid', build: (w) => w.networkFromFunction({ u: U3, v: U3, f: (u, v) => [u, v, 0.45 * Math.sin(Math.PI * u) * Math.sin(Math.PI * v) + 0.35 * u * v * v] }) },
  'paper-18x4': { label: 'm = 18, n = 4, §4.1 grid', build: (w) => w.networkFromFunction({ u: upTo(18), v: upTo(4), f: F18 }) },
  'three-sided': { label: '3-sided facets (§4.3, m = 5, n = 3)', build: (w) => w.networkExample({ name: 'three-sided' }) },
  'paper-5x4': { label: 'm = 5, n = 4, §4.3 grid', build: (w) => w.networkFromFunction({ u: upTo(5), v: upTo(4), f: F54 }) },
  separable: { label: 'Separable (S = G exactly)', build: (w) => w.networkExample({ name: 'separable' }) },
  dome: { label: 'Dome, m = n = 5', build: (w) => w.networkFromFunction({ u: U6, v: U6, f: (u, v) => [u, v, 0.6 - 0.9 * ((u - 0.5) ** 2 + (v - 0.5) ** 2) + 0.25 * u * (1 - v) * Math.cos(3 * v)] }) },
  dome10: { label: 'Dome 10 × 10 (speed)', build: (w) => w.networkExample({ name: 'dome10' }) },
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

/** Index (into the flat xyz array) of the vertex with the largest z. */
function highest(pos) {
  let top = 0;
  for (let i = 2; i < pos.length; i += 3) if (pos[i] > pos[top + 2]) top = i - 2;
  return top;
}

// The largest network the demo takes (issue 26, limits that say so): 30 × 30 cells, i.e. 31 curves φᵣ and 31 curves
// ψₛ. Chosen from measurements: its state (the network, ~57 KB of JSON) still fits in a link (www/lib/state.js
// decodes at most 64 KB; 40 × 40 is ~100 KB), and on the main thread its drag stays small (networkRepair, the
// control points: ~10 ms) while the surfaces and numbers go to the worker (30 × 30 at 96², four surfaces:
// 25–50 ms per frame on a loaded 2-core machine, which would drop frames here). Larger networks are refused with
// a message naming the field; nothing is cut down silently.
export const MAX_CELLS = 30;
/** null, or why the network `nw` is over the limit (a sentence naming the field). */
function overLimit(nw) {
  const m = nw.u.length - 1, n = nw.v.length - 1;
  if (m <= MAX_CELLS && n <= MAX_CELLS) return null;
  return `network: at most ${MAX_CELLS} × ${MAX_CELLS} cells (${MAX_CELLS + 1} values in u and in v); this one has ${m} × ${n} cells (u has ${m + 1} values, v ${n + 1}). Larger networks would not fit in a link, and a drag would fall behind.`;
}

const sub = (i) => String(i).replace(/\d/g, (d) => '₀₁₂₃₄₅₆₇₈₉'[d]);
const isNet = (n) => n && Array.isArray(n.u) && Array.isArray(n.v) && Array.isArray(n.P) && Array.isArray(n.Q);
const clone = (n) => JSON.parse(JSON.stringify(n));

/** @param {HTMLElement} root @param {import('../lib/host.js').DemoContext} ctx @returns {import('../lib/host.js').MountedDemo} */
export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);

  // ---------- state ----------
  function sanitize() {
    const d = defaults();
    if (!PRESETS[state.preset]) state.preset = d.preset;
    if (state.network !== null && !isNet(state.network)) state.network = null;
    if (!state.show || typeof state.show !== 'object') state.show = { ...d.show };
    for (const k of SURFACES) state.show[k] = !!state.show[k];
    if (!['side', 'overlay'].includes(state.layout)) state.layout = d.layout;
    if (!['none', 'SG', 'ST', 'TG', 'SGB'].includes(state.colorBy)) state.colorBy = 'none';
    state.components = !!state.components;
    state.triangulation = !!state.triangulation;
    if (!(Array.isArray(state.cell) && state.cell.length === 2 && state.cell.every(Number.isInteger))) state.cell = null;
    if (!Number.isInteger(state.density) || state.density < 8 || state.density > 96) state.density = d.density;
    if (!Number.isInteger(state.step) || state.step < -1 || state.step > 40) state.step = -1;
  }
  sanitize();

  let net = null;        // the current network (plain object)
  let result = null;     // the last networkSurfaces result
  let c2 = 0;
  function loadNetwork() {
    try {
      const why = state.network && overLimit(state.network);
      if (why) throw Object.assign(new Error(why), { field: 'network', kind: 'too-many' });
      net = state.network ? clone(state.network) : PRESETS[state.preset].build(wasm);
      c2 = wasm.networkCompatibility({ network: net }).c2;
      if (state.network && !wasm.networkCompatibility({ network: net }).compatible) {
        net = wasm.networkRepair({ network: net }).network;
      }
    } catch (e) {
      notify(e, 'error');
      state.network = null;
      net = PRESETS[state.preset].build(wasm);
    }
  }
  const m = () => net.u.length - 1;
  const n = () => net.v.length - 1;
  const scale = () => Math.max(1, ...net.P.flat().concat(net.Q.flat()).map((p) => Math.max(...p.map(Math.abs))));

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
  const timeOut = readout({ label: 'API time (networkSurfaces)', value: '' });
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
    const c = wasm.networkCompatibility({ network: nw }); // the API judges the shapes first (its Error names the field)
    state.network = nw; state.cell = null; loadNetwork(); refresh(true); ctx.save();
    return c;
  } }).el));

  // ---------- drawing ----------
  // where each surface is drawn: [dx, dy]. Side by side: a row along x (the network's width + a gap apart);
  // overlaid: all at the network. The Gordon components always go in a second row, in front.
  let offsets = {};
  function layoutOffsets(names, comps, forceSide = false) {
    const pts = net.P.flat().concat(net.Q.flat());
    const extent = (k) => { const xs = pts.map((p) => p[k]); return (Math.max(...xs) - Math.min(...xs)) || 1; };
    const w = extent(0) * 1.25, d = extent(1) * 1.35;
    offsets = {};
    names.forEach((k, i) => { offsets[k] = [state.layout === 'side' || forceSide ? i * w : 0, 0]; });
    comps.forEach((k, i) => { offsets[k] = [i * w, -d]; });
  }
  const shift = (flat, off = [0, 0]) => {
    const [dx, dy] = off;
    if (!dx && !dy) return flat;
    const a = new Float32Array(flat);   // (a typed-array copy: Float32Array.from goes through the iterator, 10× slower)
    for (let i = 0; i < a.length; i += 3) { a[i] += dx; a[i + 1] += dy; }
    return a;
  };
  const shifted = (mesh, off) => ({ ...mesh, positions: shift(mesh.positions, off) });

  function drawn() {
    const names = SURFACES.filter((k) => state.show[k]);
    return names.length ? names : ['S'];
  }

  const STEP_SEQ = ['L1', 'L2', 'Tg', 'G'];
  // While a point is dragged, a frame builds only the surfaces on screen (networkSurfaces with norms: false) and
  // touches no text: the numbers (the four norms on the 57² grid from surfaceDifferences, the C2 residual, the
  // claim, the API time) follow in a task after the frame, at most every NUMBERS_MS (readable while they move;
  // each text change costs a style and layout pass). On release and on every other change they are computed
  // with the surfaces and shown at once.
  //
  // Off the main thread (issue 26; www/lib/compute-client.js): the surfaces and the numbers are two lists of wasm
  // calls, each run here when the same size of work was measured under SYNC_MS (the small networks of the presets:
  // unchanged, synchronous) and in a worker otherwise (large networks, fine tessellations). In the worker the
  // latest request wins while dragging; the control points follow the pointer at once, the surfaces as soon as
  // they are computed. Two clients (two workers), so that a numbers request never supersedes a surfaces request.
  const NUMBERS_MS = 200;
  const surfacesCC = computeClient({ demoId: meta.id, wasm, status: busyLine, label: 'Computing the surfaces' });
  const numbersCC = computeClient({ demoId: meta.id, wasm, status: busyLine, label: 'Computing the numbers' });
  let normsTimer = 0, lastNumbers = 0, apiTime = '';
  /** The estimated time (ms) of a request never measured (a new size): per sample of a surface and per cell of the
   * network, with the norms (57² samples of four surfaces) or without; the rates are from networkSurfaces and
   * surfaceDifferences measured in Node (2 cores, loaded: 96² × 4 surfaces ≈ 25 ms, norms of 50 × 50 cells ≈ 20 ms). */
  const costMs = ({ samples = 0, norms = false }) => 7e-4 * samples + (norms ? 5 + 8e-3 * m() * n() : 2e-3 * m() * n());
  let numbers = null;   // { c2, c11: { d, same } } of the network on screen (null: coming)
  /** The wasm calls of the numbers: the C2 residual, S with the two C₁₁ of Theorem 3.2 (and the norms, when the
   * surfaces came without them). @returns {import('../lib/compute-client.js').WasmCall[]} */
  function numberCalls(withNorms) {
    /** @returns {import('../lib/compute-client.js').WasmCall} */
    const sum = (C11) => ({ fn: 'crissCrossSurface', args: { network: net, C11, evaluate: 'sum', samplesU: 17, samplesV: 17 } });
    return [{ fn: 'networkCompatibility', args: { network: net } }, sum([1.5, 1.5, 32]), sum([1, 0, 30]),
      ...(withNorms ? [/** @type {const} */ ({ fn: 'surfaceDifferences', args: { network: net, samples: 57 } })] : [])];
  }
  /** Computes the numbers of the network on screen (here or in the worker), then shows them. */
  function computeNumbers(withNorms) {
    const forNet = net, forResult = result, calls = numberCalls(withNorms);
    const key = `numbers ${m()}×${n()}${withNorms ? ' norms' : ''}`;
    const apply = (r) => {
      if (!r || forNet !== net) return;   // superseded, cancelled, or the network moved on (a newer request follows)
      c2 = r[0].c2;
      numbers = { c11: c11Difference(r[1].points, r[2].points) };
      if (withNorms && forResult === result) result.norms = r[3];
      showNumbers();
    };
    if (numbersCC.runsHere(key, costMs({ norms: withNorms }))) {
      try { apply(numbersCC.runHere(calls, key)); } catch (e) { notify(e, 'error'); }
    } else numbersCC.run(calls, { key }).then(apply, (e) => notify(e, 'error'));
  }
  function laterNorms() {
    if (normsTimer) return;
    normsTimer = setTimeout(() => {
      normsTimer = 0;
      if (!result || result.norms) return;
      lastNumbers = performance.now();
      computeNumbers(true);
    }, Math.max(0, NUMBERS_MS - (performance.now() - lastNumbers)));
  }
  function refresh(refit = false, { dragging = false } = {}) {
    const stepping = state.step >= 0, sMode = state.step >= 4;
    // stepping through the Boolean sum: L1, then L2, then L12 (Tg), then G, side by side, the current one opaque;
    // then S = Σ C_ij B_ij summed row by row (the partial sum 'P' next to the core's S)
    const names = sMode ? ['S'] : stepping ? STEP_SEQ.slice(0, state.step + 1) : drawn();
    const comps = !stepping && state.components ? ['L1', 'L2', 'Tg'] : [];
    const colorBy = !stepping && state.colorBy !== 'none' ? state.colorBy : undefined;
    const norms = !dragging;
    const surfaces = /** @type {import('../../types/splinelab.js').NetworkSurfaceName[]} */ (names.concat(comps));
    /** @type {import('../lib/compute-client.js').WasmCall[]} */
    const calls = [{ fn: 'networkSurfaces', args: { network: net, samplesU: state.density, samplesV: state.density, surfaces, colorBy, curveSamples: 48, norms } }];
    const key = `surfaces ${m()}×${n()} ${state.density}² ${surfaces.join('+')}${colorBy ? ` ${colorBy}` : ''}${norms ? ' norms' : ''}`;
    const forNet = net;
    const done = (r, dt) => {
      if (!r) return;   // superseded by a newer request, or cancelled
      result = r[0];
      apiTime = `${fmt(dt, 1)} ms (${surfaces.join(', ')} at ${state.density}²${norms ? ', norms on 57²' : '; norms after the frame'})`;
      if (!norms) { result.norms = null; laterNorms(); }   // (the C2 residual too: it is only shown)
      draw(refit, { dragging, stepping, sMode, names, comps, colorBy });
      if (norms) computeNumbers(false);
    };
    if (surfacesCC.runsHere(key, costMs({ samples: state.density ** 2 * surfaces.length, norms }))) {
      let r;
      const t0 = performance.now();
      try { r = surfacesCC.runHere(calls, key); } catch (e) { notify(e, 'error'); return; }
      done(r, performance.now() - t0);
    } else {
      surfacesCC.run(calls, { key }).then((r) => done(r, surfacesCC.measured(key) ?? NaN), (e) => notify(e, 'error'));
      // the control points follow the pointer now (the surfaces when they are computed)
      if (result && dragging) drawNetwork(lastNames);
    }
  }
  let lastNames = [];
  function draw(refit, { dragging, stepping, sMode, names, comps, colorBy }) {
    layoutOffsets(sMode ? ['P', 'S'] : names, comps, stepping);
    // surfaces no longer drawn go; the others are replaced in place (the viewer reuses their GPU buffers)
    const keep = new Set(names.concat(comps));
    if (sMode) keep.add('P');
    for (const id of [...SURFACES, 'L1', 'L2', 'Tg', 'P']) if (!keep.has(id)) view.remove(`surf-${id}`);
    if (sMode) drawPartial();
    for (const k of names.concat(comps)) {
      const mesh = shifted(result.surfaces[k].mesh, offsets[k]);
      const mapped = colorBy && k === (colorBy === 'TG' ? 'T' : 'S') && result.colors;
      view.setMesh(`surf-${k}`, mesh, {
        color: COLOURS[k], isolines: { every: Math.max(1, Math.round(state.density / 8)) },
        opacity: sMode ? 0.3 : stepping ? (k === STEP_SEQ[state.step] ? 1 : 0.3) : state.layout === 'overlay' && names.length > 1 ? 0.7 : 1,
        colors: mapped ? result.colors : undefined, colormap: 'viridis', legend: mapped ? `|${colorBy === 'SGB' ? 'S − GB' : colorBy.split('').join(' − ')}|` : undefined,
        pickable: k === 'S',
      });
    }
    // a name tag above the highest vertex of each surface
    const tags = [], tagPos = [];
    for (const k of names.concat(comps)) {
      const pos = result.surfaces[k].mesh.positions, [dx, dy] = offsets[k];
      const top = highest(pos);
      tagPos.push(pos[top] + dx, pos[top + 1] + dy, pos[top + 2] * 1.08 + 0.02);
      tags.push(k);
    }
    if (state.layout === 'side' || comps.length || stepping) view.setPoints('tags', tagPos, { size: 3, color: '#333333', labels: tags.map((k) => (k === 'Tg' ? mathText('L_{12}') : mathText(k.replace(/^L(\d)$/, 'L_$1')))), pickable: false });
    else view.remove('tags');
    lastNames = sMode ? ['P', 'S'] : names.concat(comps);
    drawNetwork(lastNames);
    drawProbe(sMode ? ['P', 'S'] : stepping ? names : []);
    if (!dragging || stepping) steps.refresh();   // off, the panel only counts the steps: a drag does not change that
    drawTriangulation();
    drawCell();
    if (sMode) {
      const i = state.step - 4;
      legend.replaceChildren('Left: the partial sum ', math(`\\sum_{i \\le ${i}} \\sum_j C_{ij} B_{ij}`), '; right (faded): the core’s S. The black point is the probe ', math(probeTex()), '.');
    } else if (stepping) {
      legend.replaceChildren('Boolean sum, left to right: ', ...names.flatMap((k, i) => [i ? ', ' : '', math(k === 'Tg' ? 'L_{12}' : k.replace(/^L(\d)$/, 'L_$1')), k === STEP_SEQ[state.step] ? ' (this step)' : '']),
        '. The black point is the probe ', math(probeTex()), ' whose values the formula uses.');
    } else setText(legend, names.concat(comps).map((k) => `${k}: ${k === 'L1' ? 'L1 (skin of φᵣ)' : k === 'L2' ? 'L2 (skin of ψₛ)' : k === 'Tg' ? 'Tg (interpolates Iᵣₛ)' : NAMES[k]}`).join(' · ')
      + (state.layout === 'side' ? '  (left to right)' : ''));
    if (refit || !fitted) { fitted = true; if (state.view && !refit) view.setView(state.view); else view.fit(); }
  }
  let fitted = false;
  const setText = (el, t) => { if (el.childNodes.length !== 1 || el.textContent !== t) el.textContent = t; };

  // ---------- the Boolean sum, step by step ----------
  // The probe: the middle vertex of the u-major sample grid of networkSurfaces (the values come from the core).
  const probeIndex = () => { const N = state.density, iu = Math.floor(N / 2), iv = Math.floor(N / 2); return { iu, iv, i: iu * N + iv }; };
  const probeUV = () => {
    const { iu, iv } = probeIndex(), N = state.density - 1;
    return [net.u[0] + (net.u[m()] - net.u[0]) * iu / N, net.v[0] + (net.v[n()] - net.v[0]) * iv / N];
  };
  const probeTex = () => { const [u, v] = probeUV(); return `(u, v) = (${fmt(u, 3)}, ${fmt(v, 3)})`; };
  const probeVal = (k) => {
    if (k === 'P') { const P = partialSum(state.step - 4); const i = probeIndex().i; return P ? [P[3 * i], P[3 * i + 1], P[3 * i + 2]] : null; }
    const s = result && result.surfaces[k];
    if (!s) return null;
    const i = probeIndex().i;
    return [s.points[3 * i], s.points[3 * i + 1], s.points[3 * i + 2]];
  };
  function drawProbe(names) {
    if (!names.length) { view.remove('probe'); return; }
    const pos = [];
    for (const k of names) { const p = probeVal(k); if (p) pos.push(p[0] + offsets[k][0], p[1] + offsets[k][1], p[2]); }
    view.setPoints('probe', pos, { color: '#000000', size: 12, pickable: false, onTop: true });
  }
  const vec = (p) => (p ? `(${fmt(p[0], 3)}, ${fmt(p[1], 3)}, ${fmt(p[2], 3)})` : '?');
  // S = Σ C_ij B_ij (Lemma 3.1): the control points C_ij from crissCrossSurface, each B_ij sampled by
  // crissCrossBasis on the same u-major grid as networkSurfaces; the demo only adds the terms up, row by row, and
  // compares the full sum with the core's S.
  let terms = null;
  function crissCrossTerms() {
    const N = state.density, key = JSON.stringify([net.u, net.v, net.P, net.Q, N]);
    if (terms && terms.key === key) return terms;
    try {
      const C = wasm.crissCrossSurface({ network: net, atUV: [[net.u[0], net.v[0]]] }).controlPoints;
      const rows = m() + 2, cols = n() + 2, B = [];
      for (let i = 0; i < rows; i++) for (let j = 0; j < cols; j++) B.push(wasm.crissCrossBasis({ u: net.u, v: net.v, i, j, samplesU: N, samplesV: N }).values);
      terms = { key, C, B, rows, cols, N, partial: [] };
    } catch (e) { notify(e, 'error'); terms = null; }
    return terms;
  }
  /** Σ_{i' ≤ i} Σ_j C_i'j B_i'j on the grid (flat xyz), cached per row. */
  function partialSum(i) {
    const T = crissCrossTerms();
    if (!T || i < 0) return null;
    i = Math.min(i, T.rows - 1);
    if (T.partial[i]) return T.partial[i];
    const K = T.N * T.N, out = new Float64Array(3 * K);
    if (i > 0) out.set(partialSum(i - 1));
    for (let j = 0; j < T.cols; j++) {
      const b = T.B[i * T.cols + j], c = 3 * (i * T.cols + j);
      for (let q = 0; q < K; q++) { const w = b[q]; out[3 * q] += w * T.C[c]; out[3 * q + 1] += w * T.C[c + 1]; out[3 * q + 2] += w * T.C[c + 2]; }
    }
    T.partial[i] = out;
    return out;
  }
  function drawPartial() {
    const P = partialSum(state.step - 4), S = result.surfaces.S;
    if (!P || !S) return;
    const pos = Float32Array.from(P);
    const [dx, dy] = offsets.P;
    for (let q = 0; q < pos.length; q += 3) { pos[q] += dx; pos[q + 1] += dy; }
    view.setMesh('surf-P', { positions: pos, indices: S.mesh.indices }, { color: COLOURS.S, isolines: { every: Math.max(1, Math.round(state.density / 8)) } });
  }
  function sSteps() {
    const T = crissCrossTerms();
    if (!T || !result || !result.surfaces.S) return [];
    const { iu, iv, i: q } = probeIndex();
    void iu; void iv;
    const [u, v] = probeUV();
    const at = `(${fmt(u, 3)}, ${fmt(v, 3)})`;
    const S = result.surfaces.S.points;
    const out = [];
    let unity = 0;
    for (let i = 0; i < T.rows; i++) {
      const row = [0, 0, 0];
      for (let j = 0; j < T.cols; j++) {
        const b = T.B[i * T.cols + j][q], c = 3 * (i * T.cols + j);
        unity += b;
        for (let k = 0; k < 3; k++) row[k] += b * T.C[c + k];
      }
      const P = partialSum(i);
      const last = i === T.rows - 1;
      let dev = 0;
      if (last) for (let k = 0; k < P.length; k++) dev = Math.max(dev, Math.abs(P[k] - S[k]));
      out.push({
        label: `S assembled: row i = ${i} of the terms ${mathText('C_{ij} B_{ij}')} added`,
        tex: [
          `S^{(${i})} = S^{(${i - 1})} + \\sum_{j=0}^{${T.cols - 1}} C_{${i}j}\\, B_{${i}j}(u, v)`,
          `(u, v) = ${at}`,
          `\\sum_j C_{${i}j} B_{${i}j} = ${vec(row)}`,
          `S^{(${i})} = ${vec([P[3 * q], P[3 * q + 1], P[3 * q + 2]])}`,
          `\\sum_{i' \\le ${i}, j} B_{i'j} = ${fmt(unity, 4)}`,
          ...(last ? [`\\max_{\\text{grid}} |S^{(${i})} - S| = ${dev === 0 ? '0' : dev.toExponential(1)}`] : []),
        ],
        note: last
          ? `All ${T.rows} × ${T.cols} terms: the sum is the core’s S on the whole ${T.N} × ${T.N} grid, and the ${mathText('B_{ij}')} sum to 1.`
          : `The ${mathText(`B_{${i}j}`)} of row ${i} are zero away from ${mathText(`u \\approx \\xi_${i}`)}: the partial sum changes only there.`,
      });
    }
    return out;
  }
  function booleanSteps() {
    if (!net) return [];
    const [u, v] = probeUV();
    const at = `(${fmt(u, 3)}, ${fmt(v, 3)})`;
    const L1 = probeVal('L1'), L2 = probeVal('L2'), T = probeVal('Tg'), G = probeVal('G');
    const z = (p) => (p ? fmt(p[2], 4) : '?');
    const zs = (p) => (p && p[2] < 0 ? `(${fmt(p[2], 4)})` : z(p));
    return [
      { label: 'L1, the surface skinned through the curves φᵣ (v-curves)',
        tex: ['L_1(u_r, v) = \\varphi_r(v), \\quad r = 0, \\ldots, m', `(u, v) = ${at}`, `L_1 = ${vec(L1)}`],
        note: `L1 interpolates the ${m() + 1} curves φᵣ on the lines u = uᵣ, but not the ψₛ.` },
      { label: 'L2, the surface skinned through the curves ψₛ (u-curves)',
        tex: ['L_2(u, v_s) = \\psi_s(u), \\quad s = 0, \\ldots, n', `(u, v) = ${at}`, `L_2 = ${vec(L2)}`],
        note: `L2 interpolates the ${n() + 1} curves ψₛ on the lines v = vₛ.` },
      { label: 'L12, the tensor surface through the intersection points Iᵣₛ',
        tex: ['L_{12}(u_r, v_s) = I_{rs} = \\varphi_r(v_s) = \\psi_s(u_r)', `(u, v) = ${at}`, `L_{12} = ${vec(T)}`],
        note: `L12 (Tg in the other controls) interpolates only the ${(m() + 1) * (n() + 1)} points Iᵣₛ; on the network lines it equals what L1 and L2 have in common.` },
      { label: 'G = L1 + L2 − L12, the Gordon surface',
        tex: ['G = L_1 + L_2 - L_{12} \\qquad (39)', `(u, v) = ${at}`, `G_z = ${z(L1)} + ${zs(L2)} - ${zs(T)} = ${z(G)}`, `G = ${vec(G)}`],
        note: 'On u = uᵣ: L1 = φᵣ and L2 = L12, so G = φᵣ; likewise on v = vₛ. G interpolates the whole network.' },
      // then the criss-cross surface, assembled from its B_ij (computed only once the stepper gets there)
      ...(state.step >= 3 ? sSteps() : Array.from({ length: m() + 2 }, (_, i) => ({ label: `S assembled: row i = ${i} of the terms ${mathText('C_{ij} B_{ij}')} added`, tex: ['S = \\sum_{i=0}^{m+1} \\sum_{j=0}^{n+1} C_{ij} B_{ij}(u, v)'] }))),
    ];
  }
  let ready = false;   // the stepper must not clamp the step from the link before the network is loaded
  const steps = stepper({
    title: 'The Boolean sum and S, step by step',
    // (plain text: mathText would turn the hyphen of “criss-cross” into a minus)
    hint: `${mathText('L_1')}, then ${mathText('L_2')}, then ${mathText('L_{12}')}, then ${mathText('G = L_1 + L_2 - L_{12}')}; then the criss-cross surface ${mathText('S = \\sum C_{ij} B_{ij}')} summed row by row. Values at one probe point.`,
    steps: booleanSteps,
    get: () => state.step,
    set(i) { if (!ready) return; state.step = i; ctx.save(); refresh(true); },
  });

  function drawNetwork(names) {
    const curves = [...result.curves.phi, ...result.curves.psi];
    const lines = [];
    for (const k of names) for (const c of curves) lines.push(shift(c, offsets[k]));
    view.setLines('network', lines, { color: '#111111', width: 2.5 });
    // control points of the first drawn surface's copy: P (v-curves φ_r) and Q (u-curves ψ_s)
    const [dx, dy] = offsets[names[0]] || [0, 0];
    const P = [], Q = [];
    net.P.forEach((row) => row.forEach((p) => { P.push(p[0] + dx, p[1] + dy, p[2]); }));
    net.Q.forEach((row) => row.forEach((p) => { Q.push(p[0] + dx, p[1] + dy, p[2]); }));
    const drag = (kind) => (index, pos, phase) => onDrag(kind, index, [pos[0] - dx, pos[1] - dy, pos[2]], phase);
    view.setPoints('net-P', P, { color: '#D55E00', size: 11, draggable: !options.locked, onDrag: drag('P'), labels: undefined });
    view.setPoints('net-Q', Q, { color: '#0072B2', size: 9, draggable: !options.locked, onDrag: drag('Q') });
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
    const edited = clone(net);
    if (kind === 'P') edited.P[a][b] = pos; else edited.Q[a][b] = pos;
    try {
      const r = wasm.networkRepair({ network: edited, edited: kind === 'P' ? { kind, r: a, j: b } : { kind, s: a, i: b } });
      net = r.network;
    } catch (e) { notify(e, 'error'); return; }
    refresh(false, { dragging: phase !== 'end' });
    if (phase === 'end') { state.network = clone(net); ctx.save(); }
  }

  function drawTriangulation() {
    if (!state.triangulation || !result.surfaces.S) { view.remove('tri'); return; }
    // grid lines and both diagonals of every cell, lifted onto S (sampled with crissCrossSurface)
    const segs = [];
    const k = 12;
    const seg = (u0, v0, u1, v1) => { const at = []; for (let i = 0; i <= k; i++) at.push([u0 + (u1 - u0) * i / k, v0 + (v1 - v0) * i / k]); return at; };
    const U = net.u, V = net.v;
    for (let a = 1; a <= m(); a++) for (let b = 1; b <= n(); b++) {
      segs.push(seg(U[a - 1], V[b - 1], U[a], V[b]), seg(U[a - 1], V[b], U[a], V[b - 1]));
    }
    for (const u of U) segs.push(seg(u, V[0], u, V[n()]));
    for (const v of V) segs.push(seg(U[0], v, U[m()], v));
    try {
      const r = wasm.crissCrossSurface({ network: net, atUV: segs.flat() });
      const pts = r.points, lines = [];
      for (let s = 0; s < segs.length; s++) lines.push(shift(pts.subarray(3 * s * (k + 1), 3 * (s + 1) * (k + 1)), offsets.S));
      view.setLines('tri', lines, { color: '#f5f5f5', width: 1.2, opacity: 0.85 });
    } catch (e) { notify(e, 'error'); }
  }

  // BB net of one cell of S: 13 ordinates, four quadratic triangles (B, R, T, L)
  const ORD = { c00: 0, c10: 1, c11: 2, c01: 3, eb: 4, er: 5, et: 6, el: 7, d00: 8, d10: 9, d11: 10, d01: 11, o: 12 };
  const TRIS = [['c00', 'c10', 'o', 'eb', 'd10', 'd00'], ['c10', 'c11', 'o', 'er', 'd11', 'd10'], ['c11', 'c01', 'o', 'et', 'd01', 'd11'], ['c01', 'c00', 'o', 'el', 'd00', 'd01']];
  function drawCell() {
    const none = () => { view.remove('bb-net'); view.remove('bb-pts'); put(cellInfo, '— (click S)'); };
    if (!state.cell) { none(); return; }
    let [a, b] = state.cell;
    if (a < 1 || a > m() || b < 1 || b > n()) { state.cell = null; none(); return; }
    try {
      const r = wasm.crissCrossCells({ network: net });
      const base = ((a - 1) * n() + (b - 1)) * 13 * 3;
      const [dx, dy] = offsets.S || [0, 0];
      const o = (name) => { const i = base + 3 * ORD[name]; return [r.ordinates[i] + dx, r.ordinates[i + 1] + dy, r.ordinates[i + 2]]; };
      const lines = [];
      for (const [b200, b020, b002, b110, b011, b101] of TRIS) {
        lines.push([o(b200), o(b110), o(b020), o(b011), o(b002), o(b101), o(b200)], [o(b110), o(b011), o(b101), o(b110)]);
      }
      view.setLines('bb-net', lines, { color: '#E69F00', width: 2 });
      view.setPoints('bb-pts', Object.keys(ORD).flatMap(o), { color: '#E69F00', size: 7, pickable: false });
      put(cellInfo, `[u${sub(a - 1)}, u${sub(a)}] × [v${sub(b - 1)}, v${sub(b)}] — 13 ordinates`);
    } catch (e) { notify(e, 'error'); }
  }
  view.onPick((e) => {
    if (e.kind !== 'surface' || e.id !== 'surf-S') return;
    // grid indices → (u, v) → the cell (bookkeeping on the breakpoints)
    const N = state.density - 1;
    const u = net.u[0] + (net.u[m()] - net.u[0]) * e.iu / N, v = net.v[0] + (net.v[n()] - net.v[0]) * e.iv / N;
    const a = Math.min(m(), Math.max(1, net.u.findIndex((x) => x > u) === -1 ? m() : net.u.findIndex((x) => x > u)));
    const b = Math.min(n(), Math.max(1, net.v.findIndex((x) => x > v) === -1 ? n() : net.v.findIndex((x) => x > v)));
    state.cell = [a, b]; ctx.save(); drawCell();
  });

  let whyBuilt = false;
  /** max |S(C₁₁ = a) − S(C₁₁ = b)| over a 17 × 17 grid: `a`, `b` are both evaluated as Σ Cᵢⱼ Bᵢⱼ (crissCrossSurface,
   * evaluate: 'sum'; numberCalls). */
  function c11Difference(a, b) {
    let d = 0, size = 1;
    for (let i = 0; i < a.length; i++) { d = Math.max(d, Math.abs(a[i] - b[i])); size = Math.max(size, Math.abs(a[i])); }
    return { d, same: d <= 1e-10 * size };
  }
  function showNumbers() {
    put(c2Out, c2.toExponential(2));
    if (numbers) { const { d, same } = numbers.c11; put(c11Out, `${d.toExponential(1)}: ${same ? 'the same surface' : 'different surfaces'}`); }
    put(timeOut, apiTime);
    const N = result.norms;
    if (!N) return;   // coming after the frame (laterNorms)
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
    why.replaceChildren(
      h('h3', null, 'Why is S = G here?'),
      h('p', null, 'Both surfaces interpolate every network curve, but they live in different spaces: G is a piecewise biquadratic on the refined grid Ũ × Ṽ, S a piecewise quadratic on the criss-cross triangles, and S is the only C¹ quadratic on those triangles through the network. So S = G exactly when G happens to be such a spline.'),
      h('p', null, 'That is the case when every coordinate of the network comes from f(u, v) = a(u) + b(v) + c·u·v with a, b C¹ quadratic splines on U and V (an (m + n + 4)-dimensional class): then L1, L2 and Tg reproduce f and G = f = S. The paper\'s ‖S − G‖ = 4.4·10⁻¹⁵ is of this kind; for a generic network ‖S − G‖ is about a quarter of the network\'s size. Drag a point to leave the class.'));
  }

  // ---------- explanation ----------
  explanation(L.explain, {
    what: [
      ['A curve network: ', math('m + 1'), ' curves ', math('\\varphi_r(v)'), ' on the lines ', math('u = u_r'), ' and ', math('n + 1'), ' curves ', math('\\psi_s(u)'), ' on the lines ', math('v = v_s'), ', all ', math('C^1'), ' quadratic B-splines, meeting at the points ', math('I_{rs}'), ' (compatibility C2: ', math('\\varphi_r(v_s) = \\psi_s(u_r)'), '). Orange points are the control points P of the φᵣ, blue ones the Q of the ψₛ; drag any of them — the dependent control points are recomputed so the curves still meet (the C2 residual stays at rounding level).'],
      'Four surfaces pass through the same network: S, the unique C¹ piecewise quadratic on the criss-cross triangulation (the paper\'s construction, local, no parameter); T, a biquadratic tensor spline whose one free control point C11* minimises a thin-plate energy; G, the Gordon boolean sum of two skinned surfaces and a tensor interpolant on refined knots; and GB, the same boolean sum with cardinal cubic blending functions (Kuklišová’s eq. (4)).',
    ],
    math: [
      'S \\;\\text{on cell}\\; [u_{a-1}, u_a] \\times [v_{b-1}, v_b]: \\;\\text{BB net from the four edge curves (13 ordinates)}',
      'T = \\sum_{ij} C^*_{ij} B_i(u) B_j(v), \\quad C^*_{ij} = \\Gamma_{ij} + (-1)^{i+j} C^*_{11} \\frac{h_i k_j}{h_1 k_1}, \\quad C^*_{11} \\;\\text{from (38)}',
      'G = L_1 + L_2 - L_{12}, \\quad \\tilde{C} = \\tilde{C}^{L_1} + \\tilde{C}^{L_2} - \\tilde{C}^{L_{12}} \\;\\text{on}\\; \\tilde{U} = U \\cup \\bar{U}, \\; \\tilde{V} = V \\cup \\bar{V} \\qquad (39)\\text{–}(40)',
      'GB = \\sum_r \\varphi_r(v) L_r(u) + \\sum_s \\psi_s(u) M_s(v) - \\sum_{rs} I_{rs} L_r(u) M_s(v) \\qquad \\text{(Kuklišová eq. (4))}',
    ],
    tryThis: [
      'Pick "Separable": ‖S − G‖ is at rounding level (the paper\'s finding) while T differs. Drag one point: ‖S − G‖ jumps.',
      'Colour S by |S − G| to see where the two differ: along the cell diagonals, where G has no break lines.',
      'Turn on the Gordon components: G is L1 + L2 − Tg (Tg is the tensor surface L12 of the stepper); each of them interpolates only part of the data. Or press Step in “The Boolean sum and S, step by step”: L1, L2, L12, G, then S summed from its B-splines row by row.',
      'Show the triangulation and click a cell of S to see its Bernstein–Bézier net.',
    ],
    formulaNote: ['Correction (', correctionLink('correction-004-sg', '‖S − G‖ in §4.2'), '): the paper’s ‖S − G‖∞ = 4.4·10⁻¹⁵ holds only for networks of a special class (a(u) + b(v) + c·uv per coordinate); on other networks S and G differ — the table above shows by how much.'],
    paper: meta.paper,
  });

  L.controls.append(group('Gordon surface, step by step', steps.el));
  loadNetwork();
  ready = true;
  refresh(false);
  return {
    destroy() { steps.destroy(); cancelAnimationFrame(raf); clearTimeout(normsTimer); surfacesCC.destroy(); numbersCC.destroy(); view.destroy(); },
    // Export row (www/demos/README.md): the network, the norms and every computed surface as OBJ / CSV
    exports() {
      if (!result) return {};
      const keys = Object.keys(result.surfaces || {});
      return {
        // (the norms come with every surfaces result at rest; during a drag they follow, and exports() — called by the
        // Export row after every save — computes nothing: null until they are in)
        json: { network: net, norms: result.norms ?? null, c2 },
        obj: keys.filter((k) => result.surfaces[k].mesh).map((k) => ({ name: `surface_${k}`, mesh: result.surfaces[k].mesh })),
        csv: keys.length && result.surfaces[keys[0]].mesh ? { points: result.surfaces[keys[0]].mesh.positions, dim: 3 } : undefined,
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------
// (imports are hoisted: this block stays self-contained at the end of the file)
import { code, raw, snippetCode } from '../lib/snippet.js';
import { dataImport } from '../lib/data-import.js';

// The presets as code (the same calls as PRESETS[…].build).
const PRESET_CODE = {
  paper: "sl.networkFromFunction({ u: [0, 1 / 3, 2 / 3, 1], v: [0, 1 / 3, 2 / 3, 1], f: (u, v) => [u, v, 0.45 * Math.sin(Math.PI * u) * Math.sin(Math.PI * v) + 0.35 * u * v * v] })",
  'paper-18x4': "sl.networkFromFunction({ u: [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18], v: [0, 1, 2, 3, 4], f: (u, v) => [u, v, 1.5 * Math.sin(Math.PI * u / 6) * Math.cos(Math.PI * (v - 2) / 6) + 0.25 * v] })",
  'three-sided': "sl.networkExample({ name: 'three-sided' })",
  'paper-5x4': "sl.networkFromFunction({ u: [0, 1, 2, 3, 4, 5], v: [0, 1, 2, 3, 4], f: (u, v) => [u, v, 3.5 - 0.22 * (u - 2.5) ** 2 - 0.3 * (v - 2) ** 2 + 0.15 * u * Math.sin(v)] })",
  separable: "sl.networkExample({ name: 'separable' })",
  dome: "sl.networkFromFunction({ u: [0, 0.2, 0.4, 0.6, 0.8, 1], v: [0, 0.2, 0.4, 0.6, 0.8, 1], f: (u, v) => [u, v, 0.6 - 0.9 * ((u - 0.5) ** 2 + (v - 0.5) ** 2) + 0.25 * u * (1 - v) * Math.cos(3 * v)] })",
  dome10: "sl.networkExample({ name: 'dome10' })",
};

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
