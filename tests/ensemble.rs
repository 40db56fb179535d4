//! `platefall ensemble` end to end on a tiny case (the card at N = 16, spun up to one turn,
//! three members of two more turns): the members branch from the spun-up state with their own
//! perturbations, their means are pooled into `ensemble.json`, the same command goes on with
//! only the missing members (reproducibly: a member run again is byte for byte the same), and
//! bad requests are refused with one line and exit code 2 before anything runs; `ensemble.rrd`
//! overlays every member and `histograms.png` draws their means.
mod checkpoint_common;
mod record_common;

use std::path::Path;

use checkpoint_common::*;

/// The spun-up run: the card at N = 16 released at t = 1, to one turn, with its checkpoint
/// and CSV.
fn spun_up(dir: &Path) {
    let args = [
        "free",
        "--resolution",
        "16",
        "--develop",
        "1",
        "--turns",
        "1",
        "--checkpoint",
        "spin.ckpt",
        "--csv",
        "spin.csv",
        "--no-save",
        "-q",
        "--progress",
        "off",
    ];
    expect_code(&run(dir, &args), 0);
}

/// `ensemble` of the spun-up run into `out` with `extra` options.
fn ensemble(dir: &Path, out: &str, extra: &[&str]) -> std::process::Output {
    let mut args = vec!["ensemble", "--from", "spin.ckpt", "--output", out];
    args.extend(["--turns", "3", "--average-from-turn", "2", "--jobs", "2"]);
    args.extend(["--progress", "off"]);
    args.extend(extra);
    run(dir, &args)
}

/// The pooled JSON.
fn pooled(dir: &Path) -> serde_json::Value {
    serde_json::from_slice(&read(dir, "ens/ensemble.json")).unwrap()
}

/// The ensemble's recording holds every member's path, portrait and θ̇ series (with the
/// viewer built; without it there is no recording).
fn assert_overlaid(rrd: &Path, ids: &[&str]) {
    if !cfg!(feature = "viewer") {
        assert!(!rrd.exists());
        return;
    }
    let d = record_common::decode(rrd);
    assert!(
        d.has_footer && d.has_blueprint,
        "a complete file with its layout"
    );
    for id in ids {
        for path in [
            format!("/paths/members/{id}"),
            format!("/portraits/members/{id}"),
        ] {
            assert!(d.statics.contains(&path), "{path}: {:?}", d.statics);
        }
        let rows = d.rows.get(&format!("/omega/{id}")).copied().unwrap_or(0);
        assert!(rows > 100, "{id}: {rows} rows of θ̇");
    }
    assert!(d.statics.contains(&"/table".to_string()));
}

/// `histograms.png` is a 1280 × 720 picture and `histograms.svg` draws the members' means of
/// dθ/dt, V and γ.
fn assert_histograms(dir: &Path, members: usize) {
    let png = read(dir, "ens/histograms.png");
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    let be = |b: &[u8]| u32::from_be_bytes([b[0], b[1], b[2], b[3]]);
    assert_eq!((be(&png[16..20]), be(&png[20..24])), (1280, 720));
    let svg = String::from_utf8(read(dir, "ens/histograms.svg")).unwrap();
    assert!(svg.contains(&format!("The means of {members} members")));
    for label in [
        "mean dθ/dt (rad per c/U)",
        "mean speed V (U)",
        "mean flight-path angle γ (rad)",
    ] {
        assert!(svg.contains(label), "{label} missing from histograms.svg");
    }
}

