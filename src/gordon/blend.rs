//! Cardinal C² cubic splines: the blending functions L_r(u) of the spline-blended surface
//! (`../shared/spec/surfaces.md` §6).
//!
//! On nodes u_0 < … < u_m, L_r is the cubic spline with knots at the nodes (clamped cubic B-spline basis on
//! {u_0 ×4, u_1, …, u_{m−1}, u_m ×4}, m + 3 functions) with L_r(u_q) = δ_rq and either
//! * **natural** end conditions L_r″(u_0) = L_r″(u_m) = 0 (m ≥ 1), or
//! * **not-a-knot** end conditions: L_r‴ continuous at u_1 and u_{m−1} (m ≥ 3).
//!
//! Each L_r is stored by its m + 3 B-spline coefficients; one LU factorisation gives all of them.

use crate::bspline::basis_derivs;
use crate::error::{Error, Result};
use crate::knots::{find_span, MAX_DEGREE};
use crate::linalg::Lu;

const W: usize = MAX_DEGREE + 1;

/// End conditions of the cardinal cubic splines.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CubicEnd {
    /// L″ = 0 at both ends.
    Natural,
    /// L‴ continuous at the second and the second-last node (needs m ≥ 3).
    NotAKnot,
}

/// Blending functions L_r(u), r over the nodes, each a cubic B-spline Σ_k c_rk N_k(u) on one common knot
/// vector: the cardinal cubics ([`BlendFunctions::cardinal_cubic`]) or any other cubic blend given by its
/// coefficients ([`BlendFunctions::from_coefficients`], e.g. the B2 basis functions of Kuklišová).
#[derive(Debug, Clone, PartialEq)]
pub struct BlendFunctions {
    nodes: Vec<f64>,
    knots: Vec<f64>,
    /// `coef[r * count + k]`, count = m + 3.
    coef: Vec<f64>,
}

/// The non-zero cubic basis functions at a parameter (values and derivatives up to 2).
#[derive(Debug, Clone, Copy)]
pub struct CubicBasis {
    /// The span: basis functions N_{span−3..=span} are non-zero.
    pub span: usize,
    /// `ders[k][a]` = k-th derivative of N_{span−3+a}.
    pub ders: [[f64; W]; 3],
}

impl BlendFunctions {
    /// The cardinal cubic splines L_0..L_m on `nodes` (strictly increasing, finite); `field` names the
    /// nodes in errors.
    pub fn cardinal_cubic(field: &'static str, nodes: &[f64], end: CubicEnd) -> Result<Self> {
        crate::error::check_finite(field, nodes)?;
        crate::knots::check_increasing(field, nodes)?;
        let m = nodes.len().saturating_sub(1);
        let min = match end {
            CubicEnd::Natural => 1,
            CubicEnd::NotAKnot => 3,
        };
        if m < min {
            return Err(Error::too_few(
                field,
                format!(
                    "{} cubic blending needs at least {} nodes (m ≥ {min}), got {}",
                    match end {
                        CubicEnd::Natural => "natural",
                        CubicEnd::NotAKnot => "not-a-knot",
                    },
                    min + 1,
                    nodes.len()
                ),
            ));
        }
        if nodes.len() > super::MAX_LINES {
            return Err(Error::too_many(
                field,
                format!("at most {} nodes, got {}", super::MAX_LINES, nodes.len()),
            ));
        }
        let (a, b) = (nodes[0], nodes[m]);
        let mut knots = vec![a, a, a];
        knots.extend_from_slice(nodes);
        knots.extend([b, b, b]);
        let count = m + 3;
        let mut mat = vec![0.0; count * count];
        let mut ders = [[0.0; W]; 3];
        // interpolation rows q = 0..m
        for (q, &t) in nodes.iter().enumerate() {
            let span = find_span(&knots, 3, count, t);
            basis_derivs(&knots, 3, span, t, 0, &mut ders);
            for k in 0..=3 {
                mat[q * count + span - 3 + k] = ders[0][k];
            }
        }
        // two end-condition rows
        let mut row_of = |row: usize, coeffs: &[(usize, f64)]| {
            for &(k, c) in coeffs {
                mat[row * count + k] += c;
            }
        };
        match end {
            CubicEnd::Natural => {
                for (row, t, span) in [(m + 1, a, 3), (m + 2, b, m + 2)] {
                    basis_derivs(&knots, 3, span, t, 2, &mut ders);
                    let c: Vec<(usize, f64)> =
                        (0..=3).map(|k| (span - 3 + k, ders[2][k])).collect();
                    row_of(row, &c);
                }
            }
            CubicEnd::NotAKnot => {
                // third derivative on span s (constant) = (N″(right end) − N″(left end)) / h
                let third = |span: usize, ders: &mut [[f64; W]; 3]| -> Vec<(usize, f64)> {
                    let (l, r) = (knots[span], knots[span + 1]);
                    basis_derivs(&knots, 3, span, r, 2, ders);
                    let hi: Vec<f64> = (0..=3).map(|k| ders[2][k]).collect();
                    basis_derivs(&knots, 3, span, l, 2, ders);
                    (0..=3)
                        .map(|k| (span - 3 + k, (hi[k] - ders[2][k]) / (r - l)))
                        .collect()
                };
                // jump at u_1: spans 3 (cell 1) and 4 (cell 2); at u_{m−1}: spans m+1 and m+2
                for (row, left, right) in [(m + 1, 3, 4), (m + 2, m + 1, m + 2)] {
                    let lc = third(left, &mut ders);
                    let rc = third(right, &mut ders);
                    row_of(row, &lc);
                    let neg: Vec<(usize, f64)> = rc.iter().map(|&(k, c)| (k, -c)).collect();
                    row_of(row, &neg);
                }
            }
        }
        let lu = Lu::new(count, mat.clone(), field)?;
        let mut coef = vec![0.0; (m + 1) * count];
        let mut rhs = vec![0.0; count];
        for r in 0..=m {
            rhs.iter_mut().for_each(|x| *x = 0.0);
            rhs[r] = 1.0;
            lu.solve_refined(&mat, &mut rhs);
            coef[r * count..(r + 1) * count].copy_from_slice(&rhs);
        }
        Ok(BlendFunctions {
            nodes: nodes.to_vec(),
            knots,
            coef,
        })
    }

