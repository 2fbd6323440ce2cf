// Demo "Bézier remodelling" (Gânscă–Coman–Ţămbulea): a parametric degree elevation of a Bézier
// spline that keeps its class C^r. Sliders for the parameters α_k^(I) (the ones eq. (9) fixes are greyed with
// the constraint), curvature at every breakpoint (formula vs measured) with osculating circles, the paper's
// Fig. 3 (K* against α_m) as a live plot, and a surface tab (§4.1, Figs. 4–5; §4.2 bi-degree). All spline values
// come from the wasm API (bezierRemodel, bezierSpline, bezierRemodelSurface, bezierRemodelSurfaceBi,
// bsplineToBezier, bezierDeCasteljau); the modules in bezier-remodel/ draw and react:
//   data.js            the paper's examples and presets        notation.js   αₖ⁽ᴵ⁾, sub/superscripts
//   curve.js           the curve tab (plots, controls, tables)  curve-state.js  its state rules and examples
//   curve-compute.js   what it computes                          curve-draw.js   what it draws (pure)
//   steps.js           the stepper (remodel g → g*, de Casteljau) alpha-sliders.js, curve-tables.js
//   surface.js         the surface tab (§4.1)                    bi-surface.js   its §4.2 part
// This entry holds the demo contract (www/demos/README.md): meta, the declared state, mount, snippet.

import { h, demoLayout, explanation } from '../lib/dom.js';
import { cite, correctionLink } from '../lib/papers-ref.js';
import { buttonGroup } from '../lib/controls.js';
import { restoreView } from '../lib/plot2d.js';
import { code, snippetCode } from '../lib/snippet.js';
import { EXAMPLE_POINTS, EXAMPLE_BREAKS, FIG1, SURFACE_POINTS, SURFACE_PRESETS } from './bezier-remodel/data.js';
import { mountCurveTab } from './bezier-remodel/curve.js';
import { mountSurfaceTab, sanitizeSurface } from './bezier-remodel/surface.js';
import { biDefaults } from './bezier-remodel/bi-surface.js';

export const meta = {
  id: 'bezier-remodel',
  title: 'Bézier remodelling',
  summary: 'Raise the degree of a Bézier spline with free parameters α: reshape it while it stays Cʳ; watch the curvature at the joints.',
  paper: cite('001', '§2–4'),
};

export function defaults() {
  return {
    tab: 'curve',
    preset: 'fig1',
    degree: 2,
    points: EXAMPLE_POINTS.map((p) => [...p]),
    breaks: [...EXAMPLE_BREAKS],
    alphas: FIG1.map((r) => [...r]),
    r: 1,
    enforce: true,
    joint: 1,
    showCircles: true,
    showOriginal: true,
    showPolygon: true,
    u: 0,
    stepAlgo: 'remodel', // the stepper: 'remodel' (g → b* → g* on one segment) or 'casteljau' (g* at stepU)
    step: -1,            // its step (-1 = off)
    stepU: 1.375,        // the parameter of the steps (segment I = the one holding it)
    view: [],
    surface: { preset: 'fig5', alphas: SURFACE_PRESETS.fig5.alphas.map((r) => [...r]), r: 1, enforce: true, yaw: -60, pitch: 28, showOriginal: true, showNet: true, camera: [] },
    bi: biDefaults(), // surface tab, §4.2 (bi-degree): bezier-remodel/bi-surface.js
  };
}

