//! The recording's layout: entity paths, timelines, colour scales, series styles and cadences
//! (documented in the crate docs (`lib.rs`)).
use std::time::Duration;

use rerun::components::Colormap;

use platefall_core::sim::StepSample;

/// Rerun application id of every recording.
pub const APPLICATION_ID: &str = "platefall";

/// Entity paths (stable; see the crate docs (`lib.rs`)).
pub mod paths {
    /// Inertial frame, physical coordinates (Y up, gravity −Y).
    pub const WORLD: &str = "/world";
    /// A frame translating with the plate's centre, not rotating, with Y mirrored for the screen
    /// (the origin of the flow views).
    pub const FOLLOW: &str = "/world/follow";
    /// The inertial frame with Y mirrored for the screen (origin of the trajectory view).
    pub const WORLD_SCREEN: &str = "/world/screen";
    /// A faint circle around the plate: the reach of the turning image window.
    pub const REACH: &str = "/world/follow/reach";
    /// The plate pose: Transform3D (X, Y, θ); children are in body coordinates.
    pub const PLATE: &str = "/world/plate";
    /// The plate's outline and fill in body coordinates (static LineStrips2D).
    pub const OUTLINE: &str = "/world/plate/outline";
    /// Contours of the stream function relative to the chosen observer frame (LineStrips2D).
    pub const STREAMLINES: &str = "/world/plate/streamlines";
    /// Field images under `PLATE` (the close-up, body axes) and `WAKE` (path frame).
    pub const FIELDS: &[&str] = &["vorticity", "pressure", "speed"];
    /// The wake window's frame at each snapshot: Transform3D translation (X, Y) and rotation by
    /// the path heading; its field images are in path-frame coordinates.
    pub const WAKE: &str = "/world/wake";
    /// The plate at each snapshot, drawn in the path frame.
    pub const WAKE_PLATE: &str = "/world/wake/plate";
    /// A faint border of the wake window (static, path frame).
    pub const WAKE_WINDOW: &str = "/world/wake/window";
    /// The path frame with Y mirrored for the screen (origin of the wake views).
    pub const WAKE_SCREEN: &str = "/world/wake/screen";
    /// The centre's path, one LineStrips2D child per time segment.
    pub const TRAJECTORY: &str = "/world/trajectory";
    /// Plate outlines every 0.5 c/U along the path (strobe picture), one child per time segment.
    pub const STROBE: &str = "/world/strobe";
    /// Parent of the C_L, C_D, C_M series (Scalars every step).
    pub const COEFFICIENTS: &str = "/coefficients";
    /// Parent of the V, θ̇, γ, α series (Scalars every step; angles in radians).
    pub const MOTION: &str = "/motion";
    /// Parent of the solver's series.
    pub const SOLVER: &str = "/solver";
    /// The time step Δt (c/U), every step.
    pub const DT: &str = "/solver/dt";
    /// Transform3D scale (1, −1): the mirrored frame the α plots are viewed through.
    pub const POLAR_SCREEN: &str = "/polar/screen";
    /// C_L, C_D, C_M against α, grown over time (LineStrips2D).
    pub const POLAR_COEFFICIENTS: &str = "/polar/coefficients";
    /// V and θ̇ against α, grown over time (LineStrips2D).
    pub const POLAR_MOTION: &str = "/polar/motion";
    /// TextDocument: title, version, command line and the configuration JSON.
    pub const CONFIG: &str = "/run/config";
    /// TextDocument: the outcome, the end-of-run report and the summary JSON.
    pub const SUMMARY: &str = "/run/summary";
    /// How the run was started, as JSON (`provenance::RecordedInvocation`; static).
    pub const INVOCATION: &str = "/run/invocation";
    /// The summary JSON, as `--summary` writes it (static, logged at the end).
    pub const SUMMARY_JSON: &str = "/run/summary_json";
    /// The end-of-run report as plain text (static, logged at the end).
    pub const REPORT: &str = "/run/report";
    /// TextLog: started, skipped-snapshot warnings, and how the run ended.
    pub const STATUS: &str = "/run/status";
    /// Scalars at every field snapshot: the snapshots skipped so far.
    pub const SKIPPED_FIELDS: &str = "/run/skipped_fields";
}

