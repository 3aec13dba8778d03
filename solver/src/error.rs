//! Typed errors of the solver: bad input names the parameter and its allowed
//! range; non-convergence says where.
//!
//! Owns: [`Error`], `BRIEF` (a message as a person reads it). May use: nothing else in the crate.

// the brief form of a message is the command line's (a library user reads
// the whole `Display` text)
#![cfg_attr(not(feature = "cli"), allow(dead_code))]

/// Everything that can go wrong in thinjkr.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A parameter outside its allowed range.
    #[error("parameter {name} = {} is outside its allowed range {range}", short(*value))]
    OutOfRange {
        /// The parameter's name.
        name: &'static str,
        /// The value given.
        value: f64,
        /// The allowed range, in words (with its numeric ends where they
        /// depend on the contact).
        range: std::borrow::Cow<'static, str>,
    },
    /// Newton's method did not converge.
    #[error("no convergence after {iterations} iterations at a_bar = {}, s = {}{}; {context}", rounded(*a_bar), rounded(*s), residual_words(*residual))]
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
    /// The exact solver has no near-elliptic state at the control: it lies
    /// in a band of the family (an interval of ā where the family folds
    /// back), and no arm beside the band, followed past its fold, reaches
    /// it converged. A `no_state` for machine readers, told apart so that
    /// no decision has to read the words.
    #[error("no contact state: {0}")]
    InBand(String),
    /// The exact solver's family at the control, continued in ρ from a
    /// larger ρ, turns back at a fold in ρ above the ρ asked for: no state
    /// on it lies below. A `no_state` for machine readers, told apart so
    /// that no decision has to read the words.
    #[error("no contact state: {what}")]
    PastRhoFold {
        /// The smallest ρ of the family at the control.
        fold: f64,
        /// The ρ of the state the family was continued from.
        from: f64,
        /// The whole story: where the family was continued from, the fold's
        /// ā and the two states beside it, and the routes tried before.
        what: String,
    },
    /// A state followed in ρ from a larger ρ (the pull-off in the
    /// arclength representation) converges down to `reached` only, above
    /// the ρ asked for: a `no_state` for machine readers, told apart so
    /// that a table can say where in few words.
    #[error("no contact state: {what}")]
    StopsInRho {
        /// The smallest ρ at which the followed state converged.
        reached: f64,
        /// The whole story: how it stopped, and the routes tried before.
        what: String,
    },
    /// The request itself is incomplete or contradictory (a usage error,
    /// not a property of the contact).
    #[error("usage: {0}")]
    Usage(String),
    /// A value inside the allowed range but outside the range the solver
    /// supports numerically.
    #[error("parameter {name} = {} is outside the supported range {supported}", short(*value))]
    Unsupported {
        /// The parameter's name.
        name: &'static str,
        /// The value given.
        value: f64,
        /// The supported range, in words.
        supported: std::borrow::Cow<'static, str>,
    },
    /// Reading input or writing output failed (a file, a pipe, a disk).
    #[error("input/output: {0}")]
    Io(String),
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

impl Error {
    /// The kind of failure, one snake-case word per variant (for machine
    /// readers: the Python package's exception classes, JSON errors).
    pub fn kind(&self) -> &'static str {
        match self {
            Error::OutOfRange { .. } => "out_of_range",
            Error::NoConvergence { .. } => "no_convergence",
            Error::Unresolved { .. } => "unresolved",
            Error::NoState(_)
            | Error::InBand(_)
            | Error::PastRhoFold { .. }
            | Error::StopsInRho { .. } => "no_state",
            Error::Usage(_) => "usage",
            Error::Unsupported { .. } => "unsupported",
            Error::Io(_) => "io",
            Error::Unavailable { .. } => "unavailable",
        }
    }
}

impl Error {
    /// What went wrong without the words of its kind (`no contact state: `,
    /// `not resolved: `), to nest it in another message.
    pub fn detail(&self) -> String {
        match self {
            Error::NoState(why)
            | Error::InBand(why)
            | Error::PastRhoFold { what: why, .. }
            | Error::StopsInRho { what: why, .. } => why.clone(),
            Error::Unresolved { what, .. } => what.clone(),
            other => other.to_string(),
        }
    }
}

/// The most characters of an error's message as a person reads it
/// ([`Error::brief`]); the whole record is its `Display` text.
pub(crate) const BRIEF: usize = 300;

/// What a shortened message ends with.
pub(crate) const MORE: &str = " … (--explain: the whole record)";

impl Error {
    /// The message in at most [`BRIEF`] characters: as it is where it
    /// fits; else its clauses (separated by "; " outside parentheses) from
    /// the first while they fit, the first without its parenthesised
    /// asides where it alone does not, and [`MORE`] after them. An exact
    /// request's routes each add their record to the message (2,500
    /// characters at ρ = 1e-300 before its floor); the first clause says
    /// what decided.
    pub(crate) fn brief(&self) -> String {
        self.brief_ending(MORE)
    }

    /// The message in at most 300 characters, shortened as the command
    /// line shortens it and then ending with `more` (which says where the
    /// whole record is in the caller's words: the Python package's
    /// exception attribute, say). The whole record is the `Display` text.
    pub fn brief_ending(&self, more: &str) -> String {
        fitted(&self.to_string(), BRIEF, more)
    }
}

