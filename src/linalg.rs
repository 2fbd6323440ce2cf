//! Small dense linear algebra: LU factorisation with partial pivoting ([`Lu`]), factorised once and reused
//! for many right-hand sides of points (so one factorisation serves every coordinate and every row of a
//! skinning or a set of cardinal functions).
//!
//! Sizes in SplineLab are small (collocation matrices of interpolation, the 3×3 normal equations of the
//! thin-plate energy); a dense solver keeps the code short. Singular systems return a `Degenerate` error.

use crate::error::{Error, Result};
use crate::point::Point;

/// A dense row-major square matrix.
#[derive(Debug, Clone, PartialEq)]
pub struct Matrix {
    n: usize,
    a: Vec<f64>,
}

impl Matrix {
    /// The `n × n` zero matrix.
    pub fn zeros(n: usize) -> Self {
        Matrix {
            n,
            a: vec![0.0; n * n],
        }
    }
    /// The number of rows (= columns).
    pub fn size(&self) -> usize {
        self.n
    }
    /// The entry (i, j).
    pub fn get(&self, i: usize, j: usize) -> f64 {
        self.a[i * self.n + j]
    }
    /// Sets the entry (i, j).
    pub fn set(&mut self, i: usize, j: usize, x: f64) {
        self.a[i * self.n + j] = x;
    }
    /// Row i, mutable.
    pub fn row_mut(&mut self, i: usize) -> &mut [f64] {
        &mut self.a[i * self.n..(i + 1) * self.n]
    }

    /// Factorises the matrix (`P A = L U`); a (numerically) singular matrix is a `Degenerate` error about
    /// `field`.
    pub fn lu(&self, field: &'static str) -> Result<Lu> {
        Lu::new(self.n, self.a.clone(), field)
    }

    /// Solves `A x = b` in place of `b`. `field` names the input that made the system singular, for the
    /// error message.
    pub fn solve<P: Point>(self, b: &mut [P], field: &'static str) -> Result<()> {
        let n = self.n;
        if b.len() != n {
            return Err(Error::size_mismatch(
                field,
                format!("right-hand side has {} rows, matrix {n}", b.len()),
            ));
        }
        Lu::new(n, self.a, field)?.solve(b);
        Ok(())
    }
}

/// `P A = L U` of a square matrix, row-major.
#[derive(Debug, Clone)]
pub struct Lu {
    n: usize,
    a: Vec<f64>,
    perm: Vec<usize>,
    /// Per row: the first non-zero column of L and one past the last non-zero column of U (collocation
    /// matrices are banded; the substitutions skip the zeros).
    band: Vec<(usize, usize)>,
}

impl Lu {
    /// Factorises the row-major `n × n` matrix `a`; a (numerically) singular matrix is a `Degenerate`
    /// error about `field`.
    pub fn new(n: usize, mut a: Vec<f64>, field: &'static str) -> Result<Self> {
        debug_assert_eq!(a.len(), n * n);
        let scale = a
            .iter()
            .fold(0.0_f64, |m, x| m.max(x.abs()))
            .max(f64::MIN_POSITIVE);
        let mut perm: Vec<usize> = (0..n).collect();
        for col in 0..n {
            let (piv, pmax) = (col..n)
                .map(|r| (r, a[r * n + col].abs()))
                .fold((col, -1.0), |b, x| if x.1 > b.1 { x } else { b });
            if !(pmax > 1e-13 * scale) {
                return Err(Error::degenerate(
                    field,
                    "the linear system is singular (are points, parameters or breakpoints coincident?)",
                ));
            }
            if piv != col {
                for j in 0..n {
                    a.swap(piv * n + j, col * n + j);
                }
                perm.swap(piv, col);
            }
            let d = a[col * n + col];
            for r in col + 1..n {
                let f = a[r * n + col] / d;
                a[r * n + col] = f;
                if f != 0.0 {
                    for j in col + 1..n {
                        a[r * n + j] -= f * a[col * n + j];
                    }
                }
            }
        }
        let band = (0..n)
            .map(|i| {
                let lo = (0..i).find(|&j| a[i * n + j] != 0.0).unwrap_or(i);
                let hi = (i + 1..n)
                    .rev()
                    .find(|&j| a[i * n + j] != 0.0)
                    .map_or(i + 1, |j| j + 1);
                (lo, hi)
            })
            .collect();
        Ok(Lu { n, a, perm, band })
    }

