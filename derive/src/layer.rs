//! The elastic layer of finite thickness: the normal surface compliance
//! C(k; h, G, ν) of a layer of thickness h bonded to a rigid base, under a
//! normal pressure p cos(k·x) on its frictionless top, derived from
//! three-dimensional elasticity, and the checks every kernel must pass.
//!
//! The derivation (Papkovich–Neuber): with φ and ψ harmonic,
//! 2G u = ∇(φ + zψ) − 4(1 − ν) ψ e_z solves Navier's equations. For the
//! wave vector k = (3k/5, 4k/5) (any direction: the layer is isotropic in
//! its plane, and the check of the second direction is [`derive_kernel`]'s
//! own), φ and ψ are e^{±kz} cos(3kx/5) cos(4ky/5) with four constants. The
//! layer is −h ≤ z ≤ 0: on its top σ_zz = −p cos·cos and σ_xz = σ_yz = 0
//! (frictionless); on its base u = 0 (bonded). The top's displacement into
//! the layer is w = C p cos·cos. The derivation checks its own steps: φ and
//! ψ harmonic, the stresses in equilibrium, and every boundary condition
//! held at every point of the plane once the four constants are solved.
//! C is a rational function of k, h, G, ν and the symbol `ekh` = e^{kh}.
//!
//! The checks ([`check_kernel`]) take any candidate kernel, so that a wrong
//! one can be shown to fail:
//! - the printed form of the literature (Carbone & Mangialardi 2008, as
//!   implemented by ContactMechanics' `PeriodicFFTElasticHalfSpace`);
//! - at ν = ½, the small-kh series h³k²/(3G)·(1 + c₂(kh)² + c₄(kh)⁴ + …),
//!   whose leading term is the thin-layer law behind (2) and (4);
//! - at large kh, the half-space's (1 − ν)/(Gk);
//! - for ν < ½, the Winkler layer h(1 − 2ν)/(2G(1 − ν)) as kh → 0;
//! - a second, numerical route: the state vector (u_x, u_z, σ_xz, σ_zz)
//!   carried across the layer by the matrix exponential of its first-order
//!   system ([`propagated_compliance`]), at points of kh and ν.
//!
//! Two coatings pressed together under one pressure, with a frictionless
//! interface, each carry that pressure on a shear-free top: the approach
//! is the sum of their displacements, and the pair's compliance is the sum
//! of theirs. Its small-k term is k²(h₁³/3G₁ + h₂³/3G₂) = k²/m, which with
//! −∇² ↔ k² is (2) with the m of (4) ([`thin_layer_m`]).
//!
//! Owns: [`LayerKernel`], [`derive_kernel`], [`KernelCheck`],
//! [`check_kernel`], [`propagated_compliance`], [`thin_layer_m`],
//! [`propagated_m`], [`base_share`] and its generated module. May use:
//! `accuracy`, `codegen` (to emit the module),
//! `check`, `sym`.

use crate::check::{compare, describe, Verdict};
use crate::sym::{diff, ex, is_zero, poly_coeff, simplify, solve_linear, subs, subs_all};
use symbolica::atom::{Atom, AtomCore};

/// The layer's compliance, derived.
#[derive(Clone, Debug)]
pub struct LayerKernel {
    /// C(k; h, G, ν): w = C p, a rational function of `k`, `h`, `G`, `nu`
    /// and `ekh` = e^{kh}.
    pub compliance: Atom,
    /// What the derivation checked of its own steps, in words.
    pub steps: Vec<String>,
}

/// The literature's kernel, as printed (Carbone & Mangialardi 2008; the
/// form of ContactMechanics' `PeriodicFFTElasticHalfSpace`, whose surface
/// stiffness is (E*/2)k times (fac cosh 2kh + 2(kh)² + off)/(fac sinh 2kh −
/// 2kh) with fac = 3 − 4ν, off = 4ν(2ν − 3) + 5), with E* = 2G/(1 − ν),
/// sinh 2kh = (ekh² − ekh⁻²)/2 and cosh 2kh = (ekh² + ekh⁻²)/2.
pub fn literature_kernel() -> Atom {
    ex("(1-nu)/(G*k) * ((3-4*nu)*(ekh^2-ekh^-2)/2 - 2*k*h) \
        / ((3-4*nu)*(ekh^2+ekh^-2)/2 + 2*(k*h)^2 + 4*nu*(2*nu-3) + 5)")
}

