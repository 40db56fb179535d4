//! The flow's 6 × 6 added-mass matrix K from the three-dimensional discrete operator
//! (docs/physics.md §6 "Coupling" and §9; docs/three-d.md "Added mass").
//!
//! As in two dimensions (`flow/added_mass.rs`), one step's projection is linear in the change of
//! the plate's motion over the step. With q = (u₀, ω) the body-axes velocity of the centre and
//! the angular velocity, (u, v, w, ω_x, ω_y, ω_z), the plate's faces take g(qⁿ⁺¹) while uⁿ was
//! divergence-free with g(qⁿ), so the pressure is p = p_H + Σₖ (Δqₖ/Δt) pₖ with pₖ the pressure
//! of the unit motion k over a unit step from fluid at rest, and the pressure loads are
//! F = F_H + K Δq/Δt. Column k of K holds the force and moment (body axes, about the centre) of
//! pₖ: the negative of the discrete plate's added-mass tensor. The body never moves in its grid,
//! so K is computed once (six pressure solves) and stays valid for the whole run.
//!
//! A plate of periodic span cannot turn about x or y: g = ω × x would not be periodic in z. Its
//! K has those two rows and columns zero, and a periodic run keeps ω_x = ω_y = 0.
use super::frame::Frame3;
use super::grid::Grid3;
use super::layout::Layout;
use super::loads::LoadInput;
use super::metrics::Metrics3;
use super::plate::Plate;
use super::project::{cell_fluxes, pressure_rhs, PoissonSolve, Stop};
use super::Flow3Error;

/// Largest divergence a unit motion's projection may leave (U/c). A unit motion makes a
/// divergence of order 1/h next to the plate; this leaves K's entries exact to about 1e-10 of
/// themselves while staying above the round-off floor of the conjugate gradients' residual (the
/// step's own 1e-11 would ask a relative residual near 1e-14 of these right-hand sides at N = 32).
const UNIT_DIVERGENCE: f64 = 1e-9;

/// K of the module docs: `k[row][col]`, rows (F_x, F_y, F_z, M_x, M_y, M_z) in body axes on ρU²c²
/// and ρU²c³, columns the unit changes of (u, v, w, ω_x, ω_y, ω_z) over a unit step.
#[derive(Clone, Copy, Debug, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct AddedMass3 {
    /// K: the pressure loads per unit change of motion over a unit step.
    pub k: [[f64; 6]; 6],
}

impl AddedMass3 {
    /// K·x.
    pub fn apply(&self, x: [f64; 6]) -> [f64; 6] {
        self.k
            .map(|row| row.iter().zip(&x).map(|(k, x)| k * x).sum::<f64>())
    }

    /// The part of the loads that is the flow's instantaneous answer to the last change of motion,
    /// K (qⁿ − qⁿ⁻¹)/Δt (force and moment in body axes); zero before the first step (`dt` = 0).
    pub fn instantaneous(&self, now: &Frame3, before: &Frame3, dt: f64) -> [f64; 6] {
        if dt <= 0.0 {
            return [0.0; 6];
        }
        let (q1, q0) = (motion(now), motion(before));
        self.apply(std::array::from_fn(|i| (q1[i] - q0[i]) / dt))
    }
}

/// q = (Rᵀ Ẋ₀, ω) of a frame.
fn motion(f: &Frame3) -> [f64; 6] {
    let (a, w) = (f.body_velocity(), f.omega_array());
    [a[0], a[1], a[2], w[0], w[1], w[2]]
}

/// What the unit responses read: the solver's geometry and its pressure solver.
pub(super) struct UnitResponses<'a> {
    /// The grid (the plate's faces).
    pub grid: &'a Grid3,
    /// Coordinates and widths.
    pub metrics: &'a Metrics3,
    /// Array sizes.
    pub layout: &'a Layout,
    /// The held points.
    pub plate: &'a Plate,
    /// The flow's own pressure solver (its scratch is reused; its operator is the step's).
    pub pressure: &'a mut dyn PoissonSolve,
    /// Most iterations of a solve.
    pub max_iterations: usize,
}

impl UnitResponses<'_> {
    /// K from six projections of the unit motions (allocates its own scratch fields; the flow's
    /// fields are not touched).
    pub fn added_mass(&mut self) -> Result<AddedMass3, Flow3Error> {
        let mut k = [[0.0; 6]; 6];
        let periodic = self.grid.periodic_z;
        for col in (0..6).filter(|&c| !(periodic && (c == 3 || c == 4))) {
            let mut q = [0.0; 6];
            q[col] = 1.0;
            let unit = Frame3::body([q[0], q[1], q[2]], [q[3], q[4], q[5]]);
            let loads = self.pressure_loads(&unit)?;
            for (row, value) in loads.into_iter().enumerate() {
                k[row][col] = if periodic && (row == 3 || row == 4) {
                    0.0
                } else {
                    value
                };
            }
        }
        Ok(AddedMass3 { k })
    }

    /// The pressure loads (force, moment) of the plate set to g(unit) in fluid at rest,
    /// projected over a unit step.
    fn pressure_loads(&mut self, unit: &Frame3) -> Result<[f64; 6], Flow3Error> {
        let lay = self.layout;
        let mut vel: [Vec<f64>; 3] = std::array::from_fn(|_| lay.zeros());
        self.plate.hold(&mut vel, self.metrics, lay, unit);
        let op = self.pressure.operator();
        let cells = op.cells();
        let (mut rhs, mut weight, mut p) = (vec![0.0; cells], vec![0.0; cells], vec![0.0; cells]);
        let view = [&vel[0][..], &vel[1][..], &vel[2][..]];
        cell_fluxes(view, self.metrics, lay, op, &mut rhs);
        self.plate.cut_flux(view, unit, &op.diag, &mut rhs);
        pressure_rhs(op, 1.0, &mut rhs, &mut weight);
        let stop = Stop {
            weight: &weight,
            tol: UNIT_DIVERGENCE,
            max_iterations: self.max_iterations,
        };
        let stats = self.pressure.solve(&rhs, &mut p, stop);
        if !stats.converged {
            return Err(Flow3Error::PressureNotConverged {
                iterations: stats.iterations,
                divergence: stats.divergence,
                tolerance: UNIT_DIVERGENCE,
            });
        }
        let loads = self.plate.loads(&LoadInput {
            grid: self.grid,
            m: self.metrics,
            layout: lay,
            vel: view,
            p: &p,
            frame: unit,
            nu: 0.0,
        });
        let (f, m) = (loads.force_pressure, loads.moment);
        Ok([f[0], f[1], f[2], m[0], m[1], m[2]])
    }
}
