//! Reading the options object of an export: [`Opts`] reads each field with a message naming it on
//! failure (numbers, whole numbers, booleans, points, grids, curve and surface parameters), typed arrays
//! and flat arrays in one copy.

use super::errors::{self, err_kind, ApiResult};
use super::points::{flat_to_pts, rows_to_pts, rows_to_pts_named, Pts};
use crate::error::ErrorKind;
use crate::sample::{self, MAX_EVAL_POINTS, MAX_INPUT_POINTS};
use js_sys::{Array, Float64Array, Reflect};
use serde::de::DeserializeOwned;
use wasm_bindgen::prelude::*;

/// The options object of one call.
pub struct Opts {
    obj: JsValue,
}

/// Refuses a row of `points` with more than 3 numbers before anything is deserialized, with the error
/// `rows_to_pts` gives for it (a list of 300 rows of 200,000 numbers took 5 s to convert, only to be refused).
fn check_row_lengths(key: &str, rows: &Array) -> ApiResult<()> {
    let len =
        |v: JsValue| Array::is_array(&v).then(|| v.unchecked_ref::<Array>().length() as usize);
    let first = len(rows.get(0));
    for i in 0..rows.length() {
        let Some(n) = len(rows.get(i)) else { continue };
        if n <= 3 {
            continue;
        }
        return Err(match (i, first) {
            // the first row decides the dimension: rows_to_pts names it when it is not 2 or 3
            (_, Some(d)) if i > 0 && d != 2 && d != 3 => err_kind(
                ErrorKind::WrongType,
                &format!("{key}[0]"),
                format!("expected [x, y] or [x, y, z], got {d} numbers"),
            ),
            (0, _) | (_, None) => err_kind(
                ErrorKind::WrongType,
                &format!("{key}[{i}]"),
                format!("expected [x, y] or [x, y, z], got {n} numbers"),
            ),
            (_, Some(dim)) => err_kind(
                ErrorKind::SizeMismatch,
                &format!("{key}[{i}]"),
                format!("all points must have the same dimension ({dim}), got {n} numbers"),
            ),
        });
    }
    Ok(())
}

impl Opts {
    /// Wraps the single argument of an export; it must be an object.
    pub fn new(v: JsValue) -> ApiResult<Self> {
        if !v.is_object() || v.is_function() || Array::is_array(&v) {
            return Err(err_kind(
                ErrorKind::WrongType,
                "options",
                "expected one options object, e.g. { points: [[0,0],[1,1],…] }",
            ));
        }
        Ok(Opts { obj: v })
    }

    /// The raw value of `key` (`undefined` when absent).
    pub fn raw(&self, key: &str) -> JsValue {
        Reflect::get(&self.obj, &JsValue::from_str(key)).unwrap_or(JsValue::UNDEFINED)
    }

    /// Whether `key` is present and neither `undefined` nor `null`.
    pub fn has(&self, key: &str) -> bool {
        let v = self.raw(key);
        !(v.is_undefined() || v.is_null())
    }

    /// Deserializes `key` if present (`undefined`/`null` give `None`).
    pub fn opt<T: DeserializeOwned>(&self, key: &str) -> ApiResult<Option<T>> {
        let v = self.raw(key);
        if v.is_undefined() || v.is_null() {
            return Ok(None);
        }
        check_array_sizes(key, &v, 0)?;
        if Array::is_array(&v) && v.unchecked_ref::<Array>().length() > 1000 {
            // A large array where something else is expected (a name, an object): serde's message
            // would format the whole array (seconds for 10⁵ entries). A two-entry probe fails the same
            // way, cheaply; for sequence types it passes and the full read follows.
            let probe: JsValue = v.unchecked_ref::<Array>().slice(0, 2).into();
            serde_wasm_bindgen::from_value::<T>(probe)
                .map_err(|e| err_kind(ErrorKind::WrongType, key, format!("wrong type ({e})")))?;
        }
        serde_wasm_bindgen::from_value(v)
            .map(Some)
            .map_err(|e| err_kind(ErrorKind::WrongType, key, format!("wrong type ({e})")))
    }

