// End-to-end tests of www/lib/view3d.js (the WebGL2 viewer) and www/lib/export.js, on the dev page
// www/dev/view3d-demo.html, in headless Chromium with --disable-gpu (software WebGL2).
// Run: node --test tests/e2e/view3d.test.mjs   (needs www/pkg: scripts/build-wasm.sh)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, mkdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { serve } from '../../scripts/static-server.mjs';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const SHOTS = join(ROOT, 'tests', 'e2e', 'screenshots');
mkdirSync(SHOTS, { recursive: true });

let server, browser, base;

before(async () => {
  server = await serve(join(ROOT, 'www'), 0);
  base = `http://127.0.0.1:${server.address().port}`;
  browser = await chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--disable-quic'],
  });
});

after(async () => {
  await browser?.close();
  server?.close();
});

/** Opens the dev page; collects console errors, page errors and requests that leave 127.0.0.1. */
async function open(query = '') {
  const page = await browser.newPage({ viewport: { width: 1000, height: 800 } });
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  page.on('request', (r) => {
    const u = new URL(r.url());
    if (!['data:', 'blob:'].includes(u.protocol) && u.hostname !== '127.0.0.1') problems.push(`external request: ${r.url()}`);
  });
  await page.goto(`${base}/dev/view3d-demo.html${query}`);
  await page.waitForSelector('body[data-ready]', { timeout: 20000 });
  await page.evaluate(() => window.__view.renderNow());
  return { page, problems };
}

/** Pixel statistics of the WebGL canvas, read back through a 2D canvas: how many differ from white, and a fingerprint. */
function canvasStats(page) {
  return page.evaluate(() => {
    const v = window.__view;
    v.renderNow();
    const c = document.createElement('canvas');
    c.width = v.canvas.width; c.height = v.canvas.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(v.canvas, 0, 0);
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    let ink = 0, colourful = 0;
    const grid = [];
    for (let i = 0; i < d.length; i += 4) {
      if (d[i] < 245 || d[i + 1] < 245 || d[i + 2] < 245) ink++;
      if (Math.max(d[i], d[i + 1], d[i + 2]) - Math.min(d[i], d[i + 1], d[i + 2]) > 60) colourful++;
    }
    // a coarse 16×16 fingerprint of the image
    for (let gy = 0; gy < 16; gy++) for (let gx = 0; gx < 16; gx++) {
      const x = Math.floor(((gx + 0.5) * c.width) / 16), y = Math.floor(((gy + 0.5) * c.height) / 16);
      const k = 4 * (y * c.width + x);
      grid.push(d[k] + d[k + 1] + d[k + 2]);
    }
    return { ink, colourful, total: d.length / 4, grid };
  });
}

const differs = (a, b) => a.grid.filter((v, i) => Math.abs(v - b.grid[i]) > 30).length;

async function canvasBox(page) {
  const box = await page.locator('canvas.sl-view3d-canvas').first().boundingBox();
  assert.ok(box && box.width > 100 && box.height > 100, 'canvas has a size');
  return box;
}

test('renders shaded, colour-mapped surfaces in software WebGL2', async () => {
  const { page, problems } = await open();
  assert.equal(await page.evaluate(() => window.__view.supported), true, 'WebGL2 available (SwiftShader)');
  const s = await canvasStats(page);
  assert.ok(s.ink > s.total * 0.1, `enough non-background pixels: ${s.ink} of ${s.total}`);
  assert.ok(s.colourful > s.total * 0.03, `colour-mapped and shaded pixels: ${s.colourful}`);
  assert.equal(await page.locator('#view .sl-legend').isVisible(), true, 'legend shown for the colour map');
  assert.match(await page.locator('#status').textContent(), /bsplineCurve/, 'the wasm curve was drawn');
  await page.screenshot({ path: join(SHOTS, 'view3d-initial.png') });
  assert.deepEqual(problems, []);
  await page.close();
});

