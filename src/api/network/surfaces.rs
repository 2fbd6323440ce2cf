//! The surfaces and bases of a curve network: crissCrossSurface, crissCrossBasis, crissCrossCells, thinPlateSurface.

use super::*;

api_options! {
    /// The options of `crissCrossSurface` (where: `atUV` or `samplesU`/`samplesV`; C11 and the evaluation:
    /// `CrissCrossSurfaceChoices`, read once the network is known compatible).
    pub struct CrissCrossSurfaceOptions extends "SurfaceSampling, NetworkTolerance, CrissCrossSurfaceChoices" |o| {
        /// The curve network (compatible within `tolerance`).
        network: Network = "network", req "NetworkInput" => |k| read_network(o, k)?;
    }
}

api_options! {
    /// The free control point C11 of `crissCrossSurface` and how S is evaluated (the surface does not depend on
    /// either, up to rounding).
    pub struct CrissCrossSurfaceChoices |o| {
        /// [x, y, z], "area" (default) or "edges".
        c11: C11Choice = "C11", opt "Point3 | 'area' | 'edges'" => |k| read_c11(o, k)?;
        /// "local" (default: the local cell form) or "sum" (Σ C_ij B_ij).
        evaluate: Evaluation = "evaluate", opt "'local' | 'sum'" => |k| read_evaluation(o, k)?;
    }
}

/// `C11`: `[x, y, z]`, `"area"` (also when absent) or `"edges"`.
#[inline]
fn read_c11(o: &Opts, key: &str) -> ApiResult<C11Choice> {
    match o.raw(key).as_string().as_deref() {
        Some("area") => Ok(C11Choice::Area),
        Some("edges") => Ok(C11Choice::Edges),
        Some(other) => Err(err_kind(
            ErrorKind::WrongType,
            key,
            format!("expected [x, y, z], \"area\" or \"edges\", got \"{other}\""),
        )),
        None => Ok(point3(o, key)?.map_or(C11Choice::Area, C11Choice::Point)),
    }
}

/// `evaluate`: `"local"` (also when absent) or `"sum"`.
#[inline]
fn read_evaluation(o: &Opts, key: &str) -> ApiResult<Evaluation> {
    let choices = [("local", Evaluation::Local), ("sum", Evaluation::Sum)];
    o.choice(key, choices, Evaluation::Local)
}

#[wasm_bindgen(typescript_custom_section)]
const CRISS_CROSS_SURFACE_TS: &str = r#"
// curve networks

export interface CrissCrossSurfaceResult extends SurfaceResult {
  controlPoints: Float64Array;
  C11: Float64Array;
  c2: number;
}
"#;

/// The C¹ quadratic criss-cross surface S through a network.
///
/// `crissCrossSurface({ network, C11, tolerance, evaluate, atUV | samplesU/samplesV, derivatives, mesh })`.
#[wasm_bindgen(js_name = crissCrossSurface, unchecked_return_type = "CrissCrossSurfaceResult")]
pub fn criss_cross_surface(
    #[wasm_bindgen(unchecked_param_type = "CrissCrossSurfaceOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let CrissCrossSurfaceOptions { network: net } = CrissCrossSurfaceOptions::read(&o)?;
    let tol = read_tolerance(&o)?;
    let s = CrissCrossSurface::with_tolerance(&net, tol).map_err(core_err)?;
    let CrissCrossSurfaceChoices { c11, evaluate } = CrissCrossSurfaceChoices::read(&o)?;
    let r = s.resolve(c11, evaluate).map_err(core_err)?;
    Ok(surface_output(&o, &r.surface)?
        .f64s("controlPoints", &flat(r.surface.control_points()))
        .f64s("C11", &[r.c11.x, r.c11.y, r.c11.z])
        .num("c2", r.c2)
        .build())
}

