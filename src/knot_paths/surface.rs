//! Surfaces: the family s(u, v; u_p, v_q), its limits (Theorem 3) and envelopes (eqs. (6), (8)).

#![allow(clippy::needless_range_loop)] // index loops pair weights with control points

use super::knot_line::{check_knot_value, check_points};
use super::{Jet, KnotLine, Scalar, W};
use crate::bspline::BSplineSurface;
use crate::error::{Error, Result};
use crate::kernel::TensorGrid;
use crate::point::Point;
use crate::sample::Surface;

// ---------------------------------------------------------------------------------------------------
// Surfaces
// ---------------------------------------------------------------------------------------------------

/// A tensor-product B-spline surface (eq. (1)) with optionally the knot `u_p` and/or `v_q` replaced:
/// the families (5) and (7), extended to any values (module doc). Implements [`Surface`] at the current
/// `(up, vq)`.
///
/// # Template
/// * **What**: the family s(u, v; u_p, v_q) of Juhász–Hoffmann: a tensor B-spline surface (eq. (1))
///   with the knot u_p (and/or v_q) replaced by any finite value (families (5), (7)).
/// * **Interpolates**: nothing in general; with the knot unmoved it is the original surface.
/// * **Continuity**: that of the modified knot vectors (C^{k−1−μ} across a knot of multiplicity μ); across
///   u_p it drops when the moved knot meets a neighbour.
/// * **Parametrisation**: the domain [u_{k−1}, u_{n+1}] × [v_{l−1}, v_{m+1}] of the (modified) knots.
///
/// # Example
/// ```
/// use glam::DVec3;
/// use splinelab::{knot_paths::KnotModifiedSurface, Surface};
/// let knots = vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0]; // order 3, 4 control points, interior knot p = 3
/// let pts: Vec<DVec3> = (0..16).map(|i| DVec3::new((i / 4) as f64, (i % 4) as f64, ((i * 7) % 5) as f64)).collect();
/// let s0 = KnotModifiedSurface::new(3, 3, knots.clone(), knots.clone(), 4, 4, pts.clone(), None, None)?;
/// // moving u_3 to its own value changes nothing
/// let s1 = KnotModifiedSurface::new(3, 3, knots.clone(), knots, 4, 4, pts, Some((3, 1.0)), None)?;
/// for (u, v) in [(0.2, 0.3), (1.0, 1.5), (1.7, 0.9)] {
///     assert!((s0.eval(u, v) - s1.eval(u, v)).length() < 1e-12);
/// }
/// assert_eq!(s0.domain(), ((0.0, 2.0), (0.0, 2.0)));
/// # Ok::<(), splinelab::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct KnotModifiedSurface<P: Point> {
    lu: KnotLine,
    lv: KnotLine,
    /// `d_rs` at `r * nv + s`.
    points: Vec<P>,
    up: f64,
    vq: f64,
}

/// A limit control row or column with its index (Theorem 3).
pub type LimitRow<P> = (usize, Vec<P>);

/// Which knot a derivative is taken with respect to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Var {
    /// The surface parameter u.
    U,
    /// The surface parameter v.
    V,
    /// The moved knot u_p.
    Up,
    /// The moved knot v_q.
    Vq,
}

