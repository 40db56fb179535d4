//! When the members parted: their θ̇ from each member's CSV, put on common times from the
//! branch to the earliest member's end, and the decorrelation of those series
//! ([`platefall_post::ensemble::decorrelation`]).
use std::path::Path;

use serde::Serialize;

use super::traces::columns;
use platefall_post::ensemble::decorrelation;

/// Common times from the branch on at which the members are compared.
pub(crate) const COMMON_TIMES: usize = 800;
/// The correlation is smoothed over this many common times (a fortieth of the series).
pub(crate) const SMOOTHING: usize = COMMON_TIMES / 40;

/// The members' decorrelation, as the ensemble's JSON states it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct Parting {
    /// The quantity compared.
    pub(crate) quantity: &'static str,
    /// The first time at which the members' correlation falls below e⁻² (None: it does not
    /// within the members' common span).
    pub(crate) time: Option<f64>,
    /// Its delay after the branch.
    pub(crate) after_branch: Option<f64>,
    /// The earliest start of a member's averaging window.
    pub(crate) window_start: Option<f64>,
    /// Whether every member's window starts after the members decorrelated.
    pub(crate) independent: bool,
}

/// (time, θ̇) of the rows of a member's CSV from `t0` on.
fn series(csv: &Path, t0: f64) -> Option<(Vec<f64>, Vec<f64>)> {
    let (t, mut c) = columns(csv, t0, &["thetadot"])?;
    Some((t, c.pop()?))
}

/// The value of the piecewise-linear series (t, x) at `s` inside its span, `k` a hint that
/// only moves forward.
fn at(t: &[f64], x: &[f64], s: f64, k: &mut usize) -> f64 {
    while *k + 2 < t.len() && t[*k + 1] < s {
        *k += 1;
    }
    let (a, b) = (t[*k], t[*k + 1]);
    let f = if b > a {
        ((s - a) / (b - a)).clamp(0.0, 1.0)
    } else {
        0.0
    };
    x[*k] + f * (x[*k + 1] - x[*k])
}

/// The members' parting from their CSVs after the branch time `t0`, with the earliest start
/// of their windows; None when fewer than two CSVs can be read or they share no span.
pub(crate) fn parting(csvs: &[&Path], t0: f64, window_start: Option<f64>) -> Option<Parting> {
    let all: Vec<(Vec<f64>, Vec<f64>)> = csvs
        .iter()
        .filter_map(|p| series(p, t0))
        .filter(|(t, _)| t.len() >= 2)
        .collect();
    if all.len() < 2 {
        return None;
    }
    let (a, b) = all.iter().fold((f64::MIN, f64::MAX), |(a, b), (t, _)| {
        (a.max(t[0]), b.min(t[t.len() - 1]))
    });
    if b <= a {
        return None;
    }
    let times: Vec<f64> = (0..COMMON_TIMES)
        .map(|k| a + (b - a) * k as f64 / (COMMON_TIMES - 1) as f64)
        .collect();
    let members: Vec<Vec<f64>> = all
        .iter()
        .map(|(t, x)| {
            let mut k = 0;
            times.iter().map(|s| at(t, x, *s, &mut k)).collect()
        })
        .collect();
    let d = decorrelation(&times, &members, SMOOTHING)?;
    let independent = window_start.is_some_and(|w| d.allows(w));
    Some(Parting {
        quantity: "thetadot",
        time: d.time,
        after_branch: d.time.map(|t| t - t0),
        window_start,
        independent,
    })
}
