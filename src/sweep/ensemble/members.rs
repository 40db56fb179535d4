//! An ensemble's members: the request checked against its checkpoint (every refusal one line,
//! before anything runs) and each member's command line, a `platefall resume` of the spun-up
//! checkpoint with its own perturbation of θ̇.
//!
//! Member k's perturbation is ε z_k (to six significant digits), where z_0, z_1, … are the
//! standard normal numbers of the seeded generator [`platefall_post::rng::Rng`] started at the
//! seed: the same seed gives the same members, and a larger ensemble of the same seed holds the
//! smaller one.
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::super::failure::Failure;
use super::super::plan::CaseSpec;
use super::super::values::Value;
use platefall_core::config::{EndTime, Units};
use platefall_core::sim::RunConfig;
use platefall_post::rng::Rng;
use platefall_record::checkpoint::{read_checkpoint, Checkpoint};

/// Largest |ε| accepted: a perturbation of θ̇ meant to be tiny against the plate's rates (of
/// order 1 rad per c/U).
pub(crate) const MAX_PERTURBATION: f64 = 1e-2;

/// What the command line asks of an ensemble (the run options).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct EnsembleSpec {
    /// The spun-up run's checkpoint.
    pub(crate) from: PathBuf,
    /// Members M.
    pub(crate) members: usize,
    /// Size ε of the perturbation of θ̇ (rad per c/U).
    pub(crate) perturbation: f64,
    /// Seed of the perturbations.
    pub(crate) seed: u64,
    /// Each member's end: net turns after release, and/or a time.
    pub(crate) turns: Option<f64>,
    /// See `turns`.
    pub(crate) t_end: Option<EndTime>,
    /// Average from this complete turn after release (None: two whole turns after the branch).
    pub(crate) average_from_turn: Option<usize>,
    /// Members' checkpoint cadence (None: the spun-up run's).
    pub(crate) checkpoint_every: Option<f64>,
    /// Worker threads of each member.
    pub(crate) threads: usize,
}

/// Where the members branch: the checkpoint's time and turns.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct Branch {
    /// The checkpoint (absolute path).
    pub(crate) checkpoint: PathBuf,
    /// Its time (c/U) and step.
    pub(crate) t: f64,
    pub(crate) steps: u64,
    /// Net turns after release at the branch.
    pub(crate) turns: f64,
    /// The members' averaging start (complete turn after release).
    pub(crate) average_from_turn: usize,
}

/// One member: its id and perturbation of θ̇.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct Member {
    pub(crate) id: String,
    pub(crate) perturbation: f64,
}

/// The members' perturbations ε z_k (see the module docs), to six significant digits: short
/// decimals that the members' command lines and the directory's `sweep.json` hold exactly (a
/// 17-digit number may not come back from the JSON bit for bit, and the sweep would take it
/// for another member).
pub(crate) fn perturbations(size: f64, seed: u64, members: usize) -> Vec<f64> {
    let mut rng = Rng(seed);
    (0..members)
        .map(|_| {
            let d = size * rng.normal();
            format!("{d:.5e}").parse().unwrap_or(d)
        })
        .collect()
}

fn bad(message: String) -> Failure {
    Failure::input(message)
}

/// Checks the numbers of the request (not the checkpoint).
fn check_numbers(spec: &EnsembleSpec) -> Result<(), Failure> {
    if spec.members < 2 {
        return Err(bad(format!(
            "--members {}: out of range: accepted 2 or more (an interval needs two independent \
             members)",
            spec.members
        )));
    }
    let e = spec.perturbation;
    if !(e.is_finite() && e != 0.0 && e.abs() <= MAX_PERTURBATION) {
        return Err(bad(format!(
            "--perturbation {e}: out of range: accepted a finite size with 0 < |ε| ≤ \
             {MAX_PERTURBATION} (rad per c/U)"
        )));
    }
    if let Some(n) = spec.turns.filter(|n| !(n.is_finite() && *n > 0.0)) {
        return Err(bad(format!(
            "--turns {n}: out of range: accepted a positive number"
        )));
    }
    if let Some(t) = spec.t_end.filter(|t| !t.is_finite()) {
        return Err(bad(format!("--t-end {t}: out of range: accepted a number")));
    }
    if let Some(c) = spec
        .checkpoint_every
        .filter(|c| !(c.is_finite() && *c > 0.0))
    {
        return Err(bad(format!(
            "--checkpoint-every {c}: out of range: accepted a positive number"
        )));
    }
    Ok(())
}

