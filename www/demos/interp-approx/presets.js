// The data of "Interpolating vs approximating" (Kuklišová): the default shape, the limits on the number of points
// and the samples, and the paper's figures as presets (the paper prints no coordinates: the data are chosen to
// show the same effect). A preset's `state` is laid over defaults() (entry module) when it is applied.

export const MAX_POINTS = 30;
export const SAMPLES = 600;

export const SHAPE = [[-0.6, -0.4], [0, 0], [0.6, 1.6], [1.8, 2.4], [2.4, 2.2], [3.6, 0.2], [4.4, 0.1], [5.6, 1.8], [6.4, 2.2], [7.6, 1.2], [8.2, 0.6]];

// The paper's figures as presets (the paper prints no coordinates: the data are chosen to show the same effect).
export const PRESETS = {
  fig6: {
    label: 'Fig. 6: a = −0.1 … 0.2',
    state: {
      points: [[-1, 0], [0, 0], [1, 2], [2, 2.2], [3, 0.2], [4, 0], [5, 2], [6, 2.2], [7, 0.4], [8, 0.2]],
      construction: 'section3', knots: 'uniform', a: 0, p: 0.05, autoTension: 'off', useK: false,
      family: { key: 'a', values: [-0.1, 0, 0.1, 0.2] },
    },
    note: 'Fig. 6 (section 3, uniform): the approximation parameter a = −0.1, 0, 0.1, 0.2. a < 0 overshoots the data, a = 0 interpolates, a > 0 approximates.',
  },
  fig7: {
    label: 'Fig. 7: p = 0 … 0.3',
    state: {
      points: [[-1, 0], [0, 0], [1, 2], [2, 2.2], [3, 0.2], [4, 0], [5, 2], [6, 2.2], [7, 0.4], [8, 0.2]],
      construction: 'section3', knots: 'uniform', a: 0, p: 0.1, autoTension: 'off', useK: false,
      family: { key: 'p', values: [0, 0.1, 0.2, 0.3] },
    },
    note: 'Fig. 7 (section 3, a = 0): the tension p = 0, 0.1, 0.2, 0.3. Larger p pulls the even control vertices outwards: rounder, fuller curves.',
  },
  fig8: {
    label: 'Fig. 8: uneven spacing (uniform)',
    state: {
      points: [[-0.3, -0.3], [0, 0], [0.25, 0.3], [0.5, 0.35], [4, 0.6], [4.3, 1], [4.4, 3.6], [4.7, 4], [5.2, 4.1], [5.6, 4.2]],
      construction: 'section3', knots: 'uniform', a: 0, p: 1 / 12, autoTension: 'off', useK: false, family: null,
    },
    note: 'Fig. 8: the uniform construction of section 3 on unevenly spaced data overshoots and loops on the long edges.',
  },
  fig10: {
    label: 'Fig. 10: the chord-length cure',
    state: {
      points: [[-0.3, -0.3], [0, 0], [0.25, 0.3], [0.5, 0.35], [4, 0.6], [4.3, 1], [4.4, 3.6], [4.7, 4], [5.2, 4.1], [5.6, 4.2]],
      construction: 'nonuniform', knots: 'chord', a: 0, p: 1 / 6, autoTension: 'off', useK: false, family: null,
    },
    note: 'Fig. 10: the non-uniform curve (chord-length knots, eq. (8)) on the same data: no loops.',
  },
  fig13: {
    label: 'Fig. 13: stairs, K off',
    state: {
      points: [[-1, 0], [0, 0], [3, 0], [3, 0.5], [6, 0.5], [6, 1], [9, 1], [9, 1.5], [12, 1.5], [13, 1.5]],
      construction: 'nonuniform', knots: 'chord', a: 0, p: 1 / 6, autoTension: 'off', useK: false, K: 20, family: null,
    },
    note: 'Fig. 13: a staircase of long and short edges: with the standard split knots the curve swings away from the long edges (max. distance to the polygon 0.25).',
  },
  fig14: {
    label: 'Fig. 14: K = 20',
    state: {
      points: [[-1, 0], [0, 0], [3, 0], [3, 0.5], [6, 0.5], [6, 1], [9, 1], [9, 1.5], [12, 1.5], [13, 1.5]],
      construction: 'nonuniform', knots: 'chord', a: 0, p: 1 / 6, autoTension: 'off', useK: true, K: 20, family: null,
    },
    note: 'Fig. 14: the modified knots u′₂ᵢ = (uᵢ₋₁ + K·uᵢ + uᵢ₊₁)/(K + 2) with K = 20 follow the polygon better (max. distance 0.15).',
  },
  fig19: {
    label: 'Fig. 19: automatic tension',
    state: {
      points: SHAPE.map((q) => [...q]), construction: 'nonuniform', knots: 'chord', a: 0, p: 1 / 6,
      autoTension: 'paper', autoScale: 0.2, useK: false, family: null,
    },
    note: 'Automatic tension pᵢ = p·|cos αᵢ + cos αᵢ₊₁|/2 with p = 0.2 (the printed formula).',
  },
};
