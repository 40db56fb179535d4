//! Reading a platefall recording back ([`read_recording`]): the invocation document, the
//! summary and report, and the per-step series, with Rerun's own decoder.
use std::collections::BTreeMap;
use std::io::BufReader;
use std::path::Path;

use rerun::external::re_log_encoding::DecoderApp;
use rerun::log::{Chunk, LogMsg};
use rerun::TimelineName;
use rerun::{StoreKind, TextDocument};

use super::layout::{paths, SERIES, TIMELINE_STEP, TIMELINE_TIME};
use crate::provenance::{RecordedInvocation, INVOCATION_FORMAT};
use crate::recorded::{ReadError, Recorded, RecordedStep, RECORDED_SERIES};

/// The recording's data chunks (the blueprint's are left out), read to the end.
fn chunks(path: &Path) -> Result<Vec<Chunk>, ReadError> {
    let file = std::fs::File::open(path).map_err(|e| ReadError::Open {
        path: path.to_path_buf(),
        why: e.to_string(),
    })?;
    let undecodable = |why: String| ReadError::Undecodable {
        path: path.to_path_buf(),
        why,
    };
    let mut it = DecoderApp::decode_lazy(BufReader::new(file));
    let (mut out, mut messages) = (Vec::new(), 0);
    for msg in &mut it {
        let msg = msg.map_err(|e| undecodable(e.to_string()))?;
        messages += 1;
        if let LogMsg::ArrowMsg(store, arrow) = msg {
            if store.kind() == StoreKind::Recording {
                out.push(Chunk::from_arrow_msg(&arrow).map_err(|e| undecodable(e.to_string()))?);
            }
        }
    }
    if messages == 0 {
        return Err(undecodable("it holds no Rerun messages".to_string()));
    }
    let footer = it.rrd_manifests().is_ok_and(|m| !m.is_empty());
    if !footer {
        return Err(ReadError::Truncated {
            path: path.to_path_buf(),
        });
    }
    Ok(out)
}

/// The text of the static document at `entity`, if there is one.
fn document(chunks: &[Chunk], entity: &str) -> Option<String> {
    let id = TextDocument::descriptor_text().component;
    chunks
        .iter()
        .filter(|c| c.is_static() && c.entity_path().to_string() == entity)
        .flat_map(|c| c.iter_component::<rerun::components::Text>(id))
        .flat_map(|batch| {
            batch
                .iter()
                .map(|t| t.as_str().to_string())
                .collect::<Vec<_>>()
        })
        .last()
}

/// Every recorded step: the series joined by step number (time from the `time` timeline).
fn steps(chunks: &[Chunk]) -> Vec<RecordedStep> {
    let id = rerun::Scalars::descriptor_scalars().component;
    let mut rows: BTreeMap<i64, RecordedStep> = BTreeMap::new();
    for (i, (entity, _, _)) in SERIES.iter().enumerate().take(RECORDED_SERIES.len()) {
        for c in chunks
            .iter()
            .filter(|c| c.entity_path().to_string() == *entity)
        {
            let step = c.iter_component_indices(TimelineName::from_static_str(TIMELINE_STEP), id);
            let time = c.iter_component_indices(TimelineName::from_static_str(TIMELINE_TIME), id);
            let values = c.iter_component::<rerun::components::Scalar>(id);
            for (((s, _), (t, _)), v) in step.zip(time).zip(values) {
                let row = rows.entry(s.as_i64()).or_insert(RecordedStep {
                    step: s.as_i64().max(0) as u64,
                    t: t.as_i64() as f64 * 1e-9,
                    values: [f64::NAN; RECORDED_SERIES.len()],
                });
                if let Some(v) = v.first() {
                    row.values[i] = v.0 .0;
                }
            }
        }
    }
    rows.into_values().collect()
}

/// Reads the platefall recording at `path`; refuses a file that is not a complete recording
/// platefall made.
pub fn read_recording(path: &Path) -> Result<Recorded, ReadError> {
    let chunks = chunks(path)?;
    let text = document(&chunks, paths::INVOCATION).ok_or_else(|| ReadError::NotPlatefall {
        path: path.to_path_buf(),
    })?;
    let bad = |why: String| ReadError::Invocation {
        path: path.to_path_buf(),
        why,
    };
    let invocation: RecordedInvocation =
        serde_json::from_str(&text).map_err(|e| bad(e.to_string()))?;
    if invocation.invocation.format != INVOCATION_FORMAT {
        return Err(bad(format!("format `{}`", invocation.invocation.format)));
    }
    Ok(Recorded {
        invocation,
        summary_json: document(&chunks, paths::SUMMARY_JSON),
        report: document(&chunks, paths::REPORT),
        steps: steps(&chunks),
    })
}
