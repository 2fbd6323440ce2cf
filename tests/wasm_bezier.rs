//! wasm-bindgen tests of the Gânscă–Coman–Ţămbulea exports (bezierRemodel, bezierRemodelSurface, bezierSpline,
//! bsplineToBezier).
#![cfg(target_arch = "wasm32")]

mod wasm_util;
use wasm_util::*;

use js_sys::{Array, Float64Array, Reflect};
use splinelab::api::bezier::{
    bezier_remodel, bezier_remodel_surface, bezier_remodel_surface_bi, bezier_spline,
    bspline_to_bezier,
};
use wasm_bindgen::prelude::*;
use wasm_bindgen_test::*;

fn rows(o: &JsValue, k: &str) -> Vec<Vec<f64>> {
    get(o, k)
        .dyn_into::<Array>()
        .unwrap()
        .iter()
        .map(|r| r.dyn_into::<Float64Array>().unwrap().to_vec())
        .collect()
}
fn message(e: JsValue) -> String {
    e.dyn_into::<js_sys::Error>()
        .map(|e| String::from(e.message()))
        .unwrap_or_default()
}

const EXAMPLE: &str = r#""points":[[10,16],[7,21],[3,9],[0,0],[-4,0],[-8,0],[-6,3],[-4,6],[2,2],[8,-2],[10,3]],
  "degree":2,"breaks":[0,1,1.75,2.5,3.25,4]"#;
const FIG1: &str = r#""alphas":[[0.6666666666666666,0.05],[null,0.3333333333333333],[null,0.3333333333333333],[null,0.3333333333333333],[null,0.1]]"#;

#[wasm_bindgen_test]
fn remodel_has_documented_shape() {
    let r = bezier_remodel(js(&format!(
        "{{{EXAMPLE},{FIG1},\"r\":1,\"samples\":9,\"derivatives\":2}}"
    )))
    .unwrap();
    assert_eq!(get(&r, "dim").as_f64(), Some(2.0));
    assert_eq!(
        f64s(&r, "params"),
        vec![0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0]
    );
    assert_eq!(f64s(&r, "points").len(), 18);
    assert_eq!(f64s(&r, "d1").len(), 18);
    assert_eq!(f64s(&r, "d2").len(), 18);
    let p = f64s(&r, "points");
    assert_eq!((p[0], p[1]), (10.0, 16.0));
    assert!((p[16] - 10.0).abs() < 1e-14 && (p[17] - 3.0).abs() < 1e-14);
    // b* (Fig. 1): (10,16), (8, 19.333…), (6.8, 20.4), (3, 9), …; (m+1)L + 1 = 16 points
    let b = f64s(&r, "controlPoints");
    assert_eq!(b.len(), 32);
    let want = [10.0, 16.0, 8.0, 58.0 / 3.0, 6.8, 20.4, 3.0, 9.0];
    for (x, w) in b.iter().zip(want) {
        assert!((x - w).abs() < 1e-13, "{b:?}");
    }
    // the α used: nulls filled by eq. (9), α_1^(1) = 1 − α_2^(0) = 0.95
    let al = rows(&r, "alphas");
    assert_eq!(al.len(), 5);
    assert!((al[1][0] - 0.95).abs() < 1e-15);
    let free: Vec<Vec<bool>> = serde_wasm_bindgen::from_value(get(&r, "free")).unwrap();
    assert_eq!(free[0], vec![true, true]);
    assert_eq!(free[3], vec![false, true]);
    let cons: Vec<Vec<String>> = serde_wasm_bindgen::from_value(get(&r, "constraints")).unwrap();
    assert!(
        cons[1][0].contains("α_1^(1) = 1 − α_2^(0)"),
        "{}",
        cons[1][0]
    );
    assert_eq!(cons[1][1], "");
    // curvature at I = 0..L, formula vs measured
    let k = f64s(&r, "curvature");
    let km = f64s(&r, "curvatureMeasured");
    let kp = f64s(&r, "curvaturePredicted");
    assert_eq!(k.len(), 6);
    assert_eq!(f64s(&r, "curvatureOriginal").len(), 6);
    for i in 0..6 {
        assert!((k[i] - km[i]).abs() <= 1e-12 * k[i].max(1.0));
        assert!((k[i] - kp[i]).abs() <= 1e-10 * k[i].max(1.0));
    }
    assert_eq!(f64s(&r, "osculatingRadii").len(), 6);
    assert_eq!(f64s(&r, "osculatingCentres").len(), 12);
    // continuity: L − 1 = 4 rows of r + 2 = 3 jumps; C¹ kept
    let c = rows(&r, "continuity");
    assert_eq!(c.len(), 4);
    for row in &c {
        assert_eq!(row.len(), 3);
        assert!(row[0] < 1e-12 && row[1] < 1e-11);
    }
    assert!(c.iter().any(|row| row[2] > 1.0));
    assert!(get(&r, "crResidual").as_f64().unwrap() < 1e-11);
}

