//! Seed 000 (Kuklišová): non-uniform B2-spline curves and surfaces that move continuously from
//! interpolation (`a = 0`) to the cubic B-spline (`a = 1/6`), with tension.
//!
//! Conventions are those of `../shared/spec/curves.md` §2 (binding where the paper is inconsistent).
//!
//! * **Data** W_{−1}, W_0, …, W_{n+2} (n + 4 points, n ≥ 2), stored 0-based (`data[j + 1] = W_j`), and
//!   knots u_{−1}..u_{n+2} of the same length; Δ_j = u_{j+1} − u_j. Chord-length knots set
//!   Δ_j = |W_{j+1} − W_j| (auxiliary spans included) and u_1 = 0; uniform knots are u_j = j − 1.
//! * **Interpolating curve L** (a = 0): a cubic B-spline with control points C_0..C_{2n} on the Farin
//!   knots u′_{2i} = u_i (i = 0..n+1), u′_{2i+1} = (u_i + u_{i+1})/2 (i = 0..n); full knot vector
//!   `[u′_0] + u′ + [u′_{2n+2}]`, domain [u_1, u_n].
//!   * even vertices, eq. (8)/(9): C_{2i} = −p_i⁻W_{i−1} + (½+p_i⁻)W_i + (½+p_i⁺)W_{i+1} − p_i⁺W_{i+2},
//!     p_i⁻ = 6p_iΔ_i²/(Δ_i² + 5Δ_iΔ_{i−1} + c2·Δ_{i−1}²), p_i⁺ = 6p_iΔ_i²/(Δ_i² + 5Δ_iΔ_{i+1} + c2·Δ_{i+1}²)
//!     (c2 = 1 is the printed formula and the default; c2 = 2 is the paper's own derivation, §2.3);
//!   * odd vertices C_{2i−1} from the joints R_i = W_i by eq. (5) **with the corrected last weight**
//!     (findings §2.1): R_i = w₀C_{2i−2} + w₁C_{2i−1} + w₂C_{2i}, w₀ = c²/((b+c)(a+b+c)),
//!     w₂ = b²/((b+c)(b+c+d)), (a, b, c, d) = Δ′_{2i−2..2i+1} of the knots u′.
//! * **Modified knots** (`K`): u′_{2i} = (u_{i−1} + K·u_i + u_{i+1})/(K + 2); domain [u′_2, u′_{2n}].
//! * **B-spline L^B** with control W_0..W_{n+1} on the knots u_{−1}..u_{n+2}: its joints W^B_i = L^B(u_i)
//!   and its even B2 vertices C^B_{2i} by eq. (7).
//! * **Approximating curve L^a** (section 5): joints 6a·W^B_i + (1−6a)·W_i, even vertices
//!   6a·C^B_{2i} + (1−6a)·C_{2i}, odd vertices again by eq. (5) on the knots u′. Without `K` this is
//!   6a·L^B + (1−6a)·L pointwise.
//! * **Section 3 (uniform)**: u_j = j − 1, R_i = aW_{i−1} + (1−2a)W_i + aW_{i+1},
//!   C_{2i} = −pW_{i−1} + (½+p)(W_i + W_{i+1}) − pW_{i+2}.
//! * **Automatic tension** (§2.6): `Paper`: p_i = p·|cos α_i + cos α_{i+1}|/2 with the interior angle
//!   α_j = ∠W_{j−1}W_jW_{j+1}; `Turning` (not in the paper, 2D only): p_i = p·|sin θ_i + sin θ_{i+1}|/2
//!   with the signed turning angle θ_j.
//!
//! The construction is linear in the data once the knots and tensions are fixed: [`B2Scheme`] holds that
//! linear map (it does not depend on the points), [`B2Curve`] applies it to points of any [`Point`] type
//! (`f64` data give the B2 basis/blending functions), and [`B2Surface`] applies it in both directions of a
//! grid (tensor product, section 6).
//!
//! ```
//! use splinelab::b2spline::{B2Curve, B2Options};
//! use splinelab::Curve;
//! use glam::DVec2;
//! let w: Vec<DVec2> = [(0., 0.), (1., 1.), (2., 0.), (3., 1.), (4., 0.), (5., 1.)]
//!     .iter().map(|&(x, y)| DVec2::new(x, y)).collect();
//! let c = B2Curve::new(&w, &B2Options::default()).unwrap(); // a = 0: interpolates W_1..W_n
//! let (u1, _) = c.domain();
//! assert!((c.eval(u1) - w[2]).length() < 1e-12);
//! ```

use crate::bspline::{BSplineCurve, BSplineSurface};
use crate::error::{Error, Result};
use crate::point::Point;
use crate::sample::{Curve, Surface, MAX_INPUT_POINTS};

