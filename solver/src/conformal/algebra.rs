//! A loaded family's algebra, checked by numbers before its tables are used
//! (issue 72), independently of the digest `generate` writes: a table
//! edited by hand and sealed again, or written by another tool, is held to
//! what its registry entry says it is.
//!
//! - The gap: the entry's texts of φ̄ and P, read as polynomials in X, Y,
//!   mu (and dbar), against the particular solution's terms at a few
//!   points: ΔP₀ = φ̄ (P solves ΔP = φ̄ − δ̄ for the stated gap; ΔP₁ = −1 is
//!   the exact solver's own check) and the terms are the text's P.
//! - Each member, at two points (c, δ̄, μ) where every row counts: Π̄ =
//!   ½∫ω p̄(δ̄ − φ̄) dA − ½|ω|, F̄ = ∂Π̄/∂δ̄ = ∫ω p̄ dA and the boundary slope
//!   ∂p̄/∂r at |ζ| = 1 (its cosine coefficients, and no other mode), with
//!   p̄ = P + h vanishing on the contour (h harmonic, −P on |ζ| = 1, from a
//!   discrete Fourier transform of P on the circle), integrated over the
//!   disk by Gauss–Legendre in r and the trapezoid in θ, both exact for the
//!   polynomial degrees involved; against the tables' values.
//!
//! Agreement is to 1e-9 of the sum of the magnitudes of the terms on
//! either side (round-off is below 1e-13 of it in the built-in family); a
//! corrupted row, a member's rows cut short or every coefficient scaled by
//! 1.01 move the values by far more.
//!
//! Owns: `check`, `Polynomial`. May use: the parent (`conformal`: `Tables`,
//! `poly`), `exact` (the particular solution's `Term`), `quadrature`
//! (Gauss–Legendre), `error` (numbers in messages).

use super::poly::{evaluate, Decoded};
use super::Tables;
use crate::error::rounded;
use crate::exact::gap::Term;
use crate::quadrature::GaussLegendre;
use std::f64::consts::PI;

/// The agreement asked of every value, relative to its terms' magnitudes.
const TOLERANCE: f64 = 1e-9;

/// The most quadrature points × particular terms the check spends on one
/// member (the built-in family's largest member takes about 4e4).
const MAX_WORK: usize = 50_000_000;

/// Points (X, Y, μ, δ̄) at which the texts are compared with the terms.
const TEXT_POINTS: [[f64; 4]; 4] = [
    [0.7, 0.3, 1.25, 0.6],
    [-1.1, 0.9, 2.0, -0.35],
    [0.4, -1.3, 1.0, 1.7],
    [1.7, 1.2, 3.3, 0.2],
];

/// Checks the family's algebra: its texts against its terms, then each
/// member's tables against the quadrature. The error says which check
/// failed and by how much.
pub(crate) fn check(
    gap: &str,
    particular: &str,
    terms: &[Term],
    members: &[Tables],
) -> Result<(), String> {
    let phi = Polynomial::read(gap).map_err(|why| format!("its gap {gap:?}: {why}"))?;
    let p_text = Polynomial::read(particular)
        .map_err(|why| format!("its particular solution {particular:?}: {why}"))?;
    let p = Particular(terms);
    for [x, y, mu, dbar] in TEXT_POINTS {
        let at = rounded;
        let (lap, lap_size) = p.laplacian_of_p0(x, y, mu);
        let want = phi.at(x, y, mu, dbar);
        if !agrees(lap, want.0, lap_size.max(want.1)) {
            return Err(format!(
                "its particular solution does not solve ΔP = φ − dbar for its gap: at X = {}, Y = {}, mu = {} ΔP0 = {} but φ = {}",
                at(x), at(y), at(mu), rounded(lap), rounded(want.0)
            ));
        }
        let (value, size) = p.value(x, y, mu, dbar);
        let text = p_text.at(x, y, mu, dbar);
        if !agrees(value, text.0, size.max(text.1)) {
            return Err(format!(
                "its particular solution's terms are not its text: at X = {}, Y = {}, mu = {}, dbar = {} they give {} and the text {}",
                at(x), at(y), at(mu), at(dbar), rounded(value), rounded(text.0)
            ));
        }
    }
    for m in members {
        member(&p, m).map_err(|why| format!("member {}: {why}", m.terms))?;
    }
    Ok(())
}

