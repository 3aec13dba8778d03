//! The command line, `thinjkr` (the binary is [`main`] and nothing else):
//! the verbs and their arguments (clap), each answered through the model
//! layer (`crate::registry`) and printed for a person, as CSV or as JSON
//! (`crate::report`); `thinjkr exact …` in `exact_command`, the contour
//! families' printers in `contour`, every write through `output`, every
//! file through `files`. With no arguments it prints the paper's ρ = 0.8
//! example.
//!
//! Owns: the verbs, their parsing and printing, the thread pool of a run.
//! May use: `generated` (`ModelId`), `accuracy`, `control`, `crate::registry`, `crate::report`, `crate::units`,
//! `crate::contact`, `crate::model`, `crate::conformal`, `crate::exact`,
//! `crate::batch`, `crate::curve`, `crate::fold`, `crate::figures`,
//! `crate::limits`, `crate::error`, `crate::layer` (a layer state),
//! `crate::studies` (the thickness map), `crate::progress` (its points as
//! they come), its own modules.

use crate::report::{AnyState, Document, ErrorBody};
use crate::units::Cylinders;
use crate::{Contact, ModelId, State};
use clap::{Parser, Subcommand, ValueEnum};
use std::process::ExitCode;

fn parse_model(s: &str) -> Result<ModelChoice, String> {
    crate::registry::parse(s)
}

/// `--model` of `batch`: the models whose states are rows (not `exact`,
/// seconds a state, nor a slender model, whose contact has no size a
/// row could carry); another is a usage error, as an unknown name is.
fn parse_batch_model(s: &str) -> Result<ModelChoice, String> {
    match crate::registry::parse(s)? {
        ModelChoice::Exact => Err(
            "model exact has no batch (an exact state takes up to seconds: use `thinjkr exact solve` per state)"
                .into(),
        ),
        ModelChoice::Slender(_) => Err(format!(
            "model {s} has no batch rows (a row carries a and s, and a slender contact has no finite length: use `thinjkr solve --model {s}` per state)"
        )),
        other => Ok(other),
    }
}

use crate::fold::FoldCondition;
/// A model of the ellipse, a member of a contour family, or the exact
/// solution of (2)-(3) (`crate::registry`).
use crate::registry::Choice as ModelChoice;
use crate::registry::PhysicalAnswer;

#[macro_use]
mod output;
mod contour;
mod exact_command;
mod files;

/// Approximate JKR contact of thin incompressible coatings on rigid cylinders
/// (Argatov, Mishuris & Popov 2016), dimensionless as in Eq. (17) unless
/// `physical` is used.
#[derive(Parser)]
#[command(
    version,
    about,
    after_help = "Examples:\n  thinjkr solve --rho 0.8 --delta 2\n  thinjkr solve --rho 0.8 --force -2 --json\n  thinjkr pull-off --rho 0.8 --control displacement\n  thinjkr pull-off --rho 0.8 --model energy\n  thinjkr zero-force --rho 0.9\n  thinjkr curve --rho 0.8 --points 50 --format csv\n  thinjkr physical --file contact.toml --force 1e-3"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    /// Every line of the answer: the checks, the route, each control's stability, the shape, every warning and
    /// the models beside an exact answer (without it: the answer, and at most two lines on how far to trust it).
    #[arg(long, global = true)]
    explain: bool,
    /// An exact state at a force or an approach: search even where the map of where the exact search finds
    /// none (solver/data/exact_no_state.json, `thinjkr exact store-no-state`) refuses it at once (minutes).
    #[arg(long, global = true)]
    search: bool,
}

