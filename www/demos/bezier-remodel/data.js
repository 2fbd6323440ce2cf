// The paper's data for the "Bézier remodelling" demo (Gânscă–Coman–Ţămbulea): the quadratic example of §3 with
// the α of Figs. 1–2, a quartic B-spline for r = 2, the §4 surface table with the α of Figs. 4–5, and the
// bi-degree net of §4.2 (ours: the paper prints none).

// §3: a quadratic Bézier spline, 11 control points, breakvalues 0, 1, 7/4, 5/2, 13/4, 4
export const EXAMPLE_POINTS = [[10, 16], [7, 21], [3, 9], [0, 0], [-4, 0], [-8, 0], [-6, 3], [-4, 6], [2, 2], [8, -2], [10, 3]];
export const EXAMPLE_BREAKS = [0, 1, 7 / 4, 5 / 2, 13 / 4, 4];
export const FIG1 = [[2 / 3, 1 / 20], [19 / 20, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 10]];
export const FIG2 = [[1 / 10, 1 / 10], [9 / 10, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 100], [99 / 100, 1 / 5]];
// a quartic B-spline (C³) turned into Bézier form with bsplineToBezier: here C² can be kept (r = 2 ≤ ⌊4/2⌋)
export const QUARTIC = { degree: 4, knots: [0, 0, 0, 0, 0, 1, 2, 3, 3, 3, 3, 3], points: [[0, 0], [1.5, 4], [4, 5.5], [6.5, 2], [8, -1.5], [11, -1], [12.5, 2.5]] };
export const CURVE_PRESETS = [
  { value: 'fig1', label: 'Fig. 1' },
  { value: 'fig2', label: 'Fig. 2' },
  { value: 'classical', label: 'Classical (g* = g)' },
  { value: 'quartic', label: 'Quartic from a B-spline' },
];

// §4.1: the surface table (rows k = 0..6 along u, columns l = 0..3 along v; repeated rows merged)
export const SURFACE_POINTS = [
  [[0, 0, 3], [0, 1, 2], [0, 3, 1], [0, 4, 3]],
  [[1, 0, 1], [1, 1, 4], [1, 3, 2], [1, 4, 4]],
  [[2, 0, 2.5], [2, 1, 3], [2, 3, 1], [2, 4, 3]],
  [[3, 0, 4], [3, 1, 2], [3, 3, 0], [3, 4, 2]],
  [[4, 0, 2.5], [4, 1, 3], [4, 3, 1], [4, 4, 2.5]],
  [[5, 0, 1], [5, 1, 4], [5, 3, 2], [5, 4, 3]],
  [[6, 0, 3], [6, 1, 0], [6, 3, 1], [6, 4, 2]],
];
export const SURFACE_PRESETS = {
  fig4: { label: 'Fig. 4: usual elevation (2/3, 1/3)', alphas: [[2 / 3, 1 / 3], [2 / 3, 1 / 3], [2 / 3, 1 / 3]], enforce: true },
  literal: { label: 'Fig. 4 text taken literally: all α = 1/3 (not C¹)', alphas: [[1 / 3, 1 / 3], [1 / 3, 1 / 3], [1 / 3, 1 / 3]], enforce: false },
  fig5: { label: 'Fig. 5: (1/2, 1/500), (·, 1/1000), (·, 4/5)', alphas: [[1 / 2, 1 / 500], [499 / 500, 1 / 1000], [999 / 1000, 4 / 5]], enforce: true },
};

// §4.2, the bi-degree remodelling: the §4 table with its v-patch split at v = 1 (a biquadratic net, 3 × 2 patches,
// C¹ in u and v): columns y = 0, 1, 2, 3, 4 where the y = 2 column is the midpoint of its neighbours (the C¹ joint in v).
export const BI_POINTS = [
  [[0, 0, 3], [0, 1, 2], [0, 2, 1.5], [0, 3, 1], [0, 4, 3]],
  [[1, 0, 1], [1, 1, 4], [1, 2, 3], [1, 3, 2], [1, 4, 4]],
  [[2, 0, 2.5], [2, 1, 3], [2, 2, 2], [2, 3, 1], [2, 4, 3]],
  [[3, 0, 4], [3, 1, 2], [3, 2, 1], [3, 3, 0], [3, 4, 2]],
  [[4, 0, 2.5], [4, 1, 3], [4, 2, 2], [4, 3, 1], [4, 4, 2.5]],
  [[5, 0, 1], [5, 1, 4], [5, 2, 3], [5, 3, 2], [5, 4, 3]],
  [[6, 0, 3], [6, 1, 0], [6, 2, 0.5], [6, 3, 1], [6, 4, 2]],
];
export const BI_BREAKS_U = [0, 1, 2, 3];
export const BI_BREAKS_V = [0, 1, 2];
export const BI_M = 2, BI_N = 2, BI_COLS = 5, BI_SEGS_U = 3, BI_SEGS_V = 2;
export const BI_NU = 61, BI_NV = 41;   // samples: u = 1, 2 at iu = 20, 40; v = 1 at iv = 20
