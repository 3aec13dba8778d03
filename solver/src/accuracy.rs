//! The approximate models against the exact solution, a room above the
//! model families (it uses every kind and belongs to none): the tables of
//! `docs/accuracy.md` (load-controlled pull-off, zero force, F̄ = 10), one
//! row per ρ, each model's relative errors beside the exact values. An
//! exact value that is not resolved or not reached is said in words in
//! its row, never given as a number.
//!
//! Beside them, (2) itself against the layer of finite thickness at first
//! order in h/L at each pull-off (`render_layer`).
//!
//! It also renders the band maps of docs/exact.md ([`band_markdown`]), and
//! owns the convergence table under doubling (each resolved
//! pull-off recomputed with twice the contour modes and quadrature points)
//! and the reference file the checker reads for `sec6.error.exact`.
//!
//! Owns: [`Quantity`], `Row`, `row`, `render`, `render_layer`, `RHOS`,
//! `Doubling`, `doubling`, [`Reference`], [`band_markdown`]. May use: `generated` (`ModelId`), `fold`, `control`, `exact`, `contact`,
//! `conformal` (the compared members), `model` (the ellipse models), `slender`
//! (the slender limit's table), `report` (its state), `error`, `layer` ((2)
//! against the layer of finite thickness at first order in h/L).

// the accuracy table is rendered by the command line (`thinjkr accuracy`)
#![cfg_attr(not(feature = "cli"), allow(dead_code))]

use crate::conformal::{Conformal, ConformalState, Family};
use crate::control::Hold;
use crate::exact::bands::{Band, BandEdge, PROBE_STEP};
use crate::exact::{
    at_resolved_searching, pull_off_resolved, pull_off_resolved_on, Exact, ExactState, Gap,
    Truncation,
};
use crate::fold::FoldCondition;
use crate::report::BandMap;
use crate::{Contact, Error, ModelId, State};

/// The radii ratios of the table.
pub(crate) const RHOS: [f64; 12] = [1.0, 0.9, 0.8, 0.7, 0.6, 0.5, 0.4, 0.3, 0.2, 0.1, 0.05, 0.02];

/// What a table compares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    /// The load-controlled pull-off.
    PullOff,
    /// The zero-force state.
    ZeroForce,
    /// The state at F̄ = 10.
    Force10,
}

impl Quantity {
    /// All, in the order of the document.
    pub const ALL: [Quantity; 3] = [Quantity::PullOff, Quantity::ZeroForce, Quantity::Force10];

    #[cfg(feature = "cli")]
    fn title(self) -> &'static str {
        match self {
            Quantity::PullOff => "Load-controlled pull-off",
            Quantity::ZeroForce => "Zero force",
            Quantity::Force10 => "F̄ = 10",
        }
    }
}

/// One row: the exact state (or why there is none) and each model's.
pub(crate) struct Row {
    /// ρ.
    pub rho: f64,
    /// The quantity.
    pub quantity: Quantity,
    /// The exact state, or the error's text.
    pub exact: Result<ExactState, Error>,
    /// Each model's state, or the error's text.
    pub models: Vec<(ModelId, Result<State, String>)>,
    /// The states of the compared contour-family members
    /// ([`compared_members`]), by name, or the errors' text.
    pub conformal: Vec<(String, Result<ConformalState, String>)>,
    /// The family on a gap of its own whose row this is (its members
    /// against the exact solution of that gap, [`row_on`]); `None` for
    /// the cylinders' gap.
    pub family: Option<&'static Family>,
}

/// The K of every contour family's members the table compares.
pub(crate) const CONFORMAL_KS: [usize; 4] = [2, 4, 6, 8];

/// The contour-family members the table compares: those with K in
/// [`CONFORMAL_KS`] of every family on the exact solver's gap, in the
/// registry's order.
pub(crate) fn compared_members() -> Vec<Conformal> {
    crate::conformal::members()
        .filter(|m| m.family().on_exact_gap && CONFORMAL_KS.contains(&m.terms()))
        .collect()
}

/// The families on a gap of their own (not the cylinders'), each measured
/// against the exact solution of its gap ([`row_on`]).
pub(crate) fn own_gap_families() -> Vec<&'static Family> {
    crate::conformal::families()
        .iter()
        .copied()
        .filter(|f| crate::conformal::exact_gap(f) != Gap::CYLINDERS)
        .collect()
}

/// The members of `family` a table compares: K in [`CONFORMAL_KS`] and
/// its largest.
fn compared_in(family: &Family) -> Vec<Conformal> {
    let largest = family.members.iter().map(|t| t.terms).max().unwrap_or(0);
    crate::conformal::members()
        .filter(|m| std::ptr::eq(m.family(), family))
        .filter(|m| CONFORMAL_KS.contains(&m.terms()) || m.terms() == largest)
        .collect()
}

/// One row of `family` (on a gap of its own): the exact state of its gap
/// at `rho` and its compared members' states.
pub(crate) fn row_on(family: &'static Family, rho: f64, quantity: Quantity) -> Row {
    let gap = crate::conformal::exact_gap(family);
    let exact = match quantity {
        Quantity::PullOff => pull_off_resolved_on(gap, rho).map(|(s, _)| s),
        Quantity::ZeroForce => at_resolved_searching(gap, rho, Hold::Force(0.0)),
        Quantity::Force10 => at_resolved_searching(gap, rho, Hold::Force(10.0)),
    };
    Row {
        rho,
        quantity,
        exact,
        models: Vec::new(),
        conformal: member_states(&compared_in(family), rho, quantity),
        family: Some(family),
    }
}

fn member_states(
    members: &[Conformal],
    rho: f64,
    quantity: Quantity,
) -> Vec<(String, Result<ConformalState, String>)> {
    members
        .iter()
        .map(|m| {
            let st = match quantity {
                Quantity::PullOff => m.pull_off(rho, FoldCondition::Load).map(|(s, _)| s),
                Quantity::ZeroForce => m.zero_force(rho),
                Quantity::Force10 => m.solve(rho, Hold::Force(10.0)),
            };
            (m.name(), st.map_err(|e| refusal_or_words(m.family(), e)))
        })
        .collect()
}

/// The words of a member's failure for a cell; a ρ below its family's
/// `rho_min` as the refusal and the family's reason alone, so that the
/// reason fits the cell (the command line gives the range with it).
fn refusal_or_words(family: &Family, e: Error) -> String {
    match e {
        Error::Unsupported { name: "rho", .. } if !family.rho_min_why.is_empty() => {
            format!(
                "refused below ρ = {}: {}",
                crate::error::short(family.rho_min),
                family.rho_min_why
            )
        }
        e => e.to_string(),
    }
}

