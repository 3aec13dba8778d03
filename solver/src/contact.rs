//! Contact states of a model at a fixed radii ratio ρ, in the
//! dimensionless variables of (17): control by displacement δ̄, by contact
//! size ā, by load F̄; pull-off under load and displacement control; the
//! zero-force state. Written once, for every generated model, through the
//! [`Model`] interface; the model is chosen at run time ([`ModelId`]).
//!
//! At fixed ρ < 1 every model's solution set is explicit in s (the
//! generated `branch`: for the paper's model both residuals (19)–(20) are
//! linear in ā³ and δ̄ā; for the energy closure they are quadratic forms,
//! whose two roots are the adhesive and the compressive-edge branch of
//! (∂p/∂ν)² = 2mΔγ; the adhesive one, ∂p/∂ν > 0 at the apex, is kept).
//! The physical branch starts at the non-adhesive aspect ratio s∞(ρ) (for
//! the paper, (29)), where ā → ∞, and is followed towards smaller s: F̄
//! and δ̄ decrease, F̄ reaches its minimum (pull-off under load control),
//! and the contact size reaches a minimum (a fold in ā) beyond which s
//! collapses towards 0 and ā grows again. States beyond that fold are
//! flagged. Brackets come from a scan of the explicit branch (module
//! `cold`: about 10–60 explicit evaluations, [`Search::Cold`], the
//! default) or from the walk of 4000 points that it replaced and is tested
//! against ([`Search::Walk`]); each state is then solved by Newton's method
//! on the generated residuals and Jacobian with the control equation, and
//! folds by Newton on the fold condition ([`crate::fold`]). At ρ = 1 the
//! model's axisymmetric solution (22)–(25) is used (s = 1).
//!
//! Owns: [`Contact`], `NEAR_CIRCLE`, [`State`], [`Stability`], [`PullOff`], [`Search`]
//! and the walk.
//! May use: `generated` (`ModelId`), `control`, `model`, `newton`, `fold`, `error`, `equations` (the one model
//! interface its Newton and continuation run on), `cutoff` (the neutral band).

mod cold;
mod near_circle;

/// 1 − ρ below which states are continued from ρ₀ = 1 − NEAR_CIRCLE
/// (`near_circle`).
pub(crate) const NEAR_CIRCLE: f64 = 1e-6;

use crate::control::{Hold, Quantity};
use crate::cutoff::Eigen;
use crate::equations::held;
use crate::error::{check_range, rounded, short, Error, Result};
use crate::fold::{self, FoldCondition};
use crate::generated::ModelId;
use crate::model::{brent_minimum, ClosureKind, Model};
use crate::newton::{self, NewtonConfig};
use nalgebra::{Vector2, Vector3};
use serde::{Deserialize, Serialize};

/// The stability of a state, for models with an energy (the energy
/// closure): positive definiteness of the Hessian of Π̄ in (ā, s) under
/// displacement control, of Π̄ − F̄δ̄ in (ā, s, δ̄) under load control.
/// Stable means that no eigenvalue is negative beyond the neutral band
/// (`crate::cutoff::Eigen`: 1e-6 of the largest in magnitude). A state on
/// a fold (a pull-off, where the Hessian is singular up to round-off) is
/// neutral under the control that ends there, whichever sign round-off
/// gives its smallest eigenvalue: the limit of the stable states before
/// it, marked by `neutral_*`, as the contour models mark theirs.
/// `None` for models without an energy, whose stability is not defined.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct Stability {
    /// Stable under displacement control: no eigenvalue below the band.
    pub stable_displacement: Option<bool>,
    /// Stable under load control.
    pub stable_load: Option<bool>,
    /// Stable under displacement control, with an eigenvalue zero within
    /// the band: on a fold or bifurcation of that control.
    #[serde(default, skip_serializing_if = "is_false")]
    pub neutral_displacement: bool,
    /// The same under load control (at the load-controlled pull-off).
    #[serde(default, skip_serializing_if = "is_false")]
    pub neutral_load: bool,
    /// Strictly stable under displacement control: the least eigenvalue
    /// above 1e-9 of the largest in magnitude. The walk to the
    /// displacement-controlled end looks for the first state that is not,
    /// so that a state on or near the fold counts as its end.
    #[serde(skip)]
    pub(crate) strictly_stable_displacement: bool,
}

fn is_false(b: &bool) -> bool {
    !*b
}

/// The smallest radii ratio the solver supports: the paper's model is
/// followed down to ρ = 1e-8 (s ≈ 2e-6 at δ̄ = 1); below, an
/// [`Error::Unsupported`]. (The energy model's numeric s∞ is bracketed on a
/// grid from s = 1e-4, which reaches ρ = 1e-8: at ρ = 1e-8, δ̄ = 1 its state
/// has s ≈ 8e-5, beyond the contact-size fold.)
pub(crate) const RHO_MIN: f64 = 1e-8;

/// One state of a model, dimensionless as in (17) (lengths in
/// L = (2R₁²Δγ/m)^(1/6), pressures in √(2mΔγ) L).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct State {
    /// The model that produced this state.
    pub model: ModelId,
    /// Radii ratio ρ = R₂/R₁ (21).
    pub rho: f64,
    /// Major semi-axis ā (17).
    pub a_bar: f64,
    /// Minor semi-axis b̄ = s ā.
    pub b_bar: f64,
    /// Aspect ratio s = b/a (12).
    pub s: f64,
    /// Collocation parameter ξ ((15)₁ for collocation models; from the
    /// definition (10) of ξ through A for the energy model).
    pub xi: f64,
    /// Shape parameter A L² of (5).
    pub shape_a: f64,
    /// Shape parameter B L² of (5).
    pub shape_b: f64,
    /// Maximum pressure p₀ / (√(2mΔγ) L) (Section 6).
    pub p0: f64,
    /// Force F̄ = F/(2R₁Δγ) (for the paper's model the derived form of (18)).
    pub force_bar: f64,
    /// Approach δ̄ (17).
    pub delta_bar: f64,
    /// A-posteriori error (14) of the boundary condition (3)₂: (max − min)/min
    /// of ∂p/∂ν along Γ₀, as a fraction.
    pub bc_error: f64,
    /// ρ below the paper's stated range 0.8 ≤ ρ ≤ 1: read `bc_error`.
    pub outside_stated_range: bool,
    /// The state lies beyond the fold of the contact size, where s
    /// collapses towards 0: far from the physical branch.
    pub beyond_size_fold: bool,
    /// Stability, where the model has an energy (in JSON its two fields
    /// sit beside the others).
    #[serde(flatten)]
    pub stability: Stability,
}

/// The words of a state beyond the contact-size fold.
pub(crate) const BEYOND_SIZE_FOLD: &str = "beyond the contact-size fold";

impl State {
    /// Why the state is doubtful, in the words every front end shows (the
    /// command line's brackets, a batch row's `warning`, Python's
    /// ThinJkrWarning): ρ below the paper's stated range, and a state
    /// beyond the contact-size fold.
    pub(crate) fn warning_words(&self) -> Vec<&'static str> {
        let mut out = Vec::new();
        if self.outside_stated_range {
            out.push("rho < 0.8: outside the paper's stated range");
        }
        if self.beyond_size_fold {
            out.push(BEYOND_SIZE_FOLD);
        }
        out
    }
}

