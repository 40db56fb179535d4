//! Confidence intervals of time means from a run's own, autocorrelated, time series. Pure
//! functions on numbers; [`crate::intervals`] applies them to a run.
//!
//! Two estimators of the variance of a mean, each where it fits:
//!
//! - **Batch means** ([`batch_interval`]): the window is cut into batches (for a tumbling or
//!   fluttering plate its whole turns or periods, for a shedding plate its lift periods). Each
//!   batch's time mean b_i, of duration w_i, is one observation; the time mean of the window is
//!   m = Σ w_i b_i / Σ w_i and its variance is estimated by
//!   n/(n − 1) · Σ (w_i/W)² (b_i − m)² (which is s²/n for equal batches). Whole cycles remove the
//!   periodic part of the signal exactly, so a strictly periodic signal gets a zero half-width.
//!   Batches that are still correlated (a plate whose turns drift over several turns) are
//!   corrected by the integrated autocorrelation time τ of the sequence of batch means
//!   (Geyer's initial monotone sequence, [`iat_initial_monotone`]), never below 1: the
//!   effective number of independent batches is n_eff = n/τ and the half-width
//!   t(0.975; n_eff − 1) · √(τ · var).
//! - **Integrated autocorrelation time of an evenly sampled series** ([`series_interval`]), for
//!   a window with no natural cycles (a steady wake, a steady descent): τ = 1 + 2 Σ_{k=1}^{M} ρ(k)
//!   with Sokal's automatic window (the smallest M with M ≥ c τ(M), [`iat_sokal`]); the series
//!   must be at least [`SERIES_MIN_TAUS`] τ long. Uneven time steps are first averaged into equal
//!   time bins ([`time_bins`]), time-weighted.
//!
//! The quantile of Student's t for a real number of degrees of freedom comes from the
//! regularised incomplete beta function ([`student_t_quantile`]).

/// The confidence level of every interval.
pub const LEVEL: f64 = 0.95;
/// Fewest batches that give an interval (4 degrees of freedom: t = 2.78).
pub const MIN_BATCHES: usize = 5;
/// Fewest effective independent batches (after the autocorrelation correction).
pub const MIN_EFFECTIVE: f64 = 2.0;
/// Sokal's window constant c: the window M is the smallest with M ≥ c τ(M).
pub const SOKAL_C: f64 = 5.0;
/// A series gives an interval only when it is at least this many autocorrelation times long.
pub const SERIES_MIN_TAUS: f64 = 50.0;

/// A mean with its 95 % confidence interval.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Interval {
    /// The (time-weighted) mean.
    pub mean: f64,
    /// Half-width of the 95 % interval: the mean is `mean ± half_width`.
    pub half_width: f64,
    /// Standard error of the mean (τ included).
    pub std_error: f64,
    /// Batches (batch means) or evenly spaced samples (series) behind it.
    pub samples: usize,
    /// Integrated autocorrelation time, in batches or samples (1: independent).
    pub tau: f64,
    /// Effective number of independent samples, samples / τ.
    pub n_eff: f64,
    /// Degrees of freedom of the t quantile, n_eff − 1.
    pub dof: f64,
    /// The t quantile used, t(0.975; dof).
    pub t: f64,
}

/// Why a series gives no interval.
#[derive(Clone, Debug, PartialEq)]
pub enum NoInterval {
    /// Fewer batches than [`MIN_BATCHES`].
    TooFewBatches {
        /// Batches the window holds.
        have: usize,
        /// Batches needed ([`MIN_BATCHES`]).
        need: usize,
    },
    /// The batches are so correlated that fewer than [`MIN_EFFECTIVE`] are independent.
    Correlated {
        /// The effective number of independent batches, batches / τ.
        n_eff: f64,
    },
    /// The series is shorter than [`SERIES_MIN_TAUS`] autocorrelation times (or its
    /// autocorrelation does not decay within it).
    TooShort {
        /// Samples in the series.
        samples: usize,
        /// The series' integrated autocorrelation time in samples; `None` when it does not decay.
        tau: Option<f64>,
    },
    /// A value is not finite.
    NotFinite,
}