test('dragging the background orbits the camera; wheel zooms; right-drag pans', async () => {
  const { page, problems } = await open();
  const box = await canvasBox(page);
  const v0 = await page.evaluate(() => window.__view.getView());
  const s0 = await canvasStats(page);
  // before the view has focus, the wheel scrolls the page and does not zoom
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.wheel(0, 200);
  await page.waitForTimeout(100);
  assert.equal((await page.evaluate(() => window.__view.getView())).distance, v0.distance, 'no zoom without focus');
  assert.ok(await page.evaluate(() => window.scrollY) > 0, 'the page scrolled');
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.waitForTimeout(50);
  // start near the top-left corner (empty background)
  await page.mouse.move(box.x + 30, box.y + 30);
  await page.mouse.down();
  await page.mouse.move(box.x + 130, box.y + 60, { steps: 8 });
  await page.mouse.up();
  const v1 = await page.evaluate(() => window.__view.getView());
  assert.notEqual(v1.yaw, v0.yaw, 'yaw changed');
  const s1 = await canvasStats(page);
  assert.ok(differs(s0, s1) > 10, `pixels changed after orbit (${differs(s0, s1)} of 256 samples)`);
  await page.screenshot({ path: join(SHOTS, 'view3d-orbited.png') });

  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.wheel(0, 300);
  await page.waitForTimeout(50);
  const v2 = await page.evaluate(() => window.__view.getView());
  assert.ok(v2.distance > v1.distance, 'wheel down zooms out');

  await page.mouse.move(box.x + 30, box.y + 30);
  await page.mouse.down({ button: 'right' });
  await page.mouse.move(box.x + 90, box.y + 30, { steps: 4 });
  await page.mouse.up({ button: 'right' });
  const v3 = await page.evaluate(() => window.__view.getView());
  assert.notDeepEqual(v3.target, v2.target, 'right-drag pans');
  assert.deepEqual(problems, []);
  await page.close();
});

test('dragging a control point moves it in the screen plane and recomputes the wasm curve', async () => {
  const { page, problems } = await open();
  const box = await canvasBox(page);
  const before = await page.evaluate(() => Array.from(window.__view.getPoints('ctrl')));
  const p = await page.evaluate(() => window.__view.screenPosition('ctrl', 2));
  const s0 = await canvasStats(page);
  await page.mouse.move(box.x + p[0], box.y + p[1]);
  await page.mouse.down();
  await page.mouse.move(box.x + p[0] + 40, box.y + p[1] - 60, { steps: 6 });
  await page.mouse.up();
  const after = await page.evaluate(() => Array.from(window.__view.getPoints('ctrl')));
  const moved = [0, 1, 2].some((k) => Math.abs(after[6 + k] - before[6 + k]) > 1e-3);
  assert.ok(moved, 'point 2 moved');
  for (const i of [0, 1, 3, 4]) for (const k of [0, 1, 2]) assert.equal(after[3 * i + k], before[3 * i + k], 'other points stay');
  const q = await page.evaluate(() => window.__view.screenPosition('ctrl', 2));
  assert.ok(Math.hypot(q[0] - p[0] - 40, q[1] - p[1] + 60) < 3, `point follows the pointer (${q} vs ${p})`);
  assert.match(await page.locator('#status').textContent(), /moved P2/);
  const s1 = await canvasStats(page);
  assert.ok(differs(s0, s1) > 0, 'pixels changed');

  // Shift: along z only
  const b2 = after.slice(6, 9);
  await page.mouse.move(box.x + q[0], box.y + q[1]);
  await page.mouse.down();
  await page.keyboard.down('Shift');
  await page.mouse.move(box.x + q[0] + 30, box.y + q[1] - 50, { steps: 5 });
  await page.keyboard.up('Shift');
  await page.mouse.up();
  const a2 = await page.evaluate(() => Array.from(window.__view.getPoints('ctrl')).slice(6, 9));
  assert.ok(Math.abs(a2[0] - b2[0]) < 1e-5 && Math.abs(a2[1] - b2[1]) < 1e-5, 'x, y fixed with Shift');
  assert.ok(a2[2] > b2[2] + 0.05, `z grew (${b2[2]} → ${a2[2]})`);
  await page.screenshot({ path: join(SHOTS, 'view3d-dragged.png') });
  assert.deepEqual(problems, []);
  await page.close();
});