/// What ends a controlled branch.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum FoldBasis {
    /// The Hessian of the model's potential energy loses definiteness here:
    /// an instability of the model, proven by its energy.
    EnergyInstability,
    /// A fold of the model's solution curve. The model has no energy, so
    /// this is where its branch turns, not a proven instability.
    ModelFold,
    /// The minimum of F̄ on the exact axisymmetric solution (ρ = 1).
    AxisymmetricMinimum,
    /// At ρ = 1, where the circle loses stability to an elliptic contour
    /// under displacement control (det ∂r/∂(ā, s) = 0 at s = 1): the limit
    /// of the folds at ρ < 1.
    CircleBifurcation,
}

impl FoldBasis {
    /// What the end point is, in words.
    pub fn describe(self) -> &'static str {
        match self {
            FoldBasis::EnergyInstability => "loss of stability of the model's energy (Hessian of the potential)",
            FoldBasis::ModelFold => "a fold of the model's solution curve; the model has no energy, so this is not a proven instability",
            FoldBasis::AxisymmetricMinimum => "the minimum of the force on the exact axisymmetric solution",
            FoldBasis::CircleBifurcation => "the circle loses stability to an elliptic contour (the limit of the folds at rho < 1)",
        }
    }
}

/// Pull-off: the state where a controlled branch ends, and why.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct PullOff {
    /// The state.
    pub state: State,
    /// The control.
    pub control: FoldCondition,
    /// What the end point is.
    pub basis: FoldBasis,
}

/// How a state's starting point on the branch is found (ρ < 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Search {
    /// A scan of some of the walk's points (about 10–60, the stride
    /// adapting to the branch), then the crossing or extremum bracketed
    /// and refined (module `cold`): the default.
    #[default]
    Cold,
    /// The walk of 4000 points of the explicit branch that every solve
    /// used before the cold path: kept as the reference the cold path is
    /// tested against.
    Walk,
}

/// A model at one radii ratio ρ.
#[derive(Clone, Copy)]
pub struct Contact {
    rho: f64,
    id: ModelId,
    model: &'static dyn Model,
    newton: NewtonConfig,
    search: Search,
    /// s∞, found when the contact was made; `None` at ρ = 1 or if not
    /// found (asking again then gives the error).
    s_inf: Option<f64>,
}

/// Points of the walk of the branch (the reference search).
const WALK_POINTS: usize = 4000;

/// One sample of the walk.
enum WalkSample {
    /// (s, ā, δ̄) of the adhesive point.
    Point(f64, f64, f64),
    /// The two roots of a quadratic branch nearly meet: skipped.
    IllConditioned,
    /// No adhesive point at this s.
    NoAdhesivePoint,
}

impl std::fmt::Debug for Contact {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Contact")
            .field("model", &self.id)
            .field("rho", &self.rho)
            .finish()
    }
}

/// The value of a quantity at a state.
fn value_at(quantity: Quantity, st: &State) -> f64 {
    match quantity {
        Quantity::Delta => st.delta_bar,
        Quantity::ABar => st.a_bar,
        Quantity::Force => st.force_bar,
    }
}

/// Tolerance within which ρ counts as 1 (the axisymmetric case): none, only
/// ρ = 1 itself (near it, module `near_circle`).
const AXISYMMETRIC: f64 = 0.0;

impl Contact {
    /// The paper's model (`max`) at radii ratio `rho` ∈ (0, 1].
    pub fn new(rho: f64) -> Result<Self> {
        Contact::with_model(ModelId::Max, rho)
    }

    /// Any generated model at radii ratio `rho` ∈ (0, 1].
    pub fn with_model(model: ModelId, rho: f64) -> Result<Self> {
        let mut c = Contact::unprepared(model, rho)?;
        if !c.axisymmetric() {
            // found once per contact (numerically, where the model has no
            // derived relation: tens of microseconds)
            c.s_inf = c.s_infinity().ok();
        }
        Ok(c)
    }

    /// [`Contact::with_model`] without finding s∞ ahead (found when a
    /// search needs it): for a state continued from a neighbour
    /// ([`Contact::at_near`]), which searches nothing.
    pub(crate) fn unprepared(model: ModelId, rho: f64) -> Result<Self> {
        check_range("rho", rho, rho > 0.0 && rho <= 1.0, "(0, 1]")?;
        if rho < RHO_MIN {
            return Err(Error::Unsupported {
                name: "rho",
                value: rho,
                supported: "[1e-8, 1]: below 1e-8 the aspect ratio s is below 1e-5 and the branch is not followed".into(),
            });
        }
        Ok(Contact {
            rho,
            id: model,
            model: model.model(),
            newton: NewtonConfig::default(),
            search: Search::Cold,
            s_inf: None,
        })
    }

    /// Replace the search for starting points ([`Search::Cold`] by default).
    pub fn search(mut self, search: Search) -> Self {
        self.search = search;
        self
    }

    /// Replace the Newton controls.
    pub fn newton(mut self, config: NewtonConfig) -> Self {
        self.newton = config;
        self
    }

    /// The radii ratio.
    pub fn rho(&self) -> f64 {
        self.rho
    }

