//! What a run's intervals say about its length (docs/statistics.md "Planning"): how many of its
//! observations (whole turns, batches) the mean rotation rate, speed and glide angle need, in all,
//! for a 95 % half-width of 2 % of the mean, assuming the observations stay as correlated as they
//! were ([`crate::ensemble::single_run_length`]).
use crate::ensemble::single_run_length;
use crate::keys::{IntervalInfo, IntervalKeys};
use crate::stats::Interval;

/// The relative half-width the planning line aims at.
pub const TARGET: f64 = 0.02;

/// The observations `info`'s mean needs for a half-width of [`TARGET`] of its value; None
/// without an interval, or when the interval holds zero (a relative width of a mean whose sign
/// is not known asks for no length in particular).
pub fn observations_for_target(info: &IntervalInfo) -> Option<f64> {
    let (hw, t, n_eff) = (info.half_width?, info.t?, info.n_eff?);
    if covers_zero(info) {
        return None;
    }
    let interval = Interval {
        mean: info.value,
        half_width: hw,
        std_error: hw / t,
        samples: info.count,
        tau: info.count as f64 / n_eff,
        n_eff,
        dof: info.dof?,
        t,
    };
    single_run_length(&interval, info.count as f64, TARGET * info.value.abs())
}

/// Whether `info`'s interval holds zero.
fn covers_zero(info: &IntervalInfo) -> bool {
    info.half_width.is_some_and(|hw| hw >= info.value.abs())
}

/// "for ±2 % (95 %) average over: θ̇ about 41, V within it now, γ about 13 whole turns (this run:
/// 10), …", for a coupled run's θ̇, V and γ (from its summary's `ci`); a mean whose interval
/// holds zero (a fluttering plate's θ̇) is named as such. None when none of them has an
/// interval away from zero.
pub fn planning_line(ci: &IntervalKeys) -> Option<String> {
    let mut parts = Vec::new();
    let mut unit: Option<(&str, usize)> = None;
    for (key, name) in [
        ("mean_omega", "θ̇"),
        ("mean_speed", "V"),
        ("mean_gamma", "γ"),
    ] {
        let Some(info) = ci.intervals.get(key) else {
            continue;
        };
        if covers_zero(info) {
            parts.push(format!("{name} zero within its interval"));
            continue;
        }
        let Some(needed) = observations_for_target(info) else {
            continue;
        };
        unit.get_or_insert((info.observations.as_str(), info.count));
        parts.push(if info.half_width? <= TARGET * info.value.abs() {
            format!("{name} within it now")
        } else {
            format!("{name} about {:.0}", needed.ceil())
        });
    }
    let (observations, count) = unit?;
    Some(format!(
        "for ±{:.0} % (95 %) average over: {} {observations} (this run: {count}), if they stay as \
         correlated\n",
        100.0 * TARGET,
        parts.join(", ")
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stats::t95;

    fn info(value: f64, half_width: f64, count: usize, n_eff: f64) -> IntervalInfo {
        let dof = n_eff - 1.0;
        IntervalInfo {
            value,
            half_width: Some(half_width),
            observations: "whole turns".into(),
            count,
            n_eff: Some(n_eff),
            dof: Some(dof),
            t: Some(t95(dof)),
            ..IntervalInfo::default()
        }
    }

    #[test]
    fn the_planned_length_gives_two_percent_by_the_intervals_own_rule() {
        // ±10 % over 10 independent turns: the half-width t(n − 1) s/√n with s fixed by the
        // pilot reaches 2 % of the mean at the planned n (about 25 × 10 × (1.96/2.26)²).
        let i = info(1.0, 0.1, 10, 10.0);
        let n = observations_for_target(&i).unwrap();
        let s = 0.1 / t95(9.0) * 10f64.sqrt();
        let width = t95(n - 1.0) * s / n.sqrt();
        assert!((width - 0.02).abs() < 1e-6, "n {n}: width {width}");
        assert!((180.0..200.0).contains(&n), "{n}");
        // Correlated turns (n_eff half the count) need as many effective ones, twice the turns.
        let n2 = observations_for_target(&info(1.0, 0.1, 20, 10.0)).unwrap();
        assert!((n2 - 2.0 * n).abs() < 1e-3 * n, "{n2} against {n}");
    }

    #[test]
    fn the_line_names_each_quantity_or_says_it_is_within_now() {
        let mut ci = IntervalKeys::default();
        ci.intervals
            .insert("mean_omega".into(), info(2.0, 0.2, 10, 10.0));
        ci.intervals
            .insert("mean_speed".into(), info(1.5, 0.01, 10, 10.0));
        let line = planning_line(&ci).unwrap();
        assert!(
            line.starts_with("for ±2 % (95 %) average over: θ̇ about 1"),
            "{line}"
        );
        assert!(
            line.contains("V within it now") && line.contains("(this run: 10)"),
            "{line}"
        );
        assert!(!line.contains('γ'), "{line}");
        assert!(planning_line(&IntervalKeys::default()).is_none());
        // A fluttering plate's θ̇ (−0.00009 ± 0.00044) asks for no relative width.
        let flutter = info(-0.00009, 0.00044, 6, 6.0);
        assert!(observations_for_target(&flutter).is_none());
        ci.intervals.insert("mean_omega".into(), flutter);
        let line = planning_line(&ci).unwrap();
        assert!(
            line.contains("θ̇ zero within its interval, V within it now"),
            "{line}"
        );
        ci.intervals.remove("mean_speed");
        assert!(planning_line(&ci).is_none(), "nothing to plan");
    }
}