/// Whether `a` and `b` agree to [`TOLERANCE`] of `size`.
fn agrees(a: f64, b: f64, size: f64) -> bool {
    (a - b).abs() <= TOLERANCE * size.max(f64::MIN_POSITIVE) && a.is_finite() && b.is_finite()
}

/// The particular solution P(X, Y; μ, δ̄) of its terms, with its gradient
/// and ΔP₀, each beside the sum of its terms' magnitudes.
struct Particular<'a>(&'a [Term]);

impl Particular<'_> {
    fn coefficient(t: &Term, mu: f64, dbar: f64) -> f64 {
        t.num as f64 / t.den as f64 * mu.powi(t.mu as i32) * dbar.powi(t.dbar as i32)
    }

    fn value(&self, x: f64, y: f64, mu: f64, dbar: f64) -> (f64, f64) {
        let (mut v, mut size) = (0.0, 0.0);
        for t in self.0 {
            let m = Self::coefficient(t, mu, dbar) * x.powi(t.x as i32) * y.powi(t.y as i32);
            v += m;
            size += m.abs();
        }
        (v, size)
    }

    /// (∂P/∂X, ∂P/∂Y) and the magnitude of their terms.
    fn gradient(&self, x: f64, y: f64, mu: f64, dbar: f64) -> ((f64, f64), f64) {
        let (mut gx, mut gy, mut size) = (0.0, 0.0, 0.0);
        for t in self.0 {
            let c = Self::coefficient(t, mu, dbar);
            if t.x > 0 {
                let m = c * t.x as f64 * x.powi(t.x as i32 - 1) * y.powi(t.y as i32);
                gx += m;
                size += m.abs();
            }
            if t.y > 0 {
                let m = c * t.y as f64 * x.powi(t.x as i32) * y.powi(t.y as i32 - 1);
                gy += m;
                size += m.abs();
            }
        }
        ((gx, gy), size)
    }

    /// ΔP₀, the Laplacian of P's part without δ̄: the gap φ̄ it claims.
    fn laplacian_of_p0(&self, x: f64, y: f64, mu: f64) -> (f64, f64) {
        let (mut v, mut size) = (0.0, 0.0);
        for t in self.0.iter().filter(|t| t.dbar == 0) {
            let c = Self::coefficient(t, mu, 1.0);
            for (k, px, py) in [(t.x, 2, 0), (t.y, 0, 2)] {
                if k >= 2 {
                    let m = c
                        * (k as f64 * (k as f64 - 1.0))
                        * x.powi(t.x as i32 - px)
                        * y.powi(t.y as i32 - py);
                    v += m;
                    size += m.abs();
                }
            }
        }
        (v, size)
    }

    /// The largest total degree in X and Y.
    fn degree(&self) -> usize {
        self.0
            .iter()
            .map(|t| (t.x + t.y) as usize)
            .max()
            .unwrap_or(0)
    }
}