    /// The model.
    pub(crate) fn model(&self) -> &'static dyn Model {
        self.model
    }

    /// The model's identifier.
    pub fn model_id(&self) -> ModelId {
        self.id
    }

    fn axisymmetric(&self) -> bool {
        self.rho >= 1.0 - AXISYMMETRIC
    }

    fn has_energy(&self) -> bool {
        self.model.info().closure == ClosureKind::Energy
    }

    /// The pressure p/(√(2mΔγ) L) of `state` at (x̄, ȳ) = (x, y)/L; zero
    /// outside the ellipse (7).
    pub fn pressure(&self, state: &State, x: f64, y: f64) -> f64 {
        if (x / state.a_bar).powi(2) + (y / state.b_bar).powi(2) > 1.0 {
            return 0.0;
        }
        self.model.pressure(
            x,
            y,
            Vector2::new(state.a_bar, state.s),
            self.rho,
            state.delta_bar,
        )
    }

    /// ∂p̄/∂ν of `state` on Γ₀ at u = sin²t, in units of √(2mΔγ).
    pub fn normal_derivative(&self, state: &State, u: f64) -> f64 {
        self.model.normal_derivative(
            Vector2::new(state.a_bar, state.s),
            self.rho,
            state.delta_bar,
            u,
        )
    }

    /// s∞(ρ): the non-adhesive aspect ratio (for the paper, (29)), where
    /// ā → ∞ on the branch. From the model's derived relation ρ(s) where it
    /// has one; otherwise the end of the s-range where the model's adhesive
    /// branch exists, located by bisection (once, when the contact is made).
    pub(crate) fn s_infinity(&self) -> Result<f64> {
        if self.axisymmetric() {
            return Ok(1.0);
        }
        if let Some(s_inf) = self.s_inf {
            return Ok(s_inf);
        }
        if self.model.info().has_non_adhesive_limit {
            let m = self.model;
            return bisect(
                |s| m.non_adhesive_rho(s).unwrap_or(f64::NAN) - self.rho,
                1e-9,
                1.0,
            );
        }
        // numeric: ā → ∞ at s∞. Continued through infinity, the adhesive
        // branch comes back as the mirror solution (−ā³, −δ̄ā) of a closure
        // that is even in p (the energy closure), which the explicit branch
        // reports with ā³ > 0 and a compressive edge. The signed 1/ā³
        // (positive on the adhesive branch, negative on the mirror) changes
        // sign at s∞: bracket it on a grid and bisect.
        let f = |s: f64| self.signed_inverse_size(s);
        let mut bracket = None;
        let mut prev: Option<(f64, f64)> = None;
        // logarithmic in s from 1e-4, uniform, then logarithmic in 1 − s
        // down to 1e-12: 100 points, which only bracket the sign change
        // (bisection then resolves it)
        let grid = (0..15)
            .map(|j| 10f64.powf(-4.0 + 3.0 * j as f64 / 15.0))
            .chain((0..45).map(|j| 0.1 + 0.88 * j as f64 / 45.0))
            .chain((0..40).map(|j| 1.0 - 10f64.powf(-1.7 - 10.3 * j as f64 / 39.0)));
        for s in grid {
            if let Some(v) = f(s) {
                if let Some((sp, vp)) = prev {
                    if vp > 0.0 && v < 0.0 {
                        bracket = Some((sp, s));
                    }
                }
                prev = Some((s, v));
            }
        }
        let (mut lo, mut hi) = bracket.ok_or_else(|| {
            Error::NoState(format!(
                "model {}: no end of the adhesive branch found at rho = {}",
                self.model_id(),
                short(self.rho)
            ))
        })?;
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            match f(mid) {
                Some(v) if v > 0.0 => lo = mid,
                Some(_) => hi = mid,
                // neither branch is resolved here: lo stays the last
                // adhesive point found, which is where the walk starts
                None => break,
            }
            if hi - lo <= 4.0 * f64::EPSILON * hi {
                break;
            }
        }
        Ok(lo)
    }

    /// 1/ā³ on the adhesive branch at `s`, −1/ā³ on its mirror (compressive
    /// edge at both apexes); `None` where neither exists.
    fn signed_inverse_size(&self, s: f64) -> Option<f64> {
        if let Some((a, _)) = self.adhesive_point(s) {
            return Some(a.powi(-3));
        }
        for (a, d) in self.model.branch(s, self.rho).into_iter().flatten() {
            let [g0, g1] = self.model.edge_slopes(Vector2::new(a, s), self.rho, d);
            let g = g0.max(g1);
            if g < 0.0 {
                return Some(-a.powi(-3));
            }
        }
        None
    }

    /// The adhesive point of the model's branch at `s`: among the explicit
    /// solutions at (s, ρ), the one with ∂p/∂ν > 0 at both apexes (a
    /// tensile edge), the larger smaller apex value if both are. (For the
    /// energy closure the other root has ∂p/∂ν < 0 at an apex.)
    fn adhesive_point(&self, s: f64) -> Option<(f64, f64)> {
        self.adhesive_of(s, self.model.branch(s, self.rho))
    }

    /// [`Contact::adhesive_point`] among given branch points at `s`.
    fn adhesive_of(&self, s: f64, points: crate::model::BranchPoints) -> Option<(f64, f64)> {
        let mut best: Option<((f64, f64), f64)> = None;
        for (a, d) in points.into_iter().flatten() {
            let g = self.edge_slope(a, s, d);
            if g.is_finite() && g > 0.0 && best.is_none_or(|(_, gb)| g > gb) {
                best = Some(((a, d), g));
            }
        }
        best.map(|(p, _)| p)
    }

    /// The smaller of ∂p̄/∂ν at the two apexes: positive on the adhesive
    /// (tensile-edge) solution, negative on the mirror solution of a
    /// closure that is even in p (the energy closure).
    fn edge_slope(&self, a: f64, s: f64, delta: f64) -> f64 {
        let [g0, g1] = self.model.edge_slopes(Vector2::new(a, s), self.rho, delta);
        g0.min(g1)
    }

    /// The branch state at `s` without the contour-sampled error (14): for
    /// walks and brackets.
    fn light_state_at_s(&self, s: f64) -> Option<State> {
        let (a, d) = self.adhesive_point(s)?;
        Some(self.state_with(a, s, d, false))
    }

    /// The state on the branch at aspect ratio `s` (explicit; no Newton).
    pub(crate) fn state_at_s(&self, s: f64) -> Option<State> {
        let (a, d) = self.adhesive_point(s)?;
        Some(self.state_from(a, s, d))
    }

    /// The full state at (ā, s, δ̄), which must satisfy the model's residuals.
    pub(crate) fn state_from(&self, a: f64, s: f64, delta: f64) -> State {
        self.state_with(a, s, delta, true)
    }

    fn state_with(&self, a: f64, s: f64, delta: f64, with_bc_error: bool) -> State {
        let x = Vector2::new(a, s);
        let m = self.model;
        let p = m.pressure_parameters(x, self.rho, delta);
        let stability = match m.potential_hessian(x, self.rho, delta) {
            Some(h) => {
                let (displacement, strict) = least_eigen(h.fixed_view::<2, 2>(0, 0).into_owned());
                let (load, _) = least_eigen(h);
                Stability {
                    stable_displacement: Some(displacement != Eigen::Unstable),
                    stable_load: Some(load != Eigen::Unstable),
                    neutral_displacement: displacement == Eigen::Neutral,
                    neutral_load: load == Eigen::Neutral,
                    strictly_stable_displacement: strict,
                }
            }
            None => Stability::default(),
        };
        State {
            model: self.id,
            rho: self.rho,
            a_bar: a,
            b_bar: s * a,
            s,
            xi: p.xi,
            shape_a: p.shape[0],
            shape_b: p.shape[1],
            p0: p.p0,
            force_bar: m.force_bar(x, self.rho, delta),
            delta_bar: delta,
            bc_error: if s >= 1.0 {
                0.0
            } else if with_bc_error {
                m.bc_error(x, self.rho, delta)
            } else {
                f64::NAN
            },
            outside_stated_range: self.rho < 0.8,
            beyond_size_fold: false,
            stability,
        }
    }

    fn axisymmetric_state(&self, a: f64) -> Result<State> {
        let (delta, force) = self
            .model
            .axisymmetric(a)
            .ok_or_else(|| self.unavailable("the axisymmetric solution (22)-(25)"))?;
        let mut st = self.state_from(a, 1.0, delta);
        st.force_bar = force;
        st.bc_error = 0.0;
        Ok(st)
    }

    fn unavailable(&self, what: &str) -> Error {
        Error::Unavailable {
            model: self.model_id().name(),
            what: what.to_string(),
            why: self.model.info().missing_limits,
        }
    }

    /// The minimum of the axisymmetric F̄(ā) (pull-off at ρ = 1): the derived
    /// critical point where the model has it, otherwise a logarithmic scan
    /// and Brent's method, then secant steps on dF̄/dā.
    fn axisymmetric_pull_off(&self) -> Result<State> {
        let f = |a: f64| self.model.axisymmetric(a).map(|v| v.1).unwrap_or(f64::NAN);
        if !self.model.info().has_axisymmetric_limit {
            return Err(self.unavailable("the axisymmetric solution (22)-(25)"));
        }
        if let Some(a_c) = self.model.axisymmetric_critical_a() {
            return self.axisymmetric_state(a_c);
        }
        let n = 400;
        let grid: Vec<f64> = (0..=n)
            .map(|k| 10f64.powf(-2.0 + 5.0 * k as f64 / n as f64))
            .collect();
        let k = (1..n)
            .min_by(|&i, &j| f(grid[i]).total_cmp(&f(grid[j])))
            .ok_or_else(|| Error::NoState("no axisymmetric minimum".into()))?;
        let mut a = brent_minimum(f, grid[k - 1], grid[k + 1], 1e-10 * grid[k]);
        let df = |a: f64| {
            let h = 1e-5 * a;
            (f(a + h) - f(a - h)) / (2.0 * h)
        };
        let mut a_prev = a * (1.0 + 1e-6);
        for _ in 0..20 {
            let (d0, d1) = (df(a), df(a_prev));
            if d0 == d1 {
                break;
            }
            let next = a - d0 * (a - a_prev) / (d0 - d1);
            a_prev = a;
            a = next;
            if (a - a_prev).abs() < 1e-15 * a {
                break;
            }
        }
        self.axisymmetric_state(a)
    }

    /// The k-th sample (k = 1 … 3999) of the walk from s∞ towards s → 0:
    /// logarithmic in s∞ − s, from 1e-13 s∞ (1e-8 s∞ for d = 2, d the
    /// residuals' degree: then the two roots of the explicit branch meet
    /// as ā → ∞ and lose accuracy closer to s∞); near ρ = 1 the whole
    /// physical branch lies within O(1 − ρ) of s∞. `None` where the branch
    /// has no adhesive point, or where the two roots of a quadratic branch
    /// nearly meet (as ā → ∞ near s∞) and are ill-conditioned.
    fn walk_sample(&self, s_inf: f64, k: usize) -> Option<(f64, f64, f64)> {
        match self.walk_sample_why(s_inf, k) {
            WalkSample::Point(s, a, d) => Some((s, a, d)),
            _ => None,
        }
    }

    /// [`Contact::walk_sample`], saying why there is no point.
    fn walk_sample_why(&self, s_inf: f64, k: usize) -> WalkSample {
        let s = self.walk_s(s_inf, k);
        let points = self.model.branch(s, self.rho);
        if let [Some((a1, d1)), Some((a2, d2))] = points {
            let (t1, t2) = (d1 / (a1 * a1), d2 / (a2 * a2));
            if (t1 - t2).abs() < 1e-4 * t1.abs().max(t2.abs()) {
                return WalkSample::IllConditioned;
            }
        }
        match self.adhesive_of(s, points) {
            Some((a, d)) => WalkSample::Point(s, a, d),
            None => WalkSample::NoAdhesivePoint,
        }
    }

    /// The decades of s∞ − s the walk spans: 13, or 8 for d = 2.
    fn walk_decades(&self) -> f64 {
        if self.model.info().residual_degree == 1 {
            13.0
        } else {
            8.0
        }
    }

    /// s at the k-th walk sample.
    fn walk_s(&self, s_inf: f64, k: usize) -> f64 {
        s_inf - s_inf * 10f64.powf(-self.walk_decades() * (1.0 - k as f64 / WALK_POINTS as f64))
    }

    /// Walk the branch from s∞ towards s → 0: the samples (s, state).
    fn walk(&self) -> Result<Vec<State>> {
        let s_inf = self.s_infinity()?;
        let mut out: Vec<State> = Vec::with_capacity(WALK_POINTS);
        for k in 1..WALK_POINTS {
            if let Some((s, a, d)) = self.walk_sample(s_inf, k) {
                out.push(self.state_with(a, s, d, false));
            }
        }
        // the fold of the contact size: the first ā along the walk that is
        // the smallest within 20 points on either side
        let sizes: Vec<f64> = out.iter().map(|st| st.a_bar).collect();
        if let Some(k) = first_window_minimum(&sizes) {
            for st in &mut out[k + 1..] {
                st.beyond_size_fold = true;
            }
        }
        if out.len() < 3 {
            return Err(self.no_branch(s_inf));
        }
        Ok(out)
    }

    fn no_branch(&self, s_inf: f64) -> Error {
        Error::NoState(format!(
            "model {} has no branch at rho = {} (its non-adhesive limit is at s = {})",
            self.model_id(),
            short(self.rho),
            crate::error::rounded(s_inf)
        ))
    }

    fn stable_throughout(&self, last_s: Option<f64>) -> Error {
        Error::NoState(format!(
            "model {}: the branch at rho = {} stays stable under displacement control down to s = {:.3e} (the contact shrinks and elongates without a fold in delta_bar)",
            self.model_id(),
            short(self.rho),
            last_s.unwrap_or(f64::NAN)
        ))
    }

    /// Polish a state by Newton's method on the model's residuals at its δ̄.
    fn polish(&self, guess: &State, context: &str) -> Result<State> {
        let delta = guess.delta_bar;
        let m = self.model;
        // a guess on the adhesive side stays there
        let adhesive_start = self.edge_slope(guess.a_bar, guess.s, delta) > 0.0;
        let sol = newton::solve_within(
            |x| m.residuals_and_jacobian(x, self.rho, delta),
            |a| m.residual_scale(a, delta),
            Vector2::new(guess.a_bar, guess.s),
            &self.newton,
            context,
            |x| !adhesive_start || self.edge_slope(x[0], x[1], delta) > 0.0,
        )?;
        let mut st = self.state_from(sol.a_bar, sol.s, delta);
        st.beyond_size_fold = guess.beyond_size_fold;
        Ok(st)
    }

    /// Along the walk (extended at the large-load end by [`Contact::tail`]),
    /// all crossings of the controlled quantity `control` = `target`, each
    /// started by bisection in s on the explicit branch (or by
    /// interpolation between two tail states) and solved by Newton on the
    /// residuals with the control equation (so the state has the control
    /// value to round-off, not to the bisection's resolution in s).
    fn crossings(&self, control: Quantity, target: f64, what: &str) -> Result<Vec<State>> {
        if self.search == Search::Cold {
            return self.cold_crossings(control, target, what, false, false);
        }
        let walk = self.walk()?;
        let mut all = self.tail(&walk);
        let n_tail = all.len();
        all.reverse();
        all.extend(walk);
        let key = |st: &State| value_at(control, st);
        let mut out = Vec::new();
        for (k, w) in all.windows(2).enumerate() {
            let (f0, f1) = (key(&w[0]) - target, key(&w[1]) - target);
            if f0.signum() == f1.signum() || !f0.is_finite() || !f1.is_finite() {
                continue;
            }
            let guess = if k >= n_tail {
                let s = bisect(
                    |s| {
                        self.light_state_at_s(s)
                            .map(|st| key(&st) - target)
                            .unwrap_or(f64::NAN)
                    },
                    w[1].s,
                    w[0].s,
                )?;
                self.state_at_s(s).ok_or_else(|| {
                    Error::NoState(format!("{what}: off the branch at s = {}", rounded(s)))
                })?
            } else {
                self.tail_guess(&w[0], &w[1], control, target)
            };
            let guess = Vector3::new(guess.a_bar, guess.s, guess.delta_bar);
            let mut st = self.solve_controlled(guess, control, target, what)?;
            st.beyond_size_fold = w[1].beyond_size_fold;
            out.push(st);
        }
        if out.is_empty() {
            self.within_reach(
                control,
                target,
                what,
                all.iter().map(|st| (key(st), st.a_bar)),
            )?;
        }
        Ok(out)
    }

    /// A start for Newton between two states of the large-load tail at
    /// `control` = `target`: tail states are 1.25× apart in δ̄ > 0, so ln ā,
    /// s, ln δ̄ (nearly linear there) are interpolated in ln of the control
    /// where it is positive; the nearer tail state if the interpolated one
    /// is off the adhesive sheet.
    fn tail_guess(&self, w0: &State, w1: &State, control: Quantity, target: f64) -> State {
        let (k0, k1) = (value_at(control, w0), value_at(control, w1));
        let t = if k0 > 0.0 && k1 > 0.0 && target > 0.0 {
            (target / k0).ln() / (k1 / k0).ln()
        } else {
            (k0 - target) / (k0 - k1)
        };
        let mut g = *w0;
        g.a_bar = w0.a_bar * (t * (w1.a_bar / w0.a_bar).ln()).exp();
        g.s += t * (w1.s - w0.s);
        g.delta_bar = w0.delta_bar * (t * (w1.delta_bar / w0.delta_bar).ln()).exp();
        if self.edge_slope(g.a_bar, g.s, g.delta_bar) > 0.0 {
            g
        } else if t < 0.5 {
            *w0
        } else {
            *w1
        }
    }

    /// Ok if `target` is not beyond every value of the controlled quantity
    /// in `reached` (pairs of its value and ā); otherwise the error that
    /// says how far the branch was followed.
    fn within_reach(
        &self,
        control: Quantity,
        target: f64,
        what: &str,
        reached: impl Iterator<Item = (f64, f64)>,
    ) -> Result<()> {
        let (reach, a_at) = reached.fold((f64::NEG_INFINITY, f64::NAN), |best, v| {
            if v.0 > best.0 {
                v
            } else {
                best
            }
        });
        if target > reach {
            return Err(Error::NoState(format!(
                "{what}: {} = {} is beyond the largest value reached on the branch of model {} at rho = {} ({}, at a_bar = {}): the branch is followed up to a_bar = 1e4, or less where Newton no longer reaches the adhesive root (a model with quadratic residuals, at large loads)",
                match control {
                    Quantity::Delta => "delta",
                    Quantity::ABar => "a",
                    Quantity::Force => "force",
                },
                crate::error::short(target),
                self.model_id(),
                short(self.rho),
                crate::error::rounded(reach),
                crate::error::rounded(a_at),
            )));
        }
        Ok(())
    }

    /// Newton's method on z = (ā, s, δ̄) for the model's residuals and the
    /// control equation `control(z) = target` (the bordered system
    /// [∂r/∂(ā, s) ∂r/∂δ̄; ∇control]), from `guess` = (ā, s, δ̄).
    fn solve_controlled(
        &self,
        guess: Vector3<f64>,
        control: Quantity,
        target: f64,
        what: &str,
    ) -> Result<State> {
        let m = self.model;
        let mut z = guess;
        let adhesive_start = self.edge_slope(z[0], z[1], z[2]) > 0.0;
        let mut last = f64::INFINITY;
        let hold = match control {
            Quantity::Delta => Hold::Delta(target),
            Quantity::ABar => Hold::Size(target),
            Quantity::Force => Hold::Force(target),
        };
        for _ in 0..60 {
            // the state equations under the control, written once for
            // every model (`equations::held`)
            let (r, mat, _) = held(m, &z, self.rho, hold);
            let rhs = -r;
            let Some(step) = mat
                .lu()
                .solve(&rhs)
                .filter(|v| v.iter().all(|x| x.is_finite()))
            else {
                break;
            };
            // damped to stay in the domain, and on the adhesive sheet when
            // started there
            let mut lambda = 1.0;
            while lambda > 1e-9 {
                let zn = z + step * lambda;
                if zn[0] > 0.0
                    && zn[1] > 0.0
                    && zn[1] <= 1.0
                    && (!adhesive_start || self.edge_slope(zn[0], zn[1], zn[2]) > 0.0)
                {
                    break;
                }
                lambda *= 0.5;
            }
            z += step * lambda;
            z[1] = z[1].min(1.0);
            let size = step.component_div(&z.map(|v| 1.0 + v.abs())).amax();
            if size < 1e-14 || (size < 1e-10 && size >= 0.5 * last) {
                let x = Vector2::new(z[0], z[1]);
                let rn = m.residuals_and_jacobian(x, self.rho, z[2]).0.norm()
                    / m.residual_scale(z[0], z[2]);
                if rn < 1e-11 {
                    return self.adhesive_or_error(self.state_from(z[0], z[1], z[2]), what);
                }
            }
            last = size;
        }
        Err(Error::NoConvergence {
            iterations: 60,
            a_bar: z[0],
            s: z[1],
            residual: f64::NAN,
            context: format!(
                "{what}: {} = {} at rho = {}",
                match control {
                    Quantity::Delta => "delta",
                    Quantity::ABar => "a",
                    Quantity::Force => "force",
                },
                crate::error::short(target),
                short(self.rho)
            ),
        })
    }

    /// `st` if it is adhesive (tensile edge), else an error: at large loads
    /// the two roots of a quadratic closure are nearly equal in (ā, s, δ̄),
    /// and Newton may reach the compressive-edge one.
    fn adhesive_or_error(&self, st: State, what: &str) -> Result<State> {
        if self.edge_slope(st.a_bar, st.s, st.delta_bar) > 0.0 {
            return Ok(st);
        }
        Err(Error::NoState(format!(
            "{what}: Newton reached the compressive-edge (non-adhesive) root at a_bar = {:.6e}, s = {:.6e}, delta_bar = {:.6e} (rho = {}), not the adhesive state; at such loads the two roots of model {} are nearly equal",
            st.a_bar, st.s, st.delta_bar, short(self.rho), self.model_id()
        )))
    }

    /// The branch beyond the walk's large-load end: from the walk's two
    /// states nearest s∞, natural continuation in δ̄ (×1.25 per step, the
    /// predictor linear in ln δ̄ through the last two states for ln ā and
    /// s) up to ā = 1e4, stopping where Newton fails or reaches a state
    /// that is not adhesive. The walk samples s, and for a model with
    /// quadratic residuals it stops short of s∞ (its two roots meet
    /// there), which near ρ = 1 is still at moderate loads; this part
    /// reaches large loads. The two roots of a quadratic closure differ
    /// there by O(ā⁻³) in ln ā, and so does the predictor's error (the
    /// curvature of the branch in ln δ̄), so a fixed small step keeps
    /// Newton on the adhesive root.
    fn tail(&self, walk: &[State]) -> Vec<State> {
        let mut out = Vec::new();
        let (mut prev, mut older) = match walk {
            [a, b, ..] => (*a, *b),
            _ => return out,
        };
        while prev.a_bar < 1e4
            && prev.delta_bar > 0.0
            && older.delta_bar > 0.0
            && older.delta_bar != prev.delta_bar
        {
            let step = 1.25f64.ln();
            let dl = (prev.delta_bar / older.delta_bar).ln();
            let mut g = prev;
            g.delta_bar = prev.delta_bar * step.exp();
            g.a_bar = prev.a_bar * ((prev.a_bar / older.a_bar).ln() / dl * step).exp();
            g.s = prev.s + (prev.s - older.s) / dl * step;
            match self.polish(&g, "large-load continuation") {
                Ok(st)
                    if st.a_bar > prev.a_bar
                        && (st.s - prev.s).abs() < 0.1
                        && self.edge_slope(st.a_bar, st.s, st.delta_bar) > 0.0 =>
                {
                    out.push(st);
                    older = prev;
                    prev = st;
                }
                _ => break,
            }
        }
        out
    }

    /// The first minimum of `key` along the walk from s∞ that is the
    /// smallest value within 20 walk points on either side (robust to the
    /// round-off of the explicit branch near s∞, where a quadratic
    /// closure's roots meet), refined by Brent's method in s (not
    /// polished: a starting point for Newton).
    fn branch_minimum(&self, control: Quantity, what: &str) -> Result<State> {
        if self.search == Search::Cold {
            return self.cold_minimum(control, what);
        }
        let key = |st: &State| value_at(control, st);
        let walk = self.walk()?;
        let v: Vec<f64> = walk.iter().map(&key).collect();
        let k = first_window_minimum(&v)
            .filter(|&k| k + 1 < walk.len())
            .ok_or_else(|| {
                Error::NoState(format!(
                    "{what}: no minimum along the branch at rho = {}",
                    short(self.rho)
                ))
            })?;
        let f = |s: f64| {
            self.light_state_at_s(s)
                .map(|st| key(&st))
                .unwrap_or(f64::INFINITY)
        };
        let mut st = self
            .light_state_at_s(brent_minimum(f, walk[k + 1].s, walk[k - 1].s, 1e-12))
            .ok_or_else(|| Error::NoState(format!("{what}: off the branch")))?;
        st.beyond_size_fold = walk[k].beyond_size_fold;
        Ok(st)
    }

    /// Refine a fold from a walk state by Newton on the fold condition.
    fn refine_fold(&self, guess: &State, which: FoldCondition) -> Result<State> {
        let z = fold::locate(
            self.model,
            self.rho,
            Vector3::new(guess.a_bar, guess.s, guess.delta_bar),
            which,
        )?;
        let mut st = self.state_from(z[0], z[1], z[2]);
        st.beyond_size_fold = guess.beyond_size_fold;
        Ok(st)
    }

    /// Displacement control: the state at approach `delta` on the branch
    /// that continues the non-adhesive one (the first met from s∞).
    pub fn at_displacement(&self, delta: f64) -> Result<State> {
        check_range("delta", delta, true, "finite")?;
        let what = "displacement control";
        if self.axisymmetric() || self.near_circle() {
            return self.near_circle_at_displacement(delta, what);
        }
        match self.search {
            Search::Cold => self.cold_crossings(Quantity::Delta, delta, what, true, false)?,
            Search::Walk => self.crossings(Quantity::Delta, delta, what)?,
        }
            .into_iter()
            .next()
            .ok_or_else(|| Error::NoState(format!("no contact at delta = {} for rho = {} (below the displacement-controlled pull-off)", short(delta), short(self.rho))))
    }

    /// The circle's state at approach `delta` (ρ = 1, whatever this
    /// contact's ρ): δ̄(ā) = ā²/4 − 2/ā is increasing, one state for every δ̄.
    fn circle_at_displacement(&self, delta: f64) -> Result<State> {
        let m = self.model;
        if !m.info().has_axisymmetric_limit {
            return Err(self.unavailable("the axisymmetric solution (22)-(25)"));
        }
        let a = bisect(
            |a| m.axisymmetric(a).map(|v| v.0).unwrap_or(f64::NAN) - delta,
            1e-9,
            1e9,
        )?;
        // ā is the root to round-off; the state is at the δ̄ asked for
        let mut st = self.axisymmetric_state(a)?;
        st.delta_bar = delta;
        st.rho = 1.0;
        Ok(st)
    }

    /// The state at `hold` on the branch through `near` (a state of this
    /// contact's model nearby, as in a sweep): Newton from it, with the
    /// checks of every state (adhesive edge, s ≤ 1).
    pub(crate) fn at_near(&self, hold: Hold, near: &State) -> Result<State> {
        let hold = hold.check_finite()?;
        if near.model != self.model_id() {
            return Err(Error::Usage(format!(
                "the state to start from is of model {}, not {}",
                near.model.name(),
                self.model_id().name()
            )));
        }
        if let Hold::Delta(d) = hold {
            // at a given δ̄ Newton on the model's own equations in (ā, s);
            // a step to the compressive-edge root is refused at the end,
            // not steered at every iterate (a sweep's neighbour is close)
            let m = self.model;
            let what = "continued from a nearby state";
            let sol = crate::newton::solve(
                |x| m.residuals_and_jacobian(x, self.rho, d),
                |a| m.residual_scale(a, d),
                Vector2::new(near.a_bar, near.s),
                &self.newton,
                what,
            )?;
            return self.adhesive_or_error(self.state_from(sol.a_bar, sol.s, d), what);
        }
        let (quantity, target) = match hold {
            Hold::Delta(d) => (Quantity::Delta, d),
            Hold::Force(f) => (Quantity::Force, f),
            Hold::Size(a) => (Quantity::ABar, a),
        };
        self.solve_controlled(
            Vector3::new(near.a_bar, near.s, near.delta_bar),
            quantity,
            target,
            "continued from a nearby state",
        )
    }

    /// Contact-size control: every state with major semi-axis `a` (none, one
    /// or two), the one before the contact-size fold first.
    pub fn at_contact_size(&self, a: f64) -> Result<Vec<State>> {
        check_range("a", a, a > 0.0, "(0, ∞)")?;
        if self.axisymmetric() {
            return Ok(vec![self.axisymmetric_state(a)?]);
        }
        if self.near_circle() {
            let circle = self.circle()?.axisymmetric_state(a)?;
            return self
                .anchor()?
                .at_contact_size(a)?
                .iter()
                .map(|anchor| {
                    self.near_circle_controlled(
                        Some(&circle),
                        anchor,
                        Quantity::ABar,
                        a,
                        "contact-size control",
                    )
                })
                .collect();
        }
        self.crossings(Quantity::ABar, a, "contact-size control")
    }

    /// The fold of the contact size: the minimum of ā along the branch.
    pub fn size_fold(&self) -> Result<State> {
        if self.axisymmetric() {
            return Err(Error::NoState(
                "no fold in a_bar at rho = 1: a_bar decreases to 0".into(),
            ));
        }
        if self.near_circle() {
            let anchor = self.anchor()?.size_fold()?;
            return self.near_circle_sqrt_fold(&anchor, FoldCondition::ContactSize);
        }
        let guess = self.branch_minimum(Quantity::ABar, "fold of the contact size")?;
        self.refine_fold(&guess, FoldCondition::ContactSize)
    }

    /// Load control: the stable state at force `force` (on the branch from
    /// the non-adhesive end down to pull-off).
    pub fn at_load(&self, force: f64) -> Result<State> {
        check_range("force", force, true, "finite")?;
        // a solve that fails looks at the pull-off once: the range
        // [pull-off force, ∞) is closed, and at its end (to 1e-9, where
        // Newton on the load is singular) the state is the pull-off's, the
        // fold where the stable branch ends; below it, the range error
        // states the bound
        let inside = match self.at_load_inside(force) {
            // the branch under load control ends at the fold of the contact
            // size where that comes first (`load_end`): a state beyond it
            // is not on it
            Ok(st) if st.beyond_size_fold && !self.has_energy() => Err(Error::OutOfRange {
                name: "force",
                value: force,
                range: "above the force at the end of the branch".into(),
            }),
            other => other,
        };
        inside.or_else(|e| {
            let Ok(p) = self.load_end() else {
                return Err(e);
            };
            let from = if p.state.force_bar < 0.0 {
                "the pull-off force"
            } else {
                "the (compressive) force at the end of the branch"
            };
            if (force - p.state.force_bar).abs() <= 1e-9 * (1.0 + p.state.force_bar.abs()) {
                return Ok(p.state);
            }
            Err(match e {
                Error::OutOfRange {
                    name: "force",
                    value,
                    ..
                } => Error::OutOfRange {
                    name: "force",
                    value,
                    range: format!(
                        "[{}, ∞): from {from} of model {} at rho = {}",
                        crate::error::rounded(p.state.force_bar),
                        self.model_id(),
                        short(self.rho)
                    )
                    .into(),
                },
                other => other,
            })
        })
    }

    fn at_load_inside(&self, force: f64) -> Result<State> {
        if self.near_circle() {
            let circle = self.circle()?.at_load_inside(force)?;
            let anchor = self
                .anchor()?
                .at_load_inside(force)
                .map_err(|e| self.from_anchor(e))?;
            return self.near_circle_controlled(
                Some(&circle),
                &anchor,
                Quantity::Force,
                force,
                "load control",
            );
        }
        if self.search == Search::Cold && !self.axisymmetric() {
            return self
                .cold_crossings(Quantity::Force, force, "load control", true, true)?
                .into_iter()
                .next()
                .ok_or_else(|| Error::NoState(format!("no state at force {}", short(force))));
        }
        match self.load_end() {
            Ok(pull) if force < pull.state.force_bar => {
                return Err(Error::OutOfRange {
                    name: "force",
                    value: force,
                    range: "[pull-off force, ∞) for this rho and model".into(),
                })
            }
            // a model whose force decreases along the whole branch has no
            // pull-off: every crossing is looked for
            Ok(_) | Err(Error::NoState(_)) => {}
            Err(e) => return Err(e),
        }
        self.at_load_all(force)?
            .into_iter()
            .next()
            .ok_or_else(|| Error::NoState(format!("no state at force {}", short(force))))
    }

    /// Load control: every state at force `force`, the stable one first.
    pub fn at_load_all(&self, force: f64) -> Result<Vec<State>> {
        check_range("force", force, true, "finite")?;
        if self.axisymmetric() {
            let m = self.model;
            let f = |a: f64| m.axisymmetric(a).map(|v| v.1).unwrap_or(f64::NAN);
            let pull = self.axisymmetric_pull_off()?;
            let mut out = Vec::new();
            if force >= pull.force_bar {
                out.push(self.axisymmetric_state(bisect(|a| f(a) - force, pull.a_bar, 1e6)?)?);
                if force < f(1e-9) {
                    out.push(self.axisymmetric_state(bisect(
                        |a| f(a) - force,
                        1e-9,
                        pull.a_bar,
                    )?)?);
                }
            }
            return Ok(out);
        }
        if self.near_circle() {
            let circle = self.circle()?.at_load_all(force)?;
            let anchor = self.anchor()?.at_load_all(force)?;
            return circle
                .iter()
                .zip(&anchor)
                .map(|(c, a)| {
                    self.near_circle_controlled(Some(c), a, Quantity::Force, force, "load control")
                })
                .collect();
        }
        self.crossings(Quantity::Force, force, "load control")
    }

    /// Pull-off under load control: the minimum of F̄ along the branch,
    /// located by Newton on the fold condition.
    pub fn pull_off_load(&self) -> Result<PullOff> {
        // a minimum of F̄ at a compressive force is no pull-off (issue 31,
        // item 6: apex45 far below the paper's range)
        self.tensile(self.load_end()?, "load")
    }

    /// `end` as a pull-off under `control` ("load" or "displacement") if
    /// its force is tensile: a pull-off is where a tensile load detaches
    /// the contact, and an end at a compressive force is refused, with
    /// that force.
    fn tensile(&self, end: PullOff, control: &str) -> Result<PullOff> {
        if end.state.force_bar < 0.0 {
            return Ok(end);
        }
        Err(Error::NoState(format!(
            "model {} has no {control}-controlled pull-off at rho = {}: its branch ends under {control} control at a compressive force (F = {} at a_bar = {}, s = {}), so the contact carries no tensile load",
            self.model_id(),
            short(self.rho),
            rounded(end.state.force_bar),
            rounded(end.state.a_bar),
            rounded(end.state.s)
        )))
    }

    /// Where the branch from large loads ends under load control, whatever
    /// the sign of its force (the load-controlled pull-off where it is
    /// tensile): the first minimum of F̄, or, for a model without an
    /// energy, the fold of the contact size where that comes first, as its
    /// displacement-controlled end (past the size fold the branch is far
    /// from the physical one; issue 31, item 6: max at ρ ≤ 0.03 had its
    /// minimum of F̄ there, after the displacement-controlled end).
    fn load_end(&self) -> Result<PullOff> {
        let mut end = self.force_minimum()?;
        if !self.has_energy() && end.state.beyond_size_fold {
            end.state = self.size_fold()?;
        }
        Ok(end)
    }

    /// The first minimum of F̄ along the branch from large loads.
    fn force_minimum(&self) -> Result<PullOff> {
        let basis = if self.has_energy() {
            FoldBasis::EnergyInstability
        } else {
            FoldBasis::ModelFold
        };
        if self.axisymmetric() {
            return Ok(PullOff {
                state: self.axisymmetric_pull_off()?,
                control: FoldCondition::Load,
                basis: FoldBasis::AxisymmetricMinimum,
            });
        }
        if self.near_circle() {
            let circle = self.circle()?.axisymmetric_pull_off()?;
            let anchor = self.anchor()?.force_minimum()?.state;
            return Ok(PullOff {
                state: self.near_circle_fold(&circle, &anchor, FoldCondition::Load)?,
                control: FoldCondition::Load,
                basis,
            });
        }
        let guess = self.branch_minimum(Quantity::Force, "pull-off under load control")?;
        let state = self.refine_fold(&guess, FoldCondition::Load)?;
        Ok(PullOff {
            state,
            control: FoldCondition::Load,
            basis,
        })
    }

    /// Pull-off under displacement control. For a model with an energy: the
    /// first state along the branch where the Hessian of Π̄ in (ā, s) stops
    /// being positive definite (a fold in δ̄), located by Newton on the fold
    /// condition. For a model without one: the end of the part of the
    /// branch that continues the non-adhesive one with dδ̄/dā > 0 — the first
    /// minimum of δ̄ or the fold of the contact size, whichever comes first;
    /// labelled a fold of the model, not a proven instability.
    ///
    /// An end at a compressive force is no pull-off: the contact would
    /// separate while still pressed (issue 31, item 6: `apexes` at
    /// ρ = 0.01, F̄ = +0.605, error (14) 250 %), and is refused as the
    /// load-controlled one is.
    pub fn pull_off_displacement(&self) -> Result<PullOff> {
        self.tensile(self.displacement_end()?, "displacement")
    }

    /// Where the branch from large loads ends under displacement control,
    /// whatever the sign of its force.
    fn displacement_end(&self) -> Result<PullOff> {
        let basis = if self.has_energy() {
            FoldBasis::EnergyInstability
        } else {
            FoldBasis::ModelFold
        };
        let from_anchor = |e: Error| match e {
            Error::NoState(why) => Error::NoState(format!(
                "at rho = {}, as at the near-circular anchor rho = {}: {why}",
                crate::error::short(self.rho),
                crate::error::short(1.0 - NEAR_CIRCLE)
            )),
            other => other,
        };
        if self.axisymmetric() {
            // δ̄(ā) increases along the circle, but below ā_b the circle is
            // a saddle (the cos 2θ mode). Where the branches at ρ < 1 have
            // a fold, it tends to that point (a subcritical bifurcation);
            // where they stay stable (the energy closure), so does the
            // limit: the stable state elongates
            self.anchor()?
                .pull_off_displacement()
                .map_err(from_anchor)?;
            return Ok(PullOff {
                state: self.circle_bifurcation()?,
                control: FoldCondition::Displacement,
                basis: FoldBasis::CircleBifurcation,
            });
        }
        if self.near_circle() {
            let anchor = self
                .anchor()?
                .pull_off_displacement()
                .map_err(from_anchor)?;
            let fold = self.near_circle_sqrt_fold(&anchor.state, FoldCondition::Displacement);
            let state = if self.has_energy() {
                fold?
            } else {
                // as below: the minimum of δ̄ or the fold of the contact
                // size, whichever comes first
                let size = self.size_fold()?;
                match fold {
                    Ok(m) if m.s > size.s => m,
                    _ => size,
                }
            };
            return Ok(PullOff {
                state,
                control: FoldCondition::Displacement,
                basis,
            });
        }
        if self.has_energy() && self.search == Search::Cold {
            let guess = self.cold_first_unstable()?;
            return Ok(PullOff {
                state: self.refine_fold(&guess, FoldCondition::Displacement)?,
                control: FoldCondition::Displacement,
                basis: FoldBasis::EnergyInstability,
            });
        }
        if self.has_energy() {
            let walk = self.walk()?;
            let k = walk
                .iter()
                .position(|st| {
                    st.stability.stable_displacement.is_some()
                        && !st.stability.strictly_stable_displacement
                })
                .ok_or_else(|| self.stable_throughout(walk.last().map(|st| st.s)))?;
            let guess = walk[k.saturating_sub(1)];
            return Ok(PullOff {
                state: self.refine_fold(&guess, FoldCondition::Displacement)?,
                control: FoldCondition::Displacement,
                basis: FoldBasis::EnergyInstability,
            });
        }
        let fold = self.size_fold()?;
        let state =
            match self.branch_minimum(Quantity::Delta, "pull-off under displacement control") {
                Ok(m) if m.s > fold.s => self.refine_fold(&m, FoldCondition::Displacement)?,
                _ => fold,
            };
        Ok(PullOff {
            state,
            control: FoldCondition::Displacement,
            basis: FoldBasis::ModelFold,
        })
    }

    /// The zero-force state (Section 5).
    pub fn zero_force(&self) -> Result<State> {
        self.at_load(0.0).map_err(|e| match e {
            Error::OutOfRange { name: "force", .. } => Error::NoState(format!(
                "model {} has no zero-force state at rho = {}: the force at the end of its branch under load control is above zero ({}), so the contact cannot be unloaded to F = 0",
                self.model_id(),
                short(self.rho),
                self.load_end()
                    .map(|p| crate::error::rounded(p.state.force_bar))
                    .unwrap_or_else(|_| "not located".into())
            )),
            other => other,
        })
    }
}

