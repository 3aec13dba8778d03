//! The contour families as the exact solver's seeds: the largest member of
//! the family that seeds the exact solver of its gap (`seeds_exact` in its
//! data file; `conformal:8` for the cylinders) gives the solver its
//! starting guesses through the solver's own [`Seed`] interface, handed in
//! with the gap ([`exact_gap`], `Gap::cylinders`), so that the
//! exact solver names no model.
//!
//! Owns: the `Seed` implementation of a member, `Gap::cylinders`, the
//! seeds' lookup. May use: `conformal`, `exact` (its `Seed`, `Guess` and
//! `Gap`), `control`, `fold`, `error`.

use super::{families, Conformal, ConformalState, Family};
use crate::control::Hold;
use crate::exact::seed::{Guess, Seed};
use crate::exact::Gap;
use crate::fold::FoldCondition;
use std::sync::OnceLock;

fn guess(st: &ConformalState) -> Guess {
    Guess {
        a_bar: st.a_bar,
        b_bar: st.b_bar,
        s: st.s,
        delta_bar: st.delta_bar,
        force_bar: st.force_bar,
        bc_defect: st.bc_defect,
    }
}

impl Seed for Conformal {
    fn name(&self) -> String {
        Conformal::name(self)
    }
    fn trace_start(&self) -> f64 {
        self.family().trace_start_a
    }
    fn state(&self, rho: f64, hold: Hold) -> crate::Result<Guess> {
        self.solve(rho, hold).map(|st| guess(&st))
    }
    fn pull_off(&self, rho: f64) -> Option<Guess> {
        Conformal::pull_off(self, rho, FoldCondition::Load)
            .ok()
            .map(|(st, _)| guess(&st))
    }
}

/// Each family's seed (its largest member, where it seeds the exact solver
/// of its gap), in the registry's order, made once: the built-in families'
/// (`compiled`, no file read), or every family's.
fn seeds(built_in: bool) -> &'static [Option<&'static dyn Seed>] {
    static BUILT_IN: OnceLock<Vec<Option<&'static dyn Seed>>> = OnceLock::new();
    static ALL: OnceLock<Vec<Option<&'static dyn Seed>>> = OnceLock::new();
    let make = |fams: Vec<&'static super::Family>| -> Vec<Option<&'static dyn Seed>> {
        fams.into_iter()
            .enumerate()
            .map(|(i, f)| {
                let largest = f.members.iter().map(|t| t.terms).max()?;
                let m = Conformal::in_family(i, largest)
                    .ok()
                    .filter(|_| f.seeds_exact)?;
                Some(&*Box::leak(Box::new(m)) as &'static dyn Seed)
            })
            .collect()
    };
    if built_in {
        BUILT_IN.get_or_init(|| make(super::compiled().iter().collect()))
    } else {
        ALL.get_or_init(|| make(families().to_vec()))
    }
}

/// The family on `gap` that seeds its exact solver and its seed: a
/// built-in one first (no file read; a loaded family does not take a
/// built-in one's place, `load`), else a loaded one.
fn seeding(gap: &Gap) -> Option<(&'static super::Family, &'static dyn Seed)> {
    let find = |fams: Vec<&'static super::Family>, seeds: &'static [Option<&'static dyn Seed>]| {
        fams.into_iter()
            .zip(seeds)
            .find(|(f, s)| s.is_some() && f.unseeded_gap() == *gap)
            .and_then(|(f, s)| Some((f, (*s)?)))
    };
    find(super::compiled().iter().collect(), seeds(true))
        .or_else(|| find(families().to_vec(), seeds(false)))
}

/// The seed of the exact solver of `gap`: the largest member of the family
/// on that gap that seeds it, if the registry has one.
pub(crate) fn seed_of(gap: &Gap) -> Option<&'static dyn Seed> {
    seeding(gap).map(|(_, s)| s)
}

/// The family whose largest member seeds the exact solver of `gap`.
#[cfg(feature = "figures")]
pub(crate) fn seeding_family(gap: &Gap) -> Option<&'static Family> {
    seeding(gap).map(|(f, _)| f)
}

impl Gap {
    /// The cylinders' gap (1) with its seed from the registry (the family
    /// on it that seeds the exact solver, `conformal:8`).
    pub(crate) fn cylinders() -> Gap {
        Gap {
            seed: seed_of(&Gap::CYLINDERS),
            ..Gap::CYLINDERS
        }
    }
}

/// The gap the members of `family` solve, as data for the exact solver,
/// with the seed of that gap's exact solver.
pub(crate) fn exact_gap(family: &Family) -> Gap {
    let g = family.unseeded_gap();
    Gap {
        seed: seed_of(&g),
        ..g
    }
}
