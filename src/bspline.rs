//! B-splines: Cox–de Boor basis functions and their derivatives, de Boor evaluation of curves and
//! tensor-product surfaces, and global interpolation (used for skinning by the Gordon surface).
//!
//! Basis functions follow the Cox–de Boor recursion N_{i,0} = 1 on [t_i, t_{i+1}),
//! N_{i,p} = (u − t_i)/(t_{i+p} − t_i)·N_{i,p−1} + (t_{i+p+1} − u)/(t_{i+p+1} − t_{i+1})·N_{i+1,p−1}
//! with 0/0 := 0; derivatives by Piegl–Tiller A2.3. Conventions for spans are in [`crate::knots`].

use crate::error::{Error, Result};
use crate::kernel::PiecewisePoly;
use crate::knots::{self, find_span, MAX_DEGREE};
use crate::linalg::Matrix;
use crate::point::Point;
use crate::sample::{Curve, Surface};

const W: usize = MAX_DEGREE + 1;

/// The non-zero basis functions on span `span` and their derivatives up to `order` (≤ 2) at `u`:
/// `ders[k][r]` = N^{(k)}_{span−p+r, p}(u), r = 0..=p. Allocation-free (Piegl–Tiller A2.3).
pub fn basis_derivs(
    knots: &[f64],
    degree: usize,
    span: usize,
    u: f64,
    order: usize,
    ders: &mut [[f64; W]; 3],
) {
    // work arrays sized for the degree: zeroing a 25 × 25 table per call cost more than the recursion
    if degree < 4 {
        basis_derivs_sized::<4>(knots, degree, span, u, order, ders)
    } else if degree < 8 {
        basis_derivs_sized::<8>(knots, degree, span, u, order, ders)
    } else {
        basis_derivs_sized::<W>(knots, degree, span, u, order, ders)
    }
}

