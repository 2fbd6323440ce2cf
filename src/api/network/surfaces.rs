//! The surfaces and bases of a curve network: crissCrossSurface, crissCrossBasis, crissCrossCells, thinPlateSurface.

use super::*;

#[wasm_bindgen(typescript_custom_section)]
const CRISS_CROSS_SURFACE_TS: &str = r#"
// curve networks

export interface CrissCrossSurfaceOptions extends SurfaceSampling, NetworkTolerance {
  network: NetworkInput;
  /** [x, y, z], "area" (default) or "edges". */
  C11?: Point3 | 'area' | 'edges';
  evaluate?: 'local' | 'sum';
}
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
    let net = read_network(&o, "network")?;
    let tol = read_tolerance(&o)?;
    let s = CrissCrossSurface::with_tolerance(&net, tol).map_err(core_err)?;
    let c11 = match o.raw("C11").as_string().as_deref() {
        Some("area") => s.min_area_c11(),
        Some("edges") => s.default_c11(),
        Some(other) => {
            return Err(err_kind(
                ErrorKind::WrongType,
                "C11",
                format!("expected [x, y, z], \"area\" or \"edges\", got \"{other}\""),
            ))
        }
        None => match point3(&o, "C11")? {
            Some(c) => c,
            None => s.min_area_c11(),
        },
    };
    let ctrl = s.control_points(c11);
    let evaluate: Option<String> = o.opt("evaluate")?;
    let out = match evaluate.as_deref() {
        None | Some("local") => surface_output(&o, &s)?,
        Some("sum") => surface_output(&o, &s.spline(c11).map_err(core_err)?)?,
        Some(other) => {
            return Err(err_kind(
                ErrorKind::Invalid,
                "evaluate",
                format!("expected \"local\" or \"sum\", got \"{other}\""),
            ))
        }
    };
    let c2 = net.compatibility().map_err(core_err)?.c2;
    Ok(out
        .f64s("controlPoints", &flat(&ctrl))
        .f64s("C11", &[c11.x, c11.y, c11.z])
        .num("c2", c2)
        .build())
}

#[wasm_bindgen(typescript_custom_section)]
const CRISS_CROSS_BASIS_TS: &str = r#"
export interface CrissCrossBasisOptions extends SurfaceSampling {
  u: Numbers;
  v: Numbers;
  i: number;
  j: number;
}
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
    let pu = breakpoints(&o, "u")?;
    let pv = breakpoints(&o, "v")?;
    let (m, n) = (pu.cells(), pv.cells());
    let i = o.usize_or("i", usize::MAX, m + 1)?;
    if i == usize::MAX {
        return Err(err_kind(
            ErrorKind::Missing,
            "i",
            format!("this field is required (0..={})", m + 1),
        ));
    }
    let j = o.usize_or("j", usize::MAX, n + 1)?;
    if j == usize::MAX {
        return Err(err_kind(
            ErrorKind::Missing,
            "j",
            format!("this field is required (0..={})", n + 1),
        ));
    }
    let derivs = o.derivatives(1)? >= 1;
    let cc = CrissCross::from_partitions(pu, pv);
    let uv = o.surface_uv(cc.domain())?;
    let count = uv.len() / 2;
    let mut values = Vec::with_capacity(count);
    let (mut du, mut dv) = (Vec::new(), Vec::new());
    for w in uv.chunks_exact(2) {
        let [f, fu, fv] = cc.basis(i, j, w[0], w[1]);
        values.push(f);
        if derivs {
            du.push(fu);
            dv.push(fv);
        }
    }
    let mut out = Out::new().f64s("uv", &uv).f64s("values", &values);
    if derivs {
        out = out.f64s("du", &du).f64s("dv", &dv);
    }
    if o.bool_or("mesh", false)? {
        if o.has("atUV") {
            return Err(err_kind(
                ErrorKind::SizeMismatch,
                "mesh",
                "render buffers need a grid (samplesU/samplesV), not atUV",
            ));
        }
        // the graph (u, v, B_ij(u, v)) with its partials (1, 0, B_u), (0, 1, B_v)
        let nu = o.usize_or("samplesU", 40, MAX_EVAL_POINTS)?;
        let nv = o.usize_or("samplesV", 40, MAX_EVAL_POINTS)?;
        let mut pts = Vec::with_capacity(3 * count);
        let (mut gu, mut gv) = (Vec::with_capacity(3 * count), Vec::with_capacity(3 * count));
        for (k, w) in uv.chunks_exact(2).enumerate() {
            let [_, fu, fv] = cc.basis(i, j, w[0], w[1]);
            pts.extend_from_slice(&[w[0], w[1], values[k]]);
            gu.extend_from_slice(&[1.0, 0.0, fu]);
            gv.extend_from_slice(&[0.0, 1.0, fv]);
        }
        let m =
            crate::mesh::Mesh::from_grid(&pts, Some((&gu, &gv)), 3, nu, nv).map_err(core_err)?;
        out = out.set("mesh", crate::api::mesh::mesh_object(&m));
    }
    Ok(out.build())
}

