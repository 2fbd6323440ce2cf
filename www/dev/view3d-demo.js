// Dev page for www/lib/view3d.js: exercises meshes (shaded, colour-mapped, wireframe, isolines), lines,
// draggable points and the exporters. Test geometry (a torus, a height field) is built here in JS; the curve
// through the draggable points comes from the wasm `bsplineCurve`.
import { View3D, linkViews } from '../lib/view3d.js';
import { exportButtons } from '../lib/export.js';

const status = document.getElementById('status');
const view = new View3D(document.getElementById('view'), { height: 460, ariaLabel: 'Test scene: torus, height field and a B-spline curve' });
window.__view = view;

/** A u-major nu × nv grid mesh of f(u, v) → [x, y, z] with u, v ∈ [0, 1]. */
function gridMesh(nu, nv, f) {
  const positions = new Float32Array(nu * nv * 3);
  for (let i = 0; i < nu; i++) for (let j = 0; j < nv; j++) positions.set(f(i / (nu - 1), j / (nv - 1)), 3 * (i * nv + j));
  const indices = [];
  for (let i = 0; i + 1 < nu; i++) for (let j = 0; j + 1 < nv; j++) {
    const a = i * nv + j, b = a + nv;
    indices.push(a, b, b + 1, a, b + 1, a + 1);
  }
  return { nu, nv, positions, indices: Uint32Array.from(indices) };
}

const torus = gridMesh(48, 24, (u, v) => {
  const R = 1, r = 0.38, a = 2 * Math.PI * u, b = 2 * Math.PI * v;
  return [(R + r * Math.cos(b)) * Math.cos(a) - 1.6, (R + r * Math.cos(b)) * Math.sin(a), r * Math.sin(b)];
});
const field = gridMesh(41, 41, (u, v) => {
  const x = 2 * u - 1, y = 2 * v - 1;
  return [x * 1.2 + 1.6, y * 1.2, 0.5 * Math.exp(-3 * (x * x + y * y)) * Math.cos(3 * x)];
});

let wire = false, cmap = true;
function showMeshes() {
  view.setMesh('torus', torus, { color: '#3f7fd6', wireframe: wire, colors: cmap ? 'height' : undefined, legend: 'height z' });
  view.setMesh('field', field, { color: '#e07b24', isolines: { every: 4 }, wireframe: wire });
}
showMeshes();

const ctrl = [[-2.4, -1.4, 0.2], [-1.2, -1.8, 1.2], [0, -1.2, 0.4], [1.2, -1.8, 1.3], [2.4, -1.4, 0.3]];
let wasm = null;
function showCurve() {
  view.setPoints('ctrl', ctrl, { color: '#d62728', size: 14, draggable: true, labels: ctrl.map((_, i) => `P${i}`), onDrag });
  view.setLines('polygon', [ctrl], { color: '#777777', width: 1.5 });
  if (!wasm) return;
  try {
    const n = ctrl.length, p = 3;
    const knots = [0, 0, 0, 0, ...Array.from({ length: n - p - 1 }, (_, k) => (k + 1) / (n - p)), 1, 1, 1, 1];
    const r = wasm.bsplineCurve({ degree: p, knots, points: ctrl, samples: 120 });
    view.setLines('curve', r.points, { color: '#111111', width: 3.5 });
    status.textContent = `curve: ${r.params.length} samples from wasm bsplineCurve`;
  } catch (e) {
    status.textContent = `wasm error: ${e.message}`;
  }
}
function onDrag(index, p, phase) {
  ctrl[index] = p;
  showCurve();
  if (phase === 'end') status.textContent = `moved P${index} to (${p.map((v) => v.toFixed(2)).join(', ')})`;
}

showCurve();
view.fit();
import('../pkg/splinelab.js').then(async (m) => {
  await m.default();
  wasm = m;
  showCurve();
  if (typeof m.crissCrossSurface === 'function' && typeof m.networkExample === 'function') {
    const view3 = new View3D(document.getElementById('view3'), { height: 360, ariaLabel: 'Criss-cross surface of a dome network' });
    window.__view3 = view3;
    const network = m.networkExample({ name: 'uniform-dome' });
    const t0 = performance.now();
    const r = m.crissCrossSurface({ network, samplesU: 64, samplesV: 64, mesh: true });
    const t1 = performance.now();
    view3.setMesh('S', r.mesh, { colors: 'height', isolines: true, pickable: true });
    view3.onPick((hit) => {
      if (hit.kind !== 'surface') return;
      const uv = [r.uv[2 * hit.vertex], r.uv[2 * hit.vertex + 1]];
      document.getElementById('picked').textContent = `picked ${hit.id} at grid (${hit.iu}, ${hit.iv}), (u, v) ≈ (${uv.map((t) => t.toFixed(3)).join(', ')})`;
    });
    view3.setPoints('C', r.controlPoints, { size: 9, color: '#111111' });
    view3.renderNow();
    const t2 = performance.now();
    document.getElementById('timing').textContent = `64×64 surface: wasm ${(t1 - t0).toFixed(1)} ms, setMesh + first draw ${(t2 - t1).toFixed(1)} ms`;
  }
  document.body.dataset.ready = 'true';
}).catch((e) => {
  status.textContent = `wasm not available (${e.message}); run scripts/build-wasm.sh`;
  document.body.dataset.ready = 'true';
});

document.getElementById('fit').addEventListener('click', () => view.fit());
document.getElementById('wire').addEventListener('click', () => { wire = !wire; showMeshes(); });
document.getElementById('cmap').addEventListener('click', () => { cmap = !cmap; showMeshes(); });
let axes = false;
document.getElementById('axes').addEventListener('click', () => { axes = !axes; view.setAxes(axes); });
document.getElementById('exports').append(exportButtons({
  name: 'view3d-test',
  png: view,
  json: () => ({ controlPoints: ctrl }),
  obj: () => [{ name: 'torus', mesh: torus }, { name: 'field', mesh: field }],
  csv: () => ({ points: ctrl.flat(), dim: 3 }),
  onError: (e) => { status.textContent = `export failed: ${e.message}`; },
}));

// a second view with a signed scalar and the diverging map, camera linked to the first
const view2 = new View3D(document.getElementById('view2'), { height: 300, ariaLabel: 'Height field coloured by its signed height' });
window.__view2 = view2;
let mean = 0;
for (let i = 2; i < field.positions.length; i += 3) mean += field.positions[i];
mean /= field.positions.length / 3;
const signed = new Float32Array(field.positions.length / 3).map((_, i) => field.positions[3 * i + 2] - mean);
view2.setMesh('field', field, { colors: signed, colormap: 'diverging', legend: 'z − mean', isolines: { every: 5 } });
linkViews(view, view2);

// the no-WebGL2 fallback, side by side (small)
if (new URLSearchParams(location.search).has('fallback')) {
  new View3D(document.getElementById('fallback'), { height: 120, disableWebGL: true, ariaLabel: 'fallback test' });
}
