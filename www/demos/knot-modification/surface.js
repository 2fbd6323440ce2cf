// The surface tab of "Knot modification": a bi-quadratic B-spline surface (8 × 8 control points) whose knots u_p
// and/or v_q move (knotModifiedSurface, eq. (5)); the tracked points move on path-surfaces (knotPaths), the
// envelope (8) (knotEnvelope), and the limits of Theorems 3 (curves, one knot) and 4 (corners, two knots)
// (knotLimits), in a WebGL2 view (www/lib/view3d.js: drag to orbit, wheel to zoom). All values from the wasm API.
import { PALETTE } from '../../lib/plot2d.js';
import { View3D } from '../../lib/view3d.js';
import { SURF_N, sub, surfNb, surfaceDesc } from './knots.js';
import { pathColor } from './curve-draw.js';

/** Computes into S = { desc, surf, orig, tracked, twoKnots, paths, trackedNow, env, limits }. */
function computeSurface(wasm, state, notify, S) {
  try {
    const surface = surfaceDesc();
    S.desc = surface;
    const mu = state.smove !== 'v', mv = state.smove !== 'u';
    // which knots move: p (value up) and/or q (value vq)
    const base = { surface, ...(mu ? { p: state.sp } : {}), ...(mv ? { q: state.sq } : {}) };
    const vals = { ...(mu ? { up: state.sup } : {}), ...(mv ? { vq: state.svq } : {}) };
    S.surf = wasm.knotModifiedSurface({ ...base, ...vals, samplesU: 41, samplesV: 41, mesh: true });
    S.orig = wasm.knotModifiedSurface({ surface, samplesU: 21, samplesV: 21 });
    const [a, b] = surfNb(state.sp), [c, d] = surfNb(state.sq);
    S.tracked = [[a + 0.35 * (b - a), c + 0.4 * (d - c)], [a + 0.75 * (b - a), c + 0.7 * (d - c)]];
    const [fa, fb] = state.extend ? [a - 40, b + 40] : [a, b];
    const [fc, fd] = state.extend ? [c - 40, d + 40] : [c, d];
    S.twoKnots = mu && mv;
    S.paths = S.twoKnots
      ? wasm.knotPaths({ ...base, points: S.tracked, from: [fa, fc], to: [fb, fd], samples: [15, 15] }).paths
      : wasm.knotPaths({ ...base, points: S.tracked, from: mu ? fa : fc, to: mu ? fb : fd, samples: 160 }).paths;
    S.trackedNow = wasm.knotModifiedSurface({ ...base, ...vals, atUV: S.tracked }).points;
    S.env = wasm.knotEnvelope({ ...base, samplesU: 11, samplesV: 11 });
    S.limits = wasm.knotLimits({ ...base, samples: 80 });
  } catch (e) { notify(e, 'error'); }
}

/** Grid lines (every `step`-th) of a u-major nu × nv grid of xyz points, as 3D polylines (NaN breaks a line). */
function gridLines(flat3, nu, nv, step, mask) {
  const lines = [];
  const at = (iu, iv) => { const k = 3 * (iu * nv + iv); return [flat3[k], flat3[k + 1], flat3[k + 2]]; };
  const gap = [NaN, NaN, NaN];
  for (let iu = 0; iu < nu; iu += step) {
    const l = [];
    for (let iv = 0; iv < nv; iv++) l.push(mask && !mask(iu, iv) ? gap : at(iu, iv));
    lines.push(l);
  }
  for (let iv = 0; iv < nv; iv += step) {
    const l = [];
    for (let iu = 0; iu < nu; iu++) l.push(mask && !mask(iu, iv) ? gap : at(iu, iv));
    lines.push(l);
  }
  return lines;
}

