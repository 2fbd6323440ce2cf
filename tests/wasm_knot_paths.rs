//! wasm-bindgen tests of the knot-modification exports (Juhász–Hoffmann): documented shapes, agreement with the
//! ordinary B-spline, the contact relation (10), limits, and field-named errors that leave the module usable.
#![cfg(target_arch = "wasm32")]

mod wasm_util;
use wasm_util::*;

use js_sys::{Array, Float64Array, Reflect};
use splinelab::api::bspline::bspline_curve;
use splinelab::api::knot_paths::*;
use wasm_bindgen::prelude::*;
use wasm_bindgen_test::*;

fn message(e: JsValue) -> String {
    e.dyn_into::<js_sys::Error>()
        .map(|e| String::from(e.message()))
        .unwrap_or_default()
}
fn fail(r: Result<JsValue, JsError>) -> String {
    message(r.map_err(JsValue::from).unwrap_err())
}

/// Order (4, 3), 7 × 5 net, knotsU interior 1, 2, 3 (indices 4, 5, 6), knotsV interior 1, 2 (3, 4).
fn surface() -> String {
    let mut rows = Vec::new();
    for r in 0..7 {
        let row: Vec<String> = (0..5)
            .map(|s| format!("[{r},{s},{}]", ((r * 7 + s * 3) % 5) as f64 * 0.5 - 1.0))
            .collect();
        rows.push(format!("[{}]", row.join(",")));
    }
    format!(
        r#"{{"orderU":4,"orderV":3,"knotsU":[0,0,0,0,1,2,3,4,4,4,4],"knotsV":[0,0,0,1,2,3,3,3],"controlPoints":[{}]}}"#,
        rows.join(",")
    )
}

const CURVE: &str = r#"{"order":4,"knots":[0,0,0,0,1,2,3,4,5,5,5,5],"controlPoints":[[0,0],[1,2],[2,-1],[3,3],[4,0],[5,2],[6,-1],[7,1]]}"#;