/// Compute one row.
pub(crate) fn row(rho: f64, quantity: Quantity) -> Row {
    let exact = match quantity {
        Quantity::PullOff => pull_off_resolved(rho).map(|(s, _)| s),
        // searched, not refused by the map of where the search finds
        // none: the table says why the search found none
        Quantity::ZeroForce => at_resolved_searching(Gap::cylinders(), rho, Hold::Force(0.0)),
        Quantity::Force10 => at_resolved_searching(Gap::cylinders(), rho, Hold::Force(10.0)),
    };
    let models = ModelId::ALL
        .iter()
        .map(|&m| {
            let st = Contact::with_model(m, rho).and_then(|c| match quantity {
                Quantity::PullOff => c.pull_off_load().map(|p| p.state),
                Quantity::ZeroForce => c.zero_force(),
                Quantity::Force10 => c.at_load(10.0),
            });
            (m, st.map_err(|e| e.to_string()))
        })
        .collect();
    Row {
        rho,
        quantity,
        exact,
        models,
        conformal: member_states(&compared_members(), rho, quantity),
        family: None,
    }
}

/// A relative error in scientific notation with two digits and its sign;
/// below 1e-10 (within the tolerances of the two solves: the exact state's
/// boundary error is below 1e-9) as "< 1e-10" without a sign.
fn sci(model: f64, exact: f64) -> String {
    let e = model / exact - 1.0;
    if e.abs() < 1e-10 {
        "< 1e-10".into()
    } else {
        format!("{e:+.1e}")
    }
}

/// Words for a markdown table cell: a `|` (as in max |dp/dnu - 1|) escaped.
fn cell(words: &str) -> String {
    words.replace('|', "\\|")
}

/// The markdown line of a row's conformal members.
pub(crate) fn render_conformal_row(r: &Row) -> String {
    let mut cells = vec![format!("{}", r.rho)];
    for (_, st) in &r.conformal {
        cells.push(match (&r.exact, st) {
            (Ok(e), Ok(c)) => {
                let first = match r.quantity {
                    Quantity::PullOff => sci(c.force_bar, e.force_bar),
                    _ => sci(c.delta_bar, e.delta_bar),
                };
                format!("{first} / {} / {}", sci(c.a_bar, e.a_bar), sci(c.s, e.s))
            }
            (Err(_), Ok(_)) => "no exact value (see above)".into(),
            (_, Err(why)) => cell(why),
        });
    }
    format!("| {} |", cells.join(" | "))
}

/// A relative error in per cent with three decimals; below 5e-4 % it is
/// printed as 0.000 % without a sign (round-off, which a sign would
/// make look like a result).
fn pct(model: f64, exact: f64) -> String {
    let p = 100.0 * (model / exact - 1.0);
    if p.abs() < 5e-4 {
        "0.000 %".into()
    } else {
        format!("{p:+.3} %")
    }
}

/// The fine-grid boundary error, to one digit; at round-off (below 1e-12)
/// as "< 1e-12".
fn bc(v: f64) -> String {
    if v < 1e-12 {
        "< 1e-12".into()
    } else {
        format!("{v:.0e}")
    }
}

/// The markdown line of a row.
pub(crate) fn render_row(r: &Row) -> String {
    let mut cells = vec![format!("{}", r.rho)];
    match &r.exact {
        Ok(e) => {
            let main = match r.quantity {
                Quantity::PullOff => format!("F̄ = {:.6}", e.force_bar),
                _ => format!("δ̄ = {:.6}", e.delta_bar),
            };
            let route = match e.route {
                crate::exact::Route::PastFold => ", past a fold",
                crate::exact::Route::ContinuedInRho => ", continued in ρ",
                crate::exact::Route::BetweenStored => ", between stored pull-offs",
                crate::exact::Route::FromLargerContact => ", on a larger contact's arm",
                _ => "",
            };
            let form = if e.truncation.arclength > 0 {
                " in arclength"
            } else {
                ""
            };
            cells.push(format!(
                "{main}, ā = {:.6}, s = {:.6} (N = {}{form}, bc {}{route})",
                e.a_bar,
                e.s,
                e.truncation.modes,
                bc(e.bc_error)
            ));
            if has_coatings_column(r) {
                cells.push(load_coatings(e));
            }
            for (_, m) in &r.models {
                cells.push(match m {
                    Ok(st) => {
                        let first = match r.quantity {
                            Quantity::PullOff => pct(st.force_bar, e.force_bar),
                            _ => pct(st.delta_bar, e.delta_bar),
                        };
                        format!("{first} / {} / {}", pct(st.a_bar, e.a_bar), pct(st.s, e.s))
                    }
                    Err(_) => "no state".into(),
                });
            }
        }
        Err(e) => {
            let why = e.to_string();
            let short = match e {
                Error::Unresolved { .. } => cell(&why),
                // the reason in a few words; the story in docs/exact.md
                // (the routes below the fold, continued from the state at
                // the tenth below it and on the arms of larger contacts,
                // have been tried and failed when this comes back)
                Error::PastRhoFold { fold, from, .. } => format!(
                    "no exact value: continued in ρ from its state at ρ = {}, the family turns back at ρ = {} (exact.md)",
                    crate::error::short(*from),
                    crate::error::rounded(*fold)
                ),
                Error::StopsInRho { reached, .. } => format!(
                    "no exact value: followed in ρ, it converges down to ρ = {} only (exact.md)",
                    crate::error::rounded(*reached)
                ),
                _ => format!("no exact value: {}", cell(&why)),
            };
            cells.push(short);
            if has_coatings_column(r) {
                cells.push("—".into());
            }
            for _ in &r.models {
                cells.push("—".into());
            }
        }
    }
    format!("| {} |", cells.join(" | "))
}