#[derive(Subcommand)]
enum Command {
    /// One state at given δ̄, F̄ or ā.
    #[command(
        after_help = "Examples:\n  thinjkr solve --rho 0.8 --delta 2\n  thinjkr solve --rho 0.8 --a 3 --json"
    )]
    Solve {
        /// Radii ratio ρ = R2/R1 in (0, 1].
        #[arg(long, allow_hyphen_values = true)]
        rho: f64,
        #[arg(long, default_value = "max", value_parser = parse_model, help = crate::registry::help(true, ""))]
        model: ModelChoice,
        /// With --model layer: the coatings' thinness h/L (two equal coatings; default 0.1).
        #[arg(long, allow_hyphen_values = true)]
        thinness: Option<f64>,
        /// With --model layer: the coatings' Poisson's ratio in [0, 0.5] (default 0.5, incompressible).
        #[arg(long, allow_hyphen_values = true)]
        nu: Option<f64>,
        /// Approach δ̄.
        #[arg(long, allow_hyphen_values = true, group = "control")]
        delta: Option<f64>,
        /// Force F̄ (the stable state).
        #[arg(long, allow_hyphen_values = true, group = "control")]
        force: Option<f64>,
        /// Major semi-axis ā (all states with this size).
        #[arg(long, allow_hyphen_values = true, group = "control")]
        a: Option<f64>,
        /// Every state at that control, the one answered without --all first (with --force and a model of the
        /// ellipse: each state with that force, the stable one first; --a lists every state of that size anyway;
        /// with a contour family: every state at that control on its curve, the arm through its state at δ̄ = 20
        /// and the pull-off's arm).
        #[arg(long)]
        all: bool,
        #[command(flatten)]
        gap: exact_command::GapChoice,
        /// Print JSON.
        #[arg(long)]
        json: bool,
    },
    /// Pull-off (minimum force under load control; end of the stable branch under displacement control).
    #[command(
        name = "pull-off",
        after_help = "Example:\n  thinjkr pull-off --rho 0.8 --control displacement --json"
    )]
    PullOff {
        /// Radii ratio ρ in (0, 1].
        #[arg(long, allow_hyphen_values = true)]
        rho: f64,
        #[arg(long, default_value = "max", value_parser = parse_model, help = crate::registry::help(true, ""))]
        model: ModelChoice,
        /// With --model layer: the coatings' thinness h/L (two equal coatings; default 0.1).
        #[arg(long, allow_hyphen_values = true)]
        thinness: Option<f64>,
        /// With --model layer: the coatings' Poisson's ratio in [0, 0.5] (default 0.5, incompressible).
        #[arg(long, allow_hyphen_values = true)]
        nu: Option<f64>,
        /// Control.
        #[arg(long, value_enum, default_value_t = FoldCondition::Load)]
        control: FoldCondition,
        #[command(flatten)]
        gap: exact_command::GapChoice,
        /// Print JSON.
        #[arg(long)]
        json: bool,
    },
    /// The exact solution of the free-boundary problem (2)-(3), every model beside it.
    #[command(
        after_help = "Examples:\n  thinjkr exact pull-off --rho 0.8\n  thinjkr exact solve --rho 0.8 --force 10\n  thinjkr exact zero-force --rho 0.8 --json\n  thinjkr pull-off --rho 0.8 --model exact"
    )]
    Exact {
        #[command(subcommand)]
        command: exact_command::ExactCommand,
    },
    /// The table of docs/accuracy.md: every model against the exact solution for rho from 1 to 0.02 (all cores; about 40 minutes on two).
    #[command(
        after_help = "Example:\n  thinjkr accuracy --out docs/accuracy.md --reference derive/data/exact_reference.json --figures docs/figures"
    )]
    Accuracy {
        /// Write the markdown here instead of to standard output.
        #[arg(long)]
        out: Option<std::path::PathBuf>,
        /// Also write the exact pull-offs as JSON here (the checker's reference, derive/data/exact_reference.json).
        #[arg(long)]
        reference: Option<std::path::PathBuf>,
        /// Also draw the exact solution's figures (SVG) into this directory (docs/figures).
        #[arg(long)]
        figures: Option<std::path::PathBuf>,
        /// Only the rows at these rho (each one of the table's: 1, 0.9, …, 0.1, 0.05, 0.02; repeat the flag or separate by commas); not with --reference or --figures, which need every row.
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true, conflicts_with_all = ["reference", "figures"])]
        rho: Vec<f64>,
    },
    /// The zero-force state (Section 5).
    #[command(
        name = "zero-force",
        after_help = "Example:\n  thinjkr zero-force --rho 0.8 --json"
    )]
    ZeroForce {
        /// Radii ratio ρ in (0, 1].
        #[arg(long, allow_hyphen_values = true)]
        rho: f64,
        #[arg(long, default_value = "max", value_parser = parse_model, help = crate::registry::help(true, ""))]
        model: ModelChoice,
        /// With --model layer: the coatings' thinness h/L (two equal coatings; default 0.1).
        #[arg(long, allow_hyphen_values = true)]
        thinness: Option<f64>,
        /// With --model layer: the coatings' Poisson's ratio in [0, 0.5] (default 0.5, incompressible).
        #[arg(long, allow_hyphen_values = true)]
        nu: Option<f64>,
        #[command(flatten)]
        gap: exact_command::GapChoice,
        /// Print JSON.
        #[arg(long)]
        json: bool,
    },
    /// The force–displacement curve including its unstable part.
    #[command(
        after_help = "Example:\n  thinjkr curve --rho 0.8 --points 100 --format csv > curve.csv"
    )]
    Curve {
        /// Radii ratio ρ in (0, 1].
        #[arg(long, allow_hyphen_values = true)]
        rho: f64,
        #[arg(long, default_value = "max", value_parser = parse_model, help = crate::registry::help(false, "; exact gives states, not curves (use exact solve)"))]
        model: ModelChoice,
        /// With --model layer: the coatings' thinness h/L (two equal coatings; default 0.1).
        #[arg(long, allow_hyphen_values = true)]
        thinness: Option<f64>,
        /// With --model layer: the coatings' Poisson's ratio in [0, 0.5] (default 0.5, incompressible).
        #[arg(long, allow_hyphen_values = true)]
        nu: Option<f64>,
        /// Number of points, 2 ..= 100000.
        #[arg(long, default_value_t = 100)]
        points: usize,
        /// Output format.
        #[arg(long, value_enum, default_value_t = Format::Csv)]
        format: Format,
    },
    /// Solve many inputs: a CSV `rho,control,value` (control delta or force) on stdin, one state per line on stdout, in input order, on all cores.
    #[command(
        after_help = "Example:\n  printf 'rho,control,value\\n0.8,delta,2\\n0.5,force,-1\\n' | thinjkr batch --model max > out.csv\n\nOutput columns: line,rho,control,value,a,b,s,delta,force,xi,p0,bc_error,error,warning. A line that cannot be read or solved gets an empty state and the error (naming the line) in the column error; the other lines are still written. A doubtful state (a contour member's closure missing (3)2 by more than 0.1, or b > a; a model of the ellipse below the paper's range rho >= 0.8 or beyond its contact-size fold) has why in the column warning. A progress count is shown on stderr when it is a terminal."
    )]
    Batch {
        #[arg(long, default_value = "max", value_parser = parse_batch_model, help = crate::registry::batch_help())]
        model: ModelChoice,
    },
    /// The models the solver has, one line each.
    Models {
        /// Print JSON.
        #[arg(long)]
        json: bool,
    },
    /// Draw the paper's Figures 2–9 and the crossing-angle figure as SVG.
    #[command(after_help = "Example:\n  thinjkr figures --out docs/figures")]
    Figures {
        /// Output directory.
        #[arg(long)]
        out: std::path::PathBuf,
    },
    /// The map of the thin-layer equation (2)'s pull-off error against the layer of finite thickness, by crossing angle and coating thinness (equal incompressible coatings on equal cylinders; docs/thickness.md; seconds to a minute a point).
    #[command(
        name = "thickness-map",
        after_help = "Example:\n  thinjkr thickness-map --theta-deg 60,90 --thinness 0.5,1 --json"
    )]
    ThicknessMap {
        /// Crossing angles θ in degrees, in (0, 90] (repeat the flag or separate by commas; default 30, 40, …, 90).
        #[arg(long = "theta-deg", value_delimiter = ',', allow_hyphen_values = true)]
        theta_deg: Vec<f64>,
        /// Each coating's thinness h/L (repeat or separate by commas; default 0.3, 0.5, 0.73, 1, 2, 5, 10).
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        thinness: Vec<f64>,
        /// Print JSON, one point a line.
        #[arg(long)]
        json: bool,
        /// Also draw the map (SVG, one line per angle) into this file (docs/figures/thickness_map.svg).
        #[arg(long)]
        figure: Option<std::path::PathBuf>,
    },
    /// Physical inputs (SI units), from flags or a TOML file with the same keys.
    #[command(
        after_help = "Example:\n  thinjkr physical --r1 0.01 --r2 0.01 --theta-deg 60 --h1 1e-4 --h2 1e-4 --g1 1e6 --g2 1e6 --work-of-adhesion 0.05 --force 0"
    )]
    Physical {
        /// TOML file with r1, r2, theta_deg, h1, h2, g1, g2, work_of_adhesion, and optionally nu1, nu2 (and no other keys); not together with those flags.
        #[arg(long, conflicts_with_all = ["r1", "r2", "theta_deg", "h1", "h2", "g1", "g2", "work_of_adhesion", "nu1", "nu2"])]
        file: Option<std::path::PathBuf>,
        /// Radius of cylinder 1 [m], > 0.
        #[arg(long, allow_hyphen_values = true)]
        r1: Option<f64>,
        /// Radius of cylinder 2 [m], > 0.
        #[arg(long, allow_hyphen_values = true)]
        r2: Option<f64>,
        /// Crossing angle θ between the cylinder axes [degrees], in (0, 90].
        #[arg(long, allow_hyphen_values = true)]
        theta_deg: Option<f64>,
        /// Thickness of coating 1 [m], > 0 (thin: much smaller than the contact).
        #[arg(long, allow_hyphen_values = true)]
        h1: Option<f64>,
        /// Thickness of coating 2 [m], > 0.
        #[arg(long, allow_hyphen_values = true)]
        h2: Option<f64>,
        /// Out-of-plane shear modulus G′₁ of coating 1 [Pa], > 0.
        #[arg(long, allow_hyphen_values = true)]
        g1: Option<f64>,
        /// Out-of-plane shear modulus G′₂ of coating 2 [Pa], > 0.
        #[arg(long, allow_hyphen_values = true)]
        g2: Option<f64>,
        /// Work of adhesion Δγ [J/m²], > 0.
        #[arg(long, allow_hyphen_values = true)]
        work_of_adhesion: Option<f64>,
        /// Poisson's ratio ν₁ of coating 1, in [0, 0.5] (default 0.5, incompressible); read by the layer of finite thickness (at rho = 1), which G′₁ is the shear modulus of; (2) assumes 0.5.
        #[arg(long, allow_hyphen_values = true)]
        nu1: Option<f64>,
        /// Poisson's ratio ν₂ of coating 2, as --nu1.
        #[arg(long, allow_hyphen_values = true)]
        nu2: Option<f64>,
        /// Force [N] (the stable state); without it and --delta, pull-off under load control.
        #[arg(long, allow_hyphen_values = true, group = "physical_control")]
        force: Option<f64>,
        /// Approach [m].
        #[arg(long, allow_hyphen_values = true, group = "physical_control")]
        delta: Option<f64>,
        #[arg(long, value_parser = parse_model, help = crate::registry::help(true, "; without it, the model that the table of defaults gives for this rho and question (docs/guide.md, \"Which model answers by default\"), said in the output with its reason"))]
        model: Option<ModelChoice>,
        /// Print JSON.
        #[arg(long)]
        json: bool,
    },
    /// The JSON Schema of every `--json` output (docs/schema.json).
    Schema,
    /// Shell completions for SHELL (bash, zsh, fish, elvish, powershell) on standard output.
    #[command(
        after_help = "Example:\n  thinjkr completions bash > ~/.local/share/bash-completion/completions/thinjkr"
    )]
    Completions {
        /// The shell.
        shell: clap_complete::Shell,
    },
    /// The manual page (roff) on standard output (docs/thinjkr.1).
    Manpage,
}

