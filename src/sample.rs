//! Evaluating constructions at many parameters into caller-owned flat buffers.
//!
//! Every curve construction implements [`Curve`] and every surface [`Surface`]; the API layer then uses
//! one code path ([`eval_curve_into`], [`eval_surface_into`]) for all of them. Buffers are flat `f64`
//! (`DIM` coordinates per point, points in parameter order) and are written without allocating per point.

use crate::error::{Error, Result};
use crate::kernel::PiecewisePoly;
use crate::point::Point;

/// Hard limit on evaluation points per call (the API contract).
pub const MAX_EVAL_POINTS: usize = 1_000_000;
/// Hard limit on input points per call (the API contract).
pub const MAX_INPUT_POINTS: usize = 100_000;

/// A parametric curve with up to two derivatives with respect to its global parameter.
pub trait Curve<P: Point> {
    /// The parameter interval `[start, end]`.
    fn domain(&self) -> (f64, f64);
    /// Position and derivatives up to `order` (≤ 2) at `u`: `out[k]` = k-th derivative, for k = 0..=order.
    /// `out.len() > order`. Parameters outside the domain are clamped or extrapolated by the last piece,
    /// as the construction documents.
    fn eval_derivs(&self, u: f64, order: usize, out: &mut [P; 3]);

    /// The curve as a piecewise polynomial, when it is one (B-splines, Bézier splines and the
    /// constructions that reduce to them): the kernel's fast path ([`crate::kernel`]). Built per call,
    /// O(segments · degree²); `None` (the default) means every parameter goes through
    /// [`Self::eval_derivs`].
    fn piecewise(&self) -> Option<PiecewisePoly<P>> {
        None
    }

    /// Batch evaluation at `params` into flat buffers (see [`eval_curve_into`]). The default uses
    /// [`Self::piecewise`] when there is one, else [`Self::eval_derivs`] per point; constructions with
    /// their own per-segment sampler (the quasi-cubic curve) override it.
    fn sample_into(
        &self,
        params: &[f64],
        order: usize,
        points: &mut [f64],
        d1: &mut [f64],
        d2: &mut [f64],
    ) {
        match self.piecewise() {
            Some(pp) => pp.sample_into(params, order.min(2), points, d1, d2),
            None => eval_curve_generic_into(self, params, order, points, d1, d2),
        }
    }

    /// Positions at `count` uniform parameters ([`uniform_params`]) over the domain into `out`
    /// (`count · DIM` entries). Default: the piecewise polynomial's uniform sampler, else per point.
    fn sample_uniform_into(&self, count: usize, out: &mut [f64]) {
        match self.piecewise() {
            Some(pp) if pp.domain() == self.domain() => pp.sample_uniform_into(count, out),
            _ => {
                let (a, b) = self.domain();
                let params = uniform_params(a, b, count);
                eval_curve_generic_into(self, &params, 0, out, &mut [], &mut []);
            }
        }
    }

    /// Positions and derivatives up to `order` (≤ 2) at `count` uniform parameters ([`uniform_params`])
    /// over the domain, into flat buffers as [`Self::sample_into`]. Default: [`Self::sample_into`] at those
    /// parameters; the quasi-cubic curve overrides it with its block sampler (no `sin_cos` per point).
    fn sample_uniform_derivs_into(
        &self,
        count: usize,
        order: usize,
        points: &mut [f64],
        d1: &mut [f64],
        d2: &mut [f64],
    ) {
        let (a, b) = self.domain();
        let params = uniform_params(a, b, count);
        self.sample_into(&params, order, points, d1, d2)
    }

    /// The point at `u`.
    fn eval(&self, u: f64) -> P {
        let mut out = [P::ZERO; 3];
        self.eval_derivs(u, 0, &mut out);
        out[0]
    }

    /// The curvature at `u`, from the first two derivatives by the one formula of every curve type
    /// ([`Point::curvature_of`]: signed in the plane, unsigned in 3D; 0 where c′ = 0).
    fn curvature(&self, u: f64) -> f64 {
        let mut out = [P::ZERO; 3];
        self.eval_derivs(u, 2, &mut out);
        P::curvature_of(out[1], out[2])
    }

    /// The period of a closed curve (c(u + T) = c(u) for the parameter length T of its domain), `None`
    /// (the default) for an open one.
    fn period(&self) -> Option<f64> {
        None
    }
}

