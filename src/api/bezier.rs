//! Seed 001 exports: `bezierRemodel`, `bezierRemodelSurface`, `bezierSpline` (the witness g) and
//! `bsplineToBezier` (start from any B-spline).
//!
//! Extras of `bezierRemodel` beyond the contract of `api.md` (all per breakvalue I = 0..L unless stated):
//! * `degree` (= m + 1), `breaks`, `crResidual` (eq. 8 for g*), `crResidualOriginal` (eq. 2 for g);
//! * `free[I][k−1]` (booleans: the entry is free) and `constraints[I][k−1]` (the eq. 9 constraint that fixes
//!   it, e.g. `"α_1^(2) = 1 − α_2^(1)  (eq. 9)"`, or `""` when free);
//! * `curvature` = K*(u_I) by the corrected eq. (14), `curvatureOriginal` = K(u_I) by eq. (13),
//!   `curvatureMeasured` = |g*′ × g*″| / |g*′|³ from the derivatives (right-hand piece, last piece at u_L),
//!   `curvaturePredicted` = the right-sided eq. (15) m²/(m²−1)·α_2^{(I)}/(α_1^{(I)})²·K(u_I⁺) (valid for every
//!   r), `curvaturePrinted` = eq. (15) exactly as printed (wrong at interior I when r = 1), `curvatureRatio`;
//! * `osculatingCentres` (flat, dim per point) and `osculatingRadii` of g* at every breakvalue (radius 0 and
//!   centre = the point where the curvature is 0);
//! * **`continuity`**: an `Array` with one `Float64Array` per interior joint I = 1..L−1 (so L − 1 rows), row
//!   I − 1 holding r + 2 numbers: `continuity[I−1][i]` = ‖g*^{(i)}(u_I⁺) − g*^{(i)}(u_I⁻)‖∞ for i = 0..r+1
//!   (one-sided derivatives w.r.t. u, largest coordinate). `continuityOriginal` is the same for g;
//!   `continuityMax[i]` is the maximum over joints and `continuityScale[i]` the largest one-sided derivative
//!   of order i at the joints (≥ 1), so `continuityMax[i] / continuityScale[i]` is a relative jump;
//! * **one-call curvature sweep** (the paper's Fig. 3): with `alphaSweep` (numbers or a `Float64Array`) and
//!   `alphaSweepJoint` = I ∈ 1..=L (default 1), `sweepCurvature[j]` = K*(u_I) (corrected eq. 14) and
//!   `sweepCurvaturePrinted[j]` = eq. (15) as printed, with α_m^{(I−1)} = `alphaSweep[j]` and every other α as
//!   given (eq. 9 applied afterwards when enforced) — the same numbers as one `bezierRemodel` call per value.

use super::{core_err, curve_result_for, err_kind, flat, with_points, ApiResult, Opts, Out};
use crate::bezier::{
    alpha_roles, check_r, curvature_sweep, osculating_circle, AlphaRole, AlphaTable, BezierSpline,
    BezierSplineSurface, Remodelling, SurfaceRemodelling, MAX_BEZIER_DEGREE,
};
use crate::bspline::BSplineCurve;
use crate::error::ErrorKind;
use crate::knots;
use crate::point::Point;
use crate::sample::Curve;
use js_sys::Array;
use wasm_bindgen::prelude::*;

/// `degree` (or inferred from the point count and `breaks`) and `breaks` (default 0, 1, …, L).
fn degree_and_breaks(
    o: &Opts,
    deg_key: &str,
    breaks_key: &str,
    count: usize,
    default_degree: usize,
) -> ApiResult<(usize, Vec<f64>)> {
    let breaks = o.f64s(breaks_key)?;
    let degree = if o.has(deg_key) {
        o.usize_or(deg_key, default_degree, MAX_BEZIER_DEGREE)?
    } else if let Some(b) = &breaks {
        let l = b.len().saturating_sub(1);
        if l == 0 || count == 0 || !(count - 1).is_multiple_of(l) {
            return Err(err_kind(ErrorKind::SizeMismatch,
                deg_key,
                format!("not given, and {count} control points do not fit {l} segments (need mL + 1); give the degree"),
            ));
        }
        (count - 1) / l
    } else {
        default_degree
    };
    if degree == 0 {
        return Err(err_kind(
            ErrorKind::OutOfRange,
            deg_key,
            "need a degree m ≥ 1, got 0",
        ));
    }
    let breaks = match breaks {
        Some(b) => b,
        None => {
            if count == 0 || !(count - 1).is_multiple_of(degree) || count < degree + 1 {
                return Err(err_kind(ErrorKind::SizeMismatch,
                    "points",
                    format!("a Bézier spline of degree {degree} needs mL + 1 control points (L ≥ 1), got {count}"),
                ));
            }
            knots::uniform((count - 1) / degree + 1)
        }
    };
    Ok((degree, breaks))
}

