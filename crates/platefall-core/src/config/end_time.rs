//! An end time as a person gives it: convective times c/U ("60"), or seconds of physical time
//! for a plate with physical units ("10.5s"), converted with its chord and velocity scale
//! (docs/physics.md §2: t [s] = t [c/U] · c / U).
use std::fmt;
use std::str::FromStr;

use crate::sim::ReferenceScales;

/// An end time as given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EndTime {
    /// In convective times c/U.
    Convective(f64),
    /// In seconds (a physical plate's).
    Seconds(f64),
}

impl EndTime {
    /// Whether the number given is finite.
    pub fn is_finite(self) -> bool {
        match self {
            EndTime::Convective(v) | EndTime::Seconds(v) => v.is_finite(),
        }
    }

    /// The end time in c/U; `None` for seconds when the plate has no physical scales.
    pub fn convective(self, scales: Option<ReferenceScales>) -> Option<f64> {
        match (self, scales) {
            (EndTime::Convective(t), _) => Some(t),
            (EndTime::Seconds(s), Some(k)) => Some(s * k.speed_m_s / k.chord_m),
            (EndTime::Seconds(_), None) => None,
        }
    }
}

impl FromStr for EndTime {
    type Err = String;

    fn from_str(text: &str) -> Result<EndTime, String> {
        let text = text.trim();
        let (number, seconds) = match text.strip_suffix('s') {
            Some(n) => (n.trim_end(), true),
            None => (text, false),
        };
        let value: f64 = number.parse().map_err(|_| {
            format!("{text}: accepted a number of convective times c/U (60) or of seconds (10.5s)")
        })?;
        Ok(if seconds {
            EndTime::Seconds(value)
        } else {
            EndTime::Convective(value)
        })
    }
}

impl fmt::Display for EndTime {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EndTime::Convective(t) => write!(f, "{t}"),
            EndTime::Seconds(s) => write!(f, "{s}s"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn end_times_read_as_given_and_seconds_convert_with_the_plates_scales() {
        assert_eq!("60".parse(), Ok(EndTime::Convective(60.0)));
        assert_eq!("10.5s".parse(), Ok(EndTime::Seconds(10.5)));
        assert_eq!(" 2 s".parse(), Ok(EndTime::Seconds(2.0)));
        assert!("10m".parse::<EndTime>().is_err() && "s".parse::<EndTime>().is_err());
        // A chord of 16 mm at U = 9.14 cm/s: c/U = 0.175 s, so 10.5 s is 60 c/U.
        let k = ReferenceScales {
            chord_m: 0.016,
            speed_m_s: 0.016 / 0.175,
        };
        let t = EndTime::Seconds(10.5).convective(Some(k)).unwrap();
        assert!((t - 60.0).abs() < 1e-12, "{t}");
        assert_eq!(EndTime::Convective(60.0).convective(None), Some(60.0));
        assert_eq!(EndTime::Seconds(1.0).convective(None), None);
        assert_eq!(EndTime::Seconds(10.5).to_string(), "10.5s");
    }
}
