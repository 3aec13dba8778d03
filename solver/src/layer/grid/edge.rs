//! The adhesive edge's short-wave cutoff on the pair of coatings
//! (issue 71, item 3, begun): the kernel's own stiffness at mode k̄,
//! βk̄/(1 − Φ(k̄)), and the wave number where it is least, the wavelength
//! at which a uniformly stretched confined film first gives way (Shenoy
//! and Sharma, PRL 86:119, 2001: kh = 2.12 for an incompressible film,
//! about 3h). The straight edge's own most unstable undulation, measured
//! against it, is the next step.
//!
//! Owns: `stiffness_minimum`. May use: `layer` (the pair's Φ), `model`
//! (Brent's minimum).

use crate::layer::Layers;
use crate::model::brent_minimum;

/// The wave number k̄ at which the pair's stiffness βk̄/(1 − Φ(k̄)) is
/// least, by Brent's method on ln k̄ between 0.1/h and 20/h (h the
/// thicker coating).
pub(crate) fn stiffness_minimum(layers: &Layers) -> f64 {
    let h = layers.thickest();
    let stiffness = |t: f64| {
        let k = t.exp() / h;
        k / (1.0 - layers.base_share(k))
    };
    brent_minimum(stiffness, (0.1f64).ln(), (20.0f64).ln(), 1e-10).exp() / h
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stiffness_is_least_where_confined_films_finger() {
        // Shenoy and Sharma (PRL 86:119, 2001) and the issue: kh = 2.12
        // for ν = ½, 1.84 for ν = 0.45, printed to three figures; one
        // coating or two equal ones, at any thinness (the minimum scales
        // with h)
        for (nu, printed) in [(0.5, 2.12), (0.45, 1.84)] {
            for thin in [0.05, 1.0, 30.0] {
                let kh = stiffness_minimum(&Layers::equal(thin, nu).unwrap()) * thin;
                println!(
                    "nu {nu}, h/L {thin}: kh {kh:.5}, wavelength {:.4} h",
                    2.0 * std::f64::consts::PI / kh
                );
                assert!((kh - printed).abs() < 0.005, "nu {nu}, h/L {thin}: kh {kh}");
            }
        }
    }
}
