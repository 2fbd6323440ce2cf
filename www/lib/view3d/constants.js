// View3D defaults shared by its parts: angles, field of view, the default camera and colours.
import { PALETTE as FIGURE } from '../plot2d/palette.js';

/** '#rrggbb' → [r, g, b] in 0…1. */
const rgb01 = (hex) => [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16) / 255);

export const DEG = Math.PI / 180;
export const FOV = 35 * DEG;
export const POINT_COLOR = rgb01(FIGURE.control);   // the playground's control-point colour
export const DEFAULT_VIEW = { yaw: -60 * DEG, pitch: 28 * DEG };
// The figure palette (plot2d/palette.js, ≥ 3:1 on white): default surface colours, in order
export const PALETTE = [FIGURE.curve, FIGURE.accent, FIGURE.second, FIGURE.highlight, FIGURE.sky, FIGURE.control];
