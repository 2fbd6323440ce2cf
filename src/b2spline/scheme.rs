//! [`B2Scheme`]: the data-independent linear map of a B2-spline, built one equation of the paper at a time.

use super::{joint_weights, Construction};
use crate::error::{Error, Result};
use crate::point::Point;

/// The data-independent part of a B2-spline: data knots, tensions and options, as the linear map from
/// the data W_{−1}..W_{n+2} to the joints R_1..R_n and the cubic control points C_0..C_{2n} of L^a.
#[derive(Debug, Clone, PartialEq)]
pub struct B2Scheme {
    pub(super) n: usize,
    pub(super) a: f64,
    pub(super) construction: Construction,
    pub(super) data_knots: Vec<f64>,
    pub(super) tension: Vec<f64>,
    /// Full cubic knot vector `[u′_0] + u′ + [u′_{2n+2}]` (2n + 5 knots; u′ possibly K-modified).
    pub(super) knots: Vec<f64>,
    /// Weights of joint R_i (i = 1..n, stored at i − 1) on W_{i−1}, W_i, W_{i+1}.
    joint_w: Vec<[f64; 3]>,
    /// Weights of even vertex C_{2i} (i = 0..n) on W_{i−1}..W_{i+2}.
    even_w: Vec<[f64; 4]>,
    /// Eq. (5) weights at the joint knots u′_{2i} (i = 1..n, stored at i − 1) on C_{2i−2}, C_{2i−1}, C_{2i}.
    eq5_w: Vec<[f64; 3]>,
}

impl B2Scheme {
    /// Builds the scheme from the data knots u_{−1}..u_{n+2} (strictly increasing, n ≥ 2) and the tensions
    /// p_0..p_n. `k`, `c2` and `construction` as in [`B2Options`](super::B2Options); section 3 needs
    /// u_j = j − 1 and equal tensions.
    ///
    /// One step per equation: `split_knots` (Farin knots, §5 modified knots), then the joint weights
    /// (`approx_joint_weights`, section 5 with eq. (5)) and the even-vertex weights (`even_vertex_weights`,
    /// eqs. (7)–(9)) — or both from section 3 (`section3_weights`) — and finally `odd_vertex_weights`
    /// (eq. (5) on the split knots).
    pub fn new(
        data_knots: Vec<f64>,
        tension: Vec<f64>,
        a: f64,
        k: Option<f64>,
        c2: f64,
        construction: Construction,
    ) -> Result<Self> {
        let n = check_scheme_inputs(&data_knots, &tension, a, k, c2, construction)?;
        let knots = split_knots(&data_knots, k)?;
        let (joint_w, even_w) = match construction {
            Construction::Section3 => section3_weights(n, a, tension[0]),
            Construction::NonUniform => (
                approx_joint_weights(&data_knots, a),
                even_vertex_weights(&data_knots, &tension, a, c2),
            ),
        };
        let eq5_w = odd_vertex_weights(&knots, n);
        Ok(B2Scheme {
            n,
            a,
            construction,
            data_knots,
            tension,
            knots,
            joint_w,
            even_w,
            eq5_w,
        })
    }

