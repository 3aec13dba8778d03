//! Step 5 of the derivation: the limits of the reduced model.
//! - the axisymmetric case ρ = 1 (Section 4): (22)–(25) and the critical point;
//! - zero force (Section 5): (26)–(28);
//! - the non-adhesive limit, Δγ → 0: the relation behind (29);
//! - nearly circular contacts (Appendix): the exact first-order perturbation
//!   of the free-boundary problem (2)–(3), giving (36)–(37) independently of
//!   any ansatz, and the first-order expansion of the reduced model, to be
//!   compared with it.
//!
//! Owns: these limits. May use: `nondimensional`, `sym`.

use crate::sym::{
    derivative_at, diff, ex, factor_list, is_zero, normalize_radicals, poly_coeff, simplify,
    solve_linear, subs, subs_all, value_at,
};
use symbolica::atom::{Atom, AtomCore};

/// The axisymmetric case ρ = 1, s = 1.
#[derive(Clone, Debug)]
pub struct Axisymmetric {
    /// η(1).
    pub eta_at_1: Atom,
    /// δ̄(ā), the first relation (25).
    pub dbar: Atom,
    /// F̄(ā), the second relation (25).
    pub fbar: Atom,
    /// δ(a), Eq. (22), in `a`, `L`, `R1` (with √(2mΔγ) = m L³/R₁).
    pub delta: Atom,
    /// F(a), Eq. (23), in `a`, `L`, `R1`, `m`.
    pub force: Atom,
    /// The critical (minimum-force) point: (ā_c, F̄_c, δ̄_c).
    pub critical: (Atom, Atom, Atom),
}

/// Solve `eq = 0` for ā³ (written `XX`), when ā enters only as ā³.
pub fn solve_abar_cubed(eq: &Atom) -> Option<Atom> {
    let e = simplify(&subs(eq, "abar", &ex("XX^(1/3)")));
    if e.contains_symbol(symbolica::symbol!("abar")) {
        return None;
    }
    solve_linear(&e, "XX")
}

/// Section 4 from the reduced model: set ρ = 1, s = 1, η = η(1).
pub fn axisymmetric(
    eta: &Atom,
    residuals: &[Atom],
    xi1: &Atom,
    fbar: &Atom,
) -> Result<Axisymmetric, String> {
    let eta1 = value_at(eta, "s", 1)?;
    let at1 = |e: &Atom| {
        let v = subs_all(
            e,
            &[
                ("rho", Atom::num(1)),
                ("s", Atom::num(1)),
                ("eta", eta1.clone()),
            ],
        );
        simplify(&normalize_radicals(&simplify(&v)))
    };
    let dbars: Vec<Atom> = residuals
        .iter()
        .map(|r| solve_linear(&at1(r), "dbar").ok_or("residual not linear in dbar at rho = 1"))
        .collect::<Result<_, _>>()?;
    if dbars.windows(2).any(|w| !is_zero(&(&w[0] - &w[1]))) {
        return Err("the residuals disagree at rho = 1, s = 1".into());
    }
    let dbar = dbars[0].clone();
    let fb = simplify(&subs(&at1(&subs(fbar, "xi", xi1)), "dbar", &dbar));
    let delta = simplify(&(subs(&dbar, "abar", &ex("a/L")) * ex("L^2/R1")));
    let force = simplify(&(subs(&fb, "abar", &ex("a/L")) * ex("m*L^6/R1")));
    // Critical point: dF̄/dā = 0 at a factor ā³ − c.
    let crit = critical_point(&fb, &dbar);
    let critical = crit.ok_or("no critical point of the form abar^3 = c")?;
    Ok(Axisymmetric {
        eta_at_1: eta1,
        dbar,
        fbar: fb,
        delta,
        force,
        critical,
    })
}

