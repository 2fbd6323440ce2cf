//! Dagnino–Lamberti–Remogna §4.2 (ii): the Gordon boolean sum **G** through a curve network, and Kuklišová §7 eq. (4): the
//! spline-blended surface **GB** ([`blended`]).
//!
//! # G (`../shared/spec/surfaces.md` §5, binding)
//!
//! G = L1 + L2 − Tg (eq. (39)), all three biquadratic:
//! * **L1** on Ū × V skins the v-curves: its control rows interpolate the control points P_j^{(r)} of φ_r
//!   over r at the parameters u_r, so L1(u_r, v) = φ_r(v);
//! * **L2** on U × V̄ skins the u-curves ψ_s at v_s likewise;
//! * **Tg** on Ū × V̄ interpolates the intersection points I_rs = φ_r(v_s) = ψ_s(u_r).
//!
//! Ū, V̄ are the averaged knots of Piegl–Tiller (9.8) for the parameters u_0..u_m (v_0..v_n):
//! {u_0 ×3, (u_1+u_2)/2, …, (u_{m−2}+u_{m−1})/2, u_m ×3}. The three surfaces are refined to the merged knot
//! vectors Ũ = U ∪ Ū, Ṽ = V ∪ V̄ (lengths 2m + 3, 2n + 3) and their control points summed (eq. (40)):
//! C̃ = C̃^{L1} + C̃^{L2} − C̃^{Tg}, a 2m × 2n net. Quadratic interpolation at m + 1 parameters needs
//! m ≥ 2 (and n ≥ 2).
//!
//! G interpolates every network curve and reproduces the space {a(u) + b(v) + c·uv} (a, b C¹ quadratic
//! splines on U, V) exactly; that is also the class where G equals the criss-cross surface S (§1.3).

mod blend;
pub mod blended;
pub mod family;
pub mod grid;
pub mod render;

pub use crate::b2spline::Tension;
pub use blend::{BlendFunctions, CubicBasis, CubicEnd};
pub use blended::{Blend, FnLines, LineNetwork, NetworkLines, SplineBlendedSurface};
pub use family::{
    check_family_size, check_norm_samples, distance_map, NetworkCurves, SurfaceFamily,
    FAMILY_MAX_CURVE_SAMPLES, FAMILY_MAX_GRID_POINTS, FAMILY_MAX_LINES, FAMILY_MAX_NORM_SAMPLES,
    FAMILY_NAMES, FAMILY_PAIRS,
};
pub use grid::{bspline_grid, Grid, GridSurface};
pub use render::{
    render_family, FamilyRender, FamilyRequest, RenderedSurface, FAMILY_MAX_SURFACES,
};

use crate::bspline::{basis_derivs, BSplineSurface};
use crate::error::{Error, Result};
use crate::knots::{self, find_span, MAX_DEGREE};
use crate::linalg::Lu;
use crate::network::Network;
pub use crate::network::COMPATIBILITY_TOL;
use crate::sample::{self, Surface};
use glam::DVec3;

/// The grid size of the paper's ‖·‖∞ measure (Dagnino–Lamberti–Remogna §4.2: a 57 × 57 uniform grid).
pub const DIFFERENCE_GRID: usize = 57;

/// The most network lines per direction G and GB accept (their interpolation systems are dense).
pub const MAX_LINES: usize = 1025;

/// ‖A − B‖∞ over all coordinates on the paper's 57 × 57 grid of A's domain.
pub fn difference<A: Surface<DVec3> + ?Sized, B: Surface<DVec3> + ?Sized>(a: &A, b: &B) -> f64 {
    sample::max_difference(a, b, DIFFERENCE_GRID)
}

/// The clamped quadratic knot vector of breakpoints `x_0..x_k`: {x_0, x_0, x_0, x_1, …, x_{k−1}, x_k, x_k, x_k}.
pub fn quadratic_knots(breaks: &[f64]) -> Vec<f64> {
    let mut k = Vec::with_capacity(breaks.len() + 4);
    if let (Some(&a), Some(&b)) = (breaks.first(), breaks.last()) {
        k.extend([a, a]);
        k.extend_from_slice(breaks);
        k.extend([b, b]);
    }
    k
}

/// The sorted union of two sorted knot vectors, each knot with the larger of its two multiplicities.
pub(crate) fn merge_knots(a: &[f64], b: &[f64]) -> Vec<f64> {
    let mut out = a.to_vec();
    out.extend(knots::missing_knots(a, b));
    out.sort_by(f64::total_cmp);
    out
}

/// The largest |coordinate| of the network's control points (the "scale" of the spec's tolerances).
pub fn network_scale(net: &Network) -> f64 {
    net.scale()
}

