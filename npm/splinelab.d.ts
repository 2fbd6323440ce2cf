// TypeScript declarations of the SplineLab module: every export of the wasm build (www/pkg, pkg-node), with typed
// options and results. Written by hand from docs/API.md and the option readers of src/api/*.rs; tests/package/
// types.test.mjs checks them against the module so they cannot drift: every export is declared (and every
// declaration exported), every option key the Rust bindings read is in that export's options (and every declared
// key is read), and the keys of real results are declared.
//
// Conventions (docs/API.md): one options object in, one plain object out. Numeric arrays in results are
// Float64Arrays (render buffers Float32Array / Uint32Array); points are flat [x0, y0, x1, y1, …] with `dim`.
// A bad argument throws a SplineLabError (an Error with `.field` and `.kind`).

// ------------------------------------------------------------------------------------------------- shared types

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

// ------------------------------------------------------------------------------------------------- B-spline basics

export interface BsplineCurveOptions extends CurveSampling, FlatDim {
  /** Degree p (default 3, at most 24). */
  degree?: number;
  /** Full knot vector (points + degree + 1 knots); default clamped uniform on [0, 1]. */
  knots?: Numbers;
  /** Control points (at least degree + 1). */
  points: Points;
}
export interface BsplineCurveResult extends CurveResult {
  knots: Float64Array;
}
/** The ordinary B-spline curve. */
export function bsplineCurve(options: BsplineCurveOptions): BsplineCurveResult;

export interface BsplineBasisOptions {
  degree?: number;
  /** Full knot vector (required). */
  knots: Numbers;
  at?: Numbers;
  samples?: number;
  derivatives?: 0 | 1 | 2;
}
/** All basis functions N_0..N_{count−1} at each parameter. */
export function bsplineBasis(options: BsplineBasisOptions): BasisResult;

export interface BsplineAtOptions extends FlatDim {
  /** Degree p (default 3, at most 24). */
  degree?: number;
  /** Full knot vector (points + degree + 1 knots); default clamped uniform on [0, 1]. */
  knots?: Numbers;
  /** Control points (at least degree + 1). */
  points: Points;
  /** The parameter, in the domain [knots[degree], knots[len − degree − 1]] (`out-of-range` otherwise). */
  u: number;
}
export interface BsplineDeBoorResult {
  dim: number;
  /** k with t_k ≤ u < t_{k+1} (the last non-empty span at the right end). */
  span: number;
  u: number;
  /** `levels[r]` = P^r_i for i = firstIndex[r] … k, flat: level 0 the p + 1 points acting at u, level p = C(u). */
  levels: Float64Array[];
  /** `alphas[r]` = α_{i,r} = (u − t_i)/(t_{i+p+1−r} − t_i) of level r (`alphas[0]` empty). */
  alphas: Float64Array[];
  /** k − p + r per level r. */
  firstIndex: Float64Array;
  /** C(u), the single point of level p. */
  point: Float64Array;
}
/** Every intermediate point of de Boor's algorithm at u (for steppers). */
export function bsplineDeBoor(options: BsplineAtOptions): BsplineDeBoorResult;

export interface BsplineInsertKnotResult {
  dim: number;
  /** k with t_k ≤ u < t_{k+1}. */
  span: number;
  u: number;
  /** k − p + 1: the new Q_first … Q_k replace P_first … P_{k−1}. */
  first: number;
  /** α_i = (u − t_i)/(t_{i+p} − t_i) at `alphas[i − first]`, Q_i = (1 − α_i) P_{i−1} + α_i P_i. */
  alphas: Float64Array;
  /** The new knot vector (one more knot). */
  knots: Float64Array;
  /** The new control points, flat (one more point): the same curve. */
  points: Float64Array;
}
/** Boehm's insertion of the knot u once. */
export function bsplineInsertKnot(options: BsplineAtOptions): BsplineInsertKnotResult;

/** The crate version, e.g. "0.1.0". */
export function version(): string;

// ------------------------------------------------------------------------------------------------- quasi-cubic

export interface QuasiCubicBasisOptions {
  /** α (default 1; any finite |α| ≤ 1e6). */
  alpha?: number;
  at?: Numbers;
  samples?: number;
  /** 0..3 (3 adds `d3`). */
  derivatives?: 0 | 1 | 2 | 3;
}
export interface QuasiCubicBasisResult {
  params: Float64Array;
  /** Four values B_0..B_3 per parameter. */
  values: Float64Array;
  d1?: Float64Array;
  d2?: Float64Array;
  d3?: Float64Array;
}
/** The quasi-cubic trigonometric basis B_0..B_3 on t ∈ [0, 1]. */
export function quasiCubicBasis(options: QuasiCubicBasisOptions): QuasiCubicBasisResult;

export interface QuasiCubicCurveOptions extends CurveSampling, FlatDim {
  /** Control points b_0..b_{n+2} (at least 4). */
  points: Points;
  /** α ∈ [−3, 3] (default 1). */
  alpha?: number;
  /** Periodic curve of N ≥ 4 points (default false). */
  closed?: boolean;
}
export interface QuasiCubicCurveResult extends CurveResult {
  domain: Float64Array;
  segments: number;
}
/** The quasi-cubic trigonometric B-spline curve. */
export function quasiCubicCurve(options: QuasiCubicCurveOptions): QuasiCubicCurveResult;

