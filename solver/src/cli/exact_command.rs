//! `thinjkr exact …` and `--model exact`: the exact solution of the
//! free-boundary problem (2)–(3) at the command line, every approximate
//! model's answer printed beside it.
//!
//! Owns: [`ExactCommand`], the exact printers. May use: `generated` (`ModelId`), `batch` (an ellipse model at a control), `control`, `crate::exact`,
//! `crate::Contact`, `crate::model` (the ellipse models beside an exact
//! state), `crate::report`, `crate::fold`, `crate::error`, `crate::cutoff`,
//! `crate::studies` (the loading path, the unloading trace, the reach), `crate::cli` (`output`, `files`),
//! `crate::conformal` (a family's gap and members, `--gap`), `crate::registry` (`Choice`: `--gap`
//! is for `--model exact` alone).

use crate::control::Hold;
use crate::exact::stability::UnstableMode;
use crate::exact::{ExactState, Gap, Truncation};
use crate::report::{AnyState, Document, ModelAnswer, Passed};
use crate::{Contact, Error, ModelId, Result};
use clap::{Args, Subcommand};

/// The truncation of the exact solver, and the cutoff its stability is
/// judged by.
#[derive(Args, Clone, Debug, Default)]
pub(crate) struct Discretisation {
    /// The coatings' thinness h/L (h the thicker coating, L the length unit of (17)): contour modes shorter
    /// than 2π h/L are not resolved by the thin-layer equation (2), and the stability verdicts count only the
    /// longer ones (default 0.1; see docs/exact.md, "The short-wave cutoff").
    #[arg(long)]
    pub thinness: Option<f64>,
    /// Contour modes N (the contour series' length, 1..=96; the answer is given when its boundary error is
    /// below 1e-5, with that error); default: escalated from 12 to 96 modes until the boundary error is
    /// below 1e-9, and only such an answer is given. --modes takes the exterior-map series of N modes alone;
    /// where that series does not resolve the contour (the pull-off below rho = 0.3, states at a force or an
    /// approach below about 0.34), the default goes on to the
    /// arclength representation ("N modes of each sign" in its answer), which --modes does not choose.
    #[arg(long)]
    pub modes: Option<usize>,
    /// Quadrature points on the contour (default 8 N; without --modes, the escalation goes as far as these
    /// points allow: at least 4 N + 8 for N modes).
    #[arg(long)]
    pub points: Option<usize>,
}

impl Discretisation {
    /// The short-wave cutoff of `--thinness`, else the default's.
    fn cutoff(&self) -> Result<crate::cutoff::Cutoff> {
        match self.thinness {
            Some(t) => crate::cutoff::Cutoff::for_thinness(t),
            None => Ok(crate::cutoff::Cutoff::default()),
        }
    }

    /// An exact state's stability judged under this cutoff.
    fn judged(&self, st: ExactState) -> Result<ExactState> {
        Ok(st.judged(self.cutoff()?))
    }

    /// The truncations asked for, or none: the default escalation (and the
    /// continuation in ρ from a larger ρ where no start finds the answer).
    fn asked(&self) -> Result<Option<Vec<Truncation>>> {
        match (self.modes, self.points) {
            (None, None) => Ok(None),
            _ => self.tries().map(Some),
        }
    }

    /// The truncations to try, in order.
    fn tries(&self) -> Result<Vec<Truncation>> {
        let modes = match self.modes {
            Some(m) if !(1..=crate::exact::MAX_USER_MODES).contains(&m) => {
                return Err(Error::OutOfRange {
                    name: "modes",
                    value: m as f64,
                    range: format!("1 ..= {}", crate::exact::MAX_USER_MODES).into(),
                })
            }
            Some(m) => vec![m],
            // the escalation's rungs, as far as the points given allow
            None => crate::exact::default_tries()
                .iter()
                .map(|t| t.modes)
                .filter(|&m| self.points.is_none_or(|p| p >= 4 * m + 8))
                .collect(),
        };
        if modes.is_empty() {
            return Err(Error::OutOfRange {
                name: "points",
                value: self.points.unwrap_or(0) as f64,
                range: format!(
                    "at least {} for the escalation's first rung of {} modes (4 · modes + 8), or give --modes",
                    4 * crate::exact::default_tries()[0].modes + 8,
                    crate::exact::default_tries()[0].modes
                )
                .into(),
            });
        }
        Ok(modes
            .into_iter()
            .map(|m| Truncation {
                modes: m,
                points: self.points.unwrap_or(crate::exact::POINTS_PER_MODE * m),
                arclength: 0,
            })
            .collect())
    }
}

/// The gap of the exact problem (issue 73): `--gap NAME`.
#[derive(Args, Clone, Debug, Default)]
pub(crate) struct GapChoice {
    /// The gap the exact problem solves: `cylinders`, the paper's (1) (the default), or the name of a contour
    /// family, built in or loaded through THINJKR_FAMILIES, whose own gap it then solves (`thinjkr models`
    /// lists the families); its members' answers are printed beside the exact one.
    #[arg(long, value_name = "NAME")]
    pub gap: Option<String>,
}

impl GapChoice {
    /// The gap asked for, with its family where it is a gap of its own (a
    /// family on the cylinders' gap names the default).
    fn gap(&self) -> Result<(Gap, Option<&'static crate::conformal::Family>)> {
        match self.gap.as_deref() {
            None => Ok((Gap::cylinders(), None)),
            Some(name) => crate::conformal::gap_named(name),
        }
    }

    /// The name asked for (`cylinders` by default).
    fn name(&self) -> &str {
        self.gap.as_deref().unwrap_or("cylinders")
    }

    /// A usage error where `--gap` is given with a model other than
    /// `exact` (each model solves its own gap).
    pub(crate) fn only_for_exact(&self, model: &crate::registry::Choice) -> Result<()> {
        match (&self.gap, model) {
            (None, _) | (Some(_), crate::registry::Choice::Exact) => Ok(()),
            (Some(name), _) => Err(Error::Usage(format!(
                "--gap {name}: only --model exact (and `thinjkr exact …`) solves a gap by name; every other model solves its own"
            ))),
        }
    }

    /// A typed refusal where `command` solves the cylinders' gap alone.
    pub(crate) fn refused_by(&self, command: &str) -> Result<()> {
        match (self.gap.as_deref(), self.gap()?) {
            (_, (_, None)) => Ok(()),
            (name, (_, Some(_))) => Err(Error::Usage(format!(
                "--gap {}: `thinjkr exact {command}` solves the cylinders' gap (1) alone; `exact pull-off`, `solve` and `zero-force` take --gap",
                name.unwrap_or_default()
            ))),
        }
    }
}

/// The members of `family`, in the registry's order.
fn members_of(family: &'static crate::conformal::Family) -> Vec<crate::conformal::Conformal> {
    crate::conformal::members()
        .filter(|m| std::ptr::eq(m.family(), family))
        .collect()
}

