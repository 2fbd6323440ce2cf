//! The quasi-cubic trigonometric α-basis (the quasi-cubic paper, Eq. (1), reconstructed in `curves.md` §1).
//!
//! With θ = πt/2,
//! B(α; t) = (1 − α)·B⁰(t) + α·B¹(t), where
//! * B⁰ = [(1−t)/4 − σ, 1/2 − t/4 + σ, 1/4 + t/4 + σ, t/4 − σ], σ = sin(πt)/(4π), and
//! * B¹ = [(1 − sin θ)²/6, (1 + cos θ)²/6, (1 + sin θ)²/6, (1 − cos θ)²/6].
//!
//! The functions sum to 1, are symmetric (B_i(t) = B_{3−i}(1 − t)), and are non-negative exactly for
//! α ∈ [−3, 1]. At α = 3 they interpolate (B(0) = e₁, Eq. (11)). This module allows α ∈ [−3, 3].
//!
//! Expanding B¹ with sin²θ = (1 − cos πt)/2 gives
//! B¹ = [3/2 − 2 sin θ − (cos πt)/2, 3/2 + 2 cos θ + (cos πt)/2, 3/2 + 2 sin θ − (cos πt)/2,
//! 3/2 − 2 cos θ + (cos πt)/2] / 6, which is what is differentiated below (any order, in closed form).

use crate::error::{Error, Result};
use std::f64::consts::PI;

/// Smallest allowed shape parameter α.
pub(crate) const ALPHA_MIN: f64 = -3.0;
/// Largest allowed shape parameter α (α = 3 is the interpolation spline of Eq. (11)).
pub(crate) const ALPHA_MAX: f64 = 3.0;

/// Checks α ∈ [−3, 3] (finite); the error names `field`.
pub fn check_alpha(field: &'static str, alpha: f64) -> Result<()> {
    if !alpha.is_finite() {
        return Err(Error::not_finite(
            field,
            crate::error::not_finite_detail(alpha),
        ));
    }
    if !(ALPHA_MIN..=ALPHA_MAX).contains(&alpha) {
        return Err(Error::out_of_range(
            field,
            "α must lie in [−3, 3] (non-negative basis on [−3, 1], interpolation at 3)",
        ));
    }
    Ok(())
}

/// k-th derivative of sin(w·t) (k ≥ 0).
#[inline]
fn dsin(w: f64, t: f64, k: usize) -> f64 {
    let s = w.powi(k as i32);
    match k % 4 {
        0 => s * (w * t).sin(),
        1 => s * (w * t).cos(),
        2 => -s * (w * t).sin(),
        _ => -s * (w * t).cos(),
    }
}

/// k-th derivative of cos(w·t) (k ≥ 0).
#[inline]
fn dcos(w: f64, t: f64, k: usize) -> f64 {
    let s = w.powi(k as i32);
    match k % 4 {
        0 => s * (w * t).cos(),
        1 => -s * (w * t).sin(),
        2 => -s * (w * t).cos(),
        _ => s * (w * t).sin(),
    }
}

/// The k-th derivative in t of the four functions B_0..B_3 at shape parameter `alpha`.
///
/// `alpha` is not checked here (callers validate it once with [`check_alpha`]); any finite `t` works
/// (values outside [0, 1] continue the trigonometric formulas).
pub fn basis_deriv(alpha: f64, t: f64, k: usize) -> [f64; 4] {
    // B⁰ pieces: linear part and σ = sin(πt)/(4π)
    let sig = dsin(PI, t, k) / (4.0 * PI);
    let (lin_a, lin_b) = match k {
        0 => ((1.0 - t) / 4.0, t / 4.0),
        1 => (-0.25, 0.25),
        _ => (0.0, 0.0),
    };
    let (c0, c1) = match k {
        0 => (0.5 - t / 4.0, 0.25 + t / 4.0),
        1 => (-0.25, 0.25),
        _ => (0.0, 0.0),
    };
    let b0 = [lin_a - sig, c0 + sig, c1 + sig, lin_b - sig];
    // B¹ pieces
    let h = PI / 2.0;
    let st = dsin(h, t, k);
    let ct = dcos(h, t, k);
    let cp = dcos(PI, t, k);
    let k0 = if k == 0 { 1.5 } else { 0.0 };
    let b1 = [
        (k0 - 2.0 * st - 0.5 * cp) / 6.0,
        (k0 + 2.0 * ct + 0.5 * cp) / 6.0,
        (k0 + 2.0 * st - 0.5 * cp) / 6.0,
        (k0 - 2.0 * ct + 0.5 * cp) / 6.0,
    ];
    let mut out = [0.0; 4];
    for i in 0..4 {
        out[i] = (1.0 - alpha) * b0[i] + alpha * b1[i];
    }
    out
}