    /// n (the curve interpolates/approximates W_1..W_n; n − 1 segments).
    pub fn n(&self) -> usize {
        self.n
    }
    /// The approximation parameter a.
    pub fn a(&self) -> f64 {
        self.a
    }
    /// Which construction of the paper the curve follows (general non-uniform, or section 3).
    pub fn construction(&self) -> Construction {
        self.construction
    }
    /// The data knots u_{−1}..u_{n+2}.
    pub fn data_knots(&self) -> &[f64] {
        &self.data_knots
    }
    /// The tensions p_0..p_n used.
    pub fn tension(&self) -> &[f64] {
        &self.tension
    }
    /// The full cubic knot vector `[u′_0] + u′ + [u′_{2n+2}]` (2n + 5 knots).
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }
    /// The domain [u′_2, u′_{2n}] (= [u_1, u_n] without K).
    pub fn domain(&self) -> (f64, f64) {
        (self.knots[3], self.knots[2 * self.n + 1])
    }
    /// The parameters of the joints, u′_{2i} for i = 1..n.
    pub fn joint_params(&self) -> Vec<f64> {
        (1..=self.n).map(|i| self.knots[2 * i + 1]).collect()
    }
    /// Eq. (5) weights (corrected) used at the joint u′_{2i}, i = 1..n.
    pub fn eq5_weights(&self, i: usize) -> Option<[f64; 3]> {
        self.eq5_w.get(i.wrapping_sub(1)).copied()
    }

    /// The weights of every joint R_i (i = 1..n, stored at i − 1) on W_{i−1}, W_i, W_{i+1}.
    pub fn joint_weights_all(&self) -> &[[f64; 3]] {
        &self.joint_w
    }
    /// The weights of every even vertex C_{2i} (i = 0..n) on W_{i−1}, W_i, W_{i+1}, W_{i+2} (eq. (8)/(9)
    /// blended by section 5; the first and last are −p_i⁻ and −p_i⁺ at a = 0).
    pub fn even_weights(&self) -> &[[f64; 4]] {
        &self.even_w
    }
    /// The eq. (5) weights used at every joint u′_{2i} (i = 1..n, stored at i − 1) on C_{2i−2}, C_{2i−1},
    /// C_{2i}: the corrected ones, or the printed ones after [`B2Scheme::with_eq5_as_printed`].
    pub fn eq5_weights_all(&self) -> &[[f64; 3]] {
        &self.eq5_w
    }

    /// The same scheme with eq. (5) exactly as printed (last weight b/(b+c)·c/(b+c+d), see
    /// [`joint_weights_as_printed`](super::joint_weights_as_printed)) for the odd vertices. For showing the
    /// typo only: the weights do not sum to 1 on non-uniform knots, so the curve misses its joints and is
    /// not affine invariant.
    pub fn with_eq5_as_printed(mut self) -> Self {
        self.eq5_w = odd_vertex_weights_with(&self.knots, self.n, super::joint_weights_as_printed);
        self
    }

    /// The joints R_1..R_n and control points C_0..C_{2n} of L^a for the data W_{−1}..W_{n+2}
    /// (`data.len()` must be n + 4, else a `SizeMismatch` error on `points`).
    pub fn control_points<P: Point>(&self, data: &[P]) -> Result<(Vec<P>, Vec<P>)> {
        let n = self.n;
        if data.len() != n + 4 {
            return Err(Error::size_mismatch(
                "points",
                format!(
                    "expected {} points W₋₁..Wₙ₊₂ (as many as knots), got {}",
                    n + 4,
                    data.len()
                ),
            ));
        }
        let mut joints = Vec::with_capacity(n);
        for (i, w) in self.joint_w.iter().enumerate() {
            // R_{i+1} on W_i, W_{i+1}, W_{i+2} → data[i + 1..=i + 3]
            joints.push(data[i + 1] * w[0] + data[i + 2] * w[1] + data[i + 3] * w[2]);
        }
        let mut ctrl = vec![P::ZERO; 2 * n + 1];
        for (i, w) in self.even_w.iter().enumerate() {
            // C_{2i} on W_{i−1}..W_{i+2} → data[i..=i + 3]
            ctrl[2 * i] =
                data[i] * w[0] + data[i + 1] * w[1] + data[i + 2] * w[2] + data[i + 3] * w[3];
        }
        for (i, w) in self.eq5_w.iter().enumerate() {
            let i = i + 1;
            ctrl[2 * i - 1] =
                (joints[i - 1] - ctrl[2 * i - 2] * w[0] - ctrl[2 * i] * w[2]) * (1.0 / w[1]);
        }
        Ok((joints, ctrl))
    }

    /// The n + 4 basis (blending) functions L_{−1}..L_{n+2} and their derivatives up to `order` (≤ 2) at
    /// `u`: `out[k][j + 1]` = L_j^{(k)}(u). Allocates; for plots and tests, not for hot loops (there, compute
    /// [`B2Scheme::control_matrix`] once and use [`B2Scheme::basis_with`]).
    pub fn basis(&self, u: f64, order: usize, out: &mut [Vec<f64>; 3]) {
        let cmat = self.control_matrix();
        self.basis_with(&cmat, u, order, out);
    }

    /// Like [`B2Scheme::basis`], with the control matrix computed beforehand.
    pub fn basis_with(&self, cmat: &[f64], u: f64, order: usize, out: &mut [Vec<f64>; 3]) {
        let m = self.n + 4;
        let nc = 2 * self.n + 1;
        let order = order.min(2);
        let span = crate::knots::find_span(&self.knots, 3, nc, u);
        let mut ders = [[0.0; crate::knots::MAX_DEGREE + 1]; 3];
        crate::bspline::basis_derivs(&self.knots, 3, span, u, order, &mut ders);
        for (k, o) in out.iter_mut().enumerate() {
            o.clear();
            o.resize(m, 0.0);
            if k <= order {
                for r in 0..4 {
                    let c = span - 3 + r;
                    let nk = ders[k][r];
                    if nk != 0.0 {
                        for (j, o) in o.iter_mut().enumerate() {
                            *o += nk * cmat[c * m + j];
                        }
                    }
                }
            }
        }
    }

    /// The (2n + 1) × (n + 4) matrix (row-major) of the control points C_k on the data W_j.
    pub fn control_matrix(&self) -> Vec<f64> {
        let m = self.n + 4;
        let mut mat = vec![0.0; (2 * self.n + 1) * m];
        let mut e = vec![0.0; m];
        for j in 0..m {
            e[j] = 1.0;
            if let Ok((_, c)) = self.control_points(&e) {
                for (k, ck) in c.iter().enumerate() {
                    mat[k * m + j] = *ck;
                }
            }
            e[j] = 0.0;
        }
        mat
    }
}

