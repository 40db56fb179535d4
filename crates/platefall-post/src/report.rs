//! The human-readable end-of-run report: the run's figures and, where the case has one, the
//! comparison with the dissertation's reference results (docs/physics.md §8).
use std::f64::consts::PI;

use super::regime::Regime;
use super::summary::Summary;
use platefall_core::sim::{Case, RunConfig};

/// One row of the comparison table: quantity, this run, dissertation / experiment.
type Row = (String, String, String);

fn fmt_opt(x: Option<f64>, digits: usize) -> String {
    x.map(|v| format!("{v:.digits$}"))
        .unwrap_or_else(|| "—".into())
}

/// Means and half-widths both below this are round-off.
const ROUND_OFF: f64 = 1e-9;

/// `value ± half-width` when the value has a 95 % interval (the half-width to two significant
/// digits, the value to the same decimal place), else the value as `fmt_opt` gives it.
pub fn pm(x: Option<f64>, half_width: Option<f64>, digits: usize) -> String {
    match (x, half_width) {
        // A mean that vanishes by symmetry (the lift of a section at zero incidence) is zero to
        // round-off, interval included: its twelve decimals would say nothing.
        (Some(v), Some(hw)) if v.abs() < ROUND_OFF && hw.abs() < ROUND_OFF => {
            format!("{:.digits$} ± 0", 0.0)
        }
        (Some(v), Some(hw)) if hw.is_finite() && hw > 0.0 => {
            // Two significant digits of the half-width, at least `digits` decimals.
            let d = (1.0 - hw.log10().floor()).max(digits as f64).min(12.0) as usize;
            format!("{v:.d$} ± {hw:.d$}")
        }
        (Some(v), Some(0.0)) => format!("{v:.digits$} ± 0"),
        _ => fmt_opt(x, digits),
    }
}

fn row(quantity: &str, this_run: String, reference: &str) -> Row {
    (quantity.into(), this_run, reference.into())
}

/// The end-of-run report: the run's figures and the docs/physics.md §8 comparison for its case.
pub fn report(config: &RunConfig, sum: &Summary) -> String {
    let mut r = report_figures(config, &config.title(), sum);
    r.push_str(&comparison(config, sum));
    r
}

/// The report's figures under `title` without the comparison with the dissertation.
pub fn report_figures(config: &RunConfig, title: &str, sum: &Summary) -> String {
    let mut r = header(title, sum);
    case_part(config, sum, &mut r);
    r
}

/// The docs/physics.md §8 comparison of the run's case (a plate's).
pub fn comparison(config: &RunConfig, sum: &Summary) -> String {
    comparison_table(&case_part(config, sum, &mut String::new()))
}

/// The case's own lines (into `r`) and its comparison rows.
fn case_part(config: &RunConfig, sum: &Summary, r: &mut String) -> Vec<Row> {
    match config.case {
        Case::Static { alpha, .. } => static_part(alpha, sum, r),
        Case::Forced { omega, .. } => forced_part(omega, sum, r),
        Case::Pinned { .. } | Case::Free { .. } => coupled_part(&config.case, sum, r),
    }
}

/// Title, status, cost, developed window and the coefficient means.
fn header(title: &str, sum: &Summary) -> String {
    format!(
        "platefall {} — {}\n\
         status {}: {} steps to t = {:.3} in {:.1} s ({} cells, {:.0} ns/cell/step)\n\
         developed part: {} .. {} ({})\n\
         mean C_L {}  C_D {}  C_M {}   C_L band [{}, {}]   max C_D {}\n\
         {}\n",
        sum.case,
        title,
        sum.status,
        sum.steps,
        sum.t_reached,
        sum.wall_seconds,
        sum.cells,
        1e9 * sum.wall_seconds / (sum.steps.max(1) as f64 * sum.cells as f64),
        fmt_opt(sum.developed_from, 2),
        fmt_opt(sum.developed_to, 2),
        sum.developed_rule,
        pm(sum.mean_cl, sum.ci.mean_cl_ci95, 3),
        pm(sum.mean_cd, sum.ci.mean_cd_ci95, 3),
        pm(sum.mean_cm, sum.ci.mean_cm_ci95, 3),
        fmt_opt(sum.min_cl, 3),
        fmt_opt(sum.max_cl, 3),
        fmt_opt(sum.max_cd, 3),
        interval_line(sum)
    )
}

