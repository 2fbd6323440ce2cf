//! Tension of a B2-spline: the default p = 1/6 (eq. (8)), the resolution of a scalar or per-vertex
//! tension to p_0..p_n, and the automatic tension of findings §2.6.

use super::{AutoTension, Tension};
use crate::error::{Error, Result};
use crate::point::Point;

/// The default tension p = 1/6: with it the even vertices follow eq. (8) as printed.
pub const DEFAULT_TENSION: f64 = 1.0 / 6.0;

/// Automatic tension values p_0..p_n (findings §2.6) for the data W_{−1}..W_{n+2}.
pub fn auto_tension<P: Point>(points: &[P], mode: AutoTension) -> Result<Vec<f64>> {
    let m = points.len();
    let (scale, turning) = match mode {
        AutoTension::Off => {
            return Err(Error::invalid(
                "autoTension",
                "no automatic tension requested",
            ))
        }
        AutoTension::Paper(s) => (s, false),
        AutoTension::Turning(s) => (s, true),
    };
    if !scale.is_finite() {
        return Err(Error::not_finite(
            "autoTensionScale",
            crate::error::not_finite_detail(scale),
        ));
    }
    if turning && P::DIM != 2 {
        return Err(Error::invalid(
            "autoTension",
            format!(
                "\"turning\" uses signed turning angles and needs 2D points, got {}D",
                P::DIM
            ),
        ));
    }
    if m < 6 {
        return Err(Error::too_few(
            "points",
            format!("need at least 6 points (n ≥ 2), got {m}"),
        ));
    }
    // per data vertex j = 0..n+1 (index k = j + 1 = 1..m−2): cos α_j or sin θ_j
    let mut f = vec![0.0; m];
    for k in 1..m - 1 {
        let e0 = points[k] - points[k - 1];
        let e1 = points[k + 1] - points[k];
        let (l0, l1) = (e0.length(), e1.length());
        if !(l0 > 0.0) {
            return Err(Error::degenerate(
                format!("points[{k}]"),
                format!(
                    "coincides with points[{}]: the angle needed by automatic tension is undefined",
                    k - 1
                ),
            ));
        }
        if !(l1 > 0.0) {
            return Err(Error::degenerate(
                format!("points[{}]", k + 1),
                format!("coincides with points[{k}]: the angle needed by automatic tension is undefined"),
            ));
        }
        f[k] = if turning {
            (e0.coord(0) * e1.coord(1) - e0.coord(1) * e1.coord(0)) / (l0 * l1)
        } else {
            // interior angle at W_j between W_{j−1} − W_j and W_{j+1} − W_j
            (-e0).dot(e1) / (l0 * l1)
        };
    }
    let n = m - 4;
    Ok((0..=n)
        .map(|i| scale * (f[i + 1] + f[i + 2]).abs() / 2.0)
        .collect())
}

/// Resolves the tension option to p_0..p_n.
pub fn resolve_tension(t: &Tension, n: usize) -> Result<Vec<f64>> {
    match t {
        Tension::Scalar(p) => {
            crate::error::check_finite_scalar("tension", *p)?;
            Ok(vec![*p; n + 1])
        }
        Tension::PerVertex(v) => {
            crate::error::check_finite("tension", v)?;
            if v.len() == n + 1 {
                Ok(v.clone())
            } else if v.len() == n - 1 {
                // the paper's p_1..p_{n−1}: p_0 := p_1 and p_n := p_{n−1} (curves.md §2, a recommendation)
                let mut p = Vec::with_capacity(n + 1);
                p.push(v[0]);
                p.extend_from_slice(v);
                p.push(v[n - 2]);
                Ok(p)
            } else {
                Err(Error::size_mismatch(
                    "tension",
                    format!(
                        "expected one value per even vertex p₀..pₙ ({} values for n = {n}; or the paper's p₁..pₙ₋₁, {} values), got {}",
                        n + 1,
                        n - 1,
                        v.len()
                    ),
                ))
            }
        }
    }
}
