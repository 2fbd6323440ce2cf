//! Noisy data and fits (seed 000, Figs. 1–3). Shapes (2D points, flat `Float64Array`s `[x0, y0, x1, …]`):
//!
//! * `fitNames()` → `{ curves: string[], datasets: string[] }`.
//! * `noisyData({ curve = "sine", count = 40, sigma = 0.1, seed = 1, truthSamples = 1001 })` →
//!   `{ curve, count, sigma, seed, params, clean, points, truth }`: samples of a known curve c(t), t ∈ [0, 1]
//!   at uniform t (`clean`), the same plus Gaussian noise σ (`points`; SplitMix64 + Box–Muller, so a seed
//!   always gives the same data), and a dense polyline of the curve (`truth`, `truthSamples` points).
//!   Curves: "sine", "arc", "lemniscate", "spiral", "step".
//! * `dataset({ name })` → `{ name, source, count, points }`: "titanium_heat" (de Boor, 49 points) or
//!   "rpn14" (Fritsch–Carlson, 9 points), embedded in the module (works offline).
//! * `b2Fit({ points, a, tension, autoTension, autoTensionScale, knots, K, c2, truth | truthCurve,
//!   errorSamples = 400, at | samples, derivatives, curvature })` → curve result + `{ domain, dataPoints,
//!   joints, jointParams, controlPoints, evenVertices, knots, tension, residuals, residualRms, rms?, max? }`
//!   (and `curvature`/`normals` as in `b2Curve`). `points` are the data
//!   D_1..D_N (N ≥ 3); the auxiliary end points are added by point reflection (`dataPoints` =
//!   W_{−1}..W_{N+2}). `residuals[i]` = |L^a(u′_{2i}) − D_i|. With `truth` (points `[[x, y], …]`, a dense
//!   polyline) or `truthCurve` (a curve name, sampled at 2001 points), `rms`/`max` are the RMS and maximum
//!   distance from `errorSamples` points of the fitted curve to the known curve.
//! * `b2FitSweep({ points, aValues | aMin = −0.1, aMax = 0.25, steps = 36, cv = true, truth | truthCurve,
//!   errorSamples = 400, …b2Curve options })` → `{ a, residualRms, rms?, max?, cv?, bestCvA?, bestA? }`:
//!   the error curve over `a`; `cv` = leave-one-out cross-validation score (mean squared prediction error
//!   of each interior point from a fit of the others — **not in the paper**); `bestCvA` its minimiser;
//!   `bestA` the minimiser of `rms` when a known curve is given.

use super::curve_result_curvature;
use super::readers::read_b2_options;
use super::{api_options, core_err, err_kind, ApiResult, Opts, Out, Pts};
use crate::b2spline;
use crate::error::ErrorKind;
use crate::fit::{self, KnownCurve, DATASET_NAMES};
use crate::sample::{Curve, MAX_INPUT_POINTS};
use glam::DVec2;
use wasm_bindgen::prelude::*;

const MAX_SWEEP: usize = 1000;

fn points2d(o: &Opts, key: &str, min: usize) -> ApiResult<Vec<DVec2>> {
    match o.points(key, min)? {
        Pts::D2(p) => Ok(p),
        Pts::D3(_) => Err(err_kind(
            ErrorKind::SizeMismatch,
            key,
            "expected 2D points [x, y]",
        )),
    }
}

/// A known curve by name (`name` when absent), the field named on failure.
fn known_curve(o: &Opts, key: &'static str, name: Option<&str>) -> ApiResult<Option<KnownCurve>> {
    let given: Option<String> = o.opt(key)?;
    let Some(name) = given.as_deref().or(name) else {
        return Ok(None);
    };
    KnownCurve::from_name(name)
        .map(Some)
        .map_err(|e| core_err(e.in_field(key)))
}

api_options! {
    /// The known curve a fit is measured against (`b2Fit`, `b2FitSweep`).
    pub struct B2FitMeasureOptions |o| {
        /// A dense polyline of the known curve.
        truth: Option<Vec<DVec2>> = "truth", opt "Points"
            => |k| if o.has(k) { Some(points2d(o, k, 1)?) } else { None };
        /// A known curve by name, sampled at 2001 points (read when `truth` is not given).
        truth_curve: Option<KnownCurve> = "truthCurve", opt "KnownCurveName"
            => |k| if truth.is_some() { None } else { known_curve(o, k, None)? };
        /// Default 400.
        error_samples: usize = "errorSamples", opt "number" => |k| o.usize_or(k, 400, 100_000)?;
    }
}