#[derive(Clone, Copy, ValueEnum)]
enum Format {
    Csv,
    Json,
}

/// Whether the subcommand prints JSON (then an error is JSON on stdout too).
fn wants_json(c: &Option<Command>) -> bool {
    match c {
        Some(Command::Solve { json, .. })
        | Some(Command::PullOff { json, .. })
        | Some(Command::ZeroForce { json, .. })
        | Some(Command::Models { json, .. })
        | Some(Command::Physical { json, .. }) => *json,
        Some(Command::Curve { format, .. }) => matches!(format, Format::Json),
        Some(Command::Exact { command }) => command.json(),
        _ => false,
    }
}

fn stability(st: &State) -> String {
    let word = |v: Option<bool>, neutral: bool| match v {
        Some(true) if neutral => "neutral (a zero eigenvalue: a fold of this control)",
        Some(true) => "stable",
        Some(false) => "unstable",
        None => "n/a",
    };
    let s = st.stability;
    match (s.stable_displacement, s.stable_load) {
        (None, None) => String::new(),
        (d, l) => format!(
            " [displacement control: {}, load control: {}]",
            word(d, s.neutral_displacement),
            word(l, s.neutral_load)
        ),
    }
}

/// A layer state in two lines: its size, approach and force with its
/// coatings and its stability under each control (from the slopes along
/// its branch), then what its coatings are.
fn show_layer(label: &str, st: &crate::layer::LayerState) -> crate::Result<()> {
    outln!(
        "{label}: model layer, a = {}, delta = {}, force = {} [h/L = {}, nu = {}; {}]",
        output::num(st.a_bar),
        output::num(st.delta_bar),
        output::num(st.force_bar),
        crate::error::short(st.coatings[0].thinness),
        crate::error::short(st.coatings[0].nu),
        st.verdicts.words()
    );
    outln!("  {}", st.coatings_are);
    Ok(())
}

/// `thinjkr thickness-map`: the map's points as JSON lines, or its table
/// under a line that says what it is.
fn thickness_map(
    thetas: Vec<f64>,
    thins: Vec<f64>,
    json: bool,
    figure: Option<&std::path::Path>,
) -> crate::Result<()> {
    use crate::studies::thickness_map::{map, markdown, THETAS, THINS};
    let thetas = if thetas.is_empty() {
        THETAS.to_vec()
    } else {
        thetas
    };
    let thins = if thins.is_empty() {
        THINS.to_vec()
    } else {
        thins
    };
    if let Some(path) = figure {
        files::check_file(path)?;
    }
    let spin = output::Spinner::start("the layer's pull-off at each point");
    let (mut done, count) = (0, thetas.len().saturating_mul(thins.len()));
    let points = map(&thetas, &thins, |p| {
        done += 1;
        crate::progress::stage(format!(
            "point {done} of {count} (theta = {} degrees, h/L = {}) done",
            crate::error::short(p.theta_deg),
            crate::error::short(p.thinness)
        ));
    })?;
    drop(spin);
    if let Some(path) = figure {
        files::write_whole(path, crate::figures::thickness_map(&points)?.as_bytes())?;
    }
    if json {
        for p in points {
            outln!(
                "{}",
                crate::report::Document::Thickness { thickness: p }.to_json()
            );
        }
        return Ok(());
    }
    outln!("the thin-layer equation (2)'s pull-off error -F2/F - 1 against the layer of finite thickness (F its pull-off: s by the sharp edge, g by the grid, at 90 degrees the axisymmetric layer), equal incompressible coatings on equal cylinders:");
    outln!("{}", markdown(&points)?.trim_end());
    for p in &points {
        if let crate::report::ThicknessAnswer::None { why } = &p.layer {
            outln!(
                "  theta = {} degrees, h/L = {}: no pull-off of the layer ({why})",
                crate::error::short(p.theta_deg),
                crate::error::short(p.thinness)
            );
        }
    }
    Ok(())
}

/// A state of the layer in the plane: the answer in a line, how far to
/// trust it in the next, any warning; with `--explain` what its coatings
/// are, the ladder's rungs and the check's limit.
fn show_layer_plane(label: &str, st: &crate::layer::PlaneState) -> crate::Result<()> {
    outln!(
        "{label}: model layer, rho = {}, force = {}, a = {}, s = {}, delta = {} [h/L = {}, nu = {}; {}]",
        output::num(st.rho),
        output::num(st.force_bar),
        output::num(st.a_bar),
        output::num(st.s),
        output::num(st.delta_bar),
        crate::error::short(st.coatings[0].thinness),
        crate::error::short(st.coatings[0].nu),
        st.verdicts.words()
    );
    outln!("  {}", st.trust_words());
    for w in &st.warnings {
        outln!("  warning: {w}");
    }
    if output::explain() {
        outln!("  {}", st.coatings_are);
        for r in &st.rungs {
            let rung = match (r.eps, r.cells, r.functions) {
                (Some(eps), Some(cells), _) => format!(
                    "process zone {} of the contact, {cells} cells per side",
                    crate::error::short(eps)
                ),
                (.., Some([radial, angular])) => {
                    format!("{radial} x {angular} functions, {angular} edge modes")
                }
                _ => "a rung".into(),
            };
            outln!(
                "  {rung}: force = {}, a = {}, b = {}, delta = {}",
                output::num(r.force_bar),
                output::num(r.a_bar),
                output::num(r.b_bar),
                output::num(r.delta_bar)
            );
        }
        if let Some(g) = st.griffith_error {
            outln!(
                "  the finest edge departs from Griffith's condition by at most {:.1e}",
                g
            );
        }
        if st.held != crate::layer::Held::Force && st.method == crate::layer::Method::Grid {
            outln!(
                "  the JKR limit through the three coarsest: force = {}",
                output::num(st.force_bar_coarse)
            );
        }
    }
    Ok(())
}