#[cfg(feature = "api-network")]
#[wasm_bindgen(typescript_custom_section)]
const THIN_PLATE_SURFACE_TS: &str = r#"
export interface ThinPlateSurfaceOptions extends SurfaceSampling, NetworkTolerance {
  network: NetworkInput;
}
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
    let net = read_network(&o, "network")?;
    let tol = read_tolerance(&o)?;
    let t = ThinPlateSurface::with_tolerance(&net, tol).map_err(core_err)?;
    let c = t.c11();
    Ok(surface_output(&o, &t)?
        .f64s("C11", &[c.x, c.y, c.z])
        .num("energy", t.energy())
        .f64s("controlPoints", &flat(t.control_points()))
        .build())
}

#[wasm_bindgen(typescript_custom_section)]
const CRISS_CROSS_CELLS_TS: &str = r#"
export interface CrissCrossCellsOptions extends NetworkTolerance {
  network?: NetworkInput;
  u?: Numbers;
  v?: Numbers;
  i?: number;
  j?: number;
}
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
    if o.has("network") {
        let net = read_network(&o, "network")?;
        let s = CrissCrossSurface::with_tolerance(&net, read_tolerance(&o)?).map_err(core_err)?;
        let cc = s.triangulation();
        let (m, n) = cc.cells();
        let mut ord = Vec::with_capacity(m * n * 39);
        for a in 1..=m {
            for b in 1..=n {
                if let Some(net) = s.cell_net(a, b) {
                    ord.extend(flat(net));
                }
            }
        }
        return Ok(Out::new()
            .num("m", m as f64)
            .num("n", n as f64)
            .num("dim", 3.0)
            .f64s("ordinates", &ord)
            .f64s("domainPoints", &domain_points(cc))
            .build());
    }
    let pu = breakpoints(&o, "u")?;
    let pv = breakpoints(&o, "v")?;
    let (m, n) = (pu.cells(), pv.cells());
    if m.saturating_mul(n) > MAX_EVAL_POINTS / 13 {
        return Err(err_kind(ErrorKind::TooMany, "u", "too many cells"));
    }
    let i = o.usize_or("i", 0, m + 1)?;
    let j = o.usize_or("j", 0, n + 1)?;
    let cc = CrissCross::from_partitions(pu, pv);
    let mut ord = Vec::with_capacity(m * n * 13);
    let mut support = Vec::with_capacity(m * n * 4);
    for a in 1..=m {
        for b in 1..=n {
            let net = cc.basis_net(i, j, a, b);
            ord.extend_from_slice(&net);
            for tri in Triangle::ALL {
                support.push(if tri.ordinates().iter().any(|k| net[*k] != 0.0) {
                    1.0
                } else {
                    0.0
                });
            }
        }
    }
    Ok(Out::new()
        .num("m", m as f64)
        .num("n", n as f64)
        .num("dim", 1.0)
        .f64s("ordinates", &ord)
        .f64s("domainPoints", &domain_points(&cc))
        .f64s("support", &support)
        .build())
}
