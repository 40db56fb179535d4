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

use super::analysis::{count_turns, lags_cd_behind_cl, projected_width, TimeWindow};
use super::keys::Summary;
pub use super::keys::{IntervalInfo, IntervalKeys};
use super::regime::{cycle_events, rising_crossings, MotionClass, Regime, CROSSING_HYSTERESIS};
use super::stats::{
    autocovariance, batch_interval, series_interval, trend, Interval, NoInterval, LEVEL,
    MIN_BATCHES,
};
use platefall_core::config::{physical, Units};
use platefall_core::sim::{Case, History, Quantity, RunConfig, RunRecord, StepSample};

/// Equal time bins of a window without natural cycles (the series estimator's samples).
pub const SERIES_BINS: usize = 2000;

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

/// How the interval of a key is made.
#[derive(Clone, Copy)]
enum Rule {
    /// The time mean of a quantity (times a sign) over the batches or bins.
    TimeMean(Quantity, f64),
    /// The descent angle, linearised about the mean descent and drift for each batch.
    DescentAngle,
    /// The lag of the drag peak: its value in each half-turn.
    Lag,
    /// The Strouhal number on the chord: the relative half-width of the mean lift period.
    Strouhal,
    /// The Strouhal number on the width: the chord's interval times the projected width.
    StrouhalWidth,
    /// The period of the motion: the durations of its cycles over the regime window.
    Period,
    /// The mean half range of θ per oscillation (no full turns); the key's value is computed
    /// here, not read from the summary.
    CycleAmplitude,
    /// The named key's interval in physical units, with the factor of the run's units (none
    /// when the plate has no physical scales).
    Converted(&'static str, fn(&RunConfig) -> Option<f64>),
    /// The frequency 1/P of the named period key: the half-width of P divided by P² (the delta
    /// method).
    Reciprocal(&'static str),
}

/// A key of the summary with an interval: its name, its `<key>_ci95` slot, its value in the
/// summary and the rule of its interval.
struct Key {
    name: &'static str,
    slot: fn(&mut IntervalKeys) -> &mut Option<f64>,
    value: fn(&Summary) -> Option<f64>,
    rule: Rule,
}

/// Every key with an interval, each after the keys its rule reads.
#[rustfmt::skip]
const KEYS: &[Key] = &[
    Key { name: "mean_cl", slot: |k| &mut k.mean_cl_ci95, value: |s| s.mean_cl, rule: Rule::TimeMean(Quantity::Cl, 1.0) },
    Key { name: "mean_cd", slot: |k| &mut k.mean_cd_ci95, value: |s| s.mean_cd, rule: Rule::TimeMean(Quantity::Cd, 1.0) },
    Key { name: "mean_cm", slot: |k| &mut k.mean_cm_ci95, value: |s| s.mean_cm, rule: Rule::TimeMean(Quantity::Cm, 1.0) },
    Key { name: "mean_speed", slot: |k| &mut k.mean_speed_ci95, value: |s| s.mean_speed, rule: Rule::TimeMean(Quantity::Speed, 1.0) },
    Key { name: "mean_omega", slot: |k| &mut k.mean_omega_ci95, value: |s| s.mean_omega, rule: Rule::TimeMean(Quantity::Omega, 1.0) },
    Key { name: "mean_gamma", slot: |k| &mut k.mean_gamma_ci95, value: |s| s.mean_gamma, rule: Rule::TimeMean(Quantity::Gamma, 1.0) },
    Key { name: "mean_descent_speed", slot: |k| &mut k.mean_descent_speed_ci95, value: |s| s.fall.mean_descent_speed, rule: Rule::TimeMean(Quantity::Ydot, -1.0) },
    Key { name: "mean_horizontal_speed", slot: |k| &mut k.mean_horizontal_speed_ci95, value: |s| s.fall.mean_horizontal_speed, rule: Rule::TimeMean(Quantity::Xdot, 1.0) },
    Key { name: "descent_angle", slot: |k| &mut k.descent_angle_ci95, value: |s| s.fall.descent_angle, rule: Rule::DescentAngle },
    Key { name: "lag_cd_behind_cl", slot: |k| &mut k.lag_cd_behind_cl_ci95, value: |s| s.lag_cd_behind_cl, rule: Rule::Lag },
    Key { name: "strouhal_chord", slot: |k| &mut k.strouhal_chord_ci95, value: |s| s.strouhal_chord, rule: Rule::Strouhal },
    Key { name: "strouhal_width", slot: |k| &mut k.strouhal_width_ci95, value: |s| s.strouhal_width, rule: Rule::StrouhalWidth },
    Key { name: "period", slot: |k| &mut k.period_ci95, value: |s| s.fall.period, rule: Rule::Period },
    Key { name: "mean_cycle_amplitude", slot: |k| &mut k.mean_cycle_amplitude_ci95, value: |_| None, rule: Rule::CycleAmplitude },
    Key { name: "mean_speed_ft_s", slot: |k| &mut k.mean_speed_ft_s_ci95, value: |s| s.mean_speed_ft_s, rule: Rule::Converted("mean_speed", |c| physical(c).map(|p| p.speed_to_ft_s(1.0))) },
    Key { name: "mean_omega_rad_s", slot: |k| &mut k.mean_omega_rad_s_ci95, value: |s| s.mean_omega_rad_s, rule: Rule::Converted("mean_omega", |c| Units::of(c).map(|u| u.rate_rad_s(1.0))) },
    Key { name: "mean_speed_cm_s", slot: |k| &mut k.mean_speed_cm_s_ci95, value: |s| s.physical.mean_speed_cm_s, rule: Rule::Converted("mean_speed", |c| Units::of(c).map(|u| u.speed_cm_s(1.0))) },
    Key { name: "mean_descent_speed_cm_s", slot: |k| &mut k.mean_descent_speed_cm_s_ci95, value: |s| s.physical.mean_descent_speed_cm_s, rule: Rule::Converted("mean_descent_speed", |c| Units::of(c).map(|u| u.speed_cm_s(1.0))) },
    Key { name: "mean_horizontal_speed_cm_s", slot: |k| &mut k.mean_horizontal_speed_cm_s_ci95, value: |s| s.physical.mean_horizontal_speed_cm_s, rule: Rule::Converted("mean_horizontal_speed", |c| Units::of(c).map(|u| u.speed_cm_s(1.0))) },
    Key { name: "period_s", slot: |k| &mut k.period_s_ci95, value: |s| s.physical.period_s, rule: Rule::Converted("period", |c| Units::of(c).map(|u| u.time_s(1.0))) },
    Key { name: "frequency_hz", slot: |k| &mut k.frequency_hz_ci95, value: |s| s.physical.frequency_hz, rule: Rule::Reciprocal("period_s") },
];

/// What the rules read besides the summary: the run, its developed window cut into batches, its
/// motion class.
struct Context<'a> {
    config: &'a RunConfig,
    rec: &'a RunRecord,
    w: TimeWindow,
    means: TimeMeans<'a>,
    motion: Option<&'a (TimeWindow, MotionClass)>,
}

impl Context<'_> {
    /// The interval of a key by `rule` about its summary `value`, given the intervals of the keys
    /// before it (`done`); None when the run has none for it.
    fn interval(
        &self,
        rule: Rule,
        value: Option<f64>,
        sum: &Summary,
        done: &BTreeMap<String, IntervalInfo>,
    ) -> Option<IntervalInfo> {
        let samples = &self.rec.samples[..];
        match rule {
            Rule::TimeMean(q, sign) => value.map(|v| self.means.interval(q, sign, v)),
            Rule::DescentAngle => {
                let (d, x) = (
                    sum.fall.mean_descent_speed?,
                    sum.fall.mean_horizontal_speed?,
                );
                Some(self.means.descent_angle(value?, d, x))
            }
            Rule::Lag => {
                let lags = lags_cd_behind_cl(samples, self.w);
                let b: Vec<(f64, f64)> = lags.iter().map(|x| (1.0, *x)).collect();
                Some(with_drift(
                    list_interval(value?, &lags, "half-turns", 1.0),
                    &b,
                ))
            }
            Rule::Strouhal => {
                let (st, Case::Static { .. }) = (value?, &self.config.case) else {
                    return None;
                };
                let periods = lift_periods(samples, self.w);
                let mean_p = periods.iter().sum::<f64>() / periods.len().max(1) as f64;
                let mut i = list_interval(st, &periods, "lift cycles", 1.0);
                i.half_width = i.half_width.map(|hw| st * hw / mean_p);
                i.note = i.note.or(Some(
                    "relative half-width of the mean duration of the lift cycles".into(),
                ));
                Some(i)
            }
            Rule::StrouhalWidth => {
                let (chord, Case::Static { alpha, .. }) =
                    (done.get("strouhal_chord")?, &self.config.case)
                else {
                    return None;
                };
                let width = projected_width(self.config, *alpha);
                Some(IntervalInfo {
                    value: value?,
                    half_width: chord.half_width.map(|hw| hw * width),
                    ..chord.clone()
                })
            }
            Rule::Period => {
                let (rw, class) = self.motion?;
                let events = cycle_events(samples, *rw, class);
                let durations: Vec<f64> = events.windows(2).map(|e| e[1] - e[0]).collect();
                let (what, per) = if class.turns == (0, 0) {
                    ("oscillation durations", 1.0)
                } else {
                    ("half-turn durations", 2.0)
                };
                let b: Vec<(f64, f64)> = durations.iter().map(|x| (1.0, per * x)).collect();
                Some(with_drift(list_interval(value?, &durations, what, per), &b))
            }
            Rule::CycleAmplitude => {
                let (rw, class) = self.motion?;
                if sum.fall.period.is_none() || class.turns != (0, 0) {
                    return None;
                }
                let amps = cycle_amplitudes(samples, &cycle_events(samples, *rw, class));
                let mean = amps.iter().sum::<f64>() / amps.len() as f64;
                (!amps.is_empty()).then(|| list_interval(mean, &amps, "oscillations", 1.0))
            }
            Rule::Converted(base, factor) => converted(done.get(base), value, factor(self.config)?),
            Rule::Reciprocal(base) => {
                let (p, f) = (done.get(base)?, value?);
                Some(IntervalInfo {
                    value: f,
                    half_width: p.half_width.map(|hw| hw * f * f),
                    ..p.clone()
                })
            }
        }
    }
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
    let means = TimeMeans {
        h: &rec.samples,
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
    let ctx = Context {
        config,
        rec,
        w,
        means,
        motion,
    };
    for key in KEYS {
        let Some(i) = ctx.interval(key.rule, (key.value)(sum), sum, &keys.intervals) else {
            continue;
        };
        if matches!(key.rule, Rule::CycleAmplitude) {
            keys.mean_cycle_amplitude = Some(i.value);
        }
        *(key.slot)(&mut keys) = i.half_width;
        keys.intervals.insert(key.name.into(), i);
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

// The tests build summaries, which sit above this module: they live in their own file.
#[cfg(test)]
#[path = "intervals_tests.rs"]
mod tests;
