//! Bézier spline surfaces (eq. 3) and their remodelling by degree elevation in u (Gânscă–Coman–Ţămbulea §4.1,
//! eqs. 16–19).

use super::alphas::{alpha_roles, AlphaRole, AlphaTable};
use super::{falling, forward_difference, segment_derivs, MAX_BEZIER_DEGREE, W};
use crate::error::{check_finite, Error, Result};
use crate::knots::check_increasing;
use crate::point::Point;
use crate::sample::{Surface, MAX_INPUT_POINTS};

/// A tensor-product Bézier spline surface of degrees (m, n) (eq. 3): control points b_{k,l},
/// k = 0..mL along u and l = 0..nM along v, stored row-major (`points[k * cols + l]`), breakvalues
/// u_0..u_L and v_0..v_M. On D_{IJ} = [u_I, u_{I+1}] × [v_J, v_{J+1}] it is
/// Σ_k Σ_l B_{m,k}(s) B_{n,l}(t) b_{mI+k, nJ+l}. Right-hand pieces at interior breakvalues, last pieces
/// at the far ends. Gânscă–Coman–Ţămbulea §4.1 is the case M = 1.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierSplineSurface<P: Point> {
    degree_u: usize,
    degree_v: usize,
    breaks_u: Vec<f64>,
    breaks_v: Vec<f64>,
    points: Vec<P>,
}

fn check_degree(field: &'static str, d: usize) -> Result<()> {
    if d == 0 {
        return Err(Error::out_of_range(field, "need a degree ≥ 1, got 0"));
    }
    if d > MAX_BEZIER_DEGREE + 1 {
        return Err(Error::out_of_range(
            field,
            format!("at most {MAX_BEZIER_DEGREE}, got {d}"),
        ));
    }
    Ok(())
}

fn check_breaks(field: &'static str, b: &[f64]) -> Result<()> {
    if b.len() < 2 {
        return Err(Error::too_few(
            field,
            format!("need at least 2 breakvalues (one segment), got {}", b.len()),
        ));
    }
    check_finite(field, b)?;
    check_increasing(field, b)?;
    // segments shorter than 1e-12 × the range make derivatives overflow (robustness bug 4)
    crate::knots::check_separated(field, b)
}

fn segment_of(breaks: &[f64], u: f64) -> usize {
    let l = breaks.len() - 1;
    breaks[..l].partition_point(|&b| b <= u).saturating_sub(1)
}

impl<P: Point> BezierSplineSurface<P> {
    /// Validates and builds the surface: degrees ≥ 1, strictly increasing finite breakvalues, and
    /// (mL + 1)·(nM + 1) finite control points in row-major order.
    pub fn new(
        degree_u: usize,
        degree_v: usize,
        breaks_u: Vec<f64>,
        breaks_v: Vec<f64>,
        points: Vec<P>,
    ) -> Result<Self> {
        check_degree("degreeU", degree_u)?;
        check_degree("degreeV", degree_v)?;
        check_breaks("breaksU", &breaks_u)?;
        check_breaks("breaksV", &breaks_v)?;
        let rows = degree_u
            .saturating_mul(breaks_u.len() - 1)
            .saturating_add(1);
        let cols = degree_v
            .saturating_mul(breaks_v.len() - 1)
            .saturating_add(1);
        if rows.saturating_mul(cols) > MAX_INPUT_POINTS {
            return Err(Error::too_many(
                "points",
                format!("at most {MAX_INPUT_POINTS} control points"),
            ));
        }
        if points.len() != rows * cols {
            return Err(Error::size_mismatch(
                "points",
                format!(
                    "expected (mL + 1) × (nM + 1) = {rows} × {cols} control points, got {}",
                    points.len()
                ),
            ));
        }
        if let Some(i) = points.iter().position(|p| !p.is_finite()) {
            return Err(Error::not_finite(
                format!("points[{}][{}]", i / cols, i % cols),
                "expected finite coordinates",
            ));
        }
        Ok(BezierSplineSurface {
            degree_u,
            degree_v,
            breaks_u,
            breaks_v,
            points,
        })
    }