impl B2FitMeasureOptions {
    /// The known curve as a polyline: `truth`, or `truthCurve` sampled at 2001 points, or none.
    fn truth(&mut self) -> Option<Vec<DVec2>> {
        self.truth
            .take()
            .or_else(|| self.truth_curve.map(|c| c.polyline(2001)))
    }
}

/// Bounds the cost of the distance measure (fit samples × truth segments × fits).
fn check_error_work(truth: &Option<Vec<DVec2>>, samples: usize, fits: usize) -> ApiResult<()> {
    if let Some(t) = truth {
        if t.len().saturating_mul(samples).saturating_mul(fits) > 50_000_000 {
            return Err(err_kind(ErrorKind::TooMany,
                "errorSamples",
                format!("errorSamples × truth points × fits must stay below 5e7 (got {samples} × {} × {fits})", t.len()),
            ));
        }
    }
    Ok(())
}

fn read_seed(o: &Opts, key: &'static str) -> ApiResult<u64> {
    let s = o.f64_or(key, 1.0)?;
    if s < 0.0 || s.fract() != 0.0 || s > 9_007_199_254_740_991.0 {
        return Err(err_kind(
            ErrorKind::OutOfRange,
            key,
            "expected a whole number between 0 and 2⁵³ − 1",
        ));
    }
    Ok(s as u64)
}

#[wasm_bindgen(typescript_custom_section)]
const FIT_NAMES_TS: &str = r#"
export type KnownCurveName = 'sine' | 'arc' | 'lemniscate' | 'spiral' | 'step';
"#;

/// The known curves of noisyData and the data sets of dataset.
///
/// `fitNames()`: the known curves and data sets.
#[wasm_bindgen(js_name = fitNames, unchecked_return_type = "{ curves: string[]; datasets: string[] }")]
pub fn fit_names() -> JsValue {
    let curves: Vec<&str> = KnownCurve::ALL.iter().map(|c| c.name()).collect();
    Out::new()
        .ser("curves", &curves)
        .ser("datasets", &DATASET_NAMES[..])
        .build()
}

api_options! {
    /// Seeded noisy samples of a known curve (`noisyData`).
    pub struct NoisyDataOptions |o| {
        /// The known curve (default "sine").
        curve: Option<KnownCurve> = "curve", opt "KnownCurveName"
            => |k| known_curve(o, k, Some("sine"))?;
        /// The number of samples (default 40).
        count: usize = "count", opt "number" => |k| o.usize_or(k, 40, MAX_INPUT_POINTS)?;
        /// σ of the Gaussian noise (default 0.1).
        sigma: f64 = "sigma", opt "number" => |k| o.f64_or(k, 0.1)?;
        /// A whole number 0..2⁵³ − 1 (default 1): a seed always gives the same data.
        seed: u64 = "seed", opt "number" => |k| read_seed(o, k)?;
        /// The points of the dense polyline `truth` (default 1001, at least 2).
        truth_samples: usize = "truthSamples", opt "number" => |k| truth_samples(o, k)?;
    }
}

fn truth_samples(o: &Opts, key: &'static str) -> ApiResult<usize> {
    let ts = o.usize_or(key, 1001, MAX_INPUT_POINTS)?;
    if ts < 2 {
        return Err(err_kind(
            ErrorKind::TooFew,
            key,
            format!("need at least 2, got {ts}"),
        ));
    }
    Ok(ts)
}

#[wasm_bindgen(typescript_custom_section)]
const NOISY_DATA_TS: &str = r#"
export interface NoisyDataResult {
  curve: string;
  count: number;
  sigma: number;
  seed: number;
  params: Float64Array;
  clean: Float64Array;
  points: Float64Array;
  truth: Float64Array;
}
"#;

/// Seeded noisy samples of a known curve.
///
/// `noisyData(options)`: see the module docs.
#[wasm_bindgen(js_name = noisyData, unchecked_return_type = "NoisyDataResult")]
pub fn noisy_data(
    #[wasm_bindgen(unchecked_param_type = "NoisyDataOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let NoisyDataOptions {
        curve,
        count,
        sigma,
        seed,
        truth_samples,
    } = NoisyDataOptions::read(&o)?;
    let curve = curve.unwrap_or(KnownCurve::Sine);
    let d = fit::noisy_curve(curve, count, sigma, seed).map_err(core_err)?;
    Ok(Out::new()
        .set("curve", curve.name())
        .num("count", count as f64)
        .num("sigma", sigma)
        .num("seed", seed as f64)
        .f64s("params", &d.params)
        .pts("clean", &d.clean)
        .pts("points", &d.noisy)
        .pts("truth", &curve.polyline(truth_samples))
        .build())
}