/// The critical (minimum-force) point of an axisymmetric F̄(ā): dF̄/dā = 0
/// at a factor of the form ā³ − c. Returns (ā_c, F̄_c, δ̄_c).
pub fn critical_point(fbar: &Atom, dbar: &Atom) -> Option<(Atom, Atom, Atom)> {
    let dfb = diff(fbar, "abar");
    let mut crit = None;
    for f in factor_list(&crate::sym::numerator(&dfb)) {
        if let Some(c) = solve_abar_cubed(&f) {
            if c.contains_symbol(symbolica::symbol!("XX")) {
                continue;
            }
            let a_c = normalize_radicals(&c.pow(&ex("1/3")));
            let f_c = simplify(&normalize_radicals(&subs(fbar, "abar", &a_c)));
            let d_c = normalize_radicals(&simplify(&normalize_radicals(&subs(dbar, "abar", &a_c))));
            crit = Some((a_c, f_c, d_c));
        }
    }
    crit
}

/// Section 5: zero force.
#[derive(Clone, Debug)]
pub struct ZeroForce {
    /// δ̄ at F̄ = 0 (so that ā δ̄ is the left side of (26)).
    pub dbar: Atom,
    /// ā³ at F̄ = 0 from the first residual: (27).
    pub abar_cubed: Atom,
    /// ρ as a function of s at F̄ = 0: (28).
    pub rho: Atom,
}

/// Set F̄ = 0 in the reduced force and solve the residuals.
pub fn zero_force(fbar_reduced: &Atom, residuals: &[Atom]) -> Result<ZeroForce, String> {
    let num = crate::sym::numerator(fbar_reduced);
    let dbar = factor_list(&num)
        .into_iter()
        .find(|f| f.contains_symbol(symbolica::symbol!("dbar")))
        .and_then(|f| solve_linear(&f, "dbar"))
        .ok_or("zero force does not fix dbar")?;
    let cubes: Vec<Atom> = residuals
        .iter()
        .map(|r| {
            solve_abar_cubed(&subs(r, "dbar", &dbar)).ok_or("abar^3 not explicit at zero force")
        })
        .collect::<Result<_, _>>()?;
    let rho =
        solve_linear(&(&cubes[0] - &cubes[1]), "rho").ok_or("rho not linear at zero force")?;
    Ok(ZeroForce {
        dbar,
        abar_cubed: cubes[0].clone(),
        rho,
    })
}

/// The non-adhesive limit: Δγ → 0 is ā → ∞ with δ̄/ā² fixed. Returns ρ(s).
pub fn non_adhesive(residuals: &[Atom]) -> Result<Atom, String> {
    let lead: Vec<Atom> = residuals
        .iter()
        .map(|r| {
            let e = subs(r, "dbar", &ex("dd*abar^2")) * ex("abar^-3");
            let e = subs(&simplify(&e), "abar", &ex("1/eps")).expand();
            simplify(&subs(&simplify(&e), "eps", &Atom::num(0)))
        })
        .collect();
    let dd = solve_linear(&lead[0], "dd").ok_or("leading terms not linear in delta/a^2")?;
    solve_linear(&subs(&lead[1], "dd", &dd), "rho")
        .ok_or_else(|| "rho not linear in the non-adhesive limit".into())
}

/// The exact first-order solution of (2)–(3) for the nearly circular gap
/// (31): p = P₀(r) + μ P₁(r) cos 2θ on the contour r = a₀ + μ a₂ cos 2θ.
#[derive(Clone, Debug)]
pub struct NearCircularExact {
    /// δ(a₀): Eq. (37).
    pub delta: Atom,
    /// a₂(a₀): Eq. (36).
    pub a2: Atom,
}

