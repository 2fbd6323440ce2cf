//! The options of an export, declared once: [`api_options!`] expands one field list — Rust name and type,
//! JavaScript key, TypeScript type, doc line, reader — into
//! * the Rust struct the binding works with,
//! * its `read(&Opts)`, which reads the fields in the listed order with the existing [`Opts`] readers (so
//!   `.field` and `.kind` of every error, typed arrays read in one copy and ignored unknown keys stay as they
//!   are), and
//! * the TypeScript interface, as a `typescript_custom_section` of the declarations wasm-bindgen generates
//!   (`pkg-node/splinelab.d.ts`, shipped in the npm package and copied to `types/splinelab.d.ts`).
//!
//! The exports name these interfaces with `unchecked_param_type` / `unchecked_return_type`; result interfaces
//! and the shared types below are `typescript_custom_section`s next to the code that writes them.
//! `tests/package/types.test.mjs` calls every export with a `Proxy` that records the keys it reads and compares
//! them with the declared ones.
//!
//! [`Opts`]: super::Opts

use wasm_bindgen::prelude::*;

/// Declares an options struct, its reader and its TypeScript interface from one field list:
///
/// ```ignore
/// api_options! {
///     /// Options of `bsplineCurve` (the doc of the TypeScript interface).
///     pub struct BsplineCurveOptions extends "CurveSampling, FlatDim" |o| {
///         /// Degree p (default 3, at most 24).
///         degree: usize = "degree", opt "number" => |k| o.usize_or(k, 3, MAX_DEGREE)?;
///         /// Control points (at least degree + 1).
///         points: Pts = "points", req "Points" => |k| o.points(k, degree + 1)?;
///     }
/// }
/// ```
///
/// A field is `name: RustType = "jsKey", opt|req "TsType" => |k| reader;` — `opt` makes the key optional in
/// TypeScript (`req`: required), `k` is the key inside the reader, and a reader may use the fields listed before it.
///
/// `ext` instead of `opt`/`req` reads a field that another interface declares, mostly one named in `extends` (a
/// shared reader's field such as `tolerance` of `NetworkTolerance`, or a group of fields read by another
/// `api_options!` struct, e.g. `MovedKnots` of the knot exports): it is read in its place in the list (so the
/// first bad field is still the one reported), and gets no line of its own in this TypeScript interface. Its
/// TypeScript type names the declaring interface:
/// `tolerance: f64 = "tolerance", ext "NetworkTolerance" => |_k| read_tolerance(o)?;`.
///
/// Context arguments after the options, `|o, m: usize, segments: usize|`, become parameters of `read` and are in
/// scope in every reader: for options whose checks need values the export has already read or computed (the
/// degree and segment count of a Bézier spline check its α table).
#[macro_export]
macro_rules! api_options {
    (@mark opt) => { "?" };
    (@mark req) => { "" };
    (@doc) => { "" };
    (@doc $one:literal) => { concat!("/**", $one, " */") };
    (@doc $($line:literal)*) => { concat!("/**", $("\n *", $line,)* "\n */") };
    // one line of the interface (none for `ext`: the extended interface declares it)
    (@line ext $key:literal $ts:literal $($fdoc:literal)*) => { "" };
    (@line $req:ident $key:literal $ts:literal $($fdoc:literal)*) => {
        concat!("  ", $crate::api_options!(@doc $($fdoc)*), "\n  ", $key, $crate::api_options!(@mark $req), ": ", $ts, ";\n")
    };
    (
        $(#[doc = $doc:literal])*
        $vis:vis struct $name:ident $(extends $ext:literal)? |$o:ident $(, $arg:ident: $argty:ty)*| {
            $(
                $(#[doc = $fdoc:literal])*
                $field:ident: $ty:ty = $key:literal, $req:ident $ts:literal => |$k:ident| $read:expr;
            )*
        }
    ) => {
        $(#[doc = $doc])*
        $vis struct $name {
            $( $(#[doc = $fdoc])* pub $field: $ty, )*
        }

        impl $name {
            /// Reads the fields from the options object in the order they are declared (so the first bad
            /// field is the one reported).
            // inlined into its caller (mostly the export alone: no struct returned and moved field by field):
            // 2.9 KB raw / 1.3 KB gzip less wasm in the complete module (measured with issue 29's knot_paths)
            #[inline]
            pub fn read($o: &$crate::api::Opts $(, $arg: $argty)*) -> $crate::api::ApiResult<Self> {
                $( let $field: $ty = { let $k: &'static str = $key; $read }; )*
                Ok(Self { $($field),* })
            }
        }

        const _: () = {
            #[wasm_bindgen::prelude::wasm_bindgen(typescript_custom_section)]
            const TS: &'static str = concat!(
                $crate::api_options!(@doc $($doc)*), "\nexport interface ", stringify!($name),
                $(" extends ", $ext,)? " {\n",
                $( $crate::api_options!(@line $req $key $ts $($fdoc)*), )*
                "}\n"
            );
        };
    };
}
pub use api_options;

// The shared types of the declarations: conventions every export uses (docs/API.md), the options read by the
// shared readers of `Opts` (points, grids, curve and surface sampling) and the shared result shapes of `Out`.
#[wasm_bindgen(typescript_custom_section)]
const SHARED_TS: &str = r#"
// Conventions (docs/API.md): one options object in, one plain object out. Numeric arrays in results are
// Float64Arrays (render buffers Float32Array / Uint32Array); points are flat [x0, y0, x1, y1, …] with `dim`.
// A bad argument throws a SplineLabError (an Error with `.field` and `.kind`).

/** A point [x, y] or [x, y, z]. */
export type Point = readonly number[];
/** A 3D point [x, y, z]. */
export type Point3 = readonly [number, number, number] | readonly number[];
/**
 * A list of points: nested `[[x, y], …]` / `[[x, y, z], …]`, or flat coordinates `[x0, y0, x1, y1, …]` (a
 * Float64Array or plain numbers) with the dimension from the option `dim` (default 2).
 */
export type Points = ReadonlyArray<Point> | Float64Array | readonly number[];
/**
 * A rectangular grid of points, `grid[i][j]` = [x, y] or [x, y, z]; or rows of flat coordinates, `grid[i]` =
 * [x0, y0, z0, x1, …] (a Float64Array or plain numbers, one copy per row) with the dimension from the option
 * `dim` (default 3; see {@link GridDim}). All rows nested or all flat.
 */
export type Grid = ReadonlyArray<ReadonlyArray<Point>> | ReadonlyArray<Float64Array | readonly number[]>;
/** A list of numbers (parameters, knots): plain or a Float64Array. */
export type Numbers = readonly number[] | Float64Array;
/** (u, v) pairs: `[[u, v], …]`, or flat `[u0, v0, u1, v1, …]` (a Float64Array or plain numbers). */
export type UVPairs = ReadonlyArray<readonly [number, number] | readonly number[]> | Float64Array | readonly number[];

/** The stable error kinds (`error.kind`). */
export type ErrorKind =
  | 'missing' | 'wrong-type' | 'not-finite' | 'too-few' | 'too-many' | 'out-of-range' | 'not-increasing'
  | 'incompatible' | 'degenerate' | 'invalid';

/** What every export throws on bad input: message `"<field>: <what was expected>"`. */
export interface SplineLabError extends Error {
  /** The offending field, with a path into nested input: `points[3][1]`, `network.P[1][2]`, `surface.knotsU`. */
  field: string;
  kind: ErrorKind;
  /** `too-few`: the minimum; `too-many`: the maximum. */
  expected?: number;
  got?: number;
}

/** Where a curve is evaluated: `at` (parameters in the domain) or `samples` (uniform, both ends; default 200). */
export interface CurveSampling {
  at?: Numbers;
  samples?: number;
  /** 0 (default), 1 adds `d1`, 2 adds `d2`. */
  derivatives?: 0 | 1 | 2;
}

/** Where a surface is evaluated: `atUV` pairs, or a u-major `samplesU` × `samplesV` grid (default 40 × 40). */
export interface SurfaceSampling {
  atUV?: UVPairs;
  samplesU?: number;
  samplesV?: number;
  /** 0 (default) or 1 (adds `du`, `dv`). */
  derivatives?: 0 | 1;
  /** Adds render buffers `mesh` (needs the grid, not `atUV`). */
  mesh?: boolean;
}

/** The dimension of flat `points` (2 or 3; default 2). */
export interface FlatDim {
  dim?: 2 | 3;
}

/** The dimension of a grid's flat rows (2 or 3; default 3). */
export interface GridDim {
  dim?: 2 | 3;
}

/** `{ dim, params, points, d1?, d2? }`, `points.length === params.length * dim`. */
export interface CurveResult {
  dim: number;
  params: Float64Array;
  points: Float64Array;
  d1?: Float64Array;
  d2?: Float64Array;
}

/** Render buffers of a surface grid (u-major, vertex `iu * nv + iv`). */
export interface Mesh {
  nu: number;
  nv: number;
  positions: Float32Array;
  normals: Float32Array;
  indices: Uint32Array;
}

/** `{ dim, uv, points, du?, dv?, mesh? }`. */
export interface SurfaceResult {
  dim: number;
  uv: Float64Array;
  points: Float64Array;
  du?: Float64Array;
  dv?: Float64Array;
  mesh?: Mesh;
}

/** Basis values row after row: `values[r * count + i]`. */
export interface BasisResult {
  count: number;
  params: Float64Array;
  values: Float64Array;
  d1?: Float64Array;
  d2?: Float64Array;
}

/**
 * A curve network `{ u, v, P, Q }`: `P[r][j]` = P_j^(r) (r = 0..m, j = 0..n+1) of the curve φ_r on u = u_r,
 * `Q[s][i]` = Q_i^(s) (s = 0..n, i = 0..m+1) of ψ_s on v = v_s; 3D points as plain arrays.
 */
export interface Network {
  u: number[];
  v: number[];
  P: number[][][];
  Q: number[][][];
}
/**
 * One curve of a network as input: its control points `[[x, y, z], …]`, or flat coordinates
 * `[x0, y0, z0, x1, …]` (a `Float64Array`, read in one copy, or plain numbers).
 */
export type NetworkCurve = ReadonlyArray<Point3> | Numbers;
/**
 * A table of network points as input: one {@link NetworkCurve} per row, or the whole table flat (all points row
 * after row, 3 numbers each; a `Float64Array` or plain numbers).
 */
export type NetworkTable = ReadonlyArray<NetworkCurve> | Numbers;
/** A network as input (readonly arrays, flat curves and flat tables accepted; same results as nested). */
export interface NetworkInput {
  u: Numbers;
  v: Numbers;
  /** P[r]: the control points of φ_r (n + 2 points), or the whole table flat ((m + 1)(n + 2) points, r-major). */
  P: NetworkTable;
  /** Q[s]: the control points of ψ_s (m + 2 points), or the whole table flat ((n + 1)(m + 2) points, s-major). */
  Q: NetworkTable;
}

/** `tolerance` of the compatibility check (relative, ≥ 0; default 1e-12). */
export interface NetworkTolerance {
  tolerance?: number;
}
"#;
