//! The loads on the plate as the solver reports them (docs/physics.md §5): the force and moment in body
//! axes, and the lift, drag and moment coefficients. How they are computed from the flow is in
//! `flow/wall/loads.rs`.
use super::frame::Frame;

/// Force (body axes) and moment about the centre (counter-clockwise positive), per unit span,
/// non-dimensional on ρU²c and ρU²c².
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct BodyAxesLoads {
    /// The force along the body x axis (the chord).
    pub fx: f64,
    /// The force along the body y axis (normal to the chord).
    pub fy: f64,
    /// The moment about the plate's centre, counter-clockwise positive.
    pub moment: f64,
    /// The pressure's part of `fx` (the rest is shear), for reporting.
    pub fx_pressure: f64,
    /// The pressure's part of `fy`, for reporting.
    pub fy_pressure: f64,
}

/// Lift, drag and moment coefficients on the reference speed (docs/physics.md §5): with ê_V the unit vector
/// of the plate's velocity in body axes and ê_L = ê_V turned 90° counter-clockwise,
/// D = −F·ê_V, L = F·ê_L, C = 2·(force)/(U_ref² c). When the plate is not translating, ê_V falls
/// back to the body x axis.
pub fn coefficients(l: &BodyAxesLoads, frame: &Frame) -> (f64, f64, f64) {
    let speed = frame.speed();
    let (ex, ey) = if speed > 1e-12 {
        (frame.u0 / speed, frame.v0 / speed)
    } else {
        (1.0, 0.0)
    };
    let drag = -(l.fx * ex + l.fy * ey);
    let lift = l.fx * (-ey) + l.fy * ex;
    (2.0 * lift, 2.0 * drag, 2.0 * l.moment)
}
