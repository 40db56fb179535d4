//! The human-readable end-of-run report: the run's figures and, where the case has one, the
//! comparison with the seed's reference results (SPEC §8).
use std::f64::consts::PI;

use super::summary::Summary;
use platefall_core::sim::{Case, RunConfig};

/// One row of the comparison table: quantity, this run, seed / experiment.
type Row = (String, String, String);

fn fmt_opt(x: Option<f64>, digits: usize) -> String {
    x.map(|v| format!("{v:.digits$}"))
        .unwrap_or_else(|| "—".into())
}

fn row(quantity: &str, this_run: String, reference: &str) -> Row {
    (quantity.into(), this_run, reference.into())
}

/// The end-of-run report: the run's figures and the SPEC §8 comparison for its case.
pub fn report(config: &RunConfig, sum: &Summary) -> String {
    let mut r = header(config, sum);
    let table = match config.case {
        Case::Static { alpha, .. } => static_part(alpha, sum, &mut r),
        Case::Forced { omega, .. } => forced_part(omega, sum, &mut r),
        Case::Pinned { .. } | Case::Free { .. } => coupled_part(&config.case, sum, &mut r),
    };
    r.push_str(&comparison_table(&table));
    r
}

/// Title, status, cost, developed window and the coefficient means.
fn header(config: &RunConfig, sum: &Summary) -> String {
    format!(
        "platefall {} — {}\n\
         status {}: {} steps to t = {:.3} in {:.1} s ({} cells, {:.0} ns/cell/step)\n\
         developed part: {} .. {} ({})\n\
         mean C_L {}  C_D {}  C_M {}   C_L band [{}, {}]   max C_D {}\n",
        sum.case,
        config.title(),
        sum.status,
        sum.steps,
        sum.t_end,
        sum.wall_seconds,
        sum.cells,
        1e9 * sum.wall_seconds / (sum.steps.max(1) as f64 * sum.cells as f64),
        fmt_opt(sum.developed_from, 2),
        fmt_opt(sum.developed_to, 2),
        sum.developed_rule,
        fmt_opt(sum.mean_cl, 3),
        fmt_opt(sum.mean_cd, 3),
        fmt_opt(sum.mean_cm, 3),
        fmt_opt(sum.min_cl, 3),
        fmt_opt(sum.max_cl, 3),
        fmt_opt(sum.max_cd, 3)
    )
}

fn static_part(alpha: f64, sum: &Summary, r: &mut String) -> Vec<Row> {
    let strouhal = format!(
        "{} / {}",
        fmt_opt(sum.strouhal_chord, 3),
        fmt_opt(sum.strouhal_width, 3)
    );
    r.push_str(&format!(
        "Strouhal: {} on the chord, {} on the projected width\n",
        fmt_opt(sum.strouhal_chord, 3),
        fmt_opt(sum.strouhal_width, 3)
    ));
    if let Some(l) = sum.recirculation_length {
        r.push_str(&format!(
            "recirculation length behind the plate at the end: {l:.3} c\n"
        ));
    }
    let mut table = Vec::new();
    if (alpha - 0.4).abs() < 0.05 {
        table.push(row("Strouhal (chord / width)", strouhal, "0.34 / 0.13"));
    }
    if (alpha - PI / 2.0).abs() < 0.05 {
        let seed = "1.494 (seed, symmetric wake); 1.4 experiment";
        table.push(row("mean C_D", fmt_opt(sum.mean_cd, 3), seed));
    }
    if alpha.abs() <= 0.16 {
        let seed = "≈ 0.44 at α = 0.15";
        table.push(row(
            "C_L (steady up to α ≈ 0.15)",
            fmt_opt(sum.mean_cl, 3),
            seed,
        ));
    }
    table
}

fn forced_part(omega: f64, sum: &Summary, r: &mut String) -> Vec<Row> {
    r.push_str(&format!(
        "lag of max C_D behind max C_L: {} rad of α; mean moment over whole turns {}\n",
        fmt_opt(sum.lag_cd_behind_cl, 2),
        fmt_opt(sum.mean_cm, 4)
    ));
    let seed = [
        (1.0, "3.2", "1.1", "accelerating"),
        (2.0, "5.8", "1.0", "≈ neutral"),
        (4.0, "9.5", "0.75", "retarding"),
    ];
    let Some((_, cl, lag, m)) = seed.iter().find(|(k, ..)| (omega.abs() - k).abs() < 1e-9) else {
        return Vec::new();
    };
    let sense = sum.mean_cm.map(|m| {
        if m * omega > 0.0 {
            "accelerating"
        } else {
            "retarding"
        }
    });
    vec![
        row("max C_L", fmt_opt(sum.peak_cl_rotation, 2), cl),
        row(
            "lag of max C_D (rad)",
            fmt_opt(sum.lag_cd_behind_cl, 2),
            lag,
        ),
        row(
            "mean moment",
            format!("{} ({})", sense.unwrap_or("—"), fmt_opt(sum.mean_cm, 4)),
            m,
        ),
    ]
}

