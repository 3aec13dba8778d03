//! The conformal family `conformal:K`: contact domains that are images of
//! the unit disk under a polynomial map w(ζ) = Σ c_k ζ^(n_k) (the map's
//! powers are data, [`ConformalAnsatz::powers`]), the pressure as a
//! particular solution of (2) plus the harmonic correction that makes it
//! vanish on the contour exactly, and the energy (Ritz) closure of (3)₂.
//!
//! In the units (17) the thin-layer equation (2) reads Δp̄ = φ̄ − δ̄ with
//! φ̄ = X²/2 + Y²/(2ρ) (the gap (1) scaled: see `nondimensional`), and the
//! total potential energy of the energy closure is
//! Π̄ = ½∫ω p̄ (δ̄ − φ̄) dA − ½|ω| (as `energy` derives for the ellipse; the
//! constant factors are checked there against the dimensional U − Δγ|ω|).
//! With X + iY = w(ζ), on |ζ| = 1 every polynomial in (X, Y) is a Laurent
//! polynomial in ζ (ζ̄ = 1/ζ), so its harmonic extension is a polynomial in
//! ζ and ζ̄: the term κ ζ^a ζ̄^b of P becomes κ (ζ^a ζ̄^b − ζ^(a−m) ζ̄^(b−m)),
//! m = min(a, b), in p̄ = P + h. Integrals over ω are integrals over the disk
//! with the Jacobian |w′|², and ∫ ζ^j ζ̄^k dA = π/(j + 1) δ_jk, so Π̄/π is a
//! polynomial in (c, δ̄, μ = 1/ρ) with rational coefficients, computed here
//! exactly with symbolica's polynomials.
//!
//! Every step is checked as it is taken: P solves (2) (its Laplacian is
//! φ̄ − δ̄); p̄ vanishes on |ζ| = 1; 4∂ζ∂ζ̄ p̄ = (φ̄ − δ̄)|w′|² inside (so (2)
//! holds on ω); the boundary slope is a real trigonometric polynomial; and
//! ∂Π̄/∂δ̄ equals F̄ = ∫ω p̄ dA computed separately (the force identity).
//!
//! Owns: [`ConformalAnsatz`] (the data of one member) and its derivation.
//! May use: `sym`, symbolica's polynomials.

use crate::sym::{diff, ex, is_zero, subs_all};
use std::collections::BTreeMap;
use std::sync::Arc;
use symbolica::atom::{Atom, AtomCore};
use symbolica::domains::rational::{Rational, RationalField, Q};
use symbolica::domains::Ring;
use symbolica::poly::polynomial::MultivariatePolynomial;
use symbolica::poly::PolyVariable;

/// A polynomial with rational coefficients in the derivation's variables.
pub type Poly = MultivariatePolynomial<RationalField, u16>;

/// One member of a contour family given by a polynomial map of the unit
/// disk and the pressure built on it, as data (read from a family's data
/// file by [`crate::family`]).
#[derive(Clone, Debug, PartialEq)]
pub struct ConformalAnsatz {
    /// The family's name; a member is `family:K`.
    pub family: String,
    /// The number of map coefficients K.
    pub terms: usize,
    /// One line for reports.
    pub title: String,
    /// The particular solution P(X, Y) of Δp̄ = φ̄ − δ̄, in the symbols `X`,
    /// `Y`, `dbar` and `mu` = 1/ρ (symbolica syntax).
    pub particular: String,
    /// The scaled gap φ̄(X, Y) (symbolica syntax, same symbols).
    pub gap: String,
    /// The powers of ζ in the map, at least `terms` of them: member K
    /// takes the first K.
    pub family_powers: Vec<u16>,
}

impl ConformalAnsatz {
    /// The powers of ζ in the map: the first K of the family's (for
    /// `conformal`, the odd powers 1, 3, …, 2K − 1: the map is odd and
    /// real, so the domain has both symmetries of the problem, about X = 0
    /// and about Y = 0).
    pub fn powers(&self) -> Vec<u16> {
        self.family_powers
            .iter()
            .take(self.terms)
            .copied()
            .collect()
    }

    /// The member's name, `family:K`.
    pub fn name(&self) -> String {
        format!("{}:{}", self.family, self.terms)
    }

    /// The names of the unknowns: the map coefficients c1 … cK.
    pub fn coefficient_names(&self) -> Vec<String> {
        (1..=self.terms).map(|k| format!("c{k}")).collect()
    }
}

/// The largest K a family may generate: the packed tables hold the
/// exponents of at most eight map coefficients.
pub const MAX_TERMS: usize = 8;