/// Reads `alphas` (`[I][k − 1]`, numbers; `null` allowed where eq. (9) fixes the entry and `enforce` is
/// on); absent = the classical elevation.
fn read_alphas(
    o: &Opts,
    m: usize,
    segments: usize,
    enforce: Option<usize>,
) -> ApiResult<AlphaTable> {
    let raw: Option<Vec<Vec<Option<f64>>>> = o.opt("alphas")?;
    let Some(raw) = raw else {
        return Ok(AlphaTable::classical(m, segments));
    };
    if raw.len() != segments {
        return Err(err_kind(
            ErrorKind::SizeMismatch,
            "alphas",
            format!(
                "expected {segments} rows (one per segment I = 0..L−1), got {}",
                raw.len()
            ),
        ));
    }
    let roles = alpha_roles(m, segments, enforce.unwrap_or(0));
    let mut rows = Vec::with_capacity(segments);
    for (i, row) in raw.iter().enumerate() {
        if row.len() != m {
            return Err(err_kind(
                ErrorKind::SizeMismatch,
                &format!("alphas[{i}]"),
                format!("expected {m} entries α_1..α_m (m = {m}), got {}", row.len()),
            ));
        }
        let mut out = Vec::with_capacity(m);
        for (k, a) in row.iter().enumerate() {
            out.push(match (a, roles[i][k]) {
                (Some(x), _) => *x,
                (None, role) if enforce.is_some() && !role.is_free() => 0.5, // overwritten by eq. (9)
                (None, _) => {
                    return Err(err_kind(
                        ErrorKind::OutOfRange,
                        &format!("alphas[{i}][{k}]"),
                        format!("α_{}^({i}) is free and needs a number in (0, 1)", k + 1),
                    ))
                }
            });
        }
        rows.push(out);
    }
    AlphaTable::new(m, segments, rows).map_err(core_err)
}

fn rows_array(rows: &[Vec<f64>]) -> Array {
    let arr = Array::new();
    for r in rows {
        let f = js_sys::Float64Array::new_with_length(r.len() as u32);
        f.copy_from(r);
        arr.push(&f);
    }
    arr
}

fn roles_out(out: Out, roles: &[Vec<AlphaRole>], m: usize) -> Out {
    let free: Vec<Vec<bool>> = roles
        .iter()
        .map(|r| r.iter().map(|x| x.is_free()).collect())
        .collect();
    let text: Vec<Vec<String>> = roles
        .iter()
        .enumerate()
        .map(|(i, r)| {
            r.iter()
                .enumerate()
                .map(|(k, x)| x.describe(m, i, k + 1))
                .collect()
        })
        .collect();
    out.ser("free", &free).ser("constraints", &text)
}

fn continuity_out(out: Out, key: &str, jumps: &[Vec<f64>]) -> Out {
    out.set(key, rows_array(jumps))
}

fn read_r_enforce(o: &Opts, m: usize) -> ApiResult<(usize, bool)> {
    let r = o.usize_or("r", m / 2, 1000)?;
    check_r(m, r).map_err(core_err)?;
    let enforce = o.bool_or("enforce", true)?;
    Ok((r, enforce))
}