impl<P: Point> KnotModifiedSurface<P> {
    /// The surface of orders `(k, l)` with knots `knots_u` (`nu + k`), `knots_v` (`nv + l`) and the control
    /// net `points[r * nv + s]` = d_rs (`nu × nv`), with knot `p` of u replaced by `up` and knot `q` of v by
    /// `vq` (either, both or none).
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        order_u: usize,
        order_v: usize,
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
        nu: usize,
        nv: usize,
        points: Vec<P>,
        moved_u: Option<(usize, f64)>,
        moved_v: Option<(usize, f64)>,
    ) -> Result<Self> {
        if points.len() != nu * nv {
            return Err(Error::size_mismatch(
                "controlPoints",
                format!("expected {nu} × {nv} control points, got {}", points.len()),
            ));
        }
        check_points("controlPoints", &points, nv)?;
        let lu = KnotLine::new(
            "knotsU",
            "orderU",
            "p",
            order_u,
            knots_u,
            nu,
            moved_u.map(|m| m.0),
        )?;
        let lv = KnotLine::new(
            "knotsV",
            "orderV",
            "q",
            order_v,
            knots_v,
            nv,
            moved_v.map(|m| m.0),
        )?;
        let up = moved_u.map_or(0.0, |m| m.1);
        let vq = moved_v.map_or(0.0, |m| m.1);
        check_knot_value("up", up)?;
        check_knot_value("vq", vq)?;
        Ok(KnotModifiedSurface {
            lu,
            lv,
            points,
            up,
            vq,
        })
    }

    /// The knot line in u.
    pub fn line_u(&self) -> &KnotLine {
        &self.lu
    }
    /// The knot line in v.
    pub fn line_v(&self) -> &KnotLine {
        &self.lv
    }
    /// `(nu, nv)`.
    pub fn size(&self) -> (usize, usize) {
        (self.lu.count, self.lv.count)
    }
    /// The control point (r, s): r along u, s along v.
    pub fn point(&self, r: usize, s: usize) -> P {
        self.points[r * self.lv.count + s]
    }
    /// The current values `(up, vq)` of the moved knots.
    pub fn knot_values(&self) -> (f64, f64) {
        (self.up, self.vq)
    }
    /// The same surface with the moved knots at `(up, vq)`.
    pub fn with_knots(&self, up: f64, vq: f64) -> Self {
        KnotModifiedSurface {
            lu: self.lu.clone(),
            lv: self.lv.clone(),
            points: self.points.clone(),
            up,
            vq,
        }
    }

    /// Σ_a Σ_b wu[a]_i wv[b]_j d: the Taylor coefficients `out[i][j]` of a tensor combination.
    fn combine<const N: usize, const M: usize>(
        &self,
        (iu, iv): (usize, usize),
        wu: &[Jet<N>; W],
        wv: &[Jet<M>; W],
    ) -> [[P; M]; N] {
        let (k, l) = (self.lu.order, self.lv.order);
        let nv = self.lv.count;
        let mut out = [[P::ZERO; M]; N];
        for a in 0..k {
            let r = iu + 1 + a - k;
            let mut row = [P::ZERO; M];
            for b in 0..l {
                let d = self.points[r * nv + iv + 1 + b - l];
                for (j, x) in row.iter_mut().enumerate() {
                    *x += d * wv[b].0[j];
                }
            }
            for (i, o) in out.iter_mut().enumerate() {
                for j in 0..M {
                    o[j] += row[j] * wu[a].0[i];
                }
            }
        }
        out
    }

    /// The Taylor coefficients `out[i][j]` = (1/(i! j!)) ∂^{i+j}/∂xⁱ∂yʲ of s(u, v; up, vq), where `x` is
    /// `u` or `up` (per `xu`) and `y` is `v` or `vq` (per `yv`). `left_u`/`left_v`: at `u = u_p`
    /// (`v = v_q`) use the piece on the left of the moved knot.
    #[allow(clippy::too_many_arguments)]
    pub fn taylor<const N: usize, const M: usize>(
        &self,
        u: f64,
        v: f64,
        up: f64,
        vq: f64,
        x: Var,
        y: Var,
        (left_u, left_v): (bool, bool),
    ) -> [[P; M]; N] {
        let iu = self.lu.span(u, up, left_u);
        let iv = self.lv.span(v, vq, left_v);
        let mut wu = [Jet::<N>::constant(0.0); W];
        let mut wv = [Jet::<M>::constant(0.0); W];
        match x {
            Var::Up => self
                .lu
                .weights(iu, Jet::constant(u), Jet::variable(up), &mut wu),
            _ => self
                .lu
                .weights(iu, Jet::variable(u), Jet::constant(up), &mut wu),
        }
        match y {
            Var::Vq => self
                .lv
                .weights(iv, Jet::constant(v), Jet::variable(vq), &mut wv),
            _ => self
                .lv
                .weights(iv, Jet::variable(v), Jet::constant(vq), &mut wv),
        }
        self.combine((iu, iv), &wu, &wv)
    }

    /// The point s(u, v; up, vq) (allocation-free; used for paths and path-surfaces).
    pub fn eval_at(&self, u: f64, v: f64, up: f64, vq: f64) -> P {
        self.taylor::<1, 1>(u, v, up, vq, Var::U, Var::V, (false, false))[0][0]
    }

    /// `(∂s/∂u_p, ∂s/∂v_q)` at `(u, v; up, vq)` (Theorems 7–8).
    pub fn d_dknots(&self, u: f64, v: f64, up: f64, vq: f64, left: (bool, bool)) -> (P, P) {
        let a = self.taylor::<2, 1>(u, v, up, vq, Var::Up, Var::V, left);
        let b = self.taylor::<1, 2>(u, v, up, vq, Var::U, Var::Vq, left);
        (a[1][0], b[0][1])
    }

    /// The path of the point `(u, v)` as `u_p` runs through `ups` (v_q at its current value), into `out`.
    pub fn path_into(&self, u: f64, v: f64, ups: &[f64], out: &mut Vec<P>) {
        out.extend(ups.iter().map(|&up| self.eval_at(u, v, up, self.vq)));
    }

    /// The path of `(u, v)` as `v_q` runs through `vqs` (u_p at its current value).
    pub fn path_v_into(&self, u: f64, v: f64, vqs: &[f64], out: &mut Vec<P>) {
        out.extend(vqs.iter().map(|&vq| self.eval_at(u, v, self.up, vq)));
    }

    /// The path-surface of `(u, v)`: s(u, v; up, vq) on the grid `ups × vqs`, `up`-major, into `out`.
    pub fn path_surface_into(&self, u: f64, v: f64, ups: &[f64], vqs: &[f64], out: &mut Vec<P>) {
        for &up in ups {
            out.extend(vqs.iter().map(|&vq| self.eval_at(u, v, up, vq)));
        }
    }

    /// The limit control curves of Theorem 3 (as control-point rows/columns of the net): for `u_p → −∞`
    /// row `p` (d_{p,s}), for `+∞` row `p − k`; for `v_q → −∞` column `q`, for `+∞` column `q − l`.
    /// Returns `(index, control points)` for (−∞, +∞) in the direction asked for.
    pub fn limit_curves(&self, dir: Var) -> Option<(LimitRow<P>, LimitRow<P>)> {
        let (nu, nv) = self.size();
        match dir {
            Var::U | Var::Up => {
                let p = self.lu.moved?;
                let row = |r: usize| (0..nv).map(|s| self.point(r, s)).collect::<Vec<P>>();
                Some(((p, row(p)), (p - self.lu.order, row(p - self.lu.order))))
            }
            Var::V | Var::Vq => {
                let q = self.lv.moved?;
                let col = |s: usize| (0..nu).map(|r| self.point(r, s)).collect::<Vec<P>>();
                Some(((q, col(q)), (q - self.lv.order, col(q - self.lv.order))))
            }
        }
    }

    /// The limit control points of Theorem 4 (corrected list, `surfaces.md` §8.6) for
    /// (u_p, v_q) → (−∞, −∞), (−∞, +∞), (+∞, −∞), (+∞, +∞): d_{p,q}, d_{p,q−l}, d_{p−k,q}, d_{p−k,q−l},
    /// each with its index pair.
    pub fn limit_points(&self) -> Option<[((usize, usize), P); 4]> {
        let (p, q) = (self.lu.moved?, self.lv.moved?);
        let (k, l) = (self.lu.order, self.lv.order);
        let at = |r: usize, s: usize| ((r, s), self.point(r, s));
        Some([at(p, q), at(p, q - l), at(p - k, q), at(p - k, q - l)])
    }

    /// The envelope (6) (only `u_p` moved), its v-analogue (only `v_q`), or (8) (both).
    pub fn envelope(&self) -> Option<KnotEnvelopeSurface<P>> {
        let eu = self.lu.envelope();
        let ev = self.lv.envelope();
        if eu.is_none() && ev.is_none() {
            return None;
        }
        Some(KnotEnvelopeSurface {
            lu: eu.unwrap_or_else(|| self.lu.clone()),
            lv: ev.unwrap_or_else(|| self.lv.clone()),
            points: self.points.clone(),
        })
    }
}