/// Checks the inputs of [`B2Scheme::new`] and returns n (= number of knots − 4).
fn check_scheme_inputs(
    data_knots: &[f64],
    tension: &[f64],
    a: f64,
    k: Option<f64>,
    c2: f64,
    construction: Construction,
) -> Result<usize> {
    let m = data_knots.len();
    if m < 6 {
        return Err(Error::too_few(
            "knots",
            format!("need at least 6 knots u₋₁..uₙ₊₂ (n ≥ 2), got {m}"),
        ));
    }
    let n = m - 4;
    crate::error::check_finite("knots", data_knots)?;
    crate::knots::check_increasing("knots", data_knots)?;
    crate::error::check_finite_scalar("a", a)?;
    crate::error::check_finite_scalar("c2", c2)?;
    if c2 < 0.0 {
        return Err(Error::out_of_range(
            "c2",
            "expected a number ≥ 0 (1 = eq. (8)/(9), 2 = derived)",
        ));
    }
    if tension.len() != n + 1 {
        return Err(Error::size_mismatch(
            "tension",
            format!(
                "expected one value per even vertex p₀..pₙ ({} values for n = {n}), got {}",
                n + 1,
                tension.len()
            ),
        ));
    }
    crate::error::check_finite("tension", tension)?;
    if let Some(kk) = k {
        crate::error::check_finite_scalar("K", kk)?;
        if kk < 0.0 {
            return Err(Error::out_of_range("K", "expected a number ≥ 0 (e.g. 20)"));
        }
    }
    if construction == Construction::Section3 {
        if let Some(j) = data_knots
            .iter()
            .enumerate()
            .position(|(j, &u)| (u - (j as f64 - 2.0)).abs() > 1e-12)
        {
            return Err(Error::invalid(
                "construction",
                format!(
                    "\"section3\" is the uniform construction and requires knots: \"uniform\" (uⱼ = j − 1), but knots[{j}] ≠ {j} − 1"
                ),
            ));
        }
        if tension.iter().any(|&p| p != tension[0]) {
            return Err(Error::invalid(
                "tension",
                "\"section3\" uses one scalar tension p, got different values",
            ));
        }
    }
    Ok(n)
}

/// The data knot u_j (j = −1..n+2) of the 0-based `data_knots`.
fn u_at(data_knots: &[f64], j: isize) -> f64 {
    data_knots[(j + 1) as usize]
}

/// The span Δ_j = u_{j+1} − u_j (j = −1..n+1).
fn delta_at(data_knots: &[f64], j: isize) -> f64 {
    u_at(data_knots, j + 1) - u_at(data_knots, j)
}

/// The split (Farin) knots u′_{2i} = u_i, u′_{2i+1} = (u_i + u_{i+1})/2 — with `Some(K)` the modified knots
/// of section 5, u′_{2i} = (u_{i−1} + K·u_i + u_{i+1})/(K + 2) — as the full cubic knot vector
/// `[u′_0] + u′ + [u′_{2n+2}]` (2n + 5 knots). Knots that do not increase are an error.
fn split_knots(data_knots: &[f64], k: Option<f64>) -> Result<Vec<f64>> {
    let n = data_knots.len() - 4;
    let u = |j: isize| u_at(data_knots, j);
    let mut up = Vec::with_capacity(2 * n + 3);
    for i in 0..=(n as isize + 1) {
        let even = match k {
            Some(kk) => (u(i - 1) + kk * u(i) + u(i + 1)) / (kk + 2.0),
            None => u(i),
        };
        up.push(even);
        if i <= n as isize {
            up.push((u(i) + u(i + 1)) / 2.0);
        }
    }
    if let Some(j) = up.windows(2).position(|w| !(w[1] > w[0])) {
        return Err(Error::not_increasing(
            if k.is_some() { "K" } else { "knots" },
            format!("the split knots u'_{} and u'_{} do not increase", j, j + 1),
        ));
    }
    let mut knots = Vec::with_capacity(2 * n + 5);
    knots.push(up[0]);
    knots.extend_from_slice(&up);
    knots.push(up[2 * n + 2]);
    Ok(knots)
}

