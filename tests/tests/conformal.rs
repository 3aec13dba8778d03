//! The generated tables of every contour family in the registry against
//! its derivation from its data file: Π̄, its
//! gradient (the residuals and F̄) and its Hessian (their Jacobian) as the
//! solver evaluates them in f64, against 256-bit evaluations of the symbolic
//! derivatives, at points across the family's domain (ρ from 0.3 to 1,
//! small and large contacts, near-circular and strongly shaped maps). And
//! Π̄ against a quadrature of its definition that uses no polynomial
//! algebra (the harmonic correction by a discrete Fourier transform), and
//! K = 1 against the ellipse energy model at s = 1.

use thinjkr::conformal::poly::{evaluate, Decoded};
use thinjkr::conformal::Tables;
use thinjkr_derive::conformal::{derive, ConformalDerivation};
use thinjkr_derive::family::{self, Family};

/// Every family's data file, beside its generated tables from the
/// registry (the freshness test holds the two to each other).
fn families() -> Vec<(Family, &'static [Tables])> {
    let files = family::read_all(&thinjkr_derive::generate::workspace_root()).unwrap();
    let registry = thinjkr::conformal::families();
    assert_eq!(
        files.len(),
        registry.len(),
        "one registry entry per family file"
    );
    files
        .into_iter()
        .map(|f| {
            let r = registry
                .iter()
                .find(|r| r.name == f.name)
                .unwrap_or_else(|| panic!("{} is not in the registry: run generate", f.name));
            (f, r.members)
        })
        .collect()
}

/// The built-in family `conformal`'s data and tables.
fn builtin() -> (Family, &'static [Tables]) {
    families()
        .into_iter()
        .find(|(f, _)| f.name == "conformal")
        .expect("the built-in family")
}

/// Sample points (c scaled from a shape, δ̄, ρ).
fn points(k: usize) -> Vec<(Vec<f64>, f64, f64)> {
    let shape = |a: f64, decay: f64| -> Vec<f64> {
        (0..k)
            .map(|j| {
                if j == 0 {
                    a
                } else {
                    a * decay.powi(j as i32) * if j % 2 == 0 { 1.0 } else { -0.5 }
                }
            })
            .collect()
    };
    vec![
        (shape(2.9, 0.05), 1.44, 0.8),
        (shape(0.3, 0.1), -5.0, 1.0),
        (shape(8.0, 0.02), 20.0, 0.3),
        (shape(2.55, 0.15), 0.2, 0.5),
    ]
}

/// The worst error of the f64 evaluation, relative to max(|value|, 1e-3 M)
/// with M the sum of the terms' magnitudes (as the generator's check of the
/// ellipse models measures it).
#[test]
fn generated_tables_match_the_derivation_to_round_off() {
    let mut worst_all = 0.0f64;
    for (f, members) in families() {
        for k in 1..=f.largest() {
            let d = derive(&f.member(k)).expect("derives");
            let t = members.iter().find(|t| t.terms == k).expect("generated");
            let table = Decoded::new(&t.potential[..t.potential_rows], k);
            let mut worst = 0.0f64;
            for (c, dbar, rho) in points(k) {
                let mu = 1.0 / rho;
                let got = evaluate(&table, &c, dbar, mu, 2);
                let mut check = |got: f64, unknowns: &[usize]| {
                    let p = d.potential_derivative(unknowns);
                    let (want, mag) = d.evaluate_high_precision(&p, &c, dbar, mu, true).unwrap();
                    let err = (got - want).abs() / want.abs().max(1e-3 * mag).max(1e-300);
                    worst = worst.max(err);
                    assert!(err < 1e-12, "K = {k}, {unknowns:?} at c = {c:?}, dbar = {dbar}, rho = {rho}: {got} vs {want} (error {err:.1e})");
                };
                check(got.value, &[]);
                for i in 0..=k {
                    check(got.grad[i], &[i]);
                    for j in i..=k {
                        check(got.hess[i][j], &[i, j]);
                        assert_eq!(got.hess[i][j], got.hess[j][i]);
                    }
                }
            }
            eprintln!("{}:{k}: worst relative error {worst:.1e}", f.name);
            worst_all = worst_all.max(worst);
        }
    }
    assert!(worst_all > 0.0, "the comparison compared something");
}

