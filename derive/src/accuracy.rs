//! The generator checks what it writes: every generated function is
//! evaluated in `f64`, with the same expression tree, operations and
//! division structure as the emitted Rust code, and in binary floating
//! point of 192 and of 384 bits (astro-float; the exact rationals of the
//! derived expression, correctly rounded operations), at sample points
//! across its declared domain (ρ from 0.05
//! to 1; s from 0.05 to 1, including s within 1e-6 of 1 and s = 1; ā and
//! δ̄ over the physical range). The inputs are the exact binary values of
//! the `f64` inputs, so that only evaluation error is measured.
//!
//! The error is relative to max(|value|, 1e-3 · M), where M is the value of
//! the expression with every term and factor replaced by its magnitude: a
//! value near 0 is judged against the size of the terms that cancel to it.
//! Generation fails, naming the function and the point, when this exceeds
//! [`TOLERANCE`], when the `f64` value is not finite, or when the two
//! high-precision references disagree beyond 1e-24 (the reference itself
//! is then not trusted).
//!
//! Owns: the sample domain and the check. May use: `ir`, `sym`.

use crate::ir::Ir;
use astro_float::{BigFloat, Consts, RoundingMode};
use std::collections::BTreeMap;
use symbolica::atom::Atom;

/// The largest relative error a generated function may have.
pub const TOLERANCE: f64 = 1e-12;

/// A chart variable `one_minus_x` stands for 1 − x, computed in the
/// generated code from the parameter x (exactly, for x in [1/2, 1]).
pub const SHIFT_PREFIX: &str = "one_minus_";

/// The parameters that charts may shift, and where a chart shifts them:
/// x ≥ 1/2.
pub const SHIFTABLE: [&str; 2] = ["s", "rho"];

/// One chart of a function: the parameters it shifts (x → 1 − x); the
/// chart is used where each shifted parameter is ≥ 1/2 and each other
/// shiftable parameter is < 1/2.
#[derive(Clone, Debug, PartialEq)]
pub struct Chart {
    /// The shifted parameters.
    pub shifted: Vec<&'static str>,
}

impl Chart {
    /// Whether `point` lies in this chart's region.
    pub fn contains(&self, params: &[&str], point: &[(String, f64)]) -> bool {
        SHIFTABLE.iter().filter(|x| params.contains(x)).all(|x| {
            let v = point
                .iter()
                .find(|(n, _)| n == x)
                .map(|(_, v)| *v)
                .unwrap_or(0.0);
            (v >= 0.5) == self.shifted.contains(x)
        })
    }
}

/// The sample values of each parameter name (the declared domain).
fn samples(name: &str) -> &'static [f64] {
    match name {
        "s" => &[0.05, 0.3, 0.7, 0.95, 0.99, 0.999, 0.9999, 0.999999, 1.0],
        "rho" => &[0.05, 0.3, 0.8, 1.0],
        "abar" | "a" | "abar0" => &[0.5, 1.7, 6.0, 20.0],
        "dbar" => &[-2.0, 0.3, 4.0, 50.0],
        "eta" => &[1.0, 1.05, 1.2],
        "eta_s" => &[-0.5, 0.0, 0.3],
        "u" => &[0.0, 0.25, 0.5, 0.9, 1.0],
        "xi" => &[0.5, 1.7, 4.0],
        "p0" => &[0.3, 1.0, 2.5],
        "x" | "y" => &[0.0, 0.3, 0.45],
        "t" => &[-1.0, 0.05, 0.2],
        "m" => &[1.0, 2.5],
        "delta" => &[0.3, 2.0],
        "R1" => &[1.0, 3.0],
        "R2" => &[0.5, 1.0],
        "A" => &[0.2, 1.1],
        "B" => &[0.1, 0.7],
        "b" => &[0.4, 1.2],
        _ => &[0.7, 1.3],
    }
}

/// Deterministic sample points: for a function of s, every s value with
/// four combinations of the other parameters; otherwise twelve.
fn points(params: &[&str], domain: &[(&str, &'static [f64])]) -> Vec<Vec<(String, f64)>> {
    let samples = |name: &str| -> &'static [f64] {
        domain
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, v)| *v)
            .unwrap_or_else(|| samples(name))
    };
    let primes = [1usize, 3, 5, 7, 11, 13, 17, 19, 23];
    let has_s = params.contains(&"s");
    let outer = if has_s { samples("s").len() } else { 1 };
    let inner = if has_s { 4 } else { 12 };
    let mut out = Vec::new();
    for i in 0..outer {
        for j in 0..inner {
            let p = params
                .iter()
                .enumerate()
                .map(|(k, name)| {
                    let set = samples(name);
                    let v = if *name == "s" {
                        set[i]
                    } else {
                        set[(j * primes[k % primes.len()] + k + i) % set.len()]
                    };
                    (name.to_string(), v)
                })
                .collect();
            out.push(p);
        }
    }
    out
}

