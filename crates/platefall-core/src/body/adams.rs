//! Variable-step Adams–Bashforth integrator of orders 1..=6 (docs/physics.md §6, "Time integration").
//!
//! For y' = f(t, y), the step t_n → t_n + h is
//!
//! ```text
//!     y_{n+1} = y_n + h Σ_{j=0}^{k-1} β_j f_{n-j},
//!     β_j = (1/h) ∫_{t_n}^{t_n+h} ℓ_j(t) dt,
//! ```
//!
//! where ℓ_j is the Lagrange basis polynomial through the stored derivative times
//! t_n, t_{n-1}, …, t_{n-k+1} (ℓ_j(t_{n-i}) = δ_ij). This is the exact variable-step
//! generalisation of the constant-step table of docs/physics.md §6, to which it reduces when the steps are equal.
//! The derivative comes from a CFD solve, so the caller evaluates it exactly once per step and hands
//! it to [`AdamsBashforth::step`]; the integrator only stores it.

use thiserror::Error;

/// Highest supported order (docs/physics.md §6 table: orders 1–6); also the ring-buffer capacity.
pub const MAX_ORDER: usize = 6;

/// 4-point Gauss–Legendre rule on [−1, 1] (nodes, weights). Exact for polynomials of degree ≤ 7,
/// more than the degree ≤ 5 of the Lagrange basis for order 6, so the β_j are exact up to round-off.
const GAUSS4: [(f64, f64); 4] = [
    (-0.861_136_311_594_052_6, 0.347_854_845_137_453_86),
    (-0.339_981_043_584_856_26, 0.652_145_154_862_546_1),
    (0.339_981_043_584_856_26, 0.652_145_154_862_546_1),
    (0.861_136_311_594_052_6, 0.347_854_845_137_453_86),
];

/// How the integrator behaves while it has fewer than `order` stored derivatives
/// (at the start of a run and after [`AdamsBashforth::reset`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum AbStart {
    /// Use order min(k, number of stored derivatives): the order rises 1, 2, …, k over the first
    /// k steps, using only true derivatives.
    Ramp,
    /// The dissertation's start (docs/physics.md §6, "Time integration": the initial state extrapolated
    /// along a straight line to earlier times):
    /// before a step, missing older history is invented at spacing h (the current step) backwards
    /// from the oldest stored entry, assuming the derivative is a linear function of time.
    /// With two or more stored derivatives the line through the two oldest is continued backwards;
    /// with only one (the usual case: the first step after construction or `reset`) there is no
    /// slope estimate, so the derivative is taken as constant in the past — the history is filled
    /// with copies of `f_now` at t_n − h, t_n − 2h, …, which is exactly "the state moved linearly in
    /// time before the start". The full order k is then used from the first step (whose result, as
    /// Σβ_j = 1, equals a forward-Euler step).
    Extrapolate,
}

/// Errors from constructing or priming an [`AdamsBashforth`] integrator.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum AbError {
    /// The order is outside 1..=6.
    #[error("Adams–Bashforth order must be in 1..={MAX_ORDER}, got {0}")]
    Order(usize),
    /// More primer entries than the history can hold.
    #[error("history primer has {0} entries; at most {MAX_ORDER} fit")]
    PrimeTooLong(usize),
    /// Primer times not finite and strictly increasing.
    #[error("history primer times must be finite and strictly increasing (oldest first)")]
    PrimeTimes,
    /// A saved history does not fit this integrator (another number of components).
    #[error("the saved Adams–Bashforth history does not fit this integrator")]
    HistoryShape,
}

/// Variable-step Adams–Bashforth coefficients β_j (docs/physics.md §6, exact variable-step generalisation of
/// the table): `times[j]` = t_{n−j}, newest first (`times[0]` = t_n), k = `times.len()` in 1..=6,
/// for the step t_n → t_n + h. Entries j ≥ k of the result are zero.
///
/// Computed by mapping [t_n, t_n + h] to s ∈ [0, 1], nodes s_j = (t_{n−j} − t_n)/h, and integrating
/// each Lagrange basis polynomial with a 4-point Gauss–Legendre rule (exact for degree ≤ 7).
///
/// # Panics
/// If k is not in 1..=6 or h is not positive. Distinct times are the caller's responsibility.
pub fn ab_weights(times: &[f64], h: f64) -> [f64; MAX_ORDER] {
    let k = times.len();
    assert!(
        (1..=MAX_ORDER).contains(&k),
        "ab_weights: need 1..=6 times, got {k}"
    );
    assert!(h > 0.0, "ab_weights: step must be positive, got {h}");
    let mut s = [0.0; MAX_ORDER];
    for (sj, tj) in s.iter_mut().zip(times) {
        *sj = (tj - times[0]) / h;
    }
    let mut beta = [0.0; MAX_ORDER];
    for &(xi, wi) in &GAUSS4 {
        let u = 0.5 * (1.0 + xi);
        let w = 0.5 * wi;
        for j in 0..k {
            let mut l = 1.0;
            for m in (0..k).filter(|&m| m != j) {
                l *= (u - s[m]) / (s[j] - s[m]);
            }
            beta[j] += w * l;
        }
    }
    beta
}

