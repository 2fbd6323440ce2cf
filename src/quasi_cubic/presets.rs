//! Exact shapes of quasi-cubic curves and surfaces (the quasi-cubic paper §3, Props. 6–8, Figs. 5–10; `curves.md` §1.1),
//! control data for them, and a measure of how far a curve is from its analytic shape.
//!
//! Curves (all planar):
//! * **ellipse** (Prop. 7): α = 1, closed, four control points forming a parallelogram b_0 + b_2 = b_1 + b_3
//!   (the paper states a rhombus, which puts the axes on the diagonals; by affine invariance any
//!   parallelogram gives an ellipse). With o the centre, the curve is
//!   o + ⅔(b_1 − o)·cos θ + ⅔(b_2 − o)·sin θ: segment i covers θ ∈ [iπ/2, (i+1)π/2].
//! * **circle**: a square, radius ⅔ of the half-diagonal.
//! * **parabola** (Prop. 6): α = 1, four points with b_0 = b_2 (= A; the paper also asks for an isosceles
//!   triangle A b_1 b_3, again not needed by affine invariance). With c = cos(πt/2):
//!   p = [⅔A + (b_1+b_3)/6] + c·(b_1 − b_3)/3 + c²·[(b_1+b_3)/6 − A/3].
//! * **sine** (Prop. 8): α = 0 and, for every segment, x_i + x_{i+3} = x_{i+1} + x_{i+2} (x linear in t) and
//!   y_i + y_{i+1} = y_{i+2} + y_{i+3}; then y = y_c + A·sin(π(x − x_s)/L) with x_s = x_i/4 + x_{i+1}/2 + x_{i+2}/4,
//!   L = (x_{i+2} + x_{i+3} − x_i − x_{i+1})/4, y_c = y_i/4 + y_{i+1}/2 + y_{i+2}/4, A = (y_{i+1} + y_{i+2} − y_i − y_{i+3})/(4π).
//!   The zig-zag b_i = (x₀ + h·i, a·(−1)^i·(i − c)) satisfies both for all segments (the general bounded-or-
//!   linear solution of the y recurrence) and gives one sine wave over the whole curve:
//!   x = x₀ + h(u + 1), y = (a/π)·sin(πu).
//!
//! Surfaces (3D, α = 1 in both directions): a surface of revolution S(u, v) = (R(v)·C(u), Z(v)) is the tensor
//! product of a circle control polygon c_k (square, periodic in u) and a meridian control polygon (R_l, Z_l),
//! with b_kl = (R_l·c_k, Z_l): by the partition of unity S = (Σ_l B_l R_l · Σ_k B_k c_k, Σ_l B_l Z_l).
//! * **sphere** of radius ρ: the meridian is the open half of a square (R, Z) = (−d, 0), (0, d), (d, 0), (0, −d),
//!   (−d, 0), d = 3ρ/2, a semicircle from pole to pole, so |S| = ρ exactly.
//! * **cylinder**: a straight meridian (R constant, Z collinear): distance to the axis is exactly ρ.
//! * **torus**: a closed square meridian shifted by R₀: R(v) = R₀ + r cos, Z = r sin.
//! * **bowl** (Fig. 8): a meridian starting on the axis with a horizontal tangent (b_0, b_2 mirror images),
//!   four patches around.

use super::curve::QuasiCubicCurve;
use crate::error::{Error, Result};
use crate::sample::Curve;
use glam::{DVec2, DVec3};
use std::f64::consts::PI;

/// The exact planar shapes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExactShape {
    /// x = a cos t, y = b sin t.
    Ellipse,
    /// The unit circle.
    Circle,
    /// y = x².
    Parabola,
    /// y = sin x.
    Sine,
}