/** Puts S into the view: the net, the original, the surface, its affected part, the envelope, paths, limits, points. */
function drawSurface(view, state, S) {
  const put = (id, on, f) => { if (on) f(); else view.remove(id); };
  put('net', !!S.desc, () => {
    const cp = S.desc.controlPoints;
    const lines = cp.map((r) => r.map((q) => q.slice()));
    for (let c = 0; c < SURF_N; c++) lines.push(cp.map((r) => r[c].slice()));
    view.setLines('net', lines, { color: PALETTE.polygon, width: 1.25, opacity: 0.8 });
  });
  put('orig', !!S.orig, () => view.setLines('orig', gridLines(S.orig.points, 21, 21, 2), { color: PALETTE.muted, width: 1, opacity: 0.7 }));
  put('surf', !!S.surf?.mesh, () => view.setMesh('surf', S.surf.mesh, { color: PALETTE.curve, isolines: true, opacity: 0.5 }));
  put('affected', !!S.surf, () => {
    const uv = S.surf.uv;
    const ru = S.surf.affectedRangeU || [-Infinity, Infinity], rv = S.surf.affectedRangeV || [-Infinity, Infinity];
    const inside = (iu, iv) => { const i = iu * 41 + iv; const u = uv[2 * i], v = uv[2 * i + 1]; return u >= ru[0] && u <= ru[1] && v >= rv[0] && v <= rv[1]; };
    view.setLines('affected', gridLines(S.surf.points, 41, 41, 4, inside), { color: PALETTE.highlight, width: 3 });
  });
  put('envelope', state.showEnvelope && !!S.env, () => view.setLines('envelope', gridLines(S.env.points, 11, 11, 1), { color: PALETTE.second, width: 2.5 }));
  for (let j = 0; j < 8; j++) view.remove(`path${j}`);
  S.paths.forEach((ps, j) => {
    if (S.twoKnots) view.setLines(`path${j}`, gridLines(ps, 15, 15, 1), { color: pathColor(j), width: 1.5 });
    else view.setLines(`path${j}`, [ps], { color: pathColor(j), width: 3 });
  });
  const limitLines = [], limitPts = [], limitLabels = [];
  if (state.showLimits && S.limits && !S.twoKnots) {
    // Theorem 3: the limit curves Σ_s N_s^l(v) d_{p,s} (u_p → −∞) and Σ_s N_s^l(v) d_{p−k,s} (u_p → +∞)
    const dir = state.smove === 'u' ? 'u' : 'v', knot = dir === 'u' ? `u${sub(state.sp)}` : `v${sub(state.sq)}`;
    for (const [key, txt] of [['Minus', '−∞'], ['Plus', '+∞']]) {
      const curve = S.limits[`${dir}${key}Curve`], i = S.limits[`${dir}${key}Index`];
      if (!curve) continue;
      limitLines.push(curve);
      const m = Math.floor(curve.length / 6) * 3;
      limitPts.push(curve[m], curve[m + 1], curve[m + 2]);
      limitLabels.push(`${knot} → ${txt}: Σ N ${dir === 'u' ? `d${sub(i)},ₛ` : `dᵣ,${sub(i)}`}`);
    }
  }
  if (state.showLimits && S.limits && S.twoKnots) {
    // Theorem 4 (corrected): the corners d_{p,q}, d_{p,q−l}, d_{p−k,q}, d_{p−k,q−l}
    const c = S.limits.corners, idx = S.limits.cornerIndices;
    const names = ['(−∞,−∞)', '(−∞,+∞)', '(+∞,−∞)', '(+∞,+∞)'];
    for (let i = 0; i < 4; i++) { limitPts.push(c[3 * i], c[3 * i + 1], c[3 * i + 2]); limitLabels.push(`${names[i]}: d${sub(idx[i][0])},${sub(idx[i][1])}`); }
  }
  put('limits', limitLines.length > 0, () => view.setLines('limits', limitLines, { color: PALETTE.ink, width: 3 }));
  put('limitPts', limitPts.length > 0, () => view.setPoints('limitPts', limitPts, { color: PALETTE.ink, size: 10, labels: limitLabels, pickable: false }));
  put('tracked', !!S.trackedNow, () => view.setPoints('tracked', S.trackedNow, { colors: S.tracked.map((_, j) => pathColor(j)), size: 12, pickable: false }));
}

/** The text under the surface controls: which knots move, what is affected, what is drawn. */
export function surfaceInfoText(state, S) {
  if (S.twoKnots) {
    const [ul, uh] = S.surf.affectedSpansU, [vl, vh] = S.surf.affectedSpansV;
    return `Knots u${sub(state.sp)} and v${sub(state.sq)} move. Patches with span indices u ${ul}…${uh}, v ${vl}…${vh} are affected by both (highlighted; at most 4(k − 1)(l − 1) = 16 patches). Each tracked point moves on a path-surface; the envelope (8) is green; with "extend" the path-surfaces reach out to the four corner control points (Theorem 4).`;
  }
  const u = state.smove === 'u';
  const [lo, hi] = u ? S.surf.affectedSpansU : S.surf.affectedSpansV;
  const knot = u ? `u${sub(state.sp)}` : `v${sub(state.sq)}`;
  return `Only ${knot} moves: the strip of patches with ${u ? 'u' : 'v'}-span ${lo}…${hi} changes (highlighted). The tracked points move on paths; the envelope (${u ? '6' : '6, in v'}) is green; the dashed black curves are the limits of Theorem 3 as ${knot} → ±∞ — B-spline curves of the control ${u ? 'rows' : 'columns'} ${u ? state.sp : state.sq} and ${u ? state.sp - 3 : state.sq - 3}.`;
}

/**
 * The surface view in `wrap`. onTurn(yaw, pitch) tells the Turn/Tilt sliders about an orbit of the view.
 * Returns { view, S, compute(), plot } where plot = { canvas, redraw, destroy } (the interface of a 2D plot).
 */
export function surfaceView({ wrap, wasm, state, ctx, notify, onTurn }) {
  const S = { surf: null, orig: null, paths: [], env: null, limits: null, info: null, tracked: [] };
  let framed = false;
  const view = new View3D(wrap, {
    height: 500,
    ariaLabel: 'B-spline surface with moving knots (3D view): path-surfaces, envelope, corner limits',
    locked: true,
    onViewChange(v) {
      const yaw = Math.round(((((v.yaw + 180) % 360) + 360) % 360) - 180), pitch = Math.round(Math.min(89, Math.max(0, v.pitch)));
      const camera = [v.distance, ...v.target];
      if (yaw === state.yaw && pitch === state.pitch && String(camera) === String(state.camera)) return;
      state.yaw = yaw; state.pitch = pitch; state.camera = camera;
      onTurn(yaw, pitch);
      ctx.save();
    },
  });
  function redraw() {
    drawSurface(view, state, S);
    view.setView({ yaw: state.yaw, pitch: state.pitch });
    if (!framed && wrap.style.display !== 'none') {
      view.fit(); framed = true;
      const c = state.camera;   // the zoom and target kept in the link
      if (Array.isArray(c) && c.length === 4 && c.every(Number.isFinite) && c[0] > 0) view.setView({ distance: c[0], target: c.slice(1) });
    }
    view.render();
  }
  const plot = { canvas: view.canvas, redraw, destroy: () => view.destroy() };
  plot.canvas.dataset.plot = 'surface';
  return { view, S, plot, compute: () => computeSurface(wasm, state, notify, S) };
}
