//! The Rerun sinks of one run: file, gRPC server (--serve, with the --web viewer beside it),
//! gRPC client (--connect / --spawn).
//!
//! All sinks hang off one `RecordingStream` through a `MultiSink`. The file is our own
//! [`RrdSink`] (`rrd_file.rs`): written under a temporary name, its errors seen by the logger,
//! committed on its own while the server keeps serving.
//!
//! The gRPC *client* (`GrpcSink`) blocks its caller once its queue (100 messages) fills while no
//! viewer is listening, and its `Drop` flushes with no time limit. Both would stall the file sink
//! that shares the stream's sink thread. So it is wrapped in [`DetachedGrpcSink`]: a bounded
//! queue in front of a forwarding thread that alone talks to the `GrpcSink`. Sending never blocks
//! (a full queue drops the message and counts it), flushing waits at most a few seconds, and at
//! the end a forwarder that is stuck on a dead connection is left behind instead of joined.
use std::str::FromStr as _;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use anyhow::Context as _;
use crossbeam_channel::{bounded, Receiver, Sender, TrySendError};
use rerun::log::LogMsg;
use rerun::sink::{GrpcSink, GrpcSinkConnectionState, LogSink, SinkFlushError};

use super::rrd_file::{RrdFile, RrdSink};
use super::web::{host_web_viewer, WebServer};
use crate::options::RecordOptions;

/// Messages queued for a --connect viewer before further ones are dropped.
const CONNECT_QUEUE: usize = 512;
/// Messages Rerun's gRPC client queues before `send` blocks (its channel holds 100); we hand it
/// fewer while no viewer is connected.
const CLIENT_QUEUE: usize = 90;
/// Longest a flush waits for the --connect viewer.
const CONNECT_FLUSH_LIMIT: Duration = Duration::from_secs(3);
/// Longest the end of the run waits for the --connect forwarder to hand over its queue.
const CONNECT_SHUTDOWN_LIMIT: Duration = Duration::from_secs(5);

/// Counters of a [`DetachedGrpcSink`], shared with the logger for the final report.
#[derive(Debug, Default)]
pub(crate) struct ConnectStats {
    pub sent: AtomicU64,
    pub dropped: AtomicU64,
    pub ever_connected: AtomicBool,
}

enum Cmd {
    Msg(LogMsg),
    Flush(Sender<()>),
}

/// A `GrpcSink` behind a bounded, never-blocking queue; see the module docs.
pub(crate) struct DetachedGrpcSink {
    tx: Mutex<Option<Sender<Cmd>>>,
    done: Receiver<()>,
    thread: Mutex<Option<std::thread::JoinHandle<()>>>,
    stats: Arc<ConnectStats>,
}

impl DetachedGrpcSink {
    pub fn new(url: &str) -> anyhow::Result<(Self, Arc<ConnectStats>)> {
        let uri = rerun::external::re_uri::ProxyUri::from_str(url)
            .map_err(|e| anyhow::anyhow!("--connect {url:?}: {e}"))?;
        let (tx, rx) = bounded::<Cmd>(CONNECT_QUEUE);
        let (done_tx, done) = bounded::<()>(1);
        let stats = Arc::new(ConnectStats::default());
        let st = stats.clone();
        let thread = std::thread::Builder::new()
            .name("platefall-connect".into())
            .spawn(move || {
                let sink = GrpcSink::new(uri);
                // Messages handed to the client while no viewer is connected: the client queues
                // CLIENT_QUEUE of them and then blocks, so stop short of that until it connects.
                let mut unconnected = 0usize;
                for cmd in rx {
                    match cmd {
                        Cmd::Msg(msg) => match sink.status() {
                            GrpcSinkConnectionState::Connected => {
                                unconnected = 0;
                                sink.send(msg);
                                st.sent.fetch_add(1, Ordering::Relaxed);
                            }
                            GrpcSinkConnectionState::Connecting { .. }
                                if unconnected < CLIENT_QUEUE =>
                            {
                                unconnected += 1;
                                sink.send(msg);
                                st.sent.fetch_add(1, Ordering::Relaxed);
                            }
                            _ => {
                                st.dropped.fetch_add(1, Ordering::Relaxed);
                            }
                        },
                        Cmd::Flush(ack) => {
                            // Only wait for a viewer that is actually there.
                            if sink.status() == GrpcSinkConnectionState::Connected {
                                let _ = sink.flush_blocking(CONNECT_FLUSH_LIMIT);
                            }
                            let _ = ack.send(());
                        }
                    }
                    if sink.status() == GrpcSinkConnectionState::Connected {
                        st.ever_connected.store(true, Ordering::Relaxed);
                    }
                }
                // The queue is closed: hand the rest to the viewer if there is one. A sink that
                // never connected would block forever in its Drop (unbounded flush), so leak it;
                // the process ends soon anyway.
                if sink.status() == GrpcSinkConnectionState::Connected {
                    let _ = sink.flush_blocking(CONNECT_FLUSH_LIMIT);
                    let _ = done_tx.send(());
                    drop(sink);
                } else {
                    let _ = done_tx.send(());
                    std::mem::forget(sink);
                }
            })
            .context("cannot start the --connect forwarding thread")?;
        Ok((
            Self {
                tx: Mutex::new(Some(tx)),
                done,
                thread: Mutex::new(Some(thread)),
                stats: stats.clone(),
            },
            stats,
        ))
    }