test('keyboard: arrows orbit, +/- zoom, N selects a point and arrows move it', async () => {
  const { page, problems } = await open();
  await page.locator('#view canvas.sl-view3d-canvas').focus();
  const outline = await page.locator('#view canvas.sl-view3d-canvas').evaluate((c) => getComputedStyle(c).outlineStyle);
  assert.equal(outline, 'solid', 'visible focus ring');
  const v0 = await page.evaluate(() => window.__view.getView());
  await page.keyboard.press('ArrowLeft');
  await page.keyboard.press('Minus');
  const v1 = await page.evaluate(() => window.__view.getView());
  assert.notEqual(v1.yaw, v0.yaw);
  assert.ok(v1.distance > v0.distance);
  const before = await page.evaluate(() => Array.from(window.__view.getPoints('ctrl')));
  await page.keyboard.press('n');
  await page.keyboard.press('PageUp');
  await page.keyboard.press('Shift+PageUp');
  const after = await page.evaluate(() => Array.from(window.__view.getPoints('ctrl')));
  assert.ok(after[2] > before[2], 'first point moved up with Page Up');
  assert.equal(after[0], before[0]);
  assert.match(await page.locator('#status').textContent(), /moved P0/);
  // the view change pressed just before is said 400 ms after it, unless a newer action was said meanwhile
  await page.waitForTimeout(600);
  assert.match(await page.locator('#view .sl-view3d [aria-live]').textContent(), /P0/, 'the move, not the older view change, is what the live region says');
  await page.keyboard.press('n');
  await page.keyboard.press('ArrowRight');
  const after2 = await page.evaluate(() => Array.from(window.__view.getPoints('ctrl')));
  assert.ok([3, 4, 5].some((k) => after2[k] !== before[k]), 'second point moved with ArrowRight');
  assert.equal(await page.evaluate(() => document.activeElement.tagName), 'CANVAS');
  assert.deepEqual(problems, []);
  await page.close();
});

test('without WebGL2 the element shows a message and nothing throws', async () => {
  const { page, problems } = await open('?fallback');
  const alert = page.locator('#fallback [role=alert]');
  assert.match(await alert.textContent(), /WebGL2/);
  await page.screenshot({ path: join(SHOTS, 'view3d-fallback.png') });
  assert.deepEqual(problems, []);
  await page.close();
});

