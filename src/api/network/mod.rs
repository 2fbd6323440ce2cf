//! Curve-network exports (seed 004; `../shared/spec/api.md` "Curve-network surfaces", `surfaces.md`).
//!
//! Contract functions:
//! * `crissCrossSurface({ network, C11, tolerance, evaluate, atUV | samplesU/samplesV, derivatives, mesh })`
//!   → surface result + `{ controlPoints, C11, c2 }`. `controlPoints` = C_ij of Lemma 3.1 (flat xyz,
//!   (m+2)(n+2) points, i-major: index i·(n+2)+j). `C11`: `[x, y, z]`, or `"area"` (the default: the paper's
//!   choice, §4.1, minimising the area of the bilinear control net, a convex problem solved by Newton's method
//!   with 4×4 Gauss points per quad), or `"edges"` (minimal sum of squared net edge lengths, closed form);
//!   the result's `C11` is the one used. The surface never depends on it: it is evaluated by the local cell form, or with
//!   `evaluate: "sum"` as Σ C_ij B_ij (same surface up to rounding ∝ max|C_ij|). `c2` = the C2 residual.
//! * `crissCrossBasis({ u, v, i, j, atUV | samplesU/samplesV, derivatives, mesh })` → `{ uv, values, du?, dv?,
//!   mesh? }` for B_ij (i = 0..m+1, j = 0..n+1); `mesh: true` adds the render buffers of the graph (u, v, B_ij).
//! * `thinPlateSurface({ network, tolerance, atUV | samplesU/samplesV, derivatives, mesh })` → surface result +
//!   `{ C11, energy, controlPoints }` (C11* of eq. (38), Π at C11*, C*_ij i-major).
//! * `networkFromFunction({ u, v, f })` → network (Schoenberg quasi-interpolant C*_ij = f(ξ_i, η_j), then its
//!   isocurves).
//!
//! The network object is `{ u, v, P, Q }` with `P[r][j]` = P_j^{(r)} (r = 0..m, j = 0..n+1) and `Q[s][i]` =
//! Q_i^{(s)} (s = 0..n, i = 0..m+1), 3D points as `[x, y, z]` (plain arrays, so it can be passed back).
//! Functions that build a surface check compatibility (C2 residual ≤ `tolerance`·max(1, scale), default
//! 1e-12) and throw an Error naming the worst residual, the node (r, s) and the equation otherwise.
//!
//! Additions:
//! * `networkCompatibility({ network, tolerance })` → `{ compatible, c2, worst: [r, s], equation, scale,
//!   tolerance, residuals }` (`residuals` = ‖φ_r(v_s) − ψ_s(u_r)‖∞, r-major, (m+1)(n+1) entries).
//! * `networkFromControlNet({ u, v, C })` → network: the isocurves of the biquadratic Σ C_ij B_i(u)B_j(v),
//!   `C[i][j]`, (m+2) × (n+2) points.
//! * `networkFromFreeData({ u, v, P, Q1 })` → network: all P free, `Q1[s]` = Q_1^{(s)} free, other Q from C2.
//! * `networkRepair({ network, edited })` → `{ network, c2, dependentQ }`: recomputes the dependent control points so the
//!   network is compatible, keeping the edited one (`edited`: `{ kind: "P", r, j }` or `{ kind: "Q", s, i }`,
//!   optional). Free points: all P and Q_1^{(s)} (or the edited Q_i^{(s)} in its row); editing an end point
//!   Q_0^{(s)} / Q_{m+1}^{(s)} moves the boundary curve φ_0 / φ_m through it. Use it while dragging.
//!   `dependentQ[s·(m+2)+i]` = 1 for the Q_i^{(s)} that were recomputed, 0 for the free pivot of each row.
//! * `networkExample({ name })` → network: `"uniform-dome"`, `"uniform-random"`, `"nonuniform-dome"`,
//!   `"three-sided"`, `"strongly-nonuniform"`, `"separable"`, `"free-data"`, `"dome10"`.
//! * `crissCrossCells({ u, v, i, j })` or `crissCrossCells({ network })` → `{ m, n, dim, ordinates,
//!   domainPoints, support? }`: the 13 BB ordinates of every cell (cell (a, b) at block (a−1)·n + (b−1), ordinates
//!   in the order c00, c10, c11, c01, eb, er, et, el, d00, d10, d11, d01, o; `dim` 1 for B_ij, 3 for S's local
//!   form), their (u, v) domain points (2 per ordinate), and for B_ij `support`: 4 flags per cell (triangles
//!   bottom, right, top, left; 1 where B_ij is not identically zero).

use super::mesh::surface_output;
use super::readers::{read_network, read_row, read_table, read_tolerance};
use super::{api_options, call_point_fn, core_err, err_kind, flat, ApiResult, Opts, Out};
use crate::criss_cross::{C11Choice, CellOrdinates, CrissCross, CrissCrossSurface, Evaluation};
use crate::error::ErrorKind;
use crate::network::{examples, FromFunctionError, NetPoint, Network, Partition};
use crate::sample::{MAX_EVAL_POINTS, MAX_INPUT_POINTS};
use crate::thin_plate::ThinPlateSurface;
use glam::DVec3;
use serde::Deserialize;
use wasm_bindgen::prelude::*;

mod data;
pub use data::*;
mod surfaces;
pub use surfaces::*;

/// The network as a plain JS object `{ u, v, P, Q }` (nested arrays).
pub fn network_to_js(net: &Network) -> JsValue {
    let t = |rows: &Vec<Vec<DVec3>>| -> Vec<Vec<[f64; 3]>> {
        rows.iter()
            .map(|r| r.iter().map(|p| [p.x, p.y, p.z]).collect())
            .collect()
    };
    Out::new()
        .ser("u", &net.u)
        .ser("v", &net.v)
        .ser("P", &t(&net.p))
        .ser("Q", &t(&net.q))
        .build()
}

fn point3(o: &Opts, key: &str) -> ApiResult<Option<DVec3>> {
    let v: Option<Vec<f64>> = o.f64s(key)?;
    match v {
        None => Ok(None),
        Some(x) if x.len() == 3 => Ok(Some(DVec3::new(x[0], x[1], x[2]))),
        Some(x) => Err(err_kind(
            ErrorKind::WrongType,
            key,
            format!("expected [x, y, z], got {} numbers", x.len()),
        )),
    }
}

fn breakpoints(o: &Opts, key: &'static str) -> ApiResult<Partition> {
    let x = o.f64s(key)?.ok_or_else(|| {
        err_kind(
            ErrorKind::Missing,
            key,
            "this field is required (breakpoints, strictly increasing)",
        )
    })?;
    Partition::new(key, &x).map_err(core_err)
}