/// Beside an exact answer: the ellipse models on the cylinders' gap
/// (`family` none), else the family's members on its own gap, each
/// answered by `ellipse` or `member`: its name, [ā, s, δ̄, F̄] or its
/// error, and its answer for the JSON.
#[allow(clippy::type_complexity)]
fn models_beside(
    family: Option<&'static crate::conformal::Family>,
    ellipse: impl Fn(ModelId) -> Result<crate::contact::State>,
    member: impl Fn(&crate::conformal::Conformal) -> Result<crate::conformal::ConformalState>,
) -> Vec<(String, Result<[f64; 4]>, ModelAnswer)> {
    let values = |a: f64, s: f64, delta: f64, force: f64| [a, s, delta, force];
    match family {
        None => ModelId::ALL
            .iter()
            .map(|&m| {
                let r = ellipse(m);
                let v = r
                    .as_ref()
                    .map(|p| values(p.a_bar, p.s, p.delta_bar, p.force_bar));
                (
                    m.name().to_string(),
                    v.map_err(Clone::clone),
                    ModelAnswer::new(m.name(), &r),
                )
            })
            .collect(),
        Some(f) => members_of(f)
            .iter()
            .map(|m| {
                let r = member(m);
                let v = r
                    .as_ref()
                    .map(|p| values(p.a_bar, p.s, p.delta_bar, p.force_bar));
                (
                    m.name(),
                    v.map_err(Clone::clone),
                    ModelAnswer::member(&m.name(), &r),
                )
            })
            .collect(),
    }
}

/// `thinjkr exact …`.
#[derive(Subcommand, Clone, Debug)]
pub(crate) enum ExactCommand {
    /// The exact load-controlled pull-off, with every model's beside it.
    #[command(
        name = "pull-off",
        after_help = "Example:\n  thinjkr exact pull-off --rho 0.8 --modes 8"
    )]
    PullOff {
        /// Radii ratio ρ in (0, 1].
        #[arg(long, allow_hyphen_values = true)]
        rho: f64,
        #[command(flatten)]
        discretisation: Discretisation,
        /// Also trace the unloading path: the family from its state at F̄ = 10 towards smaller ā to its first
        /// minimum of F̄, whether that is this pull-off, and the thinness h/L below which a state on the way is
        /// unstable above the short-wave cutoff; and the loading path by descent: the load lowered from F̄ = 10,
        /// where the contact loses its state and whether it comes off there (seconds at ρ ≥ 0.8, minutes below:
        /// up to 7 at ρ = 0.3). Where no state at F̄ = 10 is found (below ρ ≈ 0.165; the search takes about
        /// 19 min at ρ = 0.1), both start from the largest load on the pull-off's piece at which its state is
        /// resolved and stable under load above the cutoff, and say so; where there is none, neither starts.
        /// Prints every line, as --explain does.
        #[arg(long)]
        unloading: bool,
        /// The pull-off by its second route, which checks the first: Newton from the own contour of the largest
        /// member of the family that seeds the gap's exact solver (conformal:8 on the cylinders'), at that
        /// member's pull-off, then the least force along that arm, with the arclength representation's modes
        /// raised until the boundary error is below 1e-9 (no walk in the gap or in ρ; the route
        /// `from_model_contour`).
        #[arg(long, conflicts_with_all = ["unloading", "modes", "points"])]
        from_model_contour: bool,
        #[command(flatten)]
        gap: GapChoice,
        /// Print JSON.
        #[arg(long)]
        json: bool,
    },
    /// The exact state at given δ̄ or F̄ (started from conformal:8's state at that value, else on the near-elliptical arm through the circle with that value, else past the folds of the arms beside a band, else continued in ρ); with --all, every near-elliptic exact state at that value.
    #[command(
        after_help = "Examples:\n  thinjkr exact solve --rho 0.8 --delta 2\n  thinjkr exact solve --rho 0.8 --force -4 --all",
        group(clap::ArgGroup::new("control").required(true).args(["delta", "force"]))
    )]
    Solve {
        /// Radii ratio ρ in (0, 1].
        #[arg(long, allow_hyphen_values = true)]
        rho: f64,
        /// Approach δ̄.
        #[arg(long, allow_hyphen_values = true)]
        delta: Option<f64>,
        /// Force F̄.
        #[arg(long, allow_hyphen_values = true)]
        force: Option<f64>,
        /// Every near-elliptic exact state at that value with ā in [--from, --to]: where conformal:8's states at fixed ā (steps of 0.01) cross it, and on the arms beside its gaps traced past their folds, each solved exactly.
        #[arg(long)]
        all: bool,
        /// Smallest ā screened with --all.
        #[arg(
            long,
            default_value_t = 1.0,
            allow_hyphen_values = true,
            requires = "all"
        )]
        from: f64,
        /// Largest ā screened with --all (at most from + 9.99; default: 4, or 1.2 times the circle's ā at that value where larger).
        #[arg(long, allow_hyphen_values = true, requires = "all")]
        to: Option<f64>,
        #[command(flatten)]
        discretisation: Discretisation,
        #[command(flatten)]
        gap: GapChoice,
        /// Print JSON.
        #[arg(long)]
        json: bool,
    },
    /// The band map: the intervals of contact size ā where no near-elliptic exact state exists, with the contour mode responsible and F̄, δ̄ at both edges (screened by conformal:8 in steps of 0.01, each gap settled by the exact family's folds; the circle's neutral points ā³ = 4(n − 1) the screen passes are probed in steps of 0.002).
    #[command(after_help = "Example:\n  thinjkr exact bands --rho 0.8")]
    Bands {
        /// Radii ratio ρ in (0, 1).
        #[arg(long, allow_hyphen_values = true)]
        rho: f64,
        /// Smallest ā screened.
        #[arg(long, default_value_t = 2.0, allow_hyphen_values = true)]
        from: f64,
        /// Largest ā screened (at most from + 9.99).
        #[arg(long, default_value_t = 4.0, allow_hyphen_values = true)]
        to: f64,
        #[command(flatten)]
        gap: GapChoice,
        /// Print JSON.
        #[arg(long)]
        json: bool,
    },
    /// The reach of each contact size: the near-elliptic exact state of half-width ā followed in ρ at fixed ā from the circle (ρ = 0.98) down to where ρ turns back (located) or to ρ = 0.02; at any ρ the sizes whose reach lies above it are its bands (a map at every ρ, also below 0.4; 128 modes of each sign, a few seconds per size).
    #[command(after_help = "Example:\n  thinjkr exact reach --from 3 --to 3.2 --step 0.05")]
    Reach {
        /// Smallest ā.
        #[arg(long, default_value_t = 2.0, allow_hyphen_values = true)]
        from: f64,
        /// Largest ā (at most 10, and at most 1000 sizes).
        #[arg(long, default_value_t = 4.0, allow_hyphen_values = true)]
        to: f64,
        /// The step in ā.
        #[arg(long, default_value_t = 0.01, allow_hyphen_values = true)]
        step: f64,
        /// Settle the windows at this ρ in (0.02, 0.98): from the state at ρ of each window's size with the smallest reach, the family at ρ traced in ā both ways to its folds (band edges) or to where 128 modes stop resolving it.
        #[arg(long, allow_hyphen_values = true)]
        windows_at: Option<f64>,
        /// With --windows-at: unload each window's start with the short-wave cutoff of this thinness h/L, where the start is a stable contact (2) resolves at that h/L (the loading path of `exact pull-off --unloading`, followed up to the first band it passes onto the piece below; docs/exact.md, "The loading path by descent").
        #[arg(long, requires = "windows_at", allow_hyphen_values = true)]
        unloading_at: Option<f64>,
        /// With --windows-at: read the reach from this file of `exact reach --json` lines (as docs/data/exact_reach.jsonl) instead of computing it over --from, --to, --step.
        #[arg(long, requires = "windows_at")]
        map: Option<std::path::PathBuf>,
        #[command(flatten)]
        gap: GapChoice,
        /// Print one JSON document per size (per window with --windows-at).
        #[arg(long)]
        json: bool,
    },
    /// Write the stored pull-offs (solver/data/exact_pull_offs.json): the exact pull-off at rho = 0.3 and at every step of its follow in rho down to where it stops converging, the starts of the exact pull-off below rho = 0.3 (minutes).
    #[command(
        name = "store-pull-offs",
        after_help = "Example:\n  thinjkr exact store-pull-offs --out solver/data/exact_pull_offs.json"
    )]
    StorePullOffs {
        /// Write the JSON here (a new or existing file in an existing folder).
        #[arg(long)]
        out: std::path::PathBuf,
    },
    /// Write the map of where the exact search finds no state (solver/data/exact_no_state.json): the search of
    /// `exact solve` at each force and approach given, at each rho of 0.25, 0.2, 0.175, 0.15, 0.125, 0.1, 0.075
    /// and 0.05, each stopped after --minutes (hours); a request in a cell of the map that found none at every
    /// corner is then refused at once (as not resolved where some corners ran out of the time limit instead).
    /// The file is written after each force or approach; a map already there (with the same --minutes) is
    /// extended: its other lines and the cells that found a state or none are kept, the others searched again.
    #[command(
        name = "store-no-state",
        after_help = "Example:\n  thinjkr exact store-no-state --forces 0,10 --minutes 30 --out solver/data/exact_no_state.json"
    )]
    StoreNoState {
        /// The forces F̄ (comma-separated, at most 50).
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        forces: Vec<f64>,
        /// The approaches δ̄ (comma-separated, at most 50).
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        deltas: Vec<f64>,
        /// The time limit of one search, in minutes (0 < minutes ≤ 1440); a search stopped by it marks its cell
        /// stopped.
        #[arg(long, default_value_t = 30.0)]
        minutes: f64,
        /// Write the JSON here (a new or existing file in an existing folder).
        #[arg(long)]
        out: std::path::PathBuf,
    },
    /// The exact zero-force state.
    #[command(
        name = "zero-force",
        after_help = "Example:\n  thinjkr exact zero-force --rho 0.8"
    )]
    ZeroForce {
        /// Radii ratio ρ in (0, 1].
        #[arg(long, allow_hyphen_values = true)]
        rho: f64,
        #[command(flatten)]
        discretisation: Discretisation,
        #[command(flatten)]
        gap: GapChoice,
        /// Print JSON.
        #[arg(long)]
        json: bool,
    },
}

