//! Ensembles (docs/statistics.md, "Ensembles of independent members"): the mean of a quantity over M independent members (runs branched from one
//! spun-up state, each perturbed a little) and its 95 % confidence interval. Pure functions on
//! numbers; the command that runs the members is the binary's.
//!
//! - **Pooling** ([`mod@pool`]): the members' means m_i are M independent observations of the same
//!   mean, so the ensemble mean is their plain average m̄ and its interval is Student's
//!   t(0.975; M − 1) · s/√M with s the between-member standard deviation: this holds whatever
//!   each member's own correlation structure, as long as the members are independent. When the
//!   members carry their own intervals (batch means over their turns, [`crate::stats`]), their
//!   standard errors predict the same variance, V_w = Σ se_i²/M², with Satterthwaite's degrees of
//!   freedom; the two estimates are compared by an F test ([`Consistency`]) and, when they
//!   agree, pooled by their degrees of freedom into a narrower *combined* interval.
//! - **Independence** ([`independence`]): members that agree far more closely than their own
//!   intervals allow are not independent (the F test's lower tail: started without a
//!   perturbation, or averaged before they parted); the decorrelation time of the members, from
//!   their separation, says from when on their windows may be averaged.
//! - **Separation** ([`mod@separation`]): whether two ensembles' means differ by more than their
//!   noise (Welch's t).
//! - **Planning** ([`plan`]): the members, or a single run's length, needed for a requested
//!   half-width, from a pilot's measured spread or interval.
//! - **Distribution** ([`histogram`]): the members' means binned by Sturges' rule.
pub mod histogram;
pub mod independence;
pub mod plan;
pub mod pool;
pub mod separation;
pub mod trace;

pub use histogram::Histogram;
pub use independence::{decorrelation, Decorrelation};
pub use plan::{members_for, single_run_length, MemberPlan};
pub use pool::{
    f_cdf, pool, Combined, Consistency, EnsembleInterval, MemberEstimate, NoEnsembleInterval,
    OwnInterval, Verdict, MIN_MEMBERS,
};
pub use separation::{separation, Separation};
pub use trace::MemberTrace;

#[cfg(test)]
mod tests;
