//! What a user sees on opening a recording: real runs through the binary (tiny grids), read back
//! with Rerun's own decoder — the wake entities at the field cadence with the plate drawn in
//! their frame, the wake window turned to the path, the blueprint's plot ranges (set, holding the
//! developed motion, leaving the start-up spike out) and view bounds, and `--small`.
#[path = "record_common/mod.rs"]
mod record_common;

use std::f64::consts::PI;
use std::path::PathBuf;
use std::process::Command;

use record_common::{decode, run_platefall, temp_dir, Decoded};
use rerun::components::{ImageFormat, RotationQuat, Translation3D};

/// Runs the binary with `args` plus `--save DIR/NAME.rrd`; returns the decoded recording and the
/// time, the coefficients and the centre (t, C_L, C_D, C_M, X, Y) from `--csv`.
fn record(name: &str, args: &[&str]) -> (Decoded, Vec<[f64; 6]>) {
    let dir = temp_dir(&format!("view-{name}"));
    let rrd = dir.join(format!("{name}.rrd"));
    let csv = dir.join(format!("{name}.csv"));
    let mut all: Vec<&str> = args.to_vec();
    all.extend([
        "--save",
        rrd.to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
    ]);
    run_platefall(&all);
    let rows = std::fs::read_to_string(&csv)
        .unwrap()
        .lines()
        .skip(1)
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            [v[0], v[3], v[4], v[5], v[6], v[7]]
        })
        .collect();
    (decode(&rrd), rows)
}

/// Checks the wake's rows against the `snaps` field snapshots: one image of each field per
/// snapshot; the frame and the plate drawn in it also at the start (t = 0).
fn assert_wake_cadence(d: &Decoded, snaps: usize) {
    for f in ["vorticity", "pressure", "speed"] {
        assert_eq!(d.rows(&format!("/world/wake/{f}")), snaps, "{f}");
    }
    for e in ["/world/wake", "/world/wake/plate"] {
        assert_eq!(d.rows(e), snaps + 1, "{e}");
    }
}

/// Image sizes (width, height) logged at `path`.
fn image_sizes(d: &Decoded, path: &str) -> Vec<(u32, u32)> {
    let id = rerun::DepthImage::descriptor_format().component;
    d.values::<ImageFormat>(path, id)
        .iter()
        .map(|f| (f.0.width, f.0.height))
        .collect()
}

#[test]
fn static_run_has_the_wake_at_the_cadence_and_plots_without_the_spike() {
    let (d, rows) = record(
        "static",
        &[
            "static",
            "--alpha",
            "0.4",
            "--resolution",
            "8",
            "--t-end",
            "12",
            "--field-every",
            "0.5",
            "--wake-res",
            "64",
        ],
    );
    assert!(d.has_footer && d.has_blueprint);
    // One wake picture (and its frame and plate) per field snapshot: the close-up's cadence.
    let snaps = d.rows("/world/plate/vorticity");
    assert!(
        (24..=25).contains(&snaps),
        "{snaps} snapshots in 12 every 0.5"
    );
    assert_wake_cadence(&d, snaps);
    assert!(d.statics.iter().any(|p| p == "/world/wake/screen"));
    assert!(d.statics.iter().any(|p| p == "/world/wake/window"));
    // The default window of a static run, 10 × 5 chords, at 64 pixels along the path.
    assert!(image_sizes(&d, "/world/wake/vorticity")
        .iter()
        .all(|s| *s == (64, 32)));
    assert_eq!(d.visual_bounds("Wake: ω"), Some(([-8.0, 2.0], [-2.5, 2.5])));
    // The plate moves along +X: the window is not turned, and sits on the plate's centre.
    let quats = d.values::<RotationQuat>(
        "/world/wake",
        rerun::Transform3D::descriptor_quaternion().component,
    );
    assert!(quats.iter().all(|q| q.0 .0[2].abs() < 1e-6), "{quats:?}");
    let xs = d.values::<Translation3D>(
        "/world/wake",
        rerun::Transform3D::descriptor_translation().component,
    );
    assert!(xs[1..]
        .windows(2)
        .all(|w| (w[1].0 .0[0] - w[0].0 .0[0] - 0.5).abs() < 0.02));

    let [lo, hi] = d
        .y_range("Coefficients")
        .expect("a y range for the coefficients");
    // The impulsive start's spike (C_L ≈ 60, C_D ≈ 30 in the first step) is outside the range…
    let spike = rows[0][1].max(rows[0][2]);
    assert!(spike > 3.0 * hi, "spike {spike} vs range top {hi}");
    // …the developed second half is inside, and spans a good part of it.
    let developed: Vec<f64> = rows
        .iter()
        .filter(|r| r[0] > 6.0)
        .flat_map(|r| [r[1], r[2], r[3]])
        .collect();
    let (dmin, dmax) = developed
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), &v| (a.min(v), b.max(v)));
    assert!(
        lo < dmin && dmax < hi,
        "developed [{dmin}, {dmax}] vs [{lo}, {hi}]"
    );
    assert!(
        dmax - dmin > 0.25 * (hi - lo),
        "developed [{dmin}, {dmax}] in [{lo}, {hi}]"
    );
    let [mlo, mhi] = d.y_range("Rotation rate").expect("a y range for the rate");
    assert!(mlo < 0.0 && 0.0 < mhi, "θ̇ = 0 in [{mlo}, {mhi}]");
    // The angles (dots: they wrap at ±π) open on ±π and a margin.
    let [alo, ahi] = d.y_range("Angles").expect("a y range for the angles");
    assert!(alo < -PI && PI < ahi && ahi < 3.5, "[{alo}, {ahi}]");
    // Each field image has its colour bar (and the line naming it) under each flow view's
    // origin, and each flow view its caption.
    for origin in ["/world/follow", "/world/wake/screen"] {
        for field in ["vorticity", "pressure", "speed"] {
            for part in ["/bar", "/text"] {
                let path = format!("{origin}/legend/{field}{part}");
                assert!(d.statics.contains(&path), "{path}");
            }
        }
        assert!(d.statics.contains(&format!("{origin}/legend/caption")));
    }
    // The α plots (mirrored screen frame: a value v is drawn at y = −v) open on the same values,
    // with a margin of 4 % of the range on each side.
    let (_, y) = d.visual_bounds("C vs α").expect("bounds of the α plot");
    let m = 0.04 * (hi - lo);
    assert!(
        (y[0] - (-hi - m)).abs() < 1e-9 && (y[1] - (-lo + m)).abs() < 1e-9,
        "{y:?} against [{lo}, {hi}]"
    );
}