/// Run one `thinjkr exact` subcommand.
impl ExactCommand {
    /// Whether the subcommand prints JSON.
    pub(crate) fn json(&self) -> bool {
        match self {
            ExactCommand::PullOff { json, .. }
            | ExactCommand::Solve { json, .. }
            | ExactCommand::ZeroForce { json, .. }
            | ExactCommand::Bands { json, .. }
            | ExactCommand::Reach { json, .. } => *json,
            ExactCommand::StorePullOffs { .. } | ExactCommand::StoreNoState { .. } => false,
        }
    }
}

pub(crate) fn run(c: ExactCommand) -> Result<()> {
    match c {
        ExactCommand::PullOff {
            rho,
            discretisation,
            unloading,
            from_model_contour,
            gap,
            json,
        } => pull_off(
            rho,
            &discretisation,
            unloading,
            from_model_contour,
            &gap,
            json,
        ),
        ExactCommand::Solve {
            rho,
            delta,
            force,
            all,
            from,
            to,
            discretisation,
            gap,
            json,
        } => {
            let control = match (delta, force) {
                (Some(d), _) => Hold::Delta(d),
                (_, Some(f)) => Hold::Force(f),
                _ => return Err(Error::Usage("give one of --delta, --force".into())),
            };
            if all {
                gap.refused_by("solve --all")?;
                let circle = crate::exact::branch::circle_a_bar(
                    &crate::exact::Gap::CYLINDERS.at(1.0)?,
                    control,
                );
                let to = to.unwrap_or(if circle.is_finite() {
                    (1.2 * circle).max(4.0)
                } else {
                    4.0
                });
                return every_state(rho, control, from, to, &discretisation, json);
            }
            state(rho, control, &discretisation, &gap, json)
        }
        ExactCommand::ZeroForce {
            rho,
            discretisation,
            gap,
            json,
        } => state(rho, Hold::Force(0.0), &discretisation, &gap, json),
        ExactCommand::Bands {
            rho,
            from,
            to,
            gap,
            json,
        } => {
            gap.refused_by("bands")?;
            bands(rho, from, to, json)
        }
        ExactCommand::Reach {
            from,
            to,
            step,
            windows_at: Some(rho),
            unloading_at,
            map,
            gap,
            json,
        } => {
            gap.refused_by("reach")?;
            settled_windows(rho, unloading_at, map.as_deref(), from, to, step, json)
        }
        ExactCommand::Reach {
            from,
            to,
            step,
            gap,
            json,
            ..
        } => {
            gap.refused_by("reach")?;
            reach(from, to, step, json)
        }
        ExactCommand::StoreNoState {
            forces,
            deltas,
            minutes,
            out,
        } => store_no_state(&forces, &deltas, minutes, &out),
        ExactCommand::StorePullOffs { out } => {
            super::files::check_file(&out)?;
            let spin = crate::cli::output::Spinner::start("following the pull-off down in rho");
            let stored = crate::studies::stored_pull_offs::store()?;
            drop(spin);
            let json = serde_json::to_string_pretty(&stored).expect("plain data serialises");
            super::files::write_whole(&out, (json + "\n").as_bytes())?;
            errln!(
                "thinjkr: {} stored pull-offs, rho = {} down to {}; {}",
                stored.pull_offs.len(),
                crate::exact::stored::STORED_FROM_RHO,
                crate::error::rounded(stored.reached),
                stored.why_stopped
            );
            Ok(())
        }
    }
}

/// The map's line when it has no band: that the screen found a
/// near-elliptic state everywhere only where it has no gap of any kind
/// (a gap crossed, not settled or at an end of the range is listed after
/// it); `None` when it has a band.
fn no_band_words(map: &crate::report::BandMap) -> Option<&'static str> {
    if !map.bands.is_empty() {
        None
    } else if map.crossed.is_empty() && map.unsettled.is_empty() && map.open_ends.is_empty() {
        Some("no band: a near-elliptic state at every a screened")
    } else {
        Some("no band found: each gap of the screen, listed below, is crossed by the exact family or not settled")
    }
}

