//! The whole derivation for one ansatz, step by step, from the ansatz (5)
//! to the reduced equations (19)–(20), their limits and Section 6's
//! recovery formulas. Every step is a call into a module named after it.
//!
//! Owns: the [`Derivation`] record. May use: every derivation module.

use crate::ansatz::{Ansatz, Closure};
use crate::contour::{self, Extrema, NormalDerivative};
use crate::force;
use crate::limits::{self, Axisymmetric, NearCircularExact, NearCircularModel, ZeroForce};
use crate::nondimensional::{self, Branch};
use crate::sym::{ex, normalize_radicals, simplify, solve_linear, subs, subs_all};
use crate::thin_layer::{self, LaplaceEquation};
use symbolica::atom::Atom;

/// The derivation of one model, by the route its closure requires.
#[derive(Clone, Debug)]
pub enum ModelDerivation {
    /// Collocation closures (`Max`, `AtPoint`): Eqs. (6)–(20).
    Collocation(Box<Derivation>),
    /// The energy (Ritz) closure.
    Energy(Box<crate::energy::EnergyDerivation>),
}

impl ModelDerivation {
    /// Derive `ansatz` by the route of its closure.
    pub fn new(ansatz: &Ansatz) -> Result<ModelDerivation, String> {
        match ansatz.closure {
            Closure::Energy => Ok(ModelDerivation::Energy(Box::new(crate::energy::derive(
                ansatz,
            )?))),
            _ => Ok(ModelDerivation::Collocation(Box::new(Derivation::new(
                ansatz,
            )?))),
        }
    }

    /// The ansatz.
    pub fn ansatz(&self) -> &Ansatz {
        match self {
            ModelDerivation::Collocation(d) => &d.ansatz,
            ModelDerivation::Energy(e) => &e.ansatz,
        }
    }
}

/// Every intermediate result of the derivation for one ansatz.
#[derive(Clone, Debug)]
pub struct Derivation {
    /// The ansatz this was derived from.
    pub ansatz: Ansatz,
    /// p(x, y): Eq. (5).
    pub pressure: Atom,
    /// The matched thin-layer system: Eq. (6).
    pub laplace: Vec<LaplaceEquation>,
    /// F with free shape parameters: Eq. (8).
    pub force: Atom,
    /// ∂p/∂ν on Γ₀ with free shape parameters: Eq. (9).
    pub normal_derivative: NormalDerivative,
    /// Shape parameters from the collocation: Eq. (10).
    pub collocation: Vec<(String, Atom)>,
    /// ∂p/∂ν on Γ₀ after collocation, b = s a: Eq. (11).
    pub normal_derivative_collocated: NormalDerivative,
    /// Extrema of (11) along Γ₀.
    pub extrema: Extrema,
    /// η(s) = (the value of ∂p/∂ν set by the closure) / (apex value): for
    /// the paper's closure (13), max ∂p/∂ν / apex value, Eq. (16).
    pub eta: Atom,
    /// (max − min)/min of ∂p/∂ν on Γ₀, as a function of s: quantity (14).
    pub bc_error: Atom,
    /// ξ from the closure (for the paper: max ∂p/∂ν = √(2mΔγ), Eq. (13)),
    /// with `g` = √(2mΔγ).
    pub xi_adhesion: Atom,
    /// p₀ from (13) with η as a symbol.
    pub p0: Atom,
    /// p₀ with η(s) written out: Section 6.
    pub p0_explicit: Atom,
    /// p(x, y) after collocation: Section 6.
    pub pressure_collocated: Atom,
    /// ξ from each matched equation, dimensionless: Eq. (15).
    pub xi: Vec<Atom>,
    /// The residuals in (ā, s; ρ, δ̄, η): Eqs. (19), (20).
    pub residuals: Vec<Atom>,
    /// F̄ in (ā, s, ξ; η).
    pub fbar: Atom,
    /// F̄ with ξ from the first form (15): Eq. (18).
    pub fbar_reduced: Atom,
    /// The explicit parametrisation of the solution curve by s, if any.
    pub branch: Option<Branch>,
    /// ξ₂ = ξ₃ solved for ρ: the Appendix's display before (38).
    pub rho_from_xi: Option<Atom>,
    /// Step 5, or why it could not be completed for this ansatz.
    pub limits: Result<Limits, String>,
}

/// Step 5: the limits of the reduced model.
#[derive(Clone, Debug)]
pub struct Limits {
    /// Section 4.
    pub axisymmetric: Axisymmetric,
    /// Section 5.
    pub zero_force: ZeroForce,
    /// ρ(s) in the non-adhesive limit: the relation behind (29).
    pub non_adhesive_rho: Atom,
    /// The exact nearly circular solution: (36), (37).
    pub near_circular_exact: NearCircularExact,
    /// The reduced model about the circle.
    pub near_circular_model: NearCircularModel,
}

