//! Physical plates for the 6-DOF equations and the card of Gallaway (1985, Table I) in three
//! dimensions (docs/physics.md §2, §8, §9).

use nalgebra::Matrix3;

use super::{Plate6, SixError, State6};

/// The principal moments (I_x, I_y, I_z) of a uniform thin rectangular plate of mass m, chord c
/// (body x) and span b (body z) about its centre (docs/physics.md §9): m b²/12 about the chord,
/// m (b² + c²)/12 about the normal, m c²/12 about the span (the pitch inertia of 2-D).
pub fn thin_plate_inertia(mass: f64, chord: f64, span: f64) -> [f64; 3] {
    let (b2, c2) = (span * span, chord * chord);
    [mass * b2 / 12.0, mass * (b2 + c2) / 12.0, mass * c2 / 12.0]
}

/// The principal moments (I_x, I_y, I_z) of a uniform rectangular box of mass m, chord c (body
/// x), thickness t (body y) and span b (body z) about its centre (docs/physics.md §9):
/// m(t² + b²)/12 about the chord, m(c² + b²)/12 about the normal, m(c² + t²)/12 about the span
/// (the 2-D rectangle's pitch inertia per unit span).
pub fn box_inertia(mass: f64, chord: f64, thickness: f64, span: f64) -> [f64; 3] {
    let (c2, t2, b2) = (chord * chord, thickness * thickness, span * span);
    [
        mass * (t2 + b2) / 12.0,
        mass * (c2 + b2) / 12.0,
        mass * (c2 + t2) / 12.0,
    ]
}

/// A uniform rectangular plate: chord c (body x), thickness t (body y), span b (body z) and its
/// density ρs, in the units of the fluid it is put in.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Slab {
    /// Chord c.
    pub chord: f64,
    /// Thickness t.
    pub thickness: f64,
    /// Span b.
    pub span: f64,
    /// Density ρs.
    pub density: f64,
}

impl Slab {
    /// The volume c t b.
    pub fn volume(&self) -> f64 {
        self.chord * self.thickness * self.span
    }
}

/// A physical rigid plate in a physical fluid, in any consistent units (the card's are ft, slug,
/// s), principal axes along the body axes.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PhysicalPlate6 {
    /// Chord c (body x), the reference length.
    pub chord: f64,
    /// Span b (body z).
    pub span: f64,
    /// Mass m.
    pub mass: f64,
    /// Principal moments of inertia about the centre, (I_x, I_y, I_z): chord, normal, span axes.
    pub inertia: [f64; 3],
    /// Fluid density ρ.
    pub density: f64,
    /// Kinematic viscosity ν.
    pub viscosity: f64,
    /// Reference (release) speed U.
    pub speed: f64,
    /// Gravity g.
    pub gravity: f64,
    /// The displaced fluid mass ρ × volume (buoyancy; 0 for the card, whose weight is the
    /// apparent weight).
    #[serde(default)]
    pub displaced: f64,
}

impl PhysicalPlate6 {
    /// The card of Gallaway (1985), Table I, in three dimensions (docs/physics.md §8, §9), in ft,
    /// slug, s: chord 3 in, span 8 in, weight 7.02e-3 lbf (m = W/g with g = 32.174 ft/s²), pitch
    /// inertia I_z = 1.13e-6 slug·ft² as measured; I_x = m b²/12 (thin plate), and
    /// I_y = I_x + I_z, the perpendicular-axis theorem of a thin plate, which equals m(b² + c²)/12
    /// when I_z = m c²/12 (the measured I_z is 0.6 % below that; taking the thin-plate I_y
    /// instead would make I_y exceed I_x + I_z, which no mass distribution can). Sea-level air
    /// (ρ = 0.0023769 slug/ft³, ν = 1.5723e-4 ft²/s), U = 3 ft/s.
    pub fn card() -> Self {
        let (chord, span) = (0.25, 8.0 / 12.0);
        let gravity = 32.174;
        let mass = 7.02e-3 / gravity;
        let pitch = 1.13e-6;
        let [roll, _, _] = thin_plate_inertia(mass, chord, span);
        Self {
            chord,
            span,
            mass,
            inertia: [roll, roll + pitch, pitch],
            density: 0.0023769,
            viscosity: 1.5723e-4,
            speed: 3.0,
            gravity,
            displaced: 0.0,
        }
    }

    /// A uniform rectangular plate ([`box_inertia`]) in a fluid of density ρ and kinematic
    /// viscosity ν under gravity g, on the reference speed U (docs/physics.md §2, §9), with its
    /// displaced fluid mass ρ c t b: the weight is (m − m_f) g as for the 2-D physical plate.
    pub fn uniform(slab: &Slab, density: f64, viscosity: f64, gravity: f64, speed: f64) -> Self {
        let mass = slab.density * slab.volume();
        Self {
            chord: slab.chord,
            span: slab.span,
            mass,
            inertia: box_inertia(mass, slab.chord, slab.thickness, slab.span),
            density,
            viscosity,
            speed,
            gravity,
            displaced: density * slab.volume(),
        }
    }

    /// A uniform thin rectangular plate ([`thin_plate_inertia`]) of this chord, span and mass.
    #[must_use]
    pub fn thin_rectangle(self) -> Self {
        Self {
            inertia: thin_plate_inertia(self.mass, self.chord, self.span),
            ..self
        }
    }

    /// Re = U c / ν (docs/physics.md §2).
    pub fn reynolds(&self) -> f64 {
        self.speed * self.chord / self.viscosity
    }

    /// The span in chords, b/c.
    pub fn aspect_ratio(&self) -> f64 {
        self.span / self.chord
    }

    /// The non-dimensional body (module docs of [`super`]): m* = m/(ρc³), I* = I/(ρc⁵),
    /// g* = g c/U², m_f* = m_f/(ρc³) (0 for the card: its weight is the apparent weight, as for
    /// the 2-D card). Dividing m*, m_f* and I*_z by b/c gives the 2-D m/(ρc²b), m_f/(ρc²b) and
    /// I/(ρc⁴b).
    ///
    /// # Errors
    /// [`SixError::Dimension`] for the first of chord, span, density, viscosity and speed that is not
    /// finite and positive; the errors of [`Plate6::new`] for the scaled mass, inertia and gravity.
    pub fn nondimensional(&self) -> Result<Plate6, SixError> {
        let positive = [
            ("chord", self.chord),
            ("span", self.span),
            ("density", self.density),
            ("viscosity", self.viscosity),
            ("speed", self.speed),
        ];
        for (name, value) in positive {
            if !(value.is_finite() && value > 0.0) {
                return Err(SixError::Dimension { name, value });
            }
        }
        let mass_unit = self.density * self.chord.powi(3);
        let inertia_unit = mass_unit * self.chord * self.chord;
        let moments = self.inertia.map(|i| i / inertia_unit);
        Plate6::new(
            self.mass / mass_unit,
            Matrix3::from_diagonal(&moments.into()),
            self.gravity * self.chord / (self.speed * self.speed),
            self.displaced / mass_unit,
        )
    }

    /// The release of Gallaway's (1985) case D (docs/physics.md §8): V₀ = U (speed 1) at
    /// γ₀ = −π/4, α₀ = 0.1, the span horizontal.
    pub fn card_release() -> State6 {
        State6::release(1.0, -std::f64::consts::FRAC_PI_4, 0.1)
    }
}
