// What "Curve networks" draws into the 3D view (reads the state and the computed c; changes only the view): the
// surfaces side by side or overlaid (the Gordon components in a second row), their name tags, the partial sum of S
// (the stepper), the network curves with their draggable control points, the probe, the criss-cross triangulation
// lifted onto S and the BB net of one cell of S. Each surface is drawn shifted by its offset [dx, dy].
import { mathText } from '../../lib/mathml.js';
import { COLOURS } from './presets.js';
import { PALETTE } from '../../lib/plot2d.js';

/** Index (into the flat xyz array) of the vertex with the largest z. */
function highest(pos) {
  let top = 0;
  for (let i = 2; i < pos.length; i += 3) if (pos[i] > pos[top + 2]) top = i - 2;
  return top;
}

/** A flat xyz array moved by [dx, dy] (the same array when the offset is zero). */
export const shift = (flat, off = [0, 0]) => {
  const [dx, dy] = off;
  if (!dx && !dy) return flat;
  const a = new Float32Array(flat);   // (a typed-array copy: Float32Array.from goes through the iterator, 10× slower)
  for (let i = 0; i < a.length; i += 3) { a[i] += dx; a[i + 1] += dy; }
  return a;
};
const shifted = (mesh, off) => ({ ...mesh, positions: shift(mesh.positions, off) });

/** Where each surface is drawn: [dx, dy]. Side by side: a row along x (the network's width + a gap apart);
 * overlaid: all at the network. The Gordon components always go in a second row, in front. */
export function layoutOffsets(net, state, names, comps, forceSide = false) {
  const pts = net.P.flat().concat(net.Q.flat());
  const extent = (k) => { const xs = pts.map((p) => p[k]); return (Math.max(...xs) - Math.min(...xs)) || 1; };
  const w = extent(0) * 1.25, d = extent(1) * 1.35;
  const offsets = {};
  names.forEach((k, i) => { offsets[k] = [state.layout === 'side' || forceSide ? i * w : 0, 0]; });
  comps.forEach((k, i) => { offsets[k] = [i * w, -d]; });
  return offsets;
}

/** The surfaces `names` and `comps` of c.result (stepping: the current step opaque, the others faded; the colour
 * map on S or T), and a name tag above the highest vertex of each. */
export function drawSurfaces(view, state, { result }, offsets, { stepping, sMode, names, comps, colorBy, stepName }) {
  for (const k of names.concat(comps)) {
    const mesh = shifted(result.surfaces[k].mesh, offsets[k]);
    const mapped = colorBy && k === (colorBy === 'TG' ? 'T' : 'S') && result.colors;
    view.setMesh(`surf-${k}`, mesh, {
      color: COLOURS[k], isolines: { every: Math.max(1, Math.round(state.density / 8)) },
      opacity: sMode ? 0.3 : stepping ? (k === stepName ? 1 : 0.3) : state.layout === 'overlay' && names.length > 1 ? 0.7 : 1,
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
}

/** The partial sum P of S = Σ Cᵢⱼ Bᵢⱼ (flat xyz on S's grid) as a mesh with S's triangles. */
export function drawPartial(view, state, { result }, offsets, P) {
  const S = result.surfaces.S;
  if (!P || !S) return;
  const pos = Float32Array.from(P);
  const [dx, dy] = offsets.P;
  for (let q = 0; q < pos.length; q += 3) { pos[q] += dx; pos[q + 1] += dy; }
  view.setMesh('surf-P', { positions: pos, indices: S.mesh.indices }, { color: COLOURS.S, isolines: { every: Math.max(1, Math.round(state.density / 8)) } });
}

/** The network curves at every drawn surface, and the control points P (of the φᵣ) and Q (of the ψₛ) at the first;
 * `onDrag(kind, index, pos, phase)` gets a dragged point back in the network's coordinates. */
export function drawNetwork(view, { net, result }, offsets, names, { locked, onDrag }) {
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
  // the paper's names: P[r][j] = P_j^{(r)}, Q[s][i] = Q_i^{(s)}, all from 0
  const nameOf = (rows, letter) => (index) => {
    const cols = rows[0]?.length || 1;
    return mathText(`${letter}_{${index % cols}}^{(${Math.floor(index / cols)})}`);
  };
  view.setPoints('net-P', P, { color: PALETTE.control, size: 11, draggable: !locked, onDrag: drag('P'), labels: undefined, names: nameOf(net.P, 'P') });
  view.setPoints('net-Q', Q, { color: PALETTE.curve, size: 9, draggable: !locked, onDrag: drag('Q'), names: nameOf(net.Q, 'Q') });
}

/** The probe of the stepper on each surface of `names` (`pointOf(k)`: its point, or null). */
export function drawProbe(view, names, offsets, pointOf) {
  if (!names.length) { view.remove('probe'); return; }
  const pos = [];
  for (const k of names) { const p = pointOf(k); if (p) pos.push(p[0] + offsets[k][0], p[1] + offsets[k][1], p[2]); }
  view.setPoints('probe', pos, { color: PALETTE.black, size: 12, pickable: false, onTop: true });
}

/** The triangulation's pieces (compute.js triangulation()) on S's copy. */
export function drawTriangulation(view, pieces, offsets) {
  view.setLines('tri', pieces.map((p) => shift(p, offsets.S)), { color: '#f5f5f5', width: 1.2, opacity: 0.85 });
}

// BB net of one cell of S: 13 ordinates, four quadratic triangles (B, R, T, L)
const ORD = { c00: 0, c10: 1, c11: 2, c01: 3, eb: 4, er: 5, et: 6, el: 7, d00: 8, d10: 9, d11: 10, d01: 11, o: 12 };
const TRIS = [['c00', 'c10', 'o', 'eb', 'd10', 'd00'], ['c10', 'c11', 'o', 'er', 'd11', 'd10'], ['c11', 'c01', 'o', 'et', 'd01', 'd11'], ['c01', 'c00', 'o', 'el', 'd00', 'd01']];
/** The BB net of cell (a, b) of S from the ordinates of every cell (n: the cells in v). */
export function drawCellNet(view, ordinates, a, b, n, offsets) {
  const base = ((a - 1) * n + (b - 1)) * 13 * 3;
  const [dx, dy] = offsets.S || [0, 0];
  const o = (name) => { const i = base + 3 * ORD[name]; return [ordinates[i] + dx, ordinates[i + 1] + dy, ordinates[i + 2]]; };
  const lines = [];
  for (const [b200, b020, b002, b110, b011, b101] of TRIS) {
    lines.push([o(b200), o(b110), o(b020), o(b011), o(b002), o(b101), o(b200)], [o(b110), o(b011), o(b101), o(b110)]);
  }
  view.setLines('bb-net', lines, { color: PALETTE.accent, width: 2 });
  view.setPoints('bb-pts', Object.keys(ORD).flatMap(o), { color: PALETTE.accent, size: 7, pickable: false });
}
