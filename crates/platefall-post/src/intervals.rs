//! The 95 % confidence interval of every mean in the summary, from the run's own time series
//! (the statistics are in [`crate::stats`]; this module chooses the batches of a run).
//!
//! The developed window of a run is cut at the boundaries of its natural cycles, and the time
//! means of each quantity over those batches are the observations of a batch-means interval:
//!
//! | run | batches |
//! |---|---|
//! | pinned or free, full turns in both senses (chaotic) | none: the series estimator below, over the regime window |
//! | pinned or free, two or more whole turns | the whole turns of the developed window (it runs from one turn's completion to another's) |
//! | pinned or free, oscillating without turns | the cycles of θ between up-crossings of its midpoint (the regime rule's) |
//! | forced | the half-turns of the developed window |
//! | static, shedding | the lift periods 1/f of the developed window (it holds a whole number of them) |
//! | steady, or no cycles | none: the integrated autocorrelation time of the series, in 2000 equal time bins |
//!
//! The time means come from the history's exact running integrals ([`History::mean`]), so every
//! step counts with its own duration. Quantities that are not time means get their own
//! observations: the period from the durations of the cycles (half-turns, oscillations) of the
//! regime window, the lag of the drag peak from its value per half-turn, the angle amplitude from
//! each oscillation's half range (`mean_cycle_amplitude`), the Strouhal number from the durations
//! of the lift cycles (its relative half-width), and the descent angle, a function of two means,
//! by linearising it about the means for each batch (the delta method).
use std::collections::BTreeMap;
use std::f64::consts::PI;

use serde::Serialize;

use super::analysis::{count_turns, TimeWindow};
use super::regime::{cycle_events, rising_crossings, MotionClass, Regime, CROSSING_HYSTERESIS};
use super::stats::{
    autocovariance, batch_interval, series_interval, trend, Interval, NoInterval, LEVEL,
    MIN_BATCHES,
};
use super::summary::Summary;
use platefall_core::config::{physical, Units};
use platefall_core::sim::{Case, History, Quantity, RunConfig, RunRecord, StepSample};

/// Equal time bins of a window without natural cycles (the series estimator's samples).
pub const SERIES_BINS: usize = 2000;

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
    /// Degrees of freedom and the t quantile of the interval.
    pub dof: Option<f64>,
    pub t: Option<f64>,
    /// Why there is no interval, or how it was derived.
    pub note: Option<String>,
    /// The change of the batch means over the window from their straight-line trend (slope ×
    /// (batches − 1)), and whether the slope is significant at 95 %: a significant drift means
    /// the window still holds a transient, so the mean depends on where the window starts.
    pub drift: Option<f64>,
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
    pub mean_cl_ci95: Option<f64>,
    pub mean_cd_ci95: Option<f64>,
    pub mean_cm_ci95: Option<f64>,
    pub strouhal_chord_ci95: Option<f64>,
    pub strouhal_width_ci95: Option<f64>,
    pub mean_speed_ci95: Option<f64>,
    pub mean_omega_ci95: Option<f64>,
    pub mean_gamma_ci95: Option<f64>,
    pub lag_cd_behind_cl_ci95: Option<f64>,
    pub mean_speed_ft_s_ci95: Option<f64>,
    pub mean_omega_rad_s_ci95: Option<f64>,
    pub mean_descent_speed_ci95: Option<f64>,
    pub mean_horizontal_speed_ci95: Option<f64>,
    pub descent_angle_ci95: Option<f64>,
    pub period_ci95: Option<f64>,
    /// Mean over the oscillations of θ of half their peak-to-peak range (rad; no full turns);
    /// `angle_amplitude` is the half range over the whole window.
    pub mean_cycle_amplitude: Option<f64>,
    pub mean_cycle_amplitude_ci95: Option<f64>,
    pub mean_speed_cm_s_ci95: Option<f64>,
    pub mean_descent_speed_cm_s_ci95: Option<f64>,
    pub mean_horizontal_speed_cm_s_ci95: Option<f64>,
    pub period_s_ci95: Option<f64>,
    pub frequency_hz_ci95: Option<f64>,
    /// Per key: the observations, τ, n_eff, the t quantile, or why there is no interval.
    pub intervals: BTreeMap<String, IntervalInfo>,
}

