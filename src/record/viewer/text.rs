//! The recording's text documents: the run configuration and the end-of-run summary.
use crate::post::ImageGrid;
use crate::record::messages::{RunInfo, RunOutcome};
use crate::record::options::RecordOptions;

fn code_block(lang: &str, body: &str) -> String {
    // A fence longer than any run of backticks in the body.
    let mut fence = "```".to_string();
    while body.contains(&fence) {
        fence.push('`');
    }
    format!("{fence}{lang}\n{}\n{fence}\n", body.trim_end())
}

pub(super) fn config_markdown(info: &RunInfo, opts: &RecordOptions, img: &ImageGrid) -> String {
    let w = img.window;
    format!(
        "# {title}\n\n\
         - **program**: platefall {version}\n\
         - **case**: {case}\n\
         - **command line**:\n\n{cmd}\n\
         - **recording**: field snapshots every {fe} c/U; images {iw}×{ih} px over \
           x in [{x0}, {x1}], y in [{y0}, {y1}] (body axes, chords); streamlines and speed in frame \
           {fr} ({frd}); timelines `time` (convective time t·U/c, shown as seconds) and `step`.\n\
         - **grid**: {nx} × {ny} cells; plate thickness {th} c.\n\n\
         ## Configuration\n\n{json}",
        title = info.title,
        version = info.version,
        case = info.case,
        cmd = code_block("sh", &info.command_line),
        fe = opts.field_every,
        iw = img.width,
        ih = img.height,
        x0 = w.x0,
        x1 = w.x1,
        y0 = w.y0,
        y1 = w.y1,
        fr = opts.streamlines_frame.number(),
        frd = opts.streamlines_frame.describe(),
        nx = info.grid.nx(),
        ny = info.grid.ny(),
        th = info.thickness,
        json = code_block("json", &info.config_json),
    )
}

pub(super) fn summary_markdown(outcome: &RunOutcome, status: &str, stats_md: &str) -> String {
    format!(
        "# Summary: {status}\n\n{stats_md}\n\n## Report\n\n{report}\n## Summary JSON\n\n{json}",
        report = code_block("text", &outcome.report),
        json = code_block("json", &outcome.summary_json),
    )
}
