//! The remodelled spline g* (eq. 6, and eqs. 10–12 once eq. 9 holds) and its curvature (eqs. 13–15).

use super::alphas::{alpha_roles, AlphaRole, AlphaTable};
use super::spline::BezierSpline;
use crate::error::{Error, Result};
use crate::point::{curvature, Point};
use crate::sample::Curve;

/// The parametric degree elevation of Gânscă–Coman–Ţămbulea §2: from g of degree m and the parameters α_k^{(I)}, the
/// spline g* of degree m + 1 on the same breakvalues with control points (eq. 6)
///
/// b*_{(m+1)I} = b_{mI},  b*_{(m+1)I+k} = (1 − α_k^{(I)}) b_{mI+k−1} + α_k^{(I)} b_{mI+k} (k = 1..m),
/// b*_{(m+1)I+m+1} = b_{m(I+1)}.
///
/// α_k = (m + 1 − k)/(m + 1) is the classical elevation (g* ≡ g). When C^r is enforced (r ≤ ⌊m/2⌋), the
/// entries fixed by eq. (9) are overwritten, and g* is C^r wherever g is (eq. 8).
///
/// # Template
/// * **What**: the remodelled Bézier spline g* of Gânscă–Coman–Ţămbulea: degree m + 1 on the
///   breakvalues of g, control points by eq. (6) with parameters α_k^{(I)} ∈ (0, 1).
/// * **Interpolates**: the junction points of g, g*(u_I) = g(u_I) (b*_{(m+1)I} = b_{mI}); with the classical
///   α it *is* g.
/// * **Continuity**: C^r wherever g is, when `enforce = Some(r)` fixes the α of eq. (9) (r ≤ ⌊m/2⌋).
/// * **Parametrisation**: that of g, u ∈ [u_0, u_L], segment I on [u_I, u_{I+1}].
///
/// # Example
/// ```
/// use glam::DVec2;
/// use splinelab::{bezier::{AlphaTable, BezierSpline, Remodelling}, Curve};
/// // a quadratic spline with 2 segments on [0, 2]
/// let b: Vec<DVec2> = [(0.0, 0.0), (1.0, 2.0), (2.0, 1.0), (3.0, 0.0), (4.0, 1.0)]
///     .iter().map(|&(x, y)| DVec2::new(x, y)).collect();
/// let g = BezierSpline::new(2, vec![0.0, 1.0, 2.0], b)?;
/// // classical α: g* ≡ g
/// let same = Remodelling::new(g.clone(), AlphaTable::classical(2, 2), None)?;
/// assert!((same.eval(0.7) - g.eval(0.7)).length() < 1e-12);
/// // free α, C¹ enforced: the junction point stays
/// let r = Remodelling::new(g.clone(), AlphaTable::new(2, 2, vec![vec![0.5, 0.2], vec![0.5, 0.3]])?, Some(1))?;
/// assert!((r.eval(1.0) - g.eval(1.0)).length() < 1e-12);
/// # Ok::<(), splinelab::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct Remodelling<P: Point> {
    original: BezierSpline<P>,
    alphas: AlphaTable,
    r: Option<usize>,
    elevated: BezierSpline<P>,
}

impl<P: Point> Remodelling<P> {
    /// Builds g*. `alphas` must be a table for the spline's degree and segment count. With
    /// `enforce = Some(r)` the entries fixed by eq. (9) are overwritten first (errors: r > ⌊m/2⌋, or a fixed
    /// value outside (0, 1)).
    pub fn new(
        original: BezierSpline<P>,
        alphas: AlphaTable,
        enforce: Option<usize>,
    ) -> Result<Self> {
        let (m, l) = (original.degree(), original.segments());
        if alphas.degree() != m || alphas.rows().len() != l {
            return Err(Error::size_mismatch(
                "alphas",
                format!(
                    "expected {l} rows of {m} entries (L = {l}, m = {m}), got {} rows of {}",
                    alphas.rows().len(),
                    alphas.degree()
                ),
            ));
        }
        let alphas = match enforce {
            Some(r) => alphas.enforce(r)?,
            None => alphas,
        };
        let elevated = elevate(&original, &alphas)?;
        Ok(Remodelling {
            original,
            alphas,
            r: enforce,
            elevated,
        })
    }

