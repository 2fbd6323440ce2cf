//! Dagnino, Lamberti and Remogna: C¹ quadratic B-splines B_ij on a non-uniform criss-cross
//! triangulation T_mn and the surface S through a compatible curve network.
//!
//! **Cells and BB nets** (`surfaces.md` §2.1): cell (a, b) = [u_{a−1}, u_a]×[v_{b−1}, v_b] (a = 1..m,
//! b = 1..n) with local s = (u − u_{a−1})/h_a, t = (v − v_{b−1})/k_b is cut by its diagonals into the
//! triangles B (bottom), R, T, L. A quadratic on the cell has 13 BB ordinates ([`CellNet`], index
//! constants [`C00`] … [`O`], domain points [`DOMAIN_POINTS`]). A C¹ cell is fixed by its edge traces: the
//! half-diagonal ordinates are the means of the two adjacent edge-midpoint ordinates and the centre is the
//! mean of the four (§2.2).
//!
//! **B_ij** (i = 0..m+1, j = 0..n+1) is the element of S₂¹(T_mn) whose traces on all grid lines equal
//! those of B_i(u|U)B_j(v|V) (eq. (23) and its v-analogue): on cell (a, b), with the Bernstein
//! coefficients α of B_i on column a and β of B_j on row b ([`Partition::bernstein`](crate::network::Partition::bernstein)),
//! c00 = α0β0, c10 = α2β0, c11 = α2β2, c01 = α0β2, eb = α1β0, er = α2β1, et = α1β2, el = α0β1 (§2.3).
//! They are ≥ 0, sum to 1, reproduce bilinears and P₂, and satisfy the dependence relation
//! Σ_{i=1..m, j=1..n} (−1)^{i+j} h_i k_j B_ij = 0.
//!
//! **S** (Thm 3.2) is evaluated by the local cell form (§3): corners I_rs, edge midpoints the middle
//! Bézier ordinates of the network curves (Q_a^{(b−1)} bottom, P_b^{(a)} right, Q_a^{(b)} top, P_b^{(a−1)}
//! left). The control points C_ij of Lemma 3.1 for a chosen C11 ((18)–(21) and the recursions (17) at
//! i = 1, then (16); the closed form (26)–(27) is [`CrissCrossSurface::control_points_closed_form`]) give
//! the same surface Σ C_ij B_ij ([`CrissCrossSpline`]) for every C11.
//!
//! **Choice of C11** (it changes the control net, never the surface): the paper's minimal area of the
//! bilinear control net ([`CrissCrossSurface::min_area_c11`], convex, Newton's method; the API
//! default), or the closed-form minimum of the sum of squared control-net edge lengths
//! ([`CrissCrossSurface::default_c11`], also the starting value of the former).
//!
//! Files: `cell` (one cell's BB net and triangles), `cells` ([`CellOrdinates`], the nets of every cell),
//! `triangulation` ([`CrissCross`], the B_ij and their samples), `spline` ([`CrissCrossSpline`]), `surface`
//! ([`CrissCrossSurface`] and its C11 rules), `choice` ([`C11Choice`], [`Evaluation`] and
//! [`CrissCrossSurface::resolve`]).

mod cell;
mod cells;
mod choice;
mod spline;
mod surface;
mod triangulation;

pub use cell::*;
pub use cells::CellOrdinates;
pub use choice::{C11Choice, Evaluation, ResolvedSurface};
pub use spline::CrissCrossSpline;
pub use surface::*;
pub use triangulation::{BasisSamples, CrissCross};
