//! Near-circular inputs, 0 < 1 − ρ < [`NEAR_CIRCLE`]: every state and fold
//! continued in ρ from the anchor ρ₀ = 1 − [`NEAR_CIRCLE`] (issue 21, items
//! 8 and 9).
//!
//! Below ρ₀ the explicit branch in s that the cold scan samples cancels:
//! the whole physical branch lies within O(1 − ρ) of s∞ ≈ 1, where its
//! coefficients are differences of O(10³) terms that vanish at s = ρ = 1
//! (the energy closure found no state at all for 1 − ρ between 2e-12 and
//! 2.3e-8). The residuals themselves do not cancel in that way: their
//! error near s = 1 is round-off in absolute terms, and Newton's method on
//! them is as well conditioned as anywhere on the branch. So a state at
//! ρ = 1 − ε is found from two states the solver already trusts:
//! - regular states (at δ̄, ā or F̄ given, the pull-off under load
//!   control): the exact axisymmetric state at ρ = 1 and the state at ρ₀,
//!   interpolated linearly in ε (they are analytic in ε), then Newton on
//!   the residuals with the control (or fold) equation at ρ;
//! - the end of displacement control (and the fold of the contact size):
//!   near ρ = 1 it sits where the circle loses stability to the cos 2θ mode
//!   (ā = 2^{2/3} for the paper's models), an imperfect bifurcation whose
//!   states move as √ε; they are continued from ρ₀ in steps of ε by 10,
//!   with a predictor linear in √ε through the last two states.
//!
//! At ρ = 1 exactly the displacement-controlled pull-off is that loss of
//! stability of the circle ([`Contact::circle_bifurcation`]), the limit of
//! the ρ < 1 answers (continuous in ρ up to 1).
//!
//! Owns: the near-circular forms of the searches of
//! [`Contact`]. May use: `control`, its parent `contact`, `fold`, `error`.

use super::{Contact, FoldCondition, State, NEAR_CIRCLE};
use crate::control::Quantity;
use crate::error::{Error, Result};
use nalgebra::{Vector2, Vector3};

/// 1 − s above which the anchor's state is not near the circle (1 − s of
/// a near-circular state there is of order 1e-6).
const ELONGATED: f64 = 1e-3;

/// The relative precision to which a near-circular fold that moves as √ε
/// is located: its condition is a difference of nearly equal terms, known
/// to about 1e-13, and so the fold to about 1e-9 at 1 − ρ = 1e-12 (Newton
/// steps stagnate there; measured on `apex45`).
const FOLD_FLOOR: f64 = 1e-8;

fn z(st: &State) -> Vector3<f64> {
    Vector3::new(st.a_bar, st.s, st.delta_bar)
}

impl Contact {
    /// Whether ρ is near-circular (0 < 1 − ρ < [`NEAR_CIRCLE`]).
    pub(super) fn near_circle(&self) -> bool {
        self.rho < 1.0 && 1.0 - self.rho < NEAR_CIRCLE
    }

    /// The same model at `rho` (searches and Newton controls kept).
    fn at_rho(&self, rho: f64) -> Result<Contact> {
        let mut c = Contact::with_model(self.model_id(), rho)?;
        c.newton = self.newton;
        c.search = self.search;
        Ok(c)
    }

    /// The anchor ρ₀ = 1 − NEAR_CIRCLE.
    pub(super) fn anchor(&self) -> Result<Contact> {
        self.at_rho(1.0 - NEAR_CIRCLE)
    }

    /// The circle, ρ = 1.
    pub(super) fn circle(&self) -> Result<Contact> {
        self.at_rho(1.0)
    }

    /// ε/ε₀ of this contact.
    fn fraction(&self) -> f64 {
        (1.0 - self.rho) / NEAR_CIRCLE
    }

    /// A state at ρ from the anchor's at the same control. Near the circle
    /// (1 − s of the anchor's state at most [`ELONGATED`]) with the circle's
    /// state at that control: predictor linear in ε, then Newton on the
    /// residuals with `control` = `target`. Otherwise (the branch has
    /// turned into an elongated contact past the circle's bifurcation, or
    /// the circle has no such state) continued from the anchor's in steps
    /// of ε by 10, down to ρ itself (ρ = 1 included).
    pub(super) fn near_circle_controlled(
        &self,
        circle: Option<&State>,
        anchor: &State,
        control: Quantity,
        target: f64,
        what: &str,
    ) -> Result<State> {
        match circle {
            Some(c) if 1.0 - anchor.s <= ELONGATED => {
                let guess = z(c) + (z(anchor) - z(c)) * self.fraction();
                self.solve_controlled(guess, control, target, what)
            }
            _ => {
                let end = 1.0 - self.rho;
                let mut eps = NEAR_CIRCLE;
                let mut x = z(anchor);
                loop {
                    eps = if eps * 0.1 > end.max(1e-16) {
                        eps * 0.1
                    } else {
                        end
                    };
                    x = z(&self
                        .at_rho(1.0 - eps)?
                        .solve_controlled(x, control, target, what)?);
                    if eps <= end {
                        break;
                    }
                }
                let mut st = self.state_from(x[0], x[1], x[2]);
                st.beyond_size_fold = anchor.beyond_size_fold;
                Ok(st)
            }
        }
    }

    /// An error of the anchor's, said for this ρ.
    pub(super) fn from_anchor(&self, e: Error) -> Error {
        match e {
            Error::NoState(why) => Error::NoState(format!(
                "at rho = {}, as at the near-circular anchor rho = {}: {why}",
                crate::error::short(self.rho),
                crate::error::short(1.0 - NEAR_CIRCLE)
            )),
            other => other,
        }
    }

