//! Knot vectors: construction (uniform, clamped, chord-length, averaging), validation, span search,
//! knot insertion and refinement.
//!
//! Conventions: a B-spline of degree `p` with `n` control points has a full knot vector of `n + p + 1`
//! non-decreasing knots and lives on `[t_p, t_n]`. At an interior knot the **right-hand** piece is used;
//! at the last knot (and beyond) the last non-empty piece (Piegl–Tiller, *The NURBS Book*, A2.1).

use crate::error::{Error, Result};
use crate::point::Point;

/// The largest degree the kernel supports (fixed-size work arrays keep evaluation allocation-free).
pub const MAX_DEGREE: usize = 24;

/// Validates a full knot vector for `n_ctrl` control points of degree `degree`: finite, non-decreasing,
/// of length `n_ctrl + degree + 1`, no knot of multiplicity above `degree + 1`, and a non-empty domain.
pub fn validate(field: &'static str, knots: &[f64], degree: usize, n_ctrl: usize) -> Result<()> {
    if degree > MAX_DEGREE {
        return Err(Error::out_of_range(
            "degree",
            format!("at most {MAX_DEGREE}, got {degree}"),
        ));
    }
    if n_ctrl < degree + 1 {
        return Err(Error::too_few(
            "points",
            format!(
                "need at least {} control points for degree {degree}, got {n_ctrl}",
                degree + 1
            ),
        ));
    }
    let expected = n_ctrl + degree + 1;
    if knots.len() != expected {
        return Err(Error::size_mismatch(
            field,
            format!(
                "expected {expected} knots (points + degree + 1 = {n_ctrl} + {degree} + 1), got {}",
                knots.len()
            ),
        ));
    }
    crate::error::check_finite(field, knots)?;
    check_non_decreasing(field, knots)?;
    let mut run = 1;
    for i in 1..knots.len() {
        if knots[i] == knots[i - 1] {
            run += 1;
            if run > degree + 1 {
                return Err(Error::degenerate(
                    format!("{field}[{i}]"),
                    format!(
                        "a knot is repeated more than degree + 1 = {} times",
                        degree + 1
                    ),
                ));
            }
        } else {
            run = 1;
        }
    }
    if knots[degree] >= knots[n_ctrl] {
        return Err(Error::degenerate(
            field,
            format!("empty domain: knots[{degree}] must be < knots[{n_ctrl}]"),
        ));
    }
    Ok(())
}

/// Checks `values[i] ≤ values[i + 1]` for all i.
pub(crate) fn check_non_decreasing(field: &'static str, values: &[f64]) -> Result<()> {
    match values.windows(2).position(|w| w[1] < w[0]) {
        None => Ok(()),
        Some(i) => Err(Error::not_increasing(
            format!("{field}[{}]", i + 1),
            format!(
                "values must not decrease, but entry {} is less than entry {}",
                i + 1,
                i
            ),
        )),
    }
}

/// Checks `values[i] < values[i + 1]` for all i (breakpoints, interpolation parameters).
pub(crate) fn check_increasing(field: &'static str, values: &[f64]) -> Result<()> {
    match values.windows(2).position(|w| !(w[1] > w[0])) {
        None => Ok(()),
        Some(i) => Err(Error::not_increasing(
            format!("{field}[{}]", i + 1),
            format!(
                "values must strictly increase, but entry {} is not greater than entry {}",
                i + 1,
                i
            ),
        )),
    }
}

/// The smallest gap allowed between distinct knots of a user's knot vector, relative to the knot range
/// (and at least [`MIN_KNOT_GAP_ABS`]): B-spline derivatives grow like 1/gap^order, so closer knots make
/// them overflow to ±∞/NaN. Equal knots (multiplicity) are fine. Nearly equal knots with a gap ratio of
/// 1e-6 are well inside the limit.
pub const MIN_KNOT_GAP: f64 = 1e-12;
/// The absolute floor of the knot gap (see [`MIN_KNOT_GAP`]).
pub const MIN_KNOT_GAP_ABS: f64 = 1e-100;

/// Checks that distinct knots are at least `MIN_KNOT_GAP × range` (and `MIN_KNOT_GAP_ABS`) apart, so
/// every derivative the kernel evaluates stays finite. Call it at the API boundary, after [`validate`].
pub fn check_separated(field: &'static str, knots: &[f64]) -> Result<()> {
    let (Some(first), Some(last)) = (knots.first(), knots.last()) else {
        return Ok(());
    };
    let min_gap = (MIN_KNOT_GAP * (last - first)).max(MIN_KNOT_GAP_ABS);
    match knots
        .windows(2)
        .position(|w| w[1] != w[0] && w[1] - w[0] < min_gap)
    {
        None => Ok(()),
        Some(i) => Err(Error::degenerate(
            format!("{field}[{}]", i + 1),
            format!(
                "knots {i} and {} are distinct but closer than 1e-12 × the knot range: derivatives would \
                 overflow; make them equal or move them apart",
                i + 1
            ),
        )),
    }
}

