//! Points as the bindings take them: [`Pts`], a validated list of 2D or 3D points (from rows `[[x, y], …]` or flat
//! coordinates), [`with_points!`] to run code on either, and [`flat`] to write points back as flat coordinates.

use super::errors::{self, err_kind, ApiResult};
use crate::error::ErrorKind;
use crate::point::Point;
use crate::sample::MAX_INPUT_POINTS;
use glam::{DVec2, DVec3};

/// A list of points of one dimension, 2 or 3.
pub enum Pts {
    /// Points `[x, y]`.
    D2(Vec<DVec2>),
    /// Points `[x, y, z]`.
    D3(Vec<DVec3>),
}

impl Pts {
    /// The number of points.
    pub fn len(&self) -> usize {
        match self {
            Pts::D2(p) => p.len(),
            Pts::D3(p) => p.len(),
        }
    }
    /// Whether there are no points.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// The dimension, 2 or 3.
    pub fn dim(&self) -> usize {
        match self {
            Pts::D2(_) => 2,
            Pts::D3(_) => 3,
        }
    }
}

/// Runs `$body` with `$p` bound to the `Vec<DVec2>` or `Vec<DVec3>` inside a [`Pts`].
#[macro_export]
macro_rules! with_points {
    ($pts:expr, $p:ident => $body:expr) => {
        match $pts {
            $crate::api::Pts::D2($p) => $body,
            $crate::api::Pts::D3($p) => $body,
        }
    };
}
pub use with_points;

/// Flattens points to `[x0, y0, (z0,) x1, …]`.
pub fn flat<P: Point>(pts: &[P]) -> Vec<f64> {
    let mut out = vec![0.0; pts.len() * P::DIM];
    for (i, p) in pts.iter().enumerate() {
        p.write_coords(&mut out[i * P::DIM..]);
    }
    out
}

/// Validates raw coordinate rows (`field` names them) into points of one dimension (2 or 3).
pub fn rows_to_pts(field: &str, rows: &[Vec<f64>], min: usize) -> ApiResult<Pts> {
    rows_to_pts_named(field, rows, min, |i| format!("{field}[{i}]"))
}

/// [`rows_to_pts`] where `point(i)` names point `i` in errors (a grid's point `i` is `grid[row][col]`).
pub fn rows_to_pts_named(
    field: &str,
    rows: &[Vec<f64>],
    min: usize,
    point: impl Fn(usize) -> String,
) -> ApiResult<Pts> {
    if rows.len() < min {
        return Err(errors::too_few(
            field,
            min,
            rows.len(),
            format!("need at least {min} points, got {}", rows.len()),
        ));
    }
    if rows.len() > MAX_INPUT_POINTS {
        return Err(errors::too_many(
            field,
            MAX_INPUT_POINTS,
            rows.len(),
            format!("at most {MAX_INPUT_POINTS} points, got {}", rows.len()),
        ));
    }
    let dim = rows.first().map_or(2, |r| r.len());
    if dim != 2 && dim != 3 {
        return Err(err_kind(
            ErrorKind::WrongType,
            &point(0),
            format!("expected [x, y] or [x, y, z], got {dim} numbers"),
        ));
    }
    for (i, r) in rows.iter().enumerate() {
        if r.len() != dim {
            return Err(err_kind(
                ErrorKind::SizeMismatch,
                &point(i),
                format!(
                    "all points must have the same dimension ({dim}), got {} numbers",
                    r.len()
                ),
            ));
        }
        if let Some(k) = r.iter().position(|x| !x.is_finite()) {
            return Err(err_kind(
                ErrorKind::NotFinite,
                &format!("{}[{k}]", point(i)),
                crate::error::not_finite_detail(r[k]),
            ));
        }
    }
    Ok(if dim == 2 {
        Pts::D2(rows.iter().map(|r| DVec2::new(r[0], r[1])).collect())
    } else {
        Pts::D3(rows.iter().map(|r| DVec3::new(r[0], r[1], r[2])).collect())
    })
}

/// Validates flat coordinates (`dim` per point, finite already checked) into points (`field` names them).
pub fn flat_to_pts(field: &str, xs: &[f64], dim: usize, min: usize) -> ApiResult<Pts> {
    if !xs.len().is_multiple_of(dim) {
        return Err(err_kind(
            ErrorKind::Invalid,
            field,
            format!(
                "flat coordinates need a multiple of dim = {dim} numbers, got {}",
                xs.len()
            ),
        ));
    }
    let n = xs.len() / dim;
    if n < min {
        return Err(err_kind(
            ErrorKind::TooFew,
            field,
            format!("need at least {min} points, got {n}"),
        ));
    }
    if n > MAX_INPUT_POINTS {
        return Err(err_kind(
            ErrorKind::TooMany,
            field,
            format!("at most {MAX_INPUT_POINTS} points, got {n}"),
        ));
    }
    Ok(if dim == 2 {
        Pts::D2(xs.chunks_exact(2).map(|c| DVec2::new(c[0], c[1])).collect())
    } else {
        Pts::D3(
            xs.chunks_exact(3)
                .map(|c| DVec3::new(c[0], c[1], c[2]))
                .collect(),
        )
    })
}

/// Validates raw 3D coordinate rows.
pub fn rows_to_3d(field: &str, rows: &[Vec<f64>]) -> ApiResult<Vec<DVec3>> {
    match rows_to_pts(field, rows, 0)? {
        Pts::D3(p) => Ok(p),
        Pts::D2(_) if rows.is_empty() => Ok(Vec::new()),
        Pts::D2(_) => Err(err_kind(
            ErrorKind::SizeMismatch,
            field,
            "expected 3D points [x, y, z]",
        )),
    }
}
