//! When field snapshots are due: the first step, then every multiple of a convective interval.

/// A cadence of snapshots every `every` convective times (see [`Cadence::due`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cadence {
    every: f64,
    next: f64,
}

impl Cadence {
    /// Every `every` (> 0) convective times, starting at the first time asked.
    pub fn new(every: f64) -> Cadence {
        Cadence {
            every,
            next: f64::NEG_INFINITY,
        }
    }

    /// The interval.
    pub fn every(&self) -> f64 {
        self.every
    }

    /// True if a snapshot is due at time `t` (the first call always is; then at the first time
    /// at or past each multiple of the interval). A true answer moves on to the next multiple,
    /// so ask once per step.
    pub fn due(&mut self, t: f64) -> bool {
        let fe = self.every;
        let eps = 1e-9 * fe.max(1.0);
        if t + eps >= self.next {
            self.next = ((t + eps) / fe).floor() * fe + fe;
            true
        } else {
            false
        }
    }
}
