//! The non-dimensional 6-DOF plate (docs/physics.md §2, §9): mass, inertia tensor, gravity and
//! displaced fluid mass, validated once.

use nalgebra::{Matrix3, Vector3};

use super::SixError;

/// Relative asymmetry tolerated in an inertia tensor (round-off of a rotated diagonal tensor).
const SYMMETRY_TOL: f64 = 1e-12;

/// Non-dimensional properties of a rigid body for the 6-DOF equations (docs/physics.md §9), on
/// the chord c (module docs of [`super`]): m* = m/(ρc³), I* = I/(ρc⁵) about the centre in body
/// axes (x chord, y normal, z span), g* = g c/U², m_f* the displaced fluid mass by ρc³.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Plate6 {
    mass: f64,
    inertia: Matrix3<f64>,
    inertia_inv: Matrix3<f64>,
    gravity: f64,
    displaced: f64,
}

impl Plate6 {
    /// A body with mass m* > 0, a symmetric positive-definite inertia tensor I* (body axes, about
    /// the centre), g* ≥ 0 and displaced fluid mass m_f* ≥ 0 (buoyancy m_f* g* upwards).
    ///
    /// # Errors
    /// [`SixError::Mass`], [`SixError::Gravity`], [`SixError::Displaced`] or [`SixError::Inertia`]
    /// for the first value outside its range.
    pub fn new(
        mass: f64,
        inertia: Matrix3<f64>,
        gravity: f64,
        displaced: f64,
    ) -> Result<Self, SixError> {
        if !(mass.is_finite() && mass > 0.0) {
            return Err(SixError::Mass(mass));
        }
        if !(gravity.is_finite() && gravity >= 0.0) {
            return Err(SixError::Gravity(gravity));
        }
        if !(displaced.is_finite() && displaced >= 0.0) {
            return Err(SixError::Displaced(displaced));
        }
        let inertia_inv = check_inertia(&inertia)?;
        Ok(Self {
            mass,
            inertia,
            inertia_inv,
            gravity,
            displaced,
        })
    }

    /// A body whose principal axes are the body axes: I* = diag(I_x, I_y, I_z).
    ///
    /// # Errors
    /// As [`Plate6::new`]: the first of m*, the moments, g* and m_f* outside its range.
    pub fn principal(
        mass: f64,
        moments: [f64; 3],
        gravity: f64,
        displaced: f64,
    ) -> Result<Self, SixError> {
        Self::new(
            mass,
            Matrix3::from_diagonal(&Vector3::from(moments)),
            gravity,
            displaced,
        )
    }

    /// m*.
    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// I*, the inertia tensor about the centre in body axes.
    pub fn inertia(&self) -> &Matrix3<f64> {
        &self.inertia
    }

    /// (I*)⁻¹.
    pub fn inertia_inv(&self) -> &Matrix3<f64> {
        &self.inertia_inv
    }

    /// g*.
    pub fn gravity(&self) -> f64 {
        self.gravity
    }

    /// m_f*.
    pub fn displaced(&self) -> f64 {
        self.displaced
    }

    /// The buoyancy-corrected gravity acceleration of the body's own mass, g*(1 − m_f*/m*)
    /// (downwards; negative for a body lighter than the fluid).
    pub fn apparent_gravity(&self) -> f64 {
        self.gravity * (1.0 - self.displaced / self.mass)
    }

    /// The buoyancy-corrected weight (m* − m_f*) g_vec in inertial axes, by ρU²c².
    pub fn weight(&self) -> Vector3<f64> {
        Vector3::new(0.0, -(self.mass - self.displaced) * self.gravity, 0.0)
    }
}

/// The inverse of a finite, symmetric, positive-definite inertia tensor, or the typed error.
fn check_inertia(i: &Matrix3<f64>) -> Result<Matrix3<f64>, SixError> {
    let bad = || SixError::Inertia(i.transpose().into());
    let scale = i.amax();
    let symmetric = (i - i.transpose()).amax() <= SYMMETRY_TOL * scale;
    if !(i.iter().all(|x| x.is_finite()) && symmetric) {
        return Err(bad());
    }
    let chol = nalgebra::Cholesky::new(*i).ok_or_else(bad)?;
    Ok(chol.inverse())
}
