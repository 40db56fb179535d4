//! `--vtk`: a static case and a free fall at small N write a VTK series whose collection lists
//! exactly the snapshot times, one `.vts` and one `.vtp` each, and whose arrays are the solver's
//! fields (the same run reproduced in-process through the library) to 1e-9. The files are
//! decoded here from their bytes (appended zlib blocks), independently of the writer.
use std::io::Read as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use platefall_core::grid::GridGeometry;
use platefall_core::sim::{FieldSnapshot, Observer, Simulation, StepSample};
use platefall_post::fields::{cell_centres, stream_function_at_nodes, SnapshotFields};
use platefall_record::Cadence;

/// The arrays of one VTK XML file with appended raw zlib data, by name (the points: "").
struct VtkFile {
    arrays: Vec<(String, Vec<u8>)>,
}

impl VtkFile {
    fn read(path: &Path) -> VtkFile {
        let bytes = std::fs::read(path).unwrap();
        let start = find(&bytes, b"<AppendedData encoding=\"raw\">").expect("appended data");
        let text = std::str::from_utf8(&bytes[..start]).unwrap();
        let data = start + find(&bytes[start..], b"_").unwrap() + 1;
        let arrays = text
            .split("<DataArray ")
            .skip(1)
            .map(|tag| {
                let name = attribute(tag, "Name").unwrap_or_default();
                let offset: usize = attribute(tag, "offset").unwrap().parse().unwrap();
                (name, inflate(&bytes[data + offset..]))
            })
            .collect();
        VtkFile { arrays }
    }

    fn raw(&self, name: &str) -> &[u8] {
        let found = self.arrays.iter().find(|(n, _)| n == name);
        &found.unwrap_or_else(|| panic!("no array {name:?}")).1
    }

    fn f64s(&self, name: &str) -> Vec<f64> {
        let raw = self.raw(name).chunks_exact(8);
        raw.map(|b| f64::from_le_bytes(b.try_into().unwrap()))
            .collect()
    }
}

fn find(hay: &[u8], needle: &[u8]) -> Option<usize> {
    hay.windows(needle.len()).position(|w| w == needle)
}

fn attribute(tag: &str, key: &str) -> Option<String> {
    let tag = format!(" {tag}");
    let at = tag.find(&format!(" {key}=\""))? + key.len() + 3;
    let end = tag[at..].find('"')?;
    Some(tag[at..at + end].to_string())
}

/// One array behind its UInt64 compression header.
fn inflate(b: &[u8]) -> Vec<u8> {
    let word = |k: usize| u64::from_le_bytes(b[8 * k..8 * k + 8].try_into().unwrap()) as usize;
    let n = word(0);
    let mut at = 8 * (3 + n);
    let mut out = Vec::new();
    for k in 0..n {
        let size = word(3 + k);
        flate2::read::ZlibDecoder::new(&b[at..at + size])
            .read_to_end(&mut out)
            .unwrap();
        at += size;
    }
    out
}

/// The (time, flow file, plate file) entries of a collection.
fn collection(path: &Path) -> Vec<(f64, String, String)> {
    let text = std::fs::read_to_string(path).unwrap();
    let sets: Vec<(f64, String, String)> = text
        .split("<DataSet ")
        .skip(1)
        .map(|tag| {
            let t = attribute(tag, "timestep").unwrap().parse().unwrap();
            (
                t,
                attribute(tag, "part").unwrap(),
                attribute(tag, "file").unwrap(),
            )
        })
        .collect();
    sets.chunks(2)
        .map(|p| {
            assert_eq!(
                (p[0].0, p[0].1.as_str(), p[1].1.as_str()),
                (p[1].0, "0", "1")
            );
            (p[0].0, p[0].2.clone(), p[1].2.clone())
        })
        .collect()
}

/// The run in-process, keeping the snapshots due at the VTK cadence.
struct Keep {
    cadence: Cadence,
    snapshots: Vec<FieldSnapshot>,
}

impl Observer for Keep {
    fn step(&mut self, _: &StepSample) {}
    fn wants_field(&mut self, t: f64) -> bool {
        self.cadence.due(t)
    }
    fn field(&mut self, s: FieldSnapshot) {
        self.snapshots.push(s);
    }
    fn should_stop(&self) -> bool {
        false
    }
}

fn close(a: &[f64], b: &[f64], what: &str) {
    assert_eq!(a.len(), b.len(), "{what}: lengths");
    for (k, (x, y)) in a.iter().zip(b).enumerate() {
        assert!(
            (x - y).abs() <= 1e-9 * (1.0 + y.abs()),
            "{what}[{k}]: {x} vs {y}"
        );
    }
}

/// (X, Y) of body point (x, y) and a body vector in inertial axes, for pose (X0, Y0, θ).
fn place(s: &FieldSnapshot, x: f64, y: f64) -> (f64, f64) {
    let (sn, c) = s.theta.sin_cos();
    (s.x + c * x - sn * y, s.y + sn * x + c * y)
}

