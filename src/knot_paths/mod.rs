//! Juhász–Hoffmann (Juhász–Hoffmann, *On the family of B-spline surfaces obtained by knot modification*):
//! the one- and two-parameter families obtained by moving a knot, paths and path-surfaces, their limits
//! (Theorems 3–4) and envelopes (eqs. (6), (8)); the curve case of the same (the paper's ref. \[2\], \[6\]).
//!
//! Conventions follow the paper and `surfaces.md` §7 (binding):
//! * orders `k` (u) and `l` (v), degree = order − 1; full knot vectors `u_0..u_{n+k}`, `v_0..v_{m+l}`,
//!   control net `d_rs`, r = 0..n, s = 0..m. The knot index `p` is the 0-based index into the full
//!   vector (the paper's own index), and must be an **interior** knot, `k ≤ p ≤ n` (so that both
//!   neighbouring intervals lie in the domain `[u_{k−1}, u_{n+1}]` and the limit control points
//!   `d_p`, `d_{p−k}` exist).
//! * **Family** s(u, v; u_p): the knot `u_p` replaced by any finite value. The other knots must be
//!   non-decreasing (validated); the moved one is not. Evaluation is the de Boor recursion as pure algebra
//!   in the knots: the span of `u` is found on the knot vector *with `u_p` removed*; for
//!   `u ∈ [u_{p−1}, u_{p+1})` the piece of span `p` is used if `u ≥ u_p`, else the piece of span `p − 1`
//!   (so values of `u_p` outside `[u_{p−1}, u_{p+1}]` give the **extended** paths of §2 of the paper);
//!   elsewhere the ordinary span. Inside its neighbours this is the ordinary B-spline with the modified knot.
//!   A vanishing denominator of the recursion counts as 0/0 := 0 (Definition 1).
//! * `u_p = ±∞` is accepted by the core and evaluated exactly (the recursion weight with the infinite knot
//!   on its left is 1, on its right 0): the limits of Theorems 3–4. With the corrected list of
//!   `surfaces.md` §8.6: (u_p, v_q) → (−∞, −∞): d_{p,q}; (−∞, +∞): d_{p,q−l}; (+∞, −∞): d_{p−k,q};
//!   (+∞, +∞): d_{p−k,q−l}.
//! * **Envelope** (6): order `k − 1` B-splines on the knot vector `w` = `u` with `u_p` removed, control rows
//!   `p−k+1..p−1`, `w ∈ [u_{p−1}, u_{p+1}]` (that is the piece of `w`-span `p − 1`; outside it the same
//!   polynomial piece is continued). (8): the same in both directions. Contact relations (9), (10) and
//!   Theorems 5–8 hold with this choice (`surfaces.md` §7, §8.7).
//!
//! Derivatives are exact: the recursion is generic over a [`Scalar`], and [`Jet`] (truncated Taylor series)
//! gives derivatives in `u`, `v` or in the moved knot itself (∂s/∂u_p of Theorem 7).

mod curve;
mod jet;
mod knot_line;
mod surface;

pub use curve::{DeBoorStep, DeBoorTriangle, KnotEnvelopeCurve, KnotModifiedCurve};
pub use jet::{Jet, Scalar};
pub use knot_line::KnotLine;
pub use surface::{KnotEnvelopeSurface, KnotModifiedSurface, LimitRow, Var};

use crate::knots::MAX_DEGREE;

/// The largest order supported (degree ≤ [`MAX_DEGREE`]).
pub const MAX_ORDER: usize = MAX_DEGREE + 1;
/// The fixed width of the de Boor work arrays (= [`MAX_ORDER`]).
const W: usize = MAX_ORDER;

#[cfg(test)]
mod tests;