/// The tension: one scalar for all even vertices, or p_0..p_n (n + 1 values).
#[derive(Debug, Clone, PartialEq)]
pub enum Tension {
    /// One tension for every even vertex.
    Scalar(f64),
    /// One tension per even vertex, p_0..p_n.
    PerVertex(Vec<f64>),
}

impl Default for Tension {
    /// p = 1/6, which gives eq. (8).
    fn default() -> Self {
        Tension::Scalar(1.0 / 6.0)
    }
}

/// Automatic tension (findings §2.6). The value is the scale p (the paper suggests 0.2).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum AutoTension {
    /// Use [`B2Options::tension`].
    #[default]
    Off,
    /// The printed formula p_i = p·|cos α_i + cos α_{i+1}|/2 (α = interior angle).
    Paper(f64),
    /// Not in the paper: p_i = p·|sin θ_i + sin θ_{i+1}|/2 (θ = signed turning angle); 2D only.
    Turning(f64),
}

/// How the data knots u_{−1}..u_{n+2} are chosen.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum KnotChoice {
    /// Δ_j = |W_{j+1} − W_j|, u_1 = 0 (the default).
    #[default]
    Chord,
    /// u_j = j − 1.
    Uniform,
    /// The given u_{−1}..u_{n+2} (n + 4 strictly increasing values).
    Explicit(Vec<f64>),
}

/// Which formulas build the B2 vertices.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Construction {
    /// Sections 4–5: eq. (8)/(9), (5) with corrected weights, (7), the section-5 blend.
    #[default]
    NonUniform,
    /// Section 3: the uniform formulas with `a` and a scalar tension used directly (uniform knots only).
    Section3,
}

/// All options of a B2-spline curve. `B2Options::default()` is the interpolating curve (a = 0) with
/// chord-length knots, tension 1/6 (eq. (8)), c2 = 1, no modified knots.
#[derive(Debug, Clone, PartialEq)]
pub struct B2Options {
    /// The approximation parameter a (0 interpolates, 1/6 is the cubic B-spline).
    pub a: f64,
    /// Tension p (scalar) or p_0..p_n (n + 1 values). The paper's p_1..p_{n−1} (n − 1 values) are accepted
    /// too, with p_0 := p_1 and p_n := p_{n−1} (the recommendation of curves.md §2).
    pub tension: Tension,
    /// Automatic tension; when not `Off`, it replaces `tension`.
    pub auto_tension: AutoTension,
    /// The data knots.
    pub knots: KnotChoice,
    /// `Some(K)` for the modified knots u′_{2i} = (u_{i−1} + K u_i + u_{i+1})/(K + 2); K ≥ 0.
    pub k: Option<f64>,
    /// The last coefficient of the tension denominators (1 = eq. (8)/(9) as printed; 2 = derived).
    pub c2: f64,
    /// Non-uniform (default) or section 3.
    pub construction: Construction,
}

impl Default for B2Options {
    fn default() -> Self {
        B2Options {
            a: 0.0,
            tension: Tension::default(),
            auto_tension: AutoTension::Off,
            knots: KnotChoice::Chord,
            k: None,
            c2: 1.0,
            construction: Construction::NonUniform,
        }
    }
}

/// Weights of a cubic B-spline at a knot on its three non-zero control points, given the four knot spans
/// around it, (a, b, c, d) = Δ_{j−2}, Δ_{j−1}, Δ_j, Δ_{j+1} for the knot t_j. This is eq. (5) with the
/// corrected last weight (findings §2.1): `[c²/((b+c)(a+b+c)), middle, b²/((b+c)(b+c+d))]`.
pub fn joint_weights(a: f64, b: f64, c: f64, d: f64) -> [f64; 3] {
    let w0 = c * c / ((b + c) * (a + b + c));
    let w1 = c / (b + c) * (a + b) / (a + b + c) + b / (b + c) * (c + d) / (b + c + d);
    let w2 = b * b / ((b + c) * (b + c + d));
    [w0, w1, w2]
}

/// The weights of eq. (5) exactly as printed in the paper (last weight b/(b+c)·c/(b+c+d)). They do **not**
/// sum to 1 in general; kept only to document and test the typo.
pub fn joint_weights_as_printed(a: f64, b: f64, c: f64, d: f64) -> [f64; 3] {
    let mut w = joint_weights(a, b, c, d);
    w[2] = b / (b + c) * c / (b + c + d);
    w
}

