//! The run summary: stable JSON keys for scripts, computed from the time series of a run over its
//! developed part (docs/physics.md §8), with what a falling plate is doing ([`FallKeys`], docs/physics.md §1 case D)
//! and the results in physical units when the plate has them ([`PhysicalKeys`], docs/physics.md §2).
//! Everything is computed from `&[StepSample]` windows.
use std::f64::consts::PI;

use serde::Serialize;

use super::analysis::{count_turns, dominant_frequency, whole_periods, TimeWindow};
use super::intervals::{intervals_of, IntervalKeys};
use super::regime::{classify, regime_window, MotionClass, Regime};
use platefall_core::config::{physical, Units};
use platefall_core::sim::{
    Case, CaseKind, History, Quantity, RunConfig, RunRecord, StatusKind, StepSample,
};

/// Peak-to-peak C_L below which the flow counts as steady (no Strouhal number).
pub const STEADY_BAND: f64 = 0.02;

#[derive(Clone, Debug, Serialize)]
pub struct Summary {
    pub case: CaseKind,
    pub status: StatusKind,
    pub re: f64,
    pub resolution: usize,
    pub cells: usize,
    pub steps: u64,
    /// The convective time the run reached (its end time when it completed by reaching it; the
    /// JSON key is `t_end`).
    #[serde(rename = "t_end")]
    pub t_reached: f64,
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
    /// Dominant lift frequency × c/U, and × the section's width across the stream / U (static
    /// case; c|sin α| + t|cos α| for a rectangle, see [`projected_width`]); null when steady.
    pub strouhal_chord: Option<f64>,
    pub strouhal_width: Option<f64>,
    /// Static case: the reversed-flow length behind the plate at the end of the run, from its rear
    /// boundary along the relative free stream (chords; the cylinder's L/D).
    pub recirculation_length: Option<f64>,
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
    /// −min C_L turning clockwise), over the developed part; the dissertation's "max C_L in autorotation".
    pub peak_cl_rotation: Option<f64>,
    /// Card preset: the mean speed in the card's feet.
    pub mean_speed_ft_s: Option<f64>,
    /// The mean rotation rate |θ̇| in rad/s (plates with physical units).
    pub mean_omega_rad_s: Option<f64>,
    #[serde(flatten)]
    pub fall: FallKeys,
    #[serde(flatten)]
    pub physical: PhysicalKeys,
    /// The 95 % confidence intervals of the means (`<key>_ci95`, `intervals`; see `post::intervals`).
    #[serde(flatten)]
    pub ci: IntervalKeys,
}

/// What a falling (or pinned) plate is doing, over the developed part; null for static and forced
/// runs. Descent is positive downwards; the regime rule is in `post::regime`.
#[derive(Clone, Debug, Default, Serialize)]
pub struct FallKeys {
    /// steady, fluttering, tumbling, chaotic or undetermined.
    pub regime: Option<Regime>,
    pub regime_rule: Option<String>,
    /// Start of the window the regime is judged on (it ends with the run).
    pub regime_from: Option<f64>,
    /// −mean Ẏ (positive when sinking).
    pub mean_descent_speed: Option<f64>,
    /// mean Ẋ: the mean horizontal drift (signed; ≈ 0 for a plate that flutters in place).
    pub mean_horizontal_speed: Option<f64>,
    /// Angle of the mean path below the horizontal, atan2(descent, |drift|) (rad; π/2 straight
    /// down, negative when rising).
    pub descent_angle: Option<f64>,
    /// One full oscillation of θ (fluttering) or one full turn (tumbling), in c/U.
    pub period: Option<f64>,
    /// Half the peak-to-peak range of θ when the plate makes no full turn (rad).
    pub angle_amplitude: Option<f64>,
}

/// The results in physical units (plates with physical scales: described physically, or the card).
#[derive(Clone, Debug, Default, Serialize)]
pub struct PhysicalKeys {
    /// U (m/s) and c (m) behind the conversions.
    pub velocity_scale_m_s: Option<f64>,
    pub chord_m: Option<f64>,
    pub mean_speed_cm_s: Option<f64>,
    pub mean_descent_speed_cm_s: Option<f64>,
    pub mean_horizontal_speed_cm_s: Option<f64>,
    pub period_s: Option<f64>,
    pub frequency_hz: Option<f64>,
}

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

/// Mean lag (in α) of the maximum of C_D behind the maximum of C_L, per half-turn (period π in θ).
/// For clockwise rotation the lift is taken in the rotation's own sense (−C_L): the mirror image
/// y → −y of a counter-clockwise run turns clockwise with C_L negated and C_D unchanged.
fn lag_cd_behind_cl(samples: &[StepSample], w: TimeWindow) -> Option<f64> {
    let lags = lags_cd_behind_cl(samples, w);
    (!lags.is_empty()).then(|| lags.iter().sum::<f64>() / lags.len() as f64)
}

/// The lag of `lag_cd_behind_cl` in each half-turn of the window.
pub fn lags_cd_behind_cl(samples: &[StepSample], w: TimeWindow) -> Vec<f64> {
    lag_list(samples, w).unwrap_or_default()
}

fn lag_list(samples: &[StepSample], w: TimeWindow) -> Option<Vec<f64>> {
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
    Some(lags)
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

/// The width of a static section at angle of attack α across the stream (chords): the length
/// the Strouhal number on the width is based on (c|sin α| + t|cos α| for a rectangle).
pub fn projected_width(config: &RunConfig, alpha: f64) -> f64 {
    let (s, c) = alpha.sin_cos();
    config.grid.shape.outline().width_across([c, -s])
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
fn motion_of(config: &RunConfig, rec: &RunRecord) -> Option<(TimeWindow, MotionClass)> {
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