/// Which pull-off the rows of the pull-off table measure the models
/// against, and where the loading path's pull-off is the same state (the
/// loading paths measured with `thinjkr exact pull-off --unloading`, listed
/// in docs/exact.md, "The loading path by descent").
#[cfg(feature = "cli")]
const WHICH_PULL_OFF: &str = "**Which pull-off.** Every row measures the models against today's pull-off: the \
     first minimum of F̄ on the near-elliptic arm described above, a state of (2) found without asking how a contact \
     comes to it. The loading path's pull-off is where a contact unloaded under load control from F̄ = 10 (below \
     ρ ≈ 0.165, where no state at F̄ = 10 is found, from the largest stable load on the pull-off's piece), through \
     states that are resolved and stable above the short-wave cutoff 2πh, comes off (exact.md, \"The loading path by \
     descent\"); it depends on the coatings' thinness h/L. It can be today's pull-off only where that state is \
     itself resolved and stable under load; the column \"resolved and stable under load for\" says for which h/L it \
     is (exact.md, \"Coatings for which a state is resolved and stable\"). Measured with h/L = 0.5 (`thinjkr exact pull-off --rho R --unloading \
     --thinness 0.5`), the loading path reaches today's pull-off at ρ = 1, 0.9, 0.8, 0.7, 0.6 and 0.5, passing the \
     bands of modes shorter than the cutoff: there the two pull-offs are one state, and the rows measure against \
     both. Where that column says \"none\" (ρ ≤ 0.4), no contact unloaded through stable states comes to the \
     state the row measures against, so the row compares the models with (2), not with a contact's path; the \
     loading paths measured there end not settled before any pull-off (ρ = 0.4 with h/L = 0.4 to 0.6, ρ = 0.3 from \
     its windows), and below ρ = 0.3 none was followed.\n\n";

/// Whether a row of the models' table has the column of the coatings for
/// which the exact state is a contact (the pull-off table's rows).
fn has_coatings_column(r: &Row) -> bool {
    r.quantity == Quantity::PullOff && r.family.is_none()
}

/// For which coatings (2) gives the state resolved and stable under load
/// above the short-wave cutoff (`exact::undulations::Coatings`), as a cell:
/// only a contact with such coatings can come to it by unloading through
/// stable states.
fn load_coatings(e: &ExactState) -> String {
    match e.coatings_measured().0 {
        None => "not computed".into(),
        Some(c) => match c.load.map(|t| t.bounds()) {
            None => "none".into(),
            Some((Some(from), Some(to))) => format!("{from:.3} ≤ h/L < {to:.3}"),
            Some((None, Some(to))) => format!("h/L < {to:.3}"),
            Some((Some(from), None)) => format!("h/L ≥ {from:.3}"),
            Some((None, None)) => "every h/L".into(),
        },
    }
}

/// The whole document.
#[cfg(feature = "cli")]
pub(crate) fn render(rows: &[Row], doublings: &[Doubling]) -> String {
    let mut o = render_method();
    o.push_str(&render_lowest(rows));
    o.push_str(&render_models(rows));
    o.push_str(&render_conformal(rows));
    for m in crate::slender::Slender::all() {
        o.push_str(&render_slender(m, rows));
    }
    for f in own_gap_families() {
        o.push_str(&render_own_gap(f, rows));
    }
    o.push_str(&render_layer(rows));
    o.push_str(&render_doublings(doublings));
    tidy(&o)
}

/// The page's head: how the exact values are found and how the models
/// are compared with them.
#[cfg(feature = "cli")]
fn render_method() -> String {
    let mut o = String::new();
    o.push_str(
        "<!-- @generated by `thinjkr accuracy --out docs/accuracy.md --reference derive/data/exact_reference.json --figures docs/figures`; do not edit. -->\n\n",
    );
    o.push_str("# How good the models are: the approximate models against the exact solution\n\n");
    o.push_str(
        "Every approximate model of thinjkr replaces the contact contour by an ellipse; the exact solution of the \
         free-boundary problem (2)–(3) ([exact.md](exact.md)) does not. The near-elliptical exact family is \
         not one curve: at each neutral point of the circle, ā³ = 4(n − 1), an imperfect bifurcation of the \
         contour mode n splits it into arms that fold in ā and turn undulated (exact.md, \"Which family\"). \
         The pull-off is the first minimum of F̄ along the arm traced towards smaller ā from the exact state at \
         `conformal:8`'s pull-off ā + 0.03 (the model misses the exact ā by 1e-5 to 1e-3), or, where that start \
         is not found, from the state at ā = 2.6 continued in ρ from the circle; each truncation after the \
         first starts just above the pull-off of the one before; where neither start finds it, the pull-off is \
         followed in ρ in the arclength representation (steps of 0.01, grown to at most 0.02) from the pull-off at \
         the first of ρ + 0.1, ρ + 0.2, … found; \
         below ρ = 0.3 it is followed in ρ in the arclength representation from the stored pull-offs \
         (interpolated between three of one truncation, route `between_stored`, \"between stored pull-offs\" in the row; else from the one nearest above) (\"N = … in arclength\": the contour's series with modes of both signs and θ proportional to \
         arclength; exact.md, \"The arclength representation\" and \"The stored pull-offs\"). A state at given F̄ is solved by Newton at that \
         F̄ from the ellipse with `conformal:8`'s ā, b̄ and δ̄ at the same F̄ (else at the model's ā, then the \
         family traced to the F̄) and, where that finds \
         nothing near the model's state, looked for on the arm through the circle with that F̄ continued in ρ \
         (and once more from beyond a fold the trace meets); where none of these finds it, on the arms beside \
         each gap of `conformal:8`'s screen at fixed ā whose neighbours bracket that F̄, traced through their \
         folds in ā and on along their returning stretches (route `past_fold`, \"past a fold\" in the row: the \
         contour of such a state undulates with the band's mode, as the pull-off's does past the mode-4 band); \
         where that finds none either, and the value lies in no band, it is continued in ρ at that F̄ from the \
         state at the first of ρ + 0.1, ρ + 0.2, … that is found (route `continued_in_rho`, \"continued in ρ\" \
         in the row); where that continuation turns back at a fold in ρ, and ρ lies below the tenth under the \
         fold (ρ = 0.3 for both folds met), the state at that tenth, as found there, continued in ρ at that F̄ \
         (\"continued in ρ\"), and where that turns back too, from its state at the hundredth above that fold \
         on the arm of a larger contact (below) to ρ, or to the tenth under that fold and on from there (at most \
         four rungs); else on the arm of a larger contact: sizes \
         above the state's at that larger ρ continued in ρ at fixed ā, the first that arrives above the value \
         traced down in ā through its folds to it (route `from_larger_contact`, \"on a larger contact's arm\" \
         in the row; exact.md, \"Below the fold\"); where that fails too, the states the screen of `thinjkr exact solve --all` finds at that \
         value (ā from 1 to the larger of 4 and 1.2 times the circle's ā), the one nearest an ellipse; a row says where the arm ended, or down to which ρ the continuation converged and why it \
         stopped, when the value is not reached. The contour modes are escalated (",
    );
    let modes: Vec<String> = crate::exact::default_tries()
        .iter()
        .map(|t| t.modes.to_string())
        .collect();
    o.push_str(&modes.join(", "));
    o.push_str(&format!(
        ", {} quadrature points per mode; after two, the rungs whose boundary error, extrapolated geometrically \
         from the last two, would not converge are skipped) until the boundary error max|∂p̄/∂ν − 1| on the \
         independent fine grid is below 1e-9; only such a state is accepted (given as N and bc; a boundary \
         error above 1e-2 stops the escalation), and each model's error is given relative to it, in per cent: \
         the first quantity / ā / s. A row whose exact value is not resolved or not reached says so instead \
         of a number. Generated by `thinjkr accuracy --out docs/accuracy.md --reference derive/data/exact_reference.json --figures docs/figures` (all cores, a progress bar on a \
         terminal), which also writes the exact pull-offs to derive/data/exact_reference.json (read by the \
         checker's claim `sec6.error.exact`) and draws docs/figures/exact_*.svg from them; \
         `solver/tests/accuracy_table.rs` recomputes the rows ρ = 1 and ρ = 0.9 and the reference's ρ = 0.8 \
         pull-off, and `tests/tests/figures_fresh.rs` redraws the figures from the reference.\n",
        crate::exact::POINTS_PER_MODE
    ));
    o
}

