//! Lists of numbers and rows and tables of 3D points as the network exports take them: nested
//! `[[x, y, z], …]`, or flat coordinates `[x0, y0, z0, x1, …]` (a `Float64Array` or an array of numbers, read in
//! one copy). Read by the network reader (`network.u`, `network.P`, …) and by `networkFromControlNet` (`C`) and
//! `networkFromFreeData` (`P`, `Q1`).

use crate::api::{err_kind, ApiResult};
use crate::error::ErrorKind;
use crate::sample::MAX_INPUT_POINTS;
use glam::DVec3;
use js_sys::{Array, Float64Array};
use wasm_bindgen::prelude::*;

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
pub(super) fn numbers(field: &str, raw: &JsValue) -> ApiResult<Vec<f64>> {
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
pub fn read_row(field: &str, raw: &JsValue, max: usize) -> ApiResult<Vec<DVec3>> {
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
pub fn read_table(field: &str, raw: &JsValue, cols: usize) -> ApiResult<Vec<Vec<DVec3>>> {
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
