//! The 3-D flow's added-mass matrix K (docs/three-d.md "Added mass"): the periodic-span plate
//! against two-dimensional potential flow around the same section (the boundary-element solution
//! of `panels`), the finite plate's symmetries, sign and tip loss, and the curved bodies cut into
//! the grid against the closed forms of a sphere, ½ρV along any axis, and of a thin circular
//! disk of radius a moving broadside, 8ρa³/3 (edgewise 0).
//!
//! `cargo test --release -p platefall-core --test added_mass_3d -- --nocapture` prints the
//! measured matrices and ratios.
mod panels;

use platefall_core::body::six::{PhysicalPlate6, StrongCoupling6};
use platefall_core::flow3d::{
    AddedMass3, FlowParams3, FlowSolver3, Frame3, Grid3, GridSpec3, OuterBc3, Shape3, Span,
    Stretch3,
};
use platefall_core::shape::Shape;

/// Thickness of the test plate (chords): four cells at N = 64, two at N = 32.
const THICKNESS: f64 = 1.0 / 16.0;

/// K of a plate of `THICKNESS` at resolution `n`, 12 chords from the outer boundary in x and y.
fn added_mass(n: usize, span: Span) -> AddedMass3 {
    added_mass_of(GridSpec3 {
        resolution: n,
        thickness: THICKNESS,
        span,
        extent: [12.0, 12.0, 6.0],
        stretch: Stretch3::GrowthCap(1.2),
        memory_limit: 4e9,
        shape: Default::default(),
    })
}

/// K of the body of `spec`, from fluid at rest.
fn added_mass_of(spec: GridSpec3) -> AddedMass3 {
    let grid = Grid3::new(&spec).expect("grid");
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

/// −K (the added-mass matrix, ρc³ and ρc⁵) of `shape` inscribed in the box chord 1 ×
/// `thickness` × `span`, at resolution `n`, 10 chords from the outer boundary.
fn body_added_mass(shape: Shape3, n: usize, thickness: f64, span: f64) -> [[f64; 6]; 6] {
    let k = added_mass_of(GridSpec3 {
        resolution: n,
        thickness,
        span: Span::Finite(span),
        extent: [10.0; 3],
        stretch: Stretch3::GrowthCap(1.2),
        memory_limit: 4e9,
        shape,
    });
    k.k.map(|row| row.map(|v| -v))
}

#[test]
fn a_sphere_has_half_its_displaced_mass_along_every_axis() {
    // Diameter 1: ½ρV = π/12. The cut faces' apertures are exact to the sampling, so the error
    // is the discretisation's: within 3 % at N = 16 and 1.5 % at N = 32, and smaller on the finer
    // grid (the wall pressure is read from clean cells, docs/three-d.md "Bodies", which costs the
    // first order of reading the cut cells themselves: +2.1 % and +1.4 %). A sphere turning
    // about its centre displaces no fluid: its rotational added mass vanishes.
    let exact = std::f64::consts::PI / 12.0;
    let mut previous = f64::INFINITY;
    for (n, bound) in [(16, 0.03), (32, 0.015)] {
        let m = body_added_mass(Shape3::Ellipsoid, n, 1.0, 1.0);
        let error = m[0][0] / exact - 1.0;
        println!(
            "sphere N = {n}: added mass / (ρV/2) − 1 = {:+.4} {:+.4} {:+.4}; rotation {:.1e} {:.1e} {:.1e}",
            m[0][0] / exact - 1.0,
            m[1][1] / exact - 1.0,
            m[2][2] / exact - 1.0,
            m[3][3],
            m[4][4],
            m[5][5]
        );
        assert!(error.abs() < bound, "N = {n}: {error:+.4}");
        assert!(
            error.abs() < previous,
            "N = {n}: {error:+.4} after {previous:+.4}"
        );
        previous = error.abs();
        // The grid is the same along x, y and z: the three axes agree to round-off.
        for a in 1..3 {
            assert!((m[a][a] / m[0][0] - 1.0).abs() < 1e-9, "axis {a}");
        }
        for a in 3..6 {
            assert!(m[a][a].abs() < 1e-4 * m[0][0], "rotation {a}: {}", m[a][a]);
        }
    }
}

#[test]
fn a_thin_disk_has_eight_thirds_its_radius_cubed_broadside() {
    // Diameter 1 (a = ½), one cell thick: 8ρa³/3 = 1/3 for zero thickness. The finite thickness
    // adds to it (at N = 32 a disk two cells thick is 3.7 % above one a cell thick), so the
    // disk converges as its thickness h shrinks: within 3 % at N = 48 (t = a/24), and the
    // edgewise added mass, zero for the thin disk, below 1 % of the broadside one.
    let exact = 8.0 / 3.0 * 0.125;
    let (mut previous, mut edgewise) = (f64::INFINITY, f64::INFINITY);
    for n in [16, 32, 48] {
        let m = body_added_mass(Shape3::Disk, n, 1.0 / n as f64, 1.0);
        let error = m[1][1] / exact - 1.0;
        println!(
            "disk N = {n}, one cell thick: broadside / (8ρa³/3) − 1 = {error:+.4}; edgewise {:.2e} {:.2e}",
            m[0][0], m[2][2]
        );
        assert!(error > 0.0 && error < previous, "N = {n}: {error:+.4}");
        assert!(
            (m[0][0] / m[2][2] - 1.0).abs() < 1e-9,
            "a circle: x and z alike"
        );
        assert!(m[0][0] < edgewise, "N = {n}: edgewise {}", m[0][0]);
        (previous, edgewise) = (error, m[0][0]);
    }
    assert!(previous < 0.03, "N = 48: {previous:+.4}");
    assert!(edgewise < 0.01 * exact, "N = 48: edgewise {edgewise:.2e}");
}
