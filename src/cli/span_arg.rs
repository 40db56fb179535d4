//! `--span`: the plate's span for the three-dimensional flow, `B` (a finite span of B chords
//! with free tips) or `periodic:P` (an infinite span, periodic over P chords).
use platefall_core::flow3d::Span;

/// Why a `--span` value was rejected.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum SpanArgError {
    /// Not a number, or `periodic:` without one.
    #[error("`{0}` is not a span: give B (a finite span, chords) or periodic:P (period, chords)")]
    Syntax(String),
    /// Zero, negative or not finite.
    #[error("span {0} is out of range: accepted a finite number of chords > 0")]
    NotPositive(f64),
}

/// Parses a `--span` value.
///
/// # Errors
/// [`SpanArgError`] when the text is neither a number nor `periodic:` and a number, or the
/// number is not positive and finite.
pub fn parse_span(s: &str) -> Result<Span, SpanArgError> {
    let (periodic, number) = match s.trim().strip_prefix("periodic:") {
        Some(rest) => (true, rest),
        None => (false, s.trim()),
    };
    let b: f64 = number
        .trim()
        .parse()
        .map_err(|_| SpanArgError::Syntax(s.to_string()))?;
    if !(b > 0.0 && b.is_finite()) {
        return Err(SpanArgError::NotPositive(b));
    }
    Ok(if periodic {
        Span::Periodic(b)
    } else {
        Span::Finite(b)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finite_and_periodic_spans_parse_and_bad_ones_are_named() {
        assert_eq!(parse_span("2.67"), Ok(Span::Finite(2.67)));
        assert_eq!(parse_span("periodic:1"), Ok(Span::Periodic(1.0)));
        assert_eq!(parse_span("0"), Err(SpanArgError::NotPositive(0.0)));
        assert_eq!(
            parse_span("periodic:-2"),
            Err(SpanArgError::NotPositive(-2.0))
        );
        assert!(matches!(
            parse_span("inf"),
            Err(SpanArgError::NotPositive(_))
        ));
        assert!(matches!(parse_span("wide"), Err(SpanArgError::Syntax(_))));
        assert!(matches!(
            parse_span("periodic:"),
            Err(SpanArgError::Syntax(_))
        ));
    }
}
