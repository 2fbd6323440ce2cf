//! Tensor-product quasi-cubic surfaces (the quasi-cubic paper Eq. (6)) and blended interpolation surfaces
//! (the quasi-cubic paper Eqs. (21)–(30), Remark 2, Figs. 13, 16, 17).
//!
//! **Tensor product.** `grid[i][j]` = b_ij, (m+3) × (n+3) points (stored row-major, i along u), domain
//! [0, m] × [0, n]; patch (i, j) = (min(⌊u⌋, m−1), min(⌊v⌋, n−1)) is Σ_{a,b} B_a(α; s) B_b(α; t) b_{i+a, j+b}.
//! A direction may be **periodic**: then it has N ≥ 4 points, N patches, and indices wrap mod N
//! (full surfaces of revolution: sphere, cylinder, torus).
//!
//! **Blended interpolation surface.** The seed's formulas (21)–(27) are lost in the text; what survives
//! (Eq. (23): L_{i,j} takes the four corner values b_{i+1,j+1}, b_{i+2,j+1}, b_{i+1,j+2}, b_{i+2,j+2};
//! Eq. (28): BIS_{i,j} interpolates them; Eq. (30): β_{i,j}(1, v) = β_{i+1,j}(0, v); β*_{i+m,j+n}, m, n = 1, 2
//! belong to the corner points) fixes this reading, the tensor analogue of the curve BIS:
//! * p_{i,j}(s, t): the tensor α-surface on the 4 × 4 control points of the patch (α = 3: the
//!   interpolation surface, Eq. (20)),
//! * L_{i,j}(s, t) = Σ_{m,n∈{0,1}} w_m(s) w_n(t) b_{i+1+m, j+1+n}, with w_0 = 1 − s(·), w_1 = s(·) (the
//!   allocated function of order k blended in both directions),
//! * β_{i,j}(s, t) = Σ w_m(s) w_n(t) β*_{i+m, j+n},
//! * BIS_{i,j} = L_{i,j} + β_{i,j}·(p_{i,j} − L_{i,j}).
//!
//! Indices are in the 0-based grid layout of this module: the grid holds b_{−1..m+1, −1..n+1}, the
//! interpolated points are `grid[i+1][j+1]` at (u, v) = (i, j), and `beta[i][j]` (m+1 × n+1) belongs to
//! that point. Because L and β have vanishing u-derivatives up to order k−1 across u = const joints
//! (and likewise in v), the cross-boundary derivatives are β·∂p, and the surface is C² for k ≥ 3 (C¹ for
//! k = 2). With α ≠ 3 this is Remark 2's blended surface (Figs. 16, 17: α = 0.6, β* = 0..0.9), which passes
//! through the control points only where β* = 0.

use super::basis::{allocated, basis_derivs, check_alpha, check_order};
use super::bis::check_beta;
use super::curve::{check_points, locate};
use crate::error::{Error, Result};
use crate::point::Point;
use crate::sample::Surface;

/// A tensor-product quasi-cubic surface.
#[derive(Debug, Clone, PartialEq)]
pub struct QuasiCubicSurface<P: Point> {
    alpha: f64,
    rows: usize,
    cols: usize,
    grid: Vec<P>,
    periodic: (bool, bool),
}

fn check_grid<P: Point>(
    rows: usize,
    cols: usize,
    grid: &[P],
    periodic: (bool, bool),
) -> Result<()> {
    check_points("grid", grid)?;
    if grid.len() != rows * cols {
        return Err(Error::size_mismatch(
            "grid",
            format!(
                "expected {rows} × {cols} = {} points, got {}",
                rows * cols,
                grid.len()
            ),
        ));
    }
    for (field, count, per) in [("grid", rows, periodic.0), ("grid[0]", cols, periodic.1)] {
        if count < 4 {
            let what = if field == "grid" {
                "rows"
            } else {
                "points per row"
            };
            let detail = if per {
                format!("a periodic direction needs at least 4 {what}, got {count}")
            } else {
                format!("need at least 4 {what} (m + 3 with m ≥ 1 patch), got {count}")
            };
            return Err(Error::too_few(field, detail));
        }
    }
    Ok(())
}

impl<P: Point> QuasiCubicSurface<P> {
    /// A surface from `grid` (row-major, `rows` × `cols`, row i along u), shape parameter α ∈ [−3, 3], and
    /// periodicity per direction `(u, v)`.
    pub fn new(
        alpha: f64,
        rows: usize,
        cols: usize,
        grid: Vec<P>,
        periodic: (bool, bool),
    ) -> Result<Self> {
        check_alpha("alpha", alpha)?;
        check_grid(rows, cols, &grid, periodic)?;
        Ok(QuasiCubicSurface {
            alpha,
            rows,
            cols,
            grid,
            periodic,
        })
    }