impl ExactShape {
    /// Parses `"ellipse" | "circle" | "parabola" | "sine"`.
    pub fn parse(name: &str) -> Option<Self> {
        match name {
            "ellipse" => Some(Self::Ellipse),
            "circle" => Some(Self::Circle),
            "parabola" => Some(Self::Parabola),
            "sine" => Some(Self::Sine),
            _ => None,
        }
    }
    /// The α at which the shape is exact.
    pub fn alpha(self) -> f64 {
        match self {
            Self::Sine => 0.0,
            _ => 1.0,
        }
    }
    /// Whether the curve is closed (periodic).
    pub fn closed(self) -> bool {
        matches!(self, Self::Ellipse | Self::Circle)
    }
    /// The condition on the control points, in words.
    pub fn condition(self) -> &'static str {
        match self {
            Self::Ellipse => "α = 1 and b0 + b2 = b1 + b3 (a parallelogram; the paper's rhombus puts the axes on the diagonals)",
            Self::Circle => "α = 1 and a square: b0 + b2 = b1 + b3, equal and perpendicular diagonals",
            Self::Parabola => "α = 1 and b0 = b2 (the paper also asks for an isosceles triangle b0 b1 b3)",
            Self::Sine => "α = 0 and, for each segment, xᵢ + xᵢ₊₃ = xᵢ₊₁ + xᵢ₊₂ and yᵢ + yᵢ₊₁ = yᵢ₊₂ + yᵢ₊₃",
        }
    }
}

/// Control points of a circle: the square with half-diagonal 3r/2 (closed, α = 1).
pub fn circle(center: DVec2, radius: f64) -> Vec<DVec2> {
    ellipse(center, radius, radius)
}

/// Control points of an axis-aligned ellipse with semi-axes `a` (x) and `b` (y): the rhombus with
/// half-diagonals 3a/2 and 3b/2 (closed, α = 1). The curve starts at u = 0 at the top (centre + (0, b)).
pub fn ellipse(center: DVec2, a: f64, b: f64) -> Vec<DVec2> {
    let (ha, hb) = (1.5 * a, 1.5 * b);
    vec![
        center + DVec2::new(ha, 0.0),
        center + DVec2::new(0.0, hb),
        center + DVec2::new(-ha, 0.0),
        center + DVec2::new(0.0, -hb),
    ]
}

/// Control points of a parabola arc: [apex, left, apex, right] (open, one segment, α = 1).
pub fn parabola(apex: DVec2, left: DVec2, right: DVec2) -> Vec<DVec2> {
    vec![apex, left, apex, right]
}

/// Control points of a sine wave over `segments` half-periods (open, α = 0): the zig-zag
/// b_i = (x0 + h·i, a·(−1)^i·(i − (segments + 2)/2)); the curve is x = x0 + h(u + 1), y = (a/π)·sin(πu),
/// i.e. y = (a/π)·sin(π(x − x0 − h)/h): a sine of amplitude |a|/π and half-period h.
pub fn sine(x0: f64, h: f64, a: f64, segments: usize) -> Vec<DVec2> {
    let c = (segments as f64 + 2.0) / 2.0;
    (0..segments + 3)
        .map(|i| {
            let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
            DVec2::new(x0 + h * i as f64, a * sign * (i as f64 - c))
        })
        .collect()
}

/// How far a curve is from the analytic shape its control points define.
#[derive(Debug, Clone, PartialEq)]
pub struct ShapeCheck {
    /// Largest deviation (a distance) of the sampled curve from the analytic shape.
    pub deviation: f64,
    /// Largest residual of the conditions on the control points (0 when they hold); α is checked
    /// separately (`alpha_ok`).
    pub condition_residual: f64,
    /// Per-segment residuals of the condition (sine: |x_i + x_{i+3} − x_{i+1} − x_{i+2}| and
    /// |y_i + y_{i+1} − y_{i+2} − y_{i+3}| as pairs, flat; the other shapes: one value, the whole polygon).
    pub segment_residuals: Vec<f64>,
    /// Whether α equals the shape's α.
    pub alpha_ok: bool,
    /// Points of the analytic shape (for overlays).
    pub analytic: Vec<DVec2>,
    /// The curve samples the deviation was measured on.
    pub params: Vec<f64>,
}

fn need(points: &[DVec2], exact: Option<usize>, min: usize, shape: &str) -> Result<()> {
    let n = points.len();
    match exact {
        Some(e) if n != e => Err(Error::size_mismatch(
            "points",
            format!("the {shape} preset needs exactly {e} control points, got {n}"),
        )),
        _ if n < min => Err(Error::too_few(
            "points",
            format!("the {shape} preset needs at least {min} control points, got {n}"),
        )),
        _ => Ok(()),
    }
}

