//! A refinement study's levels: the refined option, its values, and the sweep plan written from
//! the case's own options.
use std::path::PathBuf;

use crate::sweep::failure::Failure;
use crate::sweep::plan_error::{plan_err, PlanError};
use crate::sweep::CaseCommands;
use platefall_core::sim::CaseKind;

/// The refined option and how a level's representative spacing h follows from it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Refined {
    /// h = 1/N, the cell size at the plate in chords.
    Resolution,
    /// A time-step control: h is the run's mean time step t_end / steps.
    TimeStep(&'static str),
    /// h = 1/extent (the truncation of the domain).
    Extent,
}

impl Refined {
    pub(crate) fn from_name(name: &str) -> Result<Refined, PlanError> {
        match name {
            "resolution" => Ok(Refined::Resolution),
            "cc" => Ok(Refined::TimeStep("cc")),
            "cfl" => Ok(Refined::TimeStep("cfl")),
            "dt-max" | "dt_max" => Ok(Refined::TimeStep("dt-max")),
            "extent" => Ok(Refined::Extent),
            other => Err(plan_err!(
                "--refine {other}: not a refinable option: accepted resolution, cc, cfl, dt-max, \
                 extent"
            )),
        }
    }

    pub(crate) fn name(self) -> &'static str {
        match self {
            Refined::Resolution => "resolution",
            Refined::TimeStep(n) => n,
            Refined::Extent => "extent",
        }
    }

    /// What h is, for the study's header.
    pub(crate) fn spacing(self) -> &'static str {
        match self {
            Refined::Resolution => "h = 1/N, the cell size at the plate (chords)",
            Refined::TimeStep(_) => "h = t_end / steps, the run's mean time step (c/U)",
            Refined::Extent => {
                "h = 1/extent, the inverse distance to the outer boundary (1/chords)"
            }
        }
    }
}

/// A study ready to run: its directory, plan and refined option.
pub(crate) struct Study {
    pub(crate) output: PathBuf,
    pub(crate) refined: Refined,
    pub(crate) plan_text: String,
    pub(crate) jobs: usize,
}

/// `--refine NAME=V1,V2,...`: the option and its values as written (numbers, at least three,
/// distinct, positive; whole for the resolution).
pub(crate) fn refine_values(spec: &str) -> Result<(Refined, Vec<String>), PlanError> {
    let (name, list) = spec.split_once('=').ok_or_else(|| {
        plan_err!("--refine {spec}: expected OPTION=V1,V2,V3, e.g. resolution=32,64,128")
    })?;
    let refined = Refined::from_name(name.trim())?;
    let values: Vec<String> = list.split(',').map(|v| v.trim().to_string()).collect();
    let mut nums = Vec::new();
    for v in &values {
        let x: f64 = v.parse().map_err(|_| {
            plan_err!("--refine {name}: {v:?} is not a number: accepted positive numbers")
        })?;
        let whole = refined != Refined::Resolution || (x.fract() == 0.0 && x >= 1.0);
        if !(x.is_finite() && x > 0.0 && whole) {
            let what = if refined == Refined::Resolution {
                "whole numbers of cells per chord (≥ 4)"
            } else {
                "positive numbers"
            };
            return Err(plan_err!(
                "--refine {name}: {v} is out of range: accepted {what}"
            ));
        }
        if nums.iter().any(|y: &f64| (y - x).abs() <= 1e-12 * x) {
            return Err(plan_err!(
                "--refine {name}: {v} is given twice: the levels must differ"
            ));
        }
        nums.push(x);
    }
    if values.len() < 3 {
        return Err(plan_err!(
            "--refine {name}: {} value(s) given: accepted 3 or more (an order needs three levels)",
            values.len()
        ));
    }
    Ok((refined, values))
}

