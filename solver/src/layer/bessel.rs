//! Spherical Bessel functions j₀(x), j₁(x), …, j_L(x): the even orders are
//! the cosine transforms of the even Legendre polynomials,
//! ∫₋₁¹ P₂ₙ(t) cos(xt) dt = 2(−1)ⁿ j₂ₙ(x), in which the layer's Galerkin
//! matrix is written, and the odd ones give their derivatives. Upward recurrence where it is stable (x above the
//! highest order), Miller's downward recurrence otherwise, normalised by
//! j₀ = sin x/x or j₁ = sin x/x² − cos x/x, whichever is larger.
//!
//! Owns: [`orders`]. May use: nothing else in the crate.

/// Writes j_l(x) for l = 0, …, out.len() − 1 into `out` (x ≥ 0).
pub(crate) fn orders(x: f64, out: &mut [f64]) {
    let n = out.len();
    if n == 0 {
        return;
    }
    let top = n - 1;
    if x < 1e-30 {
        out.fill(0.0);
        out[0] = 1.0;
        return;
    }
    let (sin, cos) = x.sin_cos();
    let j0 = if x < 1e-4 { 1.0 - x * x / 6.0 } else { sin / x };
    let j1 = if x < 1e-2 {
        x / 3.0 * (1.0 - x * x / 10.0 * (1.0 - x * x / 28.0))
    } else {
        sin / (x * x) - cos / x
    };
    if x > top as f64 {
        // upward: stable while the order stays below x
        let (mut prev, mut cur) = (j0, j1);
        out[0] = j0;
        if n > 1 {
            out[1] = j1;
        }
        for l in 1..top {
            let next = (2 * l + 1) as f64 / x * cur - prev;
            prev = cur;
            cur = next;
            out[l + 1] = cur;
        }
        return;
    }
    // Miller: start far enough above both the top order and x that the
    // minimal solution has decayed below round-off
    let reach = top.max(x as usize);
    let start = reach + 20 + (60.0 * reach as f64).sqrt() as usize;
    let (mut above, mut cur) = (0.0f64, 1e-280f64);
    for l in (1..=start).rev() {
        if l <= top {
            out[l] = cur;
        }
        let below = (2 * l + 1) as f64 / x * cur - above;
        above = cur;
        cur = below;
        if cur.abs() > 1e200 {
            cur *= 1e-200;
            above *= 1e-200;
            for v in out[l.min(n)..].iter_mut() {
                *v *= 1e-200;
            }
        }
    }
    // cur = f₀, above = f₁
    out[0] = cur;
    let scale = if j0.abs() >= j1.abs() {
        j0 / cur
    } else {
        j1 / above
    };
    for v in out.iter_mut() {
        *v *= scale;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// j₂(x) and j₄(x) in closed form, where they do not cancel (x ≥ 1).
    fn j2(x: f64) -> f64 {
        (3.0 / (x * x) - 1.0) * x.sin() / x - 3.0 * x.cos() / (x * x)
    }
    fn j4(x: f64) -> f64 {
        let x2 = x * x;
        (1.0 / x)
            * ((105.0 / (x2 * x2) - 45.0 / x2 + 1.0) * x.sin()
                - (105.0 / (x2 * x) - 10.0 / x) * x.cos())
    }

    #[test]
    fn the_closed_forms_of_the_low_orders_agree() {
        for &x in &[1.0, 2.5, std::f64::consts::PI, 7.0, 30.0, 300.0] {
            let mut out = [0.0; 80];
            orders(x, &mut out);
            let j1 = x.sin() / (x * x) - x.cos() / x;
            assert!((out[0] - x.sin() / x).abs() < 1e-15, "j0 at {x}");
            assert!((out[1] - j1).abs() < 1e-15, "j1 at {x}");
            assert!(
                (out[2] - j2(x)).abs() < 2e-14,
                "j2 at {x}: {} against {}",
                out[2],
                j2(x)
            );
            assert!(
                (out[4] - j4(x)).abs() < 2e-13,
                "j4 at {x}: {} against {}",
                out[4],
                j4(x)
            );
        }
    }

    #[test]
    fn small_arguments_follow_the_power_series() {
        // j_l(x) ≈ x^l/(2l+1)!! (1 − x²/(2(2l+3)))
        let x = 1e-3;
        let mut out = [0.0; 12];
        orders(x, &mut out);
        let mut dfact = 1.0;
        for (l, &v) in out.iter().enumerate() {
            dfact *= (2 * l + 1) as f64;
            let series = x.powi(l as i32) / dfact * (1.0 - x * x / (2.0 * (2 * l + 3) as f64));
            assert!(
                (v / series - 1.0).abs() < 1e-12,
                "order {l}: {v} against {series}"
            );
        }
    }

    #[test]
    fn the_sum_rule_holds_and_both_recurrences_meet() {
        for &x in &[0.5, 5.0, 49.0, 51.0, 150.0, 2000.0] {
            let mut a = vec![0.0; 51]; // top order 50: x = 49 runs Miller, 51 upward
            orders(x, &mut a);
            let mut b = vec![0.0; 400]; // top order 399: Miller everywhere here
            orders(x, &mut b);
            for l in 0..51 {
                assert!(
                    (a[l] - b[l]).abs() < 1e-13 / x.min(1.0),
                    "x {x} order {l}: {} against {}",
                    a[l],
                    b[l]
                );
            }
            // Σ (2l + 1) j_l² = 1, the tail beyond order 399 negligible for x ≤ 150
            if x <= 150.0 {
                let sum: f64 = b
                    .iter()
                    .enumerate()
                    .map(|(l, v)| (2 * l + 1) as f64 * v * v)
                    .sum();
                assert!((sum - 1.0).abs() < 1e-13, "x {x}: the sum rule gives {sum}");
            }
        }
    }
}
