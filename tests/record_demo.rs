//! A synthetic recording to look at (and to measure sizes with):
//!
//! ```sh
//! PLATEFALL_DEMO_T_END=60 PLATEFALL_DEMO_OUT=/tmp/platefall_demo.rrd \
//!     cargo test --release --test record_demo -- --ignored --nocapture
//! /work/shared/tools/rrd-screenshot.sh /tmp/platefall_demo.rrd /tmp/shot.png
//! ```
//! Optional: PLATEFALL_DEMO_FIELD_EVERY, PLATEFALL_DEMO_FIELD_RES, PLATEFALL_DEMO_DT.
mod record_common;

use std::time::Instant;

use platefall_core::sim::RunStatus;
use platefall_record::messages::RunOutcome;
use platefall_record::{spawn_logger, RecordOptions};
use record_common::*;

fn env_f64(name: &str, default: f64) -> f64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

#[test]
#[ignore = "writes a demo recording to /tmp; run by hand"]
fn demo_recording() {
    let t_end = env_f64("PLATEFALL_DEMO_T_END", 6.0);
    let dt = env_f64("PLATEFALL_DEMO_DT", 0.004);
    let out = std::env::var("PLATEFALL_DEMO_OUT").unwrap_or("/tmp/platefall_demo.rrd".into());
    let defaults = RecordOptions::default();
    let field_every = env_f64("PLATEFALL_DEMO_FIELD_EVERY", defaults.field_every);
    let field_res = env_f64("PLATEFALL_DEMO_FIELD_RES", defaults.field_res as f64) as usize;
    let g = grid(250, 200, 0.0625);
    let opts = RecordOptions {
        field_every,
        field_res,
        max_fields_in_flight: 8,
        ..RecordOptions::to_file(&out)
    };
    let t0 = Instant::now();
    let mut logger = spawn_logger(opts, run_info_until(g.clone(), Some(t_end))).unwrap();
    let steps = (t_end / dt).round() as u64;
    let mut snap_time = 0.0;
    let mut offered = 0;
    for k in 1..=steps {
        let s = sample(k, dt);
        logger.step(s).unwrap();
        if logger.field_due(s.t) {
            let ts = Instant::now();
            let snap = snapshot(&g, &s);
            snap_time += ts.elapsed().as_secs_f64();
            // Pace like a real solver would: wait while the logger is busy rather than skip.
            let mut snap = Some(snap);
            while let Some(sn) = snap.take() {
                if !logger.offer_field(sn.clone()) {
                    std::thread::sleep(std::time::Duration::from_millis(5));
                    snap = Some(sn);
                }
            }
            offered += 1;
        }
    }
    let t_run = t0.elapsed();
    let report = logger
        .finish(RunOutcome {
            status: RunStatus::Completed,
            summary_json: "{\n  \"synthetic\": true\n}".into(),
            report: "synthetic demo run".into(),
        })
        .unwrap();
    let (path, bytes) = report.rrd.clone().unwrap();
    eprintln!(
        "demo: {} steps, {} snapshots offered, {} logged, {} skipped; {:.2} MB → {:.1} kB per snapshot (all data); \
         run {:.1}s (snapshot generation {:.1}s), total {:.1}s; {}",
        report.steps,
        offered,
        report.fields_logged,
        report.fields_skipped,
        bytes as f64 / 1e6,
        bytes as f64 / 1e3 / report.fields_logged.max(1) as f64,
        t_run.as_secs_f64(),
        snap_time,
        t0.elapsed().as_secs_f64(),
        path.display()
    );
    let d = decode(&path);
    assert!(d.has_footer);
}

/// Every view side by side (the default layout hides some in tabs), for screenshots.
fn all_views_blueprint() -> rerun::blueprint::Blueprint {
    use platefall_record::paths;
    use rerun::blueprint::{Blueprint, Grid, Spatial2DView, TimeSeriesView};
    let flow = |name: &str, field: &str| {
        Spatial2DView::new(name)
            .with_origin(paths::FOLLOW)
            .with_contents([
                format!("+ {}/**", paths::PLATE),
                format!("+ {}", paths::REACH),
                format!("- {}/vorticity", paths::PLATE),
                format!("- {}/pressure", paths::PLATE),
                format!("- {}/speed", paths::PLATE),
                format!("+ {}/{field}", paths::PLATE),
            ])
    };
    let grid = Grid::new([
        flow("Pressure", "pressure").into(),
        flow("Speed", "speed").into(),
        Spatial2DView::new("C vs α")
            .with_origin(paths::POLAR_SCREEN)
            .with_contents([format!("+ {}/**", paths::POLAR_COEFFICIENTS)])
            .into(),
        Spatial2DView::new("V, dθ/dt vs α")
            .with_origin(paths::POLAR_SCREEN)
            .with_contents([format!("+ {}/**", paths::POLAR_MOTION)])
            .into(),
        TimeSeriesView::new("Solver")
            .with_contents([
                format!("+ {}/**", paths::SOLVER),
                format!("+ {}", paths::SKIPPED_FIELDS),
            ])
            .into(),
        rerun::blueprint::TextDocumentView::new("Summary")
            .with_origin(paths::SUMMARY)
            .into(),
    ])
    .with_grid_columns(3);
    Blueprint::new(grid)
}

/// Rewrites PLATEFALL_INSPECT_IN (an .rrd) to /tmp/platefall_inspect.rrd with its own layout
/// replaced by one that shows every view at once:
/// `PLATEFALL_INSPECT_IN=run.rrd cargo test --release --test record_demo inspect -- --ignored`.
#[test]
#[ignore = "rewrites a recording for screenshots; run by hand"]
fn inspect_all_views() {
    use rerun::external::re_log_encoding::{DecoderApp, Encoder, EncodingOptions};
    use rerun::log::LogMsg;
    let input = std::env::var("PLATEFALL_INSPECT_IN").unwrap_or("/tmp/platefall_demo.rrd".into());
    let out = std::fs::File::create("/tmp/platefall_inspect.rrd").unwrap();
    let mut enc = Encoder::new_eager(
        rerun::external::re_build_info::CrateVersion::LOCAL,
        EncodingOptions::PROTOBUF_COMPRESSED,
        std::io::BufWriter::new(out),
    )
    .unwrap();
    let reader = std::io::BufReader::new(std::fs::File::open(&input).unwrap());
    for msg in DecoderApp::decode_lazy(reader) {
        let msg = msg.unwrap();
        let keep = match &msg {
            LogMsg::BlueprintActivationCommand(_) => false,
            other => other.store_id().kind() == rerun::StoreKind::Recording,
        };
        if keep {
            enc.append(&msg).unwrap();
        }
    }
    let (rec, storage) = rerun::RecordingStreamBuilder::new(platefall_record::APPLICATION_ID)
        .blueprint()
        .send_properties(false)
        .memory()
        .unwrap();
    all_views_blueprint()
        .send(&rec, rerun::blueprint::BlueprintActivation::default())
        .unwrap();
    rec.flush_blocking().unwrap();
    for msg in storage.take() {
        enc.append(&msg).unwrap();
    }
    enc.finish().unwrap();
}
