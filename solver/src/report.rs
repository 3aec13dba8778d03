//! The one output schema of the command line's `--json` (issue 22): every
//! subcommand prints one `Document`. One state sits under `"state"`,
//! several under `"states"`, each with the names of the Rust fields (and
//! of the Python package's `State`): `a_bar`, `b_bar`, `s`, `delta_bar`,
//! `force_bar`, … ; a state of `conformal:K` and an exact state add their
//! own keys to the same object. Events and verdicts are tagged objects
//! (`{"kind": "force_minimum", "state": {…}}`); an error is
//! `{"error": {"kind": …, "message": …}}`. With the feature `schema` the
//! JSON Schema of `Document` is derived from these types (`thinjkr
//! schema`, committed as docs/schema.json).
//!
//! Owns: `Document` and its parts, and the shapes of the command line's studies' outcomes (the
//! reach map's `SizeReach`, its `Window`s, the paths' [`Passed`], the
//! band map's [`BandMap`]), with [`band_maps_from_json_lines`] and
//! `documents_of` reading their JSON lines back. May use: `contact`, `conformal`, `layer` (its state),
//! `exact`, `curve`, `fold`, `units`, `error`, `slender` (its state's
//! shape, [`SlenderState`], re-exported here).

use crate::conformal::{ConformalState, Extremum};
use crate::contact::State;
use crate::curve::{Fold, FoldKind};
use crate::exact::branch::Event;
use crate::exact::ExactState;
pub use crate::slender::SlenderState;
#[cfg(feature = "cli")]
use crate::units::{Scales, Si};
#[cfg(feature = "cli")]
use crate::{contact::FoldBasis, error::Error, fold::FoldCondition};
#[cfg(feature = "cli")]
use serde::Deserialize;
use serde::Serialize;

/// The thin-layer equation (2)'s answer beside the layer of finite
/// thickness (`physical` at ρ = 1 without a model).
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct ThinLayer {
    /// The model of (2) that answered (the table of defaults').
    pub model: String,
    /// Its dimensionless state.
    pub state: AnyState,
    /// Its state in SI units.
    pub si: crate::units::Si,
    /// Its relative error against the layer on the answered quantity (the
    /// force at the pull-off; size and approach at a force; size and force
    /// at an approach; the larger).
    pub relative_error: f64,
}

/// Where (2) answers `physical` for coatings the layer of finite thickness
/// does not answer at this ρ: the best estimate of the layer's pull-off
/// force, or of its state at the force or approach asked, the same numbers
/// as the warning that gives it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct LayerEstimate {
    /// The estimate of the layer's pull-off force, in newtons; of a
    /// state's force where `state` is given (at a force, the force asked).
    pub force: f64,
    /// Where the estimate is of a state at a force or an approach: that
    /// state in SI units (its `force` the same as above); `None` for a
    /// pull-off.
    pub state: Option<crate::units::Si>,
    /// Its bound, relative to it (for a state, the larger on the answered
    /// quantities: the size and the approach at a force, the size and the
    /// force at an approach, the approach and the force relative to
    /// themselves or to 1 in the units (17) where smaller, as they pass
    /// through zero); `None` where none is measured for these coatings.
    pub within: Option<f64>,
    /// How it is made.
    pub by: EstimateBy,
    /// (2)'s relative error against it: of the pull-off force (for
    /// `ratio`, at ρ = 1), or on a state's answered quantities (the
    /// larger).
    pub thin_layer_error: f64,
    /// Whether it is the answer a person reads first: its bound is measured
    /// and below (2)'s error, so it is nearer the layer than (2) is
    /// (the command line's first line and Python's repr lead with it).
    pub leads: bool,
}

impl LayerEstimate {
    /// Its bound where it leads, else `None`.
    #[cfg(feature = "cli")]
    pub(crate) fn leading_bound(&self) -> Option<f64> {
        self.within.filter(|_| self.leads)
    }

    /// The estimate `force` (N) made `by`, within `within` (relative;
    /// `None` where not measured), against which (2) is `thin_layer_error`
    /// off; it leads where its bound is below that error.
    pub(crate) fn new(
        force: f64,
        within: Option<f64>,
        by: EstimateBy,
        thin_layer_error: f64,
    ) -> LayerEstimate {
        LayerEstimate {
            force,
            state: None,
            within,
            by,
            thin_layer_error,
            leads: within.is_some_and(|w| w < thin_layer_error),
        }
    }
}

