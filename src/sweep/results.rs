//! The merged results: one row per case (its parameters, how it ended, and every key of its
//! summary), written as `results.csv` and `results.json`, and the list of cases that did not
//! complete, with why.
use std::path::PathBuf;

use serde::ser::{Serialize, SerializeMap, Serializer};
use serde_json::Value as Json;

use super::child::{read_status, summary_status, CaseStatus};
use super::failure::{write_output, Failure};
use super::json::{self, Object};
use super::layout::Layout;
use super::plan::CaseSpec;
use platefall_core::sim::StatusKind;
use platefall_post::phase::CaseState;

/// One case in the merged table.
#[derive(Clone, Debug)]
pub(crate) struct Row {
    pub(crate) case: CaseSpec,
    /// How the case stands.
    pub(crate) status: CaseState,
    pub(crate) exit_code: Option<i32>,
    pub(crate) message: String,
    /// The case's recording, if it has one.
    pub(crate) recording: Option<PathBuf>,
    /// The case's summary (empty if it has none).
    pub(crate) summary: Object,
}

/// A case's sweep status from its summary and its `status.json`.
pub(crate) fn outcome(layout: &Layout, id: &str, status: Option<&CaseStatus>) -> CaseState {
    let summary = summary_status(layout, id);
    match (summary, status) {
        (Some(StatusKind::Completed), _) => CaseState::Completed,
        (Some(StatusKind::Diverged), _) => CaseState::Diverged,
        // Exit 130 after Ctrl-C (75 with its checkpoint), or killed by SIGINT before its handler
        // was installed.
        (_, Some(s))
            if s.state == "exited"
                && (matches!(s.exit_code, Some(130 | 75)) || s.signal == Some(2)) =>
        {
            CaseState::Interrupted
        }
        (_, Some(s)) if s.state == "exited" => CaseState::Failed,
        (Some(StatusKind::Interrupted), _) => CaseState::Interrupted,
        (_, Some(_)) => CaseState::Unfinished,
        (_, None) => CaseState::Missing,
    }
}

/// Why a case has no result, in one line.
fn explain(state: CaseState, status: Option<&CaseStatus>) -> String {
    match (state, status) {
        (CaseState::Missing, _) => "not run yet".into(),
        (CaseState::Unfinished, Some(s)) => format!(
            "attempt {} started {} on {} (pid {}) and left no result: still running, or killed (e.g. a time limit)",
            s.attempt, s.started, s.host, s.pid
        ),
        (_, Some(s)) if !s.message.is_empty() => s.message.clone(),
        (CaseState::Diverged, _) => "the solution diverged".into(),
        _ => String::new(),
    }
}

/// The row of one case.
pub(crate) fn row(layout: &Layout, case: &CaseSpec) -> Row {
    let status = read_status(layout, &case.id);
    let state = outcome(layout, &case.id, status.as_ref());
    let summary = std::fs::read_to_string(layout.summary(&case.id))
        .ok()
        .and_then(|t| json::parse_object(&t).ok())
        .unwrap_or_default();
    let recording = Some(layout.recording(&case.id)).filter(|p| p.is_file());
    Row {
        case: case.clone(),
        status: state,
        exit_code: status.as_ref().and_then(|s| s.exit_code),
        message: explain(state, status.as_ref()),
        recording,
        summary,
    }
}

/// Every case's row, in case order.
pub(crate) fn gather(layout: &Layout, cases: &[CaseSpec]) -> Vec<Row> {
    cases.iter().map(|c| row(layout, c)).collect()
}

/// The summary keys of all rows in first-seen order (the summary's own `status` is the row's).
/// Nested values (the per-key details of the intervals, `intervals`) stay in each case's
/// summary: a table holds scalars, such as the half-widths `<key>_ci95`.
fn summary_keys(rows: &[Row]) -> Vec<String> {
    let mut keys: Vec<String> = Vec::new();
    for r in rows {
        for (k, v) in &r.summary {
            let nested = matches!(v, Json::Object(_) | Json::Array(_));
            if k != "status" && !nested && !keys.contains(k) {
                keys.push(k.clone());
            }
        }
    }
    keys
}

