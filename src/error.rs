//! The one error type of the core.
//!
//! Every fallible construction returns `Result<T, Error>`. An [`Error`] names the offending input
//! (`field`, e.g. `"points"`, `"knots[3]"`, `"tension"`) and says what was expected, so the API layer can
//! hand it to JavaScript unchanged: its `Display` is `"<field>: <detail>"`.
//!
//! Its [`ErrorKind`] travels too: the API layer throws a JS `Error` whose `.field` is the field and whose
//! `.kind` is [`ErrorKind::as_str`] (a stable string such as `"too-few"`), so a page can react to the kind
//! of problem without parsing the message. Counting errors may carry a typed [`Counts`] payload
//! (`expected`, `got`), thrown as `.expected` / `.got`.

use std::borrow::Cow;
use std::fmt;

/// What kind of input problem an [`Error`] reports.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorKind {
    /// Too few points, knots, segments… for the construction.
    TooFew,
    /// More than a documented hard limit (points, samples, tessellation density).
    TooMany,
    /// A NaN or infinite number.
    NotFinite,
    /// Knots or breakpoints that decrease (or do not strictly increase where that is required).
    NotIncreasing,
    /// Inputs that must agree do not: two arrays whose lengths or dimensions must match, or the
    /// compatibility conditions of a curve network. Thrown to JavaScript as `"incompatible"`.
    SizeMismatch,
    /// A parameter outside its documented range (α ∉ [−3, 3], an index out of range, …).
    OutOfRange,
    /// Geometrically degenerate input (coincident points, zero-length spans, singular systems).
    Degenerate,
    /// Anything else that is not a valid input (an unknown name, a value none of the accepted ones).
    Invalid,
    /// A value of the wrong type (a string where a number is expected, an object where an array is…).
    /// Reported by the API layer, which reads untyped JavaScript values.
    WrongType,
    /// A required field is absent. Reported by the API layer.
    Missing,
}

impl ErrorKind {
    /// Every kind, in declaration order.
    pub const ALL: [ErrorKind; 10] = [
        ErrorKind::TooFew,
        ErrorKind::TooMany,
        ErrorKind::NotFinite,
        ErrorKind::NotIncreasing,
        ErrorKind::SizeMismatch,
        ErrorKind::OutOfRange,
        ErrorKind::Degenerate,
        ErrorKind::Invalid,
        ErrorKind::WrongType,
        ErrorKind::Missing,
    ];

    /// The stable name of the kind, as thrown to JavaScript in `error.kind` (documented in
    /// `docs/API.md`, "Errors"). These strings never change; new kinds may be added.
    ///
    /// ```
    /// use splinelab::ErrorKind;
    /// assert_eq!(ErrorKind::TooFew.as_str(), "too-few");
    /// assert_eq!(ErrorKind::SizeMismatch.as_str(), "incompatible");
    /// ```
    pub const fn as_str(self) -> &'static str {
        match self {
            ErrorKind::TooFew => "too-few",
            ErrorKind::TooMany => "too-many",
            ErrorKind::NotFinite => "not-finite",
            ErrorKind::NotIncreasing => "not-increasing",
            ErrorKind::SizeMismatch => "incompatible",
            ErrorKind::OutOfRange => "out-of-range",
            ErrorKind::Degenerate => "degenerate",
            ErrorKind::Invalid => "invalid",
            ErrorKind::WrongType => "wrong-type",
            ErrorKind::Missing => "missing",
        }
    }
}

impl fmt::Display for ErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// The typed payload of a counting error ([`ErrorKind::TooFew`], [`ErrorKind::TooMany`]): how many were
/// expected (the minimum, or the maximum) and how many came.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Counts {
    /// The bound: at least this many (too few) or at most this many (too many).
    pub expected: usize,
    /// How many were given.
    pub got: usize,
}

/// An input error that names the bad field.
#[derive(Debug, Clone, PartialEq)]
pub struct Error {
    kind: ErrorKind,
    field: Cow<'static, str>,
    detail: String,
    counts: Option<Counts>,
}

/// Shorthand for results of the core.
pub type Result<T, E = Error> = std::result::Result<T, E>;

