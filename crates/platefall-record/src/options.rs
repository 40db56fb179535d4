//! Validated recording options: everything the logger needs. The command line builds them
//! (`src/cli/record_args.rs`); Rust callers build them directly.
use std::net::{IpAddr, SocketAddr};
use std::path::PathBuf;

use super::view_options::ViewOptions;
use super::vtk::VtkOptions;
use platefall_post::{FieldWindow, StreamFrame};

/// Default convective time between field snapshots (see the size budget in the crate docs (`lib.rs`)).
pub const DEFAULT_FIELD_EVERY: f64 = 0.1;
/// Default image size: pixels along the longer side of the field window.
pub const DEFAULT_FIELD_RES: usize = 256;
/// Accepted range of the field image size.
pub const FIELD_RES_RANGE: std::ops::RangeInclusive<usize> = 16..=2048;
/// Default gRPC port (Rerun's own default).
pub const DEFAULT_PORT: u16 = 9876;
/// Default port of the web viewer (Rerun's own default).
pub const DEFAULT_WEB_PORT: u16 = 9090;

/// How progress is shown on stderr.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ProgressMode {
    /// A bar on a terminal, plain lines every ~10 s otherwise.
    #[default]
    Auto,
    /// Always the bar (indicatif).
    Bar,
    /// Always plain lines (every ~10 s).
    Lines,
    /// Nothing.
    Off,
}

/// `--serve` settings.
#[derive(Clone, Debug, PartialEq)]
pub struct ServeOptions {
    pub bind: IpAddr,
    pub port: u16,
    /// As accepted by Rerun: "25%", "2GB", "unlimited".
    pub memory_limit: String,
    /// Also serve the Rerun web viewer over HTTP on this port of `bind`, connected to the server
    /// (needs the cargo feature `web`).
    pub web_port: Option<u16>,
}

impl ServeOptions {
    /// The URL a viewer opens: `rerun+http://HOST:PORT/proxy` (127.0.0.1 for an unspecified bind).
    pub fn url(&self) -> String {
        format!("rerun+http://{}/proxy", self.reachable(self.port))
    }

    /// The page a browser opens for the web viewer, `http://HOST:WEB_PORT/?url=` and the
    /// server's [`url`](Self::url) with its `+` escaped (as the Rerun SDK writes it); None
    /// without a web viewer.
    pub fn web_url(&self) -> Option<String> {
        let web = self.reachable(self.web_port?);
        let proxy = self.url().replace('+', "%2B");
        Some(format!("http://{web}/?url={proxy}"))
    }

    /// `port` at the bind address, 127.0.0.1 for an unspecified bind.
    fn reachable(&self, port: u16) -> SocketAddr {
        let host = if self.bind.is_unspecified() {
            IpAddr::from([127, 0, 0, 1])
        } else {
            self.bind
        };
        SocketAddr::new(host, port)
    }
}

/// Validated recording options; everything the logger needs.
///
/// Built by the command line, or directly (tests, benches): [`RecordOptions::default`]
/// records nothing; [`RecordOptions::to_file`] writes one .rrd and shows no progress.
#[derive(Clone, Debug, PartialEq)]
pub struct RecordOptions {
    /// The .rrd file to write (None: no file).
    pub save: Option<PathBuf>,
    /// Host a gRPC server.
    pub serve: Option<ServeOptions>,
    /// Push to an already-running viewer at this URL (never stalls the run; see the crate docs (`lib.rs`)).
    pub connect: Option<String>,
    /// Start a local viewer (`rerun` on PATH) and stream to it.
    pub spawn: bool,
    /// Convective time between field snapshots (> 0).
    pub field_every: f64,
    /// Image pixels along the longer side of `field_window`.
    pub field_res: usize,
    /// Field image window in body coordinates.
    pub field_window: FieldWindow,
    /// Observer frame of streamlines and the speed image.
    pub streamlines_frame: StreamFrame,
    /// Per-step CSV output.
    pub csv: Option<PathBuf>,
    /// The VTK series for ParaView (`--vtk DIR`).
    pub vtk: Option<VtkOptions>,
    /// How progress is shown on stderr.
    pub progress: ProgressMode,
    /// Capacity of the solver → logger channel in messages.
    pub channel_capacity: usize,
    /// At most this many field snapshots queued at once; more are skipped (and counted).
    pub max_fields_in_flight: usize,
    /// Convective time between the plate outlines of the strobe picture.
    pub strobe_every: f64,
    /// The wake pictures.
    pub view: ViewOptions,
    /// A resumed run's CSV starts with the first rows of this earlier CSV (its path and the
    /// checkpoint's step count).
    pub csv_prefix: Option<(PathBuf, u64)>,
    /// The Rerun recording id (None: a new random one); a continuation recording takes its
    /// run's.
    pub recording_id: Option<String>,
}

impl Default for RecordOptions {
    fn default() -> Self {
        Self {
            save: None,
            serve: None,
            connect: None,
            spawn: false,
            field_every: DEFAULT_FIELD_EVERY,
            field_res: DEFAULT_FIELD_RES,
            field_window: FieldWindow::default(),
            streamlines_frame: StreamFrame::default(),
            csv: None,
            vtk: None,
            progress: ProgressMode::Off,
            channel_capacity: 1024,
            max_fields_in_flight: 4,
            strobe_every: 0.5,
            view: ViewOptions::default(),
            csv_prefix: None,
            recording_id: None,
        }
    }
}

impl RecordOptions {
    /// Only a file sink at `path`, no progress output, default cadence and resolution.
    pub fn to_file(path: impl Into<PathBuf>) -> Self {
        Self {
            save: Some(path.into()),
            ..Self::default()
        }
    }

    /// True if anything at all is recorded or streamed.
    pub fn has_rerun_sink(&self) -> bool {
        self.save.is_some() || self.serve.is_some() || self.connect.is_some() || self.spawn
    }
}