    /// The shape parameter α.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }
    /// Patches (m, n).
    pub fn patches(&self) -> (usize, usize) {
        (
            if self.periodic.0 {
                self.rows
            } else {
                self.rows - 3
            },
            if self.periodic.1 {
                self.cols
            } else {
                self.cols - 3
            },
        )
    }
    /// The control net size (rows, cols).
    pub fn size(&self) -> (usize, usize) {
        (self.rows, self.cols)
    }
    /// The control point (i, j), indices taken modulo the size (periodic nets).
    pub fn point(&self, i: usize, j: usize) -> P {
        self.grid[(i % self.rows) * self.cols + (j % self.cols)]
    }

    /// The partial derivative ∂^{a+b}S/∂u^a∂v^b (a, b ≤ 3) at (u, v).
    pub fn partial(&self, u: f64, v: f64, a: usize, b: usize) -> P {
        let (m, n) = self.patches();
        let (i, s) = locate(u, m, self.periodic.0);
        let (j, t) = locate(v, n, self.periodic.1);
        self.patch_partial(i, j, s, t, a, b)
    }

    /// ∂^{a+b} of patch (i, j) at local (s, t) (one-sided values at the patch borders).
    pub fn patch_partial(&self, i: usize, j: usize, s: f64, t: f64, a: usize, b: usize) -> P {
        let bu = super::basis::basis_deriv(self.alpha, s, a.min(3));
        let bv = super::basis::basis_deriv(self.alpha, t, b.min(3));
        let mut acc = P::ZERO;
        for (r, wu) in bu.iter().enumerate() {
            let mut row = P::ZERO;
            for (c, wv) in bv.iter().enumerate() {
                row += self.point(i + r, j + c) * *wv;
            }
            acc += row * *wu;
        }
        acc
    }
}

impl<P: Point> Surface<P> for QuasiCubicSurface<P> {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        let (m, n) = self.patches();
        ((0.0, m as f64), (0.0, n as f64))
    }
    /// A periodic direction repeats after its N patches.
    fn periods(&self) -> (Option<f64>, Option<f64>) {
        let (m, n) = self.patches();
        (
            self.periodic.0.then_some(m as f64),
            self.periodic.1.then_some(n as f64),
        )
    }
    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [P; 3]) {
        let (m, n) = self.patches();
        let (i, s) = locate(u, m, self.periodic.0);
        let (j, t) = locate(v, n, self.periodic.1);
        let mut bu = [[0.0; 4]; 4];
        let mut bv = [[0.0; 4]; 4];
        let order = usize::from(derivs);
        basis_derivs(self.alpha, s, order, &mut bu);
        basis_derivs(self.alpha, t, order, &mut bv);
        let mut p = P::ZERO;
        let mut pu = P::ZERO;
        let mut pv = P::ZERO;
        for (r, (&w0, &w1)) in bu[0].iter().zip(&bu[1]).enumerate() {
            let mut row = P::ZERO;
            let mut row_v = P::ZERO;
            for (c, (&v0, &v1)) in bv[0].iter().zip(&bv[1]).enumerate() {
                let q = self.point(i + r, j + c);
                row += q * v0;
                if derivs {
                    row_v += q * v1;
                }
            }
            p += row * w0;
            if derivs {
                pu += row * w1;
                pv += row_v * w0;
            }
        }
        out[0] = p;
        if derivs {
            out[1] = pu;
            out[2] = pv;
        }
    }

    /// The grid sampler: basis rows once per grid line (one trigonometric basis evaluation per u and per
    /// v, not per point), per u-line the isocurve's control points Σ_r B_r(s)·P_{i+r, c} (and with ∂/∂u),
    /// then four-term sums per point.
    fn sample_grid_into(
        &self,
        us: &[f64],
        vs: &[f64],
        derivs: bool,
        points: &mut [f64],
        du: &mut [f64],
        dv: &mut [f64],
    ) {
        let (m, n) = self.patches();
        let order = usize::from(derivs);
        let dim = P::DIM;
        // v-lines: segment and basis rows
        let vrows: Vec<(usize, [[f64; 4]; 4])> = vs
            .iter()
            .map(|&v| {
                let (j, t) = locate(v, n, self.periodic.1);
                let mut b = [[0.0; 4]; 4];
                basis_derivs(self.alpha, t, order, &mut b);
                (j, b)
            })
            .collect();
        let cols = self.cols;
        let mut iso = vec![P::ZERO; cols];
        let mut iso_u = vec![P::ZERO; if derivs { cols } else { 0 }];
        let mut k = 0;
        for &u in us {
            let (i, s) = locate(u, m, self.periodic.0);
            let mut bu = [[0.0; 4]; 4];
            basis_derivs(self.alpha, s, order, &mut bu);
            for c in 0..cols {
                let (mut a, mut b) = (P::ZERO, P::ZERO);
                for r in 0..4 {
                    let q = self.point(i + r, c);
                    a += q * bu[0][r];
                    if derivs {
                        b += q * bu[1][r];
                    }
                }
                iso[c] = a;
                if derivs {
                    iso_u[c] = b;
                }
            }
            for (j, bv) in &vrows {
                let (mut p, mut pu, mut pv) = (P::ZERO, P::ZERO, P::ZERO);
                for c in 0..4 {
                    let q = iso[(j + c) % cols];
                    p += q * bv[0][c];
                    if derivs {
                        pu += iso_u[(j + c) % cols] * bv[0][c];
                        pv += q * bv[1][c];
                    }
                }
                p.write_coords(&mut points[k * dim..]);
                if derivs {
                    pu.write_coords(&mut du[k * dim..]);
                    pv.write_coords(&mut dv[k * dim..]);
                }
                k += 1;
            }
        }
    }
}

