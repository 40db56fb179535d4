//! `--t-end` on the command line: an [`EndTime`] in c/U or in seconds, converted with the plate's
//! scales, and refused by name when seconds are given for a plate without physical units.
use platefall_core::config::EndTime;
use platefall_core::sim::ReferenceScales;

use super::flags::ArgError;

/// `--t-end`'s value in c/U: seconds need the plate's scales.
pub fn convective(t: EndTime, scales: Option<ReferenceScales>) -> Result<f64, ArgError> {
    t.convective(scales).ok_or_else(|| ArgError::Invalid {
        flag: "--t-end",
        value: t.to_string(),
        accepted: "convective times c/U (e.g. 60); seconds need a plate with physical units \
                   (--chord-mm … --fluid, or the card's preset)"
            .into(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seconds_without_scales_are_refused_by_name() {
        let e = convective(EndTime::Seconds(1.0), None).unwrap_err();
        assert!(e.to_string().contains("--t-end 1s"), "{e}");
        assert_eq!(convective(EndTime::Convective(6.0), None).unwrap(), 6.0);
    }
}
