//! The library names a bad input by its quantity ([`Param`]); the command line names its flag.
use platefall_core::param::{InputError, Param};

/// The flag that sets `p`.
pub fn flag(p: Param) -> &'static str {
    match p {
        Param::Resolution => "--resolution",
        Param::Thickness => "--thickness",
        Param::Shape => "--shape",
        Param::EdgeRadius => "--edge-radius",
        Param::Polygon => "--polygon",
        Param::ExtentX | Param::ExtentY => "--extent",
        Param::Growth => "--growth",
        Param::StretchIntervals => "--seed-grid",
        Param::Reynolds => "--re",
        Param::Cfl => "--cfl",
        Param::TEnd => "--t-end",
        Param::DtMax => "--dt-max",
        Param::Cc => "--cc",
        Param::Turns => "--turns",
        Param::AverageFromTurn => "--average-from-turn",
        Param::Alpha => "--alpha",
        Param::Kick => "--kick",
        Param::ForcedOmega => "--rate",
        Param::Spinup => "--spinup",
        Param::Alpha0 => "--alpha0",
        Param::Develop => "--develop",
        Param::V0 => "--v0",
        Param::Gamma0 => "--gamma0",
        Param::Mass => "--mass",
        Param::Inertia => "--inertia",
        Param::Gravity => "--gravity",
        Param::DisplacedMass => "--displaced-mass",
        Param::Torque => "--torque",
        Param::AbOrder => "--ab-order",
        Param::NearX => "--near-x",
        Param::NearY => "--near-y",
        Param::Threads => "--threads",
        Param::Chord => "--chord-mm",
        Param::PlateThickness => "--thickness-mm",
        Param::PlateSpan => "--span-mm",
        Param::PlateDensity => "--plate-density",
        Param::FluidDensity => "--fluid-density",
        Param::Viscosity => "--viscosity",
        Param::GravityAccel => "--g",
    }
}

/// A bad command line: one line naming the flag, the value and what is accepted.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ArgError {
    /// A value the library refused (the message already says all the library's does, so the
    /// library's error is not repeated as a source).
    #[error("{}", input_message(.0))]
    Input(InputError),
    /// A value the command line needs and did not get.
    #[error("{flag} is required {when}")]
    Missing {
        flag: &'static str,
        when: &'static str,
    },
    /// A subcommand that describes no run.
    #[error("`{0}` is not a case subcommand (static, forced, pinned, free)")]
    NotACase(&'static str),
    /// A flag given where it does not apply.
    #[error("{flag} {when}")]
    Refused {
        flag: &'static str,
        when: &'static str,
    },
    /// A value out of its accepted range.
    #[error("{flag} {value} is out of range: accepted {accepted}")]
    Invalid {
        flag: &'static str,
        value: String,
        accepted: String,
    },
    /// A file named by a flag that cannot be read or holds bad data.
    #[error("{flag} {path}: {why}")]
    File {
        flag: &'static str,
        path: String,
        why: String,
    },
}

impl From<InputError> for ArgError {
    fn from(e: InputError) -> Self {
        ArgError::Input(e)
    }
}

/// The library's message with the flag put in front of the quantity's value.
fn input_message(e: &InputError) -> String {
    match e {
        InputError::OutOfRange {
            param,
            value,
            accepted,
        } => format!(
            "{} {value} is out of range: accepted {accepted} ({})",
            flag(*param),
            param.describe()
        ),
        InputError::Inconsistent { param, value, why } => {
            format!("{} {value} is not accepted: {why}", flag(*param))
        }
        InputError::Missing { param, why } => format!("{} is required {why}", flag(*param)),
        InputError::MissingPlate | InputError::Conflict { .. } => e.to_string(),
        InputError::Shape(s) => format!("{}: {s}", flag(s.param())),
        InputError::TooThin { .. } => format!("{}: {e}", flag(Param::Resolution)),
    }
}
