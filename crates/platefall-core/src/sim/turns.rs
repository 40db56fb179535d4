//! The turn limit of a free or pinned run (docs/how-it-works.md, the run's end): the run ends once the plate
//! has turned the requested number of net turns since its release. The 2-D run
//! ([`super::Simulation::finished`]) and the 3-D flight (the command line's `free --span`) both
//! stop on it.
use std::f64::consts::PI;

/// Whether `turns` net turns (None: no limit) are done: |θ − θ_release| ≥ 2π turns, with θ
/// unwrapped and θ_release the pitch at the release (None: not released yet).
pub fn turns_done(turns: Option<f64>, theta: f64, theta_release: Option<f64>) -> bool {
    match (turns, theta_release) {
        (Some(n), Some(th)) => (theta - th).abs() >= 2.0 * PI * n,
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn turns_count_either_way_from_the_release_and_not_before_it() {
        assert!(!turns_done(Some(1.0), 10.0, None));
        assert!(!turns_done(None, 10.0, Some(0.0)));
        assert!(turns_done(Some(1.0), 1.0 + 2.0 * PI, Some(1.0)));
        assert!(turns_done(Some(1.0), 1.0 - 2.0 * PI, Some(1.0)));
        assert!(!turns_done(Some(1.0), 1.0 + 2.0 * PI - 1e-9, Some(1.0)));
    }
}
