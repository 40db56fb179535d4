//! View properties that the Rust blueprint API of Rerun 0.36 does not expose — a time-series
//! view's y range (`ScalarAxis`) and a 2-D view's visual bounds (`VisualBounds2D`) — sent in the
//! same blueprint store as the layout.
//!
//! The viewer reads a view's property archetype from the blueprint entity
//! `view/<id>/<ArchetypeName>` (as the Python API writes it). [`Blueprint::send`] makes a fresh
//! blueprint store each time, so the layout is first serialised into memory, the properties are
//! logged into a second stream with the same store id, and both go out together ahead of one
//! activation command.
use rerun::blueprint::{Blueprint, BlueprintActivation, ContainerLike};
use rerun::external::re_log_types::BlueprintActivationCommand;
use rerun::external::re_sdk_types::blueprint::archetypes::{ScalarAxis, VisualBounds2D};
use rerun::external::re_sdk_types::blueprint::components::LockRangeDuringZoom;
use rerun::external::re_sdk_types::datatypes::{Range1D, Range2D};
use rerun::external::re_sdk_types::{AsComponents, SerializedComponentBatch};
use rerun::log::LogMsg;
use rerun::{RecordingStream, RecordingStreamBuilder, RecordingStreamResult, StoreKind};

use super::layout::APPLICATION_ID;

/// Properties to set on views of a blueprint, by the views' blueprint paths.
#[derive(Default)]
pub(super) struct ViewProperties(Vec<(String, Vec<SerializedComponentBatch>)>);

impl ViewProperties {
    fn add(&mut self, view: &ContainerLike, archetype: &str, value: &dyn AsComponents) {
        if let ContainerLike::View(v) = view {
            let path = format!("{}/{archetype}", v.blueprint_path());
            self.0.push((path, value.as_serialized_batches()));
        }
    }

    /// The y range a time-series `view` opens on; zooming and panning stay free.
    pub(super) fn y_range(&mut self, view: &ContainerLike, [lo, hi]: [f64; 2]) {
        let axis = ScalarAxis::new()
            .with_range(Range1D([lo, hi]))
            .with_zoom_lock(LockRangeDuringZoom(false.into()));
        self.add(view, "ScalarAxis", &axis);
    }

    /// The region a 2-D `view` shows, in the coordinates of its origin.
    pub(super) fn bounds(&mut self, view: &ContainerLike, x: [f64; 2], y: [f64; 2]) {
        let range = Range2D {
            x_range: Range1D(x),
            y_range: Range1D(y),
        };
        self.add(view, "VisualBounds2D", &VisualBounds2D::new(range));
    }
}

/// Sends `blueprint` with `props` to `rec` as one blueprint store, made active and default.
pub(super) fn send_with_properties(
    rec: &RecordingStream,
    blueprint: &Blueprint,
    props: &ViewProperties,
) -> RecordingStreamResult<()> {
    let (scratch, storage) = RecordingStreamBuilder::new(APPLICATION_ID)
        .blueprint()
        .send_properties(false)
        .memory()?;
    blueprint.send(&scratch, BlueprintActivation::default())?;
    let _ = scratch.flush_blocking();
    let mut activation = None;
    let mut msgs = Vec::new();
    for msg in storage.take() {
        match msg {
            LogMsg::BlueprintActivationCommand(cmd) => activation = Some(cmd),
            other => msgs.push(other),
        }
    }
    let Some(activation) = activation else {
        return Ok(());
    };
    // The layout's own store only (the scratch stream announces itself too).
    msgs.retain(|m| m.store_id() == &activation.blueprint_id);
    msgs.extend(property_messages(&activation, props)?);
    rec.send_blueprint(msgs, activation);
    Ok(())
}

/// The property rows, logged into the store of `activation` at blueprint time 0.
fn property_messages(
    activation: &BlueprintActivationCommand,
    props: &ViewProperties,
) -> RecordingStreamResult<Vec<LogMsg>> {
    let id = &activation.blueprint_id;
    let (stream, storage) = RecordingStreamBuilder::new(id.application_id().clone())
        .recording_id(id.recording_id().clone())
        .blueprint()
        .send_properties(false)
        .memory()?;
    stream.set_time_sequence("blueprint", 0);
    for (path, batches) in &props.0 {
        stream.log_serialized_batches(path.as_str(), false, batches.iter().cloned())?;
    }
    let _ = stream.flush_blocking();
    Ok(storage
        .take()
        .into_iter()
        .filter(|m| {
            matches!(m, LogMsg::ArrowMsg(..)) && m.store_id().kind() == StoreKind::Blueprint
        })
        .collect())
}
