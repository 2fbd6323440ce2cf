//! `gordonSurface`, `splineBlendedSurface`, `networkSurfaces`, `surfaceDifferences`: the Gordon boolean
//! sum G and the spline-blended GB through curve networks (`../shared/spec/surfaces.md` §5, §6).
//!
//! Contract functions (`../shared/spec/api.md`):
//! * `gordonSurface({ network, tolerance, components, atUV | samplesU/samplesV, derivatives, mesh })` →
//!   surface result + `{ knotsU, knotsV, controlPoints, countU, countV, knotsUBar, knotsVBar, components? }`:
//!   Ũ, Ṽ (2m + 3, 2n + 3 knots), C̃ of eq. (40) (2m × 2n points, flat xyz, i-major: index i·2n + j), Ū, V̄;
//!   `components: true` adds `{ L1, L2, Tg }`, each `{ knotsU, knotsV, countU, countV, controlPoints }`.
//! * `splineBlendedSurface({ network, uKnots, vKnots, blend, a, tensionU, tensionV, c2, atUV |
//!   samplesU/samplesV, derivatives, mesh })` → surface result. `network`: a function `(u, v) => [x, y, z]`
//!   (read only on the lines u = u_i, v = v_j, each point once) or a curve network `{ u, v, P, Q }`.
//!   `blend`: `"b2"` (default; knots u_{−1}..u_{m+2}, domain [u_1, u_m]; tensions numbers or p_0..p_m),
//!   `"cubic-natural"`, `"cubic-notaknot"` (knots u_0..u_m).
//!
//! Additions:
//! * `networkSurfaces({ network, samplesU = 64, samplesV = 64, surfaces, blend, colorBy, components,
//!   curveSamples, normSamples = 57, tolerance })` → `{ names, available, surfaces: { S, T, G, GB, L1?, L2?,
//!   Tg?: { points, mesh } }, norms: { SG, ST, TG, SGB, GGB }, colors?, curves?, gordon }`: everything the
//!   "Curve networks" demo draws, for one network in one call.
//! * `surfaceDifferences({ network, samples = 57, blend, tolerance })` → `{ SG, ST, TG, SGB, GGB, samples }`,
//!   ‖A − B‖∞ over all coordinates on the `samples × samples` grid (seed 004 §4.2's measure).

use super::mesh::{mesh_object, surface_output};
use super::readers::{read_network, read_tension, read_tolerance};
use super::{api_options, call_point_fn, core_err, err_kind, ApiResult, Opts, Out};
use crate::b2spline::{Tension, DEFAULT_TENSION};
use crate::bspline::BSplineSurface;
use crate::error::ErrorKind;
use crate::gordon::{
    self, Blend, FnLines, GordonSurface, GridSurface, LineNetwork, NetworkLines,
    SplineBlendedSurface, SurfaceFamily, FAMILY_NAMES,
};
use crate::gordon::{render_family, FamilyRequest};
use crate::mesh::{self, Mesh};
use crate::network::Network;
use crate::sample::{self, Surface};
use glam::DVec3;
use std::cell::RefCell;
use std::collections::HashMap;
use wasm_bindgen::prelude::*;

fn surface_data(s: &BSplineSurface<DVec3>) -> JsValue {
    let (nu, nv) = s.size();
    Out::new()
        .f64s("knotsU", s.knots_u())
        .f64s("knotsV", s.knots_v())
        .num("countU", nu as f64)
        .num("countV", nv as f64)
        .pts("controlPoints", s.points())
        .build()
}

/// The Gordon extras: `knotsU`, `knotsV` (Ũ, Ṽ), `controlPoints` (C̃, 2m × 2n, i-major, flat),
/// `countU`, `countV`, `knotsUBar`, `knotsVBar`, and with `components` the L1/L2/Tg control data.
fn gordon_extras(out: Out, g: &GordonSurface, components: bool) -> Out {
    let (nu, nv) = g.size();
    let mut out = out
        .f64s("knotsU", g.knots_u())
        .f64s("knotsV", g.knots_v())
        .pts("controlPoints", g.control_points())
        .num("countU", nu as f64)
        .num("countV", nv as f64)
        .f64s("knotsUBar", g.knots_u_bar())
        .f64s("knotsVBar", g.knots_v_bar());
    if components {
        let c = Out::new()
            .set("L1", surface_data(g.l1()))
            .set("L2", surface_data(g.l2()))
            .set("Tg", surface_data(g.tg()))
            .build();
        out = out.set("components", c);
    }
    out
}