/// Solves x·e1 + y·e2 = r (2×2); `None` when e1, e2 are (nearly) parallel.
fn solve2(e1: DVec2, e2: DVec2, r: DVec2) -> Option<(f64, f64)> {
    let det = crate::point::cross2(e1, e2);
    let scale = e1.length() * e2.length();
    if det.is_nan() || det.abs() <= 1e-14 * scale {
        return None;
    }
    Some((
        crate::point::cross2(r, e2) / det,
        crate::point::cross2(e1, r) / det,
    ))
}

/// Measures the curve of `points` at `alpha` (closed for the ellipse/circle) against the analytic shape
/// that the points define if the shape's conditions hold. `per_segment` samples per segment (≥ 2).
pub fn check_shape(
    shape: ExactShape,
    alpha: f64,
    points: &[DVec2],
    per_segment: usize,
) -> Result<ShapeCheck> {
    let per_segment = per_segment.clamp(2, 10_000);
    match shape {
        ExactShape::Ellipse | ExactShape::Circle => need(points, Some(4), 4, "ellipse/circle")?,
        ExactShape::Parabola => need(points, Some(4), 4, "parabola")?,
        ExactShape::Sine => need(points, None, 4, "sine")?,
    }
    let curve = if shape.closed() {
        QuasiCubicCurve::closed(alpha, points.to_vec())?
    } else {
        QuasiCubicCurve::new(alpha, points.to_vec())?
    };
    let n = curve.segments();
    let params = crate::sample::uniform_params(0.0, n as f64, n * per_segment + 1);
    let samples: Vec<DVec2> = params.iter().map(|&u| curve.eval(u)).collect();
    let b = points;
    let mut analytic = Vec::new();
    let mut segment_residuals = Vec::new();
    let (deviation, residual) = match shape {
        ExactShape::Ellipse | ExactShape::Circle => {
            let o = (b[0] + b[1] + b[2] + b[3]) * 0.25;
            let par = (b[0] + b[2] - b[1] - b[3]).length();
            if shape == ExactShape::Circle {
                let r = (2.0 / 3.0) * b.iter().map(|p| p.distance(o)).sum::<f64>() / 4.0;
                let (d1, d2) = (b[2] - b[0], b[3] - b[1]);
                let res = par
                    .max((d1.length() - d2.length()).abs())
                    .max(d1.dot(d2).abs() / d1.length().max(d2.length()).max(f64::MIN_POSITIVE));
                for k in 0..=128 {
                    let th = 2.0 * PI * k as f64 / 128.0;
                    analytic.push(o + DVec2::new(th.cos(), th.sin()) * r);
                }
                let dev = samples
                    .iter()
                    .map(|p| (p.distance(o) - r).abs())
                    .fold(0.0, f64::max);
                (dev, res)
            } else {
                let e1 = (b[1] - b[3]) * (1.0 / 3.0);
                let e2 = (b[2] - b[0]) * (1.0 / 3.0);
                for k in 0..=128 {
                    let th = 2.0 * PI * k as f64 / 128.0;
                    analytic.push(o + e1 * th.cos() + e2 * th.sin());
                }
                let mut dev = 0.0_f64;
                for p in &samples {
                    let d = match solve2(e1, e2, *p - o) {
                        Some((c, s)) => {
                            let r = c.hypot(s);
                            if r == 0.0 {
                                p.distance(o).max(e1.length().min(e2.length()))
                            } else {
                                p.distance(o) * (1.0 - 1.0 / r).abs()
                            }
                        }
                        None => f64::INFINITY,
                    };
                    dev = dev.max(d);
                }
                (dev, par)
            }
        }
        ExactShape::Parabola => {
            let a = (b[0] + b[2]) * 0.5;
            let p0 = a * (2.0 / 3.0) + (b[1] + b[3]) * (1.0 / 6.0);
            let e1 = (b[1] - b[3]) * (1.0 / 3.0);
            let e2 = (b[1] + b[3]) * (1.0 / 6.0) - a * (1.0 / 3.0);
            let mut dev = 0.0_f64;
            // the parabola's parameter c over the curve (c = cos(πt/2) ∈ [0, 1] when the condition holds): the
            // overlay covers exactly that arc, not a wider band around a short curve
            let (mut c_lo, mut c_hi) = (f64::INFINITY, f64::NEG_INFINITY);
            for p in &samples {
                let d = match solve2(e1, e2, *p - p0) {
                    Some((c, w)) => {
                        c_lo = c_lo.min(c);
                        c_hi = c_hi.max(c);
                        (w - c * c).abs() * e2.length()
                    }
                    None => f64::INFINITY,
                };
                dev = dev.max(d);
            }
            if !(c_lo.is_finite() && c_hi.is_finite() && c_hi > c_lo) {
                (c_lo, c_hi) = (-1.25, 1.25);
            }
            for k in 0..=128 {
                let c = c_lo + (c_hi - c_lo) * k as f64 / 128.0;
                analytic.push(p0 + e1 * c + e2 * (c * c));
            }
            (dev, b[0].distance(b[2]))
        }
        ExactShape::Sine => {
            let mut res = 0.0_f64;
            // per segment: (x_s, L, y_c, A)
            let mut seg = Vec::with_capacity(n);
            for i in 0..n {
                let q = &b[i..i + 4];
                let (x, y) = (
                    [q[0].x, q[1].x, q[2].x, q[3].x],
                    [q[0].y, q[1].y, q[2].y, q[3].y],
                );
                let (rx, ry) = (
                    (x[0] + x[3] - x[1] - x[2]).abs(),
                    (y[0] + y[1] - y[2] - y[3]).abs(),
                );
                segment_residuals.extend([rx, ry]);
                res = res.max(rx).max(ry);
                let xs = x[0] / 4.0 + x[1] / 2.0 + x[2] / 4.0;
                let len = (x[2] + x[3] - x[0] - x[1]) / 4.0;
                let yc = y[0] / 4.0 + y[1] / 2.0 + y[2] / 4.0;
                let amp = (y[1] + y[2] - y[0] - y[3]) / (4.0 * PI);
                seg.push((xs, len, yc, amp));
            }
            let f = |(xs, len, yc, amp): (f64, f64, f64, f64), xx: f64| {
                yc + amp * (PI * (xx - xs) / len).sin()
            };
            for (i, s) in seg.iter().enumerate() {
                let start = if i == 0 { 0 } else { 1 };
                for k in start..=32 {
                    let xx = s.0 + s.1 * k as f64 / 32.0;
                    analytic.push(DVec2::new(xx, f(*s, xx)));
                }
            }
            let mut dev = 0.0_f64;
            for (u, p) in params.iter().zip(&samples) {
                let s = seg[curve.locate(*u).0];
                let d = if s.1 == 0.0 {
                    f64::INFINITY
                } else {
                    (p.y - f(s, p.x)).abs()
                };
                dev = dev.max(d);
            }
            (dev, res)
        }
    };
    if !deviation.is_finite() {
        // the analytic frame (axes of the ellipse, of the parabola, span of a sine segment) is degenerate
        return Err(Error::degenerate(
            "points",
            format!("the control polygon is degenerate: the analytic {shape:?} it should reproduce is not defined"),
        ));
    }
    if segment_residuals.is_empty() {
        segment_residuals.push(residual);
    }
    Ok(ShapeCheck {
        deviation,
        condition_residual: residual,
        segment_residuals,
        alpha_ok: alpha == shape.alpha(),
        analytic,
        params,
    })
}

