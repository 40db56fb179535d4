//! Strong fluid–body coupling in three dimensions (docs/physics.md §6, §9): the flow's 6 × 6
//! added-mass matrix on the left-hand side, as in 2-D (`body/strong.rs`).
//!
//! K is the discrete flow's own response (force and moment in body axes per unit change of the
//! body-axes velocity q = (u₀, ω), u₀ = Rᵀ Ẋ₀, per unit time): the negative of its added-mass
//! tensor. The caller removes K·Δq/Δt from the loads (`rest`), and the body's equations are solved
//! with the added-mass force at the acceleration being computed. With A = Rᵀ Ẍ₀ the acceleration in
//! body axes, d(Rᵀ Ẋ₀)/dt = A − ω × u₀, so dq/dt = (A, ω̇) + (−ω × u₀, 0) and
//!
//! ```text
//!     m A            = F_rest + [K dq/dt]_F + Rᵀ (m − m_f) g_vec
//!     I ω̇ + ω × Iω   = M_rest + [K dq/dt]_M
//!  ⇔ (diag(m, m, m) ⊕ I − K) (A, ω̇) = (F_rest + Rᵀ W, M_rest − ω × Iω) + K (−ω × u₀, 0)
//! ```
//!
//! then Ẍ₀ = R A. For planar motion (ω = θ̇ ẑ) −ω × u₀ = (θ̇ v₀, −θ̇ u₀, 0), the 2-D form. Pinned
//! about the centre (A = 0) the moment rows are solved with the 3 × 3 block I − K_MM; pinned about
//! the span the z row alone; planar (A_z = 0, ω ∥ z) the rows and columns of (u, v, ω_z). The left-hand side must be positive definite (its symmetric part), as
//! it is for a physical K (negative semi-definite) and any m > 0 and positive-definite I.

use nalgebra::{Matrix3, Matrix6, SymmetricEigen, Vector3, Vector6, LU, U3, U6};

use super::dynamics::in_plane;
use super::{Accel6, Constraint6, Loads6, Plate6, SixError, State6};

/// The rows of (u, v, ω_z), the planar motion's, among the six.
const PLANAR: [usize; 3] = [0, 1, 5];

/// The body's equations with the added mass implicit (module docs).
#[derive(Clone, Debug)]
pub struct StrongCoupling6 {
    k: Matrix6<f64>,
    lhs: Matrix6<f64>,
    full: LU<f64, U6, U6>,
    moments: LU<f64, U3, U3>,
    /// Rows and columns (u, v, ω_z) of the left-hand side.
    planar: LU<f64, U3, U3>,
}

impl StrongCoupling6 {
    /// The coupling for `plate` with the flow's K (rows and columns ordered u, v, w, ω_x, ω_y,
    /// ω_z in body axes, row-major); the typed error when diag(m, m, m) ⊕ I − K is not positive
    /// definite or not finite.
    ///
    /// # Errors
    /// [`SixError::AddedMass`] when diag(m, m, m) ⊕ I − K is not finite or not positive definite.
    pub fn new(plate: &Plate6, k: [[f64; 6]; 6]) -> Result<Self, SixError> {
        let k = Matrix6::from_fn(|r, c| k[r][c]);
        let mut rigid = Matrix6::zeros();
        for d in 0..3 {
            rigid[(d, d)] = plate.mass();
        }
        rigid
            .fixed_view_mut::<3, 3>(3, 3)
            .copy_from(plate.inertia());
        let lhs = rigid - k;
        if !lhs.iter().all(|x| x.is_finite()) {
            return Err(SixError::AddedMass(f64::NAN));
        }
        let smallest = SymmetricEigen::new(0.5 * (lhs + lhs.transpose()))
            .eigenvalues
            .min();
        if smallest.is_nan() || smallest <= 0.0 {
            return Err(SixError::AddedMass(smallest));
        }
        let moments: Matrix3<f64> = lhs.fixed_view::<3, 3>(3, 3).into_owned();
        let planar = Matrix3::from_fn(|r, c| lhs[(PLANAR[r], PLANAR[c])]);
        Ok(Self {
            k,
            lhs,
            full: lhs.lu(),
            moments: moments.lu(),
            planar: planar.lu(),
        })
    }

    /// K.
    pub fn k(&self) -> &Matrix6<f64> {
        &self.k
    }

    /// diag(m, m, m) ⊕ I − K, the left-hand side.
    pub fn lhs(&self) -> &Matrix6<f64> {
        &self.lhs
    }

    /// The accelerations (Ẍ₀ inertial, ω̇ body) of the module docs, given the loads without their
    /// instantaneous added-mass part, `rest` (body axes).
    pub fn acceleration(
        &self,
        plate: &Plate6,
        constraint: Constraint6,
        s: &State6,
        rest: &Loads6,
    ) -> Accel6 {
        let w = s.omega;
        let turn = -w.cross(&s.body_velocity());
        let answer = self.k * Vector6::new(turn.x, turn.y, turn.z, 0.0, 0.0, 0.0);
        let force = rest.force + s.to_body(&plate.weight()) + answer.fixed_rows::<3>(0);
        let moment = rest.moment - w.cross(&(plate.inertia() * w)) + answer.fixed_rows::<3>(3);
        let solve_moments = |m: Vector3<f64>| self.moments.solve(&m).unwrap_or(m * f64::NAN);
        match constraint {
            Constraint6::Prescribed => Accel6::default(),
            Constraint6::PinnedSpan => Accel6 {
                linear: Vector3::zeros(),
                angular: Vector3::new(0.0, 0.0, moment.z / self.lhs[(5, 5)]),
            },
            Constraint6::PinnedPoint => Accel6 {
                linear: Vector3::zeros(),
                angular: solve_moments(moment),
            },
            Constraint6::Planar => {
                let rhs = Vector3::new(force.x, force.y, moment.z);
                let x = self.planar.solve(&rhs).unwrap_or(rhs * f64::NAN);
                Accel6 {
                    linear: in_plane(s.to_inertial(&Vector3::new(x[0], x[1], 0.0))),
                    angular: Vector3::new(0.0, 0.0, x[2]),
                }
            }
            Constraint6::Free => {
                let rhs = Vector6::new(force.x, force.y, force.z, moment.x, moment.y, moment.z);
                let x = self.full.solve(&rhs).unwrap_or(rhs * f64::NAN);
                Accel6 {
                    linear: s.to_inertial(&x.fixed_rows::<3>(0).into_owned()),
                    angular: x.fixed_rows::<3>(3).into_owned(),
                }
            }
        }
    }
}
