//! What a curve-network figure draws of the [`SurfaceFamily`] (S, T, G, GB) in one call: the named surfaces
//! sampled on one `samples_u × samples_v` grid of the common domain with their render meshes, and, when asked
//! for, the ‖·‖∞ norms of every pair ([`SurfaceFamily::norms`], Dagnino–Lamberti–Remogna §4.2), a per-vertex
//! distance between two surfaces for a colour map ([`distance_map`]) and the network curves φ_r, ψ_s
//! ([`SurfaceFamily::network_curves`]).
//!
//! Only the surfaces these need are built ([`SurfaceFamily::with_only`]): the named ones, all four for the norms,
//! the coloured pair, and GB (which holds the network lines) for the curves.

use super::family::{
    distance_map, NetworkCurves, SurfaceFamily, FAMILY_MAX_GRID_POINTS, FAMILY_NAMES,
};
use super::Blend;
use crate::error::{Error, ErrorKind, Result};
use crate::mesh::{self, Mesh};
use crate::network::Network;
use crate::sample;

/// The most surface names one request may list.
pub const FAMILY_MAX_SURFACES: usize = 8;

/// What to draw of the family (the options of `networkSurfaces`).
#[derive(Clone, Debug)]
pub struct FamilyRequest {
    /// The surfaces to sample, by name: `"S"`, `"T"`, `"G"`, `"GB"` ([`FAMILY_NAMES`]) or the Gordon components
    /// `"L1"`, `"L2"`, `"Tg"`; at most [`FAMILY_MAX_SURFACES`].
    pub surfaces: Vec<String>,
    /// The sampling grid of the domain: `samples_u × samples_v` points per surface.
    pub samples_u: usize,
    /// See `samples_u`.
    pub samples_v: usize,
    /// The side of the grid of the norms; under 2: no norms.
    pub norm_samples: usize,
    /// Two surface names run together (`"SG"`, `"GGB"`): their per-vertex distance.
    pub color_by: Option<String>,
    /// Points per network curve; under 2: no curves.
    pub curve_samples: usize,
}

/// One sampled surface of a [`FamilyRender`].
pub struct RenderedSurface {
    /// Its name as asked for.
    pub name: String,
    /// The `samples_u × samples_v` points, flat xyz, u-major.
    pub points: Vec<f64>,
    /// Its render mesh (normals from the partial derivatives).
    pub mesh: Mesh,
}

/// The result of [`render_family`].
pub struct FamilyRender {
    /// The family built for the request (its names, domain and Gordon surface G).
    pub family: SurfaceFamily,
    /// The asked-for surfaces, in the order asked.
    pub surfaces: Vec<RenderedSurface>,
    /// `(key, ‖A − B‖∞)` per pair of [`super::FAMILY_PAIRS`], when `norm_samples ≥ 2`.
    pub norms: Option<Vec<(&'static str, f64)>>,
    /// The per-vertex distance of the `color_by` pair on the sampling grid.
    pub colors: Option<Vec<f32>>,
    /// The network curves, when `curve_samples ≥ 2`.
    pub curves: Option<NetworkCurves>,
}

/// Builds the surfaces `req` needs through `net` (compatibility tolerance `tol`, `blend` for GB) and samples them.
///
/// Errors name the request's field: `samplesU` (the density of [`mesh::check_density`], or more than
/// [`FAMILY_MAX_GRID_POINTS`] points over all surfaces), `surfaces` (over [`FAMILY_MAX_SURFACES`] names),
/// `surfaces[i]` (an unknown name), `colorBy` (not two surface names), and the network's own errors.
pub fn render_family(
    net: &Network,
    blend: Blend,
    tol: f64,
    req: &FamilyRequest,
) -> Result<FamilyRender> {
    let (nu, nv) = (req.samples_u, req.samples_v);
    mesh::check_density(nu, nv)?;
    let wanted = &req.surfaces;
    if wanted.len() > FAMILY_MAX_SURFACES {
        return Err(Error::too_many(
            "surfaces",
            format!("at most {FAMILY_MAX_SURFACES} names, got {}", wanted.len()),
        ));
    }
    let grid_points = (nu * nv).saturating_mul(wanted.len().max(1));
    if grid_points > FAMILY_MAX_GRID_POINTS {
        return Err(Error::too_many_of(
            "samplesU",
            FAMILY_MAX_GRID_POINTS,
            grid_points,
            format!(
                "at most {FAMILY_MAX_GRID_POINTS} evaluation points (samplesU × samplesV × surfaces), got {nu} × {nv} × {}",
                wanted.len()
            ),
        ));
    }
    let mut needed: Vec<&str> = wanted.iter().map(String::as_str).collect();
    if req.norm_samples >= 2 {
        needed.extend(FAMILY_NAMES);
    }
    if let Some(pair) = &req.color_by {
        needed.extend(FAMILY_NAMES.iter().filter(|n| pair.contains(*n)));
    }
    if req.curve_samples >= 2 {
        needed.push("GB");
    }
    let family = SurfaceFamily::with_only(net, blend, tol, &needed)?;
    let ((u0, u1), (v0, v1)) = family.domain();
    let (us, vs) = (
        sample::uniform_params(u0, u1, nu),
        sample::uniform_params(v0, v1, nv),
    );
    let mut surfaces = Vec::with_capacity(wanted.len());
    for (i, name) in wanted.iter().enumerate() {
        let s = family.get(name).ok_or_else(|| {
            Error::new(
                ErrorKind::Invalid,
                format!("surfaces[{i}]"),
                format!(
                    "unknown surface {name:?}; expected some of {:?} or the Gordon components \"L1\", \"L2\", \"Tg\"",
                    family.names()
                ),
            )
        })?;
        let grid = s.eval_grid(&us, &vs, true);
        let mesh = Mesh::from_grid(&grid.points, Some((&grid.du, &grid.dv)), 3, nu, nv)?;
        surfaces.push(RenderedSurface {
            name: name.clone(),
            points: grid.points,
            mesh,
        });
    }
    let norms = (req.norm_samples >= 2).then(|| family.norms(req.norm_samples));
    let colors = match &req.color_by {
        None => None,
        Some(pair) => {
            let (a, b) = family.pair(pair).ok_or_else(|| {
                Error::new(
                    ErrorKind::Invalid,
                    "colorBy",
                    format!("expected two surface names such as \"SG\" or \"GGB\", got {pair:?}"),
                )
            })?;
            // a surface sampled above is not evaluated again
            let values = |name: &str| match surfaces.iter().find(|s| s.name == name) {
                Some(s) => s.points.clone(),
                None => family
                    .get(name)
                    .map(|s| s.eval_grid(&us, &vs, false).points)
                    .unwrap_or_default(),
            };
            Some(distance_map(&values(a), &values(b)))
        }
    };
    let curves = (req.curve_samples >= 2)
        .then(|| family.network_curves(req.curve_samples))
        .flatten();
    Ok(FamilyRender {
        family,
        surfaces,
        norms,
        colors,
        curves,
    })
}
