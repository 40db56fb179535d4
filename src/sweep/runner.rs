//! The local pool: up to `jobs` cases at once as child processes of this executable. Ctrl-C stops
//! launching, forwards SIGINT to the running cases and waits for them to finalise their outputs
//! (a second Ctrl-C kills them).
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::Duration;

use super::child::{finish, interrupt, launch, launch_failed, Running};
use super::failure::Failure;
use super::layout::Layout;
use super::plan::{CaseSpec, Outputs};
use super::progress::Progress;
use super::results::outcome;
use platefall_post::phase::CaseState;

/// How often running cases are polled.
const POLL: Duration = Duration::from_millis(50);

/// Installs the Ctrl-C (and SIGTERM, and SIGUSR1: Slurm's warning before a time limit)
/// handler: the count of presses.
pub(crate) fn interrupt_counter() -> Result<Arc<AtomicUsize>, Failure> {
    let presses = Arc::new(AtomicUsize::new(0));
    let p = presses.clone();
    ctrlc::set_handler(move || {
        p.fetch_add(1, Ordering::SeqCst);
    })
    .map_err(|e| Failure::output(format!("cannot install the Ctrl-C handler: {e}")))?;
    let p = presses.clone();
    // SAFETY: the handler only increments an atomic, which is async-signal-safe.
    unsafe {
        signal_hook::low_level::register(signal_hook::consts::SIGUSR1, move || {
            p.fetch_add(1, Ordering::SeqCst);
        })
    }
    .map_err(|e| Failure::output(format!("cannot install the SIGUSR1 handler: {e}")))?;
    Ok(presses)
}

/// Runs `todo` with at most `jobs` at once. Returns true if it was interrupted.
pub(crate) fn run_pool(
    exe: &Path,
    layout: &Layout,
    todo: &[CaseSpec],
    outputs: Outputs,
    jobs: usize,
    progress: &mut Progress,
    presses: &AtomicUsize,
) -> bool {
    let mut queue = todo.iter();
    let mut running: Vec<Running> = Vec::new();
    let mut forwarded = 0;
    loop {
        let stop = presses.load(Ordering::SeqCst);
        while stop == 0 && running.len() < jobs.max(1) {
            let Some(case) = queue.next() else { break };
            match launch(exe, layout, case, outputs) {
                Ok(r) => {
                    progress.started();
                    running.push(r);
                }
                Err(e) => {
                    let status = launch_failed(layout, case, &e);
                    progress.started();
                    progress.finished(&case.id, CaseState::Failed, &status);
                }
            }
        }
        if running.is_empty() {
            return stop > 0;
        }
        if stop > forwarded {
            forward(&mut running, stop, progress);
            forwarded = stop;
        }
        reap(layout, &mut running, progress);
        std::thread::sleep(POLL);
    }
}

/// First Ctrl-C: SIGINT to every running case; later ones: SIGKILL.
fn forward(running: &mut [Running], presses: usize, progress: &Progress) {
    let hard = presses > 1;
    progress.note(&if hard {
        format!("interrupted again: killing {} running case(s)", running.len())
    } else {
        format!(
            "interrupted: no new cases; waiting for {} running case(s) to finalise (Ctrl-C again to kill them)",
            running.len()
        )
    });
    for r in running.iter_mut() {
        interrupt(r, hard);
    }
}

/// Collects the cases that have exited.
fn reap(layout: &Layout, running: &mut Vec<Running>, progress: &mut Progress) {
    let mut i = 0;
    while i < running.len() {
        match running[i].child.try_wait() {
            Ok(Some(exit)) => {
                let r = running.swap_remove(i);
                let id = r.case.id.clone();
                let status = finish(layout, r, exit);
                progress.finished(&id, outcome(layout, &id, Some(&status)), &status);
            }
            Ok(None) => i += 1,
            Err(e) => {
                let r = running.swap_remove(i);
                progress.note(&format!("{}: lost track of the process: {e}", r.case.id));
            }
        }
    }
}