/** @param {HTMLElement} root @param {import('../lib/host.js').DemoContext} ctx @returns {import('../lib/host.js').MountedDemo} */
export function mount(root, ctx) {
  const { wasm, state, notify, options } = ctx;
  const L = demoLayout(root, options);
  const locked = !!options.locked;

  // ---------- layout: two tabs, each a panel of figures and a box of controls ----------
  const curvePanel = h('div', { class: 'bezier-curve-panel' });
  const surfacePanel = h('div', { class: 'bezier-surface-panel' });
  const curveCtl = h('div');
  const surfaceCtl = h('div');
  L.plots.append(curvePanel, surfacePanel);
  const curve = mountCurveTab({ wasm, state, ctx, notify, locked, panel: curvePanel, ctl: curveCtl, defaults });
  const surface = mountSurfaceTab({ wasm, state, ctx, notify, locked, panel: surfacePanel, ctl: surfaceCtl });

  // ---------- tabs ----------
  const tabCtl = buttonGroup({ label: 'Show', options: [{ value: 'curve', label: 'Curve (§2–3)' }, { value: 'surface', label: 'Surface (§4)' }], value: state.tab, onChange(v) { state.tab = v; showTab(); ctx.save(); } });
  L.controls.append(tabCtl.el, curveCtl, surfaceCtl);
  function showTab() {
    const c = state.tab !== 'surface';
    curvePanel.hidden = !c; curveCtl.hidden = !c;
    surfacePanel.hidden = c; surfaceCtl.hidden = c;
    tabCtl.set(state.tab);
    if (c) curve.redraw(); else surface.frame();
  }

  // ---------- explanation ----------
  explanation(L.explain, {
    what: [
      'A Bézier spline g of degree m (here the paper’s quadratic example, 11 control points, breakvalues 0, 1, 7/4, 5/2, 13/4, 4) is rewritten with degree m + 1. The classical degree elevation puts each new control point at a fixed place on the old control polygon and gives the same curve; here each new point b*₍ₘ₊₁₎ᵢ₊ₖ slides along its polygon leg with a free parameter αₖ⁽ᴵ⁾ ∈ (0, 1), which changes the shape while the breakpoints stay put.',
      'To keep the curve Cʳ at the joints, eq. (9) ties some parameters to the last parameter αₘ of a segment: those sliders are greyed and say which constraint fixes them. The others are free. The curvature at each breakpoint follows from the α (eq. 15): the table compares the formulas (13), the corrected (14) and the right-sided (15) with the curvature measured from the derivatives; the circles are the osculating circles there. The lower plot is the paper’s Fig. 3, computed live: K* at one joint as αₘ of the previous segment moves (the dot is the current value).',
    ],
    math: [
      'b^{*}_{(m+1)I} = b_{mI}, \\quad b^{*}_{(m+1)I+k} = (1 - \\alpha^{(I)}_{k})\\,b_{mI+k-1} + \\alpha^{(I)}_{k}\\,b_{mI+k} \\;(k = 1, \\ldots, m) \\quad (6)',
      '\\alpha_{k} = \\frac{m + 1 - k}{m + 1} \\;\\Rightarrow\\; g^{*} = g \\quad (\\text{classical elevation})',
      '\\alpha^{(I)}_{p} = 1 - p\\,\\alpha^{(I-1)}_{m} \\;(p = 1, \\ldots, r), \\quad \\alpha^{(I)}_{m-p+1} = p\\,\\alpha^{(I)}_{m} \\;(p = 2, \\ldots, r), \\quad r \\le \\lfloor m/2 \\rfloor \\quad (9)',
      'K^{*}(u_{I}) = \\frac{m^{2}}{m^{2} - 1} \\cdot \\frac{\\alpha^{(I)}_{2}}{(\\alpha^{(I)}_{1})^{2}} \\cdot K(u^{+}_{I}) \\quad (\\text{right-sided form of (15), any}\\; r)',
      'b^{r}_{k} = (1 - t)\\,b^{r-1}_{k} + t\\,b^{r-1}_{k+1}, \\quad t = \\frac{u - u_{I}}{u_{I+1} - u_{I}} \\quad (\\text{de Casteljau})',
    ],
    mathLabel: 'Remodelling eqs. (6), (9), (15) and de Casteljau’s algorithm',
    formulaNote: ['Corrections (', correctionLink('correction-001-eq14', 'eq. (14)'), ', ', correctionLink('correction-001-eq15', 'eq. (15)'), ', ', correctionLink('correction-001-alpha', '§4.1 surface'), ', ', correctionLink('correction-001-breaks', 'breakvalues'), ', ', correctionLink('correction-001-eq20', 'eqs. (20)–(22)'), '): the printed (14) has wrong indices at I = L; the printed interior (15) uses α₂⁽ᴵ⁾ = 1 − 2αₘ⁽ᴵ⁻¹⁾, which holds only for r ≥ 2 (compare the last two columns with r = 1 on the quartic example). On the surface, “all α = 1/3” is not the usual elevation: it breaks C¹ (jump 1.5); the usual one is (2/3, 1/3).'],
    tryThis: [
      'Fig. 1 → move α₂⁽¹⁾ towards 0: near the joint u₂ the curve flattens and K*(u₂) falls (pick joint 2 for Fig. 3: the dot runs down the solid curve). With r = 1 the printed (15), dashed orange, predicts the opposite trend: it is only valid for r ≥ 2.',
      'Turn “Enforce eq. (9)” off and move any α₁: the d₁ jump at that joint is no longer 0 — g* has a kink.',
      'Choose “Quartic from a B-spline” and r = 2: C² is kept (d₂ ≈ 1e−15) and the d₃ jump is not; switch to r = 1 and compare the printed (15) column.',
      'Quartic example with r = 2: set αₘ of a segment to 1/(m + 1) = 0.2 (the dashed vertical line in Fig. 3): K* equals K at the next joint (remark c); below it K* > K, above it K* < K.',
      'Step by step: walk through the remodelling of the segment that holds u (the points b* appear one by one), then switch to de Casteljau to evaluate g* there.',
      'Surface tab: “Fig. 4 literally” shows the kink across u = 1 and u = 2 that the all-1/3 reading produces; Fig. 5 stays C¹.',
      'Surface tab, “Bi-degree (§4.2)”: pick column l = 0 and move α₂,₀⁽¹⁾: only the edge v = 0 region bends, the jumps d₀, d₁ across u = 1, 2 and v = 1 stay at rounding level and the corner points do not move; turn “Enforce eq. (9)” off and move β₁⁽¹⁾ to see the kink across v = 1.',
    ],
    paper: meta.paper,
  });

  // ---------- start ----------
  curve.sanitize();
  sanitizeSurface(state.surface, defaults().surface);
  curve.refreshControls();
  curve.update();
  surface.update();
  surface.showConstruction();
  showTab();
  if (!restoreView(curve.plot, state.view)) {
    state.view = [];
    curve.plot.fitBounds(curve.plot.boundsOf(state.points), 40);
  }

  return {
    destroy() { curve.destroy(); surface.destroy(); },
    // idle warm-up (www/lib/warm.js): the curve tab's point-drag frame with the current state (same pixels; no save)
    warm() { if (state.tab !== 'surface') curve.warm(); },
    // for the shell's Export row: the remodelled control data (curve tab) or the surface (surface tab)
    exports() {
      if (state.tab === 'surface' && state.bi.on) {
        const b = surface.biResult();
        return {
          json: b ? { surfaceBi: { controlPoints: b.controlPoints, alphas: b.alphas, betas: b.betas, continuityU: b.continuityU, continuityV: b.continuityV, uv: b.uv, points: b.points } } : undefined,
          obj: b?.mesh ? [{ name: 'bidegree_remodelled_surface', mesh: b.mesh }] : [],
          csv: b ? { points: b.points, dim: b.dim || 3 } : undefined,
        };
      }
      const sres = surface.result(), res = curve.result();
      if (state.tab === 'surface') {
        return {
          json: sres ? { surface: { controlPoints: sres.controlPoints, alphas: sres.alphas, uv: sres.uv, points: sres.points } } : undefined,
          obj: sres?.mesh ? [{ name: 'remodelled_surface', mesh: sres.mesh }] : [],
          csv: sres ? { points: sres.points, dim: sres.dim || 3 } : undefined,
        };
      }
      return {
        json: res ? {
          curve: { controlPoints: res.controlPoints, alphas: res.alphas, curvature: res.curvature, curvatureOriginal: res.curvatureOriginal, continuity: res.continuity },
          samples: { params: res.params, points: res.points },
        } : undefined,
        csv: res ? { points: res.points, dim: res.dim || 2 } : undefined,
      };
    },
  };
}

