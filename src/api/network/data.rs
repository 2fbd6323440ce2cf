//! Building and checking curve networks: networkFromFunction, networkFromControlNet, networkFromFreeData, networkRepair, networkCompatibility, networkExample.

use super::*;

api_options! {
    /// The options of `networkFromFunction`: the partitions and the function sampled at their Greville points.
    pub struct NetworkFromFunctionOptions |o| {
        /// The breakpoints u_0 < … < u_m.
        u: Partition = "u", req "Numbers" => |k| breakpoints(o, k)?;
        /// The breakpoints v_0 < … < v_n.
        v: Partition = "v", req "Numbers" => |k| breakpoints(o, k)?;
        /// f(u, v) → [x, y, z]: C*_ij = f(ξ_i, η_j) ((m + 2)(n + 2) calls).
        f: js_sys::Function = "f", req "(u: number, v: number) => Point3" => |k| {
            let f = o.function(k)?;
            // bound the calls of f before making them (named by `u`, as before)
            if (u.cells() + 2).saturating_mul(v.cells() + 2) > MAX_INPUT_POINTS {
                return Err(err_kind(
                    ErrorKind::TooMany,
                    "u",
                    format!("(m+2)(n+2) must be at most {MAX_INPUT_POINTS}"),
                ));
            }
            f
        };
    }
}

/// The network of the Schoenberg quasi-interpolant of f (always compatible).
///
/// `networkFromFunction({ u, v, f })` → `{ u, v, P, Q }`.
#[wasm_bindgen(js_name = networkFromFunction, unchecked_return_type = "Network")]
pub fn network_from_function(
    #[wasm_bindgen(unchecked_param_type = "NetworkFromFunctionOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let NetworkFromFunctionOptions { u: pu, v: pv, f } = NetworkFromFunctionOptions::read(&o)?;
    // C*_ij = f(ξ_i, η_j): the core runs the loop, the closure calls the user's function (the core never calls JS)
    let net = Network::try_from_function(&pu, &pv, &mut |x, y| call_point_fn("f", &f, x, y))
        .map_err(|e| match e {
            FromFunctionError::Function(e) => e,
            FromFunctionError::Network(e) => core_err(e),
        })?;
    Ok(network_to_js(&net))
}

#[cfg(feature = "api-network")]
api_options! {
    /// The options of `networkFromControlNet`: the partitions and the biquadratic control net.
    pub struct NetworkFromControlNetOptions |o| {
        /// The breakpoints u_0 < … < u_m.
        u: Partition = "u", req "Numbers" => |k| breakpoints(o, k)?;
        /// The breakpoints v_0 < … < v_n.
        v: Partition = "v", req "Numbers" => |k| breakpoints(o, k)?;
        /// `C[i][j]`, (m + 2) × (n + 2) points (rows may be flat coordinates, or the whole table flat, i-major).
        c: Vec<Vec<DVec3>> = "C", req "NetworkTable" => |k| read_table(k, &o.raw(k), v.breaks().len() + 1)?;
    }
}

/// The isocurves of a biquadratic control net.
///
/// `networkFromControlNet({ u, v, C })` → network (isocurves of the biquadratic tensor surface).
#[cfg(feature = "api-network")]
#[wasm_bindgen(js_name = networkFromControlNet, unchecked_return_type = "Network")]
pub fn network_from_control_net(
    #[wasm_bindgen(unchecked_param_type = "NetworkFromControlNetOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let NetworkFromControlNetOptions { u, v, c } = NetworkFromControlNetOptions::read(&o)?;
    let net = Network::from_control_net(u.breaks(), v.breaks(), &c).map_err(core_err)?;
    Ok(network_to_js(&net))
}

#[cfg(feature = "api-network")]
api_options! {
    /// The options of `networkFromFreeData`: the partitions and the free control points (all P, and Q_1^(s)).
    pub struct NetworkFromFreeDataOptions |o| {
        /// The breakpoints u_0 < … < u_m.
        u: Partition = "u", req "Numbers" => |k| breakpoints(o, k)?;
        /// The breakpoints v_0 < … < v_n.
        v: Partition = "v", req "Numbers" => |k| breakpoints(o, k)?;
        /// `P[r][j]` = P_j^(r), (m + 1) × (n + 2) points (rows may be flat coordinates, or the whole table flat).
        p: Vec<Vec<DVec3>> = "P", req "NetworkTable" => |k| read_table(k, &o.raw(k), v.breaks().len() + 1)?;
        /// `Q1[s]` = Q_1^(s) (or flat coordinates).
        q1: Vec<DVec3> = "Q1", req "NetworkCurve" => |k| required_row(o, k)?;
    }
}

