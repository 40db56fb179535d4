//! From the levels' summaries to the study: each level's spacing h, and per quantity (every mean
//! of the summary that states a 95 % interval, `<key>_ci95`) the analysis of its triples.
use serde::Serialize;
use serde_json::Value as Json;

use super::study::Refined;
use crate::sweep::json::{get, parse_object, Object};
use crate::sweep::layout::Layout;
use crate::sweep::plan::CaseSpec;
use crate::sweep::results::outcome;
use platefall_post::convergence::{study, Level, Triple, SAFETY_FACTOR};
use platefall_post::phase::CaseState;

/// One level of the study.
#[derive(Clone, Debug, Serialize)]
pub(crate) struct LevelInfo {
    pub(crate) id: String,
    /// The refined option's value (as given).
    pub(crate) value: f64,
    /// The representative spacing (see the study's `spacing`).
    pub(crate) h: Option<f64>,
    /// completed, diverged, failed, interrupted, unfinished or missing.
    pub(crate) status: String,
    pub(crate) summary: String,
    pub(crate) cells: Option<u64>,
    pub(crate) steps: Option<u64>,
    pub(crate) t_end: Option<f64>,
    /// t_end / steps.
    pub(crate) mean_dt: Option<f64>,
    /// The batches of its intervals (whole turns, periods …).
    pub(crate) ci_batches: Option<u64>,
}

/// One quantity over the levels.
#[derive(Clone, Debug, Serialize)]
pub(crate) struct QuantityStudy {
    pub(crate) key: String,
    /// Per completed level, coarsest first: its value and 95 % half-width.
    pub(crate) values: Vec<f64>,
    pub(crate) half_widths: Vec<Option<f64>>,
    /// The triples of consecutive levels, the finest first; `triples[0]` is the headline.
    pub(crate) triples: Vec<Triple>,
    /// The levels (their refined values) whose batch means of this quantity drift significantly
    /// over the window: a transient is left in their means.
    pub(crate) drifting: Vec<f64>,
    /// The levels whose batch means of this quantity alternate (lag-1 autocorrelation below
    /// −0.5): a period of two batches, and a wide interval.
    pub(crate) alternating: Vec<f64>,
}

/// The study as written to `convergence.json`.
#[derive(Clone, Debug, Serialize)]
pub(crate) struct Study {
    pub(crate) refined: String,
    pub(crate) spacing: String,
    /// The case's options (the first level's, without the refined option and the outputs).
    pub(crate) case: Vec<String>,
    pub(crate) safety_factor: f64,
    /// Every level of the plan, coarsest first.
    pub(crate) levels: Vec<LevelInfo>,
    /// Completed levels used (fewer than three: no triples).
    pub(crate) completed: usize,
    pub(crate) quantities: Vec<QuantityStudy>,
    pub(crate) notes: Vec<String>,
}

pub(crate) fn num(o: &Object, key: &str) -> Option<f64> {
    get(o, key).and_then(Json::as_f64)
}

/// The refined option's value of a case.
fn refined_value(case: &CaseSpec) -> f64 {
    case.params
        .first()
        .and_then(|(_, v)| v.as_f64())
        .unwrap_or(f64::NAN)
}

/// The spacing h of a level from its refined value and its summary.
pub(crate) fn spacing(refined: &Refined, value: f64, summary: &Object) -> Option<f64> {
    match refined {
        Refined::Resolution => Some(1.0 / value),
        Refined::Extent => Some(1.0 / value),
        Refined::TimeStep(_) => {
            let (t, n) = (num(summary, "t_end")?, num(summary, "steps")?);
            (n > 0.0).then(|| t / n)
        }
    }
}

/// The quantities of a study: the keys with a `<key>_ci95` partner, in the summary's order.
fn quantity_keys(summary: &Object) -> Vec<String> {
    summary
        .iter()
        .filter_map(|(k, _)| {
            let base = k.strip_suffix("_ci95")?;
            get(summary, base).is_some().then(|| base.to_string())
        })
        .collect()
}

