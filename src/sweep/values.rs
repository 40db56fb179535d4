//! Option values in a plan: single values, lists and ranges (linear or logarithmic), and how a
//! value is written on a command line and in a case id.
use serde::{Deserialize, Serialize};

use super::plan_error::{plan_err, PlanError};
pub(crate) use platefall_post::phase::Scale;

/// One value of an option, as written in the plan.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub(crate) enum Value {
    Bool(bool),
    Int(i64),
    Float(f64),
    Text(String),
}

/// Significant digits kept when a computed range value is written out (so a log range from 16 to
/// 64 gives 32, not 31.999999999999996).
const RANGE_DIGITS: usize = 12;

impl Value {
    /// The value as a command-line argument.
    pub(crate) fn arg(&self) -> String {
        match self {
            Value::Bool(b) => b.to_string(),
            Value::Int(i) => i.to_string(),
            Value::Float(x) => format!("{x}"),
            Value::Text(s) => s.clone(),
        }
    }

    /// The value as a number, when it is one.
    pub(crate) fn as_f64(&self) -> Option<f64> {
        match self {
            Value::Int(i) => Some(*i as f64),
            Value::Float(x) => Some(*x),
            _ => None,
        }
    }

    /// The value in a case id: the argument with anything but `[A-Za-z0-9.+_-]` replaced by `_`.
    pub(crate) fn id_part(&self) -> String {
        self.arg()
            .chars()
            .map(|c| {
                if c.is_ascii_alphanumeric() || "._+-".contains(c) {
                    c
                } else {
                    '_'
                }
            })
            .collect()
    }

    /// A plan value: a boolean, integer, float or string (`what` names it in errors).
    pub(crate) fn from_toml(v: &toml::Value, what: &str) -> Result<Value, PlanError> {
        match v {
            toml::Value::Boolean(b) => Ok(Value::Bool(*b)),
            toml::Value::Integer(i) => Ok(Value::Int(*i)),
            toml::Value::Float(x) if x.is_finite() => Ok(Value::Float(*x)),
            toml::Value::Float(x) => Err(plan_err!("{what} = {x}: not a finite number")),
            toml::Value::String(s) => Ok(Value::Text(s.clone())),
            other => Err(plan_err!(
                "{what} is {}: accepted a number, a string or true/false",
                describe(other)
            )),
        }
    }
}

/// Rounds to [`RANGE_DIGITS`] significant digits (the nearest double to that decimal).
fn tidy(x: f64) -> f64 {
    format!("{:.*e}", RANGE_DIGITS - 1, x).parse().unwrap_or(x)
}

/// `{ from = A, to = B, count = N, scale = "linear" | "log" }` in a plan.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RangeSpec {
    from: f64,
    to: f64,
    count: i64,
    #[serde(default)]
    scale: Scale,
}

/// The values of a swept option: a list, or a range table. `what` names it in errors.
pub(crate) fn expand(v: &toml::Value, what: &str) -> Result<(Vec<Value>, Scale), PlanError> {
    match v {
        toml::Value::Array(items) => {
            if items.is_empty() {
                return Err(plan_err!(
                    "{what} = []: an empty list (accepted: one value or more)"
                ));
            }
            let values = items
                .iter()
                .map(|x| Value::from_toml(x, what))
                .collect::<Result<Vec<_>, _>>()?;
            Ok((values, Scale::Linear))
        }
        toml::Value::Table(t) => {
            let spec: RangeSpec = t.clone().try_into().map_err(|e: toml::de::Error| {
                plan_err!(
                    "{what}: {} (a range is {{ from = A, to = B, count = N, scale = \"linear\" | \"log\" }})",
                    one_line(e.message())
                )
            })?;
            Ok((range(&spec, what)?, spec.scale))
        }
        other => Err(plan_err!(
            "{what} is {}: a swept option takes a list [a, b, ...] or a range {{ from = A, to = B, count = N }}",
            describe(other)
        )),
    }
}

/// The values of a range, checked.
fn range(r: &RangeSpec, what: &str) -> Result<Vec<Value>, PlanError> {
    if r.count < 1 {
        return Err(plan_err!(
            "{what}: count = {} is out of range: accepted 1 or more",
            r.count
        ));
    }
    if r.count > 100_000 {
        return Err(plan_err!(
            "{what}: count = {} is out of range: accepted at most 100000",
            r.count
        ));
    }
    if !r.from.is_finite() || !r.to.is_finite() {
        return Err(plan_err!("{what}: from and to must be finite numbers"));
    }
    if r.scale == Scale::Log && (r.from <= 0.0 || r.to <= 0.0) {
        return Err(plan_err!(
            "{what}: a log range needs from > 0 and to > 0 (got from = {}, to = {})",
            r.from,
            r.to
        ));
    }
    let n = r.count as usize;
    let at = |i: usize| -> f64 {
        if n == 1 {
            return r.from;
        }
        let s = i as f64 / (n - 1) as f64;
        match r.scale {
            Scale::Linear => r.from + s * (r.to - r.from),
            Scale::Log => r.from * (r.to / r.from).powf(s),
        }
    };
    Ok((0..n).map(|i| Value::Float(tidy(at(i)))).collect())
}

/// What kind of TOML value `v` is, for errors.
pub(crate) fn describe(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => format!("the string {s:?}"),
        toml::Value::Integer(i) => format!("the number {i}"),
        toml::Value::Float(x) => format!("the number {x}"),
        toml::Value::Boolean(b) => format!("{b}"),
        toml::Value::Datetime(d) => format!("the date {d}"),
        toml::Value::Array(_) => "a list".into(),
        toml::Value::Table(_) => "a table".into(),
    }
}

/// A possibly multi-line message on one line.
pub(crate) fn one_line(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}
