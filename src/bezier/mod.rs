//! Gânscă, Coman and Ţămbulea: polynomial Bézier splines, parametric degree elevation that keeps
//! C^r, curvature at the breakpoints, and the surface variant of §4.1.
//!
//! * [`BezierSpline`]: a spline of degree m with control points b_0..b_{mL} and breakvalues
//!   u_0 < … < u_L (eq. 1); segment I uses b_{mI}..b_{mI+m} with t = (u − u_I)/(u_{I+1} − u_I).
//!   Its C^r conditions (eq. 2) are measured by [`BezierSpline::joint_jumps`] and
//!   [`BezierSpline::cr_residual`].
//! * [`AlphaTable`]: the parameters α_k^{(I)} ∈ (0, 1), stored as `rows[I][k − 1]`; [`AlphaTable::enforce`]
//!   overwrites the entries fixed by eq. (9) for C^r (r ≤ ⌊m/2⌋) and [`alpha_roles`] says which are free.
//! * [`Remodelling`]: the elevated spline g* of degree m + 1 (eq. 6 / 10–12) and the curvatures of
//!   eqs. (13)–(15) at every breakvalue (with the corrections of `curves.md` §3.2).
//! * [`BezierSplineSurface`] and [`SurfaceRemodelling`]: eqs. (16)–(19), elevation in u only.
//! * [`BiRemodelling`]: §4.2, elevation in u and then in v keeping C^{r,s} (eqs. 20–22 rebuilt).
//! * [`BezierSpline::from_bspline`]: any B-spline in Bézier form (knot insertion to multiplicity p).

mod alphas;
mod bidegree;
mod casteljau;
mod convert;
mod curvature;
mod remodel;
mod spline;
mod surface;

pub use alphas::{alpha_roles, check_r, AlphaRole, AlphaTable};
pub use bidegree::{transpose, BiRemodelling, DirectionParams};
pub use casteljau::DeCasteljau;
pub use curvature::{osculating_circle, wedge_norm};
pub use remodel::{curvature_sweep, elevate, Remodelling};
pub use spline::{BezierSpline, Side};
pub use surface::{BezierSplineSurface, SurfaceRemodelling};

/// The largest input degree m (the elevated spline has degree m + 1). Evaluation uses fixed-size work
/// arrays of `MAX_BEZIER_DEGREE + 2` points, so it never allocates.
pub const MAX_BEZIER_DEGREE: usize = 24;

/// Work-array width: enough for the control points of one elevated segment.
pub(crate) const W: usize = MAX_BEZIER_DEGREE + 2;

/// Position and derivatives up to `order` (≤ 2) of one Bézier segment with control points `ctrl`
/// (degree `ctrl.len() − 1`, 1 ≤ degree ≤ W − 1) at the local parameter `t`, scaled to a global parameter
/// whose span has length `h` (d/du = (1/h)·d/dt). De Casteljau: the last three levels give the
/// derivatives, d1 = d(r1 − r0)/h and d2 = d(d − 1)(q2 − 2q1 + q0)/h².
pub(crate) fn segment_derivs<P: crate::Point>(
    ctrl: &[P],
    t: f64,
    h: f64,
    order: usize,
    out: &mut [P; 3],
) {
    let d = ctrl.len().saturating_sub(1);
    let mut w = [P::ZERO; W];
    let n = ctrl.len().min(W);
    w[..n].copy_from_slice(&ctrl[..n]);
    if d == 0 {
        out[0] = w[0];
        out[1] = P::ZERO;
        out[2] = P::ZERO;
        return;
    }
    // de Casteljau down to 3 points (or 2 when d = 1)
    let stop = if d >= 2 { 2 } else { 1 };
    let mut len = d; // highest index in use
    while len > stop {
        for j in 0..len {
            w[j] = w[j].lerp_to(w[j + 1], t);
        }
        len -= 1;
    }
    let df = d as f64;
    if order >= 2 {
        out[2] = if d >= 2 {
            (w[2] - w[1] * 2.0 + w[0]) * (df * (df - 1.0) / (h * h))
        } else {
            P::ZERO
        };
    }
    if d >= 2 {
        for j in 0..2 {
            w[j] = w[j].lerp_to(w[j + 1], t);
        }
    }
    if order >= 1 {
        out[1] = (w[1] - w[0]) * (df / h);
    }
    out[0] = w[0].lerp_to(w[1], t);
}

/// The forward difference Δ^k of `pts` starting at index 0 (uses `pts[0..=k]`; `k < W`).
pub(crate) fn forward_difference<P: crate::Point>(pts: &[P], k: usize) -> P {
    let mut w = [P::ZERO; W];
    let n = (k + 1).min(pts.len()).min(W);
    w[..n].copy_from_slice(&pts[..n]);
    for level in 0..k.min(n.saturating_sub(1)) {
        for j in 0..n - 1 - level {
            w[j] = w[j + 1] - w[j];
        }
    }
    w[0]
}

/// The falling factorial d(d − 1)…(d − k + 1) (0 when k > d): the factor of the k-th derivative of a
/// degree-d Bézier segment at an end.
pub(crate) fn falling(d: usize, k: usize) -> f64 {
    if k > d {
        return 0.0;
    }
    (0..k).map(|i| (d - i) as f64).product()
}