/// One member's Π̄, F̄ and boundary slope against the quadrature.
fn member(p: &Particular, t: &Tables) -> Result<(), String> {
    let k = t.terms;
    let n_max = t.powers.iter().copied().max().unwrap_or(1) as usize;
    // P∘w has modes up to deg P · n on the circle; the integrand of Π̄ total
    // degree below 2 deg P · n in ζ and ζ̄ (r dr one more)
    let modes = p.degree().max(2) * n_max;
    let (n_theta, n_r) = (2 * modes + 2, modes + 1);
    let work = n_theta * n_r * (p.0.len() + modes);
    if work > MAX_WORK {
        return Err(format!(
            "its check would take {work} steps, more than the {MAX_WORK} a loaded member may (a gap of lower degree or a map of lower powers)"
        ));
    }
    let potential = Decoded::new(&t.potential[..t.potential_rows], k);
    let potential_size = Decoded::new(&magnitudes(&t.potential[..t.potential_rows]), k);
    let slopes: Vec<(usize, Decoded, Decoded)> = t
        .slope_rows
        .iter()
        .map(|&(n, len)| {
            let rows = t
                .slope
                .iter()
                .find(|(j, _)| *j == n)
                .map(|(_, r)| &r[..len.min(r.len())])
                .unwrap_or(&[]);
            (
                n as usize,
                Decoded::new(rows, k),
                Decoded::new(&magnitudes(rows), k),
            )
        })
        .collect();
    if let Some((n, _, _)) = slopes.iter().find(|(n, _, _)| *n > modes) {
        return Err(format!(
            "its boundary slope lists mode {n}, above the {modes} its gap and map can have"
        ));
    }
    let grid = Grid {
        thetas: (0..n_theta)
            .map(|j| 2.0 * PI * j as f64 / n_theta as f64)
            .collect(),
        rule: GaussLegendre::new(n_r),
        modes,
    };
    for (c, dbar, mu) in points(k) {
        let at = Point {
            c: &c,
            powers: t.powers,
            dbar,
            mu,
        };
        let said = format!(
            "at c = [{}], dbar = {}, mu = {}",
            c.iter().map(|&v| rounded(v)).collect::<Vec<_>>().join(", "),
            rounded(dbar),
            rounded(mu)
        );
        // P on the circle and its Fourier coefficients: p̄ = P + h, h
        // harmonic, vanishes on the contour
        let boundary: Vec<f64> = grid
            .thetas
            .iter()
            .map(|&th| {
                let ((x, y), _) = at.w(1.0, th);
                p.value(x, y, mu, dbar).0
            })
            .collect();
        let fourier = transform(&boundary, &grid.thetas, modes);
        let q = potential_and_force(p, &grid, &at, &fourier);
        let table = evaluate(&potential, &c, dbar, mu, 1);
        let abs_c: Vec<f64> = c.iter().map(|v| v.abs()).collect();
        let size = evaluate(&potential_size, &abs_c, dbar.abs(), mu, 1);
        if !agrees(table.value, q.pi_bar, size.value.max(q.pi_size)) {
            return Err(format!(
                "its table of the potential is not its algebra: {said} it gives {} and the quadrature {}",
                rounded(table.value),
                rounded(q.pi_bar)
            ));
        }
        if !agrees(table.grad[k], q.force, size.grad[k].max(q.force_size)) {
            return Err(format!(
                "its table's force dΠ/d(dbar) is not the integral of its pressure: {said} it gives {} and the quadrature {}",
                rounded(table.grad[k]),
                rounded(q.force)
            ));
        }
        let (numeric, slope_size) = slope_modes(p, &grid, &at, &fourier);
        for (m, &(a, b)) in numeric.iter().enumerate() {
            let listed = slopes.iter().find(|(n, _, _)| *n == m);
            let (want, size) = listed.map_or((0.0, 0.0), |(_, d, s)| {
                (
                    evaluate(d, &c, dbar, mu, 0).value,
                    evaluate(s, &abs_c, dbar.abs(), mu, 0).value,
                )
            });
            let size = size.max(slope_size);
            if !agrees(want, a, size) || !agrees(b, 0.0, size) {
                return Err(format!(
                    "its boundary slope's mode {m} is not its algebra: {said} the table gives {} and the quadrature {}",
                    rounded(want),
                    rounded(a)
                ));
            }
        }
    }
    Ok(())
}

/// The quadrature's nodes: trapezoid in θ, Gauss–Legendre in r, and the
/// highest mode a member's functions have on the circle.
struct Grid {
    thetas: Vec<f64>,
    rule: GaussLegendre,
    modes: usize,
}

