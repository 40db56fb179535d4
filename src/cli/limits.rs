//! Resource limits, checked before anything large is allocated: the run's estimated memory
//! (cells and pressure factor, [`platefall_core::sim::estimate`]) against `--max-memory`, and the number
//! of steps its time-step limits imply against `--max-steps`. A refusal is one line with the
//! estimate, the limit, and the options that reduce it.
use clap::Args;

use platefall_core::grid::Stretch;
use platefall_core::sim::estimate::{estimate, DtFloor, Estimate, FACTOR_NONZERO_LIMIT};
use platefall_core::sim::{RunConfig, ValidatedConfig};

/// Default share of physical memory a run may take.
const DEFAULT_MEMORY_SHARE: &str = "75%";
/// Assumed physical memory when it cannot be read (/proc/meminfo).
const FALLBACK_MEMORY: f64 = 8e9;
/// Estimated wall time above which a warning is printed (seconds).
const WARN_SECONDS: f64 = 3600.0;

/// Resource limits of a run (flattened into every case's options).
#[derive(Args, Debug, Clone)]
#[command(next_help_heading = "Resource limits")]
pub struct LimitArgs {
    /// Refuse a run whose estimated memory exceeds this: a share of physical memory ("75%"), a
    /// size ("16GB", "512MB", "2GiB") or "unlimited"
    #[arg(long, value_name = "SIZE", default_value = DEFAULT_MEMORY_SHARE)]
    pub max_memory: String,
    /// Refuse a run that needs more time steps than this; the floor is t_end / min(--dt-max,
    /// the explicit viscous limit ∝ Re h²)
    #[arg(long, value_name = "N", default_value_t = 1e8)]
    pub max_steps: f64,
}

/// Checks `config` against the limits; `recording` is the number of field snapshots that may be
/// queued when a Rerun sink is open. Ok carries a warning for long runs.
pub fn check_limits(
    config: &ValidatedConfig,
    limits: &LimitArgs,
    recording: Option<usize>,
) -> anyhow::Result<Option<String>> {
    let est = estimate(config);
    check_memory(config, &est, limits, recording)?;
    check_steps(config, &est, limits)?;
    let hours = est.seconds_min() / 3600.0;
    Ok((est.seconds_min() > WARN_SECONDS).then(|| {
        format!(
            "this run takes at least {:.3e} steps ({}) on {} cells: roughly {hours:.1} h or more",
            est.steps_min,
            floor_reason(config, &est),
            est.cells
        )
    }))
}

/// The grid options, as the user gave them, for messages.
fn grid_flags(config: &RunConfig) -> String {
    let g = &config.grid;
    match g.stretch {
        Stretch::GrowthCap(r) => format!(
            "--resolution {} --extent {} --growth {r}",
            g.resolution, g.extent_x
        ),
        Stretch::Intervals { .. } => "--seed-grid".into(),
    }
}

fn check_memory(
    config: &RunConfig,
    est: &Estimate,
    limits: &LimitArgs,
    recording: Option<usize>,
) -> anyhow::Result<()> {
    let need = est.memory_bytes(recording);
    let (limit, shown) = memory_limit(&limits.max_memory)?;
    let what = format!(
        "{}: the grid has {} x {} = {} cells and its pressure factor ≈ {:.2e} nonzeros",
        grid_flags(config),
        est.nx,
        est.ny,
        est.cells,
        est.factor_nonzeros
    );
    let cure = "reduce --resolution or --extent, or raise --growth";
    if est.factor_nonzeros > FACTOR_NONZERO_LIMIT {
        anyhow::bail!(
            "{what}, more than the {FACTOR_NONZERO_LIMIT:.3e} its 32-bit indices can address; {cure}"
        );
    }
    if need > limit {
        anyhow::bail!(
            "{what}, needing ≈ {} of memory; accepted: up to --max-memory {} ({shown}); {cure}, or raise --max-memory",
            human_bytes(need),
            limits.max_memory
        );
    }
    Ok(())
}

