//! Ctrl-C (SIGINT; also SIGTERM and SIGHUP through the `ctrlc` crate's termination feature),
//! and SIGUSR1 (through `signal-hook`: Slurm's `--signal` warning before a time limit).
//!
//! - SIGUSR1 stops the run like the first Ctrl-C, without counting as one. With checkpoints on
//!   (`--checkpoint-every`, `--checkpoint`) every stop writes a checkpoint before the outputs
//!   are finalised (exit code 75).
//! - The first one asks the run to stop after the current step; every output is then finalised
//!   with what it has and says it was interrupted (exit code 130). After a completed run that
//!   keeps serving (--serve), it just stops the server (the exit code stays the run's).
//! - A second one quits at once with 130, whatever is going on (a finalisation that hangs on a
//!   dead disk, for instance): outputs not yet renamed into place stay under their temporary
//!   `.NAME.partial-PID` names, and no final name is touched.
use std::sync::atomic::{AtomicBool, AtomicU8, AtomicUsize, Ordering};
use std::sync::Arc;

use anyhow::Context as _;

/// What the process is doing, for the message the first Ctrl-C prints.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum Phase {
    /// Building the grid and solver, or stepping.
    Running = 0,
    /// Writing and renaming the outputs.
    Finalising = 1,
    /// The run is over and --serve keeps serving it.
    Serving = 2,
}

/// The shared state of the handler.
#[derive(Debug, Default)]
struct State {
    stop: Arc<AtomicBool>,
    presses: AtomicUsize,
    phase: AtomicU8,
}

/// The installed handler's state: the stop flag the run polls, and the phase.
#[derive(Clone, Debug)]
pub struct Interrupts(Arc<State>);

impl Interrupts {
    /// Installs the handler (once per process).
    pub fn install() -> anyhow::Result<Interrupts> {
        let state = Arc::new(State::default());
        state.phase.store(Phase::Running as u8, Ordering::SeqCst);
        let s = state.clone();
        ctrlc::set_handler(move || on_interrupt(&s)).context("installing the Ctrl-C handler")?;
        signal_hook::flag::register(signal_hook::consts::SIGUSR1, state.stop.clone())
            .context("installing the SIGUSR1 handler")?;
        Ok(Interrupts(state))
    }

    /// The flag the first Ctrl-C sets.
    pub fn stop(&self) -> &AtomicBool {
        &self.0.stop
    }

    /// Tells the handler what is going on now.
    pub fn set_phase(&self, phase: Phase) {
        self.0.phase.store(phase as u8, Ordering::SeqCst);
    }
}

fn on_interrupt(s: &State) {
    let earlier = s.presses.fetch_add(1, Ordering::SeqCst);
    s.stop.store(true, Ordering::SeqCst);
    if earlier > 0 {
        eprintln!(
            "\nplatefall: second Ctrl-C: quitting now; outputs not yet complete are left as \
             .NAME.partial-{} files",
            std::process::id()
        );
        std::process::exit(130);
    }
    let what = match s.phase.load(Ordering::SeqCst) {
        0 => "stopping after this step and finishing the outputs",
        1 => "finishing the outputs",
        _ => return,
    };
    eprintln!(
        "\nplatefall: interrupted: {what} (Ctrl-C again quits at once, leaving them partial)"
    );
}