/// `thinjkr exact bands`.
pub(crate) fn bands(rho: f64, from: f64, to: f64, json: bool) -> Result<()> {
    let spin = crate::cli::output::Spinner::start("screening for the bands");
    let map = crate::studies::band_map::bands(rho, from, to)?;
    drop(spin);
    if json {
        outln!("{}", Document::Bands { bands: map }.to_json());
        return Ok(());
    }
    outln!(
        "near-elliptic exact states at rho = {} for a from {} to {} (screened by {} in steps of {}, each gap settled by the exact family's folds, the neutral points it passed probed):",
        map.rho,
        map.range[0],
        map.range[1],
        map.screen,
        map.step
    );
    if let Some(words) = no_band_words(&map) {
        outln!("  {words}");
    }
    let mode = |m: Option<usize>| match m {
        Some(0) => "the size".to_string(),
        Some(n) => format!("cos {n}θ"),
        None => "not computed".to_string(),
    };
    for b in &map.bands {
        outln!(
            "  band {:.4} < a < {:.4}, mode {}: the arms beside it fold back at its edges",
            b.lower.a_bar,
            b.upper.a_bar,
            mode(b.lower.mode)
        );
        for (edge, e) in [("lower", &b.lower), ("upper", &b.upper)] {
            outln!(
                "    {edge} edge: a = {:.6}, s = {:.6}, force = {:.6}, delta = {:.6} (mode {}; N = {}, bc {:.0e})",
                e.a_bar,
                e.s,
                e.force_bar,
                e.delta_bar,
                mode(e.mode),
                e.modes,
                e.bc_error
            );
        }
    }
    for c in &map.crossed {
        outln!(
            "  no band where {} has none between a = {:.2} and {:.2}: {}",
            map.screen,
            c.screened[0],
            c.screened[1],
            c.why
        );
    }
    for c in &map.unsettled {
        outln!(
            "  not settled where {} has none between a = {:.2} and {:.2}: {}",
            map.screen,
            c.screened[0],
            c.screened[1],
            c.why
        );
    }
    for o in &map.open_ends {
        outln!(
            "  {} has no near-elliptic state from a = {:.2} to {:.2}, at an end of the range (not settled)",
            map.screen,
            o[0],
            o[1]
        );
    }
    if map
        .open_ends
        .iter()
        .any(|o| o[0] <= map.range[0] && o[1] >= map.range[1])
    {
        outln!(
            "  the screen has no state anywhere here; `thinjkr exact reach` maps the sizes with a state at every rho from the exact family alone (docs/exact.md, \"The reach of each size\")"
        );
    }
    for p in &map.probed {
        outln!(
            "  neutral point n = {} (a = {:.4}), passed by the screen, probed in steps of {}: {}",
            p.n,
            p.a_bar,
            crate::exact::bands::PROBE_STEP,
            if p.outcome == "band" {
                "a band (above)"
            } else {
                p.outcome.as_str()
            }
        );
    }
    Ok(())
}

/// `thinjkr exact reach`.
pub(crate) fn reach(from: f64, to: f64, step: f64, json: bool) -> Result<()> {
    use crate::studies::reach::Reached;
    let spin = crate::cli::output::Spinner::start("the reach of each size");
    let map = crate::studies::reach::reach(from, to, step)?;
    drop(spin);
    if json {
        for size in map {
            outln!("{}", Document::Reach { reach: size }.to_json());
        }
        return Ok(());
    }
    outln!(
        "the near-elliptic exact state of each size a, followed in rho at fixed a from the circle at rho = {} ({} modes of each sign):",
        crate::studies::reach::PATHS_START_RHO,
        crate::studies::reach::MODES
    );
    for p in &map {
        let what = match &p.reached {
            Reached::TurnsBack { rho, bc_error } => format!(
                "turns back at rho = {} (boundary error {})",
                crate::error::rounded(*rho),
                bc_error.map_or("not computed: singular".to_string(), |e| format!("{e:.0e}"))
            ),
            Reached::Floor { bc_error } => format!(
                "reaches rho = {} without turning back (boundary error {bc_error:.0e})",
                crate::studies::reach::FLOOR
            ),
            Reached::Stopped { why } => format!("stopped: {why}"),
        };
        outln!("  a = {:.4}: {what}", p.a_bar);
    }
    outln!("");
    outln!("{}", crate::studies::reach::markdown(&map).trim_end());
    Ok(())
}

/// The largest reach map `exact reach --windows-at --map` reads: 1000
/// sizes of a few hundred bytes each.
const MAX_REACH_MAP: u64 = 4 << 20;

/// `thinjkr exact reach --windows-at`.
pub(crate) fn settled_windows(
    rho: f64,
    unloading_at: Option<f64>,
    map: Option<&std::path::Path>,
    from: f64,
    to: f64,
    step: f64,
    json: bool,
) -> Result<()> {
    use crate::studies::reach::{self, WindowEnd};
    crate::error::check_range(
        "windows-at",
        rho,
        rho.is_finite() && rho > reach::FLOOR && rho < reach::PATHS_START_RHO,
        "(0.02, 0.98)",
    )?;
    let unloading = match unloading_at {
        Some(h) => {
            crate::error::check_range("unloading-at", h, h > 0.0, "(0, ∞)")?;
            Some(crate::cutoff::Cutoff::for_thinness(h)?)
        }
        None => None,
    };
    let spin = crate::cli::output::Spinner::start("the windows at this rho");
    let map = match map {
        Some(p) => reach::from_json_lines(&super::files::input(p, MAX_REACH_MAP)?)?,
        None => reach::reach(from, to, step)?,
    };
    let windows = reach::settle(&map, rho, unloading)?;
    drop(spin);
    if json {
        for window in windows {
            outln!("{}", Document::Window { window }.to_json());
        }
        return Ok(());
    }
    if windows.is_empty() {
        outln!(
            "no size of the map has a state at rho = {} connected to the circle at fixed a (`thinjkr exact reach` without --windows-at lists each size's reach)",
            crate::error::rounded(rho)
        );
        return Ok(());
    }
    outln!(
        "the windows of the reach at rho = {}, each traced in a at that rho ({} modes of each sign; an end is a fold, a band's edge, or where the boundary error passes {:.0e}):",
        crate::error::rounded(rho),
        reach::MODES,
        reach::WINDOW_RESOLVED
    );
    outln!("{}", reach::windows_markdown(&windows).trim_end());
    for w in &windows {
        for (side, e) in [("smaller", &w.lower), ("larger", &w.upper)] {
            if let WindowEnd::Failed { why } = e {
                outln!(
                    "the window {:.2} to {:.2}, towards {side} a: {why}",
                    w.grid[0],
                    w.grid[1]
                );
            }
        }
    }
    Ok(())
}

/// The unstable modes in words: runs of three or more consecutive even
/// modes as one range with its wavelengths, the shortest the series of
/// `series_modes` contour modes represents (n = 2N) named where a run
/// reaches it.
fn modes(v: &[UnstableMode], series_modes: usize) -> String {
    if v.is_empty() {
        return "stable".into();
    }
    let ns: Vec<usize> = v.iter().map(|m| m.n).collect();
    let mut parts = Vec::new();
    for (i, j) in even_runs(&ns) {
        if j >= i + 2 {
            let last = if v[j].n == 2 * series_modes {
                format!(", the shortest the {series_modes}-mode series represents")
            } else {
                String::new()
            };
            parts.push(format!(
                "n = {}, {}, …, {} (every even n{last}; wavelengths {:.3} down to {:.3})",
                v[i].n,
                v[i + 1].n,
                v[j].n,
                v[i].wavelength,
                v[j].wavelength
            ));
        } else {
            for m in &v[i..=j] {
                parts.push(if m.n == 0 {
                    "n = 0 (size)".to_string()
                } else {
                    format!("n = {} (wavelength {:.3})", m.n, m.wavelength)
                });
            }
        }
    }
    format!("unstable modes {}", parts.join(", "))
}

/// The index ranges `(i, j)` (inclusive) of `ns` in order: a run of
/// consecutive even modes n, n + 2, … (n > 0) as one range, every other
/// mode alone; a range of three or more is written as a run.
fn even_runs(ns: &[usize]) -> Vec<(usize, usize)> {
    let mut runs = Vec::new();
    let mut i = 0;
    while i < ns.len() {
        let mut j = i;
        while j + 1 < ns.len() && ns[j + 1] == ns[j] + 2 && ns[j] > 0 {
            j += 1;
        }
        runs.push((i, j));
        i = j + 1;
    }
    runs
}

/// An exact state in words: its size and load to ten digits, then how
/// well it is resolved.
pub(crate) fn show_state(label: &str, st: &ExactState) -> crate::Result<()> {
    outln!(
        "{label}: rho = {}, a = {:.10}, b = {:.10}, s = {:.10}, delta = {:.10}, force = {:.10}",
        st.rho,
        st.a_bar,
        st.b_bar,
        st.s,
        st.delta_bar,
        st.force_bar
    );
    if crate::cli::output::explain() {
        show_quality(st)
    } else {
        show_trust(st)
    }
}

