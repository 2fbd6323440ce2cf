//! The curve exports of Bézier remodelling: bezierRemodel, bezierDeCasteljau, bezierSpline, bsplineToBezier.

use super::*;

api_options! {
    /// The remodelling of `bezierRemodel`: the spline g of `BezierSplineOptions` raised to degree m + 1 with
    /// free parameters α (where: `at` or `samples`).
    pub struct BezierRemodelOptions extends "BezierSplineOptions" |o, m: usize, segments: usize| {
        /// The class C^r kept (default ⌊m/2⌋).
        r: usize = "r", opt "number" => |k| read_r(o, k, m)?;
        /// Apply eq. (9) (default true).
        enforce: bool = "enforce", opt "boolean" => |k| o.bool_or(k, true)?;
        /// `[I][k − 1]`, one row per segment (default: the classical elevation).
        alphas: AlphaTable = "alphas", opt "AlphaTable"
            => |k| read_alphas(o, k, m, segments, enforce.then_some(r))?;
        /// One-call curvature sweep over α_m^(I−1).
        alpha_sweep: Option<Vec<f64>> = "alphaSweep", opt "Numbers" => |k| o.f64s(k)?;
        /// The joint I of the sweep, 1..=L (default 1; read with `alphaSweep`).
        alpha_sweep_joint: usize = "alphaSweepJoint", opt "number"
            => |k| if alpha_sweep.is_some() { o.usize_or(k, 1, segments)? } else { 1 };
    }
}

#[wasm_bindgen(typescript_custom_section)]
const BEZIER_REMODEL_TS: &str = r#"
export interface BezierRemodelResult extends CurveResult {
  degree: number;
  breaks: Float64Array;
  controlPoints: Float64Array;
  alphas: Float64Array[];
  curvature: Float64Array;
  curvatureOriginal: Float64Array;
  curvatureMeasured: Float64Array;
  curvaturePredicted: Float64Array;
  curvaturePrinted: Float64Array;
  curvatureRatio: Float64Array;
  osculatingCentres: Float64Array;
  osculatingRadii: Float64Array;
  r: number;
  enforce: boolean;
  crResidual: number;
  crResidualOriginal: number;
  continuity: Float64Array[];
  continuityOriginal: Float64Array[];
  continuityMax: Float64Array;
  continuityScale: Float64Array;
  free: boolean[][];
  constraints: string[][];
  sweepCurvature?: Float64Array;
  sweepCurvaturePrinted?: Float64Array;
}
"#;

/// The Bézier spline raised to degree m + 1 with free parameters α, keeping C^r.
///
/// `bezierRemodel({ points, degree, breaks, alphas, r, enforce, at | samples, derivatives })` → curve result of
/// g* + `{ controlPoints, alphas, curvature, curvatureOriginal, continuity, … }` (see the module docs).
/// Defaults: `alphas` = the classical elevation, `r` = ⌊m/2⌋, `enforce` = true, `breaks` = 0, 1, …, L,
/// `degree` inferred from `points` and `breaks` (3 when neither is given).
#[wasm_bindgen(js_name = bezierRemodel, unchecked_return_type = "BezierRemodelResult")]
pub fn bezier_remodel(
    #[wasm_bindgen(unchecked_param_type = "BezierRemodelOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let mut spline = BezierSplineOptions::read(&o)?;
    let (m, breaks) = (spline.degree, spline.breaks_or_uniform());
    with_points!(spline.points, p => remodel(&o, m, breaks, p))
}

api_options! {
    /// One parameter of a Bézier spline (`bezierDeCasteljau`).
    pub struct BezierDeCasteljauOptions extends "FlatDim" |o| {
        /// b_0..b_{mL}; with neither degree nor breaks, one segment of degree points − 1 on [0, 1].
        points: Pts = "points", req "Points" => |k| o.points(k, 2)?;
        /// u_0..u_L (default 0, 1, …, L).
        breaks: Option<Vec<f64>> = "breaks", opt "Numbers" => |k| o.f64s(k)?;
        /// m (inferred from the points and breaks; points − 1 when neither is given).
        degree: usize = "degree", opt "number" => |k| {
            let whole = (points.len() - 1).min(MAX_BEZIER_DEGREE + 1);
            bezier_degree(o, k, "points", breaks.as_deref(), points.len(), whole)?
        };
        /// The parameter, in [u_0, u_L] (required).
        u: f64 = "u", req "number" => |k| o.req_f64(k)?;
    }
}