    /// `key` as one of the named `choices`, or `default` when absent (`undefined`/`null`). Another string is
    /// `invalid` and anything else `wrong-type`; both messages list the names, and `invalid` repeats what was given.
    pub fn choice<T: Copy, const N: usize>(
        &self,
        key: &str,
        choices: [(&str, T); N],
        default: T,
    ) -> ApiResult<T> {
        let names = choices.map(|(name, _)| name);
        Ok(match self.choice_index(key, &names)? {
            Some(i) => choices[i].1,
            None => default,
        })
    }

    /// The index of `key`'s string in `names`, `None` when absent ([`Opts::choice`]; one copy for every type).
    #[inline(never)]
    fn choice_index(&self, key: &str, names: &[&str]) -> ApiResult<Option<usize>> {
        let v = self.raw(key);
        if v.is_undefined() || v.is_null() {
            return Ok(None);
        }
        let Some(given) = v.as_string() else {
            let expected = format!("expected {}", choice_names(names));
            return Err(err_kind(ErrorKind::WrongType, key, expected));
        };
        match names.iter().position(|name| *name == given) {
            Some(i) => Ok(Some(i)),
            None => Err(err_kind(
                ErrorKind::Invalid,
                key,
                format!("expected {}, got \"{given}\"", choice_names(names)),
            )),
        }
    }

    /// Deserializes the required field `key`.
    pub fn req<T: DeserializeOwned>(&self, key: &str) -> ApiResult<T> {
        self.opt(key)?
            .ok_or_else(|| err_kind(ErrorKind::Missing, key, "this field is required"))
    }

    /// A required finite number (`missing` when absent, then as [`Opts::f64_or`]).
    pub fn req_f64(&self, key: &str) -> ApiResult<f64> {
        if !self.has(key) {
            return Err(err_kind(
                ErrorKind::Missing,
                key,
                "this field is required (a number)",
            ));
        }
        self.f64_or(key, 0.0)
    }

    /// A finite number, or `default` when absent.
    pub fn f64_or(&self, key: &str, default: f64) -> ApiResult<f64> {
        let v = self.raw(key);
        if v.is_undefined() || v.is_null() {
            return Ok(default);
        }
        let x = v
            .as_f64()
            .ok_or_else(|| err_kind(ErrorKind::WrongType, key, "expected a number"))?;
        if !x.is_finite() {
            return Err(err_kind(
                ErrorKind::NotFinite,
                key,
                crate::error::not_finite_detail(x),
            ));
        }
        Ok(x)
    }

    /// `key` as one finite number when it is a number, `None` when it is anything else (absent included), for
    /// fields that take a number or something else (a tension: a number or one per vertex). A number that is
    /// not finite is refused (`not-finite`).
    pub fn finite_if_number(&self, key: &str) -> ApiResult<Option<f64>> {
        match self.raw(key).as_f64() {
            Some(x) if !x.is_finite() => Err(err_kind(
                ErrorKind::NotFinite,
                key,
                crate::error::not_finite_detail(x),
            )),
            x => Ok(x),
        }
    }

    /// A non-negative integer ≤ `max`, or `default` when absent.
    pub fn usize_or(&self, key: &str, default: usize, max: usize) -> ApiResult<usize> {
        let v = self.raw(key);
        if v.is_undefined() || v.is_null() {
            return Ok(default);
        }
        let x = v
            .as_f64()
            .ok_or_else(|| err_kind(ErrorKind::WrongType, key, "expected a whole number"))?;
        if !x.is_finite() || x < 0.0 || x.fract() != 0.0 {
            return Err(err_kind(
                ErrorKind::OutOfRange,
                key,
                "expected a whole number ≥ 0",
            ));
        }
        if x > max as f64 {
            // with `.expected` / `.got` when the count fits a usize (it is exact then: x is whole)
            return Err(if x <= usize::MAX as f64 {
                super::errors::too_many(key, max, x as usize, format!("at most {max}, got {x}"))
            } else {
                err_kind(ErrorKind::TooMany, key, format!("at most {max}, got {x:e}"))
            });
        }
        Ok(x as usize)
    }