export interface QuasiCubicInterpolationOptions extends CurveSampling, FlatDim {
  /** b_{−1}..b_{n+1}. */
  points: Points;
  /** n + 1 numbers ≥ 0, or "curvature" (default all 1). */
  beta?: Numbers | 'curvature';
  /** The allocated function's k (2..10, default 3). */
  k?: number;
  /** Default 3 (other values: Remark 2's blend with the α-spline). */
  alpha?: number;
  /** Adds `curvature` at each parameter. */
  curvature?: boolean;
}
export interface QuasiCubicInterpolationResult extends CurveResult {
  beta: Float64Array;
  domain: Float64Array;
  circleCurvature: Float64Array;
  curvature?: Float64Array;
}
/** The blended interpolation spline (BIS). */
export function quasiCubicInterpolation(options: QuasiCubicInterpolationOptions): QuasiCubicInterpolationResult;

export interface QuasiCubicSurfaceOptions extends SurfaceSampling, GridDim {
  /** (m + 3) × (n + 3) control points. */
  grid: Grid;
  alpha?: number;
  periodicU?: boolean;
  periodicV?: boolean;
}
export interface QuasiCubicSurfaceResult extends SurfaceResult {
  /** [u0, u1, v0, v1]. */
  domain: Float64Array;
}
/** The tensor-product quasi-cubic surface. */
export function quasiCubicSurface(options: QuasiCubicSurfaceOptions): QuasiCubicSurfaceResult;

export interface QuasiCubicBlendedSurfaceOptions extends SurfaceSampling, GridDim {
  /** (m + 3) × (n + 3) = b_{−1..m+1, −1..n+1}. */
  grid: Grid;
  /** (m + 1) × (n + 1) numbers ≥ 0 (default all 1). */
  beta?: ReadonlyArray<Numbers>;
  k?: number;
  alpha?: number;
}
export interface QuasiCubicBlendedSurfaceResult extends SurfaceResult {
  beta: Float64Array;
  domain: Float64Array;
}
/** The blended interpolation surface. */
export function quasiCubicBlendedSurface(options: QuasiCubicBlendedSurfaceOptions): QuasiCubicBlendedSurfaceResult;

export type QuasiCubicCurvePresetName = 'ellipse' | 'circle' | 'parabola' | 'sine';
export type QuasiCubicSurfacePresetName = 'sphere' | 'cylinder' | 'torus' | 'bowl' | 'wavy';
export interface QuasiCubicPresetOptions {
  name: QuasiCubicCurvePresetName | QuasiCubicSurfacePresetName;
  /** Ellipse half-axes (2, 1). */
  a?: number;
  b?: number;
  /** Circle, sphere, cylinder (1). */
  radius?: number;
  /** Cylinder (2). */
  height?: number;
  /** Torus (1.5, 0.5). */
  major?: number;
  minor?: number;
  /** Sine (4). */
  segments?: number;
  /** Wavy (4, 4). */
  m?: number;
  n?: number;
}
export interface QuasiCubicCurvePreset {
  name: string;
  kind: 'curve';
  alpha: number;
  closed: boolean;
  points: number[][];
  condition: string;
}
export interface QuasiCubicSurfacePreset {
  name: string;
  kind: 'surface';
  alpha: number;
  grid: number[][][];
  periodicU: boolean;
  periodicV: boolean;
  exact: { centre?: number[]; radius?: number; axis?: number[]; major?: number; minor?: number };
}
/** Control data of an exact shape, ready to pass back. */
export function quasiCubicPreset(options: QuasiCubicPresetOptions & { name: QuasiCubicCurvePresetName }): QuasiCubicCurvePreset;
export function quasiCubicPreset(options: QuasiCubicPresetOptions & { name: QuasiCubicSurfacePresetName }): QuasiCubicSurfacePreset;
export function quasiCubicPreset(options: QuasiCubicPresetOptions): QuasiCubicCurvePreset | QuasiCubicSurfacePreset;

export interface QuasiCubicShapeCheckOptions extends FlatDim {
  shape: QuasiCubicCurvePresetName;
  /** 2D control points. */
  points: Points;
  alpha?: number;
  /** Samples per segment (default 200, at most 10,000). */
  samples?: number;
}
export interface QuasiCubicShapeCheckResult {
  deviation: number;
  conditionResidual: number;
  segmentResiduals: Float64Array;
  alphaOk: boolean;
  condition: string;
  analytic: Float64Array;
  params: Float64Array;
}
/** How far a quasi-cubic curve is from the exact shape its control points define. */
export function quasiCubicShapeCheck(options: QuasiCubicShapeCheckOptions): QuasiCubicShapeCheckResult;

// ------------------------------------------------------------------------------------------------- B2-splines

/** A number or one per vertex p_0..p_n. */
export type Tension = number | Numbers;
/** The B2 options shared by b2Curve, b2Basis, b2Fit and b2FitSweep. */
export interface B2Options {
  /** The family parameter (0 interpolates, 1/6 is the cubic B-spline; default 0). */
  a?: number;
  /** Default 1/6. */
  tension?: Tension;
  /** false (default), "paper", "turning" (true = "paper"). */
  autoTension?: boolean | 'paper' | 'turning';
  /** The p of automatic tension (default 0.2). */
  autoTensionScale?: number;
  /** "chord" (default), "uniform" or u_{−1}..u_{n+2}. */
  knots?: 'chord' | 'uniform' | Numbers;
  /** Modified knots u′_2i = (u_{i−1} + K u_i + u_{i+1}) / (K + 2); null = none. */
  K?: number | null;
  /** 1 (default, as printed) or 2; any number ≥ 0. */
  c2?: number;
  construction?: 'nonuniform' | 'section3';
}

