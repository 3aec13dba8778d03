//! The layer of finite thickness at ρ = 1: JKR adhesive contact of two
//! elastic coatings of finite thickness (each bonded to its rigid
//! cylinder, the two in frictionless contact) on crossed equal cylinders at
//! 90°, the gap r²/2R of a sphere on a flat. It measures the thin-layer
//! equation (2) that every other model of thinjkr solves: (2) is this
//! problem's limit as h/L → 0, and JKR's half-space contact its limit as
//! h/L → ∞.
//!
//! The coatings' surface compliance is the kernel derived from
//! three-dimensional elasticity in `thinjkr_derive::layer` (docs/derivation.md,
//! Step 0). The paper's coatings are transversely isotropic with
//! out-of-plane shear modulus G′; here each coating is isotropic, and G′ is
//! read as its G. The units are those of (17) at ρ = 1, with m of (4):
//! lengths in L = (2R²Δγ/m)^(1/6), the approach in L²/R, the force in 2RΔγ;
//! h/L is a coating's thinness.
//!
//! A state at contact radius ā solves (L1) of `galerkin` for g₁ and g₂,
//! and the approach δ̄ follows from Griffith's condition at the edge (the
//! energy release rate equals Δγ): g(ā) = −½√(2πāβ), where g(ā) measures
//! the stress-intensity factor, K = −2g(ā)/√(πā) in the units of g. The
//! force is F̄ = 4∫₀ᵃ g dt. A second route, `energy`, finds δ̄ from the
//! elastic energy instead (∂Ū/∂ā = πā at fixed δ̄) and is held against the
//! first in the tests.
//!
//! At ρ < 1 the contact is not axisymmetric: `plane` gives the pull-off
//! under load control in the plane, [`PlaneState`] (issue 71), by the
//! sharp edge (`sharp`: JKR's edge kept sharp, the contact's outline
//! solved for; it reproduces this module's states at ρ = 1) where its
//! ladder converges, else by the grid solver (`grid`: a cohesive law
//! shrunk toward JKR's edge), which also gives the state at a force.
//!
//! Coatings thin against the contact, below the grid's reach, are taken at
//! first order in h/L at any ρ by `thin`: (2)'s exact pull-off with the
//! layer's edge as a line tension. `line_tension` solves that line tension
//! whole, not linearised: the layer's pull-off to third order in h/L at
//! ρ = 1 and 0.8, and with the interior's approach shift its state at a
//! given approach or force.
//!
//! Owns: [`Coating`], [`Layers`], [`Route`], [`LayerState`], [`LayerPullOff`], [`Verdicts`], `Controlled`. May use:
//! `control` (what a state is held at), `error`, `quadrature` (Gauss–Legendre), `generated` (the layer's kernel), `model` (Brent's minimum),
//! `exact` (the exact solution of (2), in `thin`).

mod bessel;
mod energy;
mod galerkin;
// the first order in h/L at any ρ (issue 71): where the grid does not reach
#[allow(dead_code)]
pub(crate) mod thin;
// (2) with the edge's line tension kept whole, the first order's model
#[allow(dead_code)]
pub(crate) mod line_tension;
// the sharp edge at ρ < 1 (issue 71): the free edge and its pull-off,
// which `plane` answers with
pub(crate) mod sharp;
#[cfg(feature = "bench-internals")]
pub mod sharp_bench;
// the grid solver of issue 71: its states in the plane answer through
// the model layer (`plane`); the straight edge's undulations are tested
// here
#[allow(dead_code)]
pub(crate) mod grid;
// the model layer's answer in the plane: the sharp edge's pull-off, else
// the grid's
pub(crate) mod plane;
pub use plane::{Held, Method, PlaneRung, PlaneState};

use crate::control::Hold;
use crate::error::{check_range, rounded, short, Error, Result};
use crate::generated::layer_kernel::base_share_at;
use crate::model::brent_minimum;
use serde::{Deserialize, Serialize};
use std::cell::RefCell;