#[wasm_bindgen(typescript_custom_section)]
const BEZIER_DE_CASTELJAU_TS: &str = r#"
export interface BezierDeCasteljauResult {
  dim: number;
  degree: number;
  /** The segment I holding u (the right-hand one at an interior breakvalue, the last at u_L). */
  segment: number;
  u: number;
  /** The local t = (u − u_I)/(u_{I+1} − u_I). */
  t: number;
  /** `levels[r]` = b^r_0 … b^r_{m−r}, flat; b^r_k = (1 − t) b^{r−1}_k + t b^{r−1}_{k+1}. */
  levels: Float64Array[];
  /** g(u). */
  point: Float64Array;
}
"#;

/// Every intermediate point of de Casteljau's algorithm at u (for steppers).
///
/// `bezierDeCasteljau({ points, degree, breaks, u })` → `{ dim, degree, segment, u, t, levels, point }`:
/// de Casteljau's algorithm on the segment I of the spline that holds u (the right-hand one at an interior
/// breakvalue), at t = (u − u_I)/(u_{I+1} − u_I). `levels[r]` (flat points, a `Float64Array`) holds
/// b^r_0..b^r_{m−r}, with b^0_k = b_{mI+k} and b^r_k = (1 − t)b^{r−1}_k + t·b^{r−1}_{k+1}; `point` = g(u).
/// `degree` and `breaks` as in `bezierSpline` (one segment of degree `points.length − 1` when only `points`
/// and `u` are given with `degree` absent and no `breaks`).
#[wasm_bindgen(js_name = bezierDeCasteljau, unchecked_return_type = "BezierDeCasteljauResult")]
pub fn bezier_de_casteljau(
    #[wasm_bindgen(unchecked_param_type = "BezierDeCasteljauOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let BezierDeCasteljauOptions {
        points: pts,
        breaks,
        degree: m,
        u,
    } = BezierDeCasteljauOptions::read(&o)?;
    let breaks = breaks_or_uniform(breaks, m, pts.len());
    let dim = pts.dim() as f64;
    with_points!(pts, p => {
        let g = BezierSpline::new(m, breaks, p).map_err(core_err)?;
        let dc = g.de_casteljau(u).map_err(core_err)?;
        Ok(Out::new()
            .num("dim", dim)
            .num("degree", m as f64)
            .num("segment", dc.segment as f64)
            .num("u", u)
            .num("t", dc.t)
            .set("levels", crate::api::rows_out(dc.levels.iter().map(|l| flat(l))))
            .pts("point", &[dc.point()])
            .build())
    })
}

#[wasm_bindgen(typescript_custom_section)]
const ALPHA_TABLE_TS: &str = r#"
// Bézier remodelling

/** `alphas[I][k − 1]`; `null` where eq. (9) fixes the entry (with enforce). */
export type AlphaTable = ReadonlyArray<ReadonlyArray<number | null>>;
"#;

api_options! {
    /// A Bézier spline g of degree m on breakvalues u_0..u_L (`bezierSpline`, `bezierRemodel`).
    pub struct BezierSplineOptions extends "CurveSampling, FlatDim" |o| {
        /// b_0..b_{mL}.
        points: Pts = "points", req "Points" => |k| o.points(k, 2)?;
        /// u_0..u_L (default 0, 1, …, L).
        breaks: Option<Vec<f64>> = "breaks", opt "Numbers" => |k| o.f64s(k)?;
        /// m (inferred from the points and breaks; 3 when neither is given).
        degree: usize = "degree", opt "number"
            => |k| bezier_degree(o, k, "points", breaks.as_deref(), points.len(), 3)?;
    }
}

impl BezierSplineOptions {
    /// The breakvalues: as given, or 0, 1, …, L.
    fn breaks_or_uniform(&mut self) -> Vec<f64> {
        breaks_or_uniform(self.breaks.take(), self.degree, self.points.len())
    }
}

