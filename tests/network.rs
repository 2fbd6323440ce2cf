//! Curve networks: partitions, compatibility (C2, eqs. (6)–(12)), builders, repair, bad input.

use glam::DVec3;
use splinelab::bspline::basis_all;
use splinelab::network::{
    examples, examples::Lcg, Condition, NetPoint, Network, Partition, COMPATIBILITY_TOL,
};
use splinelab::{ErrorKind, Point};

#[test]
fn partition_sigmas_and_bernstein_match_cox_de_boor() {
    let x = [0.0, 0.01, 0.5, 0.51, 0.75, 1.0];
    let p = Partition::new("u", &x).unwrap();
    let m = p.cells();
    assert_eq!(m, 5);
    assert_eq!(
        (p.sigma(1), p.sigma_p(1), p.sigma(m + 1), p.sigma_p(m + 1)),
        (1.0, 0.0, 0.0, 1.0)
    );
    assert_eq!(
        p.knots(),
        vec![0.0, 0.0, 0.0, 0.01, 0.5, 0.51, 0.75, 1.0, 1.0, 1.0]
    );
    assert_eq!(p.greville()[0], 0.0);
    assert!((p.greville()[3] - 0.505).abs() < 1e-15);
    assert_eq!(p.greville()[m + 1], 1.0);
    let k = p.knots();
    let mut row = [Vec::new(), Vec::new(), Vec::new()];
    for step in 0..=200 {
        let t = step as f64 / 200.0;
        basis_all(&k, 2, t, 1, &mut row);
        for i in 0..m + 2 {
            let [b, db] = p.basis(i, t);
            assert!((b - row[0][i]).abs() <= 1e-14, "B_{i}({t})");
            assert!(
                (db - row[1][i]).abs() <= 1e-12 * (1.0 + db.abs()),
                "B_{i}'({t}) {db} vs {}",
                row[1][i]
            );
        }
        // B_r(u_r) = σ_{r+1}, B_{r+1}(u_r) = σ'_{r+1}
    }
    for r in 0..=m {
        basis_all(&k, 2, x[r], 0, &mut row);
        assert!((row[0][r] - p.sigma(r + 1)).abs() < 1e-15);
        assert!((row[0][r + 1] - p.sigma_p(r + 1)).abs() < 1e-15);
    }
}

fn all_examples() -> Vec<(&'static str, Network)> {
    examples::NAMES
        .iter()
        .map(|n| (*n, examples::by_name(n).unwrap()))
        .collect()
}

#[test]
fn built_networks_are_compatible() {
    for (name, net) in all_examples() {
        let rep = net
            .check_compatible(COMPATIBILITY_TOL)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(rep.c2 <= 1e-14 * rep.scale.max(1.0), "{name}: {}", rep.c2);
        assert_eq!(rep.residuals.len(), net.m() + 1);
        assert_eq!(rep.residuals[0].len(), net.n() + 1);
    }
    // sin/cos example of surfaces.md §9
    let net = Network::from_function(&[0.0, 0.3, 0.5, 1.2], &[0.0, 0.4, 1.0, 1.5, 2.0], |u, v| {
        DVec3::new(u.sin(), v.cos(), u * v * v)
    })
    .unwrap();
    assert!(net.compatibility().unwrap().c2 <= 1e-15 * 8.0);
}

#[test]
fn incompatible_network_names_worst_residual_and_where() {
    let mut net = examples::nonuniform_dome();
    // perturb an interior curve control point P_2^{(2)}: affects φ_2 at v_1, v_2
    net.p[2][2] += DVec3::new(0.0, 0.0, 0.05);
    let rep = net.compatibility().unwrap();
    assert_eq!(rep.condition, Condition::Interior);
    assert!(
        rep.worst == (2, 1) || rep.worst == (2, 2),
        "{:?}",
        rep.worst
    );
    let e = net.check_compatible(COMPATIBILITY_TOL).unwrap_err();
    assert_eq!(e.field(), "network");
    let msg = e.to_string();
    assert!(
        msg.contains("C2")
            && msg.contains("(9)")
            && msg.contains(&format!("r = 2, s = {}", rep.worst.1)),
        "{msg}"
    );
    // the message names the worst residual but no longer prints it (issue 13, size: no float formatting)
    assert!(
        msg.contains("worst residual") && !msg.contains("e-"),
        "{msg}"
    );
    // boundary conditions (10), (11), (12)
    let mut net = examples::nonuniform_dome();
    net.q[0][2] += DVec3::X * 0.1;
    let rep = net.compatibility().unwrap();
    assert_eq!(rep.condition, Condition::UBoundary);
    assert!(net
        .check_compatible(COMPATIBILITY_TOL)
        .unwrap_err()
        .to_string()
        .contains("(10)"));
    let mut net = examples::nonuniform_dome();
    net.q[2][0] += DVec3::X * 0.1;
    assert_eq!(net.compatibility().unwrap().condition, Condition::VBoundary);
    assert_eq!(net.compatibility().unwrap().worst, (0, 2));
    let mut net = examples::nonuniform_dome();
    net.q[0][0] += DVec3::Y * 0.1;
    assert_eq!(net.compatibility().unwrap().condition, Condition::Corner);
    // a tiny perturbation within tolerance passes, slightly above fails
    let mut net = examples::uniform_dome();
    net.p[1][1] += DVec3::Z * 1e-14;
    assert!(net.check_compatible(COMPATIBILITY_TOL).is_ok());
    net.p[1][1] += DVec3::Z * 1e-10;
    assert!(net.check_compatible(COMPATIBILITY_TOL).is_err());
    assert!(splinelab::criss_cross::CrissCrossSurface::new(&net).is_err());
    assert!(splinelab::thin_plate::ThinPlateSurface::new(&net).is_err());
}

