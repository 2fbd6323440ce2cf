//! Render buffers for every surface export.
//!
//! Any surface function that samples a grid (`samplesU`/`samplesV`) accepts `mesh: true` and then adds
//! `mesh: { nu, nv, positions: Float32Array (xyz per vertex), normals: Float32Array (unit, xyz),
//! indices: Uint32Array (triangles, two per grid cell) }` to its result, u-major like `points`
//! (vertex `iu * nv + iv`). With `atUV` there is no grid and `mesh: true` is an error.

use super::{core_err, ApiResult, Opts, Out};
use crate::mesh::Mesh;
use crate::point::Point;
use crate::sample::{self, Surface};

/// The common surface result `{ dim, uv, points, du?, dv?, mesh? }` for the sampling options in `o`
/// (`atUV` | `samplesU`/`samplesV`, `derivatives`, `mesh`).
pub fn surface_output<P: Point>(o: &Opts, surface: &dyn Surface<P>) -> ApiResult<Out> {
    surface_output_checked(o, surface, &|_| Ok(()))
}

/// [`surface_output`] with `check` applied to the evaluated points and partials (each flat array) before
/// the result is built: a construction can turn values it cannot represent into an error.
pub fn surface_output_checked<P: Point>(
    o: &Opts,
    surface: &dyn Surface<P>,
    check: &dyn Fn(&[f64]) -> ApiResult<()>,
) -> ApiResult<Out> {
    let derivs = o.derivatives(1)? >= 1;
    let want_mesh = o.mesh_on_grid()?;
    let uv = o.surface_uv(surface.domain())?;
    let (pts, du, dv) = if o.has("atUV") {
        sample::eval_surface(surface, &uv, derivs || want_mesh)
    } else {
        // a grid: the surface's grid sampler (basis rows once per grid line), the same u-major order as `uv`
        let ((u0, u1), (v0, v1)) = surface.domain();
        let nu = o.usize_or("samplesU", 40, usize::MAX)?;
        let nv = o.usize_or("samplesV", 40, usize::MAX)?;
        let us = sample::uniform_params(u0, u1, nu);
        let vs = sample::uniform_params(v0, v1, nv);
        sample::eval_surface_grid(surface, &us, &vs, derivs || want_mesh)
    };
    check(&pts)?;
    check(&du)?;
    check(&dv)?;
    let mut out = Out::new()
        .num("dim", P::DIM as f64)
        .f64s("uv", &uv)
        .f64s("points", &pts);
    if derivs {
        out = out.f64s("du", &du).f64s("dv", &dv);
    }
    if want_mesh {
        let nu = o.usize_or("samplesU", 40, usize::MAX)?;
        let nv = o.usize_or("samplesV", 40, usize::MAX)?;
        let m = Mesh::from_grid(&pts, Some((&du, &dv)), P::DIM, nu, nv).map_err(core_err)?;
        out = out.set("mesh", mesh_object(&m));
    }
    Ok(out)
}

/// `{ nu, nv, positions, normals, indices }` as a JS object.
pub fn mesh_object(m: &Mesh) -> wasm_bindgen::JsValue {
    Out::new()
        .num("nu", m.nu as f64)
        .num("nv", m.nv as f64)
        .f32s("positions", &m.positions)
        .f32s("normals", &m.normals)
        .u32s("indices", &m.indices)
        .build()
}
