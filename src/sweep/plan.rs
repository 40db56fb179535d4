//! The sweep plan (a TOML file): which case, the fixed options, the swept ones (a full grid and/or
//! a zipped group), the output directory, the per-case outputs, the phase diagram and the Slurm
//! resources. Parsing checks everything that can be checked before a case runs; every error is one
//! line naming the plan, the value and what is accepted.
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::options::{CaseCommands, OptionInfo, MANAGED};
use super::slurm_time::{time_limit_seconds, DEFAULT_TIME};
use super::values::{describe, expand, one_line, Scale, Value};
use platefall_core::sim::CaseKind;

pub(crate) use super::plan_error::{plan_err, PlanError};

/// `[outputs]`: what each case writes besides its summary, CSV and log.
#[derive(Clone, Copy, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub(crate) struct Outputs {
    /// Also write each case's Rerun recording, `cases/<id>/run.rrd`.
    #[serde(default)]
    pub(crate) recording: bool,
    /// Also write each case's flow for ParaView, `cases/<id>/vtk/` (`--vtk`).
    #[serde(default)]
    pub(crate) vtk: bool,
}

/// `[diagram]` as written.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
struct RawDiagram {
    x: Option<String>,
    y: Option<String>,
    value: Option<String>,
    x_scale: Option<Scale>,
    y_scale: Option<Scale>,
}

/// The phase diagram: two swept options as axes, and the summary key of the second panel.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Diagram {
    pub(crate) x: String,
    pub(crate) y: Option<String>,
    pub(crate) value: String,
    pub(crate) x_scale: Scale,
    pub(crate) y_scale: Scale,
}

/// `[slurm]`: resources of each array task (command-line flags override them).
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub(crate) struct SlurmPlan {
    /// Wall-time limit per case, as sbatch takes it (e.g. "01:00:00").
    pub(crate) time: Option<String>,
    /// Memory per case, as sbatch takes it (e.g. "2G").
    pub(crate) memory: Option<String>,
    /// CPUs per case.
    pub(crate) cpus: Option<u32>,
    pub(crate) partition: Option<String>,
    /// At most this many array tasks at once (`--array=...%N`).
    pub(crate) max_parallel: Option<u32>,
    /// Seconds before the time limit at which Slurm sends SIGUSR1 (None: 120, or a quarter of
    /// the time limit when that is shorter).
    #[serde(default, deserialize_with = "signal_lead")]
    pub(crate) signal_lead: Option<u32>,
    /// Extra sbatch options, one per line, e.g. "--account=abc" (written as `#SBATCH --account=abc`).
    #[serde(default)]
    pub(crate) sbatch: Vec<String>,
    /// Shell lines run before each case, e.g. "module load gcc".
    #[serde(default)]
    pub(crate) setup: Vec<String>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
struct RawPlan {
    case: String,
    name: Option<String>,
    output: Option<PathBuf>,
    #[serde(default)]
    fixed: toml::Table,
    #[serde(default)]
    grid: toml::Table,
    #[serde(default)]
    zip: toml::Table,
    #[serde(default)]
    outputs: Outputs,
    #[serde(default)]
    diagram: RawDiagram,
    #[serde(default)]
    slurm: SlurmPlan,
}

/// One swept option and its values.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Axis {
    pub(crate) name: String,
    pub(crate) values: Vec<Value>,
    pub(crate) scale: Scale,
}

/// A checked plan.
#[derive(Clone, Debug)]
pub(crate) struct Plan {
    /// Used in titles and job names: `name`, or the plan file's stem.
    pub(crate) name: String,
    pub(crate) case: CaseKind,
    /// The output directory as written (None: give --output).
    pub(crate) output: Option<PathBuf>,
    pub(crate) fixed: Vec<(String, Value)>,
    /// Full-grid options, outermost first.
    pub(crate) grid: Vec<Axis>,
    /// Zipped options (advanced together; innermost).
    pub(crate) zip: Vec<Axis>,
    pub(crate) outputs: Outputs,
    pub(crate) diagram: Diagram,
    pub(crate) slurm: SlurmPlan,
    /// The plan file's text, copied into the sweep directory.
    pub(crate) text: String,
}

/// One case of a sweep.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct CaseSpec {
    pub(crate) index: usize,
    /// Stable and readable, e.g. `0003-alpha=0.4-re=1000`.
    pub(crate) id: String,
    /// The swept options' values.
    pub(crate) params: Vec<(String, Value)>,
    /// The case's own options (`[case, --opt=value, ...]`), without the outputs the sweep adds.
    pub(crate) args: Vec<String>,
}