/// How the ± figures were made, or why there are none.
fn interval_line(sum: &Summary) -> String {
    let ci = &sum.ci;
    let line = match (&ci.ci_note, &ci.ci_method) {
        (Some(note), _) => format!("95 % intervals: {note}"),
        (None, Some(method)) => format!("± is the 95 % confidence half-width: {method}"),
        (None, None) => "95 % intervals: none".into(),
    };
    let mut line = line;
    if let Some(d) = &ci.ci_drift {
        line.push_str(&format!(
            "\nwarning: the batch means drift over the window ({d}, first to last batch): \
             a transient is left in it, so these means depend on where it starts"
        ));
    }
    if let Some(a) = &ci.ci_alternating {
        line.push_str(&format!(
            "\nnote: the batch means alternate (lag-1 autocorrelation {a}): the motion repeats \
             every two batches, the window is not a whole number of its periods, and the \
             intervals are wide"
        ));
    }
    line
}

fn static_part(alpha: f64, sum: &Summary, r: &mut String) -> Vec<Row> {
    let (chord, width) = (
        pm(sum.strouhal_chord, sum.ci.strouhal_chord_ci95, 3),
        pm(sum.strouhal_width, sum.ci.strouhal_width_ci95, 3),
    );
    let strouhal = format!("{chord} / {width}");
    r.push_str(&format!(
        "Strouhal: {chord} on the chord, {width} on the projected width\n"
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
        let reference = "1.494 (dissertation, symmetric wake); 1.4 experiment";
        let cd = pm(sum.mean_cd, sum.ci.mean_cd_ci95, 3);
        table.push(row("mean C_D", cd, reference));
    }
    if alpha.abs() <= 0.16 {
        let reference = "≈ 0.44 at α = 0.15";
        table.push(row(
            "C_L (steady up to α ≈ 0.15)",
            pm(sum.mean_cl, sum.ci.mean_cl_ci95, 3),
            reference,
        ));
    }
    table
}

fn forced_part(omega: f64, sum: &Summary, r: &mut String) -> Vec<Row> {
    r.push_str(&format!(
        "lag of max C_D behind max C_L: {} rad of α; mean moment over whole turns {}\n",
        pm(sum.lag_cd_behind_cl, sum.ci.lag_cd_behind_cl_ci95, 2),
        pm(sum.mean_cm, sum.ci.mean_cm_ci95, 4)
    ));
    let reference = [
        (1.0, "3.2", "1.1", "accelerating"),
        (2.0, "5.8", "1.0", "≈ neutral"),
        (4.0, "9.5", "0.75", "retarding"),
    ];
    let Some((_, cl, lag, m)) = reference
        .iter()
        .find(|(k, ..)| (omega.abs() - k).abs() < 1e-9)
    else {
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
            pm(sum.lag_cd_behind_cl, sum.ci.lag_cd_behind_cl_ci95, 2),
            lag,
        ),
        row(
            "mean moment",
            format!(
                "{} ({})",
                sense.unwrap_or("—"),
                pm(sum.mean_cm, sum.ci.mean_cm_ci95, 4)
            ),
            m,
        ),
    ]
}

