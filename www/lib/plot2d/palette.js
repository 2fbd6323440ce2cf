// The playground's figure colours for 2D plots (mirrored by the CSS variables at the top of style.css; 3D views
// take theirs from view3d/constants.js, built from these). They keep the hues of the Okabe–Ito colour-blind-safe
// palette, made dark enough for WCAG 2.2 SC 1.4.11 (every colour drawn as a line, marker or swatch has at least
// 3:1 contrast against the white plot and the #f6f6f3 page) and spaced so that each pair drawn together stays
// apart under simulated protanopia, deuteranopia and tritanopia. tests/node/palette.test.mjs checks all three
// and that style.css says the same; change a colour here and there together.

/** Named figure colours. `grid` is decorative (the eye does not need it to read a value) and exempt from 3:1. */
export const PALETTE = {
  curve: '#0072B2',      // blue (Okabe–Ito, unchanged: 5.2:1)
  control: '#B0571C',    // vermillion, darker (Okabe–Ito #D55E00 stood too close to the darkened orange)
  polygon: '#6b6b6b',    // grey
  highlight: '#D9009A',  // reddish purple, stronger (Okabe–Ito #CC79A7 was 3.06:1 on white, 2.83:1 on the page)
  second: '#0B8E67',     // bluish green, darker (Okabe–Ito #009E73 was 3.16:1 on the page)
  accent: '#B7811C',     // orange, darker (Okabe–Ito #E69F00 was 2.25:1)
  sky: '#3C95C4',        // sky blue, darker (Okabe–Ito #56B4E9 was 2.31:1)
  yellow: '#8B8505',     // yellow, darkened to olive (Okabe–Ito #F0E442 was 1.32:1); no figure draws it yet
  ink: '#111111',
  muted: '#8a8a8a',
  grid: '#e3e3e3',
  axis: '#7a7a7a',
  background: '#ffffff',
  focus: '#111111',
  wine: '#771047',       // Paul Tol's wine, the series' last colour
  black: '#000000',
};
/** Series colours for many curves (basis functions…), cycled. */
export const SERIES = [PALETTE.curve, PALETTE.control, PALETTE.second, PALETTE.highlight, PALETTE.accent, PALETTE.sky, PALETTE.black, PALETTE.wine];