/// A parametric surface with first partial derivatives.
pub trait Surface<P: Point> {
    /// The parameter rectangle `((u0, u1), (v0, v1))`.
    fn domain(&self) -> ((f64, f64), (f64, f64));
    /// `[S, ∂S/∂u, ∂S/∂v]` at `(u, v)`; the partials only when `derivs` (else left as they were).
    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [P; 3]);

    /// Samples the u-major grid `us × vs` (point `iu · vs.len() + iv`) into flat buffers (`du`, `dv` only
    /// when `derivs`). The default evaluates point by point; tensor-product surfaces override it with the
    /// kernel's grid sampler ([`crate::kernel::TensorGrid`]).
    #[allow(clippy::too_many_arguments)]
    fn sample_grid_into(
        &self,
        us: &[f64],
        vs: &[f64],
        derivs: bool,
        points: &mut [f64],
        du: &mut [f64],
        dv: &mut [f64],
    ) {
        grid_generic_into(self, us, vs, derivs, points, du, dv)
    }

    /// The point at `(u, v)`.
    fn eval(&self, u: f64, v: f64) -> P {
        let mut out = [P::ZERO; 3];
        self.eval_derivs(u, v, false, &mut out);
        out[0]
    }

    /// The periods `(in u, in v)` of a surface closed in that direction (S(u + T, v) = S(u, v)), `None`
    /// (the default) for an open direction.
    fn periods(&self) -> (Option<f64>, Option<f64>) {
        (None, None)
    }
}

/// `count` uniform parameters over `[a, b]`, ends included (`count == 1` gives `[a]`).
pub fn uniform_params(a: f64, b: f64, count: usize) -> Vec<f64> {
    match count {
        0 => Vec::new(),
        1 => vec![a],
        _ => {
            let step = (b - a) / (count - 1) as f64;
            let mut v: Vec<f64> = (0..count).map(|i| a + step * i as f64).collect();
            v[count - 1] = b;
            v
        }
    }
}

/// The index of the first non-finite entry of `xs` (NaN or ±∞), `None` when all are finite.
///
/// A branch-free pass over blocks of 1024 — an entry is non-finite exactly when its 11 exponent bits are
/// all set, i.e. when `(bits & EXP) + 2⁵²` reaches bit 63, so the block's flag is an OR of integer sums,
/// which vectorises — and a search only inside a block whose flag is set.
pub fn first_non_finite(xs: &[f64]) -> Option<usize> {
    const EXP: u64 = 0x7ff0_0000_0000_0000;
    const ONE: u64 = 1 << 52;
    const BLOCK: usize = 1024;
    for (b, block) in xs.chunks(BLOCK).enumerate() {
        let flags = block
            .iter()
            .fold(0u64, |acc, x| acc | ((x.to_bits() & EXP) + ONE));
        if flags >> 63 != 0 {
            return block
                .iter()
                .position(|x| !x.is_finite())
                .map(|i| b * BLOCK + i);
        }
    }
    None
}

/// Checks a requested evaluation count against [`MAX_EVAL_POINTS`].
pub fn check_eval_count(field: &'static str, count: usize) -> Result<()> {
    if count > MAX_EVAL_POINTS {
        Err(Error::too_many(
            field,
            format!("at most {MAX_EVAL_POINTS} evaluation points per call, got {count}"),
        ))
    } else {
        Ok(())
    }
}

/// Curvatures from flat derivative buffers `d1`, `d2` (`DIM` coordinates per point, as
/// [`eval_curve`] writes them), by [`Point::curvature_of`] (signed in the plane, unsigned in 3D).
pub fn curvatures<P: Point>(d1: &[f64], d2: &[f64]) -> Vec<f64> {
    d1.chunks_exact(P::DIM)
        .zip(d2.chunks_exact(P::DIM))
        .map(|(a, b)| match (P::from_coords(a), P::from_coords(b)) {
            (Some(a), Some(b)) => P::curvature_of(a, b),
            _ => 0.0,
        })
        .collect()
}

/// Unit left normals (−y′, x′)/|c′| of a planar curve from its flat first-derivative buffer (`[0, 0]`
/// where c′ = 0).
pub fn left_normals(d1: &[f64]) -> Vec<f64> {
    let mut out = Vec::with_capacity(d1.len());
    for a in d1.chunks_exact(2) {
        let s = (a[0] * a[0] + a[1] * a[1]).sqrt();
        if s > 0.0 {
            out.extend_from_slice(&[-a[1] / s, a[0] / s]);
        } else {
            out.extend_from_slice(&[0.0, 0.0]);
        }
    }
    out
}

