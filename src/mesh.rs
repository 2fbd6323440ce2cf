//! Surface tessellation to render buffers: positions, unit normals and triangle indices of a u-major
//! `nu × nv` grid of surface points (vertex index `iu * nv + iv`, as the API's sample grids).
//!
//! Normals are ∂S/∂u × ∂S/∂v where the partials are known and non-degenerate, else (e.g. at a sphere's
//! pole, where ∂S/∂v = 0) from central differences of the neighbouring grid points.

use crate::error::{Error, Result};
use crate::point::Point;
use crate::sample::{self, Surface};
use glam::DVec3;

/// The most vertices along one direction of a tessellation.
pub const MAX_DENSITY: usize = 2048;

/// Render buffers of a tessellated surface (`f32` for the GPU).
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    /// Vertices along u.
    pub nu: usize,
    /// Vertices along v.
    pub nv: usize,
    /// `3 * nu * nv` coordinates (2D surfaces get z = 0).
    pub positions: Vec<f32>,
    /// `3 * nu * nv` unit normals (zero where the surface is degenerate in every direction).
    pub normals: Vec<f32>,
    /// Triangles, two per grid cell, counter-clockwise when seen against the normal.
    pub indices: Vec<u32>,
}

/// Checks a requested tessellation density.
pub fn check_density(nu: usize, nv: usize) -> Result<()> {
    for (field, n) in [("samplesU", nu), ("samplesV", nv)] {
        if n < 2 {
            return Err(Error::too_few(
                field,
                format!("a tessellation needs at least 2 vertices per direction, got {n}"),
            ));
        }
        if n > MAX_DENSITY {
            return Err(Error::too_many(
                field,
                format!("at most {MAX_DENSITY} vertices per direction, got {n}"),
            ));
        }
    }
    sample::check_eval_count("samplesU", nu * nv)
}

fn to3(flat: &[f64], dim: usize, i: usize) -> DVec3 {
    let c = &flat[i * dim..i * dim + dim];
    DVec3::new(
        c[0],
        if dim > 1 { c[1] } else { 0.0 },
        if dim > 2 { c[2] } else { 0.0 },
    )
}

impl Mesh {
    /// Builds the buffers from an already evaluated u-major grid: `points` (and optionally the partials
    /// `du`, `dv`) flat with `dim` coordinates per point.
    pub fn from_grid(
        points: &[f64],
        du: Option<(&[f64], &[f64])>,
        dim: usize,
        nu: usize,
        nv: usize,
    ) -> Result<Mesh> {
        check_density(nu, nv)?;
        if points.len() != nu * nv * dim {
            return Err(Error::size_mismatch(
                "points",
                format!(
                    "expected {} coordinates, got {}",
                    nu * nv * dim,
                    points.len()
                ),
            ));
        }
        let count = nu * nv;
        let mut positions = Vec::with_capacity(3 * count);
        let mut normals = Vec::with_capacity(3 * count);
        let scale = (0..count)
            .map(|i| to3(points, dim, i).max_abs())
            .fold(1e-300, f64::max);
        for iu in 0..nu {
            for iv in 0..nv {
                let k = iu * nv + iv;
                let p = to3(points, dim, k);
                positions.extend_from_slice(&[p.x as f32, p.y as f32, p.z as f32]);
                let mut n = match du {
                    Some((su, sv)) if su.len() == points.len() && sv.len() == points.len() => {
                        to3(su, dim, k).cross(to3(sv, dim, k))
                    }
                    _ => DVec3::ZERO,
                };
                if !(n.length() > 1e-12 * scale * scale) {
                    // central differences on the grid (one-sided at the border)
                    let a = to3(points, dim, (iu.min(nu - 2) + 1) * nv + iv)
                        - to3(points, dim, iu.saturating_sub(1) * nv + iv);
                    let b = to3(points, dim, iu * nv + iv.min(nv - 2) + 1)
                        - to3(points, dim, iu * nv + iv.saturating_sub(1));
                    n = a.cross(b);
                    if !(n.length() > 1e-12 * scale * scale) {
                        // a collapsed row (pole): use the next row's spread
                        let iu2 = if iu + 1 < nu { iu + 1 } else { iu - 1 };
                        let b2 = to3(points, dim, iu2 * nv + iv.min(nv - 2) + 1)
                            - to3(points, dim, iu2 * nv + iv.saturating_sub(1));
                        let a2 = to3(points, dim, iu2 * nv + iv) - p;
                        n = if iu2 > iu {
                            a2.cross(b2)
                        } else {
                            -a2.cross(b2)
                        };
                    }
                }
                let n = n.normalize_or_zero();
                normals.extend_from_slice(&[n.x as f32, n.y as f32, n.z as f32]);
            }
        }
        let mut indices = Vec::with_capacity(6 * (nu - 1) * (nv - 1));
        for iu in 0..nu - 1 {
            for iv in 0..nv - 1 {
                let a = (iu * nv + iv) as u32;
                let b = ((iu + 1) * nv + iv) as u32;
                let c = ((iu + 1) * nv + iv + 1) as u32;
                let d = (iu * nv + iv + 1) as u32;
                indices.extend_from_slice(&[a, b, c, a, c, d]);
            }
        }
        Ok(Mesh {
            nu,
            nv,
            positions,
            normals,
            indices,
        })
    }
}