/// Solve the perturbation problem. Symbols: `r`, `a0`, `a2`, `R`, `m`, and
/// `g` = √(2mΔγ). To first order in μ the normal derivative on the
/// perturbed contour is ∂p/∂r there (the tilt of the normal is O(μ) and
/// ∂p/∂θ is O(μ)).
pub fn near_circular_exact() -> Result<NearCircularExact, String> {
    let l0 = |p: &Atom| diff(&diff(p, "r"), "r") + diff(p, "r") * ex("1/r");
    let l2 = |p: &Atom| l0(p) - p * ex("4/r^2");
    let coeffs = |e: &Atom| -> Vec<Atom> {
        (0..=4)
            .map(|k| poly_coeff(&(e * ex("r^2")), "r", k + 2, "zz", 0))
            .collect()
    };
    // Order 1: radial Laplacian of c0 + c2 r^2 + c4 r^4 = m (r^2/(2R) − δ).
    let p0 = ex("c0 + c2*r^2 + c4*r^4");
    let eq0 = simplify(&(l0(&p0) - ex("m*(r^2/(2*R) - delta)")));
    let c = coeffs(&eq0);
    let c2 = solve_linear(&c[0], "c2").ok_or("c2")?;
    let c4 = solve_linear(&c[2], "c4").ok_or("c4")?;
    let p0 = subs_all(&p0, &[("c2", c2), ("c4", c4)]);
    // Order μ, mode cos 2θ: the gap (31) contributes −m r²/(2R).
    let p1 = ex("d2*r^2 + d4*r^4");
    let eq1 = simplify(&(l2(&p1) + ex("m*r^2/(2*R)")));
    let d4 = solve_linear(&coeffs(&eq1)[2], "d4").ok_or("d4")?;
    let p1 = subs(&p1, "d4", &d4);
    let at = |e: &Atom| subs(e, "r", &ex("a0"));
    let c0 = solve_linear(&at(&p0), "c0").ok_or("c0")?;
    let p0 = subs(&p0, "c0", &c0);
    let dp0 = diff(&p0, "r");
    let delta = solve_linear(&(at(&dp0) - ex("g")), "delta").ok_or("delta")?;
    let p0 = subs(&p0, "delta", &delta);
    let dp0 = diff(&p0, "r");
    let bc1 = ex("a2") * at(&dp0) + at(&p1);
    let bc2 = ex("a2") * at(&diff(&dp0, "r")) + at(&diff(&p1, "r"));
    let d2 = solve_linear(&bc1, "d2").ok_or("d2")?;
    let a2 = solve_linear(&subs(&bc2, "d2", &d2), "a2").ok_or("a2")?;
    Ok(NearCircularExact { delta, a2 })
}

/// The reduced model expanded to first order about the circle.
#[derive(Clone, Debug)]
pub struct NearCircularModel {
    /// ds/dμ at μ = 0 at fixed δ, as a function of ā₀.
    pub s1: Atom,
    /// dη/ds at s = 1.
    pub eta_prime_1: Atom,
    /// ξ at μ = 0 as a function of ā₀.
    pub xi0: Atom,
}

/// Expand the residuals with ρ = (1 − μ)/(1 + μ) ≈ 1 − 2μ, R₁ = R/(1 − μ)
/// (33): at fixed physical δ and a = a₀ + μ a₁, the scales (17) give
/// ā ≈ ā₀ (1 + μ k) with k = a₁/a₀ − 1/3 and δ̄ ≈ δ̄₀ (1 + μ/3).
pub fn near_circular_model(
    eta: &Atom,
    residuals: &[Atom],
    xi1: &Atom,
    axi: &Axisymmetric,
) -> Result<NearCircularModel, String> {
    let etap = derivative_at(eta, "s", 1)?;
    let dbar0 = subs(&axi.dbar, "abar", &ex("abar0"));
    let rules = [
        ("abar", ex("abar0*(1 + mu*kk)")),
        ("s", ex("1 + mu*s1")),
        ("dbar", &dbar0 * ex("(1 + mu/3)")),
        ("rho", ex("1 - 2*mu")),
        ("eta", &axi.eta_at_1 + ex("mu*s1") * &etap),
    ];
    let lin: Vec<Atom> = residuals
        .iter()
        .map(|r| {
            simplify(&subs(
                &diff(&subs_all(r, &rules), "mu"),
                "mu",
                &Atom::num(0),
            ))
        })
        .collect();
    let kk = solve_linear(&lin[0], "kk").ok_or("first-order residual not linear in k")?;
    let s1 = solve_linear(&subs(&lin[1], "kk", &kk), "s1")
        .ok_or("first-order residual not linear in s1")?;
    let xi0 = simplify(&subs_all(
        xi1,
        &[
            ("s", Atom::num(1)),
            ("rho", Atom::num(1)),
            ("eta", axi.eta_at_1.clone()),
            ("abar", ex("abar0")),
            ("dbar", dbar0),
        ],
    ));
    Ok(NearCircularModel {
        s1,
        eta_prime_1: etap,
        xi0,
    })
}