/// Down to which ρ the exact pull-off is resolved.
#[cfg(feature = "cli")]
fn render_lowest(rows: &[Row]) -> String {
    let mut o = String::new();
    let lowest = rows
        .iter()
        .filter(|r| r.quantity == Quantity::PullOff && r.exact.is_ok())
        .map(|r| r.rho)
        .fold(f64::INFINITY, f64::min);
    let smallest = rows.iter().map(|r| r.rho).fold(f64::INFINITY, f64::min);
    let stored = crate::exact::stored::stored()
        .map(|t| crate::error::rounded(t.reached))
        .unwrap_or_else(|| "the last stored pull-off".into());
    o.push_str(&if lowest <= smallest {
        format!(
            "\nThe exact pull-off on this family is resolved at every ρ of the table, down to ρ = {lowest} \
             (followed in ρ in the arclength representation, it converges down to ρ = {stored}; exact.md, \
             \"Convergence under refinement\").\n"
        )
    } else {
        format!(
            "\nThe exact pull-off on this family is resolved down to ρ = {lowest}; below, the pull-off followed \
             in ρ in the arclength representation stops converging (the rows say where; exact.md, \
             \"Convergence under refinement\").\n"
        )
    });
    o
}

/// The models of the ellipse against the exact solution: a table per
/// quantity.
#[cfg(feature = "cli")]
fn render_models(rows: &[Row]) -> String {
    let mut o = String::new();
    let names: Vec<String> = ModelId::ALL.iter().map(|m| format!("`{m}`")).collect();
    for q in Quantity::ALL {
        let first = match q {
            Quantity::PullOff => "F̄",
            _ => "δ̄",
        };
        o.push_str(&format!("\n## {}\n\n", q.title()));
        if q == Quantity::PullOff {
            o.push_str(WHICH_PULL_OFF);
        }
        let coatings = if q == Quantity::PullOff {
            "resolved and stable under load for | "
        } else {
            ""
        };
        o.push_str(&format!(
            "| ρ | exact | {coatings}{} |\n|{}\n",
            names
                .iter()
                .map(|n| format!("{n}: {first} / ā / s"))
                .collect::<Vec<_>>()
                .join(" | "),
            "---|".repeat(2 + usize::from(q == Quantity::PullOff) + names.len())
        ));
        for r in rows
            .iter()
            .filter(|r| r.quantity == q && r.family.is_none())
        {
            o.push_str(&render_row(r));
            o.push('\n');
        }
    }
    o
}

/// The conformal family against the exact solution: its method, and a
/// table per quantity.
#[cfg(feature = "cli")]
fn render_conformal(rows: &[Row]) -> String {
    let mut o = String::new();
    o.push_str(
        "\n## The conformal family against the exact solution\n\n\
         `conformal:K` ([derivation.md](derivation.md), the family `conformal:K`) replaces the ellipse by the image of the \
         unit disk under an odd polynomial map of K terms, solves (2) and p̄ = 0 on the contour exactly and \
         closes (3)₂ by the Ritz method. Its pull-off is the first minimum of F̄ on the branch traced from \
         ā = 2.6 (as for the exact solution) by pseudo-arclength continuation (where the state at ā = 2.6 \
         folds in ρ before the ρ asked for, the pull-off itself is continued in ρ from ρ + 0.05); its \
         states at given F̄ are continued in ρ from the circle. Convergence in K need not be monotone at \
         small ρ (compare the columns). Relative errors (not per cent) of the first quantity / ā / s, \
         \"< 1e-10\" where the difference is within the two solves' tolerances; \
         `docs/figures/conformal_convergence.svg` shows the pull-off's error against K.\n",
    );
    for q in Quantity::ALL {
        let first = match q {
            Quantity::PullOff => "F̄",
            _ => "δ̄",
        };
        o.push_str(&format!("\n### {}\n\n", q.title()));
        let compared = compared_members();
        o.push_str(&format!(
            "| ρ | {} |\n|{}\n",
            compared
                .iter()
                .map(|m| format!("`{}`: {first} / ā / s", m.name()))
                .collect::<Vec<_>>()
                .join(" | "),
            "---|".repeat(1 + compared.len())
        ));
        for r in rows
            .iter()
            .filter(|r| r.quantity == q && r.family.is_none())
        {
            o.push_str(&render_conformal_row(r));
            o.push('\n');
        }
    }
    o
}

/// The section on (2) against the layer of finite thickness: at each
/// pull-off row, the first order in h/L of equal incompressible coatings
/// (`layer::thin`).
#[cfg(feature = "cli")]
fn render_layer(rows: &[Row]) -> String {
    // b/h of equal incompressible coatings (a quadrature; it fails only for
    // compressible ones)
    let shift = crate::layer::Layers::equal(1.0, 0.5)
        .and_then(|l| crate::layer::thin::edge_shift(&l))
        .map_or_else(|e| format!("(not computed: {e})"), |b| format!("{b:.6}"));
    let mut o = format!(
        "\n## (2) against the layer of finite thickness\n\n\
         Every row above measures a model against the exact solution of the thin-layer equation (2); the \
         coatings' finite thickness measures (2) itself ([thickness.md](thickness.md)). For coatings thin \
         against the contact the layer's pull-off is (2)'s exact pull-off moved at first order in h/L: \
         the layer's edge acts on (2) as a line tension Δγ·b, b = {shift} h for two equal incompressible \
         coatings of thickness h, and the pull-off force moves by ½b̄ dP̄/dδ̄ (P̄ the contour's perimeter \
         along (2)'s branch; thickness.md, \"Thin coatings: the first order in h/L\"). Per row: (2)'s \
         pull-off, ½dP̄/dδ̄ there, dF̄/d(h/L), its share of −F̄ ((2)'s relative error per unit h/L), and \
         the h/L at which (2)'s pull-off is 1 % and 5 % off the layer's at first order. On the circle the \
         first order is within 3e-4 of the layer's pull-off while its correction is below 7 %.\n\n\
         | ρ | (2)'s F̄ | ½dP̄/dδ̄ | dF̄/d(h/L) | its share of −F̄ | (2) 1 % off at h/L | 5 % off at h/L |\n\
         |---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        if let Some(line) = render_layer_row(r) {
            o.push_str(&line);
            o.push('\n');
        }
    }
    o
}

