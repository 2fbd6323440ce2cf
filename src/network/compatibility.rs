//! Compatibility of a curve network (Dagnino–Lamberti–Remogna): C1 (common knot vectors) and C2, eq. (6): φ_r(v_s) = ψ_s(u_r),
//! the residual report and the check that names the worst node.

use super::{Network, Partition};
use crate::error::{Error, Result};
use crate::point::Point;
use glam::DVec3;

/// Which compatibility equation of Dagnino–Lamberti–Remogna a network node (r, s) belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Condition {
    /// Interior node: eq. (9).
    Interior,
    /// s = 0 or s = n, interior r: eq. (10).
    UBoundary,
    /// r = 0 or r = m, interior s: eq. (11).
    VBoundary,
    /// A corner: eq. (12).
    Corner,
}

impl Condition {
    /// The paper's equation number, e.g. `"(9)"`.
    pub fn equation(self) -> &'static str {
        match self {
            Condition::Interior => "(9)",
            Condition::UBoundary => "(10)",
            Condition::VBoundary => "(11)",
            Condition::Corner => "(12)",
        }
    }
}

/// The C2 residuals of a network (C1 holds once [`Network::check_shape`] passed: all ψ_s share U, all
/// φ_r share V).
#[derive(Debug, Clone, PartialEq)]
pub struct CompatibilityReport {
    /// `residuals[r][s]` = ‖φ_r(v_s) − ψ_s(u_r)‖∞.
    pub residuals: Vec<Vec<f64>>,
    /// max over (r, s).
    pub c2: f64,
    /// (r, s) of the largest residual.
    pub worst: (usize, usize),
    /// The equation of Dagnino–Lamberti–Remogna the worst node belongs to.
    pub condition: Condition,
    /// Scale of the network: the largest absolute control-point coordinate.
    pub scale: f64,
}

impl CompatibilityReport {
    /// The tolerance used by [`Network::check_compatible`] for relative tolerance `rel`.
    pub fn tolerance(&self, rel: f64) -> f64 {
        rel * self.scale.max(1.0)
    }
}

impl Network {
    /// The node points I_rs = φ_r(v_s) (from the P side), `[r][s]`.
    pub(crate) fn nodes_from_p(&self, pv: &Partition) -> Vec<Vec<DVec3>> {
        self.p
            .iter()
            .map(|row| (0..=self.n()).map(|s| pv.value_at_break(row, s)).collect())
            .collect()
    }

    /// The node points ψ_s(u_r) (from the Q side), `[r][s]`.
    pub(crate) fn nodes_from_q(&self, pu: &Partition) -> Vec<Vec<DVec3>> {
        (0..=self.m())
            .map(|r| self.q.iter().map(|row| pu.value_at_break(row, r)).collect())
            .collect()
    }

    /// The network intersection points I_rs = φ_r(v_s) = ψ_s(u_r) (eq. (6)), `[r][s]`, taken as the mean
    /// of the two sides (exactly symmetric under transposition). Requires a shape-checked network.
    pub fn intersections(&self) -> Result<Vec<Vec<DVec3>>> {
        let (pu, pv) = self.partitions()?;
        let a = self.nodes_from_p(&pv);
        let b = self.nodes_from_q(&pu);
        Ok(a.iter()
            .zip(&b)
            .map(|(ra, rb)| ra.iter().zip(rb).map(|(x, y)| (*x + *y) * 0.5).collect())
            .collect())
    }

    /// Which equation node (r, s) belongs to.
    pub(crate) fn condition_at(&self, r: usize, s: usize) -> Condition {
        let rb = r == 0 || r == self.m();
        let sb = s == 0 || s == self.n();
        match (rb, sb) {
            (true, true) => Condition::Corner,
            (false, true) => Condition::UBoundary,
            (true, false) => Condition::VBoundary,
            (false, false) => Condition::Interior,
        }
    }

    /// The C2 residual report (checks the shape first).
    pub fn compatibility(&self) -> Result<CompatibilityReport> {
        self.check_shape()?;
        let (pu, pv) = self.partitions()?;
        let a = self.nodes_from_p(&pv);
        let b = self.nodes_from_q(&pu);
        let mut c2 = 0.0;
        let mut worst = (0, 0);
        let residuals: Vec<Vec<f64>> = a
            .iter()
            .zip(&b)
            .enumerate()
            .map(|(r, (ra, rb))| {
                ra.iter()
                    .zip(rb)
                    .enumerate()
                    .map(|(s, (x, y))| {
                        let d = (*x - *y).max_abs();
                        if d > c2 || d.is_nan() {
                            c2 = d;
                            worst = (r, s);
                        }
                        d
                    })
                    .collect()
            })
            .collect();
        Ok(CompatibilityReport {
            residuals,
            c2,
            worst,
            condition: self.condition_at(worst.0, worst.1),
            scale: self.scale(),
        })
    }

    /// Shape check plus C2 with residual ≤ `rel`·max(1, scale) (use [`COMPATIBILITY_TOL`](super::COMPATIBILITY_TOL)); the error names
    /// the worst residual, the node (r, s), the equation and how to fix it.
    pub fn check_compatible(&self, rel: f64) -> Result<CompatibilityReport> {
        let rep = self.compatibility()?;
        let tol = rep.tolerance(rel);
        if !(rep.c2 <= tol) {
            let (r, s) = rep.worst;
            return Err(Error::size_mismatch(
                "network",
                format!(
                    "the curves are not compatible (condition C2, eq. {}): φᵣ(vₛ) ≠ ψₛ(uᵣ) at node (r = {r}, s = {s}), \
                     the worst residual, beyond the tolerance (P[{r}] vs Q[{s}]; networkCompatibility gives the residuals); \
                     build the network with networkFromFunction or make it compatible with networkRepair",
                    rep.condition.equation()
                ),
            ));
        }
        Ok(rep)
    }
}