impl Limits {
    fn new(
        eta: &Atom,
        residuals: &[Atom],
        xi1: &Atom,
        fbar: &Atom,
        fbar_reduced: &Atom,
    ) -> Result<Limits, String> {
        trace("limits");
        let axisymmetric = limits::axisymmetric(eta, residuals, xi1, fbar)?;
        let zero_force = limits::zero_force(fbar_reduced, residuals)?;
        let non_adhesive_rho = limits::non_adhesive(residuals)?;
        let near_circular_exact = limits::near_circular_exact()?;
        let near_circular_model = limits::near_circular_model(eta, residuals, xi1, &axisymmetric)?;
        Ok(Limits {
            axisymmetric,
            zero_force,
            non_adhesive_rho,
            near_circular_exact,
            near_circular_model,
        })
    }
}

impl Derivation {
    /// Run every step for `ansatz`.
    pub fn new(ansatz: &Ansatz) -> Result<Derivation, String> {
        let pressure = ex(ansatz.pressure);
        // Step 1: (2) with (1) → (6).
        let laplace = thin_layer::laplace_equations(&pressure)?;
        // Step 2: (8).
        let force = force::integrate_over_ellipse(&pressure)?;
        // Step 3: (9), (10), (11), (13).
        let normal_derivative = contour::normal_derivative(&pressure)?;
        let collocation = contour::collocate(ansatz, &normal_derivative)?;
        let shape: Vec<(&str, Atom)> = collocation
            .iter()
            .map(|(n, v)| (n.as_str(), v.clone()))
            .collect();
        let normal_derivative_collocated = normal_derivative
            .subs_all(&[("b", ex("s*a"))])
            .subs_all(&shape);
        let extrema = contour::extrema(&normal_derivative_collocated)?;
        // The closure: the value of ∂p/∂ν that is set equal to √(2mΔγ).
        let closed = match ansatz.closure {
            Closure::Max => extrema.max.clone(),
            Closure::AtPoint(u) => normal_derivative_collocated.at(&ex(u)),
            Closure::Energy => {
                return Err(
                    "the energy closure is derived by `energy::derive`, not by collocation".into(),
                )
            }
        };
        // η with any sum of radicals that cancels near s = 1 rationalised,
        // so that it has no removable singularity at s = 1
        let eta = crate::sym::rationalize(
            &normalize_radicals(&simplify(&(&closed / &extrema.apex))),
            &[("s", crate::sym::rat(999, 1000))],
        );
        let bc_error = normalize_radicals(&simplify(&(&extrema.max / &extrema.min - Atom::num(1))));
        let xi_adhesion =
            solve_linear(&(&closed - ex("g")), "xi").ok_or("closure not linear in 1/xi")?;
        let p0 = solve_linear(&(ex("eta") * &extrema.apex - ex("g")), "p0")
            .ok_or("apex value not linear in p0")?;
        let p0_explicit = normalize_radicals(&simplify(&subs(&p0, "eta", &eta)));
        let pressure_collocated =
            simplify(&subs_all(&subs_all(&pressure, &shape), &[("b", ex("s*a"))]));
        // Step 4: (17) → (15), (19), (20), (18).
        let mut rules = shape.clone();
        rules.push(("b", ex("s*a")));
        rules.push(("p0", p0.clone()));
        let eqs: Vec<Atom> = laplace.iter().map(|e| e.residual.clone()).collect();
        let xi = nondimensional::xi_forms(&eqs, &rules)?;
        let residuals = nondimensional::residuals(&xi)?;
        let f_scaled = subs_all(&subs_all(&force, &rules), &nondimensional::scale_rules());
        let fbar = simplify(&(f_scaled * ex("R1/(m*L^6)")));
        nondimensional::check_dimensionless(&fbar, "the force")?;
        let fbar_reduced = simplify(&subs(&fbar, "xi", &xi[0]));
        let branch = nondimensional::branch(&residuals);
        let rho_from_xi = rho_eliminating_abar(&xi);
        // Step 5: limits.
        let limits = Limits::new(&eta, &residuals, &xi[0], &fbar, &fbar_reduced);
        Ok(Derivation {
            ansatz: ansatz.clone(),
            pressure,
            laplace,
            force,
            normal_derivative,
            collocation,
            normal_derivative_collocated,
            extrema,
            eta,
            bc_error,
            xi_adhesion,
            p0,
            p0_explicit,
            pressure_collocated,
            xi,
            residuals,
            fbar,
            fbar_reduced,
            branch,
            rho_from_xi,
            limits,
        })
    }
}

/// The Appendix's display before (38): (15)₂ and (15)₃ with a common ξ,
/// ā³ eliminated, solved for ρ.
fn rho_eliminating_abar(xi: &[Atom]) -> Option<Atom> {
    if xi.len() != 3 {
        return None;
    }
    let x = limits::solve_abar_cubed(&(ex("xi") - &xi[1]))?;
    let e3 = simplify(&subs(&(ex("xi") - &xi[2]), "abar", &ex("XX^(1/3)")));
    solve_linear(&subs(&e3, "XX", &x), "rho")
}

fn trace(step: &str) {
    if std::env::var_os("THINJKR_TRACE").is_some() {
        eprintln!("[derive] {step}");
    }
}