#[wasm_bindgen(typescript_custom_section)]
const BEZIER_SPLINE_TS: &str = r#"
export interface BezierSplineResult extends CurveResult {
  degree: number;
  breaks: Float64Array;
  curvature: Float64Array;
  crResidual: number;
  continuity: Float64Array[];
}
"#;

/// The Bézier spline g itself (the witness curve).
///
/// `bezierSpline({ points, degree, breaks, at | samples, derivatives })` → curve result of g itself +
/// `{ curvature (eq. 13 at every breakvalue), crResidual (eq. 2 for r = 1), continuity (rows of jumps of
/// orders 0..2 at the interior joints, as in bezierRemodel) }`: the witness curve.
#[wasm_bindgen(js_name = bezierSpline, unchecked_return_type = "BezierSplineResult")]
pub fn bezier_spline(
    #[wasm_bindgen(unchecked_param_type = "BezierSplineOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let mut spline = BezierSplineOptions::read(&o)?;
    let (m, breaks) = (spline.degree, spline.breaks_or_uniform());
    let order = o.derivatives(2)?;
    with_points!(spline.points, p => {
        let g = BezierSpline::new(m, breaks, p).map_err(core_err)?;
        let params = o.curve_params(g.domain())?;
        let curv: Vec<f64> = (0..=g.segments()).map(|i| g.break_curvature(i)).collect();
        let out = curve_result_for(&o, &g, &params, order)
            .num("degree", m as f64)
            .f64s("breaks", g.breaks())
            .f64s("curvature", &curv)
            .num("crResidual", g.cr_residual(1));
        Ok(continuity_out(out, "continuity", &g.joint_jumps(2)).build())
    })
}

api_options! {
    /// The B-spline of `bsplineToBezier`.
    pub struct BsplineToBezierOptions extends "FlatDim" |o| {
        /// Degree p (default 3).
        degree: usize = "degree", opt "number" => |k| o.usize_or(k, 3, MAX_BEZIER_DEGREE)?;
        /// Control points (at least degree + 1).
        points: Pts = "points", req "Points" => |k| o.points(k, degree + 1)?;
        /// Full knot vector (default clamped uniform on [0, 1]).
        knots: Vec<f64> = "knots", opt "Numbers" => |k| match o.f64s(k)? {
            Some(knots) => knots,
            None => knots::clamped_uniform(points.len(), degree, 0.0, 1.0),
        };
    }
}

#[wasm_bindgen(typescript_custom_section)]
const BSPLINE_TO_BEZIER_TS: &str = r#"
export interface BsplineToBezierResult {
  degree: number;
  breaks: Float64Array;
  /** Plain nested points, ready for bezierRemodel. */
  points: number[][];
  controlPoints: Float64Array;
  dim: number;
}
"#;

/// A B-spline as a Bézier spline on its domain.
///
/// `bsplineToBezier({ degree, knots, points })` → `{ degree, breaks, points, controlPoints, dim }`: the same
/// curve as a Bézier spline on the B-spline's domain (knot insertion to multiplicity p at every distinct
/// knot). `points` is a plain `number[][]` so the result can be passed straight to `bezierRemodel`;
/// `controlPoints` holds the same points flat. `knots` defaults to clamped uniform on [0, 1].
#[wasm_bindgen(js_name = bsplineToBezier, unchecked_return_type = "BsplineToBezierResult")]
pub fn bspline_to_bezier(
    #[wasm_bindgen(unchecked_param_type = "BsplineToBezierOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let BsplineToBezierOptions {
        degree,
        points: pts,
        knots,
    } = BsplineToBezierOptions::read(&o)?;
    with_points!(pts, p => {
        let curve = BSplineCurve::new(degree, knots, p).map_err(core_err)?;
        let g = BezierSpline::from_bspline(&curve).map_err(core_err)?;
        let rows: Vec<Vec<f64>> = g.points().iter().map(|q| flat(std::slice::from_ref(q))).collect();
        let dim = g.points().first().map_or(2, |_| rows[0].len());
        Ok(Out::new()
            .num("degree", g.degree() as f64)
            .f64s("breaks", g.breaks())
            .ser("points", &rows)
            .pts("controlPoints", g.points())
            .num("dim", dim as f64)
            .build())
    })
}