    /// The given spline g (the witness curve).
    pub fn original(&self) -> &BezierSpline<P> {
        &self.original
    }
    /// The remodelled spline g* of degree m + 1.
    pub fn elevated(&self) -> &BezierSpline<P> {
        &self.elevated
    }
    /// The parameters actually used (after enforcing eq. 9).
    pub fn alphas(&self) -> &AlphaTable {
        &self.alphas
    }
    /// The r that was enforced, if any.
    pub fn enforced_r(&self) -> Option<usize> {
        self.r
    }
    /// Which entries are free and which eq. (9) fixes (all free when nothing was enforced).
    pub fn roles(&self) -> Vec<Vec<AlphaRole>> {
        alpha_roles(
            self.original.degree(),
            self.original.segments(),
            self.r.unwrap_or(0),
        )
    }

    /// K(u_I) of g by eq. (13), I = 0..L.
    pub fn curvature_original(&self, joint: usize) -> f64 {
        self.original.break_curvature(joint)
    }
    /// K*(u_I) of g* by the corrected eq. (14), I = 0..L.
    pub fn curvature(&self, joint: usize) -> f64 {
        self.elevated.break_curvature(joint)
    }
    /// K*(u_I) measured directly, |g*′ × g*″| / |g*′|³ from the derivatives at u_I (right-hand piece;
    /// the last piece at u_L).
    pub fn curvature_measured(&self, joint: usize) -> f64 {
        let u = self.elevated.breaks()[joint.min(self.elevated.segments())];
        let mut out = [P::ZERO; 3];
        self.elevated.eval_derivs(u, 2, &mut out);
        curvature(out[1], out[2])
    }

    /// The ratio K*(u_I)/K(u_I) predicted from the parameters, valid for every r (`curves.md` §3.2):
    /// * I < L (right-sided form of eq. 15): m²/(m² − 1) · α_2^{(I)} / (α_1^{(I)})²;
    /// * I = L (eq. 15 as printed): m²/(m² − 1) · (1 − α_{m−1}^{(L−1)}) / (1 − α_m^{(L−1)})².
    ///
    /// For m = 1 both curves are polylines (K = K* = 0) and the ratio is reported as 1.
    pub fn curvature_ratio(&self, joint: usize) -> f64 {
        let m = self.original.degree();
        let l = self.original.segments();
        if m < 2 {
            return 1.0;
        }
        let mf = m as f64;
        let factor = mf * mf / (mf * mf - 1.0);
        let a = &self.alphas;
        if joint < l {
            factor * a.get(joint, 2) / a.get(joint, 1).powi(2)
        } else {
            factor * (1.0 - a.get(l - 1, m - 1)) / (1.0 - a.get(l - 1, m)).powi(2)
        }
    }

    /// K*(u_I) predicted by the general right-sided eq. (15): ratio × K(u_I⁺).
    pub fn curvature_predicted(&self, joint: usize) -> f64 {
        self.curvature_ratio(joint) * self.curvature_original(joint)
    }

    /// K*(u_I) by eq. (15) exactly as printed: at interior I it uses (1 − 2α_m^{(I−1)})/(1 − α_m^{(I−1)})²,
    /// which equals the right-sided form only when eq. (9) holds with r ≥ 2 (for r = 1 it is wrong,
    /// `curves.md` §3.2). Shown next to the correct value so the difference can be seen.
    pub fn curvature_printed(&self, joint: usize) -> f64 {
        let m = self.original.degree();
        let l = self.original.segments();
        if m < 2 || joint == 0 || joint >= l {
            return self.curvature_predicted(joint);
        }
        let mf = m as f64;
        let am = self.alphas.get(joint - 1, m);
        mf * mf / (mf * mf - 1.0) * (1.0 - 2.0 * am) / (1.0 - am).powi(2)
            * self.curvature_original(joint)
    }
}

