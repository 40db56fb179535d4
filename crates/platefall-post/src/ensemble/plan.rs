//! How much to run for a requested half-width, from a pilot.
//!
//! - **Members** ([`members_for`]): a pilot ensemble of members averaged over a length L_p
//!   (turns or time) has the between-member standard deviation s_p. Over a length L ≫ the
//!   correlation time the variance of a member's mean falls as 1/L, so s(L) = s_p √(L_p/L), and
//!   the members needed are the fewest M ≥ 2 with t(0.975; M − 1) s(L)/√M ≤ the target. Each
//!   member also runs its discarded part (until it has decorrelated) before its window.
//! - **One run** ([`single_run_length`]): a run of length L whose mean has the standard error
//!   se with n_eff effective observations reaches the target at the length L' for which
//!   t(0.975; n_eff L'/L − 1) · se √(L/L') ≤ the target; "run about L' − L more".
use serde::Serialize;

use super::pool::{EnsembleInterval, MIN_MEMBERS};
use crate::stats::{t95, Interval};

/// Members beyond which the planner gives up (the target is out of reach).
pub const MAX_MEMBERS: usize = 100_000;

/// An ensemble plan.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct MemberPlan {
    /// Members needed.
    pub members: usize,
    /// Length of each member's window of averaging.
    pub length: f64,
    /// Total length run, members × (discard + length).
    pub total: f64,
    /// The half-width the plan expects, t(M − 1) s(L)/√M.
    pub expected_half_width: f64,
}

/// The members needed for `target` half-width with windows of `length`, from a `pilot` whose
/// members were averaged over `pilot_length`, each member also running `discard` before its
/// window. None when the target is not positive or needs more than [`MAX_MEMBERS`].
pub fn members_for(
    pilot: &EnsembleInterval,
    pilot_length: f64,
    length: f64,
    discard: f64,
    target: f64,
) -> Option<MemberPlan> {
    if !(target > 0.0 && pilot_length > 0.0 && length > 0.0) {
        return None;
    }
    let s = pilot.spread * (pilot_length / length).sqrt();
    let width = |m: usize| t95(m as f64 - 1.0) * s / (m as f64).sqrt();
    // The width falls monotonically with M: bisect on [MIN_MEMBERS, MAX_MEMBERS].
    if width(MAX_MEMBERS) > target {
        return None;
    }
    let (mut lo, mut hi) = (MIN_MEMBERS, MAX_MEMBERS);
    if width(lo) <= target {
        hi = lo;
    }
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if width(mid) <= target {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(MemberPlan {
        members: hi,
        length,
        total: hi as f64 * (discard + length),
        expected_half_width: width(hi),
    })
}

/// The length a single run needs for `target` half-width, from its `interval` over `length`;
/// None when the interval or the target is not positive.
pub fn single_run_length(interval: &Interval, length: f64, target: f64) -> Option<f64> {
    if !(target > 0.0 && length > 0.0 && interval.std_error > 0.0 && interval.n_eff > 0.0) {
        return None;
    }
    let width = |l: f64| {
        let n_eff = interval.n_eff * l / length;
        t95((n_eff - 1.0).max(0.5)) * interval.std_error * (length / l).sqrt()
    };
    // Double until reached, then bisect (the width falls monotonically with the length).
    let (mut lo, mut hi) = (0.0, length);
    while width(hi) > target {
        lo = hi;
        hi *= 2.0;
        if hi > 1e12 * length {
            return None;
        }
    }
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if width(mid) <= target {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(hi)
}
