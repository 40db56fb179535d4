//! A study whose levels are ensembles (`--ensembles DIR1,DIR2,DIR3`): at each level every
//! quantity is the ensemble's pooled mean and its 95 % half-width the pooled one, from the
//! members' independent means (`DIR/ensemble.json`, docs/statistics.md "Ensembles of independent
//! members"), so the noise that decides which differences are resolved shrinks with the members.
use std::path::{Path, PathBuf};

use serde_json::Value as Json;

use super::analysis::{num, spacing, LevelInfo};
use super::study::Refined;
use crate::sweep::failure::Failure;
use crate::sweep::json::{parse_object, Object};
use crate::sweep::layout::Layout;

/// One ensemble directory read as a level of the study.
fn level(refined: &Refined, value: f64, dir: &Path) -> (LevelInfo, Option<Object>) {
    let layout = Layout::new(dir);
    let pooled: Option<Json> = std::fs::read_to_string(layout.output("ensemble.json"))
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok());
    let count = |p: &Json, key: &str| p.get(key).and_then(Json::as_array).map(Vec::len);
    let (status, members) = match &pooled {
        None => ("missing", None),
        Some(p) => match (count(p, "completed"), count(p, "members")) {
            (Some(done), Some(all)) if done == all && done >= 2 => ("completed", Some(done)),
            (done, _) => ("unfinished", done),
        },
    };
    // The first pooled member's summary: the grid and the steps (its run from the start).
    let member: Object = pooled
        .as_ref()
        .and_then(|p| {
            p.get("completed")?
                .as_array()?
                .first()?
                .as_str()
                .map(String::from)
        })
        .and_then(|id| std::fs::read_to_string(layout.summary(&id)).ok())
        .and_then(|t| parse_object(&t).ok())
        .unwrap_or_default();
    let mut summary: Object = ["cells", "steps", "t_end"]
        .iter()
        .filter_map(|k| Some((k.to_string(), Json::from(num(&member, k)?))))
        .collect();
    let quantities = pooled
        .as_ref()
        .and_then(|p| p.get("quantities")?.as_object());
    for (key, q) in quantities.into_iter().flatten() {
        if let (Some(mean), Some(hw)) = (q.get("mean"), q.get("half_width")) {
            summary.push((key.clone(), mean.clone()));
            summary.push((format!("{key}_ci95"), hw.clone()));
        }
    }
    let (t, n) = (num(&summary, "t_end"), num(&summary, "steps"));
    let info = LevelInfo {
        id: dir.to_string_lossy().into_owned(),
        value,
        h: spacing(refined, value, &summary),
        status: status.to_string(),
        summary: layout
            .output("ensemble.json")
            .to_string_lossy()
            .into_owned(),
        cells: num(&summary, "cells").map(|x| x as u64),
        steps: n.map(|x| x as u64),
        t_end: t,
        mean_dt: t.zip(n).filter(|(_, n)| *n > 0.0).map(|(t, n)| t / n),
        ci_batches: members.map(|m| m as u64),
    };
    (info, (status == "completed").then_some(summary))
}

/// The levels of a study of ensembles: `dirs[k]` at the refined value `values[k]`.
pub(crate) fn ensemble_levels(
    refined: &Refined,
    values: &[String],
    dirs: &[PathBuf],
) -> Result<Vec<(LevelInfo, Option<Object>)>, Failure> {
    if dirs.len() != values.len() {
        return Err(Failure::input(format!(
            "--ensembles: {} director{} for {} levels of --refine: accepted one ensemble \
             directory per level, in the order of the values",
            dirs.len(),
            if dirs.len() == 1 { "y" } else { "ies" },
            values.len()
        )));
    }
    if let Some(d) = dirs.iter().find(|d| !d.join("ensemble.json").is_file()) {
        return Err(Failure::input(format!(
            "--ensembles: {} holds no ensemble.json: accepted directories `platefall ensemble` \
             has pooled",
            d.display()
        )));
    }
    Ok(values
        .iter()
        .zip(dirs)
        .map(|(v, d)| level(refined, v.parse().unwrap_or(f64::NAN), d))
        .collect())
}
