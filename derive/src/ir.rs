//! A small expression tree mirrored from a symbolica atom: numbers, symbols,
//! sums, products and powers. It is what leaves the symbolic world: the
//! checker evaluates it in `f64` for curve tracing, and the code generator
//! turns it into Rust tokens.
//!
//! Owns: the conversion from symbolica atoms and `f64` evaluation.
//! May use: symbolica's atom views (read only).

use std::collections::BTreeMap;
use symbolica::atom::{Atom, AtomView};

/// An expression over `f64`.
#[derive(Clone, Debug, PartialEq)]
pub enum Ir {
    /// An exact rational `p/q` (kept exact so that code generation can emit
    /// the correctly rounded literal).
    Rational(i128, i128),
    /// π.
    Pi,
    /// A named variable.
    Var(String),
    /// A sum.
    Add(Vec<Ir>),
    /// A product.
    Mul(Vec<Ir>),
    /// `base^exp` with a rational exponent `p/q`.
    Pow(Box<Ir>, i64, i64),
}

impl Ir {
    /// Convert a symbolica atom. Function atoms are rejected:
    /// the model only needs arithmetic and rational powers.
    pub fn from_atom(a: &Atom) -> Result<Ir, String> {
        from_view(a.as_view())
    }

    /// Evaluate with the given variable values.
    pub fn eval(&self, vars: &BTreeMap<&str, f64>) -> Result<f64, String> {
        Ok(match self {
            Ir::Rational(p, q) => *p as f64 / *q as f64,
            Ir::Pi => std::f64::consts::PI,
            Ir::Var(n) => *vars
                .get(n.as_str())
                .ok_or_else(|| format!("unbound variable {n}"))?,
            Ir::Add(v) => v.iter().map(|t| t.eval(vars)).sum::<Result<f64, _>>()?,
            Ir::Mul(v) => v.iter().map(|t| t.eval(vars)).product::<Result<f64, _>>()?,
            Ir::Pow(b, p, q) => {
                let x = b.eval(vars)?;
                match q {
                    1 => x.powi(*p as i32),
                    2 => x.sqrt().powi(*p as i32),
                    3 => x.cbrt().powi(*p as i32),
                    _ => x.powf(*p as f64 / *q as f64),
                }
            }
        })
    }

    /// Every variable name used.
    pub fn variables(&self) -> std::collections::BTreeSet<String> {
        let mut out = std::collections::BTreeSet::new();
        self.collect_vars(&mut out);
        out
    }

    fn collect_vars(&self, out: &mut std::collections::BTreeSet<String>) {
        match self {
            Ir::Var(n) => {
                out.insert(n.clone());
            }
            Ir::Add(v) | Ir::Mul(v) => v.iter().for_each(|t| t.collect_vars(out)),
            Ir::Pow(b, _, _) => b.collect_vars(out),
            _ => {}
        }
    }
}

/// Parse symbolica's printing of a rational number, `p` or `p/q`.
pub fn parse_rational(s: &str) -> Option<(i128, i128)> {
    match s.split_once('/') {
        Some((p, q)) => Some((p.trim().parse().ok()?, q.trim().parse().ok()?)),
        None => Some((s.trim().parse().ok()?, 1)),
    }
}

fn from_view(v: AtomView<'_>) -> Result<Ir, String> {
    Ok(match v {
        AtomView::Num(_) => {
            let s = v.to_owned().to_string();
            let (p, q) = parse_rational(&s).ok_or_else(|| format!("not an exact rational: {s}"))?;
            Ir::Rational(p, q)
        }
        AtomView::Var(x) => {
            let name = x.get_symbol().get_stripped_name().to_string();
            if name == "pi" || name == "𝜋" {
                Ir::Pi
            } else {
                Ir::Var(name)
            }
        }
        AtomView::Add(a) => Ir::Add(a.iter().map(from_view).collect::<Result<_, _>>()?),
        AtomView::Mul(m) => Ir::Mul(m.iter().map(from_view).collect::<Result<_, _>>()?),
        AtomView::Pow(p) => {
            let (b, x) = p.get_base_exp();
            let xs = x.to_owned().to_string();
            let (p, q) =
                parse_rational(&xs).ok_or_else(|| format!("non-rational exponent {xs}"))?;
            Ir::Pow(Box::new(from_view(b)?), p as i64, q as i64)
        }
        AtomView::Fun(f) => {
            return Err(format!(
                "function {} is not supported",
                f.get_symbol().get_stripped_name()
            ))
        }
    })
}