/// How a [`LayerEstimate`] is made (docs/thickness.md, "`physical` by
/// default").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum EstimateBy {
    /// (2) with the coatings' edge as a line tension kept whole, plus the
    /// layer's departure from that on the circle (from ρ = 0.65 up).
    LineTension,
    /// A state: (2) with the coatings' edge as a line tension kept whole,
    /// at the approach moved by the layer's interior (from ρ = 0.5 up).
    ShiftedLineTension,
    /// The layer's pull-off at first order in h/L.
    FirstOrder,
    /// (2)'s pull-off times the layer's ratio to it at ρ = 1.
    Ratio,
}

impl EstimateBy {
    /// How the estimate is made, in a few words (the warning that gives
    /// it says more).
    #[cfg(feature = "cli")]
    pub(crate) fn words(self) -> &'static str {
        match self {
            EstimateBy::LineTension => "the coatings' edge as a line tension kept whole",
            EstimateBy::ShiftedLineTension => {
                "the coatings' edge as a line tension kept whole, at the approach moved by the layer's interior"
            }
            EstimateBy::FirstOrder => "the first order in h/L",
            EstimateBy::Ratio => "(2)'s ratio to the layer at rho = 1",
        }
    }
}

/// A state of any model: of the ellipse, of the contour family, or exact.
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(untagged)]
pub enum AnyState {
    /// A model of the ellipse (`max`, `apexes`, `energy`, `apex45`); in
    /// JSON with its `warnings` in words beside its flags.
    #[serde(serialize_with = "ellipse_with_warnings")]
    #[cfg_attr(feature = "schema", schemars(with = "EllipseJson"))]
    Ellipse(State),
    /// A member of `conformal:K`.
    Conformal(ConformalState),
    /// The exact solution of (2)–(3).
    Exact(Box<ExactState>),
    /// The slender limit ρ → 0 (`slender`).
    Slender(SlenderState),
    /// The layer of finite thickness at ρ = 1 (`layer`).
    Layer(crate::layer::LayerState),
    /// The layer of finite thickness at ρ < 1: its pull-off under load
    /// control in the plane (`layer`, by the grid solver).
    LayerPlane(Box<crate::layer::PlaneState>),
}

/// A state of a model of the ellipse as JSON: its fields and, where it is
/// doubtful, why, in the words every front end shows.
#[derive(Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
struct EllipseJson {
    #[serde(flatten)]
    state: State,
    /// Why the state is doubtful (ρ below the paper's stated range, beyond
    /// the contact-size fold); absent when it is not.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    warnings: Vec<&'static str>,
}

fn ellipse_with_warnings<S: serde::Serializer>(st: &State, s: S) -> Result<S::Ok, S::Error> {
    EllipseJson {
        state: *st,
        warnings: st.warning_words(),
    }
    .serialize(s)
}

impl AnyState {
    /// (ā, b̄, δ̄, F̄) of the state, whatever its model (a slender state's
    /// ā is infinite: its contact has no finite length; b̄ is its half-width
    /// at the centre).
    pub fn size_and_load(&self) -> (f64, f64, f64, f64) {
        match self {
            AnyState::Ellipse(st) => (st.a_bar, st.b_bar, st.delta_bar, st.force_bar),
            AnyState::Conformal(st) => (st.a_bar, st.b_bar, st.delta_bar, st.force_bar),
            AnyState::Exact(st) => (st.a_bar, st.b_bar, st.delta_bar, st.force_bar),
            AnyState::Slender(st) => (f64::INFINITY, st.b_bar, st.delta_bar, st.force_bar),
            AnyState::Layer(st) => (st.a_bar, st.a_bar, st.delta_bar, st.force_bar),
            AnyState::LayerPlane(st) => (st.a_bar, st.b_bar, st.delta_bar, st.force_bar),
        }
    }
}

/// A fold of a curve, of any model.
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct AnyFold {
    /// Which quantity turns.
    pub kind: FoldKind,
    /// The state there.
    pub state: AnyState,
}

impl From<Fold> for AnyFold {
    fn from(f: Fold) -> AnyFold {
        AnyFold {
            kind: f.kind,
            state: AnyState::Ellipse(f.state),
        }
    }
}

impl From<crate::conformal::CurveFold> for AnyFold {
    fn from(f: crate::conformal::CurveFold) -> AnyFold {
        AnyFold {
            kind: f.kind,
            state: AnyState::Conformal(f.state),
        }
    }
}

