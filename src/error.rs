//! The one error type of the core.
//!
//! Every fallible construction returns `Result<T, Error>`. An [`Error`] names the offending input
//! (`field`, e.g. `"points"`, `"knots[3]"`, `"tension"`) and says what was expected, so the API layer can
//! hand it to JavaScript unchanged: its `Display` is `"<field>: <detail>"`.

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
    /// Two arrays whose lengths or dimensions must agree do not.
    SizeMismatch,
    /// A parameter outside its documented range (α ∉ [−3, 3], an index out of range, …).
    OutOfRange,
    /// Geometrically degenerate input (coincident points, zero-length spans, singular systems).
    Degenerate,
    /// Anything else that is not a valid input.
    Invalid,
}

/// An input error that names the bad field.
#[derive(Debug, Clone, PartialEq)]
pub struct Error {
    kind: ErrorKind,
    field: Cow<'static, str>,
    detail: String,
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
        }
    }
    pub fn too_few(field: impl Into<Cow<'static, str>>, detail: impl Into<String>) -> Self {
        Self::new(ErrorKind::TooFew, field, detail)
    }
    pub fn too_many(field: impl Into<Cow<'static, str>>, detail: impl Into<String>) -> Self {
        Self::new(ErrorKind::TooMany, field, detail)
    }
    pub fn not_finite(field: impl Into<Cow<'static, str>>, detail: impl Into<String>) -> Self {
        Self::new(ErrorKind::NotFinite, field, detail)
    }
    pub fn not_increasing(field: impl Into<Cow<'static, str>>, detail: impl Into<String>) -> Self {
        Self::new(ErrorKind::NotIncreasing, field, detail)
    }
    pub fn size_mismatch(field: impl Into<Cow<'static, str>>, detail: impl Into<String>) -> Self {
        Self::new(ErrorKind::SizeMismatch, field, detail)
    }
    pub fn out_of_range(field: impl Into<Cow<'static, str>>, detail: impl Into<String>) -> Self {
        Self::new(ErrorKind::OutOfRange, field, detail)
    }
    pub fn degenerate(field: impl Into<Cow<'static, str>>, detail: impl Into<String>) -> Self {
        Self::new(ErrorKind::Degenerate, field, detail)
    }
    pub fn invalid(field: impl Into<Cow<'static, str>>, detail: impl Into<String>) -> Self {
        Self::new(ErrorKind::Invalid, field, detail)
    }

    pub fn kind(&self) -> ErrorKind {
        self.kind
    }
    /// The offending input, e.g. `"knots"` or `"grid[2][5]"`.
    pub fn field(&self) -> &str {
        &self.field
    }
    pub fn detail(&self) -> &str {
        &self.detail
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
pub fn check_finite(field: &'static str, values: &[f64]) -> Result<()> {
    match values.iter().position(|v| !v.is_finite()) {
        None => Ok(()),
        Some(i) => Err(Error::not_finite(
            format!("{field}[{i}]"),
            format!("expected a finite number, got {}", values[i]),
        )),
    }
}

/// Checks that a scalar is finite.
pub fn check_finite_scalar(field: &'static str, value: f64) -> Result<()> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(Error::not_finite(
            field,
            format!("expected a finite number, got {value}"),
        ))
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