/// The thinnest coating the layer solver takes, h/L: its cost grows as
/// (L/h)² (quadrature nodes ∝ L/h, Legendre modes ∝ (L/h)^½), 2.8 s for a
/// pull-off at h/L = 0.01; for incompressible coatings (2)'s pull-off is
/// within 0.07 % of the layer's below it.
pub(crate) const THINNEST: f64 = 1e-3;
/// The thickest coating, h/L: the pull-off under load control is JKR's to
/// round-off from h/L ≈ 100 on (its excess falls as (h/L)⁻⁶).
pub(crate) const THICKEST: f64 = 1e4;
/// The largest of the last Legendre coefficients, relative, that a state
/// may have: its truncation.
const TAIL_MAX: f64 = 1e-12;

/// One coating: thinness h/L in the units (17), shear modulus G (any unit,
/// only the two coatings' ratio enters) and Poisson's ratio ν.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct Coating {
    /// Thickness h over the length unit L of (17).
    pub thinness: f64,
    /// Shear modulus G (G′ of the paper read as the isotropic G).
    pub shear_modulus: f64,
    /// Poisson's ratio ν, in [0, ½].
    pub nu: f64,
}

/// How a state's approach is found from its contact radius.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Route {
    /// Griffith's condition at the edge: the stress-intensity factor.
    Griffith,
    /// The energy balance ∂Ū/∂ā = πā at fixed approach (module `energy`).
    Energy,
}

/// Two coatings in contact at ρ = 1: the layer model's contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layers {
    coatings: [Coating; 2],
    /// Each coating's share of the pair's half-space compliance (1 − ν)/G.
    weights: [f64; 2],
    /// Quadrature panels this many times finer than `galerkin`'s rule.
    refine: f64,
    /// E*/(2mL³): the pair's half-space modulus in the units (17).
    beta: f64,
}

/// A state of the layer model, in the units (17) at ρ = 1.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct LayerState {
    /// Contact radius ā.
    pub a_bar: f64,
    /// Approach δ̄.
    pub delta_bar: f64,
    /// Force F̄ (compressive positive).
    pub force_bar: f64,
    /// dF̄/dā along the branch: the state is stable under load control
    /// where it is positive.
    pub force_slope: f64,
    /// dδ̄/dā along the branch: the state is stable under displacement
    /// control where it is positive.
    pub delta_slope: f64,
    /// Legendre modes used.
    pub modes: usize,
    /// Truncation: the last Legendre coefficients over the largest.
    pub tail: f64,
    /// The two coatings.
    pub coatings: [Coating; 2],
    /// What the coatings are, in words every output of the layer gives:
    /// isotropic, the paper's out-of-plane G′ read as their shear modulus.
    pub coatings_are: &'static str,
    /// Its stability on the branch under each control, from the slopes.
    pub verdicts: Verdicts,
}

/// A state's stability on its branch under one control: from the sign of
/// its slope along the branch (dF̄/dā under load control, dδ̄/dā under
/// displacement control); neutral where that slope is zero, at the
/// pull-off under that control.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// The slope is positive.
    Stable,
    /// The slope is zero: a pull-off under this control.
    Neutral,
    /// The slope is negative.
    Unstable,
}

impl Verdict {
    /// The verdict of a slope along the branch, neutral within `zero` of
    /// 0; none where the slope is not known (NaN).
    pub(crate) fn of_slope(slope: f64, zero: f64) -> Option<Verdict> {
        if slope.is_nan() {
            None
        } else if slope.abs() <= zero {
            Some(Verdict::Neutral)
        } else if slope > 0.0 {
            Some(Verdict::Stable)
        } else {
            Some(Verdict::Unstable)
        }
    }

    /// In the words every front end shows.
    #[cfg_attr(not(feature = "cli"), allow(dead_code))]
    pub(crate) fn words(self) -> &'static str {
        match self {
            Verdict::Stable => "stable",
            Verdict::Neutral => "neutral (a pull-off)",
            Verdict::Unstable => "unstable",
        }
    }
}

/// A state's stability on its branch under each control (`None` where it
/// is not judged).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct Verdicts {
    /// Under load control.
    pub load: Option<Verdict>,
    /// Under displacement control.
    pub displacement: Option<Verdict>,
}

