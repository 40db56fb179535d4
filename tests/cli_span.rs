//! `--span` on the command line (docs/three-d.md "Cases"): a periodic span gives the 2-D plate's
//! loads per unit span, a finite span has no side force, roll or yaw by its mirror symmetry in z,
//! the options a 3-D run cannot honour are refused in one line, a 3-D flight writes its CSV
//! and summary, a physical plate (aluminium in water) falls from rest under strong coupling with
//! its derivation and regime stated (and resumes exactly) and a bad span refused, a flight stops
//! after `--turns`, and stopped with a checkpoint and resumed writes the
//! same CSV and summary as the run straight through (docs/three-d.md "On the command line").
use std::path::Path;

mod checkpoint_common;
mod cli_common;
use checkpoint_common::{assert_same_outputs, run_full, run_stopped, FLIGHT};
use cli_common::{platefall, scratch};

/// The CSV's header and its data rows (the trailer skipped).
fn table(path: &Path) -> (String, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap().to_string();
    let rows = lines
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    (header, rows)
}

/// A short static run on the N = 8 grid (plate 1/8 thick: one cell) with `extra` options.
fn static_run(dir: &Path, name: &str, extra: &[&str]) -> (String, Vec<Vec<f64>>) {
    let csv = dir.join(name);
    let mut args = vec![
        "static",
        "--resolution",
        "8",
        "--t-end",
        "0.5",
        "--extent",
        "3",
        "--growth",
        "1.2",
        "--thickness",
        "0.125",
        "--no-save",
        "--progress",
        "off",
        "--csv",
    ];
    args.push(csv.to_str().unwrap());
    args.extend_from_slice(extra);
    let (code, _, err) = platefall(&args);
    assert_eq!(code, 0, "{err}");
    table(&csv)
}

#[test]
fn a_periodic_span_gives_the_two_dimensional_lift_and_drag_per_unit_span() {
    // The same x–y grid (same --extent and --growth); Re 5000, where the loads are the pressure's:
    // the 3-D solver's flight of the card on such a grid follows the 2-D one within 0.4 %
    // (docs/three-d.md "Free flight"), so 1 % is the tolerance. (At Re 200 the viscous drag of
    // the two solvers' wall stencils differs by 5 % on this one-cell-thick plate.)
    let dir = scratch("periodic");
    let (_, two) = static_run(&dir, "two.csv", &[]);
    let (_, three) = static_run(&dir, "three.csv", &["--span", "periodic:0.25"]);
    let (a, b) = (two.last().unwrap(), three.last().unwrap());
    assert!((a[0] - 0.5).abs() < 1e-12 && (b[0] - 0.5).abs() < 1e-12);
    let (lift, drag) = ((b[3] / a[3] - 1.0).abs(), (b[4] / a[4] - 1.0).abs());
    println!(
        "t = 0.5: C_L {} against {}, C_D {} against {}",
        b[3], a[3], b[4], a[4]
    );
    assert!(lift < 0.01 && drag < 0.01, "lift {lift:.4}, drag {drag:.4}");
}

#[test]
fn a_finite_span_has_no_side_force_roll_or_yaw() {
    let dir = scratch("finite");
    let (header, rows) = static_run(&dir, "fin.csv", &["--span", "1", "--re", "200"]);
    assert_eq!(
        header,
        "time [c/U],step,dt [c/U],C_L,C_D,C_S,C_roll,C_yaw,C_pitch,theta [rad],\
         thetadot [U/c],iterations,divergence [U/c]"
    );
    let largest = rows
        .iter()
        .map(|r| r[5].abs().max(r[6].abs()).max(r[7].abs()) / (1.0 + r[3].abs() + r[4].abs()))
        .fold(0.0, f64::max);
    println!("largest |C_S|, |C_roll|, |C_yaw| on 1 + |C_L| + |C_D|: {largest:.2e}");
    assert!(
        rows.iter().all(|r| r[3] > 0.1),
        "the plate at α = 0.4 lifts"
    );
    // Mirror symmetry about z = 0: zero up to the pressure solve's tolerance.
    assert!(largest < 1e-8, "{largest}");
}

