//! Facts about a sampled plane curve, for a description in words (issue 25): where it reaches furthest left,
//! right, down and up, where it inflects, how long it is and how far it passes from data points.
//!
//! The input is what a demo already drew: parameters u₀ ≤ u₁ ≤ … ≤ u_{n−1} and the points P_k = (x_k, y_k) of
//! the curve at them. Everything is measured on these samples (no second evaluation of the curve):
//!
//! * **Extremes** in x and in y: the sample with the least / greatest coordinate, refined (when it is not an end
//!   sample) by the parabola in u through the three samples (u_{k−1}, c_{k−1}), (u_k, c_k), (u_{k+1}, c_{k+1}):
//!   its vertex u* gives the coordinate's extreme value, and the other coordinate is the parabola through its own
//!   three samples at u*. For a curve that is locally quadratic in u (a parabola) the refinement is exact.
//! * **Inflections**: the turn at an inner sample, s_k = (P_k − P_{k−1}) × (P_{k+1} − P_k) / (|P_k − P_{k−1}|
//!   |P_{k+1} − P_k|) (the sine of the turning angle, the sign of the signed curvature). Turns with
//!   |s_k| ≤ max(10⁻¹⁰, 10⁻⁴ · max_j |s_j|) count as straight (no sign: straight pieces and rounding give no
//!   inflection). Between two successive signed turns of opposite sign, at samples i < j, lies one inflection at
//!   u = u_i + (u_j − u_i) s_i / (s_i − s_j) (linear interpolation of the turn), its point on the polyline.
//! * **Length**: the length of the polyline Σ |P_{k+1} − P_k| (a lower bound of the curve's length).
//! * **Distances to data** W_i: the distance of W_i to the polyline, min over its segments of the point–segment
//!   distance; the largest of them with its index, and the root mean square √(Σ d_i² / m).
//!
//! Continuity at the joints is not measured here: a construction knows it (a B-spline of degree p is C^(p−m) at
//! a knot of multiplicity m), so the caller states it.

use crate::error::{Error, ErrorKind, Result};

/// A point of the curve with its parameter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurvePoint {
    /// The parameter u.
    pub u: f64,
    /// x(u).
    pub x: f64,
    /// y(u).
    pub y: f64,
}

/// How far data points lie from the sampled curve.
#[derive(Clone, Debug, PartialEq)]
pub struct DataDistances {
    /// The distance of each data point to the polyline, in the data's order.
    pub distances: Vec<f64>,
    /// The index of the farthest data point (the first one on ties).
    pub max_index: usize,
    /// Its distance.
    pub max: f64,
    /// The root mean square of the distances.
    pub rms: f64,
}

/// The facts of a sampled plane curve ([module docs](self)).
#[derive(Clone, Debug, PartialEq)]
pub struct CurveFacts {
    /// The point of least x.
    pub leftmost: CurvePoint,
    /// The point of greatest x.
    pub rightmost: CurvePoint,
    /// The point of least y.
    pub lowest: CurvePoint,
    /// The point of greatest y.
    pub highest: CurvePoint,
    /// The inflections, in the order of u.
    pub inflections: Vec<CurvePoint>,
    /// The polyline's length.
    pub length: f64,
    /// Distances to the data points, when data were given.
    pub data: Option<DataDistances>,
}

/// The facts of the curve through `points` at `params` (ascending, one per point), with distances to `data`
/// when given. Errors: fewer than 2 points (`points`, too-few), a parameter count that differs from the point
/// count (`params`, incompatible), decreasing parameters (`params`, not-increasing), non-finite numbers.
pub fn curve_facts(
    params: &[f64],
    points: &[[f64; 2]],
    data: Option<&[[f64; 2]]>,
) -> Result<CurveFacts> {
    let n = points.len();
    if n < 2 {
        return Err(Error::too_few_of(
            "points",
            2,
            n,
            "a curve needs at least 2 points",
        ));
    }
    if params.len() != n {
        return Err(Error::new(
            ErrorKind::SizeMismatch,
            "params",
            format!(
                "one parameter per point: {n} points, {} parameters",
                params.len()
            ),
        ));
    }
    check_finite("params", params.iter().copied())?;
    check_finite("points", points.iter().flatten().copied())?;
    if let Some(d) = data {
        check_finite("data", d.iter().flatten().copied())?;
    }
    if let Some(k) = (1..n).find(|&k| params[k] < params[k - 1]) {
        return Err(Error::new(
            ErrorKind::NotIncreasing,
            format!("params[{k}]"),
            format!(
                "parameters must not decrease: {} after {}",
                params[k],
                params[k - 1]
            ),
        ));
    }
    Ok(CurveFacts {
        leftmost: extreme(params, points, 0, false),
        rightmost: extreme(params, points, 0, true),
        lowest: extreme(params, points, 1, false),
        highest: extreme(params, points, 1, true),
        inflections: inflections(params, points),
        length: points.windows(2).map(|w| dist(w[0], w[1])).sum(),
        data: data.map(|d| data_distances(points, d)),
    })
}