#[test]
fn members_branch_are_pooled_and_resume() {
    let dir = scratch("ensemble");
    spun_up(&dir);
    let three = ["--members", "3", "--perturbation", "1e-2", "--seed", "5"];
    expect_code(&ensemble(&dir, "ens", &three), 0);
    let p = pooled(&dir);
    assert_eq!(p["completed"].as_array().unwrap().len(), 3, "{p}");
    let w = &p["quantities"]["mean_omega"];
    let means: Vec<f64> = w["member_means"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    // Three members, each its own run: distinct means, pooled into their average with a
    // positive half-width.
    assert_eq!(means.len(), 3);
    assert!(means[0] != means[1] && means[1] != means[2] && means[0] != means[2]);
    let avg = means.iter().sum::<f64>() / 3.0;
    assert!((w["mean"].as_f64().unwrap() - avg).abs() < 1e-12, "{w}");
    assert!(w["half_width"].as_f64().unwrap() > 0.0 && w["members"] == 3);
    // Two turns after the branch the members have not parted (a chaotic separation takes tens
    // of c/U to grow from 10⁻²): measured from their θ̇, not assumed, and said so.
    let parting = &p["parting"];
    assert!(
        parting["time"].is_null() && parting["independent"] == false,
        "{parting}"
    );
    let (start, branch) = (parting["window_start"].as_f64(), p["branch"]["t"].as_f64());
    assert!(start.unwrap() > branch.unwrap(), "{p}");
    // Every member's CSV holds the spun-up run's rows first, then its own.
    let spin = read(&dir, "spin.csv");
    let body = |b: &[u8]| {
        let text = String::from_utf8(b.to_vec()).unwrap();
        text.lines()
            .filter(|l| !l.starts_with('#'))
            .map(String::from)
            .collect::<Vec<_>>()
    };
    let spin_rows = body(&spin);
    let m0 = read(&dir, "ens/cases/m000/run.csv");
    assert_eq!(body(&m0)[..spin_rows.len()], spin_rows[..]);
    assert!(body(&m0).len() > spin_rows.len() + 100);
    assert_overlaid(&dir.join("ens/ensemble.rrd"), &["m000", "m001", "m002"]);
    assert_histograms(&dir, 3);
    // The same command again runs nothing; with one member gone (as if it never ran), it runs
    // that one alone, byte for byte as before (its perturbation comes from the seed).
    let summaries = read(&dir, "ens/cases/m002/summary.json");
    let m1 = read(&dir, "ens/cases/m001/run.csv");
    let out = ensemble(&dir, "ens", &three);
    expect_code(&out, 0);
    assert!(String::from_utf8_lossy(&out.stderr).contains("(3 already done); running 0"));
    std::fs::remove_dir_all(dir.join("ens/cases/m001")).unwrap();
    let out = ensemble(&dir, "ens", &three);
    expect_code(&out, 0);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("(2 already done); running 1"), "{err}");
    assert!(read(&dir, "ens/cases/m001/run.csv") == m1);
    assert!(read(&dir, "ens/cases/m002/summary.json") == summaries);
    assert_eq!(pooled(&dir)["quantities"]["mean_omega"], *w);
    // `platefall sweep collect` reads a plan: it sends the user back here.
    let out = run(&dir, &["sweep", "collect", "ens"]);
    expect_one_line_error(&out, "was made by `platefall ensemble`");
    as_slurm_array(&dir, &three);
    let _ = std::fs::remove_dir_all(&dir);
}

