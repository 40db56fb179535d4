//! A physical plate of finite span for the 3-D flight (docs/physics.md §2, §9; docs/three-d.md
//! "Free flight"): the 2-D [`Strip`] (its fluid, units and velocity scale U = √(|ρs/ρf − 1| g t))
//! with a span b, as a uniform box ([`PhysicalPlate6::uniform`]). Per unit span in chords its
//! m*, m_f* and pitch I* are the 2-D strip's.
use super::strip::Strip;
use crate::body::six::{PhysicalPlate6, Slab};
use crate::param::{check_range, InputError, Param};

impl Strip {
    /// The strip as a uniform plate of span `span` (m), on the 2-D strip's velocity scale.
    ///
    /// # Errors
    /// The [`InputError`] of [`Strip::validate`] for the first bad input, or
    /// [`InputError::OutOfRange`] naming [`Param::PlateSpan`] for a span (mm) outside (0, 1e4].
    pub fn plate6(&self, span: f64) -> Result<PhysicalPlate6, InputError> {
        self.validate()?;
        check_range(Param::PlateSpan, span * 1e3, 0.0, 1e4, true)?;
        let slab = Slab {
            chord: self.chord,
            thickness: self.thickness,
            span,
            density: self.density,
        };
        let f = &self.fluid;
        Ok(PhysicalPlate6::uniform(
            &slab,
            f.density,
            f.viscosity,
            self.gravity,
            self.speed_scale(),
        ))
    }

    /// The lines that state a 3-D plate's span and its non-dimensional mass, displaced mass and
    /// principal moments (m* = m/(ρf c³), I* = I/(ρf c⁵)), beside [`Strip::derivation`].
    pub fn derivation3(&self, plate: &PhysicalPlate6) -> Vec<String> {
        let Ok(p) = plate.nondimensional() else {
            return Vec::new();
        };
        let i = p.inertia();
        let b = plate.aspect_ratio();
        vec![
            format!(
                "span b = {} mm = {b:.4} c; m* = m/(ρf c³) = (ρs/ρf)(t/c)(b/c) = {:.4}; \
                 m_f* = (t/c)(b/c) = {:.4}",
                plate.span * 1e3,
                p.mass(),
                p.displaced()
            ),
            format!(
                "box moments I* = I/(ρf c⁵): about the chord m*((t/c)² + (b/c)²)/12 = {:.5}, \
                 the normal m*(1 + (b/c)²)/12 = {:.5}, the span m*(1 + (t/c)²)/12 = {:.5} \
                 (per chord of span {:.5}, the 2-D I*)",
                i[(0, 0)],
                i[(1, 1)],
                i[(2, 2)],
                i[(2, 2)] / b
            ),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::six::{box_inertia, thin_plate_inertia};
    use crate::config::Fluid;

    /// ∫ x_k² + x_l² dm over a uniform box, by the midpoint rule on n³ cells.
    fn quadrature(mass: f64, sides: [f64; 3], n: usize) -> [f64; 3] {
        let mid = |side: f64, i: usize| ((i as f64 + 0.5) / n as f64 - 0.5) * side;
        let dm = mass / (n * n * n) as f64;
        let mut moments = [0.0; 3];
        for i in 0..n {
            for j in 0..n {
                for k in 0..n {
                    let r = [mid(sides[0], i), mid(sides[1], j), mid(sides[2], k)];
                    for (a, m) in moments.iter_mut().enumerate() {
                        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
                        *m += dm * (r[b] * r[b] + r[c] * r[c]);
                    }
                }
            }
        }
        moments
    }

    #[test]
    fn box_moments_are_the_uniform_boxs() {
        let (m, c, t, b) = (2.5, 1.0, 0.2, 3.0);
        let got = box_inertia(m, c, t, b);
        // The midpoint rule on n cells gives ∫x² exactly (1 − 1/n²) times too small.
        let n = 20;
        let sum = quadrature(m, [c, t, b], n);
        for (g, q) in got.iter().zip(sum) {
            let exact = q / (1.0 - 1.0 / (n * n) as f64);
            assert!((g / exact - 1.0).abs() < 1e-12, "{got:?} against {sum:?}");
        }
        let cube = box_inertia(6.0, 2.0, 2.0, 2.0);
        assert!(cube.iter().all(|i| (i - 4.0).abs() < 1e-15), "{cube:?}");
        // Thickness → 0: the thin plate's.
        assert_eq!(box_inertia(m, c, 0.0, b), thin_plate_inertia(m, c, b));
    }

    #[test]
    fn per_chord_of_span_the_plate_is_the_two_dimensional_strip() {
        let strip = Strip {
            chord: 0.016,
            thickness: 5e-4,
            density: 2700.0,
            fluid: Fluid::water(),
            gravity: 9.81,
        };
        let two = strip.props();
        for b in [0.008, 0.016, 0.032, 0.1] {
            let six = strip.plate6(b).unwrap();
            let p = six.nondimensional().unwrap();
            let per = |x: f64| x / six.aspect_ratio();
            let close = |a: f64, e: f64| (a / e - 1.0).abs() < 1e-13;
            assert!(close(per(p.mass()), two.mass), "{} {}", p.mass(), two.mass);
            assert!(close(per(p.displaced()), two.displaced));
            assert!(close(per(p.inertia()[(2, 2)]), two.inertia));
            assert!(close(p.gravity(), two.gravity) && close(six.reynolds(), strip.reynolds()));
            // The buoyancy-corrected weight per chord of span is the 2-D strip's +1.
            assert!(close(per(p.weight().y), -two.weight()));
        }
        let err = strip.plate6(0.0).unwrap_err();
        assert_eq!(err.param(), Some(Param::PlateSpan));
    }
}