/// The three cartesian coordinates.
const XYZ: [&str; 3] = ["x", "y", "z"];

/// The fields at (x, y, z) with the four constants a1, a2, b1, b2.
struct Fields {
    /// u_x, u_y, u_z.
    u: [Atom; 3],
    /// σ_ij.
    sigma: [[Atom; 3]; 3],
    /// The plane wave cos(k_x x) cos(k_y y) of the fields.
    wave: Atom,
}

fn fields(direction: (&str, &str)) -> Result<(Fields, Vec<String>), String> {
    let (kx, ky) = direction;
    let wave = ex(&format!("cos({kx}*k*x)*cos({ky}*k*y)"));
    let phi = ex("a1*exp(k*z) + a2*exp(-k*z)") * &wave;
    let psi = ex("b1*exp(k*z) + b2*exp(-k*z)") * &wave;
    let mut steps = Vec::new();
    for (name, f) in [("φ", &phi), ("ψ", &psi)] {
        let lap = XYZ
            .iter()
            .fold(Atom::num(0), |acc, c| acc + diff(&diff(f, c), c));
        if !is_zero(&lap) {
            return Err(format!("{name} is not harmonic: ∇²{name} = {lap}"));
        }
    }
    steps.push("φ and ψ harmonic".to_string());
    // 2G u = ∇(φ + zψ) − 4(1 − ν) ψ e_z
    let chi = &phi + &(ex("z") * &psi);
    let two_g = ex("2*G");
    let u = [
        diff(&chi, "x") / &two_g,
        diff(&chi, "y") / &two_g,
        (diff(&chi, "z") - ex("4*(1-nu)") * &psi) / &two_g,
    ];
    let eps = |i: usize, j: usize| (diff(&u[i], XYZ[j]) + diff(&u[j], XYZ[i])) / Atom::num(2);
    let trace = eps(0, 0) + eps(1, 1) + eps(2, 2);
    let lambda = ex("2*G*nu/(1-2*nu)");
    let sigma: [[Atom; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let s = ex("2*G") * eps(i, j);
            if i == j {
                simplify(&(s + &lambda * &trace))
            } else {
                simplify(&s)
            }
        })
    });
    for (i, row) in sigma.iter().enumerate() {
        let div = row
            .iter()
            .zip(XYZ)
            .fold(Atom::num(0), |acc, (s, c)| acc + diff(s, c));
        if !is_zero(&div) {
            return Err(format!("the stresses are not in equilibrium (row {i})"));
        }
    }
    steps.push("∂_j σ_ij = 0 for i = x, y, z (Hooke's law in G and ν)".to_string());
    Ok((Fields { u, sigma, wave }, steps))
}

/// e^{kz} and e^{−kz} at z = 0 and z = −h, written in `ekh`.
fn at_depth(e: &Atom, z: &str) -> Atom {
    let e = subs(e, "z", &ex(z));
    let e = e
        .replace(ex("exp(-h*k)"))
        .with(ex("ekh^-1"))
        .replace(ex("exp(h*k)"))
        .with(ex("ekh"));
    simplify(&e)
}

fn at_origin(e: &Atom) -> Atom {
    subs_all(e, &[("x", Atom::num(0)), ("y", Atom::num(0))])
}

