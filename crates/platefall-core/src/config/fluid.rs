//! Named fluids for physical plates (docs/physics.md §2: Re = U c/ν needs the fluid's kinematic viscosity, the
//! weight needs its density). Values at 20 °C and atmospheric pressure; every one can be overridden.

/// A fluid: density and kinematic viscosity in SI units, and where the numbers come from.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Fluid {
    /// Name as the user gave it (`water`, `air`, `glycerol-water`, or `custom`).
    pub name: String,
    /// ρf (kg/m³).
    pub density: f64,
    /// ν (m²/s).
    pub viscosity: f64,
    /// The state and source of the values.
    pub source: String,
}

/// The names [`Fluid::named`] knows.
pub const FLUID_NAMES: [&str; 3] = ["water", "air", "glycerol-water"];

impl Fluid {
    /// Water at 20 °C: ρ = 998.2 kg/m³, μ = 1.002 mPa·s, so ν = 1.004 mm²/s (CRC Handbook of
    /// Chemistry and Physics, properties of water).
    pub fn water() -> Self {
        Self::table(
            "water",
            998.2,
            1.002e-3,
            "20 °C; CRC Handbook of Chemistry and Physics",
        )
    }

    /// Dry air at 20 °C and 101.325 kPa: ρ = 1.204 kg/m³, μ = 18.25 µPa·s, so ν = 15.16 mm²/s
    /// (CRC Handbook, properties of air).
    pub fn air() -> Self {
        Self::table(
            "air",
            1.204,
            1.825e-5,
            "dry, 20 °C, 101.325 kPa; CRC Handbook of Chemistry and Physics",
        )
    }

    /// 50 % glycerol by mass in water at 20 °C: ρ = 1126.3 kg/m³, μ = 6.00 mPa·s, so
    /// ν = 5.33 mm²/s (Glycerine Producers' Association 1963 tables; Cheng 2008, Ind. Eng. Chem.
    /// Res. 47, 3285, whose correlation gives 6.00 mPa·s).
    pub fn glycerol_water() -> Self {
        Self::table(
            "glycerol-water",
            1126.3,
            6.00e-3,
            "50 % glycerol by mass, 20 °C; Glycerine Producers' Association (1963), Cheng (2008)",
        )
    }

    /// The fluid of one of [`FLUID_NAMES`].
    pub fn named(name: &str) -> Option<Self> {
        match name {
            "water" => Some(Self::water()),
            "air" => Some(Self::air()),
            "glycerol-water" => Some(Self::glycerol_water()),
            _ => None,
        }
    }

    /// A fluid from a table: density ρ (kg/m³) and dynamic viscosity μ (Pa·s); ν = μ/ρ.
    fn table(name: &str, density: f64, dynamic_viscosity: f64, source: &str) -> Self {
        Self {
            name: name.into(),
            density,
            viscosity: dynamic_viscosity / density,
            source: source.into(),
        }
    }

    /// The same fluid with some values replaced (density kg/m³, kinematic viscosity m²/s); the
    /// source then says which were given.
    #[must_use]
    pub fn overridden(mut self, density: Option<f64>, viscosity: Option<f64>) -> Self {
        let mut given = Vec::new();
        if let Some(d) = density {
            self.density = d;
            given.push("density");
        }
        if let Some(v) = viscosity {
            self.viscosity = v;
            given.push("viscosity");
        }
        if !given.is_empty() {
            self.source = format!("{} given; otherwise {}", given.join(" and "), self.source);
        }
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn named_fluids_have_their_tabulated_kinematic_viscosity() {
        // ν in mm²/s to the digits the docs quote.
        let nu = |f: Fluid| f.viscosity * 1e6;
        assert!((nu(Fluid::water()) - 1.004).abs() < 5e-4);
        assert!((nu(Fluid::air()) - 15.16).abs() < 5e-3);
        assert!((nu(Fluid::glycerol_water()) - 5.33).abs() < 5e-3);
        for name in FLUID_NAMES {
            assert_eq!(Fluid::named(name).unwrap().name, name);
        }
        assert!(Fluid::named("honey").is_none());
        let w = Fluid::water().overridden(Some(1000.0), None);
        assert_eq!(w.density, 1000.0);
        assert!(w.source.starts_with("density given"));
    }
}