/// A blended interpolation surface (module docs for the definition and the reading of the seed).
#[derive(Debug, Clone, PartialEq)]
pub struct BisSurface<P: Point> {
    tensor: QuasiCubicSurface<P>,
    beta: Vec<f64>,
    k: usize,
}

impl<P: Point> BisSurface<P> {
    /// `grid` (row-major, `rows` × `cols` = (m+3) × (n+3), b_{−1..m+1, −1..n+1}), `beta` row-major
    /// (m+1) × (n+1) (`None`: all 1, the α = 3 interpolation surface), allocated order `k` (2..=10).
    pub fn new(
        rows: usize,
        cols: usize,
        grid: Vec<P>,
        beta: Option<Vec<f64>>,
        k: usize,
    ) -> Result<Self> {
        let tensor = QuasiCubicSurface::new(3.0, rows, cols, grid, (false, false))?;
        check_order("k", k)?;
        let len = (rows - 2) * (cols - 2);
        let beta = beta.unwrap_or_else(|| vec![1.0; len]);
        check_beta("beta", &beta, len)?;
        Ok(BisSurface { tensor, beta, k })
    }

    /// Remark 2 (Figs. 16, 17): blend the α-surface instead of the α = 3 one.
    pub fn with_alpha(mut self, alpha: f64) -> Result<Self> {
        check_alpha("alpha", alpha)?;
        self.tensor.alpha = alpha;
        Ok(self)
    }

    /// The shape parameter α.
    pub fn alpha(&self) -> f64 {
        self.tensor.alpha
    }
    /// β* row-major, (m+1) × (n+1).
    pub fn beta(&self) -> &[f64] {
        &self.beta
    }
    /// Patches (m, n) of the underlying tensor surface.
    pub fn patches(&self) -> (usize, usize) {
        self.tensor.patches()
    }
    /// The interpolated point at (u, v) = (i, j): `grid[i+1][j+1]`.
    pub fn data_point(&self, i: usize, j: usize) -> P {
        self.tensor.point(i + 1, j + 1)
    }

    fn beta_at(&self, i: usize, j: usize) -> f64 {
        let cols = self.tensor.cols - 2;
        self.beta[i * cols + j]
    }

    /// ∂^{a+b}BIS/∂u^a∂v^b (a, b ≤ 2) at (u, v).
    pub fn partial(&self, u: f64, v: f64, a: usize, b: usize) -> P {
        let (m, n) = self.patches();
        let (i, s) = locate(u, m, false);
        let (j, t) = locate(v, n, false);
        self.patch_partial(i, j, s, t, a, b)
    }

