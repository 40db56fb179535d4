//! The card of Gallaway (1985) flying in three dimensions (docs/three-d.md "The card in three
//! dimensions"): chord 3 in, span 8 in, six degrees of freedom (or a periodic span flying
//! planar), launched as the 2-D free fall (V₀ = 1 along γ₀ = −π/4 at α₀ = 0.1, held 5 c/U).
//! Writes every step to a CSV and ends with the means over the whole turns after the first
//! complete one, with 95 % batch-means intervals (docs/statistics.md), beside the experiment.
//!
//! With `aluminium` as the fifth argument the plate is instead a thin aluminium plate in water
//! (chord 16 mm, span 32 mm, thickness 0.5 mm), released from rest pitched 0.1 rad: a light plate
//! (m* about 1/10 of its added mass) that only strong coupling flies.
//!
//! `cargo run --release --example card3 -- N T_END finite|periodic OUT.csv [card|aluminium]`
use std::f64::consts::TAU;
use std::io::Write;

use platefall_core::body::six::{Constraint6, PhysicalPlate6, Plate6, RigidBody6, State6};
use platefall_core::body::AbStart;
use platefall_core::config::{Fluid, Strip};
use platefall_core::flow3d::{
    FlowParams3, FlowSolver3, Grid3, GridSpec3, OuterBc3, Span, Stretch3,
};
use platefall_core::sim3::{frame_of, Flight3, Sample6};
use platefall_post::stats::batch_interval;

/// The plate, its release and its units.
struct Setup {
    plate: Plate6,
    start: State6,
    /// Span in chords.
    span: f64,
    /// t/c.
    thickness: f64,
    re: f64,
    /// Held on its launch path until then (c/U) while the flow develops.
    t_release: f64,
    /// U/c (s⁻¹) and U (in the report's speed unit).
    rate_scale: f64,
    speed_scale: f64,
    /// The report's units and the measured figures (rate, speed, glide angle), if any.
    units: (&'static str, &'static str),
    measured: [f64; 3],
}

/// The card of Gallaway (1985), Table I (ft, s), launched as the 2-D free fall.
fn card() -> Result<Setup, Box<dyn std::error::Error>> {
    let card = PhysicalPlate6::card();
    Ok(Setup {
        plate: card.nondimensional()?,
        start: PhysicalPlate6::card_release(),
        span: card.aspect_ratio(),
        thickness: 1.0 / 16.0,
        re: card.reynolds(),
        t_release: 5.0,
        rate_scale: card.speed / card.chord,
        speed_scale: card.speed,
        units: ("rad/s", "ft/s"),
        measured: [23.4, 3.75, -0.81],
    })
}

/// Aluminium (2700 kg/m³) 16 × 32 × 0.5 mm in water (1000 kg/m³, ν = 1e-6 m²/s), from rest: the
/// 2-D physical plate of the same section ([`Strip`], its U = √((ρs/ρf − 1) g t), docs/physics.md
/// §2) as a uniform box of span 32 mm, buoyancy included ([`Strip::plate6`]).
fn aluminium() -> Result<Setup, Box<dyn std::error::Error>> {
    let strip = Strip {
        chord: 0.016,
        thickness: 0.0005,
        density: 2700.0,
        fluid: Fluid::water().overridden(Some(1000.0), Some(1e-6)),
        gravity: 9.81,
    };
    let plate = strip.plate6(0.032)?;
    let speed = plate.speed;
    Ok(Setup {
        plate: plate.nondimensional()?,
        start: State6::release(0.0, 0.0, 0.1),
        span: plate.aspect_ratio(),
        thickness: strip.aspect(),
        re: plate.reynolds(),
        t_release: 0.0,
        rate_scale: speed / plate.chord,
        speed_scale: speed * 100.0,
        units: ("rad/s", "cm/s"),
        measured: [f64::NAN; 3],
    })
}

/// One step's motion, as the analysis needs it.
struct Row {
    t: f64,
    dt: f64,
    pitch: f64,
    rate: f64,
    velocity: [f64; 3],
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let n: usize = args.first().map_or(Ok(16), |a| a.parse())?;
    let t_end: f64 = args.get(1).map_or(Ok(40.0), |a| a.parse())?;
    let periodic = args.get(2).is_some_and(|a| a == "periodic");
    let out = args.get(3).map_or("card3.csv", String::as_str);
    let setup = match args.get(4).map(String::as_str) {
        None | Some("card") => card()?,
        Some("aluminium") => aluminium()?,
        Some(other) => return Err(format!("plate `{other}`: accepted card or aluminium").into()),
    };
    let b = setup.span;
    let (span, constraint) = if periodic {
        (Span::Periodic(b), Constraint6::Planar)
    } else {
        (Span::Finite(b), Constraint6::Free)
    };
    let grid = Grid3::new(&GridSpec3 {
        resolution: n,
        thickness: setup.thickness,
        span,
        extent: [8.0; 3],
        stretch: Stretch3::GrowthCap(1.2),
        memory_limit: 8e9,
    })?;
    eprintln!("cells {}, Re {:.1}", grid.cells(), setup.re);
    let params = FlowParams3 {
        re: setup.re,
        ..FlowParams3::default()
    };
    let flow = FlowSolver3::new(grid, params, OuterBc3::FarField, frame_of(&setup.start))?;
    let body = RigidBody6::new(setup.plate, constraint, setup.start, 2, AbStart::Ramp)?;
    let mut flight = Flight3::new(flow, body)?.hold_until(setup.t_release)?;
    let mut csv = std::io::BufWriter::new(std::fs::File::create(out)?);
    writeln!(csv, "step,t,dt,x,y,z,vx,vy,vz,roll,yaw,pitch,omega_x,omega_y,omega_z,span_y,cl,cd,cs,c_roll,c_yaw,c_pitch,iterations,divergence")?;
    let clock = std::time::Instant::now();
    let mut rows = Vec::new();
    let mut pitch = 0.0_f64;
    let mut next_print = 0.0;
    while flight.flow().t() < t_end - 1e-9 {
        let s = flight.step(0.01)?;
        pitch = unwrap(pitch, s.state.orientation.euler_angles().2);
        write_row(&mut csv, &s, pitch)?;
        let v = s.state.velocity;
        rows.push(Row {
            t: s.t,
            dt: s.dt,
            pitch,
            rate: s.state.omega.z,
            velocity: [v.x, v.y, v.z],
        });
        if s.t >= next_print - 1e-9 {
            next_print += 1.0;
            csv.flush()?;
            eprintln!(
                "t {:6.2}  wall {:6.0} s  pitch {pitch:+8.3}  θ̇ {:+.3}  V ({:+.3} {:+.3} {:+.4})  span_y {:+.4}  CG {}",
                s.t,
                clock.elapsed().as_secs_f64(),
                s.state.omega.z,
                v.x,
                v.y,
                v.z,
                s.state.span_axis().y,
                s.iterations
            );
        }
    }
    csv.flush()?;
    println!(
        "{} steps to t = {t_end} in {:.0} s",
        rows.len(),
        clock.elapsed().as_secs_f64()
    );
    report(&rows, &setup);
    Ok(())
}

