//! [`BSplineSurface`]: tensor-product B-spline surfaces.

use super::{basis_derivs, W};
use crate::error::{Error, Result};
use crate::knots::{self, find_span};
use crate::point::Point;
use crate::sample::Surface;

/// A tensor-product B-spline surface; control points `points[i * nv + j]` (i along u, j along v).
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineSurface<P: Point> {
    degree_u: usize,
    degree_v: usize,
    knots_u: Vec<f64>,
    knots_v: Vec<f64>,
    nu: usize,
    nv: usize,
    points: Vec<P>,
}

impl<P: Point> BSplineSurface<P> {
    /// Validates and builds the surface from `nu × nv` control points, row-major in i (u).
    pub fn new(
        degree_u: usize,
        degree_v: usize,
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
        nu: usize,
        nv: usize,
        points: Vec<P>,
    ) -> Result<Self> {
        if points.len() != nu * nv {
            return Err(Error::size_mismatch(
                "points",
                format!("expected {nu} × {nv} control points, got {}", points.len()),
            ));
        }
        if let Some(i) = points.iter().position(|p| !p.is_finite()) {
            return Err(Error::not_finite(
                format!("points[{}][{}]", i / nv.max(1), i % nv.max(1)),
                "expected finite coordinates",
            ));
        }
        knots::validate("knotsU", &knots_u, degree_u, nu)?;
        knots::validate("knotsV", &knots_v, degree_v, nv)?;
        Ok(BSplineSurface {
            degree_u,
            degree_v,
            knots_u,
            knots_v,
            nu,
            nv,
            points,
        })
    }

    /// The degrees (in u, in v).
    pub fn degrees(&self) -> (usize, usize) {
        (self.degree_u, self.degree_v)
    }
    /// The knot vector in u.
    pub fn knots_u(&self) -> &[f64] {
        &self.knots_u
    }
    /// The knot vector in v.
    pub fn knots_v(&self) -> &[f64] {
        &self.knots_v
    }
    /// `(nu, nv)`.
    pub fn size(&self) -> (usize, usize) {
        (self.nu, self.nv)
    }
    /// Control points, row-major in u: index `i * nv + j`.
    pub fn points(&self) -> &[P] {
        &self.points
    }
    /// The surface's data as the kernel's grid sampler reads it.
    pub(crate) fn tensor_net(&self) -> crate::kernel::TensorNet<'_, P> {
        crate::kernel::TensorNet {
            knots: (&self.knots_u, &self.knots_v),
            degrees: (self.degree_u, self.degree_v),
            size: (self.nu, self.nv),
            points: &self.points,
        }
    }
    /// The control point (i, j): i along u, j along v.
    pub fn point(&self, i: usize, j: usize) -> P {
        self.points[i * self.nv + j]
    }

    /// Refines in u and v (inserting `extra_u`, `extra_v`); the surface is unchanged.
    pub fn refine(&self, extra_u: &[f64], extra_v: &[f64]) -> Result<Self> {
        // refine every column (fixed j) in u
        let mut cols: Vec<Vec<P>> = Vec::with_capacity(self.nv);
        let mut ku = self.knots_u.clone();
        for j in 0..self.nv {
            let col: Vec<P> = (0..self.nu).map(|i| self.point(i, j)).collect();
            let (k, c) = knots::refine(self.degree_u, &self.knots_u, &col, extra_u)?;
            ku = k;
            cols.push(c);
        }
        let nu2 = cols.first().map_or(self.nu, |c| c.len());
        let mut kv = self.knots_v.clone();
        let mut pts = Vec::new();
        let mut nv2 = self.nv;
        for i in 0..nu2 {
            let row: Vec<P> = cols.iter().map(|c| c[i]).collect();
            let (k, r) = knots::refine(self.degree_v, &self.knots_v, &row, extra_v)?;
            kv = k;
            nv2 = r.len();
            pts.extend(r);
        }
        Self::new(self.degree_u, self.degree_v, ku, kv, nu2, nv2, pts)
    }
}

impl<P: Point> Surface<P> for BSplineSurface<P> {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        (
            (self.knots_u[self.degree_u], self.knots_u[self.nu]),
            (self.knots_v[self.degree_v], self.knots_v[self.nv]),
        )
    }

    /// The kernel's grid sampler ([`crate::kernel::TensorGrid`]).
    fn sample_grid_into(
        &self,
        us: &[f64],
        vs: &[f64],
        derivs: bool,
        points: &mut [f64],
        du: &mut [f64],
        dv: &mut [f64],
    ) {
        crate::kernel::TensorGrid::sample_into(&self.tensor_net(), us, vs, derivs, points, du, dv)
    }

    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [P; 3]) {
        let (p, q) = (self.degree_u, self.degree_v);
        let su = find_span(&self.knots_u, p, self.nu, u);
        let sv = find_span(&self.knots_v, q, self.nv, v);
        let order = usize::from(derivs);
        let mut nu = [[0.0; W]; 3];
        let mut nv = [[0.0; W]; 3];
        basis_derivs(&self.knots_u, p, su, u, order, &mut nu);
        basis_derivs(&self.knots_v, q, sv, v, order, &mut nv);
        let (mut s, mut su_, mut sv_) = (P::ZERO, P::ZERO, P::ZERO);
        for a in 0..=p {
            let i = su - p + a;
            let (mut row0, mut row1) = (P::ZERO, P::ZERO);
            for b in 0..=q {
                let c = self.points[i * self.nv + sv - q + b];
                row0 += c * nv[0][b];
                if derivs {
                    row1 += c * nv[1][b];
                }
            }
            s += row0 * nu[0][a];
            if derivs {
                su_ += row0 * nu[1][a];
                sv_ += row1 * nu[0][a];
            }
        }
        out[0] = s;
        if derivs {
            out[1] = su_;
            out[2] = sv_;
        }
    }
}