impl<P: Point> KnotModifiedSurface<P> {
    /// The tensor B-spline this surface is while both moved knots stay strictly between their
    /// neighbours (else `None`).
    pub fn bspline(&self) -> Option<BSplineSurface<P>> {
        let ku = self.lu.modified_knots(self.up)?;
        let kv = self.lv.modified_knots(self.vq)?;
        BSplineSurface::new(
            self.lu.order - 1,
            self.lv.order - 1,
            ku,
            kv,
            self.lu.count,
            self.lv.count,
            self.points.clone(),
        )
        .ok()
    }
}

impl<P: Point> Surface<P> for KnotModifiedSurface<P> {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        (self.lu.domain(), self.lv.domain())
    }
    /// The kernel's grid sampler while the moved knots stay strictly between their neighbours.
    fn sample_grid_into(
        &self,
        us: &[f64],
        vs: &[f64],
        derivs: bool,
        points: &mut [f64],
        du: &mut [f64],
        dv: &mut [f64],
    ) {
        match self.bspline() {
            Some(b) => TensorGrid::sample_into(&b.tensor_net(), us, vs, derivs, points, du, dv),
            None => crate::sample::grid_generic_into(self, us, vs, derivs, points, du, dv),
        }
    }
    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [P; 3]) {
        if derivs {
            let t = self.taylor::<2, 2>(u, v, self.up, self.vq, Var::U, Var::V, (false, false));
            out[0] = t[0][0];
            out[1] = t[1][0];
            out[2] = t[0][1];
        } else {
            out[0] = self.eval_at(u, v, self.up, self.vq);
        }
    }
}