#[cfg(feature = "api-gordon")]
api_options! {
    /// The options of `gordonSurface` (where: `atUV` or `samplesU`/`samplesV`).
    pub struct GordonSurfaceOptions extends "SurfaceSampling, NetworkTolerance, GordonComponents" |o| {
        /// The curve network.
        network: Network = "network", req "NetworkInput" => |k| read_network(o, k)?;
        /// The tolerance of the compatibility check.
        tolerance: f64 = "tolerance", ext "NetworkTolerance" => |_k| read_tolerance(o)?;
    }
}

api_options! {
    /// The Gordon components (`gordonSurface`, `networkSurfaces`), read once the surfaces are built.
    pub struct GordonComponents |o| {
        /// Adds `components: { L1, L2, Tg }`.
        components: bool = "components", opt "boolean" => |k| o.bool_or(k, false)?;
    }
}

#[cfg(feature = "api-gordon")]
#[wasm_bindgen(typescript_custom_section)]
const GORDON_SURFACE_TS: &str = r#"
export interface TensorSurfaceData {
  knotsU: Float64Array;
  knotsV: Float64Array;
  countU: number;
  countV: number;
  controlPoints: Float64Array;
}
export interface GordonExtras extends TensorSurfaceData {
  knotsUBar: Float64Array;
  knotsVBar: Float64Array;
  components?: { L1: TensorSurfaceData; L2: TensorSurfaceData; Tg: TensorSurfaceData };
}
export interface GordonSurfaceResult extends SurfaceResult, GordonExtras {}
"#;

/// The biquadratic Gordon (boolean sum) surface G through a network.
///
/// `gordonSurface({ network, atUV | samplesU/samplesV, derivatives, mesh, components })` → surface result
/// + `{ knotsU, knotsV, controlPoints, countU, countV, knotsUBar, knotsVBar, components? }`.
#[cfg(feature = "api-gordon")]
#[wasm_bindgen(js_name = gordonSurface, unchecked_return_type = "GordonSurfaceResult")]
pub fn gordon_surface(
    #[wasm_bindgen(unchecked_param_type = "GordonSurfaceOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let GordonSurfaceOptions { network, tolerance } = GordonSurfaceOptions::read(&o)?;
    let g = GordonSurface::with_tolerance(&network, tolerance).map_err(core_err)?;
    let GordonComponents { components } = GordonComponents::read(&o)?;
    let out = surface_output(&o, &g)?;
    Ok(gordon_extras(out, &g, components).build())
}

/// The blend names of `blend`.
#[derive(Clone, Copy, PartialEq)]
pub enum BlendName {
    /// `"b2"`.
    B2,
    /// `"cubic-natural"`.
    CubicNatural,
    /// `"cubic-notaknot"`.
    CubicNotAKnot,
}

/// `blend`: `"b2"` (also when absent), `"cubic-natural"` or `"cubic-notaknot"`.
fn read_blend_name(o: &Opts, key: &str) -> ApiResult<BlendName> {
    let choices = [
        ("b2", BlendName::B2),
        ("cubic-natural", BlendName::CubicNatural),
        ("cubic-notaknot", BlendName::CubicNotAKnot),
    ];
    o.choice(key, choices, BlendName::B2)
}

api_options! {
    /// The blend of GB (`splineBlendedSurface`); `a`, `tensionU`, `tensionV`, `c2` are read for `"b2"` only.
    pub struct SplineBlend |o| {
        /// `"b2"` (default; knots u_{−1}..u_{m+2}), `"cubic-natural"` or `"cubic-notaknot"` (knots u_0..u_m).
        name: BlendName = "blend", opt "'b2' | 'cubic-natural' | 'cubic-notaknot'" => |k| read_blend_name(o, k)?;
        /// The approximation parameter a of the b2 blend (default 0).
        a: f64 = "a", opt "number" => |k| if name == BlendName::B2 { o.f64_or(k, 0.0)? } else { 0.0 };
        /// The tension in u of the b2 blend (a number or p_0..p_m; default 1/6).
        tension_u: Tension = "tensionU", opt "Tension" => |k| b2_tension(o, k, name)?;
        /// The tension in v.
        tension_v: Tension = "tensionV", opt "Tension" => |k| b2_tension(o, k, name)?;
        /// c2 of the b2 blend (default 1).
        c2: f64 = "c2", opt "number" => |k| if name == BlendName::B2 { o.f64_or(k, 1.0)? } else { 1.0 };
    }
}

