//! The bounded per-step history (`sim/history.rs`) in a real run: the summary computed from a
//! history thinned 16-fold agrees with the one from every step (means exact over the retained
//! window, which may start a few steps later; extremes exact), and the step count is the run's.
mod common;

use platefall_core::config::RunBuilder;
use platefall_core::sim::{History, Quantity, RunRecord};
use platefall_post::summary::summarize;

#[test]
fn the_summary_from_a_thinned_history_agrees_with_the_full_one() {
    let config = RunBuilder::forced(2.0).spinup(1.0).resolution(8).t_end(6.0);
    let (cfg, rec, full) = common::run(config.build().unwrap());
    assert_eq!(rec.samples.stride(), 1, "the run fits the default capacity");
    let mut thin = History::with_capacity(256);
    rec.samples.iter().for_each(|s| thin.push(*s));
    assert!(thin.stride() >= 8 && thin.len() <= 256, "{}", thin.stride());
    let thinned = RunRecord {
        status: rec.status.clone(),
        samples: thin,
        t_release: rec.t_release,
        cells: rec.cells,
        recirculation_length: rec.recirculation_length,
    };
    let sum = summarize(&cfg, &thinned, 0.0);
    assert_eq!(sum.steps, full.steps);
    assert_eq!(sum.steps, rec.samples.total_steps());
    let close = |name: &str, a: Option<f64>, b: Option<f64>, tol: f64| {
        let (a, b) = (a.unwrap(), b.unwrap());
        eprintln!("{name}: full {a:.6}, thinned {b:.6}");
        assert!(
            (a - b).abs() <= tol * a.abs().max(1.0),
            "{name}: {a} vs {b}"
        );
    };
    close("mean C_L", full.mean_cl, sum.mean_cl, 0.01);
    close("mean C_D", full.mean_cd, sum.mean_cd, 0.01);
    close("mean C_M", full.mean_cm, sum.mean_cm, 0.01);
    close("mean omega", full.mean_omega, sum.mean_omega, 1e-9);
    close("max C_L", full.max_cl, sum.max_cl, 0.01);
    // Counted from the first retained sample after the release: up to a stride later.
    close("revolutions", full.revolutions, sum.revolutions, 0.01);
    // Over the whole run (both ends retained) the thinned history is exact.
    let (t0, t1) = (rec.samples[0].t, rec.samples.last().unwrap().t);
    let a = rec.samples.mean(Quantity::Cl, t0, t1).unwrap();
    let b = thinned.samples.mean(Quantity::Cl, t0, t1).unwrap();
    assert!((a - b).abs() < 1e-12, "{a} vs {b}");
    assert_eq!(
        rec.samples.range(Quantity::Cd, t0, t1),
        thinned.samples.range(Quantity::Cd, t0, t1)
    );
}