/// What happens along a branch on the way to a state (tagged by `kind`).
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Passed {
    /// ā turns (a fold of the contact size) near `a_bar`.
    SizeFold {
        /// ā there.
        a_bar: f64,
        /// F̄ there, where known.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        force_bar: Option<f64>,
    },
    /// A bifurcation point of the exact family between two ā.
    Bifurcation {
        /// The ā of the traced points that bracket it.
        between: [f64; 2],
        /// The contour mode n that dominates its null direction.
        mode: Option<usize>,
    },
    /// The unloading path to an exact pull-off (`exact pull-off
    /// --unloading`): the family traced from its state at F̄ = `from_force`
    /// (10, else the largest stable load on the pull-off's piece)
    /// towards smaller ā to its first minimum of F̄. `None` where the path
    /// is not settled (`why_not_settled` says why).
    Unloading {
        /// The load the path starts from.
        from_force: f64,
        /// Which state it starts from (none where no start is found).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        start_at: Option<StartAt>,
        /// Whether its first force minimum is this pull-off.
        reaches: Option<bool>,
        /// F̄ at its first force minimum.
        first_minimum_force: Option<f64>,
        /// ā there.
        first_minimum_a_bar: Option<f64>,
        /// The largest h/L below which a traced state is unstable under
        /// load control above the short-wave cutoff (the longest unstable
        /// contour mode's wavelength over 2π); `None` when no contour mode
        /// is unstable on the way.
        critical_thinness: Option<f64>,
        /// That mode's n.
        critical_mode: Option<usize>,
        /// The thinness h/L the path is judged with.
        cutoff_thinness: f64,
        /// Whether every traced state is stable under load control above
        /// the cutoff (h/L above the critical thinness and the size stable).
        stable_above_cutoff: Option<bool>,
        /// The contour modes of the bifurcation points the trace meets
        /// before its minimum, in order: at ρ < 1 the family has none (the
        /// circle's bifurcations are imperfect), so each is a band the
        /// trace steps across onto the piece beyond; at ρ = 1 the circle's
        /// neutral points.
        #[serde(default)]
        bands_crossed: Vec<usize>,
        /// Why the path is not settled, in words.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        why_not_settled: Option<String>,
    },
    /// The loading path by descent (`--unloading`; docs/exact.md, "The
    /// loading path by descent"): the load lowered from F̄ = 10 (else from
    /// the largest stable load on the pull-off's piece) in steps, each state
    /// the descent of the potential at the new load from the last, modes
    /// shorter than the cutoff held at equilibrium.
    LoadingPath {
        /// The load the path starts from.
        from_force: f64,
        /// Which state it starts from (none where no start is found).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        start_at: Option<StartAt>,
        /// The thinness h/L whose cutoff chose the moving modes.
        cutoff_thinness: f64,
        /// The number of states held on the way.
        states_held: usize,
        /// The forces at which the path jumped to another state.
        jump_forces: Vec<f64>,
        /// ā of the state each jump landed on.
        jump_landing_a_bar: Vec<f64>,
        /// The modes of the bands the path passed (docs/exact.md, "Bands
        /// of unresolved modes"): where the arm it holds turns into lobes
        /// of a mode shorter than the cutoff (above 1 % of ā), the contact
        /// goes on from the piece beyond the band, found at smaller sizes
        /// from the contour with those undulations taken off.
        #[serde(default)]
        bands_passed: Vec<usize>,
        /// F̄ of the state of (2) at which each band's lobes pass 1 % of ā.
        #[serde(default)]
        bands_passed_unresolved_at: Vec<f64>,
        /// F̄ of the state beyond each band where the path goes on: where
        /// that piece's states of a shape the cutoff resolves begin, below
        /// the force at which the lobes passed 1 % of ā.
        #[serde(default)]
        bands_passed_to_force: Vec<f64>,
        /// ā of that state.
        #[serde(default)]
        bands_passed_to_a_bar: Vec<f64>,
        /// The contour modes shorter than the cutoff to which the path's
        /// states turn unstable on the way and stay so (the path does not
        /// count them): below ρ = 1, on a near-elliptic piece, each is a
        /// band the path steps over (at ρ = 1 a neutral point of the
        /// circle); past a fold in ā, the fold's mode.
        #[serde(default)]
        unresolved_turned_unstable: Vec<usize>,
        /// F̄ of the first state from which each stays unstable.
        #[serde(default)]
        unresolved_turned_unstable_at: Vec<f64>,
        /// F̄ where the path first loses the state it holds (a fold in F̄
        /// or a resolved mode turning unstable); none where it is not
        /// settled before.
        first_lost_force: Option<f64>,
        /// ā there.
        first_lost_a_bar: Option<f64>,
        /// Whether that state is this pull-off.
        reaches: Option<bool>,
        /// Whether the contact comes off where the path ends (true: the
        /// path's pull-off is its last state; false: not settled there).
        comes_off: Option<bool>,
        /// Why the path or the descent from its last state is not settled,
        /// in words.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        why_not_settled: Option<String>,
    },
}