/// The stored derivatives of an [`AdamsBashforth`] integrator, as plain data for a checkpoint:
/// the ring buffer exactly as it is, so a restored integrator takes the same steps.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct AbHistory {
    /// The ring's times.
    pub times: [f64; MAX_ORDER],
    /// The ring's derivatives (`MAX_ORDER` entries of N components).
    pub derivs: Vec<Vec<f64>>,
    /// Ring index of the newest entry.
    pub newest: usize,
    /// Entries stored.
    pub len: usize,
}

/// Adams–Bashforth integrator of order k ∈ 1..=6 for an N-component state (docs/physics.md §6), with a
/// fixed-capacity ring buffer of past derivatives (no allocation per step). The coupled solver uses
/// N = 6: (X, Y, θ, Ẋ, Ẏ, θ̇).
#[derive(Debug, Clone)]
pub struct AdamsBashforth<const N: usize> {
    order: usize,
    start: AbStart,
    times: [f64; MAX_ORDER],
    derivs: [[f64; N]; MAX_ORDER],
    /// Ring index of the newest entry (meaningful when `len > 0`).
    newest: usize,
    len: usize,
}

impl<const N: usize> AdamsBashforth<N> {
    /// A new integrator of the given order (1..=6, docs/physics.md §6 table) with an empty history.
    ///
    /// # Errors
    /// [`AbError::Order`] when `order` is outside 1..=6.
    pub fn new(order: usize, start: AbStart) -> Result<Self, AbError> {
        if !(1..=MAX_ORDER).contains(&order) {
            return Err(AbError::Order(order));
        }
        Ok(Self {
            order,
            start,
            times: [0.0; MAX_ORDER],
            derivs: [[0.0; N]; MAX_ORDER],
            newest: 0,
            len: 0,
        })
    }

    /// The nominal order k.
    pub fn order(&self) -> usize {
        self.order
    }

    /// The start mode.
    pub fn start(&self) -> AbStart {
        self.start
    }

    /// Number of stored (true or primed) derivatives.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True when no derivative is stored (fresh or just reset).
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The order the next [`step`](Self::step) will use: k for `Extrapolate`, min(k, len + 1) for
    /// `Ramp`.
    pub fn next_order(&self) -> usize {
        match self.start {
            AbStart::Extrapolate => self.order,
            AbStart::Ramp => self.order.min(self.len + 1),
        }
    }

    /// The j-th newest stored entry (t_{n−j}, f_{n−j}), j = 0 newest.
    pub fn history(&self, j: usize) -> Option<(f64, &[f64; N])> {
        (j < self.len).then(|| {
            let i = self.index(j);
            (self.times[i], &self.derivs[i])
        })
    }

    /// Forget the derivative history (at release, when the motion changes from prescribed to free:
    /// the old derivatives belong to a different equation of motion).
    pub fn reset(&mut self) {
        self.len = 0;
        self.newest = 0;
    }

    /// Replace the history by `history` (oldest first, times strictly increasing), e.g. with exact
    /// derivatives at earlier times so that start-up error does not pollute a convergence test.
    /// The next `step` must be at a time later than the last primer entry.
    ///
    /// # Errors
    /// [`AbError::PrimeTooLong`] for more than 6 entries, [`AbError::PrimeTimes`] for times not finite
    /// and strictly increasing; the history is then unchanged.
    pub fn prime(&mut self, history: &[(f64, [f64; N])]) -> Result<(), AbError> {
        if history.len() > MAX_ORDER {
            return Err(AbError::PrimeTooLong(history.len()));
        }
        let times_ok = history.iter().all(|(t, _)| t.is_finite())
            && history.windows(2).all(|w| w[1].0 > w[0].0);
        if !times_ok {
            return Err(AbError::PrimeTimes);
        }
        self.reset();
        for (t, f) in history {
            self.push(*t, *f);
        }
        Ok(())
    }