/// A tension of the b2 blend (not read for the cubic ones).
fn b2_tension(o: &Opts, key: &str, name: BlendName) -> ApiResult<Tension> {
    match name {
        BlendName::B2 => read_tension(o, key, DEFAULT_TENSION),
        _ => Ok(Tension::Scalar(DEFAULT_TENSION)),
    }
}

impl SplineBlend {
    fn blend(self) -> Blend {
        match self.name {
            BlendName::CubicNatural => Blend::CubicNatural,
            BlendName::CubicNotAKnot => Blend::CubicNotAKnot,
            BlendName::B2 => Blend::B2 {
                a: self.a,
                tension_u: self.tension_u,
                tension_v: self.tension_v,
                c2: self.c2,
            },
        }
    }
}

fn nodes(o: &Opts, key: &str) -> ApiResult<Vec<f64>> {
    let k = o.f64s(key)?.ok_or_else(|| {
        err_kind(
            ErrorKind::Missing,
            key,
            "this field is required (the nodes of the network lines)",
        )
    })?;
    // a function network is called on every line for every grid line: keep that bounded
    const MAX_FN_LINES: usize = 257;
    if k.len() > MAX_FN_LINES {
        return Err(err_kind(
            ErrorKind::TooMany,
            key,
            format!("at most {MAX_FN_LINES} nodes, got {}", k.len()),
        ));
    }
    Ok(k)
}

/// A JS network function `(u, v) => [x, y, z]`, each point asked once (memoised); the first failure is
/// kept and reported after the evaluation.
struct JsNetwork {
    f: js_sys::Function,
    cache: RefCell<HashMap<(u64, u64), DVec3>>,
    failure: RefCell<Option<JsError>>,
}

impl JsNetwork {
    fn call(&self, u: f64, v: f64) -> DVec3 {
        let key = (u.to_bits(), v.to_bits());
        if let Some(p) = self.cache.borrow().get(&key) {
            return *p;
        }
        let p = match call_point_fn("network", &self.f, u, v) {
            Ok(p) => p,
            Err(e) => {
                let mut f = self.failure.borrow_mut();
                if f.is_none() {
                    *f = Some(e);
                }
                DVec3::NAN
            }
        };
        self.cache.borrow_mut().insert(key, p);
        p
    }
    fn check(&self) -> ApiResult<()> {
        match self.failure.borrow_mut().take() {
            Some(e) => Err(e),
            None => Ok(()),
        }
    }
}

