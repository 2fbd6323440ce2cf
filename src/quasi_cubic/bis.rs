//! The α = 3 interpolation spline and the blended interpolation spline (BIS) with local parameters β*
//! (the quasi-cubic paper §4, Eqs. (11)–(19), `curves.md` §1 and findings §1.2).
//!
//! Layout (binding): `P` = b_{−1}, b_0, …, b_n, b_{n+1} (n + 3 points, n ≥ 1), so `P[j+1] = b_j`; the curve
//! passes through b_j at u = j, j = 0..n, on u ∈ [0, n]. Global segment g = 0..n−1 (the paper's p_{g−1})
//! uses P[g..g+4] and blends the interpolated points b_g = P[g+1], b_{g+1} = P[g+2]:
//!
//! * p_g(t) = Σ_j B_j(3; t) P[g+j] (the α = 3 spline, Eq. (12)),
//! * L_g(t) = (1 − s(t)) b_g + s(t) b_{g+1} (Eq. (15)),
//! * β_g(t) = (1 − s(t)) β*_g + s(t) β*_{g+1} (Eq. (17)),
//! * BIS_g(t) = L_g(t) + β_g(t)·(p_g(t) − L_g(t)) (Eq. (18)),
//!
//! with the allocated function s of order k (Eq. (13)), default k = 3 (s = 10t³ − 15t⁴ + 6t⁵).
//! At u = j: BIS = b_j, BIS′ = β*_j·p′(j) = β*_j(π/2 − 1)(b_{j+1} − b_{j−1}); for k ≥ 3 also
//! BIS″ = β*_j·p″(j), so the curve is C². **k = 2 is accepted but the curve is only C¹**: s″(0) ≠ 0
//! makes L″ and β′ appear in BIS″ and the second derivative jumps at the joints (15.0 on the spec's
//! test data). β* ≡ 1 gives the α = 3 spline; β*_j = 0 gives a tangent of length 0 (a corner) at b_j.
//!
//! The quasi-cubic paper's Remark 2 blends the quasi-cubic B-spline of any α with the same L; [`Bis::with_alpha`]
//! gives that variant (it interpolates b_j only where β*_j = 0). The default is α = 3.
//!
//! **Curvature matching** ([`beta_curvature`], findings §1.2; the paper's Eq. (36) is garbled):
//! β*_j = (c1/c0²)·|b_j − b_{j−1}|·|b_{j+1} − b_j| / |b_{j+1} − b_{j−1}|², c0 = π/2 − 1, c1 = π²/4, makes the
//! BIS curvature at b_j equal the curvature K_j = 1/R_j of the circle through b_{j−1}, b_j, b_{j+1}.

use super::basis::{allocated, basis_derivs, check_alpha, check_order};
use super::curve::check_points;
use crate::error::{Error, Result};
use crate::point::Point;
use crate::sample::Curve;
use std::f64::consts::PI;

/// c0 = π/2 − 1: p′(j) = c0 (b_{j+1} − b_{j−1}) for the α = 3 spline.
pub const C0: f64 = PI / 2.0 - 1.0;
/// c1 = π²/4: p″(j) = c1 (b_{j−1} − 2b_j + b_{j+1}) for the α = 3 spline.
pub const C1: f64 = PI * PI / 4.0;

/// The default order of the allocated function (C²).
pub const DEFAULT_ORDER: usize = 3;

/// A blended interpolation spline (BIS).
///
/// # Template
/// * **What**: the blended interpolation spline of the quasi-cubic paper §4: BIS = L + β·(p − L) (eq. (18)), blending the
///   α = 3 interpolation spline p (eq. (12)) with the chords L (eq. (15)) by local parameters β*_j and the
///   allocated function s of order k (eq. (13)).
/// * **Interpolates**: b_0..b_n at u = 0..n, with BIS′(j) = β*_j·p′(j).
/// * **Continuity**: C¹ for k = 2, C² for k ≥ 3 (the default).
/// * **Parametrisation**: uniform, u ∈ [0, n], b_j at u = j.
///
/// # Example
/// ```
/// use glam::DVec2;
/// use splinelab::{quasi_cubic::Bis, Curve};
/// // b_{−1}, b_0..b_4, b_5
/// let p: Vec<DVec2> = (0..7).map(|i| DVec2::new(i as f64, (i as f64).sqrt())).collect();
/// let c = Bis::new(p.clone(), Some(vec![1.0, 0.5, 0.0, 2.0, 1.0]), 3)?;
/// assert_eq!(c.domain(), (0.0, 4.0));
/// for j in 0..=4 {
///     assert!((c.eval(j as f64) - p[j + 1]).length() < 1e-12);
/// }
/// # Ok::<(), splinelab::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Bis<P: Point> {
    alpha: f64,
    points: Vec<P>,
    beta: Vec<f64>,
    k: usize,
}

