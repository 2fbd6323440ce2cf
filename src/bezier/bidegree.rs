//! Gânscă–Coman–Ţămbulea §4.2: remodelling a Bézier spline surface of class C^{r,s} by a parametric degree elevation in
//! both directions, degrees (m, n) → (m + 1, n + 1).
//!
//! The printed eqs. (20)–(22) are garbled (`curves.md` §3.4: the corner case writes I where J is meant,
//! the edge rows are never defined), so the construction is rebuilt from the curve remodelling (eq. 6)
//! applied in u and then in v:
//!
//! 1. **u-step** (eq. 17 with per-column parameters): every column l = 0..nM of the control net is a
//!    Bézier spline in u and is elevated with its own table α_{k,l}^{(I)} (k = 1..m, I = 0..L−1):
//!    b′_{(m+1)I+k, l} = (1 − α_{k,l}^{(I)}) b_{mI+k−1, l} + α_{k,l}^{(I)} b_{mI+k, l}, end rows kept.
//! 2. **v-step**: every row k = 0..(m+1)L of b′ is a Bézier spline in v and is elevated with its own
//!    table β_{l,k}^{(J)} (l = 1..n, J = 0..M−1) in the same way.
//!
//! Keeping the class (with `enforce = Some((r, s))`, r ≤ ⌊m/2⌋, s ≤ ⌊n/2⌋, and an original of class
//! C^{r,s}):
//! * C^r in u: each column's table satisfies eq. (9) (= eq. 19 per column), so each column of b′ is C^r
//!   at every u_I; the jump of ∂^i/∂u^i along the line u = u_I is a Bézier curve in v whose coefficients
//!   are those columns' jumps, hence zero.
//! * C^s in v survives the u-step only if the columns nJ − s..nJ + s around an interior break v_J are
//!   combined with the *same* weights (each row of b′ is then a fixed combination of two rows of b, both
//!   C^s at v_J). So those columns take the table of column nJ before eq. (9) is applied. Symmetrically
//!   the rows (m+1)I − r..(m+1)I + r of b′ take the β table of row (m+1)I, which keeps the C^r in u of
//!   b′ through the v-step, and eq. (9) on every row's β gives C^s in v.
//!
//! The patch corners are kept by both steps (k = 0 rows and l = 0 columns are copied), so
//! b*_{(m+1)I, (n+1)J} = b_{mI, nJ}: G* interpolates G at every (u_I, v_J). The classical parameters
//! α = (m + 1 − k)/(m + 1), β = (n + 1 − l)/(n + 1) reproduce G exactly.

use super::alphas::AlphaTable;
use super::surface::BezierSplineSurface;
use crate::error::{Error, Result};
use crate::point::Point;
use crate::sample::Surface;

/// Parameters for one direction: one table shared by every column (row), or one table per column (row).
#[derive(Debug, Clone, PartialEq)]
pub enum DirectionParams {
    /// The classical elevation in this direction.
    Classical,
    /// One table `rows[I][k − 1]` for every line.
    Shared(AlphaTable),
    /// One table per line (columns l = 0..nM for α, rows k = 0..(m+1)L for β).
    PerLine(Vec<AlphaTable>),
}

/// G* of Gânscă–Coman–Ţămbulea §4.2, built as the u- then v-remodelling (see the module doc).
#[derive(Debug, Clone)]
pub struct BiRemodelling<P: Point> {
    original: BezierSplineSurface<P>,
    alphas: Vec<AlphaTable>,
    betas: Vec<AlphaTable>,
    enforced: Option<(usize, usize)>,
    elevated_u: BezierSplineSurface<P>,
    elevated: BezierSplineSurface<P>,
}

/// One table per line from `params`, checked against the degree and segment count; errors name
/// `field[line]` for per-line tables.
fn tables(
    field: &'static str,
    params: DirectionParams,
    degree: usize,
    segments: usize,
    lines: usize,
) -> Result<Vec<AlphaTable>> {
    let check = |t: &AlphaTable, at: String| -> Result<()> {
        if t.degree() != degree || t.rows().len() != segments {
            return Err(Error::size_mismatch(
                at,
                format!(
                    "expected {segments} rows of {degree} entries, got {} rows of {}",
                    t.rows().len(),
                    t.degree()
                ),
            ));
        }
        Ok(())
    };
    match params {
        DirectionParams::Classical => Ok(vec![AlphaTable::classical(degree, segments); lines]),
        DirectionParams::Shared(t) => {
            check(&t, field.to_string())?;
            Ok(vec![t; lines])
        }
        DirectionParams::PerLine(ts) => {
            if ts.len() != lines {
                return Err(Error::size_mismatch(
                    field,
                    format!(
                        "expected one table per line ({lines}) or one shared table, got {}",
                        ts.len()
                    ),
                ));
            }
            for (i, t) in ts.iter().enumerate() {
                check(t, format!("{field}[{i}]"))?;
            }
            Ok(ts)
        }
    }
}

