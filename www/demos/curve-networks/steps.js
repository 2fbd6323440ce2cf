// The stepper of "Curve networks": the Gordon boolean sum G = L₁ + L₂ − L₁₂ (eq. (39)) stage by stage, then the
// criss-cross surface S = Σ Cᵢⱼ Bᵢⱼ (Lemma 3.1) summed row by row, with the values at one probe point: the middle
// vertex of the u-major sample grid of networkSurfaces (the values come from the core; the partial sums from the
// terms of compute.js).
import { fmt } from '../../lib/dom.js';
import { mathText } from '../../lib/mathml.js';

export const STEP_SEQ = ['L1', 'L2', 'Tg', 'G'];

/** The probe's grid indices (iu, iv) and its index i into the u-major samples. */
export const probeIndex = (state) => { const N = state.density, iu = Math.floor(N / 2), iv = Math.floor(N / 2); return { iu, iv, i: iu * N + iv }; };
/** The probe's (u, v) on the network's domain. */
export function probeUV(state, net) {
  const { iu, iv } = probeIndex(state), N = state.density - 1, m = net.u.length - 1, n = net.v.length - 1;
  return [net.u[0] + (net.u[m] - net.u[0]) * iu / N, net.v[0] + (net.v[n] - net.v[0]) * iv / N];
}
export const probeTex = (state, net) => { const [u, v] = probeUV(state, net); return `(u, v) = (${fmt(u, 3)}, ${fmt(v, 3)})`; };

/** The probe's point on surface k of c.result, or on the partial sum 'P' of the current step (null: none). */
export function probeVal(k, state, { result }, model) {
  if (k === 'P') { const P = model.partialSum(state.step - 4); const i = probeIndex(state).i; return P ? [P[3 * i], P[3 * i + 1], P[3 * i + 2]] : null; }
  const s = result && result.surfaces[k];
  if (!s) return null;
  const i = probeIndex(state).i;
  return [s.points[3 * i], s.points[3 * i + 1], s.points[3 * i + 2]];
}
const vec = (p) => (p ? `(${fmt(p[0], 3)}, ${fmt(p[1], 3)}, ${fmt(p[2], 3)})` : '?');

/** S assembled from its terms, one step per row i: the row's sum at the probe, the partial sum, Σ B (→ 1), and at
 * the last row the largest distance of the full sum from the core's S on the whole grid. */
function sSteps(state, c, model) {
  const T = model.crissCrossTerms();
  if (!T || !c.result || !c.result.surfaces.S) return [];
  const { i: q } = probeIndex(state);
  const [u, v] = probeUV(state, c.net);
  const at = `(${fmt(u, 3)}, ${fmt(v, 3)})`;
  const S = c.result.surfaces.S.points;
  const out = [];
  let unity = 0;
  for (let i = 0; i < T.rows; i++) {
    const row = [0, 0, 0];
    for (let j = 0; j < T.cols; j++) {
      const b = T.B[i * T.cols + j][q], c3 = 3 * (i * T.cols + j);
      unity += b;
      for (let k = 0; k < 3; k++) row[k] += b * T.C[c3 + k];
    }
    const P = model.partialSum(i);
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

/** Every step of the stepper (the S steps are computed only once the stepper gets there). */
export function booleanSteps(state, c, model) {
  if (!c.net) return [];
  const m = c.net.u.length - 1, n = c.net.v.length - 1;
  const [u, v] = probeUV(state, c.net);
  const at = `(${fmt(u, 3)}, ${fmt(v, 3)})`;
  const val = (k) => probeVal(k, state, c, model);
  const L1 = val('L1'), L2 = val('L2'), T = val('Tg'), G = val('G');
  const z = (p) => (p ? fmt(p[2], 4) : '?');
  const zs = (p) => (p && p[2] < 0 ? `(${fmt(p[2], 4)})` : z(p));
  return [
    { label: 'L1, the surface skinned through the curves φᵣ (v-curves)',
      tex: ['L_1(u_r, v) = \\varphi_r(v), \\quad r = 0, \\ldots, m', `(u, v) = ${at}`, `L_1 = ${vec(L1)}`],
      note: `L1 interpolates the ${m + 1} curves φᵣ on the lines u = uᵣ, but not the ψₛ.` },
    { label: 'L2, the surface skinned through the curves ψₛ (u-curves)',
      tex: ['L_2(u, v_s) = \\psi_s(u), \\quad s = 0, \\ldots, n', `(u, v) = ${at}`, `L_2 = ${vec(L2)}`],
      note: `L2 interpolates the ${n + 1} curves ψₛ on the lines v = vₛ.` },
    { label: 'L12, the tensor surface through the intersection points Iᵣₛ',
      tex: ['L_{12}(u_r, v_s) = I_{rs} = \\varphi_r(v_s) = \\psi_s(u_r)', `(u, v) = ${at}`, `L_{12} = ${vec(T)}`],
      note: `L12 (Tg in the other controls) interpolates only the ${(m + 1) * (n + 1)} points Iᵣₛ; on the network lines it equals what L1 and L2 have in common.` },
    { label: 'G = L1 + L2 − L12, the Gordon surface',
      tex: ['G = L_1 + L_2 - L_{12} \\qquad (39)', `(u, v) = ${at}`, `G_z = ${z(L1)} + ${zs(L2)} - ${zs(T)} = ${z(G)}`, `G = ${vec(G)}`],
      note: 'On u = uᵣ: L1 = φᵣ and L2 = L12, so G = φᵣ; likewise on v = vₛ. G interpolates the whole network.' },
    // then the criss-cross surface, assembled from its B_ij (computed only once the stepper gets there)
    ...(state.step >= 3 ? sSteps(state, c, model) : Array.from({ length: m + 2 }, (_, i) => ({ label: `S assembled: row i = ${i} of the terms ${mathText('C_{ij} B_{ij}')} added`, tex: ['S = \\sum_{i=0}^{m+1} \\sum_{j=0}^{n+1} C_{ij} B_{ij}(u, v)'] }))),
  ];
}
