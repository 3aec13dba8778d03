//! A contour family and a slender model as data: the shapes the generator
//! fills (`thinjkr-derive generate` writes them into `crate::generated`,
//! and `conformal::load` reads them from a family's files at run time),
//! with the evaluator of a member's monomial tables ([`poly`]). Ranked
//! below `generated`, which names these types, and above `exact`, whose
//! gap a family's particular solution is.
//!
//! Owns: [`Family`], [`Tables`], [`SlenderModel`], [`poly`]. May use:
//! `exact` (a gap's monomials, [`crate::exact::gap::Term`], and the gap
//! itself).

use crate::exact::Gap;

pub mod poly;

/// The generated tables of one member (`crate::generated::<family>::MEMBERS`).
#[derive(Debug)]
pub struct Tables {
    /// K.
    pub terms: usize,
    /// The powers n_k of ζ in the map.
    pub powers: &'static [u16],
    /// Π̄(c, δ̄; μ) rows of the family's largest member …
    pub potential: &'static [(u64, f64)],
    /// … of which this member's are the first `potential_rows`.
    pub potential_rows: usize,
    /// ∂p̄/∂r at |ζ| = 1 of the largest member: (n, rows of the
    /// coefficient of cos nθ) …
    pub slope: &'static [(u16, &'static [(u64, f64)])],
    /// … of which this member has the modes n listed here, each with its
    /// leading rows.
    pub slope_rows: &'static [(u16, usize)],
    /// Π̄ with its gradient and Hessian from the table evaluator unrolled
    /// over this member's rows (bit for bit [`poly::evaluate`] at order 2,
    /// faster), generated for the small members.
    pub second: Option<fn(&[f64], f64, f64) -> poly::Second>,
}

/// A contour family as the registry lists it
/// (`crate::generated::registry::CONTOUR_FAMILIES`, written by `generate`
/// from the family's data file `derive/families/<name>.toml`).
#[derive(Debug)]
pub struct Family {
    /// The family's name; members are `name:K`.
    pub name: &'static str,
    /// Its kind (`conformal`: a polynomial map of the unit disk).
    pub kind: &'static str,
    /// One line.
    pub title: &'static str,
    /// The scaled gap φ̄ (symbolica syntax in X, Y, mu = 1/ρ).
    pub gap: &'static str,
    /// The particular solution of (2) the pressure is built on.
    pub particular: &'static str,
    /// The data file it was generated from.
    pub source: &'static str,
    /// The smallest ρ its solves accept.
    pub rho_min: f64,
    /// Why a smaller ρ is refused, in one sentence (empty where its data
    /// file does not say).
    pub rho_min_why: &'static str,
    /// ā at which the pull-off trace starts, where its data file says: on a
    /// gap radial at ρ = 1, between the neutral points of the circle's
    /// modes 4 and 6 of its gap, so that the trace follows the
    /// near-elliptic arm that carries the pull-off (each mode's imperfect
    /// bifurcation splits the family for ρ < 1, docs/exact.md, and an arm
    /// traced from a larger contact folds back before reaching it);
    /// omitted, halfway between them. On a gap no circle solves it is not
    /// used: the trace starts between the cylinders' neutral points of
    /// modes 2 and 4 (the one rule, `crate::exact::gap::GapAt::trace_start`).
    pub trace_start_a: Option<f64>,
    /// Whether its gap is the one the exact solver solves (then its
    /// members are measured against the exact solution).
    pub on_exact_gap: bool,
    /// Whether its largest member gives the exact solver its starting
    /// states.
    pub seeds_exact: bool,
    /// For each member K (in order), the boundary defect above which its
    /// state is warned as doubtful: the smallest defect at which a state of
    /// docs/accuracy.md's rows is more than 0.5 % off in ā against the
    /// exact solution. Empty where its data file does not say: then
    /// `DOUBTFUL_DEFECT` (0.1) for every member.
    pub doubtful_defects: &'static [f64],
    /// Its members, by K.
    pub members: &'static [Tables],
    /// The particular solution's monomials, as the exact solver reads the
    /// gap (`crate::exact::Gap`).
    pub particular_terms: &'static [crate::exact::gap::Term],
}