/// A required row of points (`Q1` of `networkFromFreeData`), nested or flat.
#[cfg(feature = "api-network")]
fn required_row(o: &Opts, key: &str) -> ApiResult<Vec<DVec3>> {
    let raw = o.raw(key);
    if raw.is_undefined() || raw.is_null() {
        return Err(err_kind(ErrorKind::Missing, key, "this field is required"));
    }
    read_row(key, &raw, MAX_INPUT_POINTS)
}

/// A network from its free control points (the other Q from compatibility).
///
/// `networkFromFreeData({ u, v, P, Q1 })` → network.
#[cfg(feature = "api-network")]
#[wasm_bindgen(js_name = networkFromFreeData, unchecked_return_type = "Network")]
pub fn network_from_free_data(
    #[wasm_bindgen(unchecked_param_type = "NetworkFromFreeDataOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let NetworkFromFreeDataOptions { u, v, p, q1 } = NetworkFromFreeDataOptions::read(&o)?;
    // the core names the network's tables (`network.P[1]`); here they are the options `P`, `Q1`
    let net = Network::from_free_data(u.breaks(), v.breaks(), p, &q1).map_err(|e| {
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

api_options! {
    /// The options of `networkRepair`: the network and the control point the user moved.
    pub struct NetworkRepairOptions |o| {
        /// The network (its P and free Q are kept).
        network: Network = "network", req "NetworkInput" => |k| read_network(o, k)?;
        /// The moved control point, kept as it is (default: none).
        edited: Option<NetPoint> = "edited",
            opt "{ kind: 'P'; r: number; j: number } | { kind: 'Q'; s: number; i: number }" => |k| read_edited(o, k)?;
    }
}

#[derive(Deserialize)]
struct RawEdit {
    kind: String,
    r: Option<usize>,
    j: Option<usize>,
    s: Option<usize>,
    i: Option<usize>,
}

/// `edited` of `networkRepair`: `{ kind: "P", r, j }` or `{ kind: "Q", s, i }` (absent: none).
#[inline]
fn read_edited(o: &Opts, key: &str) -> ApiResult<Option<NetPoint>> {
    let edit: Option<RawEdit> = o.opt(key)?;
    Ok(match edit {
        None => None,
        Some(e) => match (e.kind.as_str(), e.r, e.j, e.s, e.i) {
            ("P", Some(r), Some(j), _, _) => Some(NetPoint::P { r, j }),
            ("Q", _, _, Some(s), Some(i)) => Some(NetPoint::Q { s, i }),
            _ => {
                return Err(err_kind(
                    ErrorKind::Invalid,
                    key,
                    "expected { kind: \"P\", r, j } or { kind: \"Q\", s, i }",
                ))
            }
        },
    })
}

/// Recomputes the dependent control points so the network is compatible.
///
/// `networkRepair({ network, edited })` → `{ network, c2, dependentQ }`.
#[wasm_bindgen(js_name = networkRepair, unchecked_return_type = "{ network: Network; c2: number; dependentQ: Float64Array }")]
pub fn network_repair(
    #[wasm_bindgen(unchecked_param_type = "NetworkRepairOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let NetworkRepairOptions {
        network: net,
        edited,
    } = NetworkRepairOptions::read(&o)?;
    let r = net.repair_report(edited).map_err(core_err)?;
    Ok(Out::new()
        .set("network", network_to_js(&r.network))
        .num("c2", r.c2)
        .f64s("dependentQ", &r.dependent_q)
        .build())
}

api_options! {
    /// The options of `networkCompatibility`: the network and the tolerance of the check.
    pub struct NetworkCompatibilityOptions extends "NetworkTolerance" |o| {
        /// The network (checked for shape; its compatibility is the result).
        network: Network = "network", req "NetworkInput" => |k| read_network(o, k)?;
    }
}

#[wasm_bindgen(typescript_custom_section)]
const NETWORK_COMPATIBILITY_TS: &str = r#"
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
    let NetworkCompatibilityOptions { network: net } = NetworkCompatibilityOptions::read(&o)?;
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

api_options! {
    /// The options of `networkExample`: which ready network.
    pub struct NetworkExampleOptions |o| {
        /// The example's name.
        name: String = "name", req "'uniform-dome' | 'uniform-random' | 'nonuniform-dome' | 'three-sided' \
            | 'strongly-nonuniform' | 'separable' | 'free-data' | 'dome10'" => |k| o.req(k)?;
    }
}

/// A ready network.
///
/// `networkExample({ name })` → network.
#[wasm_bindgen(js_name = networkExample, unchecked_return_type = "Network")]
pub fn network_example(
    #[wasm_bindgen(unchecked_param_type = "NetworkExampleOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let NetworkExampleOptions { name } = NetworkExampleOptions::read(&o)?;
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