    /// The degrees (m, n).
    pub fn degrees(&self) -> (usize, usize) {
        (self.degree_u, self.degree_v)
    }
    /// Breakpoints along u.
    pub fn breaks_u(&self) -> &[f64] {
        &self.breaks_u
    }
    /// Breakpoints along v.
    pub fn breaks_v(&self) -> &[f64] {
        &self.breaks_v
    }
    /// (rows, cols) = (mL + 1, nM + 1).
    pub fn size(&self) -> (usize, usize) {
        (
            self.degree_u * (self.breaks_u.len() - 1) + 1,
            self.degree_v * (self.breaks_v.len() - 1) + 1,
        )
    }
    /// All control points, row-major.
    pub fn points(&self) -> &[P] {
        &self.points
    }
    /// b_{k,l}.
    pub fn point(&self, k: usize, l: usize) -> P {
        self.points[k * self.size().1 + l]
    }
    /// The column l = const of control points b_{0,l}..b_{mL,l} (a curve along u).
    pub fn column(&self, l: usize) -> Vec<P> {
        let (rows, cols) = self.size();
        (0..rows).map(|k| self.points[k * cols + l]).collect()
    }

    /// Measured continuity across the lines u = u_I: `jumps[I − 1][i]` = the largest jump of ∂^i/∂u^i over
    /// the control coefficients of the boundary curve, max_l ‖Δ^i-left − Δ^i-right‖ scaled as derivatives
    /// (the jump along the whole line is a Bézier curve in v with these coefficients, so it vanishes
    /// exactly when they do), for I = 1..L−1, i = 0..=max_order.
    pub fn u_jumps(&self, max_order: usize) -> Vec<Vec<f64>> {
        let m = self.degree_u;
        let (_, cols) = self.size();
        let l_segs = self.breaks_u.len() - 1;
        let mut col = vec![P::ZERO; m + 1];
        (1..l_segs)
            .map(|joint| {
                let (hl, hr) = (
                    self.breaks_u[joint] - self.breaks_u[joint - 1],
                    self.breaks_u[joint + 1] - self.breaks_u[joint],
                );
                (0..=max_order)
                    .map(|i| {
                        if i > m {
                            return 0.0;
                        }
                        let f = falling(m, i);
                        (0..cols)
                            .map(|l| {
                                for (k, c) in col.iter_mut().enumerate().take(i + 1) {
                                    *c = self.points[(m * joint - i + k) * cols + l];
                                }
                                let left =
                                    forward_difference(&col[..=i], i) * (f / hl.powi(i as i32));
                                for (k, c) in col.iter_mut().enumerate().take(i + 1) {
                                    *c = self.points[(m * joint + k) * cols + l];
                                }
                                let right =
                                    forward_difference(&col[..=i], i) * (f / hr.powi(i as i32));
                                (right - left).max_abs()
                            })
                            .fold(0.0, f64::max)
                    })
                    .collect()
            })
            .collect()
    }
}

impl<P: Point> Surface<P> for BezierSplineSurface<P> {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        let (bu, bv) = (&self.breaks_u, &self.breaks_v);
        ((bu[0], bu[bu.len() - 1]), (bv[0], bv[bv.len() - 1]))
    }

    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [P; 3]) {
        let (m, n) = (self.degree_u, self.degree_v);
        let (_, cols) = self.size();
        let i = segment_of(&self.breaks_u, u);
        let j = segment_of(&self.breaks_v, v);
        let hu = self.breaks_u[i + 1] - self.breaks_u[i];
        let hv = self.breaks_v[j + 1] - self.breaks_v[j];
        let s = (u - self.breaks_u[i]) / hu;
        let t = (v - self.breaks_v[j]) / hv;
        // evaluate the m + 1 v-curves of the patch at t, then the u-curve through them
        let mut at = [P::ZERO; W];
        let mut at_v = [P::ZERO; W];
        let mut tmp = [P::ZERO; 3];
        for k in 0..=m {
            let start = (m * i + k) * cols + n * j;
            segment_derivs(
                &self.points[start..=start + n],
                t,
                hv,
                usize::from(derivs),
                &mut tmp,
            );
            at[k] = tmp[0];
            at_v[k] = tmp[1];
        }
        segment_derivs(&at[..=m], s, hu, usize::from(derivs), &mut tmp);
        out[0] = tmp[0];
        if derivs {
            out[1] = tmp[1];
            let mut tv = [P::ZERO; 3];
            segment_derivs(&at_v[..=m], s, hu, 0, &mut tv);
            out[2] = tv[0];
        }
    }
}

