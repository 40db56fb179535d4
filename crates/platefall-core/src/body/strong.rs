//! Strong fluid–body coupling (docs/physics.md §6, "Coupling"): the added-mass part of the fluid's
//! response is treated implicitly.
//!
//! The flow's loads after a step contain its instantaneous answer to the change of motion that
//! step imposed, K·Δq/Δt ([`AddedMass`]: K is the discrete flow's own, negative, added-mass matrix
//! in body axes). Taking those loads as given (explicit coupling) lags the added-mass force by a
//! step, which diverges once the added mass exceeds the plate's (m* < π/4 or I* < π/128). Here the
//! caller removes the known part, F_rest = F − K·Δq/Δt, and the body's equations are solved with
//! the added-mass force at the acceleration being computed:
//!
//! ```text
//!     q = (u0, v0, θ̇) in body axes,  dq/dt = (A + θ̇ (v0, −u0), θ̈),  A = Rᵀ(θ) (Ẍ, Ÿ)
//!     diag(m*, m*, I*) (A, θ̈) = F_rest + K dq/dt + (W_body, T)
//!  ⇔ (diag(m*, m*, I*) − K) (A, θ̈) = F_rest + K (θ̇ v0, −θ̇ u0, 0) + (W_body, T)
//! ```
//!
//! with W_body the buoyancy-corrected weight −(m* − m_f*) g* Ŷ in body axes and T the applied
//! moment. A pinned plate (translation prescribed at constant velocity, A = 0) solves the moment
//! row for θ̈ alone. diag(m*, m*, I*) − K is the plate's mass plus the discrete added mass: positive
//! definite for every m* > 0, I* > 0.
//!
//! The wall shear's instantaneous answer S (per unit change of velocity, [`AddedMass::shear`]) is a
//! damping force; it is taken at the velocity the coming step reaches, F_S + S·Δt·(A, θ̈), which
//! moves −Δt·S to the left-hand side: (diag(m*, m*, I*) − K − Δt S)(A, θ̈) = …. That is an O(Δt)
//! change of when the shear acts, and it keeps very light plates at low Re stable at the flow's
//! time step (explicitly the step would need Δt·|S| < m* + m_added).
use super::rigid::{body_to_inertial, inertial_to_body, BodyState, Dof, PlateProps};
use crate::flow::AddedMass;

/// Which coupling of flow and body a run uses (docs/physics.md §6).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Coupling {
    /// The loads of the current flow are taken as given (the dissertation's; diverges for light plates).
    Explicit,
    /// The flow's instantaneous added-mass answer is moved to the left-hand side ([`StrongCoupling`]).
    #[default]
    Strong,
}

/// The body's equations with the added mass implicit (and the shear's answer, see the module docs).
#[derive(Clone, Debug)]
pub struct StrongCoupling {
    /// The flow's response matrices K and S.
    pub added: AddedMass,
    /// diag(m*, m*, I*) − K, row-major.
    mass: [[f64; 3]; 3],
}

impl StrongCoupling {
    /// The coupling for a plate with these properties; `None` when diag(m*, m*, I*) − K is singular
    /// (not for physical input: m*, I* > 0 and K negative semi-definite).
    pub fn new(props: &PlateProps, added: AddedMass) -> Option<Self> {
        let diag = [props.mass, props.mass, props.inertia];
        let mass = [0, 1, 2]
            .map(|r| [0, 1, 2].map(|c| if r == c { diag[r] } else { 0.0 } - added.k[r][c]));
        inverse3(&mass)?;
        Some(Self { added, mass })
    }

