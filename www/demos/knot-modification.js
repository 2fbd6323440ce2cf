// Demo "Knot modification" (Juhász–Hoffmann): drag one knot of a B-spline curve along the knot line
// (and, with "extend", beyond its neighbours); see the paths traced by a few curve points, the envelope of the
// family of curves, the limit control points as the knot goes to ±∞, and which segments the knot affects.
// A surface tab moves two knots of a B-spline surface (WebGL 3D view) and shows path-surfaces, the
// envelope (8) and the four corner limits of Theorem 4. All spline values come from the wasm API
// (knotModifiedCurve, knotPathsCurve, knotEnvelopeCurve, knotLimits, knotModifiedSurface, knotPaths,
// knotEnvelope); this module only draws and handles input.

import { h, demoLayout, explanation, fmt } from '../lib/dom.js';
import { math, mathText } from '../lib/mathml.js';
import { stepper } from '../lib/stepper.js';
import { cite, correctionLink } from '../lib/papers-ref.js';
import { createPlot, PALETTE, SERIES, restoreView } from '../lib/plot2d.js';
import { slider, toggle, buttonGroup, button, table, group, row } from '../lib/controls.js';
import { View3D } from '../lib/view3d.js';
import { uPlayer } from '../lib/player.js';

export const meta = {
  id: 'knot-modification',
  title: 'Knot modification',
  summary: 'Move one knot (even past its neighbours): curve points travel on paths, the family has an envelope, and the paths end at control points.',
  paper: cite('002', 'Thms 3–8, eqs. (6)–(10)'),
};

const KNOT_ROW = 0;          // y of the knot line in the knot plot
const EXT = 12;              // how far beyond its neighbours the knot may go with "extend" (knot units)
const FAR = 400;             // the extended paths are followed to u_p = u_{p−1} − FAR … u_{p+1} + FAR
const SURF_N = 8;            // surface control net SURF_N × SURF_N
// Dragging the knot snaps it to the first of these steps that is at least one screen pixel of the knot line:
// 0.01 on a desktop, 0.02 on a phone (1 px ≈ 0.017 there). The value then is what the labels show (1.6, not
// 1.604), and every value of the grid (such as an exercise's answer 1.6) can be reached by a finger.
const KNOT_SNAPS = [0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1];
/** A knot value as the labels show it: at most 4 decimals, no trailing zeros (1.6, 1.604). */
const knotText = (x) => String(+x.toFixed(4));

export function defaults() {
  return {
    tab: 'curve',
    order: 4,
    points: [[0, 0], [1, 2.4], [2.2, 2.8], [3.2, 0.6], [4.4, 0.2], [5.4, 2.6], [6.6, 2.4], [7.4, 0.4]],
    p: 5,
    up: 2.4,
    extend: false,
    tracked: 3,
    trackAll: false,
    showFamily: true,
    showEnvelope: true,
    showLimits: true,
    step: -1,     // the de Boor stepper at the first tracked point: −1 = off, else the index of d_j^r shown
    // surface tab
    sp: 4,
    sq: 4,
    sup: 2.5,
    svq: 2.5,
    smove: 'both',
    yaw: 35,
    pitch: 30,
    view: [],
    camera: [],   // 3D camera distance and target [d, x, y, z] ([] = frame the surface); the direction is yaw/pitch
  };
}

/** Clamped knots with integer interior spacing for `count` control points of order `k` (bookkeeping). */
function clampedKnots(k, count) {
  const t = [];
  for (let i = 0; i < k; i++) t.push(0);
  for (let i = 1; i <= count - k; i++) t.push(i);
  for (let i = 0; i < k; i++) t.push(count - k + 1);
  return t;
}

const sub = (i) => String(i).replace(/\d/g, (d) => '₀₁₂₃₄₅₆₇₈₉'[d]).replace('-', '₋');

