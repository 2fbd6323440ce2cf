// The shell's Export row under every demo (used by app.js and spline-lab.js): PNG of the demo's main view
// (the first visible 2D plot or WebGL canvas), SVG of each visible 2D plot (plotToSVG: exactly as drawn), JSON of
// the construction (the state plus, when the demo provides it, computed control data), OBJ of surfaces and CSV
// of sampled points. JSON/OBJ/CSV come from the optional `exports()` hook a demo's mount() may return
// (www/demos/README.md):
//
//   exports() → { json?: object, obj?: [{ name, mesh: { positions, normals?, indices } }], csv?: { points, dim } }
//
//   const row = demoExportRow({ id, title, root, getInstance: () => instance, getState: () => state,
//                               snippet: mod.snippet, onError });
//   parent.append(row.element); … row.refresh() after a state change; row.destroy().
//
// The buttons shown follow what the demo offers now (refreshed after state changes and when the pointer or the
// keyboard focus approaches the row). Each button downloads a file named `<demo-id>[-<part>].<ext>`; tests can
// read the last file produced through `row.element.lastExport` ({ name, type, text | blob }).

// The writers (www/lib/export.js: PNG, SVG, JSON, OBJ, CSV) are not needed for a demo's first drawing (the row's
// buttons appear two frames after it): they load then, and a click that comes first waits for them.
let writers = null;
const loadWriters = () => (writers ??= import('./export.js'));
import { snippetBar } from './snippet.js'; // "Copy as code" / "Open in sandbox" (the demo's snippet(state))
import { t } from './i18n.js';

const visible = (el) => !!(el && el.isConnected && el.getClientRects().length && !el.closest('[hidden]'));

/** The canvases of 2D plots (plot2d) in `root`, visible ones only. */
export function plotCanvases(root) {
  return Array.from(root.querySelectorAll('canvas')).filter((c) => c.splinePlot && visible(c));
}

/** The demo's main view: the first visible canvas that is a 2D plot or a 3D view (else any visible canvas). */
export function mainCanvas(root) {
  const all = Array.from(root.querySelectorAll('canvas')).filter(visible);
  return all.find((c) => c.splinePlot || c.view3d) || all[0] || null;
}

/**
 * The legend of a view as items for slideCanvas(): the visible `ul.legend` marked `data-legend-for` with the
 * canvas' data-plot, else the first visible legend after the canvas in the demo. Colours as drawn (legend()
 * records them in data-color; older legends are read from their computed style).
 */
export function legendItemsFor(root, canvas) {
  const all = Array.from(root.querySelectorAll('ul.legend')).filter(visible);
  const key = canvas?.dataset?.plot;
  let ul = key ? all.find((u) => u.dataset.legendFor === key) : null;
  if (!ul && canvas) ul = all.find((u) => canvas.compareDocumentPosition(u) & Node.DOCUMENT_POSITION_FOLLOWING) || null;
  if (!ul) return [];
  return Array.from(ul.querySelectorAll(':scope > li')).map((li) => {
    const sw = li.querySelector('.swatch');
    const label = li.textContent.trim();
    if (!sw) return { label, color: '#111111', kind: 'line' };
    const cs = getComputedStyle(sw);
    let color = sw.dataset.color;
    if (!color) {
      const m = (cs.backgroundImage && cs.backgroundImage !== 'none' ? cs.backgroundImage : cs.backgroundColor).match(/rgba?\([^)]*\)/);
      color = m ? m[0] : '#111111';
    }
    const kind = sw.dataset.kind || (sw.classList.contains('dot') ? 'dot' : sw.classList.contains('dashed') ? 'dashed' : sw.classList.contains('band') ? 'band' : 'line');
    // a colour ramp (a surface coloured by a map): its stops, drawn as the same gradient under the figure
    if (kind === 'ramp') return { label, color, kind, stops: cs.backgroundImage.match(/rgba?\([^)]*\)/g) || [color], alpha: 1 };
    const alpha = Number(cs.opacity);
    return { label, color, kind, alpha: kind === 'band' ? 0.5 : (Number.isFinite(alpha) ? alpha : 1) };
  });
}

function callExports(instance) {
  if (!instance || typeof instance.exports !== 'function') return {};
  const r = instance.exports();
  return r && typeof r === 'object' ? r : {};
}

