//! The members' CSVs read back: the columns the ensemble's analysis and recording need, from the
//! branch on.
use std::path::Path;

use platefall_post::ensemble::MemberTrace;
use platefall_record::CSV_HEADER;

/// The time and the columns `names` of the rows of a member's CSV from `t0` on (rows that do
/// not parse are skipped); None when the file cannot be read or is not a 2-D run's CSV.
pub(crate) fn columns(csv: &Path, t0: f64, names: &[&str]) -> Option<(Vec<f64>, Vec<Vec<f64>>)> {
    let text = std::fs::read_to_string(csv).ok()?;
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next()?.split(',').collect();
    if header != CSV_HEADER.split(',').collect::<Vec<_>>() {
        return None;
    }
    let at: Vec<usize> = names
        .iter()
        .map(|n| header.iter().position(|h| h == n))
        .collect::<Option<_>>()?;
    let (mut t, mut cols) = (Vec::new(), vec![Vec::new(); names.len()]);
    for line in lines.filter(|l| !l.starts_with('#')) {
        let f: Vec<&str> = line.split(',').collect();
        let parse = |i: usize| f.get(i).and_then(|v| v.parse::<f64>().ok());
        let (Some(time), Some(values)) = (
            parse(0),
            at.iter().map(|&i| parse(i)).collect::<Option<Vec<_>>>(),
        ) else {
            continue;
        };
        if time >= t0 {
            t.push(time);
            cols.iter_mut().zip(values).for_each(|(c, v)| c.push(v));
        }
    }
    Some((t, cols))
}

/// Member `id`'s motion from its CSV from `t0` on.
pub(crate) fn trace(id: &str, csv: &Path, t0: f64) -> Option<MemberTrace> {
    let (t, mut c) = columns(csv, t0, &["X", "Y", "thetadot", "V"])?;
    let (speed, omega, y, x) = (c.pop()?, c.pop()?, c.pop()?, c.pop()?);
    Some(MemberTrace {
        id: id.to_string(),
        t,
        x,
        y,
        omega,
        speed,
    })
}
