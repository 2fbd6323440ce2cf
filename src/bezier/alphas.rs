//! The parameters α_k^{(I)} of the parametric degree elevation (eq. 6) and the C^r constraints (eq. 9).

use crate::error::{Error, Result};

/// The table of parameters α_k^{(I)}, k = 1..m, I = 0..L−1, stored as `rows[I][k − 1]`
/// (`curves.md` §3). Every entry lies in the open interval (0, 1).
#[derive(Debug, Clone, PartialEq)]
pub struct AlphaTable {
    degree: usize,
    rows: Vec<Vec<f64>>,
}

/// What decides one entry α_k^{(I)} when C^r is enforced (eq. 9).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AlphaRole {
    /// Free in (0, 1).
    Free,
    /// α_p^{(I)} = 1 − p·α_m^{(I−1)} (first line of eq. 9; p = 1..r, I = 1..L−1).
    /// Determined by the last α of the previous segment.
    FromPrevious {
        /// p = 1..r.
        p: usize,
    },
    /// α_{m−p+1}^{(I)} = p·α_m^{(I)} (second line of eq. 9; p = 2..r, I = 0..L−2).
    /// Determined by the last α of the same segment.
    FromOwnLast {
        /// p = 2..r.
        p: usize,
    },
}

impl AlphaRole {
    /// Whether the entry is free.
    pub fn is_free(self) -> bool {
        self == AlphaRole::Free
    }

    /// A human-readable statement of the constraint for α_k^{(I)} of a degree-m spline, e.g.
    /// `"α_1^(2) = 1 − α_2^(1)  (eq. 9)"`; empty for a free entry.
    pub fn describe(self, m: usize, segment: usize, k: usize) -> String {
        match self {
            AlphaRole::Free => String::new(),
            AlphaRole::FromPrevious { p } => {
                let coef = if p == 1 {
                    String::new()
                } else {
                    format!("{p}·")
                };
                format!(
                    "α_{k}^({segment}) = 1 − {coef}α_{m}^({})  (eq. 9)",
                    segment.wrapping_sub(1)
                )
            }
            AlphaRole::FromOwnLast { p } => {
                format!("α_{k}^({segment}) = {p}·α_{m}^({segment})  (eq. 9)")
            }
        }
    }
}

/// The role of every entry (`roles[I][k − 1]`) when C^r is enforced on a degree-m spline with L segments
/// (eq. 9). Free are: α_m^{(I)} for every I; for I = 0 also α_1..α_{m−r}; for I = L−1 also α_{r+1}..α_m;
/// for interior I also α_{r+1}..α_{m−r}. With L = 1 or r = 0 every entry is free.
/// Requires r ≤ ⌊m/2⌋ (then the two lines of eq. 9 never fix the same entry).
pub fn alpha_roles(degree: usize, segments: usize, r: usize) -> Vec<Vec<AlphaRole>> {
    let m = degree;
    let mut roles = vec![vec![AlphaRole::Free; m]; segments];
    for (i, row) in roles.iter_mut().enumerate() {
        if i >= 1 {
            for p in 1..=r.min(m) {
                row[p - 1] = AlphaRole::FromPrevious { p };
            }
        }
        if i + 1 < segments {
            for p in 2..=r.min(m) {
                if m + 1 > p {
                    row[m - p] = AlphaRole::FromOwnLast { p };
                }
            }
        }
    }
    roles
}

/// Checks 0 ≤ r ≤ ⌊m/2⌋, the range in which eq. (9) characterises C^r of g*.
pub fn check_r(degree: usize, r: usize) -> Result<()> {
    if r > degree / 2 {
        return Err(Error::out_of_range(
            "r",
            format!(
                "Cʳ can be kept only for r ≤ ⌊m/2⌋ = {} (degree m = {degree}), got {r}",
                degree / 2
            ),
        ));
    }
    Ok(())
}

/// How close an α may come to 0 or 1: closer values make the curvature ratios α_2/α_1² of eq. (15) overflow
/// (found by the API fuzzer with α = 1e-300), so the open interval (0, 1) is enforced with this margin.
pub(crate) const ALPHA_MARGIN: f64 = 1e-9;

