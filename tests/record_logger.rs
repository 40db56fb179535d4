//! The logger end to end: synthetic messages → spawn_logger → .rrd → decoded back with Rerun's
//! own decoder (`re_log_encoding::DecoderApp`, reachable as `rerun::external::re_log_encoding`).
mod record_common;

use std::time::{Duration, Instant};

use platefall_core::flow::FlowError;
use platefall_core::sim::{RunStatus, SimError};
use platefall_record::messages::RunOutcome;
use platefall_record::{paths, spawn_logger, RecordOptions, CSV_HEADER};
use record_common::*;

fn outcome(status: RunStatus) -> RunOutcome {
    RunOutcome {
        status,
        summary_json: "{\n  \"mean_speed\": 1.0\n}".into(),
        report: "synthetic report".into(),
    }
}

/// Runs `steps` synthetic steps through a logger with `opts`, offering a field whenever due.
/// Returns (fields accepted, fields due).
fn drive(
    logger: &mut platefall_record::Logger,
    g: &platefall_core::grid::GridGeometry,
    steps: u64,
    dt: f64,
) -> (u64, u64) {
    let (mut accepted, mut due) = (0, 0);
    for k in 1..=steps {
        let s = sample(k, dt);
        logger.step(s).unwrap();
        if logger.field_due(s.t) {
            due += 1;
            if logger.offer_field(snapshot(g, &s)) {
                accepted += 1;
            }
        }
    }
    (accepted, due)
}

