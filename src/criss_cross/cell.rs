//! One criss-cross cell: the 13 BB ordinates of a quadratic, its four triangles, the C¹ completion
//! from edge traces and the evaluation on a triangle (`surfaces.md` §2.1–2.2).

use crate::point::Point;

/// Index of the corner ordinate at (s, t) = (0, 0) in a [`CellNet`].
pub const C00: usize = 0;
/// Corner (1, 0).
pub const C10: usize = 1;
/// Corner (1, 1).
pub const C11: usize = 2;
/// Corner (0, 1).
pub const C01: usize = 3;
/// Bottom edge midpoint (½, 0).
pub const EB: usize = 4;
/// Right edge midpoint (1, ½).
pub const ER: usize = 5;
/// Top edge midpoint (½, 1).
pub const ET: usize = 6;
/// Left edge midpoint (0, ½).
pub const EL: usize = 7;
/// Half-diagonal (¼, ¼).
pub const D00: usize = 8;
/// Half-diagonal (¾, ¼).
pub const D10: usize = 9;
/// Half-diagonal (¾, ¾).
pub const D11: usize = 10;
/// Half-diagonal (¼, ¾).
pub const D01: usize = 11;
/// Centre (½, ½).
pub const O: usize = 12;

/// The 13 BB ordinates of a quadratic on one criss-cross cell, indexed by [`C00`] … [`O`].
pub type CellNet<P> = [P; 13];

/// Local (s, t) domain points of the 13 ordinates.
pub const DOMAIN_POINTS: [(f64, f64); 13] = [
    (0.0, 0.0),
    (1.0, 0.0),
    (1.0, 1.0),
    (0.0, 1.0),
    (0.5, 0.0),
    (1.0, 0.5),
    (0.5, 1.0),
    (0.0, 0.5),
    (0.25, 0.25),
    (0.75, 0.25),
    (0.75, 0.75),
    (0.25, 0.75),
    (0.5, 0.5),
];

/// The four triangles of a cell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Triangle {
    /// (c00, c10, o).
    Bottom,
    /// (c10, c11, o).
    Right,
    /// (c11, c01, o).
    Top,
    /// (c01, c00, o).
    Left,
}

impl Triangle {
    /// The four triangles of a cell: bottom, right, top, left.
    pub const ALL: [Triangle; 4] = [
        Triangle::Bottom,
        Triangle::Right,
        Triangle::Top,
        Triangle::Left,
    ];

    /// The triangle containing local (s, t): B if t ≤ s and t ≤ 1−s, T if t ≥ s and t ≥ 1−s, R if s ≥ t,
    /// else L (ties are irrelevant: S₂¹ is C¹).
    pub fn locate(s: f64, t: f64) -> Triangle {
        if t <= s && t <= 1.0 - s {
            Triangle::Bottom
        } else if t >= s && t >= 1.0 - s {
            Triangle::Top
        } else if s >= t {
            Triangle::Right
        } else {
            Triangle::Left
        }
    }

    /// Net indices of (b200, b020, b002, b110, b011, b101).
    pub fn ordinates(self) -> [usize; 6] {
        match self {
            Triangle::Bottom => [C00, C10, O, EB, D10, D00],
            Triangle::Right => [C10, C11, O, ER, D11, D10],
            Triangle::Top => [C11, C01, O, ET, D01, D11],
            Triangle::Left => [C01, C00, O, EL, D00, D01],
        }
    }

    /// Barycentric coordinates of local (s, t) and their constant s- and t-derivatives.
    fn barycentric(self, s: f64, t: f64) -> ([f64; 3], [f64; 3], [f64; 3]) {
        match self {
            Triangle::Bottom => (
                [1.0 - s - t, s - t, 2.0 * t],
                [-1.0, 1.0, 0.0],
                [-1.0, -1.0, 2.0],
            ),
            Triangle::Right => (
                [s - t, s + t - 1.0, 2.0 - 2.0 * s],
                [1.0, 1.0, -2.0],
                [-1.0, 1.0, 0.0],
            ),
            Triangle::Top => (
                [s + t - 1.0, t - s, 2.0 - 2.0 * t],
                [1.0, -1.0, 0.0],
                [1.0, 1.0, -2.0],
            ),
            Triangle::Left => (
                [t - s, 1.0 - s - t, 2.0 * s],
                [-1.0, -1.0, 2.0],
                [1.0, -1.0, 0.0],
            ),
        }
    }
}

/// Completes a C¹ cell net from its 4 corners and 4 edge-midpoint ordinates (`surfaces.md` §2.2).
pub(crate) fn cell_net_from_edges<P: Point>(corners: [P; 4], edges: [P; 4]) -> CellNet<P> {
    let [c00, c10, c11, c01] = corners;
    let [eb, er, et, el] = edges;
    [
        c00,
        c10,
        c11,
        c01,
        eb,
        er,
        et,
        el,
        (eb + el) * 0.5,
        (eb + er) * 0.5,
        (er + et) * 0.5,
        (et + el) * 0.5,
        (eb + er + et + el) * 0.25,
    ]
}

/// Value and local (s, t) derivatives of the quadratic with net `net` at local (s, t):
/// f = Σ b_{ijk}·2/(i!j!k!)·λ1^iλ2^jλ3^k on the triangle containing (s, t).
pub fn eval_cell_net<P: Point>(net: &CellNet<P>, s: f64, t: f64) -> [P; 3] {
    let tri = Triangle::locate(s, t);
    eval_on_triangle(net, tri, s, t)
}

/// Like [`eval_cell_net`] on a given triangle (its polynomial, extended beyond it).
pub fn eval_on_triangle<P: Point>(net: &CellNet<P>, tri: Triangle, s: f64, t: f64) -> [P; 3] {
    let [i200, i020, i002, i110, i011, i101] = tri.ordinates();
    let (b200, b020, b002, b110, b011, b101) = (
        net[i200], net[i020], net[i002], net[i110], net[i011], net[i101],
    );
    let ([l1, l2, l3], ds, dt) = tri.barycentric(s, t);
    let f = b200 * (l1 * l1)
        + b020 * (l2 * l2)
        + b002 * (l3 * l3)
        + b110 * (2.0 * l1 * l2)
        + b011 * (2.0 * l2 * l3)
        + b101 * (2.0 * l1 * l3);
    let g1 = (b200 * l1 + b110 * l2 + b101 * l3) * 2.0;
    let g2 = (b110 * l1 + b020 * l2 + b011 * l3) * 2.0;
    let g3 = (b101 * l1 + b011 * l2 + b002 * l3) * 2.0;
    let fs = g1 * ds[0] + g2 * ds[1] + g3 * ds[2];
    let ft = g1 * dt[0] + g2 * dt[1] + g3 * dt[2];
    [f, fs, ft]
}