fn coupled_part(case: &Case, sum: &Summary, r: &mut String) -> Vec<Row> {
    r.push_str(&format!(
        "revolutions {}  autorotation established at t = {}\nmean V {}  mean θ̇ {}  mean γ {}\n",
        fmt_opt(sum.revolutions, 2),
        fmt_opt(sum.autorotation_time, 2),
        fmt_opt(sum.mean_speed, 3),
        fmt_opt(sum.mean_omega, 3),
        fmt_opt(sum.mean_gamma, 3)
    ));
    r.push_str(&fall_part(sum));
    if matches!(case, Case::Pinned { .. }) {
        let rate = fmt_opt(sum.mean_omega.map(f64::abs), 3);
        return vec![
            row("mean θ̇ (c/U)", rate, "1.58"),
            row(
                "lag of max C_D behind max C_L",
                fmt_opt(sum.lag_cd_behind_cl, 2),
                "0.70 rad",
            ),
        ];
    }
    if sum.mean_speed_ft_s.is_none() {
        return Vec::new();
    }
    vec![
        row(
            "mean speed (ft/s)",
            fmt_opt(sum.mean_speed_ft_s, 2),
            "3.01 (seed), 3.75 (experiment)",
        ),
        row(
            "mean rotation (rad/s)",
            fmt_opt(sum.mean_omega_rad_s, 2),
            "19.56 (seed), 23.4 (experiment)",
        ),
        row(
            "mean flight-path angle (rad)",
            fmt_opt(sum.mean_gamma, 3),
            "−0.20 (seed), −0.81 (experiment)",
        ),
        row(
            "max C_L in autorotation",
            fmt_opt(sum.peak_cl_rotation, 2),
            "≈ 6.2 (seed)",
        ),
    ]
}

/// What the falling plate is doing, in the run's units and, when known, physical ones.
fn fall_part(sum: &Summary) -> String {
    let (f, p) = (&sum.fall, &sum.physical);
    let unit = |x: Option<f64>, u: &str, d: usize| {
        x.map(|v| format!(" ({v:.d$} {u})")).unwrap_or_default()
    };
    let mut text = format!(
        "regime {} (judged from t = {}): period {}{}{}, angle amplitude {} rad\n\
         mean descent speed {}{}, horizontal drift {}{}, descent angle {} rad\n",
        f.regime.as_deref().unwrap_or("—"),
        fmt_opt(f.regime_from, 2),
        fmt_opt(f.period, 3),
        unit(p.period_s, "s", 3),
        unit(p.frequency_hz, "Hz", 3),
        fmt_opt(f.angle_amplitude, 3),
        fmt_opt(f.mean_descent_speed, 3),
        unit(p.mean_descent_speed_cm_s, "cm/s", 2),
        fmt_opt(f.mean_horizontal_speed, 3),
        unit(p.mean_horizontal_speed_cm_s, "cm/s", 2),
        fmt_opt(f.descent_angle, 3),
    );
    if let (Some(u), Some(c)) = (p.velocity_scale_m_s, p.chord_m) {
        text.push_str(&format!(
            "physical units: U = {:.3} cm/s, c = {:.2} mm; mean speed {} cm/s, mean |θ̇| {} rad/s\n",
            100.0 * u,
            1e3 * c,
            fmt_opt(p.mean_speed_cm_s, 2),
            fmt_opt(sum.mean_omega_rad_s, 2)
        ));
    }
    text
}

/// The comparison table with aligned columns (empty when there is nothing to compare).
fn comparison_table(table: &[Row]) -> String {
    if table.is_empty() {
        return String::new();
    }
    let width = |f: fn(&Row) -> &String| table.iter().map(|x| f(x).chars().count()).max();
    let w0 = width(|x| &x.0).unwrap_or(0);
    let w1 = width(|x| &x.1).unwrap_or(0).max(9);
    let pad = |s: &str, w: usize| format!("{s}{}", " ".repeat(w - s.chars().count()));
    let mut r = String::from("\ncomparison with the seed (SPEC §8)\n");
    r.push_str(&format!(
        "  {}  {}  seed / experiment\n",
        pad("quantity", w0),
        pad("this run", w1)
    ));
    for (a, b, c) in table {
        r.push_str(&format!("  {}  {}  {c}\n", pad(a, w0), pad(b, w1)));
    }
    r
}
