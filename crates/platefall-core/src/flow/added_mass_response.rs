//! The added-mass matrices K and S ([`AddedMass`], docs/physics.md §6) computed from the flow
//! solver's own discrete operator: one projection per unit change of the plate's motion.
use super::added_mass::AddedMass;
use super::array::Padded;
use super::frame::Frame;
use super::plate::BodyAxesLoads;
use super::FlowSolver;

/// The three unit motions (u0, v0, θ̇) whose responses are the columns of K.
const UNIT_MOTIONS: [Frame; 3] = [
    Frame {
        u0: 1.0,
        v0: 0.0,
        omega: 0.0,
    },
    Frame {
        u0: 0.0,
        v0: 1.0,
        omega: 0.0,
    },
    Frame {
        u0: 0.0,
        v0: 0.0,
        omega: 1.0,
    },
];

impl FlowSolver {
    /// K and S of the module docs, from three projections of the unit plate motions with the
    /// factored pressure matrix (set-up cost only; allocates its own scratch fields and leaves the
    /// flow untouched).
    pub fn added_mass(&mut self) -> AddedMass {
        let (mut k, mut shear) = ([[0.0; 3]; 3], [[0.0; 3]; 3]);
        let nu = self.params.nu();
        for (col, unit) in UNIT_MOTIONS.iter().enumerate() {
            let (pressure, all) = self.unit_response(unit, nu);
            let rows = [
                (pressure.fx, all.fx),
                (pressure.fy, all.fy),
                (pressure.moment, all.moment),
            ];
            for (row, (p, a)) in rows.into_iter().enumerate() {
                k[row][col] = p;
                shear[row][col] = a - p;
            }
        }
        AddedMass { k, shear }
    }

    /// The loads of one unit change of motion over a unit step, from fluid at rest: plate faces at
    /// g(unit), projected, p = φ. Returns (pressure alone, pressure and shear at viscosity `nu`).
    fn unit_response(&mut self, unit: &Frame, nu: f64) -> (BodyAxesLoads, BodyAxesLoads) {
        let (nx, ny) = (self.grid.nx, self.grid.ny);
        let mut u = Padded::zeros(nx + 1, ny);
        let mut v = Padded::zeros(nx, ny + 1);
        let mut p = vec![0.0; nx * ny];
        // The step's answer to a change of motion alone: the covered parts of the faces take the
        // new motion, while the no-slip values next to the wall follow the motion extrapolated
        // from before the step (here: rest).
        let rest = Frame::default();
        self.wall.impose(&mut u, &mut v, unit, &rest);
        let (g, m, wall) = (&self.grid, &self.metrics, &self.wall);
        self.pressure
            .project(&mut u, &mut v, g, m, (wall, unit), 1.0, &mut p);
        wall.hold(&mut u, &mut v, unit, &rest);
        (
            wall.loads(&u, &v, &p, unit, 0.0),
            wall.loads(&u, &v, &p, unit, nu),
        )
    }
}