/// Data knots u_{−1}..u_{n+2} from the chord lengths of `points` (u_1 = 0). Coincident neighbours are a
/// `Degenerate` error naming `points[j]`.
pub fn chord_knots<P: Point>(points: &[P]) -> Result<Vec<f64>> {
    let mut u = Vec::with_capacity(points.len());
    let mut acc = 0.0;
    u.push(0.0);
    for j in 1..points.len() {
        let d = points[j].distance(points[j - 1]);
        if !(d > 0.0) || !d.is_finite() {
            return Err(Error::degenerate(
                format!("points[{j}]"),
                format!(
                    "coincides with points[{}]: chord-length knots need distinct neighbours (use knots: \"uniform\" or explicit knots)",
                    j - 1
                ),
            ));
        }
        acc += d;
        u.push(acc);
    }
    // shift so that u_1 (index 2) = 0
    let shift = u.get(2).copied().unwrap_or(0.0);
    for x in u.iter_mut() {
        *x -= shift;
    }
    Ok(u)
}

/// Uniform data knots u_j = j − 1 for `count` = n + 4 points (j = −1..n+2).
pub fn uniform_knots(count: usize) -> Vec<f64> {
    (0..count).map(|k| k as f64 - 2.0).collect()
}

/// Automatic tension values p_0..p_n (findings §2.6) for the data W_{−1}..W_{n+2}.
pub fn auto_tension<P: Point>(points: &[P], mode: AutoTension) -> Result<Vec<f64>> {
    let m = points.len();
    let (scale, turning) = match mode {
        AutoTension::Off => {
            return Err(Error::invalid(
                "autoTension",
                "no automatic tension requested",
            ))
        }
        AutoTension::Paper(s) => (s, false),
        AutoTension::Turning(s) => (s, true),
    };
    if !scale.is_finite() {
        return Err(Error::not_finite(
            "autoTensionScale",
            format!("expected a finite number, got {scale}"),
        ));
    }
    if turning && P::DIM != 2 {
        return Err(Error::invalid(
            "autoTension",
            format!(
                "\"turning\" uses signed turning angles and needs 2D points, got {}D",
                P::DIM
            ),
        ));
    }
    if m < 6 {
        return Err(Error::too_few(
            "points",
            format!("need at least 6 points (n ≥ 2), got {m}"),
        ));
    }
    // per data vertex j = 0..n+1 (index k = j + 1 = 1..m−2): cos α_j or sin θ_j
    let mut f = vec![0.0; m];
    for k in 1..m - 1 {
        let e0 = points[k] - points[k - 1];
        let e1 = points[k + 1] - points[k];
        let (l0, l1) = (e0.length(), e1.length());
        if !(l0 > 0.0) {
            return Err(Error::degenerate(
                format!("points[{k}]"),
                format!(
                    "coincides with points[{}]: the angle needed by automatic tension is undefined",
                    k - 1
                ),
            ));
        }
        if !(l1 > 0.0) {
            return Err(Error::degenerate(
                format!("points[{}]", k + 1),
                format!("coincides with points[{k}]: the angle needed by automatic tension is undefined"),
            ));
        }
        f[k] = if turning {
            (e0.coord(0) * e1.coord(1) - e0.coord(1) * e1.coord(0)) / (l0 * l1)
        } else {
            // interior angle at W_j between W_{j−1} − W_j and W_{j+1} − W_j
            (-e0).dot(e1) / (l0 * l1)
        };
    }
    let n = m - 4;
    Ok((0..=n)
        .map(|i| scale * (f[i + 1] + f[i + 2]).abs() / 2.0)
        .collect())
}

/// Adds the auxiliary end points by point reflection, for data D_1..D_N (N ≥ 3): W_{1−k} = 2D_1 − D_{1+k}
/// and W_{N+k} = 2D_N − D_{N−k}, k = 1, 2. Returns W_{−1}..W_{N+2} (N + 4 points): the B2 curve then
/// interpolates/approximates all of D_1..D_N. (The paper leaves the auxiliary points to the user.)
pub fn reflect_ends<P: Point>(data: &[P]) -> Result<Vec<P>> {
    let m = data.len();
    if m < 3 {
        return Err(Error::too_few(
            "points",
            format!("need at least 3 data points to add reflected ends, got {m}"),
        ));
    }
    let (f, l) = (data[0], data[m - 1]);
    let mut w = Vec::with_capacity(m + 4);
    w.push(f * 2.0 - data[2]);
    w.push(f * 2.0 - data[1]);
    w.extend_from_slice(data);
    w.push(l * 2.0 - data[m - 2]);
    w.push(l * 2.0 - data[m - 3]);
    Ok(w)
}

