//! The command line for the contour families: a state printed for a person
//! (solved through the model layer, `crate::registry`), and the pull-off
//! under either control with the folds it passed, for a person or as JSON.
//!
//! Owns: the printing of contour-family states. May use: `crate::conformal`,
//! `crate::report`, `crate::fold`, `crate::error`, `crate::cli` (`output`).

use crate::conformal::{Conformal, ConformalState};
use crate::fold::FoldCondition;
use crate::report::Passed;

fn modes(st: &ConformalState) -> String {
    if st.unstable_modes.is_empty() {
        String::new()
    } else {
        let m: Vec<String> = st
            .unstable_modes
            .iter()
            .map(|n| format!("cos {n}θ"))
            .collect();
        format!(
            "; unstable contour modes under displacement control: {}",
            m.join(", ")
        )
    }
}

/// One state for a person.
pub(crate) fn show(label: &str, st: &ConformalState) -> crate::Result<()> {
    let word = |b: bool| if b { "stable" } else { "unstable" };
    outln!(
        "{label}: model {}, a = {}, b = {}, s = {}, delta = {}, force = {}, max |dp/dnu - 1| on the contour = {:.1e} [displacement control: {}, load control: {}{}]",
        st.model,
        crate::cli::output::num(st.a_bar),
        crate::cli::output::num(st.b_bar),
        crate::cli::output::num(st.s),
        crate::cli::output::num(st.delta_bar),
        crate::cli::output::num(st.force_bar),
        st.bc_defect,
        word(st.stable_displacement),
        word(st.stable_load),
        modes(st)
    );
    let c: Vec<String> = st.coefficients.iter().map(|c| format!("{c:.6e}")).collect();
    outln!("  map coefficients c1..c{}: {}", c.len(), c.join(", "));
    for w in &st.warnings {
        outln!("  warning: {w}");
    }
    Ok(())
}

/// `pull-off --model family:K` in words: the state, where its branch was
/// traced from and what ends it, and the folds in ā it passed.
pub(crate) fn show_pull_off(
    m: &Conformal,
    st: &ConformalState,
    control: FoldCondition,
    passed: &[Passed],
) -> crate::Result<()> {
    show("pull-off", st)?;
    let what = match control {
        FoldCondition::Load => "the first minimum of the force",
        _ => "the first extremum of the approach",
    };
    outln!(
        "  end point: {what} along the branch traced from a = {} (pseudo-arclength in (c, delta))",
        m.family().trace_start_a
    );
    for p in passed {
        if let Passed::SizeFold {
            a_bar,
            force_bar: Some(force_bar),
        } = p
        {
            outln!("  passed a fold in a at a = {a_bar:.4}, force = {force_bar:.6}");
        }
    }
    Ok(())
}
