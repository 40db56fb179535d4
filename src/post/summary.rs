//! The run summary: stable JSON keys for scripts, computed from the time series of a run over its
//! developed part.
use std::f64::consts::PI;

use serde::Serialize;

use super::analysis::{count_turns, dominant_frequency, whole_periods, TimeWindow};
use crate::config::physical;
use crate::sim::{Case, Quantity, RunConfig, RunRecord, StepSample};

/// Peak-to-peak C_L below which the flow counts as steady (no Strouhal number).
pub const STEADY_BAND: f64 = 0.02;

#[derive(Clone, Debug, Serialize)]
pub struct Summary {
    pub case: String,
    pub status: String,
    pub re: f64,
    pub resolution: usize,
    pub cells: usize,
    pub steps: u64,
    /// Convective time reached.
    pub t_end: f64,
    pub wall_seconds: f64,
    /// The developed part the means are taken over, and how it was chosen.
    pub developed_from: Option<f64>,
    pub developed_to: Option<f64>,
    pub developed_rule: String,
    pub mean_cl: Option<f64>,
    pub mean_cd: Option<f64>,
    pub mean_cm: Option<f64>,
    pub max_cl: Option<f64>,
    pub min_cl: Option<f64>,
    pub max_cd: Option<f64>,
    /// Dominant lift frequency × c/U, and × projected width c|sin α| / U (static case); null when steady.
    pub strouhal_chord: Option<f64>,
    pub strouhal_width: Option<f64>,
    // Coupled and forced cases.
    pub mean_speed: Option<f64>,
    pub mean_omega: Option<f64>,
    pub mean_gamma: Option<f64>,
    pub revolutions: Option<f64>,
    pub autorotation_time: Option<f64>,
    pub autorotation_rule: Option<String>,
    /// Lag of max C_D behind max C_L in α (rad), averaged over the developed half-turns.
    pub lag_cd_behind_cl: Option<f64>,
    /// Peak lift coefficient in the sense of the rotation (max C_L turning counter-clockwise,
    /// −min C_L turning clockwise), over the developed part; the seed's "max C_L in autorotation".
    pub peak_cl_rotation: Option<f64>,
    /// Card preset: the means in physical units.
    pub mean_speed_ft_s: Option<f64>,
    pub mean_omega_rad_s: Option<f64>,
}

/// The developed window: for coupled cases the whole turns after autorotation is established (the
/// first complete turn after release); for forced rotation the whole half-turns after spin-up plus
/// one half-turn; for the static case the second half of the run, trimmed to whole lift periods.
fn developed(
    config: &RunConfig,
    rec: &RunRecord,
    freq: Option<f64>,
) -> (Option<TimeWindow>, String, Option<f64>) {
    let Some(last) = rec.samples.last() else {
        return (None, "no steps".into(), None);
    };
    match &config.case {
        Case::Static { .. } => {
            let w = TimeWindow {
                t0: 0.5 * last.t,
                t1: last.t,
            };
            match freq {
                Some(f) => (
                    Some(whole_periods(w, 1.0 / f)),
                    "second half of the run, whole lift periods".into(),
                    None,
                ),
                None => (Some(w), "second half of the run (steady)".into(), None),
            }
        }
        Case::Forced { omega, spinup } => {
            let half_turn = PI / omega.abs();
            let w = TimeWindow {
                t0: spinup + half_turn,
                t1: last.t,
            };
            if w.t1 - w.t0 < half_turn {
                return (
                    None,
                    "shorter than one half-turn after spin-up".into(),
                    None,
                );
            }
            (
                Some(whole_periods(w, half_turn)),
                "whole half-turns after spin-up + one half-turn".into(),
                None,
            )
        }
        Case::Pinned { .. } | Case::Free { .. } => {
            let turns = count_turns(&rec.samples, rec.t_release);
            let established = turns.completed.first().copied();
            let w = match (established, turns.completed.last()) {
                (Some(a), Some(&b)) if b > a => Some(TimeWindow { t0: a, t1: b }),
                _ => None,
            };
            (
                w,
                "whole turns after the first complete turn following release".into(),
                established,
            )
        }
    }
}

/// Mean lag (in α) of the maximum of C_D behind the maximum of C_L, per half-turn (period π in θ).
/// For clockwise rotation the lift is taken in the rotation's own sense (−C_L): the mirror image
/// y → −y of a counter-clockwise run turns clockwise with C_L negated and C_D unchanged.
fn lag_cd_behind_cl(samples: &[StepSample], w: TimeWindow) -> Option<f64> {
    let inside: Vec<&StepSample> = samples
        .iter()
        .filter(|s| s.t >= w.t0 && s.t <= w.t1)
        .collect();
    let first = inside.first()?;
    let dir = if inside.last()?.theta >= first.theta {
        1.0
    } else {
        -1.0
    };
    let mut lags = Vec::new();
    let mut k0 = 0;
    for k in 1..=inside.len() {
        let end = k == inside.len() || dir * (inside[k].theta - inside[k0].theta) >= PI;
        if end {
            let seg = &inside[k0..k];
            if k < inside.len() || dir * (seg.last()?.theta - seg[0].theta) >= PI * 0.999 {
                let a_cl = seg
                    .iter()
                    .max_by(|a, b| (dir * a.cl).total_cmp(&(dir * b.cl)))?
                    .theta;
                let a_cd = seg.iter().max_by(|a, b| a.cd.total_cmp(&b.cd))?.theta;
                lags.push((dir * (a_cd - a_cl)).rem_euclid(PI));
            }
            k0 = k;
        }
    }
    (!lags.is_empty()).then(|| lags.iter().sum::<f64>() / lags.len() as f64)
}

