//! Gauss–Legendre rules: the nodes and weights of the n-point rule on
//! [−1, 1], by Newton's method on the Legendre polynomial (accurate to
//! round-off; held by the exact integrals of the polynomials of degree
//! below 2n in the tests), and a composite rule on an interval.
//!
//! Owns: [`GaussLegendre`]. May use: nothing else in the crate.

/// The n-point Gauss–Legendre rule on [−1, 1].
#[derive(Clone, Debug)]
pub(crate) struct GaussLegendre {
    pub(crate) nodes: Vec<f64>,
    pub(crate) weights: Vec<f64>,
}

impl GaussLegendre {
    /// The rule of `n` ≥ 1 points.
    pub(crate) fn new(n: usize) -> GaussLegendre {
        let mut nodes = vec![0.0; n];
        let mut weights = vec![0.0; n];
        let nf = n as f64;
        for i in 0..n.div_ceil(2) {
            // Tricomi's first guess, then Newton on P_n
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (nf + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (p, d) = legendre_and_derivative(n, x);
                dp = d;
                let dx = p / d;
                x -= dx;
                if dx.abs() <= 1e-16 * x.abs().max(1e-300) {
                    break;
                }
            }
            let (_, d) = legendre_and_derivative(n, x);
            dp = if d.is_finite() { d } else { dp };
            let w = 2.0 / ((1.0 - x * x) * dp * dp);
            nodes[i] = -x;
            nodes[n - 1 - i] = x;
            weights[i] = w;
            weights[n - 1 - i] = w;
        }
        GaussLegendre { nodes, weights }
    }

    /// The composite rule: `panels` equal panels on [lo, hi], each with
    /// this rule, as (node, weight) pairs in increasing order.
    pub(crate) fn composite(&self, lo: f64, hi: f64, panels: usize) -> Vec<(f64, f64)> {
        let width = (hi - lo) / panels as f64;
        let mut out = Vec::with_capacity(panels * self.nodes.len());
        for p in 0..panels {
            let mid = lo + (p as f64 + 0.5) * width;
            for (x, w) in self.nodes.iter().zip(&self.weights) {
                out.push((mid + 0.5 * width * x, 0.5 * width * w));
            }
        }
        out
    }
}

/// P_n(x) and P_n′(x) by the three-term recurrence.
fn legendre_and_derivative(n: usize, x: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0, x);
    if n == 0 {
        return (1.0, 0.0);
    }
    for k in 2..=n {
        let kf = k as f64;
        let p2 = ((2.0 * kf - 1.0) * x * p1 - (kf - 1.0) * p0) / kf;
        p0 = p1;
        p1 = p2;
    }
    let nf = n as f64;
    (p1, nf * (x * p1 - p0) / (x * x - 1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rule_integrates_every_polynomial_below_degree_two_n_exactly() {
        for n in [1usize, 2, 5, 16, 17] {
            let rule = GaussLegendre::new(n);
            for degree in 0..2 * n {
                let sum: f64 = rule
                    .nodes
                    .iter()
                    .zip(&rule.weights)
                    .map(|(x, w)| w * x.powi(degree as i32))
                    .sum();
                let exact = if degree % 2 == 1 {
                    0.0
                } else {
                    2.0 / (degree as f64 + 1.0)
                };
                // n terms, each below 2 in size: n rounding errors of 2 ulps at most
                assert!(
                    (sum - exact).abs() < n as f64 * 4.5e-16,
                    "n {n} degree {degree}: {sum} against {exact}"
                );
            }
        }
    }

    #[test]
    fn the_composite_rule_integrates_an_exponential_to_round_off() {
        let rule = GaussLegendre::new(16);
        let sum: f64 = rule
            .composite(0.0, 3.0, 7)
            .iter()
            .map(|(x, w)| w * x.exp())
            .sum();
        assert!(
            (sum - (3f64.exp() - 1.0)).abs() < 1e-14 * 3f64.exp(),
            "{sum}"
        );
    }
}
