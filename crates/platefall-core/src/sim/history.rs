//! The per-step history of a run, bounded in memory (docs/physics.md §8 needs the whole time series only
//! through means, extremes, turn times and a spectrum).
//!
//! Every step is pushed; at most `capacity` samples are retained. When full, every other retained
//! sample is dropped and the stride between retained steps doubles, so the retained samples are
//! always the steps 0, s, 2s, 3s, … (s = [`History::stride`]) plus the latest step. Nothing is
//! lost for the statistics of the summary:
//!
//! - a running time integral (trapezoidal, compensated summation) of every [`Quantity`] over
//!   *all* steps is stored at each retained sample, so [`History::mean`] over a window whose ends
//!   are retained samples is exactly the trapezoidal mean over every step in it;
//! - each retained sample keeps the smallest and largest value of every quantity over the steps
//!   since the previous retained one, so [`History::range`] is exact over the same windows.
//!
//! Everything else (turn counting, the lift spectrum, lags between peaks) reads the retained
//! samples, which the history dereferences to (`&[StepSample]`, in time order).
use std::ops::Deref;

use super::sample::StepSample;

/// Retained samples when none is given: ≈ 13 MB at most (32 768 × 408 bytes); runs up to this
/// many steps keep every step.
pub const DEFAULT_CAPACITY: usize = 1 << 15;

/// The scalars of a [`StepSample`] whose exact means and extremes the history keeps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    /// C_L.
    Cl,
    /// C_D.
    Cd,
    /// C_M.
    Cm,
    /// X.
    X,
    /// Y.
    Y,
    /// θ.
    Theta,
    /// Ẋ.
    Xdot,
    /// Ẏ.
    Ydot,
    /// θ̇.
    Omega,
    /// V.
    Speed,
    /// γ.
    Gamma,
    /// α.
    Alpha,
}

const Q: usize = 12;

impl Quantity {
    /// Every quantity, in the order of their storage.
    pub const ALL: [Quantity; Q] = [
        Quantity::Cl,
        Quantity::Cd,
        Quantity::Cm,
        Quantity::X,
        Quantity::Y,
        Quantity::Theta,
        Quantity::Xdot,
        Quantity::Ydot,
        Quantity::Omega,
        Quantity::Speed,
        Quantity::Gamma,
        Quantity::Alpha,
    ];

    /// The quantity's value in a sample.
    pub fn of(self, s: &StepSample) -> f64 {
        match self {
            Quantity::Cl => s.cl,
            Quantity::Cd => s.cd,
            Quantity::Cm => s.cm,
            Quantity::X => s.x,
            Quantity::Y => s.y,
            Quantity::Theta => s.theta,
            Quantity::Xdot => s.xdot,
            Quantity::Ydot => s.ydot,
            Quantity::Omega => s.omega,
            Quantity::Speed => s.speed,
            Quantity::Gamma => s.gamma,
            Quantity::Alpha => s.alpha,
        }
    }

    fn values(s: &StepSample) -> [f64; Q] {
        Self::ALL.map(|q| q.of(s))
    }
}

/// What a retained sample knows about the steps since the previous retained one.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
struct Bucket {
    /// Index of the sample among all steps pushed (0-based).
    index: u64,
    /// ∫ q dt from the first step to this one, over every step.
    integral: [f64; Q],
    /// Extremes of q over the steps after the previous retained sample, up to this one.
    lo: [f64; Q],
    hi: [f64; Q],
}

impl Bucket {
    fn absorb(&mut self, earlier: &Bucket) {
        for k in 0..Q {
            self.lo[k] = self.lo[k].min(earlier.lo[k]);
            self.hi[k] = self.hi[k].max(earlier.hi[k]);
        }
    }
}

/// A bounded history of the steps of a run; see the module docs. Its serde form is the whole
/// state (retained samples, their integrals and extremes, the running sums), so a history read
/// back from a checkpoint goes on exactly as the saved one would have.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct History {
    samples: Vec<StepSample>,
    buckets: Vec<Bucket>,
    capacity: usize,
    stride: u64,
    total: u64,
    /// Running integrals and their compensation terms (Kahan–Babuška).
    sum: [f64; Q],
    carry: [f64; Q],
}

impl Default for History {
    fn default() -> Self {
        History::with_capacity(DEFAULT_CAPACITY)
    }
}

