//! What a state is held at, one vocabulary for every model and every front
//! end: the approach δ̄, the force F̄ or the contact size ā ([`Hold`]). The
//! models of the ellipse, the contour families, the exact solver, the
//! model layer (`registry`), `batch`, the command line and the Python
//! package all take it; a kind that cannot hold a state at one of them
//! says so with a typed error.
//!
//! Owns: [`Hold`], `Quantity`. May use: `error`.

use serde::Serialize;

/// What a state is held at: the approach δ̄, the force F̄, or the contact
/// size ā.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum Hold {
    /// Given δ̄ (displacement control).
    Delta(f64),
    /// Given F̄ (load control; F̄ = 0: the zero-force state).
    Force(f64),
    /// Given ā (the major semi-axis).
    Size(f64),
}

impl Hold {
    /// The control named as the command line and Python name it (`delta`,
    /// `force`, `a`), at `value`.
    pub fn named(control: &str, value: f64) -> crate::Result<Hold> {
        match control {
            "delta" => Ok(Hold::Delta(value)),
            "force" => Ok(Hold::Force(value)),
            "a" => Ok(Hold::Size(value)),
            other => Err(crate::Error::Usage(format!(
                "the control is delta, force or a (got '{}')",
                crate::error::quote_start(other).trim_matches('"')
            ))),
        }
    }

    /// The value held.
    pub(crate) fn value(self) -> f64 {
        match self {
            Hold::Delta(v) | Hold::Force(v) | Hold::Size(v) => v,
        }
    }

    /// How far a state with these values lies from the value held: its
    /// δ̄, F̄ or ā minus the held one.
    pub(crate) fn excess(self, a_bar: f64, delta_bar: f64, force_bar: f64) -> f64 {
        match self {
            Hold::Delta(v) => delta_bar - v,
            Hold::Force(v) => force_bar - v,
            Hold::Size(v) => a_bar - v,
        }
    }

    /// The control's value, refused unless finite (an `Error::OutOfRange`
    /// naming `delta`, `force` or `a`): NaN or ∞ is bad input, not a value
    /// no state reaches.
    pub(crate) fn check_finite(self) -> crate::Result<Self> {
        let name = match self {
            Hold::Delta(_) => "delta",
            Hold::Force(_) => "force",
            Hold::Size(_) => "a",
        };
        crate::error::check_range(name, self.value(), true, "finite").map(|_| self)
    }
}

impl std::fmt::Display for Hold {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Hold::Delta(d) => write!(f, "delta = {}", crate::error::short(*d)),
            Hold::Force(v) => write!(f, "force = {}", crate::error::short(*v)),
            Hold::Size(a) => write!(f, "a = {}", crate::error::short(*a)),
        }
    }
}

/// A quantity a state is held at or watched in: ā, δ̄ or F̄ (the
/// quantity of a [`Hold`], without its value).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Quantity {
    /// ā.
    ABar,
    /// δ̄.
    Delta,
    /// F̄.
    Force,
}

impl Quantity {
    /// The quantity `hold` holds.
    pub(crate) fn of(hold: Hold) -> Quantity {
        match hold {
            Hold::Delta(_) => Quantity::Delta,
            Hold::Force(_) => Quantity::Force,
            Hold::Size(_) => Quantity::ABar,
        }
    }
}
