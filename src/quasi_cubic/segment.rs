//! One quasi-cubic segment in closed form: its value and derivatives at a local parameter t₀.
//!
//! A segment is p(t) = K₀ + K₁t + K₂ sin πt + K₃ cos πt + K₄ sin θ + K₅ cos θ, θ = πt/2
//! ([`super::QuasiCubicCurve::segment_coefficients`]). With f = K₂ sin πt₀ + K₃ cos πt₀,
//! g = K₂ cos πt₀ − K₃ sin πt₀ and F, G the same for K₄, K₅ at θ₀,
//!
//! p⁽ʲ⁾(t₀) = πʲ·(f, g, −f, −g)[j mod 4] + (π/2)ʲ·(F, G, −F, −G)[j mod 4]  (+ K₀ + K₁t₀ at j = 0, + K₁ at j = 1),
//!
//! from one (sin θ₀, cos θ₀) by [`quarter_sin_cos`]. Used by the curve's samplers (a point's derivatives, the
//! uniform sampler's last sample) and by the runs of explicit parameters (their Taylor coefficients).

use super::trig::quarter_sin_cos;
use crate::point::Point;
use std::f64::consts::{FRAC_PI_2, PI};

/// How many derivatives p⁽⁰⁾..p⁽⁸⁾ [`derivatives_at`] can give: a run's Taylor polynomial of degree 6 and
/// up to its second derivative.
pub(super) const DERIVATIVES: usize = 9;

/// p⁽ʲ⁾(t₀), j < `count` (≤ [`DERIVATIVES`]), of the segment with coefficients `k` (the closed form of the
/// module docs; one [`quarter_sin_cos`]). The first `order` + 1 are a single point's value and derivatives.
/// Also the uniform sampler's last sample ([`super::QuasiCubicCurve::sample_uniform_blocks`]). Not inlined: its
/// callers share one copy (the wasm's size budget), and a call per run or lone parameter costs little.
#[inline(never)]
pub(super) fn derivatives_at<P: Point>(k: &[P; 6], t0: f64, count: usize) -> [P; DERIVATIVES] {
    let (s, c) = quarter_sin_cos(t0);
    let (s2, c2) = (2.0 * s * c, (c - s) * (c + s)); // sin πt₀, cos πt₀
    let (f, g) = (k[2] * s2 + k[3] * c2, k[2] * c2 - k[3] * s2);
    let (ff, gg) = (k[4] * s + k[5] * c, k[4] * c - k[5] * s);
    // the π terms cycle through (f, g, −f, −g)·πʲ, the π/2 terms through (F, G, −F, −G)·(π/2)ʲ
    let (full, half) = ([f, g, -f, -g], [ff, gg, -ff, -gg]);
    let mut der = [P::ZERO; DERIVATIVES];
    let (mut wp, mut wh) = (1.0, 1.0);
    for (j, d) in der.iter_mut().enumerate().take(count) {
        *d = full[j % 4] * wp + half[j % 4] * wh;
        wp *= PI;
        wh *= FRAC_PI_2;
    }
    der[0] = k[0] + k[1] * t0 + der[0];
    der[1] += k[1];
    der
}
