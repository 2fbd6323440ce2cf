//! Unit tests of the B-spline kernel.

use super::*;
use glam::{DVec2, DVec3};

/// The cubic fast path uses forward differences re-anchored every 16 samples: with many samples per span
/// (where rounding would build up) it still agrees with de Boor evaluation to 1e-12 relative, in 2D and 3D,
/// on non-uniform knots with a double knot; every sample is written.
#[test]
fn forward_differences_stay_exact_over_long_runs() {
    let knots = vec![0.0, 0.0, 0.0, 0.0, 0.1, 0.35, 0.35, 0.8, 1.0, 1.0, 1.0, 1.0];
    let pts2: Vec<DVec2> = (0..8)
        .map(|i| {
            DVec2::new(
                (i as f64 * 0.7).cos() * 3.0,
                (i as f64 * 1.3).sin() * 5.0 + 100.0,
            )
        })
        .collect();
    let c2 = BSplineCurve::new(3, knots.clone(), pts2).unwrap();
    let pts3: Vec<DVec3> = (0..8)
        .map(|i| DVec3::new(i as f64, (i as f64).sqrt(), -(i as f64 * 0.4).sin()))
        .collect();
    let c3 = BSplineCurve::new(3, knots, pts3).unwrap();
    for count in [1usize, 2, 3, 17, 33, 1000, 100_003] {
        let params = crate::sample::uniform_params(0.0, 1.0, count);
        let mut out = vec![f64::NAN; 2 * count];
        c2.sample_uniform_into(count, &mut out);
        for (i, &u) in params.iter().enumerate() {
            let e = c2.de_boor(u);
            let f = DVec2::new(out[2 * i], out[2 * i + 1]);
            assert!(
                (e - f).length() <= 1e-12 * e.length(),
                "2D count {count} u {u}: {e} vs {f}"
            );
        }
        let mut out = vec![f64::NAN; 3 * count];
        c3.sample_uniform_into(count, &mut out);
        for (i, &u) in params.iter().enumerate() {
            let e = c3.de_boor(u);
            let f = DVec3::new(out[3 * i], out[3 * i + 1], out[3 * i + 2]);
            assert!(
                (e - f).length() <= 1e-12 * (1.0 + e.length()),
                "3D count {count} u {u}: {e} vs {f}"
            );
        }
    }
}