/// The four constants a1, a2, b1, b2 from four conditions at the origin
/// of the plane (the (x, y) dependence is cos·cos for σ_zz and u_z, and ∂_x
/// of cos·cos for σ_xz and u_x), by elimination one at a time.
fn constants(f: &Fields) -> Result<Vec<(&'static str, Atom)>, String> {
    let mut pending = vec![
        at_depth(&at_origin(&(&f.sigma[2][2] + &ex("p"))), "0"),
        at_depth(&at_origin(&diff(&f.sigma[0][2], "x")), "0"),
        at_depth(&at_origin(&f.u[2]), "-h"),
        at_depth(&at_origin(&diff(&f.u[0], "x")), "-h"),
    ];
    let mut solved: Vec<(&'static str, Atom)> = Vec::new();
    for name in ["a1", "a2", "b1", "b2"] {
        let (i, value) = pending
            .iter()
            .enumerate()
            .find_map(|(i, c)| solve_linear(c, name).map(|v| (i, v)))
            .ok_or_else(|| format!("the boundary conditions do not determine {name}"))?;
        let _condition_used = pending.remove(i);
        pending = pending
            .iter()
            .map(|c| simplify(&subs(c, name, &value)))
            .collect();
        for (_, v) in solved.iter_mut() {
            *v = simplify(&subs(v, name, &value));
        }
        solved.push((name, value));
    }
    Ok(solved)
}

/// The top's displacement into the layer (−z) over p at the origin: C.
fn compliance_of(f: &Fields, solved: &[(&str, Atom)]) -> Atom {
    simplify(&(-at_depth(&at_origin(&subs_all(&f.u[2], solved)), "0") / ex("p")))
}

thread_local! {
    static KERNEL: std::cell::OnceCell<Result<LayerKernel, String>> =
        const { std::cell::OnceCell::new() };
}

/// The derived kernel, derived once per thread ([`derive_kernel`]).
pub fn kernel() -> Result<LayerKernel, String> {
    KERNEL.with(|k| k.get_or_init(derive_kernel).clone())
}

/// Derive C(k; h, G, ν) (module docs), checking every step.
pub fn derive_kernel() -> Result<LayerKernel, String> {
    let (f, mut steps) = fields(("3/5", "4/5"))?;
    let solved = constants(&f)?;
    // every condition at every point of the plane, not only the origin
    let top = |e: &Atom| at_depth(&subs_all(e, &solved), "0");
    let base = |e: &Atom| at_depth(&subs_all(e, &solved), "-h");
    let holds = [
        (
            "σ_zz = −p cos·cos on the top",
            top(&(&f.sigma[2][2] + &(ex("p") * &f.wave))),
        ),
        ("σ_xz = 0 on the top", top(&f.sigma[0][2])),
        ("σ_yz = 0 on the top", top(&f.sigma[1][2])),
        ("u_x = 0 on the base", base(&f.u[0])),
        ("u_y = 0 on the base", base(&f.u[1])),
        ("u_z = 0 on the base", base(&f.u[2])),
    ];
    for (what, residual) in &holds {
        if !is_zero(residual) {
            return Err(format!("the solved constants break {what}"));
        }
    }
    steps.push(
        "every boundary condition holds at every (x, y) once the four constants are solved".into(),
    );
    let compliance = compliance_of(&f, &solved);
    // the same C along the x axis: the layer is isotropic in its plane
    let (g, _) = fields(("1", "0"))?;
    let along_x = compliance_of(&g, &constants(&g)?);
    if !is_zero(&simplify(&(&along_x - &compliance))) {
        return Err("the compliance depends on the wave vector's direction".into());
    }
    steps.push("the same C for the wave vector along x as along (3/5, 4/5)".into());
    Ok(LayerKernel { compliance, steps })
}

/// The second route: C·G·k of the layer at kh = `kh` and Poisson's ratio
/// `nu`, by the state vector y = (U, W, T, S) of u_x = U sin kx, u_z =
/// W cos kx, σ_xz = T sin kx, σ_zz = S cos kx (plane strain along the wave
/// vector, in units G = k = 1). Hooke's law and equilibrium give y′ = A y
/// with
///   U′ = W + T,  W′ = −ν/(1−ν) U + (1−2ν)/(2(1−ν)) S,
///   T′ = 2/(1−ν) U + ν/(1−ν) S,  S′ = −T,
/// finite at ν = ½. y(0) = exp(A kh) y(−h) from the bonded base
/// y(−h) = (0, 0, T₀, S₀); T(0) = 0 and S(0) = −1 fix T₀, S₀, and C·G·k =
/// −W(0). The exponential is by scaling and squaring of its Taylor series.
/// `None` where the 2 × 2 system is singular (it is not, for kh > 0).
pub fn propagated_compliance(kh: f64, nu: f64) -> Option<f64> {
    let q = 1.0 / (1.0 - nu);
    let a = [
        [0.0, 1.0, 1.0, 0.0],
        [-nu * q, 0.0, 0.0, (1.0 - 2.0 * nu) * q / 2.0],
        [2.0 * q, 0.0, 0.0, nu * q],
        [0.0, 0.0, -1.0, 0.0],
    ];
    let p = expm(&a, kh);
    // T(0) = p[2][2] T₀ + p[2][3] S₀ = 0, S(0) = p[3][2] T₀ + p[3][3] S₀ = −1
    let det = p[2][2] * p[3][3] - p[2][3] * p[3][2];
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let t0 = p[2][3] / det;
    let s0 = -p[2][2] / det;
    let w = p[1][2] * t0 + p[1][3] * s0;
    Some(-w).filter(|c| c.is_finite())
}

type Mat4 = [[f64; 4]; 4];

fn mul(a: &Mat4, b: &Mat4) -> Mat4 {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..4).map(|k| a[i][k] * b[k][j]).sum()))
}

