//! Π̄ of a `conformal:K` member, its gradient and its Hessian in
//! (c₁ … c_K, δ̄), side by side, from the generated monomial table. A
//! monomial's derivatives follow from its integer exponents exactly, so
//! the only rounding is that of the table's coefficients and of the sums.
//!
//! Owns: the table evaluator. May use: nothing else in the crate.

/// Bits per packed exponent (as generated).
pub(crate) const BITS: u32 = 4;
/// Bit offset of δ̄'s exponent.
pub(crate) const DBAR_SHIFT: u32 = 32;
/// Bit offset of μ's exponent.
pub(crate) const MU_SHIFT: u32 = 36;
/// The most unknowns: K ≤ 8 map coefficients and δ̄.
pub(crate) const MAX_UNKNOWNS: usize = 9;

/// Value, gradient and Hessian of a table polynomial in (c, δ̄).
#[derive(Clone, Debug)]
pub struct Second {
    /// The number of unknowns n = K + 1.
    pub n: usize,
    /// The value.
    pub value: f64,
    /// ∂/∂(c, δ̄).
    pub grad: [f64; MAX_UNKNOWNS],
    /// ∂²/∂(c, δ̄)², row-major n × n in the top-left of the array.
    pub hess: [[f64; MAX_UNKNOWNS]; MAX_UNKNOWNS],
}

fn field(packed: u64, shift: u32) -> usize {
    ((packed >> shift) & ((1 << BITS) - 1)) as usize
}

/// A table decoded once: rows with the same c-exponents grouped, each
/// group's nonzero exponents listed.
#[derive(Clone, Debug)]
pub struct Decoded {
    k: usize,
    groups: Vec<Group>,
    /// (δ̄ exponent, μ exponent, κ) of every row, group by group.
    rows: Vec<(u8, u8, f64)>,
}

#[derive(Clone, Debug)]
struct Group {
    m: u8,
    idx: [u8; MAX_UNKNOWNS],
    exp: [u8; MAX_UNKNOWNS],
    first: u32,
    len: u32,
}

impl Decoded {
    /// Decode the rows of a member with `k` map coefficients.
    pub fn new(table: &[(u64, f64)], k: usize) -> Decoded {
        assert!(
            k < MAX_UNKNOWNS,
            "at most {} map coefficients",
            MAX_UNKNOWNS - 1
        );
        let c_mask = (1u64 << DBAR_SHIFT) - 1;
        let mut groups: Vec<Group> = Vec::new();
        let mut rows = Vec::with_capacity(table.len());
        let mut last = None;
        for &(p, kappa) in table {
            let key = p & c_mask;
            if last != Some(key) {
                let mut g = Group {
                    m: 0,
                    idx: [0; MAX_UNKNOWNS],
                    exp: [0; MAX_UNKNOWNS],
                    first: rows.len() as u32,
                    len: 0,
                };
                for i in 0..k {
                    let e = field(key, BITS * i as u32);
                    if e > 0 {
                        g.idx[g.m as usize] = i as u8;
                        g.exp[g.m as usize] = e as u8;
                        g.m += 1;
                    }
                }
                groups.push(g);
                last = Some(key);
            }
            rows.push((field(p, DBAR_SHIFT) as u8, field(p, MU_SHIFT) as u8, kappa));
            groups.last_mut().expect("pushed").len += 1;
        }
        Decoded { k, groups, rows }
    }
}

impl Decoded {
    /// The sum of several tables' polynomials, decoded (rows grouped by
    /// their c-exponents).
    pub(crate) fn sum<'a>(tables: impl Iterator<Item = &'a [(u64, f64)]>, k: usize) -> Decoded {
        let mut rows: Vec<(u64, f64)> = tables.flatten().copied().collect();
        let c_mask = (1u64 << DBAR_SHIFT) - 1;
        rows.sort_by_key(|&(p, _)| p & c_mask);
        Decoded::new(&rows, k)
    }

    /// The rows that are not zero where every coefficient but c₁ vanishes
    /// (the circle): those without c₂ … c_K. They give the value and the
    /// derivatives in c₁ and δ̄ there, not those in c₂ … c_K.
    pub(crate) fn on_circle(&self) -> Decoded {
        let mut out = Decoded {
            k: self.k,
            groups: Vec::new(),
            rows: Vec::new(),
        };
        for g in &self.groups {
            if (0..g.m as usize).all(|x| g.idx[x] == 0) {
                let mut h = g.clone();
                h.first = out.rows.len() as u32;
                out.rows
                    .extend_from_slice(&self.rows[g.first as usize..(g.first + g.len) as usize]);
                out.groups.push(h);
            }
        }
        out
    }
}

