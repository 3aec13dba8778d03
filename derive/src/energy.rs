//! The energy (Ritz) closure of an ansatz: its shape parameters and p₀ come
//! from the matched thin-layer system (6) alone, which makes the pressure
//! the exact solution of (2) with p = 0 on the ellipse (7); the semi-axes
//! then make the total potential energy stationary.
//!
//! Stored energy of the layers for a given contact domain:
//! U = ½∫ω p (δ − φ) dA, checked against the second route
//! U = (1/2m)∫ω |∇p|² dA (Green's identity with Δp = m(φ − δ), p = 0 on Γ₀).
//! Total potential energy under displacement control: Π = U − Δγ·πab.
//! With the scales (17), Π = Π̄ m L⁸/R₁², and
//! - the equilibrium equations are ∂Π̄/∂ā = 0 and ∂Π̄/∂s = 0 (equivalent to
//!   ∂Π/∂a = ∂Π/∂b = 0, since (a, b) ↦ (ā, s) is a diffeomorphism for
//!   ā > 0); each is divided by the derivative of the adhesion term
//!   W̄ = πsā²/2, so the residual is "energy release over adhesion − 1";
//! - the force is F̄ = ∂Π̄/∂δ̄ (checked against ∫ω p dA, which is F of (8));
//! - stability: the Hessian of Π̄ in (ā, s) under displacement control, in
//!   (ā, s, δ̄) of Π̄ − F̄δ̄ under load control. At an equilibrium the
//!   Hessian in (ā, s) is congruent to the one in (a, b), so positive
//!   definiteness is the same statement.
//!
//! Owns: the Ritz closure. May use: `ansatz`, `thin_layer`, `force`,
//! `contour`, `nondimensional`, `sym`.

use crate::ansatz::{Ansatz, Closure};
use crate::contour;
use crate::force::integrate_over_ellipse;
use crate::nondimensional::{check_dimensionless, scale_rules};
use crate::sym::{
    diff, eval_prec, ex, factor_list, is_zero, normalize_radicals, numerator, rat, simplify,
    solve_linear, subs, subs_all,
};
use crate::thin_layer::{self, LaplaceEquation};
use symbolica::atom::{Atom, AtomCore};

/// The unknowns of the energy model, in the order of the residuals'
/// Jacobian and the Hessian.
pub const UNKNOWNS: [&str; 3] = ["abar", "s", "dbar"];

/// Every intermediate result of the energy closure for one ansatz.
#[derive(Clone, Debug)]
pub struct EnergyDerivation {
    /// The ansatz this was derived from.
    pub ansatz: Ansatz,
    /// p(x, y) as given.
    pub pressure: Atom,
    /// The matched thin-layer system (6).
    pub laplace: Vec<LaplaceEquation>,
    /// p₀ and the shape parameters from (6), in a, b, δ, m, R₁, R₂.
    pub dirichlet: Vec<(String, Atom)>,
    /// The pressure with those values: the exact solution of (2) on ω₀.
    pub pressure_exact: Atom,
    /// U = ½∫ p (δ − φ) dA, dimensional.
    pub stored_energy: Atom,
    /// Π̄(ā, s, δ̄; ρ).
    pub potential: Atom,
    /// F̄ = ∂Π̄/∂δ̄ (equal to ∫p dA scaled).
    pub fbar: Atom,
    /// The equilibrium residuals (∂Π̄/∂ā)/(∂W̄/∂ā), (∂Π̄/∂s)/(∂W̄/∂s).
    pub residuals: Vec<Atom>,
    /// Hessian of Π̄ in (ā, s, δ̄), row-major 3 × 3.
    pub hessian: Vec<Atom>,
    /// ∂p̄/∂ν̄ on Γ₀ at u = sin²t, in units of √(2mΔγ): (ā, s, δ̄, ρ, u).
    pub normal_derivative: Atom,
    /// [p̄₀, A L², B L², ξ] (the shape parameters in the ansatz's order, then ξ).
    pub pressure_parameters: Vec<Atom>,
    /// p̄(x̄, ȳ) in units √(2mΔγ) L, coordinates in units L.
    pub pressure_bar: Atom,
}