/// exp(A t) by scaling (to a norm below ½), a 24-term Taylor series and
/// squaring back.
fn expm(a: &Mat4, t: f64) -> Mat4 {
    let norm = a
        .iter()
        .map(|r| r.iter().map(|x| x.abs()).sum::<f64>())
        .fold(0.0, f64::max)
        * t.abs();
    let squarings = if norm > 0.5 {
        (norm / 0.5).log2().ceil() as i32
    } else {
        0
    };
    let scale = t / 2f64.powi(squarings);
    let b: Mat4 = std::array::from_fn(|i| std::array::from_fn(|j| a[i][j] * scale));
    let mut sum: Mat4 =
        std::array::from_fn(|i| std::array::from_fn(|j| f64::from(u8::from(i == j))));
    let mut term = sum;
    for n in 1..=24 {
        term = mul(&term, &b);
        for row in term.iter_mut() {
            for x in row.iter_mut() {
                *x /= n as f64;
            }
        }
        for i in 0..4 {
            for j in 0..4 {
                sum[i][j] += term[i][j];
            }
        }
    }
    for _ in 0..squarings {
        sum = mul(&sum, &sum);
    }
    sum
}

/// The points of kh and ν where [`propagated_compliance`] is held against
/// a kernel.
pub const ROUTE_POINTS: [(f64, f64); 12] = [
    (0.05, 0.5),
    (0.3, 0.5),
    (1.0, 0.5),
    (2.5, 0.5),
    (6.0, 0.5),
    (0.05, 0.0),
    (1.0, 0.0),
    (4.0, 0.0),
    (0.3, 0.3),
    (2.5, 0.3),
    (0.1, 0.45),
    (3.0, 0.45),
];

/// The agreement the numerical route must reach (relative). The route is
/// good to round-off at small kh (derive/tests/layer_kernel.rs); its
/// exponential grows as e^{kh}, and at the largest kh of [`ROUTE_POINTS`]
/// it differed from the derived kernel by 6.1e-15 when first run.
pub const ROUTE_TOLERANCE: f64 = 1e-10;

/// One check of a kernel.
#[derive(Clone, Debug)]
pub struct KernelCheck {
    /// Short name.
    pub name: &'static str,
    /// What it holds, in words.
    pub claim: String,
    /// Holds, differs, or unverified.
    pub verdict: Verdict,
    /// How, with the numbers.
    pub note: String,
}

impl KernelCheck {
    fn new(name: &'static str, claim: &str, holds: Result<bool, String>, note: String) -> Self {
        let (verdict, note) = match holds {
            Ok(true) => (Verdict::Holds, note),
            Ok(false) => (Verdict::Differs, note),
            Err(why) => (Verdict::Unverified, format!("{note}{why}")),
        };
        KernelCheck {
            name,
            claim: claim.to_string(),
            verdict,
            note,
        }
    }
}

/// The Taylor coefficients c₀ … c_n of the rational function `e` of `x`
/// at x = 0, as exact atoms (coefficients may hold other symbols), by
/// dividing the power series of its numerator by its denominator's.
pub fn taylor(e: &Atom, n: u32) -> Result<Vec<Atom>, String> {
    let (num, den) = crate::sym::num_den(&simplify(e));
    let coeff = |p: &Atom, i: u32| poly_coeff(p, "x", i, "x_unused", 0);
    let b0 = coeff(&den, 0);
    if is_zero(&b0) {
        return Err("the denominator vanishes at x = 0".into());
    }
    let mut c: Vec<Atom> = Vec::new();
    for i in 0..=n {
        let mut acc = coeff(&num, i);
        for j in 1..=i {
            acc -= coeff(&den, j) * &c[(i - j) as usize];
        }
        c.push(simplify(&(acc / &b0)));
    }
    Ok(c)
}

