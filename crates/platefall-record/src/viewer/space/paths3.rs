//! Entity paths of a 3-D recording (docs/three-d.md "Recording").
/// Inertial frame (chords, Y up, gravity −Y).
pub const WORLD: &str = "/world";
/// The plate's pose (Transform3D: the centre and the body-to-inertial rotation); its
/// children are in body axes.
pub const PLATE: &str = "/world/plate";
/// The plate as a box (static, body axes).
pub const BOX: &str = "/world/plate/box";
/// The vortex iso-surface Q = level at each snapshot (Mesh3D, body axes).
pub const Q: &str = "/world/plate/q";
/// The mid-span slice coloured by ω_z at each snapshot (Mesh3D, body axes).
pub const MID_SPAN: &str = "/world/plate/slice_midspan";
/// The mid-chord slice coloured by ω_x at each snapshot (Mesh3D, body axes).
pub const MID_CHORD: &str = "/world/plate/slice_midchord";
/// The centre's path, one LineStrips3D child per time segment.
pub const TRAJECTORY: &str = "/world/trajectory";
/// The plate's poses every 0.5 c/U (Boxes3D), one child per time segment.
pub const STROBE: &str = "/world/strobe";
/// C_L, C_D, C_S, C_roll, C_yaw, C_pitch (Scalars every step).
pub const COEFFICIENTS: &str = "/coefficients";
/// Roll, yaw, pitch (rad), ω_x, ω_y, ω_z (U/c, body axes) and the speed (U), every step.
pub const MOTION: &str = "/motion";
/// Pressure iterations and divergence, every step.
pub const SOLVER: &str = "/solver";
/// TextDocument: the run's description.
pub const CONFIG: &str = "/run/config";
/// TextDocument: the outcome and the end-of-run report.
pub const SUMMARY: &str = "/run/summary";
/// TextLog: started, and how the run ended.
pub const STATUS: &str = "/run/status";
