//! The binary as a user meets it: bad input is refused with one clear line and exit code 2, with
//! nothing written; a good run writes the summary JSON with its stable keys.
use std::path::PathBuf;
use std::process::Command;

fn platefall(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_platefall"))
        .args(args)
        .output()
        .expect("binary runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("platefall-cli-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn bad_values_are_refused_naming_the_value_and_range() {
    let dir = scratch("bad");
    let summary = dir.join("s.json");
    let s = summary.to_str().unwrap();
    let cases: &[(&[&str], &str)] = &[
        (&["static", "--re", "-5"], "-5"),
        (&["static", "--re", "0"], "(0, 100000]"),
        (&["static", "--resolution", "0"], "4..=1024"),
        (&["static", "--alpha", "NaN"], "NaN"),
        (&["static", "--alpha", "4"], "[-3.14"),
        (&["static", "--t-end", "-1"], "--t-end"),
        (&["forced", "--rate", "0"], "--rate"),
        (&["free", "--mass", "0"], "(0, 1000000]"),
        (&["free", "--inertia", "-0.1"], "--inertia"),
        (&["pinned", "--preset", "none"], "--mass"),
        (&["free", "--ab-order", "7"], "1..=6"),
        (
            &["static", "--summary", "/nonexistent-dir/s.json"],
            "/nonexistent-dir",
        ),
    ];
    for (args, needle) in cases {
        let mut full: Vec<&str> = args.to_vec();
        full.extend_from_slice(&["--no-save", "--summary", s]);
        // The later --summary wins for the last case; keep the bad one there.
        if args.contains(&"--summary") {
            full.truncate(args.len() + 1);
        }
        let (code, _, err) = platefall(&full);
        assert_eq!(code, 2, "{args:?}: exit {code}, stderr {err}");
        let first = err.lines().next().unwrap_or("");
        assert!(
            first.starts_with("error:") && first.contains(needle),
            "{args:?}: stderr {err:?} lacks {needle:?}"
        );
        assert!(!err.contains("panicked"), "{args:?} panicked: {err}");
        assert!(!summary.exists(), "{args:?} wrote a summary");
    }
}

#[test]
fn summary_json_has_the_stable_keys() {
    let dir = scratch("ok");
    let summary = dir.join("s.json");
    let (code, out, err) = platefall(&[
        "static",
        "--resolution",
        "8",
        "--t-end",
        "1",
        "--no-save",
        "--progress",
        "off",
        "--summary",
        summary.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("status completed"), "{out}");
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&summary).unwrap()).unwrap();
    for key in [
        "case",
        "re",
        "resolution",
        "cells",
        "steps",
        "t_end",
        "wall_seconds",
        "mean_cl",
        "mean_cd",
        "mean_cm",
        "max_cl",
        "min_cl",
        "max_cd",
        "strouhal_chord",
        "strouhal_width",
        "mean_speed",
        "mean_omega",
        "mean_gamma",
        "revolutions",
        "autorotation_time",
        "mean_speed_ft_s",
        "mean_omega_rad_s",
    ] {
        assert!(v.get(key).is_some(), "summary lacks {key}: {v}");
    }
    assert_eq!(v["case"], "static");
    assert!(v["steps"].as_u64().unwrap() > 0);
    assert!(v["t_end"].as_f64().unwrap() >= 1.0 - 1e-9);
}
