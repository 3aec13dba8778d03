//! The layer's answer in the plane (issue 71): a state of two coatings at
//! any ρ, with how far to trust it and how it was found ([`Method`]).
//!
//! The pull-off under load control is the sharp edge's (`by_sharp_edge`:
//! JKR's edge kept sharp, the contact's outline solved for), where its
//! ladder of functions converges and its force bound is at most
//! [`WORST_FORCE_ERROR`]; elsewhere (a rung that finds no state, or rungs
//! that do not converge, as at θ = 30° with equal cylinders) the grid
//! solver's (`by_grid`: a cohesive law shrunk toward JKR's edge), where
//! it reaches the coatings. A state at a force is found the same way (the
//! sharp edge's, else the grid's); a state at an approach or a size and
//! the pull-off under displacement control by the sharp edge alone.
//!
//! Owns: [`PlaneState`], [`PlaneRung`], [`Held`], [`Method`], [`state`],
//! [`pull_off`], [`WORST_FORCE_ERROR`], [`PULL_OFF_REACH`],
//! [`beyond_reach`]; it passes on `by_sharp_edge`'s `pull_off_displacement`
//! and `curve`. May use: its own `by_grid` and `by_sharp_edge`, and
//! through them `layer` (the pair, `grid`, `sharp`), `control` (the hold),
//! `error`, `progress` (the rung a spinner shows), `newton` (the stop
//! request).

pub(crate) mod by_grid;
pub(crate) mod by_sharp_edge;

// the sharp edge's alone (the grid locates no pull-off under displacement
// control and holds no size)
pub(crate) use by_sharp_edge::{curve, pull_off_displacement};

use crate::control::Hold;
use crate::error::{short, Result};
use crate::layer::{Coating, Layers, Verdict, Verdicts};
use serde::Serialize;

/// The largest bound on the force's relative error an answer may have.
pub(crate) const WORST_FORCE_ERROR: f64 = 0.02;

/// The bound above which an answer carries a warning: within 1 % or
/// worse, the force is too rough to tell coatings apart by.
pub(crate) const WARN_FORCE_ERROR: f64 = 0.01;

/// The coatings whose pull-off at ρ < 1 is measured, h/L of each: from
/// 0.3, the sharp edge's (its rungs within 8.7e-4 of each other at
/// ρ = 0.2, docs/thickness.md), to 10, the grid's and the sharp edge's.
/// A state at a force takes the grid's reach ([`by_grid::REACH`]).
pub(crate) const PULL_OFF_REACH: (f64, f64) = (by_sharp_edge::REACH.0, by_grid::REACH.1);

/// One rung of the ladder: its resolution (the grid's process zone and
/// cells, or the sharp edge's functions) and its state.
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct PlaneRung {
    /// The grid's process zone ε, a fraction of the size scale (none on
    /// the sharp edge).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub eps: Option<f64>,
    /// Cells per side of the grid (none on the sharp edge).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cells: Option<usize>,
    /// The sharp edge's functions of the pressure, radial × angular, with
    /// as many modes of the edge as angular orders (none on the grid).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub functions: Option<[usize; 2]>,
    /// The force F̄ on this rung.
    pub force_bar: f64,
    /// Its approach δ̄.
    pub delta_bar: f64,
    /// Its half width along X (on the grid where the gap reaches the
    /// law's range).
    pub a_bar: f64,
    /// Its half width along Y.
    pub b_bar: f64,
}

/// What a state of the layer in the plane is held at.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum Held {
    /// The pull-off under load control: the least force on the branch a
    /// loaded contact follows under displacement control.
    PullOff,
    /// An approach δ̄, on the branch stable under displacement control.
    Delta,
    /// A force F̄, on the branch stable under load control.
    Force,
    /// A half-width ā along X, anywhere on the branch from large loads.
    Size,
    /// The pull-off under displacement control: the least approach on
    /// the branch.
    DisplacementPullOff,
}

impl Held {
    /// The stability on its branch of a state so held: a pull-off is
    /// neutral under its own control (and the one under displacement
    /// control unstable under load control), a state at an approach or a
    /// force lies on the branch stable under that control, and a state at a
    /// size is judged by its slopes dF̄/dā and dδ̄/dā, where it has them.
    pub(crate) fn verdicts(self, slopes: Option<[f64; 2]>) -> Verdicts {
        use Verdict::{Neutral, Stable, Unstable};
        let (load, displacement) = match (self, slopes) {
            (Held::PullOff, _) => (Some(Neutral), None),
            (Held::DisplacementPullOff, _) => (Some(Unstable), Some(Neutral)),
            (Held::Delta, _) => (None, Some(Stable)),
            (Held::Force, _) => (Some(Stable), None),
            (Held::Size, Some([force, delta])) => {
                (Verdict::of_slope(force, 0.0), Verdict::of_slope(delta, 0.0))
            }
            (Held::Size, None) => (None, None),
        };
        Verdicts { load, displacement }
    }
}

