//! A small seeded generator (SplitMix64) with Box–Muller normals: the ensembles' perturbations
//! and the statistics' synthetic tests are reproducible from their seed alone.

/// SplitMix64 (Steele, Lea and Flood 2014, "Fast splittable pseudorandom number generators"):
/// the state advances by a fixed odd constant and each output is a mix of it. The state is the
/// seed; two generators of the same seed give the same numbers on every platform.
#[derive(Clone, Debug)]
pub struct Rng(pub u64);

impl Rng {
    /// A uniform number in (0, 1), never 0 or 1 (53 random bits, centred in their cell).
    pub fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        ((z >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }

    /// A standard normal number (Box–Muller, the cosine branch).
    pub fn normal(&mut self) -> f64 {
        let (u, v) = (self.uniform(), self.uniform());
        (-2.0 * u.ln()).sqrt() * (2.0 * std::f64::consts::PI * v).cos()
    }

    /// An AR(1) series x_k = φ x_(k−1) + e_k of unit normal innovations e_k, started from its
    /// stationary distribution (|φ| < 1): mean 0, integrated autocorrelation time (1 + φ)/(1 − φ).
    pub fn ar1(&mut self, phi: f64, n: usize) -> Vec<f64> {
        let mut x = self.normal() / (1.0 - phi * phi).sqrt();
        (0..n)
            .map(|_| {
                x = phi * x + self.normal();
                x
            })
            .collect()
    }
}