/// Solve the matched system (6) for p₀ and the shape parameters, which
/// enter it linearly as p₀ and the products p₀·S (S a shape parameter).
/// Fails unless (6) determines them uniquely.
pub fn solve_matched_system(
    ansatz: &Ansatz,
    laplace: &[LaplaceEquation],
) -> Result<Vec<(String, Atom)>, String> {
    let params = ansatz.shape_params;
    if laplace.len() != params.len() + 1 {
        return Err(format!(
            "(6) has {} equations for p0 and {} shape parameters",
            laplace.len(),
            params.len()
        ));
    }
    // S = l_S / p0 makes every equation linear in (p0, l_S).
    let lin = |p: &str| format!("lin{p}");
    let to_lin: Vec<(String, Atom)> = params
        .iter()
        .map(|p| (p.to_string(), ex(&format!("{}/p0", lin(p)))))
        .collect();
    let to_lin: Vec<(&str, Atom)> = to_lin
        .iter()
        .map(|(n, v)| (n.as_str(), v.clone()))
        .collect();
    let mut eqs: Vec<Atom> = laplace
        .iter()
        .map(|l| numerator(&simplify(&subs_all(&l.residual, &to_lin))).expand())
        .collect();
    let unknowns: Vec<String> = std::iter::once("p0".to_string())
        .chain(params.iter().map(|p| lin(p)))
        .collect();
    let mut solved: Vec<(String, Atom)> = Vec::new();
    for name in &unknowns {
        let k = eqs
            .iter()
            .position(|e| solve_linear(e, name).is_some())
            .ok_or_else(|| format!("(6) does not determine {name} linearly"))?;
        let v = solve_linear(&eqs.remove(k), name).expect("checked");
        eqs = eqs
            .iter()
            .map(|e| numerator(&simplify(&subs(e, name, &v))).expand())
            .collect();
        for (_, w) in solved.iter_mut() {
            *w = simplify(&subs(w, name, &v));
        }
        solved.push((name.clone(), v));
    }
    let value = |n: &str| solved.iter().find(|(m, _)| m == n).map(|(_, v)| v.clone());
    let p0 = value("p0").expect("solved");
    let mut out = vec![("p0".to_string(), p0.clone())];
    for p in params {
        out.push((
            p.to_string(),
            simplify(&(value(&lin(p)).expect("solved") / &p0)),
        ));
    }
    Ok(out)
}

