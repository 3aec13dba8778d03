//! The resolution policy of the exact solver: which truncations are tried
//! and when one resolves a state (the escalation of contour modes, the
//! fine-grid boundary error a state must reach), and the routes to a state
//! or a pull-off (from the seeding model's state, along the family, past
//! the folds of a band, continued in ρ from a larger ρ, and where that
//! stops, whether the family turns back in ρ: `rho_path`). The problem itself
//! (the contour, the fields, the equations, one truncation's Newton) is the
//! parent's.
//!
//! The routes and their order are two tables, [`STATE_ROUTES`] and
//! [`PULL_OFF_ROUTES`], run by one loop ([`run`]); what every route
//! missed is one typed error ([`Misses`]).
//!
//! Owns: [`CONVERGED`], [`RESOLVED`], [`default_tries`], [`resolved`],
//! [`pull_off_resolved`], [`at_resolved`], [`at_searched`],
//! [`continued_in_rho`]. May use: its parent `exact`, `control`, `error`, `progress` (the
//! stage a spinner shows), `newton` (the
//! caller's stop flag).

use super::ladder::Ladder;
use super::rho_path::Followed;
use super::rho_walk::{walk_down, Attempt, Stopped};
use super::same::Same;
use super::{bands, branch, larger_contacts, Exact, ExactState, Gap, Route, Truncation};
use crate::control::Hold;
use crate::error::{Error, Result};

/// The largest max|∂p̄/∂ν − 1| on the independent fine grid for which a
/// pull-off is reported: above it the truncation does not resolve the
/// contour, and the answer is an error asking for more modes. (At
/// ρ = 0.8 a fine-grid error of 8e-6 goes with an error of 4e-9 in F̄.)
pub(crate) const RESOLVED: f64 = 1e-5;

/// The fine-grid boundary error at which `resolved` stops escalating:
/// the aspect ratio s of a pull-off changes by about 0.01–0.07 times the
/// boundary error when the truncation is doubled (docs/accuracy.md), so
/// 1e-9 keeps that change near or below 1e-10.
pub const CONVERGED: f64 = 1e-9;

/// An answer of the exact solver with its fine-grid boundary error.
pub(crate) trait BoundaryError {
    /// max |∂p̄/∂ν − 1| on the fine grid.
    fn bc_error(&self) -> f64;
    /// The exact states the answer holds, whose stability [`resolved`]
    /// computes once it has chosen the answer.
    fn states_mut(&mut self) -> Vec<&mut ExactState>;
}

impl BoundaryError for ExactState {
    fn bc_error(&self) -> f64 {
        self.bc_error
    }
    fn states_mut(&mut self) -> Vec<&mut ExactState> {
        vec![self]
    }
}

impl BoundaryError for (ExactState, Vec<branch::Event>) {
    fn bc_error(&self) -> f64 {
        self.0.bc_error
    }
    fn states_mut(&mut self) -> Vec<&mut ExactState> {
        let mut all = vec![&mut self.0];
        all.extend(self.1.iter_mut().filter_map(|e| e.state_mut()));
        all
    }
}

/// `solve` at `rho` on each rung of `ladder` in turn until one
/// converges the answer: its boundary error (max |∂p̄/∂ν − 1| on the
/// independent fine grid) at most [`CONVERGED`]. Only such an answer is
/// accepted from an escalation; where none converges the answer is an
/// [`Error::Unresolved`] naming the smallest boundary error reached and
/// with how many modes. A single truncation (a user's choice of modes)
/// gives its answer when it is resolved (≤ [`RESOLVED`]), with its
/// boundary error for the reader to judge. More modes help only a contour
/// that is nearly resolved: a boundary error above 1e-2 with
/// [`FOLLOWS_THE_FAMILY`] modes or more means the trace left the
/// near-elliptical family, and stops the escalation (as does any other
/// error); with fewer, the series may be too short to follow the contour,
/// and the next rung is tried.
///
/// The rungs predicted not to converge are skipped ([`Ladder::escalate`]).
/// The intermediate answers are solved without their stability; the
/// accepted answer's is computed once, with its own truncation.
pub(crate) fn resolved<T: BoundaryError>(
    gap: Gap,
    rho: f64,
    ladder: &Ladder,
    solve: impl Fn(&Exact) -> Result<T>,
) -> Result<T> {
    // (the climb from the ladder's rung up)
    let mut ladder = Ladder::of(ladder.from_rung().to_vec());
    let single = ladder.rungs().len() == 1;
    let mut best: Option<(T, Exact)> = None;
    let mut last = None;
    let with_stability = |(mut v, ex): (T, Exact)| {
        for st in v.states_mut() {
            st.stability = ex.stability(st)?;
        }
        Ok(v)
    };
    // where no truncation converges: a single truncation's resolved
    // answer, else an error that says how far the escalation got
    let or_best = |best: Option<(T, Exact)>, e: Error| match best {
        Some(b) if single => with_stability(b),
        Some((v, ex)) => Err(not_converged(rho, v.bc_error(), ex.truncation.modes, e)),
        None => Err(e),
    };
    while let Some(t) = ladder.rung() {
        crate::newton::check_stop()?;
        // (the stability is computed with the same problem: it does not
        // depend on the deferral, which only [`Exact::state`] reads)
        let ex = Exact::on(gap, rho, t)?.deferring_stability();
        match solve(&ex) {
            Ok(v) if v.bc_error() <= CONVERGED => return with_stability((v, ex)),
            Ok(v) => {
                ladder.saw(t.modes, v.bc_error());
                if best
                    .as_ref()
                    .is_none_or(|(b, _)| v.bc_error() < b.bc_error())
                {
                    best = Some((v, ex));
                }
            }
            // off the family with a series long enough to follow it
            Err(e @ Error::Unresolved { residual, .. })
                if residual > 1e-2 && t.modes >= FOLLOWS_THE_FAMILY =>
            {
                return or_best(best, e)
            }
            // too short a series to follow an elongated contour (at
            // ρ = 0.3 the pull-off's trace leaves the family with 12 to 20
            // modes, and converges with more): the next rung, its error
            // no measure of the rate
            Err(e @ Error::Unresolved { residual, .. }) if residual > 1e-2 => {
                last = Some(e);
            }
            // likewise a start that such a series cannot converge
            Err(e @ Error::NoState(_)) if t.modes < FOLLOWS_THE_FAMILY => {
                last = Some(e);
            }
            Err(e @ Error::Unresolved { residual, .. }) => {
                ladder.saw(t.modes, residual);
                last = Some(e);
            }
            Err(e) => return or_best(best, e),
        }
        if !ladder.escalate() {
            break;
        }
    }
    let tried = Error::Unresolved {
        what: format!("the most modes tried: {}", ladder.top_modes()),
        residual: f64::NAN,
    };
    match best {
        Some(_) => or_best(best, tried),
        None => Err(last.unwrap_or(tried)),
    }
}

/// The error of an escalation that did not converge: the smallest boundary
/// error reached, with how many modes, and the last error met.
fn not_converged(rho: f64, bc_error: f64, modes: usize, last: Error) -> Error {
    Error::Unresolved {
        what: format!(
            "exact answer at rho = {}: max |dp/dnu - 1| on the fine grid fell to {:.1e} with {} modes, not to the {:.0e} required ({})",
            crate::error::short(rho),
            bc_error,
            modes,
            CONVERGED,
            last.detail()
        ),
        residual: bc_error,
    }
}

/// The fewest contour modes with which a boundary error above 1e-2 (a
/// trace that left the near-elliptic family) stops an escalation: with
/// fewer, an elongated contour may not be followed at all (at ρ = 0.3 the
/// pull-off's trace leaves the family with 12, 16 and 20 modes; with 24 its
/// boundary error is 4.8e-4, with 40 5.1e-6).
const FOLLOWS_THE_FAMILY: usize = 24;

/// The default escalation (the conformal ladder): 12, 16, 20, 24, 28,
/// 32, 40, 48, 56, 64, 80 and 96 contour modes (of which the escalation
/// skips those predicted not to converge), each with `POINTS_PER_MODE`
/// quadrature points per mode.
pub fn default_tries() -> Vec<Truncation> {
    Ladder::conformal().rungs().to_vec()
}