impl Verdicts {
    /// In words, the controls judged only: "load control: stable,
    /// displacement control: neutral (a pull-off)".
    #[cfg_attr(not(feature = "cli"), allow(dead_code))]
    pub(crate) fn words(&self) -> String {
        let judged: Vec<String> = [("load", self.load), ("displacement", self.displacement)]
            .into_iter()
            .filter_map(|(control, v)| v.map(|v| format!("{control} control: {}", v.words())))
            .collect();
        if judged.is_empty() {
            "stability not judged".into()
        } else {
            judged.join(", ")
        }
    }
}

/// [`LayerState::coatings_are`].
pub(crate) const COATINGS_ARE: &str = "coatings of finite thickness at rho = 1, from three-dimensional elasticity (docs/thickness.md); G' is read as each coating's isotropic shear modulus G";

/// The pull-offs of the layer model: the minimum of F̄ along the branch
/// (load control) and of δ̄ (displacement control).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct LayerPullOff {
    /// Under load control.
    pub load: LayerState,
    /// Under displacement control.
    pub displacement: LayerState,
}

impl Layers {
    /// Two coatings; each thinness in [0.001, 10⁴] (`THINNEST`, `THICKEST`), each
    /// shear modulus positive and finite, each ν in [0, ½].
    pub fn new(first: Coating, second: Coating) -> Result<Layers> {
        for (c, (thin, g, nu)) in [first, second]
            .iter()
            .zip([("h1/L", "g1", "nu1"), ("h2/L", "g2", "nu2")])
        {
            check_range(thin, c.thinness, c.thinness > 0.0, "(0, ∞)")?;
            if !(THINNEST..=THICKEST).contains(&c.thinness) {
                return Err(Error::Unsupported {
                    name: thin,
                    value: c.thinness,
                    supported: format!(
                        "[{}, {}] (thinner coatings cost too much; thicker ones are JKR's half-spaces)",
                        short(THINNEST),
                        short(THICKEST)
                    )
                    .into(),
                });
            }
            check_range(g, c.shear_modulus, c.shear_modulus > 0.0, "(0, ∞)")?;
            check_range(nu, c.nu, (0.0..=0.5).contains(&c.nu), "[0, 0.5]")?;
        }
        let compliance = |c: &Coating| (1.0 - c.nu) / c.shear_modulus;
        let total = compliance(&first) + compliance(&second);
        let cubes = first.thinness.powi(3) / first.shear_modulus
            + second.thinness.powi(3) / second.shear_modulus;
        Ok(Layers {
            coatings: [first, second],
            weights: [compliance(&first) / total, compliance(&second) / total],
            beta: cubes / (3.0 * total),
            refine: 1.0,
        })
    }

    /// Two equal coatings of thinness h/L and Poisson's ratio ν.
    pub fn equal(thinness: f64, nu: f64) -> Result<Layers> {
        let c = Coating {
            thinness,
            shear_modulus: 1.0,
            nu,
        };
        Layers::new(c, c)
    }

    /// The two coatings.
    pub(crate) fn coatings(&self) -> [Coating; 2] {
        self.coatings
    }

    pub(crate) fn beta(&self) -> f64 {
        self.beta
    }

    pub(crate) fn thinnest(&self) -> f64 {
        self.coatings[0].thinness.min(self.coatings[1].thinness)
    }

    pub(crate) fn thickest(&self) -> f64 {
        self.coatings[0].thinness.max(self.coatings[1].thinness)
    }

    /// Φ of the pair at wave number k̄ (units 1/L): each coating's base
    /// share weighted by its share of the compliance.
    pub(crate) fn base_share(&self, k: f64) -> f64 {
        self.coatings
            .iter()
            .zip(self.weights)
            .map(|(c, w)| w * base_share_at(k * c.thinness, c.nu))
            .sum()
    }

    /// g₁ and g₂ of (L1) at ā, with their slopes in ā, resolved: the
    /// modes of `galerkin::modes_for`, raised by half until the truncation is
    /// below [`TAIL_MAX`].
    pub(crate) fn resolved(&self, a_bar: f64) -> Result<galerkin::Solution> {
        let mut modes = galerkin::modes_for(self, a_bar);
        loop {
            let solution = galerkin::solve_with(self, a_bar, modes, self.refine, true)?;
            let tail = solution.tail();
            if tail < TAIL_MAX {
                return Ok(solution);
            }
            if modes >= galerkin::MODES_MAX {
                return Err(Error::Unresolved {
                    what: format!(
                        "the layer at a_bar = {}, h/L = {}: {modes} Legendre modes leave a truncation of {}",
                        rounded(a_bar),
                        short(self.thinnest()),
                        short(tail)
                    ),
                    residual: tail,
                });
            }
            modes = (modes * 3 / 2).min(galerkin::MODES_MAX);
        }
    }

