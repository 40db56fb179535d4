//! The variable-step Adams–Bashforth 2 weights of the explicit right-hand side (docs/physics.md
//! §3 "Time stepping"), shared by the explicit predictor (`momentum.rs` through `mod.rs`) and the
//! implicit one (`implicit/`).

/// The weights of Hⁿ and Hⁿ⁻¹ in u* = uⁿ + Δt (`new` Hⁿ + `old` Hⁿ⁻¹).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ab2 {
    /// The weight of the right-hand side at n: 1 + r/2 (1 on the first step).
    pub new: f64,
    /// The weight of the right-hand side at n − 1: −r/2 (0 on the first step).
    pub old: f64,
}

impl Ab2 {
    /// The weights for a step `dt` after a step `dt_prev`, r = Δt/Δtⁿ⁻¹; `dt_prev` ≤ 0 (the
    /// first step) gives Euler.
    pub fn new(dt: f64, dt_prev: f64) -> Ab2 {
        if dt_prev <= 0.0 {
            return Ab2 { new: 1.0, old: 0.0 };
        }
        let r = dt / dt_prev;
        Ab2 {
            new: 1.0 + 0.5 * r,
            old: -0.5 * r,
        }
    }
}