/// Evaluate Σ κ δ̄^p μ^q Π c_i^(e_i) with its derivatives in (c, δ̄) up to
/// `order` (0: value; 1: and the gradient; 2: and the Hessian).
/// `c.len()` must be the table's K.
pub fn evaluate(t: &Decoded, c: &[f64], dbar: f64, mu: f64, order: u8) -> Second {
    evaluate_in(t, c, dbar, mu, order, false)
}

/// The derivative in μ of [`evaluate`]'s value, gradient and Hessian (the
/// rows' μ exponents differentiated exactly).
pub(crate) fn evaluate_mu_derivative(
    t: &Decoded,
    c: &[f64],
    dbar: f64,
    mu: f64,
    order: u8,
) -> Second {
    evaluate_in(t, c, dbar, mu, order, true)
}

fn evaluate_in(t: &Decoded, c: &[f64], dbar: f64, mu: f64, order: u8, d_mu: bool) -> Second {
    let k = t.k;
    assert_eq!(c.len(), k, "one value per map coefficient");
    let n = k + 1;
    let mut pw = [[0.0f64; 16]; MAX_UNKNOWNS];
    for (i, &ci) in c.iter().enumerate() {
        pw[i][0] = 1.0;
        for e in 1..16 {
            pw[i][e] = pw[i][e - 1] * ci;
        }
    }
    let mut mu_pw = [1.0f64; 16];
    let mut d_pw = [1.0f64; 16];
    for e in 1..16 {
        mu_pw[e] = mu_pw[e - 1] * mu;
        d_pw[e] = d_pw[e - 1] * dbar;
    }
    let mut out = Second {
        n,
        value: 0.0,
        grad: [0.0; MAX_UNKNOWNS],
        hess: [[0.0; MAX_UNKNOWNS]; MAX_UNKNOWNS],
    };
    for g in &t.groups {
        let m = g.m as usize;
        // a factor c_i = 0 with exponent e vanishes with its first e − 1
        // derivatives: skip monomials that contribute nothing at this order
        let zeros = (0..m).filter(|&x| c[g.idx[x] as usize] == 0.0).count();
        if zeros > order as usize {
            continue;
        }
        let (mut a0, mut a1, mut a2) = (0.0, 0.0, 0.0);
        for &(dp, q, kappa) in &t.rows[g.first as usize..(g.first + g.len) as usize] {
            let q = q as usize;
            let coef = match (d_mu, q) {
                (false, _) => kappa * mu_pw[q],
                (true, 0) => continue,
                (true, _) => kappa * q as f64 * mu_pw[q - 1],
            };
            let dp = dp as usize;
            a0 += coef * d_pw[dp];
            if dp >= 1 {
                a1 += coef * dp as f64 * d_pw[dp - 1];
            }
            if dp >= 2 {
                a2 += coef * (dp * (dp - 1)) as f64 * d_pw[dp - 2];
            }
        }
        let mut f0 = [0.0f64; MAX_UNKNOWNS];
        let mut f1 = [0.0f64; MAX_UNKNOWNS];
        let mut f2 = [0.0f64; MAX_UNKNOWNS];
        for x in 0..m {
            let (i, e) = (g.idx[x] as usize, g.exp[x] as usize);
            f0[x] = pw[i][e];
            f1[x] = e as f64 * pw[i][e - 1];
            f2[x] = if e >= 2 {
                (e * (e - 1)) as f64 * pw[i][e - 2]
            } else {
                0.0
            };
        }
        let mut pre = [1.0f64; MAX_UNKNOWNS + 1];
        let mut suf = [1.0f64; MAX_UNKNOWNS + 1];
        for x in 0..m {
            pre[x + 1] = pre[x] * f0[x];
        }
        for x in (0..m).rev() {
            suf[x] = suf[x + 1] * f0[x];
        }
        let mono = pre[m];
        out.value += a0 * mono;
        if order == 0 {
            continue;
        }
        out.grad[k] += a1 * mono;
        if order >= 2 {
            out.hess[k][k] += a2 * mono;
        }
        for x in 0..m {
            let i = g.idx[x] as usize;
            let others = pre[x] * suf[x + 1];
            let d_i = f1[x] * others;
            out.grad[i] += a0 * d_i;
            if order < 2 {
                continue;
            }
            out.hess[i][k] += a1 * d_i;
            out.hess[i][i] += a0 * f2[x] * others;
            // the product of the factors strictly between x and y
            let mut between = 1.0;
            let a_fx_pre = a0 * f1[x] * pre[x];
            for y in x + 1..m {
                out.hess[i][g.idx[y] as usize] += a_fx_pre * f1[y] * between * suf[y + 1];
                between *= f0[y];
            }
        }
    }
    if order >= 2 {
        // the loops above wrote the upper triangle (the indices increase)
        for i in 0..n {
            for j in 0..i {
                out.hess[i][j] = out.hess[j][i];
            }
        }
    }
    out
}

