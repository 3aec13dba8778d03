//! Restarted GMRES for the Newton steps of the grid solver: the system
//! J v = b with J given by its product, modified Gram–Schmidt and Givens
//! rotations (Saad, Iterative Methods for Sparse Linear Systems, 6.5).
//!
//! Owns: `gmres`. May use: nothing else in the crate.

/// Solves J x = b from x = 0 until ‖b − Jx‖ ≤ `tol`·‖b‖, restarting every
/// `restart` steps, at most `max_products` products. Returns x, the
/// relative residual reached and the products used.
pub(crate) fn gmres(
    apply: &mut dyn FnMut(&[f64], &mut [f64]),
    b: &[f64],
    tol: f64,
    restart: usize,
    max_products: usize,
) -> (Vec<f64>, f64, usize) {
    let n = b.len();
    let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let b_norm = norm(b);
    let mut x = vec![0.0; n];
    if b_norm == 0.0 {
        return (x, 0.0, 0);
    }
    let mut products = 0;
    let mut r = b.to_vec();
    let mut rel = 1.0;
    let mut w = vec![0.0; n];
    while products < max_products {
        let beta = norm(&r);
        rel = beta / b_norm;
        if rel <= tol {
            break;
        }
        let mut v: Vec<Vec<f64>> = vec![r.iter().map(|x| x / beta).collect()];
        let mut h = vec![vec![0.0; restart]; restart + 1];
        let (mut cs, mut sn) = (vec![0.0; restart], vec![0.0; restart]);
        let mut g = vec![0.0; restart + 1];
        g[0] = beta;
        let mut k = 0;
        while k < restart && products < max_products {
            apply(&v[k], &mut w);
            products += 1;
            for (i, vi) in v.iter().enumerate() {
                let d: f64 = w.iter().zip(vi).map(|(a, b)| a * b).sum();
                h[i][k] = d;
                w.iter_mut().zip(vi).for_each(|(a, b)| *a -= d * b);
            }
            let wn = norm(&w);
            h[k + 1][k] = wn;
            for i in 0..k {
                let t = cs[i] * h[i][k] + sn[i] * h[i + 1][k];
                h[i + 1][k] = -sn[i] * h[i][k] + cs[i] * h[i + 1][k];
                h[i][k] = t;
            }
            let d = h[k][k].hypot(h[k + 1][k]);
            cs[k] = h[k][k] / d;
            sn[k] = h[k + 1][k] / d;
            h[k][k] = d;
            h[k + 1][k] = 0.0;
            g[k + 1] = -sn[k] * g[k];
            g[k] *= cs[k];
            k += 1;
            rel = g[k].abs() / b_norm;
            if rel <= tol || wn == 0.0 {
                break;
            }
            v.push(w.iter().map(|x| x / wn).collect());
        }
        // back substitution
        let mut y = vec![0.0; k];
        for i in (0..k).rev() {
            let s: f64 = (i + 1..k).map(|j| h[i][j] * y[j]).sum();
            y[i] = (g[i] - s) / h[i][i];
        }
        for (i, yi) in y.iter().enumerate() {
            x.iter_mut().zip(&v[i]).for_each(|(a, b)| *a += yi * b);
        }
        // the true residual
        apply(&x, &mut w);
        products += 1;
        r.iter_mut()
            .zip(b.iter().zip(&w))
            .for_each(|(ri, (bi, wi))| *ri = bi - wi);
        rel = norm(&r) / b_norm;
        if rel <= tol {
            break;
        }
    }
    (x, rel, products)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gmres_solves_an_unsymmetric_system() {
        let n = 50;
        let a = |i: usize, j: usize| -> f64 {
            if i == j {
                4.0 + i as f64 * 0.1
            } else if j == i + 1 {
                1.5
            } else if i == j + 1 {
                -0.7
            } else {
                0.0
            }
        };
        let x_true: Vec<f64> = (0..n).map(|i| (i as f64 * 0.37).sin()).collect();
        let b: Vec<f64> = (0..n)
            .map(|i| (0..n).map(|j| a(i, j) * x_true[j]).sum())
            .collect();
        let mut apply = |v: &[f64], out: &mut [f64]| {
            for (i, o) in out.iter_mut().enumerate() {
                *o = (0..n).map(|j| a(i, j) * v[j]).sum();
            }
        };
        let (x, rel, _) = gmres(&mut apply, &b, 1e-12, 10, 500);
        assert!(rel <= 1e-12);
        for i in 0..n {
            assert!((x[i] - x_true[i]).abs() < 1e-10);
        }
    }
}