    /// A boolean, or `default` when absent.
    pub fn bool_or(&self, key: &str, default: bool) -> ApiResult<bool> {
        let v = self.raw(key);
        if v.is_undefined() || v.is_null() {
            return Ok(default);
        }
        v.as_bool()
            .ok_or_else(|| err_kind(ErrorKind::WrongType, key, "expected true or false"))
    }

    /// `mesh` (default false): whether to add render buffers. They need a grid, so `mesh` with `atUV` is
    /// `incompatible` (named `mesh`).
    pub fn mesh_on_grid(&self) -> ApiResult<bool> {
        let want = self.bool_or("mesh", false)?;
        if want && self.has("atUV") {
            return Err(err_kind(
                ErrorKind::SizeMismatch,
                "mesh",
                "render buffers need a grid (samplesU/samplesV), not atUV",
            ));
        }
        Ok(want)
    }

    /// A finite number array (e.g. knots), or `None` when absent.
    pub fn f64s(&self, key: &str) -> ApiResult<Option<Vec<f64>>> {
        let v: Option<Vec<f64>> = self.opt(key)?;
        if let Some(xs) = &v {
            if let Some(i) = xs.iter().position(|x| !x.is_finite()) {
                return Err(err_kind(
                    ErrorKind::NotFinite,
                    &format!("{key}[{i}]"),
                    crate::error::not_finite_detail(xs[i]),
                ));
            }
        }
        Ok(v)
    }

    /// Points `[[x, y], …]` or `[[x, y, z], …]`, at least `min` of them; or flat coordinates
    /// `[x0, y0, x1, y1, …]` as a `Float64Array` (or a plain array of numbers), read in one copy, with the
    /// dimension from the option `dim` (2 or 3, default 2).
    pub fn points(&self, key: &str, min: usize) -> ApiResult<Pts> {
        // the input limit is checked before deserializing (reading 10⁶ rows costs seconds)
        let raw = self.raw(key);
        if let Some(flat) = self.flat_numbers(key, &raw, MAX_INPUT_POINTS * 3)? {
            let dim = self.usize_or("dim", 2, 3)?;
            if dim < 2 {
                return Err(err_kind(
                    ErrorKind::Invalid,
                    "dim",
                    format!("expected 2 or 3, got {dim}"),
                ));
            }
            return flat_to_pts(key, &flat, dim, min);
        }
        if Array::is_array(&raw) {
            let n = raw.unchecked_ref::<Array>().length() as usize;
            if n > MAX_INPUT_POINTS {
                return Err(errors::too_many(
                    key,
                    MAX_INPUT_POINTS,
                    n,
                    format!("at most {MAX_INPUT_POINTS} points, got {n}"),
                ));
            }
            check_row_lengths(key, raw.unchecked_ref::<Array>())?;
        }
        let rows: Vec<Vec<f64>> = self.req(key)?;
        rows_to_pts(key, &rows, min)
    }

