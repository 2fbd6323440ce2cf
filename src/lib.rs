//! # SplineLab
//!
//! Exact spline constructions of five research papers, as a plain Rust library (the *core*) with a thin
//! WebAssembly binding (`api`, the only module that knows about JavaScript).
//!
//! | module | what |
//! | --- | --- |
//! | [`error`] | the error type that names the bad input |
//! | [`point`] | the point abstraction (`f64`, `DVec2`, `DVec3`) and curvature helpers |
//! | [`linalg`] | small dense linear solves with point-valued right-hand sides |
//! | [`sample`] | the `Curve`/`Surface` traits, batch evaluation into flat buffers |
//! | [`basis`] | Cox–de Boor basis functions and their derivatives |
//! | [`kernel`] | the fast samplers: piecewise polynomials per span, tensor-product grids |
//! | [`knots`] | knot vectors: uniform, clamped, chord-length, averaging, validation, span search, insertion |
//! | [`bspline`] | Cox–de Boor basis, de Boor evaluation, curves, tensor surfaces, global interpolation |
//! | [`b2spline`] | Kuklišová: interpolating ↔ approximating B2-splines, tension, modified knots, surfaces |
//! | [`rng`] | the two seeded pseudo-random generators (example networks, noisy data), side by side |
//! | [`fit`] | noisy data: seeded generators, fit measures, choice of the approximation parameter |
//! | [`quasi_cubic`] | the quasi-cubic paper: quasi-cubic trigonometric B-splines, BIS, surfaces |
//! | [`bezier`] | Gânscă–Coman–Ţămbulea: Bézier splines, parametric degree elevation keeping C^r, curvature at joints |
//! | [`knot_paths`] | Juhász–Hoffmann: knot modification, paths, path-surfaces, limits, envelopes |
//! | [`network`] | curve networks: compatibility conditions, builders |
//! | [`criss_cross`] | Dagnino–Lamberti–Remogna: C¹ quadratic B-splines on criss-cross triangulations, the surface S |
//! | [`thin_plate`] | Dagnino–Lamberti–Remogna §4.2 the thin-plate tensor-product surface T |
//! | [`gordon`] | Dagnino–Lamberti–Remogna §4.2 the Gordon boolean sum G; Kuklišová §7 the spline-blended GB |
//! | [`facts`] | facts of a sampled plane curve for a description in words: extremes, inflections, length, distances to data |
//! | [`mesh`] | surface tessellation to render buffers |
//! | [`exercise`] | the measures of self-checking exercises: distance to data, C^k jumps, fit error, ellipse, ‖S − G‖, envelope point |
//!
//! Every construction is a value built once by a fallible `new` (an [`Error`] names the bad input and has an
//! [`ErrorKind`], which the JavaScript binding throws as `error.field` / `error.kind`) and evaluated through
//! the [`Curve`] or [`Surface`] trait. Each public construction type documents, in one template, the paper
//! and equation it implements, what it interpolates, its continuity and its parametrisation, with a
//! runnable example; `tests/conformance.rs` checks those claims for every type. How to add a construction,
//! run each test layer, and the lint policy: `CONTRIBUTING.md`.

pub mod b2spline;
pub mod basis;
pub mod bezier;
pub mod bspline;
pub mod criss_cross;
pub mod error;
pub mod exercise;
pub mod facts;
pub mod fit;
pub mod gordon;
pub mod kernel;
pub mod knot_paths;
pub mod knots;
pub mod linalg;
pub mod mesh;
pub mod network;
pub mod point;
pub mod quasi_cubic;
pub mod rng;
pub mod sample;
pub mod thin_plate;

#[cfg(target_arch = "wasm32")]
pub mod api;

pub use error::{Error, ErrorKind, Result};
pub use point::Point;
pub use sample::{Curve, Surface};
