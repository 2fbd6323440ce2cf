//! Noisy data and the choice of the approximation parameter `a` (Kuklišová, Figs. 1–3: "the interpolation
//! highlights a possible noise; the approximation is more suitable for noisy data").
//!
//! * [`SplitMix64`]: a small seeded PRNG (Steele–Lea–Flood SplitMix64) with Box–Muller Gaussians, so a
//!   seed reproduces the same data on every platform.
//! * [`KnownCurve`] + [`noisy_curve`]: samples of a known planar curve at uniform parameters plus
//!   isotropic Gaussian noise of standard deviation σ.
//! * [`dataset`]: the classic data sets of `../shared/data/datasets.json` (Titanium heat, RPN 14), embedded
//!   in the binary (a copy lives in `src/data/`).
//! * [`fit`]: the B2 curve through/near data D_1..D_N, with the auxiliary end points added by
//!   [`reflect_ends`](crate::b2spline::reflect_ends()).
//! * Measures: [`residuals`] at the data (|L^a(u′_{2i}) − D_i|, zero at a = 0), [`curve_distance`]
//!   (RMS and max distance of the fitted curve to the known curve, sampled), [`sweep`] of `a` with the error
//!   curve, and [`loo_cv`] leave-one-out cross-validation to choose `a` — **not in the paper**: for each
//!   interior D_i, fit the other points, predict D_i at a chord-proportional parameter between its
//!   neighbours, and average the squared prediction errors.

use crate::b2spline::{reflect_ends, B2Curve, B2Options, KnotChoice};
use crate::error::{Error, Result};
use crate::sample::{uniform_params, Curve, MAX_INPUT_POINTS};
use glam::DVec2;

pub use crate::rng::SplitMix64;

/// Known planar curves c(t), t ∈ [0, 1], to generate test data from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KnownCurve {
    /// (4πt, 2 sin 4πt)/… : two periods of a sine wave, x ∈ [0, 10], amplitude 2.
    Sine,
    /// A circular arc of radius 4 over 270°.
    Arc,
    /// The lemniscate of Bernoulli (figure eight), half-width 5.
    Lemniscate,
    /// An Archimedean spiral, 1.5 turns.
    Spiral,
    /// The graph of a smooth step (logistic), x ∈ [0, 10] — shaped like the RPN 14 data.
    Step,
}

impl KnownCurve {
    /// Every known curve.
    pub const ALL: [KnownCurve; 5] = [
        KnownCurve::Sine,
        KnownCurve::Arc,
        KnownCurve::Lemniscate,
        KnownCurve::Spiral,
        KnownCurve::Step,
    ];

    /// The name used in the API (`"sine"`, `"arc"`, …).
    pub fn name(self) -> &'static str {
        match self {
            KnownCurve::Sine => "sine",
            KnownCurve::Arc => "arc",
            KnownCurve::Lemniscate => "lemniscate",
            KnownCurve::Spiral => "spiral",
            KnownCurve::Step => "step",
        }
    }

    /// Parses a name of [`KnownCurve::ALL`]; the error names `curve` and lists the choices.
    pub fn from_name(name: &str) -> Result<Self> {
        Self::ALL
            .into_iter()
            .find(|c| c.name() == name)
            .ok_or_else(|| {
                let names: Vec<&str> = Self::ALL.iter().map(|c| c.name()).collect();
                Error::invalid(
                    "curve",
                    format!(
                        "unknown curve \"{name}\"; expected one of {}",
                        names.join(", ")
                    ),
                )
            })
    }

    /// The point c(t).
    pub fn eval(self, t: f64) -> DVec2 {
        use std::f64::consts::PI;
        match self {
            KnownCurve::Sine => DVec2::new(10.0 * t, 2.0 * (4.0 * PI * t).sin()),
            KnownCurve::Arc => {
                let th = 1.5 * PI * t - 0.25 * PI;
                DVec2::new(4.0 * th.cos(), 4.0 * th.sin())
            }
            KnownCurve::Lemniscate => {
                let th = 2.0 * PI * t + 0.5 * PI;
                let d = 1.0 + th.sin().powi(2);
                DVec2::new(5.0 * th.cos() / d, 5.0 * th.sin() * th.cos() / d)
            }
            KnownCurve::Spiral => {
                let th = 3.0 * PI * t;
                let r = 1.0 + 1.2 * th;
                DVec2::new(r * th.cos(), r * th.sin())
            }
            KnownCurve::Step => {
                let x = 10.0 * t;
                DVec2::new(x, 4.0 / (1.0 + (-2.0 * (x - 5.0)).exp()))
            }
        }
    }

    /// A dense polyline of the curve (`count` points at uniform t).
    pub fn polyline(self, count: usize) -> Vec<DVec2> {
        uniform_params(0.0, 1.0, count)
            .into_iter()
            .map(|t| self.eval(t))
            .collect()
    }
}

