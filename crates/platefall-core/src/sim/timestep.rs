//! Time-step control of the coupled loop (docs/physics.md §6 "Time step").
use super::spec::TimeControl;

/// Largest growth of Δt from one step to the next.
pub const MAX_GROWTH: f64 = 1.2;

/// Chooses Δt at time `t`: the flow's own stability limit, the ceiling, the dissertation's rotation rule
/// Δt·|θ̇| ≤ C_c, at most [`MAX_GROWTH`] × the previous step (`dt_prev`, 0 before the first step),
/// landing exactly on the release time and on t_end without leaving a sliver of a step.
pub fn choose_dt(
    t: f64,
    flow_limit: f64,
    omega: f64,
    dt_prev: f64,
    release: f64,
    time: &TimeControl,
) -> f64 {
    let mut dt = flow_limit.min(time.dt_max);
    if omega != 0.0 {
        dt = dt.min(time.cc / omega.abs());
    }
    if dt_prev > 0.0 {
        dt = dt.min(MAX_GROWTH * dt_prev);
    }
    for target in [release, time.t_end] {
        dt = land(t, dt, target);
    }
    dt
}

/// The step `dt` from `t` shortened to land exactly on `target` without leaving a sliver: the
/// whole remainder when it is at most `dt`, half of it when it is less than two steps; `dt`
/// itself when the target is farther or already passed.
pub fn land(t: f64, dt: f64, target: f64) -> f64 {
    let remaining = target - t;
    if remaining > 1e-9 {
        if remaining <= dt {
            return remaining;
        } else if remaining < 2.0 * dt {
            return 0.5 * remaining;
        }
    }
    dt
}

#[cfg(test)]
mod tests {
    use super::*;

    fn time(t_end: f64) -> TimeControl {
        TimeControl {
            t_end,
            turns: None,
            dt_max: 0.01,
            cc: 0.005,
            average_from_turn: 1,
        }
    }

    #[test]
    fn the_smallest_limit_wins() {
        let tc = time(100.0);
        // Flow limit below everything else.
        assert_eq!(choose_dt(1.0, 0.002, 0.0, 0.002, 0.0, &tc), 0.002);
        // The ceiling.
        assert_eq!(choose_dt(1.0, 1.0, 0.0, 0.01, 0.0, &tc), 0.01);
        // The rotation rule Δt|θ̇| = C_c, either sense of rotation.
        assert_eq!(choose_dt(1.0, 1.0, 2.5, 0.01, 0.0, &tc), 0.002);
        assert_eq!(choose_dt(1.0, 1.0, -2.5, 0.01, 0.0, &tc), 0.002);
    }

    #[test]
    fn growth_is_capped_at_twenty_percent() {
        let tc = time(100.0);
        let dt = choose_dt(1.0, 1.0, 0.0, 0.001, 0.0, &tc);
        assert!((dt - 0.0012).abs() < 1e-15, "{dt}");
        // No previous step: no cap.
        assert_eq!(choose_dt(0.0, 1.0, 0.0, 0.0, 0.0, &tc), 0.01);
    }

    #[test]
    fn steps_land_on_release_and_end_without_slivers() {
        let tc = time(10.0);
        // Within one step of the release: land on it.
        assert!((choose_dt(4.995, 1.0, 0.0, 0.01, 5.0, &tc) - 0.005).abs() < 1e-12);
        // Between one and two steps away: halve the remainder, so no sliver is left.
        let dt = choose_dt(4.985, 1.0, 0.0, 0.01, 5.0, &tc);
        assert!((dt - 0.0075).abs() < 1e-12, "{dt}");
        // The same for the end time.
        assert!((choose_dt(9.996, 1.0, 0.0, 0.01, 0.0, &tc) - 0.004).abs() < 1e-12);
        // A release already passed does not limit.
        assert_eq!(choose_dt(6.0, 1.0, 0.0, 0.01, 5.0, &tc), 0.01);
    }
}
