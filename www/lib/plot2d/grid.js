// Grid lines, axis lines, tick values and axis names of a 2D plot (drawn first, under the demo's drawing).

import { fmt } from '../dom.js';
import { PALETTE } from './palette.js';
import { niceStep, tickDigits } from './view.js';

/** Draws the grid, axes, ticks and axis names for transform `tf` on a W × H px canvas (options `o`: grid, axes, ticks, xLabel, yLabel). */
export function drawGrid(g, { tf, W, H, o, sx, sy }) {
  const { xmin, xmax, ymin, ymax } = tf;
  const stepX = niceStep(xmax - xmin, W / 90), stepY = niceStep(ymax - ymin, H / 60);
  g.lineWidth = 1;
  if (o.grid) {
    g.strokeStyle = PALETTE.grid;
    g.beginPath();
    for (let x = Math.ceil(xmin / stepX) * stepX; x <= xmax; x += stepX) { const X = Math.round(sx(x)) + 0.5; g.moveTo(X, 0); g.lineTo(X, H); }
    for (let y = Math.ceil(ymin / stepY) * stepY; y <= ymax; y += stepY) { const Y = Math.round(sy(y)) + 0.5; g.moveTo(0, Y); g.lineTo(W, Y); }
    g.stroke();
  }
  if (o.axes) {
    g.strokeStyle = PALETTE.axis;
    g.lineWidth = 1.5;
    g.beginPath();
    if (xmin <= 0 && xmax >= 0) { const X = Math.round(sx(0)) + 0.5; g.moveTo(X, 0); g.lineTo(X, H); }
    if (ymin <= 0 && ymax >= 0) { const Y = Math.round(sy(0)) + 0.5; g.moveTo(0, Y); g.lineTo(W, Y); }
    g.stroke();
  }
  if (o.ticks) {
    g.font = '12px system-ui, sans-serif';
    g.fillStyle = '#444';
    const ax = Math.min(H - 4, Math.max(14, ymin <= 0 && ymax >= 0 ? sy(0) + 14 : H - 4));
    const dx = tickDigits(stepX), dy = tickDigits(stepY);
    g.textAlign = 'center'; g.textBaseline = 'alphabetic';
    for (let x = Math.ceil(xmin / stepX) * stepX; x <= xmax; x += stepX) {
      const X = sx(x);
      if (X < 16 || X > W - 16) continue;
      if (o.axes && Math.abs(x) < stepX / 2 && xmin <= 0 && xmax >= 0 && ymin <= 0 && ymax >= 0) { g.textAlign = 'right'; g.fillText('0', X - 4, ax); g.textAlign = 'center'; continue; }
      g.fillText(fmt(x, dx), X, ax);
    }
    const ay = Math.min(W - 30, Math.max(4, xmin <= 0 && xmax >= 0 ? sx(0) + 4 : 4));
    g.textAlign = 'left'; g.textBaseline = 'middle';
    for (let y = Math.ceil(ymin / stepY) * stepY; y <= ymax; y += stepY) {
      const Y = sy(y);
      if (Y < (o.yLabel ? 24 : 10) || Y > H - 20 || Math.abs(y) < stepY / 2) continue;
      g.fillText(fmt(y, dy), ay, Y);
    }
    if (o.xLabel) { g.textAlign = 'right'; g.textBaseline = 'bottom'; g.font = 'italic 14px system-ui, sans-serif'; g.fillText(o.xLabel, W - 6, Math.min(H - 2, ax - 14)); }
    if (o.yLabel) { g.textAlign = 'left'; g.textBaseline = 'top'; g.font = 'italic 14px system-ui, sans-serif'; g.fillText(o.yLabel, ay + 2, 4); }
  }
}

/**
 * A cached grid layer: `draw(g, { tf, W, H, o, sx, sy, ratio }, canvas)` paints the grid, axes and ticks once
 * into an offscreen canvas of the plot canvas's size, at the plot's pixel ratio `ratio` (device px per CSS px,
 * the same scale the plot paints with), and then copies it pixel for pixel while the view, the size, the ratio
 * and the options stay the same (a drag redraws the plot every frame; its grid does not change). A recording
 * context (the SVG export shadows the context's methods with its own) gets the vector drawing.
 */
export function createGridLayer() {
  let layer = null, key = '';
  return function draw(g, p, canvas) {
    const { tf, W, H, o } = p;
    if (Object.prototype.hasOwnProperty.call(g, 'drawImage') || typeof document === 'undefined' || !canvas) { drawGrid(g, p); return; }
    const ratio = p.ratio || canvas.width / W;
    const k = [tf.xmin, tf.xmax, tf.ymin, tf.ymax, tf.kx, tf.ky, W, H, ratio, canvas.width, canvas.height, o.grid, o.axes, o.ticks, o.xLabel, o.yLabel].join('|');
    if (k !== key) {
      if (!layer) layer = document.createElement('canvas');
      if (layer.width !== canvas.width) layer.width = canvas.width;
      if (layer.height !== canvas.height) layer.height = canvas.height;
      const lg = layer.getContext('2d');
      if (!lg) { drawGrid(g, p); return; }
      lg.setTransform(1, 0, 0, 1, 0, 0);
      lg.clearRect(0, 0, layer.width, layer.height);
      lg.setTransform(ratio, 0, 0, ratio, 0, 0);
      drawGrid(lg, p);
      key = k;
    }
    g.save();
    g.setTransform(1, 0, 0, 1, 0, 0);
    g.drawImage(layer, 0, 0);
    g.restore();
  };
}