/// A tensor control net (row-major `rows × cols`, row i along u) with its periodicity and α.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceNet {
    /// Rows (along u).
    pub rows: usize,
    /// Columns (along v).
    pub cols: usize,
    /// Control points, row-major.
    pub grid: Vec<DVec3>,
    /// Whether the net is closed in (u, v).
    pub periodic: (bool, bool),
    /// The shape parameter α that makes the shape exact.
    pub alpha: f64,
}

/// The net of a surface of revolution about the z axis: circle polygon (unit circle: square with
/// half-diagonal 3/2, periodic in u) × meridian polygon (R_l, Z_l).
pub fn revolution(meridian: &[DVec2], closed_meridian: bool) -> SurfaceNet {
    let circle = circle(DVec2::ZERO, 1.0);
    let mut grid = Vec::with_capacity(4 * meridian.len());
    for c in &circle {
        for m in meridian {
            grid.push(DVec3::new(m.x * c.x, m.x * c.y, m.y));
        }
    }
    SurfaceNet {
        rows: 4,
        cols: meridian.len(),
        grid,
        periodic: (true, closed_meridian),
        alpha: 1.0,
    }
}

/// A sphere of radius ρ about the origin (exact at α = 1): u ∈ [0, 4] around, v ∈ [0, 2] pole to pole.
pub fn sphere(radius: f64) -> SurfaceNet {
    let d = 1.5 * radius;
    revolution(
        &[
            DVec2::new(-d, 0.0),
            DVec2::new(0.0, d),
            DVec2::new(d, 0.0),
            DVec2::new(0.0, -d),
            DVec2::new(-d, 0.0),
        ],
        false,
    )
}

