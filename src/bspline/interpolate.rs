//! Global interpolation (Piegl–Tiller §9.2.1).

use super::{basis_derivs, BSplineCurve, W};
use crate::error::{Error, Result};
use crate::knots::{self, find_span};
use crate::linalg::Matrix;
use crate::point::Point;

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
            "interpolation is too ill-conditioned (residual above 1e-9 × the data size): the parameters are nearly coincident",
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