/// `e` with kh = x (h = x/k) and e^{kh} replaced by its Taylor polynomial
/// of degree `degree` in x: a rational function of x whose Taylor
/// coefficients are exact up to x^(degree − 3) or better.
fn in_thinness(e: &Atom, degree: u32) -> Atom {
    simplify(&subs_all(
        e,
        &[("h", ex("x/k")), ("ekh", exp_polynomial("x", degree))],
    ))
}

/// The Taylor polynomial of e^t of degree `degree`, t = `arg`.
fn exp_polynomial(arg: &str, degree: u32) -> Atom {
    let t = ex(arg);
    let mut term = Atom::num(1);
    let mut poly = Atom::num(1);
    for n in 1..=i64::from(degree) {
        term = term * &t / Atom::num(n);
        poly += &term;
    }
    poly
}

/// The series of the thin incompressible layer: the Taylor coefficients
/// in kh of C·3Gk at ν = ½, up to (kh)⁹. The thin-layer law is
/// C·3Gk = (kh)³(1 + c₂(kh)² + c₄(kh)⁴ + c₆(kh)⁶ + …): the coefficients of
/// (kh)⁰ … (kh)² and of even powers vanish, that of (kh)³ is 1.
pub fn incompressible_series(kernel: &Atom) -> Result<Vec<Atom>, String> {
    let scaled = subs(kernel, "nu", &ex("1/2")) * ex("3*G*k");
    taylor(&in_thinness(&scaled, 14), 9)
}

/// Hold a candidate kernel (in `k`, `h`, `G`, `nu`, `ekh`) to every check
/// of the module docs. A kernel fails where any check differs.
pub fn check_kernel(kernel: &Atom) -> Vec<KernelCheck> {
    let mut out = Vec::new();
    // 1. the literature's printed form
    let c = compare(
        &literature_kernel(),
        kernel,
        crate::check::seed("layer.kernel"),
    );
    out.push(KernelCheck::new(
        "literature",
        "C = (1−ν)/(Gk) · ((3−4ν) sinh 2kh − 2kh) / ((3−4ν) cosh 2kh + 2(kh)² + 5 − 12ν + 8ν²)",
        match c.verdict {
            Verdict::Unverified => Err("could not be evaluated".into()),
            v => Ok(v == Verdict::Holds),
        },
        describe(&c),
    ));
    // 2. thin and incompressible: (kh)³(1 + c₂(kh)² + c₄(kh)⁴ + …)/(3Gk)
    let claim = "at ν = ½, C = h³k²/(3G)·(1 + c₂(kh)² + c₄(kh)⁴ + …): the thin-layer law w = −(h³/3G)∇²p behind (2) and (4)";
    out.push(match incompressible_series(kernel) {
        Ok(c) => {
            let vanish = |is: &[usize]| is.iter().all(|&i| is_zero(&c[i]));
            let below = vanish(&[0, 1, 2]);
            let leading = is_zero(&(&c[3] - &Atom::num(1)));
            let odd = vanish(&[4, 6, 8]);
            let note = if below {
                format!(
                    "C·3G/(h³k²) = {} + ({})(kh)² + ({})(kh)⁴ + ({})(kh)⁶ + …, odd powers {}",
                    c[3],
                    c[5],
                    c[7],
                    c[9],
                    if odd { "absent" } else { "present" }
                )
            } else {
                format!(
                    "C·3Gk starts below (kh)³: its coefficients of 1, kh, (kh)² are {}, {}, {}",
                    c[0], c[1], c[2]
                )
            };
            KernelCheck::new(
                "thin incompressible",
                claim,
                Ok(below && leading && odd),
                note,
            )
        }
        Err(why) => KernelCheck::new("thin incompressible", claim, Err(why), String::new()),
    });
    // 3. thick: the half-space's (1 − ν)/(Gk) as e^{kh} → ∞
    out.push(thick_limit(kernel));
    // 4. compressible and thin: the Winkler layer
    out.push(winkler_limit(kernel));
    // 5. the numerical route
    out.push(by_propagator(kernel));
    out
}