/// Reads and checks a plan file.
pub(crate) fn load(path: &Path, commands: &dyn CaseCommands) -> Result<Plan, PlanError> {
    let shown = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| plan_err!("plan {shown}: {e}"))?;
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "sweep".into());
    parse(&text, &stem, commands).map_err(|e| plan_err!("plan {shown}: {e}"))
}

/// Parses and checks a plan's text (`stem` names it when it has no `name`).
pub(crate) fn parse(
    text: &str,
    stem: &str,
    commands: &dyn CaseCommands,
) -> Result<Plan, PlanError> {
    let raw: RawPlan = toml::from_str(text).map_err(|e| toml_error(&e, text))?;
    let Some(case) = CaseKind::from_name(&raw.case) else {
        let names: Vec<&str> = CaseKind::ALL.iter().map(|k| k.name()).collect();
        return Err(plan_err!(
            "case = \"{}\" is not a case: accepted {}",
            raw.case,
            names.join(", ")
        ));
    };
    let known = commands.options(case);
    let mut seen = Vec::new();
    let fixed = fixed_options(&raw.fixed, &known, case, &mut seen)?;
    let grid = axes(&raw.grid, "grid", &known, case, &mut seen)?;
    let zip = axes(&raw.zip, "zip", &known, case, &mut seen)?;
    check_zip(&zip)?;
    let diagram = diagram(&raw.diagram, &grid, &zip, case)?;
    let name = raw.name.clone().unwrap_or_else(|| stem.to_string());
    let plan = Plan {
        name,
        case,
        output: raw.output,
        fixed,
        grid,
        zip,
        outputs: raw.outputs,
        diagram,
        slurm: raw.slurm,
        text: text.to_string(),
    };
    check_slurm(&plan.slurm, &[])?;
    Ok(plan)
}

/// A TOML error on one line, with its line number.
fn toml_error(e: &toml::de::Error, text: &str) -> PlanError {
    let msg = one_line(e.message());
    match e.span() {
        Some(span) => {
            let line = text[..span.start.min(text.len())].matches('\n').count() + 1;
            plan_err!("line {line}: {msg}")
        }
        None => PlanError(msg),
    }
}

/// An option name as on the command line: `t_end` and `--t-end` are `t-end`.
fn normalise(name: &str) -> String {
    name.trim_start_matches("--").replace('_', "-")
}

/// Checks an option name against the case's options and the ones already given.
fn check_name(
    raw: &str,
    table: &str,
    known: &[OptionInfo],
    case: CaseKind,
    seen: &mut Vec<(String, String)>,
) -> Result<OptionInfo, PlanError> {
    let name = normalise(raw);
    if MANAGED.contains(&name.as_str()) {
        return Err(plan_err!(
            "[{table}] {raw}: the sweep sets --{name} itself for every case (under DIR/cases/<id>/); remove it"
        ));
    }
    let Some(info) = known.iter().find(|o| o.name == name) else {
        let accepted: Vec<&str> = known
            .iter()
            .map(|o| o.name.as_str())
            .filter(|n| !MANAGED.contains(n))
            .collect();
        return Err(plan_err!(
            "[{table}] {raw}: `{case}` has no option --{name}: accepted {}",
            accepted.join(", ")
        ));
    };
    if let Some((_, other)) = seen.iter().find(|(n, _)| *n == name) {
        return Err(plan_err!(
            "[{table}] {raw}: option --{name} is already given in [{other}]; give each option once"
        ));
    }
    seen.push((name, table.to_string()));
    Ok(info.clone())
}

/// A value's type against the option's: flags take true/false, other options anything else.
fn check_kind(info: &OptionInfo, v: &Value, what: &str) -> Result<(), PlanError> {
    match (info.takes_value, v) {
        (false, Value::Bool(_)) => Ok(()),
        (false, other) => Err(plan_err!(
            "{what} = {}: --{} is a flag: accepted true or false",
            other.arg(),
            info.name
        )),
        (true, Value::Bool(b)) => Err(plan_err!(
            "{what} = {b}: --{} takes a value, not true/false",
            info.name
        )),
        (true, _) => Ok(()),
    }
}

/// `[fixed]`: one value per option.
fn fixed_options(
    table: &toml::Table,
    known: &[OptionInfo],
    case: CaseKind,
    seen: &mut Vec<(String, String)>,
) -> Result<Vec<(String, Value)>, PlanError> {
    let mut out = Vec::new();
    for (raw, v) in table {
        let info = check_name(raw, "fixed", known, case, seen)?;
        let what = format!("[fixed] {raw}");
        if matches!(v, toml::Value::Array(_) | toml::Value::Table(_)) {
            return Err(plan_err!(
                "{what}: [fixed] takes one value per option; sweep lists and ranges in [grid] or [zip]"
            ));
        }
        let value = Value::from_toml(v, &what)?;
        check_kind(&info, &value, &what)?;
        out.push((info.name, value));
    }
    Ok(out)
}

