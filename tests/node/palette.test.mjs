// The figure palette (www/lib/plot2d/palette.js) against WCAG 2.2 SC 1.4.11 and colour-vision deficiency:
//  (a) every colour drawn as a line, marker or legend swatch has ≥ 3:1 contrast on the white plot and on the
//      #f6f6f3 page (swatches sit there); `grid` and `background` are exempt (grid lines are decorative: no value is
//      read from them alone — ticks, axis labels and the readout give the numbers);
//  (b) under simulated protanopia, deuteranopia and tritanopia (Machado, Oliveira & Fernandes 2009, severity 1.0,
//      applied to linear RGB) and under normal vision, every pair of SERIES colours and every pair of named figure
//      colours drawn together differs by CIEDE2000 ΔE₀₀ ≥ MIN_DE;
//  (c) the CSS variables at the top of www/style.css equal the palette, so the two cannot drift.
//
// MIN_DE = 8: ΔE₀₀ ≈ 1–2.3 is a just-noticeable difference for large patches seen side by side; our marks are
// 2–3 px lines and 5–8 px markers, for which discrimination is several times coarser (Szafir 2017, "Modeling
// Color Difference for Visualization Design", finds the noticeable step grows steeply as marks shrink), so we ask
// for about four JNDs. 10 is not reachable with eight series colours that are all ≥ 3:1 on white: the
// constraint squeezes every colour into CIE L* ≲ 62, and a dichromat has only lightness and one hue axis left.
// Pairs that are compared in a figure also differ by dash pattern, marker or a label (issue 25), so colour is
// never the only cue; this threshold keeps colour a useful second cue.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { PALETTE, SERIES } from '../../www/lib/plot2d/palette.js';

const MIN_CONTRAST = 3;
const MIN_DE = 8;
const PAGE_BG = '#f6f6f3';
/** Not judged for contrast: grid lines are decorative, background is what the others are judged on. */
const DECORATIVE = new Set(['grid', 'background']);
/** Named colours drawn together in a figure. The greys (polygon, muted) are compared with every hue but not with
 * each other: CVD does not change greys, and the two always differ in dash (polygon dashed, muted dotted/ghost).
 * yellow is left out: no figure draws it (add it here when one does). ink/focus are text/outline colours. */
const DRAWN_TOGETHER = ['curve', 'control', 'highlight', 'second', 'accent', 'sky', 'polygon', 'muted'];
const NOT_COMPARED = new Set(['polygon|muted']);

// ---------- colour maths ----------
const rgb = (hex) => {
  const h = hex.replace('#', '');
  const full = h.length === 3 ? [...h].map((c) => c + c).join('') : h;
  return [0, 2, 4].map((i) => parseInt(full.slice(i, i + 2), 16) / 255);
};
const linear = (c) => (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);
/** WCAG 2.x relative luminance. */
const luminance = (hex) => { const [r, g, b] = rgb(hex).map(linear); return 0.2126 * r + 0.7152 * g + 0.0722 * b; };
export const contrast = (a, b) => {
  const [hi, lo] = [luminance(a), luminance(b)].sort((p, q) => q - p);
  return (hi + 0.05) / (lo + 0.05);
};
/** Machado, Oliveira & Fernandes (2009), severity 1.0; rows act on linear RGB. */
const MACHADO = {
  protanopia: [[0.152286, 1.052583, -0.204868], [0.114503, 0.786281, 0.099216], [-0.003882, -0.048116, 1.051998]],
  deuteranopia: [[0.367322, 0.860646, -0.227968], [0.280085, 0.672501, 0.047413], [-0.011820, 0.042940, 0.968881]],
  tritanopia: [[1.255528, -0.076749, -0.178779], [-0.078411, 0.930809, 0.147602], [0.004733, 0.691367, 0.303900]],
};
const clamp01 = (v) => Math.min(1, Math.max(0, v));
/** CIELAB (D65) of a colour as seen through `matrix` (undefined: normal vision). */
function lab(hex, matrix) {
  let lin = rgb(hex).map(linear);
  if (matrix) lin = matrix.map((row) => clamp01(row[0] * lin[0] + row[1] * lin[1] + row[2] * lin[2]));
  const [r, g, b] = lin;
  const X = (0.4124564 * r + 0.3575761 * g + 0.1804375 * b) / 0.95047;
  const Y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
  const Z = (0.0193339 * r + 0.1191920 * g + 0.9503041 * b) / 1.08883;
  const f = (t) => (t > 216 / 24389 ? Math.cbrt(t) : (24389 / 27 * t + 16) / 116);
  return [116 * f(Y) - 16, 500 * (f(X) - f(Y)), 200 * (f(Y) - f(Z))];
}
/** CIEDE2000 (Sharma, Wu & Dalal 2005). */
export function deltaE2000([L1, a1, b1], [L2, a2, b2]) {
  const rad = Math.PI / 180;
  const Cbar = (Math.hypot(a1, b1) + Math.hypot(a2, b2)) / 2;
  const G = 0.5 * (1 - Math.sqrt(Cbar ** 7 / (Cbar ** 7 + 25 ** 7)));
  const a1p = (1 + G) * a1, a2p = (1 + G) * a2;
  const C1p = Math.hypot(a1p, b1), C2p = Math.hypot(a2p, b2);
  const hue = (b, a) => (a === 0 && b === 0 ? 0 : (Math.atan2(b, a) / rad + 360) % 360);
  const h1p = hue(b1, a1p), h2p = hue(b2, a2p);
  let dh = 0;
  if (C1p * C2p !== 0) { dh = h2p - h1p; if (dh > 180) dh -= 360; else if (dh < -180) dh += 360; }
  const dL = L2 - L1, dC = C2p - C1p, dH = 2 * Math.sqrt(C1p * C2p) * Math.sin(dh * rad / 2);
  const Lb = (L1 + L2) / 2, Cbp = (C1p + C2p) / 2;
  let hb = h1p + h2p;
  if (C1p * C2p !== 0) { if (Math.abs(h1p - h2p) > 180) hb = hb < 360 ? hb + 360 : hb - 360; hb /= 2; }
  const T = 1 - 0.17 * Math.cos((hb - 30) * rad) + 0.24 * Math.cos(2 * hb * rad) + 0.32 * Math.cos((3 * hb + 6) * rad) - 0.20 * Math.cos((4 * hb - 63) * rad);
  const dTheta = 30 * Math.exp(-(((hb - 275) / 25) ** 2));
  const RC = 2 * Math.sqrt(Cbp ** 7 / (Cbp ** 7 + 25 ** 7));
  const SL = 1 + 0.015 * (Lb - 50) ** 2 / Math.sqrt(20 + (Lb - 50) ** 2), SC = 1 + 0.045 * Cbp, SH = 1 + 0.015 * Cbp * T;
  const RT = -Math.sin(2 * dTheta * rad) * RC;
  return Math.sqrt((dL / SL) ** 2 + (dC / SC) ** 2 + (dH / SH) ** 2 + RT * (dC / SC) * (dH / SH));
}

