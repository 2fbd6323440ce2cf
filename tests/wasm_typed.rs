//! wasm-bindgen tests of the O(1) boundary: `at`, `atUV` and `points` given as `Float64Array`s (or flat
//! number arrays) read in one copy give exactly the results of the nested-array forms, and bad entries are
//! named (`at[i]`, `atUV`, `points[i]`, `dim`).
#![cfg(target_arch = "wasm32")]

mod wasm_util;
use wasm_util::*;

use js_sys::Float64Array;
use splinelab::api::b2::{b2_curve, b2_surface};
use splinelab::api::bspline::bspline_curve;
use wasm_bindgen::prelude::*;
use wasm_bindgen_test::*;

fn message(e: JsError) -> String {
    JsValue::from(e)
        .dyn_into::<js_sys::Error>()
        .map(|e| String::from(e.message()))
        .unwrap_or_default()
}

fn typed(xs: &[f64]) -> JsValue {
    Float64Array::from(xs).into()
}

const CURVE: &str = r#"{"degree":3,"points":[[0,0],[1,2],[2,-1],[3,3],[4,0],[5,1]],"derivatives":2,"at":[0,0.1,0.5,0.77,1,0.3]}"#;

#[wasm_bindgen_test]
fn typed_at_equals_nested_at() {
    let nested = bspline_curve(js(CURVE)).unwrap();
    let o = js(CURVE);
    set(&o, "at", &typed(&[0.0, 0.1, 0.5, 0.77, 1.0, 0.3]));
    let fast = bspline_curve(o).unwrap();
    for k in ["params", "points", "d1", "d2"] {
        assert_eq!(f64s(&fast, k), f64s(&nested, k), "{k}");
    }
}

#[wasm_bindgen_test]
fn typed_at_names_a_bad_entry() {
    let o = js(CURVE);
    set(&o, "at", &typed(&[0.0, 0.5, f64::NAN]));
    let m = message(bspline_curve(o).unwrap_err());
    assert!(m.starts_with("at[2]:"), "{m}");
}

#[wasm_bindgen_test]
fn flat_points_with_dim_equal_nested_points() {
    let nested = bspline_curve(js(CURVE)).unwrap();
    let flat = [0.0, 0.0, 1.0, 2.0, 2.0, -1.0, 3.0, 3.0, 4.0, 0.0, 5.0, 1.0];
    for pts in [typed(&flat), js("[0,0,1,2,2,-1,3,3,4,0,5,1]")] {
        let o = js(CURVE);
        set(&o, "points", &pts);
        let r = bspline_curve(o).unwrap();
        assert_eq!(f64s(&r, "points"), f64s(&nested, "points"));
    }
    // 3D through dim: 3 (12 numbers = 4 points)
    let o = js(r#"{"degree":3,"dim":3,"samples":3}"#);
    set(&o, "points", &typed(&flat));
    let r = bspline_curve(o).unwrap();
    assert_eq!(get(&r, "dim").as_f64(), Some(3.0));
    // a count that is not a multiple of dim, a bad dim, a non-finite entry: named
    let o = js(r#"{"degree":1,"dim":3}"#);
    set(&o, "points", &typed(&flat[..10]));
    assert!(message(bspline_curve(o).unwrap_err()).starts_with("points:"));
    let o = js(r#"{"degree":1,"dim":1}"#);
    set(&o, "points", &typed(&flat));
    assert!(message(bspline_curve(o).unwrap_err()).starts_with("dim:"));
    let o = js(r#"{"degree":1}"#);
    set(&o, "points", &typed(&[0.0, 1.0, f64::INFINITY, 2.0]));
    assert!(message(bspline_curve(o).unwrap_err()).starts_with("points[2]:"));
}

#[wasm_bindgen_test]
fn typed_b2_at_and_flat_atuv() {
    let base = r#"{"points":[[0,0],[1,1],[2,0],[3,1],[4,0],[5,1],[6,0]],"a":0.05}"#;
    let dom = f64s(&b2_curve(js(base)).unwrap(), "domain");
    let at = [dom[0], 0.5 * (dom[0] + dom[1]), dom[1]];
    let o = js(base);
    set(&o, "at", &js(&format!("[{},{},{}]", at[0], at[1], at[2])));
    let nested = b2_curve(o).unwrap();
    let o = js(base);
    set(&o, "at", &typed(&at));
    assert_eq!(
        f64s(&b2_curve(o).unwrap(), "points"),
        f64s(&nested, "points")
    );

    let mut grid = String::from("[");
    for i in 0..6 {
        grid.push_str(if i > 0 { ",[" } else { "[" });
        for j in 0..6 {
            if j > 0 {
                grid.push(',');
            }
            grid.push_str(&format!("[{i},{j},{}]", ((i * j) as f64 * 0.3).sin()));
        }
        grid.push(']');
    }
    grid.push(']');
    let base = format!(r#"{{"grid":{grid},"derivatives":1}}"#);
    let o = js(&base);
    set(&o, "atUV", &js("[[0.2,0.3],[1.1,0.9],[0.5,1.7]]"));
    let nested = b2_surface(o).unwrap();
    for uv in [
        typed(&[0.2, 0.3, 1.1, 0.9, 0.5, 1.7]),
        js("[0.2,0.3,1.1,0.9,0.5,1.7]"),
    ] {
        let o = js(&base);
        set(&o, "atUV", &uv);
        let r = b2_surface(o).unwrap();
        for k in ["uv", "points", "du", "dv"] {
            assert_eq!(f64s(&r, k), f64s(&nested, k), "{k}");
        }
    }
    let o = js(&base);
    set(&o, "atUV", &typed(&[0.2, 0.3, 1.1]));
    assert!(message(b2_surface(o).unwrap_err()).starts_with("atUV:"));
    // a grid: the grid sampler gives the values of atUV at the same pairs
    let o = js(&base);
    set(&o, "samplesU", &JsValue::from(5));
    set(&o, "samplesV", &JsValue::from(4));
    let g = b2_surface(o).unwrap();
    let o = js(&base);
    set(&o, "atUV", &typed(&f64s(&g, "uv")));
    let p = b2_surface(o).unwrap();
    for k in ["points", "du", "dv"] {
        let (a, b) = (f64s(&g, k), f64s(&p, k));
        assert!(
            a.iter()
                .zip(&b)
                .all(|(x, y)| (x - y).abs() <= 1e-12 * (1.0 + y.abs())),
            "{k}"
        );
    }
}
