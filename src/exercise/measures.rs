//! The checks that measure a whole construction: fit error, ellipse reproduction, ‖A − B‖ of two network
//! surfaces, the envelope point of a moved knot.

use super::distance::foot_point;
use crate::b2spline::B2Options;
use crate::error::{Error, Result};
use crate::fit;
use crate::gordon::{Blend, SurfaceFamily};
use crate::knot_paths::KnotModifiedCurve;
use crate::network::Network;
use crate::quasi_cubic::presets::{check_shape, ExactShape};
use crate::sample::Curve;
use glam::DVec2;

/// The fit error of the B2-spline paper's noisy-data experiment (Figs. 1–3): the B2 curve L^a of `data`
/// with reflected end points ([`fit::fit`]), sampled at `samples` parameters, against the known curve given
/// as a dense polyline `truth`: returns (RMS, max) of the distances ([`fit::curve_distance`]).
pub fn fit_error(
    data: &[DVec2],
    opts: &B2Options,
    truth: &[DVec2],
    samples: usize,
) -> Result<(f64, f64)> {
    if truth.len() < 2 {
        return Err(Error::too_few_of(
            "truth",
            2,
            truth.len(),
            "the known curve needs at least 2 points",
        ));
    }
    let c = fit::fit(data, opts)?;
    Ok(fit::curve_distance(&c, truth, samples.max(2)))
}

/// How far the closed quasi-cubic curve of the four control points `points` at `alpha` is from an exact
/// ellipse: the maximum distance (over `per_segment` samples per segment) to the ellipse
/// o + e_1 cos θ + e_2 sin θ that the points define, with o = (b_0 + b_1 + b_2 + b_3)/4, e_1 = (b_1 − b_3)/3,
/// e_2 = (b_2 − b_0)/3. It is 0 (to rounding) exactly when α = 1 and b_0 + b_2 = b_1 + b_3 (the quasi-cubic
/// paper's ellipse: the diagonals of the control polygon bisect each other).
pub fn ellipse_deviation(points: &[DVec2], alpha: f64, per_segment: usize) -> Result<f64> {
    Ok(check_shape(ExactShape::Ellipse, alpha, points, per_segment)?.deviation)
}

/// ‖A − B‖∞ on an `n × n` grid between two surfaces of the family through `net` (criss-cross S, thin-plate
/// T, Gordon G, spline-blended GB; `pair` such as `"SG"`); `tol` is the network's compatibility tolerance.
pub fn network_norm(net: &Network, pair: &str, n: usize, tol: f64) -> Result<f64> {
    crate::gordon::check_norm_samples("normSamples", n)?;
    let fam = SurfaceFamily::new(net, Blend::CubicNatural, tol)?;
    if fam.pair(pair).is_none() {
        return Err(Error::invalid(
            "pair",
            format!("expected two of S, T, G, GB such as \"SG\", got {pair:?}"),
        ));
    }
    fam.norms(n)
        .into_iter()
        .find(|(k, _)| *k == pair)
        .map(|(_, v)| v)
        .ok_or_else(|| {
            Error::invalid(
                "pair",
                format!("expected one of SG, ST, TG, SGB, GGB, got {pair:?}"),
            )
        })
}

/// Knot modification (Definition 2, eq. (6)): the curve a(u; u_p) of order `order` with `knots` and
/// `points`, its knot of index `p` moved to `up`, touches the envelope e(w) at w = u_p. Returns
/// (‖e(u_p) − Q‖, dist(Q, a(·; u_p))): how far the touching point is from `target` Q, and how far Q is from
/// the moved curve. `up` is clamped to the envelope's domain [u_{p−1}, u_{p+1}].
pub fn envelope_point(
    order: usize,
    knots: Vec<f64>,
    points: Vec<DVec2>,
    p: usize,
    up: f64,
    target: DVec2,
) -> Result<(f64, f64)> {
    if !(target.x.is_finite() && target.y.is_finite()) {
        return Err(Error::not_finite(
            "target",
            "expected a finite point [x, y]",
        ));
    }
    let curve = KnotModifiedCurve::new(order, knots, points, Some(p), up)?;
    let env = curve
        .envelope()
        .ok_or_else(|| Error::invalid("p", "no knot moves"))?;
    let (a, b) = env.domain();
    let touch = env.eval(up.max(a).min(b)); // not clamp: its a ≤ b assertion formats floats
    let (_, on_curve) = foot_point(&curve, target);
    Ok((touch.distance(target), on_curve))
}
