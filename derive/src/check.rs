//! The verdict engine: compare a printed expression with the derived one.
//!
//! First an exact symbolic test (radicals normalised under positivity, then
//! the rational normal form of the difference must vanish). When that does
//! not reach zero, a numeric test at six pseudo-random points with 40
//! digits decides: agreement to 1e-30 relative at every point is `holds`
//! (method `numeric`), anything else is `differs`, with the size of the
//! difference. A printed claim is never bent: the comparison is the same
//! for every claim.
//!
//! Owns: verdicts and methods. May use: `sym`.

use crate::sym::{eval_prec, is_zero, normalize_radicals, rat, simplify};
use serde::Serialize;
use symbolica::atom::{Atom, AtomCore};

/// The outcome for one claim.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    /// The printed claim agrees with the derivation.
    Holds,
    /// The printed claim disagrees with the derivation.
    Differs,
    /// The claim could not be checked.
    Unverified,
}

impl Verdict {
    /// Lower-case name.
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Holds => "holds",
            Verdict::Differs => "differs",
            Verdict::Unverified => "unverified",
        }
    }
}

/// How a verdict was reached.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// The difference simplifies to zero (or, for `differs`, a numeric test
    /// confirmed that it is not zero).
    Exact,
    /// High-precision evaluation at random points.
    Numeric,
    /// A numerical solution of the derived equations at the stated parameters.
    Solve,
}

/// The result of comparing one printed with one derived expression.
#[derive(Clone, Debug)]
pub struct Comparison {
    /// The verdict.
    pub verdict: Verdict,
    /// `exact` when the symbolic difference vanished, else `numeric`.
    pub method: Method,
    /// The largest relative difference seen at the sample points.
    pub max_rel_diff: f64,
    /// A sample (point description, printed value, derived value).
    pub sample: Option<(String, f64, f64)>,
}

/// Sampling ranges (as rationals lo..hi) for the symbols the claims use.
fn domain(name: &str) -> (f64, f64) {
    match name {
        "s" => (0.3, 0.99),
        "rho" => (0.1, 0.99),
        "nu" => (0.0, 0.5),
        "u" => (0.05, 0.95),
        "mu" => (0.001, 0.1),
        "eta" => (1.0, 1.5),
        _ => (0.5, 3.0),
    }
}

/// Deterministic pseudo-random rationals in [lo, hi].
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64) / ((1u64 << 53) as f64)
    }
}

/// Free (non-builtin) symbols of an expression, sorted.
pub fn free_symbols(e: &Atom) -> Vec<String> {
    let mut v: Vec<String> = e
        .get_all_symbols(false)
        .into_iter()
        .filter(|s| !s.is_builtin())
        .map(|s| s.get_stripped_name().to_string())
        .collect();
    v.sort();
    v.dedup();
    v
}

/// Number of sample points and digits of the numeric tier.
pub const POINTS: usize = 6;
/// Decimal digits of the numeric tier.
pub const DIGITS: u32 = 40;

/// Compare `printed` with `derived`, as described in the module docs.
pub fn compare(printed: &Atom, derived: &Atom, seed: u64) -> Comparison {
    let p = normalize_radicals(printed);
    let d = normalize_radicals(derived);
    let exact = is_zero(&simplify(&(&p - &d)));
    let mut names = free_symbols(&p);
    names.extend(free_symbols(&d));
    names.sort();
    names.dedup();
    let mut rng = Lcg(seed ^ 0x9e3779b97f4a7c15);
    let mut max_rel: f64 = 0.0;
    let mut sample = None;
    let mut failed = false;
    for _ in 0..POINTS {
        let point: Vec<(&str, Atom)> = names
            .iter()
            .map(|n| {
                let (lo, hi) = domain(n);
                let x = lo + (hi - lo) * rng.next();
                (n.as_str(), rat((x * 1000.0).round() as i64, 1000))
            })
            .collect();
        match (eval_prec(&p, &point, DIGITS), eval_prec(&d, &point, DIGITS)) {
            (Ok(vp), Ok(vd)) => {
                let scale = vp.abs().max(vd.abs()).max(1e-300);
                let rel = (vp - vd).abs() / scale;
                if sample.is_none() || rel > max_rel {
                    let desc = point
                        .iter()
                        .map(|(n, v)| format!("{n}={v}"))
                        .collect::<Vec<_>>()
                        .join(", ");
                    sample = Some((desc, vp, vd));
                }
                max_rel = max_rel.max(rel);
            }
            _ => failed = true,
        }
    }
    let verdict = if exact || (!failed && max_rel < 1e-30) {
        Verdict::Holds
    } else if failed {
        Verdict::Unverified
    } else {
        Verdict::Differs
    };
    Comparison {
        verdict,
        method: if exact {
            Method::Exact
        } else {
            Method::Numeric
        },
        max_rel_diff: max_rel,
        sample,
    }
}

/// A numeric statement "x ≈ printed" with the printed number of decimals:
/// it holds when |x − printed| is at most half a unit in the last printed
/// place.
pub fn approx_printed(derived: f64, printed: &str) -> (bool, f64) {
    let decimals = printed.split_once('.').map(|(_, f)| f.len()).unwrap_or(0);
    let p: f64 = printed.parse().unwrap_or(f64::NAN);
    let tol = 0.5 * 10f64.powi(-(decimals as i32));
    ((derived - p).abs() <= tol * (1.0 + 1e-12), tol)
}

/// The comparison in words, for a claim's note.
pub fn describe(c: &Comparison) -> String {
    match c.verdict {
        Verdict::Holds if c.method == Method::Exact => "the difference simplifies to 0".into(),
        Verdict::Holds => format!(
            "no exact normal form reached; agrees to {:.1e} relative at {} points with {} digits",
            c.max_rel_diff, POINTS, DIGITS
        ),
        Verdict::Differs => {
            let (pt, vp, vd) = c.sample.clone().unwrap_or_default();
            format!(
                "largest relative difference {:.3e} (at {pt}: printed {vp:.10}, derived {vd:.10})",
                c.max_rel_diff
            )
        }
        Verdict::Unverified => "could not be evaluated at the sample points".into(),
    }
}

/// The verdict of a claim made of several checks: `unverified` if any
/// check is, else `differs` if any differs, else `holds`.
pub fn combine(parts: &[Verdict]) -> Verdict {
    if parts.contains(&Verdict::Unverified) {
        Verdict::Unverified
    } else if parts.contains(&Verdict::Differs) {
        Verdict::Differs
    } else {
        Verdict::Holds
    }
}

/// The seed of a claim's random sample points: a hash (FNV-1a) of its ID,
/// so that every run samples the same points.
pub fn seed(id: &str) -> u64 {
    id.bytes().fold(1469598103934665603u64, |h, b| {
        (h ^ b as u64).wrapping_mul(1099511628211)
    })
}