#[wasm_bindgen_test]
fn classical_default_reproduces_the_witness() {
    let a = bezier_remodel(js(&format!("{{{EXAMPLE},\"samples\":50}}"))).unwrap();
    let b = bezier_spline(js(&format!("{{{EXAMPLE},\"samples\":50}}"))).unwrap();
    let (pa, pb) = (f64s(&a, "points"), f64s(&b, "points"));
    assert_eq!(pa.len(), pb.len());
    for (x, y) in pa.iter().zip(&pb) {
        assert!((x - y).abs() < 1e-12);
    }
    assert_eq!(get(&a, "degree").as_f64(), Some(3.0));
    assert_eq!(get(&b, "crResidual").as_f64(), Some(0.0));
    // degree inferred from points and breaks
    let c = bezier_remodel(js(
        r#"{"points":[[10,16],[7,21],[3,9],[0,0],[-4,0]],"breaks":[0,1,1.75],"samples":3}"#,
    ))
    .unwrap();
    assert_eq!(get(&c, "degree").as_f64(), Some(3.0));
}

#[wasm_bindgen_test]
fn surface_example() {
    let pts = r#"[[[0,0,3],[0,1,2],[0,3,1],[0,4,3]],[[1,0,1],[1,1,4],[1,3,2],[1,4,4]],[[2,0,2.5],[2,1,3],[2,3,1],[2,4,3]],
      [[3,0,4],[3,1,2],[3,3,0],[3,4,2]],[[4,0,2.5],[4,1,3],[4,3,1],[4,4,2.5]],[[5,0,1],[5,1,4],[5,3,2],[5,4,3]],
      [[6,0,3],[6,1,0],[6,3,1],[6,4,2]]]"#;
    let r = bezier_remodel_surface(js(&format!(
        r#"{{"points":{pts},"degreeU":2,"degreeV":3,"breaksU":[0,1,2,3],"alphas":[[0.5,0.002],[0.998,0.001],[0.999,0.8]],"r":1,"samplesU":7,"samplesV":3,"derivatives":1}}"#
    )))
    .unwrap();
    assert_eq!(get(&r, "dim").as_f64(), Some(3.0));
    assert_eq!(f64s(&r, "uv").len(), 42);
    assert_eq!(f64s(&r, "points").len(), 63);
    assert_eq!(f64s(&r, "du").len(), 63);
    assert_eq!(f64s(&r, "controlPoints").len(), 10 * 4 * 3);
    assert_eq!(
        (get(&r, "rows").as_f64(), get(&r, "cols").as_f64()),
        (Some(10.0), Some(4.0))
    );
    let c = rows(&r, "continuity");
    assert_eq!(c.len(), 2);
    assert!(c.iter().all(|row| row[1] < 1e-11));
    // the literal "all 1/3" without enforcing is not C¹ (jump 1.5)
    let r = bezier_remodel_surface(js(&format!(
        r#"{{"points":{pts},"breaksU":[0,1,2,3],"alphas":[[0.3333333333333333,0.3333333333333333],[0.3333333333333333,0.3333333333333333],[0.3333333333333333,0.3333333333333333]],"r":1,"enforce":false,"samplesU":2,"samplesV":2}}"#
    )))
    .unwrap();
    let c = rows(&r, "continuity");
    assert!((c[0][1].max(c[1][1]) - 1.5).abs() < 1e-12);
}

