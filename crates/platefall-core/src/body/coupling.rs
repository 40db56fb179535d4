//! Added-mass stability advisory for explicit fluid–body coupling (docs/physics.md §6, "Coupling":
//! explicit coupling fails for light plates). The default strong coupling
//! ([`StrongCoupling`](super::StrongCoupling)) has no such limit; this advice is for runs that
//! choose the explicit one.
//!
//! The fluid force contains a part proportional to the body's acceleration (added mass). With the
//! force lagged by one step, the body sees −(m_a/m*) × its own previous acceleration, so the
//! explicit iteration amplifies errors by about the ratio m_a/m*; it diverges for m_a/m* ≥ 1 and is
//! marginal (slow, oscillatory decay) as the ratio approaches 1. For a flat plate of chord 1 the
//! 2-D added mass per unit span for normal motion is π/4 (by ρc²) and the added pitch inertia about
//! the centre is π/128 (by ρc⁴).

use std::f64::consts::PI;

use super::rigid::PlateProps;

/// 2-D added mass of a flat plate of chord 1 in normal motion, π(c/2)²ρ = π/4 (by ρc²).
pub const PLATE_ADDED_MASS: f64 = PI / 4.0;
/// 2-D added pitch inertia of a flat plate of chord 1 about its centre, π(c/2)⁴ρ/8 = π/128 (by ρc⁴).
pub const PLATE_ADDED_INERTIA: f64 = PI / 128.0;
/// Below this multiple of the added mass/inertia, [`coupling_advice`] warns.
pub const ADVICE_MARGIN: f64 = 1.5;

/// A warning when the plate is light enough that explicit coupling may be unstable:
/// m* < 1.5·π/4 or I* < 1.5·π/128 (added-to-body ratio above 2/3). `None` when both are heavier.
pub fn coupling_advice(props: &PlateProps) -> Option<String> {
    let mut parts = Vec::new();
    if props.mass.is_nan() || props.mass < ADVICE_MARGIN * PLATE_ADDED_MASS {
        parts.push(format!(
            "m* = {:.4} is light: the plate's added mass π/4 ≈ {:.4} is {:.2} × m* \
             (warning above {:.2}, diverges at 1; m* ≥ {:.4} for no warning)",
            props.mass,
            PLATE_ADDED_MASS,
            PLATE_ADDED_MASS / props.mass,
            1.0 / ADVICE_MARGIN,
            ADVICE_MARGIN * PLATE_ADDED_MASS
        ));
    }
    if props.inertia.is_nan() || props.inertia < ADVICE_MARGIN * PLATE_ADDED_INERTIA {
        parts.push(format!(
            "I* = {:.4} is light: the plate's added pitch inertia π/128 ≈ {:.5} is {:.2} × I* \
             (warning above {:.2}, diverges at 1; I* ≥ {:.5} for no warning)",
            props.inertia,
            PLATE_ADDED_INERTIA,
            PLATE_ADDED_INERTIA / props.inertia,
            1.0 / ADVICE_MARGIN,
            ADVICE_MARGIN * PLATE_ADDED_INERTIA
        ));
    }
    (!parts.is_empty()).then(|| {
        format!(
            "explicit fluid–body coupling may be unstable (errors grow by about added/body \
             mass each step): {}",
            parts.join("; ")
        )
    })
}