    /// One Adams–Bashforth step t → t + h (docs/physics.md §6): pushes (t, f_now) into the history, then
    /// advances `y` in place with the variable-step coefficients of [`ab_weights`] over the newest
    /// k′ stored derivatives (k′ = [`next_order`](Self::next_order) before the call).
    ///
    /// # Panics
    /// If h is not finite and positive, or t is not finite and later than the newest stored time.
    pub fn step(&mut self, t: f64, y: &mut [f64; N], f_now: [f64; N], h: f64) {
        assert!(
            h.is_finite() && h > 0.0,
            "AB step: h must be finite and > 0, got {h}"
        );
        assert!(t.is_finite(), "AB step: t must be finite, got {t}");
        if let Some((t_prev, _)) = self.history(0) {
            assert!(
                t > t_prev,
                "AB step: t = {t} is not after the last stored time {t_prev}"
            );
        }
        self.push(t, f_now);
        if self.start == AbStart::Extrapolate {
            self.fill_back(h);
        }
        let k = self.len.min(self.order);
        let mut times = [0.0; MAX_ORDER];
        for (j, tj) in times.iter_mut().enumerate().take(k) {
            *tj = self.times[self.index(j)];
        }
        let beta = ab_weights(&times[..k], h);
        for (i, yi) in y.iter_mut().enumerate() {
            let mut sum = 0.0;
            for (j, bj) in beta.iter().enumerate().take(k) {
                sum += bj * self.derivs[self.index(j)][i];
            }
            *yi += h * sum;
        }
    }

    /// The stored history, for a checkpoint ([`AbHistory`]).
    pub fn save_history(&self) -> AbHistory {
        AbHistory {
            times: self.times,
            derivs: self.derivs.iter().map(|d| d.to_vec()).collect(),
            newest: self.newest,
            len: self.len,
        }
    }

    /// Puts back a history saved by [`save_history`](Self::save_history) from an integrator of
    /// the same N; the order and start mode stay this integrator's own.
    ///
    /// # Errors
    /// [`AbError::HistoryShape`] when `h` does not fit this integrator (another N or a
    /// corrupt ring); the integrator is then unchanged.
    pub fn restore_history(&mut self, h: &AbHistory) -> Result<(), AbError> {
        let fits = h.derivs.len() == MAX_ORDER
            && h.derivs.iter().all(|d| d.len() == N)
            && h.newest < MAX_ORDER
            && h.len <= MAX_ORDER;
        if !fits {
            return Err(AbError::HistoryShape);
        }
        self.times = h.times;
        for (dst, src) in self.derivs.iter_mut().zip(&h.derivs) {
            dst.copy_from_slice(src);
        }
        self.newest = h.newest;
        self.len = h.len;
        Ok(())
    }

    /// Ring index of the j-th newest entry.
    fn index(&self, j: usize) -> usize {
        (self.newest + MAX_ORDER - j) % MAX_ORDER
    }

    /// Append a new newest entry, overwriting the oldest when full.
    fn push(&mut self, t: f64, f: [f64; N]) {
        self.newest = if self.len == 0 {
            0
        } else {
            (self.newest + 1) % MAX_ORDER
        };
        self.times[self.newest] = t;
        self.derivs[self.newest] = f;
        self.len = (self.len + 1).min(MAX_ORDER);
    }

    /// `AbStart::Extrapolate`: append invented older entries until k are stored (see [`AbStart`]).
    fn fill_back(&mut self, h: f64) {
        while self.len < self.order {
            let old = self.index(self.len - 1);
            let (t_old, f_old) = (self.times[old], self.derivs[old]);
            let mut slope = [0.0; N];
            if self.len >= 2 {
                let next = self.index(self.len - 2);
                let dt = self.times[next] - t_old;
                for (i, si) in slope.iter_mut().enumerate() {
                    *si = (self.derivs[next][i] - f_old[i]) / dt;
                }
            }
            let slot = self.index(self.len);
            self.times[slot] = t_old - h;
            for i in 0..N {
                self.derivs[slot][i] = f_old[i] - h * slope[i];
            }
            self.len += 1;
        }
    }
}