impl Mesh {
    /// Render buffers of the graph (u, v, f(u, v)) of a scalar function sampled on a u-major `nu × nv` grid:
    /// `uv` the flat (u, v) pairs, `values` f there, `partials` (f_u, f_v) there. The surface's partials are
    /// (1, 0, f_u) and (0, 1, f_v), so its normal is (−f_u, −f_v, 1)/√(1 + f_u² + f_v²).
    pub fn from_graph(
        uv: &[f64],
        values: &[f64],
        partials: (&[f64], &[f64]),
        nu: usize,
        nv: usize,
    ) -> Result<Mesh> {
        let count = values.len();
        if uv.len() != 2 * count || partials.0.len() != count || partials.1.len() != count {
            return Err(Error::size_mismatch(
                "values",
                "expected one (u, v) pair, one value and two partials per point",
            ));
        }
        let mut pts = Vec::with_capacity(3 * count);
        let (mut gu, mut gv) = (Vec::with_capacity(3 * count), Vec::with_capacity(3 * count));
        for (k, w) in uv.chunks_exact(2).enumerate() {
            pts.extend_from_slice(&[w[0], w[1], values[k]]);
            gu.extend_from_slice(&[1.0, 0.0, partials.0[k]]);
            gv.extend_from_slice(&[0.0, 1.0, partials.1[k]]);
        }
        Mesh::from_grid(&pts, Some((&gu, &gv)), 3, nu, nv)
    }
}

/// Tessellates `surface` on a uniform `nu × nv` grid of its domain.
pub fn tessellate<P: Point, S: Surface<P> + ?Sized>(
    surface: &S,
    nu: usize,
    nv: usize,
) -> Result<Mesh> {
    check_density(nu, nv)?;
    let uv = sample::uv_grid(surface.domain(), nu, nv);
    let (pts, du, dv) = sample::eval_surface(surface, &uv, true);
    Mesh::from_grid(&pts, Some((&du, &dv)), P::DIM, nu, nv)
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Sphere;
    impl Surface<DVec3> for Sphere {
        fn domain(&self) -> ((f64, f64), (f64, f64)) {
            (
                (0.0, std::f64::consts::PI),
                (0.0, 2.0 * std::f64::consts::PI),
            )
        }
        fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [DVec3; 3]) {
            out[0] = DVec3::new(u.sin() * v.cos(), u.sin() * v.sin(), u.cos());
            if derivs {
                out[1] = DVec3::new(u.cos() * v.cos(), u.cos() * v.sin(), -u.sin());
                out[2] = DVec3::new(-u.sin() * v.sin(), u.sin() * v.cos(), 0.0);
            }
        }
    }

    #[test]
    fn sphere_normals_point_outwards_even_at_poles() {
        let m = tessellate(&Sphere, 9, 17).unwrap();
        assert_eq!(m.positions.len(), 3 * 9 * 17);
        assert_eq!(m.indices.len(), 6 * 8 * 16);
        for k in 0..9 * 17 {
            let p = DVec3::new(
                m.positions[3 * k] as f64,
                m.positions[3 * k + 1] as f64,
                m.positions[3 * k + 2] as f64,
            );
            let n = DVec3::new(
                m.normals[3 * k] as f64,
                m.normals[3 * k + 1] as f64,
                m.normals[3 * k + 2] as f64,
            );
            assert!((n.length() - 1.0).abs() < 1e-6, "unit normal at {k}");
            assert!(
                n.dot(p) > 0.9,
                "outward normal at vertex {k}: {n:?} vs {p:?}"
            );
        }
    }

    #[test]
    fn graph_of_a_plane_has_the_plane_normal() {
        // f(u, v) = 2u − 3v + 1 on the grid {0, 0.5, 1} × {0, 2}: positions (u, v, f), every normal
        // (−f_u, −f_v, 1)/√(1 + f_u² + f_v²) = (−2, 3, 1)/√14
        let uv = [0.0, 0.0, 0.0, 2.0, 0.5, 0.0, 0.5, 2.0, 1.0, 0.0, 1.0, 2.0];
        let f: Vec<f64> = uv
            .chunks(2)
            .map(|w| 2.0 * w[0] - 3.0 * w[1] + 1.0)
            .collect();
        let m = Mesh::from_graph(&uv, &f, (&[2.0; 6], &[-3.0; 6]), 3, 2).unwrap();
        assert_eq!((m.nu, m.nv), (3, 2));
        assert_eq!(&m.positions[9..12], &[0.5, 2.0, -4.0]);
        let want = DVec3::new(-2.0, 3.0, 1.0) / 14f64.sqrt();
        for n in m.normals.chunks(3) {
            let n = DVec3::new(n[0] as f64, n[1] as f64, n[2] as f64);
            assert!((n - want).length() < 1e-6, "{n}");
        }
        assert_eq!(m.indices, [0, 2, 3, 0, 3, 1, 2, 4, 5, 2, 5, 3]);
        // a missing partial or a too coarse grid is an error, not a panic
        let e = Mesh::from_graph(&uv, &f, (&[], &[]), 3, 2).unwrap_err();
        assert_eq!(e.field(), "values");
        let e = Mesh::from_graph(&uv[..2], &f[..1], (&[2.0], &[-3.0]), 1, 1).unwrap_err();
        assert_eq!(e.field(), "samplesU");
    }

    #[test]
    fn absurd_densities_are_errors() {
        assert_eq!(tessellate(&Sphere, 1, 5).unwrap_err().field(), "samplesU");
        assert_eq!(
            tessellate(&Sphere, 5, MAX_DENSITY + 1).unwrap_err().field(),
            "samplesV"
        );
    }
}
