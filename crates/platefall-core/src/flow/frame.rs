//! The plate's motion as the flow solver sees it (docs/physics.md §3): the centre's velocity along the body
//! axes and the pitch rate, which give the grid-point velocity g.

/// The plate's motion in body axes: the inertial velocity of the centre expressed along the body
/// axes, (u0, v0) = (ẋ₀cosθ + ẏ₀sinθ, −ẋ₀sinθ + ẏ₀cosθ), and the pitch rate θ̇ (docs/physics.md §3).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Frame {
    /// Velocity of the plate centre along the body x axis.
    pub u0: f64,
    /// Velocity of the plate centre along the body y axis.
    pub v0: f64,
    /// Pitch rate θ̇.
    pub omega: f64,
}

impl Frame {
    /// Grid-point velocity x-component at height y: g_x = u0 − θ̇ y (docs/physics.md §3).
    #[inline(always)]
    pub fn gx(&self, y: f64) -> f64 {
        self.u0 - self.omega * y
    }
    /// Grid-point velocity y-component at abscissa x: g_y = v0 + θ̇ x (docs/physics.md §3).
    #[inline(always)]
    pub fn gy(&self, x: f64) -> f64 {
        self.v0 + self.omega * x
    }
    /// The motion a step of `dt` after this one, extrapolated linearly from this one and
    /// `before`, a step of `dt_before` earlier (this one when there is no step before).
    pub fn extrapolated(&self, before: &Frame, dt: f64, dt_before: f64) -> Frame {
        if dt_before <= 0.0 {
            return *self;
        }
        let r = dt / dt_before;
        Frame {
            u0: self.u0 + r * (self.u0 - before.u0),
            v0: self.v0 + r * (self.v0 - before.v0),
            omega: self.omega + r * (self.omega - before.omega),
        }
    }

    /// Speed of the centre, |(u0, v0)|.
    pub fn speed(&self) -> f64 {
        self.u0.hypot(self.v0)
    }
}
