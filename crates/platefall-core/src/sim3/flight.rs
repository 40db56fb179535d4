//! A plate's six-degree-of-freedom flight through the three-dimensional flow, strongly coupled
//! (docs/three-d.md "Free flight"; docs/physics.md §6 and §9).
//!
//! One step tⁿ → tⁿ⁺¹ follows the two-dimensional coupled step (`sim/mod.rs`): the loads of the
//! flow at tⁿ, without their instantaneous added-mass part K (qⁿ − qⁿ⁻¹)/Δtⁿ⁻¹ (`rest`), drive
//! the body's equations with K on the left-hand side ([`StrongCoupling6`]); the body advances to
//! tⁿ⁺¹ by Adams–Bashforth ([`RigidBody6`]); the flow then advances to tⁿ⁺¹ with the plate moving
//! as the body's new state ([`frame_of`]). K comes once from the flow's own operator
//! ([`FlowSolver3::added_mass`]).
use nalgebra::{Rotation3, Vector3};

use crate::body::six::{Constraint6, Loads6, RigidBody6, SixError, State6, StrongCoupling6};
use crate::flow3d::{AddedMass3, Coefficients3, Flow3Error, FlowSolver3, Frame3, PhaseMarker};
use crate::sim::land;

/// Why a flight could not start or stopped.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Flight3Error {
    /// The flow failed (its own message).
    #[error(transparent)]
    Flow(#[from] Flow3Error),
    /// The body or the coupling is invalid (its own message).
    #[error(transparent)]
    Body(#[from] SixError),
    /// The body's motion is no longer finite.
    #[error("the plate's motion is not finite at t = {t:.4}")]
    MotionNotFinite {
        /// Time of the step that failed.
        t: f64,
    },
    /// A plate of periodic span flies planar only (it cannot roll or yaw).
    #[error("a plate of periodic span flies in the X–Y plane only: use the planar constraint")]
    PeriodicNotPlanar,
    /// The flow was not built at the body's motion (build it with `frame_of(body.state())`).
    #[error("the flow's frame is not the body's state: build the flow with frame_of(state)")]
    FrameMismatch,
}

/// The flow's frame for a body state: R = R(q), Ẋ₀, ω.
pub fn frame_of(s: &State6) -> Frame3 {
    Frame3::new(Rotation3::from(s.orientation), s.velocity, s.omega)
}

/// One step's outputs.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Sample6 {
    /// Steps taken.
    pub step: u64,
    /// Time at the end of the step (c/U).
    pub t: f64,
    /// The step (c/U).
    pub dt: f64,
    /// The body at t.
    pub state: State6,
    /// Force and moment coefficients at t.
    pub coefficients: Coefficients3,
    /// Pressure-solver iterations of the step.
    pub iterations: usize,
    /// Largest cell divergence the step left (U/c).
    pub divergence: f64,
}

/// The coupled flow and body.
pub struct Flight3 {
    pub(super) flow: FlowSolver3,
    pub(super) body: RigidBody6,
    coupling: StrongCoupling6,
    added: AddedMass3,
    /// The flow's frame one level back, and the step that left it.
    pub(super) before: Frame3,
    pub(super) dt_prev: f64,
    /// While held: the release time and the constraint the body takes then.
    pub(super) release: Option<(f64, Constraint6)>,
}

impl Flight3 {
    /// Couples `flow` (built at `frame_of(body.state())`, at rest or not) with `body`: computes
    /// K from the flow's operator (six pressure solves) and the strong coupling with it.
    ///
    /// # Errors
    /// [`Flight3Error::FrameMismatch`] when the flow's frame is not the body's,
    /// [`Flight3Error::PeriodicNotPlanar`] for a periodic span with a constraint that rolls or
    /// yaws, the flow's errors from computing K and [`SixError::AddedMass`] when
    /// diag(m, m, m) ⊕ I − K is not positive definite.
    pub fn new(mut flow: FlowSolver3, body: RigidBody6) -> Result<Flight3, Flight3Error> {
        if *flow.frame() != frame_of(body.state()) {
            return Err(Flight3Error::FrameMismatch);
        }
        if flow.grid().periodic_z
            && matches!(
                body.constraint(),
                Constraint6::Free | Constraint6::PinnedPoint
            )
        {
            return Err(Flight3Error::PeriodicNotPlanar);
        }
        let added = flow.added_mass()?;
        let coupling = StrongCoupling6::new(body.plate(), added.k)?;
        flow.begin_step()?;
        Ok(Flight3 {
            before: *flow.frame(),
            flow,
            body,
            coupling,
            added,
            dt_prev: 0.0,
            release: None,
        })
    }