fn check_finite(field: &'static str, xs: impl Iterator<Item = f64>) -> Result<()> {
    for (i, x) in xs.enumerate() {
        if !x.is_finite() {
            return Err(Error::new(
                ErrorKind::NotFinite,
                format!("{field}[{i}]"),
                crate::error::not_finite_detail(x),
            ));
        }
    }
    Ok(())
}

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (b[0] - a[0]).hypot(b[1] - a[1])
}

/// The extreme of coordinate `c` (0: x, 1: y), the greatest when `max`, refined by the parabola in u.
fn extreme(params: &[f64], points: &[[f64; 2]], c: usize, max: bool) -> CurvePoint {
    let better = |a: f64, b: f64| if max { a > b } else { a < b };
    let mut k = 0;
    for i in 1..points.len() {
        if better(points[i][c], points[k][c]) {
            k = i;
        }
    }
    let at = |i: usize| CurvePoint {
        u: params[i],
        x: points[i][0],
        y: points[i][1],
    };
    if k == 0 || k + 1 == points.len() {
        return at(k);
    }
    let (u0, u1, u2) = (params[k - 1], params[k], params[k + 1]);
    let (c0, c1, c2) = (points[k - 1][c], points[k][c], points[k + 1][c]);
    // the parabola c(u) through the three samples: its divided differences; the vertex where c'(u) = 0
    if !(u0 < u1 && u1 < u2) {
        return at(k);
    }
    let d01 = (c1 - c0) / (u1 - u0);
    let d12 = (c2 - c1) / (u2 - u1);
    let d012 = (d12 - d01) / (u2 - u0);
    if d012 == 0.0 {
        return at(k);
    }
    // c(u) = c0 + d01 (u − u0) + d012 (u − u0)(u − u1): c'(u*) = 0
    let us = ((u0 + u1) - d01 / d012) / 2.0;
    let us = us.clamp(u0, u2);
    let lagrange = |v0: f64, v1: f64, v2: f64| {
        let l0 = (us - u1) * (us - u2) / ((u0 - u1) * (u0 - u2));
        let l1 = (us - u0) * (us - u2) / ((u1 - u0) * (u1 - u2));
        let l2 = (us - u0) * (us - u1) / ((u2 - u0) * (u2 - u1));
        v0 * l0 + v1 * l1 + v2 * l2
    };
    let x = lagrange(points[k - 1][0], points[k][0], points[k + 1][0]);
    let y = lagrange(points[k - 1][1], points[k][1], points[k + 1][1]);
    CurvePoint { u: us, x, y }
}

/// The sine of the turn at each inner sample k = 1 … n − 2 (0 where a chord has zero length).
fn turns(points: &[[f64; 2]]) -> Vec<f64> {
    points
        .windows(3)
        .map(|w| {
            let a = [w[1][0] - w[0][0], w[1][1] - w[0][1]];
            let b = [w[2][0] - w[1][0], w[2][1] - w[1][1]];
            let norms = a[0].hypot(a[1]) * b[0].hypot(b[1]);
            if norms > 0.0 {
                (a[0] * b[1] - a[1] * b[0]) / norms
            } else {
                0.0
            }
        })
        .collect()
}

/// The inflections: sign changes of the turn, ignoring turns below the tolerance (module docs).
fn inflections(params: &[f64], points: &[[f64; 2]]) -> Vec<CurvePoint> {
    let s = turns(points);
    let biggest = s.iter().fold(0.0_f64, |m, t| m.max(t.abs()));
    let tol = (1e-4 * biggest).max(1e-10);
    let mut out = Vec::new();
    let mut last: Option<(usize, f64)> = None; // (sample index, turn) of the last signed turn
    for (i, &t) in s.iter().enumerate() {
        if t.abs() <= tol {
            continue;
        }
        let k = i + 1; // the turn s[i] is at sample i + 1
        if let Some((j, tj)) = last {
            if (tj > 0.0) != (t > 0.0) {
                let u = params[j] + (params[k] - params[j]) * tj / (tj - t);
                out.push(on_polyline(params, points, u));
            }
        }
        last = Some((k, t));
    }
    out
}

/// The point of the polyline at parameter u (linear between the samples around u).
fn on_polyline(params: &[f64], points: &[[f64; 2]], u: f64) -> CurvePoint {
    let k = params
        .partition_point(|&p| p <= u)
        .clamp(1, params.len() - 1);
    let (u0, u1) = (params[k - 1], params[k]);
    let t = if u1 > u0 {
        ((u - u0) / (u1 - u0)).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let (a, b) = (points[k - 1], points[k]);
    CurvePoint {
        u,
        x: a[0] + t * (b[0] - a[0]),
        y: a[1] + t * (b[1] - a[1]),
    }
}

/// The distance from `p` to the segment `a`–`b`.
pub fn point_segment_distance(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let ab = [b[0] - a[0], b[1] - a[1]];
    let len2 = ab[0] * ab[0] + ab[1] * ab[1];
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1]) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    dist(p, [a[0] + t * ab[0], a[1] + t * ab[1]])
}