    /// The state held at `hold` found by `route`: at a contact radius ā
    /// (positive), F̄(ā) and δ̄(ā); at a force F̄ (F̄ = 0: zero force), the
    /// state on the branch stable under load control (ā beyond the pull-off),
    /// none below the pull-off force; at an approach δ̄, the state on the
    /// branch stable under displacement control, none below the smallest
    /// approach.
    pub fn state(&self, hold: Hold, route: Route) -> Result<LayerState> {
        let hold = hold.check_finite()?;
        let at = |a: f64| self.at_radius(a, route);
        match hold {
            Hold::Size(a_bar) => {
                check_range("a", a_bar, a_bar > 0.0, "(0, ∞)")?;
                at(a_bar)
            }
            Hold::Force(force_bar) => self.beyond(route, true, force_bar),
            Hold::Delta(delta_bar) => self.beyond(route, false, delta_bar),
        }
    }

    /// The state on the branch beyond the pull-off under load control
    /// (`load`, at force `value`) or displacement control (at approach
    /// `value`), where it is stable under that control; none below the
    /// pull-off's value.
    fn beyond(&self, route: Route, load: bool, value: f64) -> Result<LayerState> {
        let Controlled { quantity, of, .. } = Controlled::under(load);
        let pull = self.pull_off_under(route, load)?;
        if value < of(&pull) {
            return Err(Error::NoState(format!(
                "the {quantity} {} is below the layer's pull-off {quantity} {}",
                short(value),
                short(of(&pull))
            )));
        }
        let at = |a: f64| self.at_radius(a, route);
        at(root(|a| Ok(of(&at(a)?)), pull.a_bar, value, quantity)?)
    }

    /// The state of contact radius ā found by `route`.
    pub(crate) fn at_radius(&self, a_bar: f64, route: Route) -> Result<LayerState> {
        match route {
            Route::Griffith => Ok(self.griffith(&self.resolved(a_bar)?)),
            Route::Energy => energy::by_energy(self, a_bar),
        }
    }

    /// δ̄ and F̄ of a solution by Griffith's condition at its edge, and
    /// their slopes along the branch.
    fn griffith(&self, s: &galerkin::Solution) -> LayerState {
        let a = s.a_bar;
        let (e1, e2) = s.edge();
        let edge = -0.5 * (2.0 * std::f64::consts::PI * a * self.beta).sqrt();
        let delta_bar = (e2 + edge) / e1;
        let (i1, i2) = s.integral();
        let (force_slope, delta_slope) = match &s.slopes {
            Some((d1, d2)) => {
                // g(ā) = δ̄e₁ − e₂ = edge(ā) along the branch, ∫g = ā c₀
                let (de1, de2) = (d1.sum(), d2.sum());
                let delta_slope = (de2 + 0.5 * edge / a - delta_bar * de1) / e1;
                let (di1, di2) = (s.g1[0] + a * d1[0], s.g2[0] + a * d2[0]);
                (
                    4.0 * (delta_slope * i1 + delta_bar * di1 - di2),
                    delta_slope,
                )
            }
            None => (f64::NAN, f64::NAN),
        };
        let force_bar = 4.0 * (delta_bar * i1 - i2);
        // a pull-off is neutral under its control: its slope is zero to the
        // solution's round-off (1e-9 of the scale ā/F̄ or ā/δ̄ at h/L = 0.01)
        let zero = |of: f64| 1e-7 * of.abs().max(1.0) / a;
        LayerState {
            a_bar: a,
            delta_bar,
            force_bar,
            force_slope,
            delta_slope,
            modes: s.g1.len(),
            tail: s.tail(),
            coatings: self.coatings,
            coatings_are: COATINGS_ARE,
            verdicts: Verdicts {
                load: Verdict::of_slope(force_slope, zero(force_bar)),
                displacement: Verdict::of_slope(delta_slope, zero(delta_bar)),
            },
        }
    }

