//! Checks across the values of a run description that are each in range alone but cannot work
//! together (docs/physics.md §1, §6): a run must outlast the plate's development (pinned, free) or spin-up
//! (forced), or it ends before the case begins.
use super::motion::Case;
use crate::param::{InputError, Param};

/// Refuses a development or spin-up that lasts the whole run (ending at `t_end`).
///
/// # Errors
/// [`InputError::Inconsistent`] when the development (pinned, free) or the spin-up (forced) lasts
/// until `t_end` or beyond.
pub fn check_phases(case: &Case, t_end: f64) -> Result<(), InputError> {
    let (param, value, what) = match *case {
        Case::Pinned { develop, .. } | Case::Free { develop, .. } => (
            Param::Develop,
            develop,
            "the plate would be held until then and never released",
        ),
        Case::Forced { spinup, .. } => (
            Param::Spinup,
            spinup,
            "the spin-up would take the whole run",
        ),
        Case::Static { .. } => return Ok(()),
    };
    if value < t_end {
        return Ok(());
    }
    Err(InputError::Inconsistent {
        param,
        value,
        why: format!(
            "the run ends at t_end = {t_end}, so {what}; accepted: less than t_end (--t-end)"
        ),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn phases_longer_than_the_run_are_refused() {
        let case = Case::Forced {
            omega: 1.0,
            spinup: 3.0,
        };
        let e = check_phases(&case, 2.0).unwrap_err();
        assert_eq!(e.param(), Some(Param::Spinup));
        assert!(check_phases(&case, 4.0).is_ok());
    }
}
