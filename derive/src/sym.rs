//! Thin helpers over symbolica's public API: parsing, substitution, rational
//! normal forms, linear solving, square roots of factored expressions, LaTeX
//! and high-precision numeric evaluation.
//!
//! Owns: every direct call into symbolica that the derivation needs, so that
//! the derivation modules read like the paper. May use: symbolica only.
//!
//! Everything here runs on the calling thread. symbolica, unlicensed, allows
//! one thread per user at a time; nothing in this crate spawns threads.

use symbolica::atom::{Atom, AtomCore, AtomView};
use symbolica::printer::PrintOptions;

/// Parse an expression written in symbolica's input syntax.
pub fn ex(s: &str) -> Atom {
    symbolica::parse!(s)
}

/// Parse an expression written in symbolica's input syntax, or say why it
/// does not parse (for expressions read from data files).
pub fn try_ex(s: &str) -> Result<Atom, String> {
    symbolica::try_parse!(s).map_err(|e| e.to_string())
}

/// A plain symbol as an atom.
pub fn var(name: &str) -> Atom {
    Atom::var(symbolica::symbol!(name))
}

/// An exact rational number as an atom.
pub fn rat(num: i64, den: i64) -> Atom {
    ex(&format!("({num})/({den})"))
}

/// Replace every occurrence of symbol `name` by `value`.
pub fn subs(e: &Atom, name: &str, value: &Atom) -> Atom {
    e.replace(var(name)).with(value.clone())
}

/// Apply several substitutions in order (each sees the result of the previous).
pub fn subs_all(e: &Atom, rules: &[(&str, Atom)]) -> Atom {
    rules.iter().fold(e.clone(), |acc, (n, v)| subs(&acc, n, v))
}

/// Derivative with respect to the symbol `name`.
pub fn diff(e: &Atom, name: &str) -> Atom {
    e.derivative(symbolica::symbol!(name))
}

/// Rational normal form: one fraction with cancelled gcd. Radicals such as
/// `(1+s+s^2)^(3/2)` are treated as independent variables.
pub fn simplify(e: &Atom) -> Atom {
    e.together()
}

/// `true` when `e` is identically zero as a rational function (radicals being
/// independent variables after their integer powers are merged).
pub fn is_zero(e: &Atom) -> bool {
    let t = e.expand().together();
    t.is_zero() || numerator(&t).expand().is_zero()
}

/// Split a product into (numerator, denominator) by the sign of exponents.
pub fn num_den(e: &Atom) -> (Atom, Atom) {
    let t = e.together();
    let mut num = Atom::num(1);
    let mut den = Atom::num(1);
    let mut take = |f: AtomView<'_>| match f {
        AtomView::Pow(p) => {
            let (b, x) = p.get_base_exp();
            let xs = x.to_owned().to_string();
            if xs.starts_with('-') {
                den = &den * &b.to_owned().pow(-x.to_owned());
            } else {
                num = &num * &f.to_owned();
            }
        }
        AtomView::Num(n) => {
            let s = n.as_view().to_owned().to_string();
            if let Some((a, b)) = s.split_once('/') {
                num = &num * &ex(a);
                den = &den * &ex(b);
            } else {
                num = &num * &f.to_owned();
            }
        }
        _ => num = &num * &f.to_owned(),
    };
    match t.as_view() {
        AtomView::Mul(m) => m.iter().for_each(&mut take),
        v => take(v),
    }
    (num, den)
}

/// Numerator of the rational normal form.
pub fn numerator(e: &Atom) -> Atom {
    num_den(e).0
}

/// Polynomial degree of `e` (after `expand`) in the symbol `name`, found by
/// repeated differentiation; `None` if it exceeds `max`.
pub fn degree_in(e: &Atom, name: &str, max: usize) -> Option<usize> {
    let mut d = e.expand();
    for k in 0..=max {
        if is_zero(&d) {
            return Some(k.saturating_sub(1));
        }
        d = diff(&d, name);
    }
    None
}