    /// A first contact radius to search from: the smaller of the pull-off
    /// radii of the two limits, (2)'s 12^(1/3) and JKR's (9π/32β)^(1/3).
    pub(crate) fn radius_guess(&self) -> f64 {
        let jkr = (9.0 * std::f64::consts::PI / (32.0 * self.beta)).cbrt();
        jkr.min(12f64.cbrt())
    }

    /// The pull-offs found by `route`: by Griffith's, the roots of the
    /// slopes dF̄/dā and dδ̄/dā (the contact radius to round-off); by the
    /// energy, the minima of F̄ and δ̄ by Brent's method (the force and
    /// approach to round-off, the radius to about 1e-7 of itself).
    pub fn pull_off(&self, route: Route) -> Result<LayerPullOff> {
        Ok(LayerPullOff {
            load: self.pull_off_under(route, true)?,
            displacement: self.pull_off_under(route, false)?,
        })
    }

    /// The pull-off under load control (`load`) or displacement control.
    fn pull_off_under(&self, route: Route, load: bool) -> Result<LayerState> {
        let guess = self.radius_guess();
        let Controlled {
            quantity,
            of,
            slope,
        } = Controlled::under(load);
        let a = match route {
            Route::Griffith => root(
                |a| Ok(slope(&self.at_radius(a, route)?)),
                guess,
                0.0,
                &format!("{quantity}'s slope"),
            )?,
            Route::Energy => minimum(|a| Ok(of(&energy::by_energy(self, a)?)), guess, quantity)?,
        };
        self.at_radius(a, route)
    }
}

/// The quantity a control holds, read from a state: its name, its value
/// and its slope along the branch.
struct Controlled {
    quantity: &'static str,
    of: fn(&LayerState) -> f64,
    slope: fn(&LayerState) -> f64,
}

impl Controlled {
    /// The force under load control (`load`), else the approach.
    fn under(load: bool) -> Controlled {
        if load {
            Controlled {
                quantity: "force",
                of: |s| s.force_bar,
                slope: |s| s.force_slope,
            }
        } else {
            Controlled {
                quantity: "approach",
                of: |s| s.delta_bar,
                slope: |s| s.delta_slope,
            }
        }
    }
}

/// The contact radius where the increasing function `f` of ā reaches
/// `target`, ā ≥ `from`: bracketed by factors of 1.25 from `from` (upwards
/// where f(from) < target, downwards otherwise), then the Illinois method to
/// round-off in ā.
pub(crate) fn root(
    f: impl Fn(f64) -> Result<f64>,
    from: f64,
    target: f64,
    what: &str,
) -> Result<f64> {
    const STEP: f64 = 1.25;
    const STEPS: usize = 80;
    let g = |a: f64| Ok::<f64, Error>(f(a)? - target);
    let (mut lo, mut hi) = (from, from);
    let mut f_lo = g(from)?;
    let mut f_hi;
    if f_lo == 0.0 {
        return Ok(from);
    }
    let up = f_lo < 0.0;
    let mut steps = 0;
    loop {
        steps += 1;
        if steps > STEPS {
            return Err(Error::NoState(format!(
                "the layer's {what} does not reach {} between ā = {} and {}",
                short(target),
                rounded(lo.min(hi)),
                rounded(lo.max(hi))
            )));
        }
        if up {
            hi = lo * STEP;
            f_hi = g(hi)?;
            if f_hi >= 0.0 {
                break;
            }
            (lo, f_lo) = (hi, f_hi);
        } else {
            (hi, f_hi) = (lo, f_lo);
            lo /= STEP;
            f_lo = g(lo)?;
            if f_lo <= 0.0 {
                break;
            }
        }
    }
    match illinois(g, (lo, f_lo), (hi, f_hi), |lo, hi| (hi - lo).abs() <= 1e-14 * hi.abs(), 0.0, 200)? {
        Ok(a) => Ok(a),
        Err((lo, hi)) => Err(Error::Unresolved {
            what: format!(
                "the layer's {what} reaches {} somewhere between a_bar = {} and {}, not located to 1e-14 in 200 steps",
                short(target),
                rounded(lo.min(hi)),
                rounded(lo.max(hi))
            ),
            residual: (hi - lo).abs() / hi.abs(),
        }),
    }
}

