//! [`B2Surface`]: the tensor-product B2-spline surface (section 6).

use super::{resolve_tension, uniform_knots, B2Scheme, Construction, Tension};
use crate::bspline::BSplineSurface;
use crate::error::{Error, Result};
use crate::point::Point;
use crate::sample::Surface;

/// The knot choice of one direction of a [`B2Surface`].
#[derive(Debug, Clone, PartialEq, Default)]
pub enum SurfaceKnots {
    /// Δ_i = the mean over the other index of |W_{i+1,j} − W_{ij}| (u_1 = 0) — the paper gives no rule.
    Chord,
    /// u_j = j − 1 (the default for surfaces: the paper suggests no knots for surfaces, and uniform ones
    /// are the only choice that does not depend on a convention).
    #[default]
    Uniform,
    /// The given knots (m + 4 values).
    Explicit(Vec<f64>),
}

/// Options of a [`B2Surface`] (section 6). Tensions are numbers or arrays (no automatic tension).
#[derive(Debug, Clone, PartialEq)]
pub struct B2SurfaceOptions {
    /// The approximation parameter a of the family L^a (0 interpolates).
    pub a: f64,
    /// Tension along u.
    pub tension_u: Tension,
    /// Tension along v.
    pub tension_v: Tension,
    /// Knots along u.
    pub knots_u: SurfaceKnots,
    /// Knots along v.
    pub knots_v: SurfaceKnots,
    /// The modified-knot factor c₂ of section 5 (applied in both directions).
    pub c2: f64,
}

impl Default for B2SurfaceOptions {
    fn default() -> Self {
        B2SurfaceOptions {
            a: 0.0,
            tension_u: Tension::default(),
            tension_v: Tension::default(),
            knots_u: SurfaceKnots::Uniform,
            knots_v: SurfaceKnots::Uniform,
            c2: 1.0,
        }
    }
}

/// The tensor-product B2-spline surface S(u, v) = Σ_i Σ_j W_ij L_i(u) L_j(v) (section 6), for the grid
/// W_ij, i = −1..m+2, j = −1..n+2 (stored `grid[(i + 1) * cols + (j + 1)]`). It is the tensor cubic
/// B-spline whose control net is the B2 construction applied along u, then along v.
#[derive(Debug, Clone)]
pub struct B2Surface<P: Point> {
    scheme_u: B2Scheme,
    scheme_v: B2Scheme,
    surface: BSplineSurface<P>,
}

impl<P: Point> B2Surface<P> {
    /// Builds the surface from a `rows × cols` grid (row-major, rows along u). Needs rows, cols ≥ 6.
    pub fn new(rows: usize, cols: usize, grid: &[P], opts: &B2SurfaceOptions) -> Result<Self> {
        if rows < 6 {
            return Err(Error::too_few(
                "grid",
                format!("need at least 6 rows W₋₁..Wₘ₊₂ (m ≥ 2), got {rows}"),
            ));
        }
        if cols < 6 {
            return Err(Error::too_few(
                "grid[0]",
                format!("need at least 6 points per row (n ≥ 2), got {cols}"),
            ));
        }
        if grid.len() != rows * cols {
            return Err(Error::size_mismatch(
                "grid",
                format!("expected {rows} × {cols} points, got {}", grid.len()),
            ));
        }
        if let Some(k) = grid.iter().position(|p| !p.is_finite()) {
            return Err(Error::not_finite(
                format!("grid[{}][{}]", k / cols, k % cols),
                "expected finite coordinates",
            ));
        }
        crate::error::check_finite_scalar("a", opts.a)?;
        let ku = Self::dir_knots("knotsU", &opts.knots_u, rows, |i| {
            (0..cols).map(|j| grid[i * cols + j]).collect()
        })?;
        let kv = Self::dir_knots("knotsV", &opts.knots_v, cols, |j| {
            (0..rows).map(|i| grid[i * cols + j]).collect()
        })?;
        let tu = resolve_tension(&opts.tension_u, rows - 4)
            .map_err(|e| relabel(e, "tension", "tensionU"))?;
        let tv = resolve_tension(&opts.tension_v, cols - 4)
            .map_err(|e| relabel(e, "tension", "tensionV"))?;
        let su = B2Scheme::new(ku, tu, opts.a, None, opts.c2, Construction::NonUniform)
            .map_err(|e| relabel(relabel(e, "knots", "knotsU"), "tension", "tensionU"))?;
        let sv = B2Scheme::new(kv, tv, opts.a, None, opts.c2, Construction::NonUniform)
            .map_err(|e| relabel(relabel(e, "knots", "knotsV"), "tension", "tensionV"))?;
        let (nu, nv) = (2 * (rows - 4) + 1, 2 * (cols - 4) + 1);
        // along u for every column j
        let mut cols_u: Vec<Vec<P>> = Vec::with_capacity(cols);
        for j in 0..cols {
            let col: Vec<P> = (0..rows).map(|i| grid[i * cols + j]).collect();
            cols_u.push(su.control_points(&col)?.1);
        }
        let mut net = Vec::with_capacity(nu * nv);
        for k in 0..nu {
            let row: Vec<P> = cols_u.iter().map(|c| c[k]).collect();
            net.extend(sv.control_points(&row)?.1);
        }
        let surface = BSplineSurface::new(3, 3, su.knots.clone(), sv.knots.clone(), nu, nv, net)?;
        Ok(B2Surface {
            scheme_u: su,
            scheme_v: sv,
            surface,
        })
    }