/// Samples of a known curve, clean and with noise.
#[derive(Debug, Clone, PartialEq)]
pub struct NoisyData {
    /// The parameters t_k = k/(count − 1).
    pub params: Vec<f64>,
    /// c(t_k).
    pub clean: Vec<DVec2>,
    /// c(t_k) + σ·(g_x, g_y) with independent standard normal g.
    pub noisy: Vec<DVec2>,
}

/// `count` samples (3 ≤ count ≤ 100,000) of `curve` at uniform parameters plus Gaussian noise σ ≥ 0;
/// the same `seed` always gives the same data.
pub fn noisy_curve(curve: KnownCurve, count: usize, sigma: f64, seed: u64) -> Result<NoisyData> {
    if count < 3 {
        return Err(Error::too_few_of(
            "count",
            3,
            count,
            format!("need at least 3 points, got {count}"),
        ));
    }
    if count > MAX_INPUT_POINTS {
        return Err(Error::too_many_of(
            "count",
            MAX_INPUT_POINTS,
            count,
            format!("at most {MAX_INPUT_POINTS} points, got {count}"),
        ));
    }
    if !(sigma >= 0.0) || !sigma.is_finite() {
        return Err(Error::out_of_range("sigma", "expected a finite number ≥ 0"));
    }
    let mut rng = SplitMix64::new(seed);
    let params = uniform_params(0.0, 1.0, count);
    let clean: Vec<DVec2> = params.iter().map(|&t| curve.eval(t)).collect();
    let noisy = clean
        .iter()
        .map(|&p| p + DVec2::new(rng.gaussian(), rng.gaussian()) * sigma)
        .collect();
    Ok(NoisyData {
        params,
        clean,
        noisy,
    })
}

/// A classic data set.
#[derive(Debug, Clone, PartialEq)]
pub struct Dataset {
    /// The name used in the API.
    pub name: &'static str,
    /// Where the data come from (citation).
    pub source: String,
    /// The data points.
    pub points: Vec<DVec2>,
}

const DATASETS_JSON: &str = include_str!("data/datasets.json");

/// The names [`dataset`] accepts.
pub const DATASET_NAMES: [&str; 2] = ["titanium_heat", "rpn14"];

/// The classic data set `name` (`"titanium_heat"` — also `"titanium"` — or `"rpn14"`) as points (x, y).
pub fn dataset(name: &str) -> Result<Dataset> {
    let key: &'static str = match name {
        "titanium_heat" | "titanium" => "titanium_heat",
        "rpn14" | "RPN14" | "rpn_14" => "rpn14",
        _ => {
            return Err(Error::invalid(
                "name",
                format!(
                    "unknown data set \"{name}\"; expected one of {}",
                    DATASET_NAMES.join(", ")
                ),
            ))
        }
    };
    let broken = || {
        Error::invalid(
            "name",
            format!("the embedded data set \"{key}\" could not be read"),
        )
    };
    let body = json_object_body(DATASETS_JSON, key).ok_or_else(broken)?;
    let xs = json_number_array(body, "x").ok_or_else(broken)?;
    let ys = json_number_array(body, "y").ok_or_else(broken)?;
    let source = json_string(body, "source").unwrap_or_default();
    if xs.len() != ys.len() || xs.is_empty() {
        return Err(broken());
    }
    Ok(Dataset {
        name: key,
        source,
        points: xs
            .iter()
            .zip(&ys)
            .map(|(&x, &y)| DVec2::new(x, y))
            .collect(),
    })
}