/// The Illinois method (regula falsi, halving the weight of an end kept
/// twice; bisection where round-off puts the new point on an end) on `g`
/// between `lo` and `hi`, where it takes the values `g_lo` and `g_hi` of
/// opposite signs: the end nearer zero once `settled(lo, hi)`, a point
/// where |g| ≤ `tolerance`; else, after `steps` steps, the last bracket
/// (as the inner error).
pub(crate) fn illinois(
    mut g: impl FnMut(f64) -> Result<f64>,
    (mut lo, mut g_lo): (f64, f64),
    (mut hi, mut g_hi): (f64, f64),
    settled: impl Fn(f64, f64) -> bool,
    tolerance: f64,
    steps: usize,
) -> Result<std::result::Result<f64, (f64, f64)>> {
    let mut side = 0;
    for _ in 0..steps {
        if settled(lo, hi) {
            return Ok(Ok(if g_lo.abs() < g_hi.abs() { lo } else { hi }));
        }
        for (x, gx) in [(lo, g_lo), (hi, g_hi)] {
            if gx.abs() <= tolerance {
                return Ok(Ok(x));
            }
        }
        let mut a = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
        if !(a > lo.min(hi) && a < lo.max(hi)) {
            a = 0.5 * (lo + hi);
        }
        let g_a = g(a)?;
        if g_a.abs() <= tolerance {
            return Ok(Ok(a));
        }
        if g_a * g_lo > 0.0 {
            (lo, g_lo) = (a, g_a);
            if side == -1 {
                g_hi *= 0.5;
            }
            side = -1;
        } else {
            (hi, g_hi) = (a, g_a);
            if side == 1 {
                g_lo *= 0.5;
            }
            side = 1;
        }
    }
    Ok(Err((lo, hi)))
}

/// The contact radius of the minimum of `f` along the branch: bracketed
/// downhill from `guess` by factors of 1.25, then Brent's minimum.
pub(crate) fn minimum(f: impl Fn(f64) -> Result<f64>, guess: f64, what: &str) -> Result<f64> {
    const STEP: f64 = 1.25;
    const STEPS: usize = 60;
    let failed = RefCell::new(None);
    let value = |a: f64| match f(a) {
        Ok(v) => v,
        Err(e) => {
            failed.borrow_mut().get_or_insert(e);
            f64::NAN
        }
    };
    let (mut lo, mut mid) = (guess / STEP, guess);
    let (mut f_lo, mut f_mid) = (value(lo), value(mid));
    let mut hi = guess * STEP;
    let mut f_hi = value(hi);
    let mut steps = 0;
    while !(f_mid <= f_lo && f_mid <= f_hi) {
        if let Some(e) = failed.borrow_mut().take() {
            return Err(e);
        }
        steps += 1;
        if steps > STEPS {
            return Err(Error::NoState(format!(
                "the layer's {what} has no minimum between ā = {} and {}",
                rounded(lo),
                rounded(hi)
            )));
        }
        if f_hi < f_lo {
            (lo, f_lo, mid, f_mid) = (mid, f_mid, hi, f_hi);
            hi *= STEP;
            f_hi = value(hi);
        } else {
            (hi, f_hi, mid, f_mid) = (mid, f_mid, lo, f_lo);
            lo /= STEP;
            f_lo = value(lo);
        }
    }
    let a = brent_minimum(value, lo, hi, 1e-7 * mid);
    match failed.into_inner() {
        Some(e) => Err(e),
        None => Ok(a),
    }
}

