//! Step 3 of the derivation: the boundary condition (3)₂ on the elliptical
//! contour Γ₀ (7). The outward normal derivative of the ansatz is computed on
//! x = a cos t, y = b sin t, written in u = sin² t: Eq. (9). The collocation
//! conditions of the ansatz (for (5): Eq. (10)) fix its shape parameters,
//! giving Eq. (11). The extrema of (11) along the contour are then found from
//! the roots of d(∂p/∂ν)²/du, not assumed, and the maximum is set equal to
//! √(2mΔγ): Eq. (13).
//!
//! Owns: normal derivative, collocation, extrema along Γ₀.
//! May use: `ansatz`, `sym`.

use crate::ansatz::Ansatz;
use crate::sym::{
    degree_in, diff, eval_prec, ex, factor_list, freeze_radicals, is_zero, normalize_radicals,
    numerator, rat, simplify, solve_linear, sqrt_pos, subs, subs_all, thaw,
};
use symbolica::atom::{Atom, AtomCore};

/// ∂p/∂ν on Γ₀ as `weight / sqrt(metric)`, both rational in `u` = sin² t.
#[derive(Clone, Debug)]
pub struct NormalDerivative {
    /// −∇p·∇E on Γ₀, with E = 1 − x²/a² − y²/b².
    pub weight: Atom,
    /// |∇E|² on Γ₀.
    pub metric: Atom,
}

impl NormalDerivative {
    /// ∂p/∂ν = weight/|∇E| as one expression in `u`.
    pub fn value(&self) -> Atom {
        simplify(&(&self.weight / &sqrt_pos(&self.metric)))
    }

    /// ∂p/∂ν at the contour point `u`.
    pub fn at(&self, u: &Atom) -> Atom {
        let w = simplify(&subs(&self.weight, "u", u));
        let m = simplify(&subs(&self.metric, "u", u));
        normalize_radicals(&simplify(&(w / sqrt_pos(&m))))
    }

    /// Apply substitutions to both parts.
    pub fn subs_all(&self, rules: &[(&str, Atom)]) -> NormalDerivative {
        NormalDerivative {
            weight: simplify(&subs_all(&self.weight, rules)),
            metric: simplify(&subs_all(&self.metric, rules)),
        }
    }
}

fn on_contour(e: &Atom) -> Atom {
    subs_all(e, &[("x", ex("a*(1-u)^(1/2)")), ("y", ex("b*u^(1/2)"))]).expand()
}

/// Eq. (9): the outward normal derivative of `p` on the ellipse (7), for any
/// pressure that vanishes there. Fails when `p` does not vanish on Γ₀ (the
/// first boundary condition (3) would not hold).
pub fn normal_derivative(p: &Atom) -> Result<NormalDerivative, String> {
    if !is_zero(&on_contour(p)) {
        return Err("the ansatz does not vanish on the ellipse (7)".into());
    }
    let e = ex("1 - x^2/a^2 - y^2/b^2");
    let (ex_, ey) = (diff(&e, "x"), diff(&e, "y"));
    let dot = diff(p, "x") * &ex_ + diff(p, "y") * &ey;
    Ok(NormalDerivative {
        weight: simplify(&on_contour(&(-dot))),
        metric: simplify(&on_contour(&(&ex_ * &ex_ + &ey * &ey))),
    })
}

/// Eq. (10) for the given ansatz: the values of the shape parameters, in the
/// symbols `xi`, `a`, `s`, from the definition of ξ and the equal-value
/// collocation conditions.
pub fn collocate(ansatz: &Ansatz, nd: &NormalDerivative) -> Result<Vec<(String, Atom)>, String> {
    let (xi_param, xi_value) = ansatz.xi_definition;
    let mut rules: Vec<(String, Atom)> =
        vec![(xi_param.to_string(), subs(&ex(xi_value), "b", &ex("s*a")))];
    let remaining: Vec<&str> = ansatz
        .shape_params
        .iter()
        .copied()
        .filter(|p| *p != xi_param)
        .collect();
    if remaining.len() != ansatz.equal_normal_derivative.len() {
        return Err(format!(
            "{} shape parameters left but {} collocation conditions",
            remaining.len(),
            ansatz.equal_normal_derivative.len()
        ));
    }
    for (param, (u1, u2)) in remaining.iter().zip(ansatz.equal_normal_derivative) {
        let sub: Vec<(&str, Atom)> = rules.iter().map(|(n, v)| (n.as_str(), v.clone())).collect();
        let g = nd.subs_all(&[("b", ex("s*a"))]).subs_all(&sub);
        let eq = g.at(&ex(u1)) - g.at(&ex(u2));
        let v = solve_linear(&eq, param)
            .ok_or_else(|| format!("collocation does not fix {param} linearly"))?;
        rules.push((param.to_string(), normalize_radicals(&v)));
    }
    Ok(rules)
}

/// The extrema of ∂p/∂ν along Γ₀ (after collocation).
#[derive(Clone, Debug)]
pub struct Extrema {
    /// Interior roots u* of d(∂p/∂ν)²/du that are not zeros of ∂p/∂ν.
    pub critical_points: Vec<Atom>,
    /// Where the maximum is (u = sin² t).
    pub u_max: Atom,
    /// Where the minimum is.
    pub u_min: Atom,
    /// ∂p/∂ν at the apex t = 0.
    pub apex: Atom,
    /// The maximum value.
    pub max: Atom,
    /// The minimum value.
    pub min: Atom,
}

