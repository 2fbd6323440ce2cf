// The texts of SplineLab in this language (www/lib/i18n.js loads this file only for a page shown in it): the
// shell, gallery and shared controls (core), the exercises and their page (exercises), the demos (demos), the
// words of formulas read aloud (math).
import core from './hu/core.js';
import exercises from './hu/exercises.js';
import demos from './hu/demos.js';
import math from './hu/math.js';

export default { ...core, ...exercises, ...demos, ...math };
