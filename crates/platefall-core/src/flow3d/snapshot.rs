//! What the 3-D recording shows of the flow at one moment (docs/three-d.md "Recording"): the
//! vorticity and the Q criterion at the cell centres, from the cell-centred velocity's
//! gradient, with the grid's cell centres and the plate's box in body axes. The grid moves with
//! the body, so the snapshot carries the frame too.
//!
//! u is the inertial velocity along the body axes, so ∇u is the inertial gradient turned into
//! body axes and both ω and Q = ½(‖Ω‖² − ‖S‖²) = −½ ∂_b u_a ∂_a u_b are the inertial ones.
use super::frame::Frame3;
use super::grid::Grid3;
use super::layout::Layout;
use super::solver::FlowSolver3;

/// The flow at one moment, on the cell centres (x fastest, then y, then z).
#[derive(Clone, Debug)]
pub struct FieldSnapshot3 {
    /// Time (c/U).
    pub t: f64,
    /// The body's frame at `t`.
    pub frame: Frame3,
    /// Cells along x, y, z.
    pub n: [usize; 3],
    /// Node coordinates along each axis, body axes (chords; n + 1 each).
    pub nodes: [Vec<f64>; 3],
    /// Cell-centre coordinates along each axis, body axes (chords).
    pub centres: [Vec<f64>; 3],
    /// The plate's box in body axes: its lowest and highest corners.
    pub plate: Option<[[f64; 3]; 2]>,
    /// The velocity at the cell centres (U), inertial velocity along the body axes (inside the
    /// plate: the plate's own).
    pub velocity: [Vec<f64>; 3],
    /// The cell pressures (ρU²; zero in the plate).
    pub pressure: Vec<f64>,
    /// Vorticity components (U/c) in body axes; NaN inside the plate.
    pub vorticity: [Vec<f32>; 3],
    /// The Q criterion ((U/c)²); NaN inside the plate.
    pub q: Vec<f32>,
}

impl FieldSnapshot3 {
    /// Flat index of cell (i, j, k).
    pub fn index(&self, i: usize, j: usize, k: usize) -> usize {
        i + self.n[0] * (j + self.n[1] * k)
    }
}

impl FlowSolver3 {
    /// The vorticity and Q at the cell centres now.
    pub fn snapshot(&self) -> FieldSnapshot3 {
        let grid = self.grid();
        let centres = grid.nodes.clone().map(|x| {
            x.windows(2)
                .map(|w| 0.5 * (w[0] + w[1]))
                .collect::<Vec<_>>()
        });
        let u = cell_velocity(self.velocity(), self.layout());
        let cells = grid.cells();
        let mut vorticity: [Vec<f32>; 3] = std::array::from_fn(|_| vec![f32::NAN; cells]);
        let mut q = vec![f32::NAN; cells];
        let n = grid.n;
        for k in 0..n[2] {
            for j in 0..n[1] {
                for i in 0..n[0] {
                    if grid.covers_cell([i, j, k]) {
                        continue;
                    }
                    let g = gradient(&u, &centres, n, [i, j, k], grid.periodic_z);
                    let idx = i + n[0] * (j + n[1] * k);
                    let w = [g[2][1] - g[1][2], g[0][2] - g[2][0], g[1][0] - g[0][1]];
                    for c in 0..3 {
                        vorticity[c][idx] = w[c] as f32;
                    }
                    let s: f64 = (0..3)
                        .flat_map(|a| (0..3).map(move |b| (a, b)))
                        .map(|(a, b)| g[a][b] * g[b][a])
                        .sum();
                    q[idx] = (-0.5 * s) as f32;
                }
            }
        }
        FieldSnapshot3 {
            t: self.t(),
            frame: *self.frame(),
            n,
            plate: grid.plate.then(|| plate_box(grid)),
            nodes: grid.nodes.clone(),
            centres,
            velocity: u,
            pressure: self.p().to_vec(),
            vorticity,
            q,
        }
    }
}

/// The plate's corners in body axes.
fn plate_box(grid: &Grid3) -> [[f64; 3]; 2] {
    [
        std::array::from_fn(|a| grid.nodes[a][grid.plate_lo[a]]),
        std::array::from_fn(|a| grid.nodes[a][grid.plate_hi[a]]),
    ]
}

