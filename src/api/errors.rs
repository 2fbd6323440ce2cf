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
//! Core errors carry their kind from where they are made; the binding's own input checks state theirs
//! at the check with [`err_kind`] (or [`too_few`] / [`too_many`] with their counts). Nothing infers a kind
//! from the wording of a message. Every export's bad input, with its `.field` and `.kind`, is pinned by
//! `tests/node/errors.test.mjs`.

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

/// Result type of every export.
pub type ApiResult<T> = Result<T, JsError>;

/// Converts a core error (its `Display` already names the field; its kind becomes `.kind`).
pub fn core_err(e: Error) -> JsError {
    to_js(&e)
}