#[test]
fn options_a_three_dimensional_run_cannot_honour_are_refused_in_one_line() {
    let cases: [(&[&str], &str); 3] = [
        (&["static", "--span", "2", "--shape", "rounded"], "--shape"),
        (&["pinned", "--span", "2"], "pinned --span"),
        (&["free", "--span", "2", "--mass", "1"], "--mass"),
    ];
    for (args, flag) in cases {
        let (code, out, err) = platefall(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(flag) && err.contains("3-D"), "{args:?}: {err}");
        assert!(out.is_empty());
    }
    let (code, _, err) = platefall(&["static", "--span", "periodic:-1"]);
    assert_eq!(code, 2);
    assert!(err.contains("> 0"), "{err}");
    // The curved bodies (docs/three-d.md "Bodies"): a sphere is one chord across, the bodies of
    // three dimensions need a span, and they end within a periodic one.
    let refused: [(&[&str], &str); 3] = [
        (&["static", "--shape", "sphere", "--span", "2"], "--span 1"),
        (&["static", "--shape", "disk"], "give --span"),
        (
            &["static", "--shape", "ellipsoid", "--span", "periodic:1"],
            "periodic",
        ),
    ];
    for (args, says) in refused {
        let (code, out, err) = platefall(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err}");
        assert!(out.is_empty());
    }
}

#[test]
fn a_periodic_flight_writes_its_csv_summary_and_recording() {
    let dir = scratch("free");
    let (csv, json, rrd) = (dir.join("f.csv"), dir.join("f.json"), dir.join("f.rrd"));
    // Without the viewer feature the run cannot record; the rest of the test still holds.
    let save: &[&str] = if cfg!(feature = "viewer") {
        &["--save", rrd.to_str().unwrap()]
    } else {
        &["--no-save"]
    };
    let args = [
        &[
            "free",
            "--span",
            "periodic:0.25",
            "--resolution",
            "8",
            "--t-end",
            "0.3",
            "--develop",
            "0.1",
            "--extent",
            "3",
            "--progress",
            "off",
            "--field-every",
            "0.1",
        ][..],
        &tables(&csv, &json),
        save,
    ]
    .concat();
    let (code, out, err) = platefall(&args);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("cells"), "{err}");
    for listed in [
        format!("summary: {}", json.display()),
        format!("csv: {} (", csv.display()),
    ] {
        assert!(
            err.lines().any(|l| l.starts_with(&listed)),
            "{listed}: {err}"
        );
    }
    if cfg!(feature = "viewer") {
        assert!(err.contains("recording: "), "{err}");
        assert!(std::fs::metadata(&rrd).unwrap().len() > 1000);
    }
    assert!(out.contains("attitude"), "{out}");
    let (header, rows) = table(&csv);
    assert!(header.starts_with("time [c/U],step,dt [c/U],X [c],Y [c],Z [c]"));
    assert_eq!(header.split(',').count(), rows[0].len());
    let last = rows.last().unwrap();
    assert!((last[0] - 0.3).abs() < 1e-9);
    // Planar flight: no sideways motion, the span stays horizontal.
    assert!(rows
        .iter()
        .all(|r| r[5] == 0.0 && r[8] == 0.0 && r[15] == 0.0));
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(s["case"], "free");
    assert_eq!(s["max_abs_span_y"], 0.0);
    assert!(s["cells_3d"].as_u64().unwrap() > 0 && s["mean_speed"].as_f64().unwrap() > 0.5);
}

#[test]
fn a_flight_stopped_with_checkpoints_and_resumed_writes_the_uninterrupted_runs_outputs() {
    // Stopped in the hold (step 5), after the release (23) and again (31), resumed each time
    // with one and two threads: the CSV byte for byte, the summary but for the wall time.
    let dir = checkpoint_common::scratch("span-flight");
    let flight = [&FLIGHT[..], &["--t-end", "0.4"]].concat();
    run_full(&dir, &flight);
    run_stopped(&dir, &flight, "0.1", &[5, 23, 31], &["1", "2"]);
    assert_same_outputs(&dir);
}

#[test]
fn a_flight_stops_after_its_turns() {
    let dir = scratch("turns");
    let csv = dir.join("t.csv");
    let args = [
        &FLIGHT[..],
        &["--t-end", "3", "--turns", "0.05", "--no-save"],
    ]
    .concat();
    let (code, _, err) = platefall(&[&args[..], &["--csv", csv.to_str().unwrap()]].concat());
    assert_eq!(code, 0, "{err}");
    let (_, rows) = table(&csv);
    // Pitch (column 11) from the first step after the release at t = 0.1.
    let released = rows.iter().find(|r| r[0] >= 0.1 - 1e-9).unwrap()[11];
    let turned = |r: &Vec<f64>| (r[11] - released).abs() / std::f64::consts::TAU;
    let (last, before) = (&rows[rows.len() - 1], &rows[rows.len() - 2]);
    assert!(last[0] < 2.9, "stopped before t_end: t = {}", last[0]);
    assert!(
        turned(last) >= 0.05 && turned(before) < 0.05,
        "{}",
        turned(last)
    );
}