/// Checks the shape of `net`, its size (at most [`MAX_LINES`] breakpoints per direction) and its
/// compatibility (C2: φ_r(v_s) = ψ_s(u_r) to `rel_tol`·max(1, scale), see
/// [`Network::check_compatible`]), and returns the intersection points I_rs (the mean of both sides),
/// `i[r][s]`. The error names the worst residual and where it is.
pub fn intersections(net: &Network, rel_tol: f64) -> Result<Vec<Vec<DVec3>>> {
    net.check_shape()?;
    for (field, len) in [("network.u", net.u.len()), ("network.v", net.v.len())] {
        if len > MAX_LINES {
            return Err(Error::too_many(
                field,
                format!("at most {MAX_LINES} breakpoints, got {len}"),
            ));
        }
    }
    net.check_compatible(rel_tol)?;
    net.intersections()
}

/// Control points of the quadratic B-splines on `knots` that interpolate, for each column of `data`
/// (`rows × cols`, row-major), the values of that column at `params` (one collocation factorisation).
fn skin(
    knots: &[f64],
    params: &[f64],
    data: &[DVec3],
    cols: usize,
    field: &'static str,
) -> Result<Vec<DVec3>> {
    let n = params.len();
    knots::validate(field, knots, 2, n)?;
    let mut a = vec![0.0; n * n];
    let mut ders = [[0.0; MAX_DEGREE + 1]; 3];
    for (row, &t) in params.iter().enumerate() {
        let span = find_span(knots, 2, n, t);
        basis_derivs(knots, 2, span, t, 0, &mut ders);
        for r in 0..=2 {
            a[row * n + span - 2 + r] = ders[0][r];
        }
    }
    let lu = Lu::new(n, a, field)?;
    let mut out = vec![DVec3::ZERO; n * cols];
    let mut col = vec![DVec3::ZERO; n];
    for j in 0..cols {
        for i in 0..n {
            col[i] = data[i * cols + j];
        }
        lu.solve(&mut col);
        for i in 0..n {
            out[i * cols + j] = col[i];
        }
    }
    Ok(out)
}

/// Knot refinement of the rows of a row-major `rows × cols` quadratic control net whose row direction has
/// the knot vector `knots`: inserts every knot of `extra` (sorted, strictly inside the domain) in one pass
/// (Piegl–Tiller A5.4, RefineKnotVectCurve, applied to whole rows). Returns the new knots, row count and net.
fn insert_rows(
    knots: &[f64],
    extra: &[f64],
    pts: &[DVec3],
    rows: usize,
    cols: usize,
) -> (Vec<f64>, usize, Vec<DVec3>) {
    const P: usize = 2;
    if extra.is_empty() {
        return (knots.to_vec(), rows, pts.to_vec());
    }
    let n = rows - 1;
    let m = n + P + 1;
    let r = extra.len() - 1;
    let a = find_span(knots, P, rows, extra[0]);
    let b = find_span(knots, P, rows, extra[r]) + 1;
    let mut q = vec![DVec3::ZERO; (rows + r + 1) * cols];
    let mut ub = vec![0.0; m + r + 2];
    let row = |i: usize| i * cols..(i + 1) * cols;
    for j in 0..=a - P {
        q[row(j)].copy_from_slice(&pts[row(j)]);
    }
    for j in b - 1..=n {
        let dst = row(j + r + 1);
        q[dst].copy_from_slice(&pts[row(j)]);
    }
    ub[..=a].copy_from_slice(&knots[..=a]);
    for j in b + P..=m {
        ub[j + r + 1] = knots[j];
    }
    let (mut i, mut k) = (b + P - 1, b + P + r);
    for j in (0..=r).rev() {
        while extra[j] <= knots[i] && i > a {
            let (dst, src) = (row(k - P - 1), row(i - P - 1));
            q[dst].copy_from_slice(&pts[src]);
            ub[k] = knots[i];
            k -= 1;
            i -= 1;
        }
        q.copy_within(row(k - P), (k - P - 1) * cols);
        for l in 1..=P {
            let ind = k - P + l;
            let alfa = ub[k + l] - extra[j];
            if alfa == 0.0 {
                q.copy_within(row(ind), (ind - 1) * cols);
            } else {
                let alfa = alfa / (ub[k + l] - knots[i + l - P]);
                for c in 0..cols {
                    q[(ind - 1) * cols + c] =
                        q[(ind - 1) * cols + c] * alfa + q[ind * cols + c] * (1.0 - alfa);
                }
            }
        }
        ub[k] = extra[j];
        k -= 1;
    }
    (ub, rows + r + 1, q)
}

