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

use super::{
    api_options, core_err, curve_result_for, err_kind, flat, with_points, ApiResult, Opts, Out, Pts,
};
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

mod curve;
pub use curve::*;
mod surface;
pub use surface::*;

/// The degree m of a Bézier spline with `count` control points: `deg_key` when given, else inferred from the
/// given breakvalues (count = mL + 1), else `default_degree`. Without breakvalues (the default 0, 1, …, L of
/// [`breaks_or_uniform`]) the count must be mL + 1 for this m (else an error on `points_key`).
fn bezier_degree(
    o: &Opts,
    deg_key: &'static str,
    points_key: &str,
    breaks: Option<&[f64]>,
    count: usize,
    default_degree: usize,
) -> ApiResult<usize> {
    let degree = if o.has(deg_key) {
        o.usize_or(deg_key, default_degree, MAX_BEZIER_DEGREE)?
    } else if let Some(b) = breaks {
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
    if breaks.is_none() && (count == 0 || !(count - 1).is_multiple_of(degree) || count < degree + 1)
    {
        return Err(err_kind(ErrorKind::SizeMismatch,
            points_key,
            format!("a Bézier spline of degree {degree} needs mL + 1 control points (L ≥ 1), got {count}"),
        ));
    }
    Ok(degree)
}

/// The breakvalues read, or 0, 1, …, L for `count` = mL + 1 control points (checked by [`bezier_degree`]).
fn breaks_or_uniform(breaks: Option<Vec<f64>>, degree: usize, count: usize) -> Vec<f64> {
    breaks.unwrap_or_else(|| knots::uniform((count - 1) / degree + 1))
}

/// The names in the messages about a parameter table: α (degree m, segments I = 0..L−1) or β of the bi-degree
/// remodelling (degree n, segments J = 0..M−1).
struct TableNames {
    sym: &'static str,
    deg: &'static str,
    seg: &'static str,
    segs: &'static str,
}
const ALPHA: TableNames = TableNames {
    sym: "α",
    deg: "m",
    seg: "I",
    segs: "L",
};
const BETA: TableNames = TableNames {
    sym: "β",
    deg: "n",
    seg: "J",
    segs: "M",
};

/// Reads `key` (`[I][k − 1]`, numbers; `null` allowed where eq. (9) fixes the entry and `enforce` is on);
/// absent = the classical elevation.
fn read_alphas(
    o: &Opts,
    key: &str,
    m: usize,
    segments: usize,
    enforce: Option<usize>,
) -> ApiResult<AlphaTable> {
    let raw: Option<Vec<Vec<Option<f64>>>> = o.opt(key)?;
    match raw {
        None => Ok(AlphaTable::classical(m, segments)),
        Some(raw) => alpha_table(key, &ALPHA, &raw, m, segments, enforce),
    }
}

/// One parameter table `[I][k − 1]` of degree `d` from rows of numbers (`null` allowed where eq. (9) fixes the
/// entry and `enforce` is on), errors naming `field`, `field[i]` or `field[i][k]`.
fn alpha_table(
    field: &str,
    names: &TableNames,
    raw: &[Vec<Option<f64>>],
    d: usize,
    segments: usize,
    enforce: Option<usize>,
) -> ApiResult<AlphaTable> {
    let TableNames {
        sym,
        deg,
        seg,
        segs,
    } = names;
    if raw.len() != segments {
        return Err(err_kind(
            ErrorKind::SizeMismatch,
            field,
            format!(
                "expected {segments} rows (one per segment {seg} = 0..{segs}−1), got {}",
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
                format!(
                    "expected {d} entries {sym}_1..{sym}_{deg} ({deg} = {d}), got {}",
                    row.len()
                ),
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
                        format!(
                            "{sym}ₖ⁽ᴵ⁾ with k = {}, I = {i} is free and needs a number in (0, 1)",
                            k + 1
                        ),
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

/// `key` (default ⌊m/2⌋): the class C^r kept, r ≤ ⌊m/2⌋ (`check_r`).
fn read_r(o: &Opts, key: &'static str, m: usize) -> ApiResult<usize> {
    let r = o.usize_or(key, m / 2, 1000)?;
    check_r(m, r).map_err(|e| core_err(e.in_field(key)))?;
    Ok(r)
}

/// Builds g, then reads the remodelling options (the α table is checked against g's segments).
fn remodel<P: Point>(o: &Opts, m: usize, breaks: Vec<f64>, pts: Vec<P>) -> ApiResult<JsValue> {
    let g = BezierSpline::new(m, breaks, pts).map_err(core_err)?;
    let l = g.segments();
    let BezierRemodelOptions {
        r,
        enforce,
        alphas,
        alpha_sweep,
        alpha_sweep_joint,
    } = BezierRemodelOptions::read(o, m, l)?;
    let order = o.derivatives(2)?;
    let en = if enforce { Some(r) } else { None };
    let sweep = match alpha_sweep {
        Some(values) => {
            Some(curvature_sweep(&g, &alphas, en, alpha_sweep_joint, &values).map_err(core_err)?)
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