/// How the developed window is cut.
enum Cut {
    /// Batch boundaries (increasing), and what each batch is.
    Batches(Vec<f64>, &'static str),
    /// No natural cycles: the window as an evenly binned series.
    Series(TimeWindow),
}

/// The batch boundaries of the developed window `w` (see the module docs).
fn cut(
    config: &RunConfig,
    rec: &RunRecord,
    w: TimeWindow,
    freq: Option<f64>,
    motion: Option<&(TimeWindow, MotionClass)>,
) -> Cut {
    let even = |step: f64, what| {
        let n = ((w.t1 - w.t0) / step + 1e-6).floor() as usize;
        Cut::Batches((0..=n).map(|k| w.t0 + k as f64 * step).collect(), what)
    };
    match &config.case {
        Case::Static { .. } => match freq {
            Some(f) if f > 0.0 => even(1.0 / f, "lift periods"),
            _ => Cut::Series(w),
        },
        Case::Forced { omega, .. } => even(PI / omega.abs(), "half-turns"),
        Case::Pinned { .. } | Case::Free { .. } => {
            if motion.is_some_and(|(_, class)| class.turns_both_ways()) {
                return Cut::Series(w);
            }
            let inside = |t: &f64| *t >= w.t0 - 1e-9 && *t <= w.t1 + 1e-9;
            let turns: Vec<f64> = count_turns(&rec.samples, rec.t_release)
                .completed
                .into_iter()
                .filter(inside)
                .collect();
            if turns.len() >= 2 {
                return Cut::Batches(turns, "whole turns");
            }
            match motion {
                Some((rw, class)) if class.regime != Regime::Steady => {
                    let events: Vec<f64> = cycle_events(&rec.samples, *rw, class)
                        .into_iter()
                        .filter(inside)
                        .collect();
                    if events.len() >= 2 && class.turns == (0, 0) {
                        Cut::Batches(events, "cycles of θ")
                    } else {
                        Cut::Series(w)
                    }
                }
                _ => Cut::Series(w),
            }
        }
    }
}

/// The time means of `q` over the batches between successive `edges`, with their durations.
fn batch_means(h: &History, q: Quantity, edges: &[f64]) -> Vec<(f64, f64)> {
    edges
        .windows(2)
        .filter_map(|e| h.mean(q, e[0], e[1]).map(|m| (e[1] - e[0], m)))
        .collect()
}

/// The samples of a series estimator: the time means of `q` over equal bins of `w`.
fn series_bins(h: &History, q: Quantity, w: TimeWindow) -> Vec<f64> {
    let retained = h.iter().filter(|s| s.t >= w.t0 && s.t <= w.t1).count();
    let bins = SERIES_BINS.min(retained.saturating_sub(1) / 2);
    if bins < 2 {
        return Vec::new();
    }
    let width = (w.t1 - w.t0) / bins as f64;
    (0..bins)
        .filter_map(|k| h.mean(q, w.t0 + k as f64 * width, w.t0 + (k + 1) as f64 * width))
        .collect()
}

/// An interval about `value` from a stats result; None and the reason when there is none.
fn info(
    value: f64,
    r: Result<Interval, NoInterval>,
    observations: &str,
    count: usize,
) -> IntervalInfo {
    match r {
        Ok(i) => IntervalInfo {
            value,
            half_width: Some(i.half_width),
            observations: observations.into(),
            count: i.samples,
            tau: Some(i.tau),
            n_eff: Some(i.n_eff),
            dof: Some(i.dof),
            t: Some(i.t),
            note: None,
            ..IntervalInfo::default()
        },
        Err(why) => IntervalInfo {
            value,
            observations: observations.into(),
            count,
            note: Some(format!("too short for a 95 % interval: {why}")),
            ..IntervalInfo::default()
        },
    }
}

/// The intervals of the time means, from batches or from the binned series.
struct TimeMeans<'a> {
    h: &'a History,
    cut: Cut,
}

