//! The API's `surfaceDifferences` checked against distances computed here from sampled points (the
//! surfaces as `networkSurfaces` samples them), not through the library's difference helper. The native
//! half of the independent checks is `tests/independent.rs`.
#![cfg(target_arch = "wasm32")]

mod wasm_util;
use wasm_util::*;

use splinelab::api::gordon::{network_surfaces, surface_differences};
use splinelab::api::network::network_example;
use wasm_bindgen_test::*;

/// max over the grid points and the coordinates of |a − b|.
fn distance(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    let mut d: f64 = 0.0;
    for k in 0..a.len() {
        d = d.max((a[k] - b[k]).abs());
    }
    d
}

#[wasm_bindgen_test]
fn surface_differences_match_distances_of_sampled_points() {
    for (name, samples) in [
        ("uniform-dome", 57),
        ("uniform-random", 57),
        ("nonuniform-dome", 23),
        ("three-sided", 57),
        ("free-data", 40),
    ] {
        let net = network_example(js(&format!(r#"{{"name":"{name}"}}"#))).unwrap();
        let o = js(&format!(r#"{{"samples":{samples}}}"#));
        set(&o, "network", &net);
        let d = surface_differences(o).unwrap();
        let o = js(&format!(
            r#"{{"samplesU":{samples},"samplesV":{samples},"surfaces":["S","T","G","GB"],"normSamples":0}}"#
        ));
        set(&o, "network", &net);
        let r = network_surfaces(o).unwrap();
        let pts = |k: &str| f64s(&get(&get(&r, "surfaces"), k), "points");
        let (s, t, g, gb) = (pts("S"), pts("T"), pts("G"), pts("GB"));
        assert_eq!(s.len(), 3 * samples * samples);
        for (key, a, b) in [
            ("SG", &s, &g),
            ("ST", &s, &t),
            ("TG", &t, &g),
            ("SGB", &s, &gb),
            ("GGB", &g, &gb),
        ] {
            let api = get(&d, key).as_f64().unwrap();
            let ind = distance(a, b);
            assert!(
                (api - ind).abs() <= 1e-13 * ind.max(1.0),
                "{name}: surfaceDifferences.{key} = {api}, sampled points give {ind}"
            );
        }
    }
}
