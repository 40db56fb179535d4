//! Shared helpers for the `record_*` tests: a synthetic grid, run, flow, and an .rrd reader.
#![allow(dead_code)]

use std::collections::HashMap;
use std::io::BufReader;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use platefall_core::flow::Frame;
use platefall_core::grid::GridGeometry;
use platefall_core::shape::Shape;
use platefall_core::sim::{CaseKind, FieldSnapshot, StepSample};
use platefall_post::{default_wake_window, ViewDefaults};
use platefall_record::messages::RunInfo;
use rerun::external::re_log_encoding::DecoderApp;
use rerun::log::{Chunk, LogMsg};

/// Runs the platefall binary with `args` (and `--progress off`); panics with its stderr unless
/// it succeeds.
pub fn run_platefall<S: AsRef<std::ffi::OsStr>>(args: &[S]) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_platefall"))
        .args(args)
        .args(["--progress", "off"])
        .output()
        .expect("the platefall binary runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// A fresh temporary directory for one test.
pub fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("platefall-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A stretched grid over [-4, 6] × [-5, 5] (sinh clustering at the plate), `nx × ny` cells,
/// with the plate [-0.5, 0.5] × [-t/2, t/2] solid.
pub fn grid(nx: usize, ny: usize, thickness: f64) -> GridGeometry {
    let stretch = |n: usize, lo: f64, hi: f64, mid: f64| -> Vec<f64> {
        (0..=n)
            .map(|i| {
                let s = i as f64 / n as f64;
                // map [0,1] → [lo, hi], clustered at `mid`
                let a = ((mid - lo) / (hi - lo)).clamp(0.05, 0.95);
                let k = 2.5;
                let f = |s: f64| (k * (s - a)).sinh();
                let t = (f(s) - f(0.0)) / (f(1.0) - f(0.0));
                lo + (hi - lo) * t
            })
            .collect()
    };
    let xn = stretch(nx, -4.0, 6.0, 0.0);
    let yn = stretch(ny, -5.0, 5.0, 0.0);
    let mut solid = vec![false; nx * ny];
    for j in 0..ny {
        for i in 0..nx {
            let (xc, yc) = (0.5 * (xn[i] + xn[i + 1]), 0.5 * (yn[j] + yn[j + 1]));
            solid[i + nx * j] =
                xc.abs() < 0.5 && yc.abs() < (0.5 * thickness).max(0.5 * (yn[j + 1] - yn[j]));
        }
    }
    GridGeometry { xn, yn, solid }
}

/// A synthetic free fall's run information; its end time `t_end` (None: unknown).
pub fn run_info_until(grid: GridGeometry, t_end: Option<f64>) -> RunInfo {
    RunInfo {
        case: CaseKind::Free,
        title: "synthetic free fall (test)".into(),
        config_json: "{\n  \"case\": \"free\",\n  \"re\": 4770\n}".into(),
        command_line: "platefall free --synthetic".into(),
        version: "0.1.0-test".into(),
        invocation: Default::default(),
        section: Arc::new(Shape::rect(0.0625).outline()),
        section_label: Shape::rect(0.0625).describe(),
        grid: Arc::new(grid),
        view: ViewDefaults {
            wake_window: default_wake_window(CaseKind::Free),
            plot_ranges: None,
            time_unit_s: None,
        },
        t_end,
    }
}

/// A synthetic free fall's run information, its end time unknown.
pub fn run_info(grid: GridGeometry) -> RunInfo {
    run_info_until(grid, None)
}

/// A tumbling fall: the centre drifts right and down, θ grows at ~1.6 per time unit.
pub fn sample(step: u64, dt: f64) -> StepSample {
    let t = step as f64 * dt;
    let theta = 1.6 * t + 0.3 * (2.0 * t).sin();
    let omega = 1.6 + 0.6 * (2.0 * t).cos();
    let (xdot, ydot) = (0.8 + 0.3 * (3.2 * t).sin(), -0.6 + 0.2 * (3.2 * t).cos());
    let x = 0.8 * t - 0.3 / 3.2 * ((3.2 * t).cos() - 1.0);
    let y = -0.6 * t + 0.2 / 3.2 * (3.2 * t).sin();
    let gamma = ydot.atan2(xdot);
    let mut alpha = theta - gamma;
    while alpha > std::f64::consts::PI {
        alpha -= 2.0 * std::f64::consts::PI;
    }
    while alpha <= -std::f64::consts::PI {
        alpha += 2.0 * std::f64::consts::PI;
    }
    StepSample {
        step,
        t,
        dt,
        cl: 1.2 * (2.0 * alpha).sin() + 0.5 * omega,
        cd: 1.0 + 0.8 * (1.0 - (2.0 * alpha).cos()),
        cm: -0.2 * (2.0 * alpha).sin(),
        x,
        y,
        theta,
        xdot,
        ydot,
        omega,
        speed: xdot.hypot(ydot),
        gamma,
        alpha,
    }
}

/// A synthetic flow for `s` on `grid`: a regularised vortex street in body coordinates that
/// blends smoothly into the plate's rigid motion at the plate (no-slip), built from a stream
/// function so the MAC field is exactly divergence-free.
pub fn snapshot(grid: &GridGeometry, s: &StepSample) -> FieldSnapshot {
    let (nx, ny) = (grid.nx(), grid.ny());
    let t = s.t;
    let (c, sn) = (s.theta.cos(), s.theta.sin());
    let frame = Frame {
        u0: s.xdot * c + s.ydot * sn,
        v0: -s.xdot * sn + s.ydot * c,
        omega: s.omega,
    };
    let (gx0, gy0, om) = (frame.u0, frame.v0, frame.omega);
    let vortices: Vec<(f64, f64, f64)> = (0..6)
        .map(|k| {
            let x0 = 0.7 + 0.7 * k as f64 + 0.35 * (t % 2.0);
            let y0 = if k % 2 == 0 { 0.35 } else { -0.35 };
            let g = if k % 2 == 0 { 2.5 } else { -2.5 };
            (x0, y0, g)
        })
        .collect();
    // The plate: bounding box of the solid cells.
    let (mut bx0, mut bx1, mut by0, mut by1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for j in 0..ny {
        for i in 0..nx {
            if grid.solid[i + nx * j] {
                bx0 = bx0.min(grid.xn[i]);
                bx1 = bx1.max(grid.xn[i + 1]);
                by0 = by0.min(grid.yn[j]);
                by1 = by1.max(grid.yn[j + 1]);
            }
        }
    }
    let psi = |x: f64, y: f64| -> f64 {
        let street: f64 = vortices
            .iter()
            .map(|&(x0, y0, g)| {
                let r2 = (x - x0).powi(2) + (y - y0).powi(2);
                -g / (4.0 * std::f64::consts::PI) * (r2 + 0.04).ln()
            })
            .sum();
        let rigid = gx0 * y - gy0 * x - 0.5 * om * (x * x + y * y);
        let dx = (bx0 - x).max(x - bx1).max(0.0);
        let dy = (by0 - y).max(y - by1).max(0.0);
        let blend = 1.0 - (-(dx * dx + dy * dy) / 0.0225).exp();
        rigid + blend * (street - rigid)
    };
    let mut u = vec![0.0; (nx + 1) * ny];
    let mut v = vec![0.0; nx * (ny + 1)];
    for j in 0..ny {
        for i in 0..=nx {
            let (x, y0, y1) = (grid.xn[i], grid.yn[j], grid.yn[j + 1]);
            u[i + (nx + 1) * j] = (psi(x, y1) - psi(x, y0)) / (y1 - y0);
        }
    }
    for j in 0..=ny {
        for i in 0..nx {
            let (y, x0, x1) = (grid.yn[j], grid.xn[i], grid.xn[i + 1]);
            v[i + nx * j] = -(psi(x1, y) - psi(x0, y)) / (x1 - x0);
        }
    }
    let mut p = vec![0.0; nx * ny];
    for j in 0..ny {
        for i in 0..nx {
            let uc = 0.5 * (u[i + (nx + 1) * j] + u[i + 1 + (nx + 1) * j]);
            let vc = 0.5 * (v[i + nx * j] + v[i + nx * (j + 1)]);
            p[i + nx * j] = -0.5 * (uc * uc + vc * vc);
        }
    }
    FieldSnapshot {
        step: s.step,
        t: s.t,
        x: s.x,
        y: s.y,
        theta: s.theta,
        frame,
        u,
        v,
        p,
    }
}

/// What an .rrd holds, as read back with Rerun's own decoder.
#[derive(Debug, Default)]
pub struct Decoded {
    /// Temporal rows per entity path.
    pub rows: HashMap<String, usize>,
    /// Entities with static data.
    pub statics: Vec<String>,
    /// Recording chunks (not the blueprint's).
    pub chunks: Vec<Chunk>,
    pub has_blueprint: bool,
    /// The chunks of the blueprint store made active last (the default layout and its view
    /// properties).
    pub blueprint: Vec<Chunk>,
    /// True if the file ends with a footer (RRD manifest): the sink was finalised.
    pub has_footer: bool,
    pub timelines: Vec<String>,
    /// The recording ids of the recording's chunks (one for one run).
    pub recording_ids: Vec<String>,
}

impl Decoded {
    pub fn rows(&self, path: &str) -> usize {
        self.rows.get(path).copied().unwrap_or(0)
    }

    /// All text of Text components logged at `path` (TextDocument / TextLog).
    pub fn texts(&self, path: &str) -> Vec<String> {
        let text_id = rerun::TextDocument::descriptor_text().component;
        let log_id = rerun::TextLog::descriptor_text().component;
        let mut out = Vec::new();
        for c in self
            .chunks
            .iter()
            .filter(|c| c.entity_path().to_string() == path)
        {
            for id in [text_id, log_id] {
                for batch in c.iter_component::<rerun::components::Text>(id) {
                    out.extend(batch.iter().map(|t| t.as_str().to_string()));
                }
            }
        }
        out
    }

    /// All scalar values logged at `path`, in chunk order.
    pub fn scalars(&self, path: &str) -> Vec<f64> {
        let id = rerun::Scalars::descriptor_scalars().component;
        let mut out = Vec::new();
        for c in self
            .chunks
            .iter()
            .filter(|c| c.entity_path().to_string() == path)
        {
            for batch in c.iter_component::<rerun::components::Scalar>(id) {
                out.extend(batch.iter().map(|s| s.0 .0));
            }
        }
        out
    }

    pub fn entities_under(&self, prefix: &str) -> Vec<String> {
        let mut v: Vec<String> = self
            .rows
            .keys()
            .chain(self.statics.iter())
            .filter(|p| p.starts_with(prefix))
            .cloned()
            .collect();
        v.sort();
        v.dedup();
        v
    }
}

/// Blueprint archetypes of the view properties the tests read.
use rerun::external::re_sdk_types::blueprint::archetypes::{
    ScalarAxis, ViewBlueprint, VisualBounds2D,
};

/// Every value of component `id` (type `C`) in `chunks` whose entity path (without the leading
/// slash) satisfies `at`, with that path.
fn values_where<C: rerun::Component + Clone>(
    chunks: &[Chunk],
    at: impl Fn(&str) -> bool,
    id: rerun::ComponentIdentifier,
) -> Vec<(String, C)> {
    let mut out = Vec::new();
    for c in chunks {
        let path = c.entity_path().to_string();
        let path = path.trim_start_matches('/');
        if !at(path) {
            continue;
        }
        for batch in c.iter_component::<C>(id) {
            out.extend(batch.iter().map(|v| (path.to_string(), v.clone())));
        }
    }
    out
}

impl Decoded {
    /// Every value of component `id` (of type `C`) logged at `path`, in chunk order.
    pub fn values<C: rerun::Component + Clone>(
        &self,
        path: &str,
        id: rerun::ComponentIdentifier,
    ) -> Vec<C> {
        values_where(&self.chunks, |p| p == path.trim_start_matches('/'), id)
            .into_iter()
            .map(|(_, v)| v)
            .collect()
    }

    /// (blueprint path `view/<id>`, display name) of every view of the blueprint.
    pub fn views(&self) -> Vec<(String, String)> {
        let id = ViewBlueprint::descriptor_display_name().component;
        values_where::<rerun::components::Name>(&self.blueprint, |_| true, id)
            .into_iter()
            .map(|(path, name)| (path, name.as_str().to_string()))
            .collect()
    }

    /// A blueprint property of the view called `name`: component `id` of `{view}/{property}`.
    fn view_property<C: rerun::Component + Clone>(
        &self,
        name: &str,
        property: &str,
        id: rerun::ComponentIdentifier,
    ) -> Option<C> {
        let (view, _) = self
            .views()
            .into_iter()
            .find(|(_, n)| n.starts_with(name))?;
        let path = format!("{view}/{property}");
        values_where::<C>(&self.blueprint, |p| p == path, id)
            .into_iter()
            .map(|(_, v)| v)
            .next()
    }

    /// The y range a time-series view opens on (blueprint property `ScalarAxis`).
    pub fn y_range(&self, view: &str) -> Option<[f64; 2]> {
        let id = ScalarAxis::descriptor_range().component;
        let r = self.view_property::<rerun::components::Range1D>(view, "ScalarAxis", id)?;
        Some(r.0 .0)
    }

    /// The visual bounds (x range, y range) a 2-D view opens on (`VisualBounds2D`).
    pub fn visual_bounds(&self, view: &str) -> Option<([f64; 2], [f64; 2])> {
        let id = VisualBounds2D::descriptor_range().component;
        let b = self.view_property::<rerun::blueprint::components::VisualBounds2D>(
            view,
            "VisualBounds2D",
            id,
        )?;
        Some((b.0.x_range.0, b.0.y_range.0))
    }
}

pub fn decode(path: &Path) -> Decoded {
    decode_impl(path, false)
}

/// Like [`decode`], but stops quietly at the first undecodable message (a file still being
/// written by someone else).
pub fn decode_partial(path: &Path) -> Decoded {
    decode_impl(path, true)
}

fn decode_impl(path: &Path, partial: bool) -> Decoded {
    let file = std::fs::File::open(path).expect("open rrd");
    let mut it = DecoderApp::decode_lazy(BufReader::new(file));
    let mut d = Decoded::default();
    // Blueprint chunks by store, and the store the last activation made active.
    let mut stores: Vec<(rerun::StoreId, Vec<Chunk>)> = Vec::new();
    let mut active = None;
    for msg in &mut it {
        let msg = match msg {
            Ok(m) => m,
            Err(_) if partial => break,
            Err(e) => panic!("decode rrd: {e}"),
        };
        match msg {
            LogMsg::ArrowMsg(store_id, arrow) => {
                if store_id.kind() != rerun::StoreKind::Recording {
                    d.has_blueprint = true;
                    let chunk = Chunk::from_arrow_msg(&arrow).expect("blueprint chunk");
                    match stores.iter_mut().find(|(id, _)| *id == store_id) {
                        Some((_, chunks)) => chunks.push(chunk),
                        None => stores.push((store_id, vec![chunk])),
                    }
                    continue;
                }
                let id = store_id.recording_id().to_string();
                if !d.recording_ids.contains(&id) {
                    d.recording_ids.push(id);
                }
                let chunk = Chunk::from_arrow_msg(&arrow).expect("chunk");
                let path = chunk.entity_path().to_string();
                if chunk.is_static() {
                    d.statics.push(path);
                } else {
                    *d.rows.entry(path).or_default() += chunk.num_rows();
                    for name in chunk.timelines().keys() {
                        let n = name.to_string();
                        if !d.timelines.contains(&n) {
                            d.timelines.push(n);
                        }
                    }
                }
                d.chunks.push(chunk);
            }
            LogMsg::BlueprintActivationCommand(cmd) => {
                if cmd.make_active {
                    active = Some(cmd.blueprint_id);
                }
            }
            LogMsg::SetStoreInfo(_) => {}
        }
    }
    d.blueprint = stores
        .into_iter()
        .find(|(id, _)| Some(id) == active.as_ref())
        .map(|(_, chunks)| chunks)
        .unwrap_or_default();
    d.has_footer = !it.rrd_manifests().map(|m| m.is_empty()).unwrap_or(true);
    d
}

/// `rerun` CLI from the venv of the brief, if present (for the optional outside checks).
pub fn rerun_cli() -> Option<PathBuf> {
    // The real binary inside the wheel, not the `bin/rerun` Python shim: a signal sent to the shim
    // does not reach the binary, so the shim would never exit. `PLATEFALL_RERUN_CLI` (set by
    // `.ci/run`) wins; otherwise look in the CI venv and the usual scratch venvs.
    if let Some(p) = std::env::var_os("PLATEFALL_RERUN_CLI").map(PathBuf::from) {
        return p.exists().then_some(p);
    }
    let venvs = [
        concat!(env!("CARGO_MANIFEST_DIR"), "/target/ci-venv"),
        "/tmp/rrvenv",
        "/tmp/rrview/venv",
    ];
    venvs.iter().find_map(|venv| {
        let lib = Path::new(venv).join("lib");
        std::fs::read_dir(&lib).ok()?.flatten().find_map(|py| {
            let bin = py.path().join("site-packages/rerun_sdk/rerun_cli/rerun");
            bin.exists().then_some(bin)
        })
    })
}