    /// A grid `grid[i][j] = [x, y(, z)]`, rectangular, of one dimension; returns (rows, cols, points
    /// row-major). Each row may instead be flat coordinates `[x0, y0, z0, x1, …]` (a `Float64Array` or
    /// an array of numbers), read in one copy per row, with the dimension from the option `dim` (2 or 3,
    /// default 3).
    pub fn grid(
        &self,
        key: &str,
        min_rows: usize,
        min_cols: usize,
    ) -> ApiResult<(usize, usize, Pts)> {
        // the input limit (rows × first row) is checked before deserializing
        let raw = self.raw(key);
        if Array::is_array(&raw) {
            let a: &Array = raw.unchecked_ref();
            let first = a.get(0);
            if first.is_instance_of::<Float64Array>()
                || (Array::is_array(&first)
                    && first.unchecked_ref::<Array>().get(0).as_f64().is_some())
            {
                return self.flat_grid(key, a, min_rows, min_cols);
            }
            let first = a.get(0);
            let cols = if Array::is_array(&first) {
                first.unchecked_ref::<Array>().length() as usize
            } else {
                0
            };
            let n = (a.length() as usize).saturating_mul(cols.max(1));
            if n > MAX_INPUT_POINTS {
                return Err(err_kind(
                    ErrorKind::TooMany,
                    key,
                    format!(
                        "at most {MAX_INPUT_POINTS} points, got {} rows of {cols}",
                        a.length()
                    ),
                ));
            }
        }
        let rows: Vec<Vec<Vec<f64>>> = self.req(key)?;
        let nr = rows.len();
        if nr < min_rows {
            return Err(err_kind(
                ErrorKind::TooFew,
                key,
                format!("need at least {min_rows} rows, got {nr}"),
            ));
        }
        let nc = rows[0].len();
        if nc < min_cols {
            return Err(err_kind(
                ErrorKind::TooFew,
                &format!("{key}[0]"),
                format!("need at least {min_cols} points per row, got {nc}"),
            ));
        }
        if let Some(i) = rows.iter().position(|r| r.len() != nc) {
            return Err(err_kind(
                ErrorKind::SizeMismatch,
                &format!("{key}[{i}]"),
                format!("rows must all have {nc} points, got {}", rows[i].len()),
            ));
        }
        let flat_rows: Vec<Vec<f64>> = rows.into_iter().flatten().collect();
        // a bad point is named by its row and column: grid[i][j][k]
        let pts = rows_to_pts_named(key, &flat_rows, 0, |f| {
            format!("{key}[{}][{}]", f / nc, f % nc)
        })?;
        Ok((nr, nc, pts))
    }

    /// [`Self::grid`] for rows of flat coordinates (`dim` numbers per point): one copy per row.
    fn flat_grid(
        &self,
        key: &str,
        a: &Array,
        min_rows: usize,
        min_cols: usize,
    ) -> ApiResult<(usize, usize, Pts)> {
        let dim = self.usize_or("dim", 3, 3)?;
        if dim < 2 {
            return Err(err_kind(ErrorKind::OutOfRange, "dim", "expected 2 or 3"));
        }
        let nr = a.length() as usize;
        if nr < min_rows {
            return Err(errors::too_few(
                key,
                min_rows,
                nr,
                format!("need at least {min_rows} rows, got {nr}"),
            ));
        }
        let mut xs: Vec<f64> = Vec::new();
        let mut nc = 0;
        for i in 0..nr {
            let field = format!("{key}[{i}]");
            let row = a.get(i as u32);
            let before = xs.len();
            match self.flat_numbers(&field, &row, MAX_INPUT_POINTS * 3 - before)? {
                Some(r) => xs.extend_from_slice(&r),
                None => {
                    return Err(err_kind(
                        ErrorKind::WrongType,
                        &field,
                        "expected a row of flat coordinates like the first row",
                    ))
                }
            }
            let len = xs.len() - before;
            if !len.is_multiple_of(dim) {
                return Err(err_kind(
                    ErrorKind::SizeMismatch,
                    &field,
                    format!("flat coordinates need a multiple of dim = {dim} numbers, got {len}"),
                ));
            }
            if i == 0 {
                nc = len / dim;
                if nc < min_cols {
                    return Err(errors::too_few(
                        &field,
                        min_cols,
                        nc,
                        format!("need at least {min_cols} points per row, got {nc}"),
                    ));
                }
            } else if len / dim != nc {
                return Err(err_kind(
                    ErrorKind::SizeMismatch,
                    &field,
                    format!("rows must all have {nc} points, got {}", len / dim),
                ));
            }
        }
        let pts = flat_to_pts(key, &xs, dim, 0)?;
        Ok((nr, nc, pts))
    }