/// A pull-off row of [`render_layer`]'s table (none for other rows).
pub(crate) fn render_layer_row(r: &Row) -> Option<String> {
    if r.quantity != Quantity::PullOff || r.family.is_some() {
        return None;
    }
    let cells = match &r.exact {
        Err(_) => "no exact value (see above) | — | — | — | — | —".to_string(),
        Ok(st) => {
            let first = crate::layer::Layers::equal(1.0, 0.5)
                .and_then(|l| crate::layer::thin::first_order_at(&l, st.clone()));
            match first {
                Ok(f) => format!(
                    "{:.6} | {:.6} | {:.5} | {:.4} | {:.5} | {:.4}",
                    st.force_bar,
                    f.force_per_shift,
                    f.force_moved(),
                    f.share(),
                    f.thickness_factor_for_error(0.01),
                    f.thickness_factor_for_error(0.05)
                ),
                Err(e) => format!(
                    "{:.6} | {} | — | — | — | —",
                    st.force_bar,
                    cell(&format!("not computed: {e}"))
                ),
            }
        }
    };
    Some(format!("| {} | {cells} |", r.rho))
}

/// The section on the exact pull-offs' convergence under doubling.
#[cfg(feature = "cli")]
fn render_doublings(doublings: &[Doubling]) -> String {
    let mut o = String::new();
    o.push_str(&format!(
        "\n## Convergence under doubling\n\n\
         Each resolved pull-off above (N contour modes, 8 N quadrature points) is solved again at its ā with \
         2N modes and 16 N points (or, where 2N is more than the escalation tries, its most: {}), from its own contour; the relative changes of F̄ and s are the truncation \
         and quadrature error of the pull-off. (At the pull-off F̄ is stationary in ā, so keeping ā fixed \
         does not hide a change of F̄; s is compared at the same ā.)\n\n\
         | ρ | N | F̄ (N) | F̄ (2N) | change of F̄ | change of s | bc (2N) |\n|---|---|---|---|---|---|---|\n",
        crate::exact::MAX_ESCALATED_MODES
    ));
    for d in doublings {
        o.push_str(&render_doubling(d));
        o.push('\n');
    }
    o
}

/// The slender model's section: its F̄ (pull-off) or δ̄ and its half-width
/// at the centre b̄₀ against the exact state's F̄ or δ̄ and b̄, in per cent,
/// at every ρ with an exact value (the slender contact has no length, so
/// neither ā nor s is compared).
#[cfg(feature = "cli")]
fn render_slender(m: crate::slender::Slender, rows: &[Row]) -> String {
    let c = m.pull_off_load(1.0).map(|p| p.force_bar);
    let mut o = format!(
        "\n## The slender limit against the exact solution\n\n\
         `{name}` ([derivation.md](derivation.md), \"The slender limit\") makes every cross-section of the contact a \
         strip of the one-dimensional (2)–(3) at the local approach δ̄ − X²/2: F̄ = ρ^(1/2) G and δ̄ = ρ^(−1/3) D \
         of the centre's scaled half-width β₀, the pull-off F̄ = {g} ρ^(1/2). Its contact has no finite length \
         (the strip thins as 2/ξ² along X without end), so its F̄ or δ̄ and its half-width at the centre b̄₀ are \
         compared with the exact state's F̄ or δ̄ and b̄ = sā, in per cent; exact.md, \"The slender limit\", says \
         what it is good for.\n",
        name = m.name(),
        g = c.map(|g| format!("{g:.7}")).unwrap_or_else(|e| e.to_string()),
    );
    for q in Quantity::ALL {
        let first = match q {
            Quantity::PullOff => "F̄",
            _ => "δ̄",
        };
        o.push_str(&format!(
            "\n### {}\n\n| ρ | exact: {first} / b̄ | `{}`: {first} / b̄₀ | `{}` against exact: {first} / b̄ |\n|---|---|---|---|\n",
            q.title(),
            m.name(),
            m.name()
        ));
        for r in rows
            .iter()
            .filter(|r| r.quantity == q && r.family.is_none())
        {
            let st = match q {
                Quantity::PullOff => m.pull_off_load(r.rho),
                Quantity::ZeroForce => m.zero_force(r.rho),
                Quantity::Force10 => m.at_load(r.rho, 10.0),
            };
            let mine = |st: &crate::report::SlenderState| match q {
                Quantity::PullOff => st.force_bar,
                _ => st.delta_bar,
            };
            let (exact, model, diff) = match (&r.exact, &st) {
                (Ok(e), Ok(st)) => {
                    let ex = match q {
                        Quantity::PullOff => e.force_bar,
                        _ => e.delta_bar,
                    };
                    (
                        format!("{ex:.6} / {:.6}", e.b_bar),
                        format!("{:.6} / {:.6}", mine(st), st.b_bar),
                        format!("{} / {}", pct(mine(st), ex), pct(st.b_bar, e.b_bar)),
                    )
                }
                (Err(_), Ok(st)) => (
                    "no exact value (see above)".into(),
                    format!("{:.6} / {:.6}", mine(st), st.b_bar),
                    "—".into(),
                ),
                (_, Err(why)) => ("—".into(), cell(&why.to_string()), "—".into()),
            };
            o.push_str(&format!("| {} | {exact} | {model} | {diff} |\n", r.rho));
        }
    }
    o
}

/// The longest table cell kept whole; a longer one (a reason why there is
/// no value) is cut at a word and its full words go to the closing section
/// "Reasons in full", numbered once per distinct text.
#[cfg(feature = "cli")]
const MAX_CELL: usize = 120;

/// The longest line of prose: paragraphs are broken at spaces.
const PROSE_WIDTH: usize = 100;