/// Everything derived for one member of the family.
#[derive(Clone, Debug)]
pub struct ConformalDerivation {
    /// The ansatz.
    pub ansatz: ConformalAnsatz,
    /// Π̄/π as a polynomial in (c1 … cK, dbar, mu) (the other variables
    /// have exponent 0).
    pub potential: Poly,
    /// F̄/π = ∫ω p̄ dA/π (equal to ∂(Π̄/π)/∂δ̄, checked).
    pub force: Poly,
    /// The boundary slope ∂p̄/∂r at |ζ| = 1 as Σ_n g_n cos(nθ): (n, g_n).
    /// ∂p̄/∂ν = g/|w′(e^{iθ})| on the contour, in units of √(2mΔγ).
    pub boundary_slope: Vec<(u16, Poly)>,
}

/// Variable layout of the derivation's polynomials.
struct Layout {
    terms: usize,
    vars: Arc<Vec<PolyVariable>>,
}

impl Layout {
    fn new(terms: usize) -> Layout {
        let mut names = vec!["z".to_string(), "zb".to_string()];
        names.extend((1..=terms).map(|k| format!("c{k}")));
        names.extend(["dbar", "mu", "I"].map(String::from));
        let vars = names
            .iter()
            .map(|n| PolyVariable::Symbol(symbolica::symbol!(n.as_str())))
            .collect();
        Layout {
            terms,
            vars: Arc::new(vars),
        }
    }
    const Z: usize = 0;
    const ZB: usize = 1;
    fn c(&self, k: usize) -> usize {
        2 + k
    }
    fn dbar(&self) -> usize {
        2 + self.terms
    }
    fn i(&self) -> usize {
        4 + self.terms
    }
    fn poly(&self, a: &Atom) -> Poly {
        a.to_polynomial(&Q, Some(self.vars.clone()))
    }
}

/// The monomials of a particular solution P(X, Y; μ, δ̄) as the exact
/// solver reads them (`thinjkr::exact::gap::Term`): `[x, y, mu, dbar, num,
/// den]` for c·X^x·Y^y·μ^mu·δ̄^dbar with c = num/den, in the polynomial's
/// order. Refused: powers that are odd in X or Y or above 24, δ̄ above the
/// first power, and a coefficient that does not fit 64-bit integers.
pub fn particular_terms(particular: &str) -> Result<Vec<[i64; 6]>, String> {
    let vars: Vec<PolyVariable> = ["X", "Y", "mu", "dbar"]
        .iter()
        .map(|n| PolyVariable::Symbol(symbolica::symbol!(*n)))
        .collect();
    let p: Poly = ex(particular)
        .expand()
        .to_polynomial(&Q, Some(Arc::new(vars)));
    let mut out = Vec::new();
    for (e, c) in terms_of(&p) {
        if e[0] % 2 == 1 || e[1] % 2 == 1 || e[0] > 24 || e[1] > 24 || e[3] > 1 || e[2] > 24 {
            return Err(format!(
                "the particular solution's term X^{} Y^{} mu^{} dbar^{} is not even in X and Y with degree at most 24 and linear in dbar",
                e[0], e[1], e[2], e[3]
            ));
        }
        let text = c.to_string();
        let (num, den) = text.split_once('/').unwrap_or((text.as_str(), "1"));
        let (num, den) = match (num.trim().parse::<i64>(), den.trim().parse::<i64>()) {
            (Ok(n), Ok(d)) if d > 0 => (n, d),
            _ => {
                return Err(format!(
                    "the coefficient {text} does not fit 64-bit integers"
                ))
            }
        };
        out.push([e[0] as i64, e[1] as i64, e[2] as i64, e[3] as i64, num, den]);
    }
    Ok(out)
}

/// Build a polynomial from (exponents, coefficient) pairs, like terms added.
fn from_terms(like: &Poly, terms: impl IntoIterator<Item = (Vec<u16>, Rational)>) -> Poly {
    let mut out = like.zero();
    for (e, c) in terms {
        if !Q.is_zero(&c) {
            out.append_monomial(c, &e);
        }
    }
    out
}

fn terms_of(p: &Poly) -> impl Iterator<Item = (Vec<u16>, Rational)> + '_ {
    p.into_iter()
        .map(|t| (t.exponents.to_vec(), t.coefficient.clone()))
}

/// ∂p/∂(variable `v`), term by term.
pub fn derivative(p: &Poly, v: usize) -> Poly {
    from_terms(
        p,
        terms_of(p).filter(|(e, _)| e[v] > 0).map(|(mut e, c)| {
            let k = Rational::from((e[v] as i64, 1i64));
            e[v] -= 1;
            (e, &c * &k)
        }),
    )
}

