//! The surface exports of Bézier remodelling: bezierRemodelSurface and the bi-degree bezierRemodelSurfaceBi.

use super::*;
use crate::bezier::DirectionParams;

/// The degree m in u of a surface with `rows` rows of control points (`bezier_degree`), which must be
/// mL + 1 for the given `breaksU` (error on `points`).
fn degree_u(
    o: &Opts,
    key: &'static str,
    breaks_u: Option<&[f64]>,
    rows: usize,
) -> ApiResult<usize> {
    let m = bezier_degree(o, key, "points", breaks_u, rows, 2)?;
    let l = breaks_u.map_or((rows - 1) / m, |b| b.len().saturating_sub(1));
    if rows != m * l + 1 {
        return Err(err_kind(
            ErrorKind::SizeMismatch,
            "points",
            format!(
                "expected mL + 1 = {} rows along u (m = {m}, L = {l}), got {rows}",
                m * l + 1
            ),
        ));
    }
    Ok(m)
}

/// The degree n in v: `key` when given, else inferred from `cols` columns and the segments of `breaks_v`.
fn degree_v(o: &Opts, key: &'static str, breaks_v: &[f64], cols: usize) -> ApiResult<usize> {
    if o.has(key) {
        return o.usize_or(key, 1, MAX_BEZIER_DEGREE);
    }
    let mv = breaks_v.len().saturating_sub(1).max(1);
    if !(cols - 1).is_multiple_of(mv) {
        return Err(err_kind(
            ErrorKind::SizeMismatch,
            key,
            format!("not given, and {cols} columns do not fit {mv} segments in v; give degreeV"),
        ));
    }
    Ok((cols - 1) / mv)
}

api_options! {
    /// The control net of a Bézier spline surface (`bezierRemodelSurface`, `bezierRemodelSurfaceBi`; where:
    /// `atUV` or `samplesU` × `samplesV`).
    pub struct BezierSurfaceNetOptions extends "SurfaceSampling, GridDim" |o| {
        /// `points[k][l]`, k = 0..mL along u.
        points: (usize, usize, Pts) = "points", req "Grid" => |k| o.grid(k, 2, 2)?;
        /// u_0..u_L (default 0, 1, …, L).
        breaks_u: Option<Vec<f64>> = "breaksU", opt "Numbers" => |k| o.f64s(k)?;
        /// m (inferred from the rows and breaksU; 2 when neither is given).
        degree_u: usize = "degreeU", opt "number" => |k| degree_u(o, k, breaks_u.as_deref(), points.0)?;
        /// v_0..v_M (default [0, 1]).
        breaks_v: Vec<f64> = "breaksV", opt "Numbers" => |k| o.f64s(k)?.unwrap_or_else(|| vec![0.0, 1.0]);
    }
}

impl BezierSurfaceNetOptions {
    /// (m, the control points, the breakvalues in u — as given or 0, 1, …, L — and in v).
    fn into_net(self) -> (usize, Pts, Vec<f64>, Vec<f64>) {
        let (rows, _, pts) = self.points;
        let breaks_u = breaks_or_uniform(self.breaks_u, self.degree_u, rows);
        (self.degree_u, pts, breaks_u, self.breaks_v)
    }

    /// The segments L in u: `breaksU` − 1, or (rows − 1)/m (checked by [`degree_u`]).
    fn segments_u(&self) -> usize {
        let rows = self.points.0;
        (self.breaks_u.as_deref()).map_or((rows - 1) / self.degree_u, |b| b.len().saturating_sub(1))
    }
}

api_options! {
    /// The remodelling in u of a Bézier spline surface (`bezierRemodelSurface`).
    pub struct BezierRemodelSurfaceOptions extends "BezierSurfaceNetOptions" |o, net: &BezierSurfaceNetOptions| {
        /// n (inferred from the columns and breaksV).
        degree_v: usize = "degreeV", opt "number" => |k| degree_v(o, k, &net.breaks_v, net.points.1)?;
        /// The class C^r kept in u (default ⌊m/2⌋).
        r: usize = "r", opt "number" => |k| read_r(o, k, net.degree_u)?;
        /// Apply eq. (9) (default true).
        enforce: bool = "enforce", opt "boolean" => |k| o.bool_or(k, true)?;
        /// `[I][k − 1]`, one row per segment in u (default: the classical elevation).
        alphas: AlphaTable = "alphas", opt "AlphaTable"
            => |k| read_alphas(o, k, net.degree_u, net.segments_u(), enforce.then_some(r))?;
    }
}

