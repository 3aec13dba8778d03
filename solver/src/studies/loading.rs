//! The loading path (issue 32 (b)): the states a contact takes when its
//! load is lowered quasi-statically from a large load, F̄ = 10 (else the
//! start `studies::start` finds), to where it comes off, under load control, with the jump rule of
//! `studies::descent` wherever the state it holds is lost.
//!
//! At each step in F̄ the contour descends the potential at the new force
//! from the state at the last one (`descent::descend`): on a stable arm
//! that is Newton's method with the arm's state as the guess, so a step
//! longer than the bracket is probed by Newton's method alone; where the
//! arm folds in F̄ (a load-controlled fold) or a resolved contour mode
//! turns unstable, the descent carries the contact to another state, or it
//! comes off. A landing of Newton's method must continue the arm: lie
//! near the arm's tangent line (`continues`), else it may be a hop onto
//! the piece beyond a band, and the step is halved (below the bracket
//! too) until the path follows the arm's turn. A step whose landing is
//! not near its start (or whose state the descent leaves) is halved until
//! the state is lost within 1e-3 (relative to max(1, |F̄|)); where it is
//! lost is then the minimum of F̄ over ā on its arm, by the secant method
//! on dF̄/dā (`Exact::force_minimum_in_size_from`), where there is one that
//! near (a fold in F̄), else the last state held. From there the contour
//! descends at a force 1e-4 lower: it lands on another state (a jump, an
//! event with the force, the state before and the state after) or comes
//! off (the path's pull-off: the last state held).
//!
//! Which modes count as resolved (and so move, or are held) is the
//! short-wave cutoff's choice; the path depends on it, and every path says
//! which cutoff it used. Where a state held owes a visible part of its
//! shape to undulations shorter than the cutoff (`exact::undulations`),
//! its shape is (2)'s, not a coating's of that thickness: the arm has
//! turned into the lobes of a band whose mode the cutoff leaves
//! unresolved, and a coating that holds those lobes flat passes the band
//! ([`pass_band`]: the path goes on from the piece beyond, an event of
//! the path, [`BandPass`]); where no piece beyond is found, the path is
//! not settled from there.
//!
//! Owns: [`LoadingPath`], [`Jump`], [`BandPass`], [`PathEnd`],
//! [`loading_path`], [`loading_path_to_first_band`], [`reported`], the shape
//! without its short waves (`without_short_waves`). May use: its parent `studies` (`descent`, `start`), `exact`
//! (the problem, `resolve`, `undulations`, the large load),
//! `control`, `continuation` (the family's linearisation, for the arm's
//! tangent), `cutoff`, `error`, `newton` (the stop request), `report`
//! (the outcome's shape).

use super::descent::{descend, Landing};
use crate::control::Hold;
use crate::cutoff::Cutoff;
use crate::error::Result;
use crate::exact::ladder::Ladder;
use crate::exact::same::Same;
use crate::exact::{undulations, Contour, Exact, ExactState, Truncation, CONVERGED, RESOLVED};

#[cfg(test)]
use crate::exact::START_FORCE;

/// The force steps are halved down to this (relative to max(1, |F̄|)):
/// where a step this short still loses the state held, it is lost within
/// it.
const BRACKET: f64 = 1e-3;

/// How far below the force where a state is lost the descent from it is
/// taken (relative to max(1, |F̄|)): far enough to leave the fold's
/// bottleneck in a few dozen steps, near enough for the landing to be the
/// fold's.
const PUSH: f64 = 1e-4;

/// The largest step in F̄.
const MAX_STEP: f64 = 1.0;

/// The steps in ā (relative to the ā of the state whose shape turned
/// unresolved) at which [`pass_band`] looks for the piece beyond a band,
/// how many it takes at most (down to 10 % of ā below), and how often the
/// step that first finds it is halved to locate where it begins.
const PASS_STEP: f64 = 2e-3;
const PASS_STEPS: usize = 50;
const PASS_BISECTIONS: usize = 6;

/// Where the arm turns within a step ([`continues`]), the step is halved
/// down to this (relative to max(1, |F̄|)) before the descent is asked
/// where the contact goes: a turn sharper than this is a corner.
const TURN_FLOOR: f64 = 1e-7;

/// A jump of the path: at `force` the state held at the step before is
/// lost and the contact descends to `to`.
#[derive(Clone, Debug)]
pub(crate) struct Jump {
    /// The force at which the state before is lost.
    pub force: f64,
    /// The last state held before the jump.
    pub from: ExactState,
    /// Where the descent lands.
    pub to: ExactState,
}

/// A band passed: the state held turns into the lobes of a mode shorter
/// than the cutoff (its undulations pass 1 % of ā, `undulations::VISIBLE`),
/// and the contact, whose coating holds those undulations flat, goes on
/// from the piece beyond the band ([`pass_band`]).
#[derive(Clone, Debug)]
pub(crate) struct BandPass {
    /// The band's mode: the largest of the undulations shorter than the
    /// cutoff.
    pub mode: usize,
    /// The state of (2) on that arm whose undulations pass 1 % of ā.
    pub at: ExactState,
    /// The first state beyond, at a lower F̄, whose shape the cutoff
    /// resolves.
    pub to: ExactState,
}

/// How a path ends.
#[derive(Clone, Debug)]
pub(crate) enum PathEnd {
    /// The contact comes off: `state` is the last one held (the path's
    /// pull-off), `located` says how its force was located.
    PullOff { state: Box<ExactState> },
    /// The state held is lost at `state` (located as for a pull-off), and
    /// where the contact goes from there is not settled (`why`, in words):
    /// the force of the path's pull-off is then at most this state's.
    Lost { state: Box<ExactState>, why: String },
    /// The path stops before a state is lost (in words).
    NotSettled(String),
    /// The path was asked to stop at its first band passed
    /// ([`loading_path_to_first_band`]): its last state is where it goes
    /// on beyond the band, on the piece below.
    PassedBand,
}

/// The path from F̄ = 10 down.
#[derive(Clone, Debug)]
pub(crate) struct LoadingPath {
    /// The states held on the way, at decreasing F̄ (the start first).
    pub states: Vec<ExactState>,
    /// The jumps on the way, in order.
    pub jumps: Vec<Jump>,
    /// The bands of modes shorter than the cutoff passed on the way, in
    /// order.
    pub passes: Vec<BandPass>,
    /// Where it ends.
    pub end: PathEnd,
}

/// Whether `b` continues the arm of `a` (a small step in F̄ moves a state
/// on an arm by little; a jump moves it by a finite amount): every point of
/// one contour within 2 % of ā of the other (either representation). The
/// distance is to the other contour's polygon through [`NEAR_POINTS`]
/// points, not to its points alone: the two may be in different
/// parametrisations (the conformal map's crowds its points where the
/// contour is curved, the arclength representation spreads them evenly),
/// so a point of one can fall midway between two of the other, half a
/// spacing (about 0.08 at ā = 3.4) away from both.
fn near(a: &ExactState, b: &ExactState) -> bool {
    contours_near(&a.contour, &b.contour, 0.02 * a.a_bar.max(1.0))
}