/// Replace I² by −1 (I stands for the imaginary unit); fails on an odd
/// power of I, which would make the polynomial not real.
fn real_part(p: &Poly, l: &Layout) -> Result<Poly, String> {
    let mut out = Vec::new();
    for (mut e, c) in terms_of(p) {
        let k = e[l.i()];
        if k % 2 == 1 {
            return Err("the particular solution or the gap is not even in Y".into());
        }
        e[l.i()] = 0;
        out.push((
            e,
            if k % 4 == 2 {
                &c * &Rational::from((-1i64, 1i64))
            } else {
                c
            },
        ));
    }
    Ok(from_terms(p, out))
}

/// The harmonic correction: each κ ζ^a ζ̄^b becomes κ (ζ^a ζ̄^b − ζ^(a−m) ζ̄^(b−m)).
fn minus_harmonic_extension(p: &Poly) -> Poly {
    let mut out = Vec::new();
    for (e, c) in terms_of(p) {
        let m = e[Layout::Z].min(e[Layout::ZB]);
        if m == 0 {
            continue; // harmonic already: cancelled by its own extension
        }
        let mut f = e.clone();
        f[Layout::Z] -= m;
        f[Layout::ZB] -= m;
        out.push((e, c.clone()));
        out.push((f, &c * &Rational::from((-1i64, 1i64))));
    }
    from_terms(p, out)
}

/// The values on |ζ| = 1 (ζ̄ = 1/ζ) as a Laurent polynomial: each term
/// moved to ζ^(a−m) ζ̄^(b−m).
fn on_unit_circle(p: &Poly) -> Poly {
    from_terms(
        p,
        terms_of(p).map(|(mut e, c)| {
            let m = e[Layout::Z].min(e[Layout::ZB]);
            e[Layout::Z] -= m;
            e[Layout::ZB] -= m;
            (e, c)
        }),
    )
}

/// ∫ over the unit disk, divided by π: ζ^a ζ̄^a integrates to 1/(a + 1).
fn disk_integral(p: &Poly) -> Poly {
    from_terms(
        p,
        terms_of(p)
            .filter(|(e, _)| e[Layout::Z] == e[Layout::ZB])
            .map(|(mut e, c)| {
                let w = Rational::from((1i64, e[Layout::Z] as i64 + 1));
                e[Layout::Z] = 0;
                e[Layout::ZB] = 0;
                (e, &c * &w)
            }),
    )
}

/// Split by the exponents of (ζ, ζ̄): the coefficient polynomials.
fn by_zeta(p: &Poly) -> BTreeMap<(u16, u16), Poly> {
    let mut groups: BTreeMap<(u16, u16), Vec<(Vec<u16>, Rational)>> = BTreeMap::new();
    for (mut e, c) in terms_of(p) {
        let key = (e[Layout::Z], e[Layout::ZB]);
        e[Layout::Z] = 0;
        e[Layout::ZB] = 0;
        groups.entry(key).or_default().push((e, c));
    }
    groups
        .into_iter()
        .map(|(k, v)| (k, from_terms(p, v)))
        .collect()
}

/// ∫ over the disk of the product p·q, divided by π, without forming the
/// product's off-diagonal terms.
fn disk_integral_of_product(p: &Poly, q: &Poly) -> Poly {
    let (gp, gq) = (by_zeta(p), by_zeta(q));
    let mut by_shift: BTreeMap<i32, Vec<(&(u16, u16), &Poly)>> = BTreeMap::new();
    for (k, v) in &gq {
        by_shift
            .entry(k.0 as i32 - k.1 as i32)
            .or_default()
            .push((k, v));
    }
    let mut total = p.zero();
    for ((a, b), pp) in &gp {
        let Some(partners) = by_shift.get(&(*b as i32 - *a as i32)) else {
            continue;
        };
        for ((a2, _), qq) in partners {
            let w = Rational::from((1i64, (*a + *a2) as i64 + 1));
            let prod = pp * *qq;
            let scaled = from_terms(&prod, terms_of(&prod).map(|(e, c)| (e, &c * &w)));
            total = &total + &scaled;
        }
    }
    total
}

