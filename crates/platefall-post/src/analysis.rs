//! Post-run statistics of the time series: the developed part of a run, means over it, the dominant
//! lift frequency (Strouhal number) and turn counting for autorotation. Pure functions on samples.
use std::f64::consts::PI;

use platefall_core::sim::{RunConfig, StepSample};

/// A time window [t0, t1] of the run.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct TimeWindow {
    /// Start of the window (convective time, c/U).
    pub t0: f64,
    /// End of the window (convective time, c/U).
    pub t1: f64,
}

/// Time-weighted mean of `f` over the samples inside the window (trapezoidal in t).
pub fn mean_over(
    samples: &[StepSample],
    w: TimeWindow,
    f: impl Fn(&StepSample) -> f64,
) -> Option<f64> {
    let mut acc = 0.0;
    let mut span = 0.0;
    for pair in samples.windows(2) {
        let (a, b) = (&pair[0], &pair[1]);
        if a.t >= w.t0 - 1e-12 && b.t <= w.t1 + 1e-12 {
            let dt = b.t - a.t;
            acc += 0.5 * (f(a) + f(b)) * dt;
            span += dt;
        }
    }
    (span > 0.0).then(|| acc / span)
}

/// Largest and smallest of `f` inside the window.
pub fn range_over(
    samples: &[StepSample],
    w: TimeWindow,
    f: impl Fn(&StepSample) -> f64,
) -> Option<(f64, f64)> {
    samples
        .iter()
        .filter(|s| s.t >= w.t0 - 1e-12 && s.t <= w.t1 + 1e-12)
        .map(&f)
        .fold(None, |acc, x| match acc {
            None => Some((x, x)),
            Some((lo, hi)) => Some((lo.min(x), hi.max(x))),
        })
}

/// Resamples `f` onto a uniform grid of step `h` over the window (linear interpolation).
fn resample(
    samples: &[StepSample],
    w: TimeWindow,
    h: f64,
    f: &impl Fn(&StepSample) -> f64,
) -> Vec<f64> {
    let n = ((w.t1 - w.t0) / h).floor() as usize + 1;
    let mut out = Vec::with_capacity(n);
    let mut k = 0;
    for m in 0..n {
        let t = w.t0 + m as f64 * h;
        while k + 2 < samples.len() && samples[k + 1].t < t {
            k += 1;
        }
        let (a, b) = (&samples[k], &samples[(k + 1).min(samples.len() - 1)]);
        let s = if b.t > a.t {
            ((t - a.t) / (b.t - a.t)).clamp(0.0, 1.0)
        } else {
            0.0
        };
        out.push(f(a) + s * (f(b) - f(a)));
    }
    out
}

/// Dominant frequency (cycles per convective time) of `f` over the window: the peak of the
/// Hann-windowed periodogram of the mean-removed, uniformly resampled signal, searched on a grid
/// eight times finer than 1/T and refined by a parabola through the peak. `None` when the signal's
/// peak-to-peak band is below `steady_band` (the flow is steady) or the window is too short.
pub fn dominant_frequency(
    samples: &[StepSample],
    w: TimeWindow,
    steady_band: f64,
    f: impl Fn(&StepSample) -> f64,
) -> Option<f64> {
    let (lo, hi) = range_over(samples, w, &f)?;
    let span = w.t1 - w.t0;
    if hi - lo < steady_band || span <= 0.0 || samples.len() < 8 {
        return None;
    }
    let h = 0.02_f64.min(span / 64.0);
    let mut x = resample(samples, w, h, &f);
    let n = x.len();
    let mean = x.iter().sum::<f64>() / n as f64;
    for (k, v) in x.iter_mut().enumerate() {
        let hann = 0.5 - 0.5 * (2.0 * PI * k as f64 / (n - 1) as f64).cos();
        *v = (*v - mean) * hann;
    }
    let power = |freq: f64| -> f64 {
        // Goertzel-style recurrence for one DFT bin at an arbitrary frequency.
        let wdt = 2.0 * PI * freq * h;
        let coeff = 2.0 * wdt.cos();
        let (mut s1, mut s2) = (0.0, 0.0);
        for &v in &x {
            let s0 = v + coeff * s1 - s2;
            s2 = s1;
            s1 = s0;
        }
        s1 * s1 + s2 * s2 - coeff * s1 * s2
    };
    let df = 1.0 / (8.0 * span);
    let f_max = (0.25 / h).min(10.0);
    let (mut best_f, mut best_p) = (0.0, -1.0);
    let mut fq = 1.5 / span; // skip the lowest bins, which carry the trend
    while fq <= f_max {
        let p = power(fq);
        if p > best_p {
            best_p = p;
            best_f = fq;
        }
        fq += df;
    }
    if best_p <= 0.0 {
        return None;
    }
    let (pl, pr) = (power(best_f - df), power(best_f + df));
    let denom = pl - 2.0 * best_p + pr;
    let shift = if denom.abs() > 0.0 {
        0.5 * (pl - pr) / denom
    } else {
        0.0
    };
    Some(best_f + shift.clamp(-0.5, 0.5) * df)
}