/// Transposes a row-major `rows × cols` table.
fn transpose(data: &[DVec3], rows: usize, cols: usize) -> Vec<DVec3> {
    let mut t = vec![DVec3::ZERO; data.len()];
    for i in 0..rows {
        for j in 0..cols {
            t[j * rows + i] = data[i * cols + j];
        }
    }
    t
}

/// The Gordon surface G = L1 + L2 − Tg of a compatible curve network (Dagnino–Lamberti–Remogna eqs. (39)–(40)).
///
/// # Template
/// * **What**: the Gordon boolean sum G = L1 + L2 − Tg of Dagnino–Lamberti–Remogna §4.2 (ii), eqs. (39)–(40): two biquadratic
///   skinning surfaces minus the tensor interpolant of the intersections.
/// * **Interpolates**: every curve of a compatible network (the boolean-sum property).
/// * **Continuity**: C¹ (biquadratic on the merged knots).
/// * **Parametrisation**: the network's breakpoints, (u, v) ∈ [u_0, u_m] × [v_0, v_n].
///
/// # Example
/// ```
/// use splinelab::{network::examples, Surface, gordon::GordonSurface};
/// let net = examples::uniform_dome();
/// let s = GordonSurface::new(&net)?;
/// assert_eq!(s.domain(), ((net.u[0], net.u[3]), (net.v[0], net.v[3])));
/// // through every network curve: S(u_r, v) = φ_r(v), S(u, v_s) = ψ_s(u)
/// for r in 0..net.u.len() {
///     for v in [0.1, 0.45, 0.8] {
///         assert!((s.eval(net.u[r], v) - net.phi(r, v)[0]).length() < 1e-12);
///     }
/// }
/// for (sv, &v) in net.v.iter().enumerate() {
///     assert!((s.eval(0.3, v) - net.psi(sv, 0.3)[0]).length() < 1e-12);
/// }
/// # Ok::<(), splinelab::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct GordonSurface {
    u_bar: Vec<f64>,
    v_bar: Vec<f64>,
    l1: BSplineSurface<DVec3>,
    l2: BSplineSurface<DVec3>,
    tg: BSplineSurface<DVec3>,
    sum: BSplineSurface<DVec3>,
}

impl GordonSurface {
    /// Builds G. Errors: a malformed or incompatible network (C2 residual above
    /// [`COMPATIBILITY_TOL`]·max(1, scale)), m < 2 or n < 2 (`network.u` / `network.v`).
    pub fn new(net: &Network) -> Result<Self> {
        Self::with_tolerance(net, COMPATIBILITY_TOL)
    }