/// Whether the landing `st` of a step from `held` continues `held`'s arm:
/// it lies within [`TURN`] of the step's motion from the arm's tangent
/// line, `held` moved by ΔF̄·du/dF̄ (du/dF̄ from the Jacobian of the
/// equations at fixed F̄ there), every point of the two contours compared
/// at the same parameter. On the arm the distance is of the order of the
/// step times the arm's turning, and a step that turns more is halved; a
/// step that crosses a band lands on the piece beyond it, off the tangent
/// by the band's width however short the step. The [`near`] test alone
/// lets such a hop pass where the band is narrow: at ρ = 0.5 a unit step
/// from ā = 3.5705 (F̄ = 17.74, past the fold of the piece 3.5633 – 3.7287)
/// lands at ā = 3.5236 on the piece below, 1.3 % away, and of the mode-22
/// band below ā = 4.2293 (F̄ 82.6) a step lands on the piece below the
/// band 0.1 % away, and the path then runs down that piece through four
/// bands more. Step doubling (two half steps reaching the landing again)
/// does not tell them apart either: both half steps hop there.
fn continues(ex: &Exact, held: &ExactState, st: &ExactState) -> bool {
    use crate::continuation::Family;
    let u = ex.unknowns_of(&held.contour, held.delta_bar);
    let n = u.len();
    let Some(lin) = ex.linearise(&u) else {
        return false;
    };
    let mut j = lin.j;
    j.row_mut(n - 1).copy_from(&lin.force_grad.transpose());
    let mut e = nalgebra::DVector::zeros(n);
    e[n - 1] = 1.0;
    let Some(du) = j.lu().solve(&e) else {
        return false;
    };
    let along = ex.contour_of(&(u + du * (st.force_bar - held.force_bar)));
    let (from, to, landed) = (
        contour_points(&held.contour),
        contour_points(&along),
        contour_points(&st.contour),
    );
    let largest = |x: &[nalgebra::Complex<f64>], y: &[nalgebra::Complex<f64>]| {
        x.iter()
            .zip(y)
            .map(|(p, q)| (p - q).norm())
            .fold(0.0, f64::max)
    };
    let (motion, off) = (largest(&from, &to), largest(&landed, &to));
    off.is_finite() && off <= TURN * motion + SAME_LANDING * st.a_bar.max(1.0)
}

/// How far a landing may lie from the arm's tangent line, relative to the
/// step's motion along it ([`continues`]).
const TURN: f64 = 0.25;

/// Distances below this (relative to max(1, ā)) are Newton's tolerance,
/// not a turn of the arm ([`continues`]).
const SAME_LANDING: f64 = 1e-7;

/// Whether every point of each contour lies within `tolerance` of the
/// other ([`near`]).
fn contours_near(a: &crate::exact::Contour, b: &crate::exact::Contour, tolerance: f64) -> bool {
    let (pa, pb) = (contour_points(a), contour_points(b));
    within_polygon(&pa, &pb, tolerance) && within_polygon(&pb, &pa, tolerance)
}

/// [`NEAR_POINTS`] points of a contour at equal steps of its parameter.
fn contour_points(c: &crate::exact::Contour) -> Vec<nalgebra::Complex<f64>> {
    (0..NEAR_POINTS)
        .map(|i| c.point_at(2.0 * std::f64::consts::PI * i as f64 / NEAR_POINTS as f64))
        .collect()
}

/// How many points of each contour [`near`] compares.
const NEAR_POINTS: usize = 256;