impl std::fmt::Display for NoInterval {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            NoInterval::TooFewBatches { have, need } => {
                write!(f, "{have} batches, {need} needed")
            }
            NoInterval::Correlated { n_eff } => write!(
                f,
                "the batch means are correlated over the whole window ({n_eff:.1} independent, \
                 {MIN_EFFECTIVE} needed)"
            ),
            NoInterval::TooShort {
                samples,
                tau: Some(t),
            } => write!(
                f,
                "{samples} samples are fewer than {SERIES_MIN_TAUS} autocorrelation times \
                 (τ = {t:.1} samples)"
            ),
            NoInterval::TooShort { samples, tau: None } => write!(
                f,
                "the autocorrelation does not decay within the {samples} samples"
            ),
            NoInterval::NotFinite => f.write_str("a value is not finite"),
        }
    }
}

/// ln Γ(x) for x > 0: the recurrence up to x ≥ 12, then Stirling's series (error < 1e-15).
pub fn ln_gamma(x: f64) -> f64 {
    let mut x = x;
    let mut shift = 0.0;
    while x < 12.0 {
        shift -= x.ln();
        x += 1.0;
    }
    let z = 1.0 / (x * x);
    // Bernoulli terms B_2k / (2k (2k − 1) x^(2k−1)), k = 1..6.
    let series = (1.0 / 12.0
        + z * (-1.0 / 360.0
            + z * (1.0 / 1260.0
                + z * (-1.0 / 1680.0 + z * (1.0 / 1188.0 + z * (-691.0 / 360_360.0))))))
        / x;
    shift + (x - 0.5) * x.ln() - x + 0.5 * (2.0 * std::f64::consts::PI).ln() + series
}

/// The continued fraction of the incomplete beta function (modified Lentz), for
/// x < (a + 1)/(a + b + 2) where it converges fast.
fn beta_fraction(a: f64, b: f64, x: f64) -> f64 {
    const TINY: f64 = 1e-300;
    let mut c = 1.0;
    let mut d = 1.0 - (a + b) * x / (a + 1.0);
    d = if d.abs() < TINY { TINY } else { d };
    d = 1.0 / d;
    let mut h = d;
    for m in 1..=500 {
        let m = m as f64;
        // Even step d_2m = m (b − m) x / ((a + 2m − 1)(a + 2m)), then odd step
        // d_2m+1 = −(a + m)(a + b + m) x / ((a + 2m)(a + 2m + 1)).
        for coeff in [
            m * (b - m) * x / ((a + 2.0 * m - 1.0) * (a + 2.0 * m)),
            -(a + m) * (a + b + m) * x / ((a + 2.0 * m) * (a + 2.0 * m + 1.0)),
        ] {
            d = 1.0 + coeff * d;
            d = if d.abs() < TINY { TINY } else { d };
            c = 1.0 + coeff / c;
            c = if c.abs() < TINY { TINY } else { c };
            d = 1.0 / d;
            h *= d * c;
        }
        if (d * c - 1.0).abs() < 1e-15 {
            break;
        }
    }
    h
}

/// The regularised incomplete beta function I_x(a, b), a, b > 0, x in [0, 1].
pub fn regularized_beta(a: f64, b: f64, x: f64) -> f64 {
    if x <= 0.0 {
        return 0.0;
    }
    if x >= 1.0 {
        return 1.0;
    }
    let ln_front = ln_gamma(a + b) - ln_gamma(a) - ln_gamma(b) + a * x.ln() + b * (1.0 - x).ln();
    if x < (a + 1.0) / (a + b + 2.0) {
        ln_front.exp() * beta_fraction(a, b, x) / a
    } else {
        1.0 - ln_front.exp() * beta_fraction(b, a, 1.0 - x) / b
    }
}

/// P(T ≤ t) for Student's t with `nu` > 0 degrees of freedom (real).
pub fn student_t_cdf(t: f64, nu: f64) -> f64 {
    let tail = 0.5 * regularized_beta(0.5 * nu, 0.5, nu / (nu + t * t));
    if t >= 0.0 {
        1.0 - tail
    } else {
        tail
    }
}