/// A slender state in a line: its centre's half-width instead of a size
/// (its contact has no finite length), and its stability.
fn show_slender(label: &str, st: &crate::report::SlenderState) -> crate::Result<()> {
    outln!(
        "{label}: model {}, rho = {}, half-width at the centre b = {}, delta = {}, force = {}, dF/ddelta = {} [no finite length: the strip thins as 2/xi^2 along X without end; stable under displacement control, {} under load control]",
        st.model,
        output::num(st.rho),
        output::num(st.b_bar),
        output::num(st.delta_bar),
        output::num(st.force_bar),
        output::num(st.stiffness),
        if st.stable_load { "stable" } else { "unstable" }
    );
    Ok(())
}

fn show(label: &str, st: &State) -> crate::Result<()> {
    outln!(
        "{label}: model {}, a = {}, s = {}, delta = {}, force = {}, xi = {}, p0 = {}, error (14) = {:.4} %{}{}",
        st.model,
        output::num(st.a_bar),
        output::num(st.s),
        output::num(st.delta_bar),
        output::num(st.force_bar),
        output::num(st.xi),
        output::num(st.p0),
        100.0 * st.bc_error,
        st.warning_words()
            .iter()
            .map(|w| format!(" [{w}]"))
            .collect::<String>(),
        stability(st)
    );
    Ok(())
}

/// `thinjkr batch`: some lines have no state (their rows say why).
const BATCH_SOME_FAILED: u8 = 3;
/// `thinjkr batch`: no line has a state.
const BATCH_NONE_SOLVED: u8 = 4;

/// Run a subcommand; the exit status when it succeeds (0, or a batch's
/// partial status).
fn run(cli: Cli) -> crate::Result<u8> {
    match cli.command {
        None => example()?,
        Some(Command::Solve {
            rho,
            model,
            thinness,
            nu,
            delta,
            force,
            a,
            all,
            gap,
            json,
        }) => {
            let model = model.with_coatings(thinness, nu)?;
            gap.only_for_exact(&model)?;
            solve_command(rho, model, hold_of(delta, force, a)?, all, &gap, json)?
        }
        Some(Command::PullOff {
            rho,
            model,
            thinness,
            nu,
            control,
            gap,
            json,
        }) => {
            let model = model.with_coatings(thinness, nu)?;
            gap.only_for_exact(&model)?;
            pull_off_command(rho, model, control, &gap, json)?
        }
        Some(Command::Exact { command }) => exact_command::run(command)?,
        Some(Command::Batch { model }) => return batch_command(model),
        Some(Command::Accuracy {
            out,
            reference,
            figures,
            rho,
        }) => accuracy_command(out, reference, figures, &rho)?,
        Some(Command::ZeroForce {
            rho,
            model,
            thinness,
            nu,
            gap,
            json,
        }) => {
            let model = model.with_coatings(thinness, nu)?;
            gap.only_for_exact(&model)?;
            zero_force_command(rho, model, &gap, json)?
        }
        Some(Command::Curve {
            rho,
            model,
            thinness,
            nu,
            points,
            format,
        }) => curve_command(model.with_coatings(thinness, nu)?, rho, points, format)?,
        Some(Command::Models { json }) => models_command(json)?,
        Some(Command::Schema) => outln!("{}", crate::report::schema().trim_end()),
        Some(Command::Completions { shell }) => completions_command(shell)?,
        Some(Command::Manpage) => out!("{}", manpage()),
        Some(Command::ThicknessMap {
            theta_deg,
            thinness,
            json,
            figure,
        }) => thickness_map(theta_deg, thinness, json, figure.as_deref())?,
        Some(Command::Figures { out }) => {
            files::check_folder(&out)?;
            let drawn = crate::figures::all()?;
            files::create_folder(&out)?;
            let mut written = Vec::new();
            for (name, svg) in drawn {
                let p = out.join(name);
                files::write_whole(&p, svg.as_bytes())?;
                written.push(p);
            }
            for p in written {
                outln!("{}", p.display());
            }
        }
        Some(Command::Physical {
            file,
            r1,
            r2,
            theta_deg,
            h1,
            h2,
            g1,
            g2,
            work_of_adhesion,
            nu1,
            nu2,
            force,
            delta,
            model,
            json,
        }) => {
            let inputs = [r1, r2, theta_deg, h1, h2, g1, g2, work_of_adhesion];
            physical(
                &cylinders(file, inputs, [nu1, nu2])?,
                model,
                force,
                delta,
                json,
            )?
        }
    }
    Ok(0)
}

/// No subcommand: the paper's ρ = 0.8 example.
fn example() -> crate::Result<()> {
    let c = Contact::new(0.8)?;
    outln!("thinjkr: the paper's example, rho = R2/R1 = 0.8 (dimensionless, Eq. (17)); derived forms of (18), (26), (27)");
    show("pull-off (load control)        ", &c.pull_off_load()?.state)?;
    show(
        "pull-off (displacement control)",
        &c.pull_off_displacement()?.state,
    )?;
    show("zero force                     ", &c.zero_force()?)?;
    let e = Contact::with_model(ModelId::Energy, 0.8)?;
    outln!("the same contact with the energy (Ritz) closure of the same ellipse (--model energy):");
    show("pull-off (load control)        ", &e.pull_off_load()?.state)?;
    show("zero force                     ", &e.zero_force()?)?;
    Ok(())
}

/// The control `solve` is given: one of --delta, --force, --a.
fn hold_of(
    delta: Option<f64>,
    force: Option<f64>,
    a: Option<f64>,
) -> crate::Result<crate::control::Hold> {
    use crate::control::Hold;
    match (delta, force, a) {
        (Some(d), _, _) => Ok(Hold::Delta(d)),
        (_, Some(f), _) => Ok(Hold::Force(f)),
        (_, _, Some(a)) => Ok(Hold::Size(a)),
        _ => Err(crate::Error::Usage(
            "give one of --delta, --force, --a".into(),
        )),
    }
}