fn data_distances(points: &[[f64; 2]], data: &[[f64; 2]]) -> DataDistances {
    let distances: Vec<f64> = data
        .iter()
        .map(|&w| {
            points
                .windows(2)
                .map(|s| point_segment_distance(w, s[0], s[1]))
                .fold(f64::INFINITY, f64::min)
        })
        .collect();
    let mut max_index = 0;
    for (i, &d) in distances.iter().enumerate() {
        if d > distances[max_index] {
            max_index = i;
        }
    }
    let m = distances.len();
    let rms = if m > 0 {
        (distances.iter().map(|d| d * d).sum::<f64>() / m as f64).sqrt()
    } else {
        0.0
    };
    DataDistances {
        max: distances.get(max_index).copied().unwrap_or(0.0),
        max_index,
        rms,
        distances,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(n: usize, f: impl Fn(f64) -> [f64; 2]) -> (Vec<f64>, Vec<[f64; 2]>) {
        let us: Vec<f64> = (0..n).map(|k| k as f64 / (n - 1) as f64).collect();
        let ps = us.iter().map(|&u| f(u)).collect();
        (us, ps)
    }

    #[test]
    fn parabola_vertex_is_exact_between_samples() {
        // y = (u − 0.33)² + 1 on 11 samples: the vertex u = 0.33 lies between samples 3 and 4
        let (us, ps) = sample(11, |u| [2.0 * u, (u - 0.33) * (u - 0.33) + 1.0]);
        let f = curve_facts(&us, &ps, None).unwrap();
        assert!((f.lowest.u - 0.33).abs() < 1e-12, "{:?}", f.lowest);
        assert!((f.lowest.y - 1.0).abs() < 1e-12);
        assert!((f.lowest.x - 0.66).abs() < 1e-12);
        assert_eq!(f.leftmost.u, 0.0);
        assert_eq!(f.rightmost.x, 2.0);
        assert!(f.inflections.is_empty());
    }

    #[test]
    fn cubic_inflects_once_at_its_known_parameter() {
        // y = (u − 0.4)³: curvature changes sign at u = 0.4
        let (us, ps) = sample(201, |u| [u, (u - 0.4).powi(3)]);
        let f = curve_facts(&us, &ps, None).unwrap();
        assert_eq!(f.inflections.len(), 1);
        assert!(
            (f.inflections[0].u - 0.4).abs() < 1e-3,
            "{:?}",
            f.inflections
        );
        assert!(f.inflections[0].y.abs() < 1e-6);
    }

    #[test]
    fn circle_extremes_at_the_quarter_turns() {
        let tau = std::f64::consts::TAU;
        let (us, ps) = sample(101, |u| [(tau * u).cos(), (tau * u).sin()]);
        let f = curve_facts(&us, &ps, None).unwrap();
        assert!((f.highest.u - 0.25).abs() < 1e-4 && (f.highest.y - 1.0).abs() < 1e-6);
        assert!((f.leftmost.u - 0.5).abs() < 1e-4 && (f.leftmost.x + 1.0).abs() < 1e-6);
        assert!((f.lowest.u - 0.75).abs() < 1e-4 && (f.lowest.y + 1.0).abs() < 1e-6);
        assert!(
            f.inflections.is_empty(),
            "a convex curve: {:?}",
            f.inflections
        );
        assert!((f.length - tau).abs() < 1e-2);
    }

    #[test]
    fn straight_line_has_no_inflection() {
        let (us, ps) = sample(500, |u| [3.0 * u + 0.1, -2.0 * u + 7.0]);
        let f = curve_facts(&us, &ps, None).unwrap();
        assert!(f.inflections.is_empty(), "{:?}", f.inflections);
        assert!((f.length - 13f64.sqrt()).abs() < 1e-12);
    }

    #[test]
    fn distances_of_known_points_to_a_segment() {
        let ps = [[0.0, 0.0], [4.0, 0.0]];
        let data = [[2.0, 3.0], [-3.0, 4.0], [5.0, 0.0], [1.0, 0.0]];
        let f = curve_facts(&[0.0, 1.0], &ps, Some(&data)).unwrap();
        let d = f.data.unwrap();
        assert_eq!(d.distances, vec![3.0, 5.0, 1.0, 0.0]);
        assert_eq!((d.max_index, d.max), (1, 5.0));
        assert!((d.rms - (35.0f64 / 4.0).sqrt()).abs() < 1e-12);
    }

    #[test]
    fn bad_input_names_the_field() {
        let e = curve_facts(&[0.0], &[[0.0, 0.0]], None).unwrap_err();
        assert_eq!((e.kind(), e.field()), (ErrorKind::TooFew, "points"));
        let e = curve_facts(&[0.0], &[[0.0, 0.0], [1.0, 0.0]], None).unwrap_err();
        assert_eq!((e.kind(), e.field()), (ErrorKind::SizeMismatch, "params"));
        let e = curve_facts(&[1.0, 0.0], &[[0.0, 0.0], [1.0, 0.0]], None).unwrap_err();
        assert_eq!(
            (e.kind(), e.field()),
            (ErrorKind::NotIncreasing, "params[1]")
        );
    }
}