/// The step-number timeline.
pub const TIMELINE_STEP: &str = "step";
/// The convective-time timeline (a duration: 1 s of playback = 1 c/U).
pub const TIMELINE_TIME: &str = "time";

/// Field image colour scales: (name, colormap, lower, upper).
pub const FIELD_SCALES: [(&str, Colormap, f64, f64); 3] = [
    ("vorticity", Colormap::CyanToYellow, -10.0, 10.0),
    ("pressure", Colormap::Spectral, -1.5, 1.5),
    ("speed", Colormap::Viridis, 0.0, 2.0),
];

/// Scalar series: (entity, legend name, colour).
pub(super) const SERIES: [(&str, &str, u32); 9] = [
    ("/coefficients/cl", "C_L", 0x4C9BE8FF),
    ("/coefficients/cd", "C_D", 0xE8574CFF),
    ("/coefficients/cm", "C_M", 0x5CC27AFF),
    ("/motion/speed", "V", 0xF2A93BFF),
    ("/motion/omega", "dθ/dt", 0xB07CE8FF),
    ("/motion/gamma", "γ", 0x4CC9D6FF),
    ("/motion/alpha", "α", 0xE86FB0FF),
    (paths::DT, "Δt", 0xBBBBBBFF),
    (paths::SKIPPED_FIELDS, "skipped field snapshots", 0xE8574CFF),
];

/// The angle series (drawn as dots: they wrap at ±π).
pub(super) const ANGLES: [&str; 2] = ["/motion/gamma", "/motion/alpha"];

/// The value of the per-step series `i` of [`SERIES`] (0 to 7) at step `s`.
pub(super) fn series_value(i: usize, s: &StepSample) -> f64 {
    crate::recorded::RecordedStep::of(s).values[i.min(7)]
}

/// Largest batch of steps sent as one set of columns.
pub(super) const MAX_PENDING: usize = 8192;
/// Longest a step waits before it is sent while a viewer watches live: every send makes one
/// chunk per series, and each chunk costs ~1.3 kB in the file beyond its rows, so this trades
/// live latency for size. With the file alone the steps go out in chunks of MAX_PENDING rows, so
/// the file's size does not depend on how fast the machine runs (a wall-clock cadence made a run
/// slowed down 3× by other jobs 2 MB larger).
pub(super) const STEP_FLUSH_LIVE: Duration = Duration::from_secs(1);
/// Convective time between recorded plate poses (the scalars are recorded every step).
pub(super) const POSE_EVERY: f64 = 0.01;
/// The α plots clip values to ±POLAR_CLIP (the impulsive start spikes far beyond).
pub(super) const POLAR_CLIP: f64 = 10.0;
/// Convective time between points of the trajectory and the polar curves.
pub(super) const SAMPLE_EVERY: f64 = 0.02;

/// Colour-scale steps kept in the close-up images: (upper − lower) / IMAGE_LEVELS.
pub(super) const IMAGE_LEVELS: f64 = 1024.0;
/// The same for the wake images: as many steps as a colour map shows (the picture is the same),
/// and runs of equal values in smooth regions for LZ4 (vorticity to 0.08 on hover).
pub(super) const WAKE_IMAGE_LEVELS: f64 = 256.0;

/// The rotation by `angle` (radians, counter-clockwise) about z as a quaternion (x, y, z, w).
pub(super) fn z_rotation(angle: f64) -> [f32; 4] {
    let (sin, cos) = (0.5 * angle).sin_cos();
    [0.0, 0.0, sin as f32, cos as f32]
}
