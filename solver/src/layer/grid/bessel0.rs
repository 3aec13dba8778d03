//! The Bessel function J₀(x) of the first kind and order zero, to about
//! 1e-15: Miller's downward recurrence below x = 25 (normalised by
//! J₀ + 2ΣJ₂ₖ = 1), Hankel's asymptotic expansion above (its terms fall
//! below 1e-17 there before they grow). The layer's kernel in the plane is
//! a Hankel transform, ∫₀^∞ Φ(k) J₀(kr) dk.
//!
//! `orders` gives J_n(x) of every order up to a given one by the same
//! recurrence, for the straight edge's Galerkin method (`edge`).
//!
//! Owns: [`j0`], [`orders`]. May use: nothing else in the crate.

/// Where the asymptotic expansion takes over.
const ASYMPTOTIC_FROM: f64 = 25.0;

/// J₀(x).
pub(crate) fn j0(x: f64) -> f64 {
    let x = x.abs();
    if x < ASYMPTOTIC_FROM {
        miller(x)
    } else {
        hankel(x)
    }
}

/// Downward recurrence J_{n−1} = (2n/x)J_n − J_{n+1} from an order well
/// above x, normalised by 1 = J₀ + 2(J₂ + J₄ + …).
fn miller(x: f64) -> f64 {
    if x < 1e-8 {
        return 1.0 - 0.25 * x * x;
    }
    let mut out = [0.0];
    downward(x, 2 * ((x as usize + 40) / 2), &mut out);
    out[0]
}

/// J_n(x) for n = 0, 1, …, out.len() − 1 (x ≥ 0): where x is above 25 and
/// above the highest order by 20, upward from Hankel's J₀ and J₁;
/// otherwise by Miller's recurrence from an order above both x and the
/// highest asked (by 15x^⅓ + 40, where J_n has fallen below 1e-16 of its
/// size).
pub(crate) fn orders(x: f64, out: &mut [f64]) {
    if out.is_empty() {
        return;
    }
    if x < 1e-300 {
        out.fill(0.0);
        out[0] = 1.0;
        return;
    }
    if x >= ASYMPTOTIC_FROM && x > out.len() as f64 + 20.0 {
        // upward from J₀ and J₁, stable while the order stays below x
        out[0] = hankel_order(x, 0);
        if out.len() > 1 {
            out[1] = hankel_order(x, 1);
        }
        for n in 1..out.len().saturating_sub(1) {
            out[n + 1] = 2.0 * n as f64 / x * out[n] - out[n - 1];
        }
        return;
    }
    let top = (x as usize).max(out.len()) + 40 + (15.0 * x.cbrt()) as usize;
    downward(x, 2 * (top / 2), out);
}

/// Miller's recurrence from order `start` (even), normalised by
/// 1 = J₀ + 2(J₂ + J₄ + …), the orders below out.len() written to `out`.
fn downward(x: f64, start: usize, out: &mut [f64]) {
    let (mut next, mut cur) = (0.0f64, 1e-300f64);
    let mut norm = 0.0;
    for n in (1..=start).rev() {
        let prev = 2.0 * n as f64 / x * cur - next;
        next = cur;
        cur = prev;
        // cur is now J_{n−1}
        if (n - 1) % 2 == 0 && n > 1 {
            norm += 2.0 * cur;
        }
        if n - 1 < out.len() {
            out[n - 1] = cur;
        }
        if cur.abs() > 1e250 {
            next *= 1e-250;
            cur *= 1e-250;
            norm *= 1e-250;
            out.iter_mut().skip(n - 1).for_each(|v| *v *= 1e-250);
        }
    }
    let scale = 1.0 / (norm + out[0]);
    out.iter_mut().for_each(|v| *v *= scale);
}

/// J₀(x) = √(2/πx)(P cos χ − Q sin χ), χ = x − π/4, with P and Q summed
/// until their terms stop falling.
fn hankel(x: f64) -> f64 {
    hankel_order(x, 0)
}

