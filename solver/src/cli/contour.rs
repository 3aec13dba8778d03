//! The command line for the contour families: a state printed for a person
//! (solved through the model layer, `crate::registry`), and the pull-off
//! under either control with the folds it passed, for a person or as JSON.
//!
//! Owns: the printing of contour-family states. May use: `crate::conformal`, `crate::cutoff`,
//! `crate::report`, `crate::fold`, `crate::error`, `crate::cli` (`output`).

use crate::conformal::{Conformal, ConformalState};
use crate::fold::FoldCondition;
use crate::report::Passed;

/// The unstable contour modes under each control, those shorter than the
/// short-wave cutoff marked as not resolved.
fn modes(st: &ConformalState) -> String {
    let list = |v: &[u32]| -> String {
        v.iter()
            .map(|&n| {
                if n == 0 {
                    "the size".to_string()
                } else if st.cutoff.resolves(st.wavelength(n)) {
                    format!("cos {n}θ")
                } else {
                    format!("cos {n}θ (shorter than the cutoff)")
                }
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut out = String::new();
    if !st.unstable_modes.is_empty() {
        out.push_str(&format!(
            "; unstable contour modes under displacement control: {}",
            list(&st.unstable_modes)
        ));
    }
    if !st.unstable_modes_load.is_empty() {
        out.push_str(&format!(
            "; {} load control: {}",
            if st.unstable_modes.is_empty() {
                "unstable contour modes under"
            } else {
                "under"
            },
            list(&st.unstable_modes_load)
        ));
    }
    for (control, v) in [
        ("displacement", &st.neutral_modes),
        ("load", &st.neutral_modes_load),
    ] {
        if !v.is_empty() {
            out.push_str(&format!(
                "; neutral under {control} control (a zero eigenvalue: a fold or bifurcation of that control): {}",
                list(v)
            ));
        }
    }
    out
}

/// The verdict under one control in a word: unstable, neutral (no
/// resolved mode unstable, one neutral: the limit of stable states), or
/// stable.
pub(crate) fn verdict(st: &ConformalState, stable: bool, neutral: &[u32]) -> &'static str {
    if !stable {
        "unstable"
    } else if neutral
        .iter()
        .any(|&n| st.cutoff.resolves(st.wavelength(n)))
    {
        "neutral"
    } else {
        "stable"
    }
}

/// One state for a person.
pub(crate) fn show(label: &str, st: &ConformalState) -> crate::Result<()> {
    outln!(
        "{label}: model {}, a = {}, b = {}, s = {}, delta = {}, force = {}, max |dp/dnu - 1| on the contour = {:.1e} [above the short-wave cutoff {:.3} (2π h/L, h/L = {}): displacement control: {}, load control: {}{}]",
        st.model,
        crate::cli::output::num(st.a_bar),
        crate::cli::output::num(st.b_bar),
        crate::cli::output::num(st.s),
        crate::cli::output::num(st.delta_bar),
        crate::cli::output::num(st.force_bar),
        st.bc_defect,
        st.cutoff.wavelength,
        crate::error::short(st.cutoff.thinness),
        verdict(st, st.stable_displacement, &st.neutral_modes),
        verdict(st, st.stable_load, &st.neutral_modes_load),
        modes(st)
    );
    if !crate::cli::output::explain() {
        // the brief text: one more line at most, its first warning, else the
        // arm where it is not the circle's
        match (st.warnings.split_first(), arm_words(st)) {
            (Some((w, [])), _) => outln!("  warning: {w}"),
            (Some((w, more)), _) => outln!("  warning: {w} ({} more: --explain)", more.len()),
            (None, Some(arm)) if !matches!(st.folds_crossed.as_deref(), Some([])) => {
                outln!("  arm: {arm}")
            }
            (None, _) => {}
        }
        return Ok(());
    }
    let c: Vec<String> = st.coefficients.iter().map(|c| format!("{c:.6e}")).collect();
    outln!("  map coefficients c1..c{}: {}", c.len(), c.join(", "));
    // how much of its shape the thin-layer model resolves, as for an
    // exact state (`exact::undulations`)
    if let Some(m) = crate::conformal::members().find(|m| m.name() == st.model) {
        outln!(
            "  shape: {}",
            m.short_waves(&st.coefficients, st.cutoff).words(st.cutoff)
        );
    }
    if let Some(arm) = arm_words(st) {
        outln!("  arm: {arm}");
    }
    for w in &st.warnings {
        outln!("  warning: {w}");
    }
    Ok(())
}

/// Which arm a state continued in ρ lies on, in words; `None` where it
/// was not continued in ρ.
fn arm_words(st: &ConformalState) -> Option<String> {
    match st.folds_crossed.as_deref()? {
        [] => Some("continued in rho from the circle at this control, on the circle's arm".into()),
        folds => {
            let at: Vec<String> = folds.iter().map(|r| crate::error::short(*r)).collect();
            Some(format!(
                "continued in rho from the circle at this control, past {} of its arm (the Jacobian changed sign at rho = {}): another arm than the circle's",
                if folds.len() == 1 { "a fold" } else { "folds" },
                at.join(", ")
            ))
        }
    }
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
    if control == FoldCondition::Displacement && crate::conformal::is_the_circle_end(st) {
        outln!("  end point: the circle loses stability to cos 2θ at a^3 = 4 (the limit of the first extrema of delta at rho < 1, which move as √(1 − rho))");
        return Ok(());
    }
    let what = match control {
        FoldCondition::Load => "the first minimum of the force",
        _ => "the first extremum of the approach",
    };
    outln!(
        "  end point: {what} along the branch traced from a = {} (pseudo-arclength in (c, delta))",
        crate::error::short(m.trace_start())
    );
    if !crate::cli::output::explain() {
        return Ok(());
    }
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
