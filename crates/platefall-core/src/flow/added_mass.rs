//! The discrete flow's instantaneous pressure response to a change of the plate's motion (docs/physics.md §6,
//! "coupling that treats the added-mass part of the fluid force implicitly").
//!
//! One step t → t + Δt predicts u* = uⁿ + Δt·H and sets the plate faces to g(qⁿ⁺¹), with
//! q = (u0, v0, θ̇) the plate's motion in body axes ([`Frame`]). Because uⁿ was divergence-free
//! with its plate faces at g(qⁿ), the divergence of u* is the fluid-face part Δt·∇·H plus the
//! plate-face part, which is linear in Δq = qⁿ⁺¹ − qⁿ. The projection is linear too, so
//! φ = φ_H + Σₖ Δqₖ φₖ with φₖ the potential of a unit change of motion k, and the pressure loads
//! (p = φ/Δt) are F = F_H + K·Δq/Δt. K is a constant 3 × 3 matrix of the discrete operator (rows
//! F_x, F_y, M in body axes; columns u0, v0, θ̇): the negative of the discrete plate's added-mass
//! tensor (potential flow: π/4 normal, ≈ 0 along a thin plate, π/128 in pitch). It is computed once
//! with the factored pressure matrix (three projections).
//!
//! The viscous shear on the plate, μ(u − g)/d from the first fluid velocity, also answers a change
//! of motion at once: through g(qⁿ⁺¹) and through the projection's near-wall velocity −∇φ. Per unit
//! change of velocity (not divided by Δt) that answer is the matrix S, of order 4μ/h along the
//! plate. It is a damping force, which an explicit body step integrates stably only while
//! Δt·|S|/(m + m_added) < 1 — violated by very light plates at low Re.
use super::frame::Frame;
use super::plate::BodyAxesLoads;

/// K and S of the module docs: `k[row][col]`, rows (F_x, F_y, M) in body axes on ρU²c and ρU²c²,
/// columns the unit changes of (u0, v0, θ̇) over a unit step; `shear[row][col]` likewise per unit
/// change of (u0, v0, θ̇), at the run's Reynolds number.
#[derive(Clone, Copy, Debug, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct AddedMass {
    /// K: the pressure loads per unit change of motion over a unit step.
    pub k: [[f64; 3]; 3],
    /// S: the shear loads per unit change of motion.
    pub shear: [[f64; 3]; 3],
}

impl AddedMass {
    /// K·x.
    pub fn apply(&self, x: [f64; 3]) -> [f64; 3] {
        let k = &self.k;
        [0, 1, 2].map(|r| k[r][0] * x[0] + k[r][1] * x[1] + k[r][2] * x[2])
    }

    /// The part of the loads that is the flow's instantaneous answer to the last change of motion,
    /// K·(qⁿ − qⁿ⁻¹)/Δtⁿ⁻¹ ((F_x, F_y, M) in body axes); zero before the first step (`dt` = 0).
    pub fn instantaneous(&self, now: &Frame, before: &Frame, dt: f64) -> [f64; 3] {
        if dt <= 0.0 {
            return [0.0; 3];
        }
        let dq = [
            (now.u0 - before.u0) / dt,
            (now.v0 - before.v0) / dt,
            (now.omega - before.omega) / dt,
        ];
        self.apply(dq)
    }

    /// The loads without their instantaneous part: F − K·Δq/Δt (body axes).
    pub fn rest(&self, loads: &BodyAxesLoads, now: &Frame, before: &Frame, dt: f64) -> [f64; 3] {
        let inst = self.instantaneous(now, before, dt);
        [
            loads.fx - inst[0],
            loads.fy - inst[1],
            loads.moment - inst[2],
        ]
    }
}
