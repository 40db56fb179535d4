//! A plan's cases: the full grid of the `[grid]` options (first option outermost) times the
//! `[zip]` group (innermost), each with a stable id and its own argument vector, all checked with
//! the command line's own validation before anything runs.
use super::options::{summary_keys, CaseCommands};
use super::plan::{plan_err, CaseSpec, Plan, PlanError};
use super::values::Value;

/// Most cases one plan may hold.
pub(crate) const MAX_CASES: usize = 100_000;
/// Longest parameter part of a case id (the index prefix keeps ids unique when it is cut).
const MAX_ID_PARAMS: usize = 120;

impl Plan {
    /// Number of cases.
    pub(crate) fn case_count(&self) -> usize {
        let grid: usize = self.grid.iter().map(|a| a.values.len()).product();
        grid * self.zip.first().map_or(1, |a| a.values.len())
    }

    /// The swept values of case `index`.
    fn params(&self, index: usize) -> Vec<(String, Value)> {
        let zip_len = self.zip.first().map_or(1, |a| a.values.len());
        let (mut rest, z) = (index / zip_len, index % zip_len);
        let mut grid = Vec::with_capacity(self.grid.len());
        for a in self.grid.iter().rev() {
            grid.push((a.name.clone(), a.values[rest % a.values.len()].clone()));
            rest /= a.values.len();
        }
        grid.reverse();
        let zipped = self
            .zip
            .iter()
            .map(|a| (a.name.clone(), a.values[z].clone()));
        grid.into_iter().chain(zipped).collect()
    }

    /// Case `index` of `width` digits.
    fn case(&self, index: usize, width: usize) -> CaseSpec {
        let params = self.params(index);
        let mut tail: String = params
            .iter()
            .map(|(n, v)| format!("-{n}={}", v.id_part()))
            .collect();
        if tail.len() > MAX_ID_PARAMS {
            let cut = (0..=MAX_ID_PARAMS)
                .rev()
                .find(|&i| tail.is_char_boundary(i));
            tail.truncate(cut.unwrap_or(0));
        }
        let id = format!("{index:0width$}{tail}");
        let mut args = vec![self.case.name().to_string()];
        for (name, v) in self.fixed.iter().chain(params.iter()) {
            match v {
                Value::Bool(true) => args.push(format!("--{name}")),
                Value::Bool(false) => {}
                other => args.push(format!("--{name}={}", other.arg())),
            }
        }
        CaseSpec {
            index,
            id,
            params,
            args,
        }
    }

    /// All cases, unchecked.
    pub(crate) fn cases(&self) -> Vec<CaseSpec> {
        let n = self.case_count();
        let width = n.saturating_sub(1).to_string().len().max(4);
        (0..n).map(|i| self.case(i, width)).collect()
    }

    /// All cases, each checked as the command line would check it, and the diagram's value key
    /// checked against the case's summary keys.
    pub(crate) fn checked_cases(
        &self,
        commands: &dyn CaseCommands,
    ) -> Result<Vec<CaseSpec>, PlanError> {
        let n = self.case_count();
        if n > MAX_CASES {
            return Err(plan_err!(
                "{n} cases: accepted at most {MAX_CASES} in one plan"
            ));
        }
        let cases = self.cases();
        let mut first = None;
        for c in &cases {
            let config = commands.config(&c.args).map_err(|e| {
                plan_err!("case {}: {e} (options: {})", c.id, c.args[1..].join(" "))
            })?;
            first.get_or_insert(config);
        }
        if let Some(config) = first {
            let keys = summary_keys(&config)?;
            let key = &self.diagram.value;
            if !keys.iter().any(|k| k == key) {
                return Err(plan_err!(
                    "[diagram] value = \"{key}\" is not a summary key of `{}`: accepted {}",
                    self.case,
                    keys.join(", ")
                ));
            }
        }
        Ok(cases)
    }
}