/// The surface result of GB: with `atUV` point by point; on a `samplesU × samplesV` grid by grid lines (each
/// network curve and blending function evaluated once per grid line, so a function network is called
/// (m + 1)·samplesV + (n + 1)·samplesU times, three times that with derivatives or `mesh`).
fn blended_output<N: LineNetwork>(
    o: &Opts,
    gb: &SplineBlendedSurface<N>,
    fn_lines: Option<(usize, usize)>,
) -> ApiResult<Out> {
    let derivs = o.derivatives(1)? >= 1;
    let want_mesh = o.mesh_on_grid()?;
    let at = o.has("atUV");
    let uv = o.surface_uv(gb.domain())?; // parsed once; validates the point limit
                                         // GB costs a few µs a point: cap one call at 400,000 points so it stays well under a second
                                         // (robustness bug 5: 1e6 points took ~2.2 s on the loaded test machine)
    const MAX_GB_POINTS: usize = 400_000;
    if uv.len() / 2 > MAX_GB_POINTS {
        return Err(err_kind(
            ErrorKind::TooMany,
            if o.has("atUV") { "atUV" } else { "samplesU" },
            format!(
                "at most {MAX_GB_POINTS} evaluation points for a spline-blended surface, got {}",
                uv.len() / 2
            ),
        ));
    }
    let nu = o.usize_or("samplesU", 40, sample::MAX_EVAL_POINTS)?;
    let nv = o.usize_or("samplesV", 40, sample::MAX_EVAL_POINTS)?;
    if let Some((lu, lv)) = fn_lines {
        // bound the calls of the JS function: every evaluation line meets every network line
        const MAX_CALLS: usize = 300_000;
        let calls = if at {
            (uv.len() / 2).saturating_mul(lu + lv)
        } else {
            nu.saturating_mul(lv).saturating_add(nv.saturating_mul(lu))
        };
        let calls = calls.saturating_mul(if derivs || want_mesh { 3 } else { 1 });
        if calls > MAX_CALLS {
            return Err(err_kind(ErrorKind::TooMany,
                if at { "atUV" } else { "samplesU" },
                format!("the network function would be called about {calls} times (evaluation lines × network lines, × 3 with derivatives); at most {MAX_CALLS}"),
            ));
        }
    }
    let mut out = Out::new().num("dim", 3.0).f64s("uv", &uv);
    if at {
        let (pts, du, dv) = sample::eval_surface(gb, &uv, derivs);
        out = out.f64s("points", &pts);
        if derivs {
            out = out.f64s("du", &du).f64s("dv", &dv);
        }
        return Ok(out);
    }
    if want_mesh {
        mesh::check_density(nu, nv).map_err(core_err)?;
    }
    let ((u0, u1), (v0, v1)) = gb.domain();
    let (us, vs) = (
        sample::uniform_params(u0, u1, nu),
        sample::uniform_params(v0, v1, nv),
    );
    let grid = gb.eval_grid(&us, &vs, derivs || want_mesh);
    out = out.f64s("points", &grid.points);
    if derivs {
        out = out.f64s("du", &grid.du).f64s("dv", &grid.dv);
    }
    if want_mesh {
        let m = Mesh::from_grid(&grid.points, Some((&grid.du, &grid.dv)), 3, nu, nv)
            .map_err(core_err)?;
        out = out.set("mesh", mesh_object(&m));
    }
    Ok(out)
}

/// The `network` of `splineBlendedSurface`: a function or a curve network.
pub enum BlendNetwork {
    /// `(u, v) => [x, y, z]`.
    Function(js_sys::Function),
    /// `{ u, v, P, Q }`.
    Curves(Network),
}

/// `network`: a function `(u, v) => [x, y, z]` or a curve network `{ u, v, P, Q }`.
fn read_blend_network(o: &Opts, key: &str) -> ApiResult<BlendNetwork> {
    let raw = o.raw(key);
    if raw.is_function() {
        return Ok(BlendNetwork::Function(raw.unchecked_into()));
    }
    if raw.is_object() {
        return Ok(BlendNetwork::Curves(read_network(o, key)?));
    }
    Err(err_kind(
        ErrorKind::WrongType,
        key,
        "expected a function (u, v) => [x, y, z] or a curve network { u, v, P, Q }",
    ))
}

/// `uKnots` / `vKnots`: the nodes of a function network (required); with a curve network they must equal its
/// breakpoints `mine` (or be omitted) and are not kept (empty).
fn blend_nodes(
    o: &Opts,
    key: &str,
    net: &BlendNetwork,
    mine: fn(&Network) -> &Vec<f64>,
) -> ApiResult<Vec<f64>> {
    let net = match net {
        BlendNetwork::Function(_) => return nodes(o, key),
        BlendNetwork::Curves(net) => net,
    };
    if let Some(k) = o.f64s(key)? {
        if &k != mine(net) {
            return Err(err_kind(
                ErrorKind::SizeMismatch,
                key,
                "must equal the network's breakpoints (or be omitted)",
            ));
        }
    }
    Ok(Vec::new())
}

