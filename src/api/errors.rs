//! Core errors → JavaScript `Error`s that keep their kind.
//!
//! Every error an export throws is a plain JS `Error` with
//! * `message` — `"<field>: <detail>"` (unchanged, tests and pages match it);
//! * `field` — the option path of the offending input, e.g. `"points[1][1]"`, `"surface.knotsU"`;
//! * `kind` — a stable string, [`ErrorKind::as_str`] (`"too-few"`, `"not-finite"`, …; the table is in
//!   `docs/API.md`, "Errors");
//! * `expected`, `got` — numbers, only on counting errors whose core constructor knew them
//!   ([`crate::error::Counts`]).
//!
//! Core errors carry their kind from where they are made. The binding's own input checks (`api::err`)
//! state theirs with [`err_kind`]; the older two-argument `api::err(field, detail)` derives the kind from
//! the house wording of the detail ([`kind_of_detail`]; every export's bad input is pinned by
//! `tests/node/errors.test.mjs`).

use crate::error::{Error, ErrorKind};
use js_sys::Reflect;
use wasm_bindgen::prelude::*;

/// The JS `Error` thrown for a core error: its message is the error's `Display`, with `.field`, `.kind`
/// (and `.expected` / `.got` when known) set on it.
pub fn to_js(e: &Error) -> JsError {
    let js = JsError::new(&e.to_string());
    // `JsError` is a handle: the clone refers to the same JS object, so the properties set here are
    // on the error that is thrown.
    let obj = JsValue::from(js.clone());
    let set = |k: &str, v: JsValue| {
        let _ = Reflect::set(&obj, &JsValue::from_str(k), &v);
    };
    set("field", JsValue::from_str(e.field()));
    set("kind", JsValue::from_str(e.kind().as_str()));
    if let Some(c) = e.counts() {
        set("expected", JsValue::from_f64(c.expected as f64));
        set("got", JsValue::from_f64(c.got as f64));
    }
    js
}

/// A binding error of a stated kind about `field`.
pub fn err_kind(kind: ErrorKind, field: &str, detail: impl std::fmt::Display) -> JsError {
    to_js(&Error::new(kind, field.to_string(), detail.to_string()))
}

/// [`ErrorKind::TooFew`] with its payload (`.expected` = the minimum, `.got`).
pub fn too_few(
    field: &str,
    expected: usize,
    got: usize,
    detail: impl std::fmt::Display,
) -> JsError {
    to_js(&Error::too_few_of(
        field.to_string(),
        expected,
        got,
        detail.to_string(),
    ))
}

/// [`ErrorKind::TooMany`] with its payload (`.expected` = the maximum, `.got`).
pub fn too_many(
    field: &str,
    expected: usize,
    got: usize,
    detail: impl std::fmt::Display,
) -> JsError {
    to_js(&Error::too_many_of(
        field.to_string(),
        expected,
        got,
        detail.to_string(),
    ))
}

/// The kind of a binding error from the house wording of its detail (see `docs/API.md`, "Errors"):
///
/// | wording | kind |
/// | --- | --- |
/// | "is required", "are required" | `missing` |
/// | "the function threw" | `invalid` |
/// | "expected a finite number" (with "\|α\| ≤": `out-of-range`) | `not-finite` |
/// | "need at least", "expected at least", "need 1 to" | `too-few` |
/// | "at most", "too many", "too long", "exceeds", "must stay below", "would be called", "overflows" | `too-many` |
/// | "must equal", "must all have", "same dimension", "do not fit", "mL + 1", "2D/3D points", "… rows", "… entries", "need (", "together with", "needs points", "need a grid", "planar" | `incompatible` |
/// | "wrong type", "expected a number/function/whole number/true or false/an array/a parameter pair/[x, y…", "the function must return" (with "≥ 0, got", "≥ 2", "between", "2..=": `out-of-range`) | `wrong-type` |
/// | "≥", "between", "in (0, 1)", "positive", "≤" | `out-of-range` |
/// | anything else (unknown names, choices) | `invalid` |
pub fn kind_of_detail(detail: &str) -> ErrorKind {
    let d = detail;
    let has = |p: &str| d.contains(p);
    if has("is required") || has("are required") {
        ErrorKind::Missing
    } else if has("threw") {
        ErrorKind::Invalid
    } else if d.starts_with("expected a finite number") {
        if has("|α| ≤") {
            ErrorKind::OutOfRange
        } else {
            ErrorKind::NotFinite
        }
    } else if has("at most")
        || has("too many")
        || has("too long")
        || has("exceeds")
        || has("must stay below")
        || has("would be called")
        || has("overflows")
    {
        ErrorKind::TooMany
    } else if has("need at least") || has("expected at least") || has("need 1 to") {
        ErrorKind::TooFew
    } else if has("must equal")
        || has("must all have")
        || has("same dimension")
        || has("do not fit")
        || has("needs mL + 1")
        || has("expected mL + 1")
        || has("D points")
        || has(" rows")
        || has(" entries")
        || has("need (")
        || has("together with")
        || has("needs points")
        || has("need a grid")
        || has("planar")
    {
        ErrorKind::SizeMismatch
    } else if has("wrong type")
        || has("the function must return")
        || d.starts_with("expected a number")
        || d.starts_with("expected a whole number")
        || d.starts_with("expected an ")
        || d.starts_with("expected a function")
        || d.starts_with("expected a parameter pair")
        || d.starts_with("expected a rectangular")
        || d.starts_with("expected one options object")
        || d.starts_with("expected true or false")
        || d.starts_with("expected [x, y")
    {
        if has("≥ 0, got") || has("≥ 2") || has("between") || has("2..=") {
            ErrorKind::OutOfRange
        } else {
            ErrorKind::WrongType
        }
    } else if has("≥") || has("≤") || has("between") || has("in (0, 1)") || has("positive") {
        ErrorKind::OutOfRange
    } else {
        ErrorKind::Invalid
    }
}