/// The velocity at the cell centres: each component the mean of its two faces.
fn cell_velocity(vel: &[Vec<f64>; 3], lay: &Layout) -> [Vec<f64>; 3] {
    let n = lay.n;
    std::array::from_fn(|c| {
        let mut out = Vec::with_capacity(n[0] * n[1] * n[2]);
        for k in 0..n[2] as isize {
            for j in 0..n[1] as isize {
                for i in 0..n[0] as isize {
                    let p = [i, j, k];
                    let mut up = p;
                    up[c] += 1;
                    out.push(0.5 * (vel[c][lay.at(p)] + vel[c][lay.at(up)]));
                }
            }
        }
        out
    })
}

/// ∂u_a/∂x_b at cell `p` (g[a][b]): central differences between the neighbouring centres,
/// one-sided at the grid's edge (wrapping along a periodic z).
fn gradient(
    u: &[Vec<f64>; 3],
    x: &[Vec<f64>; 3],
    n: [usize; 3],
    p: [usize; 3],
    periodic_z: bool,
) -> [[f64; 3]; 3] {
    let at = |q: [usize; 3]| q[0] + n[0] * (q[1] + n[1] * q[2]);
    let mut g = [[0.0; 3]; 3];
    for b in 0..3 {
        let wrap = b == 2 && periodic_z && n[2] > 2;
        let (lo, hi, dx) = neighbours(p[b], n[b], &x[b], wrap);
        let (mut ql, mut qh) = (p, p);
        ql[b] = lo;
        qh[b] = hi;
        if dx == 0.0 {
            continue;
        }
        for (a, ua) in u.iter().enumerate() {
            g[a][b] = (ua[at(qh)] - ua[at(ql)]) / dx;
        }
    }
    g
}

/// The two cells a difference along one axis uses at index `i` of `m`, and their distance.
fn neighbours(i: usize, m: usize, x: &[f64], wrap: bool) -> (usize, usize, f64) {
    if m < 2 {
        return (i, i, 0.0);
    }
    if wrap {
        let period = x[m - 1] - x[0] + (x[1] - x[0]);
        let (lo, hi) = ((i + m - 1) % m, (i + 1) % m);
        return (lo, hi, 2.0 * period / m as f64);
    }
    let lo = i.saturating_sub(1);
    let hi = (i + 1).min(m - 1);
    (lo, hi, x[hi] - x[lo])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flow3d::{FlowParams3, GridSpec3, OuterBc3, Span, Stretch3};

    fn solver(u: impl Fn([f64; 3]) -> [f64; 3]) -> FlowSolver3 {
        let spec = GridSpec3 {
            resolution: 4,
            thickness: 0.25,
            span: Span::Finite(1.0),
            extent: [1.5; 3],
            stretch: Stretch3::GrowthCap(1.3),
            memory_limit: 1e9,
            shape: Default::default(),
        };
        let grid = Grid3::new(&spec).unwrap().without_plate();
        let params = FlowParams3::default();
        let mut s = FlowSolver3::new(grid, params, OuterBc3::FarField, Frame3::default()).unwrap();
        s.set_velocity(u);
        s
    }

    /// A rigid rotation u = w × x on a stretched grid: ω = 2w and Q = |w|² in every cell
    /// (the field is linear, so the differences are exact up to round-off).
    #[test]
    fn rigid_rotation_has_twice_its_rate_as_vorticity_and_q_its_square() {
        let w = [0.3, -0.5, 0.7];
        let s = solver(|x| {
            [
                w[1] * x[2] - w[2] * x[1],
                w[2] * x[0] - w[0] * x[2],
                w[0] * x[1] - w[1] * x[0],
            ]
        });
        let f = s.snapshot();
        let w2: f64 = w.iter().map(|a| a * a).sum();
        for idx in 0..f.q.len() {
            for (wc, rate) in f.vorticity.iter().zip(w) {
                assert!((wc[idx] as f64 - 2.0 * rate).abs() < 1e-5);
            }
            assert!((f.q[idx] as f64 - w2).abs() < 1e-5, "{}", f.q[idx]);
        }
    }

    /// A pure strain u = (x, −y, 0): no vorticity and Q = −½ ‖S‖² = −1.
    #[test]
    fn pure_strain_has_no_vorticity_and_negative_q() {
        let s = solver(|x| [x[0], -x[1], 0.0]);
        let f = s.snapshot();
        for idx in 0..f.q.len() {
            for c in 0..3 {
                assert!(f.vorticity[c][idx].abs() < 1e-5);
            }
            assert!((f.q[idx] + 1.0).abs() < 1e-5);
        }
    }
}