/// The study of the levels `cases` in `layout`.
pub(crate) fn analyse(layout: &Layout, cases: &[CaseSpec], refined: &Refined) -> Study {
    let levels: Vec<(LevelInfo, Option<Object>)> = cases
        .iter()
        .map(|c| {
            let summary = std::fs::read_to_string(layout.summary(&c.id))
                .ok()
                .and_then(|t| parse_object(&t).ok());
            let status = outcome(
                layout,
                &c.id,
                crate::sweep::child::read_status(layout, &c.id).as_ref(),
            );
            let value = refined_value(c);
            let s = summary.clone().unwrap_or_default();
            let (t, n) = (num(&s, "t_end"), num(&s, "steps"));
            let info = LevelInfo {
                id: c.id.clone(),
                value,
                h: summary.as_ref().and_then(|s| spacing(refined, value, s)),
                status: status.to_string(),
                summary: layout
                    .summary(&c.id)
                    .strip_prefix(&layout.dir)
                    .map(|p| p.to_string_lossy().into_owned())
                    .unwrap_or_default(),
                cells: num(&s, "cells").map(|x| x as u64),
                steps: n.map(|x| x as u64),
                t_end: t,
                mean_dt: t.zip(n).filter(|(_, n)| *n > 0.0).map(|(t, n)| t / n),
                ci_batches: num(&s, "ci_batches").map(|x| x as u64),
            };
            let usable = (status == CaseState::Completed)
                .then_some(summary)
                .flatten();
            (info, usable)
        })
        .collect();
    let case = cases
        .first()
        .map(|c| {
            c.args
                .iter()
                .filter(|a| !a.starts_with(&format!("--{}=", refined.name())))
                .cloned()
                .collect()
        })
        .unwrap_or_default();
    analyse_levels(levels, refined, case)
}

/// The study of `levels` (each with its summary, or None when it is not usable), of the case
/// `case` (its command line after `platefall`).
pub(crate) fn analyse_levels(
    mut levels: Vec<(LevelInfo, Option<Object>)>,
    refined: &Refined,
    case: Vec<String>,
) -> Study {
    // Coarsest first: the largest h (levels without one at the end).
    levels.sort_by(|a, b| {
        let key = |l: &LevelInfo| l.h.unwrap_or(f64::NEG_INFINITY);
        key(&b.0).total_cmp(&key(&a.0))
    });
    let done: Vec<(&LevelInfo, &Object)> = levels
        .iter()
        .filter_map(|(i, s)| Some((i, s.as_ref()?)).filter(|(i, _)| i.h.is_some()))
        .collect();
    let mut notes = Vec::new();
    let not_done: Vec<String> = levels
        .iter()
        .filter(|(i, s)| s.is_none() || i.h.is_none())
        .map(|(i, _)| format!("{} ({})", i.id, i.status))
        .collect();
    if !not_done.is_empty() {
        notes.push(format!(
            "levels left out (not completed): {}",
            not_done.join(", ")
        ));
    }
    if done.len() < 3 {
        notes.push(format!(
            "{} completed level(s): an order needs three",
            done.len()
        ));
    }
    let keys = done
        .first()
        .map(|(_, s)| quantity_keys(s))
        .unwrap_or_default();
    let mut quantities = Vec::new();
    for key in keys {
        let pts: Vec<(f64, f64, Option<f64>)> = done
            .iter()
            .filter_map(|(i, s)| {
                let v = num(s, &key)?;
                Some((i.h?, v, num(s, &format!("{key}_ci95"))))
            })
            .collect();
        if pts.len() != done.len() {
            continue; // a level without the value (e.g. no turns): not comparable
        }
        let lv: Vec<Level> = pts
            .iter()
            .map(|&(h, value, half_width)| Level {
                h,
                value,
                half_width,
            })
            .collect();
        let detail = |s: &Object, field: &str| -> Option<Json> {
            get(s, "intervals")?.get(&key)?.get(field).cloned()
        };
        let drifting = done
            .iter()
            .filter(|(_, s)| detail(s, "drift_significant").and_then(|v| v.as_bool()) == Some(true))
            .map(|(i, _)| i.value)
            .collect();
        let alternating = done
            .iter()
            .filter(|(_, s)| {
                detail(s, "lag1")
                    .and_then(|v| v.as_f64())
                    .is_some_and(|r| r < platefall_post::intervals::ALTERNATING)
            })
            .map(|(i, _)| i.value)
            .collect();
        quantities.push(QuantityStudy {
            drifting,
            alternating,
            key,
            values: pts.iter().map(|p| p.1).collect(),
            half_widths: pts.iter().map(|p| p.2).collect(),
            triples: study(&lv),
        });
    }
    if let (Refined::TimeStep(name), true) = (refined, done.len() >= 2) {
        let dts: Vec<String> = done
            .iter()
            .filter_map(|(i, _)| i.mean_dt.map(|d| format!("{d:.3e}")))
            .collect();
        notes.push(format!(
            "--{name} refines only its own limit of the time step; the mean steps realised were \
             {} (h is the mean step)",
            dts.join(", ")
        ));
    }
    Study {
        refined: refined.name().to_string(),
        spacing: refined.spacing().to_string(),
        case,
        safety_factor: SAFETY_FACTOR,
        completed: done.len(),
        levels: levels.into_iter().map(|(i, _)| i).collect(),
        quantities,
        notes,
    }
}
