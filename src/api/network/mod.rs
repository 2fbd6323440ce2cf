//! Curve-network exports (seed 004; `../shared/spec/api.md` "Curve-network surfaces", `surfaces.md`).
//!
//! Contract functions:
//! * `crissCrossSurface({ network, C11, tolerance, evaluate, atUV | samplesU/samplesV, derivatives, mesh })`
//!   → surface result + `{ controlPoints, C11, c2 }`. `controlPoints` = C_ij of Lemma 3.1 (flat xyz,
//!   (m+2)(n+2) points, i-major: index i·(n+2)+j). `C11`: `[x, y, z]`, or `"area"` (the default: the paper's
//!   choice, §4.1, minimising the area of the bilinear control net, a convex problem solved by reweighted least
//!   squares with 4×4 Gauss points per quad), or `"edges"` (minimal sum of squared net edge lengths, closed form);
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
use super::{call_point_fn, core_err, err_kind, flat, ApiResult, Opts, Out};
use crate::criss_cross::{CrissCross, CrissCrossSurface, Triangle, DOMAIN_POINTS};
use crate::error::ErrorKind;
use crate::network::{examples, NetPoint, Network, Partition, COMPATIBILITY_TOL};
use crate::sample::{MAX_EVAL_POINTS, MAX_INPUT_POINTS};
use crate::thin_plate::ThinPlateSurface;
use glam::DVec3;
use js_sys::{Array, Float64Array, Reflect};
use serde::Deserialize;
use wasm_bindgen::prelude::*;

mod data;
pub use data::*;
mod surfaces;
pub use surfaces::*;

/// The numbers of a flat input: a `Float64Array` (one copy) or a plain array of numbers (one
/// deserialization), at most `max` of them; `None` when `raw` is neither (e.g. nested arrays).
fn flat_numbers(field: &str, raw: &JsValue, max: usize) -> ApiResult<Option<Vec<f64>>> {
    let len = if let Some(ta) = raw.dyn_ref::<Float64Array>() {
        ta.length() as usize
    } else if Array::is_array(raw) {
        let a: &Array = raw.unchecked_ref();
        if a.length() == 0 || a.get(0).as_f64().is_none() {
            return Ok(None);
        }
        a.length() as usize
    } else {
        return Ok(None);
    };
    if len > max {
        return Err(err_kind(
            ErrorKind::TooMany,
            field,
            format!("at most {max} numbers, got {len}"),
        ));
    }
    if let Some(ta) = raw.dyn_ref::<Float64Array>() {
        return Ok(Some(ta.to_vec()));
    }
    serde_wasm_bindgen::from_value::<Vec<f64>>(raw.clone())
        .map(Some)
        .map_err(|_| err_kind(ErrorKind::WrongType, field, "expected an array of numbers"))
}

/// Breakpoints (`network.u`, `u`, …): an array of numbers or a `Float64Array` (finiteness and order are
/// checked by the core).
fn numbers(field: &str, raw: &JsValue) -> ApiResult<Vec<f64>> {
    if raw.is_undefined() || raw.is_null() {
        return Err(err_kind(
            ErrorKind::Missing,
            field,
            "this field is required",
        ));
    }
    if Array::is_array(raw) && raw.unchecked_ref::<Array>().length() == 0 {
        return Ok(Vec::new());
    }
    flat_numbers(field, raw, MAX_INPUT_POINTS)?
        .ok_or_else(|| err_kind(ErrorKind::WrongType, field, "expected an array of numbers"))
}

/// Flat coordinates `[x0, y0, z0, x1, …]` → points; the count must be a multiple of 3.
fn flat_points(field: &str, xs: &[f64]) -> ApiResult<Vec<DVec3>> {
    if !xs.len().is_multiple_of(3) {
        return Err(err_kind(
            ErrorKind::SizeMismatch,
            field,
            format!(
                "flat coordinates need 3 numbers per point, got {} numbers",
                xs.len()
            ),
        ));
    }
    if let Some(k) = xs.iter().position(|x| !x.is_finite()) {
        // named like the nested form: point k / 3, coordinate k % 3
        return Err(err_kind(
            ErrorKind::NotFinite,
            &format!("{field}[{}][{}]", k / 3, k % 3),
            crate::error::not_finite_detail(xs[k]),
        ));
    }
    Ok(xs
        .chunks_exact(3)
        .map(|c| DVec3::new(c[0], c[1], c[2]))
        .collect())
}

/// One row of points (a network curve's control points): nested `[[x, y, z], …]`, or flat coordinates
/// `[x0, y0, z0, x1, …]` as a `Float64Array` or an array of numbers, read in one copy. `max`: the points
/// still allowed.
fn read_row(field: &str, raw: &JsValue, max: usize) -> ApiResult<Vec<DVec3>> {
    if let Some(xs) = flat_numbers(field, raw, max.saturating_mul(3))? {
        return flat_points(field, &xs);
    }
    if !Array::is_array(raw) {
        return Err(err_kind(
            ErrorKind::WrongType,
            field,
            "expected points [[x, y, z], …] or flat coordinates (a Float64Array or an array of numbers)",
        ));
    }
    let n = raw.unchecked_ref::<Array>().length() as usize;
    if n > max {
        return Err(err_kind(
            ErrorKind::TooMany,
            field,
            format!("at most {MAX_INPUT_POINTS} points in all"),
        ));
    }
    let rows: Vec<Vec<f64>> = serde_wasm_bindgen::from_value(raw.clone()).map_err(|_| {
        err_kind(
            ErrorKind::WrongType,
            field,
            "expected points [[x, y, z], …] of numbers",
        )
    })?;
    rows.iter()
        .enumerate()
        .map(|(j, p)| {
            if p.len() != 3 {
                return Err(err_kind(
                    ErrorKind::WrongType,
                    &format!("{field}[{j}]"),
                    format!("expected [x, y, z], got {} numbers", p.len()),
                ));
            }
            if let Some(k) = p.iter().position(|x| !x.is_finite()) {
                return Err(err_kind(
                    ErrorKind::NotFinite,
                    &format!("{field}[{j}][{k}]"),
                    crate::error::not_finite_detail(p[k]),
                ));
            }
            Ok(DVec3::new(p[0], p[1], p[2]))
        })
        .collect()
}