/// The members of `ens` (made with `members`) as a Slurm job array in `slm`, without Slurm:
/// `--slurm` writes the script and runs nothing; each task's command (`sweep run-case DIR
/// INDEX`) runs that member byte for byte as the local ensemble did; the script then holds only
/// the members not done, and once all are done the same command pools them as the local one.
fn as_slurm_array(dir: &Path, members: &[&str]) {
    let slurm = |extra: &[&str]| {
        let mut args = vec!["ensemble", "--from", "spin.ckpt", "--output", "slm"];
        args.extend([
            "--turns",
            "3",
            "--average-from-turn",
            "2",
            "--progress",
            "off",
        ]);
        args.extend(members);
        args.extend(["--slurm", "--time", "00:10:00"]);
        args.extend(extra);
        run(dir, &args)
    };
    let out = slurm(&[]);
    expect_code(&out, 0);
    let script = String::from_utf8(read(dir, "slm/sweep.sbatch")).unwrap();
    let slm = std::path::absolute(dir.join("slm")).unwrap();
    assert!(script.contains("#SBATCH --array=0-2\n"), "{script}");
    assert!(script.contains("#SBATCH --time=00:10:00\n"), "{script}");
    let task = format!("sweep run-case {} \"$SLURM_ARRAY_TASK_ID\"", slm.display());
    assert!(script.contains(&task), "{script}");
    assert!(
        !dir.join("slm/cases/m000/summary.json").exists(),
        "nothing ran"
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("sbatch ")
            && stdout.contains("run this `platefall ensemble` command again"),
        "{stdout}"
    );
    // A task's command, as the array runs it.
    expect_code(&run(dir, &["sweep", "run-case", "slm", "1"]), 0);
    let member = |d: &str, id: &str| read(dir, &format!("{d}/cases/{id}/run.csv"));
    assert!(
        member("slm", "m001") == member("ens", "m001"),
        "m001 as a task differs"
    );
    expect_code(&slurm(&[]), 0);
    let script = String::from_utf8(read(dir, "slm/sweep.sbatch")).unwrap();
    assert!(script.contains("#SBATCH --array=0,2\n"), "{script}");
    for k in ["0", "2"] {
        expect_code(&run(dir, &["sweep", "run-case", "slm", k]), 0);
    }
    expect_code(&slurm(&[]), 0);
    let pooled_in = |d: &str| -> serde_json::Value {
        serde_json::from_slice(&read(dir, &format!("{d}/ensemble.json"))).unwrap()
    };
    assert_eq!(
        pooled_in("slm")["quantities"],
        pooled_in("ens")["quantities"]
    );
    let out = run(dir, &["sweep", "run-case", "slm", "3"]);
    expect_one_line_error(&out, "case index 3 is out of range: accepted 0..=2");
    // Pooled ensembles are the levels of `converge --ensembles` (here the same ensemble three
    // times: every quantity is the pooled mean at each level, the members its batches).
    let refine = ["converge", "--refine", "resolution=16,17,18"];
    let mut args = refine.to_vec();
    args.extend(["--ensembles", "ens,slm,ens", "--output", "conv"]);
    expect_code(&run(dir, &args), 0);
    let study: serde_json::Value =
        serde_json::from_slice(&read(dir, "conv/convergence.json")).unwrap();
    assert!(study["levels"]
        .as_array()
        .unwrap()
        .iter()
        .all(|l| l["ci_batches"] == 3));
    let omega = study["quantities"]
        .as_array()
        .unwrap()
        .iter()
        .find(|q| q["key"] == "mean_omega")
        .expect("θ̇ in the study");
    let mean = &pooled_in("ens")["quantities"]["mean_omega"]["mean"];
    assert!(
        omega["values"]
            .as_array()
            .unwrap()
            .iter()
            .all(|v| v == mean),
        "{omega}"
    );
}

#[test]
fn bad_ensembles_are_refused_in_one_line_before_anything_runs() {
    let dir = scratch("ensemble-refusals");
    spun_up(&dir);
    for (extra, what) in [
        (
            &["--members", "1", "--perturbation", "1e-3"][..],
            "--members 1",
        ),
        (
            &["--members", "3", "--perturbation", "0"][..],
            "--perturbation 0",
        ),
        (
            &["--members", "3", "--perturbation", "NaN"][..],
            "--perturbation NaN",
        ),
        (
            &["--members", "3", "--perturbation", "1e-3", "--t-end", "2"][..],
            "--t-end 2",
        ),
        (
            &[
                "--members",
                "3",
                "--perturbation",
                "1e-3",
                "--t-end",
                "0.01s",
            ][..],
            "--t-end 0.01s: the branch point is at t = ",
        ),
    ] {
        let out = ensemble(&dir, "bad", extra);
        expect_one_line_error(&out, what);
        assert!(!dir.join("bad").exists(), "{what}: nothing runs");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
