//! wasm-bindgen tests of `b2Curve`, `b2Surface`, `b2Basis` (shapes of `../shared/spec/api.md`, errors).
#![cfg(target_arch = "wasm32")]

mod wasm_util;
use wasm_util::*;

use js_sys::Reflect;
use splinelab::api::b2::{b2_basis, b2_curve, b2_surface};
use splinelab::api::fit::{b2_fit, b2_fit_sweep, dataset, fit_names, noisy_data};
use wasm_bindgen::prelude::*;
use wasm_bindgen_test::*;

fn message(e: JsError) -> String {
    JsValue::from(e)
        .dyn_into::<js_sys::Error>()
        .map(|e| String::from(e.message()))
        .unwrap_or_default()
}

const PTS: &str = "[[-1,-0.5],[0,0],[0.3,1.1],[1.6,1.9],[2,1.7],[4.5,2.2],[5,0.4],[5.6,-0.3],[7.9,0.1],[8.3,1.2]]";

#[wasm_bindgen_test]
fn curve_has_documented_shape_and_interpolates() {
    let r = b2_curve(js(&format!(
        r#"{{"points":{PTS},"samples":50,"derivatives":2}}"#
    )))
    .unwrap();
    let n = 6;
    assert_eq!(get(&r, "dim").as_f64(), Some(2.0));
    assert_eq!(f64s(&r, "params").len(), 50);
    assert_eq!(f64s(&r, "points").len(), 100);
    assert_eq!(f64s(&r, "d1").len(), 100);
    assert_eq!(f64s(&r, "d2").len(), 100);
    let dom = f64s(&r, "domain");
    assert_eq!(dom.len(), 2);
    assert_eq!(dom[0], 0.0); // chord knots: u_1 = 0
    assert_eq!(f64s(&r, "knots").len(), 2 * n + 5);
    assert_eq!(f64s(&r, "controlPoints").len(), (2 * n + 1) * 2);
    assert_eq!(f64s(&r, "joints").len(), n * 2);
    assert_eq!(f64s(&r, "evenVertices").len(), (n + 1) * 2);
    assert_eq!(f64s(&r, "tension"), vec![1.0 / 6.0; n + 1]);
    assert_eq!(f64s(&r, "dataKnots").len(), n + 4);
    // a = 0: the first sample is W_1 = points[2] and the last W_n = points[n + 1]
    let p = f64s(&r, "points");
    assert!((p[0] - 0.3).abs() < 1e-12 && (p[1] - 1.1).abs() < 1e-12);
    assert!((p[98] - 5.6).abs() < 1e-12 && (p[99] + 0.3).abs() < 1e-12);
    // at: the joints' parameters give the data
    let jp = f64s(&r, "jointParams");
    let at = format!("{:?}", jp);
    let r = b2_curve(js(&format!(
        r#"{{"points":{PTS},"at":{at},"K":20,"tension":0.13}}"#
    )))
    .unwrap();
    let p = f64s(&r, "points");
    let _ = p; // K changes where the joints sit: compare with this call's own jointParams
    let jp = f64s(&r, "jointParams");
    let r = b2_curve(js(&format!(
        r#"{{"points":{PTS},"at":{:?},"K":20,"tension":0.13}}"#,
        jp
    )))
    .unwrap();
    let p = f64s(&r, "points");
    assert!((p[2] - 1.6).abs() < 1e-12 && (p[3] - 1.9).abs() < 1e-12);
}

#[wasm_bindgen_test]
fn curvature_option_gives_signed_curvature_and_normals() {
    // data on the unit circle with the cubic-reproducing tension (p_eff = 6p/7 = 1/12): curvature ≈ 1 (> 0:
    // counter-clockwise). (With the default p = 1/6 it swings between −0.18 and 2.3 inside each span.)
    let pts: Vec<String> = (0..12)
        .map(|k| {
            let t = k as f64 * std::f64::consts::PI / 6.0;
            format!("[{},{}]", t.cos(), t.sin())
        })
        .collect();
    let r = b2_curve(js(&format!(
        r#"{{"points":[{}],"samples":9,"curvature":true,"tension":0.09722222222222222}}"#,
        pts.join(",")
    )))
    .unwrap();
    let k = f64s(&r, "curvature");
    assert_eq!(k.len(), 9);
    assert!(k.iter().all(|&x| (x - 1.0).abs() < 0.15), "{k:?}");
    let n = f64s(&r, "normals");
    assert_eq!(n.len(), 18);
    for w in n.chunks(2) {
        assert!((w[0].hypot(w[1]) - 1.0).abs() < 1e-12);
    }
    assert!(get(
        &b2_curve(js(&format!(
            r#"{{"points":[{}],"samples":2}}"#,
            pts.join(",")
        )))
        .unwrap(),
        "curvature"
    )
    .is_undefined());
}

