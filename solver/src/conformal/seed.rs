//! The contour families as the exact solver's seeds: the largest member of
//! the family that seeds the exact solver of its gap (`seeds_exact` in its
//! data file; `conformal:8` for the cylinders) gives the solver its
//! starting guesses through the solver's own [`Seed`] interface, handed in
//! with the gap ([`exact_gap`], `Gap::cylinders`), so that the
//! exact solver names no model.
//!
//! It also names the gaps (issue 73): `cylinders` and each family's own,
//! the exact solver's answers on a gap named so ([`exact_pull_off_on_gap`],
//! [`exact_state_on_gap`]) for the command line's and Python's `--gap`.
//!
//! Owns: the `Seed` implementation of a member, `Gap::cylinders`, the
//! seeds' lookup, the gaps' names. May use: `conformal`, `exact` (its
//! `Seed`, `Guess`, `Gap`, and its answers on a gap), `control`, `fold`,
//! `error`.

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
    fn trace_start(&self) -> Option<f64> {
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
    #[cfg(feature = "cli")]
    fn pull_off_contour(&self, rho: f64) -> Option<(Guess, crate::exact::Contour)> {
        let (st, _) = Conformal::pull_off(self, rho, FoldCondition::Load).ok()?;
        let powers = self.tables.powers;
        let mut contour = crate::exact::Contour {
            a: 0.0,
            b: Vec::new(),
            c: vec![0.0; usize::from(powers.iter().max()?.saturating_sub(1) / 2)],
        };
        for (&p, &c) in powers.iter().zip(&st.coefficients) {
            match p {
                1 => contour.a = c,
                // odd p ≥ 3: e^{(2j+3)iθ}
                _ => contour.c[usize::from((p - 3) / 2)] = c,
            }
        }
        Some((guess(&st), contour))
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

/// The gap named `name` (`cylinders`, the paper's (1), or the name of a
/// contour family built in or loaded, whose own gap it is), with the
/// family where it is a gap of its own (a family on the cylinders' gap
/// names the cylinders'); an unknown name is a usage error that lists the
/// known ones.
pub(crate) fn gap_named(name: &str) -> crate::Result<(Gap, Option<&'static Family>)> {
    if name == "cylinders" {
        return Ok((Gap::cylinders(), None));
    }
    match families().iter().find(|f| f.name == name) {
        Some(f) => {
            let gap = exact_gap(f);
            Ok(if gap == Gap::CYLINDERS {
                (Gap::cylinders(), None)
            } else {
                (gap, Some(*f))
            })
        }
        None => Err(crate::Error::Usage(format!(
            "unknown gap {name}: the known gaps are cylinders{}",
            families()
                .iter()
                .map(|f| format!(", {}", f.name))
                .collect::<String>()
        ))),
    }
}

/// ρ on a family's own gap: at least the stored pull-offs' smallest, below
/// which the exact answers on the cylinders' gap start from
/// solver/data/exact_pull_offs.json, which holds no other gap.
fn own_gap_rho(rho: f64, family: &Family) -> crate::Result<()> {
    let least = crate::exact::stored::STORED_FROM_RHO;
    if rho < least {
        return Err(crate::Error::Unsupported {
            name: "rho",
            value: rho,
            supported: format!(
                "[{least}, 1] on the gap {}: below {least} the exact solver's starts are the stored pull-offs of the cylinders' gap",
                family.name
            )
            .into(),
        });
    }
    Ok(())
}

/// The gap named `name` ([`gap_named`]) where `rho` is in its range
/// (a family's own gap: `own_gap_rho`).
pub(crate) fn gap_at_rho(name: &str, rho: f64) -> crate::Result<Gap> {
    let (gap, family) = gap_named(name)?;
    if let Some(f) = family {
        own_gap_rho(rho, f)?;
    }
    Ok(gap)
}

/// The exact load-controlled pull-off at `rho` on the gap named `gap`
/// (`cylinders` or a contour family's name), with the default escalation of truncations (`tries`
/// `None`) or those given.
pub fn exact_pull_off_on_gap(
    gap: &str,
    rho: f64,
    tries: Option<&[crate::exact::Truncation]>,
) -> crate::Result<(crate::exact::ExactState, Vec<crate::exact::branch::Event>)> {
    let gap = gap_at_rho(gap, rho)?;
    match tries {
        None => crate::exact::pull_off_resolved_on(gap, rho),
        Some(t) => {
            crate::exact::pull_off_on(gap, rho, &crate::exact::ladder::Ladder::of(t.to_vec()))
        }
    }
}

/// The exact state at `control` and `rho` on the gap named `gap`
/// (`cylinders` or a contour family's name), with the default escalation of truncations (`tries`
/// `None`) or those given.
pub fn exact_state_on_gap(
    gap: &str,
    rho: f64,
    control: Hold,
    tries: Option<&[crate::exact::Truncation]>,
) -> crate::Result<crate::exact::ExactState> {
    let gap = gap_at_rho(gap, rho)?;
    match tries {
        None => crate::exact::at_resolved_on(gap, rho, control),
        Some(t) => crate::exact::searched_on(
            gap,
            rho,
            control,
            &crate::exact::ladder::Ladder::of(t.to_vec()),
            &mut |_| {},
        ),
    }
}