test('exports: PNG, SVG, JSON, OBJ and CSV parse back', async () => {
  const { page, problems } = await open();
  const r = await page.evaluate(async () => {
    const ex = await import('../lib/export.js');
    const blob = await ex.exportPNG(window.__view.canvas);
    const head = Array.from(new Uint8Array(await blob.slice(0, 8).arrayBuffer()));
    const svg = ex.exportSVG({
      width: 200, height: 100, title: 'a < b & "c"', bounds: { xmin: 0, xmax: 2, ymin: 0, ymax: 1 },
      layers: [
        { type: 'polyline', points: [0, 0, 1, 1, NaN, NaN, 1.5, 0.5, 2, 0], stroke: '#123456', width: 3 },
        { type: 'points', points: [[0, 0], [1, 1]], labels: ['P<0>', 'P1'] },
        { type: 'text', x: 1, y: 0.5, text: '<script>alert(1)</script>', anchor: 'middle' },
      ],
    });
    const doc = new DOMParser().parseFromString(svg, 'image/svg+xml');
    const svgInfo = {
      error: !!doc.querySelector('parsererror'),
      paths: [...doc.querySelectorAll('path')].map((p) => p.getAttribute('d')),
      circles: [...doc.querySelectorAll('circle')].map((c) => [Number(c.getAttribute('cx')), Number(c.getAttribute('cy'))]),
      texts: [...doc.querySelectorAll('text')].map((t) => t.textContent),
      scripts: doc.querySelectorAll('script').length,
      title: doc.querySelector('title').textContent,
    };
    const mesh = { positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0.5]), normals: new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]), indices: new Uint32Array([0, 1, 3, 0, 3, 2]) };
    return {
      head, svg: svgInfo,
      json: ex.exportJSON({ a: new Float64Array([1.5, NaN]), b: 'x' }),
      obj: ex.exportOBJ(mesh),
      obj2: ex.exportOBJ([{ name: 'S', mesh }, { name: 'G', mesh: { positions: mesh.positions, indices: mesh.indices } }]),
      csv: ex.exportCSV(new Float64Array([0, 1, 2, 3.25, 4, 5]), 3),
    };
  });
  assert.deepEqual(r.head, [137, 80, 78, 71, 13, 10, 26, 10], 'PNG signature');
  assert.equal(r.svg.error, false, 'SVG parses');
  assert.equal(r.svg.paths.length, 1);
  assert.equal(r.svg.paths[0], 'M0 100L100 0 M150 50L200 100', 'data coordinates mapped, NaN breaks the path');
  assert.deepEqual(r.svg.circles, [[0, 100], [100, 0]]);
  assert.deepEqual(r.svg.texts, ['P<0>', 'P1', '<script>alert(1)</script>'], 'text escaped, not markup');
  assert.equal(r.svg.scripts, 0);
  assert.equal(r.svg.title, 'a < b & "c"');
  assert.deepEqual(JSON.parse(r.json), { a: [1.5, null], b: 'x' });
  // OBJ: parse v / vn / f back
  const parseOBJ = (text) => {
    const v = [], vn = [], f = [];
    for (const line of text.split('\n')) {
      const [k, ...rest] = line.trim().split(/\s+/);
      if (k === 'v') v.push(rest.map(Number));
      else if (k === 'vn') vn.push(rest.map(Number));
      else if (k === 'f') f.push(rest.map((s) => Number(s.split('/')[0])));
    }
    return { v, vn, f };
  };
  const o = parseOBJ(r.obj);
  assert.equal(o.v.length, 4);
  assert.equal(o.vn.length, 4);
  assert.deepEqual(o.f, [[1, 2, 4], [1, 4, 3]]);
  assert.deepEqual(o.v[3], [1, 1, 0.5]);
  const o2 = parseOBJ(r.obj2);
  assert.equal(o2.v.length, 8);
  assert.deepEqual(o2.f[2], [5, 6, 8], 'second object offset by the first one’s vertices');
  assert.match(r.obj2, /^o G$/m);
  const rows = r.csv.trim().split('\n').map((l) => l.split(','));
  assert.deepEqual(rows, [['x', 'y', 'z'], ['0', '1', '2'], ['3.25', '4', '5']]);
  assert.deepEqual(problems, []);
  await page.close();
});

test('touch: two-finger pinch zooms; one finger orbits only after a tap activated the view (synthetic pointer events)', async () => {
  const { page, problems } = await open();
  const r = await page.evaluate(() => {
    const v = window.__view, c = v.canvas, rect = c.getBoundingClientRect();
    const ev = (type, id, x, y) => c.dispatchEvent(new PointerEvent(type, { pointerId: id, pointerType: 'touch', isPrimary: id === 1, clientX: rect.left + x, clientY: rect.top + y, bubbles: true, cancelable: true, button: 0, buttons: type === 'pointerup' ? 0 : 1 }));
    const swipe = (id) => { ev('pointerdown', id, 60, 60); for (let k = 1; k <= 5; k++) ev('pointermove', id, 60 + 10 * k, 60); ev('pointerup', id, 110, 60); };
    const d0 = v.getView().distance;
    const inactiveTouch = getComputedStyle(c).touchAction;
    ev('pointerdown', 1, 400, 200); ev('pointerdown', 2, 500, 200);
    for (let k = 1; k <= 5; k++) { ev('pointermove', 1, 400 - 20 * k, 200); ev('pointermove', 2, 500 + 20 * k, 200); }
    ev('pointerup', 1, 300, 200); ev('pointerup', 2, 600, 200);
    const d1 = v.getView().distance;
    const y0 = v.getView().yaw;
    swipe(3);                                   // not active yet: the swipe belongs to the page
    const yInactive = v.getView().yaw;
    ev('pointerdown', 4, 80, 80); ev('pointerup', 4, 80, 80);   // a tap activates the view
    const active = v.touchActive, activeTouch = getComputedStyle(c).touchAction;
    swipe(5);
    const y1 = v.getView().yaw;
    document.body.dispatchEvent(new PointerEvent('pointerdown', { pointerId: 6, pointerType: 'touch', bubbles: true, composed: true }));
    return { d0, d1, y0, yInactive, y1, active, activeTouch, inactiveTouch, after: v.touchActive, afterTouch: getComputedStyle(c).touchAction,
      pageTouch: getComputedStyle(document.body).touchAction };
  });
  assert.ok(r.d1 < r.d0 * 0.7, `pinch out zooms in (${r.d0} → ${r.d1})`);
  assert.equal(r.yInactive, r.y0, 'one finger does not orbit an inactive view');
  assert.equal(r.inactiveTouch, 'pan-y', 'an inactive view lets vertical swipes scroll the page');
  assert.ok(r.active, 'a tap activates the view');
  assert.equal(r.activeTouch, 'none', 'an active view takes one-finger gestures');
  assert.notEqual(r.y1, r.y0, 'one finger orbits after the tap');
  assert.ok(!r.after && r.afterTouch === 'pan-y', 'a tap outside deactivates the view');
  assert.equal(r.pageTouch, 'auto', 'the page keeps scrolling by touch');
  assert.deepEqual(problems, []);
  await page.close();
});

