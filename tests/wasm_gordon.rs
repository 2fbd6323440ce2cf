//! wasm-bindgen tests of `gordonSurface`, `splineBlendedSurface`, `networkSurfaces`, `surfaceDifferences`.
#![cfg(target_arch = "wasm32")]

mod wasm_util;
use wasm_util::*;

use glam::DVec3;
use js_sys::{Float32Array, Function};
use splinelab::api::gordon::{
    gordon_surface, network_surfaces, spline_blended_surface, surface_differences,
};
use splinelab::api::network::network_example;
use splinelab::bspline::basis_all;
use splinelab::gordon::quadratic_knots;
use wasm_bindgen::prelude::*;
use wasm_bindgen_test::*;

fn message(e: JsError) -> String {
    JsValue::from(e)
        .dyn_into::<js_sys::Error>()
        .map(|e| String::from(e.message()))
        .unwrap_or_default()
}

/// The isocurve network (JSON) of the tensor surface with coefficients `c(i, j)`.
fn network_json(u: &[f64], v: &[f64], c: impl Fn(usize, usize) -> [f64; 3]) -> String {
    let (m, n) = (u.len() - 1, v.len() - 1);
    let (uk, vk) = (quadratic_knots(u), quadratic_knots(v));
    let cc = |i: usize, j: usize| DVec3::from(c(i, j));
    let mut row = [Vec::new(), Vec::new(), Vec::new()];
    let pt = |p: DVec3| format!("[{:?},{:?},{:?}]", p.x, p.y, p.z);
    let mut ps = Vec::new();
    for &ur in u {
        basis_all(&uk, 2, ur, 0, &mut row);
        let r: Vec<String> = (0..n + 2)
            .map(|j| pt((0..m + 2).map(|i| cc(i, j) * row[0][i]).sum()))
            .collect();
        ps.push(format!("[{}]", r.join(",")));
    }
    let mut qs = Vec::new();
    for &vs in v {
        basis_all(&vk, 2, vs, 0, &mut row);
        let r: Vec<String> = (0..m + 2)
            .map(|i| pt((0..n + 2).map(|j| cc(i, j) * row[0][j]).sum()))
            .collect();
        qs.push(format!("[{}]", r.join(",")));
    }
    format!(
        r#"{{"u":{u:?},"v":{v:?},"P":[{}],"Q":[{}]}}"#,
        ps.join(","),
        qs.join(",")
    )
}

const U: [f64; 4] = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0];

fn dome() -> String {
    network_json(&U, &U, |i, j| {
        let (x, y) = (i as f64 / 4.0, j as f64 / 4.0);
        [
            x,
            y,
            1.0 - (x - 0.5).powi(2) - (y - 0.5).powi(2) + 0.3 * ((i * 7 + j * 3) % 5) as f64 / 5.0,
        ]
    })
}

#[wasm_bindgen_test]
fn gordon_has_documented_shape() {
    let o = js(&format!(
        r#"{{"network":{},"samplesU":5,"samplesV":4,"components":true,"mesh":true,"derivatives":1}}"#,
        dome()
    ));
    let r = gordon_surface(o).unwrap();
    assert_eq!(get(&r, "dim").as_f64(), Some(3.0));
    assert_eq!(f64s(&r, "points").len(), 5 * 4 * 3);
    assert_eq!(f64s(&r, "du").len(), 5 * 4 * 3);
    let ku = f64s(&r, "knotsU");
    assert_eq!(ku.len(), 9);
    assert!((ku[4] - 0.5).abs() < 1e-15 && (ku[3] - 1.0 / 3.0).abs() < 1e-15);
    assert_eq!(f64s(&r, "knotsV").len(), 9);
    assert_eq!(f64s(&r, "controlPoints").len(), 6 * 6 * 3);
    assert_eq!(get(&r, "countU").as_f64(), Some(6.0));
    assert_eq!(
        f64s(&r, "knotsUBar"),
        vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]
    );
    let c = get(&r, "components");
    for (name, nu, nv) in [("L1", 4, 5), ("L2", 5, 4), ("Tg", 4, 4)] {
        let s = get(&c, name);
        assert_eq!(get(&s, "countU").as_f64(), Some(nu as f64), "{name}");
        assert_eq!(f64s(&s, "controlPoints").len(), nu * nv * 3, "{name}");
    }
    let mesh = get(&r, "mesh");
    assert_eq!(
        get(&mesh, "positions")
            .dyn_into::<Float32Array>()
            .unwrap()
            .length(),
        60
    );
}

