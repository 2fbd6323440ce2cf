//! sin θ and cos θ on one quasi-cubic segment, θ = πt/2 with t ∈ [0, 1], by polynomials (no libm call).
//!
//! Every quasi-cubic segment is a combination of 1, t, sin πt, cos πt, sin θ and cos θ
//! ([`super::QuasiCubicCurve::segment_coefficients`]); sin πt = 2 sin θ cos θ and cos πt = cos²θ − sin²θ
//! follow from (sin θ, cos θ). On a segment θ ∈ [0, π/2], so no range reduction is needed: with
//! x = θ − π/4 ∈ [−π/4, π/4],
//!
//! sin θ = (cos x + sin x)/√2,  cos θ = (cos x − sin x)/√2,
//!
//! and sin x, cos x are their Taylor polynomials to x¹⁵ and x¹⁶. The first omitted terms are
//! |x|¹⁷/17! ≤ 4.6·10⁻¹⁷ and |x|¹⁸/18! ≤ 2·10⁻¹⁸ at |x| = π/4, so the error is the rounding of a few
//! operations (a few units in the last place; `tests/samplers.rs` checks ≤ 10⁻¹⁵ against libm).

use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2, FRAC_PI_4};

/// Taylor coefficients of sin x / x in x²: (−1)ᵏ/(2k + 1)!, k = 0..=7.
const SIN: [f64; 8] = [
    1.0,
    -1.0 / 6.0,
    1.0 / 120.0,
    -1.0 / 5040.0,
    1.0 / 362_880.0,
    -1.0 / 39_916_800.0,
    1.0 / 6_227_020_800.0,
    -1.0 / 1_307_674_368_000.0,
];

/// Taylor coefficients of cos x in x²: (−1)ᵏ/(2k)!, k = 0..=8.
const COS: [f64; 9] = [
    1.0,
    -1.0 / 2.0,
    1.0 / 24.0,
    -1.0 / 720.0,
    1.0 / 40_320.0,
    -1.0 / 3_628_800.0,
    1.0 / 479_001_600.0,
    -1.0 / 87_178_291_200.0,
    1.0 / 20_922_789_888_000.0,
];

/// `(sin θ, cos θ)` for θ = πt/2 with `t` ∈ [0, 1] (error ≤ 10⁻¹⁵; the module docs). Outside [0, 1]
/// (the extrapolated ends of an open curve) it falls back to libm's `sin_cos`.
#[inline(always)]
pub fn quarter_sin_cos(t: f64) -> (f64, f64) {
    if !(0.0..=1.0).contains(&t) {
        return (FRAC_PI_2 * t).sin_cos();
    }
    let x = FRAC_PI_2 * t - FRAC_PI_4;
    let x2 = x * x;
    let x4 = x2 * x2;
    let x8 = x4 * x4;
    // Estrin's scheme in x² (short dependency chains: the two polynomials and their halves overlap)
    let pair = |c: &[f64], k: usize| c[k] + c[k + 1] * x2;
    let s = (pair(&SIN, 0) + pair(&SIN, 2) * x4) + (pair(&SIN, 4) + pair(&SIN, 6) * x4) * x8;
    let s = s * x;
    let c = (pair(&COS, 0) + pair(&COS, 2) * x4)
        + (pair(&COS, 4) + pair(&COS, 6) * x4) * x8
        + COS[8] * (x8 * x8);
    ((c + s) * FRAC_1_SQRT_2, (c - s) * FRAC_1_SQRT_2)
}