/// Solve `eq = 0` for the symbol `name`, in which it must be linear after
/// clearing denominators. Returns `None` when it is not linear or its
/// coefficient vanishes.
pub fn solve_linear(eq: &Atom, name: &str) -> Option<Atom> {
    let n = numerator(eq).expand();
    let c1 = diff(&n, name);
    if !is_zero(&diff(&c1, name)) || is_zero(&c1) {
        return None;
    }
    let c0 = subs(&n, name, &Atom::num(0));
    Some(simplify(&(-c0 / c1)))
}

/// Coefficient of `x^i y^j` in a polynomial in the symbols `x`, `y`.
pub fn poly_coeff(e: &Atom, x: &str, i: u32, y: &str, j: u32) -> Atom {
    let mut d = e.expand();
    for _ in 0..i {
        d = diff(&d, x);
    }
    for _ in 0..j {
        d = diff(&d, y);
    }
    let at0 = subs_all(&d, &[(x, Atom::num(0)), (y, Atom::num(0))]);
    let fact = |k: u32| (1..=k as i64).product::<i64>();
    simplify(&(at0 / Atom::num(fact(i) * fact(j))))
}

/// Square root of an expression known to be positive on the domain of
/// interest, taken factor by factor of its factorisation, so that perfect
/// squares leave the radical: `sqrt(4 (1+s+s^2) / (3 s^2))` becomes
/// `2 (1+s+s^2)^(1/2) / (3^(1/2) s)`. Every symbol is assumed positive; a
/// negative overall constant is moved into a sum factor of odd power.
pub fn sqrt_pos(e: &Atom) -> Atom {
    let (num, den) = num_den(e);
    let half = rat(1, 2);
    let root_of = |x: &Atom| -> Atom {
        let f = x.factor();
        let mut factors: Vec<(Atom, Atom)> = Vec::new();
        let mut constant = Atom::num(1);
        let mut push = |v: AtomView<'_>| match v {
            AtomView::Num(_) => constant = &constant * &v.to_owned(),
            AtomView::Pow(p) => {
                let (b, x) = p.get_base_exp();
                factors.push((b.to_owned(), x.to_owned()));
            }
            other => factors.push((other.to_owned(), Atom::num(1))),
        };
        match f.as_view() {
            AtomView::Mul(m) => m.iter().for_each(&mut push),
            v => push(v),
        }
        if constant.to_string().starts_with('-') {
            if let Some(k) = factors.iter().position(|(b, x)| {
                matches!(b.as_view(), AtomView::Add(_))
                    && ["1", "3", "5"].contains(&x.to_string().as_str())
            }) {
                constant = -constant;
                factors[k].0 = (-factors[k].0.clone()).expand();
            }
        }
        factors.iter().fold(constant.pow(&half), |acc, (b, x)| {
            &acc * &b.pow(&(x * &half))
        })
    };
    normalize_radicals(&(root_of(&num) / root_of(&den)))
}

/// LaTeX rendering by symbolica's printer.
pub fn latex(e: &Atom) -> String {
    e.printer(PrintOptions::latex()).to_string()
}

/// Plain (symbolica syntax) rendering.
pub fn plain(e: &Atom) -> String {
    e.to_string()
}

/// Evaluate `e` at exact rational values of its symbols, then to `digits`
/// decimal digits. Returns the value as `f64` (the cancellation, if any, has
/// happened at `digits` digits) or an error when symbols remain.
pub fn eval_prec(e: &Atom, point: &[(&str, Atom)], digits: u32) -> Result<f64, String> {
    let floats: Vec<(&str, Atom)> = point
        .iter()
        .map(|(n, v)| (*n, v.to_float(digits + 10)))
        .collect();
    let v = subs_all(e, &floats).to_float(digits);
    match v.as_view() {
        AtomView::Num(n) => {
            let c = n.get_coeff_view().to_float(4 * digits + 16)?;
            Ok(symbolica::prelude::RealLike::to_f64(&c.re))
        }
        _ => Err(format!("not a number after substitution: {v}")),
    }
}

/// Normalise radicals under the assumption that every symbol is positive:
/// `(x^6 y^-2)^(1/2)` becomes `x^3 y^-1`, and rational bases of fractional
/// powers are split into prime powers (`12^(1/3)` becomes `2^(2/3) 3^(1/3)`,
/// `(1/3)^(1/2)` becomes `3^(-1/2)`), so that symbolica's product
/// normalisation can merge them. Functions are left untouched.
pub fn normalize_radicals(e: &Atom) -> Atom {
    rebuild(e.as_view())
}

