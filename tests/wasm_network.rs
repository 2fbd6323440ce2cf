//! wasm-bindgen tests of the curve-network exports (Node and headless Chromium).
#![cfg(target_arch = "wasm32")]

mod wasm_util;
use wasm_util::*;

use js_sys::{Function, Object};
use splinelab::api::network::*;
use wasm_bindgen::prelude::*;
use wasm_bindgen_test::*;

fn message(e: JsValue) -> String {
    e.dyn_into::<js_sys::Error>()
        .map(|e| String::from(e.message()))
        .unwrap_or_default()
}

/// networkFromFunction on U = {0,1/3,2/3,1} × V = {0,.5,1} for f = (u, v, u² + uv − v²).
fn network() -> JsValue {
    let o = js(r#"{"u":[0,0.3333333333333333,0.6666666666666666,1],"v":[0,0.5,1]}"#);
    set(
        &o,
        "f",
        &Function::new_with_args("u, v", "return [u, v, u*u + u*v - v*v]").into(),
    );
    network_from_function(o).unwrap()
}

fn with_network(extra: &str, net: &JsValue) -> JsValue {
    let o = js(extra);
    set(&o, "network", net);
    o
}

#[wasm_bindgen_test]
fn network_from_function_has_documented_shape() {
    let net = network();
    let p = arr(&get(&net, "P"));
    let q = arr(&get(&net, "Q"));
    assert_eq!(p.length(), 4); // m + 1
    assert_eq!(arr(&p.get(0)).length(), 4); // n + 2
    assert_eq!(q.length(), 3); // n + 1
    assert_eq!(arr(&q.get(0)).length(), 5); // m + 2
    assert_eq!(arr(&arr(&p.get(1)).get(2)).length(), 3);
    let rep = network_compatibility(with_network("{}", &net)).unwrap();
    assert_eq!(get(&rep, "compatible").as_bool(), Some(true));
    assert!(get(&rep, "c2").as_f64().unwrap() < 1e-15);
    assert_eq!(f64s(&rep, "residuals").len(), 12);
}

#[wasm_bindgen_test]
fn criss_cross_surface_shape_and_c11_independence() {
    let net = network();
    let a = criss_cross_surface(with_network(
        r#"{"samplesU":7,"samplesV":5,"derivatives":1,"C11":[1,0,3]}"#,
        &net,
    ))
    .unwrap();
    assert_eq!(get(&a, "dim").as_f64(), Some(3.0));
    assert_eq!(f64s(&a, "uv").len(), 70);
    let pa = f64s(&a, "points");
    assert_eq!(pa.len(), 105);
    assert_eq!(f64s(&a, "du").len(), 105);
    let c = f64s(&a, "controlPoints");
    assert_eq!(c.len(), 5 * 4 * 3);
    assert_eq!(&c[(4 + 1) * 3..(4 + 1) * 3 + 3], &[1.0, 0.0, 3.0]); // C_11
    assert_eq!(f64s(&a, "C11"), vec![1.0, 0.0, 3.0]);
    // x = u, y = v are reproduced; the grid is u-major
    assert!((pa[3 * 5] - 1.0 / 6.0).abs() < 1e-14 && pa[3 * 5 + 1].abs() < 1e-14);
    let b = criss_cross_surface(with_network(
        r#"{"samplesU":7,"samplesV":5,"evaluate":"sum","C11":[1.5,1.5,32]}"#,
        &net,
    ))
    .unwrap();
    let pb = f64s(&b, "points");
    for k in 0..pa.len() {
        assert!((pa[k] - pb[k]).abs() < 1e-12);
    }
    // the default C11 is reported
    let d = criss_cross_surface(with_network(r#"{"atUV":[[0.2,0.7]]}"#, &net)).unwrap();
    assert_eq!(f64s(&d, "C11").len(), 3);
    assert_eq!(f64s(&d, "points").len(), 3);
}

#[wasm_bindgen_test]
fn basis_values_and_cells() {
    let r = criss_cross_basis(js(r#"{"u":[0,1,2,3,4],"v":[0,1,2,3,4],"i":2,"j":2,"atUV":[[1.5,1.5],[0.9,0.9],[3.9,3.9]],"derivatives":1}"#)).unwrap();
    let v = f64s(&r, "values");
    assert_eq!(v.len(), 3);
    assert!((v[0] - 0.5).abs() < 1e-15);
    assert!(v[1] > 0.0 && v[2] == 0.0);
    assert_eq!(f64s(&r, "du").len(), 3);
    let g = criss_cross_basis(js(
        r#"{"u":[0,0.5,1],"v":[0,0.5,1],"i":0,"j":3,"samplesU":4,"samplesV":3}"#,
    ))
    .unwrap();
    assert_eq!(f64s(&g, "values").len(), 12);
    let cells = criss_cross_cells(js(r#"{"u":[0,1,2,3,4],"v":[0,1,2,3,4],"i":2,"j":2}"#)).unwrap();
    assert_eq!(get(&cells, "m").as_f64(), Some(4.0));
    let ord = f64s(&cells, "ordinates");
    assert_eq!(ord.len(), 16 * 13);
    // central cell (2,2): block (2−1)·4 + (2−1) = 5, centre ordinate 1/2
    assert!((ord[5 * 13 + 12] - 0.5).abs() < 1e-15);
    assert_eq!(f64s(&cells, "domainPoints").len(), 16 * 26);
    let support = f64s(&cells, "support");
    assert_eq!(support.iter().sum::<f64>(), 28.0);
    let s = criss_cross_cells(with_network("{}", &network())).unwrap();
    assert_eq!(get(&s, "dim").as_f64(), Some(3.0));
    assert_eq!(f64s(&s, "ordinates").len(), 6 * 13 * 3);
}

#[wasm_bindgen_test]
fn thin_plate_shape() {
    let t = thin_plate_surface(with_network(r#"{"samplesU":3,"samplesV":3}"#, &network())).unwrap();
    assert_eq!(f64s(&t, "points").len(), 27);
    let c = f64s(&t, "C11");
    assert!(
        (c[0] - 1.0 / 6.0).abs() < 1e-13 && (c[1] - 0.25).abs() < 1e-13,
        "{c:?}"
    );
    assert!(get(&t, "energy").as_f64().unwrap() > 0.0);
    assert_eq!(f64s(&t, "controlPoints").len(), 60);
}

#[wasm_bindgen_test]
fn repair_free_data_control_net_and_examples() {
    let net = network();
    // drag P_1^{(1)}: the network becomes incompatible; repair keeps the dragged point
    let p = arr(&get(&net, "P"));
    arr(&p.get(1)).set(1, js("[0.4,0.3,0.9]"));
    let e = criss_cross_surface(with_network("{}", &net))
        .map_err(JsValue::from)
        .unwrap_err();
    let msg = message(e);
    assert!(
        msg.starts_with("network:") && msg.contains("C2") && msg.contains("r = 1"),
        "{msg}"
    );
    let fixed =
        network_repair(with_network(r#"{"edited":{"kind":"P","r":1,"j":1}}"#, &net)).unwrap();
    assert!(get(&fixed, "c2").as_f64().unwrap() < 1e-14);
    let dep = f64s(&fixed, "dependentQ");
    assert_eq!(dep.len(), 3 * 5);
    assert_eq!(&dep[0..5], &[1.0, 0.0, 1.0, 1.0, 1.0]);
    let fnet = get(&fixed, "network");
    assert!(stringify(&fnet).contains("[0.4,0.3,0.9]"));
    assert!(criss_cross_surface(with_network(r#"{"samplesU":2,"samplesV":2}"#, &fnet)).is_ok());
    let free = network_from_free_data(js(
        r#"{"u":[0,1,2],"v":[0,1],"P":[[[0,0,0],[0,0.5,0],[0,1,0]],[[1,0,1],[1,0.5,2],[1,1,1]],[[2,0,0],[2,0.5,0],[2,1,0]]],"Q1":[[0.5,0,0.3],[0.5,1,0.2]]}"#,
    ))
    .unwrap();
    let rep = network_compatibility(with_network("{}", &free)).unwrap();
    assert_eq!(get(&rep, "compatible").as_bool(), Some(true));
    let cn = network_from_control_net(js(r#"{"u":[0,1],"v":[0,1],"C":[[[0,0,0],[0,1,0],[0,2,0]],[[1,0,0],[1,1,1],[1,2,0]],[[2,0,0],[2,1,0],[2,2,0]]]}"#)).unwrap();
    assert_eq!(arr(&get(&cn, "P")).length(), 2);
    let ex = network_example(js(r#"{"name":"three-sided"}"#)).unwrap();
    assert!(criss_cross_surface(with_network(r#"{"samplesU":3,"samplesV":3}"#, &ex)).is_ok());
    let e = network_example(js(r#"{"name":"nope"}"#))
        .map_err(JsValue::from)
        .unwrap_err();
    assert!(message(e).starts_with("name:"));
}

#[wasm_bindgen_test]
fn bad_input_names_the_field_and_module_keeps_working() {
    let net = network();
    // wrong shape: drop a row of P
    let p = arr(&get(&net, "P"));
    p.pop();
    let e = criss_cross_surface(with_network("{}", &net))
        .map_err(JsValue::from)
        .unwrap_err();
    assert!(message(e).starts_with("network.P"), "shape");
    let e = thin_plate_surface(js(
        r#"{"network":{"u":[0,1],"v":[0,1],"P":[[[0,0,0],[0,1,0],[0,2,NaN]]],"Q":[]}}"#
            .replace("NaN", "0")
            .as_str(),
    ))
    .map_err(JsValue::from)
    .unwrap_err();
    assert!(message(e).starts_with("network."));
    let e = criss_cross_basis(js(
        r#"{"u":[0,1,1,2],"v":[0,1],"i":0,"j":0,"atUV":[[0,0]]}"#,
    ))
    .map_err(JsValue::from)
    .unwrap_err();
    assert!(message(e).starts_with("u[2]"), "breakpoints");
    let e = criss_cross_basis(js(r#"{"u":[0,1],"v":[0,1],"i":5,"j":0,"atUV":[[0,0]]}"#))
        .map_err(JsValue::from)
        .unwrap_err();
    assert!(message(e).starts_with("i:"));
    // a missing part is named (the reader of flat/typed networks reads each part: was "network:" from serde)
    let e = criss_cross_surface(js(r#"{"network":{"u":[0,1]}}"#))
        .map_err(JsValue::from)
        .unwrap_err();
    assert!(message(e).starts_with("network.v:"));
    let o = js(r#"{"u":[0,1],"v":[0,1]}"#);
    set(
        &o,
        "f",
        &Function::new_with_args("u, v", "return [u, NaN, 0]").into(),
    );
    let e = network_from_function(o).map_err(JsValue::from).unwrap_err();
    assert!(message(e).starts_with("f:"));
    let e = criss_cross_surface(with_network(r#"{"C11":[1,2]}"#, &network()))
        .map_err(JsValue::from)
        .unwrap_err();
    assert!(message(e).starts_with("C11:"));
    let e = network_repair(with_network(r#"{"edited":{"kind":"X"}}"#, &network()))
        .map_err(JsValue::from)
        .unwrap_err();
    assert!(message(e).starts_with("edited:"));
    let e = criss_cross_surface(Object::new().into())
        .map_err(JsValue::from)
        .unwrap_err();
    assert!(message(e).starts_with("network:"));
    let huge = js_sys::Array::new();
    for _ in 0..100_001 {
        huge.push(&js_sys::Array::new());
    }
    let net = js(r#"{"u":[0,1],"v":[0,1],"Q":[]}"#);
    set(&net, "P", &huge);
    let e = criss_cross_surface(with_network("{}", &net))
        .map_err(JsValue::from)
        .unwrap_err();
    assert!(message(e).starts_with("network.P:"));
    // the next valid call works
    assert!(
        criss_cross_surface(with_network(r#"{"samplesU":2,"samplesV":2}"#, &network())).is_ok()
    );
}

fn arr(v: &JsValue) -> js_sys::Array {
    v.clone().unchecked_into::<js_sys::Array>()
}
