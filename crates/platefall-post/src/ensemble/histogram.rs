//! The distribution of an ensemble's member means (docs/statistics.md, "Ensembles of independent
//! members"): equal bins over the members' range, as many as Sturges' rule gives for their count.

/// Counts of values in equal bins: bin k holds the values in [lo + k·width, lo + (k + 1)·width),
/// the last bin its upper edge as well.
#[derive(Clone, Debug, PartialEq)]
pub struct Histogram {
    /// The lower edge of the first bin.
    pub lo: f64,
    /// The width of every bin (positive).
    pub width: f64,
    /// How many values each bin holds.
    pub counts: Vec<usize>,
}

impl Histogram {
    /// The histogram of the finite values (others are left out): ⌈log₂ n⌉ + 1 bins spanning
    /// their smallest to their largest (Sturges' rule), or, when they are all equal, one bin
    /// centred on them of width 1e-6 of their size (1e-6 for zero). None without a finite value.
    #[must_use]
    pub fn of(values: &[f64]) -> Option<Histogram> {
        let finite: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
        let lo = finite.iter().copied().reduce(f64::min)?;
        let hi = finite.iter().copied().reduce(f64::max)?;
        let (lo, width, bins) = if hi > lo {
            let bins = (finite.len() as f64).log2().ceil() as usize + 1;
            (lo, (hi - lo) / bins as f64, bins)
        } else {
            let width = 1e-6 * lo.abs().max(1.0);
            (lo - 0.5 * width, width, 1)
        };
        let mut counts = vec![0; bins];
        for v in finite {
            let k = ((v - lo) / width).floor().max(0.0) as usize;
            counts[k.min(bins - 1)] += 1;
        }
        Some(Histogram { lo, width, counts })
    }

    /// Each bin's lower and upper edge and count, in order.
    pub fn bins(&self) -> impl Iterator<Item = (f64, f64, usize)> + '_ {
        self.counts.iter().enumerate().map(|(k, &n)| {
            let a = self.lo + k as f64 * self.width;
            (a, a + self.width, n)
        })
    }

    /// The upper edge of the last bin.
    #[must_use]
    pub fn hi(&self) -> f64 {
        self.lo + self.counts.len() as f64 * self.width
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bin_of(h: &Histogram, v: f64) -> usize {
        h.bins()
            .position(|(a, b, _)| v >= a && (v < b || (v <= b && (b - h.hi()).abs() < 1e-12)))
            .unwrap_or_else(|| panic!("{v} in no bin of {h:?}"))
    }

    #[test]
    fn every_finite_value_is_counted_once_in_the_bin_that_holds_it() {
        // 24 members: ⌈log₂ 24⌉ + 1 = 6 bins over [min, max].
        let values: Vec<f64> = (0..24).map(|k| ((k * 7) % 24) as f64 * 0.1 + 2.5).collect();
        let h = Histogram::of(&values).unwrap();
        assert_eq!(h.counts.len(), 6);
        assert_eq!(h.counts.iter().sum::<usize>(), 24);
        assert!((h.lo - 2.5).abs() < 1e-12 && (h.hi() - 4.8).abs() < 1e-12);
        let mut counts = vec![0; 6];
        for &v in &values {
            counts[bin_of(&h, v)] += 1;
        }
        assert_eq!(
            counts, h.counts,
            "the largest value belongs to the last bin"
        );
    }

    #[test]
    fn equal_values_fill_one_bin_around_them_and_others_are_left_out() {
        let h = Histogram::of(&[3.0, 3.0, f64::NAN, 3.0, f64::INFINITY]).unwrap();
        assert_eq!(h.counts, [3]);
        assert!(h.lo < 3.0 && h.hi() > 3.0 && h.width > 0.0);
        assert_eq!(Histogram::of(&[0.0]).unwrap().counts, [1]);
        assert!(Histogram::of(&[]).is_none() && Histogram::of(&[f64::NAN]).is_none());
    }
}