fn rebuild(v: AtomView<'_>) -> Atom {
    match v {
        AtomView::Add(a) => a.iter().fold(Atom::num(0), |acc, t| &acc + &rebuild(t)),
        AtomView::Mul(m) => m.iter().fold(Atom::num(1), |acc, t| &acc * &rebuild(t)),
        AtomView::Pow(p) => {
            let (b, x) = p.get_base_exp();
            let base = rebuild(b);
            let exp = x.to_owned();
            if is_integer_atom(&exp) {
                base.pow(&exp)
            } else {
                power_pos(&base, &exp)
            }
        }
        other => other.to_owned(),
    }
}

fn is_integer_atom(a: &Atom) -> bool {
    matches!(a.as_view(), AtomView::Num(_))
        && !a.to_string().contains('/')
        && !a.to_string().contains('.')
}

fn power_pos(base: &Atom, exp: &Atom) -> Atom {
    match base.as_view() {
        AtomView::Mul(m) => m
            .iter()
            .fold(Atom::num(1), |acc, f| &acc * &power_pos(&f.to_owned(), exp)),
        AtomView::Pow(p) => {
            let (bb, be) = p.get_base_exp();
            let e2 = &be.to_owned() * exp;
            if is_integer_atom(&e2) {
                bb.to_owned().pow(&e2)
            } else {
                power_pos(&bb.to_owned(), &e2)
            }
        }
        AtomView::Num(_) => {
            let s = base.to_string();
            let (p, q) = match s.split_once('/') {
                Some((p, q)) => (p.to_string(), q.to_string()),
                None => (s.clone(), "1".to_string()),
            };
            let ex_s = exp.to_string();
            let (xp, xq) = match ex_s.split_once('/') {
                Some((a, b)) => (a.parse::<i64>().ok(), b.parse::<i64>().ok()),
                None => (ex_s.parse::<i64>().ok(), Some(1)),
            };
            match (p.parse::<u64>(), q.parse::<u64>(), xp, xq) {
                (Ok(p), Ok(q), Some(xp), Some(xq)) => {
                    // prime^(k xp/xq) = prime^floor * prime^(fraction in [0, 1))
                    let mut out = Atom::num(1);
                    let mut put = |prime: u64, k: i64| {
                        let n = k * xp;
                        let fl = n.div_euclid(xq);
                        let fr = n.rem_euclid(xq);
                        let pr = Atom::num(prime as i64);
                        out = &out * &pr.pow(&Atom::num(fl));
                        if fr != 0 {
                            out = &out * &pr.pow(&rat(fr, xq));
                        }
                    };
                    for (prime, k) in factor_u64(p) {
                        put(prime, k as i64);
                    }
                    for (prime, k) in factor_u64(q) {
                        put(prime, -(k as i64));
                    }
                    out
                }
                _ => base.pow(exp),
            }
        }
        _ => base.pow(exp),
    }
}

fn factor_u64(mut n: u64) -> Vec<(u64, u32)> {
    let mut out = Vec::new();
    let mut p = 2;
    while p * p <= n {
        let mut k = 0;
        while n % p == 0 {
            n /= p;
            k += 1;
        }
        if k > 0 {
            out.push((p, k));
        }
        p += 1;
    }
    if n > 1 {
        out.push((n, 1));
    }
    out
}

/// The distinct non-constant factors of `e` (exponents dropped). Radicals
/// are frozen into plain symbols while factoring.
pub fn factor_list(e: &Atom) -> Vec<Atom> {
    let (frozen, radicals) = freeze_radicals(e);
    let f = frozen.factor();
    let base = |v: AtomView<'_>| -> Option<Atom> {
        match v {
            AtomView::Num(_) => None,
            AtomView::Pow(p) => Some(thaw(&p.get_base_exp().0.to_owned(), &radicals)),
            other => Some(thaw(&other.to_owned(), &radicals)),
        }
    };
    match f.as_view() {
        AtomView::Mul(m) => m.iter().filter_map(base).collect(),
        v => base(v).into_iter().collect(),
    }
}