/// The text after `"key": {` (good enough for the embedded, known file).
fn json_object_body<'a>(json: &'a str, key: &str) -> Option<&'a str> {
    let pat = format!("\"{key}\"");
    let at = json.find(&pat)? + pat.len();
    let rest = &json[at..];
    let open = rest.find('{')?;
    Some(&rest[open + 1..])
}

fn json_number_array(body: &str, key: &str) -> Option<Vec<f64>> {
    let pat = format!("\"{key}\"");
    let at = body.find(&pat)? + pat.len();
    let rest = &body[at..];
    let open = rest.find('[')?;
    let close = rest[open..].find(']')? + open;
    rest[open + 1..close]
        .split(',')
        .map(|s| s.trim().parse::<f64>().ok())
        .collect()
}

fn json_string(body: &str, key: &str) -> Option<String> {
    let pat = format!("\"{key}\"");
    let at = body.find(&pat)? + pat.len();
    let rest = &body[at..];
    let q1 = rest.find('"')? + 1;
    let q2 = rest[q1..].find('"')? + q1;
    Some(rest[q1..q2].to_string())
}

/// The B2 curve for data D_1..D_N (N ≥ 3): the auxiliary end points are added by reflection, so the curve
/// covers all the data. `opts` as for [`B2Curve::new`]; explicit knots must then have N + 4 entries.
pub fn fit(data: &[DVec2], opts: &B2Options) -> Result<B2Curve<DVec2>> {
    if let Some(i) = data.iter().position(|p| !p.is_finite()) {
        return Err(Error::not_finite(
            format!("points[{i}]"),
            "expected finite coordinates",
        ));
    }
    let w = reflect_ends(data)?;
    B2Curve::new(&w, opts).map_err(|e| shift_point_index(e, 2))
}

/// Re-labels `points[k]` (an index into the extended data) as `points[k − shift]` of the user's data.
fn shift_point_index(e: Error, shift: usize) -> Error {
    let idx = e
        .field()
        .strip_prefix("points[")
        .and_then(|r| r.strip_suffix(']'))
        .and_then(|r| r.parse::<usize>().ok());
    match idx {
        Some(k) => {
            let k = k.saturating_sub(shift);
            e.in_field(format!("points[{k}]"))
        }
        None => e,
    }
}

/// Residuals at the data: |L^a(u′_{2i}) − W_i| = |R_i − W_i| for i = 1..n (the joints of L^a against
/// the data they come from). All zero at a = 0.
pub fn residuals(curve: &B2Curve<DVec2>) -> Vec<f64> {
    curve
        .joints()
        .iter()
        .zip(&curve.data()[2..])
        .map(|(r, w)| r.distance(*w))
        .collect()
}

/// Root mean square of `xs` (0 for an empty slice).
pub fn rms(xs: &[f64]) -> f64 {
    if xs.is_empty() {
        0.0
    } else {
        (xs.iter().map(|x| x * x).sum::<f64>() / xs.len() as f64).sqrt()
    }
}