/// Derive the energy closure for `ansatz` (whose closure must be
/// [`Closure::Energy`]).
pub fn derive(ansatz: &Ansatz) -> Result<EnergyDerivation, String> {
    if ansatz.closure != Closure::Energy {
        return Err(format!(
            "ansatz {} does not have the energy closure",
            ansatz.id
        ));
    }
    let pressure = ex(ansatz.pressure);
    let laplace = thin_layer::laplace_equations(&pressure)?;
    let dirichlet = solve_matched_system(ansatz, &laplace)?;
    let rules: Vec<(&str, Atom)> = dirichlet
        .iter()
        .map(|(n, v)| (n.as_str(), v.clone()))
        .collect();
    let p = simplify(&subs_all(&pressure, &rules));
    if !is_zero(&thin_layer::thin_layer_residual(&p)) {
        return Err("the pressure from (6) does not satisfy (2)".into());
    }
    // U two ways.
    let u1 =
        integrate_over_ellipse(&(&p * &(ex("delta") - thin_layer::gap())).expand())? * rat(1, 2);
    let grad2 = diff(&p, "x") * diff(&p, "x") + diff(&p, "y") * diff(&p, "y");
    let u2 = integrate_over_ellipse(&grad2.expand())? / ex("2*m");
    if !is_zero(&(&u1 - &u2)) {
        return Err("U = ½∫p(δ − φ) and (1/2m)∫|∇p|² differ".into());
    }
    let stored_energy = simplify(&u1);
    // Scales (17), with Δγ = m L⁶/(2 R₁²).
    let mut scale = scale_rules();
    scale.push(("dg", ex("m*L^6/(2*R1^2)")));
    let energy_unit = ex("R1^2/(m*L^8)");
    let potential =
        simplify(&(subs_all(&(&stored_energy - ex("dg*pi*a*b")), &scale) * &energy_unit));
    check_dimensionless(&potential, "the potential energy")?;
    let adhesion = simplify(&(subs_all(&ex("dg*pi*a*b"), &scale) * &energy_unit));
    let fbar = simplify(&diff(&potential, "dbar"));
    let fbar_direct =
        simplify(&(subs_all(&integrate_over_ellipse(&p.expand())?, &scale) * ex("R1/(m*L^6)")));
    if !is_zero(&(&fbar - &fbar_direct)) {
        return Err("∂Π̄/∂δ̄ differs from ∫p dA: the force identity fails".into());
    }
    let residuals: Vec<Atom> = ["abar", "s"]
        .iter()
        .map(|q| simplify(&(diff(&potential, q) / diff(&adhesion, q))))
        .collect();
    let mut hessian = Vec::new();
    for qi in UNKNOWNS {
        for qj in UNKNOWNS {
            hessian.push(simplify(&diff(&diff(&potential, qi), qj)));
        }
    }
    // ∂p̄/∂ν̄ on Γ₀, in units of √(2mΔγ) = m L³/R₁.
    let nd = contour::normal_derivative(&p)?;
    let normal_derivative =
        normalize_radicals(&simplify(&(nd.subs_all(&scale).value() * ex("R1/(m*L^3)"))));
    check_dimensionless(&normal_derivative, "the normal derivative")?;
    // p̄₀, the shape parameters times L², ξ.
    let pressure_unit = ex("R1/(m*L^4)");
    let mut pressure_parameters = vec![simplify(
        &(subs_all(&dirichlet[0].1, &scale) * &pressure_unit),
    )];
    for (_, v) in &dirichlet[1..] {
        pressure_parameters.push(simplify(&(subs_all(v, &scale) * ex("L^2"))));
    }
    let (xi_param, xi_value) = ansatz.xi_definition;
    let xi = solve_linear(&(ex(xi_param) - ex(xi_value)), "xi")
        .ok_or("the definition of xi is not linear in xi")?;
    let xi = simplify(&subs_all(&subs_all(&xi, &rules), &scale));
    check_dimensionless(&xi, "xi")?;
    pressure_parameters.push(xi);
    let pressure_bar = simplify(
        &(subs_all(&subs_all(&p, &[("x", ex("x*L")), ("y", ex("y*L"))]), &scale) * &pressure_unit),
    );
    check_dimensionless(&pressure_bar, "the pressure")?;
    Ok(EnergyDerivation {
        ansatz: ansatz.clone(),
        pressure,
        laplace,
        dirichlet,
        pressure_exact: p,
        stored_energy,
        potential,
        fbar,
        residuals,
        hessian,
        normal_derivative,
        pressure_parameters,
        pressure_bar,
    })
}

/// The axisymmetric limit ρ = 1, s = 1 of an energy model: the residual's
/// factors linear in δ̄ are the candidate branches ((∂p/∂ν)² = 2mΔγ has
/// two roots); the adhesive one has ∂p/∂ν > 0 (tensile edge). Returns
/// (δ̄(ā), F̄(ā)).
pub fn axisymmetric(e: &EnergyDerivation) -> Result<(Atom, Atom), String> {
    let at1 = |x: &Atom| simplify(&subs_all(x, &[("rho", Atom::num(1)), ("s", Atom::num(1))]));
    let r: Vec<Atom> = e.residuals.iter().map(at1).collect();
    let nd = at1(&subs(&e.normal_derivative, "u", &Atom::num(0)));
    for f in factor_list(&numerator(&r[0])) {
        let Some(dbar) = solve_linear(&f, "dbar") else {
            continue;
        };
        if r.iter().any(|ri| !is_zero(&subs(ri, "dbar", &dbar))) {
            continue;
        }
        let edge = subs(&subs(&nd, "dbar", &dbar), "abar", &rat(3, 1));
        if eval_prec(&edge, &[], 30)? > 0.0 {
            let fbar = simplify(&subs(&at1(&e.fbar), "dbar", &dbar));
            return Ok((simplify(&dbar), fbar));
        }
    }
    Err("no factor of the residual at rho = 1 is linear in dbar with a tensile edge".into())
}