/// One point of a member's unknowns: its map's coefficients and powers, δ̄
/// and μ.
struct Point<'a> {
    c: &'a [f64],
    powers: &'a [u16],
    dbar: f64,
    mu: f64,
}

impl Point<'_> {
    /// The map at (r, θ) and its Jacobian.
    fn w(&self, r: f64, theta: f64) -> ((f64, f64), f64) {
        map(self.c, self.powers, r, theta)
    }
}

/// Π̄, F̄ = ∫p̄ dA and their sizes (the same sums over the magnitudes).
struct Quadrature {
    pi_bar: f64,
    pi_size: f64,
    force: f64,
    force_size: f64,
}

/// The harmonic part h = −Σ r^m (a cos mθ + b sin mθ) of p̄ at (r, θ).
fn harmonic(fourier: &[(f64, f64)], r: f64, th: f64) -> f64 {
    -fourier
        .iter()
        .enumerate()
        .map(|(m, &(a, b))| {
            r.powi(m as i32) * (a * (m as f64 * th).cos() + b * (m as f64 * th).sin())
        })
        .sum::<f64>()
}

/// Π̄ = ∫ (p̄(δ̄ − φ̄)/2 − 1/2) dA and F̄ = ∫p̄ dA over the unit disk mapped
/// by w, p̄ = P + h.
fn potential_and_force(
    p: &Particular,
    grid: &Grid,
    at: &Point,
    fourier: &[(f64, f64)],
) -> Quadrature {
    let n_theta = grid.thetas.len();
    let mut q = Quadrature {
        pi_bar: 0.0,
        pi_size: 0.0,
        force: 0.0,
        force_size: 0.0,
    };
    for (&u, &wu) in grid.rule.nodes.iter().zip(&grid.rule.weights) {
        let r = 0.5 * (u + 1.0);
        for &th in &grid.thetas {
            let ((x, y), jac) = at.w(r, th);
            let (pv, psize) = p.value(x, y, at.mu, at.dbar);
            let hv = harmonic(fourier, r, th);
            let pbar = pv + hv;
            let gap = p.laplacian_of_p0(x, y, at.mu).0;
            let weight = 0.5 * wu * r * (2.0 * PI / n_theta as f64) * jac;
            q.pi_bar += weight * (0.5 * pbar * (at.dbar - gap) - 0.5);
            q.pi_size += weight * (0.5 * (psize + hv.abs()) * (at.dbar.abs() + gap.abs()) + 0.5);
            q.force += weight * pbar;
            q.force_size += weight * (psize + hv.abs());
        }
    }
    q
}

/// The cosine and sine modes of ∂p̄/∂r at r = 1 (∇P·∂w/∂r, less the
/// harmonic part's m·(a, b)) up to the grid's modes, and their size: the
/// largest |∇P|·|∂w/∂r| and the harmonic part's terms.
fn slope_modes(
    p: &Particular,
    grid: &Grid,
    at: &Point,
    fourier: &[(f64, f64)],
) -> (Vec<(f64, f64)>, f64) {
    let mut gradient_size = 0.0f64;
    let slope: Vec<f64> = grid
        .thetas
        .iter()
        .map(|&th| {
            let ((x, y), _) = at.w(1.0, th);
            let ((gx, gy), size) = p.gradient(x, y, at.mu, at.dbar);
            let (wx, wy) = radial_derivative(at.c, at.powers, th);
            gradient_size = gradient_size.max(size * wx.hypot(wy));
            let harmonic: f64 = fourier
                .iter()
                .enumerate()
                .map(|(m, &(a, b))| {
                    m as f64 * (a * (m as f64 * th).cos() + b * (m as f64 * th).sin())
                })
                .sum();
            gx * wx + gy * wy - harmonic
        })
        .collect();
    let size = gradient_size
        + fourier
            .iter()
            .enumerate()
            .map(|(m, &(a, b))| m as f64 * (a.abs() + b.abs()))
            .sum::<f64>();
    (transform(&slope, &grid.thetas, grid.modes), size)
}

