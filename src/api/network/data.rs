//! Building and checking curve networks: networkFromFunction, networkFromControlNet, networkFromFreeData, networkRepair, networkCompatibility, networkExample.

use super::*;

#[wasm_bindgen(typescript_custom_section)]
const NETWORK_FROM_FUNCTION_TS: &str = r#"
export interface NetworkFromFunctionOptions {
  u: Numbers;
  v: Numbers;
  f: (u: number, v: number) => Point3;
}
"#;

/// The network of the Schoenberg quasi-interpolant of f (always compatible).
///
/// `networkFromFunction({ u, v, f })` → `{ u, v, P, Q }`.
#[wasm_bindgen(js_name = networkFromFunction, unchecked_return_type = "Network")]
pub fn network_from_function(
    #[wasm_bindgen(unchecked_param_type = "NetworkFromFunctionOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let pu = breakpoints(&o, "u")?;
    let pv = breakpoints(&o, "v")?;
    let f = o.function("f")?;
    let (xi, eta) = (pu.greville(), pv.greville());
    if xi.len().saturating_mul(eta.len()) > MAX_INPUT_POINTS {
        return Err(err_kind(
            ErrorKind::TooMany,
            "u",
            format!("(m+2)(n+2) must be at most {MAX_INPUT_POINTS}"),
        ));
    }
    let mut c = Vec::with_capacity(xi.len());
    for &x in &xi {
        let mut row = Vec::with_capacity(eta.len());
        for &y in &eta {
            row.push(call_point_fn("f", &f, x, y)?);
        }
        c.push(row);
    }
    let net = Network::from_control_net(pu.breaks(), pv.breaks(), &c).map_err(core_err)?;
    Ok(network_to_js(&net))
}

#[cfg(feature = "api-network")]
#[wasm_bindgen(typescript_custom_section)]
const NETWORK_FROM_CONTROL_NET_TS: &str = r#"
export interface NetworkFromControlNetOptions {
  u: Numbers;
  v: Numbers;
  /** C[i][j], (m + 2) × (n + 2) points (rows may be flat coordinates, or the whole table flat, i-major). */
  C: NetworkTable;
}
"#;

/// The isocurves of a biquadratic control net.
///
/// `networkFromControlNet({ u, v, C })` → network (isocurves of the biquadratic tensor surface).
#[cfg(feature = "api-network")]
#[wasm_bindgen(js_name = networkFromControlNet, unchecked_return_type = "Network")]
pub fn network_from_control_net(
    #[wasm_bindgen(unchecked_param_type = "NetworkFromControlNetOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let pu = breakpoints(&o, "u")?;
    let pv = breakpoints(&o, "v")?;
    let c = read_table("C", &o.raw("C"), pv.breaks().len() + 1)?;
    let net = Network::from_control_net(pu.breaks(), pv.breaks(), &c).map_err(core_err)?;
    Ok(network_to_js(&net))
}

#[cfg(feature = "api-network")]
#[wasm_bindgen(typescript_custom_section)]
const NETWORK_FROM_FREE_DATA_TS: &str = r#"
export interface NetworkFromFreeDataOptions {
  u: Numbers;
  v: Numbers;
  P: NetworkTable;
  /** Q1[s] = Q_1^(s) (or flat coordinates). */
  Q1: NetworkCurve;
}
"#;

/// A network from its free control points (the other Q from compatibility).
///
/// `networkFromFreeData({ u, v, P, Q1 })` → network.
#[cfg(feature = "api-network")]
#[wasm_bindgen(js_name = networkFromFreeData, unchecked_return_type = "Network")]
pub fn network_from_free_data(
    #[wasm_bindgen(unchecked_param_type = "NetworkFromFreeDataOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let pu = breakpoints(&o, "u")?;
    let pv = breakpoints(&o, "v")?;
    let p = read_table("P", &o.raw("P"), pv.breaks().len() + 1)?;
    let q1 = match o.raw("Q1") {
        q if q.is_undefined() || q.is_null() => {
            return Err(err_kind(ErrorKind::Missing, "Q1", "this field is required"))
        }
        q => read_row("Q1", &q, MAX_INPUT_POINTS)?,
    };
    let net = Network::from_free_data(pu.breaks(), pv.breaks(), p, &q1).map_err(|e| {
        let f = e.field().to_string();
        let f = if f.starts_with("network.") {
            f.trim_start_matches("network.").to_string()
        } else {
            f
        };
        core_err(e.in_field(f))
    })?;
    Ok(network_to_js(&net))
}

#[derive(Deserialize)]
struct RawEdit {
    kind: String,
    r: Option<usize>,
    j: Option<usize>,
    s: Option<usize>,
    i: Option<usize>,
}

