//! Typed errors of the solver: bad input names the parameter and its allowed
//! range; non-convergence says where.
//!
//! Owns: [`Error`]. May use: nothing else in the crate.

/// Everything that can go wrong in thinjkr.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// A parameter outside its allowed range.
    #[error("parameter {name} = {value} is outside its allowed range {range}")]
    OutOfRange {
        /// The parameter's name.
        name: &'static str,
        /// The value given.
        value: f64,
        /// The allowed range, in words.
        range: &'static str,
    },
    /// Newton's method did not converge.
    #[error("no convergence after {iterations} iterations at a_bar = {a_bar}, s = {s} (residual norm {residual:e}); {context}")]
    NoConvergence {
        /// Iterations done.
        iterations: usize,
        /// Last iterate ā.
        a_bar: f64,
        /// Last iterate s.
        s: f64,
        /// Last residual norm.
        residual: f64,
        /// What was being solved.
        context: String,
    },
    /// A numerical reference (the exact solver) does not resolve the
    /// answer at the discretisation used; no number is given.
    #[error("not resolved: {what}")]
    Unresolved {
        /// What was not resolved, and with which discretisation.
        what: String,
        /// The residual measure that was too large (for the exact solver,
        /// max |∂p̄/∂ν − 1| on the fine grid).
        residual: f64,
    },
    /// The model has no state for the given input.
    #[error("no contact state: {0}")]
    NoState(String),
    /// The model lacks what was asked for (a closed form its derivation
    /// could not produce).
    #[error("model {model} has no {what} ({why})")]
    Unavailable {
        /// The model's name.
        model: &'static str,
        /// What is missing.
        what: String,
        /// Why, from the derivation.
        why: &'static str,
    },
}

/// Shorthand.
pub type Result<T> = std::result::Result<T, Error>;

/// `Ok(value)` when `value` is finite and `ok` (the caller's range test);
/// otherwise an [`Error::OutOfRange`] naming the parameter and its range.
pub(crate) fn check_range(
    name: &'static str,
    value: f64,
    ok: bool,
    range: &'static str,
) -> Result<f64> {
    if value.is_finite() && ok {
        Ok(value)
    } else {
        Err(Error::OutOfRange { name, value, range })
    }
}