/// The rows with their coefficients' magnitudes.
fn magnitudes(rows: &[(u64, f64)]) -> Vec<(u64, f64)> {
    rows.iter().map(|&(p, c)| (p, c.abs())).collect()
}

/// Two points (c, δ̄, μ) for a member of `k` coefficients, every
/// coefficient of order one (so that every row of the tables counts), not
/// a contact: the identities hold for any c.
fn points(k: usize) -> [(Vec<f64>, f64, f64); 2] {
    let shape = |first: f64, rest: f64| -> Vec<f64> {
        (0..k)
            .map(|j| {
                if j == 0 {
                    first
                } else {
                    rest * (1.0 - 0.07 * j as f64) * if j % 2 == 0 { 1.0 } else { -1.0 }
                }
            })
            .collect()
    };
    [(shape(1.1, 0.45), 0.6, 1.4), (shape(0.8, 0.3), -0.35, 2.5)]
}

/// w(ζ) = Σ c_k ζ^(n_k) and |w′(ζ)|² at ζ = r e^{iθ}.
fn map(c: &[f64], powers: &[u16], r: f64, theta: f64) -> ((f64, f64), f64) {
    let (mut x, mut y, mut dx, mut dy) = (0.0, 0.0, 0.0, 0.0);
    for (&ck, &n) in c.iter().zip(powers) {
        let n = n as f64;
        x += ck * r.powf(n) * (n * theta).cos();
        y += ck * r.powf(n) * (n * theta).sin();
        dx += ck * n * r.powf(n - 1.0) * ((n - 1.0) * theta).cos();
        dy += ck * n * r.powf(n - 1.0) * ((n - 1.0) * theta).sin();
    }
    ((x, y), dx * dx + dy * dy)
}

/// ∂w/∂r at ζ = e^{iθ}: Σ c_k n_k e^{i n_k θ}.
fn radial_derivative(c: &[f64], powers: &[u16], theta: f64) -> (f64, f64) {
    c.iter().zip(powers).fold((0.0, 0.0), |(x, y), (&ck, &n)| {
        let n = n as f64;
        (
            x + ck * n * (n * theta).cos(),
            y + ck * n * (n * theta).sin(),
        )
    })
}

/// The Fourier coefficients (a_m, b_m), m = 0 … `modes`, of samples on a
/// uniform grid: f = Σ a_m cos mθ + b_m sin mθ (exact for a trigonometric
/// polynomial of degree below half the samples).
fn transform(values: &[f64], thetas: &[f64], modes: usize) -> Vec<(f64, f64)> {
    let n = values.len() as f64;
    (0..=modes)
        .map(|m| {
            let (mut a, mut b) = (0.0, 0.0);
            for (v, &th) in values.iter().zip(thetas) {
                a += v * (m as f64 * th).cos();
                b += v * (m as f64 * th).sin();
            }
            let scale = if m == 0 { 1.0 / n } else { 2.0 / n };
            (a * scale, b * scale)
        })
        .collect()
}

/// A polynomial's text, as a registry entry writes φ̄ and P: numbers, the
/// symbols X, Y, mu and dbar, + − * / ^ (a non-negative integer power) and
/// parentheses. Read once, evaluated at points with the sum of the
/// magnitudes of its terms.
pub(crate) struct Polynomial(Vec<Token>);

#[derive(Clone, Copy, Debug, PartialEq)]
enum Token {
    Number(f64),
    Symbol(usize),
    Op(char),
}

/// The symbols a text may name, in the order [`Polynomial::at`] takes them.
const SYMBOLS: [&str; 4] = ["X", "Y", "mu", "dbar"];

/// The deepest nesting read (of parentheses and signs).
const MAX_DEPTH: usize = 64;

/// The longest text read.
const MAX_TEXT: usize = 4096;

