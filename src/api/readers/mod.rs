//! The option readers that more than one binding module shares: each reads one kind of field from the options
//! object, with the `.field`, `.kind` and message of every error fixed here, so that each binding module imports
//! only from the API layer (`Opts`, `Out`, these readers), never from another binding module.
//!
//! Not gated by a cargo feature (unlike the binding modules): a group module built without a reader's callers
//! links none of its code (the linker drops what no export reaches).
//!
//! * [`read_tension`]: `tension`, `tensionU`, `tensionV` (a number or one per vertex);
//! * [`B2Options`] and [`read_b2_options`]: the B2 options of `b2Curve`, `b2Basis`, `b2Fit`, `b2FitSweep` and the
//!   `fitError` exercise check; [`read_knot_choice`]: a B2 knot choice (`knots`, `knotsU`, `knotsV`);
//! * [`read_network`]: a curve network `{ u, v, P, Q }`;
//! * [`read_row`], [`read_table`]: rows and tables of 3D points, nested or flat;
//! * [`read_tolerance`]: the relative tolerance of a network's compatibility check.

mod b2_options;
mod network;
mod tables;
mod tension;
mod tolerance;

pub use b2_options::{read_b2_options, read_knot_choice, B2Options};
pub use network::read_network;
pub use tables::{read_row, read_table};
pub use tension::read_tension;
pub use tolerance::read_tolerance;