#[test]
fn wrong_shapes_and_bad_breakpoints_are_named() {
    let good = examples::uniform_dome();
    let mut n = good.clone();
    n.p.pop();
    let e = n.check_shape().unwrap_err();
    assert_eq!(
        (e.field(), e.kind()),
        ("network.P", ErrorKind::SizeMismatch)
    );
    let mut n = good.clone();
    n.q[2].pop();
    assert_eq!(n.check_shape().unwrap_err().field(), "network.Q[2]");
    let mut n = good.clone();
    n.u[2] = n.u[1];
    let e = n.check_shape().unwrap_err();
    assert_eq!(
        (e.field(), e.kind()),
        ("network.u[2]", ErrorKind::NotIncreasing)
    );
    let mut n = good.clone();
    n.v = vec![1.0, 0.5, 0.2, 0.0];
    assert_eq!(
        n.check_shape().unwrap_err().kind(),
        ErrorKind::NotIncreasing
    );
    let mut n = good.clone();
    n.p[1][2].x = f64::NAN;
    let e = n.check_shape().unwrap_err();
    assert_eq!(
        (e.field(), e.kind()),
        ("network.P[1][2]", ErrorKind::NotFinite)
    );
    let mut n = good.clone();
    n.u = vec![0.0];
    assert_eq!(n.check_shape().unwrap_err().kind(), ErrorKind::TooFew);
    assert!(n.compatibility().is_err());
    assert_eq!(
        Partition::new("u", &[0.0, 1.0, 1.0]).unwrap_err().kind(),
        ErrorKind::NotIncreasing
    );
    assert_eq!(
        Network::from_function(&[0.0, 1.0], &[0.0, f64::NAN], |u, v| DVec3::new(u, v, 0.0))
            .unwrap_err()
            .field(),
        "v[1]"
    );
    let e = Network::from_function(&[0.0, 1.0], &[0.0, 1.0], |u, _| {
        DVec3::new(1.0 / (u - 0.5), 0.0, 0.0)
    })
    .unwrap_err();
    assert_eq!(e.kind(), ErrorKind::NotFinite);
    let e = Network::from_control_net(&[0.0, 1.0], &[0.0, 1.0], &vec![vec![DVec3::ZERO; 3]; 2])
        .unwrap_err();
    assert_eq!(e.field(), "C");
}

#[test]
fn control_net_builder_gives_the_isocurves() {
    let u = [0.0, 0.2, 0.5, 0.7, 1.0];
    let v = [0.0, 0.3, 0.6, 1.0];
    let mut g = Lcg::new(1);
    let c: Vec<Vec<DVec3>> = (0..6)
        .map(|_| (0..5).map(|_| g.point()).collect())
        .collect();
    let net = Network::from_control_net(&u, &v, &c).unwrap();
    let ku = Partition::new("u", &u).unwrap().knots();
    let kv = Partition::new("v", &v).unwrap().knots();
    let mut bu = [Vec::new(), Vec::new(), Vec::new()];
    let mut bv = [Vec::new(), Vec::new(), Vec::new()];
    let tensor = |x: f64, y: f64, bu: &mut [Vec<f64>; 3], bv: &mut [Vec<f64>; 3]| {
        basis_all(&ku, 2, x, 0, bu);
        basis_all(&kv, 2, y, 0, bv);
        let mut s = DVec3::ZERO;
        for i in 0..6 {
            for j in 0..5 {
                s += c[i][j] * (bu[0][i] * bv[0][j]);
            }
        }
        s
    };
    for k in 0..=50 {
        let t = k as f64 / 50.0;
        for r in 0..=4 {
            let d = (net.phi(r, t)[0] - tensor(u[r], t, &mut bu, &mut bv)).max_abs();
            assert!(d < 1e-14, "φ_{r}({t})");
        }
        for s in 0..=3 {
            let d = (net.psi(s, t)[0] - tensor(t, v[s], &mut bu, &mut bv)).max_abs();
            assert!(d < 1e-14, "ψ_{s}({t})");
        }
    }
}