/// Checks a β* list: `len` entries, finite, ≥ 0. `field` names it.
pub(crate) fn check_beta(field: &'static str, beta: &[f64], len: usize) -> Result<()> {
    if beta.len() != len {
        return Err(Error::size_mismatch(
            field,
            format!(
                "need one β* per interpolated point ({len} = n + 1), got {}",
                beta.len()
            ),
        ));
    }
    for (i, &b) in beta.iter().enumerate() {
        if !b.is_finite() {
            return Err(Error::not_finite(
                format!("{field}[{i}]"),
                crate::error::not_finite_detail(b),
            ));
        }
        if b < 0.0 {
            return Err(Error::out_of_range(
                format!("{field}[{i}]"),
                "β* scales a tangent length and must be ≥ 0",
            ));
        }
    }
    Ok(())
}

impl<P: Point> Bis<P> {
    /// The BIS through b_0..b_n with `points` = b_{−1}..b_{n+1} (≥ 4 points), local parameters
    /// `beta` = β*_0..β*_n (`None`: all 1, the α = 3 spline) and allocated-function order `k` (2..=10).
    pub fn new(points: Vec<P>, beta: Option<Vec<f64>>, k: usize) -> Result<Self> {
        check_points("points", &points)?;
        if points.len() < 4 {
            return Err(Error::too_few(
                "points",
                format!(
                    "need at least 4 points b₋₁..bₙ₊₁ (n ≥ 1 segment), got {}",
                    points.len()
                ),
            ));
        }
        check_order("k", k)?;
        let n1 = points.len() - 2;
        let beta = beta.unwrap_or_else(|| vec![1.0; n1]);
        check_beta("beta", &beta, n1)?;
        Ok(Bis {
            alpha: 3.0,
            points,
            beta,
            k,
        })
    }

    /// The curvature-matching BIS: β* from [`beta_curvature`].
    pub fn curvature_matched(points: Vec<P>, k: usize) -> Result<Self> {
        check_points("points", &points)?;
        let beta = beta_curvature(&points)?;
        Self::new(points, Some(beta), k)
    }

    /// Remark 2: blend the quasi-cubic B-spline of shape parameter `alpha` (α ∈ [−3, 3]) instead of the
    /// α = 3 spline. Only α = 3 interpolates for every β*.
    pub fn with_alpha(mut self, alpha: f64) -> Result<Self> {
        check_alpha("alpha", alpha)?;
        self.alpha = alpha;
        Ok(self)
    }

    /// The shape parameter α.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }
    /// The interpolated points.
    pub fn points(&self) -> &[P] {
        &self.points
    }
    /// β*_0..β*_n.
    pub fn beta(&self) -> &[f64] {
        &self.beta
    }
    /// The blending order k.
    pub fn order(&self) -> usize {
        self.k
    }
    /// Number of segments n.
    pub fn segments(&self) -> usize {
        self.points.len() - 3
    }
    /// The interpolated point b_j (j = 0..n).
    pub fn data_point(&self, j: usize) -> Option<P> {
        self.points.get(j + 1).copied()
    }

