//! What a VTK snapshot holds, sampled from a [`FieldSnapshot`] on the solver's own grid: the
//! grid's nodes placed at the plate's pose in the inertial frame, and at the nodes the inertial
//! velocity (a vector in the inertial axes), the vorticity and the stream function (the
//! recording's own: `platefall_post::fields`); at the cells the pressure.
use platefall_core::grid::GridGeometry;
use platefall_core::shape::{LineDir, Outline};
use platefall_core::sim::FieldSnapshot;
use platefall_post::fields::{cell_centres, stream_function_at_nodes, SnapshotFields};

/// The plate's pose: the centre (X, Y) and the pitch θ; body axes turned by θ from the inertial.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    /// X of the centre.
    pub x: f64,
    /// Y of the centre.
    pub y: f64,
    /// Pitch angle θ (radians).
    pub theta: f64,
}

impl Pose {
    /// The pose of a snapshot.
    pub fn of(snap: &FieldSnapshot) -> Pose {
        Pose {
            x: snap.x,
            y: snap.y,
            theta: snap.theta,
        }
    }

    /// The inertial position of body point (x, y).
    pub fn place(&self, x: f64, y: f64) -> [f64; 2] {
        let [a, b] = self.rotate(x, y);
        [self.x + a, self.y + b]
    }

    /// A vector with body components (a, b) in inertial components.
    pub fn rotate(&self, a: f64, b: f64) -> [f64; 2] {
        let (s, c) = self.theta.sin_cos();
        [c * a - s * b, s * a + c * b]
    }
}

/// Which grid nodes lie inside the section or on its boundary (1) and which in the fluid (0),
/// index `i + (nx + 1) j`. Computed once per run.
pub fn nodes_on_plate(grid: &GridGeometry, section: &Outline) -> Vec<u8> {
    let w = grid.xn.len();
    let mut mask = vec![0u8; w * grid.yn.len()];
    if !grid.solid.iter().any(|&s| s) {
        return mask;
    }
    for (j, &y) in grid.yn.iter().enumerate() {
        let covered = section.covered(LineDir::Horizontal, y);
        for (i, &x) in grid.xn.iter().enumerate() {
            mask[i + w * j] = u8::from(covered.holding(x, 0.0).is_some());
        }
    }
    mask
}

/// One snapshot's arrays, as the `.vts` file holds them (points and point arrays at the nodes,
/// index `i + (nx + 1) j`; cell arrays index `i + nx j`).
#[derive(Clone, Debug)]
pub struct FlowSample {
    /// The nodes in the inertial frame, (X, Y, 0) each.
    pub points: Vec<f64>,
    /// The inertial velocity at the nodes, (u_X, u_Y, 0) each: the plate's rigid velocity on
    /// the plate, elsewhere interpolated linearly from the two nearest faces along the grid line.
    pub velocity: Vec<f64>,
    /// Vorticity ω at the nodes.
    pub vorticity: Vec<f64>,
    /// The stream function ψ of the inertial velocity at the nodes (ψ = 0 at the first node).
    pub stream_function: Vec<f64>,
    /// Pressure at the cell centres.
    pub pressure: Vec<f64>,
}

impl FlowSample {
    /// The arrays of `snap` on `grid`; `on_plate` from [`nodes_on_plate`].
    pub fn new(grid: &GridGeometry, on_plate: &[u8], snap: &FieldSnapshot) -> FlowSample {
        let pose = Pose::of(snap);
        let fields = SnapshotFields::new(grid, snap);
        let stream_function = stream_function_at_nodes(grid, &fields.u, &fields.v);
        let mut points = Vec::with_capacity(3 * on_plate.len());
        for &y in &grid.yn {
            for &x in &grid.xn {
                let [px, py] = pose.place(x, y);
                points.extend_from_slice(&[px, py, 0.0]);
            }
        }
        FlowSample {
            points,
            velocity: node_velocity(grid, on_plate, snap, &fields),
            vorticity: fields.vorticity,
            stream_function,
            pressure: snap.p.clone(),
        }
    }
}

/// The inertial velocity at every node (see [`FlowSample::velocity`]).
fn node_velocity(
    grid: &GridGeometry,
    on_plate: &[u8],
    snap: &FieldSnapshot,
    fields: &SnapshotFields,
) -> Vec<f64> {
    let (nx, ny) = (grid.nx(), grid.ny());
    let (xc, yc) = (cell_centres(&grid.xn), cell_centres(&grid.yn));
    let pose = Pose::of(snap);
    let mut out = Vec::with_capacity(3 * on_plate.len());
    for j in 0..=ny {
        for i in 0..=nx {
            let (x, y) = (grid.xn[i], grid.yn[j]);
            let (a, b) = if on_plate[i + (nx + 1) * j] == 1 {
                (snap.frame.gx(y), snap.frame.gy(x))
            } else {
                let u = between(&yc, j, y, |jj| fields.u[i + (nx + 1) * jj]);
                let v = between(&xc, i, x, |ii| fields.v[ii + nx * j]);
                (u, v)
            };
            let [vx, vy] = pose.rotate(a, b);
            out.extend_from_slice(&[vx, vy, 0.0]);
        }
    }
    out
}

/// The value at `s` interpolated linearly between the centres `k − 1` and `k` of `centres`
/// (node `k` lies between them), the nearest centre's value at either end of the line.
fn between(centres: &[f64], k: usize, s: f64, value: impl Fn(usize) -> f64) -> f64 {
    if k == 0 {
        return value(0);
    }
    if k >= centres.len() {
        return value(centres.len() - 1);
    }
    let (a, b) = (centres[k - 1], centres[k]);
    let w = (s - a) / (b - a);
    (1.0 - w) * value(k - 1) + w * value(k)
}

/// The section's outline placed at `pose`: (X, Y, 0) per vertex.
pub fn placed_outline(section: &Outline, pose: &Pose) -> Vec<f64> {
    section
        .points()
        .iter()
        .flat_map(|&[x, y]| {
            let [px, py] = pose.place(x, y);
            [px, py, 0.0]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nodes_on_a_rectangle_fitted_to_grid_lines_are_on_the_plate() {
        let grid = GridGeometry {
            xn: vec![-1.0, -0.5, 0.0, 0.5, 1.0],
            yn: vec![-1.0, -0.25, 0.25, 1.0],
            solid: vec![
                false, true, true, false, false, false, false, false, false, false, false, false,
            ],
        };
        let plate = Outline::new(vec![[-0.5, -0.25], [0.5, -0.25], [0.5, 0.25], [-0.5, 0.25]]);
        let on = nodes_on_plate(&grid, &plate);
        let expected: Vec<u8> = (0..4)
            .flat_map(|j| {
                (0..5).map(move |i| u8::from((1..=3).contains(&i) && (1..=2).contains(&j)))
            })
            .collect();
        assert_eq!(on, expected);
    }

    #[test]
    fn a_node_value_lies_on_the_line_between_its_two_centres() {
        let centres = [0.0, 1.0, 3.0];
        let value = |k: usize| [10.0, 20.0, 40.0][k];
        assert_eq!(between(&centres, 0, -0.5, value), 10.0);
        assert_eq!(between(&centres, 2, 2.0, value), 30.0);
        assert_eq!(between(&centres, 3, 3.5, value), 40.0);
        let pose = Pose {
            x: 1.0,
            y: 2.0,
            theta: std::f64::consts::FRAC_PI_2,
        };
        let [x, y] = pose.place(1.0, 0.0);
        assert!((x - 1.0).abs() < 1e-15 && (y - 3.0).abs() < 1e-15);
    }
}
