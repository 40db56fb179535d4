//! The run summary: stable JSON keys for scripts, computed from the time series of a run over its
//! developed part (docs/physics.md §8), with what a falling plate is doing ([`FallKeys`], docs/physics.md §1 case D)
//! and the results in physical units when the plate has them ([`PhysicalKeys`], docs/physics.md §2).
//! Everything is computed from `&[StepSample]` windows.
use std::f64::consts::PI;

use super::analysis::{
    count_turns, dominant_frequency, lag_cd_behind_cl, projected_width, whole_periods, TimeWindow,
};
use super::intervals::intervals_of;
pub use super::keys::{FallKeys, IntervalKeys, PhysicalKeys, Summary};
use super::regime::{classify, regime_window, MotionClass};
use platefall_core::config::{physical, Units};
use platefall_core::sim::{Case, History, Quantity, RunConfig, RunRecord, StepSample};

/// Peak-to-peak C_L below which the flow counts as steady (no Strouhal number).
pub const STEADY_BAND: f64 = 0.02;

/// The developed window: for coupled cases the whole turns after autorotation is established (the
/// first complete turn after release, or the turn `--average-from-turn` names), or, for a plate
/// that makes no two whole turns, the regime window trimmed to whole periods of its motion, or,
/// for a plate that turns both ways in the regime window, that window itself; for forced rotation the whole half-turns after
/// spin-up plus one half-turn; for the static case the second half of the run, trimmed to whole lift
/// periods.
fn developed(
    config: &RunConfig,
    rec: &RunRecord,
    freq: Option<f64>,
    motion: Option<&(TimeWindow, MotionClass)>,
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
            coupled_window(rec, config.time.average_from_turn, motion)
        }
    }
}

/// The developed window of a coupled run (see [`developed`]).
fn coupled_window(
    rec: &RunRecord,
    from_turn: usize,
    motion: Option<&(TimeWindow, MotionClass)>,
) -> (Option<TimeWindow>, String, Option<f64>) {
    let turns = count_turns(&rec.samples, rec.t_release);
    let established = turns.completed.first().copied();
    if let Some((w, class)) = motion.filter(|(_, class)| class.turns_both_ways()) {
        let rule = format!(
            "second half after release ({} turns counter-clockwise and {} clockwise: means over \
             time, not whole turns)",
            class.turns.0, class.turns.1
        );
        return (Some(*w), rule, None);
    }
    let from = turns.completed.get(from_turn.max(1) - 1).copied();
    if let (Some(a), Some(&b)) = (from, turns.completed.last()) {
        if b > a {
            let rule = match from_turn {
                1 => "whole turns after the first complete turn following release".into(),
                k => format!("whole turns after complete turn {k} following release"),
            };
            return (Some(TimeWindow { t0: a, t1: b }), rule, established);
        }
    }
    match motion {
        Some((w, class)) => {
            let w = class.period.map_or(*w, |p| whole_periods(*w, p));
            let rule =
                "second half after release, whole periods of the motion (no two whole turns)";
            (Some(w), rule.into(), established)
        }
        None => (None, "no motion after release".into(), established),
    }
}

/// The coefficient keys over the developed window `w` (Strouhal numbers for the static case).
fn set_coefficients(
    sum: &mut Summary,
    config: &RunConfig,
    h: &History,
    w: Option<TimeWindow>,
    freq: Option<f64>,
) {
    let mean = |q: Quantity| w.and_then(|w| h.mean(q, w.t0, w.t1));
    let cl_range = w.and_then(|w| h.range(Quantity::Cl, w.t0, w.t1));
    (sum.mean_cl, sum.mean_cd, sum.mean_cm) =
        (mean(Quantity::Cl), mean(Quantity::Cd), mean(Quantity::Cm));
    (sum.min_cl, sum.max_cl) = (cl_range.map(|r| r.0), cl_range.map(|r| r.1));
    sum.max_cd = w
        .and_then(|w| h.range(Quantity::Cd, w.t0, w.t1))
        .map(|r| r.1);
    if let (Case::Static { alpha, .. }, Some(f)) = (&config.case, freq) {
        (sum.strouhal_chord, sum.strouhal_width) =
            (Some(f), Some(f * projected_width(config, *alpha)));
    }
}

/// The keys measured on the final flow field.
fn set_final_field(sum: &mut Summary, rec: &RunRecord) {
    sum.recirculation_length = rec.recirculation_length;
}

/// The keys of a moving plate (forced, pinned, free) over the developed window `w`.
fn set_motion(
    sum: &mut Summary,
    config: &RunConfig,
    rec: &RunRecord,
    w: Option<TimeWindow>,
    both_ways: bool,
) {
    let (h, s) = (&rec.samples, &rec.samples[..]);
    let mean = |q: Quantity| w.and_then(|w| h.mean(q, w.t0, w.t1));
    if config.case.is_coupled() {
        sum.mean_speed = mean(Quantity::Speed);
        sum.mean_gamma = mean(Quantity::Gamma);
        sum.autorotation_rule = Some(
            "time of the first complete net turn after release (counted from any reversal)".into(),
        );
    }
    sum.mean_omega = mean(Quantity::Omega);
    sum.revolutions = Some(count_turns(s, rec.t_release).revolutions);
    // Half-turns in both senses have no common lag.
    sum.lag_cd_behind_cl = w
        .filter(|_| !both_ways)
        .and_then(|w| lag_cd_behind_cl(s, w));
    sum.peak_cl_rotation = match (sum.mean_omega, sum.min_cl, sum.max_cl) {
        (Some(om), Some(lo), Some(hi)) => Some(if om >= 0.0 { hi } else { -lo }),
        _ => None,
    };
}