/// Whether every point of `from` lies within `tolerance` of the closed
/// polygon through `to`.
fn within_polygon(
    from: &[nalgebra::Complex<f64>],
    to: &[nalgebra::Complex<f64>],
    tolerance: f64,
) -> bool {
    let segment =
        |p: nalgebra::Complex<f64>, q: nalgebra::Complex<f64>, r: nalgebra::Complex<f64>| {
            let d = r - q;
            let t = (((p - q).conj() * d).re / d.norm_sqr().max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
            (p - (q + d * t)).norm()
        };
    from.iter()
        .all(|&p| (0..to.len()).any(|j| segment(p, to[j], to[(j + 1) % to.len()]) <= tolerance))
}

/// The modes of `st` unstable under load that `cutoff` resolves.
fn unstable_resolved(
    st: &ExactState,
    cutoff: Cutoff,
) -> Vec<crate::exact::stability::UnstableMode> {
    st.stability
        .clone()
        .under(cutoff)
        .load
        .into_iter()
        .filter(|m| m.resolved)
        .collect()
}

/// Whether `next` is unstable under load to a resolved mode that `held` is
/// not unstable to.
fn newly_unstable(held: &ExactState, next: &ExactState, cutoff: Cutoff) -> bool {
    let before = unstable_resolved(held, cutoff);
    unstable_resolved(next, cutoff)
        .iter()
        .any(|m| before.iter().all(|b| b.n != m.n))
}

/// Whether `b` is the state `a` itself ([`Same::ITSELF`]): a descent
/// that stays where it started.
fn same_state(a: &ExactState, b: &ExactState) -> bool {
    Same::ITSELF.of(b, a)
}

/// The loading path from `start` (the state at F̄ = [`crate::exact::START_FORCE`], else
/// the largest stable load on the pull-off's piece: `studies::start`), down, with `cutoff` choosing the resolved modes.
pub(crate) fn loading_path(start: &ExactState, cutoff: Cutoff) -> Result<LoadingPath> {
    Ok(follow(
        Exact::of_state(start)?,
        start.clone(),
        cutoff,
        false,
    ))
}

/// [`loading_path`] up to the first band it passes: where it has passed
/// one, it ends ([`PathEnd::PassedBand`]) at the state beyond, on the
/// piece below, from which the path goes on as that piece's (the windows'
/// rows, `studies::reach`, each the path on its own piece).
pub(crate) fn loading_path_to_first_band(
    start: &ExactState,
    cutoff: Cutoff,
) -> Result<LoadingPath> {
    Ok(follow(Exact::of_state(start)?, start.clone(), cutoff, true))
}

/// `st` (a state of `ex`) or, where `ex`'s modes do not resolve it to
/// [`CONVERGED`] (its fine-grid boundary error), the same state solved
/// again at the force with more modes of the escalation (the conformal-map
/// form's, then the arclength representation's), up to the first that
/// does; accepted when its boundary error is at most [`RESOLVED`], the
/// finer problem then replacing `ex`.
fn resolved(ex: &mut Exact, st: ExactState) -> std::result::Result<ExactState, String> {
    if st.bc_error <= CONVERGED {
        return Ok(st);
    }
    // the best state so far, and the finer problem it is on (none: `ex`)
    let mut best: (Option<Exact>, ExactState) = (None, st);
    // the conformal-map form's rungs above the state's, then the
    // arclength representation's (above the state's if it is in it)
    let rungs = Ladder::conformal()
        .then(Ladder::arclength())
        .above(ex.truncation());
    for &rung in rungs.rungs() {
        let st = &best.1;
        let Ok(finer) = of_state_with(st, rung) else {
            continue;
        };
        if let Ok(again) = finer.solve_at(Hold::Force(st.force_bar), &st.contour, st.delta_bar) {
            if again.bc_error < st.bc_error && near(st, &again) {
                let done = again.bc_error <= CONVERGED;
                best = (Some(finer), again);
                if done {
                    break;
                }
            }
        }
    }
    let (finer, st) = best;
    let on = finer.as_ref().unwrap_or(ex).truncation();
    if st.bc_error <= RESOLVED {
        if let Some(f) = finer {
            *ex = f;
        }
        return Ok(st);
    }
    Err(format!(
        "at force = {} the state (a = {:.4}) is not resolved by {} modes{} (boundary error {:.1e})",
        crate::error::rounded(st.force_bar),
        st.a_bar,
        on.modes,
        if on.arclength > 0 {
            " of each sign in the arclength representation"
        } else {
            ""
        },
        st.bc_error
    ))
}

/// Where the state `held` is lost, given that a step of at most
/// [`BRACKET`] loses it (to `force`, where the descent gave `landing`):
/// the minimum of F̄ over ā on its arm where there is one in the bracket
/// (the secant method, else the traced arm), from which the descent is
/// taken again just below (where that descent does not settle, the
/// landing from `held` stands); else `held` and that landing.
fn where_lost(
    ex: &Exact,
    held: &ExactState,
    force: f64,
    landing: Landing,
    cutoff: Cutoff,
) -> (ExactState, Landing) {
    let in_bracket =
        |m: &ExactState| near(held, m) && m.force_bar <= held.force_bar && m.force_bar >= force;
    let fold = ex
        .force_minimum_in_size_from(ex.unknowns(held))
        .ok()
        .filter(in_bracket)
        .or_else(|| {
            ex.force_minimum_nearest(held, held.a_bar - 0.05)
                .ok()
                .filter(in_bracket)
        });
    match fold {
        Some(m) => {
            let below = m.force_bar - PUSH * m.force_bar.abs().max(1.0);
            match descend(ex, &m, below, cutoff) {
                // the fold's bottleneck can outlast the descent's steps
                // (at ρ = 1, 600 steps from the circle's pull-off); the
                // landing from the state held, within the bracket of the
                // fold, then says where the contact goes
                Landing::NotSettled(_) if !matches!(landing, Landing::NotSettled(_)) => {
                    (m, landing)
                }
                from_fold => (m, from_fold),
            }
        }
        None => (held.clone(), landing),
    }
}

/// The path from `start` (a state of `ex`'s truncation) down; with
/// `to_first_band`, up to the first band it passes.
fn follow(ex: Exact, start: ExactState, cutoff: Cutoff, to_first_band: bool) -> LoadingPath {
    let mut walk = Walk {
        ex,
        states: vec![start.clone()],
        jumps: Vec::new(),
        passes: Vec::new(),
        held: start,
        step: 0.25,
        before: None,
        judged: false,
        cutoff,
        to_first_band,
    };
    loop {
        if let Some(end) = walk.advance() {
            return LoadingPath {
                states: walk.states,
                jumps: walk.jumps,
                passes: walk.passes,
                end,
            };
        }
    }
}

/// The loading path as it is followed: the states, jumps and band passes
/// so far, the state held, the step in F̄ and what the last step left.
struct Walk {
    ex: Exact,
    states: Vec<ExactState>,
    jumps: Vec<Jump>,
    passes: Vec<BandPass>,
    held: ExactState,
    step: f64,
    /// The state held before the last step, that step and the truncation
    /// it was held in, while the step was longer than the bracket: where
    /// the descent leaves the state the step reached, the path steps back
    /// and halves the step, so that where a state is lost is bracketed to
    /// [`BRACKET`] whichever test finds it.
    before: Option<(ExactState, f64, Truncation)>,
    /// Whether the state held has passed the descent's test already (a
    /// state stepped back to, or one a halved step comes back to): kept
    /// until the state held changes.
    judged: bool,
    cutoff: Cutoff,
    to_first_band: bool,
}

/// What a part of a step of the walk decided.
enum Flow {
    /// Go on with the step.
    On,
    /// The step is done: take the next.
    Next,
    /// The path ends.
    End(PathEnd),
}

impl Walk {
    /// One step of the path; its end where it ends.
    fn advance(&mut self) -> Option<PathEnd> {
        if let Err(e) = crate::newton::check_stop() {
            return Some(PathEnd::NotSettled(e.to_string()));
        }
        match self.past_short_waves() {
            Flow::On => {}
            Flow::Next => return None,
            Flow::End(end) => return Some(end),
        }
        let scale = self.held.force_bar.abs().max(1.0);
        let shape_loss = self.shape_loss();
        self.judged = shape_loss.is_none();
        if shape_loss.is_some() {
            if let Some((back, taken, truncation)) = self.before.take() {
                if truncation != self.ex.truncation() {
                    match of_state_with(&back, truncation) {
                        Ok(e) => self.ex = e,
                        Err(e) => return Some(PathEnd::NotSettled(e.to_string())),
                    }
                }
                self.states.pop();
                self.held = back;
                self.step = 0.5 * taken;
                self.judged = true;
                return None;
            }
        }
        let (lost, landing, shape) = match shape_loss {
            Some((landing, words)) => (self.held.clone(), landing, words),
            None => match self.step_down(scale) {
                Ok(Some((lost, landing))) => (lost, landing, String::new()),
                Ok(None) => return None,
                Err(end) => return Some(end),
            },
        };
        self.after_loss(lost, landing, &shape, scale)
    }

    /// Where the state held owes a visible part of its shape to
    /// undulations shorter than the cutoff, (2) does not resolve where the
    /// contact goes from there, whatever the verdicts of its directions: a
    /// coating this thick holds those undulations flat, and the contact
    /// passes the band onto the piece beyond it (not from the start, whose
    /// shape no state before resolved); else the path ends there.
    fn past_short_waves(&mut self) -> Flow {
        let (held, cutoff) = (&self.held, self.cutoff);
        let short = crate::exact::undulations::short_waves(&held.contour, cutoff);
        if short.unresolved && self.states.len() > 1 {
            if let Some(to) = pass_band(&mut self.ex, held, cutoff) {
                self.states.pop();
                self.passes.push(BandPass {
                    mode: short.mode.unwrap_or(0),
                    at: held.clone(),
                    to: to.clone(),
                });
                self.held = to;
                self.states.push(self.held.clone());
                if self.to_first_band {
                    return Flow::End(PathEnd::PassedBand);
                }
                self.before = None;
                self.judged = false;
                self.step = 0.25;
                return Flow::Next;
            }
            // (a search stopped by the user found nothing because it
            // was stopped, not because nothing is there)
            if let Err(e) = crate::newton::check_stop() {
                return Flow::End(PathEnd::NotSettled(e.to_string()));
            }
        }
        if !short.unresolved {
            return Flow::On;
        }
        // (the start is never passed from: no search was made there)
        let searched = if self.states.len() > 1 {
            format!(
                "; no state of a resolved shape was found beyond the band within {} % of a below",
                (PASS_STEP * PASS_STEPS as f64 * 100.0).round()
            )
        } else {
            String::new()
        };
        Flow::End(PathEnd::NotSettled(format!(
            "at force = {} (a = {:.4}, s = {:.4}) {}{searched}",
            crate::error::rounded(held.force_bar),
            held.a_bar,
            held.s,
            short.words(cutoff)
        )))
    }

    /// A state unstable under load to a resolved mode is lost where it
    /// is: the descent leaves it along that mode (`descend` kicks a
    /// saddle); the landing and the words that say so. (The verdict counts
    /// every mode free; the descent holds the shorter ones at equilibrium:
    /// where it stays on the state, the state is a minimum of what moves,
    /// and the path goes on.)
    fn shape_loss(&self) -> Option<(Landing, String)> {
        let (held, cutoff) = (&self.held, self.cutoff);
        let unstable = if self.judged {
            None
        } else {
            unstable_resolved(held, cutoff).into_iter().next()
        };
        unstable.and_then(|m| {
            let landing = descend(&self.ex, held, held.force_bar, cutoff);
            let stays = matches!(&landing, Landing::Landed(st) if same_state(held, st));
            let words = format!(
                "the state at force = {} is unstable under load to the resolved mode n = {} (wavelength {:.3}); from there: ",
                crate::error::rounded(held.force_bar),
                m.n,
                m.wavelength
            );
            (!stays).then_some((landing, words))
        })
    }

    /// A step down in F̄ from the state held: taken where it continues the
    /// arm (`Ok(None)`: the next step), else the state held is lost below
    /// it, and where, with the descent's landing.
    ///
    /// A step longer than the bracket is probed by Newton's method at the
    /// new force from the state held: on an arm stable under load the
    /// descent is that Newton's method, and near a fold in F̄ (a minimum) no
    /// state lies close below it, so Newton's method fails or lands far and
    /// the step is halved. The descent, which may run hundreds of steps
    /// before it shows that it goes far, is taken once the step is at the
    /// bracket, the only place its landing is used. A state Newton's method
    /// reaches with a resolved mode unstable under load that the state held
    /// is not unstable to fails the probe too: where that mode turns
    /// unstable is then bracketed as a fold is, and the descent judges the
    /// state at the bracket.
    fn step_down(
        &mut self,
        scale: f64,
    ) -> std::result::Result<Option<(ExactState, Landing)>, PathEnd> {
        let (cutoff, step) = (self.cutoff, self.step);
        let force = self.held.force_bar - step;
        let probed = if step > TURN_FLOOR * scale {
            match self
                .ex
                .solve_at(Hold::Force(force), &self.held.contour, self.held.delta_bar)
            {
                Ok(st) if !newly_unstable(&self.held, &st, cutoff) && near(&self.held, &st) => {
                    Some(st)
                }
                _ => None,
            }
        } else {
            None
        };
        match probed {
            Some(st) if continues(&self.ex, &self.held, &st) => {
                let back = (self.held.clone(), step, self.ex.truncation());
                self.held = resolved(&mut self.ex, st).map_err(PathEnd::NotSettled)?;
                self.judged = false;
                self.before = (step > BRACKET * scale).then_some(back);
                self.states.push(self.held.clone());
                self.step = (step * 1.5).min(MAX_STEP);
                return Ok(None);
            }
            // the arm turns within the step (or the landing lies on
            // another piece): a shorter step, below the bracket too
            Some(_) => {
                self.step *= 0.5;
                return Ok(None);
            }
            None if step > BRACKET * scale => {
                self.step *= 0.5;
                return Ok(None);
            }
            None => {}
        }
        let landing = descend(&self.ex, &self.held, force, cutoff);
        if let Landing::Landed(st) = &landing {
            if near(&self.held, st) {
                self.held = resolved(&mut self.ex, (**st).clone()).map_err(PathEnd::NotSettled)?;
                self.judged = false;
                self.before = None;
                self.states.push(self.held.clone());
                self.step = (step * 1.5).min(MAX_STEP);
                return Ok(None);
            }
        }
        // the state held is lost within BRACKET below its force
        Ok(Some(where_lost(
            &self.ex, &self.held, force, landing, cutoff,
        )))
    }

    /// Where the contact goes from the state `lost` (`shape`: the words of
    /// a loss of shape, empty for a loss of the arm): a jump to the
    /// landing, which the path goes on from, or the path's end.
    fn after_loss(
        &mut self,
        lost: ExactState,
        landing: Landing,
        shape: &str,
        scale: f64,
    ) -> Option<PathEnd> {
        // (from a state unstable to a resolved mode the landing may lie
        // close by: the contact changes shape a little, still a jump from
        // one arm to another at the same force)
        let moved =
            |st: &ExactState| !near(&lost, st) || (!shape.is_empty() && !same_state(&lost, st));
        match landing {
            Landing::Landed(st) if moved(&st) => {
                self.jumps.push(Jump {
                    force: lost.force_bar,
                    from: lost,
                    to: (*st).clone(),
                });
                self.before = None;
                self.held = match resolved(&mut self.ex, *st) {
                    Ok(st) => st,
                    Err(why) => return Some(PathEnd::NotSettled(why)),
                };
                self.judged = false;
                self.states.push(self.held.clone());
                self.step = 0.25;
            }
            Landing::Landed(_) => {
                return Some(PathEnd::NotSettled(format!(
                    "{shape}at force = {} the state is lost for a step of {:.0e} but the descent from it lands beside it",
                    crate::error::rounded(lost.force_bar),
                    BRACKET * scale,
                )))
            }
            Landing::Detached => {
                return Some(PathEnd::PullOff {
                    state: Box::new(lost),
                })
            }
            Landing::NotSettled(why) => {
                return Some(PathEnd::Lost {
                    state: Box::new(lost),
                    why: format!("{shape}{why}"),
                })
            }
        }
        (self.jumps.len() > 50).then(|| PathEnd::NotSettled("more than 50 jumps".into()))
    }
}

/// Where the state `held` owes a visible part of its shape to undulations
/// shorter than the cutoff (the lobes of a band whose mode (2) does not
/// resolve at this thinness), the state the contact goes on from: a
/// coating that holds those undulations flat does not follow (2)'s arm
/// into the lobes but passes the band. The piece beyond is sought at sizes
/// below `held`'s in steps of [`PASS_STEP`] of its ā, at most
/// [`PASS_STEPS`], by Newton's method at each fixed ā from `held`'s
/// contour with those undulations taken off
/// ([`without_short_waves`]), scaled to that ā. (At a fixed
/// force Newton's method from that guess is drawn to the lobed arm beyond
/// the next piece's fold where the band is wide, at ρ = 0.5 with
/// h/L = 0.3; at a fixed size the lobes are what the guess lacks.) A state
/// reached whose force is below `held`'s, whose shape the cutoff resolves
/// and whose boundary error is resolved is on the piece beyond; the step
/// that first reaches one is halved [`PASS_BISECTIONS`] times (the larger
/// ā where the test holds kept) to locate where that piece's resolved
/// states begin, and the path goes on from the state there. None where no
/// step reaches one.
fn pass_band(ex: &mut Exact, held: &ExactState, cutoff: Cutoff) -> Option<ExactState> {
    let mut guess = held.clone();
    guess.contour = without_short_waves(&held.contour, cutoff);
    // the search's problem, without the states' stability (the state
    // chosen gets it from `ex`)
    let search = of_state_with(held, ex.truncation())
        .ok()?
        .deferring_stability();
    // a resolved state beyond at size `a_bar`, by Newton's method
    let beyond = |ex: &mut Exact, a_bar: f64| -> Option<ExactState> {
        let st = search.solve_from(a_bar, &guess).ok()?;
        if st.force_bar >= held.force_bar
            || crate::exact::undulations::short_waves(&st.contour, cutoff).unresolved
        {
            return None;
        }
        let st = ex
            .solve_at(Hold::Size(st.a_bar), &st.contour, st.delta_bar)
            .ok()?;
        // (a finer truncation that resolves it replaces `ex`, as on the
        // path)
        let st = resolved(ex, st).ok()?;
        (!crate::exact::undulations::short_waves(&st.contour, cutoff).unresolved).then_some(st)
    };
    let step = PASS_STEP * held.a_bar;
    let mut above = held.a_bar;
    for k in 1..=PASS_STEPS {
        crate::newton::check_stop().ok()?;
        let a_bar = held.a_bar - k as f64 * step;
        if let Some(mut found) = beyond(ex, a_bar) {
            // where between the last size that found none and this one the
            // piece beyond is first reached, by bisection
            let mut below = a_bar;
            for _ in 0..PASS_BISECTIONS {
                crate::newton::check_stop().ok()?;
                let mid = 0.5 * (above + below);
                match beyond(ex, mid) {
                    Some(st) => {
                        found = st;
                        below = mid;
                    }
                    None => above = mid,
                }
            }
            return Some(found);
        }
        above = a_bar;
    }
    None
}

/// The loading path at `pull_off.rho` judged against `pull_off` (the
/// pull-off the trace reports): an entry of its `passed` list. `start` is
/// where it begins ([`super::start::start`]: the state at F̄ = 10 there,
/// else the largest stable load on the pull-off's piece), or why there
/// is none.
pub(crate) fn reported(
    pull_off: &ExactState,
    cutoff: Cutoff,
    start: &Result<super::start::Start>,
) -> crate::report::Passed {
    let path = start
        .as_ref()
        .map_err(Clone::clone)
        .and_then(|s| loading_path(&s.state, cutoff));
    let passed = path
        .as_ref()
        .map(|p| p.unresolved_turned_unstable(cutoff))
        .unwrap_or_default();
    let bands: Vec<(usize, f64, f64, f64)> = path
        .as_ref()
        .map(|p| {
            p.passes
                .iter()
                .map(|b| (b.mode, b.at.force_bar, b.to.force_bar, b.to.a_bar))
                .collect()
        })
        .unwrap_or_default();
    let (held, jumps, lost, comes_off, why): (usize, Vec<(f64, f64)>, _, _, _) = match &path {
        Err(e) => (0, Vec::new(), None, None, Some(e.detail())),
        Ok(p) => {
            let (comes_off, why) = match &p.end {
                PathEnd::PullOff { .. } => (Some(true), None),
                PathEnd::Lost { why, .. } => (Some(false), Some(why.clone())),
                PathEnd::NotSettled(why) => (None, Some(why.clone())),
                PathEnd::PassedBand => (None, Some("stopped at the first band passed".into())),
            };
            (
                p.states.len(),
                p.jumps.iter().map(|j| (j.force, j.to.a_bar)).collect(),
                p.first_lost(),
                comes_off,
                why,
            )
        }
    };
    let (from_force, start_at) = super::start::reported_from(start);
    crate::report::Passed::LoadingPath {
        from_force,
        start_at,
        cutoff_thinness: cutoff.thinness,
        states_held: held,
        jump_forces: jumps.iter().map(|j| j.0).collect(),
        jump_landing_a_bar: jumps.iter().map(|j| j.1).collect(),
        bands_passed: bands.iter().map(|b| b.0).collect(),
        bands_passed_unresolved_at: bands.iter().map(|b| b.1).collect(),
        bands_passed_to_force: bands.iter().map(|b| b.2).collect(),
        bands_passed_to_a_bar: bands.iter().map(|b| b.3).collect(),
        unresolved_turned_unstable: passed.iter().map(|p| p.1).collect(),
        unresolved_turned_unstable_at: passed.iter().map(|p| p.0).collect(),
        first_lost_force: lost.map(|s| s.force_bar),
        first_lost_a_bar: lost.map(|s| s.a_bar),
        reaches: lost.map(|s| Same::THE_PULL_OFF.of(s, pull_off)),
        comes_off,
        why_not_settled: why,
    }
}

impl LoadingPath {
    /// The path's pull-off state, or why there is none.
    #[cfg(test)]
    pub(crate) fn pull_off(&self) -> Result<&ExactState> {
        match &self.end {
            PathEnd::PullOff { state, .. } => Ok(state),
            PathEnd::Lost { state, why, .. } => Err(crate::error::Error::NoState(format!(
                "the loading path from force = {START_FORCE} loses its state at force = {}, a = {}, and where the contact goes from there is not settled: {why}",
                crate::error::rounded(state.force_bar),
                crate::error::rounded(state.a_bar)
            ))),
            PathEnd::NotSettled(why) => Err(crate::error::Error::NoState(format!(
                "the loading path from force = {START_FORCE} is not settled: {why}"
            ))),
            PathEnd::PassedBand => Err(crate::error::Error::NoState(
                "the loading path was followed to its first band only".into(),
            )),
        }
    }

    /// The first state the path loses (at a fold in F̄ or a resolved mode
    /// turning unstable): the first jump's start, else the end's state.
    pub(crate) fn first_lost(&self) -> Option<&ExactState> {
        self.jumps.first().map(|j| &j.from).or(match &self.end {
            PathEnd::PullOff { state, .. } | PathEnd::Lost { state, .. } => Some(&**state),
            PathEnd::NotSettled(_) | PathEnd::PassedBand => None,
        })
    }

    /// The contour modes shorter than `cutoff` to which the path's states
    /// turn unstable under load on the way and stay so to its last state
    /// (the start not unstable to them, and showing modes that short), each
    /// with the force of the first state from which it stays unstable, in
    /// that order. The path does not count them ((2) does not resolve
    /// them). Below ρ = 1, on a near-elliptic piece such a turn is the
    /// passage of that mode's band, stepped over where the band is
    /// narrower than [`continues`] resolves (at ρ = 0.9 the bands of n = 8
    /// and 6); past a fold in ā it is the fold's mode.
    pub(crate) fn unresolved_turned_unstable(&self, cutoff: Cutoff) -> Vec<(f64, usize)> {
        let unresolved = |st: &ExactState| -> Vec<usize> {
            st.stability
                .clone()
                .under(cutoff)
                .load
                .into_iter()
                .filter(|m| !m.resolved && m.n > 0)
                .map(|m| m.n)
                .collect()
        };
        let (Some(first), Some(last)) = (self.states.first(), self.states.last()) else {
            return Vec::new();
        };
        let at_start = unresolved(first);
        // a band passed on purpose is reported as passed, not as stepped
        // over
        let passed = |n: usize| self.passes.iter().any(|b| b.mode == n);
        // modes the start could show: a truncation grown on the way
        // represents shorter modes, unstable already (the shortest
        // unstable mode at the start bounds them)
        let shown = at_start
            .iter()
            .max()
            .copied()
            .unwrap_or(2 * first.truncation.modes);
        let sets: Vec<Vec<usize>> = self.states.iter().map(unresolved).collect();
        let mut turned: Vec<(f64, usize)> = unresolved(last)
            .into_iter()
            .filter(|n| !at_start.contains(n) && *n <= shown)
            .map(|n| {
                // the first state of the last run of states unstable to n
                let from = sets
                    .iter()
                    .rposition(|set| !set.contains(&n))
                    .map_or(0, |k| k + 1);
                (self.states[from].force_bar, n)
            })
            .filter(|&(_, n)| !passed(n))
            .collect();
        turned.sort_by(|x, y| y.0.total_cmp(&x.0));
        turned
    }
}

/// `contour` with the undulations shorter than `cutoff`'s wavelength taken
/// off: its coefficients of those modes (b_j and c_j of the mode 2j + 2,
/// its lobes' number) set to those of its ellipse (the ellipse through its
/// extremes, in the same representation), its longer modes kept: the shape
/// of a coating that holds those undulations flat, to the mixing of modes
/// between the coefficients and the radial departure that `undulations::short_waves`
/// measures (a tenth or less of the short part is left).
fn without_short_waves(contour: &Contour, cutoff: Cutoff) -> Contour {
    let h = 2.0 * std::f64::consts::PI / undulations::POINTS as f64;
    let z: Vec<nalgebra::Complex<f64>> = (0..undulations::POINTS)
        .map(|k| contour.point_at(h * k as f64))
        .collect();
    let perimeter: f64 = (0..undulations::POINTS)
        .map(|k| (z[(k + 1) % undulations::POINTS] - z[k]).norm())
        .sum();
    let modes = contour.b.len();
    // (beyond the modes held, none is short: capped before the cast, so a
    // cutoff far below the contour's scale cannot overflow it)
    let first_short = (perimeter / cutoff.wavelength)
        .floor()
        .min(2.0 * modes as f64 + 2.0) as usize
        + 1;
    let ellipse = Contour::ellipse(contour.a_bar(), contour.b_bar(), modes);
    let ellipse = if contour.c.is_empty() {
        ellipse
    } else {
        ellipse.in_arclength(modes)
    };
    let mut out = contour.clone();
    for j in (0..modes).filter(|j| 2 * j + 2 >= first_short) {
        out.b[j] = ellipse.b.get(j).copied().unwrap_or(0.0);
        if let Some(c) = out.c.get_mut(j) {
            *c = ellipse.c.get(j).copied().unwrap_or(0.0);
        }
    }
    out
}

/// [`Exact::of_state`] with another truncation (a finer or coarser rung
/// for the same state).
fn of_state_with(st: &ExactState, truncation: Truncation) -> Result<Exact> {
    Ok(Exact::on(st.gap, st.rho, truncation)?.keeping_the_speed_of_grooved(&st.contour))
}

/// The integration tests' reader of docs/exact-record.md's table rows.
#[cfg(test)]
#[path = "../../tests/docs_tables/mod.rs"]
mod docs_tables;

#[cfg(test)]
mod tests {
    use super::super::start::at_large_load as start;
    use super::docs_tables;
    use super::*;

    /// An ellipse (ā = 3, b̄ = 2.4) undulated by cos 4θ and cos 10θ in the
    /// arclength representation: with the cutoff of h/L = 0.5 (3.14; the
    /// perimeter about 17, so the modes from n = 6 on are short) taking the
    /// short undulations off leaves less than a tenth of them, where the
    /// undulated contour had more than 1 % of ā, and keeps the longer
    /// coefficients; in the conformal-map form the same holds.
    #[test]
    fn taking_the_short_waves_off_keeps_the_long_ones() {
        let cutoff = Cutoff::for_thinness(0.5).unwrap();
        for arclength in [true, false] {
            let ellipse = Contour::ellipse(3.0, 2.4, 24);
            let mut c = if arclength {
                ellipse.in_arclength(24)
            } else {
                ellipse
            };
            c.b[1] += 0.02;
            c.b[4] += 0.06;
            let before = crate::exact::undulations::short_waves(&c, cutoff);
            assert!(before.unresolved, "{before:?}");
            assert_eq!(before.mode, Some(10));
            let smooth = without_short_waves(&c, cutoff);
            let after = crate::exact::undulations::short_waves(&smooth, cutoff);
            // (the radial departure of the long modes' coefficients has a
            // little of the short modes too: 0.09 % of ā here, 0.13 % in
            // the conformal-map form's θ)
            assert!(
                !after.unresolved && after.amplitude < 0.1 * before.amplitude,
                "{arclength}: {} {}",
                before.amplitude,
                after.amplitude
            );
            assert_eq!(smooth.b[..2], c.b[..2]);
            assert_eq!(smooth.a, c.a);
        }
    }

    /// A contour in the conformal-map form and the same contour in the
    /// arclength representation are near (their points lie at different
    /// places along the contour); moved by 3 % of ā it is not. The
    /// contour is the ρ = 0.5 ellipse's size at F̄ = 7.6 undulated by
    /// cos 8θ, the loading path's shape there; before the distance was
    /// taken to the polygon, the two representations of one contour were
    /// judged apart and every escalation into arclength was refused.
    #[test]
    fn a_contour_is_near_itself_in_either_representation() {
        let mut c = crate::exact::Contour::ellipse(3.4, 2.45, 96);
        c.b[3] += 0.02;
        let a = c.in_arclength(96);
        let tolerance = 0.02 * 3.4;
        assert!(contours_near(&c, &a, tolerance));
        assert!(contours_near(&a, &c, tolerance));
        let mut moved = a.clone();
        moved.a += 0.03 * 3.4;
        assert!(!contours_near(&c, &moved, tolerance));
    }

    /// Every state of `held` is resolved, its shape resolved, and not
    /// unstable under load above `cutoff`.
    fn held_resolved_and_not_unstable(held: &[ExactState], cutoff: Cutoff) {
        for st in held {
            let judged = st.clone().judged(cutoff);
            assert!(st.bc_error <= RESOLVED, "{}", st.bc_error);
            assert!(!judged.shape.unwrap().unresolved, "F = {}", st.force_bar);
            assert_ne!(
                judged.stability.stable_load,
                Some(false),
                "F = {}",
                st.force_bar
            );
        }
    }

    /// The first state `path` loses is `pull_off` (F̄ to 1e-6, ā to 1e-3).
    fn reaches(path: &LoadingPath, pull_off: &ExactState) {
        let lost = path.first_lost().expect("a state lost");
        assert!(
            (lost.force_bar - pull_off.force_bar).abs() < 1e-6 * pull_off.force_bar.abs(),
            "{} {}",
            lost.force_bar,
            pull_off.force_bar
        );
        assert!((lost.a_bar - pull_off.a_bar).abs() < 1e-3 * pull_off.a_bar);
    }

    /// At ρ = 1 the path from F̄ = 10 is the circle all the way (the circle
    /// is stable under load to every mode longer than the cutoff at h/L =
    /// 0.5), and it comes off at the closed form's pull-off, ā³ = 12,
    /// F̄ = −3π/2, with no jump.
    #[test]
    fn at_rho_1_the_path_is_the_circle_down_to_the_closed_form_pull_off() {
        let path = loading_path(&start(1.0).unwrap(), Cutoff::for_thinness(0.5).unwrap()).unwrap();
        assert!(path.jumps.is_empty(), "{:?}", path.jumps.len());
        let p = path.pull_off().unwrap();
        assert!(
            (p.force_bar + 1.5 * std::f64::consts::PI).abs() < 1e-9,
            "{}",
            p.force_bar
        );
        assert!((p.a_bar - 12f64.cbrt()).abs() < 1e-5, "{}", p.a_bar);
        for st in &path.states {
            assert!(
                st.s > 1.0 - 1e-9 && st.bc_error < 1e-9,
                "{} {}",
                st.s,
                st.bc_error
            );
        }
    }

    /// At ρ = 0.8 the arm from F̄ = 10 turns back in ā at the lower fold
    /// of the mode-6 band: a fine arclength trace of the family (steps of
    /// 5e-4 in u) locates the fold at ā = 2.758686 with the null direction
    /// of mode 6, F̄ falling on through it. The loading path follows the
    /// arm through that fold (its smallest ā before the band is the
    /// fold's), and where the band's six lobes, shorter than the cutoff at
    /// h/L = 0.5 and 1, pass 1 % of ā (F̄ ≈ −2.35) it passes the band: it
    /// goes on from the piece below the band (ā about 0.05 smaller), and
    /// at h/L = 0.5 holds that piece down to the pull-off `exact pull-off`
    /// reports (F̄ = −4.1976, ā = 2.396), found there by another route (the
    /// arm traced from `conformal:8`'s pull-off). At h/L = 1 the four-lobed
    /// undulations of that piece (3.55 long, cutoff 6.28) pass 1 % of ā
    /// just above it, and no resolved state lies below: not settled.
    /// Every state held is resolved and stable under load above the
    /// cutoff, its shape resolved.
    #[test]
    fn at_rho_0_8_the_path_passes_the_mode_6_band_to_the_pull_off() {
        let s0 = start(0.8).unwrap();
        let ex = Exact::new(0.8, s0.truncation)
            .unwrap()
            .deferring_stability();
        let near_band = ex
            .solve_at(Hold::Size(2.8), &s0.contour, s0.delta_bar)
            .unwrap();
        let (fold, mode) = ex
            .to_size_fold(&near_band, -1.0, 2.7, 5e-4)
            .unwrap()
            .expect("the arm turns back in a above 2.7");
        assert_eq!(mode, Some(6));
        assert!((fold.a_bar - 2.758686).abs() < 1e-5, "{}", fold.a_bar);
        let (pull_off, _) = crate::exact::pull_off_resolved(0.8).unwrap();
        for h in [0.5, 1.0] {
            let cutoff = Cutoff::for_thinness(h).unwrap();
            let path = loading_path(&s0, cutoff).unwrap();
            assert!(path.jumps.is_empty());
            let [pass] = &path.passes[..] else {
                panic!("{} bands passed", path.passes.len())
            };
            assert_eq!(pass.mode, 6);
            assert!(
                pass.at.force_bar < fold.force_bar && pass.at.force_bar > -2.4,
                "{}",
                pass.at.force_bar
            );
            assert!(
                pass.to.force_bar < pass.at.force_bar && pass.to.force_bar > -2.7,
                "{}",
                pass.to.force_bar
            );
            assert!(pass.to.a_bar < fold.a_bar - 0.03, "{}", pass.to.a_bar);
            let smallest_before = path
                .states
                .iter()
                .filter(|st| st.force_bar > pass.at.force_bar)
                .map(|st| st.a_bar)
                .fold(f64::INFINITY, f64::min);
            assert!(
                (smallest_before - fold.a_bar).abs() < 1e-4,
                "{smallest_before}"
            );
            // (at h/L = 1 the last state is the one whose shape is
            // unresolved)
            let held = &path.states[..path.states.len() - usize::from(h == 1.0)];
            // (at h/L = 0.5 the last state is the pull-off, neutral)
            held_resolved_and_not_unstable(held, cutoff);
            let last = path.states.last().unwrap();
            if h == 0.5 {
                reaches(&path, &pull_off);
            } else {
                let PathEnd::NotSettled(why) = &path.end else {
                    panic!("{:?}", path.end)
                };
                assert!(why.contains("(the largest n = 4,"), "{why}");
                // (a piece beyond was looked for, and the words say so)
                assert!(
                    why.ends_with(
                        "no state of a resolved shape was found beyond the band within 10 % of a below"
                    ),
                    "{why}"
                );
                assert!(
                    last.force_bar > pull_off.force_bar
                        && last.force_bar < pull_off.force_bar + 0.02,
                    "{}",
                    last.force_bar
                );
            }
        }
    }

    /// At ρ = 0.9 (h/L = 0.5) the path holds its state down to the pull-off
    /// `exact pull-off` reports (F̄ = −4.46609, ā = 2.34244, found there by
    /// another route), where it is lost; the descent from there at the
    /// force just below grows ā and stalls: for `descent::STALL_STEPS` (20)
    /// steps in a row a longer step found no equilibrium of the modes
    /// shorter than the cutoff, and where the contact goes is not settled
    /// (before the stall rule the descent crept on until no step lowered
    /// the potential). Where it stalls is the ā docs/exact-record.md's row ρ = 0.9
    /// prints.
    #[test]
    fn at_rho_0_9_the_path_is_lost_at_the_pull_off_where_the_descent_stalls() {
        let cutoff = Cutoff::for_thinness(0.5).unwrap();
        let path = loading_path(&start(0.9).unwrap(), cutoff).unwrap();
        assert!(path.jumps.is_empty());
        let (pull_off, _) = crate::exact::pull_off_resolved(0.9).unwrap();
        reaches(&path, &pull_off);
        let PathEnd::Lost { why, .. } = &path.end else {
            panic!("not lost: {:?}", path.end);
        };
        let row = docs_tables::row("| ρ | h/L | the path | time |", "| 0.9 | 0.5 |");
        let printed = row[1]
            .split("stalls at ā = ")
            .nth(1)
            .and_then(|rest| rest.split(' ').next())
            .expect("the row says where the descent stalls");
        assert!(
            why.contains(&format!("the descent stalls at a = {printed},")),
            "{why} (docs: {printed})"
        );
        // the descent grows ā from the pull-off
        assert!(
            printed.parse::<f64>().unwrap() > pull_off.a_bar,
            "{printed}"
        );
    }

    /// docs/exact-record.md's ten crossing angles (two equal cylinders, r = 10 mm,
    /// h = 0.1 mm, G′ = 1 MPa, Δγ = 0.05 J/m², ρ = tan²(θ/2)), each with its
    /// coatings' own thinness (the table's row "h/L"): the table's row
    /// "loading path with this h/L" says where the path ends, which is the
    /// reference of issue 32's item 5 where it is a pull-off. Held here at
    /// the two cheapest angles: at 90° the circle comes off at the closed
    /// form's pull-off; at 80° the path passes the bands of n = 8 and 6 and
    /// ends not settled at the force the row prints, above today's pull-off.
    #[test]
    fn at_80_and_90_degrees_the_path_with_the_coatings_own_thinness_ends_where_the_table_says() {
        let (thinness, ends) = (
            docs_tables::row("| θ | 16° |", "| h/L |"),
            docs_tables::row("| θ | 16° |", "| loading path with this h/L |"),
        );
        assert_eq!((thinness.len(), ends.len()), (10, 10), "one cell an angle");
        let rho = |theta: f64| (theta.to_radians() / 2.0).tan().powi(2);
        let path_at = |k: usize, theta: f64| {
            let cutoff = Cutoff::for_thinness(thinness[k].parse().unwrap()).unwrap();
            loading_path(&start(rho(theta)).unwrap(), cutoff).unwrap()
        };
        // 90°: the circle comes off at F̄ = −3π/2
        assert_eq!(ends[9], "comes off at today's pull-off");
        let circle = path_at(9, 90.0);
        let p = circle.pull_off().unwrap();
        assert!(
            (p.force_bar + 1.5 * std::f64::consts::PI).abs() < 1e-6,
            "{}",
            p.force_bar
        );
        // 80°: not settled at the force the row prints
        let printed: f64 = ends[8]
            .strip_prefix("not settled at F̄ = ")
            .and_then(|rest| rest.split(' ').next())
            .map(|v| v.replace('−', "-"))
            .expect("the row says where the path at 80° ends")
            .parse()
            .unwrap();
        let path = path_at(8, 80.0);
        let PathEnd::NotSettled(why) = &path.end else {
            panic!("{:?}", path.end);
        };
        let at: f64 = why
            .split("at force = ")
            .nth(1)
            .and_then(|rest| rest.split(' ').next())
            .expect("where")
            .parse()
            .unwrap();
        assert!(
            (at - printed).abs() < 5e-4,
            "{at} against the row's {printed}"
        );
        let modes: Vec<usize> = path.passes.iter().map(|b| b.mode).collect();
        assert_eq!(modes, [8, 6]);
        let (pull_off, _) = crate::exact::pull_off_resolved(rho(80.0)).unwrap();
        assert!(at > pull_off.force_bar, "{at} {}", pull_off.force_bar);
    }

    /// At ρ = 0.5 the path from F̄ = 10 (h/L = 0.5) meets three bands whose
    /// modes are shorter than the cutoff (3.14): n = 10 (its arm's lobes,
    /// 1.86 long, pass 1 % of ā at F̄ = 8.44 on the returning stretch past
    /// the band's upper edge at F̄ = 8.79, docs/exact.md "Bands"), n = 8
    /// (near F̄ = 2) and n = 6 (near F̄ = −1.4, the band between the
    /// zero-force state and the pull-off). It passes each onto the piece
    /// beyond and holds that piece's states, resolved and stable above the
    /// cutoff, down to the pull-off `exact pull-off` reports (F̄ = −3.2408,
    /// found there from `conformal:8`'s pull-off), where it is lost.
    /// (The same start with h/L = 0.28: the ignored test below.)
    #[test]
    #[ignore = "slow tier (.ci/slow): about 90 s; the loading path at rho = 0.8 and at 80/90 degrees stays in CI"]
    fn at_rho_0_5_the_path_passes_three_bands_to_the_pull_off() {
        let cutoff = Cutoff::for_thinness(0.5).unwrap();
        let from = start(0.5).unwrap();
        let path = loading_path(&from, cutoff).unwrap();
        let modes: Vec<usize> = path.passes.iter().map(|b| b.mode).collect();
        assert_eq!(modes, [10, 8, 6]);
        let first = &path.passes[0];
        assert!(
            first.at.force_bar < 8.79 && first.at.force_bar > 7.57,
            "{}",
            first.at.force_bar
        );
        // each landing lies below (in F̄) and inside (in ā) the arm it
        // leaves: the states held since the pass before
        let mut since = f64::INFINITY;
        for b in &path.passes {
            assert!(b.to.force_bar < b.at.force_bar);
            let arm = path
                .states
                .iter()
                .filter(|st| st.force_bar > b.at.force_bar && st.force_bar <= since)
                .map(|st| st.a_bar)
                .fold(f64::INFINITY, f64::min);
            assert!(b.to.a_bar < arm, "n = {}: {} {arm}", b.mode, b.to.a_bar);
            since = b.to.force_bar;
        }
        assert!(path.jumps.is_empty());
        held_resolved_and_not_unstable(&path.states, cutoff);
        let (pull_off, _) = crate::exact::pull_off_resolved(0.5).unwrap();
        reaches(&path, &pull_off);
    }

    /// With h/L = 0.28 (cutoff 1.76) the path from ρ = 0.5's start passes
    /// the band of n = 12 (1.56 long) instead of n = 10 and is lost on the
    /// piece beyond, at the state it lands on (F̄ = 7.69), which is unstable
    /// under load to n = 10 (1.84 long, resolved at this cutoff): the
    /// descent from it stalls where the modes shorter than the cutoff cut
    /// its steps short (before the stall was a rule it crept on, one step
    /// of 3e-6 in ā a second, and the path had not ended after 57 min).
    /// docs/exact-record.md's row ρ = 0.5, h/L = 0.28. Ignored: 101 s in the test
    /// profile (2026-11-30); a stall the tests run is at ρ = 0.9 above.
    #[test]
    #[ignore = "slow tier (.ci/slow): about 100 s; run it after changing the descent"]
    fn at_rho_0_5_and_h_0_28_the_path_passes_n_12_and_the_descent_stalls() {
        let from = start(0.5).unwrap();
        let thin = Cutoff::for_thinness(0.28).unwrap();
        let path = loading_path(&from, thin).unwrap();
        let modes: Vec<usize> = path.passes.iter().map(|b| b.mode).collect();
        assert_eq!(modes, [12]);
        let PathEnd::Lost { state, why } = &path.end else {
            panic!("not lost: {:?}", path.end);
        };
        assert!(
            state.force_bar > 7.6 && state.force_bar < 7.8,
            "{}",
            state.force_bar
        );
        assert!((state.force_bar - path.passes[0].to.force_bar).abs() < 1e-9);
        let unstable: Vec<usize> = unstable_resolved(state, thin).iter().map(|m| m.n).collect();
        assert!(unstable.contains(&10), "{unstable:?}");
        assert!(why.contains("the descent stalls"), "{why}");
        assert!(path.states.iter().all(|st| st.bc_error <= RESOLVED));
    }

    /// docs/exact.md ("The loading path by descent", ρ = 0.3 from the
    /// window): on the piece of the family connected to the circle between
    /// the folds ā = 3.6004 and 3.6731 at ρ = 0.3, the state of ā = 3.6367
    /// (F̄ = 13.64) is stable under load above the cutoff of h/L = 0.3 and
    /// its shape resolved. Unloaded from there, the contact holds resolved
    /// states stable above the cutoff down to F̄ = 11.61, and at the next
    /// state held, F̄ = 11.11 (ā = 3.6006, just above the piece's fold in ā
    /// at 3.6004), its undulations from n = 14 on, shorter than the cutoff,
    /// pass 1 % of ā. The path passes that band onto the next piece below,
    /// the window between the folds ā = 3.4115 (F̄ = 5.00, n = 12) and
    /// 3.4702 (F̄ = 8.55, n = 10) located by the windows' own route
    /// (docs/data/exact_windows.jsonl), holds it down towards its lower
    /// fold, and is not settled where that fold's n = 12 undulations pass
    /// 1 % of ā above it: no resolved piece is found within 10 % of ā
    /// below. (Before the arm's tangent checked each step, a unit step
    /// landed at F̄ = 10.61, past the fold.)
    #[test]
    #[ignore = "slow tier (.ci/slow): about 120 s; the loading path at rho = 0.8 and at 80/90 degrees stays in CI"]
    fn at_rho_0_3_a_state_of_a_window_passes_one_band_and_unloads_until_its_shape_is_unresolved() {
        let cutoff = Cutoff::for_thinness(0.3).unwrap();
        let t = Truncation::in_arclength(crate::studies::reach::MODES);
        let st = crate::studies::reach::from_the_circle(3.62, t)
            .unwrap()
            .unwrap();
        let Ok(crate::exact::rho_path::Followed::Reached(st)) =
            crate::exact::rho_path::follow(&st, 0.3, Hold::Size(3.62))
        else {
            panic!("the size 3.62 reaches rho = 0.3");
        };
        let ex = Exact::new(0.3, st.truncation).unwrap();
        let s0 = ex
            .solve_at(Hold::Size(3.6367), &st.contour, st.delta_bar)
            .unwrap()
            .judged(cutoff);
        assert_eq!(s0.stability.stable_load, Some(true));
        assert!(s0.shape.is_some_and(|w| !w.unresolved));
        assert!((s0.force_bar - 13.6418).abs() < 1e-4, "{}", s0.force_bar);
        let path = loading_path(&s0, cutoff).unwrap();
        let PathEnd::NotSettled(_) = &path.end else {
            panic!("{:?}", path.end)
        };
        assert!(path.jumps.is_empty());
        let [pass] = &path.passes[..] else {
            panic!("{} bands passed", path.passes.len())
        };
        assert_eq!(pass.mode, 14);
        // the band's mode passes 1 % of ā as the piece nears its fold in ā
        // (3.6004, F̄ = 10.951, the windows), followed step by step along
        // the arm: the state whose shape turns unresolved lies above the
        // fold; the last state held before it at F̄ = 11.61
        assert!(
            pass.at.force_bar > 10.951 && pass.at.force_bar < 11.6,
            "{}",
            pass.at.force_bar
        );
        let before = path
            .states
            .iter()
            .rfind(|st| st.force_bar > pass.at.force_bar)
            .unwrap();
        assert!(
            (before.force_bar - 11.6105).abs() < 1e-3,
            "{}",
            before.force_bar
        );
        // the landing lies on the window's piece below (between its folds)
        let (lower, upper) = ((3.411480, 5.000404), (3.470180, 8.552680));
        assert!(
            pass.to.a_bar > lower.0 && pass.to.a_bar < upper.0,
            "{}",
            pass.to.a_bar
        );
        assert!(
            pass.to.force_bar > lower.1 && pass.to.force_bar < upper.1,
            "{}",
            pass.to.force_bar
        );
        let (last, held) = path.states.split_last().unwrap();
        let shape = last.clone().judged(cutoff).shape.unwrap();
        assert!(shape.unresolved && shape.mode == Some(12), "{shape:?}");
        assert!(
            last.a_bar > lower.0 && last.force_bar > lower.1 && last.force_bar < pass.to.force_bar,
            "{} {}",
            last.a_bar,
            last.force_bar
        );
        for st in held {
            let judged = st.clone().judged(cutoff);
            assert!(st.bc_error <= CONVERGED, "{}", st.bc_error);
            assert_eq!(
                judged.stability.stable_load,
                Some(true),
                "F = {}",
                st.force_bar
            );
            assert!(!judged.shape.unwrap().unresolved, "F = {}", st.force_bar);
        }
    }
}
