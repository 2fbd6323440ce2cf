//! Test curves shared by the quasi-cubic sampler tests (`tests/quasi_cubic_uniform.rs`, `tests/quasi_cubic_at.rs`).

use glam::{DVec2, DVec3};

/// The curve of `benches/engine.mjs` (`n` = 100): points on a wobbly spiral.
pub fn spiral(n: usize) -> Vec<DVec2> {
    (0..n)
        .map(|i| {
            let t = i as f64 * 0.15;
            DVec2::new(
                (1.0 + t) * t.cos() + 0.1 * (7.0 * t).sin(),
                (1.0 + t) * t.sin(),
            )
        })
        .collect()
}

/// `n` points on a rising helix.
pub fn helix(n: usize) -> Vec<DVec3> {
    (0..n)
        .map(|i| {
            let t = i as f64 * 0.3;
            DVec3::new(t.cos(), t.sin(), 0.2 * t * t)
        })
        .collect()
}