/// `value` as `printed` in docs/thickness.md, to half a unit of its
/// last printed digit: "−" for minus, "%" (a hundredth), bold marks,
/// e-notation, and "< x" (below x).
#[cfg(test)]
pub(crate) fn as_printed(value: f64, printed: &str) -> bool {
    let p = printed.replace('−', "-").replace("**", "");
    let p = p.trim();
    let (p, value) = match p.strip_suffix('%') {
        Some(p) => (p.trim(), 100.0 * value),
        None => (p, value),
    };
    if let Some(bound) = p.strip_prefix('<') {
        return value.abs() < bound.trim().parse::<f64>().expect("a number");
    }
    let number: f64 = p.parse().expect("a number");
    let (mantissa, exponent) = match p.split_once('e') {
        Some((m, e)) => (m, e.parse::<i32>().expect("an exponent")),
        None => (p, 0),
    };
    let decimals = mantissa.split_once('.').map_or(0, |(_, d)| d.len()) as i32;
    (value - number).abs() <= 0.5 * 10f64.powi(exponent - decimals) * (1.0 + 1e-9)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The verdicts every front end shows (issue 71): each pull-off is
    /// neutral under its own control and the other control's verdict is
    /// its slope's sign; a state between the two pull-offs is unstable
    /// under load control and stable under displacement control, one
    /// above both stable under both, one below the least approach
    /// unstable under both: the signs of its slopes.
    #[test]
    fn pull_offs_are_neutral_under_their_control_and_states_take_their_slopes_signs() {
        use Verdict::{Neutral, Stable, Unstable};
        let layers = Layers::equal(1.0, 0.5).unwrap();
        let po = layers.pull_off(Route::Griffith).unwrap();
        let judged = |v: Verdicts| (v.load.unwrap(), v.displacement.unwrap());
        assert_eq!(judged(po.load.verdicts), (Neutral, Stable));
        assert_eq!(judged(po.displacement.verdicts), (Unstable, Neutral));
        let (least, most) = (po.displacement.a_bar, po.load.a_bar);
        for (a, expected) in [
            (1.5 * most, (Stable, Stable)),
            (0.5 * (least + most), (Unstable, Stable)),
            (0.7 * least, (Unstable, Unstable)),
        ] {
            let st = layers.at_radius(a, Route::Griffith).unwrap();
            assert_eq!(judged(st.verdicts), expected, "at a = {a}: {st:?}");
            assert_eq!(st.force_slope > 0.0, expected.0 == Stable);
            assert_eq!(st.delta_slope > 0.0, expected.1 == Stable);
        }
        // the energy route gives no slopes, and judges nothing
        let st = layers.at_radius(most, Route::Energy).unwrap();
        assert_eq!((st.verdicts.load, st.verdicts.displacement), (None, None));
        assert_eq!(st.verdicts.words(), "stability not judged");
    }

    /// The state at a contact radius moves by less than 1e-10 (relative)
    /// when the quadrature's panels are halved and the modes raised by half,
    /// and the error of fewer modes falls geometrically (the convergence
    /// table of the Legendre truncation). 1e-10 is above the solution's
    /// round-off, which grows with the system's condition, about (ā/h)³: the
    /// force scatters by 4e-11 over changes of ā by 1e-9 at h/L = 0.03
    /// (1e-11 relative), by 1e-9 at h/L = 0.01.
    #[test]
    fn the_discretisation_is_converged_and_converges_geometrically() {
        for (h, a) in [(0.03, 2.2), (0.3, 1.8), (3.0, 0.4)] {
            let layers = Layers::equal(h, 0.5).unwrap();
            let n = galerkin::modes_for(&layers, a);
            let state = |modes: usize, refine: f64| {
                layers.griffith(&galerkin::solve_with(&layers, a, modes, refine, true).unwrap())
            };
            let base = state(n, 1.0);
            let fine = state(n * 3 / 2, 2.0);
            let scale = base.force_bar.abs().max(1.0);
            assert!(
                (base.force_bar - fine.force_bar).abs() < 1e-10 * scale,
                "h {h}: {base:?} against {fine:?}"
            );
            assert!(
                (base.delta_bar - fine.delta_bar).abs() < 1e-10 * base.delta_bar.abs().max(1.0),
                "h {h}: {base:?} against {fine:?}"
            );
            // a quarter and a half of the modes: errors falling geometrically
            let errors: Vec<f64> = [n / 4, n / 2]
                .iter()
                .map(|&m| (state(m, 1.0).force_bar - fine.force_bar).abs() / scale)
                .collect();
            assert!(
                errors[0] > 1e3 * errors[1].max(1e-16),
                "h {h}: errors {errors:?} with {} and {} modes",
                n / 4,
                n / 2
            );
        }
    }
}