    fn sender(&self) -> Option<Sender<Cmd>> {
        self.tx.lock().ok().and_then(|g| g.clone())
    }
}

impl LogSink for DetachedGrpcSink {
    fn send(&self, msg: LogMsg) {
        let Some(tx) = self.sender() else { return };
        match tx.try_send(Cmd::Msg(msg)) {
            Ok(()) => {}
            Err(TrySendError::Full(_)) | Err(TrySendError::Disconnected(_)) => {
                self.stats.dropped.fetch_add(1, Ordering::Relaxed);
            }
        }
    }

    fn flush_blocking(&self, timeout: Duration) -> Result<(), SinkFlushError> {
        let Some(tx) = self.sender() else {
            return Ok(());
        };
        let (ack_tx, ack_rx) = bounded(1);
        if tx.try_send(Cmd::Flush(ack_tx)).is_err() {
            return Err(SinkFlushError::Timeout);
        }
        ack_rx
            .recv_timeout(timeout.min(CONNECT_FLUSH_LIMIT + Duration::from_secs(1)))
            .map_err(|_| SinkFlushError::Timeout)
    }
}

impl Drop for DetachedGrpcSink {
    fn drop(&mut self) {
        if let Ok(mut g) = self.tx.lock() {
            g.take(); // closes the queue: the forwarder drains it and stops
        }
        let handle = self.thread.lock().ok().and_then(|mut g| g.take());
        if self.done.recv_timeout(CONNECT_SHUTDOWN_LIMIT).is_ok() {
            if let Some(h) = handle {
                // After `done` the forwarder only drops a connected sink (bounded by its flush).
                let _ = h.join();
            }
        }
        // else: stuck on a dead connection; leave the thread behind.
    }
}

/// The sinks of a run and how to report on them.
pub(crate) struct SinkSet {
    pub sinks: Vec<Box<dyn LogSink>>,
    /// The .rrd file being written (--save).
    pub rrd: Option<Arc<RrdFile>>,
    /// URL viewers open for --serve.
    pub serve_url: Option<String>,
    /// The web viewer next to the --serve server (--web).
    pub web: Option<WebServer>,
    /// Where --connect / --spawn streams, and its counters.
    pub connect: Option<(String, Arc<ConnectStats>)>,
    /// Warnings to show at the end (e.g. the viewer could not be started).
    pub notes: Vec<String>,
}

/// Opens every sink asked for in `opts`. Errors are one line naming the option.
pub(crate) fn open_sinks(opts: &RecordOptions) -> anyhow::Result<SinkSet> {
    let mut set = SinkSet {
        sinks: Vec::new(),
        rrd: None,
        serve_url: None,
        web: None,
        connect: None,
        notes: Vec::new(),
    };
    if let Some(path) = &opts.save {
        let file = RrdFile::create("--save", path)?;
        set.sinks.push(Box::new(RrdSink(file.clone())));
        set.rrd = Some(file);
    }
    if let Some(serve) = &opts.serve {
        let memory_limit = rerun::MemoryLimit::parse(&serve.memory_limit)
            .map_err(|e| anyhow::anyhow!("--server-memory-limit {:?}: {e}", serve.memory_limit))?;
        let server_options = rerun::ServerOptions {
            memory_limit,
            ..Default::default()
        };
        let sink = rerun::grpc_server::GrpcServerSink::new(
            &serve.bind.to_string(),
            serve.port,
            server_options,
        )
        .map_err(|e| anyhow::anyhow!("--bind {} --port {}: {e}", serve.bind, serve.port))?;
        set.serve_url = Some(serve.url());
        set.sinks.push(Box::new(sink));
        set.web = host_web_viewer(serve)?;
    }

    let mut connect_url = opts.connect.clone();
    if opts.spawn {
        match spawn_viewer(opts) {
            Ok(Some(url)) => connect_url = Some(url),
            Ok(None) => {} // the viewer reads from our --serve server
            Err(e) => set.notes.push(format!("--spawn: {e}")),
        }
    }
    if let Some(url) = connect_url {
        let (sink, stats) = DetachedGrpcSink::new(&url)?;
        set.connect = Some((url, stats));
        set.sinks.push(Box::new(sink));
    }
    Ok(set)
}

/// Starts a local viewer. With --serve it is pointed at our server (returns None); otherwise it
/// listens on Rerun's default port and we connect to it (returns its URL).
fn spawn_viewer(opts: &RecordOptions) -> anyhow::Result<Option<String>> {
    let mut spawn = rerun::SpawnOptions {
        wait_for_bind: true,
        ..Default::default()
    };
    if let Some(serve) = &opts.serve {
        // The viewer's own server needs a port of its own; it connects to ours.
        let free = std::net::TcpListener::bind("127.0.0.1:0")?
            .local_addr()?
            .port();
        spawn.port = free;
        spawn.extra_args = vec![serve.local_url()];
        rerun::spawn(&spawn)?;
        Ok(None)
    } else {
        let info = rerun::spawn(&spawn)?;
        Ok(Some(format!("rerun+http://127.0.0.1:{}/proxy", info.port)))
    }
}
