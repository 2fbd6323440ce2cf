//! wasm-bindgen tests of `curveFacts` (the facts behind a 2D curve figure's words, issue 25): the options read from
//! JavaScript (rows or a `Float64Array`), the result's shape and numbers, errors with `.field` and `.kind`.
#![cfg(target_arch = "wasm32")]

mod wasm_util;
use wasm_util::*;

use js_sys::{Float64Array, Reflect};
use splinelab::api::facts::curve_facts_js;
use wasm_bindgen::prelude::*;
use wasm_bindgen_test::*;

fn field_kind(e: JsValue) -> (String, String) {
    let f = Reflect::get(&e, &"field".into())
        .unwrap()
        .as_string()
        .unwrap_or_default();
    let k = Reflect::get(&e, &"kind".into())
        .unwrap()
        .as_string()
        .unwrap_or_default();
    (f, k)
}

#[wasm_bindgen_test]
fn s_curve_from_a_typed_array() {
    // y = (u − 0.4)³ at u = 0, 0.01, …, 1, flat in a Float64Array: one inflection at u = 0.4
    let us: Vec<f64> = (0..=100).map(|k| k as f64 / 100.0).collect();
    let xy: Vec<f64> = us.iter().flat_map(|&u| [u, (u - 0.4).powi(3)]).collect();
    let o = js("{}");
    set(&o, "points", &Float64Array::from(&xy[..]).into());
    set(&o, "params", &Float64Array::from(&us[..]).into());
    let r = curve_facts_js(o).unwrap();
    let infl = f64s(&r, "inflectionParams");
    assert_eq!(infl.len(), 1);
    assert!((infl[0] - 0.4).abs() < 2e-3, "{infl:?}");
    assert_eq!(f64s(&r, "inflectionPoints").len(), 2);
    let highest = get(&r, "highest");
    assert_eq!(get(&highest, "u").as_f64(), Some(1.0));
    assert!(get(&r, "distances").is_undefined());
}

#[wasm_bindgen_test]
fn distances_to_rows_of_data() {
    let r = curve_facts_js(js(
        r#"{"points":[[0,0],[4,0]],"data":[[2,3],[-3,4],[5,0]]}"#,
    ))
    .unwrap();
    assert_eq!(f64s(&r, "distances"), vec![3.0, 5.0, 1.0]);
    assert_eq!(get(&r, "maxDistance").as_f64(), Some(5.0));
    assert_eq!(get(&r, "maxDistanceIndex").as_f64(), Some(1.0));
    assert_eq!(get(&r, "length").as_f64(), Some(4.0));
}

#[wasm_bindgen_test]
fn bad_input_names_field_and_kind() {
    let cases = [
        (r#"{"points":[[0,0]]}"#, "points", "too-few"),
        (
            r#"{"points":[[0,0],[1,1]],"params":[0]}"#,
            "params",
            "incompatible",
        ),
        (
            r#"{"points":[[0,0],[1,1]],"params":[1,0]}"#,
            "params[1]",
            "not-increasing",
        ),
        (r#"{"points":[[0,0,0],[1,1,1]]}"#, "points", "invalid"),
        (
            r#"{"points":[[0,0],[1,1]],"data":[[1,2,3]]}"#,
            "data",
            "invalid",
        ),
        (r#"{"params":[0,1]}"#, "points", "missing"),
    ];
    for (opts, field, kind) in cases {
        let e = curve_facts_js(js(opts)).map_err(JsValue::from).unwrap_err();
        assert_eq!(
            field_kind(e),
            (field.to_string(), kind.to_string()),
            "{opts}"
        );
    }
}