/// `thinjkr solve`: one state at given δ̄, F̄ or ā (every state of that ā).
fn solve_command(
    rho: f64,
    model: ModelChoice,
    hold: crate::control::Hold,
    all: bool,
    gap: &exact_command::GapChoice,
    j: bool,
) -> crate::Result<()> {
    // the exact state's report also solves the ellipse models at its
    // control and prints each one's distance from it
    use crate::control::Hold;
    let exact = match (model, hold) {
        (ModelChoice::Exact, Hold::Delta(d)) => Some(Hold::Delta(d)),
        (ModelChoice::Exact, Hold::Force(f)) => Some(Hold::Force(f)),
        _ => None,
    };
    if let Some(control) = exact {
        return exact_command::state(
            rho,
            control,
            &exact_command::Discretisation::default(),
            gap,
            j,
        );
    }
    gap.refused_by("solve --model exact --a")?;
    // a contour family's states at any control are read from its curve
    let contour = matches!(model, ModelChoice::Contour(_));
    if all || !(matches!(hold, Hold::Force(_)) || contour) {
        let states = model.states(rho, hold)?;
        if contour && !j {
            outln!(
                "{} state{} of {} at {} (rho = {}) on its curve (the arm through its state at delta = 20 and the pull-off's arm, past their folds), the one answered without --all first:",
                states.len(),
                if states.len() == 1 { "" } else { "s" },
                model.name(),
                hold,
                crate::error::short(rho)
            );
        }
        return show_states("state", &states, j);
    }
    // at a given force the stable state (for a contour family, the one its
    // route answers), and how many others have it (the state alone where
    // the others cannot be read)
    let (state, others) = match model.states(rho, hold) {
        Ok(mut all) => {
            let n = all.len() - 1;
            (all.remove(0), Ok(n))
        }
        Err(e) => (model.state(rho, hold)?, Err(e)),
    };
    if j {
        let doc = Document::State {
            state,
            models: Vec::new(),
            others: others.as_ref().ok().copied(),
        };
        outln!("{}", doc.to_json());
        return Ok(());
    }
    show_states("state", std::slice::from_ref(&state), false)?;
    let value = match hold {
        Hold::Delta(_) => "this approach",
        Hold::Force(_) => "this force",
        Hold::Size(_) => "this size",
    };
    match others {
        Ok(0) if contour => outln!(
            "  no other state on the member's curve (the arm through its state at delta = 20 and the pull-off's arm) has {value}"
        ),
        Ok(n) if contour => outln!(
            "  {n} other state{} on the member's curve (the arm through its state at delta = 20 and the pull-off's arm) {} {value} (--all lists every one)",
            if n == 1 { "" } else { "s" },
            if n == 1 { "has" } else { "have" }
        ),
        Err(e) if contour => outln!(
            "  the other states with {value} were not counted: {e}"
        ),
        Ok(0) => {}
        Ok(n) => outln!(
            "  the stable state, on the branch from large loads; {n} other state{} {} this force (--all lists every one)",
            if n == 1 { "" } else { "s" },
            if n == 1 { "has" } else { "have" }
        ),
        Err(e) => outln!(
            "  the stable state, on the branch from large loads; the other states with this force were not counted: {e}"
        ),
    }
    Ok(())
}

/// States of the models of the ellipse and of the contour families, as
/// text or as one JSON document (`state`, or `states` for several).
fn show_states(label: &str, states: &[AnyState], j: bool) -> crate::Result<()> {
    if j {
        let doc = match states {
            [one] => Document::State {
                state: one.clone(),
                models: Vec::new(),
                others: None,
            },
            many => Document::States {
                states: many.to_vec(),
            },
        };
        outln!("{}", doc.to_json());
        return Ok(());
    }
    for st in states {
        match st {
            AnyState::Ellipse(st) => show(label, st)?,
            AnyState::Conformal(st) => contour::show(label, st)?,
            AnyState::Exact(st) => exact_command::show_state(label, st)?,
            AnyState::Slender(st) => show_slender(label, st)?,
            AnyState::Layer(st) => show_layer(label, st)?,
            AnyState::LayerPlane(st) => show_layer_plane(label, st)?,
        }
    }
    Ok(())
}

/// `thinjkr pull-off`: the end of the branch under load or displacement control.
fn pull_off_command(
    rho: f64,
    model: ModelChoice,
    condition: FoldCondition,
    gap: &exact_command::GapChoice,
    j: bool,
) -> crate::Result<()> {
    if let (ModelChoice::Exact, FoldCondition::Load) = (model, condition) {
        // the exact pull-off's report also solves the ellipse models' and
        // prints each one's distance from it
        return exact_command::pull_off(
            rho,
            &exact_command::Discretisation::default(),
            false,
            false,
            gap,
            j,
        );
    }
    gap.refused_by("pull-off --model exact --control displacement")?;
    let p = model.pull_off(rho, condition)?;
    if j {
        let doc = Document::PullOff {
            state: p.state,
            control: p.control,
            basis: p.basis,
            passed: p.passed,
            models: Vec::new(),
        };
        outln!("{}", doc.to_json());
        return Ok(());
    }
    match (&p.state, model) {
        (AnyState::Ellipse(st), _) => {
            show("pull-off", st)?;
            if let Some(b) = p.basis {
                outln!("  end point: {}", b.describe());
            }
        }
        (AnyState::Conformal(st), ModelChoice::Contour(m)) => {
            contour::show_pull_off(&m, st, condition, &p.passed)?
        }
        (st, _) => show_states("pull-off", std::slice::from_ref(st), false)?,
    }
    Ok(())
}

/// `thinjkr batch`: CSV lines on stdin, one row each on stdout, in blocks
/// solved on all cores; the exit status says whether every line solved.
fn batch_command(model: ModelChoice) -> crate::Result<u8> {
    output::check_input_open()?;
    use crate::batch::{csv_row_values, decode_line, parse_line, solve_all, Row, CSV_HEADER};
    use std::io::{BufRead, IsTerminal};
    let stdin = std::io::stdin();
    outln!("{CSV_HEADER}");
    let bar = std::io::stderr().is_terminal().then(|| {
        let b = indicatif::ProgressBar::new_spinner();
        b.set_style(
            indicatif::ProgressStyle::with_template("{spinner} {pos} lines, {elapsed}")
                .expect("template"),
        );
        b
    });
    // raw lines: a line that is not UTF-8 is an error row of its own
    let mut lines = stdin.lock().split(b'\n').enumerate();
    let (mut failed, mut solved_any) = (0usize, false);
    loop {
        // a block of input lines, solved in parallel, written in order
        let mut block = Vec::with_capacity(4096);
        for (i, raw) in lines.by_ref() {
            let raw = raw.map_err(|e| {
                crate::Error::Io(format!("reading line {} of the input: {e}", i + 1))
            })?;
            let parsed = match decode_line(i + 1, &raw) {
                Ok(line) => parse_line(i + 1, line),
                Err(e) => Some(Err(e)),
            };
            if let Some(parsed) = parsed {
                block.push((i + 1, parsed));
                if block.len() == 4096 {
                    break;
                }
            }
        }
        if block.is_empty() {
            break;
        }
        let items: Vec<_> = block
            .iter()
            .filter_map(|(_, p)| p.as_ref().ok().copied())
            .collect();
        let rows: Vec<crate::Result<Row>> = solve_all(&model, &items)
            .iter()
            .map(|r| r.as_ref().map(Row::from).map_err(Clone::clone))
            .collect();
        let mut solved = rows.into_iter();
        for (n, parsed) in &block {
            let row = match parsed {
                Ok(item) => {
                    let r = solved.next().expect("one result per item");
                    match &r {
                        Err(e) => {
                            errln!("thinjkr: line {n}: {e}");
                            failed += 1;
                        }
                        Ok(_) => solved_any = true,
                    }
                    csv_row_values(*n, Some(item), &r)
                }
                Err(e) => {
                    errln!("thinjkr: {e}");
                    failed += 1;
                    csv_row_values(*n, None, &Err(e.clone()))
                }
            };
            outln!("{row}");
        }
        if let Some(b) = &bar {
            b.inc(block.len() as u64);
        }
    }
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    if failed == 0 {
        return Ok(0);
    }
    errln!("thinjkr: {failed} line(s) without a state (see the error column)");
    Ok(if solved_any {
        BATCH_SOME_FAILED
    } else {
        BATCH_NONE_SOLVED
    })
}

