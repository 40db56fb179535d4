//! A boundary-element reference for potential flow around any closed polygon: the added-mass
//! matrix of a rigid section moving in unbounded ideal fluid at rest at infinity.
//!
//! Constant-strength source panels on the polygon's edges, collocated at their midpoints, solve
//! the exterior Neumann problem ∂φ/∂n = U·n for each unit motion (translation along x, along y,
//! rotation about the origin). Then m_jk = −ρ ∮ φ_j (U_k·n) ds (n out of the body), from the
//! kinetic energy T = −½ρ ∮ φ ∂φ/∂n ds. The panel integrals are exact for straight panels:
//!
//! ```text
//!   ∫₀ᴸ ln r dξ = x ln r₁ − (x − L) ln r₂ − L + y (atan(x/y) − atan((x − L)/y))
//! ```
//!
//! in the panel's frame (x along it from its start, y to its left; r₁, r₂ the distances to its
//! ends). The method is independent of the flow solver: it shares nothing with the grid.
#![allow(dead_code)]

use std::f64::consts::PI;

use faer::linalg::solvers::Solve;

/// The added-mass matrix (rows and columns: x, y, pitch about the origin), ρ = 1.
pub fn added_mass(points: &[[f64; 2]]) -> [[f64; 3]; 3] {
    let n = points.len();
    let panel = |k: usize| (points[k], points[(k + 1) % n]);
    let mid: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let (a, b) = panel(k);
            [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]
        })
        .collect();
    // Outward normal of a counter-clockwise polygon's edge: to the right of a → b.
    let normal = |k: usize| {
        let (a, b) = panel(k);
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let l = dx.hypot(dy);
        [dy / l, -dx / l]
    };
    let length = |k: usize| {
        let (a, b) = panel(k);
        (b[0] - a[0]).hypot(b[1] - a[1])
    };
    let mut a_mat = faer::Mat::<f64>::zeros(n, n);
    let mut phi_mat = faer::Mat::<f64>::zeros(n, n);
    for i in 0..n {
        let ni = normal(i);
        for j in 0..n {
            let (vel, pot) = influence(panel(j), mid[i], i == j);
            a_mat[(i, j)] = vel[0] * ni[0] + vel[1] * ni[1];
            phi_mat[(i, j)] = pot;
        }
    }
    let mut rhs = faer::Mat::<f64>::zeros(n, 3);
    for i in 0..n {
        let (m, nr) = (mid[i], normal(i));
        rhs[(i, 0)] = nr[0];
        rhs[(i, 1)] = nr[1];
        rhs[(i, 2)] = m[0] * nr[1] - m[1] * nr[0];
    }
    let sigma = a_mat.partial_piv_lu().solve(&rhs);
    let phi = &phi_mat * &sigma;
    let mut out = [[0.0; 3]; 3];
    for (j, row) in out.iter_mut().enumerate() {
        for (k, cell) in row.iter_mut().enumerate() {
            *cell = -(0..n)
                .map(|i| phi[(i, j)] * rhs[(i, k)] * length(i))
                .sum::<f64>();
        }
    }
    out
}

/// The velocity and potential at `x` of a unit source density on the panel (a, b); `own`: x is
/// the panel's own midpoint, on the outside (the fluid side).
fn influence((a, b): ([f64; 2], [f64; 2]), x: [f64; 2], own: bool) -> ([f64; 2], f64) {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let l = dx.hypot(dy);
    let t = [dx / l, dy / l];
    let left = [-t[1], t[0]];
    let r = [x[0] - a[0], x[1] - a[1]];
    let xl = r[0] * t[0] + r[1] * t[1];
    let yl = if own {
        0.0
    } else {
        r[0] * left[0] + r[1] * left[1]
    };
    let r1 = xl.hypot(yl);
    let r2 = (xl - l).hypot(yl);
    let k = 0.5 / PI;
    let u = k * (r1 / r2).ln();
    let (v, angle) = if own {
        // The fluid lies to the right (outside a counter-clockwise polygon).
        (-0.5, 0.0)
    } else if yl == 0.0 {
        (0.0, 0.0)
    } else {
        let d = (xl / yl).atan() - ((xl - l) / yl).atan();
        (k * d, yl * d)
    };
    let ln = |r: f64| if r > 0.0 { r.ln() } else { 0.0 };
    let pot = k * (xl * ln(r1) - (xl - l) * ln(r2) - l + angle);
    ([u * t[0] + v * left[0], u * t[1] + v * left[1]], pot)
}

