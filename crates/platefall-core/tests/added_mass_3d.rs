//! The 3-D flow's added-mass matrix K (docs/three-d.md "Added mass"): the periodic-span plate
//! against two-dimensional potential flow around the same section (the boundary-element solution
//! of `panels`), and the finite plate's symmetries, sign and tip loss.
//!
//! `cargo test --release -p platefall-core --test added_mass_3d -- --nocapture` prints the
//! measured matrices and ratios.
mod panels;

use platefall_core::body::six::{PhysicalPlate6, StrongCoupling6};
use platefall_core::flow3d::{
    AddedMass3, FlowParams3, FlowSolver3, Frame3, Grid3, GridSpec3, OuterBc3, Span, Stretch3,
};
use platefall_core::shape::Shape;

/// Thickness of the test plate (chords): four cells at N = 64, two at N = 32.
const THICKNESS: f64 = 1.0 / 16.0;

/// K of a plate of `THICKNESS` at resolution `n`, 12 chords from the outer boundary in x and y.
fn added_mass(n: usize, span: Span) -> AddedMass3 {
    let grid = Grid3::new(&GridSpec3 {
        resolution: n,
        thickness: THICKNESS,
        span,
        extent: [12.0, 12.0, 6.0],
        stretch: Stretch3::GrowthCap(1.2),
        memory_limit: 4e9,
    })
    .expect("grid");
    let mut flow = FlowSolver3::new(
        grid,
        FlowParams3::default(),
        OuterBc3::FarField,
        Frame3::default(),
    )
    .expect("solver");
    flow.added_mass().expect("added mass")
}

/// The largest |K_ij| off the diagonal over the largest |K_ii|.
fn largest_off_diagonal(k: &[[f64; 6]; 6]) -> f64 {
    let diag = (0..6).map(|i| k[i][i].abs()).fold(0.0, f64::max);
    let off = (0..6)
        .flat_map(|i| (0..6).filter(move |&j| j != i).map(move |j| (i, j)))
        .map(|(i, j)| k[i][j].abs())
        .fold(0.0, f64::max);
    off / diag
}

#[test]
fn periodic_plate_has_the_sections_potential_flow_added_mass() {
    // Per unit span, the (u, v, ω_z) block of −K is the 2-D added-mass matrix of the section:
    // normal and pitch within 3 % at N = 64 (the 2-D solver's own first-order convergence at the
    // plate's sharp edges reaches about 1 % there), closer than at N = 32.
    let section = Shape::rect(THICKNESS).outline();
    let exact = panels::added_mass(&panels::panelled(section.points(), 1200));
    let mut previous: Option<[f64; 2]> = None;
    for n in [32, 64] {
        let period = 4.0 / n as f64;
        let k = added_mass(n, Span::Periodic(period)).k;
        let normal = -k[1][1] / period / exact[1][1];
        let pitch = -k[5][5] / period / exact[2][2];
        println!(
            "N = {n}: normal {:.5} (potential {:.5}, ratio {normal:.4}); pitch {:.6} \
             (potential {:.6}, ratio {pitch:.4}); along {:.2e}",
            -k[1][1] / period,
            exact[1][1],
            -k[5][5] / period,
            exact[2][2],
            -k[0][0] / period,
        );
        if let Some([n0, p0]) = previous {
            assert!(
                (normal - 1.0).abs() < (n0 - 1.0).abs(),
                "normal: no convergence"
            );
            assert!(
                (pitch - 1.0).abs() < (p0 - 1.0).abs(),
                "pitch: no convergence"
            );
        }
        previous = Some([normal, pitch]);
    }
    let [normal, pitch] = previous.unwrap();
    assert!((normal - 1.0).abs() < 0.03, "normal ratio {normal}");
    assert!((pitch - 1.0).abs() < 0.03, "pitch ratio {pitch}");
}

#[test]
fn finite_plate_added_mass_is_symmetric_diagonal_and_below_the_infinite_span() {
    // A box mirror-symmetric about its three mid-planes on a grid with the same symmetry: every
    // coupling between the six unit motions vanishes (round-off and the solver's tolerance), K is
    // symmetric and negative definite; the tips let fluid round the span, so the normal added
    // mass per unit span is below the periodic plate's at the same spacing (tip loss).
    let n = 16;
    let span = 2.0;
    let k = added_mass(n, Span::Finite(span)).k;
    for row in &k {
        println!("{}", row.map(|v| format!("{v:11.4e}")).join(" "));
    }
    let off = largest_off_diagonal(&k);
    println!("largest off-diagonal / diagonal: {off:.2e}");
    assert!(off < 1e-6, "couplings {off:.2e}");
    for (i, row) in k.iter().enumerate() {
        assert!(row[i] < 0.0, "K[{i}][{i}] = {} is not negative", row[i]);
    }
    let period = 4.0 / n as f64;
    let periodic = added_mass(n, Span::Periodic(period)).k;
    let (finite_normal, infinite_normal) = (-k[1][1] / span, -periodic[1][1] / period);
    println!(
        "normal per unit span: finite {finite_normal:.4}, periodic {infinite_normal:.4}, \
         ratio {:.3}",
        finite_normal / infinite_normal
    );
    assert!(finite_normal < infinite_normal);
    // The card (docs/physics.md §8) flies with this K on the left-hand side: it must leave
    // diag(m, m, m) ⊕ I − K positive definite.
    let card = PhysicalPlate6::card().nondimensional().expect("card");
    assert!(StrongCoupling6::new(&card, k).is_ok());
}