    /// Holds the body on a straight line at its velocity, without turning, until `t_release`
    /// (the flow develops around it, as in the 2-D free fall, docs/physics.md §1 D), then lets it
    /// go with its constraint.
    ///
    /// # Errors
    /// [`Flow3Error::BadParameter`] when `t_release` is not finite and ≥ 0.
    pub fn hold_until(mut self, t_release: f64) -> Result<Flight3, Flight3Error> {
        if !(t_release.is_finite() && t_release >= 0.0) {
            let e = Flow3Error::BadParameter {
                name: "release time",
                value: t_release,
            };
            return Err(e.into());
        }
        let constraint = self.body.constraint();
        self.body.set_constraint(Constraint6::Prescribed)?;
        self.release = Some((t_release, constraint));
        Ok(self)
    }

    /// One coupled step of Δt = min(the flow's stable step, `dt_max`).
    ///
    /// # Errors
    /// [`Flight3Error::MotionNotFinite`] when the body's new state is not finite, the body's
    /// errors at the release, and the flow's errors.
    pub fn step(&mut self, dt_max: f64) -> Result<Sample6, Flight3Error> {
        let t = self.flow.t();
        let mut dt = self.flow.stable_dt().min(dt_max);
        match self.release {
            Some((t_release, constraint)) if t >= t_release - 1e-9 => {
                self.body.set_constraint(constraint)?;
                self.release = None;
            }
            Some((t_release, _)) => dt = land(t, dt, t_release),
            None => {}
        }
        if !(dt > 0.0 && dt.is_finite()) {
            return Err(Flow3Error::BadStep { dt }.into());
        }
        if self.release.is_some() {
            let s = *self.body.state();
            self.body.impose(State6 {
                position: s.position + s.velocity * dt,
                ..s
            })?;
        } else {
            self.fly(t, dt);
        }
        if self.body.state().validate().is_err() {
            return Err(Flight3Error::MotionNotFinite { t: t + dt });
        }
        self.before = *self.flow.frame();
        self.dt_prev = dt;
        self.flow.advance(dt, frame_of(self.body.state()))?;
        let stats = self.flow.solve_stats();
        Ok(Sample6 {
            step: self.flow.steps(),
            t: self.flow.t(),
            dt,
            state: *self.body.state(),
            coefficients: self.flow.coefficients(),
            iterations: stats.iterations,
            divergence: stats.divergence,
        })
    }

    /// Installs the flow's phase marker (`FlowSolver3::set_phase_marker`).
    pub fn set_phase_marker(&mut self, marker: PhaseMarker) {
        self.flow.set_phase_marker(marker);
    }

    /// The body's step t → t + dt under the flow's loads at t, strongly coupled.
    fn fly(&mut self, t: f64, dt: f64) {
        let loads = self.flow.loads();
        let inst = self
            .added
            .instantaneous(self.flow.frame(), &self.before, self.dt_prev);
        let rest = Loads6 {
            force: Vector3::from_fn(|i, _| loads.force[i] - inst[i]),
            moment: Vector3::from_fn(|i, _| loads.moment[i] - inst[i + 3]),
        };
        let plate = *self.body.plate();
        let accel =
            self.coupling
                .acceleration(&plate, self.body.constraint(), self.body.state(), &rest);
        self.body.step_with(t, accel, dt);
    }

    /// The flow.
    pub fn flow(&self) -> &FlowSolver3 {
        &self.flow
    }

    /// The body.
    pub fn body(&self) -> &RigidBody6 {
        &self.body
    }

    /// The flow's added-mass matrix K.
    pub fn added_mass(&self) -> &AddedMass3 {
        &self.added
    }
}
