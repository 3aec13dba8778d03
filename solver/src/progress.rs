//! What a long computation is doing now, for a person waiting on it: the
//! stage (a route of the exact solver, in words) and the count done in it
//! (`3 of 6`, `at rho = 0.21`). The computation says it ([`stage`]); the
//! command line's spinner shows it ([`now`]) beside the elapsed time, so a
//! search of minutes shows where it is, not only that it runs. One slot
//! for the process (the newest word wins; a search's threads write in turn).
//!
//! Owns: [`stage`], [`now`]. May use: nothing else in the crate.

// read by the command line's spinner
#![cfg_attr(not(feature = "cli"), allow(dead_code))]

use std::sync::Mutex;

static STAGE: Mutex<String> = Mutex::new(String::new());

/// Say what the computation does now (replacing what it said before).
pub(crate) fn stage(words: impl Into<String>) {
    let mut s = STAGE.lock().unwrap_or_else(|p| p.into_inner());
    *s = words.into();
}

/// What the computation said last (empty: nothing yet).
pub(crate) fn now() -> String {
    STAGE.lock().unwrap_or_else(|p| p.into_inner()).clone()
}
