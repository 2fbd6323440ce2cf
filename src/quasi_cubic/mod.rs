//! The quasi-cubic paper: quasi-cubic trigonometric B-splines with a shape parameter α, their exact conics and
//! transcendental curves, the blended interpolation spline (BIS) with local parameters β*, and
//! tensor-product / blended surfaces.
//!
//! The seed's text lost its basis functions (Eq. (1)); the reconstructed basis of `curves.md` §1 is used,
//! with every property of findings §1.1–1.2 (including the corrections: positivity exactly for
//! α ∈ [−3, 1], C³ only at α = 1, the exact curvature-matching β* replacing the garbled Eq. (36)).
//!
//! | module | what |
//! | --- | --- |
//! | [`basis`](mod@basis) | the α-basis B(α; t) and its t-derivatives (any order), the allocated function s of order k |
//! | [`curve`] | open and closed (periodic) quasi-cubic curves ([`QuasiCubicCurve`]); at explicit parameters in runs of one Taylor expansion each (`explicit`) |
//! | [`bis`] | the α = 3 interpolation spline and the BIS ([`Bis`]), curvature-matching β* |
//! | [`surface`] | tensor-product surfaces ([`QuasiCubicSurface`], periodic per direction) and blended interpolation surfaces ([`BisSurface`]) |
//! | `segment` | one segment in closed form: its derivatives at t₀ (for the samplers and the runs) |
//! | [`trig`] | sin θ, cos θ (θ = πt/2, t ∈ [0, 1]) by polynomials, for the segment samplers |
//! | [`presets`] | control data of the exact shapes (ellipse, circle, parabola, sine, sphere, cylinder, torus, bowl) and the deviation measure |

pub mod basis;
pub mod bis;
pub mod curve;
mod explicit;
pub mod presets;
mod segment;
pub mod surface;
pub mod trig;

pub use basis::{allocated, basis, basis_deriv, basis_derivs, check_alpha, end_constants};
pub use bis::{beta_curvature, circle_curvatures, Bis};
pub use curve::QuasiCubicCurve;
pub use surface::{BisSurface, QuasiCubicSurface};