/// A TOML basic string.
fn toml_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if c.is_control() => out.push_str(&format!("\\u{:04X}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// The case's options as (name, value) pairs for the plan's `[fixed]` (a flag is `true`).
fn fixed_options(
    case: CaseKind,
    argv: &[String],
    commands: &dyn CaseCommands,
) -> Result<Vec<(String, String)>, PlanError> {
    let known = commands.options(case);
    let mut out: Vec<(String, String)> = Vec::new();
    let mut k = 0;
    while k < argv.len() {
        let arg = &argv[k];
        let Some(body) = arg.strip_prefix("--") else {
            return Err(plan_err!(
                "{arg:?} is not an option of `{case}`: give the case's options as --name value"
            ));
        };
        let (name, inline) = match body.split_once('=') {
            Some((n, v)) => (n.to_string(), Some(v.to_string())),
            None => (body.to_string(), None),
        };
        let info = known.iter().find(|o| o.name == name).ok_or_else(|| {
            let names: Vec<&str> = known.iter().map(|o| o.name.as_str()).collect();
            plan_err!(
                "`{case}` has no option --{name}: accepted {}",
                names.join(", ")
            )
        })?;
        let value = if info.takes_value {
            match inline {
                Some(v) => v,
                None => {
                    k += 1;
                    argv.get(k)
                        .cloned()
                        .ok_or_else(|| plan_err!("--{name} needs a value"))?
                }
            }
        } else {
            match inline.as_deref() {
                None | Some("true") => "true".into(),
                Some("false") => "false".into(),
                Some(v) => return Err(plan_err!("--{name} is a flag: {v:?} is not accepted")),
            }
        };
        out.push((name, value));
        k += 1;
    }
    Ok(out)
}

/// The names of the cases, for messages.
fn case_names() -> String {
    let names: Vec<&str> = CaseKind::ALL.iter().map(|k| k.name()).collect();
    names.join(", ")
}

/// Checks a study's request and writes its plan.
pub(crate) fn study_of(
    refine: &str,
    output: &std::path::Path,
    jobs: usize,
    threads: Option<usize>,
    argv: &[String],
    commands: &dyn CaseCommands,
) -> Result<Study, Failure> {
    let bad = |m: String| Failure::input(m);
    let (refined, values) = refine_values(refine)?;
    if jobs == 0 {
        return Err(bad("--jobs 0 is out of range: accepted 1 or more".into()));
    }
    let Some((name, rest)) = argv.split_first() else {
        return Err(bad(format!(
            "give the case after the options: one of {}",
            case_names()
        )));
    };
    let Some(case) = CaseKind::from_name(name) else {
        return Err(bad(format!(
            "{name:?} is not a case: accepted {}",
            case_names()
        )));
    };
    let mut fixed = fixed_options(case, rest, commands)?;
    let same = |n: &str| n.replace('_', "-") == refined.name();
    if fixed.iter().any(|(n, _)| same(n)) {
        return Err(bad(format!(
            "--{} is the refined option: give its values only in --refine",
            refined.name()
        )));
    }
    if let Some(t) = threads {
        if !fixed.iter().any(|(n, _)| n == "threads") {
            fixed.push(("threads".into(), t.to_string()));
        }
    } else if !fixed.iter().any(|(n, _)| n == "threads") {
        let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
        fixed.push(("threads".into(), (cores / jobs).max(1).to_string()));
    }
    let mut text = format!(
        "# Written by `platefall converge`: the levels of a refinement study of `{case}`.\n\
         case = {}\nname = {}\n\n[fixed]\n",
        toml_string(case.name()),
        toml_string(&format!("converge-{}", refined.name()))
    );
    for (name, value) in &fixed {
        let v = match value.as_str() {
            "true" | "false" => value.clone(),
            v => toml_string(v),
        };
        text.push_str(&format!("{name} = {v}\n"));
    }
    let list: Vec<&str> = values.iter().map(String::as_str).collect();
    text.push_str(&format!(
        "\n[grid]\n{} = [{}]\n\n[diagram]\nx = {}\ny = \"\"\n",
        refined.name(),
        list.join(", "),
        toml_string(refined.name())
    ));
    Ok(Study {
        output: output.to_path_buf(),
        refined,
        plan_text: text,
        jobs,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refine_values_are_checked_with_one_line_errors() {
        assert!(refine_values("resolution=32,64,128").is_ok());
        assert_eq!(
            refine_values("cc=0.01,0.005,0.0025").unwrap().0,
            Refined::TimeStep("cc")
        );
        for (spec, needle) in [
            ("resolution=32,64", "accepted 3 or more"),
            ("resolution=32,64,64", "given twice"),
            ("resolution=32,48.5,64", "whole numbers"),
            ("cc=0.01,-0.005,0.0025", "positive"),
            ("cc=0.01,x,0.0025", "not a number"),
            ("alpha=1,2,3", "not a refinable option"),
            ("resolution", "expected OPTION="),
        ] {
            let e = refine_values(spec).unwrap_err().0;
            assert!(e.contains(needle) && !e.contains('\n'), "{spec}: {e}");
        }
    }

    #[test]
    fn case_options_become_the_plans_fixed_table() {
        let argv: Vec<String> = ["--thickness", "0.03125", "--turns=20", "--seed-grid"]
            .map(String::from)
            .to_vec();
        let cases = crate::cli::CommandLineCases;
        let f = fixed_options(CaseKind::Free, &argv, &cases).unwrap();
        assert_eq!(
            f,
            vec![
                ("thickness".into(), "0.03125".into()),
                ("turns".into(), "20".into()),
                ("seed-grid".into(), "true".into())
            ]
        );
        assert!(
            fixed_options(CaseKind::Free, &["--nope".to_string()], &cases)
                .unwrap_err()
                .0
                .contains("no option --nope")
        );
        assert!(fixed_options(CaseKind::Free, &["0.1".to_string()], &cases).is_err());
        assert_eq!(toml_string("a\"b\\c"), "\"a\\\"b\\\\c\"");
    }
}
