//! The implicit far field's variants of the step's phases (docs/physics.md §3; the scheme is
//! described in `implicit/mod.rs`): the predictor (the right-hand side, the boundary values at
//! n+1, the row and column sweeps) and the projection with the incremental pressure.
use super::boundary::{OuterBc, Outflow};
use super::frame::Frame;
use super::implicit::{self, GhostEnds, Inputs, Part, State, Weights};
use super::metrics::Component;
use super::pressure::PressureUpdate;
use super::FlowSolver;

impl FlowSolver {
    /// The predictor of the implicit far field (see `implicit/mod.rs`): the right-hand side, the
    /// boundary values at n+1, the row and column sweeps and u* = uⁿ + Δ, from the frames at n
    /// (`frame_prev`) and n+1 (`frame`).
    pub(super) fn predict_implicit(&mut self, dt: f64) {
        let Some(mut state) = self.implicit.take() else {
            return;
        };
        if self.steps == 0 {
            self.start_pressure(&mut state);
        }
        let w = Weights::new(dt, if self.steps == 0 { 0.0 } else { self.dt_prev });
        state.g2 = w.g2;
        let (f0, next) = (self.frame_prev, self.frame);
        let (pu, pv) = (&mut state.u, &mut state.v);
        let (xu, xv) = (
            self.inputs(Component::U, &f0, &next),
            self.inputs(Component::V, &f0, &next),
        );
        rayon::join(|| pu.assemble(&xu, &w, dt), || pv.assemble(&xv, &w, dt));
        std::mem::swap(&mut self.hu, &mut self.hu_old);
        std::mem::swap(&mut self.hv, &mut self.hv_old);
        self.implicit_boundary(pu, pv, dt);
        let (m, z, a) = (&self.metrics, &self.zones, w.g2 * dt);
        let rule = GhostEnds::of(&self.outer);
        let (u, v) = (&mut self.u, &mut self.v);
        rayon::join(
            || {
                pu.intermediate_ends(m, z, &next, a, rule);
                pu.sweep_rows(m, z, &next, a, rule);
                pu.sweep_columns(m, z, &next, a, rule);
                pu.apply(u);
            },
            || {
                pv.intermediate_ends(m, z, &next, a, rule);
                pv.sweep_rows(m, z, &next, a, rule);
                pv.sweep_columns(m, z, &next, a, rule);
                pv.apply(v);
            },
        );
        self.implicit = Some(state);
    }

    /// The projection of the implicit far field: the velocity as usual, and the incremental
    /// pressure p += A φ/Δt with A = (I + a L_x)(I + a L_y) the factored operator of the
    /// predictor applied to φ (`implicit::factored_potential`). Adding φ/Δt alone would feed the
    /// factorisation error back into the next predictor through the pressure, which diverges
    /// where both directions are implicit at Courant numbers ≳ 1; with A it cancels.
    pub(super) fn project_incremental(&mut self, dt: f64) {
        self.pressure.project_velocity(
            &mut self.u,
            &mut self.v,
            &self.grid,
            &self.metrics,
            (&self.wall, &self.frame),
        );
        if let Some(state) = &mut self.implicit {
            let t = state.g2 * dt;
            implicit::factored_potential(
                &mut self.pressure.phi,
                &mut state.cells,
                (&state.u, &state.v),
                &self.grid,
                &self.metrics,
                &self.zones,
                &self.frame,
                t,
            );
        }
        self.pressure
            .set_pressure(dt, &mut self.p, PressureUpdate::Increment);
    }

    /// What a component's right-hand side reads (the frames at n and n+1).
    fn inputs<'a>(&'a self, c: Component, f0: &'a Frame, f1: &'a Frame) -> Inputs<'a> {
        let (q, h, h_old) = match c {
            Component::U => (&self.u, &self.hu, &self.hu_old),
            Component::V => (&self.v, &self.hv, &self.hv_old),
        };
        Inputs {
            q,
            h,
            h_old,
            p: &self.p,
            grid: &self.grid,
            m: &self.metrics,
            zones: &self.zones,
            f0,
            f1,
        }
    }

    /// The outer normal velocities at n+1 (implicit outflow, from the interior at n), kept as the
    /// known ends of the sweeps; for a prescribed boundary also the tangential ghosts at n+1.
    fn implicit_boundary(&mut self, pu: &mut Part, pv: &mut Part, dt: f64) {
        let t_next = self.t + dt;
        pu.save_boundary(&self.u);
        pv.save_boundary(&self.v);
        self.set_outer_normals(t_next, dt, Outflow::Implicit);
        pu.finish_boundary(&self.u);
        pv.finish_boundary(&self.v);
        if let OuterBc::Prescribed(f) = &self.outer {
            pu.prescribed_ghosts(&self.u, &self.metrics, f, t_next);
            pv.prescribed_ghosts(&self.v, &self.metrics, f, t_next);
        }
    }

    /// The incremental pressure's start: p⁰ is the potential of the gradient part of the full
    /// right-hand side at t = 0 (so a steady flow, e.g. rigid rotation, starts in balance), with
    /// the motion at t = 0 (`frame_prev` once the step has begun).
    fn start_pressure(&mut self, state: &mut State) {
        let f0 = self.frame_prev;
        let (xu, xv) = (
            self.inputs(Component::U, &f0, &f0),
            self.inputs(Component::V, &f0, &f0),
        );
        state.u.total_rhs(&xu);
        state.v.total_rhs(&xv);
        let zero = Frame::default();
        self.wall.hold(&mut state.u.d, &mut state.v.d, &zero, &zero);
        self.pressure
            .potential(&state.u.d, &state.v.d, &self.grid, &self.wall, &mut self.p);
    }
}