/// The load-controlled pull-off at `rho` with the default escalation of
/// truncations (`resolved`, [`default_tries`]); below ρ = 0.3 on the
/// cylinders' gap, followed in ρ in the arclength representation from the
/// stored pull-offs (`super::stored`); where no start finds
/// it, followed in ρ from the pull-off at the first of ρ + 0.1, ρ + 0.2, …
/// that is found, in the arclength representation
/// (`pull_off_followed_in_arclength`).
pub fn pull_off_resolved(rho: f64) -> Result<(ExactState, Vec<branch::Event>)> {
    pull_off_resolved_on(Gap::cylinders(), rho)
}

/// [`pull_off_resolved`] on `gap`: below ρ = 0.3 on the cylinders' gap
/// from the stored pull-offs (the same pull-off as the follow from ρ = 0.3
/// reaches, sooner), else by the routes of [`PULL_OFF_ROUTES`].
pub(crate) fn pull_off_resolved_on(gap: Gap, rho: f64) -> Result<(ExactState, Vec<branch::Event>)> {
    if let Some(followed) = super::stored::pull_off(gap, rho) {
        return followed.map(|st| (st, Vec::new()));
    }
    run(&PULL_OFF_ROUTES, &Asked::new(gap, rho, None))
}

/// The load-controlled pull-off at `rho` on `gap`, climbing `ladder`
/// ([`resolved`]).
pub(crate) fn pull_off_on(
    gap: Gap,
    rho: f64,
    ladder: &Ladder,
) -> Result<(ExactState, Vec<branch::Event>)> {
    // the model's pull-off once; each truncation after the first starts
    // just above the pull-off the one before found (resolved or not)
    let model = branch::model_pull_off(gap, rho);
    let coarser: std::cell::RefCell<Option<ExactState>> = std::cell::RefCell::new(None);
    resolved(gap, rho, ladder, |ex| {
        let found = ex.pull_off_found(model.as_ref(), coarser.borrow().as_ref())?;
        *coarser.borrow_mut() = Some(found.0.clone());
        ex.accept_resolved_pull_off(found)
    })
}

/// The exact state at `control` with the default escalation of
/// truncations ([`at_searched`] with [`default_tries`]); where none is
/// found, and the control lies in no band of the near-elliptic family,
/// continued in ρ at the control from the state at a larger ρ
/// (`continued_in_rho`).
pub fn at_resolved(rho: f64, control: Hold) -> Result<ExactState> {
    at_resolved_on(Gap::cylinders(), rho, control)
}

/// [`at_resolved`] on `gap`: refused at once where the map of where the
/// search finds no state says so ([`super::no_state`]), else searched.
pub(crate) fn at_resolved_on(gap: Gap, rho: f64, control: Hold) -> Result<ExactState> {
    // (the map's ρ lie above the floor, which the search checks first)
    if let Some(none) = super::no_state::refusal(gap, rho, control) {
        return Err(none);
    }
    at_resolved_searching(gap, rho, control)
}

/// [`at_resolved_on`] without the map: every route searched (the map's
/// own search, and the routes that start from a state at another ρ).
pub(crate) fn at_resolved_searching(gap: Gap, rho: f64, control: Hold) -> Result<ExactState> {
    by_delta_or_force(control)?;
    let asked = format!("state at {control}");
    if let Some(below) = super::stored::below_the_floor(gap, rho, &asked) {
        return Err(below);
    }
    run(&STATE_ROUTES, &Asked::new(gap, rho, Some(control)))
}

