//! `platefall converge` end to end on a tiny static case (N = 8, 12, 16): the study is complete
//! and consistent with the levels' own summaries, a rerun runs nothing again, `collect` rewrites
//! the same study, and bad options are refused with one line and exit 2 before anything is
//! written.
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use serde_json::Value;

fn platefall() -> Command {
    Command::new(env!("CARGO_BIN_EXE_platefall"))
}

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("platefall-converge-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The study's command: three resolutions of a short static run at Re 500 in a small domain,
/// with a plate of fixed thickness (2, 3, 4 cells).
fn study(out: &Path, refine: &str, case: &[&str]) -> Output {
    platefall()
        .args(["converge", "--refine", refine, "--output"])
        .arg(out)
        .args(["--jobs", "2", "--threads", "1", "--progress", "off", "--"])
        .args(case)
        .output()
        .expect("binary runs")
}

const CASE: [&str; 9] = [
    "static",
    "--t-end",
    "40",
    "--re",
    "500",
    "--extent",
    "6",
    "--thickness",
    "0.25",
];

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

fn json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).expect("file exists")).unwrap()
}

#[test]
fn a_three_level_study_is_complete_consistent_and_resumable() {
    let dir = scratch("study");
    let out = dir.join("out");
    let o = study(&out, "resolution=8,12,16", &CASE);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}{}",
        text(&o.stdout),
        text(&o.stderr)
    );
    let s = json(&out.join("convergence.json"));
    assert_eq!(s["refined"], "resolution");
    assert_eq!(s["safety_factor"], 1.25);
    assert_eq!(s["completed"], 3);
    let levels = s["levels"].as_array().unwrap();
    let hs: Vec<f64> = levels.iter().map(|l| l["h"].as_f64().unwrap()).collect();
    assert_eq!(
        hs,
        vec![1.0 / 8.0, 1.0 / 12.0, 1.0 / 16.0],
        "coarsest first"
    );
    // Each level's values in the study are its own summary's.
    let summaries: Vec<Value> = levels
        .iter()
        .map(|l| {
            assert_eq!(l["status"], "completed");
            json(&out.join(l["summary"].as_str().unwrap()))
        })
        .collect();
    let quantities = s["quantities"].as_array().unwrap();
    let keys: Vec<&str> = quantities
        .iter()
        .map(|q| q["key"].as_str().unwrap())
        .collect();
    for k in ["mean_cl", "mean_cd", "mean_cm"] {
        assert!(keys.contains(&k), "{k} in {keys:?}");
    }
    let statuses = [
        "monotone_convergence",
        "monotone_divergence",
        "oscillatory_convergence",
        "oscillatory_divergence",
        "not_resolved_by_the_noise",
        "identical",
        "indeterminate",
        "no_refinement",
    ];
    for q in quantities {
        let key = q["key"].as_str().unwrap();
        for (i, sum) in summaries.iter().enumerate() {
            assert_eq!(q["values"][i], sum[key], "{key} level {i}");
            assert_eq!(
                q["half_widths"][i],
                sum[format!("{key}_ci95")],
                "{key} level {i}"
            );
        }
        let triples = q["triples"].as_array().unwrap();
        assert_eq!(triples.len(), 1, "{key}");
        let t = &triples[0];
        let status = t["status"].as_str().unwrap();
        assert!(statuses.contains(&status), "{key}: {status}");
        // The triple is the finest three, finest first.
        let f: Vec<f64> = (0..3).map(|i| t["values"][i].as_f64().unwrap()).collect();
        assert_eq!(f[0], q["values"][2].as_f64().unwrap());
        assert_eq!(f[2], q["values"][0].as_f64().unwrap());
        assert!((t["r21"].as_f64().unwrap() - 4.0 / 3.0).abs() < 1e-12);
        assert!((t["r32"].as_f64().unwrap() - 1.5).abs() < 1e-12);
        if status == "monotone_convergence" {
            // The extrapolation and the GCI follow from the order as the formulas say.
            let p = t["order"].as_f64().unwrap();
            let rp = (4.0_f64 / 3.0).powf(p);
            let ext = (rp * f[0] - f[1]) / (rp - 1.0);
            assert!((t["extrapolated"].as_f64().unwrap() - ext).abs() < 1e-9 * ext.abs().max(1.0));
            let gci = 1.25 * (f[0] - f[1]).abs() / (rp - 1.0);
            assert!((t["gci_fine_abs"].as_f64().unwrap() - gci).abs() < 1e-12 * gci.max(1.0));
        } else {
            assert!(
                t["order"].is_null() && t["extrapolated"].is_null(),
                "{key}: {t}"
            );
            assert!(!t["note"].as_str().unwrap().is_empty());
        }
        if status == "not_resolved_by_the_noise" {
            let n21 = t["noise21"].as_f64().unwrap();
            let n32 = t["noise32"].as_f64().unwrap();
            let e21 = t["eps21"].as_f64().unwrap().abs();
            let e32 = t["eps32"].as_f64().unwrap().abs();
            assert!(e21 <= n21 || e32 <= n32, "{key}: {t}");
        }
    }
    // The table: one row per quantity, a column per level; the sweep's table has the
    // half-widths as columns and leaves the nested details out.
    let md = std::fs::read_to_string(out.join("convergence.md")).unwrap();
    for k in &keys {
        assert!(md.contains(&format!("| {k} |")), "{k} row in\n{md}");
    }
    assert!(md.contains("N = 8") && md.contains("N = 16"), "{md}");
    let csv = std::fs::read_to_string(out.join("results.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    assert!(header.contains(&"mean_cl_ci95") && header.contains(&"ci_batches"));
    assert!(!header.contains(&"intervals"), "{header:?}");

    // A rerun runs nothing again and writes the same study.
    let o = study(&out, "resolution=8,12,16", &CASE);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(
        text(&o.stderr).contains("3 already done"),
        "{}",
        text(&o.stderr)
    );
    for l in levels {
        let id = l["id"].as_str().unwrap();
        let log = std::fs::read_to_string(out.join("cases").join(id).join("log.txt")).unwrap();
        assert!(!log.contains("attempt 2"), "{id} was run again");
    }
    let again = json(&out.join("convergence.json"));
    assert_eq!(again, s);
    // `collect` rewrites it from the finished levels.
    std::fs::remove_file(out.join("convergence.json")).unwrap();
    let o = platefall()
        .args(["converge", "collect"])
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert_eq!(json(&out.join("convergence.json")), s);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_options_are_refused_with_one_line_before_anything_is_written() {
    let dir = scratch("bad");
    let out = dir.join("out");
    let cases: [(&str, &[&str], &str); 6] = [
        ("resolution=8,12", &CASE, "accepted 3 or more"),
        ("resolution=8,12,12", &CASE, "given twice"),
        ("alpha=0.1,0.2,0.3", &CASE, "not a refinable option"),
        (
            "resolution=8,12,16",
            &["static", "--resolution", "8"],
            "refined option",
        ),
        ("resolution=8,12,16", &["hover"], "not a case"),
        (
            "resolution=8,12,2",
            &["static", "--t-end", "1"],
            "resolution",
        ),
    ];
    for (refine, case, needle) in cases {
        let o = study(&out, refine, case);
        let err = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{refine} {case:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{refine} {case:?}: {err}");
        assert!(err.contains(needle), "{refine} {case:?}: {err}");
        assert!(!out.exists(), "{refine} {case:?} wrote {}", out.display());
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// An ensemble directory as `platefall ensemble` leaves it, with one pooled quantity: its
/// pooled mean and half-width, `done` of `members` completed, and the first member's summary.
fn pooled_ensemble(dir: &Path, mean: f64, half_width: f64, done: usize, members: usize) {
    let ids: Vec<String> = (0..members).map(|k| format!("m{k:03}")).collect();
    let pooled = serde_json::json!({
        "members": ids.iter().map(|id| serde_json::json!({"id": id, "perturbation": 1e-6}))
            .collect::<Vec<_>>(),
        "completed": ids[..done],
        "quantities": {"mean_omega": {"mean": mean, "half_width": half_width, "members": done}},
    });
    std::fs::create_dir_all(dir.join("cases/m000")).unwrap();
    std::fs::write(dir.join("ensemble.json"), pooled.to_string()).unwrap();
    let member = serde_json::json!({"cells": 1000, "steps": 400, "t_end": 20.0});
    std::fs::write(dir.join("cases/m000/summary.json"), member.to_string()).unwrap();
}

/// The study of the ensembles `dirs` (comma-separated) at N = 16, 32, 64, written to `out`.
fn of_ensembles(dirs: &str, out: &Path) -> Output {
    platefall()
        .args([
            "converge",
            "--refine",
            "resolution=16,32,64",
            "--ensembles",
            dirs,
        ])
        .arg("--output")
        .arg(out)
        .output()
        .unwrap()
}

/// `converge --ensembles`: each level is an ensemble's pooled mean with its pooled half-width.
/// Values f(h) = 2 + 3h² at N = 16, 32, 64 give order 2 when the ensembles' half-widths are
/// below the differences (1e-4 against ≥ 7e-4), and "not resolved by the noise" when they are
/// not (0.01); a level whose ensemble is unfinished is left out, and a wrong count of
/// directories or one without `ensemble.json` is refused in one line before anything is written.
#[test]
fn ensembles_as_levels_decide_with_their_pooled_intervals() {
    let dir = scratch("ensembles");
    let f = |n: f64| 2.0 + 3.0 / (n * n);
    let run = |hw: f64, name: &str| {
        let dirs: Vec<String> = [16.0, 32.0, 64.0]
            .iter()
            .map(|&n| {
                let d = dir.join(format!("{name}-{n}"));
                pooled_ensemble(&d, f(n), hw, 8, 8);
                d.to_string_lossy().into_owned()
            })
            .collect();
        let out = dir.join(format!("study-{name}"));
        let o = of_ensembles(&dirs.join(","), &out);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
        (json(&out.join("convergence.json")), dirs)
    };
    let (tight, dirs) = run(1e-4, "tight");
    let levels = tight["levels"].as_array().unwrap();
    assert!(levels
        .iter()
        .all(|l| l["status"] == "completed" && l["ci_batches"] == 8));
    assert_eq!(levels[0]["h"], 1.0 / 16.0);
    let t = &tight["quantities"][0]["triples"][0];
    assert_eq!(t["status"], "monotone_convergence", "{t}");
    assert!((t["order"].as_f64().unwrap() - 2.0).abs() < 1e-9, "{t}");
    let (wide, _) = run(0.01, "wide");
    let t = &wide["quantities"][0]["triples"][0];
    assert_eq!(t["status"], "not_resolved_by_the_noise", "{t}");
    // One level unfinished (5 of 8 members): left out, and said so.
    pooled_ensemble(Path::new(&dirs[1]), f(32.0), 1e-4, 5, 8);
    let out = dir.join("study-partial");
    let o = of_ensembles(&dirs.join(","), &out);
    assert_eq!(o.status.code(), Some(3), "{}", text(&o.stderr));
    let partial = json(&out.join("convergence.json"));
    assert_eq!(partial["levels"][1]["status"], "unfinished");
    assert_eq!(partial["completed"], 2);
    for (list, needle) in [
        (dirs[..2].join(","), "2 directories for 3 levels"),
        (
            format!("{},{},{}", dirs[0], dirs[1], dir.join("none").display()),
            "holds no ensemble.json",
        ),
    ] {
        let out = dir.join("refused");
        let o = of_ensembles(&list, &out);
        let err = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(err.contains(needle), "{err}");
        assert!(!out.exists());
    }
    let _ = std::fs::remove_dir_all(&dir);
}