/// `[grid]` or `[zip]`: the swept options in file order.
fn axes(
    table: &toml::Table,
    section: &str,
    known: &[OptionInfo],
    case: CaseKind,
    seen: &mut Vec<(String, String)>,
) -> Result<Vec<Axis>, PlanError> {
    let mut out = Vec::new();
    for (raw, v) in table {
        let info = check_name(raw, section, known, case, seen)?;
        let what = format!("[{section}] {raw}");
        let (values, scale) = expand(v, &what)?;
        for value in &values {
            check_kind(&info, value, &what)?;
        }
        out.push(Axis {
            name: info.name,
            values,
            scale,
        });
    }
    Ok(out)
}

/// Zipped options advance together, so their lists must have one length.
fn check_zip(zip: &[Axis]) -> Result<(), PlanError> {
    let Some(first) = zip.first() else {
        return Ok(());
    };
    for a in &zip[1..] {
        if a.values.len() != first.values.len() {
            return Err(plan_err!(
                "[zip] {} has {} values but {} has {}: zipped options need equally many values",
                a.name,
                a.values.len(),
                first.name,
                first.values.len()
            ));
        }
    }
    Ok(())
}

/// The summary key shown by default in the second panel.
fn default_value_key(case: CaseKind) -> &'static str {
    match case {
        CaseKind::Static => "mean_cl",
        CaseKind::Forced => "mean_cm",
        CaseKind::Pinned | CaseKind::Free => "mean_omega",
    }
}

/// `[diagram]`: axes default to the first two swept options.
fn diagram(
    raw: &RawDiagram,
    grid: &[Axis],
    zip: &[Axis],
    case: CaseKind,
) -> Result<Diagram, PlanError> {
    let swept: Vec<&Axis> = grid.iter().chain(zip).collect();
    if swept.is_empty() {
        return Err(PlanError(
            "nothing is swept: give at least one option in [grid] or [zip] (e.g. alpha = [0.2, 0.4])"
                .into(),
        ));
    }
    let names: Vec<&str> = swept.iter().map(|a| a.name.as_str()).collect();
    let pick = |key: &str, given: &Option<String>, default: Option<&str>| match given {
        Some(n) => {
            let n = normalise(n);
            match swept.iter().find(|a| a.name == n) {
                Some(a) => Ok(Some(a.name.clone())),
                None => Err(plan_err!(
                    "[diagram] {key} = \"{n}\" is not a swept option: accepted {}",
                    names.join(", ")
                )),
            }
        }
        None => Ok(default.map(str::to_string)),
    };
    let x = pick("x", &raw.x, names.first().copied())?.unwrap_or_default();
    let y_default = names.iter().copied().find(|n| *n != x);
    // `y = ""` asks for a one-parameter diagram even when more options are swept.
    let y = match raw.y.as_deref() {
        Some("") => None,
        _ => pick("y", &raw.y, y_default)?,
    };
    if y.as_deref() == Some(x.as_str()) {
        return Err(plan_err!(
            "[diagram] x and y are both \"{x}\": choose two different swept options"
        ));
    }
    let scale_of = |name: &str| {
        swept
            .iter()
            .find(|a| a.name == name)
            .map(|a| a.scale)
            .unwrap_or_default()
    };
    Ok(Diagram {
        x_scale: raw.x_scale.unwrap_or_else(|| scale_of(&x)),
        y_scale: raw
            .y_scale
            .unwrap_or_else(|| y.as_deref().map(scale_of).unwrap_or_default()),
        value: raw
            .value
            .clone()
            .unwrap_or_else(|| default_value_key(case).to_string()),
        x,
        y,
    })
}

/// `signal-lead`: a whole number of seconds Slurm's `--signal` takes (1 to 65535); anything
/// else is one line naming the value.
fn signal_lead<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<u32>, D::Error> {
    let v = toml::Value::deserialize(d)?;
    match v.as_integer().map(u32::try_from) {
        Some(Ok(n)) if (1..=MAX_SIGNAL_LEAD).contains(&n) => Ok(Some(n)),
        _ => Err(serde::de::Error::custom(format!(
            "[slurm] signal-lead = {}: accepted whole seconds from 1 to {MAX_SIGNAL_LEAD}, shorter than the time limit",
            describe(&v)
        ))),
    }
}

