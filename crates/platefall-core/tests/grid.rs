//! Grid (docs/physics.md §4): the dissertation's stretching figures, monotone spacing, growth within the cap.
use platefall_core::grid::{stretch_coefficient, Grid, GridSpec, Stretch};
use platefall_core::shape::Shape;

#[test]
fn x_stretching_matches_the_dissertation() {
    // h = c/16, 24 intervals over 10 c beyond each plate edge: the dissertation's C_x = 3.157, outer spacing 1.287 c.
    let c = stretch_coefficient(1.0 / 16.0, 10.0, 24).unwrap();
    assert!((c - 3.157).abs() < 5e-4, "C_x = {c}");
    let g = Grid::new(&GridSpec::seed()).unwrap();
    assert!(
        (g.outer_spacing().0 - 1.287).abs() < 5e-4,
        "outer dx = {}",
        g.outer_spacing().0
    );
    assert_eq!(
        g.nx + 1,
        65,
        "the dissertation's grid has 65 points along x"
    );
}

#[test]
fn y_stretching_matches_the_dissertation() {
    // 27 intervals over 10 c above and below: C_y ≈ 2.98, outer spacing ≈ 1.10 c (seed: 2.988, 1.110;
    // the dissertation's exact patch length is not given, hence the looser tolerance).
    let g = Grid::new(&GridSpec::seed()).unwrap();
    let cy = g.cy.unwrap();
    assert!((cy - 2.98).abs() < 0.01, "C_y = {cy}");
    assert!(
        (g.outer_spacing().1 - 1.10).abs() < 0.012,
        "outer dy = {}",
        g.outer_spacing().1
    );
    // The first stretched interval equals h: the map joins the uniform core smoothly.
    let h = 1.0 / 16.0;
    assert!((g.dy[g.j0 - 1] - h).abs() < 1e-12 && (g.dx[g.i0 - 1] - h).abs() < 1e-12);
}

#[test]
fn spacing_is_monotone_and_growth_within_the_cap() {
    for n in [16, 32, 64] {
        let spec = GridSpec::modern(n);
        let cap = match spec.stretch {
            Stretch::GrowthCap(r) => r,
            _ => unreachable!(),
        };
        let g = Grid::new(&spec).unwrap();
        // Spacing decreases towards the plate and increases away from it, on both sides.
        for w in g.dx[..g.i0 + 1].windows(2) {
            assert!(w[1] <= w[0] * (1.0 + 1e-12));
        }
        for w in g.dx[g.i1 - 1..].windows(2) {
            assert!(w[1] >= w[0] * (1.0 - 1e-12));
        }
        assert!(
            g.max_growth() <= cap * (1.0 + 1e-9),
            "N={n}: growth {} > cap {cap}",
            g.max_growth()
        );
        // Extent reached: outer boundary 15 chords from the plate.
        assert!((g.xn[g.nx] - 15.5).abs() < 1e-9 && (g.xn[0] + 15.5).abs() < 1e-9);
        // Plate is a whole number of cells and the chord is N cells.
        assert_eq!(g.i1 - g.i0, n);
        assert!(g.j1 > g.j0);
    }
}

#[test]
fn bad_grid_input_is_refused_with_the_range() {
    let mut s = GridSpec::modern(0);
    let e = Grid::new(&s).unwrap_err().to_string();
    assert!(e.contains("resolution 0") && e.contains("4..=1024"), "{e}");
    s = GridSpec::modern(32);
    s.shape = Shape::rect(f64::NAN);
    assert!(Grid::new(&s).unwrap_err().to_string().contains("thickness"));
    s = GridSpec::modern(32);
    s.stretch = Stretch::GrowthCap(0.9);
    assert!(Grid::new(&s)
        .unwrap_err()
        .to_string()
        .contains("growth cap"));
}

#[test]
fn a_plate_is_the_same_body_at_every_resolution() {
    // t/c = 0.1 is not a whole number of cells at N = 32, 64 or 128 (3.2, 6.4, 12.8): the grid
    // is fitted to the faces, so the plate is exactly 0.1 thick at each.
    for n in [32, 64, 128] {
        let mut spec = GridSpec::modern(n);
        spec.shape = Shape::rect(0.1);
        let g = Grid::new(&spec).unwrap();
        let (top, bottom) = (g.yn[g.j1], g.yn[g.j0]);
        assert!(
            (top - bottom - 0.1).abs() < 1e-12,
            "N = {n}: thickness {}",
            top - bottom
        );
        assert!((top - 0.05).abs() < 1e-12 && (bottom + 0.05).abs() < 1e-12);
        assert!((g.xn[g.i1] - 0.5).abs() < 1e-12 && (g.xn[g.i0] + 0.5).abs() < 1e-12);
        // Outside the plate the first cells are h, as on every grid.
        assert!((g.dy[g.j1] - 1.0 / n as f64).abs() < 1e-12);
    }
}
