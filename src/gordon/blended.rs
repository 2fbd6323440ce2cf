//! The spline-blended surface GB of Kuklišová §7 eq. (4) (`../shared/spec/surfaces.md` §6):
//!
//! GB(u, v) = G1 + G2 − G12, G1 = Σ_r F(u_r, v)·L_r(u), G2 = Σ_s F(u, v_s)·M_s(v),
//! G12 = Σ_r Σ_s F(u_r, v_s)·L_r(u)·M_s(v),
//!
//! where F is the network, read only on the lines u = u_r and v = v_s ([`LineNetwork`]), and L_r, M_s are
//! blending functions ([`BlendFunctions`]): the cardinal C² cubic splines on the nodes (natural or
//! not-a-knot end conditions; L_r(u_q) = δ_rq), so GB interpolates every network curve. GB is the
//! boolean sum P1 ⊕ P2 of the two univariate spline projectors, hence reproduces every function
//! a(u) + b(v) + c·uv with a, b reproduced by the blends (P₂ in particular), where it equals S and G.
//!
//! G12 is precomputed as a bicubic tensor-product B-spline (its coefficients Σ_rs c_rk d_sl F(u_r, v_s)).

use super::blend::{BlendFunctions, CubicEnd};
use super::quadratic_knots;
use crate::b2spline::{B2Scheme, Construction, Tension};
use crate::bspline::{basis_derivs, BSplineSurface};
use crate::error::{Error, Result};
use crate::knots::{find_span, MAX_DEGREE};
use crate::network::Network;
use crate::sample::Surface;
use glam::DVec3;

/// How GB blends the network curves.
#[derive(Debug, Clone, PartialEq)]
pub enum Blend {
    /// Cardinal C² cubic splines on the nodes, natural end conditions (m, n ≥ 1).
    CubicNatural,
    /// Cardinal C² cubic splines on the nodes, not-a-knot end conditions (m, n ≥ 3).
    CubicNotAKnot,
    /// The B2 basis functions of Kuklišová on the data knots u_{−1}..u_{m+2}, v_{−1}..v_{n+2} (the network is
    /// sampled on all those lines, auxiliary ones included); see [`blend_functions`].
    B2 {
        /// The approximation parameter a (0 interpolates the inner lines).
        a: f64,
        /// Tension p of the u blend: one value or p_0..p_m (m + 1 values).
        tension_u: Tension,
        /// Tension of the v blend.
        tension_v: Tension,
        /// The last coefficient of the tension denominators (1 = eq. (8)/(9) as printed).
        c2: f64,
    },
}

/// A network read on its lines: the v-curves F(u_r, v) and the u-curves F(u, v_s).
pub trait LineNetwork {
    /// The nodes u_r of the v-curves.
    fn u_nodes(&self) -> &[f64];
    /// The nodes v_s of the u-curves.
    fn v_nodes(&self) -> &[f64];
    /// Calls `f(r, F(u_r, v), ∂F/∂v(u_r, v))` for every r (the derivative only when `derivs`, else 0).
    fn v_curves(&self, v: f64, derivs: bool, f: &mut dyn FnMut(usize, DVec3, DVec3));
    /// Calls `f(s, F(u, v_s), ∂F/∂u(u, v_s))` for every s.
    fn u_curves(&self, u: f64, derivs: bool, f: &mut dyn FnMut(usize, DVec3, DVec3));
    /// The node F(u_r, v_s).
    fn node(&self, r: usize, s: usize) -> DVec3;
}

/// The curves of a seed-004 [`Network`] as a [`LineNetwork`] (exact derivatives).
#[derive(Debug, Clone)]
pub struct NetworkLines {
    u: Vec<f64>,
    v: Vec<f64>,
    uk: Vec<f64>,
    vk: Vec<f64>,
    p: Vec<Vec<DVec3>>,
    q: Vec<Vec<DVec3>>,
    nodes: Vec<Vec<DVec3>>,
}

impl NetworkLines {
    /// Checks the network (shape, size, compatibility to [`super::COMPATIBILITY_TOL`]) and keeps its
    /// curves.
    pub fn new(net: &Network) -> Result<Self> {
        Self::with_tolerance(net, super::COMPATIBILITY_TOL)
    }

    /// Like [`NetworkLines::new`] with a custom relative compatibility tolerance.
    pub fn with_tolerance(net: &Network, rel_tol: f64) -> Result<Self> {
        let nodes = super::intersections(net, rel_tol)?;
        Ok(NetworkLines {
            u: net.u.clone(),
            v: net.v.clone(),
            uk: quadratic_knots(&net.u),
            vk: quadratic_knots(&net.v),
            p: net.p.clone(),
            q: net.q.clone(),
            nodes,
        })
    }
}

