// What the curve tab computes (every value from the wasm API) into C = { cur, orig, affected, trackedU,
// trackedPts, paths, env, touch, family, limits, db }: the curve with u_p moved (knotModifiedCurve, eq. (5)), the
// original, the affected part, the paths of the tracked points (knotPathsCurve, Theorem 1; with "extend" the
// extended paths of §2), the envelope (knotEnvelopeCurve, eq. (6)) and its contact point, the family, the limits
// of Theorem 3 (knotLimits) and the de Boor triangle of the stepper (knotDeBoorCurve).
import { FAR, knots, nb, curveDesc } from './knots.js';

/** The parameters of the tracked points: `tracked` evenly in [u_{p−1}, u_{p+1}), or the middle of every affected span. */
function trackedParams(state, C) {
  if (state.trackAll && C.cur) {
    // one point in the middle of every affected span (bookkeeping on the knot vector)
    const t = knots(state), [lo, hi] = C.cur.affectedSpans, us = [];
    for (let i = lo; i <= hi; i++) if (t[i + 1] > t[i]) us.push((t[i] + t[i + 1]) / 2);
    return us;
  }
  const [a, b] = nb(state);
  const m = state.tracked;
  return Array.from({ length: m }, (_, j) => a + (b - a) * (j + 0.5) / m);
}

export function computeCurve(wasm, state, notify, C) {
  try {
    const curve = curveDesc(state);
    C.cur = wasm.knotModifiedCurve({ curve, p: state.p, up: state.up, samples: 400 });
    C.orig = wasm.knotModifiedCurve({ curve, p: state.p, up: knots(state)[state.p], samples: 300 });
    const [ra, rb] = C.cur.affectedRange;
    C.affected = wasm.knotModifiedCurve({ curve, p: state.p, up: state.up, at: Array.from({ length: 201 }, (_, i) => ra + (rb - ra) * i / 200) });
    C.trackedU = trackedParams(state, C);
    const [a, b] = nb(state);
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