    /// The numbers of `raw` when it is a `Float64Array` (one copy) or a plain array whose first entry is a
    /// number (flat coordinates), else `None` (nested arrays take the serde path). Entries must be finite
    /// (`key[i]` names a bad one); at most `max` of them.
    fn flat_numbers(&self, key: &str, raw: &JsValue, max: usize) -> ApiResult<Option<Vec<f64>>> {
        let xs = if let Some(ta) = raw.dyn_ref::<Float64Array>() {
            if ta.length() as usize > max {
                return Err(err_kind(
                    ErrorKind::TooMany,
                    key,
                    format!(
                        "array too long ({} numbers; the limit is {max})",
                        ta.length()
                    ),
                ));
            }
            ta.to_vec()
        } else if Array::is_array(raw) {
            let a: &Array = raw.unchecked_ref();
            if a.length() == 0 || a.get(0).as_f64().is_none() {
                return Ok(None);
            }
            if a.length() as usize > max {
                return Err(err_kind(
                    ErrorKind::TooMany,
                    key,
                    format!(
                        "array too long ({} numbers; the limit is {max})",
                        a.length()
                    ),
                ));
            }
            serde_wasm_bindgen::from_value::<Vec<f64>>(raw.clone())
                .map_err(|e| err_kind(ErrorKind::WrongType, key, format!("wrong type ({e})")))?
        } else {
            return Ok(None);
        };
        if let Some(i) = xs.iter().position(|x| !x.is_finite()) {
            return Err(err_kind(
                ErrorKind::NotFinite,
                &format!("{key}[{i}]"),
                crate::error::not_finite_detail(xs[i]),
            ));
        }
        Ok(Some(xs))
    }

    /// Whether the curve parameters are the uniform `samples` (not `at`): the kernel's uniform sampler
    /// applies.
    pub fn uniform_samples(&self) -> bool {
        !self.has("at")
    }

    /// `derivatives: 0 | 1 | … | max` (default 0).
    pub fn derivatives(&self, max: usize) -> ApiResult<usize> {
        self.usize_or("derivatives", 0, max)
    }

    /// A JS function field.
    pub fn function(&self, key: &str) -> ApiResult<js_sys::Function> {
        let v = self.raw(key);
        v.dyn_into::<js_sys::Function>()
            .map_err(|_| err_kind(ErrorKind::WrongType, key, "expected a function"))
    }

    /// Curve parameters: `at` (in the given order, finite) or `samples` (uniform over `domain`, default 200).
    pub fn curve_params(&self, domain: (f64, f64)) -> ApiResult<Vec<f64>> {
        if self.has("at") {
            let raw = self.raw("at");
            if let Some(ta) = raw.dyn_ref::<Float64Array>() {
                // a typed array: one copy, no per-entry crossing
                if ta.length() as usize > MAX_EVAL_POINTS {
                    return Err(err_kind(
                        ErrorKind::TooMany,
                        "at",
                        format!(
                            "at most {MAX_EVAL_POINTS} parameters per call, got {}",
                            ta.length()
                        ),
                    ));
                }
                let at = ta.to_vec();
                // branch-free over all entries; the index is searched only when one is bad
                if let Some(i) = sample::first_non_finite(&at) {
                    return Err(err_kind(
                        ErrorKind::NotFinite,
                        &format!("at[{i}]"),
                        crate::error::not_finite_detail(at[i]),
                    ));
                }
                return Ok(at);
            }
            let at = self.f64s("at")?.unwrap_or_default();
            if at.len() > MAX_EVAL_POINTS {
                return Err(err_kind(
                    ErrorKind::TooMany,
                    "at",
                    format!(
                        "at most {MAX_EVAL_POINTS} parameters per call, got {}",
                        at.len()
                    ),
                ));
            }
            return Ok(at);
        }
        let n = self.usize_or("samples", 200, MAX_EVAL_POINTS)?;
        Ok(sample::uniform_params(domain.0, domain.1, n))
    }

