//! A planar body state as the 3-D flow's frame (docs/three-d.md "Cases").
use nalgebra::{Rotation3, Vector3};

use crate::body::BodyState;
use crate::flow3d::Frame3;

/// The 3-D motion of a plate in planar motion: rotated by θ about the span axis z, its centre
/// moving at (Ẋ, Ẏ, 0), turning at ω = (0, 0, θ̇).
pub fn planar_frame(s: &BodyState) -> Frame3 {
    Frame3::new(
        Rotation3::from_axis_angle(&Vector3::z_axis(), s.theta),
        Vector3::new(s.xdot, s.ydot, 0.0),
        Vector3::new(0.0, 0.0, s.omega),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_body_velocity_is_the_two_dimensional_frames() {
        // The 2-D frame's (u0, v0, θ̇) are the body-axis velocity and the rate (physics.md §3).
        let s = BodyState {
            x: 0.3,
            y: -1.0,
            theta: 0.7,
            xdot: 0.9,
            ydot: -0.4,
            omega: 1.3,
        };
        let f2 = s.frame();
        let f3 = planar_frame(&s);
        let a = f3.body_velocity();
        assert!((a[0] - f2.u0).abs() < 1e-15 && (a[1] - f2.v0).abs() < 1e-15);
        assert_eq!(a[2], 0.0);
        assert_eq!(f3.omega_array(), [0.0, 0.0, 1.3]);
    }
}