api_options! {
    /// A classic data set (`dataset`).
    pub struct DatasetOptions |o| {
        /// "titanium_heat" (de Boor, 49 points) or "rpn14" (Fritsch–Carlson, 9 points).
        name: String = "name", req "'titanium_heat' | 'rpn14'" => |k| o.req(k)?;
    }
}

/// A classic data set, embedded in the module.
///
/// `dataset({ name })`: a classic data set.
#[wasm_bindgen(js_name = dataset, unchecked_return_type = "{ name: string; source: string; count: number; points: Float64Array }")]
pub fn dataset(
    #[wasm_bindgen(unchecked_param_type = "DatasetOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let DatasetOptions { name } = DatasetOptions::read(&o)?;
    let d = fit::dataset(&name).map_err(core_err)?;
    Ok(Out::new()
        .set("name", d.name)
        .set("source", d.source.as_str())
        .num("count", d.points.len() as f64)
        .pts("points", &d.points)
        .build())
}

#[wasm_bindgen(typescript_custom_section)]
const B2_FIT_TS: &str = r#"
export interface B2FitResult extends CurveResult {
  domain: Float64Array;
  knots: Float64Array;
  controlPoints: Float64Array;
  joints: Float64Array;
  evenVertices: Float64Array;
  tension: Float64Array;
  jointParams: Float64Array;
  curvature?: Float64Array;
  normals?: Float64Array;
  dataPoints: Float64Array;
  residuals: Float64Array;
  residualRms: number;
  rms?: number;
  max?: number;
}
"#;

api_options! {
    /// Options of `b2Fit`: the B2 curve of data D_1..D_N with reflected ends.
    pub struct B2FitOptions extends "B2Options, B2FitMeasureOptions, CurveSampling, FlatDim" |o| {
        /// 2D data D_1..D_N (N ≥ 3).
        points: Vec<DVec2> = "points", req "Points" => |k| points2d(o, k, 3)?;
        /// The shared B2 options (construction, K, a, tension, autoTension…, knots, c2).
        options: b2spline::B2Options = "construction", ext "B2Options" => |_k| read_b2_options(o)?;
        /// The known curve the fit is measured against (truth, truthCurve, errorSamples).
        measure: B2FitMeasureOptions = "truth", ext "B2FitMeasureOptions" => |_k| B2FitMeasureOptions::read(o)?;
        /// Adds `curvature` (and `normals`); read with the samples, after the fit.
        curvature: () = "curvature", opt "boolean" => |_k| ();
    }
}

/// The B2 curve of data with reflected ends, and its fit measures.
///
/// `b2Fit(options)`: the B2 curve of data with reflected ends, and its fit measures.
#[wasm_bindgen(js_name = b2Fit, unchecked_return_type = "B2FitResult")]
pub fn b2_fit(
    #[wasm_bindgen(unchecked_param_type = "B2FitOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let B2FitOptions {
        points: data,
        options: opts,
        mut measure,
        ..
    } = B2FitOptions::read(&o)?;
    let (truth, es) = (measure.truth(), measure.error_samples);
    check_error_work(&truth, es, 1)?;
    let c = fit::fit(&data, &opts).map_err(core_err)?;
    let order = o.derivatives(2)?;
    let params = o.curve_params(c.domain())?;
    let res = fit::residuals(&c);
    let (d0, d1) = c.domain();
    let mut out = curve_result_curvature(&c, &params, order, &o)?
        .f64s("domain", &[d0, d1])
        .pts("evenVertices", &c.even_vertices())
        .pts("dataPoints", c.data())
        .pts("joints", c.joints())
        .f64s("jointParams", &c.scheme().joint_params())
        .pts("controlPoints", c.control_points())
        .f64s("knots", c.knots())
        .f64s("tension", c.tension())
        .f64s("residuals", &res)
        .num("residualRms", fit::rms(&res));
    if let Some(t) = truth {
        let (r, m) = fit::curve_distance(&c, &t, es);
        out = out.num("rms", r).num("max", m);
    }
    Ok(out.build())
}

#[wasm_bindgen(typescript_custom_section)]
const B2_FIT_SWEEP_TS: &str = r#"
export interface B2FitSweepResult {
  a: Float64Array;
  residualRms: Float64Array;
  rms?: Float64Array;
  max?: Float64Array;
  cv?: Float64Array;
  bestCvA?: number;
  bestA?: number;
}
"#;