fn in_open_unit(a: f64) -> bool {
    (ALPHA_MARGIN..=1.0 - ALPHA_MARGIN).contains(&a)
}

fn check_entry(i: usize, k: usize, a: f64) -> Result<()> {
    if !a.is_finite() {
        return Err(Error::not_finite(
            format!("alphas[{i}][{k}]"),
            crate::error::not_finite_detail(a),
        ));
    }
    if !in_open_unit(a) {
        return Err(Error::out_of_range(
            format!("alphas[{i}][{k}]"),
            format!(
                "αₖ⁽ᴵ⁾ with k = {}, I = {i} must lie in the open interval (0, 1) (at least 1e-9 from its ends)",
                k + 1
            ),
        ));
    }
    Ok(())
}

impl AlphaTable {
    /// Validates the table: L rows of m entries, each finite and in (0, 1).
    pub fn new(degree: usize, segments: usize, rows: Vec<Vec<f64>>) -> Result<Self> {
        if rows.len() != segments {
            return Err(Error::size_mismatch(
                "alphas",
                format!(
                    "expected {segments} rows (one per segment I = 0..L−1), got {}",
                    rows.len()
                ),
            ));
        }
        for (i, row) in rows.iter().enumerate() {
            if row.len() != degree {
                return Err(Error::size_mismatch(
                    format!("alphas[{i}]"),
                    format!(
                        "expected {degree} entries α₁..αₘ (m = {degree}), got {}",
                        row.len()
                    ),
                ));
            }
            for (k, &a) in row.iter().enumerate() {
                check_entry(i, k, a)?;
            }
        }
        Ok(AlphaTable { degree, rows })
    }

    /// The classical degree elevation α_k = (m + 1 − k)/(m + 1) in every segment (g* ≡ g).
    pub fn classical(degree: usize, segments: usize) -> Self {
        let m = degree as f64;
        let row: Vec<f64> = (1..=degree)
            .map(|k| (m + 1.0 - k as f64) / (m + 1.0))
            .collect();
        AlphaTable {
            degree,
            rows: vec![row; segments],
        }
    }

    /// The degree m the table is for.
    pub fn degree(&self) -> usize {
        self.degree
    }
    /// The rows, `rows[I][k − 1]` = α_k^{(I)}.
    pub fn rows(&self) -> &[Vec<f64>] {
        &self.rows
    }
    /// α_k^{(I)} (k = 1..m).
    pub fn get(&self, segment: usize, k: usize) -> f64 {
        self.rows[segment][k - 1]
    }

    /// Overwrites the entries fixed by eq. (9) so that g* keeps C^r (r ≤ ⌊m/2⌋); free entries stay.
    /// Fails when a fixed value leaves (0, 1), which happens when α_m^{(I)} ≥ 1/p for a p ≤ r; the error
    /// names the α_m entry responsible.
    pub fn enforce(&self, r: usize) -> Result<Self> {
        let m = self.degree;
        check_r(m, r)?;
        let roles = alpha_roles(m, self.rows.len(), r);
        let mut rows = self.rows.clone();
        for i in 0..rows.len() {
            for k in 1..=m {
                let (value, source) = match roles[i][k - 1] {
                    AlphaRole::Free => continue,
                    AlphaRole::FromPrevious { p } => {
                        (1.0 - p as f64 * self.rows[i - 1][m - 1], i - 1)
                    }
                    AlphaRole::FromOwnLast { p } => (p as f64 * self.rows[i][m - 1], i),
                };
                if !in_open_unit(value) {
                    return Err(Error::out_of_range(
                        format!("alphas[{source}][{}]", m - 1),
                        format!(
                            "with r = {r}, eq. (9) needs αₘ⁽ᴶ⁾ < 1/{r} (m = {m}, J = {source}) so that the entries it fixes stay in (0, 1); it would make αₖ⁽ᴵ⁾ (k = {k}, I = {i}) leave (0, 1)"
                        ),
                    ));
                }
                rows[i][k - 1] = value;
            }
        }
        Ok(AlphaTable { degree: m, rows })
    }
}
