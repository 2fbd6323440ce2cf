// What "Criss-cross basis" draws (reads the state and the computed c, changes nothing of them): the 2D parameter
// domain — the colour map of Bᵢⱼ clipped to its octagonal support, the support triangles, the criss-cross
// triangulation (grid and both diagonals of every cell), the knot strips, the picked cell and the pre-image
// (ξᵢ, ηⱼ) —, the 13 BB ordinates of the picked cell over it, and the 3D height view of Bᵢⱼ with its BB net.
import { fmt } from '../../lib/dom.js';
import { PALETTE } from '../../lib/plot2d.js';
import { GRID, STRIP, TRIANGLES, sub, cellsU, cellsV, cellIndex, preImage } from './data.js';
import { ramp, MAP_ALPHA } from './colour-map.js';

/** The domain plot (`g` its 2D context, `p` the plot, `map` the colour map image of colour-map.js). */
export function drawDomain(g, p, state, { basis, cells, vmax }, map) {
  const U = state.u, V = state.v, m = cellsU(state), n = cellsV(state);
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
  // on screen: one image (see colourMap), clipped to the support triangles
  if (state.map && basis && cells && map.ok && !vector) {
    const h = 0.5 / (GRID - 1);      // half a sample step: the texels' outer edges
    const x0 = p.sx(-h), x1 = p.sx(1 + h), y0 = p.sy(1 + h), y1 = p.sy(-h);
    g.save();
    g.beginPath();
    for (let a = 1; a <= m; a++) {
      for (let b = 1; b <= n; b++) {
        const [u0, u1, v0, v1] = [U[a - 1], U[a], V[b - 1], V[b]];
        const ox = p.sx((u0 + u1) / 2), oy = p.sy((v0 + v1) / 2);
        const corners = [[u0, v0], [u1, v0], [u1, v1], [u0, v1]];
        for (let k = 0; k < 4; k++) {
          if (!cells.support[4 * cellIndex(state, a, b) + k]) continue;
          const [pa, pb] = [corners[k], corners[(k + 1) % 4]];
          g.moveTo(p.sx(pa[0]), p.sy(pa[1])); g.lineTo(p.sx(pb[0]), p.sy(pb[1])); g.lineTo(ox, oy); g.closePath();
        }
      }
    }
    g.clip();
    g.globalAlpha = MAP_ALPHA;
    g.imageSmoothingEnabled = true;
    g.imageSmoothingQuality = 'low';
    g.drawImage(map.canvas, x0, y0, x1 - x0, y1 - y0);
    g.restore();
  }
  // support triangles (outline), the triangulation, the picked cell; each kind of line is one path
  // (NaN breaks the pen between pieces)
  const BREAK = [NaN, NaN];
  if (cells) {
    const sup = [];
    for (let a = 1; a <= m; a++) {
      for (let b = 1; b <= n; b++) {
        const [u0, u1, v0, v1] = [U[a - 1], U[a], V[b - 1], V[b]];
        const o = [(u0 + u1) / 2, (v0 + v1) / 2];
        const tris = [[[u0, v0], [u1, v0], o], [[u1, v0], [u1, v1], o], [[u1, v1], [u0, v1], o], [[u0, v1], [u0, v0], o]];
        tris.forEach((t, k) => { if (cells.support[4 * cellIndex(state, a, b) + k]) sup.push(t[0], t[1], t[2], t[0], BREAK); });
      }
    }
    if (sup.length) p.polyline(sup, { color: PALETTE.control, width: 2.5, alpha: 0.9 });
  }
  const diag = [];
  for (let a = 1; a <= m; a++) {
    for (let b = 1; b <= n; b++) diag.push([U[a - 1], V[b - 1]], [U[a], V[b]], BREAK, [U[a], V[b - 1]], [U[a - 1], V[b]], BREAK);
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
  const [xi, eta] = preImage(state);
  p.points([[xi, eta]], { color: PALETTE.ink, radius: 6, shape: 'diamond', stroke: '#fff' });
  p.label(xi, eta, `(ξ${sub(state.i)}, η${sub(state.j)})`, { offset: [8, -6], font: '600 13px system-ui, sans-serif' });
}

/** The 13 BB ordinates of the picked cell at their domain points (values written when the cell is > 150 px wide). */
export function drawOrdinates(p, state, { cells }) {
  if (!state.ordinates || !cells) return;
  const k0 = 13 * cellIndex(state, state.cell[0], state.cell[1]);
  const [ca, cb] = state.cell;
  const wide = Math.min(p.sx(state.u[ca]) - p.sx(state.u[ca - 1]), p.sy(state.v[cb - 1]) - p.sy(state.v[cb])) > 150;
  for (let k = 0; k < 13; k++) {
    const x = cells.domainPoints[2 * (k0 + k)], y = cells.domainPoints[2 * (k0 + k) + 1];
    const val = cells.ordinates[k0 + k];
    p.points([[x, y]], { color: val !== 0 ? PALETTE.highlight : '#fff', radius: 4.5, stroke: PALETTE.ink });
    if (val !== 0 && wide) p.label(x, y, fmt(val, 2), { offset: [4, -3], font: '600 11px system-ui, sans-serif' });
  }
}

/** The 3D view: Bᵢⱼ as a height surface, the lifted triangulation, the unit square, the picked cell's BB net. */
export function drawSurface(view, state, { basis, cells, lines }) {
  view.setMesh('B', basis.mesh, { colors: 'height', colormap: 'viridis', legend: `B${sub(state.i)}${sub(state.j)}(u, v)`, isolines: false });
  view.setLines('tri', lines || [], { color: '#222', width: 1.6, opacity: 0.8 });
  if (!view.objects.has('domain')) view.setLines('domain', [[0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 0]], { color: PALETTE.muted, width: 1.5 });
  // the BB net of the picked cell: its 13 ordinates over their domain points, joined triangle by triangle
  if (cells && state.ordinates) {
    const k0 = 13 * cellIndex(state, state.cell[0], state.cell[1]);
    const P = (k) => [cells.domainPoints[2 * (k0 + k)], cells.domainPoints[2 * (k0 + k) + 1], cells.ordinates[k0 + k]];
    const pts = [];
    for (let k = 0; k < 13; k++) pts.push(...P(k));
    const net = [];
    for (const [a, b, c, ab, bc, ca] of TRIANGLES) {
      net.push([...P(a), ...P(ab), ...P(b), ...P(bc), ...P(c), ...P(ca), ...P(a)]);
      net.push([...P(ab), ...P(bc), ...P(ca), ...P(ab)]);
    }
    view.setLines('bbnet', net, { color: PALETTE.highlight, width: 2 });
    view.setPoints('bb', pts, { color: PALETTE.highlight, size: 9, pickable: false });
  } else {
    view.setVisible('bbnet', false);
    view.setVisible('bb', false);
  }
}