/// The summary of a run; `wall_seconds` is measured by the caller (the solver reads no clock).
///
/// Means and extremes come from the bounded history's exact running integrals and per-step
/// extremes (`History::mean`, `History::range`): exact over every step of the developed window
/// between its first and last retained samples. Turns, the spectrum and the lag read the retained
/// samples (`&rec.samples` is a `&[StepSample]`).
pub fn summarize(config: &RunConfig, rec: &RunRecord, wall_seconds: f64) -> Summary {
    let h = &rec.samples;
    let s: &[StepSample] = h;
    let last_t = s.last().map(|x| x.t).unwrap_or(0.0);
    let provisional = TimeWindow {
        t0: 0.5 * last_t,
        t1: last_t,
    };
    let freq = match config.case {
        Case::Static { .. } => dominant_frequency(s, provisional, STEADY_BAND, |x| x.cl),
        _ => None,
    };
    let (w, rule, established) = developed(config, rec, freq);
    let mean = |q: Quantity| w.and_then(|w| h.mean(q, w.t0, w.t1));
    let cl_range = w.and_then(|w| h.range(Quantity::Cl, w.t0, w.t1));
    let cd_range = w.and_then(|w| h.range(Quantity::Cd, w.t0, w.t1));
    let coupled = config.case.is_coupled();
    let moving = !matches!(config.case, Case::Static { .. });
    let (strouhal_chord, strouhal_width) = match (config.case.clone(), freq) {
        (Case::Static { alpha, .. }, Some(f)) => (Some(f), Some(f * alpha.sin().abs())),
        _ => (None, None),
    };
    let mean_speed = if coupled { mean(Quantity::Speed) } else { None };
    let mean_omega = if moving { mean(Quantity::Omega) } else { None };
    let physical = physical(config);
    Summary {
        case: config.case.name().into(),
        status: rec.status.name().into(),
        re: config.flow.re,
        resolution: config.grid.resolution,
        cells: rec.cells,
        steps: h.total_steps(),
        t_end: last_t,
        wall_seconds,
        developed_from: w.map(|w| w.t0),
        developed_to: w.map(|w| w.t1),
        developed_rule: rule,
        mean_cl: mean(Quantity::Cl),
        mean_cd: mean(Quantity::Cd),
        mean_cm: mean(Quantity::Cm),
        max_cl: cl_range.map(|r| r.1),
        min_cl: cl_range.map(|r| r.0),
        max_cd: cd_range.map(|r| r.1),
        strouhal_chord,
        strouhal_width,
        mean_speed,
        mean_omega,
        mean_gamma: if coupled { mean(Quantity::Gamma) } else { None },
        revolutions: moving.then(|| count_turns(s, rec.t_release).revolutions),
        autorotation_time: established,
        autorotation_rule: coupled.then(|| {
            "time of the first complete net turn after release (counted from any reversal)".into()
        }),
        lag_cd_behind_cl: if moving {
            w.and_then(|w| lag_cd_behind_cl(s, w))
        } else {
            None
        },
        peak_cl_rotation: match (moving, mean_omega, cl_range) {
            (true, Some(om), Some((lo, hi))) => Some(if om >= 0.0 { hi } else { -lo }),
            _ => None,
        },
        mean_speed_ft_s: physical
            .as_ref()
            .and_then(|p| mean_speed.map(|v| p.speed_to_ft_s(v))),
        mean_omega_rad_s: physical
            .as_ref()
            .and_then(|p| mean_omega.map(|v| p.rate_to_rad_s(v.abs()))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A plate turning at rate `om` with C_L peaking at θ = 1.0 and C_D at θ = 1.5 (mod π) for
    /// counter-clockwise rotation, and the mirror image (C_L negated) for clockwise rotation.
    fn turning(om: f64) -> Vec<StepSample> {
        let dir = om.signum();
        (0..20000)
            .map(|k| {
                let t = k as f64 * 0.001;
                let th = om * t;
                let phase = dir * th;
                let bump =
                    |c: f64| (-(((phase - c).rem_euclid(PI) - PI / 2.0).powi(2)) * 8.0).exp();
                StepSample {
                    t,
                    theta: th,
                    omega: om,
                    cl: dir * bump(1.0 - PI / 2.0 + PI),
                    cd: bump(1.5 - PI / 2.0 + PI),
                    ..Default::default()
                }
            })
            .collect()
    }

    #[test]
    fn lag_of_drag_behind_lift_is_the_same_for_mirror_image_rotations() {
        let w = TimeWindow { t0: 1.0, t1: 19.0 };
        let ccw = lag_cd_behind_cl(&turning(2.0), w).unwrap();
        let cw = lag_cd_behind_cl(&turning(-2.0), w).unwrap();
        assert!((ccw - 0.5).abs() < 0.01, "counter-clockwise lag {ccw}");
        assert!(
            (cw - ccw).abs() < 0.01,
            "clockwise lag {cw} differs from {ccw}"
        );
    }
}