type Ders = [[f64; MAX_DEGREE + 1]; 3];

fn quad_basis(knots: &[f64], t: f64, derivs: bool) -> (usize, Ders) {
    let count = knots.len() - 3;
    let span = find_span(knots, 2, count, t);
    let mut d = [[0.0; MAX_DEGREE + 1]; 3];
    basis_derivs(knots, 2, span, t, usize::from(derivs), &mut d);
    (span, d)
}

impl LineNetwork for NetworkLines {
    fn u_nodes(&self) -> &[f64] {
        &self.u
    }
    fn v_nodes(&self) -> &[f64] {
        &self.v
    }
    fn v_curves(&self, v: f64, derivs: bool, f: &mut dyn FnMut(usize, DVec3, DVec3)) {
        let (span, d) = quad_basis(&self.vk, v, derivs);
        for (r, row) in self.p.iter().enumerate() {
            let (mut x, mut dx) = (DVec3::ZERO, DVec3::ZERO);
            for b in 0..=2 {
                let c = row[span - 2 + b];
                x += c * d[0][b];
                dx += c * d[1][b];
            }
            f(r, x, dx);
        }
    }
    fn u_curves(&self, u: f64, derivs: bool, f: &mut dyn FnMut(usize, DVec3, DVec3)) {
        let (span, d) = quad_basis(&self.uk, u, derivs);
        for (s, row) in self.q.iter().enumerate() {
            let (mut x, mut dx) = (DVec3::ZERO, DVec3::ZERO);
            for a in 0..=2 {
                let c = row[span - 2 + a];
                x += c * d[0][a];
                dx += c * d[1][a];
            }
            f(s, x, dx);
        }
    }
    fn node(&self, r: usize, s: usize) -> DVec3 {
        self.nodes[r][s]
    }
}

/// A network given by a function F(u, v), read on the lines u = u_r, v = v_s only. Derivatives along the
/// lines are central differences with step `h` = 2⁻²⁰ × the extent of the nodes (the blends' derivatives are
/// exact).
#[derive(Clone)]
pub struct FnLines<F> {
    f: F,
    u: Vec<f64>,
    v: Vec<f64>,
    hu: f64,
    hv: f64,
}

impl<F> std::fmt::Debug for FnLines<F> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("FnLines")
            .field("u", &self.u)
            .field("v", &self.v)
            .finish_non_exhaustive()
    }
}

/// The finite-difference step used by [`FnLines`] for nodes `x`.
pub(crate) fn fd_step(x: &[f64]) -> f64 {
    let ext = match (x.first(), x.last()) {
        (Some(a), Some(b)) => (b - a).abs(),
        _ => 1.0,
    };
    ext.max(f64::MIN_POSITIVE) * (2.0f64).powi(-20)
}

impl<F: Fn(f64, f64) -> DVec3> FnLines<F> {
    /// The lines u = u_r (`u`) and v = v_s (`v`) of `f`.
    pub fn new(f: F, u: Vec<f64>, v: Vec<f64>) -> Self {
        let (hu, hv) = (fd_step(&u), fd_step(&v));
        FnLines { f, u, v, hu, hv }
    }
}

impl<F: Fn(f64, f64) -> DVec3> LineNetwork for FnLines<F> {
    fn u_nodes(&self) -> &[f64] {
        &self.u
    }
    fn v_nodes(&self) -> &[f64] {
        &self.v
    }
    fn v_curves(&self, v: f64, derivs: bool, f: &mut dyn FnMut(usize, DVec3, DVec3)) {
        for (r, &u) in self.u.iter().enumerate() {
            let d = if derivs {
                ((self.f)(u, v + self.hv) - (self.f)(u, v - self.hv)) * (0.5 / self.hv)
            } else {
                DVec3::ZERO
            };
            f(r, (self.f)(u, v), d);
        }
    }
    fn u_curves(&self, u: f64, derivs: bool, f: &mut dyn FnMut(usize, DVec3, DVec3)) {
        for (s, &v) in self.v.iter().enumerate() {
            let d = if derivs {
                ((self.f)(u + self.hu, v) - (self.f)(u - self.hu, v)) * (0.5 / self.hu)
            } else {
                DVec3::ZERO
            };
            f(s, (self.f)(u, v), d);
        }
    }
    fn node(&self, r: usize, s: usize) -> DVec3 {
        (self.f)(self.u[r], self.v[s])
    }
}