#[wasm_bindgen_test]
fn bspline_to_bezier_round_trips() {
    let r = bspline_to_bezier(js(
        r#"{"degree":2,"knots":[0,0,0,1,3,3,3],"points":[[0,0],[1,2],[3,2],[4,0]]}"#,
    ))
    .unwrap();
    assert_eq!(get(&r, "degree").as_f64(), Some(2.0));
    assert_eq!(f64s(&r, "breaks"), vec![0.0, 1.0, 3.0]);
    assert_eq!(f64s(&r, "controlPoints").len(), 10);
    // feed it straight into bezierRemodel
    let opts = js_sys::Object::new();
    Reflect::set(&opts, &"points".into(), &get(&r, "points")).unwrap();
    Reflect::set(&opts, &"degree".into(), &get(&r, "degree")).unwrap();
    Reflect::set(&opts, &"breaks".into(), &get(&r, "breaks")).unwrap();
    Reflect::set(&opts, &"at".into(), &js("[0.5]")).unwrap();
    let g = bezier_remodel(opts.into()).unwrap();
    let p = f64s(&g, "points");
    // the same point as the B-spline
    let b = splinelab::api::bspline::bspline_curve(js(
        r#"{"degree":2,"knots":[0,0,0,1,3,3,3],"points":[[0,0],[1,2],[3,2],[4,0]],"at":[0.5]}"#,
    ))
    .unwrap();
    let q = f64s(&b, "points");
    assert_eq!(p.len(), 2);
    assert!(
        (p[0] - q[0]).abs() < 1e-14 && (p[1] - q[1]).abs() < 1e-14,
        "{p:?} vs {q:?}"
    );
}

