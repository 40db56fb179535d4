//! Recording and output options of every case subcommand ([`RecordArgs`], flattened into each)
//! and their resolution into the recording layer's [`RecordOptions`], checking everything that can
//! be checked before a run: ranges, URLs, the --serve and --web ports, output paths.
use std::net::{IpAddr, SocketAddr, TcpListener};
use std::path::{Path, PathBuf};

use platefall_core::sim::CaseKind;
use platefall_post::{FieldWindow, StreamFrame};
use platefall_record::files::{check_directory, check_outputs, OutputPath};
use platefall_record::options::{
    ProgressMode, RecordOptions, ServeOptions, DEFAULT_FIELD_EVERY, DEFAULT_FIELD_RES,
    DEFAULT_PORT, DEFAULT_WEB_PORT, FIELD_RES_RANGE,
};
use platefall_record::view_options::{ViewOptions, DEFAULT_WAKE_RES};
use platefall_record::viewer;
use platefall_record::vtk::{VtkOptions, COLLECTION};

/// How progress is shown on stderr.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum ProgressArg {
    /// A bar on a terminal, plain lines every ~10 s otherwise.
    #[default]
    Auto,
    /// Always the bar.
    Bar,
    /// Always plain lines (every ~10 s).
    Lines,
    /// Nothing.
    Off,
}

impl From<ProgressArg> for ProgressMode {
    fn from(p: ProgressArg) -> Self {
        match p {
            ProgressArg::Auto => ProgressMode::Auto,
            ProgressArg::Bar => ProgressMode::Bar,
            ProgressArg::Lines => ProgressMode::Lines,
            ProgressArg::Off => ProgressMode::Off,
        }
    }
}

/// Recording and output options shared by every case (`#[command(flatten)]` them).
#[derive(Clone, Debug, clap::Args)]
#[command(next_help_heading = "Recording and output")]
pub struct RecordArgs {
    /// Write the Rerun recording to FILE.rrd [default: recordings/<case>.rrd]
    #[arg(long, value_name = "FILE.rrd")]
    pub save: Option<PathBuf>,

    /// Do not write a .rrd file (stream only, or CSV only)
    #[arg(long, conflicts_with = "save")]
    pub no_save: bool,

    /// Host a gRPC server that viewers connect to (`rerun rerun+http://HOST:PORT/proxy`); it keeps
    /// serving after the run ends, until Ctrl-C, so a late viewer still sees the whole run
    #[arg(long)]
    pub serve: bool,

    /// Watch the run in a browser: serve the Rerun web viewer (built into platefall) on
    /// --web-port, reading from the --serve server, which --web starts too. Open the printed
    /// http://127.0.0.1:9090/?url=... page (no browser is started for you); it keeps serving
    /// after the run, until Ctrl-C. From another machine tunnel both ports, e.g.
    /// `ssh -L 9090:127.0.0.1:9090 -L 9876:127.0.0.1:9876 HOST`
    #[arg(long)]
    pub web: bool,

    /// Port of the --web viewer's page (1..=65535, not --port) [default: 9090]
    #[arg(long, value_name = "N")]
    pub web_port: Option<u16>,

    /// Address the --serve server and the --web viewer bind to (0.0.0.0 to accept remote
    /// viewers: the printed URLs then name this machine by its host name)
    #[arg(long, value_name = "ADDR", default_value = "127.0.0.1")]
    pub bind: IpAddr,

    /// Port of the --serve server (1..=65535)
    #[arg(long, value_name = "N", default_value_t = DEFAULT_PORT)]
    pub port: u16,

    /// History the --serve server keeps for late viewers, e.g. "25%" (of RAM) or "2GB"
    #[arg(long, value_name = "LIMIT", default_value = "25%")]
    pub server_memory_limit: String,

    /// Also stream to an already-running viewer, e.g. rerun+http://127.0.0.1:9876/proxy
    #[arg(long, value_name = "URL", conflicts_with = "spawn")]
    pub connect: Option<String>,

    /// Start a local Rerun viewer (needs `rerun` on PATH) and stream to it
    #[arg(long)]
    pub spawn: bool,