test('axe-core: no serious or critical accessibility violation on the test page', async () => {
  const context = await browser.newContext({ bypassCSP: true }); // to inject axe
  const page = await context.newPage();
  await page.goto(`${base}/dev/view3d-demo.html?fallback`);
  await page.waitForSelector('body[data-ready]', { timeout: 20000 });
  await page.addScriptTag({ path: join(ROOT, 'node_modules', 'axe-core', 'axe.min.js') });
  const violations = await page.evaluate(async () => (await window.axe.run(document, { resultTypes: ['violations'] })).violations
    .filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`));
  assert.deepEqual(violations, []);
  await context.close();
});

test('exports: a 2D plot (plot2d.js) as SVG, exactly as drawn, parses back', { skip: existsSync(join(ROOT, 'www', 'demos', 'bspline-basics.js')) ? false : 'needs the bspline-basics demo' }, async () => {
  const page = await browser.newPage({ viewport: { width: 1100, height: 900 } });
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(`${base}/index.html#bspline-basics`);
  await page.waitForSelector('[data-mounted="true"]', { timeout: 20000 });
  const r = await page.evaluate(async () => {
    const ex = await import('../lib/export.js');
    const plot = document.querySelector('canvas').splinePlot;
    const before = plot.canvas.getContext('2d').getImageData(0, 0, plot.canvas.width, plot.canvas.height).data.reduce((s, v) => s + v, 0);
    const svg = ex.plotToSVG(plot);
    const after = plot.canvas.getContext('2d').getImageData(0, 0, plot.canvas.width, plot.canvas.height).data.reduce((s, v) => s + v, 0);
    const doc = new DOMParser().parseFromString(svg, 'image/svg+xml');
    const texts = [...doc.querySelectorAll('text')].map((t) => t.textContent);
    const colours = new Set([...doc.querySelectorAll('path')].map((p) => p.getAttribute('stroke')));
    return { error: !!doc.querySelector('parsererror'), paths: doc.querySelectorAll('path').length, texts, colours: [...colours],
      width: Number(doc.documentElement.getAttribute('width')), cssWidth: plot.width, before, after, ownProps: Object.keys(plot.g).length };
  });
  assert.equal(r.error, false, 'SVG parses');
  assert.ok(r.paths > 10, `paths: ${r.paths}`);
  for (const label of ['P₀', 'P₆', '1']) assert.ok(r.texts.includes(label), `label ${label} in ${r.texts.join(' ')}`);
  assert.ok(r.colours.includes('#0072B2'), 'the curve colour is kept');
  assert.equal(r.width, r.cssWidth, 'CSS pixel size');
  assert.equal(r.after, r.before, 'the canvas is repainted identically');
  assert.equal(r.ownProps, 0, 'the context is restored');
  assert.deepEqual(errors, []);
  await page.close();
});

test('linked views share the camera; export buttons download parseable files', async () => {
  const { page, problems } = await open();
  const box = await canvasBox(page);
  await page.mouse.move(box.x + 30, box.y + 30);
  await page.mouse.down();
  await page.mouse.move(box.x + 90, box.y + 50, { steps: 5 });
  await page.mouse.up();
  const [v1, v2] = await page.evaluate(() => [window.__view.getView(), window.__view2.getView()]);
  assert.deepEqual(v2, v1, 'second view follows the first');
  assert.equal(await page.locator('#view2 .sl-legend').isVisible(), true);
  assert.match(await page.locator('#view2 .sl-legend').textContent(), /z − mean/);

  const grab = async (label) => {
    const [dl] = await Promise.all([page.waitForEvent('download'), page.click(`#exports button:text-is("${label}")`)]);
    const path = await dl.path();
    const { readFileSync } = await import('node:fs');
    return { name: dl.suggestedFilename(), data: readFileSync(path) };
  };
  const png = await grab('PNG');
  assert.equal(png.name, 'view3d-test.png');
  assert.deepEqual([...png.data.subarray(0, 4)], [137, 80, 78, 71]);
  const obj = await grab('OBJ');
  const text = obj.data.toString('utf8');
  assert.equal(text.split('\n').filter((l) => l.startsWith('v ')).length, 48 * 24 + 41 * 41);
  assert.equal(text.split('\n').filter((l) => l.startsWith('f ')).length, 2 * (47 * 23 + 40 * 40));
  const json = JSON.parse((await grab('JSON')).data.toString('utf8'));
  assert.equal(json.controlPoints.length, 5);
  const csv = (await grab('CSV')).data.toString('utf8').trim().split('\n');
  assert.equal(csv[0], 'x,y,z');
  assert.equal(csv.length, 6);
  assert.deepEqual(problems, []);
  await page.close();
});

test('clicking a pickable surface reports the hit with its grid indices; a drag does not', async () => {
  const { page, problems } = await open();
  await page.waitForFunction(() => window.__view3, null, { timeout: 20000 });
  const canvas = page.locator('#view3 canvas.sl-view3d-canvas');
  await canvas.scrollIntoViewIfNeeded();
  const box = await canvas.boundingBox();
  // a drag (orbit) is not a pick
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 30, box.y + box.height / 2, { steps: 3 });
  await page.mouse.up();
  assert.match(await page.locator('#picked').textContent(), /Click the surface/);
  // a click on the middle of the dome
  const hit = await page.evaluate(() => {
    const v = window.__view3, c = v.canvas;
    return v.pickSurface(c.clientWidth / 2, c.clientHeight / 2);
  });
  assert.ok(hit && hit.kind === 'surface' && hit.id === 'S', 'the ray hits the surface');
  assert.ok(hit.iu >= 0 && hit.iu < 64 && hit.iv >= 0 && hit.iv < 64);
  assert.equal(hit.position.length, 3);
  await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
  assert.match(await page.locator('#picked').textContent(), /picked S at grid \(\d+, \d+\), \(u, v\) ≈ \(0\.\d+, 0\.\d+\)/);
  // clicking empty background picks nothing
  await page.mouse.click(box.x + 5, box.y + 5);
  assert.deepEqual(problems, []);
  await page.close();
});

