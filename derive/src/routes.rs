//! Second routes: independent numerical computations of what the
//! derivation gives symbolically, so that a verdict rests on two routes
//! (the claim's comparison and one of these) that agree.
//!
//! - (8), (18): Gauss–Legendre quadrature of the pressure over the ellipse;
//! - (22)–(25) and the Section 4 critical values: the radial problem (2)–(3)
//!   at ρ = 1 integrated as an ODE (RK4), independent of the ellipse ansatz;
//! - (26), (27): the zero-force state found numerically on the solved
//!   branch (F̄ = 0 by bisection), against the closed forms.
//!
//! - (2), (4): the layer of finite thickness carried numerically across
//!   each coating ([`crate::layer`]), its m extrapolated to long waves.
//!
//! Owns: [`SecondRoute`], [`decided_by_two_routes`], the routes. May use:
//! `claims` (the result type and the derived forms), `layer`, `model`, `ir`,
//! `numeric`, `sym`.

use crate::check::Verdict;
use crate::claims::ClaimResult;
use crate::ir::Ir;
use crate::model::{Derivation, Limits};
use crate::numeric::Curve;
use crate::sym::{ex, simplify, solve_linear, subs, subs_all};
use std::collections::BTreeMap;
use symbolica::atom::Atom;

/// The relative agreement two routes must reach for a verdict: the
/// quadratures below are Gauss–Legendre (48 × 96 points) of a polynomial
/// of low degree, exact to round-off.
pub const SECOND_ROUTE_TOLERANCE: f64 = 1e-10;

/// A second, independent route to a claim's derived side: its text, and
/// whether it agrees with the derived value to [`SECOND_ROUTE_TOLERANCE`].
#[derive(Clone, Debug)]
pub struct SecondRoute {
    /// What was compared, with the numbers.
    pub text: String,
    /// The two routes agree.
    pub agrees: bool,
}

/// Combine a claim with its second route: the verdict stands only when
/// the routes agree; when they disagree, or the second route fails, the
/// claim is `unverified` and says why.
pub fn decided_by_two_routes(
    mut c: ClaimResult,
    route: Result<SecondRoute, String>,
) -> ClaimResult {
    match route {
        Ok(r) if r.agrees => {
            c.note = format!("{}. Second route agrees: {}", c.note, r.text);
        }
        Ok(r) => {
            c.verdict = Verdict::Unverified;
            c.note = format!(
                "{}. Second route DISAGREES with the derived side (beyond {SECOND_ROUTE_TOLERANCE:e} relative), so no verdict: {}",
                c.note, r.text
            );
        }
        Err(e) => {
            c.verdict = Verdict::Unverified;
            c.note = format!("{}. Second route failed, so no verdict: {e}", c.note);
        }
    }
    c
}

fn agree(x: f64, y: f64) -> bool {
    agree_to(x, y, SECOND_ROUTE_TOLERANCE)
}

fn agree_to(x: f64, y: f64, tol: f64) -> bool {
    (x - y).abs() <= tol * x.abs().max(y.abs()).max(1e-300)
}

/// Second route for (8): Gauss–Legendre quadrature of p over the ellipse.
pub fn force(d: &Derivation) -> Result<SecondRoute, String> {
    let vals = [("a", 1.3), ("b", 0.7), ("A", 0.4), ("B", 1.1), ("p0", 1.0)];
    let p = Ir::from_atom(&d.pressure)?;
    let f = Ir::from_atom(&d.force)?;
    let mut env: BTreeMap<&str, f64> = vals.iter().cloned().collect();
    let quad = quadrature_over_ellipse(&p, &mut env, 1.3, 0.7)?;
    let formula = f.eval(&env)?;
    Ok(SecondRoute {
        text: format!("Gauss–Legendre quadrature of the derived p at a=1.3, b=0.7, A=0.4, B=1.1 gives {quad:.12}, the derived F {formula:.12}"),
        agrees: agree(quad, formula),
    })
}

