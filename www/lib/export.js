// Exporters for figures and data: PNG of a canvas, SVG of a 2D drawing, JSON of a construction, OBJ of a
// surface mesh, CSV of sampled points. Each builds the file and returns it (text, or a Promise of a Blob for
// PNG); pass a file name to also download it. The text outputs are deterministic and parse back.
//
//   exportPNG(canvas, 'figure.png')                 → Promise<Blob>
//   exportSlidePNG(plot | view3d | canvas, { scale: 2, legend: [...], caption }, 'figure.png') → Promise<Blob>
//                                                    (re-rendered at the scale, legend and caption under it)
//   exportSVG(drawing, 'figure.svg')                → SVG text (see `toSVG` for the drawing description)
//   exportJSON(obj, 'construction.json')            → JSON text (typed arrays become arrays)
//   exportOBJ(mesh | [{ name, mesh }], 'surface.obj') → Wavefront OBJ text (v / vn / f a//a b//b c//c)
//   exportCSV(flatPoints, dim, 'points.csv', { header }) → CSV text (header x,y[,z] by default)
//   plotToSVG(plot, 'figure.svg')                → SVG text of a 2D plot (plot2d.js) exactly as drawn
//   canvasToSVG(ctx2d, paint, { width, height, scale }) → SVG text of whatever paint() draws on a 2D context
//   exportButtons({ name, png, svg, json, obj, csv, onError }) → a row of buttons for a demo's controls
//   download(textOrBlob, 'name.ext', mime)          → triggers a download

/** Triggers a browser download of a Blob or text. */
export function download(data, filename, mime = 'text/plain') {
  const blob = data instanceof Blob ? data : new Blob([data], { type: `${mime};charset=utf-8` });
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = safeName(filename);
  a.rel = 'noopener';
  a.style.display = 'none';
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 2000);
  return blob;
}