    /// Solves `A x = b`; `b` has `n` entries and is overwritten by `x`.
    pub fn solve<P: Point>(&self, b: &mut [P]) {
        let n = self.n;
        let pb: Vec<P> = self.perm.iter().map(|&i| b[i]).collect();
        b.copy_from_slice(&pb);
        for i in 0..n {
            let mut acc = b[i];
            for j in self.band[i].0..i {
                acc -= b[j] * self.a[i * n + j];
            }
            b[i] = acc;
        }
        for i in (0..n).rev() {
            let mut acc = b[i];
            for j in i + 1..self.band[i].1 {
                acc -= b[j] * self.a[i * n + j];
            }
            b[i] = acc * (1.0 / self.a[i * n + i]);
        }
    }
}

impl Lu {
    /// Solves `A x = b` with one step of iterative refinement against the original matrix `a`
    /// (row-major, the one that was factorised): residual errors drop to about one ulp.
    pub(crate) fn solve_refined(&self, a: &[f64], b: &mut [f64]) {
        let n = self.n;
        let rhs = b.to_vec();
        self.solve(b);
        let mut res: Vec<f64> = (0..n)
            .map(|i| rhs[i] - (0..n).map(|j| a[i * n + j] * b[j]).sum::<f64>())
            .collect();
        self.solve(&mut res);
        for (x, d) in b.iter_mut().zip(res) {
            *x += d;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    #[test]
    fn solves_with_pivoting() {
        let mut m = Matrix::zeros(3);
        let rows = [[0.0, 2.0, 1.0], [1.0, 1.0, 0.0], [3.0, 0.0, 1.0]];
        for (i, r) in rows.iter().enumerate() {
            m.row_mut(i).copy_from_slice(r);
        }
        // x = (1, 2), (−1, 0), (0.5, 3) per coordinate
        let x = [
            DVec2::new(1.0, 2.0),
            DVec2::new(-1.0, 0.0),
            DVec2::new(0.5, 3.0),
        ];
        let mut b: Vec<DVec2> = rows
            .iter()
            .map(|r| x[0] * r[0] + x[1] * r[1] + x[2] * r[2])
            .collect();
        m.solve(&mut b, "t").unwrap();
        for (a, e) in b.iter().zip(&x) {
            assert!((*a - *e).length() < 1e-14);
        }
    }

    #[test]
    fn singular_is_an_error() {
        let mut m = Matrix::zeros(2);
        m.row_mut(0).copy_from_slice(&[1.0, 2.0]);
        m.row_mut(1).copy_from_slice(&[2.0, 4.0]);
        let mut b = [1.0, 2.0];
        assert_eq!(
            m.solve(&mut b, "params").unwrap_err().kind(),
            crate::ErrorKind::Degenerate
        );
    }

    #[test]
    fn solves_and_reuses() {
        let a = vec![0.0, 2.0, 1.0, 1.0, 1.0, 0.0, 3.0, 0.0, 1.0];
        let lu = Lu::new(3, a.clone(), "t").unwrap();
        for x in [[1.0, -1.0, 0.5], [0.0, 2.0, 3.0]] {
            let mut b: Vec<f64> = (0..3)
                .map(|i| (0..3).map(|j| a[i * 3 + j] * x[j]).sum())
                .collect();
            lu.solve(&mut b);
            for (p, q) in b.iter().zip(x) {
                assert!((p - q).abs() < 1e-15);
            }
        }
        assert!(Lu::new(2, vec![1.0, 2.0, 2.0, 4.0], "t").is_err());
    }
}