/// Second route for (18): quadrature of the collocated pressure at a
/// solved state, against the derived (and, for the reader, the printed) F̄.
pub fn force_bar(d: &Derivation) -> Result<SecondRoute, String> {
    // state: s, ξ, ā chosen; dimensional with L = R1 = m = 1 (g = 1)
    let (s, xi, abar) = (0.8, 1.7, 3.0);
    let p0 = subs_all(&d.p0_explicit, &[("a", ex("abar")), ("g", Atom::num(1))]);
    let p = subs_all(&d.pressure_collocated, &[("a", ex("abar")), ("p0", p0)]);
    let pi = Ir::from_atom(&p)?;
    let mut env = BTreeMap::from([("s", s), ("xi", xi), ("abar", abar)]);
    let quad = quadrature_over_ellipse(&pi, &mut env, abar, s * abar)?;
    // F̄ = F R1/(m L^6) = F here; δ̄ from (15)₁ inverted
    let dbar =
        solve_linear(&(ex("xi") - &d.xi[0]), "dbar").ok_or("(15)₁ could not be solved for dbar")?;
    let dbar = Ir::from_atom(&simplify(&subs(&dbar, "eta", &d.eta)))?.eval(&env)?;
    env.insert("dbar", dbar);
    let derived = Ir::from_atom(&simplify(&subs(&d.fbar_reduced, "eta", &d.eta)))?.eval(&env)?;
    let printed = Ir::from_atom(&ex("pi*3^(1/2)*abar^3*(2*s^2*abar*dbar - (s + 1)^3)*s^2*(s + 1)/(16*(s^2 + 1)*(s^2 + s + 1)^(3/2))"))?.eval(&env)?;
    Ok(SecondRoute {
        text: format!("quadrature of the collocated pressure at s = 0.8, ξ = 1.7, ā = 3 gives F̄ = {quad:.10}; derived (18) {derived:.10}; printed (18) {printed:.10}"),
        agrees: agree(quad, derived),
    })
}

/// ∫∫ over x²/a² + y²/b² ≤ 1 in elliptic polar coordinates, 48 × 96 points.
fn quadrature_over_ellipse(
    p: &Ir,
    env: &mut BTreeMap<&str, f64>,
    a: f64,
    b: f64,
) -> Result<f64, String> {
    let (xr, wr) = gauss_legendre(48);
    let nt = 96;
    let mut total = 0.0;
    for (ri, wi) in xr.iter().zip(&wr) {
        let r = 0.5 * (ri + 1.0);
        for k in 0..nt {
            let t = 2.0 * std::f64::consts::PI * (k as f64) / nt as f64;
            env.insert("x", a * r * t.cos());
            env.insert("y", b * r * t.sin());
            total +=
                0.5 * wi * (2.0 * std::f64::consts::PI / nt as f64) * a * b * r * p.eval(env)?;
        }
    }
    Ok(total)
}

/// Gauss–Legendre nodes and weights on [−1, 1] by Newton on P_n.
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut x = vec![0.0; n];
    let mut w = vec![0.0; n];
    for i in 0..n {
        let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        for _ in 0..100 {
            let (mut p1, mut p2) = (1.0, 0.0);
            for j in 0..n {
                let p3 = p2;
                p2 = p1;
                p1 = ((2 * j + 1) as f64 * z * p2 - j as f64 * p3) / (j + 1) as f64;
            }
            let pp = n as f64 * (z * p1 - p2) / (z * z - 1.0);
            let dz = p1 / pp;
            z -= dz;
            if dz.abs() < 1e-15 {
                x[i] = z;
                w[i] = 2.0 / ((1.0 - z * z) * pp * pp);
                break;
            }
        }
    }
    (x, w)
}