#[test]
fn a_static_run_writes_its_vtk_series() {
    let dir = scratch("vtk");
    let vtk = dir.join("vtk");
    let (code, _, err) = platefall(&[
        "static",
        "--span",
        "1",
        "--resolution",
        "6",
        "--extent",
        "2",
        "--t-end",
        "0.3",
        "--no-save",
        "--progress",
        "off",
        "--vtk",
        vtk.to_str().unwrap(),
        "--vtk-every",
        "0.1",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("VTK: "), "{err}");
    let pvd = std::fs::read_to_string(vtk.join("run.pvd")).unwrap();
    let listed = pvd.matches("<DataSet").count();
    // Snapshots at the first step and every 0.1 after it, up to t = 0.3.
    assert!((3..=4).contains(&listed), "{pvd}");
    for k in 0..listed {
        let vts = std::fs::read(vtk.join(format!("flow-{k:06}.vts"))).unwrap();
        assert!(vts.starts_with(b"<?xml") && vts.len() > 1000);
    }
}

/// `--csv CSV --summary JSON`.
fn tables<'a>(csv: &'a std::path::Path, json: &'a std::path::Path) -> [&'a str; 4] {
    let text = |p: &'a std::path::Path| p.to_str().unwrap();
    ["--csv", text(csv), "--summary", text(json)]
}

/// A thin aluminium plate in water, chord 16 mm, thickness 0.5 mm, released from rest at
/// θ₀ = 0.1 on the N = 6 grid, with `extra` options.
fn aluminium<'a>(extra: &[&'a str]) -> Vec<&'a str> {
    let plate = "free --chord-mm 16 --thickness-mm 0.5 --plate-density 2700 --fluid water \
                 --theta0 0.1 --resolution 6 --extent 2";
    plate
        .split_whitespace()
        .chain(extra.iter().copied())
        .collect()
}

#[test]
fn a_physical_aluminium_plate_in_water_falls_from_rest_and_states_its_derivation() {
    let dir = scratch("aluminium");
    let (csv, json) = (dir.join("a.csv"), dir.join("a.json"));
    let options = [
        &[
            "--no-save",
            "--span",
            "2",
            "--span-mm",
            "32",
            "--t-end",
            "0.3",
            "--progress",
            "off",
        ][..],
        &tables(&csv, &json),
    ]
    .concat();
    let (code, out, err) = platefall(&aluminium(&options));
    assert_eq!(code, 0, "{err}");
    // U = √(1.7049 g t) = 9.1446 cm/s, Re = U c/ν; per chord of span the 2-D m*, m_f*, I*.
    for derived in [
        "U = √(|ρs/ρf − 1| g t)",
        "= 9.1446 cm/s",
        "Re = U c/ν = 1457.6",
        "span b = 32 mm = 2.0000 c",
        "(t/c)(b/c) = 0.1691; m_f* = (t/c)(b/c) = 0.0625",
        "the span m*(1 + (t/c)²)/12 = 0.01410",
    ] {
        assert!(err.contains(derived), "{derived}: {err}");
    }
    assert!(
        out.contains("from rest") && out.contains("regime "),
        "{out}"
    );
    let (header, rows) = table(&csv);
    assert!(header.starts_with("time [c/U],step,dt [c/U],X [c],Y [c]"));
    assert!(rows.iter().flatten().all(|x| x.is_finite()));
    let (first, last) = (&rows[0], rows.last().unwrap());
    assert!((last[0] - 0.3).abs() < 1e-9);
    // Heavier than the water it displaces: it sinks from rest.
    assert!(last[4] < first[4] - 0.01, "Y {} -> {}", first[4], last[4]);
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(s["status"], "completed");
    assert!(s["regime"].is_string(), "{s}");
}

#[test]
fn a_physical_plates_flight_stopped_and_resumed_writes_the_uninterrupted_runs_outputs() {
    // The resumed run rebuilds the plate from the checkpoint's command line.
    let dir = checkpoint_common::scratch("span-aluminium");
    let flight = aluminium(&["--span", "2", "--t-end", "0.3", "--progress", "off"]);
    run_full(&dir, &flight);
    run_stopped(&dir, &flight, "0.1", &[12], &["1"]);
    assert_same_outputs(&dir);
}

#[test]
fn a_bad_or_contradicting_span_in_millimetres_is_refused_in_one_line() {
    let cases: [(&[&str], &str); 3] = [
        (&["--span", "2", "--span-mm", "0"], "accepted (0, 10000]"),
        (&["--span", "2", "--span-mm", "-5"], "accepted (0, 10000]"),
        (&["--span", "periodic:2", "--span-mm", "30"], "--span 1.875"),
    ];
    for (extra, says) in cases {
        let (code, out, err) = platefall(&aluminium(&[extra, &["--no-save"]].concat()));
        assert_eq!(code, 2, "{extra:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{extra:?}: {err}");
        assert!(
            err.contains("--span-mm") && err.contains(says),
            "{extra:?}: {err}"
        );
        assert!(out.is_empty());
    }
}
