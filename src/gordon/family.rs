//! [`SurfaceFamily`]: every surface the papers build through one curve network (S, T, G, GB and the Gordon
//! components), looked up by the paper's names, with the ‖A − B‖∞ differences of Dagnino–Lamberti–Remogna §4.2, the
//! per-vertex distance map between two of them and the sampled network curves.

use super::{
    Blend, GordonSurface, Grid, GridSurface, LineNetwork, NetworkLines, SplineBlendedSurface,
};
use crate::criss_cross::CrissCrossSurface;
use crate::error::{Error, Result};
use crate::network::Network;
use crate::sample::{self, Surface};
use crate::thin_plate::ThinPlateSurface;
use std::collections::HashMap;

/// The surface names of a family, in the paper's order.
pub const FAMILY_NAMES: [&str; 4] = ["S", "T", "G", "GB"];

/// The pairs whose ‖A − B‖∞ the paper reports, as (key, A, B).
pub const FAMILY_PAIRS: [(&str, &str, &str); 5] = [
    ("SG", "S", "G"),
    ("ST", "S", "T"),
    ("TG", "T", "G"),
    ("SGB", "S", "GB"),
    ("GGB", "G", "GB"),
];

/// The most breakpoints per direction of a network whose family is built (m, n ≤ 64). Building S, T, G
/// and GB through an m × m network grows like m^2.5 (G's and T's systems are dense): measured in Node
/// (wasm, 2 cores at load 11), 11 ms at 33 × 33, 52 ms at 65 × 65, 238 ms at 97 × 97, 496 ms at 129 × 129.
/// The limit keeps `networkSurfaces` and `surfaceDifferences` well under a second (the demo's largest
/// network has 19 breakpoints).
pub const FAMILY_MAX_LINES: usize = 65;

/// The largest grid side `n` of [`SurfaceFamily::norms`] (`n × n` points on each of the four surfaces; the
/// paper's measure uses 57).
pub const FAMILY_MAX_NORM_SAMPLES: usize = 200;

/// The most evaluation points of the tessellated surfaces of one `networkSurfaces` call (samplesU ×
/// samplesV × surfaces; the demo asks for at most 96² × 7 = 64,512).
pub const FAMILY_MAX_GRID_POINTS: usize = 200_000;

/// The most samples per network curve ([`SurfaceFamily::network_curves`]; the demo asks for 48).
pub const FAMILY_MAX_CURVE_SAMPLES: usize = 1024;

/// Checks the family's size limits on `net` (at most [`FAMILY_MAX_LINES`] breakpoints per direction).
pub fn check_family_size(net: &Network) -> Result<()> {
    for (field, len) in [("network.u", net.u.len()), ("network.v", net.v.len())] {
        if len > FAMILY_MAX_LINES {
            return Err(Error::too_many_of(
                field,
                FAMILY_MAX_LINES,
                len,
                format!(
                    "at most {FAMILY_MAX_LINES} breakpoints per direction for the surface family (S, T, G, GB), got {len}"
                ),
            ));
        }
    }
    Ok(())
}

/// Checks a grid side `n` of [`SurfaceFamily::norms`] read from `field` (2 ≤ n ≤ [`FAMILY_MAX_NORM_SAMPLES`]).
pub fn check_norm_samples(field: &'static str, n: usize) -> Result<()> {
    if n < 2 {
        return Err(Error::too_few_of(
            field,
            2,
            n,
            format!("need at least 2, got {n}"),
        ));
    }
    if n > FAMILY_MAX_NORM_SAMPLES {
        return Err(Error::too_many_of(
            field,
            FAMILY_MAX_NORM_SAMPLES,
            n,
            format!("at most {FAMILY_MAX_NORM_SAMPLES} (an n × n grid on four surfaces), got {n}"),
        ));
    }
    Ok(())
}

/// The sampled network curves `(φ_0..φ_m, ψ_0..ψ_n)`, each flat xyz ([`SurfaceFamily::network_curves`]).
pub type NetworkCurves = (Vec<Vec<f64>>, Vec<Vec<f64>>);

/// The surfaces through one network: criss-cross S, thin-plate T, Gordon G and spline-blended GB. G is
/// always built (it gives the domain); S, T and GB are built only when asked for
/// ([`SurfaceFamily::with_only`]).
pub struct SurfaceFamily {
    s: Option<CrissCrossSurface>,
    t: Option<ThinPlateSurface>,
    g: GordonSurface,
    gb: Option<SplineBlendedSurface<NetworkLines>>,
}

impl SurfaceFamily {
    /// Builds all four surfaces through `net` (compatibility tolerance `tol`; `blend` for GB).
    pub fn new(net: &Network, blend: Blend, tol: f64) -> Result<Self> {
        Self::with_only(net, blend, tol, &FAMILY_NAMES)
    }