impl TimeMeans<'_> {
    fn interval(&self, q: Quantity, sign: f64, value: f64) -> IntervalInfo {
        match &self.cut {
            Cut::Batches(edges, what) => {
                let b: Vec<(f64, f64)> = batch_means(self.h, q, edges)
                    .into_iter()
                    .map(|(w, m)| (w, sign * m))
                    .collect();
                with_drift(info(value, batch_interval(&b), what, b.len()), &b)
            }
            Cut::Series(w) => {
                let x: Vec<f64> = series_bins(self.h, q, *w)
                    .into_iter()
                    .map(|m| sign * m)
                    .collect();
                info(value, series_interval(&x), "time bins", x.len())
            }
        }
    }

    /// The descent angle atan2(d, |h|) of the mean descent d and drift h, linearised about the
    /// means for each batch (or bin).
    fn descent_angle(&self, angle: f64, d: f64, drift: f64) -> IntervalInfo {
        let r2 = d * d + drift * drift;
        if r2 == 0.0 {
            return IntervalInfo {
                value: angle,
                note: Some("no mean motion".into()),
                ..IntervalInfo::default()
            };
        }
        let (gd, gh) = (drift.abs() / r2, -drift.signum() * d / r2);
        let lin = |dy: f64, dx: f64| angle + gd * (-dy - d) + gh * (dx - drift);
        let mut out = match &self.cut {
            Cut::Batches(edges, what) => {
                let ys = batch_means(self.h, Quantity::Ydot, edges);
                let xs = batch_means(self.h, Quantity::Xdot, edges);
                let b: Vec<(f64, f64)> = ys
                    .iter()
                    .zip(&xs)
                    .map(|(y, x)| (y.0, lin(y.1, x.1)))
                    .collect();
                info(angle, batch_interval(&b), what, b.len())
            }
            Cut::Series(w) => {
                let ys = series_bins(self.h, Quantity::Ydot, *w);
                let xs = series_bins(self.h, Quantity::Xdot, *w);
                let x: Vec<f64> = ys.iter().zip(&xs).map(|(y, x)| lin(*y, *x)).collect();
                info(angle, series_interval(&x), "time bins", x.len())
            }
        };
        out.note = out
            .note
            .or(Some("delta method on the descent and drift".into()));
        out
    }
}

/// Adds the straight-line drift of the batch means.
fn with_drift(mut i: IntervalInfo, batches: &[(f64, f64)]) -> IntervalInfo {
    let values: Vec<f64> = batches.iter().map(|b| b.1).collect();
    if let Some(t) = trend(&values) {
        i.drift = Some(t.slope * (values.len() as f64 - 1.0));
        i.drift_significant = Some(t.significant);
    }
    let g = autocovariance(&values, 1);
    if g.len() == 2 && g[0] > 0.0 {
        i.lag1 = Some(g[1] / g[0]);
    }
    i
}

/// Equal-weight interval of a list of observations (durations, lags, amplitudes).
fn list_interval(value: f64, xs: &[f64], what: &str, scale: f64) -> IntervalInfo {
    let b: Vec<(f64, f64)> = xs.iter().map(|x| (1.0, scale * x)).collect();
    info(value, batch_interval(&b), what, b.len())
}

/// Half of each oscillation's peak-to-peak range of θ between successive `events`.
fn cycle_amplitudes(samples: &[StepSample], events: &[f64]) -> Vec<f64> {
    events
        .windows(2)
        .filter_map(|e| {
            let (lo, hi) = samples
                .iter()
                .filter(|s| s.t >= e[0] && s.t <= e[1])
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), s| {
                    (a.min(s.theta), b.max(s.theta))
                });
            (hi >= lo).then_some(0.5 * (hi - lo))
        })
        .collect()
}

/// Durations of the lift cycles inside `w` (up-crossings of C_L's midpoint, hysteresis as for θ).
fn lift_periods(samples: &[StepSample], w: TimeWindow) -> Vec<f64> {
    let pts: Vec<(f64, f64)> = samples
        .iter()
        .filter(|s| s.t >= w.t0 && s.t <= w.t1)
        .map(|s| (s.t, s.cl))
        .collect();
    let (lo, hi) = pts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.1), b.max(p.1))
        });
    if pts.len() < 4 || hi <= lo {
        return Vec::new();
    }
    let up = rising_crossings(&pts, 0.5 * (lo + hi), CROSSING_HYSTERESIS * 0.5 * (hi - lo));
    up.windows(2).map(|e| e[1] - e[0]).collect()
}

/// Sets `<key>_ci95` and the details of one key (None leaves both unset).
fn put(
    keys: &mut IntervalKeys,
    name: &str,
    slot: fn(&mut IntervalKeys) -> &mut Option<f64>,
    i: Option<IntervalInfo>,
) {
    if let Some(i) = i {
        *slot(keys) = i.half_width;
        keys.intervals.insert(name.into(), i);
    }
}

