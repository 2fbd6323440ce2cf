// The curve tab of "Bézier remodelling" (§2–3): the curve plot with draggable control points of g, the live
// Fig. 3, the controls (example, r, eq. (9), joint, what is shown, "Play u", the stepper, the α sliders, your
// data) and the tables. Computing is curve-compute.js, drawing curve-draw.js and steps.js; this module wires
// controls to the state and redraws.
import { mathText } from '../../lib/mathml.js';
import { h, fmt, legend, setLegendItems } from '../../lib/dom.js';
import { createPlot, curveSection, evenParams, paramRange } from '../../lib/plot2d.js';
import { slider, toggle, buttonGroup, group, readout, row } from '../../lib/controls.js';
import { uPlayer } from '../../lib/player.js';
import { stepper } from '../../lib/stepper.js';
import { dataImport } from '../../lib/data-import.js';
import { frameSteps } from '../../lib/frame-steps.js';
import { CURVE_PRESETS } from './data.js';
import { sub } from './notation.js';
import { sanitizeCurve, limitLast, applyCurvePreset, classicalAlphas } from './curve-state.js';
import { callRemodel, computeCurve, computeFig3, computeSteps, computeAtU, uRange } from './curve-compute.js';
import { describeCurve, drawCurve, drawCurveOver, curveLegendItems, fig3Title, describeFig3, fig3View, drawFig3, drawFig3Over } from './curve-draw.js';
import { ALGOS, remodelSteps, casteljauSteps } from './steps.js';
import { alphaSliders } from './alpha-sliders.js';
import { curveTables } from './curve-tables.js';

// the "Show" toggles: a state key each; they change the drawing and the legend only
const SHOW = [
  { key: 'showCircles', label: 'Osculating circle at joint I' },
  { key: 'showOriginal', label: 'Given curve g (dotted)' },
  { key: 'showPolygon', label: 'Control polygons' },
];
const choices = (values) => values.map((v) => ({ value: v, label: String(v) }));

/**
 * Builds the curve tab into `panel` (plots, tables) and `ctl` (controls). `defaults` is the demo's defaults().
 * Returns { sanitize, refreshControls, update, redraw, result, plot, destroy }.
 */