#[wasm_bindgen_test]
fn modified_surface_has_documented_shape_and_is_the_bspline_with_the_new_knot() {
    let s = surface();
    let r = knot_modified_surface(js(&format!(
        r#"{{"surface":{s},"p":5,"up":2.5,"atUV":[[2.2,1.5],[2.7,0.3],[0.5,2.9]],"derivatives":1}}"#
    )))
    .unwrap();
    assert_eq!(get(&r, "dim").as_f64(), Some(3.0));
    assert_eq!(f64s(&r, "uv"), vec![2.2, 1.5, 2.7, 0.3, 0.5, 2.9]);
    assert_eq!(f64s(&r, "points").len(), 9);
    assert_eq!(f64s(&r, "du").len(), 9);
    assert_eq!(
        f64s(&r, "knotsU"),
        vec![0., 0., 0., 0., 1., 2.5, 3., 4., 4., 4., 4.]
    );
    // spans max(p−k+1, k−1)..=min(p+k−2, n) = 3..=6
    assert_eq!(f64s(&r, "affectedSpansU"), vec![3.0, 6.0]);
    // the grid form (u-major) and the default 40 × 40 grid
    let g = knot_modified_surface(js(&format!(
        r#"{{"surface":{s},"p":5,"up":2.5,"samplesU":4,"samplesV":3}}"#
    )))
    .unwrap();
    assert_eq!(f64s(&g, "points").len(), 4 * 3 * 3);
    assert_eq!(&f64s(&g, "uv")[..4], &[0.0, 0.0, 0.0, 1.5]);
    let d = knot_modified_surface(js(&format!(r#"{{"surface":{s},"q":3,"vq":0.5}}"#))).unwrap();
    assert_eq!(f64s(&d, "points").len(), 40 * 40 * 3);
}

#[wasm_bindgen_test]
fn curve_family_matches_bspline_curve_with_the_modified_knot() {
    let r = knot_modified_curve(js(&format!(
        r#"{{"curve":{CURVE},"p":5,"up":1.4,"samples":9,"derivatives":2}}"#
    )))
    .unwrap();
    let b = bspline_curve(js(
        r#"{"degree":3,"knots":[0,0,0,0,1,1.4,3,4,5,5,5,5],"points":[[0,0],[1,2],[2,-1],[3,3],[4,0],[5,2],[6,-1],[7,1]],"samples":9,"derivatives":2}"#,
    ))
    .unwrap();
    for key in ["points", "d1", "d2"] {
        let (x, y) = (f64s(&r, key), f64s(&b, key));
        assert_eq!(x.len(), y.len());
        for (a, c) in x.iter().zip(&y) {
            assert!(
                (a - c).abs() <= 1e-12 * c.abs().max(1.0),
                "{key}: {a} vs {c}"
            );
        }
    }
    assert_eq!(f64s(&r, "affectedRange"), vec![0.0, 5.0]);
    assert_eq!(f64s(&r, "neighbours"), vec![1.0, 3.0]);
}

#[wasm_bindgen_test]
fn envelope_touches_the_family_relation_10() {
    let s = surface();
    // e(u_p, v) = s(u_p, v; u_p) for u_p = 2.4
    let e = knot_envelope(js(&format!(
        r#"{{"surface":{s},"p":5,"atUV":[[2.4,0.7],[2.4,2.2]],"derivatives":1}}"#
    )))
    .unwrap();
    let f = knot_modified_surface(js(&format!(
        r#"{{"surface":{s},"p":5,"up":2.4,"atUV":[[2.4,0.7],[2.4,2.2]],"derivatives":1}}"#
    )))
    .unwrap();
    let (a, b) = (f64s(&e, "points"), f64s(&f, "points"));
    for (x, y) in a.iter().zip(&b) {
        assert!((x - y).abs() < 1e-12);
    }
    // (10) for the first v-derivative, (9) for the first u-derivative: e_w = (k−2)/(k−1) s_u
    let (a, b) = (f64s(&e, "dv"), f64s(&f, "dv"));
    for (x, y) in a.iter().zip(&b) {
        assert!((x - y).abs() < 1e-12);
    }
    let (a, b) = (f64s(&e, "du"), f64s(&f, "du"));
    for (x, y) in a.iter().zip(&b) {
        assert!((x - y * 2.0 / 3.0).abs() < 1e-12);
    }
    assert_eq!(get(&e, "orderU").as_f64(), Some(3.0));
    // (8): both knots; default grid on [u_{p−1}, u_{p+1}] × [v_{q−1}, v_{q+1}]
    let e8 = knot_envelope(js(&format!(
        r#"{{"surface":{s},"p":5,"q":3,"samplesU":3,"samplesV":2}}"#
    )))
    .unwrap();
    assert_eq!(
        f64s(&e8, "uv"),
        vec![1., 0., 1., 2., 2., 0., 2., 2., 3., 0., 3., 2.]
    );
}

#[wasm_bindgen_test]
fn paths_and_path_surfaces_have_documented_shapes_and_limits() {
    let s = surface();
    let r = knot_paths(js(&format!(
        r#"{{"surface":{s},"p":5,"points":[[2.2,1.5],[1.5,0.5]],"from":-1e8,"to":1e8,"samples":3}}"#
    )))
    .unwrap();
    let paths: Array = get(&r, "paths").dyn_into().unwrap();
    assert_eq!(paths.length(), 2);
    let p0: Float64Array = paths.get(0).dyn_into().unwrap();
    assert_eq!(p0.length(), 9);
    assert_eq!(get(&p0, "dim").as_f64(), Some(3.0));
    assert_eq!(f64s(&p0, "params"), vec![-1e8, 0.0, 1e8]);
    // the limits of Theorem 3 at u_p = ∓1e8: the limit control curves at v = 1.5 (rows p and p − k)
    let l = knot_limits(js(&format!(r#"{{"surface":{s},"p":5,"samples":3}}"#))).unwrap();
    assert_eq!(get(&l, "uMinusIndex").as_f64(), Some(5.0));
    assert_eq!(get(&l, "uPlusIndex").as_f64(), Some(1.0));
    let minus = f64s(&l, "uMinusCurve"); // v = 0, 1.5, 3
    let plus = f64s(&l, "uPlusCurve");
    let v = p0.to_vec();
    for c in 0..3 {
        assert!((v[c] - minus[3 + c]).abs() < 1e-6, "u_p → −∞");
        assert!((v[6 + c] - plus[3 + c]).abs() < 1e-6, "u_p → +∞");
    }
    // path-surfaces and the corner limits (corrected Theorem 4)
    let r = knot_paths(js(&format!(
        r#"{{"surface":{s},"p":5,"q":3,"points":[[2.2,1.5]],"from":[-1e8,-1e8],"to":[1e8,1e8],"samples":[2,3]}}"#
    )))
    .unwrap();
    let ps: Array = get(&r, "paths").dyn_into().unwrap();
    let p0: Float64Array = ps.get(0).dyn_into().unwrap();
    assert_eq!(p0.length(), 2 * 3 * 3);
    let l = knot_limits(js(&format!(r#"{{"surface":{s},"p":5,"q":3}}"#))).unwrap();
    let corners = f64s(&l, "corners");
    let v = p0.to_vec();
    // grid (u_p, v_q) = (−,−) index 0, (−,+) index 2, (+,−) index 3, (+,+) index 5
    for (g, c) in [(0, 0), (2, 1), (3, 2), (5, 3)] {
        for i in 0..3 {
            assert!(
                (v[3 * g + i] - corners[3 * c + i]).abs() < 1e-6,
                "corner {c}"
            );
        }
    }
    // curve limits and curve paths
    let l = knot_limits(js(&format!(r#"{{"curve":{CURVE},"p":5}}"#))).unwrap();
    assert_eq!(f64s(&l, "minus"), vec![5.0, 2.0]);
    assert_eq!(f64s(&l, "plus"), vec![1.0, 2.0]);
    let r = knot_paths_curve(js(&format!(
        r#"{{"curve":{CURVE},"p":5,"params":[1.5,2.5],"samples":5}}"#
    )))
    .unwrap();
    assert_eq!(f64s(&r, "params"), vec![1.0, 1.5, 2.0, 2.5, 3.0]);
    let e = knot_envelope_curve(js(&format!(r#"{{"curve":{CURVE},"p":5,"samples":3}}"#))).unwrap();
    assert_eq!(f64s(&e, "params"), vec![1.0, 2.0, 3.0]);
}

#[wasm_bindgen_test]
fn bad_input_throws_error_naming_the_field_and_module_keeps_working() {
    let s = surface();
    assert!(fail(knot_modified_surface(js(&format!(
        r#"{{"surface":{s},"p":2,"up":0.5}}"#
    ))))
    .starts_with("p:"));
    assert!(fail(knot_modified_surface(js(&format!(
        r#"{{"surface":{s},"p":11,"up":0.5}}"#
    ))))
    .starts_with("p:"));
    assert!(fail(knot_modified_surface(js(&format!(
        r#"{{"surface":{s},"p":5}}"#
    ))))
    .starts_with("up:"));
    assert!(fail(knot_modified_surface(js(&format!(
        r#"{{"surface":{s},"p":-1,"up":1}}"#
    ))))
    .starts_with("p:"));
    let bad_order = s.replacen(r#""orderU":4"#, r#""orderU":1"#, 1);
    assert!(fail(knot_modified_surface(js(&format!(
        r#"{{"surface":{bad_order},"p":5,"up":1}}"#
    ))))
    .contains("orderU"));
    let bad_knots = s.replacen("[0,0,0,0,1,2,3,4,4,4,4]", "[0,0,0,0,1,2,3,4,4,4]", 1);
    assert!(fail(knot_modified_surface(js(&format!(
        r#"{{"surface":{bad_knots},"p":5,"up":1}}"#
    ))))
    .contains("knotsU"));
    let ragged = s.replacen("[0,1,", "[0,1,2,3,", 1);
    assert!(fail(knot_envelope(js(&format!(
        r#"{{"surface":{ragged},"p":5}}"#
    ))))
    .contains("controlPoints"));
    assert!(fail(knot_envelope(js(&format!(r#"{{"surface":{s}}}"#)))).starts_with("p:"));
    assert!(fail(knot_paths(js(&format!(
        r#"{{"surface":{s},"p":5,"points":[[1]]}}"#
    ))))
    .starts_with("points[0]"));
    assert!(
        fail(knot_modified_surface(js(r#"{"surface":3,"p":5,"up":1}"#))).starts_with("surface")
    );
    assert!(fail(knot_modified_curve(js(&format!(
        r#"{{"curve":{CURVE},"p":3,"up":1}}"#
    ))))
    .starts_with("p:"));
    // non-finite knot values (JSON cannot carry NaN: build the object in JS)
    let o = js(&format!(r#"{{"surface":{s},"p":5,"up":1}}"#));
    let surf = get(&o, "surface");
    let ku: Array = get(&surf, "knotsU").dyn_into().unwrap();
    ku.set(3, JsValue::from_f64(f64::NAN));
    assert!(fail(knot_modified_surface(o)).contains("knotsU"));
    let o = js(&format!(r#"{{"surface":{s},"p":5}}"#));
    Reflect::set(&o, &"up".into(), &JsValue::from_f64(f64::INFINITY)).unwrap();
    assert!(fail(knot_modified_surface(o)).starts_with("up:"));
    // the next valid call works
    assert!(knot_modified_surface(js(&format!(
        r#"{{"surface":{s},"p":5,"up":9.5,"atUV":[[2,2]]}}"#
    )))
    .is_ok());
}