/// How far to trust an exact state, in the brief text's two lines (with
/// `--explain`, [`show_quality`]'s lines instead): its check and route, then
/// one stability verdict.
fn show_trust(st: &ExactState) -> crate::Result<()> {
    outln!(
        "  checked: max |dp/dnu - 1| = {:.1e} with {} modes; found: {}",
        st.bc_error,
        st.truncation.modes,
        st.route_words()
    );
    outln!("  {} (more with --explain)", verdict_words(st));
    Ok(())
}

fn show_quality(st: &ExactState) -> crate::Result<()> {
    outln!(
        "  max |dp/dnu - 1| = {:.1e} on {} points; contour off the ellipse by {:.3e} a; {} modes{}, {} points",
        st.bc_error,
        2 * st.truncation.points,
        st.deviation_from_ellipse,
        st.truncation.modes,
        if st.truncation.arclength > 0 {
            " of each sign (the arclength representation)"
        } else {
            ""
        },
        st.truncation.points
    );
    outln!("  found: {}", st.route_words());
    outln!(
        "  displacement control: {}",
        modes(&st.stability.displacement, st.truncation.modes)
    );
    outln!(
        "  load control: {}",
        modes(&st.stability.load, st.truncation.modes)
    );
    outln!("  {}", cutoff_words(&st.stability));
    outln!("  shape: {}", shape_words(st));
    outln!("  coatings: {}", coatings_words(st));
    Ok(())
}

/// For which coatings (2) gives the state as a contact it resolves
/// (`exact::undulations::Coatings`), in words; "none" under a control where
/// no thinness does, with the modes that set the two bounds.
pub(crate) fn coatings_words(st: &ExactState) -> String {
    let Some((load, displacement)) = coatings_ranges(st) else {
        return "not judged (its stability was not computed)".into();
    };
    let head =
        "the thinness h/L for which (2) resolves its shape and finds it stable above the cutoff:";
    if load == displacement {
        format!("{head} {load}, under either control")
    } else {
        format!("{head} {load} under load control, {displacement} under displacement control")
    }
}

/// The stability verdict of the brief text, in a line: for which coatings
/// the state is a stable contact whose shape (2) resolves ([`coatings_words`]
/// in fewer words).
pub(crate) fn verdict_words(st: &ExactState) -> String {
    let Some((load, displacement)) = coatings_ranges(st) else {
        return "its stability was not judged".into();
    };
    let range = |r: &Thinness| match r {
        Thinness::Range(r) => format!("for coatings of h/L {r}"),
        Thinness::None(why) => format!("for no coating thickness ({why})"),
    };
    if load == displacement {
        format!(
            "a stable contact whose shape (2) resolves {}, under either control",
            range(&load)
        )
    } else {
        format!(
            "a stable contact whose shape (2) resolves {} under load control, {} under displacement control",
            range(&load),
            range(&displacement)
        )
    }
}

/// For which coatings a state is stable above the cutoff with its shape
/// resolved, in words.
#[derive(PartialEq)]
enum Thinness {
    /// A range of h/L ("from 0.373 to 0.560").
    Range(String),
    /// No thinness, and why.
    None(String),
}

impl std::fmt::Display for Thinness {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Thinness::Range(r) => f.write_str(r),
            Thinness::None(why) => write!(f, "none ({why})"),
        }
    }
}

/// The ranges of thinness h/L under load and under displacement control
/// for which the state is stable above the cutoff with its shape resolved;
/// `None` where its stability was not computed.
fn coatings_ranges(st: &ExactState) -> Option<(Thinness, Thinness)> {
    use crate::exact::undulations::{no_thinness_words, Thinnesses};
    let stab = &st.stability;
    let (Some(coatings), shape) = st.coatings_measured() else {
        return None;
    };
    let words = |range: Option<Thinnesses>, modes: &[UnstableMode]| -> Thinness {
        Thinness::Range(match range.map(|t| t.bounds()) {
            Some((Some(from), Some(to))) => format!("from {from:.3} to {to:.3}"),
            Some((None, Some(to))) => format!("below {to:.3}"),
            Some((Some(from), None)) => format!("from {from:.3} on"),
            Some((None, None)) => "every h/L".into(),
            None => return Thinness::None(no_thinness_words(modes, &shape)),
        })
    };
    Some((
        words(coatings.load, &stab.load),
        words(coatings.displacement, &stab.displacement),
    ))
}

/// How much of the state's shape lies in undulations shorter than the
/// cutoff of its stability verdicts (`exact::undulations`).
pub(crate) fn shape_words(st: &ExactState) -> String {
    st.short_waves().words(st.stability.cutoff)
}

/// The stability verdicts above the short-wave cutoff, and which unstable
/// modes lie below it, in words.
pub(crate) fn cutoff_words(stab: &crate::exact::stability::ExactStability) -> String {
    let c = stab.cutoff;
    let verdict = |v: &[UnstableMode], neutral: &[UnstableMode], stable: Option<bool>| -> String {
        let list = |resolved: bool| -> Vec<usize> {
            v.iter()
                .filter(|m| m.resolved == resolved)
                .map(|m| m.n)
                .collect()
        };
        let (above, below) = (list(true), list(false));
        let zero: Vec<usize> = neutral.iter().filter(|m| m.resolved).map(|m| m.n).collect();
        let mut w = match stable {
            Some(true) if !zero.is_empty() => format!(
                "neutral (n = {}: a zero eigenvalue, a fold or bifurcation of this control; no mode unstable)",
                mode_list(&zero)
            ),
            Some(true) => "stable".to_string(),
            Some(false) => format!("unstable (n = {})", mode_list(&above)),
            None => match stab.shortest_wavelength {
                Some(w) => format!(
                    "not settled (no mode the series holds is unstable above the cutoff, but its shortest, wavelength {w:.3}, is longer than the cutoff: more --modes settle it)"
                ),
                None => "not computed".to_string(),
            },
        };
        if stable != Some(true) && !zero.is_empty() {
            w.push_str(&format!(
                "; n = {} neutral (a zero eigenvalue: a fold or bifurcation of this control)",
                mode_list(&zero)
            ));
        }
        if !below.is_empty() {
            w.push_str(&format!(
                "; n = {} shorter, not resolved by (2)",
                mode_list(&below)
            ));
        }
        w
    };
    format!(
        "above the short-wave cutoff (wavelength {:.3} = 2π h/L, h/L = {}{}): under displacement control {}; under load control {}",
        c.wavelength,
        crate::error::short(c.thinness),
        if c.thinness == crate::cutoff::Cutoff::DEFAULT_THINNESS {
            ", the default"
        } else {
            ""
        },
        verdict(
            &stab.displacement,
            &stab.neutral_displacement,
            stab.stable_displacement
        ),
        verdict(&stab.load, &stab.neutral_load, stab.stable_load)
    )
}

/// Mode numbers, runs of three or more consecutive even ones as a range.
fn mode_list(ns: &[usize]) -> String {
    let mut parts = Vec::new();
    for (i, j) in even_runs(ns) {
        if j >= i + 2 {
            parts.push(format!("{}, {}, …, {}", ns[i], ns[i + 1], ns[j]));
        } else {
            parts.extend(ns[i..=j].iter().map(|n| n.to_string()));
        }
    }
    parts.join(", ")
}