/// Uniform (unclamped) knots `0, 1, …, count − 1`.
pub fn uniform(count: usize) -> Vec<f64> {
    (0..count).map(|i| i as f64).collect()
}

/// Clamped knots on `[a, b]` for `n_ctrl` control points of degree `p`, uniform interior knots
/// (`p + 1` copies of each end).
pub fn clamped_uniform(n_ctrl: usize, degree: usize, a: f64, b: f64) -> Vec<f64> {
    let inner = n_ctrl.saturating_sub(degree + 1);
    let mut k = vec![a; degree + 1];
    for i in 1..=inner {
        k.push(a + (b - a) * i as f64 / (inner + 1) as f64);
    }
    k.extend(std::iter::repeat_n(b, degree + 1));
    k
}

/// Chord-length parameters of `points`, `t_0 = 0 < … < t_{n−1} = 1`. Coincident neighbours give a
/// `Degenerate` error naming the index.
pub fn chord_length_params<P: Point>(field: &'static str, points: &[P]) -> Result<Vec<f64>> {
    if points.len() < 2 {
        return Err(Error::too_few(
            field,
            format!("need at least 2 points, got {}", points.len()),
        ));
    }
    let mut t = Vec::with_capacity(points.len());
    t.push(0.0);
    for i in 1..points.len() {
        let d = points[i].distance(points[i - 1]);
        if !(d > 0.0) {
            return Err(Error::degenerate(
                format!("{field}[{i}]"),
                format!("coincides with the previous point (zero chord length between points {} and {i})", i - 1),
            ));
        }
        t.push(t[i - 1] + d);
    }
    let total = t[t.len() - 1];
    for x in t.iter_mut() {
        *x /= total;
    }
    let last = t.len() - 1;
    t[last] = 1.0;
    Ok(t)
}

/// Averaging knots (Piegl–Tiller eq. (9.8)) for interpolation of degree `p` at parameters `params`:
/// `p + 1` copies of each end, interior knots the means of `p` consecutive interior parameters.
pub fn averaging(params: &[f64], degree: usize) -> Vec<f64> {
    let n = params.len();
    let (first, last) = (params[0], params[n - 1]);
    let mut k = vec![first; degree + 1];
    for j in 1..n.saturating_sub(degree) {
        let s: f64 = params[j..j + degree].iter().sum();
        k.push(s / degree as f64);
    }
    k.extend(std::iter::repeat_n(last, degree + 1));
    k
}

/// The span index `s` with `t_s ≤ u < t_{s+1}`, `p ≤ s ≤ n_ctrl − 1`; parameters at or beyond the last
/// knot of the domain use the last non-empty span, parameters before the domain the first one.
pub fn find_span(knots: &[f64], degree: usize, n_ctrl: usize, u: f64) -> usize {
    let (lo, hi) = (degree, n_ctrl - 1);
    if u >= knots[n_ctrl] {
        // last non-empty span
        let mut s = hi;
        while s > lo && knots[s] >= knots[s + 1] {
            s -= 1;
        }
        return s;
    }
    if u <= knots[lo] {
        let mut s = lo;
        while s < hi && knots[s + 1] <= knots[lo] {
            s += 1;
        }
        return s;
    }
    // binary search for t_s <= u < t_{s+1}
    let (mut a, mut b) = (lo, n_ctrl);
    while b - a > 1 {
        let mid = (a + b) / 2;
        if u < knots[mid] {
            b = mid;
        } else {
            a = mid;
        }
    }
    a
}

/// Inserts the knot `u` once (Boehm's algorithm); the curve is unchanged. Returns the new knots and
/// control points. `u` must lie in the domain `[t_p, t_n]`.
pub fn insert_knot<P: Point>(
    degree: usize,
    knots: &[f64],
    ctrl: &[P],
    u: f64,
) -> Result<(Vec<f64>, Vec<P>)> {
    let n = ctrl.len();
    validate("knots", knots, degree, n)?;
    if !(u >= knots[degree] && u <= knots[n]) {
        return Err(Error::out_of_range(
            "u",
            format!("the knot to insert must lie in the domain [knots[{degree}], knots[{n}]]"),
        ));
    }
    // span with t_k <= u < t_{k+1}; inserting at the right end uses the last span
    let k = find_span(knots, degree, n, u);
    let mut new_knots = Vec::with_capacity(knots.len() + 1);
    new_knots.extend_from_slice(&knots[..=k]);
    new_knots.push(u);
    new_knots.extend_from_slice(&knots[k + 1..]);
    let mut new_ctrl = Vec::with_capacity(n + 1);
    for i in 0..=n {
        let q = if i + degree <= k {
            ctrl[i]
        } else if i > k {
            ctrl[i - 1]
        } else {
            let a = insertion_alpha(knots, degree, i, u);
            ctrl[i - 1] * (1.0 - a) + ctrl[i] * a
        };
        new_ctrl.push(q);
    }
    Ok((new_knots, new_ctrl))
}