/// [`basis_derivs`] with work arrays of `M > degree` entries.
#[inline(always)]
fn basis_derivs_sized<const M: usize>(
    knots: &[f64],
    degree: usize,
    span: usize,
    u: f64,
    order: usize,
    ders: &mut [[f64; W]; 3],
) {
    let p = degree;
    let order = order.min(2).min(p);
    let mut ndu = [[0.0_f64; M]; M];
    let mut left = [0.0_f64; M];
    let mut right = [0.0_f64; M];
    ndu[0][0] = 1.0;
    for j in 1..=p {
        left[j] = u - knots[span + 1 - j];
        right[j] = knots[span + j] - u;
        let mut saved = 0.0;
        for r in 0..j {
            ndu[j][r] = right[r + 1] + left[j - r];
            let temp = if ndu[j][r] != 0.0 {
                ndu[r][j - 1] / ndu[j][r]
            } else {
                0.0
            };
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    for k in 0..3 {
        for r in 0..=p {
            ders[k][r] = 0.0;
        }
    }
    for j in 0..=p {
        ders[0][j] = ndu[j][p];
    }
    if order == 0 {
        return;
    }
    let mut a = [[0.0_f64; M]; 2];
    for r in 0..=p {
        let (mut s1, mut s2) = (0usize, 1usize);
        a[0][0] = 1.0;
        for k in 1..=order {
            let mut d = 0.0;
            let rk = r as isize - k as isize;
            let pk = p - k;
            if r >= k {
                let rk = rk as usize;
                a[s2][0] = if ndu[pk + 1][rk] != 0.0 {
                    a[s1][0] / ndu[pk + 1][rk]
                } else {
                    0.0
                };
                d = a[s2][0] * ndu[rk][pk];
            }
            let j1 = if rk >= -1 { 1 } else { (-rk) as usize };
            let j2 = if (r as isize - 1) <= pk as isize {
                k - 1
            } else {
                p - r
            };
            for j in j1..=j2 {
                let idx = (rk + j as isize) as usize;
                a[s2][j] = if ndu[pk + 1][idx] != 0.0 {
                    (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][idx]
                } else {
                    0.0
                };
                d += a[s2][j] * ndu[idx][pk];
            }
            if r <= pk {
                a[s2][k] = if ndu[pk + 1][r] != 0.0 {
                    -a[s1][k - 1] / ndu[pk + 1][r]
                } else {
                    0.0
                };
                d += a[s2][k] * ndu[r][pk];
            }
            ders[k][r] = d;
            std::mem::swap(&mut s1, &mut s2);
        }
    }
    let mut f = p as f64;
    for k in 1..=order {
        for r in 0..=p {
            ders[k][r] *= f;
        }
        f *= (p - k) as f64;
    }
}

/// All `count = knots.len() − degree − 1` basis functions N_{i,p} and derivatives up to `order` at `u`
/// (right-hand piece at knots, last piece at and beyond the end). `out[k]` has `count` entries.
pub fn basis_all(knots: &[f64], degree: usize, u: f64, order: usize, out: &mut [Vec<f64>; 3]) {
    let count = knots.len() - degree - 1;
    let span = find_span(knots, degree, count, u);
    let mut ders = [[0.0; W]; 3];
    basis_derivs(knots, degree, span, u, order, &mut ders);
    for (k, row) in out.iter_mut().enumerate() {
        row.clear();
        row.resize(count, 0.0);
        if k <= order {
            for r in 0..=degree {
                row[span - degree + r] = ders[k][r];
            }
        }
    }
}

/// A B-spline curve of degree `p` with a full knot vector (`points + p + 1` knots).
///
/// # Template
/// * **What**: the polynomial B-spline curve Σ N_{i,p}(u) P_i, with the Cox–de Boor basis (de Boor 1972;
///   Piegl–Tiller eq. (2.5)); the kernel every polynomial construction of the five papers reduces to.
/// * **Interpolates**: its end control points when the knot vector is clamped (end knots of multiplicity
///   p + 1); otherwise nothing.
/// * **Continuity**: C^{p−μ} at a knot of multiplicity μ, polynomial between knots.
/// * **Parametrisation**: u ∈ [t_p, t_{n+1}] (n + 1 points); the right-hand piece at an interior knot.
///
/// # Example
/// ```
/// use glam::DVec2;
/// use splinelab::{bspline::BSplineCurve, Curve};
/// let pts = vec![DVec2::new(0.0, 0.0), DVec2::new(1.0, 2.0), DVec2::new(3.0, 2.0), DVec2::new(4.0, 0.0)];
/// let c = BSplineCurve::new(3, vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0], pts.clone())?;
/// assert_eq!(c.domain(), (0.0, 1.0));
/// assert!((c.eval(0.0) - pts[0]).length() < 1e-15 && (c.eval(1.0) - pts[3]).length() < 1e-15);
/// // one Bézier piece: the end tangent is 3 (P1 − P0)
/// let mut d = [DVec2::ZERO; 3];
/// c.eval_derivs(0.0, 1, &mut d);
/// assert!((d[1] - 3.0 * (pts[1] - pts[0])).length() < 1e-12);
/// # Ok::<(), splinelab::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineCurve<P: Point> {
    degree: usize,
    knots: Vec<f64>,
    points: Vec<P>,
}

impl<P: Point> BSplineCurve<P> {
    /// Validates and builds the curve (see [`knots::validate`]; control points must be finite).
    pub fn new(degree: usize, knots: Vec<f64>, points: Vec<P>) -> Result<Self> {
        if let Some(i) = points.iter().position(|p| !p.is_finite()) {
            return Err(Error::not_finite(
                format!("points[{i}]"),
                "expected finite coordinates",
            ));
        }
        knots::validate("knots", &knots, degree, points.len())?;
        Ok(BSplineCurve {
            degree,
            knots,
            points,
        })
    }

    /// A clamped curve with uniform interior knots on `[0, 1]`.
    pub fn clamped_uniform(degree: usize, points: Vec<P>) -> Result<Self> {
        if points.len() < degree + 1 {
            return Err(Error::too_few(
                "points",
                format!(
                    "need at least {} control points for degree {degree}, got {}",
                    degree + 1,
                    points.len()
                ),
            ));
        }
        let k = knots::clamped_uniform(points.len(), degree, 0.0, 1.0);
        Self::new(degree, k, points)
    }

    /// The polynomial degree.
    pub fn degree(&self) -> usize {
        self.degree
    }
    /// The knot vector.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }
    /// The control points.
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The point at `u` by de Boor's algorithm (independent of the basis-function path; used to test it).
    pub fn de_boor(&self, u: f64) -> P {
        let p = self.degree;
        let k = find_span(&self.knots, p, self.points.len(), u);
        let mut d = [P::ZERO; W];
        d[..=p].copy_from_slice(&self.points[k - p..=k]);
        for r in 1..=p {
            for j in (r..=p).rev() {
                let i = j + k - p;
                let denom = self.knots[i + p + 1 - r] - self.knots[i];
                let a = if denom != 0.0 {
                    (u - self.knots[i]) / denom
                } else {
                    0.0
                };
                d[j] = d[j - 1] * (1.0 - a) + d[j] * a;
            }
        }
        d[p]
    }

    /// The blossom (polar form) of the piece on span `span` at the arguments `args` (`degree` of them):
    /// de Boor's algorithm with a different argument at each level. `blossom(u, …, u)` is the point at u.
    pub fn blossom(&self, span: usize, args: &[f64]) -> P {
        let p = self.degree;
        let mut d = [P::ZERO; W];
        d[..=p].copy_from_slice(&self.points[span - p..=span]);
        for r in 1..=p {
            let u = args[r - 1];
            for j in (r..=p).rev() {
                let i = j + span - p;
                let denom = self.knots[i + p + 1 - r] - self.knots[i];
                let a = if denom != 0.0 {
                    (u - self.knots[i]) / denom
                } else {
                    0.0
                };
                d[j] = d[j - 1] * (1.0 - a) + d[j] * a;
            }
        }
        d[p]
    }

    /// Evaluates the curve at `count` uniform parameters over its domain (ends included) into `out`
    /// (`count * DIM` coordinates; shorter buffers are filled as far as they go), fast: through the
    /// kernel's [`PiecewisePoly`] (each span converted once to the power basis in its local parameter, then
    /// forward differences for cubics, Horner otherwise, over the run of samples that fall in it). The
    /// parameters are exactly those of [`crate::sample::uniform_params`]; agrees with [`Curve::eval`] to
    /// rounding (≈1e-13 relative).
    pub fn sample_uniform_into(&self, count: usize, out: &mut [f64]) {
        match self.to_piecewise() {
            Some(pp) => pp.sample_uniform_into(count, out),
            None => {
                let (a, b) = self.domain();
                let params = crate::sample::uniform_params(a, b, count.min(out.len() / P::DIM));
                crate::sample::eval_curve_generic_into(self, &params, 0, out, &mut [], &mut []);
            }
        }
    }

    /// The curve as a piecewise polynomial in the power basis (one piece per non-empty span), or `None`
    /// above [`crate::kernel::MAX_FAST_DEGREE`].
    pub fn to_piecewise(&self) -> Option<PiecewisePoly<P>> {
        let p = self.degree;
        if p > crate::kernel::MAX_FAST_DEGREE {
            return None;
        }
        let n = self.points.len();
        let mut pp = PiecewisePoly::with_degree(p, self.knots[p]);
        let mut coef = [P::ZERO; W];
        for span in p..n {
            let (t0, t1) = (self.knots[span], self.knots[span + 1]);
            if t1 <= t0 {
                continue;
            }
            self.power_coefficients(span, &mut coef);
            pp.push_segment(t1, &coef);
        }
        if pp.segments() == 0 {
            return None;
        }
        Some(pp)
    }

    /// The power-basis coefficients c_0..c_p of the piece on `span` in its local parameter
    /// t = (u − t_span)/(t_{span+1} − t_span): c_k = f^{(k)}(t_span) h^k / k!, the k-th derivative taken
    /// from the derivative control points R^{(k)}_j = (q + 1)(R^{(k−1)}_j − R^{(k−1)}_{j−1})/(t_{j+q+1} − t_j)
    /// (q = p − k) by de Boor's algorithm at t_span. Differences of control points keep the rounding error
    /// relative to the curve's local size (not to its distance from the origin), also on short spans.
    fn power_coefficients(&self, span: usize, coef: &mut [P; W]) {
        let p = self.degree;
        let t = &self.knots;
        let u = t[span];
        let h = t[span + 1] - u;
        // r[j - (span - p)] = R^{(k)}_j for j = span − q ..= span (stored right-aligned)
        let mut r = [P::ZERO; W];
        r[..=p].copy_from_slice(&self.points[span - p..=span]);
        let mut fact_h = 1.0; // h^k / k!
        for k in 0..=p {
            let q = p - k;
            if k > 0 {
                for idx in (k..=p).rev() {
                    let j = span - p + idx;
                    r[idx] = (r[idx] - r[idx - 1]) * ((q + 1) as f64 / (t[j + q + 1] - t[j]));
                }
                fact_h *= h / k as f64;
            }
            // de Boor for degree q on the span, at u = t_span, points r[k..=p]
            let mut d = [P::ZERO; W];
            d[..=q].copy_from_slice(&r[k..=p]);
            for lvl in 1..=q {
                for jj in (lvl..=q).rev() {
                    let i = jj + span - q;
                    let denom = t[i + q + 1 - lvl] - t[i];
                    let a = if denom != 0.0 {
                        (u - t[i]) / denom
                    } else {
                        0.0
                    };
                    d[jj] = d[jj - 1] * (1.0 - a) + d[jj] * a;
                }
            }
            coef[k] = d[q] * fact_h;
        }
    }

    /// Inserts the knot `u` once; the curve is unchanged.
    pub fn insert_knot(&self, u: f64) -> Result<Self> {
        let (k, c) = knots::insert_knot(self.degree, &self.knots, &self.points, u)?;
        Ok(BSplineCurve {
            degree: self.degree,
            knots: k,
            points: c,
        })
    }

    /// Inserts all of `extra`; the curve is unchanged.
    pub fn refine(&self, extra: &[f64]) -> Result<Self> {
        let (k, c) = knots::refine(self.degree, &self.knots, &self.points, extra)?;
        Ok(BSplineCurve {
            degree: self.degree,
            knots: k,
            points: c,
        })
    }
}

impl<P: Point> Curve<P> for BSplineCurve<P> {
    fn domain(&self) -> (f64, f64) {
        (self.knots[self.degree], self.knots[self.points.len()])
    }

    fn piecewise(&self) -> Option<PiecewisePoly<P>> {
        self.to_piecewise()
    }

    fn eval_derivs(&self, u: f64, order: usize, out: &mut [P; 3]) {
        let p = self.degree;
        let span = find_span(&self.knots, p, self.points.len(), u);
        let mut ders = [[0.0; W]; 3];
        basis_derivs(&self.knots, p, span, u, order, &mut ders);
        for (k, o) in out.iter_mut().enumerate().take(order.min(2) + 1) {
            let mut acc = P::ZERO;
            for r in 0..=p {
                acc += self.points[span - p + r] * ders[k][r];
            }
            *o = acc;
        }
    }
}

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
        crate::kernel::TensorGrid::sample_into(self, us, vs, derivs, points, du, dv)
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

/// Global interpolation (Piegl–Tiller §9.2.1): the control points of the degree-`p` B-spline on
/// `knots` (`params.len() + p + 1` of them) that passes through `data[k]` at `params[k]`.
/// Solves the collocation system; a singular system (Schoenberg–Whitney violated) is a `Degenerate` error.
pub fn interpolate<P: Point>(
    degree: usize,
    knots: &[f64],
    params: &[f64],
    data: &[P],
) -> Result<Vec<P>> {
    let n = data.len();
    if params.len() != n {
        return Err(Error::size_mismatch(
            "params",
            format!("{} parameters for {n} data points", params.len()),
        ));
    }
    knots::validate("knots", knots, degree, n)?;
    let mut m = Matrix::zeros(n);
    let mut ders = [[0.0; W]; 3];
    for (row, &t) in params.iter().enumerate() {
        let span = find_span(knots, degree, n, t);
        basis_derivs(knots, degree, span, t, 0, &mut ders);
        for r in 0..=degree {
            m.set(row, span - degree + r, ders[0][r]);
        }
    }
    // solve, then one step of iterative refinement: chord-length parameters of very unevenly spaced data
    // make the collocation matrix ill-conditioned (found by tests/fuzz_core.rs)
    let lu = m.lu("params")?; // factorised once, used for the solve and the refinement
    let mut c = data.to_vec();
    lu.solve(&mut c);
    let residual = |c: &[P]| -> Vec<P> {
        (0..n)
            .map(|row| data[row] - (0..n).fold(P::ZERO, |acc, j| acc + c[j] * m.get(row, j)))
            .collect()
    };
    let mut r = residual(&c);
    lu.solve(&mut r);
    for (ci, di) in c.iter_mut().zip(&r) {
        *ci += *di;
    }
    let scale = data.iter().map(|p| p.max_abs()).fold(1.0, f64::max);
    let worst = residual(&c).iter().map(|p| p.max_abs()).fold(0.0, f64::max);
    if !(worst <= 1e-9 * scale) {
        return Err(Error::degenerate(
            "params",
            format!("interpolation is too ill-conditioned (residual {worst:.3e} for data of size {scale:.3e}): the parameters are nearly coincident"),
        ));
    }
    Ok(c)
}

/// Interpolating curve through `data` with chord-length parameters and averaging knots (degree `p`).
pub fn interpolate_chord<P: Point>(degree: usize, data: &[P]) -> Result<BSplineCurve<P>> {
    if data.len() < degree + 1 {
        return Err(Error::too_few(
            "points",
            format!(
                "need at least {} points for degree {degree}, got {}",
                degree + 1,
                data.len()
            ),
        ));
    }
    let t = knots::chord_length_params("points", data)?;
    let k = knots::averaging(&t, degree);
    let c = interpolate(degree, &k, &t, data)?;
    BSplineCurve::new(degree, k, c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DVec2, DVec3};

    /// The cubic fast path uses forward differences re-anchored every 16 samples: with many samples per span
    /// (where rounding would build up) it still agrees with de Boor evaluation to 1e-12 relative, in 2D and 3D,
    /// on non-uniform knots with a double knot; every sample is written.
    #[test]
    fn forward_differences_stay_exact_over_long_runs() {
        let knots = vec![0.0, 0.0, 0.0, 0.0, 0.1, 0.35, 0.35, 0.8, 1.0, 1.0, 1.0, 1.0];
        let pts2: Vec<DVec2> = (0..8)
            .map(|i| {
                DVec2::new(
                    (i as f64 * 0.7).cos() * 3.0,
                    (i as f64 * 1.3).sin() * 5.0 + 100.0,
                )
            })
            .collect();
        let c2 = BSplineCurve::new(3, knots.clone(), pts2).unwrap();
        let pts3: Vec<DVec3> = (0..8)
            .map(|i| DVec3::new(i as f64, (i as f64).sqrt(), -(i as f64 * 0.4).sin()))
            .collect();
        let c3 = BSplineCurve::new(3, knots, pts3).unwrap();
        for count in [1usize, 2, 3, 17, 33, 1000, 100_003] {
            let params = crate::sample::uniform_params(0.0, 1.0, count);
            let mut out = vec![f64::NAN; 2 * count];
            c2.sample_uniform_into(count, &mut out);
            for (i, &u) in params.iter().enumerate() {
                let e = c2.de_boor(u);
                let f = DVec2::new(out[2 * i], out[2 * i + 1]);
                assert!(
                    (e - f).length() <= 1e-12 * e.length(),
                    "2D count {count} u {u}: {e} vs {f}"
                );
            }
            let mut out = vec![f64::NAN; 3 * count];
            c3.sample_uniform_into(count, &mut out);
            for (i, &u) in params.iter().enumerate() {
                let e = c3.de_boor(u);
                let f = DVec3::new(out[3 * i], out[3 * i + 1], out[3 * i + 2]);
                assert!(
                    (e - f).length() <= 1e-12 * (1.0 + e.length()),
                    "3D count {count} u {u}: {e} vs {f}"
                );
            }
        }
    }
}