/// The radial problem (2)–(3) at ρ = 1 in the units (17): p̄'' + p̄'/r =
/// r²/2 − δ̄ on (0, ā), p̄(ā) = 0, p̄'(ā) = 1 (the tensile edge: ∂p̄/∂ν = 1),
/// regular at 0. By superposition p̄ = u + δ̄ v + C with u'' + u'/r = r²/2
/// and v'' + v'/r = −1 (regular, zero at 0); u, v and ∫2πr u, ∫2πr v are
/// integrated together by the classical Runge–Kutta method from r = h
/// (started on their regular series u = r⁴/32, v = −r²/4) in `steps`
/// steps. Returns (δ̄, F̄) at ā.
pub fn radial(abar: f64, steps: usize) -> (f64, f64) {
    let h = abar / steps as f64;
    // y = (u, u', v, v', ∫2πr u, ∫2πr v)
    let rhs = |r: f64, y: &[f64; 6]| -> [f64; 6] {
        let tau = 2.0 * std::f64::consts::PI * r;
        [
            y[1],
            r * r / 2.0 - y[1] / r,
            y[3],
            -1.0 - y[3] / r,
            tau * y[0],
            tau * y[2],
        ]
    };
    let r0 = h;
    let mut y = [
        r0.powi(4) / 32.0,
        r0.powi(3) / 8.0,
        -r0 * r0 / 4.0,
        -r0 / 2.0,
        2.0 * std::f64::consts::PI * r0.powi(6) / 192.0,
        -2.0 * std::f64::consts::PI * r0.powi(4) / 16.0,
    ];
    let mut r = r0;
    for _ in 1..steps {
        let k1 = rhs(r, &y);
        let add = |y: &[f64; 6], k: &[f64; 6], c: f64| {
            let mut z = *y;
            for i in 0..6 {
                z[i] += c * k[i];
            }
            z
        };
        let k2 = rhs(r + h / 2.0, &add(&y, &k1, h / 2.0));
        let k3 = rhs(r + h / 2.0, &add(&y, &k2, h / 2.0));
        let k4 = rhs(r + h, &add(&y, &k3, h));
        for i in 0..6 {
            y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
        r += h;
    }
    // p̄'(ā) = u' + δ̄ v' = 1; p̄(ā) = u + δ̄ v + C = 0
    let dbar = (1.0 - y[1]) / y[3];
    let c = -(y[0] + dbar * y[2]);
    let fbar = y[4] + dbar * y[5] + std::f64::consts::PI * abar * abar * c;
    (dbar, fbar)
}

/// The steps of [`radial`] used by the routes: the RK4 error is then far
/// below the tolerances below (checked by halving in a test).
pub const RADIAL_STEPS: usize = 4000;

/// The load-controlled pull-off of the radial problem: the zero of dF̄/dā
/// (five-point central differences, h = 1e-3: truncation O(h⁴), about
/// 1e-12 in the location) by bisection on [2, 2.6]. (ā_c, F̄_c, δ̄_c).
pub fn radial_critical() -> Result<(f64, f64, f64), String> {
    let f = |a: f64| radial(a, RADIAL_STEPS).1;
    let h = 1e-3;
    let df =
        |a: f64| (-f(a + 2.0 * h) + 8.0 * f(a + h) - 8.0 * f(a - h) + f(a - 2.0 * h)) / (12.0 * h);
    let a_c = crate::numeric::bisect(df, 2.0, 2.6)?;
    let (d_c, f_c) = radial(a_c, RADIAL_STEPS);
    Ok((a_c, f_c, d_c))
}

/// Second route for (25)₁ and (25)₂: δ̄ and F̄ of the radial problem at
/// ā = 2.5 against the derived forms.
pub fn axisymmetric(l: &Limits, which: usize) -> Result<SecondRoute, String> {
    let abar = 2.5;
    let (dbar, fbar) = radial(abar, RADIAL_STEPS);
    let form = if which == 0 {
        &l.axisymmetric.dbar
    } else {
        &l.axisymmetric.fbar
    };
    let derived = Ir::from_atom(form)?.eval(&BTreeMap::from([("abar", abar)]))?;
    let numeric = if which == 0 { dbar } else { fbar };
    let name = if which == 0 { "δ̄" } else { "F̄" };
    Ok(SecondRoute {
        text: format!("the radial problem (2)–(3) at ρ = 1 integrated as an ODE (RK4, {RADIAL_STEPS} steps) gives {name} = {numeric:.12} at ā = 2.5, the derived form {derived:.12}"),
        agrees: agree_to(numeric, derived, 1e-9),
    })
}

/// Second route for the Section 4 critical values: the minimum of the
/// radial problem's F̄(ā) against the derived (ā_c, F̄_c, δ̄_c); `which` is
/// 0, 1 or 2.
pub fn axisymmetric_critical(l: &Limits, which: usize) -> Result<SecondRoute, String> {
    let (a_c, f_c, d_c) = radial_critical()?;
    let (numeric, form, name, tol) = match which {
        0 => (a_c, &l.axisymmetric.critical.0, "ā_c", 1e-8),
        1 => (f_c, &l.axisymmetric.critical.1, "F̄_c", 1e-10),
        _ => (d_c, &l.axisymmetric.critical.2, "δ̄_c", 1e-8),
    };
    let derived = crate::sym::eval_prec(form, &[], 30)?;
    Ok(SecondRoute {
        text: format!("the minimum of F̄(ā) of the radial problem (2)–(3) at ρ = 1 (RK4, dF̄/dā = 0 by bisection) gives {name} = {numeric:.10}, the derived value {derived:.10} (agreement asked: {tol:e} relative, the location's accuracy)"),
        agrees: agree_to(numeric, derived, tol),
    })
}

/// Second route for (26) and (27): the zero-force state found numerically
/// on the solved branch at ρ = 0.8 (bisection on F̄ = 0 along the curve
/// parametrised by s), against the derived closed form (`form`, in s,
/// with η) of ā δ̄ (`which` = 0) or ā³ (`which` = 1) at its s.
pub fn zero_force(d: &Derivation, form: &Atom, which: usize) -> Result<SecondRoute, String> {
    let curve = Curve::new(d, 0.8)?;
    let st = curve.first_crossing(|st| st.fbar, 0.0)?;
    let derived = Ir::from_atom(&simplify(&subs(form, "eta", &d.eta)))?
        .eval(&BTreeMap::from([("s", st.s)]))?;
    let (numeric, name) = if which == 0 {
        (st.abar * st.dbar, "ā δ̄")
    } else {
        (st.abar.powi(3), "ā³")
    };
    Ok(SecondRoute {
        text: format!("the zero-force state found numerically on the branch at ρ = 0.8 (s = {:.10}) has {name} = {numeric:.12}, the derived closed form there {derived:.12}", st.s),
        agrees: agree_to(numeric, derived, 1e-9),
    })
}

/// Second route for a state found on the solved branch (the explicit
/// parametrisation by s, [`Curve`]): the residuals (19) and (20),
/// evaluated directly at the state, vanish (relative to ā³), and F̄
/// evaluated from the derived (18) is the state's — the branch formula
/// and the equations are two routes to the same state.
pub fn on_branch(
    d: &Derivation,
    rho: f64,
    st: &crate::numeric::State,
    what: &str,
) -> Result<SecondRoute, String> {
    let env = BTreeMap::from([
        ("abar", st.abar),
        ("s", st.s),
        ("rho", rho),
        ("dbar", st.dbar),
    ]);
    let with_eta = |e: &Atom| Ir::from_atom(&simplify(&subs(e, "eta", &d.eta)));
    let r: Vec<f64> = d
        .residuals
        .iter()
        .map(|e| with_eta(e)?.eval(&env))
        .collect::<Result<_, _>>()?;
    let f = with_eta(&d.fbar_reduced)?.eval(&env)?;
    let scale = st.abar.powi(3);
    let worst = r.iter().fold(0.0f64, |m, v| m.max(v.abs())) / scale;
    Ok(SecondRoute {
        text: format!(
            "at {what} (s = {:.8}, ā = {:.8}, δ̄ = {:.8}) the residuals (19), (20) evaluated directly are {:.1e} of ā³ and the derived (18) gives F̄ = {f:.10} (the branch: {:.10})",
            st.s, st.abar, st.dbar, worst, st.fbar
        ),
        agrees: worst < 1e-10 && agree_to(f, st.fbar, 1e-10),
    })
}

/// Second route for a value of (14): its 30-digit evaluation from the
/// symbolic form against the f64 evaluation of the compiled expression.
pub fn two_evaluations(form: &Atom, s: (i64, i64)) -> Result<SecondRoute, String> {
    let exact = crate::sym::eval_prec(form, &[("s", crate::sym::rat(s.0, s.1))], 30)?;
    let fast = Ir::from_atom(form)?.eval(&BTreeMap::from([("s", s.0 as f64 / s.1 as f64)]))?;
    Ok(SecondRoute {
        text: format!(
            "(14) at s = {}/{} is {exact:.15} at 30 digits and {fast:.15} in f64",
            s.0, s.1
        ),
        agrees: agree_to(exact, fast, 1e-12),
    })
}

/// Second route for (2) and (4): m from the numerical layer alone (the
/// state vector carried across each coating, [`crate::layer::propagated_m`],
/// no symbolic step) at (h₁, G₁) = (0.7, 1.3) and (h₂, G₂) = (1.1, 0.6),
/// against the derived m at the same point.
pub fn layer_thin(d: &Derivation) -> Result<SecondRoute, String> {
    let m = crate::claims::derived_form(d, "layer.m")?;
    let r = crate::sym::rat;
    let point = [
        ("h1", r(7, 10)),
        ("G1", r(13, 10)),
        ("h2", r(11, 10)),
        ("G2", r(3, 5)),
    ];
    let derived = crate::sym::eval_prec(&m, &point, 30)?;
    let route = crate::layer::propagated_m(0.7, 1.3, 1.1, 0.6)
        .ok_or("the layer's state vector could not be carried across a coating")?;
    Ok(SecondRoute {
        text: format!(
            "m at h₁ = 0.7, G₁ = 1.3, h₂ = 1.1, G₂ = 0.6 is {derived:.12} derived and {route:.12} from the numerical layer (C₁ + C₂ over k² at kh₁ = 0.0025 … 0.02, extrapolated to k → 0)"
        ),
        agrees: agree(derived, route),
    })
}

/// The second route named `name` in the catalog (`route = …` in
/// derive/claims.toml).
pub fn by_name(d: &Derivation, name: &str) -> Result<SecondRoute, String> {
    let l = || {
        d.limits
            .as_ref()
            .map_err(|e| format!("the limits of this ansatz failed: {e}"))
    };
    match name {
        "force" => force(d),
        "force_bar" => force_bar(d),
        "layer.thin" => layer_thin(d),
        "radial.dbar" => axisymmetric(l()?, 0),
        "radial.fbar" => axisymmetric(l()?, 1),
        "radial.critical.a_bar" => axisymmetric_critical(l()?, 0),
        "radial.critical.force" => axisymmetric_critical(l()?, 1),
        "radial.critical.delta_bar" => axisymmetric_critical(l()?, 2),
        "zero_force.abar_dbar" => zero_force(
            d,
            &crate::claims::derived_form(d, "zero_force.abar_dbar")?,
            0,
        ),
        "zero_force.abar_cubed" => zero_force(
            d,
            &crate::claims::derived_form(d, "zero_force.abar_cubed")?,
            1,
        ),
        _ => Err(format!("unknown second route {name} in derive/claims.toml")),
    }
}
