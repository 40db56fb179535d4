//! What a falling plate is doing: its motion regime from the pitch angle θ(t) (docs/physics.md §1 case D, §6;
//! the regimes of falling-plate experiments). Pure functions on a window of samples.
//!
//! The rule, over the window (the second half of the time after release, see
//! [`regime_window`]):
//!
//! 1. **steady** when θ stays within ±[`STEADY_AMPLITUDE`] of its midpoint (steady descent);
//! 2. otherwise θ is cut into *runs* between reversals: a run ends when θ comes back from its
//!    extreme by more than [`REVERSAL`]. A run that advances by 2π or more is a full turn (counted
//!    per sign, one per 2π);
//! 3. full turns of **both signs** → **chaotic**;
//! 4. full turns of one sign → the plate turns: the times θ crosses each successive multiple of π
//!    (from the window's first θ, in the turning sense) give half-turn durations; with at least
//!    [`MIN_CYCLES`] of them and a coefficient of variation at most [`REGULAR_CV`] it is
//!    **tumbling** (period: one full turn, twice the mean half-turn), else **chaotic**;
//! 5. no full turn → θ oscillates: the up-crossings of its midpoint (with a hysteresis of
//!    [`CROSSING_HYSTERESIS`] of the amplitude) give cycle durations; with at least
//!    [`MIN_CYCLES`] of them and a coefficient of variation at most [`REGULAR_CV`] it is
//!    **fluttering** (period: one full oscillation), else **chaotic**;
//! 6. fewer than [`MIN_CYCLES`] durations in 4 or 5 → **undetermined** (the window is too short).
//!
//! The amplitude of the angle is half its peak-to-peak range over the window when there is no full
//! turn (steady, fluttering, or chaotic without turns), and undefined when the plate turns.
use std::f64::consts::PI;

use super::analysis::TimeWindow;
use platefall_core::sim::StepSample;

/// Half peak-to-peak of θ below which the descent counts as steady (rad, ≈ 1.1°).
pub const STEADY_AMPLITUDE: f64 = 0.02;
/// A run of θ ends when θ comes back this far from its extreme (rad).
pub const REVERSAL: f64 = 0.1;
/// Hysteresis of the midpoint crossings, as a fraction of the amplitude.
pub const CROSSING_HYSTERESIS: f64 = 0.2;
/// Largest coefficient of variation of the cycle durations for a dominant period.
pub const REGULAR_CV: f64 = 0.25;
/// Fewest cycle (or half-turn) durations that can show a dominant period.
pub const MIN_CYCLES: usize = 2;

/// The motion regimes of a falling plate (rule in the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Regime {
    /// θ stays within ±0.02 rad of its midpoint.
    Steady,
    /// θ oscillates without a full turn, with regular periods.
    Fluttering,
    /// Full turns in one sense with regular half-turn durations.
    Tumbling,
    /// Full turns in both senses, or irregular oscillations or turns.
    Chaotic,
    /// Too few oscillations or turns in the window to tell.
    Undetermined,
}

impl Regime {
    /// Every regime, in the order of the rule.
    pub const ALL: [Regime; 5] = [
        Regime::Steady,
        Regime::Fluttering,
        Regime::Tumbling,
        Regime::Chaotic,
        Regime::Undetermined,
    ];

    /// The name summaries write: `steady`, `fluttering`, `tumbling`, `chaotic`, `undetermined`.
    pub fn name(self) -> &'static str {
        match self {
            Regime::Steady => "steady",
            Regime::Fluttering => "fluttering",
            Regime::Tumbling => "tumbling",
            Regime::Chaotic => "chaotic",
            Regime::Undetermined => "undetermined",
        }
    }
}

/// The classification of a window of motion.
#[derive(Clone, Debug, PartialEq)]
pub struct MotionClass {
    /// What the plate is doing in the window.
    pub regime: Regime,
    /// Fluttering: one full oscillation of θ; turning: one full turn (2π); in c/U.
    pub period: Option<f64>,
    /// Half the peak-to-peak range of θ when there is no full turn (rad).
    pub amplitude: Option<f64>,
    /// Full turns counter-clockwise and clockwise.
    pub turns: (usize, usize),
}

impl MotionClass {
    /// Whether the plate made full turns in both senses: its whole turns are then not cycles of the
    /// motion, and a run's means are taken over time rather than over whole turns.
    pub fn turns_both_ways(&self) -> bool {
        self.turns.0 > 0 && self.turns.1 > 0
    }
}

