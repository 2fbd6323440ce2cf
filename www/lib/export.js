// Exporters for figures and data: PNG of a canvas, SVG of a 2D drawing, JSON of a construction, OBJ of a
// surface mesh, CSV of sampled points. Each builds the file and returns it (text, or a Promise of a Blob for
// PNG); pass a file name to also download it. The text outputs are deterministic and parse back.
//
//   exportPNG(canvas, 'figure.png')                 → Promise<Blob>
//   exportSVG(drawing, 'figure.svg')                → SVG text (see `toSVG` for the drawing description)
//   exportJSON(obj, 'construction.json')            → JSON text (typed arrays become arrays)
//   exportOBJ(mesh | [{ name, mesh }], 'surface.obj') → Wavefront OBJ text (v / vn / f a//a b//b c//c)
//   exportCSV(flatPoints, dim, 'points.csv', { header }) → CSV text (header x,y[,z] by default)
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
