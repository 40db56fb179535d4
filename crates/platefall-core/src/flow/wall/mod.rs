//! The plate inside the body-fixed grid (docs/physics.md §3–§5): which unknowns are fluid, how the
//! projection sees the plate's boundary, the momentum equations next to it, and the loads on it.
//!
//! The body never moves relative to the grid, so all of this is computed once from the plate's
//! outline ([`crate::shape::Outline`]) and the grid, and a step only reads it:
//!
//! - [`faces`]: held faces (the plate's rigid velocity g), fluid faces with their apertures,
//!   cells that carry a pressure, and the flux corrections of cut faces;
//! - [`stencils`]: the wall flux and the forced points of the momentum equations;
//! - [`loads`]: the force and moment to second order;
//! - [`thinness`]: whether the grid can follow the plate at all ([`check_representable`]).
//!
//! A rectangle's faces lie on grid lines (the grid is fitted to it): no face is cut, every held
//! face is inside or on the plate, and δ = ½ on every wall line, so the scheme is the classical
//! staggered-grid wall. Every other shape cuts the grid's cells.
pub mod faces;
pub mod lines;
pub mod loads;
pub mod stencils;
pub mod thinness;

#[cfg(test)]
mod loads_convergence;

use faces::{Faces, ON_BOUNDARY};
use lines::Lines;
use loads::Loads;
use stencils::{near_wall_velocity, wall_velocity, Stencils};

pub use thinness::check_representable;

use super::array::Padded;
use super::frame::Frame;
use super::metrics::{Component, Metrics};
use super::plate::BodyAxesLoads;
use crate::grid::Grid;

/// Everything the solver knows of the plate.
#[derive(Clone, Debug)]
pub struct Wall {
    pub faces: Faces,
    pub stencils: Stencils,
    pub loads: Loads,
    nx: usize,
}

impl Wall {
    /// The plate of `grid` (none: every face fluid).
    pub fn new(grid: &Grid, m: &Metrics, nu: f64) -> Wall {
        let Some(body) = &grid.body else {
            return Wall {
                faces: Faces::all_fluid(grid),
                stencils: Stencils::default(),
                loads: Loads::default(),
                nx: grid.nx,
            };
        };
        let tol = ON_BOUNDARY * grid.h;
        let lines = Lines::new(grid, body);
        let faces = Faces::new(grid, body, &lines, tol);
        let stencils = Stencils::new(grid, body, m, &lines, (&faces.u_open, &faces.v_open), nu);
        let loads = Loads::new(grid, body, &lines, (&faces, &stencils.forced), tol);
        Wall {
            faces,
            stencils,
            loads,
            nx: grid.nx,
        }
    }

    /// No-slip at the new time level: held faces carry the plate's motion `now` over their
    /// covered parts; the values next to the wall (held faces' open parts, forced points) take
    /// the wall's velocity with its normal part from `now` and its tangential part from `guess`,
    /// the motion extrapolated from the steps before ([`near_wall_velocity`]).
    ///
    /// A change of motion within the step then moves the wall's normal velocity at once, as in
    /// potential flow, while the no-slip of the tangential velocity (a layer one spacing thick,
    /// whose projection would add O(h) to the added mass) follows at the next step, a time error
    /// of order Δt². A rectangle on a fitted grid has no such values.
    pub fn impose(&self, u: &mut Padded, v: &mut Padded, now: &Frame, guess: &Frame) {
        self.hold(u, v, now, guess);
        self.stencils.force(u, v, now, guess);
    }

    /// Held faces take the plate's velocity (see [`Wall::impose`]).
    pub fn hold(&self, u: &mut Padded, v: &mut Padded, now: &Frame, guess: &Frame) {
        for f in &self.faces.held {
            let q = match f.c {
                Component::U => &mut *u,
                Component::V => &mut *v,
            };
            let covered = wall_velocity(f.c, now, f.covered_at);
            let value = if f.open > 0.0 {
                let wall = near_wall_velocity(f.c, now, guess, f.open_at, f.normal);
                f.open * wall + (1.0 - f.open) * covered
            } else {
                covered
            };
            q.set(f.i, f.j, value);
        }
    }

    /// Adds the near-wall viscous fluxes to the explicit right-hand sides.
    pub fn apply(&self, u: &Padded, v: &Padded, frame: &Frame, hu: &mut Padded, hv: &mut Padded) {
        self.stencils.apply(u, v, frame, hu, hv);
    }

    /// Loads of the fluid on the plate (shear at kinematic viscosity `nu`; 0 for pressure alone).
    pub fn loads(
        &self,
        u: &Padded,
        v: &Padded,
        p: &[f64],
        frame: &Frame,
        nu: f64,
    ) -> BodyAxesLoads {
        self.loads.evaluate(u, v, p, self.nx, frame, nu)
    }

    /// Adds to each cell's outflow the part of its cut faces that lies inside the plate,
    /// L (1 − A)(ĝ − u_f), so that `flux` holds the fluid's true outflow.
    pub fn cut_flux(
        &self,
        u: &Padded,
        v: &Padded,
        frame: &Frame,
        flux: &mut impl FnMut(usize, f64),
    ) {
        for f in &self.faces.cut {
            let q = match f.c {
                Component::U => u,
                Component::V => v,
            };
            let add =
                f.covered_length * (wall_velocity(f.c, frame, f.covered_at) - q.get(f.i, f.j));
            if let Some(k) = f.cell_low {
                flux(k, add);
            }
            if let Some(k) = f.cell_high {
                flux(k, -add);
            }
        }
    }
}
