//! Small dense linear algebra: Gaussian elimination with partial pivoting, with a right-hand side of
//! points (so one factorisation serves every coordinate).
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
    pub fn size(&self) -> usize {
        self.n
    }
    pub fn get(&self, i: usize, j: usize) -> f64 {
        self.a[i * self.n + j]
    }
    pub fn set(&mut self, i: usize, j: usize, x: f64) {
        self.a[i * self.n + j] = x;
    }
    pub fn row_mut(&mut self, i: usize) -> &mut [f64] {
        &mut self.a[i * self.n..(i + 1) * self.n]
    }

    /// Solves `A x = b` in place of `b` (A is consumed by the elimination). `field` names the input
    /// that made the system singular, for the error message.
    pub fn solve<P: Point>(mut self, b: &mut [P], field: &'static str) -> Result<()> {
        let n = self.n;
        if b.len() != n {
            return Err(Error::size_mismatch(
                field,
                format!("right-hand side has {} rows, matrix {n}", b.len()),
            ));
        }
        let scale = self
            .a
            .iter()
            .fold(0.0_f64, |m, x| m.max(x.abs()))
            .max(f64::MIN_POSITIVE);
        for col in 0..n {
            // partial pivoting
            let (piv, pmax) = (col..n)
                .map(|r| (r, self.get(r, col).abs()))
                .fold((col, -1.0), |best, x| if x.1 > best.1 { x } else { best });
            if !(pmax > 1e-13 * scale) {
                return Err(Error::degenerate(
                    field,
                    "the linear system is singular (are points or parameters coincident?)",
                ));
            }
            if piv != col {
                for j in 0..n {
                    self.a.swap(piv * n + j, col * n + j);
                }
                b.swap(piv, col);
            }
            let d = self.get(col, col);
            for r in col + 1..n {
                let f = self.get(r, col) / d;
                if f != 0.0 {
                    for j in col..n {
                        let v = self.get(r, j) - f * self.get(col, j);
                        self.set(r, j, v);
                    }
                    let bc = b[col];
                    b[r] -= bc * f;
                }
            }
        }
        for col in (0..n).rev() {
            let mut acc = b[col];
            for j in col + 1..n {
                acc -= b[j] * self.get(col, j);
            }
            b[col] = acc * (1.0 / self.get(col, col));
        }
        Ok(())
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
}
