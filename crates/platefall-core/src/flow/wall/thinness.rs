//! Whether the grid can follow the plate (docs/physics.md §4): a plate thinner somewhere than the
//! grid's spacing leaves a face with fluid on both sides of the plate, which the wall treatment
//! cannot represent. Whoever builds the grid for a flow checks its description here first.
use super::faces::{Faces, ON_BOUNDARY};
use super::lines::Lines;
use crate::grid::{Grid, GridSpec};
use crate::param::InputError;

/// The largest resolution searched for one that follows the plate.
const MAX_RESOLUTION: usize = 1024;

/// Refuses a plate thinner somewhere than the grid of `spec` can follow (a grid face that would
/// see fluid on both sides of the plate), naming the smallest resolution that follows it. A
/// rectangle is followed at every resolution (the grid is fitted to it).
///
/// # Errors
/// [`InputError::TooThin`] with the first such face's point and the smallest resolution that
/// follows the plate, if any up to 1024 does.
pub fn check_representable(spec: &GridSpec) -> Result<(), InputError> {
    if spec.shape.fits_grid() {
        return Ok(());
    }
    let Some(at) = defect_at(spec, spec.resolution) else {
        return Ok(());
    };
    let smallest = match smallest_followed(spec) {
        Some(n) => format!("the smallest resolution that follows it is {n} (--resolution {n})"),
        None => {
            "no resolution up to 1024 follows it; give the section a thicker part there".to_string()
        }
    };
    Err(InputError::TooThin {
        resolution: spec.resolution,
        x: at[0],
        y: at[1],
        smallest,
    })
}

/// The smallest resolution above `spec`'s that follows the plate: up in steps of a quarter to
/// the first that works, then back to the smallest.
fn smallest_followed(spec: &GridSpec) -> Option<usize> {
    let mut hi = spec.resolution;
    let found = loop {
        hi = ((hi as f64 * 1.25).ceil() as usize).min(MAX_RESOLUTION);
        if defect_at(spec, hi).is_none() {
            break Some(hi);
        }
        if hi >= MAX_RESOLUTION {
            break None;
        }
    };
    found.map(|hi| {
        (spec.resolution + 1..hi)
            .find(|&n| defect_at(spec, n).is_none())
            .unwrap_or(hi)
    })
}

/// The first face where the plate of `spec` at `resolution` is thinner than the grid can follow.
fn defect_at(spec: &GridSpec, resolution: usize) -> Option<[f64; 2]> {
    let spec = GridSpec {
        resolution,
        ..spec.clone()
    };
    Grid::new(&spec).ok().and_then(|g| first_defect(&g))
}

/// Where the plate of `grid` is thinner than the grid can follow (a face with fluid on both
/// sides of the plate), if anywhere: the first such face's point.
fn first_defect(grid: &Grid) -> Option<[f64; 2]> {
    let body = grid.body.as_ref()?;
    let lines = Lines::new(grid, body);
    let faces = Faces::new(grid, body, &lines, ON_BOUNDARY * grid.h);
    faces.defects.first().map(|d| d.at)
}
