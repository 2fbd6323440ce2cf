//! Juhász and Hoffmann: knot-modified families, paths, limits and envelopes.
//! `surfaces.md` §10 items 21–24 with their tolerances, for (k, l) ∈ {(3,3), (4,4), (4,3), (5,4), (3,5)},
//! plus the curve case and input validation.
#![allow(clippy::needless_range_loop)]

use glam::{DVec2, DVec3};
use splinelab::bspline::{BSplineCurve, BSplineSurface};
use splinelab::knot_paths::{KnotModifiedCurve, KnotModifiedSurface, Var};
use splinelab::{Curve, ErrorKind, Point, Surface};

const ORDERS: [(usize, usize); 5] = [(3, 3), (4, 4), (4, 3), (5, 4), (3, 5)];

/// A small deterministic generator (LCG) for test data.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64) / ((1u64 << 53) as f64)
    }
}

/// Clamped non-uniform knots for `count` control points of order `k` on [0, count − k + 1].
fn knots(k: usize, count: usize, rng: &mut Rng) -> Vec<f64> {
    let inner = count - k;
    let mut t = vec![0.0; k];
    let mut x = 0.0;
    for _ in 0..inner {
        x += 0.6 + 0.8 * rng.next();
        t.push(x);
    }
    let end = x + 0.6 + 0.8 * rng.next();
    t.extend(std::iter::repeat_n(end, k));
    t
}

struct Data {
    k: usize,
    l: usize,
    ku: Vec<f64>,
    kv: Vec<f64>,
    nu: usize,
    nv: usize,
    net: Vec<DVec3>,
    p: usize,
    q: usize,
}

fn data(k: usize, l: usize, seed: u64) -> Data {
    let mut rng = Rng(seed);
    let (nu, nv) = (k + 4, l + 4);
    let ku = knots(k, nu, &mut rng);
    let kv = knots(l, nv, &mut rng);
    let mut net = Vec::new();
    for r in 0..nu {
        for s in 0..nv {
            net.push(DVec3::new(
                r as f64 + 0.4 * rng.next(),
                s as f64 + 0.4 * rng.next(),
                2.0 * rng.next() - 1.0,
            ));
        }
    }
    // interior knots k..=n (n = nu − 1); take one in the middle
    Data {
        k,
        l,
        ku,
        kv,
        nu,
        nv,
        net,
        p: k + 1,
        q: l + 2,
    }
}

impl Data {
    fn family(&self, mu: Option<f64>, mv: Option<f64>) -> KnotModifiedSurface<DVec3> {
        KnotModifiedSurface::new(
            self.k,
            self.l,
            self.ku.clone(),
            self.kv.clone(),
            self.nu,
            self.nv,
            self.net.clone(),
            mu.map(|x| (self.p, x)),
            mv.map(|x| (self.q, x)),
        )
        .unwrap()
    }
    fn d(&self, r: usize, s: usize) -> DVec3 {
        self.net[r * self.nv + s]
    }
    /// 4 positions of u_p inside [u_{p−1}, u_{p+1}] (ends included).
    fn ups_inside(&self) -> [f64; 4] {
        let (a, b) = (self.ku[self.p - 1], self.ku[self.p + 1]);
        [a, a + 0.3 * (b - a), a + 0.71 * (b - a), b]
    }
    fn vqs_inside(&self) -> [f64; 4] {
        let (a, b) = (self.kv[self.q - 1], self.kv[self.q + 1]);
        [a, a + 0.37 * (b - a), a + 0.8 * (b - a), b]
    }
    fn ups_outside(&self) -> [f64; 4] {
        let (a, b) = (self.ku[self.p - 1], self.ku[self.p + 1]);
        [a - 0.45, a - 3.3, b + 0.55, b + 2.7]
    }
    fn vqs_outside(&self) -> [f64; 4] {
        let (a, b) = (self.kv[self.q - 1], self.kv[self.q + 1]);
        [a - 0.35, a - 4.1, b + 0.45, b + 3.3]
    }
    fn params(t: &[f64], k: usize, count: usize, n: usize) -> Vec<f64> {
        let (a, b) = (t[k - 1], t[count]);
        (0..n)
            .map(|i| a + (b - a) * (i as f64 + 0.13) / (n as f64 - 0.74))
            .chain([a, b])
            .collect()
    }
    fn us(&self) -> Vec<f64> {
        Self::params(&self.ku, self.k, self.nu, 23)
    }
    fn vs(&self) -> Vec<f64> {
        Self::params(&self.kv, self.l, self.nv, 19)
    }
    /// Parameters in [a, b) (the interval of the neighbours).
    fn within(a: f64, b: f64) -> Vec<f64> {
        (0..7).map(|i| a + (b - a) * i as f64 / 7.3).collect()
    }
}

fn close<P: Point>(a: P, b: P, tol: f64) -> bool {
    (a - b).max_abs() <= tol * 1f64.max(b.max_abs())
}

fn replaced(t: &[f64], i: usize, x: f64) -> Vec<f64> {
    let mut t = t.to_vec();
    t[i] = x;
    t
}

// ---------------------------------------------------------------------------------------------------
// An independent evaluator for the extended families: de Boor's *point* recursion on the chosen span,
// pure algebra in the (possibly unsorted) knots, the span rule written out from surfaces.md §7.
// ---------------------------------------------------------------------------------------------------

fn span_rule(t_orig: &[f64], k: usize, count: usize, p: Option<usize>, x: f64, u: f64) -> usize {
    if let Some(p) = p {
        if u >= t_orig[p - 1] && u < t_orig[p + 1] {
            return if u >= x { p } else { p - 1 };
        }
    }
    // ordinary span on the original knots (right-hand piece, last piece at the end)
    splinelab::knots::find_span(t_orig, k - 1, count, u)
}