/// Π̄ = ½∫ω p̄(δ̄ − φ̄) dA − ½|ω| by quadrature over the disk (Gauss–Legendre
/// in r, trapezoid in θ, both exact for the polynomial degrees involved),
/// with p̄ = P + h and h the harmonic function equal to −P on |ζ| = 1 built
/// from P's discrete Fourier coefficients on the circle.
#[test]
fn potential_equals_a_quadrature_of_its_definition() {
    use std::f64::consts::PI;
    // the quadrature's P and φ̄ are the built-in family's, written out
    let (f, members) = builtin();
    assert_eq!(f.particular, "X^4/24 + mu*Y^4/24 - dbar*(X^2 + Y^2)/4");
    assert_eq!(f.gap, "X^2/2 + mu*Y^2/2");
    for k in [1, 2, 3, 5] {
        let member = members.iter().find(|t| t.terms == k).expect("generated");
        let table = Decoded::new(&member.potential[..member.potential_rows], k);
        for (c, dbar, rho) in points(k) {
            let mu = 1.0 / rho;
            let w = |r: f64, t: f64| -> ((f64, f64), f64) {
                // w(ζ) and |w′(ζ)|² at ζ = r e^{it}
                let (mut x, mut y, mut dx, mut dy) = (0.0, 0.0, 0.0, 0.0);
                for (j, &cj) in c.iter().enumerate() {
                    let n = member.powers[j] as f64;
                    x += cj * r.powf(n) * (n * t).cos();
                    y += cj * r.powf(n) * (n * t).sin();
                    dx += cj * n * r.powf(n - 1.0) * ((n - 1.0) * t).cos();
                    dy += cj * n * r.powf(n - 1.0) * ((n - 1.0) * t).sin();
                }
                ((x, y), dx * dx + dy * dy)
            };
            let particular = |x: f64, y: f64| {
                x.powi(4) / 24.0 + mu * y.powi(4) / 24.0 - dbar * (x * x + y * y) / 4.0
            };
            let gap = |x: f64, y: f64| x * x / 2.0 + mu * y * y / 2.0;
            let nt = 256;
            let thetas: Vec<f64> = (0..nt).map(|j| 2.0 * PI * j as f64 / nt as f64).collect();
            let boundary: Vec<f64> = thetas
                .iter()
                .map(|&t| {
                    let ((x, y), _) = w(1.0, t);
                    particular(x, y)
                })
                .collect();
            let modes = 4 * member.powers[k - 1] as usize + 1;
            let fourier: Vec<(f64, f64)> = (0..=modes)
                .map(|n| {
                    let (mut a, mut b) = (0.0, 0.0);
                    for (j, &t) in thetas.iter().enumerate() {
                        a += boundary[j] * (n as f64 * t).cos();
                        b += boundary[j] * (n as f64 * t).sin();
                    }
                    (a / nt as f64, b / nt as f64)
                })
                .collect();
            let h = |r: f64, t: f64| -> f64 {
                -fourier
                    .iter()
                    .enumerate()
                    .map(|(n, &(a, b))| {
                        let m = if n == 0 { 1.0 } else { 2.0 };
                        m * r.powi(n as i32) * (a * (n as f64 * t).cos() + b * (n as f64 * t).sin())
                    })
                    .sum::<f64>()
            };
            let (nodes, weights) = thinjkr_derive::routes::gauss_legendre(64);
            let mut pi_bar = 0.0;
            for (&u, &wu) in nodes.iter().zip(&weights) {
                let r = 0.5 * (u + 1.0);
                for &t in &thetas {
                    let ((x, y), jac) = w(r, t);
                    let p = particular(x, y) + h(r, t);
                    pi_bar += 0.5
                        * wu
                        * r
                        * (2.0 * PI / nt as f64)
                        * jac
                        * (0.5 * p * (dbar - gap(x, y)) - 0.5);
                }
            }
            let got = evaluate(&table, &c, dbar, mu, 0).value;
            let scale = 1.0 + pi_bar.abs();
            assert!(
                (got - pi_bar).abs() < 1e-9 * scale,
                "K = {k}, c = {c:?}: table {got} vs quadrature {pi_bar}"
            );
        }
    }
}

/// conformal:1 is the circle: its Π̄ is the energy model's Π̄ at s = 1 (a
/// separate derivation, on the ellipse (7) with the polynomial pressure (5)).
#[test]
fn conformal_1_is_the_energy_model_on_the_circle() {
    use thinjkr_derive::sym::{eval_prec, ex, subs_all};
    let e = thinjkr_derive::energy::derive(&thinjkr_derive::ansatz::ENERGY).unwrap();
    let d: ConformalDerivation = derive(&builtin().0.member(1)).unwrap();
    for (a, dbar, rho) in [(2.5, 1.25, 0.8), (0.75, -2.0, 0.5), (4.0, 3.0, 1.0)] {
        let ellipse = eval_prec(
            &subs_all(
                &e.potential,
                &[
                    ("s", ex("1")),
                    ("abar", ex(&a.to_string())),
                    ("dbar", ex(&dbar.to_string())),
                    ("rho", ex(&rho.to_string())),
                ],
            ),
            &[],
            30,
        )
        .unwrap();
        let (circle, _) = d
            .evaluate_high_precision(&d.potential, &[a], dbar, 1.0 / rho, true)
            .unwrap();
        assert!(
            (ellipse - circle).abs() < 1e-12 * (1.0 + circle.abs()),
            "{ellipse} vs {circle}"
        );
    }
}