/// A table of points (`network.P`, `network.Q`, `C`): rows as [`read_row`] reads them, or the whole table
/// as flat coordinates (row-major, `cols` points per row, 3 numbers per point) in one copy. Row counts and
/// finiteness are checked by the core (`Network::check_shape`).
fn read_table(field: &str, raw: &JsValue, cols: usize) -> ApiResult<Vec<Vec<DVec3>>> {
    if raw.is_undefined() || raw.is_null() {
        return Err(err_kind(
            ErrorKind::Missing,
            field,
            "this field is required",
        ));
    }
    if let Some(xs) = flat_numbers(field, raw, MAX_INPUT_POINTS * 3)? {
        let per_row = 3 * cols.max(1);
        if !xs.len().is_multiple_of(per_row) {
            return Err(err_kind(
                ErrorKind::SizeMismatch,
                field,
                format!(
                    "a flat table needs rows of {cols} points (3 numbers each), got {} numbers",
                    xs.len()
                ),
            ));
        }
        return xs
            .chunks_exact(per_row)
            .enumerate()
            .map(|(r, row)| flat_points(&format!("{field}[{r}]"), row))
            .collect();
    }
    if !Array::is_array(raw) {
        return Err(err_kind(
            ErrorKind::WrongType,
            field,
            "expected rows of points or flat coordinates (a Float64Array or an array of numbers)",
        ));
    }
    let a: &Array = raw.unchecked_ref();
    let mut left = MAX_INPUT_POINTS;
    let mut out = Vec::with_capacity(a.length() as usize);
    for (r, row) in a.iter().enumerate() {
        if left == 0 {
            return Err(err_kind(
                ErrorKind::TooMany,
                field,
                format!("at most {MAX_INPUT_POINTS} points"),
            ));
        }
        let pts = read_row(&format!("{field}[{r}]"), &row, left)?;
        left -= pts.len().max(1).min(left);
        out.push(pts);
    }
    Ok(out)
}

/// Reads the network object `{ u, v, P, Q }` at `key` and checks its shape (not compatibility); errors name
/// `network.P[r][j]` etc. Each curve (`P[r]`, `Q[s]`) may be nested points or flat coordinates (a
/// `Float64Array` or an array of numbers), and each of `P`, `Q` a whole flat table (r-major, n + 2 points
/// per row for `P`, m + 2 for `Q`); `u`, `v` may be `Float64Array`s. Public so that other network exports
/// (Gordon, exercises) share it.
pub fn read_network(o: &Opts, key: &str) -> ApiResult<Network> {
    let obj = o.raw(key);
    if obj.is_undefined() || obj.is_null() {
        return Err(err_kind(ErrorKind::Missing, key, "this field is required"));
    }
    if !obj.is_object() || Array::is_array(&obj) {
        return Err(err_kind(
            ErrorKind::WrongType,
            key,
            "expected a network { u, v, P, Q }",
        ));
    }
    let get = |k: &str| Reflect::get(&obj, &JsValue::from_str(k)).unwrap_or(JsValue::UNDEFINED);
    let mut uv = [Vec::new(), Vec::new()];
    for (slot, k) in uv.iter_mut().zip(["u", "v"]) {
        let field = format!("{key}.{k}");
        let raw = get(k);
        // bound the work before reading: breakpoints per direction
        let len = if let Some(ta) = raw.dyn_ref::<Float64Array>() {
            ta.length() as usize
        } else if Array::is_array(&raw) {
            raw.unchecked_ref::<Array>().length() as usize
        } else {
            0
        };
        if len > crate::network::MAX_BREAKPOINTS {
            return Err(err_kind(
                ErrorKind::TooMany,
                &field,
                format!("at most {} breakpoints", crate::network::MAX_BREAKPOINTS),
            ));
        }
        *slot = numbers(&field, &raw)?;
    }
    let [u, v] = uv;
    let p = read_table(&format!("{key}.P"), &get("P"), v.len() + 1)?;
    let q = read_table(&format!("{key}.Q"), &get("Q"), u.len() + 1)?;
    let net = Network { u, v, p, q };
    net.check_shape().map_err(core_err)?;
    Ok(net)
}

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

/// `tolerance` (relative C2 tolerance ≥ 0, default [`COMPATIBILITY_TOL`]), read the same way by every
/// network export.
pub(super) fn tolerance(o: &Opts) -> ApiResult<f64> {
    let t = o.f64_or("tolerance", COMPATIBILITY_TOL)?;
    if t < 0.0 {
        return Err(err_kind(
            ErrorKind::OutOfRange,
            "tolerance",
            "expected a number ≥ 0",
        ));
    }
    Ok(t)
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

fn domain_points(cc: &CrissCross) -> Vec<f64> {
    let (m, n) = cc.cells();
    let (pu, pv) = (cc.u(), cc.v());
    let mut out = Vec::with_capacity(m * n * 26);
    for a in 1..=m {
        for b in 1..=n {
            let (u0, v0) = (pu.breaks()[a - 1], pv.breaks()[b - 1]);
            for (s, t) in DOMAIN_POINTS {
                out.push(u0 + s * pu.h(a));
                out.push(v0 + t * pv.h(b));
            }
        }
    }
    out
}
