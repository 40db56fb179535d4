//! The added-mass matrix K of strong coupling (`flow::added_mass`: the discrete flow's pressure
//! answer to a unit change of the plate's motion) against potential-flow theory for an ellipse
//! of semi-axes a (along the chord) and b: added masses π ρ b² along the major axis, π ρ a²
//! across it, and π ρ (a² − b²)²/8 in pitch (per unit span; Lamb, *Hydrodynamics*, §71–72).
use std::f64::consts::PI;

use platefall_core::flow::{AddedMass, FlowParams, FlowSolver, Frame, OuterBc};
use platefall_core::grid::{Grid, GridSpec, Stretch};
use platefall_core::shape::Shape;

fn k_matrix(shape: Shape, n: usize) -> AddedMass {
    let spec = GridSpec {
        resolution: n,
        shape,
        extent_x: 15.0,
        extent_y: 15.0,
        stretch: Stretch::GrowthCap(1.045),
    };
    let grid = Grid::new(&spec).expect("grid");
    let mut flow = FlowSolver::new(
        grid,
        FlowParams::explicit(5000.0),
        OuterBc::FarField,
        Frame::default(),
    )
    .expect("solver");
    flow.added_mass()
}

/// (along, across, pitch) added masses: −K's diagonal.
fn diagonal(k: &AddedMass) -> [f64; 3] {
    [-k.k[0][0], -k.k[1][1], -k.k[2][2]]
}

fn check_ellipse(ratio: f64, n: usize, tol: f64) {
    let (a, b) = (0.5, 0.5 * ratio);
    let exact = [PI * b * b, PI * a * a, PI * (a * a - b * b).powi(2) / 8.0];
    let got = diagonal(&k_matrix(Shape::Ellipse { thickness: ratio }, n));
    let names = ["along", "across", "pitch"];
    for d in 0..3 {
        if exact[d] == 0.0 {
            eprintln!(
                "b/a = {ratio}, N = {n}: {} {:.5} (exact 0)",
                names[d], got[d]
            );
            assert!(
                got[d].abs() < 1e-3,
                "{} added mass {} of a circle",
                names[d],
                got[d]
            );
            continue;
        }
        let err = got[d] / exact[d] - 1.0;
        eprintln!(
            "b/a = {ratio}, N = {n}: {} {:.5} exact {:.5} ({:+.2} %)",
            names[d],
            got[d],
            exact[d],
            100.0 * err
        );
        assert!(
            err.abs() < tol,
            "b/a = {ratio}: {} added mass off by {:.2} %",
            names[d],
            100.0 * err
        );
    }
}

#[test]
fn circle_added_mass_within_two_percent_at_n64() {
    check_ellipse(1.0, 64, 0.02);
}

#[test]
fn half_ellipse_added_mass_within_two_percent_at_n64() {
    check_ellipse(0.5, 64, 0.02);
}

#[test]
fn eighth_ellipse_added_mass_within_two_percent_at_n64() {
    check_ellipse(0.125, 64, 0.02);
}

mod panels;

/// Panels of the potential-flow reference (its error is a few 10⁻⁴ with this many).
const PANELS: usize = 1200;

#[test]
fn the_panel_reference_reproduces_the_ellipse() {
    // The reference itself, against the exact values, on ellipses of 1/2 and 1/8.
    for ratio in [0.5, 0.125] {
        let (a, b) = (0.5, 0.5 * ratio);
        let outline = Shape::Ellipse { thickness: ratio }.outline();
        let m = panels::added_mass(&panels::panelled(outline.points(), PANELS));
        let exact = [PI * b * b, PI * a * a, PI * (a * a - b * b).powi(2) / 8.0];
        for d in 0..3 {
            let err = m[d][d] / exact[d] - 1.0;
            eprintln!(
                "panels, b/a = {ratio}: m[{d}][{d}] = {:.6} exact {:.6} ({:+.3} %)",
                m[d][d],
                exact[d],
                100.0 * err
            );
            assert!(
                err.abs() < 2e-3,
                "the panel reference is off by {:.3} %",
                100.0 * err
            );
        }
    }
}

/// K of a shape at N = 64 against the panel reference for the same outline, within `tol`.
fn against_panels(shape: Shape, tol: f64) {
    let outline = shape.outline();
    let reference = panels::added_mass(&panels::panelled(outline.points(), PANELS));
    let got = diagonal(&k_matrix(shape.clone(), 64));
    for d in 0..3 {
        let err = got[d] / reference[d][d] - 1.0;
        eprintln!(
            "{}: m[{d}][{d}] {:.5} panels {:.5} ({:+.2} %)",
            shape.describe(),
            got[d],
            reference[d][d],
            100.0 * err
        );
        assert!(
            err.abs() < tol,
            "{}: m[{d}][{d}] off by {:.2} %",
            shape.describe(),
            100.0 * err
        );
    }
}

#[test]
fn rounded_plate_added_mass_within_two_percent_of_the_potential_solution() {
    against_panels(
        Shape::Rounded {
            thickness: 0.125,
            radius: 0.0625,
        },
        0.02,
    );
}