/// Sample points (s, ξ, a, p0) at which candidate extrema are compared.
const SAMPLES: &[(i64, i64)] = &[(3, 10), (11, 20), (4, 5), (19, 20)];

fn sample_point(s: (i64, i64)) -> Vec<(&'static str, Atom)> {
    vec![
        ("s", rat(s.0, s.1)),
        ("xi", rat(17, 10)),
        ("a", rat(13, 10)),
        ("p0", Atom::num(1)),
    ]
}

/// Find the extrema of ∂p/∂ν along Γ₀: candidates are the endpoints u = 0, 1
/// and the interior critical points from linear factors of d(∂p/∂ν)²/du;
/// the maximum and minimum are the candidates that are largest and smallest
/// at every sample s in (0, 1).
pub fn extrema(nd: &NormalDerivative) -> Result<Extrema, String> {
    let h = simplify(&(&nd.weight * &nd.weight / &nd.metric));
    let mut dh = poly_coefficients(&numerator(&diff(&h, "u")), "u")?;
    // Zeros of ∂p/∂ν are roots of d(∂p/∂ν)²/du too: deflate them away.
    for r in linear_roots(&nd.weight)? {
        if vanishes(&eval_poly(&dh, &r)) {
            dh = deflate(&dh, &r);
        }
    }
    let mut critical = Vec::new();
    let remaining = eval_poly(&dh, &ex("u"));
    let roots = if dh.len() == 2 {
        vec![simplify(&(-&dh[0] / &dh[1]))]
    } else {
        linear_roots(&remaining)?
    };
    for root in roots {
        if !is_zero(&simplify(&subs(&nd.weight, "u", &root))) {
            critical.push(normalize_radicals(&root));
        }
    }
    let mut candidates = vec![Atom::num(0), Atom::num(1)];
    for c in &critical {
        let inside = SAMPLES.iter().all(|&s| {
            eval_prec(c, &sample_point(s), 30)
                .map(|v| v > 0.0 && v < 1.0)
                .unwrap_or(false)
        });
        if inside {
            candidates.push(c.clone());
        }
    }
    let values: Vec<Vec<f64>> = candidates
        .iter()
        .map(|u| {
            let g = nd.at(u);
            SAMPLES
                .iter()
                .map(|&s| eval_prec(&g, &sample_point(s), 30))
                .collect::<Result<Vec<_>, _>>()
        })
        .collect::<Result<_, _>>()?;
    let pick = |better: fn(f64, f64) -> bool| -> Result<usize, String> {
        (0..candidates.len())
            .find(|&i| {
                (0..candidates.len()).all(|j| {
                    j == i || (0..SAMPLES.len()).all(|k| !better(values[j][k], values[i][k]))
                })
            })
            .ok_or_else(|| "no candidate is extremal at every sample".to_string())
    };
    let imax = pick(|x, y| x > y * (1.0 + 1e-12))?;
    let imin = pick(|x, y| x < y * (1.0 - 1e-12))?;
    Ok(Extrema {
        critical_points: critical,
        u_max: candidates[imax].clone(),
        u_min: candidates[imin].clone(),
        apex: nd.at(&Atom::num(0)),
        max: nd.at(&candidates[imax]),
        min: nd.at(&candidates[imin]),
    })
}

/// Coefficients c₀…cₙ of a polynomial in `x`.
fn poly_coefficients(e: &Atom, x: &str) -> Result<Vec<Atom>, String> {
    let n = degree_in(e, x, 12).ok_or("degree too high")?;
    Ok((0..=n as u32)
        .map(|k| crate::sym::poly_coeff(e, x, k, "zz", 0))
        .collect())
}

fn eval_poly(c: &[Atom], u: &Atom) -> Atom {
    c.iter().rev().fold(Atom::num(0), |acc, ck| &acc * u + ck)
}

/// Synthetic division by (u − r).
fn deflate(c: &[Atom], r: &Atom) -> Vec<Atom> {
    let n = c.len() - 1;
    let mut q = vec![Atom::num(0); n];
    q[n - 1] = c[n].clone();
    for k in (1..n).rev() {
        q[k - 1] = simplify(&(&c[k] + &(r * &q[k])));
    }
    q
}

/// Numerically zero at every sample point (40 digits, relative to 1e-25).
fn vanishes(e: &Atom) -> bool {
    SAMPLES.iter().all(|&s| {
        eval_prec(e, &sample_point(s), 40)
            .map(|v| v.abs() < 1e-25)
            .unwrap_or(false)
    })
}

/// Roots of the factors of `e` that are linear in `u` (radicals frozen while factoring).
fn linear_roots(e: &Atom) -> Result<Vec<Atom>, String> {
    let (frozen, radicals) = freeze_radicals(&numerator(e));
    let mut out = Vec::new();
    for f in factor_list(&frozen) {
        if degree_in(&f, "u", 8) == Some(1) {
            out.push(thaw(
                &solve_linear(&f, "u").ok_or("linear factor without a root")?,
                &radicals,
            ));
        }
    }
    Ok(out)
}