/// Shrinks a window from its start so it holds a whole number of periods (at least one).
pub fn whole_periods(w: TimeWindow, period: f64) -> TimeWindow {
    let n = ((w.t1 - w.t0) / period).floor();
    if n >= 1.0 {
        TimeWindow {
            t0: w.t1 - n * period,
            t1: w.t1,
        }
    } else {
        w
    }
}

/// Net turns of θ after release and the times at which whole turns were completed, counted in the
/// final direction of rotation from the extreme angle reached the other way (so a plate that first
/// turns back and then autorotates is counted from its reversal).
#[derive(Clone, Debug, PartialEq)]
pub struct Turns {
    /// Net revolutions (θ_end − θ_release)/2π, signed.
    pub revolutions: f64,
    /// Completion times of turns 1, 2, … (in the final direction).
    pub completed: Vec<f64>,
}

/// Counts the turns of θ in `samples` from the release time `t_release` (c/U) on: the net
/// revolutions and the completion time of every whole turn (see [`Turns`]).
pub fn count_turns(samples: &[StepSample], t_release: f64) -> Turns {
    let after: Vec<&StepSample> = samples
        .iter()
        .filter(|s| s.t >= t_release - 1e-12)
        .collect();
    let (Some(first), Some(last)) = (after.first(), after.last()) else {
        return Turns {
            revolutions: 0.0,
            completed: vec![],
        };
    };
    let revolutions = (last.theta - first.theta) / (2.0 * PI);
    let dir = if last.theta >= first.theta { 1.0 } else { -1.0 };
    // Start from the extreme reached against the final direction.
    let (mut start, mut start_idx) = (dir * first.theta, 0);
    for (k, s) in after.iter().enumerate() {
        if dir * s.theta < start {
            start = dir * s.theta;
            start_idx = k;
        }
    }
    let mut completed = Vec::new();
    let mut next = start + 2.0 * PI;
    for s in &after[start_idx..] {
        while dir * s.theta >= next {
            completed.push(s.t);
            next += 2.0 * PI;
        }
    }
    Turns {
        revolutions,
        completed,
    }
}

/// Mean lag (in α) of the maximum of C_D behind the maximum of C_L, per half-turn (period π in θ).
/// For clockwise rotation the lift is taken in the rotation's own sense (−C_L): the mirror image
/// y → −y of a counter-clockwise run turns clockwise with C_L negated and C_D unchanged.
pub fn lag_cd_behind_cl(samples: &[StepSample], w: TimeWindow) -> Option<f64> {
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

/// The width of a static section at angle of attack α across the stream (chords): the length
/// the Strouhal number on the width is based on (c|sin α| + t|cos α| for a rectangle).
pub fn projected_width(config: &RunConfig, alpha: f64) -> f64 {
    let (s, c) = alpha.sin_cos();
    config.grid.shape.outline().width_across([c, -s])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn series(f: impl Fn(f64) -> f64, t_end: f64, dt: f64) -> Vec<StepSample> {
        (0..=((t_end / dt) as usize))
            .map(|k| {
                let t = k as f64 * dt;
                StepSample {
                    t,
                    cl: f(t),
                    theta: f(t),
                    ..Default::default()
                }
            })
            .collect()
    }

    #[test]
    fn finds_a_sine_frequency_within_half_a_percent() {
        let s = series(|t| 0.3 + (2.0 * PI * 0.37 * t).sin(), 60.0, 0.013);
        let f = dominant_frequency(&s, TimeWindow { t0: 10.0, t1: 60.0 }, 1e-3, |s| s.cl).unwrap();
        assert!((f - 0.37).abs() < 0.002, "{f}");
    }

    #[test]
    fn steady_signal_has_no_frequency() {
        let s = series(|t| 1.0 + 1e-5 * t.sin(), 30.0, 0.01);
        assert!(dominant_frequency(&s, TimeWindow { t0: 0.0, t1: 30.0 }, 1e-3, |s| s.cl).is_none());
    }

    #[test]
    fn mean_of_a_sine_over_whole_periods_is_its_offset() {
        let s = series(|t| 2.0 + (2.0 * PI * t / 3.0).sin(), 30.0, 0.001);
        let w = whole_periods(TimeWindow { t0: 1.0, t1: 30.0 }, 3.0);
        assert!((mean_over(&s, w, |s| s.cl).unwrap() - 2.0).abs() < 1e-6);
    }

    #[test]
    fn turns_are_counted_from_a_reversal() {
        // θ dips to −1 then rises steadily by 3 turns.
        let s = series(
            |t| if t < 1.0 { -t } else { -1.0 + (t - 1.0) * 2.0 },
            11.0,
            0.001,
        );
        let turns = count_turns(&s, 0.0);
        assert_eq!(turns.completed.len(), 3);
        assert!((turns.completed[0] - (1.0 + PI)).abs() < 2e-3);
    }

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