/// Which state a path begins from.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum StartAt {
    /// The state at the large load F̄ = 10.
    LargeLoad,
    /// No state at F̄ = 10 was found (`why_not_large_load`): the largest
    /// load resolved on the piece that carries the pull-off.
    PullOffPiece {
        /// Why the state at F̄ = 10 is not the start, in words.
        why_not_large_load: String,
        /// Whether that load is a maximum of F̄ on the piece (true) or not:
        /// the piece rises further, past states that its modes do not
        /// resolve or that are unstable under load.
        maximum: bool,
        /// The largest F̄ resolved on that side of the piece.
        top_force: f64,
        /// F̄ of the start.
        start_force: f64,
    },
}

impl StartAt {
    /// The start in words, after "from F = …"; `brief`: without the
    /// reasons (said on the unloading trace's line before).
    #[cfg_attr(not(feature = "cli"), allow(dead_code))]
    pub(crate) fn words(&self, brief: bool) -> String {
        match self {
            StartAt::LargeLoad => String::new(),
            StartAt::PullOffPiece { .. } if brief => {
                " (the largest stable load on the piece that carries the pull-off, as above)".into()
            }
            StartAt::PullOffPiece {
                why_not_large_load,
                maximum,
                top_force,
                start_force,
            } => {
                // the reason's first clause (the whole is in the JSON)
                let why_not_large_load = first_clause(why_not_large_load);
                let top = if *maximum {
                    "its maximum of F".to_string()
                } else if *top_force > *start_force {
                    format!(
                        "above it, up to F = {} (the last state its modes resolve to 1e-9), unstable under load to a mode the cutoff resolves",
                        crate::error::short(*top_force)
                    )
                } else {
                    "the last state its modes resolve to 1e-9 (the piece rises further, not resolved by them)".to_string()
                };
                format!(
                    " (no state at F = {}: {why_not_large_load}; the start is the largest load stable under load on the piece that carries the pull-off, {top})",
                    crate::exact::START_FORCE
                )
            }
        }
    }
}

#[cfg(feature = "cli")]
/// How a size's path in ρ ended.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(tag = "kind", rename_all = "snake_case")]
pub(crate) enum Reached {
    /// ρ turned back at this located fold; the fine-grid boundary error of
    /// the path's lowest point (absent where that system is singular).
    TurnsBack {
        /// The fold's ρ: the size's reach.
        rho: f64,
        /// The boundary error there.
        bc_error: Option<f64>,
    },
    /// The path reached ρ = 0.02, the smallest it is followed to, without
    /// turning back.
    Floor {
        /// The boundary error of the state at the floor.
        bc_error: f64,
    },
    /// The path stopped without turning back (no state of this size near
    /// the circle, or a step that failed): why, in words.
    Stopped {
        /// Why.
        why: String,
    },
}

#[cfg(feature = "cli")]
/// One point of the map of (2)'s pull-off error against the coatings'
/// thinness and the crossing angle (`thickness-map --json`; issue 71):
/// equal incompressible coatings on equal cylinders.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub(crate) struct ThicknessPoint {
    /// The crossing angle θ in degrees.
    pub theta_deg: f64,
    /// Radii ratio ρ = tan²(θ/2).
    pub rho: f64,
    /// Each coating's thinness h/L.
    pub thinness: f64,
    /// (2)'s exact pull-off F̄₍₂₎ at ρ (the units (17), the same at every
    /// thinness).
    pub force_bar_2: f64,
    /// The layer's pull-off: its force, the bound on its relative error,
    /// how it was found and (2)'s relative error −F̄₍₂₎/F̄ − 1; or why it
    /// has none.
    pub layer: ThicknessAnswer,
}