/// Gânscă–Coman–Ţămbulea §4.1: remodelling a Bézier spline surface by a parametric degree elevation in u (eq. 17),
/// b*_{(m+1)I+k, l} = (1 − α_k^{(I)}) b_{mI+k−1, l} + α_k^{(I)} b_{mI+k, l} (k = 1..m), the end rows kept,
/// with one table α_k^{(I)} shared by every column l (`api.md`). The result G* (eq. 18) has degrees
/// (m + 1, n); enforcing eq. (19) (= eq. 9 per column) keeps C^r in u.
#[derive(Debug, Clone)]
pub struct SurfaceRemodelling<P: Point> {
    original: BezierSplineSurface<P>,
    alphas: AlphaTable,
    r: Option<usize>,
    elevated: BezierSplineSurface<P>,
}

impl<P: Point> SurfaceRemodelling<P> {
    /// Builds G*; with `enforce = Some(r)` the entries fixed by eq. (19) are overwritten first.
    pub fn new(
        original: BezierSplineSurface<P>,
        alphas: AlphaTable,
        enforce: Option<usize>,
    ) -> Result<Self> {
        let m = original.degree_u;
        let l_segs = original.breaks_u.len() - 1;
        if alphas.degree() != m || alphas.rows().len() != l_segs {
            return Err(Error::size_mismatch(
                "alphas",
                format!("expected {l_segs} rows of {m} entries (L = {l_segs}, m = {m})"),
            ));
        }
        let alphas = match enforce {
            Some(r) => alphas.enforce(r)?,
            None => alphas,
        };
        let (rows, cols) = original.size();
        let new_rows = (m + 1) * l_segs + 1;
        let mut pts = Vec::with_capacity(new_rows * cols);
        let b = |k: usize, l: usize| original.points[k * cols + l];
        for i in 0..l_segs {
            for k in 0..=m {
                for l in 0..cols {
                    pts.push(if k == 0 {
                        b(m * i, l)
                    } else {
                        let a = alphas.get(i, k);
                        b(m * i + k - 1, l) * (1.0 - a) + b(m * i + k, l) * a
                    });
                }
            }
        }
        for l in 0..cols {
            pts.push(b(rows - 1, l));
        }
        let elevated = BezierSplineSurface::new(
            m + 1,
            original.degree_v,
            original.breaks_u.clone(),
            original.breaks_v.clone(),
            pts,
        )?;
        Ok(SurfaceRemodelling {
            original,
            alphas,
            r: enforce,
            elevated,
        })
    }

    /// The surface before degree elevation.
    pub fn original(&self) -> &BezierSplineSurface<P> {
        &self.original
    }
    /// The surface after parametric degree elevation.
    pub fn elevated(&self) -> &BezierSplineSurface<P> {
        &self.elevated
    }
    /// The α table that was used (free and derived entries).
    pub fn alphas(&self) -> &AlphaTable {
        &self.alphas
    }
    /// Which entries are free and which eq. (19) fixes.
    pub fn roles(&self) -> Vec<Vec<AlphaRole>> {
        alpha_roles(
            self.original.degree_u,
            self.original.breaks_u.len() - 1,
            self.r.unwrap_or(0),
        )
    }
}

impl<P: Point> Surface<P> for SurfaceRemodelling<P> {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        self.elevated.domain()
    }
    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [P; 3]) {
        self.elevated.eval_derivs(u, v, derivs, out)
    }
}