/// The window the regime is judged on: the second half of the time after release.
pub fn regime_window(samples: &[StepSample], t_release: f64) -> Option<TimeWindow> {
    let t1 = samples.last()?.t;
    (t1 > t_release).then_some(TimeWindow {
        t0: t_release + 0.5 * (t1 - t_release),
        t1,
    })
}

/// Classifies the motion of the samples inside `w` (rule in the module docs).
pub fn classify(samples: &[StepSample], w: TimeWindow) -> MotionClass {
    let pts: Vec<(f64, f64)> = samples
        .iter()
        .filter(|s| s.t >= w.t0 - 1e-12 && s.t <= w.t1 + 1e-12)
        .map(|s| (s.t, s.theta))
        .collect();
    let (lo, hi) = pts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.1), b.max(p.1))
        });
    let amplitude = 0.5 * (hi - lo);
    if pts.len() < 2 || amplitude < STEADY_AMPLITUDE {
        return MotionClass {
            regime: Regime::Steady,
            period: None,
            amplitude: (pts.len() >= 2).then_some(amplitude),
            turns: (0, 0),
        };
    }
    let turns = full_turns(&pts);
    let (regime, period) = match turns {
        (p, n) if p > 0 && n > 0 => (Regime::Chaotic, None),
        (p, n) if p + n > 0 => {
            let dir = if p > 0 { 1.0 } else { -1.0 };
            periodic(&half_turn_times(&pts, dir), Regime::Tumbling, 2.0)
        }
        _ => {
            let mid = 0.5 * (lo + hi);
            let up = up_crossings(&pts, mid, CROSSING_HYSTERESIS * amplitude);
            periodic(&up, Regime::Fluttering, 1.0)
        }
    };
    MotionClass {
        regime,
        period,
        amplitude: (turns == (0, 0)).then_some(amplitude),
        turns,
    }
}

/// `regular` with the mean duration × `per` as its period when the event times are at least
/// [`MIN_CYCLES`] durations with a coefficient of variation ≤ [`REGULAR_CV`]; chaotic when they
/// are irregular; undetermined when too few.
fn periodic(events: &[f64], regular: Regime, per: f64) -> (Regime, Option<f64>) {
    let d: Vec<f64> = events.windows(2).map(|e| e[1] - e[0]).collect();
    if d.len() < MIN_CYCLES {
        return (Regime::Undetermined, None);
    }
    let n = d.len() as f64;
    let mean = d.iter().sum::<f64>() / n;
    let sd = (d.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n).sqrt();
    if sd <= REGULAR_CV * mean {
        (regular, Some(per * mean))
    } else {
        (Regime::Chaotic, None)
    }
}

/// Full turns (counter-clockwise, clockwise) over the runs of θ between reversals.
fn full_turns(pts: &[(f64, f64)]) -> (usize, usize) {
    let mut counts = (0, 0);
    let mut add = |excursion: f64| {
        let n = (excursion.abs() / (2.0 * PI)).floor() as usize;
        if excursion > 0.0 {
            counts.0 += n;
        } else {
            counts.1 += n;
        }
    };
    let (mut start, mut extreme, mut dir) = (pts[0].1, pts[0].1, 0.0);
    for &(_, th) in &pts[1..] {
        if dir == 0.0 {
            if (th - start).abs() > REVERSAL {
                dir = (th - start).signum();
                extreme = th;
            }
        } else if dir * (th - extreme) > 0.0 {
            extreme = th;
        } else if dir * (extreme - th) > REVERSAL {
            add(extreme - start);
            (start, extreme, dir) = (extreme, th, -dir);
        }
    }
    if dir != 0.0 {
        add(extreme - start);
    }
    counts
}

/// Times at which θ first passes each successive multiple of π from its first value, turning in
/// the sense `dir`.
fn half_turn_times(pts: &[(f64, f64)], dir: f64) -> Vec<f64> {
    let th0 = pts[0].1;
    let mut next = PI;
    let mut out = Vec::new();
    for &(t, th) in pts {
        while dir * (th - th0) >= next {
            out.push(t);
            next += PI;
        }
    }
    out
}

/// Times at which θ rises through `mid` after having been below `mid − hysteresis`.
fn up_crossings(pts: &[(f64, f64)], mid: f64, hysteresis: f64) -> Vec<f64> {
    let mut armed = false;
    let mut out = Vec::new();
    for &(t, th) in pts {
        if th < mid - hysteresis {
            armed = true;
        } else if armed && th >= mid {
            out.push(t);
            armed = false;
        }
    }
    out
}