/// Derive Π̄, F̄ and the boundary slope for one member of the family.
pub fn derive(ansatz: &ConformalAnsatz) -> Result<ConformalDerivation, String> {
    if ansatz.terms == 0 || ansatz.terms > 16 {
        return Err(format!("K = {} is outside 1..=16", ansatz.terms));
    }
    let l = Layout::new(ansatz.terms);
    if ansatz.family_powers.len() < ansatz.terms {
        return Err(format!(
            "K = {} needs {} powers of the map, the family has {}",
            ansatz.terms,
            ansatz.terms,
            ansatz.family_powers.len()
        ));
    }
    let particular = ex(&ansatz.particular);
    let gap = ex(&ansatz.gap);
    // (2) for the particular solution: ΔP = φ̄ − δ̄.
    let lap = diff(&diff(&particular, "X"), "X") + diff(&diff(&particular, "Y"), "Y");
    if !is_zero(&(lap - &gap + ex("dbar"))) {
        return Err("the particular solution does not satisfy Δp = φ − δ (2)".into());
    }
    let powers = ansatz.powers();
    let w = powers
        .iter()
        .enumerate()
        .map(|(k, n)| ex(&format!("c{}*z^{n}", k + 1)))
        .fold(Atom::num(0), |a, t| a + t);
    let wb = subs_all(&w, &[("z", ex("zb"))]);
    let dw = diff(&w, "z");
    let dwb = diff(&wb, "zb");
    // X = (w + w̄)/2, Y = (w − w̄)/(2i) = I (w̄ − w)/2 with I² = −1.
    let to_zeta = |e: &Atom| -> Result<Poly, String> {
        let s = subs_all(
            e,
            &[
                ("X", (&w + &wb) * ex("1/2")),
                ("Y", ex("I") * (&wb - &w) * ex("1/2")),
            ],
        );
        real_part(&l.poly(&s.expand()), &l)
    };
    let p_particular = to_zeta(&particular)?;
    let jacobian = l.poly(&(&dw * &dwb).expand()); // |w′|²
    let pressure = minus_harmonic_extension(&p_particular);
    // p̄ = 0 on the contour.
    if !on_unit_circle(&pressure).is_zero() {
        return Err("the pressure does not vanish on |ζ| = 1".into());
    }
    // (2) inside: 4 ∂ζ∂ζ̄ p̄ = (φ̄ − δ̄)|w′|².
    let source = &(&to_zeta(&gap)? - &l.poly(&ex("dbar"))) * &jacobian;
    let lap_zeta = derivative(&derivative(&pressure, Layout::Z), Layout::ZB);
    let four = from_terms(
        &lap_zeta,
        terms_of(&lap_zeta).map(|(e, c)| (e, &c * &Rational::from((4i64, 1i64)))),
    );
    if !(&four - &source).is_zero() {
        return Err("the pressure does not satisfy (2) inside the disk".into());
    }
    // Π̄/π = ½∫ p̄ (δ̄ − φ̄)|w′|² − ½∫|w′|².
    let work = &(&l.poly(&ex("dbar")) - &to_zeta(&gap)?) * &jacobian;
    let half = Rational::from((1i64, 2i64));
    let scale = |p: &Poly, k: &Rational| from_terms(p, terms_of(p).map(|(e, c)| (e, &c * k)));
    let potential = scale(
        &(&disk_integral_of_product(&pressure, &work) - &disk_integral(&jacobian)),
        &half,
    );
    let force = disk_integral_of_product(&pressure, &jacobian);
    if !(&derivative(&potential, l.dbar()) - &force).is_zero() {
        return Err("∂Π̄/∂δ̄ differs from ∫p̄ dA: the force identity fails".into());
    }
    // ∂p̄/∂r at r = 1: κ ζ^a ζ̄^b (with its correction) gives 2m κ e^{i(a−b)θ}.
    let mut shifts: BTreeMap<i32, Vec<(Vec<u16>, Rational)>> = BTreeMap::new();
    for (mut e, c) in terms_of(&p_particular) {
        let m = e[Layout::Z].min(e[Layout::ZB]);
        if m == 0 {
            continue;
        }
        let d = e[Layout::Z] as i32 - e[Layout::ZB] as i32;
        e[Layout::Z] = 0;
        e[Layout::ZB] = 0;
        shifts
            .entry(d)
            .or_default()
            .push((e, &c * &Rational::from((2 * m as i64, 1i64))));
    }
    let shifted: BTreeMap<i32, Poly> = shifts
        .into_iter()
        .map(|(d, v)| (d, from_terms(&pressure, v)))
        .collect();
    let mut boundary_slope = Vec::new();
    for (d, g) in &shifted {
        if *d < 0 {
            continue;
        }
        if *d == 0 {
            boundary_slope.push((0u16, g.clone()));
            continue;
        }
        let mirror = shifted.get(&-d).cloned().unwrap_or_else(|| pressure.zero());
        if !(g - &mirror).is_zero() {
            return Err(format!(
                "the boundary slope is not a real cosine series (mode {d})"
            ));
        }
        boundary_slope.push((*d as u16, scale(g, &Rational::from((2i64, 1i64)))));
    }
    Ok(ConformalDerivation {
        ansatz: ansatz.clone(),
        potential,
        force,
        boundary_slope,
    })
}