const label = (c, i) => (c.getAttribute('aria-label') || t('plot {i}', { i: i + 1 })).replace(/\s*\(.*$/, '').slice(0, 80);

export function demoExportRow({ id, title, root, getInstance, getState, snippet = null, onError, hidden = false }) {
  const name = async () => (await loadWriters()).safeName(id || 'splinelab');
  const row = document.createElement('div');
  row.className = 'export-bar';
  row.setAttribute('role', 'group');
  row.setAttribute('aria-label', t('Export this figure'));
  if (hidden) row.hidden = true;
  const head = document.createElement('span');
  head.className = 'export-bar-label';
  head.textContent = t('Export:');
  const box = document.createElement('span');
  box.className = 'export-bar-buttons';
  // options of the PNG for slides: scale, the legend under the figure, a caption
  const uid = Math.random().toString(36).slice(2, 8);
  const scaleSel = document.createElement('select');
  scaleSel.id = `export-scale-${uid}`;
  scaleSel.name = 'export-scale';
  for (const v of [1, 2, 4]) { const o = document.createElement('option'); o.value = String(v); o.textContent = `${v}×`; scaleSel.appendChild(o); }
  scaleSel.value = '2';
  const scaleLab = document.createElement('label');
  scaleLab.htmlFor = scaleSel.id; scaleLab.textContent = t('PNG scale');
  const legendBox = document.createElement('input');
  legendBox.type = 'checkbox'; legendBox.id = `export-legend-${uid}`; legendBox.name = 'export-legend';
  const legendLab = document.createElement('label');
  legendLab.htmlFor = legendBox.id; legendLab.textContent = t('with legend');
  const capIn = document.createElement('input');
  capIn.type = 'text'; capIn.id = `export-caption-${uid}`; capIn.name = 'export-caption'; capIn.maxLength = 300;
  capIn.placeholder = t('optional caption');
  const capLab = document.createElement('label');
  capLab.htmlFor = capIn.id; capLab.textContent = t('Caption');
  const opts = document.createElement('span');
  opts.className = 'export-bar-options';
  const pair = (...els) => { const s2 = document.createElement('span'); s2.className = 'export-opt'; s2.append(...els); return s2; };
  opts.append(pair(scaleLab, scaleSel), pair(legendBox, legendLab), pair(capLab, capIn));
  row.append(head, box, opts);
  // "Copy as code" and "Open in sandbox" (www/lib/snippet.js; shown when the demo module exports snippet(state))
  const snip = snippetBar({ snippet, getState, onError });
  box.after(snip.element);
  let signature = '';
  let timer = 0;
  const fail = (e) => { if (typeof onError === 'function') onError(e); else console.error(e); };
  const record = (file, type, data) => { row.lastExport = { name: file, type, ...(typeof data === 'string' ? { text: data } : { blob: data }) }; row.dataset.exported = String((Number(row.dataset.exported) || 0) + 1); };

  function available() {
    /** @type {{ key: string, text: string, title: string, aria?: string, run: () => Promise<void> }[]} */
    const out = [];
    let ex = {};
    try { ex = callExports(getInstance()); } catch (e) { ex = { error: e }; }
    const main = mainCanvas(root);
    if (main) {
      out.push({ key: 'png', text: 'PNG', title: t('Download a PNG image of the main view (re-drawn at the chosen scale, with the legend and caption if set)'), run: async () => {
        const c = mainCanvas(root);
        if (!c) throw new Error(t('Export: there is no figure to export in this view'));
        const scale = Number(scaleSel.value) || 1;
        const legend = legendBox.checked ? legendItemsFor(root, c) : null;
        const caption = capIn.value.trim();
        const src = c.view3d || c.splinePlot || c;
        const { slideCanvas, exportPNG } = await loadWriters();
        const fig = slideCanvas(src, { scale, legend, caption });
        const file = `${await name()}.png`;
        const blob = await exportPNG(fig, file);
        record(file, 'image/png', blob);
        row.lastExport.figure = { scale: Number(fig.dataset.scale), width: fig.width, height: fig.height, cssWidth: Number(fig.dataset.cssWidth), cssHeight: Number(fig.dataset.cssHeight), plotHeight: Number(fig.dataset.plotHeight) };
      } });
    }
    const plots = plotCanvases(root);
    plots.forEach((c, i) => {
      const what = label(c, i);
      const text = plots.length > 1 ? `SVG ${i + 1}` : 'SVG';
      out.push({ key: `svg${i}:${what}`, text, title: t('Download “{what}” as SVG (vector)', { what }), aria: `${text}: ${what}`, run: async () => {
        const { plotToSVG } = await loadWriters();
        const file = plots.length > 1 ? `${await name()}-${i + 1}.svg` : `${await name()}.svg`;
        const svg = plotToSVG(c.splinePlot, file, { title: `${title ? t(title) : id}: ${what}` });
        record(file, 'image/svg+xml', svg);
      } });
    });
    out.push({ key: 'json', text: 'JSON', title: t('Download the construction (state and computed data) as JSON'), run: async () => {
      const { exportJSON } = await loadWriters();
      const file = `${await name()}.json`;
      const x = callExports(getInstance());
      const doc = { splinelab: 1, demo: id, title: title || id, state: getState() };
      if (x.json !== undefined) doc.computed = x.json;
      const text = exportJSON(doc, file);
      record(file, 'application/json', text);
    } });
    if (Array.isArray(ex.obj) && ex.obj.length) {
      out.push({ key: 'obj', text: 'OBJ', title: t('Download the surface mesh as a Wavefront OBJ file'), run: async () => {
        const { exportOBJ } = await loadWriters();
        const file = `${await name()}.obj`;
        const text = exportOBJ(callExports(getInstance()).obj, file);
        record(file, 'model/obj', text);
      } });
    }
    if (ex.csv && ex.csv.points && ex.csv.points.length) {
      out.push({ key: 'csv', text: 'CSV', title: t('Download the sampled points as CSV'), run: async () => {
        const { exportCSV } = await loadWriters();
        const file = `${await name()}.csv`;
        const c = callExports(getInstance()).csv || {};
        const text = exportCSV(c.points, c.dim || 2, file, { header: c.header ?? true });
        record(file, 'text/csv', text);
      } });
    }
    return out;
  }

  function refresh() {
    if (!row.isConnected && signature) return;
    const list = available();
    const sig = list.map((b) => b.key).join('|');
    if (sig === signature) { row._list = list; return; }
    signature = sig;
    row._list = list;
    const active = /** @type {HTMLElement | null} */ ((/** @type {Document | ShadowRoot} */ (row.getRootNode())).activeElement);
    const focused = box.contains(active) ? active.dataset.key : null;
    box.replaceChildren(...list.map((b) => {
      const btn = document.createElement('button');
      btn.type = 'button';
      btn.className = 'btn btn-small';
      btn.textContent = b.text;
      btn.title = b.title;
      btn.dataset.key = b.key;
      btn.dataset.format = b.key.replace(/\d.*$/, '');
      if (b.aria) btn.setAttribute('aria-label', b.aria);
      btn.addEventListener('click', async () => {
        const cur = (row._list || []).find((x) => x.key === b.key) || b;
        try { await cur.run(); } catch (e) { fail(e); }
      });
      return btn;
    }));
    if (focused) /** @type {HTMLElement | null} */ (box.querySelector(`[data-key="${CSS.escape(focused)}"]`))?.focus();
  }
  const soon = () => { clearTimeout(timer); timer = setTimeout(refresh, 120); };
  row.addEventListener('pointerenter', refresh);
  // a state change can add or remove views (tabs) and data (OBJ/CSV): follow clicks and keys in the demo
  root.addEventListener('click', soon);
  root.addEventListener('change', soon);
  root.addEventListener('keyup', soon);
  requestAnimationFrame(() => requestAnimationFrame(() => { refresh(); loadWriters().catch(() => { writers = null; }); }));
  return {
    element: row, refresh: soon, refreshNow: refresh,
    destroy() { clearTimeout(timer); snip.destroy(); root.removeEventListener('click', soon); root.removeEventListener('change', soon); root.removeEventListener('keyup', soon); row.remove(); },
    /** Downloads nothing; for tests: the formats on offer now. */
    formats: () => available().map((b) => b.key),
  };
}

/** Puts the row right under the demo's figures and controls (before its explanation), else after `root`. */
export function placeRow(root, row) {
  const explain = Array.from(root.children).find((c) => c.classList.contains('demo-explain'));
  if (explain) explain.before(row); else root.after(row);
}

/** Downloads a file (www/lib/export.js's download, loaded on first use). */
export async function download(...args) { return (await loadWriters()).download(...args); }