/// A cylinder of radius ρ about the z axis, z from about −h/2 to h/2 (exact at α = 1 in u).
pub fn cylinder(radius: f64, height: f64) -> SurfaceNet {
    let m: Vec<DVec2> = (0..6)
        .map(|l| DVec2::new(radius, height * (l as f64 - 2.5) / 3.0))
        .collect();
    revolution(&m, false)
}

/// A torus: tube radius r about the circle of radius R₀ in the xy plane (exact at α = 1).
pub fn torus(major: f64, minor: f64) -> SurfaceNet {
    let d = 1.5 * minor;
    revolution(
        &[
            DVec2::new(major + d, 0.0),
            DVec2::new(major, d),
            DVec2::new(major - d, 0.0),
            DVec2::new(major, -d),
        ],
        true,
    )
}

/// The bowl of Fig. 8: four patches around, a meridian from the axis (horizontal tangent) to the rim.
pub fn bowl() -> SurfaceNet {
    revolution(
        &[
            DVec2::new(-1.0, 0.6),
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 0.6),
            DVec2::new(1.5, 2.4),
        ],
        false,
    )
}

/// A wavy (m+3) × (n+3) grid over [−1, 1]² (z = small bumps), for blended interpolation surfaces.
pub fn wavy_grid(m: usize, n: usize) -> SurfaceNet {
    let (rows, cols) = (m + 3, n + 3);
    let mut grid = Vec::with_capacity(rows * cols);
    for i in 0..rows {
        for j in 0..cols {
            let x = -1.0 + 2.0 * (i as f64 - 1.0) / m as f64;
            let y = -1.0 + 2.0 * (j as f64 - 1.0) / n as f64;
            let z = 0.35 * (1.7 * x).cos() * (1.3 * y + 0.4).sin() + 0.15 * x * y;
            grid.push(DVec3::new(x, y, z));
        }
    }
    SurfaceNet {
        rows,
        cols,
        grid,
        periodic: (false, false),
        alpha: 3.0,
    }
}

/// Largest | |S(u, v) − centre| − ρ | over an n × n grid of the surface's domain (the sphere check).
pub fn max_radial_error<S: crate::sample::Surface<DVec3>>(
    s: &S,
    centre: DVec3,
    radius: f64,
    n: usize,
) -> f64 {
    let uv = crate::sample::uv_grid(s.domain(), n, n);
    uv.chunks_exact(2)
        .map(|w| (s.eval(w[0], w[1]).distance(centre) - radius).abs())
        .fold(0.0, f64::max)
}

/// Largest | dist(S(u, v), z axis) − ρ | over an n × n grid (the cylinder check).
pub fn max_axis_error<S: crate::sample::Surface<DVec3>>(s: &S, radius: f64, n: usize) -> f64 {
    let uv = crate::sample::uv_grid(s.domain(), n, n);
    uv.chunks_exact(2)
        .map(|w| {
            let p = s.eval(w[0], w[1]);
            (p.x.hypot(p.y) - radius).abs()
        })
        .fold(0.0, f64::max)
}
