//! Pooling the members' means into the ensemble mean with its 95 % interval, and the F test
//! of their spread against their own intervals (docs/statistics.md, "Ensembles of independent
//! members").
use serde::Serialize;

use crate::stats::{regularized_beta, t95, Interval, LEVEL};

/// Fewest members that give an ensemble interval.
pub const MIN_MEMBERS: usize = 2;

/// One member's estimate of a quantity: its mean and, when its own run gave one, its own
/// interval (the standard error of its mean with the degrees of freedom and the effective number
/// of independent observations behind it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MemberEstimate {
    /// The member's (time) mean.
    pub mean: f64,
    /// The member's own interval, if any.
    pub own: Option<OwnInterval>,
}

/// The part of a member's own interval that pooling uses.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct OwnInterval {
    /// Standard error of the member's mean (its half-width over its t quantile).
    pub std_error: f64,
    /// Degrees of freedom of that standard error.
    pub dof: f64,
    /// Effective number of independent observations behind it.
    pub n_eff: f64,
}

impl From<&Interval> for OwnInterval {
    fn from(i: &Interval) -> Self {
        OwnInterval {
            std_error: i.std_error,
            dof: i.dof,
            n_eff: i.n_eff,
        }
    }
}

/// The verdict of the F test of the between-member variance against the members' own.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// The spread of the members' means is what their own intervals predict.
    Consistent,
    /// The members agree far more closely than their own intervals allow (lower 2.5 % tail):
    /// they are not independent (no perturbation, or averaged before they parted).
    TooAlike,
    /// The members differ far more than their own intervals allow (upper 2.5 % tail): their own
    /// intervals are too narrow (a transient left in the window, correlated batches).
    TooSpread,
}

/// The F test of V_b (between members, M − 1 degrees of freedom) against V_w (from the
/// members' own standard errors, Satterthwaite's degrees of freedom).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Consistency {
    /// V_b / V_w.
    pub ratio: f64,
    /// P(F ≤ ratio) for F(M − 1, ν_w): near 0 the members are too alike, near 1 too spread.
    pub p_lower: f64,
    /// What the test says, at the two-sided 95 % level.
    pub verdict: Verdict,
}

/// The combined interval: V_b and V_w pooled by their degrees of freedom.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Combined {
    /// Half-width of the 95 % interval.
    pub half_width: f64,
    /// Its standard error.
    pub std_error: f64,
    /// Degrees of freedom, ν_b + ν_w.
    pub dof: f64,
}

/// An ensemble mean with its 95 % interval and what lies behind it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct EnsembleInterval {
    /// The average of the members' means.
    pub mean: f64,
    /// Half-width of the 95 % interval from the between-member spread.
    pub half_width: f64,
    /// Standard error of the mean, s/√M.
    pub std_error: f64,
    /// Members behind it.
    pub members: usize,
    /// Between-member standard deviation s of the members' means.
    pub spread: f64,
    /// Degrees of freedom, M − 1, and the t quantile.
    pub dof: f64,
    /// See `dof`.
    pub t: f64,
    /// Σ of the members' effective numbers of independent observations (when all have one).
    pub n_eff: Option<f64>,
    /// The standard error the members' own intervals predict, √(Σ se_i²)/M.
    pub within_std_error: Option<f64>,
    /// Its Satterthwaite degrees of freedom, (Σ se_i²)² / Σ (se_i⁴/ν_i).
    pub within_dof: Option<f64>,
    /// The F test of the two estimates.
    pub consistency: Option<Consistency>,
    /// The pooled interval, when the test finds them consistent.
    pub combined: Option<Combined>,
}

/// Why an ensemble gives no interval.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum NoEnsembleInterval {
    /// Fewer than [`MIN_MEMBERS`] members.
    #[error("{have} members, {MIN_MEMBERS} needed")]
    TooFewMembers {
        /// Members given.
        have: usize,
    },
    /// A mean or a standard error is not finite.
    #[error("a member's value is not finite")]
    NotFinite,
}