#[wasm_bindgen(typescript_custom_section)]
const BEZIER_REMODEL_SURFACE_TS: &str = r#"
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
    let net = BezierSurfaceNetOptions::read(&o)?;
    let BezierRemodelSurfaceOptions {
        degree_v: n,
        r,
        enforce,
        alphas,
    } = BezierRemodelSurfaceOptions::read(&o, &net)?;
    let (m, pts, breaks_u, breaks_v) = net.into_net();
    with_points!(pts, p => {
        let g = BezierSplineSurface::new(m, n, breaks_u, breaks_v, p).map_err(core_err)?;
        let en = if enforce { Some(r) } else { None };
        let rem = SurfaceRemodelling::new(g, alphas, en).map_err(core_err)?;
        let (rows, cols) = rem.elevated().size();
        let mut out = crate::api::mesh::surface_output(&o, &rem)?
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

// ---- bi-degree remodelling (papers branch) ----

/// `alphas` / `betas` of `bezierRemodelSurfaceBi`: absent (classical), one table `[I][k − 1]` shared by
/// every line, or one table per line `[line][I][k − 1]`.
fn read_direction(
    o: &Opts,
    key: &str,
    names: &TableNames,
    d: usize,
    segments: usize,
    lines: usize,
    enforce: Option<usize>,
) -> ApiResult<DirectionParams> {
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
            .map(|(l, t)| alpha_table(&format!("{key}[{l}]"), names, t, d, segments, enforce))
            .collect::<ApiResult<Vec<_>>>()?;
        Ok(DirectionParams::PerLine(tables))
    } else {
        let t: Vec<Vec<Option<f64>>> = o.opt(key)?.unwrap_or_default();
        Ok(DirectionParams::Shared(alpha_table(
            key, names, &t, d, segments, enforce,
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

/// The degree n in v of the bi-degree remodelling ([`degree_v`]), 1..=`MAX_BEZIER_DEGREE`, with nM + 1 columns.
fn degree_v_bi(o: &Opts, key: &'static str, breaks_v: &[f64], cols: usize) -> ApiResult<usize> {
    let n = degree_v(o, key, breaks_v, cols)?;
    if n == 0 || n > MAX_BEZIER_DEGREE {
        return Err(err_kind(
            ErrorKind::OutOfRange,
            key,
            format!("need 1 ≤ n ≤ {MAX_BEZIER_DEGREE}, got {n}"),
        ));
    }
    let mv = breaks_v.len().saturating_sub(1).max(1);
    if cols != n * mv + 1 {
        return Err(err_kind(
            ErrorKind::Invalid,
            "points",
            format!(
                "expected nM + 1 = {} columns along v (n = {n}, M = {mv}), got {cols}",
                n * mv + 1
            ),
        ));
    }
    Ok(n)
}

api_options! {
    /// The bi-degree remodelling (m, n) → (m + 1, n + 1) of `bezierRemodelSurfaceBi`; `points[k][l]`, k = 0..mL
    /// along u, l = 0..nM along v.
    pub struct BezierRemodelSurfaceBiOptions extends "BezierSurfaceNetOptions" |o, net: &BezierSurfaceNetOptions| {
        /// n (inferred from the columns and breaksV).
        degree_v: usize = "degreeV", opt "number" => |k| degree_v_bi(o, k, &net.breaks_v, net.points.1)?;
        /// The class C^r kept in u (default ⌊m/2⌋).
        r: usize = "r", opt "number" => |k| read_r(o, k, net.degree_u)?;
        /// The class C^s kept in v (default ⌊n/2⌋).
        s: usize = "s", opt "number" => |k| read_r(o, k, degree_v)?;
        /// Apply eq. (9) and share the tables of the break lines (default true).
        enforce: bool = "enforce", opt "boolean" => |k| o.bool_or(k, true)?;
        /// One table `[I][k − 1]` shared by every column, or one per column `[l][I][k − 1]`.
        alphas: DirectionParams = "alphas", opt "AlphaTable | ReadonlyArray<AlphaTable>" => |k| {
            let (m, l, cols) = (net.degree_u, net.segments_u(), net.points.1);
            read_direction(o, k, &ALPHA, m, l, cols, enforce.then_some(r))?
        };
        /// One table `[J][l − 1]` shared by every row, or one per row.
        betas: DirectionParams = "betas", opt "AlphaTable | ReadonlyArray<AlphaTable>" => |k| {
            let (mv, rows) = (net.breaks_v.len().saturating_sub(1).max(1), (net.degree_u + 1) * net.segments_u() + 1);
            read_direction(o, k, &BETA, degree_v, mv, rows, enforce.then_some(s))?
        };
    }
}

#[wasm_bindgen(typescript_custom_section)]
const BEZIER_REMODEL_SURFACE_BI_TS: &str = r#"
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
    let net = BezierSurfaceNetOptions::read(&o)?;
    let BezierRemodelSurfaceBiOptions {
        degree_v: n,
        r,
        s,
        enforce,
        alphas,
        betas,
    } = BezierRemodelSurfaceBiOptions::read(&o, &net)?;
    let (m, pts, breaks_u, breaks_v) = net.into_net();
    with_points!(pts, p => {
        let g = BezierSplineSurface::new(m, n, breaks_u, breaks_v, p).map_err(core_err)?;
        let rem = BiRemodelling::new(g, alphas, betas, enforce.then_some((r, s))).map_err(core_err)?;
        let (rows, cols) = rem.elevated().size();
        let (ju, jv) = rem.jumps(r + 1, s + 1);
        let orig_v = crate::bezier::transpose(rem.original())
            .map(|t| t.u_jumps(s + 1))
            .map_err(core_err)?;
        let mut out = crate::api::mesh::surface_output(&o, &rem)?
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