#[wasm_bindgen_test]
fn curve_options_auto_tension_section3_3d() {
    let r = b2_curve(js(&format!(
        r#"{{"points":{PTS},"autoTension":"turning","autoTensionScale":0.3,"samples":3}}"#
    )))
    .unwrap();
    let t = f64s(&r, "tension");
    assert_eq!(t.len(), 7);
    assert!(t.iter().all(|&p| (0.0..=0.3).contains(&p)));
    let r = b2_curve(js(&format!(
        r#"{{"points":{PTS},"construction":"section3","knots":"uniform","a":0.1,"tension":0.05}}"#
    )))
    .unwrap();
    assert_eq!(f64s(&r, "domain"), vec![0.0, 5.0]);
    let r = b2_curve(js(r#"{"points":[[0,0,0],[1,0,1],[2,1,0],[3,1,1],[4,0,0],[5,0,2]],"a":0.1,"c2":2,"samples":4}"#)).unwrap();
    assert_eq!(get(&r, "dim").as_f64(), Some(3.0));
    assert_eq!(f64s(&r, "points").len(), 12);
    let r = b2_curve(js(&format!(r#"{{"points":{PTS},"knots":[-2,-1,0,1,2,3,4,5,6,7],"tension":[0,0.1,0.2,0.1,0,0.3,0.1],"samples":2}}"#))).unwrap();
    assert_eq!(f64s(&r, "domain"), vec![0.0, 5.0]);
}

#[wasm_bindgen_test]
fn bad_input_throws_error_naming_the_field_and_module_keeps_working() {
    let cases: [(&str, &str); 12] = [
        (r#"{"points":[[0,0],[1,1],[2,0],[3,1],[4,0]]}"#, "points"),
        (
            r#"{"points":[[0,0],[1,1],[1,1],[3,1],[4,0],[5,1]]}"#,
            "points[2]",
        ),
        (
            r#"{"points":[[0,0],[1,1],[2,0],[3,1,0],[4,0],[5,1]]}"#,
            "points[3]",
        ),
        (
            r#"{"points":[[0,0],[1,1],[2,0],[3,1],[4,0],[5,1]],"knots":[0,1,3,2,4,5]}"#,
            "knots[3]",
        ),
        (
            r#"{"points":[[0,0],[1,1],[2,0],[3,1],[4,0],[5,1]],"knots":[0,1,2]}"#,
            "knots",
        ),
        (
            r#"{"points":[[0,0],[1,1],[2,0],[3,1],[4,0],[5,1]],"tension":[0.1,0.2]}"#,
            "tension",
        ),
        (
            r#"{"points":[[0,0],[1,1],[2,0],[3,1],[4,0],[5,1]],"construction":"section3"}"#,
            "construction",
        ),
        (
            r#"{"points":[[0,0],[1,1],[2,0],[3,1],[4,0],[5,1]],"autoTension":"maybe"}"#,
            "autoTension",
        ),
        (
            r#"{"points":[[0,0,0],[1,1,0],[2,0,0],[3,1,0],[4,0,0],[5,1,0]],"autoTension":"turning"}"#,
            "autoTension",
        ),
        (
            r#"{"points":[[0,0],[1,1],[2,0],[3,1],[4,0],[5,1]],"K":-3}"#,
            "K",
        ),
        (
            r#"{"points":[[0,0],[1,1],[2,0],[3,1],[4,0],[5,1]],"samples":2000000}"#,
            "samples",
        ),
        (
            r#"{"points":[[0,0],[1,1],[2,0],[3,1],[4,0],[5,1]],"a":"x"}"#,
            "a",
        ),
    ];
    for (input, field) in cases {
        let e = b2_curve(js(input)).unwrap_err();
        let m = message(e);
        assert!(m.starts_with(&format!("{field}:")), "{input} → {m}");
    }
    // non-finite numbers cannot come through JSON: build one by hand
    let o = js(r#"{"points":[[0,0],[1,1],[2,0],[3,1],[4,0],[5,1]]}"#);
    Reflect::set(&o, &"a".into(), &JsValue::from_f64(f64::NAN)).unwrap();
    assert!(message(b2_curve(o).unwrap_err()).starts_with("a:"));
    let e = b2_curve(JsValue::from_f64(1.0)).unwrap_err();
    assert!(message(e).starts_with("options:"));
    assert!(b2_curve(js(
        r#"{"points":[[0,0],[1,1],[2,0],[3,1],[4,0],[5,1]],"samples":3}"#
    ))
    .is_ok());
}

fn grid_json(rows: usize, cols: usize) -> String {
    let mut g = Vec::new();
    for i in 0..rows {
        let mut r = Vec::new();
        for j in 0..cols {
            r.push(format!("[{},{},{}]", i, j, ((i * j) as f64 * 0.3).sin()));
        }
        g.push(format!("[{}]", r.join(",")));
    }
    format!("[{}]", g.join(","))
}

#[wasm_bindgen_test]
fn surface_shape_and_interpolation() {
    let g = grid_json(7, 6);
    let r = b2_surface(js(&format!(r#"{{"grid":{g},"knotsU":"uniform","knotsV":"uniform","samplesU":4,"samplesV":3,"derivatives":1}}"#)))
        .unwrap();
    assert_eq!(get(&r, "dim").as_f64(), Some(3.0));
    assert_eq!(f64s(&r, "uv").len(), 24);
    assert_eq!(f64s(&r, "points").len(), 36);
    assert_eq!(f64s(&r, "du").len(), 36);
    assert_eq!(f64s(&r, "domain"), vec![0.0, 2.0, 0.0, 1.0]);
    let r = b2_surface(js(&format!(
        r#"{{"grid":{g},"knotsU":"uniform","knotsV":"uniform","atUV":[[0,0],[2,1]]}}"#
    )))
    .unwrap();
    let p = f64s(&r, "points");
    // S(u_1, v_1) = W_{1,1} = grid[2][2] = [2, 2, sin(1.2)]
    assert!(
        (p[0] - 2.0).abs() < 1e-12
            && (p[1] - 2.0).abs() < 1e-12
            && (p[2] - 1.2f64.sin()).abs() < 1e-12
    );
    let r = b2_surface(js(&format!(
        r#"{{"grid":{g},"samplesU":5,"samplesV":4,"mesh":true}}"#
    )))
    .unwrap();
    let mesh = get(&r, "mesh");
    assert_eq!(get(&mesh, "nu").as_f64(), Some(5.0));
    assert_eq!(
        get(&mesh, "indices")
            .dyn_into::<js_sys::Uint32Array>()
            .unwrap()
            .length(),
        4 * 3 * 2 * 3
    );
    let e = b2_surface(js(&format!(r#"{{"grid":{g},"tensionU":[0.1]}}"#))).unwrap_err();
    assert!(message(e).starts_with("tensionU:"));
    let e = b2_surface(js(r#"{"grid":[[[0,0,0]]]}"#)).unwrap_err();
    assert!(message(e).starts_with("grid"));
    assert!(b2_surface(js(&format!(
        r#"{{"grid":{g},"a":0.1,"samplesU":2,"samplesV":2}}"#
    )))
    .is_ok());
}

#[wasm_bindgen_test]
fn basis_rows_sum_to_one() {
    let r = b2_basis(js(
        r#"{"knots":"uniform","count":8,"a":0.1,"tension":0.2,"samples":11,"derivatives":1}"#,
    ))
    .unwrap();
    assert_eq!(get(&r, "count").as_f64(), Some(8.0));
    let v = f64s(&r, "values");
    assert_eq!(v.len(), 88);
    for row in v.chunks(8) {
        assert!((row.iter().sum::<f64>() - 1.0).abs() < 1e-13);
    }
    let r = b2_basis(js(&format!(r#"{{"points":{PTS},"samples":5}}"#))).unwrap();
    assert_eq!(f64s(&r, "values").len(), 50);
    let e = b2_basis(js(r#"{"a":0.1}"#)).unwrap_err();
    assert!(message(e).starts_with("knots:"));
}

#[wasm_bindgen_test]
fn basis_accepts_the_per_segment_tension_that_curve_accepts() {
    // n = 4: the paper's p_1..p_3 (n − 1 values) mean p_0 := p_1, p_4 := p_3 — in b2Curve and b2Basis alike
    let short = r#""tension":[0.1,0.25,0.4]"#;
    let full = r#""tension":[0.1,0.1,0.25,0.4,0.4]"#;
    let opts = |t: &str| format!(r#"{{"knots":"uniform","count":8,"a":0.05,{t},"samples":9}}"#);
    let a = f64s(&b2_basis(js(&opts(short))).unwrap(), "values");
    let b = f64s(&b2_basis(js(&opts(full))).unwrap(), "values");
    let d = f64s(&b2_basis(js(&opts(r#""tension":0.1"#))).unwrap(), "values");
    assert_eq!(a.len(), 72);
    assert_eq!(a, b);
    assert!(a.iter().zip(&d).any(|(x, y)| (x - y).abs() > 1e-6));
    // b2Curve on the same knots and tension: L(u) = Σ_j W_j L_j(u) with the basis above
    let pts = "[[0,0],[1,2],[2,-1],[3,3],[4,0],[5,2],[6,1],[7,0]]";
    let c = b2_curve(js(&format!(
        r#"{{"points":{pts},"knots":"uniform","a":0.05,{short},"samples":9}}"#
    )))
    .unwrap();
    let w: Vec<f64> = js_sys::JSON::parse(pts)
        .map(|v| flatten_points(&v))
        .unwrap();
    let cp = f64s(&c, "points");
    for (r, row) in a.chunks(8).enumerate() {
        let x: f64 = row.iter().enumerate().map(|(j, l)| l * w[2 * j]).sum();
        let y: f64 = row.iter().enumerate().map(|(j, l)| l * w[2 * j + 1]).sum();
        assert!((x - cp[2 * r]).abs() < 1e-12 && (y - cp[2 * r + 1]).abs() < 1e-12);
    }
    // a wrong count still names the field
    let e = b2_basis(js(&opts(r#""tension":[0.1,0.2]"#))).unwrap_err();
    assert!(message(e).starts_with("tension:"));
}

fn flatten_points(v: &JsValue) -> Vec<f64> {
    js_sys::Array::from(v)
        .iter()
        .flat_map(|p| {
            js_sys::Array::from(&p)
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect::<Vec<_>>()
        })
        .collect()
}

#[wasm_bindgen_test]
fn noisy_data_and_datasets() {
    let r = noisy_data(js(r#"{"curve":"spiral","count":25,"sigma":0.2,"seed":7}"#)).unwrap();
    let r2 = noisy_data(js(r#"{"curve":"spiral","count":25,"sigma":0.2,"seed":7}"#)).unwrap();
    assert_eq!(f64s(&r, "points"), f64s(&r2, "points"));
    assert_eq!(f64s(&r, "points").len(), 50);
    assert_eq!(f64s(&r, "clean").len(), 50);
    assert_eq!(f64s(&r, "truth").len(), 2002);
    assert_ne!(f64s(&r, "points"), f64s(&r, "clean"));
    let e = noisy_data(js(r#"{"curve":"zigzag"}"#)).unwrap_err();
    assert!(message(e).starts_with("curve:"));
    let e = noisy_data(js(r#"{"seed":-1}"#)).unwrap_err();
    assert!(message(e).starts_with("seed:"));
    let d = dataset(js(r#"{"name":"titanium_heat"}"#)).unwrap();
    assert_eq!(get(&d, "count").as_f64(), Some(49.0));
    assert_eq!(&f64s(&d, "points")[..2], &[595.0, 0.644]);
    let d = dataset(js(r#"{"name":"rpn14"}"#)).unwrap();
    assert_eq!(f64s(&d, "points").len(), 18);
    let e = dataset(js(r#"{"name":"x"}"#)).unwrap_err();
    assert!(message(e).starts_with("name:"));
    let names = fit_names();
    assert!(js_sys::Array::is_array(&get(&names, "curves")));
}

#[wasm_bindgen_test]
fn fits_and_sweeps() {
    let pts = "[[0,0],[1,1.2],[2,-0.1],[3,0.9],[4,0.2],[5,1.1],[6,0],[7,1]]";
    let r = b2_fit(js(&format!(
        r#"{{"points":{pts},"a":0,"truthCurve":"sine","samples":30}}"#
    )))
    .unwrap();
    let res = f64s(&r, "residuals");
    assert_eq!(res.len(), 8);
    assert!(res.iter().all(|&x| x < 1e-12));
    assert_eq!(f64s(&r, "dataPoints").len(), 24);
    assert!(get(&r, "rms").as_f64().unwrap() > 0.0);
    let r = b2_fit(js(&format!(
        r#"{{"points":{pts},"a":0.1,"knots":"uniform"}}"#
    )))
    .unwrap();
    assert!(get(&r, "residualRms").as_f64().unwrap() > 0.05);
    assert!(get(&r, "rms").is_undefined());
    let s = b2_fit_sweep(js(&format!(
        r#"{{"points":{pts},"aMin":0,"aMax":0.2,"steps":5}}"#
    )))
    .unwrap();
    assert_eq!(
        f64s(&s, "a"),
        vec![0.0, 0.05, 0.1, 0.15000000000000002, 0.2]
    );
    assert_eq!(f64s(&s, "cv").len(), 5);
    assert!(get(&s, "bestCvA").as_f64().unwrap() > 0.0); // zigzag data: smoothing predicts better
    let e = b2_fit(js(r#"{"points":[[0,0],[1,1]]}"#)).unwrap_err();
    assert!(message(e).starts_with("points:"));
    let e = b2_fit_sweep(js(&format!(r#"{{"points":{pts},"aMin":0.3,"aMax":0.1}}"#))).unwrap_err();
    assert!(message(e).starts_with("aMax:"));
    assert!(b2_fit(js(&format!(r#"{{"points":{pts}}}"#))).is_ok());
}
