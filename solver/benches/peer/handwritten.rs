//! Hand-written (19)–(20) with a hand-derived Jacobian: the baseline of the
//! side-by-side comparison. Benchmark code only, not part of the library.

/// η(s) of (16) and dη/ds.
#[inline]
pub fn eta(s: f64) -> (f64, f64) {
    let w = s * s + s + 1.0;
    let e = 2.0 * w * w.sqrt() / (3f64.powf(1.5) * s * (s + 1.0));
    let de = e * (1.5 * (2.0 * s + 1.0) / w - 1.0 / s - 1.0 / (s + 1.0));
    (e, de)
}

/// Residuals (19), (20) and their Jacobian with respect to (ā, s).
#[inline]
pub fn residuals_and_jacobian(a: f64, s: f64, rho: f64, d: f64) -> ([f64; 2], [[f64; 2]; 2]) {
    let (e, de) = eta(s);
    let s2 = s * s;
    let a2 = a * a;
    let a3 = a2 * a;
    // (19)
    let c1 = (3.0 * s2 + 1.0) / (s2 + 1.0);
    let dc1 = 4.0 * s / ((s2 + 1.0) * (s2 + 1.0));
    let p = 3.0 * s2 * s2 - 2.0 * s2 * s + 6.0 * s2 + 1.0;
    let dp = 12.0 * s2 * s - 6.0 * s2 + 12.0 * s;
    let dd = (s2 * s2 + s2) * e;
    let ddd = (4.0 * s2 * s + 2.0 * s) * e + (s2 * s2 + s2) * de;
    let r1 = a3 - 2.0 * d * c1 * a - 2.0 * p / dd;
    let r1_a = 3.0 * a2 - 2.0 * d * c1;
    let r1_s = -2.0 * d * a * dc1 - 2.0 * (dp * dd - p * ddd) / (dd * dd);
    // (20)
    let g = s2 * s2 + s2;
    let c2 = (s2 + 3.0) / g;
    let dc2 = (2.0 * s * g - (s2 + 3.0) * (4.0 * s2 * s + 2.0 * s)) / (g * g);
    let q = s2 * s2 + 6.0 * s2 - 2.0 * s + 3.0;
    let dq = 4.0 * s2 * s + 12.0 * s - 2.0;
    let ee = (s2 * s2 * s + s2 * s) * e;
    let dee = (5.0 * s2 * s2 + 3.0 * s2) * e + (s2 * s2 * s + s2 * s) * de;
    let r2 = a3 - 2.0 * rho * d * c2 * a - 2.0 * rho * q / ee;
    let r2_a = 3.0 * a2 - 2.0 * rho * d * c2;
    let r2_s = -2.0 * rho * d * a * dc2 - 2.0 * rho * (dq * ee - q * dee) / (ee * ee);
    ([r1, r2], [[r1_a, r1_s], [r2_a, r2_s]])
}
