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
    /// The address the gRPC server (and the web viewer) bind to (`--bind`, 127.0.0.1 by default).
    pub bind: IpAddr,
    /// The gRPC server's TCP port (`--port`).
    pub port: u16,
    /// As accepted by Rerun: "25%", "2GB", "unlimited".
    pub memory_limit: String,
    /// Also serve the Rerun web viewer over HTTP on this port of `bind`, connected to the server
    /// (needs the cargo feature `web`).
    pub web_port: Option<u16>,
}

impl ServeOptions {
    /// The URL a viewer opens: `rerun+http://HOST:PORT/proxy`, HOST the bind address, or for an
    /// unspecified bind (0.0.0.0, ::) this machine's host name, which other machines on its
    /// network can use (127.0.0.1 when it has none).
    pub fn url(&self) -> String {
        format!("rerun+http://{}/proxy", self.advertised(self.port))
    }

    /// The URL a viewer on this machine opens (127.0.0.1 for an unspecified bind).
    pub fn local_url(&self) -> String {
        let host = if self.bind.is_unspecified() {
            IpAddr::from([127, 0, 0, 1])
        } else {
            self.bind
        };
        format!("rerun+http://{}/proxy", SocketAddr::new(host, self.port))
    }

    /// The page a browser opens for the web viewer, `http://HOST:WEB_PORT/?url=` and the
    /// server's [`url`](Self::url) with its `+` escaped (as the Rerun SDK writes it); None
    /// without a web viewer. The page and the server it names have the same HOST.
    pub fn web_url(&self) -> Option<String> {
        let web = self.advertised(self.web_port?);
        let proxy = self.url().replace('+', "%2B");
        Some(format!("http://{web}/?url={proxy}"))
    }

    /// `HOST:PORT` as [`url`](Self::url) names it.
    fn advertised(&self, port: u16) -> String {
        match (self.bind.is_unspecified(), host_name()) {
            (true, Some(name)) => format!("{name}:{port}"),
            (true, None) => SocketAddr::new(IpAddr::from([127, 0, 0, 1]), port).to_string(),
            (false, _) => SocketAddr::new(self.bind, port).to_string(),
        }
    }
}

/// This machine's host name, if it has one that can stand in a URL.
#[cfg(unix)]
fn host_name() -> Option<String> {
    let mut buf = [0u8; 256];
    // SAFETY: gethostname writes at most `buf.len()` bytes into `buf`, which outlives the call.
    let rc = unsafe { libc::gethostname(buf.as_mut_ptr().cast(), buf.len()) };
    let end = buf.iter().position(|&b| b == 0)?;
    let name = std::str::from_utf8(&buf[..end]).ok()?;
    let usable = |c: char| c.is_ascii_alphanumeric() || c == '-' || c == '.';
    (rc == 0 && !name.is_empty() && name.chars().all(usable)).then(|| name.to_string())
}

/// This machine's host name (none looked up off Unix).
#[cfg(not(unix))]
fn host_name() -> Option<String> {
    None
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

#[cfg(test)]
mod tests {
    use super::*;

    fn serve(bind: &str, web_port: Option<u16>) -> ServeOptions {
        ServeOptions {
            bind: bind.parse().unwrap(),
            port: 9876,
            memory_limit: "25%".into(),
            web_port,
        }
    }

    #[test]
    fn a_bound_address_is_named_in_every_url() {
        let s = serve("10.1.2.3", Some(9090));
        assert_eq!(s.url(), "rerun+http://10.1.2.3:9876/proxy");
        assert_eq!(s.local_url(), s.url());
        assert_eq!(
            s.web_url().unwrap(),
            "http://10.1.2.3:9090/?url=rerun%2Bhttp://10.1.2.3:9876/proxy"
        );
        assert_eq!(serve("::1", None).url(), "rerun+http://[::1]:9876/proxy");
        assert_eq!(serve("::1", None).web_url(), None);
    }

    /// Bound to every interface, the URLs name the machine as others reach it (its host name),
    /// the page and the server alike; a viewer started here uses loopback.
    #[test]
    fn an_unspecified_bind_names_this_host() {
        let s = serve("0.0.0.0", Some(9090));
        let host = host_name().unwrap_or_else(|| "127.0.0.1".into());
        assert_ne!(host, "0.0.0.0");
        assert_eq!(s.url(), format!("rerun+http://{host}:9876/proxy"));
        assert_eq!(
            s.web_url().unwrap(),
            format!("http://{host}:9090/?url=rerun%2Bhttp://{host}:9876/proxy")
        );
        assert_eq!(s.local_url(), "rerun+http://127.0.0.1:9876/proxy");
        assert_eq!(
            serve("::", None).local_url(),
            "rerun+http://127.0.0.1:9876/proxy"
        );
    }
}
