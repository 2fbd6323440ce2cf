//! [`B2Curve`]: a B2-spline curve L^a (sections 4–5).

use super::data::{check_points, resolve_knots};
use super::{
    auto_tension, resolve_tension, AutoTension, B2Options, B2Scheme, Construction, Eq5, KnotChoice,
    Tension,
};
use crate::bspline::BSplineCurve;
use crate::error::{Error, Result};
use crate::point::Point;
use crate::sample::Curve;

/// A B2-spline curve L^a through/near the data W_{−1}..W_{n+2}: a cubic B-spline whose control polygon is
/// built by the construction of the module docs. Works for any [`Point`] (`f64` gives blending functions).
///
/// # Template
/// * **What**: Kuklišová's non-uniform B2-spline L^a: a cubic B-spline whose control polygon is
///   built from the data by eqs. (8)–(9) (even vertices, with tension p_i) and (5) (odd vertices), blending
///   from interpolation (a = 0) to the cubic B-spline of the data (a = 1/6).
/// * **Interpolates**: at a = 0 the data W_1..W_n at their knots u_1..u_n (W_{−1}, W_0, W_{n+1}, W_{n+2}
///   are auxiliary); for a ≠ 0 it approximates them.
/// * **Continuity**: C² (a cubic B-spline on simple knots); C¹ with the modified knots of §5.
/// * **Parametrisation**: the data knots (chord length by default, u_1 = 0), domain [u_1, u_n].
///
/// # Example
/// ```
/// use glam::DVec2;
/// use splinelab::{b2spline::{B2Curve, B2Options}, Curve};
/// let w: Vec<DVec2> = (0..7).map(|i| DVec2::new(i as f64, (i as f64 * 1.3).sin())).collect();
/// let c = B2Curve::new(&w, &B2Options::default())?; // a = 0: interpolating
/// let (u, n) = (c.data_knots(), c.n());
/// for i in 1..=n {
///     assert!((c.eval(u[i + 1]) - w[i + 1]).length() < 1e-12); // L(u_i) = W_i
/// }
/// assert_eq!(c.domain(), (u[2], u[n + 1]));
/// # Ok::<(), splinelab::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct B2Curve<P: Point> {
    scheme: B2Scheme,
    data: Vec<P>,
    joints: Vec<P>,
    curve: BSplineCurve<P>,
}

impl<P: Point> B2Curve<P> {
    /// Builds L^a for the data `points` = W_{−1}..W_{n+2} (n ≥ 2). Errors name the field: `points`,
    /// `points[i]`, `knots`, `knots[i]`, `tension`, `autoTension`, `K`, `c2`, `a`, `construction`.
    pub fn new(points: &[P], opts: &B2Options) -> Result<Self> {
        Self::new_with_eq5(points, opts, Eq5::Corrected)
    }

    /// Like [`B2Curve::new`], with the odd vertices from eq. (5) corrected (what `new` does) or exactly as
    /// printed ([`Eq5::AsPrinted`], to show the paper's typo: the curve then misses its joints where the
    /// knot spans around a joint differ; see [`B2Curve::joint_residuals`]).
    pub fn new_with_eq5(points: &[P], opts: &B2Options, eq5: Eq5) -> Result<Self> {
        check_points(points)?;
        let n = points.len() - 4;
        crate::error::check_finite_scalar("a", opts.a)?;
        if opts.construction == Construction::Section3 {
            match &opts.knots {
                KnotChoice::Uniform | KnotChoice::Explicit(_) => {}
                KnotChoice::Chord => {
                    return Err(Error::invalid(
                        "construction",
                        "\"section3\" is the uniform construction and requires knots: \"uniform\", got knots: \"chord\"",
                    ))
                }
            }
            if matches!(opts.tension, Tension::PerVertex(_)) {
                return Err(Error::invalid(
                    "tension",
                    "\"section3\" uses one scalar tension p, not an array",
                ));
            }
            if opts.auto_tension != AutoTension::Off {
                return Err(Error::invalid(
                    "autoTension",
                    "\"section3\" uses one scalar tension p; automatic tension is not available",
                ));
            }
        }
        let data_knots = resolve_knots(&opts.knots, points)?;
        let tension = match opts.auto_tension {
            AutoTension::Off => resolve_tension(&opts.tension, n)?,
            mode => auto_tension(points, mode)?,
        };
        let scheme = B2Scheme::new(
            data_knots,
            tension,
            opts.a,
            opts.k,
            opts.c2,
            opts.construction,
        )?;
        let scheme = match eq5 {
            Eq5::Corrected => scheme,
            Eq5::AsPrinted => scheme.with_eq5_as_printed(),
        };
        Self::from_scheme(scheme, points)
    }

    /// |L(u′_{2i}) − R_i| for i = 1..n: how far the curve passes from its joints (rounding-level with the
    /// corrected eq. (5); not with [`Eq5::AsPrinted`]).
    pub fn joint_residuals(&self) -> Vec<f64> {
        self.scheme
            .joint_params()
            .iter()
            .zip(&self.joints)
            .map(|(&u, &r)| self.curve.eval(u).distance(r))
            .collect()
    }

    /// Applies a prepared scheme to data (n + 4 points, as many as the scheme's knots).
    pub(crate) fn from_scheme(scheme: B2Scheme, points: &[P]) -> Result<Self> {
        check_points(points)?;
        let (joints, ctrl) = scheme.control_points(points)?;
        let curve = BSplineCurve::new(3, scheme.knots.clone(), ctrl)?;
        Ok(B2Curve {
            scheme,
            data: points.to_vec(),
            joints,
            curve,
        })
    }

    /// The data-independent part (knots, tensions, weights).
    pub fn scheme(&self) -> &B2Scheme {
        &self.scheme
    }
    /// The data W_{−1}..W_{n+2}.
    pub fn data(&self) -> &[P] {
        &self.data
    }
    /// n.
    pub fn n(&self) -> usize {
        self.scheme.n
    }
    /// The joints R_1..R_n of L^a (= W_1..W_n at a = 0), at the parameters [`B2Scheme::joint_params`].
    pub fn joints(&self) -> &[P] {
        &self.joints
    }
    /// All cubic control points C_0..C_{2n}.
    pub fn control_points(&self) -> &[P] {
        self.curve.points()
    }
    /// The even vertices C_0, C_2, …, C_{2n}.
    pub fn even_vertices(&self) -> Vec<P> {
        self.curve.points().iter().step_by(2).copied().collect()
    }
    /// The full cubic knot vector (2n + 5 knots).
    pub fn knots(&self) -> &[f64] {
        self.curve.knots()
    }
    /// The data knots u_{−1}..u_{n+2}.
    pub fn data_knots(&self) -> &[f64] {
        &self.scheme.data_knots
    }
    /// The tensions p_0..p_n used.
    pub fn tension(&self) -> &[f64] {
        &self.scheme.tension
    }
    /// The cubic B-spline this curve is.
    pub fn bspline(&self) -> &BSplineCurve<P> {
        &self.curve
    }
}

impl<P: Point> Curve<P> for B2Curve<P> {
    fn domain(&self) -> (f64, f64) {
        self.scheme.domain()
    }
    /// Cubic B-spline evaluation (right-hand piece at knots, last piece at the end; extrapolates outside).
    fn eval_derivs(&self, u: f64, order: usize, out: &mut [P; 3]) {
        self.curve.eval_derivs(u, order, out)
    }
    /// The cubic B-spline's per-span sampler.
    fn piecewise(&self) -> Option<crate::kernel::PiecewisePoly<P>> {
        self.curve.to_piecewise()
    }
}
