//! The binary as a user meets it: bad input is refused with one clear line and exit code 2, with
//! nothing written; a good run writes the summary JSON with its stable keys.

mod cli_common;
use cli_common::{platefall, scratch};

#[test]
fn bad_values_are_refused_naming_the_value_and_range() {
    let dir = scratch("bad");
    let summary = dir.join("s.json");
    let s = summary.to_str().unwrap();
    // Arguments separated by spaces; a physical plate's three inputs are PLATE.
    const PLATE: &str = "free --chord-mm 10 --thickness-mm 1 --plate-density 2700";
    let cases: Vec<(String, String)> = [
        ("static --re -5", "-5"),
        ("static --re 0", "(0, 100000]"),
        ("static --resolution 0", "4..=1024"),
        // Negative whole numbers are values, refused by name (not "unexpected argument").
        ("static --resolution -16", "'-16' for '--resolution"),
        (
            "static --t-end 3s",
            "seconds need a plate with physical units",
        ),
        ("free --t-end 10m", "or of seconds (10.5s)"),
        (
            "free --threads -1",
            "-1 is negative: accepted a whole number, 0 or more",
        ),
        (
            "ensemble --from x.ckpt --members -3 --perturbation 1e-6 --output o",
            "'-3' for '--members",
        ),
        ("static --alpha NaN", "NaN"),
        ("static --alpha 4", "[-3.14"),
        ("static --t-end -1", "--t-end"),
        ("forced --rate 0", "--rate"),
        ("free --mass 0", "(0, 1000000]"),
        ("free --inertia -0.1", "--inertia"),
        ("pinned --preset none", "--mass"),
        ("free --ab-order 7", "1..=6"),
        ("free --average-from-turn 0", "--average-from-turn 0"),
        ("free --turns 20 --average-from-turn 20", "accepted 1..=19"),
        ("free --displaced-mass -1", "[0, 1000000]"),
        ("pinned --torque 1e9", "[-1000, 1000]"),
        ("pinned --v0 -1", "[0, 10]"),
        ("free --coupling implicit", "implicit"),
        ("free --chord-mm 10", "the following required"),
        ("free --fluid air", "the following required"),
        (
            "free --chord-mm 0 --thickness-mm 1 --plate-density 2700",
            "(0, 10000]",
        ),
        (
            "free --chord-mm 10 --thickness-mm 12 --plate-density 2700",
            "(0, 10]",
        ),
        (
            "static --thickness 0",
            "--thickness: thickness 0 is out of range: accepted (0, 1]",
        ),
        ("static --thickness 1.5", "accepted (0, 1]"),
        (
            "static --shape rounded --thickness 0.1 --edge-radius 0.06",
            "--edge-radius: edge radius 0.06 is out of range: accepted (0, 0.05]",
        ),
        (
            "static --shape naca00x2",
            "is not a NACA four-digit section",
        ),
        (
            "static --shape naca2012",
            "is not a NACA four-digit section",
        ),
        ("static --shape hexagon", "`hexagon` is not a shape"),
        (
            "static --edge-radius 0.01",
            "--edge-radius only goes with --shape rounded",
        ),
        (
            "static --shape circle --thickness 0.1",
            "--thickness does not go with",
        ),
        (
            "static --shape polygon",
            "--polygon goes with --shape polygon",
        ),
        (
            "free --chord-mm 10 --thickness-mm 1 --plate-density -1",
            "(0, 100000]",
        ),
        ("PLATE --fluid-density 0", "--fluid-density"),
        ("PLATE --viscosity 0", "(0, 1000000]"),
        ("PLATE --g -9.81", "(0, 1000]"),
        (
            "free --chord-mm 1000 --thickness-mm 10 --plate-density 2700 --fluid air",
            "Reynolds number",
        ),
        ("PLATE --mass 1", "cannot be used"),
        (
            "static --near-x 0.2",
            "--near-x 0.2 is out of range: accepted [0.5, 1000]",
        ),
        ("forced --near-y NaN", "--near-y NaN"),
        (
            "static --threads 300",
            "--threads 300 is out of range: accepted 0..=256",
        ),
        ("free --far-field sideways", "sideways"),
        (
            "static --summary /nonexistent-dir/s.json",
            "/nonexistent-dir",
        ),
    ]
    .into_iter()
    .map(|(a, n)| (a.replace("PLATE", PLATE), n.to_string()))
    .collect();
    // --vtk names a directory: not a file, not one that cannot be written (even by root: /proc).
    let file = dir.join("not-a-dir");
    std::fs::write(&file, "x").unwrap();
    let mut cases = cases;
    cases.extend(
        [
            (
                format!("static --vtk {}", file.display()),
                "exists and is not a directory",
            ),
            (
                "static --vtk /proc/self".into(),
                "--vtk /proc/self: directory",
            ),
            ("static --vtk /nonexistent-dir/v".into(), "/nonexistent-dir"),
            (
                format!("static --vtk {} --vtk-every 0", dir.display()),
                "--vtk-every 0: must be",
            ),
            ("static --vtk-every 1".into(), "required arguments"),
        ]
        .map(|(a, n)| (a, n.to_string())),
    );
    // A port this test holds, so that it is busy while the cases run.
    let held = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    cases.extend(port_cases(held.local_addr().unwrap().port(), free_port()));
    for (line, needle) in &cases {
        let args: Vec<&str> = line.split_whitespace().collect();
        let mut full: Vec<&str> = args.clone();
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

/// A port no one listens on now.
fn free_port() -> u16 {
    let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    l.local_addr().unwrap().port()
}

/// Refused --serve and --web ports (`busy` is held by the caller, `free` is not): each needs a
/// port of its own, free now, not 0; --web-port only with --web, --web only in a build with it.
fn port_cases(busy: u16, free: u16) -> Vec<(String, String)> {
    let mut cases = vec![(
        format!("static --web-port {free}"),
        format!("--web-port {free} only goes with --web"),
    )];
    if cfg!(feature = "web") {
        cases.extend([
            (
                "static --web --web-port 9876".into(),
                "--web-port 9876: the same port as --port".into(),
            ),
            (
                format!("static --web --port {free} --web-port {busy}"),
                format!("--web-port {busy}: cannot listen on 127.0.0.1:{busy}"),
            ),
            (
                format!("static --web --port {free} --web-port 0"),
                "--web-port 0: must be in 1..=65535".into(),
            ),
            (
                "static --web --port 0".into(),
                "--port 0: must be in 1..=65535".into(),
            ),
        ]);
    } else {
        cases.push((
            "static --web".into(),
            "--web: this platefall was built without the `web` feature".into(),
        ));
    }
    if cfg!(feature = "viewer") {
        cases.push((
            format!("static --serve --port {busy}"),
            format!("--port {busy}: cannot listen on 127.0.0.1:{busy}"),
        ));
        cases.push((
            "static --serve --port 0".into(),
            "--port 0: must be in 1..=65535".into(),
        ));
    }
    cases
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
    // The end-of-run list of outputs names the summary.
    let listed = format!("summary: {}", summary.display());
    assert!(err.lines().any(|l| l == listed), "{err}");
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
        "regime",
        "regime_rule",
        "regime_from",
        "mean_descent_speed",
        "mean_horizontal_speed",
        "descent_angle",
        "period",
        "angle_amplitude",
        "velocity_scale_m_s",
        "chord_m",
        "mean_speed_cm_s",
        "mean_descent_speed_cm_s",
        "mean_horizontal_speed_cm_s",
        "period_s",
        "frequency_hz",
    ] {
        assert!(v.get(key).is_some(), "summary lacks {key}: {v}");
    }
    assert_eq!(v["case"], "static");
    assert!(v["steps"].as_u64().unwrap() > 0);
    assert!(v["t_end"].as_f64().unwrap() >= 1.0 - 1e-9);
}

#[test]
fn a_physical_plate_prints_its_derivation_and_reports_in_physical_units() {
    let (code, err, v) = run_with_summary(
        "physical",
        &[
            "free",
            "--chord-mm",
            "10",
            "--thickness-mm",
            "0.5",
            "--plate-density",
            "2700",
            "--resolution",
            "8",
            "--t-end",
            "0.055s",
        ],
    );
    assert_eq!(code, 0, "{err}");
    for line in [
        "U = √(|ρs/ρf − 1| g t)",
        "Re = U c/ν = 911.0",
        "m_f* = t/c = 0.0500",
        "weight (m* − m_f*) g* = +1.0000 (sinks)",
        "section: rectangle t/c = 0.05 (exact at every N)",
    ] {
        assert!(err.contains(line), "stderr lacks {line:?}: {err}");
    }
    assert!((v["velocity_scale_m_s"].as_f64().unwrap() - 0.09145).abs() < 1e-4);
    assert!((v["re"].as_f64().unwrap() - 911.0).abs() < 0.5);
    assert!(v["regime"].is_string(), "{v}");
    // The end in seconds is t_end c/U: 0.055 s on a 10 mm chord at U ≈ 9.1 cm/s, about 0.5 c/U.
    let (u, t_end) = (
        v["velocity_scale_m_s"].as_f64().unwrap(),
        v["t_end"].as_f64().unwrap(),
    );
    assert!(
        (t_end - 0.055 * u / 0.010).abs() < 1e-9,
        "t_end {t_end} c/U"
    );
}

/// A thin ellipse's tips (radius of curvature b²/a = t²/2 = c/128 at t/c = 1/8) are a quarter
/// of a cell at N = 32: the run says so before it starts, and from N = 64 (half a cell) it does
/// not. A rectangle's corners are corners: no note.
#[test]
fn unresolved_rounded_edges_are_noted_before_the_run() {
    let note = "note: the section's edges have a radius of curvature";
    let ellipse = [
        "static",
        "--shape",
        "ellipse",
        "--thickness",
        "0.125",
        "--t-end",
        "0.05",
    ];
    let at = |n: &str, shape: &[&str]| {
        let args: Vec<&str> = shape.iter().copied().chain(["--resolution", n]).collect();
        let (code, err, _) = run_with_summary(&format!("edge-{n}"), &args);
        assert_eq!(code, 0, "{err}");
        err
    };
    let coarse = at("32", &ellipse);
    assert!(
        coarse.contains(&format!("{note} of 0.0078 c, 0.25 of a cell at N = 32"))
            && coarse.contains("from N = 64 on here"),
        "{coarse}"
    );
    assert!(!at("64", &ellipse).contains(note));
    assert!(!at("16", &["static", "--t-end", "0.05"]).contains(note));
}

/// Runs with `--no-save --progress off --summary` in a scratch directory: exit code, stderr and
/// the summary JSON.
fn run_with_summary(name: &str, args: &[&str]) -> (i32, String, serde_json::Value) {
    let summary = scratch(name).join("s.json");
    let path = summary.to_str().unwrap();
    let tail = ["--no-save", "--progress", "off", "--summary", path];
    let all: Vec<&str> = args.iter().copied().chain(tail).collect();
    let (code, _, err) = platefall(&all);
    let text = std::fs::read_to_string(&summary).unwrap_or_default();
    (code, err, serde_json::from_str(&text).unwrap_or_default())
}

#[test]
fn bad_polygons_are_refused_naming_the_fault() {
    let dir = std::env::temp_dir().join(format!("platefall-polygons-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let cases = [
        ("open", "0 0\n1 0\n1 1\n0 1\n", "is not closed"),
        ("bow", "0 0\n1 1\n1 0\n0 1\n0 0\n", "intersects itself"),
        ("two", "0 0\n1 0\n0 0\n", "at least 3 vertices"),
        ("text", "0 0\n1 zero\n", "line 2 is `1 zero`"),
    ];
    for (name, text, needle) in cases {
        let path = dir.join(format!("{name}.txt"));
        std::fs::write(&path, text).unwrap();
        let p = path.to_string_lossy().into_owned();
        let (code, _, err) =
            platefall(&["static", "--shape", "polygon", "--polygon", &p, "--no-save"]);
        assert_eq!(code, 2, "{name}: exit {code}, stderr {err}");
        let first = err.lines().next().unwrap_or("");
        assert!(
            first.starts_with("error:") && first.contains("--polygon") && first.contains(needle),
            "{name}: stderr {err:?} lacks {needle:?}"
        );
        assert_eq!(err.lines().count(), 1, "{name}: one line, got {err:?}");
    }
    let missing = dir.join("missing.txt").to_string_lossy().into_owned();
    let (code, _, err) = platefall(&[
        "static",
        "--shape",
        "polygon",
        "--polygon",
        &missing,
        "--no-save",
    ]);
    assert!(
        code == 2 && err.contains("--polygon") && err.contains("missing.txt"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_three_dimensional_benchmarks_are_refused_in_one_line() {
    let dir = scratch("bench3");
    let json = dir.join("b.json");
    let j = json.to_str().unwrap();
    let cases = [
        ("--span 0", "span 0 is out of range"),
        ("--span periodic:-1", "span -1 is out of range"),
        ("--span wide", "`wide` is not a span"),
        ("--span 0.1 --resolutions 8", "at least 0.25 chords"),
        ("--span 2.67 --resolutions 600", "over the limit"),
        ("--span 2.67 --card", "cannot be used with"),
    ];
    for (line, needle) in cases {
        let mut args = vec!["bench", "--steps", "1", "--json", j];
        args.extend(line.split_whitespace());
        let (code, _, err) = platefall(&args);
        assert_eq!(code, 2, "{line}: exit {code}, stderr {err}");
        let first = err.lines().next().unwrap_or("");
        assert!(
            first.starts_with("error:") && first.contains(needle),
            "{line}: stderr {err:?} lacks {needle:?}"
        );
        assert!(!err.contains("panicked"), "{line} panicked: {err}");
        assert!(!json.exists(), "{line} wrote {j}");
    }
}
