//! The number type of the recursion: `f64`, or a [`Jet`] (truncated Taylor series) carrying derivatives.

use std::ops::{Add, Div, Mul, Sub};

// ---------------------------------------------------------------------------------------------------
// Scalars: f64 and truncated Taylor series
// ---------------------------------------------------------------------------------------------------

/// The number type of the recursion: `f64`, or a [`Jet`] to carry derivatives along.
pub trait Scalar:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self>
{
    /// A constant.
    fn constant(x: f64) -> Self;
    /// The value (the constant Taylor coefficient).
    fn value(self) -> f64;
}

impl Scalar for f64 {
    fn constant(x: f64) -> Self {
        x
    }
    fn value(self) -> f64 {
        self
    }
}

/// A truncated Taylor series `c_0 + c_1 ε + … + c_{N−1} ε^{N−1}` in one variable: arithmetic on jets
/// propagates exact derivatives (the i-th derivative is `i!·c_i`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jet<const N: usize>(pub [f64; N]);

impl<const N: usize> Jet<N> {
    /// The independent variable at `x` (`x + ε`).
    pub fn variable(x: f64) -> Self {
        let mut c = [0.0; N];
        c[0] = x;
        if N > 1 {
            c[1] = 1.0;
        }
        Jet(c)
    }
    /// The i-th derivative `i!·c_i`.
    pub fn derivative(&self, i: usize) -> f64 {
        self.0[i] * factorial(i)
    }
}

fn factorial(i: usize) -> f64 {
    (1..=i).fold(1.0, |a, b| a * b as f64)
}

impl<const N: usize> Add for Jet<N> {
    type Output = Self;
    fn add(mut self, o: Self) -> Self {
        for i in 0..N {
            self.0[i] += o.0[i];
        }
        self
    }
}
impl<const N: usize> Sub for Jet<N> {
    type Output = Self;
    fn sub(mut self, o: Self) -> Self {
        for i in 0..N {
            self.0[i] -= o.0[i];
        }
        self
    }
}
impl<const N: usize> Mul for Jet<N> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        let mut c = [0.0; N];
        for i in 0..N {
            for j in 0..=i {
                c[i] += self.0[j] * o.0[i - j];
            }
        }
        Jet(c)
    }
}
impl<const N: usize> Div for Jet<N> {
    type Output = Self;
    fn div(self, o: Self) -> Self {
        let mut q = [0.0; N];
        for i in 0..N {
            let mut s = self.0[i];
            for j in 1..=i {
                s -= o.0[j] * q[i - j];
            }
            q[i] = s / o.0[0];
        }
        Jet(q)
    }
}
impl<const N: usize> Scalar for Jet<N> {
    fn constant(x: f64) -> Self {
        let mut c = [0.0; N];
        c[0] = x;
        Jet(c)
    }
    fn value(self) -> f64 {
        self.0[0]
    }
}

// ---------------------------------------------------------------------------------------------------