/// The data-independent part of a B2-spline: data knots, tensions and options, as the linear map from
/// the data W_{−1}..W_{n+2} to the joints R_1..R_n and the cubic control points C_0..C_{2n} of L^a.
#[derive(Debug, Clone, PartialEq)]
pub struct B2Scheme {
    n: usize,
    a: f64,
    construction: Construction,
    data_knots: Vec<f64>,
    tension: Vec<f64>,
    /// Full cubic knot vector `[u′_0] + u′ + [u′_{2n+2}]` (2n + 5 knots; u′ possibly K-modified).
    knots: Vec<f64>,
    /// Weights of joint R_i (i = 1..n, stored at i − 1) on W_{i−1}, W_i, W_{i+1}.
    joint_w: Vec<[f64; 3]>,
    /// Weights of even vertex C_{2i} (i = 0..n) on W_{i−1}..W_{i+2}.
    even_w: Vec<[f64; 4]>,
    /// Eq. (5) weights at the joint knots u′_{2i} (i = 1..n, stored at i − 1) on C_{2i−2}, C_{2i−1}, C_{2i}.
    eq5_w: Vec<[f64; 3]>,
}

impl B2Scheme {
    /// Builds the scheme from the data knots u_{−1}..u_{n+2} (strictly increasing, n ≥ 2) and the tensions
    /// p_0..p_n. `k`, `c2` and `construction` as in [`B2Options`]; section 3 needs u_j = j − 1 and equal
    /// tensions.
    pub fn new(
        data_knots: Vec<f64>,
        tension: Vec<f64>,
        a: f64,
        k: Option<f64>,
        c2: f64,
        construction: Construction,
    ) -> Result<Self> {
        let m = data_knots.len();
        if m < 6 {
            return Err(Error::too_few(
                "knots",
                format!("need at least 6 knots u_-1..u_n+2 (n ≥ 2), got {m}"),
            ));
        }
        let n = m - 4;
        crate::error::check_finite("knots", &data_knots)?;
        crate::knots::check_increasing("knots", &data_knots)?;
        crate::error::check_finite_scalar("a", a)?;
        crate::error::check_finite_scalar("c2", c2)?;
        if c2 < 0.0 {
            return Err(Error::out_of_range(
                "c2",
                format!("expected a number ≥ 0 (1 = eq. (8)/(9), 2 = derived), got {c2}"),
            ));
        }
        if tension.len() != n + 1 {
            return Err(Error::size_mismatch(
                "tension",
                format!(
                    "expected one value per even vertex p_0..p_n ({} values for n = {n}), got {}",
                    n + 1,
                    tension.len()
                ),
            ));
        }
        crate::error::check_finite("tension", &tension)?;
        if let Some(kk) = k {
            crate::error::check_finite_scalar("K", kk)?;
            if kk < 0.0 {
                return Err(Error::out_of_range(
                    "K",
                    format!("expected a number ≥ 0 (e.g. 20), got {kk}"),
                ));
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
                        "\"section3\" is the uniform construction and requires knots: \"uniform\" (u_j = j − 1), but knots[{j}] = {}",
                        data_knots[j]
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
        let u = |j: isize| data_knots[(j + 1) as usize]; // u_j, j = −1..n+2
        let delta = |j: isize| u(j + 1) - u(j); // Δ_j, j = −1..n+1

        // Farin knots u′_0..u′_{2n+2}
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
                format!(
                    "the split knots u'_{} = {} and u'_{} = {} do not increase",
                    j,
                    up[j],
                    j + 1,
                    up[j + 1]
                ),
            ));
        }
        let mut knots = Vec::with_capacity(2 * n + 5);
        knots.push(up[0]);
        knots.extend_from_slice(&up);
        knots.push(up[2 * n + 2]);

