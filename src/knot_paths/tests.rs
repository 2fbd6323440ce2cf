//! Unit tests of the private helpers.

use super::*;

#[test]
fn jets_differentiate() {
    // f(x) = x² / (1 + x) at x = 2: f = 4/3, f' = (2x(1+x) − x²)/(1+x)² = 8/9
    let x = Jet::<3>::variable(2.0);
    let f = x * x / (Jet::constant(1.0) + x);
    assert!((f.value() - 4.0 / 3.0).abs() < 1e-15);
    assert!((f.derivative(1) - 8.0 / 9.0).abs() < 1e-15);
    // f'' = 2/(1+x)³ = 2/27
    assert!((f.derivative(2) - 2.0 / 27.0).abs() < 1e-15);
}

#[test]
fn weights_partition_unity_even_when_extended() {
    let line = KnotLine::new(
        "k",
        "o",
        "p",
        4,
        vec![0., 0., 0., 0., 1., 2., 3., 4., 4., 4., 4.],
        7,
        Some(5),
    )
    .unwrap();
    let mut w = [0.0; W];
    for &up in &[1.5, 2.0, -7.0, 9.0] {
        for &u in &[0.3, 1.2, 1.9, 2.5, 3.7] {
            let i = line.span(u, up, false);
            line.weights(i, u, up, &mut w);
            let s: f64 = w[..4].iter().sum();
            assert!((s - 1.0).abs() < 1e-12, "up {up} u {u} sum {s}");
        }
    }
    assert_eq!(line.span(1.5, 9.0, false), 4);
    assert_eq!(line.span(2.5, -7.0, false), 5);
    assert_eq!(line.affected(), Some(((3, 6), (0.0, 4.0))));
}

#[test]
fn bad_knot_index_and_orders() {
    let k = vec![0., 0., 0., 1., 2., 2., 2.];
    assert_eq!(
        KnotLine::new("knots", "order", "p", 3, k.clone(), 4, Some(2))
            .unwrap_err()
            .field(),
        "p"
    );
    assert_eq!(
        KnotLine::new("knots", "order", "p", 3, k.clone(), 4, Some(4))
            .unwrap_err()
            .field(),
        "p"
    );
    assert!(KnotLine::new("knots", "order", "p", 3, k.clone(), 4, Some(3)).is_ok());
    assert_eq!(
        KnotLine::new("knots", "order", "p", 1, k.clone(), 6, None)
            .unwrap_err()
            .field(),
        "order"
    );
    let mut bad = k.clone();
    bad[3] = 5.0; // the moved one may be anywhere
    assert!(KnotLine::new("knots", "order", "p", 3, bad.clone(), 4, Some(3)).is_ok());
    assert_eq!(
        KnotLine::new("knots", "order", "p", 3, bad, 4, None)
            .unwrap_err()
            .field(),
        "knots[4]"
    );
}

#[test]
fn de_boor_triangle_ends_at_the_curve_point() {
    use glam::DVec2;
    let pts: Vec<DVec2> = (0..8)
        .map(|i| DVec2::new(i as f64, ((i * 7) % 5) as f64 * 0.6))
        .collect();
    let knots = vec![0., 0., 0., 0., 1., 2., 3., 4., 5., 5., 5., 5.];
    let c = KnotModifiedCurve::new(4, knots, pts, Some(5), 2.0).unwrap();
    for &up in &[1.3, 2.0, 2.9, -3.0, 7.5] {
        for &u in &[0.4, 1.1, 1.7, 2.2, 2.8, 4.6] {
            let t = c.de_boor(u, up);
            assert_eq!(t.steps.len(), 6);
            let last = t.steps.last().unwrap();
            assert_eq!(last.level, 3);
            let e = c.eval_at(u, up);
            assert!((last.point - e).length() < 1e-12, "up {up} u {u}");
        }
    }
    // u_5 moved to 2.9 (neighbours u_4 = 1, u_6 = 3): u = 2.2 < u_5 lies on span p − 1 = 4, and the first
    // point d_2^1 has α = (u − u_2)/(u_5 − u_2) with the moved knot
    let t = c.de_boor(2.2, 2.9);
    assert_eq!(t.span, 4);
    let s = t.steps[0];
    assert_eq!((s.level, s.index, s.knots), (1, 2, (2, 5)));
    assert!((s.alpha - (2.2 - 0.0) / (2.9 - 0.0)).abs() < 1e-15);
}
