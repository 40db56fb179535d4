//! The ensemble's statistics from its members' summaries: for every summary key with an
//! interval, the members' means with their own intervals pooled into the ensemble mean and its
//! 95 % interval ([`platefall_post::ensemble::pool`]), and the table of them.
use std::collections::BTreeMap;

use serde::Serialize;
use serde_json::Value;

use platefall_post::ensemble::{pool, EnsembleInterval, MemberEstimate, OwnInterval, Verdict};

/// One quantity of the ensemble: the pooled interval and the members' means.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct Quantity {
    #[serde(flatten)]
    pub(crate) interval: EnsembleInterval,
    /// Each pooled member's mean, in member order.
    pub(crate) member_means: Vec<f64>,
}

/// A member's estimate of `key` from its summary's `intervals` (the value, and its own
/// interval when it states one).
fn estimate(summary: &Value, key: &str) -> Option<MemberEstimate> {
    let i = summary.get("intervals")?.get(key)?;
    let mean = i.get("value")?.as_f64()?;
    let num = |k: &str| i.get(k).and_then(Value::as_f64);
    let own = match (num("half_width"), num("t"), num("dof"), num("n_eff")) {
        (Some(hw), Some(t), Some(dof), Some(n_eff)) if t > 0.0 && dof > 0.0 => Some(OwnInterval {
            std_error: hw / t,
            dof,
            n_eff,
        }),
        _ => None,
    };
    Some(MemberEstimate { mean, own })
}

/// Every key that some member's summary states an interval for, pooled over the members
/// that state it; keys no two members state are left out.
pub(crate) fn pool_keys(summaries: &[Value]) -> BTreeMap<String, Quantity> {
    let mut keys: Vec<String> = summaries
        .iter()
        .filter_map(|s| s.get("intervals").and_then(Value::as_object))
        .flat_map(|o| o.keys().cloned())
        .collect();
    keys.sort();
    keys.dedup();
    keys.into_iter()
        .filter_map(|key| {
            let members: Vec<MemberEstimate> =
                summaries.iter().filter_map(|s| estimate(s, &key)).collect();
            let interval = pool(&members).ok()?;
            let member_means = members.iter().map(|m| m.mean).collect();
            Some((
                key,
                Quantity {
                    interval,
                    member_means,
                },
            ))
        })
        .collect()
}

/// The half-width as a percentage of the mean's size; None for a mean of zero.
pub(crate) fn relative_percent(e: &EnsembleInterval) -> Option<f64> {
    (e.mean != 0.0).then(|| 100.0 * e.half_width / e.mean.abs())
}

/// A value with its half-width to two significant digits of the half-width.
pub(crate) fn shown(value: f64, hw: f64) -> String {
    if !(hw.is_finite() && hw > 0.0) {
        return format!("{value:.4} ± {hw:.2}");
    }
    let digits = (1 - hw.log10().floor() as i32).max(0) as usize;
    format!("{value:.digits$} ± {hw:.digits$}")
}

/// The Markdown table: per key the ensemble mean ± its half-width, relative, the combined
/// interval, the spread, Σ n_eff and the independence verdict.
pub(crate) fn table(quantities: &BTreeMap<String, Quantity>) -> String {
    let mut out = String::from(
        "| key | ensemble mean ± 95 % | relative | combined ± 95 % | members | spread | Σ n_eff | members' spread vs own intervals |\n|---|---|---|---|---|---|---|---|\n",
    );
    for (key, q) in quantities {
        let e = &q.interval;
        let rel = relative_percent(e).map_or("-".into(), |r| format!("{r:.2} %"));
        let combined = e
            .combined
            .map_or("-".into(), |c| shown(e.mean, c.half_width));
        let verdict = e.consistency.map_or("-".into(), |c| {
            let what = match c.verdict {
                Verdict::Consistent => "consistent",
                Verdict::TooAlike => "too alike: not independent",
                Verdict::TooSpread => "too spread: own intervals too narrow",
            };
            format!("{what} (F = {:.2}, P = {:.3})", c.ratio, c.p_lower)
        });
        let n_eff = e.n_eff.map_or("-".into(), |n| format!("{n:.0}"));
        out.push_str(&format!(
            "| {key} | {} | {rel} | {combined} | {} | {:.3e} | {n_eff} | {verdict} |\n",
            shown(e.mean, e.half_width),
            e.members,
            e.spread
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn members_own_intervals_are_read_from_their_summaries() {
        let s = |v: f64| {
            serde_json::json!({"intervals": {
                "mean_omega": {"value": v, "half_width": 0.2, "t": 2.0, "dof": 9.0, "n_eff": 10.0},
                "period": {"value": v, "half_width": null}
            }})
        };
        let q = pool_keys(&[s(1.0), s(2.0), s(3.0)]);
        let w = &q["mean_omega"].interval;
        assert_eq!(q["mean_omega"].member_means, [1.0, 2.0, 3.0]);
        // m̄ = 2, s = 1, se = 1/√3; own se 0.1 each: √(3 · 0.01)/3; Σ n_eff = 30.
        assert!((w.mean - 2.0).abs() < 1e-15 && (w.std_error - 3f64.sqrt().recip()).abs() < 1e-15);
        assert!((w.within_std_error.unwrap() - 0.03f64.sqrt() / 3.0).abs() < 1e-15);
        assert_eq!(w.n_eff, Some(30.0));
        assert!(q["period"].interval.within_std_error.is_none());
        assert!(
            table(&q).contains("| mean_omega | 2.0 ± 2.5 |"),
            "{}",
            table(&q)
        );
    }
}