/// Boehm's coefficient α_i = (u − t_i)/(t_{i+p} − t_i) of the new control point
/// Q_i = (1 − α_i)·P_{i−1} + α_i·P_i when the knot `u` is inserted (0 where the denominator is 0).
pub(crate) fn insertion_alpha(knots: &[f64], degree: usize, i: usize, u: f64) -> f64 {
    let denom = knots[i + degree] - knots[i];
    if denom > 0.0 {
        (u - knots[i]) / denom
    } else {
        0.0
    }
}

/// Knot refinement: inserts every knot of `extra` (any order, repeats allowed) into the curve.
pub fn refine<P: Point>(
    degree: usize,
    knots: &[f64],
    ctrl: &[P],
    extra: &[f64],
) -> Result<(Vec<f64>, Vec<P>)> {
    let mut k = knots.to_vec();
    let mut c = ctrl.to_vec();
    for &u in extra {
        let (k2, c2) = insert_knot(degree, &k, &c, u)?;
        k = k2;
        c = c2;
    }
    Ok((k, c))
}

/// The knots of `b` that are not in `a`, counting multiplicity (both sorted): what to insert into a knot
/// vector `a` to obtain the union `a ∪ b`.
pub fn missing_knots(a: &[f64], b: &[f64]) -> Vec<f64> {
    let mut out = Vec::new();
    let (mut i, mut j) = (0, 0);
    while j < b.len() {
        if i < a.len() && a[i] == b[j] {
            i += 1;
            j += 1;
        } else if i < a.len() && a[i] < b[j] {
            i += 1;
        } else {
            out.push(b[j]);
            j += 1;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spans_use_right_piece_and_last_piece_at_end() {
        let k = [0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0];
        let n = 5;
        assert_eq!(find_span(&k, 2, n, 0.0), 2);
        assert_eq!(find_span(&k, 2, n, 0.5), 2);
        assert_eq!(find_span(&k, 2, n, 1.0), 3);
        assert_eq!(find_span(&k, 2, n, 2.999), 4);
        assert_eq!(find_span(&k, 2, n, 3.0), 4);
        assert_eq!(find_span(&k, 2, n, 7.0), 4);
        assert_eq!(find_span(&k, 2, n, -1.0), 2);
    }

    #[test]
    fn validation_names_the_problem() {
        let e = validate("knots", &[0.0, 0.0, 1.0, 0.5, 1.0, 1.0], 1, 4).unwrap_err();
        assert_eq!(e.kind(), crate::ErrorKind::NotIncreasing);
        assert_eq!(e.field(), "knots[3]");
        let e = validate("knots", &[0.0, 0.0, 1.0, 1.0], 1, 3).unwrap_err();
        assert_eq!(e.kind(), crate::ErrorKind::SizeMismatch);
        let e = validate("knots", &[0.0, 0.0, f64::NAN, 1.0, 1.0], 1, 3).unwrap_err();
        assert_eq!(e.kind(), crate::ErrorKind::NotFinite);
        let e = validate("knots", &[0.0, 0.0, 0.0, 0.0, 1.0], 1, 3).unwrap_err();
        assert_eq!(e.kind(), crate::ErrorKind::Degenerate);
        assert!(validate("knots", &[0.0, 0.0, 0.5, 1.0, 1.0], 1, 3).is_ok());
    }

    #[test]
    fn averaging_knots_match_piegl_tiller() {
        // parameters 0, 1/3, 2/3, 1 with degree 2: interior knot (1/3 + 2/3)/2 = 1/2
        let k = averaging(&[0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0], 2);
        assert_eq!(k, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]);
        assert_eq!(
            clamped_uniform(5, 2, 0.0, 3.0),
            vec![0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0]
        );
    }

    #[test]
    fn chord_length_rejects_coincident_points() {
        use glam::DVec2;
        let t = chord_length_params(
            "p",
            &[DVec2::ZERO, DVec2::new(3.0, 4.0), DVec2::new(3.0, 9.0)],
        )
        .unwrap();
        assert_eq!(t, vec![0.0, 0.5, 1.0]);
        let e = chord_length_params("p", &[DVec2::ZERO, DVec2::ZERO]).unwrap_err();
        assert_eq!(e.field(), "p[1]");
    }

    #[test]
    fn missing_knots_counts_multiplicity() {
        let a = [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
        let b = [0.0, 0.0, 0.0, 1.0 / 3.0, 0.5, 0.5, 1.0, 1.0, 1.0];
        assert_eq!(missing_knots(&a, &b), vec![1.0 / 3.0, 0.5]);
    }
}