#[test]
fn full_run_round_trips_through_the_rrd_file() {
    let dir = temp_dir("roundtrip");
    let rrd = dir.join("run.rrd");
    let csv = dir.join("run.csv");
    let g = grid(40, 30, 0.0625);
    let info = run_info_until(g.clone(), Some(2.0));
    let opts = RecordOptions {
        csv: Some(csv.clone()),
        field_every: 0.1,
        // The synthetic "solver" is far faster than the painter; let every snapshot queue up.
        max_fields_in_flight: 64,
        ..RecordOptions::to_file(&rrd)
    };
    let mut logger = spawn_logger(opts, info).unwrap();
    assert_eq!(logger.field_every(), 0.1);
    // 200 steps of 0.01 → t in (0, 2]: snapshots due at 0.01 (the first), 0.1, 0.2, …, 2.0.
    let (accepted, due) = drive(&mut logger, &g, 200, 0.01);
    assert_eq!(due, 21, "field cadence");
    let report = logger.finish(outcome(RunStatus::Completed)).unwrap();
    assert_eq!(report.steps, 200);
    assert_eq!(report.fields_logged + report.fields_skipped, due);
    assert_eq!(report.fields_logged, accepted);
    assert_eq!(accepted, due);
    let (path, bytes) = report.rrd.clone().expect("rrd in report");
    assert_eq!(path, rrd);
    assert!(bytes > 10_000, "{bytes}");
    assert!(!report.is_serving());

    let d = decode(&rrd);
    assert!(d.has_footer, "file sink finalised (footer present)");
    assert!(d.has_blueprint, "blueprint sent");
    for tl in ["step", "time"] {
        assert!(
            d.timelines.iter().any(|t| t == tl),
            "timeline {tl}: {:?}",
            d.timelines
        );
    }
    assert!(
        !d.timelines.iter().any(|t| t == "log_time"),
        "{:?}",
        d.timelines
    );
    // Every step, every series.
    for p in [
        "/coefficients/cl",
        "/coefficients/cd",
        "/coefficients/cm",
        "/motion/speed",
        "/motion/omega",
        "/motion/gamma",
        "/motion/alpha",
        "/solver/dt",
    ] {
        assert_eq!(d.rows(p), 200, "{p}");
    }
    // Poses: at the start (t = 0), every ≥ 0.01 c/U (here every step) and at every snapshot.
    assert_eq!(d.rows(paths::PLATE), 1 + 200 + accepted as usize);
    assert_eq!(d.rows(paths::FOLLOW), 1 + 200 + accepted as usize);
    let cl = d.scalars("/coefficients/cl");
    assert_eq!(cl.len(), 200);
    assert!((cl[41] - sample(42, 0.01).cl).abs() < 1e-12);
    // Every accepted snapshot: three images, streamlines, the skipped counter.
    for f in ["vorticity", "pressure", "speed"] {
        assert_eq!(
            d.rows(&format!("{}/{f}", paths::PLATE)),
            accepted as usize,
            "{f}"
        );
    }
    assert_eq!(d.rows(paths::STREAMLINES), accepted as usize);
    assert_eq!(d.rows(paths::SKIPPED_FIELDS), accepted as usize);
    // Static parts and growing curves.
    for p in [
        paths::OUTLINE,
        paths::CONFIG,
        paths::SUMMARY,
        paths::WORLD_SCREEN,
        paths::POLAR_SCREEN,
    ] {
        assert!(d.statics.iter().any(|s| s == p), "static {p}");
    }
    assert!(!d
        .entities_under(&format!("{}/", paths::TRAJECTORY))
        .is_empty());
    assert!(!d.entities_under(&format!("{}/", paths::STROBE)).is_empty());
    // The three curves C_L, C_D, C_M, and the plot's own axes with their labels.
    let polar = d.entities_under(&format!("{}/", paths::POLAR_COEFFICIENTS));
    let curves = ["cl", "cd", "cm"].map(|c| format!("{}/{c}", paths::POLAR_COEFFICIENTS));
    for c in &curves {
        assert!(
            polar.iter().any(|e| e.starts_with(c.as_str())),
            "{c} in {polar:?}"
        );
    }
    let axes = format!("{}/axes", paths::POLAR_COEFFICIENTS);
    assert!(
        polar
            .iter()
            .all(|e| curves.iter().any(|c| e.starts_with(c.as_str()))
                || e.starts_with(axes.as_str())),
        "{polar:?}"
    );
    assert!(d.statics.contains(&axes), "static {axes}");
    // 2 time units at 0.5 per outline → 5 outlines (t = 0.01, 0.5, 1.0, 1.5, 2.0).
    let config = d.texts(paths::CONFIG).join("\n");
    assert!(config.contains("platefall free --synthetic"), "{config}");
    assert!(config.contains("\"re\": 4770"), "{config}");
    assert!(config.contains("0.1.0-test"));
    let summary = d.texts(paths::SUMMARY).join("\n");
    assert!(summary.contains("completed"), "{summary}");
    assert!(summary.contains("mean_speed"));
    assert!(
        summary.contains("skipped because the logger fell behind: 0"),
        "{summary}"
    );
    let status = d.texts(paths::STATUS);
    assert!(status.first().unwrap().starts_with("started"), "{status:?}");
    assert_eq!(status.last().unwrap(), "completed");

    // CSV: header + one line per step + the trailer saying how the run ended.
    let text = std::fs::read_to_string(&csv).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], CSV_HEADER);
    assert_eq!(lines.len(), 202);
    assert_eq!(lines[201], "# platefall: status=completed steps=200 t=2");
    let row: Vec<f64> = lines[42].split(',').map(|x| x.parse().unwrap()).collect();
    let s = sample(42, 0.01);
    assert_eq!(row.len(), 15);
    assert_eq!(row[0], s.t);
    assert_eq!(row[1], 42.0);
    assert_eq!(row[3], s.cl);
    assert_eq!(row[14], s.alpha);
    assert_eq!(report.csv, Some((csv, 200)));

    // From outside, if the rerun CLI of the brief is installed.
    if let Some(cli) = rerun_cli() {
        let out = std::process::Command::new(cli)
            .args(["rrd", "verify"])
            .arg(&rrd)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "rerun rrd verify: {}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn snapshots_offered_to_a_busy_logger_are_skipped_and_reported() {
    let dir = temp_dir("skip");
    let rrd = dir.join("skip.rrd");
    let g = grid(40, 30, 0.0625);
    let opts = RecordOptions {
        max_fields_in_flight: 2,
        ..RecordOptions::to_file(&rrd)
    };
    let logger = spawn_logger(opts, run_info(g.clone())).unwrap();
    let s = sample(1, 0.01);
    logger.step(s).unwrap();
    {
        let _pause = logger.pause();
        assert!(logger.offer_field(snapshot(&g, &s)));
        assert!(logger.offer_field(snapshot(&g, &s)));
        // Two in flight: the next ones are refused at once, without blocking.
        let t0 = Instant::now();
        assert!(!logger.offer_field(snapshot(&g, &s)));
        assert!(!logger.offer_field(snapshot(&g, &s)));
        assert!(t0.elapsed() < Duration::from_millis(500));
        assert_eq!(logger.skipped_fields(), 2);
    }
    let s2 = sample(2, 0.01);
    logger.step(s2).unwrap();
    // After the logger caught up, snapshots are accepted again.
    let t0 = Instant::now();
    while !logger.offer_field(snapshot(&g, &s2)) {
        assert!(
            t0.elapsed() < Duration::from_secs(20),
            "logger never caught up"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    let report = logger.finish(outcome(RunStatus::Completed)).unwrap();
    assert!(report.fields_skipped >= 2);
    assert_eq!(report.fields_logged, 3);
    assert!(
        report.lines()[0].contains("skipped"),
        "{:?}",
        report.lines()
    );

    let d = decode(&rrd);
    assert!(d.has_footer);
    let skipped = d.scalars(paths::SKIPPED_FIELDS);
    assert_eq!(skipped.last().copied(), Some(report.fields_skipped as f64));
    let summary = d.texts(paths::SUMMARY).join("\n");
    assert!(
        summary.contains(&format!(
            "skipped because the logger fell behind: {}",
            report.fields_skipped
        )),
        "{summary}"
    );
    assert!(d.texts(paths::STATUS).iter().any(|l| l.contains("skipped")));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn interrupted_and_abandoned_runs_still_give_finalised_files() {
    let dir = temp_dir("interrupt");
    let g = grid(24, 20, 0.0625);

    // Ctrl-C: finish with Interrupted.
    let rrd = dir.join("interrupted.rrd");
    let mut logger = spawn_logger(RecordOptions::to_file(&rrd), run_info(g.clone())).unwrap();
    drive(&mut logger, &g, 50, 0.01);
    let report = logger.finish(outcome(RunStatus::Interrupted)).unwrap();
    assert_eq!(report.steps, 50);
    let d = decode(&rrd);
    assert!(d.has_footer);
    assert_eq!(d.rows("/coefficients/cl"), 50);
    assert!(d
        .texts(paths::STATUS)
        .last()
        .unwrap()
        .contains("interrupted"));

    // Diverged.
    let rrd = dir.join("diverged.rrd");
    let mut logger = spawn_logger(RecordOptions::to_file(&rrd), run_info(g.clone())).unwrap();
    drive(&mut logger, &g, 30, 0.01);
    logger
        .finish(outcome(RunStatus::Diverged(SimError::Flow(
            FlowError::Diverged {
                t: 0.3,
                step: 30,
                reason: "NaN in u".into(),
            },
        ))))
        .unwrap();
    let d = decode(&rrd);
    assert!(d.has_footer);
    assert!(d
        .texts(paths::STATUS)
        .last()
        .unwrap()
        .contains("diverged at t = 0.3000 (step 30): NaN in u"));

    // The solver errors out and drops the logger without finish().
    let rrd = dir.join("dropped.rrd");
    {
        let mut logger = spawn_logger(RecordOptions::to_file(&rrd), run_info(g.clone())).unwrap();
        drive(&mut logger, &g, 20, 0.01);
    }
    let d = decode(&rrd);
    assert!(d.has_footer);
    assert_eq!(d.rows("/coefficients/cl"), 20);
    assert!(d
        .texts(paths::STATUS)
        .last()
        .unwrap()
        .contains("interrupted"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn connect_to_nothing_never_stalls_the_run_or_the_file() {
    let dir = temp_dir("connect");
    let rrd = dir.join("connect.rrd");
    let port = free_port();
    let g = grid(40, 30, 0.0625);
    let opts = RecordOptions {
        connect: Some(format!("rerun+http://127.0.0.1:{port}/proxy")),
        field_every: 0.05,
        ..RecordOptions::to_file(&rrd)
    };
    let t0 = Instant::now();
    let mut logger = spawn_logger(opts, run_info(g.clone())).unwrap();
    let (accepted, _) = drive(&mut logger, &g, 3000, 0.01);
    let run_time = t0.elapsed();
    let report = logger.finish(outcome(RunStatus::Completed)).unwrap();
    let total = t0.elapsed();
    assert!(
        total < Duration::from_secs(60),
        "run {run_time:?}, total {total:?}"
    );
    let c = report.connect.clone().expect("connect report");
    assert!(!c.ever_connected);
    assert!(
        report
            .notes
            .iter()
            .any(|n| n.contains("no viewer was reachable")),
        "{:?}",
        report.notes
    );
    let d = decode(&rrd);
    assert!(d.has_footer);
    assert_eq!(d.rows("/coefficients/cl"), 3000);
    assert_eq!(
        d.rows(&format!("{}/vorticity", paths::PLATE)),
        accepted as usize
    );
    eprintln!(
        "connect to nothing: run {run_time:?}, finish {:?}, {c:?}",
        total - run_time
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn csv_only_run_needs_no_rerun_sink() {
    let dir = temp_dir("csvonly");
    let csv = dir.join("only.csv");
    let g = grid(16, 12, 0.0625);
    let opts = RecordOptions {
        csv: Some(csv.clone()),
        ..RecordOptions::default()
    };
    let mut logger = spawn_logger(opts, run_info(g.clone())).unwrap();
    drive(&mut logger, &g, 10, 0.01);
    let report = logger.finish(outcome(RunStatus::Completed)).unwrap();
    assert!(report.rrd.is_none());
    assert_eq!(std::fs::read_to_string(&csv).unwrap().lines().count(), 12);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn connect_to_a_viewer_that_goes_away_mid_run() {
    let dir = temp_dir("connect-away");
    let rrd = dir.join("away.rrd");
    let port = free_port();
    // A stand-in viewer: Rerun's own gRPC message proxy, the server a viewer runs.
    let viewer = rerun::RecordingStreamBuilder::new("stand_in_viewer")
        .serve_grpc_opts("127.0.0.1", port, rerun::ServerOptions::default())
        .unwrap();
    std::thread::sleep(Duration::from_millis(300));
    let g = grid(40, 30, 0.0625);
    let opts = RecordOptions {
        connect: Some(format!("rerun+http://127.0.0.1:{port}/proxy")),
        field_every: 0.05,
        ..RecordOptions::to_file(&rrd)
    };
    let t0 = Instant::now();
    let mut logger = spawn_logger(opts, run_info(g.clone())).unwrap();
    let mut accepted = 0;
    for k in 1..=3000u64 {
        let s = sample(k, 0.01);
        logger.step(s).unwrap();
        if logger.field_due(s.t) && logger.offer_field(snapshot(&g, &s)) {
            accepted += 1;
        }
        if k % 500 == 0 {
            std::thread::sleep(Duration::from_millis(300));
        }
        if k == 1500 {
            drop(viewer.clone());
            viewer.disconnect(); // shuts the stand-in's server down: the viewer went away
            std::thread::sleep(Duration::from_millis(300));
            assert!(
                std::net::TcpStream::connect(("127.0.0.1", port)).is_err(),
                "stand-in viewer still listening"
            );
        }
    }
    let run_time = t0.elapsed();
    let report = logger.finish(outcome(RunStatus::Completed)).unwrap();
    let total = t0.elapsed();
    let c = report.connect.clone().unwrap();
    eprintln!(
        "viewer went away: run {run_time:?}, finish {:?}, {c:?}",
        total - run_time
    );
    assert!(c.ever_connected, "{c:?}");
    assert!(total - run_time < Duration::from_secs(15));
    let d = decode(&rrd);
    assert!(d.has_footer);
    assert_eq!(d.rows("/coefficients/cl"), 3000);
    assert_eq!(
        d.rows(&format!("{}/vorticity", paths::PLATE)),
        accepted as usize
    );
    drop(viewer);
    let _ = std::fs::remove_dir_all(&dir);
}

/// A port of 127.0.0.1 that nothing listens on (free when asked).
fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0")
        .unwrap()
        .local_addr()
        .unwrap()
        .port()
}

/// --serve: after `finish` the server keeps the whole run for a viewer that connects late.
/// The late viewer is the real `rerun` CLI (`rerun URL --save FILE`), when it is installed.
#[test]
fn serve_keeps_the_run_for_a_late_viewer() {
    let dir = temp_dir("serve");
    let port = free_port();
    let g = grid(30, 24, 0.0625);
    let opts = RecordOptions {
        serve: Some(platefall_record::ServeOptions {
            bind: "127.0.0.1".parse().unwrap(),
            port,
            memory_limit: "10%".into(),
            web_port: None,
        }),
        ..RecordOptions::default()
    };
    let mut logger = spawn_logger(opts, run_info(g.clone())).unwrap();
    drive(&mut logger, &g, 300, 0.01);
    let report = logger.finish(outcome(RunStatus::Completed)).unwrap();
    assert!(report.is_serving());
    let url = report.serve_url.clone().unwrap();
    assert_eq!(url, format!("rerun+http://127.0.0.1:{port}/proxy"));
    assert!(
        std::net::TcpStream::connect(("127.0.0.1", port)).is_ok(),
        "still serving"
    );

    if let Some(cli) = rerun_cli() {
        let late = dir.join("late.rrd");
        let mut child = std::process::Command::new(cli)
            .arg(&url)
            .arg("--save")
            .arg(&late)
            .args(["--port", &free_port().to_string()])
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        let t0 = Instant::now();
        let mut rows = 0;
        while t0.elapsed() < Duration::from_secs(30) {
            std::thread::sleep(Duration::from_millis(500));
            if late.exists() {
                let d = decode_partial(&late);
                rows = d.rows("/coefficients/cl");
                if rows == 300 {
                    break;
                }
            }
        }
        let _ = std::process::Command::new("kill")
            .args(["-INT", &child.id().to_string()])
            .status();
        // Ctrl-C makes the viewer finalise and exit; never wait for it unboundedly.
        let t1 = Instant::now();
        while child.try_wait().ok().flatten().is_none() && t1.elapsed() < Duration::from_secs(10) {
            std::thread::sleep(Duration::from_millis(100));
        }
        let _ = child.kill();
        let _ = child.wait();
        assert_eq!(rows, 300, "the late viewer got every step");
    } else {
        eprintln!("rerun CLI not installed: late-viewer check skipped");
    }

    // Ctrl-C: serve_until_interrupted returns and the port is released.
    let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let s2 = stop.clone();
    let t = std::thread::spawn(move || report.serve_until_interrupted(&s2));
    std::thread::sleep(Duration::from_millis(300));
    stop.store(true, std::sync::atomic::Ordering::SeqCst);
    t.join().unwrap().unwrap();
    std::thread::sleep(Duration::from_millis(500));
    assert!(
        std::net::TcpStream::connect(("127.0.0.1", port)).is_err(),
        "server stopped"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// One HTTP/1.0 GET of `path` on 127.0.0.1:`port`: the status line and the body (bounded by a
/// 30 s read timeout).
#[cfg(feature = "web")]
fn http_get(port: u16, path: &str) -> (String, Vec<u8>) {
    use std::io::{Read as _, Write as _};
    let mut s = std::net::TcpStream::connect(("127.0.0.1", port)).expect("web viewer listens");
    s.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    write!(s, "GET {path} HTTP/1.0\r\nHost: 127.0.0.1\r\n\r\n").unwrap();
    let mut raw = Vec::new();
    s.read_to_end(&mut raw).unwrap();
    let end = raw
        .windows(4)
        .position(|w| w == b"\r\n\r\n")
        .expect("headers")
        + 4;
    let head = String::from_utf8_lossy(&raw[..end]).into_owned();
    (
        head.lines().next().unwrap_or("").to_string(),
        raw[end..].to_vec(),
    )
}

/// --web: the web viewer's page, script and wasm are served from the binary next to the gRPC
/// server, at the URL the report names, after the run and until the servers stop.
#[test]
#[cfg(feature = "web")]
fn web_viewer_is_served_next_to_the_server() {
    let (port, web_port) = (free_port(), free_port());
    let g = grid(30, 24, 0.0625);
    let opts = RecordOptions {
        serve: Some(platefall_record::ServeOptions {
            bind: "127.0.0.1".parse().unwrap(),
            port,
            memory_limit: "10%".into(),
            web_port: Some(web_port),
        }),
        ..RecordOptions::default()
    };
    let mut logger = spawn_logger(opts, run_info(g.clone())).unwrap();
    drive(&mut logger, &g, 20, 0.01);
    let mut report = logger.finish(outcome(RunStatus::Completed)).unwrap();
    assert_eq!(
        report.web_url.as_deref(),
        Some(
            format!("http://127.0.0.1:{web_port}/?url=rerun%2Bhttp://127.0.0.1:{port}/proxy")
                .as_str()
        )
    );
    let (status, page) = http_get(web_port, "/?url=x");
    assert!(status.contains(" 200"), "{status}");
    assert!(String::from_utf8_lossy(&page).contains("<title>Rerun Viewer</title>"));
    let (status, wasm) = http_get(web_port, "/re_viewer_bg.wasm");
    assert!(status.contains(" 200"), "{status}");
    assert!(
        wasm.starts_with(b"\0asm") && wasm.len() > 1_000_000,
        "{} bytes",
        wasm.len()
    );
    report.stop_serving();
    std::thread::sleep(Duration::from_millis(500));
    for p in [port, web_port] {
        assert!(
            std::net::TcpStream::connect(("127.0.0.1", p)).is_err(),
            "{p} stopped"
        );
    }
}

#[test]
fn a_snapshot_that_does_not_fit_the_grid_is_reported_not_fatal() {
    let dir = temp_dir("badsnap");
    let rrd = dir.join("bad.rrd");
    let g = grid(20, 16, 0.0625);
    let logger = spawn_logger(RecordOptions::to_file(&rrd), run_info(g.clone())).unwrap();
    let s = sample(1, 0.01);
    logger.step(s).unwrap();
    let mut bad = snapshot(&g, &s);
    bad.u.pop();
    assert!(logger.offer_field(bad));
    assert!(logger.offer_field(snapshot(&g, &s)));
    logger.step(sample(2, 0.01)).unwrap();
    let report = logger.finish(outcome(RunStatus::Completed)).unwrap();
    assert_eq!(report.fields_logged, 1);
    let d = decode(&rrd);
    assert!(d.has_footer);
    assert_eq!(d.rows(&format!("{}/vorticity", paths::PLATE)), 1);
    assert!(
        d.texts(paths::STATUS)
            .iter()
            .any(|l| l.contains("ignored: u has")),
        "{:?}",
        d.texts(paths::STATUS)
    );
    let _ = std::fs::remove_dir_all(&dir);
}