    /// Builds G and those of S, T, GB that `names` lists (other names are ignored; the Gordon components
    /// `"L1"`, `"L2"`, `"Tg"` come with G). In the order S, T, G, GB, so the first error is that of
    /// [`SurfaceFamily::new`] when all are asked for.
    /// Fails for a network over [`FAMILY_MAX_LINES`] breakpoints per direction ([`check_family_size`]).
    pub fn with_only(net: &Network, blend: Blend, tol: f64, names: &[&str]) -> Result<Self> {
        check_family_size(net)?;
        let wants = |n: &str| names.contains(&n);
        let s = match wants("S") {
            true => Some(CrissCrossSurface::with_tolerance(net, tol)?),
            false => None,
        };
        let t = match wants("T") {
            true => Some(ThinPlateSurface::with_tolerance(net, tol)?),
            false => None,
        };
        let g = GordonSurface::with_tolerance(net, tol)?;
        let gb = match wants("GB") {
            true => {
                let lines = NetworkLines::with_tolerance(net, tol)?;
                Some(SplineBlendedSurface::new(lines, blend)?)
            }
            false => None,
        };
        Ok(SurfaceFamily { s, t, g, gb })
    }

    /// The names of the surfaces (see [`FAMILY_NAMES`]).
    pub fn names(&self) -> Vec<&'static str> {
        FAMILY_NAMES.to_vec()
    }

    /// The surface called `name`: `"S"`, `"T"`, `"G"`, `"GB"` or a Gordon component `"L1"`, `"L2"`, `"Tg"`
    /// (`None` for an unknown name or a surface not built, see [`SurfaceFamily::with_only`]).
    pub fn get(&self, name: &str) -> Option<&dyn GridSurface> {
        match name {
            "S" => self.s.as_ref().map(|s| s as &dyn GridSurface),
            "T" => self.t.as_ref().map(|s| s as &dyn GridSurface),
            "G" => Some(&self.g),
            "GB" => self.gb.as_ref().map(|s| s as &dyn GridSurface),
            "L1" => Some(self.g.l1()),
            "L2" => Some(self.g.l2()),
            "Tg" => Some(self.g.tg()),
            _ => None,
        }
    }

    /// The Gordon surface G.
    pub fn gordon(&self) -> &GordonSurface {
        &self.g
    }

    /// The common domain (that of G).
    pub fn domain(&self) -> ((f64, f64), (f64, f64)) {
        self.g.domain()
    }

    /// ‖A − B‖∞ on an `n × n` grid for every pair of [`FAMILY_PAIRS`] whose two surfaces are built, as
    /// (key, value).
    pub fn norms(&self, n: usize) -> Vec<(&'static str, f64)> {
        let ((u0, u1), (v0, v1)) = self.domain();
        let (us, vs) = (
            sample::uniform_params(u0, u1, n),
            sample::uniform_params(v0, v1, n),
        );
        let grids: HashMap<&str, Grid> = self
            .names()
            .into_iter()
            .filter_map(|k| self.get(k).map(|s| (k, s.eval_grid(&us, &vs, false))))
            .collect();
        FAMILY_PAIRS
            .iter()
            .filter_map(|&(key, a, b)| match (grids.get(a), grids.get(b)) {
                (Some(x), Some(y)) => Some((key, x.max_difference(y))),
                _ => None,
            })
            .collect()
    }

    /// Splits a pair name such as `"SG"` or `"GGB"` into two different surface names of the family.
    pub fn pair(&self, pair: &str) -> Option<(&'static str, &'static str)> {
        self.names()
            .into_iter()
            .flat_map(|a| self.names().into_iter().map(move |b| (a, b)))
            .find(|(a, b)| a != b && format!("{a}{b}") == pair)
    }

    /// The network curves φ_0..φ_m (on u = u_r, over v) and ψ_0..ψ_n (on v = v_s, over u), each sampled at
    /// `k` uniform parameters of the domain, as flat xyz (`None` when GB, which holds them, is not built).
    pub fn network_curves(&self, k: usize) -> Option<NetworkCurves> {
        let ((u0, u1), (v0, v1)) = self.domain();
        let lines = self.gb.as_ref()?.lines();
        let (mr, ns) = (lines.u_nodes().len(), lines.v_nodes().len());
        let (mut phi, mut psi) = (
            vec![Vec::with_capacity(3 * k); mr],
            vec![Vec::with_capacity(3 * k); ns],
        );
        for t in sample::uniform_params(v0, v1, k) {
            lines.v_curves(t, false, &mut |r, p, _| {
                phi[r].extend_from_slice(&p.to_array())
            });
        }
        for t in sample::uniform_params(u0, u1, k) {
            lines.u_curves(t, false, &mut |s, p, _| {
                psi[s].extend_from_slice(&p.to_array())
            });
        }
        Some((phi, psi))
    }
}

/// Per-vertex max-coordinate distance between two evaluated xyz grids (for a colour map).
pub fn distance_map(a: &[f64], b: &[f64]) -> Vec<f32> {
    a.chunks_exact(3)
        .zip(b.chunks_exact(3))
        .map(|(p, q)| {
            (p[0] - q[0])
                .abs()
                .max((p[1] - q[1]).abs())
                .max((p[2] - q[2]).abs()) as f32
        })
        .collect()
}