impl Family {
    /// "1 ..= 8": the family's K, from its smallest member to its largest.
    pub(crate) fn member_range(&self) -> String {
        let ks = self.members.iter().map(|t| t.terms);
        let (lo, hi) = (ks.clone().min().unwrap_or(0), ks.max().unwrap_or(0));
        format!("{lo} ..= {hi}")
    }

    /// s = b̄/ā where a state of this family at `rho` with semi-axes ā, b̄
    /// is wider across than along though its gap makes the near-elliptic
    /// states longer along: the one rule of the "b > a" warning and of the
    /// end of a member's trace (issue 73, item 4). The gap makes them
    /// longer along where it rises at least as fast across as along at
    /// every distance: every coefficient of φ̄(0, t) − φ̄(t, 0) in t is at
    /// least 0 and one is above (the cylinders' (μ − 1)t²/2 at ρ < 1, the
    /// quartic gap's (μ² − 1)t⁴/8). On any other gap nothing is judged: a
    /// quartic term in X alone makes even the states at ρ = 1 wider across.
    pub(crate) fn wider_than_its_gap_allows(
        &self,
        rho: f64,
        a_bar: f64,
        b_bar: f64,
    ) -> Option<f64> {
        let wider = b_bar > a_bar * (1.0 + 1e-9);
        (wider && longer_along(self.particular_terms, rho)).then_some(b_bar / a_bar)
    }
}

/// Whether the gap whose particular solution has the monomials `terms`
/// rises at least as fast across as along at `rho`, and faster somewhere
/// ([`Family::wider_than_its_gap_allows`]).
pub(crate) fn longer_along(terms: &[crate::exact::gap::Term], rho: f64) -> bool {
    // φ̄ = ΔP at δ̄ = 0, on either axis: X^x Y^y gives x(x−1) t^(x−2) on
    // the X axis where y = 0 and 2 t^x where y = 2 (and so across)
    let mu = 1.0 / rho;
    let mut across_minus_along = [0.0f64; 256];
    for t in terms.iter().filter(|t| t.dbar == 0) {
        let v = t.num as f64 / t.den as f64 * mu.powi(i32::from(t.mu));
        let (x, y) = (usize::from(t.x), usize::from(t.y));
        let mut add = |power: usize, by: f64| {
            if let Some(c) = across_minus_along.get_mut(power) {
                *c += by;
            }
        };
        if y == 0 && x >= 2 {
            add(x - 2, -((x * (x - 1)) as f64) * v);
        }
        if y == 2 {
            add(x, -2.0 * v);
        }
        if x == 0 && y >= 2 {
            add(y - 2, (y * (y - 1)) as f64 * v);
        }
        if x == 2 {
            add(y, 2.0 * v);
        }
    }
    let size = across_minus_along
        .iter()
        .fold(0.0f64, |m, c| m.max(c.abs()));
    size > 0.0
        && across_minus_along.iter().all(|&c| c >= -1e-12 * size)
        && across_minus_along.iter().any(|&c| c > 1e-12 * size)
}

impl Family {
    /// The gap its members solve, without looking up its seed (usable while
    /// the registry is being read; `conformal` adds the seed).
    pub(crate) fn unseeded_gap(&self) -> Gap {
        Gap {
            name: self.name,
            particular: self.particular_terms,
            seed: None,
        }
    }
}

/// One slender model as the generator registers it: its name and title,
/// and its generated functions.
#[derive(Debug)]
pub(crate) struct SlenderModel {
    /// The model's name (its family file's `name`).
    pub name: &'static str,
    /// One line for reports.
    pub title: &'static str,
    /// D(β) and D′(β): a strip's local approach in the slender units.
    pub approach: fn(f64) -> [f64; 2],
    /// G(β₀) and dG/dβ₀: the total force in the slender units (the
    /// generated kernel integrated over φ by the generated rule).
    pub force: fn(f64) -> [f64; 2],
    /// The largest β₀ the functions are checked for.
    pub beta0_max: f64,
}