#[cfg(feature = "cli")]
/// The layer's pull-off at one point of the thickness map, or why it has
/// none.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(tag = "kind", rename_all = "snake_case")]
pub(crate) enum ThicknessAnswer {
    /// The layer's pull-off under load control.
    Found {
        /// Its force F̄ (the units (17)).
        force_bar: f64,
        /// The bound on F̄'s relative error it states.
        force_error: f64,
        /// How it was found: `axisymmetric` (ρ = 1), `sharp_edge` or `grid`.
        method: String,
        /// (2)'s relative error, F̄₍₂₎/F̄ − 1 (positive where (2)
        /// overstates the pull-off).
        error_2: f64,
    },
    /// No pull-off: why, in words.
    None {
        /// Why.
        why: String,
    },
}

#[cfg(feature = "cli")]
/// One size's reach.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub(crate) struct SizeReach {
    /// ā.
    pub a_bar: f64,
    /// The modes of each sign of the arclength representation.
    pub modes: usize,
    /// How its path in ρ ended.
    pub reached: Reached,
}

#[cfg(feature = "cli")]
/// One end of a window of `studies::reach::settle`: where the family at that ρ, traced
/// in ā from the window's state, ends on that side.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(tag = "kind", rename_all = "snake_case")]
pub(crate) enum WindowEnd {
    /// The family folds in ā: the edge of the band beyond.
    Fold {
        /// ā at the fold.
        a_bar: f64,
        /// s there.
        s: f64,
        /// F̄ there.
        force_bar: f64,
        /// The contour mode n of the fold's null direction, where computed.
        mode: Option<usize>,
        /// The fine-grid boundary error there.
        bc_error: f64,
    },
    /// Before any fold the series stopped following the family: at this
    /// traced point the boundary error passed `studies::reach::WINDOW_RESOLVED`. The
    /// family goes on, with a shape `studies::reach::MODES` modes do not resolve.
    Unresolved {
        /// ā there.
        a_bar: f64,
        /// F̄ there.
        force_bar: f64,
        /// The boundary error there.
        bc_error: f64,
    },
    /// ā moved `studies::reach::WINDOW_SPAN` from the start without a fold.
    Beyond {
        /// The ā passed.
        a_bar: f64,
    },
    /// The trace failed: why, in words.
    Failed {
        /// Why.
        why: String,
    },
    /// The trace ended (at a fold, or where it stopped being resolved, or
    /// at its limit) past another window of the grid, across the band
    /// between, in steps of 0.01 and again in the band maps' fine steps
    /// (a band narrower than those, or another arm it left the piece
    /// for). Not settled.
    Crossed {
        /// Where it ended.
        a_bar: f64,
        /// The window it passed: its first and last size on the grid.
        window: [f64; 2],
    },
}

#[cfg(feature = "cli")]
impl WindowEnd {
    /// Where the trace ended; `None` where it failed.
    pub(crate) fn a_bar(&self) -> Option<f64> {
        match self {
            WindowEnd::Fold { a_bar, .. }
            | WindowEnd::Unresolved { a_bar, .. }
            | WindowEnd::Beyond { a_bar }
            | WindowEnd::Crossed { a_bar, .. } => Some(*a_bar),
            WindowEnd::Failed { .. } => None,
        }
    }
}

#[cfg(feature = "cli")]
/// A window of the reach at one ρ, settled by the family at that ρ: the
/// state of the window's size with the smallest reach, followed from the
/// circle at fixed ā down to ρ, traced in ā both ways to where the family
/// folds (a band's edge) or stops being resolved.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub(crate) struct Window {
    /// ρ.
    pub rho: f64,
    /// The window of `studies::reach::windows`: its first and last size on the grid.
    pub grid: [f64; 2],
    /// The size the traces start from.
    pub a_bar: f64,
    /// F̄ of its state at ρ (absent where the state was not found).
    pub force_bar: Option<f64>,
    /// The boundary error of that state.
    pub bc_error: Option<f64>,
    /// For which coatings (2) gives that state as a contact it resolves
    /// (stable above the cutoff under each control, its shape resolved);
    /// absent where the state or its stability was not found.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub coatings: Option<crate::exact::undulations::Coatings>,
    /// The loading path from that state (`--unloading-at`), where it is a
    /// stable contact (2) resolves at that thinness.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unloading: Option<WindowPath>,
    /// Towards smaller ā.
    pub lower: WindowEnd,
    /// Towards larger ā.
    pub upper: WindowEnd,
}