    /// A recording small enough to attach to a bug report: field snapshots every 0.5 c/U and
    /// 128-pixel close-up and wake images (an explicit --field-every, --field-res or --wake-res
    /// overrides its value)
    #[arg(long)]
    pub small: bool,

    /// Convective time (c/U) between field snapshots (images and streamlines) [default: 0.1;
    /// with --small 0.5]
    #[arg(long, value_name = "T")]
    pub field_every: Option<f64>,

    /// Pixels along the longer side of the close-up field images (16..=2048) [default: 256;
    /// with --small 128]
    #[arg(long, value_name = "PX")]
    pub field_res: Option<usize>,

    /// Wake window along the plate's path, in chords: SMIN,SMAX along the direction of travel
    /// (the plate at 0, its wake at negative values), NMIN,NMAX across it [default: static and
    /// forced -8,2,-2.5,2.5; pinned and free -10,2,-3,3]
    #[arg(long, value_name = "SMIN,SMAX,NMIN,NMAX", allow_hyphen_values = true)]
    pub wake_window: Option<String>,

    /// Pixels along the longer side of the wake images (16..=2048) [default: 256; with --small
    /// 128]
    #[arg(long, value_name = "PX")]
    pub wake_res: Option<usize>,

    /// Field image window in body coordinates (chords): XMIN,XMAX,YMIN,YMAX
    #[arg(
        long,
        value_name = "XMIN,XMAX,YMIN,YMAX",
        default_value = "-2.5,4,-2.5,2.5",
        allow_hyphen_values = true
    )]
    pub field_window: String,

    /// Observer frame of the streamlines and the speed image: 1 fixed to the plate, 2 fixed in the
    /// fluid, 3 translating with the plate but not rotating (the dissertation's), 4 rotating with the
    /// plate but not translating
    #[arg(long, value_name = "1..4", default_value_t = 3)]
    pub streamlines_frame: u8,

    /// Also write every step to a CSV file (time, step, dt, C_L, C_D, C_M, X, Y, θ, Ẋ, Ẏ, θ̇, V, γ, α)
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,

    /// Also write the flow for ParaView into DIR: one .vts (the grid at the plate's pose:
    /// velocity, pressure, vorticity, stream function) and one .vtp (the plate) per snapshot, and
    /// DIR/run.pvd listing them by time (DIR is created if its parent exists)
    #[arg(long, value_name = "DIR")]
    pub vtk: Option<PathBuf>,

    /// Convective time (c/U) between VTK snapshots [default: the field cadence, --field-every]
    #[arg(long, value_name = "T", requires = "vtk")]
    pub vtk_every: Option<f64>,

    /// No progress output
    #[arg(long, short = 'q')]
    pub quiet: bool,

    /// Progress display on stderr
    #[arg(long, value_enum, value_name = "MODE", default_value_t = ProgressArg::Auto)]
    pub progress: ProgressArg,
}