/// A route to an answer (issue 69: the routes and their order are data,
/// [`STATE_ROUTES`] and [`PULL_OFF_ROUTES`]): the first miss it takes,
/// the words that name it where every route misses, and the route itself,
/// which answers or misses with a typed error.
type Strategy<T> = (Takes, &'static str, fn(&Asked) -> Result<T>);

/// Which first miss a route after the first answers.
#[derive(Clone, Copy)]
enum Takes {
    /// None: it is the first route.
    First,
    /// The first found no state, or its Newton or trace did not converge.
    NothingFound,
    /// The first resolved the state ([`RESOLVED`]) but did not converge it.
    NearlyResolved,
    /// The first found no pull-off, or did not resolve it.
    NoPullOff,
}

impl Takes {
    fn first(self, e: &Error) -> bool {
        match self {
            Takes::First => false,
            Takes::NothingFound => matches!(e, Error::NoState(_) | Error::NoConvergence { .. }),
            Takes::NearlyResolved => {
                matches!(e, Error::Unresolved { residual, .. } if *residual <= RESOLVED)
            }
            Takes::NoPullOff => matches!(e, Error::NoState(_) | Error::Unresolved { .. }),
        }
    }

    /// The error where the routes that take `first` miss too, with the
    /// words of every miss: not resolved where the first came near,
    /// else no state.
    fn all_missed(self, first: &Error, what: String) -> Error {
        match (self, first) {
            (Takes::NearlyResolved, Error::Unresolved { residual, .. }) => Error::Unresolved {
                what,
                residual: *residual,
            },
            _ => Error::NoState(what),
        }
    }
}

/// The routes to a state at a control, in the order tried. The first is
/// the seed's state at the control and its family with the conformal
/// ladder ([`searched_on`]). Where it comes near but not to
/// [`CONVERGED`] (at F̄ = 10 for 0.33 ≤ ρ ≤ 0.335, 1.5e-9 to 1.6e-8 with
/// its last rung), the same state solved again in the arclength
/// representation. Where it finds none (nor its Newton or trace
/// converges), and the control lies in no band ([`Error::InBand`] is
/// answered as it is): continued in ρ from the state at a larger ρ, and
/// below a fold in ρ met on the way; then every near-elliptic state the
/// seed's screen finds.
const STATE_ROUTES: [Strategy<ExactState>; 4] = [
    (Takes::First, "", seed_s_family),
    (
        Takes::NearlyResolved,
        "solved again in the arclength representation",
        again_in_arclength,
    ),
    (Takes::NothingFound, "", from_larger_rho),
    (Takes::NothingFound, "", screened),
];

/// The routes to the load-controlled pull-off, in the order tried (below
/// ρ = 0.3 on the cylinders' gap the stored pull-offs answer before
/// them, [`pull_off_resolved_on`]): the conformal ladder's
/// ([`pull_off_on`]); where that finds none or does not resolve it,
/// followed in ρ from the pull-off at a larger ρ in the arclength
/// representation ([`pull_off_followed_in_arclength`]).
const PULL_OFF_ROUTES: [Strategy<(ExactState, Vec<branch::Event>)>; 2] = [
    (Takes::First, "", |asked| {
        pull_off_on(asked.gap, asked.rho, &Ladder::conformal())
    }),
    (Takes::NoPullOff, "", |asked| {
        pull_off_followed_in_arclength(&asked.above()?, asked.rho).map(|st| (st, Vec::new()))
    }),
];

/// What the routes are asked: the gap, ρ and the control of a state
/// (`None`: the pull-off), and what a route leaves for the next: the
/// escalation's best state, where it resolves one without converging, and
/// the start at a larger ρ, found once for every route that needs it.
struct Asked {
    gap: Gap,
    rho: f64,
    control: Option<Hold>,
    best: std::cell::RefCell<Option<ExactState>>,
    above: std::cell::OnceCell<Result<ExactState>>,
}

impl Asked {
    fn new(gap: Gap, rho: f64, control: Option<Hold>) -> Asked {
        Asked {
            gap,
            rho,
            control,
            best: Default::default(),
            above: Default::default(),
        }
    }

    /// The control of the state asked for.
    fn control(&self) -> Result<Hold> {
        self.control
            .ok_or_else(|| Error::Usage("a state is asked at a control".into()))
    }

    /// The state at the control (or the pull-off) at the first larger ρ
    /// where the conformal ladder finds it ([`first_above`]): the start of
    /// the routes from a larger ρ, searched once.
    fn above(&self) -> Result<ExactState> {
        let (gap, rho) = (self.gap, self.rho);
        self.above
            .get_or_init(|| match self.control {
                None => first_above(gap, rho, |r| pull_off_on(gap, r, &Ladder::conformal()))
                    .map(|(st, _)| st)
                    .ok_or_else(|| {
                        Error::NoState(
                            "no pull-off found at any rho above it in steps of 0.1 to continue from"
                                .into(),
                        )
                    }),
                Some(control) => {
                    first_above(gap, rho, |r| {
                        at_with(gap, r, control, &Ladder::conformal(), &mut |_| {})
                    })
                        .ok_or_else(|| {
                            Error::NoState(format!(
                                "no state at {control} found at any rho above it in steps of 0.1 to continue from"
                            ))
                        })
                }
            })
            .clone()
    }
}

/// `routes` in their order for `asked`: each after the first only where
/// it takes the first's miss; the first answer, else one error of every
/// miss ([`Misses::error`]).
fn run<T>(routes: &[Strategy<T>], asked: &Asked) -> Result<T> {
    let mut misses = Misses::default();
    for (takes, words, route) in routes {
        if misses.0.first().is_some_and(|(_, e)| !takes.first(e)) {
            continue;
        }
        match route(asked) {
            Ok(answer) => return Ok(answer),
            Err(e) => misses.push(words, e),
        }
    }
    Err(misses.error(routes.iter().map(|r| r.0)))
}

/// The misses of the routes to an answer, in the order tried, each with
/// its route's words.
#[derive(Default)]
struct Misses(Vec<(&'static str, Error)>);

impl Misses {
    /// A miss, unless the same was said already (two routes from the same
    /// missing start).
    fn push(&mut self, words: &'static str, e: Error) {
        if !self.0.iter().any(|(_, said)| *said == e) {
            self.0.push((words, e));
        }
    }

    /// One error for every miss: the only one as it is; else the last fold
    /// in ρ or stop in ρ met on the way (the furthest the routes got)
    /// decides the kind (a table reads where the family stops from it) and
    /// is said first, the rest in order;
    /// else the kind the routes that took the first miss give
    /// ([`Takes::all_missed`]).
    fn error(self, mut routes: impl Iterator<Item = Takes>) -> Error {
        let mut misses = self.0;
        if misses.len() == 1 {
            return misses.remove(0).1;
        }
        let deciding =
            |e: &Error| matches!(e, Error::PastRhoFold { .. } | Error::StopsInRho { .. });
        let first = misses[0].1.clone();
        if let Some(k) = misses.iter().rposition(|(_, e)| deciding(e)) {
            let decides = misses.remove(k);
            misses.insert(0, decides);
        }
        let what = misses
            .iter()
            .map(|(words, e)| match *words {
                "" => e.detail(),
                words => format!("{words}: {}", e.detail()),
            })
            .collect::<Vec<_>>()
            .join("; ");
        match misses.remove(0).1 {
            Error::PastRhoFold { fold, from, .. } => Error::PastRhoFold { fold, from, what },
            Error::StopsInRho { reached, .. } => Error::StopsInRho { reached, what },
            _ => match routes.find(|t| t.first(&first)) {
                Some(takes) => takes.all_missed(&first, what),
                None => Error::NoState(what),
            },
        }
    }
}

/// The first route to a state: the seed's state at the control and its
/// family, the conformal ladder climbed ([`searched_on`]), keeping
/// the best state it resolves without converging.
fn seed_s_family(asked: &Asked) -> Result<ExactState> {
    let control = asked.control()?;
    crate::progress::stage(format!("the seed's state at {control} and its family"));
    let mut keep_best = |st: &ExactState| {
        let mut best = asked.best.borrow_mut();
        if best.as_ref().is_none_or(|b| st.bc_error < b.bc_error) {
            *best = Some(st.clone());
        }
    };
    searched_on(
        asked.gap,
        asked.rho,
        control,
        &Ladder::conformal(),
        &mut keep_best,
    )
}

/// The state at the control that the conformal form's escalation
/// resolves ([`RESOLVED`]) but does not converge (its best), solved again
/// by Newton at the control in the arclength representation from its
/// contour, the modes escalated ([`resolved`], [`Ladder::arclength`] from
/// as many modes); each finer state is accepted only within 1e-3 in ā of
/// the conformal one (the same state, not a neighbour).
fn again_in_arclength(asked: &Asked) -> Result<ExactState> {
    let control = asked.control()?;
    let near = asked.best.borrow().clone().ok_or_else(|| {
        Error::NoState("the conformal form's escalation resolves no state to start from".into())
    })?;
    let ladder = Ladder::arclength().from_modes(near.truncation.modes);
    let of = format!("the state of {} modes", near.truncation.modes);
    resolved(asked.gap, asked.rho, &ladder, |ex| {
        again_within_its_size(ex, control, &near, &of, near.route)
    })
}

/// Below the fold in ρ at `fold` (`met`, its error) of the family at
/// `control` continued from `start`: the state at the tenth under the fold
/// continued in ρ ([`below_the_fold`]), else on the arm of a larger
/// contact from `start`, which the fold does not bind
/// ([`from_larger_contact`]). Where both fail, the error of the furthest
/// fold met, with the routes before it ([`Misses::error`]).
fn past_the_fold(
    start: &ExactState,
    fold: f64,
    met: Error,
    rho: f64,
    control: Hold,
) -> Result<ExactState> {
    let mut misses = Misses::default();
    misses.push("", met);
    match below_the_fold(start.gap, fold, rho, control) {
        Ok(st) => return Ok(st),
        Err(Some(e)) => misses.push("", e),
        Err(None) => {}
    }
    from_larger_contact(start, rho, control).map_err(|e| {
        misses.push("", e);
        misses.error(std::iter::empty())
    })
}

/// Below a fold in ρ of the family at `control` (at `fold`): the state at
/// the tenth below the fold (ρ = 0.3 for the folds at 0.357 of zero force
/// and 0.322 of F̄ = 10), as [`at_resolved_on`] finds it there (on the arm
/// of a larger contact), continued in ρ at the control down to `rho` in
/// the arclength representation ([`continued_in_rho_along`]), rung by rung
/// ([`RUNGS`]): where that continuation turns back too, the state it
/// reached at the hundredth above its fold takes the arms of larger
/// contacts ([`from_larger_contact`]) to `rho` (F̄ = 10 at ρ = 0.2, from the
/// fold at 0.21875), else to the tenth below that fold, the next rung's
/// start. `Err(None)` where `rho` is not below the first tenth (the route
/// does not apply), else the last rung's error (its fold in ρ says where).
fn below_the_fold(
    gap: Gap,
    fold: f64,
    rho: f64,
    control: Hold,
) -> std::result::Result<ExactState, Option<Error>> {
    let tenth = |fold: f64| ((fold * 10.0).floor() / 10.0 * 1e6).round() / 1e6;
    if tenth(fold) <= rho + 1e-9 {
        return Err(None);
    }
    let ladder = Ladder::arclength();
    let mut stone = at_resolved_searching(gap, tenth(fold), control).map_err(Some)?;
    for rung in 1..=RUNGS {
        crate::progress::stage(format!(
            "below the fold in rho at {}: rung {rung} of {RUNGS}, from rho = {}",
            crate::error::rounded(fold),
            crate::error::short(stone.rho)
        ));
        let (fold, from, what) = match continued_in_rho_along(&stone, rho, control, &ladder) {
            Ok(st) => return Ok(st),
            Err(Error::PastRhoFold { fold, from, what }) => (fold, from, what),
            Err(e) => return Err(Some(e)),
        };
        let above = ((fold * 100.0).floor() + 1.0) / 100.0;
        let next = tenth(fold);
        let further = next > rho + 1e-9;
        let on_arm = continued_in_rho_along(&stone, above, control, &ladder).and_then(|above| {
            from_larger_contact(&above, rho, control).or_else(|none| {
                if further {
                    from_larger_contact(&above, next, control)
                } else {
                    Err(none)
                }
            })
        });
        match on_arm {
            Ok(st) if (st.rho - rho).abs() < 1e-12 => return Ok(st),
            Ok(st) => stone = st,
            Err(_) => {
                let what = format!(
                    "{what}; no arm of a larger contact from its state at rho = {} reaches rho = {}{}",
                    crate::error::short(above),
                    crate::error::short(rho),
                    if further {
                        format!(" or {}", crate::error::short(next))
                    } else {
                        String::new()
                    }
                );
                return Err(Some(Error::PastRhoFold { fold, from, what }));
            }
        }
    }
    Err(Some(Error::NoState(format!(
        "below the fold in rho at {control}, {RUNGS} rungs of continuation and larger contacts' arms end at rho = {} above rho = {}",
        crate::error::short(stone.rho),
        crate::error::short(rho)
    ))))
}

/// How many rungs [`below_the_fold`] descends: a continuation in ρ at the
/// control and, where it turns back, a larger contact's arm to the next
/// tenth (0.3 → 0.2 → 0.1 → 0.0 at most).
const RUNGS: usize = 4;

/// The last route to a state at the control: every near-elliptic state the
/// seed's screen finds at that value ([`bands::states_at_on`], the search
/// of `thinjkr exact solve --all`, ā from 1 to the larger of 4 and 1.2
/// times the circle's ā), where no route before it finds one. Of several,
/// the one nearest an ellipse among those where the seed's states cross
/// the control (else past a fold).
fn screened(asked: &Asked) -> Result<ExactState> {
    let (gap, rho, control) = (asked.gap, asked.rho, asked.control()?);
    crate::progress::stage("the seed's screen for every near-elliptic state");
    let a_circle = branch::circle_a_bar(&gap.at(1.0)?, control);
    let to = if a_circle.is_finite() {
        (1.2 * a_circle).max(4.0)
    } else {
        4.0
    };
    let all = bands::states_at_on(gap, rho, control, 1.0, to.min(10.9), &Ladder::conformal())?;
    all.states
        .into_iter()
        .min_by(|x, y| {
            let past = |s: &ExactState| s.route == Route::PastFold;
            (past(x), x.deviation_from_ellipse).partial_cmp(&(past(y), y.deviation_from_ellipse))
                .unwrap_or(std::cmp::Ordering::Equal)
        })
        .ok_or_else(|| {
            Error::NoState(format!(
                "the screen of {} for a from 1 to {} finds no near-elliptic state at {control} either",
                gap.seed.map_or("no seed".into(), |s| s.name()),
                crate::error::rounded(to.min(10.9))
            ))
        })
}

/// The exact state at `control` with the truncations `tries`: by every
/// route of `at_with`, and where these find nothing, on the arms beside
/// a band of the family traced past their folds; where there is none
/// there either, and the control lies in a band, the error says so
/// (`bands::past_folds_or_band`).
pub fn at_searched(rho: f64, control: Hold, tries: &[Truncation]) -> Result<ExactState> {
    searched_on(
        Gap::cylinders(),
        rho,
        control,
        &Ladder::of(tries.to_vec()),
        &mut |_| {},
    )
}

/// [`at_searched`] on `gap` climbing `ladder`, handing every state the
/// escalation resolves on the way to `visit` ([`at_with`]).
pub(crate) fn searched_on(
    gap: Gap,
    rho: f64,
    control: Hold,
    ladder: &Ladder,
    visit: &mut dyn FnMut(&ExactState),
) -> Result<ExactState> {
    by_delta_or_force(control)?;
    at_with(gap, rho, control, ladder, visit).or_else(|e| {
        let circle_a = branch::circle_a_bar(&gap.at(1.0)?, control);
        bands::past_folds_or_band(gap, rho, control, circle_a, ladder, e)
    })
}

/// The routes to an exact state are asked by δ̄ or F̄, finite: a given ā
/// is refused (an [`Error::Unavailable`]; the family is traced in
/// arclength, and [`Exact::solve`] is the state at a given ā from a guess).
fn by_delta_or_force(control: Hold) -> Result<Hold> {
    match control {
        Hold::Size(_) => Err(Error::Unavailable {
            model: "exact",
            what: "state at a given contact size".into(),
            why: "the exact family is traced in arclength; give delta or force",
        }),
        _ => control.check_finite(),
    }
}

/// The state at the control continued in ρ from the state at a larger ρ
/// ([`Asked::above`]; [`continued_in_rho`]), and where the conformal
/// form's series stops resolving the family, again in the arclength
/// representation; below a fold in ρ met on the way
/// ([`Error::PastRhoFold`]), by the routes past it ([`past_the_fold`]).
fn from_larger_rho(asked: &Asked) -> Result<ExactState> {
    let (rho, control, start) = (asked.rho, asked.control()?, asked.above()?);
    let continued = continued_in_rho(&start, rho, control).or_else(|conformal| match conformal {
        Error::PastRhoFold { .. } => Err(conformal),
        // where the conformal form's series no longer resolves the family:
        // again from the start, in the arclength representation
        _ => continued_in_rho_along(&start, rho, control, &Ladder::arclength()).map_err(
            |arclength| match arclength {
                Error::PastRhoFold { .. } => arclength,
                _ => Error::NoState(format!(
                    "{}; in the arclength representation: {}",
                    conformal.detail(),
                    arclength.detail()
                )),
            },
        ),
    });
    match continued {
        Err(met @ Error::PastRhoFold { fold, .. }) => {
            past_the_fold(&start, fold, met, rho, control)
        }
        other => other,
    }
}

/// The state at `control` at `rho` on the arm of a larger contact
/// ([`larger_contacts::from_larger_contacts`], from `start`, the state at
/// the control at a larger ρ), resolved by Newton at the control with the
/// arclength representation's modes escalated from the arm's
/// ([`resolved`]); each finer state is accepted only within 1e-3 in ā of
/// the arm's state (the same state, not a neighbour).
pub(crate) fn from_larger_contact(
    start: &ExactState,
    rho: f64,
    control: Hold,
) -> Result<ExactState> {
    let gap = start.gap;
    crate::progress::stage(format!(
        "the arms of contacts larger than a = {} from rho = {}",
        crate::error::rounded(start.a_bar),
        crate::error::short(start.rho)
    ));
    let arm = larger_contacts::from_larger_contacts(start, rho, control)?;
    let ladder = Ladder::notched_arm().from_modes(arm.truncation.modes);
    resolved(gap, rho, &ladder, |ex| {
        again_within_its_size(
            ex,
            control,
            &arm,
            "the arm's state",
            Route::FromLargerContact,
        )
    })
}

/// Newton at `control` with `ex`'s modes from the contour of `from` (named
/// `of` in the error), accepted only within 1e-3 in ā of it (the same
/// state, not a neighbour), with `route`.
fn again_within_its_size(
    ex: &Exact,
    control: Hold,
    from: &ExactState,
    of: &str,
    route: Route,
) -> Result<ExactState> {
    let mut st = ex.solve_at(control, &from.contour, from.delta_bar)?;
    if !Same::AGAIN.of(&st, from) {
        return Err(Error::NoState(format!(
            "with {} modes Newton at {control} from {of} lands at a = {:.4}, not at its a = {:.4}",
            ex.truncation.modes, st.a_bar, from.a_bar
        )));
    }
    st.route = route;
    Ok(st)
}

/// The first answer of `solve` at ρ + 0.1, ρ + 0.2, … (below 1, or up to
/// 1 on a gap no circle solves, whose state at ρ = 1 is no circle's): the
/// start of a continuation in ρ down to `rho` on `gap`.
fn first_above<T>(gap: Gap, rho: f64, solve: impl Fn(f64) -> Result<T>) -> Option<T> {
    let top = match gap.at(1.0) {
        Ok(circle) if !circle.is_radial() => 1.0 + 1e-9,
        _ => 1.0,
    };
    (1..)
        .map(|k| ((rho + 0.1 * k as f64) * 1e6).round() / 1e6)
        .take_while(|&above| above < top)
        .find_map(|above| {
            crate::progress::stage(format!(
                "a state at rho = {} to continue from",
                crate::error::short(above)
            ));
            solve(above).ok()
        })
}

/// The state at `control` at `rho`, continued in ρ at that control from
/// `start`, a converged state at a larger ρ: Newton with the control held
/// at each step from the state before (the steps
/// [`AT_A_CONTROL`](super::rho_walk::AT_A_CONTROL)), the contour modes escalated along
/// [`default_tries`] wherever a state's boundary error exceeds
/// [`CONVERGED`]. The answer only where it converges; else an error that
/// says down to which ρ the family was followed converged, and how it
/// stopped.
pub(crate) fn continued_in_rho(start: &ExactState, rho: f64, control: Hold) -> Result<ExactState> {
    continued_in_rho_along(start, rho, control, &Ladder::conformal())
}

/// [`continued_in_rho`] climbing `ladder` (from the first rung as fine as
/// `start`; a start of another representation is converted to the
/// ladder's).
pub(crate) fn continued_in_rho_along(
    start: &ExactState,
    rho: f64,
    control: Hold,
    ladder: &Ladder,
) -> Result<ExactState> {
    by_delta_or_force(control)?;
    let mut ladder = ladder.clone().starting_at(start.truncation.modes);
    let mut st = start.clone();
    let walked = walk_down(
        &mut st,
        rho,
        super::rho_walk::AT_A_CONTROL,
        |st| st.rho,
        |st, next| {
            let Some(t) = ladder.rung() else {
                return Err(Error::NoState(
                    "no truncation to continue in rho with".into(),
                ));
            };
            crate::progress::stage(format!(
                "continued in rho at {control} from rho = {}: at rho = {}, {} modes",
                crate::error::short(start.rho),
                crate::error::rounded(next),
                t.modes
            ));
            let ex = Exact::on(start.gap, next, t)?.deferring_stability();
            Ok(match ex.solve_at(control, &st.contour, st.delta_bar) {
                Ok(n) if n.bc_error <= CONVERGED => Attempt::Took(n),
                // (the climb in the guard: a rung up where there is one)
                Ok(n) if n.bc_error <= 1e-2 && ladder.escalate() => Attempt::Again,
                missed => Attempt::Missed(missed),
            })
        },
    )?;
    match walked {
        Ok(()) => {}
        Err(Stopped { next, why: Ok(n) }) => {
            let how = if n.bc_error <= 1e-2 {
                "the most tried"
            } else {
                "a contour Newton reaches but the series does not resolve"
            };
            return Err(converged_only_to(
                start,
                &st,
                control,
                &format!(
                    "at rho = {} the boundary error is {:.1e} with {} modes ({how}), and the contour is {:.1e} a off the ellipse",
                    crate::error::rounded(next),
                    n.bc_error,
                    n.truncation.modes,
                    n.deviation_from_ellipse
                ),
            ));
        }
        Err(Stopped { why: Err(e), .. }) => return past_newtons_end(&st, start, rho, control, &e),
    }
    st.stability = Exact::on(start.gap, rho, st.truncation)?.stability(&st)?;
    st.route = Route::ContinuedInRho;
    Ok(st)
}

/// Where Newton failed below `st` (the last converged state of
/// [`continued_in_rho_along`], continued from `start` towards `rho`) with
/// `e`: the path in (u, ρ), which steps around a fold in ā (a band's
/// edge), reaches `rho` (the answer) or shows a fold in ρ as ρ turning
/// back, located, an error that says so; else an error that says down to
/// which ρ the family converged.
fn past_newtons_end(
    st: &ExactState,
    start: &ExactState,
    rho: f64,
    control: Hold,
    e: &Error,
) -> Result<ExactState> {
    match super::rho_path::follow(st, rho, control) {
        Ok(Followed::Reached(found)) if found.bc_error <= CONVERGED => {
            let mut found = *found;
            found.stability = Exact::on(start.gap, rho, found.truncation)?.stability(&found)?;
            found.route = Route::ContinuedInRho;
            return Ok(found);
        }
        Ok(Followed::TurnedBack { fold, a_bar, .. }) if fold > rho => {
            return Err(Error::PastRhoFold {
                fold,
                from: start.rho,
                what: format!(
                    "the near-elliptic family at {control}, continued in rho from rho = {}, turns back at rho = {} (the path in shape and rho from its last state at rho = {} turns back there, at a_bar = {}, {} modes{}), so it has no state at rho = {}",
                    crate::error::short(start.rho),
                    crate::error::rounded(fold),
                    crate::error::rounded(st.rho),
                    crate::error::rounded(a_bar),
                    st.truncation.modes,
                    if st.truncation.arclength > 0 { " of each sign" } else { "" },
                    crate::error::short(rho)
                ),
            });
        }
        _ => {}
    }
    Err(converged_only_to(
        start,
        st,
        control,
        &format!(
            "Newton fails below it with steps in rho down to {:.0e} (the contour is {:.1e} a off the ellipse there; {})",
            super::rho_walk::AT_A_CONTROL.smallest,
            st.deviation_from_ellipse,
            e.to_string().chars().take(120).collect::<String>()
        ),
    ))
}

/// The family continued in ρ at `control` from `start` converged down to
/// `st` only, and `why`.
fn converged_only_to(start: &ExactState, st: &ExactState, control: Hold, why: &str) -> Error {
    Error::NoState(format!(
        "continued in rho at {control} from its state at rho = {} ({} modes), the family converges (boundary error below {:.0e}) down to rho = {} only: {why}",
        crate::error::short(start.rho),
        start.truncation.modes,
        CONVERGED,
        crate::error::rounded(st.rho)
    ))
}

/// The exact state at `control` climbing `ladder` ([`resolved`]), each
/// after the first started from the state the one before found (resolved
/// or not), handing every state a truncation resolves ([`RESOLVED`]) on
/// the way to `visit`, converged or not.
pub(crate) fn at_with(
    gap: Gap,
    rho: f64,
    control: Hold,
    ladder: &Ladder,
    visit: &mut dyn FnMut(&ExactState),
) -> Result<ExactState> {
    let coarser: std::cell::RefCell<Option<ExactState>> = std::cell::RefCell::new(None);
    let visit = std::cell::RefCell::new(visit);
    resolved(gap, rho, ladder, |ex| {
        let st = ex.find(control, coarser.borrow().as_ref())?;
        *coarser.borrow_mut() = Some(st.clone());
        let at = format!("{control} ({})", st.route);
        let st = ex.accept_resolved(at, st)?;
        (visit.borrow_mut())(&st);
        Ok(st)
    })
}

/// The load-controlled pull-off (the first minimum of F̄ on the arm that
/// carries `start`) followed in ρ from `start`, a converged pull-off at a
/// larger ρ, in the arclength representation ([`Truncation::in_arclength`]).
/// Each step in ρ ([`PULL_OFF_IN_ARCLENGTH`](super::rho_walk::PULL_OFF_IN_ARCLENGTH): 0.01 first, grown by 1.5 up to 0.02, halved where it
/// fails down to 0.00125): Newton at the previous pull-off's ā, else at
/// its δ̄ (both regular there, where fixed F̄ is singular); then the
/// minimum of F̄ over ā by the secant method on dF̄/dā
/// ([`Exact::force_minimum_in_size_from`]), or, where ā is no parameter there (a
/// fold in ā near, as at ρ ≈ 0.3), the arm traced from that state towards
/// the previous pull-off's ā to its first force minimum, the other way
/// only where that finds none ([`Exact::force_minimum_nearest`]). A step is taken when its pull-off's
/// boundary error is at most [`CONVERGED`]; else the modes are escalated
/// along [`Ladder::arclength`], then the step is halved. The last route
/// of [`pull_off_resolved`], where the conformal form's continuation stops
/// (near ρ = 0.3).
pub(crate) fn pull_off_followed_in_arclength(start: &ExactState, rho: f64) -> Result<ExactState> {
    pull_off_followed_in_arclength_visiting(start, rho, &mut |_| {})
}

/// [`pull_off_followed_in_arclength`], handing every pull-off it takes on
/// the way (resolved, without its stability) to `visit` (the pull-offs
/// stored as starts, [`super::stored`]). The escalation begins at the rung
/// of `start`'s modes when `start` is in the arclength representation.
pub(crate) fn pull_off_followed_in_arclength_visiting(
    start: &ExactState,
    rho: f64,
    visit: &mut dyn FnMut(&ExactState),
) -> Result<ExactState> {
    let mut at = start.clone();
    let mut ladder = match start.truncation.arclength {
        0 => Ladder::arclength(),
        _ => Ladder::arclength().starting_at(start.truncation.modes),
    };
    let steps = super::rho_walk::PULL_OFF_IN_ARCLENGTH;
    let walked = walk_down(
        &mut at,
        rho,
        steps,
        |at| at.rho,
        |at, next| {
            let Some(t) = ladder.rung() else {
                return Err(Error::NoState(
                    "no truncation to follow the pull-off with".into(),
                ));
            };
            crate::progress::stage(format!(
                "the pull-off followed in rho from rho = {}: at rho = {}, {} modes of each sign",
                crate::error::short(start.rho),
                crate::error::rounded(next),
                t.modes
            ));
            // where the previous pull-off has narrow grooves, its points
            // crowded into them, and the gauge that keeps them there
            let crowded = at.contour.crowded_at_groove(t.modes);
            let start_contour = crowded.as_ref().unwrap_or(&at.contour);
            let ex = Exact::on(start.gap, next, t)?
                .deferring_stability()
                .keeping_the_speed_of_grooved(start_contour);
            // Newton at the previous pull-off's ā, else at its δ̄ (the state
            // there is checked on the fine grid only where the trace needs it)
            let from = |hold: Hold| {
                ex.newton(hold, start_contour, at.delta_bar).and_then(|u0| {
                    ex.force_minimum_in_size_from(u0.clone()).or_else(|_| {
                        ex.state(&u0)
                            .and_then(|s0| ex.force_minimum_nearest(&s0, at.a_bar))
                    })
                })
            };
            Ok(
                match from(Hold::Size(at.a_bar)).or_else(|_| from(Hold::Delta(at.delta_bar))) {
                    Ok(po) if po.bc_error <= CONVERGED => {
                        visit(&po);
                        Attempt::Took(po)
                    }
                    // (the climb in the guard: a rung up where there is one)
                    Ok(_) if ladder.escalate() => Attempt::Again,
                    missed => Attempt::Missed((missed, t.modes)),
                },
            )
        },
    )?;
    if let Err(Stopped {
        next,
        why: (missed, modes),
    }) = walked
    {
        // how the step at `next` failed, after "only: at rho = …"
        let how = match missed {
            Ok(po) => format!(
                " the boundary error is {:.1e} with {modes} modes",
                po.bc_error
            ),
            Err(e) => format!(": {}", e.to_string().chars().take(160).collect::<String>()),
        };
        return Err(Error::StopsInRho {
            reached: at.rho,
            what: format!(
                "the pull-off followed in rho in the arclength representation converges down to rho = {} only: at rho = {}{how}",
                crate::error::rounded(at.rho),
                crate::error::rounded(next),
            ),
        });
    }
    let ex = Exact::on(start.gap, at.rho, at.truncation)?.keeping_the_speed_of_grooved(&at.contour);
    at.stability = ex.stability(&at)?;
    at.route = Route::ContinuedInRho;
    ex.accept_resolved_pull_off((at, Vec::new()))
        .map(|(st, _)| st)
}

/// Test support: `st` solved again at `control` from its own contour with
/// each of `modes` (of each sign) is resolved (boundary error at most
/// [`CONVERGED`]) and the same state: ā, s and δ̄ within 1e-9.
#[cfg(test)]
pub(crate) fn assert_same_with_modes(st: &ExactState, control: Hold, modes: &[usize]) {
    for &m in modes {
        let finer = Exact::on(st.gap, st.rho, Truncation::in_arclength(m))
            .unwrap()
            .deferring_stability()
            .solve_at(control, &st.contour, st.delta_bar)
            .unwrap();
        assert!(
            finer.bc_error <= CONVERGED,
            "{m} modes: {:.1e}",
            finer.bc_error
        );
        for (name, got, want) in [
            ("a", finer.a_bar, st.a_bar),
            ("s", finer.s, st.s),
            ("delta", finer.delta_bar, st.delta_bar),
        ] {
            assert!(
                (got - want).abs() < 1e-9,
                "{m} modes: {name} {got} against {want}"
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The routes run in the table's order, each after the first only
    /// where it takes the first's miss (issue 69's route table), and where
    /// every one misses the error is typed by the furthest fold in ρ met,
    /// said first, with every other miss once, in order; no solver runs.
    #[test]
    fn the_route_table_runs_its_routes_in_order_and_types_their_misses() {
        let asked = Asked::new(Gap::cylinders(), 0.5, Some(Hold::Force(0.0)));
        let no = |w: &str| Error::NoState(w.into());
        let fold = |f: f64, w: &str| Error::PastRhoFold {
            fold: f,
            from: 0.4,
            what: w.into(),
        };
        // found nothing: not the arclength route; the fold decides
        let routes: [Strategy<u32>; 4] = [
            (Takes::First, "", |_| Err(Error::NoState("a".into()))),
            (Takes::NearlyResolved, "again", |_| Ok(1)),
            (Takes::NothingFound, "", |_| {
                Err(Error::PastRhoFold {
                    fold: 0.3,
                    from: 0.4,
                    what: "c".into(),
                })
            }),
            (Takes::NothingFound, "", |_| Err(Error::NoState("d".into()))),
        ];
        assert_eq!(run(&routes, &asked), Err(fold(0.3, "c; a; d")));
        // came near: only the arclength route, and not resolved with its words
        let routes: [Strategy<u32>; 3] = [
            (Takes::First, "", |_| {
                Err(Error::Unresolved {
                    what: "a".into(),
                    residual: 1e-8,
                })
            }),
            (Takes::NearlyResolved, "again", |_| {
                Err(Error::NoState("b".into()))
            }),
            (Takes::NothingFound, "", |_| Ok(2)),
        ];
        let unresolved = Error::Unresolved {
            what: "a; again: b".into(),
            residual: 1e-8,
        };
        assert_eq!(run(&routes, &asked), Err(unresolved));
        // a miss no route takes is the answer as it is; a route's answer ends the run
        let routes: [Strategy<u32>; 2] = [
            (Takes::First, "", |_| Err(Error::InBand("in a band".into()))),
            (Takes::NothingFound, "", |_| Ok(3)),
        ];
        assert_eq!(run(&routes, &asked), Err(Error::InBand("in a band".into())));
        let routes: [Strategy<u32>; 3] = [
            (Takes::First, "", |_| Err(Error::NoState("a".into()))),
            (Takes::NothingFound, "", |_| Ok(4)),
            (Takes::NothingFound, "", |_| Ok(5)),
        ];
        assert_eq!(run(&routes, &asked), Ok(4));
        // the same miss twice is said once; of two folds, the last met decides
        let mut misses = Misses::default();
        misses.push("", fold(0.36, "first fold"));
        misses.push("", no("x"));
        misses.push("", fold(0.17, "further fold"));
        misses.push("", no("x"));
        assert_eq!(
            misses.error(std::iter::empty()),
            fold(0.17, "further fold; first fold; x")
        );
    }

    /// Which states lie above the pull-off on its own piece of the family
    /// (docs/exact.md, "Above the pull-off on its own piece"): at ρ = 0.2,
    /// traced from the pull-off (64 modes of each sign) towards larger ā,
    /// F̄ rises to a fold in ā near ā = 2.6015, where F̄ ≈ −1.2, and past it
    /// ā shrinks while F̄ keeps rising, still below zero. Every traced state
    /// resolved below 1e-9 has F̄ below −1.1; 128 modes (Newton at the same
    /// ā, from the 64-mode contour) resolve the last traced state past the
    /// fold (ā ≈ 2.39, 8e-7 with 64 modes) to 1e-9 with F̄ unchanged to
    /// 1e-5 (measured: F̄ = −0.70742, boundary error 1.1e-11), still
    /// tensile.
    #[test]
    fn above_the_pull_off_at_rho_0_2_its_piece_folds_before_zero_force() {
        let rho = 0.2;
        let (po, _) = pull_off_resolved(rho).unwrap();
        assert_eq!(po.truncation.modes, 64, "{:?}", po.truncation);
        let ex = Exact::on(po.gap, rho, po.truncation)
            .unwrap()
            .deferring_stability()
            .keeping_the_speed_of_grooved(&po.contour);
        let br = ex.trace_from(&po, 1.0, 2.4, 3.0, 0.05, 60).unwrap();
        let folds: Vec<f64> = br
            .events
            .iter()
            .filter_map(|e| match e {
                branch::Event::SizeFold { a_bar } => Some(*a_bar),
                _ => None,
            })
            .collect();
        assert_eq!(folds.len(), 1, "{folds:?}");
        assert!((folds[0] - 2.6015).abs() < 5e-4, "{folds:?}");
        let widest = br
            .points
            .iter()
            .max_by(|p, q| p.state.a_bar.total_cmp(&q.state.a_bar))
            .unwrap();
        assert!(
            (widest.state.force_bar + 1.2).abs() < 0.03,
            "F at the fold {}",
            widest.state.force_bar
        );
        let resolved: Vec<&ExactState> = br
            .points
            .iter()
            .map(|p| &p.state)
            .filter(|st| st.bc_error <= 1e-9)
            .collect();
        assert!(resolved.len() > 10);
        for st in &resolved {
            assert!(
                st.force_bar < -1.1,
                "a = {}, F = {}",
                st.a_bar,
                st.force_bar
            );
        }
        // past the fold: the last traced state, ā below 2.45, solved again
        // with 128 modes at its ā
        let past = &br.points.last().unwrap().state;
        assert!(past.a_bar < 2.45 && past.force_bar > widest.state.force_bar);
        let fine = Exact::on(po.gap, rho, Truncation::in_arclength(128))
            .unwrap()
            .deferring_stability();
        let st = fine
            .solve_at(
                Hold::Size(past.a_bar),
                &past.contour.in_arclength(128),
                past.delta_bar,
            )
            .unwrap();
        assert!(st.bc_error <= 1e-9, "{:e}", st.bc_error);
        assert!(
            (st.force_bar - past.force_bar).abs() < 1e-5 && st.force_bar < 0.0,
            "F = {} with 128 modes, {} with 64",
            st.force_bar,
            past.force_bar
        );
        eprintln!(
            "rho = 0.2 above the pull-off: fold at a = {:.5} (F = {:.4}); past it a = {:.4}, F = {:.5} (128 modes, bc {:.1e})",
            folds[0], widest.state.force_bar, st.a_bar, st.force_bar, st.bc_error
        );
    }

    /// The continuation in ρ at a fixed control (the route for ρ where no
    /// start finds the state directly): from the state at F̄ = 10 and ρ = 0.4,
    /// continued to ρ = 0.38, it is the state found there directly from
    /// `conformal:8` (another start, another truncation): ā and s agree to
    /// 1e-9, and both are converged below 1e-9.
    #[test]
    fn continuing_in_rho_at_a_force_gives_the_state_found_there_directly() {
        let control = Hold::Force(10.0);
        let start = at_resolved(0.4, control).unwrap();
        let continued = continued_in_rho(&start, 0.38, control).unwrap();
        let direct = at_resolved(0.38, control).unwrap();
        assert_eq!(continued.route, Route::ContinuedInRho);
        assert_eq!(direct.route, Route::FromModel);
        assert!(continued.bc_error <= 1e-9 && direct.bc_error <= 1e-9);
        assert!(
            (continued.a_bar - direct.a_bar).abs() < 1e-9 && (continued.s - direct.s).abs() < 1e-9,
            "continued a = {}, s = {}; direct a = {}, s = {}",
            continued.a_bar,
            continued.s,
            direct.a_bar,
            direct.s
        );
    }

    /// Where the conformal form's escalation comes near but not to 1e-9
    /// (at F̄ = 10 and ρ = 0.33 its last rung, 96 modes, leaves 1.6e-8, and
    /// the answer had been an error, the loading path at θ = 60° without a
    /// start), the state is solved again in the arclength representation.
    /// A second route: the state at ρ = 0.34 (conformal, converged)
    /// continued to 0.33 in the arclength representation. ā, s and δ̄
    /// agree to 1e-9 (measured: 1.2e-14 and less).
    #[test]
    fn a_state_the_conformal_escalation_leaves_near_is_resolved_in_arclength() {
        let control = Hold::Force(10.0);
        let direct = at_resolved(0.33, control).unwrap();
        assert!(direct.truncation.arclength > 0, "{:?}", direct.truncation);
        assert!(direct.bc_error <= CONVERGED, "{:e}", direct.bc_error);
        let above = at_resolved(0.34, control).unwrap();
        assert_eq!(above.truncation.arclength, 0, "{:?}", above.truncation);
        is_the_state_above_continued_in_arclength(&direct, &above, control);
    }

    /// `direct` (at its ρ and `control`) is `above` (the state at
    /// `control` at a larger ρ) continued to that ρ in the arclength
    /// representation, converged: ā, s and δ̄ to 1e-9.
    fn is_the_state_above_continued_in_arclength(
        direct: &ExactState,
        above: &ExactState,
        control: Hold,
    ) {
        let continued =
            continued_in_rho_along(above, direct.rho, control, &Ladder::arclength()).unwrap();
        assert!(continued.bc_error <= CONVERGED, "{:e}", continued.bc_error);
        for (what, d, c) in [
            ("a", direct.a_bar, continued.a_bar),
            ("s", direct.s, continued.s),
            ("delta", direct.delta_bar, continued.delta_bar),
        ] {
            assert!((d - c).abs() < 1e-9, "{what}: directly {d}, continued {c}");
        }
    }

    /// The route past a band's folds re-solves each crossing with the rungs
    /// of the escalation from the trace's on; where the trace took the last
    /// (96 modes), that one rung had been answered as a user's choice of
    /// modes, resolved only: zero force at ρ = 0.36 came with a boundary
    /// error of 3.0e-7. Now the arclength representation's rungs follow, and
    /// the answer is converged. A second route: the state at ρ = 0.37 (found
    /// directly) continued to 0.36 in the arclength representation. ā, s and
    /// δ̄ agree to 1e-9 (measured: 3.1e-14 and less; 15 s in release).
    #[test]
    fn a_state_past_a_bands_fold_is_converged_in_the_arclength_representation() {
        let control = Hold::Force(0.0);
        let direct = at_resolved(0.36, control).unwrap();
        assert_eq!(direct.route, Route::PastFold);
        assert!(direct.bc_error <= CONVERGED, "{:e}", direct.bc_error);
        let above = at_resolved(0.37, control).unwrap();
        is_the_state_above_continued_in_arclength(&direct, &above, control);
    }

    /// The pull-off followed in ρ (the route below the ρ that the starts from
    /// `conformal:8` and from the circle reach): from the pull-off at ρ = 0.4,
    /// followed to ρ = 0.38 in the arclength representation, it is the
    /// pull-off found there directly (another start, the conformal form):
    /// F̄ agrees to 1e-11, s to 1e-9 and ā (where F̄ is stationary) to
    /// 1e-8, both converged below 1e-9.
    #[test]
    fn following_the_pull_off_in_rho_gives_the_pull_off_found_there_directly() {
        let (start, _) = pull_off_resolved(0.4).unwrap();
        let followed = pull_off_followed_in_arclength(&start, 0.38).unwrap();
        let (direct, _) = pull_off_resolved(0.38).unwrap();
        assert_eq!(followed.route, Route::ContinuedInRho);
        assert_ne!(direct.route, Route::ContinuedInRho);
        assert!(followed.bc_error <= 1e-9 && direct.bc_error <= 1e-9);
        let (df, ds, da) = (
            (followed.force_bar - direct.force_bar).abs(),
            (followed.s - direct.s).abs(),
            (followed.a_bar - direct.a_bar).abs(),
        );
        eprintln!("pull-off at rho = 0.38, followed against direct: F {df:e}, s {ds:e}, a {da:e}");
        assert!(
            df < 1e-11 && ds < 1e-9 && da < 1e-8,
            "F {df:e}, s {ds:e}, a {da:e}"
        );
    }

    /// The arclength representation against the conformal-map form at
    /// states both resolve (ρ = 0.8 at zero force, the pull-offs at 0.5 and
    /// 0.35): the same contact at the same ā, solved with 48 modes of each
    /// sign from the conformal contour re-parametrised, agrees in s, δ̄ and
    /// F̄ to 1e-9, with a boundary error below 1e-9 of its own, and finds
    /// the same unstable modes under both controls among those both series
    /// hold (n ≤ 40 and n ≤ twice the conformal state's modes).
    #[test]
    fn the_arclength_representation_reproduces_the_conformal_states() {
        let states = [
            at_resolved(0.8, Hold::Force(0.0)).unwrap(),
            pull_off_resolved(0.5).unwrap().0,
            pull_off_resolved(0.35).unwrap().0,
        ];
        for st in states {
            assert_eq!(st.truncation.arclength, 0);
            let ex = Exact::new(st.rho, Truncation::in_arclength(48)).unwrap();
            let guess = st.contour.in_arclength(48);
            let a = ex.solve(st.a_bar, &guess, st.delta_bar).unwrap();
            assert_eq!(a.contour.c.len(), 47);
            assert!(a.bc_error < 1e-9, "rho {}: bc {:e}", st.rho, a.bc_error);
            for (what, x, y) in [
                ("s", a.s, st.s),
                ("delta_bar", a.delta_bar, st.delta_bar),
                ("force_bar", a.force_bar, st.force_bar),
            ] {
                assert!(
                    (x - y).abs() <= 1e-9 * y.abs().max(1.0),
                    "rho {}: {what} {x} vs {y}",
                    st.rho
                );
            }
            // the modes both series hold: n ≤ 2N of the conformal state's N
            let top = (2 * st.truncation.modes).min(40);
            let low = |m: &[super::super::stability::UnstableMode]| -> Vec<usize> {
                m.iter().map(|u| u.n).filter(|&n| n <= top).collect()
            };
            assert_eq!(
                low(&a.stability.load),
                low(&st.stability.load),
                "rho {}",
                st.rho
            );
            assert_eq!(
                low(&a.stability.displacement),
                low(&st.stability.displacement),
                "rho {}",
                st.rho
            );
        }
    }

    /// The pull-off followed in ρ in the arclength representation from the
    /// resolved pull-off at ρ = 0.35 reaches the conformal-map form's
    /// resolved pull-off at ρ = 0.3 (80 modes there, 48 here): F̄ to 1e-9
    /// relative, ā and s to 1e-6 (F̄ is flat at its minimum, which locates
    /// ā only to about the square root of F̄'s accuracy).
    #[test]
    fn the_pull_off_followed_in_arclength_reaches_the_resolved_one_at_rho_0_3() {
        let start = pull_off_resolved(0.35).unwrap().0;
        let followed = pull_off_followed_in_arclength(&start, 0.3).unwrap();
        let conformal = pull_off_resolved(0.3).unwrap().0;
        assert!(followed.truncation.arclength > 0 && followed.bc_error <= RESOLVED);
        assert!(
            (followed.force_bar / conformal.force_bar - 1.0).abs() <= 1e-9,
            "{} vs {}",
            followed.force_bar,
            conformal.force_bar
        );
        assert!((followed.a_bar - conformal.a_bar).abs() <= 1e-6);
        assert!((followed.s - conformal.s).abs() <= 1e-6);
    }

    /// The second rung below the folds: F̄ = 10 at ρ = 0.3 (a larger
    /// contact's arm) continued in ρ turns back at 0.21875, and from its
    /// state at ρ = 0.22 the arm of a larger contact carries F̄ = 10 to
    /// ρ = 0.2 (route `FromLargerContact`, [`below_the_fold`]). Solved again
    /// with 320 and 384 modes of each sign, ā, s and δ̄ stay within 1e-9 and
    /// the boundary error at most 1e-9 (docs/exact.md, "Below ρ = 0.3", has
    /// the table from 128 modes). Ignored in CI: about 3 minutes, most of
    /// it the routes tried before this one.
    #[test]
    #[ignore = "slow tier (.ci/slow)"]
    fn below_the_folds_force_10_at_rho_0_2_is_on_a_larger_contacts_arm_from_0_22() {
        let ten = Hold::Force(10.0);
        let st = at_resolved(0.2, ten).unwrap();
        assert_eq!(st.route, Route::FromLargerContact);
        assert!((st.force_bar - 10.0).abs() < 1e-9 && st.bc_error <= CONVERGED);
        assert_same_with_modes(&st, ten, &[320, 384]);
    }

    /// The two ways to the force minimum of one step of the follow in ρ
    /// give the same pull-off: from the pull-off at ρ = 0.3, solved at
    /// ρ = 0.25 at its ā (48 modes of each sign), the secant method on
    /// dF̄/dā ([`Exact::force_minimum_in_size_from`]) and the arm traced to its
    /// first force minimum ([`Exact::force_minimum_nearest`]) agree to
    /// 1e-11 relative in F̄ and 1e-8 in ā (measured: 1.2e-14 and 6.3e-14),
    /// and the secant's is a minimum: F̄ is larger at ā ± 0.01.
    #[test]
    fn the_secant_minimum_is_the_traced_one() {
        let start = pull_off_resolved(0.3).unwrap().0;
        let ex = Exact::on(start.gap, 0.25, Truncation::in_arclength(48))
            .unwrap()
            .deferring_stability();
        let s0 = ex
            .solve_at(Hold::Size(start.a_bar), &start.contour, start.delta_bar)
            .unwrap();
        let secant = ex.force_minimum_in_size_from(ex.unknowns(&s0)).unwrap();
        let traced = ex.force_minimum_nearest(&s0, start.a_bar).unwrap();
        assert!(
            (secant.force_bar / traced.force_bar - 1.0).abs() <= 1e-11,
            "{} vs {}",
            secant.force_bar,
            traced.force_bar
        );
        assert!(
            (secant.a_bar - traced.a_bar).abs() <= 1e-8,
            "{} vs {}",
            secant.a_bar,
            traced.a_bar
        );
        for da in [-0.01, 0.01] {
            let beside = ex.solve_from(secant.a_bar + da, &secant).unwrap();
            assert!(
                beside.force_bar > secant.force_bar,
                "{da}: {}",
                beside.force_bar
            );
        }
    }
}

#[cfg(test)]
mod convergence {
    use super::*;

    /// The convergence table of docs/exact.md for the pull-offs below
    /// ρ = 0.3 (not run by default: about 2 min on the release build):
    /// each pull-off as `pull_off_resolved` finds it, solved again at its ā
    /// with N = 32 … 320 modes of each sign in its own parametrisation (its
    /// points crowded into narrow grooves where the follow crowded them);
    /// the boundary error on the fine grid and F̄'s change from the finest.
    /// `cargo test --release -p thinjkr --lib convergence_table -- --ignored
    /// --nocapture`. It holds what the docs say of the table: it is below
    /// 1e-9 at the N the pull-off was found with; every row falls from rung
    /// to rung until it reaches 2e-10 (a few times the round-off floor,
    /// 2e-11 to 8e-11 with 192 modes and more), at equal arclength each
    /// rung to at most half the one before; crowded, it falls from above
    /// 1e-4 at 32 modes by more than 1e5 at the N used.
    #[test]
    #[ignore = "slow tier (.ci/slow)"]
    fn convergence_table_of_the_small_rho_pull_offs() {
        let ns = [32, 48, 64, 96, 128, 160, 192, 224, 256, 288, 320];
        println!("| ρ | N = {} |", ns.map(|n| n.to_string()).join(" | "));
        let reached = crate::exact::stored::stored().unwrap().reached;
        for rho in [0.2, 0.1, 0.0718, 0.05, 0.03, 0.02, reached] {
            let po = pull_off_resolved(rho).unwrap().0;
            let rows: Vec<(f64, f64)> = ns
                .iter()
                .map(|&n| {
                    // in the pull-off's own parametrisation (crowded into
                    // narrow grooves where the follow crowded it), its
                    // series truncated or padded to n
                    Exact::on(po.gap, rho, Truncation::in_arclength(n))
                        .and_then(|ex| {
                            ex.deferring_stability()
                                .keeping_the_speed_of_grooved(&po.contour)
                                .solve(po.a_bar, &po.contour, po.delta_bar)
                        })
                        .map_or((f64::NAN, f64::NAN), |st| (st.bc_error, st.force_bar))
                })
                .collect();
            let finest = rows.last().unwrap().1;
            let cells: Vec<String> = rows
                .iter()
                .map(|(bc, f)| format!("{bc:.1e} / {:.0e}", (f - finest).abs()))
                .collect();
            println!(
                "| {} (N = {}) | {} |",
                crate::error::rounded(rho),
                po.truncation.modes,
                cells.join(" | ")
            );
            let own = ns.iter().position(|&n| n == po.truncation.modes).unwrap();
            assert!(rows[own].0 <= 1e-9, "rho {rho}: {}", cells.join(" | "));
            assert!(rows.iter().all(|r| r.0.is_finite()), "rho {rho}");
            let crowded = po.contour.narrow_groove().is_some();
            for w in rows.windows(2).filter(|w| w[0].0 > 2e-10) {
                let fall = if crowded { 1.0 } else { 0.5 };
                assert!(w[1].0 < fall * w[0].0, "rho {rho}: {}", cells.join(" | "));
            }
            if crowded {
                assert!(rows[0].0 > 1e-4 && rows[own].0 < 1e-5 * rows[0].0);
            }
        }
    }
}
