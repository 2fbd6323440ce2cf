//! Example networks (the test set of `surfaces.md` §2.4/§3 and the presets of the demos). All are
//! compatible up to rounding.

use super::Network;
use glam::DVec3;

pub use crate::rng::Lcg;

fn dome(u: f64, v: f64, (u0, u1): (f64, f64), (v0, v1): (f64, f64)) -> DVec3 {
    let x = (u - u0) / (u1 - u0) * 2.0 - 1.0;
    let y = (v - v0) / (v1 - v0) * 2.0 - 1.0;
    DVec3::new(u, v, 0.6 * (1.0 - 0.5 * (x * x + y * y)) + 0.1 * x * y * y)
}

fn from_dome(u: &[f64], v: &[f64]) -> Network {
    let du = (u[0], u[u.len() - 1]);
    let dv = (v[0], v[v.len() - 1]);
    Network::from_function(u, v, |a, b| dome(a, b, du, dv)).expect("valid example")
}

fn random_net(u: &[f64], v: &[f64], seed: u64) -> Network {
    let mut g = Lcg::new(seed);
    let c: Vec<Vec<DVec3>> = (0..u.len() + 1)
        .map(|_| (0..v.len() + 1).map(|_| g.point()).collect())
        .collect();
    Network::from_control_net(u, v, &c).expect("valid example")
}

/// The paper's m = n = 3 uniform grid on \[0,1\]² (U = V = {0,0,0,1/3,2/3,1,1,1}).
pub const UNIFORM3: [f64; 4] = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0];

/// Uniform m = n = 3, a dome sampled by the Schoenberg quasi-interpolant.
pub fn uniform_dome() -> Network {
    from_dome(&UNIFORM3, &UNIFORM3)
}
/// Uniform m = n = 3, a random control net's isocurves.
pub fn uniform_random() -> Network {
    random_net(&UNIFORM3, &UNIFORM3, 7)
}
/// Non-uniform m = 4, n = 5 dome.
pub fn nonuniform_dome() -> Network {
    from_dome(
        &[0.0, 0.1, 0.35, 0.6, 1.0],
        &[0.0, 0.15, 0.3, 0.55, 0.8, 1.0],
    )
}
/// §4.3: m = 5, n = 3 on \[0,5\]×\[0,3\] with all ψ_0 ≡ Q^{(0)} and ψ_3 ≡ Q^{(3)} (three-sided facets).
pub fn three_sided() -> Network {
    let u = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
    let v = [0.0, 1.0, 2.0, 3.0];
    let (bottom, top) = (DVec3::new(0.0, 0.0, 0.0), DVec3::new(0.0, 0.0, 3.0));
    let c: Vec<Vec<DVec3>> = (0..7)
        .map(|i| {
            let th = std::f64::consts::PI * i as f64 / 6.0;
            (0..5)
                .map(|j| match j {
                    0 => bottom,
                    4 => top,
                    _ => {
                        let r = [0.0, 1.2, 1.6, 1.2, 0.0][j];
                        DVec3::new(r * th.cos(), r * th.sin(), 0.75 * j as f64)
                    }
                })
                .collect()
        })
        .collect();
    Network::from_control_net(&u, &v, &c).expect("valid example")
}
/// Strongly non-uniform m = 5, n = 3 (h-ratio 50: u = 0, .01, .5, .51, .75, 1), random net.
pub fn strongly_nonuniform() -> Network {
    random_net(
        &[0.0, 0.01, 0.5, 0.51, 0.75, 1.0],
        &[0.0, 0.4, 0.45, 1.0],
        11,
    )
}
/// Separable network on the uniform m = n = 3 grid: x = u, y = v, z = a(u) + b(v) + c·uv (the class
/// where S = G, `surfaces.md` §5).
pub fn separable() -> Network {
    Network::from_function(&UNIFORM3, &UNIFORM3, |u, v| {
        DVec3::new(u, v, 0.8 * u * u - 0.5 * v * v + 0.7 * u * v + 0.2)
    })
    .expect("valid example")
}
/// Free data m = 4, n = 3: random P and Q_1, the other Q from C2.
pub fn free_data() -> Network {
    let u = [0.0, 0.2, 0.5, 0.7, 1.0];
    let v = [0.0, 0.3, 0.6, 1.0];
    let mut g = Lcg::new(3);
    let p: Vec<Vec<DVec3>> = (0..5)
        .map(|r| {
            (0..5)
                .map(|j| DVec3::new(u[r], j as f64 / 4.0, 0.0) + g.point() * 0.2)
                .collect()
        })
        .collect();
    let q1: Vec<DVec3> = (0..4)
        .map(|s| DVec3::new(0.1, v[s], 0.0) + g.point() * 0.2)
        .collect();
    Network::from_free_data(&u, &v, p, &q1).expect("valid example")
}
/// A 10 × 10 dome (m = n = 9 uniform on \[0,1\]²), for the speed target.
pub fn dome10() -> Network {
    let b: Vec<f64> = (0..10).map(|i| i as f64 / 9.0).collect();
    from_dome(&b, &b)
}

/// Names accepted by [`by_name`].
pub const NAMES: [&str; 8] = [
    "uniform-dome",
    "uniform-random",
    "nonuniform-dome",
    "three-sided",
    "strongly-nonuniform",
    "separable",
    "free-data",
    "dome10",
];

/// The example network called `name`.
pub fn by_name(name: &str) -> Option<Network> {
    Some(match name {
        "uniform-dome" => uniform_dome(),
        "uniform-random" => uniform_random(),
        "nonuniform-dome" => nonuniform_dome(),
        "three-sided" => three_sided(),
        "strongly-nonuniform" => strongly_nonuniform(),
        "separable" => separable(),
        "free-data" => free_data(),
        "dome10" => dome10(),
        _ => return None,
    })
}