/// `thinjkr accuracy`: the table of docs/accuracy.md, on all cores.
fn accuracy_command(
    out: Option<std::path::PathBuf>,
    reference: Option<std::path::PathBuf>,
    figures: Option<std::path::PathBuf>,
    only: &[f64],
) -> crate::Result<()> {
    use crate::accuracy::RHOS;
    // the rows asked for: each a ρ of the table
    if let Some(&r) = only.iter().find(|r| !RHOS.contains(r)) {
        return Err(crate::Error::OutOfRange {
            name: "rho",
            value: r,
            range: format!(
                "one of the table's: {}",
                RHOS.map(|r| r.to_string()).join(", ")
            )
            .into(),
        });
    }
    let rhos: Vec<f64> = RHOS
        .iter()
        .copied()
        .filter(|r| only.is_empty() || only.contains(r))
        .collect();
    // every output path is checked before the minutes of work, and none
    // is created until the work is done (files::check_file)
    for p in [&out, &reference].into_iter().flatten() {
        files::check_file(p)?;
    }
    if let Some(dir) = &figures {
        files::check_folder(dir)?;
    }
    let began = std::time::Instant::now();
    use crate::accuracy::{
        doubling, own_gap_families, reference as reference_of, render, row, row_on, Quantity,
    };
    use rayon::prelude::*;
    // the cylinders' rows, then those of every family on a gap of its own
    // (at the ρ of the table it accepts)
    let mut jobs: Vec<(Option<&'static crate::conformal::Family>, f64, Quantity)> = rhos
        .iter()
        .flat_map(|&r| Quantity::ALL.iter().map(move |&q| (None, r, q)))
        .collect();
    for f in own_gap_families() {
        for &r in rhos.iter().filter(|&&r| r >= f.rho_min) {
            jobs.extend(Quantity::ALL.iter().map(|&q| (Some(f), r, q)));
        }
    }
    let bar = indicatif::ProgressBar::new(jobs.len() as u64);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} rows, {elapsed}")
            .expect("template"),
    );
    let rows: Vec<_> = jobs
        .par_iter()
        .map(|&(f, r, q)| {
            let x = match f {
                None => row(r, q),
                Some(f) => row_on(f, r, q),
            };
            bar.inc(1);
            x
        })
        .collect();
    bar.finish_and_clear();
    let pull_offs: Vec<_> = rows
        .iter()
        .filter(|r| r.quantity == Quantity::PullOff && r.family.is_none())
        .filter_map(|r| r.exact.as_ref().ok())
        .collect();
    let bar = indicatif::ProgressBar::new(pull_offs.len() as u64);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} doublings, {elapsed}")
            .expect("template"),
    );
    let doublings: Vec<_> = pull_offs
        .par_iter()
        .map(|st| {
            let d = doubling(st);
            bar.inc(1);
            d
        })
        .collect();
    bar.finish_and_clear();
    let mut text = render(&rows, &doublings);
    if !only.is_empty() {
        let at: Vec<String> = rhos.iter().map(|r| r.to_string()).collect();
        text = format!(
            "<!-- only the rows at rho = {} (`--rho`): a part of the table, not docs/accuracy.md -->\n{text}",
            at.join(", ")
        );
    }
    let refdata = reference_of(&doublings);
    if let Some(dir) = figures {
        let drawn = crate::figures::exact_all(&refdata)?;
        files::create_folder(&dir)?;
        for (name, svg) in drawn {
            files::write_whole(&dir.join(name), svg.as_bytes())?;
        }
    }
    if let Some(p) = reference {
        let json = serde_json::to_string_pretty(&refdata).expect("plain data serialises");
        files::write_whole(&p, (json + "\n").as_bytes())?;
    }
    match out {
        Some(p) => files::write_whole(&p, text.as_bytes())?,
        None => out!("{text}"),
    }
    errln!(
        "thinjkr: accuracy table: {} rows and {} doublings in {:.1} s on {} threads",
        rows.len(),
        doublings.len(),
        began.elapsed().as_secs_f64(),
        rayon::current_num_threads()
    );
    Ok(())
}

/// `thinjkr zero-force`.
fn zero_force_command(
    rho: f64,
    model: ModelChoice,
    gap: &exact_command::GapChoice,
    j: bool,
) -> crate::Result<()> {
    if let ModelChoice::Exact = model {
        // the exact state's report, with the ellipse models beside it
        return exact_command::state(
            rho,
            crate::control::Hold::Force(0.0),
            &exact_command::Discretisation::default(),
            gap,
            j,
        );
    }
    show_states("zero force", &[model.zero_force(rho)?], j)
}

/// `thinjkr models`.
fn models_command(j: bool) -> crate::Result<()> {
    // the families' problems, if any, are said by `main` after the output
    let models = crate::registry::entries();
    if j {
        outln!("{}", Document::Models { models }.to_json());
    } else {
        for m in models {
            outln!("{:<13} {}", m.name, m.description);
        }
    }
    Ok(())
}

/// `thinjkr completions`.
fn completions_command(shell: clap_complete::Shell) -> crate::Result<()> {
    let mut buf = Vec::new();
    clap_complete::generate(
        shell,
        &mut <Cli as clap::CommandFactory>::command(),
        "thinjkr",
        &mut buf,
    );
    out!("{}", String::from_utf8_lossy(&buf));
    Ok(())
}

/// The largest contact file read: eight numbers and their keys take a few
/// hundred bytes.
const CONTACT_FILE_MAX_BYTES: u64 = 64 * 1024;

/// The contact of `physical`: from its TOML file, or every input given
/// (r1, r2, theta_deg, h1, h2, g1, g2, work_of_adhesion; nu1 and nu2 0.5
/// unless given).
fn cylinders(
    file: Option<std::path::PathBuf>,
    inputs: [Option<f64>; 8],
    poisson: [Option<f64>; 2],
) -> crate::Result<Cylinders> {
    let [r1, r2, theta_deg, h1, h2, g1, g2, work_of_adhesion] = inputs;
    Ok(match file {
        Some(p) => {
            let text = files::input(&p, CONTACT_FILE_MAX_BYTES)?;
            toml::from_str::<Cylinders>(&text).map_err(|e| {
                // the parser's words, not the file's line (which may be
                // megabytes long)
                let at = e
                    .span()
                    .map(|r| {
                        let line = text[..r.start.min(text.len())].matches('\n').count() + 1;
                        format!(" (line {line})")
                    })
                    .unwrap_or_default();
                crate::Error::Usage(format!(
                    "{} is not a valid contact file{at}: {}",
                    p.display(),
                    files::quote(e.message(), 160)
                ))
            })?
        }
        None => {
            let need = |n: &'static str, v: Option<f64>| {
                v.ok_or_else(|| {
                    crate::Error::Usage(format!(
                        "physical needs --{} (or every input in a --file)",
                        n.replace('_', "-")
                    ))
                })
            };
            Cylinders {
                r1: need("r1", r1)?,
                r2: need("r2", r2)?,
                theta_deg: need("theta_deg", theta_deg)?,
                h1: need("h1", h1)?,
                h2: need("h2", h2)?,
                g1: need("g1", g1)?,
                g2: need("g2", g2)?,
                work_of_adhesion: need("work_of_adhesion", work_of_adhesion)?,
                nu1: poisson[0].unwrap_or(0.5),
                nu2: poisson[1].unwrap_or(0.5),
            }
        }
    })
}