/// `f64` evaluation mirroring the emitted code: a product is its numerator
/// factors divided by the product of its reciprocal factors.
fn eval_like_code(e: &Ir, vars: &BTreeMap<&str, f64>) -> Result<f64, String> {
    Ok(match e {
        Ir::Mul(v) => {
            let mut num = 1.0;
            let mut den = 1.0;
            let mut has_den = false;
            for f in v {
                match f {
                    Ir::Pow(b, p, q) if *p < 0 => {
                        den *= eval_like_code(&Ir::Pow(b.clone(), -p, *q), vars)?;
                        has_den = true;
                    }
                    other => num *= eval_like_code(other, vars)?,
                }
            }
            if has_den {
                num / den
            } else {
                num
            }
        }
        Ir::Add(v) => {
            let mut acc = 0.0;
            for t in v {
                acc += eval_like_code(t, vars)?;
            }
            acc
        }
        Ir::Pow(b, p, q) => {
            let x = eval_like_code(b, vars)?;
            match q {
                1 => x.powi(*p as i32),
                2 => x.sqrt().powi(*p as i32),
                3 => x.cbrt().powi(*p as i32),
                _ => x.powf(*p as f64 / *q as f64),
            }
        }
        other => other.eval(vars)?,
    })
}

/// The value of the expression with every term and factor by its magnitude.
fn magnitude(e: &Ir, vars: &BTreeMap<&str, f64>) -> Result<f64, String> {
    Ok(match e {
        Ir::Add(v) => v
            .iter()
            .map(|t| magnitude(t, vars))
            .sum::<Result<f64, _>>()?,
        Ir::Mul(v) => v
            .iter()
            .map(|t| magnitude(t, vars))
            .product::<Result<f64, _>>()?,
        Ir::Pow(b, p, q) => {
            let x = magnitude(b, vars)?;
            x.powf(*p as f64 / *q as f64)
        }
        other => other.eval(vars)?.abs(),
    })
}

/// High-precision evaluation of the expression tree at `p` bits; every
/// input is the exact value of its `f64`.
fn eval_big(e: &Ir, vars: &BTreeMap<&str, f64>, p: usize) -> Result<BigFloat, String> {
    let rm = RoundingMode::ToEven;
    let finite = |x: BigFloat, what: &str| {
        if x.is_nan() || x.is_inf() {
            Err(format!("{what} is not finite at high precision"))
        } else {
            Ok(x)
        }
    };
    Ok(match e {
        Ir::Rational(a, b) => BigFloat::from_i128(*a, p).div(&BigFloat::from_i128(*b, p), p, rm),
        Ir::Pi => {
            let mut cc = Consts::new().map_err(|e| format!("{e:?}"))?;
            cc.pi(p, rm)
        }
        Ir::Var(n) if n.starts_with(SHIFT_PREFIX) => {
            let base = &n[SHIFT_PREFIX.len()..];
            let x = *vars
                .get(base)
                .ok_or_else(|| format!("unbound variable {base}"))?;
            BigFloat::from_i64(1, p).sub(&BigFloat::from_f64(x, p), p, rm)
        }
        Ir::Var(n) => BigFloat::from_f64(
            *vars
                .get(n.as_str())
                .ok_or_else(|| format!("unbound variable {n}"))?,
            p,
        ),
        Ir::Add(v) => {
            let mut acc = BigFloat::from_i64(0, p);
            for t in v {
                acc = acc.add(&eval_big(t, vars, p)?, p, rm);
            }
            acc
        }
        Ir::Mul(v) => {
            let mut acc = BigFloat::from_i64(1, p);
            for t in v {
                acc = acc.mul(&eval_big(t, vars, p)?, p, rm);
            }
            acc
        }
        Ir::Pow(b, k, q) => {
            let x = eval_big(b, vars, p)?;
            let root = match q {
                1 => x,
                2 => finite(x.sqrt(p, rm), "a square root")?,
                3 => x.cbrt(p, rm),
                _ => return Err(format!("root of order {q}")),
            };
            let pos = root.powi(k.unsigned_abs() as usize, p, rm);
            if *k < 0 {
                if pos.is_zero() {
                    return Err("the expression divides by zero here".into());
                }
                BigFloat::from_i64(1, p).div(&pos, p, rm)
            } else {
                pos
            }
        }
    })
}

fn to_f64(x: &BigFloat) -> f64 {
    x.to_string().parse::<f64>().unwrap_or(f64::NAN)
}