fn thick_limit(kernel: &Atom) -> KernelCheck {
    let claim = "as kh → ∞, C → (1 − ν)/(Gk), the half-space's";
    // C·Gk/(1−ν) is a rational function of e^{kh} whose coefficients are
    // polynomials in kh: its limit is the ratio of the leading coefficients
    // in e^{kh} of its numerator and denominator
    let (num, den) = crate::sym::num_den(&simplify(&(kernel * &ex("G*k/(1-nu)"))));
    let lead = |p: &Atom| -> Result<Atom, String> {
        let d = crate::sym::degree_in(p, "ekh", 40).ok_or("degree in e^{kh} above 40")?;
        Ok(poly_coeff(p, "ekh", d as u32, "x_unused", 0))
    };
    match (lead(&num), lead(&den)) {
        (Ok(a), Ok(b)) => {
            let limit = simplify(&(a / b));
            let holds = is_zero(&(&limit - &Atom::num(1)));
            KernelCheck::new("thick", claim, Ok(holds), format!("C·Gk/(1−ν) → {limit}"))
        }
        (Err(e), _) | (_, Err(e)) => KernelCheck::new("thick", claim, Err(e), String::new()),
    }
}

fn winkler_limit(kernel: &Atom) -> KernelCheck {
    let claim = "for ν < ½, as kh → 0, C → h(1 − 2ν)/(2G(1 − ν)), the Winkler layer (not (2))";
    let scaled = kernel * &ex("2*G*(1-nu)*k/((1-2*nu)*k*h)");
    match taylor(&in_thinness(&scaled, 8), 0) {
        Ok(c) => {
            let holds = is_zero(&(&c[0] - &Atom::num(1)));
            KernelCheck::new(
                "winkler",
                claim,
                Ok(holds),
                format!("C·2G(1−ν)/(h(1−2ν)) → {} as kh → 0", c[0]),
            )
        }
        Err(why) => KernelCheck::new("winkler", claim, Err(why), String::new()),
    }
}

/// The kernel's C·G·k at (kh, ν), to 30 digits.
pub fn kernel_value(kernel: &Atom, kh: f64, nu: f64) -> Result<f64, String> {
    let r = |x: f64| crate::sym::rat((x * 1e6).round() as i64, 1_000_000);
    let point = [
        ("k", Atom::num(1)),
        ("G", Atom::num(1)),
        ("h", r(kh)),
        ("nu", r(nu)),
        ("ekh", ex(&format!("exp({})", r(kh)))),
    ];
    crate::sym::eval_prec(kernel, &point, 30)
}

fn by_propagator(kernel: &Atom) -> KernelCheck {
    let claim = "the state vector carried across the layer gives the same C";
    let mut worst: (f64, f64, f64) = (0.0, 0.0, 0.0);
    for &(kh, nu) in &ROUTE_POINTS {
        let Some(route) = propagated_compliance(kh, nu) else {
            return KernelCheck::new(
                "propagator",
                claim,
                Err(format!("the propagator failed at kh = {kh}, ν = {nu}")),
                String::new(),
            );
        };
        let value = match kernel_value(kernel, kh, nu) {
            Ok(v) => v,
            Err(e) => return KernelCheck::new("propagator", claim, Err(e), String::new()),
        };
        let rel = (value - route).abs() / route.abs().max(1e-300);
        if rel >= worst.0 {
            worst = (rel, kh, nu);
        }
    }
    KernelCheck::new(
        "propagator",
        claim,
        Ok(worst.0 <= ROUTE_TOLERANCE),
        format!(
            "at {} points of kh in [{}, {}] and ν in [{}, {}], the largest relative difference is {:.1e} (kh = {}, ν = {}; tolerance {ROUTE_TOLERANCE:e})",
            ROUTE_POINTS.len(),
            range(ROUTE_POINTS.iter().map(|p| p.0)).0,
            range(ROUTE_POINTS.iter().map(|p| p.0)).1,
            range(ROUTE_POINTS.iter().map(|p| p.1)).0,
            range(ROUTE_POINTS.iter().map(|p| p.1)).1,
            worst.0,
            worst.1,
            worst.2
        ),
    )
}