/// The quantile t_p of Student's t with `nu` > 0 degrees of freedom (real): P(T ≤ t_p) = p, for
/// p in (0, 1). Bisection on the distribution function, to 1e-12.
pub fn student_t_quantile(p: f64, nu: f64) -> f64 {
    if p == 0.5 {
        return 0.0;
    }
    if p < 0.5 {
        return -student_t_quantile(1.0 - p, nu);
    }
    let (mut lo, mut hi) = (0.0, 1.0);
    while student_t_cdf(hi, nu) < p && hi < 1e12 {
        lo = hi;
        hi *= 2.0;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if student_t_cdf(mid, nu) < p {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo <= 1e-12 * hi {
            break;
        }
    }
    0.5 * (lo + hi)
}

/// The two-sided 95 % quantile t(0.975; nu).
pub fn t95(nu: f64) -> f64 {
    student_t_quantile(0.5 + 0.5 * LEVEL, nu)
}

/// Autocovariances γ(0..=max_lag) of `x` about its mean (the 1/n estimator).
pub fn autocovariance(x: &[f64], max_lag: usize) -> Vec<f64> {
    let n = x.len();
    if n == 0 {
        return Vec::new();
    }
    let mean = x.iter().sum::<f64>() / n as f64;
    let d: Vec<f64> = x.iter().map(|v| v - mean).collect();
    (0..=max_lag.min(n - 1))
        .map(|k| {
            d[..n - k]
                .iter()
                .zip(&d[k..])
                .map(|(a, b)| a * b)
                .sum::<f64>()
                / n as f64
        })
        .collect()
}

/// The integrated autocorrelation time τ = 1 + 2 Σ ρ(k) of a short sequence (batch means) by
/// Geyer's initial monotone sequence: the sums of adjacent pairs Γ_m = γ(2m) + γ(2m + 1) are
/// kept while positive and made non-increasing, τ = (2 Σ Γ_m − γ(0))/γ(0). A constant sequence
/// has τ = 1. The result can be below 1 (anticorrelated values); callers clamp it.
pub fn iat_initial_monotone(x: &[f64]) -> f64 {
    let g = autocovariance(x, x.len().saturating_sub(1));
    let Some(&g0) = g.first() else {
        return 1.0;
    };
    if g0 <= 0.0 {
        return 1.0;
    }
    let mut sum = 0.0;
    let mut prev = f64::INFINITY;
    for pair in g.chunks_exact(2) {
        let gamma = (pair[0] + pair[1]).min(prev);
        if gamma <= 0.0 {
            break;
        }
        sum += gamma;
        prev = gamma;
    }
    if sum == 0.0 {
        // Only γ(0) (one value) or a negative first pair: no evidence of correlation.
        return 1.0;
    }
    (2.0 * sum - g0) / g0
}

/// Sokal's windowed estimate of τ = 1 + 2 Σ_{k=1}^{M} ρ(k) for an evenly sampled series: the
/// window M is the smallest with M ≥ c τ(M). None when no window shorter than the series does.
pub fn iat_sokal(x: &[f64], c: f64) -> Option<(f64, usize)> {
    let n = x.len();
    if n < 4 {
        return None;
    }
    // Autocovariances one lag at a time: the window is usually far shorter than the series.
    let mean = x.iter().sum::<f64>() / n as f64;
    let d: Vec<f64> = x.iter().map(|v| v - mean).collect();
    let gamma = |k: usize| {
        d[..n - k]
            .iter()
            .zip(&d[k..])
            .map(|(a, b)| a * b)
            .sum::<f64>()
    };
    let g0 = gamma(0);
    if g0 <= 0.0 {
        return Some((1.0, 0));
    }
    let mut tau = 1.0;
    for m in 1..=n / 2 {
        tau += 2.0 * gamma(m) / g0;
        if m as f64 >= c * tau {
            return Some((tau.max(1.0 / n as f64), m));
        }
    }
    None
}

/// The interval of a time mean from its batches `(duration, batch mean)`: see the module docs.
pub fn batch_interval(batches: &[(f64, f64)]) -> Result<Interval, NoInterval> {
    let n = batches.len();
    if batches
        .iter()
        .any(|(w, b)| !w.is_finite() || !b.is_finite())
    {
        return Err(NoInterval::NotFinite);
    }
    if n < MIN_BATCHES {
        return Err(NoInterval::TooFewBatches {
            have: n,
            need: MIN_BATCHES,
        });
    }
    let total: f64 = batches.iter().map(|(w, _)| w).sum();
    let mean = batches.iter().map(|(w, b)| w * b).sum::<f64>() / total;
    let var = n as f64 / (n as f64 - 1.0)
        * batches
            .iter()
            .map(|(w, b)| (w / total).powi(2) * (b - mean).powi(2))
            .sum::<f64>();
    let values: Vec<f64> = batches.iter().map(|(_, b)| *b).collect();
    let tau = iat_initial_monotone(&values).clamp(1.0, n as f64);
    let n_eff = n as f64 / tau;
    if n_eff < MIN_EFFECTIVE {
        return Err(NoInterval::Correlated { n_eff });
    }
    let dof = n_eff - 1.0;
    let std_error = (tau * var).sqrt();
    let t = t95(dof);
    Ok(Interval {
        mean,
        half_width: t * std_error,
        std_error,
        samples: n,
        tau,
        n_eff,
        dof,
        t,
    })
}

/// A straight-line trend of a sequence against its index: the slope per step, its standard error
/// (from the residuals, as if they were independent) and whether it differs from zero at 95 %
/// (|slope| > t(0.975; n − 2) × its standard error).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Trend {
    /// Slope of the least-squares line, per index step.
    pub slope: f64,
    /// Standard error of the slope.
    pub std_error: f64,
    /// True when |slope| > t(0.975; n − 2) × `std_error` (docs/statistics.md, "Drift").
    pub significant: bool,
}