fn de_boor_algebra<P: Point>(t: &[f64], k: usize, i: usize, u: f64, d: &[P]) -> P {
    let mut c: Vec<P> = d[i + 1 - k..=i].to_vec();
    for r in 1..k {
        for j in (r..k).rev() {
            let idx = i + 1 - k + j; // control index of c[j]
            let den = t[idx + k - r] - t[idx];
            let a = if den == 0.0 { 0.0 } else { (u - t[idx]) / den };
            c[j] = c[j - 1] * (1.0 - a) + c[j] * a;
        }
    }
    c[k - 1]
}

fn reference_family(dt: &Data, u: f64, v: f64, up: Option<f64>, vq: Option<f64>) -> DVec3 {
    let tu = up.map_or(dt.ku.clone(), |x| replaced(&dt.ku, dt.p, x));
    let tv = vq.map_or(dt.kv.clone(), |x| replaced(&dt.kv, dt.q, x));
    let iu = span_rule(&dt.ku, dt.k, dt.nu, up.map(|_| dt.p), up.unwrap_or(0.0), u);
    let iv = span_rule(&dt.kv, dt.l, dt.nv, vq.map(|_| dt.q), vq.unwrap_or(0.0), v);
    // u-direction on every column, then v
    let b: Vec<DVec3> = (0..dt.nv)
        .map(|s| {
            let col: Vec<DVec3> = (0..dt.nu).map(|r| dt.d(r, s)).collect();
            de_boor_algebra(&tu, dt.k, iu, u, &col)
        })
        .collect();
    de_boor_algebra(&tv, dt.l, iv, v, &b)
}

// ---------------------------------------------------------------------------------------------------
// 21. family values (ordinary and extended) and the two-knot family: 1e-12
// ---------------------------------------------------------------------------------------------------

