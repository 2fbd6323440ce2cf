//! The small point abstraction every construction is written against.
//!
//! Basis functions produce **weights**; weights combine **points**. A [`Point`] is anything that can be
//! combined affinely: `f64` (scalar data, e.g. to obtain basis/cardinal functions by evaluating a
//! construction on unit data), glam's [`DVec2`] and [`DVec3`]. One evaluation kernel serves all three.

use glam::{DVec2, DVec3};
use std::fmt::Debug;
use std::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};

/// A point (or vector) of a real affine space of dimension [`Point::DIM`].
pub trait Point:
    Copy
    + Debug
    + PartialEq
    + Default
    + Add<Output = Self>
    + Sub<Output = Self>
    + Neg<Output = Self>
    + Mul<f64, Output = Self>
    + AddAssign
    + SubAssign
    + Send
    + Sync
    + 'static
{
    /// Number of coordinates.
    const DIM: usize;
    /// The origin / zero vector.
    const ZERO: Self;

    /// Euclidean inner product.
    fn dot(self, other: Self) -> f64;
    /// Euclidean length.
    fn length(self) -> f64 {
        self.dot(self).sqrt()
    }
    /// Distance between two points.
    fn distance(self, other: Self) -> f64 {
        (self - other).length()
    }
    /// `(1 − t)·self + t·other`.
    fn lerp_to(self, other: Self, t: f64) -> Self {
        self + (other - self) * t
    }
    /// Coordinate `i` (`i < DIM`).
    fn coord(self, i: usize) -> f64;
    /// Builds a point from the first `DIM` entries of `c` (`c.len() >= DIM`, else `None`).
    fn from_coords(c: &[f64]) -> Option<Self>;
    /// Writes the `DIM` coordinates into `out[..DIM]`.
    fn write_coords(self, out: &mut [f64]) {
        for (i, o) in out.iter_mut().take(Self::DIM).enumerate() {
            *o = self.coord(i);
        }
    }
    /// All coordinates finite.
    fn is_finite(self) -> bool {
        (0..Self::DIM).all(|i| self.coord(i).is_finite())
    }
    /// Largest absolute coordinate (a scale for relative tolerances).
    fn max_abs(self) -> f64 {
        (0..Self::DIM)
            .map(|i| self.coord(i).abs())
            .fold(0.0, f64::max)
    }
    /// The curve's curvature from its first and second derivatives, the one formula every curve type
    /// uses ([`crate::sample::Curve::curvature`]): unsigned κ = |c′ × c″| / |c′|³ ([`curvature`]),
    /// except in the plane, where it is signed ([`signed_curvature`], positive turning left).
    fn curvature_of(d1: Self, d2: Self) -> f64 {
        curvature(d1, d2)
    }
}

impl Point for f64 {
    const DIM: usize = 1;
    const ZERO: Self = 0.0;
    fn dot(self, other: Self) -> f64 {
        self * other
    }
    fn coord(self, _i: usize) -> f64 {
        self
    }
    fn from_coords(c: &[f64]) -> Option<Self> {
        c.first().copied()
    }
}

impl Point for DVec2 {
    const DIM: usize = 2;
    const ZERO: Self = DVec2::ZERO;
    fn curvature_of(d1: Self, d2: Self) -> f64 {
        signed_curvature(d1, d2)
    }
    fn dot(self, other: Self) -> f64 {
        DVec2::dot(self, other)
    }
    fn coord(self, i: usize) -> f64 {
        if i == 0 {
            self.x
        } else {
            self.y
        }
    }
    fn from_coords(c: &[f64]) -> Option<Self> {
        match c {
            [x, y, ..] => Some(DVec2::new(*x, *y)),
            _ => None,
        }
    }
}

impl Point for DVec3 {
    const DIM: usize = 3;
    const ZERO: Self = DVec3::ZERO;
    fn dot(self, other: Self) -> f64 {
        DVec3::dot(self, other)
    }
    fn coord(self, i: usize) -> f64 {
        match i {
            0 => self.x,
            1 => self.y,
            _ => self.z,
        }
    }
    fn from_coords(c: &[f64]) -> Option<Self> {
        match c {
            [x, y, z, ..] => Some(DVec3::new(*x, *y, *z)),
            _ => None,
        }
    }
}

/// Affine combination Σ wᵢ·pᵢ (the weights are not checked to sum to 1).
pub fn combine<P: Point>(weights: &[f64], points: &[P]) -> P {
    let mut acc = P::ZERO;
    for (w, p) in weights.iter().zip(points) {
        acc += *p * *w;
    }
    acc
}

/// 2D cross product (signed area of the parallelogram), the z of the 3D cross product.
pub fn cross2(a: DVec2, b: DVec2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// Curvature κ = |c′ × c″| / |c′|³ from first and second derivatives, in any dimension
/// (uses |c′|²|c″|² − (c′·c″)² = |c′ × c″|²). Returns 0 where c′ = 0.
pub fn curvature<P: Point>(d1: P, d2: P) -> f64 {
    let s = d1.dot(d1);
    if s == 0.0 {
        return 0.0;
    }
    let cross2 = (s * d2.dot(d2) - d1.dot(d2).powi(2)).max(0.0);
    cross2.sqrt() / (s * s.sqrt())
}

/// Signed curvature of a planar curve: (x′y″ − y′x″)/|c′|³ (0 where c′ = 0).
pub fn signed_curvature(d1: DVec2, d2: DVec2) -> f64 {
    let s = d1.length_squared();
    if s == 0.0 {
        0.0
    } else {
        cross2(d1, d2) / (s * s.sqrt())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn combine_and_coords() {
        let p = combine(&[0.25, 0.75], &[DVec2::new(0.0, 4.0), DVec2::new(4.0, 0.0)]);
        assert_eq!(p, DVec2::new(3.0, 1.0));
        let mut out = [0.0; 3];
        DVec3::new(1.0, 2.0, 3.0).write_coords(&mut out);
        assert_eq!(out, [1.0, 2.0, 3.0]);
        assert_eq!(DVec3::from_coords(&[1.0, 2.0]), None);
        assert_eq!(<f64 as Point>::from_coords(&[5.0]), Some(5.0));
    }

    #[test]
    fn circle_curvature() {
        // c(t) = r(cos t, sin t) at t = 0.3
        let (r, t) = (2.0_f64, 0.3_f64);
        let d1 = DVec2::new(-r * t.sin(), r * t.cos());
        let d2 = DVec2::new(-r * t.cos(), -r * t.sin());
        assert!((curvature(d1, d2) - 0.5).abs() < 1e-15);
        assert!((signed_curvature(d1, d2) - 0.5).abs() < 1e-15);
        let d1 = DVec3::new(d1.x, d1.y, 0.0);
        let d2 = DVec3::new(d2.x, d2.y, 0.0);
        assert!((curvature(d1, d2) - 0.5).abs() < 1e-15);
    }
}