/// Section 3 (uniform knots): the joints R_i = aW_{i−1} + (1−2a)W_i + aW_{i+1} and the even vertices
/// C_{2i} = −pW_{i−1} + (½+p)(W_i + W_{i+1}) − pW_{i+2}, as (joint weights, even-vertex weights).
fn section3_weights(n: usize, a: f64, p: f64) -> (Vec<[f64; 3]>, Vec<[f64; 4]>) {
    (
        vec![[a, 1.0 - 2.0 * a, a]; n],
        vec![[-p, 0.5 + p, 0.5 + p, -p]; n + 1],
    )
}

/// Section 5: the joints of L^a, R_i = 6a·W^B_i + (1−6a)·W_i, where W^B_i = L^B(u_i) is the cubic B-spline
/// of the data at its knot u_i, by eq. (5) (corrected weights). Weights on W_{i−1}, W_i, W_{i+1}, i = 1..n.
fn approx_joint_weights(data_knots: &[f64], a: f64) -> Vec<[f64; 3]> {
    let n = data_knots.len() - 4;
    let delta = |j: isize| delta_at(data_knots, j);
    let sixa = 6.0 * a;
    (1..=n as isize)
        .map(|i| {
            let wb = joint_weights(delta(i - 2), delta(i - 1), delta(i), delta(i + 1));
            [sixa * wb[0], (1.0 - sixa) + sixa * wb[1], sixa * wb[2]]
        })
        .collect()
}

/// The even vertices of L^a, 6a·C^B_{2i} + (1−6a)·C_{2i} (section 5), with C_{2i} by eq. (8)/(9):
/// C_{2i} = −p_i⁻W_{i−1} + (½+p_i⁻)W_i + (½+p_i⁺)W_{i+1} − p_i⁺W_{i+2},
/// p_i^∓ = 6p_iΔ_i²/(Δ_i² + 5Δ_iΔ_{i∓1} + c2·Δ_{i∓1}²), and C^B_{2i} on W_i, W_{i+1} by eq. (7).
/// Weights on W_{i−1}..W_{i+2}, i = 0..n.
fn even_vertex_weights(data_knots: &[f64], tension: &[f64], a: f64, c2: f64) -> Vec<[f64; 4]> {
    let delta = |j: isize| delta_at(data_knots, j);
    let sixa = 6.0 * a;
    tension
        .iter()
        .enumerate()
        .map(|(i, &p)| {
            let i = i as isize;
            let (dm, d0, dp) = (delta(i - 1), delta(i), delta(i + 1));
            let pm = 6.0 * p * d0 * d0 / (d0 * d0 + 5.0 * d0 * dm + c2 * dm * dm);
            let pp = 6.0 * p * d0 * d0 / (d0 * d0 + 5.0 * d0 * dp + c2 * dp * dp);
            // eq. (7): C^B_{2i} on W_i, W_{i+1}
            let s = dm + d0 + dp;
            let (b0, b1) = ((d0 / 2.0 + dp) / s, (dm + d0 / 2.0) / s);
            let l = 1.0 - sixa;
            [
                -l * pm,
                l * (0.5 + pm) + sixa * b0,
                l * (0.5 + pp) + sixa * b1,
                -l * pp,
            ]
        })
        .collect()
}

/// Eq. (5) (corrected) on the split knots: the weights of the joint at u′_{2i} (= `knots[2i + 1]`) on
/// C_{2i−2}, C_{2i−1}, C_{2i}, i = 1..n; they give the odd vertices C_{2i−1} from the joints.
fn odd_vertex_weights(knots: &[f64], n: usize) -> Vec<[f64; 3]> {
    odd_vertex_weights_with(knots, n, joint_weights)
}

/// [`odd_vertex_weights`] with the given eq. (5) weight formula (corrected or as printed).
fn odd_vertex_weights_with(
    knots: &[f64],
    n: usize,
    weights: fn(f64, f64, f64, f64) -> [f64; 3],
) -> Vec<[f64; 3]> {
    let t = knots;
    (1..=n)
        .map(|i| {
            let j = 2 * i + 1;
            weights(
                t[j - 1] - t[j - 2],
                t[j] - t[j - 1],
                t[j + 1] - t[j],
                t[j + 2] - t[j + 1],
            )
        })
        .collect()
}