/// The blending functions of `blend` on `nodes` (`field` names the nodes). `v_direction` picks the tension
/// of the B2 blend (`tension_v` instead of `tension_u`).
///
/// For [`Blend::B2`] the nodes are the data knots u_{−1}..u_{m+2} (m ≥ 2): L_j is the B2-spline of Kuklišová
/// (non-uniform construction, eq. (5) corrected, (8)/(9) with `c2`, approximation parameter `a`) of the
/// unit data e_j, i.e. the column j of [`B2Scheme::control_matrix`] on the cubic Farin knots; its domain is
/// [u_1, u_m] and, for a = 0, L_j(u_k) = δ_jk for k = 1..m.
pub fn blend_functions(
    field: &'static str,
    nodes: &[f64],
    blend: &Blend,
    v_direction: bool,
) -> Result<BlendFunctions> {
    match blend {
        Blend::CubicNatural => BlendFunctions::cardinal_cubic(field, nodes, CubicEnd::Natural),
        Blend::CubicNotAKnot => BlendFunctions::cardinal_cubic(field, nodes, CubicEnd::NotAKnot),
        Blend::B2 {
            a,
            tension_u,
            tension_v,
            c2,
        } => {
            crate::error::check_finite(field, nodes)?;
            if nodes.len() < 6 {
                return Err(Error::too_few(
                    field,
                    format!(
                        "the b2 blend needs at least 6 knots u₋₁..uₘ₊₂ (m ≥ 2), got {}",
                        nodes.len()
                    ),
                ));
            }
            if nodes.len() > super::MAX_LINES {
                return Err(Error::too_many(
                    field,
                    format!("at most {} lines, got {}", super::MAX_LINES, nodes.len()),
                ));
            }
            let n = nodes.len() - 4;
            let (tension, tfield) = if v_direction {
                (tension_v, "tensionV")
            } else {
                (tension_u, "tensionU")
            };
            let p = match tension {
                Tension::Scalar(p) => vec![*p; n + 1],
                Tension::PerVertex(ps) if ps.len() == n + 1 => ps.clone(),
                Tension::PerVertex(ps) => {
                    return Err(Error::size_mismatch(
                        tfield,
                        format!(
                        "expected one tension or {} values p₀..pₙ, n = {n} (one per inner line), got {}",
                        n + 1,
                        ps.len()
                    ),
                    ))
                }
            };
            let scheme = B2Scheme::new(nodes.to_vec(), p, *a, None, *c2, Construction::NonUniform)
                .map_err(|e| {
                    let f = e.field().to_string();
                    if f.starts_with("knots") {
                        e.in_field(f.replacen("knots", field, 1))
                    } else if f.starts_with("tension") {
                        e.in_field(tfield)
                    } else {
                        e
                    }
                })?;
            let cmat = scheme.control_matrix();
            let (m, count) = (nodes.len(), 2 * n + 1);
            let mut coef = vec![0.0; m * count];
            for r in 0..m {
                for k in 0..count {
                    coef[r * count + k] = cmat[k * m + r];
                }
            }
            BlendFunctions::from_coefficients(field, nodes.to_vec(), scheme.knots().to_vec(), coef)
        }
    }
}

/// GB = G1 + G2 − G12 (Kuklišová eq. (4)) through the lines of a [`LineNetwork`].
#[derive(Debug, Clone)]
pub struct SplineBlendedSurface<N> {
    lines: N,
    bu: BlendFunctions,
    bv: BlendFunctions,
    g12: BSplineSurface<DVec3>,
}

impl<N: LineNetwork> SplineBlendedSurface<N> {
    /// Builds GB with the same kind of blend in u and v. The network must give finite values on its lines
    /// (checked at the nodes and at the span midpoints of every line; the error names `network`).
    pub fn new(lines: N, blend: Blend) -> Result<Self> {
        let bu = blend_functions("uKnots", lines.u_nodes(), &blend, false)?;
        let bv = blend_functions("vKnots", lines.v_nodes(), &blend, true)?;
        Self::with_blends(lines, bu, bv)
    }