export function mountCurveTab({ wasm, state, ctx, notify, locked, panel, ctl, defaults }) {
  const c = { res: null, orig: null, fig3: null, dc: null, atU: null };   // computed (curve-compute.js)
  let steps = null; // the stepper (built with the controls)
  const imported = frameSteps();   // the frames of an import of your points (useData)

  // ---------- "Play u": the evaluation point g*(u) runs along [u₀, u_L] ----------
  const uOut = readout({ label: 'Evaluation point', value: '—' });
  uOut.el.dataset.readout = 'u';
  const refreshU = () => uOut.set(c.atU ? `u = ${fmt(state.u, 3)}: g*(u) = (${fmt(c.atU[0], 3)}, ${fmt(c.atU[1], 3)})` : '—');
  const player = uPlayer({
    range: () => uRange(state), get: () => state.u,
    set(v) { state.u = v; computeAtU(wasm, state, c); refreshU(); curvePlot.redraw(); },
    onPause() { ctx.save(); },
  });

  // ---------- the curve plot ----------
  const curvePlot = createPlot(panel, {
    ariaLabel: 'Remodelled Bézier spline g* (solid), the given spline g (dotted), draggable control points of g, osculating circles at the breakpoints',
    equal: true, height: 540, locked,
    view: { xmin: -10, xmax: 13, ymin: -4, ymax: 23 },
    describe: () => describeCurve(state, c),
    table: () => { const r = paramRange(c.res); return r ? [curveSection('The remodelled spline g* at 11 values of u', callRemodel(wasm, state, { at: evenParams(...r) }))] : []; },
    onView(v) { state.view = [v.xmin, v.xmax, v.ymin, v.ymax]; ctx.save(); },
    draw(g, plot) { drawCurve(plot, state, c); },
    drawOver(g, plot) { drawCurveOver(plot, state, c, player.playing); },
  });
  curvePlot.canvas.dataset.plot = 'curve';
  curvePlot.addHandles({
    name: 'control point',
    points: () => state.points,
    label: (i) => (i % state.degree === 0 ? '' : `b${sub(i)}`),
    labelOf: (i) => `Control point ${mathText(`b_{${i}}`)}`,
    radius: 7,
    move(i, q) { state.points[i] = [q[0], q[1]]; state.preset = 'custom'; update(); },
    end() { ctx.save(); },
  });
  const legendEl = legend([]);
  legendEl.dataset.legendFor = 'curve';
  const refreshLegend = () => setLegendItems(legendEl, curveLegendItems(state, c));
  panel.appendChild(legendEl);

  // ---------- Fig. 3 ----------
  const fig3TitleEl = h('h3', { class: 'plot-title', style: { margin: '0.5rem 0 0', fontSize: '1.05rem' } });
  panel.appendChild(fig3TitleEl);
  const fig3Plot = createPlot(panel, {
    ariaLabel: 'Fig. 3: curvature K* at a joint against the parameter αₘ of the previous segment',
    height: 250, pan: false, zoom: false, xLabel: 'αₘ⁽ᴵ⁻¹⁾', yLabel: 'K* at joint I',
    view: { xmin: 0, xmax: 0.55, ymin: 0, ymax: 1 },
    describe: () => describeFig3(c),
    draw(g, plot) { drawFig3(plot, state, c); },
    drawOver(g, plot) { drawFig3Over(plot, state, c); },
  });
  fig3Plot.canvas.dataset.plot = 'fig3';
  function fitFig3() { const v = fig3View(state, c); if (v) fig3Plot.setView(v); }
  const refreshTitles = () => { fig3TitleEl.textContent = fig3Title(state, c); };

  // ---------- controls ----------
  const presetCtl = buttonGroup({ label: 'Example', options: CURVE_PRESETS, value: state.preset, onChange: applyPreset });
  const rCtl = buttonGroup({ label: 'Keep Cʳ: r', options: choices([0, 1, 2, 3, 4]), value: state.r, onChange(v) { state.r = v; limitLast(state); update(); ctx.save(); } });
  const enforceCtl = toggle({ label: 'Enforce eq. (9)', value: state.enforce, hint: 'Off: every α is free and g* generally loses C¹ (see the jumps).', onChange(v) { state.enforce = v; limitLast(state); update(); ctx.save(); } });
  function onJoint(v) { state.joint = v; computeFig3(wasm, state, notify, c); fitFig3(); fig3Plot.redraw(); refreshTitles(); refreshLegend(); curvePlot.redraw(); ctx.save(); }
  const jointCtl = buttonGroup({ label: 'Fig. 3 at joint I', options: [1], value: state.joint, onChange: onJoint });
  const showCtls = SHOW.map(({ key, label }) => toggle({ label, value: state[key], onChange(v) { state[key] = v; refreshLegend(); curvePlot.redraw(); ctx.save(); } }));
  const alphas = alphaSliders({
    state, locked,
    onInput(I, k, v) { state.alphas[I][k - 1] = v; state.preset = 'custom'; update({ quick: true }); },
    onChange() { update(); ctx.save(); },
  });
  const tables = curveTables();
  // ---------- step by step ----------
  const algoCtl = buttonGroup({
    label: 'Algorithm', options: [{ value: 'remodel', label: 'Remodel g → g*' }, { value: 'casteljau', label: 'de Casteljau' }], value: state.stepAlgo,
    onChange(v) { state.stepAlgo = v; if (state.step >= 0) state.step = 0; steps.setTitle(ALGOS[v]); steps.refresh(); curvePlot.redraw(); ctx.save(); },
  });
  const stepUCtl = slider({
    label: 'Parameter u of the steps', min: state.breaks[0], max: state.breaks[state.breaks.length - 1], step: 0.001, value: state.stepU, number: true,
    hint: 'The segment I that holds u is the one remodelled and evaluated.',
    onInput(v) { state.stepU = v; computeSteps(wasm, state, c); steps.refresh(); curvePlot.redraw(); },
    onChange() { ctx.save(); },
  });
  steps = stepper({
    title: ALGOS[state.stepAlgo],
    steps: () => (state.stepAlgo === 'casteljau' ? casteljauSteps(state, c) : remodelSteps(state, c)),
    get: () => state.step,
    set(i) { state.step = i; curvePlot.redraw(); ctx.save(); },
  });

  ctl.append(
    group('Curve', presetCtl.el, rCtl.el, enforceCtl.el, tables.status),
    group('Show', jointCtl.el, ...showCtls.map((t) => t.el), h('div', { class: 'ctl-added' }, row(player.el), uOut.el)),
    group('Step by step', algoCtl.el, stepUCtl.el, steps.el),
    group('Parameters α (eq. 6)', alphas.el),
  );
  // "Use my data" (www/lib/data-import.js): your Bézier control points (degree m: m·L + 1 points, breaks 0..L,
  // the classical α, so g* = g until you move them)
  if (!locked) ctl.append(group('Your data', dataImport({ label: 'Use my control points', apply: 'Use these points', min: 3, max: 12 * 8 + 1, onData: useData }).el));
  // the number tables are wide: they go under the plots
  panel.insertBefore(h('div', { class: 'bezier-tables', style: { display: 'flex', flexWrap: 'wrap', gap: '0.5rem 1.5rem', alignItems: 'flex-start' } }, tables.curvature, tables.jumps), fig3TitleEl);

  const sanitize = () => sanitizeCurve(state, defaults());

  function refreshControls() {
    presetCtl.set(state.preset);
    rCtl.set(state.r);
    rCtl.inputs.forEach((inp, k) => { inp.disabled = locked || k > Math.floor(state.degree / 2); });
    enforceCtl.set(state.enforce);
    const joints = Array.from({ length: Math.max(0, state.breaks.length - 2) }, (_, i) => i + 1);
    // rebuild the joint choice when the number of joints changes
    if (jointCtl.inputs.length !== joints.length) {
      const fresh = buttonGroup({ label: 'Fig. 3 at joint I', options: choices(joints), value: state.joint, onChange: onJoint });
      jointCtl.el.replaceWith(fresh.el);
      Object.assign(jointCtl, fresh);
    }
    jointCtl.set(state.joint);
    // the steps' parameter runs over the whole spline, from the first break to the last
    stepUCtl.setRange({ min: state.breaks[0], max: state.breaks[state.breaks.length - 1] });
    stepUCtl.set(state.stepU);
    SHOW.forEach(({ key }, i) => showCtls[i].set(state[key]));
  }

  /** Recomputes from the state and refreshes everything the curve tab shows (quick: Fig. 3 keeps its view). */
  function update({ quick = false } = {}) {
    imported.cancel();   // this does all that an import still had to do
    compute();
    refreshSliders();
    refreshNumbers();
    if (!quick) fitFig3();
    curvePlot.redraw();
    fig3Plot.redraw();
  }
  // the parts of update(): every wasm call; the α sliders; the tables, titles, legend, g*(u) and the stepper
  function compute() { computeCurve(wasm, state, notify, c); computeAtU(wasm, state, c); }
  function refreshSliders() { alphas.build(); alphas.refresh(c.res); }
  function refreshNumbers() { tables.refresh(state, c.res); refreshTitles(); refreshLegend(); refreshU(); steps?.refresh(); }

  // "Use my data" (issue 26): 25 control points took up to 81 ms in one frame on a busy machine (the sliders of 12
  // segments built, the tables, five wasm calls, both plots painted). The click checks the points (a message naming
  // them when they do not fit the degree) and computes; the curve, the joint choice, the α sliders (four segments at
  // a time), then the tables and Fig. 3 follow in frames of their own (www/lib/frame-steps.js). A newer import or any
  // update() (a drag, a slider, an example: it builds what is missing) drops the rest.
  function useData(pts) {
    const m = state.degree, L = (pts.length - 1) / m;
    if (!Number.isInteger(L) || L < 1 || L > 12) throw new Error(`a Bézier spline of degree ${m} has m·L + 1 control points (${[1, 2, 3, 4].map((k) => k * m + 1).join(', ')}, …, L ≤ 12), got ${pts.length}`);
    imported.run([
      () => {
        Object.assign(state, { preset: 'custom', points: pts, breaks: Array.from({ length: L + 1 }, (_, i) => i), r: 1, enforce: true, joint: 1, alphas: classicalAlphas(m, L) });
        sanitize();
        compute();
        ctx.save();
      },
      () => { curvePlot.fitBounds(curvePlot.boundsOf(state.points), 40); },
      () => { refreshControls(); },
      // the α sliders, four segments' rows per frame
      ...Array.from({ length: Math.ceil(L / 4) }, () => () => { alphas.build(4); alphas.refresh(c.res); }),
      () => { refreshNumbers(); fitFig3(); fig3Plot.redraw(); },
    ]);
  }

  function applyPreset(p) {
    try { applyCurvePreset(state, p, wasm); } catch (e) { notify(e, 'error'); return; }
    sanitize();
    refreshControls();
    update();
    curvePlot.fitBounds(curvePlot.boundsOf(state.points), 40);
    ctx.save();
  }

  return {
    sanitize, refreshControls, update,
    redraw() { curvePlot.redraw(); fig3Plot.redraw(); },
    // a point drag's frame (update()) with the current state, for the idle warm-up; not while an import's frames
    // are pending (update() would drop them)
    warm() { if (!imported.pending) update(); },
    result: () => c.res,
    plot: curvePlot,
    destroy() { steps.destroy(); player.destroy(); curvePlot.destroy(); fig3Plot.destroy(); },
  };
}