/// Values and derivatives up to `order` (≤ 3): `out[k]` = (d/dt)^k [B_0, B_1, B_2, B_3] at `t`.
pub fn basis_derivs(alpha: f64, t: f64, order: usize, out: &mut [[f64; 4]; 4]) {
    for (k, row) in out.iter_mut().enumerate().take(order.min(3) + 1) {
        *row = basis_deriv(alpha, t, k);
    }
}

/// The four basis values at `t`.
pub fn basis(alpha: f64, t: f64) -> [f64; 4] {
    basis_deriv(alpha, t, 0)
}

/// The end-value constants of Prop. 3 (`curves.md` §1.1): l1 = (3−α)/12, l2 = (3+α)/6,
/// l3 = απ/6 + (1−α)/2, l4 = απ²/12, with B(0) = [l1, l2, l1, 0], B′(0) = [−l3, 0, l3, 0] and
/// B″(0) = [l4, −2l4, l4, 0].
pub fn end_constants(alpha: f64) -> [f64; 4] {
    [
        (3.0 - alpha) / 12.0,
        (3.0 + alpha) / 6.0,
        alpha * PI / 6.0 + (1.0 - alpha) / 2.0,
        alpha * PI * PI / 12.0,
    ]
}

/// The allocated function of order k (the quasi-cubic paper Eq. (13)): s(t) = Σ_{j=k}^{2k−1} C(2k−1, j) t^j (1−t)^{2k−1−j},
/// with s(0) = 0, s(1) = 1 and s^{(l)}(0) = s^{(l)}(1) = 0 for 1 ≤ l < k (Eq. (14)). Returns
/// `[s, s′, s″, s‴]` at `t`. Uses s′ = c_k t^{k−1}(1−t)^{k−1}, c_k = (2k−1)!/((k−1)!)².
pub fn allocated(k: usize, t: f64) -> [f64; 4] {
    let n = 2 * k - 1;
    let mut s = 0.0;
    let mut binom = 1.0; // C(n, j), built up from j = 0
    for j in 0..=n {
        if j >= k {
            s += binom * t.powi(j as i32) * (1.0 - t).powi((n - j) as i32);
        }
        binom = binom * (n - j) as f64 / (j + 1) as f64;
    }
    // c_k = n · C(n − 1, k − 1)
    let mut c = n as f64;
    for j in 0..(k - 1) {
        c = c * (n - 1 - j) as f64 / (j + 1) as f64;
    }
    // g(t) = t^m (1−t)^m with m = k − 1, and its derivatives via the product rule.
    let m = (k - 1) as i32;
    let pw = |base: f64, e: i32, d: usize| -> f64 {
        // d-th derivative of base^e with d(base)/dt = ±1 handled by the caller
        let mut coef = 1.0;
        for i in 0..d as i32 {
            coef *= (e - i) as f64;
        }
        if coef == 0.0 {
            0.0
        } else {
            coef * base.powi(e - d as i32)
        }
    };
    let g = |d: usize| -> f64 {
        // Σ C(d, r) (t^m)^{(r)} ((1−t)^m)^{(d−r)}, the second factor's derivatives carry (−1)^{d−r}
        let mut acc = 0.0;
        let mut bin = 1.0;
        for r in 0..=d {
            let sign = if (d - r).is_multiple_of(2) { 1.0 } else { -1.0 };
            acc += bin * pw(t, m, r) * sign * pw(1.0 - t, m, d - r);
            bin = bin * (d - r) as f64 / (r + 1) as f64;
        }
        acc
    };
    [s, c * g(0), c * g(1), c * g(2)]
}

/// Largest supported order of the allocated function.
pub(crate) const MAX_ALLOCATED_ORDER: usize = 10;

/// Checks the order k of the allocated function: 2 ≤ k ≤ 10 (k = 2 is C¹ only, see [`super::bis`]).
pub(crate) fn check_order(field: &'static str, k: usize) -> Result<()> {
    if (2..=MAX_ALLOCATED_ORDER).contains(&k) {
        Ok(())
    } else {
        Err(Error::out_of_range(
            field,
            format!("the allocated function's order k must be 2..={MAX_ALLOCATED_ORDER} (3 or more for C²), got {k}"),
        ))
    }
}