test('bad and degenerate input: field-named errors, no crash, the view keeps working', async () => {
  const { page, problems } = await open();
  const r = await page.evaluate(async () => {
    const { View3D } = await import('../lib/view3d.js');
    const host = document.createElement('div');
    document.body.appendChild(host);
    const v = new View3D(host, { height: 200 });
    const errors = [];
    const tryIt = (f) => { try { f(); return null; } catch (e) { errors.push(e.message); return e.message; } };
    tryIt(() => v.setMesh('m', { positions: [0, 0, 0, 1, 0, 0, 0, 1, 0], indices: [0, 1, 7] }));
    tryIt(() => v.setMesh('m', { positions: [0, 0, 0, 1, 0], indices: [0, 1, 2] }));
    tryIt(() => v.setMesh('m', { positions: [0, 0, 0, 1, 0, 0, 0, 1, 0], indices: [0, 1, 2] }, { colors: [1, 2] }));
    tryIt(() => v.setMesh('m', null));
    tryIt(() => v.setLines('l', 'nonsense'));
    // degenerate but valid: one point, NaN vertices, empty sets, garbage view
    v.setPoints('one', [[1, 2, 3]]);
    v.fit();
    v.renderNow();
    const single = v.getView();
    v.setMesh('nan', { positions: [0, 0, 0, NaN, 0, 0, 0, 1, 0], indices: [0, 1, 2] });
    v.setLines('empty', []);
    v.setPoints('none', []);
    const badView = v.setView({ yaw: 'x', distance: -1, target: [1, NaN, 2] });
    v.remove('does-not-exist');
    v.renderNow();
    const ok = v.getView();
    v.setMesh('good', { positions: [0, 0, 0, 1, 0, 0, 0, 1, 0], indices: [0, 1, 2] });
    v.renderNow();
    v.destroy();
    v.render(); v.renderNow(); v.setPoints('after', [[0, 0, 0]]); v.destroy();
    return { errors, single, badView, ok, gone: !host.querySelector('canvas') };
  });
  assert.equal(r.errors.length, 5);
  assert.match(r.errors[0], /^mesh\.indices: index 7 out of range/);
  assert.match(r.errors[1], /^mesh\.positions: /);
  assert.match(r.errors[2], /^colors: need one value per vertex \(3\), got 2/);
  assert.match(r.errors[3], /^mesh: /);
  assert.match(r.errors[4], /^polylines: /);
  assert.ok(Number.isFinite(r.single.distance) && r.single.distance > 0.5, `a single point gets a sane frame (${r.single.distance})`);
  assert.deepEqual(r.single.target, [1, 2, 3]);
  assert.equal(r.badView, false, 'a garbage view is ignored');
  assert.ok(Object.values(r.ok).flat().every(Number.isFinite));
  assert.equal(r.gone, true, 'destroy removes the canvas');
  assert.deepEqual(problems, []);
  await page.close();
});

