//! Helpers shared by the wasm-bindgen test files (`tests/wasm_*.rs`): JSON in, typed arrays out.
#![allow(dead_code)]

use js_sys::{Float64Array, Reflect};
use wasm_bindgen::prelude::*;

/// Parses a JSON literal into a JS value (an options object).
pub fn js(v: &str) -> JsValue {
    js_sys::JSON::parse(v).unwrap()
}
/// `o[k]`.
pub fn get(o: &JsValue, k: &str) -> JsValue {
    Reflect::get(o, &JsValue::from_str(k)).unwrap()
}
/// `o[k] = v`.
pub fn set(o: &JsValue, k: &str, v: &JsValue) {
    Reflect::set(o, &JsValue::from_str(k), v).unwrap();
}
/// `o[k]` as a `Float64Array`, copied out.
pub fn f64s(o: &JsValue, k: &str) -> Vec<f64> {
    get(o, k).dyn_into::<Float64Array>().unwrap().to_vec()
}
/// `JSON.stringify(v)`.
pub fn stringify(v: &JsValue) -> String {
    String::from(js_sys::JSON::stringify(v).unwrap())
}