    /// Surface parameters, flat `[u0, v0, u1, v1, …]`: `atUV` pairs, or the u-major grid
    /// `samplesU × samplesV` (default 40 each) over `domain`.
    pub fn surface_uv(&self, domain: ((f64, f64), (f64, f64))) -> ApiResult<Vec<f64>> {
        if self.has("atUV") {
            let raw = self.raw("atUV");
            // flat pairs [u0, v0, u1, v1, …] (a Float64Array or plain numbers): one copy
            if let Some(uv) = self.flat_numbers("atUV", &raw, 2 * MAX_EVAL_POINTS)? {
                if !uv.len().is_multiple_of(2) {
                    return Err(err_kind(
                        ErrorKind::Invalid,
                        "atUV",
                        format!(
                            "flat (u, v) pairs need an even count of numbers, got {}",
                            uv.len()
                        ),
                    ));
                }
                return Ok(uv);
            }
            let pairs: Vec<Vec<f64>> = self.req("atUV")?;
            if pairs.len() > MAX_EVAL_POINTS {
                return Err(err_kind(
                    ErrorKind::TooMany,
                    "atUV",
                    format!(
                        "at most {MAX_EVAL_POINTS} pairs per call, got {}",
                        pairs.len()
                    ),
                ));
            }
            let mut uv = Vec::with_capacity(2 * pairs.len());
            for (i, p) in pairs.iter().enumerate() {
                if p.len() != 2 || !p[0].is_finite() || !p[1].is_finite() {
                    return Err(err_kind(
                        ErrorKind::Invalid,
                        &format!("atUV[{i}]"),
                        "expected a pair of finite numbers [u, v]",
                    ));
                }
                uv.extend_from_slice(p);
            }
            return Ok(uv);
        }
        let nu = self.usize_or("samplesU", 40, MAX_EVAL_POINTS)?;
        let nv = self.usize_or("samplesV", 40, MAX_EVAL_POINTS)?;
        if nu.saturating_mul(nv) > MAX_EVAL_POINTS {
            return Err(err_kind(
                ErrorKind::TooMany,
                "samplesU",
                format!("samplesU × samplesV must be at most {MAX_EVAL_POINTS}, got {nu} × {nv}"),
            ));
        }
        Ok(sample::uv_grid(domain, nu, nv))
    }
}

/// Rejects arrays (and nested arrays, one level) longer than the input limit before deserializing them.
fn check_array_sizes(key: &str, v: &JsValue, depth: usize) -> ApiResult<()> {
    const LIMIT: u32 = MAX_EVAL_POINTS as u32;
    if Array::is_array(v) {
        let a: &Array = v.unchecked_ref();
        if a.length() > LIMIT {
            return Err(err_kind(
                ErrorKind::TooMany,
                key,
                format!(
                    "array too long ({} entries; the limit is {LIMIT})",
                    a.length()
                ),
            ));
        }
        if depth == 0 && a.length() > 0 {
            check_array_sizes(key, &a.get(0), 1)?;
        }
    }
    Ok(())
}

/// `"a"`, `"a" or "b"`, `"a", "b" or "c"`: the names of a choice as a message lists them.
fn choice_names(names: &[&str]) -> String {
    let mut out = String::new();
    for (k, name) in names.iter().enumerate() {
        if k > 0 {
            out.push_str(if k + 1 == names.len() { " or " } else { ", " });
        }
        out.push('"');
        out.push_str(name);
        out.push('"');
    }
    out
}