/// Evaluates `curve` at `params`, writing positions into `points` and, when `order ≥ 1` / `order ≥ 2`,
/// derivatives into `d1` / `d2`. Each buffer has `params.len() * P::DIM` entries (unused ones may be empty).
/// Goes through [`Curve::sample_into`]: the kernel's per-span sampler when the curve is a piecewise
/// polynomial ([`Curve::piecewise`]), a construction's own sampler where it has one.
pub fn eval_curve_into<P: Point, C: Curve<P> + ?Sized>(
    curve: &C,
    params: &[f64],
    order: usize,
    points: &mut [f64],
    d1: &mut [f64],
    d2: &mut [f64],
) {
    curve.sample_into(params, order, points, d1, d2)
}

/// Like [`eval_curve_into`] but always point by point through [`Curve::eval_derivs`] (the reference the
/// fast paths are tested against).
pub fn eval_curve_generic_into<P: Point, C: Curve<P> + ?Sized>(
    curve: &C,
    params: &[f64],
    order: usize,
    points: &mut [f64],
    d1: &mut [f64],
    d2: &mut [f64],
) {
    let dim = P::DIM;
    let mut out = [P::ZERO; 3];
    for (i, &u) in params.iter().enumerate() {
        curve.eval_derivs(u, order, &mut out);
        out[0].write_coords(&mut points[i * dim..]);
        if order >= 1 {
            out[1].write_coords(&mut d1[i * dim..]);
        }
        if order >= 2 {
            out[2].write_coords(&mut d2[i * dim..]);
        }
    }
}

/// Positions at `count` uniform parameters ([`uniform_params`]) over the curve's domain, through the
/// kernel's uniform sampler when the curve is a piecewise polynomial (forward differences for cubics).
pub fn eval_curve_uniform<P: Point, C: Curve<P> + ?Sized>(curve: &C, count: usize) -> Vec<f64> {
    let mut pts = vec![0.0; count * P::DIM];
    curve.sample_uniform_into(count, &mut pts);
    pts
}

/// Flat buffers of a curve evaluation: `(points, d1, d2)`, the derivative ones empty when not asked for.
pub fn eval_curve<P: Point, C: Curve<P> + ?Sized>(
    curve: &C,
    params: &[f64],
    order: usize,
) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let n = params.len() * P::DIM;
    let mut pts = vec![0.0; n];
    let mut d1 = vec![0.0; if order >= 1 { n } else { 0 }];
    let mut d2 = vec![0.0; if order >= 2 { n } else { 0 }];
    eval_curve_into(curve, params, order, &mut pts, &mut d1, &mut d2);
    (pts, d1, d2)
}

/// Evaluates `surface` at the `(u, v)` pairs `uv` (flat, `2 * count` entries) into flat buffers
/// `(points, du, dv)`; `du`, `dv` are empty unless `derivs`.
pub fn eval_surface<P: Point, S: Surface<P> + ?Sized>(
    surface: &S,
    uv: &[f64],
    derivs: bool,
) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let count = uv.len() / 2;
    let n = count * P::DIM;
    let mut pts = vec![0.0; n];
    let mut du = vec![0.0; if derivs { n } else { 0 }];
    let mut dv = vec![0.0; if derivs { n } else { 0 }];
    eval_surface_into(surface, uv, derivs, &mut pts, &mut du, &mut dv);
    (pts, du, dv)
}

/// Like [`eval_surface`], into caller buffers.
pub fn eval_surface_into<P: Point, S: Surface<P> + ?Sized>(
    surface: &S,
    uv: &[f64],
    derivs: bool,
    points: &mut [f64],
    du: &mut [f64],
    dv: &mut [f64],
) {
    let dim = P::DIM;
    let mut out = [P::ZERO; 3];
    for (i, w) in uv.chunks_exact(2).enumerate() {
        surface.eval_derivs(w[0], w[1], derivs, &mut out);
        out[0].write_coords(&mut points[i * dim..]);
        if derivs {
            out[1].write_coords(&mut du[i * dim..]);
            out[2].write_coords(&mut dv[i * dim..]);
        }
    }
}

