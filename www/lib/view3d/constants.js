// View3D defaults shared by its parts: angles, field of view, the default camera and colours.

export const DEG = Math.PI / 180;
export const FOV = 35 * DEG;
export const POINT_COLOR = [0xd5 / 255, 0x5e / 255, 0];   // vermillion, the playground's control-point colour
export const DEFAULT_VIEW = { yaw: -60 * DEG, pitch: 28 * DEG };
// Okabe–Ito colour-blind-safe palette (as style.css / plot2d.js): default surface colours, in order
export const PALETTE = ['#0072B2', '#E69F00', '#009E73', '#CC79A7', '#56B4E9', '#D55E00'];