impl ConformalDerivation {
    /// The index of c_k (k from 0) and of δ̄ in the polynomials' exponents.
    pub fn layout(&self) -> (Vec<usize>, usize, usize) {
        let l = Layout::new(self.ansatz.terms);
        (
            (0..self.ansatz.terms).map(|k| l.c(k)).collect(),
            l.dbar(),
            l.dbar() + 1,
        )
    }

    /// Π̄/π as a symbolica expression.
    pub fn potential_atom(&self) -> Atom {
        self.potential.to_expression()
    }

    /// The number of monomials of Π̄ and of the upper triangle of its
    /// Hessian in (c, δ̄).
    pub fn sizes(&self) -> (usize, usize) {
        let (cs, d, _) = self.layout();
        let unknowns: Vec<usize> = cs.into_iter().chain([d]).collect();
        let mut hess = 0;
        for (i, &vi) in unknowns.iter().enumerate() {
            let gi = derivative(&self.potential, vi);
            for &vj in &unknowns[i..] {
                hess += derivative(&gi, vj).nterms();
            }
        }
        (self.potential.nterms(), hess)
    }

    /// The degrees of Π̄: in c (total), in δ̄ and in μ.
    pub fn degrees(&self) -> (u32, u32, u32) {
        let (cs, d, mu) = self.layout();
        let mut out = (0, 0, 0);
        for t in self.potential.into_iter() {
            let e = t.exponents;
            let in_c: u32 = cs.iter().map(|&v| e[v] as u32).sum();
            out = (
                out.0.max(in_c),
                out.1.max(e[d] as u32),
                out.2.max(e[mu] as u32),
            );
        }
        out
    }
}

impl ConformalDerivation {
    /// ∂Π̄/∂(unknown i) as a polynomial (i < K: c_{i+1}; i = K: δ̄), Π̄
    /// including its factor π (returned as Π̄/π: multiply by π).
    pub fn potential_derivative(&self, unknowns: &[usize]) -> Poly {
        let (cs, d, _) = self.layout();
        unknowns.iter().fold(self.potential.clone(), |p, &i| {
            derivative(&p, if i < cs.len() { cs[i] } else { d })
        })
    }

    /// A polynomial of this derivation evaluated at (c, δ̄, μ) given as
    /// f64 (taken exactly) in 256-bit binary floating point, rounded to
    /// f64 at the end; with `times_pi` multiplied by π first. Also returns
    /// the sum of the terms' magnitudes (the scale against which cancellation
    /// is judged).
    pub fn evaluate_high_precision(
        &self,
        p: &Poly,
        c: &[f64],
        dbar: f64,
        mu: f64,
        times_pi: bool,
    ) -> Result<(f64, f64), String> {
        use astro_float::{BigFloat, Consts, Radix, RoundingMode};
        let prec = 256;
        let rm = RoundingMode::ToEven;
        let mut cc = Consts::new().map_err(|e| format!("{e:?}"))?;
        let (cs, d, m) = self.layout();
        let mut total = BigFloat::from_i64(0, prec);
        let mut magnitude = BigFloat::from_i64(0, prec);
        for t in p.into_iter() {
            let num = BigFloat::parse(
                &t.coefficient.numerator().to_string(),
                Radix::Dec,
                prec,
                rm,
                &mut cc,
            );
            let den = BigFloat::parse(
                &t.coefficient.denominator().to_string(),
                Radix::Dec,
                prec,
                rm,
                &mut cc,
            );
            let mut v = num.div(&den, prec, rm);
            let pow = |x: f64, e: u16| BigFloat::from_f64(x, prec).powi(e as usize, prec, rm);
            for (k, &i) in cs.iter().enumerate() {
                v = v.mul(&pow(c[k], t.exponents[i]), prec, rm);
            }
            v = v.mul(&pow(dbar, t.exponents[d]), prec, rm);
            v = v.mul(&pow(mu, t.exponents[m]), prec, rm);
            magnitude = magnitude.add(&v.abs(), prec, rm);
            total = total.add(&v, prec, rm);
        }
        if times_pi {
            let pi = cc.pi(prec, rm);
            total = total.mul(&pi, prec, rm);
            magnitude = magnitude.mul(&pi, prec, rm);
        }
        let f = |x: &BigFloat| x.to_string().parse::<f64>().map_err(|e| e.to_string());
        Ok((f(&total)?, f(&magnitude)?))
    }
}