fn remodel<P: Point>(o: &Opts, m: usize, breaks: Vec<f64>, pts: Vec<P>) -> ApiResult<JsValue> {
    let (r, enforce) = read_r_enforce(o, m)?;
    let g = BezierSpline::new(m, breaks, pts).map_err(core_err)?;
    let l = g.segments();
    let order = o.derivatives(2)?;
    let en = if enforce { Some(r) } else { None };
    let alphas = read_alphas(o, m, l, en)?;
    let sweep = match o.f64s("alphaSweep")? {
        Some(values) => {
            let joint = o.usize_or("alphaSweepJoint", 1, l)?;
            Some(curvature_sweep(&g, &alphas, en, joint, &values).map_err(core_err)?)
        }
        None => None,
    };
    let rem = Remodelling::new(g, alphas, en).map_err(core_err)?;
    let params = o.curve_params(rem.domain())?;
    let gs = rem.elevated();
    let joints = 0..=l;
    let curv: Vec<f64> = joints.clone().map(|i| rem.curvature(i)).collect();
    let curv0: Vec<f64> = joints.clone().map(|i| rem.curvature_original(i)).collect();
    let meas: Vec<f64> = joints.clone().map(|i| rem.curvature_measured(i)).collect();
    let pred: Vec<f64> = joints.clone().map(|i| rem.curvature_predicted(i)).collect();
    let printed: Vec<f64> = joints.clone().map(|i| rem.curvature_printed(i)).collect();
    let ratio: Vec<f64> = joints.clone().map(|i| rem.curvature_ratio(i)).collect();
    let mut centres = Vec::with_capacity(l + 1);
    let mut radii = Vec::with_capacity(l + 1);
    for &u in gs.breaks() {
        let (c, rad) = osculating_circle(gs, u);
        centres.push(c);
        radii.push(rad);
    }
    let jumps = gs.joint_jumps(r + 1);
    let cmax: Vec<f64> = (0..=r + 1)
        .map(|i| jumps.iter().map(|j| j[i]).fold(0.0, f64::max))
        .collect();
    let cscale: Vec<f64> = (0..=r + 1).map(|i| gs.joint_scale(i)).collect();
    let mut out = curve_result_for(o, &rem, &params, order)
        .num("degree", (m + 1) as f64)
        .f64s("breaks", gs.breaks())
        .pts("controlPoints", gs.points())
        .set("alphas", rows_array(rem.alphas().rows()))
        .f64s("curvature", &curv)
        .f64s("curvatureOriginal", &curv0)
        .f64s("curvatureMeasured", &meas)
        .f64s("curvaturePredicted", &pred)
        .f64s("curvaturePrinted", &printed)
        .f64s("curvatureRatio", &ratio)
        .pts("osculatingCentres", &centres)
        .f64s("osculatingRadii", &radii)
        .num("r", r as f64)
        .set("enforce", enforce)
        .num("crResidual", gs.cr_residual(r))
        .num("crResidualOriginal", rem.original().cr_residual(r))
        .f64s("continuityMax", &cmax)
        .f64s("continuityScale", &cscale);
    out = continuity_out(out, "continuity", &jumps);
    out = continuity_out(
        out,
        "continuityOriginal",
        &rem.original().joint_jumps(r + 1),
    );
    out = roles_out(out, &rem.roles(), m);
    if let Some((k, printed)) = sweep {
        out = out
            .f64s("sweepCurvature", &k)
            .f64s("sweepCurvaturePrinted", &printed);
    }
    Ok(out.build())
}

#[wasm_bindgen(typescript_custom_section)]
const BEZIER_REMODEL_TS: &str = r#"
export interface BezierRemodelOptions extends BezierSplineOptions {
  alphas?: AlphaTable;
  /** The class C^r kept (default ⌊m/2⌋). */
  r?: number;
  /** Apply eq. (9) (default true). */
  enforce?: boolean;
  /** One-call curvature sweep over α_m^(I−1). */
  alphaSweep?: Numbers;
  alphaSweepJoint?: number;
}
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
    let pts = o.points("points", 2)?;
    let (m, breaks) = degree_and_breaks(&o, "degree", "breaks", pts.len(), 3)?;
    with_points!(pts, p => remodel(&o, m, breaks, p))
}

