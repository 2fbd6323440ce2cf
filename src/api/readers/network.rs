//! The curve network `{ u, v, P, Q }` every export that takes a network reads (`crissCrossSurface`,
//! `thinPlateSurface`, `networkCompatibility`, `networkRepair`, `gordonSurface`, `splineBlendedSurface`,
//! `networkSurfaces`, `surfaceDifferences`, the `networkNorm` exercise check).

use super::tables::{numbers, read_table};
use crate::api::{core_err, err_kind, ApiResult, Opts};
use crate::error::ErrorKind;
use crate::network::Network;
use js_sys::{Array, Float64Array, Reflect};
use wasm_bindgen::prelude::*;

/// Reads the network object `{ u, v, P, Q }` at `key` and checks its shape (not compatibility); errors name
/// `network.P[r][j]` etc. Each curve (`P[r]`, `Q[s]`) may be nested points or flat coordinates (a
/// `Float64Array` or an array of numbers), and each of `P`, `Q` a whole flat table (r-major, n + 2 points
/// per row for `P`, m + 2 for `Q`); `u`, `v` may be `Float64Array`s, at most `network::MAX_BREAKPOINTS`
/// each.
pub fn read_network(o: &Opts, key: &str) -> ApiResult<Network> {
    let obj = o.raw(key);
    if obj.is_undefined() || obj.is_null() {
        return Err(err_kind(ErrorKind::Missing, key, "this field is required"));
    }
    if !obj.is_object() || Array::is_array(&obj) {
        return Err(err_kind(
            ErrorKind::WrongType,
            key,
            "expected a network { u, v, P, Q }",
        ));
    }
    let get = |k: &str| Reflect::get(&obj, &JsValue::from_str(k)).unwrap_or(JsValue::UNDEFINED);
    let mut uv = [Vec::new(), Vec::new()];
    for (slot, k) in uv.iter_mut().zip(["u", "v"]) {
        let field = format!("{key}.{k}");
        let raw = get(k);
        // bound the work before reading: breakpoints per direction
        let len = if let Some(ta) = raw.dyn_ref::<Float64Array>() {
            ta.length() as usize
        } else if Array::is_array(&raw) {
            raw.unchecked_ref::<Array>().length() as usize
        } else {
            0
        };
        if len > crate::network::MAX_BREAKPOINTS {
            return Err(err_kind(
                ErrorKind::TooMany,
                &field,
                format!("at most {} breakpoints", crate::network::MAX_BREAKPOINTS),
            ));
        }
        *slot = numbers(&field, &raw)?;
    }
    let [u, v] = uv;
    let p = read_table(&format!("{key}.P"), &get("P"), v.len() + 1)?;
    let q = read_table(&format!("{key}.Q"), &get("Q"), u.len() + 1)?;
    let net = Network { u, v, p, q };
    net.check_shape().map_err(core_err)?;
    Ok(net)
}
