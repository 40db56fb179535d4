//! The run summary's data: its stable JSON keys ([`Summary`], with what a falling plate is doing,
//! the results in physical units and the confidence intervals of the means), below the
//! computations that fill them (`intervals`, then `summary`).
use std::collections::BTreeMap;

use serde::Serialize;

use super::regime::Regime;
use platefall_core::sim::{CaseKind, StatusKind};

/// The summary of a run as `--summary` writes it, one field per JSON key (docs/user-guide.md,
/// "The summary"); a key that does not apply is `None` (null).
#[derive(Clone, Debug, Serialize)]
pub struct Summary {
    /// Which of the four cases the run is (docs/physics.md §1).
    pub case: CaseKind,
    /// How the run ended.
    pub status: StatusKind,
    /// The Reynolds number U c/ν.
    pub re: f64,
    /// Grid cells per chord, N.
    pub resolution: usize,
    /// Cells of the grid.
    pub cells: usize,
    /// Time steps taken.
    pub steps: u64,
    /// The convective time the run reached (its end time when it completed by reaching it; the
    /// JSON key is `t_end`).
    #[serde(rename = "t_end")]
    pub t_reached: f64,
    /// Wall-clock time of the run (s), measured by the caller.
    pub wall_seconds: f64,
    /// Start of the developed part the means are taken over (c/U).
    pub developed_from: Option<f64>,
    /// End of the developed part the means are taken over (c/U).
    pub developed_to: Option<f64>,
    /// How the developed part was chosen, in words.
    pub developed_rule: String,
    /// Mean lift coefficient C_L over the developed part.
    pub mean_cl: Option<f64>,
    /// Mean drag coefficient C_D over the developed part.
    pub mean_cd: Option<f64>,
    /// Mean moment coefficient C_M (about the centre) over the developed part.
    pub mean_cm: Option<f64>,
    /// Largest C_L over the developed part.
    pub max_cl: Option<f64>,
    /// Smallest C_L over the developed part.
    pub min_cl: Option<f64>,
    /// Largest C_D over the developed part.
    pub max_cd: Option<f64>,
    /// Static case: dominant lift frequency × c/U (the Strouhal number on the chord); null when
    /// the flow is steady.
    pub strouhal_chord: Option<f64>,
    /// Static case: dominant lift frequency × the section's width across the stream / U
    /// (c|sin α| + t|cos α| for a rectangle, see [`projected_width`](crate::analysis::projected_width));
    /// null when the flow is steady.
    pub strouhal_width: Option<f64>,
    /// Static case: the reversed-flow length behind the plate at the end of the run, from its rear
    /// boundary along the relative free stream (chords; the cylinder's L/D).
    pub recirculation_length: Option<f64>,
    // Coupled and forced cases.
    /// Coupled cases: mean speed V of the plate over the developed part (units of U).
    pub mean_speed: Option<f64>,
    /// Mean pitch rate θ̇ over the developed part (units of U/c, signed).
    pub mean_omega: Option<f64>,
    /// Coupled cases: mean flight-path angle γ over the developed part (rad).
    pub mean_gamma: Option<f64>,
    /// Net revolutions of θ after release, (θ_end − θ_release)/2π, signed.
    pub revolutions: Option<f64>,
    /// Time of the first complete net turn after release (c/U), counted from any reversal.
    pub autorotation_time: Option<f64>,
    /// Coupled cases: how `autorotation_time` is defined, in words.
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
    /// What a falling (or pinned) plate is doing (flattened into the summary).
    #[serde(flatten)]
    pub fall: FallKeys,
    /// The results in physical units (flattened into the summary).
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
    /// The rule the regime was judged by, in words.
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
    /// The velocity scale U behind the conversions (m/s).
    pub velocity_scale_m_s: Option<f64>,
    /// The chord c behind the conversions (m).
    pub chord_m: Option<f64>,
    /// `mean_speed` in cm/s.
    pub mean_speed_cm_s: Option<f64>,
    /// `mean_descent_speed` in cm/s.
    pub mean_descent_speed_cm_s: Option<f64>,
    /// `mean_horizontal_speed` in cm/s.
    pub mean_horizontal_speed_cm_s: Option<f64>,
    /// `period` in seconds.
    pub period_s: Option<f64>,
    /// The inverse of `period_s` (Hz).
    pub frequency_hz: Option<f64>,
}

/// One quantity's interval as the summary states it.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct IntervalInfo {
    /// The summary's value the interval is about.
    pub value: f64,
    /// Half-width of the 95 % interval (null when there is none: see `note`).
    pub half_width: Option<f64>,
    /// What the observations are: "whole turns", "half-turns", "lift periods", "cycles of θ",
    /// "half-turn durations", "time bins", ….
    pub observations: String,
    /// How many there were.
    pub count: usize,
    /// Integrated autocorrelation time of the observations (1: independent).
    pub tau: Option<f64>,
    /// Effective number of independent observations, count / τ.
    pub n_eff: Option<f64>,
    /// Degrees of freedom of the interval's t quantile.
    pub dof: Option<f64>,
    /// The Student t quantile of the interval, t(0.975; dof).
    pub t: Option<f64>,
    /// Why there is no interval, or how it was derived.
    pub note: Option<String>,
    /// The change of the batch means over the window from their straight-line trend (slope ×
    /// (batches − 1)), and whether the slope is significant at 95 %: a significant drift means
    /// the window still holds a transient, so the mean depends on where the window starts.
    pub drift: Option<f64>,
    /// Whether the slope of `drift` is significant at 95 % (docs/statistics.md, "Drift").
    pub drift_significant: Option<bool>,
    /// The lag-1 autocorrelation of the observations. Near −1 the batch means alternate: the
    /// motion repeats every two batches (a period doubling), so the window is not a whole
    /// number of its periods and the interval is wide (conservative) rather than wrong.
    pub lag1: Option<f64>,
}

