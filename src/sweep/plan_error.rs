//! Why a plan cannot run, below every part of the sweep that checks one.

/// A plan that cannot run: one line naming the value and what is accepted (exit 2).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct PlanError(pub(crate) String);

/// A [`PlanError`] from a format string.
macro_rules! plan_err {
    ($($t:tt)*) => {
        PlanError(format!($($t)*))
    };
}
pub(crate) use plan_err;