/// Flat buffers `(points, du, dv)` of `surface` on the u-major grid `us × vs` (through
/// [`Surface::sample_grid_into`]; `du`, `dv` empty unless `derivs`).
pub fn eval_surface_grid<P: Point, S: Surface<P> + ?Sized>(
    surface: &S,
    us: &[f64],
    vs: &[f64],
    derivs: bool,
) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let n = us.len() * vs.len() * P::DIM;
    let mut pts = vec![0.0; n];
    let mut du = vec![0.0; if derivs { n } else { 0 }];
    let mut dv = vec![0.0; if derivs { n } else { 0 }];
    surface.sample_grid_into(us, vs, derivs, &mut pts, &mut du, &mut dv);
    (pts, du, dv)
}

/// The point-by-point grid evaluation (the default of [`Surface::sample_grid_into`], and the reference
/// the grid samplers are tested against).
#[allow(clippy::too_many_arguments)]
pub fn grid_generic_into<P: Point, S: Surface<P> + ?Sized>(
    surface: &S,
    us: &[f64],
    vs: &[f64],
    derivs: bool,
    points: &mut [f64],
    du: &mut [f64],
    dv: &mut [f64],
) {
    let dim = P::DIM;
    let mut out = [P::ZERO; 3];
    let mut i = 0;
    for &u in us {
        for &v in vs {
            surface.eval_derivs(u, v, derivs, &mut out);
            out[0].write_coords(&mut points[i * dim..]);
            if derivs {
                out[1].write_coords(&mut du[i * dim..]);
                out[2].write_coords(&mut dv[i * dim..]);
            }
            i += 1;
        }
    }
}

/// The u-major grid of `(u, v)` pairs: index `iu * nv + iv`, uniform over the given rectangle.
pub fn uv_grid(domain: ((f64, f64), (f64, f64)), nu: usize, nv: usize) -> Vec<f64> {
    let us = uniform_params(domain.0 .0, domain.0 .1, nu);
    let vs = uniform_params(domain.1 .0, domain.1 .1, nv);
    let mut out = Vec::with_capacity(2 * nu * nv);
    for &u in &us {
        for &v in &vs {
            out.push(u);
            out.push(v);
        }
    }
    out
}

/// Maximum distance between two surfaces over a uniform `n × n` grid of their (common) domain — the
/// ‖·‖∞ measure of Dagnino–Lamberti–Remogna §4 (which uses n = 57), taken over all coordinates.
pub fn max_difference<P: Point, A: Surface<P> + ?Sized, B: Surface<P> + ?Sized>(
    a: &A,
    b: &B,
    n: usize,
) -> f64 {
    let uv = uv_grid(a.domain(), n, n);
    uv.chunks_exact(2)
        .map(|w| (a.eval(w[0], w[1]) - b.eval(w[0], w[1])).max_abs())
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    struct Parabola;
    impl Curve<DVec2> for Parabola {
        fn domain(&self) -> (f64, f64) {
            (0.0, 1.0)
        }
        fn eval_derivs(&self, u: f64, _order: usize, out: &mut [DVec2; 3]) {
            out[0] = DVec2::new(u, u * u);
            out[1] = DVec2::new(1.0, 2.0 * u);
            out[2] = DVec2::new(0.0, 2.0);
        }
    }

    #[test]
    fn uniform_params_include_ends() {
        assert_eq!(uniform_params(0.0, 1.0, 5), vec![0.0, 0.25, 0.5, 0.75, 1.0]);
        assert_eq!(uniform_params(2.0, 3.0, 1), vec![2.0]);
        assert!(uniform_params(0.0, 1.0, 0).is_empty());
    }

    #[test]
    fn flat_buffers() {
        let (p, d1, d2) = eval_curve(&Parabola, &[0.5, 1.0], 2);
        assert_eq!(p, vec![0.5, 0.25, 1.0, 1.0]);
        assert_eq!(d1, vec![1.0, 1.0, 1.0, 2.0]);
        assert_eq!(d2, vec![0.0, 2.0, 0.0, 2.0]);
        let (_, d1, d2) = eval_curve(&Parabola, &[0.5], 0);
        assert!(d1.is_empty() && d2.is_empty());
        assert!(check_eval_count("samples", MAX_EVAL_POINTS + 1).is_err());
    }

    #[test]
    fn grid_is_u_major() {
        let g = uv_grid(((0.0, 1.0), (0.0, 2.0)), 2, 3);
        assert_eq!(
            g,
            vec![0.0, 0.0, 0.0, 1.0, 0.0, 2.0, 1.0, 0.0, 1.0, 1.0, 1.0, 2.0]
        );
    }
}