    /// Time derivative of (X, Y, θ, Ẋ, Ẏ, θ̇) for the equations of the module docs, given the
    /// loads without their instantaneous part, `rest` = (F_x, F_y, M) in body axes, for the step
    /// `dt` about to be taken.
    pub fn derivative(
        &self,
        props: &PlateProps,
        dof: Dof,
        s: &BodyState,
        rest: [f64; 3],
        dt: f64,
    ) -> [f64; 6] {
        let q = s.frame();
        let turn = self.added.apply([s.omega * q.v0, -s.omega * q.u0, 0.0]);
        let (wx, wy) = inertial_to_body(s.theta, 0.0, -props.weight());
        let rhs = [
            rest[0] + turn[0] + wx,
            rest[1] + turn[1] + wy,
            rest[2] + turn[2] + props.torque,
        ];
        let lhs =
            [0, 1, 2].map(|r| [0, 1, 2].map(|c| self.mass[r][c] - dt * self.added.shear[r][c]));
        let (ax, ay, alpha) = match dof {
            Dof::Prescribed => (0.0, 0.0, 0.0),
            Dof::PitchOnly => (0.0, 0.0, rhs[2] / lhs[2][2]),
            Dof::Free => match inverse3(&lhs) {
                Some(inv) => {
                    let x = [0, 1, 2].map(|r| (0..3).map(|c| inv[r][c] * rhs[c]).sum());
                    let (ax, ay) = body_to_inertial(s.theta, x[0], x[1]);
                    (ax, ay, x[2])
                }
                None => (f64::NAN, f64::NAN, f64::NAN),
            },
        };
        [s.xdot, s.ydot, s.omega, ax, ay, alpha]
    }
}

/// The inverse of a 3 × 3 matrix by cofactors; `None` when it is singular or not finite.
fn inverse3(a: &[[f64; 3]; 3]) -> Option<[[f64; 3]; 3]> {
    let cof = |r: usize, c: usize| {
        let (r1, r2) = ((r + 1) % 3, (r + 2) % 3);
        let (c1, c2) = ((c + 1) % 3, (c + 2) % 3);
        a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1]
    };
    let det: f64 = (0..3).map(|c| a[0][c] * cof(0, c)).sum();
    if !(det.is_finite() && det.abs() > 0.0) {
        return None;
    }
    // inverse[r][c] = cofactor(c, r) / det (the adjugate is the transposed cofactor matrix).
    Some([0, 1, 2].map(|r| [0, 1, 2].map(|c| cof(c, r) / det)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_of_a_full_matrix() {
        let a = [[2.0, 1.0, 0.5], [0.3, 3.0, -1.0], [0.0, 0.7, 1.5]];
        let inv = inverse3(&a).unwrap();
        for (r, row) in a.iter().enumerate() {
            for c in 0..3 {
                let v: f64 = row.iter().zip(&inv).map(|(x, i)| x * i[c]).sum();
                let want = if r == c { 1.0 } else { 0.0 };
                assert!((v - want).abs() < 1e-14, "({r}, {c}): {v}");
            }
        }
        assert!(inverse3(&[[1.0, 2.0, 3.0], [2.0, 4.0, 6.0], [0.0, 0.0, 1.0]]).is_none());
    }

    #[test]
    fn plate_at_rest_accelerates_with_its_mass_plus_the_added_mass() {
        // Horizontal plate (θ = 0), weight 1 down, K = −diag(0.01, π/4, π/128): A_y = −1/(m* + π/4).
        let props = PlateProps {
            displaced: 0.05,
            ..PlateProps::new(0.1, 0.01, 20.0)
        };
        let pi = std::f64::consts::PI;
        let added = AddedMass {
            k: [
                [-0.01, 0.0, 0.0],
                [0.0, -pi / 4.0, 0.0],
                [0.0, 0.0, -pi / 128.0],
            ],
            shear: [[-0.2, 0.0, 0.0], [0.0, -0.02, 0.0], [0.0, 0.0, -0.003]],
        };
        let sc = StrongCoupling::new(&props, added).unwrap();
        let f = sc.derivative(&props, Dof::Free, &BodyState::default(), [0.0; 3], 0.0);
        let want = -(0.1 - 0.05) * 20.0 / (0.1 + pi / 4.0);
        assert!(
            (f[4] - want).abs() < 1e-14 && f[3] == 0.0 && f[5] == 0.0,
            "{f:?}"
        );
        // Pinned, with an applied moment: θ̈ = T/(I* + π/128).
        let spun = PlateProps {
            torque: 0.3,
            ..props
        };
        let f = sc.derivative(&spun, Dof::PitchOnly, &BodyState::default(), [0.0; 3], 0.0);
        assert!((f[5] - 0.3 / (0.01 + pi / 128.0)).abs() < 1e-14, "{f:?}");
        // With a step, the shear's answer adds Δt·|S| to the pitch inertia.
        let f = sc.derivative(&spun, Dof::PitchOnly, &BodyState::default(), [0.0; 3], 0.01);
        assert!((f[5] - 0.3 / (0.01 + pi / 128.0 + 0.01 * 0.003)).abs() < 1e-14);
    }
}