/// How a state in the plane is found.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum Method {
    /// JKR's edge kept sharp, on a contact whose outline is solved for,
    /// on a ladder of functions (the pull-off where it resolves it).
    SharpEdge,
    /// The grid solver: a cohesive law shrunk toward JKR's edge on a
    /// ladder of process zones, the force extrapolated to its limit.
    Grid,
}

/// A state of the layer at any ρ, by the sharp edge or the grid solver
/// (see the module).
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct PlaneState {
    /// Radii ratio ρ.
    pub rho: f64,
    /// What the state is held at.
    pub held: Held,
    /// How it is found.
    pub method: Method,
    /// The force F̄: the held one, else the JKR limit through the three
    /// finest rungs.
    pub force_bar: f64,
    /// The bound on F̄'s relative error: on the grid twice the relative
    /// difference of the two three-rung limits (at an approach relative to
    /// the force unit where |F̄| is below 1), on the sharp edge twice that
    /// of the two finest rungs; 0 where F̄ is held.
    pub force_error: f64,
    /// The check: on the grid the JKR limit through the three coarsest
    /// rungs, on the sharp edge the force of the rung before the finest
    /// (the held force where it is held).
    pub force_bar_coarse: f64,
    /// Half width along X, the finest rung's.
    pub a_bar: f64,
    /// Half width along Y, the finest rung's.
    pub b_bar: f64,
    /// Aspect ratio b̄/ā.
    pub s: f64,
    /// Approach δ̄: the held one, else the finest rung's.
    pub delta_bar: f64,
    /// The bound on ā's and b̄'s relative error: their spread over the
    /// three finest rungs, relative, the larger (on the grid at least
    /// 0.5 %, the half width's bias at a held force, which the spread does
    /// not show).
    pub size_error: f64,
    /// The bound on δ̄'s error: its spread over the three finest rungs (0
    /// where δ̄ is held).
    pub delta_error: f64,
    /// The ladder's rungs, coarsest first.
    pub rungs: Vec<PlaneRung>,
    /// On the sharp edge, the largest departure of the finest rung's edge
    /// from Griffith's condition, |K/√(2β) − 1| at 65 points of the quarter.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub griffith_error: Option<f64>,
    /// At a held size and at the pull-off under displacement control, the
    /// slopes dF̄/dā and dδ̄/dā along the branch on the finest rung
    /// (central differences over 1e-4 ā): the contact is stable under load
    /// control where the first is positive, under displacement control
    /// where the second is (near zero at that pull-off).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub slopes: Option<[f64; 2]>,
    /// Its stability on the branch under each control: what it is held at
    /// says it, or at a size its slopes do (`Held::verdicts`).
    pub verdicts: Verdicts,
    /// The two coatings.
    pub coatings: [Coating; 2],
    /// What the coatings are and how the answer is found, in words every
    /// output gives.
    pub coatings_are: &'static str,
    /// Why the answer is doubtful, in the words every front end shows
    /// (empty when it is not).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
}

/// [`PlaneState::coatings_are`] on the grid.
pub(crate) const ON_THE_GRID: &str = "coatings of finite thickness in the plane, by the grid solver: a cohesive law shrunk toward JKR's sharp edge on a ladder of process zones, the force extrapolated to its limit (docs/thickness.md); G' is read as each coating's isotropic shear modulus G";

/// [`PlaneState::coatings_are`] on the sharp edge.
pub(crate) const WITH_A_SHARP_EDGE: &str = "coatings of finite thickness in the plane, with JKR's sharp edge: the contact's outline solved for with Griffith's condition along it, on a ladder of functions of the pressure (docs/thickness.md); G' is read as each coating's isotropic shear modulus G";

impl PlaneState {
    /// How far to trust it, in a line: the bounds and where they come from.
    #[cfg_attr(not(feature = "cli"), allow(dead_code))]
    pub(crate) fn trust_words(&self) -> String {
        let mut within = vec![format!(
            "size within {} %",
            two_digits(100.0 * self.size_error)
        )];
        if self.held != Held::Force {
            within.insert(
                0,
                format!("force within {} %", two_digits(100.0 * self.force_error)),
            );
        }
        if self.held != Held::Delta {
            within.push(format!("delta within {}", two_digits(self.delta_error)));
        }
        let (first, last) = (&self.rungs[0], &self.rungs[self.rungs.len() - 1]);
        let ladder = match (self.method, first.functions, last.functions) {
            (Method::SharpEdge, Some([r0, a0]), Some([r1, a1])) => format!(
                "the finest of {} states with a sharp edge, from {r0} x {a0} to {r1} x {a1} functions of the pressure",
                self.rungs.len()
            ),
            _ => format!(
                "{} {} states with cohesive process zones from {} to {} of the contact",
                if self.held == Held::Force {
                    "the finest of"
                } else {
                    "the force the JKR limit, the rest the finest, of"
                },
                self.rungs.len(),
                first.eps.map_or_else(|| "-".into(), short),
                last.eps.map_or_else(|| "-".into(), short)
            ),
        };
        format!("{}: {ladder}", within.join(", "))
    }
}