/// d ln e / d`x` for `e` a product of powers: Σ p f′/f over its factors
/// f^p (numbers dropped), in rational normal form.
pub fn log_derivative(e: &Atom, x: &str) -> Atom {
    let mut sum = Atom::num(0);
    let mut add = |f: AtomView<'_>| match f {
        AtomView::Num(_) => {}
        AtomView::Pow(p) => {
            let (b, q) = p.get_base_exp();
            let (b, q) = (b.to_owned(), q.to_owned());
            sum = &sum + &(&q * &diff(&b, x) / &b);
        }
        other => {
            let b = other.to_owned();
            sum = &sum + &(diff(&b, x) / &b);
        }
    };
    match e.as_view() {
        AtomView::Mul(m) => m.iter().for_each(&mut add),
        v => add(v),
    }
    simplify(&sum)
}

/// Replace every radical `base^(p/q)` (q > 1) by `rk^p` with a fresh symbol
/// `rk` standing for `base^(1/q)`, so that polynomial algorithms (factoring)
/// see a plain polynomial. Returns the frozen expression and the rules that
/// thaw it.
pub fn freeze_radicals(e: &Atom) -> (Atom, Vec<(String, Atom)>) {
    let mut table: Vec<(String, Atom)> = Vec::new();
    let frozen = freeze(e.as_view(), &mut table);
    (frozen, table)
}

fn freeze(v: AtomView<'_>, table: &mut Vec<(String, Atom)>) -> Atom {
    match v {
        AtomView::Add(a) => a
            .iter()
            .fold(Atom::num(0), |acc, t| &acc + &freeze(t, table)),
        AtomView::Mul(m) => m
            .iter()
            .fold(Atom::num(1), |acc, t| &acc * &freeze(t, table)),
        AtomView::Pow(p) => {
            let (b, x) = p.get_base_exp();
            let xs = x.to_owned().to_string();
            match xs.split_once('/') {
                Some((num, den)) => {
                    let root = b.to_owned().pow(&ex(&format!("1/{den}")));
                    let name = match table.iter().find(|(_, r)| *r == root) {
                        Some((n, _)) => n.clone(),
                        None => {
                            let n = format!("frozenradical{}", table.len());
                            table.push((n.clone(), root));
                            n
                        }
                    };
                    var(&name).pow(&ex(num))
                }
                None => freeze(b, table).pow(&x.to_owned()),
            }
        }
        other => other.to_owned(),
    }
}

/// Undo [`freeze_radicals`].
pub fn thaw(e: &Atom, table: &[(String, Atom)]) -> Atom {
    table.iter().fold(e.clone(), |acc, (n, r)| subs(&acc, n, r))
}

/// The value of `e` at `name = point`, where a symbolic substitution may give
/// 0/0 (a removable singularity, e.g. radicals that do not cancel). First the
/// exact substitution; if that is not a finite number, the limit is taken
/// numerically from both sides (distance 1e-30, 120 digits). A limit that
/// agrees with a rational of denominator at most 1000 to 1e-15 is returned
/// exactly, any other as a 30-digit float.
pub fn value_at(e: &Atom, name: &str, point: i64) -> Result<Atom, String> {
    if let Some(exact) = exact_value_at(e, name, point) {
        return Ok(exact);
    }
    let h = ex("10^-30");
    let side = |sign: i64| eval_prec(e, &[(name, Atom::num(point) + Atom::num(sign) * &h)], 120);
    numeric_limit(side(-1)?, side(1)?)
}

/// d e/d name at `name = point` by a central difference (step 1e-30, 120
/// digits) of [`value_at`]-style one-sided values; rounded as in [`value_at`].
pub fn derivative_at(e: &Atom, name: &str, point: i64) -> Result<Atom, String> {
    if let Some(exact) = exact_value_at(&diff(e, name), name, point) {
        return Ok(exact);
    }
    let at = |k: i64| {
        eval_prec(
            e,
            &[(name, Atom::num(point) + Atom::num(k) * ex("10^-30"))],
            120,
        )
    };
    let (m2, m1, p1, p2) = (at(-2)?, at(-1)?, at(1)?, at(2)?);
    // one-sided values straddle the singular point; use the symmetric pairs
    let d1 = (p1 - m1) / 2e-30;
    let d2 = (p2 - m2) / 4e-30;
    numeric_limit(d1, d2)
}

