//! Slurm's time limits: the default of an array task and sbatch's `--time` format, below the plan
//! that checks them and the script that uses them.

/// The time limit of each array task when neither the plan nor a flag gives one.
pub(crate) const DEFAULT_TIME: &str = "01:00:00";

/// A time limit as sbatch's `--time` takes it, in seconds rounded up to whole minutes as Slurm
/// does: `Some(None)` for no limit (UNLIMITED, INFINITE, 0), None when Slurm would not read it.
pub(crate) fn time_limit_seconds(time: &str) -> Option<Option<u64>> {
    if ["unlimited", "infinite", "-1"].contains(&time.to_ascii_lowercase().as_str()) {
        return Some(None);
    }
    let number = |s: &str| {
        (!s.is_empty() && s.bytes().all(|b| b.is_ascii_digit()))
            .then(|| s.parse::<u64>().ok())
            .flatten()
    };
    let (days, clock) = match time.split_once('-') {
        Some((d, rest)) => (Some(number(d)?), rest),
        None => (None, time),
    };
    let parts: Vec<u64> = clock.split(':').map(number).collect::<Option<_>>()?;
    let seconds = match (days, parts.as_slice()) {
        (None, [m]) => m * 60,
        (None, [m, s]) => m * 60 + s,
        (None, [h, m, s]) => h * 3600 + m * 60 + s,
        (Some(d), [h]) => d * 86400 + h * 3600,
        (Some(d), [h, m]) => d * 86400 + h * 3600 + m * 60,
        (Some(d), [h, m, s]) => d * 86400 + h * 3600 + m * 60 + s,
        _ => return None,
    };
    Some((seconds > 0).then(|| seconds.div_ceil(60) * 60))
}