impl Error {
    /// A new error of `kind` about `field`, with a human-readable `detail` (what was expected, what came).
    pub fn new(
        kind: ErrorKind,
        field: impl Into<Cow<'static, str>>,
        detail: impl Into<String>,
    ) -> Self {
        Error {
            kind,
            field: field.into(),
            detail: detail.into(),
            counts: None,
        }
    }
    /// [`ErrorKind::TooFew`] with its [`Counts`] payload: at least `expected`, `got` came.
    pub fn too_few_of(
        field: impl Into<Cow<'static, str>>,
        expected: usize,
        got: usize,
        detail: impl Into<String>,
    ) -> Self {
        Self::too_few(field, detail).with_counts(expected, got)
    }
    /// [`ErrorKind::TooMany`] with its [`Counts`] payload: at most `expected`, `got` came.
    pub fn too_many_of(
        field: impl Into<Cow<'static, str>>,
        expected: usize,
        got: usize,
        detail: impl Into<String>,
    ) -> Self {
        Self::too_many(field, detail).with_counts(expected, got)
    }
    /// Attaches a [`Counts`] payload.
    pub(crate) fn with_counts(mut self, expected: usize, got: usize) -> Self {
        self.counts = Some(Counts { expected, got });
        self
    }
    /// [`ErrorKind::TooFew`].
    pub fn too_few(field: impl Into<Cow<'static, str>>, detail: impl Into<String>) -> Self {
        Self::new(ErrorKind::TooFew, field, detail)
    }
    /// [`ErrorKind::TooMany`].
    pub fn too_many(field: impl Into<Cow<'static, str>>, detail: impl Into<String>) -> Self {
        Self::new(ErrorKind::TooMany, field, detail)
    }
    /// [`ErrorKind::NotFinite`].
    pub(crate) fn not_finite(
        field: impl Into<Cow<'static, str>>,
        detail: impl Into<String>,
    ) -> Self {
        Self::new(ErrorKind::NotFinite, field, detail)
    }
    /// [`ErrorKind::NotIncreasing`].
    pub(crate) fn not_increasing(
        field: impl Into<Cow<'static, str>>,
        detail: impl Into<String>,
    ) -> Self {
        Self::new(ErrorKind::NotIncreasing, field, detail)
    }
    /// [`ErrorKind::SizeMismatch`].
    pub(crate) fn size_mismatch(
        field: impl Into<Cow<'static, str>>,
        detail: impl Into<String>,
    ) -> Self {
        Self::new(ErrorKind::SizeMismatch, field, detail)
    }
    /// [`ErrorKind::OutOfRange`].
    pub(crate) fn out_of_range(
        field: impl Into<Cow<'static, str>>,
        detail: impl Into<String>,
    ) -> Self {
        Self::new(ErrorKind::OutOfRange, field, detail)
    }
    /// [`ErrorKind::Degenerate`].
    pub fn degenerate(field: impl Into<Cow<'static, str>>, detail: impl Into<String>) -> Self {
        Self::new(ErrorKind::Degenerate, field, detail)
    }
    /// [`ErrorKind::Invalid`].
    pub(crate) fn invalid(field: impl Into<Cow<'static, str>>, detail: impl Into<String>) -> Self {
        Self::new(ErrorKind::Invalid, field, detail)
    }
    /// [`ErrorKind::WrongType`].
    pub fn wrong_type(field: impl Into<Cow<'static, str>>, detail: impl Into<String>) -> Self {
        Self::new(ErrorKind::WrongType, field, detail)
    }
    /// [`ErrorKind::Missing`].
    pub fn missing(field: impl Into<Cow<'static, str>>, detail: impl Into<String>) -> Self {
        Self::new(ErrorKind::Missing, field, detail)
    }

    /// What kind of problem this is.
    pub fn kind(&self) -> ErrorKind {
        self.kind
    }
    /// The offending input, e.g. `"knots"` or `"grid[2][5]"`.
    pub fn field(&self) -> &str {
        &self.field
    }
    /// What was expected and what came (the message without the field).
    pub fn detail(&self) -> &str {
        &self.detail
    }
    /// The typed payload of a counting error, when the constructor knew the numbers.
    pub fn counts(&self) -> Option<Counts> {
        self.counts
    }
    /// Re-labels the field, e.g. to report a core error about `"points"` as `"network.P[3]"`.
    pub fn in_field(mut self, field: impl Into<Cow<'static, str>>) -> Self {
        self.field = field.into();
        self
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.field, self.detail)
    }
}

impl std::error::Error for Error {}

/// Checks that every number is finite; the error names `field[index]`.
pub(crate) fn check_finite(field: &'static str, values: &[f64]) -> Result<()> {
    match values.iter().position(|v| !v.is_finite()) {
        None => Ok(()),
        Some(i) => Err(Error::not_finite(
            format!("{field}[{i}]"),
            not_finite_detail(values[i]),
        )),
    }
}

/// The detail of a non-finite-number error: `"expected a finite number, got NaN"` (or `inf`, `-inf`), a
/// fixed string (formatting the float would link the float-to-decimal code into the wasm module).
pub fn not_finite_detail(x: f64) -> &'static str {
    if x.is_nan() {
        "expected a finite number, got NaN"
    } else if x.is_finite() {
        "expected a finite number"
    } else if x > 0.0 {
        "expected a finite number, got inf"
    } else {
        "expected a finite number, got -inf"
    }
}

/// Checks that a scalar is finite.
pub(crate) fn check_finite_scalar(field: &'static str, value: f64) -> Result<()> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(Error::not_finite(field, not_finite_detail(value)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn display_names_the_field() {
        let e = Error::too_few("points", "need at least 4 control points, got 3");
        assert_eq!(
            e.to_string(),
            "points: need at least 4 control points, got 3"
        );
        assert_eq!(e.kind(), ErrorKind::TooFew);
        assert_eq!(e.in_field("P[2]").field(), "P[2]");
        let e = Error::too_few_of("points", 4, 3, "need at least 4 control points, got 3");
        assert_eq!(
            e.counts(),
            Some(Counts {
                expected: 4,
                got: 3
            })
        );
        assert_eq!(e.kind(), ErrorKind::TooFew);
    }

    #[test]
    fn kind_names_are_stable_and_distinct() {
        let names: Vec<&str> = ErrorKind::ALL.iter().map(|k| k.as_str()).collect();
        assert_eq!(
            names,
            [
                "too-few",
                "too-many",
                "not-finite",
                "not-increasing",
                "incompatible",
                "out-of-range",
                "degenerate",
                "invalid",
                "wrong-type",
                "missing"
            ]
        );
    }

    #[test]
    fn finite_checks() {
        assert!(check_finite("x", &[1.0, 2.0]).is_ok());
        let e = check_finite("x", &[1.0, f64::NAN]).unwrap_err();
        assert_eq!(e.field(), "x[1]");
        assert_eq!(e.kind(), ErrorKind::NotFinite);
        assert!(check_finite_scalar("a", f64::INFINITY).is_err());
    }
}
