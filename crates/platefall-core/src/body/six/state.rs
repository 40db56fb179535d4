//! The 6-DOF state (docs/physics.md §9): the centre's position and velocity in inertial axes, the
//! orientation (body → inertial) as a unit quaternion, the angular velocity in body axes.

use nalgebra::{UnitQuaternion, Vector3};

use super::SixError;
use crate::body::BodyState;

/// How far the orientation's norm may be from 1 in a state handed in (a few thousand round-offs).
pub(super) const UNIT_TOL: f64 = 1e-12;

/// The rigid body's state (docs/physics.md §9), non-dimensional on c and U. Inertial axes: X, Y
/// up, Z; body axes: x chord, y normal to the plate, z span; X = X₀ + R(q) x.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct State6 {
    /// X₀, the centre in inertial axes.
    pub position: Vector3<f64>,
    /// Ẋ₀, the centre's velocity in inertial axes.
    pub velocity: Vector3<f64>,
    /// q, the rotation from body to inertial axes.
    pub orientation: UnitQuaternion<f64>,
    /// ω, the angular velocity in body axes.
    pub omega: Vector3<f64>,
}

impl Default for State6 {
    fn default() -> Self {
        Self::at_rest()
    }
}

impl State6 {
    /// At the origin, at rest, body axes along the inertial axes (span along Z, horizontal).
    pub fn at_rest() -> Self {
        Self {
            position: Vector3::zeros(),
            velocity: Vector3::zeros(),
            orientation: UnitQuaternion::identity(),
            omega: Vector3::zeros(),
        }
    }

    /// A planar release as in 2-D (docs/physics.md §6, §8): at the origin with speed V₀ along the
    /// flight-path angle γ₀ in the X–Y plane, pitched to θ₀ = γ₀ + α₀ about the span, the span
    /// horizontal along Z, not rotating.
    pub fn release(speed: f64, gamma: f64, alpha: f64) -> Self {
        Self::from_planar(&BodyState {
            theta: gamma + alpha,
            xdot: speed * gamma.cos(),
            ydot: speed * gamma.sin(),
            ..BodyState::default()
        })
    }

    /// The 2-D state (docs/physics.md §3, §6) as a 6-DOF one: (X, Y) and (Ẋ, Ẏ) in the X–Y plane,
    /// the pitch θ and rate θ̇ about the span, which lies along Z. A 2-D motion law (the static and
    /// forced cases' prescribed motions) gives the 3-D prescribed motion this way.
    pub fn from_planar(s: &BodyState) -> Self {
        Self {
            position: Vector3::new(s.x, s.y, 0.0),
            velocity: Vector3::new(s.xdot, s.ydot, 0.0),
            orientation: UnitQuaternion::from_axis_angle(&Vector3::z_axis(), s.theta),
            omega: Vector3::new(0.0, 0.0, s.omega),
        }
    }

    /// A body-axes vector in inertial axes, R(q) v.
    pub fn to_inertial(&self, v: &Vector3<f64>) -> Vector3<f64> {
        self.orientation * v
    }

    /// An inertial vector in body axes, Rᵀ(q) v.
    pub fn to_body(&self, v: &Vector3<f64>) -> Vector3<f64> {
        self.orientation.inverse_transform_vector(v)
    }

    /// u₀ = Rᵀ Ẋ₀: the centre's velocity along the body axes, as the flow solver sees it.
    pub fn body_velocity(&self) -> Vector3<f64> {
        self.to_body(&self.velocity)
    }

    /// The span (body z) in inertial axes; horizontal when its Y component is 0.
    pub fn span_axis(&self) -> Vector3<f64> {
        self.to_inertial(&Vector3::z())
    }

    /// The state's components are finite and the orientation of unit norm (within 1e-12).
    ///
    /// # Errors
    /// [`SixError::NotFinite`] naming the first non-finite part, or [`SixError::Orientation`] when
    /// the quaternion's norm is off 1 by more than 1e-12.
    pub fn validate(&self) -> Result<(), SixError> {
        let finite = |v: &Vector3<f64>| v.iter().all(|x| x.is_finite());
        if !finite(&self.position) {
            return Err(SixError::NotFinite("position"));
        }
        if !finite(&self.velocity) {
            return Err(SixError::NotFinite("velocity"));
        }
        if !finite(&self.omega) {
            return Err(SixError::NotFinite("angular velocity"));
        }
        let norm = self.orientation.quaternion().norm();
        if !norm.is_finite() {
            return Err(SixError::NotFinite("orientation"));
        }
        if (norm - 1.0).abs() > UNIT_TOL {
            return Err(SixError::Orientation(norm));
        }
        Ok(())
    }
}