export interface B2CurveOptions extends B2Options, CurveSampling, FlatDim {
  /** W_{−1}..W_{n+2} (n ≥ 2). */
  points: Points;
  /** Adds `curvature` (and in 2D `normals`). */
  curvature?: boolean;
  /**
   * The last weight of eq. (5) for the odd vertices: "corrected" (default) b²/((b+c)(b+c+d)), or "printed"
   * b·c/((b+c)(b+c+d)) as in the paper (the curve then misses its joints where the spans differ).
   */
  eq5?: 'corrected' | 'printed';
}
export interface B2CurveResult extends CurveResult {
  domain: Float64Array;
  knots: Float64Array;
  controlPoints: Float64Array;
  joints: Float64Array;
  evenVertices: Float64Array;
  tension: Float64Array;
  dataKnots: Float64Array;
  jointParams: Float64Array;
  /** 3 per joint R_i, on W_{i−1}, W_i, W_{i+1}. */
  jointWeights: Float64Array;
  /** 4 per even vertex C_{2i}, on W_{i−1}..W_{i+2}. */
  evenWeights: Float64Array;
  /** 3 per joint: the eq. (5) weights on C_{2i−2}, C_{2i−1}, C_{2i} that gave the odd vertices. */
  eq5Weights: Float64Array;
  /** |L^a(u′_{2i}) − R_i|, i = 1..n (rounding-level unless eq5: "printed"). */
  jointResiduals: Float64Array;
  curvature?: Float64Array;
  normals?: Float64Array;
}
/** The B2-spline curve L^a. */
export function b2Curve(options: B2CurveOptions): B2CurveResult;

export interface B2BasisOptions extends B2Options, FlatDim {
  /** Data points (the knots and automatic tension come from them), or give `knots`. */
  points?: Points;
  /** n + 4 (with knots: "uniform"). */
  count?: number;
  at?: Numbers;
  samples?: number;
  derivatives?: 0 | 1 | 2;
}
export interface B2BasisResult extends BasisResult {
  domain: Float64Array;
  dataKnots: Float64Array;
  jointParams: Float64Array;
}
/** The blending functions L_{−1}..L_{n+2}. */
export function b2Basis(options: B2BasisOptions): B2BasisResult;

export interface B2SurfaceOptions extends SurfaceSampling, GridDim {
  /** W_ij, i = −1..m+2, j = −1..n+2 (at least 6 × 6). */
  grid: Grid;
  a?: number;
  tensionU?: Tension;
  tensionV?: Tension;
  /** "uniform" (default), "chord" or u_{−1}..u_{m+2}. */
  knotsU?: 'chord' | 'uniform' | Numbers;
  knotsV?: 'chord' | 'uniform' | Numbers;
  c2?: number;
}
export interface B2SurfaceResult extends SurfaceResult {
  domain: Float64Array;
  dataKnotsU: Float64Array;
  dataKnotsV: Float64Array;
}
/** The tensor-product B2-spline surface. */
export function b2Surface(options: B2SurfaceOptions): B2SurfaceResult;

export interface SplineBlendedSurfaceOptions extends SurfaceSampling, NetworkTolerance {
  /** A function (u, v) => [x, y, z] (sampled on the lines only) or a curve network. */
  network: ((u: number, v: number) => Point3) | NetworkInput;
  uKnots?: Numbers;
  vKnots?: Numbers;
  blend?: 'b2' | 'cubic-natural' | 'cubic-notaknot';
  a?: number;
  tensionU?: Tension;
  tensionV?: Tension;
  c2?: number;
}
/** The spline-blended (boolean sum) surface G = G1 + G2 − G12. */
export function splineBlendedSurface(options: SplineBlendedSurfaceOptions): SurfaceResult;

export type KnownCurveName = 'sine' | 'arc' | 'lemniscate' | 'spiral' | 'step';
/** The known curves of noisyData and the data sets of dataset. */
export function fitNames(): { curves: string[]; datasets: string[] };

export interface NoisyDataOptions {
  curve?: KnownCurveName;
  count?: number;
  sigma?: number;
  seed?: number;
  truthSamples?: number;
}
export interface NoisyDataResult {
  curve: string;
  count: number;
  sigma: number;
  seed: number;
  params: Float64Array;
  clean: Float64Array;
  points: Float64Array;
  truth: Float64Array;
}
/** Seeded noisy samples of a known curve. */
export function noisyData(options: NoisyDataOptions): NoisyDataResult;

export interface DatasetOptions {
  name: 'titanium_heat' | 'rpn14';
}
/** A classic data set, embedded in the module. */
export function dataset(options: DatasetOptions): { name: string; source: string; count: number; points: Float64Array };