impl Deref for History {
    type Target = [StepSample];
    /// The retained samples, in time order (the first and the latest step always among them).
    fn deref(&self) -> &[StepSample] {
        &self.samples
    }
}

impl History {
    /// A history retaining at most `capacity` samples (at least 4).
    pub fn with_capacity(capacity: usize) -> Self {
        History {
            samples: Vec::new(),
            buckets: Vec::new(),
            capacity: capacity.max(4),
            stride: 1,
            total: 0,
            sum: [0.0; Q],
            carry: [0.0; Q],
        }
    }

    /// Steps pushed so far (the run's step count; `len()` is the retained count).
    pub fn total_steps(&self) -> u64 {
        self.total
    }

    /// Steps between retained samples (1 until the history first fills).
    pub fn stride(&self) -> u64 {
        self.stride
    }

    /// The most samples ever retained.
    pub fn capacity(&self) -> usize {
        self.capacity
    }

    /// Adds the next step (samples must come in time order).
    pub fn push(&mut self, s: StepSample) {
        let v = Quantity::values(&s);
        if let Some(prev) = self.samples.last() {
            let (pv, dt) = (Quantity::values(prev), s.t - prev.t);
            for k in 0..Q {
                self.add(k, 0.5 * (pv[k] + v[k]) * dt);
            }
        }
        let mut bucket = Bucket {
            index: self.total,
            integral: std::array::from_fn(|k| self.sum[k] + self.carry[k]),
            lo: v,
            hi: v,
        };
        self.total += 1;
        // The latest step is always retained; the previous latest only if it is on the stride.
        if let Some(tail) = self.buckets.last().copied() {
            if tail.index % self.stride != 0 {
                bucket.absorb(&tail);
                self.samples.pop();
                self.buckets.pop();
            }
        }
        self.reserve_one();
        self.samples.push(s);
        self.buckets.push(bucket);
        if self.samples.len() > self.capacity {
            self.decimate();
        }
    }

    /// Compensated addition to the running integral of quantity `k`.
    fn add(&mut self, k: usize, x: f64) {
        let t = self.sum[k] + x;
        if self.sum[k].abs() >= x.abs() {
            self.carry[k] += (self.sum[k] - t) + x;
        } else {
            self.carry[k] += (x - t) + self.sum[k];
        }
        self.sum[k] = t;
    }

    /// Grows the storage by doubling, but never past capacity + 1.
    fn reserve_one(&mut self) {
        let len = self.samples.len();
        if len == self.samples.capacity() {
            let room = (self.capacity + 1).saturating_sub(len).max(1);
            let extra = len.max(16).min(room);
            self.samples.reserve_exact(extra);
            self.buckets.reserve_exact(extra);
        }
    }

    /// Doubles the stride: keeps the samples on it (and the latest), folding the extremes of
    /// the dropped ones into the next retained sample.
    fn decimate(&mut self) {
        self.stride *= 2;
        let n = self.samples.len();
        let mut kept = 0;
        let mut pending: Option<Bucket> = None;
        for r in 0..n {
            let mut b = self.buckets[r];
            if let Some(p) = pending.take() {
                b.absorb(&p);
            }
            if b.index % self.stride == 0 || r == n - 1 {
                self.buckets[kept] = b;
                self.samples[kept] = self.samples[r];
                kept += 1;
            } else {
                pending = Some(b);
            }
        }
        self.samples.truncate(kept);
        self.buckets.truncate(kept);
    }

    /// Indices of the first and last retained samples inside [t0, t1] (1e-12 tolerance).
    fn span(&self, t0: f64, t1: f64) -> Option<(usize, usize)> {
        let a = self.samples.partition_point(|s| s.t < t0 - 1e-12);
        let b = self.samples.partition_point(|s| s.t <= t1 + 1e-12);
        (b > a).then_some((a, b - 1))
    }

    /// Time-weighted (trapezoidal) mean of `q` over every step between the first and the last
    /// retained samples inside [t0, t1]: exact over windows whose ends are retained samples.
    /// None if the window holds less than two retained samples.
    pub fn mean(&self, q: Quantity, t0: f64, t1: f64) -> Option<f64> {
        let (a, b) = self.span(t0, t1)?;
        let span = self.samples[b].t - self.samples[a].t;
        let k = q as usize;
        (span > 0.0).then(|| (self.buckets[b].integral[k] - self.buckets[a].integral[k]) / span)
    }

