// What a 2D curve figure shows, in words (issue 25, "figures in words"): the core measures the demo's own samples
// (curveFacts: extremes, inflections, length, distances to the data) and this module turns the facts into one or
// two plain sentences for the figure's description. Continuity at the joints is not measured: the construction
// knows it, so the demo states it (bsplineContinuityWords here for a B-spline's knots, a fixed sentence otherwise).

import { fmt } from './dom.js';
import { subscript, superscript } from './indices.js';

/** A number to 3 significant digits like the readouts (dom.js's fmt: no exponent, a true minus sign, −0 → 0). */
export function sig3(x) {
  if (!Number.isFinite(x)) return String(x);
  if (Math.abs(x) < 5e-4) return '0';
  return fmt(Number(x.toPrecision(3)), Math.min(20, Math.max(0, 2 - Math.floor(Math.log10(Math.abs(x))))));
}

const pt = (p) => `(${sig3(p.x)}, ${sig3(p.y)})`;
const count = (n, one, many) => (n === 0 ? `no ${many}` : n === 1 ? `one ${one}` : `${n} ${many}`);

/**
 * The facts of a sampled curve `{ params, points }` (a result of the demo's own wasm call) with the distances to
 * `data` (flat x, y or [x, y] pairs) when given; null when the module has no curveFacts or the call fails (then
 * the description simply says less). Memoised on the result and data objects: describe() runs at every redraw.
 * @param {any} wasm @param {{ params: Float64Array, points: Float64Array } | null | undefined} curve
 * @param {Float64Array | number[][] | null} [data]
 */
export function curveFactsOf(wasm, curve, data = null) {
  if (!curve || typeof wasm?.curveFacts !== 'function') return null;
  const known = memo.get(curve);
  if (known && known.data === data) return known.facts;
  let facts = null;
  try {
    const flatData = data && !(data instanceof Float64Array) ? Float64Array.from(data.flat()) : data;
    facts = wasm.curveFacts({ points: curve.points, params: curve.params, ...(flatData ? { data: flatData } : {}) });
  } catch { facts = null; }
  memo.set(curve, { data, facts });
  return facts;
}
/** @type {WeakMap<object, { data: any, facts: any }>} the facts of each curve result (and the data they measured) */
const memo = new WeakMap();

/**
 * One or two sentences: the curve's span in x, its highest and lowest points, its inflections; with data, how
 * close it passes to every data point and which is farthest.
 * @param {any} f curveFacts result (or null: '')
 * @param {{ u?: string, dataName?: (i: number) => string, name?: string }} [o] the parameter's name, the name of
 *   data point i (default Wᵢ), the curve's name (default "The curve")
 */
export function curveWords(f, { u = 'u', dataName = (i) => `W${subscript(i)}`, name = 'The curve' } = {}) {
  if (!f) return '';
  const at = (p) => `${pt(p)} at ${u} = ${sig3(p.u)}`;
  const n = f.inflectionParams.length;
  let infl = `it has ${count(n, 'inflection', 'inflections')}`;
  if (n > 0 && n <= 4) {
    const list = Array.from(f.inflectionParams, (v, i) => `(${sig3(f.inflectionPoints[2 * i])}, ${sig3(f.inflectionPoints[2 * i + 1])}), ${u} = ${sig3(v)}`);
    infl += `, at ${list.join('; ')}`;
  }
  let s = `${name} runs from x = ${sig3(f.leftmost.x)} to ${sig3(f.rightmost.x)}; its highest point is ${at(f.highest)}, its lowest ${at(f.lowest)}; ${infl}; its length is ${sig3(f.length)}.`;
  if (f.distances && f.distances.length > 0) {
    const far = `farthest: ${dataName(f.maxDistanceIndex)}, ${sig3(f.maxDistance)}`;
    s += f.maxDistance < 5e-4
      ? ` It passes through every data point (${far}).`
      : ` It passes within ${sig3(f.maxDistance)} of every data point (${far}; RMS ${sig3(f.rmsDistance)}).`;
  }
  return s;
}

/**
 * A clamped B-spline's continuity at its inner knots in words: C^(p−m) at a knot of multiplicity m.
 * @param {number} degree @param {number[]} knots the full knot vector
 */
export function bsplineContinuityWords(degree, knots) {
  const inner = knots.slice(degree + 1, knots.length - degree - 1);
  if (inner.length === 0) return 'It is one polynomial piece: no inner knots.';
  /** @type {Map<number, number[]>} continuity order → the distinct inner knots with it */
  const byOrder = new Map();
  for (let i = 0; i < inner.length;) {
    let m = 1;
    while (i + m < inner.length && inner[i + m] === inner[i]) m += 1;
    const order = degree - m;
    byOrder.set(order, [...(byOrder.get(order) ?? []), inner[i]]);
    i += m;
  }
  const parts = [...byOrder.entries()].sort((a, b) => b[0] - a[0]).map(([k, us]) => {
    const where = `${us.length === 1 ? 'the knot' : 'the knots'} u = ${us.map(sig3).join(', ')}`;
    return k < 0 ? `breaks at ${where}` : `is C${superscript(k)} at ${where}`;
  });
  return `At its joints it ${parts.join(' and ')} (degree ${degree}: C${superscript(degree)}⁻ᵐ at a knot of multiplicity m).`;
}
