//! Cox–de Boor basis functions and their derivatives (Piegl–Tiller A2.3): N_{i,0} = 1 on [t_i, t_{i+1}),
//! N_{i,p} = (u − t_i)/(t_{i+p} − t_i)·N_{i,p−1} + (t_{i+p+1} − u)/(t_{i+p+1} − t_{i+1})·N_{i+1,p−1}, 0/0 := 0.
//! They depend on the knot vector only, so they sit below every construction that uses them: the B-spline
//! types ([`crate::bspline`]) and the fast samplers ([`crate::kernel`]).

use crate::knots::{find_span, MAX_DEGREE};

/// The fixed width of the basis work arrays (degree ≤ [`MAX_DEGREE`]).
pub(crate) const W: usize = MAX_DEGREE + 1;

/// The non-zero basis functions on span `span` and their derivatives up to `order` (≤ 2) at `u`:
/// `ders[k][r]` = N^{(k)}_{span−p+r, p}(u), r = 0..=p. Allocation-free (Piegl–Tiller A2.3).
pub fn basis_derivs(
    knots: &[f64],
    degree: usize,
    span: usize,
    u: f64,
    order: usize,
    ders: &mut [[f64; W]; 3],
) {
    // work arrays sized for the degree: zeroing a 25 × 25 table per call cost more than the recursion
    if degree < 4 {
        basis_derivs_sized::<4>(knots, degree, span, u, order, ders)
    } else if degree < 8 {
        basis_derivs_sized::<8>(knots, degree, span, u, order, ders)
    } else {
        basis_derivs_sized::<W>(knots, degree, span, u, order, ders)
    }
}

/// [`basis_derivs`] with work arrays of `M > degree` entries.
#[inline(always)]
fn basis_derivs_sized<const M: usize>(
    knots: &[f64],
    degree: usize,
    span: usize,
    u: f64,
    order: usize,
    ders: &mut [[f64; W]; 3],
) {
    let p = degree;
    let order = order.min(2).min(p);
    let mut ndu = [[0.0_f64; M]; M];
    let mut left = [0.0_f64; M];
    let mut right = [0.0_f64; M];
    ndu[0][0] = 1.0;
    for j in 1..=p {
        left[j] = u - knots[span + 1 - j];
        right[j] = knots[span + j] - u;
        let mut saved = 0.0;
        for r in 0..j {
            ndu[j][r] = right[r + 1] + left[j - r];
            let temp = if ndu[j][r] != 0.0 {
                ndu[r][j - 1] / ndu[j][r]
            } else {
                0.0
            };
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    for k in 0..3 {
        for r in 0..=p {
            ders[k][r] = 0.0;
        }
    }
    for j in 0..=p {
        ders[0][j] = ndu[j][p];
    }
    if order == 0 {
        return;
    }
    let mut a = [[0.0_f64; M]; 2];
    for r in 0..=p {
        let (mut s1, mut s2) = (0usize, 1usize);
        a[0][0] = 1.0;
        for k in 1..=order {
            let mut d = 0.0;
            let rk = r as isize - k as isize;
            let pk = p - k;
            if r >= k {
                let rk = rk as usize;
                a[s2][0] = if ndu[pk + 1][rk] != 0.0 {
                    a[s1][0] / ndu[pk + 1][rk]
                } else {
                    0.0
                };
                d = a[s2][0] * ndu[rk][pk];
            }
            let j1 = if rk >= -1 { 1 } else { (-rk) as usize };
            let j2 = if (r as isize - 1) <= pk as isize {
                k - 1
            } else {
                p - r
            };
            for j in j1..=j2 {
                let idx = (rk + j as isize) as usize;
                a[s2][j] = if ndu[pk + 1][idx] != 0.0 {
                    (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][idx]
                } else {
                    0.0
                };
                d += a[s2][j] * ndu[idx][pk];
            }
            if r <= pk {
                a[s2][k] = if ndu[pk + 1][r] != 0.0 {
                    -a[s1][k - 1] / ndu[pk + 1][r]
                } else {
                    0.0
                };
                d += a[s2][k] * ndu[r][pk];
            }
            ders[k][r] = d;
            std::mem::swap(&mut s1, &mut s2);
        }
    }
    let mut f = p as f64;
    for k in 1..=order {
        for r in 0..=p {
            ders[k][r] *= f;
        }
        f *= (p - k) as f64;
    }
}

/// All `count = knots.len() − degree − 1` basis functions N_{i,p} and derivatives up to `order` at `u`
/// (right-hand piece at knots, last piece at and beyond the end). `out[k]` has `count` entries.
pub fn basis_all(knots: &[f64], degree: usize, u: f64, order: usize, out: &mut [Vec<f64>; 3]) {
    let count = knots.len() - degree - 1;
    let span = find_span(knots, degree, count, u);
    let mut ders = [[0.0; W]; 3];
    basis_derivs(knots, degree, span, u, order, &mut ders);
    for (k, row) in out.iter_mut().enumerate() {
        row.clear();
        row.resize(count, 0.0);
        if k <= order {
            for r in 0..=degree {
                row[span - degree + r] = ders[k][r];
            }
        }
    }
}
