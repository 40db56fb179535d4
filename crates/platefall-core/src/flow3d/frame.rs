//! The body's motion as the 3-D flow solver sees it (docs/physics.md §9): the rotation R from body
//! to inertial axes, the centre's inertial velocity Ẋ₀ and the angular velocity ω in body axes,
//! which give the grid-point velocity g = Rᵀ Ẋ₀ + ω × x.
use nalgebra::{Rotation3, Vector3};

/// The body's motion at one time level.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Frame3 {
    /// Rotation from body to inertial axes.
    pub rotation: Rotation3<f64>,
    /// The centre's velocity in inertial axes, Ẋ₀.
    pub velocity: Vector3<f64>,
    /// Angular velocity in body axes, ω.
    pub omega: Vector3<f64>,
    /// Rᵀ Ẋ₀: the centre's velocity along the body axes.
    a: [f64; 3],
    w: [f64; 3],
}

impl Default for Frame3 {
    fn default() -> Self {
        Frame3::new(Rotation3::identity(), Vector3::zeros(), Vector3::zeros())
    }
}

impl Frame3 {
    /// The motion with this rotation, centre velocity (inertial) and angular velocity (body).
    pub fn new(rotation: Rotation3<f64>, velocity: Vector3<f64>, omega: Vector3<f64>) -> Frame3 {
        let a = rotation.inverse() * velocity;
        Frame3 {
            rotation,
            velocity,
            omega,
            a: [a.x, a.y, a.z],
            w: [omega.x, omega.y, omega.z],
        }
    }

    /// The motion given directly in body axes (R = identity): centre velocity `a` and ω.
    pub fn body(a: [f64; 3], omega: [f64; 3]) -> Frame3 {
        Frame3::new(Rotation3::identity(), a.into(), omega.into())
    }

    /// The centre's velocity along the body axes, Rᵀ Ẋ₀.
    pub fn body_velocity(&self) -> [f64; 3] {
        self.a
    }

    /// ω as an array.
    #[inline(always)]
    pub fn omega_array(&self) -> [f64; 3] {
        self.w
    }

    /// Component c of g = Rᵀ Ẋ₀ + ω × x at x (it does not depend on `x[c]`).
    #[inline(always)]
    pub fn g(&self, c: usize, x: [f64; 3]) -> f64 {
        let (e1, e2) = ((c + 1) % 3, (c + 2) % 3);
        self.a[c] + (self.w[e1] * x[e2] - self.w[e2] * x[e1])
    }

    /// The grid-point velocity g at x.
    pub fn g_vec(&self, x: [f64; 3]) -> [f64; 3] {
        std::array::from_fn(|c| self.g(c, x))
    }

    /// Component c of −ω × u for u = (u₀, u₁, u₂).
    #[inline(always)]
    pub fn minus_omega_cross(&self, c: usize, u: [f64; 3]) -> f64 {
        let (e1, e2) = ((c + 1) % 3, (c + 2) % 3);
        -(self.w[e1] * u[e2] - self.w[e2] * u[e1])
    }

    /// Largest |g| over the box with these corners (g is affine: the largest is at a corner).
    pub fn max_speed_over(&self, lo: [f64; 3], hi: [f64; 3]) -> f64 {
        (0..8)
            .map(|m| {
                let x = std::array::from_fn(|a| if m >> a & 1 == 1 { hi[a] } else { lo[a] });
                let g = self.g_vec(x);
                (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt()
            })
            .fold(0.0, f64::max)
    }
}