export interface B2FitMeasureOptions {
  /** A dense polyline of the known curve. */
  truth?: Points;
  truthCurve?: KnownCurveName;
  /** Default 400. */
  errorSamples?: number;
}
export interface B2FitOptions extends B2Options, B2FitMeasureOptions, CurveSampling, FlatDim {
  /** 2D data D_1..D_N (N ≥ 3). */
  points: Points;
  curvature?: boolean;
}
export interface B2FitResult extends CurveResult {
  domain: Float64Array;
  knots: Float64Array;
  controlPoints: Float64Array;
  joints: Float64Array;
  evenVertices: Float64Array;
  tension: Float64Array;
  jointParams: Float64Array;
  curvature?: Float64Array;
  normals?: Float64Array;
  dataPoints: Float64Array;
  residuals: Float64Array;
  residualRms: number;
  rms?: number;
  max?: number;
}
/** The B2 curve of data with reflected ends, and its fit measures. */
export function b2Fit(options: B2FitOptions): B2FitResult;

export interface B2FitSweepOptions extends B2Options, B2FitMeasureOptions, FlatDim {
  points: Points;
  aValues?: Numbers;
  aMin?: number;
  aMax?: number;
  steps?: number;
  /** Leave-one-out cross-validation (default true). */
  cv?: boolean;
}
export interface B2FitSweepResult {
  a: Float64Array;
  residualRms: Float64Array;
  rms?: Float64Array;
  max?: Float64Array;
  cv?: Float64Array;
  bestCvA?: number;
  bestA?: number;
}
/** The fit measures over many values of a. */
export function b2FitSweep(options: B2FitSweepOptions): B2FitSweepResult;

// ------------------------------------------------------------------------------------------------- Bézier remodelling

/** `alphas[I][k − 1]`; `null` where eq. (9) fixes the entry (with enforce). */
export type AlphaTable = ReadonlyArray<ReadonlyArray<number | null>>;

export interface BezierSplineOptions extends CurveSampling, FlatDim {
  /** b_0..b_{mL}. */
  points: Points;
  /** m (inferred from the points and breaks; 3 when neither is given). */
  degree?: number;
  /** u_0..u_L (default 0, 1, …, L). */
  breaks?: Numbers;
}
export interface BezierSplineResult extends CurveResult {
  degree: number;
  breaks: Float64Array;
  curvature: Float64Array;
  crResidual: number;
  continuity: Float64Array[];
}
/** The Bézier spline g itself (the witness curve). */
export function bezierSpline(options: BezierSplineOptions): BezierSplineResult;

export interface BezierDeCasteljauOptions extends FlatDim {
  /** b_0..b_{mL}; with neither degree nor breaks, one segment of degree points − 1 on [0, 1]. */
  points: Points;
  degree?: number;
  /** u_0..u_L (default 0, 1, …, L). */
  breaks?: Numbers;
  /** The parameter, in [u_0, u_L] (required). */
  u: number;
}
export interface BezierDeCasteljauResult {
  dim: number;
  degree: number;
  /** The segment I holding u (the right-hand one at an interior breakvalue, the last at u_L). */
  segment: number;
  u: number;
  /** The local t = (u − u_I)/(u_{I+1} − u_I). */
  t: number;
  /** `levels[r]` = b^r_0 … b^r_{m−r}, flat; b^r_k = (1 − t) b^{r−1}_k + t b^{r−1}_{k+1}. */
  levels: Float64Array[];
  /** g(u). */
  point: Float64Array;
}
/** Every intermediate point of de Casteljau's algorithm at u (for steppers). */
export function bezierDeCasteljau(options: BezierDeCasteljauOptions): BezierDeCasteljauResult;

export interface BezierRemodelOptions extends BezierSplineOptions {
  alphas?: AlphaTable;
  /** The class C^r kept (default ⌊m/2⌋). */
  r?: number;
  /** Apply eq. (9) (default true). */
  enforce?: boolean;
  /** One-call curvature sweep over α_m^(I−1). */
  alphaSweep?: Numbers;
  alphaSweepJoint?: number;
}
export interface BezierRemodelResult extends CurveResult {
  degree: number;
  breaks: Float64Array;
  controlPoints: Float64Array;
  alphas: Float64Array[];
  curvature: Float64Array;
  curvatureOriginal: Float64Array;
  curvatureMeasured: Float64Array;
  curvaturePredicted: Float64Array;
  curvaturePrinted: Float64Array;
  curvatureRatio: Float64Array;
  osculatingCentres: Float64Array;
  osculatingRadii: Float64Array;
  r: number;
  enforce: boolean;
  crResidual: number;
  crResidualOriginal: number;
  continuity: Float64Array[];
  continuityOriginal: Float64Array[];
  continuityMax: Float64Array;
  continuityScale: Float64Array;
  free: boolean[][];
  constraints: string[][];
  sweepCurvature?: Float64Array;
  sweepCurvaturePrinted?: Float64Array;
}
/** The Bézier spline raised to degree m + 1 with free parameters α, keeping C^r. */
export function bezierRemodel(options: BezierRemodelOptions): BezierRemodelResult;

export interface BezierRemodelSurfaceOptions extends SurfaceSampling, GridDim {
  /** points[k][l], k = 0..mL along u. */
  points: Grid;
  degreeU?: number;
  degreeV?: number;
  breaksU?: Numbers;
  breaksV?: Numbers;
  alphas?: AlphaTable;
  r?: number;
  enforce?: boolean;
}
export interface BezierRemodelSurfaceResult extends SurfaceResult {
  controlPoints: Float64Array;
  degreeU: number;
  degreeV: number;
  rows: number;
  cols: number;
  alphas: Float64Array[];
  r: number;
  continuity: Float64Array[];
  continuityOriginal: Float64Array[];
  free: boolean[][];
  constraints: string[][];
}
/** Remodelling of a Bézier spline surface in u (one patch row in v). */
export function bezierRemodelSurface(options: BezierRemodelSurfaceOptions): BezierRemodelSurfaceResult;