/// The event times behind the period of [`classify`] over `w`: the half-turn times when the
/// plate turns, the up-crossings of θ's midpoint when it oscillates (empty when steady, or when it
/// turns both ways). Successive differences are the durations the period is the mean of.
pub fn cycle_events(samples: &[StepSample], w: TimeWindow, class: &MotionClass) -> Vec<f64> {
    let pts: Vec<(f64, f64)> = samples
        .iter()
        .filter(|s| s.t >= w.t0 - 1e-12 && s.t <= w.t1 + 1e-12)
        .map(|s| (s.t, s.theta))
        .collect();
    if pts.len() < 2 || class.regime == Regime::Steady {
        return Vec::new();
    }
    match class.turns {
        (p, n) if p > 0 && n > 0 => Vec::new(),
        (p, n) if p + n > 0 => half_turn_times(&pts, if p > 0 { 1.0 } else { -1.0 }),
        _ => {
            let (lo, hi) = pts
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                    (a.min(p.1), b.max(p.1))
                });
            let amplitude = 0.5 * (hi - lo);
            up_crossings(&pts, 0.5 * (lo + hi), CROSSING_HYSTERESIS * amplitude)
        }
    }
}

/// Times at which the signal `pts` (t, value) rises through `mid` after having been below
/// `mid − hysteresis` (the cycle boundaries of an oscillating signal).
pub fn rising_crossings(pts: &[(f64, f64)], mid: f64, hysteresis: f64) -> Vec<f64> {
    up_crossings(pts, mid, hysteresis)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn motion(theta: impl Fn(f64) -> f64, t_end: f64) -> Vec<StepSample> {
        (0..=((t_end / 0.01) as usize))
            .map(|k| {
                let t = k as f64 * 0.01;
                StepSample {
                    t,
                    theta: theta(t),
                    ..Default::default()
                }
            })
            .collect()
    }

    fn judge(theta: impl Fn(f64) -> f64) -> MotionClass {
        let s = motion(theta, 60.0);
        classify(&s, regime_window(&s, 0.0).unwrap())
    }

    #[test]
    fn a_sine_of_the_angle_flutters_with_its_period_and_amplitude() {
        let c = judge(|t| 0.3 + 0.7 * (2.0 * PI * t / 4.5).sin());
        assert_eq!(c.regime, Regime::Fluttering);
        assert!((c.period.unwrap() - 4.5).abs() < 0.02, "{c:?}");
        assert!((c.amplitude.unwrap() - 0.7).abs() < 1e-3, "{c:?}");
        assert_eq!(c.turns, (0, 0));
        // A large swing that still never completes a turn (±170°) is fluttering too.
        assert_eq!(judge(|t| 2.97 * (t / 1.3).sin()).regime, Regime::Fluttering);
    }

    #[test]
    fn a_steady_ramp_tumbles_with_the_period_of_a_turn() {
        // θ̇ = −2 with a half-turn wobble: clockwise tumbling, one turn in π.
        let c = judge(|t| -2.0 * t + 0.2 * (4.0 * t).sin());
        assert_eq!(c.regime, Regime::Tumbling);
        assert!((c.period.unwrap() - PI).abs() < 0.02, "{c:?}");
        assert!(
            c.amplitude.is_none() && c.turns.0 == 0 && c.turns.1 == 9,
            "{c:?}"
        );
    }

    #[test]
    fn a_ramp_with_reversals_is_chaotic() {
        // Two turns one way, then two the other, repeatedly (period 24: the window holds both).
        let c = judge(|t| {
            let ph = t.rem_euclid(24.0);
            let up = if ph < 12.0 { ph } else { 24.0 - ph };
            4.0 * PI * up / 12.0
        });
        assert_eq!(c.regime, Regime::Chaotic, "{c:?}");
        assert!(c.turns.0 >= 1 && c.turns.1 >= 1, "{c:?}");
        // Irregular oscillations without turns: no dominant period.
        let c = judge(|t| 0.5 * (t * 0.9).sin() + 0.6 * (t * 2.17).sin() + 0.4 * (t * 0.31).sin());
        assert_eq!(c.regime, Regime::Chaotic, "{c:?}");
    }

    #[test]
    fn a_constant_angle_is_a_steady_descent() {
        let c = judge(|t| 0.8 + 1e-3 * (3.0 * t).sin());
        assert_eq!(c.regime, Regime::Steady);
        assert!(c.amplitude.unwrap() < 2e-3 && c.period.is_none());
    }

    #[test]
    fn one_slow_swing_is_undetermined() {
        assert_eq!(
            judge(|t| (2.0 * PI * t / 50.0).sin()).regime,
            Regime::Undetermined
        );
    }
}
