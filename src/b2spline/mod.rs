//! Kuklišová: non-uniform B2-spline curves and surfaces that move continuously from
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
//! linear map (it does not depend on the points), [`B2Curve`] applies it to points of any [`Point`](crate::point::Point) type
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

mod curve;
mod data;
mod scheme;
mod surface;
mod tension;

pub use curve::B2Curve;
pub use data::{chord_knots, joint_weights, joint_weights_as_printed, reflect_ends, uniform_knots};
pub use scheme::B2Scheme;
pub use surface::{B2Surface, B2SurfaceOptions, SurfaceKnots};
pub use tension::{auto_tension, resolve_tension, DEFAULT_TENSION};

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
        Tension::Scalar(DEFAULT_TENSION)
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

/// Which weights of eq. (5) give the odd vertices C_{2i−1} from the joints.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Eq5 {
    /// The corrected last weight b²/((b+c)(b+c+d)) (de Boor's weights at the knot; the default).
    #[default]
    Corrected,
    /// The last weight as printed, b/(b+c)·c/(b+c+d): for showing the typo only.
    AsPrinted,
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