/// The least-squares trend of `x` (at least 4 values).
pub fn trend(x: &[f64]) -> Option<Trend> {
    let n = x.len();
    if n < 4 || x.iter().any(|v| !v.is_finite()) {
        return None;
    }
    let nf = n as f64;
    let (mi, mx) = ((nf - 1.0) / 2.0, x.iter().sum::<f64>() / nf);
    let sii: f64 = (0..n).map(|i| (i as f64 - mi).powi(2)).sum();
    let slope = x
        .iter()
        .enumerate()
        .map(|(i, v)| (i as f64 - mi) * (v - mx))
        .sum::<f64>()
        / sii;
    let rss: f64 = x
        .iter()
        .enumerate()
        .map(|(i, v)| (v - mx - slope * (i as f64 - mi)).powi(2))
        .sum();
    let std_error = (rss / (nf - 2.0) / sii).sqrt();
    let significant = slope.abs() > t95(nf - 2.0) * std_error;
    Some(Trend {
        slope,
        std_error,
        significant,
    })
}

/// The interval of the mean of an evenly sampled series from its integrated autocorrelation
/// time (Sokal's window, [`SOKAL_C`]); see the module docs.
pub fn series_interval(x: &[f64]) -> Result<Interval, NoInterval> {
    let n = x.len();
    if x.iter().any(|v| !v.is_finite()) {
        return Err(NoInterval::NotFinite);
    }
    let Some((tau, _)) = iat_sokal(x, SOKAL_C) else {
        return Err(NoInterval::TooShort {
            samples: n,
            tau: None,
        });
    };
    let tau = tau.max(1.0);
    if (n as f64) < SERIES_MIN_TAUS * tau {
        return Err(NoInterval::TooShort {
            samples: n,
            tau: Some(tau),
        });
    }
    let mean = x.iter().sum::<f64>() / n as f64;
    let var = x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n as f64 - 1.0);
    let n_eff = n as f64 / tau;
    let std_error = (var / n_eff).sqrt();
    let dof = n_eff - 1.0;
    let t = t95(dof);
    Ok(Interval {
        mean,
        half_width: t * std_error,
        std_error,
        samples: n,
        tau,
        n_eff,
        dof,
        t,
    })
}

