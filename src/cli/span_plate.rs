//! The plate a free fall with `--span` flies (docs/three-d.md "Free flight"): the card of
//! Gallaway (1985) in three dimensions, or a physical plate (`--chord-mm`, `--thickness-mm`,
//! `--plate-density`, the fluid, `--g`) as a uniform box whose span is `--span`'s B (or P) chords;
//! `--span-mm`, when given, must say the same span in millimetres.
use super::command::Command;
use super::flags::ArgError;
use super::plate_args::PhysicalArgs;
use platefall_core::body::six::{PhysicalPlate6, Plate6};
use platefall_core::config::Strip;
use platefall_core::flow3d::Span;
use platefall_core::param::{check_range, InputError, Param};

/// Relative difference tolerated between `--span-mm` and `--span` times the chord (round-off of
/// a span typed in both units).
const SPAN_AGREEMENT: f64 = 1e-6;

/// The non-dimensional plate a free fall with `span` flies and, for a physical plate, the lines
/// that state its span and box moments (after the 2-D derivation the run prints first).
///
/// # Errors
/// An [`ArgError`] naming `--span-mm` when it is out of range or says another span than `--span`,
/// the first bad input of the physical plate, or the plate's
/// [`platefall_core::body::six::SixError`].
pub(super) fn flight_plate(cmd: &Command, span: Span) -> anyhow::Result<(Plate6, Vec<String>)> {
    let physical = match cmd {
        Command::Free(a) => Some(&a.body.physical),
        _ => None,
    };
    let Some((args, strip)) = physical.and_then(|p| Some((p, p.strip()?))) else {
        return Ok((PhysicalPlate6::card().nondimensional()?, Vec::new()));
    };
    let plate = strip.plate6(span_m(args, &strip, span)?)?;
    Ok((plate.nondimensional()?, strip.derivation3(&plate)))
}

/// The plate's span in metres: `--span`'s chords, which `--span-mm` must agree with.
fn span_m(args: &PhysicalArgs, strip: &Strip, span: Span) -> Result<f64, ArgError> {
    let chords = span.length();
    if let Some(mm) = args.span_mm {
        check_range(Param::PlateSpan, mm, 0.0, 1e4, true)?;
        let implied = mm * 1e-3 / strip.chord;
        if (implied / chords - 1.0).abs() > SPAN_AGREEMENT {
            let why = format!(
                "--span gives {chords} chords = {} mm of span; give that, or --span {implied}",
                chords * strip.chord * 1e3
            );
            return Err(InputError::Inconsistent {
                param: Param::PlateSpan,
                value: mm,
                why,
            }
            .into());
        }
    }
    Ok(chords * strip.chord)
}