api_options! {
    /// The options of `splineBlendedSurface` (where: `atUV` or `samplesU`/`samplesV`).
    pub struct SplineBlendedSurfaceOptions extends "SurfaceSampling, NetworkTolerance, SplineBlend" |o| {
        /// The blend.
        blend: Blend = "blend", ext "SplineBlend" => |_k| SplineBlend::read(o)?.blend();
        /// A function (u, v) => [x, y, z] (sampled on the lines only) or a curve network.
        network: BlendNetwork = "network", req "((u: number, v: number) => Point3) | NetworkInput"
            => |k| read_blend_network(o, k)?;
        /// The nodes u_i of a function network (required then); with a curve network its breakpoints u (or omitted).
        u_knots: Vec<f64> = "uKnots", opt "Numbers" => |k| blend_nodes(o, k, &network, |n| &n.u)?;
        /// The nodes v_j (as `uKnots`).
        v_knots: Vec<f64> = "vKnots", opt "Numbers" => |k| blend_nodes(o, k, &network, |n| &n.v)?;
        /// The tolerance of the compatibility check of a curve network (not read for a function).
        tolerance: f64 = "tolerance", ext "NetworkTolerance" => |_k| match network {
            BlendNetwork::Curves(_) => read_tolerance(o)?,
            BlendNetwork::Function(_) => 0.0,
        };
    }
}

/// The spline-blended (boolean sum) surface G = G1 + G2 − G12.
///
/// `splineBlendedSurface({ network, uKnots, vKnots, blend, a, tensionU, tensionV, atUV | samplesU/samplesV,
/// derivatives, mesh })` → surface result (seed 000 eq. (4), G = G1 + G2 − G12).
///
/// `network` is a function `(u, v) => [x, y, z]` sampled only on the lines u = u_i, v = v_j (each point
/// once), or a curve network `{ u, v, P, Q }` (then `uKnots`/`vKnots` default to its breakpoints).
/// Derivatives along the lines of a function network are central differences (step 2⁻²⁰ × extent).
#[wasm_bindgen(js_name = splineBlendedSurface, unchecked_return_type = "SurfaceResult")]
pub fn spline_blended_surface(
    #[wasm_bindgen(unchecked_param_type = "SplineBlendedSurfaceOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let SplineBlendedSurfaceOptions {
        blend,
        network,
        u_knots: u,
        v_knots: v,
        tolerance,
    } = SplineBlendedSurfaceOptions::read(&o)?;
    match network {
        BlendNetwork::Function(f) => {
            let jn = JsNetwork {
                f,
                cache: RefCell::new(HashMap::new()),
                failure: RefCell::new(None),
            };
            let counts = Some((u.len(), v.len()));
            let lines = FnLines::new(|a: f64, b: f64| jn.call(a, b), u, v);
            let gb = SplineBlendedSurface::new(lines, blend);
            jn.check()?;
            let gb = gb.map_err(core_err)?;
            let out = blended_output(&o, &gb, counts);
            jn.check()?;
            Ok(out?.build())
        }
        BlendNetwork::Curves(net) => {
            let lines = NetworkLines::with_tolerance(&net, tolerance).map_err(core_err)?;
            let gb = SplineBlendedSurface::new(lines, blend).map_err(core_err)?;
            Ok(blended_output(&o, &gb, None)?.build())
        }
    }
}

/// The ‖A − B‖∞ pairs of a family as `{ SG, ST, TG, SGB, GGB }`.
fn norms_out(fam: &SurfaceFamily, n: usize) -> Out {
    fam.norms(n)
        .into_iter()
        .fold(Out::new(), |out, (key, v)| out.num(key, v))
}

/// The blend of GB through a curve network: `"cubic-natural"` (default) or `"cubic-notaknot"` (the b2
/// blend needs auxiliary lines u_{−1}, u_{m+2} that a curve network does not have).
fn blend_or_cubic(o: &Opts, key: &str) -> ApiResult<Blend> {
    if !o.has(key) {
        return Ok(Blend::CubicNatural);
    }
    match SplineBlend::read(o)?.blend() {
        Blend::B2 { .. } => Err(err_kind(ErrorKind::Invalid,
            "blend",
            "GB through a curve network uses \"cubic-natural\" or \"cubic-notaknot\" (the b2 blend needs the \
             auxiliary lines u₋₁, uₘ₊₂; use splineBlendedSurface with a function for it)",
        )),
        b => Ok(b),
    }
}

