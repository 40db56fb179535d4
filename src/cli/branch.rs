//! An ensemble member's branch from a spun-up run's checkpoint: `platefall resume
//! --perturb-omega D --average-from-turn K`. The perturbation adds D (rad per c/U) to the
//! plate's angular velocity θ̇ in the restored state (the plate's own and its integrator's
//! snapshot) before the first step; the flow is left as it is. A checkpoint from before the
//! release is refused (the hold would undo the perturbation). The averaging start is written
//! into the member's command line, so that its own checkpoints resume with it. A branch writes
//! only the outputs it names, and must name its own checkpoint: the spun-up run's files stay
//! as they are for the next member.
use std::path::Path;

use super::command::parse;
use super::config::run_config;
use platefall_core::sim::SimState;
use platefall_record::checkpoint::ResumeInfo;

/// Why a checkpoint cannot be branched as asked.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum BranchRefusal {
    /// A perturbation that is not a finite number.
    #[error("--perturb-omega {0}: out of range: accepted a finite number (rad per c/U)")]
    NotFinite(f64),
    /// A prescribed motion has no θ̇ of its own to perturb.
    #[error("--perturb-omega: the checkpoint's plate moves as prescribed (a static or forced run): accepted only for pinned and free runs")]
    Prescribed,
    /// The plate is still held at its initial attitude: the prescribed hold would overwrite
    /// the perturbation at the next step.
    #[error("--perturb-omega: the checkpoint is before the plate's release (it is still held): accepted a checkpoint after the release")]
    NotReleased,
    /// The branch would write its checkpoints over the one it branches from (the next member
    /// would branch from this one's end).
    #[error("--perturb-omega: the branch would overwrite {}: give it its own --checkpoint FILE", .0.display())]
    SameCheckpoint(std::path::PathBuf),
    /// The run's case takes no averaging start.
    #[error("--average-from-turn: the checkpoint's case takes no --average-from-turn (accepted for pinned and free runs)")]
    NoTurns,
}

/// Adds `d` to θ̇ of the saved state (docs/physics.md §1: the coupled plate's pitch rate).
pub fn perturb_omega(sim: &mut SimState, d: f64) -> Result<(), BranchRefusal> {
    if !d.is_finite() {
        return Err(BranchRefusal::NotFinite(d));
    }
    let Some((body, released)) = sim.body.as_mut() else {
        return Err(BranchRefusal::Prescribed);
    };
    if !*released {
        return Err(BranchRefusal::NotReleased);
    }
    body.state.omega += d;
    sim.state.omega += d;
    Ok(())
}

/// Checks that a branch from `from` writes its checkpoints to another file, `to`.
pub fn own_checkpoint(from: &Path, to: &Path) -> Result<(), BranchRefusal> {
    let same = match (from.canonicalize(), to.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => from == to,
    };
    if same {
        return Err(BranchRefusal::SameCheckpoint(from.to_path_buf()));
    }
    Ok(())
}

/// The command line `argv` with the option `flag` (`--name`) set to `value` (replacing it
/// where it is given, as `--name V` or `--name=V`).
fn with_option(argv: &[String], flag: &str, value: &str) -> Vec<String> {
    let mut out = Vec::with_capacity(argv.len() + 1);
    let mut skip = false;
    let joined = format!("{flag}=");
    for a in argv {
        if std::mem::take(&mut skip) {
            continue;
        }
        if a == flag {
            skip = true;
        } else if !a.starts_with(&joined) {
            out.push(a.clone());
        }
    }
    out.push(format!("{flag}={value}"));
    out
}

/// Writes the averaging start `turn` into the resume information, with the run's end in force
/// (`info.t_end`, `info.turns`): its command line and the run description that command line
/// builds (an averaging start must lie before the last turn, so the end moves with it).
pub fn set_average_from_turn(info: &mut ResumeInfo, turn: usize) -> anyhow::Result<()> {
    let mut argv = with_option(&info.argv, "--t-end", &info.t_end.to_string());
    if let Some(n) = info.turns {
        argv = with_option(&argv, "--turns", &n.to_string());
    }
    let argv = with_option(&argv, "--average-from-turn", &turn.to_string());
    let cmd = parse(&argv).map_err(|_| BranchRefusal::NoTurns)?;
    let config = run_config(&cmd.command)?;
    info.config_json = serde_json::to_string_pretty(&config)?;
    info.argv = argv;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_averaging_start_replaces_the_one_given() {
        let argv: Vec<String> = ["platefall", "free", "--average-from-turn", "3", "--turns=9"]
            .map(String::from)
            .to_vec();
        assert_eq!(
            with_option(&argv, "--average-from-turn", "11"),
            ["platefall", "free", "--turns=9", "--average-from-turn=11"]
        );
        let argv: Vec<String> = ["platefall", "free", "--average-from-turn=3"]
            .map(String::from)
            .to_vec();
        assert_eq!(
            with_option(&argv, "--average-from-turn", "4"),
            ["platefall", "free", "--average-from-turn=4"]
        );
    }
}
