//! The confidence intervals of the summaries of synthetic runs.
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