api_options! {
    /// The options of `surfaceDifferences`.
    pub struct SurfaceDifferencesOptions extends "NetworkTolerance" |o| {
        /// At most 65 breakpoints per direction.
        network: Network = "network", req "NetworkInput" => |k| read_network(o, k)?;
        /// The grid side, 2 ..= 200 (default 57).
        samples: usize = "samples", opt "number" => |k| {
            let n = o.usize_or(k, gordon::DIFFERENCE_GRID, gordon::FAMILY_MAX_NORM_SAMPLES)?;
            gordon::check_norm_samples(k, n).map_err(core_err)?;
            n
        };
        /// The blend of GB (default "cubic-natural").
        blend: Blend = "blend", opt "'cubic-natural' | 'cubic-notaknot'" => |k| blend_or_cubic(o, k)?;
        /// The tolerance of the compatibility check.
        tolerance: f64 = "tolerance", ext "NetworkTolerance" => |_k| read_tolerance(o)?;
    }
}

/// ‖A − B‖∞ of the network surfaces on a samples × samples grid.
///
/// `surfaceDifferences({ network, samples = 57, blend = "cubic-natural" })` → `{ SG, ST, TG, SGB, GGB }`:
/// ‖A − B‖∞ over all coordinates on the `samples × samples` grid (the paper's measure), for the surfaces
/// available in this build (S, T come with the criss-cross module).
#[wasm_bindgen(js_name = surfaceDifferences, unchecked_return_type = "SurfaceNorms & { samples: number }")]
pub fn surface_differences(
    #[wasm_bindgen(unchecked_param_type = "SurfaceDifferencesOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let SurfaceDifferencesOptions {
        network,
        samples: n,
        blend,
        tolerance,
    } = SurfaceDifferencesOptions::read(&o)?;
    let fam = SurfaceFamily::new(&network, blend, tolerance).map_err(core_err)?;
    Ok(norms_out(&fam, n).num("samples", n as f64).build())
}

api_options! {
    /// Limits: network ≤ 65 breakpoints per direction; samplesU × samplesV × surfaces ≤ 200,000; normSamples ≤ 200;
    /// curveSamples ≤ 1024 (beyond: an Error with kind "too-many" naming the field).
    pub struct NetworkSurfacesOptions extends "NetworkTolerance, GordonComponents" |o| {
        /// At most 65 breakpoints per direction.
        network: Network = "network", req "NetworkInput" => |k| read_network(o, k)?;
        /// samplesU × samplesV × surfaces ≤ 200,000.
        samples_u: usize = "samplesU", opt "number" => |k| o.usize_or(k, 64, mesh::MAX_DENSITY)?;
        /// The grid in v (default 64, as `samplesU`).
        samples_v: usize = "samplesV", opt "number" => |k| o.usize_or(k, 64, mesh::MAX_DENSITY)?;
        /// The blend of GB (default "cubic-natural").
        blend: Blend = "blend", opt "'cubic-natural' | 'cubic-notaknot'" => |k| blend_or_cubic(o, k)?;
        /// The tolerance of the compatibility check.
        tolerance: f64 = "tolerance", ext "NetworkTolerance" => |_k| read_tolerance(o)?;
        /// The surfaces to sample (default S, T, G, GB; also the Gordon components L1, L2, Tg).
        surfaces: Vec<String> = "surfaces", opt "ReadonlyArray<NetworkSurfaceName>" => |k| match o.opt::<Vec<String>>(k)? {
            Some(w) => w,
            None => FAMILY_NAMES.iter().map(|s| s.to_string()).collect(),
        };
        /// Compute `norms` (default true; false skips them and the surfaces only they need).
        norms: bool = "norms", opt "boolean" => |k| o.bool_or(k, true)?;
        /// The norms' grid (default 57, at most 200; < 2 omits `norms`).
        norm_samples: usize = "normSamples", opt "number" => |k| match norms {
            true => o.usize_or(k, gordon::DIFFERENCE_GRID, gordon::FAMILY_MAX_NORM_SAMPLES)?,
            false => 0,
        };
        /// Two names, e.g. "SG": adds `colors`.
        color_by: Option<String> = "colorBy", opt "string" => |k| o.opt::<String>(k)?;
        /// Adds `curves: { phi, psi }` (at most 1024 points per curve).
        curve_samples: usize = "curveSamples", opt "number"
            => |k| o.usize_or(k, 0, gordon::FAMILY_MAX_CURVE_SAMPLES)?;
    }
}