/// The document with every table cell at most [`MAX_CELL`] characters (the
/// full reasons numbered in a last section) and its prose broken into lines
/// of at most [`PROSE_WIDTH`], so that no line is longer than a table row
/// of short cells.
#[cfg(feature = "cli")]
fn tidy(doc: &str) -> String {
    let mut notes: Vec<String> = Vec::new();
    let mut out = String::new();
    for line in doc.lines() {
        if line.starts_with("| ") {
            let cells: Vec<String> = line
                .trim_start_matches("| ")
                .trim_end_matches(" |")
                .split(" | ")
                .map(|c| {
                    if c.chars().count() <= MAX_CELL {
                        return c.to_string();
                    }
                    let n = match notes.iter().position(|t| t == c) {
                        Some(i) => i + 1,
                        None => {
                            notes.push(c.to_string());
                            notes.len()
                        }
                    };
                    let suffix = format!(" … [{n}](#reasons-in-full)");
                    let keep = MAX_CELL - suffix.chars().count();
                    let mut cut: String = c.chars().take(keep).collect();
                    if let Some(i) = cut.rfind(' ') {
                        cut.truncate(i);
                    }
                    // an escaped bar must not lose its backslash's partner
                    cut = cut.trim_end_matches('\\').to_string();
                    cut + &suffix
                })
                .collect();
            out.push_str(&format!("| {} |\n", cells.join(" | ")));
        } else {
            out.push_str(&wrap(line, PROSE_WIDTH));
            out.push('\n');
        }
    }
    if !notes.is_empty() {
        out.push_str(
            "\n## Reasons in full\n\nThe cells above that end in a number say why in full here.\n",
        );
        for (i, t) in notes.iter().enumerate() {
            out.push('\n');
            out.push_str(&wrap(
                &format!("{}. {}", i + 1, t.replace("\\|", "|")),
                PROSE_WIDTH,
            ));
            out.push('\n');
        }
    }
    out
}

/// `line` broken at spaces into lines of at most `width` characters (a word
/// longer than that stays whole); headings, tables and blank lines as they
/// are.
fn wrap(line: &str, width: usize) -> String {
    if line.chars().count() <= width || line.starts_with('#') || line.starts_with('|') {
        return line.to_string();
    }
    let mut out = String::new();
    let mut current = String::new();
    // a word Markdown would read as the start of a block stays on the line
    let opens_a_block = |w: &str| {
        matches!(w, "-" | "+" | "*" | ">" | "=")
            || w.starts_with('#')
            || w.starts_with('|')
            || (w.ends_with('.') && w[..w.len() - 1].chars().all(|c| c.is_ascii_digit()))
    };
    for word in line.split(' ') {
        let next = current.chars().count() + word.chars().count() + 1;
        if !current.is_empty() && next > width && !opens_a_block(word) {
            out.push_str(&current);
            out.push('\n');
            current.clear();
        }
        if !current.is_empty() {
            current.push(' ');
        }
        current.push_str(word);
    }
    out.push_str(&current);
    out
}

/// The section of a family on a gap of its own: its compared members
/// against the exact solution of that gap, one table per quantity, with
/// the circle's closed form at ρ = 1 where the gap is radial there.
#[cfg(feature = "cli")]
fn render_own_gap(f: &'static Family, rows: &[Row]) -> String {
    let mut o = format!(
        "\n## The family `{}:K` against the exact solution of its own gap\n\n\
         `{}:K` ({}, from `{}`) solves the gap φ̄ = `{}` (μ = 1/ρ), not the cylinders' (1); its members are \
         measured against the exact solution of (2)–(3) with that gap: the same exact solver, given the \
         gap as data (the particular solution P = `{}`), with the family's largest member as its start. \
         Relative errors (not per cent) of the first quantity / ā / s.\n",
        f.name, f.name, f.title, f.source, f.gap, f.particular
    );
    if let Ok(circle) = crate::conformal::exact_gap(f).at(1.0) {
        if circle.is_radial() {
            let (a, force) = crate::exact::branch::circle_pull_off(&circle);
            o.push_str(&format!(
                "\nAt ρ = 1 the gap depends on X² + Y² alone, and the exact states are circles: δ̄ = ⟨φ̄⟩ − 2/ā \
                 (⟨·⟩ the mean over the disk) and F̄ = −πā³/2 + ∫ w(φ̄ − δ̄) dA (exact.md, \"The gap as data\"), \
                 whose minimum, the load-controlled pull-off, is F̄ = {force:.6} at ā = {a:.6}.\n"
            ));
        }
    }
    for q in Quantity::ALL {
        let first = match q {
            Quantity::PullOff => "F̄",
            _ => "δ̄",
        };
        let mine: Vec<&Row> = rows
            .iter()
            .filter(|r| r.quantity == q && r.family.is_some_and(|g| std::ptr::eq(g, f)))
            .collect();
        let Some(r0) = mine.first() else { continue };
        o.push_str(&format!("\n### {} (`{}:K`)\n\n", q.title(), f.name));
        o.push_str(&format!(
            "| ρ | exact | {} |\n|{}\n",
            r0.conformal
                .iter()
                .map(|(name, _)| format!("`{name}`: {first} / ā / s"))
                .collect::<Vec<_>>()
                .join(" | "),
            "---|".repeat(2 + r0.conformal.len())
        ));
        for r in mine {
            let exact = render_row(r);
            let members = render_conformal_row(r);
            // ρ | exact | and the members' cells after their ρ
            let tail = members.split_once(" | ").map_or("|", |(_, t)| t);
            o.push_str(&format!("{} | {tail}\n", exact.trim_end_matches(" |")));
        }
    }
    o
}

/// A resolved pull-off recomputed with twice the modes and points.
pub(crate) struct Doubling {
    /// ρ.
    pub rho: f64,
    /// The pull-off as in the table.
    pub coarse: ExactState,
    /// The state at the same ā with 2N modes and twice the points, or why
    /// there is none.
    pub fine: Result<ExactState, String>,
}

/// The doubling check of a resolved pull-off `coarse` (from [`row`]).
pub(crate) fn doubling(coarse: &ExactState) -> Doubling {
    let t = coarse.truncation;
    // twice the modes and points, or as many as the solver accepts
    let modes = (2 * t.modes).min(crate::exact::MAX_ESCALATED_MODES);
    let fine = Exact::new(
        coarse.rho,
        Truncation {
            modes,
            points: t.points * modes / t.modes,
            arclength: if t.arclength == 0 {
                0
            } else {
                (2 * t.arclength + 1).min(modes)
            },
        },
    )
    .and_then(|ex| {
        ex.keeping_the_speed_of_grooved(&coarse.contour).solve(
            coarse.a_bar,
            &coarse.contour,
            coarse.delta_bar,
        )
    })
    .map_err(|e| e.to_string());
    Doubling {
        rho: coarse.rho,
        coarse: coarse.clone(),
        fine,
    }
}

