//! Every model a user can choose by name, in one place: the generated models
//! of the ellipse ([`ModelId`]), every member of every contour family in the
//! generated registry (`crate::generated::registry`, written by `generate`
//! from `derive/families/*.toml`), and `exact`. The command line's parsing,
//! its help text and `thinjkr models`, and the Python package's model list
//! are built from here, so that a family added as a data file appears in all
//! of them without an edit.
//!
//! Owns: [`Choice`], [`Entry`], [`parse`], [`entries`], [`help`]. May use:
//! `generated` (the ellipse models), `conformal` (the families), `contact`
//! (the ellipse models' smallest ρ), `report` (the entry's shape).

use crate::conformal::{families, Conformal};
use crate::ModelId;

/// A model chosen by name.
#[derive(Clone, Copy, Debug)]
pub enum Choice {
    /// A generated model of the ellipse.
    Ellipse(ModelId),
    /// A member of a contour family.
    Contour(Conformal),
    /// The exact solution of the free-boundary problem (2)–(3).
    Exact,
}

/// What a model is, for `thinjkr models` and the Python package.
pub type Entry = crate::report::ModelEntry;

/// The name of the exact solution.
pub const EXACT: &str = "exact";

/// What `exact` is, in a line.
const EXACT_TITLE: &str =
    "the free-boundary problem (2)-(3) itself (boundary integral equation on a contour series)";

/// The model named `name`, or why there is none (naming what there is).
pub fn parse(name: &str) -> Result<Choice, String> {
    if name == EXACT {
        return Ok(Choice::Exact);
    }
    if let Some(member) = Conformal::parse(name) {
        return member.map(Choice::Contour);
    }
    name.parse().map(Choice::Ellipse).map_err(|_: String| {
        let mut why = format!(
            "unknown model '{}' (allowed: {})",
            crate::batch::quote_start(name).trim_matches('"'),
            names()
        );
        for p in crate::conformal::load_problems() {
            why.push_str("; ");
            why.push_str(p);
        }
        why
    })
}

/// Every model's name in a line: `max, apexes, energy, apex45,
/// conformal:K with K = 1 ..= 8, exact`.
pub fn names() -> String {
    let mut out: Vec<String> = ModelId::ALL.iter().map(|m| m.name().to_string()).collect();
    for f in families() {
        out.push(format!("{}:K with K = {}", f.name, member_range(f)));
    }
    out.push(EXACT.into());
    out.join(", ")
}

/// The help text of `--model`; `exact` is left out where the command has
/// no exact counterpart (`extra` then says so, or adds a word).
pub fn help(with_exact: bool, extra: &str) -> String {
    let ellipse: Vec<&str> = ModelId::ALL.iter().map(|m| m.name()).collect();
    let mut parts = vec![format!(
        "Model: {} (the paper's, default), {}",
        ellipse[0],
        ellipse[1..].join(", ")
    )];
    for f in families() {
        let exact = if f.on_exact_gap {
            " converging to the exact solution"
        } else {
            ""
        };
        parts.push(format!(
            "{}:K (K = {}, a contour family{exact})",
            f.name,
            member_range(f)
        ));
    }
    if with_exact {
        parts.push("or exact (the free-boundary problem itself)".into());
    }
    format!("{}{extra}; `thinjkr models` lists them.", parts.join(", "))
}

/// "1 ..= 8".
fn member_range(f: &crate::conformal::Family) -> String {
    let ks = f.members.iter().map(|t| t.terms);
    format!(
        "{} ..= {}",
        ks.clone().min().unwrap_or(0),
        ks.max().unwrap_or(0)
    )
}

/// Every model, in the order `thinjkr models` lists them: the models of the
/// ellipse, the members of each contour family in the registry's order,
/// and `exact`.
pub fn entries() -> Vec<Entry> {
    let controls = || vec!["delta".to_string(), "force".into(), "a".into()];
    let mut out: Vec<Entry> = ModelId::ALL
        .iter()
        .map(|m| Entry {
            name: m.name().to_string(),
            description: m.model().info().title.to_string(),
            family: None,
            unknowns: Some(2),
            rho_min: crate::contact::RHO_MIN,
            controls: controls(),
        })
        .collect();
    out.extend(crate::conformal::members().map(|c| Entry {
        name: c.name(),
        description: c.family().title.to_string(),
        family: Some(c.family().name.to_string()),
        unknowns: Some(c.terms() + 1),
        rho_min: c.family().rho_min,
        controls: controls(),
    }));
    out.push(Entry {
        name: EXACT.into(),
        description: EXACT_TITLE.into(),
        family: None,
        unknowns: None,
        rho_min: crate::contact::RHO_MIN,
        controls: vec!["delta".into(), "force".into()],
    });
    out
}