// ---------- "Copy as code" (www/lib/snippet.js): the API calls of this view with its data ----------

export function snippet(state) {
  if (state.tab === 'surface') {
    const s = state.surface;
    return snippetCode(meta.title, code`
      // the bi-quadratic/cubic Bézier patches of §4: control points [k][l] (k along u, l along v)
      const points = ${SURFACE_POINTS};
      // degree elevation 2 → 3 along u with the α of each segment (eq. 9 fixes some when C^r is enforced)
      const options = { degreeU: 2, degreeV: 3, breaksU: [0, 1, 2, 3], alphas: ${s.alphas}, r: ${s.r}, enforce: ${s.enforce} };
      const surface = sl.bezierRemodelSurface({ points, ...options, samplesU: 61, samplesV: 17, mesh: true });
      const original = sl.bezierRemodelSurface({ points, degreeU: 2, degreeV: 3, breaksU: [0, 1, 2, 3], samplesU: 61, samplesV: 17 });
      return { surface, original };
    `);
  }
  return snippetCode(meta.title, code`
    const points = ${state.points};
    const degree = ${state.degree};
    const breaks = ${state.breaks};
    // the parametric degree elevation g → g* with one α vector per segment (eq. 9 fixes some when C^r is enforced)
    const alphas = ${state.alphas};
    const curve = sl.bezierRemodel({ points, degree, breaks, alphas, r: ${state.r}, enforce: ${state.enforce}, samples: 600 });
    const original = sl.bezierSpline({ points, degree, breaks, samples: 600 });
    return { curve, original };
  `);
}