#[wasm_bindgen(typescript_custom_section)]
const NETWORK_REPAIR_TS: &str = r#"
export interface NetworkRepairOptions {
  network: NetworkInput;
  edited?: { kind: 'P'; r: number; j: number } | { kind: 'Q'; s: number; i: number };
}
"#;

/// Recomputes the dependent control points so the network is compatible.
///
/// `networkRepair({ network, edited })` → `{ network, c2, dependentQ }`.
#[wasm_bindgen(js_name = networkRepair, unchecked_return_type = "{ network: Network; c2: number; dependentQ: Float64Array }")]
pub fn network_repair(
    #[wasm_bindgen(unchecked_param_type = "NetworkRepairOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let net = read_network(&o, "network")?;
    let edit: Option<RawEdit> = o.opt("edited")?;
    let edited = match edit {
        None => None,
        Some(e) => match (e.kind.as_str(), e.r, e.j, e.s, e.i) {
            ("P", Some(r), Some(j), _, _) => Some(NetPoint::P { r, j }),
            ("Q", _, _, Some(s), Some(i)) => Some(NetPoint::Q { s, i }),
            _ => {
                return Err(err_kind(
                    ErrorKind::Invalid,
                    "edited",
                    "expected { kind: \"P\", r, j } or { kind: \"Q\", s, i }",
                ))
            }
        },
    };
    let fixed = net.repair(edited).map_err(core_err)?;
    let c2 = fixed.compatibility().map_err(core_err)?.c2;
    // which Q_i^{(s)} were recomputed: all but the pivot of each row (Q_1, or the edited interior Q_i)
    let (m, n) = (fixed.m(), fixed.n());
    let mut dependent = Vec::with_capacity((n + 1) * (m + 2));
    for s in 0..=n {
        let pivot = match edited {
            Some(NetPoint::Q { s: es, i }) if es == s && (2..=m).contains(&i) => i,
            _ => 1,
        };
        dependent.extend((0..m + 2).map(|i| if i == pivot { 0.0 } else { 1.0 }));
    }
    Ok(Out::new()
        .set("network", network_to_js(&fixed))
        .num("c2", c2)
        .f64s("dependentQ", &dependent)
        .build())
}

#[wasm_bindgen(typescript_custom_section)]
const NETWORK_COMPATIBILITY_TS: &str = r#"
export interface NetworkCompatibilityOptions extends NetworkTolerance {
  network: NetworkInput;
}
export interface NetworkCompatibilityResult {
  compatible: boolean;
  c2: number;
  worst: Float64Array;
  equation: string;
  scale: number;
  tolerance: number;
  residuals: Float64Array;
}
"#;

/// The compatibility residuals of a network.
///
/// `networkCompatibility({ network, tolerance })` → the residual report.
#[wasm_bindgen(js_name = networkCompatibility, unchecked_return_type = "NetworkCompatibilityResult")]
pub fn network_compatibility(
    #[wasm_bindgen(unchecked_param_type = "NetworkCompatibilityOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let net = read_network(&o, "network")?;
    let tol = read_tolerance(&o)?;
    let rep = net.compatibility().map_err(core_err)?;
    let flat: Vec<f64> = rep.residuals.iter().flatten().copied().collect();
    let t = rep.tolerance(tol);
    Ok(Out::new()
        .set("compatible", rep.c2 <= t)
        .num("c2", rep.c2)
        .f64s("worst", &[rep.worst.0 as f64, rep.worst.1 as f64])
        .set("equation", rep.condition.equation())
        .num("scale", rep.scale)
        .num("tolerance", t)
        .f64s("residuals", &flat)
        .build())
}

#[wasm_bindgen(typescript_custom_section)]
const NETWORK_EXAMPLE_TS: &str = r#"
export interface NetworkExampleOptions {
  name:
    | 'uniform-dome' | 'uniform-random' | 'nonuniform-dome' | 'three-sided' | 'strongly-nonuniform' | 'separable'
    | 'free-data' | 'dome10';
}
"#;

/// A ready network.
///
/// `networkExample({ name })` → network.
#[wasm_bindgen(js_name = networkExample, unchecked_return_type = "Network")]
pub fn network_example(
    #[wasm_bindgen(unchecked_param_type = "NetworkExampleOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let name: String = o.req("name")?;
    let net = examples::by_name(&name).ok_or_else(|| {
        err_kind(
            ErrorKind::Invalid,
            "name",
            format!(
                "expected one of {}, got \"{name}\"",
                examples::NAMES.join(", ")
            ),
        )
    })?;
    Ok(network_to_js(&net))
}