/// The markdown line of a doubling check.
#[cfg(feature = "cli")]
pub(crate) fn render_doubling(d: &Doubling) -> String {
    let c = &d.coarse;
    match &d.fine {
        Ok(f) => format!(
            "| {} | {} | {:.12} | {:.12} | {:.1e} | {:.1e} | {} |",
            d.rho,
            if f.truncation.modes == 2 * c.truncation.modes {
                c.truncation.modes.to_string()
            } else {
                format!(
                    "{} (refined to {}, the most the solver accepts)",
                    c.truncation.modes, f.truncation.modes
                )
            },
            c.force_bar,
            f.force_bar,
            (f.force_bar / c.force_bar - 1.0).abs(),
            (f.s / c.s - 1.0).abs(),
            bc(f.bc_error)
        ),
        Err(why) => format!(
            "| {} | {} | {:.12} | failed: {} | — | — | — |",
            d.rho,
            c.truncation.modes,
            c.force_bar,
            cell(why)
        ),
    }
}

/// The exact pull-offs the checker of `derive` reads
/// (`derive/data/exact_reference.json`, claim `sec6.error.exact`): derive
/// cannot depend on the solver, so the solver writes this file and a test
/// of the solver recomputes its ρ = 0.8 entry.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct Reference {
    /// How the file was made.
    pub generated_by: String,
    /// One entry per resolved pull-off.
    pub pull_off: Vec<ReferenceState>,
}

/// One exact pull-off in [`Reference`].
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct ReferenceState {
    /// ρ.
    pub rho: f64,
    /// F̄ at pull-off.
    pub force_bar: f64,
    /// ā at pull-off.
    pub a_bar: f64,
    /// s = b̄/ā at pull-off.
    pub s: f64,
    /// δ̄ at pull-off.
    pub delta_bar: f64,
    /// The contour at pull-off.
    pub contour: crate::exact::Contour,
    /// max |∂p̄/∂ν − 1| on the fine grid.
    pub bc_error: f64,
    /// Contour modes used.
    pub modes: usize,
    /// Quadrature points used.
    pub points: usize,
    /// Relative change of F̄ when modes and points are doubled.
    pub doubling_change_force: Option<f64>,
    /// Relative change of s when modes and points are doubled.
    pub doubling_change_s: Option<f64>,
}

/// The reference file's contents from the table's doubling checks.
pub(crate) fn reference(doublings: &[Doubling]) -> Reference {
    Reference {
        generated_by: "thinjkr accuracy --out docs/accuracy.md --reference derive/data/exact_reference.json --figures docs/figures".into(),
        pull_off: doublings
            .iter()
            .map(|d| {
                let c = &d.coarse;
                let fine = d.fine.as_ref().ok();
                ReferenceState {
                    rho: d.rho,
                    force_bar: c.force_bar,
                    a_bar: c.a_bar,
                    s: c.s,
                    delta_bar: c.delta_bar,
                    contour: c.contour.clone(),
                    bc_error: c.bc_error,
                    modes: c.truncation.modes,
                    points: c.truncation.points,
                    doubling_change_force: fine.map(|f| (f.force_bar / c.force_bar - 1.0).abs()),
                    doubling_change_s: fine.map(|f| (f.s / c.s - 1.0).abs()),
                }
            })
            .collect(),
    }
}