// Issue 13 (interaction): an object replaced by one of the same kind takes over the old one's GPU buffers and
// vertex arrays (rewritten in place, resized when the data grows or shrinks). The picture must be exactly that
// of a view that only ever saw the new objects.
test('replacing meshes, lines and points in place draws exactly what a fresh view draws', async () => {
  const { page, problems } = await open();
  const same = await page.evaluate(async () => {
    const { View3D } = await import('/lib/view3d.js');
    const grid = (n, f) => {
      const positions = new Float32Array(3 * n * n), indices = [];
      for (let i = 0; i < n; i++) for (let j = 0; j < n; j++) positions.set([i / (n - 1), j / (n - 1), f(i / (n - 1), j / (n - 1))], 3 * (i * n + j));
      for (let i = 0; i + 1 < n; i++) for (let j = 0; j + 1 < n; j++) { const a = i * n + j; indices.push(a, a + n, a + 1, a + 1, a + n, a + n + 1); }
      return { positions, indices: Uint32Array.from(indices), nu: n, nv: n };
    };
    const scene = (v, k) => {
      v.setMesh('m', grid(k === 0 ? 12 : 20, (u, w) => (k === 0 ? 0.3 * u * w : 0.4 * Math.sin(3 * u) * w)), { colors: k === 0 ? undefined : 'height', isolines: { every: 4 } });
      v.setLines('l', k === 0 ? [[0, 0, 0, 1, 1, 0.5]] : [[0, 1, 0, 1, 0, 0.2, 0.5, 0.5, 0.8]], { color: '#d55e00' });
      v.setPoints('p', k === 0 ? [0.5, 0.5, 0.5] : [0, 0, 0, 1, 1, 0.3], { size: 10 });
    };
    const box = (id) => { const d = document.createElement('div'); d.style.width = '400px'; document.body.appendChild(d); return d; };
    const a = new View3D(box(), { height: 300, axes: false }), b = new View3D(box(), { height: 300, axes: false });
    scene(a, 0); a.setView({ yaw: 30, pitch: 30, distance: 3, target: [0.5, 0.5, 0.2] }); a.renderNow();
    scene(a, 1); scene(a, 1);   // replaced twice before a frame: the second takes the first's (never uploaded) buffers
    scene(b, 1);
    for (const v of [a, b]) v.setView({ yaw: 30, pitch: 30, distance: 3, target: [0.5, 0.5, 0.2] });
    const png = (v) => v.toDataURL();
    const same = png(a) === png(b);
    a.destroy(); b.destroy();
    return same;
  });
  assert.ok(same, 'the replaced scene differs from a fresh one');
  assert.deepEqual(problems, []);
  await page.close();
});
