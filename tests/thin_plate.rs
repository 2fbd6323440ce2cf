//! The thin-plate tensor-product surface T (`surfaces.md` §4, §10 item 17).

use glam::DVec3;
use splinelab::bspline::BSplineSurface;
use splinelab::criss_cross::CrissCrossSurface;
use splinelab::network::{examples, Network};
use splinelab::thin_plate::{energy_for_c11, thin_plate_energy, ThinPlateSurface};
use splinelab::{Point, Surface};

fn networks() -> Vec<(&'static str, Network)> {
    vec![
        ("uniform dome", examples::uniform_dome()),
        ("uniform random", examples::uniform_random()),
        ("non-uniform m4n5", examples::nonuniform_dome()),
        ("three-sided m5n3", examples::three_sided()),
        ("strongly non-uniform", examples::strongly_nonuniform()),
        ("separable", examples::separable()),
        ("free data m4n3", examples::free_data()),
    ]
}

#[test]
fn t_interpolates_the_network() {
    for (name, net) in networks() {
        let t = ThinPlateSurface::new(&net).unwrap();
        let scale = net.scale();
        let ((u0, u1), (v0, v1)) = t.domain();
        for k in 0..100 {
            let y = v0 + (v1 - v0) * k as f64 / 99.0;
            let x = u0 + (u1 - u0) * k as f64 / 99.0;
            for r in 0..=net.m() {
                let d = (t.eval(net.u[r], y) - net.phi(r, y)[0]).max_abs();
                assert!(
                    d <= 1e-13 * scale.max(1.0) * t.c11().max_abs().max(1.0),
                    "{name}: T(u_{r},{y}) off by {d}"
                );
            }
            for s in 0..=net.n() {
                let d = (t.eval(x, net.v[s]) - net.psi(s, x)[0]).max_abs();
                assert!(
                    d <= 1e-13 * scale.max(1.0) * t.c11().max_abs().max(1.0),
                    "{name}: T({x},v_{s}) off by {d}"
                );
            }
        }
    }
}

#[test]
fn c11_star_is_optimal_and_energy_is_reported() {
    for (name, net) in networks() {
        let t = ThinPlateSurface::new(&net).unwrap();
        let e0 = energy_for_c11(&net, t.c11()).unwrap();
        assert!(
            (e0 - t.energy()).abs() <= 1e-10 * e0.abs().max(1.0),
            "{name}: {e0} vs {}",
            t.energy()
        );
        for k in 0..3 {
            for sgn in [-1.0, 1.0] {
                let mut d = DVec3::ZERO;
                d[k] = sgn * 1e-3;
                let e = energy_for_c11(&net, t.c11() + d).unwrap();
                assert!(e > e0, "{name}: component {k} sign {sgn}: {e} ≤ {e0}");
            }
        }
        // C*_ij = Lemma 3.1 control points for C11*
        let s = CrissCrossSurface::new(&net).unwrap();
        let c = s.control_points(t.c11());
        for (a, b) in c.iter().zip(t.control_points()) {
            assert!((*a - *b).max_abs() <= 1e-12 * a.max_abs().max(1.0));
        }
    }
}

#[test]
fn separable_network_gives_c11_star_one_sixth() {
    let t = ThinPlateSurface::new(&examples::separable()).unwrap();
    assert!((t.c11().x - 1.0 / 6.0).abs() <= 1e-13, "{}", t.c11());
    assert!((t.c11().y - 1.0 / 6.0).abs() <= 1e-13, "{}", t.c11());
    // x = u, y = v exactly: T reproduces them
    for k in 0..20 {
        let (u, v) = (k as f64 / 19.0, (k * 7 % 19) as f64 / 19.0);
        let p = t.eval(u, v);
        assert!((p.x - u).abs() < 1e-14 && (p.y - v).abs() < 1e-14);
    }
}

#[test]
fn gauss_3x3_is_exact_per_cell() {
    // refining the knots leaves the surface unchanged; with an exact rule the energy is unchanged too
    for (name, net) in networks() {
        let t = ThinPlateSurface::new(&net).unwrap();
        let b: &BSplineSurface<DVec3> = t.bspline();
        let (u0, u1) = (b.knots_u()[2], b.knots_u()[b.knots_u().len() - 3]);
        let (v0, v1) = (b.knots_v()[2], b.knots_v()[b.knots_v().len() - 3]);
        let extra_u = [u0 + 0.137 * (u1 - u0), u0 + 0.61 * (u1 - u0)];
        let extra_v = [v0 + 0.29 * (v1 - v0), v0 + 0.83 * (v1 - v0)];
        let r = b.refine(&extra_u, &extra_v).unwrap();
        let (nu, nv) = b.size();
        let (ru, rv) = r.size();
        let e1 = thin_plate_energy(b.knots_u(), b.knots_v(), nu, nv, b.points());
        let e2 = thin_plate_energy(r.knots_u(), r.knots_v(), ru, rv, r.points());
        let scale = e1.max_abs().max(1e-300);
        assert!((e1 - e2).max_abs() <= 1e-11 * scale, "{name}: {e1} vs {e2}");
        assert!(
            (e1.element_sum() - t.energy()).abs() <= 1e-10 * scale,
            "{name}"
        );
    }
}

#[test]
fn t_differs_from_s_in_general_and_does_not_reproduce_p2() {
    let net = examples::uniform_random();
    let s = CrissCrossSurface::new(&net).unwrap();
    let t = ThinPlateSurface::new(&net).unwrap();
    let d = splinelab::sample::max_difference(&s, &t, 57);
    assert!(d > 1e-3, "‖S − T‖ = {d}");
}