/// The exact value at a point, unless the denominator vanishes there.
fn exact_value_at(e: &Atom, name: &str, point: i64) -> Option<Atom> {
    let (_, den) = num_den(e);
    let d = eval_prec(&den, &[(name, Atom::num(point))], 40).ok()?;
    if d.abs() < 1e-30 {
        return None;
    }
    let exact = simplify(&normalize_radicals(&simplify(&subs(
        e,
        name,
        &Atom::num(point),
    ))));
    eval_prec(&exact, &[], 40)
        .ok()
        .filter(|v| v.is_finite())
        .map(|_| exact)
}

fn numeric_limit(lo: f64, hi: f64) -> Result<Atom, String> {
    if !(lo.is_finite() && hi.is_finite()) || (lo - hi).abs() > 1e-9 * (1.0 + lo.abs()) {
        return Err(format!("no limit: {lo} .. {hi}"));
    }
    for den in 1..=1000_i64 {
        let r = (lo * den as f64).round() / den as f64;
        if (r - lo).abs() < 1e-15 * (1.0 + r.abs()) {
            return Ok(rat((lo * den as f64).round() as i64, den));
        }
    }
    Ok(ex(&format!("{lo:.17e}")).to_float(30))
}

/// `Some(true)` when `e` is positive at `probe`, `Some(false)` when
/// negative, `None` when it cannot be evaluated there.
fn positive_at(e: &Atom, probe: &[(&str, Atom)]) -> Option<bool> {
    eval_prec(e, probe, 30)
        .ok()
        .filter(|v| v.is_finite() && *v != 0.0)
        .map(|v| v > 0.0)
}

/// A polynomial `e` factored over the integers, each factor written with
/// the sign that makes it positive at `probe` (so that fractional powers
/// of it may be split factor by factor).
fn factor_positive(e: &Atom, probe: &[(&str, Atom)]) -> Atom {
    let (frozen, table) = freeze_radicals(e);
    let f = frozen.factor();
    let mut out = Atom::num(1);
    let mut put = |v: AtomView<'_>| {
        let (base, exp) = match v {
            AtomView::Pow(p) => {
                let (b, x) = p.get_base_exp();
                (thaw(&b.to_owned(), &table), x.to_owned())
            }
            other => (thaw(&other.to_owned(), &table), Atom::num(1)),
        };
        let base = if matches!(base.as_view(), AtomView::Num(_))
            || positive_at(&base, probe) != Some(false)
        {
            base
        } else {
            // (−b)^k = (−1)^k b^k
            out = &out * &Atom::num(-1).pow(&exp);
            (-base).expand()
        };
        out = &out * &base.pow(&exp);
    };
    match f.as_view() {
        AtomView::Mul(m) => m.iter().for_each(&mut put),
        v => put(v),
    }
    out
}

/// Rewrite, throughout `e`, each sum A + B√Q (one square root of a
/// non-constant Q, entering polynomially) whose two parts nearly cancel at
/// `probe` as (A² − B²Q)/(A − B√Q), with A² − B²Q factored over the
/// integers: the cancellation then happens exactly, in the factors. Bases
/// of fractional powers are made positive at `probe` first.
pub fn rationalize(e: &Atom, probe: &[(&str, Atom)]) -> Atom {
    match e.as_view() {
        AtomView::Mul(m) => m.iter().fold(Atom::num(1), |acc, f| {
            &acc * &rationalize(&f.to_owned(), probe)
        }),
        AtomView::Pow(p) => {
            let (b, x) = p.get_base_exp();
            let base = rationalize(&b.to_owned(), probe);
            let x = x.to_owned();
            if is_integer_atom(&x) {
                base.pow(&x)
            } else {
                normalize_radicals(&base.pow(&x))
            }
        }
        AtomView::Add(_) => rationalize_sum(e, probe).unwrap_or_else(|| {
            // a sum negative at the probe is written −(−e), so that equal
            // factors such as (s − 1) and (1 − s) meet and cancel
            if positive_at(e, probe) == Some(false) && freeze_radicals(e).1.is_empty() {
                Atom::num(-1) * (-e.clone()).expand()
            } else {
                e.clone()
            }
        }),
        _ => e.clone(),
    }
}