/// P(F ≤ x) for Fisher's F with (d1, d2) degrees of freedom: I_{d1 x/(d1 x + d2)}(d1/2, d2/2).
pub fn f_cdf(x: f64, d1: f64, d2: f64) -> f64 {
    if x <= 0.0 {
        return 0.0;
    }
    regularized_beta(0.5 * d1, 0.5 * d2, d1 * x / (d1 * x + d2))
}

/// Degrees of freedom above which a variance estimate counts as exact in the F test.
const DOF_CAP: f64 = 1e6;

/// The within-member estimate: √(Σ se_i²)/M, Satterthwaite's ν, Σ n_eff; None unless every
/// member has its own interval.
fn within(members: &[MemberEstimate]) -> Option<(f64, f64, f64)> {
    let own: Vec<OwnInterval> = members.iter().map(|m| m.own).collect::<Option<_>>()?;
    let m = own.len() as f64;
    let sum: f64 = own.iter().map(|o| o.std_error.powi(2)).sum();
    let denom: f64 = own
        .iter()
        .map(|o| o.std_error.powi(4) / o.dof.max(1e-12))
        .sum();
    let dof = if denom > 0.0 {
        (sum * sum / denom).min(DOF_CAP)
    } else {
        DOF_CAP
    };
    Some((sum.sqrt() / m, dof, own.iter().map(|o| o.n_eff).sum()))
}

/// The F test of V_b = s²/M (ν_b = M − 1) against V_w (ν_w); None when V_w is zero.
fn consistency(vb: f64, nu_b: f64, vw: f64, nu_w: f64) -> Option<Consistency> {
    if vw <= 0.0 {
        return None;
    }
    let ratio = vb / vw;
    let p_lower = f_cdf(ratio, nu_b, nu_w);
    let tail = 0.5 * (1.0 - LEVEL);
    let verdict = if p_lower < tail {
        Verdict::TooAlike
    } else if p_lower > 1.0 - tail {
        Verdict::TooSpread
    } else {
        Verdict::Consistent
    };
    Some(Consistency {
        ratio,
        p_lower,
        verdict,
    })
}

/// The ensemble mean of the members' estimates with its interval: see the module docs.
pub fn pool(members: &[MemberEstimate]) -> Result<EnsembleInterval, NoEnsembleInterval> {
    let n = members.len();
    if n < MIN_MEMBERS {
        return Err(NoEnsembleInterval::TooFewMembers { have: n });
    }
    let finite = |m: &MemberEstimate| {
        m.mean.is_finite()
            && m.own
                .is_none_or(|o| o.std_error.is_finite() && o.dof.is_finite() && o.dof > 0.0)
    };
    if !members.iter().all(finite) {
        return Err(NoEnsembleInterval::NotFinite);
    }
    let m = n as f64;
    let mean = members.iter().map(|e| e.mean).sum::<f64>() / m;
    let var = members.iter().map(|e| (e.mean - mean).powi(2)).sum::<f64>() / (m - 1.0);
    let (spread, std_error, dof) = (var.sqrt(), (var / m).sqrt(), m - 1.0);
    let t = t95(dof);
    let w = within(members);
    let test = w.and_then(|(se_w, nu_w, _)| consistency(var / m, dof, se_w * se_w, nu_w));
    let combined = match (w, test) {
        (Some((se_w, nu_w, _)), Some(c)) if c.verdict == Verdict::Consistent => {
            let nu = dof + nu_w;
            let v = (dof * var / m + nu_w * se_w * se_w) / nu;
            Some(Combined {
                half_width: t95(nu) * v.sqrt(),
                std_error: v.sqrt(),
                dof: nu,
            })
        }
        _ => None,
    };
    Ok(EnsembleInterval {
        mean,
        half_width: t * std_error,
        std_error,
        members: n,
        spread,
        dof,
        t,
        n_eff: w.map(|(_, _, n_eff)| n_eff),
        within_std_error: w.map(|(se, _, _)| se),
        within_dof: w.map(|(_, nu, _)| nu),
        consistency: test,
        combined,
    })
}