export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);

  // ---------- state helpers ----------
  const k = () => state.order;
  const count = () => state.points.length;
  const knots = () => clampedKnots(k(), count());
  const nb = () => { const t = knots(); return [t[state.p - 1], t[state.p + 1]]; };
  const upRange = () => { const [a, b] = nb(); return state.extend ? [a - EXT, b + EXT] : [a, b]; };
  const surfKnots = () => clampedKnots(3, SURF_N);
  const surfNb = (i) => { const t = surfKnots(); return [t[i - 1], t[i + 1]]; };
  const surfRange = (i) => { const [a, b] = surfNb(i); return state.extend ? [a - EXT, b + EXT] : [a, b]; };

  function sanitize() {
    const d = defaults();
    if (state.tab !== 'curve' && state.tab !== 'surface') state.tab = 'curve';
    if (!Number.isInteger(state.order) || state.order < 2 || state.order > 5) state.order = d.order;
    // 6…16 control points ("Use my data" may change their number; the default has 8)
    if (!Array.isArray(state.points) || state.points.length < 6 || state.points.length > 16
      || !state.points.every((q) => Array.isArray(q) && q.length === 2 && q.every(Number.isFinite))) state.points = d.points;
    const n = count() - 1;
    if (!Number.isInteger(state.p) || state.p < k() || state.p > n) state.p = Math.min(n, Math.max(k(), d.p));
    const [lo, hi] = upRange();
    if (!Number.isFinite(state.up)) state.up = knots()[state.p];
    state.up = Math.min(hi, Math.max(lo, state.up));
    if (!Number.isInteger(state.tracked) || state.tracked < 1 || state.tracked > 7) state.tracked = d.tracked;
    if (typeof state.trackAll !== 'boolean') state.trackAll = false;
    if (!Number.isInteger(state.step) || state.step < -1 || state.step > 20) state.step = -1;
    for (const key of ['sp', 'sq']) if (!Number.isInteger(state[key]) || state[key] < 3 || state[key] > SURF_N - 1) state[key] = d[key];
    for (const [key, idx] of [['sup', 'sp'], ['svq', 'sq']]) {
      const [a, b] = surfRange(state[idx]);
      if (!Number.isFinite(state[key])) state[key] = d[key];
      state[key] = Math.min(b, Math.max(a, state[key]));
    }
    if (!['both', 'u', 'v'].includes(state.smove)) state.smove = 'both';
    if (!Number.isFinite(state.yaw)) state.yaw = d.yaw;
    if (!Number.isFinite(state.pitch)) state.pitch = d.pitch;
    state.yaw = Math.min(180, Math.max(-180, state.yaw));
    state.pitch = Math.min(89, Math.max(0, state.pitch));
  }

  // ---------- curve data (all from wasm) ----------
  const C = { cur: null, orig: null, affected: null, paths: [], env: null, family: [], limits: null, info: null, trackedU: [], trackedPts: null };

  const curveDesc = () => ({ order: k(), knots: knots(), controlPoints: state.points });

  function trackedParams() {
    if (state.trackAll && C.cur) {
      // one point in the middle of every affected span (bookkeeping on the knot vector)
      const t = knots(), [lo, hi] = C.cur.affectedSpans, us = [];
      for (let i = lo; i <= hi; i++) if (t[i + 1] > t[i]) us.push((t[i] + t[i + 1]) / 2);
      return us;
    }
    const [a, b] = nb();
    const m = state.tracked;
    return Array.from({ length: m }, (_, j) => a + (b - a) * (j + 0.5) / m);
  }

  function computeCurve() {
    try {
      const curve = curveDesc();
      C.cur = wasm.knotModifiedCurve({ curve, p: state.p, up: state.up, samples: 400 });
      C.orig = wasm.knotModifiedCurve({ curve, p: state.p, up: knots()[state.p], samples: 300 });
      const [ra, rb] = C.cur.affectedRange;
      C.affected = wasm.knotModifiedCurve({ curve, p: state.p, up: state.up, at: Array.from({ length: 201 }, (_, i) => ra + (rb - ra) * i / 200) });
      C.trackedU = trackedParams();
      const [a, b] = nb();
      C.paths = [];
      const segments = state.extend ? [[a - FAR, a - 4, 300], [a - 4, b + 4, 400], [b + 4, b + FAR, 300]] : [[a, b, 200]];
      for (const [from, to, samples] of segments) {
        const r = wasm.knotPathsCurve({ curve, p: state.p, params: C.trackedU, from, to, samples });
        r.paths.forEach((path, j) => { (C.paths[j] ||= []).push(path); });
      }
      C.trackedPts = wasm.knotModifiedCurve({ curve, p: state.p, up: state.up, at: C.trackedU }).points;
      C.env = wasm.knotEnvelopeCurve({ curve, p: state.p, samples: 200 });
      // the point where the envelope touches the current member (only while u_p is between its neighbours)
      C.touch = state.up >= a && state.up <= b ? wasm.knotEnvelopeCurve({ curve, p: state.p, at: [state.up] }).points : null;
      C.family = [];
      if (state.showFamily) {
        for (let j = 0; j <= 6; j++) {
          C.family.push(wasm.knotModifiedCurve({ curve, p: state.p, up: a + (b - a) * j / 6, samples: 200 }).points);
        }
      }
      C.limits = wasm.knotLimits({ curve, p: state.p });
      // the de Boor triangle at the first tracked point with the moved knot (the stepper)
      C.db = C.trackedU.length ? wasm.knotDeBoorCurve({ curve, p: state.p, up: state.up, u: C.trackedU[0] }) : null;
    } catch (e) { C.db = null; notify(e, 'error'); }
  }

  // ---------- curve plot ----------
  const curveWrap = h('div', { class: 'km-curve' });
  L.plots.appendChild(curveWrap);
  const curvePlot = createPlot(curveWrap, {
    ariaLabel: 'B-spline curve with one moving knot: paths of curve points, envelope, limit control points',
    equal: true, height: 430, locked: options.locked,
    view: { xmin: -0.8, xmax: 8.2, ymin: -0.8, ymax: 3.4 },
    describe: () => {
      const pts = C.trackedPts ? C.trackedU.map((u, j) => `u = ${fmt(u, 2)} at (${fmt(C.trackedPts[2 * j], 2)}, ${fmt(C.trackedPts[2 * j + 1], 2)})`).join('; ') : '';
      return `B-spline of order ${k()} with knot u${sub(state.p)} moved to ${fmt(state.up, 3)}. Tracked points: ${pts}. Limits: u${sub(state.p)} → −∞ gives d${sub(state.p)}, u${sub(state.p)} → +∞ gives d${sub(state.p - k())}.`;
    },
    onView(v) { state.view = [v.xmin, v.xmax, v.ymin, v.ymax]; ctx.save(); },
    draw(g, plot) {
      plot.polyline(state.points, { color: PALETTE.polygon, width: 1.5, dash: [8, 6] });
      if (state.showFamily) for (const f of C.family) plot.polyline(f, { color: PALETTE.sky, width: 1.25, alpha: 0.7 });
      if (C.orig) plot.polyline(C.orig.points, { color: PALETTE.muted, width: 2, dash: [3, 5] });
      if (C.affected) plot.polyline(C.affected.points, { color: PALETTE.highlight, width: 11, alpha: 0.28 });
      if (C.cur) plot.polyline(C.cur.points, { color: PALETTE.curve, width: 3.5 });
      if (state.showEnvelope && C.env) plot.polyline(C.env.points, { color: PALETTE.second, width: 4, dash: [12, 5] });
      C.paths.forEach((segs, j) => {
        for (const path of segs) plot.polyline(breakJumps(path, plot), { color: pathColor(j), width: 2.25 });
      });
      if (state.showLimits && C.limits) {
        for (const [pt, idx, txt] of [[C.limits.minus, C.limits.minusIndex, '−∞'], [C.limits.plus, C.limits.plusIndex, '+∞']]) {
          const [X, Y] = plot.toScreen(pt[0], pt[1]);
          g.beginPath(); g.arc(X, Y, 16, 0, 2 * Math.PI); g.lineWidth = 3; g.strokeStyle = PALETTE.ink; g.setLineDash([4, 3]); g.stroke(); g.setLineDash([]);
          plot.label(pt[0], pt[1], `u${sub(state.p)} → ${txt}`, { offset: [0, -20], align: 'center', baseline: 'bottom', font: '700 13px system-ui, sans-serif' });
        }
      }
    },
    drawOver(g, plot) {
      drawDeBoor(g, plot);
      if (C.trackedPts) {
        for (let j = 0; j < C.trackedU.length; j++) {
          plot.points([[C.trackedPts[2 * j], C.trackedPts[2 * j + 1]]], { color: pathColor(j), radius: 6, stroke: '#fff', shape: 'diamond' });
        }
      }
      if (state.showEnvelope && C.touch) {
        plot.points([[C.touch[0], C.touch[1]]], { color: PALETTE.second, radius: 7, stroke: '#fff' });
        plot.label(C.touch[0], C.touch[1], mathText('e(u_p) = s(u_p; u_p)'), { color: '#00654a', offset: [10, 22], baseline: 'top', font: '600 13px system-ui, sans-serif' });
      }
      drawTarget(g, plot);
    },
  });
  curvePlot.canvas.dataset.plot = 'curve';

  /** An exercise's point Q (state.exercise.target, www/lib/exercise.js): a ringed cross labelled “Q”. */
  function drawTarget(g, plot) {
    const q = state.exercise?.target;
    if (!q || state.tab !== 'curve') return;
    const [X, Y] = plot.toScreen(q[0], q[1]);
    g.save();
    g.lineWidth = 2.5; g.strokeStyle = PALETTE.ink; g.fillStyle = 'rgba(255,255,255,0.6)';
    g.beginPath(); g.arc(X, Y, 11, 0, 2 * Math.PI); g.fill(); g.stroke();
    g.beginPath(); g.moveTo(X - 16, Y); g.lineTo(X + 16, Y); g.moveTo(X, Y - 16); g.lineTo(X, Y + 16); g.stroke();
    g.restore();
    plot.label(q[0], q[1], `Q (${q.map((x) => +x.toFixed(3)).join(', ')})`, { offset: [14, -14], baseline: 'bottom', font: '700 14px system-ui, sans-serif', color: PALETTE.ink });
  }
  curvePlot.addHandles({
    name: 'control point',
    points: () => state.points,
    label: (i) => `d${sub(i)}`,
    labelOf: (i) => `Control point d${i}`,
    radius: 7,
    move(i, q) { state.points[i] = [q[0], q[1]]; recompute(); },
    end() { ctx.save(); },
  });

  // ---------- the moved curve's point, step by step (de Boor with the moved knot) ----------
  /**
   * The de Boor triangle at u = the first tracked point: which intermediate points d_j^r depend on u_p (their α
   * uses the moved knot, or one of the two points they blend depends on it), from the wasm core's triangle.
   */
  function deBoorInfo() {
    const db = C.db;
    if (!db) return null;
    const k = state.order, n = db.levels.length;
    const at = (arr, i) => [arr[2 * i], arr[2 * i + 1]];
    const pos = new Map();   // `${r},${j}` → { pt, dep }
    for (let a = 0; a < k; a++) pos.set(`0,${db.startIndices[a]}`, { pt: at(db.start, a), dep: false });
    const items = [];
    for (let s = 0; s < n; s++) {
      const r = db.levels[s], j = db.indices[s];
      const left = pos.get(`${r - 1},${j - 1}`), right = pos.get(`${r - 1},${j}`);
      const dep = db.usesUp[s] === 1 || left.dep || right.dep;
      const it = { r, j, lo: db.knotLo[s], hi: db.knotHi[s], alpha: db.alphas[s], uses: db.usesUp[s] === 1, dep, pt: at(db.points, s), left, right };
      pos.set(`${r},${j}`, { pt: it.pt, dep });
      items.push(it);
    }
    return { items, u: db.u, span: db.span, start: Array.from(db.startIndices, (j, a) => ({ j, pt: at(db.start, a) })) };
  }
  const knotTex = (i) => `u_{${i}}`;
  function deBoorSteps() {
    const info = deBoorInfo();
    if (!info) return [];
    const t = C.db.knots, p = state.p, u = info.u;
    const val = (i) => (i === p ? `\\mathbf{${fmt(t[i], 3)}}` : fmt(t[i], 3));
    return info.items.map((it) => {
      const { r, j, lo, hi } = it;
      const up = lo === p || hi === p;
      return {
        label: `level ${r}, the point ${mathText(`d_${j}^${r}`)}${it.dep ? ' moves with u' + sub(p) : ' does not depend on u' + sub(p)}`,
        tex: [
          `d_{${j}}^{${r}} = (1-\\alpha_{${j}}^{${r}})\\, d_{${j - 1}}^{${r - 1}} + \\alpha_{${j}}^{${r}}\\, d_{${j}}^{${r - 1}}`,
          `\\alpha_{${j}}^{${r}} = \\frac{u - ${knotTex(lo)}}{${knotTex(hi)} - ${knotTex(lo)}} = \\frac{${fmt(u, 3)} - ${val(lo)}}{${val(hi)} - ${val(lo)}} = ${fmt(it.alpha, 4)}`,
          `d_{${j}}^{${r}} = (${fmt(it.pt[0], 3)}, ${fmt(it.pt[1], 3)})`,
        ],
        note: up
          ? `α uses the moved knot u${sub(p)} = ${fmt(state.up, 3)}: this point changes when the knot moves.`
          : it.dep ? `α does not use u${sub(p)}, but a point it blends does: this point changes too.`
          : `Neither α nor the points it blends use u${sub(p)}: this point stays put when the knot moves.`,
      };
    });
  }
  function drawDeBoor(g, plot) {
    const st = state.step, info = st >= 0 && state.tab === 'curve' ? deBoorInfo() : null;
    if (!info) return;
    const cur = info.items[Math.min(st, info.items.length - 1)];
    const colorOf = (dep) => (dep ? PALETTE.control : PALETTE.muted);
    // the control points the span uses, then every point computed so far with its two parents
    for (const s of info.start) {
      const [X, Y] = plot.toScreen(s.pt[0], s.pt[1]);
      g.beginPath(); g.arc(X, Y, 12, 0, 2 * Math.PI); g.lineWidth = 2; g.strokeStyle = PALETTE.ink; g.stroke();
    }
    info.items.slice(0, st + 1).forEach((it, s) => {
      const now = s === st;
      const w = now ? 3.5 : 1.5;
      plot.segment(it.left.pt[0], it.left.pt[1], it.right.pt[0], it.right.pt[1], { color: colorOf(it.dep), width: w, alpha: now ? 1 : 0.6 });
      plot.points([it.pt], { color: colorOf(it.dep), radius: now ? 8 : 5, stroke: '#fff', shape: it.dep ? 'diamond' : 'circle' });
      if (now) plot.label(it.pt[0], it.pt[1], mathText(`d_${it.j}^${it.r}`), { offset: [10, -10], font: '700 14px system-ui, sans-serif', color: it.dep ? '#8a2f6a' : '#333' });
    });
    void cur;
  }

  /** Splits a flat path where consecutive points jump by more than the view (poles of extended paths). */
  function breakJumps(path, plot) {
    const v = plot.getView();
    const lim = 4 * Math.max(v.xmax - v.xmin, v.ymax - v.ymin);
    const out = [];
    for (let i = 0; i + 1 < path.length; i += 2) {
      const x = path[i], y = path[i + 1];
      if (i > 0 && Math.hypot(x - path[i - 2], y - path[i - 1]) > lim) out.push(NaN, NaN);
      out.push(x, y);
    }
    return out;
  }
  const pathColor = (j) => [PALETTE.accent, PALETTE.control, '#882255', '#000000', PALETTE.sky, PALETTE.second, PALETTE.curve][j % 7];

  const legend = h('ul', { class: 'legend', 'aria-label': 'Legend' },
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.curve } }), 'curve with the moved knot'),
    h('li', null, h('span', { class: 'swatch dashed' }), 'original curve (dotted) and control polygon (dashed)'),
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.highlight, opacity: '0.5' } }), 'segments the knot affects'),
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.accent } }), 'paths of the tracked points (diamonds)'),
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.second } }), 'envelope ', math('e(w)'), ' of the family'),
    h('li', null, h('span', { class: 'swatch', style: { background: PALETTE.sky } }), 'family members for ', math('u_p'), ' between its neighbours'));
  curveWrap.appendChild(legend);

  // ---------- knot line ----------
  const knotPlot = createPlot(curveWrap, {
    ariaLabel: 'Knot line: drag the moving knot',
    height: 160, pan: true, zoom: true, zoomY: false, locked: options.locked, xLabel: 'u', ticks: true, grid: false,
    view: { xmin: -0.6, xmax: 5.6, ymin: -1, ymax: 1 },
    describe: () => `Knots ${knots().map((x, i) => (i === state.p ? `u${i} = ${fmt(state.up, 3)} (moving)` : fmt(x, 2))).join(', ')}.`,
    draw(g, plot) {
      const t = knots();
      const [a, b] = nb();
      if (C.cur) {
        const [ra, rb] = C.cur.affectedRange;
        plot.fill([[ra, -0.55], [rb, -0.55], [rb, 0.55], [ra, 0.55]], { color: PALETTE.highlight, alpha: 0.16 });
        plot.label((ra + rb) / 2, -0.55, 'affected spans', { align: 'center', baseline: 'top', offset: [0, 2], color: '#8a2f6a', font: '600 12px system-ui, sans-serif' });
      }
      plot.fill([[a, -0.3], [b, -0.3], [b, 0.3], [a, 0.3]], { color: PALETTE.second, alpha: 0.18 });
      const [lo, hi] = upRange();
      plot.segment(Math.min(lo, t[0]), KNOT_ROW, Math.max(hi, t[t.length - 1]), KNOT_ROW, { color: PALETTE.axis, width: 2 });
      t.forEach((x, i) => {
        if (i === state.p) {
          plot.points([[x, KNOT_ROW]], { color: PALETTE.muted, radius: 5, hollow: true });
          return;
        }
        plot.segment(x, -0.2, x, 0.2, { color: PALETTE.ink, width: 2 });
      });
      // labels of the distinct knots (index ranges for repeated ones)
      let i = 0;
      while (i < t.length) {
        let j = i;
        while (j + 1 < t.length && t[j + 1] === t[i]) j++;
        const idx = [];
        for (let m = i; m <= j; m++) if (m !== state.p) idx.push(m);
        if (idx.length) plot.label(t[i], 0.2, idx.length > 1 ? `u${sub(idx[0])}…${sub(idx[idx.length - 1])}` : `u${sub(idx[0])}`, { align: 'center', offset: [0, -2], font: '12px system-ui, sans-serif', color: '#333' });
        i = j + 1;
      }
    },
    drawOver(g, plot) {
      const info = state.step >= 0 && state.tab === 'curve' ? deBoorInfo() : null;
      const it = info && info.items[Math.min(state.step, info.items.length - 1)];
      if (it && C.db) {
        const t = C.db.knots, a = t[it.lo], b = t[it.hi];
        plot.segment(a, 0.55, b, 0.55, { color: it.uses ? PALETTE.control : PALETTE.ink, width: 5 });
        plot.label((a + b) / 2, 0.55, mathText(`\\alpha_${it.j}^${it.r}: [u_${it.lo}, u_${it.hi}]`), { align: 'center', baseline: 'bottom', offset: [0, -4], font: '600 12px system-ui, sans-serif' });
        plot.segment(info.u, -0.6, info.u, 0.6, { color: PALETTE.accent, width: 2, dash: [4, 3] });
      }
      plot.label(state.up, -0.25, `u${sub(state.p)} = ${knotText(state.up)}`, { align: 'center', baseline: 'top', offset: [0, 8], font: '700 13px system-ui, sans-serif' });
    },
  });
  knotPlot.canvas.dataset.plot = 'knots';

  /** `x` rounded to the knot snap (KNOT_SNAPS): the first step at least one pixel of the knot line wide. */
  function snapKnot(x) {
    const v = knotPlot.getView();
    const px = (v.xmax - v.xmin) / Math.max(1, knotPlot.canvas.clientWidth);
    const step = KNOT_SNAPS.find((st) => st >= px) ?? 1;
    return +(Math.round(x / step) * step).toFixed(6);
  }
  knotPlot.addHandles({
    name: 'moving knot',
    points: () => [[state.up, KNOT_ROW]],
    label: () => '',
    labelOf: () => `Knot u${state.p}`,
    color: PALETTE.ink, shape: 'triangle', radius: 9, axis: 'x', step: 0.02,
    constrain(_, q) { const [lo, hi] = upRange(); return [Math.min(hi, Math.max(lo, snapKnot(q[0]))), KNOT_ROW]; },
    move(_, q) { setUp(q[0]); },
    end() { ctx.save(); },
  });

  // ---------- surface data and plot ----------
  const S = { surf: null, orig: null, paths: [], env: null, limits: null, info: null, tracked: [] };

  function surfaceDesc() {
    const cp = [];
    for (let r = 0; r < SURF_N; r++) {
      const rowPts = [];
      for (let s = 0; s < SURF_N; s++) {
        const c = (SURF_N - 1) / 2;
        const z = 2.2 * Math.exp(-((r - c) ** 2 + (s - c) ** 2) / 5) + 0.4 * Math.sin(r + 0.7 * s);
        rowPts.push([r, s, z]);
      }
      cp.push(rowPts);
    }
    return { orderU: 3, orderV: 3, knotsU: surfKnots(), knotsV: surfKnots(), controlPoints: cp };
  }

  function computeSurface() {
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

  const surfWrap = h('div', { class: 'km-surface' });
  L.plots.appendChild(surfWrap);
  let framed = false, controlsReady = false;
  // The surface tab: the WebGL viewer (www/lib/view3d.js). Drag to orbit (or the Turn/Tilt sliders), wheel to zoom.
  const view = new View3D(surfWrap, {
    height: 500,
    ariaLabel: 'B-spline surface with moving knots (3D view): path-surfaces, envelope, corner limits',
    locked: true,
    onViewChange(v) {
      const yaw = Math.round(((((v.yaw + 180) % 360) + 360) % 360) - 180), pitch = Math.round(Math.min(89, Math.max(0, v.pitch)));
      const camera = [v.distance, ...v.target];
      if (yaw === state.yaw && pitch === state.pitch && String(camera) === String(state.camera)) return;
      state.yaw = yaw; state.pitch = pitch; state.camera = camera;
      if (controlsReady) { yawCtl.set(yaw); pitchCtl.set(pitch); }
      ctx.save();
    },
  });
  function drawSurface() {
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
      const c = S.limits.corners, idx = S.limits.cornerIndices;
      const names = ['(−∞,−∞)', '(−∞,+∞)', '(+∞,−∞)', '(+∞,+∞)'];
      for (let i = 0; i < 4; i++) { limitPts.push(c[3 * i], c[3 * i + 1], c[3 * i + 2]); limitLabels.push(`${names[i]}: d${sub(idx[i][0])},${sub(idx[i][1])}`); }
    }
    put('limits', limitLines.length > 0, () => view.setLines('limits', limitLines, { color: PALETTE.ink, width: 3 }));
    put('limitPts', limitPts.length > 0, () => view.setPoints('limitPts', limitPts, { color: PALETTE.ink, size: 10, labels: limitLabels, pickable: false }));
    put('tracked', !!S.trackedNow, () => view.setPoints('tracked', S.trackedNow, { colors: S.tracked.map((_, j) => pathColor(j)), size: 12, pickable: false }));
    view.setView({ yaw: state.yaw, pitch: state.pitch });
    if (!framed && surfWrap.style.display !== 'none') {
      view.fit(); framed = true;
      const c = state.camera;   // the zoom and target kept in the link
      if (Array.isArray(c) && c.length === 4 && c.every(Number.isFinite) && c[0] > 0) view.setView({ distance: c[0], target: c.slice(1) });
    }
    view.render();
  }
  // the rest of the demo redraws the surface tab through the same interface as a 2D plot
  const surfPlot = { canvas: view.canvas, redraw: drawSurface, destroy: () => view.destroy() };
  surfPlot.canvas.dataset.plot = 'surface';

  // ---------- controls ----------
  const tabCtl = buttonGroup({
    label: 'Show', options: [{ value: 'curve', label: 'Curve' }, { value: 'surface', label: 'Surface' }], value: state.tab,
    onChange(v) { state.tab = v; showTab(); ctx.save(); },
  });
  const extendCtl = toggle({
    label: 'Extend: let the knot pass its neighbours',
    value: state.extend,
    hint: mathText('\\text{Extended paths (paper §2): beyond } u_{p-1}, u_{p+1} \\text{ the pieces are continued algebraically; as } u_p \\to \\pm\\infty \\text{ the points of } [u_{p-1}, u_{p+1}) \\text{ run to a control point.}'),
    onChange(v) { state.extend = v; sanitize(); refreshControls(); recompute(); ctx.save(); },
  });
  const upCtl = slider({
    label: 'Moving knot value uₚ', min: 0, max: 1, step: 0.01, value: state.up, number: true,
    onInput(v) { knotPlayer.pause(); setUp(v); },
    onChange() { ctx.save(); },
  });
  // "Play u_p": the moving knot runs through its slider's range (the family and the path unfold)
  const knotPlayer = uPlayer({
    label: 'Play uₚ', duration: 8000,
    range: () => [Number(upCtl.input.min), Number(upCtl.input.max)], get: () => state.up,
    set(v) { setUp(v); upCtl.set(state.up); },
    onPause() { ctx.save(); },
  });
  const pCtl = buttonGroup({
    label: 'Which knot moves (index p)', options: [], value: state.p,
    onChange(v) { state.p = v; state.up = knots()[v]; sanitize(); refreshControls(); recompute(); ctx.save(); },
  });
  const pWrap = h('div', null, pCtl.el);
  const orderCtl = buttonGroup({
    label: 'Order k (degree k − 1)', options: [2, 3, 4, 5].map((v) => ({ value: v, label: String(v) })), value: state.order,
    onChange(v) { state.order = v; state.up = NaN; sanitize(); state.up = knots()[state.p]; rebuildP(); refreshControls(); recompute(); ctx.save(); },
  });
  const trackCtl = slider({
    label: 'Tracked points in [uₚ₋₁, uₚ₊₁)', min: 1, max: 7, step: 1, value: state.tracked,
    onInput(v) { state.tracked = v; recompute(); },
    onChange() { ctx.save(); },
  });
  const allCtl = toggle({
    label: 'Track one point in every affected span',
    value: state.trackAll,
    hint: 'Theorem 1: a point of the span p ± g moves on a rational curve of order k − g; in the outermost affected spans the paths are straight.',
    onChange(v) { state.trackAll = v; trackCtl.setDisabled(v); recompute(); ctx.save(); },
  });
  const famCtl = toggle({ label: 'Show the family (7 members)', value: state.showFamily, onChange(v) { state.showFamily = v; recompute(); ctx.save(); } });
  const envCtl = toggle({ label: 'Show the envelope', value: state.showEnvelope, onChange(v) { state.showEnvelope = v; redrawAll(); ctx.save(); } });
  const limCtl = toggle({ label: 'Show the limit control points', value: state.showLimits, onChange(v) { state.showLimits = v; redrawAll(); ctx.save(); } });
  const resetBtn = button({ label: 'Reset the knot', onClick() { state.up = knots()[state.p]; state.sup = surfKnots()[state.sp]; state.svq = surfKnots()[state.sq]; refreshControls(); recompute(); ctx.save(); } });
  const readoutTbl = table({ caption: ['Tracked points ', math('s(u; u_p)')], columns: ['u', 'x', 'y'], digits: 3 });
  const info = h('p', { class: 'ctl-hint km-info', 'aria-live': 'polite' });

  const supCtl = slider({
    label: 'Knot uₚ (surface)', min: 0, max: 1, step: 0.01, value: state.sup, number: true,
    onInput(v) { state.sup = v; computeSurface(); surfPlot.redraw(); refreshSurfaceInfo(); },
    onChange() { ctx.save(); },
  });
  const svqCtl = slider({
    label: ['Knot ', math('v_q'), ' (surface)'], min: 0, max: 1, step: 0.01, value: state.svq, number: true,
    onInput(v) { state.svq = v; computeSurface(); surfPlot.redraw(); refreshSurfaceInfo(); },
    onChange() { ctx.save(); },
  });
  const yawCtl = slider({ label: 'Turn', min: -180, max: 180, step: 1, value: state.yaw, onInput(v) { state.yaw = v; view.setView({ yaw: v }); }, onChange() { ctx.save(); } });
  const pitchCtl = slider({ label: 'Tilt', min: 0, max: 89, step: 1, value: state.pitch, onInput(v) { state.pitch = v; view.setView({ pitch: v }); }, onChange() { ctx.save(); } });
  const surfInfo = h('p', { class: 'ctl-hint', 'aria-live': 'polite' });

  if (options.locked) { resetBtn.setDisabled(true); }

  let stepsReady = false;   // the stepper must not clamp the step from the link before the data exists
  const steps = stepper({
    title: 'Moving uₚ, step by step',
    hint: 'The de Boor recursion at the first tracked point (the first diamond) with the moved knot: which intermediate points change when uₚ moves, each with its formula and the current numbers.',
    steps: deBoorSteps,
    get: () => state.step,
    set(i) { if (!stepsReady) return; state.step = i; redrawAll(); ctx.save(); },
  });
  steps.el.querySelector('.stepper-title').replaceChildren('Moving ', math('u_p'), ', step by step');
  const curveControls = group('Curve', orderCtl.el, pWrap, upCtl.el, h('div', { class: 'ctl-added' }, row(knotPlayer.el)), row(resetBtn.el), trackCtl.el, allCtl.el, readoutTbl.el, info, steps.el);
  const smoveCtl = buttonGroup({
    label: 'Knots that move', options: [{ value: 'both', label: ['uₚ and ', math('v_q')] }, { value: 'u', label: 'only uₚ' }, { value: 'v', label: ['only ', math('v_q')] }], value: state.smove,
    onChange(v) { state.smove = v; refreshControls(); computeSurface(); refreshSurfaceInfo(); surfPlot.redraw(); ctx.save(); },
  });
  const surfaceControls = group('Surface (orders 3 × 3, 8 × 8 control points)', smoveCtl.el, supCtl.el, svqCtl.el, yawCtl.el, pitchCtl.el, surfInfo);
  controlsReady = true;
  L.controls.append(group('Knot modification', tabCtl.el, extendCtl.el, famCtl.el, envCtl.el, limCtl.el), curveControls, surfaceControls);
  // "Use my data" (www/lib/data-import.js): your control points (6…16) for the curve tab; clamped knots 0, 1, 2, …
  if (!options.locked) curveControls.append(dataImport({ label: 'Use my control points', apply: 'Use these points', min: 6, max: 16, onData(pts) {
    state.points = pts; state.up = NaN; sanitize(); state.up = knots()[state.p]; rebuildP(); refreshControls(); recompute();
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 40); state.view = []; ctx.save();
  } }).el);

  function rebuildP() {
    const n = count() - 1;
    const opts = [];
    for (let i = k(); i <= n; i++) opts.push({ value: i, label: String(i) });
    const fresh = buttonGroup({
      label: 'Which knot moves (index p)', options: opts, value: state.p,
      onChange(v) { state.p = v; state.up = knots()[v]; sanitize(); refreshControls(); recompute(); ctx.save(); },
    });
    pWrap.replaceChildren(fresh.el);
    pCtlNow = fresh;
  }
  let pCtlNow = pCtl;

  function setUp(v) {
    const [lo, hi] = upRange();
    state.up = Math.min(hi, Math.max(lo, v));
    upCtl.set(state.up);
    computeCurve();
    refreshInfo();
    redrawAll();
  }

  function refreshInfo() {
    if (C.trackedPts) readoutTbl.set(C.trackedU.map((u, j) => [fmt(u, 3), C.trackedPts[2 * j], C.trackedPts[2 * j + 1]]));
    if (C.cur) {
      const [lo, hi] = C.cur.affectedSpans, [ra, rb] = C.cur.affectedRange;
      const [a, b] = nb();
      const outside = state.up < a || state.up > b;
      // plain text with Unicode indices, not MathML: this is a live region, and a screen reader announces the
      // text of MathML run together ("up→−∞" for uₚ → −∞)
      const up = `u${sub(state.p)}`;
      info.textContent = `Moving ${up} changes the spans ${lo}…${hi} only, u ∈ [${fmt(ra, 2)}, ${fmt(rb, 2)}] (at most 2(k − 1) = ${2 * (k() - 1)} spans). `
        + `Limits: ${up} → −∞ gives d${sub(state.p)}, ${up} → +∞ gives d${sub(state.p - k())}.`
        + (outside ? ` ${up} = ${fmt(state.up, 2)} is outside [${fmt(a, 2)}, ${fmt(b, 2)}]: an extended path.` : '');
    }
  }

  function refreshSurfaceInfo() {
    if (!S.surf) return;
    if (S.twoKnots) {
      const [ul, uh] = S.surf.affectedSpansU, [vl, vh] = S.surf.affectedSpansV;
      surfInfo.textContent = `Knots u${sub(state.sp)} and v${sub(state.sq)} move. Patches with span indices u ${ul}…${uh}, v ${vl}…${vh} are affected by both (highlighted; at most 4(k − 1)(l − 1) = 16 patches). Each tracked point moves on a path-surface; the envelope (8) is green; with "extend" the path-surfaces reach out to the four corner control points (Theorem 4).`;
    } else {
      const u = state.smove === 'u';
      const [lo, hi] = u ? S.surf.affectedSpansU : S.surf.affectedSpansV;
      const knot = u ? `u${sub(state.sp)}` : `v${sub(state.sq)}`;
      surfInfo.textContent = `Only ${knot} moves: the strip of patches with ${u ? 'u' : 'v'}-span ${lo}…${hi} changes (highlighted). The tracked points move on paths; the envelope (${u ? '6' : '6, in v'}) is green; the dashed black curves are the limits of Theorem 3 as ${knot} → ±∞ — B-spline curves of the control ${u ? 'rows' : 'columns'} ${u ? state.sp : state.sq} and ${u ? state.sp - 3 : state.sq - 3}.`;
    }
  }

  function refreshControls() {
    tabCtl.set(state.tab);
    extendCtl.set(state.extend);
    orderCtl.set(state.order);
    pCtlNow.set(state.p);
    const [lo, hi] = upRange();
    upCtl.setRange({ min: lo, max: hi });
    upCtl.set(state.up);
    trackCtl.set(state.tracked);
    trackCtl.setDisabled(state.trackAll);
    allCtl.set(state.trackAll);
    famCtl.set(state.showFamily);
    envCtl.set(state.showEnvelope);
    limCtl.set(state.showLimits);
    const [a, b] = surfRange(state.sp), [c, d] = surfRange(state.sq);
    supCtl.setRange({ min: a, max: b }); supCtl.set(state.sup);
    svqCtl.setRange({ min: c, max: d }); svqCtl.set(state.svq);
    smoveCtl.set(state.smove);
    supCtl.setDisabled(state.smove === 'v');
    svqCtl.setDisabled(state.smove === 'u');
    yawCtl.set(state.yaw); pitchCtl.set(state.pitch);
    const [kl, kh] = upRange(), t = knots();
    knotPlot.setView({ xmin: Math.min(kl, t[0]) - 0.6, xmax: Math.max(kh, t[t.length - 1]) + 0.6, ymin: -1, ymax: 1 });
  }

  function showTab() {
    const curve = state.tab === 'curve';
    const show = (el, on) => { el.style.display = on ? '' : 'none'; };
    show(curveWrap, curve);
    show(curveControls, curve);
    show(famCtl.el, curve);
    show(surfWrap, !curve);
    show(surfaceControls, !curve);
    steps.refresh();
    if (curve) { curvePlot.redraw(); knotPlot.redraw(); } else { computeSurface(); refreshSurfaceInfo(); surfPlot.redraw(); }
  }

  function redrawAll() { steps.refresh(); curvePlot.redraw(); knotPlot.redraw(); surfPlot.redraw(); }

  function recompute() {
    computeCurve();
    if (state.tab === 'surface') { computeSurface(); refreshSurfaceInfo(); }
    refreshInfo();
    redrawAll();
  }

  // ---------- explanation ----------
  explanation(L.explain, {
    what: [
      ['A B-spline curve ', math('a(u) = \\sum_r N_r^k(u)\\, d_r'), ' of order k is fixed by its control points and its knots. Replace one interior knot ', math('u_p'), ' by a new value: the curve changes only on the ', math('2(k-1)'), ' spans whose pieces use ', math('u_p'), ' (highlighted), and every curve point moves along a path — a rational curve in ', math('u_p'), ' (Theorem 1). The stepper “Moving uₚ, step by step” shows why: in the de Boor recursion at one parameter only the weights α whose interval ends at the moved knot contain it.'],
      ['While ', math('u_p'), ' stays between its neighbours the members of this one-parameter family all touch one curve, the envelope ', math('e(w)'), ': a B-spline of order ', math('k-1'), ' on the knots with ', math('u_p'), ' removed, using only the control points ', math('d_{p-k+1}, \\ldots, d_{p-1}'), ' (eq. (6)). The curve with knot value ', math('u_p'), ' touches the envelope at its own point ', math('u = u_p'), '.'],
      ['With "extend" the knot may pass its neighbours: the paths continue (extended paths) and, for the points with ', math('u \\in [u_{p-1}, u_{p+1})'), ', end in control points: ', math('d_p'), ' as ', math('u_p \\to -\\infty'), ' and ', math('d_{p-k}'), ' as ', math('u_p \\to +\\infty'), ' (Theorem 3). On a surface two knots move at once; points move on path-surfaces, and the corners of the ', math('(u_p, v_q)'), ' plane give the control points ', math('d_{p,q}, d_{p,q-l}, d_{p-k,q}, d_{p-k,q-l}'), ' (Theorem 4, with the paper\'s garbled list corrected).'],
      ['Outside its neighbours the knot vector is no longer ordered, so the whole "curve" is only the pieces of the de Boor recursion continued algebraically: far from ', math('[u_{p-1}, u_{p+1}]'), ' it may break apart or shoot off (the paths there have poles where ', math('u_p'), ' meets another knot). The paper\'s statements, and the tracked points here, are about ', math('u \\in [u_{p-1}, u_{p+1})'), '.'],
    ],
    math: [
      '\\text{family:}\\quad s(u,v;u_p) = \\sum_r \\sum_s N_r^k(u;u_p)\\, N_s^l(v)\\, d_{rs} \\qquad (5)',
      '\\text{envelope:}\\quad e(w,v) = \\sum_{r=p-k+1}^{p-1} \\sum_s N_r^{k-1}(w)\\, N_s^l(v)\\, d_{rs}, \\quad w \\in [u_{p-1}, u_{p+1}] \\qquad (6)',
      '\\text{contact:}\\quad \\frac{\\partial^i e}{\\partial w^i}(u_p, v) = \\frac{k-1-i}{k-1} \\cdot \\frac{\\partial^i s}{\\partial u^i}(u_p, v; u_p) \\qquad (9)',
      'e(u_p, v) = s(u_p, v; u_p), \\quad \\frac{\\partial e}{\\partial w} = (2-k)\\, \\frac{\\partial s}{\\partial u_p} \\qquad (10), \\;\\text{Thm 7}',
      '\\text{limits:}\\quad u_p \\to -\\infty: \\sum_s N_s^l(v)\\, d_{p,s}; \\quad u_p \\to +\\infty: \\sum_s N_s^l(v)\\, d_{p-k,s} \\qquad \\text{Thm 3}',
      '\\text{de Boor:}\\quad d_j^r = (1-\\alpha_j^r)\\, d_{j-1}^{r-1} + \\alpha_j^r\\, d_j^{r-1}, \\quad \\alpha_j^r = \\frac{u - u_j}{u_{j+k-r} - u_j}',
    ],
    tryThis: [
      'Drag the triangle on the knot line (or move the slider): the diamonds run along their paths, and only the highlighted part of the curve moves.',
      'Press Step in “Moving uₚ, step by step”: the de Boor points that contain the moved knot are drawn in red; move the knot and watch only those change.',
      ['Watch the green envelope: every light-blue family member touches it once, at ', math('u = u_p'), '.'],
      ['Switch on "extend" and push ', math('u_p'), ' far to the left or right: the paths of all tracked points end at the ringed control point ', math('d_p'), ' or ', math('d_{p-k}'), '.'],
      ['Choose order 2: the envelope degenerates to the control point ', math('d_{p-1}'), ' and the paths are straight segments.'],
      'Open the Surface tab and move both knots: the tracked points move on path-surfaces, and with "extend" their corners approach the four labelled control points.',
    ],
    formulaNote: ['Corrections (', correctionLink('correction-002-thm4', 'Theorem 4'), ', ', correctionLink('correction-002-envelope', 'the envelope’s knots'), '): two of the printed corner limits of Theorem 4 are wrong (shown here corrected), and the envelope uses the knot vector without the moving knot, which the paper does not define.'],
    paper: meta.paper,
  });

  // ---------- start ----------
  sanitize();
  stepsReady = true;
  rebuildP();
  if (!restoreView(curvePlot, state.view)) {
    state.view = [];
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 48);
  }
  refreshControls();
  computeCurve();
  refreshInfo();
  showTab();

  return {
    destroy() { steps.destroy(); knotPlayer.destroy(); curvePlot.destroy(); knotPlot.destroy(); surfPlot.destroy(); },
    // idle warm-up (www/lib/warm.js): a point drag's computation and drawing with the current state (same pixels;
    // no save, and no text rewritten in the live regions)
    warm() { computeCurve(); curvePlot.redraw(); knotPlot.redraw(); },
    // for the shell's Export row: the modified curve (curve tab) or surface (surface tab) and its data
    exports() {
      if (state.tab === 'surface') {
        if (!S.surf) return {};
        return {
          json: { surface: S.desc, moved: { p: state.sp, up: state.sup, q: state.sq, vq: state.svq, which: state.smove }, samples: { uv: S.surf.uv, points: S.surf.points } },
          obj: S.surf.mesh ? [{ name: 'knot_modified_surface', mesh: S.surf.mesh }] : [],
          csv: { points: S.surf.points, dim: S.surf.dim || 3 },
        };
      }
      if (!C.cur) return {};
      return {
        json: { curve: curveDesc(), p: state.p, up: state.up, affectedRange: C.cur.affectedRange, affectedSpans: C.cur.affectedSpans, limits: C.limits, samples: { params: C.cur.params, points: C.cur.points } },
        csv: { points: C.cur.points, dim: C.cur.dim || 2 },
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------
// (imports are hoisted: this block stays self-contained at the end of the file)
import { code, snippetCode } from '../lib/snippet.js';
import { dataImport } from '../lib/data-import.js';

/** The surface tab's control net (the same data as surfaceDesc() in mount). */
function snippetSurface() {
  const c = (SURF_N - 1) / 2;
  const controlPoints = Array.from({ length: SURF_N }, (_, r) => Array.from({ length: SURF_N }, (_, s) => [r, s, 2.2 * Math.exp(-((r - c) ** 2 + (s - c) ** 2) / 5) + 0.4 * Math.sin(r + 0.7 * s)]));
  return { orderU: 3, orderV: 3, knotsU: clampedKnots(3, SURF_N), knotsV: clampedKnots(3, SURF_N), controlPoints };
}

export function snippet(state) {
  if (state.tab === 'surface') {
    const mu = state.smove !== 'v', mv = state.smove !== 'u';
    const which = { ...(mu ? { p: state.sp } : {}), ...(mv ? { q: state.sq } : {}) };
    const vals = { ...(mu ? { up: state.sup } : {}), ...(mv ? { vq: state.svq } : {}) };
    return snippetCode(meta.title, code`
      // a bi-quadratic B-spline surface (orders 3, 3): knots and control points d_rs
      const surface = ${snippetSurface()};
      // which knots move (index p in u, q in v) …
      const which = ${which};
      // … and where to: the knot u_p becomes up, v_q becomes vq
      const moveTo = ${vals};
      const modified = sl.knotModifiedSurface({ surface, ...which, ...moveTo, samplesU: 41, samplesV: 41, mesh: true });
      const envelope = sl.knotEnvelope({ surface, ...which, samplesU: 11, samplesV: 11 });
      const limits = sl.knotLimits({ surface, ...which, samples: 80 });
      return { surface, modified, envelope, limits };
    `);
  }
  return snippetCode(meta.title, code`
    // a clamped B-spline curve: order k, knots, control points
    const curve = ${{ order: state.order, knots: clampedKnots(state.order, state.points.length), controlPoints: state.points }};
    // move the knot u_p to up (even past its neighbours)
    const p = ${state.p};
    const modified = sl.knotModifiedCurve({ curve, p, up: ${state.up}, samples: 400 });
    // the envelope of the family of curves as u_p runs between its neighbours, and the limits of the paths
    const envelope = sl.knotEnvelopeCurve({ curve, p, samples: 200 });
    const limits = sl.knotLimits({ curve, p });
    return { modified, envelope, limits };
  `);
}