/// The smallest and largest of `values`.
fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    })
}

/// The m of (4) from the kernel: two coatings (h1, G1) and (h2, G2) at
/// ν = ½ under one pressure add their compliances (frictionless interface),
/// and the sum's small-k series is k²/m + O(k⁴): m is 1 over the sum's
/// coefficient of k², taken from the kernel's Taylor series in k (whose
/// terms in k⁰ and k¹ must vanish: a pressure of long wavelength meets no
/// Winkler stiffness in an incompressible layer).
pub fn thin_layer_m(kernel: &Atom) -> Result<Atom, String> {
    let at_half = subs(kernel, "nu", &ex("1/2"));
    let mut k2 = Atom::num(0);
    for (h, g) in [("h1", "G1"), ("h2", "G2")] {
        let one = subs_all(&at_half, &[("h", ex(h)), ("G", ex(g))]);
        let c = taylor(&in_wavenumber(&one, h, 10), 2)?;
        if !is_zero(&c[0]) || !is_zero(&c[1]) {
            return Err(format!(
                "the kernel at ν = ½ has terms in k⁰ or k¹ ({}, {}): no thin-layer law",
                c[0], c[1]
            ));
        }
        k2 += &c[2];
    }
    Ok(simplify(&(Atom::num(1) / k2)))
}

/// `e` with k = x and e^{kh} replaced by its Taylor polynomial of degree
/// `degree` in x·`h`.
fn in_wavenumber(e: &Atom, h: &str, degree: u32) -> Atom {
    simplify(&subs_all(
        e,
        &[
            ("ekh", exp_polynomial(&format!("x*{h}"), degree)),
            ("k", ex("x")),
        ],
    ))
}

/// The m of (4) by the numerical route alone: C₁ + C₂ from
/// [`propagated_compliance`] at ν = ½, over k², at kh₁ = x, 2x, 4x, 8x
/// (x = 0.0025, kh₂ in proportion), extrapolated to k → 0 in three
/// Richardson steps in k². What is left is O(x⁸), about 3e-15 relative at
/// the coatings of [`crate::routes::layer_thin`] (two steps leave
/// 64 c₆ x⁶: 3e-7 at x = 0.02, where they were first tried); the
/// propagator itself is good to round-off at these kh
/// (derive/tests/layer_kernel.rs).
pub fn propagated_m(h1: f64, g1: f64, h2: f64, g2: f64) -> Option<f64> {
    let at = |x: f64| -> Option<f64> {
        let k = x / h1;
        let c = propagated_compliance(k * h1, 0.5)? / (g1 * k)
            + propagated_compliance(k * h2, 0.5)? / (g2 * k);
        Some(c / (k * k))
    };
    let mut column = [at(0.0025)?, at(0.005)?, at(0.01)?, at(0.02)?].to_vec();
    for step in 1..=3 {
        let w = 4f64.powi(step);
        column = column
            .windows(2)
            .map(|p| (w * p[0] - p[1]) / (w - 1.0))
            .collect();
    }
    Some(1.0 / column[0])
}

/// Φ(q; ν) = 1 − C·Gk/(1 − ν) at kh = q: the share of the half-space's
/// compliance that the rigid base takes away at wave number k, a rational
/// function of q, t = e^{−2q} and ν. Φ → 1 for long waves and → 0 for
/// short ones; the finite layer's compliance is the half-space's times
/// 1 − Φ. Computed this way it does not vanish by cancellation: its
/// numerator (3 − 4ν)t² + (2q² + 2q + 8ν² − 12ν + 5)t and denominator are
/// positive for t ≥ 0 and 0 ≤ ν ≤ ½ (8ν² − 12ν + 5 ≥ 1), and the
/// generator measures its error against its own value.
pub fn base_share(kernel: &Atom) -> Atom {
    let scaled = simplify(&(kernel * &ex("G*k/(1-nu)")));
    let in_q = subs_all(&scaled, &[("h", ex("q/k")), ("ekh", ex("t^(-1/2)"))]);
    simplify(&(Atom::num(1) - in_q))
}