#[wasm_bindgen(typescript_custom_section)]
const BEZIER_DE_CASTELJAU_TS: &str = r#"
export interface BezierDeCasteljauOptions extends FlatDim {
  /** b_0..b_{mL}; with neither degree nor breaks, one segment of degree points − 1 on [0, 1]. */
  points: Points;
  degree?: number;
  /** u_0..u_L (default 0, 1, …, L). */
  breaks?: Numbers;
  /** The parameter, in [u_0, u_L] (required). */
  u: number;
}
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
    let pts = o.points("points", 2)?;
    let whole = (pts.len() - 1).min(MAX_BEZIER_DEGREE + 1);
    let (m, breaks) = degree_and_breaks(&o, "degree", "breaks", pts.len(), whole)?;
    let u = o.req_f64("u")?;
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
            .set("levels", super::rows_out(dc.levels.iter().map(|l| flat(l))))
            .pts("point", &[dc.point()])
            .build())
    })
}

#[wasm_bindgen(typescript_custom_section)]
const BEZIER_SPLINE_TS: &str = r#"
// Bézier remodelling

/** `alphas[I][k − 1]`; `null` where eq. (9) fixes the entry (with enforce). */
export type AlphaTable = ReadonlyArray<ReadonlyArray<number | null>>;

export interface BezierSplineOptions extends CurveSampling, FlatDim {
  /** b_0..b_{mL}. */
  points: Points;
  /** m (inferred from the points and breaks; 3 when neither is given). */
  degree?: number;
  /** u_0..u_L (default 0, 1, …, L). */
  breaks?: Numbers;
}
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
    let pts = o.points("points", 2)?;
    let (m, breaks) = degree_and_breaks(&o, "degree", "breaks", pts.len(), 3)?;
    let order = o.derivatives(2)?;
    with_points!(pts, p => {
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

#[wasm_bindgen(typescript_custom_section)]
const BEZIER_REMODEL_SURFACE_TS: &str = r#"
export interface BezierRemodelSurfaceOptions extends SurfaceSampling, GridDim {
  /** points[k][l], k = 0..mL along u. */
  points: Grid;
  degreeU?: number;
  degreeV?: number;
  breaksU?: Numbers;
  breaksV?: Numbers;
  alphas?: AlphaTable;
  r?: number;
  enforce?: boolean;
}
export interface BezierRemodelSurfaceResult extends SurfaceResult {
  controlPoints: Float64Array;
  degreeU: number;
  degreeV: number;
  rows: number;
  cols: number;
  alphas: Float64Array[];
  r: number;
  continuity: Float64Array[];
  continuityOriginal: Float64Array[];
  free: boolean[][];
  constraints: string[][];
}
"#;

/// Remodelling of a Bézier spline surface in u (one patch row in v).
///
/// `bezierRemodelSurface({ points, degreeU, degreeV, breaksU, breaksV, alphas, r, enforce, atUV |
/// samplesU/samplesV, derivatives, mesh })` → surface result of G* (`mesh: true` adds render buffers) + `{ controlPoints, alphas, free, constraints,
/// continuity, continuityOriginal, degreeU, rows, cols }`. `points[k][l]`: k = 0..mL along u, l along v;
/// `breaksV` defaults to [0, 1] (one patch row, n = columns − 1); `controlPoints` are b*_{k,l}, k-major,
/// `rows` × `cols` = ((m+1)L + 1) × (n + 1); `continuity[I−1][i]` = the jump of ∂^i G* / ∂u^i across u = u_I
/// (largest over the boundary's control coefficients), i = 0..r+1.
#[wasm_bindgen(js_name = bezierRemodelSurface, unchecked_return_type = "BezierRemodelSurfaceResult")]
pub fn bezier_remodel_surface(
    #[wasm_bindgen(unchecked_param_type = "BezierRemodelSurfaceOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let (nr, nc, pts) = o.grid("points", 2, 2)?;
    let (m, breaks_u) = degree_and_breaks(&o, "degreeU", "breaksU", nr, 2)?;
    let breaks_v = o.f64s("breaksV")?.unwrap_or_else(|| vec![0.0, 1.0]);
    let n = if o.has("degreeV") {
        o.usize_or("degreeV", 1, MAX_BEZIER_DEGREE)?
    } else {
        let mv = breaks_v.len().saturating_sub(1).max(1);
        if (nc - 1) % mv != 0 {
            return Err(err_kind(
                ErrorKind::SizeMismatch,
                "degreeV",
                format!("not given, and {nc} columns do not fit {mv} segments in v; give degreeV"),
            ));
        }
        (nc - 1) / mv
    };
    if nr != m * breaks_u.len().saturating_sub(1) + 1 {
        return Err(err_kind(
            ErrorKind::SizeMismatch,
            "points",
            format!(
                "expected mL + 1 = {} rows along u (m = {m}, L = {}), got {nr}",
                m * breaks_u.len().saturating_sub(1) + 1,
                breaks_u.len().saturating_sub(1)
            ),
        ));
    }
    with_points!(pts, p => {
        let (r, enforce) = read_r_enforce(&o, m)?;
        let g = BezierSplineSurface::new(m, n, breaks_u, breaks_v, p).map_err(core_err)?;
        let l = g.breaks_u().len() - 1;
        let en = if enforce { Some(r) } else { None };
        let alphas = read_alphas(&o, m, l, en)?;
        let rem = SurfaceRemodelling::new(g, alphas, en).map_err(core_err)?;
        let (rows, cols) = rem.elevated().size();
        let mut out = super::mesh::surface_output(&o, &rem)?
            .pts("controlPoints", rem.elevated().points())
            .num("degreeU", (m + 1) as f64)
            .num("degreeV", n as f64)
            .num("rows", rows as f64)
            .num("cols", cols as f64)
            .set("alphas", rows_array(rem.alphas().rows()))
            .num("r", r as f64);
        out = continuity_out(out, "continuity", &rem.elevated().u_jumps(r + 1));
        out = continuity_out(out, "continuityOriginal", &rem.original().u_jumps(r + 1));
        out = roles_out(out, &rem.roles(), m);
        Ok(out.build())
    })
}

#[wasm_bindgen(typescript_custom_section)]
const BSPLINE_TO_BEZIER_TS: &str = r#"
export interface BsplineToBezierOptions extends FlatDim {
  degree?: number;
  knots?: Numbers;
  points: Points;
}
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
    let degree = o.usize_or("degree", 3, MAX_BEZIER_DEGREE)?;
    let pts = o.points("points", degree + 1)?;
    let knots = match o.f64s("knots")? {
        Some(k) => k,
        None => knots::clamped_uniform(pts.len(), degree, 0.0, 1.0),
    };
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

// ---- bi-degree remodelling (papers branch) ----

/// One parameter table from JSON rows (`null` allowed where `roles` fixes the entry and `enforce` is on),
/// errors naming `field[i][k]`.
fn table_from_rows(
    field: &str,
    raw: &[Vec<Option<f64>>],
    d: usize,
    segments: usize,
    enforce: Option<usize>,
) -> ApiResult<AlphaTable> {
    if raw.len() != segments {
        return Err(err_kind(
            ErrorKind::SizeMismatch,
            field,
            format!(
                "expected {segments} rows (one per segment), got {}",
                raw.len()
            ),
        ));
    }
    let roles = alpha_roles(d, segments, enforce.unwrap_or(0));
    let mut rows = Vec::with_capacity(segments);
    for (i, row) in raw.iter().enumerate() {
        if row.len() != d {
            return Err(err_kind(
                ErrorKind::SizeMismatch,
                &format!("{field}[{i}]"),
                format!("expected {d} entries (k = 1..{d}), got {}", row.len()),
            ));
        }
        let mut out = Vec::with_capacity(d);
        for (k, a) in row.iter().enumerate() {
            out.push(match (a, roles[i][k]) {
                (Some(x), _) => *x,
                (None, role) if enforce.is_some() && !role.is_free() => 0.5, // overwritten by eq. (9)
                (None, _) => {
                    return Err(err_kind(
                        ErrorKind::OutOfRange,
                        &format!("{field}[{i}][{k}]"),
                        "this entry is free and needs a number in (0, 1)",
                    ))
                }
            });
        }
        rows.push(out);
    }
    AlphaTable::new(d, segments, rows).map_err(|e| {
        let f = format!("{field}{}", e.field().trim_start_matches("alphas"));
        core_err(e.in_field(f))
    })
}

/// `alphas` / `betas` of `bezierRemodelSurfaceBi`: absent (classical), one table `[I][k − 1]` shared by
/// every line, or one table per line `[line][I][k − 1]`.
fn read_direction(
    o: &Opts,
    key: &str,
    d: usize,
    segments: usize,
    lines: usize,
    enforce: Option<usize>,
) -> ApiResult<crate::bezier::DirectionParams> {
    use crate::bezier::DirectionParams;
    let raw = o.raw(key);
    if raw.is_undefined() || raw.is_null() {
        return Ok(DirectionParams::Classical);
    }
    let per_line = Array::is_array(&raw) && {
        let first = raw.unchecked_ref::<Array>().get(0);
        Array::is_array(&first) && Array::is_array(&first.unchecked_ref::<Array>().get(0))
    };
    if per_line {
        let all: Vec<Vec<Vec<Option<f64>>>> = o.opt(key)?.unwrap_or_default();
        if all.len() != lines {
            return Err(err_kind(ErrorKind::Invalid,
                key,
                format!(
                    "expected one table per line ({lines}) or one shared table [I][k − 1], got {} tables",
                    all.len()
                ),
            ));
        }
        let tables = all
            .iter()
            .enumerate()
            .map(|(l, t)| table_from_rows(&format!("{key}[{l}]"), t, d, segments, enforce))
            .collect::<ApiResult<Vec<_>>>()?;
        Ok(DirectionParams::PerLine(tables))
    } else {
        let t: Vec<Vec<Option<f64>>> = o.opt(key)?.unwrap_or_default();
        Ok(DirectionParams::Shared(table_from_rows(
            key, &t, d, segments, enforce,
        )?))
    }
}

fn tables_array(tables: &[AlphaTable]) -> Array {
    let arr = Array::new();
    for t in tables {
        arr.push(&rows_array(t.rows()));
    }
    arr
}

#[wasm_bindgen(typescript_custom_section)]
const BEZIER_REMODEL_SURFACE_BI_TS: &str = r#"
export interface BezierRemodelSurfaceBiOptions extends SurfaceSampling, GridDim {
  points: Grid;
  degreeU?: number;
  degreeV?: number;
  breaksU?: Numbers;
  breaksV?: Numbers;
  /** One table [I][k − 1] shared by every column, or one per column [l][I][k − 1]. */
  alphas?: AlphaTable | ReadonlyArray<AlphaTable>;
  /** One table [J][l − 1] shared by every row, or one per row. */
  betas?: AlphaTable | ReadonlyArray<AlphaTable>;
  r?: number;
  s?: number;
  enforce?: boolean;
}
export interface BezierRemodelSurfaceBiResult extends SurfaceResult {
  controlPoints: Float64Array;
  degreeU: number;
  degreeV: number;
  rows: number;
  cols: number;
  alphas: Float64Array[][];
  betas: Float64Array[][];
  r: number;
  s: number;
  continuityU: Float64Array[];
  continuityV: Float64Array[];
  continuityUOriginal: Float64Array[];
  continuityVOriginal: Float64Array[];
}
"#;

/// The bi-degree remodelling (m, n) → (m + 1, n + 1), keeping C^{r,s}.
///
/// `bezierRemodelSurfaceBi({ points, degreeU, degreeV, breaksU, breaksV, alphas, betas, r, s, enforce,
/// atUV | samplesU/samplesV, derivatives, mesh })` → surface result of G* (degrees (m + 1, n + 1)) +
/// `{ controlPoints, degreeU, degreeV, rows, cols, alphas, betas, r, s, continuityU, continuityV,
/// continuityUOriginal, continuityVOriginal }`: the bi-degree remodelling of seed 001 §4.2, built as the
/// curve remodelling in u (per column l = 0..nM, eq. 17's α_{k,l}^{(I)}) and then in v (per row
/// k = 0..(m+1)L of the u-elevated net, β). `points[k][l]`: k = 0..mL, l = 0..nM; `degreeV` inferred from
/// the columns and `breaksV` (default [0, 1]). `alphas`: `[I][k − 1]` shared by every column or
/// `[l][I][k − 1]` per column (absent = classical); `betas`: `[J][l − 1]` shared or `[k][J][l − 1]` per row.
/// `enforce` (default true) keeps C^{r,s} (r ≤ ⌊m/2⌋, default ⌊m/2⌋; s ≤ ⌊n/2⌋, default ⌊n/2⌋): eq. (9) on
/// every line, and the lines nJ − s..nJ + s (columns) and (m+1)I − r..(m+1)I + r (rows) share the table of
/// the break line. `alphas` / `betas` in the result are the per-line tables used. `continuityU[I−1][i]` =
/// the jump of ∂^i/∂u^i across u = u_I (i = 0..r+1), `continuityV[J−1][j]` across v = v_J (j = 0..s+1).
#[wasm_bindgen(js_name = bezierRemodelSurfaceBi, unchecked_return_type = "BezierRemodelSurfaceBiResult")]
pub fn bezier_remodel_surface_bi(
    #[wasm_bindgen(unchecked_param_type = "BezierRemodelSurfaceBiOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    use crate::bezier::BiRemodelling;
    let o = Opts::new(options)?;
    let (nr, nc, pts) = o.grid("points", 2, 2)?;
    let (m, breaks_u) = degree_and_breaks(&o, "degreeU", "breaksU", nr, 2)?;
    let breaks_v = o.f64s("breaksV")?.unwrap_or_else(|| vec![0.0, 1.0]);
    let mv = breaks_v.len().saturating_sub(1).max(1);
    let n = if o.has("degreeV") {
        o.usize_or("degreeV", 1, MAX_BEZIER_DEGREE)?
    } else {
        if (nc - 1) % mv != 0 {
            return Err(err_kind(
                ErrorKind::SizeMismatch,
                "degreeV",
                format!("not given, and {nc} columns do not fit {mv} segments in v; give degreeV"),
            ));
        }
        (nc - 1) / mv
    };
    if n == 0 || n > MAX_BEZIER_DEGREE {
        return Err(err_kind(
            ErrorKind::OutOfRange,
            "degreeV",
            format!("need 1 ≤ n ≤ {MAX_BEZIER_DEGREE}, got {n}"),
        ));
    }
    let l_segs = breaks_u.len().saturating_sub(1);
    if nr != m * l_segs + 1 {
        return Err(err_kind(
            ErrorKind::SizeMismatch,
            "points",
            format!(
                "expected mL + 1 = {} rows along u (m = {m}, L = {l_segs}), got {nr}",
                m * l_segs + 1
            ),
        ));
    }
    if nc != n * mv + 1 {
        return Err(err_kind(
            ErrorKind::Invalid,
            "points",
            format!(
                "expected nM + 1 = {} columns along v (n = {n}, M = {mv}), got {nc}",
                n * mv + 1
            ),
        ));
    }
    let r = o.usize_or("r", m / 2, 1000)?;
    check_r(m, r).map_err(|e| core_err(e.in_field("r")))?;
    let s = o.usize_or("s", n / 2, 1000)?;
    check_r(n, s).map_err(|e| core_err(e.in_field("s")))?;
    let enforce = o.bool_or("enforce", true)?;
    let alphas = read_direction(&o, "alphas", m, l_segs, nc, enforce.then_some(r))?;
    let betas = read_direction(
        &o,
        "betas",
        n,
        mv,
        (m + 1) * l_segs + 1,
        enforce.then_some(s),
    )?;
    with_points!(pts, p => {
        let g = BezierSplineSurface::new(m, n, breaks_u, breaks_v, p).map_err(core_err)?;
        let rem = BiRemodelling::new(g, alphas, betas, enforce.then_some((r, s))).map_err(core_err)?;
        let (rows, cols) = rem.elevated().size();
        let (ju, jv) = rem.jumps(r + 1, s + 1);
        let orig_v = crate::bezier::transpose(rem.original())
            .map(|t| t.u_jumps(s + 1))
            .map_err(core_err)?;
        let mut out = super::mesh::surface_output(&o, &rem)?
            .pts("controlPoints", rem.elevated().points())
            .num("degreeU", (m + 1) as f64)
            .num("degreeV", (n + 1) as f64)
            .num("rows", rows as f64)
            .num("cols", cols as f64)
            .set("alphas", tables_array(rem.alphas()))
            .set("betas", tables_array(rem.betas()))
            .num("r", r as f64)
            .num("s", s as f64);
        out = continuity_out(out, "continuityU", &ju);
        out = continuity_out(out, "continuityV", &jv);
        out = continuity_out(out, "continuityUOriginal", &rem.original().u_jumps(r + 1));
        out = continuity_out(out, "continuityVOriginal", &orig_v);
        Ok(out.build())
    })
}