/// Distance from `p` to the polyline `poly`.
pub fn distance_to_polyline(p: DVec2, poly: &[DVec2]) -> f64 {
    if poly.len() == 1 {
        return p.distance(poly[0]);
    }
    let mut best = f64::INFINITY;
    for s in poly.windows(2) {
        let (a, b) = (s[0], s[1]);
        let ab = b - a;
        let l2 = ab.length_squared();
        let t = if l2 > 0.0 {
            ((p - a).dot(ab) / l2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        best = best.min(p.distance(a + ab * t));
    }
    best
}

/// The distance from `p` to segment `a`–`b`, computed exactly as [`distance_to_polyline`] does.
#[inline]
fn segment_distance(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let l2 = ab.length_squared();
    let t = if l2 > 0.0 {
        ((p - a).dot(ab) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p.distance(a + ab * t)
}

/// A uniform spatial grid over a polyline's segments, for nearest-distance queries that visit only the
/// cells near the query point instead of every segment. [`PolylineGrid::distance`] returns the same
/// number as [`distance_to_polyline`] (the minimum over a set of segments that contains the nearest one,
/// each distance computed by the same formula).
///
/// Every segment is registered in each cell its bounding box meets. A query scans square rings of cells
/// around the point's cell; after ring r every segment not yet seen lies outside the scanned block, at
/// distance ≥ r·h (h = cell size) from the point, so the scan stops once the best distance is below that.
#[derive(Debug, Clone)]
pub struct PolylineGrid<'a> {
    poly: &'a [DVec2],
    origin: DVec2,
    h: f64,
    nx: usize,
    ny: usize,
    /// `start[c]..start[c + 1]` indexes `items` for cell c = iy·nx + ix.
    start: Vec<u32>,
    items: Vec<u32>,
}

impl<'a> PolylineGrid<'a> {
    /// Builds the grid: about one cell per segment over the polyline's bounding box. `None` when the
    /// polyline has fewer than 2 points or no extent (then [`distance_to_polyline`] is as fast).
    pub fn new(poly: &'a [DVec2]) -> Option<Self> {
        if poly.len() < 2 || poly.len() > u32::MAX as usize {
            return None;
        }
        let (mut lo, mut hi) = (poly[0], poly[0]);
        for &p in poly {
            if !p.is_finite() {
                return None;
            }
            lo = lo.min(p);
            hi = hi.max(p);
        }
        let ext = hi - lo;
        let segs = (poly.len() - 1) as f64;
        let big = ext.x.max(ext.y);
        if big <= 0.0 {
            return None;
        }
        // cell size: area / segments per cell, but no thinner than the extent / segments
        let h = (ext.x * ext.y / segs)
            .sqrt()
            .max(big / segs)
            .max(big * 1e-9);
        let nx = ((ext.x / h).floor() as usize + 1).min(4096);
        let ny = ((ext.y / h).floor() as usize + 1).min(4096);
        let h = h.max(ext.x / nx as f64).max(ext.y / ny as f64) * (1.0 + 1e-12);
        let cell = |v: f64, n: usize| ((v / h).floor().max(0.0) as usize).min(n - 1);
        let ranges: Vec<(usize, usize, usize, usize)> = poly
            .windows(2)
            .map(|s| {
                let (a, b) = (s[0] - lo, s[1] - lo);
                (
                    cell(a.x.min(b.x), nx),
                    cell(a.x.max(b.x), nx),
                    cell(a.y.min(b.y), ny),
                    cell(a.y.max(b.y), ny),
                )
            })
            .collect();
        let mut count = vec![0u32; nx * ny + 1];
        for &(x0, x1, y0, y1) in &ranges {
            for iy in y0..=y1 {
                for ix in x0..=x1 {
                    count[iy * nx + ix + 1] += 1;
                }
            }
        }
        for c in 1..count.len() {
            count[c] += count[c - 1];
        }
        let mut fill = count.clone();
        let mut items = vec![0u32; count[nx * ny] as usize];
        for (k, &(x0, x1, y0, y1)) in ranges.iter().enumerate() {
            for iy in y0..=y1 {
                for ix in x0..=x1 {
                    let c = iy * nx + ix;
                    items[fill[c] as usize] = k as u32;
                    fill[c] += 1;
                }
            }
        }
        Some(PolylineGrid {
            poly,
            origin: lo,
            h,
            nx,
            ny,
            start: count,
            items,
        })
    }

    /// The distance from `p` to the polyline, equal to [`distance_to_polyline`]`(p, poly)`.
    pub fn distance(&self, p: DVec2) -> f64 {
        if !p.is_finite() {
            return distance_to_polyline(p, self.poly);
        }
        let q = (p - self.origin) / self.h;
        let (cx, cy) = (q.x.floor(), q.y.floor());
        let (nx, ny) = (self.nx as f64, self.ny as f64);
        // rings needed before the block covers the whole grid
        let last = (cx.max(nx - 1.0 - cx).max(cy).max(ny - 1.0 - cy)).max(0.0);
        // first ring that can meet the grid (Chebyshev distance from the cell to the grid)
        let first = (-cx)
            .max(cx - (nx - 1.0))
            .max(-cy)
            .max(cy - (ny - 1.0))
            .max(0.0);
        if last > 1e7 || first > 1e7 {
            return distance_to_polyline(p, self.poly);
        }
        let (cx, cy, first, last) = (cx as i64, cy as i64, first as i64, last as i64);
        let mut best = f64::INFINITY;
        let mut r = first;
        loop {
            let (y0, y1) = ((cy - r).max(0), (cy + r).min(self.ny as i64 - 1));
            for iy in y0..=y1 {
                let edge = iy == cy - r || iy == cy + r;
                let step = if edge { 1 } else { 2 * r.max(1) };
                // edge rows: only the columns inside the grid (a far point must not walk empty cells)
                let mut ix = if edge { (cx - r).max(0) } else { cx - r };
                let end = if edge {
                    (cx + r).min(self.nx as i64 - 1)
                } else {
                    cx + r
                };
                while ix <= end {
                    if (0..self.nx as i64).contains(&ix) {
                        let c = iy as usize * self.nx + ix as usize;
                        for &k in &self.items[self.start[c] as usize..self.start[c + 1] as usize] {
                            let k = k as usize;
                            best = best.min(segment_distance(p, self.poly[k], self.poly[k + 1]));
                        }
                    }
                    ix += step;
                }
            }
            // segments not yet seen lie outside the block of rings 0..=r: at distance ≥ r·h
            if r >= last || best < (r as f64) * self.h * (1.0 - 1e-12) {
                return best;
            }
            r += 1;
        }
    }
}

/// The distance of a fitted curve to a known curve given as a dense polyline: `(rms, max)` of the
/// distances from `samples` uniform points of the fitted curve's domain to the polyline. The points come
/// from the kernel's sampler, the distances from a [`PolylineGrid`] (the same numbers as
/// [`distance_to_polyline`] per point, without visiting every segment).
pub fn curve_distance<C: Curve<DVec2> + ?Sized>(
    fitted: &C,
    truth: &[DVec2],
    samples: usize,
) -> (f64, f64) {
    curve_distance_with(fitted, truth, PolylineGrid::new(truth).as_ref(), samples)
}

/// [`curve_distance`] with a prebuilt grid of `truth` (`None`: brute force over the segments).
pub fn curve_distance_with<C: Curve<DVec2> + ?Sized>(
    fitted: &C,
    truth: &[DVec2],
    grid: Option<&PolylineGrid<'_>>,
    samples: usize,
) -> (f64, f64) {
    if truth.is_empty() || samples == 0 {
        return (0.0, 0.0);
    }
    let (a, b) = fitted.domain();
    let params = uniform_params(a, b, samples);
    let (pts, _, _) = crate::sample::eval_curve(fitted, &params, 0);
    let d: Vec<f64> = pts
        .chunks_exact(2)
        .map(|c| {
            let p = DVec2::new(c[0], c[1]);
            match grid {
                Some(g) => g.distance(p),
                None => distance_to_polyline(p, truth),
            }
        })
        .collect();
    (rms(&d), d.iter().copied().fold(0.0, f64::max))
}

/// Leave-one-out cross-validation score of `a` (mean squared prediction error; **not in the paper**).
/// For each interior D_i (i = 2..N−1), the fit of the other N − 1 points is evaluated at the parameter
/// between the neighbours' parameters that divides them in the ratio of the chords |D_i − D_{i−1}| :
/// |D_{i+1} − D_i| (the midpoint for uniform knots), and compared with D_i. Needs N ≥ 4; explicit knots
/// are not supported (the knots of the reduced data are chosen by `opts.knots`).
pub fn loo_cv(data: &[DVec2], opts: &B2Options, a: f64) -> Result<f64> {
    let m = data.len();
    if m < 4 {
        return Err(Error::too_few_of(
            "points",
            4,
            m,
            format!("cross-validation needs at least 4 data points, got {m}"),
        ));
    }
    if matches!(opts.knots, KnotChoice::Explicit(_)) {
        return Err(Error::invalid(
            "knots",
            "cross-validation chooses knots for the reduced data: use \"chord\" or \"uniform\"",
        ));
    }
    let o = B2Options { a, ..opts.clone() };
    let mut reduced = Vec::with_capacity(m - 1);
    let mut sum = 0.0;
    for i in 1..m - 1 {
        reduced.clear();
        reduced.extend(
            data.iter()
                .enumerate()
                .filter(|&(k, _)| k != i)
                .map(|(_, p)| *p),
        );
        let c = fit(&reduced, &o)?;
        // in the reduced data the neighbours are D_{i−1} → index i − 1, D_{i+1} → index i; their
        // joints sit at joint_params[i − 1], joint_params[i]
        let jp = c.scheme().joint_params();
        let (u0, u1) = (jp[i - 1], jp[i]);
        let s = match opts.knots {
            KnotChoice::Uniform => 0.5,
            _ => {
                let (l0, l1) = (data[i].distance(data[i - 1]), data[i + 1].distance(data[i]));
                if l0 + l1 > 0.0 {
                    l0 / (l0 + l1)
                } else {
                    0.5
                }
            }
        };
        let p = c.eval(u0 + s * (u1 - u0));
        sum += p.distance_squared(data[i]);
    }
    Ok(sum / (m - 2) as f64)
}

/// One row of a sweep of `a`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepRow {
    /// The approximation parameter a of this row.
    pub a: f64,
    /// RMS of the residuals at the data.
    pub residual_rms: f64,
    /// RMS and max distance to the known curve (NaN without one).
    pub rms: f64,
    /// Max distance to the known curve (NaN without one).
    pub max: f64,
    /// Leave-one-out score (NaN when not asked for).
    pub cv: f64,
}

/// The error curve: for each `a` in `a_values`, the residuals, the distance to `truth` (a dense polyline
/// of the known curve, if any, with `samples` points of the fit) and optionally the cross-validation score.
pub fn sweep(
    data: &[DVec2],
    opts: &B2Options,
    a_values: &[f64],
    truth: Option<&[DVec2]>,
    samples: usize,
    with_cv: bool,
) -> Result<Vec<SweepRow>> {
    let mut rows = Vec::with_capacity(a_values.len());
    let grid = truth.and_then(PolylineGrid::new);
    for (k, &a) in a_values.iter().enumerate() {
        if !a.is_finite() {
            return Err(Error::not_finite(
                format!("aValues[{k}]"),
                crate::error::not_finite_detail(a),
            ));
        }
        let c = fit(data, &B2Options { a, ..opts.clone() })?;
        let (rms_t, max_t) = match truth {
            Some(t) => curve_distance_with(&c, t, grid.as_ref(), samples),
            None => (f64::NAN, f64::NAN),
        };
        let cv = if with_cv {
            loo_cv(data, opts, a)?
        } else {
            f64::NAN
        };
        rows.push(SweepRow {
            a,
            residual_rms: rms(&residuals(&c)),
            rms: rms_t,
            max: max_t,
            cv,
        });
    }
    Ok(rows)
}

/// The `a` of `a_values` with the smallest leave-one-out score, and all scores.
pub fn choose_a_cv(data: &[DVec2], opts: &B2Options, a_values: &[f64]) -> Result<(f64, Vec<f64>)> {
    if a_values.is_empty() {
        return Err(Error::too_few(
            "aValues",
            "need at least one candidate value of a",
        ));
    }
    let scores = a_values
        .iter()
        .map(|&a| loo_cv(data, opts, a))
        .collect::<Result<Vec<f64>>>()?;
    let best = scores
        .iter()
        .enumerate()
        .fold(
            (0, f64::INFINITY),
            |(bi, bs), (i, &s)| if s < bs { (i, s) } else { (bi, bs) },
        )
        .0;
    Ok((a_values[best], scores))
}
