//! The B2 options shared by `b2Curve`, `b2Basis`, `b2Fit`, `b2FitSweep` and the `fitError` exercise check
//! (`construction`, `K`, `a`, `tension`, `autoTensionScale`, `autoTension`, `knots`, `c2`), and the knot choice
//! `b2Surface` reads for `knotsU` / `knotsV` the same way.

use super::read_tension;
use crate::api::{api_options, err_kind, ApiResult, Opts};
use crate::b2spline::{self, AutoTension, Construction, KnotChoice, Tension, DEFAULT_TENSION};
use crate::error::ErrorKind;
use js_sys::Array;

/// `autoTension`: absent, `null` or `false` is off; `true` or `"paper"` the paper's rule, `"turning"` the
/// turning-angle rule, both with the scale `scale` (`autoTensionScale`).
fn read_auto_tension(o: &Opts, key: &'static str, scale: f64) -> ApiResult<AutoTension> {
    let v = o.raw(key);
    if v.is_undefined() || v.is_null() || v.as_bool() == Some(false) {
        return Ok(AutoTension::Off);
    }
    if v.as_bool() == Some(true) {
        return Ok(AutoTension::Paper(scale));
    }
    if v.as_string().is_none() {
        let expected = "expected true, false, \"paper\" or \"turning\"";
        return Err(err_kind(ErrorKind::WrongType, key, expected));
    }
    let choices = [
        ("paper", AutoTension::Paper(scale)),
        ("turning", AutoTension::Turning(scale)),
    ];
    o.choice(key, choices, AutoTension::Off)
}

/// Reads a knot choice at `key` (`knots`, `knotsU`, `knotsV`): `"chord"` (also when absent or `null`),
/// `"uniform"`, or an array of knots (read as `Opts::f64s` reads it; the core checks them). Anything else is
/// `invalid`, naming the three forms.
pub fn read_knot_choice(o: &Opts, key: &str) -> ApiResult<KnotChoice> {
    let v = o.raw(key);
    if v.is_undefined() || v.is_null() {
        return Ok(KnotChoice::Chord);
    }
    if let Some(s) = v.as_string() {
        return match s.as_str() {
            "chord" => Ok(KnotChoice::Chord),
            "uniform" => Ok(KnotChoice::Uniform),
            _ => Err(err_kind(
                ErrorKind::Invalid,
                key,
                format!("expected \"chord\", \"uniform\" or an array of knots, got \"{s}\""),
            )),
        };
    }
    if Array::is_array(&v) {
        return Ok(KnotChoice::Explicit(o.f64s(key)?.unwrap_or_default()));
    }
    Err(err_kind(
        ErrorKind::Invalid,
        key,
        "expected \"chord\", \"uniform\" or an array of knots",
    ))
}

/// `construction`: `"nonuniform"` (also when absent) or `"section3"`.
fn read_construction(o: &Opts, key: &'static str) -> ApiResult<Construction> {
    let choices = [
        ("nonuniform", Construction::NonUniform),
        ("section3", Construction::Section3),
    ];
    o.choice(key, choices, Construction::NonUniform)
}

api_options! {
    /// The B2 options shared by b2Curve, b2Basis, b2Fit and b2FitSweep.
    pub struct B2Options |o| {
        /// "nonuniform" (default: the construction of section 4) or "section3" (the uniform one of section 3).
        construction: Construction = "construction", opt "'nonuniform' | 'section3'"
            => |key| read_construction(o, key)?;
        /// Modified knots u′_2i = (u_{i−1} + K u_i + u_{i+1}) / (K + 2); null = none.
        k: Option<f64> = "K", opt "number | null"
            => |key| if o.has(key) { Some(o.f64_or(key, 0.0)?) } else { None };
        /// The family parameter (0 interpolates, 1/6 is the cubic B-spline; default 0).
        a: f64 = "a", opt "number" => |key| o.f64_or(key, 0.0)?;
        /// Default 1/6.
        tension: Tension = "tension", opt "Tension" => |key| read_tension(o, key, DEFAULT_TENSION)?;
        /// The p of automatic tension (default 0.2).
        auto_tension_scale: f64 = "autoTensionScale", opt "number" => |key| o.f64_or(key, 0.2)?;
        /// false (default), "paper", "turning" (true = "paper").
        auto_tension: AutoTension = "autoTension", opt "boolean | 'paper' | 'turning'"
            => |key| read_auto_tension(o, key, auto_tension_scale)?;
        /// "chord" (default), "uniform" or u_{−1}..u_{n+2}.
        knots: KnotChoice = "knots", opt "'chord' | 'uniform' | Numbers" => |key| read_knot_choice(o, key)?;
        /// 1 (default, as printed) or 2; any number ≥ 0.
        c2: f64 = "c2", opt "number" => |key| o.f64_or(key, 1.0)?;
    }
}

/// Reads the shared B2 options ([`B2Options`], in its field order, so the first bad field is the one reported)
/// as the core takes them.
pub fn read_b2_options(o: &Opts) -> ApiResult<b2spline::B2Options> {
    let B2Options {
        construction,
        k,
        a,
        tension,
        auto_tension,
        knots,
        c2,
        ..
    } = B2Options::read(o)?;
    Ok(b2spline::B2Options {
        a,
        tension,
        auto_tension,
        knots,
        k,
        c2,
        construction,
    })
}