/// Makes the lines `window` around every interior break share the break line's table, then enforces
/// eq. (9) with order `order` on every table. `degree_other`·J are the break lines, `width` the window.
fn constrain(
    field: &'static str,
    tables: &mut [AlphaTable],
    degree_other: usize,
    segments_other: usize,
    width: usize,
    order: usize,
) -> Result<()> {
    // windows of neighbouring breaks may touch (s = n/2): then they form one group with one table
    let mut prev_end: Option<usize> = None;
    for j in 1..segments_other {
        let c = degree_other * j;
        let (lo, hi) = (c.saturating_sub(width), (c + width).min(tables.len() - 1));
        let src = match prev_end {
            Some(e) if lo <= e => tables[lo].clone(),
            _ => tables[c].clone(),
        };
        for t in &mut tables[lo..=hi] {
            *t = src.clone();
        }
        prev_end = Some(hi);
    }
    for (i, t) in tables.iter_mut().enumerate() {
        *t = t.enforce(order).map_err(|e| {
            let f = format!("{field}[{i}]{}", e.field().trim_start_matches("alphas"));
            e.in_field(f)
        })?;
    }
    Ok(())
}

/// Elevates every column of `s` in u with its table (`tables[l]`).
fn elevate_columns<P: Point>(
    s: &BezierSplineSurface<P>,
    tables: &[AlphaTable],
) -> Result<BezierSplineSurface<P>> {
    let (m, n) = s.degrees();
    let segs = s.breaks_u().len() - 1;
    let (rows, cols) = s.size();
    let new_rows = (m + 1) * segs + 1;
    let mut pts = Vec::with_capacity(new_rows * cols);
    for i in 0..segs {
        for k in 0..=m {
            for (l, t) in tables.iter().enumerate().take(cols) {
                pts.push(if k == 0 {
                    s.point(m * i, l)
                } else {
                    let a = t.get(i, k);
                    s.point(m * i + k - 1, l) * (1.0 - a) + s.point(m * i + k, l) * a
                });
            }
        }
    }
    for l in 0..cols {
        pts.push(s.point(rows - 1, l));
    }
    BezierSplineSurface::new(m + 1, n, s.breaks_u().to_vec(), s.breaks_v().to_vec(), pts)
}

/// The surface with u and v exchanged (degrees, breaks and the control net transposed).
pub fn transpose<P: Point>(s: &BezierSplineSurface<P>) -> Result<BezierSplineSurface<P>> {
    let (m, n) = s.degrees();
    let (rows, cols) = s.size();
    let mut pts = Vec::with_capacity(rows * cols);
    for l in 0..cols {
        for k in 0..rows {
            pts.push(s.point(k, l));
        }
    }
    BezierSplineSurface::new(n, m, s.breaks_v().to_vec(), s.breaks_u().to_vec(), pts)
}

impl<P: Point> BiRemodelling<P> {
    /// Builds G* from G, the u-parameters `alphas` (per column l = 0..nM, or shared) and the v-parameters
    /// `betas` (per row k = 0..(m+1)L of the u-elevated net, or shared). With `enforce = Some((r, s))` the
    /// window and eq. (9) constraints of the module doc are applied first (errors: r > ⌊m/2⌋,
    /// s > ⌊n/2⌋, or a fixed entry leaving (0, 1), naming the responsible entry).
    pub fn new(
        original: BezierSplineSurface<P>,
        alphas: DirectionParams,
        betas: DirectionParams,
        enforce: Option<(usize, usize)>,
    ) -> Result<Self> {
        let (m, n) = original.degrees();
        let (segs_u, segs_v) = (original.breaks_u().len() - 1, original.breaks_v().len() - 1);
        let (_, cols) = original.size();
        let new_rows = (m + 1) * segs_u + 1;
        let mut a = tables("alphas", alphas, m, segs_u, cols)?;
        let mut b = tables("betas", betas, n, segs_v, new_rows)?;
        if let Some((r, s)) = enforce {
            constrain("alphas", &mut a, n, segs_v, s, r)?;
            constrain("betas", &mut b, m + 1, segs_u, r, s)?;
        }
        let elevated_u = elevate_columns(&original, &a)?;
        let elevated = transpose(&elevate_columns(&transpose(&elevated_u)?, &b)?)?;
        Ok(BiRemodelling {
            original,
            alphas: a,
            betas: b,
            enforced: enforce,
            elevated_u,
            elevated,
        })
    }

    /// The given surface G.
    pub fn original(&self) -> &BezierSplineSurface<P> {
        &self.original
    }
    /// The surface after the u-step (degrees (m + 1, n)).
    pub fn elevated_u(&self) -> &BezierSplineSurface<P> {
        &self.elevated_u
    }
    /// G* (degrees (m + 1, n + 1)).
    pub fn elevated(&self) -> &BezierSplineSurface<P> {
        &self.elevated
    }
    /// The α tables used, one per column l = 0..nM (after the constraints).
    pub fn alphas(&self) -> &[AlphaTable] {
        &self.alphas
    }
    /// The β tables used, one per row k = 0..(m+1)L of the u-elevated net (after the constraints).
    pub fn betas(&self) -> &[AlphaTable] {
        &self.betas
    }
    /// The enforced (r, s), if any.
    pub fn enforced(&self) -> Option<(usize, usize)> {
        self.enforced
    }
    /// Measured jumps of G*: (`u[I − 1][i]` across u = u_I for i = 0..=max_u, `v[J − 1][j]` across v = v_J
    /// for j = 0..=max_v), as [`BezierSplineSurface::u_jumps`].
    pub fn jumps(&self, max_u: usize, max_v: usize) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
        let u = self.elevated.u_jumps(max_u);
        let v = transpose(&self.elevated)
            .map(|t| t.u_jumps(max_v))
            .unwrap_or_default();
        (u, v)
    }
}

impl<P: Point> Surface<P> for BiRemodelling<P> {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        self.elevated.domain()
    }
    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [P; 3]) {
        self.elevated.eval_derivs(u, v, derivs, out)
    }
}
