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
