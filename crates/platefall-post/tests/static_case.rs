//! Case A, the static plate (docs/physics.md §1, §5, §8) at the dissertation's resolution N = 16 around the dissertation's plate
//! (a rectangle 1/16 thick), Re = 5000.
mod common;
use platefall_core::config::RunBuilder;
use platefall_core::sim::RunStatus;

#[test]
fn normal_plate_sheds_an_asymmetric_wake() {
    // α = π/2: the dissertation's solver kept a symmetric wake (C_D 1.494, no street). Here the wake must
    // break symmetry and shed: C_L oscillates with amplitude > 0.1 over the developed part.
    let config = RunBuilder::static_plate(std::f64::consts::FRAC_PI_2)
        .resolution(16)
        .thickness(0.0625)
        .t_end(60.0);
    let (_, rec, s) = common::run(config.build().unwrap());
    assert_eq!(rec.status, RunStatus::Completed);
    let amplitude = 0.5 * (s.max_cl.unwrap() - s.min_cl.unwrap());
    eprintln!(
        "α = π/2: C_L amplitude {amplitude:.3}, mean C_D {:.3}",
        s.mean_cd.unwrap()
    );
    assert!(
        amplitude > 0.1,
        "C_L amplitude {amplitude} ≤ 0.1: no shedding"
    );
    assert!(
        s.strouhal_chord.is_some(),
        "a shedding wake has a dominant lift frequency"
    );
    // A shedding wake drags harder than the dissertation's symmetric one (1.494; a symmetric wake here
    // decays below 1.0 by t = 10); 2-D computations of shedding normal plates give ≈ 2.6 at
    // Re 250 (Najjar & Vanka 1995) and more at higher Re, and this solver gives 3.3–3.8 at
    // N = 16–64; [1.5, 4.5] separates shedding from both a symmetric and a blown-up wake.
    let cd = s.mean_cd.unwrap();
    assert!((1.5..=4.5).contains(&cd), "mean C_D {cd}");
}

#[test]
fn inclined_plate_sheds_at_the_expected_strouhal_number() {
    // α = 0.4: periodic shedding with a Strouhal number on the projected width c sin α in
    // [0.12, 0.20] (dissertation 0.13; bluff-body wakes 0.14–0.18).
    let config = RunBuilder::static_plate(0.4).resolution(16).t_end(40.0);
    let (_, rec, s) = common::run(config.build().unwrap());
    assert_eq!(rec.status, RunStatus::Completed);
    let st = s.strouhal_width.expect("periodic shedding");
    assert!(
        (0.12..=0.20).contains(&st),
        "Strouhal on the projected width {st}"
    );
    // Lift is positive for positive α (docs/physics.md §5: motion to the right, lift up).
    assert!(s.mean_cl.unwrap() > 0.3 && s.mean_cd.unwrap() > 0.0);
}

#[test]
fn mirrored_angle_mirrors_lift_and_moment_and_keeps_drag() {
    // Reflection y → −y maps α to −α: C_L and C_M change sign, C_D is unchanged. Short attached
    // start-up (t ≤ 3) without the kick; only round-off in the factorisation differs, so 1e-6.
    let run = |alpha: f64| {
        let config = RunBuilder::static_plate(alpha)
            .kick(0.0)
            .resolution(16)
            .t_end(3.0);
        common::run(config.build().unwrap()).1.samples
    };
    let (a, b) = (run(0.3), run(-0.3));
    assert_eq!(a.len(), b.len());
    for (p, q) in a.iter().zip(&b).skip(1) {
        assert!(
            (p.cl + q.cl).abs() < 1e-6 * (1.0 + p.cl.abs()),
            "t={} C_L {} vs {}",
            p.t,
            p.cl,
            q.cl
        );
        assert!(
            (p.cm + q.cm).abs() < 1e-6 * (1.0 + p.cm.abs()),
            "t={} C_M {} vs {}",
            p.t,
            p.cm,
            q.cm
        );
        assert!(
            (p.cd - q.cd).abs() < 1e-6 * (1.0 + p.cd.abs()),
            "t={} C_D {} vs {}",
            p.t,
            p.cd,
            q.cd
        );
    }
}

#[test]
fn zero_incidence_plate_has_no_lift_and_only_friction_and_edge_drag() {
    // α = 0, symmetric about the chord line: C_L ≈ 0 to round-off, C_D > 0.
    let config = RunBuilder::static_plate(0.0)
        .kick(0.0)
        .resolution(16)
        .t_end(4.0);
    let (_, _, s) = common::run(config.build().unwrap());
    assert!(s.mean_cl.unwrap().abs() < 1e-8, "C_L = {:?}", s.mean_cl);
    assert!(s.mean_cd.unwrap() > 0.0);
}