/// The expected node velocity: rigid on the plate, else linear between the two faces.
fn expected_velocity(g: &GridGeometry, s: &FieldSnapshot, on: &[u8]) -> Vec<f64> {
    let f = SnapshotFields::new(g, s);
    let (xc, yc) = (cell_centres(&g.xn), cell_centres(&g.yn));
    let (nx, ny) = (g.nx(), g.ny());
    let lerp = |c: &[f64], k: usize, at: f64, val: &dyn Fn(usize) -> f64| match k {
        0 => val(0),
        k if k == c.len() => val(k - 1),
        k => val(k - 1) + (at - c[k - 1]) / (c[k] - c[k - 1]) * (val(k) - val(k - 1)),
    };
    let mut out = Vec::new();
    for j in 0..=ny {
        for i in 0..=nx {
            let (x, y) = (g.xn[i], g.yn[j]);
            let (a, b) = if on[i + (nx + 1) * j] == 1 {
                (
                    s.frame.u0 - s.frame.omega * y,
                    s.frame.v0 + s.frame.omega * x,
                )
            } else {
                let u = lerp(&yc, j, y, &|jj| f.u[i + (nx + 1) * jj]);
                let v = lerp(&xc, i, x, &|ii| f.v[ii + nx * j]);
                (u, v)
            };
            let (sn, c) = s.theta.sin_cos();
            out.extend([c * a - sn * b, sn * a + c * b, 0.0]);
        }
    }
    out
}

fn check_snapshot(g: &GridGeometry, s: &FieldSnapshot, flow: &VtkFile) {
    let mut points = Vec::new();
    for &y in &g.yn {
        for &x in &g.xn {
            let (px, py) = place(s, x, y);
            points.extend([px, py, 0.0]);
        }
    }
    close(&flow.f64s(""), &points, "points");
    close(&flow.f64s("pressure"), &s.p, "pressure");
    let f = SnapshotFields::new(g, s);
    close(&flow.f64s("vorticity"), &f.vorticity, "vorticity");
    let psi = stream_function_at_nodes(g, &f.u, &f.v);
    close(&flow.f64s("stream_function"), &psi, "stream function");
    let on = flow.raw("on_plate").to_vec();
    assert!(on.contains(&1), "nodes on the plate");
    let expected = expected_velocity(g, s, &on);
    close(&flow.f64s("velocity"), &expected, "velocity");
    close(&flow.f64s("pose"), &[s.x, s.y, s.theta], "pose");
    close(&flow.f64s("TimeValue"), &[s.t], "time");
}

fn run_and_compare(name: &str, case: &[&str], every: f64) {
    let dir = std::env::temp_dir().join(format!("platefall-vtk-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let vtk: PathBuf = dir.join("vtk");
    let out = Command::new(env!("CARGO_BIN_EXE_platefall"))
        .args(case)
        .args([
            "--no-save",
            "--progress",
            "off",
            "--vtk-every",
            &every.to_string(),
        ])
        .arg("--vtk")
        .arg(&vtk)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    let args: Vec<String> = case.iter().map(|s| s.to_string()).collect();
    let config = platefall::cli::case_config(&args).unwrap();
    let grid = config.grid().geometry();
    let mut keep = Keep {
        cadence: Cadence::new(every),
        snapshots: Vec::new(),
    };
    Simulation::new(config).unwrap().run(&mut keep);
    let entries = collection(&vtk.join("run.pvd"));
    let times: Vec<f64> = entries.iter().map(|e| e.0).collect();
    let expected: Vec<f64> = keep.snapshots.iter().map(|s| s.t).collect();
    assert_eq!(times, expected, "{name}: the collection's times");
    let count = |ext: &str| {
        let files = std::fs::read_dir(&vtk).unwrap().flatten();
        files
            .filter(|e| e.path().extension().is_some_and(|x| x == ext))
            .count()
    };
    assert_eq!((count("vts"), count("vtp")), (times.len(), times.len()));
    assert!(
        stderr.contains(&format!("({} snapshots", times.len())),
        "{stderr}"
    );
    for ((_, flow, plate), snap) in entries.iter().zip(&keep.snapshots) {
        check_snapshot(&grid, snap, &VtkFile::read(&vtk.join(flow)));
        let outline = VtkFile::read(&vtk.join(plate)).f64s("");
        assert_eq!(outline.len() % 3, 0);
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_static_plate_writes_the_solver_fields_at_every_snapshot() {
    run_and_compare(
        "static",
        &["static", "--resolution", "8", "--t-end", "1"],
        0.25,
    );
}

#[test]
fn a_free_fall_writes_the_solver_fields_at_the_plate_pose() {
    run_and_compare(
        "free",
        &[
            "free",
            "--resolution",
            "8",
            "--develop",
            "0.5",
            "--t-end",
            "2",
        ],
        0.3,
    );
}