    /// Smallest and largest `q` over every step between the first and the last retained samples
    /// inside [t0, t1].
    pub fn range(&self, q: Quantity, t0: f64, t1: f64) -> Option<(f64, f64)> {
        let (a, b) = self.span(t0, t1)?;
        let k = q as usize;
        let first = q.of(&self.samples[a]);
        let inner = &self.buckets[a + 1..=b];
        let lo = inner.iter().map(|x| x.lo[k]).fold(first, f64::min);
        let hi = inner.iter().map(|x| x.hi[k]).fold(first, f64::max);
        Some((lo, hi))
    }
}

impl<'a> IntoIterator for &'a History {
    type Item = &'a StepSample;
    type IntoIter = std::slice::Iter<'a, StepSample>;
    /// The retained samples, as for a `Vec<StepSample>`.
    fn into_iter(self) -> Self::IntoIter {
        self.samples.iter()
    }
}

impl FromIterator<StepSample> for History {
    /// A history of the default capacity holding `iter`'s samples.
    fn from_iter<I: IntoIterator<Item = StepSample>>(iter: I) -> Self {
        let mut h = History::default();
        iter.into_iter().for_each(|s| h.push(s));
        h
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A wiggly signal with a sharp spike at step 777 (which decimation must not lose).
    fn series(n: usize) -> Vec<StepSample> {
        (0..n)
            .map(|k| {
                let t = 0.01 * k as f64 + 1e-4 * ((k * 7919) % 13) as f64;
                let spike = if k == 777 { 50.0 } else { 0.0 };
                StepSample {
                    step: k as u64,
                    t,
                    cl: (3.0 * t).sin() + spike,
                    cd: 1.0 + t.cos(),
                    ..Default::default()
                }
            })
            .collect()
    }

    /// Trapezoidal mean and extremes over every sample with t in [t0, t1].
    fn brute(all: &[StepSample], t0: f64, t1: f64) -> (f64, f64, f64) {
        let inside: Vec<&StepSample> = all.iter().filter(|s| s.t >= t0 && s.t <= t1).collect();
        let acc: f64 = inside
            .windows(2)
            .map(|p| 0.5 * (p[0].cl + p[1].cl) * (p[1].t - p[0].t))
            .sum();
        let mean = acc / (inside.last().unwrap().t - inside[0].t);
        let lo = inside.iter().map(|s| s.cl).fold(f64::INFINITY, f64::min);
        let hi = inside
            .iter()
            .map(|s| s.cl)
            .fold(f64::NEG_INFINITY, f64::max);
        (mean, lo, hi)
    }

    #[test]
    fn a_history_that_never_fills_keeps_every_step() {
        let all = series(500);
        let h: History = all.iter().copied().collect();
        assert_eq!(h.len(), 500);
        assert_eq!(h.stride(), 1);
        let (mean, lo, hi) = brute(&all, 1.0, 4.0);
        assert!((h.mean(Quantity::Cl, 1.0, 4.0).unwrap() - mean).abs() < 1e-13);
        assert_eq!(h.range(Quantity::Cl, 1.0, 4.0), Some((lo, hi)));
    }

    #[test]
    fn a_full_history_stays_bounded_and_exact_between_retained_samples() {
        let all = series(10_000);
        let mut h = History::with_capacity(64);
        all.iter().for_each(|s| h.push(*s));
        assert!(h.len() <= 64 && h.len() > 32, "{}", h.len());
        assert_eq!(h.total_steps(), 10_000);
        assert_eq!(h.first().unwrap().step, 0);
        assert_eq!(h.last().unwrap().step, 9_999, "the latest step is kept");
        assert!(h.iter().rev().skip(1).all(|s| s.step % h.stride() == 0));
        // Windows ending on retained samples: exact means and extremes over every step.
        for (a, b) in [(0, h.len() - 1), (3, 20), (1, h.len() - 2)] {
            let (t0, t1) = (h[a].t, h[b].t);
            let (mean, lo, hi) = brute(&all, t0, t1);
            let m = h.mean(Quantity::Cl, t0, t1).unwrap();
            assert!((m - mean).abs() < 1e-12, "{m} vs {mean}");
            assert_eq!(h.range(Quantity::Cl, t0, t1), Some((lo, hi)));
        }
        let (_, _, hi) = brute(&all, 0.0, 1e9);
        assert_eq!(h.range(Quantity::Cl, 0.0, 1e9).unwrap().1, hi);
        assert!(hi > 49.0, "the spike survives decimation");
    }
}