export interface BezierRemodelSurfaceBiOptions extends SurfaceSampling, GridDim {
  points: Grid;
  degreeU?: number;
  degreeV?: number;
  breaksU?: Numbers;
  breaksV?: Numbers;
  /** One table [I][k − 1] shared by every column, or one per column [l][I][k − 1]. */
  alphas?: AlphaTable | ReadonlyArray<AlphaTable>;
  /** One table [J][l − 1] shared by every row, or one per row. */
  betas?: AlphaTable | ReadonlyArray<AlphaTable>;
  r?: number;
  s?: number;
  enforce?: boolean;
}
export interface BezierRemodelSurfaceBiResult extends SurfaceResult {
  controlPoints: Float64Array;
  degreeU: number;
  degreeV: number;
  rows: number;
  cols: number;
  alphas: Float64Array[][];
  betas: Float64Array[][];
  r: number;
  s: number;
  continuityU: Float64Array[];
  continuityV: Float64Array[];
  continuityUOriginal: Float64Array[];
  continuityVOriginal: Float64Array[];
}
/** The bi-degree remodelling (m, n) → (m + 1, n + 1), keeping C^{r,s}. */
export function bezierRemodelSurfaceBi(options: BezierRemodelSurfaceBiOptions): BezierRemodelSurfaceBiResult;

export interface BsplineToBezierOptions extends FlatDim {
  degree?: number;
  knots?: Numbers;
  points: Points;
}
export interface BsplineToBezierResult {
  degree: number;
  breaks: Float64Array;
  /** Plain nested points, ready for bezierRemodel. */
  points: number[][];
  controlPoints: Float64Array;
  dim: number;
}
/** A B-spline as a Bézier spline on its domain. */
export function bsplineToBezier(options: BsplineToBezierOptions): BsplineToBezierResult;

// ------------------------------------------------------------------------------------------------- curve networks

export interface CrissCrossSurfaceOptions extends SurfaceSampling, NetworkTolerance {
  network: NetworkInput;
  /** [x, y, z], "area" (default) or "edges". */
  C11?: Point3 | 'area' | 'edges';
  evaluate?: 'local' | 'sum';
}
export interface CrissCrossSurfaceResult extends SurfaceResult {
  controlPoints: Float64Array;
  C11: Float64Array;
  c2: number;
}
/** The C¹ quadratic criss-cross surface S through a network. */
export function crissCrossSurface(options: CrissCrossSurfaceOptions): CrissCrossSurfaceResult;

export interface CrissCrossBasisOptions extends SurfaceSampling {
  u: Numbers;
  v: Numbers;
  i: number;
  j: number;
}
export interface CrissCrossBasisResult {
  uv: Float64Array;
  values: Float64Array;
  du?: Float64Array;
  dv?: Float64Array;
  mesh?: Mesh;
}
/** The C¹ quadratic B-spline B_ij on the criss-cross triangulation. */
export function crissCrossBasis(options: CrissCrossBasisOptions): CrissCrossBasisResult;

export interface CrissCrossCellsOptions extends NetworkTolerance {
  network?: NetworkInput;
  u?: Numbers;
  v?: Numbers;
  i?: number;
  j?: number;
}
export interface CrissCrossCellsResult {
  m: number;
  n: number;
  dim: number;
  ordinates: Float64Array;
  domainPoints: Float64Array;
  support?: Float64Array;
}
/** The 13 Bernstein–Bézier ordinates of every cell (of B_ij, or of S's local form). */
export function crissCrossCells(options: CrissCrossCellsOptions): CrissCrossCellsResult;

export interface ThinPlateSurfaceOptions extends SurfaceSampling, NetworkTolerance {
  network: NetworkInput;
}
export interface ThinPlateSurfaceResult extends SurfaceResult {
  C11: Float64Array;
  energy: number;
  controlPoints: Float64Array;
}
/** The biquadratic surface of minimal thin-plate energy through a network. */
export function thinPlateSurface(options: ThinPlateSurfaceOptions): ThinPlateSurfaceResult;

export interface GordonSurfaceOptions extends SurfaceSampling, NetworkTolerance {
  network: NetworkInput;
  /** Adds `components: { L1, L2, Tg }`. */
  components?: boolean;
}
export interface TensorSurfaceData {
  knotsU: Float64Array;
  knotsV: Float64Array;
  countU: number;
  countV: number;
  controlPoints: Float64Array;
}
export interface GordonExtras extends TensorSurfaceData {
  knotsUBar: Float64Array;
  knotsVBar: Float64Array;
  components?: { L1: TensorSurfaceData; L2: TensorSurfaceData; Tg: TensorSurfaceData };
}
export interface GordonSurfaceResult extends SurfaceResult, GordonExtras {}
/** The biquadratic Gordon (boolean sum) surface G through a network. */
export function gordonSurface(options: GordonSurfaceOptions): GordonSurfaceResult;

export type NetworkSurfaceName = 'S' | 'T' | 'G' | 'GB' | 'L1' | 'L2' | 'Tg';
/** Limits: network ≤ 65 breakpoints per direction; samplesU × samplesV × surfaces ≤ 200,000; normSamples ≤ 200;
 * curveSamples ≤ 1024 (beyond: an Error with kind "too-many" naming the field). */