/// Whether a contact unloaded under load control through states stable
/// above the cutoff can come to the pull-off `po`, from its own stability:
/// not where it is unstable under load to a resolved mode (at the limit of
/// stable states no resolved eigenvalue is negative); where it is stable,
/// the path decides (`--unloading`, whose lines follow).
fn reached_words(po: &crate::exact::ExactState, unloading: bool) -> String {
    let stab = &po.stability;
    let path = if unloading {
        "; the unloading path (from F = 10, else from the largest stable load on the pull-off's piece):"
    } else {
        ""
    };
    // where the path may end here, how to follow it
    let then = if unloading {
        path
    } else {
        "; --unloading follows the path from F = 10 to say whether it does"
    };
    // where no thinness makes it a stable contact whose shape (2)
    // resolves, a thicker coating is no way out (`coatings:`)
    let shape = po.short_waves();
    let no_thinness = match (po.coatings, shape.critical_thinness) {
        (Some(c), Some(h)) if c.load.is_none() => format!(
            ", but from h/L = {h:.3} on its shape is unresolved: no thinness makes it a stable contact (2) resolves"
        ),
        _ => String::new(),
    };
    let unresolved = if shape.unresolved {
        ", but its shape is unresolved at this thinness"
    } else {
        ""
    };
    match (stab.stable_load, stab.doubt(true, po.a_bar)) {
        (Some(false), Some(why)) => format!("no at this thinness: {why}{no_thinness}{path}"),
        (Some(true), _) => format!(
            "possibly: it is stable under load control above the short-wave cutoff (h/L = {}{}){unresolved}{then}",
            crate::error::short(stab.cutoff.thinness),
            match stab.critical_thinness_load {
                Some(h) => format!(", as for every h/L >= {h:.3}"),
                None => ", with no contour mode unstable".into(),
            }
        ),
        _ => format!(
            "not settled: no resolved mode is unstable under load control, but the series stops short of the cutoff 2π h/L = {:.3}{then}",
            stab.cutoff.wavelength
        ),
    }
}

/// The unloading path in words.
fn unloading_words(p: &Passed) -> String {
    let Passed::Unloading {
        from_force,
        start_at,
        reaches,
        first_minimum_force,
        first_minimum_a_bar,
        critical_thinness,
        critical_mode,
        cutoff_thinness,
        stable_above_cutoff,
        bands_crossed,
        why_not_settled,
    } = p
    else {
        return String::new();
    };
    let from = format!(
        "{}{}",
        crate::error::short(*from_force),
        start_at.as_ref().map_or(String::new(), |s| s.words(false))
    );
    let (Some(reaches), Some(f), Some(a)) = (reaches, first_minimum_force, first_minimum_a_bar)
    else {
        return format!(
            "not settled: {}",
            why_not_settled.as_deref().unwrap_or("no reason given")
        );
    };
    let first = if *reaches {
        format!("from F = {from} its first force minimum is this pull-off")
    } else {
        format!(
            "from F = {from} its first force minimum is another state, F = {}, a = {} (this pull-off lies on another piece)",
            crate::error::short(*f),
            crate::error::short(*a)
        )
    };
    let stability = match (critical_thinness, critical_mode, stable_above_cutoff) {
        (Some(h), Some(n), Some(stable)) => format!(
            "; on the way a state is unstable under load control above the cutoff for h/L below {h:.3} (mode n = {n}): at h/L = {} the path is {}",
            crate::error::short(*cutoff_thinness),
            if *stable { "stable" } else { "unstable (the contact changes shape before it gets there)" }
        ),
        (_, _, Some(true)) => "; every state on the way is stable under load control".into(),
        _ => "; the size is unstable under load control on the way".into(),
    };
    let bands = if bands_crossed.is_empty() {
        String::new()
    } else {
        let list: Vec<String> = bands_crossed.iter().map(|n| n.to_string()).collect();
        format!(
            "; on the way the trace steps across the bands of modes n = {} (below rho = 1 the family has no bifurcation point there: each step lands on the piece beyond its band; at rho = 1 they are the circle's neutral points)",
            list.join(", ")
        )
    };
    format!("{first}{bands}{stability}")
}

/// The loading path by descent in words.
fn loading_words(p: &Passed) -> String {
    let Passed::LoadingPath {
        from_force,
        start_at,
        cutoff_thinness,
        states_held,
        jump_forces,
        jump_landing_a_bar,
        bands_passed,
        bands_passed_unresolved_at,
        bands_passed_to_force,
        bands_passed_to_a_bar,
        unresolved_turned_unstable,
        unresolved_turned_unstable_at,
        first_lost_force,
        first_lost_a_bar,
        reaches,
        comes_off,
        why_not_settled,
    } = p
    else {
        return String::new();
    };
    // the bands passed and the unresolved modes turned unstable, each a
    // clause between commas after "from F = 10"
    let clauses: Vec<String> = [
        passed_words(
            bands_passed,
            bands_passed_unresolved_at,
            bands_passed_to_force,
            bands_passed_to_a_bar,
        ),
        bands_words(unresolved_turned_unstable, unresolved_turned_unstable_at),
    ]
    .into_iter()
    .filter(|c| !c.is_empty())
    .collect();
    let bands = if clauses.is_empty() {
        String::new()
    } else {
        format!(", {},", clauses.join(", "))
    };
    let why = why_not_settled.as_deref().unwrap_or("no reason given");
    let from = format!(
        "{}{}",
        crate::error::short(*from_force),
        start_at.as_ref().map_or(String::new(), |s| s.words(true))
    );
    let head = format!(
        "the loading path by descent (modes at least 2 pi h long move, h/L = {}; docs/exact.md, \"The loading path by descent\"):",
        crate::error::short(*cutoff_thinness)
    );
    if start_at.is_none() && *states_held == 0 {
        return format!("{head} no start: {why}");
    }
    let (Some(f), Some(a), Some(reaches)) = (first_lost_force, first_lost_a_bar, reaches) else {
        return format!(
            "{head} from F = {from}{bands} not settled after {states_held} states: {why}"
        );
    };
    let jumps = match jump_forces.len() {
        0 => String::new(),
        n => format!(
            " after {n} jump(s), the first at F = {} to a = {}",
            crate::error::short(jump_forces[0]),
            crate::error::short(jump_landing_a_bar[0])
        ),
    };
    let lost = format!(
        "from F = {from}{bands} it holds its state down to F = {}, a = {}{jumps} ({})",
        crate::error::short(*f),
        crate::error::short(*a),
        if *reaches {
            "this pull-off"
        } else {
            "not this pull-off"
        }
    );
    match comes_off {
        Some(true) => format!("{head} {lost}, and the contact comes off there"),
        _ => format!("{head} {lost}; where the contact goes from there is not settled: {why}"),
    }
}

/// The bands of unresolved modes a path passed, in words (empty where
/// none).
fn passed_words(modes: &[usize], unresolved_at: &[f64], to_force: &[f64], to_a: &[f64]) -> String {
    if modes.is_empty() {
        return String::new();
    }
    let list: Vec<String> = modes
        .iter()
        .zip(unresolved_at)
        .zip(to_force.iter().zip(to_a))
        .map(|((n, u), (f, a))| {
            format!(
                "n = {n} (its lobes pass 1 % of a at F = {}; the path goes on from F = {}, a = {})",
                crate::error::short(*u),
                crate::error::short(*f),
                crate::error::short(*a)
            )
        })
        .collect();
    format!(
        "passing the bands of modes shorter than the cutoff (held flat by the coating): {}",
        list.join("; ")
    )
}