    /// At displacement δ̄ for 0 < 1 − ρ < NEAR_CIRCLE and at ρ = 1: the
    /// circle's state while it is stable (ā above the circle's
    /// bifurcation, continued to ρ from there and the anchor's); below it
    /// the limit of the states at ρ < 1: the anchor's state continued to ρ,
    /// or the anchor's error (below the displacement-controlled pull-off
    /// of the models whose branch folds there).
    pub(super) fn near_circle_at_displacement(&self, delta: f64, what: &str) -> Result<State> {
        let circle = self.circle()?.circle_at_displacement(delta)?;
        // the size below which the circle is a saddle; none (0) only where
        // the scan found the circle stable throughout, any other failure
        // is the answer's
        let a_b = match self.circle()?.circle_bifurcation() {
            Ok(b) => b.a_bar,
            Err(Error::NoState(_)) => 0.0,
            Err(e) => return Err(e),
        };
        let stable_circle = circle.a_bar > a_b;
        if self.rho == 1.0 && stable_circle {
            return Ok(circle);
        }
        match self.anchor()?.at_displacement(delta) {
            Ok(anchor) => self.near_circle_controlled(
                stable_circle.then_some(&circle),
                &anchor,
                Quantity::Delta,
                delta,
                what,
            ),
            // between the circle's bifurcation and the anchor's fold: from
            // the circle's state itself
            Err(_) if stable_circle => {
                self.solve_controlled(z(&circle), Quantity::Delta, delta, what)
            }
            Err(e) => Err(self.from_anchor(e)),
        }
    }

    /// A regular fold (the pull-off under load control) at ρ from the
    /// circle's and the anchor's.
    pub(super) fn near_circle_fold(
        &self,
        circle: &State,
        anchor: &State,
        which: FoldCondition,
    ) -> Result<State> {
        let guess = z(circle) + (z(anchor) - z(circle)) * self.fraction();
        let mut g = self.state_from(guess[0], guess[1].min(1.0), guess[2]);
        g.beyond_size_fold = anchor.beyond_size_fold;
        self.refine_fold(&g, which)
    }

    /// A fold that moves as √ε (the end of displacement control, the fold
    /// of the contact size): continued from the anchor's in steps of ε by
    /// 10 (the last step to ρ itself), the predictor linear in √ε through
    /// the last two states (the anchor's first step from the circle's
    /// bifurcation point).
    pub(super) fn near_circle_sqrt_fold(
        &self,
        anchor: &State,
        which: FoldCondition,
    ) -> Result<State> {
        let target = 1.0 - self.rho;
        let bifurcation = self.circle()?.circle_bifurcation()?;
        let mut older = (0.0f64, z(&bifurcation));
        let mut prev = (NEAR_CIRCLE, z(anchor));
        let mut eps = NEAR_CIRCLE;
        while eps > target {
            eps = (eps * 0.1).max(target);
            let rate = (eps.sqrt() - prev.0.sqrt()) / (prev.0.sqrt() - older.0.sqrt());
            let guess = prev.1 + (prev.1 - older.1) * rate;
            let c = self.at_rho(1.0 - eps)?;
            let st = crate::fold::locate_within(
                c.model,
                c.rho,
                Vector3::new(guess[0], guess[1].min(1.0), guess[2]),
                which,
                FOLD_FLOOR,
            )
            .map(|z| c.state_from(z[0], z[1], z[2]))
            .map_err(|e| match e {
                Error::NoConvergence { .. } => Error::NoState(format!(
                    "the {} at rho = {} could not be continued from rho = {} (near-circular continuation stopped at 1 - rho = {})",
                    fold_name(which),
                    crate::error::short(self.rho),
                    crate::error::short(1.0 - NEAR_CIRCLE),
                    crate::error::rounded(eps)
                )),
                other => other,
            })?;
            older = prev;
            prev = (eps, z(&st));
        }
        let mut st = self.state_from(prev.1[0], prev.1[1], prev.1[2]);
        st.beyond_size_fold = anchor.beyond_size_fold;
        Ok(st)
    }

    /// At ρ = 1: the state on the circle where it loses stability under
    /// displacement control, det ∂r/∂(ā, s) = 0 at s = 1 (the cos 2θ mode;
    /// for ā below it the circle is a saddle), found by a scan in ā below
    /// the pull-off under load control and bisection.
    pub(super) fn circle_bifurcation(&self) -> Result<State> {
        let m = self.model;
        let det = |a: f64| -> f64 {
            let Some((delta, _)) = m.axisymmetric(a) else {
                return f64::NAN;
            };
            m.residuals_and_jacobian(Vector2::new(a, 1.0), 1.0, delta)
                .1
                .determinant()
        };
        let top = self.axisymmetric_pull_off()?.a_bar;
        let n = 200;
        let grid: Vec<f64> = (0..=n)
            .map(|k| top * 10f64.powf(-2.0 * k as f64 / n as f64))
            .collect();
        let sign_top = det(grid[0]).signum();
        let k = (1..=n)
            .find(|&k| det(grid[k]).signum() == -sign_top)
            .ok_or_else(|| {
                Error::NoState(format!(
                    "model {}: the circle (rho = 1) keeps its stability under displacement control down to a_bar = {}",
                    self.model_id(),
                    crate::error::rounded(grid[n])
                ))
            })?;
        let a = super::bisect(|a| det(a) * sign_top, grid[k], grid[k - 1])?;
        self.axisymmetric_state(a)
    }
}

fn fold_name(which: FoldCondition) -> &'static str {
    match which {
        FoldCondition::Displacement => "end of displacement control",
        FoldCondition::Load => "pull-off under load control",
        FoldCondition::ContactSize => "fold of the contact size",
    }
}