/// The manual page, generated from the command-line definitions.
fn manpage() -> String {
    let mut buf = Vec::new();
    clap_mangen::Man::new(<Cli as clap::CommandFactory>::command())
        .render(&mut buf)
        .expect("rendering into memory");
    String::from_utf8_lossy(&buf).into_owned()
}

/// `physical`: the state of `model` for the contact `cyl` at force `force`
/// (N) or approach `delta` (m), or its pull-off under load control; in SI
/// units beside the dimensionless state, with a warning on stderr where
/// the input lies outside the model's stated range (it still answers).
fn physical(
    cyl: &Cylinders,
    model: Option<ModelChoice>,
    force: Option<f64>,
    delta: Option<f64>,
    json: bool,
) -> crate::Result<()> {
    let PhysicalAnswer {
        state,
        si,
        scales: sc,
        warnings,
        model: model_name,
        chosen_because,
        paper_model,
        thin_layer,
        layer_estimate,
    } = crate::registry::physical(model, cyl, force, delta)?;
    let (a_bar, b_bar, delta_bar, force_bar) = state.size_and_load();
    if json || output::explain() {
        for w in &warnings {
            errln!("thinjkr: warning: {w}");
        }
    }
    if json {
        let doc = Document::Physical {
            state,
            si,
            scales: sc,
            warnings,
            model: model_name,
            chosen_because,
            paper_model,
            thin_layer,
            layer_estimate,
        };
        outln!("{}", doc.to_json());
        return Ok(());
    }
    // where the layer's estimate is nearer it than (2) is, the estimate
    // first and (2)'s answer beside it
    let leading = layer_estimate.and_then(|e| e.leading_bound().map(|within| (e, within)));
    if let Some((e, within)) = &leading {
        outln!("{}", estimate_line(e, *within, sc.rho));
    }
    match leading {
        Some((e, _)) if !output::explain() => outln!(
            "  the thin-layer equation (2) ({model_name}): a = {:.6e} m, b = {:.6e} m, delta = {:.6e} m, force = {:.6e} N, {} % off",
            si.a,
            si.b,
            si.delta,
            si.force,
            crate::error::short(100.0 * e.thin_layer_error)
        ),
        _ => outln!(
            "physical: model {model_name}, rho = {}, a = {:.6e} m, b = {:.6e} m, delta = {:.6e} m, force = {:.6e} N, h/a = {:.4}",
            output::num(sc.rho),
            si.a,
            si.b,
            si.delta,
            si.force,
            si.h_over_a
        ),
    }
    if !output::explain() {
        return physical_brief(&state, thin_layer.as_ref(), &warnings);
    }
    outln!(
        "  dimensionless (17): a = {}, s = {}, delta = {}, force = {}; scales: L = {:.6e} m, approach {:.6e} m, force {:.6e} N",
        output::num(a_bar),
        output::num(b_bar / a_bar),
        output::num(delta_bar),
        output::num(force_bar),
        sc.length,
        sc.approach,
        sc.force
    );
    match &state {
        AnyState::Exact(st) => {
            outln!("  {}", exact_command::cutoff_words(&st.stability));
            outln!("  shape: {}", exact_command::shape_words(st));
            outln!(
                "  coatings: {} (h the thicker coating, L = {:.6e} m)",
                exact_command::coatings_words(st),
                sc.length
            );
        }
        AnyState::Conformal(st) => outln!("{}", conformal_line(st)),
        AnyState::Layer(st) => outln!("  {}", st.coatings_are),
        AnyState::LayerPlane(st) => {
            outln!("  {}", st.trust_words());
            outln!("  {}", st.coatings_are);
        }
        AnyState::Ellipse(_) | AnyState::Slender(_) => {}
    }
    if let Some(t) = &thin_layer {
        outln!("{}", thin_layer_line(t));
    }
    if let Some(why) = &chosen_because {
        outln!("  {why}");
    }
    if let Some(p) = &paper_model {
        let (a, b, d, f) = p.size_and_load();
        let p_si = cyl.si(&sc, a, b, d, f)?;
        outln!(
            "  the paper's model max differs by more than 1 %: a = {:.6e} m, b = {:.6e} m, delta = {:.6e} m, force = {:.6e} N",
            p_si.a,
            p_si.b,
            p_si.delta,
            p_si.force
        );
    }
    Ok(())
}

/// (2)'s answer beside the layer's in `physical`, in a line.
fn thin_layer_line(t: &crate::report::ThinLayer) -> String {
    format!(
        "  the thin-layer equation (2) ({}): a = {:.6e} m, delta = {:.6e} m, force = {:.6e} N, {} % off",
        t.model,
        t.si.a,
        t.si.delta,
        t.si.force,
        crate::error::short(100.0 * t.relative_error)
    )
}

/// `physical`'s first line where the layer's estimate `e` leads, `within`
/// its bound: the pull-off force, or the state, its bound and how it is
/// made.
fn estimate_line(e: &crate::report::LayerEstimate, within: f64, rho: f64) -> String {
    let answer = match &e.state {
        Some(s) => format!(
            "a = {:.6e} m, b = {:.6e} m, delta = {:.6e} m, force = {:.6e} N",
            s.a, s.b, s.delta, e.force
        ),
        None => format!("pull-off force = {:.6e} N", e.force),
    };
    format!(
        "physical: {answer} (the layer of finite thickness, estimated within {} % by {}), rho = {}",
        crate::error::short(100.0 * within),
        e.by.words(),
        output::num(rho)
    )
}

/// A contour member's verdicts above the coatings' cutoff, in a line.
fn conformal_line(st: &crate::conformal::ConformalState) -> String {
    format!(
        "  {} above the short-wave cutoff 2π h/L = {:.3} (h/L = {}) under displacement control, {} under load control",
        contour::verdict(st, st.stable_displacement, &st.neutral_modes),
        st.cutoff.wavelength,
        crate::error::short(st.cutoff.thinness),
        contour::verdict(st, st.stable_load, &st.neutral_modes_load)
    )
}

/// `physical`'s brief text after its answer's line: one line on how far to
/// trust it, then one warning with how many more (after the answer, which
/// is flushed first).
fn physical_brief(
    state: &AnyState,
    thin_layer: Option<&crate::report::ThinLayer>,
    warnings: &[String],
) -> crate::Result<()> {
    if let AnyState::LayerPlane(st) = state {
        outln!("  {}", st.trust_words());
    }
    match (thin_layer, state) {
        (Some(t), _) => outln!("{}", thin_layer_line(t)),
        (None, AnyState::Exact(st)) => outln!("  {}", exact_command::verdict_words(st)),
        (None, AnyState::Conformal(st)) => outln!("{}", conformal_line(st)),
        (None, _) => {}
    }
    output::finish()?;
    if let Some(w) = warnings.first() {
        match warnings.len() - 1 {
            0 => errln!("thinjkr: warning: {w}"),
            more => errln!("thinjkr: warning: {w} ({more} more: --explain)"),
        }
    }
    Ok(())
}