impl Polynomial {
    /// The text's tokens, checked to evaluate.
    pub(crate) fn read(text: &str) -> Result<Polynomial, String> {
        if text.len() > MAX_TEXT {
            return Err(format!("longer than {MAX_TEXT} characters"));
        }
        let mut tokens = Vec::new();
        let mut chars = text.char_indices().peekable();
        while let Some((i, ch)) = chars.next() {
            match ch {
                ' ' => {}
                '+' | '-' | '*' | '/' | '^' | '(' | ')' => tokens.push(Token::Op(ch)),
                '0'..='9' | '.' => {
                    let mut end = i + 1;
                    while let Some(&(j, d)) = chars.peek() {
                        if d.is_ascii_digit() || d == '.' {
                            end = j + 1;
                            chars.next();
                        } else {
                            break;
                        }
                    }
                    let v: f64 = text[i..end]
                        .parse()
                        .map_err(|_| format!("{:?} is not a number", &text[i..end]))?;
                    tokens.push(Token::Number(v));
                }
                c if c.is_ascii_alphabetic() => {
                    let mut end = i + 1;
                    while let Some(&(j, d)) = chars.peek() {
                        if d.is_ascii_alphanumeric() || d == '_' {
                            end = j + 1;
                            chars.next();
                        } else {
                            break;
                        }
                    }
                    let name = &text[i..end];
                    let s = SYMBOLS.iter().position(|s| *s == name).ok_or_else(|| {
                        format!("it names {name:?}; a polynomial in X, Y, mu and dbar was expected")
                    })?;
                    tokens.push(Token::Symbol(s));
                }
                other => {
                    return Err(format!(
                        "{other:?} is not read here (numbers, X, Y, mu, dbar, + - * / ^ and parentheses)"
                    ))
                }
            }
        }
        let p = Polynomial(tokens);
        p.evaluate(&[1.0; 4])?;
        Ok(p)
    }

    /// Its value at (X, Y, μ, δ̄) and the sum of its terms' magnitudes
    /// (the value with every subtraction an addition and every symbol its
    /// magnitude).
    pub(crate) fn at(&self, x: f64, y: f64, mu: f64, dbar: f64) -> (f64, f64) {
        let v = [x, y, mu, dbar];
        let value = self.evaluate(&v).unwrap_or(f64::NAN);
        let size = Reader {
            tokens: &self.0,
            at: 0,
            values: v.map(f64::abs),
            magnitudes: true,
        }
        .whole()
        .unwrap_or(f64::NAN);
        (value, size)
    }

    fn evaluate(&self, values: &[f64; 4]) -> Result<f64, String> {
        Reader {
            tokens: &self.0,
            at: 0,
            values: *values,
            magnitudes: false,
        }
        .whole()
    }
}

/// A recursive-descent evaluation of the tokens.
struct Reader<'a> {
    tokens: &'a [Token],
    at: usize,
    values: [f64; 4],
    /// Whether a subtraction adds (the magnitudes of the terms).
    magnitudes: bool,
}