#[wasm_bindgen_test]
fn bad_input_throws_error_and_module_keeps_working() {
    let bad = |s: String| message(bezier_remodel(js(&s)).map_err(JsValue::from).unwrap_err());
    let m = bad(format!(
        r#"{{{EXAMPLE},"alphas":[[1.5,0.5],[0.5,0.5],[0.5,0.5],[0.5,0.5],[0.5,0.5]]}}"#
    ));
    assert!(m.starts_with("alphas[0][0]:"), "{m}");
    let m = bad(format!(
        r#"{{{EXAMPLE},"alphas":[[0.5,0],[0.5,0.5],[0.5,0.5],[0.5,0.5],[0.5,0.5]],"enforce":false}}"#
    ));
    assert!(m.starts_with("alphas[0][1]:"), "{m}");
    let m = bad(format!(r#"{{{EXAMPLE},"r":2}}"#));
    assert!(m.starts_with("r:"), "{m}");
    let m = bad(format!(r#"{{{EXAMPLE},"alphas":[[0.5,0.5]]}}"#));
    assert!(m.starts_with("alphas:"), "{m}");
    let m = bad(format!(
        r#"{{{EXAMPLE},"alphas":[[0.5],[0.5,0.5],[0.5,0.5],[0.5,0.5],[0.5,0.5]]}}"#
    ));
    assert!(m.starts_with("alphas[0]:"), "{m}");
    let m = bad(format!(
        r#"{{{EXAMPLE},"alphas":[[null,0.5],[0.5,0.5],[0.5,0.5],[0.5,0.5],[0.5,0.5]]}}"#
    ));
    assert!(m.starts_with("alphas[0][0]:"), "{m}");
    let m = bad(r#"{"points":[[0,0],[1,1],[2,0],[3,1],[4,0]],"degree":2,"breaks":[0,1,1]}"#.into());
    assert!(m.starts_with("breaks[2]:"), "{m}");
    let m = bad(r#"{"points":[[0,0],[1,1],[2,0]],"degree":2,"breaks":[0,1,2]}"#.into());
    assert!(m.starts_with("points:"), "{m}");
    let m = bad(r#"{"points":[[0,0],[1,1],[2,0]],"degree":0}"#.into());
    assert!(m.starts_with("degree:"), "{m}");
    let m = bad(r#"{"points":[[0,0],[1,1],[2,0],[3,1],[4,0],[5,1],[6,0],[7,1],[8,0]],"degree":4,"breaks":[0,1,2],"alphas":[[0.5,0.5,0.5,0.7],[0.5,0.5,0.5,0.5]],"r":2}"#.into());
    assert!(m.starts_with("alphas[0][3]:"), "{m}");
    let e = bezier_remodel(JsValue::from_f64(1.0))
        .map_err(JsValue::from)
        .unwrap_err();
    assert!(message(e).starts_with("options:"));
    let e = bezier_remodel_surface(js(
        r#"{"points":[[[0,0,0],[0,1,0]],[[1,0,0],[1,1,0]]],"degreeU":2,"breaksU":[0,1]}"#,
    ))
    .map_err(JsValue::from)
    .unwrap_err();
    assert!(message(e).starts_with("points:"));
    let e = bspline_to_bezier(js(
        r#"{"degree":1,"knots":[0,0,1,1,2,2],"points":[[0,0],[1,0],[0,1],[1,1]]}"#,
    ))
    .map_err(JsValue::from)
    .unwrap_err();
    assert!(message(e).starts_with("knots:"));
    // the next valid call works
    assert!(bezier_remodel(js(&format!("{{{EXAMPLE},{FIG1},\"samples\":3}}"))).is_ok());
}

// ---- bezierRemodelSurfaceBi (papers branch) ----

/// The biquadratic Bézier net (2L + 1) × (2M + 1) of the uniform quadratic tensor B-spline with control
/// net c (L + 2) × (M + 2): C¹ in u and in v. Rows: odd k → c_{(k+1)/2}, even k → midpoint.
fn biquadratic_net(l: usize, mm: usize) -> Vec<Vec<[f64; 3]>> {
    let c = |i: usize, j: usize| -> [f64; 3] {
        let (x, y) = (i as f64, j as f64);
        [x, y, ((i * 7 + j * 3) % 5) as f64 * 0.4 + 0.1 * x * y]
    };
    let half = |k: usize, f: &dyn Fn(usize) -> [f64; 3]| -> [f64; 3] {
        if k % 2 == 1 {
            f(k.div_ceil(2))
        } else {
            let (a, b) = (f(k / 2), f(k / 2 + 1));
            [
                (a[0] + b[0]) / 2.0,
                (a[1] + b[1]) / 2.0,
                (a[2] + b[2]) / 2.0,
            ]
        }
    };
    (0..=2 * l)
        .map(|k| {
            (0..=2 * mm)
                .map(|q| half(k, &|i| half(q, &|j| c(i, j))))
                .collect()
        })
        .collect()
}

fn net_json(net: &[Vec<[f64; 3]>]) -> String {
    let rows: Vec<String> = net
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

/// `lines` tables of `segs` rows `[a_1, a_2]` (degree 2), varying with the line.
fn tables_json(lines: usize, segs: usize) -> String {
    let t: Vec<String> = (0..lines)
        .map(|l| {
            let rows: Vec<String> = (0..segs)
                .map(|i| {
                    let a1 = 0.3 + 0.05 * ((l + 2 * i) % 7) as f64;
                    let a2 = 0.1 + 0.04 * ((3 * l + i) % 8) as f64;
                    format!("[{a1},{a2}]")
                })
                .collect();
            format!("[{}]", rows.join(","))
        })
        .collect();
    format!("[{}]", t.join(","))
}

#[wasm_bindgen_test]
fn bidegree_keeps_c11_and_the_corners() {
    let (l, mm) = (3, 2);
    let net = biquadratic_net(l, mm);
    let (alphas, betas) = (tables_json(2 * mm + 1, l), tables_json(3 * l + 1, mm));
    let r = bezier_remodel_surface_bi(js(&format!(
        r#"{{"points":{},"breaksU":[0,1,2,3],"breaksV":[0,1,2],"alphas":{alphas},"betas":{betas},"r":1,"s":1,"samplesU":9,"samplesV":5,"derivatives":1}}"#,
        net_json(&net)
    )))
    .unwrap();
    assert_eq!(get(&r, "degreeU").as_f64(), Some(3.0));
    assert_eq!(get(&r, "degreeV").as_f64(), Some(3.0));
    let (rows_n, cols_n) = (3 * l + 1, 3 * mm + 1);
    assert_eq!(get(&r, "rows").as_f64(), Some(rows_n as f64));
    assert_eq!(get(&r, "cols").as_f64(), Some(cols_n as f64));
    assert_eq!(f64s(&r, "points").len(), 9 * 5 * 3);
    let cp = f64s(&r, "controlPoints");
    assert_eq!(cp.len(), rows_n * cols_n * 3);
    for i in 0..=l {
        for j in 0..=mm {
            let k = (3 * i) * cols_n + 3 * j;
            assert_eq!(
                &cp[3 * k..3 * k + 3],
                &net[2 * i][2 * j][..],
                "corner ({i},{j})"
            );
        }
    }
    let (cu, cv) = (rows(&r, "continuityU"), rows(&r, "continuityV"));
    assert_eq!((cu.len(), cv.len()), (l - 1, mm - 1));
    for row in cu.iter().chain(cv.iter()) {
        assert_eq!(row.len(), 3);
        assert!(row[0] < 1e-12 && row[1] < 1e-11, "{row:?}");
        assert!(row[2] > 1e-6, "second derivatives jump: {row:?}");
    }
    // the tables used: one per line, and the columns 1..3 (window of v_1) share column 2's
    let a = get(&r, "alphas").dyn_into::<Array>().unwrap();
    assert_eq!(a.length() as usize, 2 * mm + 1);
    assert_eq!(
        js_sys::JSON::stringify(&a.get(1)).unwrap(),
        js_sys::JSON::stringify(&a.get(2)).unwrap()
    );
    assert_eq!(
        get(&r, "betas").dyn_into::<Array>().unwrap().length() as usize,
        rows_n
    );
    // without enforcing, the per-line parameters break C¹
    let r = bezier_remodel_surface_bi(js(&format!(
        r#"{{"points":{},"breaksU":[0,1,2,3],"breaksV":[0,1,2],"alphas":{alphas},"betas":{betas},"enforce":false,"samplesU":2,"samplesV":2}}"#,
        net_json(&net)
    )))
    .unwrap();
    let worst = rows(&r, "continuityU")
        .iter()
        .chain(rows(&r, "continuityV").iter())
        .map(|row| row[1])
        .fold(0.0, f64::max);
    assert!(worst > 1e-3, "{worst}");
}

#[wasm_bindgen_test]
fn bidegree_classical_default_reproduces_the_surface() {
    let net = net_json(&biquadratic_net(2, 2));
    let opts =
        format!(r#""points":{net},"breaksU":[0,1,2],"breaksV":[0,1,2],"samplesU":7,"samplesV":6"#);
    let bi = bezier_remodel_surface_bi(js(&format!("{{{opts}}}"))).unwrap();
    let uonly = bezier_remodel_surface(js(&format!(r#"{{{opts},"degreeV":2}}"#))).unwrap();
    let (a, b) = (f64s(&bi, "points"), f64s(&uonly, "points"));
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(&b) {
        assert!((x - y).abs() < 1e-12, "{x} vs {y}");
    }
}

#[wasm_bindgen_test]
fn bidegree_bad_input_names_the_field() {
    let net = net_json(&biquadratic_net(2, 2));
    let base =
        format!(r#""points":{net},"breaksU":[0,1,2],"breaksV":[0,1,2],"samplesU":2,"samplesV":2"#);
    let field = |extra: &str| -> String {
        let e = bezier_remodel_surface_bi(js(&format!("{{{base}{extra}}}"))).unwrap_err();
        // the message starts with the field ("field: detail")
        let m = message(JsValue::from(e));
        m.split(": ").next().unwrap_or_default().to_string()
    };
    assert_eq!(
        field(&format!(r#","betas":{}"#, tables_json(3, 2))),
        "betas"
    );
    assert_eq!(field(r#","s":2"#), "s");
    assert_eq!(field(r#","alphas":[[[null,0.2],[0.5,0.2]]]"#), "alphas");
    assert_eq!(
        field(&format!(
            r#","alphas":{}"#,
            tables_json(5, 2).replacen("[0.3,", "[null,", 1)
        )),
        "alphas[0][0][0]"
    );
    assert_eq!(field(r#","alphas":[[0.5,0.2],[0.5,1.5]]"#), "alphas[1][1]");
    assert_eq!(field(r#","degreeV":3"#), "points");
}

#[wasm_bindgen_test]
fn de_casteljau_has_documented_shape() {
    let r = splinelab::api::bezier::bezier_de_casteljau(js(
        r#"{"points":[[0,0],[1,1],[2,0],[3,-1],[4,0]],"degree":2,"breaks":[0,1,3],"u":2}"#,
    ))
    .unwrap();
    assert_eq!(get(&r, "segment").as_f64(), Some(1.0));
    assert_eq!(get(&r, "t").as_f64(), Some(0.5));
    assert_eq!(f64s(&r, "point"), vec![3.0, -0.5]);
}