/// The longest `--signal` lead Slurm takes, in seconds.
pub(crate) const MAX_SIGNAL_LEAD: u32 = 65535;

/// The `[slurm]` keys and the `platefall sweep --slurm` flags that override them.
const SLURM_FLAGS: [(&str, &str); 6] = [
    ("time", "--time"),
    ("memory", "--mem"),
    ("partition", "--partition"),
    ("cpus", "--cpus"),
    ("max-parallel", "--max-parallel"),
    ("signal-lead", "--signal-lead"),
];

/// A `[slurm]` value as a refusal names it: the flag that gave it (`--time "1h"`) when its key
/// is among `from_flags`, else the plan's key (`[slurm] time = "1h"`).
fn shown(key: &str, value: impl std::fmt::Display, from_flags: &[&str]) -> String {
    match SLURM_FLAGS.iter().find(|(k, _)| *k == key) {
        Some((_, flag)) if from_flags.contains(&key) => format!("{flag} {value}"),
        _ => format!("[slurm] {key} = {value}"),
    }
}

/// Slurm strings end up in a shell script: refuse line breaks. The time limit must be one Slurm
/// reads, and the signal lead shorter than it. `from_flags`: the keys whose values came from
/// the command line (the messages name those flags).
pub(crate) fn check_slurm(s: &SlurmPlan, from_flags: &[&str]) -> Result<(), PlanError> {
    let fields = [
        ("time", &s.time),
        ("memory", &s.memory),
        ("partition", &s.partition),
    ];
    for (key, v) in fields {
        if let Some(v) = v {
            if v.is_empty() || v.contains(['\n', '\r', ' ']) {
                return Err(plan_err!(
                    "{}: accepted one word as sbatch takes it (e.g. 01:00:00 for the time, 2G for the memory)",
                    shown(key, format!("{v:?}"), from_flags)
                ));
            }
        }
    }
    for (key, v) in [("cpus", s.cpus), ("max-parallel", s.max_parallel)] {
        if v == Some(0) {
            return Err(plan_err!(
                "{}: accepted 1 or more",
                shown(key, 0, from_flags)
            ));
        }
    }
    check_signal_lead(s, from_flags)?;
    for line in s.sbatch.iter().chain(&s.setup) {
        if line.contains(['\n', '\r']) {
            return Err(plan_err!(
                "[slurm] {line:?}: one line per entry (no line breaks)"
            ));
        }
    }
    Ok(())
}

/// The time limit is one Slurm reads, and an explicit signal lead is shorter than it (and one
/// Slurm takes).
fn check_signal_lead(s: &SlurmPlan, from_flags: &[&str]) -> Result<(), PlanError> {
    let time = s.time.as_deref().unwrap_or(DEFAULT_TIME);
    let Some(limit) = time_limit_seconds(time) else {
        return Err(plan_err!(
            "{}: accepted minutes, minutes:seconds, hours:minutes:seconds, days-hours, days-hours:minutes, days-hours:minutes:seconds, or UNLIMITED",
            shown("time", format!("{time:?}"), from_flags)
        ));
    };
    let most = limit.map_or(u64::from(MAX_SIGNAL_LEAD), |l| {
        (l.saturating_sub(1)).min(u64::from(MAX_SIGNAL_LEAD))
    });
    match s.signal_lead {
        Some(lead) if lead == 0 || u64::from(lead) > most => Err(plan_err!(
            "{}: accepted whole seconds from 1 to {most}, shorter than the time limit {time}{}",
            shown("signal-lead", lead, from_flags),
            limit.map_or(String::new(), |l| format!(" ({l} s)"))
        )),
        _ => Ok(()),
    }
}

/// How the `plan.toml` of a plan made by a command begins (then the command's name): such a
/// directory goes on with that command, not with `platefall sweep`.
pub(crate) const MADE_BY: &str = "# made by `platefall ";

impl Plan {
    /// A plan made by a command rather than read from a file (`platefall ensemble`): cases of
    /// `case` along the one swept `axis`, with the diagram along it and nothing else; `text` is
    /// what the directory's `plan.toml` records.
    pub(crate) fn along(name: &str, case: CaseKind, axis: Axis, text: String) -> Plan {
        let diagram = Diagram {
            x: axis.name.clone(),
            y: None,
            value: default_value_key(case).to_string(),
            x_scale: axis.scale,
            y_scale: Scale::default(),
        };
        Plan {
            name: name.to_string(),
            case,
            output: None,
            fixed: Vec::new(),
            grid: vec![axis],
            zip: Vec::new(),
            outputs: Outputs::default(),
            diagram,
            slurm: SlurmPlan::default(),
            text,
        }
    }
}
