//! Property-based fuzzing of the core's entry points (issue 9): for arbitrary finite input within the
//! documented limits a construction either returns an `Error` or a value whose evaluation is finite — it
//! never panics and never loops. Run with more cases: `PROPTEST_CASES=100000 cargo test --release --test fuzz_core`.
#![cfg(not(target_arch = "wasm32"))]

use glam::DVec2;
use proptest::prelude::*;
use splinelab::bspline::{interpolate_chord, BSplineCurve};
use splinelab::knots;
use splinelab::sample::Curve;

fn coord() -> impl Strategy<Value = f64> {
    prop_oneof![-10.0..10.0, -1e8..1e8, -1e-8..1e-8, Just(0.0), Just(1.0),]
}

fn points(max: usize) -> impl Strategy<Value = Vec<DVec2>> {
    prop::collection::vec(
        (coord(), coord()).prop_map(|(x, y)| DVec2::new(x, y)),
        0..max,
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    #[test]
    fn bspline_curve_never_panics(degree in 0usize..6, pts in points(12), raw in prop::collection::vec(-5.0..5.0f64, 0..20), at in prop::collection::vec(-10.0..10.0f64, 0..20)) {
        let mut k = raw.clone();
        k.sort_by(|a, b| a.partial_cmp(b).unwrap());
        // both the sorted and the raw knot vector
        for knots in [k, raw] {
            if let Ok(c) = BSplineCurve::new(degree, knots, pts.clone()) {
                let scale = pts.iter().map(|p| p.abs().max_element()).fold(1.0, f64::max);
                for &u in &at {
                    let mut o = [DVec2::ZERO; 3];
                    c.eval_derivs(u, 2, &mut o);
                    prop_assert!(o[0].is_finite());
                    // inside the domain the point is in the convex hull: bounded by the control points
                    let (a, b) = c.domain();
                    if u >= a && u <= b {
                        prop_assert!(o[0].abs().max_element() <= scale * (1.0 + 1e-9));
                    }
                }
                let mut buf = vec![0.0; 2 * 17];
                c.sample_uniform_into(17, &mut buf);
                prop_assert!(buf.iter().all(|x| x.is_finite()));
                if let Ok(r) = c.refine(&[c.domain().0 * 0.5 + c.domain().1 * 0.5]) {
                    let m = 0.5 * (c.domain().0 + c.domain().1);
                    prop_assert!((r.eval(m) - c.eval(m)).length() <= 1e-9 * scale);
                }
            }
        }
    }

    #[test]
    fn interpolation_never_panics(degree in 1usize..5, pts in points(10)) {
        if let Ok(c) = interpolate_chord(degree, &pts) {
            // the interpolant passes through its data (relative to the data's scale), or the system was
            // reported singular
            let t = knots::chord_length_params("points", &pts).unwrap();
            let scale = pts.iter().map(|p| p.abs().max_element()).fold(1.0, f64::max);
            for (ti, p) in t.iter().zip(&pts) {
                let e = c.eval(*ti);
                prop_assert!(e.is_finite());
                prop_assert!((e - *p).abs().max_element() <= 1e-6 * scale, "{e:?} vs {p:?}");
            }
        }
    }
}
