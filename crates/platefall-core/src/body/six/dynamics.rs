//! The 6-DOF equations of motion with the loads taken as given (explicit coupling,
//! docs/physics.md §9), and the constraints.

use nalgebra::Vector3;

use super::{Plate6, SixError, State6};

/// Fluid load on the body (docs/physics.md §9): force and moment about the centre in BODY axes,
/// by ρU²c² and ρU²c³.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct Loads6 {
    /// F in body axes.
    pub force: Vector3<f64>,
    /// M about the centre in body axes.
    pub moment: Vector3<f64>,
}

/// What the equations of motion give the integrator: Ẍ₀ in inertial axes, ω̇ in body axes.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Accel6 {
    /// Ẍ₀ (inertial axes).
    pub linear: Vector3<f64>,
    /// ω̇ (body axes).
    pub angular: Vector3<f64>,
}

/// Which degrees of freedom the equations move (docs/physics.md §1, §9).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Constraint6 {
    /// Static and forced cases: the caller imposes the motion
    /// ([`RigidBody6::impose`](super::RigidBody6::impose)); stepping leaves the state untouched.
    Prescribed,
    /// Pinned about the span (the 2-D pinned case): rotation about body z only, which keeps its
    /// direction; ω = ω_z ẑ with I_z ω̇_z = M_z (the bearing takes the other components); the
    /// centre translates at constant velocity, no gravity.
    PinnedSpan,
    /// Free rotation about the centre held by a ball joint: the full Euler equations; the centre
    /// translates at constant velocity (zero for a fixed point), no gravity.
    PinnedPoint,
    /// All six degrees of freedom, with gravity and buoyancy.
    Free,
    /// Free flight in the X–Y plane, turning about the span only (ω = ω_z ẑ, the span along Z):
    /// the centre moves in X–Y under the loads, gravity and buoyancy, and the constraint takes the
    /// rest. A plate of periodic span flies so (it cannot roll), and the 2-D free fall is this
    /// case of the six.
    Planar,
}

impl Constraint6 {
    /// Whether `state` is consistent with the constraint: pinned about the span or planar, ω
    /// lies along body z exactly; planar, the centre does not move along Z.
    ///
    /// # Errors
    /// [`SixError::PinnedSpin`] when pinned about the span or planar and ω has an x or y
    /// component; [`SixError::PlanarVelocity`] when planar and Ż₀ ≠ 0.
    pub fn check(&self, state: &State6) -> Result<(), SixError> {
        let w = state.omega;
        let about_span = matches!(self, Constraint6::PinnedSpan | Constraint6::Planar);
        if about_span && (w.x != 0.0 || w.y != 0.0) {
            return Err(SixError::PinnedSpin(w.into()));
        }
        if *self == Constraint6::Planar && state.velocity.z != 0.0 {
            return Err(SixError::PlanarVelocity(state.velocity.z));
        }
        Ok(())
    }
}

/// The body's accelerations under the loads taken as given (docs/physics.md §9, explicit
/// coupling): `Free`: Ẍ₀ = R F/m* − g*(1 − m_f*/m*) Ŷ, ω̇ = I⁻¹(M − ω × Iω); `PinnedPoint`: Ẍ₀ = 0
/// and the same ω̇; `PinnedSpan`: Ẍ₀ = 0, ω̇ = (0, 0, M_z/I_z) (ω × Iω has no z component for
/// ω ∥ z); `Planar`: `Free`'s Ẍ₀ without its Z component and `PinnedSpan`'s ω̇; `Prescribed`: zero.
pub fn explicit_acceleration(
    plate: &Plate6,
    constraint: Constraint6,
    s: &State6,
    loads: &Loads6,
) -> Accel6 {
    let i = plate.inertia();
    let euler = || plate.inertia_inv() * (loads.moment - s.omega.cross(&(i * s.omega)));
    let linear = || {
        let mut a = s.to_inertial(&loads.force) / plate.mass();
        a.y -= plate.apparent_gravity();
        a
    };
    match constraint {
        Constraint6::Prescribed => Accel6::default(),
        Constraint6::PinnedSpan => Accel6 {
            linear: Vector3::zeros(),
            angular: Vector3::new(0.0, 0.0, loads.moment.z / i[(2, 2)]),
        },
        Constraint6::PinnedPoint => Accel6 {
            linear: Vector3::zeros(),
            angular: euler(),
        },
        Constraint6::Free => Accel6 {
            linear: linear(),
            angular: euler(),
        },
        Constraint6::Planar => Accel6 {
            linear: in_plane(linear()),
            angular: Vector3::new(0.0, 0.0, loads.moment.z / i[(2, 2)]),
        },
    }
}

/// v without its Z component (the planar constraint's reaction takes it).
pub(super) fn in_plane(v: Vector3<f64>) -> Vector3<f64> {
    Vector3::new(v.x, v.y, 0.0)
}