    /// Derivatives 0..=order (≤ 2) of segment `g` at local `t` (one-sided at the joints).
    pub fn eval_segment(&self, g: usize, t: f64, order: usize, out: &mut [P; 3]) {
        let order = order.min(2);
        let g = g.min(self.segments() - 1);
        let mut b = [[0.0; 4]; 4];
        basis_derivs(self.alpha, t, order, &mut b);
        let q = &self.points[g..g + 4];
        let mut p = [P::ZERO; 3];
        for k in 0..=order {
            p[k] = q[0] * b[k][0] + q[1] * b[k][1] + q[2] * b[k][2] + q[3] * b[k][3];
        }
        let s = allocated(self.k, t);
        let (b0, b1) = (q[1], q[2]);
        let l = [b0 + (b1 - b0) * s[0], (b1 - b0) * s[1], (b1 - b0) * s[2]];
        let (be0, be1) = (self.beta[g], self.beta[g + 1]);
        let be = [
            be0 + (be1 - be0) * s[0],
            (be1 - be0) * s[1],
            (be1 - be0) * s[2],
        ];
        // BIS = L + β·(p − L); Leibniz for the product β·d, d = p − L.
        let d = [p[0] - l[0], p[1] - l[1], p[2] - l[2]];
        out[0] = l[0] + d[0] * be[0];
        if order >= 1 {
            out[1] = l[1] + d[0] * be[1] + d[1] * be[0];
        }
        if order >= 2 {
            out[2] = l[2] + d[0] * be[2] + d[1] * (2.0 * be[1]) + d[2] * be[0];
        }
    }
}

impl<P: Point> Curve<P> for Bis<P> {
    fn domain(&self) -> (f64, f64) {
        (0.0, self.segments() as f64)
    }
    fn eval_derivs(&self, u: f64, order: usize, out: &mut [P; 3]) {
        let (g, t) = super::curve::locate(u, self.segments(), false);
        self.eval_segment(g, t, order, out);
    }
}

/// The curvature-matching local parameters β*_0..β*_n for `points` = b_{−1}..b_{n+1} (findings §1.2):
/// β*_j = (c1/c0²)·a_j·a_{j+1}/|b_{j+1} − b_{j−1}|², a_j = |b_j − b_{j−1}|. The auxiliary points b_{−1},
/// b_{n+1} are used at the ends. Fails (naming `points[j]`) when b_{j+1} = b_{j−1}.
pub fn beta_curvature<P: Point>(points: &[P]) -> Result<Vec<f64>> {
    if points.len() < 3 {
        return Err(Error::too_few(
            "points",
            format!("need at least 3 points, got {}", points.len()),
        ));
    }
    let ratio = C1 / (C0 * C0);
    let mut out = Vec::with_capacity(points.len() - 2);
    for w in points.windows(3) {
        let chord = (w[2] - w[0]).dot(w[2] - w[0]);
        if chord.is_nan() || chord <= 0.0 {
            return Err(Error::degenerate(
                format!("points[{}]", out.len() + 2),
                format!(
                    "bⱼ equals bⱼ₋₂ with j = {}: the curvature-matching β* is undefined",
                    out.len() + 1
                ),
            ));
        }
        out.push(ratio * w[1].distance(w[0]) * w[2].distance(w[1]) / chord);
    }
    Ok(out)
}

/// Curvature K_j = 1/R_j of the circle through b_{j−1}, b_j, b_{j+1}, j = 0..n (`points` = b_{−1}..b_{n+1}),
/// unsigned, any dimension (0 for collinear points): K = 2·sin∠/|b_{j+1} − b_{j−1}| = 4·area/(abc).
pub fn circle_curvatures<P: Point>(points: &[P]) -> Vec<f64> {
    points
        .windows(3)
        .map(|w| {
            let (a, b) = (w[1] - w[0], w[2] - w[1]);
            let (la, lb, lc) = (a.length(), b.length(), (w[2] - w[0]).length());
            let denom = la * lb * lc;
            if denom == 0.0 {
                0.0
            } else {
                // |a × b| from the Gram determinant (any dimension)
                let cross = (a.dot(a) * b.dot(b) - a.dot(b).powi(2)).max(0.0).sqrt();
                2.0 * cross / denom
            }
        })
        .collect()
}

/// Signed circle curvatures for planar data (positive for a left turn b_{j−1} → b_j → b_{j+1}).
pub fn circle_curvatures_signed(points: &[glam::DVec2]) -> Vec<f64> {
    points
        .windows(3)
        .map(|w| {
            let (a, b) = (w[1] - w[0], w[2] - w[1]);
            let denom = a.length() * b.length() * (w[2] - w[0]).length();
            if denom == 0.0 {
                0.0
            } else {
                2.0 * crate::point::cross2(a, b) / denom
            }
        })
        .collect()
}