    /// Blending functions given by their cubic B-spline coefficients: `coef[r * count + k]` for node r
    /// (`count = knots.len() − 4`). The domain is `[knots[3], knots[count]]`.
    pub fn from_coefficients(
        field: &'static str,
        nodes: Vec<f64>,
        knots: Vec<f64>,
        coef: Vec<f64>,
    ) -> Result<Self> {
        let count = knots.len().saturating_sub(4);
        crate::knots::validate(field, &knots, 3, count)?;
        if coef.len() != nodes.len() * count {
            return Err(Error::size_mismatch(
                field,
                format!(
                    "expected {} × {count} blend coefficients, got {}",
                    nodes.len(),
                    coef.len()
                ),
            ));
        }
        crate::error::check_finite(field, &coef)?;
        crate::error::check_finite(field, &nodes)?;
        Ok(BlendFunctions { nodes, knots, coef })
    }

    /// The parameter interval of the blend.
    pub fn domain(&self) -> (f64, f64) {
        (self.knots[3], self.knots[self.count()])
    }
    /// The nodes (the network lines the blend samples).
    pub fn nodes(&self) -> &[f64] {
        &self.nodes
    }
    /// The cubic knot vector ({u_0 ×4, u_1, …, u_{m−1}, u_m ×4} for the cardinal cubics).
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }
    /// Number of functions (one per node).
    pub fn len(&self) -> usize {
        self.nodes.len()
    }
    /// Never true (at least two nodes).
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }
    /// Number of B-spline coefficients per function (m + 3 for the cardinal cubics).
    pub fn count(&self) -> usize {
        self.knots.len() - 4
    }
    /// The B-spline coefficients of L_r (m + 3 of them).
    pub fn coefficients(&self, r: usize) -> &[f64] {
        let c = self.count();
        &self.coef[r * c..(r + 1) * c]
    }
    /// The non-zero cubic basis functions at `u` with derivatives up to `order` (≤ 2); right-hand piece at
    /// nodes, last piece at and beyond u_m.
    pub fn basis(&self, u: f64, order: usize) -> CubicBasis {
        let span = find_span(&self.knots, 3, self.count(), u);
        let mut ders = [[0.0; W]; 3];
        basis_derivs(&self.knots, 3, span, u, order.min(2), &mut ders);
        CubicBasis { span, ders }
    }
    /// `[L_r, L_r′, L_r″]` from a precomputed basis (entries above the basis order are 0).
    pub fn value(&self, r: usize, b: &CubicBasis) -> [f64; 3] {
        let c = &self.coef[r * self.count()..];
        let mut out = [0.0; 3];
        for (k, o) in out.iter_mut().enumerate() {
            for a in 0..=3 {
                *o += c[b.span - 3 + a] * b.ders[k][a];
            }
        }
        out
    }
    /// `[L_r(u), L_r′(u), L_r″(u)]`.
    pub fn eval(&self, r: usize, u: f64) -> [f64; 3] {
        self.value(r, &self.basis(u, 2))
    }
}