/** Pairs closer than MIN_DE, as readable lines. */
function closePairs(named, vision) {
  const matrix = MACHADO[vision];
  const out = [];
  for (let i = 0; i < named.length; i++) {
    for (let j = i + 1; j < named.length; j++) {
      const [[n1, c1], [n2, c2]] = [named[i], named[j]];
      if (NOT_COMPARED.has(`${n1}|${n2}`) || NOT_COMPARED.has(`${n2}|${n1}`)) continue;
      const d = deltaE2000(lab(c1, matrix), lab(c2, matrix));
      if (d < MIN_DE) out.push(`${n1} ${c1} / ${n2} ${c2}: ΔE₀₀ ${d.toFixed(2)}`);
    }
  }
  return out;
}

test('the CIEDE2000 and contrast formulas give the published reference values', () => {
  // Sharma, Wu & Dalal (2005), test pairs 1 and 24
  assert.equal(deltaE2000([50, 2.6772, -79.7751], [50, 0, -82.7485]).toFixed(4), '2.0425');
  assert.equal(deltaE2000([50, 2.5, 0], [73, 25, -18]).toFixed(4), '27.1492');
  assert.equal(contrast('#000000', '#ffffff'), 21);
  assert.equal(contrast('#767676', '#ffffff').toFixed(2), '4.54');
});

test('(a) every non-decorative figure colour has ≥ 3:1 contrast on the white plot and on the page', () => {
  const low = [];
  const colours = [...Object.entries(PALETTE).filter(([k]) => !DECORATIVE.has(k)), ...SERIES.map((c, i) => [`SERIES[${i}]`, c])];
  for (const [name, c] of colours) {
    for (const bg of ['#ffffff', PAGE_BG]) {
      const r = contrast(c, bg);
      if (r < MIN_CONTRAST) low.push(`${name} ${c} on ${bg}: ${r.toFixed(2)}:1`);
    }
  }
  assert.deepEqual(low, [], `below ${MIN_CONTRAST}:1 (WCAG 2.2 SC 1.4.11):\n${low.join('\n')}`);
});

for (const vision of ['normal', 'protanopia', 'deuteranopia', 'tritanopia']) {
  test(`(b) ${vision}: SERIES colours and the named colours drawn together differ by ΔE₀₀ ≥ ${MIN_DE}`, () => {
    const series = SERIES.map((c, i) => [`SERIES[${i}]`, c]);
    const named = DRAWN_TOGETHER.map((k) => [k, PALETTE[k]]);
    const close = [...closePairs(series, vision), ...closePairs(named, vision)];
    assert.deepEqual(close, [], `too close under ${vision}:\n${close.join('\n')}`);
  });
}

test('(c) the CSS variables at the top of www/style.css equal the palette', () => {
  const css = readFileSync(new URL('../../www/style.css', import.meta.url), 'utf8');
  const root = css.slice(css.indexOf(':root'), css.indexOf('}', css.indexOf(':root')));
  const norm = (hex) => { const h = hex.toLowerCase().replace('#', ''); return `#${h.length === 3 ? [...h].map((c) => c + c).join('') : h}`; };
  // --c-muted is the muted *text* colour (#4d4d4d, 4.5:1 for text), a different role from PALETTE.muted
  const mirrored = ['curve', 'control', 'polygon', 'highlight', 'second', 'accent', 'sky', 'yellow', 'ink'];
  const differ = [];
  for (const k of mirrored) {
    const m = root.match(new RegExp(`--c-${k}:\\s*(#[0-9a-fA-F]{3,6})\\s*;`));
    if (!m) differ.push(`--c-${k} missing`);
    else if (norm(m[1]) !== norm(PALETTE[k])) differ.push(`--c-${k} ${m[1]} ≠ PALETTE.${k} ${PALETTE[k]}`);
  }
  assert.deepEqual(differ, []);
  const bg = root.match(/--c-bg:\s*(#[0-9a-fA-F]{3,6})\s*;/);
  assert.equal(bg && norm(bg[1]), PAGE_BG, 'the page background the swatches are judged on');
});