/// The section of docs/codegen-accuracy.md for the generated module, with
/// the worst relative error its check measured.
pub fn accuracy_section(worst: f64) -> String {
    let span = |name: &str| {
        let values = ACCURACY_DOMAIN
            .iter()
            .find(|(n, _)| *n == name)
            .map_or(&[][..], |(_, v)| *v);
        range(values.iter().copied())
    };
    let ((q0, q1), (t0, t1), (n0, n1)) = (span("q"), span("t"), span("nu"));
    format!(
        "\n## The layer's kernel (`{MODULE}`)\n\nΦ(q; ν) of the layer of finite thickness (docs/derivation.md, Step 0), a rational function of q = kh, t = e^{{−2q}} and ν, checked at q and t independently (q from {q0} to {q1}, t from {t0} to {t1}) and ν from {n0} to {n1}.\n\n| function | form | error measured against | worst relative error |\n|---|---|---|---|\n| `base_share` | as derived | the value | {worst:.1e} |\n"
    )
}

/// The generated module's name (`solver/src/generated/layer_kernel.rs`).
pub const MODULE: &str = "layer_kernel";

/// The sample points of the generator's accuracy check of
/// [`base_share`]: q and t independently (the function is checked as a
/// rational function of both), ν across [0, ½].
const ACCURACY_DOMAIN: [(&str, &[f64]); 3] = [
    ("q", &[0.0, 1e-3, 0.3, 1.0, 3.0, 10.0, 40.0]),
    ("t", &[1.0, 0.998, 0.55, 0.135, 2.5e-3, 2e-9, 1.8e-35, 0.0]),
    ("nu", &[0.0, 0.3, 0.45, 0.5]),
];

/// `solver/src/generated/layer_kernel.rs` (the kernel's Φ as Rust, checked
/// by the generator against 192- and 384-bit arithmetic) and the worst
/// relative error that check measured.
pub fn module_source() -> Result<(String, f64), String> {
    let kernel = kernel()?;
    let phi = base_share(&kernel.compliance);
    let worst = crate::accuracy::check_scaled(
        "base_share",
        &["q", "t", "nu"],
        std::slice::from_ref(&phi),
        &ACCURACY_DOMAIN,
        None,
        crate::accuracy::Scale::Value,
    )
    .map_err(|failures| {
        let at: Vec<String> = failures
            .iter()
            .map(|f| format!("at {:?}: {}", f.point, f.what))
            .collect();
        format!(
            "the generated base_share fails its accuracy check {}",
            at.join("; ")
        )
    })?;
    let item = crate::codegen::plain_function(
        "base_share",
        "Φ(q; ν) = 1 − C(k)·Gk/(1 − ν) at q = kh with t = e^{−2q}: the share of the half-space's compliance (1 − ν)/(Gk) that the rigid base of a layer of thickness h takes away at wave number k (the layer's compliance C is the half-space's times 1 − Φ). Derived from three-dimensional elasticity (docs/derivation.md, Step 0); its numerator and denominator are positive for t ≥ 0 and 0 ≤ ν ≤ ½, and its error is measured against its own value (docs/codegen-accuracy.md).",
        vec!["q", "t", "nu"],
        vec![phi],
    )?;
    let file = quote::quote! {
        #item
        /// [`base_share`] at q = kh, with t = e^{−2q} computed here.
        #[inline]
        pub fn base_share_at(q: f64, nu: f64) -> f64 {
            base_share(q, (-2.0 * q).exp(), nu)
        }
    };
    let ast: syn::File = syn::parse2(file)
        .map_err(|e| format!("generated layer_kernel module does not parse: {e}"))?;
    Ok((
        format!(
            "//! @generated by `cargo run --release -p thinjkr-derive -- generate`; do not edit.\n//!\n//! The kernel of the layer of finite thickness (an elastic coating bonded to a rigid base,\n//! frictionless top): derived and checked by `thinjkr_derive::layer` (docs/derivation.md, Step 0).\n//! The paper's coatings are transversely isotropic with out-of-plane shear modulus G′; the layer\n//! here is isotropic, and G′ is read as its G.\n\n{}",
            prettyplease::unparse(&ast)
        ),
        worst,
    ))
}