/// A row as ordered (column, value) pairs.
fn record(layout: &Layout, r: &Row, keys: &[String]) -> Object {
    let mut out: Object = vec![
        ("index".into(), Json::from(r.case.index)),
        ("id".into(), Json::from(r.case.id.clone())),
    ];
    for (name, v) in &r.case.params {
        out.push((name.clone(), serde_json::to_value(v).unwrap_or(Json::Null)));
    }
    let rec = r.recording.as_ref().map(|p| {
        p.strip_prefix(&layout.dir)
            .unwrap_or(p)
            .to_string_lossy()
            .into_owned()
    });
    out.push(("status".into(), Json::from(r.status.name())));
    out.push((
        "exit_code".into(),
        r.exit_code.map_or(Json::Null, Json::from),
    ));
    out.push(("message".into(), Json::from(r.message.clone())));
    out.push(("recording".into(), rec.map_or(Json::Null, Json::from)));
    for k in keys {
        let v = json::get(&r.summary, k).cloned().unwrap_or(Json::Null);
        out.push((column_name(k, &r.case), v));
    }
    out
}

/// A summary key as a column: `summary_<key>` when a swept option has the same name (`re`).
fn column_name(key: &str, case: &CaseSpec) -> String {
    if case.params.iter().any(|(n, _)| n == key) {
        format!("summary_{key}")
    } else {
        key.to_string()
    }
}

/// Serialises ordered pairs as a JSON object.
struct Ordered<'a>(&'a Object);

impl Serialize for Ordered<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in self.0 {
            map.serialize_entry(k, v)?;
        }
        map.end()
    }
}

/// A CSV field: numbers as they are, null empty, text quoted when it needs to be.
fn csv_field(v: &Json) -> String {
    let text = match v {
        Json::Null => return String::new(),
        Json::String(s) => s.clone(),
        other => other.to_string(),
    };
    if text.contains([',', '"', '\n', '\r']) || text.trim() != text {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text
    }
}

/// Writes `results.csv` and `results.json` (each atomically).
pub(crate) fn write_tables(layout: &Layout, rows: &[Row]) -> Result<(), Failure> {
    let keys = summary_keys(rows);
    let records: Vec<Object> = rows.iter().map(|r| record(layout, r, &keys)).collect();
    let header: Vec<String> = match records.first() {
        Some(first) => first.iter().map(|(k, _)| k.clone()).collect(),
        None => vec!["index".into(), "id".into(), "status".into()],
    };
    let mut csv = header.join(",") + "\n";
    for rec in &records {
        let fields: Vec<String> = rec.iter().map(|(_, v)| csv_field(v)).collect();
        csv.push_str(&fields.join(","));
        csv.push('\n');
    }
    write_output(&layout.output("results.csv"), csv.as_bytes())?;
    let ordered: Vec<Ordered> = records.iter().map(Ordered).collect();
    let text =
        serde_json::to_string_pretty(&ordered).map_err(|e| Failure::output(e.to_string()))?;
    write_output(&layout.output("results.json"), (text + "\n").as_bytes())
}

/// Counts of each status, in a fixed order, for the closing line.
pub(crate) fn tally(rows: &[Row]) -> String {
    let parts: Vec<String> = CaseState::ALL
        .iter()
        .filter_map(|s| {
            let n = rows.iter().filter(|r| r.status == *s).count();
            (n > 0).then(|| format!("{n} {s}"))
        })
        .collect();
    format!("{} cases: {}", rows.len(), parts.join(", "))
}

/// One line per case that did not complete: its id, status, exit code and why.
pub(crate) fn not_completed(rows: &[Row]) -> Vec<String> {
    rows.iter()
        .filter(|r| r.status != CaseState::Completed)
        .map(|r| {
            let code = r
                .exit_code
                .map_or(String::new(), |c| format!(" (exit {c})"));
            format!("  {} {}{code}: {}", r.case.id, r.status, r.message)
        })
        .collect()
}