/// The band maps as docs/exact.md prints them: a table of the bands (ā
/// interval with the mode at each edge, F̄, δ̄, truncation and boundary
/// error at the edges), then per ρ the model's gaps the exact family
/// crosses or could not settle, the open ends of the screen, and where the
/// exact pull-off (`pull_offs`: (ρ, ā)) lies against the band nearest it.
pub fn band_markdown(maps: &[BandMap], pull_offs: &[(f64, f64)]) -> String {
    let mode = |e: &BandEdge| e.mode.map_or("?".to_string(), |n| format!("cos {n}θ"));
    let mut o = String::from(
        "| ρ | band in ā (mode at lower / upper edge) | F̄ at the edges | δ̄ at the edges | N, bc at the edges |\n|---|---|---|---|---|\n",
    );
    for m in maps {
        for b in &m.bands {
            let (l, u) = (&b.lower, &b.upper);
            o.push_str(&format!(
                "| {} | {:.4} < ā < {:.4} ({} / {}) | {:.4}, {:.4} | {:.4}, {:.4} | {}, {:.0e}; {}, {:.0e} |\n",
                m.rho,
                l.a_bar,
                u.a_bar,
                mode(l),
                mode(u),
                l.force_bar,
                u.force_bar,
                l.delta_bar,
                u.delta_bar,
                l.modes,
                l.bc_error,
                u.modes,
                u.bc_error
            ));
        }
    }
    o.push('\n');
    for m in maps {
        let rho = m.rho;
        for c in &m.crossed {
            o.push_str(&format!(
                "- ρ = {rho}: `{}` has no near-elliptic state between ā = {:.2} and {:.2}, but {}.\n",
                m.screen, c.screened[0], c.screened[1], c.why
            ));
        }
        for c in &m.unsettled {
            o.push_str(&format!(
                "- ρ = {rho}: `{}` has no near-elliptic state between ā = {:.2} and {:.2}, not settled: {}.\n",
                m.screen, c.screened[0], c.screened[1], c.why
            ));
        }
        for e in &m.open_ends {
            o.push_str(&format!(
                "- ρ = {rho}: `{}` has no near-elliptic state from ā = {:.2} to {:.2}, at the end of the range screened (not settled).\n",
                m.screen, e[0], e[1]
            ));
        }
        if !m.probed.is_empty() {
            let each: Vec<String> = m
                .probed
                .iter()
                .map(|p| match p.outcome.as_str() {
                    "band" => format!("n = {} (ā = {:.3}): a band", p.n, p.a_bar),
                    why => format!("n = {} (ā = {:.3}): none, {why}", p.n, p.a_bar),
                })
                .collect();
            o.push_str(&format!(
                "- ρ = {rho}: the circle's neutral points the screen passed without a gap, probed in steps of {PROBE_STEP}: {}.\n",
                each.join("; ")
            ));
        }
        let po = pull_offs.iter().find(|(r, _)| *r == rho).map(|&(_, a)| a);
        let nearest = po.and_then(|a| {
            m.bands
                .iter()
                .min_by(|x, y| {
                    let d = |b: &Band| (b.lower.a_bar - a).abs().min((b.upper.a_bar - a).abs());
                    d(x).total_cmp(&d(y))
                })
                .map(|b| (a, b))
        });
        if let Some((a, b)) = nearest {
            let place = if a > b.upper.a_bar {
                format!(
                    "{:.1e} above the upper edge {:.6}",
                    a - b.upper.a_bar,
                    b.upper.a_bar
                )
            } else if a < b.lower.a_bar {
                format!(
                    "{:.1e} below the lower edge {:.6}",
                    b.lower.a_bar - a,
                    b.lower.a_bar
                )
            } else {
                format!(
                    "inside it ({:.6} < ā < {:.6})",
                    b.lower.a_bar, b.upper.a_bar
                )
            };
            o.push_str(&format!(
                "- ρ = {rho}: the exact pull-off's ā, {a:.6}, is {place} of the band nearest it.\n"
            ));
        }
    }
    // the notes as prose of at most PROSE_WIDTH characters a line
    o.lines().map(|l| wrap(l, PROSE_WIDTH) + "\n").collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A member asked below its family's `rho_min` stands in a cell as the
    /// refusal with the family's reason, whole (within [`MAX_CELL`], and
    /// four of them within a line of the docs);
    /// other failures as their words.
    #[cfg(feature = "cli")]
    #[test]
    fn a_refused_rho_is_a_cell_with_the_reason_whole() {
        for m in compared_members() {
            let f = m.family();
            let e = m
                .pull_off(f.rho_min / 2.0, FoldCondition::Load)
                .unwrap_err();
            let words = refusal_or_words(f, e);
            if f.rho_min_why.is_empty() {
                assert!(words.contains("outside the supported range"), "{words}");
            } else {
                // whole in its cell, and a row of four such cells within
                // the docs' 400 characters a line
                let row = format!("| 0.02 | {} |", vec![cell(&words); 4].join(" | "));
                assert!(
                    words.starts_with("refused below ρ = ")
                        && words.ends_with(f.rho_min_why)
                        && cell(&words).chars().count() <= MAX_CELL
                        && row.chars().count() <= 400,
                    "{words}"
                );
            }
        }
        let f = compared_members()[0].family();
        assert_eq!(
            refusal_or_words(f, Error::NoState("x".into())),
            Error::NoState("x".into()).to_string()
        );
    }

    /// The paragraph "Which pull-off" says what the pull-off table's column
    /// of coatings shows: the rows that say "none" are those at or below the
    /// ρ it names, and at each ρ where it says the loading path with
    /// h/L = 0.5 reaches today's pull-off, 0.5 lies in that row's range
    /// (only a state resolved and stable under load can be reached so).
    #[cfg(feature = "cli")]
    #[test]
    fn which_pull_off_agrees_with_the_column_of_coatings() {
        let doc =
            std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/accuracy.md"))
                .expect("docs/accuracy.md exists");
        let after = |text: &'static str, from: &str, to: &str| -> &'static str {
            let start = text.find(from).unwrap_or_else(|| panic!("{from}")) + from.len();
            &text[start..start + text[start..].find(to).unwrap()]
        };
        let none_from: f64 = after(WHICH_PULL_OFF, "(ρ ≤ ", ")").parse().unwrap();
        let reached: Vec<f64> = after(WHICH_PULL_OFF, "today's pull-off at ρ = ", ", passing")
            .split([',', ' '])
            .filter_map(|w| w.parse().ok())
            .collect();
        assert_eq!(reached.len(), 6, "{reached:?}");
        let header = doc
            .lines()
            .position(|l| l.starts_with("| ρ | exact | resolved and stable under load for |"))
            .expect("the pull-off table");
        let rows: Vec<(f64, String)> = doc
            .lines()
            .skip(header + 2)
            .take_while(|l| l.starts_with('|'))
            .map(|l| {
                let c: Vec<&str> = l.split('|').map(str::trim).collect();
                (c[1].parse().unwrap(), c[3].to_string())
            })
            .collect();
        assert!(rows.len() >= 10, "{rows:?}");
        // whether h lies in a range "a ≤ h/L < b", "h/L ≥ a" or "h/L < b"
        let includes = |range: &str, h: f64| -> bool {
            let num = |w: &str| w.parse::<f64>().ok();
            let words: Vec<&str> = range.split(' ').collect();
            let lower = match words.as_slice() {
                ["h/L", "≥", a] => num(a),
                [a, "≤", ..] => num(a),
                _ => None,
            };
            let upper = words
                .iter()
                .position(|w| *w == "<")
                .and_then(|i| num(words[i + 1]));
            range != "none" && lower.is_none_or(|a| a <= h) && upper.is_none_or(|b| h < b)
        };
        for (rho, range) in &rows {
            assert_eq!(range == "none", *rho <= none_from, "ρ = {rho}: {range}");
            if reached.contains(rho) {
                assert!(includes(range, 0.5), "ρ = {rho}: {range}");
            }
        }
    }

    /// Prints the section of (2) against the layer as `thinjkr accuracy`
    /// writes it (the pull-offs alone: minutes less than the whole table).
    #[test]
    #[cfg(feature = "cli")]
    #[ignore = "exploration: prints docs/accuracy.md's section on (2) against the layer"]
    fn explore_the_layer_section() {
        let rows: Vec<Row> = RHOS
            .iter()
            .map(|&rho| Row {
                rho,
                quantity: Quantity::PullOff,
                exact: pull_off_resolved(rho).map(|(s, _)| s),
                models: Vec::new(),
                conformal: Vec::new(),
                family: None,
            })
            .collect();
        print!("{}", tidy(&render_layer(&rows)));
    }

    /// `docs/accuracy.md` is fresh: the rows ρ = 1 and ρ = 0.9 of its three
    /// tables (pull-off, zero force, F̄ = 10), recomputed here, are the lines
    /// the file holds (the full table takes minutes: `thinjkr accuracy`).
    #[test]
    fn accuracy_table_rows_are_fresh() {
        let doc =
            std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/accuracy.md"))
                .expect("docs/accuracy.md exists");
        let lines: Vec<&str> = doc.lines().collect();
        for rho in [1.0, 0.9] {
            for q in Quantity::ALL {
                let r = row(rho, q);
                let layer = render_layer_row(&r);
                for line in [render_row(&r), render_conformal_row(&r)]
                    .into_iter()
                    .chain(layer)
                {
                    assert!(
                        lines.contains(&line.as_str()),
                        "docs/accuracy.md is stale (run `thinjkr accuracy --out docs/accuracy.md`): no line\n{line}"
                    );
                }
            }
        }
    }
}