#[wasm_bindgen_test]
fn gordon_interpolates_the_network_corners() {
    // the corner control points of φ_0 are points of the surface at (u_0, v_0) and (u_0, v_n)
    let net = js(&dome());
    let o = js(r#"{"atUV":[[0,0],[0,1]]}"#);
    set(&o, "network", &net);
    let r = gordon_surface(o).unwrap();
    let p = f64s(&r, "points");
    let p0 = js_sys::Array::from(&js_sys::Array::from(&get(&net, "P")).get(0));
    let first: Vec<f64> = serde_wasm_bindgen::from_value(p0.get(0)).unwrap();
    let last: Vec<f64> = serde_wasm_bindgen::from_value(p0.get(p0.length() - 1)).unwrap();
    for k in 0..3 {
        assert!((p[k] - first[k]).abs() < 1e-13);
        assert!((p[3 + k] - last[k]).abs() < 1e-13);
    }
}

#[wasm_bindgen_test]
fn spline_blended_reproduces_p2_from_a_function() {
    let f = Function::new_with_args("u, v", "return [u*u - u*v, 3*v*v + u, 1 + 2*u*v - v];");
    let o = js(
        r#"{"uKnots":[0,0.2,0.5,1],"vKnots":[0,0.3,1],"blend":"cubic-natural","samplesU":7,"samplesV":6}"#,
    );
    set(&o, "network", &f);
    let r = spline_blended_surface(o).unwrap();
    let uv = f64s(&r, "uv");
    let p = f64s(&r, "points");
    assert_eq!(p.len(), 7 * 6 * 3);
    for (k, w) in uv.chunks(2).enumerate() {
        let (u, v) = (w[0], w[1]);
        let want = [u * u - u * v, 3.0 * v * v + u, 1.0 + 2.0 * u * v - v];
        for c in 0..3 {
            assert!((p[3 * k + c] - want[c]).abs() < 1e-13, "{u} {v}");
        }
    }
    // the default blend is b2: lines u_-1..u_m+2, interpolation on u_1..u_m (a = 0)
    let g = Function::new_with_args("u, v", "return [u, v, Math.sin(3*u) + v*v*u];");
    let o = js(
        r#"{"uKnots":[-0.2,-0.1,0,0.4,1,1.1,1.3],"vKnots":[-0.5,-0.2,0,0.5,1,1.4,1.5],"atUV":[[0.4,0.3],[0.7,0.5]]}"#,
    );
    set(&o, "network", &g);
    let p = f64s(&spline_blended_surface(o).unwrap(), "points");
    assert!((p[2] - ((1.2f64).sin() + 0.09 * 0.4)).abs() < 1e-13);
    assert!((p[5] - ((2.1f64).sin() + 0.25 * 0.7)).abs() < 1e-13);
    // per-line tensions (p_0..p_m, here m = 3) and a wrong count
    let o = js(
        r#"{"uKnots":[-0.2,-0.1,0,0.4,1,1.1,1.3],"vKnots":[-0.5,-0.2,0,0.5,1,1.4,1.5],"tensionU":[0.1,0.2,0.1,0.15],"atUV":[[0.4,0.3]]}"#,
    );
    set(&o, "network", &g);
    assert!(spline_blended_surface(o).is_ok());
    let o = js(
        r#"{"uKnots":[-0.2,-0.1,0,0.4,1,1.1,1.3],"vKnots":[-0.5,-0.2,0,0.5,1,1.4,1.5],"tensionV":[0.1],"atUV":[[0.4,0.3]]}"#,
    );
    set(&o, "network", &g);
    assert!(message(spline_blended_surface(o).unwrap_err()).starts_with("tensionV:"));
    // not-a-knot and a network object work too
    let o = js(
        r#"{"uKnots":[0,0.2,0.5,1],"vKnots":[0,0.3,0.6,1],"blend":"cubic-notaknot","samplesU":3,"samplesV":3,"mesh":true}"#,
    );
    set(&o, "network", &f);
    assert!(spline_blended_surface(o).is_ok());
    let o = js(&format!(
        r#"{{"network":{},"blend":"cubic-natural","samplesU":3,"samplesV":3}}"#,
        dome()
    ));
    assert_eq!(
        f64s(&spline_blended_surface(o).unwrap(), "points").len(),
        27
    );
}

#[wasm_bindgen_test]
fn bad_input_throws_error_naming_the_field_and_module_keeps_working() {
    // a throwing callback
    let f = Function::new_with_args(
        "u, v",
        "if (u > 0.4) throw new Error('boom'); return [u, v, 0];",
    );
    let o = js(r#"{"uKnots":[0,0.5,1],"vKnots":[0,0.5,1],"blend":"cubic-natural"}"#);
    set(&o, "network", &f);
    let m = message(spline_blended_surface(o).unwrap_err());
    assert!(m.starts_with("network:") && m.contains("boom"), "{m}");
    // garbage return
    let f = Function::new_with_args("u, v", "return u > 0.7 ? 'x' : [u, v, NaN];");
    let o = js(r#"{"uKnots":[0,0.5,1],"vKnots":[0,0.5,1],"blend":"cubic-natural"}"#);
    set(&o, "network", &f);
    assert!(message(spline_blended_surface(o).unwrap_err()).starts_with("network:"));
    // not-a-knot with m = 2
    let f = Function::new_with_args("u, v", "return [u, v, 0];");
    let o = js(r#"{"uKnots":[0,0.5,1],"vKnots":[0,0.3,0.5,1],"blend":"cubic-notaknot"}"#);
    set(&o, "network", &f);
    assert!(message(spline_blended_surface(o).unwrap_err()).starts_with("uKnots:"));
    let o = js(r#"{"uKnots":[0,0.5,1],"vKnots":[0,0.3,0.5,1],"blend":"spline"}"#);
    set(&o, "network", &f);
    assert!(message(spline_blended_surface(o).unwrap_err()).starts_with("blend:"));
    let o = js(r#"{"uKnots":[0,0.5,1],"vKnots":[0,0.3,0.5,1],"network":3}"#);
    assert!(message(spline_blended_surface(o).unwrap_err()).starts_with("network:"));
    // m = 1 for G
    let net = network_json(&[0.0, 1.0], &U, |i, j| [i as f64, j as f64, 0.0]);
    let e = gordon_surface(js(&format!(r#"{{"network":{net}}}"#))).unwrap_err();
    assert!(message(e).starts_with("network.u:"));
    // incompatible network
    let mut bad = dome();
    bad = bad.replacen("\"P\":[[[", "\"P\":[[[5", 1);
    let m = message(gordon_surface(js(&format!(r#"{{"network":{bad}}}"#))).unwrap_err());
    assert!(m.starts_with("network:") && m.contains("residual"), "{m}");
    // wrong shapes
    let e =
        gordon_surface(js(r#"{"network":{"u":[0,1,2],"v":[0,1,2],"P":[],"Q":[]}}"#)).unwrap_err();
    assert!(message(e).starts_with("network.P"));
    // a missing part is named (the reader of flat/typed networks reads each part: was "network:" from serde)
    let e = gordon_surface(js(r#"{"network":{"u":[0,1]}}"#)).unwrap_err();
    assert!(message(e).starts_with("network.v:"));
    let e = network_surfaces(js(&format!(r#"{{"network":{},"samplesU":1}}"#, dome()))).unwrap_err();
    assert!(message(e).starts_with("samplesU:"));
    let e =
        network_surfaces(js(&format!(r#"{{"network":{},"surfaces":["X"]}}"#, dome()))).unwrap_err();
    assert!(message(e).starts_with("surfaces[0]:"));
    // the next valid call works
    assert!(gordon_surface(js(&format!(
        r#"{{"network":{},"samplesU":3,"samplesV":3}}"#,
        dome()
    )))
    .is_ok());
}

#[wasm_bindgen_test]
fn network_surfaces_in_one_call() {
    let o = js(&format!(
        r#"{{"network":{},"samplesU":9,"samplesV":8,"colorBy":"GGB","components":true}}"#,
        dome()
    ));
    let r = network_surfaces(o).unwrap();
    let s = get(&r, "surfaces");
    assert_eq!(
        serde_wasm_bindgen::from_value::<Vec<String>>(get(&r, "names")).unwrap(),
        vec!["S", "T", "G", "GB"]
    );
    for name in ["S", "T", "G", "GB"] {
        let one = get(&s, name);
        assert_eq!(f64s(&one, "points").len(), 9 * 8 * 3);
        let mesh = get(&one, "mesh");
        assert_eq!(
            get(&mesh, "indices")
                .dyn_into::<js_sys::Uint32Array>()
                .unwrap()
                .length(),
            6 * 8 * 7
        );
    }
    let norms = get(&r, "norms");
    let ggb = get(&norms, "GGB").as_f64().unwrap();
    assert!(ggb > 1e-6 && ggb.is_finite());
    let colors = get(&r, "colors")
        .dyn_into::<Float32Array>()
        .unwrap()
        .to_vec();
    assert_eq!(colors.len(), 72);
    assert!((colors.iter().cloned().fold(0.0f32, f32::max) as f64) <= ggb * 1.5 + 1e-6);
    let g = get(&r, "gordon");
    assert_eq!(f64s(&g, "controlPoints").len(), 108);
    assert!(get(&g, "components").is_object());
    let d = surface_differences(js(&format!(r#"{{"network":{}}}"#, dome()))).unwrap();
    assert_eq!(get(&d, "GGB").as_f64(), Some(ggb));
    assert_eq!(get(&d, "samples").as_f64(), Some(57.0));
    for k in ["SG", "ST", "TG", "SGB"] {
        assert!(get(&d, k).as_f64().unwrap() > 1e-6, "{k}");
        assert_eq!(get(&d, k).as_f64(), get(&norms, k).as_f64());
    }
}

#[wasm_bindgen_test]
fn network_surfaces_builds_and_measures_only_what_is_asked_for() {
    let full = network_surfaces(js(&format!(
        r#"{{"network":{},"samplesU":6,"samplesV":5}}"#,
        dome()
    )))
    .unwrap();
    let r = network_surfaces(js(&format!(
        r#"{{"network":{},"samplesU":6,"samplesV":5,"surfaces":["G"],"norms":false}}"#,
        dome()
    )))
    .unwrap();
    assert!(get(&r, "norms").is_undefined());
    let keys = js_sys::Object::keys(get(&r, "surfaces").unchecked_ref::<js_sys::Object>());
    assert_eq!(keys.length(), 1);
    // the same G as in the full call, and the same "available" list
    let g = |x: &JsValue| f64s(&get(&get(x, "surfaces"), "G"), "points");
    assert_eq!(g(&r), g(&full));
    assert_eq!(
        serde_wasm_bindgen::from_value::<Vec<String>>(get(&r, "available")).unwrap(),
        vec!["S", "T", "G", "GB"]
    );
    // colorBy builds its pair even when not listed; equal to the full family's colours
    let c = network_surfaces(js(&format!(
        r#"{{"network":{},"samplesU":6,"samplesV":5,"surfaces":["G"],"norms":false,"colorBy":"SGB"}}"#,
        dome()
    )))
    .unwrap();
    let full_c = network_surfaces(js(&format!(
        r#"{{"network":{},"samplesU":6,"samplesV":5,"colorBy":"SGB"}}"#,
        dome()
    )))
    .unwrap();
    let colors = |x: &JsValue| {
        get(x, "colors")
            .dyn_into::<Float32Array>()
            .unwrap()
            .to_vec()
    };
    assert_eq!(colors(&c), colors(&full_c));
    assert!(colors(&c).iter().any(|&d| d > 0.0));
}

#[wasm_bindgen_test]
fn separable_network_gives_s_equal_g() {
    let net = network_example(js(r#"{"name":"separable"}"#)).unwrap();
    let o = js("{}");
    set(&o, "network", &net);
    let d = surface_differences(o).unwrap();
    let n = |k: &str| get(&d, k).as_f64().unwrap();
    assert!(n("SG") < 1e-13 * 1.24, "{}", n("SG"));
    assert!(n("SGB") < 1e-13 * 1.24);
    assert!((n("ST") - n("TG")).abs() < 1e-13 && n("ST") > 1e-6);
    let o = js(r#"{"blend":"b2"}"#);
    set(&o, "network", &net);
    assert!(message(surface_differences(o).unwrap_err()).starts_with("blend:"));
}