#[test]
fn free_fall_wake_window_turns_with_the_path() {
    let (d, rows) = record(
        "free",
        &[
            "free",
            "--resolution",
            "8",
            "--t-end",
            "7",
            "--field-every",
            "0.5",
            "--wake-res",
            "48",
        ],
    );
    let snaps = d.rows("/world/plate/vorticity");
    assert_wake_cadence(&d, snaps);
    assert_eq!(
        d.visual_bounds("Wake: speed"),
        Some(([-10.0, 2.0], [-3.0, 3.0]))
    );
    assert!(image_sizes(&d, "/world/wake/pressure")
        .iter()
        .all(|s| *s == (48, 24)));
    // Launched along γ₀ = −π/4 and held there while the flow develops (5 c/U): the window is
    // turned to the launch direction, then follows the fall.
    let quats = d.values::<RotationQuat>(
        "/world/wake",
        rerun::Transform3D::descriptor_quaternion().component,
    );
    let angle = |q: &RotationQuat| 2.0 * (q.0 .0[2] as f64).atan2(q.0 .0[3] as f64);
    let launch = -std::f64::consts::FRAC_PI_4;
    assert!(
        quats[..8].iter().all(|q| (angle(q) - launch).abs() < 1e-3),
        "{quats:?}"
    );
    // The coefficient range is symmetric (the sense of the tumble is not known beforehand) and
    // leaves out the start of the development phase (C_L ≈ 17 at N = 16).
    let [lo, hi] = d.y_range("Coefficients").unwrap();
    assert_eq!(lo, -hi);
    assert!(rows[0][1].abs() > hi, "start C_L {} vs {hi}", rows[0][1]);
    // The layout sent at the end opens the trajectory view on the whole path (screen frame:
    // inertial Y mirrored), with at least the strobe's half chord around it.
    let (x, y) = d
        .visual_bounds("Trajectory")
        .expect("bounds of the trajectory");
    for r in &rows {
        let (px, py) = (r[4], -r[5]);
        assert!(
            x[0] + 0.5 <= px && px <= x[1] - 0.5 && y[0] + 0.5 <= py && py <= y[1] - 0.5,
            "centre ({px}, {py}) at t = {} outside {x:?} × {y:?}",
            r[0]
        );
    }
}

#[test]
fn small_sets_the_bug_report_cadence_and_explicit_flags_win() {
    let (d, _) = record(
        "small",
        &["static", "--resolution", "8", "--t-end", "3", "--small"],
    );
    let snaps = d.rows("/world/wake/vorticity");
    assert!((6..=7).contains(&snaps), "{snaps} snapshots every 0.5 in 3");
    assert!(image_sizes(&d, "/world/wake/vorticity")
        .iter()
        .all(|s| *s == (128, 64)));
    assert!(image_sizes(&d, "/world/plate/vorticity")
        .iter()
        .all(|s| s.0 == 128));
    let (d, _) = record(
        "small-override",
        &[
            "static",
            "--resolution",
            "8",
            "--t-end",
            "3",
            "--small",
            "--field-every",
            "0.25",
            "--wake-res",
            "32",
        ],
    );
    let snaps = d.rows("/world/wake/vorticity");
    assert!(
        (12..=13).contains(&snaps),
        "{snaps} snapshots every 0.25 in 3"
    );
    assert!(image_sizes(&d, "/world/wake/vorticity")
        .iter()
        .all(|s| *s == (32, 16)));
}

#[test]
fn bad_view_options_are_refused_with_one_line_and_exit_2() {
    let dir = temp_dir("view-bad");
    let out: PathBuf = dir.join("never.rrd");
    for (args, needle) in [
        (
            vec!["--wake-window", "1,2,-1,1"],
            "--wake-window \"1,2,-1,1\"",
        ),
        (vec!["--wake-window", "-20,2,-1,1"], "[-15, 15]"),
        (
            vec!["--wake-res", "8"],
            "--wake-res 8: must be in 16..=2048",
        ),
        (vec!["--small", "--field-every", "0"], "--field-every 0"),
    ] {
        let o = Command::new(env!("CARGO_BIN_EXE_platefall"))
            .args(["static", "--resolution", "8", "--t-end", "1", "--save"])
            .arg(&out)
            .args(&args)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert!(!out.exists(), "{args:?} wrote the recording");
    }
}
