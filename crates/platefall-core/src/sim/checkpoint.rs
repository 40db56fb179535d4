//! A run's state between two steps as plain data ([`SimState`]): the flow's fields and their
//! time-level histories, the plate's state and Adams–Bashforth history, the release and
//! turn-counting state, and the run's [`History`] (which holds the summary's accumulators). The
//! time-step controller needs nothing else: it reads the flow's last step and the plate's rate.
//!
//! [`Simulation::save`] takes the snapshot and [`Simulation::restore`] builds a simulation from
//! a validated configuration and puts it back, so the next step is the one the saved run would
//! have taken, bit for bit. Writing it to a file is the caller's (the record crate's
//! `checkpoint` module): the core does no I/O.
use super::saved::{RestoreError, SimState};
use super::{History, Motion, Simulation, ValidatedConfig};

impl Simulation {
    /// The run's state between two steps, with the steps' `history` (what
    /// [`Simulation::run_from`] has accumulated).
    pub fn save(&self, history: &History) -> SimState {
        let body = match &self.motion {
            Motion::Prescribed => None,
            Motion::Coupled { body, released, .. } => Some((body.save(), *released)),
        };
        SimState {
            flow: self.flow.save_state(),
            state: self.state,
            body,
            theta_release: self.theta_release,
            history: history.clone(),
        }
    }

    /// A run of `config` put back into `saved`; returns it and the steps' history to go on
    /// with ([`Simulation::run_from`]). `config` may differ from the saved run's only in its end
    /// (t_end, turns); the caller checks that.
    ///
    /// # Errors
    /// [`RestoreError::Build`] when the run cannot be built, [`RestoreError::Flow`] or
    /// [`RestoreError::Body`] when the saved flow or plate does not fit it, and
    /// [`RestoreError::Motion`] when one has a free body and the other a prescribed motion.
    pub fn restore(
        config: ValidatedConfig,
        saved: SimState,
    ) -> Result<(Simulation, History), RestoreError> {
        let mut sim = Simulation::new(config)?;
        sim.flow.restore_state(&saved.flow)?;
        match (&mut sim.motion, &saved.body) {
            (Motion::Prescribed, None) => {}
            (Motion::Coupled { body, released, .. }, Some((snap, was))) => {
                body.restore(snap)?;
                *released = *was;
            }
            _ => return Err(RestoreError::Motion),
        }
        sim.state = saved.state;
        sim.theta_release = saved.theta_release;
        Ok((sim, saved.history))
    }
}