#[cfg(feature = "cli")]
/// The loading path (`studies::loading`) from a window's start, unloaded
/// under load control with the cutoff of one thinness.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub(crate) struct WindowPath {
    /// The thinness h/L of the cutoff.
    pub thinness: f64,
    /// How many states it held on its own piece, the start first.
    pub states: usize,
    /// How many jumps it made.
    pub jumps: usize,
    /// The modes shorter than the cutoff its states turned unstable to on
    /// the way and stayed so (`LoadingPath::unresolved_turned_unstable`), in
    /// order: below ρ = 1 a band stepped over on a near-elliptic piece, or
    /// past a fold in ā the fold's mode.
    #[serde(default)]
    pub unresolved_turned_unstable: Vec<usize>,
    /// Where the path passed the band whose lobes ended its piece (the
    /// last state held here), F̄ and ā of the state beyond, on the piece
    /// below, from which it goes on as that piece's path (followed up to
    /// that band only: `studies::loading::loading_path_to_first_band`,
    /// docs/exact.md "Bands of unresolved modes"); none where it found no
    /// piece beyond, or ended before.
    #[serde(default)]
    pub passed_to: Option<[f64; 2]>,
    /// F̄ of the last state held whose shape the cutoff resolves.
    pub resolved_force_bar: f64,
    /// F̄ of the last state held.
    pub last_force_bar: f64,
    /// ā of the last state held.
    pub last_a_bar: f64,
    /// Where the last state held has undulations shorter than the cutoff
    /// above 1 % of ā: the largest such mode and their share of ā.
    pub unresolved: Option<(usize, f64)>,
    /// How the path ends: it comes off (the path's pull-off), loses its
    /// state, or is not settled, in words.
    pub end: String,
}

/// The first clause of a reason (up to its first "; "): the long story of
/// why no state at F̄ = 10 is found (every route tried) is in the JSON and
/// in `thinjkr exact solve --force 10`.
pub(crate) fn first_clause(why: &str) -> &str {
    why.split("; ").next().unwrap_or(why)
}

impl Passed {
    /// The exact solver's events (its force minimum is the pull-off itself
    /// and is not repeated).
    pub(crate) fn from_exact(events: &[Event]) -> Vec<Passed> {
        events
            .iter()
            .filter_map(|e| match e {
                Event::SizeFold { a_bar } => Some(Passed::SizeFold {
                    a_bar: *a_bar,
                    force_bar: None,
                }),
                Event::Bifurcation { between, mode } => Some(Passed::Bifurcation {
                    between: *between,
                    mode: *mode,
                }),
                _ => None,
            })
            .collect()
    }

    /// The folds in ā that the trace of `conformal:K` passed.
    pub(crate) fn from_conformal(folds: &[Extremum]) -> Vec<Passed> {
        folds
            .iter()
            .map(|f| Passed::SizeFold {
                a_bar: f.a_bar,
                force_bar: Some(f.force_bar),
            })
            .collect()
    }
}

/// An error, in words and by kind ([`Error::kind`]).
#[cfg(feature = "cli")]
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub(crate) struct ErrorBody {
    /// `out_of_range`, `no_convergence`, `unresolved`, `no_state`, `usage`,
    /// `unsupported`, `io` or `unavailable`.
    pub kind: String,
    /// The message, as the command line prints it: at most 300
    /// characters.
    pub message: String,
    /// The whole record, where the message is shortened from it (an
    /// exact request's routes each add theirs); `--explain` prints it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub record: Option<String>,
}

#[cfg(feature = "cli")]
impl From<&Error> for ErrorBody {
    fn from(e: &Error) -> Self {
        let (message, whole) = (e.brief(), e.to_string());
        ErrorBody {
            kind: e.kind().into(),
            record: (message != whole).then_some(whole),
            message,
        }
    }
}

/// One model's answer beside the exact one: its state, or why it has none.
#[cfg(feature = "cli")]
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub(crate) struct ModelAnswer {
    /// The model's name.
    pub model: String,
    /// Its state at the same control (or its pull-off).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub state: Option<State>,
    /// A contour family member's state (beside the exact state of its
    /// family's own gap, `exact … --gap`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub member: Option<crate::conformal::ConformalState>,
    /// Why it has none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<ErrorBody>,
}

#[cfg(feature = "cli")]
impl ModelAnswer {
    /// From a model's result.
    pub(crate) fn new(model: &str, r: &crate::Result<State>) -> Self {
        ModelAnswer {
            model: model.into(),
            state: r.as_ref().ok().copied(),
            member: None,
            error: r.as_ref().err().map(ErrorBody::from),
        }
    }