        let sixa = 6.0 * a;
        let mut joint_w = Vec::with_capacity(n);
        let mut even_w = Vec::with_capacity(n + 1);
        match construction {
            Construction::Section3 => {
                let p = tension[0];
                for _ in 1..=n {
                    joint_w.push([a, 1.0 - 2.0 * a, a]);
                }
                for _ in 0..=n {
                    even_w.push([-p, 0.5 + p, 0.5 + p, -p]);
                }
            }
            Construction::NonUniform => {
                for i in 1..=n as isize {
                    // W^B_i = L^B(u_i): the cubic B-spline (control W_0..W_{n+1}, knots u) at its knot u_i
                    let wb = joint_weights(delta(i - 2), delta(i - 1), delta(i), delta(i + 1));
                    joint_w.push([sixa * wb[0], (1.0 - sixa) + sixa * wb[1], sixa * wb[2]]);
                }
                for (i, &p) in tension.iter().enumerate() {
                    let i = i as isize;
                    let (dm, d0, dp) = (delta(i - 1), delta(i), delta(i + 1));
                    let pm = 6.0 * p * d0 * d0 / (d0 * d0 + 5.0 * d0 * dm + c2 * dm * dm);
                    let pp = 6.0 * p * d0 * d0 / (d0 * d0 + 5.0 * d0 * dp + c2 * dp * dp);
                    // eq. (7): C^B_{2i} on W_i, W_{i+1}
                    let s = dm + d0 + dp;
                    let (b0, b1) = ((d0 / 2.0 + dp) / s, (dm + d0 / 2.0) / s);
                    let l = 1.0 - sixa;
                    even_w.push([
                        -l * pm,
                        l * (0.5 + pm) + sixa * b0,
                        l * (0.5 + pp) + sixa * b1,
                        -l * pp,
                    ]);
                }
            }
        }
        // eq. (5) on the knots u′ (corrected): the joint at u′_{2i} = knots[2i + 1]
        let t = &knots;
        let eq5_w = (1..=n)
            .map(|i| {
                let j = 2 * i + 1;
                joint_weights(
                    t[j - 1] - t[j - 2],
                    t[j] - t[j - 1],
                    t[j + 1] - t[j],
                    t[j + 2] - t[j + 1],
                )
            })
            .collect();
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

