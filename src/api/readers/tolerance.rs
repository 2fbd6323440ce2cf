//! The tolerance of a network's compatibility check: `tolerance` of every export that takes a curve network
//! (`crissCrossSurface`, `thinPlateSurface`, `networkCompatibility`, `gordonSurface`, `networkSurfaces`,
//! `surfaceDifferences`, the `networkNorm` exercise check, …).

use crate::api::{err_kind, ApiResult, Opts};
use crate::error::ErrorKind;
use crate::network::COMPATIBILITY_TOL;

/// Reads `tolerance`: the relative C2 tolerance of the compatibility check (a number ≥ 0; default
/// [`COMPATIBILITY_TOL`], 1e-12). A negative number is refused (`out-of-range`, "expected a number ≥ 0").
pub fn read_tolerance(o: &Opts) -> ApiResult<f64> {
    let t = o.f64_or("tolerance", COMPATIBILITY_TOL)?;
    if t < 0.0 {
        return Err(err_kind(
            ErrorKind::OutOfRange,
            "tolerance",
            "expected a number ≥ 0",
        ));
    }
    Ok(t)
}