/// The run's thread pool ([`crate::batch::thread_pool`]), its warnings
/// on standard error.
fn thread_pool() -> rayon::ThreadPool {
    crate::batch::thread_pool(|w| errln!("thinjkr: warning: {w}"))
}

/// The program: parse the arguments, run the verb on a pool of threads
/// that fits the machine, print, and give the exit status.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    output::set_explain(cli.explain);
    crate::exact::no_state::SEARCH_ANYWAY.store(cli.search, std::sync::atomic::Ordering::Relaxed);
    let json_mode = wants_json(&cli.command);
    let pool = thread_pool();
    let mut result = output::check_open().and_then(|()| pool.install(|| run(cli)));
    // in --json mode an error is a JSON document on stdout as well (and
    // the same words on stderr), with the nonzero status
    if let Err(e) = &result {
        if json_mode && !output::broken_pipe() {
            let doc = Document::Error {
                error: ErrorBody::from(e),
            };
            if let Err(w) = output::line(format_args!("{}", doc.to_json())) {
                result = Err(w);
            }
        }
    }
    // a family of THINJKR_FAMILIES left out is said wherever the run loaded
    // the families (a built-in model, --help and --version load none); an
    // unknown model's error names them itself
    if result.is_ok() {
        for p in crate::conformal::problems_if_loaded().unwrap_or_default() {
            errln!("thinjkr: warning: {p}");
        }
    }
    // what was written before an error is flushed too (its own write
    // error, if any, then takes the place of the first)
    let flushed = output::finish();
    match result.and_then(|status| flushed.map(|()| status)) {
        // a line for standard error was lost (a full disk): the output is
        // complete, but the run did not say everything it had to
        Ok(0) if output::stderr_failed() => ExitCode::FAILURE,
        Ok(status) => ExitCode::from(status),
        // a closed pipe: the reader has what it wanted; end quietly
        Err(_) if output::broken_pipe() => ExitCode::from(output::BROKEN_PIPE_STATUS),
        Err(e) => {
            // in at most 300 characters; --explain: the whole record
            let words = if output::explain() {
                e.to_string()
            } else {
                e.brief()
            };
            errln!("thinjkr: error: {words}");
            // a request that is incomplete or contradictory is a usage
            // error, with the status clap gives one it cannot parse
            if matches!(e, crate::Error::Usage(_)) {
                ExitCode::from(USAGE_STATUS)
            } else {
                ExitCode::FAILURE
            }
        }
    }
}

/// The exit status of a usage error, ours or clap's.
const USAGE_STATUS: u8 = 2;

/// `thinjkr curve`: the branch from δ̄ = 20 past pull-off, as CSV or JSON,
/// written state by state as each is made (its memory does not grow with
/// `--points`), with a count of the states on a terminal.
fn curve_command(model: ModelChoice, rho: f64, points: usize, format: Format) -> crate::Result<()> {
    const DELTA_START: f64 = 20.0;
    let json = matches!(format, Format::Json);
    let spinner = output::Spinner::start("tracing the curve");
    let bar = {
        use std::io::IsTerminal;
        std::io::stderr().is_terminal().then(|| {
            let b = indicatif::ProgressBar::hidden();
            b.set_length(points as u64);
            b.set_style(
                indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} states, {elapsed}")
                    .expect("template"),
            );
            b
        })
    };
    let mut first = true;
    let mut spinner = Some(spinner);
    let end = model.curve_each(rho, points, DELTA_START, &mut |p| {
        if first {
            // the trace is done: the states follow
            drop(spinner.take());
            if let Some(b) = &bar {
                b.set_draw_target(indicatif::ProgressDrawTarget::stderr());
            }
            if json {
                out!("{CURVE_JSON_HEAD}");
            } else {
                outln!("model,delta,force,a,s,bc_error,beyond_size_fold,stable_displacement,stable_load,warning");
            }
        }
        if json {
            let st = serde_json::to_string(&p.state).expect("the output types serialise");
            out!("{}{st}", if first { "" } else { "," });
        } else {
            outln!("{}", curve_row(&p));
        }
        first = false;
        if let Some(b) = &bar {
            b.inc(1);
        }
        Ok(())
    })?;
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    if json {
        // the document's own JSON with its states left out, after the
        // states written: the same text as the whole document's
        let doc = Document::Curve {
            states: Vec::new(),
            folds: end.folds,
            end: end.end,
        }
        .to_json();
        let rest = doc
            .strip_prefix(CURVE_JSON_HEAD)
            .expect("a curve's JSON opens with its states");
        outln!("{rest}");
    }
    Ok(())
}

/// How a curve's JSON opens: its states first ([`Document::Curve`]).
const CURVE_JSON_HEAD: &str = "{\"states\":[";

/// A layer state's verdicts as the curve's stable flags under
/// displacement and load control: no unstable direction (stable, or
/// neutral at a pull-off), as the other models' flags say.
fn settled(v: crate::layer::Verdicts) -> (Option<bool>, Option<bool>) {
    let no_unstable =
        |v: Option<crate::layer::Verdict>| v.map(|v| v != crate::layer::Verdict::Unstable);
    (no_unstable(v.displacement), no_unstable(v.load))
}

/// One line of `thinjkr curve`'s CSV: the numbers as a batch row has them
/// (bc_error: (14) for the ellipse, max |dp/dnu - 1| on the contour
/// otherwise), the state's stability and its warning.
fn curve_row(p: &crate::registry::CurvePoint) -> String {
    let st = &p.state;
    let r = crate::batch::Row::from(st);
    let flag = |v: Option<bool>| v.map(|b| b.to_string()).unwrap_or_default();
    let (name, stable) = match st {
        AnyState::Ellipse(e) => (
            e.model.name().to_string(),
            (e.stability.stable_displacement, e.stability.stable_load),
        ),
        AnyState::Conformal(c) => (
            c.model.clone(),
            (Some(c.stable_displacement), Some(c.stable_load)),
        ),
        AnyState::Exact(e) => (
            "exact".into(),
            (e.stability.stable_displacement, e.stability.stable_load),
        ),
        AnyState::Slender(sl) => (
            sl.model.to_string(),
            (Some(sl.stable_displacement), Some(sl.stable_load)),
        ),
        AnyState::Layer(l) => ("layer".into(), settled(l.verdicts)),
        AnyState::LayerPlane(l) => ("layer".into(), settled(l.verdicts)),
    };
    format!(
        "{name},{},{},{},{},{},{},{},{},{}",
        r.delta_bar,
        r.force_bar,
        r.a_bar,
        r.s,
        r.bc_error,
        p.beyond_size_fold,
        flag(stable.0),
        flag(stable.1),
        crate::batch::quoted(&r.warning)
    )
}