impl Reader<'_> {
    fn whole(mut self) -> Result<f64, String> {
        let v = self.sum(0)?;
        match self.tokens.get(self.at) {
            None => Ok(v),
            Some(t) => Err(format!("{} is not expected there", show(t))),
        }
    }

    fn peek(&self) -> Option<Token> {
        self.tokens.get(self.at).copied()
    }

    fn sum(&mut self, depth: usize) -> Result<f64, String> {
        let mut v = self.product(depth)?;
        while let Some(Token::Op(op @ ('+' | '-'))) = self.peek() {
            self.at += 1;
            let w = self.product(depth)?;
            v = if op == '+' || self.magnitudes {
                v + w
            } else {
                v - w
            };
        }
        Ok(v)
    }

    fn product(&mut self, depth: usize) -> Result<f64, String> {
        let mut v = self.signed(depth)?;
        while let Some(Token::Op(op @ ('*' | '/'))) = self.peek() {
            self.at += 1;
            let w = self.signed(depth)?;
            v = if op == '*' { v * w } else { v / w };
        }
        Ok(v)
    }

    fn signed(&mut self, depth: usize) -> Result<f64, String> {
        if depth > MAX_DEPTH {
            return Err(format!("nested deeper than {MAX_DEPTH}"));
        }
        match self.peek() {
            Some(Token::Op('-')) => {
                self.at += 1;
                let v = self.signed(depth + 1)?;
                Ok(if self.magnitudes { v } else { -v })
            }
            Some(Token::Op('+')) => {
                self.at += 1;
                self.signed(depth + 1)
            }
            _ => self.power(depth),
        }
    }

    fn power(&mut self, depth: usize) -> Result<f64, String> {
        let base = self.atom(depth)?;
        if self.peek() != Some(Token::Op('^')) {
            return Ok(base);
        }
        self.at += 1;
        let parenthesised = self.peek() == Some(Token::Op('('));
        if parenthesised {
            self.at += 1;
        }
        let e = match self.peek() {
            Some(Token::Number(e)) if e.fract() == 0.0 && (0.0..=64.0).contains(&e) => e as i32,
            _ => return Err("a power must be a whole number from 0 to 64".into()),
        };
        self.at += 1;
        if parenthesised {
            if self.peek() != Some(Token::Op(')')) {
                return Err("a ( is not closed".into());
            }
            self.at += 1;
        }
        Ok(base.powi(e))
    }

    fn atom(&mut self, depth: usize) -> Result<f64, String> {
        let t = self
            .peek()
            .ok_or("it ends where a number or a symbol was expected")?;
        self.at += 1;
        match t {
            Token::Number(v) => Ok(v),
            Token::Symbol(s) => Ok(self.values[s]),
            Token::Op('(') => {
                let v = self.sum(depth + 1)?;
                if self.peek() != Some(Token::Op(')')) {
                    return Err("a ( is not closed".into());
                }
                self.at += 1;
                Ok(v)
            }
            other => Err(format!("{} is not expected there", show(&other))),
        }
    }
}