/// The modes shorter than the cutoff a path's states turn unstable to on
/// the way, in words (empty where none).
fn bands_words(modes: &[usize], at: &[f64]) -> String {
    if modes.is_empty() {
        return String::new();
    }
    let list: Vec<String> = modes
        .iter()
        .zip(at)
        .map(|(n, f)| format!("n = {n} (from F = {})", crate::error::short(*f)))
        .collect();
    format!(
        "its states turning unstable on the way to modes shorter than the cutoff, which it does not count: {} (below rho = 1 on a near-elliptic piece each is that mode's band stepped over, past a fold in a the fold's mode)",
        list.join(", ")
    )
}

pub(crate) fn pull_off(
    rho: f64,
    d: &Discretisation,
    unloading: bool,
    from_model_contour: bool,
    gap: &GapChoice,
    json: bool,
) -> Result<()> {
    let (_, family) = gap.gap()?;
    if let (Some(f), true) = (family, unloading) {
        return Err(Error::Usage(format!(
            "--unloading with --gap {}: the unloading and loading paths are followed on the cylinders' gap (1) alone",
            f.name
        )));
    }
    let spin = crate::cli::output::Spinner::start("locating the exact pull-off");
    let tries = d.asked()?;
    let (po, events) = if from_model_contour {
        (
            crate::studies::model_contour::pull_off_from_model_contour(gap.name(), rho)?,
            Vec::new(),
        )
    } else {
        crate::conformal::exact_pull_off_on_gap(gap.name(), rho, tries.as_deref())?
    };
    let po = d.judged(po)?;
    let mut passed = Passed::from_exact(&events);
    // beside it: the ellipse models' pull-offs on the cylinders' gap, the
    // family's members' on its own
    let models = models_beside(
        family,
        |m| {
            Contact::with_model(m, rho)
                .and_then(|c| c.pull_off_load())
                .map(|p| p.state)
        },
        |m| {
            m.pull_off(rho, crate::fold::FoldCondition::Load)
                .map(|(s, _)| s)
        },
    );
    drop(spin);
    // the paths from the state both begin from (at F = 10, else the
    // largest stable load on the pull-off's piece), found once: minutes
    // below rho = 0.8, so the text prints the pull-off before them
    let paths = |passed: &mut Vec<Passed>| -> Result<()> {
        let _spin = crate::cli::output::Spinner::start(
            "following the unloading and loading paths (the state at F = 10 first)",
        );
        let cutoff = d.cutoff()?;
        let start = crate::studies::start::start(&po, cutoff);
        passed.push(crate::studies::unloading::unloading(&po, cutoff, &start));
        passed.push(crate::studies::loading::reported(&po, cutoff, &start));
        Ok(())
    };
    if json {
        if unloading {
            paths(&mut passed)?;
        }
        let doc = Document::PullOff {
            state: AnyState::Exact(Box::new(po)),
            control: crate::fold::FoldCondition::Load,
            basis: None,
            passed,
            models: models.into_iter().map(|(_, _, answer)| answer).collect(),
        };
        outln!("{}", doc.to_json());
        return Ok(());
    }
    // F̄ is stationary at the pull-off and accurate to round-off; its
    // location (ā, b̄, s, δ̄) only to about 1e-7 (golden-section search on
    // the flat F̄), so it is printed to 7 decimals
    outln!(
        "exact pull-off (load control): rho = {rho}, a = {:.7}, b = {:.7}, s = {:.7}, delta = {:.7}, force = {:.10}",
        po.a_bar, po.b_bar, po.s, po.delta_bar, po.force_bar
    );
    // the brief text: how far to trust it in two lines (--unloading asks
    // for the paths' story, and gets every line)
    if !(crate::cli::output::explain() || unloading) {
        return show_trust(&po);
    }
    show_quality(&po)?;
    for e in &events {
        if let Some(words) = event_words(e) {
            outln!("  on the way: {words}")
        }
    }
    outln!("  which pull-off: {}", which_pull_off(&po));
    outln!("  reached by unloading: {}", reached_words(&po, unloading));
    if unloading {
        // the lines so far reach a reader through a pipe before the paths'
        // minutes (a terminal has them already)
        crate::cli::output::finish()?;
        paths(&mut passed)?;
    }
    for p in &passed {
        match p {
            Passed::Unloading { .. } => outln!("    {}", unloading_words(p)),
            Passed::LoadingPath { .. } => outln!("    {}", loading_words(p)),
            _ => {}
        }
    }
    show_models_beside_pull_off(&po, &models)
}

/// Which pull-off `po` is, in words: the minimum followed in ρ from the
/// stored pull-offs, or the first minimum on the near-elliptic arm.
fn which_pull_off(po: &ExactState) -> String {
    if po.rho < crate::exact::stored::STORED_FROM_RHO
        && matches!(
            po.route,
            crate::exact::Route::ContinuedInRho | crate::exact::Route::BetweenStored
        )
    {
        format!(
            "the minimum of F on the piece that carries the pull-off at rho = {}, followed in rho from there (started from the stored pull-offs: between three of one truncation from their interpolation, else from the one nearest above; docs/exact.md, \"The stored pull-offs\")",
            crate::exact::stored::STORED_FROM_RHO
        )
    } else {
        "the first minimum of F on the near-elliptic arm traced towards smaller a from its start (docs/exact.md, \"Which family\")".to_string()
    }
}

/// The models' pull-offs beside the exact one `po`, each with its relative
/// errors, or its error.
fn show_models_beside_pull_off(
    po: &ExactState,
    models: &[(String, Result<[f64; 4]>, ModelAnswer)],
) -> Result<()> {
    for (m, r, _) in models {
        match r {
            Ok([a, s, _, force]) => outln!(
                "  model {m}: force = {:.6} ({:+.3} %), a = {:.6} ({:+.3} %), s = {:.6} ({:+.3} %)",
                force,
                100.0 * (force / po.force_bar - 1.0),
                a,
                100.0 * (a / po.a_bar - 1.0),
                s,
                100.0 * (s / po.s - 1.0)
            ),
            Err(e) => outln!("  model {m}: {e}"),
        }
    }
    Ok(())
}

/// `thinjkr exact solve --all`: every near-elliptic exact state at the
/// control with ā in [from, to].
pub(crate) fn every_state(
    rho: f64,
    control: Hold,
    from: f64,
    to: f64,
    d: &Discretisation,
    json: bool,
) -> Result<()> {
    control.check_finite()?;
    let cutoff = d.cutoff()?;
    let spin = crate::cli::output::Spinner::start("screening for every exact state");
    let mut all = crate::exact::bands::states_at(rho, control, from, to, &d.tries()?)?;
    all.states = std::mem::take(&mut all.states)
        .into_iter()
        .map(|st| st.judged(cutoff))
        .collect();
    drop(spin);
    if all.states.is_empty() {
        let missed: Vec<String> = all
            .missed
            .iter()
            .map(|(a, why)| format!("near a = {a:.3}: {why}"))
            .collect();
        return Err(Error::NoState(format!(
            "no near-elliptic exact state at {control} for rho = {} with a from {} to {} (conformal:8 screened in steps of 0.01, the arms beside its gaps followed past their folds{})",
            crate::error::short(rho),
            crate::error::short(from),
            crate::error::short(to),
            if missed.is_empty() {
                String::new()
            } else {
                format!("; where it crosses that value: {}", missed.join("; "))
            }
        )));
    }
    if json {
        let doc = Document::States {
            states: all
                .states
                .into_iter()
                .map(|st| AnyState::Exact(Box::new(st)))
                .collect(),
        };
        outln!("{}", doc.to_json());
        return Ok(());
    }
    let n = all.states.len();
    outln!(
        "{n} near-elliptic exact state{} at {control} for rho = {rho} with a from {} to {} (where conformal:8's states at fixed a, {} grid points, cross that value, and past the folds of the arms beside its gaps):",
        if n == 1 { "" } else { "s" },
        all.range[0],
        crate::error::short(all.range[1]),
        all.screen
    );
    for (k, st) in all.states.iter().enumerate() {
        outln!(
            "exact state {} of {n}: a = {:.10}, b = {:.10}, s = {:.10}, delta = {:.10}, force = {:.10}",
            k + 1,
            st.a_bar,
            st.b_bar,
            st.s,
            st.delta_bar,
            st.force_bar
        );
        if crate::cli::output::explain() {
            show_quality(st)?;
        }
    }
    for (a, why) in &all.missed {
        outln!("  not accepted near a = {a:.3}: {why}");
    }
    Ok(())
}