/// Time means of a sampled signal over `bins` equal bins of [t.first, t.last]: the trapezoidal
/// integral of the piecewise-linear signal through the samples (so uneven steps are weighted by
/// their duration). `t` must increase.
pub fn time_bins(t: &[f64], x: &[f64], bins: usize) -> Vec<f64> {
    let n = t.len().min(x.len());
    if n < 2 || bins == 0 || t[n - 1] <= t[0] {
        return Vec::new();
    }
    let (t0, t1) = (t[0], t[n - 1]);
    let width = (t1 - t0) / bins as f64;
    // The signal's running integral at each sample, then its value at any time by linear
    // interpolation of the signal inside the sample interval.
    let mut cum = vec![0.0; n];
    for k in 1..n {
        cum[k] = cum[k - 1] + 0.5 * (x[k] + x[k - 1]) * (t[k] - t[k - 1]);
    }
    let integral_to = |s: f64, k: &mut usize| -> f64 {
        while *k + 2 < n && t[*k + 1] < s {
            *k += 1;
        }
        let (ta, tb) = (t[*k], t[*k + 1]);
        let dt = s - ta;
        let slope = if tb > ta {
            (x[*k + 1] - x[*k]) / (tb - ta)
        } else {
            0.0
        };
        cum[*k] + x[*k] * dt + 0.5 * slope * dt * dt
    };
    let mut k = 0;
    let mut prev = 0.0;
    (1..=bins)
        .map(|b| {
            let s = if b == bins { t1 } else { t0 + b as f64 * width };
            let now = integral_to(s, &mut k);
            let mean = (now - prev) / width;
            prev = now;
            mean
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::rng::Rng;

    #[test]
    fn ln_gamma_matches_factorials_and_half_integers() {
        for n in 1..30u32 {
            let fact: f64 = (1..n).map(f64::from).product();
            assert!((ln_gamma(f64::from(n)) - fact.ln()).abs() < 1e-12, "{n}");
        }
        let sqrt_pi = std::f64::consts::PI.sqrt();
        assert!((ln_gamma(0.5) - sqrt_pi.ln()).abs() < 1e-14);
        assert!((ln_gamma(2.5) - (0.75 * sqrt_pi).ln()).abs() < 1e-14);
    }

    #[test]
    fn t_quantiles_match_the_tables() {
        // Two-sided 95 % points of Student's t (any statistics table), and the normal's 1.959964.
        for (nu, t) in [
            (1.0, 12.7062),
            (2.0, 4.3027),
            (4.0, 2.7764),
            (5.0, 2.5706),
            (10.0, 2.2281),
            (30.0, 2.0423),
            (1e7, 1.95996),
        ] {
            assert!(
                (t95(nu) - t).abs() < 1e-4 * t,
                "t(0.975; {nu}) = {}",
                t95(nu)
            );
        }
        // ν = 1 is the Cauchy distribution and ν = 2 has a closed form.
        let p: f64 = 0.9;
        let cauchy = (std::f64::consts::PI * (p - 0.5)).tan();
        assert!((student_t_quantile(p, 1.0) - cauchy).abs() < 1e-9);
        let two = (2.0 * p - 1.0) * (2.0 / (4.0 * p * (1.0 - p))).sqrt();
        assert!((student_t_quantile(p, 2.0) - two).abs() < 1e-9);
        // Real degrees of freedom fall between their integer neighbours.
        assert!(t95(3.5) < t95(3.0) && t95(3.5) > t95(4.0));
        assert!((student_t_cdf(-1.3, 7.0) + student_t_cdf(1.3, 7.0) - 1.0).abs() < 1e-14);
    }

    #[test]
    fn a_constant_has_a_zero_half_width() {
        let batches = vec![(0.7, 2.5); 8];
        let i = batch_interval(&batches).unwrap();
        assert!(
            (i.mean - 2.5).abs() < 1e-15 && i.half_width < 1e-12 && i.tau == 1.0,
            "{i:?}"
        );
        let s = series_interval(&[2.5; 400]).unwrap();
        assert_eq!((s.mean, s.half_width), (2.5, 0.0));
    }

    #[test]
    fn a_sine_over_whole_periods_has_a_zero_half_width() {
        // Batches of one period each of 1 + sin(2πt/T), sampled unevenly: every batch mean is 1.
        let period = 2.3;
        let mut t = vec![0.0];
        while *t.last().unwrap() < 12.0 * period {
            let k = t.len() as f64;
            t.push(t.last().unwrap() + 1e-3 * (1.0 + 0.5 * (0.37 * k).sin()));
        }
        let x: Vec<f64> = t
            .iter()
            .map(|s| 1.0 + (2.0 * std::f64::consts::PI * s / period).sin())
            .collect();
        let n = t.iter().filter(|s| **s <= 12.0 * period).count();
        // 12 bins of [0, t_n] are close to whole periods; use the exact bins of 12 periods.
        let (tt, xx) = (&t[..n], &x[..n]);
        let cut = |a: f64, b: f64| -> (Vec<f64>, Vec<f64>) {
            let keep: Vec<usize> = (0..tt.len())
                .filter(|&k| tt[k] >= a && tt[k] <= b)
                .collect();
            (
                keep.iter().map(|&k| tt[k]).collect(),
                keep.iter().map(|&k| xx[k]).collect(),
            )
        };
        let batches: Vec<(f64, f64)> = (0..11)
            .map(|p| {
                let (a, b) = (p as f64 * period, (p + 1) as f64 * period);
                let (bt, bx) = cut(a, b);
                let m = time_bins(&bt, &bx, 1)[0];
                (bt[bt.len() - 1] - bt[0], m)
            })
            .collect();
        let i = batch_interval(&batches).unwrap();
        assert!((i.mean - 1.0).abs() < 2e-3, "{i:?}");
        // Each batch misses at most one step at either end: the spread is of order the step.
        assert!(i.half_width < 3e-3, "{i:?}");
    }

    #[test]
    fn a_trend_is_found_in_a_ramp_and_not_in_noise() {
        let ramp: Vec<f64> = (0..19)
            .map(|i| 2.7 + 0.04 * i as f64 + 0.01 * (i as f64).sin())
            .collect();
        let t = trend(&ramp).unwrap();
        assert!(t.significant && (t.slope - 0.04).abs() < 0.005, "{t:?}");
        // Independent normal values: a significant slope in about 5 % of the sequences.
        let mut rng = Rng(5);
        let runs = 2000;
        let hits = (0..runs)
            .filter(|_| {
                let x: Vec<f64> = (0..19).map(|_| rng.normal()).collect();
                trend(&x).unwrap().significant
            })
            .count();
        let rate = hits as f64 / runs as f64;
        assert!((rate - 0.05).abs() < tolerance(runs), "false alarms {rate}");
    }

    #[test]
    fn time_bins_weight_uneven_steps_by_their_duration() {
        // x = t² sampled at uneven times; the mean over [a, b] is (b³ − a³)/(3(b − a)).
        let t: Vec<f64> = (0..=3000)
            .map(|k| {
                let s = k as f64 / 3000.0;
                4.0 * s * s
            })
            .collect();
        let x: Vec<f64> = t.iter().map(|s| s * s).collect();
        let bins = time_bins(&t, &x, 8);
        assert_eq!(bins.len(), 8);
        for (b, m) in bins.iter().enumerate() {
            let (a, c) = (0.5 * b as f64, 0.5 * (b + 1) as f64);
            let exact = (c.powi(3) - a.powi(3)) / (3.0 * (c - a));
            assert!((m - exact).abs() < 1e-4, "bin {b}: {m} vs {exact}");
        }
    }

    #[test]
    fn sokal_recovers_the_autocorrelation_time_of_an_ar1_process() {
        // τ = (1 + φ)/(1 − φ) = 9 for φ = 0.8; the estimator's relative spread is
        // √(2(2M + 1)/n) ≈ 6 % for n = 50 000 and M ≈ 45.
        let mut rng = Rng(7);
        let x = rng.ar1(0.8, 50_000);
        let (tau, m) = iat_sokal(&x, SOKAL_C).unwrap();
        assert!((tau - 9.0).abs() < 0.25 * 9.0, "τ = {tau}, window {m}");
    }

    /// The fraction of `runs` seeded realisations whose interval holds the true mean 0.
    fn coverage(runs: usize, seed: u64, interval: impl Fn(&mut Rng) -> Option<Interval>) -> f64 {
        let mut rng = Rng(seed);
        let mut hit = 0;
        let mut done = 0;
        for _ in 0..runs {
            if let Some(i) = interval(&mut rng) {
                done += 1;
                if i.mean.abs() <= i.half_width {
                    hit += 1;
                }
            }
        }
        assert!(
            done >= runs * 99 / 100,
            "only {done} of {runs} gave an interval"
        );
        hit as f64 / done as f64
    }

    /// Three binomial standard deviations of a 95 % coverage over `runs` trials.
    fn tolerance(runs: usize) -> f64 {
        3.0 * (LEVEL * (1.0 - LEVEL) / runs as f64).sqrt()
    }

    #[test]
    fn series_intervals_of_an_ar1_process_cover_its_mean_95_percent_of_the_time() {
        // AR(1) with φ = 0.8 (τ = 9), 4000 samples (n_eff ≈ 440); 1500 seeded realisations.
        // The variance of the mean is known exactly, σ²τ/n to O(1/n); the intervals must cover
        // the true mean 0 in 95 % of the realisations within three binomial deviations (1.7 %).
        let runs = 1500;
        let c = coverage(runs, 11, |rng| series_interval(&rng.ar1(0.8, 4000)).ok());
        eprintln!("series coverage {c}");
        assert!((c - LEVEL).abs() < tolerance(runs), "coverage {c}");
    }

    #[test]
    fn batch_intervals_of_an_ar1_process_cover_its_mean_95_percent_of_the_time() {
        // The same process in 20 batches of 400 samples (≈ 44 τ each, so nearly independent):
        // Student's t with the batches' own autocorrelation correction.
        let runs = 1500;
        let c = coverage(runs, 23, |rng| {
            let x = rng.ar1(0.8, 8000);
            let batches: Vec<(f64, f64)> = x
                .chunks(400)
                .map(|b| (1.0, b.iter().sum::<f64>() / b.len() as f64))
                .collect();
            batch_interval(&batches).ok()
        });
        eprintln!("batch coverage {c}");
        assert!((c - LEVEL).abs() < tolerance(runs), "coverage {c}");
    }

    /// The batch estimator on short sequences of batch means (the turns of a run): coverage and
    /// mean half-width relative to the exact one, for independent batches and for batch means
    /// that are themselves AR(1) with φ_b. `cargo test --release -p platefall-post batch_diag
    /// -- --ignored --nocapture` prints the figures quoted in docs/statistics.md.
    #[test]
    #[ignore]
    fn batch_diagnostics() {
        for (n, phi) in [
            (10, 0.0_f64),
            (20, 0.0),
            (40, 0.0),
            (10, 0.5),
            (20, 0.5),
            (40, 0.5),
        ] {
            let runs = 4000;
            let mut rng = Rng(99);
            let (mut hit, mut hit_naive, mut width) = (0, 0, 0.0);
            // The exact standard error of the mean of n AR(1) values of unit innovation.
            let var1 = 1.0 / (1.0 - phi * phi);
            let exact: f64 = (0..n)
                .flat_map(|i| (0..n).map(move |j| (i as i32 - j as i32).unsigned_abs()))
                .map(|k| var1 * phi.powi(k as i32))
                .sum::<f64>()
                / (n * n) as f64;
            for _ in 0..runs {
                let x = rng.ar1(phi, n);
                let b: Vec<(f64, f64)> = x.iter().map(|v| (1.0, *v)).collect();
                let Ok(i) = batch_interval(&b) else { continue };
                hit += usize::from(i.mean.abs() <= i.half_width);
                let naive = t95(n as f64 - 1.0) * i.std_error / i.tau.sqrt();
                hit_naive += usize::from(i.mean.abs() <= naive);
                width += i.std_error / exact.sqrt() / runs as f64;
            }
            eprintln!(
                "n = {n}, φ_b = {phi}: coverage {:.3} (without the τ correction {:.3}), mean \
                 standard error / exact {width:.2}",
                hit as f64 / runs as f64,
                hit_naive as f64 / runs as f64
            );
        }
    }
}