/// The continuous angle nearest `previous` whose wrapped value is `wrapped`.
fn unwrap(previous: f64, wrapped: f64) -> f64 {
    previous + (wrapped - previous + std::f64::consts::PI).rem_euclid(TAU) - std::f64::consts::PI
}

fn write_row(csv: &mut impl Write, s: &Sample6, pitch: f64) -> std::io::Result<()> {
    let (roll, yaw, _) = s.state.orientation.euler_angles();
    let (p, v, w, c) = (
        s.state.position,
        s.state.velocity,
        s.state.omega,
        s.coefficients,
    );
    writeln!(
        csv,
        "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
        s.step,
        s.t,
        s.dt,
        p.x,
        p.y,
        p.z,
        v.x,
        v.y,
        v.z,
        roll,
        yaw,
        pitch,
        w.x,
        w.y,
        w.z,
        s.state.span_axis().y,
        c.lift,
        c.drag,
        c.side,
        c.roll,
        c.yaw,
        c.pitch,
        s.iterations,
        s.divergence
    )
}

/// Means over the whole turns after the first complete turn following the release, each turn
/// one batch, with their 95 % intervals; the glide angle per turn from the turn's mean velocity.
fn report(rows: &[Row], setup: &Setup) {
    let released: Vec<&Row> = rows.iter().filter(|r| r.t > setup.t_release).collect();
    let Some(first) = released.first() else {
        println!("no steps after the release");
        return;
    };
    let mut edges = Vec::new();
    let mut k = 1.0;
    for r in &released {
        if (r.pitch - first.pitch).abs() >= k * TAU {
            edges.push(r.t);
            k += 1.0;
        }
    }
    println!(
        "complete turns after the release: {} (at t = {:?})",
        edges.len(),
        edges
    );
    let batches: Vec<[f64; 5]> = edges
        .windows(2)
        .map(|w| turn_means(&released, w[0], w[1]))
        .collect();
    let (rate_unit, speed_unit) = setup.units;
    let [rate, speed, glide] = setup.measured;
    let names = [
        (
            "mean rotation rate θ̇ (c/U)",
            setup.rate_scale,
            rate_unit,
            rate,
        ),
        ("mean speed (U)", setup.speed_scale, speed_unit, speed),
        ("glide angle γ (rad)", 1.0, "rad", glide),
        (
            "sideways drift speed (U)",
            setup.speed_scale,
            speed_unit,
            f64::NAN,
        ),
        ("turn duration (c/U)", 1.0 / setup.rate_scale, "s", f64::NAN),
    ];
    for (i, (name, scale, unit, measured)) in names.iter().enumerate() {
        // Time means weigh each turn by its duration; the duration itself is a plain mean.
        let weight = |m: &[f64; 5]| if i == 4 { 1.0 } else { m[4] };
        let b: Vec<(f64, f64)> = batches.iter().map(|m| (weight(m), m[i])).collect();
        match batch_interval(&b) {
            Ok(iv) => println!(
                "{name}: {:.4} ± {:.4}  = {:.3} ± {:.3} {unit}  (experiment {measured}; {} turns, n_eff {:.1})",
                iv.mean,
                iv.half_width,
                iv.mean * scale,
                iv.half_width * scale,
                iv.samples,
                iv.n_eff
            ),
            Err(e) => println!("{name}: no interval ({e:?}); turns {}", b.len()),
        }
    }
}

/// Time means over [t0, t1]: rate, speed, glide angle of the mean velocity, the spanwise (Z)
/// speed, and the duration.
fn turn_means(rows: &[&Row], t0: f64, t1: f64) -> [f64; 5] {
    let mut sum = [0.0; 5];
    let mut total = 0.0;
    for r in rows.iter().filter(|r| r.t > t0 && r.t <= t1) {
        let [vx, vy, vz] = r.velocity;
        sum[0] += r.rate * r.dt;
        sum[1] += (vx * vx + vy * vy + vz * vz).sqrt() * r.dt;
        sum[2] += vx * r.dt;
        sum[3] += vy * r.dt;
        sum[4] += vz * r.dt;
        total += r.dt;
    }
    let m: Vec<f64> = sum.iter().map(|s| s / total).collect();
    [m[0], m[1], m[3].atan2(m[2]), m[4], total]
}
