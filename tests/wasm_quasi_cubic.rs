//! wasm-bindgen tests of the the quasi-cubic paper exports (quasiCubicBasis, quasiCubicCurve, quasiCubicInterpolation,
//! quasiCubicSurface, quasiCubicBlendedSurface, quasiCubicPreset, quasiCubicShapeCheck).
#![cfg(target_arch = "wasm32")]

mod wasm_util;
use wasm_util::*;

use js_sys::{Float32Array, Reflect, Uint32Array};
use splinelab::api::quasi_cubic::*;
use wasm_bindgen::prelude::*;
use wasm_bindgen_test::*;

fn num(o: &JsValue, k: &str) -> f64 {
    get(o, k).as_f64().unwrap()
}
fn message(r: Result<JsValue, JsError>) -> String {
    r.map_err(JsValue::from)
        .unwrap_err()
        .dyn_into::<js_sys::Error>()
        .map(|e| String::from(e.message()))
        .unwrap_or_default()
}

#[wasm_bindgen_test]
fn basis_shape_and_values() {
    let r = quasi_cubic_basis(js(r#"{"alpha":3,"at":[0,0.25,1],"derivatives":2}"#)).unwrap();
    let v = f64s(&r, "values");
    assert_eq!(v.len(), 12);
    assert!((v[1] - 1.0).abs() < 1e-15 && v[0].abs() < 1e-15); // α = 3: B(0) = e1
    for row in v.chunks(4) {
        assert!((row.iter().sum::<f64>() - 1.0).abs() < 1e-14);
    }
    let d1 = f64s(&r, "d1");
    assert!((d1[2] - (std::f64::consts::PI / 2.0 - 1.0)).abs() < 1e-14);
    assert_eq!(f64s(&r, "d2").len(), 12);
    assert!(get(&r, "d3").is_undefined());
    let r = quasi_cubic_basis(js(r#"{"alpha":0,"samples":5,"derivatives":3}"#)).unwrap();
    assert_eq!(f64s(&r, "d3").len(), 20);
    assert_eq!(f64s(&r, "params"), vec![0.0, 0.25, 0.5, 0.75, 1.0]);
}

#[wasm_bindgen_test]
fn curve_shape_domain_and_closed() {
    let r = quasi_cubic_curve(js(
        r#"{"points":[[0,0],[1,2],[3,2],[4,0],[5,1]],"alpha":0.5,"samples":11,"derivatives":2}"#,
    ))
    .unwrap();
    assert_eq!(num(&r, "dim"), 2.0);
    assert_eq!(f64s(&r, "domain"), vec![0.0, 2.0]);
    assert_eq!(f64s(&r, "params").len(), 11);
    assert_eq!(f64s(&r, "points").len(), 22);
    assert_eq!(f64s(&r, "d2").len(), 22);
    // closed square → circle of radius ⅔ of the half-diagonal (1.5 → 1)
    let r = quasi_cubic_curve(js(
        r#"{"points":[[1.5,0],[0,1.5],[-1.5,0],[0,-1.5]],"alpha":1,"closed":true,"samples":101}"#,
    ))
    .unwrap();
    assert_eq!(f64s(&r, "domain"), vec![0.0, 4.0]);
    for p in f64s(&r, "points").chunks(2) {
        assert!((p[0].hypot(p[1]) - 1.0).abs() < 1e-12);
    }
    // 3D
    let r = quasi_cubic_curve(js(
        r#"{"points":[[0,0,0],[1,2,1],[3,2,2],[4,0,3]],"at":[0.5]}"#,
    ))
    .unwrap();
    assert_eq!(num(&r, "dim"), 3.0);
}

#[wasm_bindgen_test]
fn interpolation_passes_through_and_reports_beta() {
    let pts = r#"[[0,0],[1,2.1],[2.7,2.6],[3.4,0.9],[5.2,0.4],[6.1,2.8],[8,3.3],[9.5,1.2]]"#;
    let r = quasi_cubic_interpolation(js(&format!(
        r#"{{"points":{pts},"beta":[1,0.3,1.7,0,2,0.8],"at":[0,1,2,3,4,5],"curvature":true}}"#
    )))
    .unwrap();
    let p = f64s(&r, "points");
    let data = [
        [1.0, 2.1],
        [2.7, 2.6],
        [3.4, 0.9],
        [5.2, 0.4],
        [6.1, 2.8],
        [8.0, 3.3],
    ];
    for (j, d) in data.iter().enumerate() {
        assert!((p[2 * j] - d[0]).abs() < 1e-12 && (p[2 * j + 1] - d[1]).abs() < 1e-12);
    }
    assert_eq!(f64s(&r, "beta"), vec![1.0, 0.3, 1.7, 0.0, 2.0, 0.8]);
    assert_eq!(f64s(&r, "circleCurvature").len(), 6);
    assert_eq!(f64s(&r, "curvature").len(), 6);
    // β* by curvature: the curve's curvature at b_j equals the circle curvature K_j
    let r = quasi_cubic_interpolation(js(&format!(
        r#"{{"points":{pts},"beta":"curvature","at":[0,1,2,3,4,5],"curvature":true}}"#
    )))
    .unwrap();
    let (k, kk) = (f64s(&r, "curvature"), f64s(&r, "circleCurvature"));
    for j in 0..6 {
        assert!((k[j] - kk[j]).abs() < 1e-12 * kk[j].abs().max(1.0));
    }
    assert!(f64s(&r, "beta").iter().all(|b| *b > 0.0));
    // default: β* all 1
    let r = quasi_cubic_interpolation(js(&format!(r#"{{"points":{pts},"samples":3}}"#))).unwrap();
    assert_eq!(f64s(&r, "beta"), vec![1.0; 6]);
}

#[wasm_bindgen_test]
fn surfaces_presets_and_mesh() {
    let sphere = quasi_cubic_preset(js(r#"{"name":"sphere","radius":2}"#)).unwrap();
    assert_eq!(get(&sphere, "periodicU").as_bool(), Some(true));
    // pass the preset back as the options object, with a mesh
    Reflect::set(&sphere, &"samplesU".into(), &9.0.into()).unwrap();
    Reflect::set(&sphere, &"samplesV".into(), &7.0.into()).unwrap();
    Reflect::set(&sphere, &"mesh".into(), &true.into()).unwrap();
    let r = quasi_cubic_surface(sphere).unwrap();
    assert_eq!(f64s(&r, "domain"), vec![0.0, 4.0, 0.0, 2.0]);
    let p = f64s(&r, "points");
    assert_eq!(p.len(), 9 * 7 * 3);
    for q in p.chunks(3) {
        assert!(((q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt() - 2.0).abs() < 1e-12);
    }
    let mesh = get(&r, "mesh");
    assert_eq!(
        get(&mesh, "positions")
            .dyn_into::<Float32Array>()
            .unwrap()
            .length(),
        9 * 7 * 3
    );
    assert_eq!(
        get(&mesh, "indices")
            .dyn_into::<Uint32Array>()
            .unwrap()
            .length(),
        8 * 6 * 6
    );
    // the plain contract: (m+3) × (n+3) grid, domain [0,m]×[0,n], du/dv with derivatives: 1
    let grid: Vec<Vec<[f64; 3]>> = (0..5)
        .map(|i| {
            (0..4)
                .map(|j| [i as f64, j as f64, ((i * j) % 3) as f64])
                .collect()
        })
        .collect();
    let g = serde_json_like(&grid);
    let r = quasi_cubic_surface(js(&format!(
        r#"{{"grid":{g},"alpha":0.5,"samplesU":3,"samplesV":2,"derivatives":1}}"#
    )))
    .unwrap();
    assert_eq!(
        f64s(&r, "uv"),
        vec![0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 1.0, 1.0, 2.0, 0.0, 2.0, 1.0]
    );
    assert_eq!(f64s(&r, "du").len(), 18);
    // blended surface interpolates grid[i+1][j+1] at (i, j)
    let r = quasi_cubic_blended_surface(js(&format!(
        r#"{{"grid":{g},"beta":[[1,1],[1,0.2],[1,1]],"atUV":[[1,1],[2,0]]}}"#
    )))
    .unwrap();
    let p = f64s(&r, "points");
    assert!((p[0] - 2.0).abs() < 1e-12 && (p[1] - 2.0).abs() < 1e-12 && (p[2] - 1.0).abs() < 1e-12);
    assert!((p[3] - 3.0).abs() < 1e-12 && (p[4] - 1.0).abs() < 1e-12);
    assert!(
        stringify(&quasi_cubic_preset(js(r#"{"name":"ellipse"}"#)).unwrap())
            .contains("\"closed\":true")
    );
}

fn serde_json_like(grid: &[Vec<[f64; 3]>]) -> String {
    let rows: Vec<String> = grid
        .iter()
        .map(|r| {
            let pts: Vec<String> = r
                .iter()
                .map(|p| format!("[{},{},{}]", p[0], p[1], p[2]))
                .collect();
            format!("[{}]", pts.join(","))
        })
        .collect();
    format!("[{}]", rows.join(","))
}

#[wasm_bindgen_test]
fn shape_check_reads_tiny_deviation_and_grows_when_broken() {
    let e = quasi_cubic_preset(js(r#"{"name":"ellipse","a":2,"b":1}"#)).unwrap();
    let pts = stringify(&get(&e, "points"));
    let r = quasi_cubic_shape_check(js(&format!(
        r#"{{"shape":"ellipse","points":{pts},"alpha":1}}"#
    )))
    .unwrap();
    assert!(num(&r, "deviation") < 1e-12);
    assert_eq!(num(&r, "conditionResidual"), 0.0);
    assert!(f64s(&r, "analytic").len() > 100);
    let r = quasi_cubic_shape_check(js(
        r#"{"shape":"ellipse","points":[[3.4,0.2],[0,1.5],[-3,0],[0,-1.5]],"alpha":1}"#,
    ))
    .unwrap();
    assert!(num(&r, "deviation") > 1e-3);
    for name in ["circle", "parabola", "sine"] {
        let pr = quasi_cubic_preset(js(&format!(r#"{{"name":"{name}"}}"#))).unwrap();
        let pts = stringify(&get(&pr, "points"));
        let a = num(&pr, "alpha");
        let r = quasi_cubic_shape_check(js(&format!(
            r#"{{"shape":"{name}","points":{pts},"alpha":{a}}}"#
        )))
        .unwrap();
        assert!(num(&r, "deviation") < 1e-12, "{name}");
        assert_eq!(get(&r, "alphaOk").as_bool(), Some(true));
    }
}

#[wasm_bindgen_test]
fn bad_input_throws_error_naming_the_field_and_module_keeps_working() {
    let m = message(quasi_cubic_curve(js(
        r#"{"points":[[0,0],[1,1],[2,0]],"alpha":1}"#,
    )));
    assert!(m.starts_with("points:"), "{m}");
    let m = message(quasi_cubic_curve(js(
        r#"{"points":[[0,0],[1,1],[2,0],[3,3]],"alpha":3.5}"#,
    )));
    assert!(m.starts_with("alpha:"), "{m}");
    let m = message(quasi_cubic_curve(js(
        r#"{"points":[[0,0],[1,1],[2,0]],"closed":true}"#,
    )));
    assert!(m.starts_with("points:") && m.contains("closed"), "{m}");
    let m = message(quasi_cubic_basis(js(r#"{"alpha":-4e6,"at":[0]}"#)));
    assert!(m.starts_with("alpha:"), "{m}");
    let pts = r#"[[0,0],[1,2],[2,2],[3,0],[4,1]]"#;
    let m = message(quasi_cubic_interpolation(js(&format!(
        r#"{{"points":{pts},"beta":[1,1]}}"#
    ))));
    assert!(m.starts_with("beta:"), "{m}");
    let m = message(quasi_cubic_interpolation(js(&format!(
        r#"{{"points":{pts},"beta":[1,-1,1]}}"#
    ))));
    assert!(m.starts_with("beta[1]:"), "{m}");
    let m = message(quasi_cubic_interpolation(js(&format!(
        r#"{{"points":{pts},"beta":"fair"}}"#
    ))));
    assert!(m.starts_with("beta:"), "{m}");
    let m = message(quasi_cubic_interpolation(js(&format!(
        r#"{{"points":{pts},"k":1}}"#
    ))));
    assert!(m.starts_with("k:"), "{m}");
    let m = message(quasi_cubic_interpolation(js(
        r#"{"points":[[0,0],[1,2],[2,null],[3,0]]}"#,
    )));
    assert!(m.starts_with("points"), "{m}");
    let m = message(quasi_cubic_surface(js(
        r#"{"grid":[[[0,0,0],[1,0,0],[2,0,0]]],"periodicU":true}"#,
    )));
    assert!(m.starts_with("grid"), "{m}");
    let m = message(quasi_cubic_preset(js(r#"{"name":"klein bottle"}"#)));
    assert!(m.starts_with("name:"), "{m}");
    let m = message(quasi_cubic_shape_check(js(
        r#"{"shape":"ellipse","points":[[0,0],[1,1],[2,0]]}"#,
    )));
    assert!(m.starts_with("points:"), "{m}");
    let m = message(quasi_cubic_curve(JsValue::from_f64(1.0)));
    assert!(m.starts_with("options:"), "{m}");
    // the next valid call works
    let r = quasi_cubic_curve(js(r#"{"points":[[0,0],[1,1],[2,0],[3,3]],"samples":4}"#)).unwrap();
    assert_eq!(f64s(&r, "points").len(), 8);
}