/// The outline resampled into about `m` panels for the panel method: cut at its corners (where
/// the direction turns by more than 30°), each smooth piece divided in proportion to its length,
/// evenly in the sum of its relative arc length and turning angle (so curved parts get more
/// panels), with a cosine spacing of that measure that clusters panels at the corners.
pub fn panelled(points: &[[f64; 2]], m: usize) -> Vec<[f64; 2]> {
    let n = points.len();
    let dir = |k: usize| {
        let (a, b) = (points[k], points[(k + 1) % n]);
        let l = (b[0] - a[0]).hypot(b[1] - a[1]);
        [(b[0] - a[0]) / l, (b[1] - a[1]) / l]
    };
    let corner = |k: usize| {
        let (p, q) = (dir((k + n - 1) % n), dir(k));
        p[0] * q[0] + p[1] * q[1] < (30f64).to_radians().cos()
    };
    let mut corners: Vec<usize> = (0..n).filter(|&k| corner(k)).collect();
    let smooth = corners.is_empty();
    if smooth {
        corners.push(0);
    }
    let seg_len = |k: usize| {
        let (a, b) = (points[k], points[(k + 1) % n]);
        (b[0] - a[0]).hypot(b[1] - a[1])
    };
    let perimeter: f64 = (0..n).map(seg_len).sum();
    let mut out = Vec::with_capacity(m + corners.len());
    for (c, &start) in corners.iter().enumerate() {
        let end = corners[(c + 1) % corners.len()];
        let count = if end > start {
            end - start
        } else {
            end + n - start
        };
        let edges: Vec<usize> = (0..count).map(|k| (start + k) % n).collect();
        let length: f64 = edges.iter().map(|&e| seg_len(e)).sum();
        let pieces = ((m as f64 * length / perimeter).round() as usize).max(8);
        let measure = Measure::new(points, &edges);
        for s in 0..pieces {
            let f = s as f64 / pieces as f64;
            let tau = if smooth {
                f
            } else {
                0.5 * (1.0 - (PI * f).cos())
            };
            out.push(measure.point(points, &edges, tau));
        }
    }
    out
}

/// The cumulative measure (arc length / total + turning / total turning, halved) at each vertex
/// of a chain of edges.
struct Measure {
    at_vertex: Vec<f64>,
}

impl Measure {
    fn new(points: &[[f64; 2]], edges: &[usize]) -> Measure {
        let n = points.len();
        let len = |e: usize| {
            let (a, b) = (points[e], points[(e + 1) % n]);
            (b[0] - a[0]).hypot(b[1] - a[1])
        };
        let angle = |e: usize| {
            let (a, b) = (points[e], points[(e + 1) % n]);
            (b[1] - a[1]).atan2(b[0] - a[0])
        };
        let total_len: f64 = edges.iter().map(|&e| len(e)).sum();
        // Turning at each interior vertex of the chain (half of it to each adjacent edge).
        let turn: Vec<f64> = edges
            .windows(2)
            .map(|w| {
                let d = angle(w[1]) - angle(w[0]);
                (d + PI).rem_euclid(2.0 * PI) - PI
            })
            .map(f64::abs)
            .collect();
        let total_turn: f64 = turn.iter().sum::<f64>().max(1e-300);
        let mut at_vertex = vec![0.0];
        for (k, &e) in edges.iter().enumerate() {
            let t_before = if k > 0 { 0.5 * turn[k - 1] } else { 0.0 };
            let t_after = turn.get(k).map_or(0.0, |t| 0.5 * t);
            let w = 0.5 * len(e) / total_len + 0.5 * (t_before + t_after) / total_turn;
            at_vertex.push(at_vertex[k] + w);
        }
        let total = at_vertex[edges.len()];
        at_vertex.iter_mut().for_each(|m| *m /= total);
        Measure { at_vertex }
    }

    /// The point at the fraction `f` of the measure.
    fn point(&self, points: &[[f64; 2]], edges: &[usize], f: f64) -> [f64; 2] {
        let n = points.len();
        let k = self
            .at_vertex
            .partition_point(|&m| m <= f)
            .clamp(1, edges.len())
            - 1;
        let (m0, m1) = (self.at_vertex[k], self.at_vertex[k + 1]);
        let t = if m1 > m0 { (f - m0) / (m1 - m0) } else { 0.0 };
        let e = edges[k];
        let (a, b) = (points[e], points[(e + 1) % n]);
        [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
    }
}