/// The curvature sweep of the paper's Fig. 3 in one pass: K*(u_I) by the corrected eq. (14) and by eq. (15)
/// as printed, at joint I = `joint` (1..=L), as α_m^{(I−1)} takes each of `values` (every other entry as in
/// `alphas`; with `enforce = Some(r)` eq. (9) is applied after the entry is set, exactly as
/// [`Remodelling::new`] would). Returns `(curvature, printed)`, one entry per value. Each value equals
/// `Remodelling::new(g, alphas with α_m^{(I−1)} = value, enforce)?.curvature(joint)` (and
/// `curvature_printed`), with one validation of g and the table instead of one per value.
///
/// Errors: `joint` outside 1..=L, a value outside (0, 1), or one for which eq. (9) leaves (0, 1) (the error
/// names `alphaSweep[j]`).
pub fn curvature_sweep<P: Point>(
    g: &BezierSpline<P>,
    alphas: &AlphaTable,
    enforce: Option<usize>,
    joint: usize,
    values: &[f64],
) -> Result<(Vec<f64>, Vec<f64>)> {
    let (m, l) = (g.degree(), g.segments());
    if joint == 0 || joint > l {
        return Err(Error::out_of_range(
            "alphaSweepJoint",
            format!("the swept entry is αₘ⁽ᴵ⁻¹⁾, so the joint I must be in 1..={l}; got {joint}"),
        ));
    }
    if alphas.degree() != m || alphas.rows().len() != l {
        return Err(Error::size_mismatch(
            "alphas",
            format!("expected {l} rows of {m} entries (L = {l}, m = {m})"),
        ));
    }
    let mut rows = alphas.rows().to_vec();
    let mut curv = Vec::with_capacity(values.len());
    let mut printed = Vec::with_capacity(values.len());
    for (j, &a) in values.iter().enumerate() {
        rows[joint - 1][m - 1] = a;
        let table = AlphaTable::new(m, l, rows.clone())
            .map_err(|e| e.in_field(format!("alphaSweep[{j}]")))?;
        let table = match enforce {
            Some(r) => table
                .enforce(r)
                .map_err(|e| e.in_field(format!("alphaSweep[{j}]")))?,
            None => table,
        };
        let rem = Remodelling {
            elevated: elevate(g, &table)?,
            original: g.clone(),
            alphas: table,
            r: enforce,
        };
        curv.push(rem.curvature(joint));
        printed.push(rem.curvature_printed(joint));
    }
    Ok((curv, printed))
}

/// Eq. (6): the control points of g* for the given parameters (no constraint applied).
pub fn elevate<P: Point>(g: &BezierSpline<P>, alphas: &AlphaTable) -> Result<BezierSpline<P>> {
    let m = g.degree();
    let b = g.points();
    let mut out = Vec::with_capacity((m + 1) * g.segments() + 1);
    for i in 0..g.segments() {
        out.push(b[m * i]);
        for k in 1..=m {
            let a = alphas.get(i, k);
            out.push(b[m * i + k - 1] * (1.0 - a) + b[m * i + k] * a);
        }
    }
    out.push(b[m * g.segments()]);
    BezierSpline::new(m + 1, g.breaks().to_vec(), out)
}

impl<P: Point> Curve<P> for Remodelling<P> {
    fn domain(&self) -> (f64, f64) {
        self.elevated.domain()
    }
    fn eval_derivs(&self, u: f64, order: usize, out: &mut [P; 3]) {
        self.elevated.eval_derivs(u, order, out)
    }
    /// g* is a Bézier spline: the kernel's per-segment sampler.
    fn piecewise(&self) -> Option<crate::kernel::PiecewisePoly<P>> {
        self.elevated.piecewise()
    }
}