/// A bad recording option: one line naming the value and what is accepted.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum OptionsError {
    #[error("--field-every {0}: must be a finite number > 0 (convective time units between field snapshots)")]
    FieldEvery(f64),
    #[error("--field-res {0}: must be in {lo}..={hi} pixels", lo = FIELD_RES_RANGE.start(), hi = FIELD_RES_RANGE.end())]
    FieldRes(usize),
    #[error("--field-window {0:?}: expected XMIN,XMAX,YMIN,YMAX (four finite numbers, XMIN < XMAX, YMIN < YMAX, containing the plate [-0.5, 0.5] x 0)")]
    FieldWindow(String),
    #[error("--wake-window {0:?}: expected SMIN,SMAX,NMIN,NMAX (four finite numbers in [-15, 15] chords, SMIN < -0.5 < 0.5 < SMAX, NMIN < 0 < NMAX)")]
    WakeWindow(String),
    #[error("--wake-res {0}: must be in {lo}..={hi} pixels", lo = FIELD_RES_RANGE.start(), hi = FIELD_RES_RANGE.end())]
    WakeRes(usize),
    #[error("--vtk-every {0}: must be a finite number > 0 (convective time units between VTK snapshots)")]
    VtkEvery(f64),
    #[error("--streamlines-frame {0}: must be 1, 2, 3 or 4 (1 plate-fixed, 2 fluid-fixed, 3 translating, 4 rotating)")]
    StreamlinesFrame(u8),
    #[error("--server-memory-limit {value:?}: {reason}; accepted: a share of RAM like \"25%\", a size like \"2GB\", or \"unlimited\"")]
    MemoryLimit { value: String, reason: String },
    #[error("--connect {value:?}: not a Rerun proxy URL ({reason}); expected e.g. rerun+http://127.0.0.1:9876/proxy")]
    ConnectUrl { value: String, reason: String },
    #[error("{flag} {port}: cannot listen on {addr} ({reason})")]
    Port {
        flag: &'static str,
        port: u16,
        addr: String,
        reason: String,
    },
    #[error("{flag} 0: must be in 1..=65535 (the URL a viewer opens names the port)")]
    PortZero { flag: &'static str },
    #[error("--web-port {0}: the same port as --port; accepted any other port in 1..=65535")]
    WebPortIsPort(u16),
    #[error("--web-port {0} only goes with --web")]
    WebPortAlone(u16),
    #[error("--web: this platefall was built without the `web` feature, so it cannot serve the web viewer (rebuild with default features, or use --serve and the `rerun` viewer)")]
    NoWebFeature,
    #[error("--spawn: no `rerun` viewer executable on PATH (install it with `pip install rerun-sdk==0.36.3`), or use --serve and connect a viewer yourself")]
    NoViewer,
    #[error("{flag}: this platefall was built without the `viewer` feature, so it cannot record or stream for Rerun (rebuild with default features, or use --no-save)")]
    NoViewerFeature { flag: &'static str },
    #[error("{flag} {path}: {reason}")]
    Path {
        flag: &'static str,
        path: String,
        reason: String,
    },
}

impl RecordArgs {
    /// The default recording path for a case: `recordings/<case>.rrd`.
    pub fn default_save_path(case: CaseKind) -> PathBuf {
        Path::new("recordings").join(format!("{case}.rrd"))
    }

    /// How progress is shown: off with --quiet, else --progress.
    pub fn progress_mode(&self) -> ProgressMode {
        if self.quiet {
            ProgressMode::Off
        } else {
            self.progress.into()
        }
    }

    /// True if the run opens a Rerun recording or stream (a file, a server or a viewer).
    pub fn uses_rerun(&self) -> bool {
        !self.no_save || self.serves() || self.connect.is_some() || self.spawn
    }

    /// True if the run hosts the gRPC server: --serve, or --web (which reads from it).
    fn serves(&self) -> bool {
        self.serve || self.web
    }

    /// Validates the options for a run of `case`; `others` are the run's other outputs (e.g.
    /// `("--summary", path)`).
    ///
    /// Checks everything that can be checked before the run starts: numeric ranges, the --connect
    /// URL, the --serve port (free?), `rerun` on PATH for --spawn, and that every output path is
    /// writable and names a file of its own (creating `recordings/` for the default path, but
    /// never any other directory).
    pub fn resolve(
        &self,
        case: CaseKind,
        others: &[(&'static str, &Path)],
    ) -> Result<RecordOptions, OptionsError> {
        let fields = self.field_options()?;
        self.check_web_feature()?;
        self.check_viewer_feature()?;
        let serve = self.serve_options()?;
        let connect = self.connect_url()?;
        if self.spawn && find_on_path("rerun").is_none() {
            return Err(OptionsError::NoViewer);
        }
        let save = self.save_path(case)?;
        let vtk = self.vtk_options(fields.every)?;
        let collection = vtk.as_ref().map(|v| v.dir.join(COLLECTION));
        let mut others = others.to_vec();
        if let Some(pvd) = collection
            .as_deref()
            .filter(|p| p.parent().is_some_and(Path::is_dir))
        {
            others.push(("--vtk", pvd));
        }
        self.check_paths(save.as_deref(), &others)?;
        let csv = self.csv.clone();
        let progress = self.progress_mode();
        Ok(RecordOptions {
            save,
            serve,
            connect,
            spawn: self.spawn,
            field_every: fields.every,
            field_res: fields.res,
            field_window: fields.window,
            streamlines_frame: fields.frame,
            view: fields.view,
            csv,
            vtk,
            progress,
            ..RecordOptions::default()
        })
    }

    /// The field cadence, image sizes, windows and streamline frame: explicit flags, else the
    /// --small setting, else the defaults.
    fn field_options(&self) -> Result<FieldOptions, OptionsError> {
        let (every, res) = if self.small {
            (SMALL_FIELD_EVERY, SMALL_RES)
        } else {
            (DEFAULT_FIELD_EVERY, DEFAULT_FIELD_RES)
        };
        let every = self.field_every.unwrap_or(every);
        if !(every.is_finite() && every > 0.0) {
            return Err(OptionsError::FieldEvery(every));
        }
        let field_res = self.field_res.unwrap_or(res);
        if !FIELD_RES_RANGE.contains(&field_res) {
            return Err(OptionsError::FieldRes(field_res));
        }
        let wake_res = self.wake_res.unwrap_or(if self.small {
            SMALL_RES
        } else {
            DEFAULT_WAKE_RES
        });
        if !FIELD_RES_RANGE.contains(&wake_res) {
            return Err(OptionsError::WakeRes(wake_res));
        }
        let window = parse_window(&self.field_window)
            .ok_or_else(|| OptionsError::FieldWindow(self.field_window.clone()))?;
        let wake_window = match &self.wake_window {
            Some(text) => Some(
                parse_wake_window(text).ok_or_else(|| OptionsError::WakeWindow(text.clone()))?,
            ),
            None => None,
        };
        let frame = StreamFrame::from_number(self.streamlines_frame)
            .ok_or(OptionsError::StreamlinesFrame(self.streamlines_frame))?;
        Ok(FieldOptions {
            every,
            res: field_res,
            window,
            frame,
            view: ViewOptions {
                wake_window,
                wake_res,
            },
        })
    }

    /// `--vtk DIR`: an existing writable directory, or a new one in an existing writable
    /// directory; `--vtk-every` (default `field_every`) a finite number > 0.
    fn vtk_options(&self, field_every: f64) -> Result<Option<VtkOptions>, OptionsError> {
        let Some(dir) = &self.vtk else {
            return Ok(None);
        };
        let every = self.vtk_every.unwrap_or(field_every);
        if !(every.is_finite() && every > 0.0) {
            return Err(OptionsError::VtkEvery(every));
        }
        check_directory(dir).map_err(|reason| path_error("--vtk", dir, reason.to_string()))?;
        Ok(Some(VtkOptions {
            dir: dir.clone(),
            every,
        }))
    }

    /// --web needs the `web` feature.
    fn check_web_feature(&self) -> Result<(), OptionsError> {
        if self.web && !viewer::WEB_AVAILABLE {
            return Err(OptionsError::NoWebFeature);
        }
        Ok(())
    }

    /// Without the `viewer` feature only --no-save runs (CSV, summary) are possible.
    fn check_viewer_feature(&self) -> Result<(), OptionsError> {
        if viewer::AVAILABLE {
            return Ok(());
        }
        let asked = [
            ("--save", !self.no_save),
            ("--serve", self.serve),
            ("--connect", self.connect.is_some()),
            ("--spawn", self.spawn),
        ];
        match asked.into_iter().find(|(_, on)| *on) {
            Some((flag, _)) => Err(OptionsError::NoViewerFeature { flag }),
            None => Ok(()),
        }
    }

    /// --serve (or --web): the memory limit parses and the ports are free now.
    fn serve_options(&self) -> Result<Option<ServeOptions>, OptionsError> {
        let web_port = self.web_port()?;
        if !self.serves() {
            return Ok(None);
        }
        viewer::check_memory_limit(&self.server_memory_limit).map_err(|e| {
            OptionsError::MemoryLimit {
                value: self.server_memory_limit.clone(),
                reason: e.0,
            }
        })?;
        check_port("--port", self.bind, self.port)?;
        if let Some(port) = web_port {
            check_port("--web-port", self.bind, port)?;
        }
        Ok(Some(ServeOptions {
            bind: self.bind,
            port: self.port,
            memory_limit: self.server_memory_limit.clone(),
            web_port,
        }))
    }

    /// The --web viewer's port (None without --web): --web-port only with --web, and not --port.
    fn web_port(&self) -> Result<Option<u16>, OptionsError> {
        match (self.web, self.web_port) {
            (false, None) => Ok(None),
            (false, Some(port)) => Err(OptionsError::WebPortAlone(port)),
            (true, Some(port)) if port == self.port => Err(OptionsError::WebPortIsPort(port)),
            (true, port) => Ok(Some(port.unwrap_or(DEFAULT_WEB_PORT))),
        }
    }

    fn connect_url(&self) -> Result<Option<String>, OptionsError> {
        let Some(url) = &self.connect else {
            return Ok(None);
        };
        viewer::check_proxy_url(url).map_err(|e| OptionsError::ConnectUrl {
            value: url.clone(),
            reason: e.0,
        })?;
        Ok(Some(url.clone()))
    }

    /// The .rrd path: --save, or `recordings/<case>.rrd`, or none with --no-save.
    fn save_path(&self, case: CaseKind) -> Result<Option<PathBuf>, OptionsError> {
        if self.no_save {
            return Ok(None);
        }
        let path = self
            .save
            .clone()
            .unwrap_or_else(|| Self::default_save_path(case));
        if path.extension().and_then(|e| e.to_str()) != Some("rrd") {
            return Err(path_error(
                "--save",
                &path,
                "the file name must end in .rrd".into(),
            ));
        }
        Ok(Some(path))
    }

    /// Every output path writable and a file of its own (`files::check_outputs`).
    fn check_paths(
        &self,
        save: Option<&Path>,
        others: &[(&'static str, &Path)],
    ) -> Result<(), OptionsError> {
        let mut outputs = Vec::new();
        if let Some(path) = save {
            let create_dir = self.save.is_none(); // only the default recordings/ is created
            outputs.push(OutputPath {
                flag: "--save",
                path,
                create_dir,
            });
        }
        let csv = self.csv.as_deref().map(|p| ("--csv", p));
        for (flag, path) in csv.into_iter().chain(others.iter().copied()) {
            outputs.push(OutputPath {
                flag,
                path,
                create_dir: false,
            });
        }
        check_outputs(&outputs).map_err(|p| path_error(p.flag, &p.path, p.reason.to_string()))
    }
}

/// The port `flag` names on `bind`: not 0, and free now (a listener binds it and lets it go).
fn check_port(flag: &'static str, bind: IpAddr, port: u16) -> Result<(), OptionsError> {
    if port == 0 {
        return Err(OptionsError::PortZero { flag });
    }
    let addr = SocketAddr::new(bind, port);
    match TcpListener::bind(addr) {
        Ok(_) => Ok(()),
        Err(err) => Err(OptionsError::Port {
            flag,
            port,
            addr: addr.to_string(),
            reason: err.to_string(),
        }),
    }
}

fn path_error(flag: &'static str, path: &Path, reason: String) -> OptionsError {
    OptionsError::Path {
        flag,
        path: path.display().to_string(),
        reason,
    }
}

/// "x0,x1,y0,y1" → a valid window (four finite numbers, x0 < x1, y0 < y1).
fn parse_four(s: &str) -> Option<FieldWindow> {
    let v: Vec<f64> = s
        .split(',')
        .map(|p| p.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .ok()?;
    let [x0, x1, y0, y1] = v.as_slice() else {
        return None;
    };
    let w = FieldWindow {
        x0: *x0,
        x1: *x1,
        y0: *y0,
        y1: *y1,
    };
    w.is_valid().then_some(w)
}

/// "x0,x1,y0,y1" → a valid window containing the plate.
fn parse_window(s: &str) -> Option<FieldWindow> {
    parse_four(s).filter(|w| w.x0 < -0.5 && w.x1 > 0.5 && w.y0 < 0.0 && w.y1 > 0.0)
}

/// "s0,s1,n0,n1" → a valid wake window around the plate, within 15 chords (the default grid's
/// extent) on every side.
fn parse_wake_window(s: &str) -> Option<FieldWindow> {
    let within = |v: f64| (-15.0..=15.0).contains(&v);
    parse_window(s).filter(|w| [w.x0, w.x1, w.y0, w.y1].into_iter().all(within))
}

/// The resolved field options of [`RecordArgs::field_options`].
struct FieldOptions {
    every: f64,
    res: usize,
    window: FieldWindow,
    frame: StreamFrame,
    view: ViewOptions,
}

/// `--small`: convective time (c/U) between field snapshots.
pub const SMALL_FIELD_EVERY: f64 = 0.5;
/// `--small`: pixels along the longer side of the close-up and wake images.
pub const SMALL_RES: usize = 128;

/// The first executable called `name` on PATH.
pub(crate) fn find_on_path(name: &str) -> Option<PathBuf> {
    let path = std::env::var_os("PATH")?;
    std::env::split_paths(&path).find_map(|dir| {
        let candidate = dir.join(name);
        let meta = std::fs::metadata(&candidate).ok()?;
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt as _;
            if meta.is_file() && meta.permissions().mode() & 0o111 != 0 {
                return Some(candidate);
            }
            None
        }
        #[cfg(not(unix))]
        {
            meta.is_file().then_some(candidate)
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Parser)]
    struct Cli {
        #[command(flatten)]
        rec: RecordArgs,
    }

    fn args(extra: &[&str]) -> RecordArgs {
        let mut argv = vec!["x"];
        argv.extend_from_slice(extra);
        Cli::try_parse_from(argv).expect("parse").rec
    }

    #[test]
    #[cfg(feature = "viewer")]
    fn defaults_resolve() {
        let dir = std::env::temp_dir().join(format!("pf-opt-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let save = dir.join("a.rrd");
        let o = args(&["--save", save.to_str().unwrap()])
            .resolve(CaseKind::Free, &[])
            .unwrap();
        assert_eq!(o.save.as_deref(), Some(save.as_path()));
        assert_eq!(o.field_every, DEFAULT_FIELD_EVERY);
        assert_eq!(o.streamlines_frame, StreamFrame::Translating);
        assert_eq!(o.field_window, FieldWindow::default());
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    #[cfg(feature = "viewer")]
    fn bad_values_are_refused_with_one_line() {
        let cases: &[(&[&str], &str)] = &[
            (&["--field-every", "0"], "--field-every 0"),
            (&["--field-every", "inf"], "--field-every inf"),
            (&["--field-res", "8"], "--field-res 8: must be in 16..=2048"),
            (&["--streamlines-frame", "5"], "--streamlines-frame 5"),
            (&["--field-window", "1,2,3"], "--field-window"),
            (&["--wake-window", "-8,2,0,1"], "--wake-window"),
            (&["--wake-window", "-16,2,-1,1"], "[-15, 15]"),
            (
                &["--wake-res", "4096"],
                "--wake-res 4096: must be in 16..=2048",
            ),
            (&["--small", "--field-res", "8"], "--field-res 8"),
            (&["--save", "/nonexistent-dir-pf/x.rrd"], "does not exist"),
            (&["--save", "/tmp/x.txt"], "must end in .rrd"),
            (&["--csv", "/nonexistent-dir-pf/x.csv"], "--csv"),
            (&["--connect", "http://nope"], "--connect"),
            (
                &["--serve", "--server-memory-limit", "lots"],
                "--server-memory-limit",
            ),
        ];
        for (argv, expect) in cases {
            let mut a = args(argv);
            if !argv.contains(&"--save") {
                a.no_save = true;
            }
            let e = a.resolve(CaseKind::Free, &[]).unwrap_err().to_string();
            assert!(e.contains(expect), "{argv:?}: {e}");
            assert!(!e.contains('\n'), "one line: {e}");
        }
    }

    #[test]
    fn small_sets_the_bug_report_setting_and_explicit_flags_win() {
        let o = args(&["--no-save", "--small"])
            .resolve(CaseKind::Free, &[])
            .unwrap();
        assert_eq!((o.field_every, o.field_res), (SMALL_FIELD_EVERY, SMALL_RES));
        assert_eq!(o.view.wake_res, SMALL_RES);
        assert_eq!(o.view.wake_window, None);
        let o = args(&[
            "--no-save",
            "--small",
            "--field-res",
            "200",
            "--wake-res",
            "96",
        ])
        .resolve(CaseKind::Free, &[])
        .unwrap();
        assert_eq!(
            (o.field_every, o.field_res, o.view.wake_res),
            (0.5, 200, 96)
        );
        let o = args(&["--no-save", "--wake-window", "-6,1.5,-2,3"])
            .resolve(CaseKind::Static, &[])
            .unwrap();
        let w = o.view.wake_window.unwrap();
        assert_eq!([w.x0, w.x1, w.y0, w.y1], [-6.0, 1.5, -2.0, 3.0]);
        assert_eq!(o.view.wake_res, DEFAULT_WAKE_RES);
    }

    #[test]
    #[cfg(feature = "viewer")]
    fn busy_port_is_detected() {
        let l = TcpListener::bind("127.0.0.1:0").unwrap();
        let port = l.local_addr().unwrap().port().to_string();
        let mut a = args(&["--serve", "--port", &port]);
        a.no_save = true;
        let e = a.resolve(CaseKind::Free, &[]).unwrap_err().to_string();
        assert!(e.starts_with(&format!("--port {port}")), "{e}");
        if viewer::WEB_AVAILABLE {
            let free = free_port();
            let mut a = args(&["--web", "--port", &free, "--web-port", &port]);
            a.no_save = true;
            let e = a.resolve(CaseKind::Free, &[]).unwrap_err().to_string();
            assert!(
                e.starts_with(&format!("--web-port {port}: cannot listen")),
                "{e}"
            );
        }
    }

    /// A port no one listens on now.
    #[cfg(feature = "viewer")]
    fn free_port() -> String {
        let l = TcpListener::bind("127.0.0.1:0").unwrap();
        l.local_addr().unwrap().port().to_string()
    }

    #[test]
    #[cfg(feature = "web")]
    fn web_serves_the_run_and_its_viewer_on_the_bind_address() {
        let port = free_port();
        let o = args(&["--no-save", "--web", "--port", &port])
            .resolve(CaseKind::Static, &[])
            .unwrap();
        let serve = o.serve.expect("--web starts the server");
        assert_eq!(serve.port.to_string(), port);
        assert_eq!(serve.web_port, Some(DEFAULT_WEB_PORT));
        assert!(serve.bind.is_loopback());
        let web = free_port();
        let o = args(&["--no-save", "--serve", "--web", "--web-port", &web])
            .resolve(CaseKind::Static, &[])
            .unwrap();
        assert_eq!(o.serve.unwrap().web_port.unwrap().to_string(), web);
        let port = free_port();
        let o = args(&["--no-save", "--serve", "--port", &port])
            .resolve(CaseKind::Static, &[])
            .unwrap();
        assert_eq!(o.serve.unwrap().web_port, None, "no viewer without --web");
    }

    #[test]
    #[cfg(not(feature = "viewer"))]
    fn sinks_are_refused_without_the_viewer_feature() {
        for (argv, flag) in [
            (&[][..], "--save"),
            (&["--no-save", "--serve"][..], "--serve"),
            (&["--no-save", "--spawn"][..], "--spawn"),
        ] {
            let e = args(argv)
                .resolve(CaseKind::Free, &[])
                .unwrap_err()
                .to_string();
            assert!(e.starts_with(flag) && e.contains("viewer"), "{argv:?}: {e}");
        }
        let o = args(&["--no-save"]).resolve(CaseKind::Free, &[]).unwrap();
        assert!(!o.has_rerun_sink());
    }
}