    /// Builds GB with given blending functions (one per u-node and per v-node).
    pub(crate) fn with_blends(lines: N, bu: BlendFunctions, bv: BlendFunctions) -> Result<Self> {
        let (mu, mv) = (lines.u_nodes().len(), lines.v_nodes().len());
        if bu.len() != mu || bv.len() != mv {
            return Err(Error::size_mismatch(
                "network",
                format!(
                    "{mu} × {mv} network lines but {} × {} blending functions",
                    bu.len(),
                    bv.len()
                ),
            ));
        }
        // finiteness of the network on its lines
        let bad = |what: String| {
            Error::not_finite(
                "network",
                format!("the network must give finite points; it did not at {what}"),
            )
        };
        let mut nodes = vec![DVec3::ZERO; mu * mv];
        for r in 0..mu {
            for s in 0..mv {
                let p = lines.node(r, s);
                if !p.is_finite() {
                    return Err(bad(format!("the node (uᵣ, vₛ) with r = {r}, s = {s}")));
                }
                nodes[r * mv + s] = p;
            }
        }
        for w in lines.v_nodes().windows(2) {
            let mid = 0.5 * (w[0] + w[1]);
            let mut ok = true;
            lines.v_curves(mid, false, &mut |_, p, _| ok &= p.is_finite());
            if !ok {
                return Err(bad("a line u = uᵣ between two v nodes".to_string()));
            }
        }
        for w in lines.u_nodes().windows(2) {
            let mid = 0.5 * (w[0] + w[1]);
            let mut ok = true;
            lines.u_curves(mid, false, &mut |_, p, _| ok &= p.is_finite());
            if !ok {
                return Err(bad("a line v = vₛ between two u nodes".to_string()));
            }
        }
        // G12 as a bicubic B-spline: D_kl = Σ_r Σ_s c^u_rk c^v_sl F(u_r, v_s)
        let (cu, cv) = (bu.count(), bv.count());
        let mut tmp = vec![DVec3::ZERO; cu * mv]; // Σ_r c^u_rk F(u_r, v_s)  [k][s]
        for r in 0..mu {
            let c = bu.coefficients(r);
            for k in 0..cu {
                if c[k] != 0.0 {
                    for s in 0..mv {
                        tmp[k * mv + s] += nodes[r * mv + s] * c[k];
                    }
                }
            }
        }
        let mut d = vec![DVec3::ZERO; cu * cv];
        for s in 0..mv {
            let c = bv.coefficients(s);
            for l in 0..cv {
                if c[l] != 0.0 {
                    for k in 0..cu {
                        d[k * cv + l] += tmp[k * mv + s] * c[l];
                    }
                }
            }
        }
        let g12 = BSplineSurface::new(3, 3, bu.knots().to_vec(), bv.knots().to_vec(), cu, cv, d)?;
        Ok(SplineBlendedSurface { lines, bu, bv, g12 })
    }

    /// The blending functions L_r (u direction).
    pub(crate) fn blend_u(&self) -> &BlendFunctions {
        &self.bu
    }
    /// The blending functions M_s (v direction).
    pub(crate) fn blend_v(&self) -> &BlendFunctions {
        &self.bv
    }
    /// The network lines.
    pub fn lines(&self) -> &N {
        &self.lines
    }
    /// G12 as a bicubic B-spline surface.
    pub(crate) fn g12(&self) -> &BSplineSurface<DVec3> {
        &self.g12
    }
}

impl<N: LineNetwork> Surface<DVec3> for SplineBlendedSurface<N> {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        (self.bu.domain(), self.bv.domain())
    }
    /// The grid path of [`super::GridSurface`]: network curves and blending functions once per grid line.
    fn sample_grid_into(
        &self,
        us: &[f64],
        vs: &[f64],
        derivs: bool,
        points: &mut [f64],
        du: &mut [f64],
        dv: &mut [f64],
    ) {
        let g = super::GridSurface::eval_grid(self, us, vs, derivs);
        points[..g.points.len()].copy_from_slice(&g.points);
        if derivs {
            du[..g.du.len()].copy_from_slice(&g.du);
            dv[..g.dv.len()].copy_from_slice(&g.dv);
        }
    }
    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [DVec3; 3]) {
        let order = usize::from(derivs);
        let (nu, nv) = (self.bu.basis(u, order), self.bv.basis(v, order));
        let (mut g, mut gu, mut gv) = (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO);
        // G1 = Σ_r F(u_r, v) L_r(u)
        self.lines.v_curves(v, derivs, &mut |r, p, dp| {
            let l = self.bu.value(r, &nu);
            g += p * l[0];
            if derivs {
                gu += p * l[1];
                gv += dp * l[0];
            }
        });
        // G2 = Σ_s F(u, v_s) M_s(v)
        self.lines.u_curves(u, derivs, &mut |s, p, dp| {
            let mv = self.bv.value(s, &nv);
            g += p * mv[0];
            if derivs {
                gu += dp * mv[0];
                gv += p * mv[1];
            }
        });
        let mut t = [DVec3::ZERO; 3];
        self.g12.eval_derivs(u, v, derivs, &mut t);
        out[0] = g - t[0];
        if derivs {
            out[1] = gu - t[1];
            out[2] = gv - t[2];
        }
    }
}