fn show(t: &Token) -> String {
    match t {
        Token::Number(v) => format!("the number {v}"),
        Token::Symbol(s) => SYMBOLS[*s].to_string(),
        Token::Op(c) => format!("{c:?}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every compiled family passes the check: its texts are its terms'
    /// and its tables its algebra.
    #[test]
    fn every_compiled_family_passes() {
        for f in super::super::compiled() {
            check(f.gap, f.particular, f.particular_terms, f.members)
                .unwrap_or_else(|why| panic!("{}: {why}", f.name));
        }
    }

    /// The built-in family's texts, terms and members, with `edit` applied
    /// to a copy of its members.
    fn edited(edit: impl Fn(&mut Vec<Tables>)) -> Result<(), String> {
        let f = &super::super::compiled()[0];
        let mut members: Vec<Tables> = f
            .members
            .iter()
            .map(|t| Tables { second: None, ..*t })
            .collect();
        edit(&mut members);
        check(f.gap, f.particular, f.particular_terms, &members)
    }

    fn leaked<T: Clone>(v: &[T]) -> &'static [T] {
        Box::leak(v.to_vec().into_boxed_slice())
    }

    /// Issue 72's hand edits, each refused by the check that fails: a
    /// member's rows cut short (K = 2: 38 rows to 20), every coefficient
    /// scaled by 1.01, one coefficient of the boundary slope changed, a
    /// slope mode's rows cut, and the particular solution's terms or texts
    /// not the gap's.
    #[test]
    fn an_edited_family_is_refused_by_the_check_that_fails() {
        let refused = |why: Result<(), String>, says: &str| {
            let why = why.expect_err("refused");
            assert!(why.contains(says), "{why}");
        };
        refused(
            edited(|m| {
                assert_eq!(m[1].potential_rows, 38);
                m[1].potential_rows = 20;
            }),
            "member 2: its table of the potential is not its algebra",
        );
        refused(
            edited(|m| {
                let scaled: Vec<(u64, f64)> =
                    m[0].potential.iter().map(|&(p, c)| (p, 1.01 * c)).collect();
                let scaled = leaked(&scaled);
                for t in m.iter_mut() {
                    t.potential = scaled;
                }
            }),
            "member 1: its table of the potential",
        );
        refused(
            edited(|m| {
                let mut slope: Vec<(u16, &'static [(u64, f64)])> = m[0].slope.to_vec();
                let mut rows = slope[1].1.to_vec();
                rows[0].1 *= 1.0 + 1e-6;
                slope[1].1 = leaked(&rows);
                let slope = leaked(&slope);
                for t in m.iter_mut() {
                    t.slope = slope;
                }
            }),
            "its boundary slope's mode",
        );
        refused(
            edited(|m| {
                let mut rows = m[3].slope_rows.to_vec();
                rows[0].1 -= 1;
                m[3].slope_rows = leaked(&rows);
            }),
            "member 4: its boundary slope's mode 0",
        );
        let f = &super::super::compiled()[0];
        // the quartic gap X^2/2 + mu*Y^2/2 + X^4/24 under the quadratic's P
        refused(
            check(
                "X^2/2 + mu*Y^2/2 + X^4/24",
                f.particular,
                f.particular_terms,
                f.members,
            ),
            "does not solve ΔP = φ − dbar for its gap",
        );
        // its P (one more term X^6/720) under the quadratic gap's tables
        let mut quartic = f.particular_terms.to_vec();
        quartic.push(Term {
            x: 6,
            y: 0,
            mu: 0,
            dbar: 0,
            num: 1,
            den: 720,
        });
        let text = "X^4/24 + mu*Y^4/24 - dbar*(X^2 + Y^2)/4 + X^6/720";
        refused(
            check("X^2/2 + mu*Y^2/2 + X^4/24", text, &quartic, f.members),
            "member 1: its table of the potential is not its algebra",
        );
        // a numerator of i64::MAX
        let mut huge = f.particular_terms.to_vec();
        huge[3].num = i64::MAX;
        refused(
            check(f.gap, f.particular, &huge, f.members),
            "does not solve ΔP = φ − dbar",
        );
        // the terms' P differs from the text's by a δ̄-free harmonic X^2 − Y^2
        let mut harmonic = f.particular_terms.to_vec();
        harmonic.push(Term {
            x: 2,
            y: 0,
            mu: 0,
            dbar: 0,
            num: 1,
            den: 1,
        });
        harmonic.push(Term {
            x: 0,
            y: 2,
            mu: 0,
            dbar: 0,
            num: -1,
            den: 1,
        });
        refused(
            check(f.gap, f.particular, &harmonic, f.members),
            "its particular solution's terms are not its text",
        );
    }

    #[test]
    fn a_text_reads_as_symbolica_writes_it() {
        let p = Polynomial::read("X^4/24 + mu*Y^4/24 - dbar*(X^2 + Y^2)/4").unwrap();
        let (v, size) = p.at(2.0, 1.0, 3.0, 0.5);
        assert_eq!(v, 16.0 / 24.0 + 3.0 / 24.0 - 0.5 * 5.0 / 4.0);
        assert_eq!(size, 16.0 / 24.0 + 3.0 / 24.0 + 0.5 * 5.0 / 4.0);
        assert_eq!(
            Polynomial::read("-X^2").unwrap().at(3.0, 0.0, 1.0, 0.0).0,
            -9.0
        );
        assert_eq!(
            Polynomial::read("2^(3)*Y")
                .unwrap()
                .at(0.0, 0.5, 1.0, 0.0)
                .0,
            4.0
        );
        for bad in ["X^", "sqrt(X)", "(X", "X^-2", "X^1.5", "X $ Y", "X Y", ""] {
            assert!(Polynomial::read(bad).is_err(), "{bad}");
        }
        assert!(Polynomial::read(&"(".repeat(100)).is_err());
    }
}