fn check_steps(config: &RunConfig, est: &Estimate, limits: &LimitArgs) -> anyhow::Result<()> {
    if !(limits.max_steps.is_finite() && limits.max_steps >= 1.0) {
        anyhow::bail!(
            "--max-steps {}: must be a finite number >= 1",
            limits.max_steps
        );
    }
    if est.steps_min <= limits.max_steps {
        return Ok(());
    }
    let (flag, cure) = match est.dt_floor_from {
        DtFloor::Viscous => (
            format!("--re {}", show(config.flow.re)),
            "raise --re, shorten --t-end or coarsen --resolution",
        ),
        DtFloor::Ceiling => (
            format!("--dt-max {}", show(config.time.dt_max)),
            "raise --dt-max or shorten --t-end",
        ),
    };
    anyhow::bail!(
        "{flag}: with {} reaching --t-end {} takes at least {:.3e} steps; accepted: up to --max-steps {:.0e}; {cure}, or raise --max-steps",
        floor_reason(config, est),
        config.time.t_end,
        est.steps_min,
        limits.max_steps
    )
}

/// "Δt ≤ 1.2e-5 (the explicit viscous limit at Re 1)" or "Δt ≤ 0.01 (--dt-max)".
fn floor_reason(config: &RunConfig, est: &Estimate) -> String {
    match est.dt_floor_from {
        DtFloor::Viscous => format!(
            "Δt ≤ {:.3e} from the explicit viscous limit at Re {}",
            est.dt_floor,
            show(config.flow.re)
        ),
        DtFloor::Ceiling => format!("Δt ≤ {} from --dt-max", show(est.dt_floor)),
    }
}

/// A number as typed: plain, or in exponent form when very small or large.
fn show(x: f64) -> String {
    if x != 0.0 && !(1e-4..1e7).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// The memory limit in bytes and how it was worked out.
pub(super) fn memory_limit(spec: &str) -> anyhow::Result<(f64, String)> {
    let bad = || {
        anyhow::anyhow!(
            "--max-memory {spec:?}: accepted: a share of physical memory like \"75%\", a size like \"16GB\" or \"512MiB\", or \"unlimited\""
        )
    };
    let s = spec.trim();
    if s.eq_ignore_ascii_case("unlimited") {
        return Ok((f64::INFINITY, "unlimited".into()));
    }
    if let Some(pct) = s.strip_suffix('%') {
        let p: f64 = pct.trim().parse().map_err(|_| bad())?;
        if !(p > 0.0 && p <= 100.0) {
            return Err(bad());
        }
        let (total, known) = match physical_memory() {
            Some(t) => (t, ""),
            None => (FALLBACK_MEMORY, ", assumed: physical memory unknown"),
        };
        let limit = total * p / 100.0;
        let shown = format!("{} of {}{known}", human_bytes(limit), human_bytes(total));
        return Ok((limit, shown));
    }
    let bytes = parse_size(s).ok_or_else(bad)?;
    Ok((bytes, human_bytes(bytes)))
}

/// "16GB", "512MB", "2GiB", "1e9" → bytes.
fn parse_size(s: &str) -> Option<f64> {
    if let Ok(n) = s.parse::<f64>() {
        return (n.is_finite() && n > 0.0).then_some(n);
    }
    let split = s.find(|c: char| c.is_ascii_alphabetic()).unwrap_or(s.len());
    let (num, unit) = s.split_at(split);
    let n: f64 = num.trim().parse().ok()?;
    let scale = match unit.trim().to_ascii_lowercase().as_str() {
        "" | "b" => 1.0,
        "kb" => 1e3,
        "mb" => 1e6,
        "gb" => 1e9,
        "tb" => 1e12,
        "kib" => 1024.0,
        "mib" => 1024.0 * 1024.0,
        "gib" => 1024.0 * 1024.0 * 1024.0,
        "tib" => 1024f64.powi(4),
        _ => return None,
    };
    (n.is_finite() && n > 0.0).then_some(n * scale)
}

/// Physical memory (MemTotal of /proc/meminfo), if known.
fn physical_memory() -> Option<f64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = text.lines().find(|l| l.starts_with("MemTotal:"))?;
    let kb: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024.0)
}

/// "1.5 GB", "230 MB".
fn human_bytes(b: f64) -> String {
    if b >= 1e9 {
        format!("{:.1} GB", b / 1e9)
    } else {
        format!("{:.0} MB", b / 1e6)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_and_shares_parse() {
        assert_eq!(parse_size("16GB"), Some(16e9));
        assert_eq!(parse_size("512 MiB"), Some(512.0 * 1024.0 * 1024.0));
        assert_eq!(parse_size("lots"), None);
        assert_eq!(parse_size("1e9"), Some(1e9));
        assert_eq!(parse_size("-1GB"), None);
        assert!(memory_limit("50%").unwrap().0 > 0.0);
        assert!(memory_limit("150%").is_err());
        assert_eq!(memory_limit("unlimited").unwrap().0, f64::INFINITY);
    }
}