    /// From a contour family member's result.
    pub(crate) fn member(model: &str, r: &crate::Result<crate::conformal::ConformalState>) -> Self {
        ModelAnswer {
            model: model.into(),
            state: None,
            member: r.as_ref().ok().cloned(),
            error: r.as_ref().err().map(ErrorBody::from),
        }
    }
}

/// A model in the list of `thinjkr models`.
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct ModelEntry {
    /// The name `--model` takes.
    pub name: String,
    /// What it is, in a line.
    pub description: String,
    /// The contour family it is a member of (from the registry), if any.
    pub family: Option<String>,
    /// How many unknowns its equations have (none for `exact`, whose
    /// contour series is sized per solve).
    pub unknowns: Option<usize>,
    /// The smallest ρ its solves accept (the largest is 1).
    pub rho_min: f64,
    /// The controls a state can be held at: `delta`, `force`, `a`.
    pub controls: Vec<String>,
}

/// Everything `--json` prints: exactly one of these objects.
#[cfg(feature = "cli")]
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(untagged)]
pub(crate) enum Document {
    /// A pull-off: the state where a controlled branch ends.
    PullOff {
        /// The state.
        state: AnyState,
        /// The control it ends.
        control: FoldCondition,
        /// What ends it there (models of the ellipse).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        basis: Option<FoldBasis>,
        /// What the trace passed on the way.
        passed: Vec<Passed>,
        /// The models of the ellipse at the same control (beside an exact
        /// pull-off).
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        models: Vec<ModelAnswer>,
    },
    /// A state in SI units and its dimensionless state.
    Physical {
        /// The dimensionless state.
        state: AnyState,
        /// The same state in SI units.
        si: Si,
        /// The scales of (17) of this contact.
        scales: Scales,
        /// Inputs outside the model's stated range of validity.
        warnings: Vec<String>,
        /// The name of the model that answered (named, or chosen by the
        /// table of defaults).
        model: String,
        /// Where no model was named: the model the table of defaults
        /// chose for this ρ and question, and why.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        chosen_because: Option<String>,
        /// Where no model was named and the chosen one is not `max`: the
        /// paper's model `max` at the same question, when the two differ by
        /// more than 1 % in F̄, δ̄ or ā.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        paper_model: Option<AnyState>,
        /// Where the layer of finite thickness answered by default (ρ = 1):
        /// the thin-layer equation (2)'s answer and its relative error.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        thin_layer: Option<ThinLayer>,
        /// Where (2) answered coatings the layer does not answer at this
        /// ρ: the best estimate of the layer's pull-off force.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        layer_estimate: Option<LayerEstimate>,
    },
    /// One state (`solve`, `zero-force`, `exact solve`), with the models
    /// of the ellipse at the same control beside an exact one.
    State {
        /// The state.
        state: AnyState,
        /// The models at the same control (beside an exact state).
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        models: Vec<ModelAnswer>,
        /// How many other states have the same force (`solve --force`
        /// with a model of the ellipse), or the same control on the
        /// member's curve (`solve` with a contour family, at any control);
        /// `solve --all` lists them. Absent where not counted.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        others: Option<usize>,
    },
    /// A curve (`curve --format json`): its states in order and its folds
    /// (`{"kind": "load", "state": {…}}`).
    Curve {
        /// The states along the branch.
        states: Vec<AnyState>,
        /// The folds met.
        folds: Vec<AnyFold>,
        /// Why the trace ended, where that is not the model's own end of
        /// the branch (`conformal:K`: the map stops being one-to-one, or
        /// the contact shrank away).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        end: Option<String>,
    },
    /// Several states (`solve --a`: every state of that contact size).
    States {
        /// The states.
        states: Vec<AnyState>,
    },
    /// The band map of the exact family (`exact bands`).
    Bands {
        /// The bands at one ρ.
        bands: BandMap,
    },
    #[cfg(feature = "cli")]
    /// The reach in ρ of one contact size (`exact reach --json`).
    Reach {
        /// The size and how its path in ρ ended.
        reach: SizeReach,
    },
    #[cfg(feature = "cli")]
    /// One point of the thickness map (`thickness-map --json`).
    Thickness {
        /// The point.
        thickness: ThicknessPoint,
    },
    #[cfg(feature = "cli")]
    /// A window of the reach at one ρ settled by the family at that ρ
    /// (`exact reach --windows-at --json`).
    Window {
        /// The window and where the family ends on either side.
        window: Window,
    },
    /// The models (`models --json`).
    Models {
        /// Every model.
        models: Vec<ModelEntry>,
    },
    /// A failure.
    Error {
        /// What failed.
        error: ErrorBody,
    },
}