#[wasm_bindgen(typescript_custom_section)]
const NETWORK_SURFACES_TS: &str = r#"
export type NetworkSurfaceName = 'S' | 'T' | 'G' | 'GB' | 'L1' | 'L2' | 'Tg';
export interface SurfaceNorms {
  SG?: number;
  ST?: number;
  TG?: number;
  SGB?: number;
  GGB?: number;
}
export interface NetworkSurfacesResult {
  names: string[];
  available: string[];
  samplesU: number;
  samplesV: number;
  surfaces: { [name: string]: { points: Float64Array; mesh: Mesh } };
  norms?: SurfaceNorms;
  gordon: GordonExtras;
  colors?: Float32Array;
  curves?: { phi: Float64Array[]; psi: Float64Array[] };
}
"#;

/// Every surface through one network, tessellated on one grid, in one call.
///
/// `networkSurfaces({ network, samplesU = 64, samplesV = 64, surfaces = ["S", "T", "G", "GB"] (also "L1", "L2",
/// "Tg": the Gordon components), blend = "cubic-natural",
/// colorBy, components, normSamples = 57 })` → `{ names, surfaces: { S?, T?, G, GB: { points, mesh } },
/// norms: { SG?, ST?, TG?, SGB?, GGB }, gordon: { knotsU, knotsV, controlPoints, …, components? },
/// colors? }`: every surface through one network, tessellated on one u-major grid, in one call (the
/// "Curve networks" demo calls this on every drag). `curveSamples: k` adds `curves: { phi, psi }`, the
/// network curves φ_0..φ_m and ψ_0..ψ_n sampled at k points each (Float64Array xyz per curve). `colorBy: "SG"` (any pair of names) adds `colors`, the
/// per-vertex distance between the two surfaces (Float32Array), for a colour map.
#[wasm_bindgen(js_name = networkSurfaces, unchecked_return_type = "NetworkSurfacesResult")]
pub fn network_surfaces(
    #[wasm_bindgen(unchecked_param_type = "NetworkSurfacesOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let NetworkSurfacesOptions {
        network: net,
        samples_u,
        samples_v,
        blend,
        tolerance: tol,
        surfaces,
        norm_samples,
        color_by,
        curve_samples,
        ..
    } = NetworkSurfacesOptions::read(&o)?;
    let req = FamilyRequest {
        surfaces,
        samples_u,
        samples_v,
        norm_samples,
        color_by,
        curve_samples,
    };
    let r = render_family(&net, blend, tol, &req).map_err(core_err)?;
    let mut surfaces = Out::new();
    for s in &r.surfaces {
        surfaces = surfaces.set(
            &s.name,
            Out::new()
                .f64s("points", &s.points)
                .set("mesh", mesh_object(&s.mesh))
                .build(),
        );
    }
    let names: Vec<&str> = r.surfaces.iter().map(|s| s.name.as_str()).collect();
    let mut out = Out::new()
        .ser("names", &names)
        .ser("available", &r.family.names())
        .num("samplesU", samples_u as f64)
        .num("samplesV", samples_v as f64)
        .set("surfaces", surfaces.build());
    if let Some(norms) = &r.norms {
        let n = norms
            .iter()
            .fold(Out::new(), |out, (key, v)| out.num(key, *v));
        out = out.set("norms", n.build());
    }
    if let Some(colors) = &r.colors {
        out = out.f32s("colors", colors);
    }
    if let Some((phi, psi)) = &r.curves {
        // the network curves φ_r (on u = u_r) and ψ_s (on v = v_s), k points each, flat xyz
        out = out.set(
            "curves",
            Out::new()
                .set("phi", f64_arrays(phi))
                .set("psi", f64_arrays(psi))
                .build(),
        );
    }
    let GordonComponents { components } = GordonComponents::read(&o)?;
    let gordon = gordon_extras(Out::new(), r.family.gordon(), components);
    Ok(out.set("gordon", gordon.build()).build())
}

/// A JS array of `Float64Array`s, one per list.
fn f64_arrays(lists: &[Vec<f64>]) -> js_sys::Array {
    let a = js_sys::Array::new();
    for c in lists {
        let f = js_sys::Float64Array::new_with_length(c.len() as u32);
        f.copy_from(c);
        a.push(&f);
    }
    a
}
