//! The 6-DOF rigid body and its integrator (docs/physics.md §6, §9): position, velocity and
//! angular velocity by the variable-step Adams–Bashforth method of [`AdamsBashforth`], the
//! orientation by the same weights in a chart on the rotations ([`super::chart`]), and the
//! checkpoint of both histories.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use super::chart::SpinHistory;
use super::state::UNIT_TOL;
use super::{explicit_acceleration, Accel6, Constraint6, Loads6, Plate6, SixError, State6};
use crate::body::{AbHistory, AbStart, AdamsBashforth};

/// Components of the vector the Adams–Bashforth integrator advances: (X₀, Ẋ₀, ω), derivative
/// (Ẋ₀, Ẍ₀, ω̇).
const EUCLIDEAN: usize = 9;

/// The plate as a 6-DOF rigid body: properties, constraint, state and its integrator.
#[derive(Debug, Clone)]
pub struct RigidBody6 {
    plate: Plate6,
    state: State6,
    constraint: Constraint6,
    ab: AdamsBashforth<EUCLIDEAN>,
    spins: SpinHistory,
}

impl RigidBody6 {
    /// A body with the given properties, constraint, initial state and Adams–Bashforth order
    /// (1..=6) and start (docs/physics.md §6).
    ///
    /// # Errors
    /// The errors of [`State6::validate`] and [`Constraint6::check`] for `state`, and
    /// [`SixError::History`] ([`AbError::Order`](crate::body::AbError::Order)) when `order` is outside 1..=6.
    pub fn new(
        plate: Plate6,
        constraint: Constraint6,
        state: State6,
        order: usize,
        start: AbStart,
    ) -> Result<Self, SixError> {
        state.validate()?;
        constraint.check(&state)?;
        Ok(Self {
            plate,
            state,
            constraint,
            ab: AdamsBashforth::new(order, start)?,
            spins: SpinHistory::default(),
        })
    }

    /// The properties.
    pub fn plate(&self) -> &Plate6 {
        &self.plate
    }

    /// The current state.
    pub fn state(&self) -> &State6 {
        &self.state
    }

    /// The current constraint.
    pub fn constraint(&self) -> Constraint6 {
        self.constraint
    }

    /// The Euclidean part's integrator (to inspect its history).
    pub fn integrator(&self) -> &AdamsBashforth<EUCLIDEAN> {
        &self.ab
    }

    /// Change the constraint (release) and forget the history, which belonged to the previous
    /// equations of motion.
    ///
    /// # Errors
    /// [`SixError::PinnedSpin`] when the current state does not satisfy `constraint`; nothing is
    /// changed then.
    pub fn set_constraint(&mut self, constraint: Constraint6) -> Result<(), SixError> {
        constraint.check(&self.state)?;
        self.constraint = constraint;
        self.ab.reset();
        self.spins.clear();
        Ok(())
    }

    /// Set the state (a prescribed motion's, or a new start); the history is kept, so for a
    /// free body this is the caller's restart.
    ///
    /// # Errors
    /// The errors of [`State6::validate`] and [`Constraint6::check`] for `state`; nothing is
    /// changed then.
    pub fn impose(&mut self, state: State6) -> Result<(), SixError> {
        state.validate()?;
        self.constraint.check(&state)?;
        self.state = state;
        Ok(())
    }

    /// The accelerations under `loads` taken as given ([`explicit_acceleration`]).
    pub fn acceleration(&self, loads: &Loads6) -> Accel6 {
        explicit_acceleration(&self.plate, self.constraint, &self.state, loads)
    }

    /// Advance t → t + h under the current loads (explicit coupling).
    pub fn step(&mut self, t: f64, loads: &Loads6, h: f64) {
        let accel = self.acceleration(loads);
        self.step_with(t, accel, h);
    }