/// Evaluate Σ κ δ̄^p μ^q Π c_i^(e_i) (value only).
#[cfg(test)]
pub(crate) fn value(rows: &[(u64, f64)], c: &[f64], dbar: f64, mu: f64) -> f64 {
    let mut total = 0.0;
    for &(p, kappa) in rows {
        let mut t =
            kappa * dbar.powi(field(p, DBAR_SHIFT) as i32) * mu.powi(field(p, MU_SHIFT) as i32);
        for (i, &ci) in c.iter().enumerate() {
            let e = field(p, BITS * i as u32);
            if e > 0 {
                t *= ci.powi(e as i32);
            }
        }
        total += t;
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 2 c₁³ c₂ δ̄ μ + c₂² δ̄² − c₁ and its derivatives by hand.
    #[test]
    fn derivatives_of_a_small_table() {
        let pack = |e1: u64, e2: u64, d: u64, q: u64| e1 | e2 << 4 | d << 32 | q << 36;
        let rows = [
            (pack(1, 0, 0, 0), -1.0),
            (pack(3, 1, 1, 1), 2.0),
            (pack(0, 2, 2, 0), 1.0),
        ];
        let (c1, c2, d, mu) = (1.3, -0.7, 0.4, 1.25);
        let s = evaluate(&Decoded::new(&rows, 2), &[c1, c2], d, mu, 2);
        let v = 2.0 * c1.powi(3) * c2 * d * mu + c2 * c2 * d * d - c1;
        assert!((s.value - v).abs() < 1e-14);
        assert!((value(&rows, &[c1, c2], d, mu) - v).abs() < 1e-14);
        // on the circle (c₂ = 0) the rows without c₂ give the value and the
        // derivatives in c₁ and δ̄
        let full = evaluate(&Decoded::new(&rows, 2), &[c1, 0.0], d, mu, 2);
        let circle = evaluate(&Decoded::new(&rows, 2).on_circle(), &[c1, 0.0], d, mu, 2);
        for (a, b) in [
            (full.value, circle.value),
            (full.grad[0], circle.grad[0]),
            (full.grad[2], circle.grad[2]),
            (full.hess[0][0], circle.hess[0][0]),
            (full.hess[0][2], circle.hess[0][2]),
            (full.hess[2][2], circle.hess[2][2]),
        ] {
            assert_eq!(a, b);
        }
        // the same polynomial as a sum of two tables (rows interleaved)
        let summed = Decoded::sum([&rows[..1], &rows[1..]].into_iter(), 2);
        let t = evaluate(&summed, &[c1, c2], d, mu, 2);
        assert!((t.value - v).abs() < 1e-14 && (t.hess[0][1] - s.hess[0][1]).abs() < 1e-14);
        // ∂/∂μ: only the middle row depends on μ, linearly
        let dm = evaluate_mu_derivative(&Decoded::new(&rows, 2), &[c1, c2], d, mu, 2);
        assert!((dm.value - 2.0 * c1.powi(3) * c2 * d).abs() < 1e-14);
        assert!((dm.grad[0] - 6.0 * c1 * c1 * c2 * d).abs() < 1e-13);
        assert!((dm.grad[1] - 2.0 * c1.powi(3) * d).abs() < 1e-13);
        assert!((dm.grad[2] - 2.0 * c1.powi(3) * c2).abs() < 1e-13);
        assert!((dm.hess[0][1] - 6.0 * c1 * c1 * d).abs() < 1e-13);
        let g = [
            6.0 * c1 * c1 * c2 * d * mu - 1.0,
            2.0 * c1.powi(3) * d * mu + 2.0 * c2 * d * d,
            2.0 * c1.powi(3) * c2 * mu + 2.0 * c2 * c2 * d,
        ];
        let h = [
            [
                12.0 * c1 * c2 * d * mu,
                6.0 * c1 * c1 * d * mu,
                6.0 * c1 * c1 * c2 * mu,
            ],
            [
                6.0 * c1 * c1 * d * mu,
                2.0 * d * d,
                2.0 * c1.powi(3) * mu + 4.0 * c2 * d,
            ],
            [
                6.0 * c1 * c1 * c2 * mu,
                2.0 * c1.powi(3) * mu + 4.0 * c2 * d,
                2.0 * c2 * c2,
            ],
        ];
        for i in 0..3 {
            assert!((s.grad[i] - g[i]).abs() < 1e-13, "grad {i}");
            for j in 0..3 {
                assert!(
                    (s.hess[i][j] - h[i][j]).abs() < 1e-13,
                    "hess {i} {j}: {} vs {}",
                    s.hess[i][j],
                    h[i][j]
                );
            }
        }
    }
}
