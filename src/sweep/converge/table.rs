//! The study as a Markdown table: one row per quantity, the levels coarsest first with their 95 %
//! intervals, then the finest triple's status, observed order, extrapolation and GCI.
use super::analysis::Study;
use platefall_post::convergence::Status;

/// Decimals that show two significant digits of `x` (at least `min`).
fn decimals(x: f64, min: usize) -> usize {
    if !(x.is_finite() && x > 0.0) {
        return min;
    }
    ((1.0 - x.log10().floor()).max(min as f64)).min(12.0) as usize
}

/// A value with four significant digits.
fn sig4(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let d = (3.0 - v.abs().log10().floor()).clamp(0.0, 12.0) as usize;
    format!("{v:.d$}")
}

/// `value ± half-width` at the half-width's precision, or four significant digits.
pub(crate) fn with_interval(v: f64, hw: Option<f64>) -> String {
    match hw {
        Some(hw) if hw > 0.0 => {
            let d = decimals(hw, 0);
            format!("{v:.d$} ± {hw:.d$}")
        }
        Some(_) => format!("{} ± 0", sig4(v)),
        None => sig4(v),
    }
}

fn level_label(refined: &str, value: f64) -> String {
    match refined {
        "resolution" => format!("N = {value}"),
        other => format!("{other} = {value}"),
    }
}

/// The Markdown document of a study.
pub(crate) fn markdown(s: &Study) -> String {
    let mut out = format!(
        "# Convergence study: --{} ({})\n\n`platefall {}`\n\n",
        s.refined,
        s.spacing,
        s.case.join(" ")
    );
    let done: Vec<_> = s
        .levels
        .iter()
        .filter(|l| l.status == "completed" && l.h.is_some())
        .collect();
    out.push_str("| level | h | status | cells | steps | mean Δt | batches |\n|---|---|---|---|---|---|---|\n");
    for l in &s.levels {
        let opt = |x: Option<String>| x.unwrap_or_else(|| "—".into());
        out.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} | {} |\n",
            level_label(&s.refined, l.value),
            opt(l.h.map(|h| format!("{h:.4e}"))),
            l.status,
            opt(l.cells.map(|c| c.to_string())),
            opt(l.steps.map(|c| c.to_string())),
            opt(l.mean_dt.map(|d| format!("{d:.3e}"))),
            opt(l.ci_batches.map(|c| c.to_string())),
        ));
    }
    out.push('\n');
    let mut header = String::from("| quantity |");
    let mut rule = String::from("|---|");
    for l in &done {
        header.push_str(&format!(" {} |", level_label(&s.refined, l.value)));
        rule.push_str("---|");
    }
    header.push_str(
        " convergence (finest three) | p | extrapolated | GCI fine | finest ± (grid and noise) |\n",
    );
    rule.push_str("---|---|---|---|---|\n");
    out.push_str(&header);
    out.push_str(&rule);
    for q in &s.quantities {
        let mut row = format!("| {} |", q.key);
        for (v, hw) in q.values.iter().zip(&q.half_widths) {
            row.push_str(&format!(" {} |", with_interval(*v, *hw)));
        }
        match q.triples.first() {
            Some(t) => {
                let dash = || "—".to_string();
                let status = match t.status {
                    Status::NotResolvedByTheNoise => "not resolved by the noise".to_string(),
                    st => st.describe().to_string(),
                };
                row.push_str(&format!(
                    " {status} | {} | {} | {} | {} |\n",
                    t.order.map_or_else(dash, |p| format!("{p:.2}")),
                    t.extrapolated.map_or_else(dash, sig4),
                    match (t.gci_fine, t.gci_fine_abs) {
                        (Some(r), Some(a)) => format!("{:.2} % ({})", 100.0 * r, sig4(a)),
                        _ => dash(),
                    },
                    t.combined_uncertainty
                        .map_or_else(dash, |u| with_interval(t.values[0], Some(u))),
                ));
            }
            None => row.push_str(" — | — | — | — | — |\n"),
        }
        out.push_str(&row);
    }
    out.push_str(&format!(
        "\nValues are the levels' means ± their 95 % half-widths (the runs' own time series). A \
         difference between levels counts only when it exceeds √(hw₁² + hw₂²); p is the observed \
         order (Celik et al. 2008), the GCI uses F_s = {}, and the last column combines the GCI \
         and the finest level's half-width in quadrature.\n",
        s.safety_factor
    ));
    for q in &s.quantities {
        if let Some(t) = q.triples.first() {
            if !matches!(t.status, Status::MonotoneConvergence) {
                out.push_str(&format!("- {}: {}\n", q.key, t.note));
            }
        }
    }
    for q in &s.quantities {
        if !q.drifting.is_empty() {
            let at: Vec<String> = q
                .drifting
                .iter()
                .map(|v| level_label(&s.refined, *v))
                .collect();
            out.push_str(&format!(
                "- {}: the batch means drift over the window at {} (a transient is left in the \
                 mean: longer runs, or a later start, would move it)\n",
                q.key,
                at.join(", ")
            ));
        }
    }
    for q in &s.quantities {
        if !q.alternating.is_empty() {
            let at: Vec<String> = q
                .alternating
                .iter()
                .map(|v| level_label(&s.refined, *v))
                .collect();
            out.push_str(&format!(
                "- {}: the batch means alternate at {} (the motion repeats every two batches: the \
                 window is not whole periods of it, and the interval is wide)\n",
                q.key,
                at.join(", ")
            ));
        }
    }
    for n in &s.notes {
        out.push_str(&format!("- {n}\n"));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_are_shown_at_the_precision_of_their_interval() {
        assert_eq!(with_interval(2.61828, Some(0.0123)), "2.618 ± 0.012");
        assert_eq!(with_interval(2.61828, Some(0.4)), "2.62 ± 0.40");
        assert_eq!(with_interval(2.61828, None), "2.618");
        assert_eq!(with_interval(1234.4, Some(12.0)), "1234 ± 12");
    }
}