/// A linear conversion of another key's interval (physical units): the same observations, the
/// half-width converted.
fn converted(base: Option<&IntervalInfo>, value: Option<f64>, conv: f64) -> Option<IntervalInfo> {
    let (b, v) = (base?, value?);
    Some(IntervalInfo {
        value: v,
        half_width: b.half_width.map(|hw| hw * conv.abs()),
        note: Some(match &b.note {
            Some(n) => n.clone(),
            None => "converted from the non-dimensional interval".into(),
        }),
        ..b.clone()
    })
}

/// The intervals of every mean in `sum` (computed by `summarize` from the same window, lift
/// frequency and motion class).
pub fn intervals_of(
    config: &RunConfig,
    rec: &RunRecord,
    sum: &Summary,
    freq: Option<f64>,
    motion: Option<&(TimeWindow, MotionClass)>,
) -> IntervalKeys {
    let mut keys = IntervalKeys {
        ci_level: LEVEL,
        ..IntervalKeys::default()
    };
    let (Some(t0), Some(t1)) = (sum.developed_from, sum.developed_to) else {
        keys.ci_note = Some("no developed part: no intervals".into());
        return keys;
    };
    let w = TimeWindow { t0, t1 };
    let h = &rec.samples;
    let means = TimeMeans {
        h,
        cut: cut(config, rec, w, freq, motion),
    };
    keys.ci_method = Some(match &means.cut {
        Cut::Batches(edges, what) => {
            let n = edges.len().saturating_sub(1);
            keys.ci_batches = Some(n);
            if n < MIN_BATCHES {
                keys.ci_note = Some(format!(
                    "too short for 95 % intervals of the means: {n} {what} in the developed part, \
                     {MIN_BATCHES} needed"
                ));
            }
            format!(
                "batch means over {n} {what} of the developed part; Student t with n_eff = \
                 batches / τ (τ of the batch means, Geyer's initial monotone sequence, ≥ 1)"
            )
        }
        Cut::Series(_) => {
            "no cycles to batch: integrated autocorrelation time τ of the series in equal \
                           time bins (Sokal's window, c = 5), n_eff = bins / τ, Student t"
                .to_string()
        }
    });
    let time_mean = |q: Quantity, sign: f64, v: Option<f64>| v.map(|v| means.interval(q, sign, v));
    put(
        &mut keys,
        "mean_cl",
        |k| &mut k.mean_cl_ci95,
        time_mean(Quantity::Cl, 1.0, sum.mean_cl),
    );
    put(
        &mut keys,
        "mean_cd",
        |k| &mut k.mean_cd_ci95,
        time_mean(Quantity::Cd, 1.0, sum.mean_cd),
    );
    put(
        &mut keys,
        "mean_cm",
        |k| &mut k.mean_cm_ci95,
        time_mean(Quantity::Cm, 1.0, sum.mean_cm),
    );
    let speed = time_mean(Quantity::Speed, 1.0, sum.mean_speed);
    let omega = time_mean(Quantity::Omega, 1.0, sum.mean_omega);
    put(
        &mut keys,
        "mean_speed",
        |k| &mut k.mean_speed_ci95,
        speed.clone(),
    );
    put(
        &mut keys,
        "mean_omega",
        |k| &mut k.mean_omega_ci95,
        omega.clone(),
    );
    put(
        &mut keys,
        "mean_gamma",
        |k| &mut k.mean_gamma_ci95,
        time_mean(Quantity::Gamma, 1.0, sum.mean_gamma),
    );
    let descent = time_mean(Quantity::Ydot, -1.0, sum.fall.mean_descent_speed);
    let drift = time_mean(Quantity::Xdot, 1.0, sum.fall.mean_horizontal_speed);
    put(
        &mut keys,
        "mean_descent_speed",
        |k| &mut k.mean_descent_speed_ci95,
        descent.clone(),
    );
    put(
        &mut keys,
        "mean_horizontal_speed",
        |k| &mut k.mean_horizontal_speed_ci95,
        drift.clone(),
    );
    if let (Some(a), Some(d), Some(x)) = (
        sum.fall.descent_angle,
        sum.fall.mean_descent_speed,
        sum.fall.mean_horizontal_speed,
    ) {
        let i = means.descent_angle(a, d, x);
        put(
            &mut keys,
            "descent_angle",
            |k| &mut k.descent_angle_ci95,
            Some(i),
        );
    }
    // The lag of the drag peak: one value per half-turn.
    if let Some(lag) = sum.lag_cd_behind_cl {
        let lags = super::summary::lags_cd_behind_cl(&rec.samples, w);
        let b: Vec<(f64, f64)> = lags.iter().map(|x| (1.0, *x)).collect();
        let i = with_drift(list_interval(lag, &lags, "half-turns", 1.0), &b);
        put(
            &mut keys,
            "lag_cd_behind_cl",
            |k| &mut k.lag_cd_behind_cl_ci95,
            Some(i),
        );
    }
    // The Strouhal numbers: the relative half-width of the mean lift period.
    if let (Some(st), Case::Static { alpha, .. }) = (sum.strouhal_chord, &config.case) {
        let periods = lift_periods(&rec.samples, w);
        let mean_p = periods.iter().sum::<f64>() / periods.len().max(1) as f64;
        let mut i = list_interval(st, &periods, "lift cycles", 1.0);
        i.half_width = i.half_width.map(|hw| st * hw / mean_p);
        i.note = i.note.or(Some(
            "relative half-width of the mean duration of the lift cycles".into(),
        ));
        let mut iw = i.clone();
        let width = crate::summary::projected_width(config, *alpha);
        iw.value = st * width;
        iw.half_width = i.half_width.map(|hw| hw * width);
        put(
            &mut keys,
            "strouhal_chord",
            |k| &mut k.strouhal_chord_ci95,
            Some(i),
        );
        put(
            &mut keys,
            "strouhal_width",
            |k| &mut k.strouhal_width_ci95,
            Some(iw),
        );
    }
    // The period and amplitude of the motion: its cycles over the regime window.
    let mut period = None;
    if let (Some(p), Some((rw, class))) = (sum.fall.period, motion) {
        let events = cycle_events(&rec.samples, *rw, class);
        let durations: Vec<f64> = events.windows(2).map(|e| e[1] - e[0]).collect();
        let (what, per) = if class.turns == (0, 0) {
            ("oscillation durations", 1.0)
        } else {
            ("half-turn durations", 2.0)
        };
        let b: Vec<(f64, f64)> = durations.iter().map(|x| (1.0, per * x)).collect();
        let i = with_drift(list_interval(p, &durations, what, per), &b);
        period = Some(i.clone());
        put(&mut keys, "period", |k| &mut k.period_ci95, Some(i));
        if class.turns == (0, 0) {
            let amps = cycle_amplitudes(&rec.samples, &events);
            if !amps.is_empty() {
                let mean = amps.iter().sum::<f64>() / amps.len() as f64;
                keys.mean_cycle_amplitude = Some(mean);
                let i = list_interval(mean, &amps, "oscillations", 1.0);
                put(
                    &mut keys,
                    "mean_cycle_amplitude",
                    |k| &mut k.mean_cycle_amplitude_ci95,
                    Some(i),
                );
            }
        }
    }
    // Physical units: the same intervals, converted.
    if let Some(card) = physical(config) {
        let i = converted(speed.as_ref(), sum.mean_speed_ft_s, card.speed_to_ft_s(1.0));
        put(
            &mut keys,
            "mean_speed_ft_s",
            |k| &mut k.mean_speed_ft_s_ci95,
            i,
        );
    }
    if let Some(u) = Units::of(config) {
        let i = converted(omega.as_ref(), sum.mean_omega_rad_s, u.rate_rad_s(1.0));
        put(
            &mut keys,
            "mean_omega_rad_s",
            |k| &mut k.mean_omega_rad_s_ci95,
            i,
        );
        let p = &sum.physical;
        let cm = u.speed_cm_s(1.0);
        let i = converted(speed.as_ref(), p.mean_speed_cm_s, cm);
        put(
            &mut keys,
            "mean_speed_cm_s",
            |k| &mut k.mean_speed_cm_s_ci95,
            i,
        );
        let i = converted(descent.as_ref(), p.mean_descent_speed_cm_s, cm);
        put(
            &mut keys,
            "mean_descent_speed_cm_s",
            |k| &mut k.mean_descent_speed_cm_s_ci95,
            i,
        );
        let i = converted(drift.as_ref(), p.mean_horizontal_speed_cm_s, cm);
        put(
            &mut keys,
            "mean_horizontal_speed_cm_s",
            |k| &mut k.mean_horizontal_speed_cm_s_ci95,
            i,
        );
        let ps = converted(period.as_ref(), p.period_s, u.time_s(1.0));
        if let (Some(ps), Some(f)) = (&ps, p.frequency_hz) {
            // f = 1/P: the half-width of P divided by P² (the delta method).
            let mut i = ps.clone();
            i.value = f;
            i.half_width = ps.half_width.map(|hw| hw * f * f);
            put(
                &mut keys,
                "frequency_hz",
                |k| &mut k.frequency_hz_ci95,
                Some(i),
            );
        }
        put(&mut keys, "period_s", |k| &mut k.period_s_ci95, ps);
    }
    keys.ci_drift = drift_line(&keys.intervals);
    keys.ci_alternating = alternation_line(&keys.intervals);
    keys
}

