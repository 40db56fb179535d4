//! When members branched from one state have become independent: their decorrelation time,
//! measured from their separation.
//!
//! At each common time t_k the members' values x_i(t_k) have a between-member variance s²_k;
//! for exchangeable members of variance σ², E\[s²_k\] = σ² (1 − ρ_k), where ρ_k is the correlation
//! between two members at that time. Members just branched have ρ ≈ 1; independent ones ρ = 0.
//! σ² is the variance of all members' values over the second half of the series (the motion's
//! own variance, once they have parted), ρ_k = 1 − s²_k/σ² is smoothed by a centred running mean,
//! and the decorrelation time is the first time at which it falls below
//! [`DECORRELATED`] = e⁻² (two e-folds). Each member's window of averaging should start after it.
//! The test of the members' means themselves is [`super::pool::Consistency`].
use serde::Serialize;

/// The between-member correlation below which the members count as decorrelated (e⁻²).
pub const DECORRELATED: f64 = 0.135_335_283_236_612_7;

/// The members' decorrelation, from their separation.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Decorrelation {
    /// The first time at which the smoothed correlation falls below [`DECORRELATED`]; None when
    /// it never does within the series (the members have not parted).
    pub time: Option<f64>,
    /// The motion's variance σ² (all members, second half of the series).
    pub variance: f64,
    /// The smoothed between-member correlation ρ at each time.
    pub correlation: Vec<f64>,
}

impl Decorrelation {
    /// Whether a window of averaging that starts at `start` (same clock as the times) starts
    /// after the members have decorrelated.
    pub fn allows(&self, start: f64) -> bool {
        self.time.is_some_and(|t| start >= t)
    }
}

/// The unbiased variance of `x` (0 for fewer than two values).
fn variance(x: impl Iterator<Item = f64> + Clone) -> f64 {
    let n = x.clone().count() as f64;
    if n < 2.0 {
        return 0.0;
    }
    let mean = x.clone().sum::<f64>() / n;
    x.map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)
}

/// The decorrelation of `members` (each sampled at the common `times`, the branch point first),
/// with ρ smoothed over `window` samples (at least 1). None with fewer than two members, fewer
/// than four times, or members of different lengths.
pub fn decorrelation(times: &[f64], members: &[Vec<f64>], window: usize) -> Option<Decorrelation> {
    let n = times.len();
    if members.len() < 2 || n < 4 || members.iter().any(|m| m.len() != n) {
        return None;
    }
    let sigma2 = variance(members.iter().flat_map(|m| m[n / 2..].iter().copied()));
    let raw: Vec<f64> = (0..n)
        .map(|k| {
            if sigma2 > 0.0 {
                1.0 - variance(members.iter().map(|m| m[k])) / sigma2
            } else {
                1.0
            }
        })
        .collect();
    let half = window.max(1) / 2;
    let correlation: Vec<f64> = (0..n)
        .map(|k| {
            let (a, b) = (k.saturating_sub(half), (k + half + 1).min(n));
            raw[a..b].iter().sum::<f64>() / (b - a) as f64
        })
        .collect();
    let time = correlation
        .iter()
        .position(|r| *r < DECORRELATED)
        .map(|k| times[k]);
    Some(Decorrelation {
        time,
        variance: sigma2,
        correlation,
    })
}