fn coupled_part(case: &Case, sum: &Summary, r: &mut String) -> Vec<Row> {
    r.push_str(&format!(
        "revolutions {}  autorotation established at t = {}\nmean V {}  mean θ̇ {}  mean γ {}\n",
        fmt_opt(sum.revolutions, 2),
        fmt_opt(sum.autorotation_time, 2),
        pm(sum.mean_speed, sum.ci.mean_speed_ci95, 3),
        pm(sum.mean_omega, sum.ci.mean_omega_ci95, 3),
        pm(sum.mean_gamma, sum.ci.mean_gamma_ci95, 3)
    ));
    r.push_str(&crate::precision::planning_line(&sum.ci).unwrap_or_default());
    r.push_str(&fall_part(sum));
    if matches!(case, Case::Pinned { .. }) {
        let rate = pm(sum.mean_omega.map(f64::abs), sum.ci.mean_omega_ci95, 3);
        return vec![
            row("mean θ̇ (c/U)", rate, "1.58"),
            row(
                "lag of max C_D behind max C_L",
                pm(sum.lag_cd_behind_cl, sum.ci.lag_cd_behind_cl_ci95, 2),
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
            pm(sum.mean_speed_ft_s, sum.ci.mean_speed_ft_s_ci95, 2),
            "3.01 (dissertation), 3.75 (experiment)",
        ),
        row(
            "mean rotation (rad/s)",
            pm(sum.mean_omega_rad_s, sum.ci.mean_omega_rad_s_ci95, 2),
            "19.56 (dissertation), 23.4 (experiment)",
        ),
        row(
            "mean flight-path angle (rad)",
            pm(sum.mean_gamma, sum.ci.mean_gamma_ci95, 3),
            "−0.20 (dissertation), −0.81 (experiment)",
        ),
        row(
            "max C_L in autorotation",
            fmt_opt(sum.peak_cl_rotation, 2),
            "≈ 6.2 (dissertation)",
        ),
    ]
}

/// What the falling plate is doing, in the run's units and, when known, physical ones.
fn fall_part(sum: &Summary) -> String {
    let (f, p, ci) = (&sum.fall, &sum.physical, &sum.ci);
    let unit = |x: Option<f64>, hw: Option<f64>, u: &str, d: usize| {
        x.map(|_| format!(" ({} {u})", pm(x, hw, d)))
            .unwrap_or_default()
    };
    let cycle = ci
        .mean_cycle_amplitude
        .map(|_| {
            format!(
                " (per oscillation {})",
                pm(ci.mean_cycle_amplitude, ci.mean_cycle_amplitude_ci95, 3)
            )
        })
        .unwrap_or_default();
    let mut text = format!(
        "regime {} (judged from t = {}): period {}{}{}, angle amplitude {} rad{cycle}\n\
         mean descent speed {}{}, horizontal drift {}{}, descent angle {} rad\n",
        f.regime.map_or("—", Regime::name),
        fmt_opt(f.regime_from, 2),
        pm(f.period, ci.period_ci95, 3),
        unit(p.period_s, ci.period_s_ci95, "s", 3),
        unit(p.frequency_hz, ci.frequency_hz_ci95, "Hz", 3),
        fmt_opt(f.angle_amplitude, 3),
        pm(f.mean_descent_speed, ci.mean_descent_speed_ci95, 3),
        unit(
            p.mean_descent_speed_cm_s,
            ci.mean_descent_speed_cm_s_ci95,
            "cm/s",
            2
        ),
        pm(f.mean_horizontal_speed, ci.mean_horizontal_speed_ci95, 3),
        unit(
            p.mean_horizontal_speed_cm_s,
            ci.mean_horizontal_speed_cm_s_ci95,
            "cm/s",
            2
        ),
        pm(f.descent_angle, ci.descent_angle_ci95, 3),
    );
    if let (Some(u), Some(c)) = (p.velocity_scale_m_s, p.chord_m) {
        text.push_str(&format!(
            "physical units: U = {:.3} cm/s, c = {:.2} mm; mean speed {} cm/s, mean |θ̇| {} rad/s\n",
            100.0 * u,
            1e3 * c,
            pm(p.mean_speed_cm_s, ci.mean_speed_cm_s_ci95, 2),
            pm(sum.mean_omega_rad_s, ci.mean_omega_rad_s_ci95, 2)
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
    let mut r = String::from("\ncomparison with Gallaway (1985) (docs/physics.md §8)\n");
    r.push_str(&format!(
        "  {}  {}  dissertation / experiment\n",
        pad("quantity", w0),
        pad("this run", w1)
    ));
    for (a, b, c) in table {
        r.push_str(&format!("  {}  {}  {c}\n", pad(a, w0), pad(b, w1)));
    }
    r
}