/// The exact state at a control value and every model's.
pub(crate) fn state(
    rho: f64,
    control: Hold,
    d: &Discretisation,
    gap: &GapChoice,
    json: bool,
) -> Result<()> {
    let (_, family) = gap.gap()?;
    let spin = crate::cli::output::Spinner::start("solving the free-boundary problem (2)-(3)");
    control.check_finite()?;
    let tries = d.asked()?;
    let st = crate::conformal::exact_state_on_gap(gap.name(), rho, control, tries.as_deref())?;
    let st = d.judged(st)?;
    // beside it: the ellipse models on the cylinders' gap (their state at
    // the control as a batch solves it), the family's members on its own
    let model_states = models_beside(
        family,
        |m| Contact::with_model(m, rho).and_then(|c| crate::batch::Solves::solve(&m, &c, control)),
        |m| m.solve(rho, control),
    );
    drop(spin);
    if json {
        let doc = Document::State {
            state: AnyState::Exact(Box::new(st)),
            models: model_states
                .into_iter()
                .map(|(_, _, answer)| answer)
                .collect(),
            others: None,
        };
        outln!("{}", doc.to_json());
        return Ok(());
    }
    show_state("exact state", &st)?;
    if !crate::cli::output::explain() {
        return Ok(());
    }
    // counting the others takes the screen of --all (seconds at rho = 0.8,
    // minutes at small rho): said, not done
    outln!(
        "  other exact states at {control}: not counted; --all lists every near-elliptic one with a in [--from, --to] (by default [1, 4]; a screen of conformal:8's states at fixed a, each crossing solved exactly: seconds to minutes)"
    );
    for (m, r, _) in &model_states {
        match r {
            Ok([a, s, delta, force]) => outln!(
                "  model {m}: a = {:.6} ({:+.3} %), s = {:.6} ({:+.3} %), delta = {:.6}, force = {:.6}",
                a,
                100.0 * (a / st.a_bar - 1.0),
                s,
                100.0 * (s / st.s - 1.0),
                delta,
                force
            ),
            Err(e) => outln!("  model {m}: {e}"),
        }
    }
    Ok(())
}

/// `thinjkr exact store-no-state`: the map computed and written whole.
fn store_no_state(
    forces: &[f64],
    deltas: &[f64],
    minutes: f64,
    out: &std::path::Path,
) -> Result<()> {
    const MAX_VALUES: usize = 50;
    for (name, values) in [("forces", forces), ("deltas", deltas)] {
        if values.len() > MAX_VALUES {
            return Err(Error::OutOfRange {
                name,
                value: values.len() as f64,
                range: format!("at most {MAX_VALUES} values").into(),
            });
        }
        if let Some(&v) = values.iter().find(|v| !(v.abs() <= 1e6)) {
            return Err(Error::OutOfRange {
                name,
                value: v,
                range: "[-1e6, 1e6]".into(),
            });
        }
    }
    if forces.is_empty() && deltas.is_empty() {
        return Err(Error::Usage("give --forces, --deltas or both".into()));
    }
    if !(minutes > 0.0 && minutes <= 1440.0) {
        return Err(Error::OutOfRange {
            name: "minutes",
            value: minutes,
            range: "(0, 1440]".into(),
        });
    }
    super::files::check_file(out)?;
    // a map already there is extended, its settled cells kept; a file there
    // that is not one is not overwritten
    let previous = match std::fs::read_to_string(out) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => None,
        Err(e) => return Err(Error::Io(format!("{}: {e}", out.display()))),
        Ok(t) => Some(
            serde_json::from_str::<crate::exact::no_state::NoStateMap>(&t).map_err(|e| {
                Error::Usage(format!(
                    "{} is there and is not a map of `thinjkr exact store-no-state` ({e}): give another --out",
                    out.display()
                ))
            })?,
        ),
    };
    let mut write = |map: &crate::exact::no_state::NoStateMap| -> Result<()> {
        let json = serde_json::to_string_pretty(map).expect("plain data serialises");
        super::files::write_whole(out, (json + "\n").as_bytes())
    };
    // each line's eight searches run side by side; the spinner says the
    // newest stage one of them reached
    let spin = crate::cli::output::Spinner::start(&format!(
        "the map of no state, {} lines of 8 cells, each at most {} min",
        forces.len() + deltas.len(),
        crate::error::short(minutes)
    ));
    let map = crate::studies::no_state_map::store(forces, deltas, minutes, previous, &mut write)?;
    drop(spin);
    let count = |f: fn(&crate::exact::no_state::Cell) -> bool| {
        map.lines
            .iter()
            .flat_map(|l| &l.cells)
            .filter(|c| f(c))
            .count()
    };
    use crate::exact::no_state::Cell;
    errln!(
        "thinjkr: {} cells: {} found a state, {} none, {} stopped at the time limit, {} unsettled",
        count(|_| true),
        count(|c| matches!(c, Cell::Found { .. })),
        count(|c| matches!(c, Cell::None { .. })),
        count(|c| matches!(c, Cell::Stopped { .. })),
        count(|c| matches!(c, Cell::Unsettled { .. }))
    );
    Ok(())
}

/// An event of the trace in words, for a person (`None` for the force
/// minimum, which is reported as the pull-off itself).
fn event_words(event: &crate::exact::branch::Event) -> Option<String> {
    use crate::exact::branch::Event;
    match event {
        Event::SizeFold { a_bar } => {
            Some(format!("the family turns back in a near a = {a_bar:.6}"))
        }
        Event::Bifurcation { between, mode } => Some(format!(
            "a bifurcation point between a = {:.6} and {:.6} (contour mode {})",
            between[0],
            between[1],
            mode.map_or("not computed".to_string(), |n| format!("n = {n}"))
        )),
        Event::ForceMinimum { .. } => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A map without bands says "a near-elliptic state at every a
    /// screened" only where the screen has no gap at all: at ρ = 0.3
    /// `conformal:8` has no near-elliptic state from ā = 2 to 4 (an open
    /// end over the whole range), and the map had said both.
    #[test]
    fn a_map_without_bands_says_a_state_everywhere_only_without_gaps() {
        let mut map = crate::report::BandMap {
            rho: 0.3,
            range: [2.0, 4.0],
            step: 0.01,
            screen: "conformal:8".into(),
            bands: Vec::new(),
            crossed: Vec::new(),
            unsettled: Vec::new(),
            open_ends: Vec::new(),
            probed: Vec::new(),
            curve: Vec::new(),
        };
        assert_eq!(
            no_band_words(&map),
            Some("no band: a near-elliptic state at every a screened")
        );
        map.open_ends.push([2.0, 4.0]);
        let words = no_band_words(&map).unwrap();
        assert!(
            words.starts_with("no band found") && !words.contains("every a"),
            "{words}"
        );
    }
}
