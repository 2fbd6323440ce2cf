// What a 2D curve figure shows, in words (issue 25, "figures in words"): the core measures the demo's own samples
// (curveFacts: extremes, inflections, length, distances to the data) and this module turns the facts into one or
// two plain sentences for the figure's description. Continuity at the joints is not measured: the construction
// knows it, so the demo states it (bsplineContinuityWords here for a B-spline's knots, a fixed sentence otherwise).

import { fmt, pairSep } from './dom.js';
import { t, tn, list } from './i18n.js';
import { subscript, superscript } from './indices.js';

/** A number to 3 significant digits like the readouts (dom.js's fmt: no exponent, a true minus sign, −0 → 0). */
export function sig3(x) {
  if (!Number.isFinite(x)) return String(x);
  if (Math.abs(x) < 5e-4) return '0';
  return fmt(Number(x.toPrecision(3)), Math.min(20, Math.max(0, 2 - Math.floor(Math.log10(Math.abs(x))))));
}

const pt = (p) => `(${sig3(p.x)}${pairSep()}${sig3(p.y)})`;

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
  const at = (p) => t('{point} at {u} = {v}', { point: pt(p), u, v: sig3(p.u) });
  const n = f.inflectionParams.length;
  let infl = n === 0 ? t('it has no inflections') : tn(n, 'it has one inflection', 'it has {n} inflections');
  if (n > 0 && n <= 4) {
    const where = Array.from(f.inflectionParams, (v, i) => `(${sig3(f.inflectionPoints[2 * i])}${pairSep()}${sig3(f.inflectionPoints[2 * i + 1])}), ${u} = ${sig3(v)}`);
    infl = t('{these}, at {where}', { these: infl, where: where.join('; ') });
  }
  let s = t('{name} runs from x = {a} to {b}; its highest point is {high}, its lowest {low}; {inflections}; its length is {length}.', {
    name: t(name), a: sig3(f.leftmost.x), b: sig3(f.rightmost.x), high: at(f.highest), low: at(f.lowest), inflections: infl, length: sig3(f.length),
  });
  if (f.distances && f.distances.length > 0) {
    const far = t('farthest: {name}, {d}', { name: dataName(f.maxDistanceIndex), d: sig3(f.maxDistance) });
    s += ` ${f.maxDistance < 5e-4
      ? t('It passes through every data point ({far}).', { far })
      : t('It passes within {d} of every data point ({far}; RMS {rms}).', { d: sig3(f.maxDistance), far, rms: sig3(f.rmsDistance) })}`;
  }
  return s;
}

/**
 * A clamped B-spline's continuity at its inner knots in words: C^(p−m) at a knot of multiplicity m.
 * @param {number} degree @param {number[]} knots the full knot vector
 */
export function bsplineContinuityWords(degree, knots) {
  const inner = knots.slice(degree + 1, knots.length - degree - 1);
  if (inner.length === 0) return t('It is one polynomial piece: no inner knots.');
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
    const where = tn(us.length, 'the knot u = {list}', 'the knots u = {list}', { list: us.map(sig3).join(pairSep()) });
    return k < 0 ? t('breaks at {where}', { where }) : t('is C{k} at {where}', { k: superscript(k), where });
  });
  return t('At its joints it {parts} (degree {p}: C{sp}⁻ᵐ at a knot of multiplicity m).', { parts: list(parts), p: degree, sp: superscript(degree) });
}