/// The least eigenvalue of a symmetric Hessian, classified by the neutral
/// band (a non-finite Hessian is unstable: no verdict can be read), and
/// whether it is strictly positive definite (the least eigenvalue above
/// 1e-9 of the largest in magnitude).
fn least_eigen<const N: usize>(h: nalgebra::SMatrix<f64, N, N>) -> (Eigen, bool)
where
    nalgebra::Const<N>:
        nalgebra::DimMin<nalgebra::Const<N>, Output = nalgebra::Const<N>> + nalgebra::ToTypenum,
    nalgebra::Const<N>: nalgebra::DimSub<nalgebra::U1>,
    nalgebra::DefaultAllocator: nalgebra::allocator::Allocator<
        <nalgebra::Const<N> as nalgebra::DimSub<nalgebra::U1>>::Output,
    >,
{
    let e = h.symmetric_eigenvalues();
    if !e.iter().all(|v| v.is_finite()) {
        return (Eigen::Unstable, false);
    }
    (Eigen::of(e.min(), e.amax()), e.min() > 1e-9 * e.amax())
}

/// The first interior index whose value is the smallest within 20 indices
/// on either side (and below its predecessor): a local minimum that
/// round-off of the order of the change over 20 steps cannot fake.
fn first_window_minimum(v: &[f64]) -> Option<usize> {
    let w = 20;
    (1..v.len().saturating_sub(1)).find(|&k| {
        let (lo, hi) = (k.saturating_sub(w), (k + w).min(v.len() - 1));
        (lo..=hi).all(|j| v[k] <= v[j]) && v[k] < v[k - 1]
    })
}

/// Bisection for a sign change of `f` on [lo, hi].
pub(crate) fn bisect(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> Result<f64> {
    let (mut flo, fhi) = (f(lo), f(hi));
    if !(flo.is_finite() && fhi.is_finite()) || flo.signum() == fhi.signum() {
        return Err(Error::NoState(format!(
            "no sign change on [{}, {}]",
            rounded(lo),
            rounded(hi)
        )));
    }
    for _ in 0..300 {
        let mid = 0.5 * (lo + hi);
        let fm = f(mid);
        if fm.signum() == flo.signum() {
            lo = mid;
            flo = fm;
        } else {
            hi = mid;
        }
        if (hi - lo).abs() <= 1e-15 * (lo.abs() + hi.abs()) {
            break;
        }
    }
    Ok(0.5 * (lo + hi))
}