export interface NetworkSurfacesOptions extends NetworkTolerance {
  /** At most 65 breakpoints per direction. */
  network: NetworkInput;
  /** samplesU × samplesV × surfaces ≤ 200,000. */
  samplesU?: number;
  samplesV?: number;
  surfaces?: ReadonlyArray<NetworkSurfaceName>;
  blend?: 'cubic-natural' | 'cubic-notaknot';
  /** Two names, e.g. "SG": adds `colors`. */
  colorBy?: string;
  components?: boolean;
  /** Compute `norms` (default true; false skips them and the surfaces only they need). */
  norms?: boolean;
  /** The norms' grid (default 57, at most 200; < 2 omits `norms`). */
  normSamples?: number;
  /** Adds `curves: { phi, psi }` (at most 1024 points per curve). */
  curveSamples?: number;
}
export interface SurfaceNorms {
  SG?: number;
  ST?: number;
  TG?: number;
  SGB?: number;
  GGB?: number;
}
export interface NetworkSurfacesResult {
  names: string[];
  available: string[];
  samplesU: number;
  samplesV: number;
  surfaces: { [name: string]: { points: Float64Array; mesh: Mesh } };
  norms?: SurfaceNorms;
  gordon: GordonExtras;
  colors?: Float32Array;
  curves?: { phi: Float64Array[]; psi: Float64Array[] };
}
/** Every surface through one network, tessellated on one grid, in one call. */
export function networkSurfaces(options: NetworkSurfacesOptions): NetworkSurfacesResult;

export interface SurfaceDifferencesOptions extends NetworkTolerance {
  /** At most 65 breakpoints per direction. */
  network: NetworkInput;
  /** The grid side, 2 ..= 200 (default 57). */
  samples?: number;
  blend?: 'cubic-natural' | 'cubic-notaknot';
}
/** ‖A − B‖∞ of the network surfaces on a samples × samples grid. */
export function surfaceDifferences(options: SurfaceDifferencesOptions): SurfaceNorms & { samples: number };

export interface NetworkFromFunctionOptions {
  u: Numbers;
  v: Numbers;
  f: (u: number, v: number) => Point3;
}
/** The network of the Schoenberg quasi-interpolant of f (always compatible). */
export function networkFromFunction(options: NetworkFromFunctionOptions): Network;

export interface NetworkFromControlNetOptions {
  u: Numbers;
  v: Numbers;
  /** C[i][j], (m + 2) × (n + 2) points (rows may be flat coordinates, or the whole table flat, i-major). */
  C: NetworkTable;
}
/** The isocurves of a biquadratic control net. */
export function networkFromControlNet(options: NetworkFromControlNetOptions): Network;

export interface NetworkFromFreeDataOptions {
  u: Numbers;
  v: Numbers;
  P: NetworkTable;
  /** Q1[s] = Q_1^(s) (or flat coordinates). */
  Q1: NetworkCurve;
}
/** A network from its free control points (the other Q from compatibility). */
export function networkFromFreeData(options: NetworkFromFreeDataOptions): Network;

export interface NetworkRepairOptions {
  network: NetworkInput;
  edited?: { kind: 'P'; r: number; j: number } | { kind: 'Q'; s: number; i: number };
}
/** Recomputes the dependent control points so the network is compatible. */
export function networkRepair(options: NetworkRepairOptions): { network: Network; c2: number; dependentQ: Float64Array };

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
/** The compatibility residuals of a network. */
export function networkCompatibility(options: NetworkCompatibilityOptions): NetworkCompatibilityResult;

export interface NetworkExampleOptions {
  name:
    | 'uniform-dome' | 'uniform-random' | 'nonuniform-dome' | 'three-sided' | 'strongly-nonuniform' | 'separable'
    | 'free-data' | 'dome10';
}
/** A ready network. */
export function networkExample(options: NetworkExampleOptions): Network;

// ------------------------------------------------------------------------------------------------- knot modification

/** A B-spline surface `{ orderU, orderV, knotsU, knotsV, controlPoints[r][s] }`. */
export interface KnotSurface {
  orderU: number;
  orderV: number;
  knotsU: Numbers;
  knotsV: Numbers;
  controlPoints: Grid;
  /** The dimension of flat rows of `controlPoints` (default 3). */
  dim?: 2 | 3;
}
/** A B-spline curve `{ order, knots, controlPoints }`. */
export interface KnotCurve {
  order: number;
  knots: Numbers;
  controlPoints: Points;
  /** The dimension of flat `controlPoints` (default 2). */
  dim?: 2 | 3;
}
/** The moved knots: index p (into knotsU) with its value up, and/or q (knotsV) with vq. */
export interface MovedKnots {
  p?: number;
  up?: number;
  q?: number;
  vq?: number;
}

export interface KnotModifiedSurfaceOptions extends MovedKnots, SurfaceSampling {
  surface: KnotSurface;
}
export interface KnotModifiedSurfaceResult extends SurfaceResult {
  knotsU: Float64Array;
  knotsV: Float64Array;
  domain: Float64Array;
  affectedSpansU?: Float64Array;
  affectedRangeU?: Float64Array;
  neighboursU?: Float64Array;
  affectedSpansV?: Float64Array;
  affectedRangeV?: Float64Array;
  neighboursV?: Float64Array;
}
/** The surface with knot p replaced by up (and/or q by vq). */
export function knotModifiedSurface(options: KnotModifiedSurfaceOptions): KnotModifiedSurfaceResult;