/// Lag-1 autocorrelation below which the batch means count as alternating.
pub const ALTERNATING: f64 = -0.5;

/// "mean_cl −0.99, mean_cd −0.98" for the keys whose batch means alternate.
fn alternation_line(intervals: &BTreeMap<String, IntervalInfo>) -> Option<String> {
    let parts: Vec<String> = intervals
        .iter()
        .filter(|(_, i)| {
            i.half_width.is_some()
                && !i
                    .note
                    .as_deref()
                    .is_some_and(|n| n.starts_with("converted"))
        })
        .filter_map(|(k, i)| {
            let r = i.lag1?;
            (r < ALTERNATING).then(|| format!("{k} {r:.2}"))
        })
        .collect();
    (!parts.is_empty()).then(|| parts.join(", "))
}

/// "mean_omega +0.7712, mean_speed +0.05, mean_cm -2.100e-5" (four significant digits) for the keys whose batch means drift significantly.
fn drift_line(intervals: &BTreeMap<String, IntervalInfo>) -> Option<String> {
    let parts: Vec<String> = intervals
        .iter()
        .filter(|(_, i)| {
            i.drift_significant == Some(true)
                && i.note.as_deref() != Some("converted from the non-dimensional interval")
        })
        .filter_map(|(k, i)| {
            let d = i.drift?;
            let sign = if d > 0.0 { "+" } else { "" };
            Some(format!("{k} {sign}{}", platefall_core::param::rounded(d)))
        })
        .collect();
    (!parts.is_empty()).then(|| parts.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::summary::summarize;
    use platefall_core::grid::GridSpec;
    use platefall_core::sim::RunStatus;

    fn free() -> RunConfig {
        let case = Case::Free {
            v0: 1.0,
            gamma0: -0.5,
            alpha0: 0.1,
            develop: 0.0,
        };
        RunConfig::new(case, GridSpec::seed())
    }

    fn record(samples: Vec<StepSample>) -> RunRecord {
        RunRecord {
            status: RunStatus::Completed,
            samples: samples.into_iter().collect(),
            t_release: 0.0,
            cells: 1,
            recirculation_length: None,
        }
    }

    /// A plate turning at θ̇ = rate(θ), stepped with an uneven time step; C_L follows the angle.
    fn tumbling(rate: impl Fn(f64, usize) -> f64, turns: f64) -> Vec<StepSample> {
        let (mut t, mut th) = (0.0, 0.0);
        let mut out = Vec::new();
        let mut k = 0;
        while th < turns * 2.0 * PI {
            let turn = (th / (2.0 * PI)) as usize;
            let om = rate(th, turn);
            out.push(StepSample {
                step: k,
                t,
                theta: th,
                omega: om,
                cl: (2.0 * th).sin(),
                speed: 1.0 + 0.1 * (2.0 * th).cos(),
                ydot: -0.5,
                xdot: 0.8,
                ..Default::default()
            });
            let dt = 2e-3 * (1.0 + 0.3 * ((k as f64) * 0.7).sin());
            t += dt;
            th += om * dt;
            k += 1;
        }
        out
    }

    #[test]
    fn a_periodic_tumble_has_a_near_zero_interval_over_its_whole_turns() {
        // θ̇ = 2.5 + 0.4 sin 2θ: every turn is the same, so every whole-turn batch has the same
        // mean; only the step's discreteness is left.
        let cfg = free();
        let rec = record(tumbling(|th, _| 2.5 + 0.4 * (2.0 * th).sin(), 12.0));
        let s = summarize(&cfg, &rec, 0.0);
        assert_eq!(s.ci.ci_batches, Some(10), "{:?}", s.ci.ci_method);
        let hw = s.ci.mean_omega_ci95.unwrap();
        assert!(hw < 2e-3, "half-width {hw}");
        assert!(s.ci.mean_cl_ci95.unwrap() < 2e-3);
        let i = &s.ci.intervals["mean_omega"];
        assert_eq!(i.observations, "whole turns");
        assert_eq!(i.count, 10);
    }

    #[test]
    fn a_plate_turning_both_ways_is_averaged_over_time_in_the_regime_window() {
        // θ swings 1.5 turns each way (period 10) while drifting forward, so it completes net
        // turns, but the turns of either sense are not cycles of the motion; the descent slows from 1 to 0.5 ± 0.1 (period 0.5) half-way through.
        let (dt, t_end) = (1e-2, 200.0);
        let samples = (0..=(t_end / dt) as usize)
            .map(|k| {
                let t = k as f64 * dt;
                let descent = if t < 100.0 {
                    1.0
                } else {
                    0.5 + 0.1 * (4.0 * PI * t).sin()
                };
                StepSample {
                    step: k as u64,
                    t,
                    dt,
                    theta: 3.0 * PI * (0.2 * PI * t).sin() + 0.3 * t,
                    ydot: -descent,
                    speed: descent,
                    ..Default::default()
                }
            })
            .collect();
        let s = summarize(&free(), &record(samples), 0.0);
        assert!(
            s.developed_rule.contains("not whole turns"),
            "{}",
            s.developed_rule
        );
        assert_eq!((s.autorotation_time, s.lag_cd_behind_cl), (None, None));
        assert_eq!(
            (s.developed_from, s.developed_to),
            (Some(100.0), Some(t_end))
        );
        let descent = s.fall.mean_descent_speed.unwrap();
        assert!((descent - 0.5).abs() < 1e-3, "mean descent {descent}");
        assert_eq!(s.ci.ci_batches, None, "{:?}", s.ci.ci_method);
        let i = &s.ci.intervals["mean_descent_speed"];
        assert_eq!(i.observations, "time bins", "{i:?}");
        let hw = i.half_width.unwrap();
        assert!(hw < 0.02 && (descent - 0.5).abs() <= hw, "{descent} ± {hw}");
    }

    #[test]
    fn turns_of_random_rates_give_the_t_interval_of_the_turn_means() {
        // Each turn at its own constant rate, drawn from a fixed list: the batch means are the
        // turn means, so the interval is the Student t interval of the per-turn time means.
        let rates = [
            2.4, 2.7, 2.5, 2.9, 2.3, 2.6, 2.8, 2.45, 2.65, 2.55, 2.75, 2.35, 2.6,
        ];
        let cfg = free();
        let rec = record(tumbling(|_, turn| rates[turn.min(rates.len() - 1)], 13.0));
        let s = summarize(&cfg, &rec, 0.0);
        let i = &s.ci.intervals["mean_omega"];
        assert_eq!(i.count, 11, "{i:?}");
        // Turns 2..=12 completed after the first: the batch rates are rates[1..12] (the step
        // that crosses a turn boundary blurs each batch by one step: < 1e-3).
        let b = &rates[1..12];
        let dur: Vec<f64> = b.iter().map(|r| 2.0 * PI / r).collect();
        let total: f64 = dur.iter().sum();
        let mean = 2.0 * PI * b.len() as f64 / total;
        let n = b.len() as f64;
        let var = n / (n - 1.0)
            * b.iter()
                .zip(&dur)
                .map(|(r, d)| (d / total).powi(2) * (r - mean).powi(2))
                .sum::<f64>();
        let tau = i.tau.unwrap();
        assert!(tau >= 1.0);
        let expect = crate::stats::t95(n / tau - 1.0) * (tau * var).sqrt();
        assert!(
            (i.half_width.unwrap() - expect).abs() < 0.05 * expect,
            "{i:?} vs {expect}"
        );
        assert!((s.mean_omega.unwrap() - mean).abs() < 2e-3);
    }

    #[test]
    fn a_rate_that_still_settles_is_flagged_as_drifting() {
        // θ̇ rising from 2.7 towards 3.5 over the turns, like a coarse card's first 20 turns.
        let cfg = free();
        let rec = record(tumbling(
            |_, turn| 3.5 - 0.8 * (-(turn as f64) / 5.0).exp(),
            20.0,
        ));
        let s = summarize(&cfg, &rec, 0.0);
        let i = &s.ci.intervals["mean_omega"];
        assert_eq!(i.drift_significant, Some(true), "{i:?}");
        assert!(i.drift.unwrap() > 0.3, "{i:?}");
        assert!(s.ci.ci_drift.as_deref().unwrap().contains("mean_omega"));
        assert!(crate::report::report(&cfg, &s).contains("drift"));
        // A periodic tumble does not drift.
        let rec = record(tumbling(|th, _| 2.5 + 0.4 * (2.0 * th).sin(), 12.0));
        let s = summarize(&cfg, &rec, 0.0);
        assert_eq!(s.ci.intervals["mean_omega"].drift_significant, Some(false));
    }

    #[test]
    fn averaging_from_a_later_turn_leaves_the_transient_out() {
        // Turns 0..10 at 2.0, then 3.0 for 20 turns: from the first turn the mean mixes both and
        // drifts; from turn 10 on it is the settled 3.0 alone, over the 19 whole turns after it.
        let mut cfg = free();
        let rate = |_: f64, turn: usize| if turn < 10 { 2.0 } else { 3.0 };
        let rec = record(tumbling(rate, 30.0));
        let all = summarize(&cfg, &rec, 0.0);
        assert!(all.mean_omega.unwrap() < 2.8, "{:?}", all.mean_omega);
        cfg.time.average_from_turn = 10;
        let s = summarize(&cfg, &rec, 0.0);
        assert!(
            (s.mean_omega.unwrap() - 3.0).abs() < 1e-3,
            "{:?}",
            s.mean_omega
        );
        assert!(
            (s.developed_from.unwrap() - 10.0 * PI).abs() < 0.01,
            "{s:?}"
        );
        assert_eq!(s.ci.intervals["mean_omega"].count, 19);
        assert_eq!(s.ci.intervals["mean_omega"].drift_significant, Some(false));
        assert!(s.developed_rule.contains("turn 10"), "{}", s.developed_rule);
    }

    #[test]
    fn turns_that_alternate_are_flagged() {
        // Odd and even turns at two rates (a period-two tumble).
        let cfg = free();
        let rec = record(tumbling(
            |_, turn| if turn % 2 == 0 { 2.4 } else { 2.8 },
            16.0,
        ));
        let s = summarize(&cfg, &rec, 0.0);
        let i = &s.ci.intervals["mean_omega"];
        assert!(i.lag1.unwrap() < -0.8, "{i:?}");
        assert!(s
            .ci
            .ci_alternating
            .as_deref()
            .unwrap()
            .contains("mean_omega"));
        assert!(crate::report::report(&cfg, &s).contains("alternate"));
    }

    #[test]
    fn a_run_of_three_turns_says_it_is_too_short() {
        let cfg = free();
        let rec = record(tumbling(|_, _| 2.5, 3.5));
        let s = summarize(&cfg, &rec, 0.0);
        assert_eq!(s.ci.ci_batches, Some(2));
        assert!(s.ci.mean_omega_ci95.is_none());
        let note = s.ci.ci_note.as_deref().unwrap();
        assert!(
            note.contains("too short") && note.contains("2 whole turns"),
            "{note}"
        );
        assert!(s.ci.intervals["mean_omega"].note.is_some());
        // The report says so too, and the JSON keeps the key with a null.
        let json = serde_json::to_value(&s).unwrap();
        assert!(json["mean_omega_ci95"].is_null() && json["ci_level"] == 0.95);
        assert!(crate::report::report(&cfg, &s).contains("too short"));
    }

    #[test]
    fn the_report_shows_value_plus_minus_half_width() {
        let rates = [
            2.4, 2.7, 2.5, 2.9, 2.3, 2.6, 2.8, 2.45, 2.65, 2.55, 2.75, 2.35, 2.6,
        ];
        let cfg = free();
        let rec = record(tumbling(|_, turn| rates[turn.min(rates.len() - 1)], 13.0));
        let s = summarize(&cfg, &rec, 0.0);
        let text = crate::report::report(&cfg, &s);
        let hw = s.ci.mean_omega_ci95.unwrap();
        let shown = crate::report::pm(s.mean_omega, Some(hw), 3);
        assert!(
            shown.contains(" ± ") && text.contains(&shown),
            "{shown} in {text}"
        );
        assert!(text.contains("95 % confidence half-width"), "{text}");
    }
}