    /// The joints R_1..R_n and control points C_0..C_{2n} of L^a for the data W_{−1}..W_{n+2}
    /// (`data.len()` must be n + 4, else a `SizeMismatch` error on `points`).
    pub fn control_points<P: Point>(&self, data: &[P]) -> Result<(Vec<P>, Vec<P>)> {
        let n = self.n;
        if data.len() != n + 4 {
            return Err(Error::size_mismatch(
                "points",
                format!(
                    "expected {} points W_-1..W_n+2 (as many as knots), got {}",
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

/// Validates n + 4 data points (n ≥ 2, finite).
fn check_points<P: Point>(points: &[P]) -> Result<()> {
    if points.len() < 6 {
        return Err(Error::too_few(
            "points",
            format!(
                "need at least 6 points W_-1..W_n+2 (n ≥ 2), got {}",
                points.len()
            ),
        ));
    }
    if points.len() > MAX_INPUT_POINTS {
        return Err(Error::too_many(
            "points",
            format!("at most {MAX_INPUT_POINTS} points, got {}", points.len()),
        ));
    }
    if let Some(i) = points.iter().position(|p| !p.is_finite()) {
        return Err(Error::not_finite(
            format!("points[{i}]"),
            "expected finite coordinates",
        ));
    }
    Ok(())
}

/// Resolves the knot choice for `count` data (chord needs the points).
fn resolve_knots<P: Point>(choice: &KnotChoice, points: &[P]) -> Result<Vec<f64>> {
    match choice {
        KnotChoice::Chord => chord_knots(points),
        KnotChoice::Uniform => Ok(uniform_knots(points.len())),
        KnotChoice::Explicit(k) => {
            if k.len() != points.len() {
                return Err(Error::size_mismatch(
                    "knots",
                    format!(
                        "expected {} knots u_-1..u_n+2 (one per point), got {}",
                        points.len(),
                        k.len()
                    ),
                ));
            }
            crate::error::check_finite("knots", k)?;
            crate::knots::check_increasing("knots", k)?;
            Ok(k.clone())
        }
    }
}

/// Resolves the tension option to p_0..p_n.
fn resolve_tension(t: &Tension, n: usize) -> Result<Vec<f64>> {
    match t {
        Tension::Scalar(p) => {
            crate::error::check_finite_scalar("tension", *p)?;
            Ok(vec![*p; n + 1])
        }
        Tension::PerVertex(v) => {
            crate::error::check_finite("tension", v)?;
            if v.len() == n + 1 {
                Ok(v.clone())
            } else if v.len() == n - 1 {
                // the paper's p_1..p_{n−1}: p_0 := p_1 and p_n := p_{n−1} (curves.md §2, a recommendation)
                let mut p = Vec::with_capacity(n + 1);
                p.push(v[0]);
                p.extend_from_slice(v);
                p.push(v[n - 2]);
                Ok(p)
            } else {
                Err(Error::size_mismatch(
                    "tension",
                    format!(
                        "expected one value per even vertex p_0..p_n ({} values for n = {n}; or the paper's p_1..p_n-1, {} values), got {}",
                        n + 1,
                        n - 1,
                        v.len()
                    ),
                ))
            }
        }
    }
}

/// A B2-spline curve L^a through/near the data W_{−1}..W_{n+2}: a cubic B-spline whose control polygon is
/// built by the construction of the module docs. Works for any [`Point`] (`f64` gives blending functions).
///
/// # Template
/// * **What**: Kuklišová's non-uniform B2-spline L^a (seed 000): a cubic B-spline whose control polygon is
///   built from the data by eqs. (8)–(9) (even vertices, with tension p_i) and (5) (odd vertices), blending
///   from interpolation (a = 0) to the cubic B-spline of the data (a = 1/6).
/// * **Interpolates**: at a = 0 the data W_1..W_n at their knots u_1..u_n (W_{−1}, W_0, W_{n+1}, W_{n+2}
///   are auxiliary); for a ≠ 0 it approximates them.
/// * **Continuity**: C² (a cubic B-spline on simple knots); C¹ with the modified knots of §5.
/// * **Parametrisation**: the data knots (chord length by default, u_1 = 0), domain [u_1, u_n].
///
/// # Example
/// ```
/// use glam::DVec2;
/// use splinelab::{b2spline::{B2Curve, B2Options}, Curve};
/// let w: Vec<DVec2> = (0..7).map(|i| DVec2::new(i as f64, (i as f64 * 1.3).sin())).collect();
/// let c = B2Curve::new(&w, &B2Options::default())?; // a = 0: interpolating
/// let (u, n) = (c.data_knots(), c.n());
/// for i in 1..=n {
///     assert!((c.eval(u[i + 1]) - w[i + 1]).length() < 1e-12); // L(u_i) = W_i
/// }
/// assert_eq!(c.domain(), (u[2], u[n + 1]));
/// # Ok::<(), splinelab::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct B2Curve<P: Point> {
    scheme: B2Scheme,
    data: Vec<P>,
    joints: Vec<P>,
    curve: BSplineCurve<P>,
}

impl<P: Point> B2Curve<P> {
    /// Builds L^a for the data `points` = W_{−1}..W_{n+2} (n ≥ 2). Errors name the field: `points`,
    /// `points[i]`, `knots`, `knots[i]`, `tension`, `autoTension`, `K`, `c2`, `a`, `construction`.
    pub fn new(points: &[P], opts: &B2Options) -> Result<Self> {
        check_points(points)?;
        let n = points.len() - 4;
        crate::error::check_finite_scalar("a", opts.a)?;
        if opts.construction == Construction::Section3 {
            match &opts.knots {
                KnotChoice::Uniform | KnotChoice::Explicit(_) => {}
                KnotChoice::Chord => {
                    return Err(Error::invalid(
                        "construction",
                        "\"section3\" is the uniform construction and requires knots: \"uniform\", got knots: \"chord\"",
                    ))
                }
            }
            if matches!(opts.tension, Tension::PerVertex(_)) {
                return Err(Error::invalid(
                    "tension",
                    "\"section3\" uses one scalar tension p, not an array",
                ));
            }
            if opts.auto_tension != AutoTension::Off {
                return Err(Error::invalid(
                    "autoTension",
                    "\"section3\" uses one scalar tension p; automatic tension is not available",
                ));
            }
        }
        let data_knots = resolve_knots(&opts.knots, points)?;
        let tension = match opts.auto_tension {
            AutoTension::Off => resolve_tension(&opts.tension, n)?,
            mode => auto_tension(points, mode)?,
        };
        let scheme = B2Scheme::new(
            data_knots,
            tension,
            opts.a,
            opts.k,
            opts.c2,
            opts.construction,
        )?;
        Self::from_scheme(scheme, points)
    }

    /// Applies a prepared scheme to data (n + 4 points, as many as the scheme's knots).
    pub fn from_scheme(scheme: B2Scheme, points: &[P]) -> Result<Self> {
        check_points(points)?;
        let (joints, ctrl) = scheme.control_points(points)?;
        let curve = BSplineCurve::new(3, scheme.knots.clone(), ctrl)?;
        Ok(B2Curve {
            scheme,
            data: points.to_vec(),
            joints,
            curve,
        })
    }

    /// The data-independent part (knots, tensions, weights).
    pub fn scheme(&self) -> &B2Scheme {
        &self.scheme
    }
    /// The data W_{−1}..W_{n+2}.
    pub fn data(&self) -> &[P] {
        &self.data
    }
    /// n.
    pub fn n(&self) -> usize {
        self.scheme.n
    }
    /// The joints R_1..R_n of L^a (= W_1..W_n at a = 0), at the parameters [`B2Scheme::joint_params`].
    pub fn joints(&self) -> &[P] {
        &self.joints
    }
    /// All cubic control points C_0..C_{2n}.
    pub fn control_points(&self) -> &[P] {
        self.curve.points()
    }
    /// The even vertices C_0, C_2, …, C_{2n}.
    pub fn even_vertices(&self) -> Vec<P> {
        self.curve.points().iter().step_by(2).copied().collect()
    }
    /// The full cubic knot vector (2n + 5 knots).
    pub fn knots(&self) -> &[f64] {
        self.curve.knots()
    }
    /// The data knots u_{−1}..u_{n+2}.
    pub fn data_knots(&self) -> &[f64] {
        &self.scheme.data_knots
    }
    /// The tensions p_0..p_n used.
    pub fn tension(&self) -> &[f64] {
        &self.scheme.tension
    }
    /// The cubic B-spline this curve is.
    pub fn bspline(&self) -> &BSplineCurve<P> {
        &self.curve
    }
}

impl<P: Point> Curve<P> for B2Curve<P> {
    fn domain(&self) -> (f64, f64) {
        self.scheme.domain()
    }
    /// Cubic B-spline evaluation (right-hand piece at knots, last piece at the end; extrapolates outside).
    fn eval_derivs(&self, u: f64, order: usize, out: &mut [P; 3]) {
        self.curve.eval_derivs(u, order, out)
    }
    /// The cubic B-spline's per-span sampler.
    fn piecewise(&self) -> Option<crate::kernel::PiecewisePoly<P>> {
        self.curve.to_piecewise()
    }
}

/// The knot choice of one direction of a [`B2Surface`].
#[derive(Debug, Clone, PartialEq, Default)]
pub enum SurfaceKnots {
    /// Δ_i = the mean over the other index of |W_{i+1,j} − W_{ij}| (u_1 = 0) — the paper gives no rule.
    Chord,
    /// u_j = j − 1 (the default for surfaces: the paper suggests no knots for surfaces, and uniform ones
    /// are the only choice that does not depend on a convention).
    #[default]
    Uniform,
    /// The given knots (m + 4 values).
    Explicit(Vec<f64>),
}

/// Options of a [`B2Surface`] (section 6). Tensions are numbers or arrays (no automatic tension).
#[derive(Debug, Clone, PartialEq)]
pub struct B2SurfaceOptions {
    /// The approximation parameter a of the family L^a (0 interpolates).
    pub a: f64,
    /// Tension along u.
    pub tension_u: Tension,
    /// Tension along v.
    pub tension_v: Tension,
    /// Knots along u.
    pub knots_u: SurfaceKnots,
    /// Knots along v.
    pub knots_v: SurfaceKnots,
    /// The modified-knot factor c₂ of section 5 (applied in both directions).
    pub c2: f64,
}

impl Default for B2SurfaceOptions {
    fn default() -> Self {
        B2SurfaceOptions {
            a: 0.0,
            tension_u: Tension::default(),
            tension_v: Tension::default(),
            knots_u: SurfaceKnots::Uniform,
            knots_v: SurfaceKnots::Uniform,
            c2: 1.0,
        }
    }
}

/// The tensor-product B2-spline surface S(u, v) = Σ_i Σ_j W_ij L_i(u) L_j(v) (section 6), for the grid
/// W_ij, i = −1..m+2, j = −1..n+2 (stored `grid[(i + 1) * cols + (j + 1)]`). It is the tensor cubic
/// B-spline whose control net is the B2 construction applied along u, then along v.
#[derive(Debug, Clone)]
pub struct B2Surface<P: Point> {
    scheme_u: B2Scheme,
    scheme_v: B2Scheme,
    surface: BSplineSurface<P>,
}

impl<P: Point> B2Surface<P> {
    /// Builds the surface from a `rows × cols` grid (row-major, rows along u). Needs rows, cols ≥ 6.
    pub fn new(rows: usize, cols: usize, grid: &[P], opts: &B2SurfaceOptions) -> Result<Self> {
        if rows < 6 {
            return Err(Error::too_few(
                "grid",
                format!("need at least 6 rows W_-1..W_m+2 (m ≥ 2), got {rows}"),
            ));
        }
        if cols < 6 {
            return Err(Error::too_few(
                "grid[0]",
                format!("need at least 6 points per row (n ≥ 2), got {cols}"),
            ));
        }
        if grid.len() != rows * cols {
            return Err(Error::size_mismatch(
                "grid",
                format!("expected {rows} × {cols} points, got {}", grid.len()),
            ));
        }
        if let Some(k) = grid.iter().position(|p| !p.is_finite()) {
            return Err(Error::not_finite(
                format!("grid[{}][{}]", k / cols, k % cols),
                "expected finite coordinates",
            ));
        }
        crate::error::check_finite_scalar("a", opts.a)?;
        let ku = Self::dir_knots("knotsU", &opts.knots_u, rows, |i| {
            (0..cols).map(|j| grid[i * cols + j]).collect()
        })?;
        let kv = Self::dir_knots("knotsV", &opts.knots_v, cols, |j| {
            (0..rows).map(|i| grid[i * cols + j]).collect()
        })?;
        let tu = resolve_tension(&opts.tension_u, rows - 4)
            .map_err(|e| relabel(e, "tension", "tensionU"))?;
        let tv = resolve_tension(&opts.tension_v, cols - 4)
            .map_err(|e| relabel(e, "tension", "tensionV"))?;
        let su = B2Scheme::new(ku, tu, opts.a, None, opts.c2, Construction::NonUniform)
            .map_err(|e| relabel(relabel(e, "knots", "knotsU"), "tension", "tensionU"))?;
        let sv = B2Scheme::new(kv, tv, opts.a, None, opts.c2, Construction::NonUniform)
            .map_err(|e| relabel(relabel(e, "knots", "knotsV"), "tension", "tensionV"))?;
        let (nu, nv) = (2 * (rows - 4) + 1, 2 * (cols - 4) + 1);
        // along u for every column j
        let mut cols_u: Vec<Vec<P>> = Vec::with_capacity(cols);
        for j in 0..cols {
            let col: Vec<P> = (0..rows).map(|i| grid[i * cols + j]).collect();
            cols_u.push(su.control_points(&col)?.1);
        }
        let mut net = Vec::with_capacity(nu * nv);
        for k in 0..nu {
            let row: Vec<P> = cols_u.iter().map(|c| c[k]).collect();
            net.extend(sv.control_points(&row)?.1);
        }
        let surface = BSplineSurface::new(3, 3, su.knots.clone(), sv.knots.clone(), nu, nv, net)?;
        Ok(B2Surface {
            scheme_u: su,
            scheme_v: sv,
            surface,
        })
    }

    fn dir_knots(
        field: &'static str,
        choice: &SurfaceKnots,
        count: usize,
        line: impl Fn(usize) -> Vec<P>,
    ) -> Result<Vec<f64>> {
        match choice {
            SurfaceKnots::Uniform => Ok(uniform_knots(count)),
            SurfaceKnots::Explicit(k) => {
                if k.len() != count {
                    return Err(Error::size_mismatch(
                        field,
                        format!(
                            "expected {count} knots (one per grid line), got {}",
                            k.len()
                        ),
                    ));
                }
                crate::error::check_finite(field, k)?;
                crate::knots::check_increasing(field, k)?;
                Ok(k.clone())
            }
            SurfaceKnots::Chord => {
                let mut u = vec![0.0; count];
                let mut prev = line(0);
                for i in 1..count {
                    let cur = line(i);
                    let d = prev
                        .iter()
                        .zip(&cur)
                        .map(|(a, b)| a.distance(*b))
                        .sum::<f64>()
                        / cur.len().max(1) as f64;
                    if !(d > 0.0) {
                        return Err(Error::degenerate(
                            field,
                            format!("grid lines {} and {i} coincide: chord-length knots need distinct lines (use \"uniform\")", i - 1),
                        ));
                    }
                    u[i] = u[i - 1] + d;
                    prev = cur;
                }
                let s = u[2];
                Ok(u.into_iter().map(|x| x - s).collect())
            }
        }
    }

    /// The B2 scheme along u.
    pub fn scheme_u(&self) -> &B2Scheme {
        &self.scheme_u
    }
    /// The B2 scheme along v.
    pub fn scheme_v(&self) -> &B2Scheme {
        &self.scheme_v
    }
    /// The tensor cubic B-spline this surface is.
    pub fn bspline(&self) -> &BSplineSurface<P> {
        &self.surface
    }
}

fn relabel(e: Error, from: &str, to: &'static str) -> Error {
    if e.field() == from {
        e.in_field(to)
    } else if let Some(rest) = e.field().strip_prefix(from).filter(|r| r.starts_with('[')) {
        let f = format!("{to}{rest}");
        e.in_field(f)
    } else {
        e
    }
}

impl<P: Point> Surface<P> for B2Surface<P> {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        (self.scheme_u.domain(), self.scheme_v.domain())
    }
    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [P; 3]) {
        self.surface.eval_derivs(u, v, derivs, out)
    }
    /// The tensor cubic B-spline's grid sampler.
    fn sample_grid_into(
        &self,
        us: &[f64],
        vs: &[f64],
        derivs: bool,
        points: &mut [f64],
        du: &mut [f64],
        dv: &mut [f64],
    ) {
        self.surface
            .sample_grid_into(us, vs, derivs, points, du, dv)
    }
}