#[test]
fn item21_ordinary_family_is_the_bspline_with_the_modified_knot() {
    for (seed, &(k, l)) in ORDERS.iter().enumerate() {
        let dt = data(k, l, 11 + seed as u64);
        for &up in &dt.ups_inside() {
            let fam = dt.family(Some(up), None);
            let reference = BSplineSurface::new(
                k - 1,
                l - 1,
                replaced(&dt.ku, dt.p, up),
                dt.kv.clone(),
                dt.nu,
                dt.nv,
                dt.net.clone(),
            )
            .unwrap();
            for &u in &dt.us() {
                for &v in &dt.vs() {
                    let (mut a, mut b) = ([DVec3::ZERO; 3], [DVec3::ZERO; 3]);
                    fam.eval_derivs(u, v, true, &mut a);
                    reference.eval_derivs(u, v, true, &mut b);
                    for c in 0..3 {
                        assert!(
                            close(a[c], b[c], 1e-12),
                            "(k,l)=({k},{l}) up={up} u={u} v={v} c={c}: {:?} vs {:?}",
                            a[c],
                            b[c]
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn item21_two_knot_family_is_the_bspline_with_both_knots_modified() {
    for (seed, &(k, l)) in ORDERS.iter().enumerate() {
        let dt = data(k, l, 21 + seed as u64);
        for (&up, &vq) in dt.ups_inside().iter().zip(dt.vqs_inside().iter().rev()) {
            let fam = dt.family(Some(up), Some(vq));
            let reference = BSplineSurface::new(
                k - 1,
                l - 1,
                replaced(&dt.ku, dt.p, up),
                replaced(&dt.kv, dt.q, vq),
                dt.nu,
                dt.nv,
                dt.net.clone(),
            )
            .unwrap();
            for &u in &dt.us() {
                for &v in &dt.vs() {
                    let (mut a, mut b) = ([DVec3::ZERO; 3], [DVec3::ZERO; 3]);
                    fam.eval_derivs(u, v, true, &mut a);
                    reference.eval_derivs(u, v, true, &mut b);
                    for c in 0..3 {
                        assert!(
                            close(a[c], b[c], 1e-12),
                            "(k,l)=({k},{l}) up={up} vq={vq} u={u} v={v} c={c}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn item21_extended_families_match_the_de_boor_algebra() {
    for (seed, &(k, l)) in ORDERS.iter().enumerate() {
        let dt = data(k, l, 31 + seed as u64);
        let (a, b) = (dt.ku[dt.p - 1], dt.ku[dt.p + 1]);
        let (c, d) = (dt.kv[dt.q - 1], dt.kv[dt.q + 1]);
        let mut us = dt.us();
        us.extend(Data::within(a, b));
        let mut vs = dt.vs();
        vs.extend(Data::within(c, d));
        let cases: Vec<(Option<f64>, Option<f64>)> = dt
            .ups_outside()
            .iter()
            .map(|&x| (Some(x), None))
            .chain(dt.vqs_outside().iter().map(|&y| (None, Some(y))))
            .chain(
                dt.ups_outside()
                    .iter()
                    .zip(dt.vqs_outside().iter())
                    .map(|(&x, &y)| (Some(x), Some(y))),
            )
            .chain(
                dt.ups_inside()
                    .iter()
                    .zip(dt.vqs_outside().iter())
                    .map(|(&x, &y)| (Some(x), Some(y))),
            )
            .collect();
        for (up, vq) in cases {
            let fam = dt.family(up, vq);
            let (fu, fv) = (up.unwrap_or(0.0), vq.unwrap_or(0.0));
            for &u in &us {
                for &v in &vs {
                    let s = fam.eval_at(u, v, fu, fv);
                    let r = reference_family(&dt, u, v, up, vq);
                    // the extended paths have poles when u_p crosses other knots; compare relative to the size
                    assert!(
                        close(s, r, 1e-12),
                        "(k,l)=({k},{l}) up={up:?} vq={vq:?} u={u} v={v}: {s:?} vs {r:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn moving_a_knot_changes_only_the_affected_strip() {
    for (seed, &(k, l)) in ORDERS.iter().enumerate() {
        let dt = data(k, l, 41 + seed as u64);
        let base = dt.family(None, None);
        let up = dt.ups_inside()[1];
        let fam = dt.family(Some(up), None);
        let ((lo, hi), (ra, rb)) = fam.line_u().affected().unwrap();
        assert_eq!(
            (lo, hi),
            ((dt.p + 1 - k).max(k - 1), (dt.p + k - 2).min(dt.nu - 1))
        );
        let mut changed = false;
        for &u in &dt.us() {
            for &v in &dt.vs() {
                let diff = (fam.eval(u, v) - base.eval(u, v)).max_abs();
                if u < ra || u > rb {
                    assert!(
                        diff <= 1e-14,
                        "(k,l)=({k},{l}) u={u} outside [{ra},{rb}] moved by {diff}"
                    );
                } else if u > ra && u < rb && diff > 1e-6 {
                    changed = true;
                }
            }
        }
        assert!(changed, "moving the knot must change the strip");
    }
}

// ---------------------------------------------------------------------------------------------------
// 22. envelopes e(w, v), e_w, e_v and e(w, z) of (6), (8): 1e-12
// ---------------------------------------------------------------------------------------------------

fn removed(t: &[f64], i: usize) -> Vec<f64> {
    let mut t = t.to_vec();
    t.remove(i);
    t
}

#[test]
fn item22_envelopes_are_the_lower_order_bsplines_on_the_reduced_knots() {
    for (seed, &(k, l)) in ORDERS.iter().enumerate() {
        let dt = data(k, l, 51 + seed as u64);
        let (a, b) = (dt.ku[dt.p - 1], dt.ku[dt.p + 1]);
        let (c, d) = (dt.kv[dt.q - 1], dt.kv[dt.q + 1]);
        let w = removed(&dt.ku, dt.p);
        let z = removed(&dt.kv, dt.q);
        // (6): order k − 1 on w, all rows (only p−k+1..p−1 are non-zero on [w_{p−1}, w_p))
        let e6 = dt.family(Some(a), None).envelope().unwrap();
        assert_eq!(e6.orders(), (k - 1, l));
        assert_eq!(e6.domain().0, (a, b));
        // w is clamped with k end copies, one more than order k − 1 allows: its first and last order-(k−1)
        // functions vanish identically, so the reference drops them (and the first/last row of the net)
        let wr = w[1..w.len() - 1].to_vec();
        let inner_rows: Vec<DVec3> = dt.net[dt.nv..(dt.nu - 1) * dt.nv].to_vec();
        let r6 = BSplineSurface::new(
            k - 2,
            l - 1,
            wr.clone(),
            dt.kv.clone(),
            dt.nu - 2,
            dt.nv,
            inner_rows,
        )
        .unwrap();
        // (8): order (k − 1, l − 1) on (w, z)
        let e8 = dt.family(Some(a), Some(c)).envelope().unwrap();
        assert_eq!(e8.orders(), (k - 1, l - 1));
        let zr = z[1..z.len() - 1].to_vec();
        let inner: Vec<DVec3> = (1..dt.nu - 1)
            .flat_map(|r| (1..dt.nv - 1).map(move |s| (r, s)))
            .map(|(r, s)| dt.d(r, s))
            .collect();
        let r8 =
            BSplineSurface::new(k - 2, l - 2, wr.clone(), zr, dt.nu - 2, dt.nv - 2, inner).unwrap();
        for &ww in &Data::within(a, b) {
            for &v in &dt.vs() {
                let (mut x, mut y) = ([DVec3::ZERO; 3], [DVec3::ZERO; 3]);
                e6.eval_derivs(ww, v, true, &mut x);
                r6.eval_derivs(ww, v, true, &mut y);
                for i in 0..3 {
                    assert!(
                        close(x[i], y[i], 1e-12),
                        "(6) (k,l)=({k},{l}) w={ww} v={v} i={i}"
                    );
                }
                // the sum runs over rows p−k+1..p−1 only
                let t = e6.taylor::<1, 1>(ww, v)[0][0];
                let mut direct = DVec3::ZERO;
                let mut nw = [Vec::new(), Vec::new(), Vec::new()];
                let mut nv = [Vec::new(), Vec::new(), Vec::new()];
                splinelab::bspline::basis_all(&wr, k - 2, ww, 0, &mut nw);
                splinelab::bspline::basis_all(&dt.kv, l - 1, v, 0, &mut nv);
                for r in dt.p + 1 - k..dt.p {
                    for s in 0..dt.nv {
                        direct += dt.d(r, s) * (nw[0][r - 1] * nv[0][s]);
                    }
                }
                assert!(close(t, direct, 1e-12));
            }
            for &zz in &Data::within(c, d) {
                let (mut x, mut y) = ([DVec3::ZERO; 3], [DVec3::ZERO; 3]);
                e8.eval_derivs(ww, zz, true, &mut x);
                r8.eval_derivs(ww, zz, true, &mut y);
                for i in 0..3 {
                    assert!(
                        close(x[i], y[i], 1e-12),
                        "(8) (k,l)=({k},{l}) w={ww} z={zz} i={i}"
                    );
                }
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------------
// 23. contact relations (9), (10), Theorems 6–8: 1e-12 relative
// ---------------------------------------------------------------------------------------------------

/// Both pieces at u = u_p, except at the ends: at u_p = u_{p−1} the left piece (span p − 1) has zero length
/// and its recursion meets 0/0, at u_p = u_{p+1} the right one (span p) does.
fn sides(up: f64, a: f64, b: f64) -> Vec<bool> {
    if up <= a {
        vec![false]
    } else if up >= b {
        vec![true]
    } else {
        vec![false, true]
    }
}

fn rel(a: DVec3, b: DVec3, scale: f64) -> f64 {
    (a - b).max_abs() / scale.max(a.max_abs()).max(b.max_abs()).max(1.0)
}

#[test]
fn item23_contact_relation_9_all_orders_both_sides() {
    let fact = |i: usize| (1..=i).fold(1.0, |a, b| a * b as f64);
    for (seed, &(k, l)) in ORDERS.iter().enumerate() {
        let dt = data(k, l, 61 + seed as u64);
        for &up in &dt.ups_inside() {
            let fam = dt.family(Some(up), None);
            let env = fam.envelope().unwrap();
            for &v in &dt.vs()[..4] {
                let e = env.taylor::<6, 1>(up, v);
                for left in sides(up, dt.ku[dt.p - 1], dt.ku[dt.p + 1]) {
                    let s = fam.taylor::<6, 1>(up, v, up, 0.0, Var::U, Var::V, (left, false));
                    for i in 0..k {
                        let ew = e[i][0] * fact(i);
                        let su = s[i][0] * fact(i) * ((k - 1 - i) as f64 / (k - 1) as f64);
                        let err = rel(ew, su, 0.0);
                        assert!(
                            err <= 1e-12,
                            "(9) (k,l)=({k},{l}) up={up} v={v} i={i} left={left}: {err}"
                        );
                    }
                    // e^{(k)} ≡ 0 (e has order k − 1)
                    assert_eq!(e[k][0], DVec3::ZERO);
                    // (9) is not vacuous: s_u ≠ 0 here
                    assert!(s[1][0].max_abs() > 1e-3);
                }
            }
        }
    }
}

#[test]
fn item23_contact_relation_10() {
    let fact = |i: usize| (1..=i).fold(1.0, |a, b| a * b as f64);
    for (seed, &(k, l)) in ORDERS.iter().enumerate() {
        let dt = data(k, l, 71 + seed as u64);
        for &up in &dt.ups_inside() {
            let fam = dt.family(Some(up), None);
            let env = fam.envelope().unwrap();
            for &v in &dt.vs()[..6] {
                let e = env.taylor::<1, 6>(up, v);
                let s = fam.taylor::<1, 6>(up, v, up, 0.0, Var::U, Var::V, (false, false));
                for i in 0..=l {
                    let err = rel(e[0][i] * fact(i), s[0][i] * fact(i), 0.0);
                    assert!(
                        err <= 1e-12,
                        "(10) (k,l)=({k},{l}) up={up} v={v} i={i}: {err}"
                    );
                }
            }
        }
    }
}

#[test]
fn item23_theorem7_envelope_tangent_is_2_minus_k_times_the_path_tangent() {
    for (seed, &(k, l)) in ORDERS.iter().enumerate() {
        let dt = data(k, l, 81 + seed as u64);
        let fam = dt.family(Some(dt.ku[dt.p]), None);
        let env = fam.envelope().unwrap();
        for &ut in &dt.ups_inside() {
            for &v in &dt.vs()[..5] {
                let ew = env.taylor::<2, 1>(ut, v)[1][0];
                for left in sides(ut, dt.ku[dt.p - 1], dt.ku[dt.p + 1]) {
                    let (dup, _) = fam.d_dknots(ut, v, ut, 0.0, (left, false));
                    let err = rel(ew, dup * (2.0 - k as f64), 0.0);
                    assert!(
                        err <= 1e-12,
                        "Thm 7 (k,l)=({k},{l}) ũ={ut} v={v} left={left}: {err}"
                    );
                }
                // common point e(ũ, ṽ) = s(ũ, ṽ; ũ)
                assert!(rel(env.eval(ut, v), fam.eval_at(ut, v, ut, 0.0), 0.0) <= 1e-12);
            }
        }
    }
}

/// ∂s/∂u_p (exact, by jets) against a central difference: the error of the difference is
/// h²/6·|∂³s/∂u_p³| + ε·|s|/h; with h = 1e-5 and paths of size O(1)–O(10) on knot gaps ≥ 0.6 that is
/// ≲ 1e-9, so 1e-7·max(1, |s|) cannot be met by a wrong derivative of the magnitudes seen here (≥ 1e-2).
#[test]
fn knot_derivative_matches_central_differences() {
    for (seed, &(k, l)) in ORDERS.iter().enumerate() {
        let dt = data(k, l, 91 + seed as u64);
        let (a, b) = (dt.ku[dt.p - 1], dt.ku[dt.p + 1]);
        let fam = dt.family(Some(a), Some(dt.kv[dt.q]));
        let vq = dt.kv[dt.q];
        let h = 1e-5;
        for &up in &[a + 0.2 * (b - a), a + 0.9 * (b - a), b + 0.7, a - 1.3] {
            for &u in &Data::within(a, b) {
                if (u - up).abs() < 0.05 {
                    continue; // the piece switches at u = u_p
                }
                for &v in &dt.vs()[..5] {
                    let (dup, dvq) = fam.d_dknots(u, v, up, vq + 0.1, (false, false));
                    let fd = (fam.eval_at(u, v, up + h, vq + 0.1)
                        - fam.eval_at(u, v, up - h, vq + 0.1))
                        / (2.0 * h);
                    assert!(
                        (dup - fd).max_abs() <= 1e-7 * dup.max_abs().max(1.0),
                        "(k,l)=({k},{l}) up={up} u={u}"
                    );
                    let fd = (fam.eval_at(u, v, up, vq + 0.1 + h)
                        - fam.eval_at(u, v, up, vq + 0.1 - h))
                        / (2.0 * h);
                    assert!((dvq - fd).max_abs() <= 1e-7 * dvq.max_abs().max(1.0));
                }
            }
        }
    }
}

#[test]
fn item23_theorems_6_and_8_two_knots() {
    let fact = |i: usize| (1..=i).fold(1.0, |a, b| a * b as f64);
    for (seed, &(k, l)) in ORDERS.iter().enumerate() {
        let dt = data(k, l, 101 + seed as u64);
        for (&up, &vq) in dt.ups_inside().iter().zip(dt.vqs_inside().iter()) {
            let fam = dt.family(Some(up), Some(vq));
            let env = fam.envelope().unwrap();
            // Thm 6 at (w, z) = (u_p, v_q), all orders, both sides
            let e = env.taylor::<6, 6>(up, vq);
            let lu = sides(up, dt.ku[dt.p - 1], dt.ku[dt.p + 1]);
            let lv = sides(vq, dt.kv[dt.q - 1], dt.kv[dt.q + 1]);
            let pairs: Vec<(bool, bool)> = lu
                .iter()
                .flat_map(|&a| lv.iter().map(move |&b| (a, b)))
                .collect();
            for &(left_u, left_v) in &pairs {
                let s = fam.taylor::<6, 6>(up, vq, up, vq, Var::U, Var::V, (left_u, left_v));
                for i in 0..k {
                    let lhs = e[i][0] * fact(i);
                    let rhs = s[i][0] * fact(i) * ((k - 1 - i) as f64 / (k - 1) as f64);
                    assert!(rel(lhs, rhs, 0.0) <= 1e-12, "Thm 6 u (k,l)=({k},{l}) i={i}");
                }
                for i in 0..l {
                    let lhs = e[0][i] * fact(i);
                    let rhs = s[0][i] * fact(i) * ((l - 1 - i) as f64 / (l - 1) as f64);
                    assert!(rel(lhs, rhs, 0.0) <= 1e-12, "Thm 6 v (k,l)=({k},{l}) i={i}");
                }
            }
            // Thm 8: common point and both tangents at (ũ, ṽ) = (u_p, v_q)
            let t = env.taylor::<2, 2>(up, vq);
            assert!(rel(t[0][0], fam.eval_at(up, vq, up, vq), 0.0) <= 1e-12);
            for &left in &pairs {
                let (dup, dvq) = fam.d_dknots(up, vq, up, vq, left);
                assert!(
                    rel(t[1][0], dup * (2.0 - k as f64), 0.0) <= 1e-12,
                    "Thm 8 w (k,l)=({k},{l})"
                );
                assert!(
                    rel(t[0][1], dvq * (2.0 - l as f64), 0.0) <= 1e-12,
                    "Thm 8 z (k,l)=({k},{l})"
                );
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------------
// 24. limits (Theorems 3, 4 with the corrected list): |s(·; ±1e8) − lim| ≤ 1e-6
// ---------------------------------------------------------------------------------------------------

/// Σ_r N_r^k(u) d_{r,s} (the v = const control column as a B-spline curve in u), ordinary evaluation.
fn column_curve(dt: &Data, s: usize, u: f64) -> DVec3 {
    let col: Vec<DVec3> = (0..dt.nu).map(|r| dt.d(r, s)).collect();
    BSplineCurve::new(dt.k - 1, dt.ku.clone(), col)
        .unwrap()
        .eval(u)
}
fn row_curve(dt: &Data, r: usize, v: f64) -> DVec3 {
    let row: Vec<DVec3> = (0..dt.nv).map(|s| dt.d(r, s)).collect();
    BSplineCurve::new(dt.l - 1, dt.kv.clone(), row)
        .unwrap()
        .eval(v)
}

#[test]
fn item24_theorem3_limits_of_single_knots() {
    const X: f64 = 1e8;
    for (seed, &(k, l)) in ORDERS.iter().enumerate() {
        let dt = data(k, l, 111 + seed as u64);
        let (p, q) = (dt.p, dt.q);
        let (a, b) = (dt.ku[p - 1], dt.ku[p + 1]);
        let (c, d) = (dt.kv[q - 1], dt.kv[q + 1]);
        // v_q → ∓∞, u anywhere in the domain, v ∈ [v_{q−1}, v_{q+1})
        let fam = dt.family(None, Some(0.0));
        for &u in &dt.us() {
            for &v in &Data::within(c, d) {
                let (lm, lp) = (column_curve(&dt, q, u), column_curve(&dt, q - l, u));
                assert!(
                    (fam.eval_at(u, v, 0.0, -X) - lm).max_abs() <= 1e-6,
                    "(k,l)=({k},{l}) v_q→−∞"
                );
                assert!(
                    (fam.eval_at(u, v, 0.0, X) - lp).max_abs() <= 1e-6,
                    "(k,l)=({k},{l}) v_q→+∞"
                );
                // the exact limit (infinite knot)
                assert!((fam.eval_at(u, v, 0.0, f64::NEG_INFINITY) - lm).max_abs() <= 1e-13);
                assert!((fam.eval_at(u, v, 0.0, f64::INFINITY) - lp).max_abs() <= 1e-13);
            }
        }
        // u_p → ∓∞: Σ_s N_s^l(v) d_{p,s} and d_{p−k,s}
        let fam = dt.family(Some(0.0), None);
        for &u in &Data::within(a, b) {
            for &v in &dt.vs() {
                let (lm, lp) = (row_curve(&dt, p, v), row_curve(&dt, p - k, v));
                assert!(
                    (fam.eval_at(u, v, -X, 0.0) - lm).max_abs() <= 1e-6,
                    "(k,l)=({k},{l}) u_p→−∞"
                );
                assert!(
                    (fam.eval_at(u, v, X, 0.0) - lp).max_abs() <= 1e-6,
                    "(k,l)=({k},{l}) u_p→+∞"
                );
                assert!((fam.eval_at(u, v, f64::NEG_INFINITY, 0.0) - lm).max_abs() <= 1e-13);
                assert!((fam.eval_at(u, v, f64::INFINITY, 0.0) - lp).max_abs() <= 1e-13);
                // and the convergence is O(1/X): at 1e4 the error is 1e4 times larger, not zero
                let e4 = (fam.eval_at(u, v, 1e4, 0.0) - lp).max_abs();
                let e8 = (fam.eval_at(u, v, X, 0.0) - lp).max_abs();
                assert!(e4 > 1e-9 && e8 < e4 * 1e-3);
            }
        }
        // the limit curves the API reports are those rows/columns
        let ((im, rm), (ip, rp)) = fam.limit_curves(Var::U).unwrap();
        assert_eq!((im, ip), (p, p - k));
        assert_eq!(rm[0], dt.d(p, 0));
        assert_eq!(rp[dt.nv - 1], dt.d(p - k, dt.nv - 1));
    }
}

#[test]
fn item24_theorem4_corrected_list_and_the_printed_item_fails() {
    const X: f64 = 1e8;
    for (seed, &(k, l)) in ORDERS.iter().enumerate() {
        let dt = data(k, l, 121 + seed as u64);
        let (p, q) = (dt.p, dt.q);
        let fam = dt.family(Some(0.0), Some(0.0));
        let pts = fam.limit_points().unwrap();
        let expect = [
            ((p, q), -X, -X),
            ((p, q - l), -X, X),
            ((p - k, q), X, -X),
            ((p - k, q - l), X, X),
        ];
        let mut printed_error: f64 = 0.0;
        for &u in &Data::within(dt.ku[p - 1], dt.ku[p + 1]) {
            for &v in &Data::within(dt.kv[q - 1], dt.kv[q + 1]) {
                for (i, &((r, s), x, y)) in expect.iter().enumerate() {
                    assert_eq!(pts[i].0, (r, s));
                    let lim = dt.d(r, s);
                    assert!(
                        (fam.eval_at(u, v, x, y) - lim).max_abs() <= 1e-6,
                        "(k,l)=({k},{l}) limit {i}"
                    );
                    let exact =
                        fam.eval_at(u, v, x.signum() * f64::INFINITY, y.signum() * f64::INFINITY);
                    assert!((exact - lim).max_abs() <= 1e-13);
                }
                // the printed second item, (u_p, v_q) → (−∞, +∞) ↦ d_{p−k,q}, is wrong
                printed_error =
                    printed_error.max((fam.eval_at(u, v, -X, X) - dt.d(p - k, q)).max_abs());
            }
        }
        assert!(
            printed_error > 0.5,
            "(k,l)=({k},{l}) printed item error {printed_error}"
        );
    }
}

// ---------------------------------------------------------------------------------------------------
// Curves
// ---------------------------------------------------------------------------------------------------

fn curve_data(k: usize, seed: u64) -> (Vec<f64>, Vec<DVec2>, usize) {
    let mut rng = Rng(seed);
    let n = k + 5;
    let t = knots(k, n, &mut rng);
    let pts = (0..n)
        .map(|i| DVec2::new(i as f64 + 0.3 * rng.next(), 3.0 * rng.next()))
        .collect();
    (t, pts, k + 2)
}

#[test]
fn curve_family_envelope_theorem7_and_limits() {
    let fact = |i: usize| (1..=i).fold(1.0, |a, b| a * b as f64);
    for (seed, k) in (2..=6).enumerate() {
        let (t, pts, p) = curve_data(k, 200 + seed as u64);
        let (a, b) = (t[p - 1], t[p + 1]);
        let curve = KnotModifiedCurve::new(k, t.clone(), pts.clone(), Some(p), t[p]).unwrap();
        let env = curve.envelope().unwrap();
        assert_eq!(env.domain(), (a, b));
        for &up in &[a, a + 0.4 * (b - a), b] {
            // ordinary: the B-spline with the modified knot, values and two derivatives
            let c = curve.with_up(up);
            let r = BSplineCurve::new(k - 1, replaced(&t, p, up), pts.clone()).unwrap();
            let (d0, d1) = (t[k - 1], t[pts.len()]);
            for i in 0..=40 {
                let u = d0 + (d1 - d0) * i as f64 / 40.0;
                let (mut x, mut y) = ([DVec2::ZERO; 3], [DVec2::ZERO; 3]);
                c.eval_derivs(u, 2, &mut x);
                r.eval_derivs(u, 2, &mut y);
                for j in 0..3.min(k) {
                    assert!(close(x[j], y[j], 1e-12), "k={k} up={up} u={u} j={j}");
                }
            }
            // (9) both sides, all orders
            let e = env.taylor::<7>(up);
            for left in sides(up, a, b) {
                let s = c.taylor_u::<7>(up, up, left);
                for i in 0..k {
                    let lhs = e[i] * fact(i);
                    let rhs = s[i] * fact(i) * ((k - 1 - i) as f64 / (k - 1) as f64);
                    assert!(
                        (lhs - rhs).max_abs() <= 1e-12 * lhs.max_abs().max(1.0),
                        "k={k} i={i}"
                    );
                }
                // Theorem 7 (curve): e'(ũ) = (2 − k) ∂a/∂u_p at u_p = ũ
                let dup = c.d_dup(up, up, left);
                assert!(
                    (e[1] - dup * (2.0 - k as f64)).max_abs() <= 1e-12 * e[1].max_abs().max(1.0)
                );
            }
        }
        // limits: d_p (u_p → −∞), d_{p−k} (+∞) on [u_{p−1}, u_{p+1})
        let ((im, lm), (ip, lp)) = curve.limits().unwrap();
        assert_eq!((im, ip), (p, p - k));
        for &u in &Data::within(a, b) {
            assert!((curve.eval_at(u, -1e8) - lm).max_abs() <= 1e-6);
            assert!((curve.eval_at(u, 1e8) - lp).max_abs() <= 1e-6);
            assert!((curve.eval_at(u, f64::NEG_INFINITY) - lm).max_abs() <= 1e-13);
        }
        // paths: the first point of an ordinary path is the curve with u_p = u_{p−1}
        let mut path = Vec::new();
        curve.path_into(0.5 * (a + b), &[a, b], &mut path);
        assert_eq!(path.len(), 2);
        assert!(close(path[0], curve.with_up(a).eval(0.5 * (a + b)), 1e-15));
    }
}

// ---------------------------------------------------------------------------------------------------
// Validation
// ---------------------------------------------------------------------------------------------------

#[test]
fn bad_input_is_rejected_with_the_field_named() {
    let dt = data(4, 3, 7);
    let mk = |p: usize, q: usize, net: Vec<DVec3>, ku: Vec<f64>, k: usize| {
        KnotModifiedSurface::new(
            k,
            3,
            ku,
            dt.kv.clone(),
            dt.nu,
            dt.nv,
            net,
            Some((p, 1.0)),
            Some((q, 1.0)),
        )
    };
    // knot index out of range (not interior)
    let e = mk(3, dt.q, dt.net.clone(), dt.ku.clone(), 4).unwrap_err();
    assert_eq!((e.field(), e.kind()), ("p", ErrorKind::OutOfRange));
    let e = mk(dt.p, dt.nv, dt.net.clone(), dt.ku.clone(), 4).unwrap_err();
    assert_eq!(e.field(), "q");
    // order below 2
    let e = mk(dt.p, dt.q, dt.net.clone(), dt.ku.clone(), 1).unwrap_err();
    assert_eq!(e.field(), "orderU");
    // non-finite knots
    let e = mk(dt.p, dt.q, dt.net.clone(), replaced(&dt.ku, 2, f64::NAN), 4).unwrap_err();
    assert_eq!((e.field(), e.kind()), ("knotsU[2]", ErrorKind::NotFinite));
    let e = mk(
        dt.p,
        dt.q,
        dt.net.clone(),
        replaced(&dt.ku, dt.p, f64::INFINITY),
        4,
    )
    .unwrap_err();
    assert_eq!(e.kind(), ErrorKind::NotFinite);
    // wrong shapes
    let e = mk(dt.p, dt.q, dt.net[1..].to_vec(), dt.ku.clone(), 4).unwrap_err();
    assert_eq!(e.field(), "controlPoints");
    let e = mk(dt.p, dt.q, dt.net.clone(), dt.ku[1..].to_vec(), 4).unwrap_err();
    assert_eq!((e.field(), e.kind()), ("knotsU", ErrorKind::SizeMismatch));
    // other knots must not decrease; the moved one may be anywhere
    let mut ku = dt.ku.clone();
    ku.swap(dt.p + 1, dt.p + 2);
    assert_eq!(
        mk(dt.p, dt.q, dt.net.clone(), ku, 4).unwrap_err().field(),
        format!("knotsU[{}]", dt.p + 2)
    );
    assert!(mk(dt.p, dt.q, dt.net.clone(), replaced(&dt.ku, dt.p, 100.0), 4).is_ok());
    // NaN knot value
    let e = KnotModifiedCurve::new(
        3,
        vec![0., 0., 0., 1., 2., 2., 2.],
        vec![DVec2::ZERO; 4],
        Some(3),
        f64::NAN,
    )
    .unwrap_err();
    assert_eq!(e.field(), "up");
    let e = KnotModifiedCurve::new(
        3,
        vec![0., 0., 0., 1., 2., 2., 2.],
        vec![DVec2::ZERO; 4],
        Some(2),
        0.5,
    )
    .unwrap_err();
    assert_eq!(e.field(), "p");
}

// ---------------------------------------------------------------------------------------------------
// Theorem 1 / Corollaries 1–2: the farthest affected patches move on straight lines / bilinear surfaces
// ---------------------------------------------------------------------------------------------------

/// Largest distance of the points from the line through the first and last one, relative to their spread.
fn off_line(pts: &[DVec3]) -> f64 {
    let (a, b) = (pts[0], pts[pts.len() - 1]);
    let d = (b - a).normalize();
    let spread = (b - a).length();
    pts.iter()
        .map(|p| ((*p - a) - d * (*p - a).dot(d)).length())
        .fold(0.0, f64::max)
        / spread.max(1e-300)
}

#[test]
fn theorem1_paths_of_the_outermost_patches_are_straight_and_inner_ones_are_not() {
    let mut checked = 0;
    for (seed, &(k, l)) in ORDERS.iter().enumerate() {
        let dt = data(k, l, 131 + seed as u64);
        let fam = dt.family(Some(dt.ku[dt.p]), Some(dt.kv[dt.q]));
        let ups: Vec<f64> = (0..=10)
            .map(|i| dt.ku[dt.p - 1] + (dt.ku[dt.p + 1] - dt.ku[dt.p - 1]) * i as f64 / 10.0)
            .collect();
        let vqs: Vec<f64> = (0..=10)
            .map(|i| dt.kv[dt.q - 1] + (dt.kv[dt.q + 1] - dt.kv[dt.q - 1]) * i as f64 / 10.0)
            .collect();
        let mid = |i: usize, t: &[f64]| 0.5 * (t[i] + t[i + 1]);
        // patch s_{p+k−2, ·} (g = k − 2: order k − g = 2, a straight path), inside the domain here
        // (with the test data it lies in the domain for k ≤ 4; the left one, s_{p−k+1}, for k = 3)
        let far_u = dt.p + k - 2;
        let v = mid(dt.l - 1, &dt.kv);
        for far in [Some(far_u), (dt.p + 1).checked_sub(k)] {
            let Some(far) = far.filter(|&i| i >= k - 1 && i < dt.nu) else {
                continue;
            };
            let mut path = Vec::new();
            fam.path_into(mid(far, &dt.ku), v, &ups, &mut path);
            checked += 1;
            assert!(
                off_line(&path) < 1e-12,
                "(k,l)=({k},{l}) outermost path not straight: {}",
                off_line(&path)
            );
        }
        // the central patch s_p (order k, for k ≥ 3 a genuinely curved rational path)
        let mut path = Vec::new();
        fam.path_into(mid(dt.p, &dt.ku), v, &ups, &mut path);
        assert!(
            off_line(&path) > 1e-4,
            "(k,l)=({k},{l}) central path unexpectedly straight"
        );
        // Corollary 2: the corner patch s_{p+k−2, q+l−2} moves on a doubly ruled (bilinear-type) surface
        let far_v = dt.q + l - 2;
        if far_v < dt.nv && far_u < dt.nu {
            checked += 1;
            let (u, v) = (mid(far_u, &dt.ku), mid(far_v, &dt.kv));
            for &vq in &[vqs[2], vqs[7]] {
                let line: Vec<DVec3> = ups.iter().map(|&up| fam.eval_at(u, v, up, vq)).collect();
                assert!(off_line(&line) < 1e-12);
            }
            for &up in &[ups[3], ups[8]] {
                let line: Vec<DVec3> = vqs.iter().map(|&vq| fam.eval_at(u, v, up, vq)).collect();
                assert!(off_line(&line) < 1e-12);
            }
        }
    }
    assert!(checked >= 5, "outermost patches checked: {checked}");
}

#[test]
fn substituted_knots_replace_the_moved_knot_whatever_its_value() {
    // order 3, 5 control points: knots u_0..u_7; u_4 moves
    let t = vec![0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0];
    let pts: Vec<DVec2> = (0..5)
        .map(|i| DVec2::new(i as f64, (i * i) as f64))
        .collect();
    let c = KnotModifiedCurve::new(3, t.clone(), pts.clone(), Some(4), 1.5).unwrap();
    let mut want = t.clone();
    want[4] = 7.5; // beyond its neighbours: not a B-spline, still the shown knots
    assert_eq!(c.line().substituted_knots(7.5), want);
    assert_eq!(c.line().modified_knots(7.5), None);
    want[4] = 1.5;
    assert_eq!(c.line().substituted_knots(1.5), want);
    assert_eq!(c.line().modified_knots(1.5), Some(want));
    // nothing moved: the knots themselves
    let c0 = KnotModifiedCurve::new(3, t.clone(), pts, None, 0.0).unwrap();
    assert_eq!(c0.line().substituted_knots(7.5), t);
}

// ---------------------------------------------------------------------------------------------------
// Issue 30, item 3: formula paths that no test reached before (each seen failing on its hand mutant).

/// The envelope curve's second derivative (the curve case of eq. (6)) against central differences of its
/// first derivative: `out[2] = t[2]·2` (Taylor coefficient times 2!) — `·1` is off by a factor of two.
#[test]
fn envelope_curve_second_derivative_matches_differences_of_the_first() {
    for (seed, k) in (3..=6).enumerate() {
        let (t, pts, p) = curve_data(k, 900 + seed as u64);
        let curve = KnotModifiedCurve::new(k, t.clone(), pts, Some(p), t[p]).unwrap();
        let env = curve.envelope().unwrap();
        let (a, b) = env.domain();
        let h = 1e-5;
        let mut checked = 0;
        for i in 1..40 {
            let w = a + (b - a) * i as f64 / 40.0;
            // stay off the envelope's knots (the second derivative jumps there when k − 1 = 3)
            if t.iter().any(|&x| (x - w).abs() < 1e-3) {
                continue;
            }
            let (mut lo, mut hi, mut at) = ([DVec2::ZERO; 3], [DVec2::ZERO; 3], [DVec2::ZERO; 3]);
            env.eval_derivs(w - h, 1, &mut lo);
            env.eval_derivs(w + h, 1, &mut hi);
            env.eval_derivs(w, 2, &mut at);
            let diff = (hi[1] - lo[1]) / (2.0 * h);
            assert!(
                (at[2] - diff).max_abs() <= 1e-5 * diff.max_abs().max(1.0),
                "k={k} w={w}: e'' = {:?}, differences {:?}",
                at[2],
                diff
            );
            checked += 1;
        }
        assert!(checked > 20, "k={k}: {checked} points checked");
        // where e'' is not zero (k − 1 ≥ 3, a curved envelope) the check has something to compare
        if k >= 4 {
            let mut at = [DVec2::ZERO; 3];
            env.eval_derivs(0.5 * (a + b) + 1e-3, 2, &mut at);
            assert!(
                at[2].max_abs() > 1e-6,
                "k={k}: e'' vanishes, the check would not see a factor"
            );
        }
    }
}

/// The de Boor triangle with the moved knot on another knot (an extended family, u_p past its neighbour):
/// some denominators u_{j+k−r} − u_j vanish, and Definition 1 reads 0/0 := 0 (α = 0: the entry is the point to
/// its left). Every entry is compared with the recursion written out here on the knots with u_p := up.
#[test]
fn de_boor_triangle_uses_zero_over_zero_as_zero_where_the_moved_knot_meets_another() {
    let mut zero_dens = 0;
    for (seed, k) in (3..=5).enumerate() {
        let (t, pts, p) = curve_data(k, 950 + seed as u64);
        let curve = KnotModifiedCurve::new(k, t.clone(), pts.clone(), Some(p), t[p]).unwrap();
        assert_eq!(curve.up(), t[p], "KnotModifiedCurve::up");
        assert_eq!(
            curve.with_up(t[p + 2]).up(),
            t[p + 2],
            "KnotModifiedCurve::up after with_up"
        );
        // u_p on each knot from u_{p−2} to u_{p+2} (equal to its neighbour, or past it onto the next one)
        for q in [p - 2, p - 1, p + 1, p + 2] {
            let up = t[q];
            let tk = replaced(&t, p, up);
            let (d0, d1) = (t[k - 1], t[pts.len()]);
            for i in 0..=30 {
                let u = d0 + (d1 - d0) * (i as f64 + 0.37) / 31.0;
                let tri = curve.de_boor(u, up);
                let s = tri.span;
                // the recursion by hand: level[a] = d_{s−k+1+a}^{r}
                let mut level: Vec<DVec2> = (0..k).map(|a| pts[s + 1 + a - k]).collect();
                let mut want = Vec::new();
                for r in 1..k {
                    for a in (r..k).rev() {
                        let j = s + 1 + a - k;
                        let den = tk[j + k - r] - tk[j];
                        let alpha = if den == 0.0 {
                            zero_dens += 1;
                            0.0
                        } else {
                            (u - tk[j]) / den
                        };
                        level[a] = level[a - 1] * (1.0 - alpha) + level[a] * alpha;
                        want.push((r, j, alpha, level[a]));
                    }
                }
                want.sort_by_key(|w| (w.0, w.1));
                assert_eq!(tri.steps.len(), want.len());
                for (st, w) in tri.steps.iter().zip(&want) {
                    assert_eq!((st.level, st.index), (w.0, w.1));
                    assert!(
                        (st.alpha - w.2).abs() <= 1e-14,
                        "k={k} up=u{q} u={u} d_{}^{}: α {} vs {}",
                        w.1,
                        w.0,
                        st.alpha,
                        w.2
                    );
                    assert!(
                        close(st.point, w.3, 1e-12),
                        "k={k} up=u{q} u={u} d_{}^{}",
                        w.1,
                        w.0
                    );
                }
            }
        }
    }
    assert!(
        zero_dens > 0,
        "no vanishing denominator was met: the 0/0 rule is not exercised"
    );
}