/// `text` in at most `limit` characters, as [`Error::brief`] shortens it,
/// ending with `more` where it is shortened.
fn fitted(text: &str, limit: usize, more: &str) -> String {
    let count = |s: &str| s.chars().count();
    if count(text) <= limit {
        return text.to_string();
    }
    // the ending is at most a third of the limit, so that the message
    // keeps room for its first words
    let more: String = more.chars().take(limit / 3).collect();
    let budget = limit.saturating_sub(count(&more));
    let clauses = top_level_clauses(text);
    let mut out = String::new();
    for (i, c) in clauses.iter().enumerate() {
        let c = if i == 0 && count(c) > budget {
            without_asides(c)
        } else {
            c.to_string()
        };
        let joined = if out.is_empty() {
            c
        } else {
            format!("{out}; {c}")
        };
        if count(&joined) > budget {
            break;
        }
        out = joined;
    }
    if out.is_empty() {
        // one clause too long even without its asides: cut at a word
        let bare = without_asides(clauses[0]);
        let mut cut: String = bare.chars().take(budget).collect();
        if let Some(space) = cut.rfind(' ') {
            cut.truncate(space);
        }
        out = cut;
    }
    out + &more
}

/// The clauses of `text`: its pieces between "; " outside parentheses.
fn top_level_clauses(text: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    let bytes = text.as_bytes();
    for (i, &b) in bytes.iter().enumerate() {
        match b {
            b'(' => depth += 1,
            b')' => depth -= 1,
            b';' if depth == 0 && bytes.get(i + 1) == Some(&b' ') => {
                out.push(&text[start..i]);
                start = i + 2;
            }
            _ => {}
        }
    }
    out.push(&text[start..]);
    out
}

/// `text` without its parenthesised asides (and the space before each).
fn without_asides(text: &str) -> String {
    let mut out = String::new();
    let mut depth = 0;
    for ch in text.chars() {
        match ch {
            '(' => {
                if depth == 0 && out.ends_with(' ') {
                    out.pop();
                }
                depth += 1;
            }
            ')' if depth > 0 => depth -= 1,
            _ if depth == 0 => out.push(ch),
            _ => {}
        }
    }
    out
}

/// Shorthand.
pub type Result<T> = std::result::Result<T, Error>;

/// A number for a message, one rule everywhere: at most six significant
/// digits (what a person can act on; `rho = 0.307916`, not
/// `0.3079159382974495`), plain between 1e-4 and 1e7, else short
/// scientific notation (`-1e308`, not three hundred digits).
pub(crate) fn short(x: f64) -> String {
    let x = if x.is_finite() {
        format!("{x:.5e}").parse::<f64>().unwrap_or(x)
    } else {
        x
    };
    let a = x.abs();
    if x == 0.0 || !x.is_finite() || (1e-4..1e7).contains(&a) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// A computed number for a message, to six significant digits ([`short`]);
/// "undefined" where it is not a number.
pub(crate) fn rounded(x: f64) -> String {
    if !x.is_finite() {
        return "undefined".into();
    }
    short(x)
}

fn residual_words(r: f64) -> String {
    if r.is_finite() {
        format!(" (residual norm {r:.1e})")
    } else {
        String::new()
    }
}

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
        Err(Error::OutOfRange {
            name,
            value,
            range: range.into(),
        })
    }
}

/// The first 40 characters of `s`, quoted, with the length of the rest.
pub(crate) fn quote_start(s: &str) -> String {
    let n = s.chars().count();
    if n <= 40 {
        format!("{s:?}")
    } else {
        let head: String = s.chars().take(40).collect();
        format!("{head:?}… ({} more characters)", n - 40)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A message that fits is left as it is; a longer one keeps its
    /// clauses from the first while they fit, drops the first clause's
    /// asides where it alone is too long, never splits inside
    /// parentheses, and says the record is longer.
    #[test]
    fn a_long_message_keeps_its_first_clauses_within_the_limit() {
        assert_eq!(fitted("short; and more", 300, MORE), "short; and more");
        let aside = format!("({})", "x; ".repeat(60));
        let text = format!(
            "no contact state: the family turns back at rho = 0.19 {aside}, so it has no state at rho = 0.1; then the arms: {}; the screen finds none",
            "a = 3.2: stops, ".repeat(40)
        );
        let brief = fitted(&text, BRIEF, MORE);
        assert!(brief.chars().count() <= BRIEF, "{brief}");
        assert_eq!(
            brief,
            format!(
                "no contact state: the family turns back at rho = 0.19, so it has no state at rho = 0.1{MORE}"
            )
        );
        // clauses that fit are kept whole, the first with its aside
        let text = format!("first (a; b); second; {}", "third ".repeat(60));
        assert_eq!(
            fitted(&text, BRIEF, MORE),
            format!("first (a; b); second{MORE}")
        );
        // one clause too long even without asides is cut at a word
        let text = "word ".repeat(100);
        let brief = fitted(&text, BRIEF, MORE);
        assert!(
            brief.chars().count() <= BRIEF && brief.ends_with(MORE),
            "{brief}"
        );
        assert!(brief.starts_with("word word"), "{brief}");
        // another front end's ending, and one too long, still in the limit
        let e = Error::NoState("word ".repeat(100));
        let brief = e.brief_ending(" … (e.record: the whole)");
        assert!(
            brief.chars().count() <= BRIEF && brief.ends_with("(e.record: the whole)"),
            "{brief}"
        );
        let brief = e.brief_ending(&"!".repeat(400));
        assert!(
            brief.chars().count() <= BRIEF && brief.starts_with("no contact state: word"),
            "{brief}"
        );
    }
}
