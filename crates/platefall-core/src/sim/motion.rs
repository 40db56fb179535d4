//! The motion laws of the four cases (docs/physics.md §1, cases A–D): what is prescribed, and when the plate
//! is released to its own equations of motion.
use std::f64::consts::PI;

use serde::{Deserialize, Serialize};

use crate::body::BodyState;

/// The prescribed or free motion of a run (docs/physics.md §1, cases A–D).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Case {
    /// A: translates at U to the right (+X) at a fixed angle of attack α, impulsively started.
    /// During the first convective time the pitch is nudged by `kick`·sin²(πt) (smooth, zero at
    /// both ends) so that a symmetric configuration (α = π/2) does not rely on round-off to break
    /// its symmetry; afterwards α is exact.
    Static {
        /// The angle of attack (rad).
        alpha: f64,
        /// The start-up pitch nudge ε (rad).
        kick: f64,
    },
    /// B: translates at U; θ spun up from 0 at constant angular acceleration over `spinup` convective
    /// times to the rate θ̇ = `omega`, then held.
    Forced {
        /// The final rotation rate θ̇.
        omega: f64,
        /// The spin-up time.
        spinup: f64,
    },
    /// C: translates at `speed` (U = 1, the wind tunnel; 0: a pin in still fluid), free to rotate
    /// about its centre; held at α₀ for `develop`, then released.
    Pinned {
        /// The angle of attack held until release (rad).
        alpha0: f64,
        /// The time held before release.
        develop: f64,
        /// The translation speed.
        #[serde(default = "unit_speed")]
        speed: f64,
    },
    /// D: moves at V₀ along γ₀ at α₀ for `develop`, then falls freely (3 DOF, gravity).
    Free {
        /// The launch speed V₀.
        v0: f64,
        /// The launch flight-path angle γ₀ (rad).
        gamma0: f64,
        /// The launch angle of attack α₀ (rad); θ = γ₀ + α₀ until release.
        alpha0: f64,
        /// The time held before release.
        develop: f64,
    },
}

/// Which of the four cases a run is (docs/physics.md §1), without its parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CaseKind {
    /// A: `static`.
    Static,
    /// B: `forced`.
    Forced,
    /// C: `pinned`.
    Pinned,
    /// D: `free`.
    Free,
}

impl CaseKind {
    /// Every case, in the order A–D.
    pub const ALL: [CaseKind; 4] = [
        CaseKind::Static,
        CaseKind::Forced,
        CaseKind::Pinned,
        CaseKind::Free,
    ];

    /// The case's name as outputs and the command line spell it: `static`, `forced`, `pinned`,
    /// `free`.
    pub fn name(self) -> &'static str {
        match self {
            CaseKind::Static => "static",
            CaseKind::Forced => "forced",
            CaseKind::Pinned => "pinned",
            CaseKind::Free => "free",
        }
    }

    /// The case of a name (see [`CaseKind::name`]).
    pub fn from_name(name: &str) -> Option<CaseKind> {
        CaseKind::ALL.into_iter().find(|k| k.name() == name)
    }

    /// Whether the plate's equations of motion are integrated (pinned, free).
    pub fn is_coupled(self) -> bool {
        matches!(self, CaseKind::Pinned | CaseKind::Free)
    }
}

impl std::fmt::Display for CaseKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl Case {
    /// Which case this is.
    pub fn kind(&self) -> CaseKind {
        match self {
            Case::Static { .. } => CaseKind::Static,
            Case::Forced { .. } => CaseKind::Forced,
            Case::Pinned { .. } => CaseKind::Pinned,
            Case::Free { .. } => CaseKind::Free,
        }
    }

    /// The case's name (`static`, `forced`, `pinned`, `free`).
    pub fn name(&self) -> &'static str {
        self.kind().name()
    }

    /// Whether the plate's equations of motion are integrated.
    pub fn is_coupled(&self) -> bool {
        self.kind().is_coupled()
    }

    /// The release time (coupled), the end of spin-up (forced) or 0 (static).
    pub fn release_time(&self) -> f64 {
        match *self {
            Case::Static { .. } => 0.0,
            Case::Forced { spinup, .. } => spinup,
            Case::Pinned { develop, .. } | Case::Free { develop, .. } => develop,
        }
    }

    /// The prescribed motion at time t: cases A and B, and the development phase of C and D.
    ///
    /// A: X = t, θ = α (+ the start-up kick ε sin²(πt) for t < 1). B: X = t, θ̈ = θ̇/T_s for
    /// t < T_s, then θ̇ held. C: X = V t, θ = α₀. D: moving at V₀ along γ₀ with θ = γ₀ + α₀.
    pub fn prescribed_state(&self, t: f64) -> BodyState {
        let translate = |v: f64, gamma: f64, theta: f64, omega: f64| BodyState {
            x: v * gamma.cos() * t,
            y: v * gamma.sin() * t,
            theta,
            xdot: v * gamma.cos(),
            ydot: v * gamma.sin(),
            omega,
        };
        match *self {
            Case::Static { alpha, kick } => {
                let (theta, omega) = if t < 1.0 {
                    let s = (PI * t).sin();
                    (alpha + kick * s * s, kick * PI * (2.0 * PI * t).sin())
                } else {
                    (alpha, 0.0)
                };
                translate(1.0, 0.0, theta, omega)
            }
            Case::Forced { omega, spinup } => {
                let (theta, rate) = if t < spinup {
                    (0.5 * omega / spinup * t * t, omega * t / spinup)
                } else {
                    (0.5 * omega * spinup + omega * (t - spinup), omega)
                };
                translate(1.0, 0.0, theta, rate)
            }
            Case::Pinned { alpha0, speed, .. } => translate(speed, 0.0, alpha0, 0.0),
            Case::Free {
                v0, gamma0, alpha0, ..
            } => translate(v0, gamma0, gamma0 + alpha0, 0.0),
        }
    }
}

/// The wind-tunnel speed of a pinned plate when a description does not give one.
fn unit_speed() -> f64 {
    1.0
}
