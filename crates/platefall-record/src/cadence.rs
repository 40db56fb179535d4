//! When snapshots are due (flow fields, VTK files, checkpoints): the first step, then every
//! multiple of a convective interval.

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
        if t + self.eps() >= self.next {
            self.skip_to(t);
            true
        } else {
            false
        }
    }

    /// Goes on after time `t` as if a snapshot had been taken at `t` (a resumed run).
    pub fn skip_to(&mut self, t: f64) {
        let fe = self.every;
        self.next = ((t + self.eps()) / fe).floor() * fe + fe;
    }

    fn eps(&self) -> f64 {
        1e-9 * self.every.max(1.0)
    }
}
