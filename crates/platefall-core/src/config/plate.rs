//! The plate of a coupled run (pinned, free): its non-dimensional properties (docs/physics.md §2), where they
//! come from, and what else they imply for the run: a Reynolds number, physical scales for
//! reports and, for a plate described physically, the strip itself (its thickness in chords, and
//! its mass and inertia for any section).
use super::preset::PhysicalPlate;
use super::strip::Strip;
use crate::body::PlateProps;
use crate::param::InputError;
use crate::sim::{PlateSource, ReferenceScales};

/// A plate for [`RunBuilder::pinned`](super::RunBuilder::pinned) and
/// [`RunBuilder::free`](super::RunBuilder::free).
///
/// ```
/// use platefall_core::config::{Fluid, Plate, Strip};
/// // The dissertation's card, 20 % heavier.
/// let card = Plate::card().mass(1.2 * Plate::card().props().mass);
/// // A 10 × 0.5 mm aluminium strip in water.
/// let strip = Plate::strip(&Strip {
///     chord: 0.01,
///     thickness: 5e-4,
///     density: 2700.0,
///     fluid: Fluid::water(),
///     gravity: 9.81,
/// })?;
/// assert!((strip.reynolds().unwrap() - 911.0).abs() < 1.0);
/// # Ok::<(), platefall_core::param::InputError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Plate {
    source: PlateSource,
    props: PlateProps,
    reynolds: Option<f64>,
    scales: Option<ReferenceScales>,
    strip: Option<Strip>,
}

impl Plate {
    /// The dissertation's card in sea-level air (docs/physics.md §8): m* ≈ 2.20, I* ≈ 0.183, g* ≈ 0.894 with the
    /// apparent weight (m_f* = 0), Re ≈ 4770, and the card's scales for reports in feet.
    pub fn card() -> Plate {
        let card = PhysicalPlate::card();
        Plate {
            source: PlateSource::Card,
            props: card.props(),
            reynolds: Some(card.reynolds()),
            scales: Some(card.scales()),
            strip: None,
        }
    }

    /// A plate given by m*, I*, g* alone (no buoyancy, no applied moment). It implies no
    /// Reynolds number: give one with [`RunBuilder::re`](super::RunBuilder::re).
    pub fn nondimensional(mass: f64, inertia: f64, gravity: f64) -> Plate {
        Plate {
            source: PlateSource::NonDimensional,
            props: PlateProps::new(mass, inertia, gravity),
            reynolds: None,
            scales: None,
            strip: None,
        }
    }

    /// A plate described physically ([`Strip`], validated here): m*, I*, g*, m_f* and Re are
    /// derived from it (for the run's section: [`Strip::props_of`]), and the section has its
    /// thickness unless the run gives one.
    ///
    /// # Errors
    /// The [`InputError`] of [`Strip::validate`] for the first bad input.
    pub fn strip(strip: &Strip) -> Result<Plate, InputError> {
        strip.validate()?;
        Ok(Plate {
            source: PlateSource::Physical(strip.describe()),
            props: strip.props(),
            reynolds: Some(strip.reynolds()),
            scales: Some(strip.scales()),
            strip: Some(strip.clone()),
        })
    }

    /// The same plate with m* replaced.
    #[must_use]
    pub fn mass(mut self, mass: f64) -> Plate {
        self.props.mass = mass;
        self
    }

    /// The same plate with I* replaced.
    #[must_use]
    pub fn inertia(mut self, inertia: f64) -> Plate {
        self.props.inertia = inertia;
        self
    }

    /// The same plate with g* replaced.
    #[must_use]
    pub fn gravity(mut self, gravity: f64) -> Plate {
        self.props.gravity = gravity;
        self
    }

    /// The same plate with the displaced fluid mass m_f* (buoyancy) replaced.
    #[must_use]
    pub fn displaced(mut self, displaced: f64) -> Plate {
        self.props.displaced = displaced;
        self
    }

    /// The same plate with an applied moment (by ρU²c², counter-clockwise positive).
    #[must_use]
    pub fn torque(mut self, torque: f64) -> Plate {
        self.props.torque = torque;
        self
    }

    /// Where the values come from.
    pub fn source(&self) -> &PlateSource {
        &self.source
    }

    /// m*, I*, g*, m_f* and the applied moment.
    pub fn props(&self) -> &PlateProps {
        &self.props
    }

    /// The Reynolds number the plate implies (the card's, a physical plate's), if any.
    pub fn reynolds(&self) -> Option<f64> {
        self.reynolds
    }

    /// The chord and velocity scale behind the plate's units, if it has physical ones.
    pub fn scales(&self) -> Option<ReferenceScales> {
        self.scales
    }

    /// The thickness in chords of a plate described physically.
    pub fn thickness(&self) -> Option<f64> {
        self.strip.as_ref().map(Strip::aspect)
    }

    /// The strip of a plate described physically.
    pub fn physical_strip(&self) -> Option<&Strip> {
        self.strip.as_ref()
    }

    /// Whether the plate is described physically.
    pub fn is_physical(&self) -> bool {
        matches!(self.source, PlateSource::Physical(_))
    }
}
