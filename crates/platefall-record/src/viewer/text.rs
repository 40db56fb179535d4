//! The recording's text documents: the run configuration and the end-of-run summary.
use crate::messages::{RunInfo, RunOutcome};
use crate::options::RecordOptions;
use crate::provenance::RecordedInvocation;
use platefall_core::sim::RunStatus;
use platefall_post::ImageGrid;
use rerun::components::TextLogLevel;
use rerun::TextDocument;

/// A markdown document for the viewer, in [`viewer_text`].
pub(super) fn document(markdown: impl AsRef<str>) -> TextDocument {
    TextDocument::from_markdown(viewer_text(markdown.as_ref()))
}

/// Text as the viewer can draw it. Its font has no combining dot above, which would show θ̇ as
/// θ: the rate is written dθ/dt there, as the plots name it.
fn viewer_text(text: &str) -> String {
    text.replace("θ\u{307}", "dθ/dt")
}

fn code_block(lang: &str, body: &str) -> String {
    // A fence longer than any run of backticks in the body.
    let mut fence = "```".to_string();
    while body.contains(&fence) {
        fence.push('`');
    }
    format!("{fence}{lang}\n{}\n{fence}\n", body.trim_end())
}

/// "[lo, hi]".
fn span(lo: f64, hi: f64) -> String {
    format!("[{lo}, {hi}]")
}

/// The recording's own settings: the wake window and the plots' ranges.
fn view_markdown(info: &RunInfo, wake: &ImageGrid) -> String {
    let w = wake.window;
    let plots = match info.view.plot_ranges {
        Some(r) => format!(
            "coefficients open on [{:.2}, {:.2}], motion on [{:.2}, {:.2}] (zoom out for the start-up spike)",
            r.coefficients[0], r.coefficients[1], r.motion[0], r.motion[1]
        ),
        None => "automatic ranges".to_string(),
    };
    format!(
        "- **wake**: images {ww}×{wh} px over x in {xs} along the path and y in {ys} across it \
         (chords; the plate at 0, the path's heading averaged over its last 4 chords).\n\
         - **plots**: {plots}.\n",
        ww = wake.width,
        wh = wake.height,
        xs = span(w.x0, w.x1),
        ys = span(w.y0, w.y1),
    )
}

/// The run configuration document: title, program, command line, recording settings, grid and
/// the configuration JSON (`img` and `wake` are the close-up and wake image geometries).
pub(super) fn config_markdown(
    info: &RunInfo,
    opts: &RecordOptions,
    img: &ImageGrid,
    wake: &ImageGrid,
) -> String {
    let w = img.window;
    format!(
        "# {title}\n\n\
         - **program**: {version}\n\
         - **case**: {case}\n\
         - **command line**:\n\n{cmd}\n\
         - **recording**: field snapshots every {fe} c/U; images {iw}×{ih} px over \
           x in {xs}, y in {ys} (body axes, chords); streamlines and speed in frame \
           {fr} ({frd}); timelines `time` (convective time t·U/c, shown as seconds) and `step`.\n\
         {view}\
         - **grid**: {nx} × {ny} cells; plate section: {th}.\n\n\
         ## Configuration\n\n{json}",
        title = info.title,
        version = info.version,
        case = info.case,
        cmd = code_block("sh", &info.command_line),
        fe = opts.field_every,
        iw = img.width,
        ih = img.height,
        xs = span(w.x0, w.x1),
        ys = span(w.y0, w.y1),
        fr = opts.streamlines_frame.number(),
        frd = opts.streamlines_frame.describe(),
        nx = info.grid.nx(),
        ny = info.grid.ny(),
        th = info.section_label,
        json = code_block("json", &info.config_json),
        view = view_markdown(info, wake),
    )
}

/// The invocation document (`provenance::RecordedInvocation` as pretty JSON).
pub(super) fn invocation_json(info: &RunInfo) -> String {
    let recorded = RecordedInvocation {
        invocation: info.invocation.clone(),
        case: info.case.to_string(),
        title: info.title.clone(),
        config: serde_json::from_str(&info.config_json).unwrap_or_default(),
    };
    // (Cannot fail for plain data.)
    serde_json::to_string_pretty(&recorded).unwrap_or_default()
}

/// The status line's level and text for how a run ended.
pub(super) fn outcome_line(status: &RunStatus) -> (&'static str, String) {
    match status {
        RunStatus::Completed => (TextLogLevel::INFO, "completed".to_string()),
        RunStatus::Diverged(msg) => (TextLogLevel::ERROR, format!("diverged: {msg}")),
        RunStatus::Interrupted => (TextLogLevel::WARN, "interrupted (Ctrl-C)".to_string()),
        RunStatus::OutputFailed(msg) => (TextLogLevel::ERROR, format!("output failed: {msg}")),
    }
}

/// The summary document: the status line, the statistics, the report and the summary JSON.
pub(super) fn summary_markdown(outcome: &RunOutcome, status: &str, stats_md: &str) -> String {
    format!(
        "# Summary: {status}\n\n{stats_md}\n\n## Report\n\n{report}\n## Summary JSON\n\n{json}",
        report = code_block("text", &outcome.report),
        json = code_block("json", &outcome.summary_json),
    )
}

#[cfg(test)]
mod tests {
    use super::viewer_text;

    #[test]
    fn the_rotation_rate_is_written_so_the_viewer_shows_its_dot() {
        let report = "forced rotation to θ̇ = 2\nmean θ̇ 2.70  mean γ −0.37  θ = 0.1";
        let shown = viewer_text(report);
        assert_eq!(
            shown,
            "forced rotation to dθ/dt = 2\nmean dθ/dt 2.70  mean γ −0.37  θ = 0.1"
        );
        assert!(!shown.contains('\u{307}'));
    }
}
