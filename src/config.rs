//! Run configuration: the four cases (SPEC §1), the physical preset, and validation with one clear
//! line per bad value naming the accepted range.
use std::f64::consts::PI;

use serde::{Deserialize, Serialize};

use crate::body::{AbStart, PhysicalPlate, PlateProps};
use crate::flow::FlowParams;
use crate::grid::GridSpec;

/// The prescribed or free motion of a run (SPEC §1, cases A–D).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Case {
    /// A: translates at U to the right (+X) at a fixed angle of attack α, impulsively started.
    /// During the first convective time the pitch is nudged by `kick`·sin²(πt) (smooth, zero at
    /// both ends) so that a symmetric configuration (α = π/2) does not rely on round-off to break
    /// its symmetry; afterwards α is exact.
    Static { alpha: f64, kick: f64 },
    /// B: translates at U; θ spun up from 0 at constant angular acceleration over `spinup` convective
    /// times to the rate `rate`, then held.
    Forced { rate: f64, spinup: f64 },
    /// C: translates at U, free to rotate about its centre; held at α₀ for `develop`, then released.
    Pinned { alpha0: f64, develop: f64 },
    /// D: moves at V₀ along γ₀ at α₀ for `develop`, then falls freely (3 DOF, gravity).
    Free {
        v0: f64,
        gamma0: f64,
        alpha0: f64,
        develop: f64,
    },
}

impl Case {
    pub fn name(&self) -> &'static str {
        match self {
            Case::Static { .. } => "static",
            Case::Forced { .. } => "forced",
            Case::Pinned { .. } => "pinned",
            Case::Free { .. } => "free",
        }
    }
    /// Whether the plate's equations of motion are integrated.
    pub fn is_coupled(&self) -> bool {
        matches!(self, Case::Pinned { .. } | Case::Free { .. })
    }
}

/// The plate's inertia and gravity (coupled cases), with where they came from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BodyConfig {
    /// "card" when the values come from the seed's card preset (possibly overridden).
    pub preset: Option<String>,
    pub props: PlateProps,
    /// Adams–Bashforth order (1..=6) and start procedure (SPEC §6).
    pub ab_order: usize,
    pub ab_start: AbStart,
}

/// Everything that defines a run; serialised into the recording and the summary.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RunConfig {
    pub case: Case,
    pub grid: GridSpec,
    pub flow: FlowParams,
    pub body: Option<BodyConfig>,
    /// End time in convective times c/U from the impulsive start (development included).
    pub t_end: f64,
    /// Stop after this many net turns of θ after release (coupled cases), if reached before t_end.
    pub turns: Option<f64>,
    /// Time-step ceiling (seed: 0.01).
    pub dt_max: f64,
    /// The seed's rotation rule Δt·|θ̇| ≤ C_c (seed: 0.005).
    pub cc: f64,
}

/// A configuration error: one line naming the value and the accepted range.
#[derive(Debug, Clone, PartialEq)]
pub struct ConfigError(pub String);

impl std::fmt::Display for ConfigError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}
impl std::error::Error for ConfigError {}

/// Checks that `value` is finite and in [lo, hi] (or (lo, hi] when `open_lo`).
pub fn check_range(
    name: &str,
    value: f64,
    lo: f64,
    hi: f64,
    open_lo: bool,
) -> Result<(), ConfigError> {
    let ok = value.is_finite() && value <= hi && if open_lo { value > lo } else { value >= lo };
    if ok {
        Ok(())
    } else {
        let open = if open_lo { "(" } else { "[" };
        Err(ConfigError(format!(
            "{name} = {value} is out of range: accepted {open}{lo}, {hi}]"
        )))
    }
}

impl RunConfig {
    /// Validates every value; the first bad one is reported.
    pub fn validate(&self) -> Result<(), ConfigError> {
        self.grid.validate().map_err(|e| ConfigError(e.0))?;
        check_range("Reynolds number --re", self.flow.re, 0.0, 1e5, true)?;
        check_range("--cfl", self.flow.cfl, 0.0, 1.0, true)?;
        check_range("--t-end", self.t_end, 0.0, 1e5, true)?;
        check_range("--dt-max", self.dt_max, 0.0, 1.0, true)?;
        check_range("--cc", self.cc, 0.0, 1.0, true)?;
        if let Some(n) = self.turns {
            check_range("--turns", n, 0.0, 1e4, true)?;
        }
        match self.case {
            Case::Static { alpha, kick } => {
                check_range("--alpha (rad)", alpha, -PI, PI, false)?;
                check_range("--kick (rad)", kick.abs(), 0.0, 0.2, false)?;
            }
            Case::Forced { rate, spinup } => {
                check_range("--rate (θ̇ c/U)", rate.abs(), 0.0, 20.0, true)?;
                check_range("--spinup", spinup, 0.0, 1e3, false)?;
            }
            Case::Pinned { alpha0, develop } => {
                check_range("--alpha0 (rad)", alpha0, -PI, PI, false)?;
                check_range("--develop", develop, 0.0, 1e3, false)?;
            }
            Case::Free {
                v0,
                gamma0,
                alpha0,
                develop,
            } => {
                check_range("--v0 (on the reference speed)", v0, 0.0, 10.0, false)?;
                check_range("--gamma0 (rad)", gamma0, -PI, PI, false)?;
                check_range("--alpha0 (rad)", alpha0, -PI, PI, false)?;
                check_range("--develop", develop, 0.0, 1e3, false)?;
            }
        }
        if self.case.is_coupled() {
            let b = self
                .body
                .as_ref()
                .ok_or_else(|| ConfigError("a coupled case needs plate properties".into()))?;
            check_range("--mass (m*)", b.props.mass, 0.0, 1e6, true)?;
            check_range("--inertia (I*)", b.props.inertia, 0.0, 1e6, true)?;
            check_range("--gravity (g*)", b.props.gravity, 0.0, 1e3, false)?;
            if !(1..=6).contains(&b.ab_order) {
                return Err(ConfigError(format!(
                    "--ab-order = {} is out of range: accepted 1..=6",
                    b.ab_order
                )));
            }
            crate::body::coupling_check(&b.props).map_err(ConfigError)?;
        }
        Ok(())
    }

    /// A one-line description of the run.
    pub fn title(&self) -> String {
        let case = match &self.case {
            Case::Static { alpha, .. } => format!("static plate, α = {alpha:.4} rad"),
            Case::Forced { rate, spinup } => {
                format!("forced rotation, θ̇ = {rate}, spin-up {spinup}")
            }
            Case::Pinned { alpha0, .. } => {
                format!("pinned autorotation, released at α₀ = {alpha0}")
            }
            Case::Free {
                v0, gamma0, alpha0, ..
            } => {
                format!("free fall, V₀ = {v0}, γ₀ = {gamma0:.4}, α₀ = {alpha0}")
            }
        };
        let preset = self
            .body
            .as_ref()
            .and_then(|b| b.preset.as_deref())
            .map(|p| format!(", {p} preset"))
            .unwrap_or_default();
        format!(
            "{case}{preset}, Re {:.0}, N = {}",
            self.flow.re, self.grid.resolution
        )
    }

    /// The card preset's physical plate when this run uses it (for physical units in reports).
    pub fn physical(&self) -> Option<PhysicalPlate> {
        match self.body.as_ref()?.preset.as_deref() {
            Some("card") => Some(PhysicalPlate::card()),
            _ => None,
        }
    }
}
