//! Recording: the logger thread beside the solver, CSV, progress, and (cargo feature `viewer`,
//! on by default) the Rerun sinks, scene and blueprint in [`viewer`].
//!
//! # Contract with the solver
//!
//! ```ignore
//! let opts = cli_args.record.resolve(case, &[("--summary", p)])?; // checked first
//! let info = RunInfo::new(&config, command_line, version);  // the view defaults, the end time
//! let mut logger = platefall_record::spawn_logger(opts, info)?; // opens sinks, starts the thread
//! loop {
//!     /* advance one step */
//!     logger.step(sample)?;                  // blocking send (never dropped); fails if an output failed
//!     if logger.field_due(sample.t) {        // the field cadence (--field-every)
//!         logger.offer_field(snapshot);      // non-blocking; false = skipped (counted)
//!     }
//! }
//! let report = logger.finish(outcome)?;      // finalises and renames every complete output
//! for e in &report.errors { eprintln!("error: {e}"); } // outputs that could not be written
//! for line in report.lines() { eprintln!("{line}"); }
//! report.serve_until_interrupted(&stop)?;    // --serve: keep serving until Ctrl-C sets `stop`
//! ```
//!
//! - The solver thread only moves plain data ([`messages`]) into a bounded crossbeam channel
//!   (`RecordOptions::channel_capacity`, default 1024 messages). Everything else — painting the
//!   fields ([`platefall_post`]), Rerun, CSV, progress — runs on the logger thread, which alone owns
//!   the `RecordingStream` and sets its (per-thread) time.
//! - At most `max_fields_in_flight` (default 4) snapshots are queued at once, so memory stays
//!   bounded; more are skipped and counted. The count is in the recording (`/run/skipped_fields`
//!   scalar, a warning line in `/run/status`, and `/run/summary`) and in [`LoggerReport`].
//! - Dropping the [`Logger`] without `finish` (an error path, a panic) still finalises every
//!   sink; the recording then says "interrupted".
//!
//! # Sinks (any combination in one run)
//!
//! - `--save FILE.rrd` (default `recordings/<case>.rrd`; `--no-save` for none): Rerun's encoder
//!   (LZ4-compressed chunks) writing through [`output::PendingFile`] under a temporary name
//!   (`viewer/rrd_file.rs`); a write error stops the run; at `finish` the footer is written and
//!   the file renamed into place, on every exit path but a kill, so `rerun rrd verify` passes on
//!   every .rrd at a final name.
//!
//! - `--vtk DIR [--vtk-every T]`: the flow on the solver's grid, placed at the plate's pose, and
//!   the plate's outline, one `.vts` and one `.vtp` per snapshot with a `.pvd` collection for
//!   ParaView ([`vtk`]); written on the logger thread, each file atomically.
//!
//! # Outputs and failures
//!
//! Every output (recording, CSV, the summary the command line writes, a sweep's files and its
//! `phase.rrd`) goes through [`output::PendingFile`]: temporary name, sync, rename when
//! complete. The logger notices a
//! failed write at once and a file removed from under it within a second
//! ([`LoggerReport::errors`], [`Logger::output_failure`]); [`Logger::step`] then fails, so the
//! solver stops instead of computing what cannot be kept.
//! - `--serve [--bind 127.0.0.1] [--port 9876] [--server-memory-limit 25%]`: a gRPC server
//!   (`GrpcServerSink`); viewers run `rerun rerun+http://HOST:PORT/proxy`, also after the run
//!   (history kept up to the memory limit), until Ctrl-C.
//! - `--web [--web-port 9090]` (cargo feature `web`): the Rerun web viewer served over HTTP on
//!   the same bind address, next to the `--serve` server it reads from
//!   (`ServeOptions::web_port`); a browser opens `ServeOptions::web_url`. No browser is ever
//!   started.
//! - `--connect URL`: push to an already-running viewer. Rerun's `GrpcSink` blocks once its queue
//!   fills while no viewer listens; here it sits behind a bounded, never-blocking queue on its own
//!   thread (`sinks::DetachedGrpcSink`): if the viewer is missing, slow or goes away, messages for
//!   it are dropped (counted, reported), and neither the solver nor the file ever wait for it.
//! - `--spawn`: start a local viewer (`rerun` on PATH, checked before the run) and stream to it;
//!   with `--serve` the viewer is pointed at our server instead.
//!
//! # Timelines
//!
//! `time`: convective time t·U/c as a duration timeline (the viewer shows it as seconds, so
//! playback at 1× runs one c/U per second); `step`: the solver step (sequence). The blueprint
//! opens on `time`.
//!
//! # Entity layout (stable)
//!
//! ```text
//! /world                          inertial frame, physical coordinates: Y up, gravity −Y
//! /world/plate                    Transform3D: translation (X, Y), rotation θ about z (every
//!                                 0.01 c/U and at every field snapshot)
//! /world/plate/outline            LineStrips2D, the plate in body coordinates (static): outline
//!                                 (constant screen width) + centreline of the plate's thickness
//! /world/plate/vorticity          DepthImage (f16) of ω, body coordinates, CyanToYellow, ±10
//! /world/plate/pressure           DepthImage (f16) of p, Spectral, ±1.5
//! /world/plate/speed              DepthImage (f16) of |u − w| in the streamline frame, Viridis, [0, 2]
//!                                 (each image: static Transform3D = window corner + pixel size;
//!                                  NaN inside the plate)
//! /world/plate/streamlines        LineStrips2D, contours of the relative stream function ψ − ψ_w
//! /world/wake                     Transform3D at every field snapshot: translation (X, Y) and
//!                                 rotation by the path heading (the direction of the centre's
//!                                 last 4 chords of path); children are in this path frame
//! /world/wake/vorticity           DepthImage (f16) of ω over the wake window (default: static,
//!                                 forced x in [−8, 2], y in [−2.5, 2.5]; pinned, free [−10, 2] ×
//!                                 [−3, 3]; the wake at negative x), same scale as the close-up,
//!                                 values rounded to 1/256 of it; NaN outside the grid and plate
//! /world/wake/pressure            DepthImage (f16) of p over the wake window
//! /world/wake/speed               DepthImage (f16) of |u − w| over the wake window
//! /world/wake/plate               LineStrips2D at every snapshot: the plate as it was then, in
//!                                 the path frame (the wake view draws this one)
//! /world/wake/screen              Transform3D scale (1, −1) (static): origin of the wake view
//! /world/trajectory/NNNN          LineStrips2D, the centre's path, one entity per time segment
//! /world/strobe/NNNN              LineStrips2D, plate outlines every 0.5 c/U along the path
//! /world/follow                   Transform3D with the poses: translation (X, Y), scale (1, −1):
//!                                 a non-rotating frame on the plate, Y mirrored for the screen
//! /world/follow/reach             LineStrips2D, faint circle swept by the image window (static)
//! /world/follow/legend/FIELD/bar  DepthImage colour bar of FIELD (vorticity, pressure, speed) in
//!                                 the view's screen coordinates, and in .../text its line of
//!                                 text: name, unit, range (static; `viewer/legend.rs`)
//! /world/follow/legend/caption    Points2D label: the close-up's caption (static)
//! /world/wake/screen/legend/...   the same for the wake views
//! /world/screen                   Transform3D scale (1, −1): the inertial frame for the screen
//! /coefficients/{cl,cd,cm}        Scalars per step (SeriesLines: C_L, C_D, C_M)
//! /motion/{speed,omega,gamma,alpha}  Scalars per step (V, dθ/dt, γ, α; radians; the angles
//!                                 styled as SeriesPoints, the others as SeriesLines)
//! /solver/dt                      Scalars per step
//! /polar/coefficients/{cl,cd,cm}/NNNN  LineStrips2D of (2α, C) grown over time (x = 2α
//!                                      widens the α axis; values clipped to ±10)
//! /polar/motion/{speed,omega}/NNNN     LineStrips2D of (2α, V) and (2α, dθ/dt)
//! /polar/axes                     static axes and tick labels of the α plots
//! /polar/screen                   Transform3D scale (1, −1) for the α plots
//! /run/config                     TextDocument (markdown): title, version, command line, config JSON
//! /run/summary                    TextDocument: outcome, report, summary JSON, skipped snapshots
//! /run/invocation                 TextDocument (JSON): version and commit, arguments, directory,
//!                                 input files, case, title, configuration (`provenance`)
//! /run/summary_json, /run/report  TextDocument: the summary JSON and the report, at the end
//! /run/status                     TextLog: started / skipped-snapshot warnings / completed,
//!                                 diverged or interrupted
//! /run/skipped_fields             Scalars at every field snapshot: snapshots skipped so far
//! ```
//! The 2D view draws +y downwards, so the views look at the data through the mirrored frames
//! (`/world/follow`, `/world/screen`, `/world/wake/screen`, `/polar/screen`) instead of mirroring
//! the data: the data stay in physical coordinates and the picture has Y up, gravity down (the
//! wake view has the path along +x: for a free fall it is turned by the glide angle).
//!
//! The blueprint (`viewer/blueprint.rs`) opens the coefficient, motion and α plots on ranges
//! chosen from the case (`platefall_post::ViewDefaults`, from `RunInfo::view`: the developed
//! motion inside, the impulsive-start spike outside) and the wake and close-up views on fixed
//! bounds; these are view properties in the blueprint store (`view/<id>/ScalarAxis`,
//! `view/<id>/VisualBounds2D`). At the end of a run the layout is sent again, made active, with
//! the trajectory view's bounds holding the whole path and every wake window (`viewer/extent.rs`).
//!
//! The "growing" curves (trajectory, strobe, α plots) are split into segments of
//! max(2, t_end/40) c/U, one entity each, re-sent only while their segment grows, so the total
//! size stays linear in the run length and scrubbing shows the curve up to the cursor.
//!
//! # Size budget (measured, N = 32 card free fall, LZ4 file)
//!
//! - A field snapshot: three f16 images (256 × 197 px by default, values rounded to 1/1024 of
//!   their colour range first, which halves the compressed size) plus the streamlines:
//!   ≈ 0.11 MB in a developed wake; ≈ 0.03 MB at `--field-res 128`.
//! - A step: ≈ 0.25 kB (eight scalar series, each row carrying a row id and both time indices;
//!   rows are sent in chunks of up to 4 s, 1 s when a viewer watches live).
//! - The default free fall (`platefall free`: 10 turns, t ≈ 27, 62.6k steps, 273 snapshots at
//!   `--field-every 0.1`) is 47 MB. A 60 c/U run is ≈ 600 × 0.11 MB + steps × 0.25 kB: 70 MB at
//!   15k steps, ≈ 105 MB at this solver's ~2300 steps per c/U; within the 200 MB budget.
//! - For a bug report (< 20 MB): `--field-every 0.5 --field-res 128` gives 17.7 MB for the default
//!   free fall (57 snapshots; the 62.6k steps are 16 MB of it). Longer runs: also shorten
//!   `--t-end` / `--turns`, since the per-step series dominate.
#![warn(missing_docs)]

pub mod cadence;
pub mod checkpoint;
pub mod checkpoint3;
mod csv;
pub mod csv3;
pub mod files;
mod inject;
mod logger;
pub mod messages;
pub mod messages3;
pub mod options;
pub mod output;
pub mod progress;
pub mod provenance;
pub mod recorded;
pub mod recorder3;
pub mod view_options;
#[cfg(feature = "viewer")]
pub mod viewer;
#[cfg(not(feature = "viewer"))]
#[path = "viewer_off.rs"]
pub mod viewer;
pub mod vtk;

pub use cadence::Cadence;
pub use csv::{check_prefix as check_csv_prefix, CsvPrefixError, CSV_HEADER, CSV_TRAILER};
pub use logger::{spawn_logger, Logger, LoggerReport};
pub use messages::ConnectReport;
pub use options::{
    ProgressMode, RecordOptions, ServeOptions, DEFAULT_FIELD_EVERY, DEFAULT_FIELD_RES,
    DEFAULT_WEB_PORT,
};
pub use view_options::{ViewOptions, DEFAULT_WAKE_RES};
#[cfg(feature = "viewer")]
pub use viewer::{paths, APPLICATION_ID};