    /// Advance t → t + h with accelerations the caller computed (strong coupling:
    /// [`StrongCoupling6::acceleration`](super::StrongCoupling6::acceleration)). Nothing happens
    /// for [`Constraint6::Prescribed`].
    ///
    /// # Panics
    /// As [`AdamsBashforth::step`]: if h is not finite and positive or t not after the last step.
    pub fn step_with(&mut self, t: f64, accel: Accel6, h: f64) {
        if self.constraint == Constraint6::Prescribed {
            return;
        }
        let s = &self.state;
        let mut y = [0.0; EUCLIDEAN];
        let mut f = [0.0; EUCLIDEAN];
        for i in 0..3 {
            y[i] = s.position[i];
            y[i + 3] = s.velocity[i];
            y[i + 6] = s.omega[i];
            f[i] = s.velocity[i];
            f[i + 3] = accel.linear[i];
            f[i + 6] = accel.angular[i];
        }
        self.spins.push(s.orientation, s.omega);
        self.ab.step(t, &mut y, f, h);
        self.spins.fill_back(&self.ab);
        let turn = self.spins.increment(&self.ab, h);
        let mut q = self.state.orientation;
        if turn != Vector3::zeros() {
            // Unit up to round-off (module docs of `chart`): the renormalisation removes it.
            q *= UnitQuaternion::from_scaled_axis(turn);
            q.renormalize();
        }
        self.state = State6 {
            position: Vector3::new(y[0], y[1], y[2]),
            velocity: Vector3::new(y[3], y[4], y[5]),
            orientation: q,
            omega: Vector3::new(y[6], y[7], y[8]),
        };
    }

    /// The body's changing part, for a checkpoint: state, constraint and both histories.
    pub fn save(&self) -> Snapshot6 {
        Snapshot6 {
            state: self.state,
            constraint: self.constraint,
            history: self.ab.save_history(),
            spins: self
                .spins
                .entries()
                .iter()
                .map(|(q, w)| SpinEntry {
                    orientation: q.into_inner().coords.into(),
                    omega: (*w).into(),
                })
                .collect(),
        }
    }

    /// Puts back what [`save`](Self::save) returned, bit for bit (the properties, the order and
    /// the start mode stay this body's own); a snapshot that does not fit is refused and the body
    /// left as it was.
    ///
    /// # Errors
    /// The errors of [`State6::validate`] and [`Constraint6::check`] for the saved state,
    /// [`SixError::SpinHistory`] or [`SixError::Orientation`] for an orientation history that does not
    /// fit, and [`SixError::History`] for a derivative history that does not.
    pub fn restore(&mut self, snap: &Snapshot6) -> Result<(), SixError> {
        snap.state.validate()?;
        snap.constraint.check(&snap.state)?;
        if snap.spins.len() != snap.history.len {
            return Err(SixError::SpinHistory);
        }
        let spins = snap
            .spins
            .iter()
            .map(|e| e.to_pair())
            .collect::<Result<Vec<_>, _>>()?;
        let mut ab = self.ab.clone();
        ab.restore_history(&snap.history)?;
        self.ab = ab;
        self.spins.set(spins);
        self.state = snap.state;
        self.constraint = snap.constraint;
        Ok(())
    }
}

/// A [`RigidBody6`]'s changing part as plain data (a checkpoint's).
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Snapshot6 {
    /// The state.
    pub state: State6,
    /// The constraint.
    pub constraint: Constraint6,
    /// The stored derivatives of (X₀, Ẋ₀, ω).
    pub history: AbHistory,
    /// The stored orientations and angular velocities, newest first, one per stored derivative.
    pub spins: Vec<SpinEntry>,
}

/// One stored orientation and angular velocity of a [`Snapshot6`].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SpinEntry {
    /// The quaternion's (i, j, k, w) components.
    pub orientation: [f64; 4],
    /// ω in body axes.
    pub omega: [f64; 3],
}

impl SpinEntry {
    /// The entry as the integrator keeps it, if finite and of unit norm.
    fn to_pair(self) -> Result<(UnitQuaternion<f64>, Vector3<f64>), SixError> {
        let q = Quaternion::from(nalgebra::Vector4::from(self.orientation));
        let w = Vector3::from(self.omega);
        if !(q.coords.iter().chain(w.iter()).all(|x| x.is_finite())) {
            return Err(SixError::SpinHistory);
        }
        if (q.norm() - 1.0).abs() > UNIT_TOL {
            return Err(SixError::Orientation(q.norm()));
        }
        Ok((UnitQuaternion::new_unchecked(q), w))
    }
}
