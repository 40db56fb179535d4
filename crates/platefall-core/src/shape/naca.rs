//! NACA four-digit sections (Abbott & von Doenhoff, *Theory of Wing Sections*, §6.4): the code
//! MPTT gives the maximum camber m = M/100 at p = P/10 of the chord and the thickness t = TT/100;
//! the half-thickness is
//!
//! ```text
//!     y_t = 5t (0.2969 √x − 0.1260 x − 0.3516 x² + 0.2843 x³ − 0.1036 x⁴)
//! ```
//!
//! (the last coefficient −0.1036 closes the trailing edge, so the outline is a closed polygon),
//! laid off perpendicular to the mean line y_c = m/p² (2px − x²) ahead of p and
//! m/(1 − p)² ((1 − 2p) + 2px − x²) behind it.
use std::fmt;

/// A NACA four-digit code, e.g. 0012 or 2412.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(try_from = "String", into = "String")]
pub struct NacaCode {
    /// Maximum camber in hundredths of the chord (M).
    pub camber: u8,
    /// Its position in tenths of the chord (P).
    pub position: u8,
    /// Maximum thickness in hundredths of the chord (TT).
    pub thickness: u8,
}

/// Why a text is not a NACA four-digit code.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "`{0}` is not a NACA four-digit section: accepted `naca` and four digits MPTT \
     (e.g. naca0012, naca2412) with thickness TT ≥ 01, and camber position P ≥ 1 when M > 0"
)]
pub struct NotNaca(pub String);

impl NacaCode {
    /// Parses "0012", "naca0012" or "NACA 2412".
    ///
    /// # Errors
    /// [`NotNaca`] holding `text` when it is not four digits MPTT (after an optional `naca`), with
    /// TT ≥ 01 and P ≥ 1 when M > 0.
    pub fn parse(text: &str) -> Result<NacaCode, NotNaca> {
        let bad = || NotNaca(text.to_string());
        let t = text.trim();
        let lower = t.to_ascii_lowercase();
        let digits = lower.strip_prefix("naca").unwrap_or(&lower).trim_start();
        if digits.len() != 4 || !digits.bytes().all(|b| b.is_ascii_digit()) {
            return Err(bad());
        }
        let d: Vec<u8> = digits.bytes().map(|b| b - b'0').collect();
        let code = NacaCode {
            camber: d[0],
            position: d[1],
            thickness: 10 * d[2] + d[3],
        };
        let cambered_without_position = code.camber > 0 && code.position == 0;
        if code.thickness == 0 || cambered_without_position {
            return Err(bad());
        }
        Ok(code)
    }

    /// Thickness as a chord fraction.
    pub fn thickness_ratio(&self) -> f64 {
        f64::from(self.thickness) / 100.0
    }

    /// The section's outline with the chord along [0, 1] (leading edge at 0), counter-clockwise
    /// from the trailing edge over the upper surface; `n` points per surface, clustered at both
    /// edges by a cosine spacing.
    pub fn points(&self, n: usize) -> Vec<[f64; 2]> {
        let t = self.thickness_ratio();
        let (m, p) = (
            f64::from(self.camber) / 100.0,
            f64::from(self.position) / 10.0,
        );
        let surface = |x: f64, upper: bool| -> [f64; 2] {
            let yt = 5.0
                * t
                * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x * x + 0.2843 * x.powi(3)
                    - 0.1036 * x.powi(4));
            let (yc, slope) = mean_line(m, p, x);
            let (s, c) = slope.atan().sin_cos();
            let sign = if upper { 1.0 } else { -1.0 };
            [x - sign * yt * s, yc + sign * yt * c]
        };
        let xs: Vec<f64> = (0..=n)
            .map(|k| 0.5 * (1.0 - (std::f64::consts::PI * k as f64 / n as f64).cos()))
            .collect();
        // Upper surface from the trailing edge (x = 1) to the leading edge, then the lower
        // surface back, without repeating either edge point.
        let mut pts: Vec<[f64; 2]> = xs.iter().rev().map(|&x| surface(x, true)).collect();
        pts.extend(xs.iter().skip(1).take(n - 1).map(|&x| surface(x, false)));
        pts
    }
}

/// The mean line's height and slope at x (not from the dissertation: the NACA four-digit definition above).
fn mean_line(m: f64, p: f64, x: f64) -> (f64, f64) {
    if m == 0.0 {
        (0.0, 0.0)
    } else if x < p {
        (
            m / (p * p) * (2.0 * p * x - x * x),
            2.0 * m / (p * p) * (p - x),
        )
    } else {
        let q = (1.0 - p) * (1.0 - p);
        (
            m / q * ((1.0 - 2.0 * p) + 2.0 * p * x - x * x),
            2.0 * m / q * (p - x),
        )
    }
}

impl fmt::Display for NacaCode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "naca{}{}{:02}",
            self.camber, self.position, self.thickness
        )
    }
}

impl TryFrom<String> for NacaCode {
    type Error = NotNaca;
    fn try_from(s: String) -> Result<Self, NotNaca> {
        NacaCode::parse(&s)
    }
}

impl From<NacaCode> for String {
    fn from(c: NacaCode) -> String {
        c.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::Outline;

    #[test]
    fn codes_parse_and_bad_ones_are_refused() {
        let c = NacaCode::parse("naca2412").unwrap();
        assert_eq!((c.camber, c.position, c.thickness), (2, 4, 12));
        assert_eq!(NacaCode::parse("0012").unwrap().to_string(), "naca0012");
        for bad in [
            "naca012",
            "naca00a2",
            "naca0000",
            "naca2012",
            "",
            "naca00123",
        ] {
            assert!(NacaCode::parse(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn naca0012_has_its_maximum_thickness_at_thirty_percent_and_a_closed_trailing_edge() {
        let pts = NacaCode::parse("0012").unwrap().points(2000);
        let o = Outline::new(pts.clone());
        let (lo, hi) = o.bounds();
        assert!((hi[1] - lo[1] - 0.12).abs() < 2e-4, "t = {}", hi[1] - lo[1]);
        let top = pts.iter().max_by(|a, b| a[1].total_cmp(&b[1])).unwrap();
        assert!(
            (top[0] - 0.30).abs() < 0.01,
            "max thickness at x = {}",
            top[0]
        );
        // The closed-edge polynomial vanishes at x = 1 (to the rounding of its coefficients).
        assert!(pts[0][1].abs() < 1e-4);
        // Area of NACA 00tt ≈ 0.685 t c (integral of the thickness polynomial).
        let area_coeff =
            10.0 * (0.2969 * 2.0 / 3.0 - 0.1260 / 2.0 - 0.3516 / 3.0 + 0.2843 / 4.0 - 0.1036 / 5.0);
        assert!(
            (o.area() - area_coeff * 0.12).abs() < 1e-5,
            "area {}",
            o.area()
        );
    }
}