    /// ∂^{a+b} of patch (i, j) at local (s, t), a, b ≤ 2 (Leibniz rule on L + β·(p − L)).
    pub fn patch_partial(&self, i: usize, j: usize, s: f64, t: f64, a: usize, b: usize) -> P {
        let (a, b) = (a.min(2), b.min(2));
        let su = allocated(self.k, s);
        let sv = allocated(self.k, t);
        // w_m^{(d)}: w_0 = 1 − s, w_1 = s
        let w = |sa: &[f64; 4], d: usize| -> [f64; 2] {
            if d == 0 {
                [1.0 - sa[0], sa[0]]
            } else {
                [-sa[d], sa[d]]
            }
        };
        let lin = |da: usize, db: usize| -> P {
            let (wu, wv) = (w(&su, da), w(&sv, db));
            let mut acc = P::ZERO;
            for (mm, x) in wu.iter().enumerate() {
                for (nn, y) in wv.iter().enumerate() {
                    acc += self.tensor.point(i + 1 + mm, j + 1 + nn) * (x * y);
                }
            }
            acc
        };
        let bet = |da: usize, db: usize| -> f64 {
            let (wu, wv) = (w(&su, da), w(&sv, db));
            let mut acc = 0.0;
            for (mm, x) in wu.iter().enumerate() {
                for (nn, y) in wv.iter().enumerate() {
                    acc += self.beta_at(i + mm, j + nn) * x * y;
                }
            }
            acc
        };
        let binom = |n: usize, r: usize| -> f64 {
            match (n, r) {
                (2, 1) => 2.0,
                _ => 1.0,
            }
        };
        let mut acc = lin(a, b);
        for a1 in 0..=a {
            for b1 in 0..=b {
                let c = binom(a, a1) * binom(b, b1);
                let (da, db) = (a - a1, b - b1);
                let d = self.tensor.patch_partial(i, j, s, t, da, db) - lin(da, db);
                acc += d * (c * bet(a1, b1));
            }
        }
        acc
    }
}

impl<P: Point> Surface<P> for BisSurface<P> {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        self.tensor.domain()
    }
    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [P; 3]) {
        out[0] = self.partial(u, v, 0, 0);
        if derivs {
            out[1] = self.partial(u, v, 1, 0);
            out[2] = self.partial(u, v, 0, 1);
        }
    }

    /// The grid sampler: the tensor surface p through its own grid sampler (basis rows per grid line),
    /// the allocated weights once per grid line, then per point BIS = L + β·(p − L) and its first
    /// partials by the product rule (`∂BIS = ∂L + β·(∂p − ∂L) + ∂β·(p − L)`), the same formula as
    /// [`BisSurface::patch_partial`].
    fn sample_grid_into(
        &self,
        us: &[f64],
        vs: &[f64],
        derivs: bool,
        points: &mut [f64],
        du: &mut [f64],
        dv: &mut [f64],
    ) {
        self.tensor.sample_grid_into(us, vs, derivs, points, du, dv);
        let (m, n) = self.patches();
        let dim = P::DIM;
        // per grid line: the patch, the allocated weights w_0 = 1 − s, w_1 = s and their derivatives
        let line = |x: f64, count: usize| {
            let (i, s) = locate(x, count, false);
            let a = allocated(self.k, s);
            (i, [1.0 - a[0], a[0]], [-a[1], a[1]])
        };
        let vlines: Vec<_> = vs.iter().map(|&v| line(v, n)).collect();
        let read = |buf: &[f64], k: usize| P::from_coords(&buf[k * dim..]).unwrap_or(P::ZERO);
        let mut k = 0;
        for &u in us {
            let (i, wu, wu1) = line(u, m);
            for &(j, wv, wv1) in &vlines {
                let (mut l, mut lu, mut lv) = (P::ZERO, P::ZERO, P::ZERO);
                let (mut b, mut bu, mut bv) = (0.0, 0.0, 0.0);
                for r in 0..2 {
                    for c in 0..2 {
                        let q = self.tensor.point(i + 1 + r, j + 1 + c);
                        let beta = self.beta_at(i + r, j + c);
                        l += q * (wu[r] * wv[c]);
                        b += beta * wu[r] * wv[c];
                        if derivs {
                            lu += q * (wu1[r] * wv[c]);
                            lv += q * (wu[r] * wv1[c]);
                            bu += beta * wu1[r] * wv[c];
                            bv += beta * wu[r] * wv1[c];
                        }
                    }
                }
                let d = read(points, k) - l;
                (l + d * b).write_coords(&mut points[k * dim..]);
                if derivs {
                    let pu = read(du, k);
                    (lu + (pu - lu) * b + d * bu).write_coords(&mut du[k * dim..]);
                    let pv = read(dv, k);
                    (lv + (pv - lv) * b + d * bv).write_coords(&mut dv[k * dim..]);
                }
                k += 1;
            }
        }
    }
}