/// J_ν(x) = √(2/πx)(P cos χ − Q sin χ), χ = x − νπ/2 − π/4, for ν = 0
/// or 1, with P and Q summed until their terms stop falling (Abramowitz
/// and Stegun 9.2.5, 9.2.9, 9.2.10).
fn hankel_order(x: f64, nu: u32) -> f64 {
    let mu = 4.0 * f64::from(nu * nu);
    let (mut p, mut q) = (0.0, 0.0);
    // a_k = Π_{j ≤ k} (μ − (2j − 1)²) / (k! 8^k); P = Σ (−1)^k a_{2k}/x^{2k},
    // Q = Σ (−1)^k a_{2k+1}/x^{2k+1}
    let mut a = 1.0; // a_k / x^k
    let mut last = f64::INFINITY;
    for k in 0..60usize {
        if k > 0 {
            let j = (2 * k - 1) as f64;
            a *= (mu - j * j) / (k as f64 * 8.0 * x);
        }
        if a.abs() > last {
            break;
        }
        last = a.abs();
        let sign = if (k / 2) % 2 == 0 { 1.0 } else { -1.0 };
        if k % 2 == 0 {
            p += sign * a;
        } else {
            q += sign * a;
        }
        if a.abs() < 1e-18 {
            break;
        }
    }
    let chi = x - (f64::from(nu) * 0.5 + 0.25) * std::f64::consts::PI;
    (2.0 / (std::f64::consts::PI * x)).sqrt() * (p * chi.cos() - q * chi.sin())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn j0_matches_tabulated_values_and_its_two_routes_agree() {
        // Abramowitz & Stegun, Table 9.1, and the first zeros (Table 9.5)
        for (x, v) in [
            (0.0, 1.0),
            (1.0, 0.765_197_686_557_966_6),
            (5.0, -0.177_596_771_314_338_3),
            (10.0, -0.245_935_764_451_348_3),
            (2.404_825_557_695_773, 0.0),
            (5.520_078_110_286_311, 0.0),
            (15.0, -0.014_224_472_826_780_773),
            (30.634_606_468_431_975, 0.0),
        ] {
            assert!((j0(x) - v).abs() < 2e-15, "J0({x}) = {} not {v}", j0(x));
        }
        for x in [15.0, 20.0, 25.0, 30.0, 40.0] {
            let (m, h) = (miller(x), hankel(x));
            // Hankel's expansion, truncated where its terms stop falling,
            // is off by 1.7e-15 at x = 15 and falls fast beyond
            assert!((m - h).abs() < 2e-15, "x = {x}: {m} against {h}");
        }
    }

    #[test]
    fn every_order_matches_tabulated_values_and_the_recurrences() {
        // Abramowitz & Stegun, Tables 9.1 and 9.4: J1 and J2 at 1, J1 and
        // J10 at 10
        let mut out = [0.0; 61];
        orders(1.0, &mut out);
        assert!((out[1] - 0.440_050_585_744_933_5).abs() < 2e-15);
        assert!((out[2] - 0.114_903_484_931_900_5).abs() < 2e-15);
        orders(10.0, &mut out);
        assert!((out[1] - 0.043_472_746_168_861_44).abs() < 2e-15);
        assert!((out[10] - 0.207_486_106_633_358_9).abs() < 2e-15);
        // J0 agrees with j0's two routes, and the orders with the
        // three-term recurrence, far into the oscillating range
        // the two routes where both apply: Miller's from above x, and the
        // upward recurrence from Hankel's J₀, J₁
        for x in [30.0, 80.0, 900.0] {
            let mut up = vec![0.0; 10];
            orders(x, &mut up);
            let mut down = vec![0.0; 10];
            let top = x as usize + 40 + (15.0 * x.cbrt()) as usize;
            downward(x, 2 * (top / 2), &mut down);
            for n in 0..10 {
                assert!(
                    (up[n] - down[n]).abs() < 1e-14,
                    "x {x}, n {n}: {} {}",
                    up[n],
                    down[n]
                );
            }
        }
        for x in [0.3, 7.0, 45.0, 300.0, 2500.0] {
            let mut j = vec![0.0; 80];
            orders(x, &mut j);
            assert!((j[0] - j0(x)).abs() < 1e-14, "{x}");
            for n in 1..79 {
                let r = 2.0 * n as f64 / x * j[n] - j[n - 1] - j[n + 1];
                assert!(r.abs() < 1e-13, "x {x}, n {n}: {r}");
            }
        }
    }
}