/// Reads the checkpoint and checks the branch: a coupled plate, released, an end after it and
/// an averaging start after it.
pub(crate) fn branch_of(spec: &EnsembleSpec) -> Result<(Checkpoint, Branch), Failure> {
    check_numbers(spec)?;
    let ckpt = read_checkpoint(&spec.from, &crate::version::program_version())
        .map_err(|e| bad(format!("--from: {e}")))?;
    let shown = spec.from.display();
    let Some(sim) = ckpt.sim.planar() else {
        return Err(bad(format!(
            "--from {shown}: a 3-D run's checkpoint (--span): accepted a 2-D run's"
        )));
    };
    let (Some(_), Some(th)) = (&sim.body, sim.theta_release) else {
        return Err(bad(format!(
            "--from {shown}: the plate is not free to turn (a static or forced run, or not yet \
             released): accepted a checkpoint of a pinned or free run after its release"
        )));
    };
    let (t, turns) = (sim.flow.t, (sim.state.theta - th).abs() / (2.0 * PI));
    let t_end = match spec.t_end {
        Some(given) => member_end(given, &ckpt)?,
        None => ckpt.resume.t_end,
    };
    if t_end <= t + 1e-9 {
        let shown = spec
            .t_end
            .map_or(t_end.to_string(), |given| given.to_string());
        return Err(bad(format!(
            "--t-end {shown}: the branch point is at t = {t:.4} c/U: accepted a later end"
        )));
    }
    if let Some(n) = spec.turns.or(ckpt.resume.turns).filter(|n| *n <= turns) {
        return Err(bad(format!(
            "--turns {n}: the branch point is {turns:.2} turns after release: accepted more"
        )));
    }
    let first = turns.floor() as usize + 1;
    let average_from_turn = spec.average_from_turn.unwrap_or(first + 1);
    if average_from_turn < first {
        return Err(bad(format!(
            "--average-from-turn {average_from_turn}: the members branch {turns:.2} turns after \
             release: accepted {first} or more (their windows start after the branch)"
        )));
    }
    let last = spec.turns.or(ckpt.resume.turns);
    if let Some(n) = last.filter(|n| average_from_turn as f64 >= *n) {
        return Err(bad(format!(
            "--average-from-turn {average_from_turn}: the members end after {n} turns: accepted \
             fewer than {n}"
        )));
    }
    let checkpoint =
        std::path::absolute(&spec.from).map_err(|e| bad(format!("--from {shown}: {e}")))?;
    let steps = sim.flow.steps;
    Ok((
        ckpt,
        Branch {
            checkpoint,
            t,
            steps,
            turns,
            average_from_turn,
        },
    ))
}

/// A member's end in c/U: seconds convert with the spun-up run's plate scales.
fn member_end(given: EndTime, ckpt: &Checkpoint) -> Result<f64, Failure> {
    let config: Option<RunConfig> = serde_json::from_str(&ckpt.resume.config_json).ok();
    let scales = config.as_ref().and_then(Units::of).map(|u| u.scales);
    given.convective(scales).ok_or_else(|| {
        bad(format!(
            "--t-end {given}: the spun-up run's plate has no physical units: accepted convective \
             times c/U (e.g. 60)"
        ))
    })
}

/// The members' ids and perturbations.
pub(crate) fn members(spec: &EnsembleSpec) -> Vec<Member> {
    perturbations(spec.perturbation, spec.seed, spec.members)
        .into_iter()
        .enumerate()
        .map(|(k, perturbation)| Member {
            id: format!("m{k:03}"),
            perturbation,
        })
        .collect()
}

/// The sweep case of a member: `resume` of the branch's checkpoint with its perturbation, end
/// and averaging start (the sweep adds the outputs and the member's own checkpoint).
pub(crate) fn case_of(
    spec: &EnsembleSpec,
    branch: &Branch,
    index: usize,
    member: &Member,
) -> CaseSpec {
    let path = |p: &Path| p.to_string_lossy().into_owned();
    let mut args = vec![
        "resume".to_string(),
        path(&branch.checkpoint),
        format!("--perturb-omega={:e}", member.perturbation),
        format!("--average-from-turn={}", branch.average_from_turn),
        format!("--threads={}", spec.threads),
    ];
    args.extend(spec.turns.map(|n| format!("--turns={n}")));
    args.extend(spec.t_end.map(|t| format!("--t-end={t}")));
    args.extend(
        spec.checkpoint_every
            .map(|c| format!("--checkpoint-every={c}")),
    );
    CaseSpec {
        index,
        id: member.id.clone(),
        params: vec![("perturb-omega".into(), Value::Float(member.perturbation))],
        args,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn perturbations_are_seeded_and_a_larger_ensemble_holds_the_smaller() {
        let a = perturbations(1e-6, 7, 4);
        let b = perturbations(1e-6, 7, 9);
        assert_eq!(a[..], b[..4]);
        assert_ne!(perturbations(1e-6, 8, 4), a);
        // Normal numbers of size ε: none zero, all well within 6 ε.
        assert!(b.iter().all(|d| *d != 0.0 && d.abs() < 6e-6), "{b:?}");
        // Each comes back from the JSON of the directory's manifest bit for bit.
        for d in b {
            let back: f64 = serde_json::from_str(&serde_json::to_string(&d).unwrap()).unwrap();
            assert_eq!(back.to_bits(), d.to_bits());
        }
    }
}