api_options! {
    /// Options of `b2FitSweep`: the fit measures over many values of a.
    pub struct B2FitSweepOptions extends "B2Options, B2FitMeasureOptions, FlatDim" |o| {
        /// 2D data D_1..D_N (N ≥ 3).
        points: Vec<DVec2> = "points", req "Points" => |k| points2d(o, k, 3)?;
        /// The shared B2 options (construction, K, a, tension, autoTension…, knots, c2).
        options: b2spline::B2Options = "construction", ext "B2Options" => |_k| read_b2_options(o)?;
        /// The known curve the fits are measured against (truth, truthCurve, errorSamples).
        measure: B2FitMeasureOptions = "truth", ext "B2FitMeasureOptions" => |_k| B2FitMeasureOptions::read(o)?;
        /// Leave-one-out cross-validation (default true).
        cv: bool = "cv", opt "boolean" => |k| o.bool_or(k, true)?;
        /// The values of a (1 to 1000); without them aMin..aMax in `steps` values.
        a_values: Option<Vec<f64>> = "aValues", opt "Numbers" => |k| o.f64s(k)?;
        /// Default −0.1 (read without aValues).
        a_min: Option<f64> = "aMin", opt "number"
            => |k| if a_values.is_none() { Some(o.f64_or(k, -0.1)?) } else { None };
        /// Default 0.25 (read without aValues).
        a_max: Option<f64> = "aMax", opt "number"
            => |k| if a_values.is_none() { Some(o.f64_or(k, 0.25)?) } else { None };
        /// Default 36 (read without aValues).
        steps: Option<usize> = "steps", opt "number"
            => |k| if a_values.is_none() { Some(o.usize_or(k, 36, MAX_SWEEP)?) } else { None };
    }
}

/// The fit measures over many values of a.
///
/// `b2FitSweep(options)`: the error curve over `a` and the cross-validated choice.
#[wasm_bindgen(js_name = b2FitSweep, unchecked_return_type = "B2FitSweepResult")]
pub fn b2_fit_sweep(
    #[wasm_bindgen(unchecked_param_type = "B2FitSweepOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let B2FitSweepOptions {
        points: data,
        options: opts,
        mut measure,
        cv: with_cv,
        a_values,
        a_min,
        a_max,
        steps,
    } = B2FitSweepOptions::read(&o)?;
    let (truth, es) = (measure.truth(), measure.error_samples);
    let a_values = match (a_values, a_min, a_max, steps) {
        (Some(v), ..) => v,
        (None, Some(lo), Some(hi), Some(steps)) => {
            if steps < 1 {
                return Err(err_kind(ErrorKind::TooFew, "steps", "need at least 1"));
            }
            if !(hi >= lo) {
                return Err(err_kind(ErrorKind::OutOfRange, "aMax", "must be ≥ aMin"));
            }
            crate::sample::uniform_params(lo, hi, steps)
        }
        // the reader gives aMin, aMax and steps whenever aValues is absent
        (None, ..) => Vec::new(),
    };
    if a_values.is_empty() || a_values.len() > MAX_SWEEP {
        return Err(err_kind(
            ErrorKind::TooFew,
            "aValues",
            format!("need 1 to {MAX_SWEEP} values of a, got {}", a_values.len()),
        ));
    }
    // cross-validation costs N fits per value of a: bound the work
    if with_cv
        && data
            .len()
            .saturating_mul(data.len())
            .saturating_mul(a_values.len())
            > 10_000_000
    {
        return Err(err_kind(
            ErrorKind::TooMany,
            "points",
            "too many points × values of a for cross-validation (set cv: false or use fewer)",
        ));
    }
    check_error_work(&truth, es, a_values.len())?;
    let rows =
        fit::sweep(&data, &opts, &a_values, truth.as_deref(), es, with_cv).map_err(core_err)?;
    let col = |f: fn(&fit::SweepRow) -> f64| rows.iter().map(f).collect::<Vec<f64>>();
    let argmin = |v: &[f64]| {
        v.iter()
            .enumerate()
            .filter(|(_, x)| x.is_finite())
            .fold((None, f64::INFINITY), |(bi, bs), (i, &x)| {
                if x < bs {
                    (Some(i), x)
                } else {
                    (bi, bs)
                }
            })
            .0
    };
    let mut out = Out::new()
        .f64s("a", &a_values)
        .f64s("residualRms", &col(|r| r.residual_rms));
    if truth.is_some() {
        let rms = col(|r| r.rms);
        if let Some(i) = argmin(&rms) {
            out = out.num("bestA", a_values[i]);
        }
        out = out.f64s("rms", &rms).f64s("max", &col(|r| r.max));
    }
    if with_cv {
        let cv = col(|r| r.cv);
        if let Some(i) = argmin(&cv) {
            out = out.num("bestCvA", a_values[i]);
        }
        out = out.f64s("cv", &cv);
    }
    Ok(out.build())
}