export interface KnotEnvelopeOptions extends MovedKnots, SurfaceSampling {
  surface: KnotSurface;
}
/** The envelope of the family as the knot moves. */
export function knotEnvelope(options: KnotEnvelopeOptions): SurfaceResult & { orderU: number; orderV: number };

/** A path (flat points) that also carries `dim` and `params` (or `uv` for path-surfaces). */
export type KnotPath = Float64Array & { dim: number; params?: Float64Array; uv?: Float64Array };

export interface KnotPathsOptions extends MovedKnots {
  surface: KnotSurface;
  /** (u, v) pairs of the surface points to follow. */
  points: ReadonlyArray<readonly [number, number] | readonly number[]>;
  from?: number | readonly [number, number];
  to?: number | readonly [number, number];
  samples?: number | readonly [number, number];
}
export interface KnotPathsResult {
  dim: number;
  paths: KnotPath[];
  params?: Float64Array;
  paramsU?: Float64Array;
  paramsV?: Float64Array;
}
/** The paths of surface points as the knot moves (path-surfaces with p and q). */
export function knotPaths(options: KnotPathsOptions): KnotPathsResult;

export interface KnotModifiedCurveOptions extends CurveSampling {
  curve: KnotCurve;
  p?: number;
  up?: number;
}
export interface KnotModifiedCurveResult extends CurveResult {
  knots: Float64Array;
  domain: Float64Array;
  affectedSpans?: Float64Array;
  affectedRange?: Float64Array;
  neighbours?: Float64Array;
}
/** The curve with knot p replaced by up. */
export function knotModifiedCurve(options: KnotModifiedCurveOptions): KnotModifiedCurveResult;

export interface KnotDeBoorCurveOptions {
  curve: KnotCurve;
  /** The index of the knot that moves (required). */
  p: number;
  /** Its new value (required). */
  up: number;
  /** The curve parameter, in the domain (required). */
  u: number;
}
export interface KnotDeBoorCurveResult {
  dim: number;
  /** The span i of u (the family's span rule, extended paths included). */
  span: number;
  u: number;
  up: number;
  /** The knot vector with u_p replaced by up. */
  knots: Float64Array;
  /** d_{i−k+1}..d_i, flat. */
  start: Float64Array;
  startIndices: Float64Array;
  /** One entry per intermediate point d_j^r, level by level: its level r. */
  levels: Float64Array;
  /** Its index j. */
  indices: Float64Array;
  /** The knot indices lo, hi of α_j^r = (u − u_lo)/(u_hi − u_lo). */
  knotLo: Float64Array;
  knotHi: Float64Array;
  alphas: Float64Array;
  /** d_j^r, flat; the last is a(u; up). */
  points: Float64Array;
  /** 1 where α_j^r contains the moved knot, else 0. */
  usesUp: Float64Array;
}
/** The de Boor triangle at u with knot p moved to up (Theorem 1's recursion, for steppers). */
export function knotDeBoorCurve(options: KnotDeBoorCurveOptions): KnotDeBoorCurveResult;

export interface KnotEnvelopeCurveOptions extends CurveSampling {
  curve: KnotCurve;
  p: number;
  up?: number;
}
/** The envelope of the curve family on [u_{p−1}, u_{p+1}]. */
export function knotEnvelopeCurve(options: KnotEnvelopeCurveOptions): CurveResult & { order: number };

export interface KnotPathsCurveOptions {
  curve: KnotCurve;
  p: number;
  up?: number;
  /** Curve parameters u of the points to follow (`points` is accepted as its name too). */
  params?: Numbers;
  points?: Numbers;
  from?: number;
  to?: number;
  samples?: number;
}
/** The paths of curve points as u_p moves. */
export function knotPathsCurve(options: KnotPathsCurveOptions): { dim: number; paths: KnotPath[]; params: Float64Array };

export interface KnotLimitsOptions extends MovedKnots {
  curve?: KnotCurve;
  surface?: KnotSurface;
  samples?: number;
}
export interface KnotLimitsCurveResult {
  dim: number;
  minus: Float64Array;
  plus: Float64Array;
  minusIndex: number;
  plusIndex: number;
}
export interface KnotLimitsSurfaceResult {
  dim: number;
  uMinus?: Float64Array;
  uPlus?: Float64Array;
  uMinusIndex?: number;
  uPlusIndex?: number;
  uMinusCurve?: Float64Array;
  uPlusCurve?: Float64Array;
  vMinus?: Float64Array;
  vPlus?: Float64Array;
  vMinusIndex?: number;
  vPlusIndex?: number;
  vMinusCurve?: Float64Array;
  vPlusCurve?: Float64Array;
  corners?: Float64Array;
  cornerIndices?: number[][];
}
/** Where the family goes as the knot tends to ±∞ (curve or surface). */
export function knotLimits(options: KnotLimitsOptions & { curve: KnotCurve }): KnotLimitsCurveResult;
export function knotLimits(options: KnotLimitsOptions & { surface: KnotSurface }): KnotLimitsSurfaceResult;
export function knotLimits(options: KnotLimitsOptions): KnotLimitsCurveResult | KnotLimitsSurfaceResult;

// ------------------------------------------------------------------------------------------------- exercise checks

