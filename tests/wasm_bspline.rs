//! wasm-bindgen tests of the B-spline exports (run under Node and in headless Chromium by scripts/test.sh).
#![cfg(target_arch = "wasm32")]

mod wasm_util;
use wasm_util::*;

use splinelab::api::bspline::{bspline_basis, bspline_curve};
use wasm_bindgen::prelude::*;
use wasm_bindgen_test::*;

fn message(e: JsValue) -> String {
    e.dyn_into::<js_sys::Error>()
        .map(|e| String::from(e.message()))
        .unwrap_or_default()
}

#[wasm_bindgen_test]
fn curve_has_documented_shape() {
    let r = bspline_curve(js(r#"{"degree":2,"knots":[0,0,0,1,1,1],"points":[[0,0],[1,2],[2,0]],"samples":5,"derivatives":2}"#))
        .unwrap();
    assert_eq!(get(&r, "dim").as_f64(), Some(2.0));
    assert_eq!(f64s(&r, "params"), vec![0.0, 0.25, 0.5, 0.75, 1.0]);
    let p = f64s(&r, "points");
    assert_eq!(p.len(), 10);
    assert!((p[4] - 1.0).abs() < 1e-15 && (p[5] - 1.0).abs() < 1e-15); // midpoint of the quadratic
    assert_eq!(f64s(&r, "d1").len(), 10);
    assert_eq!(f64s(&r, "d2").len(), 10);
}

#[wasm_bindgen_test]
fn basis_rows_sum_to_one() {
    let r = bspline_basis(js(
        r#"{"degree":3,"knots":[0,0,0,0,0.3,0.5,1,1,1,1],"at":[0,0.1,0.3,0.77,1]}"#,
    ))
    .unwrap();
    assert_eq!(get(&r, "count").as_f64(), Some(6.0));
    let v = f64s(&r, "values");
    assert_eq!(v.len(), 30);
    for row in v.chunks(6) {
        assert!((row.iter().sum::<f64>() - 1.0).abs() < 1e-14);
    }
}

#[wasm_bindgen_test]
fn bad_input_throws_error_and_module_keeps_working() {
    let e = bspline_curve(js(r#"{"degree":3,"points":[[0,0],[1,1],[2,0]]}"#))
        .map_err(JsValue::from)
        .unwrap_err();
    assert!(message(e).starts_with("points:"));
    let e = bspline_curve(js(
        r#"{"degree":1,"knots":[0,0,2,1,1],"points":[[0,0],[1,1],[2,0]]}"#,
    ))
    .map_err(JsValue::from)
    .unwrap_err();
    assert!(message(e).contains("knots[3]"));
    let e = bspline_curve(JsValue::from_f64(3.0))
        .map_err(JsValue::from)
        .unwrap_err();
    assert!(message(e).starts_with("options:"));
    // the next valid call works
    assert!(bspline_curve(js(r#"{"degree":1,"points":[[0,0],[1,1]],"samples":3}"#)).is_ok());
}

#[wasm_bindgen_test]
fn de_boor_and_knot_insertion_have_documented_shapes() {
    use splinelab::api::bspline::{bspline_de_boor, bspline_insert_knot};
    let o = r#"{"degree":2,"knots":[0,0,0,1,2,2,2],"points":[[0,0],[1,2],[3,2],[4,0]],"u":0.5}"#;
    let r = bspline_de_boor(js(o)).unwrap();
    assert_eq!(get(&r, "span").as_f64(), Some(2.0));
    let levels: js_sys::Array = get(&r, "levels").dyn_into().unwrap();
    assert_eq!(levels.length(), 3);
    let l1: js_sys::Float64Array = levels.get(1).dyn_into().unwrap();
    assert_eq!(l1.to_vec(), vec![0.5, 1.0, 1.5, 2.0]);
    assert_eq!(f64s(&r, "firstIndex"), vec![0.0, 1.0, 2.0]);
    let p = f64s(&r, "point");
    assert!((p[0] - 1.0).abs() < 1e-15 && (p[1] - 1.5).abs() < 1e-15);
    let ins = bspline_insert_knot(js(o)).unwrap();
    assert_eq!(get(&ins, "first").as_f64(), Some(1.0));
    assert_eq!(f64s(&ins, "alphas"), vec![0.5, 0.25]);
    assert_eq!(f64s(&ins, "points").len(), 10);
    let e = bspline_de_boor(js(r#"{"degree":2,"points":[[0,0],[1,2],[3,2]],"u":3}"#)).unwrap_err();
    assert!(message(e.into()).starts_with("u: "));
}
