//! Tensor-grid evaluation: on a u-major grid `us × vs` the basis functions are computed once per grid
//! line instead of once per point (the "Curve networks" demo re-tessellates every surface on every drag).

use super::blended::{LineNetwork, SplineBlendedSurface};
use super::GordonSurface;
use crate::bspline::BSplineSurface;
use crate::sample::Surface;
use glam::DVec3;

/// A grid of surface points, u-major (`iu * nv + iv`), flat xyz; `du`, `dv` empty unless asked for.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Grid {
    /// Points, flat xyz.
    pub points: Vec<f64>,
    /// ∂/∂u, flat xyz (empty unless asked for).
    pub du: Vec<f64>,
    /// ∂/∂v, flat xyz (empty unless asked for).
    pub dv: Vec<f64>,
}

impl Grid {
    fn with_capacity(count: usize, derivs: bool) -> Grid {
        Grid {
            points: Vec::with_capacity(3 * count),
            du: Vec::with_capacity(if derivs { 3 * count } else { 0 }),
            dv: Vec::with_capacity(if derivs { 3 * count } else { 0 }),
        }
    }
    fn push(&mut self, p: [DVec3; 3], derivs: bool) {
        self.points.extend_from_slice(&p[0].to_array());
        if derivs {
            self.du.extend_from_slice(&p[1].to_array());
            self.dv.extend_from_slice(&p[2].to_array());
        }
    }
    /// ‖A − B‖∞ over all coordinates of two grids of the same size.
    pub fn max_difference(&self, other: &Grid) -> f64 {
        self.points
            .iter()
            .zip(&other.points)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max)
    }
}

/// Surfaces that evaluate whole grids; the default is point by point.
pub trait GridSurface: Surface<DVec3> {
    /// The u-major grid `us × vs` (with first partials when `derivs`).
    fn eval_grid(&self, us: &[f64], vs: &[f64], derivs: bool) -> Grid {
        let mut g = Grid::with_capacity(us.len() * vs.len(), derivs);
        let mut out = [DVec3::ZERO; 3];
        for &u in us {
            for &v in vs {
                self.eval_derivs(u, v, derivs, &mut out);
                g.push(out, derivs);
            }
        }
        g
    }
}

/// Grid evaluation of a tensor-product B-spline surface: the kernel's grid sampler
/// ([`crate::kernel::TensorGrid`]: bases once per grid line, isocurve control points per u-line).
pub fn bspline_grid(s: &BSplineSurface<DVec3>, us: &[f64], vs: &[f64], derivs: bool) -> Grid {
    let (points, du, dv) = crate::sample::eval_surface_grid(s, us, vs, derivs);
    Grid { points, du, dv }
}

impl GridSurface for BSplineSurface<DVec3> {
    fn eval_grid(&self, us: &[f64], vs: &[f64], derivs: bool) -> Grid {
        bspline_grid(self, us, vs, derivs)
    }
}

impl GridSurface for GordonSurface {
    fn eval_grid(&self, us: &[f64], vs: &[f64], derivs: bool) -> Grid {
        bspline_grid(self.surface(), us, vs, derivs)
    }
}

impl<N: LineNetwork> GridSurface for SplineBlendedSurface<N> {
    fn eval_grid(&self, us: &[f64], vs: &[f64], derivs: bool) -> Grid {
        let (nu, nv) = (us.len(), vs.len());
        let (mr, ms) = (self.blend_u().len(), self.blend_v().len());
        let order = usize::from(derivs);
        // per grid line: the network curves and the blending functions (value, derivative)
        let mut phi = vec![[DVec3::ZERO; 2]; nv * mr]; // [b][r]
        for (b, &v) in vs.iter().enumerate() {
            self.lines()
                .v_curves(v, derivs, &mut |r, p, d| phi[b * mr + r] = [p, d]);
        }
        let mut psi = vec![[DVec3::ZERO; 2]; nu * ms]; // [a][s]
        for (a, &u) in us.iter().enumerate() {
            self.lines()
                .u_curves(u, derivs, &mut |s, p, d| psi[a * ms + s] = [p, d]);
        }
        let mut lu = vec![[0.0; 2]; nu * mr]; // [a][r]
        for (a, &u) in us.iter().enumerate() {
            let basis = self.blend_u().basis(u, order);
            for r in 0..mr {
                let l = self.blend_u().value(r, &basis);
                lu[a * mr + r] = [l[0], l[1]];
            }
        }
        let mut mv = vec![[0.0; 2]; nv * ms]; // [b][s]
        for (b, &v) in vs.iter().enumerate() {
            let basis = self.blend_v().basis(v, order);
            for s in 0..ms {
                let l = self.blend_v().value(s, &basis);
                mv[b * ms + s] = [l[0], l[1]];
            }
        }
        let g12 = bspline_grid(self.g12(), us, vs, derivs);
        let mut g = Grid::with_capacity(nu * nv, derivs);
        for a in 0..nu {
            for b in 0..nv {
                let k = a * nv + b;
                let mut out = [DVec3::ZERO; 3];
                for r in 0..mr {
                    let [p, dp] = phi[b * mr + r];
                    let [l, dl] = lu[a * mr + r];
                    out[0] += p * l;
                    if derivs {
                        out[1] += p * dl;
                        out[2] += dp * l;
                    }
                }
                for s in 0..ms {
                    let [p, dp] = psi[a * ms + s];
                    let [m, dm] = mv[b * ms + s];
                    out[0] += p * m;
                    if derivs {
                        out[1] += dp * m;
                        out[2] += p * dm;
                    }
                }
                out[0] -= DVec3::from_slice(&g12.points[3 * k..]);
                if derivs {
                    out[1] -= DVec3::from_slice(&g12.du[3 * k..]);
                    out[2] -= DVec3::from_slice(&g12.dv[3 * k..]);
                }
                g.push(out, derivs);
            }
        }
        g
    }
}

impl GridSurface for crate::thin_plate::ThinPlateSurface {
    fn eval_grid(&self, us: &[f64], vs: &[f64], derivs: bool) -> Grid {
        bspline_grid(self.bspline(), us, vs, derivs)
    }
}

/// The criss-cross surface S is evaluated point by point (its local cell form is already cheap).
impl GridSurface for crate::criss_cross::CrissCrossSurface {}
