//! B-splines: Cox–de Boor basis functions and their derivatives, de Boor evaluation of curves and
//! tensor-product surfaces, and global interpolation (used for skinning by the Gordon surface).
//!
//! Basis functions follow the Cox–de Boor recursion N_{i,0} = 1 on [t_i, t_{i+1}),
//! N_{i,p} = (u − t_i)/(t_{i+p} − t_i)·N_{i,p−1} + (t_{i+p+1} − u)/(t_{i+p+1} − t_{i+1})·N_{i+1,p−1}
//! with 0/0 := 0; derivatives by Piegl–Tiller A2.3. Conventions for spans are in [`crate::knots`].

mod curve;
mod interpolate;
mod steps;
mod surface;

pub use crate::basis::{basis_all, basis_derivs};
pub use curve::BSplineCurve;
pub use interpolate::{interpolate, interpolate_chord};
pub use steps::{DeBoorTriangle, KnotInsertion};
pub use surface::BSplineSurface;

use crate::basis::W;

#[cfg(test)]
mod tests;