fn rationalize_sum(e: &Atom, probe: &[(&str, Atom)]) -> Option<Atom> {
    let (frozen, table) = freeze_radicals(e);
    let roots: Vec<&(String, Atom)> = table
        .iter()
        .filter(|(_, root)| {
            let s = root.to_string();
            s.ends_with("^(1/2)") && positive_at(root, &[]).is_none()
        })
        .collect();
    if roots.len() != 1 {
        return None;
    }
    let (r, root) = roots[0];
    let q = simplify(&root.pow(&Atom::num(2)));
    let n = degree_in(&frozen, r, 8)?;
    let (mut a, mut b) = (Atom::num(0), Atom::num(0));
    for k in 0..=n as u32 {
        let c = thaw(&poly_coeff(&frozen, r, k, "zzz", 0), &table);
        if k % 2 == 0 {
            a = &a + &(&c * &q.pow(&Atom::num((k / 2) as i64)));
        } else {
            b = &b + &(&c * &q.pow(&Atom::num(((k - 1) / 2) as i64)));
        }
    }
    let av = eval_prec(&a, probe, 40).ok()?;
    let bv = eval_prec(&(&b * root), probe, 40).ok()?;
    if (av + bv).abs() > 1e-2 * (av.abs() + bv.abs()) {
        return None;
    }
    let num = simplify(&normalize_radicals(&(&a * &a - &b * &b * &q).expand()));
    if is_zero(&num) {
        return Some(Atom::num(0));
    }
    let (nn, nd) = num_den(&num);
    let mut den = &a - &(&b * root);
    let mut top = factor_positive(&nn, probe);
    if positive_at(&den, probe) == Some(false) {
        den = -den;
        top = -top;
    }
    Some(top / (den * nd))
}

/// A compact normal form for reading against the printed one: radicals
/// frozen into symbols, the rational function factored over the integers
/// (numerator and denominator), radicals thawed and normalised (powers of
/// one base merged, numeric radicals split into primes and gathered).
/// The value is unchanged; only the form.
/// Of the factored and the given form, the shorter when printed (a
/// factorisation such as ā³ − 8 = (ā − 2)(ā² + 2ā + 4) is not always the
/// easier to read).
///
/// A third candidate collects the numerator in ā (then in δ̄), each
/// coefficient factored over the denominator: the form in which the paper
/// prints its reduced equations (19), (20).
pub fn compact(e: &Atom) -> Atom {
    let mut best = e.clone();
    let mut len = plain(e).chars().count();
    let mut consider = |c: Atom| {
        let n = plain(&c).chars().count();
        if n < len {
            (best, len) = (c, n);
        }
    };
    consider(factored(e));
    for v in ["abar", "dbar"] {
        if let Some(c) = collected(e, v) {
            consider(c);
        }
    }
    best
}

/// `e` factored over the integers with its radicals frozen, then thawed and
/// normalised (equal bases merged: `(1 + 2s + 3s² + 2s³ + s⁴)/(1 + s + s²)^(1/2)`
/// becomes `(1 + s + s²)^(3/2)`).
pub fn factored(e: &Atom) -> Atom {
    let (frozen, table) = freeze_radicals(e);
    normalize_radicals(&thaw(&frozen.factor(), &table))
}

/// `e` = N/D written as Σ_k (c_k/D) v^k with every coefficient factored;
/// `None` unless N is a polynomial of degree 1..=8 in `v`.
fn collected(e: &Atom, v: &str) -> Option<Atom> {
    let (n, den) = num_den(e);
    let deg = degree_in(&n, v, 8)?;
    if deg == 0 {
        return None;
    }
    let mut sum = Atom::num(0);
    for k in (0..=deg as u32).rev() {
        let c = poly_coeff(&n, v, k, "unusedsymbolforcoefficient", 0);
        if is_zero(&c) {
            continue;
        }
        sum = &sum + &(factored(&simplify(&(c / &den))) * var(v).pow(&Atom::num(k as i64)));
    }
    Some(sum)
}