    /// Like [`GordonSurface::new`] with a custom relative compatibility tolerance.
    pub fn with_tolerance(net: &Network, rel_tol: f64) -> Result<Self> {
        let i_rs = intersections(net, rel_tol)?;
        let (m, n) = (net.m(), net.n());
        if m < 2 {
            return Err(Error::too_few(
                "network.u",
                format!(
                    "the Gordon surface needs m ≥ 2 (at least 3 breakpoints u₀..uₘ), got m = {m}"
                ),
            ));
        }
        if n < 2 {
            return Err(Error::too_few(
                "network.v",
                format!(
                    "the Gordon surface needs n ≥ 2 (at least 3 breakpoints v₀..vₙ), got n = {n}"
                ),
            ));
        }
        let (uk, vk) = (quadratic_knots(&net.u), quadratic_knots(&net.v));
        let u_bar = knots::averaging(&net.u, 2);
        let v_bar = knots::averaging(&net.v, 2);

        // L1 on Ū × V: for each j, interpolate P_j^{(r)} over r at u_r.  (m+1) × (n+2)
        let p_flat: Vec<DVec3> = net.p.iter().flatten().copied().collect();
        let l1_pts = skin(&u_bar, &net.u, &p_flat, n + 2, "network.u")?;
        let l1 = BSplineSurface::new(2, 2, u_bar.clone(), vk.clone(), m + 1, n + 2, l1_pts)?;

        // L2 on U × V̄: for each i, interpolate Q_i^{(s)} over s at v_s.  (m+2) × (n+1)
        let q_flat: Vec<DVec3> = net.q.iter().flatten().copied().collect();
        let l2_t = skin(&v_bar, &net.v, &q_flat, m + 2, "network.v")?; // (n+1) × (m+2)
        let l2 = BSplineSurface::new(
            2,
            2,
            uk.clone(),
            v_bar.clone(),
            m + 2,
            n + 1,
            transpose(&l2_t, n + 1, m + 2),
        )?;

        // Tg on Ū × V̄ interpolating I_rs.  (m+1) × (n+1)
        let i_flat: Vec<DVec3> = i_rs.iter().flatten().copied().collect();
        let a = skin(&u_bar, &net.u, &i_flat, n + 1, "network.u")?; // (m+1) × (n+1): rows over r
        let b_t = skin(
            &v_bar,
            &net.v,
            &transpose(&a, m + 1, n + 1),
            m + 1,
            "network.v",
        )?;
        let tg = BSplineSurface::new(
            2,
            2,
            u_bar.clone(),
            v_bar.clone(),
            m + 1,
            n + 1,
            transpose(&b_t, n + 1, m + 1),
        )?;

        // Knot refinement to Ũ × Ṽ and the boolean sum of control points (eq. (40)).
        let ut = merge_knots(&uk, &u_bar);
        let vt = merge_knots(&vk, &v_bar);
        let refine = |s: &BSplineSurface<DVec3>| {
            let (nu, nv) = s.size();
            let (ku, nu2, pts) = insert_rows(
                s.knots_u(),
                &knots::missing_knots(s.knots_u(), &ut),
                s.points(),
                nu,
                nv,
            );
            let (kv, nv2, pts_t) = insert_rows(
                s.knots_v(),
                &knots::missing_knots(s.knots_v(), &vt),
                &transpose(&pts, nu2, nv),
                nv,
                nu2,
            );
            BSplineSurface::new(2, 2, ku, kv, nu2, nv2, transpose(&pts_t, nv2, nu2))
        };
        let (r1, r2, rt) = (refine(&l1)?, refine(&l2)?, refine(&tg)?);
        let (nu, nv) = (ut.len() - 3, vt.len() - 3);
        for s in [&r1, &r2, &rt] {
            if s.size() != (nu, nv) || s.knots_u() != ut.as_slice() || s.knots_v() != vt.as_slice()
            {
                return Err(Error::degenerate(
                    "network",
                    "knot refinement did not reach the merged knot vectors (coincident breakpoints?)",
                ));
            }
        }
        let pts: Vec<DVec3> = (0..nu * nv)
            .map(|k| r1.points()[k] + r2.points()[k] - rt.points()[k])
            .collect();
        let sum = BSplineSurface::new(2, 2, ut, vt, nu, nv, pts)?;
        Ok(GordonSurface {
            u_bar,
            v_bar,
            l1,
            l2,
            tg,
            sum,
        })
    }

    /// Ū, the averaged knots in u (Piegl–Tiller (9.8)).
    pub fn knots_u_bar(&self) -> &[f64] {
        &self.u_bar
    }
    /// V̄, the averaged knots in v.
    pub fn knots_v_bar(&self) -> &[f64] {
        &self.v_bar
    }
    /// Ũ = U ∪ Ū (2m + 3 knots).
    pub fn knots_u(&self) -> &[f64] {
        self.sum.knots_u()
    }
    /// Ṽ = V ∪ V̄ (2n + 3 knots).
    pub fn knots_v(&self) -> &[f64] {
        self.sum.knots_v()
    }
    /// C̃ of eq. (40): 2m × 2n points, index `i * 2n + j`.
    pub fn control_points(&self) -> &[DVec3] {
        self.sum.points()
    }
    /// `(2m, 2n)`.
    pub fn size(&self) -> (usize, usize) {
        self.sum.size()
    }
    /// G as one biquadratic B-spline surface on Ũ × Ṽ.
    pub fn surface(&self) -> &BSplineSurface<DVec3> {
        &self.sum
    }
    /// The skinned surface L1 on Ū × V (before refinement).
    pub fn l1(&self) -> &BSplineSurface<DVec3> {
        &self.l1
    }
    /// The skinned surface L2 on U × V̄.
    pub fn l2(&self) -> &BSplineSurface<DVec3> {
        &self.l2
    }
    /// The tensor-product interpolant Tg on Ū × V̄.
    pub fn tg(&self) -> &BSplineSurface<DVec3> {
        &self.tg
    }
}

impl Surface<DVec3> for GordonSurface {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        self.sum.domain()
    }
    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [DVec3; 3]) {
        self.sum.eval_derivs(u, v, derivs, out)
    }
    /// The kernel's grid sampler on the tensor B-spline this surface is.
    fn sample_grid_into(
        &self,
        us: &[f64],
        vs: &[f64],
        derivs: bool,
        points: &mut [f64],
        du: &mut [f64],
        dv: &mut [f64],
    ) {
        self.sum.sample_grid_into(us, vs, derivs, points, du, dv)
    }
}