api_options! {
    /// The options of `crissCrossBasis`: the partitions and the index (i, j) of B_ij (where: `atUV` or
    /// `samplesU`/`samplesV`; `mesh` adds the render buffers of the graph (u, v, B_ij)).
    pub struct CrissCrossBasisOptions extends "SurfaceSampling" |o| {
        /// The breakpoints u_0 < … < u_m.
        u: Partition = "u", req "Numbers" => |k| breakpoints(o, k)?;
        /// The breakpoints v_0 < … < v_n.
        v: Partition = "v", req "Numbers" => |k| breakpoints(o, k)?;
        /// The index i of B_ij, 0..=m + 1.
        i: usize = "i", req "number" => |k| required_index(o, k, u.cells() + 1)?;
        /// The index j of B_ij, 0..=n + 1.
        j: usize = "j", req "number" => |k| required_index(o, k, v.cells() + 1)?;
    }
}

/// A required index `0..=max` (`i`, `j` of `crissCrossBasis`).
fn required_index(o: &Opts, key: &str, max: usize) -> ApiResult<usize> {
    let i = o.usize_or(key, usize::MAX, max)?;
    if i == usize::MAX {
        return Err(err_kind(
            ErrorKind::Missing,
            key,
            format!("this field is required (0..={max})"),
        ));
    }
    Ok(i)
}

#[wasm_bindgen(typescript_custom_section)]
const CRISS_CROSS_BASIS_TS: &str = r#"
export interface CrissCrossBasisResult {
  uv: Float64Array;
  values: Float64Array;
  du?: Float64Array;
  dv?: Float64Array;
  mesh?: Mesh;
}
"#;

/// The C¹ quadratic B-spline B_ij on the criss-cross triangulation.
///
/// `crissCrossBasis({ u, v, i, j, atUV | samplesU/samplesV, derivatives })` → `{ uv, values, du?, dv? }`.
#[wasm_bindgen(js_name = crissCrossBasis, unchecked_return_type = "CrissCrossBasisResult")]
pub fn criss_cross_basis(
    #[wasm_bindgen(unchecked_param_type = "CrissCrossBasisOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let CrissCrossBasisOptions { u: pu, v: pv, i, j } = CrissCrossBasisOptions::read(&o)?;
    let derivs = o.derivatives(1)? >= 1;
    let cc = CrissCross::from_partitions(pu, pv);
    let uv = o.surface_uv(cc.domain())?;
    // the graph (u, v, B_ij(u, v)) of `mesh` needs the partials too
    let want_mesh = o.mesh_on_grid()?;
    let b = cc.sample_basis(i, j, &uv, derivs || want_mesh);
    let mut out = Out::new().f64s("uv", &uv).f64s("values", &b.values);
    if derivs {
        out = out.f64s("du", &b.du).f64s("dv", &b.dv);
    }
    if want_mesh {
        let nu = o.usize_or("samplesU", 40, MAX_EVAL_POINTS)?;
        let nv = o.usize_or("samplesV", 40, MAX_EVAL_POINTS)?;
        let m = b.graph_mesh(&uv, nu, nv).map_err(core_err)?;
        out = out.set("mesh", crate::api::mesh::mesh_object(&m));
    }
    Ok(out.build())
}

#[cfg(feature = "api-network")]
api_options! {
    /// The options of `thinPlateSurface` (where: `atUV` or `samplesU`/`samplesV`).
    pub struct ThinPlateSurfaceOptions extends "SurfaceSampling, NetworkTolerance" |o| {
        /// The curve network (compatible within `tolerance`).
        network: Network = "network", req "NetworkInput" => |k| read_network(o, k)?;
    }
}

#[cfg(feature = "api-network")]
#[wasm_bindgen(typescript_custom_section)]
const THIN_PLATE_SURFACE_TS: &str = r#"
export interface ThinPlateSurfaceResult extends SurfaceResult {
  C11: Float64Array;
  energy: number;
  controlPoints: Float64Array;
}
"#;

