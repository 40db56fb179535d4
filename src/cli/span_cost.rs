//! Where a 3-D run's time went (docs/three-d.md "Cost"): a clock the flow's phase marker reads
//! at every phase boundary of a step, and the line printed at the end of the run: nanoseconds
//! per cell per step in each phase, and the rest (the body, outputs, recording snapshots,
//! checkpoints).
use std::sync::{Arc, Mutex, PoisonError};
use std::time::Instant;

use platefall_core::flow3d::{Phase3, PhaseMarker};

/// The seconds spent in each timed phase ([`Phase3::TIMED`]), summed over the steps.
#[derive(Clone)]
pub(super) struct PhaseClock(Arc<Mutex<(Instant, [f64; 5])>>);

impl PhaseClock {
    pub(super) fn new() -> PhaseClock {
        PhaseClock(Arc::new(Mutex::new((Instant::now(), [0.0; 5]))))
    }

    /// The marker to install in the flow.
    pub(super) fn marker(&self) -> PhaseMarker {
        let clock = self.clone();
        Box::new(move |phase| {
            let mut st = clock.0.lock().unwrap_or_else(PoisonError::into_inner);
            let now = Instant::now();
            if let Some(k) = Phase3::TIMED.iter().position(|p| *p == phase) {
                st.1[k] += (now - st.0).as_secs_f64();
            }
            st.0 = now;
        })
    }

    /// The seconds of each timed phase so far.
    pub(super) fn seconds(&self) -> [f64; 5] {
        self.0.lock().unwrap_or_else(PoisonError::into_inner).1
    }
}

/// One line: the whole step's cost and each phase's, in ns per cell per step and per cent of
/// `wall`, the rest being everything outside the flow's step.
pub(super) fn cost_line(seconds: [f64; 5], wall: f64, steps: u64, cells: usize) -> Option<String> {
    if steps == 0 || cells == 0 || wall <= 0.0 {
        return None;
    }
    let per = |s: f64| s / (steps as f64 * cells as f64) * 1e9;
    let rest = (wall - seconds.iter().sum::<f64>()).max(0.0);
    let parts = Phase3::TIMED
        .iter()
        .map(|p| p.name())
        .zip(seconds)
        .chain([("body, outputs and recording", rest)]);
    let list: Vec<String> = parts
        .map(|(name, s)| format!("{name} {:.0} ({:.0} %)", per(s), 100.0 * s / wall))
        .collect();
    Some(format!(
        "cost: {:.0} ns per cell per step over {steps} steps: {}",
        per(wall),
        list.join(", ")
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_phases_and_the_rest_add_up_to_the_wall_time() {
        // 10 steps of 1000 cells in 10 s: 1e6 ns per cell per step.
        let line = cost_line([2.0, 0.5, 0.5, 5.0, 1.0], 10.0, 10, 1000).unwrap();
        assert!(
            line.starts_with("cost: 1000000 ns per cell per step over 10 steps"),
            "{line}"
        );
        assert!(line.contains("pressure 500000 (50 %)"), "{line}");
        assert!(line.contains("recording 100000 (10 %)"), "{line}");
        assert!(cost_line([0.0; 5], 10.0, 0, 1000).is_none());
    }

    #[test]
    fn the_marker_adds_each_phase_s_time_to_its_slot() {
        let clock = PhaseClock::new();
        let mut mark = clock.marker();
        mark(Phase3::Begin);
        std::thread::sleep(std::time::Duration::from_millis(20));
        mark(Phase3::RightHandSide);
        mark(Phase3::Predictor);
        let s = clock.seconds();
        assert!(
            s[0] >= 0.02 && s[1] < s[0] && s[2..].iter().all(|&x| x == 0.0),
            "{s:?}"
        );
    }
}
