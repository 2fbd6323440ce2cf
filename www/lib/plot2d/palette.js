// The playground's Okabe–Ito colour-blind-safe colours for 2D plots (mirrors the CSS variables in style.css).

/** Okabe–Ito colour-blind-safe palette (mirrors the CSS variables in style.css). */
export const PALETTE = {
  curve: '#0072B2',      // blue
  control: '#D55E00',    // vermillion
  polygon: '#6b6b6b',    // grey
  highlight: '#CC79A7',  // reddish purple
  second: '#009E73',     // bluish green
  accent: '#E69F00',     // orange
  sky: '#56B4E9',        // sky blue
  yellow: '#F0E442',
  ink: '#111111',
  muted: '#8a8a8a',
  grid: '#e3e3e3',
  axis: '#7a7a7a',
  background: '#ffffff',
  focus: '#111111',
};
/** Series colours for many curves (basis functions…), cycled. */
export const SERIES = ['#0072B2', '#D55E00', '#009E73', '#CC79A7', '#E69F00', '#56B4E9', '#000000', '#882255'];
