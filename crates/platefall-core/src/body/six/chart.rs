//! The orientation's Adams–Bashforth step (docs/physics.md §6, §9) in a chart centred on the
//! current orientation.
//!
//! Near q_n every orientation is q_n ⊗ exp(ψ) for a small rotation vector ψ (body axes at t_n), and
//! q̇ = ½ q ⊗ (0, ω) becomes the ordinary differential equation ψ̇ = J⁻¹(ψ) ω, with
//!
//! ```text
//!     J⁻¹(ψ) ω = ω + ½ ψ × ω + c(|ψ|) ψ × (ψ × ω),   c(θ) = (1 − (θ/2) cot(θ/2)) / θ²
//! ```
//!
//! (the inverse right Jacobian of the rotations; c → 1/12 as θ → 0). The stored past orientations
//! q_{n−j} and angular velocities ω_{n−j} give the exact chart coordinates ψ_{n−j} = log(q_n⁻¹
//! q_{n−j}) and derivatives ψ̇_{n−j} of the past points, and the step is Adams–Bashforth of that
//! equation with the weights of [`ab_weights`]: ψ_{n+1} = h Σ β_j ψ̇_{n−j}, q_{n+1} = q_n ⊗
//! exp(ψ_{n+1}). Its local error is the method's O(h^{k+1}), as for the other components.
//!
//! Why not Adams–Bashforth on the quaternion's four components: their step leaves the unit sphere
//! by the truncation error, which renormalising only projects away; and a rotation about a fixed
//! axis would then differ from the 2-D integrator's θ by the truncation error. In the chart a
//! rotation about body z has ψ ∥ ω ∥ ẑ, J⁻¹(ψ) ω = ω exactly, and the step is the 2-D step of θ.
//! q_n ⊗ exp(ψ) has unit norm up to round-off; the renormalisation after each step removes that
//! round-off (|1 − |q|| of a few ulp per step), so it adds no error beyond round-off.

use nalgebra::{UnitQuaternion, Vector3};

use crate::body::{ab_weights, AdamsBashforth, MAX_ORDER};

/// Below this |ψ| the series 1/12 + θ²/720 of c(θ) is exact to round-off (next term θ⁴/30240).
const SERIES_BELOW: f64 = 1e-4;

/// J⁻¹(ψ) ω of the module docs: the chart derivative of a point ψ moving with body rate ω.
pub(super) fn chart_rate(psi: &Vector3<f64>, omega: &Vector3<f64>) -> Vector3<f64> {
    let th2 = psi.norm_squared();
    let th = th2.sqrt();
    let c = if th < SERIES_BELOW {
        1.0 / 12.0 + th2 / 720.0
    } else {
        let half = 0.5 * th;
        (1.0 - half / half.tan()) / th2
    };
    let pw = psi.cross(omega);
    omega + 0.5 * pw + c * psi.cross(&pw)
}

/// The past orientations and angular velocities (newest first), in step with the derivative
/// history of an [`AdamsBashforth`] integrator: entry j belongs to its j-th newest time.
#[derive(Debug, Clone, Default, PartialEq)]
pub(super) struct SpinHistory {
    entries: Vec<(UnitQuaternion<f64>, Vector3<f64>)>,
}

impl SpinHistory {
    /// The entries, newest first.
    pub(super) fn entries(&self) -> &[(UnitQuaternion<f64>, Vector3<f64>)] {
        &self.entries
    }

    /// Replaces the entries (newest first; at most [`MAX_ORDER`]).
    pub(super) fn set(&mut self, entries: Vec<(UnitQuaternion<f64>, Vector3<f64>)>) {
        debug_assert!(entries.len() <= MAX_ORDER);
        self.entries = entries;
    }

    /// Forget everything (with the integrator's `reset`).
    pub(super) fn clear(&mut self) {
        self.entries.clear();
    }

    /// Add the newest entry (before the integrator's step pushes its derivative).
    pub(super) fn push(&mut self, q: UnitQuaternion<f64>, omega: Vector3<f64>) {
        self.entries.insert(0, (q, omega));
        self.entries.truncate(MAX_ORDER);
    }

    /// After the integrator's step: when it invented older derivatives (`AbStart::Extrapolate`,
    /// derivative constant in the past), invent the matching past of the rotation: ω as the oldest
    /// stored, the orientation turned back along it, q_{old} ⊗ exp(−(t_old − t_j) ω_old).
    pub(super) fn fill_back<const N: usize>(&mut self, ab: &AdamsBashforth<N>) {
        while self.entries.len() < ab.len() {
            let old = self.entries.len() - 1;
            let (q_old, w_old) = self.entries[old];
            let t_old = ab.history(old).map_or(0.0, |(t, _)| t);
            let t_j = ab.history(old + 1).map_or(t_old, |(t, _)| t);
            let back = UnitQuaternion::from_scaled_axis(w_old * (t_j - t_old));
            self.entries.push((q_old * back, w_old));
        }
    }

    /// The rotation vector ψ_{n+1} = h Σ β_j J⁻¹(ψ_{n−j}) ω_{n−j} of the step t_n → t_n + h over the
    /// newest k entries, with the times of `ab` (whose step has just used the same weights).
    pub(super) fn increment<const N: usize>(&self, ab: &AdamsBashforth<N>, h: f64) -> Vector3<f64> {
        let k = ab.len().min(ab.order());
        let mut times = [0.0; MAX_ORDER];
        for (j, tj) in times.iter_mut().enumerate().take(k) {
            *tj = ab.history(j).map_or(0.0, |(t, _)| t);
        }
        let beta = ab_weights(&times[..k], h);
        let (q_n, _) = self.entries[0];
        let mut sum = Vector3::zeros();
        for (bj, (q_j, w_j)) in beta.iter().zip(&self.entries).take(k) {
            let psi = (q_n.inverse() * q_j).scaled_axis();
            sum += *bj * chart_rate(&psi, w_j);
        }
        h * sum
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chart_rate_is_the_derivative_of_the_chart() {
        // Moving from exp(ψ) with body rate ω for a time ε: exp(ψ) ⊗ exp(ε ω) must equal
        // exp(ψ + ε J⁻¹(ψ) ω) to O(ε²) (≈ 1e-12 here; a wrong term of J⁻¹ would leave O(ε) ≈ 1e-6),
        // at a small |ψ| (the series) and a large one.
        for psi in [
            Vector3::new(1e-5, -2e-5, 3e-6),
            Vector3::new(0.7, -1.1, 0.4),
        ] {
            let w = Vector3::new(0.3, 0.8, -0.5);
            let eps = 1e-6;
            let moved =
                UnitQuaternion::from_scaled_axis(psi) * UnitQuaternion::from_scaled_axis(w * eps);
            let chart = UnitQuaternion::from_scaled_axis(psi + chart_rate(&psi, &w) * eps);
            let gap = 2.0 * (moved.inverse() * chart).imag().norm();
            assert!(gap < 1e-11, "|ψ| = {}: gap {gap}", psi.norm());
        }
    }
}