/// The envelope surface e(w, v) of eq. (6), its v-analogue e(u, z), or e(w, z) of eq. (8)
/// (see [`KnotModifiedSurface::envelope`]). Implements [`Surface`] on `[u_{p−1}, u_{p+1}] × …`.
#[derive(Debug, Clone, PartialEq)]
pub struct KnotEnvelopeSurface<P: Point> {
    lu: KnotLine,
    lv: KnotLine,
    points: Vec<P>,
}

impl<P: Point> KnotEnvelopeSurface<P> {
    /// Taylor coefficients `out[i][j]` = (1/(i! j!)) ∂^{i+j}e/∂wⁱ∂zʲ.
    pub fn taylor<const N: usize, const M: usize>(&self, w: f64, z: f64) -> [[P; M]; N] {
        let iu = self.lu.span(w, 0.0, false);
        let iv = self.lv.span(z, 0.0, false);
        let mut wu = [Jet::<N>::constant(0.0); W];
        let mut wv = [Jet::<M>::constant(0.0); W];
        self.lu
            .weights(iu, Jet::variable(w), Jet::constant(0.0), &mut wu);
        self.lv
            .weights(iv, Jet::variable(z), Jet::constant(0.0), &mut wv);
        let (k, l) = (self.lu.order, self.lv.order);
        let nv = self.lv.count;
        let mut out = [[P::ZERO; M]; N];
        for a in 0..k {
            let r = iu + 1 + a - k;
            for b in 0..l {
                let d = self.points[r * nv + iv + 1 + b - l];
                for (i, o) in out.iter_mut().enumerate() {
                    for (j, x) in o.iter_mut().enumerate() {
                        *x += d * (wu[a].0[i] * wv[b].0[j]);
                    }
                }
            }
        }
        out
    }
    /// The orders `(k − 1 or k, l − 1 or l)` of the envelope.
    pub fn orders(&self) -> (usize, usize) {
        (self.lu.order, self.lv.order)
    }
}

impl<P: Point> Surface<P> for KnotEnvelopeSurface<P> {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        (self.lu.domain(), self.lv.domain())
    }
    fn eval_derivs(&self, w: f64, z: f64, derivs: bool, out: &mut [P; 3]) {
        let t = self.taylor::<2, 2>(w, z);
        out[0] = t[0][0];
        if derivs {
            out[1] = t[1][0];
            out[2] = t[0][1];
        }
    }
}