/** A file name without path separators or control characters. */
export function safeName(name) {
  // biome-ignore lint/suspicious/noControlCharactersInRegex: control characters are what this removes from a file name
  const s = String(name ?? 'splinelab').replace(/[\\/:*?"<>|\u0000-\u001f]+/g, '_').slice(0, 120);
  return s || 'splinelab';
}

/** Number formatting for text exports: shortest round-trip up to 10 significant digits, no exponent noise for 0. */
export function num(v, digits = 10) {
  if (!Number.isFinite(v)) return 'NaN';
  if (v === 0) return '0';
  return String(Number(v.toPrecision(digits)));
}

// ---------------------------------------------------------------- PNG

/**
 * PNG of a canvas (2D or WebGL; a WebGL canvas needs preserveDrawingBuffer, as View3D has, or a synchronous
 * redraw just before). Resolves to the Blob; downloads it when `filename` is given.
 */
export function exportPNG(canvas, filename) {
  return new Promise((resolve, reject) => {
    if (!canvas || typeof canvas.toBlob !== 'function') { reject(new Error('canvas: expected a <canvas> element')); return; }
    canvas.toBlob((blob) => {
      if (!blob) { reject(new Error('canvas: could not encode a PNG (empty or tainted canvas)')); return; }
      if (filename) download(blob, filename);
      resolve(blob);
    }, 'image/png');
  });
}

// ---------------------------------------------------------------- PNG for slides

/**
 * Renders a view into a new canvas at `scale` × its CSS size, re-drawn at that resolution (not a scaled bitmap):
 * a plot2d plot paints itself with its pixel ratio set to the scale (`plot.renderAt`: the screen's own paint,
 * every layer — grid cache, curves, handles, labels — at k device px per CSS px); a View3D renders its GL canvas
 * with the device pixel ratio set to the scale (View3D caps it at 2, so 4× of a 3D view is 2× —
 * `canvas.dataset.scale` says what was reached); any other canvas is copied as it is. Returns { canvas, scale,
 * width, height } (CSS px).
 */
export function renderAtScale(source, scale = 2) {
  const k = Math.max(1, Math.min(8, Number(scale) || 1));
  if (source && typeof source.renderAt === 'function' && source.canvas) {
    const out = source.renderAt(k);
    out.dataset.scale = String(k);
    return { canvas: out, scale: k, width: source.width, height: source.height };
  }
  if (source && typeof source.renderNow === 'function' && source.canvas) {
    const c = source.canvas, W = c.clientWidth, H = c.clientHeight;
    const reached = Math.min(k, 2);
    const out = document.createElement('canvas');
    // window.devicePixelRatio is an own (configurable) property of the window: shadow it for one render and
    // put the original descriptor back
    const own = Object.getOwnPropertyDescriptor(window, 'devicePixelRatio');
    let shadowed = false;
    try {
      try { Object.defineProperty(window, 'devicePixelRatio', { configurable: true, get: () => reached }); shadowed = true; } catch { /* not configurable: device resolution */ }
      source.renderNow();
      out.width = c.width; out.height = c.height;
      const og = out.getContext('2d');
      og.drawImage(c, 0, 0);
      // the axes and tick values are a 2D canvas over the GL one, painted by the same render at the same ratio
      const ov = source.overlay;
      if (ov && typeof ov.getContext === 'function' && ov.width && ov.height) og.drawImage(ov, 0, 0, out.width, out.height);
    } finally {
      if (shadowed) {
        if (own) Object.defineProperty(window, 'devicePixelRatio', own);
        else delete window.devicePixelRatio;
      }
      source.renderNow();
    }
    out.dataset.scale = String(out.width / Math.max(1, W));
    return { canvas: out, scale: out.width / Math.max(1, W), width: W, height: H };
  }
  const c = source;
  if (!c || typeof c.getContext !== 'function') throw new Error('source: expected a plot, a View3D or a <canvas>');
  const W = c.clientWidth || c.width, H = c.clientHeight || c.height;
  const out = document.createElement('canvas');
  out.width = Math.round(W * k); out.height = Math.round(H * k);
  out.getContext('2d').drawImage(c, 0, 0, out.width, out.height);
  out.dataset.scale = String(k);
  return { canvas: out, scale: k, width: W, height: H };
}

/** Splits text into lines that fit `maxWidth` with the context's current font. */
function wrapText(g, text, maxWidth) {
  const words = String(text).split(/\s+/).filter(Boolean);
  const lines = [];
  let line = '';
  for (const w of words) {
    const t = line ? `${line} ${w}` : w;
    if (line && g.measureText(t).width > maxWidth) { lines.push(line); line = w; } else line = t;
  }
  if (line) lines.push(line);
  return lines;
}

/**
 * A figure for slides: the view re-rendered at `scale` (1, 2, 4), optionally with the legend drawn under it
 * (`legend`: [{ label, color, kind: 'line'|'dashed'|'dot'|'band'|'ramp', stops (ramp colours), alpha }]) and a caption (dark text) at the
 * bottom. The bands are laid out in CSS px and drawn at the same scale. Returns the canvas (its dataset holds
 * scale, cssWidth, cssHeight and plotHeight); exportSlidePNG() encodes it.
 */
export function slideCanvas(source, { scale = 2, legend: items = null, caption = '' } = {}) {
  const r = renderAtScale(source, scale);
  const k = r.scale, W = r.width;
  const pad = 10, font = 'system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';
  const meas = document.createElement('canvas').getContext('2d');
  // legend rows: swatch 26 px + gap 6 + text, items 18 px apart, rows 22 px high
  const rows = [];
  if (Array.isArray(items) && items.length) {
    meas.font = `14px ${font}`;
    let row = [], x = pad;
    for (const it of items) {
      const w = 32 + meas.measureText(String(it.label)).width;
      if (row.length && x + w > W - pad) { rows.push(row); row = []; x = pad; }
      row.push({ ...it, x, w });
      x += w + 18;
    }
    if (row.length) rows.push(row);
  }
  meas.font = `16px ${font}`;
  const capLines = caption && String(caption).trim() ? wrapText(meas, String(caption).trim(), W - 2 * pad) : [];
  const legendH = rows.length ? rows.length * 22 + pad : 0;
  const capH = capLines.length ? capLines.length * 22 + pad + 4 : 0;
  const H = r.height + legendH + capH;
  const out = document.createElement('canvas');
  out.width = r.canvas.width;
  out.height = r.canvas.height + Math.round((legendH + capH) * k);
  const g = out.getContext('2d');
  g.fillStyle = '#ffffff';
  g.fillRect(0, 0, out.width, out.height);
  g.drawImage(r.canvas, 0, 0);
  g.setTransform(k, 0, 0, k, 0, 0);
  let y = r.height + pad / 2;
  for (const row of rows) {
    const cy = y + 11;
    for (const it of row) {
      const col = it.color || '#111111';
      g.save();
      g.globalAlpha = it.alpha ?? 1;
      if (it.kind === 'dot') {
        g.fillStyle = col; g.beginPath(); g.arc(it.x + 13, cy, 5, 0, 2 * Math.PI); g.fill();
      } else if (it.kind === 'ramp' && Array.isArray(it.stops) && it.stops.length > 1) {
        // a colour map: the same ramp as the swatch on the page
        const ramp = g.createLinearGradient(it.x, 0, it.x + 26, 0);
        it.stops.forEach((c, i) => ramp.addColorStop(i / (it.stops.length - 1), c));
        g.fillStyle = ramp; g.fillRect(it.x, cy - 5, 26, 10);
      } else {
        g.strokeStyle = col;
        g.lineWidth = it.kind === 'band' ? 8 : 4;
        g.setLineDash(it.kind === 'dashed' ? [6, 4] : it.kind === 'dotted' ? [2, 4] : []);
        g.beginPath(); g.moveTo(it.x, cy); g.lineTo(it.x + 26, cy); g.stroke();
      }
      g.restore();
      g.fillStyle = '#111111'; g.font = `14px ${font}`; g.textBaseline = 'middle';
      g.fillText(String(it.label), it.x + 32, cy);
    }
    y += 22;
  }
  if (capLines.length) {
    y = r.height + legendH + pad / 2 + 2;
    g.fillStyle = '#111111'; g.font = `16px ${font}`; g.textBaseline = 'top';
    for (const line of capLines) { g.fillText(line, pad, y + 2); y += 22; }
  }
  out.dataset.scale = String(k);
  out.dataset.cssWidth = String(W);
  out.dataset.cssHeight = String(H);
  out.dataset.plotHeight = String(r.height);
  return out;
}

/** slideCanvas() as a PNG Blob (downloaded when `filename` is given). */
export function exportSlidePNG(source, options = {}, filename) {
  return exportPNG(slideCanvas(source, options), filename);
}

// ---------------------------------------------------------------- SVG

const esc = (s) => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;').replace(/'/g, '&#39;');
/** A CSS colour safe to put in an attribute (hex, rgb()/rgba()/hsl(), a named colour, 'none'); else the fallback. */
function color(c, fallback) {
  if (typeof c !== 'string') return fallback;
  const s = c.trim();
  if (/^#[0-9a-f]{3,8}$/i.test(s) || /^(rgb|rgba|hsl|hsla)\([0-9.,%\s/-]+\)$/i.test(s) || /^[a-z]{3,20}$/i.test(s)) return s;
  return fallback;
}
const finite = (v, d) => (Number.isFinite(v) ? v : d);

/** Points as pairs: [[x, y], …] or a flat [x0, y0, x1, y1, …] (2D; with `dim` 3 the z is dropped). */
function pairs(points, dim = 2) {
  if (!points) return [];
  if (ArrayBuffer.isView(points) || (Array.isArray(points) && typeof points[0] === 'number')) {
    const out = [];
    for (let i = 0; i + 1 < points.length; i += dim) out.push([points[i], points[i + 1]]);
    return out;
  }
  return Array.from(points, (p) => [p?.[0], p?.[1]]);
}

/**
 * Builds an SVG document from a drawing description:
 *
 *   { width = 640, height = 480, title, background = '#ffffff',
 *     bounds: { xmin, xmax, ymin, ymax }   // optional: data coordinates mapped onto the canvas, y up;
 *                                          // without it coordinates are SVG pixels, y down
 *     layers: [
 *       { type: 'polyline', points, dim, stroke = '#222', width = 2, dash: [6, 4], closed, fill = 'none', opacity, id },
 *       { type: 'points', points, dim, r = 4, fill = '#d62728', stroke = '#111', labels: ['P0', …], id },
 *       { type: 'text', x, y, text, size = 14, anchor = 'start' | 'middle' | 'end', fill = '#111' },
 *     ] }
 *
 * Polylines become <path> elements (NaN points break the path), points <circle>s, labels and text <text>
 * (escaped). A 2D plot can describe its layers in this form.
 */
export function toSVG(drawing = {}) {
  const W = finite(drawing.width, 640), H = finite(drawing.height, 480);
  const b = drawing.bounds;
  let tx = (x) => x, ty = (y) => y;
  if (b && [b.xmin, b.xmax, b.ymin, b.ymax].every(Number.isFinite) && b.xmax > b.xmin && b.ymax > b.ymin) {
    tx = (x) => ((x - b.xmin) / (b.xmax - b.xmin)) * W;
    ty = (y) => H - ((y - b.ymin) / (b.ymax - b.ymin)) * H;
  }
  const f = (v) => num(v, 7);
  const out = [];
  out.push('<?xml version="1.0" encoding="UTF-8"?>');
  out.push(`<svg xmlns="http://www.w3.org/2000/svg" width="${f(W)}" height="${f(H)}" viewBox="0 0 ${f(W)} ${f(H)}">`);
  if (drawing.title) out.push(`<title>${esc(drawing.title)}</title>`);
  const bg = color(drawing.background, '#ffffff');
  if (bg !== 'none') out.push(`<rect x="0" y="0" width="${f(W)}" height="${f(H)}" fill="${esc(bg)}"/>`);
  for (const layer of drawing.layers || []) {
    if (!layer || typeof layer !== 'object') continue;
    const idAttr = typeof layer.id === 'string' && /^[A-Za-z][\w-]*$/.test(layer.id) ? ` id="${layer.id}"` : '';
    const op = Number.isFinite(layer.opacity) ? ` opacity="${f(Math.min(1, Math.max(0, layer.opacity)))}"` : '';
    if (layer.type === 'polyline') {
      let d = '', pen = false;
      for (const [x, y] of pairs(layer.points, layer.dim || 2)) {
        if (!Number.isFinite(x) || !Number.isFinite(y)) { pen = false; continue; }
        d += `${pen ? 'L' : (d ? ' M' : 'M')}${f(tx(x))} ${f(ty(y))}`;
        pen = true;
      }
      if (!d) continue;
      if (layer.closed) d += 'Z';
      const dash = Array.isArray(layer.dash) && layer.dash.every(Number.isFinite) ? ` stroke-dasharray="${layer.dash.map(f).join(' ')}"` : '';
      out.push(`<path${idAttr} d="${d}" fill="${esc(color(layer.fill, 'none'))}" stroke="${esc(color(layer.stroke, '#222222'))}" `
        + `stroke-width="${f(finite(layer.width, 2))}" stroke-linejoin="round" stroke-linecap="round"${dash}${op}/>`);
    } else if (layer.type === 'points') {
      const r = finite(layer.r, 4);
      const fill = esc(color(layer.fill, '#d62728')), stroke = esc(color(layer.stroke, '#111111'));
      const labels = Array.isArray(layer.labels) ? layer.labels : [];
      out.push(`<g${idAttr}${op}>`);
      pairs(layer.points, layer.dim || 2).forEach(([x, y], i) => {
        if (!Number.isFinite(x) || !Number.isFinite(y)) return;
        out.push(`<circle cx="${f(tx(x))}" cy="${f(ty(y))}" r="${f(r)}" fill="${fill}" stroke="${stroke}" stroke-width="1.5"/>`);
        if (labels[i] != null && labels[i] !== '') {
          out.push(`<text x="${f(tx(x) + r + 3)}" y="${f(ty(y) - r - 3)}" font-family="sans-serif" font-size="${f(finite(layer.labelSize, 13))}" fill="#111111">${esc(labels[i])}</text>`);
        }
      });
      out.push('</g>');
    } else if (layer.type === 'text') {
      const x = finite(layer.x, 0), y = finite(layer.y, 0);
      const anchor = ['start', 'middle', 'end'].includes(layer.anchor) ? layer.anchor : 'start';
      const px = layer.data === false || !b ? [x, y] : [tx(x), ty(y)];
      out.push(`<text${idAttr} x="${f(px[0])}" y="${f(px[1])}" font-family="sans-serif" font-size="${f(finite(layer.size, 14))}" `
        + `text-anchor="${anchor}" fill="${esc(color(layer.fill, '#111111'))}"${op}>${esc(layer.text ?? '')}</text>`);
    }
  }
  out.push('</svg>');
  return out.join('\n') + '\n';
}

/** SVG text of a drawing (see `toSVG`); downloads it when `filename` is given. */
export function exportSVG(drawing, filename) {
  const text = toSVG(drawing);
  if (filename) download(text, filename, 'image/svg+xml');
  return text;
}

// ---------------------------------------------------------------- JSON

/** JSON text (2-space indent; typed arrays become arrays, non-finite numbers null); downloads it when `filename` is given. */
export function exportJSON(obj, filename) {
  const text = JSON.stringify(obj, (key, value) => {
    if (ArrayBuffer.isView(value) && !(value instanceof DataView)) return Array.from(value, (v) => (typeof v === 'number' && !Number.isFinite(v) ? null : v));
    if (typeof value === 'number' && !Number.isFinite(value)) return null;
    if (typeof value === 'bigint') return Number(value);
    return value;
  }, 2);
  if (filename) download(text + '\n', filename, 'application/json');
  return text;
}

// ---------------------------------------------------------------- OBJ

/**
 * Wavefront OBJ of one mesh `{ positions, normals?, indices }` (flat xyz / triangles, e.g. a wasm `mesh`) or of
 * several `[{ name, mesh }]` (one `o` group each). Faces use 1-based indices `f a//a b//b c//c` when normals are
 * present, `f a b c` otherwise. Downloads it when `filename` is given.
 */
export function exportOBJ(meshes, filename) {
  const list = Array.isArray(meshes) ? meshes : [{ name: 'surface', mesh: meshes }];
  const out = ['# SplineLab surface export'];
  let base = 0;
  list.forEach((entry, k) => {
    const m = entry?.mesh;
    if (!m || !m.positions || !m.indices) throw new Error(`mesh${list.length > 1 ? `[${k}]` : ''}: expected { positions, indices }`);
    const P = m.positions, I = m.indices, N = m.normals && m.normals.length === P.length ? m.normals : null;
    const nv = Math.floor(P.length / 3);
    const name = String(entry.name ?? `surface${k}`).replace(/[^\w.-]+/g, '_') || `surface${k}`;
    out.push(`o ${name}`);
    for (let i = 0; i < nv; i++) out.push(`v ${num(P[3 * i])} ${num(P[3 * i + 1])} ${num(P[3 * i + 2])}`);
    if (N) for (let i = 0; i < nv; i++) out.push(`vn ${num(N[3 * i], 7)} ${num(N[3 * i + 1], 7)} ${num(N[3 * i + 2], 7)}`);
    for (let t = 0; t + 2 < I.length; t += 3) {
      const a = I[t], b = I[t + 1], c = I[t + 2];
      if (!(a < nv && b < nv && c < nv)) throw new Error(`mesh.indices: index out of range at triangle ${t / 3}`);
      const A = a + 1 + base, B = b + 1 + base, C = c + 1 + base;
      out.push(N ? `f ${A}//${A} ${B}//${B} ${C}//${C}` : `f ${A} ${B} ${C}`);
    }
    base += nv;
  });
  const text = out.join('\n') + '\n';
  if (filename) download(text, filename, 'model/obj');
  return text;
}

// ---------------------------------------------------------------- CSV

/**
 * CSV of flat points (`dim` numbers per point, e.g. a wasm `points` array), one point per row, with a header
 * (`x,y` / `x,y,z` by default; `header: false` to omit, or an array of column names). Downloads it when
 * `filename` is given.
 */
export function exportCSV(points, dim = 2, filename, { header = true } = {}) {
  if (!Number.isInteger(dim) || dim < 1 || dim > 16) throw new Error(`dim: expected an integer 1..16, got ${dim}`);
  const flat = Array.isArray(points) && Array.isArray(points[0]) ? points.flat() : points;
  if (!flat || flat.length % dim !== 0) throw new Error(`points: length ${flat?.length} is not a multiple of dim ${dim}`);
  const rows = [];
  if (header) {
    const names = Array.isArray(header) ? header.map((h) => String(h).replace(/[",\n\r]/g, '_'))
      : ['x', 'y', 'z', 'w'].slice(0, dim).concat(Array.from({ length: Math.max(0, dim - 4) }, (_, i) => `c${i + 4}`));
    rows.push(names.join(','));
  }
  for (let i = 0; i < flat.length; i += dim) {
    const r = [];
    for (let k = 0; k < dim; k++) r.push(num(flat[i + k], 15));
    rows.push(r.join(','));
  }
  const text = rows.join('\n') + '\n';
  if (filename) download(text, filename, 'text/csv');
  return text;
}

// ---------------------------------------------------------------- any 2D canvas drawing → SVG

const CTX_METHODS = ['save', 'restore', 'setTransform', 'resetTransform', 'transform', 'translate', 'scale', 'rotate',
  'beginPath', 'moveTo', 'lineTo', 'closePath', 'rect', 'arc', 'ellipse', 'arcTo', 'quadraticCurveTo', 'bezierCurveTo',
  'stroke', 'fill', 'fillRect', 'strokeRect', 'clearRect', 'fillText', 'strokeText', 'setLineDash', 'getLineDash',
  'clip', 'drawImage', 'roundRect'];
const CTX_PROPS = ['fillStyle', 'strokeStyle', 'lineWidth', 'globalAlpha', 'font', 'textAlign', 'textBaseline',
  'lineJoin', 'lineCap', 'lineDashOffset'];

/**
 * Records what `paint()` draws on the 2D context `ctx` and returns it as SVG text: paths (stroke and fill with
 * their colours, widths, dashes and alpha), circles and arcs, rectangles and text, in CSS pixels. The context's
 * own methods are shadowed during `paint()` only (nothing reaches the canvas), then restored. Gradients and
 * images are not converted (gradients become grey). `opts`: { width, height (CSS px), scale (device pixels per
 * CSS px, e.g. the canvas's devicePixelRatio), title }.
 */
/**
 * @param {CanvasRenderingContext2D} ctx @param {(g: any) => void} paint
 * @param {{ width?: number, height?: number, scale?: number, title?: string }} [options]
 */
export function canvasToSVG(ctx, paint, { width, height, scale = 1, title } = {}) {
  const W = width, H = height;
  const out = [];
  let st = { fillStyle: '#000000', strokeStyle: '#000000', lineWidth: 1, globalAlpha: 1, font: '10px sans-serif',
    textAlign: 'start', textBaseline: 'alphabetic', lineJoin: 'miter', lineCap: 'butt', lineDashOffset: 0, dash: [] };
  let m = [1, 0, 0, 1, 0, 0]; // a b c d e f
  const stack = [];
  let path = '', cur = null, start = null;
  const f = (v) => num(v, 6);
  const tp = (x, y) => [(m[0] * x + m[2] * y + m[4]) / scale, (m[1] * x + m[3] * y + m[5]) / scale];
  const unit = () => Math.sqrt(Math.abs(m[0] * m[3] - m[1] * m[2])) / scale; // length scale of the transform
  const paintOf = (v) => (typeof v === 'string' ? color(v, '#888888') : '#888888');
  const common = () => {
    let s = '';
    if (st.globalAlpha < 1) s += ` opacity="${f(Math.max(0, st.globalAlpha))}"`;
    return s;
  };
  const strokeAttrs = () => {
    let s = ` stroke="${esc(paintOf(st.strokeStyle))}" stroke-width="${f(st.lineWidth * unit())}"`;
    if (st.lineJoin !== 'miter') s += ` stroke-linejoin="${st.lineJoin === 'round' ? 'round' : 'bevel'}"`;
    if (st.lineCap !== 'butt') s += ` stroke-linecap="${st.lineCap === 'round' ? 'round' : 'square'}"`;
    if (st.dash.length) s += ` stroke-dasharray="${st.dash.map((d) => f(d * unit())).join(' ')}"`;
    return s;
  };
  const moveTo = (x, y) => { const p = tp(x, y); path += `M${f(p[0])} ${f(p[1])}`; cur = p; start = p; };
  const lineTo = (x, y) => { if (!cur) { moveTo(x, y); return; } const p = tp(x, y); path += `L${f(p[0])} ${f(p[1])}`; cur = p; };
  const arc = (x, y, r, a0, a1, ccw = false, rx = r, ry = r, rot = 0) => {
    if (!(r >= 0)) return;
    const full = Math.abs(a1 - a0) >= 2 * Math.PI - 1e-9;
    const pt = (a) => {
      const ca = Math.cos(a) * rx, sa = Math.sin(a) * ry;
      return [x + ca * Math.cos(rot) - sa * Math.sin(rot), y + ca * Math.sin(rot) + sa * Math.cos(rot)];
    };
    // sample the arc (robust under any transform); 2° steps
    let delta = a1 - a0;
    if (full) delta = ccw ? -2 * Math.PI : 2 * Math.PI;
    else if (!ccw && delta < 0) delta = (delta % (2 * Math.PI)) + 2 * Math.PI;
    else if (ccw && delta > 0) delta = (delta % (2 * Math.PI)) - 2 * Math.PI;
    const n = Math.max(8, Math.ceil(Math.abs(delta) / (Math.PI / 90)));
    const [sx0, sy0] = pt(a0);
    if (cur) lineTo(sx0, sy0); else moveTo(sx0, sy0);
    for (let i = 1; i <= n; i++) { const [px, py] = pt(a0 + (delta * i) / n); lineTo(px, py); }
    if (full) path += 'Z';
  };
  const emit = (kind) => {
    if (!path) return;
    if (kind === 'stroke') out.push(`<path d="${path}" fill="none"${strokeAttrs()}${common()}/>`);
    else out.push(`<path d="${path}" fill="${esc(paintOf(st.fillStyle))}" stroke="none"${common()}/>`);
  };
  const rectPath = (x, y, w, h) => { moveTo(x, y); lineTo(x + w, y); lineTo(x + w, y + h); lineTo(x, y + h); path += 'Z'; cur = start; };
  const fontAttrs = () => {
    const mm = /^\s*(italic\s+|oblique\s+)?(normal\s+|bold\s+|[1-9]00\s+)?(\d+(?:\.\d+)?)px\s+(.+)$/i.exec(st.font || '');
    if (!mm) return ' font-family="sans-serif" font-size="10"';
    let s = ` font-family="${esc(mm[4].replace(/"/g, "'"))}" font-size="${f(Number(mm[3]) * unit())}"`;
    if (mm[1]) s += ' font-style="italic"';
    if (mm[2] && mm[2].trim() !== 'normal') s += ` font-weight="${mm[2].trim()}"`;
    return s;
  };
  const text = (str, x, y, kind) => {
    const p = tp(x, y);
    const anchor = { center: 'middle', right: 'end', end: 'end' }[st.textAlign] || 'start';
    const base = { top: 'text-before-edge', hanging: 'hanging', middle: 'central', bottom: 'text-after-edge', ideographic: 'ideographic' }[st.textBaseline];
    let attrs = ` x="${f(p[0])}" y="${f(p[1])}"${fontAttrs()} text-anchor="${anchor}"${base ? ` dominant-baseline="${base}"` : ''}`;
    if (kind === 'stroke') attrs += ` fill="none"${strokeAttrs()}`;
    else attrs += ` fill="${esc(paintOf(st.fillStyle))}"`;
    out.push(`<text${attrs}${common()}>${esc(str)}</text>`);
  };
  const impl = {
    save() { stack.push({ st: { ...st, dash: st.dash.slice() }, m: m.slice() }); },
    restore() { const s = stack.pop(); if (s) { st = s.st; m = s.m; } },
    setTransform(a, b, c, d, e, f2) {
      if (a && typeof a === 'object') m = [a.a, a.b, a.c, a.d, a.e, a.f];
      else if (arguments.length === 0) m = [1, 0, 0, 1, 0, 0];
      else m = [a, b, c, d, e, f2];
    },
    resetTransform() { m = [1, 0, 0, 1, 0, 0]; },
    transform(a, b, c, d, e, f2) {
      m = [m[0] * a + m[2] * b, m[1] * a + m[3] * b, m[0] * c + m[2] * d, m[1] * c + m[3] * d, m[0] * e + m[2] * f2 + m[4], m[1] * e + m[3] * f2 + m[5]];
    },
    translate(x, y) { impl.transform(1, 0, 0, 1, x, y); },
    scale(x, y) { impl.transform(x, 0, 0, y, 0, 0); },
    rotate(a) { impl.transform(Math.cos(a), Math.sin(a), -Math.sin(a), Math.cos(a), 0, 0); },
    beginPath() { path = ''; cur = null; start = null; },
    moveTo, lineTo,
    closePath() { if (cur) { path += 'Z'; cur = start; } },
    rect(x, y, w, h) { rectPath(x, y, w, h); },
    roundRect(x, y, w, h) { rectPath(x, y, w, h); },
    arc(x, y, r, a0, a1, ccw) { arc(x, y, r, a0, a1, !!ccw); },
    ellipse(x, y, rx, ry, rot, a0, a1, ccw) { arc(x, y, Math.max(rx, ry), a0, a1, !!ccw, rx, ry, rot); },
    arcTo(x1, y1) { lineTo(x1, y1); },
    quadraticCurveTo(cx, cy, x, y) {
      if (!cur) moveTo(cx, cy);
      const c = tp(cx, cy), p = tp(x, y);
      path += `Q${f(c[0])} ${f(c[1])} ${f(p[0])} ${f(p[1])}`; cur = p;
    },
    bezierCurveTo(c1x, c1y, c2x, c2y, x, y) {
      if (!cur) moveTo(c1x, c1y);
      const a = tp(c1x, c1y), b = tp(c2x, c2y), p = tp(x, y);
      path += `C${f(a[0])} ${f(a[1])} ${f(b[0])} ${f(b[1])} ${f(p[0])} ${f(p[1])}`; cur = p;
    },
    stroke() { emit('stroke'); },
    fill() { emit('fill'); },
    fillRect(x, y, w, h) { const keep = [path, cur, start]; path = ''; rectPath(x, y, w, h); emit('fill'); [path, cur, start] = keep; },
    strokeRect(x, y, w, h) { const keep = [path, cur, start]; path = ''; rectPath(x, y, w, h); emit('stroke'); [path, cur, start] = keep; },
    clearRect() {},
    fillText(s, x, y) { text(String(s), x, y, 'fill'); },
    strokeText(s, x, y) { text(String(s), x, y, 'stroke'); },
    setLineDash(d) { st.dash = Array.isArray(d) ? d.filter((v) => Number.isFinite(v) && v >= 0) : []; },
    getLineDash() { return st.dash.slice(); },
    clip() {}, drawImage() {},
  };
  // shadow the context's methods and style properties with the recorder, paint, restore
  const shadowed = [];
  try {
    for (const k of CTX_METHODS) {
      Object.defineProperty(ctx, k, { configurable: true, writable: true, value: impl[k] });
      shadowed.push(k);
    }
    for (const k of CTX_PROPS) {
      Object.defineProperty(ctx, k, { configurable: true, get: () => st[k], set: (v) => { st[k] = k === 'lineWidth' || k === 'globalAlpha' || k === 'lineDashOffset' ? (Number.isFinite(+v) ? +v : st[k]) : v; } });
      shadowed.push(k);
    }
    paint();
  } finally {
    for (const k of shadowed) delete ctx[k];
  }
  const head = ['<?xml version="1.0" encoding="UTF-8"?>',
    `<svg xmlns="http://www.w3.org/2000/svg" width="${f(W)}" height="${f(H)}" viewBox="0 0 ${f(W)} ${f(H)}">`];
  if (title) head.push(`<title>${esc(title)}</title>`);
  return head.concat(out, ['</svg>']).join('\n') + '\n';
}

/**
 * SVG of a SplineLab 2D plot (www/lib/plot2d.js): grid, axes, ticks, curves, points, labels and handles exactly
 * as on screen, in CSS pixels. Downloads it when `filename` is given. The plot is repainted afterwards.
 */
/** @param {any} plot @param {string} [filename] @param {{ title?: string }} [options] */
export function plotToSVG(plot, filename, { title } = {}) {
  if (!plot || !plot.g || typeof plot.paintNow !== 'function') throw new Error('plot: expected a plot from createPlot()');
  // the recorder undoes the plot's own pixel ratio: its coordinates are CSS px whatever the screen's ratio
  const scale = plot.pixelRatio || (plot.canvas && plot.width ? plot.canvas.width / plot.width : 1);
  let svg;
  try {
    svg = canvasToSVG(plot.g, () => plot.paintNow(), { width: plot.width, height: plot.height, scale, title: title || plot.canvas?.getAttribute('aria-label') || undefined });
  } finally {
    plot.paintNow();
  }
  if (filename) download(svg, filename, 'image/svg+xml');
  return svg;
}

// ---------------------------------------------------------------- a row of export buttons for a demo

const resolve = (v) => (typeof v === 'function' ? v() : v);

/**
 * A row of export buttons (only for the formats given), for a demo's controls:
 *
 *   controls.append(exportButtons({ name: 'curve-networks',
 *     png: view3d | plot | canvas | () => canvas,      // a View3D or plot is redrawn first
 *     svg: plot | () => drawing | () => svgText,       // a plot2d plot is converted exactly as drawn
 *     json: () => ({ inputs, computed }),
 *     obj: () => wasmResult.mesh | [{ name, mesh }],
 *     csv: () => ({ points: result.points, dim: result.dim }),
 *     onError: (e) => ctx.notify(e.message, 'error') }));
 *
 * Files are named `<name>.<ext>`. Returns a <div class="ctl-row export-row" role="group">.
 */
export function exportButtons(spec = {}) {
  const name = safeName(spec.name || 'splinelab');
  const row = document.createElement('div');
  row.className = 'ctl-row export-row';
  row.setAttribute('role', 'group');
  row.setAttribute('aria-label', 'Export');
  const fail = (e) => { if (typeof spec.onError === 'function') spec.onError(e); else console.error(e); };
  const add = (label, title, fn) => {
    const b = document.createElement('button');
    b.type = 'button';
    b.className = 'btn btn-small';
    b.textContent = label;
    b.title = title;
    b.addEventListener('click', async () => { try { await fn(); } catch (e) { fail(e); } });
    row.appendChild(b);
  };
  if (spec.png) {
    add('PNG', 'Download a PNG image of the view', () => {
      const src = resolve(spec.png);
      let canvas = src;
      if (src && typeof src.renderNow === 'function') { src.renderNow(); canvas = src.canvas; } // View3D
      else if (src && typeof src.paintNow === 'function') { src.paintNow(); canvas = src.canvas; } // plot2d
      return exportPNG(canvas, `${name}.png`);
    });
  }
  if (spec.svg) {
    add('SVG', 'Download the drawing as SVG (vector)', () => {
      const src = resolve(spec.svg);
      if (src && typeof src.paintNow === 'function') return plotToSVG(src, `${name}.svg`);
      if (typeof src === 'string') return download(src, `${name}.svg`, 'image/svg+xml');
      return exportSVG(src, `${name}.svg`);
    });
  }
  if (spec.json) add('JSON', 'Download the construction (inputs and computed data) as JSON', () => exportJSON(resolve(spec.json), `${name}.json`));
  if (spec.obj) add('OBJ', 'Download the surface mesh as a Wavefront OBJ file', () => exportOBJ(resolve(spec.obj), `${name}.obj`));
  if (spec.csv) {
    add('CSV', 'Download the sampled points as CSV', () => {
      const r = resolve(spec.csv) || {};
      return exportCSV(r.points, r.dim || 2, `${name}.csv`, { header: r.header ?? true });
    });
  }
  return row;
}