/// One point where a generated function failed the check.
#[derive(Clone, Debug)]
pub struct Failure {
    /// The function.
    pub function: String,
    /// Its output index.
    pub output: usize,
    /// The point.
    pub point: Vec<(String, f64)>,
    /// What went wrong.
    pub what: String,
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let p: Vec<String> = self
            .point
            .iter()
            .map(|(n, v)| format!("{n} = {v:e}"))
            .collect();
        write!(
            f,
            "generated function {}[{}] at {}: {}",
            self.function,
            self.output,
            p.join(", "),
            self.what
        )
    }
}

/// The worst relative error over the sample points, or the failures.
/// `domain` narrows the samples of some parameters to where the function
/// is used.
/// With `chart`, only the points of its region are checked, and the
/// outputs are in its shifted variables.
pub fn check(
    name: &str,
    params: &[&str],
    outputs: &[Atom],
    domain: &[(&str, &'static [f64])],
    chart: Option<&Chart>,
) -> Result<f64, Vec<Failure>> {
    check_scaled(name, params, outputs, domain, chart, Scale::Terms)
}

/// What the error of a value is measured against.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scale {
    /// max(|value|, 1e-3 · M): a value near 0 is judged against the size
    /// of the terms that cancel to it (the default).
    Terms,
    /// |value| alone: the function must be computed without cancellation,
    /// with a small relative error also where its value tends to 0 (only
    /// an exact 0 is judged by the absolute error).
    Value,
}

/// [`check`] with the error measured against `scale`.
pub fn check_scaled(
    name: &str,
    params: &[&str],
    outputs: &[Atom],
    domain: &[(&str, &'static [f64])],
    chart: Option<&Chart>,
    scale_by: Scale,
) -> Result<f64, Vec<Failure>> {
    let mut worst: f64 = 0.0;
    let mut failures = Vec::new();
    let irs: Vec<Result<Ir, String>> = outputs.iter().map(Ir::from_atom).collect();
    let shifted_names: Vec<String> = SHIFTABLE
        .iter()
        .map(|x| format!("{SHIFT_PREFIX}{x}"))
        .collect();
    for point in points(params, domain) {
        if chart.is_some_and(|c| !c.contains(params, &point)) {
            continue;
        }
        let mut vars: BTreeMap<&str, f64> = point.iter().map(|(n, v)| (n.as_str(), *v)).collect();
        for (x, name) in SHIFTABLE.iter().zip(&shifted_names) {
            if let Some(v) = vars.get(x).copied() {
                vars.insert(name.as_str(), 1.0 - v);
            }
        }
        for (k, ir) in irs.iter().enumerate() {
            let fail = |what: String| Failure {
                function: name.to_string(),
                output: k,
                point: point.clone(),
                what,
            };
            let ir = match ir {
                Ok(ir) => ir,
                Err(e) => {
                    failures.push(fail(format!("not convertible: {e}")));
                    continue;
                }
            };
            let reference = eval_big(ir, &vars, 192).and_then(|lo| {
                eval_big(ir, &vars, 384).map(|hi| {
                    let gap = to_f64(&lo.sub(&hi, 384, RoundingMode::ToEven));
                    (gap, to_f64(&hi))
                })
            });
            let (gap, hi) = match reference {
                Ok(v) if v.0.is_finite() && v.1.is_finite() => v,
                Ok(v) => {
                    failures.push(fail(format!("high-precision value not finite: {v:?}")));
                    continue;
                }
                Err(e) => {
                    failures.push(fail(format!("no high-precision value: {e}")));
                    continue;
                }
            };
            let m = magnitude(ir, &vars).unwrap_or(f64::NAN);
            let scale = match scale_by {
                Scale::Terms => hi.abs().max(1e-3 * m),
                Scale::Value => hi.abs(),
            };
            if gap.abs() > 1e-24 * scale.max(f64::MIN_POSITIVE) {
                failures.push(fail(format!(
                    "the 192- and 384-bit values disagree by {gap:e} (value {hi:e})"
                )));
                continue;
            }
            let v = match eval_like_code(ir, &vars) {
                Ok(v) if v.is_finite() => v,
                Ok(v) => {
                    failures.push(fail(format!("f64 value {v} (exact {hi:e})")));
                    continue;
                }
                Err(e) => {
                    failures.push(fail(e));
                    continue;
                }
            };
            let err = if scale == 0.0 {
                (v - hi).abs()
            } else {
                (v - hi).abs() / scale
            };
            worst = worst.max(err);
            if err > TOLERANCE || !err.is_finite() {
                failures.push(fail(format!(
                    "f64 {v:e}, exact {hi:e}: relative error {err:.2e} > {TOLERANCE:e}"
                )));
            }
        }
    }
    if failures.is_empty() {
        Ok(worst)
    } else {
        Err(failures)
    }
}