#[test]
fn free_data_keeps_p_and_q1_and_is_compatible() {
    let u = [0.0, 0.01, 0.5, 0.51, 0.75, 1.0];
    let v = [0.0, 0.3, 0.6, 1.0];
    let mut g = Lcg::new(8);
    let p: Vec<Vec<DVec3>> = (0..6)
        .map(|_| (0..5).map(|_| g.point()).collect())
        .collect();
    let q1: Vec<DVec3> = (0..4).map(|_| g.point()).collect();
    let net = Network::from_free_data(&u, &v, p.clone(), &q1).unwrap();
    assert_eq!(net.p, p);
    for s in 0..4 {
        assert_eq!(net.q[s][1], q1[s]);
    }
    let rep = net.check_compatible(COMPATIBILITY_TOL).unwrap();
    assert!(rep.c2 <= 1e-14 * rep.scale, "{}", rep.c2);
    assert_eq!(
        Network::from_free_data(&u, &v, p, &q1[..3])
            .unwrap_err()
            .field(),
        "Q1"
    );
}

#[test]
fn repair_after_edits_keeps_the_edited_point() {
    let base = examples::nonuniform_dome();
    let (m, n) = (base.m(), base.n());
    let edits = [
        NetPoint::P { r: 2, j: 3 },
        NetPoint::P { r: 0, j: 0 },
        NetPoint::Q { s: 2, i: 1 },
        NetPoint::Q { s: 2, i: 3 },
        NetPoint::Q { s: 1, i: m },
        NetPoint::Q { s: 3, i: 0 },
        NetPoint::Q { s: 0, i: m + 1 },
        NetPoint::Q { s: n, i: 0 },
    ];
    for e in edits {
        let mut net = base.clone();
        let target = DVec3::new(0.3, -0.2, 0.9);
        match e {
            NetPoint::P { r, j } => net.p[r][j] = target,
            NetPoint::Q { s, i } => net.q[s][i] = target,
        }
        assert!(net.check_compatible(COMPATIBILITY_TOL).is_err(), "{e:?}");
        let fixed = net.repair(Some(e)).unwrap();
        let rep = fixed
            .check_compatible(COMPATIBILITY_TOL)
            .unwrap_or_else(|err| panic!("{e:?}: {err}"));
        assert!(rep.c2 <= 1e-14 * rep.scale.max(1.0));
        let kept = match e {
            NetPoint::P { r, j } => fixed.p[r][j],
            NetPoint::Q { s, i } => fixed.q[s][i],
        };
        assert!(
            (kept - target).max_abs() <= 1e-15,
            "{e:?}: {kept} vs {target}"
        );
        // free points stay where they were unless the edit moved a boundary curve
        if let NetPoint::Q { i, .. } = e {
            if i != 0 && i != m + 1 {
                assert_eq!(fixed.p, base.p);
            }
        }
    }
    assert_eq!(
        base.repair(Some(NetPoint::P { r: 9, j: 0 }))
            .unwrap_err()
            .field(),
        "edited"
    );
    // repairing a compatible network changes nothing (to rounding)
    let again = base.repair(None).unwrap();
    for (a, b) in again.q.iter().flatten().zip(base.q.iter().flatten()) {
        assert!((*a - *b).max_abs() < 1e-14);
    }
}

#[test]
fn intersections_and_transpose() {
    let net = examples::strongly_nonuniform();
    let i = net.intersections().unwrap();
    for r in 0..=net.m() {
        for s in 0..=net.n() {
            assert!((i[r][s] - net.phi(r, net.v[s])[0]).max_abs() <= 1e-14 * net.scale());
            assert!((i[r][s] - net.psi(s, net.u[r])[0]).max_abs() <= 1e-14 * net.scale());
        }
    }
    let t = net.transposed();
    assert!(t.check_compatible(COMPATIBILITY_TOL).is_ok());
    assert_eq!(t.transposed(), net);
}

#[test]
fn absurd_sizes_are_rejected() {
    let many: Vec<f64> = (0..3000).map(|i| i as f64).collect();
    let e = Partition::new("u", &many).unwrap_err();
    assert_eq!((e.field(), e.kind()), ("u", ErrorKind::TooMany));
    let net = Network {
        u: many.clone(),
        v: vec![0.0, 1.0],
        p: vec![],
        q: vec![],
    };
    assert_eq!(net.check_shape().unwrap_err().kind(), ErrorKind::TooMany);
    assert!(Network::from_function(&many, &[0.0, 1.0], |u, v| DVec3::new(u, v, 0.0)).is_err());
}