/// A bound for a person: two significant digits.
fn two_digits(x: f64) -> String {
    if !(x.is_finite() && x > 0.0) {
        return short(x);
    }
    let decimals = (1.0 - x.log10().floor()).max(0.0) as usize;
    format!("{x:.decimals$}")
}

/// The pull-off under load control of `layers` at `rho` ∈ (0, 1]: the
/// sharp edge's where it answers, else the grid solver's (see the
/// module). An error where neither answers (the sharp edge's reason with
/// the grid's).
pub(crate) fn pull_off(layers: &Layers, rho: f64) -> Result<PlaneState> {
    crate::error::check_range("rho", rho, rho > 0.0 && rho <= 1.0, "(0, 1]")?;
    let sharp = match by_sharp_edge::pull_off(layers, rho) {
        Ok(state) => return Ok(state),
        // (a stop the caller asked for stops the answer too)
        Err(e) if crate::newton::stop_requested() => return Err(e),
        Err(e) => e,
    };
    let mut grid = by_grid::pull_off(layers, rho).map_err(|grid| {
        crate::error::Error::NoState(format!(
            "the layer's pull-off in the plane at rho = {}: the sharp edge has none ({sharp}), and neither has the grid solver ({grid})",
            short(rho)
        ))
    })?;
    grid.warnings.push(format!(
        "by the grid solver: the sharp edge, which answers where it resolves the contact, has no answer here ({sharp})"
    ));
    Ok(grid)
}

/// The state of `layers` at `rho` ∈ (0, 1] held at `hold` (`None`: the
/// pull-off under load control, [`pull_off`]); at a force the sharp
/// edge's where it answers, else the grid solver's, as for the pull-off;
/// at an approach or a size the sharp edge's (its error where it has
/// none).
pub(crate) fn state(layers: &Layers, rho: f64, hold: Option<Hold>) -> Result<PlaneState> {
    crate::error::check_range("rho", rho, rho > 0.0 && rho <= 1.0, "(0, 1]")?;
    let force = match hold {
        None => return pull_off(layers, rho),
        Some(Hold::Force(f)) if f.is_finite() => f,
        // the sharp edge's alone: the grid's force at a held approach has
        // no bound it can state (`by_grid`)
        Some(Hold::Delta(d)) if d.is_finite() => return by_sharp_edge::at_approach(layers, rho, d),
        // the sharp edge's alone: the grid holds no size
        Some(Hold::Size(a)) if a.is_finite() => return by_sharp_edge::at_size(layers, rho, a),
        Some(hold) => return by_grid::state(layers, rho, Some(hold)),
    };
    let sharp = match by_sharp_edge::at_force(layers, rho, force) {
        Ok(state) => return Ok(state),
        Err(e) if crate::newton::stop_requested() => return Err(e),
        Err(e) => e,
    };
    let mut grid = by_grid::state(layers, rho, hold).map_err(|grid| match sharp {
        // coatings outside both reaches: the grid's refusal (the wider's)
        crate::error::Error::Unsupported { .. } => grid,
        _ => crate::error::Error::NoState(format!(
            "the layer's state at force {} in the plane at rho = {}: the sharp edge has none ({sharp}), and neither has the grid solver ({grid})",
            short(force),
            short(rho)
        )),
    })?;
    grid.warnings.push(format!(
        "by the grid solver: the sharp edge, which answers where it resolves the contact, has no answer here ({sharp})"
    ));
    Ok(grid)
}

/// The thinness of the coating of `layers` outside [`PULL_OFF_REACH`]
/// (the thinner one first), if any: where no pull-off in the plane is
/// measured.
pub(crate) fn beyond_reach(layers: &Layers) -> Option<f64> {
    outside(layers, PULL_OFF_REACH)
}

/// The thinness of the coating of `layers` outside `(lo, hi)` (the
/// thinner one first), if any.
fn outside(layers: &Layers, (lo, hi): (f64, f64)) -> Option<f64> {
    if layers.thinnest() < lo {
        Some(layers.thinnest())
    } else if layers.thickest() > hi {
        Some(layers.thickest())
    } else {
        None
    }
}

/// An error naming the coating of `layers` outside a method's `reach`, if
/// any, with `why` it is that (after the range, in the error's words).
fn within(layers: &Layers, reach: (f64, f64), why: &str) -> Result<()> {
    match outside(layers, reach) {
        None => Ok(()),
        Some(value) => Err(crate::error::Error::Unsupported {
            name: "h/L",
            value,
            supported: format!(
                "{} to {} for each coating{why}",
                short(reach.0),
                short(reach.1)
            )
            .into(),
        }),
    }
}