/** A 2D B-spline `{ degree, knots, controlPoints }` (`order` = degree + 1 accepted instead of `degree`). */
export type ExerciseBSpline = ({ degree: number } | { order: number }) & {
  knots: Numbers;
  controlPoints: Points;
  /** Flat `controlPoints` are 2D. */
  dim?: 2;
};
/** A 2D Bézier spline `{ degree, breaks, controlPoints }`: segment I on b_{mI..mI+m}. */
export type ExerciseBezier = ({ degree: number } | { order: number }) & {
  breaks: Numbers;
  controlPoints: Points;
  dim?: 2;
};
/** A 2D quasi-cubic curve `{ alpha, controlPoints, closed }`. */
export interface ExerciseQuasiCubic {
  alpha: number;
  controlPoints: Points;
  closed?: boolean;
  dim?: 2;
}
export type ExerciseCurve = ExerciseBSpline | ExerciseBezier | ExerciseQuasiCubic;

/** What every check takes: `passed` = value ≤ tol. */
export interface ExerciseCheckBase {
  /** The tolerance (a number ≥ 0, required). */
  tol: number;
  /** The dimension of flat `data` / `points` (2D only). */
  dim?: 2;
}
export interface DataDistanceCheckOptions extends ExerciseCheckBase {
  check: 'dataDistance';
  curve: ExerciseCurve;
  /** 2D data points. */
  data: Points;
}
export interface ContinuityCheckOptions extends ExerciseCheckBase {
  check: 'continuity';
  curve: ExerciseBSpline | ExerciseBezier;
  /** An interior joint. */
  at: number;
  /** The derivatives 0..k compared (default 1). */
  order?: number;
}
export interface FitErrorCheckOptions extends ExerciseCheckBase, B2Options, B2FitMeasureOptions {
  check: 'fitError';
  /** 2D data D_1..D_N (N ≥ 3), as for b2Fit. */
  points: Points;
}
export interface EllipseCheckOptions extends ExerciseCheckBase {
  check: 'ellipse';
  /** The 4 control points of the closed quasi-cubic curve. */
  points: Points;
  /** Default 1. */
  alpha?: number;
  /** Samples per segment (default 200). */
  samples?: number;
}
export interface NetworkNormCheckOptions extends ExerciseCheckBase, NetworkTolerance {
  check: 'networkNorm';
  network: NetworkInput;
  pair: 'SG' | 'ST' | 'TG' | 'SGB' | 'GGB';
  /** Default 57, at most 200 (the network at most 65 breakpoints per direction). */
  normSamples?: number;
}
export interface EnvelopePointCheckOptions extends ExerciseCheckBase {
  check: 'envelopePoint';
  curve: ExerciseBSpline;
  /** The index of the knot that moves (required). */
  p: number;
  /** Its new value (default the knot's own). */
  up?: number;
  target: readonly [number, number] | readonly number[];
}
export type ExerciseCheckOptions =
  | DataDistanceCheckOptions | ContinuityCheckOptions | FitErrorCheckOptions | EllipseCheckOptions
  | NetworkNormCheckOptions | EnvelopePointCheckOptions;

/** `{ check, value, tol, passed, score }`. */
export interface ExerciseVerdict<C extends string = string> {
  check: C;
  /** The measure (may be Infinity or NaN). */
  value: number;
  tol: number;
  passed: boolean;
  /** 1 when passed, else 1 − (orders of magnitude above tol)/4, clamped to [0, 0.9]. */
  score: number;
}
export interface DataDistanceVerdict extends ExerciseVerdict<'dataDistance'> {
  distances: Float64Array;
  /** The foot points' parameters. */
  params: Float64Array;
  /** The index of the farthest data point. */
  worst: number;
}
export interface ContinuityVerdict extends ExerciseVerdict<'continuity'> {
  at: number;
  /** ‖c^(j)(u⁻) − c^(j)(u⁺)‖ for j = 0..k. */
  jumps: Float64Array;
  /** The jumps over scale_j. */
  relative: Float64Array;
}
export interface FitErrorVerdict extends ExerciseVerdict<'fitError'> {
  rms: number;
  max: number;
}
export interface NetworkNormVerdict extends ExerciseVerdict<'networkNorm'> {
  pair: string;
}
export interface EnvelopePointVerdict extends ExerciseVerdict<'envelopePoint'> {
  /** The distance of the touching point to the moved curve. */
  curveDistance: number;
}
export type ExerciseCheckResult =
  | DataDistanceVerdict | ContinuityVerdict | FitErrorVerdict | ExerciseVerdict<'ellipse'> | NetworkNormVerdict
  | EnvelopePointVerdict;
/** How far a construction is from what a self-checking exercise asks, against a tolerance. */
export function exerciseCheck(options: DataDistanceCheckOptions): DataDistanceVerdict;
export function exerciseCheck(options: ContinuityCheckOptions): ContinuityVerdict;
export function exerciseCheck(options: FitErrorCheckOptions): FitErrorVerdict;
export function exerciseCheck(options: EllipseCheckOptions): ExerciseVerdict<'ellipse'>;
export function exerciseCheck(options: NetworkNormCheckOptions): NetworkNormVerdict;
export function exerciseCheck(options: EnvelopePointCheckOptions): EnvelopePointVerdict;
export function exerciseCheck(options: ExerciseCheckOptions): ExerciseCheckResult;