/// The interval keys of the summary (flattened into it): `<key>_ci95` is the half-width of the
/// 95 % confidence interval of `<key>`, null when the run is too short for one (`ci_note` says
/// why); `intervals` holds the details per key.
#[derive(Clone, Debug, Default, Serialize)]
pub struct IntervalKeys {
    /// The confidence level of every interval (0.95).
    pub ci_level: f64,
    /// How the intervals were made (the batches, the estimator).
    pub ci_method: Option<String>,
    /// Batches of the time means (whole turns, periods …); null for the series estimator.
    pub ci_batches: Option<usize>,
    /// Why the time means have no interval, when they have none.
    pub ci_note: Option<String>,
    /// The keys whose batch means drift significantly over the window (a transient is left in
    /// it: the mean depends on where the window starts), with the drift; null when none does.
    pub ci_drift: Option<String>,
    /// The keys whose batch means alternate (lag-1 autocorrelation below −0.5: the motion
    /// repeats every two batches), with that autocorrelation; null when none does.
    pub ci_alternating: Option<String>,
    /// 95 % half-width of `mean_cl` (docs/statistics.md); null without one.
    pub mean_cl_ci95: Option<f64>,
    /// 95 % half-width of `mean_cd` (docs/statistics.md); null without one.
    pub mean_cd_ci95: Option<f64>,
    /// 95 % half-width of `mean_cm` (docs/statistics.md); null without one.
    pub mean_cm_ci95: Option<f64>,
    /// 95 % half-width of `strouhal_chord` (docs/statistics.md); null without one.
    pub strouhal_chord_ci95: Option<f64>,
    /// 95 % half-width of `strouhal_width` (docs/statistics.md); null without one.
    pub strouhal_width_ci95: Option<f64>,
    /// 95 % half-width of `mean_speed` (docs/statistics.md); null without one.
    pub mean_speed_ci95: Option<f64>,
    /// 95 % half-width of `mean_omega` (docs/statistics.md); null without one.
    pub mean_omega_ci95: Option<f64>,
    /// 95 % half-width of `mean_gamma` (docs/statistics.md); null without one.
    pub mean_gamma_ci95: Option<f64>,
    /// 95 % half-width of `lag_cd_behind_cl` (docs/statistics.md); null without one.
    pub lag_cd_behind_cl_ci95: Option<f64>,
    /// 95 % half-width of `mean_speed_ft_s` (docs/statistics.md); null without one.
    pub mean_speed_ft_s_ci95: Option<f64>,
    /// 95 % half-width of `mean_omega_rad_s` (docs/statistics.md); null without one.
    pub mean_omega_rad_s_ci95: Option<f64>,
    /// 95 % half-width of `mean_descent_speed` (docs/statistics.md); null without one.
    pub mean_descent_speed_ci95: Option<f64>,
    /// 95 % half-width of `mean_horizontal_speed` (docs/statistics.md); null without one.
    pub mean_horizontal_speed_ci95: Option<f64>,
    /// 95 % half-width of `descent_angle` (docs/statistics.md); null without one.
    pub descent_angle_ci95: Option<f64>,
    /// 95 % half-width of `period` (docs/statistics.md); null without one.
    pub period_ci95: Option<f64>,
    /// Mean over the oscillations of θ of half their peak-to-peak range (rad; no full turns);
    /// `angle_amplitude` is the half range over the whole window.
    pub mean_cycle_amplitude: Option<f64>,
    /// 95 % half-width of `mean_cycle_amplitude` (docs/statistics.md); null without one.
    pub mean_cycle_amplitude_ci95: Option<f64>,
    /// 95 % half-width of `mean_speed_cm_s` (docs/statistics.md); null without one.
    pub mean_speed_cm_s_ci95: Option<f64>,
    /// 95 % half-width of `mean_descent_speed_cm_s` (docs/statistics.md); null without one.
    pub mean_descent_speed_cm_s_ci95: Option<f64>,
    /// 95 % half-width of `mean_horizontal_speed_cm_s` (docs/statistics.md); null without one.
    pub mean_horizontal_speed_cm_s_ci95: Option<f64>,
    /// 95 % half-width of `period_s` (docs/statistics.md); null without one.
    pub period_s_ci95: Option<f64>,
    /// 95 % half-width of `frequency_hz` (docs/statistics.md); null without one.
    pub frequency_hz_ci95: Option<f64>,
    /// Per key: the observations, τ, n_eff, the t quantile, or why there is no interval.
    pub intervals: BTreeMap<String, IntervalInfo>,
}