/// The biquadratic surface of minimal thin-plate energy through a network.
///
/// `thinPlateSurface({ network, tolerance, atUV | samplesU/samplesV, derivatives, mesh })`.
#[cfg(feature = "api-network")]
#[wasm_bindgen(js_name = thinPlateSurface, unchecked_return_type = "ThinPlateSurfaceResult")]
pub fn thin_plate_surface(
    #[wasm_bindgen(unchecked_param_type = "ThinPlateSurfaceOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let ThinPlateSurfaceOptions { network: net } = ThinPlateSurfaceOptions::read(&o)?;
    let tol = read_tolerance(&o)?;
    let t = ThinPlateSurface::with_tolerance(&net, tol).map_err(core_err)?;
    let c = t.c11();
    Ok(surface_output(&o, &t)?
        .f64s("C11", &[c.x, c.y, c.z])
        .num("energy", t.energy())
        .f64s("controlPoints", &flat(t.control_points()))
        .build())
}

api_options! {
    /// The options of `crissCrossCells`: a network (the cells of S's local form; `tolerance` as for
    /// `crissCrossSurface`), or the partitions and the index (i, j) of B_ij (`CrissCrossCellsOfBasis`, read
    /// when there is no network).
    pub struct CrissCrossCellsOptions extends "NetworkTolerance, CrissCrossCellsOfBasis" |o| {
        /// The curve network (then `u`, `v`, `i`, `j` are not read).
        network: Option<Network> = "network", opt "NetworkInput" => |k| {
            if o.has(k) { Some(read_network(o, k)?) } else { None }
        };
    }
}

api_options! {
    /// The options of `crissCrossCells` without a network: the partitions and the index (i, j) of B_ij.
    pub struct CrissCrossCellsOfBasis |o| {
        /// The breakpoints u_0 < … < u_m (required without `network`).
        u: Partition = "u", opt "Numbers" => |k| breakpoints(o, k)?;
        /// The breakpoints v_0 < … < v_n (required without `network`).
        v: Partition = "v", opt "Numbers" => |k| {
            let v = breakpoints(o, k)?;
            if u.cells().saturating_mul(v.cells()) > MAX_EVAL_POINTS / 13 {
                return Err(err_kind(ErrorKind::TooMany, "u", "too many cells"));
            }
            v
        };
        /// The index i of B_ij, 0..=m + 1 (default 0).
        i: usize = "i", opt "number" => |k| o.usize_or(k, 0, u.cells() + 1)?;
        /// The index j of B_ij, 0..=n + 1 (default 0).
        j: usize = "j", opt "number" => |k| o.usize_or(k, 0, v.cells() + 1)?;
    }
}

#[wasm_bindgen(typescript_custom_section)]
const CRISS_CROSS_CELLS_TS: &str = r#"
export interface CrissCrossCellsResult {
  m: number;
  n: number;
  dim: number;
  ordinates: Float64Array;
  domainPoints: Float64Array;
  support?: Float64Array;
}
"#;

/// The 13 Bernstein–Bézier ordinates of every cell (of B_ij, or of S's local form).
///
/// `crissCrossCells({ u, v, i, j })` or `crissCrossCells({ network })` → BB ordinates of every cell.
#[wasm_bindgen(js_name = crissCrossCells, unchecked_return_type = "CrissCrossCellsResult")]
pub fn criss_cross_cells(
    #[wasm_bindgen(unchecked_param_type = "CrissCrossCellsOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let CrissCrossCellsOptions { network } = CrissCrossCellsOptions::read(&o)?;
    let cells = match network {
        Some(net) => {
            let s =
                CrissCrossSurface::with_tolerance(&net, read_tolerance(&o)?).map_err(core_err)?;
            CellOrdinates::of_surface(&s)
        }
        None => {
            let CrissCrossCellsOfBasis { u, v, i, j } = CrissCrossCellsOfBasis::read(&o)?;
            CellOrdinates::of_basis(&CrissCross::from_partitions(u, v), i, j)
        }
    };
    let mut out = Out::new()
        .num("m", cells.m as f64)
        .num("n", cells.n as f64)
        .num("dim", cells.dim as f64)
        .f64s("ordinates", &cells.ordinates)
        .f64s("domainPoints", &cells.domain_points);
    if let Some(support) = &cells.support {
        out = out.f64s("support", support);
    }
    Ok(out.build())
}
