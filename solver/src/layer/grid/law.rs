//! The cohesive law of the grid solver: the pressure p(g) across a gap g
//! (compressive positive), Rose, Ferrante and Smith's universal binding
//! law p = −(Δγ̄/ρ₀²) g e^(−g/ρ₀) for g ≥ 0 (tension, greatest,
//! Δγ̄/(eρ₀), at g = ρ₀), whose work to separate is Δγ̄; for g < 0 the
//! same polynomial to third order, p = −(Δγ̄/ρ₀²) g (1 − g/ρ₀ + g²/2ρ₀²),
//! a repulsion that rises monotonically (three derivatives continuous at
//! 0). Its range ρ₀ sets the process zone; the JKR limit is ρ₀ → 0.
//!
//! Owns: `Law`. May use: nothing else in the crate.

/// The work of adhesion in the units (17): Δγ/(2ΔγL²/L²).
pub(crate) const WORK: f64 = 0.5;

/// The law of range ρ₀.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Law {
    pub(crate) range: f64,
}

impl Law {
    /// p(g) and dp/dg.
    #[inline]
    pub(crate) fn pressure(&self, g: f64) -> (f64, f64) {
        let r = self.range;
        let s = WORK / (r * r);
        let x = g / r;
        if x >= 0.0 {
            let e = (-x).exp();
            (-s * g * e, -s * (1.0 - x) * e)
        } else {
            let poly = 1.0 - x + 0.5 * x * x;
            (-s * g * poly, -s * (1.0 - 2.0 * x + 1.5 * x * x))
        }
    }

    /// The greatest tension, Δγ̄/(eρ₀).
    pub(crate) fn strength(&self) -> f64 {
        WORK / (std::f64::consts::E * self.range)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_law_does_the_work_of_adhesion_and_is_smooth() {
        let law = Law { range: 0.03 };
        // ∫₀^∞ −p dg = Δγ̄ (Gauss–Laguerre would do; a fine trapezoid on 60 ranges)
        let (n, top) = (600_000, 60.0 * 0.03);
        let h = top / n as f64;
        let work: f64 = (0..=n)
            .map(|i| {
                let w = if i == 0 || i == n { 0.5 } else { 1.0 };
                -w * law.pressure(i as f64 * h).0 * h
            })
            .sum();
        assert!((work - WORK).abs() < 1e-9, "{work}");
        // the slope is the derivative, on both sides of 0
        for g in [-0.05, -0.01, -1e-4, 1e-4, 0.01, 0.05] {
            let e = 1e-7;
            let fd = (law.pressure(g + e).0 - law.pressure(g - e).0) / (2.0 * e);
            let d = law.pressure(g).1;
            assert!((fd - d).abs() < 1e-6 * d.abs(), "{g}: {fd} against {d}");
        }
        // greatest tension at g = ρ₀
        let t = -law.pressure(law.range).0;
        assert!((t - law.strength()).abs() < 1e-12 * t);
    }
}
