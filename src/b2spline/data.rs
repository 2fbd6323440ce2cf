//! The data side of a B2-spline: knot choices, the eq. (5) joint weights, auxiliary end points and the
//! validation of the data W_{−1}..W_{n+2}.

use super::KnotChoice;
use crate::error::{Error, Result};
use crate::point::Point;
use crate::sample::MAX_INPUT_POINTS;

/// Weights of a cubic B-spline at a knot on its three non-zero control points, given the four knot spans
/// around it, (a, b, c, d) = Δ_{j−2}, Δ_{j−1}, Δ_j, Δ_{j+1} for the knot t_j. This is eq. (5) with the
/// corrected last weight (findings §2.1): `[c²/((b+c)(a+b+c)), middle, b²/((b+c)(b+c+d))]`.
pub fn joint_weights(a: f64, b: f64, c: f64, d: f64) -> [f64; 3] {
    let w0 = c * c / ((b + c) * (a + b + c));
    let w1 = c / (b + c) * (a + b) / (a + b + c) + b / (b + c) * (c + d) / (b + c + d);
    let w2 = b * b / ((b + c) * (b + c + d));
    [w0, w1, w2]
}

/// The weights of eq. (5) exactly as printed in the paper (last weight b/(b+c)·c/(b+c+d)). They do **not**
/// sum to 1 in general; kept only to document and test the typo.
pub fn joint_weights_as_printed(a: f64, b: f64, c: f64, d: f64) -> [f64; 3] {
    let mut w = joint_weights(a, b, c, d);
    w[2] = b / (b + c) * c / (b + c + d);
    w
}

/// Data knots u_{−1}..u_{n+2} from the chord lengths of `points` (u_1 = 0). Coincident neighbours are a
/// `Degenerate` error naming `points[j]`.
pub fn chord_knots<P: Point>(points: &[P]) -> Result<Vec<f64>> {
    let mut u = Vec::with_capacity(points.len());
    let mut acc = 0.0;
    u.push(0.0);
    for j in 1..points.len() {
        let d = points[j].distance(points[j - 1]);
        if !(d > 0.0) || !d.is_finite() {
            return Err(Error::degenerate(
                format!("points[{j}]"),
                format!(
                    "coincides with points[{}]: chord-length knots need distinct neighbours (use knots: \"uniform\" or explicit knots)",
                    j - 1
                ),
            ));
        }
        acc += d;
        u.push(acc);
    }
    // shift so that u_1 (index 2) = 0
    let shift = u.get(2).copied().unwrap_or(0.0);
    for x in u.iter_mut() {
        *x -= shift;
    }
    Ok(u)
}

/// Uniform data knots u_j = j − 1 for `count` = n + 4 points (j = −1..n+2).
pub fn uniform_knots(count: usize) -> Vec<f64> {
    (0..count).map(|k| k as f64 - 2.0).collect()
}

/// Adds the auxiliary end points by point reflection, for data D_1..D_N (N ≥ 3): W_{1−k} = 2D_1 − D_{1+k}
/// and W_{N+k} = 2D_N − D_{N−k}, k = 1, 2. Returns W_{−1}..W_{N+2} (N + 4 points): the B2 curve then
/// interpolates/approximates all of D_1..D_N. (The paper leaves the auxiliary points to the user.)
pub fn reflect_ends<P: Point>(data: &[P]) -> Result<Vec<P>> {
    let m = data.len();
    if m < 3 {
        return Err(Error::too_few(
            "points",
            format!("need at least 3 data points to add reflected ends, got {m}"),
        ));
    }
    let (f, l) = (data[0], data[m - 1]);
    let mut w = Vec::with_capacity(m + 4);
    w.push(f * 2.0 - data[2]);
    w.push(f * 2.0 - data[1]);
    w.extend_from_slice(data);
    w.push(l * 2.0 - data[m - 2]);
    w.push(l * 2.0 - data[m - 3]);
    Ok(w)
}

/// Validates n + 4 data points (n ≥ 2, finite).
pub(super) fn check_points<P: Point>(points: &[P]) -> Result<()> {
    if points.len() < 6 {
        return Err(Error::too_few(
            "points",
            format!(
                "need at least 6 points W₋₁..Wₙ₊₂ (n ≥ 2), got {}",
                points.len()
            ),
        ));
    }
    if points.len() > MAX_INPUT_POINTS {
        return Err(Error::too_many(
            "points",
            format!("at most {MAX_INPUT_POINTS} points, got {}", points.len()),
        ));
    }
    if let Some(i) = points.iter().position(|p| !p.is_finite()) {
        return Err(Error::not_finite(
            format!("points[{i}]"),
            "expected finite coordinates",
        ));
    }
    Ok(())
}

/// Resolves the knot choice for `count` data (chord needs the points).
pub(super) fn resolve_knots<P: Point>(choice: &KnotChoice, points: &[P]) -> Result<Vec<f64>> {
    match choice {
        KnotChoice::Chord => chord_knots(points),
        KnotChoice::Uniform => Ok(uniform_knots(points.len())),
        KnotChoice::Explicit(k) => {
            if k.len() != points.len() {
                return Err(Error::size_mismatch(
                    "knots",
                    format!(
                        "expected {} knots u₋₁..uₙ₊₂ (one per point), got {}",
                        points.len(),
                        k.len()
                    ),
                ));
            }
            crate::error::check_finite("knots", k)?;
            crate::knots::check_increasing("knots", k)?;
            Ok(k.clone())
        }
    }
}