    fn dir_knots(
        field: &'static str,
        choice: &SurfaceKnots,
        count: usize,
        line: impl Fn(usize) -> Vec<P>,
    ) -> Result<Vec<f64>> {
        match choice {
            SurfaceKnots::Uniform => Ok(uniform_knots(count)),
            SurfaceKnots::Explicit(k) => {
                if k.len() != count {
                    return Err(Error::size_mismatch(
                        field,
                        format!(
                            "expected {count} knots (one per grid line), got {}",
                            k.len()
                        ),
                    ));
                }
                crate::error::check_finite(field, k)?;
                crate::knots::check_increasing(field, k)?;
                Ok(k.clone())
            }
            SurfaceKnots::Chord => {
                let mut u = vec![0.0; count];
                let mut prev = line(0);
                for i in 1..count {
                    let cur = line(i);
                    let d = prev
                        .iter()
                        .zip(&cur)
                        .map(|(a, b)| a.distance(*b))
                        .sum::<f64>()
                        / cur.len().max(1) as f64;
                    if !(d > 0.0) {
                        return Err(Error::degenerate(
                            field,
                            format!("grid lines {} and {i} coincide: chord-length knots need distinct lines (use \"uniform\")", i - 1),
                        ));
                    }
                    u[i] = u[i - 1] + d;
                    prev = cur;
                }
                let s = u[2];
                Ok(u.into_iter().map(|x| x - s).collect())
            }
        }
    }

    /// The B2 scheme along u.
    pub fn scheme_u(&self) -> &B2Scheme {
        &self.scheme_u
    }
    /// The B2 scheme along v.
    pub fn scheme_v(&self) -> &B2Scheme {
        &self.scheme_v
    }
    /// The tensor cubic B-spline this surface is.
    pub fn bspline(&self) -> &BSplineSurface<P> {
        &self.surface
    }
}

fn relabel(e: Error, from: &str, to: &'static str) -> Error {
    if e.field() == from {
        e.in_field(to)
    } else if let Some(rest) = e.field().strip_prefix(from).filter(|r| r.starts_with('[')) {
        let f = format!("{to}{rest}");
        e.in_field(f)
    } else {
        e
    }
}

impl<P: Point> Surface<P> for B2Surface<P> {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        (self.scheme_u.domain(), self.scheme_v.domain())
    }
    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [P; 3]) {
        self.surface.eval_derivs(u, v, derivs, out)
    }
    /// The tensor cubic B-spline's grid sampler.
    fn sample_grid_into(
        &self,
        us: &[f64],
        vs: &[f64],
        derivs: bool,
        points: &mut [f64],
        du: &mut [f64],
        dv: &mut [f64],
    ) {
        self.surface
            .sample_grid_into(us, vs, derivs, points, du, dv)
    }
}