#[cfg(feature = "cli")]
impl Document {
    /// The JSON text of the document (one line).
    pub(crate) fn to_json(&self) -> String {
        serde_json::to_string(self).expect("the output types serialise")
    }
}

/// The JSON Schema of [`Document`] (pretty, as committed in
/// docs/schema.json).
#[cfg(feature = "cli")]
pub(crate) fn schema() -> String {
    let s = schemars::schema_for!(Document);
    serde_json::to_string_pretty(&s).expect("a schema serialises") + "\n"
}

/// A gap of the screen that the exact family crosses: no band there.
#[derive(Clone, Debug, Serialize, serde::Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct Crossed {
    /// The near-elliptic grid points of the model on either side.
    pub screened: [f64; 2],
    /// Why it is no band, in words.
    pub why: String,
}

/// A neutral point of the circle, ā³ = 4(n − 1), that the screen passed
/// without a gap, probed by the exact family in fine steps (`PROBE_STEP`):
/// a band narrower than the screen's step would show there.
#[derive(Clone, Debug, Serialize, serde::Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct Probe {
    /// The contour mode n.
    pub n: usize,
    /// ā of the neutral point, (4(n − 1))^(1/3).
    pub a_bar: f64,
    /// "band" where one was found (it is in the map's bands), else why
    /// there is none or why the probe failed, in words.
    pub outcome: String,
}

/// F̄ at one ā of the screen: the model's and the exact family's.
#[derive(Clone, Debug, Serialize, serde::Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct CurvePoint {
    /// ā.
    pub a_bar: f64,
    /// F̄ of the screening model's near-elliptic state at this ā (`None`
    /// where it has none).
    pub model: Option<f64>,
    /// F̄ of the exact state at this ā started from the model's (every
    /// `CURVE_EVERY`th grid point; `None` elsewhere, where the model has
    /// none, or where no resolved exact state lands near the model's).
    pub exact: Option<f64>,
}

/// The band map at one ρ over a range of ā.
#[derive(Clone, Debug, Serialize, serde::Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct BandMap {
    /// ρ.
    pub rho: f64,
    /// The ā range screened.
    pub range: [f64; 2],
    /// The grid step of the screen.
    pub step: f64,
    /// The model that screened.
    pub screen: String,
    /// The bands, by increasing ā.
    pub bands: Vec<crate::exact::bands::Band>,
    /// The model's gaps that the exact family crosses.
    pub crossed: Vec<Crossed>,
    /// The model's gaps the exact family could not settle (no resolved
    /// exact state beside them, or a trace that failed), with why.
    pub unsettled: Vec<Crossed>,
    /// Gaps of the screen at an end of the range (not bracketed, not
    /// settled).
    pub open_ends: Vec<[f64; 2]>,
    /// The neutral points of the circle in the range that the screen
    /// passed without a gap, each probed by the exact family.
    #[serde(default)]
    pub probed: Vec<Probe>,
    /// F̄(ā) of the model and of the exact family over the screen.
    pub curve: Vec<CurvePoint>,
}

/// The band maps of a file of `thinjkr exact bands --json` lines (one
/// `{"bands": …}` document per line, as docs/data/exact_bands.jsonl).
pub fn band_maps_from_json_lines(text: &str) -> crate::error::Result<Vec<BandMap>> {
    documents_of(text, "bands", "band map")
}

/// The values under `key` of the one-document-per-line JSON `text` (as
/// `thinjkr exact bands --json` and `exact reach --json` write them);
/// an error names the first line that is not such a `what` document.
pub(crate) fn documents_of<T: serde::de::DeserializeOwned>(
    text: &str,
    key: &str,
    what: &str,
) -> crate::error::Result<Vec<T>> {
    text.lines()
        .filter(|l| !l.trim().is_empty())
        .enumerate()
        .map(|(k, l)| {
            serde_json::from_str::<serde_json::Value>(l)
                .ok()
                .and_then(|mut v| v.get_mut(key).map(serde_json::Value::take))
                .ok_or_else(|| format!("no \"{key}\" in it"))
                .and_then(|v| serde_json::from_value(v).map_err(|e| e.to_string()))
                .map_err(|e| {
                    crate::error::Error::NoState(format!(
                        "line {} is not a {what} document: {e}",
                        k + 1
                    ))
                })
        })
        .collect()
}