/// The regime window and its classification (coupled runs).
pub(crate) fn motion_of(config: &RunConfig, rec: &RunRecord) -> Option<(TimeWindow, MotionClass)> {
    if !config.case.is_coupled() {
        return None;
    }
    let w = regime_window(&rec.samples, rec.t_release)?;
    Some((w, classify(&rec.samples, w)))
}

/// The falling-plate keys over the developed window `w`.
fn fall_keys(
    h: &History,
    w: Option<TimeWindow>,
    motion: Option<&(TimeWindow, MotionClass)>,
) -> FallKeys {
    let Some((rw, class)) = motion else {
        return FallKeys::default();
    };
    let descent = w
        .and_then(|w| h.mean(Quantity::Ydot, w.t0, w.t1))
        .map(|v| -v);
    let drift = w.and_then(|w| h.mean(Quantity::Xdot, w.t0, w.t1));
    FallKeys {
        regime: Some(class.regime),
        regime_rule: Some(
            "second half after release: steady if |θ − mid| ≤ 0.02 rad; runs of θ between \
             reversals of 0.1 rad counted as full turns; turns of both signs chaotic; one sign \
             tumbling, none fluttering, if the half-turn / oscillation durations vary by at most \
             25 % (coefficient of variation) over at least 2, else chaotic (undetermined if fewer)"
                .into(),
        ),
        regime_from: Some(rw.t0),
        mean_descent_speed: descent,
        mean_horizontal_speed: drift,
        descent_angle: descent.zip(drift).map(|(d, h)| d.atan2(h.abs())),
        period: class.period,
        angle_amplitude: class.amplitude,
    }
}

/// The physical-unit keys (plates with physical scales).
fn physical_keys(units: Option<&Units>, mean_speed: Option<f64>, fall: &FallKeys) -> PhysicalKeys {
    let Some(u) = units else {
        return PhysicalKeys::default();
    };
    let period_s = fall.period.map(|p| u.time_s(p));
    PhysicalKeys {
        velocity_scale_m_s: Some(u.scales.speed_m_s),
        chord_m: Some(u.scales.chord_m),
        mean_speed_cm_s: mean_speed.map(|v| u.speed_cm_s(v)),
        mean_descent_speed_cm_s: fall.mean_descent_speed.map(|v| u.speed_cm_s(v)),
        mean_horizontal_speed_cm_s: fall.mean_horizontal_speed.map(|v| u.speed_cm_s(v)),
        period_s,
        frequency_hz: period_s.map(|p| 1.0 / p),
    }
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
    let motion = motion_of(config, rec);
    let (w, rule, established) = developed(config, rec, freq, motion.as_ref());
    let mut sum = Summary {
        case: config.case.kind(),
        status: rec.status.kind(),
        re: config.flow.re,
        resolution: config.grid.resolution,
        cells: rec.cells,
        steps: h.total_steps(),
        t_reached: last_t,
        wall_seconds,
        developed_from: w.map(|w| w.t0),
        developed_to: w.map(|w| w.t1),
        developed_rule: rule,
        mean_cl: None,
        mean_cd: None,
        mean_cm: None,
        max_cl: None,
        min_cl: None,
        max_cd: None,
        strouhal_chord: None,
        strouhal_width: None,
        recirculation_length: None,
        mean_speed: None,
        mean_omega: None,
        mean_gamma: None,
        revolutions: None,
        autorotation_time: established,
        autorotation_rule: None,
        lag_cd_behind_cl: None,
        peak_cl_rotation: None,
        mean_speed_ft_s: None,
        mean_omega_rad_s: None,
        fall: FallKeys::default(),
        physical: PhysicalKeys::default(),
        ci: IntervalKeys::default(),
    };
    set_coefficients(&mut sum, config, h, w, freq);
    set_final_field(&mut sum, rec);
    if !matches!(config.case, Case::Static { .. }) {
        let both_ways = motion.as_ref().is_some_and(|(_, c)| c.turns_both_ways());
        set_motion(&mut sum, config, rec, w, both_ways);
    }
    sum.fall = fall_keys(h, w, motion.as_ref());
    let units = Units::of(config);
    sum.mean_speed_ft_s = physical(config).and_then(|p| sum.mean_speed.map(|v| p.speed_to_ft_s(v)));
    sum.mean_omega_rad_s = units.and_then(|u| sum.mean_omega.map(|v| u.rate_rad_s(v.abs())));
    sum.physical = physical_keys(units.as_ref(), sum.mean_speed, &sum.fall);
    sum.ci = intervals_of(config, rec, &sum, freq, motion.as_ref());
    sum
}
